/* SPDX-License-Identifier: MIT */
/*
 * Distances in a world (query.h): between two objects, from a shape or a
 * point to the nearest object and to every object within a distance, and
 * the near pairs' distances (world.h). Every distance is the narrowphase's
 * (noct_distance_placed(), or noct_point_distance_placed() for a point)
 * on the objects' placed shapes, as noct_world_shape() gives them.
 *
 * The nearest object is searched by the broadphase's walk outward from
 * the leaf that holds the query's centre (noct_bp_nearest()): every leaf
 * and every box within the best distance so far (and a little more, see
 * below), each box once, nearer boxes first within a leaf; the walk's
 * bound shrinks with each better object. Each pairwise search is given
 * the best so far as its max_distance, so that it stops once it proves
 * an object farther. The answer is the least (distance, index) of every
 * object that could compute a distance no larger than the best's, which
 * does not depend on the tree, nor on the order the walk takes them in.
 *
 * The "little more": the best is the least computed distance
 * (noctDistanceResult::distance), which is within the accuracy of
 * noctDistance() (upper - lower, at most 2^-40 of the coordinates'
 * magnitude) of the true distance; an object whose true distance is
 * within that of the best could compute less, so the search goes
 * 2^-36 of the magnitude beyond the best (reach()).
 */
#include "config.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <noctree/query.h>

#include "narrowphase_internal.h"
#include "world_internal.h"

NOCT_DEFINE_GROW(grow_results, noctDistanceResult)

/* ---- the query --------------------------------------------------------------------- */

/* A distance query: a placed shape, or a point. */
typedef struct dquery {
    const noctWorld *w;
    noct_query_shape q;
    bool point;
    const double *t;        /* the shape's translation, or the point */
    double lo[3], hi[3];    /* the placed box (the point twice) */
    double mag;             /* the largest magnitude of its corners */
    noct_box_slot slot;     /* its box form (a point's: a box of no size) */
    bool has_slot;
    const noctMesh *mesh;   /* the query's own mesh (NULL: a box or a point) */
    const noctTransform *x; /* and its transform */
} dquery;

/* Object s's transform. */
static noctTransform object_transform(const noctWorld *w, uint32_t s)
{
    noctTransform x;
    x.q = w->pose[s].q;
    memcpy(x.p, w->pos[s], sizeof x.p);
    return x;
}

/* The distance of two shapes: when both are meshes, by noctDistance() on
 * the meshes and their transforms, so that the world's answers are the
 * pairwise call's bit for bit (its searches read views of the rotated
 * vertices, and convex meshes take its convex path); otherwise (a box
 * primitive) on the placed shapes, by the convex path when both are
 * convex. ma and mb: the meshes (NULL for a box
 * primitive); pa and pb: the shapes as placed, at ta and tb. */
static noctStatus pair_distance(const noctMesh *ma, const noctTransform *xa, const noctMesh *pa,
                                const double ta[3], const noctMesh *mb, const noctTransform *xb,
                                const noctMesh *pb, const double tb[3], double max,
                                noctDistanceResult *r)
{
    if (ma != NULL && mb != NULL)
        return noctDistance(ma, xa, mb, xb, max, r, NULL, NULL);
    /* a box primitive is convex: its placed corners take the convex path
     * when the other shape is convex too */
    if (noct_distance_convex_placed(pa, ma == NULL, ta, pb, mb == NULL, tb, max, r))
        return NOCT_OK;
    return noct_distance_placed(pa, ta, pb, tb, max, r, NULL, NULL);
}

static noctStatus check_distance(double d, const char *what, noctError *err)
{
    if (isnan(d))
        return noct_fail(err, NOCT_ERR_NONFINITE, -1, 0, "%s is not a number", what);
    if (d < 0)
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0, "%s %g is negative", what, d);
    return NOCT_OK;
}

static noctStatus check_point(const double p[3], noctError *err)
{
    for (int k = 0; k < 3; ++k)
        if (!isfinite(p[k]))
            return noct_fail(err, NOCT_ERR_NONFINITE, -1, 0, "query point is not finite");
    for (int k = 0; k < 3; ++k)
        if (fabs(p[k]) > NOCT_MAX_COORDINATE)
            return noct_fail(err, NOCT_ERR_TOO_LARGE, -1, 0, "query point beyond %g",
                             NOCT_MAX_COORDINATE);
    return NOCT_OK;
}

