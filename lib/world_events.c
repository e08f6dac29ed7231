/* SPDX-License-Identifier: MIT */
/*
 * The world's events and response: the pairs that began and ended
 * colliding, from the sorted colliding lists of this step and the one
 * before, and the report's response to them (SCENES.md's contact-begin
 * rule). They read pair lists and velocities, nothing of the tree or the
 * narrowphase.
 */
#include "config.h"

#include "world_internal.h"

/* began += now - before, ended += before - now, both sorted. */
noctStatus noct_world_diff_lists(const noct_pair_list *now, const noct_pair_list *before,
                                 noct_pair_list *began, noct_pair_list *ended)
{
    size_t i = 0, j = 0;
    while (i < now->n || j < before->n) {
        int c = i == now->n      ? 1
                : j == before->n ? -1
                                 : noct_pair_order(&now->p[i], &before->p[j]);
        if (c == 0 && now->p[i].a.generation == before->p[j].a.generation &&
            now->p[i].b.generation == before->p[j].b.generation) {
            ++i;
            ++j;
        } else if (c <= 0) {
            if (!noct_pairs_push(began, now->p[i++]))
                return NOCT_ERR_NOMEM;
        } else if (!noct_pairs_push(ended, before->p[j++])) {
            return NOCT_ERR_NOMEM;
        }
    }
    return NOCT_OK;
}

noctStatus noct_world_diff_events(noct_events *e, uint64_t *events)
{
    const size_t began = e->began.n, ended = e->ended.n;
    const size_t sbegan = e->sensor_began.n, sended = e->sensor_ended.n;
    noctStatus st = noct_world_diff_lists(&e->colliding, &e->previous, &e->began, &e->ended);
    if (st == NOCT_OK && (e->sensing.n > 0 || e->sensing_prev.n > 0))
        st = noct_world_diff_lists(&e->sensing, &e->sensing_prev, &e->sensor_began, &e->sensor_ended);
    if (st == NOCT_OK)
        *events += e->began.n - began + e->ended.n - ended + e->sensor_began.n - sbegan +
                   e->sensor_ended.n - sended;
    return st;
}

noctStatus noct_world_split_sensors(noct_events *e, const noct_object *obj)
{
    noct_pair_list *c = &e->colliding;
    size_t k = 0;
    for (size_t i = 0; i < c->n; ++i) {
        const noctPair q = c->p[i];
        if (obj[q.a.index].sensor || obj[q.b.index].sensor) {
            if (!noct_pairs_push(&e->sensing, q))
                return NOCT_ERR_NOMEM;
        } else {
            c->p[k++] = q;
        }
    }
    c->n = k;
    return NOCT_OK;
}

void noct_world_respond(noct_events *e, noct_object *obj, noctBroadphase *bp, size_t from,
                        uint64_t *reversals)
{
    const uint32_t now = noct_bp_new_epoch(bp);
    uint32_t *mark = bp->mark;
    for (size_t i = from; i < e->began.n; ++i) {
        const uint32_t ids[2] = {e->began.p[i].a.index, e->began.p[i].b.index};
        for (int s = 0; s < 2; ++s) {
            if (mark[ids[s]] == now)
                continue;
            mark[ids[s]] = now;
            if (obj[ids[s]].speed > 0) /* (not moving: nothing to turn, not even 0's sign) */
                for (int k = 0; k < 3; ++k)
                    obj[ids[s]].vel[k] = -obj[ids[s]].vel[k];
            ++*reversals;
        }
    }
}
