/* SPDX-License-Identifier: MIT */
/*
 * Meshes: validation, fan triangulation, orientation, convexity, the
 * bounding-volume hierarchy over triangles and the convex hull (qhull).
 */
#include "config.h"

#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <libqhull_r/qhull_ra.h>

#include "internal.h"
#include "bvh.h"
#include "mesh_internal.h"
#include "vec3.h"
#include "predicates.h"

/* Polygons must be planar and convex within this fraction of their size
 * (mesh.h gives the exact tests). */
#define POLY_TOLERANCE 1e-9
/* The enclosed volume must exceed this fraction of the bounding box's
 * (times 6: the sum of the fan's determinants is 6 times the volume). */
#define VOLUME_TOLERANCE 1e-12

void noctMeshDestroy(noctMesh *mesh)
{
    if (mesh == NULL)
        return;
    if (mesh->packed) {
        free(mesh);
        return;
    }
    free(mesh->axis);
    free(mesh->v);
    free(mesh->tri);
    free(mesh->hull);
    free(mesh->piece);
    free(mesh->nodes);
    free(mesh->plane);
    free(mesh);
}

size_t noctMeshVertexCount(const noctMesh *mesh)
{
    NOCT_REQUIRE(mesh != NULL);
    return mesh->nv;
}

size_t noctMeshTriangleCount(const noctMesh *mesh)
{
    NOCT_REQUIRE(mesh != NULL);
    return mesh->nt;
}

void noctMeshBounds(const noctMesh *mesh, double lo[3], double hi[3])
{
    NOCT_REQUIRE(mesh != NULL && lo != NULL && hi != NULL);
    memcpy(lo, mesh->lo, sizeof mesh->lo);
    memcpy(hi, mesh->hi, sizeof mesh->hi);
}

bool noctMeshIsConvex(const noctMesh *mesh)
{
    NOCT_REQUIRE(mesh != NULL);
    return mesh->convex;
}

bool noctMeshIsSurface(const noctMesh *mesh)
{
    NOCT_REQUIRE(mesh != NULL);
    return mesh->surface;
}

/* ---- scaling (vec3.h) --------------------------------------------------- */

/* The unit normal (p1 - p0) x (p2 - p0) / |...|, or 0 if the triangle has
 * none, from the scaled edge vectors: independent of its size and place. */
static void unit_normal(const double p0[3], const double p1[3], const double p2[3],
                        double n[3])
{
    double a[3], b[3], c[3];
    noct_sub3(p1, p0, a);
    noct_sub3(p2, p0, b);
    double m = noct_max(noct_max_abs3(a), noct_max_abs3(b));
    if (!(m > 0)) {
        n[0] = n[1] = n[2] = 0;
        return;
    }
    noct_scaler s = noct_scaler_for(m);
    for (int k = 0; k < 3; ++k) {
        a[k] = noct_scaled(&s, a[k]);
        b[k] = noct_scaled(&s, b[k]);
    }
    noct_cross3(a, b, c);
    noct_unit3(c, n);
}

/* ---- polygon checks ---------------------------------------------------- */

/* Corner i of a polygon relative to its corner 0, scaled. */
static void corner_at(const double *v, const uint32_t *idx, uint32_t i, const noct_scaler *s,
                      double out[3])
{
    const double *p = &v[3 * idx[i]], *o = &v[3 * idx[0]];
    for (int k = 0; k < 3; ++k)
        out[k] = noct_scaled(s, p[k] - o[k]);
}

/*
 * Check one polygon: distinct corners, non-zero area, planar and convex
 * within POLY_TOLERANCE of its diameter D (mesh.h). Newell's normal N
 * gives the plane and, as its length, twice the area; convexity is every
 * corner turning the same way about N. All of it is computed on the
 * corners relative to the first, scaled to the polygon's size: the same
 * verdict wherever the polygon is and whatever its size, with rounding
 * errors some 1e-16 of D (times the number of corners), far below the
 * tolerance. A triangle is planar and, with an area, convex.
 */
