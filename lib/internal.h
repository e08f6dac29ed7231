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
#include <math.h>
#include <stdbool.h>

#include <noctree/octree.h>
#include <noctree/octree_inline.h>
#include <noctree/status.h>

/* A requires clause of the API contract: checked in the defensive build,
 * compiled out (NDEBUG) in the efficient one. */
#define NOCT_REQUIRE(cond) assert(cond)

/* An invariant the code relies on (a count that cannot go negative, an
 * object found where it is removed from): checked in the defensive build
 * like a requires clause, compiled out in the efficient one. A failure is
 * a bug in the library, never bad input. */
#define NOCT_INVARIANT(cond) assert(cond)

/*
 * The accessors as the library's own clients (world.c) call them: through
 * the checked, exported functions in the defensive build, and straight to
 * the fields in the efficient one, as an efficient client's inline
 * accessors do (a call through the PLT per node otherwise).
 */
#ifdef NDEBUG
#  define NOCT_NODE_DATA(n) ((n)->data_)
#  define NOCT_NODE_IS_SPLIT(n) ((n)->children_ != NULL)
#  define NOCT_NODE_CHILD(n, o) (&(n)->children_[(o) - OCT_LDB])
#  define NOCT_NODE_PARENT(n) ((n)->parent_)
#else
#  define NOCT_NODE_DATA(n) octData(n)
#  define NOCT_NODE_IS_SPLIT(n) octIsSplit(n)
#  define NOCT_NODE_CHILD(n, o) octChild((n), (o))
#  define NOCT_NODE_PARENT(n) octParent(n)
#endif

/* Split N with the eight children's storage given (zeroed or not), and
 * join N's eight leaf children, returning their storage: the octree ADT's
 * split and join without allocation, for the broadphase's pool. */
void noct_oct_split_into(octNode *N, octNode kids[8]);
octNode *noct_oct_unsplit(octNode *N);

/* The direction whose axes are those of (x, y, z) that are not zero, on
 * the side of their signs; OCT_OMEGA for (0, 0, 0). */
octDirection noct_direction_of(int x, int y, int z);

/* Fill err (if not NULL) with status, the index and line (or -1 and 0)
 * and the formatted message, and return status (status.c): the one way a
 * layer reports a failure. */
noctStatus noct_fail(noctError *err, noctStatus status, long index, long line,
                     const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 5, 6)))
#endif
    ;

/* Seconds on the monotonic clock (clock.c), for the counters' timings. */
double noct_seconds(void);

/* min and max of finite doubles (the library validates coordinates before
 * they get here). Unlike fmin and fmax these compile to one instruction
 * instead of a libm call on the hot paths. */
static inline double noct_min(double a, double b) { return b < a ? b : a; }
static inline double noct_max(double a, double b) { return b > a ? b : a; }

/* The unit vector along finite d, into u; false if d is zero. A d within
 * 1e-9 of unit length is used as given (so speed * d is the velocity bit
 * for bit, as the benchmark scenes specify); others are scaled by their
 * largest component first, so that no length overflows or underflows. */
static inline bool noct_unit_direction(const double d[3], double u[3])
{
    double m = 0;
    for (int k = 0; k < 3; ++k)
        m = noct_max(m, d[k] < 0 ? -d[k] : d[k]);
    if (!(m > 0))
        return false;
    double s[3] = {d[0] / m, d[1] / m, d[2] / m};
    double len = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    double len0 = m * len; /* d's own length, if it is near 1 */
    for (int k = 0; k < 3; ++k)
        u[k] = len0 >= 1 - 1e-9 && len0 <= 1 + 1e-9 ? d[k] : s[k] / len;
    return true;
}

/* Small functions on the hot paths that the compiler should not leave
 * out of line however often they are called. */
#if defined(__GNUC__)
#  define NOCT_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#  define NOCT_ALWAYS_INLINE inline
#endif

/* Ask the cache for the line at p ahead of its use; nothing elsewhere. */
#if defined(__GNUC__)
#  define NOCT_PREFETCH(p) __builtin_prefetch(p)
#else
#  define NOCT_PREFETCH(p) ((void)(p))
#endif

#endif /* NOCT_LIB_INTERNAL_H */
