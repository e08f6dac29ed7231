/* SPDX-License-Identifier: MIT */
/*
 * Private: what the narrowphase's files share. Never installed.
 *
 *   narrowphase.c           the collision levels (box test, the box forms'
 *                           separating axes, the convex level, the exact
 *                           level) and noctCollide()
 *   narrowphase_query.c     point in solid, segment hits (the world's
 *                           queries)
 *   narrowphase_distance.c  distances: box forms apart by more than a
 *                           distance, and solids within one (the margin)
 *   narrowphase_point.c     a point's distance to a solid (the world's
 *                           point queries)
 *   narrowphase_turned.c    the exact level on turned meshes in a relative
 *                           frame (turned.h): oriented node boxes, lazily
 *                           placed vertices, containment by a thin ray
 *   bvh.c, bvh.h            the bounding-volume hierarchies and their walks
 *
 * The exact primitives below decide every question by the sign of
 * orient3d or orient2d, exact by predicates.c.
 */
#ifndef NOCT_LIB_NARROWPHASE_INTERNAL_H
#define NOCT_LIB_NARROWPHASE_INTERNAL_H

#include <math.h>
#include <stdbool.h>
#include <stdint.h>

#include <noctree/narrowphase.h>

#include "bvh.h"
#include "internal.h"
#include "mesh_internal.h"
#include "predicates.h"
#include "vec3.h"

/* A placed mesh, as the walks take it. */
typedef noct_placed_mesh placed;

/* ---- exact primitives ----------------------------------------------------- */

typedef struct exact_ctx {
    uint64_t *fallbacks;
} exact_ctx;

static inline int o3(const exact_ctx *x, const double a[3], const double b[3],
              const double c[3], const double d[3])
{
    return noct_orient3d(a, b, c, d, x->fallbacks);
}

/* orient2d of the projections dropping axis k. */
static inline int o2(const exact_ctx *x, int k, const double a[3], const double b[3],
              const double c[3])
{
    int i = (k + 1) % 3, j = (k + 2) % 3;
    double pa[2] = {a[i], a[j]}, pb[2] = {b[i], b[j]}, pc[2] = {c[i], c[j]};
    return noct_orient2d(pa, pb, pc, x->fallbacks);
}

/* p lies in the closed box of segment ab on the two axes other than k;
 * with p collinear with a and b in that projection this means p is on the
 * projected segment. */
static inline bool within_2d(int k, const double p[3], const double a[3], const double b[3])
{
    for (int s = 1; s <= 2; ++s) {
        int i = (k + s) % 3;
        if (p[i] < noct_min(a[i], b[i]) || p[i] > noct_max(a[i], b[i]))
            return false;
    }
    return true;
}

/* Closed segments pq and ab meet, in the projection dropping axis k. */
static inline bool seg_seg_2d(const exact_ctx *x, int k, const double p[3],
                       const double q[3], const double a[3], const double b[3])
{
    int d1 = o2(x, k, p, q, a), d2 = o2(x, k, p, q, b);
    int d3 = o2(x, k, a, b, p), d4 = o2(x, k, a, b, q);
    if (d1 * d2 < 0 && d3 * d4 < 0)
        return true;
    return (d1 == 0 && within_2d(k, a, p, q)) || (d2 == 0 && within_2d(k, b, p, q)) ||
           (d3 == 0 && within_2d(k, p, a, b)) || (d4 == 0 && within_2d(k, q, a, b));
}

