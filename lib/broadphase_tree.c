/* SPDX-License-Identifier: MIT */
/*
 * The N-objects octree (report sections 2.2-2.3): cells and their pool,
 * split and merge under the overlap rule, building the tree (with the
 * automatic settings), proxies in and out. Its incremental maintenance
 * (report 2.4) is broadphase_maintain.c's.
 *
 * Nodes and cells come eight at a time from a pool of blocks (a split
 * takes one, a merge gives it back), and a cell's lists keep their
 * capacity when its leaf splits or its block goes back: once sizes
 * settle, maintenance allocates nothing.
 */
#include "config.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <noctree/mesh.h>
#include <noctree/neighbor.h>

#include "broadphase_internal.h"

NOCT_DEFINE_GROW(grow_blocks, noct_block *)
NOCT_DEFINE_RESIZE(resize_blocks, noct_block *)
NOCT_DEFINE_GROW(grow_nodes, octNode *)

/* Is object id in leaf c? Whichever of its spans and the leaf's list is
 * shorter is searched, so that neither a crowded leaf nor an object in
 * many leaves makes the question costly. */
static bool leaf_has(const noctBroadphase *bp, const octNode *leaf, uint32_t id)
{
    const noct_cell *c = noct_cell_of(leaf);
    const noct_proxy *o = &bp->proxy[id];
    if (o->nspans <= c->count) {
        for (uint32_t i = 0; i < o->nspans; ++i)
            if (o->spans[i].leaf == leaf)
                return true;
        return false;
    }
    for (uint32_t i = 0; i < c->count; ++i)
        if (c->objs[i] == id)
            return true;
    return false;
}


/* Drop entry s of object id's spans (the leaf's list is the caller's):
 * the last entry takes its place, and its leaf is told. */
static void span_drop(noctBroadphase *bp, uint32_t id, uint32_t s)
{
    noct_proxy *o = &bp->proxy[id];
    noct_forget_home(bp, id);
    NOCT_INVARIANT(s < o->nspans);
    const noct_span last = o->spans[--o->nspans];
    if (s != o->nspans) {
        o->spans[s] = last;
        noct_back_of(noct_cell_of(last.leaf))[last.at] = s;
    }
    noct_apool_shrink(&bp->spans_pool, (void **)&o->spans, &o->capspans, o->nspans);
}

/* The object at position r of leaf c went and the one at position last
 * took its place: r's near pairs go, last's follow it. The other pairs
 * are as far apart as before. */
static void near_leave(noct_cell *c, uint32_t r, uint32_t last)
{
    uint32_t k = 0;
    for (uint32_t i = 0; i < c->nnear; ++i) {
        uint32_t a = c->near[i] & 0xffff, b = c->near[i] >> 16;
        if (a == r || b == r)
            continue;
        a = a == last ? r : a;
        b = b == last ? r : b;
        c->near[k++] = a | b << 16;
    }
    c->nnear = k;
}

/* Room for need objects in leaf c: a list of a larger class from the pool,
 * both halves copied, the old one given back. */
static bool leaf_reserve(noctBroadphase *bp, noct_cell *c, uint32_t need)
{
    if (need <= c->cap)
        return true;
    uint32_t cap;
    uint32_t *q = noct_apool_take(&bp->objs_pool, need, &cap);
    if (q == NULL)
        return false;
    if (c->count > 0) {
        memcpy(q, c->objs, c->count * sizeof *q);
        memcpy(q + cap, c->objs + c->cap, c->count * sizeof *q);
    }
    noct_apool_give(&bp->objs_pool, c->objs, c->cap);
    c->objs = q;
    c->cap = cap;
    return true;
}

/* Give a cell's lists back to the pools. */
static void give_lists(noctBroadphase *bp, noct_cell *c)
{
    noct_apool_give(&bp->objs_pool, c->objs, c->cap);
    noct_apool_give(&bp->near_pool, c->near, c->capnear);
    c->objs = c->near = NULL;
    c->cap = c->capnear = c->count = c->nnear = 0;
}

