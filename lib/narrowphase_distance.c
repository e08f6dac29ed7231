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
#include <stdlib.h>
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

static NOCT_ALWAYS_INLINE bool found_axis(double *axis, const double u[3])
{
    if (axis != NULL)
        memcpy(axis, u, 3 * sizeof *axis);
    return true;
}

/* noct_box_apart_by(), and the axis that proved it into axis (when not
 * NULL). */
static NOCT_ALWAYS_INLINE bool apart_by(const noct_box_slot *a, const double ta[3],
                                        const noct_box_slot *b, const double tb[3], double d,
                                        double *axis)
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
            return found_axis(axis, u);
    }
    for (int j = 0; j < 3; ++j) {
        const double *u = b->e[j];
        lb[j] = fabs(u[0]) + fabs(u[1]) + fabs(u[2]);
        const double gap = fabs(u[0] * T[0] + u[1] * T[1] + u[2] * T[2]) - (double)b->own[j] -
                           (fabs(C[0][j]) + fabs(C[1][j]) + fabs(C[2][j])) - lb[j] * dev -
                           unit * lb[j];
        if (gap_beyond(gap, u, d))
            return found_axis(axis, u);
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
                return found_axis(axis, u);
        }
    }
    return false;
}

bool noct_box_apart_by(const noct_box_slot *a, const double ta[3], const noct_box_slot *b,
                       const double tb[3], double d)
{
    return apart_by(a, ta, b, tb, d, NULL);
}

/* noct_box_apart_by() for a point p, the slot of no size (c = 0, e = 0,
 * dev = 0) placed at p (fl(0 + p) = p), as noct_point_slot_decide()
 * takes it: A's face axes and the nine cross products are zero (gap 0,
 * not above d times a norm of 0; l1 = 0 skips a cross product), and on
 * B's face axes every term of A is an exact zero, so each gap below is
 * bit for bit apart_by()'s, and so is the answer on one axis.
 *
 * Then the three face axes together. On axis u_j = e[j] the gap G_j
 * (computed as above, its allowance taken off) bounds |u_j.(x - p)| from
 * below for every point x of the solid, so with the unit vectors
 * w_j = u_j / |u_j| and v = x - p, |w_j.v| >= g_j = max(G_j, 0) / |u_j|.
 * The three are a basis within cos <= eps of orthonormal: their Gram
 * matrix W has ones on its diagonal and |w_i.w_j| <= eps off it, so its
 * largest eigenvalue is at most 1 + 2 eps (Gershgorin), and
 * sum_j (w_j.v)^2 = |W v|^2 <= (1 + 2 eps) |v|^2. Hence every x of the
 * solid has |x - p|^2 >= sum_j g_j^2 / (1 + 2 eps): the point is farther
 * than d when that exceeds d^2.
 *
 * Rounding. q_j = fl(u_j.u_j) is within (1 +- 3u) of |u_j|^2 (u = 2^-53)
 * when it is at least 2^-900 (the squares' underflow then counts for
 * nothing); a smaller q_j (or one not finite) skips the test. eps: the
 * test asks |fl(u_i.u_j)| <= 2^-22 min(q_i, q_j); the dot product errs
 * by at most 3u |u_i| |u_j| (Cauchy-Schwarz) plus 2^-1073 for underflow,
 * and min(|u_i|^2, |u_j|^2) <= |u_i| |u_j|, so |w_i.w_j| <= 2^-22
 * (1 + 4u) + 3u + 2^-173 <= 2^-21 = eps, and 1 + 2 eps = 1 + 2^-20. A
 * slot whose axes are farther from orthogonal (a sheared parallelepiped)
 * skips the test; a rotation's stored axes are within some 2^-40.
 * t_j = fl(max(G_j, 0) / fl(sqrt(q_j))) <= (1 + 5u) g_j (+ 2^-1075 where
 * it underflows), and s = the sum of fl(t_j^2) <= (1 + 2^-48) sum g_j^2
 * + 2^-1072. With c2 = max(fl(fl(d^2) (1 + 2^-16)), 2^-990), which is at
 * least d^2 (1 + 2^-16)(1 - 2u)^2 when d^2 is normal and 2^30 d^2
 * otherwise, s > c2 gives sum g_j^2 > (s - 2^-1072) / (1 + 2^-48) >=
 * d^2 (1 + 2^-17) > d^2 (1 + 2^-20): |x - p| > d for every x. Every
 * quantity is finite: coordinates and sizes are within NOCT_MAX_COORDINATE
 * (1e100), squares within 1e201. */
bool noct_point_apart_by(const double p[3], const noct_box_slot *b, const double tb[3],
                         double d)
{
    static const noct_box_slot point; /* zero */
    double T[3], G[3];
    const double M = box_offset(&point, p, b, tb, T);
    const double unit = 256 * 0x1p-53 * M, dev = (double)b->dev;
    for (int j = 0; j < 3; ++j) {
        const double *u = b->e[j];
        const double lb = fabs(u[0]) + fabs(u[1]) + fabs(u[2]);
        const double gap =
            fabs(u[0] * T[0] + u[1] * T[1] + u[2] * T[2]) - (double)b->own[j] - lb * dev - unit * lb;
        if (gap_beyond(gap, u, d))
            return true;
        G[j] = gap;
    }
    double q[3];
    for (int j = 0; j < 3; ++j) {
        q[j] = noct_dot3(b->e[j], b->e[j]);
        if (!(q[j] >= 0x1p-900 && q[j] <= 0x1p900))
            return false;
    }
    for (int j = 0; j < 3; ++j) {
        const int i = (j + 1) % 3;
        if (!(fabs(noct_dot3(b->e[i], b->e[j])) <= 0x1p-22 * noct_min(q[i], q[j])))
            return false;
    }
    double s = 0;
    for (int j = 0; j < 3; ++j) {
        const double t = noct_max(G[j], 0) / sqrt(q[j]);
        s += t * t;
    }
    return s > noct_max(d * d * (1 + 0x1p-16), 0x1p-990);
}

bool noct_box_apart_axis(const noct_box_slot *a, const double ta[3], const noct_box_slot *b,
                         const double tb[3], double d, double axis[3])
{
    return apart_by(a, ta, b, tb, d, axis);
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
static double proved_gap(const double axis[3], double a[3][3], double b[3][3], double s)
{
    double u[3];
    if (!noct_gap_axis(axis, u))
        return 0;
    const double l1 = fabs(u[0]) + fabs(u[1]) + fabs(u[2]);
    double amax = -INFINITY, amin = INFINITY, bmax = -INFINITY, bmin = INFINITY;
    for (int i = 0; i < 3; ++i) {
        const double pa = noct_dot3(u, a[i]), pb = noct_dot3(u, b[i]);
        amax = noct_max(amax, pa);
        amin = noct_min(amin, pa);
        bmax = noct_max(bmax, pb);
        bmin = noct_min(bmin, pb);
    }
    /* each projection errs by at most 4 ulp of l1 s (and NOCT_GAP_TINY
     * where it underflows); the difference one more */
    const double err = 0x1p-50 * l1 * s + NOCT_GAP_TINY;
    return noct_gap_over(noct_max(bmin - amax, amin - bmax) - 2 * err, u);
}

/* The bound, or any proved bound of at least target once one axis gives
 * it: a caller that takes the least bound over many pairs needs no more of
 * a pair than that it is not below the least so far. With a finite target
 * the direction between the triangles' centroids (times 3) comes first:
 * any axis bounds the distance from below, and for triangles apart by
 * more than their size it is within a little of the pair's distance, so
 * that most pairs the proof's walk meets, beyond the least so far, are
 * done with one projection. Then the axes the nearest pair of most
 * triangle pairs lies on (faces, then corners, then edges). */
static double tri_tri_lower_bound_to(double a[3][3], double b[3][3], double target)
{
    double s = 0;
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k)
            s = noct_max(s, noct_max(fabs(a[i][k]), fabs(b[i][k])));
    double first = 0;
    if (target < (double)INFINITY) {
        /* an overflowing sum is not finite: noct_gap_axis() refuses it */
        double c[3];
        for (int k = 0; k < 3; ++k)
            c[k] = ((b[0][k] - a[0][k]) + (b[1][k] - a[1][k])) + (b[2][k] - a[2][k]);
        first = proved_gap(c, a, b, s);
        if (first >= target)
            return first;
    }
    double ea[3][3], eb[3][3];
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) {
            ea[i][k] = a[(i + 1) % 3][k] - a[i][k];
            eb[i][k] = b[(i + 1) % 3][k] - b[i][k];
        }
    double best = first, u[3], w[3], v[3];
    /* face normals */
    cross_into(ea[0], ea[1], u);
    best = noct_max(best, proved_gap(u, a, b, s));
    cross_into(eb[0], eb[1], u);
    best = noct_max(best, proved_gap(u, a, b, s));
    if (best >= target)
        return best;
    /* corner against corner */
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            for (int k = 0; k < 3; ++k)
                u[k] = b[j][k] - a[i][k];
            best = noct_max(best, proved_gap(u, a, b, s));
        }
    if (best >= target)
        return best;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            /* edge against edge */
            cross_into(ea[i], eb[j], u);
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
            if (best >= target)
                return best;
        }
    return best;
}

