/* SPDX-License-Identifier: MIT */
/*
 * The broadphase's queries: the proxies whose boxes overlap a box or
 * contain a point, and those a segment meets, in order along it.
 *
 * A box query reports each proxy once, in the one leaf that owns the
 * lower corner of the overlap of its box and the query's (the pair
 * search's rule, broadphase_pairs.c): that corner lies in both boxes, so
 * the leaf that owns it overlaps both and lists the proxy.
 */
#include "config.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "broadphase_internal.h"

static bool passes(const noct_proxy *o, noctQueryFilter f)
{
    return (o->category & f.mask) != 0 && (f.category & o->mask) != 0;
}

typedef struct box_query {
    const noctBroadphase *bp;
    noct_aabb q;
    noctQueryFilter filter;
    noctQueryFcn *fcn;
    void *context;
} box_query;

/* false: the callback stopped the query */
static bool query_node(const box_query *bq, const octNode *n)
{
    const noct_cell *c = noct_cell_of(n);
    if (!noct_overlaps(&bq->q, c))
        return true;
    if (NOCT_NODE_IS_SPLIT(n)) {
        for (int i = 0; i < 8; ++i)
            if (!query_node(bq, NOCT_NODE_CHILD(n, (octDirection)(OCT_LDB + i))))
                return false;
        return true;
    }
    const noctBroadphase *bp = bq->bp;
    const noct_cell *rc = noct_cell_of(bp->root);
    for (uint32_t j = 0; j < c->count; ++j) {
        const uint32_t id = c->objs[j];
        const noct_aabb *b = &bp->box[id];
        bool apart = false;
        double corner[3];
        for (int k = 0; k < 3; ++k) {
            apart = apart || b->hi[k] < bq->q.lo[k] || bq->q.hi[k] < b->lo[k];
            corner[k] = noct_max(b->lo[k], bq->q.lo[k]);
        }
        if (apart || !noct_cell_owns(c, rc, corner) || !passes(&bp->proxy[id], bq->filter))
            continue;
        if (!bq->fcn(bq->context, (noctProxyId){id, bp->gen[id]}, bp->proxy[id].user))
            return false;
    }
    return true;
}

noctStatus noctBroadphaseQueryBox(const noctBroadphase *bp, const double lo[3],
                                  const double hi[3], noctQueryFilter filter,
                                  noctQueryFcn *fcn, void *context)
{
    NOCT_REQUIRE(bp != NULL && lo != NULL && hi != NULL && fcn != NULL);
    for (int k = 0; k < 3; ++k)
        if (isnan(lo[k]) || isnan(hi[k]))
            return NOCT_ERR_NONFINITE;
    for (int k = 0; k < 3; ++k)
        if (!(lo[k] <= hi[k]))
            return NOCT_ERR_INVALID;
    box_query bq = {bp, {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}}, filter, fcn, context};
    if (bp->root != NULL) {
        query_node(&bq, bp->root);
        return NOCT_OK;
    }
    /* No tree (a failure tore it down; the next change rebuilds it): every
     * proxy is asked. */
    for (uint32_t id = 0; id < bp->nslots; ++id) {
        const noct_aabb *b = &bp->box[id];
        if (!bp->proxy[id].alive || !passes(&bp->proxy[id], filter))
            continue;
        bool apart = false;
        for (int k = 0; k < 3; ++k)
            apart = apart || b->hi[k] < lo[k] || hi[k] < b->lo[k];
        if (!apart && !fcn(context, (noctProxyId){id, bp->gen[id]}, bp->proxy[id].user))
            break;
    }
    return NOCT_OK;
}

noctStatus noctBroadphaseQueryPoint(const noctBroadphase *bp, const double p[3],
                                    noctQueryFilter filter, noctQueryFcn *fcn, void *context)
{
    NOCT_REQUIRE(bp != NULL && p != NULL && fcn != NULL);
    for (int k = 0; k < 3; ++k)
        if (!isfinite(p[k]))
            return NOCT_ERR_NONFINITE;
    return noctBroadphaseQueryBox(bp, p, p, filter, fcn, context);
}