static noctStatus check_polygon(const double *v, const uint32_t *idx,
                                uint32_t n, size_t poly, noctError *err)
{
    for (uint32_t i = 0; i < n; ++i)
        for (uint32_t j = i + 1; j < n; ++j)
            if (idx[i] == idx[j])
                return noct_fail(err, NOCT_ERR_DEGENERATE, (long)poly, 0,
                                 "polygon %zu: vertex %u appears twice", poly,
                                 idx[i]);
    const double *o = &v[3 * idx[0]];
    double m = 0;
    for (uint32_t i = 1; i < n; ++i)
        for (int k = 0; k < 3; ++k)
            m = noct_max(m, fabs(v[3 * idx[i] + k] - o[k]));
    if (!(m > 0))
        return noct_fail(err, NOCT_ERR_DEGENERATE, (long)poly, 0,
                         "polygon %zu has no area (its corners coincide)", poly);
    const noct_scaler s = noct_scaler_for(m);
    double normal[3] = {0, 0, 0}, diam2 = 0;
    if (n == 3) {
        double a[3], b[3], d[3];
        corner_at(v, idx, 1, &s, a);
        corner_at(v, idx, 2, &s, b);
        noct_cross3(a, b, normal);
        noct_sub3(b, a, d);
        diam2 = noct_max(noct_dot3(d, d), noct_max(noct_dot3(a, a), noct_dot3(b, b)));
    } else {
        for (uint32_t i = 0; i < n; ++i) {
            double p[3], q[3], d[3];
            corner_at(v, idx, i, &s, p);
            corner_at(v, idx, (i + 1) % n, &s, q);
            normal[0] += (p[1] - q[1]) * (p[2] + q[2]);
            normal[1] += (p[2] - q[2]) * (p[0] + q[0]);
            normal[2] += (p[0] - q[0]) * (p[1] + q[1]);
            for (uint32_t j = i + 1; j < n; ++j) {
                corner_at(v, idx, j, &s, q);
                noct_sub3(p, q, d);
                diam2 = noct_max(diam2, noct_dot3(d, d));
            }
        }
    }
    /* D >= m, scaled to at least 1/2: the tests below are far from
     * underflow, and N at most 2 n D^2 far from overflow. */
    double nlen = noct_norm3(normal);
    if (!(nlen > POLY_TOLERANCE * diam2))
        return noct_fail(err, NOCT_ERR_DEGENERATE, (long)poly, 0,
                         "polygon %zu has no area (its corners are collinear "
                         "within %g of its size)", poly, POLY_TOLERANCE);
    if (n == 3)
        return NOCT_OK;
    for (int k = 0; k < 3; ++k)
        normal[k] /= nlen;
    double diam = sqrt(diam2);
    for (uint32_t i = 1; i < n; ++i) {
        double d[3];
        corner_at(v, idx, i, &s, d);
        double off = fabs(noct_dot3(d, normal));
        if (off > POLY_TOLERANCE * diam)
            return noct_fail(err, NOCT_ERR_NONPLANAR, (long)poly, 0,
                             "polygon %zu: vertex %u is %g off the polygon's "
                             "plane, more than %g of its diameter %g", poly,
                             idx[i], ldexp(off, s.e), POLY_TOLERANCE,
                             ldexp(diam, s.e));
    }
    for (uint32_t i = 0; i < n; ++i) {
        double a[3], b[3], c[3], ab[3], bc[3], turn[3];
        corner_at(v, idx, i, &s, a);
        corner_at(v, idx, (i + 1) % n, &s, b);
        corner_at(v, idx, (i + 2) % n, &s, c);
        noct_sub3(b, a, ab);
        noct_sub3(c, b, bc);
        noct_cross3(ab, bc, turn);
        if (noct_dot3(turn, normal) <= POLY_TOLERANCE * diam2)
            return noct_fail(err, NOCT_ERR_NONCONVEX, (long)poly, 0,
                             "polygon %zu is not convex at vertex %u", poly,
                             idx[(i + 1) % n]);
    }
    return NOCT_OK;
}

/* ---- closedness and orientation ----------------------------------------- */

typedef struct half_edge {
    uint32_t lo, hi;  /* vertex indices, lo < hi */
    uint32_t forward; /* 1 if the polygon runs lo -> hi */
    uint32_t poly;
} half_edge;

static int cmp_half_edge(const void *x, const void *y)
{
    const half_edge *a = x, *b = y;
    if (a->lo != b->lo)
        return a->lo < b->lo ? -1 : 1;
    if (a->hi != b->hi)
        return a->hi < b->hi ? -1 : 1;
    return (a->poly > b->poly) - (a->poly < b->poly);
}

static noctStatus check_closed(const uint32_t *sizes, size_t npoly,
                               const uint32_t *indices, size_t nidx,
                               noctError *err)
{
    half_edge *he = malloc(nidx * sizeof *he);
    if (he == NULL)
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    size_t k = 0, base = 0;
    for (size_t p = 0; p < npoly; ++p) {
        for (uint32_t i = 0; i < sizes[p]; ++i) {
            uint32_t a = indices[base + i], b = indices[base + (i + 1) % sizes[p]];
            he[k].lo = a < b ? a : b;
            he[k].hi = a < b ? b : a;
            he[k].forward = a < b;
            he[k].poly = (uint32_t)p;
            ++k;
        }
        base += sizes[p];
    }
    qsort(he, nidx, sizeof *he, cmp_half_edge);
    noctStatus st = NOCT_OK;
    for (size_t i = 0; i < nidx && st == NOCT_OK;) {
        size_t j = i;
        while (j < nidx && he[j].lo == he[i].lo && he[j].hi == he[i].hi)
            ++j;
        if (j - i != 2)
            st = noct_fail(err, NOCT_ERR_OPEN, (long)he[i].poly, 0,
                           "edge %u-%u is used by %zu polygon%s (polygon %u "
                           "among them), not 2 (not a solid: noctMeshCreateSurface() "
                           "takes it as a surface)", he[i].lo, he[i].hi, j - i,
                           j - i == 1 ? "" : "s", he[i].poly);
        else if (he[i].forward == he[i + 1].forward)
            st = noct_fail(err, NOCT_ERR_ORIENTATION, (long)he[i + 1].poly, 0,
                           "polygons %u and %u both run along edge %u-%u in "
                           "the same direction (not a solid: noctMeshCreateSurface() "
                           "takes it as a surface)", he[i].poly, he[i + 1].poly,
                           he[i].lo, he[i].hi);
        i = j;
    }
    free(he);
    return st;
}

/* ---- convexity and hull ------------------------------------------------- */

/* Exact local convexity: for every edge shared by triangles t and u, the
 * vertex of u off the edge is not above t's plane. Sorting directed edges
 * pairs each edge with its reverse. */
typedef struct dir_edge {
    uint32_t a, b, far; /* edge a -> b of a triangle, its third vertex */
    uint32_t tri;
} dir_edge;

static int cmp_dir_edge(const void *x, const void *y)
{
    const dir_edge *p = x, *q = y;
    uint32_t pl = p->a < p->b ? p->a : p->b, ql = q->a < q->b ? q->a : q->b;
    uint32_t ph = p->a < p->b ? p->b : p->a, qh = q->a < q->b ? q->b : q->a;
    if (pl != ql)
        return pl < ql ? -1 : 1;
    if (ph != qh)
        return ph < qh ? -1 : 1;
    return (p->a > q->a) - (p->a < q->a);
}

/* Add unit vector u to a list of unique directions up to sign (within a
 * relative 1e-12, which only affects how many axes are tried); u = 0 adds
 * nothing. Returns false when the list is full. */
