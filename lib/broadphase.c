/* SPDX-License-Identifier: MIT */
/*
 * The broadphase's public API (broadphase.h): proxies and their slots,
 * filters, moves, the pair list, counters, octree access and the
 * validation walk. The tree is broadphase_tree.c's, the pair search
 * broadphase_pairs.c's, the queries broadphase_query.c's.
 */
#include "config.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <noctree/mesh.h>

#include "broadphase_internal.h"

noctBroadphaseDef noctDefaultBroadphaseDef(void)
{
    noctBroadphaseDef d;
    d.N = NOCT_AUTO;
    d.max_depth = NOCT_AUTO;
    for (int k = 0; k < 3; ++k)
        d.bounds_lo[k] = d.bounds_hi[k] = 0;
    return d;
}

void noctBroadphaseGetSettings(const noctBroadphase *bp, int *N, int *max_depth)
{
    NOCT_REQUIRE(bp != NULL);
    if (N != NULL)
        *N = bp->N;
    if (max_depth != NULL)
        *max_depth = bp->max_depth;
}

noctQueryFilter noctDefaultQueryFilter(void)
{
    return (noctQueryFilter){NOCT_FILTER_ALL, NOCT_FILTER_ALL};
}

noctStatus noct_bp_init(noctBroadphase *bp, const noctBroadphaseDef *def, noctError *err)
{
    if (def->N < 0)
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0,
                         "N is %d; it must be at least 1, or NOCT_AUTO (0)", def->N);
    if (def->max_depth < 0 || def->max_depth > 40)
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0,
                         "max_depth is %d; it must be 1 to 40, or NOCT_AUTO (0)", def->max_depth);
    bool hint = true;
    for (int k = 0; k < 3; ++k) {
        if (!isfinite(def->bounds_lo[k]) || !isfinite(def->bounds_hi[k]))
            return noct_fail(err, NOCT_ERR_NONFINITE, -1, 0, "the bounds hint is not finite");
        if (fabs(def->bounds_lo[k]) > NOCT_MAX_COORDINATE ||
            fabs(def->bounds_hi[k]) > NOCT_MAX_COORDINATE)
            return noct_fail(err, NOCT_ERR_TOO_LARGE, -1, 0, "the bounds hint lies beyond %g",
                             NOCT_MAX_COORDINATE);
        hint = hint && def->bounds_lo[k] < def->bounds_hi[k];
    }
    memset(bp, 0, sizeof *bp);
    bp->objs_pool.elem = 2 * sizeof(uint32_t);
    bp->objs_pool.base = 4;
    bp->near_pool.elem = sizeof(uint32_t);
    bp->near_pool.base = 8;
    bp->spans_pool.elem = sizeof(noct_span);
    bp->spans_pool.base = 4; /* most proxies are in 4 leaves or fewer */
    bp->auto_N = def->N == NOCT_AUTO;
    bp->auto_depth = def->max_depth == NOCT_AUTO;
    /* until the first build chooses */
    bp->N = bp->auto_N ? NOCT_AUTO_N : def->N;
    bp->max_depth = bp->auto_depth ? 40 : def->max_depth;
    bp->hint = hint;
    memcpy(bp->bounds_lo, def->bounds_lo, sizeof bp->bounds_lo);
    memcpy(bp->bounds_hi, def->bounds_hi, sizeof bp->bounds_hi);
    return NOCT_OK;
}

void noct_bp_fini(noctBroadphase *bp)
{
    noct_bp_free_tree(bp);
    /* (the proxies' spans are the spans pool's, freed with its slabs) */
    free(bp->proxy);
    free(bp->box);
    free(bp->home);
    free(bp->gen);
    free(bp->mark);
    free(bp->free_slots);
    free(bp->work);
    free(bp->gather);
    free(bp->tested.p);
    free(bp->sorted);
    free(bp->digits);
    free(bp->pairs.p);
    noct_apool_free(&bp->objs_pool);
    noct_apool_free(&bp->near_pool);
    noct_apool_free(&bp->spans_pool);
}

