/* SPDX-License-Identifier: MIT */
/**
 * @file noctree/query.h
 * @brief Questions a program asks a world between steps: which objects
 * meet a box, contain a point, meet a shape, and where a segment hits.
 *
 * @defgroup noctree_query World queries
 * @brief Box, point, shape and ray queries over a world's objects, exact.
 *
 * Each query looks up candidates in the world's octree (the boxes of
 * noctBroadphaseQueryBox() and noctBroadphaseRayCast()) and decides each
 * on the object's placed shape, as the world's pair test would (its
 * placed vertices are fl(fl(R v) + t), transform.h):
 * - noctWorldQueryPoint(): the objects whose closed solids contain a
 *   point, decided exactly (a point on a face, an edge or a vertex is
 *   inside);
 * - noctWorldQueryBox(): the objects whose placed shapes meet a closed
 *   axis-aligned box, at the world's accuracy (noctWorldDef::accuracy:
 *   at the box level, those whose boxes meet it);
 * - noctWorldQueryShape(): the objects that collide with a shape (a mesh
 *   or a box primitive) at a transform, exactly, without adding it to the
 *   world (a planner's "would the arm collide here?"); noctWorldQueryNear():
 *   those within a distance of it ("would it come within d?");
 *   noctWorldCastShape(): the first object a shape meets as it moves
 *   along a translation, and when (continuous detection, exact);
 * - noctWorldDistance(): how far apart two objects are;
 *   noctWorldQueryNearest(): the object nearest a shape or a point, and
 *   noctWorldQueryWithin(): every object within a distance of one, each
 *   with its distance, nearest points and a proved interval (noctDistance());
 * - noctWorldRayCast() and noctWorldRayCastClosest(): the objects a
 *   closed segment meets (noctWorldRayCastAlong(): the first along a ray
 *   given by a direction and a distance). Whether it meets a solid is decided exactly;
 *   where (the fraction along it, the point, the normal) is computed in
 *   floating point. A segment that starts in a solid hits it at fraction
 *   0, with no triangle and a zero normal.
 *
 * **Surfaces.** An object whose mesh is a surface (mesh.h,
 * noctMeshCreateSurface()) is the union of its triangles, enclosing
 * nothing, and every query treats it as that point set: a point query
 * reports it when the point lies on one of its triangles; box and shape
 * queries when they meet one of its triangles (a box or shape that lies
 * inside a closed surface does not meet it; a surface inside a query
 * shape does); a segment hits it where it first meets a triangle (a
 * segment that starts on it hits it at fraction 0), and the normal
 * given is the triangle's, turned to face the segment's start; distances
 * are between the point sets (noctDistance()). A query shape may be a
 * surface too, with the same meaning.
 *
 * **Filters.** Every query takes a noctQueryFilter (broadphase.h): an
 * object is reported when `(object category & filter.mask) != 0 &&
 * (filter.category & object mask) != 0`; noctDefaultQueryFilter() lets
 * every object through. Sensors are objects like the others here.
 *
 * **Order.** Overlap queries report objects in order of their index; a
 * ray cast, in order of fraction, ties in order of index. The results
 * depend only on the world's objects, never on its history or its tree.
 *
 * **Results.** A query calls a function for each object, which may stop
 * it by returning false. To get an array instead, pass
 * noctCollectObjects() or noctCollectRayHits() with a buffer as the
 * context: it holds the first objects up to its capacity and counts them
 * all.
 *
 * **Threads.** Queries only read the world: any number of threads may
 * query one world at once while no thread changes or steps it. A query
 * may allocate (scratch for its candidates, a rotated copy of a query
 * mesh); it frees it before it returns.
 *
 * **Limits.** Query boxes, points and segments must be finite and within
 * #NOCT_MAX_COORDINATE of the origin (#NOCT_ERR_NONFINITE,
 * #NOCT_ERR_TOO_LARGE); nothing is called then.
 * @{
 */
