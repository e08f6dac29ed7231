/* SPDX-License-Identifier: MIT */
/*
 * The margin (noctWorldDef::margin): after a step's pairs, the pairs of
 * objects within the margin of each other ("near": the arm is about to
 * collide), and the pairs that became near or stopped being near. The
 * candidates are the pairs (i, j), i < j, whose boxes come within i's
 * box grown by the margin: the pairs whose boxes come within it grown
 * by a skin too are found by sweeping columns of a grid (columns_all();
 * each leaf of the broadphase sweeps the boxes that may have a candidate
 * it owns when the columns cannot serve, and when there is no list) and
 * kept for the next steps while the boxes move less than the
 * skin (near_candidates(), kept_candidates(); with no
 * exact tree, or when the leaves would gather far more boxes than there
 * are objects, each object scans its leaves' lists or queries the tree
 * with its grown box instead, as noct_world_stage_near() does: the same
 * candidates). A pair that collides is near; boxes farther apart than
 * the margin and the triangles' slack are not (boxes_near(), made in the
 * leaves' sweeps on the gathered copies); a pair of box forms that a
 * separating axis proves farther apart is not, a pair of box forms with
 * two points of its solids proved within the margin is, and one proved
 * beyond it on the axis through those points is not (near_witness(): the
 * answers noct_solids_within() would give; tried in the order that
 * settles most pairs soonest, which changes no answer), and else the
 * distance of their triangles decides (noct_solids_within()).
 * A pair's margin is the world's plus its objects' own (noct_margins).
 * The candidates hold every pair whose boxes overlap: a step of one
 * sub-step in a world of few sensors makes them before its pair search
 * and takes the search's pairs from them, and the sensors' from queries
 * (noct_world_near_pairs()).
 * A world without any margin never comes here (but once, to end the
 * pairs of the last margin that went).
 */
#include "config.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "box_sweep.h"
#include "narrowphase_internal.h"
#include "world_internal.h"

typedef struct partners {
    uint32_t self;
    uint32_t *s;
    size_t n, cap;
    bool failed;
} partners;

NOCT_DEFINE_GROW(grow_u32, uint32_t)
NOCT_DEFINE_GROW(grow_hint, noct_near_hint)

/* The hints of a step: the last step's, read in the order of the pairs
 * (both lists sorted by (i, j)), and this one's, made as the pairs are
 * decided (failed: no room for them, and this step keeps none). */
typedef struct hint_walk {
    const noct_near_hint *old, *end;
    noct_near_hint *h;
    size_t n, cap;
    bool failed;
} hint_walk;

/* The last step's hint for pair (i, j), or NULL; pairs asked in order. */
static NOCT_ALWAYS_INLINE const noct_near_hint *hint_of(hint_walk *k, uint32_t i, uint32_t j)
{
    while (k->old < k->end && (k->old->i < i || (k->old->i == i && k->old->j < j)))
        ++k->old;
    return k->old < k->end && k->old->i == i && k->old->j == j ? k->old : NULL;
}

/* Keep pair (i, j)'s proof h, if any, for the next step. */
static NOCT_ALWAYS_INLINE void hint_keep(hint_walk *k, uint32_t i, uint32_t j,
                                         const noct_near_hint *h)
{
    if (h->kind == 0 || k->failed)
        return;
    if (k->n == k->cap && !grow_hint(&k->h, &k->cap, k->cap > 0 ? k->n + 1 : 1024)) {
        k->failed = true;
        return;
    }
    k->h[k->n] = *h;
    k->h[k->n].i = i;
    k->h[k->n].j = j;
    ++k->n;
}

static bool take(void *context, noctProxyId id, void *user)
{
    (void)user;
    partners *p = context;
    if (id.index <= p->self)
        return true;
    if (!grow_u32(&p->s, &p->cap, p->cap > 0 ? p->n + 1 : 16)) {
        p->failed = true;
        return false;
    }
    p->s[p->n++] = id.index;
    return true;
}

static int by_index(const void *a, const void *b)
{
    const uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return (x > y) - (x < y);
}

/* Is (a, b), a < b, in the sorted list? */
static bool listed(const noct_pair_list *l, uint32_t a, uint32_t b)
{
    size_t lo = 0, hi = l->n;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        const noctPair *p = &l->p[mid];
        if (p->a.index < a || (p->a.index == a && p->b.index < b))
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < l->n && l->p[lo].a.index == a && l->p[lo].b.index == b;
}

/*
 * Two points of the solids of two placed box forms with duals proved
 * within d of each other: then the solids are within d, which
 * noct_solids_within() would answer (it never misses such a pair) at
 * some hundred thousand operations, a few hundred here. The lemma of
 * noct_box_decide()'s proof (narrowphase.c) puts every point
 * c + t + sum l_i e[i] with |l_i| <= 1 - shrink inside the solid. The
 * points are found by projecting onto each shrunk box in turn from the
 * other's last point (alternating projections, which approach the
 * closest pair of two convex sets), each coefficient clamped: any
 * coefficients in range give a point of the solid, so the projection's
 * rounding (or edges not quite orthogonal) can only make the points
 * worse, never wrong. The points in doubles are within 16 half-ulps of M
 * (box_offset()) of the exact ones per coordinate (the sum c + t, three
 * products and three additions), their difference and its length add a
 * few more; 256 half-ulps of M and a relative 2^-48 cover them. 1: the
 * pair is near. 0: the points' direction, tried every WITNESS_CHECK
 * rounds, proves the solids farther apart than noct_solids_within()
 * answers true for (witness_apart()). -1: the pair needs the triangles
 * (no dual, or neither proof after WITNESS_ROUNDS rounds: within a hair
 * of the margin, or faces so nearly parallel that alternating projections
 * approach their closest points slowly; six rounds left a pair in 200 to
 * the triangles on keyframes:2000, 64 one in 25 000, each round a few
 * dozen operations where the triangles take some 300 000).
 */
#define WITNESS_ROUNDS 64
#define WITNESS_CHECK 8

/* The coefficients of the point of shrunk box s (centre at C, factor f)
 * nearest x, if its edges are orthogonal, clamped to it, into lam; and the
 * point. */
static NOCT_ALWAYS_INLINE void project_box(const noct_box_slot *s, const double C[3], double f,
                                           const double x[3], double p[3], double lam[3])
{
    const double r[3] = {x[0] - C[0], x[1] - C[1], x[2] - C[2]};
    p[0] = C[0];
    p[1] = C[1];
    p[2] = C[2];
    for (int i = 0; i < 3; ++i) {
        const double *e = s->e[i];
        const double ee = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
        double l = ee > 0 ? (e[0] * r[0] + e[1] * r[1] + e[2] * r[2]) / ee : 0;
        l = l > f ? f : l < -f ? -f : l; /* (a NaN stays: the check fails) */
        lam[i] = l;
        for (int k = 0; k < 3; ++k)
            p[k] += l * e[k];
    }
}

/* The gap test: do the points' direction v (q - p) prove the solids
 * farther apart than noct_solids_within() answers true for? Their gap
 * along it, with noct_box_apart_by()'s allowances (each solid lies within
 * dev of its ideal box on every coordinate), bounds the distance from
 * below; beyond d and twice the slack of noct_solids_within() (2^-40 of
 * the coordinates, which M bounds), that test answers false. */
static bool witness_apart(const noct_box_slot *a, const noct_box_slot *b, const double T[3],
                          double M, double unit, double d, const double v[3])
{
    const double n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (!(n > 0 && isfinite(n)))
        return false;
    const double u[3] = {v[0] / n, v[1] / n, v[2] / n};
    const double l1 = fabs(u[0]) + fabs(u[1]) + fabs(u[2]);
    const double dev = (double)a->dev + (double)b->dev;
    const double gap = fabs(u[0] * T[0] + u[1] * T[1] + u[2] * T[2]) - box_radius(a->e, u) -
                       box_radius(b->e, u) - l1 * dev - unit * l1;
    const double un = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    const double beyond = d + 2 * 0x1p-40 * noct_max(d, M);
    return gap > beyond * un * (1 + 0x1p-40);
}

/* A hint from a proof: near, with the coefficients of the two points; or
 * apart, along axis v. */
static void hint_near(noct_near_hint *h, const double la[3], const double lb[3])
{
    h->kind = NOCT_HINT_NEAR;
    for (int k = 0; k < 3; ++k) {
        h->h[k] = (float)la[k];
        h->h[3 + k] = (float)lb[k];
    }
}

static void hint_apart(noct_near_hint *h, const double v[3])
{
    h->kind = NOCT_HINT_APART;
    for (int k = 0; k < 3; ++k)
        h->h[k] = (float)v[k];
}

/* near_witness() below; when it proves the pair near or apart, the proof
 * as a hint into *h. from: where the projections start in b's shrunk box
 * (its centre when NULL; any point will do: the points are found anew). */
