/* SPDX-License-Identifier: MIT */
/*
 * The broadphase's pair search (report section 2.2): a depth-first walk
 * over the leaves that hands each pair of proxies whose boxes overlap to
 * the caller exactly once, in the one leaf that owns the lower corner of
 * the two boxes' overlap, so that no table of found pairs is needed.
 * Leaves are swept (their boxes sorted on one axis) and keep the pairs
 * their sweep found near, for the searches while the margin lasts.
 */
#include "config.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "box_sweep.h"
#include "broadphase_internal.h"

/* ---- pair search, events, response ------------------------------------------- */

NOCT_DEFINE_GROW(grow_pairs, noctProxyPair)
NOCT_DEFINE_RESIZE(resize_pairs, noctProxyPair)
NOCT_DEFINE_GROW(grow_gather, noct_leaf_box)
NOCT_DEFINE_GROW(grow_u32, uint32_t)

void noct_bp_begin_frame(noctBroadphase *bp)
{
    ++bp->clock;
    ++bp->frame;
    bp->reach = 0;
}

void noct_bp_add_reach(noctBroadphase *bp, double travel)
{
    const noct_aabb root = noct_bp_root_box(bp);
    double r = 0;
    for (int k = 0; k < 3; ++k)
        r = noct_max(r, noct_max(fabs(root.lo[k]), fabs(root.hi[k])));
    bp->reach += travel * (1 + 1e-6) + 8 * 0x1p-52 * (isfinite(r) ? r : 0);
}

noctStatus noct_bp_find_pairs(noctBroadphase *bp)
{
    noctStatus st = noct_bp_search(bp);
    if (st == NOCT_OK && !noct_bp_sort_tested(bp))
        st = NOCT_ERR_NOMEM;
    return st;
}

void noct_bp_end_search(noctBroadphase *bp)
{
    bp->pending_reach = 0;
    ++bp->search_epoch;
}

bool noct_pairs_grow(noct_pair_list *l)
{
    /* 64 first, then doubling */
    return grow_pairs(&l->p, &l->cap, l->cap > 0 ? l->cap + 1 : 64);
}

int noct_pair_cmp(const void *x, const void *y)
{
    return noct_pair_order(x, y);
}

/* Does the leaf own point p: [lo, lo + size) per axis, closed at the
 * root's upper faces? noct_cell_owns() (broadphase_internal.h), which the
 * queries and the margin's candidates call, spelled out again here: with
 * the shared one, GCC 12 compiles search_leaf() into 0.8 % more
 * instructions (planes:10, callgrind), for the same code. */
static bool owns(const noct_cell *c, const noct_cell *root, const double p[3])
{
    for (int k = 0; k < 3; ++k) {
        double hi = c->lo[k] + c->size;
        if (p[k] < c->lo[k] || p[k] > hi)
            return false;
        if (p[k] == hi && hi != root->lo[k] + root->size)
            return false;
    }
    return true;
}

NOCT_DEFINE_BOX_SWEEP(leaf_boxes, noct_leaf_box, uint32_t)

/* The pair (a, b) of leaf c, whose boxes overlap, for the narrowphase if
 * c owns the lower corner of their overlap. */
static NOCT_ALWAYS_INLINE bool offer_pair(noctBroadphase *bp, const noct_cell *c, const noct_cell *rc,
                                          const double alo[3], uint32_t ia,
                                          const double blo[3], uint32_t ib)
{
    const double corner[3] = {noct_max(alo[0], blo[0]), noct_max(alo[1], blo[1]),
                              noct_max(alo[2], blo[2])};
    if (!owns(c, rc, corner))
        return true;
    /* the filters cost nothing until a proxy has one */
    if (bp->filtered > 0 && !noct_filters_pass(&bp->proxy[ia], &bp->proxy[ib]))
        return true;
    if (ia > ib) {
        uint32_t t = ia;
        ia = ib;
        ib = t;
    }
    return noct_pairs_push(&bp->tested, (noctProxyPair){{ia, 0}, {ib, 0}});
}

