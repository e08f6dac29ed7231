/* SPDX-License-Identifier: MIT */
/*
 * The collision world (world.h): create, destroy, reserve, what it tells
 * (its pair lists, objects, counters, octree) and validation. The objects
 * are world_object.c's, the step world_step.c's; world_internal.h maps
 * the stage files.
 */
#include "config.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <noctree/world.h>

#include "world_internal.h"

/* ---- the world ------------------------------------------------------------------------ */

noctWorldDef noctDefaultWorldDef(void)
{
    noctWorldDef d;
    d.N = NOCT_AUTO;
    d.max_depth = NOCT_AUTO;
    d.accuracy = NOCT_ACCURACY_EXACT;
    d.effects = NOCT_EFFECT_MOTION | NOCT_EFFECT_EVENTS | NOCT_EFFECT_RESPONSE;
    d.maintenance = NOCT_MAINTAIN_INCREMENTAL;
    for (int k = 0; k < 3; ++k)
        d.walls_lo[k] = d.walls_hi[k] = 0;
    d.margin = 0;
    return d;
}

noctStatus noctWorldCreate(const noctWorldDef *def, noctWorld **world, noctError *err)
{
    NOCT_REQUIRE(def != NULL && world != NULL);
    *world = NULL;
    if (def->accuracy != NOCT_ACCURACY_BOX && def->accuracy != NOCT_ACCURACY_CONVEX &&
        def->accuracy != NOCT_ACCURACY_EXACT && def->accuracy != NOCT_ACCURACY_CONTINUOUS)
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0, "unknown accuracy %d",
                         (int)def->accuracy);
    if (def->effects & ~(unsigned)(NOCT_EFFECT_MOTION | NOCT_EFFECT_EVENTS |
                                   NOCT_EFFECT_RESPONSE | NOCT_EFFECT_WALLS |
                                   NOCT_EFFECT_SUBSTEP | NOCT_EFFECT_SPIN |
                                   NOCT_EFFECT_TRACK))
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
    if (!(def->margin >= 0 && def->margin <= NOCT_MAX_COORDINATE))
        return noct_fail(err, isnan(def->margin) ? NOCT_ERR_NONFINITE : NOCT_ERR_INVALID, -1, 0,
                         "margin %g: it must be 0 to %g", def->margin, NOCT_MAX_COORDINATE);
    noctWorld *w = calloc(1, sizeof *w);
    if (w == NULL)
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    /* N and the depth are checked (and, for NOCT_AUTO, chosen) there */
    noctBroadphaseDef bd = noctDefaultBroadphaseDef();
    bd.N = def->N;
    bd.max_depth = def->max_depth;
    noctStatus st = noct_bp_init(&w->bp, &bd, err);
    if (st != NOCT_OK) {
        free(w);
        return st;
    }
    noct_bp_set_rebuild_mode(&w->bp, def->maintenance == NOCT_MAINTAIN_REBUILD);
    w->def = *def;
    w->margins.near = def->margin > 0;
    w->sweeps.world = w->sweeps.on = def->accuracy == NOCT_ACCURACY_CONTINUOUS;
    *world = w;
    return NOCT_OK;
}


void noctWorldDestroy(noctWorld *w)
{
    if (w == NULL)
        return;
    for (uint32_t i = 0; i < noct_bp_slots(&w->bp); ++i)
        if (w->obj[i].alive) {
            noctMeshDestroy(w->pose[i].rotated);
            noct_turn_free(w->turn[i]);
        }
    noct_bp_fini(&w->bp);
    free(w->obj);
    free(w->pose);
    free(w->turn);
    free(w->pos);
    free(w->mesh);
    free(w->slot);
    free(w->motion.movers);
    free(w->motion.slow);
    free(w->motion.prev);
    free(w->motion.prevvel);
    free(w->motion.flips);
    free(w->motion.flip_axes);
    noct_record_free(&w->events.contact);
    noct_record_free(&w->events.sensor);
    noct_record_free(&w->events.near);
    free(w->near_dist);
    free(w->spin.w);
    free(w->spin.spinners);
    free(w->margins.of);
    free(w->hints.h);
    free(w->hints.spare);
    noct_world_free_kept(w);
    free(w->placed);
    noct_world_free_sweeps(w);
    noct_world_free_tracks(w);
    free(w->ignored.key);
    free(w->contacts);
    free(w);
}

_Static_assert(sizeof(noct_pose) == 64, "a pose is one cache line");

noctStatus noctWorldReserve(noctWorld *w, size_t more, noctError *err)
{
    NOCT_REQUIRE(w != NULL);
    if (more > 0x80000000u)
        return noct_fail(err, NOCT_ERR_TOO_LARGE, -1, 0,
                         "room for %zu more objects: a world holds at most 2^31", more);
    if (!noct_bp_reserve(&w->bp, (uint32_t)more))
        return (uint64_t)noct_bp_slots(&w->bp) - noct_bp_free_slots(&w->bp) + more > 0x80000000u
                   ? noct_fail(err, NOCT_ERR_TOO_LARGE, -1, 0,
                               "room for %zu more objects: a world holds at most 2^31",
                               more)
                   : noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    if (!noct_world_reserve_slots(w))
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    return NOCT_OK;
}

/* ---- what the world tells ---------------------------------------------------------- */

/* The pair lists: each a list of an event record (world_events.c), valid
 * until the next step. */