static double tri_tri_lower_bound(double a[3][3], double b[3][3])
{
    return tri_tri_lower_bound_to(a, b, INFINITY);
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

/* ---- the general search: the two hierarchies, nearest pairs first ---------------- */

/* The two placed meshes of a distance search, scaled by a power of two so
 * that squared distances neither overflow nor underflow: every coordinate
 * is multiplied by scale (exactly) before any arithmetic. */
typedef struct dist_walk {
    const placed *A, *B;
    double scale;
    double best2;              /* the best squared distance so far (scaled) */
    double pa[3], pb[3];       /* its points (scaled) */
    uint32_t ia, ib;           /* its triangles (BVH order) */
    bool found;
    double reach2;             /* the lower bound walk's reach, squared */
    double lower;              /* the least lower bound (scaled) */
    uint64_t pairs, nodes;
    struct leaf_pair *leaves;  /* the pairs of leaves the float search took */
    size_t nleaves, leaves_cap;
    bool leaves_whole;         /* ... all of them: every other pair pruned by its boxes */
} dist_walk;

/* A pair of leaves the float search took, and their proved gap squared
 * (0 when not computed). */
typedef struct leaf_pair {
    uint32_t a, b;
    double g2;
} leaf_pair;

/* Squared distance between boxes, scaled: each gap is computed, then
 * scaled, then squared. A placed box holds its placed triangles exactly
 * (bvh.h), and the gaps' rounding is far inside the reaches' 2^-40. */
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

/* The bounding box of a placed (scaled) triangle. */
static inline void tri_bounds(double x[3][3], double lo[3], double hi[3])
{
    for (int k = 0; k < 3; ++k) {
        lo[k] = noct_min(x[0][k], noct_min(x[1][k], x[2][k]));
        hi[k] = noct_max(x[0][k], noct_max(x[1][k], x[2][k]));
    }
}

/* Squared distance between the bounding boxes of two placed (scaled)
 * triangles (tri_bounds()): a cheap bound below the pair's distance,
 * within rounding. */
static inline double tri_box_dist2(const double xlo[3], const double xhi[3],
                                   const double ylo[3], const double yhi[3])
{
    double s = 0;
    for (int k = 0; k < 3; ++k) {
        const double g = noct_max(noct_max(ylo[k] - xhi[k], xlo[k] - yhi[k]), 0);
        s += g * g;
    }
    return s;
}

/*
 * A proved lower bound on the distance between two sets of placed
 * (scaled) triangles x[0, nx) and y[0, ny) (a pair of leaves): their gap
 * along u (the direction between their placed boxes' centres), proved as
 * proved_gap() proves a pair's (any axis bounds the distance of disjoint
 * sets from below; the allowance covers the projections' rounding, s
 * bounding every coordinate), or 0.
 */
static double proved_gap_sets(const double axis[3], double x[][3][3], uint32_t nx,
                              double y[][3][3], uint32_t ny, double s)
{
    double u[3];
    if (!noct_gap_axis(axis, u))
        return 0;
    const double l1 = fabs(u[0]) + fabs(u[1]) + fabs(u[2]);
    double amax = -INFINITY, amin = INFINITY, bmax = -INFINITY, bmin = INFINITY;
    for (uint32_t i = 0; i < nx; ++i)
        for (int c = 0; c < 3; ++c) {
            const double pa = noct_dot3(u, x[i][c]);
            amax = noct_max(amax, pa);
            amin = noct_min(amin, pa);
        }
    for (uint32_t j = 0; j < ny; ++j)
        for (int c = 0; c < 3; ++c) {
            const double pb = noct_dot3(u, y[j][c]);
            bmax = noct_max(bmax, pb);
            bmin = noct_min(bmin, pb);
        }
    /* as proved_gap(): each projection errs by at most 4 ulp of l1 s,
     * and NOCT_GAP_TINY */
    const double err = 0x1p-50 * l1 * s + NOCT_GAP_TINY;
    return noct_gap_over(noct_max(bmin - amax, amin - bmax) - 2 * err, u);
}

/* The direction between the placed (scaled) boxes' centres of nodes na
 * and nb, and s, a bound on every coordinate of their placed (scaled)
 * triangles (a placed box holds them exactly; scaling is exact). */
static inline double leaf_axis(const bvh_node *na, const double ta[3], const bvh_node *nb,
                               const double tb[3], double scale, double u[3])
{
    double s = 0;
    for (int k = 0; k < 3; ++k) {
        const double alo = na->lo[k] + ta[k], ahi = na->hi[k] + ta[k];
        const double blo = nb->lo[k] + tb[k], bhi = nb->hi[k] + tb[k];
        u[k] = ((blo + bhi) - (alo + ahi)) * scale;
        s = noct_max(s, noct_max(noct_max(fabs(alo), fabs(ahi)), noct_max(fabs(blo), fabs(bhi))));
    }
    return s * scale;
}

/* Triangle i of P, placed and scaled. */
static inline void placed_tri(const placed *P, uint32_t i, double scale, double x[3][3])
{
    for (int c = 0; c < 3; ++c) {
        noct_place_vertex(P, P->m->tri[3 * i + c], x[c]);
        if (scale != 1)
            for (int k = 0; k < 3; ++k)
                x[c][k] *= scale;
    }
}

/* A leaf's triangles the walks below place at once (a BVH leaf holds
 * NOCT_BVH_LEAF, a box view's 12: they take it in chunks). */
#define LEAF_CHUNK 16

static inline uint32_t noct_min_u32(uint32_t a, uint32_t b)
{
    return a < b ? a : b;
}

/* The plane of triangle x: a normal n (not unit) and n.x[0] in n[3]. */
static inline void tri_plane(double x[3][3], double n[4])
{
    double e1[3], e2[3];
    noct_sub3(x[1], x[0], e1);
    noct_sub3(x[2], x[0], e2);
    noct_cross3(e1, e2, n);
    n[3] = noct_dot3(n, x[0]);
}

/* The squared gap between the plane n and triangle y when y lies wholly
 * on one side of it, else 0: in floating point, a cheap estimate from
 * below of the pair's distance for the float search (nearest_search()),
 * which proves nothing with it. */
static inline double plane_gap2(const double n[4], double y[3][3])
{
    const double d0 = noct_dot3(n, y[0]) - n[3], d1 = noct_dot3(n, y[1]) - n[3],
                 d2 = noct_dot3(n, y[2]) - n[3];
    double g;
    if (d0 > 0 && d1 > 0 && d2 > 0)
        g = noct_min(d0, noct_min(d1, d2));
    else if (d0 < 0 && d1 < 0 && d2 < 0)
        g = -noct_max(d0, noct_max(d1, d2));
    else
        return 0;
    const double nn = noct_dot3(n, n);
    return nn > 0 ? g / nn * g : 0;
}

/* The squared gap between triangles x and y along the direction between
 * their centroids, 0 if their projections overlap: in floating point, a
 * cheap estimate from below of the pair's distance for the float search
 * (nearest_leaves()), within a little of it for triangles apart by more
 * than their size; the search proves nothing with it. */
static inline double centroid_gap2(double x[3][3], double y[3][3])
{
    double u[3];
    for (int k = 0; k < 3; ++k)
        u[k] = ((y[0][k] - x[0][k]) + (y[1][k] - x[1][k])) + (y[2][k] - x[2][k]);
    const double xmax = noct_max(noct_dot3(u, x[0]), noct_max(noct_dot3(u, x[1]),
                                                              noct_dot3(u, x[2])));
    const double ymin = noct_min(noct_dot3(u, y[0]), noct_min(noct_dot3(u, y[1]),
                                                              noct_dot3(u, y[2])));
    const double g = ymin - xmax, uu = noct_dot3(u, u);
    return g > 0 && uu > 0 ? g / uu * g : 0;
}

typedef struct node_pair {
    uint32_t a, b;
    double d2;
} node_pair;


/* The float search's pair of leaves na and nb (their boxes' squared
 * distance d2): each pair of their triangles not ruled out by its boxes,
 * its centroids' axis, the planes or the leaves' own gap is measured, and the
 * nearest kept if it beats the best. */
static inline void nearest_leaves(dist_walk *w, const bvh_node *na, const bvh_node *nb,
                                  double d2, leaf_pair *rec)
{
    const placed *A = w->A, *B = w->B;
    /* B's leaf in chunks (a box view's one leaf holds 12) */
    for (uint32_t j0 = 0; j0 < nb->count; j0 += LEAF_CHUNK) {
        const uint32_t nj = noct_min_u32(nb->count - j0, LEAF_CHUNK);
        double y[LEAF_CHUNK][3][3], ny[LEAF_CHUNK][4];
        double ylo[LEAF_CHUNK][3], yhi[LEAF_CHUNK][3];
        for (uint32_t j = 0; j < nj; ++j) {
            placed_tri(B, nb->first + j0 + j, w->scale, y[j]);
            tri_plane(y[j], ny[j]);
            tri_bounds(y[j], ylo[j], yhi[j]);
        }
        if (d2 > 0 && na->count <= LEAF_CHUNK) { /* the leaves' own gap */
            double xs[LEAF_CHUNK][3][3], u[3];
            for (uint32_t i = 0; i < na->count; ++i)
                placed_tri(A, na->first + i, w->scale, xs[i]);
            const double sc = leaf_axis(na, A->t, nb, B->t, w->scale, u);
            const double g = proved_gap_sets(u, xs, na->count, y, nj, sc);
            if (rec != NULL && nb->count <= LEAF_CHUNK)
                rec->g2 = g * g; /* the whole of B's leaf: the proof may use it */
            if (g * g >= w->best2)
                continue;
        }
        for (uint32_t i = na->first; i < na->first + na->count; ++i) {
            double x[3][3], nx[4], xlo[3], xhi[3];
            placed_tri(A, i, w->scale, x);
            tri_plane(x, nx);
            tri_bounds(x, xlo, xhi);
            for (uint32_t jj = 0; jj < nj; ++jj) {
                const uint32_t j = nb->first + j0 + jj;
                double pa[3], pb[3];
                if (tri_box_dist2(xlo, xhi, ylo[jj], yhi[jj]) >= w->best2 ||
                    centroid_gap2(x, y[jj]) >= w->best2 ||
                    plane_gap2(nx, y[jj]) >= w->best2 || plane_gap2(ny[jj], x) >= w->best2)
                    continue;
                ++w->pairs;
                const double dd = tri_tri_nearest(x, y[jj], pa, pb);
                if (dd < w->best2) {
                    w->best2 = dd;
                    noct_copy3(pa, w->pa);
                    noct_copy3(pb, w->pb);
                    w->ia = i;
                    w->ib = j;
                    w->found = true;
                }
            }
        }
    }
}

/* The two child pairs of a pair of inner nodes (the split rule's), with
 * their boxes' squared distances. */
static inline void child_pairs(const dist_walk *w, const node_pair *e, node_pair c[2])
{
    const bvh_node *na = &w->A->m->nodes[e->a], *nb = &w->B->m->nodes[e->b];
    if (noct_bvh_split_a(na, nb)) {
        c[0] = (node_pair){na->first, e->b, 0};
        c[1] = (node_pair){na->first + 1, e->b, 0};
    } else {
        c[0] = (node_pair){e->a, nb->first, 0};
        c[1] = (node_pair){e->a, nb->first + 1, 0};
    }
    for (int k = 0; k < 2; ++k)
        c[k].d2 = box_dist2_scaled(&w->A->m->nodes[c[k].a], w->A->t, &w->B->m->nodes[c[k].b],
                                   w->B->t, w->scale);
}

/*
 * The float search for the nearest pair of triangles, depth first: it
 * visits the nearer child pair first (its boxes' distance), so that the
 * best distance falls early and prunes the rest, and drops a pair of
 * nodes or triangles whose boxes are no nearer than the best. Finds a
 * pair within sqrt(w->best2) if there is one (as floating point sees
 * it); its points are an upper bound, whatever the pruning missed.
 */
static void nearest_search_depth(dist_walk *w)
{
    node_pair stack[NOCT_BVH_PAIR_STACK];
    size_t top = 0;
    stack[top++] = (node_pair){0, 0, box_dist2_scaled(&w->A->m->nodes[0], w->A->t,
                                                      &w->B->m->nodes[0], w->B->t, w->scale)};
    while (top > 0) {
        const node_pair e = stack[--top];
        if (e.d2 >= w->best2)
            continue;
        ++w->nodes;
        const bvh_node *na = &w->A->m->nodes[e.a], *nb = &w->B->m->nodes[e.b];
        if (na->count > 0 && nb->count > 0) {
            nearest_leaves(w, na, nb, e.d2, NULL);
            continue;
        }
        node_pair c[2];
        child_pairs(w, &e, c);
        /* the nearer pair on top; a full stack only loses candidates for
         * the upper bound, never a proof */
        const int near = c[1].d2 < c[0].d2;
        if (top + 2 > NOCT_BVH_PAIR_STACK)
            continue;
        if (c[1 - near].d2 < w->best2)
            stack[top++] = c[1 - near];
        if (c[near].d2 < w->best2)
            stack[top++] = c[near];
    }
}

/* Node pairs the best-first search keeps pending, at most (a binary heap
 * on the stack); beyond, it finishes depth first. */
#define NEAREST_HEAP 1024

static inline void heap_push(node_pair *h, size_t *n, node_pair e)
{
    size_t i = (*n)++;
    while (i > 0) {
        const size_t p = (i - 1) / 2;
        if (!(e.d2 < h[p].d2))
            break;
        h[i] = h[p];
        i = p;
    }
    h[i] = e;
}

static inline node_pair heap_pop(node_pair *h, size_t *n)
{
    const node_pair top = h[0], e = h[--*n];
    size_t i = 0;
    for (;;) {
        size_t c = 2 * i + 1;
        if (c >= *n)
            break;
        if (c + 1 < *n && h[c + 1].d2 < h[c].d2)
            ++c;
        if (!(h[c].d2 < e.d2))
            break;
        h[i] = h[c];
        i = c;
    }
    if (*n > 0)
        h[i] = e;
    return top;
}

/*
 * The float search, best first: the pending pairs of nodes in a heap on
 * their boxes' distance, the nearest taken next, so that a pair of leaves
 * is measured only when no pending pair's boxes are nearer: once the best
 * is near the distance (the first few leaves), little else is measured.
 * Stops when the nearest pending pair is no nearer than the best. If the
 * heap fills, the pairs it could not keep are searched depth first
 * (nearest_search_depth(), the best so far pruning it), so the search
 * finds what the depth-first one alone would. Finds a pair within
 * sqrt(w->best2) if there is one (as floating point sees it); its points
 * are an upper bound, whatever the pruning missed. It records the pairs
 * of leaves it takes (w->leaves, with their proved gaps), for the proof
 * (lower_leaves_taken()); every other pair of nodes it dropped or left
 * pending has boxes no nearer than the final best, by their computed
 * distance.
 */
static void nearest_search(dist_walk *w)
{
    node_pair heap[NEAREST_HEAP];
    size_t n = 0;
    bool lost = false;
    w->nleaves = 0;
    w->leaves_whole = w->leaves_cap > 0;
    heap_push(heap, &n, (node_pair){0, 0, box_dist2_scaled(&w->A->m->nodes[0], w->A->t,
                                                           &w->B->m->nodes[0], w->B->t,
                                                           w->scale)});
    while (n > 0) {
        const node_pair e = heap_pop(heap, &n);
        if (e.d2 >= w->best2)
            break; /* every pending pair is as far */
        ++w->nodes;
        const bvh_node *na = &w->A->m->nodes[e.a], *nb = &w->B->m->nodes[e.b];
        if (na->count > 0 && nb->count > 0) {
            leaf_pair *rec = NULL;
            if (w->nleaves < w->leaves_cap) {
                rec = &w->leaves[w->nleaves++];
                *rec = (leaf_pair){e.a, e.b, 0};
            } else {
                w->leaves_whole = false;
            }
            nearest_leaves(w, na, nb, e.d2, rec);
            continue;
        }
        node_pair c[2];
        child_pairs(w, &e, c);
        for (int k = 0; k < 2; ++k) {
            if (!(c[k].d2 < w->best2))
                continue;
            if (n < NEAREST_HEAP)
                heap_push(heap, &n, c[k]);
            else
                lost = true;
        }
    }
    if (lost) {
        w->leaves_whole = false;
        nearest_search_depth(w);
    }
}

/* The proof's pair of leaves na and nb (their boxes' squared distance
 * d2, within the reach): the least proved bound of their triangle pairs
 * within the reach taken into w->lower (the leaves' own gap first: beyond
 * the reach, no pair of them is within it; gap_known when the caller has
 * it, within the reach). */
static inline void lower_leaves(dist_walk *w, const bvh_node *na, const bvh_node *nb,
                                double d2, bool gap_known)
{
    const placed *A = w->A, *B = w->B;
    for (uint32_t j0 = 0; j0 < nb->count; j0 += LEAF_CHUNK) {
        const uint32_t nj = noct_min_u32(nb->count - j0, LEAF_CHUNK);
        double y[LEAF_CHUNK][3][3], ylo[LEAF_CHUNK][3], yhi[LEAF_CHUNK][3];
        for (uint32_t j = 0; j < nj; ++j) {
            placed_tri(B, nb->first + j0 + j, w->scale, y[j]);
            tri_bounds(y[j], ylo[j], yhi[j]);
        }
        /* the leaves' own gap first: beyond the reach, no pair
         * of them is within it */
        if (!gap_known && d2 > 0 && na->count <= LEAF_CHUNK) {
            double xs[LEAF_CHUNK][3][3], u[3];
            for (uint32_t i = 0; i < na->count; ++i)
                placed_tri(A, na->first + i, w->scale, xs[i]);
            const double sc = leaf_axis(na, A->t, nb, B->t, w->scale, u);
            const double g = proved_gap_sets(u, xs, na->count, y, nj, sc);
            if (g * g > w->reach2)
                continue;
        }
        for (uint32_t i = na->first; i < na->first + na->count; ++i) {
            double x[3][3], xlo[3], xhi[3];
            placed_tri(A, i, w->scale, x);
            tri_bounds(x, xlo, xhi);
            for (uint32_t j = 0; j < nj; ++j) {
                if (tri_box_dist2(xlo, xhi, ylo[j], yhi[j]) > w->reach2)
                    continue;
                ++w->pairs;
                w->lower =
                    noct_min(w->lower, tri_tri_lower_bound_to(x, y[j], w->lower));
            }
        }
    }
}

/*
 * The proved lower bound: the least, over every pair of triangles whose
 * placed boxes are within the reach (sqrt(w->reach2)), of the pair's proved
 * bound; pairs beyond the reach are at least that far apart. A pair that
 * proves no less than the least so far stops early. false if the walk's
 * stack would overflow (never within the size limits): no proof.
 */
static bool lower_search(dist_walk *w)
{
    const placed *A = w->A, *B = w->B;
    struct { uint32_t a, b; } stack[NOCT_BVH_PAIR_STACK];
    size_t top = 0;
    stack[top].a = 0;
    stack[top++].b = 0;
    while (top > 0) {
        --top;
        const uint32_t ia = stack[top].a, ib = stack[top].b;
        const bvh_node *na = &A->m->nodes[ia], *nb = &B->m->nodes[ib];
        ++w->nodes;
        const double d2 = box_dist2_scaled(na, A->t, nb, B->t, w->scale);
        if (d2 > w->reach2)
            continue;
        if (na->count > 0 && nb->count > 0) {
            lower_leaves(w, na, nb, d2, false);
            continue;
        }
        if (top + 2 > NOCT_BVH_PAIR_STACK)
            return false;
        if (noct_bvh_split_a(na, nb)) {
            stack[top].a = na->first;     stack[top++].b = ib;
            stack[top].a = na->first + 1; stack[top++].b = ib;
        } else {
            stack[top].a = ia; stack[top++].b = nb->first;
            stack[top].a = ia; stack[top++].b = nb->first + 1;
        }
    }
    return true;
}

/*
 * The proved lower bound from the pairs of leaves the float search took
 * (w->leaves, all of them: w->leaves_whole), without a second walk: the
 * least proved bound of their triangle pairs within the reach, as
 * lower_search() takes it (a pair whose recorded proved gap, or whose
 * boxes' distance, is beyond the reach is skipped). Every pair of nodes
 * the search did not take it dropped or left pending because its boxes'
 * computed squared distance D2 was no less than the best then, so no
 * less than the final best2; the caller bounds those pairs by
 * pruned_bound() below.
 */
static void lower_leaves_taken(dist_walk *w)
{
    for (size_t k = 0; k < w->nleaves; ++k) {
        const leaf_pair *e = &w->leaves[k];
        if (e->g2 > w->reach2)
            continue;
        const bvh_node *na = &w->A->m->nodes[e->a], *nb = &w->B->m->nodes[e->b];
        ++w->nodes;
        const double d2 = box_dist2_scaled(na, w->A->t, nb, w->B->t, w->scale);
        if (d2 > w->reach2)
            continue;
        /* B's leaf in one chunk: its gap is the one recorded, within the
         * reach */
        lower_leaves(w, na, nb, d2, nb->count <= LEAF_CHUNK);
    }
}

/*
 * A proved lower bound on the distance of every pair of nodes whose
 * boxes' computed squared distance (box_dist2_scaled()) is at least
 * best2, or 0. The boxes hold their placed triangles exactly; each gap
 * is a difference of two doubles (error at most u = 2^-53 relative),
 * scaled exactly, squared and summed (three more roundings of at most u
 * each, relative, while no term underflows; a term that does errs by at
 * most 2^-1074 absolutely), so the boxes' true squared distance is at
 * least D2 (1 - 6u) - 2^-1072 >= best2 (1 - 6u) - 2^-1072. For best2 of
 * at least 2^-900 the absolute term is under 2^-170 best2, and the
 * distance is at least sqrt(best2) (1 - 4u); sqrt's rounding (half an ulp)
 * and the product's (another) take less than 2u more, far inside the
 * factor 1 - 2^-45 taken off. Below 2^-900, 0 (the caller then walks
 * the trees, lower_search()).
 */
static double pruned_bound(double best2)
{
    return best2 >= 0x1p-900 ? sqrt(best2) * (1 - 0x1p-45) : 0;
}

/* Pairs of leaves a search records for its proof, at most (on the stack);
 * beyond, the proof walks the trees again. */
#define TAKEN_LEAVES 2048

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

/* The scale of a search: meshes far from unit size are scaled (exactly,
 * by a power of two, to [1, 2)) so that neither the squares of their
 * distances nor the proofs' products of four coordinates (a corner
 * against an edge) overflow or underflow. Scaling down may round
 * coordinates under 2^-1022 of the largest, far below the allowances. */
static double search_scale(double mag)
{
    if (!(mag > 0) || (mag >= 0x1p-100 && mag <= 0x1p100))
        return 1;
    const int k = -ilogb(mag);
    return noct_pow2(k < 1023 ? k : 1023);
}

/* The answer for solids proved farther apart than max_distance. */
static void set_beyond(noctDistanceResult *r, double max_distance)
{
    memset(r, 0, sizeof *r);
    no_triangle(r->triangle_a);
    no_triangle(r->triangle_b);
    r->beyond = true;
    r->lower = max_distance;
    r->distance = r->upper = INFINITY;
}

/* The answer for solids that meet. */
static void set_colliding(noctDistanceResult *r, const noctMesh *a, const double ta[3],
                          const noctMesh *b, const double tb[3])
{
    memset(r, 0, sizeof *r);
    no_triangle(r->triangle_a);
    no_triangle(r->triangle_b);
    r->colliding = true;
    for (int k = 0; k < 3; ++k) {
        const double lo = noct_max(a->lo[k] + ta[k], b->lo[k] + tb[k]);
        const double hi = noct_min(a->hi[k] + ta[k], b->hi[k] + tb[k]);
        r->point_a[k] = r->point_b[k] = lo + (hi - lo) / 2;
    }
}

/* Do the placed boxes overlap so deeply (one's centre in the other) that
 * the solids likely meet, and the exact test should come first? */
static bool boxes_deep(const noctMesh *a, const double ta[3], const noctMesh *b,
                       const double tb[3])
{
    bool a_in_b = true, b_in_a = true;
    for (int k = 0; k < 3; ++k) {
        const double alo = a->lo[k] + ta[k], ahi = a->hi[k] + ta[k];
        const double blo = b->lo[k] + tb[k], bhi = b->hi[k] + tb[k];
        const double ca = alo + (ahi - alo) / 2, cb = blo + (bhi - blo) / 2;
        a_in_b = a_in_b && ca >= blo && ca <= bhi;
        b_in_a = b_in_a && cb >= alo && cb <= ahi;
    }
    return a_in_b || b_in_a;
}

typedef struct meet_walk {
    const placed *A, *B;
    const exact_ctx *x;
    noctNarrowStats *st;
} meet_walk;

static inline bool meet_prune(void *context, const bvh_node *na, const bvh_node *nb)
{
    const meet_walk *w = context;
    if (w->st)
        ++w->st->bvh_pairs;
    return !noct_boxes_overlap(na->lo, na->hi, w->A->t, nb->lo, nb->hi, w->B->t);
}

static inline bool meet_pair(void *context, uint32_t i, double ta[3][3], uint32_t j,
                             double tb[3][3])
{
    (void)i;
    (void)j;
    const meet_walk *w = context;
    if (w->st)
        ++w->st->triangle_pairs;
    return tri_tri(w->x, ta, tb);
}

/*
 * The exact test on the meshes of a search. Meshes as made go to
 * noctCollide(); rotated views (ex[i].R set) have no box form, filter or
 * hull, so the test is the exact level's own decision without its
 * shortcuts (which only prove it sooner): the boundaries meet (exact
 * triangle pairs through the hierarchies), or a placed box lies in the
 * other and a vertex of its mesh in the other's solid (exact).
 */
static noctStatus exact_of(const noctMesh *a, const double ta[3], const noctMesh *b,
                           const double tb[3], const noct_dist_exact *ex, bool *colliding,
                           noctNarrowStats *stats)
{
    if (ex == NULL || (ex[0].R == NULL && ex[1].R == NULL))
        return noctCollide(a, ta, b, tb, NOCT_ACCURACY_EXACT, colliding, stats);
    const placed A = {a, {ta[0], ta[1], ta[2]}}, B = {b, {tb[0], tb[1], tb[2]}};
    exact_ctx x = {stats ? &stats->exact_fallbacks : NULL};
    if (stats)
        ++stats->exact_tests;
    meet_walk w = {&A, &B, &x, stats};
    if (noct_bvh_pair_walk(&A, &B, meet_prune, meet_pair, &w)) {
        *colliding = true;
        return NOCT_OK;
    }
    const placed *pair[2][2] = {{&A, &B}, {&B, &A}};
    for (int i = 0; i < 2; ++i) {
        bool inside;
        const noctStatus st = noct_piece_inside(pair[i][0], pair[i][1], &x, stats, &inside);
        if (st != NOCT_OK)
            return st;
        if (inside) {
            *colliding = true;
            return NOCT_OK;
        }
    }
    *colliding = false;
    return NOCT_OK;
}

noctStatus noct_distance_placed(const noctMesh *a, const double ta[3], const noctMesh *b,
                                const double tb[3], double max_distance,
                                noctDistanceResult *r, noctNarrowStats *stats,
                                const noct_dist_exact ex[2])
{
    if (!placed_first(a, ta, b, tb)) {
        noct_dist_exact sw[2];
        if (ex != NULL) {
            sw[0] = ex[1];
            sw[1] = ex[0];
        }
        const noctStatus st =
            noct_distance_placed(b, tb, a, ta, max_distance, r, stats, ex ? sw : NULL);
        mirror(r);
        return st;
    }
    memset(r, 0, sizeof *r);
    no_triangle(r->triangle_a);
    no_triangle(r->triangle_b);
    const double mag = noct_max(placed_magnitude(a, ta), placed_magnitude(b, tb));
    const double scale = search_scale(mag);
    const double slack = 0x1p-40 * noct_max(mag, isfinite(max_distance) ? max_distance : 0);
    const double reach_max = isfinite(max_distance)
                                 ? (max_distance * (1 + 0x1p-40) + slack) * scale
                                 : (double)INFINITY;
    const placed A = {a, {ta[0], ta[1], ta[2]}}, B = {b, {tb[0], tb[1], tb[2]}};
    leaf_pair taken[TAKEN_LEAVES];
    dist_walk w = {&A, &B, scale, 0, {0, 0, 0}, {0, 0, 0}, 0, 0, false, 0, INFINITY, 0, 0,
                   taken, 0, TAKEN_LEAVES, false};
    const double root2 = box_dist2_scaled(&a->nodes[0], ta, &b->nodes[0], tb, scale);
    if (root2 > reach_max * reach_max) {
        set_beyond(r, max_distance);
        return NOCT_OK;
    }
    /* Placed boxes apart: the solids do not meet. Deeply overlapping
     * ones: the exact test first, as they likely meet. Else the search
     * first, and the exact test only if it cannot prove the boundaries
     * apart, or a box lies in the other (the exact level's containment). */
    bool decided = root2 > 0;
    if (!decided && boxes_deep(a, ta, b, tb)) {
        bool colliding = false;
        const noctStatus st = exact_of(a, ta, b, tb, ex, &colliding, stats);
        if (st != NOCT_OK)
            return st;
        if (colliding) {
            set_colliding(r, a, ta, b, tb);
            return NOCT_OK;
        }
        decided = true;
    }
    w.best2 = reach_max * reach_max;
    nearest_search(&w);
    /* the slack, and the points' rounding allowance, scaled */
    const double slack_s = slack * scale, allow = 0x1p-47 * mag * scale;
    double upper = INFINITY, d = INFINITY;
    bool proved = true;
    if (!w.found) {
        /* Nothing within the reach in floating point: prove it. */
        w.reach2 = reach_max * reach_max;
        w.lower = INFINITY;
        proved = lower_search(&w);
        if (!proved || !(w.lower > max_distance * scale)) {
            /* Floating point and the proof disagree at the reach: search
             * without it. */
            w.best2 = INFINITY;
            nearest_search(&w);
            NOCT_INVARIANT(w.found);
        }
    }
    if (w.found) {
        d = sqrt(w.best2);
        upper = d * (1 + 0x1p-50) + 2 * allow;
        const double reach = upper * (1 + 0x1p-40) + slack_s;
        w.reach2 = reach * reach;
        w.lower = upper;
        const double pruned = pruned_bound(w.best2);
        if (w.leaves_whole && pruned > 0) {
            /* the search's leaves, and its pruned pairs by their boxes */
            lower_leaves_taken(&w);
            w.lower = noct_min(w.lower, pruned);
        } else {
            proved = lower_search(&w);
        }
    }
    if (!proved)
        w.lower = 0;
    const placed pa = {a, {ta[0], ta[1], ta[2]}}, pb = {b, {tb[0], tb[1], tb[2]}};
    if (!decided && (!(w.lower > 0) || noct_may_hold_piece(&pa, &pb) ||
                     noct_may_hold_piece(&pb, &pa))) {
        bool colliding = false;
        const noctStatus st = exact_of(a, ta, b, tb, ex, &colliding, stats);
        if (st != NOCT_OK)
            return st;
        if (colliding) {
            set_colliding(r, a, ta, b, tb);
            return NOCT_OK;
        }
    }
    if (stats) {
        stats->bvh_pairs += w.nodes;
        stats->triangle_pairs += w.pairs;
    }
    if (!w.found) {
        set_beyond(r, max_distance);
        return NOCT_OK;
    }
    r->lower = w.lower / scale;
    r->upper = upper / scale;
    r->distance = noct_min(noct_max(d / scale, r->lower), r->upper);
    for (int k = 0; k < 3; ++k) {
        r->point_a[k] = w.pa[k] / scale;
        r->point_b[k] = w.pb[k] / scale;
        r->triangle_a[k] = a->tri[3 * w.ia + k];
        r->triangle_b[k] = b->tri[3 * w.ib + k];
    }
    return NOCT_OK;
}

/* ---- the convex path: GJK on the placed vertices, proved by its direction ------- */

/* Vertices a convex search keeps on the stack; more are allocated. */
#define CONVEX_STACK_VERTICES 64

/* The placed vertices of a mesh as the general path would place it:
 * fl(fl(R v) + t) (fl(v + t) without a rotation), then scaled. */
typedef struct convex_set {
    const noctMesh *m;
    double *p;      /* 3 m->nv */
    size_t n;
    double lo[3], hi[3]; /* the placed box (unscaled) */
    /* a box about its origin (box_corners_placed()): its placed vertices
     * are fl(fl(R v) + t) of v = (+-h0, +-h1, +-h2), R NULL for none */
    bool ideal;
    const double *R, *t;
    double h[3];
    const uint8_t *sign; /* vertex i's signs (box_dual's sign) */
} convex_set;

static size_t support(const convex_set *s, const double d[3])
{
    size_t best = 0;
    double h = -INFINITY;
    for (size_t i = 0; i < s->n; ++i) {
        const double x = noct_dot3(d, &s->p[3 * i]);
        if (x > h) {
            h = x;
            best = i;
        }
    }
    return best;
}

/* The point of the simplex w[0, n) nearest the origin, by every face's
 * affine projection (at most 15 for a tetrahedron): the nearest point lies
 * in the relative interior of one face, whose projection has positive
 * weights. Keeps the weights in lam; returns a mask of the face used. */
static unsigned simplex_nearest(double w[4][3], int n, double lam[4], double out[3])
{
    double best = INFINITY;
    unsigned mask = 1;
    /* the nearest point of the new simplex lies on a face with the new
     * point w[n - 1] (else the support would not have found it): only
     * those faces */
    const unsigned must = 1u << (n - 1);
    for (unsigned sub = must; sub < (1u << n); ++sub) {
        if (!(sub & must))
            continue;
        int idx[4], k = 0;
        for (int i = 0; i < n; ++i)
            if (sub & (1u << i))
                idx[k++] = i;
        double l[4] = {1, 0, 0, 0};
        if (k > 1) {
            double dd[3][3], G[3][3], rhs[3], mu[3];
            const double *o = w[idx[0]];
            for (int i = 1; i < k; ++i)
                noct_sub3(w[idx[i]], o, dd[i - 1]);
            const int m = k - 1;
            for (int i = 0; i < m; ++i) {
                rhs[i] = -noct_dot3(dd[i], o);
                for (int j = 0; j < m; ++j)
                    G[i][j] = noct_dot3(dd[i], dd[j]);
            }
            if (m == 1) {
                if (!(G[0][0] > 0))
                    continue;
                mu[0] = rhs[0] / G[0][0];
            } else if (m == 2) {
                const double det = G[0][0] * G[1][1] - G[0][1] * G[1][0];
                if (!(det > 1e-14 * G[0][0] * G[1][1]))
                    continue;
                mu[0] = (rhs[0] * G[1][1] - G[0][1] * rhs[1]) / det;
                mu[1] = (G[0][0] * rhs[1] - rhs[0] * G[1][0]) / det;
            } else {
                double C[3][3];
                for (int i = 0; i < 3; ++i)
                    for (int j = 0; j < 3; ++j)
                        C[i][j] = G[(i + 1) % 3][(j + 1) % 3] * G[(i + 2) % 3][(j + 2) % 3] -
                                  G[(i + 1) % 3][(j + 2) % 3] * G[(i + 2) % 3][(j + 1) % 3];
                const double det = G[0][0] * C[0][0] + G[0][1] * C[0][1] + G[0][2] * C[0][2];
                if (!(det > 1e-14 * G[0][0] * G[1][1] * G[2][2]))
                    continue;
                for (int i = 0; i < 3; ++i)
                    mu[i] = (C[0][i] * rhs[0] + C[1][i] * rhs[1] + C[2][i] * rhs[2]) / det;
            }
            double s = 0;
            bool ok = true;
            for (int i = 0; i < m; ++i) {
                ok = ok && mu[i] > 0;
                l[i + 1] = mu[i];
                s += mu[i];
            }
            l[0] = 1 - s;
            if (!ok || !(l[0] > 0))
                continue;
        }
        double x[3] = {0, 0, 0};
        for (int i = 0; i < k; ++i)
            for (int c = 0; c < 3; ++c)
                x[c] += l[i] * w[idx[i]][c];
        const double d2 = noct_dot3(x, x);
        if (d2 < best) {
            best = d2;
            mask = sub;
            for (int i = 0; i < 4; ++i)
                lam[i] = 0;
            for (int i = 0; i < k; ++i)
                lam[idx[i]] = l[i];
            noct_copy3(x, out);
        }
    }
    return mask;
}

/* GJK on the placed vertices: the nearest points of their hulls, in
 * floating point, as weights of (at most 4) vertex pairs. false if the
 * hulls (nearly) meet or it did not settle. */
static bool gjk(const convex_set *A, const convex_set *B, size_t ia[4], size_t ib[4],
                double lam[4], int *n, double tiny2)
{
    double w[4][3], v[3];
    int k = 0;
    noct_sub3(&A->p[0], &B->p[0], v);
    for (int iter = 0; iter < 64; ++iter) {
        const double nv[3] = {-v[0], -v[1], -v[2]};
        const size_t i = support(A, nv), j = support(B, v);
        double p[3];
        noct_sub3(&A->p[3 * i], &B->p[3 * j], p);
        const double vv = noct_dot3(v, v);
        /* settled: the support's bound is within 2^-44 of |v|^2 */
        if (k > 0 && vv - noct_dot3(v, p) <= 0x1p-44 * vv)
            break;
        bool again = false;
        for (int s = 0; s < k; ++s)
            again = again || (ia[s] == i && ib[s] == j);
        if (again)
            break;
        double tw[4][3], tv[3] = {0, 0, 0}, l[4];
        size_t tia[4], tib[4];
        for (int s = 0; s < k; ++s) {
            noct_copy3(w[s], tw[s]);
            tia[s] = ia[s];
            tib[s] = ib[s];
        }
        noct_copy3(p, tw[k]);
        tia[k] = i;
        tib[k] = j;
        const unsigned mask = simplex_nearest(tw, k + 1, l, tv);
        /* no progress (rounding): keep the last simplex, the best */
        if (k > 0 && !(noct_dot3(tv, tv) < vv))
            break;
        int m = 0;
        for (int s = 0; s <= k; ++s)
            if (mask & (1u << s)) {
                noct_copy3(tw[s], w[m]);
                ia[m] = tia[s];
                ib[m] = tib[s];
                lam[m] = l[s];
                ++m;
            }
        k = m;
        noct_copy3(tv, v);
        if (k == 4 || !(noct_dot3(v, v) > tiny2))
            return false;
    }
    *n = k;
    return k > 0;
}

/* The point of closed triangle x nearest p, in floating point (its edges
 * decide when the face's formula cannot); returns the squared distance. */
static double point_on_tri(const double p[3], double x[3][3], double out[3])
{
    double g[3];
    if (point_tri_nearest(p, x[0], x[1], x[2], out)) {
        noct_sub3(p, out, g);
        return noct_dot3(g, g);
    }
    double best = INFINITY, c1[3], c2[3];
    for (int e = 0; e < 3; ++e) {
        const double d = seg_seg_nearest(p, p, x[e], x[(e + 1) % 3], c1, c2);
        if (d < best) {
            best = d;
            noct_copy3(c2, out);
        }
    }
    return best;
}

/* The distinct vertices among idx[0, n) into out; returns how many. */
static int distinct(const size_t *idx, int n, size_t out[4])
{
    int m = 0;
    for (int i = 0; i < n; ++i) {
        bool seen = false;
        for (int j = 0; j < m; ++j)
            seen = seen || out[j] == idx[i];
        if (!seen)
            out[m++] = idx[i];
    }
    return m;
}

/* The triangle of s's mesh nearest p and its point nearest p: first among
 * the triangles that hold every vertex GJK used (near[0, n), repeats
 * included), which hold p when GJK's face is a triangle's, its edge or
 * its corner; then among the triangles at any of them, which hold p
 * unless a face is triangulated away from them; else among all. */
static uint32_t nearest_triangle(const convex_set *s, const double p[3], const size_t *near,
                                 int n, double tol2, double q[3])
{
    const noctMesh *m = s->m;
    size_t dv[4];
    const int nd = distinct(near, n, dv);
    double best = INFINITY;
    uint32_t bt = 0;
    for (int pass = nd <= 3 ? 0 : 1; pass < 3; ++pass) {
        for (uint32_t t = 0; t < m->nt; ++t) {
            const uint32_t *v = &m->tri[3 * t];
            bool at = pass == 2;
            if (pass == 0) {
                at = true;
                for (int i = 0; i < nd && at; ++i)
                    at = v[0] == dv[i] || v[1] == dv[i] || v[2] == dv[i];
            } else {
                for (int i = 0; i < nd && !at; ++i)
                    at = v[0] == dv[i] || v[1] == dv[i] || v[2] == dv[i];
            }
            if (!at)
                continue;
            double x[3][3], c[3];
            for (int i = 0; i < 3; ++i)
                noct_copy3(&s->p[3 * v[i]], x[i]);
            const double d2 = point_on_tri(p, x, c);
            if (d2 < best) {
                best = d2;
                bt = t;
                noct_copy3(c, q);
                if (pass == 0 && best <= tol2)
                    break; /* one that holds p (within the tolerance) will do */
            }
        }
        if (best <= tol2)
            break;
    }
    return bt;
}

/* Are the placed (unscaled) rotated triangles of s far from the
 * degeneracy noctMeshCreate() rejects (a corner collinear within 1e-9 of
 * the size), so that the rotated mesh the general path makes would be
 * made? (Conservative: 4 times the tolerance, in floating point.) */
static bool rotated_fine(const noctMesh *m, const double *r)
{
    for (size_t t = 0; t < m->nt; ++t) {
        const uint32_t *v = &m->tri[3 * t];
        double e1[3], e2[3], e3[3], n[3];
        noct_sub3(&r[3 * v[1]], &r[3 * v[0]], e1);
        noct_sub3(&r[3 * v[2]], &r[3 * v[0]], e2);
        /* scaled to the triangle's size if far from 1: no underflow or
         * overflow at any size */
        const double big = noct_max(noct_max_abs3(e1), noct_max_abs3(e2));
        if (!(big > 0))
            return false;
        if (big < 0x1p-200 || big > 0x1p200) {
            const int ex = -ilogb(big);
            const double f = noct_pow2(ex < 1023 ? ex : 1023);
            for (int k = 0; k < 3; ++k) {
                e1[k] *= f;
                e2[k] *= f;
            }
        }
        noct_sub3(e2, e1, e3);
        noct_cross3(e1, e2, n);
        const double d2 = noct_max(noct_dot3(e3, e3),
                                   noct_max(noct_dot3(e1, e1), noct_dot3(e2, e2)));
        if (!(noct_norm3(n) > 4e-9 * d2))
            return false;
    }
    return true;
}

/* A box form with a dual (every triangle on a face of the ideal box, so
 * three corners of a face, legs along two edges) whose edges are within a
 * factor 10^6 of each other, its corners within 2^-30 of its least
 * half-edge of the box: every triangle has an area over 10^-7 of its
 * longest side squared, rotated or not, far from noctMeshCreate()'s
 * tolerance, so rotated_fine() need not look. */
static bool box_far_from_flat(const noctMesh *m)
{
    return m->has_dual && m->dual.far_from_flat; /* (box_form.c) */
}

/* Lexicographic order of the two placed sets: the canonical order of a
 * call and its mirror (the same placed vertices either way). */
static bool set_first(const convex_set *a, const convex_set *b)
{
    if (a->n != b->n)
        return a->n < b->n;
    for (size_t i = 0; i < 3 * a->n; ++i)
        if (a->p[i] != b->p[i])
            return a->p[i] < b->p[i];
    if (a->m->nt != b->m->nt)
        return a->m->nt < b->m->nt;
    for (size_t i = 0; i < 3 * a->m->nt; ++i)
        if (a->m->tri[i] != b->m->tri[i])
            return a->m->tri[i] < b->m->tri[i];
    return true;
}

/* The gap between the placed vertex sets A and B along u, proved: (the
 * least of B's projections - the greatest of A's, less twice their
 * rounding) over |u|, or 0; s bounds every coordinate. Every closed solid
 * lies in the hull of its vertices, so it bounds their distance. */
static double sets_gap(const double axis[3], const convex_set *A, const convex_set *B,
                       double s)
{
    double u[3];
    if (!noct_gap_axis(axis, u))
        return 0;
    const double l1 = fabs(u[0]) + fabs(u[1]) + fabs(u[2]);
    double amax = -INFINITY, bmin = INFINITY;
    for (size_t i = 0; i < A->n; ++i)
        amax = noct_max(amax, noct_dot3(u, &A->p[3 * i]));
    for (size_t i = 0; i < B->n; ++i)
        bmin = noct_min(bmin, noct_dot3(u, &B->p[3 * i]));
    /* each projection errs by at most 4 ulp of l1 s, as in proved_gap() */
    return noct_gap_over(bmin - amax - 2 * (0x1p-50 * l1 * s + NOCT_GAP_TINY), u);
}

/* The axes of the features GJK ended on, turned towards v: the normal of
 * a side's three vertices (a face), the cross product of the two sides'
 * edges (two vertices each). Returns how many (at most 3). */
static int feature_axes(const convex_set *A, const size_t *ia, const convex_set *B,
                        const size_t *ib, int n, const double v[3], double axes[3][3])
{
    size_t da[4], db[4];
    const int na = distinct(ia, n, da), nb = distinct(ib, n, db);
    int k = 0;
    double e1[3], e2[3];
    if (na == 3) {
        noct_sub3(&A->p[3 * da[1]], &A->p[3 * da[0]], e1);
        noct_sub3(&A->p[3 * da[2]], &A->p[3 * da[0]], e2);
        noct_cross3(e1, e2, axes[k++]);
    }
    if (nb == 3) {
        noct_sub3(&B->p[3 * db[1]], &B->p[3 * db[0]], e1);
        noct_sub3(&B->p[3 * db[2]], &B->p[3 * db[0]], e2);
        noct_cross3(e1, e2, axes[k++]);
    }
    if (na == 2 && nb == 2) {
        noct_sub3(&A->p[3 * da[1]], &A->p[3 * da[0]], e1);
        noct_sub3(&B->p[3 * db[1]], &B->p[3 * db[0]], e2);
        noct_cross3(e1, e2, axes[k++]);
    }
    for (int i = 0; i < k; ++i)
        if (noct_dot3(axes[i], v) < 0)
            for (int c = 0; c < 3; ++c)
                axes[i][c] = -axes[i][c];
    return k;
}

/*
 * The distance of two convex meshes' placed vertex sets (scaled by
 * scale; mag their unscaled magnitude): GJK gives the nearest points of
 * their hulls, which are moved onto the nearest triangles; the direction
 * v between them proves the lower bound, as every closed solid lies in
 * the hull of its vertices: (min over B of v.b - max over A of v.a) / |v|,
 * less the rounding of the projections. false when GJK does not settle,
 * the hulls (nearly) meet, or the interval is wider than the accuracy
 * noctDistance() promises: the general path then answers.
 */
static bool convex_distance(const convex_set *A, const convex_set *B, double scale, double mag,
                            double max_distance, noctDistanceResult *r)
{
    const double mag_s = mag * scale, allow = 0x1p-47 * mag_s;
    size_t ia[4], ib[4];
    double lam[4];
    int n = 0;
    /* nearly meeting hulls go to the exact test */
    if (!gjk(A, B, ia, ib, lam, &n, (0x1p-44 * mag_s) * (0x1p-44 * mag_s)))
        return false;
    double pa[3] = {0, 0, 0}, pb[3] = {0, 0, 0}, qa[3], qb[3];
    for (int i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) {
            pa[k] += lam[i] * A->p[3 * ia[i] + k];
            pb[k] += lam[i] * B->p[3 * ib[i] + k];
        }
    const double tol2 = (8 * allow) * (8 * allow);
    const uint32_t ta = nearest_triangle(A, pa, ia, n, tol2, qa);
    const uint32_t tb = nearest_triangle(B, pb, ib, n, tol2, qb);
    double v[3];
    noct_sub3(qb, qa, v);
    const double d = noct_norm3(v);
    const double l1 = fabs(v[0]) + fabs(v[1]) + fabs(v[2]);
    if (!(l1 > 0))
        return false;
    double s = 0;
    for (size_t i = 0; i < A->n; ++i)
        s = noct_max(s, noct_max_abs3(&A->p[3 * i]));
    for (size_t i = 0; i < B->n; ++i)
        s = noct_max(s, noct_max_abs3(&B->p[3 * i]));
    const double upper = d * (1 + 0x1p-50) + 2 * allow;
    const double width = 0x1p-41 * noct_max(mag_s, upper);
    double lower = sets_gap(v, A, B, s);
    if (!(upper - lower <= width)) {
        /* the direction between two near points errs by about the
         * points' rounding over their distance: the axes of GJK's own
         * features, made of the vertices, are as sharp at any distance */
        double axes[3][3];
        const int na = feature_axes(A, ia, B, ib, n, v, axes);
        for (int i = 0; i < na; ++i)
            lower = noct_max(lower, sets_gap(axes[i], A, B, s));
    }
    if (!(lower > 0) || !(upper - lower <= width))
        return false;
    memset(r, 0, sizeof *r);
    if (lower > max_distance * scale) {
        set_beyond(r, max_distance);
        return true;
    }
    r->lower = lower / scale;
    r->upper = upper / scale;
    r->distance = noct_min(noct_max(d / scale, r->lower), r->upper);
    for (int k = 0; k < 3; ++k) {
        r->point_a[k] = qa[k] / scale;
        r->point_b[k] = qb[k] / scale;
        r->triangle_a[k] = A->m->tri[3 * ta + k];
        r->triangle_b[k] = B->m->tri[3 * tb + k];
    }
    return true;
}

/* Two box-form meshes (both with a dual) whose placed vertices' boxes
 * overlap: does the separating-axis proof on their box forms, turned with
 * their rotations (noct_box_slot_turned(), which bounds the rotation's
 * rounding, so that the forms describe the placed vertices
 * fl(fl(R v) + t) as every path places them), show that the solids share
 * a point (noct_box_decide())? Then the answer is the colliding one, as
 * the exact test would give it. */
static bool boxes_proved_meeting(const convex_set s[2], double R[2][9], const bool turned[2],
                                 const noctTransform *const x[2])
{
    noct_box_slot slot[2];
    for (int i = 0; i < 2; ++i) {
        if (turned[i])
            noct_box_slot_turned(s[i].m, R[i], &slot[i]);
        else
            noct_box_slot_fill(s[i].m, &slot[i]);
        if (!(slot[i].shrink < 1))
            return false;
    }
    return noct_box_decide(&slot[0], x[0]->p, &slot[1], x[1]->p) > 0;
}

/* Do the placed boxes of two vertex sets overlap: 0 no, 1 yes, 2 so
 * deeply that the centre of one lies in the other (as boxes_deep()). */
static int sets_overlap(const convex_set s[2])
{
    bool a_in_b = true, b_in_a = true;
    for (int k = 0; k < 3; ++k) {
        const double *lo = (const double[2]){s[0].lo[k], s[1].lo[k]};
        const double *hi = (const double[2]){s[0].hi[k], s[1].hi[k]};
        if (lo[0] > hi[1] || lo[1] > hi[0])
            return 0;
        const double ca = lo[0] + (hi[0] - lo[0]) / 2, cb = lo[1] + (hi[1] - lo[1]) / 2;
        a_in_b = a_in_b && ca >= lo[1] && ca <= hi[1];
        b_in_a = b_in_a && cb >= lo[0] && cb <= hi[0];
    }
    return a_in_b || b_in_a ? 2 : 1;
}

/* The answer for solids that meet, from their placed vertices: as
 * set_colliding() gives it from their placed boxes (the least and
 * greatest of the placed vertices are the placed box's corners, as
 * rounding is monotonic). */
static void set_colliding_sets(noctDistanceResult *r, const convex_set s[2])
{
    memset(r, 0, sizeof *r);
    no_triangle(r->triangle_a);
    no_triangle(r->triangle_b);
    r->colliding = true;
    for (int k = 0; k < 3; ++k) {
        const double lo = noct_max(s[0].lo[k], s[1].lo[k]);
        const double hi = noct_min(s[0].hi[k], s[1].hi[k]);
        r->point_a[k] = r->point_b[k] = lo + (hi - lo) / 2;
    }
}

/* ---- two boxes: the nearest features in closed form ----------------------------- */

/*
 * Two box-form meshes with duals or box views (their corners and faces
 * known: noct_box_topology()) are rectangular boxes up to the rounding
 * of their placed vertices (checked). Their nearest features are found
 * in closed form on the ideal boxes the placed vertices describe: the nearest points of two convex
 * solids can be chosen with one of them at a corner, or with both inside
 * edges (the direction between them then perpendicular to both edges,
 * so along a cross product of an axis of each, and each edge the one of
 * its direction that reaches farthest along it: the one the signs of
 * that cross product on the other axes name). So the candidates are each
 * box's 8 corners against the other box (clamped in its frame: the
 * clamped coordinates name the face, edge or corner reached) and the 9
 * pairs of edges whose lines' nearest points lie inside both; the
 * nearest candidate names a feature of each box. The floating-point
 * search only chooses the features: the answer is then made as the GJK
 * path makes it, on the placed vertices themselves (the nearest points
 * of the features' placed triangles or edges, the proof by the gap of
 * the placed vertex sets on the direction between the points or on the
 * features' own axis), and when it cannot prove its interval as tight
 * as promised the GJK path answers.
 */

/* A box's frame from its placed vertices: its centre, unit axes and
 * half-lengths (false if they are not orthogonal within 1e-9). */
typedef struct box_frame {
    double c[3], u[3][3], h[3];
    const uint8_t *corner;      /* vertex of each corner (noct_box_topology()) */
    const uint8_t (*face)[2];   /* triangles of each face */
} box_frame;

static bool box_frame_of(const convex_set *s, box_frame *f)
{
    if (!noct_box_topology(s->m, &f->corner, &f->face))
        return false;
    const double *p0 = &s->p[3 * f->corner[0]], *p7 = &s->p[3 * f->corner[7]];
    for (int k = 0; k < 3; ++k)
        f->c[k] = p0[k] + (p7[k] - p0[k]) / 2;
    for (int j = 0; j < 3; ++j) {
        double e[3];
        noct_sub3(p7, &s->p[3 * f->corner[7 ^ (1u << j)]], e);
        const double n = noct_norm3(e);
        if (!(n > 0))
            return false;
        f->h[j] = n / 2;
        for (int k = 0; k < 3; ++k)
            f->u[j][k] = e[k] / n;
    }
    return fabs(noct_dot3(f->u[0], f->u[1])) <= 1e-9 && fabs(noct_dot3(f->u[0], f->u[2])) <= 1e-9 &&
           fabs(noct_dot3(f->u[1], f->u[2])) <= 1e-9;
}

/* The frame of a box about its origin (s->ideal) from R, t and its
 * half-lengths rather than its placed vertices (no square roots): axis j
 * (from corner 7 ^ 2^j to corner 7, which differ in the mesh's
 * coordinate l = the dual's frame_axis[j]) is +-R's column l, its
 * half-length h_l, the centre t. The ideal box {t + R y : |y_l| <= h_l}
 * is within rounding of the placed vertices' (box_corners_placed()); the
 * frame only chooses the features, which the placed vertices then
 * prove. */
static bool box_frame_ideal(const convex_set *s, box_frame *f)
{
    const box_dual *x = &s->m->dual;
    f->corner = x->corner;
    f->face = (const uint8_t(*)[2])x->face;
    const double *R = s->R;
    for (int j = 0; j < 3; ++j) {
        const int l = x->frame_axis[j];
        const double sg = (x->frame_plus >> j) & 1u ? 1 : -1;
        if (R != NULL) {
            f->u[j][0] = sg * R[l];
            f->u[j][1] = sg * R[3 + l];
            f->u[j][2] = sg * R[6 + l];
        } else {
            f->u[j][0] = f->u[j][1] = f->u[j][2] = 0;
            f->u[j][l] = sg;
        }
        f->h[j] = s->h[l];
    }
    noct_copy3(s->t, f->c);
    return true;
}

/* A box's frame: the ideal one for a box about its origin, else from its
 * placed vertices. */
static bool frame_of_box(const convex_set *s, box_frame *f)
{
    return s->ideal ? box_frame_ideal(s, f) : box_frame_of(s, f);
}

/* A feature of a box: the corners base + any sum of the bits of free
 * (free 0: a corner, one bit: an edge along that axis, two: a face). */
typedef struct box_feature {
    unsigned base, free;
} box_feature;

/* The nearest of the corners of one box against the other, in the
 * other's frame: corner p of the first at o + sum_j (bit j of p ? 1 : -1)
 * E[j], the other's half-lengths h. Updates the best squared distance
 * *best and the two features (mine: the corner; its: what the clamp
 * reached); false if a corner lies in the other box or on it (the boxes
 * may meet). */
static bool corners_against(const double o[3], double E[3][3], const double h[3], double *best,
                            box_feature *mine, box_feature *its, double yb[3])
{
    /* (written out: the compiler keeps the 8 corners in registers) */
    double y[3][8], d2[8];
    for (int k = 0; k < 3; ++k) {
        const double a0 = o[k] - E[0][k], a1 = o[k] + E[0][k];
        const double b0 = a0 - E[1][k], b1 = a1 - E[1][k], b2 = a0 + E[1][k], b3 = a1 + E[1][k];
        const double e2 = E[2][k], hk = h[k];
        double *yk = y[k];
        yk[0] = b0 - e2;
        yk[1] = b1 - e2;
        yk[2] = b2 - e2;
        yk[3] = b3 - e2;
        yk[4] = b0 + e2;
        yk[5] = b1 + e2;
        yk[6] = b2 + e2;
        yk[7] = b3 + e2;
        const double x0 = noct_max(fabs(yk[0]) - hk, 0), x1 = noct_max(fabs(yk[1]) - hk, 0);
        const double x2 = noct_max(fabs(yk[2]) - hk, 0), x3 = noct_max(fabs(yk[3]) - hk, 0);
        const double x4 = noct_max(fabs(yk[4]) - hk, 0), x5 = noct_max(fabs(yk[5]) - hk, 0);
        const double x6 = noct_max(fabs(yk[6]) - hk, 0), x7 = noct_max(fabs(yk[7]) - hk, 0);
        if (k == 0) {
            d2[0] = x0 * x0;
            d2[1] = x1 * x1;
            d2[2] = x2 * x2;
            d2[3] = x3 * x3;
            d2[4] = x4 * x4;
            d2[5] = x5 * x5;
            d2[6] = x6 * x6;
            d2[7] = x7 * x7;
        } else {
            d2[0] += x0 * x0;
            d2[1] += x1 * x1;
            d2[2] += x2 * x2;
            d2[3] += x3 * x3;
            d2[4] += x4 * x4;
            d2[5] += x5 * x5;
            d2[6] += x6 * x6;
            d2[7] += x7 * x7;
        }
    }
    unsigned p = 0;
    for (unsigned q = 1; q < 8; ++q)
        if (d2[q] < d2[p])
            p = q;
    if (!(d2[p] > 0))
        return false;
    if (d2[p] < *best) {
        *best = d2[p];
        unsigned base = 0, free = 0;
        for (int k = 0; k < 3; ++k) {
            if (fabs(y[k][p]) > h[k])
                base |= (y[k][p] > 0 ? 1u : 0u) << k;
            else
                free |= 1u << k;
        }
        *mine = (box_feature){p, 0};
        *its = (box_feature){base, free};
        for (int k = 0; k < 3; ++k)
            yb[k] = y[k][p];
    }
    return true;
}

/* Is corner p of a box (its axes' coordinates in the other box's frame
 * ax(j) = (X[0][j], X[1][j], X[2][j]) when by_column, else row j) the
 * nearest point of its box to the point q the clamp of its coordinates
 * y to the other's half-lengths h reached? It is when p is least along
 * r = y - q: bit j of p set (the + side of axis j) where r.ax(j) <= 0,
 * clear where >= 0. Then q (the nearest point of the other box to p) and
 * p are a pair of nearest points of the two boxes (each the nearest of
 * its box to the other: the plane through q normal to r separates them
 * with their distance), and no pair of edges is nearer. */
static bool corner_least(unsigned p, const double y[3], const double h[3], double X[3][3],
                         bool by_column)
{
    double r[3];
    for (int k = 0; k < 3; ++k)
        r[k] = y[k] - noct_clamp(y[k], -h[k], h[k]);
    for (int j = 0; j < 3; ++j) {
        const double sj = by_column ? r[0] * X[0][j] + r[1] * X[1][j] + r[2] * X[2][j]
                                    : r[0] * X[j][0] + r[1] * X[j][1] + r[2] * X[j][2];
        if ((p >> j) & 1u ? sj > 0 : sj < 0)
            return false;
    }
    return true;
}

static const int NEXT3[3] = {1, 2, 0};

/* The nearest features of the ideal boxes A and B (fa on A, fb on B), or
 * false if a corner of one lies in the other. */
static bool box_features(const box_frame *A, const box_frame *B, box_feature *fa,
                         box_feature *fb)
{
    double C[3][3], D[3], T[3], TB[3], BE[3][3], AE[3][3];
    noct_sub3(B->c, A->c, D);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j)
            C[i][j] = noct_dot3(A->u[i], B->u[j]);
        T[i] = noct_dot3(A->u[i], D);
        TB[i] = -noct_dot3(B->u[i], D);
    }
    for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) {
            BE[j][k] = B->h[j] * C[k][j]; /* B's half-edge j in A's frame */
            AE[j][k] = A->h[j] * C[j][k]; /* A's half-edge j in B's frame */
        }
    /* A corner already a pair of nearest points with what it reached:
     * no other corner and no edge pair can be nearer, and the search
     * stops (the float test only spares the search; the placed vertices
     * prove whatever features it names). */
    double best = INFINITY, yb[3], ya[3];
    if (!corners_against(T, BE, A->h, &best, fb, fa, yb))
        return false;
    if (corner_least(fb->base, yb, A->h, C, true))
        return true;
    const double best_b = best;
    if (!corners_against(TB, AE, B->h, &best, fa, fb, ya))
        return false;
    if (best < best_b && corner_least(fa->base, ya, B->h, C, false))
        return true;
    /* edge i of A against edge j of B, along u = a_i x b_j (A's frame) */
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const double b[3] = {C[0][j], C[1][j], C[2][j]};
            double u[3] = {0, 0, 0};
            const int i1 = NEXT3[i], i2 = NEXT3[i1];
            u[i1] = -b[i2];
            u[i2] = b[i1];
            if (!(u[i1] * u[i1] + u[i2] * u[i2] > 1e-12))
                continue; /* parallel edges: their corners decide */
            if (noct_dot3(u, T) < 0)
                for (int k = 0; k < 3; ++k)
                    u[k] = -u[k];
            /* A's edge: the corners' signs u_k on its other axes; B's:
             * against u.b_l on its own */
            const int j1 = NEXT3[j], j2 = NEXT3[j1];
            const double s1 = u[i1] > 0 ? 1 : -1, s2 = u[i2] > 0 ? 1 : -1;
            const double w1 = u[0] * C[0][j1] + u[1] * C[1][j1] + u[2] * C[2][j1];
            const double w2 = u[0] * C[0][j2] + u[1] * C[1][j2] + u[2] * C[2][j2];
            const double t1 = w1 < 0 ? 1 : -1, t2 = w2 < 0 ? 1 : -1;
            const unsigned pa = (s1 > 0 ? 1u << i1 : 0u) | (s2 > 0 ? 1u << i2 : 0u);
            const unsigned pb = (t1 > 0 ? 1u << j1 : 0u) | (t2 > 0 ? 1u << j2 : 0u);
            double r[3];
            for (int k = 0; k < 3; ++k)
                r[k] = -T[k] - t1 * BE[j1][k] - t2 * BE[j2][k];
            r[i1] += s1 * A->h[i1];
            r[i2] += s2 * A->h[i2];
            /* r = P0 - Q0; s along a_i, t along b_j */
            const double bb = C[i][j], c = r[i], f = noct_dot3(b, r);
            const double denom = 1 - bb * bb;
            const double s = (bb * f - c) / denom, t = f + s * bb;
            if (!(fabs(s) < A->h[i]) || !(fabs(t) < B->h[j]))
                continue;
            double g[3];
            for (int k = 0; k < 3; ++k)
                g[k] = r[k] - t * b[k];
            g[i] += s;
            const double d2 = noct_dot3(g, g);
            if (d2 < best) {
                best = d2;
                *fa = (box_feature){pa, 1u << i};
                *fb = (box_feature){pb, 1u << j};
            }
        }
    return true;
}

