/* SPDX-License-Identifier: MIT */
/*
 * The narrowphase's distances: are two placed box forms apart by more
 * than a distance (a separating axis proves it), and are two placed
 * solids within a distance (their triangles' distances, bounded from
 * below in floating point, through the pair walk). The margin's near
 * pairs (world_near.c) and noctWorldQueryNear() ask them.
 */
#include "config.h"

#include <math.h>
#include <string.h>

#include "narrowphase_internal.h"
#include "vec3.h"

/* ---- box forms apart by more than a distance ------------------------------------ */

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

/* ---- triangles' distances, proved from below ------------------------------------ */

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

typedef struct within_walk {
    const double *ta, *tb;
    double reach, reach2;
} within_walk;

static inline bool within_prune(void *context, const bvh_node *na, const bvh_node *nb)
{
    const within_walk *w = context;
    return box_dist2(na->lo, na->hi, w->ta, nb->lo, nb->hi, w->tb) > w->reach2;
}

static inline bool within_pair(void *context, uint32_t i, double x[3][3], uint32_t j,
                               double y[3][3])
{
    (void)i;
    (void)j;
    const within_walk *w = context;
    return tri_tri_lower_bound(x, y) <= w->reach;
}

bool noct_solids_within(const noctMesh *a, const double ta[3], const noctMesh *b,
                        const double tb[3], double d)
{
    const placed A = {a, {ta[0], ta[1], ta[2]}}, B = {b, {tb[0], tb[1], tb[2]}};
    within_walk w = {ta, tb, 0, 0};
    w.reach = d + noct_distance_slack(a, ta, b, tb, d);
    w.reach2 = w.reach * w.reach;
    /* the walk's overflow answers true: it never misses a pair within d */
    return noct_bvh_pair_walk(&A, &B, within_prune, within_pair, &w);
}


/* ---- the distance and the nearest points ---------------------------------------- */

static inline double noct_clamp(double x, double lo, double hi)
{
    return x < lo ? lo : (x > hi ? hi : x);
}

/* The nearest points of segments p1q1 and p2q2, in floating point
 * (degenerate segments included); returns the squared distance. */
static double seg_seg_nearest(const double p1[3], const double q1[3], const double p2[3],
                              const double q2[3], double c1[3], double c2[3])
{
    double d1[3], d2[3], r[3];
    noct_sub3(q1, p1, d1);
    noct_sub3(q2, p2, d2);
    noct_sub3(p1, p2, r);
    const double a = noct_dot3(d1, d1), e = noct_dot3(d2, d2), f = noct_dot3(d2, r);
    double s = 0, t = 0;
    if (!(a > 0) && !(e > 0)) {
        s = t = 0;
    } else if (!(a > 0)) {
        t = noct_clamp(f / e, 0, 1);
    } else {
        const double c = noct_dot3(d1, r);
        if (!(e > 0)) {
            s = noct_clamp(-c / a, 0, 1);
        } else {
            const double b = noct_dot3(d1, d2), denom = a * e - b * b;
            s = denom > 0 ? noct_clamp((b * f - c * e) / denom, 0, 1) : 0;
            t = (b * s + f) / e;
            if (t < 0) {
                t = 0;
                s = noct_clamp(-c / a, 0, 1);
            } else if (t > 1) {
                t = 1;
                s = noct_clamp((b - c) / a, 0, 1);
            }
        }
    }
    double g[3];
    for (int k = 0; k < 3; ++k) {
        c1[k] = p1[k] + d1[k] * s;
        c2[k] = p2[k] + d2[k] * t;
        g[k] = c1[k] - c2[k];
    }
    return noct_dot3(g, g);
}

/* The point of closed triangle abc nearest p, in floating point (by the
 * Voronoi regions of its corners, edges and face); false if the triangle
 * is too flat for the face's formula (the caller's edges then decide). */
