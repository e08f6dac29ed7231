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
/* A built-in box's smallest half-extent is at least this fraction of its
 * largest: a rectangle a by b >= 2^-29 a has corners that turn by
 * ab >= 1.8e-9 (a^2 + b^2), well over the polygon tolerance. */
#define BOX_MIN_RATIO 0x1p-29

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

/* ---- small vector helpers -------------------------------------------- */


/* ---- scaling -------------------------------------------------------------- */

/*
 * The checks compute on differences of coordinates, which a translation
 * that keeps every coordinate exact leaves unchanged, multiplied by the
 * power of two 2^-e that brings the largest to [1/2, 1). Their products
 * of two or three then neither overflow nor underflow where it matters,
 * whatever the mesh's size and place, and so the checks' rounding is
 * relative to the polygon's or the mesh's own size. The scaling is exact
 * except for parts under 2^-1022 of the largest, far below any tolerance.
 */
typedef struct scaler {
    double s0, s1; /* s0 s1 = 2^-e, each a normal power of two */
    int e;
} scaler;

/* 2^k, for k in [-1022, 1023]. */
static double pow2(int k)
{
    uint64_t bits = (uint64_t)(k + 1023) << 52;
    double x;
    memcpy(&x, &bits, sizeof x);
    return x;
}

/* The scaler for magnitudes up to m, finite and positive. A subnormal m
 * needs a factor past the doubles (up to 2^1073), hence two. */
static scaler scaler_for(double m)
{
    scaler s;
    frexp(m, &s.e); /* m = f 2^e, f in [1/2, 1), e in [-1073, 1024] */
    int k = -s.e, k0 = k / 2;
    s.s0 = pow2(k0);
    s.s1 = pow2(k - k0);
    return s;
}

static inline double scaled(const scaler *s, double x)
{
    return x * s->s0 * s->s1;
}

static double max_abs3(const double a[3])
{
    return noct_max(fabs(a[0]), noct_max(fabs(a[1]), fabs(a[2])));
}

/* u = d / |d|, or 0 for d = 0, for d of any magnitude. */
static void unit3(const double d[3], double u[3])
{
    double m = max_abs3(d);
    if (!(m > 0)) {
        u[0] = u[1] = u[2] = 0;
        return;
    }
    scaler s = scaler_for(m);
    double x[3] = {scaled(&s, d[0]), scaled(&s, d[1]), scaled(&s, d[2])};
    double len = noct_norm3(x); /* in [1/2, 2] */
    for (int k = 0; k < 3; ++k)
        u[k] = x[k] / len;
}

/* The unit normal (p1 - p0) x (p2 - p0) / |...|, or 0 if the triangle has
 * none, from the scaled edge vectors: independent of its size and place. */
static void unit_normal(const double p0[3], const double p1[3], const double p2[3],
                        double n[3])
{
    double a[3], b[3], c[3];
    noct_sub3(p1, p0, a);
    noct_sub3(p2, p0, b);
    double m = noct_max(max_abs3(a), max_abs3(b));
    if (!(m > 0)) {
        n[0] = n[1] = n[2] = 0;
        return;
    }
    scaler s = scaler_for(m);
    for (int k = 0; k < 3; ++k) {
        a[k] = scaled(&s, a[k]);
        b[k] = scaled(&s, b[k]);
    }
    noct_cross3(a, b, c);
    unit3(c, n);
}

/* ---- polygon checks ---------------------------------------------------- */

