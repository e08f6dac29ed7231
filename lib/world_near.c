/* SPDX-License-Identifier: MIT */
/*
 * The margin (noctWorldDef::margin): after a step's pairs, the pairs of
 * objects within the margin of each other ("near": the arm is about to
 * collide), and the pairs that became near or stopped being near. Each
 * object looks for its partners of higher index in the broadphase, its
 * box grown by the margin; a pair that collides is near, else the
 * distance of their triangles decides (noct_solids_within()). A world
 * without a margin never comes here.
 */
#include "config.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "world_internal.h"

typedef struct partners {
    uint32_t self;
    uint32_t *s;
    size_t n, cap;
    bool failed;
} partners;

NOCT_DEFINE_GROW(grow_u32, uint32_t)

static bool take(void *context, noctProxyId id, void *user)
{
    (void)user;
    partners *p = context;
    if (id.index <= p->self)
        return true;
    if (!grow_u32(&p->s, &p->cap, p->cap > 0 ? p->n + 1 : 16)) {
        p->failed = true;
        return false;
    }
    p->s[p->n++] = id.index;
    return true;
}

static int by_index(const void *a, const void *b)
{
    const uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return (x > y) - (x < y);
}

/* Is (a, b), a < b, in the sorted list? */
static bool listed(const noct_pair_list *l, uint32_t a, uint32_t b)
{
    size_t lo = 0, hi = l->n;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        const noctPair *p = &l->p[mid];
        if (p->a.index < a || (p->a.index == a && p->b.index < b))
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < l->n && l->p[lo].a.index == a && l->p[lo].b.index == b;
}

/* Are objects i and j near, at the world's level? */
static bool near(const noctWorld *w, uint32_t i, uint32_t j, double d)
{
    if (listed(&w->events.contact.now, i, j))
        return true;
    if (w->def.accuracy == NOCT_ACCURACY_BOX) {
        const noct_aabb *a = noct_bp_box(&w->bp, i), *b = noct_bp_box(&w->bp, j);
        double s = 0, scale = d;
        for (int k = 0; k < 3; ++k) {
            const double g = noct_max(noct_max(b->lo[k] - a->hi[k], a->lo[k] - b->hi[k]), 0);
            s += g * g;
            scale = noct_max(scale, noct_max(noct_max(fabs(a->lo[k]), fabs(a->hi[k])),
                                             noct_max(fabs(b->lo[k]), fabs(b->hi[k]))));
        }
        const double reach = d + 0x1p-40 * scale;
        return s <= reach * reach;
    }
    /* two boxes that a separating axis proves farther apart: the common
     * case, a few dozen operations */
    if (w->slot[i].has_box && w->slot[j].has_box &&
        noct_box_apart_by(&w->slot[i], w->pos[i], &w->slot[j], w->pos[j], d))
        return false;
    noct_shape_view va, vb;
    const noctMesh *ma = noct_world_shape(w, i, &va), *mb = noct_world_shape(w, j, &vb);
    return noct_solids_within(ma, w->pos[i], mb, w->pos[j], d);
}

noctStatus noct_world_stage_near(noctWorld *w, noctError *err)
{
    noct_event_record *e = &w->events.near;
    const double d = w->def.margin;
    noct_record_rotate(e);
    partners p = {0, NULL, 0, 0, false};
    noctStatus st = NOCT_OK;
    for (uint32_t i = 0; i < noct_bp_slots(&w->bp) && st == NOCT_OK; ++i) {
        if (!w->obj[i].alive || w->obj[i].sensor)
            continue;
        const noct_proxy *o = noct_bp_proxy(&w->bp, i);
        const noct_aabb *b = noct_bp_box(&w->bp, i);
        double lo[3], hi[3], scale = d;
        for (int k = 0; k < 3; ++k)
            scale = noct_max(scale, noct_max(fabs(b->lo[k]), fabs(b->hi[k])));
        /* grown by the margin and more than its rounding */
        const double grow = d + 0x1p-38 * scale;
        for (int k = 0; k < 3; ++k) {
            lo[k] = b->lo[k] - grow;
            hi[k] = b->hi[k] + grow;
        }
        p.self = i;
        p.n = 0;
        st = noctBroadphaseQueryBox(&w->bp, lo, hi,
                                    (noctQueryFilter){o->category, o->mask}, take, &p);
        if (st == NOCT_OK && p.failed)
            st = NOCT_ERR_NOMEM;
        if (st != NOCT_OK)
            break;
        if (p.n > 1)
            qsort(p.s, p.n, sizeof *p.s, by_index);
        for (size_t k = 0; k < p.n; ++k) {
            const uint32_t j = p.s[k];
            if (w->obj[j].sensor || !near(w, i, j, d))
                continue;
            const noctPair pair = {{i, noct_bp_generation(&w->bp, i)}, {j, noct_bp_generation(&w->bp, j)}};
            if (!noct_pairs_push(&e->now, pair)) {
                st = NOCT_ERR_NOMEM;
                break;
            }
        }
    }
    free(p.s);
    /* near events are not among the counters' events */
    if (st == NOCT_OK && (w->def.effects & NOCT_EFFECT_EVENTS))
        st = noct_record_diff(e, NULL);
    if (st != NOCT_OK) {
        noct_record_unrotate(e); /* the failed step clears the events */
        return noct_fail(err, st, -1, 0, "near pairs: %s", noctStatusString(st));
    }
    return NOCT_OK;
}

size_t noctWorldNear(const noctWorld *w, const noctPair **pairs)
{
    NOCT_REQUIRE(w != NULL && pairs != NULL);
    return noct_list_out(&w->events.near.now, pairs);
}

size_t noctWorldNearBegan(const noctWorld *w, const noctPair **pairs)
{
    NOCT_REQUIRE(w != NULL && pairs != NULL);
    return noct_list_out(&w->events.near.began, pairs);
}

size_t noctWorldNearEnded(const noctWorld *w, const noctPair **pairs)
{
    NOCT_REQUIRE(w != NULL && pairs != NULL);
    return noct_list_out(&w->events.near.ended, pairs);
}
