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

noctStatus noct_world_diff_events(noct_events *e, uint64_t *events)
{
    size_t i = 0, j = 0;
    const noct_pair_list *now = &e->colliding, *before = &e->previous;
    const size_t began = e->began.n, ended = e->ended.n;
    while (i < now->n || j < before->n) {
        int c = i == now->n      ? 1
                : j == before->n ? -1
                                 : noct_pair_order(&now->p[i], &before->p[j]);
        if (c == 0 && now->p[i].a.generation == before->p[j].a.generation &&
            now->p[i].b.generation == before->p[j].b.generation) {
            ++i;
            ++j;
        } else if (c <= 0) {
            if (!noct_pairs_push(&e->began, now->p[i++]))
                return NOCT_ERR_NOMEM;
        } else if (!noct_pairs_push(&e->ended, before->p[j++])) {
            return NOCT_ERR_NOMEM;
        }
    }
    *events += e->began.n - began + e->ended.n - ended;
    return NOCT_OK;
}

void noct_world_respond(noct_events *e, noct_object *obj, size_t from, uint64_t *reversals)
{
    ++e->epoch;
    for (size_t i = from; i < e->began.n; ++i) {
        const uint32_t ids[2] = {e->began.p[i].a.index, e->began.p[i].b.index};
        for (int s = 0; s < 2; ++s) {
            if (e->mark[ids[s]] == e->epoch)
                continue;
            e->mark[ids[s]] = e->epoch;
            for (int k = 0; k < 3; ++k)
                obj[ids[s]].vel[k] = -obj[ids[s]].vel[k];
            ++*reversals;
        }
    }
}
