/* SPDX-License-Identifier: MIT */
/**
 * @file noctree/narrowphase.h
 * @brief The exhaustive pairwise collision test, at a chosen accuracy.
 *
 * @defgroup noctree_narrowphase Narrowphase
 * @brief Does a pair of placed meshes collide? The report's hierarchy of
 * partial decision mechanisms, from a bounding box test to the complete
 * edge-against-polygon test.
 *
 * **What "collide" means.** Two objects collide when their closed solids
 * share at least one point: touching counts, and so does one solid lying
 * entirely inside the other. An object is a #noctMesh placed by a
 * translation t: its vertices are `fl(v + t)`, each coordinate rounded to
 * double once, and the solid is the region those placed triangles bound
 * (see mesh.h). So a translation that is exact for every vertex (such as
 * an integer offset of a mesh with dyadic coordinates) moves the solid
 * exactly.
 *
 * **Accuracy levels**, cheapest first. Each runs the cheaper sound tests
 * first, so a pair a cheaper stage rejects is never handed to a costlier
 * one:
 * - #NOCT_ACCURACY_BOX: the placed meshes' axis-aligned bounding boxes
 *   overlap (closed boxes). May report collisions that do not exist; never
 *   misses one.
 * - #NOCT_ACCURACY_CONVEX: box test, then libccd's GJK on the convex hulls
 *   of the placed vertices. For convex solids it is exact up to libccd's
 *   tolerance: it may miss contacts shallower than about 1e-12 of the
 *   objects' size, and report separations that narrow; for non-convex
 *   solids it tests the hulls, so it may also report collisions that do
 *   not exist (never, beyond that tolerance, miss one).
 * - #NOCT_ACCURACY_EXACT: box test; for two small meshes (such as boxes), a
 *   separating-axis test that only ever rejects, and only when the gap
 *   exceeds a rigorous bound on its rounding error (the solids lie inside
 *   the hulls of their placed vertices, so this proves them apart; two
 *   meshes whose 8 vertices are a box's corners, rotated or not, within a
 *   tiny proven deviation are tested as oriented boxes, that deviation
 *   added to their radii), and a
 *   search for a point inside both solids that only ever accepts (the
 *   centre of the boxes' overlap, or a vertex of one deep inside the
 *   other, proved strictly inside every triangle's plane by exact signs);
 *   then each mesh's bounding-volume hierarchy to find the triangle pairs
 *   whose boxes overlap, then, for those, every edge of one triangle
 *   against the other and vice versa;
 *   if no boundaries meet, whether one solid contains a vertex of the
 *   other. Every decision is an orientation sign computed exactly (a
 *   floating-point filter, with a fallback in exact integer arithmetic on
 *   buffers of fixed size: no allocation), so the answer is
 *   exactly the definition above, whatever the scale, offset or
 *   degeneracy. The hull test is not used as a filter here: its tolerance
 *   could reject a touching pair.
 * @{
 */
#ifndef NOCTREE_NARROWPHASE_H
#define NOCTREE_NARROWPHASE_H

#include <stdbool.h>
#include <stdint.h>

#include <noctree/export.h>
#include <noctree/mesh.h>
#include <noctree/status.h>
#include <noctree/transform.h>

