/* SPDX-License-Identifier: MIT */
/*
 * Private: the broadphase's structures, shared by its files; the world,
 * its client, reads and writes it through the accessors below and the
 * noct_bp_* calls only (its motion loop moves proxies in bulk: it writes
 * the placed boxes and runs the fast test itself). Never installed.
 *
 *   broadphase.c        the public API: proxies, filters, pairs, counters,
 *                       validation, octree access
 *   broadphase_tree.c   cells and their pool, split and merge, building
 *                       the tree (the automatic settings), proxies in and
 *                       out
 *   broadphase_maintain.c  incremental maintenance: the fast test, the
 *                       leave and enter checks, the root's growth
 *   broadphase_pairs.c  the pair search: sweeps, near pairs, ownership of
 *                       pairs, filters, sorting
 *   broadphase_query.c  box, point and segment queries
 *
 * Every node's datum is a cell: its cube (lo, size) and, for a leaf, the
 * proxies whose boxes overlap it. Every proxy keeps the list of leaves it
 * is in (its spans), and each leaf where each of its proxies lists it, so
 * that removals need no search. Cells are closed for overlap (touching
 * counts) and half-open for ownership of a point ([lo, lo + size), closed
 * at the root's upper faces).
 */
#ifndef NOCT_LIB_BROADPHASE_INTERNAL_H
#define NOCT_LIB_BROADPHASE_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <noctree/broadphase.h>

#include "array.h"
#include "internal.h"
#include "pool.h"

typedef struct noct_cell {
    double lo[3];
    double size;
    uint32_t *objs;      /* leaf: proxies overlapping the cell, then
                            (noct_back_of) where each one's spans list the
                            leaf: 2 cap entries, from objs_pool. Given
                            back when the leaf splits or its block goes
                            back to the pool. */
    uint32_t count, cap;
    uint32_t small;      /* leaf: proxies small enough to split for */
    uint32_t stamp_obj;  /* enter check: last (proxy, clock) that queried */
    uint32_t fresh;      /* objs[fresh, count) came since the near pairs */
    uint32_t unlisted;   /* leaf: sweeps left that keep no near pairs
                            (the last list grew too long); in the
                            padding before stamp_step */
    uint64_t stamp_step; /* this node as a neighbor */
    /* Leaf, from its last sweep: every pair of its boxes not in near was
     * at least budget apart (on some axis) then, less twice the reach of
     * each search since, but for the pairs of the fresh proxies, which the
     * next search adds. near holds the pairs that were closer, as
     * positions in objs (low and high 16 bits). */
    union {
        double budget;
        /* Node whose children are leaves: they hold at least this many
         * distinct proxies (0: unknown). Proxies leaving them count it
         * down, one each; more coming cannot make it wrong. */
        uint32_t distinct;
    };
    uint32_t *near;
    uint32_t nnear, capnear;
} noct_cell;

/* Does leaf c own point p: [lo, lo + size) per axis, closed at the root's
 * upper faces? (The ownership rule: the pair search, the queries and the
 * margin's candidates hand a pair or a box to the one leaf owning a
 * point of it.) */
static inline bool noct_cell_owns(const noct_cell *c, const noct_cell *root,
                                  const double p[3])
{
    for (int k = 0; k < 3; ++k) {
        const double hi = c->lo[k] + c->size;
        if (p[k] < c->lo[k] || p[k] > hi)
            return false;
        if (p[k] == hi && hi != root->lo[k] + root->size)
            return false;
    }
    return true;
}

/* An axis-aligned box, closed. */
typedef struct noct_aabb {
    double lo[3], hi[3];
} noct_aabb;

/*
 * A proxy's home block, as the positions that keep its box in it (for
 * the public API's proxies, the block itself: noct_proxy.boxed). The
 * block is the block of cells of its smallest leaf's size, on that
 * leaf's lattice, that its box overlaps, with the high side of the first
 * column and the low side of the last on each axis; a box inside it
 * overlaps the same cells, so its leaves are unchanged. lo[0] = +inf when
 * there is none. See noct_bp_home_of().
 */