/* Closed segments pq and ab meet, in 3D. */
static inline bool seg_seg_3d(const exact_ctx *x, const double p[3], const double q[3],
                       const double a[3], const double b[3])
{
    if (o3(x, p, q, a, b) != 0)
        return false; /* not coplanar */
    /* A projection in which the four points are not collinear is one-to-one
     * on their plane. */
    for (int k = 0; k < 3; ++k)
        if (o2(x, k, p, q, a) || o2(x, k, p, q, b) || o2(x, k, a, b, p) ||
            o2(x, k, a, b, q))
            return seg_seg_2d(x, k, p, q, a, b);
    /* All four collinear: compare intervals along an axis that separates
     * them, or any axis if they all coincide. */
    int axis = 0;
    double best = -1;
    for (int k = 0; k < 3; ++k) {
        double lo = noct_min(noct_min(p[k], q[k]), noct_min(a[k], b[k]));
        double hi = noct_max(noct_max(p[k], q[k]), noct_max(a[k], b[k]));
        if (hi - lo > best) {
            best = hi - lo;
            axis = k;
        }
    }
    return noct_max(noct_min(p[axis], q[axis]), noct_min(a[axis], b[axis])) <=
           noct_min(noct_max(p[axis], q[axis]), noct_max(a[axis], b[axis]));
}

/* One triangle abc of a parity count along segment pq, p off the solid's
 * boundary and q outside its box (so off every triangle): 1 if pq
 * crosses the triangle, 0 if not, -1 if the count is ambiguous (pq
 * through an edge or a vertex, or lying in the plane of a triangle with
 * area): then another q is tried. */
static inline int noct_parity_step(const exact_ctx *x, const double p[3], const double q[3],
                                   const double a[3], const double b[3], const double c[3])
{
    const int s1 = o3(x, a, b, c, p), s2 = o3(x, a, b, c, q);
    if (s1 == 0 && s2 == 0) {
        for (int k = 0; k < 3; ++k)
            if (o2(x, k, a, b, c) != 0)
                return -1;
        return 0; /* a collapsed triangle encloses nothing */
    }
    /* pq touches the plane at p or q alone, neither on the triangle */
    if (s1 == 0 || s2 == 0 || s1 == s2)
        return 0;
    const int e1 = o3(x, p, q, a, b), e2 = o3(x, p, q, b, c), e3 = o3(x, p, q, c, a);
    if ((e1 >= 0 && e2 >= 0 && e3 >= 0) || (e1 <= 0 && e2 <= 0 && e3 <= 0))
        return e1 == 0 || e2 == 0 || e3 == 0 ? -1 : 1;
    return 0;
}

/* Closed segment pq meets closed triangle abc (any of them degenerate);
 * s1 and s2 are the signs of o3(a, b, c, p) and o3(a, b, c, q). */
static inline bool seg_tri(const exact_ctx *x, const double p[3], const double q[3],
                    int s1, int s2, const double a[3], const double b[3],
                    const double c[3])
{
    if (s1 * s2 > 0)
        return false;
    if (s1 != 0 || s2 != 0) {
        /* pq crosses or touches the plane in one point: is it inside? */
        int e1 = o3(x, p, q, a, b), e2 = o3(x, p, q, b, c), e3 = o3(x, p, q, c, a);
        return (e1 >= 0 && e2 >= 0 && e3 >= 0) || (e1 <= 0 && e2 <= 0 && e3 <= 0);
    }
    /* Coplanar (or the triangle is degenerate): project on a plane where
     * the triangle keeps its area. */
    for (int k = 0; k < 3; ++k) {
        int area = o2(x, k, a, b, c);
        if (area == 0)
            continue;
        int i1 = o2(x, k, a, b, p), i2 = o2(x, k, b, c, p), i3 = o2(x, k, c, a, p);
        if (i1 * area >= 0 && i2 * area >= 0 && i3 * area >= 0)
            return true; /* p inside */
        return seg_seg_2d(x, k, p, q, a, b) || seg_seg_2d(x, k, p, q, b, c) ||
               seg_seg_2d(x, k, p, q, c, a);
    }
    /* The triangle has collapsed to a segment or a point. */
    return seg_seg_3d(x, p, q, a, b) || seg_seg_3d(x, p, q, b, c) ||
           seg_seg_3d(x, p, q, c, a);
}

