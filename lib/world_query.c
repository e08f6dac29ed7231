/* SPDX-License-Identifier: MIT */
/*
 * The world's queries (query.h): candidates from the broadphase's boxes,
 * each decided on the object's placed shape by the narrowphase's exact
 * primitives. They only read the world: a box primitive's shape is a view
 * of its corners on the stack (noct_box_view), never the mesh a step may
 * make for it, so that queries may run in several threads at once.
 */
#include "config.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <noctree/query.h>

#include "world_internal.h"

/* ---- candidates --------------------------------------------------------------- */

/* The slots a broadphase query found: a few on the stack, more on the heap. */
typedef struct candidates {
    uint32_t *s;
    size_t n, cap;
    bool failed;
    uint32_t local[64];
} candidates;

static void candidates_init(candidates *c)
{
    c->s = c->local;
    c->n = 0;
    c->cap = sizeof c->local / sizeof *c->local;
    c->failed = false;
}

static void candidates_fini(candidates *c)
{
    if (c->s != c->local)
        free(c->s);
}

NOCT_DEFINE_GROW_LOCAL(grow_candidates, uint32_t)
NOCT_DEFINE_GROW(grow_hits, noctRayHit)

static bool candidates_push(candidates *c, uint32_t s)
{
    if (!grow_candidates(&c->s, c->local, &c->cap, c->n + 1)) {
        c->failed = true;
        return false;
    }
    c->s[c->n++] = s;
    return true;
}

static bool push_proxy(void *context, noctProxyId id, void *user)
{
    (void)user;
    return candidates_push(context, id.index);
}

static int by_index(const void *a, const void *b)
{
    const uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return (x > y) - (x < y);
}

/* The live objects whose boxes meet [lo, hi] and that the filter lets
 * through, in order of index. */
static noctStatus gather(const noctWorld *w, const double lo[3], const double hi[3],
                         noctQueryFilter filter, candidates *c, noctError *err)
{
    noctStatus st = noctBroadphaseQueryBox(&w->bp, lo, hi, filter, push_proxy, c);
    if (st == NOCT_OK && c->failed)
        st = NOCT_ERR_NOMEM;
    if (st != NOCT_OK)
        return noct_fail(err, st, -1, 0, "query: %s", noctStatusString(st));
    if (c->n > 1)
        qsort(c->s, c->n, sizeof *c->s, by_index);
    return NOCT_OK;
}

/* ---- an object's shape as the queries see it ------------------------------------- */

/* The queries' name for the shape view. */
typedef noct_shape_view shape;

static const noctMesh *shape_of_object(const noctWorld *w, uint32_t s, shape *sh)
{
    return noct_world_shape(w, s, sh);
}

const noctMesh *noct_world_shape(const noctWorld *w, uint32_t s, noct_shape_view *sh)
{
    if (!w->obj[s].box)
        return w->mesh[s];
    double R[9];
    noctQuatToMatrix(&w->pose[s].q, R, NULL); /* checked when it was set */
    noct_box_corners(w->pose[s].shape.half, R, sh->corners);
    noct_box_view(sh->corners, &sh->view, &sh->leaf);
    return &sh->view;
}

static noctObjectId handle(const noctWorld *w, uint32_t s)
{
    return (noctObjectId){s, noct_bp_generation(&w->bp, s)};
}

static noctStatus check_point(const double p[3], const char *what, noctError *err)
{
    for (int k = 0; k < 3; ++k)
        if (!isfinite(p[k]))
            return noct_fail(err, NOCT_ERR_NONFINITE, -1, 0, "query %s is not finite", what);
    for (int k = 0; k < 3; ++k)
        if (fabs(p[k]) > NOCT_MAX_COORDINATE)
            return noct_fail(err, NOCT_ERR_TOO_LARGE, -1, 0, "query %s beyond %g", what,
                             NOCT_MAX_COORDINATE);
    return NOCT_OK;
}