typedef struct noct_home {
    double lo[3], hi[3];
} noct_home;

/* A leaf a proxy is in, and where the leaf lists it: objs[at]. */
typedef struct noct_span {
    octNode *leaf;
    uint32_t at;
} noct_span;

typedef struct noct_proxy {
    /* The box relative to a position: the placed box is
     * [fl(mlo + p), fl(mhi + p)]. The world's proxies keep their mesh's
     * box here and move by position; the public API's have position 0. */
    double mlo[3], mhi[3];
    /* Next to them, what a move reads and writes, so that a move the
     * fast test settles touches the proxy at one place. */
    double travel;        /* how far its box moved since the last pair
                             search, on an axis (public moves, teleports) */
    /* The search that travel counts from, its low 32 bits: after 2^32
     * searches a stale count may be taken for this one's, which only
     * makes the search's reach larger (safe), never smaller. */
    uint32_t travel_epoch;
    bool alive;
    bool entering;        /* maintenance: needs the enter phase */
    bool boxed;           /* a public proxy: home holds its block in box
                             space (noct_bp_block_of), of cells of size
                             block, while it is finite */
    noct_aabb old;        /* the placed box before the last move */
    noct_span *spans;     /* leaves it is in */
    uint32_t nspans, capspans;
    double block;
    uint64_t category, mask;
    void *user;
} noct_proxy;

/* A list of pairs of proxies. */
typedef struct noct_pair_list {
    noctProxyPair *p;
    size_t n, cap;
} noct_pair_list;

/* A leaf's boxes, gathered for the sweep so that it reads one array. */
typedef struct noct_leaf_box {
    double lo[3], hi[3];
    uint32_t id;
} noct_leaf_box;

/* Eight sibling nodes and their cells: what a split takes from the pool
 * and a merge gives back. */
typedef struct noct_block {
    octNode node[8];
    noct_cell cell[8];
} noct_block;

struct noctBroadphase {
    int N, max_depth;         /* in force: as given, or as chosen */
    bool auto_N, auto_depth;  /* chosen at every build (choose_settings) */
    size_t chosen_for;        /* live proxies at the last choice */
    bool hint;                /* bounds_lo/hi hold a hint for the root */
    double bounds_lo[3], bounds_hi[3];
    bool rebuild_mode;        /* the world rebuilds every step: the tree
                                 holds no merge invariant */
    noct_proxy *proxy;
    /* Per slot, beside proxy, so that the world's per-step loops read
     * small contiguous records: the placed box and the home block. */
    noct_aabb *box;
    noct_home *home;
    uint32_t *gen;            /* per slot: its handles' generation */
    uint32_t *mark;           /* per slot: epoch stamp for distinct counts
                                 (noct_bp_new_epoch) */
    uint32_t epoch;
    uint32_t nslots, capslots;
    uint32_t *free_slots;     /* room for capslots: removal cannot fail */
    uint32_t nfree;
    size_t alive;
    size_t filtered;          /* live proxies whose filter is not all bits */
    octNode *root;            /* NULL while there is no tree */
    octNode *root_node;       /* the root's node, kept between trees */
    noct_cell root_cell;
    bool merge_owed;          /* a merge lacked memory: merge_all() owed */
    bool tree_owed;           /* a failure tore the tree down */
    uint64_t frame;           /* world sub-steps and public pair searches */
    uint64_t shrink_from;     /* the first frame the root may shrink at */
    uint64_t clock;           /* the enter check's stamps: one tick per
                                 world sub-step or public move */
    /* The pool: every block made, and the free ones (room for all);
     * blocks are made in chunks. */
    noct_block **blocks, **free_blocks;
    size_t nblocks, capblocks, nfree_blocks;
    noct_block **chunks;
    size_t nchunks, capchunks;
    /* The leaves' lists (2 cap entries), their near pairs and the
     * proxies' spans, pooled by size. */
    noct_apool objs_pool, near_pool, spans_pool;
    octNode **work;           /* enter check's worklist */
    size_t nwork, capwork;
    noct_leaf_box *gather;    /* pair search scratch */
    size_t capgather;
    double reach;             /* this search: how far any box may have
                                 moved on an axis since the last, rounding
                                 included */
    double owed_reach;        /* the reach of the frames whose pairs the
                                 world found without a search
                                 (noct_bp_skip_search), which the next
                                 search adds to its own */
    noct_pair_list tested;    /* the pair search's pairs */
    noctProxyPair *sorted;    /* radix sort scratch */
    size_t capsorted;
    uint32_t *digits;
    size_t capdigits;
    noct_pair_list pairs;     /* public: the last noctBroadphaseUpdatePairs */
    bool pairs_removed;       /* public: proxies were removed since, whose
                                 pairs the next read drops */
    uint64_t search_epoch;    /* public: searches made */
    double pending_reach;     /* public: the largest travel since then */
    noctBroadphaseCounters c;
};