/* Room for one more span of proxy o, from the pool as leaf_reserve. */
static bool spans_reserve(noctBroadphase *bp, noct_proxy *o)
{
    if (o->nspans < o->capspans)
        return true;
    void *a = o->spans;
    if (!noct_apool_grow(&bp->spans_pool, &a, &o->capspans, o->nspans))
        return false;
    o->spans = a;
    return true;
}

static bool leaf_add(noctBroadphase *bp, octNode *leaf, uint32_t id)
{
    noct_cell *c = noct_cell_of(leaf);
    noct_proxy *o = &bp->proxy[id];
    if (!leaf_reserve(bp, c, c->count + 1) || !spans_reserve(bp, o))
        return false;
    o->spans[o->nspans].leaf = leaf;
    noct_leaf_put(bp, c, c->count++, id, o->nspans++); /* fresh: after c->fresh */
    c->small += noct_splits_for(o, c->size);
    noct_forget_home(bp, id);
    return true;
}

/* ---- split and merge ------------------------------------------------------ */

static bool split_leaf(noctBroadphase *bp, octNode *leaf);

/*
 * Add object id to the leaf, and split it if it now holds more than N
 * objects that a split can separate: objects whose boxes are at most
 * half the leaf's size on every axis (they fit in a child). Objects
 * larger than that are listed but do not count: no split of the leaf
 * can part two of them that overlap it (coincident objects, a pile,
 * faces shared), so splitting for them would only multiply the leaves
 * they are in, down to the maximum depth. So a leaf below the maximum
 * depth holds at most N objects smaller than half its size, and an
 * object is in at most 27 leaves of at least its own extent plus those
 * that splits for smaller objects made.
 */
static bool add_and_split(noctBroadphase *bp, octNode *leaf, uint32_t id)
{
    if (!leaf_add(bp, leaf, id))
        return false;
    noct_cell *c = noct_cell_of(leaf);
    if ((int)c->small > bp->N && noct_may_split(bp, leaf))
        return split_leaf(bp, leaf);
    return true;
}

/* ---- the pool of nodes and cells -------------------------------------------- */

/* A block of eight nodes and cells for a split: a free one, or one of a
 * new chunk of them, half as many as there are already (so that a tree
 * that grows a little past its largest size so far does not allocate
 * again at once). Its cells keep the lists they had, emptied. */
static noct_block *take_block(noctBroadphase *bp)
{
    if (bp->nfree_blocks > 0)
        return bp->free_blocks[--bp->nfree_blocks];
    const size_t k = bp->nblocks / 2 > 16 ? bp->nblocks / 2 : 16;
    if (bp->nblocks + k > bp->capblocks) {
        /* blocks and free_blocks are the two halves of one array, so
         * that giving a block back cannot fail; free_blocks is empty
         * here, so nothing of it moves */
        size_t cap = bp->capblocks ? 2 * bp->capblocks : 32;
        while (cap < bp->nblocks + k)
            cap *= 2;
        if (cap > SIZE_MAX / 2 || !resize_blocks(&bp->blocks, 2 * cap))
            return NULL;
        bp->free_blocks = bp->blocks + cap;
        bp->capblocks = cap;
    }
    if (!grow_blocks(&bp->chunks, &bp->capchunks, bp->nchunks + 1))
        return NULL;
    noct_block *chunk = calloc(k, sizeof *chunk);
    if (chunk == NULL)
        return NULL;
    bp->chunks[bp->nchunks++] = chunk;
    for (size_t i = 0; i < k; ++i)
        bp->blocks[bp->nblocks++] = &chunk[i];
    for (size_t i = k; i-- > 1;)
        bp->free_blocks[bp->nfree_blocks++] = &chunk[i];
    return &chunk[0];
}

static void give_block(noctBroadphase *bp, noct_block *b)
{
    NOCT_INVARIANT(bp->nfree_blocks < bp->nblocks);
    bp->free_blocks[bp->nfree_blocks++] = b;
}

