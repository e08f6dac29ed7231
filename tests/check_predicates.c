/* SPDX-License-Identifier: MIT */
/*
 * Check suite for the private exact predicates (lib/predicates.c), built
 * into this test with the library's sources.
 *
 * Oracle: integer coordinates below 2^40 make every determinant an integer
 * below 2^125, computed exactly in 128-bit integers. The configurations are
 * nearly degenerate on purpose, so that plain double evaluation gets signs
 * wrong; the suite checks that it does, and that the predicates never do.
 */
#include <check.h>
#include <math.h>
#include <stdlib.h>

#include "../lib/predicates.h"
#include "testutil.h"

__extension__ typedef __int128 i128;

static int sign128(i128 x)
{
    return (x > 0) - (x < 0);
}

static int exact2(const double a[2], const double b[2], const double c[2])
{
    i128 acx = (i128)((long long)a[0] - (long long)c[0]);
    i128 bcx = (i128)((long long)b[0] - (long long)c[0]);
    i128 acy = (i128)((long long)a[1] - (long long)c[1]);
    i128 bcy = (i128)((long long)b[1] - (long long)c[1]);
    return sign128(acx * bcy - acy * bcx);
}

static int exact3(const double *p[4])
{
    i128 m[3][3];
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k)
            m[i][k] = (i128)((long long)p[i][k] - (long long)p[3][k]);
    i128 det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
               m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    return sign128(det);
}

/* A random integer in [-range, range]. */
static long long rnd(uint64_t *rng, long long range)
{
    return (long long)test_rand_below(rng, (size_t)(2 * range + 1)) - range;
}

/* Extended Euclid: x*a + y*b = gcd(a, b). */
static long long egcd(long long a, long long b, long long *x, long long *y)
{
    if (b == 0) {
        *x = a >= 0 ? 1 : -1;
        *y = 0;
        return a >= 0 ? a : -a;
    }
    long long x1, y1, g = egcd(b, a % b, &x1, &y1);
    *x = y1;
    *y = x1 - (a / b) * y1;
    return g;
}

/*
 * Two integer vectors u = (r, s), v = (p, q) about 2^39 long with
 * det(u, v) = r q - s p exactly 'want' (-1, 0 or 1): for 0, v is a multiple
 * of u's primitive direction; otherwise a Bezout pair. Then u is sheared
 * by multiples of v, which keeps the determinant.
 */
static void hard_pair(uint64_t *rng, int want, long long u[2], long long v[2])
{
    long long p, q, x, y;
    do {
        p = rnd(rng, 1LL << 39);
        q = rnd(rng, 1LL << 39);
    } while (p == 0 || q == 0 || egcd(q, p, &x, &y) != 1);
    v[0] = p;
    v[1] = q;
    if (want == 0) {
        long long k = rnd(rng, 3);
        u[0] = k * p;
        u[1] = k * q;
        return;
    }
    /* x q + y p = 1, so r = x, s = -y gives r q - s p = 1. */
    u[0] = want * x;
    u[1] = -want * y;
    long long k = rnd(rng, 2);
    u[0] += k * p;
    u[1] += k * q;
}

START_TEST(orient2d_near_collinear)
{
    uint64_t rng = 11, fallbacks = 0;
    int naive_wrong = 0;
    for (int t = 0; t < 30000; ++t) {
        int want = (int)test_rand_below(&rng, 3) - 1;
        long long u[2], v[2];
        hard_pair(&rng, want, u, v);
        double c[2] = {(double)rnd(&rng, 1LL << 40), (double)rnd(&rng, 1LL << 40)};
        double a[2] = {c[0] + (double)u[0], c[1] + (double)u[1]};
        double b[2] = {c[0] + (double)v[0], c[1] + (double)v[1]};
        EXPECT(exact2(a, b, c) == want); /* the construction is exact */
        EXPECT(noct_orient2d(a, b, c, &fallbacks) == want);
        /* Sign is invariant under cyclic order and flips with a swap. */
        EXPECT(noct_orient2d(b, c, a, NULL) == want);
        EXPECT(noct_orient2d(b, a, c, NULL) == -want);
        double naive = (a[0] - c[0]) * (b[1] - c[1]) - (a[1] - c[1]) * (b[0] - c[0]);
        naive_wrong += ((naive > 0) - (naive < 0)) != want;
    }
    ck_assert_int_gt(naive_wrong, 1000); /* the cases are hard */
    ck_assert_uint_gt(fallbacks, 1000);  /* and the filter handed them on */
}
END_TEST