static bool add_direction(double list[][3], size_t *n, const double u[3])
{
    if (u[0] == 0 && u[1] == 0 && u[2] == 0)
        return true;
    for (size_t i = 0; i < *n; ++i) {
        double dp = noct_dot3(list[i], u);
        if (fabs(fabs(dp) - 1) < 1e-12)
            return true;
    }
    if (*n == NOCT_SAT_MAX)
        return false;
    memcpy(list[(*n)++], u, 3 * sizeof *u);
    return true;
}

/* Each triangle's plane: its unit normal (unit_normal(): the same
 * wherever the mesh is and whatever its size) and offset. */
static void planes_of(const noctMesh *m, double (*plane)[4])
{
    for (size_t t = 0; t < m->nt; ++t) {
        const double *p0 = &m->v[3 * m->tri[3 * t]];
        unit_normal(p0, &m->v[3 * m->tri[3 * t + 1]], &m->v[3 * m->tri[3 * t + 2]], plane[t]);
        plane[t][3] = noct_dot3(plane[t], p0);
    }
}

/* m's directed edges, sorted (cmp_dir_edge): the edge list e of 3 nt. */
static void directed_edges(const uint32_t *tri, size_t nt, dir_edge *e)
{
    for (size_t t = 0; t < nt; ++t)
        for (int c = 0; c < 3; ++c)
            e[3 * t + c] = (dir_edge){tri[3 * t + c], tri[3 * t + (c + 1) % 3],
                                      tri[3 * t + (c + 2) % 3], (uint32_t)t};
    qsort(e, 3 * nt, sizeof *e, cmp_dir_edge);
}

/*
 * The convexity and the filter's directions of m, from its triangles'
 * planes and its sorted directed edges e, whose triangle is e[i].tri, or
 * pos[e[i].tri] when pos is not NULL: sets m->convex, m->nsat_faces and
 * m->nsat_edges (0 without the filter) and the directions in sat_face and
 * sat_edge. Triangles from one polygon share interior edges: still
 * checked, and coplanar (sign 0), which is allowed. A real (non-coplanar)
 * edge is an edge direction for the separating-axis filter. The walk goes
 * on past a concave edge until both answers are known: a rotated box,
 * whose rounded corners bend its faces by an ulp, is not exactly convex,
 * yet the filter needs all its edge directions.
 */
static void convexity_walk(noctMesh *m, const double (*plane)[4], const dir_edge *e,
                           const uint32_t *pos, double sat_face[][3], double sat_edge[][3])
{
    const size_t ne = 3 * m->nt;
    bool convex = true, sat = true;
    m->nsat_faces = m->nsat_edges = 0;
    for (size_t i = 0; i + 1 < ne && (convex || sat); i += 2) {
        const dir_edge *p = &e[i], *q = &e[i + 1];
        const uint32_t pt = pos != NULL ? pos[p->tri] : p->tri;
        const uint32_t qt = pos != NULL ? pos[q->tri] : q->tri;
        const double *t0 = &m->v[3 * m->tri[3 * pt]];
        const double *t1 = &m->v[3 * m->tri[3 * pt + 1]];
        const double *t2 = &m->v[3 * m->tri[3 * pt + 2]];
        /* q's far vertex must be below or on p's (outward) plane: orient3d
         * >= 0 means below. */
        if (convex && noct_orient3d(t0, t1, t2, &m->v[3 * q->far], NULL) < 0)
            convex = false;
        /* An edge between triangles whose planes differ is an edge of the
         * solid, not a diagonal of a (nearly) flat polygon. */
        if (sat && noct_dot3(plane[pt], plane[qt]) < 1 - 1e-9) {
            double d[3], u[3];
            noct_sub3(&m->v[3 * p->b], &m->v[3 * p->a], d);
            noct_unit3(d, u);
            sat = add_direction(sat_edge, &m->nsat_edges, u);
        }
    }
    for (size_t t = 0; t < m->nt && sat; ++t)
        sat = add_direction(sat_face, &m->nsat_faces, plane[t]);
    /* The filter needs no convexity to be sound (a solid lies inside the
     * hull of its vertices), only to be useful: small meshes with few
     * directions, typically convex ones. */
    if (!sat || m->nv > 4 * NOCT_SAT_MAX) /* SAT_MAX_VERTICES in narrowphase.c */
        m->nsat_faces = m->nsat_edges = 0;
    /* a union of separate convex pieces is not convex */
    m->convex = convex && m->npieces == 1;
}

/* The filter's axes (m->axis, room for them) from its directions, with
 * the intervals of m's vertices on them. */
static void fill_axes(noctMesh *m, const double sat_face[][3], const double sat_edge[][3])
{
    const size_t naxes = m->nsat_faces + m->nsat_edges;
    for (size_t i = 0; i < naxes; ++i) {
        sat_axis *a = &m->axis[i];
        memcpy(a->u, i < m->nsat_faces ? sat_face[i] : sat_edge[i - m->nsat_faces],
               sizeof a->u);
        a->lo = INFINITY;
        a->hi = -INFINITY;
        for (size_t k = 0; k < m->nv; ++k) {
            double d = noct_dot3(a->u, &m->v[3 * k]);
            a->lo = d < a->lo ? d : a->lo;
            a->hi = d > a->hi ? d : a->hi;
        }
    }
}