static noctStatus numeric(noctError *err, uint32_t s)
{
    return noct_fail(err, NOCT_ERR_NUMERIC, (long)s, 0,
                     "object %u: the containment count stayed ambiguous", s);
}

/* ---- point ----------------------------------------------------------------------- */

noctStatus noctWorldQueryPoint(const noctWorld *w, const double p[3], noctQueryFilter filter,
                               noctObjectFcn *fcn, void *context, noctError *err)
{
    NOCT_REQUIRE(w != NULL && p != NULL && fcn != NULL);
    noctStatus st = check_point(p, "point", err);
    if (st != NOCT_OK)
        return st;
    candidates c;
    candidates_init(&c);
    st = gather(w, p, p, filter, &c, err);
    for (size_t i = 0; i < c.n && st == NOCT_OK; ++i) {
        const uint32_t s = c.s[i];
        shape sh;
        bool inside;
        st = noct_point_in_solid(shape_of_object(w, s, &sh), w->pos[s], p, &inside);
        if (st != NOCT_OK)
            st = numeric(err, s);
        else if (inside && !fcn(context, handle(w, s), noct_bp_proxy(&w->bp, s)->user))
            break;
    }
    candidates_fini(&c);
    return st;
}

/* ---- box and shape ------------------------------------------------------------------ */

/* Does the query's shape q (placed at tq) meet object s, at level? Their
 * placed boxes overlap (the broadphase found s). A box shape's slot (qs,
 * or NULL) decides most pairs with a box object at the exact level, as
 * the world's pair test does. */
static noctStatus meets(const noctWorld *w, uint32_t s, const noctMesh *q, const double tq[3],
                        const noct_box_slot *qs, noctAccuracy level, bool *hit)
{
    if (qs != NULL && level == NOCT_ACCURACY_EXACT && w->slot[s].has_box) {
        const int d = noct_box_decide(qs, tq, &w->slot[s], w->pos[s]);
        if (d != 0) {
            *hit = d > 0;
            return NOCT_OK;
        }
    }
    shape sh;
    const noctMesh *m = shape_of_object(w, s, &sh);
    return noct_collide_overlapping(q, tq, m, w->pos[s], level, hit, NULL);
}

/* Report the candidates that meet q placed at tq, in order; with skins,
 * those within margin plus their own margins. */
static noctStatus report_meeting(const noctWorld *w, const noctMesh *q, const double tq[3],
                                 const noct_box_slot *qs, noctAccuracy level, double margin,
                                 bool skins, noctQueryFilter filter,
                                 noctObjectFcn *fcn, void *context, noctError *err)
{
    const double *own = skins && w->margins.count > 0 ? w->margins.of : NULL;
    const double base = margin;
    if (own != NULL) /* (max bounds every margin, stale or not) */
        margin += w->margins.max;
    double lo[3], hi[3], scale = margin;
    for (int k = 0; k < 3; ++k) {
        lo[k] = q->lo[k] + tq[k];
        hi[k] = q->hi[k] + tq[k];
        scale = noct_max(scale, noct_max(fabs(lo[k]), fabs(hi[k])));
    }
    if (margin > 0) /* grown by the margin and more than its rounding */
        for (int k = 0; k < 3; ++k) {
            lo[k] -= margin + 0x1p-38 * scale;
            hi[k] += margin + 0x1p-38 * scale;
        }
    candidates c;
    candidates_init(&c);
    noctStatus st = gather(w, lo, hi, filter, &c, err);
    for (size_t i = 0; i < c.n && st == NOCT_OK; ++i) {
        const uint32_t s = c.s[i];
        if (own != NULL)
            margin = base + own[s];
        bool hit;
        st = meets(w, s, q, tq, qs, level, &hit);
        if (st == NOCT_OK && !hit && margin > 0 &&
            !(qs != NULL && w->slot[s].has_box &&
              noct_box_apart_by(qs, tq, &w->slot[s], w->pos[s], margin))) {
            noct_shape_view v;
            hit = noct_solids_within(q, tq, noct_world_shape(w, s, &v), w->pos[s], margin);
        }
        if (st != NOCT_OK)
            st = noct_fail(err, st, (long)s, 0, "object %u: %s", s, noctStatusString(st));
        else if (hit && !fcn(context, handle(w, s), noct_bp_proxy(&w->bp, s)->user))
            break;
    }
    candidates_fini(&c);
    return st;
}