/* ---- the nearest ----------------------------------------------------------------- */

/*
 * The walk for the nearest object (noct_bp_nearest()). Each proxy is
 * handed over by one leaf only: the one that owns its anchor, the point
 * of its box nearest the query's box on each axis, min(max(blo, lo), bhi)
 * (a corner's coordinate of the box, or of their overlap). The anchor
 * lies in the box, so the leaf that owns it lists the proxy; and the
 * anchor's gap to [lo, hi] on each axis is the box's, while the owning
 * cell reaches at least to the anchor: the cell's rounded differences
 * are no larger than the box's (rounding is monotone), so its
 * noct_gap2() is at most the box's, and so is each ancestor's. A proxy
 * within the bound when its leaf comes is therefore never behind a cell
 * the walk skipped: the bound only shrinks, so a cell skipped earlier
 * was beyond a bound at least as large.
 *
 * Within a leaf the boxes within the bound are gathered in one pass (the
 * leaf's list and their boxes only), then taken nearest first (least
 * gap, then least index) by passes that also drop what the bound has
 * come to exclude: the first hand-over usually shrinks the bound to a
 * few boxes. Should many passes be needed (boxes owned elsewhere, or an
 * answer at distance 0 with many boxes tied), the rest are sorted once,
 * so that a leaf costs O(n log n) at worst.
 */

typedef struct near_cand {
    double g2;
    uint32_t id;
} near_cand;

static inline bool near_before(const near_cand *a, const near_cand *b)
{
    return a->g2 < b->g2 || (a->g2 == b->g2 && a->id < b->id);
}

static int near_order(const void *x, const void *y)
{
    const near_cand *a = x, *b = y;
    return near_before(a, b) ? -1 : near_before(b, a) ? 1 : 0;
}

/* The boxes of a leaf on the stack (N is 128 at most by default), more on
 * the heap; after this many passes over more than NEAR_SORT boxes, a sort.
 * A leaf's boxes are requested NEAR_AHEAD ahead of its scan (16 and 32
 * measured alike, both well ahead of none: docs/results.md). */
#define NEAR_LOCAL 160
#define NEAR_PASSES 4
#define NEAR_SORT 32
#define NEAR_AHEAD 32

NOCT_DEFINE_GROW_LOCAL(grow_near, near_cand)

typedef struct near_walk {
    const noctBroadphase *bp;
    const noct_cell *rc; /* the root's cell; NULL without a tree */
    double lo[3], hi[3], centre[3];
    noctQueryFilter filter;
    bool filtering; /* some proxy may fail the filter */
    const noct_nearest_bound *bound;
    noct_nearest_fcn *fcn;
    void *context;
    bool failed; /* without memory */
    bool cut;    /* something left out for the bound */
    near_cand *c;
    size_t cap;
    near_cand local[NEAR_LOCAL];
} near_walk;

/* Hand x over if leaf (NULL: no tree) owns its anchor; false: stop. */
static bool near_hand(near_walk *nw, near_cand x, const noct_cell *leaf)
{
    if (leaf != NULL) {
        const noct_aabb *b = &nw->bp->box[x.id];
        double a[3];
        for (int k = 0; k < 3; ++k)
            a[k] = noct_min(noct_max(b->lo[k], nw->lo[k]), b->hi[k]);
        if (!noct_cell_owns(leaf, nw->rc, a))
            return true;
    }
    return nw->fcn(nw->context, x.id, x.g2);
}

/* Take the n gathered boxes nearest first; false: stop. */
static bool near_take(near_walk *nw, size_t n, const noct_cell *leaf)
{
    near_cand *c = nw->c;
    const noct_nearest_bound *bd = nw->bound;
    for (int pass = 0; n > 0; ++pass) {
        if (pass == NEAR_PASSES && n > NEAR_SORT) {
            qsort(c, n, sizeof *c, near_order);
            for (size_t i = 0; i < n && c[i].g2 <= bd->gap2; ++i)
                if (c[i].id < bd->below && !near_hand(nw, c[i], leaf))
                    return false;
            return true;
        }
        size_t kept = 0, m = 0;
        for (size_t i = 0; i < n; ++i) {
            if (c[i].g2 > bd->gap2 || c[i].id >= bd->below)
                continue;
            c[kept] = c[i];
            if (near_before(&c[kept], &c[m]))
                m = kept;
            ++kept;
        }
        if (kept == 0)
            break;
        const near_cand x = c[m];
        c[m] = c[--kept];
        n = kept;
        if (!near_hand(nw, x, leaf))
            return false;
    }
    return true;
}

