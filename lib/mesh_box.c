/* SPDX-License-Identifier: MIT */
/*
 * Box primitives and turned meshes: a box's corners, its slot (the box
 * form the exact level's filter reads) and its mesh when one is needed,
 * read-only views of its corners for the queries, the checks of its
 * half-extents, noctMeshCreateBox() and noctMeshCreateOrientedBox(); and
 * a mesh turned by a rotation. All of them make meshes through
 * noctMeshCreate() (mesh.c).
 */
#include "config.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "internal.h"
#include "mesh_internal.h"
#include "vec3.h"

/* A built-in box's smallest half-extent is at least this fraction of its
 * largest: a rectangle a by b >= 2^-29 a has corners that turn by
 * ab >= 1.8e-9 (a^2 + b^2), well over the polygon tolerance. */
#define BOX_MIN_RATIO 0x1p-29

static bool positive_finite(double x)
{
    return isfinite(x) && x > 0;
}

void noct_box_slot_fill(const noctMesh *m, noct_box_slot *s)
{
    const box_form *b = &m->box;
    memcpy(s->c, b->c, sizeof s->c);
    memcpy(s->e, b->e, sizeof s->e);
    s->size = b->size;
    memcpy(s->own, b->own, sizeof s->own);
    s->dev = b->dev;
    s->shrink = m->has_dual ? m->dual.shrink : INFINITY;
    s->has_box = m->has_box;
}

/* A box's 8 corners, bit 2: +x, bit 1: +y, bit 0: +z, and its 12
 * triangles, outward. */
static const uint32_t BOX_TRIANGLES[36] = {
    0, 1, 3, 0, 3, 2, /* -x */ 4, 6, 7, 4, 7, 5, /* +x */
    0, 4, 5, 0, 5, 1, /* -y */ 2, 3, 7, 2, 7, 6, /* +y */
    0, 2, 6, 0, 6, 4, /* -z */ 1, 5, 7, 1, 7, 3, /* +z */
};

/* BOX_TRIANGLES' corners and faces as a box dual names them: corner p
 * (bit j: +axis j) is vertex (bit 0 of p) << 2 | (bit 1) | (bit 2) >> 2,
 * and the faces' triangles come in the order -x, +x, -y, +y, -z, +z. */
static const uint8_t BOX_CORNER[8] = {0, 4, 2, 6, 1, 5, 3, 7};
static const uint8_t BOX_FACE[6][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {8, 9}, {10, 11}};

bool noct_box_topology(const noctMesh *m, const uint8_t **corner, const uint8_t (**face)[2])
{
    if (m->has_dual) {
        *corner = m->dual.corner;
        *face = (const uint8_t(*)[2])m->dual.face;
        return true;
    }
    if (m->nt == 12 && m->tri == BOX_TRIANGLES) { /* a box view */
        *corner = BOX_CORNER;
        *face = BOX_FACE;
        return true;
    }
    return false;
}

/* fl(R c) of each corner c = (+-h0, +-h1, +-h2), as noct_rotate() gives
 * it, from the 9 products R_kl h_l: fl(R_kl (-h_l)) = -fl(R_kl h_l), and
 * the sums are noct_rotate()'s, in its order, bit for bit. */
void noct_box_corners(const double half[3], const double R[9], double v[24])
{
    double a[9];
    for (int k = 0; k < 3; ++k) {
        volatile double x = R[3 * k] * half[0], y = R[3 * k + 1] * half[1],
                        z = R[3 * k + 2] * half[2];
        a[3 * k] = x;
        a[3 * k + 1] = y;
        a[3 * k + 2] = z;
    }
    for (int i = 0; i < 8; ++i)
        for (int k = 0; k < 3; ++k) {
            const double x = (i & 4) ? a[3 * k] : -a[3 * k];
            const double y = (i & 2) ? a[3 * k + 1] : -a[3 * k + 1];
            const double z = (i & 1) ? a[3 * k + 2] : -a[3 * k + 2];
            v[3 * i + k] = (x + y) + z;
        }
}

void noct_box_slot_of_box(const double half[3], const double R[9], noct_box_slot *s,
                          double lo[3], double hi[3])
{
    double v[24];
    noct_box_corners(half, R, v);
    noct_box_slot_of_corners(v, R, s, lo, hi);
}

