/* SPDX-License-Identifier: MIT */
/*
 * The narrowphase: the report's hierarchy of partial decision mechanisms.
 *
 * Exact level. Two closed triangle meshes share a point iff a triangle of
 * one meets a triangle of the other, or one solid contains the other (then
 * it contains any vertex of it). Two closed triangles meet iff an edge of
 * one meets the other triangle. So: find the triangle pairs whose placed
 * boxes overlap through the two BVHs, test each pair's six edges against
 * the opposite triangle, and if no boundaries meet, test one vertex of each
 * for containment in the other. Every decision is a sign of orient3d or
 * orient2d, exact by predicates.c.
 *
 * Placement. A placed vertex is fl(v + t). Rounding is monotone, so the
 * placed box of any vertex set is exactly [fl(lo + t), fl(hi + t)]: box
 * tests on placed boxes are exact and conservative without padding.
 */
#define _POSIX_C_SOURCE 200809L /* clock_gettime(2) */
#include "config.h"

#include <ccd/ccd.h>
#include <math.h>
#include <string.h>
#include <time.h>

#include <noctree/narrowphase.h>

#include "internal.h"
#include "mesh_internal.h"
#include "vec3.h"
#include "predicates.h"

typedef struct placed {
    const noctMesh *m;
    double t[3];
} placed;

static void place(const placed *o, uint32_t vi, double out[3])
{
    const double *v = &o->m->v[3 * vi];
    out[0] = v[0] + o->t[0];
    out[1] = v[1] + o->t[1];
    out[2] = v[2] + o->t[2];
}

/* Closed boxes [alo, ahi] + ta and [blo, bhi] + tb overlap. */
static bool boxes_overlap(const double alo[3], const double ahi[3],
                          const double ta[3], const double blo[3],
                          const double bhi[3], const double tb[3])
{
    for (int k = 0; k < 3; ++k)
        if (ahi[k] + ta[k] < blo[k] + tb[k] || bhi[k] + tb[k] < alo[k] + ta[k])
            return false;
    return true;
}

/* ---- exact primitives ----------------------------------------------------- */

typedef struct exact_ctx {
    uint64_t *fallbacks;
} exact_ctx;

static int o3(const exact_ctx *x, const double a[3], const double b[3],
              const double c[3], const double d[3])
{
    return noct_orient3d(a, b, c, d, x->fallbacks);
}

/* orient2d of the projections dropping axis k. */
static int o2(const exact_ctx *x, int k, const double a[3], const double b[3],
              const double c[3])
{
    int i = (k + 1) % 3, j = (k + 2) % 3;
    double pa[2] = {a[i], a[j]}, pb[2] = {b[i], b[j]}, pc[2] = {c[i], c[j]};
    return noct_orient2d(pa, pb, pc, x->fallbacks);
}

/* p lies in the closed box of segment ab on the two axes other than k;
 * with p collinear with a and b in that projection this means p is on the
 * projected segment. */
static bool within_2d(int k, const double p[3], const double a[3], const double b[3])
{
    for (int s = 1; s <= 2; ++s) {
        int i = (k + s) % 3;
        if (p[i] < noct_min(a[i], b[i]) || p[i] > noct_max(a[i], b[i]))
            return false;
    }
    return true;
}

