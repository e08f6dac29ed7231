/* SPDX-License-Identifier: MIT */
/*
 * Exact orientation predicates: a floating-point filter with Shewchuk's
 * stage-A error bounds ("Adaptive Precision Floating-Point Arithmetic and
 * Fast Robust Geometric Predicates", 1997), and GMP rationals when the
 * filter cannot prove the sign. A double converts to a rational exactly,
 * so the fallback's sign is the true sign.
 *
 * The bounds assume no underflow or overflow. A permanent (the sum of the
 * absolute values of the determinant's terms) below 1e-250, or not finite,
 * sends the evaluation to the exact path, where neither can happen.
 */
#include "config.h"

#include <gmp.h>
#include <math.h>

#include "predicates.h"

#define EPS 0x1p-53                          /* half an ulp of 1 */
#define CCW_BOUND ((3.0 + 16.0 * EPS) * EPS) /* orient2d, stage A */
#define O3D_BOUND ((7.0 + 56.0 * EPS) * EPS) /* orient3d, stage A */
#define TINY 1e-250

static int sign_of(double x)
{
    return (x > 0) - (x < 0);
}

/* The filter's verdict, or 2 if it cannot decide. */
static int filtered(double det, double permanent, double bound)
{
    if (!isfinite(permanent) || permanent < TINY)
        return 2;
    if (fabs(det) > bound * permanent)
        return sign_of(det);
    return 2;
}

/* out = x - y, exactly. */
static void diff(mpq_t out, double x, double y, mpq_t scratch)
{
    mpq_set_d(out, x);
    mpq_set_d(scratch, y);
    mpq_sub(out, out, scratch);
}

int noct_orient2d(const double a[2], const double b[2], const double c[2],
                  uint64_t *fallbacks)
{
    double acx = a[0] - c[0], bcx = b[0] - c[0];
    double acy = a[1] - c[1], bcy = b[1] - c[1];
    double l = acx * bcy, r = acy * bcx;
    int s = filtered(l - r, fabs(l) + fabs(r), CCW_BOUND);
    if (s != 2)
        return s;
    if (fallbacks != NULL)
        ++*fallbacks;
    mpq_t ax, bx, ay, by, t;
    mpq_inits(ax, bx, ay, by, t, NULL);
    diff(ax, a[0], c[0], t);
    diff(bx, b[0], c[0], t);
    diff(ay, a[1], c[1], t);
    diff(by, b[1], c[1], t);
    mpq_mul(ax, ax, by);
    mpq_mul(ay, ay, bx);
    mpq_sub(ax, ax, ay);
    s = mpq_sgn(ax);
    mpq_clears(ax, bx, ay, by, t, NULL);
    return s;
}

int noct_orient3d(const double a[3], const double b[3], const double c[3],
                  const double d[3], uint64_t *fallbacks)
{
    double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
    double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
    double adz = a[2] - d[2], bdz = b[2] - d[2], cdz = c[2] - d[2];
    double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
    double cdxady = cdx * ady, adxcdy = adx * cdy;
    double adxbdy = adx * bdy, bdxady = bdx * ady;
    double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) +
                 cdz * (adxbdy - bdxady);
    double permanent = (fabs(bdxcdy) + fabs(cdxbdy)) * fabs(adz) +
                       (fabs(cdxady) + fabs(adxcdy)) * fabs(bdz) +
                       (fabs(adxbdy) + fabs(bdxady)) * fabs(cdz);
    int s = filtered(det, permanent, O3D_BOUND);
    if (s != 2)
        return s;
    if (fallbacks != NULL)
        ++*fallbacks;
    mpq_t x[3], y[3], z[3], m, n, t, acc;
    const double *p[3] = {a, b, c};
    mpq_inits(m, n, t, acc, NULL);
    for (int i = 0; i < 3; ++i) {
        mpq_inits(x[i], y[i], z[i], NULL);
        diff(x[i], p[i][0], d[0], t);
        diff(y[i], p[i][1], d[1], t);
        diff(z[i], p[i][2], d[2], t);
    }
    /* det = z0 (x1 y2 - x2 y1) + z1 (x2 y0 - x0 y2) + z2 (x0 y1 - x1 y0) */
    mpq_set_ui(acc, 0, 1);
    for (int i = 0; i < 3; ++i) {
        int j = (i + 1) % 3, k = (i + 2) % 3;
        mpq_mul(m, x[j], y[k]);
        mpq_mul(n, x[k], y[j]);
        mpq_sub(m, m, n);
        mpq_mul(m, m, z[i]);
        mpq_add(acc, acc, m);
    }
    s = mpq_sgn(acc);
    for (int i = 0; i < 3; ++i)
        mpq_clears(x[i], y[i], z[i], NULL);
    mpq_clears(m, n, t, acc, NULL);
    return s;
}