noctStatus noctBroadphaseCreate(const noctBroadphaseDef *def, noctBroadphase **bp,
                                noctError *err)
{
    NOCT_REQUIRE(def != NULL && bp != NULL);
    *bp = NULL;
    noctBroadphase *b = malloc(sizeof *b);
    if (b == NULL)
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    noctStatus st = noct_bp_init(b, def, err);
    if (st != NOCT_OK) {
        free(b);
        return st;
    }
    *bp = b;
    return NOCT_OK;
}

void noctBroadphaseDestroy(noctBroadphase *bp)
{
    if (bp == NULL)
        return;
    noct_bp_fini(bp);
    free(bp);
}

NOCT_DEFINE_RESIZE(resize_proxies, noct_proxy)
NOCT_DEFINE_RESIZE(resize_boxes, noct_aabb)
NOCT_DEFINE_RESIZE(resize_homes, noct_home)
NOCT_DEFINE_RESIZE(resize_u32, uint32_t)

/* Every per-slot array to capacity cap; each that grew is kept even if a
 * later one fails. */
static bool reserve_slots(noctBroadphase *bp, uint32_t cap)
{
    if (cap <= bp->capslots)
        return true;
    if (!resize_proxies(&bp->proxy, cap) || !resize_boxes(&bp->box, cap) ||
        !resize_homes(&bp->home, cap) || !resize_u32(&bp->gen, cap) ||
        !resize_u32(&bp->mark, cap) || !resize_u32(&bp->free_slots, cap))
        return false;
    bp->capslots = cap;
    return true;
}

bool noct_bp_reserve(noctBroadphase *bp, uint32_t more)
{
    /* room: the free slots, and the capacity past the last slot */
    if ((uint64_t)bp->nfree + (bp->capslots - bp->nslots) >= more)
        return true;
    const uint64_t cap = (uint64_t)bp->nslots + (more - bp->nfree);
    return cap <= 0x80000000u && reserve_slots(bp, (uint32_t)cap);
}

/* A slot for a new proxy (its generation advanced, nothing else set);
 * UINT32_MAX without memory or past 2^31 slots. */
uint32_t noct_bp_new_slot(noctBroadphase *bp)
{
    if (bp->nfree > 0)
        return bp->free_slots[--bp->nfree];
    if (bp->nslots >= 0x80000000u)
        return UINT32_MAX;
    if (bp->nslots == bp->capslots &&
        !reserve_slots(bp, bp->capslots ? 2 * bp->capslots : 16))
        return UINT32_MAX;
    const uint32_t s = bp->nslots++;
    memset(&bp->proxy[s], 0, sizeof bp->proxy[s]);
    bp->gen[s] = 0;
    bp->mark[s] = 0;
    return s;
}

void noct_bp_unuse_slot(noctBroadphase *bp, uint32_t s)
{
    NOCT_INVARIANT(s < bp->nslots && !bp->proxy[s].alive && bp->nfree < bp->capslots);
    if (s + 1 == bp->nslots)
        --bp->nslots;
    else
        bp->free_slots[bp->nfree++] = s;
}

/*
 * Make slot s (from noct_bp_new_slot) a live proxy with local box mlo, mhi
 * at position pos, and put it in the tree. On failure the slot is free
 * again, nothing was added and the tree is owed (if it was touched).
 */
noctStatus noct_bp_add(noctBroadphase *bp, uint32_t s, const double mlo[3], const double mhi[3],
                       const double pos[3], void *user, uint64_t category, uint64_t mask)
{
    noct_proxy *o = &bp->proxy[s];
    memcpy(o->mlo, mlo, sizeof o->mlo);
    memcpy(o->mhi, mhi, sizeof o->mhi);
    o->nspans = 0;
    o->alive = true;
    o->entering = false;
    o->boxed = false;
    o->user = user;
    o->category = category;
    o->mask = mask;
    o->travel = 0;
    bp->gen[s] = bp->gen[s] + 1 ? bp->gen[s] + 1 : 1;
    noct_place_box(mlo, mhi, pos, &bp->box[s]);
    noct_forget_home(bp, s);
    ++bp->alive;
    bp->filtered += category != NOCT_FILTER_ALL || mask != NOCT_FILTER_ALL;
    if (bp->tree_owed || noct_bp_choice_stale(bp)) {
        /* a failure tore the tree down, or the automatic settings are
         * due again: build it now, with this one */
        noctStatus st = noct_bp_rebuild(bp, 0);
        if (st == NOCT_OK)
            return st;
    } else {
        noctStatus st = noct_bp_insert(bp, s);
        if (st == NOCT_OK)
            return st;
    }
    noct_bp_free_slot(bp, s);
    bp->tree_owed = bp->alive > 0;
    return NOCT_ERR_NOMEM;
}

