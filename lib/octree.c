/* SPDX-License-Identifier: MIT */
/*
 * The octree ADT (report section 2.1 and appendix).
 *
 * Storage: a root is one malloc'd node; the eight children of a node are
 * one calloc'd array, so a split is one allocation and a child is found by
 * indexing. Every walk over a subtree is iterative and uses the parent
 * links, so a degenerate tree thousands of levels deep cannot overflow the
 * stack.
 */
#include "config.h"

#include <limits.h>
#include <stdint.h>
#include <stdlib.h>

#include "internal.h"

octNode *octCreate(void)
{
    octNode *n = malloc(sizeof *n);
    if (n == NULL)
        return NULL;
    n->parent_ = NULL;
    n->children_ = NULL;
    n->data_ = NULL;
    n->generation_ = 0;
    n->childType_ = OCT_OMEGA;
    n->iter_ = NOCT_ITER_UNSET;
    n->reserved_ = 0;
    return n;
}

/*
 * Post-order walk that frees every descendant of top and hands their data to
 * kill. Leaves top itself a leaf with its datum untouched. Visiting order:
 * descend to the first child while there is one; a node without children is
 * finished, so dispose of its datum and move to its next sibling; after the
 * eighth sibling, free the block and finish the parent.
 */
static void destroy_descendants(octNode *top, octItemDisposer *kill)
{
    octNode *cur = top;
    for (;;) {
        if (cur->children_ != NULL) {
            cur = cur->children_;
            continue;
        }
        if (cur == top)
            return;
        if (cur->data_ != NULL && kill != NULL)
            kill(cur->data_);
        cur->data_ = NULL;
        if (cur->childType_ != OCT_RUF) {
            ++cur;
            continue;
        }
        octNode *parent = cur->parent_;
        free(parent->children_);
        parent->children_ = NULL;
        parent->iter_ = NOCT_ITER_UNSET;
        cur = parent;
    }
}

/*
 * Pre-order successor of cur within the subtree rooted at top, or NULL when
 * the walk is over. Used by the walks that keep the tree's shape.
 */
static octNode *next_preorder(const octNode *top, octNode *cur)
{
    if (cur->children_ != NULL)
        return cur->children_;
    while (cur != top && cur->childType_ == OCT_RUF)
        cur = cur->parent_;
    return cur == top ? NULL : cur + 1;
}

#ifndef NDEBUG
static bool subtree_has_data(const octNode *top)
{
    for (octNode *n = (octNode *)top; n != NULL; n = next_preorder(top, n))
        if (n->data_ != NULL)
            return true;
    return false;
}

static bool descendants_have_data(const octNode *N)
{
    for (unsigned i = 0; N->children_ != NULL && i < 8; ++i)
        if (subtree_has_data(&N->children_[i]))
            return true;
    return false;
}
#endif

void octDispose(octNode *N)
{
    NOCT_REQUIRE(N != NULL);
    NOCT_REQUIRE(N->parent_ == NULL);
    NOCT_REQUIRE(!subtree_has_data(N));
    destroy_descendants(N, NULL);
    free(N);
}

void octClear(octNode *N, octItemDisposer *kill)
{
    NOCT_REQUIRE(N != NULL);
    NOCT_REQUIRE(kill != NULL || !subtree_has_data(N));
    for (octNode *n = N; n != NULL; n = next_preorder(N, n)) {
        if (n->data_ != NULL) {
            void *d = n->data_;
            n->data_ = NULL;
            if (kill != NULL)
                kill(d);
        }
    }
}

octNode *octParent(const octNode *N)
{
    NOCT_REQUIRE(N != NULL);
    return N->parent_;
}

octNode *octChild(const octNode *N, octDirection O)
{
    NOCT_REQUIRE(N != NULL);
    NOCT_REQUIRE(OCT_IS_VERTEX(O));
    return N->children_ != NULL ? &N->children_[O - OCT_LDB] : NULL;
}

octDirection octChildType(const octNode *N)
{
    NOCT_REQUIRE(N != NULL);
    return (octDirection)N->childType_;
}

bool octIsSplit(const octNode *N)
{
    NOCT_REQUIRE(N != NULL);
    return N->children_ != NULL;
}

