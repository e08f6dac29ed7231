/* SPDX-License-Identifier: MIT */
/*
 * Check suite for the private exact predicates (lib/predicates.c), built
 * into this test with the library's sources.
 *
 * Oracles: integer coordinates below 2^40 make every determinant an integer
 * below 2^125, computed exactly in 128-bit integers. The configurations are
 * nearly degenerate on purpose, so that plain double evaluation gets signs
 * wrong; the suite checks that it does, and that the predicates never do.
 * For inputs anywhere in the double range, the oracle is GMP's rationals
 * (mpq), which the library no longer uses: the exact path must agree with
 * them, and must not allocate.
 */
#include <check.h>
#include <float.h>
#include <gmp.h>
#include <math.h>
#include <stdbool.h>
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

/* ---- the exact path against rationals, over the whole double range ------ */

/* det[a-d; b-d; c-d] in rationals, by the rule of Sarrus (the library
 * expands by cofactors, in integers). */
static int oracle3(double p[4][3])
{
    static const int perm[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1},
                                   {2, 1, 0}, {0, 2, 1}, {1, 0, 2}};
    mpq_t m[3][3], t, det;
    mpq_inits(t, det, NULL);
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) {
            mpq_init(m[i][k]);
            mpq_set_d(m[i][k], p[i][k]);
            mpq_set_d(t, p[3][k]);
            mpq_sub(m[i][k], m[i][k], t);
        }
    /* Row i takes column perm[s][i]; the last three permutations are odd. */
    for (int s = 0; s < 6; ++s) {
        mpq_mul(t, m[0][perm[s][0]], m[1][perm[s][1]]);
        mpq_mul(t, t, m[2][perm[s][2]]);
        if (s < 3)
            mpq_add(det, det, t);
        else
            mpq_sub(det, det, t);
    }
    int sign = mpq_sgn(det);
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k)
            mpq_clear(m[i][k]);
    mpq_clears(t, det, NULL);
    return sign;
}

/* det[a-c; b-c] in rationals. */
static int oracle2(double p[3][2])
{
    mpq_t m[2][2], t, det;
    mpq_inits(m[0][0], m[0][1], m[1][0], m[1][1], t, det, NULL);
    for (int i = 0; i < 2; ++i)
        for (int k = 0; k < 2; ++k) {
            mpq_set_d(m[i][k], p[i][k]);
            mpq_set_d(t, p[2][k]);
            mpq_sub(m[i][k], m[i][k], t);
        }
    mpq_mul(det, m[0][0], m[1][1]);
    mpq_mul(t, m[0][1], m[1][0]);
    mpq_sub(det, det, t);
    int sign = mpq_sgn(det);
    mpq_clears(m[0][0], m[0][1], m[1][0], m[1][1], t, det, NULL);
    return sign;
}

static int rnd_int(uint64_t *rng, int lo, int hi)
{
    return lo + (int)test_rand_below(rng, (size_t)(hi - lo + 1));
}

/* Any finite double, biased toward the awkward ones: zeros of both signs,
 * subnormals, the extremes, and random mantissas at random exponents over
 * the whole range (rounded to subnormals or to zero at the bottom). */
static double any_double(uint64_t *rng)
{
    static const double special[] = {DBL_MAX, DBL_MIN, DBL_TRUE_MIN, 1e300, 1e-300, 1.0};
    double x;
    switch (test_rand_below(rng, 6)) {
    case 0:
        x = 0.0;
        break;
    case 1: /* a subnormal, or zero */
        x = (double)(test_rand(rng) >> 12) * DBL_TRUE_MIN;
        break;
    case 2:
        x = special[test_rand_below(rng, sizeof special / sizeof *special)];
        break;
    default:
        x = ldexp((double)(test_rand(rng) >> 11), rnd_int(rng, -1074 - 53, 1023 - 53));
    }
    return test_rand_below(rng, 2) ? -x : x;
}

/* An integer below 2^53 times 2^e, e >= -1074, short of overflow: exact. */
static double scaled(long long v, int e)
{
    return ldexp((double)v, e);
}

/* Move x by one ulp, half of the time; which way at random. */
static void maybe_nudge(uint64_t *rng, double *x)
{
    if (test_rand_below(rng, 2))
        *x = nextafter(*x, test_rand_below(rng, 2) ? INFINITY : -INFINITY);
}