static bool point_tri_nearest(const double p[3], const double a[3], const double b[3],
                              const double c[3], double out[3])
{
    double ab[3], ac[3], ap[3], bp[3], cp[3];
    noct_sub3(b, a, ab);
    noct_sub3(c, a, ac);
    noct_sub3(p, a, ap);
    const double d1 = noct_dot3(ab, ap), d2 = noct_dot3(ac, ap);
    if (d1 <= 0 && d2 <= 0) {
        noct_copy3(a, out);
        return true;
    }
    noct_sub3(p, b, bp);
    const double d3 = noct_dot3(ab, bp), d4 = noct_dot3(ac, bp);
    if (d3 >= 0 && d4 <= d3) {
        noct_copy3(b, out);
        return true;
    }
    noct_sub3(p, c, cp);
    const double d5 = noct_dot3(ab, cp), d6 = noct_dot3(ac, cp);
    if (d6 >= 0 && d5 <= d6) {
        noct_copy3(c, out);
        return true;
    }
    const double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        const double v = d1 / (d1 - d3);
        for (int k = 0; k < 3; ++k)
            out[k] = a[k] + v * ab[k];
        return true;
    }
    if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        const double w = d2 / (d2 - d6);
        for (int k = 0; k < 3; ++k)
            out[k] = a[k] + w * ac[k];
        return true;
    }
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        for (int k = 0; k < 3; ++k)
            out[k] = b[k] + w * (c[k] - b[k]);
        return true;
    }
    const double sum = va + vb + vc;
    if (!(sum > 0) || !(va >= 0 && vb >= 0 && vc >= 0))
        return false;
    const double v = vb / sum, w = vc / sum;
    for (int k = 0; k < 3; ++k)
        out[k] = a[k] + ab[k] * v + ac[k] * w;
    return true;
}

/* The nearest points of two closed triangles that do not meet, in floating
 * point: the nearest pair of two disjoint triangles is a corner of one
 * against the other or an edge of each against an edge of the other.
 * Returns the squared distance between pa and pb. */
static double tri_tri_nearest(double a[3][3], double b[3][3], double pa[3], double pb[3])
{
    double best = INFINITY, c1[3], c2[3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const double d = seg_seg_nearest(a[i], a[(i + 1) % 3], b[j], b[(j + 1) % 3], c1, c2);
            if (d < best) {
                best = d;
                noct_copy3(c1, pa);
                noct_copy3(c2, pb);
            }
        }
    for (int i = 0; i < 3; ++i) {
        double g[3];
        if (point_tri_nearest(a[i], b[0], b[1], b[2], c2)) {
            noct_sub3(a[i], c2, g);
            const double d = noct_dot3(g, g);
            if (d < best) {
                best = d;
                noct_copy3(a[i], pa);
                noct_copy3(c2, pb);
            }
        }
        if (point_tri_nearest(b[i], a[0], a[1], a[2], c1)) {
            noct_sub3(b[i], c1, g);
            const double d = noct_dot3(g, g);
            if (d < best) {
                best = d;
                noct_copy3(c1, pa);
                noct_copy3(b[i], pb);
            }
        }
    }
    return best;
}

/* The two placed meshes of a distance search, scaled by a power of two so
 * that squared distances neither overflow nor underflow: every coordinate
 * is multiplied by scale (exactly) before any arithmetic. */
typedef struct dist_walk {
    const double *ta, *tb;
    double scale;
    double best2;              /* the best squared distance so far (scaled) */
    double pa[3], pb[3];       /* its points (scaled) */
    uint32_t ia, ib;           /* its triangles (BVH order) */
    bool found;
    double reach2;             /* the lower bound walk's reach, squared */
    double lower;              /* the least lower bound (scaled) */
    uint64_t pairs, nodes;
} dist_walk;

/* Squared distance between boxes, scaled: each gap is computed, then
 * scaled, then squared. */
static double box_dist2_scaled(const bvh_node *na, const double ta[3], const bvh_node *nb,
                               const double tb[3], double scale)
{
    double s = 0;
    for (int k = 0; k < 3; ++k) {
        const double g = noct_max(noct_max((nb->lo[k] + tb[k]) - (na->hi[k] + ta[k]),
                                           (na->lo[k] + ta[k]) - (nb->hi[k] + tb[k])),
                                  0) *
                         scale;
        s += g * g;
    }
    return s;
}

static inline void scale_tri(double x[3][3], double scale)
{
    if (scale != 1)
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < 3; ++k)
                x[i][k] *= scale;
}

static inline bool nearest_prune(void *context, const bvh_node *na, const bvh_node *nb)
{
    dist_walk *w = context;
    ++w->nodes;
    return box_dist2_scaled(na, w->ta, nb, w->tb, w->scale) >= w->best2;
}