static int near_witness(const noct_box_slot *a, const double ta[3], const noct_box_slot *b,
                        const double tb[3], double d, int rounds, noct_near_hint *h,
                        const double *from)
{
    if (!(a->shrink < 1 && b->shrink < 1))
        return -1;
    const double fa = 1 - (double)a->shrink, fb = 1 - (double)b->shrink;
    double T[3];
    const double M = box_offset(a, ta, b, tb, T);
    const double unit = 256 * 0x1p-53 * M;
    if (!(d > unit))
        return -1;
    const double CA[3] = {a->c[0] + ta[0], a->c[1] + ta[1], a->c[2] + ta[2]};
    const double CB[3] = {b->c[0] + tb[0], b->c[1] + tb[1], b->c[2] + tb[2]};
    const double reach = (d - unit) * (1 - 0x1p-48);
    const double *q0 = from != NULL ? from : CB;
    double p[3], q[3] = {q0[0], q0[1], q0[2]}, v[3] = {0, 0, 0}, la[3], lb[3];
    for (int round = 1; round <= rounds; ++round) {
        project_box(a, CA, fa, q, p, la);
        project_box(b, CB, fb, p, q, lb);
        for (int k = 0; k < 3; ++k)
            v[k] = q[k] - p[k];
        if (sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) <= reach) {
            hint_near(h, la, lb);
            return 1;
        }
        /* Not near, it seems: the points' direction is close to the one
         * along which the box forms are farthest apart (now and then, as
         * the projections approach the closest pair) */
        if ((round & (WITNESS_CHECK - 1)) == 0 && witness_apart(a, b, T, M, unit, d, v)) {
            hint_apart(h, v);
            return 0;
        }
    }
    return -1;
}

/*
 * The last step's proof of a pair of box forms (a hint, noct_near_hint)
 * made afresh for their placements now: 1 near, 0 apart, -1 when it
 * proves neither (then the pair is decided as without it). Nothing of the
 * hint is trusted: a near hint's coefficients, converted back to doubles
 * (exactly) and clamped to the shrunk boxes' ranges now, are coefficients
 * in range whatever they are, so they give points of the solids (the
 * lemma of near_witness()), computed in the same operations and order as
 * near_witness() computes its points, and its bound on their roundings
 * (256 half-ulps of M, M made from the placements now, and the relative
 * 2^-48 of reach) holds as it stands: the pair is proved within the
 * margin, which noct_solids_within() would answer too (it never misses
 * such a pair). An apart hint's axis, any finite non-zero vector, is
 * handed to witness_apart() as near_witness() hands it its points'
 * direction: its argument holds for any axis. So every answer here is
 * one that each of near_solids()'s proofs would give if it decided the
 * pair (none answers near for a pair farther apart than witness_apart()
 * proves, nor apart for a pair within the margin): the hint changes no
 * answer, only the cost, whether the objects moved, turned, were placed
 * anew or replaced by others in the same slots since. Some thirty
 * operations for an apart hint, fifty for a near one.
 */
static int hint_proof(const noct_box_slot *a, const double ta[3], const noct_box_slot *b,
                      const double tb[3], double d, const noct_near_hint *h, double from[3])
{
    double T[3];
    const double M = box_offset(a, ta, b, tb, T);
    const double unit = 256 * 0x1p-53 * M;
    if (!(d > unit))
        return -1;
    if (h->kind == NOCT_HINT_APART) {
        const double v[3] = {(double)h->h[0], (double)h->h[1], (double)h->h[2]};
        return witness_apart(a, b, T, M, unit, d, v) ? 0 : -1;
    }
    if (h->kind != NOCT_HINT_NEAR || !(a->shrink < 1 && b->shrink < 1))
        return -1;
    const double f[2] = {1 - (double)a->shrink, 1 - (double)b->shrink};
    const noct_box_slot *s[2] = {a, b};
    const double *t[2] = {ta, tb};
    double x[2][3];
    for (int o = 0; o < 2; ++o) {
        for (int k = 0; k < 3; ++k)
            x[o][k] = s[o]->c[k] + t[o][k];
        for (int i = 0; i < 3; ++i) {
            double l = (double)h->h[3 * o + i];
            l = l > f[o] ? f[o] : l < -f[o] ? -f[o] : l;
            for (int k = 0; k < 3; ++k)
                x[o][k] += l * s[o]->e[i][k];
        }
    }
    const double reach = (d - unit) * (1 - 0x1p-48);
    const double v[3] = {x[1][0] - x[0][0], x[1][1] - x[0][1], x[1][2] - x[0][2]};
    memcpy(from, x[1], sizeof x[1]);
    return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) <= reach ? 1 : -1;
}

/* The squared gap between boxes a and b (objects i's and j's, i < j), in
 * floating point, and in *scale the larger of d and their coordinates'
 * magnitudes. */
static NOCT_ALWAYS_INLINE double box_gap2(const double alo[3], const double ahi[3],
                                          const double blo[3], const double bhi[3], double d,
                                          double *scale)
{
    double s = 0;
    *scale = d;
    for (int k = 0; k < 3; ++k) {
        const double g = noct_max(noct_max(blo[k] - ahi[k], alo[k] - bhi[k]), 0);
        s += g * g;
        *scale = noct_max(*scale, noct_max(noct_max(fabs(alo[k]), fabs(ahi[k])),
                                           noct_max(fabs(blo[k]), fabs(bhi[k]))));
    }
    return s;
}

static NOCT_ALWAYS_INLINE bool boxes_overlap(const double alo[3], const double ahi[3],
                                             const double blo[3], const double bhi[3])
{
    return !((ahi[0] < blo[0]) | (bhi[0] < alo[0]) | (ahi[1] < blo[1]) | (bhi[1] < alo[1]) |
             (ahi[2] < blo[2]) | (bhi[2] < alo[2]));
}

/* The boxes' test of near() below (box: the world's accuracy is
 * NOCT_ACCURACY_BOX), on boxes a and b of objects i < j
 * (colliding pairs pass it: their boxes overlap, so their gap is 0): at
 * the box level the answer, else false when the boxes alone prove the
 * pair not near. */
static NOCT_ALWAYS_INLINE bool boxes_near_as(bool box, const double alo[3],
                                             const double ahi[3], const double blo[3],
                                             const double bhi[3], double d)
{
    double scale;
    const double s = box_gap2(alo, ahi, blo, bhi, d, &scale);
    if (box) {
        const double reach = d + 0x1p-40 * scale;
        return s <= reach * reach;
    }
    /* Boxes farther apart than d and 2^-37 of their coordinates: each
     * solid lies in its box (up to the roundings of its placed
     * vertices, a few ulps of those coordinates), so the solids are
     * farther apart than d and twice noct_solids_within()'s slack
     * (2^-40 of the same coordinates, or of d), where it answers
     * false; the box forms' proofs below never answer true there
     * (their points lie in the solids). A few dozen operations, where
     * the separating-axis test takes hundreds. */
    const double beyond = d + 0x1p-37 * scale;
    return !(s > beyond * beyond);
}

static NOCT_ALWAYS_INLINE bool boxes_near(const noctWorld *w, const double alo[3],
                                          const double ahi[3], const double blo[3],
                                          const double bhi[3], double d)
{
    return boxes_near_as(w->def.accuracy == NOCT_ACCURACY_BOX, alo, ahi, blo, bhi, d);
}

/* A mark of box form s's turn, which an object that only moved keeps (a
 * heuristic: which hints to try). */
static NOCT_ALWAYS_INLINE float turn_mark(const noct_box_slot *s)
{
    return (float)(s->e[0][1] + s->e[1][2] + s->e[2][0]);
}

/* Are objects i and j, whose boxes passed boxes_near(), near at the
 * world's level (not the box level), if they do not collide? overlap:
 * their boxes overlap (a hint only). old: the last step's proof of the
 * pair, or NULL; the proof made, if any, into *h (kind 0: none). */
static bool near_solids(const noctWorld *w, uint32_t i, uint32_t j, double d, bool overlap,
                        const noct_near_hint *old, noct_near_hint *h)
{
    h->kind = 0;
    if (w->slot[i].has_box && w->slot[j].has_box) {
        const noct_box_slot *a = &w->slot[i], *b = &w->slot[j];
        h->turn[0] = turn_mark(a);
        h->turn[1] = turn_mark(b);
        /* (a turned object's hint seldom holds: not tried) */
        if (old != NULL && old->turn[0] == h->turn[0] && old->turn[1] == h->turn[1]) {
            double from[3] = {0, 0, 0};
            const int r = hint_proof(a, w->pos[i], b, w->pos[j], d, old, from);
            if (r >= 0) {
                *h = *old;
                return r == 1;
            }
            /* a near pair that moved: most often still near, its points
             * found again by a round of projections from j's old point
             * (which changes no answer, as any start would not) */
            if (old->kind == NOCT_HINT_NEAR &&
                near_witness(a, w->pos[i], b, w->pos[j], d, 1, h, from) == 1)
                return true;
        }
        /* Where the boxes overlap, a first round of the witness proves
         * most near pairs near (on keyframes:2000 four in five) in a few
         * hundred operations, where the separating-axis test tries all
         * its 15 axes in vain; else the pair is more often apart, which
         * that test proves sooner. The order of the proofs changes no
         * answer, as none contradicts another (the witness's points lie
         * in the solids, the axes part the solids' boxes by more than
         * d). */
        if (overlap && near_witness(a, w->pos[i], b, w->pos[j], d, 1, h, NULL) == 1)
            return true;
        /* two boxes that a separating axis proves farther apart: the
         * common case, a few dozen operations */
        double axis[3];
        if (noct_box_apart_axis(a, w->pos[i], b, w->pos[j], d, axis)) {
            hint_apart(h, axis);
            return false;
        }
        const int r = near_witness(a, w->pos[i], b, w->pos[j], d, WITNESS_ROUNDS, h, NULL);
        if (r >= 0)
            return r == 1;
    }
    noct_shape_view va, vb;
    const noctMesh *ma = noct_world_shape(w, i, &va), *mb = noct_world_shape(w, j, &vb);
    return noct_solids_within(ma, w->pos[i], mb, w->pos[j], d);
}

/* Are objects i and j near, at the world's level, if they collide or
 * not (colliding: listed in the step's contacts)? */
