/* SPDX-License-Identifier: MIT */
/*
 * noctWorldStep() and its stages, in the order they run:
 *
 *   1. the step's setup: the events emptied, a tree owed built, the
 *      sub-steps counted, the movers listed, what a failed step of
 *      sub-steps goes back to held, the spinners listed, room for the
 *      placements;
 *   2. placements before the motion: tracks (world_track.c), then spin;
 *   3. per sub-step (substep()): the broadphase's frame begins; motion
 *      (world_motion.c) and the reach it gives the pair search;
 *      maintenance through the broadphase; the pair search (or, with a
 *      margin, the near pairs' candidates in its stead:
 *      noct_world_near_pairs()), the narrowphase (world_narrow.c), sensors
 *      and events (world_events.c); after the last, the near pairs
 *      (world_near.c); the response;
 *   4. a step that succeeded keeps its placements; one that failed gives
 *      back everything (fail_step()), one call per record.
 */
#include "config.h"

#include <math.h>
#include <string.h>

#include <noctree/world.h>

#include "world_internal.h"

static uint64_t substeps_for(noctWorld *w, noctError *err);
static bool hold_for_substeps(noctWorld *w, uint64_t k);
static bool update_spinners(noctWorld *w);
static noctStatus stage_spin(noctWorld *w, noctError *err);
static noctStatus substep(noctWorld *w, double fraction, bool first, bool last,
                          noctError *err);
static void fail_step(noctWorld *w, uint64_t k);