/* Room for one more near pair in leaf c: a larger array from the pool,
 * the old one given back. */
static NOCT_ALWAYS_INLINE bool near_reserve(noctBroadphase *bp, noct_cell *c)
{
    if (c->nnear < c->capnear)
        return true;
    void *a = c->near;
    if (!noct_apool_grow(&bp->near_pool, &a, &c->capnear, c->nnear))
        return false;
    c->near = a;
    return true;
}

/* How many steps of reach a sweep's near pairs are kept for: a leaf is
 * swept about once in that many steps, and its near pairs tested in the
 * others. */
#define NEAR_STEPS 4
/* Near pairs a leaf keeps at most, per box (plus a few): see search_leaf. */
#define NEAR_PER_OBJECT 8
#define UNLISTED_SWEEPS 4

/*
 * The fresh objects of leaf c, which came since its near pairs were made:
 * rather than sweep the leaf again, add their pairs closer than the
 * budget (this step's, held to a sweep's margin, so that the leaf is
 * swept again as soon as one made now would be) to the near pairs. Every
 * other pair is then at least the budget apart. Their boxes were
 * requested with the leaf's.
 */
static bool near_fresh(noctBroadphase *bp, noct_cell *c)
{
    const double budget = noct_min(c->budget, 2 * NEAR_STEPS * bp->reach);
    c->budget = 0; /* until every pair is in */
    for (uint32_t r = c->fresh; r < c->count; ++r) {
        const noct_aabb *a = &bp->box[c->objs[r]];
        for (uint32_t i = 0; i < r; ++i) {
            const noct_aabb *b = &bp->box[c->objs[i]];
            const double gap = noct_max(
                noct_max(noct_max(b->lo[0] - a->hi[0], a->lo[0] - b->hi[0]),
                         noct_max(b->lo[1] - a->hi[1], a->lo[1] - b->hi[1])),
                noct_max(b->lo[2] - a->hi[2], a->lo[2] - b->hi[2]));
            if (gap > budget)
                continue;
            if (!near_reserve(bp, c))
                return false;
            c->near[c->nnear++] = i | r << 16;
        }
    }
    bp->c.candidate_pairs += (uint64_t)(c->count - c->fresh) * (c->count + c->fresh - 1) / 2;
    c->fresh = c->count;
    c->budget = budget;
    return true;
}

/*
 * The pairs of a leaf. While its budget lasts (below), the pairs that its
 * last sweep found near are tested and no other can meet, or, if there
 * were none, the leaf is skipped. Else it is swept: its boxes sorted on
 * one axis, each box against those after it that start before it ends
 * plus the margin 2 NEAR_STEPS reach; those pairs are the near ones, and
 * the others were farther apart than the margin, which is the new budget
 * (or, without near pairs, the least distance apart of any pair).
 */
