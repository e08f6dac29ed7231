/* SPDX-License-Identifier: MIT */
/*
 * Distances in a world (query.h): between two objects, from a shape or a
 * point to the nearest object and to every object within a distance, and
 * the near pairs' distances (world.h). Every distance is the narrowphase's
 * (noct_distance_placed(), or noct_point_distance_placed() for a point)
 * on the objects' placed shapes, as noct_world_shape() gives them.
 *
 * The nearest object is searched in the broadphase outward: boxes grown
 * about the query's box, wider each round until an object is found, then
 * once more to the best distance so far (and a little more, see below);
 * each round's new candidates are tested nearest box first, skipping those
 * whose boxes are farther than the best so far, and each pairwise search
 * is given the best so far as its max_distance, so that it stops once it
 * proves an object farther. Which objects are found depends only on the
 * objects and the query, never on the tree.
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

/* The distance from the query to object s, searched up to max. */
static noctStatus dquery_distance(const dquery *d, uint32_t s, double max,
                                  noctDistanceResult *r, noctError *err)
{
    noct_shape_view v;
    const noctWorld *w = d->w;
    const noctMesh *m = noct_world_shape(w, s, &v);
    if (boxes_meet(d, s, m, r))
        return NOCT_OK;
    const noctTransform xs = object_transform(w, s);
    const noctStatus st =
        d->point ? noct_point_distance_placed(d->t, m, w->pos[s], max, r)
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
    return d->has_slot && w->slot[s].has_box && isfinite(dist) &&
           noct_box_apart_by(&d->slot, d->t, &w->slot[s], w->pos[s], dist);
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

typedef struct cand {
    double gap;
    uint32_t s;
} cand;

typedef struct cands {
    cand *c;
    size_t n, cap;
    const noctWorld *w;
    const dquery *d;
    const double *plo, *phi; /* the last round's box: its objects are done */
    bool failed;
} cands;

NOCT_DEFINE_GROW(grow_cands, cand)

static bool take(void *context, noctProxyId id, void *user)
{
    (void)user;
    cands *c = context;
    const noct_aabb *b = noct_bp_box(&c->w->bp, id.index);
    if (c->plo != NULL) {
        bool apart = false; /* the broadphase's own test, on the last box */
        for (int k = 0; k < 3; ++k)
            apart = apart || b->hi[k] < c->plo[k] || c->phi[k] < b->lo[k];
        if (!apart)
            return true;
    }
    if (!grow_cands(&c->c, &c->cap, c->cap > 0 ? c->n + 1 : 64)) {
        c->failed = true;
        return false;
    }
    c->c[c->n++] = (cand){box_gap(c->d, b), id.index};
    return true;
}

static int by_gap(const void *x, const void *y)
{
    const cand *a = x, *b = y;
    if (a->gap != b->gap)
        return a->gap < b->gap ? -1 : 1;
    return (a->s > b->s) - (a->s < b->s);
}

static int by_slot(const void *x, const void *y)
{
    const cand *a = x, *b = y;
    return (a->s > b->s) - (a->s < b->s);
}

/* The objects (that the filter lets through) whose boxes meet [lo, hi]
 * and not the last round's box; sorted by gap (or by slot). */
static noctStatus gather(cands *c, const double lo[3], const double hi[3],
                         noctQueryFilter filter, bool by_index, noctError *err)
{
    c->n = 0;
    noctStatus st = noctBroadphaseQueryBox(&c->w->bp, lo, hi, filter, take, c);
    if (st == NOCT_OK && c->failed)
        st = NOCT_ERR_NOMEM;
    if (st != NOCT_OK)
        return noct_fail(err, st, -1, 0, "query: %s", noctStatusString(st));
    if (c->n > 1)
        qsort(c->c, c->n, sizeof *c->c, by_index ? by_slot : by_gap);
    return NOCT_OK;
}

/* [lo, hi] = the query's box grown by r; false if it holds every object
 * (the root's box, or everything when there is no tree). */
static bool grown(const dquery *d, double r, double lo[3], double hi[3])
{
    const noct_aabb root = noct_bp_root_box(&d->w->bp);
    bool all = true;
    for (int k = 0; k < 3; ++k) {
        lo[k] = d->lo[k] - r;
        hi[k] = d->hi[k] + r;
        all = all && lo[k] <= root.lo[k] && root.hi[k] <= hi[k];
    }
    return !all;
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
    /* The first round: the query's own size, or an eighth of the spacing
     * the objects would have if they filled the root evenly; then twice as
     * far each round until an object is found (only the cost depends on
     * it: a box about a leaf's size reads every box of the leaves it
     * meets, from all over memory). */
    const noct_aabb root = noct_bp_root_box(&w->bp);
    double r = 0, size = 0;
    for (int k = 0; k < 3; ++k) {
        r = noct_max(r, d.hi[k] - d.lo[k]);
        size = noct_max(size, root.hi[k] - root.lo[k]);
    }
    if (isfinite(size))
        r = noct_max(r, size / (8 * cbrt((double)noct_bp_live(&w->bp) + 1)));
    r = noct_max(r, noct_max(0x1p-30 * d.mag, 0x1p-1000));
    if (noct_bp_root(&w->bp) == NULL)
        r = INFINITY; /* no tree (a failed step tore it down): one pass over all */
    cands c = {NULL, 0, 0, w, &d, NULL, NULL, false};
    double lo[3], hi[3], plo[3], phi[3];
    noctDistanceResult best;
    uint32_t bs = 0;
    for (;;) {
        const bool more = grown(&d, r, lo, hi);
        if ((st = gather(&c, lo, hi, filter, false, err)) != NOCT_OK)
            break;
        for (size_t i = 0; i < c.n && st == NOCT_OK; ++i) {
            const uint32_t s = c.c[i].s;
            const double mb = box_magnitude(noct_bp_box(&w->bp, s));
            const double cap =
                reach(&d, mb, *found ? noct_min(best.distance, max_distance) : max_distance);
            if (c.c[i].gap > cap || (*found && best.distance == 0 && s > bs) || apart(&d, s, cap))
                continue; /* farther, or no nearer than the best */
            noctDistanceResult res;
            if ((st = dquery_distance(&d, s, cap, &res, err)) != NOCT_OK)
                break;
            if (res.beyond || res.distance > max_distance)
                continue;
            if (!*found || res.distance < best.distance ||
                (res.distance == best.distance && s < bs)) {
                best = res;
                bs = s;
                *found = true;
            }
        }
        if (st != NOCT_OK || !more)
            break;
        /* Every object not yet seen is farther than r from the query's box. */
        const double need = reach(&d, d.mag, *found ? best.distance : max_distance);
        if (r >= need * (1 + 0x1p-40))
            break;
        memcpy(plo, lo, sizeof plo);
        memcpy(phi, hi, sizeof phi);
        c.plo = plo;
        c.phi = phi;
        r = *found ? noct_max(need * (1 + 0x1p-40), r) : 2 * r;
    }
    free(c.c);
    noctMeshDestroy(d.q.rotated);
    if (st != NOCT_OK || !*found) {
        *found = false;
        return st;
    }
    hit->id = handle(w, bs);
    hit->user_data = noct_bp_proxy(&w->bp, bs)->user;
    hit->result = best;
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
    (void)grown(&d, r, lo, hi);
    cands c = {NULL, 0, 0, w, &d, NULL, NULL, false};
    st = gather(&c, lo, hi, filter, true, err);
    for (size_t i = 0; i < c.n && st == NOCT_OK; ++i) {
        const uint32_t s = c.c[i].s;
        const double cap = reach(&d, box_magnitude(noct_bp_box(&w->bp, s)), distance);
        if (c.c[i].gap > cap || apart(&d, s, cap))
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
    free(c.c);
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
