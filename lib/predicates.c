/* SPDX-License-Identifier: MIT */
/*
 * Exact orientation predicates: a floating-point filter with Shewchuk's
 * stage-A error bounds ("Adaptive Precision Floating-Point Arithmetic and
 * Fast Robust Geometric Predicates", 1997), and an exact integer evaluation
 * when the filter cannot prove the sign.
 *
 * The bounds assume no underflow or overflow. An overflow makes the
 * permanent (the sum of the absolute values of the determinant's terms)
 * infinite or NaN, which sends the evaluation to the exact path, where
 * neither can happen. Underflow (gradual, IEEE 754's default) costs sums
 * and differences nothing, and a product at most 2^-1075 beyond its
 * relative rounding error; stage A's analysis holds for the computation
 * without those absolute errors, which add up to about 2^-1074 in
 * orient2d and to less than 2^-1073 (1 + |adz| + |bdz| + |cdz|) in
 * orient3d, where the products of two differences are multiplied by a
 * third (the permanent is off by as much). The filter accepts only
 * |det| > E = fl(bound permanent), so |det| is at least the double after
 * E, at least E (1 + 2^-53): a margin of about 2^-103 permanent. A
 * permanent below 1e-250 (times 1 + |adz| + |bdz| + |cdz| in orient3d)
 * goes to the exact path; above, the underflow errors are below 2^-240
 * permanent, far inside the margin. The factor matters: with axes of
 * unlike scales, a product of two tiny differences can underflow, then be
 * multiplied by a huge third one, while the permanent is large.
 *
 * The exact path. A finite nonzero double is m 2^q with m an odd integer
 * below 2^53 and q >= -1074, and its magnitude is below 2^k for some
 * k <= 1024. Dividing every coordinate on an axis by 2^emin, emin the
 * smallest q among them, makes them all integers below
 * 2^(kmax - emin) <= 2^2098, and multiplies the determinant (linear in
 * each axis' column) by a positive power of two, which keeps its sign.
 * The differences, the products and the sums are then computed exactly as
 * sign-magnitude integers of GMP limbs, with the mpn layer.
 *
 * No allocation, so no abort: GMP's default allocator ends the process
 * when memory runs out, and the library never does. The integers live in
 * fixed buffers on the stack, sized for the worst case (differences below
 * 2^2099, so 33 limbs of 64 bits; triple products about 100 limbs: about
 * 9 KiB of stack in orient3d), and only mpn functions that take no
 * scratch space are called: mpn_add, mpn_sub, mpn_cmp, mpn_mul_1 and
 * mpn_addmul_1. Not mpn_mul, whose Toom-Cook branches take scratch space
 * that GMP may get from its allocator; a schoolbook product over
 * mpn_addmul_1 serves at these sizes. Inputs of like magnitude give
 * integers of a limb or two, and no gcds are taken: the exact path costs
 * several times less than GMP's rationals did (a few hundred nanoseconds
 * against one to a few microseconds on the development machine).
 */
#include "config.h"

#include <assert.h>
#include <gmp.h>
#include <limits.h>
#include <math.h>
#include <stdbool.h>
#include <string.h>

#include "predicates.h"

#define EPS 0x1p-53                          /* half an ulp of 1 */
#define CCW_BOUND ((3.0 + 16.0 * EPS) * EPS) /* orient2d, stage A */
#define O3D_BOUND ((7.0 + 56.0 * EPS) * EPS) /* orient3d, stage A */
#define TINY 1e-250

static int sign_of(double x)
{
    return (x > 0) - (x < 0);
}

/* The filter's verdict, or 2 if it cannot decide: also when the permanent
 * is below least, where underflow may have mattered (see the top). */
static int filtered(double det, double permanent, double bound, double least)
{
    if (!isfinite(permanent) || permanent < least)
        return 2;
    if (fabs(det) > bound * permanent)
        return sign_of(det);
    return 2;
}

/* ---- exact integers ------------------------------------------------------ */

#if GMP_NAIL_BITS != 0 || GMP_NUMB_BITS > 64
#error "the exact predicates assume GMP limbs of at most 64 bits, without nails"
#endif

/* Limbs for a count of bits. */
#define LIMBS(bits) (((bits) + GMP_NUMB_BITS - 1) / GMP_NUMB_BITS)