/* Closed segments pq and ab meet, in the projection dropping axis k. */
static bool seg_seg_2d(const exact_ctx *x, int k, const double p[3],
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
static bool seg_seg_3d(const exact_ctx *x, const double p[3], const double q[3],
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

/* Closed segment pq meets closed triangle abc (any of them degenerate);
 * s1 and s2 are the signs of o3(a, b, c, p) and o3(a, b, c, q). */
static bool seg_tri(const exact_ctx *x, const double p[3], const double q[3],
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
static bool tri_tri(const exact_ctx *x, double a[3][3], double b[3][3])
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

/* ---- BVH pair traversal ----------------------------------------------------- */

#define PAIR_STACK 256

static bool boundaries_meet(const placed *A, const placed *B, const exact_ctx *x,
                            noctNarrowStats *st)
{
    struct { uint32_t a, b; } stack[PAIR_STACK];
    size_t top = 0;
    stack[top].a = 0;
    stack[top++].b = 0;
    while (top > 0) {
        --top;
        const bvh_node *na = &A->m->nodes[stack[top].a];
        const bvh_node *nb = &B->m->nodes[stack[top].b];
        if (st)
            ++st->bvh_pairs;
        if (!boxes_overlap(na->lo, na->hi, A->t, nb->lo, nb->hi, B->t))
            continue;
        if (na->count > 0 && nb->count > 0) {
            for (uint32_t i = na->first; i < na->first + na->count; ++i) {
                double ta[3][3];
                for (int c = 0; c < 3; ++c)
                    place(A, A->m->tri[3 * i + c], ta[c]);
                for (uint32_t j = nb->first; j < nb->first + nb->count; ++j) {
                    double tb[3][3];
                    for (int c = 0; c < 3; ++c)
                        place(B, B->m->tri[3 * j + c], tb[c]);
                    if (st)
                        ++st->triangle_pairs;
                    if (tri_tri(x, ta, tb))
                        return true;
                }
            }
            continue;
        }
        /* Descend into the node with the larger box (or the inner one). */
        double sa = 0, sb = 0;
        for (int k = 0; k < 3; ++k) {
            sa += na->hi[k] - na->lo[k];
            sb += nb->hi[k] - nb->lo[k];
        }
        bool split_a = nb->count > 0 || (na->count == 0 && sa >= sb);
        uint32_t ia = stack[top].a, ib = stack[top].b;
        if (top + 2 > PAIR_STACK)
            return true; /* unreachable for meshes within the size limits */
        if (split_a) {
            stack[top].a = na->first;     stack[top++].b = ib;
            stack[top].a = na->first + 1; stack[top++].b = ib;
        } else {
            stack[top].a = ia; stack[top++].b = nb->first;
            stack[top].a = ia; stack[top++].b = nb->first + 1;
        }
    }
    return false;
}

/* ---- containment ---------------------------------------------------------- */

/*
 * Is point p (not on B's boundary) inside the solid B? Count the crossings
 * of B's surface by a segment from p to a point q outside B's box. If the
 * segment passes exactly through an edge or vertex of the surface, or q
 * lies in a triangle's plane, the count would be ambiguous: those cases are
 * detected exactly and another q is tried. Degenerate (collapsed) placed
 * triangles enclose nothing and are skipped.
 */
static noctStatus contains(const placed *B, const double p[3], const exact_ctx *x,
                           bool *inside)
{
    const noctMesh *m = B->m;
    double lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
        lo[k] = m->lo[k] + B->t[k];
        hi[k] = m->hi[k] + B->t[k];
        /* Placed so far out that rounding flattened it onto a plane (its
         * extent below an ulp of its place): the closed solid then has no
         * interior, and p, not on its boundary, is outside. */
        if (lo[k] == hi[k]) {
            *inside = false;
            return NOCT_OK;
        }
    }
    uint64_t seed = 0x9e3779b97f4a7c15u;
    for (int attempt = 0; attempt < 64; ++attempt) {
        double q[3];
        for (int k = 0; k < 3; ++k) {
            seed = seed * 6364136223846793005u + 1442695040888963407u;
            double u = (double)(seed >> 11) * 0x1p-53; /* [0, 1) */
            /* q's distance from the box outgrows the rounding of its
             * place, however far out the box is */
            double ext = hi[k] - lo[k] + fabs(p[k] - lo[k]) + 1 +
                         0x1p-40 * noct_max(fabs(lo[k]), fabs(hi[k]));
            q[k] = k == 0 ? hi[0] + ext * (1 + u) : lo[k] + (hi[k] - lo[k]) * u +
                   (u - 0.5) * ext;
        }
        bool ambiguous = false;
        unsigned crossings = 0;
        for (size_t t = 0; t < m->nt && !ambiguous; ++t) {
            double a[3], b[3], c[3];
            place(B, m->tri[3 * t], a);
            place(B, m->tri[3 * t + 1], b);
            place(B, m->tri[3 * t + 2], c);
            int s1 = o3(x, a, b, c, p), s2 = o3(x, a, b, c, q);
            if (s1 == 0 && s2 == 0) {
                bool flat = true;
                for (int k = 0; k < 3 && flat; ++k)
                    flat = o2(x, k, a, b, c) == 0;
                ambiguous = !flat;
                continue;
            }
            if (s2 == 0) {
                ambiguous = true;
                continue;
            }
            if (s1 == 0 || s1 == s2)
                continue; /* p is on the plane but off the triangle */
            int e1 = o3(x, p, q, a, b), e2 = o3(x, p, q, b, c), e3 = o3(x, p, q, c, a);
            bool pos = e1 >= 0 && e2 >= 0 && e3 >= 0;
            bool neg = e1 <= 0 && e2 <= 0 && e3 <= 0;
            if (pos || neg) {
                if (e1 == 0 || e2 == 0 || e3 == 0)
                    ambiguous = true; /* through an edge or a vertex */
                else
                    ++crossings;
            }
        }
        if (!ambiguous) {
            *inside = crossings % 2 == 1;
            return NOCT_OK;
        }
    }
    return NOCT_ERR_NUMERIC;
}

static bool box_inside(const placed *A, const placed *B)
{
    for (int k = 0; k < 3; ++k)
        if (A->m->lo[k] + A->t[k] < B->m->lo[k] + B->t[k] ||
            A->m->hi[k] + A->t[k] > B->m->hi[k] + B->t[k])
            return false;
    return true;
}

/* The filter serves meshes of at most this many vertices (mesh.c). */
#define SAT_MAX_VERTICES (4 * NOCT_SAT_MAX)

/* The projections of n vertices (3 doubles each) on axis u: [*lo, *hi]. */
static void project(const double *v, size_t n, const double u[3], double *lo, double *hi)
{
    double l = INFINITY, h = -INFINITY;
    for (size_t i = 0; i < n; ++i, v += 3) {
        double d = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
        l = noct_min(l, d);
        h = noct_max(h, d);
    }
    *lo = l;
    *hi = h;
}

/* The placed vertices of a mesh with the separating-axis filter. */
typedef struct placed_vertices {
    double v[SAT_MAX_VERTICES][3];
} placed_vertices;

static void place_all(const placed *P, placed_vertices *pv)
{
    for (size_t i = 0; i < P->m->nv; ++i)
        place(P, (uint32_t)i, pv->v[i]);
}

/*
 * Does some axis separate the placed vertex sets of A and B by more than
 * the rounding error? The work is done in the meshes' own frames: on
 * axis u, A's vertices project to [alo, ahi] (stored with the mesh for
 * its own face axes), B's to [blo, bhi] shifted by u.(tB - tA). With M
 * bounding every vertex coordinate in its frame and every translation
 * coordinate, and l1 = |u_x| + |u_y| + |u_z|, the computed gap differs
 * from the gap between the exactly projected placed (rounded) vertices
 * by at most 25 ulp(1/2) l1 M: 4 for rounding the placed vertices, 3 for
 * each projection, 8 for the shift (its difference and dot product) and
 * 7 for the two sums. A computed gap above 32 of those proves the hulls,
 * and so the solids, disjoint. The axes need not be exact: any axis that
 * separates is a proof.
 */
static bool sat_separated(const placed *A, const placed *B)
{
    const noctMesh *a = A->m, *b = B->m;
    double M = 0;
    for (int k = 0; k < 3; ++k) {
        M = noct_max(M, noct_max(noct_max(fabs(a->lo[k]), fabs(a->hi[k])),
                                 noct_max(fabs(b->lo[k]), fabs(b->hi[k]))));
        M = noct_max(M, noct_max(fabs(A->t[k]), fabs(B->t[k])));
    }
    const double d[3] = {B->t[0] - A->t[0], B->t[1] - A->t[1], B->t[2] - A->t[2]};
    const double unit = 32 * 0x1p-53 * M;
    size_t naxes = a->nsat_faces + b->nsat_faces + a->nsat_edges * b->nsat_edges;
    for (size_t i = 0; i < naxes; ++i) {
        double u[3], alo, ahi, blo, bhi;
        if (i < a->nsat_faces) {
            const sat_axis *x = &a->axis[i];
            memcpy(u, x->u, sizeof u);
            alo = x->lo;
            ahi = x->hi;
            project(b->v, b->nv, u, &blo, &bhi);
        } else if (i < a->nsat_faces + b->nsat_faces) {
            const sat_axis *x = &b->axis[i - a->nsat_faces];
            memcpy(u, x->u, sizeof u);
            blo = x->lo;
            bhi = x->hi;
            project(a->v, a->nv, u, &alo, &ahi);
        } else {
            size_t j = i - a->nsat_faces - b->nsat_faces;
            const double *p = a->axis[a->nsat_faces + j / b->nsat_edges].u;
            const double *q = b->axis[b->nsat_faces + j % b->nsat_edges].u;
            u[0] = p[1] * q[2] - p[2] * q[1];
            u[1] = p[2] * q[0] - p[0] * q[2];
            u[2] = p[0] * q[1] - p[1] * q[0];
            project(a->v, a->nv, u, &alo, &ahi);
            project(b->v, b->nv, u, &blo, &bhi);
        }
        double l1 = fabs(u[0]) + fabs(u[1]) + fabs(u[2]);
        if (!(l1 > 1e-6))
            continue; /* (nearly) parallel edges: no useful axis */
        double margin = unit * l1 + 1e-300;
        double shift = u[0] * d[0] + u[1] * d[1] + u[2] * d[2];
        if ((blo + shift) - ahi > margin || alo - (bhi + shift) > margin)
            return true;
    }
    return false;
}

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

/* Is a b == c d exactly? Two-products (fma) away from underflow. */
static bool products_equal(double a, double b, double c, double d)
{
    double h1 = a * b, h2 = c * d;
    if (h1 == 0 || h2 == 0)
        return (a == 0 || b == 0) && (c == 0 || d == 0);
    return h1 == h2 && fabs(h1) > 0x1p-900 && fma(a, b, -h1) == fma(c, d, -h2);
}

/*
 * The filter for two meshes with a box form (mesh_internal.h), first the
 * separation test: the oriented-box test on the 15 axes of the two boxes,
 * which reads only the descriptions. On axis u (l1 = |u_x| + |u_y| + |u_z|) every placed vertex
 * of A projects within R_A + l1 dev_A of u.(c_A + t_A), R_A = sum |u.e_i|,
 * and rounding the placed vertex moves it by at most l1 ulp(1/2) 2M, M
 * bounding the sizes and translations. A separation shows as
 * |u.T| - R_A - R_B - l1 (dev_A + dev_B) > 0 with T = c_B + t_B - c_A - t_A.
 * Computing T (as fl(c_B + t_B) - fl(c_A + t_A)), the dot products, the
 * radii (3 each) and the sums errs by under 110 ulp(1/2) l1 M in all; a
 * computed gap above 256 of those proves the solids disjoint. The radii
 * own[i] and the deviations are floats rounded up: larger, so safe.
 */
/*
 * Then the proof: do two boxes with duals provably share a point, by the
 * separating-axis test on their ideal boxes shrunk about their centres?
 * Shrunk by the factor f = 1 - shrink, shrink >= 2 gmax dev + 8 eta + 2e-15, every point
 * x = c + sum l_i e[i] of the shrunk box has g[i].(x - c) below
 * 1 - (2 gmax dev + 4 eta + 1e-15), since g[i].e[j] is within eta of
 * (i == j): box_contains' lemma puts x inside the solid. Two
 * parallelepipeds meet iff no axis among their face normals (the cross
 * products of their own edges) and the cross products of an edge of each
 * separates them, so the shrunk boxes, and with them the solids, meet when
 * the projections overlap on all 15 axes. The bound on rounding, 256
 * half-ulps of M (|u|_1 + |p|_inf |q|_inf) per axis u = p x q, covers the
 * rounding of u (about 4 ulps of |p|_inf |q|_inf per coordinate), of T
 * (|T| <= 2 M) and of the dot products several times over. An edge of
 * each that are exactly parallel span no separating plane and give no
 * axis (the boxes are the stored doubles c and e, so parallel means the
 * exact cross product is zero); nearly parallel edges give an axis that
 * the bound swamps, and the pair goes on to the witnesses.
 */
/*
 * The two tests share their work. The separation test runs first on the
 * face axes e[i], where it is cheapest and most pairs end: A's give the
 * products a_i.b_j that B's radii on A's axes need, and B's radii on A's
 * axes, read by column, are A's radii on B's (the same products in the
 * same order). On the nine axes a_i x b_j both tests need the same axis,
 * projection and radii, so they are computed once for both; the proof's
 * own face axes, the cross products of a box's edges, come last and only
 * for pairs not yet separated or refuted. The result is that of the
 * separation test on its 15 axes, then of the proof on its 15.
 */
int noct_box_decide(const noct_box_slot *a, const double ta[3], const noct_box_slot *b,
                    const double tb[3])
{
    double T[3];
    const double M = box_offset(a, ta, b, tb, T);
    const double unit = 256 * 0x1p-53 * M, dev = (double)a->dev + (double)b->dev;
    double C[3][3]; /* a_i . b_j */
    double la[3], lb[3];
    for (int i = 0; i < 3; ++i) {
        const double *u = a->e[i];
        la[i] = fabs(u[0]) + fabs(u[1]) + fabs(u[2]);
        for (int j = 0; j < 3; ++j)
            C[i][j] = u[0] * b->e[j][0] + u[1] * b->e[j][1] + u[2] * b->e[j][2];
        const double gap = fabs(u[0] * T[0] + u[1] * T[1] + u[2] * T[2]) - (double)a->own[i] -
                           (fabs(C[i][0]) + fabs(C[i][1]) + fabs(C[i][2])) - la[i] * dev;
        if (gap > unit * la[i])
            return -1;
    }
    for (int j = 0; j < 3; ++j) {
        const double *u = b->e[j];
        lb[j] = fabs(u[0]) + fabs(u[1]) + fabs(u[2]);
        const double gap = fabs(u[0] * T[0] + u[1] * T[1] + u[2] * T[2]) - (double)b->own[j] -
                           (fabs(C[0][j]) + fabs(C[1][j]) + fabs(C[2][j])) - lb[j] * dev;
        if (gap > unit * lb[j])
            return -1;
    }
    /* The proof needs both duals: shrink is +inf without one. */
    bool proven = a->shrink < 1 && b->shrink < 1;
    const double fa = 1 - (double)a->shrink, fb = 1 - (double)b->shrink;
    /* |e[i]|_inf of each edge, for the proof's products |p|_inf |q|_inf */
    double amax[3] = {0, 0, 0}, bmax[3] = {0, 0, 0};
    if (proven)
        for (int i = 0; i < 3; ++i) {
            amax[i] = noct_max(fabs(a->e[i][0]), noct_max(fabs(a->e[i][1]), fabs(a->e[i][2])));
            bmax[i] = noct_max(fabs(b->e[i][0]), noct_max(fabs(b->e[i][1]), fabs(b->e[i][2])));
        }
    for (int i = 0; i < 3; ++i) { /* pairs of edges */
        const double *x = a->e[i];
        for (int j = 0; j < 3; ++j) {
            const double *y = b->e[j];
            const double u[3] = {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2],
                                 x[0] * y[1] - x[1] * y[0]};
            const double l1 = fabs(u[0]) + fabs(u[1]) + fabs(u[2]);
            /* (nearly) parallel edges: no useful axis to separate */
            const bool separating = l1 > 1e-6 * la[i] * lb[j];
            if (!separating && !proven)
                continue;
            const double d = fabs(u[0] * T[0] + u[1] * T[1] + u[2] * T[2]);
            const double ra = box_radius(a->e, u), rb = box_radius(b->e, u);
            if (separating && d - ra - rb - l1 * dev > unit * l1)
                return -1;
            if (!proven)
                continue;
            if (l1 == 0 && products_equal(x[1], y[2], x[2], y[1]) &&
                products_equal(x[2], y[0], x[0], y[2]) && products_equal(x[0], y[1], x[1], y[0]))
                continue; /* parallel edges */
            proven = d + unit * (l1 + amax[i] * bmax[j]) < fa * ra + fb * rb;
        }
    }
    if (!proven)
        return 0;
    /* The proof's face axes: the cross products of each box's edges. */
    for (int n = 0; n < 6; ++n) {
        const noct_box_slot *s = n < 3 ? a : b;
        const double *smax = n < 3 ? amax : bmax;
        const double *x = s->e[(n + 1) % 3], *y = s->e[(n + 2) % 3];
        const double u[3] = {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2],
                             x[0] * y[1] - x[1] * y[0]};
        const double l1 = fabs(u[0]) + fabs(u[1]) + fabs(u[2]);
        const double pq = smax[(n + 1) % 3] * smax[(n + 2) % 3];
        const double d = fabs(u[0] * T[0] + u[1] * T[1] + u[2] * T[2]);
        if (!(d + unit * (l1 + pq) < fa * box_radius(a->e, u) + fb * box_radius(b->e, u)))
            return 0;
    }
    return 1;
}