static noctStatus search_leaf(noctBroadphase *bp, noct_cell *c)
{
    const noct_cell *rc = noct_cell_of(bp->root);
    const bool sweep = bp->N != NOCT_N_EXHAUSTIVE;
    if (sweep && c->budget > 2 * bp->reach && c->count <= 0x10000) {
        c->budget -= 2 * bp->reach;
        if (c->fresh < c->count && !near_fresh(bp, c))
            return NOCT_ERR_NOMEM;
        if (c->nnear == 0) {
            ++bp->c.leaves_skipped;
            return NOCT_OK;
        }
        ++bp->c.leaves_visited;
        bp->c.candidate_pairs += c->nnear;
        for (uint32_t k = 0; k < c->nnear; ++k) {
            const uint32_t ia = c->objs[c->near[k] & 0xffff], ib = c->objs[c->near[k] >> 16];
            const noct_aabb *a = &bp->box[ia], *b = &bp->box[ib];
            if ((a->hi[0] < b->lo[0]) | (b->hi[0] < a->lo[0]) | (a->hi[1] < b->lo[1]) |
                (b->hi[1] < a->lo[1]) | (a->hi[2] < b->lo[2]) | (b->hi[2] < a->lo[2]))
                continue;
            if (!offer_pair(bp, c, rc, a->lo, ia, b->lo, ib))
                return NOCT_ERR_NOMEM;
        }
        return NOCT_OK;
    }
    ++bp->c.leaves_visited;
    if (!grow_gather(&bp->gather, &bp->capgather, 2 * (size_t)c->count))
        return NOCT_ERR_NOMEM;
    noct_leaf_box *g = bp->gather;
    /* The boxes are scattered; search() requested them a leaf ahead. */
    for (uint32_t i = 0; i < c->count; ++i) {
        const noct_aabb *o = &bp->box[c->objs[i]];
        memcpy(g[i].lo, o->lo, sizeof o->lo);
        memcpy(g[i].hi, o->hi, sizeof o->hi);
        g[i].id = c->objs[i];
    }
    bp->c.candidate_pairs += (uint64_t)c->count * (c->count - 1) / 2;
    /* The exhaustive mode keeps the report's test of every pair. */
    int axis = 0;
    if (sweep) {
        axis = leaf_boxes_axis(g, c->count);
        leaf_boxes_sort(g, c->count, axis, g + c->count);
        /* The leaf keeps this order: objects move little in a step, so
         * the next sweep's insertion sort finds them nearly sorted, and
         * near pairs are positions in it. */
        for (uint32_t i = 0; i < c->count; ++i)
            if (c->objs[i] != g[i].id) /* few move: tell only those */
                noct_leaf_put(bp, c, i, g[i].id, noct_span_of(bp, g[i].id, c));
    }
    /* Near pairs pay while they are few: when objects move so far for
     * their leaf that the margin takes in most of its pairs (fast objects
     * in large leaves), testing them all every search costs more than
     * sweeping again. So a list that grows past NEAR_PER_OBJECT a box is
     * dropped at once (the sweep goes on without a margin), and the next
     * UNLISTED_SWEEPS sweeps keep none; then a list is tried again. */
    const bool listing = sweep && c->count <= 0x10000 && c->unlisted == 0;
    if (c->unlisted > 0)
        --c->unlisted;
    const uint32_t near_cap = NEAR_PER_OBJECT * c->count + 64;
    bool listed = listing;
    double m2 = listing ? 2 * NEAR_STEPS * bp->reach : 0;
    c->nnear = 0;
    /* Meanwhile the least distance apart of the pairs beyond the margin:
     * those the sweep passes over are apart on its axis by at least the
     * next box's start less a's end. The four comparisons on the other
     * axes are combined without branches: most pairs fail one of them, in
     * no predictable order. */
    const int k1 = (axis + 1) % 3, k2 = (axis + 2) % 3;
    double apart = sweep ? INFINITY : 0;
    for (uint32_t i = 0; i < c->count; ++i) {
        const noct_leaf_box *a = &g[i];
        const double ahi = a->hi[axis], reach_hi = ahi + m2;
        for (uint32_t j = i + 1; j < c->count; ++j) {
            const noct_leaf_box *b = &g[j];
            if (sweep ? b->lo[axis] > reach_hi
                      : (a->hi[axis] < b->lo[axis]) | (b->hi[axis] < a->lo[axis])) {
                if (sweep) {
                    apart = noct_min(apart, b->lo[axis] - ahi);
                    break;
                }
                continue;
            }
            const double gap = noct_max(noct_max(b->lo[k1] - a->hi[k1], a->lo[k1] - b->hi[k1]),
                                        noct_max(b->lo[k2] - a->hi[k2], a->lo[k2] - b->hi[k2]));
            if (gap > m2) {
                apart = noct_min(apart, gap);
                continue;
            }
            if (listed && c->nnear == near_cap) {
                listed = false; /* too many: no list, no margin from here on */
                m2 = 0;
                c->nnear = 0;
            }
            if (listed) {
                if (!near_reserve(bp, c))
                    return NOCT_ERR_NOMEM;
                c->near[c->nnear++] = i | j << 16;
            }
            if (gap > 0 || b->lo[axis] > ahi)
                continue; /* near, apart (touching boxes overlap) */
            if (!offer_pair(bp, c, rc, a->lo, a->id, b->lo, b->id))
                return NOCT_ERR_NOMEM;
        }
    }
    if (listing && !listed)
        c->unlisted = UNLISTED_SWEEPS;
    c->budget = !listed ? 0 : c->nnear > 0 ? m2 : apart;
    noct_apool_shrink(&bp->near_pool, (void **)&c->near, &c->capnear, c->nnear);
    c->fresh = c->count;
    return NOCT_OK;
}

