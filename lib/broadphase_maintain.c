/* SPDX-License-Identifier: MIT */
/*
 * The N-objects octree's incremental maintenance (report section 2.4):
 * the fast test, the leave check and the enter check through neighbor
 * finding, the root's growth and shrinkage, and moves of single proxies.
 * The tree's own operations (split, merge, insert) are
 * broadphase_tree.c's.
 */
#include "config.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <noctree/mesh.h>
#include <noctree/neighbor.h>

#include "broadphase_internal.h"

NOCT_DEFINE_RESIZE(resize_nodes, octNode *)

/* ---- incremental maintenance ------------------------------------------------- */

/*
 * Maintenance (report 2.4) runs in two phases over the moving objects, so
 * that every split sees leaf lists that match the objects' new boxes.
 *
 * Phase A, per object: the fast test (a box strictly inside its only leaf,
 * or more generally inside its home block, needs nothing; maintain()
 * tries the block it has first, which reads no tree), then the leave
 * check: remove the object from the leaves its box no longer overlaps,
 * merging siblings that together hold N or fewer distinct objects.
 * Returns whether phase B is needed.
 */
/* The lattice point base + q s (s a power of two, q an integer), or NaN
 * when the sum is not exact (TwoSum's error is not zero). */
static NOCT_ALWAYS_INLINE double lattice_point(double base, double q, double s)
{
    if (!(fabs(q) < 0x1p52))
        return (double)NAN;
    double d = q * s, x = base + d, bb = x - base;
    return (base - (x - bb)) + (d - bb) == 0 ? x : (double)NAN;
}

/* The largest lattice point base + q s below x (up is false) or the
 * smallest above x (up is true), strictly; NaN if not exact. */
static NOCT_ALWAYS_INLINE double lattice_beyond(double base, double s, double x, bool up)
{
    /* floor((x - base) / s), without a call or a division: s is a power
     * of two, so its inverse is exact; a q of 2^52 or more is refused. */
    const double t = (x - base) * (1 / s);
    if (!(fabs(t) < 0x1p52))
        return (double)NAN;
    double q = (double)(int64_t)t;
    q = (q > t ? q - 1 : q) + (up ? 1 : 0);
    for (int i = 0; i < 4; ++i) {
        double g = lattice_point(base, q, s), n = lattice_point(base, up ? q - 1 : q + 1, s);
        if (isnan(g) || isnan(n))
            return (double)NAN;
        if (up ? g <= x : g >= x)
            q += up ? 1 : -1;
        else if (up ? n > x : n < x)
            q += up ? -1 : 1;
        else
            return g;
    }
    return (double)NAN;
}

/*
 * A bound on the positions p whose coordinate fl(m + p) of a placed box
 * compares with t as asked: since fl(m + p) does not decrease as p grows,
 * every p >= q has fl(m + p) > t (up, strict) or >= t (up), and every
 * p <= q has fl(m + p) < t (strict) or <= t. q starts at fl(t - m), a few
 * units in the last place of the largest of them from the boundary, and
 * steps away from it, doubling; NaN if a few steps do not do.
 */
static NOCT_ALWAYS_INLINE double position_bound(double m, double t, bool up, bool strict)
{
    double q = t - m;
    double d = noct_max(0x1p-51 * noct_max(noct_max(fabs(t), fabs(m)), fabs(q)), 0x1p-1074);
    for (int i = 0; i < 8; ++i) {
        const double f = m + q;
        if (up ? (strict ? f > t : f >= t) : (strict ? f < t : f <= t))
            return q;
        q = up ? q + d : q - d;
        d *= 2;
    }
    return (double)NAN;
}

/* The cell of proxy o's smallest leaf; NULL if it has none. */
static NOCT_ALWAYS_INLINE const noct_cell *smallest_leaf(const noct_proxy *o)
{
    if (o->nspans == 0)
        return NULL;
    const noct_cell *small = noct_cell_of(o->spans[0].leaf);
    for (uint32_t i = 1; i < o->nspans; ++i)
        if (noct_cell_of(o->spans[i].leaf)->size < small->size)
            small = noct_cell_of(o->spans[i].leaf);
    return small;
}

/* The lattice lines *lo and *hi around box b on axis k of the cells of
 * small's size; false for a block that reaches out of the root, as one
 * does when the box touches the root's face: then a box inside it could
 * be outside the root (maintain() relies on it). NaN fails too. */