noctStatus noctWorldStep(noctWorld *w, noctError *err)
{
    NOCT_REQUIRE(w != NULL);
    w->contacts_made = false; /* they were the last step's */
    noct_record_clear(&w->events.contact);
    noct_record_clear(&w->events.sensor);
    noct_record_clear(&w->events.near);
    w->near_dist_made = false; /* the near pairs change, whatever the step does */
    if (noct_bp_tree_owed(&w->bp)) {
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
    const bool spin = (w->def.effects & NOCT_EFFECT_SPIN) && w->spin.count > 0;
    if (spin && !update_spinners(w))
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    const bool tracks = (w->def.effects & NOCT_EFFECT_TRACK) && w->tracks.n > 0;
    if (!noct_world_reserve_placed(w, (spin ? w->spin.nspinners : 0) +
                                          (tracks ? w->tracks.n : 0)))
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    w->substeps = k;
    ++w->c.steps;
    w->moved = w->touched = false;
    if (tracks) {
        noctStatus st = noct_world_stage_tracks(w, w->tick + 1, err);
        if (st != NOCT_OK)
            return st;
    }
    if (spin) {
        noctStatus st = stage_spin(w, err);
        if (st != NOCT_OK)
            return st;
    }
    if (w->sweeps.on) {
        w->touched = true;
        noctStatus st = noct_world_stage_grow(w);
        if (st != NOCT_OK) {
            fail_step(w, k);
            return noct_fail(err, st, -1, 0, "growing the swept boxes: %s; no object moved",
                             noctStatusString(st));
        }
    }
    for (uint64_t i = 0; i < k; ++i) {
        noctStatus st = substep(w, k == 1 ? 1 : 1.0 / (double)k, i == 0, i + 1 == k, err);
        if (st != NOCT_OK) {
            fail_step(w, k);
            return st;
        }
    }
    noct_world_placements_done(w);
    if (w->sweeps.on)
        noct_world_sweeps_done(w);
    ++w->tick;
    return NOCT_OK;
}

/* ---- 1. the step's setup ------------------------------------------------------------- */

/* How many sub-steps this step takes (1 without #NOCT_EFFECT_SUBSTEP), or
 * 0 with err set when it would be too many. */
static uint64_t substeps_for(noctWorld *w, noctError *err)
{
    if (!(w->def.effects & NOCT_EFFECT_SUBSTEP) || !(w->def.effects & NOCT_EFFECT_MOTION) ||
        w->sweeps.on) /* continuous detection makes them moot */
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

/* Keep what a failed step of k sub-steps goes back to: the contact and
 * sensor lists (the sub-steps replace them) and the movers' velocities
 * (responses may turn them). */
static bool hold_for_substeps(noctWorld *w, uint64_t k)
{
    if (k < 2)
        return true;
    if (!noct_record_hold(&w->events.contact) || !noct_record_hold(&w->events.sensor))
        return false;
    if (w->def.effects & NOCT_EFFECT_MOTION)
        for (uint32_t m = 0; m < w->motion.nmovers; ++m)
            memcpy(w->motion.prevvel[m], w->obj[w->motion.movers[m]].vel,
                   sizeof w->motion.prevvel[m]);
    return true;
}

NOCT_DEFINE_GROW(grow_u32, uint32_t)

/* The spinners (live moving objects whose angular velocity is not the
 * identity), after objects, types or angular velocities changed; false
 * without memory. */
static bool update_spinners(noctWorld *w)
{
    noct_spin *sp = &w->spin;
    if (!sp->stale)
        return true;
    size_t n = 0;
    for (uint32_t i = 0; i < noct_bp_slots(&w->bp); ++i)
        n += w->obj[i].alive && w->obj[i].type == NOCT_OBJECT_MOVING &&
             !noct_quat_is_identity(&sp->w[i]);
    if (!grow_u32(&sp->spinners, &sp->cap, n))
        return false;
    sp->nspinners = 0;
    for (uint32_t i = 0; i < noct_bp_slots(&w->bp); ++i)
        if (w->obj[i].alive && w->obj[i].type == NOCT_OBJECT_MOVING &&
            !noct_quat_is_identity(&sp->w[i]))
            sp->spinners[sp->nspinners++] = i;
    sp->stale = false;
    return true;
}

/* ---- 2. placements before the motion ------------------------------------------------- */

/* Turn each spinner by its angular velocity, q <- noctQuatCompose(w, q),
 * where it is; on failure give every placement back. */
static noctStatus stage_spin(noctWorld *w, noctError *err)
{
    noct_spin *sp = &w->spin;
    for (uint32_t k = 0; k < sp->nspinners; ++k) {
        const uint32_t s = sp->spinners[k];
        const noctQuat q = noctQuatCompose(&sp->w[s], &w->pose[s].q);
        const double p[3] = {w->pos[s][0], w->pos[s][1], w->pos[s][2]};
        noctStatus st = noct_world_place(w, s, &q, p, err);
        if (st != NOCT_OK) {
            noct_world_unplace(w);
            return st;
        }
    }
    return NOCT_OK;
}

/* ---- 3. a sub-step -------------------------------------------------------------------- */

static noctStatus stage_motion(noctWorld *w, double fraction, bool first, noctError *err);
static noctStatus stage_maintenance(noctWorld *w, bool moving);
static noctStatus stage_pairs(noctWorld *w, bool near, size_t *from_began);

/* One step, or one of k sub-steps (fraction = 1/k of the velocity); the
 * near pairs after the last. */
static noctStatus substep(noctWorld *w, double fraction, bool first, bool last,
                          noctError *err)
{
    noct_bp_begin_frame(&w->bp); /* the enter check's stamps: one tick per sub-step */
    noctStatus st = NOCT_OK;
    const double t0 = noct_seconds();
    const bool moving = (w->def.effects & NOCT_EFFECT_MOTION) != 0 && w->motion.moving > 0;
    if (moving && (st = stage_motion(w, fraction, first, err)) != NOCT_OK)
        return st;
    /* Objects a program moved since the last step (noctWorldSetTransform())
     * moved at most the pending reach each, on top of the motion. */
    if (first && noct_bp_pending_reach(&w->bp) > 0)
        noct_bp_add_reach(&w->bp, noct_bp_pending_reach(&w->bp));
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
    st = stage_pairs(w, first && last && w->margins.near, &from_began);
    if (st != NOCT_OK)
        return noct_fail(err, st, -1, 0, "pair search: %s; no object moved",
                         noctStatusString(st));
    /* near pairs with a margin (the world's or an object's), and once
     * more when the last went, to end the pairs it kept */
    if (last && w->margins.near && (st = noct_world_stage_near(w, err)) != NOCT_OK) {
        noct_record_unrotate(&w->events.contact);
        noct_record_unrotate(&w->events.sensor);
        return st;
    }
    if (first) /* the teleports' travel is in this search's reach */
        noct_bp_end_search(&w->bp);
    w->c.colliding_pairs += w->events.contact.now.n;
    const double t3 = noct_seconds();
    w->c.seconds_pairs += t3 - t2;
    if (w->def.effects & (NOCT_EFFECT_EVENTS | NOCT_EFFECT_RESPONSE)) {
        if (w->def.effects & NOCT_EFFECT_RESPONSE)
            noct_world_respond(&w->events, w->obj, &w->bp, from_began, &w->c.reversals);
        w->c.seconds_response += noct_seconds() - t3;
    }
    return NOCT_OK;
}

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
    /* |velocity| is the speed within 1e-9: a placed box moves by it and a
     * few roundings of the root's coordinates */
    noct_bp_add_reach(&w->bp, w->motion.vmax * fraction);
    return NOCT_OK;
}

/* Maintenance through the broadphase: the movers that failed the fast
 * test, or a rebuild; then the root grows or shrinks, and merges owed
 * are made. */
static noctStatus stage_maintenance(noctWorld *w, bool moving)
{
    noctStatus st = NOCT_OK;
    bool escaped = false;
    if (noct_bp_root(&w->bp) != NULL && moving) {
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

/* The pair search, narrowphase and events: the contact and sensor records
 * are rotated, the broadphase's pairs go through the narrowphase, the
 * sensors' pairs are split off, and what began and ended is found. near:
 * the step's near pairs follow (a step of one sub-step), whose candidates
 * may hold every pair the search would find (noct_world_near_pairs()):
 * then they are made first, and the search is left out. On failure the
 * records are as before. */
static noctStatus stage_pairs(noctWorld *w, bool near, size_t *from_began)
{
    noct_events *e = &w->events;
    noct_record_rotate(&e->contact);
    noct_record_rotate(&e->sensor);
    const int early = near ? noct_world_near_pairs(w) : 0;
    noctStatus st = early < 0 ? NOCT_ERR_NOMEM : early > 0 ? NOCT_OK : noct_bp_find_pairs(&w->bp);
    if (st == NOCT_OK)
        st = noct_world_narrow(w, noct_bp_found(&w->bp), &e->contact.now);
    *from_began = e->contact.began.n;
    if (st == NOCT_OK)
        noct_pairs_sort_partners(&e->contact.now);
    if (st == NOCT_OK && w->nsensors > 0)
        st = noct_world_split_sensors(e, w->obj);
    if (st == NOCT_OK && (w->def.effects & (NOCT_EFFECT_EVENTS | NOCT_EFFECT_RESPONSE))) {
        uint64_t events = 0; /* counted once both are found */
        st = noct_record_diff(&e->contact, &events);
        if (st == NOCT_OK)
            st = noct_record_diff(&e->sensor, &events);
        if (st == NOCT_OK)
            w->c.events += events;
    }
    if (st != NOCT_OK) {
        noct_record_unrotate(&e->contact);
        noct_record_unrotate(&e->sensor);
    }
    return st;
}

/* ---- 4. a failed step ------------------------------------------------------------------ */

/* Everything the step changed given back: the movers, the tree it
 * touched, the placements, and the records (with what was held for a step
 * of k > 1 sub-steps). */
static void fail_step(noctWorld *w, uint64_t k)
{
    noct_world_near_forget(w);
    noct_world_roll_back(w, w->moved, w->touched);
    noct_world_unplace(w);
    noct_record_fail(&w->events.contact, k > 1);
    noct_record_fail(&w->events.sensor, k > 1);
    noct_record_fail(&w->events.near, false);
}