START_TEST(orient3d_near_coplanar)
{
    uint64_t rng = 12, fallbacks = 0;
    int naive_wrong = 0;
    for (int t = 0; t < 30000; ++t) {
        int want = (int)test_rand_below(&rng, 3) - 1;
        long long u2[2], v2[2];
        hard_pair(&rng, want, u2, v2);
        /* det(u, v, w) = det2(u, v) * 1, then shears that keep it. */
        long long u[3] = {u2[0], u2[1], 0}, v[3] = {v2[0], v2[1], 0}, w[3] = {0, 0, 1};
        long long a2 = rnd(&rng, 2), a3 = rnd(&rng, 2);
        for (int k = 0; k < 3; ++k)
            w[k] += a2 * u[k] + a3 * v[k];
        double d[3] = {(double)rnd(&rng, 1LL << 40), (double)rnd(&rng, 1LL << 40),
                       (double)rnd(&rng, 1LL << 40)};
        double p[4][3];
        for (int k = 0; k < 3; ++k) {
            p[0][k] = d[k] + (double)u[k];
            p[1][k] = d[k] + (double)v[k];
            p[2][k] = d[k] + (double)w[k];
            p[3][k] = d[k];
        }
        const double *q[4] = {p[0], p[1], p[2], p[3]};
        EXPECT(exact3(q) == want);
        EXPECT(noct_orient3d(p[0], p[1], p[2], p[3], &fallbacks) == want);
        EXPECT(noct_orient3d(p[1], p[0], p[2], p[3], NULL) == -want);
        double m[3][3];
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < 3; ++k)
                m[i][k] = p[i][k] - p[3][k];
        double naive = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                       m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
        naive_wrong += ((naive > 0) - (naive < 0)) != want;
    }
    ck_assert_int_gt(naive_wrong, 1000);
    ck_assert_uint_gt(fallbacks, 1000);
}
END_TEST

START_TEST(extreme_magnitudes)
{
    /* Tiny and huge coordinates, where the filter's bounds do not hold:
     * the exact path must still give the geometric sign. */
    const double a[3] = {0, 0, 0}, b[3] = {0x1p-1000, 0, 0}, c[3] = {0, 0x1p-1000, 0};
    const double up[3] = {0, 0, 0x1p-1070}, down[3] = {0, 0, -0x1p-1070};
    ck_assert_int_eq(noct_orient3d(a, b, c, up, NULL), -1);
    ck_assert_int_eq(noct_orient3d(a, b, c, down, NULL), 1);
    ck_assert_int_eq(noct_orient3d(a, b, c, a, NULL), 0);
    const double A[3] = {0, 0, 0}, B[3] = {1e300, 0, 0}, C[3] = {0, 1e300, 0};
    const double U[3] = {0, 0, 1e300};
    ck_assert_int_eq(noct_orient3d(A, B, C, U, NULL), -1);
    const double a2[2] = {0, 0}, b2[2] = {1e300, 1e300}, c2[2] = {-1e300, -1e300};
    ck_assert_int_eq(noct_orient2d(a2, b2, c2, NULL), 0);
    const double d2[2] = {-1e300, -1e300 + 1e284};
    ck_assert_int_eq(noct_orient2d(a2, b2, d2, NULL), 1);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("predicates");
    TCase *tc = tcase_create("exact signs");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, orient2d_near_collinear);
    tcase_add_test(tc, orient3d_near_coplanar);
    tcase_add_test(tc, extreme_magnitudes);
    suite_add_tcase(s, tc);
    return run_suite(s);
}