/*
 * Is x proven inside the solid of a placed mesh with a box dual
 * (mesh_internal.h)? Its triangles lie, within sqrt(3) dev, on the
 * surface of the ideal box c + sum s_i e[i] (|s_i| <= 1): moving the
 * vertices there from the ideal corners never crosses a point farther
 * than that from the ideal surface, so such a point inside the ideal box
 * has the same positive winding number for the mesh, and is inside its
 * solid. x is that far inside when its coefficients a_i = g[i].(x - c - t)
 * stay below 1 by gmax 2 dev; the slack also covers eta and the rounding
 * of x - t - c (3 half-ulps of its magnitudes) and of the dot products.
 */
static bool box_contains(const placed *P, const double x[3])
{
    const box_form *b = &P->m->box;
    const box_dual *q = &P->m->dual;
    double r[3], rmax = 0, mag = 0;
    for (int k = 0; k < 3; ++k) {
        r[k] = (x[k] - P->t[k]) - b->c[k];
        rmax = noct_max(rmax, fabs(r[k]));
        mag = noct_max(mag, fabs(x[k]) + fabs(P->t[k]) + fabs(b->c[k]));
    }
    double slack = q->gmax * (2 * (double)b->dev + 3 * 0x1p-53 * mag + 4 * 0x1p-53 * rmax) +
                   4 * q->eta + 1e-15;
    double lim = 1 - slack;
    for (int i = 0; i < 3; ++i)
        if (!(fabs(q->g[i][0] * r[0] + q->g[i][1] * r[1] + q->g[i][2] * r[2]) < lim))
            return false;
    return true;
}

