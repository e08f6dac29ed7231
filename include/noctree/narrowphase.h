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
 * **Surfaces** (mesh.h, noctMeshCreateSurface()) are point sets too: the
 * union of their placed closed triangles, enclosing nothing. So, with
 * the same definition:
 * - a surface and a surface collide iff a triangle of one meets a
 *   triangle of the other (closed triangles: touching counts, and so do
 *   coplanar triangles that overlap or touch);
 * - a surface and a solid collide iff a triangle of the surface meets
 *   the closed solid: it crosses or touches the solid's boundary, or lies
 *   wholly inside it;
 * - a solid inside a closed surface does not collide with it (the
 *   surface's inside is not part of it); two solids: as above.
 *
 * At the exact level this is the same walk of triangle pairs (whose test
 * is complete for closed triangles in any position, coplanar ones
 * included), with no containment test into a surface: only a surface's
 * vertex inside a solid is looked for. The separating-axis filter, the
 * box forms and the witnesses, which reason about solids, are not used
 * for a surface. The box level is conservative as for solids (a surface
 * lies in its box). At the convex level a surface is never convex
 * (noctMeshIsConvex() is false); GJK tests the hull of its vertices, and
 * where GJK finds a pair with a surface apart the level asks a proof that
 * their triangles are apart too (the margin's distance bound, narrowphase_distance.c):
 * the level never misses a pair with a surface, not even a touching one
 * or one whose hull is flat (a planar surface). Every other function
 * treats surfaces by the same definition (it says so where it matters).
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
 * - #NOCT_ACCURACY_CONTINUOUS: the exact level over a motion: two
 *   translating meshes collide if their solids share a point at any time
 *   of the motion (noctCollideSwept()), decided as exactly, with the time
 *   of first contact. Without motion it is the exact level.
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
    NOCT_ACCURACY_EXACT,  /**< The solids share a point, decided exactly. */
    NOCT_ACCURACY_CONTINUOUS /**< Exact continuous detection: in a world,
                                  the solids share a point at some time of
                                  the step's motion (world.h,
                                  "Continuous detection"); for two meshes
                                  that do not move, as #NOCT_ACCURACY_EXACT
                                  (noctCollideSwept() takes the motion). */
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
 * rotation is the identity is used as it is. At the exact level (and the
 * continuous one, which has no motion here) no rotated copy is made: the
 * two hierarchies' boxes are tested as oriented boxes in the first mesh's
 * frame (with a proved allowance for rounding), a vertex is rotated and
 * placed only when a pair of triangles reads it (into a per-thread cache,
 * grown on first use and freed when the thread exits), and containment
 * casts a thin ray down the hierarchy; so a call costs about what the
 * walk visits, not the meshes' sizes (a few microseconds for turned
 * meshes of thousands of triangles). Only a mesh that some rotation could
 * bring near noctMeshCreate()'s tolerance (tiny triangles far from its
 * origin) is still rotated whole and checked. At the box and convex
 * levels a rotated mesh is copied with its vertices rotated (O(V log V)
 * time and memory for V vertices, freed before returning), so a program
 * that tests one rotated mesh often at those levels should rotate it once
 * with noctMeshCreate() and call noctCollide().
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

/** @brief The features by which two moving meshes first touch. */
typedef enum noctSweepFeature {
    NOCT_SWEEP_NONE,        /**< They never touch during the motion. */
    NOCT_SWEEP_START,       /**< They touch at the start, time 0. */
    NOCT_SWEEP_VERTEX_FACE, /**< A vertex of the first reaches a triangle
                                 of the second. */
    NOCT_SWEEP_FACE_VERTEX, /**< A triangle of the first reaches a vertex
                                 of the second. */
    NOCT_SWEEP_EDGE_EDGE,   /**< An edge of the first reaches an edge of
                                 the second. */
    NOCT_SWEEP_END,         /**< The swept solids never touch, but the
                                 solids placed at the end translations do
                                 (time 1): the placements' rounding (see
                                 noctCollideSwept()). */
    NOCT_SWEEP_NEAR         /**< Conservative level (a turning motion,
                                 noctCollideSweptTransformed()): at @c
                                 time the solids came within its distance
                                 bound of each other; they may touch then
                                 or not. No features. */
} noctSweepFeature;