/* Add box id of squared gap g2 to the walk's list of n; false without
 * memory. */
static inline bool near_push(near_walk *nw, size_t *n, uint32_t id, double g2)
{
    if (!grow_near(&nw->c, nw->local, &nw->cap, *n + 1)) {
        nw->failed = true;
        return false;
    }
    nw->c[(*n)++] = (near_cand){g2, id};
    return true;
}

/* A leaf's scan of one box: its noct_gap2() to [lo, hi] when it is within
 * bound, else +inf (and *cut set). First the axes alone: when a rounded
 * difference exceeds rk, its square rounds above the bound (rk's square
 * does, see near_leaf()), and so does the sum of squares, which is at
 * least each of its terms; the gap need not be computed. The six
 * differences are taken together, their largest against rk: one branch,
 * which the few boxes within the bound make predictable, where a branch
 * per axis went either way at random (the scan's boxes are requested
 * ahead, both lines). */
static NOCT_ALWAYS_INLINE double near_scan(const double lo[3], const double hi[3],
                                           const noct_aabb *b, double rk, double bound,
                                           bool *cut)
{
    const double m0 = noct_max(b->lo[0] - hi[0], lo[0] - b->hi[0]);
    const double m1 = noct_max(b->lo[1] - hi[1], lo[1] - b->hi[1]);
    const double m2 = noct_max(b->lo[2] - hi[2], lo[2] - b->hi[2]);
    if (noct_max(m0, noct_max(m1, m2)) > rk) {
        *cut = true;
        return INFINITY;
    }
    const double g2 = noct_gap2(lo, hi, b->lo, b->hi);
    if (g2 > bound) {
        *cut = true;
        return INFINITY;
    }
    return g2;
}

/* Request box id's lines: the scan reads every box of a leaf, scattered
 * over the slots' array (4.8 MB on gas 100 000), and a query spends most
 * of its time waiting for them unless they are asked for ahead. */
static NOCT_ALWAYS_INLINE void near_ask(const noct_aabb *box, uint32_t id)
{
    const char *b = (const char *)&box[id];
    NOCT_PREFETCH(b);
    NOCT_PREFETCH(b + sizeof(noct_aabb) - 1);
}

/* The boxes of list ids[0..count) (NULL: every live slot) within the
 * bound, taken nearest first; false: stop. The bound holds still while
 * they are gathered (fcn is not called), and the query's box is read
 * into locals, which the list's stores cannot change. A list's boxes
 * are requested NEAR_AHEAD ahead of the scan (a slot array in order is
 * read in order: no need). */