void noct_box_slot_of_corners(const double v[24], const double R[9], noct_box_slot *s,
                              double lo[3], double hi[3])
{
    for (int k = 0; k < 3; ++k) {
        lo[k] = hi[k] = v[k];
        for (int i = 1; i < 8; ++i) {
            lo[k] = noct_min(lo[k], v[3 * i + k]);
            hi[k] = noct_max(hi[k], v[3 * i + k]);
        }
    }
    /* the edge directions: R's columns, made unit */
    double u[3][3];
    for (int j = 0; j < 3; ++j) {
        const double col[3] = {R[j], R[3 + j], R[6 + j]};
        noct_unit3(col, u[j]);
    }
    const double *const d[3] = {u[0], u[1], u[2]};
    box_form b;
    box_dual x;
    bool has_box, has_dual;
    noct_box_form_of(v, d, BOX_TRIANGLES, 12, &b, &has_box, &x, &has_dual);
    memcpy(s->c, b.c, sizeof s->c);
    memcpy(s->e, b.e, sizeof s->e);
    s->size = b.size;
    memcpy(s->own, b.own, sizeof s->own);
    s->dev = b.dev;
    s->shrink = has_dual ? x.shrink : INFINITY;
    s->has_box = has_box;
}

noctStatus noct_mesh_of_box(const double half[3], const double R[9], noctMesh **mesh,
                            noctError *err)
{
    double v[24];
    noct_box_corners(half, R, v);
    static const uint32_t sizes[12] = {3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3};
    return noctMeshCreate(v, 8, sizes, 12, BOX_TRIANGLES, mesh, err);
}

void noct_box_view(const double v[24], noctMesh *view, bvh_node *leaf)
{
    static const uint32_t HULL[8] = {0, 1, 2, 3, 4, 5, 6, 7}, PIECE[1] = {0};
    memset(view, 0, sizeof *view);
    memset(leaf, 0, sizeof *leaf);
    view->nv = 8;
    view->v = (double *)v;                /* read only, as the view's contract */
    view->nt = 12;
    view->tri = (uint32_t *)BOX_TRIANGLES; /* the same */
    view->nhull = 8;
    view->hull = (uint32_t *)HULL;
    view->npieces = 1; /* one piece: its vertex 0 */
    view->piece = (uint32_t *)PIECE;
    for (int k = 0; k < 3; ++k) {
        view->lo[k] = view->hi[k] = v[k];
        double sum = 0;
        for (int i = 0; i < 8; ++i) {
            view->lo[k] = noct_min(view->lo[k], v[3 * i + k]);
            view->hi[k] = noct_max(view->hi[k], v[3 * i + k]);
            sum += v[3 * i + k];
        }
        view->centre[k] = sum / 8;
        leaf->lo[k] = view->lo[k];
        leaf->hi[k] = view->hi[k];
    }
    leaf->count = 12;
    view->nnodes = 1;
    view->nodes = leaf;
}

noctStatus noct_check_box_corners(const double half[3], const double R[9], noctError *err)
{
    double v[24];
    noct_box_corners(half, R, v);
    for (int i = 0; i < 24; ++i)
        if (!(fabs(v[i]) <= NOCT_MAX_COORDINATE))
            return noct_fail(err, NOCT_ERR_TOO_LARGE, -1, 0,
                             "box half-extents (%g, %g, %g) as turned put a corner beyond the "
                             "coordinate limit of %g",
                             half[0], half[1], half[2], NOCT_MAX_COORDINATE);
    return NOCT_OK;
}

noctStatus noct_check_box_half(const double half[3], noctError *err)
{
    for (int i = 0; i < 3; ++i)
        if (!isfinite(half[i]))
            return noct_fail(err, NOCT_ERR_NONFINITE, -1, 0,
                             "box half-extents (%g, %g, %g) are not finite", half[0], half[1],
                             half[2]);
    double hmax = fmax(half[0], fmax(half[1], half[2]));
    double hmin = fmin(half[0], fmin(half[1], half[2]));
    /* Below the normal doubles, the rotated corners would lose their
     * precision: a corner is rounded to within 2^-1074 at best. */
    if (!(hmin >= DBL_MIN))
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0,
                         "box half-extents (%g, %g, %g) must be positive and at least %g",
                         half[0], half[1], half[2], DBL_MIN);
    /* A corner has a coordinate of at least hmax / sqrt(3): past this,
     * beyond the limit. */
    if (hmax > 2 * NOCT_MAX_COORDINATE)
        return noct_fail(err, NOCT_ERR_TOO_LARGE, -1, 0,
                         "box half-extents (%g, %g, %g) put its corners beyond the "
                         "coordinate limit of %g",
                         half[0], half[1], half[2], NOCT_MAX_COORDINATE);
    if (hmin / BOX_MIN_RATIO < hmax)
        return noct_fail(err, NOCT_ERR_DEGENERATE, -1, 0,
                         "box half-extents (%g, %g, %g): too thin, the least is under 2^-29 "
                         "of the largest",
                         half[0], half[1], half[2]);
    return NOCT_OK;
}

_Static_assert(sizeof(noct_box_slot) == 128, "a box slot is two cache lines");