/* Take a live proxy out of the tree and free its slot (cannot fail). */
void noct_bp_free_slot(noctBroadphase *bp, uint32_t s)
{
    noct_proxy *o = &bp->proxy[s];
    if (bp->root != NULL)
        noct_bp_unlink(bp, s);
    NOCT_INVARIANT(o->alive && o->nspans == 0 && bp->alive > 0);
    o->alive = false;
    --bp->alive;
    NOCT_INVARIANT(bp->filtered >= (size_t)(o->category != NOCT_FILTER_ALL ||
                                            o->mask != NOCT_FILTER_ALL));
    bp->filtered -= o->category != NOCT_FILTER_ALL || o->mask != NOCT_FILTER_ALL;
    NOCT_INVARIANT(bp->nfree < bp->capslots);
    bp->free_slots[bp->nfree++] = s;
}

/* A box given to the API: finite, lo <= hi, within the coordinate range. */
static noctStatus check_box(const double lo[3], const double hi[3], noctError *err)
{
    for (int k = 0; k < 3; ++k)
        if (!isfinite(lo[k]) || !isfinite(hi[k]))
            return noct_fail(err, NOCT_ERR_NONFINITE, -1, 0, "a box coordinate is not finite");
    for (int k = 0; k < 3; ++k)
        if (!(lo[k] <= hi[k]))
            return noct_fail(err, NOCT_ERR_INVALID, -1, 0,
                             "the box's low corner is above its high corner on axis %d", k);
    for (int k = 0; k < 3; ++k)
        if (fabs(lo[k]) > NOCT_MAX_COORDINATE || fabs(hi[k]) > NOCT_MAX_COORDINATE)
            return noct_fail(err, NOCT_ERR_TOO_LARGE, -1, 0, "a box coordinate lies beyond %g",
                             NOCT_MAX_COORDINATE);
    return NOCT_OK;
}

noctStatus noctBroadphaseAdd(noctBroadphase *bp, const double lo[3], const double hi[3],
                             void *user_data, uint64_t category, uint64_t mask,
                             noctProxyId *id, noctError *err)
{
    NOCT_REQUIRE(bp != NULL && lo != NULL && hi != NULL && id != NULL);
    id->index = id->generation = 0;
    noctStatus st = check_box(lo, hi, err);
    if (st != NOCT_OK)
        return st;
    const uint32_t s = noct_bp_new_slot(bp);
    if (s == UINT32_MAX)
        return bp->nslots >= 0x80000000u
                   ? noct_fail(err, NOCT_ERR_TOO_LARGE, -1, 0, "too many proxies")
                   : noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    const double zero[3] = {0, 0, 0};
    st = noct_bp_add(bp, s, lo, hi, zero, user_data, category, mask);
    if (st != NOCT_OK)
        return noct_fail(err, st, -1, 0, "out of memory");
    bp->proxy[s].boxed = true;
    id->index = s;
    id->generation = bp->gen[s];
    return NOCT_OK;
}

/* The proxy a handle names, or NULL. */
static noct_proxy *lookup(const noctBroadphase *bp, noctProxyId id)
{
    if (id.index >= bp->nslots || !bp->proxy[id.index].alive ||
        bp->gen[id.index] != id.generation || id.generation == 0)
        return NULL;
    return &bp->proxy[id.index];
}

