/* SPDX-License-Identifier: MIT */
/*
 * Private: the layout of mesh data (mesh.h's noctMeshData), shared by its
 * operations (meshdata.c) and the file readers (meshio.c, meshio_assimp.c).
 */
#ifndef NOCT_LIB_MESHDATA_INTERNAL_H
#define NOCT_LIB_MESHDATA_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include <noctree/mesh.h>

/* Where each vertex and polygon came from: a line of a text file, a record
 * (a binary file's triangle or face, named by `record`), or nowhere. */
struct noctMeshData {
    double *v;        /* 3 per vertex */
    long *vline;      /* origin of each vertex */
    uint32_t *sizes;  /* corners of each polygon */
    long *pline;      /* origin of each polygon */
    uint32_t *idx;    /* the corners */
    size_t nv, np, ni;
    size_t cap_v, cap_vline, cap_sizes, cap_pline, cap_idx;
    char *path;          /* the file read, or NULL */
    bool lines;          /* origins are lines */
    const char *record;  /* else, if not NULL, the records' name */
    size_t welded, dropped, skipped;
};

bool noct_data_add_vertex(noctMeshData *d, const double xyz[3], long line);
bool noct_data_add_polygon(noctMeshData *d, const uint32_t *corners, uint32_t n, long line);

/* Read a file through assimp into d (meshio_assimp.c); in a build without
 * it, the error that says so. */
noctStatus noct_read_assimp(const char *path, noctMeshData *d, noctError *err);

#endif /* NOCT_LIB_MESHDATA_INTERNAL_H */
