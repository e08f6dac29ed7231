/* SPDX-License-Identifier: MIT */
/*
 * The world's events and response: the event records (rotated, diffed,
 * held and restored), the pairs that began and ended, from the sorted
 * lists of this step and the one before, and the report's response to
 * them (a pair that begins colliding turns both objects back). They read
 * pair lists and velocities, nothing of the tree or the narrowphase.
 */
#include "config.h"

#include <stdlib.h>
#include <string.h>

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

void noct_record_rotate(noct_event_record *r)
{
    const noct_pair_list t = r->before;
    r->before = r->now;
    r->now = t;
    r->now.n = 0;
}

void noct_record_unrotate(noct_event_record *r)
{
    const noct_pair_list t = r->now;
    r->now = r->before;
    r->before = t;
}

noctStatus noct_record_diff(noct_event_record *r, uint64_t *events)
{
    if (r->now.n == 0 && r->before.n == 0)
        return NOCT_OK;
    const size_t began = r->began.n, ended = r->ended.n;
    noctStatus st = noct_world_diff_lists(&r->now, &r->before, &r->began, &r->ended);
    if (st == NOCT_OK && events != NULL)
        *events += r->began.n - began + r->ended.n - ended;
    return st;
}

NOCT_DEFINE_RESIZE(resize_pairs, noctPair)

bool noct_record_hold(noct_event_record *r)
{
    noct_pair_list *h = &r->held;
    if (h->cap < r->now.n) {
        if (!resize_pairs(&h->p, r->now.n))
            return false;
        h->cap = r->now.n;
    }
    if (r->now.n > 0)
        memcpy(h->p, r->now.p, r->now.n * sizeof *h->p);
    h->n = r->now.n;
    return true;
}

void noct_record_clear(noct_event_record *r)
{
    r->began.n = r->ended.n = 0;
}

void noct_record_fail(noct_event_record *r, bool held)
{
    if (held) {
        const noct_pair_list t = r->now;
        r->now = r->held;
        r->held = t;
    }
    noct_record_clear(r);
}

void noct_record_free(noct_event_record *r)
{
    free(r->now.p);
    free(r->before.p);
    free(r->began.p);
    free(r->ended.p);
    free(r->held.p);
}

noctStatus noct_world_split_sensors(noct_events *e, const noct_object *obj)
{
    noct_pair_list *c = &e->contact.now;
    size_t k = 0;
    for (size_t i = 0; i < c->n; ++i) {
        const noctPair q = c->p[i];
        if (obj[q.a.index].sensor || obj[q.b.index].sensor) {
            if (!noct_pairs_push(&e->sensor.now, q))
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
    uint32_t *mark = noct_bp_marks(bp);
    const noct_pair_list *began = &e->contact.began;
    for (size_t i = from; i < began->n; ++i) {
        const uint32_t ids[2] = {began->p[i].a.index, began->p[i].b.index};
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