/* Corner i of a polygon relative to its corner 0, scaled. */
static void corner_at(const double *v, const uint32_t *idx, uint32_t i, const scaler *s,
                      double out[3])
{
    const double *p = &v[3 * idx[i]], *o = &v[3 * idx[0]];
    for (int k = 0; k < 3; ++k)
        out[k] = scaled(s, p[k] - o[k]);
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
    const scaler s = scaler_for(m);
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
                           "among them), not 2", he[i].lo, he[i].hi, j - i,
                           j - i == 1 ? "" : "s", he[i].poly);
        else if (he[i].forward == he[i + 1].forward)
            st = noct_fail(err, NOCT_ERR_ORIENTATION, (long)he[i + 1].poly, 0,
                           "polygons %u and %u both run along edge %u-%u in "
                           "the same direction", he[i].poly, he[i + 1].poly,
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

static noctStatus compute_convexity(noctMesh *m, noctError *err)
{
    /* Each triangle's plane: its unit normal (unit_normal(): the same
     * wherever the mesh is and whatever its size) and offset. The planes
     * are kept for the filter; the normals tell real edges and give the
     * face directions. */
    m->plane = malloc(m->nt * sizeof *m->plane);
    size_t ne = 3 * m->nt;
    dir_edge *e = malloc(ne * sizeof *e);
    if (e == NULL || m->plane == NULL) {
        free(e);
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    }
    for (size_t t = 0; t < m->nt; ++t) {
        const double *p0 = &m->v[3 * m->tri[3 * t]];
        unit_normal(p0, &m->v[3 * m->tri[3 * t + 1]], &m->v[3 * m->tri[3 * t + 2]],
                    m->plane[t]);
        m->plane[t][3] = noct_dot3(m->plane[t], p0);
    }
    for (size_t t = 0; t < m->nt; ++t)
        for (int c = 0; c < 3; ++c)
            e[3 * t + c] = (dir_edge){m->tri[3 * t + c],
                                      m->tri[3 * t + (c + 1) % 3],
                                      m->tri[3 * t + (c + 2) % 3], (uint32_t)t};
    qsort(e, ne, sizeof *e, cmp_dir_edge);
    bool convex = true, sat = true;
    double sat_face[NOCT_SAT_MAX][3], sat_edge[NOCT_SAT_MAX][3];
    m->nsat_faces = m->nsat_edges = 0;
    /* Triangles from one polygon share interior edges: still checked, and
     * coplanar (sign 0), which is allowed. A real (non-coplanar) edge is an
     * edge direction for the separating-axis filter. The walk goes on past
     * a concave edge until both answers are known: a rotated box, whose
     * rounded corners bend its faces by an ulp, is not exactly convex, yet
     * the filter needs all its edge directions. */
    for (size_t i = 0; i + 1 < ne && (convex || sat); i += 2) {
        const dir_edge *p = &e[i], *q = &e[i + 1];
        const double *t0 = &m->v[3 * m->tri[3 * p->tri]];
        const double *t1 = &m->v[3 * m->tri[3 * p->tri + 1]];
        const double *t2 = &m->v[3 * m->tri[3 * p->tri + 2]];
        /* q's far vertex must be below or on p's (outward) plane: orient3d
         * >= 0 means below. */
        if (convex && noct_orient3d(t0, t1, t2, &m->v[3 * q->far], NULL) < 0)
            convex = false;
        /* An edge between triangles whose planes differ is an edge of the
         * solid, not a diagonal of a (nearly) flat polygon. */
        if (sat && noct_dot3(m->plane[p->tri], m->plane[q->tri]) < 1 - 1e-9) {
            double d[3], u[3];
            noct_sub3(&m->v[3 * p->b], &m->v[3 * p->a], d);
            unit3(d, u);
            sat = add_direction(sat_edge, &m->nsat_edges, u);
        }
    }
    for (size_t t = 0; t < m->nt && sat; ++t)
        sat = add_direction(sat_face, &m->nsat_faces, m->plane[t]);
    /* The filter needs no convexity to be sound (a solid lies inside the
     * hull of its vertices), only to be useful: small meshes with few
     * directions, typically convex ones. */
    if (!sat || m->nv > 4 * NOCT_SAT_MAX) /* SAT_MAX_VERTICES in narrowphase.c */
        m->nsat_faces = m->nsat_edges = 0;
    free(e);
    m->convex = convex;
    if (m->nsat_faces == 0) { /* no filter, no planes */
        free(m->plane);
        m->plane = NULL;
        return NOCT_OK;
    }
    size_t naxes = m->nsat_faces + m->nsat_edges;
    m->axis = malloc(naxes * sizeof *m->axis);
    if (m->axis == NULL)
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
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
    return NOCT_OK;
}

/* Meshes with more vertices than this get their hull from qhull. */
#define HULL_MIN_VERTICES 32

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
         * corner and scaled to its size (see scaler), so that the hull
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
            const scaler sc = scaler_for(emax);
            for (size_t i = 0; i < m->nv; ++i)
                for (int k = 0; k < 3; ++k)
                    rel[3 * i + k] = scaled(&sc, m->v[3 * i + k] - m->lo[k]);
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
    for (int k = 0; k < 3; ++k) {
        double s = 0;
        for (size_t i = 0; i < m->nhull; ++i)
            s += m->v[3 * m->hull[i] + k];
        m->centre[k] = s / (double)m->nhull;
    }
    return NOCT_OK;
}

