/* SPDX-License-Identifier: MIT */
/*
 * The collision world: the report's system on top of the octree ADT,
 * neighbor finding and the narrowphase.
 *
 * Every node's datum is a cell: its cube (lo, size) and, for a leaf, the
 * indices of the objects whose boxes overlap it. The eight children's
 * cells are allocated together, like the nodes. Every object keeps the
 * list of leaves it is in (its spans).
 *
 * Cells are closed for overlap (touching counts) and half-open for
 * ownership of a point ([lo, lo + size), closed at the root's upper
 * faces): the pair search tests a pair only in the one leaf that owns the
 * lower corner of the two boxes' overlap, so each pair is tested once per
 * step with no table of tested pairs.
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#if defined(__x86_64__) && defined(__SSE2__)
#  include <emmintrin.h> /* _mm_stream_si64 */
#endif

#include <noctree/neighbor.h>
#include <noctree/world.h>

#include "internal.h"
#include "mesh_internal.h"
#include "world_internal.h"

typedef struct cell {
    double lo[3];
    double size;
    uint32_t *objs;      /* leaf: objects overlapping the cell, then
                            (back_of) where each one's spans list the
                            leaf, so removals need no search: 2 cap */
    uint32_t count, cap;
    uint32_t small;      /* leaf: objects small enough to split for */
    uint32_t stamp_obj;  /* enter check: last (object, step) that queried */
    uint32_t fresh;      /* objs[fresh, count) came since the near pairs */
    uint64_t stamp_step; /* this node as a neighbor */
    /* Leaf, from its last sweep: every pair of its boxes not in near was
     * at least budget apart (on some axis) then, less twice the reach of
     * each step since, but for the pairs of the fresh objects, which the
     * next search adds (near_fresh). near holds the pairs that were
     * closer, as positions in objs (low and high 16 bits). */
    union {
        double budget;
        /* Node whose children are leaves: they hold at least this many
         * distinct objects (0: unknown). Objects leaving them count it
         * down, one each; more coming cannot make it wrong. */
        uint32_t distinct;
    };
    uint32_t *near;
    uint32_t nnear, capnear;
} cell;

/* An axis-aligned box, closed. */
typedef struct aabb {
    double lo[3], hi[3];
} aabb;

/*
 * An object's home block: the block of cells of its smallest leaf's size,
 * on that leaf's lattice, that its box overlaps, with the high side of the
 * first column and the low side of the last on each axis. Each such cell
 * lies in one of its leaves (a smaller leaf in it would be overlapped too,
 * and be one of its leaves), and each of its leaves holds such a cell, so
 * the cells decide the leaves. A box strictly inside the block that also
 * reaches the first and last columns on every axis overlaps the same
 * cells: its leaves are unchanged, and maintenance has nothing to do.
 * With leaves of one size the block is the box they tile. It lies in the
 * root, so a box that passes the test is in the root too.
 *
 * The fast test does not read the block but the positions whose placed
 * boxes pass it (home_of() works them out): a closed box [lo, hi] in
 * position space, half the size and half the comparisons. lo[0] = +inf
 * when there is none (the leaves changed since it was taken, the lattice
 * is not exact there, or the box touched the root's face).
 */
typedef struct home_block {
    double lo[3], hi[3];
} home_block;

/* A leaf an object is in, and where the leaf lists it: objs[at]. */
typedef struct span {
    octNode *leaf;
    uint32_t at;
} span;

typedef struct object {
    const noctMesh *mesh;
    double vel[3], speed;  /* vel = speed * unit direction */
    double mlo[3], mhi[3]; /* the mesh's box, copied here for the motion loop */
    aabb old;              /* the placed box before the last move */
    span *spans;           /* leaves it is in */
    uint32_t nspans, capspans;
    bool alive;
    bool entering;         /* maintenance: needs the enter phase */
} object;

typedef struct pair_list {
    noctPair *p;
    size_t n, cap;
} pair_list;

/* A leaf's objects' boxes, gathered for the pair search's all-pairs loop
 * so that it reads one contiguous array instead of scattered objects. */
typedef struct leaf_box {
    double lo[3], hi[3];
    uint32_t id;
} leaf_box;

struct noctWorld {
    noctWorldDef def;
    leaf_box *gather;      /* pair search scratch */
    uint32_t capgather;
    object *obj;
    /* Per slot, beside obj, so that the per-step loops read small
     * contiguous records: the placed bounding box and the home block. */
    aabb *box;
    home_block *home;
    const noctMesh **mesh; /* obj[i].mesh again: the narrowphase's prefetch
                              reads it without touching the objects */
    double (*pos)[3];      /* per slot: the position (translation) */
    uint32_t *gen;         /* per slot: its handles' generation, read for
                              each colliding pair (4 bytes, not a line) */
    noct_box_slot *slot;   /* per object with a box-form mesh: with pos,
                              all the exact level reads of most pairs of
                              boxes (64-byte aligned, two lines each) */
    uint32_t *movers;      /* live moving objects, by slot */
    uint32_t nmovers, capmovers;
    double vmax;           /* the movers' greatest speed */
    bool movers_stale;
    uint32_t *slow;        /* maintenance: movers that failed the fast test */
    uint32_t nslow, capslow;
    uint32_t nslots, capslots;
    uint32_t *free_slots;  /* room for capslots, so a removal cannot fail */
    uint32_t nfree, capfree;
    bool merge_owed;       /* a merge lacked memory: merge_all() owed */
    bool tree_owed;        /* a failure tore the tree down: rebuild owed */
    uint64_t shrink_from;  /* the first sub-step the root may shrink at */
    /* What a failed step restores (roll_back): per mover, its position
     * before the step, as the bits the motion loop streams out (see
     * keep_position), and, for a step of sub-steps, its velocity; and
     * which velocity components the walls turned (mover * 3 + axis). */
    int64_t (*prev)[3];
    double (*prevvel)[3];
    uint64_t *flips;
    uint32_t capprev, nflips;
    bool moved, touched;   /* this step moved objects; changed the tree */
    uint64_t substeps;     /* this step's */
    pair_list held;        /* the colliding list before a step of sub-steps */
    size_t alive;
    size_t moving;         /* live objects with a non-zero speed */
    octNode *root;
    uint64_t step;
    uint64_t *mark;        /* per object: epoch stamp for distinct counts */
    uint64_t epoch;
    octNode **work;        /* enter check's worklist */
    size_t nwork, capwork;
    double reach;          /* this (sub-)step: how far any box may have
                              moved on an axis, rounding included */
    pair_list tested;      /* the pair search's pairs for the narrowphase */
    noctPair *sorted;      /* radix sort scratch for tested */
    size_t capsorted;
    uint32_t *digits;      /* and its bucket counts */
    uint32_t capdigits;
    pair_list colliding, previous, began, ended;
    noctMesh **owned;      /* meshes the scene builders made */
    size_t nowned, capowned;
    noctWorldCounters c;
};

/* ---- small helpers ------------------------------------------------------ */

static double seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static cell *cell_of(const octNode *n)
{
    return NOCT_NODE_DATA(n);
}

static bool grow_array(void **p, uint32_t *cap, uint32_t need, size_t elem)
{
    if (need <= *cap)
        return true;
    uint32_t c = *cap ? *cap : 4;
    while (c < need)
        c *= 2;
    void *q = realloc(*p, (size_t)c * elem);
    if (q == NULL)
        return false;
    *p = q;
    *cap = c;
    return true;
}

static bool overlaps(const aabb *b, const cell *c)
{
    for (int k = 0; k < 3; ++k)
        if (b->hi[k] < c->lo[k] || b->lo[k] > c->lo[k] + c->size)
            return false;
    return true;
}

/* Are the leaves of an object at position p still those of its home
 * block, whose positions h holds (the report's fast test, for a box in
 * one leaf or several)? Inlined: it runs for every mover, and almost
 * every one passes. */
static NOCT_ALWAYS_INLINE bool inside_home(const double p[3], const home_block *h)
{
    return p[0] >= h->lo[0] && p[0] <= h->hi[0] && p[1] >= h->lo[1] && p[1] <= h->hi[1] &&
           p[2] >= h->lo[2] && p[2] <= h->hi[2];
}

static void forget_home(noctWorld *w, uint32_t id)
{
    w->home[id].lo[0] = INFINITY;
}

/* The placed box: exactly the narrowphase's [fl(lo + t), fl(hi + t)]. */
static NOCT_ALWAYS_INLINE void place_box(const object *o, const double pos[3], aabb *b)
{
    b->lo[0] = o->mlo[0] + pos[0];
    b->lo[1] = o->mlo[1] + pos[1];
    b->lo[2] = o->mlo[2] + pos[2];
    b->hi[0] = o->mhi[0] + pos[0];
    b->hi[1] = o->mhi[1] + pos[1];
    b->hi[2] = o->mhi[2] + pos[2];
}

/* Is object id in leaf c? Whichever of its spans and the leaf's list is
 * shorter is searched, so that neither a crowded leaf nor an object in
 * many leaves makes the question costly. */