/**
 * @brief When and where two moving meshes first touch.
 *
 * A feature is given by the indices of its vertices in its mesh (as
 * noctMeshCreate() numbered them): one for a vertex, two for an edge,
 * three for a triangle (a triangle of the mesh's triangulation, its
 * vertices counter-clockwise seen from outside); unused entries are
 * UINT32_MAX. The features reported touch within the time's resolution
 * of the first contact: their own first contact lies in
 * [time - 2^-52, time]; where several pairs touch within that step, one
 * of them (not necessarily the very first: the bisection tells times
 * apart only to 2^-52).
 */
typedef struct noctSweepHit {
    double time;              /**< The time of first contact, in [0, 1]:
                                   the least time t at which the solids
                                   share a point lies in
                                   [time - 2^-52, time], and time is a
                                   multiple of 2^-52 (0 for
                                   #NOCT_SWEEP_START, 1 for
                                   #NOCT_SWEEP_END). */
    noctSweepFeature feature; /**< Which features touch first. */
    uint32_t a[3];            /**< The first mesh's feature. */
    uint32_t b[3];            /**< The second mesh's feature. */
    double point[3];          /**< A point where they touch at @c time, in
                                   world coordinates, computed in floating
                                   point from the features (not exact):
                                   for a vertex, where the vertex is at
                                   @c time; for two edges, the point of
                                   the first edge's line nearest the
                                   second's; for #NOCT_SWEEP_START and
                                   #NOCT_SWEEP_END, the centre of the
                                   overlap of the placed boxes (for
                                   #NOCT_SWEEP_NEAR, of the boxes at
                                   @c time grown by the distance). */
    bool conservative;        /**< Decided by the conservative level (a
                                   turning motion): a contact reported may
                                   be a near miss within its distance
                                   bound, and the time is when they came
                                   that near; false: exact. */
} noctSweepHit;

/**
 * @brief Decide exactly whether two translating meshes touch at any time
 *        of their motion, and when first.
 *
 * Continuous detection. Each mesh is placed at its start translation as
 * noctCollide() places it (each vertex fl(v + t0)), and moves rigidly
 * along the straight line to its end translation: at time s in [0, 1]
 * its placed solid is moved by s (t1 - t0), that difference taken
 * exactly (real numbers, not rounded). The two are *colliding* if their
 * closed solids share a point at some time s in [0, 1], or if they
 * collide as noctCollide() places them at the end translations (the
 * solid moved by the exact difference and the one placed at t1 differ
 * by the rounding of the placement, at most half an ulp of each
 * coordinate; so the verdict includes noctCollide()'s at both ends).
 *
 * The verdict is exact, as the exact level's is: the first contact after
 * the start is a vertex of one reaching a triangle of the other, or an
 * edge reaching an edge, and each such question is decided by signs of
 * determinants of the placed vertices and the translations, each sign
 * computed exactly (a floating-point filter, then exact integer
 * arithmetic on the stack: no allocation, no tolerance), whatever the
 * scale, offset, speed or degeneracy (grazing, sliding face on face,
 * start in contact). Two box-shaped meshes (see #NOCT_ACCURACY_EXACT)
 * are first tested by a swept separating-axis test that only rejects,
 * with a proven margin; other pairs walk the two bounding-volume
 * hierarchies with the first one's boxes swept along the relative motion.
 * The time, with @p hit, is found by bisection on the exact verdict of
 * each feature pair that could touch first, so it costs about fifty
 * exact tests of a few features more than the verdict alone.
 *
 * The motion must be a translation: for meshes that also turn, see the
 * world's continuous level (world.h).
 *
 * With a surface (mesh.h) the definition is the module's: the sets share a
 * point at some time. The argument above holds for surfaces as it does
 * for solids (the first contact of two translating sets of closed
 * triangles is a vertex reaching a triangle or an edge an edge), and the
 * start is decided by the exact level, with no containment into a
 * surface: a solid that starts inside a closed surface and stays inside
 * never collides with it; one that reaches its wall does, at that time.
 * @param[in]  a         The first mesh.
 * @param[in]  ta0,ta1   Its start and end translations.
 * @param[in]  b         The second mesh (may be @p a).
 * @param[in]  tb0,tb1   Its start and end translations.
 * @param[out] colliding Receives the verdict on #NOCT_OK.
 * @param[out] hit       Receives the time and features of the first
 *                       contact (feature #NOCT_SWEEP_NONE and time 1 if
 *                       none), or NULL for the verdict alone.
 * @param[in,out] stats  Counters to add this test's work to, or NULL.
 * @pre @p a, @p ta0, @p ta1, @p b, @p tb0, @p tb1 and @p colliding are
 *      not NULL.
 * @post On #NOCT_OK, @p *colliding is the verdict above. It does not
 *       depend on the order of the two meshes, nor on moving both
 *       translations by the same vector when that moves every placed
 *       vertex exactly.
 * @return #NOCT_OK; #NOCT_ERR_NONFINITE if a translation is not finite;
 *         #NOCT_ERR_TOO_LARGE if a translation's magnitude exceeds
 *         #NOCT_MAX_COORDINATE.
 */