static bool near(const noctWorld *w, uint32_t i, uint32_t j, double d, bool colliding,
                 const noct_near_hint *old, noct_near_hint *h)
{
    h->kind = 0;
    if (colliding)
        return true;
    const noct_aabb *a = noct_bp_box(&w->bp, i), *b = noct_bp_box(&w->bp, j);
    if (!boxes_near(w, a->lo, a->hi, b->lo, b->hi, d))
        return false;
    return w->def.accuracy == NOCT_ACCURACY_BOX ||
           near_solids(w, i, j, d, boxes_overlap(a->lo, a->hi, b->lo, b->hi), old, h);
}

/* Leaves an object's scan reads at most, and their sizes' largest ratio
 * (for the exact volumes below). */
#define SCAN_LEAVES 8
#define SCAN_RATIO 0x1p16

/*
 * The partners of object i of higher index whose boxes meet its grown box
 * [lo, hi], when that box lies in the leaves i is in: every box that meets
 * it meets one of them (cells are closed), so is in its list, and a scan
 * of the lists finds what a query would, with the query's own tests (the
 * filters, the closed boxes), for a fraction of its cost (a query walks
 * from the root and scans the boxes of every leaf it meets). A box in
 * several of the leaves is taken in the first. The leaves (cubes of
 * disjoint interiors) cover the grown box when it lies in their bounding
 * box and their volumes add up to its: counted in cubes of the smallest
 * size, all exact (the corners are, their differences are multiples of
 * that size, and the counts stay below 2^51). false when they may not:
 * then i queries.
 */
static bool leaf_partners(const noctWorld *w, uint32_t i, const double lo[3], const double hi[3],
                          partners *p)
{
    const uint32_t nl = noct_bp_leaf_count(&w->bp, i);
    if (nl == 0 || nl > SCAN_LEAVES)
        return false;
    const noct_cell *c[SCAN_LEAVES];
    double blo[3], bhi[3], smin = INFINITY, smax = 0;
    for (uint32_t s = 0; s < nl; ++s) {
        c[s] = noct_bp_leaf(&w->bp, i, s);
        smin = noct_min(smin, c[s]->size);
        smax = noct_max(smax, c[s]->size);
        for (int k = 0; k < 3; ++k) {
            const double clo = c[s]->lo[k], chi = c[s]->lo[k] + c[s]->size;
            blo[k] = s == 0 ? clo : noct_min(blo[k], clo);
            bhi[k] = s == 0 ? chi : noct_max(bhi[k], chi);
        }
    }
    for (int k = 0; k < 3; ++k)
        if (!(lo[k] >= blo[k] && hi[k] <= bhi[k]))
            return false;
    if (nl > 1) {
        if (!(smax <= SCAN_RATIO * smin))
            return false;
        double volume = 0, box = 1;
        for (uint32_t s = 0; s < nl; ++s) {
            const double r = c[s]->size / smin;
            volume += r * r * r;
        }
        for (int k = 0; k < 3; ++k) {
            const double r = (bhi[k] - blo[k]) / smin;
            if (!(r <= SCAN_RATIO))
                return false;
            box *= r;
        }
        if (volume != box)
            return false;
    }
    const noct_proxy *o = noct_bp_proxy(&w->bp, i);
    for (uint32_t s = 0; s < nl; ++s)
        for (uint32_t n = 0; n < c[s]->count; ++n) {
            const uint32_t j = c[s]->objs[n];
            if (j <= i)
                continue;
            const noct_aabb *b = noct_bp_box(&w->bp, j);
            if ((b->hi[0] < lo[0]) | (b->lo[0] > hi[0]) | (b->hi[1] < lo[1]) |
                (b->lo[1] > hi[1]) | (b->hi[2] < lo[2]) | (b->lo[2] > hi[2]))
                continue;
            const noct_proxy *q = noct_bp_proxy(&w->bp, j);
            if (!((q->category & o->mask) != 0 && (o->category & q->mask) != 0))
                continue;
            bool earlier = false; /* taken in an earlier leaf */
            for (uint32_t t = 0; t < s && !earlier; ++t)
                earlier = noct_overlaps(b, c[t]);
            if (!earlier && !take(p, (noctProxyId){j, 0}, NULL))
                return true; /* (p->failed) */
        }
    return true;
}

/* ---- the near pairs by leaves --------------------------------------------------- */

/*
 * Rather than look for each object's partners in its own grown box (a
 * query or a scan of its leaves per object, every box of those leaves
 * read again for each of their objects), every leaf sweeps once the boxes
 * that may have a near pair it owns, and hands each candidate pair over
 * once. A pair (i, j), i < j, is a candidate exactly when j's box meets
 * i's grown as the per-object search below grows it (the same rounded box, the
 * same closed test, the same filters), so the pairs tested, and the near
 * pairs, are those of the scan or query, bit for bit.
 *
 * Ownership: the candidate pair's point P = max(lo_i, lo_j) per axis (the
 * lower corner of the overlap of the grown boxes, taken at the boxes'
 * own corners, so exact) lies in the root when every box does, and one
 * leaf owns it ([lo, lo + size), closed at the root's upper faces, as the
 * pair search's rule). On each axis the box with the larger lo meets the
 * leaf's cell; the other reaches within its grow of P (the candidate
 * test, up to its roundings): so both meet the leaf's cell extended
 * downwards by the largest grow G, with room for those roundings (the
 * gather box [qlo, lo + size]). The leaf gathers the boxes that meet that
 * box (from the leaves that overlap it below its upper faces: an object
 * meeting it meets one of them), sorts them on one axis and sweeps them
 * with G and the same room as reach; the sweep passes over only pairs
 * whose larger lo is beyond the other's hi by more than the reach on some
 * axis, which are no candidates. Empty leaves own pairs too (P need not be in either
 * box), so every leaf sweeps.
 */
typedef struct near_box {
    double lo[3], hi[3];
    double grow; /* the per-object search's grow for this object */
    uint32_t id;
} near_box;

/* A gathered box's place in the sweep: its lower corner on the sweep's
 * axis and its index among the gathered. The leaves gather dozens of
 * boxes in no useful order (the lists of several leaves, each sorted on
 * its own axis if at all), so these 16 bytes are sorted, by insertion in
 * runs of KEY_RUN and by merging the runs, rather than the 64 of a box. */
typedef struct near_key {
    double lo;
    size_t at;
} near_key;

/* A gathered box as the sweep reads it, its records side by side in the
 * sweep's order (the pairs that meet on the sweep's axis, most of which
 * the other two axes turn away, are tested without reaching the boxes):
 * the box's lower corner on the sweep's axis, its lower and upper ones on
 * the next and on the last (copies: the same numbers, the same tests),
 * and its index among the gathered. */
typedef struct near_run {
    double b[5];
    size_t at;
} near_run;

typedef struct near_sweep {
    noctWorld *w;
    const double *m; /* objects' own margins, or NULL */
    double W, M;     /* world's margin, largest own margin */
    double G;        /* every object's grow at most, with room */
    double R;        /* the sweep's reach: G and the roundings' room */
    double *grow;    /* each object's grow (not sensors'), by slot */
    const noct_cell *root;
    /* the scratch (taken from the world's for the step): x.g the
     * gathered boxes; x.key their order on the sweep's axis, and as many
     * for the sort; x.run the sweep's records, in its order; x.cand the
     * candidate pairs, (i, j) with i < j (i's generation: whether their
     * boxes overlap); x.spare room for sorting them; x.idx counts and
     * cells */
    noct_near_scratch x;
    size_t ng;       /* boxes gathered into x.g */
    uint32_t epoch;
    double qlo[3], qhi[3]; /* the gather box */
    double clo[3];         /* the sweeping leaf's lower corner */
    size_t gathered;      /* boxes gathered in all (the budget below) */
    size_t budget;
    bool over;            /* the budget is spent: the old way is cheaper */
    bool filtered;        /* some object has a filter (else all pass) */
    double skin;          /* added to each grow for a kept list (else 0) */
    bool keep;            /* making the kept list: every pair whose boxes
                             meet grown by grow and skin, none turned away
                             by near()'s box test or the filters */
} near_sweep;

NOCT_DEFINE_GROW(grow_near_box, near_box)

/* The per-object search's grow of object i with box b. */
static NOCT_ALWAYS_INLINE double grow_of(const near_sweep *s, uint32_t i, const noct_aabb *b)
{
    const double reach = s->m != NULL ? (s->W + s->m[i]) + s->M : s->W;
    double scale = reach;
    for (int k = 0; k < 3; ++k)
        scale = noct_max(scale, noct_max(fabs(b->lo[k]), fabs(b->hi[k])));
    return reach + 0x1p-38 * scale;
}

/* Gather, from the leaves under n, the boxes (not sensors) that meet the
 * gather box, once each (marks). A node is visited when its cell meets the
 * gather box below its upper faces: a box meeting the gather box meets it
 * at a lowest point y, which lies in a leaf whose cell is closed at y and
 * starts below the gather box's upper faces (y less any tiny step
 * downwards on the axes where y is on them), and that leaf lists the box. */