/*
 * Removals leave the public pair list as it is and mark it: the first
 * read after them drops, in one pass, the pairs that name a proxy no
 * longer live (its slot free, or reused: another generation). So k
 * removals cost their own unlinking, and the list one pass when it is
 * next read, not k passes. The list is the broadphase's own (the
 * readers take a const broadphase only to promise they change nothing a
 * caller can see).
 */
static void drop_removed_pairs(const noctBroadphase *cbp)
{
    noctBroadphase *bp = (noctBroadphase *)cbp;
    if (!bp->pairs_removed)
        return;
    noct_pair_list *l = &bp->pairs;
    size_t k = 0;
    for (size_t i = 0; i < l->n; ++i)
        if (lookup(bp, l->p[i].a) != NULL && lookup(bp, l->p[i].b) != NULL)
            l->p[k++] = l->p[i];
    l->n = k;
    bp->pairs_removed = false;
}

noctStatus noctBroadphaseRemove(noctBroadphase *bp, noctProxyId id)
{
    NOCT_REQUIRE(bp != NULL);
    if (lookup(bp, id) == NULL)
        return NOCT_ERR_INVALID;
    noct_bp_free_slot(bp, id.index);
    bp->pairs_removed = bp->pairs.n > 0;
    return NOCT_OK;
}

noctStatus noctBroadphaseSetFilter(noctBroadphase *bp, noctProxyId id, uint64_t category,
                                   uint64_t mask)
{
    NOCT_REQUIRE(bp != NULL);
    noct_proxy *o = lookup(bp, id);
    if (o == NULL)
        return NOCT_ERR_INVALID;
    bp->filtered -= o->category != NOCT_FILTER_ALL || o->mask != NOCT_FILTER_ALL;
    o->category = category;
    o->mask = mask;
    bp->filtered += category != NOCT_FILTER_ALL || mask != NOCT_FILTER_ALL;
    return NOCT_OK;
}

noctStatus noctBroadphaseProxy(const noctBroadphase *bp, noctProxyId id, double lo[3],
                               double hi[3], void **user_data, uint64_t *category,
                               uint64_t *mask)
{
    NOCT_REQUIRE(bp != NULL);
    const noct_proxy *o = lookup(bp, id);
    if (o == NULL)
        return NOCT_ERR_INVALID;
    if (lo != NULL)
        memcpy(lo, bp->box[id.index].lo, sizeof bp->box[id.index].lo);
    if (hi != NULL)
        memcpy(hi, bp->box[id.index].hi, sizeof bp->box[id.index].hi);
    if (user_data != NULL)
        *user_data = o->user;
    if (category != NULL)
        *category = o->category;
    if (mask != NULL)
        *mask = o->mask;
    return NOCT_OK;
}

size_t noctBroadphaseProxyCount(const noctBroadphase *bp)
{
    NOCT_REQUIRE(bp != NULL);
    return bp->alive;
}

/*
 * A move of proxy s to the local box mlo, mhi at pos: the fast test in box
 * space (the new box overlaps the same cells of the proxy's smallest
 * leaf's size), else the leave and enter checks (noct_bp_maintain), else,
 * for a box that left the root, a rebuild. A box that changed size
 * changes its leaves' counts first (and may split them), while its box is
 * still the one they were made for. On failure (NOMEM) the proxy keeps its
 * old box and the tree is owed.
 */