/*
 * What the broadphase's client (the world) reads and writes of it: these
 * accessors, never the fields. The slots (live or free) are 0 to
 * noct_bp_slots(); the per-slot arrays (boxes, homes, proxies) are for
 * the motion's bulk loop, which places boxes and runs the fast test
 * itself.
 */
static inline uint32_t noct_bp_slots(const noctBroadphase *bp) { return bp->nslots; }
static inline uint32_t noct_bp_capacity(const noctBroadphase *bp) { return bp->capslots; }
static inline uint32_t noct_bp_free_slots(const noctBroadphase *bp) { return bp->nfree; }
static inline size_t noct_bp_live(const noctBroadphase *bp) { return bp->alive; }
static inline uint32_t noct_bp_generation(const noctBroadphase *bp, uint32_t s)
{
    return bp->gen[s];
}
static inline noct_aabb *noct_bp_box(const noctBroadphase *bp, uint32_t s)
{
    return &bp->box[s];
}
static inline noct_proxy *noct_bp_proxy(const noctBroadphase *bp, uint32_t s)
{
    return &bp->proxy[s];
}
static inline noct_aabb *noct_bp_boxes(const noctBroadphase *bp) { return bp->box; }
static inline noct_home *noct_bp_homes(const noctBroadphase *bp) { return bp->home; }
static inline noct_proxy *noct_bp_proxies(const noctBroadphase *bp) { return bp->proxy; }
static inline octNode *noct_bp_root(const noctBroadphase *bp) { return bp->root; }
static inline bool noct_bp_tree_owed(const noctBroadphase *bp) { return bp->tree_owed; }
static inline const noctBroadphaseCounters *noct_bp_counters(const noctBroadphase *bp)
{
    return &bp->c;
}
/* The leaves live proxy s is in (the k-th of noct_bp_leaf_count()), for
 * a client that reads their cubes (lo, size) and lists (objs, count) as
 * they are between searches; 0 leaves when there is no exact tree. */
static inline uint32_t noct_bp_leaf_count(const noctBroadphase *bp, uint32_t s)
{
    return bp->tree_owed ? 0 : bp->proxy[s].nspans;
}
static inline const struct noct_cell *noct_bp_leaf(const noctBroadphase *bp, uint32_t s,
                                                   uint32_t k)
{
    return NOCT_NODE_DATA(bp->proxy[s].spans[k].leaf);
}
/* Has any live proxy a filter that is not all bits (else every pair
 * passes noct_filters_pass())? */
static inline bool noct_bp_any_filter(const noctBroadphase *bp) { return bp->filtered > 0; }
/* Does the pair search test every pair of a leaf (N big: the report's
 * exhaustive algorithm)? */