static noctStatus compute_convexity(noctMesh *m, noctError *err)
{
    /* The planes are kept for the filter; the normals tell real edges and
     * give the face directions. */
    m->plane = malloc(m->nt * sizeof *m->plane);
    dir_edge *e = malloc(3 * m->nt * sizeof *e);
    if (e == NULL || m->plane == NULL) {
        free(e);
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    }
    planes_of(m, m->plane);
    directed_edges(m->tri, m->nt, e);
    double sat_face[NOCT_SAT_MAX][3], sat_edge[NOCT_SAT_MAX][3];
    convexity_walk(m, (const double (*)[4])m->plane, e, NULL, sat_face, sat_edge);
    free(e);
    if (m->nsat_faces == 0) { /* no filter, no planes */
        free(m->plane);
        m->plane = NULL;
        return NOCT_OK;
    }
    m->axis = malloc((m->nsat_faces + m->nsat_edges) * sizeof *m->axis);
    if (m->axis == NULL)
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    fill_axes(m, (const double (*)[3])sat_face, (const double (*)[3])sat_edge);
    return NOCT_OK;
}

/* Meshes with more vertices than this get their hull from qhull. */
#define HULL_MIN_VERTICES 32

/* The mean of the hull's vertices, in the hull's order. */
static void centre_of(noctMesh *m)
{
    for (int k = 0; k < 3; ++k) {
        double s = 0;
        for (size_t i = 0; i < m->nhull; ++i)
            s += m->v[3 * m->hull[i] + k];
        m->centre[k] = s / (double)m->nhull;
    }
}

static noctStatus compute_hull(noctMesh *m, noctError *err)
{
    m->hull = NULL;
    m->nhull = 0;
    /* GJK's support function scans the hull's vertices; any superset
     * gives the same support points. A small mesh keeps every vertex:
     * scanning a few dozen costs less than running qhull for each mesh
     * (a gas of oriented boxes is made of meshes that rounding left a hair
     * off convex). */
    if (!m->convex && m->nv > HULL_MIN_VERTICES) {
        /* qhull's tolerances follow the magnitude of the coordinates it
         * is given: it gets the vertices relative to the mesh's least
         * corner and scaled to its size (see noct_scaler), so that the hull
         * depends on neither the mesh's place nor its size. */
        double *rel = malloc(3 * m->nv * sizeof *rel);
        if (rel == NULL)
            return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
        errno = 0;
        FILE *quiet = fopen("/dev/null", "w");
        if (quiet == NULL && errno == ENOMEM) {
            free(rel);
            return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
        }
        bool nomem = false;
        if (quiet != NULL) {
            double emax = 0;
            for (int k = 0; k < 3; ++k)
                emax = noct_max(emax, m->hi[k] - m->lo[k]);
            const noct_scaler sc = noct_scaler_for(emax);
            for (size_t i = 0; i < m->nv; ++i)
                for (int k = 0; k < 3; ++k)
                    rel[3 * i + k] = noct_scaled(&sc, m->v[3 * i + k] - m->lo[k]);
            qhT qh_storage, *qh = &qh_storage;
            char cmd[] = "qhull";
            qh_zero(qh, quiet);
            const int code = qh_new_qhull(qh, 3, (int)m->nv, rel, False, cmd, NULL, quiet);
            if (code == 0) {
                m->hull = malloc((size_t)qh->num_vertices * sizeof *m->hull);
                nomem = m->hull == NULL;
                if (m->hull != NULL) {
                    vertexT *vertex;
                    FORALLvertices
                        m->hull[m->nhull++] = (uint32_t)qh_pointid(qh, vertex->point);
                }
            }
            nomem = nomem || code == qh_ERRmem;
            qh_freeqhull(qh, !qh_ALL);
            /* qh_memfreeshort frees qhull's size and free-list tables only
             * once its setup got as far as LASTsize; a setup that ran out
             * of memory between the two left them to us. */
            if (qh->qhmem.LASTsize == 0) {
                free(qh->qhmem.sizetable);
                free(qh->qhmem.freelists);
                qh->qhmem.sizetable = NULL;
                qh->qhmem.freelists = NULL;
            }
            int curlong, totlong;
            qh_memfreeshort(qh, &curlong, &totlong);
            fclose(quiet);
        }
        free(rel);
        /* Without memory the mesh is not made: a hull of every vertex
         * would give GJK other support points on ties, and so, at the
         * convex level, another answer than the same mesh made with it. */
        if (nomem)
            return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory (convex hull)");
    }
    if (m->hull == NULL) { /* convex, or qhull unavailable: every vertex */
        m->hull = malloc(m->nv * sizeof *m->hull);
        if (m->hull == NULL)
            return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
        for (size_t i = 0; i < m->nv; ++i)
            m->hull[i] = (uint32_t)i;
        m->nhull = m->nv;
    }
    centre_of(m);
    return NOCT_OK;
}

/* ---- packing ----------------------------------------------------------------- */

/* Bytes from offset *at for n elements of size elem aligned to align. */
static size_t take(size_t *at, size_t n, size_t elem, size_t align)
{
    size_t start = (*at + align - 1) / align * align;
    *at = start + n * elem;
    return start;
}

/* Move a finished mesh and its arrays into one allocation (see
 * mesh_internal.h); on failure the mesh stays as it is, which works the
 * same, only with its arrays elsewhere. */