/* A power of two for each axis: one for all, or one each, anywhere from
 * the subnormals to where the coordinates (below 2^43) stay finite.
 * Scaling an axis is a linear map: it keeps points coplanar (collinear). */
static void axis_scales(uint64_t *rng, int dim, int e[3])
{
    bool same = test_rand_below(rng, 2);
    for (int k = 0; k < dim; ++k)
        e[k] = k > 0 && same ? e[0] : rnd_int(rng, -1074, 1023 - 44);
}

/*
 * Four points, exactly coplanar: d, d + u, d + v, d + alpha u + beta v,
 * integers with |d| < 2^40 and u, v of random length up to 2^39 (long
 * ones make plain double evaluation round), each axis scaled by its own
 * power of two; then one coordinate moved by one ulp, half of the time.
 */
static void near_coplanar(uint64_t *rng, double p[4][3])
{
    long long range = 1LL << rnd_int(rng, 1, 39);
    long long alpha = rnd(rng, 3), beta = rnd(rng, 3);
    int e[3];
    axis_scales(rng, 3, e);
    for (int k = 0; k < 3; ++k) {
        long long d = rnd(rng, 1LL << 40), u = rnd(rng, range), v = rnd(rng, range);
        p[0][k] = scaled(d + u, e[k]);
        p[1][k] = scaled(d + v, e[k]);
        p[2][k] = scaled(d + alpha * u + beta * v, e[k]);
        p[3][k] = scaled(d, e[k]);
    }
    maybe_nudge(rng, &p[test_rand_below(rng, 4)][test_rand_below(rng, 3)]);
}

/* Three points, exactly collinear: c + alpha w, c + beta w, c. */
static void near_collinear(uint64_t *rng, double p[3][2])
{
    long long range = 1LL << rnd_int(rng, 1, 39);
    long long alpha = rnd(rng, 3), beta = rnd(rng, 3);
    int e[3];
    axis_scales(rng, 2, e);
    for (int k = 0; k < 2; ++k) {
        long long c = rnd(rng, 1LL << 40), w = rnd(rng, range);
        p[0][k] = scaled(c + alpha * w, e[k]);
        p[1][k] = scaled(c + beta * w, e[k]);
        p[2][k] = scaled(c, e[k]);
    }
    maybe_nudge(rng, &p[test_rand_below(rng, 3)][test_rand_below(rng, 2)]);
}

/*
 * Case t of the random inputs: nearly degenerate points; points with
 * every coordinate any double; the first with some coordinates replaced by
 * any double; and, sometimes, a coordinate copied from another point or
 * set to a signed zero, which makes zero differences.
 */
static void random_case(uint64_t *rng, int t, int n, int dim, double *p)
{
    if (n == 4)
        near_coplanar(rng, (double(*)[3])p);
    else
        near_collinear(rng, (double(*)[2])p);
    int kind = t % 3;
    for (int i = 0; i < n * dim; ++i)
        if (kind == 1 || (kind == 2 && test_rand_below(rng, 4) == 0))
            p[i] = any_double(rng);
    if (test_rand_below(rng, 4) == 0) {
        int i = (int)test_rand_below(rng, (size_t)(n * dim));
        p[i] = test_rand_below(rng, 2) ? p[(i + dim) % (n * dim)]
                                       : (test_rand_below(rng, 2) ? -0.0 : 0.0);
    }
}

START_TEST(orient3d_exact_matches_rationals)
{
    uint64_t rng = 21, fallbacks = 0;
    int count[3] = {0, 0, 0}, exact_nonzero = 0;
    for (int t = 0; t < 60000; ++t) {
        double p[4][3];
        random_case(&rng, t, 4, 3, &p[0][0]);
        int want = oracle3(p);
        ++count[want + 1];
        uint64_t before = fallbacks;
        EXPECT(noct_orient3d_exact(p[0], p[1], p[2], p[3]) == want);
        EXPECT(noct_orient3d(p[0], p[1], p[2], p[3], &fallbacks) == want);
        EXPECT(noct_orient3d_exact(p[1], p[0], p[2], p[3]) == -want);
        exact_nonzero += fallbacks != before && want != 0;
    }
    /* Every sign is well represented, the filter handed many cases on,
     * and many of those were nearly, not exactly, degenerate. */
    ck_assert_int_gt(count[0], 6000);
    ck_assert_int_gt(count[1], 6000);
    ck_assert_int_gt(count[2], 6000);
    ck_assert_uint_gt(fallbacks, 30000);
    ck_assert_int_gt(exact_nonzero, 20000);
}
END_TEST