noctStatus noctWorldQueryBox(const noctWorld *w, const double lo[3], const double hi[3],
                             noctQueryFilter filter, noctObjectFcn *fcn, void *context,
                             noctError *err)
{
    NOCT_REQUIRE(w != NULL && lo != NULL && hi != NULL && fcn != NULL);
    noctStatus st = check_point(lo, "box corner", err);
    if (st == NOCT_OK)
        st = check_point(hi, "box corner", err);
    if (st != NOCT_OK)
        return st;
    for (int k = 0; k < 3; ++k)
        if (lo[k] > hi[k])
            return noct_fail(err, NOCT_ERR_INVALID, -1, 0,
                             "query box: low corner above the high one on axis %d", k);
    /* The box's own corners, exactly: a view placed at the origin. */
    double v[24];
    for (int i = 0; i < 8; ++i) {
        v[3 * i] = (i & 4) ? hi[0] : lo[0];
        v[3 * i + 1] = (i & 2) ? hi[1] : lo[1];
        v[3 * i + 2] = (i & 1) ? hi[2] : lo[2];
    }
    noctMesh view;
    bvh_node leaf;
    noct_box_view(v, &view, &leaf);
    static const double origin[3] = {0, 0, 0};
    static const double identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    noct_box_slot slot;
    double blo[3], bhi[3];
    bool solid = true;
    for (int k = 0; k < 3; ++k)
        solid = solid && lo[k] < hi[k];
    if (solid)
        noct_box_slot_of_corners(v, identity, &slot, blo, bhi);
    return report_meeting(w, &view, origin, solid && slot.has_box ? &slot : NULL,
                          w->def.accuracy, 0, false, filter, fcn, context, err);
}

typedef noct_query_shape query_shape;

noctStatus noct_query_shape_make(query_shape *q, const noctMesh *mesh,
                                 const double half_extents[3], const noctTransform *x,
                                 noctError *err)
{
    q->rotated = NULL;
    double R[9];
    noctStatus st = noct_transform_matrix(x, R, err);
    if (st != NOCT_OK)
        return st;
    if (mesh == NULL) {
        if ((st = noct_check_box_half(half_extents, err)) != NOCT_OK ||
            (st = noct_check_box_corners(half_extents, R, err)) != NOCT_OK)
            return st;
        noct_box_corners(half_extents, R, q->v);
        noct_box_view(q->v, &q->view, &q->leaf);
        /* the form turned, not made again of the corners */
        noct_box_slot_of_half(half_extents, R, &q->slot);
        q->has_slot = q->slot.has_box;
        q->m = &q->view;
        return NOCT_OK;
    }
    if (!noct_is_identity(R) && (st = noct_mesh_rotated(mesh, R, &q->rotated, err)) != NOCT_OK)
        return st;
    q->m = q->rotated != NULL ? q->rotated : mesh;
    q->has_slot = q->m->has_box;
    if (q->has_slot)
        noct_box_slot_fill(q->m, &q->slot);
    return NOCT_OK;
}

/* The objects that meet the shape at x, or come within margin of it. */
static noctStatus shape_query(const noctWorld *w, const noctMesh *mesh,
                              const double half_extents[3], const noctTransform *x,
                              double margin, bool skins, noctQueryFilter filter,
                              noctObjectFcn *fcn, void *context, noctError *err)
{
    query_shape q;
    noctStatus st = noct_query_shape_make(&q, mesh, half_extents, x, err);
    if (st == NOCT_OK)
        st = report_meeting(w, q.m, x->p, q.has_slot ? &q.slot : NULL, NOCT_ACCURACY_EXACT,
                            margin, skins, filter, fcn, context, err);
    noctMeshDestroy(q.rotated);
    return st;
}

