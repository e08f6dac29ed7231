/* SPDX-License-Identifier: MIT */
/**
 * @file noctree/broadphase.h
 * @brief The N-objects octree on its own: a broadphase over axis-aligned
 * boxes, for programs with a narrowphase of their own.
 *
 * @defgroup noctree_broadphase Broadphase
 * @brief The N-objects octree of the report (sections 2.2-2.4) over
 * axis-aligned boxes ("proxies"), without meshes.
 *
 * A broadphase holds proxies: a closed box `[lo, hi]`, a user data
 * pointer, and a 64-bit category and mask. It answers which pairs of
 * proxies have overlapping boxes (touching counts), each pair once, and
 * box, point and segment queries. It is the layer the collision world
 * (world.h) is built on: the world's objects are proxies whose boxes are
 * their meshes' boxes placed at their positions.
 *
 * **The tree.** Each proxy is in every leaf its box overlaps. A leaf
 * splits when more than N of its proxies are at most half its size on
 * every axis (noctree_world(3), "The overlap rule"), below the maximum depth; when
 * the eight leaves under a node hold N or fewer distinct proxies they
 * merge back. The root never loses a proxy: a box that would leave it
 * makes the tree be rebuilt around a root twice as large. The first
 * proxy, or the bounds hint of noctBroadphaseDef, sizes the first root.
 *
 * **Moves.** noctBroadphaseMove() keeps the tree exact at once, so that
 * queries are right after every move. A box that still overlaps the same
 * cells of its smallest leaf's size (the report's fast test, for a box in
 * one leaf or several) costs a few comparisons; otherwise the proxy
 * leaves the leaves its box left and enters its new ones through
 * octGtEqNeighbor() (the report's leave and enter checks), or is
 * re-inserted from the root if it moved farther than its leaves are wide.
 * Proxies that are not moved cost nothing.
 *
 * **Pairs.** noctBroadphaseUpdatePairs() finds the pairs whose boxes
 * overlap and that the filters let through:
 * `(category_a & mask_b) != 0 && (category_b & mask_a) != 0`. Each pair
 * is found once, in the one leaf that owns the lower corner of the two
 * boxes' overlap, and the list is sorted by (a.index, b.index): the same
 * operations give the same pairs in the same order on every run. A leaf
 * whose proxies have not come, gone or moved closer than its last sweep's
 * margin is not swept again (see world.h, step 3).
 *
 * **Limits.** Coordinates lie within #NOCT_MAX_COORDINATE; at most 2^31
 * proxies; N and the depth as for a world. A cell is never smaller than
 * 2^-32 of the largest magnitude of its corners' coordinates (2.3e-7 at
 * 1000, 0.23 at 10^9; about 2^20 of the coordinates' ulps): far from
 * the origin a leaf of that size stays a leaf whatever it holds, as at
 * the maximum depth, so coincident or sub-ulp proxies there cost a leaf
 * of all their pairs, never a runaway split. Bad input is reported by
 * status, never by aborting, but for violated requires clauses in the
 * defensive build.
 *
 * **Settings.** N and the maximum depth are the two parameters of the
 * report's tree. Given as numbers, they are kept exactly (Table 1's
 * experiment and the tests fix N). Given as #NOCT_AUTO (the default),
 * the broadphase chooses them each time it builds its tree: when the
 * first proxy comes, when the root grows or shrinks, after a failure,
 * and when the number of proxies has grown or shrunk by a factor of 4
 * since the last choice (which then rebuilds the tree; a factor, not a
 * difference, so that a population that changes by a little never
 * rebuilds, and one that grows steadily rebuilds a logarithmic number of
 * times, in linear time in all). The choice is a pure function of the
 * proxies' boxes in their slots and the root's size, so the same
 * operations give the same tree on every run and in both builds:
 * - N is 128 whatever the proxies: measured over every scene family of
 *   the tools, at 1 000 to 1 000 000 objects and N from 5 to 128
 *   (docs/results.md, "Fast at the defaults"), the step time is flat
 *   from about N = 30 up, within the run's noise, and memory falls as N
 *   grows; small N loses up to 3 times, because leaves smaller than
 *   their boxes make every box span many leaves. (The leaves' sweeps,
 *   see Pairs, keep a large leaf cheap.) Box, point and segment queries
 *   test every box of the leaves they meet, so N = 128 costs them more
 *   than a smaller N (a segment on 100 000 boxes: 12% more instructions
 *   than at N = 30, up to twice the time); a program that mostly queries
 *   a world it seldom steps may want N = 30.
 * - max_depth comes from the proxies' sizes against the root's: a box of
 *   extent e (its largest side) can make a leaf split only while it is at
 *   most half the leaf's size, so it can bring about leaves down to the
 *   generation D(e) = 1 + max{d : e <= root 2^-(d+1)}. The maximum depth
 *   is D of the 99th percentile of the boxes, counted from the largest
 *   (1 at least, 40 at most; 40 if more than 1 in 100 are points), over
 *   all the live proxies or, beyond 4096 slots, every k-th slot for
 *   about 4096 of them. So the depth never stops 99 in 100 proxies from
 *   being separated, and coincident or crowded proxies stop splitting
 *   near their own size instead of at a fixed depth.
 *
 * noctBroadphaseGetSettings() tells what is in force. What the choice
 * does not see: between two choices the population may change by up to
 * the factor of 4, and boxes may change size, without the settings
 * following; a tree whose maximum depth became too shallow for new small
 * boxes gives the same pairs, in leaves that hold more than N.
 *
 * **Threads.** A broadphase is not thread-safe; distinct broadphases may
 * be used from distinct threads.
 * @{
 */