static inline bool noct_bp_exhaustive(const noctBroadphase *bp)
{
    return bp->N == NOCT_N_EXHAUSTIVE;
}
/* The per-slot stamps, for a use that starts with noct_bp_new_epoch(). */
static inline uint32_t *noct_bp_marks(const noctBroadphase *bp) { return bp->mark; }
/* The client rebuilds the tree every step: no merge invariant is kept. */
static inline void noct_bp_set_rebuild_mode(noctBroadphase *bp, bool on)
{
    bp->rebuild_mode = on;
}

/* The automatic settings (broadphase.h, "Settings"): N, and how many
 * proxies, as a factor of those the settings were chosen for, make them
 * be chosen again (a rebuild), either way. */
#define NOCT_AUTO_N 128
#define NOCT_AUTO_RECHOOSE 4

/* Whether the population moved far enough from the one the automatic
 * settings were chosen for that the next settle should build again. */
static inline bool noct_bp_choice_stale(const noctBroadphase *bp)
{
    return (bp->auto_N || bp->auto_depth) && bp->root != NULL &&
           (bp->alive > NOCT_AUTO_RECHOOSE * bp->chosen_for ||
            bp->alive * NOCT_AUTO_RECHOOSE < bp->chosen_for);
}

/* ---- small helpers, inlined on the hot paths --------------------------------- */

static inline noct_cell *noct_cell_of(const octNode *n)
{
    return NOCT_NODE_DATA(n);
}

/* objs[i]'s entry in its spans for leaf c is noct_back_of(c)[i]. */
static NOCT_ALWAYS_INLINE uint32_t *noct_back_of(const noct_cell *c)
{
    return c->objs + c->cap;
}

static inline bool noct_overlaps(const noct_aabb *b, const noct_cell *c)
{
    for (int k = 0; k < 3; ++k)
        if (b->hi[k] < c->lo[k] || b->lo[k] > c->lo[k] + c->size)
            return false;
    return true;
}

/* Box o lies in the closed box r. */
static inline bool noct_box_within(const noct_aabb *o, const noct_aabb *r)
{
    return o->lo[0] >= r->lo[0] && o->lo[1] >= r->lo[1] && o->lo[2] >= r->lo[2] &&
           o->hi[0] <= r->hi[0] && o->hi[1] <= r->hi[1] && o->hi[2] <= r->hi[2];
}

/* Are the leaves of a proxy at position p still those of its home block
 * (the report's fast test, for a box in one leaf or several)? */
static NOCT_ALWAYS_INLINE bool noct_inside_home(const double p[3], const noct_home *h)
{
    return p[0] >= h->lo[0] && p[0] <= h->hi[0] && p[1] >= h->lo[1] && p[1] <= h->hi[1] &&
           p[2] >= h->lo[2] && p[2] <= h->hi[2];
}

static inline void noct_forget_home(noctBroadphase *bp, uint32_t id)
{
    bp->home[id].lo[0] = INFINITY;
}

/* The placed box: exactly the narrowphase's [fl(lo + t), fl(hi + t)]. */
static NOCT_ALWAYS_INLINE void noct_place_box(const double mlo[3], const double mhi[3],
                                              const double pos[3], noct_aabb *b)
{
    b->lo[0] = mlo[0] + pos[0];
    b->lo[1] = mlo[1] + pos[1];
    b->lo[2] = mlo[2] + pos[2];
    b->hi[0] = mhi[0] + pos[0];
    b->hi[1] = mhi[1] + pos[1];
    b->hi[2] = mhi[2] + pos[2];
}

/* Put object id, whose spans entry for this leaf is s, at position i of
 * the leaf's list, and tell the entry. */
static NOCT_ALWAYS_INLINE void noct_leaf_put(noctBroadphase *bp, noct_cell *c, uint32_t i, uint32_t id,
                                        uint32_t s)
{
    c->objs[i] = id;
    noct_back_of(c)[i] = s;
    bp->proxy[id].spans[s].at = i;
}

/* The entry of object id's spans for the leaf whose cell is c (a search
 * of its few spans, for the objects a sweep moved in the leaf's list). */