/*
 * The tested pairs in order of their first object: a stable radix sort on
 * its index, in two passes of half its bits. The narrowphase then reads
 * the first objects and their meshes in memory order, and the colliding
 * pairs come out sorted but for the order of each object's partners
 * (sort_partners).
 */
bool noct_bp_sort_tested(noctBroadphase *bp)
{
    const size_t n = bp->tested.n;
    if (n < 2)
        return true;
    if (bp->capsorted < n) {
        if (!resize_pairs(&bp->sorted, n))
            return false;
        bp->capsorted = n;
    }
    unsigned bits = 1;
    while (bits < 32 && (1u << bits) < bp->nslots)
        ++bits;
    const unsigned low = (bits + 1) / 2;
    const uint32_t buckets = 1u << low;
    if (!grow_u32(&bp->digits, &bp->capdigits, buckets))
        return false;
    noctProxyPair *from = bp->tested.p, *to = bp->sorted;
    for (unsigned shift = 0; shift < bits; shift += low) {
        uint32_t *count = bp->digits;
        memset(count, 0, buckets * sizeof *count);
        for (size_t i = 0; i < n; ++i)
            ++count[(from[i].a.index >> shift) & (buckets - 1)];
        uint32_t sum = 0;
        for (uint32_t d = 0; d < buckets; ++d) {
            uint32_t c = count[d];
            count[d] = sum;
            sum += c;
        }
        for (size_t i = 0; i < n; ++i)
            to[count[(from[i].a.index >> shift) & (buckets - 1)]++] = from[i];
        noctProxyPair *t = from;
        from = to;
        to = t;
    }
    if (from != bp->tested.p) { /* an odd number of passes: swap the buffers */
        noctProxyPair *t = bp->tested.p;
        bp->tested.p = from;
        bp->sorted = t;
        size_t c = bp->tested.cap;
        bp->tested.cap = bp->capsorted;
        bp->capsorted = c;
    }
    return true;
}

/* Sort pairs that are in order of their first object by their second
 * within each first object: insertion sort for short runs, qsort for the
 * long ones a big object has. */
void noct_pairs_sort_partners(noct_pair_list *l)
{
    size_t start = 0;
    while (start < l->n) {
        size_t end = start + 1;
        while (end < l->n && l->p[end].a.index == l->p[start].a.index)
            ++end;
        noctProxyPair *r = l->p + start;
        size_t len = end - start;
        if (len > 32) {
            qsort(r, len, sizeof *r, noct_pair_cmp);
        } else {
            for (size_t i = 1; i < len; ++i) {
                noctProxyPair t = r[i];
                size_t j = i;
                for (; j > 0 && r[j - 1].b.index > t.b.index; --j)
                    r[j] = r[j - 1];
                r[j] = t;
            }
        }
        start = end;
    }
}

/* The narrowphase on the pairs the search found (whose boxes it tested
 * already). At the exact level a pair of objects with box-form meshes is
 * decided on their slots, two cache lines each, in most cases without
 * reading the meshes; the rest go through the meshes. Slots are scattered
 * by pair, so they and the positions are requested 16 pairs ahead, and 8
 * ahead the first lines of the meshes that are not boxes. */