static bool leaf_has(const noctWorld *w, const octNode *leaf, uint32_t id)
{
    const cell *c = cell_of(leaf);
    const object *o = &w->obj[id];
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

/* objs[i]'s entry in its spans for leaf c is back_of(c)[i]. */
static NOCT_ALWAYS_INLINE uint32_t *back_of(const cell *c)
{
    return c->objs + c->cap;
}

/* Is object o one that a split of a cell of this size can separate from
 * others: is its box at most half the size on every axis, so that it fits
 * in a child? See add_and_split. */
static bool splits_for(const object *o, double size)
{
    const double h = size / 2;
    return o->mhi[0] - o->mlo[0] <= h && o->mhi[1] - o->mlo[1] <= h &&
           o->mhi[2] - o->mlo[2] <= h;
}

/* Put object id, whose spans entry for this leaf is s, at position i of
 * the leaf's list, and tell the entry. */
static NOCT_ALWAYS_INLINE void leaf_put(noctWorld *w, cell *c, uint32_t i, uint32_t id,
                                        uint32_t s)
{
    c->objs[i] = id;
    back_of(c)[i] = s;
    w->obj[id].spans[s].at = i;
}

/* The entry of object id's spans for the leaf whose cell is c (a search
 * of its few spans, for the objects a sweep moved in the leaf's list). */
static uint32_t span_of(const noctWorld *w, uint32_t id, const cell *c)
{
    const object *o = &w->obj[id];
    for (uint32_t s = 0;; ++s) {
        NOCT_INVARIANT(s < o->nspans);
        if (cell_of(o->spans[s].leaf) == c)
            return s;
    }
}

/* Drop entry s of object id's spans (the leaf's list is the caller's):
 * the last entry takes its place, and its leaf is told. */
static void span_drop(noctWorld *w, uint32_t id, uint32_t s)
{
    object *o = &w->obj[id];
    forget_home(w, id);
    NOCT_INVARIANT(s < o->nspans);
    const span last = o->spans[--o->nspans];
    if (s == o->nspans)
        return;
    o->spans[s] = last;
    back_of(cell_of(last.leaf))[last.at] = s;
}

/* The object at position r of leaf c went and the one at position last
 * took its place: r's near pairs go, last's follow it. The other pairs
 * are as far apart as before. */
static void near_leave(cell *c, uint32_t r, uint32_t last)
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

/* Room for one more object in leaf c: both halves of objs double. */
static bool leaf_reserve(cell *c)
{
    if (c->count < c->cap)
        return true;
    const uint32_t cap = c->cap ? 2 * c->cap : 4;
    uint32_t *q = realloc(c->objs, 2 * (size_t)cap * sizeof *q);
    if (q == NULL)
        return false;
    memmove(q + cap, q + c->cap, c->count * sizeof *q);
    c->objs = q;
    c->cap = cap;
    return true;
}

static bool leaf_add(noctWorld *w, octNode *leaf, uint32_t id)
{
    cell *c = cell_of(leaf);
    object *o = &w->obj[id];
    if (!leaf_reserve(c) ||
        !grow_array((void **)&o->spans, &o->capspans, o->nspans + 1, sizeof *o->spans))
        return false;
    o->spans[o->nspans].leaf = leaf;
    leaf_put(w, c, c->count++, id, o->nspans++); /* fresh: after c->fresh */
    c->small += splits_for(o, c->size);
    forget_home(w, id);
    return true;
}

/* ---- split and merge ------------------------------------------------------ */

static bool split_leaf(noctWorld *w, octNode *leaf);

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
static bool add_and_split(noctWorld *w, octNode *leaf, uint32_t id)
{
    if (!leaf_add(w, leaf, id))
        return false;
    cell *c = cell_of(leaf);
    if ((int)c->small > w->def.N && octGeneration(leaf) < w->def.max_depth)
        return split_leaf(w, leaf);
    return true;
}

/* Give the leaf 8 children and hand each object to the children its box
 * overlaps (which may split in turn). */
static bool split_leaf(noctWorld *w, octNode *leaf)
{
    cell *pc = cell_of(leaf);
    cell *kids = calloc(8, sizeof *kids);
    if (kids == NULL || !octSplit(leaf)) {
        free(kids);
        return false;
    }
    double half = pc->size / 2;
    for (int i = 0; i < 8; ++i) {
        kids[i].lo[0] = pc->lo[0] + ((i & 4) ? half : 0);
        kids[i].lo[1] = pc->lo[1] + ((i & 2) ? half : 0);
        kids[i].lo[2] = pc->lo[2] + ((i & 1) ? half : 0);
        kids[i].size = half;
        octSwapData(NOCT_NODE_CHILD(leaf, (octDirection)(OCT_LDB + i)), &kids[i]);
    }
    /* The objects leave the leaf, each by its own entry: no search. */
    for (uint32_t j = 0; j < pc->count; ++j)
        span_drop(w, pc->objs[j], back_of(pc)[j]);
    uint32_t *objs = pc->objs, count = pc->count;
    pc->objs = NULL;
    pc->count = pc->cap = pc->small = 0;
    free(pc->near);
    pc->near = NULL;
    pc->nnear = pc->capnear = 0;
    pc->distinct = 0;
    /* Removals below the new children do not count the parent's down. */
    if (NOCT_NODE_PARENT(leaf) != NULL)
        cell_of(NOCT_NODE_PARENT(leaf))->distinct = 0;
    ++w->c.splits;
    bool ok = true;
    for (uint32_t j = 0; j < count && ok; ++j)
        for (int i = 0; i < 8 && ok; ++i)
            if (overlaps(&w->box[objs[j]], &kids[i]))
                ok = add_and_split(w, NOCT_NODE_CHILD(leaf, (octDirection)(OCT_LDB + i)), objs[j]);
    free(objs);
    return ok;
}

/* Detach and free the cells of every node below n (not n's own), so that
 * octJoin(n, NULL) finds no client data. */
static void free_cells_below(octNode *n)
{
    if (!NOCT_NODE_IS_SPLIT(n))
        return;
    cell *block = cell_of(NOCT_NODE_CHILD(n, OCT_LDB)); /* the 8 are one block */
    for (int i = 0; i < 8; ++i) {
        octNode *k = NOCT_NODE_CHILD(n, (octDirection)(OCT_LDB + i));
        free_cells_below(k);
        cell *c = octSwapData(k, NULL);
        free(c->objs);
        free(c->near);
    }
    free(block);
}

/*
 * If all of p's children are leaves holding N or fewer distinct objects,
 * merge them into p; then try p's parent. Every object leaving a leaf
 * asks, so the count of a node whose children hold too many is kept
 * (cell.distinct): it is taken again only when as many objects have left
 * as it was over N.
 *
 * A merge needs memory for p's list; without it the siblings stay split,
 * which costs pairs but not correctness, and w->merge_owed makes the next
 * step merge what it can (merge_all). Nothing else here allocates: an
 * object's spans lose the children before they gain p. So a removal
 * cannot fail.
 */
static void try_merge(noctWorld *w, octNode *p, bool up)
{
    while (p != NULL && w->def.N != NOCT_N_EXHAUSTIVE) {
        cell *pc = cell_of(p);
        if (pc->distinct > (uint32_t)w->def.N)
            return;
        uint32_t distinct = 0;
        ++w->epoch;
        for (int i = 0; i < 8; ++i) {
            octNode *k = NOCT_NODE_CHILD(p, (octDirection)(OCT_LDB + i));
            if (NOCT_NODE_IS_SPLIT(k))
                return;
            const cell *c = cell_of(k);
            for (uint32_t j = 0; j < c->count; ++j)
                if (w->mark[c->objs[j]] != w->epoch) {
                    w->mark[c->objs[j]] = w->epoch;
                    ++distinct;
                }
        }
        if (distinct > (uint32_t)w->def.N) {
            pc->distinct = distinct;
            return;
        }
        const uint32_t cap = distinct ? distinct : 1;
        uint32_t *objs = malloc(2 * (size_t)cap * sizeof *objs);
        if (objs == NULL) {
            w->merge_owed = true;
            return;
        }
        pc->objs = objs;
        pc->cap = cap;
        pc->count = pc->small = 0;
        pc->fresh = 0;
        pc->budget = 0;
        ++w->epoch;
        for (int i = 0; i < 8; ++i) {
            cell *c = cell_of(NOCT_NODE_CHILD(p, (octDirection)(OCT_LDB + i)));
            for (uint32_t j = 0; j < c->count; ++j) {
                const uint32_t id = c->objs[j];
                span_drop(w, id, back_of(c)[j]);
                if (w->mark[id] != w->epoch) {
                    w->mark[id] = w->epoch;
                    pc->objs[pc->count++] = id;
                }
            }
        }
        free_cells_below(p);
        octJoin(p, NULL);
        for (uint32_t j = 0; j < pc->count; ++j) {
            object *o = &w->obj[pc->objs[j]];
            NOCT_INVARIANT(o->nspans < o->capspans);
            o->spans[o->nspans].leaf = p;
            leaf_put(w, pc, j, pc->objs[j], o->nspans++);
            pc->small += splits_for(o, pc->size);
        }
        ++w->c.merges;
        p = up ? NOCT_NODE_PARENT(p) : NULL;
    }
}

/* Merge every group of leaf siblings that a merge without memory left
 * split (try_merge), deepest first: each node after its children, and
 * none upward from there (that would free nodes the walk still holds). */
static void merge_all(noctWorld *w, octNode *n)
{
    if (!NOCT_NODE_IS_SPLIT(n))
        return;
    for (int i = 0; i < 8; ++i)
        merge_all(w, NOCT_NODE_CHILD(n, (octDirection)(OCT_LDB + i)));
    try_merge(w, n, false);
}

/* Remove the object at position i of the leaf (whose spans entry says
 * so), then merge the siblings if they are few enough. Cannot fail. */
static void leaf_remove_at(noctWorld *w, octNode *leaf, uint32_t i)
{
    cell *c = cell_of(leaf);
    NOCT_INVARIANT(i < c->count);
    const uint32_t id = c->objs[i];
    uint32_t *back = back_of(c);
    span_drop(w, id, back[i]);
    NOCT_INVARIANT(c->small >= (uint32_t)splits_for(&w->obj[id], c->size));
    c->small -= splits_for(&w->obj[id], c->size);
    /* The fresh objects stay last: an old one's place goes to the last
     * old one, whose place goes to the last object. */
    const uint32_t last = --c->count;
    if (i < c->fresh) {
        const uint32_t last_old = --c->fresh;
        near_leave(c, i, last_old);
        if (i != last_old)
            leaf_put(w, c, i, c->objs[last_old], back[last_old]);
        if (last_old != last)
            leaf_put(w, c, last_old, c->objs[last], back[last]);
    } else if (i != last) {
        leaf_put(w, c, i, c->objs[last], back[last]);
    }
    ++w->c.leaves_left;
    octNode *p = NOCT_NODE_PARENT(leaf);
    if (p != NULL && cell_of(p)->distinct > 0)
        --cell_of(p)->distinct;
    try_merge(w, p, true);
}

/* Add id to every leaf under n that its box overlaps and lacks it (a new
 * object, fresh true, lacks them all). If the worklist is on, newly
 * entered leaves are pushed to it. */
static bool insert_below(noctWorld *w, octNode *n, uint32_t id, bool push, bool fresh)
{
    if (!overlaps(&w->box[id], cell_of(n)))
        return true;
    if (NOCT_NODE_IS_SPLIT(n)) {
        for (int i = 0; i < 8; ++i)
            if (!insert_below(w, NOCT_NODE_CHILD(n, (octDirection)(OCT_LDB + i)), id, push,
                              fresh))
                return false;
        return true;
    }
    if (!fresh && leaf_has(w, n, id))
        return true;
    ++w->c.leaves_entered;
    if (push) {
        if (w->nwork == w->capwork) {
            size_t cap = w->capwork ? 2 * w->capwork : 64;
            octNode **q = realloc(w->work, cap * sizeof *q);
            if (q == NULL)
                return false;
            w->work = q;
            w->capwork = cap;
        }
        w->work[w->nwork++] = n;
    }
    return add_and_split(w, n, id);
}

/* ---- building the tree ---------------------------------------------------------- */

static void destroy_tree(noctWorld *w)
{
    if (w->root == NULL)
        return;
    free_cells_below(w->root);
    if (NOCT_NODE_IS_SPLIT(w->root))
        octJoin(w->root, NULL);
    cell *rc = octSwapData(w->root, NULL);
    free(rc->objs);
    free(rc->near);
    free(rc);
    octDispose(w->root);
    w->root = NULL;
    for (uint32_t i = 0; i < w->nslots; ++i) {
        w->obj[i].nspans = 0;
        forget_home(w, i);
    }
}

/* Tear the tree down after a failure left it inconsistent; the next step
 * or addition builds it again (rebuild). */
static void drop_tree(noctWorld *w)
{
    destroy_tree(w);
    w->tree_owed = w->alive > 0;
    w->merge_owed = false;
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
static size_t straddling(const noctWorld *w, const double corner[3], double c,
                         uint32_t stride)
{
    size_t n = 0;
    for (uint32_t i = 0; i < w->nslots; i += stride) {
        if (!w->obj[i].alive)
            continue;
        const aabb *o = &w->box[i];
        for (int k = 0; k < 3; ++k)
            if (floor((o->lo[k] - corner[k]) / c) != floor((o->hi[k] - corner[k]) / c)) {
                ++n;
                break;
            }
    }
    return n;
}
static noctStatus build_tree(noctWorld *w, double min_size)
{
    destroy_tree(w);
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    bool any = false;
    for (uint32_t i = 0; i < w->nslots; ++i) {
        if (!w->obj[i].alive)
            continue;
        const aabb *o = &w->box[i];
        for (int k = 0; k < 3; ++k) {
            lo[k] = any ? noct_min(lo[k], o->lo[k]) : o->lo[k];
            hi[k] = any ? noct_max(hi[k], o->hi[k]) : o->hi[k];
        }
        any = true;
    }
    double extent = noct_max(noct_max(hi[0] - lo[0], hi[1] - lo[1]), hi[2] - lo[2]);
    double size = 1;
    while (size < 2 * extent || size < min_size)
        size *= 2;
    while (size / 2 >= 2 * extent && size / 2 >= min_size && size > 0x1p-40)
        size /= 2; /* the smallest power of two >= 2 extent (and min_size) */
    cell *rc = calloc(1, sizeof *rc);
    w->root = octCreate();
    if (rc == NULL || w->root == NULL) {
        free(rc);
        if (w->root)
            octDispose(w->root);
        w->root = NULL;
        return NOCT_ERR_NOMEM;
    }
    rc->size = size;
    /* Cells about twice the objects' mean size (a sample of at most about
     * 4096 objects), and the shift that makes the fewest straddle them. */
    uint32_t stride = w->nslots > 4096 ? w->nslots / 4096 : 1;
    double mean = 0;
    size_t counted = 0;
    for (uint32_t i = 0; i < w->nslots; i += stride)
        if (w->obj[i].alive) {
            const aabb *o = &w->box[i];
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
        size_t n = counted > 0 ? straddling(w, corner, c, stride) : 0;
        if (n < best) {
            best = n;
            memcpy(rc->lo, corner, sizeof corner);
        }
    }
    octSwapData(w->root, rc);
    ++w->c.rebuilds;
    for (uint32_t i = 0; i < w->nslots; ++i)
        if (w->obj[i].alive && !insert_below(w, w->root, i, false, true))
            return NOCT_ERR_NOMEM;
    return NOCT_OK;
}

/*
 * Build the tree afresh (build_tree). A tree that a failure left half
 * built, or half changed by a failed insertion, split or step, is torn
 * down instead: the world then has no tree, w->tree_owed says so, and the
 * next noctWorldAdd() or noctWorldStep() builds it before anything else.
 */
static noctStatus rebuild(noctWorld *w, double min_size)
{
    noctStatus st = build_tree(w, min_size);
    if (st != NOCT_OK)
        drop_tree(w);
    else
        w->tree_owed = w->merge_owed = false;
    return st;
}

/* The root's cube as a box; everything when there is no tree yet. */
static aabb root_box(const noctWorld *w)
{
    aabb r = {{-INFINITY, -INFINITY, -INFINITY}, {INFINITY, INFINITY, INFINITY}};
    if (w->root != NULL) {
        const cell *rc = cell_of(w->root);
        for (int k = 0; k < 3; ++k) {
            r.lo[k] = rc->lo[k];
            r.hi[k] = rc->lo[k] + rc->size;
        }
    }
    return r;
}

/* Box o lies in the closed box r. */
static bool box_within(const aabb *o, const aabb *r)
{
    return o->lo[0] >= r->lo[0] && o->lo[1] >= r->lo[1] && o->lo[2] >= r->lo[2] &&
           o->hi[0] <= r->hi[0] && o->hi[1] <= r->hi[1] && o->hi[2] <= r->hi[2];
}

static bool inside_root(const noctWorld *w, const aabb *o)
{
    const aabb r = root_box(w);
    return box_within(o, &r);
}

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

/* The home block of object id while its leaves are those box b overlaps
 * (b: its box when they were last made so), as the positions that keep
 * its box in it. */
static bool home_of(const noctWorld *w, uint32_t id, const aabb *b, home_block *h)
{
    const object *o = &w->obj[id];
    if (o->nspans == 0)
        return false;
    const cell *small = cell_of(o->spans[0].leaf);
    for (uint32_t i = 1; i < o->nspans; ++i)
        if (cell_of(o->spans[i].leaf)->size < small->size)
            small = cell_of(o->spans[i].leaf);
    const double s = small->size;
    const aabb root = root_box(w);
    for (int k = 0; k < 3; ++k) {
        const double lo = lattice_beyond(small->lo[k], s, b->lo[k], false);
        const double hi = lattice_beyond(small->lo[k], s, b->hi[k], true);
        /* No block that reaches out of the root, as one does when the box
         * touches the root's face: then a box inside it could be outside
         * the root (maintain() relies on it). NaN fails too. */
        if (!(lo >= root.lo[k] && hi <= root.hi[k]))
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

static noctStatus leave_phase(noctWorld *w, uint32_t id, bool *enter)
{
    object *o = &w->obj[id];
    const aabb *b = &w->box[id];
    *enter = false;
    /* maintain() tried a block it had; one is taken when there was none */
    if (!isfinite(w->home[id].lo[0]) && home_of(w, id, &o->old, &w->home[id]) &&
        inside_home(w->pos[id], &w->home[id])) {
        ++w->c.inside_fast;
        return NOCT_OK;
    }
    forget_home(w, id);
    for (uint32_t i = 0; i < o->nspans;) {
        if (overlaps(b, cell_of(o->spans[i].leaf))) {
            ++i;
            continue;
        }
        leaf_remove_at(w, o->spans[i].leaf, o->spans[i].at);
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
static noctStatus enter_phase(noctWorld *w, uint32_t id)
{
    object *o = &w->obj[id];
    const aabb *bx = &w->box[id];
    if (o->nspans == 0) {
        ++w->c.reinserts;
        return insert_below(w, w->root, id, false, true) ? NOCT_OK : NOCT_ERR_NOMEM;
    }
    if (w->capwork < o->nspans) {
        octNode **q = realloc(w->work, o->nspans * sizeof *q);
        if (q == NULL)
            return NOCT_ERR_NOMEM;
        w->work = q;
        w->capwork = o->nspans;
    }
    for (uint32_t i = 0; i < o->nspans; ++i)
        w->work[i] = o->spans[i].leaf;
    w->nwork = o->nspans;
    for (size_t wi = 0; wi < w->nwork; ++wi) {
        const cell *lc = cell_of(w->work[wi]);
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
                    octNode *nb = octGtEqNeighbor(w->work[wi], d);
                    ++w->c.neighbor_queries;
                    if (nb == NULL)
                        continue;
                    cell *nc = cell_of(nb);
                    if (nc->stamp_step == w->step && nc->stamp_obj == id)
                        continue;
                    nc->stamp_step = w->step;
                    nc->stamp_obj = id;
                    if (!insert_below(w, nb, id, true, false))
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
#define PREFETCH_OBJECTS 8192

static NOCT_ALWAYS_INLINE void prefetch_spans(const noctWorld *w, uint32_t m)
{
    const uint32_t n = w->nslow, *slow = w->slow;
    if (m + 8 < n)
        NOCT_PREFETCH(&w->obj[slow[m + 8]].spans);
    if (m + 6 < n)
        NOCT_PREFETCH(w->obj[slow[m + 6]].spans);
    if (m + 4 < n) {
        const object *o = &w->obj[slow[m + 4]];
        for (uint32_t k = 0; k < o->nspans; ++k)
            NOCT_PREFETCH(o->spans[k].leaf);
    }
    if (m + 2 < n) {
        const object *o = &w->obj[slow[m + 2]];
        for (uint32_t k = 0; k < o->nspans; ++k)
            NOCT_PREFETCH(cell_of(o->spans[k].leaf));
    }
}

/*
 * Incremental maintenance. The motion loop ran the fast test and listed
 * the boxes that failed it in w->slow. A box that passed lies in its home
 * block, and so in its leaves and the root; of the others, if one left
 * the root, *escaped is set and nothing else is done (the caller grows
 * the tree by a rebuild).
 */
static noctStatus maintain(noctWorld *w, bool *escaped)
{
    noctStatus st = NOCT_OK;
    *escaped = false;
    const aabb root = root_box(w);
    for (uint32_t m = 0; m < w->nslow; ++m)
        if (!box_within(&w->box[w->slow[m]], &root)) {
            *escaped = true;
            return NOCT_OK;
        }
    w->c.inside_fast += w->nmovers - w->nslow;
    /* Below some thousands of objects they stay in cache. */
    const bool ahead = w->nslots >= PREFETCH_OBJECTS;
    for (uint32_t m = 0; m < w->nslow && st == NOCT_OK; ++m) {
        if (ahead)
            prefetch_spans(w, m);
        st = leave_phase(w, w->slow[m], &w->obj[w->slow[m]].entering);
    }
    for (uint32_t m = 0; m < w->nslow && st == NOCT_OK; ++m) {
        if (ahead)
            prefetch_spans(w, m);
        if (w->obj[w->slow[m]].entering)
            st = enter_phase(w, w->slow[m]);
    }
    /* Their leaves are final for this step, and in cache: take their home
     * blocks now, so that the next step's fast test can pass them. A
     * later change to their leaves forgets the block again. */
    for (uint32_t m = 0; m < w->nslow && st == NOCT_OK; ++m) {
        const uint32_t id = w->slow[m];
        if (ahead)
            prefetch_spans(w, m);
        if (!isfinite(w->home[id].lo[0]) && !home_of(w, id, &w->box[id], &w->home[id]))
            forget_home(w, id);
    }
    return st;
}

/* The live moving objects in slot order, and their greatest speed, after
 * objects came or went; room for as many slow ones. */
static bool update_movers(noctWorld *w)
{
    if (!w->movers_stale)
        return true;
    uint32_t cap = w->capmovers;
    if (!grow_array((void **)&w->movers, &cap, (uint32_t)w->moving, sizeof *w->movers))
        return false;
    w->capmovers = cap;
    if (!grow_array((void **)&w->slow, &w->capslow, (uint32_t)w->moving, sizeof *w->slow))
        return false;
    if (w->capprev < w->moving) {
        const bool walls = (w->def.effects & NOCT_EFFECT_WALLS) != 0;
        const bool sub = (w->def.effects & NOCT_EFFECT_SUBSTEP) != 0;
        int64_t(*p)[3] = realloc(w->prev, w->moving * sizeof *p);
        if (p != NULL)
            w->prev = p;
        double(*v)[3] = p && sub ? realloc(w->prevvel, w->moving * sizeof *v) : NULL;
        if (v != NULL)
            w->prevvel = v;
        uint64_t *f = p && (!sub || v) && walls
                          ? realloc(w->flips, 3 * w->moving * sizeof *f) : NULL;
        if (f != NULL)
            w->flips = f;
        if (p == NULL || (sub && v == NULL) || (walls && f == NULL))
            return false;
        w->capprev = (uint32_t)w->moving;
    }
    w->nmovers = 0;
    w->vmax = 0;
    for (uint32_t i = 0; i < w->nslots; ++i)
        if (w->obj[i].alive && w->obj[i].speed > 0) {
            w->movers[w->nmovers++] = i;
            w->vmax = noct_max(w->vmax, w->obj[i].speed);
        }
    w->movers_stale = false;
    return true;
}

/* ---- pair search, events, response ------------------------------------------- */

static bool pairs_push(pair_list *l, noctPair p)
{
    if (l->n == l->cap) {
        size_t cap = l->cap ? 2 * l->cap : 64;
        noctPair *q = realloc(l->p, cap * sizeof *q);
        if (q == NULL)
            return false;
        l->p = q;
        l->cap = cap;
    }
    l->p[l->n++] = p;
    return true;
}

static int cmp_pair(const void *x, const void *y)
{
    const noctPair *a = x, *b = y;
    if (a->a.index != b->a.index)
        return a->a.index < b->a.index ? -1 : 1;
    return (a->b.index > b->b.index) - (a->b.index < b->b.index);
}

/* Does the leaf own point p: [lo, lo + size) per axis, closed at the
 * root's upper faces? */
static bool owns(const cell *c, const cell *root, const double p[3])
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

/* Insertion sort by lower corner on axis k for the leaves of up to a few
 * dozen objects that N makes common, a merge of runs for the crowded ones
 * at the maximum depth. */
static void sort_by_lower(leaf_box *g, uint32_t n, int k, leaf_box *tmp)
{
    if (n > 64) {
        /* bottom-up merge sort into tmp and back */
        leaf_box *src = g, *dst = tmp;
        for (uint32_t width = 1; width < n; width *= 2) {
            for (uint32_t lo = 0; lo < n; lo += 2 * width) {
                uint32_t mid = lo + width < n ? lo + width : n;
                uint32_t hi = lo + 2 * width < n ? lo + 2 * width : n;
                uint32_t i = lo, j = mid, o = lo;
                while (i < mid && j < hi)
                    dst[o++] = src[j].lo[k] < src[i].lo[k] ? src[j++] : src[i++];
                while (i < mid)
                    dst[o++] = src[i++];
                while (j < hi)
                    dst[o++] = src[j++];
            }
            leaf_box *t = src;
            src = dst;
            dst = t;
        }
        if (src != g)
            memcpy(g, src, n * sizeof *g);
        return;
    }
    for (uint32_t i = 1; i < n; ++i) {
        leaf_box t = g[i];
        uint32_t j = i;
        for (; j > 0 && g[j - 1].lo[k] > t.lo[k]; --j)
            g[j] = g[j - 1];
        g[j] = t;
    }
}

/* The sweep's axis: the one along which the boxes are spread farthest for
 * their size, so that the fewest pairs overlap on it (cubes in a plane all
 * share their x, a gas is spread on every axis). */
static int sweep_axis(const leaf_box *g, uint32_t n)
{
    double lo[3], hi[3], ext[3] = {0, 0, 0};
    for (int k = 0; k < 3; ++k)
        lo[k] = hi[k] = g[0].lo[k];
    for (uint32_t i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) {
            lo[k] = noct_min(lo[k], g[i].lo[k]);
            hi[k] = noct_max(hi[k], g[i].lo[k]);
            ext[k] += g[i].hi[k] - g[i].lo[k];
        }
    int best = 0;
    double best_ratio = -1;
    for (int k = 0; k < 3; ++k) {
        /* spread over total extent */
        double r = (hi[k] - lo[k]) / (ext[k] > 0 ? ext[k] : 1);
        if (r > best_ratio) {
            best_ratio = r;
            best = k;
        }
    }
    return best;
}

/* The pair (a, b) of leaf c, whose boxes overlap, for the narrowphase if
 * c owns the lower corner of their overlap. */
static NOCT_ALWAYS_INLINE bool offer_pair(noctWorld *w, const cell *c, const cell *rc,
                                          const double alo[3], uint32_t ia,
                                          const double blo[3], uint32_t ib)
{
    const double corner[3] = {noct_max(alo[0], blo[0]), noct_max(alo[1], blo[1]),
                              noct_max(alo[2], blo[2])};
    if (!owns(c, rc, corner))
        return true;
    if (ia > ib) {
        uint32_t t = ia;
        ia = ib;
        ib = t;
    }
    return pairs_push(&w->tested, (noctPair){{ia, 0}, {ib, 0}});
}

/* How many steps of reach a sweep's near pairs are kept for: a leaf is
 * swept about once in that many steps, and its near pairs tested in the
 * others. */
#define NEAR_STEPS 4

/*
 * The fresh objects of leaf c, which came since its near pairs were made:
 * rather than sweep the leaf again, add their pairs closer than the
 * budget (this step's, held to a sweep's margin, so that the leaf is
 * swept again as soon as one made now would be) to the near pairs. Every
 * other pair is then at least the budget apart. Their boxes were
 * requested with the leaf's.
 */
static bool near_fresh(noctWorld *w, cell *c)
{
    const double budget = noct_min(c->budget, 2 * NEAR_STEPS * w->reach);
    c->budget = 0; /* until every pair is in */
    for (uint32_t r = c->fresh; r < c->count; ++r) {
        const aabb *a = &w->box[c->objs[r]];
        for (uint32_t i = 0; i < r; ++i) {
            const aabb *b = &w->box[c->objs[i]];
            const double gap = noct_max(
                noct_max(noct_max(b->lo[0] - a->hi[0], a->lo[0] - b->hi[0]),
                         noct_max(b->lo[1] - a->hi[1], a->lo[1] - b->hi[1])),
                noct_max(b->lo[2] - a->hi[2], a->lo[2] - b->hi[2]));
            if (gap > budget)
                continue;
            if (!grow_array((void **)&c->near, &c->capnear, c->nnear + 1, sizeof *c->near))
                return false;
            c->near[c->nnear++] = i | r << 16;
        }
    }
    w->c.candidate_pairs += (uint64_t)(c->count - c->fresh) * (c->count + c->fresh - 1) / 2;
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
static noctStatus search_leaf(noctWorld *w, cell *c)
{
    const cell *rc = cell_of(w->root);
    const bool sweep = w->def.N != NOCT_N_EXHAUSTIVE;
    if (sweep && c->budget > 2 * w->reach && c->count <= 0x10000) {
        c->budget -= 2 * w->reach;
        if (c->fresh < c->count && !near_fresh(w, c))
            return NOCT_ERR_NOMEM;
        if (c->nnear == 0) {
            ++w->c.leaves_skipped;
            return NOCT_OK;
        }
        ++w->c.leaves_visited;
        w->c.candidate_pairs += c->nnear;
        for (uint32_t k = 0; k < c->nnear; ++k) {
            const uint32_t ia = c->objs[c->near[k] & 0xffff], ib = c->objs[c->near[k] >> 16];
            const aabb *a = &w->box[ia], *b = &w->box[ib];
            if ((a->hi[0] < b->lo[0]) | (b->hi[0] < a->lo[0]) | (a->hi[1] < b->lo[1]) |
                (b->hi[1] < a->lo[1]) | (a->hi[2] < b->lo[2]) | (b->hi[2] < a->lo[2]))
                continue;
            if (!offer_pair(w, c, rc, a->lo, ia, b->lo, ib))
                return NOCT_ERR_NOMEM;
        }
        return NOCT_OK;
    }
    ++w->c.leaves_visited;
    if (!grow_array((void **)&w->gather, &w->capgather, 2 * c->count, sizeof *w->gather))
        return NOCT_ERR_NOMEM;
    leaf_box *g = w->gather;
    /* The boxes are scattered; search() requested them a leaf ahead. */
    for (uint32_t i = 0; i < c->count; ++i) {
        const aabb *o = &w->box[c->objs[i]];
        memcpy(g[i].lo, o->lo, sizeof o->lo);
        memcpy(g[i].hi, o->hi, sizeof o->hi);
        g[i].id = c->objs[i];
    }
    w->c.candidate_pairs += (uint64_t)c->count * (c->count - 1) / 2;
    /* The exhaustive mode keeps the report's test of every pair. */
    int axis = 0;
    if (sweep) {
        axis = sweep_axis(g, c->count);
        sort_by_lower(g, c->count, axis, g + c->count);
        /* The leaf keeps this order: objects move little in a step, so
         * the next sweep's insertion sort finds them nearly sorted, and
         * near pairs are positions in it. */
        for (uint32_t i = 0; i < c->count; ++i)
            if (c->objs[i] != g[i].id) /* few move: tell only those */
                leaf_put(w, c, i, g[i].id, span_of(w, g[i].id, c));
    }
    const bool listing = sweep && c->count <= 0x10000;
    const double m2 = listing ? 2 * NEAR_STEPS * w->reach : 0;
    c->nnear = 0;
    /* Meanwhile the least distance apart of the pairs beyond the margin:
     * those the sweep passes over are apart on its axis by at least the
     * next box's start less a's end. The four comparisons on the other
     * axes are combined without branches: most pairs fail one of them, in
     * no predictable order. */
    const int k1 = (axis + 1) % 3, k2 = (axis + 2) % 3;
    double apart = sweep ? INFINITY : 0;
    for (uint32_t i = 0; i < c->count; ++i) {
        const leaf_box *a = &g[i];
        const double ahi = a->hi[axis], reach_hi = ahi + m2;
        for (uint32_t j = i + 1; j < c->count; ++j) {
            const leaf_box *b = &g[j];
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
            if (listing) {
                if (!grow_array((void **)&c->near, &c->capnear, c->nnear + 1, sizeof *c->near))
                    return NOCT_ERR_NOMEM;
                c->near[c->nnear++] = i | j << 16;
            }
            if (gap > 0 || b->lo[axis] > ahi)
                continue; /* near, apart (touching boxes overlap) */
            if (!offer_pair(w, c, rc, a->lo, a->id, b->lo, b->id))
                return NOCT_ERR_NOMEM;
        }
    }
    c->budget = !listing ? 0 : c->nnear > 0 ? m2 : apart;
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
static bool sort_tested(noctWorld *w)
{
    const size_t n = w->tested.n;
    if (n < 2)
        return true;
    if (w->capsorted < n) {
        noctPair *q = realloc(w->sorted, n * sizeof *q);
        if (q == NULL)
            return false;
        w->sorted = q;
        w->capsorted = n;
    }
    unsigned bits = 1;
    while (bits < 32 && (1u << bits) < w->nslots)
        ++bits;
    const unsigned low = (bits + 1) / 2;
    const uint32_t buckets = 1u << low;
    if (!grow_array((void **)&w->digits, &w->capdigits, buckets, sizeof *w->digits))
        return false;
    noctPair *from = w->tested.p, *to = w->sorted;
    for (unsigned shift = 0; shift < bits; shift += low) {
        uint32_t *count = w->digits;
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
        noctPair *t = from;
        from = to;
        to = t;
    }
    if (from != w->tested.p) { /* an odd number of passes: swap the buffers */
        noctPair *t = w->tested.p;
        w->tested.p = from;
        w->sorted = t;
        size_t c = w->tested.cap;
        w->tested.cap = w->capsorted;
        w->capsorted = c;
    }
    return true;
}

/* Sort pairs that are in order of their first object by their second
 * within each first object: insertion sort for short runs, qsort for the
 * long ones a big object has. */
static void sort_partners(pair_list *l)
{
    size_t start = 0;
    while (start < l->n) {
        size_t end = start + 1;
        while (end < l->n && l->p[end].a.index == l->p[start].a.index)
            ++end;
        noctPair *r = l->p + start;
        size_t len = end - start;
        if (len > 32) {
            qsort(r, len, sizeof *r, cmp_pair);
        } else {
            for (size_t i = 1; i < len; ++i) {
                noctPair t = r[i];
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
static noctStatus narrow(noctWorld *w)
{
    const noctPair *p = w->tested.p;
    size_t n = w->tested.n;
    w->c.tested_pairs += n;
    w->c.narrow.box_tests += n; /* the search's, on the same boxes */
    if (n == 0)
        return NOCT_OK;
    /* The pairs' boxes overlap, so the whole loop is the level's time:
     * two clock reads a step rather than two a pair. */
    const noctAccuracy level = w->def.accuracy;
    const double t0 = level != NOCT_ACCURACY_BOX ? seconds() : 0;
    noctStatus st = NOCT_OK;
    const noct_box_slot *slot = w->slot;
    const bool exact = level == NOCT_ACCURACY_EXACT;
    for (size_t i = 0; i < n; ++i) {
        if (i + 16 < n)
            for (int s = 0; s < 2; ++s) {
                uint32_t k = s ? p[i + 16].b.index : p[i + 16].a.index;
                const char *b = (const char *)&slot[k];
                NOCT_PREFETCH(b);
                NOCT_PREFETCH(b + 64);
                NOCT_PREFETCH(w->pos[k]);
            }
        if (i + 8 < n)
            for (int s = 0; s < 2; ++s) {
                uint32_t k = s ? p[i + 8].b.index : p[i + 8].a.index;
                if (!exact || !slot[k].has_box) {
                    const char *m = (const char *)w->mesh[k];
                    for (int line = 0; line < 10; ++line)
                        NOCT_PREFETCH(m + 64 * line);
                }
            }
        uint32_t ia = p[i].a.index, ib = p[i].b.index;
        bool hit;
        int d = 0;
        const double *ta = w->pos[ia], *tb = w->pos[ib];
        const bool boxes = exact && slot[ia].has_box && slot[ib].has_box;
        if (boxes) {
            d = noct_box_decide(&slot[ia], ta, &slot[ib], tb);
            ++w->c.narrow.exact_tests;
            if (d != 0)
                ++*(d < 0 ? &w->c.narrow.sat_rejects : &w->c.narrow.witnesses);
        }
        const noctMesh *ma = w->mesh[ia], *mb = w->mesh[ib];
        if (d != 0)
            hit = d > 0;
        else if (boxes)
            st = noct_collide_undecided_boxes(ma, ta, mb, tb, &hit, &w->c.narrow);
        else
            st = noct_collide_overlapping(ma, ta, mb, tb, level, &hit, &w->c.narrow);
        if (st != NOCT_OK)
            break;
        if (hit && !pairs_push(&w->colliding, (noctPair){{ia, 0}, {ib, 0}})) {
            st = NOCT_ERR_NOMEM;
            break;
        }
    }
    /* The generations, in a loop of its own: its scattered reads overlap,
     * where in the loop above each would wait behind the box tests. */
    for (size_t i = 0; i < w->colliding.n; ++i) {
        noctPair *q = &w->colliding.p[i];
        q->a.generation = w->gen[q->a.index];
        q->b.generation = w->gen[q->b.index];
    }
    if (level != NOCT_ACCURACY_BOX)
        *(level == NOCT_ACCURACY_CONVEX ? &w->c.narrow.seconds_convex
                                        : &w->c.narrow.seconds_exact) += seconds() - t0;
    return st;
}

/* Request a leaf's object and near-pair lists. */
static NOCT_ALWAYS_INLINE void prefetch_lists(const cell *c)
{
    if (c->count > 1) {
        NOCT_PREFETCH(c->objs);
        if (c->nnear > 0)
            NOCT_PREFETCH(c->near);
    }
}

/* Request the boxes of a leaf whose lists are in cache, if the search
 * will read them this step (search_leaf skips the leaf otherwise). */
static NOCT_ALWAYS_INLINE void prefetch_boxes(const noctWorld *w, const cell *c)
{
    if (c->count < 2 || (w->def.N != NOCT_N_EXHAUSTIVE && c->budget > 2 * w->reach &&
                         c->nnear == 0 && c->fresh == c->count))
        return;
    for (uint32_t i = 0; i < c->count; ++i) {
        const char *b = (const char *)&w->box[c->objs[i]];
        NOCT_PREFETCH(b);
        NOCT_PREFETCH(b + sizeof(aabb) - 1);
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
static noctStatus search(noctWorld *w, octNode *n, bool ahead)
{
    const cell *kids = cell_of(NOCT_NODE_CHILD(n, OCT_LDB));
    if (ahead) {
        for (size_t b = 0; b < 8 * sizeof *kids; b += 64)
            NOCT_PREFETCH((const char *)kids + b);
        prefetch_lists(&kids[0]);
        prefetch_lists(&kids[1]);
        prefetch_boxes(w, &kids[0]);
    }
    for (int i = 0; i < 8; ++i) {
        if (ahead && i + 1 < 8)
            prefetch_boxes(w, &kids[i + 1]);
        if (ahead && i + 2 < 8)
            prefetch_lists(&kids[i + 2]);
        octNode *k = NOCT_NODE_CHILD(n, (octDirection)(OCT_LDB + i));
        noctStatus st = NOCT_NODE_IS_SPLIT(k) ? search(w, k, ahead)
                        : kids[i].count < 2   ? NOCT_OK
                                              : search_leaf(w, cell_of(k));
        if (st != NOCT_OK)
            return st;
    }
    return NOCT_OK;
}

/* began = colliding - previous, ended = previous - colliding (sorted). */
static noctStatus diff_events(noctWorld *w)
{
    size_t i = 0, j = 0;
    const pair_list *now = &w->colliding, *before = &w->previous;
    while (i < now->n || j < before->n) {
        int c = i == now->n ? 1 : j == before->n ? -1 : cmp_pair(&now->p[i], &before->p[j]);
        if (c == 0 && now->p[i].a.generation == before->p[j].a.generation &&
            now->p[i].b.generation == before->p[j].b.generation) {
            ++i;
            ++j;
        } else if (c <= 0) {
            if (!pairs_push(&w->began, now->p[i++]))
                return NOCT_ERR_NOMEM;
        } else if (!pairs_push(&w->ended, before->p[j++])) {
            return NOCT_ERR_NOMEM;
        }
    }
    w->c.events += w->began.n + w->ended.n;
    return NOCT_OK;
}

/* ---- public API ----------------------------------------------------------------- */

noctWorldDef noctDefaultWorldDef(void)
{
    noctWorldDef d;
    d.N = 10;
    d.max_depth = 10;
    d.accuracy = NOCT_ACCURACY_EXACT;
    d.effects = NOCT_EFFECT_MOTION | NOCT_EFFECT_EVENTS | NOCT_EFFECT_RESPONSE;
    d.maintenance = NOCT_MAINTAIN_INCREMENTAL;
    for (int k = 0; k < 3; ++k)
        d.walls_lo[k] = d.walls_hi[k] = 0;
    return d;
}

noctStatus noctWorldCreate(const noctWorldDef *def, noctWorld **world, noctError *err)
{
    NOCT_REQUIRE(def != NULL && world != NULL);
    *world = NULL;
    if (def->N < 1)
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0, "N is %d; it must be at least 1",
                         def->N);
    if (def->max_depth < 1 || def->max_depth > 40)
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0,
                         "max_depth is %d; it must be 1 to 40", def->max_depth);
    if (def->accuracy != NOCT_ACCURACY_BOX && def->accuracy != NOCT_ACCURACY_CONVEX &&
        def->accuracy != NOCT_ACCURACY_EXACT)
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0, "unknown accuracy %d",
                         (int)def->accuracy);
    if (def->effects & ~(unsigned)(NOCT_EFFECT_MOTION | NOCT_EFFECT_EVENTS |
                                   NOCT_EFFECT_RESPONSE | NOCT_EFFECT_WALLS |
                                   NOCT_EFFECT_SUBSTEP))
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0, "unknown effect bits 0x%x",
                         def->effects);
    if (def->maintenance != NOCT_MAINTAIN_INCREMENTAL &&
        def->maintenance != NOCT_MAINTAIN_REBUILD)
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0, "unknown maintenance mode %d",
                         (int)def->maintenance);
    if (def->effects & NOCT_EFFECT_WALLS)
        for (int k = 0; k < 3; ++k)
            if (!isfinite(def->walls_lo[k]) || !isfinite(def->walls_hi[k]) ||
                !(def->walls_lo[k] < def->walls_hi[k]))
                return noct_fail(err, NOCT_ERR_INVALID, -1, 0,
                                 "the walls need a finite container with lo < hi "
                                 "on every axis");
    noctWorld *w = calloc(1, sizeof *w);
    if (w == NULL)
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    w->def = *def;
    *world = w;
    return NOCT_OK;
}

void noctWorldDestroy(noctWorld *w)
{
    if (w == NULL)
        return;
    destroy_tree(w);
    for (uint32_t i = 0; i < w->nslots; ++i)
        free(w->obj[i].spans);
    free(w->obj);
    free(w->free_slots);
    free(w->prev);
    free(w->prevvel);
    free(w->flips);
    free(w->held.p);
    free(w->mark);
    free(w->box);
    free(w->home);
    free(w->mesh);
    free(w->slot);
    free(w->pos);
    free(w->gen);
    free(w->movers);
    free(w->slow);
    free(w->work);
    free(w->gather);
    free(w->tested.p);
    free(w->sorted);
    free(w->digits);
    free(w->colliding.p);
    free(w->previous.p);
    free(w->began.p);
    free(w->ended.p);
    for (size_t i = 0; i < w->nowned; ++i)
        noctMeshDestroy(w->owned[i]);
    free(w->owned);
    free(w);
}

static object *lookup(const noctWorld *w, noctObjectId id)
{
    if (id.index >= w->nslots || !w->obj[id.index].alive ||
        w->gen[id.index] != id.generation)
        return NULL;
    return &w->obj[id.index];
}

noctStatus noctWorldAdd(noctWorld *w, const noctMesh *mesh, const double position[3],
                        const double direction[3], double speed, noctObjectId *id,
                        noctError *err)
{
    NOCT_REQUIRE(w != NULL && mesh != NULL && position != NULL && direction != NULL);
    NOCT_REQUIRE(id != NULL);
    for (int k = 0; k < 3; ++k)
        if (!isfinite(position[k]))
            return noct_fail(err, NOCT_ERR_NONFINITE, -1, 0, "object position is not finite");
    if (!isfinite(speed))
        return noct_fail(err, NOCT_ERR_NONFINITE, -1, 0, "object speed is not finite");
    if (speed < 0)
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0, "object speed %g is negative",
                         speed);
    for (int k = 0; k < 3; ++k)
        if (fabs(position[k]) > NOCT_MAX_COORDINATE)
            return noct_fail(err, NOCT_ERR_TOO_LARGE, -1, 0,
                             "object position beyond %g", NOCT_MAX_COORDINATE);
    /* A static object's direction is ignored, whatever it holds. */
    double unit[3] = {0, 0, 0};
    if (speed > 0) {
        for (int k = 0; k < 3; ++k)
            if (!isfinite(direction[k]))
                return noct_fail(err, NOCT_ERR_NONFINITE, -1, 0,
                                 "object direction is not finite");
        if (!noct_unit_direction(direction, unit))
            return noct_fail(err, NOCT_ERR_INVALID, -1, 0,
                             "a moving object needs a non-zero direction");
    }
    uint32_t slot;
    if (w->nfree > 0) {
        slot = w->free_slots[--w->nfree];
    } else {
        if (w->nslots >= 0x80000000u)
            return noct_fail(err, NOCT_ERR_TOO_LARGE, -1, 0, "too many objects");
        /* obj, box, home, mesh, pos, gen, slot and mark share one
         * capacity, capslots; each array that grew is kept even if a later
         * one fails. */
        uint32_t cap = w->capslots;
        if (!grow_array((void **)&w->obj, &cap, w->nslots + 1, sizeof *w->obj))
            return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
        if (cap != w->capslots) {
            uint64_t *mark = realloc(w->mark, cap * sizeof *mark);
            if (mark != NULL)
                w->mark = mark;
            aabb *box = mark ? realloc(w->box, cap * sizeof *box) : NULL;
            if (box != NULL)
                w->box = box;
            home_block *home = box ? realloc(w->home, cap * sizeof *home) : NULL;
            if (home != NULL)
                w->home = home;
            const noctMesh **meshes = home ? realloc(w->mesh, cap * sizeof *meshes) : NULL;
            if (meshes != NULL)
                w->mesh = meshes;
            double(*pos)[3] = meshes ? realloc(w->pos, cap * sizeof *pos) : NULL;
            if (pos != NULL)
                w->pos = pos;
            uint32_t *gen = pos ? realloc(w->gen, cap * sizeof *gen) : NULL;
            if (gen != NULL)
                w->gen = gen;
            uint32_t *fs = gen ? realloc(w->free_slots, cap * sizeof *fs) : NULL;
            if (fs != NULL) {
                w->free_slots = fs;
                w->capfree = cap;
            }
            /* aligned, so not realloc */
            noct_box_slot *slots = fs ? aligned_alloc(64, cap * sizeof *slots) : NULL;
            if (slots == NULL)
                return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
            if (w->nslots > 0)
                memcpy(slots, w->slot, w->nslots * sizeof *slots);
            free(w->slot);
            w->slot = slots;
            w->capslots = cap;
        }
        slot = w->nslots++;
        memset(&w->obj[slot], 0, sizeof w->obj[slot]);
        w->mark[slot] = 0;
        w->gen[slot] = 0;
    }
    object *o = &w->obj[slot];
    o->mesh = w->mesh[slot] = mesh;
    memcpy(o->mlo, mesh->lo, sizeof o->mlo);
    memcpy(o->mhi, mesh->hi, sizeof o->mhi);
    forget_home(w, slot);
    o->speed = speed;
    for (int k = 0; k < 3; ++k) {
        w->pos[slot][k] = position[k];
        o->vel[k] = speed * unit[k];
    }
    w->gen[slot] = w->gen[slot] + 1 ? w->gen[slot] + 1 : 1;
    o->alive = true;
    o->nspans = 0;
    place_box(o, w->pos[slot], &w->box[slot]);
    if (mesh->has_box)
        noct_box_slot_fill(mesh, &w->slot[slot]);
    else
        w->slot[slot].has_box = 0;
    ++w->alive;
    w->moving += speed > 0;
    w->movers_stale = w->movers_stale || speed > 0;
    id->index = slot;
    id->generation = w->gen[slot];
    noctStatus st;
    if (w->root == NULL || !inside_root(w, &w->box[slot]))
        st = rebuild(w, w->root ? 2 * cell_of(w->root)->size : 0);
    else if (!insert_below(w, w->root, slot, false, true)) {
        st = NOCT_ERR_NOMEM;
        drop_tree(w); /* a split may have failed halfway */
    } else
        st = NOCT_OK;
    if (st != NOCT_OK) {
        /* Not added: the tree, torn down with its spans, is owed to the
         * next step, and the slot is free again. */
        o->alive = false;
        --w->alive;
        w->moving -= speed > 0;
        NOCT_INVARIANT(w->nfree < w->capfree);
        w->free_slots[w->nfree++] = slot;
        w->tree_owed = w->alive > 0;
        id->index = 0;
        id->generation = 0;
        return noct_fail(err, st, -1, 0, "out of memory");
    }
    return NOCT_OK;
}

noctStatus noctWorldRemove(noctWorld *w, noctObjectId id)
{
    NOCT_REQUIRE(w != NULL);
    object *o = lookup(w, id);
    if (o == NULL)
        return NOCT_ERR_INVALID;
    /* Nothing below allocates (try_merge, free_slots' room was made
     * with the slot's), so a removal is whole. */
    while (o->nspans > 0)
        leaf_remove_at(w, o->spans[0].leaf, o->spans[0].at);
    o->alive = false;
    --w->alive;
    w->moving -= o->speed > 0;
    w->movers_stale = w->movers_stale || o->speed > 0;
    NOCT_INVARIANT(w->nfree < w->capfree);
    w->free_slots[w->nfree++] = id.index;
    /* Drop its pairs from the lists a caller may read. */
    pair_list *lists[2] = {&w->colliding, &w->previous};
    for (int l = 0; l < 2; ++l) {
        size_t k = 0;
        for (size_t i = 0; i < lists[l]->n; ++i)
            if (lists[l]->p[i].a.index != id.index && lists[l]->p[i].b.index != id.index)
                lists[l]->p[k++] = lists[l]->p[i];
        lists[l]->n = k;
    }
    w->began.n = w->ended.n = 0;
    return NOCT_OK;
}

/*
 * Keep a mover's position before the motion, for roll_back: 24 bytes a
 * mover that are written every step and read only after a failure, so on
 * x86-64 they are streamed past the cache (non-temporal stores) rather
 * than fetched into it to be written (the motion loop is bound by memory
 * in large worlds). The array holds the doubles' bits.
 */
static NOCT_ALWAYS_INLINE void keep_position(int64_t dst[3], const double p[3])
{
    int64_t b[3];
    memcpy(b, p, sizeof b);
#if defined(__x86_64__) && defined(__SSE2__)
    _mm_stream_si64((long long *)&dst[0], b[0]);
    _mm_stream_si64((long long *)&dst[1], b[1]);
    _mm_stream_si64((long long *)&dst[2], b[2]);
#else
    memcpy(dst, b, sizeof b);
#endif
}

/*
 * Motion: each mover's position advances by fraction of its velocity
 * (times 1 is exact, so a whole step adds the velocity itself), walls
 * turn it back, and its box is placed. With incremental maintenance
 * (fast true) the loop also runs maintenance's fast test on the new
 * position while it is in registers: an object that fails it keeps its
 * old box, for maintenance, and joins w->slow. Returns the first mover
 * beyond NOCT_MAX_COORDINATE, or UINT32_MAX. One that passed the fast
 * test is not (home_of() keeps its positions within the limit), so with
 * it only the slow ones are checked, after the loop; without it the check
 * is gathered over the loop. With save (the first sub-step of a step),
 * the old positions and the velocity components the walls turn are kept
 * for roll_back. The loop's other branches are the fast test's, which
 * almost every object passes, and the walls', decided outside it (walls,
 * fast and save are constants where it is inlined).
 */
static NOCT_ALWAYS_INLINE uint32_t move(noctWorld *w, double fraction, bool walls, bool fast,
                                        bool save)
{
    const double wlo[3] = {w->def.walls_lo[0], w->def.walls_lo[1], w->def.walls_lo[2]};
    const double whi[3] = {w->def.walls_hi[0], w->def.walls_hi[1], w->def.walls_hi[2]};
    object *obj = w->obj;
    aabb *box = w->box;
    const home_block *home = w->home;
    double(*pos)[3] = w->pos;
    int64_t(*prev)[3] = w->prev;
    uint64_t *flips = w->flips;
    uint32_t nflips = 0;
    const uint32_t *movers = w->movers;
    uint32_t *slow = w->slow;
    const uint32_t nm = w->nmovers;
    uint32_t nslow = 0;
    bool beyond = false;
    for (uint32_t m = 0; m < nm; ++m) {
        const uint32_t i = movers[m];
        object *o = &obj[i];
        double *p = pos[i];
        const double x = p[0] + o->vel[0] * fraction, y = p[1] + o->vel[1] * fraction,
                     z = p[2] + o->vel[2] * fraction;
        if (save)
            keep_position(prev[m], p);
        p[0] = x;
        p[1] = y;
        p[2] = z;
        if (walls)
            for (int k = 0; k < 3; ++k)
                if ((p[k] < wlo[k] && o->vel[k] < 0) || (p[k] > whi[k] && o->vel[k] > 0)) {
                    o->vel[k] = -o->vel[k];
                    if (save)
                        flips[nflips++] = 3 * (uint64_t)m + (uint64_t)k;
                }
        if (!fast)
            beyond |= (fabs(x) > NOCT_MAX_COORDINATE) | (fabs(y) > NOCT_MAX_COORDINATE) |
                      (fabs(z) > NOCT_MAX_COORDINATE);
        else if (!inside_home(p, &home[i])) {
            o->old = box[i];
            slow[nslow++] = i;
        }
        place_box(o, p, &box[i]);
    }
    if (save)
        w->nflips = nflips;
    w->nslow = nslow;
    const uint32_t *check = fast ? slow : movers;
    const uint32_t ncheck = fast ? nslow : beyond ? nm : 0;
    for (uint32_t m = 0; m < ncheck; ++m) {
        const double *p = pos[check[m]];
        if (fabs(p[0]) > NOCT_MAX_COORDINATE || fabs(p[1]) > NOCT_MAX_COORDINATE ||
            fabs(p[2]) > NOCT_MAX_COORDINATE)
            return check[m];
    }
    return UINT32_MAX;
}

/* Has a mover's box left the root? */
static bool movers_escaped(const noctWorld *w)
{
    const aabb root = root_box(w);
    for (uint32_t m = 0; m < w->nmovers; ++m)
        if (!box_within(&w->box[w->movers[m]], &root))
            return true;
    return false;
}

/*
 * After a stage of a step failed: the movers go back to where they were
 * before the step (positions, velocities that walls or responses turned,
 * boxes), and a tree that maintenance or the pair search may have changed
 * halfway, or for positions that no longer hold, is torn down, to be
 * built again by the next step. The caller restores the pair lists. So a
 * failed step leaves no object moved and no structure half-changed.
 */
static void roll_back(noctWorld *w, bool moved, bool tree_touched)
{
    if (moved) {
        /* Velocities: a step of sub-steps kept them whole (responses may
         * have turned them too); a single step turned back what the walls
         * turned. */
        const bool kept = w->substeps > 1;
        for (uint32_t f = 0; f < w->nflips && !kept; ++f) {
            double *v = w->obj[w->movers[w->flips[f] / 3]].vel;
            v[w->flips[f] % 3] = -v[w->flips[f] % 3];
        }
        for (uint32_t m = 0; m < w->nmovers; ++m) {
            const uint32_t i = w->movers[m];
            memcpy(w->pos[i], w->prev[m], sizeof w->pos[i]);
            if (kept)
                memcpy(w->obj[i].vel, w->prevvel[m], sizeof w->obj[i].vel);
            place_box(&w->obj[i], w->pos[i], &w->box[i]);
            forget_home(w, i);
        }
    }
    if (tree_touched && w->root != NULL)
        drop_tree(w);
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
static bool root_too_large(const noctWorld *w)
{
    const octNode *n = w->root;
    for (int level = 0; level < 2; ++level) {
        if (!NOCT_NODE_IS_SPLIT(n))
            return false;
        const octNode *only = NULL;
        for (int i = 0; i < 8; ++i) {
            const octNode *k = NOCT_NODE_CHILD(n, (octDirection)(OCT_LDB + i));
            if (!NOCT_NODE_IS_SPLIT(k) && cell_of(k)->count == 0)
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

/* Sub-steps after the root last grew before it may shrink: a group of
 * objects drifting away grows the root (twice as large, the objects near
 * its corner) and would otherwise shrink it again at once, to grow it a
 * few steps later; so it rebuilds at most about once in this many. */
#define SHRINK_AFTER 64

/* One step, or one of k sub-steps (fraction = 1/k of the velocity). */
static noctStatus substep(noctWorld *w, double fraction, bool first, noctError *err)
{
    ++w->step; /* the stamps' clock: one tick per sub-step */
    noctStatus st = NOCT_OK;
    double t0 = seconds();
    bool moving = (w->def.effects & NOCT_EFFECT_MOTION) != 0 && w->moving > 0;
    if (moving) {
        const aabb root = root_box(w);
        const bool walls = (w->def.effects & NOCT_EFFECT_WALLS) != 0;
        const bool fast = w->def.maintenance != NOCT_MAINTAIN_REBUILD;
        uint32_t far;
        if (!first) /* a later sub-step: roll_back has the step's start */
            far = walls ? move(w, fraction, true, fast, false)
                        : move(w, fraction, false, fast, false);
        else if (fast)
            far = walls ? move(w, fraction, true, true, true)
                        : move(w, fraction, false, true, true);
        else
            far = walls ? move(w, fraction, true, false, true)
                        : move(w, fraction, false, false, true);
        w->moved = true;
        if (far != UINT32_MAX)
            return noct_fail(err, NOCT_ERR_TOO_LARGE, (long)far, 0,
                             "object %u would move beyond %g; no object moved", far,
                             NOCT_MAX_COORDINATE);
        w->c.moved += w->nmovers;
        /* |velocity| is the speed within 1e-9; a placed box moves by it
         * and a few roundings of the root's coordinates. */
        double r = 0;
        for (int k = 0; k < 3; ++k)
            r = noct_max(r, noct_max(fabs(root.lo[k]), fabs(root.hi[k])));
        w->reach = w->vmax * fraction * (1 + 1e-6) + 8 * 0x1p-52 * (isfinite(r) ? r : 0);
    } else {
        w->reach = 0;
    }
    double t1 = seconds();
    if (moving)
        w->c.seconds_motion += t1 - t0;
    w->touched = true; /* from here on, the tree may change */
    if (w->root != NULL && moving) {
        /* A box that left the root makes the tree grow: a rebuild with a
         * root of at least twice the size. */
        bool escaped = false;
        if (w->def.maintenance == NOCT_MAINTAIN_REBUILD)
            escaped = movers_escaped(w);
        else
            st = maintain(w, &escaped);
        if (st == NOCT_OK && (escaped || w->def.maintenance == NOCT_MAINTAIN_REBUILD))
            st = rebuild(w, escaped ? 2 * cell_of(w->root)->size : 0);
        if (escaped)
            w->shrink_from = w->step + SHRINK_AFTER;
        w->c.seconds_maintenance += seconds() - t1;
    }
    /* Objects that went far and came back, or the far ones removed: the
     * root shrinks; merges that lacked memory are made. */
    if (st == NOCT_OK && w->root != NULL && w->step >= w->shrink_from &&
        root_too_large(w))
        st = rebuild(w, 0);
    if (st == NOCT_OK && w->root != NULL && w->merge_owed) {
        w->merge_owed = false;
        merge_all(w, w->root);
    }
    if (st != NOCT_OK)
        return noct_fail(err, st, -1, 0, "octree maintenance: %s; no object moved",
                         noctStatusString(st));
    double t2 = seconds();
    pair_list tmp = w->previous;
    w->previous = w->colliding;
    w->colliding = tmp;
    w->colliding.n = 0;
    w->tested.n = 0;
    if (w->root != NULL && NOCT_NODE_IS_SPLIT(w->root)) {
        st = search(w, w->root, w->nslots >= PREFETCH_OBJECTS);
    } else if (w->root != NULL && cell_of(w->root)->count >= 2) {
        prefetch_boxes(w, cell_of(w->root));
        st = search_leaf(w, cell_of(w->root));
    }
    if (st == NOCT_OK && !sort_tested(w))
        st = NOCT_ERR_NOMEM;
    if (st == NOCT_OK)
        st = narrow(w);
    const size_t from_began = w->began.n;
    if (st == NOCT_OK)
        sort_partners(&w->colliding);
    if (st == NOCT_OK && (w->def.effects & (NOCT_EFFECT_EVENTS | NOCT_EFFECT_RESPONSE)))
        st = diff_events(w);
    if (st != NOCT_OK) {
        /* The search's near pairs and budgets may be half made (the tree
         * goes too); the colliding list is the one before. */
        tmp = w->colliding;
        w->colliding = w->previous;
        w->previous = tmp;
        return noct_fail(err, st, -1, 0, "pair search: %s; no object moved",
                         noctStatusString(st));
    }
    w->c.colliding_pairs += w->colliding.n;
    double t3 = seconds();
    w->c.seconds_pairs += t3 - t2;
    if (w->def.effects & (NOCT_EFFECT_EVENTS | NOCT_EFFECT_RESPONSE)) {
        if (w->def.effects & NOCT_EFFECT_RESPONSE) {
            ++w->epoch;
            for (size_t i = from_began; i < w->began.n; ++i) {
                uint32_t ids[2] = {w->began.p[i].a.index, w->began.p[i].b.index};
                for (int s = 0; s < 2; ++s) {
                    if (w->mark[ids[s]] == w->epoch)
                        continue;
                    w->mark[ids[s]] = w->epoch;
                    for (int k = 0; k < 3; ++k)
                        w->obj[ids[s]].vel[k] = -w->obj[ids[s]].vel[k];
                    ++w->c.reversals;
                }
            }
        }
        w->c.seconds_response += seconds() - t3;
    }
    return NOCT_OK;
}

/* The moving object that moves farthest for its size, and how far:
 * speed over the smallest extent of its mesh's box. */
static double step_ratio(const noctWorld *w, uint32_t *which)
{
    double worst = 0;
    *which = UINT32_MAX;
    for (uint32_t i = 0; i < w->nslots; ++i) {
        const object *o = &w->obj[i];
        if (!o->alive || o->speed == 0)
            continue;
        const noctMesh *m = o->mesh;
        double extent = noct_min(noct_min(m->hi[0] - m->lo[0], m->hi[1] - m->lo[1]),
                                 m->hi[2] - m->lo[2]);
        double r = o->speed / extent;
        if (r > worst) {
            worst = r;
            *which = i;
        }
    }
    return worst;
}

noctStatus noctWorldStep(noctWorld *w, noctError *err)
{
    NOCT_REQUIRE(w != NULL);
    w->began.n = w->ended.n = 0;
    if (w->tree_owed) {
        noctStatus st = rebuild(w, 0);
        if (st != NOCT_OK)
            return noct_fail(err, st, -1, 0, "rebuilding the octree: %s",
                             noctStatusString(st));
    }
    uint64_t k = 1;
    if ((w->def.effects & NOCT_EFFECT_SUBSTEP) && (w->def.effects & NOCT_EFFECT_MOTION)) {
        uint32_t which;
        const double ratio = step_ratio(w, &which);
        /* Each sub-step moves every object at most half its smallest size. */
        if (ratio > 0.5) {
            if (!(2 * ratio <= (double)NOCT_MAX_SUBSTEPS))
                return noct_fail(err, NOCT_ERR_TOO_LARGE, (long)which, 0,
                                 "object %u moves %g times its smallest size a step; "
                                 "sub-steps of half its size would be more than %u",
                                 which, ratio, (unsigned)NOCT_MAX_SUBSTEPS);
            k = (uint64_t)ceil(2 * ratio);
        }
        w->c.substeps += k;
    }
    /* A step of sub-steps that fails goes back to the step's start: its
     * colliding list is kept aside (the sub-steps replace it). */
    if (k > 1) {
        pair_list *h = &w->held;
        if (h->cap < w->colliding.n) {
            noctPair *q = realloc(h->p, w->colliding.n * sizeof *q);
            if (q == NULL)
                return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
            h->p = q;
            h->cap = w->colliding.n;
        }
        if (w->colliding.n > 0)
            memcpy(h->p, w->colliding.p, w->colliding.n * sizeof *h->p);
        h->n = w->colliding.n;
    }
    if ((w->def.effects & NOCT_EFFECT_MOTION) && w->moving > 0 && !update_movers(w))
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    w->substeps = k;
    if (k > 1 && (w->def.effects & NOCT_EFFECT_MOTION))
        for (uint32_t m = 0; m < w->nmovers; ++m)
            memcpy(w->prevvel[m], w->obj[w->movers[m]].vel, sizeof w->prevvel[m]);
    ++w->c.steps;
    w->moved = w->touched = false;
    for (uint64_t i = 0; i < k; ++i) {
        noctStatus st = substep(w, k == 1 ? 1 : 1.0 / (double)k, i == 0, err);
        if (st != NOCT_OK) {
            roll_back(w, w->moved, w->touched);
            if (k > 1) {
                pair_list t = w->colliding;
                w->colliding = w->held;
                w->held = t;
            }
            w->began.n = w->ended.n = 0;
            return st;
        }
    }
    return NOCT_OK;
}

size_t noctWorldColliding(const noctWorld *w, const noctPair **pairs)
{
    NOCT_REQUIRE(w != NULL && pairs != NULL);
    *pairs = w->colliding.p;
    return w->colliding.n;
}

size_t noctWorldBegan(const noctWorld *w, const noctPair **pairs)
{
    NOCT_REQUIRE(w != NULL && pairs != NULL);
    *pairs = w->began.p;
    return w->began.n;
}

size_t noctWorldEnded(const noctWorld *w, const noctPair **pairs)
{
    NOCT_REQUIRE(w != NULL && pairs != NULL);
    *pairs = w->ended.p;
    return w->ended.n;
}

noctStatus noctWorldObject(const noctWorld *w, noctObjectId id, double position[3],
                           double direction[3])
{
    NOCT_REQUIRE(w != NULL);
    const object *o = lookup(w, id);
    if (o == NULL)
        return NOCT_ERR_INVALID;
    if (position != NULL)
        memcpy(position, w->pos[id.index], sizeof w->pos[id.index]);
    if (direction != NULL)
        for (int k = 0; k < 3; ++k)
            direction[k] = o->speed > 0 ? o->vel[k] / o->speed : 0;
    return NOCT_OK;
}

size_t noctWorldObjectCount(const noctWorld *w)
{
    NOCT_REQUIRE(w != NULL);
    return w->alive;
}

void noctWorldGetCounters(const noctWorld *w, noctWorldCounters *counters)
{
    NOCT_REQUIRE(w != NULL && counters != NULL);
    *counters = w->c;
}

double noctWorldMaxStepRatio(const noctWorld *w)
{
    NOCT_REQUIRE(w != NULL);
    uint32_t which;
    return step_ratio(w, &which);
}

octNode *noctWorldRoot(const noctWorld *w)
{
    NOCT_REQUIRE(w != NULL);
    return w->root;
}

void noctWorldPrintCell(FILE *strm, const void *data)
{
    NOCT_REQUIRE(strm != NULL && data != NULL);
    const cell *c = data;
    fprintf(strm, "lo (%.10g, %.10g, %.10g) size %.10g", c->lo[0], c->lo[1], c->lo[2],
            c->size);
    if (c->count > 0) {
        fprintf(strm, "; objects");
        for (uint32_t i = 0; i < c->count; ++i)
            fprintf(strm, " %u", c->objs[i]);
    }
}

size_t noctWorldCell(const noctWorld *w, const octNode *node, double lo[3], double *size,
                     noctObjectId *objects, size_t max)
{
    NOCT_REQUIRE(w != NULL && node != NULL && (objects != NULL || max == 0));
    const cell *c = cell_of(node);
    if (lo != NULL)
        memcpy(lo, c->lo, sizeof c->lo);
    if (size != NULL)
        *size = c->size;
    for (uint32_t i = 0; i < c->count && i < max; ++i)
        objects[i] = (noctObjectId){c->objs[i], w->gen[c->objs[i]]};
    return c->count;
}

noctStatus noctWorldObjectBox(const noctWorld *w, noctObjectId id, double lo[3],
                              double hi[3])
{
    NOCT_REQUIRE(w != NULL && lo != NULL && hi != NULL);
    const object *o = lookup(w, id);
    if (o == NULL)
        return NOCT_ERR_INVALID;
    memcpy(lo, w->box[id.index].lo, sizeof o->old.lo);
    memcpy(hi, w->box[id.index].hi, sizeof o->old.hi);
    return NOCT_OK;
}

/* ---- meshes the scene families make (families.c) ------------------------- */

bool noct_world_reserve_meshes(noctWorld *w, size_t more)
{
    if (w->nowned + more <= w->capowned)
        return true;
    const size_t cap = w->nowned + more;
    noctMesh **q = realloc(w->owned, cap * sizeof *q);
    if (q == NULL)
        return false;
    w->owned = q;
    w->capowned = cap;
    return true;
}

void noct_world_own_mesh(noctWorld *w, noctMesh *mesh)
{
    NOCT_INVARIANT(w->nowned < w->capowned);
    w->owned[w->nowned++] = mesh;
}

size_t noct_world_owned_meshes(const noctWorld *w)
{
    return w->nowned;
}

void noct_world_destroy_meshes_from(noctWorld *w, size_t from)
{
    while (w->nowned > from)
        noctMeshDestroy(w->owned[--w->nowned]);
}

/* ---- validation walk ----------------------------------------------------------- */

#define BAD(...) noct_fail(err, NOCT_ERR_INVARIANT, -1, 0, __VA_ARGS__)

/* The walk's scratch: per object, the leaves that list it, and the last
 * leaf (numbered as met) that did, to find an object listed twice. */
typedef struct walk {
    size_t *refs;
    size_t *seen;
    size_t leaves;
} walk;

static noctStatus validate_node(const noctWorld *w, octNode *n, walk *v, noctError *err)
{
    const cell *c = cell_of(n);
    if (c == NULL)
        return BAD("a node has no cell");
    if (NOCT_NODE_IS_SPLIT(n)) {
        if (c->count != 0)
            return BAD("an inner node holds objects");
        bool all_leaves = true;
        for (int i = 0; i < 8; ++i) {
            octNode *k = NOCT_NODE_CHILD(n, (octDirection)(OCT_LDB + i));
            const cell *kc = cell_of(k);
            if (kc == NULL)
                return BAD("a node has no cell");
            if (kc->size != c->size / 2 ||
                kc->lo[0] != c->lo[0] + ((i & 4) ? c->size / 2 : 0) ||
                kc->lo[1] != c->lo[1] + ((i & 2) ? c->size / 2 : 0) ||
                kc->lo[2] != c->lo[2] + ((i & 1) ? c->size / 2 : 0))
                return BAD("child %d's cell does not match its parent's", i);
            if (NOCT_NODE_PARENT(k) != n || octGeneration(k) != octGeneration(n) + 1)
                return BAD("child %d's links are wrong", i);
            noctStatus st = validate_node(w, k, v, err);
            if (st != NOCT_OK)
                return st;
            all_leaves = all_leaves && !NOCT_NODE_IS_SPLIT(k);
        }
        if (all_leaves && w->def.maintenance == NOCT_MAINTAIN_INCREMENTAL && !w->merge_owed &&
            w->def.N != NOCT_N_EXHAUSTIVE) {
            /* distinct objects among the 8 leaves, counted up to N + 1 */
            ++v->leaves;
            size_t distinct = 0;
            for (int i = 0; i < 8 && distinct <= (size_t)w->def.N; ++i) {
                const cell *kc = cell_of(NOCT_NODE_CHILD(n, (octDirection)(OCT_LDB + i)));
                for (uint32_t j = 0; j < kc->count; ++j)
                    if (v->seen[kc->objs[j]] != v->leaves) {
                        v->seen[kc->objs[j]] = v->leaves;
                        ++distinct;
                    }
            }
            if (distinct <= (size_t)w->def.N)
                return BAD("siblings at generation %d hold %zu distinct objects "
                           "(N = %d) but were not merged", octGeneration(n) + 1, distinct,
                           w->def.N);
        }
        return NOCT_OK;
    }
    ++v->leaves;
    uint32_t small = 0;
    for (uint32_t j = 0; j < c->count; ++j) {
        uint32_t id = c->objs[j];
        if (id >= w->nslots || !w->obj[id].alive)
            return BAD("a leaf lists a dead object %u", id);
        if (v->seen[id] == v->leaves)
            return BAD("a leaf lists object %u twice", id);
        v->seen[id] = v->leaves;
        if (!overlaps(&w->box[id], c))
            return BAD("object %u is in a leaf its box does not overlap", id);
        const object *o = &w->obj[id];
        const uint32_t b = back_of(c)[j];
        if (b >= o->nspans || o->spans[b].leaf != n || o->spans[b].at != j)
            return BAD("object %u's entry for a leaf does not point back to it", id);
        small += splits_for(o, c->size);
        ++v->refs[id];
    }
    if (small != c->small)
        return BAD("a leaf counts %u objects small enough to split for; they are %u",
                   c->small, small);
    if ((int)small > w->def.N && octGeneration(n) < w->def.max_depth)
        return BAD("a leaf at generation %d holds %u objects it could split for (N = %d)",
                   octGeneration(n), small, w->def.N);
    return NOCT_OK;
}

/* Count the leaves under n that box o overlaps. */
static size_t overlapped_leaves(const aabb *o, octNode *n)
{
    if (!overlaps(o, cell_of(n)))
        return 0;
    if (!NOCT_NODE_IS_SPLIT(n))
        return 1;
    size_t s = 0;
    for (int i = 0; i < 8; ++i)
        s += overlapped_leaves(o, NOCT_NODE_CHILD(n, (octDirection)(OCT_LDB + i)));
    return s;
}

noctStatus noctWorldValidate(const noctWorld *w, noctError *err)
{
    NOCT_REQUIRE(w != NULL);
    if (w->root == NULL)
        return w->alive == 0 || w->tree_owed ? NOCT_OK : BAD("objects but no tree");
    if (NOCT_NODE_PARENT(w->root) != NULL || octGeneration(w->root) != 0)
        return BAD("the root is not a root");
    const size_t n = w->nslots ? w->nslots : 1;
    walk v = {calloc(n, sizeof *v.refs), calloc(n, sizeof *v.seen), 0};
    noctStatus st = NOCT_OK;
    if (v.refs == NULL || v.seen == NULL)
        st = noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    if (st == NOCT_OK)
        st = validate_node(w, w->root, &v, err);
    for (uint32_t i = 0; i < w->nslots && st == NOCT_OK; ++i) {
        const object *o = &w->obj[i];
        if (!o->alive)
            continue;
        const aabb *b = &w->box[i];
        const home_block *h = &w->home[i];
        if (!inside_root(w, b))
            st = BAD("object %u is outside the root", i);
        else if (v.refs[i] != o->nspans)
            st = BAD("object %u: %zu leaves list it, its spans count %u", i, v.refs[i],
                     o->nspans);
        else if (overlapped_leaves(b, w->root) != v.refs[i])
            st = BAD("object %u is in %zu leaves but its box overlaps %zu", i, v.refs[i],
                     overlapped_leaves(b, w->root));
        else if (isfinite(h->lo[0])) {
            home_block now;
            if (!home_of(w, i, b, &now) || memcmp(&now, h, sizeof now) != 0)
                st = BAD("object %u's home block is not that of its leaves", i);
        }
    }
    free(v.refs);
    free(v.seen);
    return st;
}