static noctMesh *pack(noctMesh *m)
{
    size_t naxes = m->nsat_faces + m->nsat_edges;
    size_t at = sizeof *m;
    size_t o_axis = take(&at, naxes, sizeof *m->axis, _Alignof(sat_axis));
    size_t o_v = take(&at, 3 * m->nv, sizeof *m->v, _Alignof(double));
    size_t o_plane = take(&at, m->plane ? m->nt : 0, sizeof *m->plane, _Alignof(double));
    size_t o_tri = take(&at, 3 * m->nt, sizeof *m->tri, _Alignof(uint32_t));
    size_t o_nodes = take(&at, m->nnodes, sizeof *m->nodes, _Alignof(bvh_node));
    size_t o_hull = take(&at, m->nhull, sizeof *m->hull, _Alignof(uint32_t));
    size_t o_piece = take(&at, m->npieces, sizeof *m->piece, _Alignof(uint32_t));
    /* Cache-line aligned, so that the box form's lines are the first. */
    char *block = aligned_alloc(64, (at + 63) / 64 * 64);
    if (block == NULL)
        return m;
    noctMesh *p = (noctMesh *)block;
    *p = *m;
    p->packed = true;
    p->axis = naxes ? memcpy(block + o_axis, m->axis, naxes * sizeof *m->axis) : NULL;
    p->v = memcpy(block + o_v, m->v, 3 * m->nv * sizeof *m->v);
    p->plane = m->plane ? memcpy(block + o_plane, m->plane, m->nt * sizeof *m->plane) : NULL;
    p->tri = memcpy(block + o_tri, m->tri, 3 * m->nt * sizeof *m->tri);
    p->nodes = memcpy(block + o_nodes, m->nodes, m->nnodes * sizeof *m->nodes);
    p->hull = memcpy(block + o_hull, m->hull, m->nhull * sizeof *m->hull);
    p->piece = memcpy(block + o_piece, m->piece, m->npieces * sizeof *m->piece);
    noctMeshDestroy(m);
    return p;
}

/* ---- creation ------------------------------------------------------------- */

static uint32_t piece_root(uint32_t *parent, uint32_t i)
{
    while (parent[i] != i) {
        parent[i] = parent[parent[i]]; /* halving */
        i = parent[i];
    }
    return i;
}

/* m's pieces (m->npieces, m->piece): union-find over the vertices through
 * the triangles; a piece is named by the first vertex of its first
 * triangle, in m's triangle order. */
static noctStatus compute_pieces(noctMesh *m, noctError *err)
{
    uint32_t *parent = malloc(m->nv * sizeof *parent);
    uint32_t *first = malloc(m->nv * sizeof *first);
    if (parent == NULL || first == NULL) {
        free(parent);
        free(first);
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    }
    for (uint32_t i = 0; i < m->nv; ++i) {
        parent[i] = i;
        first[i] = UINT32_MAX;
    }
    for (size_t t = 0; t < m->nt; ++t) {
        const uint32_t *v = &m->tri[3 * t];
        for (int c = 1; c < 3; ++c) {
            const uint32_t a = piece_root(parent, v[0]), b = piece_root(parent, v[c]);
            if (a != b)
                parent[a < b ? b : a] = a < b ? a : b;
        }
    }
    size_t n = 0;
    for (size_t t = 0; t < m->nt; ++t) {
        const uint32_t r = piece_root(parent, m->tri[3 * t]);
        if (first[r] == UINT32_MAX) {
            first[r] = m->tri[3 * t];
            ++n;
        }
    }
    m->piece = malloc(n * sizeof *m->piece);
    if (m->piece == NULL) {
        free(parent);
        free(first);
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    }
    m->npieces = 0;
    for (size_t t = 0; t < m->nt; ++t) {
        const uint32_t r = piece_root(parent, m->tri[3 * t]);
        if (first[r] != UINT32_MAX) {
            m->piece[m->npieces++] = first[r];
            first[r] = UINT32_MAX;
        }
    }
    free(parent);
    free(first);
    return NOCT_OK;
}

/* m's bounding box (m->lo, m->hi) from its vertices. */
static void bounds_of(noctMesh *m)
{
    for (int k = 0; k < 3; ++k) {
        m->lo[k] = INFINITY;
        m->hi[k] = -INFINITY;
    }
    for (size_t i = 0; i < m->nv; ++i)
        for (int k = 0; k < 3; ++k) {
            m->lo[k] = noct_min(m->lo[k], m->v[3 * i + k]);
            m->hi[k] = noct_max(m->hi[k], m->v[3 * i + k]);
        }
}

/*
 * The signed volume of m's triangles (times 6 and scaled): false when it
 * has no sign to trust. 6 V = sum over the triangles of det(p0 - lo,
 * p1 - p0, p2 - p0), on differences scaled to the mesh's size (see
 * noct_scaler). Its rounding is bounded by (ntri + 16) half-ulps of the
 * sum of the terms' magnitudes (the differences, the cross product, the
 * dot product and the sum), and underflow adds under 64 2^-1075 a
 * triangle; a volume that does not clear both the tolerance and that
 * bound has no sign to trust.
 */
static bool volume_of(const noctMesh *m, double *volume)
{
    double ext[3], emax = 0;
    for (int k = 0; k < 3; ++k) {
        ext[k] = m->hi[k] - m->lo[k];
        emax = noct_max(emax, ext[k]);
    }
    const noct_scaler sc = noct_scaler_for(emax > 0 ? emax : 1);
    double vol = 0, mag = 0;
    for (size_t t = 0; t < m->nt; ++t) {
        const uint32_t *tri = &m->tri[3 * t];
        const double *p0 = &m->v[3 * tri[0]], *p1 = &m->v[3 * tri[1]],
                     *p2 = &m->v[3 * tri[2]];
        double r[3], a[3], b[3], cr[3];
        for (int k = 0; k < 3; ++k) {
            r[k] = noct_scaled(&sc, p0[k] - m->lo[k]);
            a[k] = noct_scaled(&sc, p1[k] - p0[k]);
            b[k] = noct_scaled(&sc, p2[k] - p0[k]);
        }
        noct_cross3(a, b, cr);
        vol += noct_dot3(r, cr);
        mag += fabs(r[0]) * (fabs(a[1] * b[2]) + fabs(a[2] * b[1])) +
               fabs(r[1]) * (fabs(a[2] * b[0]) + fabs(a[0] * b[2])) +
               fabs(r[2]) * (fabs(a[0] * b[1]) + fabs(a[1] * b[0]));
    }
    double box = noct_scaled(&sc, ext[0]) * noct_scaled(&sc, ext[1]) * noct_scaled(&sc, ext[2]);
    double rounding = (double)(m->nt + 16) * 0x1p-53 * mag + (double)m->nt * 0x1p-1068;
    *volume = vol;
    return fabs(vol) > VOLUME_TOLERANCE * box && fabs(vol) > rounding;
}