noctStatus noct_bp_move_to(noctBroadphase *bp, uint32_t s, const double mlo_new[3],
                           const double mhi_new[3], const double pos[3])
{
    noct_proxy *o = &bp->proxy[s];
    noctStatus st = NOCT_OK;
    if (bp->tree_owed && (st = noct_bp_rebuild(bp, 0)) != NOCT_OK)
        return st;
    noct_aabb nb;
    noct_place_box(mlo_new, mhi_new, pos, &nb);
    const noct_aabb old = bp->box[s];
    const double mlo[3] = {o->mlo[0], o->mlo[1], o->mlo[2]};
    const double mhi[3] = {o->mhi[0], o->mhi[1], o->mhi[2]};
    ++bp->c.moves;
    ++bp->clock;
    /* how far the box moved, for the pair search's margins */
    double d = 0;
    for (int k = 0; k < 3; ++k)
        d = noct_max(d, noct_max(fabs(nb.lo[k] - old.lo[k]), fabs(nb.hi[k] - old.hi[k])));
    if (o->travel_epoch != (uint32_t)bp->search_epoch) {
        o->travel = 0;
        o->travel_epoch = (uint32_t)bp->search_epoch;
    }
    o->travel += d;
    bp->pending_reach = noct_max(bp->pending_reach, o->travel);
    /* a new size changes its leaves' counts (and may split them), first */
    bool resized = false, reboxed = false;
    for (int k = 0; k < 3; ++k) {
        resized = resized || mhi_new[k] - mlo_new[k] != mhi[k] - mlo[k];
        reboxed = reboxed || mlo_new[k] != mlo[k] || mhi_new[k] != mhi[k];
    }
    /* The fast test. A public proxy's, on the block its leaves were made
     * for, in box space (kept in home while they last, else taken from
     * its leaves now); a world object's, on its home in position space,
     * which holds only while its local box is the same. */
    noct_home *blk = &bp->home[s];
    bool fast;
    if (o->boxed) {
        if (!isfinite(blk->lo[0]) && !noct_bp_block_of(bp, s, &old, blk, &o->block))
            noct_forget_home(bp, s);
        fast = isfinite(blk->lo[0]) && noct_in_block(blk, o->block, &nb);
    } else {
        if (reboxed)
            noct_forget_home(bp, s);
        fast = isfinite(blk->lo[0]) && noct_inside_home(pos, blk);
    }
    if (resized && !noct_bp_reshape(bp, s, mlo_new, mhi_new)) {
        st = NOCT_ERR_NOMEM;
    } else if (!resized) {
        memcpy(o->mlo, mlo_new, sizeof o->mlo);
        memcpy(o->mhi, mhi_new, sizeof o->mhi);
    }
    if (st == NOCT_OK && fast && isfinite(blk->lo[0])) {
        /* (still: a split for its new size would have forgotten it) */
        bp->box[s] = nb;
        ++bp->c.inside_fast;
        return NOCT_OK;
    }
    if (st == NOCT_OK) {
        bool escaped;
        o->old = old;
        bp->box[s] = nb;
        st = noct_bp_maintain(bp, NULL, &s, 1, 0, &escaped);
        if (st == NOCT_OK && escaped)
            st = noct_bp_settle(bp, true);
        /* its leaves are final: the block of the next fast test */
        if (st == NOCT_OK && !(o->boxed ? noct_bp_block_of(bp, s, &nb, blk, &o->block)
                                        : noct_bp_home_of(bp, s, &nb, blk)))
            noct_forget_home(bp, s);
    }
    if (st != NOCT_OK) {
        /* the proxy keeps its old box; the tree is built again later */
        noct_forget_home(bp, s);
        bp->box[s] = old;
        memcpy(o->mlo, mlo, sizeof mlo);
        memcpy(o->mhi, mhi, sizeof mhi);
        noct_bp_drop_tree(bp);
    }
    return st;
}

noctStatus noctBroadphaseMove(noctBroadphase *bp, noctProxyId id, const double lo[3],
                              const double hi[3], noctError *err)
{
    NOCT_REQUIRE(bp != NULL && lo != NULL && hi != NULL);
    noct_proxy *o = lookup(bp, id);
    if (o == NULL)
        return noct_fail(err, NOCT_ERR_INVALID, (long)id.index, 0, "stale proxy handle");
    noctStatus st = check_box(lo, hi, err);
    if (st != NOCT_OK)
        return st;
    /* its local box is the box itself, at position 0 */
    const double zero[3] = {0, 0, 0};
    st = noct_bp_move_to(bp, id.index, lo, hi, zero);
    if (st != NOCT_OK)
        return noct_fail(err, st, (long)id.index, 0, "moving proxy %u: out of memory",
                         id.index);
    return NOCT_OK;
}