#ifndef NOCTREE_QUERY_H
#define NOCTREE_QUERY_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include <noctree/broadphase.h>
#include <noctree/export.h>
#include <noctree/mesh.h>
#include <noctree/status.h>
#include <noctree/transform.h>
#include <noctree/world.h>

#ifdef __cplusplus
extern "C" {
#endif

/**
 * @brief A function called for an object a query found.
 * @param context the query's context.
 * @param id the object.
 * @param user_data the object's user data.
 * @return false to stop the query.
 */
typedef bool noctObjectFcn(void *context, noctObjectId id, void *user_data);

/** @brief noctRayHit::triangle's corners when the segment starts in the
 *  solid. */
#define NOCT_NO_VERTEX UINT32_MAX

/** @brief Where a segment meets an object. */
typedef struct noctRayHit {
    noctObjectId id;    /**< The object. */
    void *user_data;    /**< Its user data. */
    double fraction;    /**< Where along the segment it first meets the
                             object's solid, in [0, 1]: 0 when it starts
                             inside. */
    double point[3];    /**< origin + fraction * translation. */
    double normal[3];   /**< The unit outward normal of the triangle it
                             enters through, at any size the shapes may
                             have (for a surface, the triangle's unit
                             normal on the side the segment comes from);
                             0 when it starts inside; see flat. */
    uint32_t triangle[3]; /**< That triangle's corners, counter-clockwise
                             seen from outside: for a mesh shape, indices
                             of its vertices as given to noctMeshCreate()
                             (or read from its file); for a box primitive,
                             its corner numbers, corner k having the +x
                             half-extent when bit 2 of k is set (else -x),
                             +y when bit 1 is, +z when bit 0 is. All
                             #NOCT_NO_VERTEX when it starts inside. */
    bool flat;          /**< The triangle it enters through has no area as
                             placed: an object far from the origin for its
                             size rounds to a flat shape, a segment or a
                             point (transform.h: vertices are placed in
                             floating point). The hit is still decided
                             exactly on that placed shape; normal is then
                             the unit vector against the segment's
                             direction, and fraction where the segment
                             passes nearest the triangle's first corner
                             (within the triangle's tiny extent of where it
                             meets it). */
} noctRayHit;

/**
 * @brief A function called for each object a segment meets.
 * @param context the ray cast's context.
 * @param hit where the segment meets it (valid during the call).
 * @return false to stop the ray cast.
 */
typedef bool noctRayHitFcn(void *context, const noctRayHit *hit);

/**
 * @brief Visit the objects whose closed solids contain point p, exactly
 *        (a surface's: p lies on one of its triangles).
 * @pre world != NULL && p != NULL && fcn != NULL; fcn does not change the
 *      world.
 * @post fcn was called for each object the filter lets through whose
 *       placed solid contains p (on its boundary counts), in order of
 *       index, until it returned false; nothing else changed.
 * @param world the world.
 * @param p the point.
 * @param filter which objects to report.
 * @param fcn called for each.
 * @param context passed to fcn.
 * @param err receives the details of a failure; may be NULL.
 * @return #NOCT_OK; #NOCT_ERR_NONFINITE or #NOCT_ERR_TOO_LARGE for a
 *         point that is not finite or beyond #NOCT_MAX_COORDINATE (no
 *         call made); #NOCT_ERR_NOMEM; #NOCT_ERR_NUMERIC if a containment
 *         count stayed ambiguous (never seen).
 */
NOCT_API noctStatus noctWorldQueryPoint(const noctWorld *world, const double p[3],
                                        noctQueryFilter filter, noctObjectFcn *fcn,
                                        void *context, noctError *err);

/**
 * @brief Visit the objects whose placed shapes meet the closed box
 * [lo, hi], at the world's accuracy.
 * @pre world != NULL && lo != NULL && hi != NULL && fcn != NULL; fcn does
 *      not change the world.
 * @post fcn was called for each object the filter lets through that meets
 *       the box, in order of index, until it returned false: exactly
 *       (their closed solids share a point) at the exact level, on the
 *       convex hulls at the convex level, on the placed boxes at the box
 *       level. A box may be flat or a point (lo == hi on some axes).
 * @param world the world.
 * @param lo the box's low corner.
 * @param hi the box's high corner.
 * @param filter which objects to report.
 * @param fcn called for each.
 * @param context passed to fcn.
 * @param err receives the details of a failure; may be NULL.
 * @return #NOCT_OK; #NOCT_ERR_NONFINITE, #NOCT_ERR_TOO_LARGE or
 *         #NOCT_ERR_INVALID (lo > hi on an axis) with no call made;
 *         #NOCT_ERR_NOMEM; #NOCT_ERR_NUMERIC.
 */
NOCT_API noctStatus noctWorldQueryBox(const noctWorld *world, const double lo[3],
                                      const double hi[3], noctQueryFilter filter,
                                      noctObjectFcn *fcn, void *context, noctError *err);

/**
 * @brief Visit the objects that collide with a shape placed at x,
 * exactly, as if it were an object of the world.
 * @pre world != NULL && x != NULL && fcn != NULL && (mesh != NULL ||
 *      half_extents != NULL); fcn does not change the world.
 * @post fcn was called for each object the filter lets through whose
 *       closed solid shares a point with the shape's (mesh, or the box
 *       primitive of half_extents when mesh is NULL) placed by x as
 *       noctWorldSetTransform() would place it, in order of index, until
 *       it returned false. The test is exact whatever the world's
 *       accuracy.
 * @param world the world.
 * @param mesh the shape, or NULL for a box primitive.
 * @param half_extents the box primitive's half-extents when mesh is NULL
 *        (as noctObjectDef::half_extents); ignored otherwise.
 * @param x where the shape is: its rotation, then its translation.
 * @param filter which objects to report.
 * @param fcn called for each.
 * @param context passed to fcn.
 * @param err receives the details of a failure; may be NULL.
 * @return #NOCT_OK; what noctWorldCreateObject() returns for a bad
 *         transform or half-extents (#NOCT_ERR_NONFINITE,
 *         #NOCT_ERR_INVALID, #NOCT_ERR_TOO_LARGE), with no call made;
 *         #NOCT_ERR_NOMEM; #NOCT_ERR_NUMERIC.
 */
NOCT_API noctStatus noctWorldQueryShape(const noctWorld *world, const noctMesh *mesh,
                                        const double half_extents[3], const noctTransform *x,
                                        noctQueryFilter filter, noctObjectFcn *fcn,
                                        void *context, noctError *err);

/**
 * @brief Visit the objects within a distance of a shape placed at x:
 * those that collide with it (exactly), and those whose triangles come
 * within margin of its, as noctWorldNear() decides it: every object within
 * margin, and none farther than margin plus twice a slack of 2^-40 of the
 * coordinates' magnitude. An object with its own margin m
 * (noctObjectDef::margin) is reported within `margin + m` instead: its
 * skin counts, as in its near pairs.
 * @pre As noctWorldQueryShape().
 * @post As noctWorldQueryShape(), for the objects within margin; with a
 *       margin of 0, its objects exactly.
 * @param world the world.
 * @param mesh the shape, or NULL for a box primitive.
 * @param half_extents the box primitive's half-extents when mesh is NULL.
 * @param x where the shape is.
 * @param margin the distance, 0 to #NOCT_MAX_COORDINATE.
 * @param filter which objects to report.
 * @param fcn called for each.
 * @param context passed to fcn.
 * @param err receives the details of a failure; may be NULL.
 * @return as noctWorldQueryShape(); #NOCT_ERR_NONFINITE or
 *         #NOCT_ERR_INVALID for a bad margin.
 */
NOCT_API noctStatus noctWorldQueryNear(const noctWorld *world, const noctMesh *mesh,
                                       const double half_extents[3], const noctTransform *x,
                                       double margin, noctQueryFilter filter,
                                       noctObjectFcn *fcn, void *context, noctError *err);

/**
 * @brief Visit the objects the closed segment from origin to
 * fl(origin + translation) meets, in order along it.
 * @pre world != NULL && origin != NULL && translation != NULL &&
 *      fcn != NULL; fcn does not change the world.
 * @post fcn was called once for each object the filter lets through that
 *       the segment meets (decided exactly), with where it first meets
 *       it, in order of fraction, ties in order of index, until it
 *       returned false. A zero translation is a point: the objects that
 *       contain it, at fraction 0.
 * @param world the world.
 * @param origin where the segment starts.
 * @param translation the segment, from origin to its end.
 * @param filter which objects to report.
 * @param fcn called for each.
 * @param context passed to fcn.
 * @param err receives the details of a failure; may be NULL.
 * @return #NOCT_OK; #NOCT_ERR_NONFINITE or #NOCT_ERR_TOO_LARGE (an end
 *         beyond #NOCT_MAX_COORDINATE) with no call made; #NOCT_ERR_NOMEM;
 *         #NOCT_ERR_NUMERIC.
 */
NOCT_API noctStatus noctWorldRayCast(const noctWorld *world, const double origin[3],
                                     const double translation[3], noctQueryFilter filter,
                                     noctRayHitFcn *fcn, void *context, noctError *err);

/**
 * @brief The first object the closed segment from origin to
 * fl(origin + translation) meets.
 * @pre world != NULL && origin != NULL && translation != NULL && hit !=
 *      NULL && found != NULL
 * @post *found tells whether the segment meets an object the filter lets
 *       through; if so, *hit is the first of noctWorldRayCast()'s hits
 *       (the least fraction, ties to the least index). It visits only the
 *       objects whose boxes the segment enters before that hit (within
 *       rounding), so a long ray through a crowd costs little more than
 *       a short one.
 * @param world the world.
 * @param origin where the segment starts.
 * @param translation the segment, from origin to its end.
 * @param filter which objects to report.
 * @param hit receives the first hit.
 * @param found receives whether there is one.
 * @param err receives the details of a failure; may be NULL.
 * @return as noctWorldRayCast().
 */
NOCT_API noctStatus noctWorldRayCastClosest(const noctWorld *world, const double origin[3],
                                            const double translation[3],
                                            noctQueryFilter filter, noctRayHit *hit,
                                            bool *found, noctError *err);

/**
 * @brief The first object a ray meets: from origin along direction, up to
 * distance; a ray cast for programs that hold a direction and a length.
 * @pre world != NULL && origin != NULL && direction != NULL && hit != NULL
 *      && found != NULL
 * @post As noctWorldRayCastClosest() with the translation distance * u,
 *       where u is direction made unit (scaled first, so that any finite
 *       non-zero vector, however small or large, gives its direction);
 *       hit->fraction is then a fraction of distance. Nothing is called
 *       and *found is false on failure.
 * @param world the world.
 * @param origin where the ray starts.
 * @param direction its direction: any finite vector but zero.
 * @param distance how far it goes: finite, 0 or more.
 * @param filter which objects to report.
 * @param hit receives the first hit.
 * @param found receives whether there is one.
 * @param err receives the details of a failure; may be NULL.
 * @return as noctWorldRayCastClosest(); #NOCT_ERR_INVALID for a zero
 *         direction or a negative distance; #NOCT_ERR_NONFINITE for a
 *         direction or distance that is not finite.
 */
NOCT_API noctStatus noctWorldRayCastAlong(const noctWorld *world, const double origin[3],
                                          const double direction[3], double distance,
                                          noctQueryFilter filter, noctRayHit *hit,
                                          bool *found, noctError *err);

/** @brief Where a moving shape first meets an object
 *  (noctWorldCastShape()). */
typedef struct noctShapeHit {
    noctObjectId id;     /**< The object. */
    void *user_data;     /**< Its user data. */
    noctSweepHit sweep;  /**< When (a fraction of the translation, in
                              [0, 1]: 0 if the shape starts touching it),
                              which features (the shape's first, the
                              object's second) and where, as
                              noctCollideSwept() tells it. */
} noctShapeHit;

/**
 * @brief The first object a shape meets as it moves along a translation:
 * a swept shape query (an arm's planned move, a falling crate, a
 * character's step) with the exact verdict of continuous detection.
 *
 * The shape (a mesh, or the box primitive of half_extents when mesh is
 * NULL) is placed by x as noctWorldQueryShape() places it, and moves
 * without turning along the straight line from x's translation to
 * fl(x translation + translation), as noctCollideSwept() moves a mesh;
 * the objects stay where they are.
 * @pre world != NULL && x != NULL && translation != NULL && hit != NULL &&
 *      found != NULL; mesh != NULL or half_extents != NULL.
 * @post *found tells whether the moving shape touches an object the filter
 *       lets through; if so, *hit is the one it touches first (the least
 *       time, ties to the least index), decided exactly, its time within
 *       2^-52 (noctSweepHit). Every object whose box meets the shape's
 *       swept box is tested, so a long cast through a crowd costs the
 *       crowd.
 * @param world the world.
 * @param mesh the shape, or NULL for a box primitive.
 * @param half_extents the box primitive's half-extents when mesh is NULL.
 * @param x where the shape starts: its rotation, then its translation.
 * @param translation how it moves.
 * @param filter which objects to consider.
 * @param hit receives the first hit.
 * @param found receives whether there is one.
 * @param err receives the details of a failure; may be NULL.
 * @return as noctWorldQueryShape(); #NOCT_ERR_NONFINITE or
 *         #NOCT_ERR_TOO_LARGE for a translation, or an end, that is not
 *         finite or beyond #NOCT_MAX_COORDINATE (then *found is false).
 */
NOCT_API noctStatus noctWorldCastShape(const noctWorld *world, const noctMesh *mesh,
                                       const double half_extents[3], const noctTransform *x,
                                       const double translation[3], noctQueryFilter filter,
                                       noctShapeHit *hit, bool *found, noctError *err);

/**
 * @brief The distance between two objects of the world, as they are
 * placed now, with their nearest points and a proved interval.
 *
 * What noctDistance() gives for the two objects' shapes (a mesh, or a box
 * primitive's box) at their transforms, the first object's first: two
 * mesh objects are given to noctDistance() itself, so the answer is bit for
 * bit its answer on the objects' meshes and transforms; a box primitive is
 * its placed corners' box. An object's distance to itself is 0.
 * @pre world != NULL && result != NULL
 * @post On #NOCT_OK, *result is as #noctDistanceResult says (beyond, or
 *       lower <= true distance <= upper); nothing else changed.
 * @param world the world.
 * @param a the first object.
 * @param b the second object.
 * @param max_distance where the search may stop: 0 or more, or INFINITY.
 * @param result receives the answer.
 * @param err receives the details of a failure; may be NULL.
 * @return #NOCT_OK; #NOCT_ERR_NONFINITE (NaN) or #NOCT_ERR_INVALID
 *         (negative) for a bad max_distance; #NOCT_ERR_INVALID for a
 *         stale or unknown handle (a removed object), as
 *         noctWorldGetTransform(); #NOCT_ERR_NUMERIC (never seen).
 */
NOCT_API noctStatus noctWorldDistance(const noctWorld *world, noctObjectId a, noctObjectId b,
                                      double max_distance, noctDistanceResult *result,
                                      noctError *err);

/** @brief An object a distance query found, and how far it is. */
typedef struct noctDistanceHit {
    noctObjectId id;            /**< The object. */
    void *user_data;            /**< Its user data. */
    noctDistanceResult result;  /**< The distance: the query's shape (or
                                     point) first, the object second; for
                                     a point, point_a is the point and
                                     triangle_a #NOCT_NO_TRIANGLE. */
} noctDistanceHit;

/**
 * @brief A function called for each object a distance query found.
 * @param context the query's context.
 * @param hit the object and its distance (valid during the call).
 * @return false to stop the query.
 */
typedef bool noctDistanceHitFcn(void *context, const noctDistanceHit *hit);

/**
 * @brief The object nearest a shape placed at x, or nearest a point.
 *
 * The query is a shape (mesh, or the box primitive of half_extents when
 * mesh is NULL) placed by x as noctWorldQueryShape() places it, or, when
 * mesh and half_extents are both NULL, the point x->p (x's rotation is
 * then ignored). An object's distance is noctDistance()'s between the
 * query and the object as placed (noctWorldDistance()); a point's is its
 * distance to the object's closed solid: 0 (colliding) when the solid
 * contains it, decided exactly (as noctWorldQueryPoint()), else to its
 * boundary, with the same proved interval and accuracy (2^-40 of the
 * coordinates' magnitude) and point_b the boundary's nearest point.
 *
 * The search walks the broadphase's leaves outward from the one that
 * holds the query's centre (within a radius that grows until an object
 * is found, then within the best distance so far), testing nearer boxes
 * first and skipping cells and objects whose boxes are farther than the
 * best so far; each object's search stops once it is proved farther. It
 * never tests every object unless they are all near.
 * @pre world != NULL && x != NULL && hit != NULL && found != NULL
 * @post *found tells whether an object the filter lets through has a
 *       computed distance (noctDistanceResult::distance) at most
 *       max_distance; if so, *hit is the one of least distance, ties to
 *       the least index, with its result. The choice depends only on the
 *       objects and the query, never on the tree or its history. Objects
 *       are compared by their computed distances; every object whose true
 *       distance is within 2^-36 of the magnitude (of the query's placed
 *       box, or of the distance) of the best one's is compared, so the
 *       answer is the least of them all whenever each object's accuracy
 *       is that of coordinates no larger than 16 times the query's (an
 *       object reaching far beyond, whose own rounding is larger, may lose
 *       a near tie it would win by a hair); hit->result's points may then
 *       differ from noctWorldDistance()'s in a tie of nearest features.
 *       Nothing is found (and *found is false) on failure.
 * @param world the world.
 * @param mesh the shape, or NULL for a box primitive or a point.
 * @param half_extents the box primitive's half-extents when mesh is NULL,
 *        or NULL for a point.
 * @param x where the shape is; for a point, x->p is the point.
 * @param max_distance how far to look: 0 or more, or INFINITY.
 * @param filter which objects to consider.
 * @param hit receives the nearest object.
 * @param found receives whether there is one.
 * @param err receives the details of a failure; may be NULL.
 * @return #NOCT_OK; as noctWorldQueryShape() for a bad shape or
 *         transform; for a point, #NOCT_ERR_NONFINITE or
 *         #NOCT_ERR_TOO_LARGE (beyond #NOCT_MAX_COORDINATE);
 *         #NOCT_ERR_NONFINITE (NaN) or #NOCT_ERR_INVALID (negative) for a
 *         bad max_distance; #NOCT_ERR_NOMEM; #NOCT_ERR_NUMERIC.
 */
NOCT_API noctStatus noctWorldQueryNearest(const noctWorld *world, const noctMesh *mesh,
                                          const double half_extents[3],
                                          const noctTransform *x, double max_distance,
                                          noctQueryFilter filter, noctDistanceHit *hit,
                                          bool *found, noctError *err);

/**
 * @brief Visit every object within a distance of a shape placed at x, or
 * of a point, with its distance.
 *
 * The query and the distances are noctWorldQueryNearest()'s. An object is
 * reported when its distance search with max_distance @p distance (what
 * noctDistance(), or the point's search, gives with it) is not beyond and
 * its proved lower bound is at most @p distance: so every object whose
 * true distance is at most @p distance is reported, and none whose true
 * distance exceeds it by more than its interval's width (upper - lower,
 * at most 2^-40 of the coordinates' magnitude). In that band
 * (lower <= distance < upper) an object may be reported although its true
 * distance exceeds @p distance by less than the width: hit->result tells
 * (its lower, distance and upper). Objects whose boxes are farther than
 * @p distance (and 2^-36 of the magnitude) are not searched at all.
 * @pre world != NULL && x != NULL && fcn != NULL; fcn does not change the
 *      world.
 * @post fcn was called once for each such object the filter lets through,
 *       in order of index, until it returned false; nothing else changed.
 * @param world the world.
 * @param mesh the shape, or NULL for a box primitive or a point.
 * @param half_extents the box primitive's half-extents when mesh is NULL,
 *        or NULL for a point.
 * @param x where the shape is; for a point, x->p is the point.
 * @param distance the distance: 0 to #NOCT_MAX_COORDINATE (0: the objects
 *        that collide with the shape, or contain the point).
 * @param filter which objects to report.
 * @param fcn called for each.
 * @param context passed to fcn.
 * @param err receives the details of a failure; may be NULL.
 * @return as noctWorldQueryNearest(); #NOCT_ERR_INVALID for a distance
 *         beyond #NOCT_MAX_COORDINATE (no call made on failure before the
 *         search).
 */
NOCT_API noctStatus noctWorldQueryWithin(const noctWorld *world, const noctMesh *mesh,
                                         const double half_extents[3], const noctTransform *x,
                                         double distance, noctQueryFilter filter,
                                         noctDistanceHitFcn *fcn, void *context,
                                         noctError *err);

/** @brief An array for a query's objects: pass noctCollectObjects() as the
 *  function and a pointer to this as its context. */
typedef struct noctObjectBuffer {
    noctObjectId *ids;  /**< Room for capacity handles (NULL if 0). */
    size_t capacity;    /**< How many ids holds. */
    size_t count;       /**< Objects found: set it to 0 first; when more
                             than capacity, only the first capacity are in
                             ids (query again with a larger array). */
} noctObjectBuffer;

/**
 * @brief A #noctObjectFcn that appends to a noctObjectBuffer.
 * @pre buffer != NULL, a noctObjectBuffer
 * @post ++count; id stored at ids[count - 1] if that is within capacity.
 * @param buffer the noctObjectBuffer.
 * @param id the object.
 * @param user_data ignored.
 * @return true: the query goes on.
 */
NOCT_API bool noctCollectObjects(void *buffer, noctObjectId id, void *user_data);

/** @brief An array for a ray cast's hits: pass noctCollectRayHits() as the
 *  function and a pointer to this as its context. */
typedef struct noctRayHitBuffer {
    noctRayHit *hits;   /**< Room for capacity hits (NULL if 0). */
    size_t capacity;    /**< How many hits holds. */
    size_t count;       /**< Hits found: set it to 0 first; as
                             noctObjectBuffer::count. */
} noctRayHitBuffer;

/**
 * @brief A #noctRayHitFcn that appends to a noctRayHitBuffer.
 * @pre buffer != NULL, a noctRayHitBuffer; hit != NULL
 * @post ++count; *hit stored at hits[count - 1] if within capacity.
 * @param buffer the noctRayHitBuffer.
 * @param hit the hit.
 * @return true: the ray cast goes on.
 */
NOCT_API bool noctCollectRayHits(void *buffer, const noctRayHit *hit);

#ifdef __cplusplus
}
#endif

/** @} */

#endif /* NOCTREE_QUERY_H */
