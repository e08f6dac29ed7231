/* SPDX-License-Identifier: MIT */
/*
 * The collision world (world.h): objects with meshes, positions and
 * velocities, as proxies of the broadphase it embeds, and noctWorldStep()
 * as the sequence of its stages, each in its own file (world_internal.h):
 * motion, maintenance through the broadphase, the pair search, the
 * narrowphase dispatch, events and response, in sub-steps if the scene
 * asks for them.
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <noctree/world.h>

#include "world_internal.h"

double noct_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* ---- the world and its objects ----------------------------------------------------- */

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
    noctBroadphaseDef bd = noctDefaultBroadphaseDef();
    bd.N = def->N;
    bd.max_depth = def->max_depth;
    noctStatus st = noct_bp_init(&w->bp, &bd, err);
    if (st != NOCT_OK) {
        free(w);
        return st;
    }
    w->bp.rebuild_mode = def->maintenance == NOCT_MAINTAIN_REBUILD;
    w->def = *def;
    *world = w;
    return NOCT_OK;
}


void noctWorldDestroy(noctWorld *w)
{
    if (w == NULL)
        return;
    noct_bp_fini(&w->bp);
    free(w->obj);
    free(w->pos);
    free(w->mesh);
    free(w->slot);
    free(w->motion.movers);
    free(w->motion.slow);
    free(w->motion.prev);
    free(w->motion.prevvel);
    free(w->motion.flips);
    free(w->events.colliding.p);
    free(w->events.previous.p);
    free(w->events.began.p);
    free(w->events.ended.p);
    free(w->events.held.p);
    free(w->events.mark);
    for (size_t i = 0; i < w->nowned; ++i)
        noctMeshDestroy(w->owned[i]);
    free(w->owned);
    free(w);
}

static noct_object *lookup(const noctWorld *w, noctObjectId id)
{
    if (id.index >= w->bp.nslots || !w->obj[id.index].alive ||
        w->bp.gen[id.index] != id.generation)
        return NULL;
    return &w->obj[id.index];
}

/* The world's per-slot arrays to the broadphase's capacity; each that
 * grew is kept even if a later one fails. */
static bool reserve_slots(noctWorld *w)
{
    const uint32_t cap = w->bp.capslots;
    if (cap <= w->capslots)
        return true;
#define GROW(field)                                                      \
    do {                                                                 \
        void *q = realloc(w->field, (size_t)cap * sizeof *w->field);     \
        if (q == NULL)                                                   \
            return false;                                                \
        w->field = q;                                                    \
    } while (0)
    GROW(obj);
    GROW(pos);
    GROW(mesh);
    GROW(events.mark);
#undef GROW
    /* aligned, so not realloc */
    noct_box_slot *slots = aligned_alloc(64, cap * sizeof *slots);
    if (slots == NULL)
        return false;
    if (w->capslots > 0)
        memcpy(slots, w->slot, w->capslots * sizeof *slots);
    free(w->slot);
    w->slot = slots;
    w->capslots = cap;
    return true;
}

