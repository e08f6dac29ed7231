/* SPDX-License-Identifier: MIT */
/**
 * @file noctree/mesh.h
 * @brief Polyhedral solids given as closed polygon meshes.
 *
 * @defgroup noctree_mesh Meshes
 * @brief Closed polygon meshes: creation, validation, built-in boxes and
 * OFF and Wavefront OBJ readers.
 *
 * A #noctMesh is an immutable solid: the closed region bounded by a closed,
 * consistently oriented surface of planar convex polygons, in its own
 * frame. It is placed by a transform: a rotation and a translation
 * (noctCollideTransformed(), a world object's noctTransform; noctCollide()
 * takes translations alone). A mesh may be shared by any number of objects
 * and threads once created.
 *
 * **Validation.** Every constructor checks its input and, on failure,
 * returns a status and fills a #noctError naming the vertex, polygon or
 * edge and (for files) the line. A valid mesh has:
 * - at least 4 vertices and 4 polygons, no more than #NOCT_MESH_MAX_VERTICES
 *   vertices and #NOCT_MESH_MAX_INDICES polygon corners;
 * - finite vertex coordinates (#NOCT_ERR_NONFINITE) of magnitude at most
 *   #NOCT_MAX_COORDINATE (#NOCT_ERR_TOO_LARGE);
 * - polygons of at least 3 distinct, existing vertices
 *   (#NOCT_ERR_DEGENERATE, #NOCT_ERR_INDEX) with an area, planar and
 *   strictly convex within a tolerance of 1e-9 relative to the polygon's
 *   own size. With D the polygon's diameter (the largest distance between
 *   two of its corners) and N its Newell normal (whose length is twice its
 *   area), a polygon must have
 *   - an area: |N| > 1e-9 D^2 (#NOCT_ERR_DEGENERATE);
 *   - every corner within 1e-9 D of the plane through its first corner
 *     normal to N (#NOCT_ERR_NONPLANAR);
 *   - at every corner b, between a and c, a turn
 *     ((b - a) x (c - b)) . N / |N| > 1e-9 D^2 (#NOCT_ERR_NONCONVEX); for
 *     a triangle, that is its area test;
 * - every edge shared by exactly two polygons (#NOCT_ERR_OPEN), which run
 *   along it in opposite directions (#NOCT_ERR_ORIENTATION);
 * - an enclosed volume V with 6 |V| > 1e-12 (x1 - x0) (y1 - y0) (z1 - z0),
 *   [x0, x1] x [y0, y1] x [z0, z1] being its bounding box, and larger
 *   than a bound on its computation's rounding, so that its sign, which
 *   tells outside from inside, is not rounding's (#NOCT_ERR_DEGENERATE).
 *
 * A mesh whose polygons all face inwards (negative volume) is accepted and
 * turned outside in: the solid is the same set of points.
 *
 * **Any size, any place.** The tests are computed on differences: between
 * a polygon's corners and its first corner, and for the volume between the
 * vertices and the bounding box's least corner, scaled by a power of two
 * to the polygon's or the mesh's size. So the tolerances are the same at
 * every size the coordinates allow (from #NOCT_MAX_COORDINATE down to the
 * subnormal doubles), with rounding errors of about 1e-16 of the polygon's
 * size (times its number of corners), far below them; and a mesh moved by
 * a translation that keeps its coordinates exact (each moved coordinate a
 * double equal to the sum) is accepted or refused alike, with the same
 * convexity (noctMeshIsConvex()).
 *
 * **The solid, exactly.** Each polygon is split into a fan of triangles
 * from its first vertex; the solid is the closed region those triangles
 * bound. (For a planar convex polygon that is the polygon itself; for a
 * polygon that is planar only within the tolerance it is the nearest thing
 * to it.) The exact collision test decides on those triangles.
 * @{
 */
#ifndef NOCTREE_MESH_H
#define NOCTREE_MESH_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include <noctree/export.h>
#include <noctree/status.h>