#define PAIR_LIST(name, list)                                                              \
    size_t name(const noctWorld *w, const noctPair **pairs)                                \
    {                                                                                      \
        NOCT_REQUIRE(w != NULL && pairs != NULL);                                          \
        return noct_list_out(&w->events.list, pairs);                                      \
    }

PAIR_LIST(noctWorldColliding, contact.now)
PAIR_LIST(noctWorldBegan, contact.began)
PAIR_LIST(noctWorldEnded, contact.ended)
PAIR_LIST(noctWorldSensing, sensor.now)
PAIR_LIST(noctWorldSensorBegan, sensor.began)
PAIR_LIST(noctWorldSensorEnded, sensor.ended)
PAIR_LIST(noctWorldNear, near.now)
PAIR_LIST(noctWorldNearBegan, near.began)
PAIR_LIST(noctWorldNearEnded, near.ended)
#undef PAIR_LIST

noctStatus noctWorldObject(const noctWorld *w, noctObjectId id, double position[3],
                           double direction[3])
{
    NOCT_REQUIRE(w != NULL);
    const noct_object *o = noct_world_lookup(w, id);
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
    return noct_bp_live(&w->bp);
}

void noctWorldGetCounters(const noctWorld *w, noctWorldCounters *counters)
{
    NOCT_REQUIRE(w != NULL && counters != NULL);
    *counters = w->c;
    const noctBroadphaseCounters *b = noct_bp_counters(&w->bp);
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
    return noct_bp_root(&w->bp);
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
    if (noct_world_lookup(w, id) == NULL)
        return NOCT_ERR_INVALID;
    memcpy(lo, noct_bp_box(&w->bp, id.index)->lo, sizeof noct_bp_box(&w->bp, id.index)->lo);
    memcpy(hi, noct_bp_box(&w->bp, id.index)->hi, sizeof noct_bp_box(&w->bp, id.index)->hi);
    return NOCT_OK;
}

noctStatus noctWorldValidate(const noctWorld *w, noctError *err)
{
    NOCT_REQUIRE(w != NULL);
    /* the objects' margins: in range, counted, none above the largest */
    size_t with_margin = 0;
    for (uint32_t i = 0; i < noct_bp_slots(&w->bp); ++i) {
        const double m = noct_world_margin(w, i);
        if (!(m >= 0 && m <= NOCT_MAX_COORDINATE) || (!w->obj[i].alive && m != 0))
            return noct_fail(err, NOCT_ERR_INVARIANT, (long)i, 0,
                             "object %u's margin %g is out of range or kept dead", i, m);
        if (m > w->margins.max)
            return noct_fail(err, NOCT_ERR_INVARIANT, (long)i, 0,
                             "object %u's margin %g is above the largest, %g", i, m,
                             w->margins.max);
        with_margin += m > 0;
    }
    if (with_margin != w->margins.count)
        return noct_fail(err, NOCT_ERR_INVARIANT, -1, 0,
                         "%zu objects have a margin, but the world counts %zu", with_margin,
                         w->margins.count);
    if ((w->def.margin > 0 || with_margin > 0) && !w->margins.near)
        return noct_fail(err, NOCT_ERR_INVARIANT, -1, 0,
                         "the world has a margin but its steps would find no near pairs");
    /* the world's own records against the broadphase's proxies */
    for (uint32_t i = 0; i < noct_bp_slots(&w->bp); ++i) {
        if (w->obj[i].alive != noct_bp_proxy(&w->bp, i)->alive)
            return noct_fail(err, NOCT_ERR_INVARIANT, (long)i, 0,
                             "object %u is %s but its proxy is not", i,
                             w->obj[i].alive ? "alive" : "dead");
        if (!w->obj[i].alive)
            continue;
        const noct_pose *p = &w->pose[i];
        if (w->mesh[i] != (p->rotated != NULL ? p->rotated : noct_world_shape_of(w, i)))
            return noct_fail(err, NOCT_ERR_INVARIANT, (long)i, 0,
                             "object %u's placed mesh is not its shape or its rotated copy",
                             i);
        double R[9];
        noctQuatToMatrix(&p->q, R, NULL);
        if (!w->obj[i].box && (p->rotated == NULL) != noct_is_identity(R))
            return noct_fail(err, NOCT_ERR_INVARIANT, (long)i, 0,
                             "object %u has %s rotated copy", i,
                             p->rotated == NULL ? "no" : "a needless");
        if ((w->obj[i].speed > 0) != (w->obj[i].type == NOCT_OBJECT_MOVING &&
                                      (w->obj[i].vel[0] != 0 || w->obj[i].vel[1] != 0 ||
                                       w->obj[i].vel[2] != 0)))
            return noct_fail(err, NOCT_ERR_INVARIANT, (long)i, 0,
                             "object %u's speed does not match its type and velocity", i);
        const noctStatus st = noct_world_check_turned(w, i, err);
        if (st != NOCT_OK)
            return st;
        noct_aabb b;
        noct_place_box(w->obj[i].mlo, w->obj[i].mhi, w->pos[i], &b);
        if (memcmp(&b, noct_bp_box(&w->bp, i), sizeof b) != 0)
            return noct_fail(err, NOCT_ERR_INVARIANT, (long)i, 0,
                             "object %u's box is not its proxy's", i);
    }
    return noctBroadphaseValidate(&w->bp, err);
}