noctStatus noctWorldAdd(noctWorld *w, const noctMesh *mesh, const double position[3],
                        const double direction[3], double speed, noctObjectId *id,
                        noctError *err)
{
    NOCT_REQUIRE(w != NULL && mesh != NULL && position != NULL && direction != NULL);
    NOCT_REQUIRE(id != NULL);
    id->index = id->generation = 0;
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
    const uint32_t slot = noct_bp_new_slot(&w->bp);
    if (slot == UINT32_MAX)
        return w->bp.nslots >= 0x80000000u
                   ? noct_fail(err, NOCT_ERR_TOO_LARGE, -1, 0, "too many objects")
                   : noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    if (!reserve_slots(w)) {
        /* the slot is not live yet: give it back as it is (a new last
         * slot goes altogether: the world's arrays may not reach it) */
        if (slot + 1 == w->bp.nslots)
            --w->bp.nslots;
        else
            w->bp.free_slots[w->bp.nfree++] = slot;
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    }
    noct_object *o = &w->obj[slot];
    memset(o, 0, sizeof *o);
    o->mesh = w->mesh[slot] = mesh;
    memcpy(o->mlo, mesh->lo, sizeof o->mlo);
    memcpy(o->mhi, mesh->hi, sizeof o->mhi);
    o->speed = speed;
    for (int k = 0; k < 3; ++k) {
        w->pos[slot][k] = position[k];
        o->vel[k] = speed * unit[k];
    }
    w->events.mark[slot] = 0;
    if (mesh->has_box)
        noct_box_slot_fill(mesh, &w->slot[slot]);
    else
        w->slot[slot].has_box = 0;
    noctStatus st = noct_bp_add(&w->bp, slot, mesh->lo, mesh->hi, position, NULL,
                                NOCT_FILTER_ALL, NOCT_FILTER_ALL);
    if (st != NOCT_OK)
        return noct_fail(err, st, -1, 0, "out of memory");
    o->alive = true;
    w->motion.moving += speed > 0;
    w->motion.stale = w->motion.stale || speed > 0;
    id->index = slot;
    id->generation = w->bp.gen[slot];
    return NOCT_OK;
}

noctStatus noctWorldRemove(noctWorld *w, noctObjectId id)
{
    NOCT_REQUIRE(w != NULL);
    noct_object *o = lookup(w, id);
    if (o == NULL)
        return NOCT_ERR_INVALID;
    noct_bp_free_slot(&w->bp, id.index); /* cannot fail */
    o->alive = false;
    NOCT_INVARIANT(w->motion.moving >= (size_t)(o->speed > 0));
    w->motion.moving -= o->speed > 0;
    w->motion.stale = w->motion.stale || o->speed > 0;
    /* Drop its pairs from the lists a caller may read. */
    noct_pair_list *lists[2] = {&w->events.colliding, &w->events.previous};
    for (int l = 0; l < 2; ++l) {
        size_t k = 0;
        for (size_t i = 0; i < lists[l]->n; ++i)
            if (lists[l]->p[i].a.index != id.index && lists[l]->p[i].b.index != id.index)
                lists[l]->p[k++] = lists[l]->p[i];
        lists[l]->n = k;
    }
    w->events.began.n = w->events.ended.n = 0;
    return NOCT_OK;
}

/* ---- the step ------------------------------------------------------------------------ */

/*
 * Motion: the movers move and their boxes are placed; the fast test lists
 * those whose leaves may have changed. Returns TOO_LARGE (naming the
 * object) for a mover that would leave the coordinate range.
 */
static noctStatus stage_motion(noctWorld *w, double fraction, bool first, noctError *err)
{
    const uint32_t far = noct_world_move(w, fraction, first);
    w->moved = true;
    if (far != UINT32_MAX)
        return noct_fail(err, NOCT_ERR_TOO_LARGE, (long)far, 0,
                         "object %u would move beyond %g; no object moved", far,
                         NOCT_MAX_COORDINATE);
    w->c.moved += w->motion.nmovers;
    /* |velocity| is the speed within 1e-9; a placed box moves by it and a
     * few roundings of the root's coordinates: the pair search's reach. */
    const noct_aabb root = noct_bp_root_box(&w->bp);
    double r = 0;
    for (int k = 0; k < 3; ++k)
        r = noct_max(r, noct_max(fabs(root.lo[k]), fabs(root.hi[k])));
    w->bp.reach = w->motion.vmax * fraction * (1 + 1e-6) + 8 * 0x1p-52 * (isfinite(r) ? r : 0);
    return NOCT_OK;
}

/* Maintenance through the broadphase: the movers that failed the fast
 * test, or a rebuild; then the root grows or shrinks, and merges owed
 * are made. */
