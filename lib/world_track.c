/* SPDX-License-Identifier: MIT */
/*
 * Tracks (#NOCT_EFFECT_TRACK): keyframes of position and rotation at
 * ticks, interpolated as noctTrackAt() documents, and the step's stage
 * that places the tracked objects. A world keeps nothing for them until
 * the first track is set.
 */
#include "config.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "world_internal.h"

/* ---- interpolation ------------------------------------------------------------- */

/* Each product and sum rounded once, in the documented order (volatile:
 * no fused multiply-add whatever the compiler's flags). */
static double lerp(double a, double b, double s)
{
    volatile double u = 1 - s;
    volatile double x = u * a;
    volatile double y = s * b;
    return x + y;
}

/* Does turn t give an axis? */
static bool has_axis(const noctKeyTurn *t)
{
    return t->axis[0] != 0 || t->axis[1] != 0 || t->axis[2] != 0;
}

/* Keyframe k0's rotation turned about t's axis through the fraction s of
 * its angle (noctTrackAtTurns()). */
static noctQuat turned(const noctQuat *q0, const noctKeyTurn *t, double s)
{
    noctQuat r;
    noctQuatFromAxisAngle(t->axis, s * t->degrees, &r); /* checked when set */
    return noctQuatCompose(&r, q0);
}

void noctTrackAtTurns(const noctKeyframe *keys, const noctKeyTurn *turns, size_t n,
                      uint64_t tick, noctTransform *x)
{
    NOCT_REQUIRE(keys != NULL && n > 0 && x != NULL);
    if (tick <= keys[0].tick) {
        *x = keys[0].x;
        return;
    }
    if (tick >= keys[n - 1].tick) {
        *x = keys[n - 1].x;
        return;
    }
    /* the last keyframe at or before tick */
    size_t lo = 0, hi = n - 1;
    while (hi - lo > 1) {
        const size_t mid = lo + (hi - lo) / 2;
        if (keys[mid].tick <= tick)
            lo = mid;
        else
            hi = mid;
    }
    const noctKeyframe *k0 = &keys[lo], *k1 = &keys[lo + 1];
    if (tick == k0->tick) {
        *x = k0->x;
        return;
    }
    const double s = (double)(tick - k0->tick) / (double)(k1->tick - k0->tick);
    for (int c = 0; c < 3; ++c)
        x->p[c] = lerp(k0->x.p[c], k1->x.p[c], s);
    if (turns != NULL && has_axis(&turns[lo + 1]))
        x->q = turned(&k0->x.q, &turns[lo + 1], s);
    else
        x->q = noct_quat_slerp(&k0->x.q, &k1->x.q, s);
}

void noctTrackAt(const noctKeyframe *keys, size_t n, uint64_t tick, noctTransform *x)
{
    noctTrackAtTurns(keys, NULL, n, tick, x);
}

/* ---- the world's tracks ----------------------------------------------------------- */

static noctStatus stale_handle(noctObjectId id, noctError *err)
{
    return noct_fail(err, NOCT_ERR_INVALID, (long)id.index, 0,
                     "stale or unknown object handle (%u, %u)", id.index, id.generation);
}

static bool live(const noctWorld *w, noctObjectId id)
{
    return id.index < noct_bp_slots(&w->bp) && w->obj[id.index].alive &&
           noct_bp_generation(&w->bp, id.index) == id.generation;
}

NOCT_DEFINE_GROW(grow_tracks, noct_track)
NOCT_DEFINE_RESIZE(resize_u32, uint32_t)

/* The per-slot index, to the broadphase's capacity; false without memory. */
static bool reserve_of(noctWorld *w)
{
    noct_tracks *t = &w->tracks;
    if (t->of != NULL && w->capslots <= t->capof)
        return true;
    const uint32_t from = t->of == NULL ? 0 : t->capof;
    if (!resize_u32(&t->of, w->capslots))
        return false;
    for (uint32_t i = from; i < w->capslots; ++i)
        t->of[i] = UINT32_MAX;
    t->capof = w->capslots;
    return true;
}

void noct_world_free_tracks(noctWorld *w)
{
    for (uint32_t i = 0; i < w->tracks.n; ++i) {
        free(w->tracks.list[i].keys);
        free(w->tracks.list[i].turns);
    }
    free(w->tracks.list);
    free(w->tracks.of);
    memset(&w->tracks, 0, sizeof w->tracks);
}

/* Does turn t lead from keyframe a's rotation to b's, less than half a
 * turn a tick? */
static noctStatus check_turn(const noctKeyframe *a, const noctKeyframe *b, const noctKeyTurn *t,
                             size_t k, noctError *err)
{
    for (int c = 0; c < 3; ++c)
        if (!isfinite(t->axis[c]))
            return noct_fail(err, NOCT_ERR_NONFINITE, (long)k, 0,
                             "keyframe %zu: the turn's axis is not finite", k);
    if (!isfinite(t->degrees))
        return noct_fail(err, NOCT_ERR_NONFINITE, (long)k, 0,
                         "keyframe %zu: the turn's angle is not finite", k);
    const double ticks = (double)(b->tick - a->tick);
    if (!(fabs(t->degrees) < 180 * ticks))
        return noct_fail(err, NOCT_ERR_INVALID, (long)k, 0,
                         "keyframe %zu: a turn of %g degrees in %.0f ticks is half a turn a "
                         "tick or more", k, t->degrees, ticks);
    const noctQuat q = turned(&a->x.q, t, 1);
    const double d = q.x * b->x.q.x + q.y * b->x.q.y + q.z * b->x.q.z + q.w * b->x.q.w;
    if (!(fabs(d) >= 1 - 0x1p-30))
        return noct_fail(err, NOCT_ERR_INVALID, (long)k, 0,
                         "keyframe %zu: turning keyframe %zu's rotation by %g degrees about "
                         "the axis does not give its rotation", k, k - 1, t->degrees);
    return NOCT_OK;
}