/* noctMeshCreate() (surface false) and noctMeshCreateSurface(): the
 * same checks of the input and of each polygon; a surface skips the
 * closedness, orientation and volume, and gets no convexity, filter or
 * box form (mesh_internal.h). */
static noctStatus mesh_create(const double *vertices, size_t nvertices, const uint32_t *sizes,
                              size_t npolygons, const uint32_t *indices, bool surface,
                              noctMesh **mesh, noctError *err)
{
    NOCT_REQUIRE(mesh != NULL);
    NOCT_REQUIRE(nvertices == 0 || vertices != NULL);
    NOCT_REQUIRE(npolygons == 0 || sizes != NULL);
    *mesh = NULL;
    if (surface && (nvertices < 3 || npolygons < 1))
        return noct_fail(err, NOCT_ERR_DEGENERATE, -1, 0,
                         "a surface needs at least 3 vertices and 1 polygon "
                         "(got %zu and %zu)", nvertices, npolygons);
    if (!surface && (nvertices < 4 || npolygons < 4))
        return noct_fail(err, NOCT_ERR_DEGENERATE, -1, 0,
                         "a closed mesh needs at least 4 vertices and 4 "
                         "polygons (got %zu and %zu)", nvertices, npolygons);
    if (nvertices > NOCT_MESH_MAX_VERTICES)
        return noct_fail(err, NOCT_ERR_TOO_LARGE, -1, 0,
                         "%zu vertices (at most %u)", nvertices,
                         (unsigned)NOCT_MESH_MAX_VERTICES);
    size_t nidx = 0, ntri = 0;
    for (size_t p = 0; p < npolygons; ++p) {
        if (sizes[p] < 3)
            return noct_fail(err, NOCT_ERR_DEGENERATE, (long)p, 0,
                             "polygon %zu has %u corners (at least 3)", p,
                             sizes[p]);
        nidx += sizes[p];
        ntri += sizes[p] - 2;
        if (nidx > NOCT_MESH_MAX_INDICES)
            return noct_fail(err, NOCT_ERR_TOO_LARGE, (long)p, 0,
                             "more than %u polygon corners",
                             (unsigned)NOCT_MESH_MAX_INDICES);
    }
    NOCT_REQUIRE(indices != NULL);
    for (size_t i = 0; i < 3 * nvertices; ++i) {
        if (!isfinite(vertices[i]))
            return noct_fail(err, NOCT_ERR_NONFINITE, (long)(i / 3), 0,
                             "vertex %zu: coordinate %c is %g", i / 3,
                             "xyz"[i % 3], vertices[i]);
        if (fabs(vertices[i]) > NOCT_MAX_COORDINATE)
            return noct_fail(err, NOCT_ERR_TOO_LARGE, (long)(i / 3), 0,
                             "vertex %zu: coordinate %c is %g, beyond the limit "
                             "of %g", i / 3, "xyz"[i % 3], vertices[i],
                             NOCT_MAX_COORDINATE);
    }
    for (size_t p = 0, base = 0; p < npolygons; base += sizes[p], ++p) {
        for (uint32_t c = 0; c < sizes[p]; ++c)
            if (indices[base + c] >= nvertices)
                return noct_fail(err, NOCT_ERR_INDEX, (long)p, 0,
                                 "polygon %zu: vertex index %u out of range "
                                 "(%zu vertices)", p, indices[base + c],
                                 nvertices);
        noctStatus st = check_polygon(vertices, &indices[base], sizes[p], p, err);
        if (st != NOCT_OK)
            return st;
    }
    noctStatus st = surface ? NOCT_OK : check_closed(sizes, npolygons, indices, nidx, err);
    if (st != NOCT_OK)
        return st;

    noctMesh *m = calloc(1, sizeof *m);
    if (m == NULL)
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    m->nv = nvertices;
    m->nt = ntri;
    m->v = malloc(3 * nvertices * sizeof *m->v);
    m->tri = malloc(3 * ntri * sizeof *m->tri);
    if (m->v == NULL || m->tri == NULL) {
        noctMeshDestroy(m);
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    }
    m->surface = surface;
    memcpy(m->v, vertices, 3 * nvertices * sizeof *m->v);
    bounds_of(m);
    for (size_t p = 0, base = 0, t = 0; p < npolygons; base += sizes[p], ++p)
        for (uint32_t c = 1; c + 1 < sizes[p]; ++c, ++t) {
            uint32_t *tri = &m->tri[3 * t];
            tri[0] = indices[base];
            tri[1] = indices[base + c];
            tri[2] = indices[base + c + 1];
        }
    double volume = 0;
    if (!surface && !volume_of(m, &volume))
        st = noct_fail(err, NOCT_ERR_DEGENERATE, -1, 0,
                       "the mesh encloses no volume (none over %.2g of its "
                       "bounding box's, or within its rounding; "
                       "noctMeshCreateSurface() takes it as a surface)",
                       VOLUME_TOLERANCE / 6);
    if (st == NOCT_OK && volume < 0) /* inside out: flip every triangle */
        for (size_t i = 0; i < ntri; ++i) {
            uint32_t tmp = m->tri[3 * i + 1];
            m->tri[3 * i + 1] = m->tri[3 * i + 2];
            m->tri[3 * i + 2] = tmp;
        }
    if (st == NOCT_OK)
        st = noct_bvh_build(m, err);
    if (st == NOCT_OK)
        st = compute_pieces(m, err);
    /* a surface: not convex, no filter, planes or box form (calloc) */
    if (st == NOCT_OK && !surface)
        st = compute_convexity(m, err);
    if (st == NOCT_OK && !surface)
        noct_mesh_box_form(m);
    if (st == NOCT_OK)
        st = compute_hull(m, err);
    if (st != NOCT_OK) {
        noctMeshDestroy(m);
        return st;
    }
    m->turn_fine = noct_mesh_turn_fine(m);
    *mesh = pack(m);
    return NOCT_OK;
}