noctStatus noctWorldQueryShape(const noctWorld *w, const noctMesh *mesh,
                               const double half_extents[3], const noctTransform *x,
                               noctQueryFilter filter, noctObjectFcn *fcn, void *context,
                               noctError *err)
{
    NOCT_REQUIRE(w != NULL && x != NULL && fcn != NULL);
    NOCT_REQUIRE(mesh != NULL || half_extents != NULL);
    return shape_query(w, mesh, half_extents, x, 0, false, filter, fcn, context, err);
}

noctStatus noctWorldQueryNear(const noctWorld *w, const noctMesh *mesh,
                              const double half_extents[3], const noctTransform *x,
                              double margin, noctQueryFilter filter, noctObjectFcn *fcn,
                              void *context, noctError *err)
{
    NOCT_REQUIRE(w != NULL && x != NULL && fcn != NULL);
    NOCT_REQUIRE(mesh != NULL || half_extents != NULL);
    if (isnan(margin))
        return noct_fail(err, NOCT_ERR_NONFINITE, -1, 0, "query margin is not a number");
    if (!(margin >= 0 && margin <= NOCT_MAX_COORDINATE))
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0, "query margin %g: it must be 0 to %g",
                         margin, NOCT_MAX_COORDINATE);
    return shape_query(w, mesh, half_extents, x, margin, true, filter, fcn, context, err);
}

/* ---- rays -------------------------------------------------------------------------- */

typedef struct ray {
    const noctWorld *w;
    double p[3], q[3], d[3];
    noctStatus st;
    uint32_t bad;         /* the object that failed, with st */
    /* all hits (noctWorldRayCast), or the best (closest) */
    noctRayHit *hits;
    size_t n, cap;
    bool closest, found;
    noctRayHit best;
    double slack;         /* a box's entry fraction may be this far off */
} ray;

/* Where the segment meets object s, if it does. */
static noctStatus ray_test(ray *r, uint32_t s, bool *hit, noctRayHit *h)
{
    const noctWorld *w = r->w;
    shape sh;
    const noctMesh *m = shape_of_object(w, s, &sh);
    double f;
    uint32_t tri;
    noctStatus st =
        noct_segment_hit(m, w->pos[s], r->p, r->q, hit, &f, &tri, h->normal, &h->flat);
    if (st != NOCT_OK || !*hit)
        return st;
    h->id = handle(w, s);
    h->user_data = noct_bp_proxy(&w->bp, s)->user;
    h->fraction = f;
    for (int k = 0; k < 3; ++k) {
        h->point[k] = r->p[k] + f * r->d[k];
        h->triangle[k] = tri == UINT32_MAX ? NOCT_NO_VERTEX : m->tri[3 * tri + k];
    }
    return NOCT_OK;
}

static bool before(const noctRayHit *a, const noctRayHit *b)
{
    return a->fraction < b->fraction ||
           (a->fraction == b->fraction && a->id.index < b->id.index);
}

static double ray_visit(void *context, noctProxyId id, void *user, double t)
{
    (void)user;
    (void)t;
    ray *r = context;
    noctRayHit h;
    bool hit;
    r->st = ray_test(r, id.index, &hit, &h);
    if (r->st != NOCT_OK) {
        r->bad = id.index;
        return 0;
    }
    if (!hit)
        return 1;
    if (r->closest) {
        if (!r->found || before(&h, &r->best)) {
            r->best = h;
            r->found = true;
        }
        /* No box entered after the best hit (within rounding) can hold
         * one before it. */
        return noct_min(1, r->best.fraction + r->slack);
    }
    if (!grow_hits(&r->hits, &r->cap, r->cap > 0 ? r->n + 1 : 16)) {
        r->st = NOCT_ERR_NOMEM;
        r->bad = UINT32_MAX;
        return 0;
    }
    r->hits[r->n++] = h;
    return 1;
}

