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

/* Does the leaf own point p: [lo, lo + size) per axis, closed at the
 * root's upper faces? */
static bool owns_point(const noct_cell *c, const noct_cell *root, const double p[3])
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
        if (apart || !owns_point(c, rc, corner) || !passes(&bp->proxy[id], bq->filter))
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

typedef struct ray_hit {
    double t;
    uint32_t id;
} ray_hit;

/* Hits gather in a buffer on the stack (a ray through a few leaves meets
 * a few dozen boxes), then on the heap. */
#define RAY_LOCAL_HITS 64

typedef struct ray_query {
    const noctBroadphase *bp;
    double o[3], d[3];
    noctQueryFilter filter;
    ray_hit *hit; /* local, or from the heap */
    size_t n, cap;
    ray_hit local[RAY_LOCAL_HITS];
} ray_query;

static int cmp_hit(const void *x, const void *y)
{
    const ray_hit *a = x, *b = y;
    if (a->t != b->t)
        return a->t < b->t ? -1 : 1;
    return (a->id > b->id) - (a->id < b->id);
}

static bool ray_list(ray_query *rq, const uint32_t *ids, uint32_t n);

/* Gather the proxies of the leaves the segment passes through; false
 * without memory. */
static bool ray_node(ray_query *rq, const octNode *n)
{
    const noct_cell *c = noct_cell_of(n);
    const double hi[3] = {c->lo[0] + c->size, c->lo[1] + c->size, c->lo[2] + c->size};
    if (enter_at(rq->o, rq->d, c->lo, hi, 1) < 0)
        return true;
    if (NOCT_NODE_IS_SPLIT(n)) {
        for (int i = 0; i < 8; ++i)
            if (!ray_node(rq, NOCT_NODE_CHILD(n, (octDirection)(OCT_LDB + i))))
                return false;
        return true;
    }
    return ray_list(rq, c->objs, c->count);
}

/* Gather the proxies of list ids[0..n) that the segment meets. */
static bool ray_list(ray_query *rq, const uint32_t *ids, uint32_t n)
{
    const noctBroadphase *bp = rq->bp;
    for (uint32_t j = 0; j < n; ++j) {
        const uint32_t id = ids != NULL ? ids[j] : j;
        if (ids == NULL && !bp->proxy[id].alive)
            continue;
        const double t = enter_at(rq->o, rq->d, bp->box[id].lo, bp->box[id].hi, 1);
        if (t < 0 || !passes(&bp->proxy[id], rq->filter))
            continue;
        if (rq->n == rq->cap) {
            const size_t cap = 2 * rq->cap;
            ray_hit *q = rq->hit == rq->local ? malloc(cap * sizeof *q)
                                              : realloc(rq->hit, cap * sizeof *q);
            if (q == NULL)
                return false;
            if (rq->hit == rq->local)
                memcpy(q, rq->local, sizeof rq->local);
            rq->hit = q;
            rq->cap = cap;
        }
        rq->hit[rq->n++] = (ray_hit){t, id};
    }
    return true;
}

/*
 * The proxies along the segment: gathered from every leaf it passes
 * through, sorted by entry and index (a proxy in several leaves comes
 * out of each with the same t, so its copies are next to each other),
 * then handed to fcn in order while their t is within the clipped
 * segment.
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
    rq.hit = rq.local;
    rq.n = 0;
    rq.cap = RAY_LOCAL_HITS;
    /* without a tree (a failure tore it down), every proxy is asked */
    if (!(bp->root != NULL ? ray_node(&rq, bp->root) : ray_list(&rq, NULL, bp->nslots))) {
        if (rq.hit != rq.local)
            free(rq.hit);
        return NOCT_ERR_NOMEM;
    }
    if (rq.n > 1)
        qsort(rq.hit, rq.n, sizeof *rq.hit, cmp_hit);
    double max = 1;
    for (size_t i = 0; i < rq.n; ++i) {
        if (i > 0 && rq.hit[i].id == rq.hit[i - 1].id && rq.hit[i].t == rq.hit[i - 1].t)
            continue;
        if (rq.hit[i].t > max)
            break;
        const uint32_t id = rq.hit[i].id;
        const double r = fcn(context, (noctProxyId){id, bp->gen[id]}, bp->proxy[id].user,
                             rq.hit[i].t);
        if (!(r > 0))
            break; /* 0 (or NaN) stops */
        max = noct_min(max, r);
    }
    if (rq.hit != rq.local)
        free(rq.hit);
    return NOCT_OK;
}