/*
 * noct_mesh_turn_fine(): rotated_fine() (narrowphase_distance.c) asks of
 * each rotated triangle, with e1, e2 its edges from its first corner and
 * d2 the largest squared edge, that |e1 x e2| > 4e-9 d2. A matrix of
 * noctQuatToMatrix() is within 2^-44 (the snap) plus a few ulps of a
 * rotation in each entry, so each rotated coordinate is within
 * delta = 2^-41 A of the exact rotation's (A the mesh's largest
 * coordinate magnitude), and each edge within 2 delta plus its own ulp:
 * dd = 2 delta + 2^-50 L, L = sqrt(d2). The rotation keeps |e1 x e2| and
 * d2; the errors change the cross product by at most 2 dd L + 2 dd L +
 * dd^2 (taken twice over for rounding). So a triangle with
 * |e1 x e2| >= 8e-9 d2 and 8 dd L + 4 dd^2 <= 2e-9 d2 keeps
 * |e1 x e2| > 5.9e-9 d2 (less its own rounding, about 1e-15 d2) under
 * every such rotation. Computed on each triangle scaled by a power of
 * two to its size (as rotated_fine() does), A scaled alike.
 */
bool noct_mesh_turn_fine(const noctMesh *m)
{
    double A = 0;
    for (size_t i = 0; i < 3 * m->nv; ++i)
        A = noct_max(A, fabs(m->v[i]));
    for (size_t t = 0; t < m->nt; ++t) {
        const uint32_t *v = &m->tri[3 * t];
        double e1[3], e2[3], e3[3], n[3];
        noct_sub3(&m->v[3 * v[1]], &m->v[3 * v[0]], e1);
        noct_sub3(&m->v[3 * v[2]], &m->v[3 * v[0]], e2);
        const double big = noct_max(noct_max_abs3(e1), noct_max_abs3(e2));
        if (!(big > 0))
            return false;
        const int ex = -ilogb(big);
        const double f = noct_pow2(ex < 1023 ? (ex > -1022 ? ex : -1022) : 1023);
        for (int k = 0; k < 3; ++k) {
            e1[k] *= f;
            e2[k] *= f;
        }
        const double a = A * f; /* may be infinite: then not fine */
        noct_sub3(e2, e1, e3);
        noct_cross3(e1, e2, n);
        const double d2 = noct_max(noct_dot3(e3, e3),
                                   noct_max(noct_dot3(e1, e1), noct_dot3(e2, e2)));
        const double L = sqrt(d2), dd = 0x1p-40 * a + 0x1p-50 * L;
        if (!(noct_norm3(n) >= 8e-9 * d2) || !(8 * dd * L + 4 * dd * dd <= 2e-9 * d2))
            return false;
    }
    return true;
}

noctStatus noctMeshCreate(const double *vertices, size_t nvertices, const uint32_t *sizes,
                          size_t npolygons, const uint32_t *indices, noctMesh **mesh,
                          noctError *err)
{
    return mesh_create(vertices, nvertices, sizes, npolygons, indices, false, mesh, err);
}

noctStatus noctMeshCreateSurface(const double *vertices, size_t nvertices,
                                 const uint32_t *sizes, size_t npolygons,
                                 const uint32_t *indices, noctMesh **mesh, noctError *err)
{
    return mesh_create(vertices, nvertices, sizes, npolygons, indices, true, mesh, err);
}

/* ---- turning into a recycled copy ---------------------------------------------- */

noct_turn *noct_turn_new(const noctMesh *src)
{
    noct_turn *t = calloc(1, sizeof *t);
    if (t == NULL)
        return NULL;
    t->nt = src->nt;
    t->order = malloc(src->nt * sizeof *t->order);
    t->pos = malloc(src->nt * sizeof *t->pos);
    t->tri = malloc(3 * src->nt * sizeof *t->tri);
    t->centroid = malloc(3 * src->nt * sizeof *t->centroid);
    t->plane = malloc(src->nt * sizeof *t->plane);
    t->edges = malloc(3 * src->nt * sizeof *t->edges);
    if (t->order == NULL || t->pos == NULL || t->tri == NULL || t->centroid == NULL ||
        t->plane == NULL || t->edges == NULL) {
        noct_turn_free(t);
        return NULL;
    }
    directed_edges(src->tri, src->nt, t->edges);
    return t;
}

void noct_turn_free(noct_turn *t)
{
    if (t == NULL)
        return;
    noctMeshDestroy(t->spare);
    free(t->order);
    free(t->pos);
    free(t->tri);
    free(t->centroid);
    free(t->plane);
    free(t->edges);
    free(t);
}

/*
 * noctMeshCreate() of the vertices fl(R v) and src's triangles (as
 * noct_mesh_rotated() calls it), step by step, into m's arrays: the same
 * checks, bounds, volume, BVH (the same builder on the same input),
 * planes, convexity walk, filter axes, box form and hull, each by the
 * same code, so every field it sets is the one noctMeshCreate() would
 * set. Only the directed edges are not sorted again: cmp_dir_edge's key
 * (the edge's vertices, then its first vertex) is unique in a closed,
 * consistently oriented mesh (m was made from these triangles, so they
 * are), so the sorted sequence is the same whatever the triangles' order;
 * the sort kept in t names a triangle by its index in src->tri, which pos
 * turns into its place in m's BVH order, whose triangles are src's with
 * their corners in the same order. The cases that would change m's
 * layout or need more than this (the mesh inside out, or failing a check,
 * a filter with another number of axes, a hull from qhull) return false.
 */
