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