#ifdef __cplusplus
extern "C" {
#endif

/** @brief An immutable polyhedral solid; opaque. */
typedef struct noctMesh noctMesh;

/** Largest number of vertices a mesh may have. */
#define NOCT_MESH_MAX_VERTICES (1u << 26)
/** Largest total number of polygon corners (sum of polygon sizes). */
#define NOCT_MESH_MAX_INDICES (1u << 28)
/** Largest magnitude of a vertex coordinate or a translation: far enough
 *  from overflow that products of coordinates stay finite. */
#define NOCT_MAX_COORDINATE 1e100

/**
 * @brief Create a mesh from vertices and polygons, validating them.
 * @param[in]  vertices   `3 * nvertices` coordinates, x y z per vertex.
 * @param[in]  nvertices  Number of vertices.
 * @param[in]  sizes      Number of corners of each polygon.
 * @param[in]  npolygons  Number of polygons.
 * @param[in]  indices    Vertex indices of the polygons' corners, polygon
 *                        after polygon, each counter-clockwise seen from
 *                        outside (or each clockwise: see the module text);
 *                        `sum(sizes)` entries.
 * @param[out] mesh       Receives the new mesh on success, NULL otherwise.
 * @param[out] err        Receives the details of a failure, or NULL.
 * @pre @p mesh is not NULL; @p vertices, @p sizes and @p indices are not
 *      NULL where their counts are non-zero.
 * @post On #NOCT_OK, @p *mesh is a valid mesh owned by the caller (free it
 *       with noctMeshDestroy()). The arrays are copied, not kept.
 * @return #NOCT_OK, or the first problem found: #NOCT_ERR_TOO_LARGE,
 *         #NOCT_ERR_NONFINITE, #NOCT_ERR_INDEX, #NOCT_ERR_DEGENERATE,
 *         #NOCT_ERR_NONPLANAR, #NOCT_ERR_NONCONVEX, #NOCT_ERR_OPEN,
 *         #NOCT_ERR_ORIENTATION or #NOCT_ERR_NOMEM.
 */
NOCT_API noctStatus noctMeshCreate(const double *vertices, size_t nvertices,
                                   const uint32_t *sizes, size_t npolygons,
                                   const uint32_t *indices, noctMesh **mesh,
                                   noctError *err);

/**
 * @brief Create an axis-aligned box centred on the origin.
 * @param[in]  hx,hy,hz Half-extents along x, y and z.
 * @param[out] mesh     Receives the new mesh on success, NULL otherwise.
 * @param[out] err      Receives the details of a failure, or NULL.
 * @pre @p mesh is not NULL.
 * @post On #NOCT_OK, @p *mesh is the box [-hx, hx] x [-hy, hy] x [-hz, hz]
 *       with 8 vertices and 6 quadrilaterals.
 * @return #NOCT_OK for every box with half-extents in (0,
 *         #NOCT_MAX_COORDINATE] (subnormal ones included) whose least is
 *         at least 2^-29 of its largest; #NOCT_ERR_NONFINITE if a
 *         half-extent is not finite; #NOCT_ERR_INVALID if one is not
 *         positive; #NOCT_ERR_TOO_LARGE if one exceeds
 *         #NOCT_MAX_COORDINATE; #NOCT_ERR_DEGENERATE if the least is under
 *         2^-29 (about 1.9e-9) of the largest: the faces across the thin
 *         side would be too thin for the polygons' tolerance (see the
 *         module text), which such a ratio clears by far;
 *         #NOCT_ERR_NOMEM.
 */
NOCT_API noctStatus noctMeshCreateBox(double hx, double hy, double hz,
                                      noctMesh **mesh, noctError *err);

/**
 * @brief Create an oriented box centred on the origin.
 *
 * The box's corners are `R (±hx, ±hy, ±hz)`, each rounded to double.
 * @param[in]  half     The half-extents along the box's own axes.
 * @param[in]  rotation A rotation matrix, row-major: `rotation[3*i + j]` is
 *                      R[i][j]; its columns are the box's axes in world
 *                      coordinates.
 * @param[out] mesh     Receives the new mesh on success, NULL otherwise.
 * @param[out] err      Receives the details of a failure, or NULL.
 * @pre @p half, @p rotation and @p mesh are not NULL.
 * @post On #NOCT_OK, @p *mesh is that box, with 8 vertices and 12
 *       triangles (rounding makes its faces only nearly planar, so they
 *       are triangulated).
 * @return #NOCT_OK for every box whose half-extents are at least DBL_MIN
 *         and whose least is at least 2^-29 of its largest, with corners
 *         within #NOCT_MAX_COORDINATE; #NOCT_ERR_NONFINITE if a
 *         half-extent or a rotation entry is not finite;
 *         #NOCT_ERR_INVALID if a half-extent is under DBL_MIN (the least
 *         normal double: below it the rotated corners lose their
 *         precision; zero and negative ones included) or @p rotation is
 *         not orthonormal with determinant +1 within 1e-9;
 *         #NOCT_ERR_TOO_LARGE if a corner has a coordinate beyond
 *         #NOCT_MAX_COORDINATE; #NOCT_ERR_DEGENERATE if the least
 *         half-extent is under 2^-29 (about 1.9e-9) of the largest, as
 *         for noctMeshCreateBox(); #NOCT_ERR_NOMEM.
 */
NOCT_API noctStatus noctMeshCreateOrientedBox(const double half[3],
                                              const double rotation[9],
                                              noctMesh **mesh, noctError *err);

/**
 * @brief Read a mesh from a file in OFF or Wavefront OBJ format.
 *
 * The format is chosen by the file name's extension (`.off` or `.obj`,
 * in any case). OFF: the `OFF` header, the counts line, vertices, then
 * polygons as `n i1 ... in` (colours after the indices are ignored), `#`
 * comments. OBJ: `v x y z [w]` and `f` lines whose corners are `i`,
 * `i/t`, `i/t/n` or `i//n` with 1-based or negative (relative) indices;
 * other statements (`vn`, `vt`, `o`, `g`, `s`, `usemtl`, `mtllib`) are
 * ignored. Either way the result is validated as by noctMeshCreate(). A
 * NUL byte anywhere in a line that is read is a syntax error.
 * @param[in]  path Path of the file.
 * @param[out] mesh Receives the new mesh on success, NULL otherwise.
 * @param[out] err  Receives the details of a failure, or NULL. Its message
 *                  starts with the path and, for syntax and validation
 *                  errors, the line.
 * @pre @p path and @p mesh are not NULL.
 * @post On #NOCT_OK, @p *mesh is the file's mesh. Nothing is kept from a
 *       file that fails.
 * @return #NOCT_OK; #NOCT_ERR_IO if the file cannot be opened or read;
 *         #NOCT_ERR_NOMEM if memory runs out, opening and reading lines
 *         included (never a file read short); #NOCT_ERR_INVALID for an
 *         unknown extension; #NOCT_ERR_PARSE for a syntax error;
 *         #NOCT_ERR_TOO_LARGE for more vertices or polygon corners than
 *         the limits; any status of noctMeshCreate().
 */
NOCT_API noctStatus noctMeshRead(const char *path, noctMesh **mesh,
                                 noctError *err);

/**
 * @brief Destroy a mesh.
 * @param[in] mesh A mesh, or NULL (then nothing happens).
 * @post The mesh's memory is returned; @p mesh may no longer be used.
 */
NOCT_API void noctMeshDestroy(noctMesh *mesh);

/**
 * @brief Return the number of vertices of a mesh.
 * @param[in] mesh A mesh.
 * @pre @p mesh is not NULL.
 * @return The number of vertices.
 */
NOCT_API size_t noctMeshVertexCount(const noctMesh *mesh);

/**
 * @brief Return the number of triangles the mesh's polygons make.
 * @param[in] mesh A mesh.
 * @pre @p mesh is not NULL.
 * @return The number of triangles of the fan triangulation.
 */
NOCT_API size_t noctMeshTriangleCount(const noctMesh *mesh);

/**
 * @brief Return the mesh's axis-aligned bounding box.
 * @param[in]  mesh A mesh.
 * @param[out] lo   Receives the minimum x, y and z of its vertices.
 * @param[out] hi   Receives the maximum x, y and z of its vertices.
 * @pre @p mesh, @p lo and @p hi are not NULL.
 */
NOCT_API void noctMeshBounds(const noctMesh *mesh, double lo[3], double hi[3]);

/**
 * @brief Tell whether the solid is convex.
 *
 * Decided exactly at creation: the surface is convex at every edge (the
 * far vertex of each triangle lies on or below the plane of its neighbor
 * across the edge).
 * @param[in] mesh A mesh.
 * @pre @p mesh is not NULL.
 * @return Whether the solid is convex.
 */
NOCT_API bool noctMeshIsConvex(const noctMesh *mesh);

#ifdef __cplusplus
}
#endif

/** @} */
#endif /* NOCTREE_MESH_H */