/* Empty a cell (whose lists went back to the pools) for a new node. */
static void reset_cell(noct_cell *c, const double lo[3], double size)
{
    NOCT_INVARIANT(c->objs == NULL && c->near == NULL);
    memcpy(c->lo, lo, sizeof c->lo);
    c->size = size;
    c->count = c->small = c->fresh = c->stamp_obj = c->unlisted = 0;
    c->stamp_step = 0;
    c->budget = 0;
    c->nnear = 0;
}

/* Give the blocks of every node below n (not n's own) back to the pool;
 * n becomes a leaf. */
static void give_back_below(noctBroadphase *bp, octNode *n)
{
    if (!NOCT_NODE_IS_SPLIT(n))
        return;
    for (int i = 0; i < 8; ++i)
        give_back_below(bp, NOCT_NODE_CHILD(n, (octDirection)(OCT_LDB + i)));
    noct_block *b = (noct_block *)noct_oct_unsplit(n);
    for (int i = 0; i < 8; ++i)
        give_lists(bp, &b->cell[i]);
    give_block(bp, b);
}

/* ---- split and merge ---------------------------------------------------------- */

/* Add proxy id to node n, a leaf, or, if an earlier proxy of the same
 * split made it split in turn, to the leaves below it that its box
 * overlaps. */
static bool hand_down(noctBroadphase *bp, octNode *n, uint32_t id)
{
    if (!NOCT_NODE_IS_SPLIT(n))
        return add_and_split(bp, n, id);
    for (int i = 0; i < 8; ++i) {
        octNode *k = NOCT_NODE_CHILD(n, (octDirection)(OCT_LDB + i));
        if (noct_overlaps(&bp->box[id], noct_cell_of(k)) && !hand_down(bp, k, id))
            return false;
    }
    return true;
}

/* Give the leaf 8 children and hand each object to the children its box
 * overlaps (which may split in turn: hand_down). */
static bool split_leaf(noctBroadphase *bp, octNode *leaf)
{
    noct_cell *pc = noct_cell_of(leaf);
    noct_block *b = take_block(bp);
    if (b == NULL)
        return false;
    noct_oct_split_into(leaf, b->node);
    noct_cell *kids = b->cell;
    double half = pc->size / 2;
    for (int i = 0; i < 8; ++i) {
        const double lo[3] = {pc->lo[0] + ((i & 4) ? half : 0),
                              pc->lo[1] + ((i & 2) ? half : 0),
                              pc->lo[2] + ((i & 1) ? half : 0)};
        reset_cell(&kids[i], lo, half);
        octSwapData(&b->node[i], &kids[i]);
        /* a node's generation is its depth: its cell is the root's size
         * halved that many times */
        NOCT_INVARIANT(octGeneration(&b->node[i]) == octGeneration(leaf) + 1 &&
                       ldexp(bp->root_cell.size, -octGeneration(&b->node[i])) == half);
    }
    /* The objects leave the leaf, each by its own entry: no search. The
     * list keeps its memory for a merge back. */
    for (uint32_t j = 0; j < pc->count; ++j)
        span_drop(bp, pc->objs[j], noct_back_of(pc)[j]);
    const uint32_t *objs = pc->objs, count = pc->count;
    pc->count = pc->small = pc->fresh = 0;
    pc->nnear = 0;
    pc->distinct = 0;
    /* Removals below the new children do not count the parent's down. */
    if (NOCT_NODE_PARENT(leaf) != NULL)
        noct_cell_of(NOCT_NODE_PARENT(leaf))->distinct = 0;
    ++bp->c.splits;
    bool ok = true;
    for (uint32_t j = 0; j < count && ok; ++j)
        for (int i = 0; i < 8 && ok; ++i)
            if (noct_overlaps(&bp->box[objs[j]], &kids[i]))
                ok = hand_down(bp, &b->node[i], objs[j]);
    give_lists(bp, pc); /* an inner node holds none */
    return ok;
}