static int by_fraction(const void *a, const void *b)
{
    const noctRayHit *x = a, *y = b;
    return before(x, y) ? -1 : before(y, x) ? 1 : 0;
}

static noctStatus cast(const noctWorld *w, const double origin[3], const double translation[3],
                       noctQueryFilter filter, ray *r, noctError *err)
{
    noctStatus st = check_point(origin, "ray origin", err);
    if (st == NOCT_OK)
        st = check_point(translation, "ray translation", err);
    if (st != NOCT_OK)
        return st;
    r->w = w;
    double scale = 0, len = 0;
    for (int k = 0; k < 3; ++k) {
        r->p[k] = origin[k];
        r->q[k] = origin[k] + translation[k];
        r->d[k] = r->q[k] - r->p[k];
        scale = noct_max(scale, noct_max(fabs(r->p[k]), fabs(r->q[k])));
        len = noct_max(len, fabs(r->d[k]));
    }
    if ((st = check_point(r->q, "ray end", err)) != NOCT_OK)
        return st;
    r->slack = len > 0 ? noct_max(0x1p-20, 0x1p-30 * scale / len) : 1;
    /* The broadphase's ray on the same segment, from p to q. */
    st = noctBroadphaseRayCast(&w->bp, r->p, r->d, filter, ray_visit, r);
    if (st == NOCT_OK)
        st = r->st;
    if (st != NOCT_OK)
        return r->bad == UINT32_MAX
                   ? noct_fail(err, st, -1, 0, "ray cast: %s", noctStatusString(st))
                   : noct_fail(err, st, (long)r->bad, 0, "ray cast: object %u: %s", r->bad,
                               noctStatusString(st));
    return NOCT_OK;
}

noctStatus noctWorldRayCast(const noctWorld *w, const double origin[3],
                            const double translation[3], noctQueryFilter filter,
                            noctRayHitFcn *fcn, void *context, noctError *err)
{
    NOCT_REQUIRE(w != NULL && origin != NULL && translation != NULL && fcn != NULL);
    ray r;
    memset(&r, 0, sizeof r);
    noctStatus st = cast(w, origin, translation, filter, &r, err);
    if (st == NOCT_OK) {
        if (r.n > 1)
            qsort(r.hits, r.n, sizeof *r.hits, by_fraction);
        for (size_t i = 0; i < r.n; ++i)
            if (!fcn(context, &r.hits[i]))
                break;
    }
    free(r.hits);
    return st;
}

noctStatus noctWorldRayCastClosest(const noctWorld *w, const double origin[3],
                                   const double translation[3], noctQueryFilter filter,
                                   noctRayHit *hit, bool *found, noctError *err)
{
    NOCT_REQUIRE(w != NULL && origin != NULL && translation != NULL && hit != NULL);
    NOCT_REQUIRE(found != NULL);
    ray r;
    memset(&r, 0, sizeof r);
    r.closest = true;
    *found = false;
    noctStatus st = cast(w, origin, translation, filter, &r, err);
    if (st == NOCT_OK && r.found) {
        *hit = r.best;
        *found = true;
    }
    return st;
}