/* The triangle of s's mesh with the feature's corners (a corner's or an
 * edge's; a box's edge is a side of a triangle). */
static uint32_t triangle_at(const convex_set *s, const box_frame *f, box_feature x)
{
    const uint32_t v0 = f->corner[x.base];
    const uint32_t v1 = x.free ? f->corner[x.base | x.free] : v0;
    const noctMesh *m = s->m;
    for (uint32_t t = 0; t < m->nt; ++t) {
        const uint32_t *v = &m->tri[3 * t];
        if ((v[0] == v0 || v[1] == v0 || v[2] == v0) && (v[0] == v1 || v[1] == v1 || v[2] == v1))
            return t;
    }
    NOCT_INVARIANT(false);
    return 0;
}

/* The placed triangle t of s. */
static void set_tri(const convex_set *s, uint32_t t, double x[3][3])
{
    for (int i = 0; i < 3; ++i)
        noct_copy3(&s->p[3 * s->m->tri[3 * t + i]], x[i]);
}

/* The point of s's placed feature x nearest p (a face: of its two
 * triangles), its triangle in *t. */
static void feature_nearest(const convex_set *s, const box_frame *f, box_feature x,
                            const double p[3], double q[3], uint32_t *t)
{
    if (x.free == 0) {
        noct_copy3(&s->p[3 * f->corner[x.base]], q);
        *t = triangle_at(s, f, x);
    } else if ((x.free & (x.free - 1)) == 0) {
        double c1[3];
        seg_seg_nearest(p, p, &s->p[3 * f->corner[x.base]], &s->p[3 * f->corner[x.base | x.free]],
                        c1, q);
        *t = triangle_at(s, f, x);
    } else {
        const unsigned j = 7 ^ x.free;
        const int k = j == 1 ? 0 : j == 2 ? 1 : 2;
        const uint8_t *two = f->face[2 * k + ((x.base >> k) & 1u)];
        double best = INFINITY;
        for (int i = 0; i < 2; ++i) {
            double y[3][3], c[3];
            set_tri(s, two[i], y);
            const double d2 = point_on_tri(p, y, c);
            if (d2 < best) {
                best = d2;
                noct_copy3(c, q);
                *t = two[i];
            }
        }
    }
}

