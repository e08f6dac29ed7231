/* SPDX-License-Identifier: MIT */
/*
 * Private: 3-vector helpers (foundation floor). Plain doubles, rounded as
 * written: the exact predicates and the proved bounds do their own
 * arithmetic and never rely on these. Never installed.
 */
#ifndef NOCT_LIB_VEC3_H
#define NOCT_LIB_VEC3_H

#include <math.h>
#include <stdint.h>

/* A 3-vector as an array element type: resizable arrays of vectors
 * (array.h) and the motion's saved positions. */
typedef double noct_vec3[3];
typedef int64_t noct_ticks[3];

static inline void noct_sub3(const double a[3], const double b[3], double out[3])
{
    for (int i = 0; i < 3; ++i)
        out[i] = a[i] - b[i];
}

static inline void noct_cross3(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

static inline double noct_dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline double noct_norm3(const double a[3])
{
    return sqrt(noct_dot3(a, a));
}

#endif /* NOCT_LIB_VEC3_H */
