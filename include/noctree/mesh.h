/* SPDX-License-Identifier: MIT */
/**
 * @file noctree/mesh.h
 * @brief Polyhedral solids given as closed polygon meshes, and surfaces
 *        given as any set of polygons.
 *
 * @defgroup noctree_mesh Meshes
 * @brief Polygon meshes, solids and surfaces: creation, validation,
 * built-in boxes, and mesh files (OFF, OBJ, STL, PLY and, through assimp,
 * glTF and others): reading, welding, inspection and repair.
 *
 * A #noctMesh is an immutable shape of one of two kinds, in its own frame:
 * - a **solid** (noctMeshCreate(), noctMeshRead(), the boxes): the closed
 *   region bounded by a closed, consistently oriented surface of planar
 *   convex polygons, its inside included;
 * - a **surface** (noctMeshCreateSurface(), noctMeshReadSurface()): the
 *   union of the closed triangles of its polygons' fans, and nothing
 *   else. Any set of polygons makes one: open, non-manifold, in several
 *   pieces, inconsistently oriented or closed; a surface encloses nothing,
 *   even a closed one (the inside of a closed surface is not part of it).
 *   noctMeshIsSurface() tells the kinds apart.
 *
 * It is placed by a transform: a rotation and a translation
 * (noctCollideTransformed(), a world object's noctTransform; noctCollide()
 * takes translations alone). A mesh may be shared by any number of objects
 * and threads once created. Every function that takes a mesh takes either
 * kind; where they differ, the function says how (two shapes meet when
 * their point sets share a point: narrowphase.h).
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
 * **Surfaces** are validated like solids up to the topology: at least 3
 * vertices and 1 polygon, the same limits, finite and bounded
 * coordinates, indices in range, and each polygon's area, planarity and
 * convexity by the same tests, with the same statuses and messages naming
 * the polygon. The edges' use, the orientation and the volume are not
 * checked. Polygons may repeat, cross or overlap each other. A solid asked
 * of a mesh that is not one fails with #NOCT_ERR_OPEN,
 * #NOCT_ERR_ORIENTATION or #NOCT_ERR_DEGENERATE (no volume) and a message
 * naming the edge or polygons and saying that noctMeshCreateSurface()
 * (noctMeshReadSurface() for files) takes it as a surface.
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
 * **Several pieces.** A mesh may be several closed surfaces that share
 * no vertex (two separate cubes, or a shell with a cavity facing
 * inwards): the solid is what they bound together, the points inside an
 * odd number of them. Every test treats it as one solid: it meets
 * another where any of its pieces does, a piece wholly inside the other
 * solid included.
 *
 * **The solid, exactly.** Each polygon is split into a fan of triangles
 * from its first vertex; the solid is the closed region those triangles
 * bound. (For a planar convex polygon that is the polygon itself; for a
 * polygon that is planar only within the tolerance it is the nearest thing
 * to it.) The exact collision test decides on those triangles. A
 * surface is the union of the same fans' closed triangles.
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

/** @brief An immutable polyhedral solid or surface; opaque. */
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
 * @brief Create a surface from vertices and polygons: any set of them.
 *
 * The arguments are those of noctMeshCreate(). The surface is the union
 * of the closed triangles of the polygons' fans (see the module text): it
 * may be open, non-manifold, in several pieces, inconsistently oriented
 * or closed, and encloses nothing. The polygons' orientation is kept but
 * means nothing to the collision tests.
 * @param[in]  vertices   `3 * nvertices` coordinates, x y z per vertex.
 * @param[in]  nvertices  Number of vertices (at least 3).
 * @param[in]  sizes      Number of corners of each polygon.
 * @param[in]  npolygons  Number of polygons (at least 1).
 * @param[in]  indices    Vertex indices of the polygons' corners, polygon
 *                        after polygon; `sum(sizes)` entries.
 * @param[out] mesh       Receives the new surface on success, NULL
 *                        otherwise.
 * @param[out] err        Receives the details of a failure, or NULL.
 * @pre @p mesh is not NULL; @p vertices, @p sizes and @p indices are not
 *      NULL where their counts are non-zero.
 * @post On #NOCT_OK, @p *mesh is a surface (noctMeshIsSurface() true, and
 *       noctMeshIsConvex() false) owned by the caller (free it with
 *       noctMeshDestroy()). The arrays are copied, not kept.
 * @return #NOCT_OK, or the first problem found: #NOCT_ERR_TOO_LARGE,
 *         #NOCT_ERR_NONFINITE, #NOCT_ERR_INDEX, #NOCT_ERR_DEGENERATE
 *         (fewer than 3 vertices or no polygon, or a polygon with a vertex
 *         twice or without area), #NOCT_ERR_NONPLANAR, #NOCT_ERR_NONCONVEX
 *         or #NOCT_ERR_NOMEM; never #NOCT_ERR_OPEN or
 *         #NOCT_ERR_ORIENTATION.
 */
