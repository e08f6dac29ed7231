/* SPDX-License-Identifier: MIT */
/*
 * The pairs the program ignores (noctWorldIgnorePair()): a sorted array
 * of keys, searched by the narrowphase dispatch and the near pairs'
 * stage for each pair whose boxes meet, when it is not empty; and the
 * pairs touching now, found as a step would find them
 * (noctWorldIgnoreTouching()).
 */
#include "config.h"

#include <stdlib.h>
#include <string.h>

#include "world_internal.h"

NOCT_DEFINE_GROW(grow_keys, uint64_t)

static noctStatus stale_handle(noctObjectId id, noctError *err)
{
    return noct_fail(err, NOCT_ERR_INVALID, (long)id.index, 0,
                     "stale or unknown object handle (%u, %u)", id.index, id.generation);
}

/* Where key k is in the sorted keys, or would go. */
static size_t position(const noct_ignored *g, uint64_t k)
{
    size_t lo = 0, hi = g->n;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (g->key[mid] < k)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

noctStatus noctWorldIgnorePair(noctWorld *w, noctObjectId a, noctObjectId b, bool ignore,
                               noctError *err)
{
    NOCT_REQUIRE(w != NULL);
    if (noct_world_lookup(w, a) == NULL)
        return stale_handle(a, err);
    if (noct_world_lookup(w, b) == NULL)
        return stale_handle(b, err);
    if (a.index == b.index)
        return noct_fail(err, NOCT_ERR_INVALID, (long)a.index, 0,
                         "object %u cannot be paired with itself", a.index);
    noct_ignored *g = &w->ignored;
    const uint64_t k = noct_ignored_key(a.index, b.index);
    const size_t at = position(g, k);
    const bool there = at < g->n && g->key[at] == k;
    if (there == ignore)
        return NOCT_OK;
    if (ignore) {
        if (!grow_keys(&g->key, &g->cap, g->cap > 0 ? g->n + 1 : 16))
            return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
        memmove(&g->key[at + 1], &g->key[at], (g->n - at) * sizeof *g->key);
        g->key[at] = k;
        ++g->n;
    } else {
        memmove(&g->key[at], &g->key[at + 1], (g->n - at - 1) * sizeof *g->key);
        --g->n;
    }
    return NOCT_OK;
}

bool noctWorldPairIgnored(const noctWorld *w, noctObjectId a, noctObjectId b)
{
    NOCT_REQUIRE(w != NULL);
    if (noct_world_lookup(w, a) == NULL || noct_world_lookup(w, b) == NULL ||
        a.index == b.index || w->ignored.n == 0)
        return false;
    return noct_world_ignored(w, a.index, b.index);
}

void noct_world_forget_ignored(noctWorld *w, uint32_t s)
{
    noct_ignored *g = &w->ignored;
    size_t kept = 0;
    for (size_t i = 0; i < g->n; ++i)
        if ((uint32_t)(g->key[i] >> 32) != s && (uint32_t)g->key[i] != s)
            g->key[kept++] = g->key[i];
    g->n = kept;
}

/* ---- the pairs touching now ------------------------------------------------------- */

typedef struct candidates {
    uint32_t self;
    noct_pair_list *list;
    bool failed;
} candidates;

/* The partners of higher index whose boxes meet self's. */
static bool take(void *context, noctProxyId id, void *user)
{
    (void)user;
    candidates *c = context;
    if (id.index <= c->self)
        return true;
    if (!noct_pairs_push(c->list, (noctProxyPair){{c->self, 0}, {id.index, 0}})) {
        c->failed = true;
        return false;
    }
    return true;
}

static int key_order(const void *x, const void *y)
{
    const uint64_t a = *(const uint64_t *)x, b = *(const uint64_t *)y;
    return (a > b) - (a < b);
}

noctStatus noctWorldIgnoreTouching(noctWorld *w, size_t *count, noctError *err)
{
    NOCT_REQUIRE(w != NULL);
    if (count != NULL)
        *count = 0;
    noct_pair_list tested = {NULL, 0, 0}, colliding = {NULL, 0, 0};
    noctStatus st = NOCT_OK;
    /* The candidates: each live object's box queried for its partners of
     * higher index, through the filters (the query's own test), as the
     * pair search would pair them. */
    const uint32_t slots = noct_bp_slots(&w->bp);
    for (uint32_t i = 0; i < slots && st == NOCT_OK; ++i) {
        if (!w->obj[i].alive)
            continue;
        const noct_proxy *o = noct_bp_proxy(&w->bp, i);
        const noct_aabb *b = noct_bp_box(&w->bp, i);
        candidates c = {i, &tested, false};
        st = noctBroadphaseQueryBox(&w->bp, b->lo, b->hi,
                                    (noctQueryFilter){o->category, o->mask}, take, &c);
        if (st == NOCT_OK && c.failed)
            st = NOCT_ERR_NOMEM;
    }
    /* The step's narrowphase on them (sensors and ignored pairs as it
     * leaves them out); the counters are the steps' and stay as they were. */
    if (st == NOCT_OK) {
        const noctWorldCounters kept = w->c;
        st = noct_world_narrow(w, &tested, &colliding);
        w->c = kept;
    }
    free(tested.p);
    const size_t n = w->ignored.n + colliding.n;
    uint64_t *keys = NULL;
    if (st == NOCT_OK && colliding.n > 0) {
        keys = malloc(n * sizeof *keys);
        if (keys == NULL)
            st = NOCT_ERR_NOMEM;
    }
    if (st != NOCT_OK) {
        free(colliding.p);
        return noct_fail(err, st, -1, 0, "the pairs touching: %s", noctStatusString(st));
    }
    if (colliding.n == 0)
        return NOCT_OK;
    /* the old keys and the new ones, sorted, repeats dropped (none among
     * the new, which the dispatch left out if they were ignored) */
    if (w->ignored.n > 0)
        memcpy(keys, w->ignored.key, w->ignored.n * sizeof *keys);
    for (size_t i = 0; i < colliding.n; ++i)
        keys[w->ignored.n + i] = noct_ignored_key(colliding.p[i].a.index, colliding.p[i].b.index);
    qsort(keys, n, sizeof *keys, key_order);
    size_t kept = 0;
    for (size_t i = 0; i < n; ++i)
        if (kept == 0 || keys[kept - 1] != keys[i])
            keys[kept++] = keys[i];
    if (count != NULL)
        *count = kept - w->ignored.n;
    free(colliding.p);
    free(w->ignored.key);
    w->ignored.key = keys;
    w->ignored.n = kept;
    w->ignored.cap = n;
    return NOCT_OK;
}