START_TEST(orient2d_exact_matches_rationals)
{
    uint64_t rng = 22, fallbacks = 0;
    int count[3] = {0, 0, 0}, exact_nonzero = 0;
    for (int t = 0; t < 60000; ++t) {
        double p[3][2];
        random_case(&rng, t, 3, 2, &p[0][0]);
        int want = oracle2(p);
        ++count[want + 1];
        uint64_t before = fallbacks;
        EXPECT(noct_orient2d_exact(p[0], p[1], p[2]) == want);
        EXPECT(noct_orient2d(p[0], p[1], p[2], &fallbacks) == want);
        EXPECT(noct_orient2d_exact(p[1], p[0], p[2]) == -want);
        exact_nonzero += fallbacks != before && want != 0;
    }
    ck_assert_int_gt(count[0], 6000);
    ck_assert_int_gt(count[1], 6000);
    ck_assert_int_gt(count[2], 6000);
    ck_assert_uint_gt(fallbacks, 25000);
    ck_assert_int_gt(exact_nonzero, 15000);
}
END_TEST

/* Coordinates from the extremes only, so that the integers reach the
 * largest sizes the exact path is built for: DBL_TRUE_MIN sets the common
 * exponent to -1074 and DBL_MAX sits 2098 bits above it. */
static void extreme_case(uint64_t *rng, int n, int dim, double *p)
{
    static const double pick[] = {DBL_MAX, 0x1.fffffffffffffp1022, 0x1p1023,
                                  DBL_TRUE_MIN, 3 * DBL_TRUE_MIN, DBL_MIN,
                                  0x1.8p-1022, 1.0, 0.0};
    for (int i = 0; i < n * dim; ++i) {
        double x = pick[test_rand_below(rng, sizeof pick / sizeof *pick)];
        p[i] = test_rand_below(rng, 2) ? -x : x;
    }
}

START_TEST(exact_extremes_match_rationals)
{
    uint64_t rng = 23;
    int count[3] = {0, 0, 0};
    for (int t = 0; t < 20000; ++t) {
        double p[4][3], q[3][2];
        extreme_case(&rng, 4, 3, &p[0][0]);
        int want = oracle3(p);
        ++count[want + 1];
        EXPECT(noct_orient3d_exact(p[0], p[1], p[2], p[3]) == want);
        EXPECT(noct_orient3d(p[0], p[1], p[2], p[3], NULL) == want);
        extreme_case(&rng, 3, 2, &q[0][0]);
        want = oracle2(q);
        EXPECT(noct_orient2d_exact(q[0], q[1], q[2]) == want);
        EXPECT(noct_orient2d(q[0], q[1], q[2], NULL) == want);
    }
    ck_assert_int_gt(count[0], 1000);
    ck_assert_int_gt(count[2], 1000);
    /* Where the determinant is largest and smallest at once. */
    const double a[3] = {DBL_MAX, -DBL_MAX, DBL_TRUE_MIN}, b[3] = {-DBL_MAX, DBL_TRUE_MIN, DBL_MAX};
    const double c[3] = {DBL_TRUE_MIN, DBL_MAX, -DBL_MAX}, d[3] = {-DBL_MAX, -DBL_MAX, -DBL_MAX};
    double pts[4][3] = {{a[0], a[1], a[2]}, {b[0], b[1], b[2]}, {c[0], c[1], c[2]}, {d[0], d[1], d[2]}};
    ck_assert_int_eq(noct_orient3d_exact(a, b, c, d), oracle3(pts));
    ck_assert_int_ne(oracle3(pts), 0);
    /* Only zeros, of both signs: the determinant is zero. */
    const double z[3] = {0.0, -0.0, 0.0}, nz[3] = {-0.0, -0.0, -0.0};
    ck_assert_int_eq(noct_orient3d_exact(z, nz, z, nz), 0);
    ck_assert_int_eq(noct_orient2d_exact(z, nz, z), 0);
}
END_TEST