/* Buffer sizes in limbs. An input scaled by 2^-emin is below 2^2098 (see
 * the top); each later result may need a carry limb beyond the sum or the
 * larger of its operands' sizes, whatever the values, and is given it. */
#define IN_LIMBS LIMBS(1024 + 1074)            /* an input */
#define DIFF_LIMBS (IN_LIMBS + 1)              /* a difference */
#define PROD_LIMBS (2 * DIFF_LIMBS)            /* a product of two */
#define MINOR_LIMBS (PROD_LIMBS + 1)           /* a 2x2 determinant */
#define TERM_LIMBS (MINOR_LIMBS + DIFF_LIMBS)  /* a minor times a difference */
#define SUM_LIMBS (TERM_LIMBS + 2)             /* the sum of three terms */

/* An integer: sign and magnitude d[0..n), least significant limb first,
 * d[n-1] != 0 (n == 0 for zero). The buffer d holds cap limbs. */
typedef struct exact_int {
    mp_limb_t *d;
    mp_size_t n, cap;
    bool neg;
} exact_int;

/* A finite double as a sign, an odd mantissa and two exponents:
 * |x| = m 2^q < 2^top; m == 0 for a zero of either sign. */
typedef struct exact_split {
    uint64_t m;
    int q, top;
    bool neg;
} exact_split;

static exact_split exact_split_double(double x)
{
    exact_split s = {0, 0, 0, x < 0};
    if (x == 0)
        return s;
    /* |x| = f 2^k with 1/2 <= f < 1, f of at most 53 significant bits
     * (fewer for a subnormal), so f 2^53 is an integer. */
    int k;
    double f = frexp(fabs(x), &k);
    uint64_t m = (uint64_t)(f * 0x1p53);
    int q = k - 53;
#if defined(__GNUC__)
    int zeros = __builtin_ctzll(m); /* m != 0 */
    m >>= zeros;
    q += zeros;
#else
    while ((m & 1) == 0) {
        m >>= 1;
        ++q;
    }
#endif
    s.m = m;
    s.q = q;
    s.top = k;
    return s;
}

/* r = s / 2^emin, an integer since emin <= s.q. */
static void exact_place(exact_int *r, const exact_split *s, int emin)
{
    r->neg = s->neg;
    r->n = 0;
    if (s->m == 0)
        return;
    int shift = s->q - emin;
    mp_size_t i = shift / GMP_NUMB_BITS;
    int bit = shift % GMP_NUMB_BITS;
    assert(shift >= 0);
    for (mp_size_t j = 0; j < i; ++j)
        r->d[j] = 0;
    /* The mantissa a limb at a time: the low GMP_NUMB_BITS - bit bits of
     * what is left go to limb i, shifted up by bit. The last limb written
     * holds m's top bit, so it is not zero. */
    for (uint64_t m = s->m; m != 0; bit = 0) {
        assert(i < r->cap);
        r->d[i++] = (mp_limb_t)(m << bit);
        int fit = GMP_NUMB_BITS - bit;
        m = fit >= 64 ? 0 : m >> fit;
    }
    r->n = i;
}

static void exact_copy(exact_int *r, const exact_int *a, bool neg)
{
    assert(a->n <= r->cap);
    if (a->n > 0)
        memcpy(r->d, a->d, (size_t)a->n * sizeof *r->d);
    r->n = a->n;
    r->neg = neg;
}

/* r = a + b, or a - b if negate. r must not overlap a or b. */
static void exact_add(exact_int *r, const exact_int *a, const exact_int *b, bool negate)
{
    bool bneg = b->neg != negate;
    if (b->n == 0) {
        exact_copy(r, a, a->neg);
        return;
    }
    if (a->n == 0) {
        exact_copy(r, b, bneg);
        return;
    }
    /* mpn_add and mpn_sub take the longer operand first. */
    if (a->neg == bneg) {
        const exact_int *x = a->n >= b->n ? a : b, *y = x == a ? b : a;
        assert(x->n < r->cap);
        mp_limb_t carry = mpn_add(r->d, x->d, x->n, y->d, y->n);
        r->n = x->n;
        if (carry != 0)
            r->d[r->n++] = carry;
        r->neg = a->neg;
        return;
    }
    int cmp = a->n != b->n ? (a->n > b->n ? 1 : -1) : mpn_cmp(a->d, b->d, a->n);
    if (cmp == 0) {
        r->n = 0;
        r->neg = false;
        return;
    }
    const exact_int *x = cmp > 0 ? a : b, *y = cmp > 0 ? b : a;
    assert(x->n <= r->cap);
    mpn_sub(r->d, x->d, x->n, y->d, y->n); /* |x| > |y|: no borrow */
    r->n = x->n;
    while (r->d[r->n - 1] == 0) /* stops: the difference is not zero */
        --r->n;
    r->neg = cmp > 0 ? a->neg : bneg;
}