/* Is the vertex of Q (placed, pv) that lies deepest in box-form mesh P,
 * by its coefficients in P's frame, proven inside P? A vertex is a point
 * of its own solid. */
static bool box_vertex_witness(const placed *P, const placed *Q, const placed_vertices *pv)
{
    const box_form *b = &P->m->box;
    const box_dual *q = &P->m->dual;
    size_t best = 0;
    double best_depth = INFINITY;
    for (size_t i = 0; i < Q->m->nv; ++i) {
        const double r[3] = {(pv->v[i][0] - P->t[0]) - b->c[0], (pv->v[i][1] - P->t[1]) - b->c[1],
                             (pv->v[i][2] - P->t[2]) - b->c[2]};
        double depth = 0;
        for (int j = 0; j < 3; ++j)
            depth = noct_max(depth, fabs(q->g[j][0] * r[0] + q->g[j][1] * r[1] +
                                         q->g[j][2] * r[2]));
        if (depth < best_depth) {
            best_depth = depth;
            best = i;
        }
    }
    return best_depth < 1 && box_contains(P, pv->v[best]);
}

/* The centre of the placed meshes' boxes' overlap. */
static void overlap_centre(const placed *A, const placed *B, double c[3])
{
    for (int k = 0; k < 3; ++k)
        c[k] = 0.5 * (noct_max(A->m->lo[k] + A->t[k], B->m->lo[k] + B->t[k]) +
                      noct_min(A->m->hi[k] + A->t[k], B->m->hi[k] + B->t[k]));
}

/* How far point x is outside the placed mesh P by its floating-point
 * triangle planes: the largest signed distance, negative when x is
 * (about) inside every plane. Only a ranking; exact_inside decides. */
static double plane_depth(const placed *P, const double x[3])
{
    const noctMesh *m = P->m;
    const double r[3] = {x[0] - P->t[0], x[1] - P->t[1], x[2] - P->t[2]};
    double worst = -INFINITY;
    for (size_t t = 0; t < m->nt; ++t) {
        const double *pl = m->plane[t];
        worst = noct_max(worst, pl[0] * r[0] + pl[1] * r[1] + pl[2] * r[2] - pl[3]);
    }
    return worst;
}

/*
 * Is x strictly on the inner side of every placed triangle's plane of P,
 * by exact signs? Then every triangle of P's closed surface is seen from
 * x with a positive signed solid angle, so the surface winds around x a
 * positive number of times, and x is inside the solid.
 */
static bool exact_inside(const placed *P, const placed_vertices *pv, const double x[3],
                         const exact_ctx *ctx)
{
    const noctMesh *m = P->m;
    for (size_t t = 0; t < m->nt; ++t) {
        const uint32_t *tri = &m->tri[3 * t];
        if (o3(ctx, pv->v[tri[0]], pv->v[tri[1]], pv->v[tri[2]], x) <= 0)
            return false;
    }
    return true;
}

/*
 * A positive early-out for pairs the filter did not separate: look for a
 * point of both solids. Candidates are the centre of the two placed boxes'
 * overlap (a point inside both solids, if any is) and the vertex of each
 * mesh deepest inside the other (a vertex is a point of its own solid).
 * Floating point ranks them; only a candidate proven inside by exact
 * signs is a witness, so the answer is the exact level's own. Failing to
 * find one proves nothing: the triangle tests decide.
 */
static bool witness(const placed *A, const placed *B, const placed_vertices *va,
                    const placed_vertices *vb, const exact_ctx *ctx)
{
    double c[3];
    overlap_centre(A, B, c);
    if (plane_depth(A, c) < 0 && plane_depth(B, c) < 0 && exact_inside(A, va, c, ctx) &&
        exact_inside(B, vb, c, ctx))
        return true;
    const struct {
        const placed *from, *into;
        const placed_vertices *vf, *vi;
    } side[2] = {{A, B, va, vb}, {B, A, vb, va}};
    for (int s = 0; s < 2; ++s) {
        size_t best = 0;
        double best_depth = INFINITY;
        for (size_t i = 0; i < side[s].from->m->nv; ++i) {
            double d = plane_depth(side[s].into, side[s].vf->v[i]);
            if (d < best_depth) {
                best_depth = d;
                best = i;
            }
        }
        if (best_depth < 0 && exact_inside(side[s].into, side[s].vi, side[s].vf->v[best], ctx))
            return true;
    }
    return false;
}

/* decided: two boxes that noct_box_decide() could not decide, counted
 * already; go straight to the witnesses. */