static inline uint32_t noct_span_of(const noctBroadphase *bp, uint32_t id, const noct_cell *c)
{
    const noct_proxy *o = &bp->proxy[id];
    for (uint32_t s = 0;; ++s) {
        NOCT_INVARIANT(s < o->nspans);
        if (noct_cell_of(o->spans[s].leaf) == c)
            return s;
    }
}

/* Is object o one that a split of a cell of this size can separate from
 * others: is its box at most half the size on every axis, so that it fits
 * in a child? See add_and_split. */
static inline bool noct_splits_for(const noct_proxy *o, double size)
{
    const double h = size / 2;
    return o->mhi[0] - o->mlo[0] <= h && o->mhi[1] - o->mlo[1] <= h &&
           o->mhi[2] - o->mlo[2] <= h;
}

/* The finest cell, relative to its coordinates: a cell's size is at least
 * NOCT_CELL_RESOLUTION times the largest magnitude of its corners'
 * coordinates (2^20 ulps of them), so that far from the origin no split
 * makes a cell whose corners round together or onto its parent's, and
 * every corner stays exact (the root's shift has 20 bits below its half
 * size, which is at most 2^31 of its coordinates: 20 + 31 + 1 < 53 bits).
 * A leaf at that size stays a leaf whatever it holds, as at the maximum
 * depth. */
#define NOCT_CELL_RESOLUTION 0x1p-32

/* The largest magnitude of a coordinate of a cube's corners. */
static inline double noct_cube_magnitude(const double lo[3], double size)
{
    double m = 0;
    for (int k = 0; k < 3; ++k)
        m = noct_max(m, noct_max(fabs(lo[k]), fabs(lo[k] + size)));
    return m;
}

/* May this leaf split if it holds more than N proxies it could split
 * for: is it above the maximum depth, and are its children no finer than
 * NOCT_CELL_RESOLUTION allows? */
static inline bool noct_may_split(const noctBroadphase *bp, const octNode *leaf)
{
    const noct_cell *c = noct_cell_of(leaf);
    return octGeneration(leaf) < bp->max_depth &&
           c->size / 2 >= NOCT_CELL_RESOLUTION * noct_cube_magnitude(c->lo, c->size);
}

/* Worlds from this many slots on prefetch what their loops will read:
 * below it, it stays in cache. */
#define PREFETCH_OBJECTS 8192

/* Does this pair pass the filters? */
static NOCT_ALWAYS_INLINE bool noct_filters_pass(const noct_proxy *a, const noct_proxy *b)
{
    return (a->category & b->mask) != 0 && (b->category & a->mask) != 0;
}

/* Append p to l, doubling; false without memory. */
bool noct_pairs_grow(noct_pair_list *l);
static NOCT_ALWAYS_INLINE bool noct_pairs_push(noct_pair_list *l, noctProxyPair p)
{
    if (l->n == l->cap && !noct_pairs_grow(l))
        return false;
    l->p[l->n++] = p;
    return true;
}

/* Order of pairs by (a.index, b.index). */
static inline int noct_pair_order(const noctProxyPair *a, const noctProxyPair *b)
{
    if (a->a.index != b->a.index)
        return a->a.index < b->a.index ? -1 : 1;
    return (a->b.index > b->b.index) - (a->b.index < b->b.index);
}

/* ---- broadphase.c ---------------------------------------------------------------- */

/* Set up an empty broadphase in place (the world embeds one); check def. */
noctStatus noct_bp_init(noctBroadphase *bp, const noctBroadphaseDef *def, noctError *err);

/* Free what an initialised broadphase holds (not bp itself). */
void noct_bp_fini(noctBroadphase *bp);

/* Room for more proxies without growing the per-slot arrays again;
 * false without memory or past 2^31 slots. */
bool noct_bp_reserve(noctBroadphase *bp, uint32_t more);

/* A slot for a new proxy, or UINT32_MAX (no memory, or 2^31 slots). */
uint32_t noct_bp_new_slot(noctBroadphase *bp);