/* Request a leaf's object and near-pair lists. */
static NOCT_ALWAYS_INLINE void prefetch_lists(const noct_cell *c)
{
    if (c->count > 1) {
        NOCT_PREFETCH(c->objs);
        if (c->nnear > 0)
            NOCT_PREFETCH(c->near);
    }
}

/* Request the boxes of a leaf whose lists are in cache, if the search
 * will read them this step (search_leaf skips the leaf otherwise). */
static NOCT_ALWAYS_INLINE void prefetch_boxes(const noctBroadphase *bp, const noct_cell *c)
{
    if (c->count < 2 || (bp->N != NOCT_N_EXHAUSTIVE && c->budget > 2 * bp->reach &&
                         c->nnear == 0 && c->fresh == c->count))
        return;
    for (uint32_t i = 0; i < c->count; ++i) {
        const char *b = (const char *)&bp->box[c->objs[i]];
        NOCT_PREFETCH(b);
        NOCT_PREFETCH(b + sizeof(noct_aabb) - 1);
    }
}

/*
 * The depth-first walk. A node's children's cells are one block
 * (split_leaf), requested whole on the way down; then, while child i is
 * searched, the boxes of child i + 1, whose lists were requested while
 * child i - 1 was, and the lists of child i + 2: each leaf's scattered
 * reads are under way a leaf or two before it needs them. In worlds of
 * fewer than PREFETCH_OBJECTS objects (ahead false) they are in cache,
 * and nothing is requested. Leaves with fewer than two objects are not
 * visited.
 */
static noctStatus search(noctBroadphase *bp, octNode *n, bool ahead)
{
    const noct_cell *kids = noct_cell_of(NOCT_NODE_CHILD(n, OCT_LDB));
    if (ahead) {
        for (size_t b = 0; b < 8 * sizeof *kids; b += 64)
            NOCT_PREFETCH((const char *)kids + b);
        prefetch_lists(&kids[0]);
        prefetch_lists(&kids[1]);
        prefetch_boxes(bp, &kids[0]);
    }
    for (int i = 0; i < 8; ++i) {
        if (ahead && i + 1 < 8)
            prefetch_boxes(bp, &kids[i + 1]);
        if (ahead && i + 2 < 8)
            prefetch_lists(&kids[i + 2]);
        octNode *k = NOCT_NODE_CHILD(n, (octDirection)(OCT_LDB + i));
        noctStatus st = NOCT_NODE_IS_SPLIT(k) ? search(bp, k, ahead)
                        : kids[i].count < 2   ? NOCT_OK
                                              : search_leaf(bp, noct_cell_of(k));
        if (st != NOCT_OK)
            return st;
    }
    return NOCT_OK;
}

/* began = colliding - previous, ended = previous - colliding (sorted). */

noct_pair_list *noct_bp_skip_search(noctBroadphase *bp, uint64_t candidates)
{
    bp->owed_reach += bp->reach;
    bp->c.candidate_pairs += candidates;
    bp->tested.n = 0;
    return &bp->tested;
}

noctStatus noct_bp_search(noctBroadphase *bp)
{
    /* Every leaf's budget is spent by the reach of each frame since its
     * last search, the frames without a search too. */
    bp->reach += bp->owed_reach;
    bp->owed_reach = 0;
    bp->tested.n = 0;
    if (bp->root != NULL && NOCT_NODE_IS_SPLIT(bp->root))
        return search(bp, bp->root, bp->nslots >= PREFETCH_OBJECTS);
    if (bp->root != NULL && noct_cell_of(bp->root)->count >= 2) {
        prefetch_boxes(bp, noct_cell_of(bp->root));
        return search_leaf(bp, noct_cell_of(bp->root));
    }
    return NOCT_OK;
}
