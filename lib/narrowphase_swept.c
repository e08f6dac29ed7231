/* SPDX-License-Identifier: MIT */
/*
 * Continuous detection of translating meshes: noctCollideSwept().
 *
 * Work in B's frame: A's placed start solid moves by s D, s in [0, 1],
 * D = (ta1 - ta0) - (tb1 - tb0) exactly. If the solids do not meet at
 * s = 0 (the exact level decides), let s* be the least s at which they
 * meet; their interiors are apart there, so they touch on their
 * boundaries: a closed triangle of each meets the other's, and (the least
 * s of a small linear program over the contact's parameters is at one of
 * its vertices) then a vertex of A lies on a triangle of B, a vertex of B
 * on a triangle of A, or an edge of A on an edge of B. So s* is the least
 * time at which a feature pair touches, and the solids meet during the
 * motion iff they meet at the start or some feature pair touches:
 * - vertex p of A and triangle T of B: the segment [p, p + h D] meets T;
 * - vertex q of B and triangle T of A: the segment [q, q - h D] meets T;
 * - edge a0 a1 of A and edge b0 b1 of B: the segment b0 b1 meets the
 *   parallelogram a0, a1, a1 + h D, a0 + h D (two closed triangles);
 * for the horizon h = 1. These are the exact level's segment-against-
 * triangle tests on points whose coordinates are sums of a placed vertex
 * and the translations, with exact signs (predicates.c's xpoints).
 *
 * The time. Each feature pair's "touches by h" is monotone in h, so a
 * bisection over h = k / 2^52 finds its least k exactly; a feature pair
 * is bisected only if it touches before the least time found so far (the
 * horizon, which also shrinks the swept boxes of the walk).
 *
 * The triangle pairs come from the two bounding-volume hierarchies, A's
 * node boxes swept along h D (padded by far more than their rounding);
 * a triangle pair whose six swept points of one triangle lie strictly on
 * one side of the other's plane cannot touch.
 */
#include "config.h"

#include <math.h>
#include <string.h>

#include <noctree/narrowphase.h>

#include "narrowphase_internal.h"
#include "vec3.h"

#define HORIZON_BITS 52
#define HORIZON_ONE (UINT64_C(1) << HORIZON_BITS)

/* A feature pair: 0-2 A's vertex i of its triangle against B's triangle,
 * 3-5 B's vertex against A's triangle, 6-14 A's edge (f - 6) / 3 against
 * B's edge (f - 6) % 3 (edge e joins vertices e and e + 1 mod 3). */
#define FEATURES 15

typedef struct sweep {
    placed A, B;          /* at the start translations */
    const double *dv[4];  /* D = ta1 - ta0 - tb1 + tb0 */
    double D[3];          /* D in floating point */
    double pad[3];        /* the swept boxes' padding, per axis */
    uint64_t k;           /* the horizon: times in [0, k / 2^52] */
    int64_t num, den;     /* k / 2^52 in lowest terms */
    double h;             /* k / 2^52 */
    exact_ctx x;
    noctNarrowStats *st;
    bool timed;           /* find the time, not the verdict alone */
    bool found;
    uint64_t best;        /* the least k found */
    int feature;          /* its feature pair */
    double fa[3][3], fb[3][3]; /* its triangles, placed at the start */
    uint32_t ia, ib;      /* and their indices */
} sweep;

static void set_horizon(sweep *w, uint64_t k)
{
    int z = k == 0 ? HORIZON_BITS : __builtin_ctzll(k);
    if (z > HORIZON_BITS)
        z = HORIZON_BITS;
    w->k = k;
    w->num = (int64_t)(k >> z);
    w->den = (int64_t)(HORIZON_ONE >> z);
    w->h = (double)k / (double)HORIZON_ONE;
}

/* p moved by sign h D (sign 0, 1 or -1), all scaled by den. */
static noct_xpoint xp(const sweep *w, const double p[3], int sign)
{
    static const int64_t dw[4] = {1, -1, -1, 1};
    noct_xpoint x = {.v = {p}, .w = {w->den}, .n = 1};
    if (sign != 0 && w->num != 0) {
        for (int j = 0; j < 4; ++j) {
            x.v[1 + j] = w->dv[j];
            x.w[1 + j] = sign * dw[j] * w->num;
        }
        x.n = 5;
    }
    return x;
}