static noctStatus dquery_make(dquery *d, const noctWorld *w, const noctMesh *mesh,
                              const double half_extents[3], const noctTransform *x,
                              noctError *err)
{
    d->w = w;
    d->q.rotated = NULL;
    d->point = mesh == NULL && half_extents == NULL;
    d->mesh = mesh;
    d->x = x;
    d->t = x->p;
    noctStatus st = d->point ? check_point(x->p, err)
                             : noct_query_shape_make(&d->q, mesh, half_extents, x, err);
    if (st != NOCT_OK)
        return st;
    if (d->point) {
        memset(&d->slot, 0, sizeof d->slot);
        d->slot.has_box = 1;
        d->has_slot = true;
    } else {
        d->slot = d->q.slot;
        d->has_slot = d->q.has_slot;
    }
    d->mag = 0;
    for (int k = 0; k < 3; ++k) {
        d->lo[k] = d->point ? x->p[k] : d->q.m->lo[k] + x->p[k];
        d->hi[k] = d->point ? x->p[k] : d->q.m->hi[k] + x->p[k];
        d->mag = noct_max(d->mag, noct_max(fabs(d->lo[k]), fabs(d->hi[k])));
    }
    return NOCT_OK;
}

/* Do a box primitive query (or object) and object s (or a box primitive
 * query) meet, as the separating-axis proof on their box forms shows it
 * (noct_box_decide(), both with a dual)? Then r is the answer for solids
 * that meet, as the narrowphase gives it: the centre of the overlap of
 * their placed boxes, m the object's shape as placed at its position. A
 * pair of two meshes goes to noctDistance(), which asks its own forms. */
static bool boxes_meet(const dquery *d, uint32_t s, const noctMesh *m, noctDistanceResult *r)
{
    const noctWorld *w = d->w;
    const noct_box_slot *os = &w->slot[s];
    if (d->point || (d->mesh != NULL && noct_world_shape_of(w, s) != NULL) || !d->has_slot ||
        !(d->slot.shrink < 1) || !os->has_box || !(os->shrink < 1))
        return false;
    double lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
        lo[k] = noct_max(d->lo[k], m->lo[k] + w->pos[s][k]);
        hi[k] = noct_min(d->hi[k], m->hi[k] + w->pos[s][k]);
        if (lo[k] > hi[k])
            return false;
    }
    if (noct_box_decide(&d->slot, d->t, os, w->pos[s]) <= 0)
        return false;
    memset(r, 0, sizeof *r);
    for (int k = 0; k < 3; ++k) {
        r->triangle_a[k] = r->triangle_b[k] = NOCT_NO_TRIANGLE;
        r->point_a[k] = r->point_b[k] = lo[k] + (hi[k] - lo[k]) / 2;
    }
    r->colliding = true;
    return true;
}

/* The answer of noct_point_distance_placed() for a point p in the
 * solid: 0, colliding, both points p, no triangles. */
static void point_inside(const double p[3], noctDistanceResult *r)
{
    memset(r, 0, sizeof *r);
    for (int k = 0; k < 3; ++k) {
        r->triangle_a[k] = r->triangle_b[k] = NOCT_NO_TRIANGLE;
        r->point_a[k] = r->point_b[k] = p[k];
    }
    r->colliding = true;
}

/* The distance from the query to object s, searched up to max. A point
 * first asks the object's box form (noct_point_slot_decide()): one proved
 * inside the solid has the answer the exact containment would give
 * (inside the solid it is inside the placed box, so the narrowphase would
 * test it, and the test is exact), without the object's view; one proved
 * outside skips the containment test. */
static noctStatus dquery_distance(const dquery *d, uint32_t s, double max,
                                  noctDistanceResult *r, noctError *err)
{
    noct_shape_view v;
    const noctWorld *w = d->w;
    bool outside = false;
    if (d->point && w->slot[s].has_box) {
        const int side = noct_point_slot_decide(d->t, &w->slot[s], w->pos[s]);
        if (side > 0) {
            point_inside(d->t, r);
            return NOCT_OK;
        }
        outside = side < 0;
    }
    const noctMesh *m = noct_world_shape(w, s, &v);
    if (boxes_meet(d, s, m, r))
        return NOCT_OK;
    const noctTransform xs = object_transform(w, s);
    const noctStatus st =
        d->point ? noct_point_distance_placed(d->t, m, w->pos[s], max, outside, r)
                 : pair_distance(d->mesh, d->x, d->q.m, d->t, noct_world_shape_of(w, s), &xs,
                                 m, w->pos[s], max, r);
    if (st != NOCT_OK)
        return noct_fail(err, st, (long)s, 0, "object %u: %s", s, noctStatusString(st));
    return NOCT_OK;
}