static bool near_leaf(near_walk *nw, const uint32_t *ids, uint32_t count, const noct_cell *leaf)
{
    const noctBroadphase *bp = nw->bp;
    const noct_aabb *box = bp->box;
    const double lo[3] = {nw->lo[0], nw->lo[1], nw->lo[2]};
    const double hi[3] = {nw->hi[0], nw->hi[1], nw->hi[2]};
    const double bound = nw->bound->gap2, done = nw->bound->done2;
    const uint32_t below = nw->bound->below;
    /* rk: fl(sqrt(bound)) >= (1 - u) sqrt(bound) (u = 2^-53), so
     * rk >= (1 + 2^-51) sqrt(bound) and fl(rk^2) >= (1 + 2^-50)(1 - u)
     * bound > bound (bound is at least 2^-990, a normal number; +inf
     * stays +inf). */
    const double rk = sqrt(bound) * (1 + 0x1p-50);
    bool cut = false;
    size_t n = 0;
    if (ids == NULL) {
        for (uint32_t id = 0; id < count; ++id) {
            if (!bp->proxy[id].alive)
                continue;
            const double g2 = near_scan(lo, hi, &box[id], rk, bound, &cut);
            if (g2 <= bound && g2 > done && id < below && passes(&bp->proxy[id], nw->filter) &&
                !near_push(nw, &n, id, g2))
                return false;
        }
    } else if (nw->filtering) {
        for (uint32_t j = 0; j < count && j < NEAR_AHEAD; ++j)
            near_ask(box, ids[j]);
        for (uint32_t j = 0; j < count; ++j) {
            const uint32_t id = ids[j];
            if (j + NEAR_AHEAD < count)
                near_ask(box, ids[j + NEAR_AHEAD]);
            const double g2 = near_scan(lo, hi, &box[id], rk, bound, &cut);
            if (g2 <= bound && g2 > done && id < below && passes(&bp->proxy[id], nw->filter) &&
                !near_push(nw, &n, id, g2))
                return false;
        }
    } else {
        for (uint32_t j = 0; j < count && j < NEAR_AHEAD; ++j)
            near_ask(box, ids[j]);
        for (uint32_t j = 0; j < count; ++j) {
            const uint32_t id = ids[j];
            if (j + NEAR_AHEAD < count)
                near_ask(box, ids[j + NEAR_AHEAD]);
            const double g2 = near_scan(lo, hi, &box[id], rk, bound, &cut);
            if (g2 <= bound && g2 > done && id < below && !near_push(nw, &n, id, g2))
                return false;
        }
    }
    nw->cut = nw->cut || cut;
    return near_take(nw, n, leaf);
}

/* The walk below node n (not beyond the bound); false: stop. */
static bool near_node(near_walk *nw, const octNode *n)
{
    const noct_cell *c = noct_cell_of(n);
    if (!NOCT_NODE_IS_SPLIT(n))
        return near_leaf(nw, c->objs, c->count, c);
    /* A child's cube is its parent's lower or upper half on each axis,
     * exactly (the corners are exact): the squares of each half's gap,
     * sq[k][0] and sq[k][1], are noct_gap2()'s terms for every child, so
     * a child's sum below is noct_gap2() of its cube, bit for bit. */
    const double half = c->size / 2;
    double sq[3][2];
    unsigned o = 0; /* the child that holds the centre (or is nearest it) first */
    for (int k = 0; k < 3; ++k) {
        const double mid = c->lo[k] + half, top = c->lo[k] + c->size;
        const double g0 = noct_max(noct_max(c->lo[k] - nw->hi[k], nw->lo[k] - mid), 0);
        const double g1 = noct_max(noct_max(mid - nw->hi[k], nw->lo[k] - top), 0);
        sq[k][0] = g0 * g0;
        sq[k][1] = g1 * g1;
        o |= (nw->centre[k] >= mid ? 4u : 0u) >> k;
    }
    for (unsigned i = 0; i < 8; ++i) {
        const unsigned j = i ^ o;
        const double g2 = sq[0][j >> 2] + sq[1][(j >> 1) & 1u] + sq[2][j & 1u];
        if (g2 > nw->bound->gap2) {
            nw->cut = true;
            continue;
        }
        if (!near_node(nw, NOCT_NODE_CHILD(n, (octDirection)(OCT_LDB + (int)j))))
            return false;
    }
    return true;
}

noctStatus noct_bp_nearest(const noctBroadphase *bp, const double lo[3], const double hi[3],
                           const double centre[3], noctQueryFilter filter,
                           const noct_nearest_bound *bound, noct_nearest_fcn *fcn,
                           void *context, bool *cut)
{
    near_walk nw;
    nw.bp = bp;
    nw.rc = bp->root != NULL ? noct_cell_of(bp->root) : NULL;
    memcpy(nw.lo, lo, sizeof nw.lo);
    memcpy(nw.hi, hi, sizeof nw.hi);
    memcpy(nw.centre, centre, sizeof nw.centre);
    nw.filter = filter;
    /* without filters on the proxies, all bits in the query's pass all */
    nw.filtering = bp->filtered > 0 || filter.category != NOCT_FILTER_ALL ||
                   filter.mask != NOCT_FILTER_ALL;
    nw.bound = bound;
    nw.fcn = fcn;
    nw.context = context;
    nw.failed = false;
    nw.cut = false;
    nw.c = nw.local;
    nw.cap = NEAR_LOCAL;
    if (bp->root != NULL)
        near_node(&nw, bp->root);
    else /* no tree (a failure tore it down): every proxy, as one leaf */
        near_leaf(&nw, NULL, bp->nslots, NULL);
    if (nw.c != nw.local)
        free(nw.c);
    *cut = nw.cut;
    return nw.failed ? NOCT_ERR_NOMEM : NOCT_OK;
}

