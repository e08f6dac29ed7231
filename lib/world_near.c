/* SPDX-License-Identifier: MIT */
/*
 * The margin (noctWorldDef::margin): after a step's pairs, the pairs of
 * objects within the margin of each other ("near": the arm is about to
 * collide), and the pairs that became near or stopped being near. Each
 * object looks for its partners of higher index in the broadphase, its
 * box grown by the margin (in its leaves' lists when the grown box stays
 * in them, else by a query); a pair that collides is near, a pair of box
 * forms that a separating axis proves farther apart is not, a pair of box
 * forms with two points of its solids proved within the margin is, and
 * one proved beyond it on the axis through those points is not
 * (near_witness(): the answers noct_solids_within() would give), and
 * else the distance of their triangles decides (noct_solids_within()).
 * A pair's margin is the world's plus its objects' own (noct_margins).
 * A world without any margin never comes here (but once, to end the
 * pairs of the last margin that went).
 */
#include "config.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "narrowphase_internal.h"
#include "world_internal.h"

typedef struct partners {
    uint32_t self;
    uint32_t *s;
    size_t n, cap;
    bool failed;
} partners;

NOCT_DEFINE_GROW(grow_u32, uint32_t)

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
 * pair is near. 0: the last points' direction proves the solids farther
 * apart than noct_solids_within() answers true for (below). -1: the pair
 * needs the triangles (no dual, or neither proof after a few rounds:
 * within a hair of the margin, or skewed edges that alternating
 * projections approach slowly).
 */
#define WITNESS_ROUNDS 6

/* The coefficients of the point of shrunk box s (centre at C, factor f)
 * nearest x, if its edges are orthogonal, clamped to it; and the point. */
static NOCT_ALWAYS_INLINE void project_box(const noct_box_slot *s, const double C[3], double f,
                                           const double x[3], double p[3])
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
        for (int k = 0; k < 3; ++k)
            p[k] += l * e[k];
    }
}

static int near_witness(const noct_box_slot *a, const double ta[3], const noct_box_slot *b,
                        const double tb[3], double d)
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
    double p[3], q[3] = {CB[0], CB[1], CB[2]}, v[3] = {0, 0, 0};
    for (int round = 0; round < WITNESS_ROUNDS; ++round) {
        project_box(a, CA, fa, q, p);
        project_box(b, CB, fb, p, q);
        for (int k = 0; k < 3; ++k)
            v[k] = q[k] - p[k];
        if (sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) <= reach)
            return 1;
    }
    /* Not near, it seems: the points' direction is close to the one
     * along which the box forms are farthest apart. Their gap along it,
     * with noct_box_apart_by()'s allowances (each solid lies within dev
     * of its ideal box on every coordinate), bounds the distance from
     * below; beyond d and twice the slack of noct_solids_within() (2^-40
     * of the coordinates, which M bounds), that test answers false. */
    const double n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (!(n > 0 && isfinite(n)))
        return -1;
    const double u[3] = {v[0] / n, v[1] / n, v[2] / n};
    const double l1 = fabs(u[0]) + fabs(u[1]) + fabs(u[2]);
    const double dev = (double)a->dev + (double)b->dev;
    const double gap = fabs(u[0] * T[0] + u[1] * T[1] + u[2] * T[2]) - box_radius(a->e, u) -
                       box_radius(b->e, u) - l1 * dev - unit * l1;
    const double un = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    const double beyond = d + 2 * 0x1p-40 * noct_max(d, M);
    return gap > beyond * un * (1 + 0x1p-40) ? 0 : -1;
}

/* Are objects i and j near, at the world's level? */
static bool near(const noctWorld *w, uint32_t i, uint32_t j, double d)
{
    if (listed(&w->events.contact.now, i, j))
        return true;
    if (w->def.accuracy == NOCT_ACCURACY_BOX) {
        const noct_aabb *a = noct_bp_box(&w->bp, i), *b = noct_bp_box(&w->bp, j);
        double s = 0, scale = d;
        for (int k = 0; k < 3; ++k) {
            const double g = noct_max(noct_max(b->lo[k] - a->hi[k], a->lo[k] - b->hi[k]), 0);
            s += g * g;
            scale = noct_max(scale, noct_max(noct_max(fabs(a->lo[k]), fabs(a->hi[k])),
                                             noct_max(fabs(b->lo[k]), fabs(b->hi[k]))));
        }
        const double reach = d + 0x1p-40 * scale;
        return s <= reach * reach;
    }
    /* two boxes that a separating axis proves farther apart: the common
     * case, a few dozen operations */
    if (w->slot[i].has_box && w->slot[j].has_box &&
        noct_box_apart_by(&w->slot[i], w->pos[i], &w->slot[j], w->pos[j], d))
        return false;
    if (w->slot[i].has_box && w->slot[j].has_box) {
        const int r = near_witness(&w->slot[i], w->pos[i], &w->slot[j], w->pos[j], d);
        if (r >= 0)
            return r == 1;
    }
    noct_shape_view va, vb;
    const noctMesh *ma = noct_world_shape(w, i, &va), *mb = noct_world_shape(w, j, &vb);
    return noct_solids_within(ma, w->pos[i], mb, w->pos[j], d);
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
    const uint32_t slots = W > 0 || m != NULL ? noct_bp_slots(&w->bp) : 0;
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
            if (w->obj[j].sensor || (w->ignored.n > 0 && noct_world_ignored(w, i, j)) ||
                !near(w, i, j, d))
                continue;
            const noctPair pair = {{i, noct_bp_generation(&w->bp, i)}, {j, noct_bp_generation(&w->bp, j)}};
            if (!noct_pairs_push(&e->now, pair)) {
                st = NOCT_ERR_NOMEM;
                break;
            }
        }
    }
    free(p.s);
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