/* ---- the exact level's segment tests, on xpoints -------------------------- */

static int xo3(const sweep *w, const noct_xpoint *a, const noct_xpoint *b,
               const noct_xpoint *c, const noct_xpoint *d)
{
    return noct_orient3d_x(a, b, c, d, w->x.fallbacks);
}

static int xo2(const sweep *w, int k, const noct_xpoint *a, const noct_xpoint *b,
               const noct_xpoint *c)
{
    return noct_orient2d_x(k, a, b, c, w->x.fallbacks);
}

static int xcmp(const sweep *w, int k, const noct_xpoint *a, const noct_xpoint *b)
{
    return noct_compare_x(k, a, b, w->x.fallbacks);
}

/* p lies in the closed box of segment ab on the two axes other than k. */
static bool xwithin_2d(const sweep *w, int k, const noct_xpoint *p, const noct_xpoint *a,
                       const noct_xpoint *b)
{
    for (int s = 1; s <= 2; ++s) {
        int i = (k + s) % 3, pa = xcmp(w, i, p, a), pb = xcmp(w, i, p, b);
        if (pa * pb > 0)
            return false;
    }
    return true;
}

/* Closed segments pq and ab meet, in the projection dropping axis k. */
static bool xseg_seg_2d(const sweep *w, int k, const noct_xpoint *p, const noct_xpoint *q,
                        const noct_xpoint *a, const noct_xpoint *b)
{
    int d1 = xo2(w, k, p, q, a), d2 = xo2(w, k, p, q, b);
    int d3 = xo2(w, k, a, b, p), d4 = xo2(w, k, a, b, q);
    if (d1 * d2 < 0 && d3 * d4 < 0)
        return true;
    return (d1 == 0 && xwithin_2d(w, k, a, p, q)) || (d2 == 0 && xwithin_2d(w, k, b, p, q)) ||
           (d3 == 0 && xwithin_2d(w, k, p, a, b)) || (d4 == 0 && xwithin_2d(w, k, q, a, b));
}

/* Closed segments pq and ab meet, in 3D. */
static bool xseg_seg_3d(const sweep *w, const noct_xpoint *p, const noct_xpoint *q,
                        const noct_xpoint *a, const noct_xpoint *b)
{
    if (xo3(w, p, q, a, b) != 0)
        return false;
    for (int k = 0; k < 3; ++k)
        if (xo2(w, k, p, q, a) || xo2(w, k, p, q, b) || xo2(w, k, a, b, p) ||
            xo2(w, k, a, b, q))
            return xseg_seg_2d(w, k, p, q, a, b);
    /* All four on a line: compare the intervals on an axis on which they
     * are not all equal (the line is not perpendicular to it, so the
     * projection keeps their order); on none, they coincide. */
    for (int k = 0; k < 3; ++k) {
        if (xcmp(w, k, p, q) == 0 && xcmp(w, k, p, a) == 0 && xcmp(w, k, p, b) == 0)
            continue;
        bool pq_below = xcmp(w, k, p, a) < 0 && xcmp(w, k, p, b) < 0 &&
                        xcmp(w, k, q, a) < 0 && xcmp(w, k, q, b) < 0;
        bool ab_below = xcmp(w, k, a, p) < 0 && xcmp(w, k, a, q) < 0 &&
                        xcmp(w, k, b, p) < 0 && xcmp(w, k, b, q) < 0;
        return !pq_below && !ab_below;
    }
    return true;
}

/* Closed segment pq meets closed triangle abc (any of them degenerate);
 * s1, s2 are the signs of xo3(a, b, c, p) and xo3(a, b, c, q). As
 * narrowphase_internal.h's seg_tri(). */