noctStatus noctWorldSetTrack(noctWorld *w, noctObjectId id, const noctKeyframe *keys, size_t n,
                             noctError *err)
{
    return noctWorldSetTrackTurns(w, id, keys, NULL, n, err);
}

noctStatus noctWorldSetTrackTurns(noctWorld *w, noctObjectId id, const noctKeyframe *keys,
                                  const noctKeyTurn *turns, size_t n, noctError *err)
{
    NOCT_REQUIRE(w != NULL && (keys != NULL || n == 0));
    if (!live(w, id))
        return stale_handle(id, err);
    const uint32_t s = id.index;
    if (n == 0) {
        noct_world_drop_track(w, s);
        return NOCT_OK;
    }
    for (size_t k = 0; k < n; ++k) {
        if (k > 0 && !(keys[k].tick > keys[k - 1].tick))
            return noct_fail(err, NOCT_ERR_INVALID, (long)k, 0,
                             "keyframe %zu: tick %llu is not after keyframe %zu's tick %llu",
                             k, (unsigned long long)keys[k].tick, k - 1,
                             (unsigned long long)keys[k - 1].tick);
        noctStatus st = noctTransformCheck(&keys[k].x, err);
        if (st != NOCT_OK) {
            if (err != NULL) {
                char why[NOCT_ERROR_MESSAGE_SIZE];
                memcpy(why, err->message, sizeof why);
                noct_fail(err, st, (long)k, 0, "keyframe %zu: %s", k, why);
            }
            return st;
        }
        if (k > 0 && turns != NULL && has_axis(&turns[k]) &&
            (st = check_turn(&keys[k - 1], &keys[k], &turns[k], k, err)) != NOCT_OK)
            return st;
    }
    /* turns that give no axis anywhere: none kept */
    bool any = false;
    for (size_t k = 1; turns != NULL && k < n && !any; ++k)
        any = has_axis(&turns[k]);
    noct_tracks *t = &w->tracks;
    noctKeyframe *copy = malloc(n * sizeof *copy);
    noctKeyTurn *tcopy = any ? malloc(n * sizeof *tcopy) : NULL;
    if (copy == NULL || (any && tcopy == NULL) || !reserve_of(w)) {
        free(copy);
        free(tcopy);
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    }
    memcpy(copy, keys, n * sizeof *copy);
    if (any) {
        memcpy(tcopy, turns, n * sizeof *tcopy);
        tcopy[0] = (noctKeyTurn){{0, 0, 0}, 0};
    }
    uint32_t i = t->of[s];
    if (i == UINT32_MAX && !grow_tracks(&t->list, &t->cap, t->cap > 0 ? t->n + 1 : 8)) {
        free(copy);
        free(tcopy);
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    }
    /* Placed now, at the current tick: as a teleport, through the
     * set-transform path (which checks the pose against the shape). */
    noctTransform x;
    noctTrackAtTurns(copy, tcopy, n, w->tick, &x);
    noctStatus st = noctWorldSetTransform(w, id, &x, err);
    if (st != NOCT_OK) {
        free(copy);
        free(tcopy);
        return st;
    }
    if (i == UINT32_MAX) {
        i = t->n++;
        t->of[s] = i;
        t->list[i].slot = s;
    } else {
        free(t->list[i].keys);
        free(t->list[i].turns);
    }
    t->list[i].keys = copy;
    t->list[i].turns = tcopy;
    t->list[i].n = n;
    return NOCT_OK;
}

size_t noctWorldGetTrack(const noctWorld *w, noctObjectId id, const noctKeyframe **keys)
{
    NOCT_REQUIRE(w != NULL && keys != NULL);
    *keys = NULL;
    if (!live(w, id) || w->tracks.of == NULL || id.index >= w->tracks.capof ||
        w->tracks.of[id.index] == UINT32_MAX)
        return 0;
    const noct_track *tr = &w->tracks.list[w->tracks.of[id.index]];
    *keys = tr->keys;
    return tr->n;
}

size_t noctWorldGetTrackTurns(const noctWorld *w, noctObjectId id, const noctKeyTurn **turns)
{
    NOCT_REQUIRE(w != NULL && turns != NULL);
    const noctKeyframe *keys;
    const size_t n = noctWorldGetTrack(w, id, &keys);
    *turns = n > 0 ? w->tracks.list[w->tracks.of[id.index]].turns : NULL;
    return *turns != NULL ? n : 0;
}

uint64_t noctWorldTick(const noctWorld *w)
{
    NOCT_REQUIRE(w != NULL);
    return w->tick;
}

/* In the list's order, which only the operations made decide. */
noctStatus noct_world_stage_tracks(noctWorld *w, uint64_t tick, noctError *err)
{
    const noct_tracks *t = &w->tracks;
    for (uint32_t i = 0; i < t->n; ++i) {
        const noct_track *tr = &t->list[i];
        const uint32_t s = tr->slot;
        noctTransform x;
        noctTrackAtTurns(tr->keys, tr->turns, tr->n, tick, &x);
        noctStatus st = noct_world_place(w, s, &x.q, x.p, err);
        if (st != NOCT_OK) {
            if (err != NULL) {
                char why[NOCT_ERROR_MESSAGE_SIZE];
                memcpy(why, err->message, sizeof why);
                noct_fail(err, st, (long)s, 0, "object %u's track at tick %llu: %s", s,
                          (unsigned long long)tick, why);
            }
            noct_world_unplace(w);
            return st;
        }
    }
    return NOCT_OK;
}
