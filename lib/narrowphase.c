/* SPDX-License-Identifier: MIT */
/*
 * The narrowphase's collision levels: the report's hierarchy of partial
 * decision mechanisms (the queries and distances are in
 * narrowphase_query.c and narrowphase_distance.c).
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
#include "config.h"

#include <ccd/ccd.h>
#include <math.h>
#include <string.h>

#include <noctree/narrowphase.h>

#include "narrowphase_internal.h"
#include "vec3.h"

/* ---- the boundaries: triangle pairs through the BVHs ---------------------- */

typedef struct boundary_walk {
    const placed *A, *B;
    const exact_ctx *x;
    noctNarrowStats *st;
} boundary_walk;

static inline bool boundary_prune(void *context, const bvh_node *na, const bvh_node *nb)
{
    const boundary_walk *b = context;
    if (b->st)
        ++b->st->bvh_pairs;
    return !noct_boxes_overlap(na->lo, na->hi, b->A->t, nb->lo, nb->hi, b->B->t);
}

static inline bool boundary_pair(void *context, uint32_t i, double ta[3][3], uint32_t j,
                                 double tb[3][3])
{
    (void)i;
    (void)j;
    const boundary_walk *b = context;
    if (b->st)
        ++b->st->triangle_pairs;
    return tri_tri(b->x, ta, tb);
}

/* Do the boundaries of A and B meet? (Exact; true also if the walk's
 * stack would overflow, which meshes within the size limits never do.) */
static bool boundaries_meet(const placed *A, const placed *B, const exact_ctx *x,
                            noctNarrowStats *st)
{
    boundary_walk b = {A, B, x, st};
    return noct_bvh_pair_walk(A, B, boundary_prune, boundary_pair, &b);
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
noctStatus noct_contains(const placed *B, const double p[3], const exact_ctx *x,
                         bool *inside)
{
    const noctMesh *m = B->m;
    if (m->surface) { /* encloses nothing: p, not on it, is off it */
        *inside = false;
        return NOCT_OK;
    }
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
            noct_place_vertex(B, m->tri[3 * t], a);
            noct_place_vertex(B, m->tri[3 * t + 1], b);
            noct_place_vertex(B, m->tri[3 * t + 2], c);
            const int r = noct_parity_step(x, p, q, a, b, c);
            ambiguous = r < 0;
            crossings += r > 0;
        }
        if (!ambiguous) {
            *inside = crossings % 2 == 1;
            return NOCT_OK;
        }
    }
    return NOCT_ERR_NUMERIC;
}

noctStatus noct_piece_inside(const placed *in, const placed *out, const exact_ctx *x,
                             noctNarrowStats *stats, bool *inside)
{
    *inside = false;
    NOCT_INVARIANT(in->m->npieces > 0); /* every mesh, view or not, names its pieces */
    if (!noct_may_hold_piece(in, out))
        return NOCT_OK;
    for (size_t i = 0; i < in->m->npieces; ++i) {
        double p[3];
        noct_place_vertex(in, in->m->piece[i], p);
        bool in_box = true;
        for (int k = 0; k < 3 && in->m->npieces > 1; ++k)
            in_box = in_box && out->m->lo[k] + out->t[k] <= p[k] &&
                     p[k] <= out->m->hi[k] + out->t[k];
        if (!in_box)
            continue;
        if (stats)
            ++stats->containment_tests;
        const noctStatus st = noct_contains(out, p, x, inside);
        if (st != NOCT_OK || *inside)
            return st;
    }
    return NOCT_OK;
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
        noct_place_vertex(P, (uint32_t)i, pv->v[i]);
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
 * noct_box_decide() for a point p and the slot b placed at tb: the point
 * is the slot of no size (c = 0, e = 0, dev = 0, shrink 0) placed at p,
 * its one vertex p itself, exact (fl(0 + p) = p). With A's radii, products
 * a_i.b_j and deviation exact zeros, every quantity below is bit for bit
 * the one noct_box_decide() computes for that slot, and the bounds on
 * rounding are its own. The separation test on B's face axes e[j] then
 * proves p outside B's solid (A's face axes and the nine cross products
 * are zero: no separating axis). The proof on B's face normals (the cross
 * products of its edges) proves p inside the ideal box shrunk by B's
 * dual, and so inside the solid (box_contains' lemma): a point lies in a
 * parallelepiped iff its projection on each of the three face normals
 * lies within the parallelepiped's, so these three axes suffice (the
 * proof's other twelve are zero for a point, and noct_box_decide() gives
 * up on them; here they have nothing to prove).
 */