static bool xseg_tri(const sweep *w, const noct_xpoint *p, const noct_xpoint *q, int s1,
                     int s2, const noct_xpoint *a, const noct_xpoint *b, const noct_xpoint *c)
{
    if (s1 * s2 > 0)
        return false;
    if (s1 != 0 || s2 != 0) {
        int e1 = xo3(w, p, q, a, b), e2 = xo3(w, p, q, b, c), e3 = xo3(w, p, q, c, a);
        return (e1 >= 0 && e2 >= 0 && e3 >= 0) || (e1 <= 0 && e2 <= 0 && e3 <= 0);
    }
    for (int k = 0; k < 3; ++k) {
        int area = xo2(w, k, a, b, c);
        if (area == 0)
            continue;
        int i1 = xo2(w, k, a, b, p), i2 = xo2(w, k, b, c, p), i3 = xo2(w, k, c, a, p);
        if (i1 * area >= 0 && i2 * area >= 0 && i3 * area >= 0)
            return true;
        return xseg_seg_2d(w, k, p, q, a, b) || xseg_seg_2d(w, k, p, q, b, c) ||
               xseg_seg_2d(w, k, p, q, c, a);
    }
    return xseg_seg_3d(w, p, q, a, b) || xseg_seg_3d(w, p, q, b, c) ||
           xseg_seg_3d(w, p, q, c, a);
}

/* Segment pq meets triangle abc, the signs computed here. */
static bool xseg_tri_signs(const sweep *w, const noct_xpoint *p, const noct_xpoint *q,
                           const noct_xpoint *a, const noct_xpoint *b, const noct_xpoint *c)
{
    int s1 = xo3(w, a, b, c, p);
    if (s1 == 0)
        return xseg_tri(w, p, q, 0, xo3(w, a, b, c, q), a, b, c);
    int s2 = xo3(w, a, b, c, q);
    return s1 * s2 <= 0 && xseg_tri(w, p, q, s1, s2, a, b, c);
}

/* ---- feature pairs --------------------------------------------------------- */

/* Does feature pair f of triangles ta (A's) and tb (B's) touch by the
 * horizon? */
static bool feature_touches(const sweep *w, int f, double ta[3][3], double tb[3][3])
{
    if (f < 6) {
        /* A vertex against the other triangle, moving by +h D (A's) or
         * -h D (B's, in A's frame). */
        double(*tv)[3] = f < 3 ? ta : tb, (*tt)[3] = f < 3 ? tb : ta;
        noct_xpoint p = xp(w, tv[f % 3], 0), q = xp(w, tv[f % 3], f < 3 ? 1 : -1);
        noct_xpoint a = xp(w, tt[0], 0), b = xp(w, tt[1], 0), c = xp(w, tt[2], 0);
        return xseg_tri_signs(w, &p, &q, &a, &b, &c);
    }
    int e = (f - 6) / 3, g = (f - 6) % 3;
    noct_xpoint a0 = xp(w, ta[e], 0), a1 = xp(w, ta[(e + 1) % 3], 0);
    noct_xpoint a1d = xp(w, ta[(e + 1) % 3], 1), a0d = xp(w, ta[e], 1);
    noct_xpoint p = xp(w, tb[g], 0), q = xp(w, tb[(g + 1) % 3], 0);
    return xseg_tri_signs(w, &p, &q, &a0, &a1, &a1d) ||
           xseg_tri_signs(w, &p, &q, &a0, &a1d, &a0d);
}

/* The three points of t and the same moved by sign h D lie strictly on
 * one side of the plane of u: then t's swept triangle and u never
 * touch. */
static bool one_side(const sweep *w, double t[3][3], int sign, double u[3][3])
{
    noct_xpoint a = xp(w, u[0], 0), b = xp(w, u[1], 0), c = xp(w, u[2], 0);
    int side = 0;
    for (int i = 0; i < 3; ++i)
        for (int m = 0; m < 2; ++m) {
            noct_xpoint p = xp(w, t[i], m * sign);
            int s = xo3(w, &a, &b, &c, &p);
            if (s == 0 || (side != 0 && s != side))
                return false;
            side = s;
        }
    return true;
}

/* Bisect feature f, which touches by the horizon, for its least time;
 * keep it if it is the earliest, and leave the horizon just before the
 * earliest (only earlier contacts matter now). */
