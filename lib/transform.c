/* SPDX-License-Identifier: MIT */
/*
 * Rigid transforms (transform.h): quaternions to matrices, as documented
 * there operation by operation, so that the same quaternion always gives
 * the same matrix, and meshes rotated by them (the rotated copy an object
 * keeps while its rotation lasts).
 */
#include "config.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <noctree/transform.h>

#include "internal.h"
#include "mesh_internal.h"

static const double IDENTITY[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};

noctTransform noctIdentityTransform(void)
{
    noctTransform x = {{0, 0, 0}, {0, 0, 0, 1}};
    return x;
}

/* sin and cos of an angle in degrees, exact at multiples of 45 degrees
 * (as exact as a double holds sqrt(1/2)). */
static void sincos_degrees(double deg, double *s, double *c)
{
    deg = fmod(deg, 360);
    if (deg > 180)
        deg -= 360;
    else if (deg < -180)
        deg += 360;
    const double eighths = deg / 45;
    if (eighths == floor(eighths)) {
        static const double r = 0.70710678118654752440; /* sqrt(1/2) */
        static const double S[9] = {0, -r, -1, -r, 0, r, 1, r, 0};
        static const double C[9] = {-1, -r, 0, r, 1, r, 0, -r, -1};
        const int i = (int)eighths + 4; /* -180 .. 180 in steps of 45 */
        *s = S[i];
        *c = C[i];
        return;
    }
    const double a = deg * (3.14159265358979323846 / 180);
    *s = sin(a);
    *c = cos(a);
}

noctStatus noctQuatFromAxisAngle(const double axis[3], double degrees, noctQuat *q)
{
    NOCT_REQUIRE(axis != NULL && q != NULL);
    *q = (noctQuat){0, 0, 0, 1};
    if (!isfinite(axis[0]) || !isfinite(axis[1]) || !isfinite(axis[2]) || !isfinite(degrees))
        return NOCT_ERR_NONFINITE;
    double u[3];
    if (!noct_unit_direction(axis, u))
        return NOCT_ERR_INVALID;
    double s, c;
    /* the half angle, reduced so that w >= 0 for angles in [-180, 180] */
    double half = fmod(degrees, 360);
    if (half > 180)
        half -= 360;
    else if (half < -180)
        half += 360;
    sincos_degrees(half / 2, &s, &c);
    *q = (noctQuat){s * u[0], s * u[1], s * u[2], c};
    return NOCT_OK;
}

/* Products and sums rounded one at a time: a volatile result cannot be
 * fused into a multiply-add, whatever -ffp-contract the library is built
 * with (GNU C's default would fuse across statements). */
static double mul(double a, double b)
{
    volatile double r = a * b;
    return r;
}

static double add(double a, double b)
{
    volatile double r = a + b;
    return r;
}

static double snap(double x)
{
    if (fabs(x) <= NOCT_ROTATION_SNAP)
        return 0;
    if (fabs(x - 1) <= NOCT_ROTATION_SNAP)
        return 1;
    if (fabs(x + 1) <= NOCT_ROTATION_SNAP)
        return -1;
    return x;
}

noctStatus noctQuatToMatrix(const noctQuat *q, double R[9], noctError *err)
{
    NOCT_REQUIRE(q != NULL && R != NULL);
    memcpy(R, IDENTITY, sizeof IDENTITY);
    double x = q->x, y = q->y, z = q->z, w = q->w;
    if (!isfinite(x) || !isfinite(y) || !isfinite(z) || !isfinite(w))
        return noct_fail(err, NOCT_ERR_NONFINITE, -1, 0,
                         "rotation quaternion (%g, %g, %g, %g) is not finite", x, y, z, w);
    const double n = add(add(add(mul(x, x), mul(y, y)), mul(z, z)), mul(w, w));
    if (!(fabs(n - 1) <= NOCT_QUAT_TOLERANCE))
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0,
                         "rotation quaternion (%g, %g, %g, %g) has squared length %g; "
                         "it must be within %g of 1",
                         x, y, z, w, n, NOCT_QUAT_TOLERANCE);
    if (!(fabs(n - 1) <= NOCT_QUAT_UNIT)) {
        const double l = sqrt(n);
        x /= l;
        y /= l;
        z /= l;
        w /= l;
    }
    const double xx = mul(x, x), yy = mul(y, y), zz = mul(z, z);
    const double xy = mul(x, y), xz = mul(x, z), yz = mul(y, z);
    const double xw = mul(x, w), yw = mul(y, w), zw = mul(z, w);
    /* (2 a is exact, so 1 - 2 a fused or not is the same) */
    R[0] = snap(1 - 2 * add(yy, zz));
    R[1] = snap(2 * add(xy, -zw));
    R[2] = snap(2 * add(xz, yw));
    R[3] = snap(2 * add(xy, zw));
    R[4] = snap(1 - 2 * add(xx, zz));
    R[5] = snap(2 * add(yz, -xw));
    R[6] = snap(2 * add(xz, -yw));
    R[7] = snap(2 * add(yz, xw));
    R[8] = snap(1 - 2 * add(xx, yy));
    return NOCT_OK;
}

