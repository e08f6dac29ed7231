/* SPDX-License-Identifier: MIT */
/**
 * @file noctree/neighbor.h
 * @brief Neighbor finding in an octree, after Samet.
 *
 * @defgroup noctree_neighbor Neighbor finding
 * @brief Samet's table operations and the greater-or-equal face, edge and
 * vertex neighbors (the report's neighbor.h).
 *
 * **Geometry.** Directions are those of #octDirection: L/R is -x/+x, D/U is
 * -y/+y and B/F is -z/+z. A direction I is read as a vector with one
 * component per axis named in I (a face names one axis, an edge two, a
 * vertex three). A node's block is the cube it covers; its eight children
 * are the octants of that cube, a child's type naming the vertex of the
 * parent's cube it touches.
 *
 * **The table operations** (octAdj(), octReflect(), octCommonFace(),
 * octCommonEdge()) answer questions about an octant O of a block and the
 * equal-size block next to O in direction I. They are constant-time table
 * look-ups and never touch a tree.
 *
 * **The neighbor operations** find, for a node P and a direction I, the
 * greater-or-equal neighbor: take the cube of P's size that shares P's I
 * face, edge or vertex. If that cube lies outside the root, there is no
 * neighbor (NULL; so a root has no neighbors). Otherwise the neighbor is the
 * node of P's generation that covers that cube, if the tree reaches that
 * depth there, returned even if it is split; or else the leaf, larger than
 * P, that contains that cube. Queries are valid on internal nodes and
 * leaves. They take O(d) time for a climb of d levels to the nearest common
 * ancestor (a constant on average) and allocate nothing.
 *
 * **Quantized motion.** octVectorToDirections() maps a continuous direction
 * of motion to the face, edge and vertex directions toward which an object
 * moving that way can enter neighboring nodes (the report's Figure 3).
 * @{
 */
#ifndef NOCTREE_NEIGHBOR_H
#define NOCTREE_NEIGHBOR_H

#include <stdbool.h>
#include <stddef.h>

#include <noctree/export.h>
#include <noctree/octree.h>