static bool gather_node(near_sweep *s, const octNode *n)
{
    const noct_cell *c = noct_cell_of(n);
    for (int k = 0; k < 3; ++k)
        if (!(c->lo[k] < s->qhi[k] && c->lo[k] + c->size >= s->qlo[k]))
            return true;
    if (NOCT_NODE_IS_SPLIT(n)) {
        for (int i = 0; i < 8; ++i)
            if (!gather_node(s, NOCT_NODE_CHILD(n, (octDirection)(OCT_LDB + i))))
                return false;
        return true;
    }
    noctWorld *w = s->w;
    uint32_t *mark = noct_bp_marks(&w->bp);
    if (!grow_near_box(&s->x.g, &s->x.capg, s->ng + c->count))
        return false;
    /* A leaf below the sweeping one on an axis (its cell ends where that
     * one's starts, or lower) holds mostly boxes that end below the
     * gather box on that axis: that comparison first. */
    int below = -1;
    for (int k = 0; k < 3; ++k)
        if (c->lo[k] + c->size <= s->clo[k])
            below = k;
    for (uint32_t t = 0; t < c->count; ++t) {
        const uint32_t id = c->objs[t];
        const noct_aabb *b = noct_bp_box(&w->bp, id);
        if (below >= 0 && b->hi[below] < s->qlo[below])
            continue;
        if ((b->hi[0] < s->qlo[0]) | (b->hi[1] < s->qlo[1]) | (b->hi[2] < s->qlo[2]) |
            (b->lo[0] > s->qhi[0]) | (b->lo[1] > s->qhi[1]) | (b->lo[2] > s->qhi[2]))
            continue;
        /* (a box in several of the leaves, taken in the first) */
        if (mark[id] == s->epoch)
            continue;
        mark[id] = s->epoch;
        if (w->obj[id].sensor)
            continue;
        near_box *e = &s->x.g[s->ng++];
        memcpy(e->lo, b->lo, sizeof e->lo);
        memcpy(e->hi, b->hi, sizeof e->hi);
        e->grow = s->grow[id] + s->skin; /* (exact for a skin of 0) */
        e->id = id;
    }
    return true;
}

NOCT_DEFINE_BOX_AXIS(near_boxes, near_box, size_t)

#define KEY_RUN 8

static void sort_keys(near_key *k, size_t n, near_key *tmp)
{
    for (size_t r = 0; r < n; r += KEY_RUN) {
        const size_t end = r + KEY_RUN < n ? r + KEY_RUN : n;
        for (size_t i = r + 1; i < end; ++i) {
            const near_key t = k[i];
            size_t j = i;
            for (; j > r && k[j - 1].lo > t.lo; --j)
                k[j] = k[j - 1];
            k[j] = t;
        }
    }
    near_key *src = k, *dst = tmp;
    for (size_t width = KEY_RUN; width < n; width *= 2) {
        for (size_t lo = 0; lo < n; lo += 2 * width) {
            const size_t mid = lo + width < n ? lo + width : n;
            const size_t hi = lo + 2 * width < n ? lo + 2 * width : n;
            size_t i = lo, j = mid, o = lo;
            while (i < mid && j < hi)
                dst[o++] = src[j].lo < src[i].lo ? src[j++] : src[i++];
            while (i < mid)
                dst[o++] = src[i++];
            while (j < hi)
                dst[o++] = src[j++];
        }
        near_key *t = src;
        src = dst;
        dst = t;
    }
    if (src != k)
        memcpy(k, src, n * sizeof *k);
}

NOCT_DEFINE_GROW(grow_near_key, near_key)
NOCT_DEFINE_GROW(grow_near_run, near_run)
NOCT_DEFINE_GROW(grow_idx, size_t)
NOCT_DEFINE_GROW(grow_pair, noctPair)

/* Leaf c's candidate pairs, into s->x.cand. */
static bool sweep_leaf(near_sweep *s, const noct_cell *c)
{
    noctWorld *w = s->w;
    for (int k = 0; k < 3; ++k) {
        /* down by G and more than the roundings (see above) */
        s->qlo[k] = (c->lo[k] - s->G) - 0x1p-48 * fabs(c->lo[k]);
        s->qhi[k] = c->lo[k] + c->size;
        s->clo[k] = c->lo[k];
    }
    s->ng = 0;
    s->epoch = noct_bp_new_epoch(&w->bp);
    if (!gather_node(s, noct_bp_root(&w->bp)))
        return false;
    const size_t n = s->ng;
    s->gathered += n;
    if (s->gathered > s->budget) {
        s->over = true;
        return true;
    }
    if (n < 2)
        return true;
    const near_box *g = s->x.g;
    const int ax = near_boxes_axis(g, n);
    if (!grow_near_key(&s->x.key, &s->x.capkey, 2 * n) ||
        !grow_near_run(&s->x.run, &s->x.caprun, n))
        return false;
    near_key *key = s->x.key;
    for (size_t a = 0; a < n; ++a)
        key[a] = (near_key){g[a].lo[ax], a};
    sort_keys(key, n, key + n);
    const int k1 = (ax + 1) % 3, k2 = (ax + 2) % 3;
    /* the sweep's records in its order (see near_run); those below the
     * leaf's cell on the sweep's axis come first, up to `in`. Two boxes
     * below it on an axis have their point P = max(lo_i, lo_j) below the
     * cell there, so the leaf owns no pair of them (noct_cell_owns()):
     * a box before `in` is swept against the boxes from `in` on only,
     * which changes no candidate. */
    near_run *run = s->x.run;
    size_t in = n;
    for (size_t a = 0; a < n; ++a) {
        const near_box *B = &g[key[a].at];
        run[a] = (near_run){{B->lo[ax], B->lo[k1], B->hi[k1], B->lo[k2], B->hi[k2]},
                            key[a].at};
        if (in == n && !(B->lo[ax] < c->lo[ax]))
            in = a;
    }
    const double R = s->R;
    for (size_t a = 0; a < n; ++a) {
        const near_box *A = &g[run[a].at];
        /* A's box grown by the reach: G and more than the candidate
         * test's roundings, whichever object grows (a box beyond it on
         * an axis is no candidate); R = G + 2^-48 S, for S bounding
         * every coordinate, is at least G + 2^-48 |x| for each, and so
         * (rounding being monotone) up and dn at least as far out as
         * with that */
        const double limit = A->hi[ax] + R;
        const double up1 = A->hi[k1] + R, dn1 = A->lo[k1] - R;
        const double up2 = A->hi[k2] + R, dn2 = A->lo[k2] - R;
        for (size_t bi = a < in ? in : a + 1; bi < n; ++bi) {
            const near_run *r = &run[bi];
            if (r->b[0] > limit)
                break;
            if ((r->b[1] > up1) | (r->b[2] < dn1) | (r->b[3] > up2) |
                (r->b[4] < dn2))
                continue;
            const near_box *B = &g[r->at];
            const near_box *I = A->id < B->id ? A : B, *J = A->id < B->id ? B : A;
            const double gr = I->grow;
            if ((J->hi[0] < I->lo[0] - gr) | (J->lo[0] > I->hi[0] + gr) |
                (J->hi[1] < I->lo[1] - gr) | (J->lo[1] > I->hi[1] + gr) |
                (J->hi[2] < I->lo[2] - gr) | (J->lo[2] > I->hi[2] + gr))
                continue;
            const double P[3] = {noct_max(A->lo[0], B->lo[0]), noct_max(A->lo[1], B->lo[1]),
                                 noct_max(A->lo[2], B->lo[2])};
            if (!noct_cell_owns(c, s->root, P))
                continue;
            if (s->keep) {
                if (!noct_pairs_push(&s->x.cand, (noctPair){{I->id, 0}, {J->id, 0}}))
                    return false;
                continue;
            }
            /* near()'s test on the boxes, here where they are at hand
             * (the same numbers: copies) */
            const double d = s->m != NULL ? s->W + (s->m[I->id] + s->m[J->id]) : s->W;
            if (!boxes_near(w, I->lo, I->hi, J->lo, J->hi, d))
                continue;
            if (s->filtered &&
                !noct_filters_pass(noct_bp_proxy(&w->bp, I->id), noct_bp_proxy(&w->bp, J->id)))
                continue;
            /* (the first generation: whether the boxes overlap) */
            const bool overlap = boxes_overlap(I->lo, I->hi, J->lo, J->hi);
            if (!noct_pairs_push(&s->x.cand, (noctPair){{I->id, overlap}, {J->id, 0}}))
                return false;
        }
    }
    return true;
}

static bool sweep_node(near_sweep *s, const octNode *n)
{
    if (NOCT_NODE_IS_SPLIT(n)) {
        for (int i = 0; i < 8 && !s->over; ++i)
            if (!sweep_node(s, NOCT_NODE_CHILD(n, (octDirection)(OCT_LDB + i))))
                return false;
        return true;
    }
    return sweep_leaf(s, noct_cell_of(n));
}

static bool sort_cand(near_sweep *s, uint32_t slots);

/* The leaves' sweeps over every box, their pairs sorted by first object
 * (counting), then by second, in s->x.cand: 1; 0 when the gathering would
 * cost more than the objects' own scans; -1 without memory. */
static int sweep_all(near_sweep *s, uint32_t slots)
{
    noctWorld *w = s->w;
    s->x.cand.n = 0;
    s->gathered = 0;
    s->over = false;
    if (!sweep_node(s, noct_bp_root(&w->bp)))
        return -1;
    if (s->over)
        return 0;
    return sort_cand(s, slots) ? 1 : -1;
}

/* s->x.cand's pairs sorted by first object (counting), then by second:
 * false without memory. */