noctStatus noctBroadphaseUpdatePairs(noctBroadphase *bp, noctError *err)
{
    NOCT_REQUIRE(bp != NULL);
    bp->pairs.n = 0;
    bp->pairs_removed = false;
    noctStatus st = NOCT_OK;
    if (bp->tree_owed)
        st = noct_bp_rebuild(bp, 0);
    if (st == NOCT_OK)
        st = noct_bp_settle(bp, false);
    if (st != NOCT_OK)
        return noct_fail(err, st, -1, 0, "rebuilding the octree: out of memory");
    /* The margins: how far any box moved since the last search, and the
     * rounding of distances between boxes in the root. (The frame ticks
     * after the search here: a public search ends a frame.) */
    bp->reach = 0;
    noct_bp_add_reach(bp, bp->pending_reach);
    st = noct_bp_find_pairs(bp);
    if (st != NOCT_OK) {
        /* the leaves' near pairs may be half made */
        noct_bp_drop_tree(bp);
        return noct_fail(err, st, -1, 0, "pair search: out of memory");
    }
    noct_pairs_sort_partners(&bp->tested);
    for (size_t i = 0; i < bp->tested.n; ++i) {
        noctProxyPair *q = &bp->tested.p[i];
        q->a.generation = bp->gen[q->a.index];
        q->b.generation = bp->gen[q->b.index];
    }
    const noct_pair_list t = bp->pairs;
    bp->pairs = bp->tested;
    bp->tested = t;
    bp->tested.n = 0;
    noct_bp_end_search(bp);
    ++bp->frame;
    bp->c.pairs += bp->pairs.n;
    return NOCT_OK;
}

size_t noctBroadphasePairs(const noctBroadphase *bp, const noctProxyPair **pairs)
{
    NOCT_REQUIRE(bp != NULL && pairs != NULL);
    drop_removed_pairs(bp);
    *pairs = bp->pairs.p;
    return bp->pairs.n;
}

size_t noctBroadphaseForEachPair(const noctBroadphase *bp, noctPairFcn *fcn, void *context)
{
    NOCT_REQUIRE(bp != NULL && fcn != NULL);
    drop_removed_pairs(bp);
    size_t i = 0;
    while (i < bp->pairs.n) {
        const noctProxyPair *q = &bp->pairs.p[i++];
        if (!fcn(context, q->a, bp->proxy[q->a.index].user, q->b, bp->proxy[q->b.index].user))
            break;
    }
    return i;
}

/* Nodes and leaves under n. */
static void count_nodes(const octNode *n, uint64_t *nodes, uint64_t *leaves)
{
    ++*nodes;
    if (!NOCT_NODE_IS_SPLIT(n)) {
        ++*leaves;
        return;
    }
    for (int i = 0; i < 8; ++i)
        count_nodes(NOCT_NODE_CHILD(n, (octDirection)(OCT_LDB + i)), nodes, leaves);
}

void noctBroadphaseGetCounters(const noctBroadphase *bp, noctBroadphaseCounters *counters)
{
    NOCT_REQUIRE(bp != NULL && counters != NULL);
    *counters = bp->c;
    counters->proxies = bp->alive;
    counters->nodes = counters->leaves = 0;
    if (bp->root != NULL)
        count_nodes(bp->root, &counters->nodes, &counters->leaves);
}

octNode *noctBroadphaseRoot(const noctBroadphase *bp)
{
    NOCT_REQUIRE(bp != NULL);
    return bp->root;
}

void noctBroadphasePrintCell(FILE *strm, const void *data)
{
    NOCT_REQUIRE(strm != NULL && data != NULL);
    const noct_cell *c = data;
    fprintf(strm, "lo (%.10g, %.10g, %.10g) size %.10g", c->lo[0], c->lo[1], c->lo[2],
            c->size);
    if (c->count > 0) {
        fprintf(strm, "; objects");
        for (uint32_t i = 0; i < c->count; ++i)
            fprintf(strm, " %u", c->objs[i]);
    }
}