static NOCT_ALWAYS_INLINE bool lattice_around(const noct_cell *small, const noct_aabb *root,
                                              const noct_aabb *b, int k, double *lo, double *hi)
{
    *lo = lattice_beyond(small->lo[k], small->size, b->lo[k], false);
    *hi = lattice_beyond(small->lo[k], small->size, b->hi[k], true);
    return *lo >= root->lo[k] && *hi <= root->hi[k];
}

/* The home block of object id while its leaves are those box b overlaps
 * (b: its box when they were last made so), as the positions that keep
 * its box in it. */
bool noct_bp_home_of(const noctBroadphase *bp, uint32_t id, const noct_aabb *b, noct_home *h)
{
    const noct_proxy *o = &bp->proxy[id];
    const noct_cell *small = smallest_leaf(o);
    if (small == NULL)
        return false;
    const double s = small->size;
    const noct_aabb root = noct_bp_root_box(bp);
    for (int k = 0; k < 3; ++k) {
        double lo, hi;
        if (!lattice_around(small, &root, b, k, &lo, &hi))
            return false;
        /* The box's low side in (lo, lo + s], its high side in
         * [hi - s, hi); the lattice points next to lo and hi are exact. */
        const double p[4] = {position_bound(o->mlo[k], lo, true, true),
                             position_bound(o->mlo[k], lo + s, false, false),
                             position_bound(o->mhi[k], hi, false, true),
                             position_bound(o->mhi[k], hi - s, true, false)};
        if (isnan(p[0]) || isnan(p[1]) || isnan(p[2]) || isnan(p[3]))
            return false;
        /* and within the positions allowed, so that the motion loop need
         * not check those that pass */
        h->lo[k] = noct_max(noct_max(p[0], p[3]), -NOCT_MAX_COORDINATE);
        h->hi[k] = noct_min(noct_min(p[1], p[2]), NOCT_MAX_COORDINATE);
    }
    return true;
}

/* The block of cells of proxy id's smallest leaf's size that box b, which
 * its leaves were made for, overlaps, in box space: blk->lo and blk->hi
 * are the lattice lines around b and *size the cells' size; false if
 * there is none (see noct_in_block). */
bool noct_bp_block_of(const noctBroadphase *bp, uint32_t id, const noct_aabb *b, noct_home *blk,
                      double *size)
{
    const noct_proxy *o = &bp->proxy[id];
    const noct_cell *small = smallest_leaf(o);
    if (small == NULL)
        return false;
    const double s = small->size;
    const noct_aabb root = noct_bp_root_box(bp);
    for (int k = 0; k < 3; ++k)
        if (!lattice_around(small, &root, b, k, &blk->lo[k], &blk->hi[k]))
            return false;
    *size = s;
    return true;
}

static noctStatus leave_phase(noctBroadphase *bp, const double (*pos)[3], uint32_t id,
                              bool *enter)
{
    noct_proxy *o = &bp->proxy[id];
    const noct_aabb *b = &bp->box[id];
    *enter = false;
    /* maintain() tried a block it had; one is taken when there was none
     * (a proxy moved by the public API tested its own: pos NULL) */
    if (pos != NULL && !isfinite(bp->home[id].lo[0]) &&
        noct_bp_home_of(bp, id, &o->old, &bp->home[id]) &&
        noct_inside_home(pos[id], &bp->home[id])) {
        ++bp->c.inside_fast;
        return NOCT_OK;
    }
    noct_forget_home(bp, id);
    for (uint32_t i = 0; i < o->nspans;) {
        if (noct_overlaps(b, noct_cell_of(o->spans[i].leaf))) {
            ++i;
            continue;
        }
        noct_bp_leaf_remove_at(bp, o->spans[i].leaf, o->spans[i].at);
        i = 0; /* merges may have rewritten the list */
    }
    *enter = true;
    return NOCT_OK;
}

/*
 * Phase B, per object: the enter check. The leaves a box overlaps are
 * connected, so a flood from the leaves it is still in finds them all.
 * From each leaf whose boundary the box reaches, query the
 * greater-or-equal neighbors in the directions it reaches (for a box that
 * was inside its leaves, the quantized directions of its motion), each
 * neighbor node once per object per step (the node's stamp), and add the
 * object to the leaves below it that the box overlaps; newly entered
 * leaves join the flood. A box that left every leaf it was in (it moved
 * farther than its leaves are wide) is re-inserted from the root.
 *
 * A query is skipped when the part of the new box inside the leaf-sized
 * cube across that face, edge or vertex lies inside the old box: every
 * leaf there that the new box overlaps overlapped the old box, so the
 * object is in it already (phase A only removed leaves the new box left).
 */