/* ---- box form --------------------------------------------------------------- */

/*
 * Describe a mesh of 8 vertices with 3 face and 3 edge directions as a
 * parallelepiped (mesh_internal.h), if its vertices are the 8 corners
 * along its edge directions within a tiny deviation. Only a description
 * the filter can trust is kept: dev bounds the exact deviation of every
 * vertex coordinate from its corner, the rounding of its computation
 * included (3 additions and a difference of magnitudes at most S: well
 * under 8 half-ulps of S).
 */
/* The least float at or above x (x >= 0; +inf past the floats). */
static float float_above(double x)
{
    float f = (float)x;
    return (double)f < x ? nextafterf(f, INFINITY) : f;
}

/* The box form of 8 vertices v (and its dual, if every one of the nt
 * triangles tri lies on a face of the ideal box), given three unit edge
 * directions d: see box_form and box_dual. */
static void box_form_of(const double *v, const double *const d[3], const uint32_t *tri,
                        size_t nt, box_form *b, bool *has_box, box_dual *x, bool *has_dual)
{
    *has_box = *has_dual = false;
    double c[3] = {0, 0, 0};
    for (size_t i = 0; i < 8; ++i)
        for (int k = 0; k < 3; ++k)
            c[k] += v[3 * i + k] / 8;
    double dual[3][3]; /* dual[i].d[j] = (i == j) * det */
    noct_cross3(d[1], d[2], dual[0]);
    noct_cross3(d[2], d[0], dual[1]);
    noct_cross3(d[0], d[1], dual[2]);
    double det = noct_dot3(d[0], dual[0]);
    if (!(fabs(det) > 1e-6))
        return;
    double coef[8][3], h[3] = {0, 0, 0};
    unsigned seen = 0;
    for (size_t i = 0; i < 8; ++i) {
        double r[3];
        noct_sub3(&v[3 * i], c, r);
        unsigned pattern = 0;
        for (int j = 0; j < 3; ++j) {
            coef[i][j] = noct_dot3(r, dual[j]) / det;
            if (coef[i][j] == 0)
                return;
            pattern |= (coef[i][j] > 0 ? 1u : 0u) << j;
            h[j] += fabs(coef[i][j]) / 8;
        }
        seen |= 1u << pattern;
    }
    if (seen != 0xffu)
        return; /* not one vertex at each corner */
    memcpy(b->c, c, sizeof c);
    for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k)
            b->e[j][k] = h[j] * d[j][k];
    double dev = 0, S = 0, V = 0;
    for (size_t i = 0; i < 8; ++i)
        for (int k = 0; k < 3; ++k) {
            double corner = c[k], mag = fabs(c[k]);
            for (int j = 0; j < 3; ++j) {
                corner += coef[i][j] > 0 ? b->e[j][k] : -b->e[j][k];
                mag += fabs(b->e[j][k]);
            }
            dev = fmax(dev, fabs(v[3 * i + k] - corner));
            S = fmax(S, mag);
            V = fmax(V, fabs(v[3 * i + k]));
        }
    dev = dev * (1 + 0x1p-50) + 8 * 0x1p-53 * (S + V);
    if (!(dev <= 1e-9 * fmax(h[0], fmax(h[1], h[2]))))
        return; /* too far from a box to be worth the description */
    b->size = S + dev;
    b->dev = float_above(dev);
    for (int i = 0; i < 3; ++i)
        b->own[i] = float_above(fabs(noct_dot3(b->e[i], b->e[0])) + fabs(noct_dot3(b->e[i], b->e[1])) +
                                fabs(noct_dot3(b->e[i], b->e[2])));
    *has_box = true;

    /* The dual, for the witness: every triangle on a face of the ideal box
     * (its three corners agree in one sign), and a well-conditioned box. */
    for (size_t t = 0; t < nt; ++t) {
        unsigned agree = 7;
        for (int corner = 1; corner < 3; ++corner) {
            const double *q = coef[tri[3 * t + corner]];
            const double *q0 = coef[tri[3 * t]];
            for (int j = 0; j < 3; ++j)
                if ((q[j] > 0) != (q0[j] > 0))
                    agree &= ~(1u << j);
        }
        if (agree == 0)
            return;
    }
    double eta = 0, mag = 0, gmax = 0;
    for (int i = 0; i < 3; ++i) {
        for (int k = 0; k < 3; ++k)
            x->g[i][k] = dual[i][k] / (det * h[i]);
        gmax = fmax(gmax, fabs(x->g[i][0]) + fabs(x->g[i][1]) + fabs(x->g[i][2]));
    }
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            eta = fmax(eta, fabs(noct_dot3(x->g[i], b->e[j]) - (i == j)));
            for (int k = 0; k < 3; ++k)
                mag = fmax(mag, fabs(x->g[i][k] * b->e[j][k]));
        }
    eta = eta * (1 + 0x1p-50) + 16 * 0x1p-53 * 3 * mag;
    if (!(eta <= 1e-14))
        return;
    x->eta = eta;
    x->gmax = gmax * (1 + 0x1p-50);
    x->shrink = float_above((2 * x->gmax * (double)b->dev + 8 * eta + 2e-15) * (1 + 0x1p-50));
    *has_dual = true;
}