static noctStatus exact_collide(const placed *A, const placed *B, bool decided, bool *hit,
                                noctNarrowStats *st)
{
    exact_ctx x = {st ? &st->exact_fallbacks : NULL};
    if (st && !decided)
        ++st->exact_tests;
    /* has_box first: it is on the box form's cache lines, which the
     * world prefetches, and nsat_faces is not. */
    const bool boxes = A->m->has_box && B->m->has_box;
    if (boxes || (A->m->nsat_faces > 0 && B->m->nsat_faces > 0)) {
        int d = 0;
        if (boxes && !decided) {
            noct_box_slot sa, sb;
            noct_box_slot_fill(A->m, &sa);
            noct_box_slot_fill(B->m, &sb);
            d = noct_box_decide(&sa, A->t, &sb, B->t);
        } else if (!boxes) {
            d = sat_separated(A, B) ? -1 : 0;
        }
        if (d != 0) {
            if (st)
                ++*(d < 0 ? &st->sat_rejects : &st->witnesses);
            *hit = d > 0;
            return NOCT_OK;
        }
        /* Two boxes: the witness's candidates, tested on their
         * descriptions; else the general witness on the triangles. */
        placed_vertices va, vb;
        bool found;
        if (A->m->has_dual && B->m->has_dual) {
            double c[3];
            overlap_centre(A, B, c);
            found = box_contains(A, c) && box_contains(B, c);
            if (!found) {
                place_all(A, &va);
                place_all(B, &vb);
                found = box_vertex_witness(B, A, &va) || box_vertex_witness(A, B, &vb);
            }
        } else {
            place_all(A, &va);
            place_all(B, &vb);
            found = witness(A, B, &va, &vb, &x);
        }
        if (found) {
            if (st)
                ++st->witnesses;
            *hit = true;
            return NOCT_OK;
        }
    }
    if (boundaries_meet(A, B, &x, st)) {
        *hit = true;
        return NOCT_OK;
    }
    const placed *pair[2][2] = {{A, B}, {B, A}};
    for (int i = 0; i < 2; ++i) {
        const placed *in = pair[i][0], *out = pair[i][1];
        if (!box_inside(in, out))
            continue;
        double p[3];
        place(in, in->m->tri[0], p);
        if (st)
            ++st->containment_tests;
        bool inside;
        noctStatus s = contains(out, p, &x, &inside);
        if (s != NOCT_OK)
            return s;
        if (inside) {
            *hit = true;
            return NOCT_OK;
        }
    }
    *hit = false;
    return NOCT_OK;
}

/* ---- convex level: libccd GJK on the hulls ------------------------------- */

static void ccd_support(const void *obj, const ccd_vec3_t *dir, ccd_vec3_t *out)
{
    const placed *o = obj;
    const noctMesh *m = o->m;
    const double d[3] = {ccdVec3X(dir), ccdVec3Y(dir), ccdVec3Z(dir)};
    size_t best = 0;
    double best_dot = -INFINITY;
    for (size_t i = 0; i < m->nhull; ++i) {
        const double *v = &m->v[3 * m->hull[i]];
        double dot = v[0] * d[0] + v[1] * d[1] + v[2] * d[2];
        if (dot > best_dot) {
            best_dot = dot;
            best = i;
        }
    }
    double p[3];
    place(o, m->hull[best], p);
    ccdVec3Set(out, p[0], p[1], p[2]);
}

static void ccd_centre(const void *obj, ccd_vec3_t *out)
{
    const placed *o = obj;
    ccdVec3Set(out, o->m->centre[0] + o->t[0], o->m->centre[1] + o->t[1],
               o->m->centre[2] + o->t[2]);
}

/* GJK's iterations depend on the order of its two objects, so near
 * contact its answer could too: decide every pair in one canonical order
 * (by translation, then by box and size). */
static bool canonical_first(const placed *A, const placed *B)
{
    const double ka[10] = {A->t[0], A->t[1], A->t[2], A->m->lo[0], A->m->lo[1],
                           A->m->lo[2], A->m->hi[0], A->m->hi[1], A->m->hi[2],
                           (double)A->m->nv};
    const double kb[10] = {B->t[0], B->t[1], B->t[2], B->m->lo[0], B->m->lo[1],
                           B->m->lo[2], B->m->hi[0], B->m->hi[1], B->m->hi[2],
                           (double)B->m->nv};
    for (int i = 0; i < 10; ++i)
        if (ka[i] != kb[i])
            return ka[i] < kb[i];
    return true;
}

static noctStatus convex_collide(const placed *A, const placed *B, bool *hit,
                                 noctNarrowStats *st)
{
    if (!canonical_first(A, B)) {
        const placed *t = A;
        A = B;
        B = t;
    }
    ccd_t ccd;
    CCD_INIT(&ccd);
    ccd.support1 = ccd_support;
    ccd.support2 = ccd_support;
    ccd.center1 = ccd_centre;
    ccd.center2 = ccd_centre;
    ccd.max_iterations = 500;
    ccd.epa_tolerance = 1e-12;
    ccd.mpr_tolerance = 1e-12;
    ccd.dist_tolerance = 1e-12;
    if (st)
        ++st->convex_tests;
    /* Work relative to A's translation: smaller numbers for libccd, and
     * the same geometry up to its tolerance. */
    placed ra = {A->m, {0, 0, 0}};
    placed rb = {B->m, {B->t[0] - A->t[0], B->t[1] - A->t[1], B->t[2] - A->t[2]}};
    int r = ccdGJKIntersect(&ra, &rb, &ccd);
    if (r != 0 && r != 1)
        return NOCT_ERR_NUMERIC;
    *hit = r == 1;
    return NOCT_OK;
}

/* ---- the entry point ------------------------------------------------------- */

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

const char *noctAccuracyName(noctAccuracy accuracy)
{
    switch (accuracy) {
    case NOCT_ACCURACY_BOX: return "box";
    case NOCT_ACCURACY_CONVEX: return "convex";
    case NOCT_ACCURACY_EXACT: return "exact";
    }
    return "unknown";
}

/* The levels past the box test, untimed; the box test first. */
/* noctCollide() without its argument checks and clock reads. */
static noctStatus collide_levels(const noctMesh *a, const double ta[3], const noctMesh *b,
                                 const double tb[3], noctAccuracy accuracy, bool *colliding,
                                 noctNarrowStats *stats)
{
    if (stats)
        ++stats->box_tests;
    if (!boxes_overlap(a->lo, a->hi, ta, b->lo, b->hi, tb)) {
        if (stats)
            ++stats->box_rejects;
        *colliding = false;
        return NOCT_OK;
    }
    return noct_collide_overlapping(a, ta, b, tb, accuracy, colliding, stats);
}

noctStatus noct_collide_overlapping(const noctMesh *a, const double ta[3], const noctMesh *b,
                                    const double tb[3], noctAccuracy accuracy,
                                    bool *colliding, noctNarrowStats *stats)
{
    placed A = {a, {ta[0], ta[1], ta[2]}}, B = {b, {tb[0], tb[1], tb[2]}};
    switch (accuracy) {
    case NOCT_ACCURACY_BOX:
        *colliding = true;
        return NOCT_OK;
    case NOCT_ACCURACY_CONVEX:
        return convex_collide(&A, &B, colliding, stats);
    case NOCT_ACCURACY_EXACT:
        break;
    }
    return exact_collide(&A, &B, false, colliding, stats);
}

noctStatus noct_collide_undecided_boxes(const noctMesh *a, const double ta[3],
                                        const noctMesh *b, const double tb[3], bool *colliding,
                                        noctNarrowStats *stats)
{
    placed A = {a, {ta[0], ta[1], ta[2]}}, B = {b, {tb[0], tb[1], tb[2]}};
    return exact_collide(&A, &B, true, colliding, stats);
}

/* ---- the world's queries (world_query.c) ------------------------------------ */

/* out = a x b; returns |out|_1. */
static double cross_into(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
    return fabs(out[0]) + fabs(out[1]) + fabs(out[2]);
}

/* Call fn for each placed triangle of B whose BVH leaf's placed box meets
 * the box [lo, hi] (the placed boxes hold their placed triangles exactly),
 * in the BVH's order, until it returns true; true if one did. */
