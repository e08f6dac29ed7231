/* SPDX-License-Identifier: MIT */
/*
 * Mesh files through the Open Asset Import Library (assimp): glTF, COLLADA,
 * FBX, 3DS and the rest (mesh.h, noctMeshDataRead()). In a build without
 * it, the error that says so.
 */
#include "config.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>

#include "internal.h"
#include "meshdata_internal.h"

#ifdef HAVE_ASSIMP
#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

/* Add the meshes of node and its children, placed by parent * node's
 * transform (row-major 4x4, aiMatrix4x4's a1..d4). */
static noctStatus add_node(const char *path, const struct aiScene *sc,
                           const struct aiNode *node, const double parent[12],
                           noctMeshData *d, unsigned depth, noctError *err)
{
    if (depth > 1000)
        return noct_fail(err, NOCT_ERR_PARSE, -1, 0, "%s: node hierarchy too deep", path);
    const struct aiMatrix4x4 *t = &node->mTransformation;
    const double local[12] = {t->a1, t->a2, t->a3, t->a4, t->b1, t->b2, t->b3, t->b4,
                              t->c1, t->c2, t->c3, t->c4};
    double m[12];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j) {
            double s = j == 3 ? parent[4 * i + 3] : 0;
            for (int k = 0; k < 3; ++k)
                s += parent[4 * i + k] * local[4 * k + j];
            m[4 * i + j] = s;
        }
    double det = m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) +
                 m[2] * (m[4] * m[9] - m[5] * m[8]);
    for (unsigned mi = 0; mi < node->mNumMeshes; ++mi) {
        if (node->mMeshes[mi] >= sc->mNumMeshes)
            continue;
        const struct aiMesh *mesh = sc->mMeshes[node->mMeshes[mi]];
        size_t first = d->nv;
        if (d->nv + mesh->mNumVertices > NOCT_MESH_MAX_VERTICES)
            return noct_fail(err, NOCT_ERR_TOO_LARGE, -1, 0, "%s: more than %u vertices",
                             path, (unsigned)NOCT_MESH_MAX_VERTICES);
        for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
            const struct aiVector3D *p = &mesh->mVertices[v];
            const double q[3] = {p->x, p->y, p->z};
            double xyz[3];
            for (int i = 0; i < 3; ++i) {
                xyz[i] = m[4 * i] * q[0] + m[4 * i + 1] * q[1] + m[4 * i + 2] * q[2] +
                         m[4 * i + 3];
                if (!isfinite(xyz[i]))
                    return noct_fail(err, NOCT_ERR_NONFINITE, -1, 0,
                                     "%s: mesh '%s': vertex %u: coordinate %c is not finite",
                                     path, mesh->mName.data, v, "xyz"[i]);
            }
            if (!noct_data_add_vertex(d, xyz, 0))
                return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "%s: out of memory", path);
        }
        for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
            const struct aiFace *face = &mesh->mFaces[f];
            if (face->mNumIndices < 3) {
                ++d->skipped;
                continue;
            }
            uint32_t corners[3];
            /* triangulated: polygons of more corners would be fans */
            for (unsigned c = 1; c + 1 < face->mNumIndices; ++c) {
                unsigned ix[3] = {face->mIndices[0], face->mIndices[c], face->mIndices[c + 1]};
                for (int k = 0; k < 3; ++k) {
                    if (ix[k] >= mesh->mNumVertices)
                        return noct_fail(err, NOCT_ERR_INDEX, -1, 0,
                                         "%s: mesh '%s': face %u: vertex index %u out of range",
                                         path, mesh->mName.data, f, ix[k]);
                    corners[det < 0 ? (3 - k) % 3 : k] = (uint32_t)(first + ix[k]);
                }
                if (d->ni + 3 > NOCT_MESH_MAX_INDICES)
                    return noct_fail(err, NOCT_ERR_TOO_LARGE, -1, 0, "%s: too many polygons",
                                     path);
                if (!noct_data_add_polygon(d, corners, 3, 0))
                    return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "%s: out of memory", path);
            }
        }
    }
    for (unsigned c = 0; c < node->mNumChildren; ++c) {
        noctStatus st = add_node(path, sc, node->mChildren[c], m, d, depth + 1, err);
        if (st != NOCT_OK)
            return st;
    }
    return NOCT_OK;
}

noctStatus noct_read_assimp(const char *path, noctMeshData *d, noctError *err)
{
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(slash != NULL ? slash : path, '.');
    if (dot == NULL || !aiIsExtensionSupported(dot))
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0,
                         "%s: unknown mesh format (not .off, .obj, .stl or .ply, and not "
                         "one the Open Asset Import Library reads)", path);
    d->lines = false;
    d->record = NULL;
    FILE *probe = fopen(path, "rb"); /* a file that is not there is an I/O error */
    if (probe == NULL) {
        int e = errno;
        return noct_fail(err, e == ENOMEM ? NOCT_ERR_NOMEM : NOCT_ERR_IO, -1, 0,
                         "%s: cannot open: %s", path, strerror(e));
    }
    fclose(probe);
    const struct aiScene *sc = aiImportFile(path, aiProcess_Triangulate);
    if (sc == NULL)
        return noct_fail(err, NOCT_ERR_PARSE, -1, 0, "%s: the Open Asset Import Library "
                         "cannot read it: %s", path, aiGetErrorString());
    noctStatus st = NOCT_OK;
    if (sc->mNumMeshes == 0 || sc->mRootNode == NULL) {
        st = noct_fail(err, NOCT_ERR_PARSE, -1, 0, "%s: the scene has no meshes", path);
    } else {
        const double identity[12] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
        st = add_node(path, sc, sc->mRootNode, identity, d, 0, err);
        if (st == NOCT_OK && d->np == 0)
            st = noct_fail(err, NOCT_ERR_PARSE, -1, 0,
                           "%s: the scene's meshes have no polygons (%zu points or lines "
                           "skipped)", path, d->skipped);
    }
    aiReleaseImport(sc);
    return st;
}

#else /* !HAVE_ASSIMP */

noctStatus noct_read_assimp(const char *path, noctMeshData *d, noctError *err)
{
    (void)d;
    static const char *const formats[] = {".gltf", ".glb", ".dae", ".fbx", ".3ds", ".blend",
                                          ".x", ".lwo", ".ase", ".ms3d", ".3mf", ".amf",
                                          ".x3d", ".ifc", ".dxf", ".ac", ".md2", ".md3",
                                          ".md5mesh", ".smd", ".ogex", ".b3d", ".irr"};
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(slash != NULL ? slash : path, '.');
    for (size_t i = 0; dot != NULL && i < sizeof formats / sizeof *formats; ++i)
        if (strcasecmp(dot, formats[i]) == 0)
            return noct_fail(err, NOCT_ERR_INVALID, -1, 0,
                             "%s: the %s format is read through the Open Asset Import "
                             "Library (assimp), which this build of libnoctree lacks "
                             "(configure --with-assimp)", path, dot);
    return noct_fail(err, NOCT_ERR_INVALID, -1, 0,
                     "%s: unknown mesh format (expected .off, .obj, .stl or .ply; this "
                     "build of libnoctree lacks assimp for other formats)", path);
}

#endif
