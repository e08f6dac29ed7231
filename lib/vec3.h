/* SPDX-License-Identifier: MIT */
/*
 * Private: 3-vector helpers (foundation floor). Plain doubles, rounded as
 * written: the exact predicates and the proved bounds do their own
 * arithmetic and never rely on these. Never installed.
 */
#ifndef NOCT_LIB_VEC3_H
#define NOCT_LIB_VEC3_H

#include <float.h>
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <string.h>

#include "internal.h"

/* A 3-vector as an array element type: resizable arrays of vectors
 * (array.h) and the motion's saved positions. */
typedef double noct_vec3[3];
typedef double noct_box6[6]; /* lo, hi */
typedef int64_t noct_ticks[3];

static inline void noct_sub3(const double a[3], const double b[3], double out[3])
{
    for (int i = 0; i < 3; ++i)
        out[i] = a[i] - b[i];
}

static inline void noct_add3(const double a[3], const double b[3], double out[3])
{
    for (int i = 0; i < 3; ++i)
        out[i] = a[i] + b[i];
}

static inline void noct_copy3(const double a[3], double out[3])
{
    for (int i = 0; i < 3; ++i)
        out[i] = a[i];
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

/* ---- scaling by powers of two ------------------------------------------------ */

/*
 * The mesh checks compute on differences of coordinates, which a translation
 * that keeps every coordinate exact leaves unchanged, multiplied by the
 * power of two 2^-e that brings the largest to [1/2, 1). Their products
 * of two or three then neither overflow nor underflow where it matters,
 * whatever the mesh's size and place, and so the checks' rounding is
 * relative to the polygon's or the mesh's own size. The scaling is exact
 * except for parts under 2^-1022 of the largest, far below any tolerance.
 */
typedef struct noct_scaler {
    double s0, s1; /* s0 s1 = 2^-e, each a normal power of two */
    int e;
} noct_scaler;

/* 2^k, for k in [-1022, 1023]. */
static inline double noct_pow2(int k)
{
    uint64_t bits = (uint64_t)(k + 1023) << 52;
    double x;
    memcpy(&x, &bits, sizeof x);
    return x;
}

/* The scaler for magnitudes up to m, finite and positive. A subnormal m
 * needs a factor past the doubles (up to 2^1073), hence two. */
static inline noct_scaler noct_scaler_for(double m)
{
    noct_scaler s;
    frexp(m, &s.e); /* m = f 2^e, f in [1/2, 1), e in [-1073, 1024] */
    int k = -s.e, k0 = k / 2;
    s.s0 = noct_pow2(k0);
    s.s1 = noct_pow2(k - k0);
    return s;
}

static inline double noct_scaled(const noct_scaler *s, double x)
{
    return x * s->s0 * s->s1;
}

static inline double noct_max_abs3(const double a[3])
{
    return noct_max(fabs(a[0]), noct_max(fabs(a[1]), fabs(a[2])));
}

/* v scaled by the power of two that brings its largest component into
 * [1/2, 1) (exactly, but for parts under 2^-1022 of the largest); false
 * (out untouched) if v is 0. */
static inline bool noct_scale_to_unit(const double v[3], double out[3])
{
    const double m = noct_max_abs3(v);
    if (!(m > 0))
        return false;
    const noct_scaler s = noct_scaler_for(m);
    for (int k = 0; k < 3; ++k)
        out[k] = noct_scaled(&s, v[k]);
    return true;
}

/* u = d / |d| (false, and u = 0, for d = 0), for d of any magnitude: the
 * length is taken of d scaled into [1/2, 1), so it neither overflows nor
 * underflows. */
static inline bool noct_unit3(const double d[3], double u[3])
{
    double x[3];
    if (!noct_scale_to_unit(d, x)) {
        u[0] = u[1] = u[2] = 0;
        return false;
    }
    const double len = noct_norm3(x); /* in [1/2, 2] */
    for (int k = 0; k < 3; ++k)
        u[k] = x[k] / len;
    return true;
}

/*
 * The proved gaps (the least distance of two point sets along an axis u,
 * from their projections on u, less their rounding, over |u|) take u as
 * it is when its largest component lies in [2^-400, 2^400], and scaled
 * by a power of two into [1/2, 1) otherwise: then u.u is a normal double
 * and |u| has only its own rounding, where a u of components under
 * 2^-537 would make u.u 0 and a gap over it infinite. The projections
 * may still underflow (points near the origin): NOCT_GAP_TINY, added to
 * their allowance, covers the absolute error of subnormal products and
 * sums, and noct_gap_over() gives 0 for gaps under 2^-1000, where its
 * division's rounding would no longer be relative.
 */
#define NOCT_GAP_TINY 0x1p-1040

/* The axis to project on (see above); false if u is 0 or not finite. */
static inline bool noct_gap_axis(const double u[3], double axis[3])
{
    const double m = noct_max_abs3(u);
    if (m >= 0x1p-400 && m <= 0x1p400) {
        noct_copy3(u, axis);
        return true;
    }
    if (!(m > 0 && m <= DBL_MAX))
        return false;
    return noct_scale_to_unit(u, axis);
}

/* A gap along axis (in units of |axis|, its allowance already taken off)
 * over |axis|, rounded down: 0 if it is not above 2^-1000. */
static inline double noct_gap_over(double gap, const double axis[3])
{
    if (!(gap > 0))
        return 0;
    const double q = gap / (noct_norm3(axis) * (1 + 0x1p-48));
    return q >= 0x1p-1000 ? q : 0;
}

#endif /* NOCT_LIB_VEC3_H */
