/* SPDX-License-Identifier: MIT */
/*
 * Private: exact orientation predicates on double inputs.
 *
 * Each returns the exact sign (-1, 0 or +1) of a determinant of its
 * arguments as real numbers. A floating-point evaluation decides whenever
 * its error bound (Shewchuk's stage A) proves the sign; otherwise the
 * determinant is recomputed exactly in integer arithmetic (GMP's mpn layer
 * on buffers on the stack), which is exact for any finite doubles and
 * allocates nothing, so it can neither fail nor abort. *fallbacks, if not
 * NULL, counts the exact recomputations. An input that is not finite has
 * no exact sign: that is a bug of the caller (the library validates every
 * coordinate), an invariant in the defensive build; the exact path then
 * returns 0.
 */
#ifndef NOCT_LIB_PREDICATES_H
#define NOCT_LIB_PREDICATES_H

#include <stdint.h>

/* Sign of det[a-d; b-d; c-d]: positive when d lies below the plane through
 * a, b, c, "below" being the side from which a, b, c appear clockwise (so
 * positive for a point inside a solid whose triangle a, b, c is
 * counter-clockwise seen from outside). */
int noct_orient3d(const double a[3], const double b[3], const double c[3],
                  const double d[3], uint64_t *fallbacks);

/* Sign of det[a-c; b-c] in 2D: positive when a, b, c turn
 * counter-clockwise. */
int noct_orient2d(const double a[2], const double b[2], const double c[2],
                  uint64_t *fallbacks);

/* The exact paths alone, without the filter (and not counted): what the
 * two above fall back to, declared here for the tests. Like every
 * function without NOCT_API, they are hidden in the shared libraries. */
int noct_orient3d_exact(const double a[3], const double b[3], const double c[3],
                        const double d[3]);
int noct_orient2d_exact(const double a[2], const double b[2], const double c[2]);

#endif /* NOCT_LIB_PREDICATES_H */
