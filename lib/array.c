/* SPDX-License-Identifier: MIT */
/* The library's array growth (array.h). */
#include "config.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "array.h"

void *noct_resize_block(void *p, size_t n, size_t elem)
{
    NOCT_INVARIANT(n > 0 && elem > 0);
    if (n > SIZE_MAX / elem)
        return NULL;
    return realloc(p, n * elem);
}

void *noct_grow_block(void *p, size_t *cap, size_t need, size_t elem)
{
    NOCT_INVARIANT(need > *cap);
    size_t c = *cap > 0 ? *cap : 4;
    while (c < need)
        c = c <= SIZE_MAX / 2 ? 2 * c : need;
    void *q = noct_resize_block(p, c, elem);
    if (q != NULL)
        *cap = c;
    return q;
}

void *noct_grow_local(void *p, const void *local, size_t *cap, size_t need, size_t elem)
{
    if (p != local)
        return noct_grow_block(p, cap, need, elem);
    size_t c = *cap;
    void *q = noct_grow_block(NULL, &c, need, elem);
    if (q != NULL) {
        memcpy(q, local, *cap * elem);
        *cap = c;
    }
    return q;
}