/*
 * If all of p's children are leaves holding N or fewer distinct objects,
 * merge them into p; then try p's parent. Every object leaving a leaf
 * asks, so the count of a node whose children hold too many is kept
 * (cell.distinct): it is taken again only when as many objects have left
 * as it was over N.
 *
 * A merge may need memory for p's list (it keeps the one it had before
 * it split, and grows it by doubling); without it the siblings stay split,
 * which costs pairs but not correctness, and bp->merge_owed makes the next
 * step merge what it can (merge_all). Nothing else here allocates: an
 * object's spans lose the children before they gain p. So a removal
 * cannot fail.
 */
static void try_merge(noctBroadphase *bp, octNode *p, bool up)
{
    while (p != NULL && bp->N != NOCT_N_EXHAUSTIVE) {
        noct_cell *pc = noct_cell_of(p);
        if (pc->distinct > (uint32_t)bp->N)
            return;
        uint32_t distinct = 0;
        noct_bp_new_epoch(bp);
        for (int i = 0; i < 8; ++i) {
            octNode *k = NOCT_NODE_CHILD(p, (octDirection)(OCT_LDB + i));
            if (NOCT_NODE_IS_SPLIT(k))
                return;
            const noct_cell *c = noct_cell_of(k);
            for (uint32_t j = 0; j < c->count; ++j)
                if (bp->mark[c->objs[j]] != bp->epoch) {
                    bp->mark[c->objs[j]] = bp->epoch;
                    ++distinct;
                }
        }
        if (distinct > (uint32_t)bp->N) {
            pc->distinct = distinct;
            return;
        }
        pc->count = 0;
        if (!leaf_reserve(bp, pc, distinct ? distinct : 1)) {
            bp->merge_owed = true;
            return;
        }
        pc->count = pc->small = 0;
        pc->nnear = 0;
        pc->fresh = 0;
        pc->budget = 0;
        noct_bp_new_epoch(bp);
        for (int i = 0; i < 8; ++i) {
            noct_cell *c = noct_cell_of(NOCT_NODE_CHILD(p, (octDirection)(OCT_LDB + i)));
            for (uint32_t j = 0; j < c->count; ++j) {
                const uint32_t id = c->objs[j];
                span_drop(bp, id, noct_back_of(c)[j]);
                if (bp->mark[id] != bp->epoch) {
                    bp->mark[id] = bp->epoch;
                    pc->objs[pc->count++] = id;
                }
            }
        }
        give_back_below(bp, p);
        for (uint32_t j = 0; j < pc->count; ++j) {
            noct_proxy *o = &bp->proxy[pc->objs[j]];
            NOCT_INVARIANT(o->nspans < o->capspans);
            o->spans[o->nspans].leaf = p;
            noct_leaf_put(bp, pc, j, pc->objs[j], o->nspans++);
            pc->small += noct_splits_for(o, pc->size);
        }
        ++bp->c.merges;
        p = up ? NOCT_NODE_PARENT(p) : NULL;
    }
}

void noct_bp_merge_all(noctBroadphase *bp, octNode *n)
{
    if (!NOCT_NODE_IS_SPLIT(n))
        return;
    for (int i = 0; i < 8; ++i)
        noct_bp_merge_all(bp, NOCT_NODE_CHILD(n, (octDirection)(OCT_LDB + i)));
    try_merge(bp, n, false);
}

