/* SPDX-License-Identifier: MIT */
/**
 * @file noctree/octree_inline.h
 * @brief Private: the octNode layout and the efficient build's inline
 * accessors. Do not include this header directly; include
 * <noctree/octree.h>.
 *
 * The layout is shared by both libraries and by every client of the
 * efficient flavour, so it is part of the ABI: changing it requires a new
 * SONAME (see the libtool version rules in configure.ac). Clients must not
 * touch the fields.
 */
#ifndef NOCTREE_OCTREE_INLINE_H
#define NOCTREE_OCTREE_INLINE_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/** @cond NOCT_PRIVATE */

/* Value of iter_ while no child iteration has been started. */
#define NOCT_ITER_UNSET 0xffu

/* 32 bytes on LP64. The eight children of a node live in one array
 * (children_), in vertex order, so a child's index in it is
 * childType_ - OCT_LDB. */
struct octNode {
    struct octNode *parent_;   /* NULL for a root */
    struct octNode *children_; /* array of 8, or NULL for a leaf */
    void *data_;               /* client datum */
    int32_t generation_;       /* depth below the root */
    uint8_t childType_;        /* vertex direction, OCT_OMEGA for a root */
    uint8_t iter_;             /* next child to visit, or NOCT_ITER_UNSET */
    uint16_t reserved_;        /* zero */
};

#if NOCT_INLINE_ACCESSORS
static inline octNode *octParent(const octNode *N)
{
    return N->parent_;
}

static inline octNode *octChild(const octNode *N, octDirection O)
{
    return N->children_ ? &N->children_[O - OCT_LDB] : (octNode *)0;
}

static inline octDirection octChildType(const octNode *N)
{
    return (octDirection)N->childType_;
}

static inline bool octIsSplit(const octNode *N)
{
    return N->children_ != 0;
}

static inline int octGeneration(const octNode *N)
{
    return N->generation_;
}

static inline void *octData(const octNode *N)
{
    return N->data_;
}

static inline void *octSwapData(octNode *N, void *newData)
{
    void *old = N->data_;
    N->data_ = newData;
    return old;
}
#endif

/** @endcond */

#ifdef __cplusplus
}
#endif

#endif /* NOCTREE_OCTREE_INLINE_H */