noctStatus noctWorldRayCastAlong(const noctWorld *w, const double origin[3],
                                 const double direction[3], double distance,
                                 noctQueryFilter filter, noctRayHit *hit, bool *found,
                                 noctError *err)
{
    NOCT_REQUIRE(w != NULL && origin != NULL && direction != NULL && hit != NULL);
    NOCT_REQUIRE(found != NULL);
    *found = false;
    for (int k = 0; k < 3; ++k)
        if (!isfinite(direction[k]))
            return noct_fail(err, NOCT_ERR_NONFINITE, -1, 0, "ray direction is not finite");
    if (!isfinite(distance))
        return noct_fail(err, NOCT_ERR_NONFINITE, -1, 0, "ray distance is not finite");
    if (distance < 0)
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0, "ray distance %g is negative", distance);
    double u[3];
    if (!noct_unit_direction(direction, u))
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0, "a ray needs a non-zero direction");
    const double translation[3] = {distance * u[0], distance * u[1], distance * u[2]};
    return noctWorldRayCastClosest(w, origin, translation, filter, hit, found, err);
}

/* ---- arrays -------------------------------------------------------------------------- */

bool noctCollectObjects(void *buffer, noctObjectId id, void *user_data)
{
    NOCT_REQUIRE(buffer != NULL);
    (void)user_data;
    noctObjectBuffer *b = buffer;
    if (b->count < b->capacity)
        b->ids[b->count] = id;
    ++b->count;
    return true;
}

bool noctCollectRayHits(void *buffer, const noctRayHit *hit)
{
    NOCT_REQUIRE(buffer != NULL && hit != NULL);
    noctRayHitBuffer *b = buffer;
    if (b->count < b->capacity)
        b->hits[b->count] = *hit;
    ++b->count;
    return true;
}

/* ---- a moving shape ----------------------------------------------------------------- */

noctStatus noctWorldCastShape(const noctWorld *w, const noctMesh *mesh,
                              const double half_extents[3], const noctTransform *x,
                              const double translation[3], noctQueryFilter filter,
                              noctShapeHit *hit, bool *found, noctError *err)
{
    NOCT_REQUIRE(w != NULL && x != NULL && translation != NULL && hit != NULL &&
                 found != NULL);
    NOCT_REQUIRE(mesh != NULL || half_extents != NULL);
    *found = false;
    noctStatus st = check_point(translation, "translation", err);
    if (st != NOCT_OK)
        return st;
    double p1[3];
    for (int k = 0; k < 3; ++k)
        p1[k] = x->p[k] + translation[k];
    if ((st = check_point(p1, "end", err)) != NOCT_OK)
        return st;
    query_shape q;
    if ((st = noct_query_shape_make(&q, mesh, half_extents, x, err)) != NOCT_OK)
        return st;
    /* The swept box: the placed boxes at both ends, padded by far more than
     * the end's placement differs from the start's moved exactly. */
    double lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
        const double pad = 0x1p-40 * (fabs(q.m->lo[k]) + fabs(q.m->hi[k]) + fabs(x->p[k]) +
                                      fabs(p1[k]));
        lo[k] = noct_min(q.m->lo[k] + x->p[k], q.m->lo[k] + p1[k]) - pad;
        hi[k] = noct_max(q.m->hi[k] + x->p[k], q.m->hi[k] + p1[k]) + pad;
    }
    candidates c;
    candidates_init(&c);
    st = gather(w, lo, hi, filter, &c, err);
    for (size_t i = 0; i < c.n && st == NOCT_OK; ++i) {
        const uint32_t s = c.s[i];
        shape sh;
        const noctMesh *m = shape_of_object(w, s, &sh);
        bool meets;
        noctSweepHit h;
        st = noctCollideSwept(q.m, x->p, p1, m, w->pos[s], w->pos[s], &meets, &h, NULL);
        if (st != NOCT_OK) {
            st = noct_fail(err, st, (long)s, 0, "object %u: %s", s, noctStatusString(st));
        } else if (meets && (!*found || h.time < hit->sweep.time)) {
            /* in order of index: a tie keeps the least */
            *found = true;
            hit->id = handle(w, s);
            hit->user_data = noct_bp_proxy(&w->bp, s)->user;
            hit->sweep = h;
        }
    }
    candidates_fini(&c);
    noctMeshDestroy(q.rotated);
    if (st != NOCT_OK)
        *found = false;
    return st;
}
