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
 * consistently oriented surface of planar convex polygons. It is placed in
 * the world by a translation (see narrowphase.h); a fixed orientation is
 * baked into its vertices. A mesh may be shared by any number of objects
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
 *   (#NOCT_ERR_DEGENERATE, #NOCT_ERR_INDEX) that are planar within a
 *   relative tolerance of 1e-9 of the polygon's size (#NOCT_ERR_NONPLANAR)
 *   and strictly convex up to that tolerance, with non-zero area
 *   (#NOCT_ERR_NONCONVEX, #NOCT_ERR_DEGENERATE);
 * - every edge shared by exactly two polygons (#NOCT_ERR_OPEN), which run
 *   along it in opposite directions (#NOCT_ERR_ORIENTATION);
 * - a non-zero enclosed volume (#NOCT_ERR_DEGENERATE).
 *
 * A mesh whose polygons all face inwards (negative volume) is accepted and
 * turned outside in: the solid is the same set of points.
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
 * @return #NOCT_OK; #NOCT_ERR_NONFINITE or #NOCT_ERR_INVALID if a
 *         half-extent is not a finite positive number; #NOCT_ERR_NOMEM.
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
 * @return #NOCT_OK; #NOCT_ERR_NONFINITE or #NOCT_ERR_INVALID if a
 *         half-extent is not finite and positive or @p rotation is not
 *         orthonormal with determinant +1 within 1e-9; #NOCT_ERR_NOMEM.
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