#ifdef __cplusplus
extern "C" {
#endif

/** @name Low-level neighbor-finding operations
 * @{ */

/**
 * @brief Tell whether octant @p O touches the @p I face, edge or vertex of
 * its containing block.
 *
 * True iff, on every axis named by @p I, @p O lies on the side @p I points
 * to; then the equal-size neighbor of @p O in direction @p I lies outside
 * O's parent block. Samet's ADJ.
 * @param[in] I A face, edge or vertex direction.
 * @param[in] O A vertex direction (an octant).
 * @pre @p I is a face, an edge or a vertex (not #OCT_OMEGA).
 * @pre @p O is a vertex.
 * @post octAdj(I, O) is true iff @p O is adjacent to the Ith face, edge or
 *       vertex of O's containing block.
 * @return Whether @p O is adjacent to that face, edge or vertex.
 */
NOCT_API bool octAdj(octDirection I, octDirection O);

/**
 * @brief Return the child type of the equal-size block that shares the
 * @p I face, edge or vertex of a block of child type @p O.
 *
 * That block's child type is @p O mirrored on every axis named by @p I,
 * whether it is a sibling of @p O or a child of a neighbor of O's parent.
 * Samet's REFLECT.
 * @param[in] I A face, edge or vertex direction.
 * @param[in] O A vertex direction (an octant).
 * @pre @p I is a face, an edge or a vertex (not #OCT_OMEGA).
 * @pre @p O is a vertex.
 * @post The result is the child type of the equal-size block (not
 *       necessarily a sibling) that shares the Ith face, edge or vertex of
 *       a block of child type @p O.
 * @return A vertex direction.
 */
NOCT_API octDirection octReflect(octDirection I, octDirection O);

/**
 * @brief Return the face of O's containing block that octant @p O and its
 * neighbor in direction @p I both touch, if the step from @p O to that
 * neighbor leaves the block through that face.
 *
 * The exact rule: of the axes named by @p I, count those on which @p O lies
 * on the side @p I points to (the axes on which the step leaves O's parent
 * block). If there is exactly one, the result is the face of the parent
 * block on that axis, on that side. Otherwise the result is #OCT_OMEGA: with
 * none the neighbor lies inside O's own parent block, and with two or three
 * the step leaves across an edge or a vertex of the parent only. Samet's
 * COMMON_FACE.
 * @param[in] I An edge or vertex direction.
 * @param[in] O A vertex direction (an octant).
 * @pre @p I is an edge or a vertex.
 * @pre @p O is a vertex.
 * @post The result is the face of O's containing block common to octant
 *       @p O and its neighbor in direction @p I, or #OCT_OMEGA as above.
 * @return A face direction or #OCT_OMEGA.
 */
NOCT_API octDirection octCommonFace(octDirection I, octDirection O);

/**
 * @brief Return the edge of O's containing block that octant @p O and its
 * neighbor in vertex direction @p I both touch, if the step from @p O to
 * that neighbor leaves the block across that edge.
 *
 * The exact rule: if @p O lies on the side @p I points to on exactly two of
 * the three axes, the result is the parent block's edge on those two axes,
 * on those sides. Otherwise it is #OCT_OMEGA: the neighbor lies inside O's
 * parent block, or across a face or the vertex of the parent. Samet's
 * COMMON_EDGE.
 * @param[in] I A vertex direction.
 * @param[in] O A vertex direction (an octant).
 * @pre @p I is a vertex.
 * @pre @p O is a vertex.
 * @post The result is the edge of O's containing block common to octant
 *       @p O and its neighbor in direction @p I, or #OCT_OMEGA as above.
 * @return An edge direction or #OCT_OMEGA.
 */
NOCT_API octDirection octCommonEdge(octDirection I, octDirection O);

/** @} */

/** @name Neighbor-finding operations
 * @{ */

/**
 * @brief Return P's greater-or-equal face neighbor in direction @p I.
 * @param[in] P A node, internal or leaf.
 * @param[in] I A face direction.
 * @pre @p P is not NULL.
 * @pre @p I is a face.
 * @post If such a node exists, the result is the face neighbor of @p P, of
 *       size greater than or equal to P's, in direction @p I, as defined in
 *       the module description; otherwise it is NULL.
 * @return The neighbor, or NULL if the neighboring cube is outside the root.
 */
NOCT_API octNode *octGtEqFaceNeighbor(octNode *P, octDirection I);

/**
 * @brief Return P's greater-or-equal edge neighbor in direction @p I.
 *
 * When the path to the neighbor leaves P's parent through a face, the
 * climb continues with octCommonFace(), as Samet does.
 * @param[in] P A node, internal or leaf.
 * @param[in] I An edge direction.
 * @pre @p P is not NULL.
 * @pre @p I is an edge.
 * @post If such a node exists, the result is the edge neighbor of @p P, of
 *       size greater than or equal to P's, in direction @p I, as defined in
 *       the module description (a larger leaf is returned even if it also
 *       shares a face with P); otherwise it is NULL.
 * @return The neighbor, or NULL if the neighboring cube is outside the root.
 */
NOCT_API octNode *octGtEqEdgeNeighbor(octNode *P, octDirection I);

/**
 * @brief Return P's greater-or-equal vertex neighbor in direction @p I.
 *
 * When the path to the neighbor leaves P's parent through an edge or a
 * face, the climb continues with octCommonEdge() or octCommonFace().
 * @param[in] P A node, internal or leaf.
 * @param[in] I A vertex direction.
 * @pre @p P is not NULL.
 * @pre @p I is a vertex.
 * @post If such a node exists, the result is the vertex neighbor of @p P,
 *       of size greater than or equal to P's, in direction @p I, as defined
 *       in the module description; otherwise it is NULL.
 * @return The neighbor, or NULL if the neighboring cube is outside the root.
 */
NOCT_API octNode *octGtEqVertexNeighbor(octNode *P, octDirection I);

/**
 * @brief Return P's greater-or-equal neighbor in any direction @p I.
 *
 * Dispatches to octGtEqFaceNeighbor(), octGtEqEdgeNeighbor() or
 * octGtEqVertexNeighbor() by the kind of @p I; convenient with the lists of
 * octVectorToDirections().
 * @param[in] P A node, internal or leaf.
 * @param[in] I A face, edge or vertex direction.
 * @pre @p P is not NULL.
 * @pre @p I is a face, an edge or a vertex (not #OCT_OMEGA).
 * @post The result is the greater-or-equal neighbor of @p P in direction
 *       @p I, or NULL if the neighboring cube is outside the root.
 * @return The neighbor, or NULL.
 */
NOCT_API octNode *octGtEqNeighbor(octNode *P, octDirection I);

/** @} */

/** @name Quantized directions of motion
 * @{ */

/** Capacity an octVectorToDirections() list needs: 7 directions and the
 * terminating #OCT_OMEGA. */
#define OCT_MAX_MOTION_DIRECTIONS 8

/**
 * @brief Quantize a direction of motion into the octree directions toward
 * which an object moving that way can enter neighboring nodes.
 *
 * The report's Vector3ToDirection, with zero components handled: the
 * result names only axes whose component is non-zero, with the sign of
 * that component (x > 0 gives R, x < 0 gives L; y gives U or D; z > 0 gives
 * F, z < 0 gives B, as everywhere in this library). For each non-empty
 * subset of those axes it lists one direction: the faces first, then the
 * edges, then the vertex, each group in #octDirection order. So a motion
 * with three non-zero components gives 7 directions (3 faces, 3 edges, the
 * vertex), one with two gives 3, one with one gives its face alone, and the
 * zero vector gives none. Moving along +x only can enter R neighbors, never
 * L ones, nor any edge or vertex neighbor.
 * @param[in]  x,y,z The direction of motion (need not be normalized).
 * @param[out] dirs  Receives the list, terminated by #OCT_OMEGA, as the
 *                   report's clients expect.
 * @pre @p dirs points to at least #OCT_MAX_MOTION_DIRECTIONS elements.
 * @pre No component is NaN.
 * @post dirs[0 .. n-1] are the directions described above, dirs[n] is
 *       #OCT_OMEGA, where n is the result.
 * @return The number of directions, 0 to 7.
 */
NOCT_API size_t octVectorToDirections(double x, double y, double z,
                                      octDirection dirs[OCT_MAX_MOTION_DIRECTIONS]);

/** @} */

#ifdef __cplusplus
}
#endif

/** @} */
#endif /* NOCTREE_NEIGHBOR_H */