static noctStatus stage_maintenance(noctWorld *w, bool moving)
{
    noctStatus st = NOCT_OK;
    bool escaped = false;
    if (w->bp.root != NULL && moving) {
        if (w->def.maintenance == NOCT_MAINTAIN_REBUILD) {
            escaped = noct_world_movers_escaped(w);
            if (!escaped)
                st = noct_bp_rebuild(&w->bp, 0);
        } else {
            st = noct_bp_maintain(&w->bp, (const double (*)[3])w->pos, w->motion.slow,
                                  w->motion.nslow, w->motion.nmovers - w->motion.nslow,
                                  &escaped);
        }
    }
    if (st == NOCT_OK)
        st = noct_bp_settle(&w->bp, escaped);
    return st;
}

/* The pair search, narrowphase and events: the colliding list becomes
 * the previous one, the broadphase's pairs go through the narrowphase,
 * and what began and ended is found. On failure the colliding list is
 * the one before. */
static noctStatus stage_pairs(noctWorld *w, size_t *from_began)
{
    noct_events *e = &w->events;
    noct_pair_list tmp = e->previous;
    e->previous = e->colliding;
    e->colliding = tmp;
    e->colliding.n = 0;
    noctStatus st = noct_bp_search(&w->bp);
    if (st == NOCT_OK && !noct_bp_sort_tested(&w->bp))
        st = NOCT_ERR_NOMEM;
    if (st == NOCT_OK)
        st = noct_world_narrow(w, &w->bp.tested, &e->colliding);
    *from_began = e->began.n;
    if (st == NOCT_OK)
        noct_pairs_sort_partners(&e->colliding);
    if (st == NOCT_OK && (w->def.effects & (NOCT_EFFECT_EVENTS | NOCT_EFFECT_RESPONSE)))
        st = noct_world_diff_events(e, &w->c.events);
    if (st != NOCT_OK) {
        tmp = e->colliding;
        e->colliding = e->previous;
        e->previous = tmp;
    }
    return st;
}

/* One step, or one of k sub-steps (fraction = 1/k of the velocity). */
static noctStatus substep(noctWorld *w, double fraction, bool first, noctError *err)
{
    ++w->bp.clock; /* the enter check's stamps: one tick per sub-step */
    ++w->bp.frame;
    noctStatus st = NOCT_OK;
    const double t0 = noct_seconds();
    const bool moving = (w->def.effects & NOCT_EFFECT_MOTION) != 0 && w->motion.moving > 0;
    w->bp.reach = 0;
    if (moving && (st = stage_motion(w, fraction, first, err)) != NOCT_OK)
        return st;
    const double t1 = noct_seconds();
    if (moving)
        w->c.seconds_motion += t1 - t0;
    w->touched = true; /* from here on, the tree may change */
    st = stage_maintenance(w, moving);
    if (moving)
        w->c.seconds_maintenance += noct_seconds() - t1;
    if (st != NOCT_OK)
        return noct_fail(err, st, -1, 0, "octree maintenance: %s; no object moved",
                         noctStatusString(st));
    const double t2 = noct_seconds();
    size_t from_began;
    st = stage_pairs(w, &from_began);
    if (st != NOCT_OK)
        return noct_fail(err, st, -1, 0, "pair search: %s; no object moved",
                         noctStatusString(st));
    w->c.colliding_pairs += w->events.colliding.n;
    const double t3 = noct_seconds();
    w->c.seconds_pairs += t3 - t2;
    if (w->def.effects & (NOCT_EFFECT_EVENTS | NOCT_EFFECT_RESPONSE)) {
        if (w->def.effects & NOCT_EFFECT_RESPONSE)
            noct_world_respond(&w->events, w->obj, from_began, &w->c.reversals);
        w->c.seconds_response += noct_seconds() - t3;
    }
    return NOCT_OK;
}