/* r = a b, schoolbook: a row of mpn_addmul_1 per limb of the shorter
 * factor. r must not overlap a or b. */
static void exact_mul(exact_int *r, const exact_int *a, const exact_int *b)
{
    r->neg = a->neg != b->neg;
    r->n = 0;
    if (a->n == 0 || b->n == 0)
        return;
    if (a->n < b->n) {
        const exact_int *t = a;
        a = b;
        b = t;
    }
    assert(a->n + b->n <= r->cap);
    r->d[a->n] = mpn_mul_1(r->d, a->d, a->n, b->d[0]);
    for (mp_size_t j = 1; j < b->n; ++j)
        r->d[a->n + j] = mpn_addmul_1(r->d + j, a->d, a->n, b->d[j]);
    /* Normalized factors: the product has a->n + b->n - 1 limbs or more. */
    r->n = a->n + b->n;
    if (r->d[r->n - 1] == 0)
        --r->n;
}

static int exact_sign(const exact_int *a)
{
    return a->n == 0 ? 0 : a->neg ? -1 : 1;
}

/*
 * The coordinate differences p[i][k] - p[n-1][k], i < n-1, k < dim, as
 * integers, into diff[i * dim + k] (whose buffers hold DIFF_LIMBS). Each
 * coordinate k has its own power of two: the determinant is linear in each
 * column, so scaling one column scales it by a positive factor too, and
 * axes of unlike scales (1e-300 on one, 1e300 on another) then cost no
 * longer integers than one axis alone. False if an input is not finite.
 */
static bool exact_diffs(const double *const p[], int n, int dim, exact_int diff[])
{
    exact_split s[4][3];
    int emin[3] = {INT_MAX, INT_MAX, INT_MAX};
    assert(n <= 4 && dim <= 3);
    for (int i = 0; i < n; ++i)
        for (int k = 0; k < dim; ++k) {
            if (!isfinite(p[i][k]))
                return false;
            s[i][k] = exact_split_double(p[i][k]);
            if (s[i][k].m != 0 && s[i][k].q < emin[k])
                emin[k] = s[i][k].q;
        }
    mp_limb_t base_d[3][IN_LIMBS], in_d[IN_LIMBS];
    exact_int base[3], in = {in_d, 0, IN_LIMBS, false};
    for (int k = 0; k < dim; ++k) {
        base[k] = (exact_int){base_d[k], 0, IN_LIMBS, false};
        exact_place(&base[k], &s[n - 1][k], emin[k]);
    }
    for (int i = 0; i + 1 < n; ++i)
        for (int k = 0; k < dim; ++k) {
            exact_place(&in, &s[i][k], emin[k]);
            exact_add(&diff[i * dim + k], &in, &base[k], true);
        }
    return true;
}

/* The sign for an input that is not finite: the library validates every
 * coordinate before it gets here, so this cannot happen; an invariant in
 * the defensive build (assert, as NOCT_INVARIANT: this file is also built
 * alone for its tests), and 0, the conservative answer (degenerate: the
 * callers then take the points as touching), in the efficient one. */
static int not_finite(void)
{
    assert(!"an orientation of points that are not finite");
    return 0;
}

/* Buffer sizes for xpoints (predicates.h): a weighted input (a weight
 * below 2^54 adds a limb), a sum of up to NOCT_XPOINT_TERMS of them (a
 * limb of carries, and the one exact_add's check asks for), a difference
 * of two, and the determinants' products and sums as above. The
 * determinants of doubles use the same buffers: only the limbs the
 * values need are touched. */
