/* SPDX-License-Identifier: MIT */
/*
 * Private: the one way the library grows an array (part of the foundation
 * floor with status.c, pool.c, clock.c and vec3.h, which every layer uses
 * and which use no layer). Never installed.
 *
 * An array is a pointer and a size_t capacity counted in elements. Growth
 * is fallible: on failure (no memory, or a size that does not fit in
 * size_t bytes) nothing changes and the caller reports NOCT_ERR_NOMEM.
 * Each file defines typed wrappers for its arrays with NOCT_DEFINE_GROW and
 * NOCT_DEFINE_RESIZE, so that no call passes an element size or casts a
 * pointer's address.
 */
#ifndef NOCT_LIB_ARRAY_H
#define NOCT_LIB_ARRAY_H

#include <stdbool.h>
#include <stddef.h>

#include "internal.h"

/*
 * The block p (of *cap elements of elem bytes) grown to at least need
 * elements: *cap (or 4) doubled until it holds need, or need itself
 * when doubling would overflow. Returns the new block and sets *cap, or returns NULL and
 * leaves p and *cap as they were. need > *cap.
 */
void *noct_grow_block(void *p, size_t *cap, size_t need, size_t elem);

/* noct_grow_block() for a block that may be the caller's local buffer
 * (then a new one is made and the *cap elements copied). */
void *noct_grow_local(void *p, const void *local, size_t *cap, size_t need, size_t elem);

/* The block p resized to exactly n > 0 elements of elem bytes, or NULL
 * (p unchanged) without memory or if n * elem overflows. For arrays that
 * share one capacity. */
void *noct_resize_block(void *p, size_t n, size_t elem);

/*
 * static inline bool NAME(T **p, size_t *cap, size_t need): room for need
 * elements in *p, growing as noct_grow_block does; false without memory.
 * The test of room is inlined: the pair search calls it for every pair.
 */
#define NOCT_DEFINE_GROW(name, T)                                            \
    static NOCT_ALWAYS_INLINE bool name(T **p, size_t *cap, size_t need)     \
    {                                                                        \
        if (need <= *cap)                                                    \
            return true;                                                     \
        void *q = noct_grow_block(*p, cap, need, sizeof(T));                 \
        if (q == NULL)                                                       \
            return false;                                                    \
        *p = (T *)q;                                                         \
        return true;                                                         \
    }

/*
 * static inline bool NAME(T **p, const T *local, size_t *cap, size_t need):
 * as NOCT_DEFINE_GROW for an array that starts in a buffer of its user's
 * (on the stack: local, of *cap elements) and moves to the heap when it
 * outgrows it, its elements copied; free *p only if it is not local.
 */
#define NOCT_DEFINE_GROW_LOCAL(name, T)                                      \
    static NOCT_ALWAYS_INLINE bool name(T **p, const T *local, size_t *cap,  \
                                        size_t need)                         \
    {                                                                        \
        if (need <= *cap)                                                    \
            return true;                                                     \
        void *q = noct_grow_local(*p, local, cap, need, sizeof(T));          \
        if (q == NULL)                                                       \
            return false;                                                    \
        *p = (T *)q;                                                         \
        return true;                                                         \
    }

/* static inline bool NAME(T **p, size_t n): *p resized to n > 0 elements;
 * false without memory, *p unchanged. */
#define NOCT_DEFINE_RESIZE(name, T)                                          \
    static inline bool name(T **p, size_t n)                                 \
    {                                                                        \
        void *q = noct_resize_block(*p, n, sizeof(T));                       \
        if (q == NULL)                                                       \
            return false;                                                    \
        *p = (T *)q;                                                         \
        return true;                                                         \
    }

#endif /* NOCT_LIB_ARRAY_H */
