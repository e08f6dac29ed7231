/* SPDX-License-Identifier: MIT */
/*
 * Continuous detection in the world (accuracy #NOCT_ACCURACY_CONTINUOUS).
 *
 * Each object's step goes from where the last step left it (start) to
 * where it is after the step's placements and motion. The broadphase must
 * hand over every pair whose swept solids may touch, so each object that
 * may move enters the tree with its local box grown on every side by g:
 * its box at the step's end then holds its box at the start. With d the
 * exact displacement on an axis, the end box's low side is
 * fl(fl(lo - g) + pe) and the start box's fl(lo + ps); when
 * g >= |d| + ulp(lo), fl(lo - g) <= lo - |d| and so
 * fl(lo - g) + pe <= lo + ps, which rounding keeps (it is monotone): no
 * padding for the positions' magnitudes. A velocity v moves an object by
 * d = fl(ps + v) - ps, and |d| <= 2 |v| (round to nearest: the error is
 * at most the distance to ps, |v|), so a mover's growth is 2 |v| plus
 * what a program or a stage moved it since its start, and it stays while
 * the velocity's magnitude does (the walls and the response turn only its
 * signs).
 *
 * The growth is made before the motion, for the movers and the objects
 * placed since (todo), through the broadphase's move; an object that was
 * placed keeps its place in todo until a step ends with it where it
 * started, so that its growth shrinks back.
 */
#include "config.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <noctree/world.h>

#include "world_internal.h"

NOCT_DEFINE_RESIZE(resize_vec3s, noct_vec3)
NOCT_DEFINE_RESIZE(resize_boxes, noct_box6)
NOCT_DEFINE_RESIZE(resize_u32s, uint32_t)
NOCT_DEFINE_RESIZE(resize_u8s, uint8_t)
NOCT_DEFINE_RESIZE(resize_u64s, uint64_t)
NOCT_DEFINE_RESIZE(resize_quats, noctQuat)
NOCT_DEFINE_RESIZE(resize_doubles, double)
NOCT_DEFINE_GROW(grow_hits, noctSweepHit)

/* The sweeps' arrays to cap slots, those from slot `from` on marked
 * neither in todo nor moved by a step. */
static bool reserve_from(noctWorld *w, uint32_t from, uint32_t cap)
{
    noct_sweeps *sw = &w->sweeps;
    if (!resize_vec3s(&sw->start, cap) || !resize_vec3s(&sw->from, cap) ||
        !resize_quats(&sw->start_q, cap) || !resize_quats(&sw->from_q, cap) ||
        !resize_doubles(&sw->radius, cap) ||
        !resize_u64s(&sw->from_tick, cap) || !resize_boxes(&sw->base, cap) ||
        !resize_vec3s(&sw->grow, cap) || !resize_u32s(&sw->todo, cap) ||
        !resize_u8s(&sw->in_todo, cap))
        return false;
    for (uint32_t s = from; s < cap; ++s) {
        sw->in_todo[s] = 0;
        sw->from_tick[s] = UINT64_MAX;
    }
    return true;
}

bool noct_world_reserve_sweeps(noctWorld *w, uint32_t cap)
{
    return !w->sweeps.on || reserve_from(w, w->capslots, cap);
}

/* Object s's radius, for the growth a turn asks. */
static void set_radius(noctWorld *w, uint32_t s)
{
    double r2 = 0;
    const noctMesh *m = noct_world_shape_of(w, s);
    if (m == NULL)
        r2 = noct_dot3(w->pose[s].shape.half, w->pose[s].shape.half);
    else
        for (size_t i = 0; i < m->nv; ++i)
            r2 = noct_max(r2, noct_dot3(&m->v[3 * i], &m->v[3 * i]));
    w->sweeps.radius[s] = sqrt(r2) * (1 + 0x1p-40);
}

bool noct_world_sweeps_enable(noctWorld *w)
{
    noct_sweeps *sw = &w->sweeps;
    if (sw->on)
        return true;
    if (w->capslots > 0 && !reserve_from(w, 0, w->capslots))
        return false; /* what grew is kept, unused, for the next try */
    sw->on = true;
    sw->ntodo = 0;
    for (uint32_t s = 0; s < noct_bp_slots(&w->bp); ++s) {
        if (!w->obj[s].alive)
            continue;
        /* no growth yet: the local box is the mesh's */
        memcpy(sw->start[s], w->pos[s], sizeof sw->start[s]);
        sw->start_q[s] = w->pose[s].q;
        memcpy(sw->base[s], w->obj[s].mlo, sizeof w->obj[s].mlo);
        memcpy(sw->base[s] + 3, w->obj[s].mhi, sizeof w->obj[s].mhi);
        memset(sw->grow[s], 0, sizeof sw->grow[s]);
        set_radius(w, s);
    }
    return true;
}

void noct_world_free_sweeps(noctWorld *w)
{
    noct_sweeps *sw = &w->sweeps;
    free(sw->start);
    free(sw->from);
    free(sw->from_tick);
    free(sw->start_q);
    free(sw->from_q);
    free(sw->radius);
    free(sw->base);
    free(sw->grow);
    free(sw->todo);
    free(sw->in_todo);
    free(sw->hits);
}