/* Give back slot s from noct_bp_new_slot that never became live, as it
 * is (a new last slot goes altogether: a client's per-slot arrays may not
 * reach it); cannot fail. */
void noct_bp_unuse_slot(noctBroadphase *bp, uint32_t s);

/* Make slot s a live proxy with local box mlo, mhi at position pos and
 * put it in the tree; on failure (NOMEM) the slot is free again. */
noctStatus noct_bp_add(noctBroadphase *bp, uint32_t s, const double mlo[3], const double mhi[3],
                       const double pos[3], void *user, uint64_t category, uint64_t mask);

/* Give live proxy s the local box mlo, mhi at position pos, keeping the
 * tree exact at once; on failure (NOMEM) it keeps its old box and the
 * tree is owed. */
noctStatus noct_bp_move_to(noctBroadphase *bp, uint32_t s, const double mlo[3],
                           const double mhi[3], const double pos[3]);

/* A world object's move to position pos with its local box unchanged,
 * when the fast test settles it (pos inside its home, which is in
 * position space for world objects only: its leaves stay the same): the
 * box placed, the travel counted; false, with nothing changed, when the
 * move needs noct_bp_move_to(). It reads the proxy's first line (its
 * local box and travel) and its home and box, nothing else. */
static inline bool noct_bp_move_fast(noctBroadphase *bp, uint32_t s, const double pos[3])
{
    noct_proxy *o = &bp->proxy[s];
    if (bp->root == NULL || !noct_inside_home(pos, &bp->home[s]))
        return false; /* (no home: lo is +inf, and no position is inside) */
    noct_aabb nb;
    noct_place_box(o->mlo, o->mhi, pos, &nb);
    const noct_aabb *old = &bp->box[s];
    double d = 0;
    for (int k = 0; k < 3; ++k)
        d = noct_max(d, noct_max(fabs(nb.lo[k] - old->lo[k]), fabs(nb.hi[k] - old->hi[k])));
    if (o->travel_epoch != (uint32_t)bp->search_epoch) {
        o->travel = 0;
        o->travel_epoch = (uint32_t)bp->search_epoch;
    }
    o->travel += d;
    bp->pending_reach = noct_max(bp->pending_reach, o->travel);
    bp->box[s] = nb;
    ++bp->c.moves;
    ++bp->c.inside_fast;
    return true;
}

/* A new epoch for the per-slot stamps in bp->mark, that no stamp holds:
 * when the count wraps (once in 2^32 uses) every stamp goes back to 0. */
static inline uint32_t noct_bp_new_epoch(noctBroadphase *bp)
{
    if (++bp->epoch == 0) {
        memset(bp->mark, 0, bp->nslots * sizeof *bp->mark);
        bp->epoch = 1;
    }
    return bp->epoch;
}

/* Take live proxy s out of the tree and free its slot; cannot fail. */
void noct_bp_free_slot(noctBroadphase *bp, uint32_t s);

/* ---- broadphase_tree.c ----------------------------------------------------------- */

/* The root's cube as a box; everything when there is no tree. */
noct_aabb noct_bp_root_box(const noctBroadphase *bp);

/* Room for proxies up to capacity cap in every per-slot array. */
bool noct_bp_reserve_slots(noctBroadphase *bp, uint32_t cap);

/* Add proxy id (slot set up, box placed) to the tree: into the leaves it
 * overlaps, or by a rebuild around a larger root if it lies outside.
 * On failure the tree is torn down (tree_owed). */
noctStatus noct_bp_insert(noctBroadphase *bp, uint32_t id);

/* Remove proxy id from every leaf (cannot fail). */
void noct_bp_unlink(noctBroadphase *bp, uint32_t id);

/* Build the tree afresh with a root of at least min_size; tears it down
 * on failure (tree_owed). */
noctStatus noct_bp_rebuild(noctBroadphase *bp, double min_size);

/* Tear the tree down; tree_owed if proxies are left. */
void noct_bp_drop_tree(noctBroadphase *bp);