bool octSplit(octNode *N)
{
    NOCT_REQUIRE(N != NULL);
    NOCT_REQUIRE(N->children_ == NULL);
    if (N->generation_ == INT32_MAX)
        return false;
    octNode *kids = calloc(8, sizeof *kids);
    if (kids == NULL)
        return false;
    for (unsigned i = 0; i < 8; ++i) {
        kids[i].parent_ = N;
        kids[i].generation_ = N->generation_ + 1;
        kids[i].childType_ = (uint8_t)(OCT_LDB + i);
        kids[i].iter_ = NOCT_ITER_UNSET;
    }
    N->children_ = kids;
    N->iter_ = NOCT_ITER_UNSET;
    return true;
}

/* The library's own split and join, with the children's storage the
 * caller's (the broadphase's pool of blocks): no allocation, no free. */
void noct_oct_split_into(octNode *N, octNode kids[8])
{
    NOCT_INVARIANT(N->children_ == NULL && N->generation_ < INT32_MAX);
    for (unsigned i = 0; i < 8; ++i) {
        kids[i].parent_ = N;
        kids[i].children_ = NULL;
        kids[i].data_ = NULL;
        kids[i].generation_ = N->generation_ + 1;
        kids[i].childType_ = (uint8_t)(OCT_LDB + i);
        kids[i].iter_ = NOCT_ITER_UNSET;
        kids[i].reserved_ = 0;
    }
    N->children_ = kids;
    N->iter_ = NOCT_ITER_UNSET;
}

octNode *noct_oct_unsplit(octNode *N)
{
    octNode *kids = N->children_;
    NOCT_INVARIANT(kids != NULL);
    for (unsigned i = 0; i < 8; ++i)
        NOCT_INVARIANT(kids[i].children_ == NULL);
    N->children_ = NULL;
    N->iter_ = NOCT_ITER_UNSET;
    return kids;
}

void octJoin(octNode *N, octItemDisposer *kill)
{
    NOCT_REQUIRE(N != NULL);
    NOCT_REQUIRE(N->children_ != NULL);
    /* Checked before anything is freed, so a violation aborts with the tree
     * intact for the debugger. */
    NOCT_REQUIRE(kill != NULL || !descendants_have_data(N));
    destroy_descendants(N, kill);
}

int octGeneration(const octNode *N)
{
    NOCT_REQUIRE(N != NULL);
    return N->generation_;
}

void *octData(const octNode *N)
{
    NOCT_REQUIRE(N != NULL);
    return N->data_;
}

void *octSwapData(octNode *N, void *newData)
{
    NOCT_REQUIRE(N != NULL);
    void *old = N->data_;
    N->data_ = newData;
    return old;
}

void octInitChildIterator(octNode *N1)
{
    NOCT_REQUIRE(N1 != NULL);
    NOCT_REQUIRE(N1->children_ != NULL);
    N1->iter_ = 0;
}

bool octNextChild(octNode *N1, octNode **N2)
{
    NOCT_REQUIRE(N1 != NULL && N2 != NULL);
    NOCT_REQUIRE(N1->iter_ != NOCT_ITER_UNSET);
    if (N1->iter_ >= 8 || N1->children_ == NULL)
        return false;
    *N2 = &N1->children_[N1->iter_++];
    return true;
}

bool octPrint(octNode *N, octItemPrinter *prnt, FILE *strm)
{
    NOCT_REQUIRE(N != NULL);
    NOCT_REQUIRE(strm != NULL);
    bool ok = true;
    for (octNode *n = N; n != NULL; n = next_preorder(N, n)) {
        int indent = 2 * (n->generation_ - N->generation_);
        if (fprintf(strm, "%*s%s %d", indent, "",
                    octDirToStr((octDirection)n->childType_),
                    (int)n->generation_) < 0)
            ok = false;
        if (n->data_ != NULL && prnt != NULL) {
            if (fputs(": ", strm) == EOF)
                ok = false;
            prnt(strm, n->data_);
        }
        if (putc('\n', strm) == EOF)
            ok = false;
    }
    return ok && !ferror(strm);
}