typedef bool triangle_fn(void *context, uint32_t i, double a[3], double b[3], double c[3]);

static bool walk_triangles(const placed *B, const double lo[3], const double hi[3],
                           triangle_fn *fn, void *context)
{
    static const double zero[3] = {0, 0, 0};
    const noctMesh *m = B->m;
    uint32_t stack[64];
    size_t top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const bvh_node *n = &m->nodes[stack[--top]];
        if (!boxes_overlap(n->lo, n->hi, B->t, lo, hi, zero))
            continue;
        if (n->count == 0) {
            /* unreachable: a BVH is at most 33 deep, and the stack holds
             * one node a level and one more */
            if (top + 2 > sizeof stack / sizeof *stack)
                return true;
            stack[top++] = n->first;
            stack[top++] = n->first + 1;
            continue;
        }
        for (uint32_t i = n->first; i < n->first + n->count; ++i) {
            double a[3], b[3], c[3];
            place(B, m->tri[3 * i], a);
            place(B, m->tri[3 * i + 1], b);
            place(B, m->tri[3 * i + 2], c);
            if (fn(context, i, a, b, c))
                return true;
        }
    }
    return false;
}

typedef struct point_on {
    const double *p;
    exact_ctx x;
} point_on;

static bool point_on_triangle(void *context, uint32_t i, double a[3], double b[3], double c[3])
{
    (void)i;
    const point_on *q = context;
    return o3(&q->x, a, b, c, q->p) == 0 && seg_tri(&q->x, q->p, q->p, 0, 0, a, b, c);
}

/* Is p on a triangle of B (closed)? */
static bool on_boundary(const placed *B, const double p[3], const exact_ctx *x)
{
    point_on q = {p, *x};
    return walk_triangles(B, p, p, point_on_triangle, &q);
}

noctStatus noct_point_in_solid(const noctMesh *m, const double t[3], const double p[3],
                               bool *inside)
{
    const placed B = {m, {t[0], t[1], t[2]}};
    const exact_ctx x = {NULL};
    *inside = false;
    if (!boxes_overlap(m->lo, m->hi, t, p, p, (const double[3]){0, 0, 0}))
        return NOCT_OK;
    if (on_boundary(&B, p, &x)) {
        *inside = true;
        return NOCT_OK;
    }
    return contains(&B, p, &x, inside);
}

/* Where segment pq, known to meet closed triangle abc and not to start on
 * it, meets it first: the fraction along pq, in floating point, in
 * [0, 1]. Crossing its plane: where the plane's function changes sign.
 * In its plane: the least fraction at which pq meets an edge, in the
 * projection that keeps the triangle's area. */
static double entry_fraction(const double p[3], const double q[3], const double a[3],
                             const double b[3], const double c[3], const double n[3], bool flat)
{
    double d[3];
    for (int k = 0; k < 3; ++k)
        d[k] = q[k] - p[k];
    if (!flat) {
        double fp = 0, fq = 0;
        for (int k = 0; k < 3; ++k) {
            fp += n[k] * (p[k] - a[k]);
            fq += n[k] * (q[k] - a[k]);
        }
        const double f = fp != fq ? fp / (fp - fq) : 0;
        return f > 0 ? (f < 1 ? f : 1) : 0;
    }
    int drop = 0;
    for (int k = 1; k < 3; ++k)
        if (fabs(n[k]) > fabs(n[drop]))
            drop = k;
    const int i = (drop + 1) % 3, j = (drop + 2) % 3;
    const double *const v[3] = {a, b, c};
    double best = 1;
    for (int e = 0; e < 3; ++e) {
        const double *u = v[e], *w = v[(e + 1) % 3];
        const double ex = w[i] - u[i], ey = w[j] - u[j];
        const double den = d[i] * ey - d[j] * ex;
        if (den == 0)
            continue;
        const double rx = u[i] - p[i], ry = u[j] - p[j];
        const double s = (rx * ey - ry * ex) / den;  /* along pq */
        const double r = (rx * d[j] - ry * d[i]) / den; /* along the edge */
        if (s >= 0 && s < best && r >= -1e-12 && r <= 1 + 1e-12)
            best = s;
    }
    return best;
}

/* v scaled by the power of two that brings its largest component into
 * [1/2, 1), exactly (but for subnormal parts of a vector of huge range);
 * false if v is 0. */
static bool scale_to_unit_range(const double v[3], double out[3])
{
    const double m = noct_max(noct_max(fabs(v[0]), fabs(v[1])), fabs(v[2]));
    if (!(m > 0))
        return false;
    int e;
    frexp(m, &e);
    for (int k = 0; k < 3; ++k)
        out[k] = ldexp(v[k], -e);
    return true;
}

/* The unit vector along v into n, from v scaled as above, so that its
 * length neither overflows nor underflows; false (n = 0) if v is 0. */
static bool unit_vector(const double v[3], double n[3])
{
    double s[3];
    n[0] = n[1] = n[2] = 0;
    if (!scale_to_unit_range(v, s))
        return false;
    const double len = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    for (int k = 0; k < 3; ++k)
        n[k] = s[k] / len;
    return true;
}

/* The unit vector along u x v into n, computed on u and v scaled by
 * powers of two so that no product overflows or underflows, at any edge
 * length a mesh may have; false (n = 0) if u x v is 0 as computed: a
 * triangle without area as placed. */
static bool unit_cross(const double u[3], const double v[3], double n[3])
{
    double us[3], vs[3], c[3];
    n[0] = n[1] = n[2] = 0;
    if (!scale_to_unit_range(u, us) || !scale_to_unit_range(v, vs))
        return false;
    cross_into(us, vs, c);
    return unit_vector(c, n);
}

/* The first triangle segment pq enters, so far. */
typedef struct segment_entry {
    const double *p, *q;
    exact_ctx x;
    double best;
    uint32_t triangle;
    double *normal;
    bool flat;            /* that triangle has no area as placed */
} segment_entry;

static bool segment_meets(void *context, uint32_t i, double a[3], double b[3], double c[3])
{
    segment_entry *e = context;
    const int s1 = o3(&e->x, a, b, c, e->p), s2 = o3(&e->x, a, b, c, e->q);
    if (!seg_tri(&e->x, e->p, e->q, s1, s2, a, b, c))
        return false;
    double u[3], v[3], nn[3], d[3];
    for (int k = 0; k < 3; ++k) {
        u[k] = b[k] - a[k];
        v[k] = c[k] - a[k];
        d[k] = e->q[k] - e->p[k];
    }
    const bool area = unit_cross(u, v, nn);
    double f;
    if (area) {
        f = entry_fraction(e->p, e->q, a, b, c, nn, s1 == 0 && s2 == 0);
    } else {
        /* a point or a segment as placed (a shape far from the origin
         * for its size): where pq passes nearest its first corner, which
         * is within the triangle's extent of the meeting point */
        double num = 0, den = 0;
        for (int k = 0; k < 3; ++k) {
            num += (a[k] - e->p[k]) * d[k];
            den += d[k] * d[k];
        }
        f = den > 0 && num > 0 ? (num < den ? num / den : 1) : 0;
    }
    if (f < e->best || (f == e->best && i < e->triangle)) {
        e->best = f;
        e->triangle = i;
        e->flat = !area;
        if (area) {
            memcpy(e->normal, nn, sizeof nn);
        } else { /* against the segment: a normal a program can use */
            const double back[3] = {-d[0], -d[1], -d[2]};
            unit_vector(back, e->normal);
        }
    }
    return false; /* on: the least fraction */
}