NOCT_API noctStatus noctCollideSwept(const noctMesh *a, const double ta0[3],
                                     const double ta1[3], const noctMesh *b,
                                     const double tb0[3], const double tb1[3],
                                     bool *colliding, noctSweepHit *hit,
                                     noctNarrowStats *stats);

/**
 * @brief Decide whether two meshes touch at any time of a rigid motion
 *        between two transforms: exactly when neither turns,
 *        conservatively when one does.
 *
 * Each mesh moves from its start transform to its end one: its
 * translation along the straight line, its rotation along the shorter
 * arc between the two quaternions (spherical interpolation, the angle
 * growing evenly; for turns under about 3.6 degrees, normalized linear
 * interpolation, whose rate stays within 1e-4 of even: noctTrackAt()'s
 * formula), about the mesh's own origin. At each end it is placed
 * as noctCollideTransformed() places it.
 * - If neither rotation changes (the same quaternion bit for bit), this is
 *   noctCollideSwept() on the meshes so rotated: exact, and
 *   @c hit->conservative is false (the rotated copy's triangles may name
 *   an edge from its other end than a mesh made of the same rotated
 *   vertices would).
 * - Otherwise the **conservative level**: the exact level at the start
 *   (and the end); between them conservative advancement: from a time t,
 *   the motion may go on by an interval in which no point of either solid
 *   can move farther than their distance at t (every point moves at most
 *   |t1 - t0| + r theta per unit of time, r the mesh's farthest vertex
 *   from its origin and theta the turn's angle; the distance is bounded
 *   below by the margin's proof, narrowphase_distance.c); where they are
 *   nearer than the interval can be shrunk for, they are reported. It
 *   never misses a contact, and it reports a contact that does not
 *   happen only for solids that come within
 *   eps = max(2^-20 (rA + rB), (sA + sB) / 1024) of each other during the
 *   motion, where rA, rB are the meshes' radii and sA, sB the farthest
 *   any of their points moves (|t1 - t0| + r theta), plus 2^-36 of the
 *   coordinates' magnitude for the rounding of the placements; then
 *   @c hit->feature is #NOCT_SWEEP_NEAR and @c hit->time when they came
 *   that near. It tests at most about 25 000 placements, each rotating a
 *   copy of the mesh (O(V log V) time and memory), so it is slow for
 *   large meshes that pass near each other; most pairs end at the first
 *   test. With a surface the distance is the one of noctDistance() (its
 *   triangles'), so the level stays conservative.
 * @param[in]  a        The first mesh.
 * @param[in]  xa0,xa1  Its start and end transforms.
 * @param[in]  b        The second mesh (may be @p a).
 * @param[in]  xb0,xb1  Its start and end transforms.
 * @param[out] colliding Receives the verdict on #NOCT_OK.
 * @param[out] hit      Receives when and how, or NULL.
 * @param[in,out] stats Counters to add this test's work to, or NULL.
 * @param[out] err      Receives the details of a failure, or NULL.
 * @pre @p a, @p xa0, @p xa1, @p b, @p xb0, @p xb1 and @p colliding are
 *      not NULL.
 * @return #NOCT_OK; the failures of noctTransformCheck() for a bad
 *         transform; #NOCT_ERR_DEGENERATE (or another mesh status) if
 *         rounding the rotated vertices made a mesh degenerate;
 *         #NOCT_ERR_NOMEM.
 */
NOCT_API noctStatus noctCollideSweptTransformed(const noctMesh *a, const noctTransform *xa0,
                                                const noctTransform *xa1, const noctMesh *b,
                                                const noctTransform *xb0,
                                                const noctTransform *xb1, bool *colliding,
                                                noctSweepHit *hit, noctNarrowStats *stats,
                                                noctError *err);

