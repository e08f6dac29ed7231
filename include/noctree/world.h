/* SPDX-License-Identifier: MIT */
/**
 * @file noctree/world.h
 * @brief The collision world: moving objects, the N-objects octree that cuts
 * the candidate pairs, simple dynamics and contact events.
 *
 * @defgroup noctree_world Collision world
 * @brief The report's collision detection system (sections 1.2, 2.2-2.4) as
 * an embeddable world.
 *
 * A world holds objects (noctObjectDef): a mesh (borrowed; it must outlive
 * the objects), a rigid transform (a rotation, then a translation: see
 * transform.h for exactly how the vertices are placed), a velocity, a
 * type (static, kinematic or moving), a collision filter, a sensor flag,
 * a margin (for the near pairs) and a pointer for the program. A program may change any of them
 * between steps (noctWorldSetTransform(), noctWorldSetVelocity(), ...);
 * the next step sees the new state, and the events follow every change:
 * a pair that a removal, a teleport, a filter or a sensor flag parted ends
 * at the next step, and one they brought together begins there. Pairs
 * that filters cannot single out can be ignored one by one
 * (noctWorldIgnorePair(); noctWorldIgnoreTouching() for every pair in
 * resting contact). A world
 * without the motion effect only detects: the program places its objects
 * and steps. noctWorldStep() runs one step:
 * 1. **motion** (effect #NOCT_EFFECT_MOTION): each moving object with a
 *    non-zero velocity moves by it, `p += v`, bit for bit (noctWorldAdd()
 *    makes `v = speed * d` once); then, with #NOCT_EFFECT_WALLS, the
 *    container's walls turn it back;
 * 2. **maintenance**: the octree is brought up to date (see below);
 * 3. **pair search**: a depth-first walk over the leaves that hold more
 *    than one object hands each pair whose boxes overlap to the
 *    narrowphase exactly once per step, at the world's accuracy
 *    (narrowphase.h). A leaf is swept (its boxes sorted on one axis)
 *    about one step in four: the sweep keeps the pairs within a margin of
 *    four steps' reach, and while no object enters or leaves the leaf and
 *    the margin lasts, only those pairs are tested; a leaf without such
 *    pairs is skipped while its boxes' least distance apart lasts. A
 *    step with a margin (noctWorldNear()) finds these pairs among the
 *    candidates of its near pairs instead, which hold every pair whose
 *    boxes overlap (and the sensors' pairs by a query of each sensor's
 *    box, in a world where at most one object in 16 is a sensor), and
 *    leaves this search out (but for N big, the exhaustive algorithm,
 *    and a step of sub-steps): the same pairs;
 * 4. **events** (#NOCT_EFFECT_EVENTS): the pairs that began and ended
 *    colliding at this step;
 * 5. **response** (#NOCT_EFFECT_RESPONSE): every moving object in at
 *    least one pair that began colliding reverses its velocity once
 *    (noctree-families(7)'s contact-begin rule; the colliding set before step 1 is
 *    empty). Sensors' pairs never turn anything.
 *
 * **Layers.** The world is built on the broadphase (broadphase.h): its
 * objects are the proxies of a broadphase it owns, with the same handles,
 * whose boxes are the meshes' boxes placed at the objects' positions
 * (noctWorldBroadphase() gives it, read-only, for queries). A step is the
 * stages above in order: motion, maintenance of the broadphase's tree,
 * the broadphase's pair search, the narrowphase on its pairs, events and
 * response.
 *
 * **The octree.** Objects are inserted into every leaf their bounding box
 * overlaps (closed boxes, cells closed on every side); a leaf splits when
 * its N+1st object small enough to be separated arrives (the overlap rule
 * below), unless it is at the maximum depth, and hands its objects to the
 * children they overlap. When an object leaves a leaf and
 * the leaf's siblings together hold N or fewer distinct objects, they merge
 * back into their parent. The root never loses an object: when a box would
 * leave it, the tree is rebuilt around a root twice as large. When every
 * object lies in one grandchild of the root (the far ones came back or
 * were removed), the next step rebuilds the tree around a root at most
 * half as large; after a growth, not for 64 sub-steps, so that objects
 * going to and fro do not rebuild the tree at every step.
 *
 * **N and the maximum depth** are the world's unless a program gives
 * them (noctWorldDef, #NOCT_AUTO by default): its broadphase chooses them
 * whenever it builds the tree, and builds it again when the number of
 * objects has changed by a factor of 4 since (noctree_broadphase(3), "Settings":
 * N is 128; the depth follows the objects' sizes against the root's). The
 * choice changes neither the pairs nor the events, only the time and
 * memory a step takes; noctBroadphaseGetSettings() on
 * noctWorldBroadphase() tells what is in force. Whether objects move is
 * not an input: on the mostly static family (nine in ten static) the
 * best N is where it is for the gas that moves (docs/results.md).
 *
 * **The overlap rule: bounded work whatever the objects share.** A leaf
 * splits only for objects that a split can separate: it splits when more
 * than N of its objects have boxes no longer, on any axis, than half the
 * leaf's size (they fit in a child), and only below the maximum depth.
 * Larger objects are listed in the leaf but do not count: objects that
 * overlap (a stack at one point, a pile of touching boxes, faces shared)
 * can never be parted by a split, and splitting for them would only
 * multiply the leaves over their overlap down to the maximum depth. So:
 * - every leaf below the maximum depth holds at most N objects smaller
 *   than half its size, and so at most N^2/2 candidate pairs of them;
 * - an object is in at most 27 leaves of its own size or larger, plus the
 *   leaves that splits for smaller objects around it made;
 * - adding an object costs the depth of the tree plus the leaves it
 *   enters (no leaf is searched for it), and removing it from a leaf
 *   costs O(1) plus any merge; a leaf's pairs are found by a sweep, so a
 *   crowded leaf costs its objects times log of them plus its near pairs.
 * Adding n coincident objects takes time and memory linear in n, and
 * stepping them, linear in n plus their n(n-1)/2 colliding pairs.
 *
 * **Maintenance modes.** #NOCT_MAINTAIN_INCREMENTAL is the report's
 * section 2.4: for each moving object and each leaf it spans, a fast test
 * for a box still inside the leaf (generalised to a box that spans
 * several leaves: it still overlaps the same cells of its smallest leaf's
 * size, so that objects straddling a face stay on the fast path);
 * a leave check (remove, then merge); an
 * enter check through octGtEqNeighbor() in the quantized directions of
 * motion (octVectorToDirections()), each neighbor checked once per object
 * per step thanks to a stamp in the node. An object that moves farther in
 * one step than the size of a leaf it spans is re-inserted from the root
 * instead, so the tree is exact whatever the speeds. Static objects
 * (speed 0) cost nothing. #NOCT_MAINTAIN_REBUILD rebuilds the tree every
 * step, for comparison. Setting N to #NOCT_N_EXHAUSTIVE (the report's
 * "N = big") never splits the root: the exhaustive algorithm.
 *
 * **Sub-steps.** With #NOCT_EFFECT_SUBSTEP a step may be several sub-steps
 * (each the sequence above with a fraction of the velocity); the began and
 * ended lists then hold every sub-step's events, in sub-step order, each
 * sub-step's sorted, and the colliding list is the last sub-step's.
 *
 * **Continuous detection.** With the accuracy #NOCT_ACCURACY_CONTINUOUS,
 * a step asks whether objects *came into contact during their motion*:
 * each object's step goes from where the last step left it (or where it
 * was made) to where the step leaves it, whatever moved it (its velocity,
 * its track, or noctWorldSetTransform() between steps), along the
 * straight line between the two translations, and a pair is colliding at
 * the step if their solids share a point at some time of it, start and
 * end included: exactly as noctCollideSwept() decides it, so a thin or
 * fast object never passes through another unseen, whatever the speeds.
 * Consequences:
 * - a pair that parts during a step is still colliding at that step (it
 *   touched at its start), so it ends one step later than at the exact
 *   level; a pair that meets and parts within one step is colliding at
 *   that step, and begins and ends;
 * - noctWorldBeganHits() tells when within the step, and where, each
 *   began contact first touched;
 * - sub-steps (#NOCT_EFFECT_SUBSTEP) are not taken: they are moot;
 * - the broadphase holds each object that may move with its local box
 *   grown on every side by twice its velocity plus what a program or a
 *   track moved it since the last step (world_sweep.c says why that is
 *   enough, rounding included), so every pair whose motions may meet is
 *   tested; a mover's growth lasts while its speed does;
 * - two objects that both stay where they are are decided by the exact
 *   level; two boxes (box primitives, box meshes) are decided on their
 *   box forms first (a swept separating axis, or a collision at the end or
 *   the start), and only the rest walk their triangles; the cost, on the
 *   gas family where nothing passes through anything, is under twice the
 *   exact level's (docs/results.md).
 *
 * **Turning: conservative.** An object whose rotation changes during a
 * step (spin, a track whose keys turn, noctWorldSetTransform() with a new
 * rotation) turns along the shorter arc from its start rotation to its
 * end one while it translates; a pair with such an object is decided by
 * the conservative level of noctCollideSweptTransformed(): no contact is
 * ever missed, and a contact that does not happen is reported only for
 * objects that come within its distance bound of each other (2^-20 of
 * their sizes, or 1/1024 of how far their points move in the step,
 * whichever is larger); noctWorldBeganHits() flags such hits
 * (noctSweepHit::conservative). Its local box is grown by r theta more, r
 * the shape's farthest point from its origin and theta the turn's angle.
 * Pairs of objects that only translate stay exact.
 *
 * **Determinism.** Pair lists are sorted by object index; the same
 * operations give the same results on every run, in both builds and in
 * every maintenance mode.
 * @{
 */