/* ---- segments -------------------------------------------------------------------- */

/* Where the segment o + t d, t in [0, tmax], meets the closed box
 * [lo, hi]: its first t, or -1 if it does not. Every box and cell goes
 * through this one function, so that their t agree where faces do. */
static double enter_at(const double o[3], const double d[3], const double lo[3],
                       const double hi[3], double tmax)
{
    double t0 = 0, t1 = tmax;
    for (int k = 0; k < 3; ++k) {
        if (d[k] == 0) {
            if (o[k] < lo[k] || o[k] > hi[k])
                return -1;
            continue;
        }
        double a = (lo[k] - o[k]) / d[k], b = (hi[k] - o[k]) / d[k];
        if (a > b) {
            const double t = a;
            a = b;
            b = t;
        }
        t0 = noct_max(t0, a);
        t1 = noct_min(t1, b);
        if (t0 > t1)
            return -1;
    }
    return t0;
}

/*
 * The walk. Cells come out of a heap in order of their entry fractions
 * (a split node's children go in as it comes out, and none is entered
 * before its parent), so leaves come in order of entry. A leaf's boxes
 * go into a second heap in order of (t, index), and a hit goes to fcn as
 * soon as no cell still to come can hold one before it: when its t is
 * below E, the least entry in the cell heap. The walk ends when E is
 * beyond the clip, the largest fraction fcn left.
 *
 * Why no rounding margin is needed. For an axis with d != 0, enter_at
 * takes fl(fl(x - o) / d) at each face x of a box, a monotone function
 * f_k of x (rounding is monotone; f_k decreases for d < 0), so a box's
 * computed slab on that axis is [f_k(lo), f_k(hi)] (or reversed). Hence:
 *
 * (a) A cube within another (its faces within the other's, as doubles)
 *     is entered no earlier and left no later: a child's entry is at
 *     least its parent's, and a cell that is not met has no descendant
 *     that is. Cell corners are exact (NOCT_CELL_RESOLUTION), so children
 *     lie within their parents and the leaves tile the root.
 * (b) A box B the segment meets at a computed t is listed by a leaf C
 *     with entry(C) <= t <= exit(C), where the walk gets before any cell
 *     entered after t. Per axis: for d > 0 take x_k the largest double in
 *     [B.lo, B.hi] with f_k(x_k) <= t (B.lo is one); for d < 0 the
 *     smallest; for d = 0, o_k (in B). Let C be the leaf whose closed cube
 *     holds the point x and which, on the axes where x_k is not B's far
 *     face (B.hi for d > 0), reaches past x_k in the direction of d (the
 *     leaves tile the root, which holds B, so there is one: the leaf of
 *     the points just past x). Then f_k(C.lo) <= f_k(x_k) <= t (for
 *     d > 0), and f_k(C.hi) >= t: either C.hi >= B.hi, or C.hi is a double
 *     in (x_k, B.hi] and f_k(C.hi) > t by the choice of x_k; d < 0 is the
 *     mirror. C holds x, a point of B, so it lists B (leaves list exactly
 *     the boxes that overlap them, and the root holds every box:
 *     noctBroadphaseValidate()), and by (a) its ancestors are met too,
 *     entered no later than C.
 *
 * So when the least entry left is E, every box met at a t < E has been
 * gathered, and a hit with t < E is the next, in (t, index) order, of
 * all the hits: the output is that of gathering every leaf and sorting,
 * bit for bit. Copies of a box in several leaves: every leaf entered at
 * or before its t adds a copy with the same t while the first still
 * waits (it waits until E > t), so the copies leave the heap one after
 * another and all but the first are dropped; a leaf entered after the
 * box's t skips it, since the leaf C of (b) came before. The clip only
 * shrinks, so cells and boxes entered after it are never taken: nothing
 * in them could be reported.
 */