/** @brief A triangle's corners when a distance has none
 *  (noctDistanceResult). */
#define NOCT_NO_TRIANGLE UINT32_MAX

/**
 * @brief How far apart two placed solids are, with a proof
 *        (noctDistance()).
 *
 * The distance of two closed solids is the least distance between a point
 * of one and a point of the other: 0 when they meet (touching, crossing or
 * one inside the other), else the distance between their boundaries. It
 * is a real number that doubles seldom hold; the result brackets it:
 * `lower <= distance(true) <= upper`, both proved in floating point, and
 * `distance` is a value in [lower, upper].
 *
 * A surface (mesh.h) is the union of its triangles: the distance of a
 * surface and another shape is the least distance between their point
 * sets, 0 when they meet as the narrowphase's module text says (a surface
 * inside a solid meets it; a solid inside a closed surface is as far
 * from it as from its walls), else the distance between the surface's
 * triangles and the other's boundary; the points lie on the named
 * triangles as for solids.
 */
typedef struct noctDistanceResult {
    double distance;      /**< The distance, in [lower, upper]: the
                               distance between the two points (as
                               computed in floating point), or 0 when the
                               solids meet; INFINITY when @c beyond. */
    double lower;         /**< A proved lower bound on the distance:
                               the least, over the triangle pairs that
                               could be nearest, of the largest gap
                               between their projections on the
                               separating axes that hold the direction
                               between their nearest points (on the
                               convex path: the gap between the two
                               meshes' vertices on the direction between
                               the points), less an allowance for its
                               rounding. 0 when the solids meet. */
    double upper;         /**< A proved upper bound: the distance between
                               the two points, rounded up and grown by an
                               allowance for the rounding of the points
                               themselves (each lies within 2^-48 of the
                               coordinates' magnitude of its triangle);
                               0 when the solids meet; INFINITY when
                               @c beyond. */
    double point_a[3];    /**< A point of the first solid's boundary
                               nearest the second (within the allowance
                               above), in world coordinates. When they
                               meet: the centre of the overlap of their
                               placed bounding boxes, which need not lie
                               in either (noctCollideContact() tells
                               where they touch). */
    double point_b[3];    /**< The point of the second solid nearest
                               point_a, likewise. */
    uint32_t triangle_a[3]; /**< The first mesh's triangle holding
                               point_a, by its vertices' indices (as
                               noctMeshCreate() numbered them, counter-
                               clockwise seen from outside), or
                               #NOCT_NO_TRIANGLE three times when they
                               meet or are beyond. */
    uint32_t triangle_b[3]; /**< The second mesh's triangle holding
                               point_b, likewise. */
    bool colliding;       /**< The solids meet, decided exactly (as
                               #NOCT_ACCURACY_EXACT decides it). */
    bool beyond;          /**< They are proved farther apart than the
                               call's max_distance, and the search
                               stopped: lower is max_distance, distance
                               and upper are INFINITY, and there are no
                               points (zeros). */
} noctDistanceResult;