#define XIN_LIMBS (IN_LIMBS + 1)
#define XCOORD_LIMBS (XIN_LIMBS + 2)
#define XDIFF_LIMBS (XCOORD_LIMBS + 1)
#define XPROD_LIMBS (2 * XDIFF_LIMBS)
#define XMINOR_LIMBS (XPROD_LIMBS + 1)
#define XTERM_LIMBS (XMINOR_LIMBS + XDIFF_LIMBS)
#define XSUM_LIMBS (XTERM_LIMBS + 2)

/* The sign of det[d0 d1; d2 d3] = d0 d3 - d1 d2. */
static int det2_sign(const exact_int d[4])
{
    mp_limb_t l_d[XPROD_LIMBS], r_d[XPROD_LIMBS], det_d[XMINOR_LIMBS];
    exact_int l = {l_d, 0, XPROD_LIMBS, false}, r = {r_d, 0, XPROD_LIMBS, false};
    exact_int det = {det_d, 0, XMINOR_LIMBS, false};
    exact_mul(&l, &d[0], &d[3]);
    exact_mul(&r, &d[1], &d[2]);
    exact_add(&det, &l, &r, true);
    return exact_sign(&det);
}

/* The sign of the determinant of the rows diff[3 i .. 3 i + 2]: with x, y,
 * z for the columns, the sum over the cyclic (i, j, k) of
 * z_i (x_j y_k - x_k y_j). The running sum alternates between two
 * buffers, as exact_add does not work in place. */
static int det3_sign(const exact_int diff[9])
{
    mp_limb_t l_d[XPROD_LIMBS], r_d[XPROD_LIMBS];
    mp_limb_t minor_d[XMINOR_LIMBS], term_d[XTERM_LIMBS], sum_d[2][XSUM_LIMBS];
    exact_int l = {l_d, 0, XPROD_LIMBS, false}, r = {r_d, 0, XPROD_LIMBS, false};
    exact_int minor = {minor_d, 0, XMINOR_LIMBS, false};
    exact_int term = {term_d, 0, XTERM_LIMBS, false};
    exact_int sum[2] = {{sum_d[0], 0, XSUM_LIMBS, false}, {sum_d[1], 0, XSUM_LIMBS, false}};
    for (int i = 0; i < 3; ++i) {
        int j = (i + 1) % 3, k = (i + 2) % 3;
        exact_mul(&l, &diff[3 * j], &diff[3 * k + 1]);
        exact_mul(&r, &diff[3 * k], &diff[3 * j + 1]);
        exact_add(&minor, &l, &r, true);
        exact_mul(&term, &minor, &diff[3 * i + 2]);
        exact_add(&sum[(i + 1) % 2], &sum[i % 2], &term, false);
    }
    return exact_sign(&sum[1]);
}

int noct_orient2d_exact(const double a[2], const double b[2], const double c[2])
{
    const double *p[3] = {a, b, c};
    mp_limb_t diff_d[4][DIFF_LIMBS];
    exact_int diff[4];
    for (int i = 0; i < 4; ++i)
        diff[i] = (exact_int){diff_d[i], 0, DIFF_LIMBS, false};
    if (!exact_diffs(p, 3, 2, diff))
        return not_finite();
    /* diff = {acx, acy, bcx, bcy}; det = acx bcy - acy bcx */
    return det2_sign(diff);
}

int noct_orient3d_exact(const double a[3], const double b[3], const double c[3],
                        const double d[3])
{
    const double *p[4] = {a, b, c, d};
    mp_limb_t diff_d[9][DIFF_LIMBS];
    exact_int diff[9];
    for (int i = 0; i < 9; ++i)
        diff[i] = (exact_int){diff_d[i], 0, DIFF_LIMBS, false};
    if (!exact_diffs(p, 4, 3, diff))
        return not_finite();
    /* diff[3 i + k] is coordinate k of p[i] - d. */
    return det3_sign(diff);
}

/* ---- xpoints: exact ------------------------------------------------------- */

/*
 * Coordinates axes[0..dim) of the xpoints p[0..n), differences with the
 * last as exact_diffs() makes them: each axis scaled by 2^-emin, emin the
 * least exponent of any term's double on it, so every weighted term is an
 * integer. False if a coordinate is not finite.
 */