/* Is object s proved farther than d from the query by the box forms'
 * separating axes (the world's test of near pairs)? */
static bool apart(const dquery *d, uint32_t s, double dist)
{
    const noctWorld *w = d->w;
    if (!d->has_slot || !w->slot[s].has_box || !isfinite(dist))
        return false;
    return d->point ? noct_point_apart_by(d->t, &w->slot[s], w->pos[s], dist)
                    : noct_box_apart_by(&d->slot, d->t, &w->slot[s], w->pos[s], dist);
}

/* The magnitude of object s's placed box. */
static double box_magnitude(const noct_aabb *b)
{
    double m = 0;
    for (int k = 0; k < 3; ++k)
        m = noct_max(m, noct_max(fabs(b->lo[k]), fabs(b->hi[k])));
    return m;
}

/* A lower bound on the Euclidean distance between the query's box and
 * object s's placed box (each gap is a rounded difference). */
static double box_gap(const dquery *d, const noct_aabb *b)
{
    double s = 0;
    for (int k = 0; k < 3; ++k) {
        const double g = noct_max(noct_max(b->lo[k] - d->hi[k], d->lo[k] - b->hi[k]), 0);
        s += g * g;
    }
    return sqrt(s) * (1 - 0x1p-48);
}

/* How far beyond a distance dist an object of box magnitude mb must be
 * searched, so that no object whose computed distance is at most dist is
 * missed: its true distance is within the accuracy (2^-40 of the
 * magnitudes) of what it computes. */
static double reach(const dquery *d, double mb, double dist)
{
    if (!isfinite(dist))
        return dist;
    return dist + 0x1p-36 * noct_max(noct_max(d->mag, mb), dist);
}

static noctObjectId handle(const noctWorld *w, uint32_t s)
{
    return (noctObjectId){s, noct_bp_generation(&w->bp, s)};
}

/* ---- the candidates ----------------------------------------------------------------- */

typedef struct cands {
    uint32_t *s;
    size_t n, cap;
    bool failed;
} cands;

NOCT_DEFINE_GROW(grow_cands, uint32_t)

static bool take(void *context, noctProxyId id, void *user)
{
    (void)user;
    cands *c = context;
    if (!grow_cands(&c->s, &c->cap, c->cap > 0 ? c->n + 1 : 64)) {
        c->failed = true;
        return false;
    }
    c->s[c->n++] = id.index;
    return true;
}

static int by_slot(const void *x, const void *y)
{
    const uint32_t a = *(const uint32_t *)x, b = *(const uint32_t *)y;
    return (a > b) - (a < b);
}

/* The objects (that the filter lets through) whose boxes meet [lo, hi],
 * in order of index. */
static noctStatus gather(cands *c, const noctWorld *w, const double lo[3], const double hi[3],
                         noctQueryFilter filter, noctError *err)
{
    c->n = 0;
    noctStatus st = noctBroadphaseQueryBox(&w->bp, lo, hi, filter, take, c);
    if (st == NOCT_OK && c->failed)
        st = NOCT_ERR_NOMEM;
    if (st != NOCT_OK)
        return noct_fail(err, st, -1, 0, "query: %s", noctStatusString(st));
    if (c->n > 1)
        qsort(c->s, c->n, sizeof *c->s, by_slot);
    return NOCT_OK;
}

/* [lo, hi] = the query's box grown by r. */
static void grown(const dquery *d, double r, double lo[3], double hi[3])
{
    for (int k = 0; k < 3; ++k) {
        lo[k] = d->lo[k] - r;
        hi[k] = d->hi[k] + r;
    }
}

/* ---- between two objects ------------------------------------------------------------------ */