noctStatus noct_segment_hit(const noctMesh *m, const double t[3], const double p[3],
                            const double q[3], bool *hit, double *fraction,
                            uint32_t *triangle, double normal[3], bool *flat)
{
    const placed B = {m, {t[0], t[1], t[2]}};
    const exact_ctx x = {NULL};
    *hit = false;
    *flat = false;
    *triangle = UINT32_MAX;
    normal[0] = normal[1] = normal[2] = 0;
    double slo[3], shi[3];
    for (int k = 0; k < 3; ++k) {
        slo[k] = noct_min(p[k], q[k]);
        shi[k] = noct_max(p[k], q[k]);
    }
    static const double zero[3] = {0, 0, 0};
    if (!boxes_overlap(m->lo, m->hi, t, slo, shi, zero))
        return NOCT_OK;
    bool inside;
    noctStatus st = noct_point_in_solid(m, t, p, &inside);
    if (st != NOCT_OK)
        return st;
    if (inside) {
        *hit = true;
        *fraction = 0;
        return NOCT_OK;
    }
    segment_entry e = {p, q, x, INFINITY, UINT32_MAX, normal, false};
    walk_triangles(&B, slo, shi, segment_meets, &e);
    *triangle = e.triangle;
    *flat = e.flat;
    const double best = e.best;
    if (*triangle != UINT32_MAX) {
        *hit = true;
        *fraction = best;
    }
    return NOCT_OK;
}

/* ---- box forms apart by more than a distance (margins) ------------------------ */

/* Is the separation of the two box forms along axis u (not unit), gap
 * (their projections' distance, less the allowances, in units of u),
 * more than d? */
static bool gap_beyond(double gap, const double u[3], double d)
{
    const double n = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    return gap > d * n * (1 + 0x1p-40);
}

bool noct_box_apart_by(const noct_box_slot *a, const double ta[3], const noct_box_slot *b,
                       const double tb[3], double d)
{
    double T[3];
    const double M = box_offset(a, ta, b, tb, T);
    const double unit = 256 * 0x1p-53 * M, dev = (double)a->dev + (double)b->dev;
    double C[3][3], la[3], lb[3];
    for (int i = 0; i < 3; ++i) {
        const double *u = a->e[i];
        la[i] = fabs(u[0]) + fabs(u[1]) + fabs(u[2]);
        for (int j = 0; j < 3; ++j)
            C[i][j] = u[0] * b->e[j][0] + u[1] * b->e[j][1] + u[2] * b->e[j][2];
        const double gap = fabs(u[0] * T[0] + u[1] * T[1] + u[2] * T[2]) - (double)a->own[i] -
                           (fabs(C[i][0]) + fabs(C[i][1]) + fabs(C[i][2])) - la[i] * dev -
                           unit * la[i];
        if (gap_beyond(gap, u, d))
            return true;
    }
    for (int j = 0; j < 3; ++j) {
        const double *u = b->e[j];
        lb[j] = fabs(u[0]) + fabs(u[1]) + fabs(u[2]);
        const double gap = fabs(u[0] * T[0] + u[1] * T[1] + u[2] * T[2]) - (double)b->own[j] -
                           (fabs(C[0][j]) + fabs(C[1][j]) + fabs(C[2][j])) - lb[j] * dev -
                           unit * lb[j];
        if (gap_beyond(gap, u, d))
            return true;
    }
    for (int i = 0; i < 3; ++i) {
        const double *x = a->e[i];
        for (int j = 0; j < 3; ++j) {
            const double *y = b->e[j];
            const double u[3] = {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2],
                                 x[0] * y[1] - x[1] * y[0]};
            const double l1 = fabs(u[0]) + fabs(u[1]) + fabs(u[2]);
            if (!(l1 > 1e-6 * la[i] * lb[j]))
                continue; /* (nearly) parallel edges */
            const double gap = fabs(u[0] * T[0] + u[1] * T[1] + u[2] * T[2]) -
                               box_radius(a->e, u) - box_radius(b->e, u) - l1 * dev - unit * l1;
            if (gap_beyond(gap, u, d))
                return true;
        }
    }
    return false;
}

/* ---- distance, for margins (world_near.c, world_query.c) -------------------------- */

/* A lower bound on the distance between two closed triangles that do not
 * meet, proved in floating point: for disjoint convex polytopes the
 * distance is the largest gap between their projections on a unit axis,
 * reached on the axis from one closest point to the other, which is a
 * face normal, the cross product of two edges, the difference of two
 * corners, or the perpendicular from a corner to an edge or from one
 * edge's line to a parallel one's (the same as from one of its corners).
 * The gap on every axis, computed with
 * an allowance for its rounding, bounds the distance from below whatever
 * the axis's own rounding; the largest is the bound, within a few
 * roundings of the distance. (A zero axis is skipped: that only lowers the
 * bound.) */
/* The gap along u proved: (least of B's projections - greatest of A's,
 * less twice the rounding of either) over |u|, or 0; s bounds every
 * coordinate. */
static double proved_gap(const double u[3], double a[3][3], double b[3][3], double s)
{
    const double l1 = fabs(u[0]) + fabs(u[1]) + fabs(u[2]);
    if (!(l1 > 0))
        return 0;
    double amax = -INFINITY, amin = INFINITY, bmax = -INFINITY, bmin = INFINITY;
    for (int i = 0; i < 3; ++i) {
        const double pa = noct_dot3(u, a[i]), pb = noct_dot3(u, b[i]);
        amax = noct_max(amax, pa);
        amin = noct_min(amin, pa);
        bmax = noct_max(bmax, pb);
        bmin = noct_min(bmin, pb);
    }
    /* each projection errs by at most 4 ulp of l1 s; the difference one
     * more */
    const double err = 0x1p-50 * l1 * s;
    const double gap = noct_max(bmin - amax, amin - bmax) - 2 * err;
    if (!(gap > 0))
        return 0;
    const double n = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    return gap / (n * (1 + 0x1p-48));
}

