/* SPDX-License-Identifier: MIT */
/*
 * Shared by the OFF, OBJ, STL and PLY targets: read the input as a mesh
 * file. A file that fails must fail cleanly, naming itself. A mesh that
 * reads must be a valid solid: at least 4 vertices and triangles, finite
 * bounds within the coordinate limit, colliding with itself at the exact
 * level (a solid shares all its points with itself) and with no copy of
 * itself moved beyond its own box, at every level. The same file read as
 * mesh data is inspected, welded and repaired: a repaired surface that is
 * orientable is oriented, and one the inspection calls a solid reads as
 * one.
 */
#ifndef NOCT_FUZZ_MESH_H
#define NOCT_FUZZ_MESH_H

#include <math.h>
#include <stdbool.h>
#include <string.h>

#include <noctree/mesh.h>
#include <noctree/narrowphase.h>

#include "fuzz.h"

static void fuzz_mesh_data(const char *path)
{
    noctMeshData *d = NULL;
    noctError err = {0};
    if (noctMeshDataRead(path, &d, &err) != NOCT_OK) {
        FUZZ_CHECK(d == NULL && strstr(err.message, path) != NULL,
                   "a failed data read: %s", err.message);
        return;
    }
    noctMeshReport r;
    FUZZ_CHECK(noctMeshDataInspect(d, &r, &err) == NOCT_OK, "inspect: %s", err.message);
    FUZZ_CHECK(noctMeshDataWeld(d, 0, NULL, &err) == NOCT_OK, "weld: %s", err.message);
    FUZZ_CHECK(noctMeshDataInspect(d, &r, &err) == NOCT_OK, "inspect: %s", err.message);
    FUZZ_CHECK(r.coincident_vertices == 0, "%zu coincident after a weld",
               r.coincident_vertices);
    if (r.solid) {
        noctMesh *m = NULL;
        FUZZ_CHECK(noctMeshCreateFromData(d, &m, &err) == NOCT_OK, "a solid refused: %s",
                   err.message);
        noctMeshDestroy(m);
    }
    noctMeshRepairReport rr;
    noctStatus st = noctMeshDataRepair(d, 1e-6, &rr, &err);
    FUZZ_CHECK(st == NOCT_OK || st == NOCT_ERR_INVALID, "repair: %s", err.message);
    if (st == NOCT_OK) {
        FUZZ_CHECK(noctMeshDataInspect(d, &r, &err) == NOCT_OK, "inspect: %s", err.message);
        FUZZ_CHECK(!r.orientable || r.oriented, "repaired, orientable, %zu misoriented edges",
                   r.misoriented_edges);
        FUZZ_CHECK(r.duplicate_polygons == 0, "repaired, %zu duplicates", r.duplicate_polygons);
    }
    noctMeshDataDestroy(d);
}

static void fuzz_mesh_file(const char *name, const uint8_t *data, size_t size)
{
    const char *path = fuzz_file(name, data, size);
    fuzz_mesh_data(path);
    noctMesh *m = (noctMesh *)&m; /* must be overwritten */
    noctError err = {0};
    noctStatus st = noctMeshRead(path, &m, &err);
    if (st != NOCT_OK) {
        fuzz_failed_read(st, m, &err, path);
        return;
    }
    FUZZ_CHECK(noctMeshVertexCount(m) >= 4, "%zu vertices", noctMeshVertexCount(m));
    FUZZ_CHECK(noctMeshTriangleCount(m) >= 4, "%zu triangles", noctMeshTriangleCount(m));
    double lo[3], hi[3], most = 0;
    noctMeshBounds(m, lo, hi);
    for (int k = 0; k < 3; ++k) {
        FUZZ_CHECK(lo[k] <= hi[k] && fabs(lo[k]) <= NOCT_MAX_COORDINATE &&
                   fabs(hi[k]) <= NOCT_MAX_COORDINATE,
                   "bounds [%g, %g] on axis %d", lo[k], hi[k], k);
        most = fmax(most, fmax(fabs(lo[k]), fabs(hi[k])));
    }
    const double origin[3] = {0, 0, 0};
    bool hit = false;
    st = noctCollide(m, origin, m, origin, NOCT_ACCURACY_EXACT, &hit, NULL);
    FUZZ_CHECK(st == NOCT_OK && hit, "the mesh against itself: %s, %d",
               noctStatusString(st), (int)hit);
    /* Moved by 4 times its largest coordinate and more, on x: its box and
     * the original's are apart after any rounding of the placed vertices. */
    const double away[3] = {4 * most + 1, 0, 0};
    if (away[0] <= NOCT_MAX_COORDINATE) {
        for (int level = NOCT_ACCURACY_BOX; level <= NOCT_ACCURACY_EXACT; ++level) {
            hit = true;
            st = noctCollide(m, origin, m, away, (noctAccuracy)level, &hit, NULL);
            FUZZ_CHECK(st == NOCT_OK && !hit, "the mesh against a copy %g away, %s: %s, %d",
                       away[0], noctAccuracyName((noctAccuracy)level),
                       noctStatusString(st), (int)hit);
        }
    }
    noctMeshDestroy(m);
}

#endif /* NOCT_FUZZ_MESH_H */