/*
 * Closed triangles a and b meet. Each vertex's side of the other
 * triangle's plane is computed once: when all three vertices of one
 * triangle lie strictly on one side of the other's plane, they cannot
 * meet (the common case, six predicates); otherwise an edge of one meets
 * the other triangle, tested with the signs already known.
 */
static inline bool tri_tri(const exact_ctx *x, double a[3][3], double b[3][3])
{
    int sa[3], sb[3];
    for (int i = 0; i < 3; ++i)
        sb[i] = o3(x, a[0], a[1], a[2], b[i]);
    if (sb[0] == sb[1] && sb[1] == sb[2] && sb[0] != 0)
        return false;
    for (int i = 0; i < 3; ++i)
        sa[i] = o3(x, b[0], b[1], b[2], a[i]);
    if (sa[0] == sa[1] && sa[1] == sa[2] && sa[0] != 0)
        return false;
    for (int e = 0; e < 3; ++e) {
        int f = (e + 1) % 3;
        if (seg_tri(x, a[e], a[f], sa[e], sa[f], b[0], b[1], b[2]) ||
            seg_tri(x, b[e], b[f], sb[e], sb[f], a[0], a[1], a[2]))
            return true;
    }
    return false;
}

/* out = a x b; returns |out|_1. */
static inline double cross_into(const double a[3], const double b[3], double out[3])
{
    noct_cross3(a, b, out);
    return fabs(out[0]) + fabs(out[1]) + fabs(out[2]);
}

/* ---- the box forms' separating axes ---------------------------------------- */

/* The radius of a box with half-edges e on axis u: sum_i |u.e[i]|. */
static NOCT_ALWAYS_INLINE double box_radius(const double e[3][3], const double u[3])
{
    return fabs(u[0] * e[0][0] + u[1] * e[0][1] + u[2] * e[0][2]) +
           fabs(u[0] * e[1][0] + u[1] * e[1][1] + u[2] * e[1][2]) +
           fabs(u[0] * e[2][0] + u[1] * e[2][1] + u[2] * e[2][2]);
}

/* T = fl(c_B + t_B) - fl(c_A + t_A), and the M of the error bounds
 * below: it bounds the sizes, and |t| <= |fl(c + t)| + |c| + rounding. */
static NOCT_ALWAYS_INLINE double box_offset(const noct_box_slot *a, const double ta[3],
                                            const noct_box_slot *b, const double tb[3],
                                            double T[3])
{
    double m = 0;
    for (int k = 0; k < 3; ++k) {
        const double ca = a->c[k] + ta[k], cb = b->c[k] + tb[k];
        T[k] = cb - ca;
        m = noct_max(m, noct_max(fabs(ca), fabs(cb)));
    }
    return m + noct_max(a->size, b->size);
}

/* ---- containment ---------------------------------------------------------- */

/*
 * Is point p (not on B's boundary) inside the solid B? Exact (see
 * narrowphase.c); NOMEM never, INVARIANT if no ray could be cast.
 */
noctStatus noct_contains(const placed *B, const double p[3], const exact_ctx *x,
                         bool *inside);

/* Can a piece of in's boundary (mesh_internal.h) lie inside out's solid,
 * as placed? For one piece, only if in's box lies in out's; for several,
 * only if the boxes overlap. */
static inline bool noct_may_hold_piece(const placed *in, const placed *out)
{
    for (int k = 0; k < 3; ++k) {
        const double ilo = in->m->lo[k] + in->t[k], ihi = in->m->hi[k] + in->t[k];
        const double olo = out->m->lo[k] + out->t[k], ohi = out->m->hi[k] + out->t[k];
        if (in->m->npieces == 1 ? ilo < olo || ihi > ohi : ihi < olo || ilo > ohi)
            return false;
    }
    return true;
}