_Static_assert(offsetof(noctMesh, box) + sizeof(box_form) <= 64 * NOCT_MESH_BOX_LINES,
               "the box form and the flags fit NOCT_MESH_BOX_LINES lines");

noctStatus noctMeshCreateBox(double hx, double hy, double hz, noctMesh **mesh,
                             noctError *err)
{
    NOCT_REQUIRE(mesh != NULL);
    *mesh = NULL;
    if (!isfinite(hx) || !isfinite(hy) || !isfinite(hz))
        return noct_fail(err, NOCT_ERR_NONFINITE, -1, 0,
                         "box half-extents (%g, %g, %g) are not finite", hx, hy, hz);
    if (!positive_finite(hx) || !positive_finite(hy) || !positive_finite(hz))
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0,
                         "box half-extents (%g, %g, %g) must be positive", hx, hy, hz);
    double hmax = fmax(hx, fmax(hy, hz)), hmin = fmin(hx, fmin(hy, hz));
    if (hmax > NOCT_MAX_COORDINATE)
        return noct_fail(err, NOCT_ERR_TOO_LARGE, -1, 0,
                         "box half-extents (%g, %g, %g): beyond the coordinate "
                         "limit of %g", hx, hy, hz, NOCT_MAX_COORDINATE);
    if (hmin / BOX_MIN_RATIO < hmax) /* hmin 2^29 is exact */
        return noct_fail(err, NOCT_ERR_DEGENERATE, -1, 0,
                         "box half-extents (%g, %g, %g): too thin, the least is "
                         "under 2^-29 of the largest", hx, hy, hz);
    double v[24];
    for (int i = 0; i < 8; ++i) { /* bit 2: +x, bit 1: +y, bit 0: +z */
        v[3 * i] = (i & 4) ? hx : -hx;
        v[3 * i + 1] = (i & 2) ? hy : -hy;
        v[3 * i + 2] = (i & 1) ? hz : -hz;
    }
    static const uint32_t sizes[6] = {4, 4, 4, 4, 4, 4};
    static const uint32_t quads[24] = {
        0, 1, 3, 2, /* -x */ 4, 6, 7, 5, /* +x */
        0, 4, 5, 1, /* -y */ 2, 3, 7, 6, /* +y */
        0, 2, 6, 4, /* -z */ 1, 5, 7, 3, /* +z */
    };
    return noctMeshCreate(v, 8, sizes, 6, quads, mesh, err);
}

noctStatus noctMeshCreateOrientedBox(const double half[3],
                                     const double rotation[9], noctMesh **mesh,
                                     noctError *err)
{
    NOCT_REQUIRE(half != NULL && rotation != NULL && mesh != NULL);
    *mesh = NULL;
    for (int i = 0; i < 9; ++i)
        if (!isfinite(rotation[i]))
            return noct_fail(err, NOCT_ERR_NONFINITE, -1, 0,
                             "oriented box: a rotation entry is not finite");
    noctStatus st = noct_check_box_half(half, err);
    if (st != NOCT_OK)
        return st;
    /* R^T R = I and det R = +1, within 1e-9. */
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double sum = 0;
            for (int k = 0; k < 3; ++k)
                sum += rotation[3 * k + i] * rotation[3 * k + j];
            if (fabs(sum - (i == j)) > 1e-9)
                return noct_fail(err, NOCT_ERR_INVALID, -1, 0,
                                 "oriented box: the rotation is not "
                                 "orthonormal");
        }
    const double *r = rotation;
    double det = r[0] * (r[4] * r[8] - r[5] * r[7]) -
                 r[1] * (r[3] * r[8] - r[5] * r[6]) +
                 r[2] * (r[3] * r[7] - r[4] * r[6]);
    if (det < 0)
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0,
                         "oriented box: the rotation is a reflection");
    return noct_mesh_of_box(half, rotation, mesh, err);
}

noctStatus noct_mesh_rotated(const noctMesh *m, const double R[9], noctMesh **out,
                             noctError *err)
{
    *out = NULL;
    double *v = malloc(3 * m->nv * sizeof *v);
    uint32_t *sizes = malloc(m->nt * sizeof *sizes);
    if (v == NULL || sizes == NULL) {
        free(v);
        free(sizes);
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    }
    for (size_t i = 0; i < m->nv; ++i)
        noct_rotate(R, &m->v[3 * i], &v[3 * i]);
    for (size_t i = 0; i < m->nt; ++i)
        sizes[i] = 3;
    noctStatus st = (m->surface ? noctMeshCreateSurface : noctMeshCreate)(v, m->nv, sizes, m->nt,
                                                                         m->tri, out, err);
    free(v);
    free(sizes);
    return st;
}