/* A hit (t, proxy index) or a cell (entry, node), in a heap by (t, key):
 * a key breaks ties between hits; between cells the order of equal
 * entries does not matter. */
typedef struct ray_item {
    double t;
    uintptr_t key;
} ray_item;

static inline bool ray_before(const ray_item *a, const ray_item *b)
{
    return a->t < b->t || (a->t == b->t && a->key < b->key);
}

/* A binary min-heap, first in a buffer on the stack, then on the heap. */
typedef struct ray_heap {
    ray_item *a, *local;
    size_t n, cap;
} ray_heap;

NOCT_DEFINE_GROW_LOCAL(grow_items, ray_item)

/* false without memory */
static bool ray_push(ray_heap *h, ray_item x)
{
    if (!grow_items(&h->a, h->local, &h->cap, h->n + 1))
        return false;
    size_t i = h->n++;
    while (i > 0 && ray_before(&x, &h->a[(i - 1) / 2])) {
        h->a[i] = h->a[(i - 1) / 2];
        i = (i - 1) / 2;
    }
    h->a[i] = x;
    return true;
}

/* The least item; the heap is not empty. */
static ray_item ray_pop(ray_heap *h)
{
    const ray_item top = h->a[0], x = h->a[--h->n];
    size_t i = 0;
    for (size_t c = 1; c < h->n; c = 2 * i + 1) {
        if (c + 1 < h->n && ray_before(&h->a[c + 1], &h->a[c]))
            ++c;
        if (!ray_before(&h->a[c], &x))
            break;
        h->a[i] = h->a[c];
        i = c;
    }
    h->a[i] = x;
    return top;
}

/* Room on the stack: a segment's cell heap holds about three cells per
 * level of the tree, and its hit heap the boxes of a few leaves. */
#define RAY_LOCAL_CELLS 96
#define RAY_LOCAL_HITS 64

typedef struct ray_query {
    const noctBroadphase *bp;
    double o[3], d[3];
    noctQueryFilter filter;
    noctRayFcn *fcn;
    void *context;
    double max;    /* the clip */
    ray_item last; /* the last hit handed out (t < 0: none yet) */
    ray_heap cells, hits;
    ray_item local_cells[RAY_LOCAL_CELLS], local_hits[RAY_LOCAL_HITS];
} ray_query;

/* Add the hits of list ids[0..n) (NULL: every live slot) of a leaf
 * entered at entry; false without memory. A box entered before the leaf
 * came from an earlier one; one entered after the clip cannot count. */
static bool ray_gather(ray_query *rq, const uint32_t *ids, uint32_t n, double entry)
{
    const noctBroadphase *bp = rq->bp;
    for (uint32_t j = 0; j < n; ++j) {
        const uint32_t id = ids != NULL ? ids[j] : j;
        if (ids == NULL && !bp->proxy[id].alive)
            continue;
        /* -1 for a box not met: below entry, which is at least 0 */
        const double t = enter_at(rq->o, rq->d, bp->box[id].lo, bp->box[id].hi, rq->max);
        if (t < entry || !passes(&bp->proxy[id], rq->filter))
            continue;
        if (!ray_push(&rq->hits, (ray_item){t, id}))
            return false;
    }
    return true;
}

/* Hand fcn the hits before E; false when the query is over (fcn
 * stopped it, or the next hit is beyond the clip). */