static bool sort_cand(near_sweep *s, uint32_t slots)
{
    noct_pair_list *l = &s->x.cand, *o = &s->x.spare;
    if (l->n > 1) {
        if (!grow_idx(&s->x.idx, &s->x.capidx, (size_t)slots + 1) ||
            !grow_pair(&o->p, &o->cap, l->n))
            return false;
        size_t *count = s->x.idx;
        memset(count, 0, ((size_t)slots + 1) * sizeof *count);
        for (size_t k = 0; k < l->n; ++k)
            ++count[l->p[k].a.index + 1];
        for (uint32_t i = 0; i < slots; ++i)
            count[i + 1] += count[i];
        for (size_t k = 0; k < l->n; ++k)
            o->p[count[l->p[k].a.index]++] = l->p[k];
        /* (the two arrays trade places: the sorted one is the list) */
        const noct_pair_list t = *l;
        *l = (noct_pair_list){o->p, t.n, o->cap};
        *o = (noct_pair_list){t.p, 0, t.cap};
        noct_pairs_sort_partners(l);
    }
    return true;
}

/*
 * The kept list's pairs without the leaves: every live box that is no
 * sensor is copied once into a column of a grid over the last two axes
 * (squares of side c), the column of its lower corner, each column in the
 * order of the boxes' lower corners on the first axis (one sort of them
 * all); each column is swept against itself and against the four
 * neighbours after it, the boxes of two columns merged in that order, and
 * each pair so met is tested once with the sweeps' test (the boxes meeting
 * with i's grown by its grow g_i' = fl(g_i + skin), i < j). So the list
 * holds exactly the pairs that pass that test, the set the argument above
 * near_candidates() speaks of (and the leaves' sweeps would hand over).
 * None of them is missed: on the first axis, the sweep passes over only
 * pairs whose larger lo is beyond the other's fl(hi + R), no candidates
 * (R covering the test's roundings, whichever object grows, as in
 * sweep_leaf()); on the other two, a pair that passes has J.lo <=
 * fl(I.hi + g') and J.hi >= fl(I.lo - g'), so |I.lo - J.lo| <= E + G' +
 * u (S + G') for E every box's extent on those axes, G' (s->G) every g', S every
 * coordinate and u = 2^-53; c is made at least (E + G' + 2^-40 (S + G'))
 * (1 + 2^-20) (E the largest fl(hi - lo), each rounding of c's own
 * within the room), and a column index is floor(fl(fl(lo - o) *
 * fl(1 / c))) for o the lowest lo (lo - o exact up to u and at most 2^10
 * c: c is at least 2^-10 of the span), within 4u 2^10 < 2^-40 of
 * (lo - o) / c; two lower corners within c / (1 + 2^-20) thus have
 * indices at most 1 / (1 + 2^-20) + 2^-39 < 1 apart before the floor, at
 * most 1 after (clamping to the last column keeps that). 1; 0 when it
 * would test more than a budget of pairs (a few large boxes make the
 * columns wide: the leaves' sweeps then); -1 without memory.
 */
static int columns_all(near_sweep *s, uint32_t slots, double S)
{
    noctWorld *w = s->w;
    const noctBroadphase *bp = &w->bp;
    s->x.cand.n = 0;
    size_t n = 0;
    double o[3] = {INFINITY, INFINITY, INFINITY}, top[3] = {-INFINITY, -INFINITY, -INFINITY};
    double E = 0;
    for (uint32_t i = 0; i < slots; ++i) {
        if (!w->obj[i].alive || w->obj[i].sensor)
            continue;
        const noct_aabb *b = noct_bp_box(bp, i);
        ++n;
        for (int k = 0; k < 3; ++k) {
            o[k] = noct_min(o[k], b->lo[k]);
            top[k] = noct_max(top[k], b->lo[k]);
        }
        E = noct_max(E, noct_max(b->hi[1] - b->lo[1], b->hi[2] - b->lo[2]));
    }
    if (n < 2)
        return 1;
    const double span = noct_max(top[1] - o[1], top[2] - o[2]);
    double c = noct_max((E + s->G + 0x1p-40 * (S + s->G)) * (1 + 0x1p-20), 0x1p-10 * span);
    if (!(c > 0) || !isfinite(c) || !isfinite(span))
        return 0;
    /* no more columns than boxes (wider ones: sound) */
    size_t nc[3], cols;
    double inv;
    for (;;) {
        inv = 1 / c;
        nc[1] = (size_t)((top[1] - o[1]) * inv) + 1;
        nc[2] = (size_t)((top[2] - o[2]) * inv) + 1;
        cols = nc[1] * nc[2];
        if (cols <= n + 64)
            break;
        c *= 1.25;
    }
    /* each column cut into slabs on the first axis, about four boxes to
     * a column's slab, so that the boxes come nearly in order there (an
     * order that the insertion sort of each column then makes exact,
     * whatever the slabs' roundings) */
    const double span0 = top[0] - o[0];
    const size_t slabs = n / (4 * cols) + 1;
    const double inv0 = span0 > 0 ? (double)slabs / span0 : 0;
    const size_t cells = cols * slabs;
    /* (the arrays kept from list to list: see noct_near_scratch) */
    int r = -1;
    if (!grow_near_box(&s->x.g, &s->x.capg, 2 * n) ||
        !grow_idx(&s->x.idx, &s->x.capidx, n + (cells + 1) + (cols + 1)) ||
        !grow_near_key(&s->x.key, &s->x.capkey, 2 * n))
        return -1;
    near_box *g = s->x.g;
    size_t *cell = s->x.idx, *start = cell + n, *cb = start + (cells + 1);
    memset(start, 0, (cells + 1) * sizeof *start);
    size_t a = 0;
    for (uint32_t i = 0; i < slots; ++i) {
        if (!w->obj[i].alive || w->obj[i].sensor)
            continue;
        const noct_aabb *b = noct_bp_box(bp, i);
        near_box *e = &g[a];
        memcpy(e->lo, b->lo, sizeof e->lo);
        memcpy(e->hi, b->hi, sizeof e->hi);
        e->grow = s->grow[i] + s->skin;
        e->id = i;
        size_t x[3];
        x[0] = (size_t)((b->lo[0] - o[0]) * inv0);
        for (int k = 1; k < 3; ++k)
            x[k] = (size_t)((b->lo[k] - o[k]) * inv);
        if (x[0] >= slabs)
            x[0] = slabs - 1;
        for (int k = 1; k < 3; ++k)
            if (x[k] >= nc[k])
                x[k] = nc[k] - 1;
        cell[a] = (x[2] * nc[1] + x[1]) * slabs + x[0];
        ++start[cell[a] + 1];
        ++a;
    }
    for (size_t q = 0; q < cells; ++q)
        start[q + 1] += start[q];
    for (size_t q = 0; q < cols + 1; ++q)
        cb[q] = start[q * slabs];
    near_key *key = s->x.key;
    for (size_t q = 0; q < n; ++q)
        key[start[cell[q]]++] = (near_key){g[q].lo[0], q};
    for (size_t q = 0; q < cols; ++q) {
        /* (a column the slabs leave far from its order, by a few boxes
         * far from the others on the first axis: merge-sorted instead) */
        const size_t m = cb[q + 1] - cb[q];
        size_t moves = 0;
        for (size_t i = cb[q] + 1; i < cb[q + 1] && moves <= 8 * m; ++i) {
            const near_key t = key[i];
            size_t j = i;
            for (; j > cb[q] && key[j - 1].lo > t.lo; --j)
                key[j] = key[j - 1];
            key[j] = t;
            moves += i - j;
        }
        if (moves > 8 * m)
            sort_keys(key + cb[q], m, key + n);
    }
    near_box *h = g + n;
    for (size_t q = 0; q < n; ++q)
        h[q] = g[key[q].at];
    /* (column q is [cb[q], cb[q + 1]) of h) the sweep's records beside
     * the boxes (see near_run) */
    if (!grow_near_run(&s->x.run, &s->x.caprun, n))
        goto out;
    near_run *run = s->x.run;
    for (size_t q = 0; q < n; ++q)
        run[q] = (near_run){{h[q].lo[0], h[q].lo[1], h[q].hi[1], h[q].lo[2], h[q].hi[2]}, q};
    const double R = s->R;
    const size_t budget = 64 * n + 4096;
    size_t tests = 0;
    /* box A against the boxes from `from` on in [from, to) whose lower
     * corners on the first axis are within its upper one and R (the
     * other two axes, the same reach, first on the records: as in
     * sweep_leaf()); the index after the last, in `stop` */
#define NEAR_SCAN(A, from, to, stop)                                                      \
    do {                                                                                  \
        const near_box *I0 = &h[A];                                                       \
        const double limit = I0->hi[0] + R;                                               \
        const double up1 = I0->hi[1] + R, dn1 = I0->lo[1] - R;                            \
        const double up2 = I0->hi[2] + R, dn2 = I0->lo[2] - R;                            \
        size_t t = (from);                                                                \
        for (; t < (to); ++t) {                                                           \
            const near_run *rr = &run[t];                                                 \
            if (rr->b[0] > limit)                                                         \
                break;                                                                    \
            if ((rr->b[1] > up1) | (rr->b[2] < dn1) | (rr->b[3] > up2) |                  \
                (rr->b[4] < dn2))                                                         \
                continue;                                                                 \
            const near_box *B0 = &h[t];                                                   \
            const near_box *I = I0->id < B0->id ? I0 : B0;                                \
            const near_box *J = I0->id < B0->id ? B0 : I0;                                \
            const double gr = I->grow;                                                    \
            if ((J->hi[0] < I->lo[0] - gr) | (J->lo[0] > I->hi[0] + gr) |                 \
                (J->hi[1] < I->lo[1] - gr) | (J->lo[1] > I->hi[1] + gr) |                 \
                (J->hi[2] < I->lo[2] - gr) | (J->lo[2] > I->hi[2] + gr))                  \
                continue;                                                                 \
            if (!noct_pairs_push(&s->x.cand, (noctPair){{I->id, 0}, {J->id, 0}}))         \
                goto out;                                                                 \
        }                                                                                 \
        stop = t;                                                                         \
    } while (0)
    for (size_t z = 0; z < nc[2]; ++z)
        for (size_t y = 0; y < nc[1]; ++y) {
            const size_t at = z * nc[1] + y;
            const size_t p0 = cb[at], p1 = cb[at + 1];
            /* (the budget looked at after each box's scan: no column
             * of boxes all alike on the first axis sweeps on long) */
            for (size_t p = p0; p < p1 && tests <= budget; ++p) {
                size_t stop;
                NEAR_SCAN(p, p + 1, p1, stop);
                tests += stop - p;
            }
            for (int d = 1; d < 5; ++d) {
                /* the neighbours after it: (+1, 0), (-1, +1), (0, +1), (+1, +1) */
                const int e = 4 + d;
                const size_t Y = y + (size_t)(e % 3) - 1, Z = z + (size_t)(e / 3) - 1;
                if (!(Y < nc[1] && Z < nc[2]))
                    continue;
                const size_t nb = Z * nc[1] + Y;
                const size_t q0 = cb[nb], q1 = cb[nb + 1];
                /* the two columns merged: each box against the other's
                 * from the first not before it */
                size_t i = p0, j = q0;
                while (i < p1 && j < q1 && tests <= budget) {
                    size_t stop;
                    if (!(run[j].b[0] < run[i].b[0])) {
                        NEAR_SCAN(i, j, q1, stop);
                        tests += stop - j + 1;
                        ++i;
                    } else {
                        NEAR_SCAN(j, i, p1, stop);
                        tests += stop - i + 1;
                        ++j;
                    }
                }
            }
            if (tests > budget) {
                r = 0;
                goto out;
            }
        }
#undef NEAR_SCAN
    r = 1;
out:
    return r;
}