#ifdef __cplusplus
extern "C" {
#endif

/** @brief How exactly a pair is decided; see the module description. */
typedef enum noctAccuracy {
    NOCT_ACCURACY_BOX,    /**< Bounding boxes overlap. */
    NOCT_ACCURACY_CONVEX, /**< Convex hulls intersect (libccd GJK). */
    NOCT_ACCURACY_EXACT   /**< The solids share a point, decided exactly. */
} noctAccuracy;

/**
 * @brief Counters of the work a collision test did, by stage.
 *
 * noctCollide() adds to them, so one struct can total many tests. Start
 * from a zeroed struct.
 */
typedef struct noctNarrowStats {
    uint64_t box_tests;       /**< Bounding box tests of pairs. */
    uint64_t box_rejects;     /**< Pairs the box test separated. */
    uint64_t convex_tests;    /**< GJK calls. */
    uint64_t exact_tests;     /**< Pairs that reached the exact stage. */
    uint64_t bvh_pairs;       /**< BVH node pairs visited. */
    uint64_t triangle_pairs;  /**< Triangle pairs tested edge by edge. */
    uint64_t containment_tests; /**< Point-in-solid tests. */
    uint64_t exact_fallbacks; /**< Orientation signs the filter could not
                                   decide, computed in exact integer
                                   arithmetic (GMP's mpn functions). */
    uint64_t sat_rejects;     /**< Exact level: pairs of small meshes
                                   a separating axis proved apart. */
    uint64_t witnesses;       /**< Exact level: pairs of small meshes
                                   proved colliding before any triangle
                                   test: by a point shown inside both,
                                   or, for two box-shaped meshes, by the
                                   separating-axis test on their boxes
                                   shrunk by a proven margin. */
    double seconds_convex;    /**< Time in the convex level (GJK), box
                                   tests excluded. */
    double seconds_exact;     /**< Time in the exact level, box tests
                                   excluded. */
} noctNarrowStats;

/**
 * @brief Decide whether two placed meshes collide.
 * @param[in]  a         The first mesh.
 * @param[in]  ta        Its translation.
 * @param[in]  b         The second mesh (may be @p a).
 * @param[in]  tb        Its translation.
 * @param[in]  accuracy  The accuracy level.
 * @param[out] colliding Receives the answer on #NOCT_OK.
 * @param[in,out] stats  Counters to add this test's work to, or NULL.
 * @pre @p a, @p ta, @p b, @p tb and @p colliding are not NULL.
 * @post On #NOCT_OK, @p *colliding is the answer of the chosen level as
 *       documented above. The answer does not depend on the order of the
 *       two objects.
 * @return #NOCT_OK; #NOCT_ERR_NONFINITE if a translation is not finite;
 *         #NOCT_ERR_TOO_LARGE if a translation's magnitude exceeds
 *         #NOCT_MAX_COORDINATE; #NOCT_ERR_INVALID for an unknown accuracy;
 *         #NOCT_ERR_NUMERIC if libccd returned an unexpected code;
 *         #NOCT_ERR_NOMEM.
 */
NOCT_API noctStatus noctCollide(const noctMesh *a, const double ta[3],
                                const noctMesh *b, const double tb[3],
                                noctAccuracy accuracy, bool *colliding,
                                noctNarrowStats *stats);

/**
 * @brief Decide whether two meshes placed by rigid transforms collide.
 *
 * As noctCollide(), with each mesh rotated as well as translated: its
 * placed vertices are fl(fl(R v) + t) (transform.h). A mesh whose
 * rotation is the identity is used as it is; a rotated one is copied with
 * its vertices rotated (O(V log V) time and memory for V vertices, freed
 * before returning), so a program that tests one rotated mesh often
 * should rotate it once with noctMeshCreate() and call noctCollide().
 * @param[in]  a         The first mesh.
 * @param[in]  xa        Its transform.
 * @param[in]  b         The second mesh (may be @p a).
 * @param[in]  xb        Its transform.
 * @param[in]  accuracy  The accuracy level.
 * @param[out] colliding Receives the answer on #NOCT_OK.
 * @param[in,out] stats  Counters to add this test's work to, or NULL.
 * @param[out] err       Receives the details of a failure, or NULL.
 * @pre @p a, @p xa, @p b, @p xb and @p colliding are not NULL.
 * @post On #NOCT_OK, @p *colliding is the answer of the chosen level for
 *       the placed solids; it does not depend on the order of the two.
 * @return #NOCT_OK; the failures of noctTransformCheck() for a bad
 *         transform; #NOCT_ERR_INVALID for an unknown accuracy;
 *         #NOCT_ERR_DEGENERATE (or another mesh status) if rounding the
 *         rotated vertices made the mesh degenerate; #NOCT_ERR_NUMERIC;
 *         #NOCT_ERR_NOMEM.
 */
NOCT_API noctStatus noctCollideTransformed(const noctMesh *a, const noctTransform *xa,
                                           const noctMesh *b, const noctTransform *xb,
                                           noctAccuracy accuracy, bool *colliding,
                                           noctNarrowStats *stats, noctError *err);

/**
 * @brief Return the name of an accuracy level.
 * @param[in] accuracy A level.
 * @return The level's name: "box", "convex" or "exact"; "unknown" for
 *         another value.
 */
NOCT_API const char *noctAccuracyName(noctAccuracy accuracy);

#ifdef __cplusplus
}
#endif

/** @} */
#endif /* NOCTREE_NARROWPHASE_H */