int noct_point_slot_decide(const double p[3], const noct_box_slot *b, const double tb[3])
{
    static const noct_box_slot point; /* zero: c, e, size, dev, shrink */
    double T[3];
    const double M = box_offset(&point, p, b, tb, T);
    const double unit = 256 * 0x1p-53 * M, dev = (double)b->dev;
    double bmax[3];
    for (int j = 0; j < 3; ++j) {
        const double *u = b->e[j];
        const double lb = fabs(u[0]) + fabs(u[1]) + fabs(u[2]);
        const double gap = fabs(u[0] * T[0] + u[1] * T[1] + u[2] * T[2]) - (double)b->own[j] -
                           lb * dev;
        if (gap > unit * lb)
            return -1;
        bmax[j] = noct_max(fabs(u[0]), noct_max(fabs(u[1]), fabs(u[2])));
    }
    if (!(b->shrink < 1))
        return 0;
    const double fb = 1 - (double)b->shrink;
    for (int n = 0; n < 3; ++n) {
        const double *x = b->e[(n + 1) % 3], *y = b->e[(n + 2) % 3];
        const double u[3] = {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2],
                             x[0] * y[1] - x[1] * y[0]};
        const double l1 = fabs(u[0]) + fabs(u[1]) + fabs(u[2]);
        const double pq = bmax[(n + 1) % 3] * bmax[(n + 2) % 3];
        const double d = fabs(u[0] * T[0] + u[1] * T[1] + u[2] * T[2]);
        if (!(d + unit * (l1 + pq) < fb * box_radius(b->e, u)))
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
        bool inside;
        noctStatus s = noct_piece_inside(pair[i][0], pair[i][1], &x, st, &inside);
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
    noct_place_vertex(o, m->hull[best], p);
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
    /* A surface's hull may be flat, where GJK can miss an overlap, and
     * its tolerance a touching pair: GJK's "apart" stands for a surface
     * only when the boundaries are proved apart (a surface inside a
     * solid is inside its hull, which GJK, on a hull with a volume,
     * finds). So the level never misses a pair with a surface. */
    if (!*hit && (A->m->surface || B->m->surface))
        *hit = noct_solids_within(A->m, A->t, B->m, B->t, 0);
    return NOCT_OK;
}

/* ---- the levels in order: noctCollide() ------------------------------------- */

const char *noctAccuracyName(noctAccuracy accuracy)
{
    switch (accuracy) {
    case NOCT_ACCURACY_BOX: return "box";
    case NOCT_ACCURACY_CONVEX: return "convex";
    case NOCT_ACCURACY_EXACT: return "exact";
    case NOCT_ACCURACY_CONTINUOUS: return "continuous";
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
    if (!noct_boxes_overlap(a->lo, a->hi, ta, b->lo, b->hi, tb)) {
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
    case NOCT_ACCURACY_CONTINUOUS: /* without motion */
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

noctStatus noctCollide(const noctMesh *a, const double ta[3], const noctMesh *b,
                       const double tb[3], noctAccuracy accuracy, bool *colliding,
                       noctNarrowStats *stats)
{
    NOCT_REQUIRE(a != NULL && ta != NULL && b != NULL && tb != NULL);
    NOCT_REQUIRE(colliding != NULL);
    if (accuracy != NOCT_ACCURACY_BOX && accuracy != NOCT_ACCURACY_CONVEX &&
        accuracy != NOCT_ACCURACY_EXACT && accuracy != NOCT_ACCURACY_CONTINUOUS)
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
                 noct_boxes_overlap(a->lo, a->hi, ta, b->lo, b->hi, tb);
    double t0 = timed ? noct_seconds() : 0;
    noctStatus st = collide_levels(a, ta, b, tb, accuracy, colliding, stats);
    if (timed)
        *(accuracy == NOCT_ACCURACY_CONVEX ? &stats->seconds_convex
                                           : &stats->seconds_exact) += noct_seconds() - t0;
    return st;
}

noctStatus noct_meshes_rotated(const noctMesh *m[2], const noctTransform *const x[2],
                               noctMesh *rotated[2], noctError *err)
{
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
    return st;
}

noctStatus noctCollideTransformed(const noctMesh *a, const noctTransform *xa, const noctMesh *b,
                                  const noctTransform *xb, noctAccuracy accuracy,
                                  bool *colliding, noctNarrowStats *stats, noctError *err)
{
    NOCT_REQUIRE(a != NULL && xa != NULL && b != NULL && xb != NULL && colliding != NULL);
    const noctTransform *x[2] = {xa, xb};
    const noctMesh *m[2] = {a, b};
    if (accuracy == NOCT_ACCURACY_EXACT || accuracy == NOCT_ACCURACY_CONTINUOUS) {
        /* The exact level decides on rotated views: a rotated mesh made
         * for the call (its checks, hull and hierarchy) costs a hundred
         * times the test. */
        double R[2][9];
        bool turned[2] = {false, false};
        for (int i = 0; i < 2; ++i) {
            noctStatus st = noctTransformCheck(x[i], err);
            if (st == NOCT_OK)
                st = noctQuatToMatrix(&x[i]->q, R[i], err);
            if (st != NOCT_OK)
                return st;
            turned[i] = !noct_is_identity(R[i]);
        }
        if (turned[0] || turned[1])
            return noct_collide_exact_turned(a, xa, b, xb, R, turned, colliding, stats, err);
    }
    noctMesh *rotated[2] = {NULL, NULL};
    noctStatus st = noct_meshes_rotated(m, x, rotated, err);
    if (st == NOCT_OK) {
        st = noctCollide(m[0], xa->p, m[1], xb->p, accuracy, colliding, stats);
        if (st != NOCT_OK)
            noct_fail(err, st, -1, 0, "collision test: %s", noctStatusString(st));
    }
    noctMeshDestroy(rotated[0]);
    noctMeshDestroy(rotated[1]);
    return st;
}