/* How many sub-steps this step takes (1 without #NOCT_EFFECT_SUBSTEP), or
 * 0 with err set when it would be too many. */
static uint64_t substeps_for(noctWorld *w, noctError *err)
{
    if (!(w->def.effects & NOCT_EFFECT_SUBSTEP) || !(w->def.effects & NOCT_EFFECT_MOTION))
        return 1;
    uint32_t which;
    const double ratio = noct_world_step_ratio(w, &which);
    uint64_t k = 1;
    /* Each sub-step moves every object at most half its smallest size. */
    if (ratio > 0.5) {
        if (!(2 * ratio <= (double)NOCT_MAX_SUBSTEPS)) {
            noct_fail(err, NOCT_ERR_TOO_LARGE, (long)which, 0,
                      "object %u moves %g times its smallest size a step; "
                      "sub-steps of half its size would be more than %u",
                      which, ratio, (unsigned)NOCT_MAX_SUBSTEPS);
            return 0;
        }
        k = (uint64_t)ceil(2 * ratio);
    }
    w->c.substeps += k;
    return k;
}

/* Keep what a failed step of k sub-steps goes back to: the colliding list
 * (the sub-steps replace it) and the movers' velocities (responses may
 * turn them). */
static bool hold_for_substeps(noctWorld *w, uint64_t k)
{
    if (k < 2)
        return true;
    noct_pair_list *h = &w->events.held, *c = &w->events.colliding;
    if (h->cap < c->n) {
        noctPair *q = realloc(h->p, c->n * sizeof *q);
        if (q == NULL)
            return false;
        h->p = q;
        h->cap = c->n;
    }
    if (c->n > 0)
        memcpy(h->p, c->p, c->n * sizeof *h->p);
    h->n = c->n;
    if (w->def.effects & NOCT_EFFECT_MOTION)
        for (uint32_t m = 0; m < w->motion.nmovers; ++m)
            memcpy(w->motion.prevvel[m], w->obj[w->motion.movers[m]].vel,
                   sizeof w->motion.prevvel[m]);
    return true;
}

noctStatus noctWorldStep(noctWorld *w, noctError *err)
{
    NOCT_REQUIRE(w != NULL);
    w->events.began.n = w->events.ended.n = 0;
    if (w->bp.tree_owed) {
        noctStatus st = noct_bp_rebuild(&w->bp, 0);
        if (st != NOCT_OK)
            return noct_fail(err, st, -1, 0, "rebuilding the octree: %s",
                             noctStatusString(st));
    }
    const uint64_t k = substeps_for(w, err);
    if (k == 0)
        return NOCT_ERR_TOO_LARGE;
    if ((w->def.effects & NOCT_EFFECT_MOTION) && w->motion.moving > 0 &&
        !noct_world_update_movers(w))
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    if (!hold_for_substeps(w, k))
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    w->substeps = k;
    ++w->c.steps;
    w->moved = w->touched = false;
    for (uint64_t i = 0; i < k; ++i) {
        noctStatus st = substep(w, k == 1 ? 1 : 1.0 / (double)k, i == 0, err);
        if (st != NOCT_OK) {
            noct_world_roll_back(w, w->moved, w->touched);
            if (k > 1) {
                noct_pair_list t = w->events.colliding;
                w->events.colliding = w->events.held;
                w->events.held = t;
            }
            w->events.began.n = w->events.ended.n = 0;
            return st;
        }
    }
    return NOCT_OK;
}

/* ---- what the world tells ---------------------------------------------------------- */

size_t noctWorldColliding(const noctWorld *w, const noctPair **pairs)
{
    NOCT_REQUIRE(w != NULL && pairs != NULL);
    *pairs = w->events.colliding.p;
    return w->events.colliding.n;
}

size_t noctWorldBegan(const noctWorld *w, const noctPair **pairs)
{
    NOCT_REQUIRE(w != NULL && pairs != NULL);
    *pairs = w->events.began.p;
    return w->events.began.n;
}