static double tri_tri_lower_bound(double a[3][3], double b[3][3])
{
    double s = 0;
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k)
            s = noct_max(s, noct_max(fabs(a[i][k]), fabs(b[i][k])));
    double ea[3][3], eb[3][3];
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) {
            ea[i][k] = a[(i + 1) % 3][k] - a[i][k];
            eb[i][k] = b[(i + 1) % 3][k] - b[i][k];
        }
    double best = 0, u[3], w[3], v[3];
    /* face normals */
    cross_into(ea[0], ea[1], u);
    best = noct_max(best, proved_gap(u, a, b, s));
    cross_into(eb[0], eb[1], u);
    best = noct_max(best, proved_gap(u, a, b, s));
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            /* edge against edge */
            cross_into(ea[i], eb[j], u);
            best = noct_max(best, proved_gap(u, a, b, s));
            /* corner against corner */
            for (int k = 0; k < 3; ++k)
                u[k] = b[j][k] - a[i][k];
            best = noct_max(best, proved_gap(u, a, b, s));
            /* corner against edge, both ways: (e x (p - q)) x e */
            for (int k = 0; k < 3; ++k)
                v[k] = a[i][k] - b[j][k];
            cross_into(eb[j], v, w);
            cross_into(w, eb[j], u);
            best = noct_max(best, proved_gap(u, a, b, s));
            for (int k = 0; k < 3; ++k)
                v[k] = b[j][k] - a[i][k];
            cross_into(ea[i], v, w);
            cross_into(w, ea[i], u);
            best = noct_max(best, proved_gap(u, a, b, s));
        }
    return best;
}

/* Squared distance between placed boxes [alo, ahi] + ta and [blo, bhi] + tb. */
static double box_dist2(const double alo[3], const double ahi[3], const double ta[3],
                        const double blo[3], const double bhi[3], const double tb[3])
{
    double s = 0;
    for (int k = 0; k < 3; ++k) {
        const double g = noct_max(noct_max((blo[k] + tb[k]) - (ahi[k] + ta[k]),
                                           (alo[k] + ta[k]) - (bhi[k] + tb[k])),
                                  0);
        s += g * g;
    }
    return s;
}

double noct_distance_slack(const noctMesh *a, const double ta[3], const noctMesh *b,
                           const double tb[3], double d)
{
    double scale = d;
    for (int k = 0; k < 3; ++k) {
        scale = noct_max(scale, noct_max(fabs(a->lo[k] + ta[k]), fabs(a->hi[k] + ta[k])));
        scale = noct_max(scale, noct_max(fabs(b->lo[k] + tb[k]), fabs(b->hi[k] + tb[k])));
    }
    return 0x1p-40 * scale;
}

bool noct_solids_within(const noctMesh *a, const double ta[3], const noctMesh *b,
                        const double tb[3], double d)
{
    const placed A = {a, {ta[0], ta[1], ta[2]}}, B = {b, {tb[0], tb[1], tb[2]}};
    const double reach = d + noct_distance_slack(a, ta, b, tb, d), reach2 = reach * reach;
    struct { uint32_t a, b; } stack[PAIR_STACK];
    size_t top = 0;
    stack[top].a = 0;
    stack[top++].b = 0;
    while (top > 0) {
        --top;
        const bvh_node *na = &a->nodes[stack[top].a];
        const bvh_node *nb = &b->nodes[stack[top].b];
        if (box_dist2(na->lo, na->hi, ta, nb->lo, nb->hi, tb) > reach2)
            continue;
        if (na->count > 0 && nb->count > 0) {
            for (uint32_t i = na->first; i < na->first + na->count; ++i) {
                double x[3][3];
                for (int c = 0; c < 3; ++c)
                    place(&A, a->tri[3 * i + c], x[c]);
                for (uint32_t j = nb->first; j < nb->first + nb->count; ++j) {
                    double y[3][3];
                    for (int c = 0; c < 3; ++c)
                        place(&B, b->tri[3 * j + c], y[c]);
                    if (tri_tri_lower_bound(x, y) <= reach)
                        return true;
                }
            }
            continue;
        }
        double sa = 0, sb = 0;
        for (int k = 0; k < 3; ++k) {
            sa += na->hi[k] - na->lo[k];
            sb += nb->hi[k] - nb->lo[k];
        }
        const bool split_a = nb->count > 0 || (na->count == 0 && sa >= sb);
        const uint32_t ia = stack[top].a, ib = stack[top].b;
        if (top + 2 > PAIR_STACK)
            return true; /* unreachable for meshes within the size limits; never misses */
        if (split_a) {
            stack[top].a = na->first;     stack[top++].b = ib;
            stack[top].a = na->first + 1; stack[top++].b = ib;
        } else {
            stack[top].a = ia; stack[top++].b = nb->first;
            stack[top].a = ia; stack[top++].b = nb->first + 1;
        }
    }
    return false;
}

noctStatus noctCollide(const noctMesh *a, const double ta[3], const noctMesh *b,
                       const double tb[3], noctAccuracy accuracy, bool *colliding,
                       noctNarrowStats *stats)
{
    NOCT_REQUIRE(a != NULL && ta != NULL && b != NULL && tb != NULL);
    NOCT_REQUIRE(colliding != NULL);
    if (accuracy != NOCT_ACCURACY_BOX && accuracy != NOCT_ACCURACY_CONVEX &&
        accuracy != NOCT_ACCURACY_EXACT)
        return NOCT_ERR_INVALID;
    for (int k = 0; k < 3; ++k) {
        if (!isfinite(ta[k]) || !isfinite(tb[k]))
            return NOCT_ERR_NONFINITE;
        if (fabs(ta[k]) > NOCT_MAX_COORDINATE || fabs(tb[k]) > NOCT_MAX_COORDINATE)
            return NOCT_ERR_TOO_LARGE;
    }
    /* The levels past the box test take microseconds: timing them (two
     * vDSO clock reads) costs a few per cent, and only with stats. A
     * world times its whole narrowphase loop instead. */
    bool timed = stats != NULL && accuracy != NOCT_ACCURACY_BOX &&
                 boxes_overlap(a->lo, a->hi, ta, b->lo, b->hi, tb);
    double t0 = timed ? now() : 0;
    noctStatus st = collide_levels(a, ta, b, tb, accuracy, colliding, stats);
    if (timed)
        *(accuracy == NOCT_ACCURACY_CONVEX ? &stats->seconds_convex
                                           : &stats->seconds_exact) += now() - t0;
    return st;
}

noctStatus noctCollideTransformed(const noctMesh *a, const noctTransform *xa, const noctMesh *b,
                                  const noctTransform *xb, noctAccuracy accuracy,
                                  bool *colliding, noctNarrowStats *stats, noctError *err)
{
    NOCT_REQUIRE(a != NULL && xa != NULL && b != NULL && xb != NULL && colliding != NULL);
    const noctTransform *x[2] = {xa, xb};
    const noctMesh *m[2] = {a, b};
    noctMesh *rotated[2] = {NULL, NULL};
    noctStatus st = NOCT_OK;
    for (int i = 0; i < 2 && st == NOCT_OK; ++i) {
        double R[9];
        st = noctTransformCheck(x[i], err);
        if (st == NOCT_OK)
            st = noctQuatToMatrix(&x[i]->q, R, err);
        if (st == NOCT_OK && !noct_is_identity(R)) {
            st = noct_mesh_rotated(m[i], R, &rotated[i], err);
            if (st == NOCT_OK)
                m[i] = rotated[i];
        }
    }
    if (st == NOCT_OK) {
        st = noctCollide(m[0], xa->p, m[1], xb->p, accuracy, colliding, stats);
        if (st != NOCT_OK)
            noct_fail(err, st, -1, 0, "collision test: %s", noctStatusString(st));
    }
    noctMeshDestroy(rotated[0]);
    noctMeshDestroy(rotated[1]);
    return st;
}
