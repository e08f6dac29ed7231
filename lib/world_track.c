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

void noctTrackAt(const noctKeyframe *keys, size_t n, uint64_t tick, noctTransform *x)
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
    x->q = noct_quat_slerp(&k0->x.q, &k1->x.q, s);
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
    for (uint32_t i = 0; i < w->tracks.n; ++i)
        free(w->tracks.list[i].keys);
    free(w->tracks.list);
    free(w->tracks.of);
    memset(&w->tracks, 0, sizeof w->tracks);
}

noctStatus noctWorldSetTrack(noctWorld *w, noctObjectId id, const noctKeyframe *keys, size_t n,
                             noctError *err)
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
    }
    noct_tracks *t = &w->tracks;
    noctKeyframe *copy = malloc(n * sizeof *copy);
    if (copy == NULL || !reserve_of(w)) {
        free(copy);
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    }
    memcpy(copy, keys, n * sizeof *copy);
    uint32_t i = t->of[s];
    if (i == UINT32_MAX && !grow_tracks(&t->list, &t->cap, t->cap > 0 ? t->n + 1 : 8)) {
        free(copy);
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    }
    /* Placed now, at the current tick: as a teleport, through the
     * set-transform path (which checks the pose against the shape). */
    noctTransform x;
    noctTrackAt(copy, n, w->tick, &x);
    noctStatus st = noctWorldSetTransform(w, id, &x, err);
    if (st != NOCT_OK) {
        free(copy);
        return st;
    }
    if (i == UINT32_MAX) {
        i = t->n++;
        t->of[s] = i;
        t->list[i].slot = s;
    } else {
        free(t->list[i].keys);
    }
    t->list[i].keys = copy;
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
        noctTrackAt(tr->keys, tr->n, tick, &x);
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
