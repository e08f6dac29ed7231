/* SPDX-License-Identifier: MIT */
/*
 * Private: exact orientation predicates on double inputs.
 *
 * Each returns the exact sign (-1, 0 or +1) of a determinant of its
 * arguments as real numbers. A floating-point evaluation decides whenever
 * its error bound (Shewchuk's stage A) proves the sign; otherwise the
 * determinant is recomputed in GMP rationals, which is exact for any
 * finite doubles. *fallbacks, if not NULL, counts the exact recomputations.
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

#endif /* NOCT_LIB_PREDICATES_H */