START_TEST(filter_underflow_mixed_scales)
{
    /* Found by the test above: x differences near 2^-733 and y ones near
     * 2^-333 make products near 2^-1066, subnormal, which z differences
     * near 2^815 then multiply, while the permanent is far above 1e-250.
     * The filter with the plain 1e-250 floor returned -1 here. */
    double p[4][3] = {{-0x1.a1e664e88p-719, -0x1.1ed1d81d9p-316, 0x1.2f6f599446p+833},
                      {-0x1.a1eb15828p-719, -0x1.1ed25d5d28p-316, 0x1.2f6fb2842dfffp+833},
                      {-0x1.a1ee83e68p-719, -0x1.1ed0c2b3bp-316, 0x1.2f6f1f1e0ap+833},
                      {-0x1.a1ec3a4e8p-719, -0x1.1ed1d47ap-316, 0x1.2f6f816222p+833}};
    uint64_t fallbacks = 0;
    ck_assert_int_eq(oracle3(p), 1);
    ck_assert_int_eq(noct_orient3d(p[0], p[1], p[2], p[3], &fallbacks), 1);
    ck_assert_uint_eq(fallbacks, 1);
}
END_TEST

/* GMP's allocator, counted: the exact path must never reach it. */
static void *(*gmp_alloc)(size_t);
static void *(*gmp_realloc)(void *, size_t, size_t);
static void (*gmp_free)(void *, size_t);
static size_t gmp_calls;

static void *counted_alloc(size_t size)
{
    ++gmp_calls;
    return gmp_alloc(size);
}

static void *counted_realloc(void *p, size_t old, size_t size)
{
    ++gmp_calls;
    return gmp_realloc(p, old, size);
}

static void counted_free(void *p, size_t size)
{
    ++gmp_calls;
    gmp_free(p, size);
}

#define NO_ALLOC_CASES 3000

START_TEST(exact_path_allocates_nothing)
{
    /* The answers first, from the rationals, which allocate. */
    static double p3[NO_ALLOC_CASES][4][3], p2[NO_ALLOC_CASES][3][2];
    static int want3[NO_ALLOC_CASES], want2[NO_ALLOC_CASES];
    uint64_t rng = 24, fallbacks = 0;
    for (int t = 0; t < NO_ALLOC_CASES; ++t) {
        if (t % 4 == 3) {
            extreme_case(&rng, 4, 3, &p3[t][0][0]);
            extreme_case(&rng, 3, 2, &p2[t][0][0]);
        } else {
            random_case(&rng, t, 4, 3, &p3[t][0][0]);
            random_case(&rng, t, 3, 2, &p2[t][0][0]);
        }
        want3[t] = oracle3(p3[t]);
        want2[t] = oracle2(p2[t]);
    }
    /* No GMP object is alive here, as mp_set_memory_functions requires. */
    mp_get_memory_functions(&gmp_alloc, &gmp_realloc, &gmp_free);
    mp_set_memory_functions(counted_alloc, counted_realloc, counted_free);
    gmp_calls = 0;
    int wrong = 0;
    for (int t = 0; t < NO_ALLOC_CASES; ++t) {
        double(*p)[3] = p3[t], (*q)[2] = p2[t];
        wrong += noct_orient3d(p[0], p[1], p[2], p[3], &fallbacks) != want3[t];
        wrong += noct_orient3d_exact(p[0], p[1], p[2], p[3]) != want3[t];
        wrong += noct_orient2d(q[0], q[1], q[2], &fallbacks) != want2[t];
        wrong += noct_orient2d_exact(q[0], q[1], q[2]) != want2[t];
    }
    size_t calls = gmp_calls;
    mp_set_memory_functions(gmp_alloc, gmp_realloc, gmp_free);
    ck_assert_int_eq(wrong, 0);
    ck_assert_uint_gt(fallbacks, NO_ALLOC_CASES); /* the path was taken */
    ck_assert_uint_eq(calls, 0);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("predicates");
    TCase *tc = test_case(s, "exact signs", 120, NULL);
    add_tests(tc, orient2d_near_collinear, orient3d_near_coplanar, extreme_magnitudes,
              orient3d_exact_matches_rationals, orient2d_exact_matches_rationals,
              exact_extremes_match_rationals, filter_underflow_mixed_scales,
              exact_path_allocates_nothing);
    return run_suite(s);
}