static void compute_box_form(noctMesh *m)
{
    m->has_box = m->has_dual = false;
    if (m->nv != 8 || m->nsat_faces != 3 || m->nsat_edges != 3)
        return;
    const double *const d[3] = {m->axis[3].u, m->axis[4].u, m->axis[5].u};
    box_form_of(m->v, d, m->tri, m->nt, &m->box, &m->has_box, &m->dual, &m->has_dual);
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

void noct_box_corners(const double half[3], const double R[9], double v[24])
{
    for (int i = 0; i < 8; ++i) {
        const double local[3] = {(i & 4) ? half[0] : -half[0], (i & 2) ? half[1] : -half[1],
                                 (i & 1) ? half[2] : -half[2]};
        noct_rotate(R, local, &v[3 * i]);
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
        unit3(col, u[j]);
    }
    const double *const d[3] = {u[0], u[1], u[2]};
    box_form b;
    box_dual x;
    bool has_box, has_dual;
    box_form_of(v, d, BOX_TRIANGLES, 12, &b, &has_box, &x, &has_dual);
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
    static const uint32_t HULL[8] = {0, 1, 2, 3, 4, 5, 6, 7};
    memset(view, 0, sizeof *view);
    memset(leaf, 0, sizeof *leaf);
    view->nv = 8;
    view->v = (double *)v;                /* read only, as the view's contract */
    view->nt = 12;
    view->tri = (uint32_t *)BOX_TRIANGLES; /* the same */
    view->nhull = 8;
    view->hull = (uint32_t *)HULL;
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
    noctMeshDestroy(m);
    return p;
}

/* ---- creation ------------------------------------------------------------- */

noctStatus noctMeshCreate(const double *vertices, size_t nvertices,
                          const uint32_t *sizes, size_t npolygons,
                          const uint32_t *indices, noctMesh **mesh,
                          noctError *err)
{
    NOCT_REQUIRE(mesh != NULL);
    NOCT_REQUIRE(nvertices == 0 || vertices != NULL);
    NOCT_REQUIRE(npolygons == 0 || sizes != NULL);
    *mesh = NULL;
    if (nvertices < 4 || npolygons < 4)
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
    noctStatus st = check_closed(sizes, npolygons, indices, nidx, err);
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
    memcpy(m->v, vertices, 3 * nvertices * sizeof *m->v);
    for (int k = 0; k < 3; ++k) {
        m->lo[k] = INFINITY;
        m->hi[k] = -INFINITY;
    }
    for (size_t i = 0; i < nvertices; ++i)
        for (int k = 0; k < 3; ++k) {
            m->lo[k] = noct_min(m->lo[k], m->v[3 * i + k]);
            m->hi[k] = noct_max(m->hi[k], m->v[3 * i + k]);
        }
    /* Fan triangulation, and the signed volume to fix the orientation:
     * 6 V = sum over the triangles of det(p0 - lo, p1 - p0, p2 - p0), on
     * differences scaled to the mesh's size (see scaler). Its rounding is
     * bounded by (ntri + 16) half-ulps of the sum of the terms'
     * magnitudes (the differences, the cross product, the dot product and
     * the sum), and underflow adds under 64 2^-1075 a triangle; a volume
     * that does not clear both the tolerance and that bound has no sign to
     * trust. */
    double ext[3], emax = 0;
    for (int k = 0; k < 3; ++k) {
        ext[k] = m->hi[k] - m->lo[k];
        emax = noct_max(emax, ext[k]);
    }
    const scaler sc = scaler_for(emax > 0 ? emax : 1);
    double volume = 0, mag = 0;
    size_t t = 0;
    for (size_t p = 0, base = 0; p < npolygons; base += sizes[p], ++p) {
        for (uint32_t c = 1; c + 1 < sizes[p]; ++c, ++t) {
            uint32_t *tri = &m->tri[3 * t];
            tri[0] = indices[base];
            tri[1] = indices[base + c];
            tri[2] = indices[base + c + 1];
            const double *p0 = &m->v[3 * tri[0]], *p1 = &m->v[3 * tri[1]],
                         *p2 = &m->v[3 * tri[2]];
            double r[3], a[3], b[3], cr[3];
            for (int k = 0; k < 3; ++k) {
                r[k] = scaled(&sc, p0[k] - m->lo[k]);
                a[k] = scaled(&sc, p1[k] - p0[k]);
                b[k] = scaled(&sc, p2[k] - p0[k]);
            }
            noct_cross3(a, b, cr);
            volume += noct_dot3(r, cr);
            mag += fabs(r[0]) * (fabs(a[1] * b[2]) + fabs(a[2] * b[1])) +
                   fabs(r[1]) * (fabs(a[2] * b[0]) + fabs(a[0] * b[2])) +
                   fabs(r[2]) * (fabs(a[0] * b[1]) + fabs(a[1] * b[0]));
        }
    }
    double box = scaled(&sc, ext[0]) * scaled(&sc, ext[1]) * scaled(&sc, ext[2]);
    double rounding = (double)(ntri + 16) * 0x1p-53 * mag + (double)ntri * 0x1p-1068;
    if (!(fabs(volume) > VOLUME_TOLERANCE * box) || !(fabs(volume) > rounding))
        st = noct_fail(err, NOCT_ERR_DEGENERATE, -1, 0,
                       "the mesh encloses no volume (none over %.2g of its "
                       "bounding box's, or within its rounding)",
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
        st = compute_convexity(m, err);
    if (st == NOCT_OK)
        compute_box_form(m);
    if (st == NOCT_OK)
        st = compute_hull(m, err);
    if (st != NOCT_OK) {
        noctMeshDestroy(m);
        return st;
    }
    *mesh = pack(m);
    return NOCT_OK;
}

static bool positive_finite(double x)
{
    return isfinite(x) && x > 0;
}

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
