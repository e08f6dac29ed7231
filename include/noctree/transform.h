/* SPDX-License-Identifier: MIT */
/**
 * @file noctree/transform.h
 * @brief Rigid transforms: a rotation and a translation, and how a mesh is
 * placed by one.
 *
 * @defgroup noctree_transform Rigid transforms
 * @brief Where an object is: a unit quaternion at the API, a 3x3 matrix
 * inside, and a translation.
 *
 * **Rotations.** A rotation is given as a quaternion q = (x, y, z, w),
 * w the scalar part; q and -q are the same rotation. A quaternion whose
 * squared length n = ((x x + y y) + z z) + w w (evaluated in that order)
 * differs from 1 by more than #NOCT_QUAT_TOLERANCE is refused
 * (#NOCT_ERR_INVALID); one within it but farther than #NOCT_QUAT_UNIT
 * is normalised by dividing each component by fl(sqrt(n)), and one within
 * #NOCT_QUAT_UNIT (a unit quaternion as computed in double precision) is
 * used as given. The matrix is then, with every product and sum rounded
 * as written:
 *
 *     R = | 1 - 2(yy + zz)   2(xy - zw)       2(xz + yw)     |
 *         | 2(xy + zw)       1 - 2(xx + zz)   2(yz - xw)     |
 *         | 2(xz - yw)       2(yz + xw)       1 - 2(xx + yy) |
 *
 * and every entry within #NOCT_ROTATION_SNAP of 0, 1 or -1 is set to it.
 * So the same quaternion always gives the same matrix, the identity
 * quaternion gives the identity, and every rotation by a multiple of 90
 * degrees about a coordinate axis (however its quaternion was rounded,
 * for example by noctQuatFromAxisAngle()) gives a matrix of 0, 1 and -1.
 *
 * **Placement.** A mesh vertex v is placed by the transform (R, t) at
 *
 *     p_i = fl( fl( fl(R_i0 v_0 + R_i1 v_1) + R_i2 v_2 ) + t_i )
 *
 * every product and sum rounded to double once, in that order (no fused
 * multiply-add): first the rotation, into the rotated mesh that an object
 * keeps while its rotation lasts, then the translation, as placed
 * vertices always were (narrowphase.h). The exact level then decides
 * exactly whether the solids that the placed vertices bound share a
 * point. With a matrix of 0, 1 and -1 the rotation is exact, so a
 * rotation by a multiple of 90 degrees about an axis and a translation
 * that is exact for the mesh's coordinates (an integer offset of a mesh
 * with dyadic coordinates, say) move the solid exactly.
 * @{
 */
#ifndef NOCTREE_TRANSFORM_H
#define NOCTREE_TRANSFORM_H

#include <noctree/export.h>
#include <noctree/status.h>

#ifdef __cplusplus
extern "C" {
#endif

/** Largest accepted |squared length - 1| of a rotation quaternion. */
#define NOCT_QUAT_TOLERANCE 1e-6

/** A quaternion whose squared length is within this of 1 is used as
 *  given, without normalising: 4 units in the last place of 1. */
#define NOCT_QUAT_UNIT 0x1p-50

/** Matrix entries within this of 0, 1 or -1 are set to it. */
#define NOCT_ROTATION_SNAP 0x1p-44

/** @brief A rotation quaternion: vector part x, y, z and scalar part w. */
typedef struct noctQuat {
    double x; /**< Vector part, x. */
    double y; /**< Vector part, y. */
    double z; /**< Vector part, z. */
    double w; /**< Scalar part: cos(angle / 2). */
} noctQuat;

/** @brief A rigid transform: rotate by q, then translate by p. */
typedef struct noctTransform {
    double p[3]; /**< The translation (the object's position). */
    noctQuat q;  /**< The rotation, a unit quaternion. */
} noctTransform;

/**
 * @brief The identity transform: no rotation, no translation.
 * @return p = 0, q = (0, 0, 0, 1).
 */
NOCT_API noctTransform noctIdentityTransform(void);

/**
 * @brief The rotation by an angle about an axis.
 * @param axis the axis, of any non-zero length.
 * @param degrees the angle, counterclockwise looking down the axis.
 * @param q receives (sin(a/2) u, cos(a/2)) for the unit axis u and the
 *        angle a reduced to [-180, 180] degrees; for multiples of 90
 *        degrees about a coordinate axis its components are 0, 1/2,
 *        sqrt(1/2) or 1 up to sign, rounded.
 * @pre axis != NULL && q != NULL
 * @post On #NOCT_OK, *q is a unit quaternion within rounding. On failure
 *       *q is the identity.
 * @return #NOCT_OK; #NOCT_ERR_NONFINITE if the axis or the angle is not
 *         finite; #NOCT_ERR_INVALID for a zero axis.
 */
NOCT_API noctStatus noctQuatFromAxisAngle(const double axis[3], double degrees, noctQuat *q);

/**
 * @brief The rotation matrix of a quaternion, as the module describes.
 * @param q the quaternion.
 * @param R receives the matrix, row by row (R[3 i + j] is row i, column j).
 * @param err receives the details of a failure, or NULL.
 * @pre q != NULL && R != NULL
 * @post On #NOCT_OK, R is the matrix of q (normalised if it is farther
 *       than #NOCT_QUAT_UNIT from unit length) with its entries snapped;
 *       the same q always gives the same R. On failure R is the identity.
 * @return #NOCT_OK; #NOCT_ERR_NONFINITE for a component that is not
 *         finite; #NOCT_ERR_INVALID for a squared length farther than
 *         #NOCT_QUAT_TOLERANCE from 1.
 */
NOCT_API noctStatus noctQuatToMatrix(const noctQuat *q, double R[9], noctError *err);

/**
 * @brief The rotation b, then a: the quaternion product a b.
 *
 * Evaluated, with every product and sum rounded once and in this order
 * (no fused multiply-add):
 *
 *     x = ((a.w b.x + a.x b.w) + a.y b.z) - a.z b.y
 *     y = ((a.w b.y - a.x b.z) + a.y b.w) + a.z b.x
 *     z = ((a.w b.z + a.x b.y) - a.y b.x) + a.z b.w
 *     w = ((a.w b.w - a.x b.x) - a.y b.y) - a.z b.z
 *
 * then, if its squared length (as noctQuatToMatrix() computes it) is
 * farther than #NOCT_QUAT_UNIT from 1, divided by fl(sqrt) of it; so
 * composing a rotation with itself step after step stays unit length
 * without drifting. The world's angular velocity (#NOCT_EFFECT_SPIN)
 * turns an object's q into noctQuatCompose(angular_velocity, q).
 * @param a the rotation applied second.
 * @param b the rotation applied first.
 * @pre a != NULL && b != NULL
 * @return the product, normalised as above (for unit a and b).
 */
NOCT_API noctQuat noctQuatCompose(const noctQuat *a, const noctQuat *b);

/**
 * @brief Check a transform as the world and noctCollideTransformed() do.
 * @param x the transform.
 * @param err receives the details of a failure, or NULL.
 * @pre x != NULL
 * @return #NOCT_OK; #NOCT_ERR_NONFINITE for a component that is not
 *         finite; #NOCT_ERR_TOO_LARGE for a translation beyond
 *         #NOCT_MAX_COORDINATE; #NOCT_ERR_INVALID for a quaternion
 *         farther from unit length than #NOCT_QUAT_TOLERANCE.
 */
NOCT_API noctStatus noctTransformCheck(const noctTransform *x, noctError *err);

#ifdef __cplusplus
}
#endif

/** @} */
#endif /* NOCTREE_TRANSFORM_H */