size_t noctBroadphaseCell(const noctBroadphase *bp, const octNode *node, double lo[3],
                          double *size, noctProxyId *ids, size_t max)
{
    NOCT_REQUIRE(bp != NULL && node != NULL && (ids != NULL || max == 0));
    const noct_cell *c = noct_cell_of(node);
    if (lo != NULL)
        memcpy(lo, c->lo, sizeof c->lo);
    if (size != NULL)
        *size = c->size;
    if (NOCT_NODE_IS_SPLIT(node))
        return 0;
    for (uint32_t i = 0; i < c->count && i < max; ++i)
        ids[i] = (noctProxyId){c->objs[i], bp->gen[c->objs[i]]};
    return c->count;
}

static bool outside_root(const noctBroadphase *bp, const noct_aabb *b)
{
    const noct_aabb r = noct_bp_root_box(bp);
    return !noct_box_within(b, &r);
}

/* ---- validation walk ----------------------------------------------------------- */

#define BAD(...) noct_fail(err, NOCT_ERR_INVARIANT, -1, 0, __VA_ARGS__)

/* The walk's scratch: per proxy, the leaves that list it, and the last
 * leaf (numbered as met) that did, to find a proxy listed twice. */
typedef struct walk {
    size_t *refs;
    size_t *seen;
    size_t leaves;
} walk;

static noctStatus validate_node(const noctBroadphase *bp, octNode *n, walk *v, noctError *err)
{
    const noct_cell *c = noct_cell_of(n);
    if (c == NULL)
        return BAD("a node has no cell");
    if (NOCT_NODE_IS_SPLIT(n)) {
        if (c->count != 0)
            return BAD("an inner node holds proxies");
        bool all_leaves = true;
        for (int i = 0; i < 8; ++i) {
            octNode *k = NOCT_NODE_CHILD(n, (octDirection)(OCT_LDB + i));
            const noct_cell *kc = noct_cell_of(k);
            if (kc == NULL)
                return BAD("a node has no cell");
            if (kc->size != c->size / 2 ||
                kc->lo[0] != c->lo[0] + ((i & 4) ? c->size / 2 : 0) ||
                kc->lo[1] != c->lo[1] + ((i & 2) ? c->size / 2 : 0) ||
                kc->lo[2] != c->lo[2] + ((i & 1) ? c->size / 2 : 0))
                return BAD("child %d's cell does not match its parent's", i);
            if (NOCT_NODE_PARENT(k) != n || octGeneration(k) != octGeneration(n) + 1)
                return BAD("child %d's links are wrong", i);
            noctStatus st = validate_node(bp, k, v, err);
            if (st != NOCT_OK)
                return st;
            all_leaves = all_leaves && !NOCT_NODE_IS_SPLIT(k);
        }
        if (all_leaves && !bp->rebuild_mode && !bp->merge_owed &&
            bp->N != NOCT_N_EXHAUSTIVE) {
            /* distinct proxies among the 8 leaves, counted up to N + 1 */
            ++v->leaves;
            size_t distinct = 0;
            for (int i = 0; i < 8 && distinct <= (size_t)bp->N; ++i) {
                const noct_cell *kc = noct_cell_of(NOCT_NODE_CHILD(n, (octDirection)(OCT_LDB + i)));
                for (uint32_t j = 0; j < kc->count; ++j)
                    if (v->seen[kc->objs[j]] != v->leaves) {
                        v->seen[kc->objs[j]] = v->leaves;
                        ++distinct;
                    }
            }
            if (distinct <= (size_t)bp->N)
                return BAD("siblings at generation %d hold %zu distinct proxies "
                           "(N = %d) but were not merged", octGeneration(n) + 1, distinct,
                           bp->N);
        }
        return NOCT_OK;
    }
    ++v->leaves;
    uint32_t small = 0;
    for (uint32_t j = 0; j < c->count; ++j) {
        uint32_t id = c->objs[j];
        if (id >= bp->nslots || !bp->proxy[id].alive)
            return BAD("a leaf lists a dead proxy %u", id);
        if (v->seen[id] == v->leaves)
            return BAD("a leaf lists proxy %u twice", id);
        v->seen[id] = v->leaves;
        if (!noct_overlaps(&bp->box[id], c))
            return BAD("proxy %u is in a leaf its box does not overlap", id);
        const noct_proxy *o = &bp->proxy[id];
        const uint32_t b = noct_back_of(c)[j];
        if (b >= o->nspans || o->spans[b].leaf != n || o->spans[b].at != j)
            return BAD("proxy %u's entry for a leaf does not point back to it", id);
        small += noct_splits_for(o, c->size);
        ++v->refs[id];
    }
    if (small != c->small)
        return BAD("a leaf counts %u proxies small enough to split for; they are %u",
                   c->small, small);
    if ((int)small > bp->N && noct_may_split(bp, n))
        return BAD("a leaf at generation %d holds %u proxies it could split for (N = %d)",
                   octGeneration(n), small, bp->N);
    return NOCT_OK;
}