/* The boxes now, into k->ref: false without memory. */
static bool keep_ref(const noctWorld *w, noct_near_kept *k, uint32_t slots)
{
    if (k->capref < slots) {
        void *r = realloc(k->ref, (size_t)slots * sizeof *k->ref);
        if (r == NULL)
            return false;
        k->ref = r;
        k->capref = slots;
    }
    if (slots > 0)
        memcpy(k->ref, noct_bp_box(&w->bp, 0), (size_t)slots * sizeof *k->ref);
    return true;
}

/* The kept list made from the sweeps' pairs in s->x.cand (which it takes,
 * leaving s->x.cand empty) and the boxes now: false without memory. */
static bool keep_list(near_sweep *s, noct_near_kept *k, uint32_t slots)
{
    if (k->cap > 4 * s->x.cand.n + 4096) { /* (left by a step of far more pairs) */
        free(k->p);
        k->p = NULL;
        k->cap = 0;
    }
    if (k->cap < s->x.cand.n) {
        void *p = realloc(k->p, s->x.cand.n * sizeof *k->p);
        if (p == NULL)
            return false;
        k->p = p;
        k->cap = s->x.cand.n;
    }
    if (!keep_ref(s->w, k, slots))
        return false;
    for (size_t q = 0; q < s->x.cand.n; ++q) {
        k->p[q][0] = s->x.cand.p[q].a.index;
        k->p[q][1] = s->x.cand.p[q].b.index;
    }
    k->n = s->x.cand.n;
    s->x.cand.n = 0;
    return true;
}

/* This step's candidates, from the kept list's pairs, into s->x.cand: the
 * sweeps' own tests (the pair's boxes meeting with i's grown by its grow
 * now, near()'s test on the boxes, the filters), so the same pairs as the
 * sweeps would hand over, in their order (the list's, sorted). false
 * without memory. */
static bool kept_candidates(near_sweep *s, const noct_near_kept *k)
{
    noctWorld *w = s->w;
    const noctBroadphase *bp = &w->bp;
    noct_pair_list *c = &s->x.cand;
    c->n = 0;
    /* room for every pair of the list, made once: the candidates are
     * among them */
    if (c->cap < k->n) {
        void *p = realloc(c->p, k->n * sizeof *c->p);
        if (p == NULL)
            return false;
        c->p = p;
        c->cap = k->n;
    }
    const bool box = w->def.accuracy == NOCT_ACCURACY_BOX;
    size_t n = 0;
    for (size_t q = 0; q < k->n; ++q) {
        /* (the second objects' boxes are scattered: requested ahead) */
        if (q + 8 < k->n) {
            const char *ahead = (const char *)noct_bp_box(bp, k->p[q + 8][1]);
            NOCT_PREFETCH(ahead);
            NOCT_PREFETCH(ahead + sizeof(noct_aabb) - 1);
        }
        const uint32_t i = k->p[q][0], j = k->p[q][1];
        const noct_aabb *I = noct_bp_box(bp, i), *J = noct_bp_box(bp, j);
        const double gr = s->grow[i];
        const bool meet = !((J->hi[0] < I->lo[0] - gr) | (J->lo[0] > I->hi[0] + gr) |
                            (J->hi[1] < I->lo[1] - gr) | (J->lo[1] > I->hi[1] + gr) |
                            (J->hi[2] < I->lo[2] - gr) | (J->lo[2] > I->hi[2] + gr));
        const double d = s->m != NULL ? s->W + (s->m[i] + s->m[j]) : s->W;
        bool pass = meet && boxes_near_as(box, I->lo, I->hi, J->lo, J->hi, d);
        if (s->filtered && pass)
            pass = noct_filters_pass(noct_bp_proxy(bp, i), noct_bp_proxy(bp, j));
        const bool overlap = boxes_overlap(I->lo, I->hi, J->lo, J->hi);
        if (pass)
            c->p[n++] = (noctPair){{i, overlap}, {j, 0}};
    }
    c->n = n;
    return true;
}

/*
 * The kept list's skin. A list is made to last KEEP_STEPS steps at the
 * motion a step the last one saw (a box that moves by r a step needs a
 * skin of 2 r a step: both boxes of a pair may move towards each other),
 * with the skin at most SKIN_GROWS times the largest grow (the list's
 * pairs grow about as the cube of the boxes' size and the reach, and so
 * does the sweep that makes it); least when nothing moved. 0: no list,
 * as one would last less than two steps (objects too fast for the
 * margin): the sweeps alone find the pairs for FAST_STEPS steps, and the
 * boxes of the last of them are kept to measure the motion again, so
 * that a list comes back when it slows down. When the sweeps with the
 * skin would gather more than their budget, the step sweeps without it,
 * and so do the next HOLD_STEPS steps.
 */
#define KEEP_STEPS 4
#define SKIN_GROWS 2.0
#define HOLD_STEPS 64
#define FAST_STEPS 8

static double skin_for(double rate, double G, double least)
{
    /* (and half a step's more: the motion of a step varies a little) */
    const double want = (2 * KEEP_STEPS + 1) * rate, cap = SKIN_GROWS * G;
    if (!(want <= cap))
        return cap >= 4 * rate ? cap : 0;
    return noct_max(want, least);
}

/*
 * The candidate pairs of every object that is no sensor, sorted, into
 * s->x.cand, by the leaves' sweeps or a kept list (made by columns_all(),
 * or by the leaves' sweeps with the skin when the columns would test
 * too many pairs): 1; 0 when they cannot be had that way
 * (no exact tree, a box outside the root, or the gathering would cost
 * more than the objects' own scans: then nothing is made); -1 without
 * memory.
 *
 * The sweeps' pairs are kept from step to step (w->kept, as molecular
 * dynamics keeps Verlet lists): made with every grow larger by a skin,
 * they are the pairs (i, j) whose boxes met with i's grown by
 * g_i' = fl(g_i + skin). A later step's candidates are among them while
 * every box has moved by at most D on each coordinate since, with
 * (2 + 2^-30) D + 2^-40 (S + G + skin) <= skin (S bounding every
 * coordinate and G every grow, then and now; each object's margin, the
 * world's and the largest one the same, which edits, W and M tell):
 * a pair left out had, on some axis, say J.lo > fl(I.hi + g'), so with
 * u = 2^-53, J.lo > I.hi + g + skin - 2u (S + g + skin) (1 + u); since,
 * J.lo and I.hi moved by at most D each, and g, made from the same reach
 * and coordinates that moved by at most D (2^-38 of their largest),
 * by at most 2^-38 D + 2u G (1 + u); so now J.lo exceeds I.hi + g by
 * more than skin - 2 D (1 + 2^-38) - 5u (S + G + skin) and, by the
 * condition, more than u (S + g) (the rounding of fl(I.hi + g)), so
 * the sweeps' test turns the pair away; the same below, and D as
 * computed (each difference within an ulp of its exact value) and the
 * condition's own roundings are within the 2^-30 and 2^-40 to spare. The
 * pairs of the list then go through the sweeps' own tests
 * (kept_candidates()): the same candidates as the sweeps would find, bit
 * for bit. A step that cannot use the list makes another (the skin from
 * the motion the last one saw, skin_for()); without memory for it, the
 * step fails as without the list.
 */