#ifndef NOCTREE_WORLD_H
#define NOCTREE_WORLD_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include <stdio.h>

#include <noctree/broadphase.h>
#include <noctree/export.h>
#include <noctree/mesh.h>
#include <noctree/narrowphase.h>
#include <noctree/octree.h>
#include <noctree/status.h>
#include <noctree/transform.h>

#ifdef __cplusplus
extern "C" {
#endif

/** @brief A collision world; opaque. */
typedef struct noctWorld noctWorld;

/**
 * @brief A handle to an object of a world: the handle of the object's
 * proxy in the world's broadphase (broadphase.h).
 *
 * Handles are values. Once the object is removed its slot may be reused,
 * but with a new generation, so a stale handle is detected
 * (#NOCT_ERR_INVALID) rather than naming another object.
 */
typedef noctProxyId noctObjectId;

/** @brief Two objects, the one with the smaller index first. */
typedef noctProxyPair noctPair;

/** Most sub-steps one step may take with #NOCT_EFFECT_SUBSTEP: a step
 *  that would need more fails with #NOCT_ERR_TOO_LARGE, naming the object. */
#define NOCT_MAX_SUBSTEPS (1u << 20)

/** @brief What a world simulates: OR these into noctWorldDef::effects. */
enum noctEffect {
    NOCT_EFFECT_MOTION = 1u << 0,   /**< Objects move by their velocity. */
    NOCT_EFFECT_EVENTS = 1u << 1,   /**< Contact-begin and -end lists. */
    NOCT_EFFECT_RESPONSE = 1u << 2, /**< Contact-begin reverses directions
                                         (implies the events' bookkeeping). */
    NOCT_EFFECT_WALLS = 1u << 3,    /**< After moving, an object whose position
                                         is outside the container on an axis
                                         and still moving outward has that
                                         velocity component negated. */
    NOCT_EFFECT_SUBSTEP = 1u << 4,  /**< Split a step into k sub-steps of
                                         velocity / k, k chosen so that no
                                         object moves more than half its
                                         smallest size per sub-step (see
                                         noctWorldMaxStepRatio()); detection,
                                         events and response run at every
                                         sub-step. For scenes whose objects
                                         may otherwise pass through each
                                         other between steps. */
    NOCT_EFFECT_SPIN = 1u << 5,     /**< Moving objects turn by their angular
                                         velocity: once a step, before the
                                         motion (before the first sub-step),
                                         q becomes noctQuatCompose(angular
                                         velocity, q), and the object is
                                         placed as by noctWorldSetTransform()
                                         (a mesh shape is rotated anew each
                                         step, into the copy its step before
                                         replaced: no allocation once each
                                         has one, but for a non-convex mesh
                                         of over 32 vertices, whose hull
                                         qhull makes; a box primitive costs
                                         a few hundred instructions).
                                         Without it, angular velocities are
                                         kept but cost nothing. */
    NOCT_EFFECT_TRACK = 1u << 6     /**< Objects with a track
                                         (noctWorldSetTrack()) follow it: at
                                         each step, first, each is placed
                                         at its track's pose at the step's
                                         tick (noctWorldTick() + 1), as by
                                         noctWorldSetTransform(). Without
                                         it, tracks are kept but cost
                                         nothing, and a world without
                                         tracks pays nothing for it. */
};

/** @brief How the octree follows the objects. */
typedef enum noctMaintenance {
    NOCT_MAINTAIN_INCREMENTAL, /**< Report section 2.4, by neighbor finding. */
    NOCT_MAINTAIN_REBUILD      /**< Rebuild the whole tree every step. */
} noctMaintenance;

/** @brief Parameters of a world; fill with noctDefaultWorldDef(). */
typedef struct noctWorldDef {
    int N;                  /**< Most objects per leaf that a split could
                                 separate (1 or more; see "The octree"
                                 in noctree_world(3)), #NOCT_N_EXHAUSTIVE,
                                 or #NOCT_AUTO:
                                 chosen by the world's broadphase from
                                 what it holds (broadphase.h, Settings).
                                 Default #NOCT_AUTO. */
    int max_depth;          /**< Deepest leaf generation (1 to 40), or
                                 #NOCT_AUTO (chosen as N is); leaves
                                 there, and leaves at the finest cell size
                                 far from the origin (broadphase.h,
                                 Limits), may hold more than N. Default
                                 #NOCT_AUTO. */
    noctAccuracy accuracy;  /**< Narrowphase level. Default exact. */
    unsigned effects;       /**< #noctEffect bits. Default: motion, events
                                 and response. */
    noctMaintenance maintenance; /**< Default incremental. */
    double walls_lo[3];     /**< The container's low corner, for
                                 #NOCT_EFFECT_WALLS. Default 0. */
    double walls_hi[3];     /**< The container's high corner. Default 0. */
    double margin;          /**< Distance within which two objects are
                                 "near" (noctWorldNear()), on top of
                                 their own margins
                                 (noctObjectDef::margin): 0 (the
                                 default), in a world whose objects
                                 have no margins either, keeps no near
                                 pairs and costs nothing; at most
                                 #NOCT_MAX_COORDINATE. */
} noctWorldDef;

/** @brief How an object moves. */
typedef enum noctObjectType {
    NOCT_OBJECT_STATIC,    /**< Never moved by the world; a program may
                                still set its transform (a teleport). */
    NOCT_OBJECT_KINEMATIC, /**< Moved only by the program, with
                                noctWorldSetTransform(); its velocity is
                                kept for the program but not used. */
    NOCT_OBJECT_MOVING     /**< Moved by the world's motion effect by its
                                velocity, and reversed by the response. */
} noctObjectType;

/**
 * @brief How an object's motion is tested: at the world's accuracy, or
 *        continuously whatever the world's (noctObjectDef::quality).
 *
 * Continuous detection costs where objects move (noctree_world(3), "Continuous
 * detection"); a program can give it to the few objects that need it
 * (a thrown tool, a fast arm link: Box2D's bullets, Jolt's linear-cast
 * motion quality) in a discrete world, or take it from objects that
 * need none in a continuous one.
 */
typedef enum noctMotionQuality {
    NOCT_QUALITY_WORLD,      /**< As the world's accuracy says: continuous
                                  in a world of #NOCT_ACCURACY_CONTINUOUS,
                                  discrete otherwise. */
    NOCT_QUALITY_DISCRETE,   /**< Tested where each step leaves it, at the
                                  world's accuracy (the exact level in a
                                  continuous world). */
    NOCT_QUALITY_CONTINUOUS  /**< Swept: its pairs are decided over its
                                  motion during the step, as a continuous
                                  world decides them, whatever the world's
                                  accuracy. */
} noctMotionQuality;

/**
 * @brief Everything an object is made with; fill with
 *        noctDefaultObjectDef(), then set what differs.
 */
typedef struct noctObjectDef {
    const noctMesh *mesh;    /**< Its shape, borrowed: it must outlive the
                                  object; any number of objects may share
                                  it. A convex mesh is a convex polytope:
                                  the narrowphase uses its convexity. A
                                  surface (noctMeshCreateSurface()) is the
                                  union of its triangles, enclosing
                                  nothing: the object's pairs, events,
                                  sensors, margins, distances, contacts,
                                  continuous detection and queries all
                                  take it as that point set
                                  (narrowphase.h). NULL for a box
                                  primitive (half_extents). */
    double half_extents[3];  /**< With no mesh, the object is a box
                                  primitive with these half-extents,
                                  centred on its position: a few dozen
                                  bytes, no mesh (one is made, and kept
                                  while the rotation lasts, only for the
                                  rare pairs whose exact test needs its
                                  triangles; at the convex level, for
                                  every pair it tests, since GJK reads the
                                  vertices). Its placed corners are those
                                  of transform.h, so it collides exactly as
                                  the mesh of its corners would. Finite,
                                  at least DBL_MIN, the least at least
                                  2^-29 of the largest, and its corners as
                                  turned within #NOCT_MAX_COORDINATE.
                                  Default 0. */
    noctTransform transform; /**< Where it is: rotation, then translation
                                  (transform.h). Default the identity. */
    double velocity[3];      /**< Distance per step, as a vector, used bit
                                  for bit by the motion effect (a moving
                                  object). Default 0. */
    noctObjectType type;     /**< Default #NOCT_OBJECT_MOVING. */
    void *user_data;         /**< Returned by noctWorldGetUserData() and
                                  the broadphase's queries. Default NULL. */
    uint64_t category;       /**< Its category bits (not 0). Two objects
                                  are paired only if each one's category
                                  meets the other's mask. Default
                                  #NOCT_FILTER_ALL. */
    uint64_t mask;           /**< The categories it pairs with. Default
                                  #NOCT_FILTER_ALL. */
    noctQuat angular_velocity; /**< Its rotation per step, applied with
                                  #NOCT_EFFECT_SPIN to a moving object.
                                  Checked as a transform's quaternion.
                                  Default the identity (0, 0, 0, 1). */
    bool sensor;             /**< A sensor: its overlaps with objects that
                                  are not sensors are decided as collisions
                                  are, but listed apart (noctWorldSensing()
                                  and the sensor events), never in the
                                  colliding list, and never turn anything
                                  back; two sensors are never paired.
                                  Default false. */
    noctMotionQuality quality; /**< How its motion is tested. A pair is
                                  decided continuously if either object's
                                  quality is continuous (its own or, with
                                  #NOCT_QUALITY_WORLD, the world's); the
                                  other object is then taken over its own
                                  motion if it is continuous too, and at
                                  the step's end pose if not (so a bullet
                                  meets a discrete object where the step
                                  leaves that one). A world with any
                                  continuous object takes no sub-steps.
                                  Default #NOCT_QUALITY_WORLD. */
    double margin;           /**< Its own margin: a skin of this
                                  thickness around it, for the near
                                  pairs. Two objects are near when their
                                  skins come within the world's margin
                                  (noctWorldDef::margin) of each other:
                                  their pair's margin is the world's
                                  plus both of theirs (noctWorldNear()
                                  says exactly); and noctWorldQueryNear()
                                  reports the object within its query's
                                  margin plus this. Finite, 0 to
                                  #NOCT_MAX_COORDINATE. A world whose
                                  objects all have 0 pays nothing for
                                  it. Default 0. */
} noctObjectDef;

/**
 * @brief Per-stage work and time, totalled over the world's steps.
 *
 * A stage that a world's effects leave out does no work: its counters and
 * time stay zero.
 */
typedef struct noctWorldCounters {
    uint64_t steps;            /**< Steps run. */
    uint64_t substeps;         /**< Sub-steps run (#NOCT_EFFECT_SUBSTEP). */
    uint64_t moved;            /**< Object moves (motion). */
    uint64_t inside_fast;      /**< Maintenance: boxes whose leaves the
                                    fast test found unchanged: they
                                    overlap the same cells, of their
                                    smallest leaf's size, as when their
                                    leaves were last made. */
    uint64_t leaves_left;      /**< Maintenance: removals from leaves. */
    uint64_t leaves_entered;   /**< Maintenance: additions to leaves. */
    uint64_t neighbor_queries; /**< Maintenance: octGtEqNeighbor() calls. */
    uint64_t reinserts;        /**< Maintenance: fast objects re-inserted
                                    from the root. */
    uint64_t splits;           /**< Leaves split. */
    uint64_t merges;           /**< Sibling groups merged. */
    uint64_t rebuilds;         /**< Whole-tree rebuilds (rebuild mode, and
                                    root growth). */
    uint64_t leaves_visited;   /**< Pair search: leaves with 2+ objects
                                    whose pairs were searched: swept, or
                                    the near pairs their last sweep kept
                                    tested. */
    uint64_t leaves_skipped;   /**< Pair search: leaves with 2+ objects
                                    left out because at their last sweep
                                    their boxes were farther apart, pair
                                    by pair, than the objects have moved
                                    since (and none came or went). */
    uint64_t candidate_pairs;  /**< Pair search: pairs in a swept leaf,
                                    and near pairs tested; in a step that
                                    took its pairs from the margin's
                                    candidates (which visits no leaf),
                                    the pairs of the margin's kept list
                                    tested, or its candidates. */
    uint64_t tested_pairs;     /**< Pairs handed to the narrowphase. */
    uint64_t colliding_pairs;  /**< Pairs found colliding (not a sensor's
                                    pairs). */
    uint64_t events;           /**< Contact-begin plus contact-end events,
                                    and sensor events. */
    uint64_t reversals;        /**< Response: direction reversals. */
    noctNarrowStats narrow;    /**< The narrowphase's own counters; its
                                    time is the world's whole loop over
                                    the pairs whose boxes overlap, at the
                                    world's accuracy. */
    double seconds_motion;     /**< Time in motion. With incremental
                                    maintenance this includes its fast
                                    test, which runs in the motion loop
                                    on each new position. */
    double seconds_maintenance;/**< Time keeping the octree up to date
                                    (but for the fast test, above). */
    double seconds_pairs;      /**< Time in the pair search, narrowphase
                                    included. */
    double seconds_response;   /**< Time in events and response. */
} noctWorldCounters;

/**
 * @brief Return the default world parameters.
 * @return N and max_depth #NOCT_AUTO, exact accuracy, the effects motion,
 *         events and response (not walls or sub-steps), incremental
 *         maintenance.
 */
NOCT_API noctWorldDef noctDefaultWorldDef(void);

/**
 * @brief Create an empty world.
 * @param[in]  def   The parameters.
 * @param[out] world Receives the world on success, NULL otherwise.
 * @param[out] err   Receives the details of a failure, or NULL.
 * @pre @p def and @p world are not NULL.
 * @return #NOCT_OK; #NOCT_ERR_INVALID if a parameter is out of range;
 *         #NOCT_ERR_NOMEM.
 */
NOCT_API noctStatus noctWorldCreate(const noctWorldDef *def, noctWorld **world,
                                    noctError *err);

/**
 * @brief Destroy a world (not the meshes its objects use).
 * @param[in] world A world, or NULL.
 */
NOCT_API void noctWorldDestroy(noctWorld *world);

/**
 * @brief Add an object.
 * @param[in]  world     The world.
 * @param[in]  mesh      Its shape; must outlive the world.
 * @param[in]  position  Its translation.
 * @param[in]  direction Its direction of motion (ignored when @p speed is
 *                       0, and may then be anything, NaN included). A
 *                       direction within 1e-9 of unit length is used as
 *                       given, so the velocity is `speed * direction` bit
 *                       for bit, as the benchmark scenes specify; any
 *                       other finite non-zero vector, however large or
 *                       small its components, is normalized.
 * @param[in]  speed     Distance per step, 0 for a static object.
 * @param[out] id        Receives the new object's handle.
 * @param[out] err       Receives the details of a failure, or NULL.
 * @pre @p world, @p mesh, @p position, @p direction and @p id are not NULL.
 * @post On #NOCT_OK the object is in the octree; it takes part in the
 *       next step. On failure no object was added and *id is {0, 0}.
 * @return #NOCT_OK; #NOCT_ERR_NONFINITE for a NaN or infinite position or
 *         speed, or direction of a moving object; #NOCT_ERR_INVALID for a
 *         negative speed or a zero direction with a non-zero speed;
 *         #NOCT_ERR_TOO_LARGE for a position beyond #NOCT_MAX_COORDINATE or
 *         more than 2^31 objects; #NOCT_ERR_NOMEM (the octree may then have
 *         been torn down: the next noctWorldAdd() or noctWorldStep()
 *         builds it again, and noctWorldRoot() is NULL until then).
 */
NOCT_API noctStatus noctWorldAdd(noctWorld *world, const noctMesh *mesh,
                                 const double position[3],
                                 const double direction[3], double speed,
                                 noctObjectId *id, noctError *err);

/**
 * @brief Make room for more objects at once.
 *
 * The per-object arrays otherwise grow by doubling as objects come, and
 * may hold up to twice the room the objects need; a program that knows
 * how many objects it will add saves that memory and the copying.
 * @param[in]  world The world.
 * @param[in]  more  How many objects will be added beyond those there.
 * @param[out] err   Receives the details of a failure, or NULL.
 * @pre @p world is not NULL.
 * @post On #NOCT_OK, adding @p more objects grows no per-object array.
 *       On failure the world is as it was, with perhaps more room.
 * @return #NOCT_OK; #NOCT_ERR_TOO_LARGE past 2^31 objects;
 *         #NOCT_ERR_NOMEM.
 */
NOCT_API noctStatus noctWorldReserve(noctWorld *world, size_t more, noctError *err);

/**
 * @brief Return the default object definition.
 * @return No mesh and zero half-extents (one or the other must be set),
 *         the identity transform, zero velocity, no angular velocity
 *         (the identity), #NOCT_OBJECT_MOVING, no user data, every category
 *         and mask bit set, not a sensor, the world's motion quality, no
 *         margin (0).
 */
NOCT_API noctObjectDef noctDefaultObjectDef(void);

/**
 * @brief Add an object made from a definition.
 *
 * With a rotation other than the identity the world keeps a copy of the
 * mesh with its vertices rotated (noctree_transform(3), "Placement") while that
 * rotation lasts: memory and time of a mesh creation, once per rotation
 * set, none per step.
 * @param[in]  world The world.
 * @param[in]  def   The object.
 * @param[out] id    Receives the new object's handle; {0, 0} on failure.
 * @param[out] err   Receives the details of a failure, or NULL.
 * @pre @p world, @p def and @p id are not NULL.
 * @post On #NOCT_OK the object is in the octree; it takes part in the
 *       next step. On failure no object was added.
 * @return #NOCT_OK; the failures of noctTransformCheck(); a mesh status
 *         if rotating the mesh's vertices made it degenerate; for a box
 *         primitive, #NOCT_ERR_INVALID for no mesh and zero half-extents
 *         or half-extents below DBL_MIN, #NOCT_ERR_NONFINITE,
 *         #NOCT_ERR_TOO_LARGE for a corner, as turned, beyond
 *         #NOCT_MAX_COORDINATE,
 *         #NOCT_ERR_DEGENERATE for the least under 2^-29 of the largest;
 *         #NOCT_ERR_NONFINITE for a velocity that is not finite; the
 *         failures of noctQuatToMatrix() for the angular velocity;
 *         #NOCT_ERR_TOO_LARGE for more than 2^31 objects (a velocity that
 *         would carry an object beyond #NOCT_MAX_COORDINATE fails the
 *         step that would);
 *         #NOCT_ERR_INVALID for an unknown type or a category of 0;
 *         #NOCT_ERR_NONFINITE for a margin that is not finite,
 *         #NOCT_ERR_INVALID for one below 0 or beyond
 *         #NOCT_MAX_COORDINATE;
 *         #NOCT_ERR_NOMEM (as for noctWorldAdd(); and the first object
 *         with a margin makes a per-object array).
 */
NOCT_API noctStatus noctWorldCreateObject(noctWorld *world, const noctObjectDef *def,
                                          noctObjectId *id, noctError *err);

/**
 * @brief Remove an object.
 * @param[in]  world The world.
 * @param[in]  id    The object.
 * @param[out] err   Receives the details of a failure, or NULL.
 * @pre @p world is not NULL.
 * Removal never needs memory, so it cannot fail once the handle is good:
 * it removes the object whole, or (for a bad handle) changes nothing.
 * @post On #NOCT_OK the object is gone from the tree; its handle is
 *       stale. The lists of the last step are left as they were: the
 *       colliding and sensing lists still hold the object's pairs, with
 *       its now stale handle, until the next step, whose ended lists
 *       report them (with the events effect). Leaf siblings left with N or fewer objects
 *       merge (if a merge finds no memory, they stay split until the next
 *       step merges them).
 * @return #NOCT_OK, or #NOCT_ERR_INVALID for a stale or unknown handle
 *         (then nothing changed).
 */
NOCT_API noctStatus noctWorldRemove(noctWorld *world, noctObjectId id, noctError *err);

/**
 * @brief Run one step.
 * @param[in]  world The world.
 * @param[out] err   Receives the details of a failure, or NULL.
 * @pre @p world is not NULL.
 * A failed step changes nothing that a program can see but the error and
 * the counters: every object is where it was, with the velocity it had,
 * before the step (all of its sub-steps with #NOCT_EFFECT_SUBSTEP; turned
 * and placed as it was, whatever spin or a track did), the
 * colliding list is the one before the step, and the began and ended
 * lists are empty. If the octree might have been changed, it is torn
 * down and the next step builds it again (noctWorldRoot() is NULL until
 * then). The world can be stepped again, changed or destroyed; a step
 * retried once memory is to be had gives what the failed one would have.
 * @return #NOCT_OK; #NOCT_ERR_TOO_LARGE if an object would move beyond
 *         #NOCT_MAX_COORDINATE, or would need more than #NOCT_MAX_SUBSTEPS
 *         sub-steps (the message and noctError::index name the object);
 *         #NOCT_ERR_NOMEM; a narrowphase status (#NOCT_ERR_NUMERIC).
 */
NOCT_API noctStatus noctWorldStep(noctWorld *world, noctError *err);

/**
 * @brief The pairs near each other after the last step: the pairs of
 * objects that are not sensors, whose filters let them pair, and whose
 * solids come within their pair's margin d of each other, colliding ones
 * included, sorted as noctWorldColliding()'s.
 *
 * A pair's margin is the world's margin W (noctWorldDef::margin) plus
 * the two objects' own margins m_a and m_b (noctObjectDef::margin):
 * `d = W + (m_a + m_b)` in doubles (each object's margin a skin around
 * it, the pair near when the skins come within W). A world whose margin
 * and objects' margins are all 0 keeps no near pairs and pays nothing;
 * once any is not 0, a pair whose own margin is 0 is near when it
 * collides. Each object looks for its partners with its box grown by
 * W + m + M, m its margin and M the largest object margin in the world;
 * the pairs so found with a wider box (by up to twice that grow) are kept
 * from one step to the next while every object moves by less than the
 * difference, which changes no answer and takes some 8 bytes a kept pair
 * and 48 an object. As the candidates hold every pair whose boxes
 * overlap, a step that can make them (one sub-step, at most one object
 * in 16 a sensor) takes its colliding pairs from them, and the sensors'
 * by a query of each sensor's box, and leaves the octree's pair search out
 * (noctWorldStep(), stage 3; the octree is kept up to date all the same,
 * for the queries and the steps that need its search).
 *
 * Found once a step, after its last sub-step. At the box level, two
 * objects are near when their placed boxes are within d (Euclidean
 * distance, in floating point). At the convex and exact levels, when the
 * pair collides, or when a lower bound on the distance between two of
 * their placed triangles is at most d plus a slack of 2^-40 of the
 * largest coordinate of their placed boxes (or of d). The bound is proved
 * in floating point (the largest gap between the triangles' projections
 * on the separating axes that hold the direction between their closest
 * points, each gap less an allowance for its rounding), and is within a
 * few roundings of the distance. So a pair within d is always near, and
 * one farther than d by more than twice the slack never is. (Two boxes
 * that the separating-axis test proves farther apart are not near
 * without looking at their triangles.)
 * @pre world != NULL && pairs != NULL
 * @param world the world.
 * @param pairs receives the list, valid until the next noctWorldStep()
 *        (succeeded or failed) or noctWorldDestroy(), as noctWorldColliding()'s.
 * @return how many.
 */
NOCT_API size_t noctWorldNear(const noctWorld *world, const noctPair **pairs);

/**
 * @brief The pairs that became near at the last step (with
 * #NOCT_EFFECT_EVENTS; sorted).
 * @pre world != NULL && pairs != NULL
 * @param world the world.
 * @param pairs receives the list.
 * @return how many.
 */
NOCT_API size_t noctWorldNearBegan(const noctWorld *world, const noctPair **pairs);

/**
 * @brief The pairs that stopped being near at the last step, removed
 * objects' pairs included (with #NOCT_EFFECT_EVENTS; sorted).
 * @pre world != NULL && pairs != NULL
 * @param world the world.
 * @param pairs receives the list.
 * @return how many.
 */
NOCT_API size_t noctWorldNearEnded(const noctWorld *world, const noctPair **pairs);

/**
 * @brief The distances and nearest points of the near pairs
 * (noctWorldNear()): how near each is, with a proved interval.
 *
 * One result per pair of noctWorldNear(), in the same order, the pair's
 * first object first: what noctWorldDistance() gives for the two objects
 * (max_distance INFINITY), so `lower <= distance(true) <= upper` and a
 * colliding pair has 0 (noctDistanceResult). The step does not compute
 * them: the first call after a step does (a distance search per pair)
 * and keeps them until the next step, so a world whose program never asks
 * pays nothing, as for noctWorldBeganHits(). Call it before changing the
 * world: the distances are those of the objects as they are at that first
 * call (a pair one of whose objects was removed since gets distance,
 * lower and upper NaN, no points and #NOCT_NO_TRIANGLE).
 * @pre world != NULL && results != NULL && n != NULL
 * @post On #NOCT_OK, *n is noctWorldNear()'s count and *results its
 *       pairs' results (NULL when there are none), valid until the next
 *       noctWorldStep() (succeeded or failed) or noctWorldDestroy(); on
 *       failure *n is 0 and *results NULL, and a later call tries again.
 * @param world the world.
 * @param results receives the array.
 * @param n receives its length.
 * @param err receives the details of a failure; may be NULL.
 * @return #NOCT_OK; #NOCT_ERR_NOMEM; a narrowphase status
 *         (#NOCT_ERR_NUMERIC, never seen).
 */
NOCT_API noctStatus noctWorldNearDistances(noctWorld *world, const noctDistanceResult **results,
                                           size_t *n, noctError *err);

/** @brief A keyframe of a track: where an object is at a tick. */
typedef struct noctKeyframe {
    uint64_t tick;   /**< The world's tick (steps done, noctWorldTick()) at
                          which the object is here. */
    noctTransform x; /**< Its rotation and translation there. */
} noctKeyframe;

/**
 * @brief Where a track puts an object at a tick.
 *
 * Before the first keyframe, the first one's transform; from the last one
 * on, the last one's; at a keyframe's tick, that keyframe's transform, bit
 * for bit. Between keyframes k and k + 1, with
 * `s = fl((double)(tick - t_k) / (double)(t_k+1 - t_k))`:
 * - each coordinate of the position is `fl(fl(fl(1 - s) p_k) + fl(s p_k+1))`
 *   (linear interpolation, every operation rounded once, no fused
 *   multiply-add);
 * - the rotation is, when the two keyframes' quaternions are the same bit
 *   for bit, that quaternion (a track that only translates keeps its
 *   rotation exactly); otherwise the spherical linear interpolation along
 *   the shorter arc: with `d` the dot product of the two quaternions (((x x + y y) +
 *   z z) + w w) and q_k+1 negated when d < 0 (then d = -d), `q = a q_k +
 *   b q_k+1` with `a = 1 - s, b = s` when d > 0.9995 (nearly the same
 *   rotation), else `a = sin((1 - s) t) / sin(t)`, `b = sin(s t) / sin(t)`
 *   for `t = acos(d)` (the C library's acos and sin), then divided by
 *   `fl(sqrt(((x x + y y) + z z) + w w))` of itself. The shorter arc
 *   turns through half a turn at most; noctTrackAtTurns() turns through
 *   the angle a keyframe gives (noctKeyTurn).
 *
 * So the same keyframes give the same poses on every run, in both builds;
 * across C libraries the rotations between keyframes may differ in their
 * last bits.
 * @pre keys != NULL && n > 0 && x != NULL; the keyframes' ticks increase
 *      and their quaternions are unit (as noctWorldSetTrack() checks).
 * @post *x is the pose at tick.
 * @param keys the keyframes, in order of tick.
 * @param n how many.
 * @param tick the tick.
 * @param x receives the pose.
 */
NOCT_API void noctTrackAt(const noctKeyframe *keys, size_t n, uint64_t tick, noctTransform *x);

/**
 * @brief How an object turns from one keyframe to the next when the
 *        shorter arc is not what is meant (noctWorldSetTrackTurns()).
 *
 * The shorter arc, which noctTrackAt() takes, turns through at most half
 * a turn: a key of 270 degrees after one of 0 turns by -90. A turn says
 * the angle itself, any number of turns either way.
 */
typedef struct noctKeyTurn {
    double axis[3]; /**< The axis, in the world's frame (its length does not
                         matter); all zero: no turn given, the shorter
                         arc. */
    double degrees; /**< The angle the object turns through about it,
                         counterclockwise seen from its tip (720: twice
                         round). */
} noctKeyTurn;

/**
 * @brief Where a track with turns puts an object at a tick.
 *
 * As noctTrackAt(), except between keyframes k - 1 and k when turns[k]
 * has an axis: there the rotation is `noctQuatCompose(r, q_k-1)` for `r =
 * noctQuatFromAxisAngle(axis, fl(s degrees))`, the rotation of keyframe
 * k - 1 turned about the axis through the fraction s of the angle (at a
 * keyframe's tick, still that keyframe's transform bit for bit). So the
 * object turns at a steady rate through the whole angle, and arrives at
 * keyframe k's rotation within the rounding that noctWorldSetTrackTurns()
 * allows.
 * @pre keys != NULL && n > 0 && x != NULL; the keyframes' ticks increase,
 *      their quaternions are unit, and the turns' axes and angles finite
 *      (as noctWorldSetTrackTurns() checks).
 * @post *x is the pose at tick; with turns == NULL, noctTrackAt()'s.
 * @param keys the keyframes, in order of tick.
 * @param turns per keyframe, how the object turns from the one before it
 *        (turns[0] is not read), or NULL for the shorter arc everywhere.
 * @param n how many keyframes.
 * @param tick the tick.
 * @param x receives the pose.
 */
NOCT_API void noctTrackAtTurns(const noctKeyframe *keys, const noctKeyTurn *turns, size_t n,
                               uint64_t tick, noctTransform *x);

/**
 * @brief Make an object follow a track whose keyframes say how it turns
 *        (noctKeyTurn), or none.
 *
 * As noctWorldSetTrack(), with the poses of noctTrackAtTurns(). A turn
 * must lead where its keyframe says: the rotation of keyframe k - 1,
 * turned about turns[k]'s axis through its angle, is keyframe k's within
 * rounding (their quaternions' dot product at least 1 - 2^-30 in
 * magnitude: a few 1e-5 radians). And it must turn less than half a turn
 * a tick (|degrees| < 180 (t_k - t_k-1)), so that each step's turn is the
 * shorter arc between its poses, which continuous detection follows.
 * @pre world != NULL && (keys != NULL || n == 0)
 * @post As noctWorldSetTrack(); the world keeps a copy of the turns too.
 * @param world the world.
 * @param id the object.
 * @param keys its keyframes, in strictly increasing order of tick.
 * @param turns per keyframe, how the object turns from the one before it
 *        (turns[0] is not read), or NULL: then as noctWorldSetTrack().
 * @param n how many (0: no track).
 * @param err receives the details of a failure; may be NULL.
 * @return as noctWorldSetTrack(); #NOCT_ERR_NONFINITE for a turn's axis
 *         or angle that is not finite, #NOCT_ERR_INVALID for a turn that
 *         does not lead to its keyframe's rotation or turns half a turn a
 *         tick or more (the message names the keyframe).
 */
NOCT_API noctStatus noctWorldSetTrackTurns(noctWorld *world, noctObjectId id,
                                           const noctKeyframe *keys, const noctKeyTurn *turns,
                                           size_t n, noctError *err);

/**
 * @brief An object's track's turns (noctWorldSetTrackTurns()).
 * @pre world != NULL && turns != NULL
 * @post *turns points at the world's copy of the turns, one per keyframe
 *       (valid as noctWorldGetTrack()'s keyframes are), or NULL when the
 *       object has no track, its track was set without turns (or with
 *       none that gives an axis), or the handle is stale.
 * @param world the world.
 * @param id the object.
 * @param turns receives the turns.
 * @return how many (0 when *turns is NULL).
 */
NOCT_API size_t noctWorldGetTrackTurns(const noctWorld *world, noctObjectId id,
                                       const noctKeyTurn **turns);

/**
 * @brief Make an object follow a track (#NOCT_EFFECT_TRACK), or none.
 * @pre world != NULL && (keys != NULL || n == 0)
 * @post On #NOCT_OK the world keeps a copy of the keyframes; the object is
 *       placed at once at the track's pose at the current tick
 *       (noctTrackAt() at noctWorldTick(), as noctWorldSetTransform()
 *       places it), and at each step, with the effect, at the step's. With
 *       n == 0 the object has no track any more (it stays where it is).
 *       A track places the object; it does not stop it moving: a moving
 *       object also moves by its velocity after the track placed it, so
 *       objects that follow tracks are usually kinematic. On failure
 *       nothing changed.
 * @param world the world.
 * @param id the object.
 * @param keys its keyframes, in strictly increasing order of tick.
 * @param n how many (0: no track).
 * @param err receives the details of a failure; may be NULL.
 * @return #NOCT_OK; #NOCT_ERR_INVALID for a stale handle, or keyframes
 *         whose ticks do not strictly increase (the message names the
 *         keyframe); what noctWorldSetTransform() returns for a keyframe's
 *         bad transform, naming it (#NOCT_ERR_NONFINITE, #NOCT_ERR_INVALID,
 *         #NOCT_ERR_TOO_LARGE); #NOCT_ERR_NOMEM.
 */
NOCT_API noctStatus noctWorldSetTrack(noctWorld *world, noctObjectId id,
                                      const noctKeyframe *keys, size_t n, noctError *err);

/**
 * @brief An object's track.
 * @pre world != NULL && keys != NULL
 * @post *keys points at the world's copy of its keyframes (valid until the
 *       track or the object changes), NULL when it has none or the handle
 *       is stale.
 * @param world the world.
 * @param id the object.
 * @param keys receives the keyframes.
 * @return how many keyframes (0: no track, or a stale handle).
 */
NOCT_API size_t noctWorldGetTrack(const noctWorld *world, noctObjectId id,
                                  const noctKeyframe **keys);

/**
 * @brief The world's tick: how many steps it has done (failed ones not
 * counted).
 * @pre world != NULL
 * @param world the world.
 * @return the steps done.
 */
NOCT_API uint64_t noctWorldTick(const noctWorld *world);

/**
 * @brief The pairs colliding after the last step (or none before the
 *        first), sorted by (a.index, b.index).
 * @param[in]  world The world.
 * @param[out] pairs Receives a pointer to the list, valid until the next
 *                   noctWorldStep() (succeeded or failed) or
 *                   noctWorldDestroy(): no other call changes the lists
 *                   (a removed object's pairs stay until the step that
 *                   ends them).
 * @pre @p world and @p pairs are not NULL.
 * @return The number of pairs.
 */
NOCT_API size_t noctWorldColliding(const noctWorld *world, const noctPair **pairs);

/**
 * @brief The pairs of a sensor and an object that is not one whose solids
 *        shared a point after the last step, sorted as noctWorldColliding().
 * @param[in]  world The world.
 * @param[out] pairs Receives a pointer to the list, as for
 *                   noctWorldColliding().
 * @pre @p world and @p pairs are not NULL.
 * @return The number of pairs.
 */
NOCT_API size_t noctWorldSensing(const noctWorld *world, const noctPair **pairs);

/**
 * @brief The sensor pairs that began at the last step, as noctWorldBegan()
 *        for the sensing list.
 * @param[in]  world The world.
 * @param[out] pairs Receives a pointer to the list, as for
 *                   noctWorldColliding().
 * @pre @p world and @p pairs are not NULL.
 * @return The number of pairs; 0 without #NOCT_EFFECT_EVENTS or
 *         #NOCT_EFFECT_RESPONSE.
 */
NOCT_API size_t noctWorldSensorBegan(const noctWorld *world, const noctPair **pairs);

/**
 * @brief The sensor pairs that ended at the last step, as noctWorldEnded()
 *        for the sensing list.
 * @param[in]  world The world.
 * @param[out] pairs Receives a pointer to the list, as for
 *                   noctWorldColliding().
 * @pre @p world and @p pairs are not NULL.
 * @return The number of pairs; 0 without #NOCT_EFFECT_EVENTS or
 *         #NOCT_EFFECT_RESPONSE.
 */
NOCT_API size_t noctWorldSensorEnded(const noctWorld *world, const noctPair **pairs);

/**
 * @brief The pairs that began colliding at the last step, sorted (by
 *        sub-step, then by pair, with #NOCT_EFFECT_SUBSTEP).
 * @param[in]  world The world.
 * @param[out] pairs Receives a pointer to the list, as for
 *                   noctWorldColliding().
 * @pre @p world and @p pairs are not NULL.
 * @return The number of pairs; 0 without #NOCT_EFFECT_EVENTS or
 *         #NOCT_EFFECT_RESPONSE.
 */
NOCT_API size_t noctWorldBegan(const noctWorld *world, const noctPair **pairs);

/**
 * @brief The pairs that stopped colliding at the last step, sorted (by
 *        sub-step, then by pair, with #NOCT_EFFECT_SUBSTEP).
 * @param[in]  world The world.
 * @param[out] pairs Receives a pointer to the list, as for
 *                   noctWorldColliding().
 * @pre @p world and @p pairs are not NULL.
 * @return The number of pairs; 0 without #NOCT_EFFECT_EVENTS or
 *         #NOCT_EFFECT_RESPONSE.
 */
NOCT_API size_t noctWorldEnded(const noctWorld *world, const noctPair **pairs);

/**
 * @brief When and where the contacts that began at the last step first
 *        touched, with continuous detection.
 *
 * In a world whose accuracy is #NOCT_ACCURACY_CONTINUOUS, the hits of the
 * pairs noctWorldBegan() lists, in the same order: the time within the
 * step (0 at its start, 1 at its end) at which the two first touched, the
 * features that touched and a point, as noctCollideSwept() tells them for
 * the two objects' motions over the step. A pair that began without
 * either object moving (just made, or a filter changed) began at time 0,
 * #NOCT_SWEEP_START. The step does not compute them: the first call
 * after a step does (a bisection of about fifty exact tests per pair, on
 * the features that may touch first), so a world whose program never
 * asks pays nothing for them. Call it before changing the world: the
 * hits are those of the objects as they are now (a pair one of whose
 * objects was removed since gets #NOCT_SWEEP_NONE).
 * @param[in]  world The world.
 * @param[out] hits  Receives the array (valid until the next step,
 *                   change of the world or noctWorldDestroy()), NULL in a
 *                   discrete world.
 * @param[out] n     Receives the number of hits: noctWorldBegan()'s count
 *                   with continuous detection, 0 without.
 * @param[out] err   Receives the details of a failure, or NULL.
 * @pre @p world, @p hits and @p n are not NULL.
 * @return #NOCT_OK; #NOCT_ERR_NOMEM (then *n is 0).
 */
NOCT_API noctStatus noctWorldBeganHits(noctWorld *world, const noctSweepHit **hits, size_t *n,
                                       noctError *err);

/**
 * @brief The contacts of the colliding pairs: where each pair's solids
 *        meet, and for convex shapes the minimum translation.
 *
 * For each pair noctWorldColliding() lists, in the same order, its
 * contact as noctCollideContact() computes it for the two objects as
 * they are placed (#noctContact: normal from the pair's first object
 * towards its second, depth, up to four points). Box primitives are the
 * solids of their corners as the world turns them, and count as convex,
 * as do objects made with a convex or box-shaped mesh. A pair whose
 * solids share no point, which a world at the box or convex level lists
 * when their boxes or hulls meet, and continuous detection when they
 * touched during the step but not at its end, gets #NOCT_CONTACT_NONE;
 * so does a pair one of whose objects was removed since the step.
 *
 * The step does not compute them: the first call after a step does, and
 * keeps them until the next step, so a world whose program never asks
 * pays nothing for them (the step only marks them stale). Call it before
 * changing the world: the contacts are those of the objects as they are
 * when it is first called.
 * @param[in]  world    The world.
 * @param[out] contacts Receives the array (valid until the next step or
 *                      noctWorldDestroy()), NULL when there are none.
 * @param[out] n        Receives their number: noctWorldColliding()'s.
 * @param[out] err      Receives the details of a failure, or NULL.
 * @pre @p world, @p contacts and @p n are not NULL.
 * @post On #NOCT_OK, (*contacts)[i] is the contact of the i-th pair of
 *       noctWorldColliding().
 * @return #NOCT_OK; #NOCT_ERR_NOMEM or #NOCT_ERR_NUMERIC (then *n is 0).
 */
NOCT_API noctStatus noctWorldContacts(noctWorld *world, const noctContact **contacts, size_t *n,
                                      noctError *err);

/**
 * @brief The handle of the object at an index (its slot), if one lives
 *        there.
 *
 * Indices are what the world's pairs, events and a scene's objects name
 * (noctPair's `index`; a world built by noctSceneBuild() holds the
 * scene's i-th object at index i). A program that keeps only indices (a
 * tool, a log) gets the handle back here, generation included.
 * @param[in]  world The world.
 * @param[in]  index An index.
 * @param[out] id    Receives the handle of the live object there.
 * @pre @p world and @p id are not NULL.
 * @post On #NOCT_OK, noctWorldObject(world, *id, ...) succeeds.
 * @return #NOCT_OK; #NOCT_ERR_INVALID if no object lives at @p index
 *         (never made, or removed); then *id is (0, 0).
 */
NOCT_API noctStatus noctWorldObjectAt(const noctWorld *world, uint32_t index, noctObjectId *id);

/**
 * @brief Read an object's position and direction.
 * @param[in]  world     The world.
 * @param[in]  id        The object.
 * @param[out] position  Receives its position, or NULL.
 * @param[out] direction Receives its unit direction, or NULL.
 * @pre @p world is not NULL.
 * @return #NOCT_OK, or #NOCT_ERR_INVALID for a stale or unknown handle.
 */
NOCT_API noctStatus noctWorldObject(const noctWorld *world, noctObjectId id,
                                    double position[3], double direction[3]);

/**
 * @brief Move an object to a new transform at once (a teleport).
 *
 * The octree follows at once; the next step tests the object where it
 * now is, with the events of whatever it began or stopped touching. A new
 * rotation replaces the object's rotated copy of its mesh (see
 * noctWorldCreateObject()); the same rotation again costs nothing.
 * Allowed for objects of every type, between steps.
 * @param[in]  world The world.
 * @param[in]  id    The object.
 * @param[in]  x     Its new transform.
 * @param[out] err   Receives the details of a failure, or NULL.
 * @pre @p world and @p x are not NULL.
 * @post On #NOCT_OK the object is at @p x. On failure nothing changed but,
 *       for #NOCT_ERR_NOMEM, the octree may have been torn down (the
 *       next step builds it again).
 * @return #NOCT_OK; #NOCT_ERR_INVALID for a stale handle; the failures of
 *         noctTransformCheck(); a mesh status if rotating the mesh made it
 *         degenerate; #NOCT_ERR_NOMEM.
 */
NOCT_API noctStatus noctWorldSetTransform(noctWorld *world, noctObjectId id,
                                          const noctTransform *x, noctError *err);

/**
 * @brief Read an object's transform.
 * @param[in]  world The world.
 * @param[in]  id    The object.
 * @param[out] x     Receives its position and the rotation quaternion as
 *                   it was given.
 * @pre @p world and @p x are not NULL.
 * @return #NOCT_OK, or #NOCT_ERR_INVALID for a stale handle.
 */
NOCT_API noctStatus noctWorldGetTransform(const noctWorld *world, noctObjectId id,
                                          noctTransform *x);

/**
 * @brief Set an object's velocity, used bit for bit.
 * @param[in]  world    The world.
 * @param[in]  id       The object.
 * @param[in]  velocity Distance per step.
 * @param[out] err      Receives the details of a failure, or NULL.
 * @pre @p world and @p velocity are not NULL.
 * @post On #NOCT_OK a moving object moves by @p velocity from the next
 *       step; other objects keep it for when they become moving. On
 *       failure nothing changed.
 * @return #NOCT_OK; #NOCT_ERR_INVALID for a stale handle;
 *         #NOCT_ERR_NONFINITE for a component that is not finite.
 */
NOCT_API noctStatus noctWorldSetVelocity(noctWorld *world, noctObjectId id,
                                         const double velocity[3], noctError *err);

/**
 * @brief Read an object's velocity (as the response last left it).
 * @param[in]  world    The world.
 * @param[in]  id       The object.
 * @param[out] velocity Receives it.
 * @pre @p world and @p velocity are not NULL.
 * @return #NOCT_OK, or #NOCT_ERR_INVALID for a stale handle.
 */
NOCT_API noctStatus noctWorldGetVelocity(const noctWorld *world, noctObjectId id,
                                         double velocity[3]);

/**
 * @brief Change how an object moves.
 * @param[in]  world The world.
 * @param[in]  id    The object.
 * @param[in]  type  Its new type; its velocity is kept.
 * @param[out] err   Receives the details of a failure, or NULL.
 * @pre @p world is not NULL.
 * @return #NOCT_OK; #NOCT_ERR_INVALID for a stale handle or an unknown
 *         type (then nothing changed).
 */
NOCT_API noctStatus noctWorldSetType(noctWorld *world, noctObjectId id, noctObjectType type,
                                     noctError *err);

/**
 * @brief Read an object's type.
 * @param[in]  world The world.
 * @param[in]  id    The object.
 * @param[out] type  Receives it.
 * @pre @p world and @p type are not NULL.
 * @return #NOCT_OK, or #NOCT_ERR_INVALID for a stale handle.
 */
NOCT_API noctStatus noctWorldGetType(const noctWorld *world, noctObjectId id,
                                     noctObjectType *type);

/**
 * @brief Set an object's collision filter.
 *
 * Pairs that the new filter forbids end at the next step (their ended
 * events), and pairs it allows begin there.
 * @param[in]  world    The world.
 * @param[in]  id       The object.
 * @param[in]  category Its category bits, not 0.
 * @param[in]  mask     The categories it pairs with.
 * @param[out] err      Receives the details of a failure, or NULL.
 * @pre @p world is not NULL.
 * @return #NOCT_OK; #NOCT_ERR_INVALID for a stale handle or a category of
 *         0 (then nothing changed).
 */
NOCT_API noctStatus noctWorldSetFilter(noctWorld *world, noctObjectId id, uint64_t category,
                                       uint64_t mask, noctError *err);

/**
 * @brief Read an object's collision filter.
 * @param[in]  world    The world.
 * @param[in]  id       The object.
 * @param[out] category Receives its category bits, or NULL.
 * @param[out] mask     Receives its mask, or NULL.
 * @pre @p world is not NULL.
 * @return #NOCT_OK, or #NOCT_ERR_INVALID for a stale handle.
 */
NOCT_API noctStatus noctWorldGetFilter(const noctWorld *world, noctObjectId id,
                                       uint64_t *category, uint64_t *mask);

/**
 * @brief Ignore a pair of objects, or stop ignoring it.
 *
 * An ignored pair is never colliding, sensing or near, whatever its
 * filters say: it is in none of the lists of noctWorldColliding(),
 * noctWorldSensing(), noctWorldNear() and their events, and neither the
 * response nor noctWorldContacts() sees it. It is a filter of these two
 * objects only (Box2D's joint without collideConnected, Jolt's group
 * filter), for pairs that categories and masks cannot single out: a
 * robot's link and the floor it stands on, a hinge's two halves.
 * Queries (query.h) search no pairs and report both objects as before.
 * A pair colliding when it becomes ignored ends at the next step (its
 * ended event); one no longer ignored begins there if it collides.
 * Removing either object forgets the pair (a new object in its slot is
 * not ignored).
 *
 * A step pays for ignored pairs only when there are some: a binary search
 * among them for each pair whose boxes overlap.
 * @param[in]  world  The world.
 * @param[in]  a      One object.
 * @param[in]  b      The other (in either order).
 * @param[in]  ignore Whether to ignore the pair from now on.
 * @param[out] err    Receives the details of a failure, or NULL.
 * @pre @p world is not NULL.
 * @post On #NOCT_OK, noctWorldPairIgnored(world, a, b) == ignore;
 *       ignoring a pair twice, or un-ignoring one that is not ignored,
 *       changes nothing. On failure nothing changed.
 * @return #NOCT_OK; #NOCT_ERR_INVALID for a stale handle or a == b (the
 *         same object twice); #NOCT_ERR_NOMEM.
 */
NOCT_API noctStatus noctWorldIgnorePair(noctWorld *world, noctObjectId a, noctObjectId b,
                                        bool ignore, noctError *err);

/**
 * @brief Is a pair of objects ignored (noctWorldIgnorePair())?
 * @param[in] world The world.
 * @param[in] a     One object.
 * @param[in] b     The other (in either order).
 * @pre @p world is not NULL.
 * @return Whether the pair is ignored; false for a stale handle or a == b.
 */
NOCT_API bool noctWorldPairIgnored(const noctWorld *world, noctObjectId a, noctObjectId b);

/**
 * @brief Ignore every pair of objects that collide now, where they are:
 *        resting contact, so that the steps report only new contacts.
 *
 * The pairs are decided as a step's pair search and narrowphase decide
 * them (the world's accuracy, filters, no two sensors, ignored pairs
 * left out), on the objects' poses as they are: a world just built, or
 * as the last step or the program left them. Nothing moves and no event
 * is made; the pairs that the last step found colliding and are now
 * ignored end at the next step. Call it before the first step to ignore
 * the contacts a scene starts with (noctree-sim(1) `--ignore-initial`,
 * noctree-scene(5) `ignore initial`).
 * @param[in]  world The world.
 * @param[out] count Receives how many pairs became ignored (not counting
 *                   those ignored already), or NULL.
 * @param[out] err   Receives the details of a failure, or NULL.
 * @pre @p world is not NULL.
 * @post On #NOCT_OK, each pair of objects that collide at their current
 *       poses is ignored. On failure no pair became ignored.
 * @return #NOCT_OK; #NOCT_ERR_NOMEM; a narrowphase status
 *         (#NOCT_ERR_NUMERIC, never seen).
 */
NOCT_API noctStatus noctWorldIgnoreTouching(noctWorld *world, size_t *count, noctError *err);

/**
 * @brief Make an object a sensor, or not (see noctObjectDef::sensor).
 *
 * Its pairs move between the colliding and the sensing lists at the next
 * step, with an ended event in one and a began event in the other; a
 * pair with another sensor just ends (two sensors never pair).
 * @param[in]  world  The world.
 * @param[in]  id     The object.
 * @param[in]  sensor Whether it is a sensor.
 * @param[out] err    Receives the details of a failure, or NULL.
 * @pre @p world is not NULL.
 * @return #NOCT_OK, or #NOCT_ERR_INVALID for a stale handle.
 */
NOCT_API noctStatus noctWorldSetSensor(noctWorld *world, noctObjectId id, bool sensor,
                                       noctError *err);

/**
 * @brief Tell whether an object is a sensor.
 * @param[in]  world  The world.
 * @param[in]  id     The object.
 * @param[out] sensor Receives it.
 * @pre @p world and @p sensor are not NULL.
 * @return #NOCT_OK, or #NOCT_ERR_INVALID for a stale handle.
 */
NOCT_API noctStatus noctWorldGetSensor(const noctWorld *world, noctObjectId id,
                                       bool *sensor);

/**
 * @brief Set an object's own margin (see noctObjectDef::margin).
 *
 * Its near pairs follow at the next step, with their near events.
 * @param[in]  world  The world.
 * @param[in]  id     The object.
 * @param[in]  margin Its margin: finite, 0 to #NOCT_MAX_COORDINATE.
 * @param[out] err    Receives the details of a failure, or NULL.
 * @pre @p world is not NULL.
 * @post On #NOCT_OK the object's pairs have the new margin from the next
 *       step on. On failure nothing changed.
 * @return #NOCT_OK; #NOCT_ERR_INVALID for a stale handle or a margin
 *         below 0 or beyond #NOCT_MAX_COORDINATE; #NOCT_ERR_NONFINITE for
 *         a NaN or infinite one; #NOCT_ERR_NOMEM when the first margin of
 *         a world needs its per-object array.
 */
NOCT_API noctStatus noctWorldSetMargin(noctWorld *world, noctObjectId id, double margin,
                                       noctError *err);

/**
 * @brief Read an object's own margin.
 * @param[in]  world  The world.
 * @param[in]  id     The object.
 * @param[out] margin Receives it, as set (0 for none).
 * @pre @p world and @p margin are not NULL.
 * @return #NOCT_OK, or #NOCT_ERR_INVALID for a stale handle.
 */
NOCT_API noctStatus noctWorldGetMargin(const noctWorld *world, noctObjectId id,
                                       double *margin);

/**
 * @brief Set how an object's motion is tested (noctObjectDef::quality).
 * @param[in]  world   The world.
 * @param[in]  id      The object.
 * @param[in]  quality The quality.
 * @param[out] err     Receives the details of a failure, or NULL.
 * @pre @p world is not NULL.
 * @post On #NOCT_OK, the next step tests the object's motion so: from
 *       where the last step left it, if it becomes continuous.
 * @return #NOCT_OK; #NOCT_ERR_INVALID for a stale handle or an unknown
 *         quality; #NOCT_ERR_NOMEM when the first continuous object of a
 *         discrete world needs the world's per-object records of where
 *         each step starts (then nothing changed).
 */
NOCT_API noctStatus noctWorldSetMotionQuality(noctWorld *world, noctObjectId id,
                                              noctMotionQuality quality, noctError *err);

/**
 * @brief Get how an object's motion is tested.
 * @param[in]  world   The world.
 * @param[in]  id      The object.
 * @param[out] quality Receives its quality, as set.
 * @pre @p world and @p quality are not NULL.
 * @return #NOCT_OK; #NOCT_ERR_INVALID for a stale handle.
 */
NOCT_API noctStatus noctWorldGetMotionQuality(const noctWorld *world, noctObjectId id,
                                              noctMotionQuality *quality);

/**
 * @brief Set an object's angular velocity (see #NOCT_EFFECT_SPIN).
 * @param[in]  world The world.
 * @param[in]  id    The object.
 * @param[in]  q     Its rotation per step; the identity for none.
 * @param[out] err   Receives the details of a failure, or NULL.
 * @pre @p world and @p q are not NULL.
 * @post On #NOCT_OK a moving object turns by @p q each step of a world
 *       with #NOCT_EFFECT_SPIN. On failure nothing changed.
 * @return #NOCT_OK; #NOCT_ERR_INVALID for a stale handle; the failures of
 *         noctQuatToMatrix(); #NOCT_ERR_NOMEM (the first angular velocity
 *         of a world makes a per-object array).
 */
NOCT_API noctStatus noctWorldSetAngularVelocity(noctWorld *world, noctObjectId id,
                                                const noctQuat *q, noctError *err);

/**
 * @brief Read an object's angular velocity.
 * @param[in]  world The world.
 * @param[in]  id    The object.
 * @param[out] q     Receives it (the identity for none).
 * @pre @p world and @p q are not NULL.
 * @return #NOCT_OK, or #NOCT_ERR_INVALID for a stale handle.
 */
NOCT_API noctStatus noctWorldGetAngularVelocity(const noctWorld *world, noctObjectId id,
                                                noctQuat *q);

/**
 * @brief Set the pointer a program keeps with an object.
 * @param[in]  world     The world.
 * @param[in]  id        The object.
 * @param[in]  user_data Any pointer; the world never reads it.
 * @param[out] err       Receives the details of a failure, or NULL.
 * @pre @p world is not NULL.
 * @return #NOCT_OK, or #NOCT_ERR_INVALID for a stale handle.
 */
NOCT_API noctStatus noctWorldSetUserData(noctWorld *world, noctObjectId id, void *user_data,
                                         noctError *err);

/**
 * @brief Read the pointer a program keeps with an object.
 * @param[in] world The world.
 * @param[in] id    The object.
 * @pre @p world is not NULL.
 * @return The pointer, or NULL for a stale handle.
 */
NOCT_API void *noctWorldGetUserData(const noctWorld *world, noctObjectId id);

/**
 * @brief The mesh an object was made with (not its rotated copy).
 * @param[in] world The world.
 * @param[in] id    The object.
 * @pre @p world is not NULL.
 * @return The mesh, or NULL for a box primitive or a stale handle.
 */
NOCT_API const noctMesh *noctWorldGetMesh(const noctWorld *world, noctObjectId id);

/**
 * @brief A box primitive's half-extents.
 * @param[in]  world The world.
 * @param[in]  id    The object.
 * @param[out] half  Receives them.
 * @pre @p world and @p half are not NULL.
 * @return #NOCT_OK, or #NOCT_ERR_INVALID for a stale handle or an object
 *         with a mesh.
 */
NOCT_API noctStatus noctWorldGetHalfExtents(const noctWorld *world, noctObjectId id,
                                            double half[3]);

/**
 * @brief Return the number of objects.
 * @param[in] world The world.
 * @pre @p world is not NULL.
 * @return The number of live objects.
 */
NOCT_API size_t noctWorldObjectCount(const noctWorld *world);

/**
 * @brief How far the fastest object moves in a step, relative to its size.
 *
 * The report's fidelity constraint: the time-step method (as here, without
 * sub-stepping) only sees collisions if objects move little compared to
 * their sizes. Above 0.5, two such objects moving head-on can pass
 * through each other between two steps unseen.
 * @param[in] world The world.
 * @pre @p world is not NULL.
 * @return The largest speed / (smallest extent of the box) over the moving
 *         objects; 0 if none moves.
 */
NOCT_API double noctWorldMaxStepRatio(const noctWorld *world);

/**
 * @brief Copy the world's counters.
 * @param[in]  world    The world.
 * @param[out] counters Receives the totals since the world was created.
 * @pre @p world and @p counters are not NULL.
 */
NOCT_API void noctWorldGetCounters(const noctWorld *world,
                                   noctWorldCounters *counters);

/**
 * @brief Check the whole structure, for tests and debugging.
 *
 * The heavier of the two tiers of checking: walks the whole tree. Checks
 * that the octree is well formed, that every object is in exactly the
 * leaves its box overlaps and that those leaves list it once, that no leaf
 * holds more than N objects small enough to split for unless at the
 * maximum depth (the overlap rule above), that each object's record of
 * its leaves and each leaf's record of its objects point at each other,
 * and that no group of leaf siblings holds N or fewer distinct objects
 * (it should have merged; rebuild mode, the exhaustive N and merges owed
 * for want of memory aside), and that each object's mesh shape as turned
 * by its rotation is, bit for bit, the mesh noctMeshCreate() makes of the
 * turned vertices (the world refills turned copies in place). A world
 * whose octree a failure tore down
 * (see noctWorldStep()) is valid: its tree is owed.
 * @param[in]  world The world.
 * @param[out] err   Receives the first problem found, or NULL.
 * @pre @p world is not NULL.
 * @return #NOCT_OK; #NOCT_ERR_INVARIANT with a description of the first
 *         broken invariant (a library bug, or memory the program
 *         overwrote); #NOCT_ERR_NOMEM for the walk's own scratch.
 */
NOCT_API noctStatus noctWorldValidate(const noctWorld *world, noctError *err);

/**
 * @brief The octree's root, to inspect with the octree ADT (read only).
 *
 * Each node's datum is private to the world: read it with noctWorldCell()
 * and print it with noctWorldPrintCell().
 * @param[in] world The world.
 * @pre @p world is not NULL.
 * @return The root; valid until the next call that changes the world.
 *         NULL for a world without objects, or whose tree a failure tore
 *         down (the next step builds it).
 */
NOCT_API octNode *noctWorldRoot(const noctWorld *world);

/**
 * @brief The world's broadphase, read-only: its proxies are the world's
 * objects (the same handles, noctObjectId being noctProxyId), their boxes
 * the objects' placed boxes.
 *
 * Use it for the broadphase's queries (noctBroadphaseQueryBox(),
 * noctBroadphaseQueryPoint(), noctBroadphaseRayCast()) on the world's
 * objects, its counters, validation and tree. The pair list of
 * noctBroadphasePairs() is not the world's: the world's pairs are
 * noctWorldColliding().
 * @param world the world.
 * @return its broadphase.
 * @pre world != NULL
 * @post The pointer is valid while the world is; the broadphase changes
 *       with the world (each step, addition and removal).
 */
NOCT_API const noctBroadphase *noctWorldBroadphase(const noctWorld *world);

/**
 * @brief An #octItemPrinter for the nodes of noctWorldRoot()'s tree.
 *
 * Prints the node's cube and, for a leaf, the indices of its objects, for
 * example `lo (-8, -8, -8) size 8; objects 0 5 17`. Pass it to octPrint()
 * to print the N-objects octree as the report does.
 * @param[in] strm An open stream.
 * @param[in] data A node's datum from a world's tree.
 * @pre @p strm is an open FILE*; @p data is octData() of a node of a
 *      world's current tree.
 * @post The node's cube and objects are printed on one line, without a
 *       newline.
 */
NOCT_API void noctWorldPrintCell(FILE *strm, const void *data);

/**
 * @brief Read a node's cube and, for a leaf, its objects.
 * @param[in]  world   The world.
 * @param[in]  node    A node of the world's current tree (noctWorldRoot()).
 * @param[out] lo      Receives the cube's low corner, or NULL.
 * @param[out] size    Receives the cube's edge length, or NULL.
 * @param[out] objects Receives the first @p max of the leaf's objects, or
 *                     NULL when @p max is 0.
 * @param[in]  max     Room in @p objects.
 * @pre @p world and @p node are not NULL; @p node belongs to the world's
 *      current tree; @p objects is not NULL or @p max is 0.
 * @post min(result, @p max) handles are written, in the leaf's order.
 * @return The number of objects in the leaf; 0 for a split node.
 */
NOCT_API size_t noctWorldCell(const noctWorld *world, const octNode *node, double lo[3],
                              double *size, noctObjectId *objects, size_t max);

/**
 * @brief Read an object's bounding box, as placed at its position.
 * @param[in]  world The world.
 * @param[in]  id    The object.
 * @param[out] lo    Receives the box's low corner.
 * @param[out] hi    Receives the box's high corner.
 * @pre @p world, @p lo and @p hi are not NULL.
 * @return #NOCT_OK, or #NOCT_ERR_INVALID for a stale or unknown handle.
 */
NOCT_API noctStatus noctWorldObjectBox(const noctWorld *world, noctObjectId id,
                                       double lo[3], double hi[3]);

/**
 * @brief Add the report's test set t_k (noctree-families(7), THE PLANES).
 *
 * Two planes of axis-aligned unit cubes, each a central cube and @p k
 * rings, moving towards each other at speed 0.05.
 * @deprecated Use noctSceneFamily() with `planes:K` and noctSceneBuild()
 *             (scene.h), which build every family; this function builds
 *             the same objects, and goes at the next SONAME change.
 * @param[in]  world     The world.
 * @param[in]  k         Number of rings, 0 to 1000.
 * @param[in]  unit_cube A cube of edge 1 centred on the origin, such as
 *                       noctMeshCreateBox(0.5, 0.5, 0.5); must outlive the
 *                       world.
 * @param[out] err       Receives the details of a failure, or NULL.
 * @pre @p world and @p unit_cube are not NULL.
 * @post On #NOCT_OK the world holds 2 (2k + 1)^2 more objects, added left
 *       plane first, row by row; on failure, none of them (those added
 *       are removed again).
 * @return #NOCT_OK; #NOCT_ERR_INVALID for k out of range; any status of
 *         noctWorldAdd().
 */
NOCT_API noctStatus noctWorldAddPlanes(noctWorld *world, int k,
                                       const noctMesh *unit_cube, noctError *err);

/**
 * @brief The side of gas_n's cubic container, `cbrt(10 n)`.
 * @deprecated Use noctSceneFamily() with `gas:N`, whose scene has the
 *             container as its walls (noctSceneDef()); this function goes
 *             at the next SONAME change.
 * @param[in] n Number of boxes.
 * @return The container's side length Lb.
 */
NOCT_API double noctGasContainerSize(size_t n);

/**
 * @brief Add the scene gas_n (noctree-families(7), FAMILIES OF BOXES): n oriented boxes with
 *        seeded random sizes, orientations, positions and directions.
 *
 * The boxes are box primitives (noctObjectDef::half_extents) turned by
 * the scene's quaternions, whose matrices are noctree-families(7)'s bit for bit
 * (noctQuatToMatrix() computes that formula and, for these quaternions,
 * neither normalises nor snaps: all 10 000 000 were checked); room for
 * them is reserved at once (noctWorldReserve()). For the scene as
 * defined, create the world with #NOCT_EFFECT_WALLS and the container
 * `[0, noctGasContainerSize(n)]` on every axis.
 * @deprecated Use noctSceneFamily() with `gas:N` and noctSceneBuild()
 *             (scene.h), which build every family and give the world its
 *             container; this function builds the same objects, and goes at
 *             the next SONAME change.
 * @param[in]  world The world.
 * @param[in]  n     Number of boxes, 1 to 10 000 000.
 * @param[out] err   Receives the details of a failure, or NULL.
 * @pre @p world is not NULL.
 * @post On #NOCT_OK the world holds n more objects, in the scene's order;
 *       on failure, none of them.
 * @return #NOCT_OK; #NOCT_ERR_INVALID for n out of range; #NOCT_ERR_NOMEM;
 *         #NOCT_ERR_TOO_LARGE past 2^31 objects.
 */
NOCT_API noctStatus noctWorldAddGas(noctWorld *world, size_t n, noctError *err);

#ifdef __cplusplus
}
#endif

/** @} */
#endif /* NOCTREE_WORLD_H */