static noctStatus enter_phase(noctBroadphase *bp, uint32_t id)
{
    noct_proxy *o = &bp->proxy[id];
    const noct_aabb *bx = &bp->box[id];
    if (o->nspans == 0) {
        ++bp->c.reinserts;
        return noct_bp_insert_below(bp, bp->root, id, false, true) ? NOCT_OK : NOCT_ERR_NOMEM;
    }
    if (bp->capwork < o->nspans) {
        if (!resize_nodes(&bp->work, o->nspans))
            return NOCT_ERR_NOMEM;
        bp->capwork = o->nspans;
    }
    for (uint32_t i = 0; i < o->nspans; ++i)
        bp->work[i] = o->spans[i].leaf;
    bp->nwork = o->nspans;
    for (size_t wi = 0; wi < bp->nwork; ++wi) {
        const noct_cell *lc = noct_cell_of(bp->work[wi]);
        /* Per axis: 0, and -1 / +1 if the box reaches that face. */
        int reach[3][3], nr[3];
        for (int k = 0; k < 3; ++k) {
            nr[k] = 0;
            reach[k][nr[k]++] = 0;
            if (bx->lo[k] <= lc->lo[k])
                reach[k][nr[k]++] = -1;
            if (bx->hi[k] >= lc->lo[k] + lc->size)
                reach[k][nr[k]++] = 1;
        }
        if (nr[0] + nr[1] + nr[2] == 3)
            continue; /* strictly inside: no neighbor can be reached */
        for (int a = 0; a < nr[0]; ++a)
            for (int b = 0; b < nr[1]; ++b)
                for (int c = 0; c < nr[2]; ++c) {
                    const int v[3] = {reach[0][a], reach[1][b], reach[2][c]};
                    bool covered = true;
                    for (int k = 0; k < 3 && covered; ++k) {
                        double clo = lc->lo[k] + v[k] * lc->size;
                        double ilo = noct_max(bx->lo[k], clo);
                        double ihi = noct_min(bx->hi[k], clo + lc->size);
                        covered = ilo >= o->old.lo[k] && ihi <= o->old.hi[k];
                    }
                    if (covered)
                        continue;
                    octDirection d = noct_direction_of(v[0], v[1], v[2]);
                    if (d == OCT_OMEGA)
                        continue;
                    octNode *nb = octGtEqNeighbor(bp->work[wi], d);
                    ++bp->c.neighbor_queries;
                    if (nb == NULL)
                        continue;
                    noct_cell *nc = noct_cell_of(nb);
                    if (nc->stamp_step == bp->clock && nc->stamp_obj == id)
                        continue;
                    nc->stamp_step = bp->clock;
                    nc->stamp_obj = id;
                    if (!noct_bp_insert_below(bp, nb, id, true, false))
                        return NOCT_ERR_NOMEM;
                }
    }
    return NOCT_OK;
}

/*
 * The slow objects' leaves are four dependent reads away (the object, its
 * spans array, the leaf node, its cell), each a likely miss when objects
 * are many: while slow object m is maintained, request them in stages for
 * the objects 2, 4, 6 and 8 places ahead, each stage reading what the one
 * before requested two objects earlier.
 */

static NOCT_ALWAYS_INLINE void prefetch_spans(const noctBroadphase *bp, const uint32_t *slow,
                                              uint32_t n, uint32_t m)
{
    if (m + 8 < n)
        NOCT_PREFETCH(&bp->proxy[slow[m + 8]].spans);
    if (m + 6 < n)
        NOCT_PREFETCH(bp->proxy[slow[m + 6]].spans);
    if (m + 4 < n) {
        const noct_proxy *o = &bp->proxy[slow[m + 4]];
        for (uint32_t k = 0; k < o->nspans; ++k)
            NOCT_PREFETCH(o->spans[k].leaf);
    }
    if (m + 2 < n) {
        const noct_proxy *o = &bp->proxy[slow[m + 2]];
        for (uint32_t k = 0; k < o->nspans; ++k)
            NOCT_PREFETCH(noct_cell_of(o->spans[k].leaf));
    }
}

