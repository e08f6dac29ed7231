/* SPDX-License-Identifier: MIT */
/* Arrays pooled by size class (pool.h). */
#include "config.h"

#include <stdlib.h>

#include "array.h"
#include "pool.h"

NOCT_DEFINE_GROW(grow_slabs, void *)

void *noct_apool_take(noct_apool *p, uint32_t need, uint32_t *cap)
{
    unsigned k = 0;
    while (k < NOCT_APOOL_CLASSES && (uint64_t)p->base << k < need)
        ++k;
    if (k == NOCT_APOOL_CLASSES)
        return NULL;
    *cap = p->base << k;
    if (p->cls[k].n > 0)
        return p->cls[k].free[--p->cls[k].n];
    /* None free: make a sixteenth as many again as there are (at least
     * two), in one slab, so that a little more demand than ever before
     * does not allocate at once, and arrays carry no allocator header. */
    const size_t more = p->cls[k].made / 16 > 2 ? p->cls[k].made / 16 : 2;
    if (!grow_slabs(&p->cls[k].free, &p->cls[k].cap, p->cls[k].made + more) ||
        !grow_slabs(&p->slabs, &p->capslabs, p->nslabs + 1))
        return NULL;
    const size_t bytes = (size_t)*cap * p->elem;
    char *slab = malloc(more * bytes);
    if (slab == NULL)
        return NULL;
    p->slabs[p->nslabs++] = slab;
    for (size_t i = 0; i < more; ++i)
        p->cls[k].free[p->cls[k].n++] = slab + i * bytes;
    p->cls[k].made += more;
    return p->cls[k].free[--p->cls[k].n];
}

void *noct_apool_take_free(noct_apool *p, uint32_t cap)
{
    unsigned k = 0;
    while (k < NOCT_APOOL_CLASSES && p->base << k != cap)
        ++k;
    return k < NOCT_APOOL_CLASSES && p->cls[k].n > 0 ? p->cls[k].free[--p->cls[k].n] : NULL;
}

void noct_apool_give(noct_apool *p, void *a, uint32_t cap)
{
    if (a == NULL)
        return;
    unsigned k = 0;
    while (p->base << k != cap)
        ++k;
    NOCT_INVARIANT(k < NOCT_APOOL_CLASSES && p->cls[k].n < p->cls[k].made);
    p->cls[k].free[p->cls[k].n++] = a;
}

void noct_apool_free(noct_apool *p)
{
    for (size_t i = 0; i < p->nslabs; ++i)
        free(p->slabs[i]);
    free(p->slabs);
    p->slabs = NULL;
    p->nslabs = p->capslabs = 0;
    for (unsigned k = 0; k < NOCT_APOOL_CLASSES; ++k) {
        free(p->cls[k].free);
        p->cls[k].free = NULL;
        p->cls[k].n = p->cls[k].cap = p->cls[k].made = 0;
    }
}