void noct_bp_leaf_remove_at(noctBroadphase *bp, octNode *leaf, uint32_t i)
{
    noct_cell *c = noct_cell_of(leaf);
    NOCT_INVARIANT(i < c->count);
    const uint32_t id = c->objs[i];
    uint32_t *back = noct_back_of(c);
    /* the proxy is in the leaf it leaves, and its entry says so */
    NOCT_INVARIANT(c->count > 0 && back[i] < bp->proxy[id].nspans &&
                   bp->proxy[id].spans[back[i]].leaf == leaf &&
                   bp->proxy[id].spans[back[i]].at == i);
    span_drop(bp, id, back[i]);
    NOCT_INVARIANT(c->small >= (uint32_t)noct_splits_for(&bp->proxy[id], c->size));
    c->small -= noct_splits_for(&bp->proxy[id], c->size);
    /* The fresh objects stay last: an old one's place goes to the last
     * old one, whose place goes to the last object. */
    const uint32_t last = --c->count;
    if (i < c->fresh) {
        const uint32_t last_old = --c->fresh;
        near_leave(c, i, last_old);
        if (i != last_old)
            noct_leaf_put(bp, c, i, c->objs[last_old], back[last_old]);
        if (last_old != last)
            noct_leaf_put(bp, c, last_old, c->objs[last], back[last]);
    } else if (i != last) {
        noct_leaf_put(bp, c, i, c->objs[last], back[last]);
    }
    /* a list a quarter full moves to a smaller array, if one is free (its
     * two halves move apart: shrink by hand) */
    if (c->cap > bp->objs_pool.base && c->count <= c->cap / 4) {
        uint32_t *q = noct_apool_take_free(&bp->objs_pool, c->cap / 2);
        if (q != NULL) {
            memcpy(q, c->objs, c->count * sizeof *q);
            memcpy(q + c->cap / 2, c->objs + c->cap, c->count * sizeof *q);
            noct_apool_give(&bp->objs_pool, c->objs, c->cap);
            c->objs = q;
            c->cap /= 2;
        }
    }
    ++bp->c.leaves_left;
    octNode *p = NOCT_NODE_PARENT(leaf);
    if (p != NULL && noct_cell_of(p)->distinct > 0)
        --noct_cell_of(p)->distinct;
    try_merge(bp, p, true);
}

bool noct_bp_insert_below(noctBroadphase *bp, octNode *n, uint32_t id, bool push, bool fresh)
{
    if (!noct_overlaps(&bp->box[id], noct_cell_of(n)))
        return true;
    if (NOCT_NODE_IS_SPLIT(n)) {
        for (int i = 0; i < 8; ++i)
            if (!noct_bp_insert_below(bp, NOCT_NODE_CHILD(n, (octDirection)(OCT_LDB + i)), id, push,
                              fresh))
                return false;
        return true;
    }
    if (!fresh && leaf_has(bp, n, id))
        return true;
    ++bp->c.leaves_entered;
    if (push) {
        if (!grow_nodes(&bp->work, &bp->capwork, bp->capwork > 0 ? bp->nwork + 1 : 64))
            return false;
        bp->work[bp->nwork++] = n;
    }
    return add_and_split(bp, n, id);
}

/* ---- building the tree ---------------------------------------------------------- */

/* Give the tree's blocks back to the pool; the root's node and cell stay
 * for the next tree. */
static void destroy_tree(noctBroadphase *bp)
{
    if (bp->root == NULL)
        return;
    give_back_below(bp, bp->root);
    give_lists(bp, &bp->root_cell);
    bp->root_cell.small = 0;
    bp->root = NULL;
    for (uint32_t i = 0; i < bp->nslots; ++i) {
        bp->proxy[i].nspans = 0;
        noct_forget_home(bp, i);
    }
}

/* Tear the tree down after a failure left it inconsistent; the next step
 * or addition builds it again (rebuild). */
void noct_bp_drop_tree(noctBroadphase *bp)
{
    destroy_tree(bp);
    bp->owed_reach = 0; /* (no leaf is left to owe it to) */
    bp->tree_owed = bp->alive > 0;
    bp->merge_owed = false;
}

/* Build the tree afresh around every live object: a root cube whose size
 * is a power of two at least twice the objects' extent (and at least
 * min_size). Its corner is the largest point of the lattice (m + s) h
 * (h half the size, m an integer) at or below the objects' low corner, so
 * the root contains them all. The shift s, a 20-bit binary fraction, moves
 * cell boundaries off the round coordinates scenes like to use (a grid of
 * objects at integer positions would otherwise straddle boundaries
 * everywhere and miss the fast path) while every cell corner stays an
 * exact dyadic number. No single shift suits every scale, so rebuild tries
 * a few and keeps the one with which the fewest objects straddle the
 * boundaries of cells about twice their typical size. */