static void refine(sweep *w, int f, uint32_t i, double ta[3][3], uint32_t j,
                   double tb[3][3])
{
    /* The solids do not meet at time 0, so no feature touches by 0. */
    uint64_t lo = 0, hi = w->k;
    while (hi - lo > 1) {
        uint64_t mid = lo + (hi - lo) / 2;
        set_horizon(w, mid);
        if (feature_touches(w, f, ta, tb))
            hi = mid;
        else
            lo = mid;
    }
    if (!w->found || hi < w->best) {
        w->found = true;
        w->best = hi;
        w->feature = f;
        memcpy(w->fa, ta, sizeof w->fa);
        memcpy(w->fb, tb, sizeof w->fb);
        w->ia = i;
        w->ib = j;
    }
    set_horizon(w, w->best - 1);
}

static inline bool swept_prune(void *context, const bvh_node *na, const bvh_node *nb)
{
    const sweep *w = context;
    if (w->st)
        ++w->st->bvh_pairs;
    for (int k = 0; k < 3; ++k) {
        double alo = na->lo[k] + w->A.t[k], ahi = na->hi[k] + w->A.t[k];
        double blo = nb->lo[k] + w->B.t[k], bhi = nb->hi[k] + w->B.t[k];
        double hd = w->h * w->D[k];
        double pad = w->pad[k] + 0x1p-40 * (fabs(alo) + fabs(ahi) + fabs(blo) + fabs(bhi));
        if (ahi + noct_max(hd, 0) + pad < blo || bhi + pad < alo + noct_min(hd, 0))
            return true;
    }
    return false;
}

static inline bool swept_pair(void *context, uint32_t i, double ta[3][3], uint32_t j,
                              double tb[3][3])
{
    sweep *w = context;
    if (w->st)
        ++w->st->triangle_pairs;
    if (w->k == 0 || one_side(w, ta, 1, tb) || one_side(w, tb, -1, ta))
        return false;
    for (int f = 0; f < FEATURES && w->k > 0; ++f) {
        if (!feature_touches(w, f, ta, tb))
            continue;
        if (!w->timed)
            return true;
        refine(w, f, i, ta, j, tb);
    }
    return false;
}

/* ---- the swept boxes' separating axes ------------------------------------- */

/*
 * Two box-shaped meshes (mesh_internal.h's box slots: every vertex within
 * dev of a corner of the box c + sum of +-e[i], so each solid lies in its
 * box grown by dev), A moving from ta0 to ta1 and B from tb0 to tb1, kept
 * apart along an axis u over the whole motion: with D the relative
 * motion, the centres' distance along u over the motion is the interval
 * around (cB - cA) u - D u / 2 of half-width |D u| / 2, and the radii are
 * sum |e[i] u| + dev |u|_1. Every quantity is computed in floating point
 * within a few dozen ulps of the magnitudes summed in m, so a gap beyond
 * 2^-40 of m |u|_1 is real; m includes the end translations, so the
 * solids placed at the end (within rounding of the start's moved by D)
 * are apart too. The axes: the boxes' edges, their cross products, and
 * the edges' cross products with D.
 */
bool noct_swept_slots_apart(const noct_box_slot *fa, const double ta0[3], const double ta1[3],
                            const noct_box_slot *fb, const double tb0[3], const double tb1[3])
{
    double c[3], D[3], m = (double)fa->dev + (double)fb->dev + 0x1p-1000;
    for (int k = 0; k < 3; ++k) {
        c[k] = (fb->c[k] + tb0[k]) - (fa->c[k] + ta0[k]);
        D[k] = (ta1[k] - ta0[k]) - (tb1[k] - tb0[k]);
        m += fabs(fa->c[k]) + fabs(fb->c[k]) + fabs(ta0[k]) + fabs(tb0[k]) + fabs(ta1[k]) +
             fabs(tb1[k]) + fabs(D[k]);
        for (int i = 0; i < 3; ++i)
            m += fabs(fa->e[i][k]) + fabs(fb->e[i][k]);
    }
    double axes[21][3];
    int n = 0;
    for (int i = 0; i < 3; ++i) {
        noct_copy3(fa->e[i], axes[n++]);
        noct_copy3(fb->e[i], axes[n++]);
        noct_cross3(D, fa->e[i], axes[n++]);
        noct_cross3(D, fb->e[i], axes[n++]);
        for (int j = 0; j < 3; ++j)
            noct_cross3(fa->e[i], fb->e[j], axes[n++]);
    }
    for (int a = 0; a < n; ++a) {
        const double *u = axes[a];
        double u1 = fabs(u[0]) + fabs(u[1]) + fabs(u[2]);
        if (!(u1 > 0) || !isfinite(u1))
            continue;
        double r = ((double)fa->dev + (double)fb->dev) * u1;
        for (int i = 0; i < 3; ++i)
            r += fabs(noct_dot3(fa->e[i], u)) + fabs(noct_dot3(fb->e[i], u));
        double du = noct_dot3(D, u);
        double gap = fabs(noct_dot3(c, u) - du / 2) - fabs(du) / 2 - r;
        if (gap > 0x1p-40 * m * u1)
            return true;
    }
    return false;
}