/* The normal of a face feature's first triangle, as placed. */
static void face_axis(const convex_set *s, const box_frame *f, box_feature x, double u[3])
{
    const unsigned j = 7 ^ x.free;
    const int k = j == 1 ? 0 : j == 2 ? 1 : 2;
    double y[3][3], e1[3], e2[3];
    set_tri(s, f->face[2 * k + ((x.base >> k) & 1u)][0], y);
    noct_sub3(y[1], y[0], e1);
    noct_sub3(y[2], y[0], e2);
    noct_cross3(e1, e2, u);
}

/*
 * The distance of two boxes (A, B in the canonical order; unscaled, their
 * magnitude mag within [2^-100, 2^100]) by their nearest features in
 * closed form. false when a corner of one lies in the other (they may
 * meet), or the proof is not as tight as noctDistance() promises: the
 * caller goes on as without it.
 */
static bool boxes_distance(const convex_set *A, const convex_set *B, double mag,
                           double max_distance, noctDistanceResult *r)
{
    box_frame fa, fb;
    box_feature xa, xb;
    if (!frame_of_box(A, &fa) || !frame_of_box(B, &fb) || !box_features(&fa, &fb, &xa, &xb))
        return false;
    double qa[3], qb[3];
    uint32_t ta, tb;
    if (xa.free == 0) {
        noct_copy3(&A->p[3 * fa.corner[xa.base]], qa);
        ta = triangle_at(A, &fa, xa);
        feature_nearest(B, &fb, xb, qa, qb, &tb);
    } else if (xb.free == 0) {
        noct_copy3(&B->p[3 * fb.corner[xb.base]], qb);
        tb = triangle_at(B, &fb, xb);
        feature_nearest(A, &fa, xa, qb, qa, &ta);
    } else {
        seg_seg_nearest(&A->p[3 * fa.corner[xa.base]], &A->p[3 * fa.corner[xa.base | xa.free]],
                        &B->p[3 * fb.corner[xb.base]], &B->p[3 * fb.corner[xb.base | xb.free]],
                        qa, qb);
        ta = triangle_at(A, &fa, xa);
        tb = triangle_at(B, &fb, xb);
    }
    double v[3];
    noct_sub3(qb, qa, v);
    const double d = noct_norm3(v);
    if (!(d > 0))
        return false;
    const double allow = 0x1p-47 * mag;
    /* (mag: the largest magnitude of a placed coordinate, from the
     * placed boxes) */
    const double s = mag;
    const double upper = d * (1 + 0x1p-50) + 2 * allow;
    const double width = 0x1p-41 * noct_max(mag, upper);
    double lower = sets_gap(v, A, B, s);
    if (!(upper - lower <= width)) {
        /* the features' own axis: a face's normal, two edges' cross
         * product (made of the placed vertices) */
        double u[3];
        if (xa.free != 0 && (xa.free & (xa.free - 1)) != 0) {
            face_axis(A, &fa, xa, u);
        } else if (xb.free != 0 && (xb.free & (xb.free - 1)) != 0) {
            face_axis(B, &fb, xb, u);
        } else if (xa.free != 0 && xb.free != 0) {
            double e1[3], e2[3];
            noct_sub3(&A->p[3 * fa.corner[xa.base | xa.free]], &A->p[3 * fa.corner[xa.base]], e1);
            noct_sub3(&B->p[3 * fb.corner[xb.base | xb.free]], &B->p[3 * fb.corner[xb.base]], e2);
            noct_cross3(e1, e2, u);
        } else {
            return false;
        }
        if (noct_dot3(u, v) < 0)
            for (int k = 0; k < 3; ++k)
                u[k] = -u[k];
        lower = noct_max(lower, sets_gap(u, A, B, s));
    }
    if (!(lower > 0) || !(upper - lower <= width))
        return false;
    memset(r, 0, sizeof *r);
    if (lower > max_distance) {
        set_beyond(r, max_distance);
        return true;
    }
    r->lower = lower;
    r->upper = upper;
    r->distance = noct_min(noct_max(d, lower), upper);
    for (int k = 0; k < 3; ++k) {
        r->point_a[k] = qa[k];
        r->point_b[k] = qb[k];
        r->triangle_a[k] = A->m->tri[3 * ta + k];
        r->triangle_b[k] = B->m->tri[3 * tb + k];
    }
    return true;
}