static const double ROOT_SHIFTS[] = {347127.0 / 1048576.0, 611953.0 / 1048576.0,
                                     95349.0 / 1048576.0, 869381.0 / 1048576.0};

/* The root corner on the lattice (m + s) h at or below lo. */
static void root_corner(const double lo[3], const double hi[3], double size, double s,
                        double corner[3])
{
    for (int k = 0; k < 3; ++k) {
        /* lo - h < corner <= lo, so corner + 2 h > lo + h >= hi. The
         * lattice point is exact while |m| < 2^32; beyond that (objects
         * very far from the origin for their size) fall back to m h. */
        double h = size / 2, m = floor(lo[k] / h - s);
        corner[k] = fabs(m) < 0x1p32 ? (m + s) * h : floor(lo[k] / h) * h;
        if (corner[k] > lo[k] || corner[k] + size < hi[k])
            corner[k] = floor(lo[k] / h) * h; /* a rounding safeguard */
    }
}

/* Of a sample of the objects, how many straddle a boundary of the cells
 * of size c laid from corner? */
static size_t straddling(const noctBroadphase *bp, const double corner[3], double c,
                         uint32_t stride)
{
    size_t n = 0;
    for (uint32_t i = 0; i < bp->nslots; i += stride) {
        if (!bp->proxy[i].alive)
            continue;
        const noct_aabb *o = &bp->box[i];
        for (int k = 0; k < 3; ++k)
            if (floor((o->lo[k] - corner[k]) / c) != floor((o->hi[k] - corner[k]) / c)) {
                ++n;
                break;
            }
    }
    return n;
}
/*
 * The automatic settings (broadphase.h, "Settings"), chosen for a root of
 * the given size from the live proxies, or from a sample of about 4096 of
 * them (every stride-th slot): a pure function of the boxes in the slots.
 *
 * A proxy of extent e (its box's largest side) can make a leaf split only
 * while it is at most half the leaf's size, so the deepest leaves it can
 * bring about are at generation D(e) = 1 + max{d : e <= size 2^-(d+1)}
 * (40 for a point). max_depth is D at the 99th percentile of the sample,
 * from the small end: deep enough that 99 in 100 proxies never meet it,
 * shallow enough that coincident proxies cannot split the cells far below
 * their own size. N is NOCT_AUTO_N, whatever the scene: the sweep in
 * docs/results.md found it within the noise of the best N on every family
 * and size, and the lowest in memory.
 */
static void choose_settings(noctBroadphase *bp, double size)
{
    bp->chosen_for = bp->alive;
    if (bp->auto_N)
        bp->N = NOCT_AUTO_N;
    if (!bp->auto_depth)
        return;
    uint32_t hist[41] = {0}, counted = 0;
    const uint32_t stride = bp->nslots > 4096 ? bp->nslots / 4096 : 1;
    for (uint32_t i = 0; i < bp->nslots; i += stride) {
        if (!bp->proxy[i].alive)
            continue;
        const noct_aabb *o = &bp->box[i];
        const double e =
            noct_max(noct_max(o->hi[0] - o->lo[0], o->hi[1] - o->lo[1]), o->hi[2] - o->lo[2]);
        int d = 0; /* 1 + the deepest generation whose half-size is >= e */
        for (double half = size / 2; d < 40 && e <= half; half /= 2)
            ++d;
        ++hist[d];
        ++counted;
    }
    /* the depth that all but the smallest 1 in 100 stay within */
    const uint64_t keep = counted - counted / 100;
    uint64_t seen = 0;
    int depth = 0;
    while (depth < 40 && seen + hist[depth] < keep)
        seen += hist[depth++];
    bp->max_depth = depth < 1 ? 1 : depth;
}