#ifndef NOCTREE_BROADPHASE_H
#define NOCTREE_BROADPHASE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include <noctree/export.h>
#include <noctree/octree.h>
#include <noctree/status.h>

#ifdef __cplusplus
extern "C" {
#endif

/** @brief A broadphase; opaque. */
typedef struct noctBroadphase noctBroadphase;

/**
 * @brief A handle to a proxy of a broadphase.
 *
 * Once the proxy is removed its slot may be reused, with a new
 * generation, so a stale handle is detected (#NOCT_ERR_INVALID).
 */
typedef struct noctProxyId {
    uint32_t index;      /**< Slot of the proxy. */
    uint32_t generation; /**< Generation of the slot; 0 is never valid. */
} noctProxyId;

/** @brief Two proxies whose boxes overlap, the smaller index first. */
typedef struct noctProxyPair {
    noctProxyId a; /**< The proxy with the smaller index. */
    noctProxyId b; /**< The proxy with the larger index. */
} noctProxyPair;

/** N or max_depth chosen by the broadphase itself (see "Settings" above):
 *  the default of both. */
#define NOCT_AUTO 0

/** N that never splits the root: the exhaustive algorithm ("N = big"). */
#define NOCT_N_EXHAUSTIVE 0x7fffffff

/** The category and mask a proxy gets when none is given: every bit. */
#define NOCT_FILTER_ALL UINT64_MAX

/** @brief Parameters of a broadphase; fill with noctDefaultBroadphaseDef(). */
typedef struct noctBroadphaseDef {
    int N;               /**< Most proxies per leaf that a split could
                              separate (1 or more), #NOCT_N_EXHAUSTIVE
                              (never split: every pair of proxies is a
                              candidate), or #NOCT_AUTO (chosen; see
                              Settings). Default #NOCT_AUTO. */
    int max_depth;       /**< Deepest leaf generation, 1 to 40, or
                              #NOCT_AUTO (chosen; see Settings); see also
                              the finest cell under Limits. Default
                              #NOCT_AUTO. */
    double bounds_lo[3]; /**< Bounds hint: the first root covers this box as
                              well as the proxies. Ignored unless
                              bounds_lo < bounds_hi on every axis. Default
                              0 (no hint). */
    double bounds_hi[3]; /**< The hint's high corner. Default 0. */
} noctBroadphaseDef;

/** @brief What a broadphase did, totalled since it was created. */
typedef struct noctBroadphaseCounters {
    uint64_t proxies;          /**< Live proxies now. */
    uint64_t nodes;            /**< Nodes of the tree now. */
    uint64_t leaves;           /**< Leaves of the tree now. */
    uint64_t moves;            /**< noctBroadphaseMove() calls. */
    uint64_t inside_fast;      /**< Moves and world steps that the fast
                                    test settled. */
    uint64_t leaves_left;      /**< Removals of a proxy from a leaf. */
    uint64_t leaves_entered;   /**< Additions of a proxy to a leaf. */
    uint64_t neighbor_queries; /**< octGtEqNeighbor() calls. */
    uint64_t reinserts;        /**< Proxies re-inserted from the root. */
    uint64_t splits;           /**< Leaves split. */
    uint64_t merges;           /**< Sibling groups merged. */
    uint64_t rebuilds;         /**< Whole-tree rebuilds. */
    uint64_t leaves_visited;   /**< Pair search: leaves searched. */
    uint64_t leaves_skipped;   /**< Pair search: leaves left out. */
    uint64_t candidate_pairs;  /**< Pair search: pairs considered. */
    uint64_t pairs;            /**< Overlapping pairs found, filtered. */
} noctBroadphaseCounters;

/**
 * @brief Return the default parameters.
 * @return N and max_depth #NOCT_AUTO (chosen from the proxies), no
 *         bounds hint.
 */
NOCT_API noctBroadphaseDef noctDefaultBroadphaseDef(void);

/**
 * @brief Create an empty broadphase.
 * @pre def != NULL && bp != NULL
 * @post On #NOCT_OK, *bp is a new broadphase with no proxies. Otherwise
 *       *bp is NULL and err (if not NULL) says why: #NOCT_ERR_INVALID for
 *       N < 0 or max_depth outside 0..40 (0 is #NOCT_AUTO), #NOCT_ERR_NONFINITE for a bounds
 *       hint that is not finite, #NOCT_ERR_TOO_LARGE for one beyond
 *       #NOCT_MAX_COORDINATE, #NOCT_ERR_NOMEM.
 * @param def the parameters.
 * @param bp the broadphase.
 * @param err receives the details of a failure, or NULL.
 * @return #NOCT_OK or a failure status (see the postcondition).
 */
NOCT_API noctStatus noctBroadphaseCreate(const noctBroadphaseDef *def, noctBroadphase **bp,
                                         noctError *err);

/**
 * @brief The N and maximum depth in force: as given to
 *        noctBroadphaseCreate(), or as last chosen for #NOCT_AUTO (see
 *        Settings).
 * @pre bp != NULL
 * @post *N and *max_depth (each optional, NULL for none) hold them; before
 *       the first proxy, a #NOCT_AUTO N reads 128 and a #NOCT_AUTO depth
 *       40.
 * @param bp the broadphase.
 * @param N receives N, or NULL.
 * @param max_depth receives the maximum depth, or NULL.
 */
NOCT_API void noctBroadphaseGetSettings(const noctBroadphase *bp, int *N, int *max_depth);

/**
 * @brief Free a broadphase and its tree. NULL is allowed.
 * @post bp and every handle and octNode it gave are invalid.
 * @param bp the broadphase.
 */
NOCT_API void noctBroadphaseDestroy(noctBroadphase *bp);

/**
 * @brief Add a proxy.
 * @param bp the broadphase.
 * @param lo, hi the box, closed.
 * @param user_data returned with the proxy by queries and callbacks.
 * @param category the proxy's category bits; 0 is allowed and parks it, as
 *        for noctBroadphaseSetFilter().
 * @param mask the categories it may pair with.
 * @param id receives the handle; {0, 0} on failure.
 * @param err optional error details.
 * @pre bp != NULL && lo != NULL && hi != NULL && id != NULL
 * @post On #NOCT_OK the proxy is in the tree: queries and the next
 *       noctBroadphaseUpdatePairs() see it. On failure nothing was added:
 *       #NOCT_ERR_NONFINITE (a coordinate is NaN or infinite),
 *       #NOCT_ERR_INVALID (lo > hi on an axis), #NOCT_ERR_TOO_LARGE (a
 *       coordinate beyond #NOCT_MAX_COORDINATE, or 2^31 proxies),
 *       #NOCT_ERR_NOMEM.
 * @return #NOCT_OK or a failure status (see the postcondition).
 */
NOCT_API noctStatus noctBroadphaseAdd(noctBroadphase *bp, const double lo[3],
                                      const double hi[3], void *user_data, uint64_t category,
                                      uint64_t mask, noctProxyId *id, noctError *err);

/**
 * @brief Give a proxy a new box.
 * @pre bp != NULL && lo != NULL && hi != NULL
 * @post On #NOCT_OK the tree holds the proxy in exactly the leaves its new
 *       box overlaps. On #NOCT_ERR_INVALID (stale handle, or lo > hi),
 *       #NOCT_ERR_NONFINITE or #NOCT_ERR_TOO_LARGE nothing changed. On
 *       #NOCT_ERR_NOMEM the proxy keeps its old box and the tree is
 *       rebuilt before its next use.
 * @param bp the broadphase.
 * @param id the proxy's handle.
 * @param lo the box's low corner.
 * @param hi the box's high corner.
 * @param err receives the details of a failure, or NULL.
 * @return #NOCT_OK or a failure status (see the postcondition).
 */
NOCT_API noctStatus noctBroadphaseMove(noctBroadphase *bp, noctProxyId id, const double lo[3],
                                       const double hi[3], noctError *err);

/**
 * @brief Remove a proxy.
 * @pre bp != NULL
 * @post On #NOCT_OK the proxy is gone and its handle is stale; it cannot
 *       fail otherwise but with #NOCT_ERR_INVALID for a stale handle. The
 *       pairs of the last noctBroadphaseUpdatePairs() that named it are
 *       dropped from the list: a removal costs the proxy's own leaves, and
 *       the next noctBroadphasePairs() or noctBroadphaseForEachPair() one
 *       pass over the list for all the removals since.
 * @param bp the broadphase.
 * @param id the proxy's handle.
 * @return #NOCT_OK, or #NOCT_ERR_INVALID for a stale handle.
 */
NOCT_API noctStatus noctBroadphaseRemove(noctBroadphase *bp, noctProxyId id);

/**
 * @brief Change a proxy's category and mask.
 * @pre bp != NULL
 * @post On #NOCT_OK the next noctBroadphaseUpdatePairs() filters with
 *       them; #NOCT_ERR_INVALID for a stale handle.
 * @param bp the broadphase.
 * @param id the proxy's handle.
 * @param category the proxy's category bits. 0 is allowed: the proxy
 *        then pairs with nothing and no query finds it, parked without
 *        being removed (noctWorldSetFilter() refuses 0: an object that can
 *        never pair is a mistake in a world).
 * @param mask the categories it pairs with.
 * @return #NOCT_OK, or #NOCT_ERR_INVALID for a stale handle.
 */
NOCT_API noctStatus noctBroadphaseSetFilter(noctBroadphase *bp, noctProxyId id,
                                            uint64_t category, uint64_t mask);

/**
 * @brief A proxy's box, user data and filter.
 * @pre bp != NULL
 * @post On #NOCT_OK each of lo, hi, user_data, category and mask that is
 *       not NULL receives the proxy's; #NOCT_ERR_INVALID for a stale
 *       handle.
 * @param bp the broadphase.
 * @param id the proxy's handle.
 * @param lo the box's low corner.
 * @param hi the box's high corner.
 * @param user_data the proxy's user data (or where to put it).
 * @param category the proxy's category bits (or where to put them).
 * @param mask the categories it pairs with (or where to put them).
 * @return #NOCT_OK, or #NOCT_ERR_INVALID for a stale handle.
 */
NOCT_API noctStatus noctBroadphaseProxy(const noctBroadphase *bp, noctProxyId id, double lo[3],
                                        double hi[3], void **user_data, uint64_t *category,
                                        uint64_t *mask);

/**
 * @brief The number of live proxies.
 * @pre bp != NULL
 * @param bp the broadphase.
 * @return the number of live proxies.
 */
NOCT_API size_t noctBroadphaseProxyCount(const noctBroadphase *bp);

/**
 * @brief Find the pairs of proxies whose boxes overlap now.
 * @pre bp != NULL
 * @post On #NOCT_OK, noctBroadphasePairs() and noctBroadphaseForEachPair()
 *       give every pair whose closed boxes overlap and whose filters match,
 *       once, sorted by (a.index, b.index). On #NOCT_ERR_NOMEM the list is
 *       empty and the tree is rebuilt before its next use.
 * @param bp the broadphase.
 * @param err receives the details of a failure, or NULL.
 * @return #NOCT_OK or #NOCT_ERR_NOMEM.
 */
NOCT_API noctStatus noctBroadphaseUpdatePairs(noctBroadphase *bp, noctError *err);

/**
 * @brief The pairs of the last noctBroadphaseUpdatePairs().
 * @pre bp != NULL && pairs != NULL
 * @post *pairs points at the sorted list, valid until the next call that
 *       changes the broadphase; returns its length.
 * @param bp the broadphase.
 * @param pairs receives the list.
 * @return the number of pairs.
 */
NOCT_API size_t noctBroadphasePairs(const noctBroadphase *bp, const noctProxyPair **pairs);

/**
 * @brief A function called for a pair: return false to stop.
 */
typedef bool noctPairFcn(void *context, noctProxyId a, void *user_a, noctProxyId b,
                         void *user_b);

/**
 * @brief Call fcn for each pair of the last noctBroadphaseUpdatePairs(),
 * in order, until it returns false.
 * @pre bp != NULL && fcn != NULL; fcn does not change the broadphase.
 * @post Returns how many calls were made.
 * @param bp the broadphase.
 * @param fcn the function to call.
 * @param context passed to fcn.
 * @return the number of calls made.
 */
NOCT_API size_t noctBroadphaseForEachPair(const noctBroadphase *bp, noctPairFcn *fcn,
                                          void *context);

/** @brief A query's filter: a proxy is reported when
 *  `(proxy.category & filter.mask) != 0 && (filter.category & proxy.mask) != 0`. */
typedef struct noctQueryFilter {
    uint64_t category; /**< The query's own category. */
    uint64_t mask;     /**< The categories it reports. */
} noctQueryFilter;

/**
 * @brief A filter that reports every proxy.
 * @return a filter with both fields #NOCT_FILTER_ALL.
 */
NOCT_API noctQueryFilter noctDefaultQueryFilter(void);

/**
 * @brief A function called for a proxy that a box or point query found:
 * return false to stop the query.
 */
typedef bool noctQueryFcn(void *context, noctProxyId id, void *user_data);

/**
 * @brief Visit the proxies whose boxes overlap the closed box [lo, hi].
 * @pre bp != NULL && lo != NULL && hi != NULL && fcn != NULL; fcn does
 *      not change the broadphase.
 * @post fcn was called once for each such proxy that the filter lets
 *       through, in an order that depends only on the operations made,
 *       until it returned false. The box may be infinite (-INFINITY to
 *       INFINITY: every proxy). Returns #NOCT_OK, or #NOCT_ERR_NONFINITE
 *       (a NaN) or #NOCT_ERR_INVALID (lo > hi) with no call made.
 * @param bp the broadphase.
 * @param lo the box's low corner.
 * @param hi the box's high corner.
 * @param filter which proxies to report.
 * @param fcn the function to call.
 * @param context passed to fcn.
 * @return #NOCT_OK, #NOCT_ERR_NONFINITE or #NOCT_ERR_INVALID.
 */
NOCT_API noctStatus noctBroadphaseQueryBox(const noctBroadphase *bp, const double lo[3],
                                           const double hi[3], noctQueryFilter filter,
                                           noctQueryFcn *fcn, void *context);

/**
 * @brief Visit the proxies whose closed boxes contain point p.
 * @pre bp != NULL && p != NULL && fcn != NULL; fcn does not change the
 *      broadphase.
 * @post As noctBroadphaseQueryBox() with the box [p, p]; a p that is
 *       not finite gives #NOCT_ERR_NONFINITE.
 * @param bp the broadphase.
 * @param p the point.
 * @param filter which proxies to report.
 * @param fcn the function to call.
 * @param context passed to fcn.
 * @return #NOCT_OK or #NOCT_ERR_NONFINITE.
 */
NOCT_API noctStatus noctBroadphaseQueryPoint(const noctBroadphase *bp, const double p[3],
                                             noctQueryFilter filter, noctQueryFcn *fcn,
                                             void *context);

/**
 * @brief A function called for a proxy whose box the segment enters at
 * fraction t (0 when it starts inside).
 * @return the new largest fraction to report: t or less clips the
 *         segment there (0 stops the query), and anything not less than
 *         the current largest fraction leaves it unchanged.
 */
typedef double noctRayFcn(void *context, noctProxyId id, void *user_data, double t);

/**
 * @brief Visit, in order along the segment from origin to
 * origin + translation, the proxies whose closed boxes it meets.
 * @pre bp != NULL && origin != NULL && translation != NULL && fcn != NULL;
 *      fcn does not change the broadphase.
 * @post fcn was called once for each proxy that the filter lets through
 *       whose box the segment meets at a fraction t in [0, max], where
 *       max starts at 1 and is what fcn last returned (if less); in order
 *       of t, ties in order of index. Returns #NOCT_OK, or
 *       #NOCT_ERR_NONFINITE with no call made, or #NOCT_ERR_NOMEM,
 *       possibly after calls for the proxies first along the segment
 *       (each is handed out as soon as none can come before it).
 * @param bp the broadphase.
 * @param origin where the segment starts.
 * @param translation the segment, from origin to its end.
 * @param filter which proxies to report.
 * @param fcn the function to call.
 * @param context passed to fcn.
 * @return #NOCT_OK, #NOCT_ERR_NONFINITE or #NOCT_ERR_NOMEM.
 */
NOCT_API noctStatus noctBroadphaseRayCast(const noctBroadphase *bp, const double origin[3],
                                          const double translation[3], noctQueryFilter filter,
                                          noctRayFcn *fcn, void *context);

/**
 * @brief Copy the counters.
 * @pre bp != NULL && counters != NULL
 * @param bp the broadphase.
 * @param counters receives the counters.
 */
NOCT_API void noctBroadphaseGetCounters(const noctBroadphase *bp,
                                        noctBroadphaseCounters *counters);

/**
 * @brief Check every invariant of the tree and the proxies (leaves list
 * exactly the proxies whose boxes overlap them, each once; no leaf could
 * split or merge; the root holds every proxy).
 * @pre bp != NULL
 * @post #NOCT_OK, or #NOCT_ERR_INVARIANT with err saying what is wrong
 *       (a bug in the library), or #NOCT_ERR_NOMEM.
 * @param bp the broadphase.
 * @param err receives the details of a failure, or NULL.
 * @return #NOCT_OK, #NOCT_ERR_INVARIANT or #NOCT_ERR_NOMEM.
 */
NOCT_API noctStatus noctBroadphaseValidate(const noctBroadphase *bp, noctError *err);

/**
 * @brief The root of the tree, for octPrint() and the octree ADT's walks.
 * @pre bp != NULL
 * @post NULL while the broadphase has no tree (no proxies yet). The
 *       tree belongs to the broadphase: read it, never change it. Each
 *       node's datum is a cell that noctBroadphasePrintCell() prints and
 *       noctBroadphaseCell() reads.
 * @param bp the broadphase.
 * @return the root, or NULL.
 */
NOCT_API octNode *noctBroadphaseRoot(const noctBroadphase *bp);

/**
 * @brief Print a node's cell: an octItemPrinter for octPrint().
 * @pre strm != NULL && data != NULL (a datum of this broadphase's tree)
 * @param strm the stream to print to.
 * @param data a node's datum.
 */
NOCT_API void noctBroadphasePrintCell(FILE *strm, const void *data);

/**
 * @brief A node's cube and, for a leaf, its proxies.
 * @pre bp != NULL && node is a node of bp's tree && (ids != NULL || max == 0)
 * @post lo and size (if not NULL) receive the cube; the first max of the
 *       leaf's proxies are copied to ids. Returns how many the leaf holds
 *       (0 for an inner node).
 * @param bp the broadphase.
 * @param node a node of the tree.
 * @param lo the box's low corner.
 * @param size receives the cube's side, or NULL.
 * @param ids receives the leaf's proxies.
 * @param max room in ids.
 * @return the number of proxies in the leaf; 0 for an inner node.
 */
NOCT_API size_t noctBroadphaseCell(const noctBroadphase *bp, const octNode *node,
                                   double lo[3], double *size, noctProxyId *ids, size_t max);

/** @} */

#ifdef __cplusplus
}
#endif

#endif /* NOCTREE_BROADPHASE_H */
