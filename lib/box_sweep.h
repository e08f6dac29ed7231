/* SPDX-License-Identifier: MIT */
/*
 * What a sweep over boxes needs, for any record holding `double lo[3],
 * hi[3]`: NOCT_DEFINE_BOX_SWEEP(prefix, T, I) defines, static to the file,
 *
 *   void prefix_sort(T *g, I n, int k, T *tmp)
 *       g[0, n) sorted by lower corner on axis k: an insertion sort for
 *       the few dozen boxes of most leaves (nearly sorted already, as a
 *       leaf keeps them), a bottom-up merge of runs into tmp (n records)
 *       and back for more than 64;
 *   int prefix_axis(const T *g, I n)
 *       the axis along which the boxes' lower corners spread farthest for
 *       the boxes' total extent, so that the fewest pairs overlap on it
 *       (cubes in a plane share their x; a gas spreads on every axis).
 *
 * The pair search (broadphase_pairs.c) sweeps with both; the margin's
 * candidates (world_near.c) choose their axis so (NOCT_DEFINE_BOX_AXIS
 * alone) but sort keys rather than their records. I is the index type of
 * each.
 */
#ifndef NOCT_LIB_BOX_SWEEP_H
#define NOCT_LIB_BOX_SWEEP_H

#include <string.h>

#include "internal.h"

#define NOCT_DEFINE_BOX_SWEEP(prefix, T, I)                                              \
    NOCT_DEFINE_BOX_SORT(prefix, T, I)                                                   \
    NOCT_DEFINE_BOX_AXIS(prefix, T, I)

/* Each half alone (NOCT_DEFINE_BOX_SORT: prefix_sort; NOCT_DEFINE_BOX_AXIS:
 * prefix_axis), for a sweep that sorts otherwise. */
#define NOCT_DEFINE_BOX_SORT(prefix, T, I)                                               \
    static void prefix##_sort(T *g, I n, int k, T *tmp)                                  \
    {                                                                                    \
        if (n > 64) {                                                                    \
            T *src = g, *dst = tmp;                                                      \
            for (I width = 1; width < n; width *= 2) {                                   \
                for (I lo = 0; lo < n; lo += 2 * width) {                                \
                    const I mid = lo + width < n ? lo + width : n;                       \
                    const I hi = lo + 2 * width < n ? lo + 2 * width : n;                \
                    I i = lo, j = mid, o = lo;                                           \
                    while (i < mid && j < hi)                                            \
                        dst[o++] = src[j].lo[k] < src[i].lo[k] ? src[j++] : src[i++];    \
                    while (i < mid)                                                      \
                        dst[o++] = src[i++];                                             \
                    while (j < hi)                                                       \
                        dst[o++] = src[j++];                                             \
                }                                                                        \
                T *t = src;                                                              \
                src = dst;                                                               \
                dst = t;                                                                 \
            }                                                                            \
            if (src != g)                                                                \
                memcpy(g, src, n * sizeof *g);                                           \
            return;                                                                      \
        }                                                                                \
        for (I i = 1; i < n; ++i) {                                                      \
            const T t = g[i];                                                            \
            I j = i;                                                                     \
            for (; j > 0 && g[j - 1].lo[k] > t.lo[k]; --j)                               \
                g[j] = g[j - 1];                                                         \
            g[j] = t;                                                                    \
        }                                                                                \
    }

#define NOCT_DEFINE_BOX_AXIS(prefix, T, I)                                               \
    static int prefix##_axis(const T *g, I n)                                            \
    {                                                                                    \
        double lo[3], hi[3], ext[3] = {0, 0, 0};                                         \
        for (int k = 0; k < 3; ++k)                                                      \
            lo[k] = hi[k] = g[0].lo[k];                                                  \
        for (I i = 0; i < n; ++i)                                                        \
            for (int k = 0; k < 3; ++k) {                                                \
                lo[k] = noct_min(lo[k], g[i].lo[k]);                                     \
                hi[k] = noct_max(hi[k], g[i].lo[k]);                                     \
                ext[k] += g[i].hi[k] - g[i].lo[k];                                       \
            }                                                                            \
        int best = 0;                                                                    \
        double best_ratio = -1;                                                          \
        for (int k = 0; k < 3; ++k) {                                                    \
            const double r = (hi[k] - lo[k]) / (ext[k] > 0 ? ext[k] : 1);                \
            if (r > best_ratio) {                                                        \
                best_ratio = r;                                                          \
                best = k;                                                                \
            }                                                                            \
        }                                                                                \
        return best;                                                                     \
    }

#endif