/* ---- noctCollideSwept() ----------------------------------------------------- */

static bool finite_in_range(const double t[3], noctStatus *st)
{
    for (int k = 0; k < 3; ++k) {
        if (!isfinite(t[k])) {
            *st = NOCT_ERR_NONFINITE;
            return false;
        }
        if (fabs(t[k]) > NOCT_MAX_COORDINATE) {
            *st = NOCT_ERR_TOO_LARGE;
            return false;
        }
    }
    return true;
}

/* Do a and b, placed at ta and tb, collide (exact level)? */
static noctStatus placed_collide(const noctMesh *a, const double ta[3], const noctMesh *b,
                                 const double tb[3], bool *hit, noctNarrowStats *st)
{
    if (!noct_boxes_overlap(a->lo, a->hi, ta, b->lo, b->hi, tb)) {
        *hit = false;
        return NOCT_OK;
    }
    return noct_collide_overlapping(a, ta, b, tb, NOCT_ACCURACY_EXACT, hit, st);
}

void noct_box_overlap_centre(const noctMesh *a, const double ta[3], const noctMesh *b,
                             const double tb[3], double c[3])
{
    for (int k = 0; k < 3; ++k) {
        double lo = noct_max(a->lo[k] + ta[k], b->lo[k] + tb[k]);
        double hi = noct_min(a->hi[k] + ta[k], b->hi[k] + tb[k]);
        c[k] = lo + (hi - lo) / 2;
    }
}

/* The hit's features, indices and point from what the sweep kept. */
static void describe(const sweep *w, const double ta0[3], const double ta1[3],
                     const double tb0[3], const double tb1[3], noctSweepHit *hit)
{
    const double t = hit->time;
    const uint32_t *tria = &w->A.m->tri[3 * (size_t)w->ia];
    const uint32_t *trib = &w->B.m->tri[3 * (size_t)w->ib];
    double da[3], db[3];
    for (int k = 0; k < 3; ++k) {
        da[k] = t * (ta1[k] - ta0[k]);
        db[k] = t * (tb1[k] - tb0[k]);
    }
    const int f = w->feature;
    if (f < 3) {
        hit->feature = NOCT_SWEEP_VERTEX_FACE;
        hit->a[0] = tria[f];
        memcpy(hit->b, trib, sizeof hit->b);
        noct_add3(w->fa[f], da, hit->point);
    } else if (f < 6) {
        hit->feature = NOCT_SWEEP_FACE_VERTEX;
        memcpy(hit->a, tria, sizeof hit->a);
        hit->b[0] = trib[f - 3];
        noct_add3(w->fb[f - 3], db, hit->point);
    } else {
        int e = (f - 6) / 3, g = (f - 6) % 3;
        hit->feature = NOCT_SWEEP_EDGE_EDGE;
        hit->a[0] = tria[e];
        hit->a[1] = tria[(e + 1) % 3];
        hit->b[0] = trib[g];
        hit->b[1] = trib[(g + 1) % 3];
        /* The point of line p + u r nearest line q + v s. */
        double p[3], r[3], q[3], s[3], pq[3];
        noct_add3(w->fa[e], da, p);
        noct_add3(w->fb[g], db, q);
        noct_sub3(w->fa[(e + 1) % 3], w->fa[e], r);
        noct_sub3(w->fb[(g + 1) % 3], w->fb[g], s);
        noct_sub3(q, p, pq);
        double rr = noct_dot3(r, r), rs = noct_dot3(r, s), ss = noct_dot3(s, s);
        double den = rr * ss - rs * rs;
        double u = den > 0 ? (noct_dot3(pq, r) * ss - noct_dot3(pq, s) * rs) / den : 0.5;
        u = noct_min(noct_max(u, 0), 1);
        for (int k = 0; k < 3; ++k)
            hit->point[k] = p[k] + u * r[k];
    }
}