static noctStatus build_tree(noctBroadphase *bp, double min_size)
{
    destroy_tree(bp);
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    bool any = false;
    for (uint32_t i = 0; i < bp->nslots; ++i) {
        if (!bp->proxy[i].alive)
            continue;
        const noct_aabb *o = &bp->box[i];
        for (int k = 0; k < 3; ++k) {
            lo[k] = any ? noct_min(lo[k], o->lo[k]) : o->lo[k];
            hi[k] = any ? noct_max(hi[k], o->hi[k]) : o->hi[k];
        }
        any = true;
    }
    for (int k = 0; k < 3 && bp->hint; ++k) {
        lo[k] = any ? noct_min(lo[k], bp->bounds_lo[k]) : bp->bounds_lo[k];
        hi[k] = any ? noct_max(hi[k], bp->bounds_hi[k]) : bp->bounds_hi[k];
    }
    double extent = noct_max(noct_max(hi[0] - lo[0], hi[1] - lo[1]), hi[2] - lo[2]);
    /* Far from the origin the root is no finer than NOCT_CELL_RESOLUTION
     * allows (twice over, so that it may split once), which also keeps
     * root_corner's lattice index below 2^31. */
    double far = 0;
    for (int k = 0; k < 3; ++k)
        far = noct_max(far, noct_max(fabs(lo[k]), fabs(hi[k])));
    min_size = noct_max(min_size, 4 * NOCT_CELL_RESOLUTION * far);
    double size = 1;
    while (size < 2 * extent || size < min_size)
        size *= 2;
    while (size / 2 >= 2 * extent && size / 2 >= min_size && size > 0x1p-40)
        size /= 2; /* the smallest power of two >= 2 extent (and min_size) */
    if (bp->root_node == NULL) {
        bp->root_node = octCreate();
        if (bp->root_node == NULL)
            return NOCT_ERR_NOMEM;
        octSwapData(bp->root_node, &bp->root_cell);
    }
    noct_cell *rc = &bp->root_cell;
    const double zero[3] = {0, 0, 0};
    reset_cell(rc, zero, size);
    choose_settings(bp, size);
    /* Cells about twice the objects' mean size (a sample of at most about
     * 4096 objects), and the shift that makes the fewest straddle them. */
    uint32_t stride = bp->nslots > 4096 ? bp->nslots / 4096 : 1;
    double mean = 0;
    size_t counted = 0;
    for (uint32_t i = 0; i < bp->nslots; i += stride)
        if (bp->proxy[i].alive) {
            const noct_aabb *o = &bp->box[i];
            mean += noct_max(noct_max(o->hi[0] - o->lo[0], o->hi[1] - o->lo[1]),
                             o->hi[2] - o->lo[2]);
            ++counted;
        }
    double c = size;
    if (counted > 0)
        while (c / 2 >= 2 * (mean / (double)counted) && c > size * 0x1p-30)
            c /= 2;
    size_t best = SIZE_MAX;
    for (size_t i = 0; i < sizeof ROOT_SHIFTS / sizeof *ROOT_SHIFTS; ++i) {
        double corner[3];
        root_corner(lo, hi, size, ROOT_SHIFTS[i], corner);
        size_t n = counted > 0 ? straddling(bp, corner, c, stride) : 0;
        if (n < best) {
            best = n;
            memcpy(rc->lo, corner, sizeof corner);
        }
    }
    bp->root = bp->root_node;
    ++bp->c.rebuilds;
    for (uint32_t i = 0; i < bp->nslots; ++i)
        if (bp->proxy[i].alive && !noct_bp_insert_below(bp, bp->root, i, false, true))
            return NOCT_ERR_NOMEM;
    return NOCT_OK;
}

/*
 * Build the tree afresh (build_tree). A tree that a failure left half
 * built, or half changed by a failed insertion, split or step, is torn
 * down instead: the world then has no tree, bp->tree_owed says so, and the
 * next noctWorldAdd() or noctWorldStep() builds it before anything else.
 */