/* With the boundaries of in and out apart: does a piece of in's boundary
 * lie inside out's solid? A vertex of each piece that noct_may_hold_piece()
 * lets through (and, for several pieces, that lies in out's box) is tested
 * by noct_contains(); containment_tests counts them (narrowphase.c). */
noctStatus noct_piece_inside(const placed *in, const placed *out, const exact_ctx *x,
                             noctNarrowStats *stats, bool *inside);

/* Check two transforms and, for each that turns, make its mesh's rotated
 * copy (noct_mesh_rotated()) into rotated[i] and m[i]; the caller destroys
 * rotated[0] and rotated[1] (NULL where not turned), whatever the status
 * (narrowphase.c). */
noctStatus noct_meshes_rotated(const noctMesh *m[2], const noctTransform *const x[2],
                               noctMesh *rotated[2], noctError *err);

/* ---- distances (narrowphase_distance.c) ----------------------------------- */

/* Is a mesh of a distance search a rotated view (R set: the rotation;
 * only its vertices, triangles and hierarchy are valid), not a made mesh
 * (R NULL)? */
typedef struct noct_dist_exact {
    const double *R;
} noct_dist_exact;

/* noctCollideTransformed() at the exact level with at least one mesh
 * turned (R[i] its matrix where turned[i]): decided in A's frame
 * (turned.h, narrowphase_turned.c): the hierarchies' boxes tested as
 * oriented boxes, the vertices placed as triangle pairs read them; the
 * same placed vertices, so the same answer. A mesh not turn_fine goes to
 * noct_collide_exact_views(). */
noctStatus noct_collide_exact_turned(const noctMesh *a, const noctTransform *xa,
                                     const noctMesh *b, const noctTransform *xb,
                                     double R[2][9], const bool turned[2],
                                     bool *colliding, noctNarrowStats *stats, noctError *err);

/* The same decided on rotated views of the meshes (their vertices
 * rotated, their hierarchies refitted; narrowphase_distance.c), or on
 * rotated meshes where a rotated triangle comes near noctMeshCreate()'s
 * tolerance (then a DEGENERATE rotated mesh fails the call). */
noctStatus noct_collide_exact_views(const noctMesh *a, const noctTransform *xa,
                                    const noctMesh *b, const noctTransform *xb,
                                    double R[2][9], const bool turned[2], bool *colliding,
                                    noctNarrowStats *stats, noctError *err);

/* noctDistance() of two meshes placed at translations (already rotated,
 * or rotated views, as ex says; NULL: both made meshes). */
noctStatus noct_distance_placed(const noctMesh *a, const double ta[3], const noctMesh *b,
                                const double tb[3], double max_distance,
                                noctDistanceResult *result, noctNarrowStats *stats,
                                const noct_dist_exact ex[2]);

/* noctDistance()'s convex path on two meshes placed at translations (views
 * of box primitives' corners included): true if it answered, proved as
 * there; false when a mesh is not convex-like (a_convex, b_convex: known
 * convex, such as a box primitive) or the path could not prove its answer
 * within the accuracy (then noct_distance_placed() answers). */
bool noct_distance_convex_placed(const noctMesh *a, bool a_convex, const double ta[3],
                                 const noctMesh *b, bool b_convex, const double tb[3],
                                 double max_distance, noctDistanceResult *r);

/* ---- a point's distance (narrowphase_point.c) ------------------------------ */

/* The distance from point p to the solid of m placed at t, as
 * noct_distance_placed() gives a pair's with p the first solid: point_a is
 * p, triangle_a none; 0 and colliding when the solid contains p (exactly);
 * beyond max_distance as there. NUMERIC if the containment count stayed
 * ambiguous. outside: p is known to be outside the solid (a proof the
 * caller made): the containment test is skipped, the answer the same. */
noctStatus noct_point_distance_placed(const double p[3], const noctMesh *m, const double t[3],
                                      double max_distance, bool outside,
                                      noctDistanceResult *result);

#endif /* NOCT_LIB_NARROWPHASE_INTERNAL_H */