/**
 * @brief The distance between two placed meshes, their nearest points,
 *        and a proved interval that holds it.
 *
 * Each mesh is placed as noctCollideTransformed() places it (its vertices
 * fl(fl(R v) + t)), though no rotated copy is made: the searches read the
 * rotated vertices with the mesh's own hierarchy refitted to them.
 *
 * Two paths. **Convex:** when both meshes are convex (noctMeshIsConvex(),
 * a box primitive, or a solid of more than 32 vertices all on its hull;
 * never a surface),
 * GJK finds the nearest points of the hulls of the placed vertices; each
 * is moved onto the nearest triangle of its mesh, and the direction
 * between them proves the lower bound (every solid lies in the hull of
 * its vertices, so their projections on it are at least that far apart).
 * The proof also shows the solids apart, so no collision test is needed.
 * Two boxes (noctMeshCreateBox() meshes, or any mesh of 8 vertices that
 * is a box up to rounding) find their nearest features in closed form
 * instead of GJK, proved the same way, and overlapping ones are shown to
 * meet by the separating-axis proof on their turned boxes.
 * If GJK does not settle, the hulls (nearly) meet, or the proved interval
 * is wider than the accuracy below, the general path answers instead.
 * **General:** the two bounding-volume hierarchies are searched depth
 * first, the nearer pair of boxes first, pruning node and triangle pairs
 * whose boxes are no nearer than the best distance so far; then the
 * lower bound is proved over the triangle pairs within reach of it (each
 * pair's proof stops as soon as it reaches the least bound so far). The
 * exact collision test runs first when the placed boxes overlap deeply
 * (one's centre in the other), else only when the search cannot prove the
 * boundaries apart or one placed box lies in the other; placed boxes
 * apart need none.
 *
 * **Accuracy.** `lower <= true distance <= upper`, always, and
 * `upper - lower` is at most a few roundings of the coordinates: at most
 * 2^-40 of the largest magnitude of the two placed bounding boxes' corners
 * (or of the distance, if larger). So `distance` is within that of the
 * true distance, at any scale the meshes allow (a mesh 1e-100 across or
 * placed 2^40 from the origin: the error is relative to its coordinates,
 * not to the distance between them, as for every floating-point
 * distance). Touching solids give 0 exactly. The answer does not depend on
 * the order of the two meshes: swapping them swaps the points and keeps
 * every number.
 *
 * **Cost.** Convex path: a few GJK iterations, each a scan of both
 * meshes' vertices, then a scan of the triangles at the nearest vertices
 * and one of all vertices for the proof (about a microsecond for two
 * turned boxes). General path: rotating the vertices and refitting the
 * hierarchy of each turned mesh (linear in its size), then a walk of the
 * hierarchies near their nearest triangles, and a second walk within the
 * reach of the best distance for the proof (some hundreds of
 * microseconds for two turned 1000-triangle meshes; docs/results.md,
 * "Distance"). A finite @p max_distance lets the search stop once it
 * proves the meshes farther apart (a planner's "is the arm within 0.3 of
 * anything").
 * @param[in]  a            The first mesh.
 * @param[in]  xa           Its transform.
 * @param[in]  b            The second mesh (may be @p a).
 * @param[in]  xb           Its transform.
 * @param[in]  max_distance Where the search may stop: 0 or more, or
 *                          INFINITY for no limit.
 * @param[out] result       Receives the answer on #NOCT_OK.
 * @param[in,out] stats     Counters to add this test's work to, or NULL.
 * @param[out] err          Receives the details of a failure, or NULL.
 * @pre @p a, @p xa, @p b, @p xb and @p result are not NULL.
 * @post On #NOCT_OK, @p *result is as #noctDistanceResult says: either
 *       @c beyond and the true distance exceeds @p max_distance, or
 *       lower <= distance <= upper bracket the true distance within the
 *       accuracy above.
 * @return #NOCT_OK; the failures of noctTransformCheck() for a bad
 *         transform; #NOCT_ERR_NONFINITE or #NOCT_ERR_INVALID for a NaN or
 *         negative @p max_distance; #NOCT_ERR_DEGENERATE (or another mesh
 *         status) if rounding the rotated vertices brought a triangle near
 *         noctMeshCreate()'s tolerance and the rotated mesh it then makes
 *         is refused; #NOCT_ERR_NOMEM.
 */
NOCT_API noctStatus noctDistance(const noctMesh *a, const noctTransform *xa, const noctMesh *b,
                                 const noctTransform *xb, double max_distance,
                                 noctDistanceResult *result, noctNarrowStats *stats,
                                 noctError *err);

/** @brief At most this many contact points (#noctContact). */
#define NOCT_CONTACT_POINTS 4

/** @brief What a #noctContact holds: which of its fields mean what. */
typedef enum noctContactKind {
    NOCT_CONTACT_NONE,      /**< The solids share no point: no contact
                                 (a world at the box or convex level, or
                                 continuous detection whose pair touched
                                 during the step but not at its end, lists
                                 such pairs; or an object of the pair was
                                 removed since the step). Every number is
                                 0 and @c count is 0. */
    NOCT_CONTACT_CONVEX,    /**< Both shapes convex (a convex mesh, a
                                 box-shaped mesh, a box primitive): the
                                 normal and depth are the minimum
                                 translation, the points lie in the
                                 overlap. */
    NOCT_CONTACT_CROSSING,  /**< A shape is not convex and the boundaries
                                 meet: the points lie where they meet, the
                                 normal is a weighted mean of the crossing
                                 triangles' normals, the depth is not
                                 computed (0). */
    NOCT_CONTACT_CONTAINED  /**< A shape is not convex and one solid lies
                                 inside the other with no boundary
                                 meeting: one point (a vertex of the inner
                                 solid), the normal from centre to centre,
                                 no depth (0). */
} noctContactKind;