size_t noctWorldEnded(const noctWorld *w, const noctPair **pairs)
{
    NOCT_REQUIRE(w != NULL && pairs != NULL);
    *pairs = w->events.ended.p;
    return w->events.ended.n;
}

noctStatus noctWorldObject(const noctWorld *w, noctObjectId id, double position[3],
                           double direction[3])
{
    NOCT_REQUIRE(w != NULL);
    const noct_object *o = lookup(w, id);
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
    return w->bp.alive;
}

void noctWorldGetCounters(const noctWorld *w, noctWorldCounters *counters)
{
    NOCT_REQUIRE(w != NULL && counters != NULL);
    *counters = w->c;
    const noctBroadphaseCounters *b = &w->bp.c;
    counters->inside_fast = b->inside_fast;
    counters->leaves_left = b->leaves_left;
    counters->leaves_entered = b->leaves_entered;
    counters->neighbor_queries = b->neighbor_queries;
    counters->reinserts = b->reinserts;
    counters->splits = b->splits;
    counters->merges = b->merges;
    counters->rebuilds = b->rebuilds;
    counters->leaves_visited = b->leaves_visited;
    counters->leaves_skipped = b->leaves_skipped;
    counters->candidate_pairs = b->candidate_pairs;
}

double noctWorldMaxStepRatio(const noctWorld *w)
{
    NOCT_REQUIRE(w != NULL);
    uint32_t which;
    return noct_world_step_ratio(w, &which);
}

octNode *noctWorldRoot(const noctWorld *w)
{
    NOCT_REQUIRE(w != NULL);
    return w->bp.root;
}

const noctBroadphase *noctWorldBroadphase(const noctWorld *w)
{
    NOCT_REQUIRE(w != NULL);
    return &w->bp;
}

void noctWorldPrintCell(FILE *strm, const void *data)
{
    NOCT_REQUIRE(strm != NULL && data != NULL);
    noctBroadphasePrintCell(strm, data);
}

size_t noctWorldCell(const noctWorld *w, const octNode *node, double lo[3], double *size,
                     noctObjectId *objects, size_t max)
{
    NOCT_REQUIRE(w != NULL && node != NULL && (objects != NULL || max == 0));
    return noctBroadphaseCell(&w->bp, node, lo, size, objects, max);
}

noctStatus noctWorldObjectBox(const noctWorld *w, noctObjectId id, double lo[3],
                              double hi[3])
{
    NOCT_REQUIRE(w != NULL && lo != NULL && hi != NULL);
    if (lookup(w, id) == NULL)
        return NOCT_ERR_INVALID;
    memcpy(lo, w->bp.box[id.index].lo, sizeof w->bp.box[id.index].lo);
    memcpy(hi, w->bp.box[id.index].hi, sizeof w->bp.box[id.index].hi);
    return NOCT_OK;
}

noctStatus noctWorldValidate(const noctWorld *w, noctError *err)
{
    NOCT_REQUIRE(w != NULL);
    /* the world's own records against the broadphase's proxies */
    for (uint32_t i = 0; i < w->bp.nslots; ++i) {
        if (w->obj[i].alive != w->bp.proxy[i].alive)
            return noct_fail(err, NOCT_ERR_INVARIANT, (long)i, 0,
                             "object %u is %s but its proxy is not", i,
                             w->obj[i].alive ? "alive" : "dead");
        if (!w->obj[i].alive)
            continue;
        noct_aabb b;
        noct_place_box(w->obj[i].mlo, w->obj[i].mhi, w->pos[i], &b);
        if (memcmp(&b, &w->bp.box[i], sizeof b) != 0)
            return noct_fail(err, NOCT_ERR_INVARIANT, (long)i, 0,
                             "object %u's box is not its proxy's", i);
    }
    return noctBroadphaseValidate(&w->bp, err);
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
