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

/*
 * Points whose coordinates are not doubles: a moving vertex at a time of
 * its motion, p + s D, with D a difference of translations. Coordinate k of
 * an xpoint is the exact sum over j < n of w[j] v[j][k], real numbers, with
 * integer weights of magnitude at most 2^53. The predicates below are the
 * exact signs for such points, filtered as the ones above and recomputed
 * in integers (on the stack, no allocation) when the filter cannot
 * decide.
 */
#define NOCT_XPOINT_TERMS 6

typedef struct noct_xpoint {
    const double *v[NOCT_XPOINT_TERMS];
    int64_t w[NOCT_XPOINT_TERMS];
    int n;
} noct_xpoint;

/* orient3d (as above) of four xpoints. */
int noct_orient3d_x(const noct_xpoint *a, const noct_xpoint *b, const noct_xpoint *c,
                    const noct_xpoint *d, uint64_t *fallbacks);

/* orient2d (as above) of the projections of three xpoints dropping axis
 * k: the two other axes, in cyclic order (k + 1, k + 2). */
int noct_orient2d_x(int k, const noct_xpoint *a, const noct_xpoint *b,
                    const noct_xpoint *c, uint64_t *fallbacks);

/* The sign of a's coordinate k minus b's. */
int noct_compare_x(int k, const noct_xpoint *a, const noct_xpoint *b, uint64_t *fallbacks);

#endif /* NOCT_LIB_PREDICATES_H */