/* The placed vertices fl(fl(R v) + t) of a mesh of 8 vertices (+-h0,
 * +-h1, +-h2), a box about its origin (noctMeshCreateBox()'s), into s,
 * with its placed box, from the 9 products R_kl h_l (R NULL: none, the
 * vertices fl(v + t)). fl(R_kl (-h_l)) = -fl(R_kl h_l) and, rounding
 * being symmetric, fl(-x - y) = -fl(x + y): so coordinate k of every
 * corner, in noct_rotate()'s order ((R_k0 v0 + R_k1 v1) + R_k2 v2) + t_k,
 * is +-one of the four sums fl(fl(a0 +- a1) +- a2) (a_l = fl(R_kl h_l))
 * plus t_k, bit for bit: 14 additions a coordinate instead of 24. The
 * least and greatest coordinates are fl(t_k -+ M) for M the largest of
 * the four sums' magnitudes (x -> fl(x + t_k) is monotonic). false for
 * another mesh (one whose dual is not about_origin: box_form.c). */
static bool box_corners_placed(const noctMesh *m, const double *R, const double t[3],
                               convex_set *s)
{
    if (m->nv != 8 || !m->has_dual || !m->dual.about_origin)
        return false;
    const double h0 = fabs(m->v[0]), h1 = fabs(m->v[1]), h2 = fabs(m->v[2]);
    s->sign = m->dual.sign;
    /* (the dual describes m's own vertices: a copy of a mesh with other
     * vertices, as rotated_view() makes, clears about_origin) */
    for (int i = 0; i < 8; ++i) {
        const double *v = &m->v[3 * i];
        const unsigned c = s->sign[i];
        NOCT_INVARIANT(v[0] == ((c & 4u) ? h0 : -h0) && v[1] == ((c & 2u) ? h1 : -h1) &&
                       v[2] == ((c & 1u) ? h2 : -h2));
        (void)v;
        (void)c;
    }
    double a[9] = {h0, 0, 0, 0, h1, 0, 0, 0, h2};
    if (R != NULL)
        for (int k = 0; k < 3; ++k) {
            volatile double x = R[3 * k] * h0, y = R[3 * k + 1] * h1, z = R[3 * k + 2] * h2;
            a[3 * k] = x;
            a[3 * k + 1] = y;
            a[3 * k + 2] = z;
        }
    for (int k = 0; k < 3; ++k) {
        const double pp = a[3 * k] + a[3 * k + 1], pm = a[3 * k] - a[3 * k + 1];
        const double a2 = a[3 * k + 2], tk = t[k];
        const double q0 = pp + a2, q1 = pp - a2, q2 = pm + a2, q3 = pm - a2;
        /* corner c (bit 2: +h0, bit 1: +h1, bit 0: +h2): with sx, sy, sz
         * its signs, fl(fl(sx a0 + sy a1) + sz a2) = sx q_(sx == sy ? 0 :
         * 2) + (sx == sz ? 0 : 1): -q0, -q1, -q2, -q3, q3, q2, q1, q0 */
        const double c[8] = {tk - q0, tk - q1, tk - q2, tk - q3,
                             tk + q3, tk + q2, tk + q1, tk + q0};
        const uint8_t *sg = s->sign;
        double *p = s->p + k;
        p[0] = c[sg[0]];
        p[3] = c[sg[1]];
        p[6] = c[sg[2]];
        p[9] = c[sg[3]];
        p[12] = c[sg[4]];
        p[15] = c[sg[5]];
        p[18] = c[sg[6]];
        p[21] = c[sg[7]];
        const double M = noct_max(noct_max(fabs(q0), fabs(q1)), noct_max(fabs(q2), fabs(q3)));
        s->lo[k] = tk - M;
        s->hi[k] = tk + M;
    }
    s->ideal = true;
    s->R = R;
    s->t = t;
    s->h[0] = h0;
    s->h[1] = h1;
    s->h[2] = h2;
    return true;
}