noctQuat noctQuatCompose(const noctQuat *a, const noctQuat *b)
{
    NOCT_REQUIRE(a != NULL && b != NULL);
    noctQuat q = {
        add(add(add(mul(a->w, b->x), mul(a->x, b->w)), mul(a->y, b->z)), -mul(a->z, b->y)),
        add(add(add(mul(a->w, b->y), -mul(a->x, b->z)), mul(a->y, b->w)), mul(a->z, b->x)),
        add(add(add(mul(a->w, b->z), mul(a->x, b->y)), -mul(a->y, b->x)), mul(a->z, b->w)),
        add(add(add(mul(a->w, b->w), -mul(a->x, b->x)), -mul(a->y, b->y)), -mul(a->z, b->z)),
    };
    const double n = add(add(add(mul(q.x, q.x), mul(q.y, q.y)), mul(q.z, q.z)), mul(q.w, q.w));
    if (isfinite(n) && n > 0 && !(fabs(n - 1) <= NOCT_QUAT_UNIT)) {
        const double l = sqrt(n);
        q.x /= l;
        q.y /= l;
        q.z /= l;
        q.w /= l;
    }
    return q;
}

noctStatus noctTransformCheck(const noctTransform *x, noctError *err)
{
    NOCT_REQUIRE(x != NULL);
    double R[9];
    return noct_transform_matrix(x, R, err);
}

noctStatus noct_transform_matrix(const noctTransform *x, double R[9], noctError *err)
{
    for (int k = 0; k < 3; ++k) {
        if (!isfinite(x->p[k]))
            return noct_fail(err, NOCT_ERR_NONFINITE, -1, 0,
                             "translation (%g, %g, %g) is not finite", x->p[0], x->p[1],
                             x->p[2]);
        if (fabs(x->p[k]) > NOCT_MAX_COORDINATE)
            return noct_fail(err, NOCT_ERR_TOO_LARGE, -1, 0,
                             "translation (%g, %g, %g) lies beyond %g", x->p[0], x->p[1],
                             x->p[2], NOCT_MAX_COORDINATE);
    }
    return noctQuatToMatrix(&x->q, R, err);
}

bool noct_is_identity(const double R[9])
{
    return memcmp(R, IDENTITY, sizeof IDENTITY) == 0;
}

/* fl(R v), in the documented order. */
void noct_rotate(const double R[9], const double v[3], double out[3])
{
    for (int i = 0; i < 3; ++i) {
        volatile double a = R[3 * i] * v[0];
        volatile double b = R[3 * i + 1] * v[1];
        volatile double c = R[3 * i + 2] * v[2];
        out[i] = (a + b) + c;
    }
}

/* ---- interpolation ---------------------------------------------------------- */

static double dot4(const noctQuat *a, const noctQuat *b)
{
    volatile double xx = a->x * b->x, yy = a->y * b->y, zz = a->z * b->z, ww = a->w * b->w;
    volatile double s = xx + yy;
    s = s + zz;
    return s + ww;
}

noctQuat noct_quat_slerp(const noctQuat *q0, const noctQuat *q1_, double s)
{
    /* Two keys of the same rotation, bit for bit: that rotation (a track
     * that only translates keeps its rotation exactly, so continuous
     * detection sees no turn). */
    if (memcmp(q0, q1_, sizeof *q0) == 0)
        return *q0;
    noctQuat q1 = *q1_;
    double d = dot4(q0, &q1);
    if (d < 0) {
        q1 = (noctQuat){-q1.x, -q1.y, -q1.z, -q1.w};
        d = -d;
    }
    double a, b;
    if (d > 0.9995) {
        a = 1 - s;
        b = s;
    } else {
        const double t = acos(d), st = sin(t);
        a = sin((1 - s) * t) / st;
        b = sin(s * t) / st;
    }
    volatile double c[4];
    const double u[4] = {q0->x, q0->y, q0->z, q0->w}, v[4] = {q1.x, q1.y, q1.z, q1.w};
    for (int k = 0; k < 4; ++k) {
        volatile double x = a * u[k];
        volatile double y = b * v[k];
        c[k] = x + y;
    }
    const noctQuat q = {c[0], c[1], c[2], c[3]};
    const double n = sqrt(dot4(&q, &q));
    return (noctQuat){q.x / n, q.y / n, q.z / n, q.w / n};
}