static bool exact_xdiffs(const noct_xpoint *const p[], int n, int dim, const int axes[],
                         exact_int diff[])
{
    int emin[3] = {INT_MAX, INT_MAX, INT_MAX};
    assert(n <= 4 && dim <= 3);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < p[i]->n; ++j)
            for (int c = 0; c < dim; ++c) {
                double x = p[i]->v[j][axes[c]];
                if (!isfinite(x))
                    return false;
                exact_split s = exact_split_double(x);
                if (s.m != 0 && s.q < emin[c])
                    emin[c] = s.q;
            }
    mp_limb_t in_d[IN_LIMBS], w_d[XIN_LIMBS], coord_d[2][4][3][XCOORD_LIMBS];
    exact_int coord[4][3];
    for (int i = 0; i < n; ++i)
        for (int c = 0; c < dim; ++c) {
            /* The coordinate, a term at a time, alternating between two
             * buffers; coord[i][c] is the last one written. */
            exact_int acc[2] = {{coord_d[0][i][c], 0, XCOORD_LIMBS, false},
                                {coord_d[1][i][c], 0, XCOORD_LIMBS, false}};
            int cur = 0;
            for (int j = 0; j < p[i]->n; ++j) {
                int64_t w = p[i]->w[j];
                exact_split s = exact_split_double(p[i]->v[j][axes[c]]);
                if (w == 0 || s.m == 0)
                    continue;
                assert(w >= -(INT64_C(1) << 53) && w <= (INT64_C(1) << 53));
                exact_int in = {in_d, 0, IN_LIMBS, false};
                exact_place(&in, &s, emin[c]);
                exact_int wt = {w_d, 0, XIN_LIMBS, s.neg != (w < 0)};
                uint64_t mag = w < 0 ? (uint64_t)-w : (uint64_t)w;
                mp_limb_t carry = mpn_mul_1(wt.d, in.d, in.n, (mp_limb_t)mag);
                wt.n = in.n;
                if (carry != 0)
                    wt.d[wt.n++] = carry;
                exact_add(&acc[1 - cur], &acc[cur], &wt, false);
                cur = 1 - cur;
            }
            coord[i][c] = acc[cur];
        }
    for (int i = 0; i + 1 < n; ++i)
        for (int c = 0; c < dim; ++c)
            exact_add(&diff[i * dim + c], &coord[i][c], &coord[n - 1][c], true);
    return true;
}
/* ---- the filtered predicates ---------------------------------------------- */

int noct_orient2d(const double a[2], const double b[2], const double c[2],
                  uint64_t *fallbacks)
{
    double acx = a[0] - c[0], bcx = b[0] - c[0];
    double acy = a[1] - c[1], bcy = b[1] - c[1];
    double l = acx * bcy, r = acy * bcx;
    int s = filtered(l - r, fabs(l) + fabs(r), CCW_BOUND, TINY);
    if (s != 2)
        return s;
    if (fallbacks != NULL)
        ++*fallbacks;
    return noct_orient2d_exact(a, b, c);
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
    double least = TINY * (1 + fabs(adz) + fabs(bdz) + fabs(cdz));
    int s = filtered(det, permanent, O3D_BOUND, least);
    if (s != 2)
        return s;
    if (fallbacks != NULL)
        ++*fallbacks;
    return noct_orient3d_exact(a, b, c, d);
}

/* ---- xpoints: filtered ---------------------------------------------------- */

/*
 * The filter for xpoints. Each coordinate is summed in floating point
 * from its weighted terms (w v, exact products for |w| <= 2^53 but for
 * rounding: error eps |w v|), with its magnitude, the sum of the terms'
 * absolute values; a difference of two coordinates is then within
 * 14 eps of the sum of their magnitudes (at most 12 terms: 11 additions
 * and the products' roundings, each under eps of the magnitude, with
 * (1 + eps)^12 to spare). A determinant of such differences is within
 * 3 * 14 eps (1 + 14 eps)^2 of the sum over its terms of the products of
 * their magnitudes, plus its own rounding, under 7 eps of the same (stage
 * A, on values below the magnitudes): under 50 eps. The filter asks for
 * 64 eps of the magnitudes' permanent, rounded up by the factor below,
 * and sends permanents that may have underflowed or overflowed to the
 * exact path, as the filters above do.
 */