noctStatus noctCollideSwept(const noctMesh *a, const double ta0[3], const double ta1[3],
                            const noctMesh *b, const double tb0[3], const double tb1[3],
                            bool *colliding, noctSweepHit *hit, noctNarrowStats *stats)
{
    NOCT_REQUIRE(a != NULL && ta0 != NULL && ta1 != NULL);
    NOCT_REQUIRE(b != NULL && tb0 != NULL && tb1 != NULL && colliding != NULL);
    noctStatus st = NOCT_OK;
    if (!finite_in_range(ta0, &st) || !finite_in_range(ta1, &st) ||
        !finite_in_range(tb0, &st) || !finite_in_range(tb1, &st))
        return st;
    if (hit != NULL)
        noct_sweep_hit_none(hit);
    sweep w = {.A = {a, {ta0[0], ta0[1], ta0[2]}},
               .B = {b, {tb0[0], tb0[1], tb0[2]}},
               .dv = {ta1, ta0, tb1, tb0},
               .x = {stats ? &stats->exact_fallbacks : NULL},
               .st = stats,
               .timed = hit != NULL,
               .best = HORIZON_ONE};
    for (int k = 0; k < 3; ++k) {
        w.D[k] = (ta1[k] - ta0[k]) - (tb1[k] - tb0[k]);
        w.pad[k] = 0x1p-40 * (fabs(ta0[k]) + fabs(ta1[k]) + fabs(tb0[k]) + fabs(tb1[k])) +
                   0x1p-1000;
    }
    set_horizon(&w, HORIZON_ONE);
    if (stats)
        ++stats->box_tests;
    if (a->has_box && b->has_box) {
        noct_box_slot sa, sb;
        noct_box_slot_fill(a, &sa);
        noct_box_slot_fill(b, &sb);
        if (noct_swept_slots_apart(&sa, ta0, ta1, &sb, tb0, tb1)) {
            if (stats)
                ++stats->sat_rejects;
            *colliding = false;
            return NOCT_OK;
        }
    }
    bool touch;
    st = placed_collide(a, ta0, b, tb0, &touch, stats);
    if (st != NOCT_OK)
        return st;
    if (touch) {
        *colliding = true;
        if (hit != NULL) {
            hit->time = 0;
            hit->feature = NOCT_SWEEP_START;
            noct_box_overlap_centre(a, ta0, b, tb0, hit->point);
        }
        return NOCT_OK;
    }
    if (hit == NULL) {
        /* The verdict alone: the end, cheaper than the walk, first. */
        st = placed_collide(a, ta1, b, tb1, &touch, stats);
        if (st != NOCT_OK || touch) {
            *colliding = touch;
            return st;
        }
    }
    if (stats)
        ++stats->exact_tests;
    bool swept = noct_bvh_pair_walk(&w.A, &w.B, swept_prune, swept_pair, &w);
    if (swept || w.found) {
        *colliding = true;
        if (hit != NULL && w.found) {
            hit->time = (double)w.best / (double)HORIZON_ONE;
            describe(&w, ta0, ta1, tb0, tb1, hit);
        } else if (hit != NULL) {
            /* the walk's stack overflowed (never within the size limits):
             * the conservative answer, without a time */
            hit->feature = NOCT_SWEEP_END;
            noct_box_overlap_centre(a, ta1, b, tb1, hit->point);
        }
        return NOCT_OK;
    }
    if (hit == NULL) {
        *colliding = false;
        return NOCT_OK;
    }
    st = placed_collide(a, ta1, b, tb1, &touch, stats);
    if (st == NOCT_OK) {
        *colliding = touch;
        if (touch && hit != NULL) {
            hit->time = 1;
            hit->feature = NOCT_SWEEP_END;
            noct_box_overlap_centre(a, ta1, b, tb1, hit->point);
        }
    }
    return st;
}