NOCT_API noctStatus noctMeshCreateSurface(const double *vertices, size_t nvertices,
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
 * @brief Read a solid from a mesh file: noctMeshDataRead(), an exact weld
 *        (noctMeshDataWeld() with tolerance 0) and noctMeshCreateFromData().
 *
 * Every format of noctMeshDataRead() is read. The exact weld makes a
 * triangle soup (an STL file, or an OBJ, OFF or PLY file that repeats
 * each triangle's corners) into a connected surface and drops the
 * polygons it collapses; nothing else is changed: coordinates that differ
 * by one unit in the last place stay apart. The result must then be a
 * closed, consistently oriented solid as noctMeshCreate() requires. A
 * surface that is not closed or not consistently oriented fails with
 * #NOCT_ERR_OPEN or #NOCT_ERR_ORIENTATION and a message that says why
 * (noctMeshDataInspect()'s reason, such as `12 boundary edges, first
 * 3-7, ...`, vertex numbers counted after the weld) and names the
 * noctree-mesh(1) tool, which inspects and repairs mesh files.
 * @param[in]  path Path of the file.
 * @param[out] mesh Receives the new mesh on success, NULL otherwise.
 * @param[out] err  Receives the details of a failure, or NULL. Its message
 *                  starts with the path and, for syntax and validation
 *                  errors, the line (for binary files, the triangle or
 *                  face).
 * @pre @p path and @p mesh are not NULL.
 * @post On #NOCT_OK, @p *mesh is the file's mesh. Nothing is kept from a
 *       file that fails.
 * @return #NOCT_OK; any status of noctMeshDataRead(); any status of
 *         noctMeshCreate().
 */
NOCT_API noctStatus noctMeshRead(const char *path, noctMesh **mesh,
                                 noctError *err);

/**
 * @brief Read a surface from a mesh file: noctMeshDataRead(), the exact
 *        weld of noctMeshRead() and noctMeshCreateSurfaceFromData().
 *
 * Every format of noctMeshDataRead() is read and welded exactly as
 * noctMeshRead() does; the result is made a surface (see the module
 * text), whatever its topology: a triangle soup, an open or non-manifold
 * mesh, several pieces, or a closed solid's boundary (which is then a
 * surface, enclosing nothing).
 * @param[in]  path Path of the file.
 * @param[out] mesh Receives the new surface on success, NULL otherwise.
 * @param[out] err  Receives the details of a failure, or NULL, as for
 *                  noctMeshRead().
 * @pre @p path and @p mesh are not NULL.
 * @post On #NOCT_OK, @p *mesh is the file's surface (noctMeshIsSurface()
 *       true). Nothing is kept from a file that fails.
 * @return #NOCT_OK; any status of noctMeshDataRead(); any status of
 *         noctMeshCreateSurface().
 */
NOCT_API noctStatus noctMeshReadSurface(const char *path, noctMesh **mesh, noctError *err);

/**
 * @name Mesh data: what a mesh file holds, before it is a solid
 *
 * A #noctMeshData is a list of vertices and of polygons over them, as a
 * file gives them: possibly a triangle soup, open, non-manifold, in
 * several pieces or inconsistently oriented. It can be welded, inspected,
 * repaired, written as OFF, and made into a solid (noctMeshCreateFromData())
 * when it is one. Its arrays can be read back (noctMeshDataVertices() and
 * the others) to build other kinds of shapes from it.
 *
 * **Exact weld** (noctMeshDataWeld() with tolerance 0, and noctMeshRead()):
 * vertices whose three coordinates are equal as doubles, bit for bit, are
 * one vertex, except that -0.0 and +0.0 count as equal. Coordinates that
 * differ by one unit in the last place are not welded.
 *
 * **Tolerance weld** (a tolerance eps > 0): two vertices each of whose
 * three coordinates differ by at most eps, exactly (|x_k - y_k| <= eps
 * as real numbers, no rounding: the max-norm distance), are merged, and
 * so, transitively, are chains of them: a chain of vertices each within
 * eps of the next becomes one vertex even if its ends are farther apart.
 * The classes depend on the vertices alone, not on their order, and a
 * tolerance of 0 would give the exact weld's. They are found in
 * O(n log n) time for any n vertices: by cells of side eps (two vertices
 * of one cell are within eps; two within eps lie in the same or adjacent
 * cells), each pair of adjacent cells decided by a sort and a dominance
 * sweep, never by comparing every pair. (A Euclidean distance would
 * admit no such bound: deciding whether two dense clusters have a pair
 * within eps is then a bichromatic closest-pair problem, for which no
 * O(n log n) algorithm is known in three dimensions. The box of side
 * 2 eps around a vertex holds its ball of radius eps.)
 *
 * Either way the welded vertex of a class is the class's first vertex (the
 * lowest index), with its coordinates (not an average); the kept vertices
 * keep their order. Each polygon's corners are renamed; corners that then
 * repeat their predecessor (cyclically) are removed, and a polygon left
 * with fewer than 3 corners, or with a vertex twice, is dropped and
 * counted (#noctMeshWeldReport). Duplicate polygons (the same vertices as
 * another, in the same or the reverse cyclic order) are kept by a weld
 * and counted by noctMeshDataInspect(); noctMeshDataRepair() resolves
 * them.
 * @{
 */

/** @brief A mesh file's vertices and polygons; opaque. */
typedef struct noctMeshData noctMeshData;

/** How many edges of each kind a #noctMeshReport lists. */
#define NOCT_MESH_REPORT_FIRST 3

/** @brief What a weld did. */
typedef struct noctMeshWeldReport {
    size_t welded_vertices;  /**< Vertices merged into another (removed). */
    size_t dropped_polygons; /**< Polygons the weld collapsed, dropped. */
} noctMeshWeldReport;

/** @brief What noctMeshDataRepair() did. */
typedef struct noctMeshRepairReport {
    size_t welded_vertices;      /**< As #noctMeshWeldReport. */
    size_t dropped_polygons;     /**< As #noctMeshWeldReport. */
    size_t removed_duplicates;   /**< Duplicate polygons removed. */
    size_t flipped_polygons;     /**< Polygons whose corner order was reversed. */
    size_t unorientable_components; /**< Components no orientation suits. */
} noctMeshRepairReport;

/**
 * @brief The inspection of a #noctMeshData (noctMeshDataInspect()).
 *
 * Edges are the unordered pairs of vertices that are consecutive corners
 * of a polygon (cyclically); an edge is used once per such occurrence.
 * Edges are named `a-b`, a < b, by the data's vertex numbers (0-based,
 * after any weld). The components are the classes of polygons connected
 * through shared edges.
 */
typedef struct noctMeshReport {
    size_t vertices;            /**< Vertices of the data. */
    size_t unused_vertices;     /**< Vertices on no polygon. */
    size_t coincident_vertices; /**< Vertices equal to an earlier one: the
                                     number an exact weld would remove. */
    size_t polygons;            /**< Polygons of the data. */
    size_t triangles;           /**< Triangles of their fan triangulation. */
    size_t welded_vertices;     /**< Vertices removed by the welds applied. */
    size_t dropped_polygons;    /**< Polygons those welds dropped. */
    size_t skipped_primitives;  /**< Points and lines the reader skipped. */
    size_t duplicate_polygons;  /**< Polygons with the vertices of an earlier
                                     one, in the same or the reverse order. */
    size_t edges;               /**< Distinct edges. */
    size_t boundary_edges;      /**< Edges used once. */
    /** The first boundary edges (in the order of their vertex numbers). */
    uint32_t boundary_first[NOCT_MESH_REPORT_FIRST][2];
    size_t nonmanifold_edges;   /**< Edges used more than twice. */
    /** The first non-manifold edges. */
    uint32_t nonmanifold_first[NOCT_MESH_REPORT_FIRST][2];
    /** How many times each of them is used. */
    size_t nonmanifold_uses[NOCT_MESH_REPORT_FIRST];
    size_t misoriented_edges;   /**< Edges used twice in the same direction. */
    /** The first misoriented edges. */
    uint32_t misoriented_first[NOCT_MESH_REPORT_FIRST][2];
    size_t components;          /**< Connected components of polygons. */
    bool closed;      /**< Every edge is used exactly twice. */
    bool orientable;  /**< Some choice of each polygon's direction makes
                           every edge used twice run both ways. */
    bool oriented;    /**< No edge is misoriented. */
    bool has_volume;  /**< Closed and oriented: noctMeshReport::volume is defined. */
    /** The signed enclosed volume (positive if the polygons face outwards),
     *  or 0 without noctMeshReport::has_volume. */
    double volume;
    bool solid;       /**< noctMeshCreateFromData() would succeed. */
    /** #NOCT_OK if solid, else the status noctMeshCreateFromData() would
     *  return (#NOCT_ERR_OPEN, #NOCT_ERR_ORIENTATION, ...). */
    noctStatus status;
    /** Why it is not a solid (empty if it is), such as `12 boundary edges,
     *  first 3-7, 7-9, 2-3; 2 non-manifold edges, first 5-9 (4 polygons)`. */
    char reason[NOCT_ERROR_MESSAGE_SIZE];
} noctMeshReport;

/**
 * @brief Make mesh data from arrays (copied).
 * @param[in]  vertices  `3 * nvertices` coordinates.
 * @param[in]  nvertices Number of vertices.
 * @param[in]  sizes     Number of corners of each polygon.
 * @param[in]  npolygons Number of polygons.
 * @param[in]  indices   The polygons' corners, `sum(sizes)` entries.
 * @param[out] data      Receives the new data, or NULL on failure.
 * @param[out] err       Receives the details of a failure, or NULL.
 * @pre @p data is not NULL; the arrays are not NULL where their counts are
 *      not zero.
 * @post On #NOCT_OK, @p *data holds copies of the arrays; free it with
 *       noctMeshDataDestroy().
 * @return #NOCT_OK; #NOCT_ERR_NONFINITE for a coordinate that is not
 *         finite; #NOCT_ERR_DEGENERATE for a polygon of fewer than 3
 *         corners; #NOCT_ERR_INDEX for a corner out of range;
 *         #NOCT_ERR_TOO_LARGE beyond #NOCT_MESH_MAX_VERTICES or
 *         #NOCT_MESH_MAX_INDICES; #NOCT_ERR_NOMEM.
 */
NOCT_API noctStatus noctMeshDataCreate(const double *vertices, size_t nvertices,
                                       const uint32_t *sizes, size_t npolygons,
                                       const uint32_t *indices, noctMeshData **data,
                                       noctError *err);

/**
 * @brief Read the vertices and polygons of a mesh file, as they are.
 *
 * The format is chosen by the file name's extension, in any case:
 * - `.off`: the `OFF` header, the counts, vertices, then polygons as
 *   `n i1 ... in` (colours after the indices are ignored), `#` comments.
 * - `.obj` (Wavefront): `v x y z [w]` and `f` lines whose corners are
 *   `i`, `i/t`, `i/t/n` or `i//n` with 1-based or negative (relative)
 *   indices; `vn`, `vt`, `vp`, `o`, `g`, `s`, `usemtl` and `mtllib` are
 *   ignored, any other statement is an error.
 * - `.stl`: binary if the file's size is 84 + 50 n bytes, n the count at
 *   byte 80 (whatever its first bytes: binary files often start with
 *   `solid` too); else ASCII (`solid`, `facet normal`, `outer loop`, three
 *   `vertex x y z`, `endloop`, `endfacet`, `endsolid`, keywords in any
 *   case, several solids in a row allowed). A file of another size that
 *   holds a NUL byte is a binary file of the wrong size: an error. Facet
 *   normals are ignored: the corners' order gives the orientation. Each
 *   triangle has its own three vertices (weld them).
 * - `.ply`: `format ascii 1.0`, `binary_little_endian 1.0` or
 *   `binary_big_endian 1.0`; the `vertex` element's `x`, `y` and `z`
 *   properties of any numeric type (char, uchar, short, ushort, int,
 *   uint, float, double, or int8 ... float64); the `face` element's
 *   `vertex_indices` or `vertex_index` list, whose count and items are of
 *   any integer type. Other elements and properties, lists included, are
 *   skipped; `comment` and `obj_info` lines are ignored.
 * - any other extension: through the Open Asset Import Library (assimp)
 *   when the library was built with it (configure `--with-assimp`):
 *   glTF 2 (`.gltf`, `.glb`), COLLADA (`.dae`), FBX, 3DS, and every other
 *   format assimp reads. All meshes of the scene are merged, each placed
 *   by the product of its nodes' transforms from the root (once per node
 *   that names it; the matrices' affine part; a mirroring transform
 *   reverses the polygons' corners so that they keep facing the same
 *   side). Polygons are triangulated by assimp (aiProcess_Triangulate);
 *   its JoinIdenticalVertices step is not used, since it may merge
 *   vertices within a tolerance: weld the data instead. Points and lines
 *   are skipped and counted (#noctMeshReport's skipped_primitives). A
 *   scene without meshes, or whose meshes have no polygons, is an error.
 *   In a build without assimp such a file is an #NOCT_ERR_INVALID error
 *   that says so.
 *
 * Nothing is welded or checked beyond the syntax, finite coordinates and
 * indices in range: the data may be any surface.
 * @param[in]  path Path of the file.
 * @param[out] data Receives the data, or NULL on failure.
 * @param[out] err  Receives the details of a failure, or NULL: a message
 *                  starting with the path and, where there is one, the
 *                  line (`path:12: ...`) or, in a binary file, the
 *                  triangle or face (`path: triangle 7: ...`).
 * @pre @p path and @p data are not NULL.
 * @post On #NOCT_OK, @p *data is the file's data, owned by the caller. It
 *       remembers the path and the line of each vertex and polygon, for
 *       the messages of noctMeshCreateFromData().
 * @return #NOCT_OK; #NOCT_ERR_IO if the file cannot be opened or read;
 *         #NOCT_ERR_NOMEM if memory runs out; #NOCT_ERR_INVALID for an
 *         unknown extension, or one that needs assimp in a build without
 *         it; #NOCT_ERR_PARSE for a syntax error, a truncated file, a
 *         wrong count, an unsupported PLY type or layout, or a scene
 *         without meshes; #NOCT_ERR_NONFINITE for a coordinate that is
 *         NaN or infinite; #NOCT_ERR_INDEX for a corner out of range;
 *         #NOCT_ERR_TOO_LARGE for more vertices or polygon corners than
 *         the limits.
 */
NOCT_API noctStatus noctMeshDataRead(const char *path, noctMeshData **data,
                                     noctError *err);

/**
 * @brief Weld the data's vertices (exactly, or within a tolerance) and
 *        drop the polygons that collapse: see the group's text.
 * @param[in,out] data      Mesh data.
 * @param[in]     tolerance 0 for the exact weld, or eps > 0.
 * @param[out]    report    Receives what was done, or NULL.
 * @param[out]    err       Receives the details of a failure, or NULL.
 * @pre @p data is not NULL.
 * @post On #NOCT_OK, each class of the weld is one vertex (so no two
 *       vertices are within @p tolerance, or equal for 0); polygons are
 *       renamed and the collapsed ones dropped; the data's counts of
 *       welded vertices and dropped polygons (#noctMeshReport) grow by the
 *       report's. On failure the data is unchanged.
 * @return #NOCT_OK; #NOCT_ERR_INVALID if @p tolerance is negative, not
 *         finite, or so small that some coordinate is 2^53 or more
 *         tolerances from 0; #NOCT_ERR_NOMEM.
 */
NOCT_API noctStatus noctMeshDataWeld(noctMeshData *data, double tolerance,
                                     noctMeshWeldReport *report, noctError *err);

/**
 * @brief Inspect the data: counts, edges, components, orientation, volume,
 *        and why it is not a solid.
 *
 * The topology is decided first: a data with boundary, non-manifold or
 * misoriented edges is not a solid, for that reason. Otherwise the data
 * is tried with noctMeshCreateFromData() (which may refuse it for its
 * geometry: non-planar or non-convex polygons, no volume...).
 * @param[in]  data   Mesh data.
 * @param[out] report Receives the inspection.
 * @param[out] err    Receives the details of a failure, or NULL.
 * @pre @p data and @p report are not NULL.
 * @post On #NOCT_OK, @p *report is filled (see #noctMeshReport).
 * @return #NOCT_OK, or #NOCT_ERR_NOMEM.
 */
NOCT_API noctStatus noctMeshDataInspect(const noctMeshData *data, noctMeshReport *report,
                                        noctError *err);

/**
 * @brief Repair the data as far as it goes: weld, resolve duplicate
 *        polygons, orient each component consistently, outwards if closed.
 *
 * 1. noctMeshDataWeld() with @p tolerance.
 * 2. Duplicate polygons (the same vertices in the same or reverse cyclic
 *    order) are resolved by their net orientation: counting the copies
 *    that run like the first as +1 and the reversed ones as -1, a positive
 *    sum keeps the first alone, a negative one keeps the first reversed
 *    copy alone, and zero (a two-sided sheet) drops them all.
 * 3. In each component (polygons connected through edges), the polygons
 *    are flipped (corner order reversed) to run like the component's first
 *    polygon across every edge used exactly twice, as far as that can be
 *    done (in an unorientable component, the constraints met first, in
 *    the order of the edges' vertex numbers, win).
 * 4. Each closed, orientable component whose signed volume is negative is
 *    turned outside in (all its polygons flipped), so that it faces
 *    outwards.
 * @param[in,out] data      Mesh data.
 * @param[in]     tolerance The weld's tolerance, 0 for the exact weld.
 * @param[out]    report    Receives what was done, or NULL.
 * @param[out]    err       Receives the details of a failure, or NULL.
 * @pre @p data is not NULL.
 * @post On #NOCT_OK, the data is repaired as above.
 * @return #NOCT_OK, any status of noctMeshDataWeld(), or #NOCT_ERR_NOMEM.
 */
NOCT_API noctStatus noctMeshDataRepair(noctMeshData *data, double tolerance,
                                       noctMeshRepairReport *report, noctError *err);

/**
 * @brief Write the data as an OFF file (coordinates to 17 significant
 *        digits: they read back as the same doubles).
 * @param[in]  data Mesh data.
 * @param[in]  path Path of the file to write (replaced).
 * @param[out] err  Receives the details of a failure, or NULL.
 * @pre @p data and @p path are not NULL.
 * @return #NOCT_OK, or #NOCT_ERR_IO naming the path.
 */
NOCT_API noctStatus noctMeshDataWriteOff(const noctMeshData *data, const char *path,
                                         noctError *err);

/**
 * @brief Make a solid of the data, as noctMeshCreate() does of its arrays.
 * @param[in]  data Mesh data.
 * @param[out] mesh Receives the new mesh, or NULL on failure.
 * @param[out] err  Receives the details of a failure, or NULL; for data
 *                  read from a file, the message names the file and the
 *                  line (or triangle) of the vertex or polygon at fault.
 * @pre @p data and @p mesh are not NULL.
 * @return Any status of noctMeshCreate().
 */
NOCT_API noctStatus noctMeshCreateFromData(const noctMeshData *data, noctMesh **mesh,
                                           noctError *err);

/**
 * @brief Make a surface of the data, as noctMeshCreateSurface() does of its
 *        arrays.
 * @param[in]  data Mesh data.
 * @param[out] mesh Receives the new surface, or NULL on failure.
 * @param[out] err  Receives the details of a failure, or NULL; for data
 *                  read from a file, the message names the file and the
 *                  line (or triangle) of the vertex or polygon at fault.
 * @pre @p data and @p mesh are not NULL.
 * @post On #NOCT_OK, @p *mesh is a surface owned by the caller.
 * @return Any status of noctMeshCreateSurface().
 */
NOCT_API noctStatus noctMeshCreateSurfaceFromData(const noctMeshData *data, noctMesh **mesh,
                                                  noctError *err);

/**
 * @brief Destroy mesh data.
 * @param[in] data Mesh data, or NULL (then nothing happens).
 */
NOCT_API void noctMeshDataDestroy(noctMeshData *data);

/**
 * @brief Return the number of vertices.
 * @param[in] data Mesh data.
 * @pre @p data is not NULL.
 * @return The number of vertices.
 */
NOCT_API size_t noctMeshDataVertexCount(const noctMeshData *data);

/**
 * @brief Return the vertices' coordinates.
 * @param[in] data Mesh data.
 * @pre @p data is not NULL.
 * @return `3 * noctMeshDataVertexCount()` coordinates, valid until the data
 *         is changed or destroyed (NULL if there are none).
 */
NOCT_API const double *noctMeshDataVertices(const noctMeshData *data);

/**
 * @brief Return the number of polygons.
 * @param[in] data Mesh data.
 * @pre @p data is not NULL.
 * @return The number of polygons.
 */
NOCT_API size_t noctMeshDataPolygonCount(const noctMeshData *data);

/**
 * @brief Return the polygons' sizes (numbers of corners).
 * @param[in] data Mesh data.
 * @pre @p data is not NULL.
 * @return noctMeshDataPolygonCount() sizes, valid until the data is changed
 *         or destroyed (NULL if there are none).
 */
NOCT_API const uint32_t *noctMeshDataPolygonSizes(const noctMeshData *data);

/**
 * @brief Return the polygons' corners, polygon after polygon.
 * @param[in] data Mesh data.
 * @pre @p data is not NULL.
 * @return The sum of the sizes' vertex indices, valid until the data is
 *         changed or destroyed (NULL if there are none).
 */
NOCT_API const uint32_t *noctMeshDataIndices(const noctMeshData *data);

/** @} */

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
 * Decided exactly at creation: the surface is one piece (its triangles
 * connected through shared vertices) and convex at every edge (the far
 * vertex of each triangle lies on or below the plane of its neighbor
 * across the edge). A mesh of several separate pieces, each convex, is
 * not; nor is a surface (noctMeshIsSurface()): it encloses nothing.
 * @param[in] mesh A mesh.
 * @pre @p mesh is not NULL.
 * @return Whether the mesh is a convex solid.
 */
NOCT_API bool noctMeshIsConvex(const noctMesh *mesh);

/**
 * @brief Tell whether the mesh is a surface (noctMeshCreateSurface(),
 *        noctMeshCreateSurfaceFromData(), noctMeshReadSurface()) rather
 *        than a solid.
 * @param[in] mesh A mesh.
 * @pre @p mesh is not NULL.
 * @return true for a surface; false for a solid, boxes included.
 */
NOCT_API bool noctMeshIsSurface(const noctMesh *mesh);

#ifdef __cplusplus
}
#endif

/** @} */
#endif /* NOCTREE_MESH_H */