/* Free every node and cell (the broadphase's end). */
void noct_bp_free_tree(noctBroadphase *bp);

/*
 * Incremental maintenance of the proxies slow[0..n): their boxes (bp->box)
 * moved from proxy.old and failed the fast test at their positions pos
 * (NULL: position 0; reshaped proxies have no home block and skip it).
 * If one left the root, *escaped is set and nothing else is done. nfast
 * proxies passed the fast test elsewhere (counted).
 */
noctStatus noct_bp_maintain(noctBroadphase *bp, const double (*pos)[3], const uint32_t *slow,
                            uint32_t n, uint32_t nfast, bool *escaped);

/* After maintenance: grow the root if a box escaped it, shrink it if it
 * is far too large, make the merges owed. Tears the tree down on failure. */
noctStatus noct_bp_settle(noctBroadphase *bp, bool escaped);

/* Proxy id's local box becomes mlo, mhi (its placed box is the caller's):
 * its leaves' counts follow, and split if they must. False without
 * memory (the tree is then inconsistent: drop it). */
bool noct_bp_reshape(noctBroadphase *bp, uint32_t id, const double mlo[3], const double mhi[3]);

/* The home block of proxy id while its leaves are those box b overlaps. */
bool noct_bp_home_of(const noctBroadphase *bp, uint32_t id, const noct_aabb *b, noct_home *h);

/* The block of cells, of proxy id's smallest leaf's size s, that box b
 * overlaps (its leaves were made for b), in box space: the lattice lines
 * around b, into blk; false if there is none. */
bool noct_bp_block_of(const noctBroadphase *bp, uint32_t id, const noct_aabb *b, noct_home *blk,
                      double *s);

/* Does box nb overlap the cells of block blk (cells of size s), and so
 * lie in the same leaves: its low side in (lo, lo + s], its high side in
 * [hi - s, hi), on every axis? The lattice points are exact. */
static inline bool noct_in_block(const noct_home *blk, double s, const noct_aabb *nb)
{
    for (int k = 0; k < 3; ++k)
        if (!(nb->lo[k] > blk->lo[k] && nb->lo[k] <= blk->lo[k] + s &&
              nb->hi[k] >= blk->hi[k] - s && nb->hi[k] < blk->hi[k]))
            return false;
    return true;
}

/* The tree's operations that maintenance (broadphase_maintain.c) uses:
 * add id to every leaf under n that its box overlaps and lacks (all of
 * them when fresh; newly entered leaves pushed to the worklist with
 * push), false without memory; remove the object at position i of a leaf
 * and merge its siblings if they are few enough; make every merge owed. */
bool noct_bp_insert_below(noctBroadphase *bp, octNode *n, uint32_t id, bool push, bool fresh);
void noct_bp_leaf_remove_at(noctBroadphase *bp, octNode *leaf, uint32_t i);
void noct_bp_merge_all(noctBroadphase *bp, octNode *n);

/* ---- broadphase_query.c ---------------------------------------------------------- */

/*
 * The squared gap between a box [blo, bhi] and the query box [lo, hi], as
 * noct_bp_nearest() computes it for boxes and cells alike: per axis
 * g = max(fl(blo - hi), fl(lo - bhi), 0), and the sum of fl(g * g) over
 * the axes x, y, z in order, each operation rounded to nearest. Each
 * rounded operation is monotone in its operands, so a box within another
 * never has a larger gap than it.
 */
static NOCT_ALWAYS_INLINE double noct_gap2(const double lo[3], const double hi[3],
                                           const double blo[3], const double bhi[3])
{
    const double gx = noct_max(noct_max(blo[0] - hi[0], lo[0] - bhi[0]), 0);
    const double gy = noct_max(noct_max(blo[1] - hi[1], lo[1] - bhi[1]), 0);
    const double gz = noct_max(noct_max(blo[2] - hi[2], lo[2] - bhi[2]), 0);
    return gx * gx + gy * gy + gz * gz;
}