void noct_world_sweep_touch(noctWorld *w, uint32_t s, bool made)
{
    noct_sweeps *sw = &w->sweeps;
    if (!sw->on)
        return;
    if (made) {
        memcpy(sw->start[s], w->pos[s], sizeof sw->start[s]);
        sw->start_q[s] = w->pose[s].q;
        sw->from_tick[s] = UINT64_MAX;
        set_radius(w, s);
    }
    if (!sw->in_todo[s]) {
        sw->in_todo[s] = 1;
        sw->todo[sw->ntodo++] = s;
    }
}

void noct_world_sweep_reshaped(noctWorld *w, uint32_t s)
{
    noct_sweeps *sw = &w->sweeps;
    if (!sw->on)
        return;
    const noct_object *o = &w->obj[s];
    memcpy(sw->base[s], o->mlo, sizeof o->mlo);
    memcpy(sw->base[s] + 3, o->mhi, sizeof o->mhi);
    memset(sw->grow[s], 0, sizeof sw->grow[s]);
    noct_world_sweep_touch(w, s, false);
}

/* The growth object s's motion this step asks for (the top of the file):
 * 0 for an object that is where it started and will not move. */
static void wanted(const noctWorld *w, uint32_t s, double g[3])
{
    const noct_object *o = &w->obj[s];
    const double *start = w->sweeps.start[s], *base = w->sweeps.base[s];
    const bool moves = (w->def.effects & NOCT_EFFECT_MOTION) &&
                       o->type == NOCT_OBJECT_MOVING && o->speed > 0;
    const bool cont = noct_world_continuous(w, s);
    const bool turned = memcmp(&w->sweeps.start_q[s], &w->pose[s].q, sizeof(noctQuat)) != 0;
    /* a discrete object is where the step leaves it: no growth */
    bool still = !cont || (!moves && !turned && memcmp(start, w->pos[s], 3 * sizeof *start) == 0);
    /* A turn by theta moves no point farther than r theta (the end box
     * grown by it holds the turning solid). */
    double arc = 0;
    if (turned) {
        const noctQuat *a = &w->sweeps.start_q[s], *b = &w->pose[s].q;
        double d = fabs(a->x * b->x + a->y * b->y + a->z * b->z + a->w * b->w);
        arc = w->sweeps.radius[s] * (2 * acos(noct_min(d, 1)) * (1 + 0x1p-40) + 0x1p-24);
    }
    for (int k = 0; k < 3; ++k) {
        if (still) {
            g[k] = 0;
            continue;
        }
        /* fl(|a - b|) (1 + 2^-49) >= |a - b|; each later sum rounded up
         * by the factor at the end, the ulp of the box's side by 2^-50 of
         * its magnitude, and a few of the least doubles for subnormals. */
        double d = fabs(w->pos[s][k] - start[k]) * (1 + 0x1p-49);
        if (moves)
            d += 2 * fabs(o->vel[k]);
        d += arc;
        d += 0x1p-50 * (fabs(base[k]) + fabs(base[k + 3]));
        g[k] = d * (1 + 0x1p-49) + 0x1p-1072;
    }
}

/* Give object s the growth its motion asks for; NOMEM (its box is then as
 * it was, and the tree owed). */
static noctStatus regrow(noctWorld *w, uint32_t s)
{
    noct_sweeps *sw = &w->sweeps;
    double g[3];
    wanted(w, s, g);
    if (memcmp(g, sw->grow[s], sizeof g) == 0)
        return NOCT_OK;
    double lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
        lo[k] = sw->base[s][k] - g[k];
        hi[k] = sw->base[s][k + 3] + g[k];
    }
    noctStatus st = noct_bp_move_to(&w->bp, s, lo, hi, w->pos[s]);
    if (st != NOCT_OK)
        return st;
    noct_object *o = &w->obj[s];
    memcpy(o->mlo, lo, sizeof lo);
    memcpy(o->mhi, hi, sizeof hi);
    memcpy(sw->grow[s], g, sizeof g);
    return NOCT_OK;
}

noctStatus noct_world_stage_grow(noctWorld *w)
{
    noct_sweeps *sw = &w->sweeps;
    noctStatus st = NOCT_OK;
    if ((w->def.effects & NOCT_EFFECT_MOTION) && w->motion.moving > 0)
        for (uint32_t m = 0; m < w->motion.nmovers && st == NOCT_OK; ++m)
            st = regrow(w, w->motion.movers[m]);
    /* The placed: grown for this step; those back where they started
     * leave todo, their growth shrunk. */
    uint32_t kept = 0;
    for (uint32_t i = 0; i < sw->ntodo; ++i) {
        const uint32_t s = sw->todo[i];
        if (st == NOCT_OK && w->obj[s].alive)
            st = regrow(w, s);
        if (w->obj[s].alive &&
            (st != NOCT_OK || memcmp(sw->start[s], w->pos[s], sizeof sw->start[s]) != 0 ||
             memcmp(sw->grow[s], (double[3]){0, 0, 0}, sizeof sw->grow[s]) != 0))
            sw->todo[kept++] = s;
        else
            sw->in_todo[s] = 0;
    }
    sw->ntodo = kept;
    return st;
}