noctStatus noctWorldDistance(const noctWorld *w, noctObjectId a, noctObjectId b,
                             double max_distance, noctDistanceResult *result, noctError *err)
{
    NOCT_REQUIRE(w != NULL && result != NULL);
    noctStatus st = check_distance(max_distance, "max_distance", err);
    if (st != NOCT_OK)
        return st;
    if (noct_world_lookup(w, a) == NULL || noct_world_lookup(w, b) == NULL)
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0, "distance: a stale or unknown object");
    noct_shape_view va, vb;
    const noctMesh *ma = noct_world_shape(w, a.index, &va);
    const noctMesh *mb = noct_world_shape(w, b.index, &vb);
    const noctTransform xa = object_transform(w, a.index), xb = object_transform(w, b.index);
    st = pair_distance(noct_world_shape_of(w, a.index), &xa, ma, w->pos[a.index],
                       noct_world_shape_of(w, b.index), &xb, mb, w->pos[b.index], max_distance,
                       result);
    if (st != NOCT_OK)
        return noct_fail(err, st, (long)a.index, 0, "distance of objects %u and %u: %s",
                         a.index, b.index, noctStatusString(st));
    return NOCT_OK;
}

/* ---- the nearest ------------------------------------------------------------------------- */

/* The search for the nearest: the best so far, and the bound it puts on
 * the broadphase's walk. */
typedef struct nearest {
    const noctWorld *w;
    const dquery *d;
    double max;        /* max_distance */
    double mag;        /* at least every object's box magnitude */
    double c2;         /* the squared gap the best so far allows */
    double r2;         /* and the one this round's walk stops at */
    noct_nearest_bound bound;
    bool found;
    uint32_t bs;
    noctDistanceResult best;
    noctStatus st;
    noctError *err;
} nearest;

/*
 * The walk's bound from the best so far: the squared gap beyond which no
 * object need be searched. An object need not be when its box's gap G
 * (the exact distance between the boxes) exceeds cap = reach() of the
 * best (or of max_distance) with the magnitude of any object's box. The
 * walk computes s = sum of fl(g_k^2), each g_k a rounded difference, and
 * skips when s > c2. Each g_k <= (1 + u) G_k (u = 2^-53; a difference of
 * doubles that underflows is exact), fl(g_k^2) <= (1 + u) g_k^2 + 2^-1075,
 * and two additions of non-negative terms: s <= (1 + u)^5 G^2 + 2^-1072.
 * So G <= cap gives s <= G^2 (1 + 2^-50) <= cap^2 (1 + 2^-50) when
 * G^2 >= 2^-1000, and s < 2^-999 otherwise; c2 = max(fl(fl(cap^2)
 * (1 + 2^-45)), 2^-990) exceeds both (fl(cap^2) >= (1 - u) cap^2 when
 * cap^2 >= 2^-1000 is normal). An infinite cap (or one whose square
 * overflows) skips nothing.
 */
static void nearest_bound(nearest *n)
{
    const double cap =
        reach(n->d, n->mag, n->found ? noct_min(n->best.distance, n->max) : n->max);
    n->c2 = noct_max(cap * cap * (1 + 0x1p-45), 0x1p-990);
    n->bound.gap2 = noct_min(n->c2, n->r2);
    /* at distance 0 only a less index may win */
    if (n->found && n->best.distance == 0)
        n->bound.below = n->bs;
}

/* Request what the search of object s reads beside its box, scattered
 * by object: its slot (two lines) and position for the separating axes,
 * then its record and pose for its shape (noct_world_shape()), so that
 * they come in one wait rather than one after another. */
static NOCT_ALWAYS_INLINE void ask_object(const noctWorld *w, uint32_t s)
{
    NOCT_PREFETCH(&w->slot[s]);
    NOCT_PREFETCH((const char *)&w->slot[s] + sizeof w->slot[s] - 1);
    NOCT_PREFETCH(w->pos[s]);
    NOCT_PREFETCH(&w->obj[s]);
    NOCT_PREFETCH(&w->pose[s]);
    NOCT_PREFETCH((const char *)&w->pose[s] + sizeof w->pose[s] - 1);
}