/*
 * Incremental maintenance. The caller (the world's motion loop, or a
 * public move) ran the fast test and listed the boxes that failed it in
 * slow. A box that passed lies in its home block, and so in its leaves
 * and the root; of the others, if one left the root, *escaped is set and
 * nothing else is done (the caller grows the tree, noct_bp_settle).
 */
noctStatus noct_bp_maintain(noctBroadphase *bp, const double (*pos)[3], const uint32_t *slow,
                            uint32_t n, uint32_t nfast, bool *escaped)
{
    noctStatus st = NOCT_OK;
    *escaped = false;
    const noct_aabb root = noct_bp_root_box(bp);
    for (uint32_t m = 0; m < n; ++m)
        if (!noct_box_within(&bp->box[slow[m]], &root)) {
            *escaped = true;
            return NOCT_OK;
        }
    bp->c.inside_fast += nfast;
    /* Below some thousands of objects they stay in cache. */
    const bool ahead = bp->nslots >= PREFETCH_OBJECTS;
    for (uint32_t m = 0; m < n && st == NOCT_OK; ++m) {
        if (ahead)
            prefetch_spans(bp, slow, n, m);
        st = leave_phase(bp, pos, slow[m], &bp->proxy[slow[m]].entering);
    }
    for (uint32_t m = 0; m < n && st == NOCT_OK; ++m) {
        if (ahead)
            prefetch_spans(bp, slow, n, m);
        if (bp->proxy[slow[m]].entering)
            st = enter_phase(bp, slow[m]);
    }
    /* Their leaves are final for this step, and in cache: take their home
     * blocks now, so that the next step's fast test can pass them. A
     * later change to their leaves forgets the block again. */
    for (uint32_t m = 0; m < n && st == NOCT_OK; ++m) {
        const uint32_t id = slow[m];
        if (ahead)
            prefetch_spans(bp, slow, n, m);
        if (!isfinite(bp->home[id].lo[0]) && !noct_bp_home_of(bp, id, &bp->box[id], &bp->home[id]))
            noct_forget_home(bp, id);
    }
    return st;
}

/*
 * Is the root far larger than its objects need? When all of them lie in
 * one grandchild of the root (every other child and grandchild is an
 * empty leaf: a split node always holds objects, try_merge sees to it),
 * a rebuild fits a root at most half as large. A rebuilt root is less
 * than four times the objects' extent, so it does not fit them in one of
 * its grandchildren again until they draw together: the hysteresis that
 * keeps an object going to and fro from rebuilding the tree every step.
 */
static bool root_too_large(const noctBroadphase *bp)
{
    const octNode *n = bp->root;
    for (int level = 0; level < 2; ++level) {
        if (!NOCT_NODE_IS_SPLIT(n))
            return false;
        const octNode *only = NULL;
        for (int i = 0; i < 8; ++i) {
            const octNode *k = NOCT_NODE_CHILD(n, (octDirection)(OCT_LDB + i));
            if (!NOCT_NODE_IS_SPLIT(k) && noct_cell_of(k)->count == 0)
                continue;
            if (only != NULL)
                return false;
            only = k;
        }
        if (only == NULL)
            return false;
        n = only;
    }
    return true;
}

/* Frames (world sub-steps, public pair searches) after the root last grew
 * before it may shrink: a group of
 * objects drifting away grows the root (twice as large, the objects near
 * its corner) and would otherwise shrink it again at once, to grow it a
 * few steps later; so it rebuilds at most about once in this many. */
#define SHRINK_AFTER 64

/*
 * After maintenance: grow the root if a box escaped it (a rebuild around
 * a root twice as large), shrink it when all the proxies lie in one
 * grandchild (not within SHRINK_AFTER ticks of a growth), and make the
 * merges that lacked memory.
 */
noctStatus noct_bp_settle(noctBroadphase *bp, bool escaped)
{
    noctStatus st = NOCT_OK;
    if (escaped && bp->root != NULL) {
        st = noct_bp_rebuild(bp, 2 * noct_cell_of(bp->root)->size);
        bp->shrink_from = bp->frame + SHRINK_AFTER;
    }
    if (st == NOCT_OK && bp->root != NULL &&
        ((bp->frame >= bp->shrink_from && root_too_large(bp)) || noct_bp_choice_stale(bp)))
        st = noct_bp_rebuild(bp, 0);
    if (st == NOCT_OK && bp->root != NULL && bp->merge_owed) {
        bp->merge_owed = false;
        noct_bp_merge_all(bp, bp->root);
    }
    return st;
}