/**
 * @brief Where and how deep two colliding placed solids overlap
 *        (noctCollideContact(), noctWorldContacts()).
 *
 * The first object is A, the second B; all in world coordinates.
 *
 * **Convex shapes** (#NOCT_CONTACT_CONVEX). @c normal and @c depth are
 * the minimum translation: moving B by `depth * normal` leaves the two
 * touching (their interiors apart), and no shorter translation does. They
 * come from the separating-axis test over every candidate axis: each
 * triangle normal of A and of B, and the cross product of each edge of A
 * with each edge of B that spans a face of the Minkowski difference (the
 * arcs of the two edges' face normals cross on the Gauss map; edges
 * between coplanar triangles are not edges); the depth is the least
 * overlap of the two solids' projections over these axes, which for two
 * convex polyhedra is the penetration depth. It is computed in floating
 * point from the placed vertices (a box-shaped mesh or box primitive is
 * the hull of its 8 corners), so it is within a few roundings of the
 * coordinates' magnitude of the true value: about 1e-15 of the largest
 * coordinate of the placed boxes (tested against brute force to 1e-12
 * of it). Cost: O(Ea Eb) for the edge pairs plus O((Fa + Fb + K) (Va +
 * Vb)) for the axes kept, for meshes of E edges, F triangles and V
 * vertices: meant for the small convex shapes of games and robots.
 *
 * The candidate points are the vertices of the overlap of A and B: each point
 * where an edge of one crosses a triangle of the other, and each vertex of
 * one inside the other (decided exactly); and, when the minimum is an
 * edge pair's axis, the middle of the closest points of the two edges
 * that support the overlap along it (the deepest point of an edge
 * across an edge, which is no vertex of the overlap), if it lies in both
 * solids (decided exactly). Each is then moved along the
 * normal to the middle of the overlap's chord through it (the segment of
 * the line through it along @c normal that lies in both solids, clipped
 * by the placed triangles' planes), and that chord's length is its
 * @c point_depth: for two boxes resting face on face, the corners of the
 * overlap rectangle half way through it, each with the full depth; for a
 * corner poking into a face, the corner pushed back half its depth. The
 * points are then reduced to at most #NOCT_CONTACT_POINTS as Box2D and
 * Jolt reduce manifolds, in the plane normal to @c normal: the deepest
 * first (of those within the tolerance below of the deepest, the one
 * farthest from the candidates' mean), then the one farthest from it,
 * then the one spanning the largest triangle with those two, then the one
 * that adds the most area to that triangle; points within the tolerance
 * below of one kept are dropped.
 *
 * **Non-convex shapes** (#NOCT_CONTACT_CROSSING): the candidate points are
 * where the boundaries meet: each point where an edge of a triangle of A
 * crosses a triangle of B that it meets, and vice versa (the ends of the
 * segments along which the boundary triangles intersect; for coplanar
 * triangles, the corners of their overlap), reduced as above, the first
 * being the one farthest from the candidates' mean. @c normal is the
 * length-weighted mean of (n_A - n_B) over the pairs of triangles that
 * meet, n_A and n_B their unit outward normals and the weight the length
 * of the pair's intersection segment (unweighted if every length is 0;
 * the centre-to-centre direction if the sum vanishes; +z if that does
 * too), normalized: from A towards B, as A's outward normal and the
 * opposite of B's are at the contact. @c depth and @c point_depth are 0:
 * not computed (no minimum translation is computed for non-convex
 * solids).
 *
 * **Surfaces** (mesh.h) are never convex: a pair with a surface has a
 * #NOCT_CONTACT_CROSSING contact where its triangles meet the other's
 * (n_A and n_B are then the triangles' normals as their corners run: a
 * surface's orientation is its polygons', perhaps inconsistent, so the
 * normal is only as meaningful as that orientation), or, for a surface
 * that lies wholly inside a solid, #NOCT_CONTACT_CONTAINED as below (the
 * surface is the inner shape; a solid is never inside a surface).
 *
 * **Containment.** Of convex shapes: as above (the points are then the
 * inner solid's vertices, each mid-way along its chord through the inner
 * solid; @c depth the translation that takes the inner one out);
 * @c contained is true. Of non-convex shapes, #NOCT_CONTACT_CONTAINED:
 * one point, the first vertex (as numbered by noctMeshCreate()) of the
 * inner solid as placed, which lies in both; @c normal the unit vector
 * from A's centre (the mean of its hull's vertices, placed) to B's (+z if
 * they coincide); @c depth 0 (not computed).
 *
 * **Tolerance.** Points are computed in floating point, so a point lies
 * in both closed solids only up to rounding: each lies within
 * 2^-30 M (about 1e-9 M) of each solid, M being the largest magnitude of
 * a coordinate of the two placed bounding boxes (the tests check this
 * bound; the error seen is nearer 1e-15 M). The normal is a unit vector
 * within rounding (|1 - |normal|| < 1e-12).
 */