/* Called by noct_bp_nearest() with a proxy and its squared gap; false stops
 * the walk (the caller's failure). */
typedef bool noct_nearest_fcn(void *context, uint32_t id, double gap2);

/* What noct_bp_nearest() reads from its caller as it goes (gap2 and below
 * may shrink at every call of its function; done2 holds still). */
typedef struct noct_nearest_bound {
    double gap2;    /* proxies (and cells) whose noct_gap2() exceeds it are
                       not wanted */
    double done2;   /* nor proxies whose noct_gap2() is at most this (an
                       earlier walk's bound; -1: none) */
    uint32_t below; /* nor proxies of this index or more */
} noct_nearest_bound;

/*
 * Hand fcn, once each, every live proxy that the filter lets through, of
 * index below bound->below, whose box's noct_gap2() to [lo, hi] is above
 * bound->done2 and at most bound->gap2 when its turn comes: the walk goes
 * through the leaves depth first, from the child that holds centre (a
 * point of [lo, hi]) outward, skipping cells beyond the bound, and within
 * a leaf nearer boxes first; fcn may shrink the bound at every call.
 * Without a tree, every proxy is asked, nearer first. *cut tells whether
 * a cell or a box was left out for being beyond the bound as it was then
 * (else every proxy above done2 was handed over, or was left out by a
 * shrunk bound while the walk took a leaf's boxes in order). NOMEM when
 * the walk's list of a leaf's boxes could not grow (fcn may have been
 * called).
 */
noctStatus noct_bp_nearest(const noctBroadphase *bp, const double lo[3], const double hi[3],
                           const double centre[3], noctQueryFilter filter,
                           const noct_nearest_bound *bound, noct_nearest_fcn *fcn,
                           void *context, bool *cut);

/* ---- broadphase_pairs.c ---------------------------------------------------------- */

/* Every pair of proxies whose boxes overlap (and filters pass), once,
 * into bp->tested (emptied first), unsorted; reach as bp->reach. */
noctStatus noct_bp_search(noctBroadphase *bp);

/* Sort bp->tested by its first proxy (stable radix sort). */
bool noct_bp_sort_tested(noctBroadphase *bp);

/*
 * The search protocol, which noctBroadphaseUpdatePairs() and the world's
 * step both follow: a frame begins (the enter check's clock and the frame
 * tick, the reach from 0); the reach grows by each distance a box may
 * have travelled since the last search (the world's motion, the program's
 * moves), with the rounding of the root's coordinates; the pairs are
 * found; and the search that took in the program's moves says so.
 */
void noct_bp_begin_frame(noctBroadphase *bp);
void noct_bp_add_reach(noctBroadphase *bp, double travel);

/* Every pair within reach, into the found list (noct_bp_found()), sorted
 * by its first proxy. NOMEM: the leaves' near pairs may be half made. */
noctStatus noct_bp_find_pairs(noctBroadphase *bp);

/* The frame's pairs are found by the client instead of a search (the
 * world's margin candidates hold every overlapping pair: world_near.c):
 * the found list, emptied, for it to fill, sorted by first proxy, with
 * the pairs a search would find; the frame's reach is owed to the next
 * search (the leaves' budgets are spent by it then), and candidates, the
 * pairs the client considered, counted as a search's. */
noct_pair_list *noct_bp_skip_search(noctBroadphase *bp, uint64_t candidates);

static inline const noct_pair_list *noct_bp_found(const noctBroadphase *bp)
{
    return &bp->tested;
}

/* The program's moves since the last search are in this one's reach. */
static inline double noct_bp_pending_reach(const noctBroadphase *bp)
{
    return bp->pending_reach;
}
void noct_bp_end_search(noctBroadphase *bp);

/* Sort pairs that are in order of their first proxy by their second. */
void noct_pairs_sort_partners(noct_pair_list *l);

/* noct_pair_order for qsort. */
int noct_pair_cmp(const void *x, const void *y);

#endif /* NOCT_LIB_BROADPHASE_INTERNAL_H */