static int near_candidates(near_sweep *s)
{
    noctWorld *w = s->w;
    noctBroadphase *bp = &w->bp;
    noct_near_kept *k = &w->kept;
    const uint32_t slots = noct_bp_slots(bp);
    /* the boxes of age steps ago are those of these objects (none came,
     * went or changed), and the list, if valid, theirs */
    const bool same = k->ref_ok && k->edits == w->margins.edits && k->slots == slots &&
                      k->W == s->W && k->M == s->M;
    const bool usable = same && k->valid;
    k->valid = false;
    k->ref_ok = false;
    if (noct_bp_root(bp) == NULL || noct_bp_tree_owed(bp))
        return 0;
    const noct_aabb root = noct_bp_root_box(bp);
    /* every object's grow, once (a box is gathered by several leaves),
     * and how far the boxes moved since the list was made */
    if (k->capgrow < (size_t)slots + 1) {
        free(k->grow);
        k->capgrow = 0;
        k->grow = malloc(((size_t)slots + 1) * sizeof *k->grow);
        if (k->grow == NULL)
            return -1;
        k->capgrow = (size_t)slots + 1;
    }
    s->grow = k->grow;
    double G = 0, D = 0, C = 0;
    size_t live = 0;
    for (uint32_t i = 0; i < slots; ++i) {
        if (!w->obj[i].alive || w->obj[i].sensor)
            continue;
        const noct_aabb *b = noct_bp_box(bp, i);
        if (!noct_box_within(b, &root))
            return 0;
        ++live;
        s->grow[i] = grow_of(s, i, b);
        G = noct_max(G, s->grow[i]);
        for (int a = 0; a < 3; ++a)
            C = noct_max(C, noct_max(fabs(b->lo[a]), fabs(b->hi[a])));
        if (same) {
            const noct_aabb *r = &k->ref[i];
            for (int a = 0; a < 3; ++a)
                D = noct_max(D, noct_max(fabs(b->lo[a] - r->lo[a]), fabs(b->hi[a] - r->hi[a])));
        }
    }
    if (!isfinite(G))
        return 0;
    double S = 0;
    for (int a = 0; a < 3; ++a)
        S = noct_max(S, noct_max(fabs(root.lo[a]), fabs(root.hi[a])));
    s->root = noct_cell_of(noct_bp_root(bp));
    s->budget = 16 * live + 4096;
    s->filtered = noct_bp_any_filter(bp);
    if (same) {
        ++k->age;
        /* (C, the boxes' largest coordinate, bounds those the tests
         * read: the root's, S, is 2^-40 at least, and may be far larger) */
        const double S2 = noct_max(C, k->S), G2 = noct_max(G, k->G);
        if (usable && (2 + 0x1p-30) * D + 0x1p-40 * ((S2 + G2) + k->skin) <= k->skin) {
            k->valid = k->ref_ok = true;
            return kept_candidates(s, k) ? 1 : -1;
        }
        /* (a NaN fails too, and makes no list) */
        k->rate = D / k->age;
    }
    /* a new list; the least skin 2^-38 (C + G), four times the
     * condition's 2^-40 when nothing moved and at most about G (every
     * grow is 2^-38 of its box's coordinates at least; from the root's S
     * and 2^-30, it was 2^10 grows at an offset of 2^40, every pair of
     * the world, and at a scale of 2^-300 some 2^-71, as the root is
     * 2^-40 wide at least) */
    uint32_t hold = k->hold > 0 ? k->hold - 1 : 0;
    const double skin = k->hold > 0 ? 0 : skin_for(k->rate, G, 0x1p-38 * (C + G));
    if (k->hold == 0 && skin == 0)
        hold = FAST_STEPS;
    s->skin = skin;
    s->keep = skin > 0;
    s->G = (G + skin) * (1 + 0x1p-30);
    s->R = s->G + 0x1p-48 * S;
    int r = !isfinite(s->R) ? 0 : s->keep ? columns_all(s, slots, S) : sweep_all(s, slots);
    if (r > 0 && s->keep && !sort_cand(s, slots))
        r = -1;
    if (r == 0 && s->keep)
        r = sweep_all(s, slots);
    if (r == 0 && s->keep) {
        /* more than the budget with the skin: the sweeps alone, as
         * without a list, for HOLD_STEPS steps */
        hold = HOLD_STEPS;
        s->skin = 0;
        s->keep = false;
        s->G = G * (1 + 0x1p-30);
        s->R = s->G + 0x1p-48 * S;
        r = isfinite(s->R) ? sweep_all(s, slots) : 0;
    }
    if (r <= 0) {
        /* (the steps still without a list count down, and a sweep with
         * the skin over its budget holds them off, even when the sweeps
         * alone cannot serve either: else each step would try the skin
         * again, two gatherings over their budget a step) */
        if (r == 0)
            k->hold = hold;
        return r;
    }
    *k = (noct_near_kept){.p = k->p, .n = k->n, .cap = k->cap, .ref = k->ref,
                          .capref = k->capref, .skin = s->skin, .S = C, .G = G, .W = s->W,
                          .M = s->M, .rate = k->rate, .edits = w->margins.edits,
                          .slots = slots, .hold = hold, .grow = k->grow,
                          .capgrow = k->capgrow, .x = k->x};
    if (!s->keep) {
        /* (the candidates are the sweeps'; the boxes kept, if there is
         * memory for them, to measure the motion over the next step when
         * that may make a list) */
        k->ref_ok = hold == 0 && keep_ref(w, k, slots);
        return 1;
    }
    if (!keep_list(s, k, slots))
        return -1;
    k->valid = k->ref_ok = true;
    return kept_candidates(s, k) ? 1 : -1;
}

/*
 * The step's pairs from its near candidates. Every pair whose boxes
 * overlap (closed, as the search's) is a candidate: the candidates are
 * every pair of objects that are no sensors whose boxes meet with i's
 * grown by a grow of at least 0 and pass near()'s test on the boxes (which
 * boxes that overlap pass: their gap is 0) and the filters (the search's
 * own); the candidates' first generation says whether their boxes
 * overlap, tested on the same boxes as the search would. So, in a world
 * without sensors, those candidates are the search's pairs, once each
 * (i < j, as it hands them), sorted by (i, j) where the search sorts them
 * by i alone: the narrowphase's colliding pairs are the same, and sorted
 * the same once each object's partners are. A world with a few sensors
 * (sensors_query()) adds their pairs by a query of each sensor's box
 * (sensor_pairs()). The leaves' sweeps of the
 * search are left out, not the tree's maintenance (the queries and the
 * steps that cannot make the candidates this way use the tree). The
 * exhaustive mode (N big) keeps its search: it is the report's
 * algorithm, to be measured.
 */
/* Sensors a world may have, at most one in SENSOR_SHARE of its objects,
 * for its step to take its pairs from the candidates: each sensor's pairs
 * come from a query of the tree with its box, which costs about what the
 * search's leaves would for it. */
#define SENSOR_SHARE 16

typedef struct sensed {
    const noctWorld *w;
    uint32_t s;
    noct_pair_list *found;
    bool failed;
} sensed;

/* A proxy whose box meets sensor t->s's: their pair, once (a pair of
 * sensors from its lower one), as the search hands it over (i < j). */
static bool take_sensed(void *context, noctProxyId id, void *user)
{
    (void)user;
    sensed *t = context;
    const uint32_t j = id.index, s = t->s;
    if (j == s || (t->w->obj[j].sensor && j < s))
        return true;
    const noctProxyPair pair = j < s ? (noctProxyPair){{j, 0}, {s, 0}}
                                     : (noctProxyPair){{s, 0}, {j, 0}};
    if (!noct_pairs_push(t->found, pair)) {
        t->failed = true;
        return false;
    }
    return true;
}

/* The sensors' pairs, which the candidates leave out, added to found and
 * the whole sorted by first object, as the search's: false without
 * memory. A query hands over every proxy whose box meets the sensor's
 * (closed boxes, as the search's) and whose filter passes with its
 * (the search's test: noct_filters_pass()). */
static bool sensor_pairs(noctWorld *w, noct_pair_list *found)
{
    sensed t = {w, 0, found, false};
    for (uint32_t s = 0; s < noct_bp_slots(&w->bp); ++s) {
        if (!w->obj[s].alive || !w->obj[s].sensor)
            continue;
        const noct_proxy *o = noct_bp_proxy(&w->bp, s);
        const noct_aabb *b = noct_bp_box(&w->bp, s);
        t.s = s;
        /* (the box is within the root: no status but OK) */
        (void)noctBroadphaseQueryBox(&w->bp, b->lo, b->hi,
                                     (noctQueryFilter){o->category, o->mask}, take_sensed, &t);
        if (t.failed)
            return false;
    }
    return noct_bp_sort_tested(&w->bp);
}

/* Are the sensors few enough, and their boxes within the root? */
static bool sensors_query(const noctWorld *w)
{
    if (w->nsensors == 0)
        return true;
    if (w->nsensors > noct_bp_live(&w->bp) / SENSOR_SHARE)
        return false;
    const noct_aabb root = noct_bp_root_box(&w->bp);
    for (uint32_t s = 0; s < noct_bp_slots(&w->bp); ++s)
        if (w->obj[s].alive && w->obj[s].sensor && !noct_box_within(noct_bp_box(&w->bp, s), &root))
            return false;
    return true;
}

int noct_world_near_pairs(noctWorld *w)
{
    noct_near_kept *kk = &w->kept;
    kk->early = 0;
    if (w->margins.stale)
        noct_world_refresh_margins(w);
    const double W = w->def.margin;
    const double *m = w->margins.count > 0 ? w->margins.of : NULL;
    if (!(W > 0 || m != NULL) || noct_bp_exhaustive(&w->bp) || noct_bp_root(&w->bp) == NULL ||
        !sensors_query(w))
        return 0;
    near_sweep s = {.w = w, .m = m, .W = W, .M = m != NULL ? w->margins.max : 0, .x = kk->x};
    s.x.cand.n = 0;
    kk->x = (noct_near_scratch){0};
    const int r = near_candidates(&s);
    kk->x = s.x;
    if (r < 0)
        return -1;
    kk->early = (uint8_t)(r + 1);
    if (r == 0)
        return 0;
    const noct_pair_list *c = &kk->x.cand;
    noct_pair_list *found = noct_bp_skip_search(&w->bp, kk->valid ? kk->n : c->n);
    for (size_t q = 0; q < c->n; ++q) {
        if (!c->p[q].a.generation)
            continue;
        if (!noct_pairs_push(found, (noctProxyPair){{c->p[q].a.index, 0},
                                                   {c->p[q].b.index, 0}}))
            return -1;
    }
    return w->nsensors == 0 || sensor_pairs(w, found) ? 1 : -1;
}