/*
 * Is the point x proved inside the solid of s, a box about its origin
 * placed by R and t (s->ideal)? A floating-point test with its rounding
 * bounded, sound as follows. Let B* = {t + R y : |y_l| <= h_l} be the
 * ideal box of the float matrix R (its entries, from a unit quaternion
 * as noctQuatToMatrix() rounds and snaps them, within 2^-43 of an
 * orthogonal Q's, so ||R - Q|| < 2^-41 and ||R^T - R^-1|| < 2^-39) and
 * S = h0 + h1 + h2, T = max |t_k|.
 *  (1) Each placed vertex fl(fl(R v) + t) is within d = 2^-50 (S + T) +
 *      2^-1070 of R v + t in each coordinate (three products and two
 *      sums, then the sum with t: under 6 u (S + T), plus an absolute
 *      2^-1074 an operation for underflow), so within 2 d in length.
 *  (2) Moving each vertex on the straight line from R v + t to its placed
 *      point moves every point of the surface (the mesh's triangles, all
 *      on B*'s faces, a dual's) by at most 2 d; a point farther than 2 d
 *      from B*'s boundary is never crossed, so its winding number about
 *      the placed surface is its winding number about B*'s: 1 inside
 *      B*. x is then inside the placed solid.
 *  (3) y = R^-1 (x - t) is computed as fl(R^T fl(x - t)): within
 *      2^-38 D of it in each coordinate, D = |d_0| + |d_1| + |d_2| of the
 *      computed difference d (R^T for R^-1: 2^-39 |d|; the difference's
 *      and the sums' rounding: under 6 u D), plus 2^-1070 for underflow.
 *      If |y_l| <= h_l - m for every l, the ball of radius m (1 - 2^-41)
 *      about x lies in B*, so x is farther than m / 2 from its boundary.
 *  So |fl(y_l)| + 2^-38 D + 4 d < h_l for every l proves x inside. The
 *  test adds slack = 2^-36 (D + S + T) + 2^-1000 > 2^-38 D + 4 d + 2^-1069,
 *  which also covers the rounding of fl(|y_l| + slack) (at most 2 u h_l
 *  where it matters, below 2^-37 S).
 */