/* The walk's function: search object s if its box may hold a nearer. */
static bool consider(void *context, uint32_t s, double gap2)
{
    (void)gap2;
    nearest *n = context;
    const dquery *d = n->d;
    ask_object(n->w, s);
    const noct_aabb *b = noct_bp_box(&n->w->bp, s);
    const double cap =
        reach(d, box_magnitude(b), n->found ? noct_min(n->best.distance, n->max) : n->max);
    if (box_gap(d, b) > cap || apart(d, s, cap))
        return true; /* farther than the best could compute */
    noctDistanceResult res;
    if ((n->st = dquery_distance(d, s, cap, &res, n->err)) != NOCT_OK)
        return false;
    if (res.beyond || res.distance > n->max)
        return true;
    if (!n->found || res.distance < n->best.distance ||
        (res.distance == n->best.distance && s < n->bs)) {
        n->best = res;
        n->bs = s;
        n->found = true;
        nearest_bound(n);
    }
    return true;
}

noctStatus noctWorldQueryNearest(const noctWorld *w, const noctMesh *mesh,
                                 const double half_extents[3], const noctTransform *x,
                                 double max_distance, noctQueryFilter filter,
                                 noctDistanceHit *hit, bool *found, noctError *err)
{
    NOCT_REQUIRE(w != NULL && x != NULL && hit != NULL && found != NULL);
    *found = false;
    noctStatus st = check_distance(max_distance, "max_distance", err);
    if (st != NOCT_OK)
        return st;
    dquery d;
    if ((st = dquery_make(&d, w, mesh, half_extents, x, err)) != NOCT_OK) {
        noctMeshDestroy(d.q.rotated);
        return st;
    }
    nearest n;
    memset(&n, 0, sizeof n);
    n.w = w;
    n.d = &d;
    n.max = max_distance;
    n.bound.below = UINT32_MAX;
    n.st = NOCT_OK;
    n.err = err;
    /* The first round: boxes within a quarter of the spacing the objects
     * would have if they filled the root evenly (the query's box reaching
     * no farther than its gap to the root: nothing is nearer); then
     * twice as far each round until an object is found, and then to the
     * best distance. Only the cost depends on it: a round's walk reads
     * every box of the leaves it reaches, and one too wide makes many
     * candidates, one too narrow makes rounds (on gas:100000 an eighth
     * or a half cost 1 to 7% more instructions). */
    const noct_aabb root = noct_bp_root_box(&w->bp); /* holds every box */
    n.mag = box_magnitude(&root);
    double r = 0;
    if (isfinite(n.mag)) {
        double size = 0;
        for (int k = 0; k < 3; ++k)
            size = noct_max(size, root.hi[k] - root.lo[k]);
        r = noct_max(size / (4 * cbrt((double)noct_bp_live(&w->bp) + 1)),
                     sqrt(noct_gap2(d.lo, d.hi, root.lo, root.hi)));
    } else { /* no tree: one pass over every object */
        n.mag = 0;
        for (uint32_t s = 0; s < noct_bp_slots(&w->bp); ++s)
            if (noct_bp_proxy(&w->bp, s)->alive)
                n.mag = noct_max(n.mag, box_magnitude(noct_bp_box(&w->bp, s)));
        r = INFINITY;
    }
    n.r2 = noct_max(r * r, 0x1p-990);
    n.bound.done2 = -1;
    double centre[3];
    for (int k = 0; k < 3; ++k)
        centre[k] = d.lo[k] + (d.hi[k] - d.lo[k]) / 2;
    for (;;) {
        nearest_bound(&n);
        bool cut;
        st = noct_bp_nearest(&w->bp, d.lo, d.hi, centre, filter, &n.bound, consider, &n, &cut);
        if (n.st != NOCT_OK) {
            st = n.st;
            break;
        }
        if (st != NOCT_OK) {
            st = noct_fail(err, st, -1, 0, "nearest: %s", noctStatusString(st));
            break;
        }
        /* Every object whose box is within the last bound has been
         * searched, or was beyond the best when its turn came: done when
         * nothing was left out, or the round's radius reached the best. */
        if (!cut || n.c2 <= n.r2)
            break;
        n.bound.done2 = n.r2;
        n.r2 = n.found ? (double)INFINITY : 4 * n.r2;
    }
    noctMeshDestroy(d.q.rotated);
    if (st != NOCT_OK || !n.found)
        return st;
    *found = true;
    hit->id = handle(w, n.bs);
    hit->user_data = noct_bp_proxy(&w->bp, n.bs)->user;
    hit->result = n.best;
    return NOCT_OK;
}

