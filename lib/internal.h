/* SPDX-License-Identifier: MIT */
/*
 * Private to the library: never installed.
 *
 * Included by every library source instead of the public headers directly,
 * so that the accessors are always declared as exported functions (both
 * libraries export the same symbols) and the node layout is visible.
 */
#ifndef NOCT_LIB_INTERNAL_H
#define NOCT_LIB_INTERNAL_H

#ifndef NOCT_BUILDING
#  error "lib/internal.h is for the library's own sources"
#endif

#include <assert.h>

#include <noctree/octree.h>
#include <noctree/octree_inline.h>

/* A requires clause of the API contract: checked in the defensive build,
 * compiled out (NDEBUG) in the efficient one. */
#define NOCT_REQUIRE(cond) assert(cond)

#endif /* NOCT_LIB_INTERNAL_H */