static bool ideal_box_holds(const convex_set *s, const double x[3])
{
    double d[3];
    noct_sub3(x, s->t, d);
    const double D = fabs(d[0]) + fabs(d[1]) + fabs(d[2]);
    const double T = noct_max(fabs(s->t[0]), noct_max(fabs(s->t[1]), fabs(s->t[2])));
    const double slack = 0x1p-36 * (D + (s->h[0] + s->h[1] + s->h[2]) + T) + 0x1p-1000;
    for (int l = 0; l < 3; ++l) {
        const double *R = s->R;
        const double y = R != NULL ? R[l] * d[0] + R[3 + l] * d[1] + R[6 + l] * d[2] : d[l];
        if (!(fabs(y) + slack < s->h[l]))
            return false;
    }
    return true;
}

/* Two boxes about their origins (both s[i].ideal): is a point proved
 * inside both solids (ideal_box_holds()), either's centre t? Then they
 * meet. */
static bool ideal_boxes_meet(const convex_set s[2])
{
    for (int i = 0; i < 2; ++i)
        if (ideal_box_holds(&s[0], s[i].t) && ideal_box_holds(&s[1], s[i].t))
            return true;
    return false;
}

/* The convex path of noctDistance(): true if it answered. */
static bool convex_path(const noctMesh *m[2], double R[2][9], const bool turned[2],
                        const noctTransform *x[2], double max_distance, noctDistanceResult *r,
                        noctNarrowStats *stats)
{
    double stack_p[2][3 * CONVEX_STACK_VERTICES];
    double *heap[2] = {NULL, NULL};
    convex_set s[2];
    bool ok = true;
    double mag = 0;
    s[0].ideal = s[1].ideal = false;
    for (int i = 0; i < 2 && ok; ++i) {
        s[i].m = m[i];
        s[i].n = m[i]->nv;
        if (s[i].n <= CONVEX_STACK_VERTICES) {
            s[i].p = stack_p[i];
        } else {
            s[i].p = heap[i] = malloc(3 * s[i].n * sizeof *heap[i]);
            ok = heap[i] != NULL;
            if (!ok)
                break;
        }
        if (s[i].n == 8 && box_far_from_flat(m[i]) &&
            box_corners_placed(m[i], turned[i] ? R[i] : NULL, x[i]->p, &s[i])) {
            ok = true;
        } else {
            for (size_t j = 0; j < s[i].n; ++j) {
                double *p = &s[i].p[3 * j];
                if (turned[i])
                    noct_rotate(R[i], &m[i]->v[3 * j], p);
                else
                    noct_copy3(&m[i]->v[3 * j], p);
            }
            ok = !turned[i] || box_far_from_flat(m[i]) || rotated_fine(m[i], s[i].p);
            for (int k = 0; k < 3; ++k) {
                s[i].lo[k] = INFINITY;
                s[i].hi[k] = -INFINITY;
            }
            for (size_t j = 0; j < s[i].n && ok; ++j)
                for (int k = 0; k < 3; ++k) {
                    const double c = s[i].p[3 * j + k] += x[i]->p[k];
                    s[i].lo[k] = noct_min(s[i].lo[k], c);
                    s[i].hi[k] = noct_max(s[i].hi[k], c);
                }
        }
        for (int k = 0; k < 3 && ok; ++k)
            mag = noct_max(mag, noct_max(fabs(s[i].lo[k]), fabs(s[i].hi[k])));
    }
    bool answered = false;
    /* Two boxes whose placed boxes overlap deeply likely meet: a centre
     * proved inside both (boxes about their origins), else the
     * separating-axis proof on their box forms first; else only when GJK
     * could not answer and the placed boxes overlap. */
    const bool boxes = ok && m[0]->has_dual && m[1]->has_dual && s[0].n == 8 && s[1].n == 8;
    const int overlap = boxes ? sets_overlap(s) : 0;
    /* (box views, noct_box_view(), have no dual but their corners and
     * faces are known: the closed form serves them too) */
    const uint8_t *corner;
    const uint8_t (*face)[2];
    const bool box_like = ok && s[0].n == 8 && s[1].n == 8 &&
                          noct_box_topology(m[0], &corner, &face) &&
                          noct_box_topology(m[1], &corner, &face);
    /* Two boxes about their origins whose placed boxes overlap: either's
     * centre proved inside both (ideal_boxes_meet(), a few products)
     * before the separating-axis proof on their turned forms. */
    bool meet = overlap != 0 && s[0].ideal && s[1].ideal && ideal_boxes_meet(s);
    if (!meet && overlap == 2)
        meet = boxes_proved_meeting(s, R, turned, x);
    if (meet) {
        set_colliding_sets(r, s);
        if (stats)
            ++stats->witnesses;
        free(heap[0]);
        free(heap[1]);
        return true;
    }
    /* Two boxes: their nearest features in closed form, at magnitudes
     * that need no scaling (search_scale()). */
    if (box_like && mag >= 0x1p-100 && mag <= 0x1p100) {
        const bool first = set_first(&s[0], &s[1]);
        if (boxes_distance(&s[first ? 0 : 1], &s[first ? 1 : 0], mag, max_distance, r)) {
            if (!first)
                mirror(r);
            if (stats)
                ++stats->convex_tests;
            free(heap[0]);
            free(heap[1]);
            return true;
        }
    }
    if (ok) {
        const double scale = search_scale(mag);
        if (scale != 1)
            for (int i = 0; i < 2; ++i)
                for (size_t j = 0; j < 3 * s[i].n; ++j)
                    s[i].p[j] *= scale;
        const bool first = set_first(&s[0], &s[1]);
        answered = convex_distance(&s[first ? 0 : 1], &s[first ? 1 : 0], scale, mag,
                                   max_distance, r);
        if (answered && !first)
            mirror(r);
        if (answered && stats)
            ++stats->convex_tests;
        /* (the forms turned and placed as the vertices were, unscaled) */
        if (!answered && overlap == 1 && boxes_proved_meeting(s, R, turned, x)) {
            set_colliding_sets(r, s);
            answered = true;
            if (stats)
                ++stats->witnesses;
        }
    }
    free(heap[0]);
    free(heap[1]);
    return answered;
}