/* ---- within a distance --------------------------------------------------------------------- */

noctStatus noctWorldQueryWithin(const noctWorld *w, const noctMesh *mesh,
                                const double half_extents[3], const noctTransform *x,
                                double distance, noctQueryFilter filter,
                                noctDistanceHitFcn *fcn, void *context, noctError *err)
{
    NOCT_REQUIRE(w != NULL && x != NULL && fcn != NULL);
    noctStatus st = check_distance(distance, "distance", err);
    if (st == NOCT_OK && distance > NOCT_MAX_COORDINATE)
        st = noct_fail(err, NOCT_ERR_INVALID, -1, 0, "distance %g: at most %g", distance,
                       NOCT_MAX_COORDINATE);
    if (st != NOCT_OK)
        return st;
    dquery d;
    if ((st = dquery_make(&d, w, mesh, half_extents, x, err)) != NOCT_OK) {
        noctMeshDestroy(d.q.rotated);
        return st;
    }
    /* Every object within reach of any magnitude the query may meet: its
     * box is within distance of the query's. */
    const double r = reach(&d, 0, distance) * (1 + 0x1p-40);
    double lo[3], hi[3];
    grown(&d, r, lo, hi);
    cands c = {NULL, 0, 0, false};
    st = gather(&c, w, lo, hi, filter, err);
    for (size_t i = 0; i < c.n && st == NOCT_OK; ++i) {
        const uint32_t s = c.s[i];
        const noct_aabb *b = noct_bp_box(&w->bp, s);
        const double cap = reach(&d, box_magnitude(b), distance);
        if (box_gap(&d, b) > cap || apart(&d, s, cap))
            continue; /* its boxes prove it farther than it could compute */
        noctDistanceHit h;
        if ((st = dquery_distance(&d, s, distance, &h.result, err)) != NOCT_OK)
            break;
        if (h.result.beyond || !(h.result.lower <= distance))
            continue;
        h.id = handle(w, s);
        h.user_data = noct_bp_proxy(&w->bp, s)->user;
        if (!fcn(context, &h))
            break;
    }
    free(c.s);
    noctMeshDestroy(d.q.rotated);
    return st;
}

/* ---- the near pairs' distances --------------------------------------------------------------- */

noctStatus noctWorldNearDistances(noctWorld *w, const noctDistanceResult **results, size_t *n,
                                  noctError *err)
{
    NOCT_REQUIRE(w != NULL && results != NULL && n != NULL);
    const noct_pair_list *near = &w->events.near.now;
    *results = NULL;
    *n = 0;
    if (near->n == 0)
        return NOCT_OK;
    if (!w->near_dist_made) {
        if (!grow_results(&w->near_dist, &w->capnear_dist, near->n))
            return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
        for (size_t i = 0; i < near->n; ++i) {
            const noctPair *p = &near->p[i];
            noctDistanceResult *r = &w->near_dist[i];
            if (noct_world_lookup(w, p->a) == NULL || noct_world_lookup(w, p->b) == NULL) {
                /* removed since the step */
                memset(r, 0, sizeof *r);
                r->distance = r->lower = r->upper = (double)NAN;
                for (int k = 0; k < 3; ++k)
                    r->triangle_a[k] = r->triangle_b[k] = NOCT_NO_TRIANGLE;
                continue;
            }
            noct_shape_view va, vb;
            const noctMesh *ma = noct_world_shape(w, p->a.index, &va);
            const noctMesh *mb = noct_world_shape(w, p->b.index, &vb);
            const noctTransform xa = object_transform(w, p->a.index);
            const noctTransform xb = object_transform(w, p->b.index);
            const noctStatus st =
                pair_distance(noct_world_shape_of(w, p->a.index), &xa, ma, w->pos[p->a.index],
                              noct_world_shape_of(w, p->b.index), &xb, mb, w->pos[p->b.index],
                              INFINITY, r);
            if (st != NOCT_OK)
                return noct_fail(err, st, (long)p->a.index, 0,
                                 "the near pairs' distances: objects %u and %u: %s",
                                 p->a.index, p->b.index, noctStatusString(st));
        }
        w->near_dist_made = true;
    }
    *results = w->near_dist;
    *n = near->n;
    return NOCT_OK;
}