typedef struct noctContact {
    noctContactKind kind;     /**< Which of the cases above. */
    double normal[3];         /**< Unit vector from A towards B (see
                                   above); 0 with #NOCT_CONTACT_NONE. */
    double depth;             /**< The penetration depth along @c normal
                                   (#NOCT_CONTACT_CONVEX; 0 for touching
                                   solids); 0 otherwise: not computed. */
    bool contained;           /**< The boundaries do not meet: one solid
                                   lies inside the other. */
    unsigned count;           /**< Contact points, 0 to
                                   #NOCT_CONTACT_POINTS (0 only with
                                   #NOCT_CONTACT_NONE). */
    double points[NOCT_CONTACT_POINTS][3]; /**< The points, the first
                                   @c count of them, as above. */
    double point_depth[NOCT_CONTACT_POINTS]; /**< Each point's depth: the
                                   length of the overlap's chord along
                                   @c normal through it
                                   (#NOCT_CONTACT_CONVEX); 0 otherwise. */
} noctContact;

/**
 * @brief Decide exactly whether two placed meshes collide, and if they
 *        do, where and how deep.
 *
 * The verdict is noctCollideTransformed()'s at #NOCT_ACCURACY_EXACT. When
 * the solids collide, @p contact receives the contact #noctContact
 * describes: for two convex shapes, the minimum translation (normal and
 * depth) and up to four points of the overlap; for others, points where
 * the boundaries meet and a mean normal. A program that needs only the
 * verdict should call noctCollide(): the contact costs a walk of every
 * pair of triangles that meet, and for convex shapes the separating-axis
 * search (see #noctContact). The contact, unlike the verdict, depends on
 * the order of the two meshes: swapping them turns the normal round.
 * @param[in]  a         The first mesh.
 * @param[in]  xa        Its transform.
 * @param[in]  b         The second mesh (may be @p a).
 * @param[in]  xb        Its transform.
 * @param[out] colliding Receives the verdict on #NOCT_OK.
 * @param[out] contact   Receives the contact on #NOCT_OK (kind
 *                       #NOCT_CONTACT_NONE, count 0, when they do not
 *                       collide).
 * @param[out] err       Receives the details of a failure, or NULL.
 * @pre @p a, @p xa, @p b, @p xb, @p colliding and @p contact are not NULL.
 * @post On #NOCT_OK, @p *colliding is the exact verdict, and
 *       @c contact->kind is #NOCT_CONTACT_NONE exactly when it is false.
 * @return #NOCT_OK; the failures of noctTransformCheck() for a bad
 *         transform; #NOCT_ERR_DEGENERATE (or another mesh status) if
 *         rounding the rotated vertices made a mesh degenerate;
 *         #NOCT_ERR_NUMERIC if no ray could decide a point's containment;
 *         #NOCT_ERR_NOMEM.
 */
NOCT_API noctStatus noctCollideContact(const noctMesh *a, const noctTransform *xa,
                                       const noctMesh *b, const noctTransform *xb,
                                       bool *colliding, noctContact *contact, noctError *err);

/**
 * @brief Return the name of an accuracy level.
 * @param[in] accuracy A level.
 * @return The level's name: "box", "convex", "exact" or "continuous";
 *         "unknown" for another value.
 */
NOCT_API const char *noctAccuracyName(noctAccuracy accuracy);

#ifdef __cplusplus
}
#endif

/** @} */
#endif /* NOCTREE_NARROWPHASE_H */