/* Object s's step ends where it is: where it started is kept for the
 * hits (noctWorldBeganHits()). */
static void step_done(noctWorld *w, uint32_t s)
{
    noct_sweeps *sw = &w->sweeps;
    if (sw->from_tick[s] == w->tick)
        return; /* done already: a mover that was also placed (todo) */
    memcpy(sw->from[s], sw->start[s], sizeof sw->from[s]);
    sw->from_q[s] = sw->start_q[s];
    sw->from_tick[s] = w->tick;
    memcpy(sw->start[s], w->pos[s], sizeof sw->start[s]);
    sw->start_q[s] = w->pose[s].q;
}

void noct_world_sweeps_done(noctWorld *w)
{
    noct_sweeps *sw = &w->sweeps;
    for (uint32_t m = 0; m < w->motion.nmovers; ++m)
        step_done(w, w->motion.movers[m]);
    for (uint32_t i = 0; i < sw->ntodo; ++i)
        step_done(w, sw->todo[i]);
    sw->hits_made = false;
}

/* The continuous level on objects a and b moving from a0, qa and b0, qb:
 * exact if neither turned, conservative if one did. */
static noctStatus sweep(noctWorld *w, uint32_t a, const double a0[3], const noctQuat *qa,
                        uint32_t b, const double b0[3], const noctQuat *qb, bool *colliding,
                        noctSweepHit *hit)
{
    if (memcmp(qa, &w->pose[a].q, sizeof *qa) != 0 || memcmp(qb, &w->pose[b].q, sizeof *qb) != 0) {
        const noct_turning A = {noct_world_shape_of(w, a), w->pose[a].shape.half, *qa,
                                w->pose[a].q, a0, w->pos[a]};
        const noct_turning B = {noct_world_shape_of(w, b), w->pose[b].shape.half, *qb,
                                w->pose[b].q, b0, w->pos[b]};
        return noct_collide_turning(&A, &B, colliding, hit, &w->c.narrow);
    }
    noctStatus st = NOCT_OK;
    const noctMesh *ma = noct_world_mesh(w, a, &st);
    const noctMesh *mb = ma != NULL ? noct_world_mesh(w, b, &st) : NULL;
    if (ma == NULL || mb == NULL)
        return st;
    return noctCollideSwept(ma, a0, w->pos[a], mb, b0, w->pos[b], colliding, hit,
                            &w->c.narrow);
}

noctStatus noct_world_sweep_pair(noctWorld *w, uint32_t a, uint32_t b, bool *colliding)
{
    return sweep(w, a, noct_world_from(w, a), noct_world_from_q(w, a), b,
                 noct_world_from(w, b), noct_world_from_q(w, b), colliding, NULL);
}

noctStatus noctWorldBeganHits(noctWorld *w, const noctSweepHit **hits, size_t *n,
                              noctError *err)
{
    NOCT_REQUIRE(w != NULL && hits != NULL && n != NULL);
    noct_sweeps *sw = &w->sweeps;
    *hits = NULL;
    *n = 0;
    if (!sw->on)
        return NOCT_OK;
    const noct_pair_list *began = &w->events.contact.began;
    if (!sw->hits_made) {
        if (!grow_hits(&sw->hits, &sw->caphits, began->n))
            return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
        /* The last step is tick - 1; an object it did not move started
         * where it is. */
        for (size_t i = 0; i < began->n; ++i) {
            const uint32_t a = began->p[i].a.index, b = began->p[i].b.index;
            if (noct_world_lookup(w, began->p[i].a) == NULL ||
                noct_world_lookup(w, began->p[i].b) == NULL) {
                /* removed since the step: no motion to tell */
                noct_sweep_hit_none(&sw->hits[i]);
                continue;
            }
            const bool ca = noct_world_continuous(w, a), cb = noct_world_continuous(w, b);
            if (!ca && !cb) {
                /* a discrete pair: found where the step left it */
                noctSweepHit *h = &sw->hits[i];
                noct_sweep_hit_none(h);
                h->feature = NOCT_SWEEP_END;
                continue;
            }
            const bool ma = ca && sw->from_tick[a] + 1 == w->tick;
            const bool mb = cb && sw->from_tick[b] + 1 == w->tick;
            bool colliding;
            noctStatus st = sweep(w, a, ma ? sw->from[a] : w->pos[a],
                                  ma ? &sw->from_q[a] : &w->pose[a].q, b,
                                  mb ? sw->from[b] : w->pos[b],
                                  mb ? &sw->from_q[b] : &w->pose[b].q, &colliding, &sw->hits[i]);
            if (st != NOCT_OK)
                return noct_fail(err, st, -1, 0, "the began contacts' hits: %s",
                                 noctStatusString(st));
        }
        sw->hits_made = true;
    }
    *hits = sw->hits;
    *n = began->n;
    return NOCT_OK;
}