static inline bool nearest_pair(void *context, uint32_t i, double x[3][3], uint32_t j,
                                double y[3][3])
{
    dist_walk *w = context;
    ++w->pairs;
    scale_tri(x, w->scale);
    scale_tri(y, w->scale);
    double pa[3], pb[3];
    const double d2 = tri_tri_nearest(x, y, pa, pb);
    if (d2 < w->best2) {
        w->best2 = d2;
        noct_copy3(pa, w->pa);
        noct_copy3(pb, w->pb);
        w->ia = i;
        w->ib = j;
        w->found = true;
    }
    return false;
}

static inline bool lower_prune(void *context, const bvh_node *na, const bvh_node *nb)
{
    dist_walk *w = context;
    ++w->nodes;
    return box_dist2_scaled(na, w->ta, nb, w->tb, w->scale) > w->reach2;
}

static inline bool lower_pair(void *context, uint32_t i, double x[3][3], uint32_t j,
                              double y[3][3])
{
    (void)i;
    (void)j;
    dist_walk *w = context;
    ++w->pairs;
    scale_tri(x, w->scale);
    scale_tri(y, w->scale);
    w->lower = noct_min(w->lower, tri_tri_lower_bound(x, y));
    return false;
}

/* The largest magnitude of a placed mesh's box corners. */
static double placed_magnitude(const noctMesh *m, const double t[3])
{
    double s = 0;
    for (int k = 0; k < 3; ++k)
        s = noct_max(s, noct_max(fabs(m->lo[k] + t[k]), fabs(m->hi[k] + t[k])));
    return s;
}

/* Does (a, ta) come before (b, tb) in a canonical order of the two
 * arguments, so that a call and its mirror search in the same order? */
static bool placed_first(const noctMesh *a, const double ta[3], const noctMesh *b,
                         const double tb[3])
{
    for (int k = 0; k < 3; ++k) {
        const double la = a->lo[k] + ta[k], lb = b->lo[k] + tb[k];
        if (la != lb)
            return la < lb;
    }
    for (int k = 0; k < 3; ++k) {
        const double ha = a->hi[k] + ta[k], hb = b->hi[k] + tb[k];
        if (ha != hb)
            return ha < hb;
    }
    if (a->nv != b->nv)
        return a->nv < b->nv;
    if (a->nt != b->nt)
        return a->nt < b->nt;
    for (size_t i = 0; i < 3 * a->nv; ++i)
        if (a->v[i] != b->v[i])
            return a->v[i] < b->v[i];
    for (size_t i = 0; i < 3 * a->nt; ++i)
        if (a->tri[i] != b->tri[i])
            return a->tri[i] < b->tri[i];
    return true; /* the same placed mesh: either order gives the same */
}

static void no_triangle(uint32_t t[3])
{
    t[0] = t[1] = t[2] = NOCT_NO_TRIANGLE;
}

static void mirror(noctDistanceResult *r)
{
    for (int k = 0; k < 3; ++k) {
        const double p = r->point_a[k];
        r->point_a[k] = r->point_b[k];
        r->point_b[k] = p;
        const uint32_t t = r->triangle_a[k];
        r->triangle_a[k] = r->triangle_b[k];
        r->triangle_b[k] = t;
    }
}