bool noct_mesh_turn_into(const noctMesh *src, const double R[9], noct_turn *t, noctMesh *m)
{
    NOCT_INVARIANT(t->nt == src->nt && m->nt == src->nt && m->nv == src->nv);
    const size_t naxes = m->nsat_faces + m->nsat_edges;
    const bool planes = m->plane != NULL;
    for (size_t i = 0; i < m->nv; ++i)
        noct_rotate(R, &src->v[3 * i], &m->v[3 * i]);
    for (size_t i = 0; i < 3 * m->nv; ++i)
        if (!isfinite(m->v[i]) || fabs(m->v[i]) > NOCT_MAX_COORDINATE)
            return false;
    for (size_t s = 0; s < m->nt; ++s)
        if (check_polygon(m->v, &src->tri[3 * s], 3, s, NULL) != NOCT_OK)
            return false;
    memcpy(m->tri, src->tri, 3 * m->nt * sizeof *m->tri);
    bounds_of(m);
    double volume;
    if (!src->surface && (!volume_of(m, &volume) || volume < 0))
        return false;
    noct_bvh_build_with(m, t->order, t->centroid, t->tri);
    memcpy(m->tri, t->tri, 3 * m->nt * sizeof *m->tri);
    for (uint32_t i = 0; i < m->nt; ++i)
        t->pos[t->order[i]] = i;
    /* as a new mesh has them (calloc) where the box form sets nothing */
    memset(&m->box, 0, sizeof m->box);
    memset(&m->dual, 0, sizeof m->dual);
    m->turn_fine = false; /* not worked out again for a turned copy */
    if (src->surface) { /* no convexity, filter, planes or box form */
        if (m->nv > HULL_MIN_VERTICES || m->nhull != m->nv)
            return false;
        for (size_t i = 0; i < m->nv; ++i)
            m->hull[i] = (uint32_t)i;
        centre_of(m);
        return true;
    }
    planes_of(m, t->plane);
    double sat_face[NOCT_SAT_MAX][3], sat_edge[NOCT_SAT_MAX][3];
    convexity_walk(m, (const double (*)[4])t->plane, t->edges, t->pos, sat_face, sat_edge);
    if ((m->nsat_faces > 0) != planes || m->nsat_faces + m->nsat_edges != naxes)
        return false;
    if (planes)
        memcpy(m->plane, t->plane, m->nt * sizeof *m->plane);
    fill_axes(m, (const double (*)[3])sat_face, (const double (*)[3])sat_edge);
    noct_mesh_box_form(m);
    /* compute_hull(): every vertex, unless qhull is run */
    if ((!m->convex && m->nv > HULL_MIN_VERTICES) || m->nhull != m->nv)
        return false;
    for (size_t i = 0; i < m->nv; ++i)
        m->hull[i] = (uint32_t)i;
    centre_of(m);
    return true;
}

bool noct_mesh_same(const noctMesh *a, const noctMesh *b)
{
    if (a->nv != b->nv || a->nt != b->nt || a->nnodes != b->nnodes || a->nhull != b->nhull ||
        a->nsat_faces != b->nsat_faces || a->nsat_edges != b->nsat_edges ||
        a->convex != b->convex || a->surface != b->surface || a->has_box != b->has_box ||
        a->has_dual != b->has_dual ||
        (a->plane == NULL) != (b->plane == NULL))
        return false;
    const size_t naxes = a->nsat_faces + a->nsat_edges;
    if (memcmp(a->v, b->v, 3 * a->nv * sizeof *a->v) != 0 ||
        memcmp(a->tri, b->tri, 3 * a->nt * sizeof *a->tri) != 0 ||
        memcmp(a->nodes, b->nodes, a->nnodes * sizeof *a->nodes) != 0 ||
        memcmp(a->hull, b->hull, a->nhull * sizeof *a->hull) != 0 ||
        (naxes > 0 && memcmp(a->axis, b->axis, naxes * sizeof *a->axis) != 0) ||
        (a->plane != NULL && memcmp(a->plane, b->plane, a->nt * sizeof *a->plane) != 0) ||
        memcmp(a->lo, b->lo, sizeof a->lo) != 0 || memcmp(a->hi, b->hi, sizeof a->hi) != 0 ||
        memcmp(a->centre, b->centre, sizeof a->centre) != 0)
        return false;
    /* field by field: box_dual has padding */
    const box_form *x = &a->box, *y = &b->box;
    if (a->has_box &&
        (memcmp(x->c, y->c, sizeof x->c) != 0 || memcmp(x->e, y->e, sizeof x->e) != 0 ||
         memcmp(&x->size, &y->size, sizeof x->size) != 0 ||
         memcmp(x->own, y->own, sizeof x->own) != 0 || memcmp(&x->dev, &y->dev, sizeof x->dev) != 0))
        return false;
    const box_dual *g = &a->dual, *h = &b->dual;
    return !a->has_dual ||
           (memcmp(g->g, h->g, sizeof g->g) == 0 && memcmp(&g->gmax, &h->gmax, sizeof g->gmax) == 0 &&
            memcmp(&g->eta, &h->eta, sizeof g->eta) == 0 &&
            memcmp(&g->shrink, &h->shrink, sizeof g->shrink) == 0 &&
            memcmp(g->corner, h->corner, sizeof g->corner) == 0 &&
            memcmp(g->face, h->face, sizeof g->face) == 0 &&
            g->about_origin == h->about_origin && memcmp(g->sign, h->sign, sizeof g->sign) == 0 &&
            memcmp(g->frame_axis, h->frame_axis, sizeof g->frame_axis) == 0 &&
            g->frame_plus == h->frame_plus && g->far_from_flat == h->far_from_flat);
}