#define X_BOUND (64.0 * EPS)
#define X_ROUND_UP (1.0 + 64.0 * EPS)

typedef struct xcoord {
    double v, m; /* value, magnitude */
} xcoord;

static xcoord xcoord_of(const noct_xpoint *p, int k)
{
    xcoord c = {0, 0};
    for (int j = 0; j < p->n; ++j) {
        double t = (double)p->w[j] * p->v[j][k];
        c.v += t;
        c.m += fabs(t);
    }
    return c;
}

static xcoord xdiff(const noct_xpoint *a, const noct_xpoint *b, int k)
{
    xcoord x = xcoord_of(a, k), y = xcoord_of(b, k);
    return (xcoord){x.v - y.v, x.m + y.m};
}

int noct_orient3d_x(const noct_xpoint *a, const noct_xpoint *b, const noct_xpoint *c,
                    const noct_xpoint *d, uint64_t *fallbacks)
{
    const noct_xpoint *p[4] = {a, b, c, d};
    xcoord r[3][3];
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k)
            r[i][k] = xdiff(p[i], d, k);
    double det = 0, permanent = 0;
    for (int i = 0; i < 3; ++i) {
        int j = (i + 1) % 3, k = (i + 2) % 3;
        det += r[i][2].v * (r[j][0].v * r[k][1].v - r[k][0].v * r[j][1].v);
        permanent += r[i][2].m * (r[j][0].m * r[k][1].m + r[k][0].m * r[j][1].m);
    }
    double least = TINY * (1 + r[0][2].m + r[1][2].m + r[2][2].m);
    int s = filtered(det, permanent * X_ROUND_UP, X_BOUND, least);
    if (s != 2)
        return s;
    if (fallbacks != NULL)
        ++*fallbacks;
    mp_limb_t diff_d[9][XDIFF_LIMBS];
    exact_int diff[9];
    for (int i = 0; i < 9; ++i)
        diff[i] = (exact_int){diff_d[i], 0, XDIFF_LIMBS, false};
    static const int axes[3] = {0, 1, 2};
    if (!exact_xdiffs(p, 4, 3, axes, diff))
        return not_finite();
    return det3_sign(diff);
}

int noct_orient2d_x(int k, const noct_xpoint *a, const noct_xpoint *b,
                    const noct_xpoint *c, uint64_t *fallbacks)
{
    const int axes[2] = {(k + 1) % 3, (k + 2) % 3};
    xcoord ax = xdiff(a, c, axes[0]), ay = xdiff(a, c, axes[1]);
    xcoord bx = xdiff(b, c, axes[0]), by = xdiff(b, c, axes[1]);
    double det = ax.v * by.v - ay.v * bx.v;
    double permanent = ax.m * by.m + ay.m * bx.m;
    int s = filtered(det, permanent * X_ROUND_UP, X_BOUND, TINY);
    if (s != 2)
        return s;
    if (fallbacks != NULL)
        ++*fallbacks;
    const noct_xpoint *p[3] = {a, b, c};
    mp_limb_t diff_d[4][XDIFF_LIMBS];
    exact_int diff[4];
    for (int i = 0; i < 4; ++i)
        diff[i] = (exact_int){diff_d[i], 0, XDIFF_LIMBS, false};
    if (!exact_xdiffs(p, 3, 2, axes, diff))
        return not_finite();
    return det2_sign(diff);
}

int noct_compare_x(int k, const noct_xpoint *a, const noct_xpoint *b, uint64_t *fallbacks)
{
    xcoord d = xdiff(a, b, k);
    /* A difference is within 14 eps of its magnitude (above); underflow
     * costs sums nothing, but the products w v may be off by 2^-1075. */
    if (isfinite(d.m) && d.m > TINY && fabs(d.v) > X_BOUND * d.m * X_ROUND_UP)
        return sign_of(d.v);
    if (fallbacks != NULL)
        ++*fallbacks;
    const noct_xpoint *p[2] = {a, b};
    const int axes[1] = {k};
    mp_limb_t diff_d[1][XDIFF_LIMBS];
    exact_int diff[1] = {{diff_d[0], 0, XDIFF_LIMBS, false}};
    if (!exact_xdiffs(p, 2, 1, axes, diff))
        return not_finite();
    return exact_sign(&diff[0]);
}
