/* SPDX-License-Identifier: MIT */
/*
 * Private: arrays pooled by size class (foundation floor; pool.c). The
 * broadphase keeps its leaves' lists in them so that a step allocates
 * nothing once sizes settle. Never installed.
 */
#ifndef NOCT_LIB_POOL_H
#define NOCT_LIB_POOL_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "internal.h"

/*
 * Arrays pooled by size class: class k holds base << k elements of elem
 * bytes. A list that must grow takes an array of a larger class and gives
 * its own back; a leaf that splits or goes back to the pool gives its
 * lists back. So the arrays of each class in use never outnumber the most
 * ever in use at once, and once that settles nothing is allocated. A
 * class's free stack has room for every array of the class ever made, so
 * giving one back cannot fail.
 */
#define NOCT_APOOL_CLASSES 28
typedef struct noct_apool {
    size_t elem;
    uint32_t base;
    struct {
        void **free;
        size_t n, cap, made;
    } cls[NOCT_APOOL_CLASSES];
    void **slabs;          /* the arrays are made several to a slab */
    size_t nslabs, capslabs;
} noct_apool;

/* An array of at least need elements, its capacity into *cap; NULL
 * without memory (or beyond the largest class). */
void *noct_apool_take(noct_apool *p, uint32_t need, uint32_t *cap);

/* A free array of capacity cap (a class's), or NULL if none is free: it
 * never allocates. For lists that shrink, so that the arrays in use
 * follow the lists' sizes now rather than the largest they ever were. */
void *noct_apool_take_free(noct_apool *p, uint32_t cap);

/* Give back array a of capacity cap (from noct_apool_take; NULL and 0
 * for none); cannot fail. */
void noct_apool_give(noct_apool *p, void *a, uint32_t cap);

/* Free every array given back. */
void noct_apool_free(noct_apool *p);

/* Room for n + 1 elements in the list *a of capacity *cap with n in use:
 * an array of a larger class from the pool, the n copied, the old one
 * given back; false without memory (nothing changed). */
static NOCT_ALWAYS_INLINE bool noct_apool_grow(noct_apool *p, void **a, uint32_t *cap,
                                               uint32_t n)
{
    uint32_t c;
    void *q = noct_apool_take(p, n + 1, &c);
    if (q == NULL)
        return false;
    if (n > 0)
        memcpy(q, *a, n * p->elem);
    noct_apool_give(p, *a, *cap);
    *a = q;
    *cap = c;
    return true;
}

/* A list of n elements in *a (capacity *cap) that has a quarter of its
 * room or less in use moves to a free array of half the capacity, if the
 * pool has one (elem bytes each, first n copied). */
static inline void noct_apool_shrink(noct_apool *p, void **a, uint32_t *cap, uint32_t n)
{
    if (*cap <= p->base || n > *cap / 4)
        return;
    void *q = noct_apool_take_free(p, *cap / 2);
    if (q == NULL)
        return;
    if (n > 0)
        memcpy(q, *a, n * p->elem);
    noct_apool_give(p, *a, *cap);
    *a = q;
    *cap /= 2;
}

#endif /* NOCT_LIB_POOL_H */