/* A view of m rotated by R, for the general path: m's fields, with its
 * vertices fl(R v) and its hierarchy's boxes refitted to them (the same
 * tree, children after their parents), the bounds theirs; *buf owns the
 * arrays. DEGENERATE when a rotated triangle is near noctMeshCreate()'s
 * tolerance (rotated_fine()), NOMEM. */
static noctStatus rotated_view(const noctMesh *m, const double R[9], noctMesh *view, void **buf)
{
    *buf = NULL;
    double *v = malloc(3 * m->nv * sizeof *v + m->nnodes * sizeof(bvh_node));
    if (v == NULL)
        return NOCT_ERR_NOMEM;
    *buf = v;
    bvh_node *nodes = (bvh_node *)(v + 3 * m->nv);
    for (size_t i = 0; i < m->nv; ++i)
        noct_rotate(R, &m->v[3 * i], &v[3 * i]);
    if (!m->turn_fine && !rotated_fine(m, v))
        return NOCT_ERR_DEGENERATE;
    /* refitted children first; the bounds kept in locals (stores through
     * x would be reloaded for every corner) */
    for (size_t n = m->nnodes; n-- > 0;) {
        const bvh_node *o = &m->nodes[n];
        bvh_node *x = &nodes[n];
        x->first = o->first;
        x->count = o->count;
        double lo[3], hi[3];
        if (o->count > 0) {
            const double *p = &v[3 * m->tri[3 * o->first]];
            for (int k = 0; k < 3; ++k)
                lo[k] = hi[k] = p[k];
            const uint32_t *t = &m->tri[3 * o->first];
            for (uint32_t c = 1; c < 3 * o->count; ++c) {
                p = &v[3 * t[c]];
                /* the axes written out: the loop over them cost a third */
                lo[0] = noct_min(lo[0], p[0]);
                hi[0] = noct_max(hi[0], p[0]);
                lo[1] = noct_min(lo[1], p[1]);
                hi[1] = noct_max(hi[1], p[1]);
                lo[2] = noct_min(lo[2], p[2]);
                hi[2] = noct_max(hi[2], p[2]);
            }
        } else {
            const bvh_node *c0 = &nodes[o->first], *c1 = &nodes[o->first + 1];
            for (int k = 0; k < 3; ++k) {
                lo[k] = noct_min(c0->lo[k], c1->lo[k]);
                hi[k] = noct_max(c0->hi[k], c1->hi[k]);
            }
        }
        for (int k = 0; k < 3; ++k) {
            x->lo[k] = lo[k];
            x->hi[k] = hi[k];
        }
    }
    *view = *m;
    view->v = v;
    view->dual.about_origin = false; /* (its vertices are no longer (+-h)) */
    view->nodes = nodes;
    for (int k = 0; k < 3; ++k) {
        view->lo[k] = nodes[0].lo[k];
        view->hi[k] = nodes[0].hi[k];
    }
    return NOCT_OK;
}

/* Is m worth the convex path: convex, a box form (a rotated box's rounded
 * corners may bend it by an ulp), or every vertex a corner of its hull (a
 * convex shape whose flat faces rounding bent; mesh.c runs qhull only on
 * meshes of more than 32 vertices, and keeps every vertex of smaller
 * ones)? The path's proof holds for any mesh; this only spares the
 * others a GJK that would not prove their distance. */
static bool convex_like(const noctMesh *m)
{
    return m->convex || m->has_box || (!m->surface && m->nv > 32 && m->nhull == m->nv);
}

bool noct_distance_convex_placed(const noctMesh *a, bool a_convex, const double ta[3],
                                 const noctMesh *b, bool b_convex, const double tb[3],
                                 double max_distance, noctDistanceResult *r)
{
    if (!(a_convex || convex_like(a)) || !(b_convex || convex_like(b)))
        return false;
    const noctMesh *m[2] = {a, b};
    double R[2][9] = {{0}};
    const bool turned[2] = {false, false};
    noctTransform xa = noctIdentityTransform(), xb = noctIdentityTransform();
    memcpy(xa.p, ta, sizeof xa.p);
    memcpy(xb.p, tb, sizeof xb.p);
    const noctTransform *x[2] = {&xa, &xb};
    return convex_path(m, R, turned, x, max_distance, r, NULL);
}

/* The turned meshes of m as rotated views (view[i], owning buf[i]; ex[i]
 * says so), or, near the degeneracy tolerance, as rotated meshes
 * (rotated[i]); m[i] then names what to read. The caller frees buf and
 * destroys rotated, whatever the status. */
static noctStatus turned_views(const noctMesh *m[2], double R[2][9], const bool turned[2],
                               noctMesh view[2], void *buf[2], noctMesh *rotated[2],
                               noct_dist_exact ex[2], noctError *err)
{
    noctStatus st = NOCT_OK;
    for (int i = 0; i < 2 && st == NOCT_OK; ++i) {
        if (!turned[i])
            continue;
        st = rotated_view(m[i], R[i], &view[i], &buf[i]);
        if (st == NOCT_OK) {
            ex[i].R = R[i];
            m[i] = &view[i];
        } else if (st == NOCT_ERR_DEGENERATE) {
            /* near the tolerance: the rotated mesh says what it is */
            st = noct_mesh_rotated(m[i], R[i], &rotated[i], err);
            if (st == NOCT_OK)
                m[i] = rotated[i];
        } else {
            noct_fail(err, st, -1, 0, "out of memory");
        }
    }
    return st;
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
    double R[2][9];
    bool turned[2] = {false, false};
    noctStatus st = NOCT_OK;
    for (int i = 0; i < 2 && st == NOCT_OK; ++i) {
        st = noct_transform_matrix(x[i], R[i], err);
        turned[i] = st == NOCT_OK && !noct_is_identity(R[i]);
    }
    if (st != NOCT_OK)
        return st;
    if (convex_like(a) && convex_like(b) &&
        convex_path(m, R, turned, x, max_distance, result, stats))
        return NOCT_OK;
    /* The general path reads a rotated mesh's vertices, triangles and
     * hierarchy only: a view of the mesh with its vertices rotated and its
     * hierarchy's boxes refitted, not a new mesh (its checks, hull and
     * hierarchy cost far more than the search). The exact test, when the
     * search needs it, decides on the views (exact_of()). */
    noctMesh view[2];
    void *buf[2] = {NULL, NULL};
    noct_dist_exact ex[2] = {{NULL}, {NULL}};
    st = turned_views(m, R, turned, view, buf, rotated, ex, err);
    if (st == NOCT_OK) {
        st = noct_distance_placed(m[0], xa->p, m[1], xb->p, max_distance, result, stats, ex);
        if (st != NOCT_OK)
            noct_fail(err, st, -1, 0, "distance: %s", noctStatusString(st));
    }
    for (int i = 0; i < 2; ++i) {
        free(buf[i]);
        noctMeshDestroy(rotated[i]);
    }
    return st;
}

noctStatus noct_collide_exact_views(const noctMesh *a, const noctTransform *xa,
                                    const noctMesh *b, const noctTransform *xb,
                                    double R[2][9], const bool turned[2], bool *colliding,
                                    noctNarrowStats *stats, noctError *err)
{
    const noctMesh *m[2] = {a, b};
    noctMesh view[2], *rotated[2] = {NULL, NULL};
    void *buf[2] = {NULL, NULL};
    noct_dist_exact ex[2] = {{NULL}, {NULL}};
    noctStatus st = turned_views(m, R, turned, view, buf, rotated, ex, err);
    if (st == NOCT_OK) {
        st = exact_of(m[0], xa->p, m[1], xb->p, ex, colliding, stats);
        if (st != NOCT_OK)
            noct_fail(err, st, -1, 0, "collision test: %s", noctStatusString(st));
    }
    for (int i = 0; i < 2; ++i) {
        free(buf[i]);
        noctMeshDestroy(rotated[i]);
    }
    return st;
}