void noct_world_near_forget(noctWorld *w)
{
    w->kept.early = 0;
}

noctStatus noct_world_stage_near(noctWorld *w, noctError *err)
{
    noct_event_record *e = &w->events.near;
    const double W = w->def.margin;
    noct_record_rotate(e);
    /* The objects' own margins, if any: a pair's margin is W + (m_i + m_j),
     * and each object looks as far as W + m_i + M for M the largest. */
    if (w->margins.stale)
        noct_world_refresh_margins(w);
    const double *m = w->margins.count > 0 ? w->margins.of : NULL;
    const double M = m != NULL ? w->margins.max : 0;
    partners p = {0, NULL, 0, 0, false};
    noctStatus st = NOCT_OK;
    /* (no margin left: the pairs the last one kept end) */
    const bool any = W > 0 || m != NULL;
    /* (the kept scratch, which s holds until it goes back below) */
    noct_near_kept *kk = &w->kept;
    near_sweep s = {.w = w, .m = m, .W = W, .M = M, .x = kk->x};
    /* (the candidates, if made before the pair search, are kept) */
    const int early = kk->early;
    kk->early = 0;
    if (early != 2)
        s.x.cand.n = 0;
    kk->x = (noct_near_scratch){0};
    /* (an empty list may have no array: no pointer arithmetic on NULL) */
    const noct_near_hint *hint_end = w->hints.n > 0 ? w->hints.h + w->hints.n : w->hints.h;
    hint_walk hw = {w->hints.h, hint_end, w->hints.spare, 0, w->hints.capspare,
                    !any};
    noct_near_hint h;
    const int by_leaves = early > 0 ? early - 1 : any ? near_candidates(&s) : 0;
    if (by_leaves < 0)
        st = NOCT_ERR_NOMEM;
    /* the step's colliding pairs, sorted as the candidates are, walked
     * beside them */
    const noct_pair_list *col = &w->events.contact.now;
    const bool solids = w->def.accuracy != NOCT_ACCURACY_BOX;
    size_t at = 0;
    for (size_t k = 0; by_leaves > 0 && k < s.x.cand.n; ++k) {
        const uint32_t i = s.x.cand.p[k].a.index, j = s.x.cand.p[k].b.index;
        /* the box forms of the pairs a few ahead, scattered by the
         * second object, requested */
        if (solids && k + 8 < s.x.cand.n) {
            const uint32_t ahead = s.x.cand.p[k + 8].b.index;
            NOCT_PREFETCH((const char *)&w->slot[ahead]);
            NOCT_PREFETCH((const char *)&w->slot[ahead] + 64);
            NOCT_PREFETCH(w->pos[ahead]);
        }
        /* (and its generation, for the pair's record) */
        if (k + 8 < s.x.cand.n)
            NOCT_PREFETCH(&w->bp.gen[s.x.cand.p[k + 8].b.index]);
        while (at < col->n && (col->p[at].a.index < i ||
                               (col->p[at].a.index == i && col->p[at].b.index < j)))
            ++at;
        const bool colliding =
            at < col->n && col->p[at].a.index == i && col->p[at].b.index == j;
        const double d = m != NULL ? W + (m[i] + m[j]) : W;
        /* (the candidates passed near()'s test on the boxes) */
        if (w->ignored.n > 0 && noct_world_ignored(w, i, j))
            continue;
        if (!colliding && solids) {
            const bool is_near = near_solids(w, i, j, d, s.x.cand.p[k].a.generation != 0,
                                             hint_of(&hw, i, j), &h);
            hint_keep(&hw, i, j, &h);
            if (!is_near)
                continue;
        }
        const noctPair pair = {{i, noct_bp_generation(&w->bp, i)},
                               {j, noct_bp_generation(&w->bp, j)}};
        if (!noct_pairs_push(&e->now, pair)) {
            st = NOCT_ERR_NOMEM;
            break;
        }
    }
    /* (the scratch kept for the next step, each array unless far larger
     * than this step's candidates and list, or the objects, ask) */
    const size_t need = s.x.cand.n + kk->n + noct_bp_slots(&w->bp);
    if (s.x.cand.cap > 4 * need + 4096 || s.x.spare.cap > 4 * need + 4096 ||
        s.x.capg > 8 * need + 4096 || s.x.capkey > 8 * need + 4096 ||
        s.x.caprun > 8 * need + 4096 || s.x.capidx > 8 * need + 4096) {
        free(s.x.cand.p);
        free(s.x.spare.p);
        free(s.x.g);
        free(s.x.key);
        free(s.x.run);
        free(s.x.idx);
    } else {
        kk->x = s.x;
        kk->x.cand.n = kk->x.spare.n = 0;
    }
    /* else each object by a scan of its leaves or a query */
    const uint32_t slots = any && by_leaves == 0 ? noct_bp_slots(&w->bp) : 0;
    for (uint32_t i = 0; i < slots && st == NOCT_OK; ++i) {
        if (!w->obj[i].alive || w->obj[i].sensor)
            continue;
        const noct_proxy *o = noct_bp_proxy(&w->bp, i);
        const noct_aabb *b = noct_bp_box(&w->bp, i);
        const double mi = m != NULL ? m[i] : 0;
        const double reach = m != NULL ? (W + mi) + M : W;
        double lo[3], hi[3], scale = reach;
        for (int k = 0; k < 3; ++k)
            scale = noct_max(scale, noct_max(fabs(b->lo[k]), fabs(b->hi[k])));
        /* grown by the farthest pair margin and more than its rounding
         * (W + (mi + mj) <= (W + mi) + M within a few roundings of it) */
        const double grow = reach + 0x1p-38 * scale;
        for (int k = 0; k < 3; ++k) {
            lo[k] = b->lo[k] - grow;
            hi[k] = b->hi[k] + grow;
        }
        p.self = i;
        p.n = 0;
        if (!leaf_partners(w, i, lo, hi, &p))
            st = noctBroadphaseQueryBox(&w->bp, lo, hi,
                                        (noctQueryFilter){o->category, o->mask}, take, &p);
        if (st == NOCT_OK && p.failed)
            st = NOCT_ERR_NOMEM;
        if (st != NOCT_OK)
            break;
        if (p.n > 1)
            qsort(p.s, p.n, sizeof *p.s, by_index);
        for (size_t k = 0; k < p.n; ++k) {
            const uint32_t j = p.s[k];
            const double d = m != NULL ? W + (mi + m[j]) : W;
            if (w->obj[j].sensor || (w->ignored.n > 0 && noct_world_ignored(w, i, j)))
                continue;
            const bool is_near =
                near(w, i, j, d, listed(&w->events.contact.now, i, j), hint_of(&hw, i, j), &h);
            hint_keep(&hw, i, j, &h);
            if (!is_near)
                continue;
            const noctPair pair = {{i, noct_bp_generation(&w->bp, i)}, {j, noct_bp_generation(&w->bp, j)}};
            if (!noct_pairs_push(&e->now, pair)) {
                st = NOCT_ERR_NOMEM;
                break;
            }
        }
    }
    free(p.s);
    /* this step's hints for the next (none when it failed or could not
     * keep them all: a missing hint only costs a proof); the last step's
     * array is the next one's spare */
    noct_near_hints *kept = &w->hints;
    if (!any) {
        free(kept->h);
        free(hw.h);
        *kept = (noct_near_hints){NULL, NULL, 0, 0, 0};
        noct_world_free_kept(w);
    } else if (st == NOCT_OK && !hw.failed) {
        *kept = (noct_near_hints){hw.h, kept->h, hw.n, hw.cap, kept->cap};
    } else {
        kept->n = 0;
        kept->spare = hw.h;
        kept->capspare = hw.cap;
    }
    /* (a spare far larger than the pairs now, left by a step of many
     * more, goes: what the hints hold stays within a few times the
     * pairs of the last two steps) */
    if (kept->capspare > 4 * kept->n + 4096) {
        free(kept->spare);
        kept->spare = NULL;
        kept->capspare = 0;
    }
    /* near events are not among the counters' events */
    if (st == NOCT_OK && (w->def.effects & NOCT_EFFECT_EVENTS))
        st = noct_record_diff(e, NULL);
    if (st != NOCT_OK) {
        noct_record_unrotate(e); /* the failed step clears the events */
        return noct_fail(err, st, -1, 0, "near pairs: %s", noctStatusString(st));
    }
    w->margins.near = W > 0 || w->margins.count > 0 || e->now.n > 0;
    return NOCT_OK;
}

void noct_world_free_kept(noctWorld *w)
{
    free(w->kept.p);
    free(w->kept.ref);
    free(w->kept.grow);
    free(w->kept.x.cand.p);
    free(w->kept.x.spare.p);
    free(w->kept.x.g);
    free(w->kept.x.key);
    free(w->kept.x.run);
    free(w->kept.x.idx);
    w->kept = (noct_near_kept){0};
}