noctStatus noct_bp_rebuild(noctBroadphase *bp, double min_size)
{
    noctStatus st = build_tree(bp, min_size);
    if (st != NOCT_OK)
        noct_bp_drop_tree(bp);
    else
        bp->tree_owed = bp->merge_owed = false;
    /* (every leaf is new: its first search sweeps it) */
    bp->owed_reach = 0;
    return st;
}

/* The root's cube as a box; everything when there is no tree yet. */
noct_aabb noct_bp_root_box(const noctBroadphase *bp)
{
    noct_aabb r = {{-INFINITY, -INFINITY, -INFINITY}, {INFINITY, INFINITY, INFINITY}};
    if (bp->root != NULL) {
        const noct_cell *rc = noct_cell_of(bp->root);
        for (int k = 0; k < 3; ++k) {
            r.lo[k] = rc->lo[k];
            r.hi[k] = rc->lo[k] + rc->size;
        }
    }
    return r;
}

static bool inside_root(const noctBroadphase *bp, const noct_aabb *o)
{
    const noct_aabb r = noct_bp_root_box(bp);
    return noct_box_within(o, &r);
}

/* ---- proxies in and out, and the end --------------------------------------------- */

noctStatus noct_bp_insert(noctBroadphase *bp, uint32_t id)
{
    if (bp->root == NULL || !inside_root(bp, &bp->box[id]))
        return noct_bp_rebuild(bp, bp->root ? 2 * noct_cell_of(bp->root)->size : 0);
    if (!noct_bp_insert_below(bp, bp->root, id, false, true)) {
        noct_bp_drop_tree(bp); /* a split may have failed halfway */
        return NOCT_ERR_NOMEM;
    }
    return NOCT_OK;
}

void noct_bp_unlink(noctBroadphase *bp, uint32_t id)
{
    noct_proxy *o = &bp->proxy[id];
    while (o->nspans > 0)
        noct_bp_leaf_remove_at(bp, o->spans[0].leaf, o->spans[0].at);
}

/* A proxy's box changed size: the leaves it is in count it again among
 * the proxies small enough to split for, and split if they now hold too
 * many. Its new local box is mlo, mhi. */
bool noct_bp_reshape(noctBroadphase *bp, uint32_t id, const double mlo[3], const double mhi[3])
{
    noct_proxy *o = &bp->proxy[id];
    for (uint32_t s = 0; s < o->nspans; ++s) {
        noct_cell *c = noct_cell_of(o->spans[s].leaf);
        NOCT_INVARIANT(c->small >= (uint32_t)noct_splits_for(o, c->size));
        c->small -= noct_splits_for(o, c->size);
    }
    memcpy(o->mlo, mlo, sizeof o->mlo);
    memcpy(o->mhi, mhi, sizeof o->mhi);
    for (uint32_t s = 0; s < o->nspans; ++s) {
        noct_cell *c = noct_cell_of(o->spans[s].leaf);
        c->small += noct_splits_for(o, c->size);
    }
    for (uint32_t s = 0; s < o->nspans; ++s) {
        octNode *leaf = o->spans[s].leaf;
        if ((int)noct_cell_of(leaf)->small > bp->N && noct_may_split(bp, leaf)) {
            if (!split_leaf(bp, leaf))
                return false;
            s = UINT32_MAX; /* the split rewrote the list: again */
        }
    }
    return true;
}

void noct_bp_free_tree(noctBroadphase *bp)
{
    destroy_tree(bp);
    /* every list is back in its pool (noct_bp_fini frees them) */
    for (size_t i = 0; i < bp->nchunks; ++i)
        free(bp->chunks[i]);
    free(bp->chunks);
    bp->chunks = NULL;
    bp->nchunks = bp->capchunks = 0;
    free(bp->blocks);
    bp->blocks = bp->free_blocks = NULL;
    bp->nblocks = bp->capblocks = bp->nfree_blocks = 0;
    if (bp->root_node != NULL) {
        octSwapData(bp->root_node, NULL);
        octDispose(bp->root_node);
    }
    bp->root_node = NULL;
}