/* Count the leaves under n that box o overlaps. */
static size_t overlapped_leaves(const noct_aabb *o, octNode *n)
{
    if (!noct_overlaps(o, noct_cell_of(n)))
        return 0;
    if (!NOCT_NODE_IS_SPLIT(n))
        return 1;
    size_t s = 0;
    for (int i = 0; i < 8; ++i)
        s += overlapped_leaves(o, NOCT_NODE_CHILD(n, (octDirection)(OCT_LDB + i)));
    return s;
}

noctStatus noctBroadphaseValidate(const noctBroadphase *bp, noctError *err)
{
    NOCT_REQUIRE(bp != NULL);
    /* every slot is live or free, none lost */
    for (uint32_t f = 0; f < bp->nfree; ++f)
        if (bp->free_slots[f] >= bp->nslots || bp->proxy[bp->free_slots[f]].alive)
            return BAD("free slot %u is live or beyond the slots", bp->free_slots[f]);
    if (bp->alive + bp->nfree != bp->nslots)
        return BAD("%zu live proxies and %u free slots, but %u slots", bp->alive, bp->nfree,
                   bp->nslots);
    if (bp->root == NULL)
        return bp->alive == 0 || bp->tree_owed ? NOCT_OK : BAD("proxies but no tree");
    if (NOCT_NODE_PARENT(bp->root) != NULL || octGeneration(bp->root) != 0)
        return BAD("the root is not a root");
    const size_t n = bp->nslots ? bp->nslots : 1;
    walk v = {calloc(n, sizeof *v.refs), calloc(n, sizeof *v.seen), 0};
    noctStatus st = NOCT_OK;
    if (v.refs == NULL || v.seen == NULL)
        st = noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    if (st == NOCT_OK)
        st = validate_node(bp, bp->root, &v, err);
    for (uint32_t i = 0; i < bp->nslots && st == NOCT_OK; ++i) {
        const noct_proxy *o = &bp->proxy[i];
        if (!o->alive)
            continue;
        const noct_aabb *b = &bp->box[i];
        const noct_home *h = &bp->home[i];
        if (outside_root(bp, b))
            st = BAD("proxy %u is outside the root", i);
        else if (v.refs[i] != o->nspans)
            st = BAD("proxy %u: %zu leaves list it, its spans count %u", i, v.refs[i],
                     o->nspans);
        else if (overlapped_leaves(b, bp->root) != v.refs[i])
            st = BAD("proxy %u is in %zu leaves but its box overlaps %zu", i, v.refs[i],
                     overlapped_leaves(b, bp->root));
        else if (isfinite(h->lo[0])) {
            noct_home now;
            double size = 0;
            if (o->boxed ? !noct_bp_block_of(bp, i, b, &now, &size) || size != o->block
                         : !noct_bp_home_of(bp, i, b, &now))
                st = BAD("proxy %u has a home block but its leaves have none", i);
            else if (memcmp(&now, h, sizeof now) != 0)
                st = BAD("proxy %u's home block is not that of its leaves", i);
        }
    }
    free(v.refs);
    free(v.seen);
    return st;
}