noctStatus noct_distance_placed(const noctMesh *a, const double ta[3], const noctMesh *b,
                                const double tb[3], double max_distance,
                                noctDistanceResult *r, noctNarrowStats *stats)
{
    if (!placed_first(a, ta, b, tb)) {
        const noctStatus st = noct_distance_placed(b, tb, a, ta, max_distance, r, stats);
        mirror(r);
        return st;
    }
    memset(r, 0, sizeof *r);
    no_triangle(r->triangle_a);
    no_triangle(r->triangle_b);
    const double mag = noct_max(placed_magnitude(a, ta), placed_magnitude(b, tb));
    /* Scale tiny meshes up (exactly) so that squares of their distances do
     * not underflow; NOCT_MAX_COORDINATE keeps large ones' squares finite. */
    double scale = 1;
    if (mag > 0 && mag < 0x1p-200)
        scale = noct_pow2(-ilogb(mag));
    const double slack = 0x1p-40 * noct_max(mag, isfinite(max_distance) ? max_distance : 0);
    const double reach_max = isfinite(max_distance)
                                 ? (max_distance * (1 + 0x1p-40) + slack) * scale
                                 : (double)INFINITY;
    const placed A = {a, {ta[0], ta[1], ta[2]}}, B = {b, {tb[0], tb[1], tb[2]}};
    dist_walk w = {ta, tb, scale, 0, {0, 0, 0}, {0, 0, 0}, 0, 0, false, 0, INFINITY, 0, 0};
    const bool far = box_dist2_scaled(&a->nodes[0], ta, &b->nodes[0], tb, scale) >
                     reach_max * reach_max;
    if (!far) {
        bool colliding = false;
        const noctStatus st =
            noctCollide(a, ta, b, tb, NOCT_ACCURACY_EXACT, &colliding, stats);
        if (st != NOCT_OK)
            return st;
        if (colliding) {
            r->colliding = true;
            for (int k = 0; k < 3; ++k) {
                const double lo = noct_max(a->lo[k] + ta[k], b->lo[k] + tb[k]);
                const double hi = noct_min(a->hi[k] + ta[k], b->hi[k] + tb[k]);
                r->point_a[k] = r->point_b[k] = lo + (hi - lo) / 2;
            }
            return NOCT_OK;
        }
        w.best2 = reach_max * reach_max;
        noct_bvh_pair_walk(&A, &B, nearest_prune, nearest_pair, &w);
    }
    /* the slack, and the points' rounding allowance, scaled */
    const double slack_s = slack * scale, allow = 0x1p-47 * mag * scale;
    if (!w.found) {
        /* Nothing within the reach in floating point: prove it. */
        if (!far) {
            w.reach2 = reach_max * reach_max;
            w.lower = INFINITY;
            noct_bvh_pair_walk(&A, &B, lower_prune, lower_pair, &w);
        }
        if (far || w.lower > max_distance * scale) {
            r->beyond = true;
            r->lower = max_distance;
            r->distance = r->upper = INFINITY;
            if (stats) {
                stats->bvh_pairs += w.nodes;
                stats->triangle_pairs += w.pairs;
            }
            return NOCT_OK;
        }
        /* Floating point and the proof disagree at the reach: search
         * without it. */
        w.best2 = INFINITY;
        noct_bvh_pair_walk(&A, &B, nearest_prune, nearest_pair, &w);
        NOCT_INVARIANT(w.found);
    }
    const double d = sqrt(w.best2);
    const double upper = d * (1 + 0x1p-50) + 2 * allow;
    const double reach = upper * (1 + 0x1p-40) + slack_s;
    w.reach2 = reach * reach;
    w.lower = upper;
    noct_bvh_pair_walk(&A, &B, lower_prune, lower_pair, &w);
    r->lower = w.lower / scale;
    r->upper = upper / scale;
    r->distance = noct_min(noct_max(d / scale, r->lower), r->upper);
    for (int k = 0; k < 3; ++k) {
        r->point_a[k] = w.pa[k] / scale;
        r->point_b[k] = w.pb[k] / scale;
        r->triangle_a[k] = a->tri[3 * w.ia + k];
        r->triangle_b[k] = b->tri[3 * w.ib + k];
    }
    if (stats) {
        stats->bvh_pairs += w.nodes;
        stats->triangle_pairs += w.pairs;
    }
    return NOCT_OK;
}

noctStatus noctDistance(const noctMesh *a, const noctTransform *xa, const noctMesh *b,
                        const noctTransform *xb, double max_distance,
                        noctDistanceResult *result, noctNarrowStats *stats, noctError *err)
{
    NOCT_REQUIRE(a != NULL && xa != NULL && b != NULL && xb != NULL && result != NULL);
    if (isnan(max_distance))
        return noct_fail(err, NOCT_ERR_NONFINITE, -1, 0, "distance: max_distance is NaN");
    if (max_distance < 0)
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0,
                         "distance: max_distance %g is negative", max_distance);
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
        st = noct_distance_placed(m[0], xa->p, m[1], xb->p, max_distance, result, stats);
        if (st != NOCT_OK)
            noct_fail(err, st, -1, 0, "distance: %s", noctStatusString(st));
    }
    noctMeshDestroy(rotated[0]);
    noctMeshDestroy(rotated[1]);
    return st;
}