static bool ray_flush(ray_query *rq, double E)
{
    const noctBroadphase *bp = rq->bp;
    while (rq->hits.n > 0 && rq->hits.a[0].t < E) {
        const ray_item h = ray_pop(&rq->hits);
        if (h.t == rq->last.t && h.key == rq->last.key)
            continue; /* a copy from another leaf */
        if (h.t > rq->max)
            return false;
        NOCT_INVARIANT(rq->last.t < 0 || ray_before(&rq->last, &h));
        rq->last = h;
        const uint32_t id = (uint32_t)h.key;
        const double r =
            rq->fcn(rq->context, (noctProxyId){id, bp->gen[id]}, bp->proxy[id].user, h.t);
        if (!(r > 0))
            return false; /* 0 (or NaN) stops */
        rq->max = noct_min(rq->max, r);
    }
    return true;
}

/* The walk from the root; false without memory. */
static bool ray_walk(ray_query *rq)
{
    const noct_cell *rc = noct_cell_of(rq->bp->root);
    const double rhi[3] = {rc->lo[0] + rc->size, rc->lo[1] + rc->size, rc->lo[2] + rc->size};
    const double t = enter_at(rq->o, rq->d, rc->lo, rhi, rq->max);
    if (t >= 0 && !ray_push(&rq->cells, (ray_item){t, (uintptr_t)rq->bp->root}))
        return false;
    while (rq->cells.n > 0) {
        if (!ray_flush(rq, rq->cells.a[0].t))
            return true;
        if (rq->cells.a[0].t > rq->max)
            break; /* no hit left, and none in the cells to come, is in the clip */
        const ray_item e = ray_pop(&rq->cells);
        const octNode *n = (const octNode *)e.key;
        const noct_cell *c = noct_cell_of(n);
        if (!NOCT_NODE_IS_SPLIT(n)) {
            if (!ray_gather(rq, c->objs, c->count, e.t))
                return false;
            continue;
        }
        for (int i = 0; i < 8; ++i) {
            const octNode *kid = NOCT_NODE_CHILD(n, (octDirection)(OCT_LDB + i));
            const noct_cell *kc = noct_cell_of(kid);
            const double hi[3] = {kc->lo[0] + kc->size, kc->lo[1] + kc->size,
                                  kc->lo[2] + kc->size};
            const double tk = enter_at(rq->o, rq->d, kc->lo, hi, rq->max);
            if (tk >= 0 && !ray_push(&rq->cells, (ray_item){tk, (uintptr_t)kid}))
                return false;
        }
    }
    ray_flush(rq, INFINITY);
    return true;
}

/*
 * The proxies along the segment, in order, from a walk of the leaves in
 * order of entry that stops at the first leaf entered beyond the clip
 * (see "The walk" above). It reads the broadphase only: its scratch is
 * its own.
 */
noctStatus noctBroadphaseRayCast(const noctBroadphase *bp, const double origin[3],
                                 const double translation[3], noctQueryFilter filter,
                                 noctRayFcn *fcn, void *context)
{
    NOCT_REQUIRE(bp != NULL && origin != NULL && translation != NULL && fcn != NULL);
    for (int k = 0; k < 3; ++k)
        if (!isfinite(origin[k]) || !isfinite(translation[k]))
            return NOCT_ERR_NONFINITE;
    ray_query rq;
    rq.bp = bp;
    memcpy(rq.o, origin, sizeof rq.o);
    memcpy(rq.d, translation, sizeof rq.d);
    rq.filter = filter;
    rq.fcn = fcn;
    rq.context = context;
    rq.max = 1;
    rq.last = (ray_item){-1, 0};
    rq.cells = (ray_heap){rq.local_cells, rq.local_cells, 0, RAY_LOCAL_CELLS};
    rq.hits = (ray_heap){rq.local_hits, rq.local_hits, 0, RAY_LOCAL_HITS};
    bool ok;
    if (bp->root != NULL) {
        ok = ray_walk(&rq);
    } else {
        /* No tree (a failure tore it down): every proxy is asked, as
         * from one leaf entered at 0. */
        ok = ray_gather(&rq, NULL, bp->nslots, 0);
        if (ok)
            ray_flush(&rq, INFINITY);
    }
    if (rq.cells.a != rq.local_cells)
        free(rq.cells.a);
    if (rq.hits.a != rq.local_hits)
        free(rq.hits.a);
    return ok ? NOCT_OK : NOCT_ERR_NOMEM;
}
