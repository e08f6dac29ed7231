/* SPDX-License-Identifier: MIT */
/*
 * Check suite for continuous collision detection (noctCollideSwept(),
 * narrowphase.h) against the test's own oracle, in exact rational
 * arithmetic (GMP's mpq_t on the very doubles the library is given:
 * mpq_set_d is exact). The oracle shares nothing with the library but the
 * contract: it keeps its own copy of each mesh's vertices and triangles.
 *
 * The oracle. A is placed at fl(v + ta0), B at fl(w + tb0); in B's frame A
 * moves by s D, D = (ta1 - ta0) - (tb1 - tb0) taken exactly, s in [0, 1].
 *
 *  - Start. The closed solids meet at s = 0 iff their boundaries meet or
 *    one contains a vertex of the other. Two closed triangles meet iff an
 *    edge of one meets the other (an extreme point of their convex
 *    intersection lies on the boundary of one of them), so the boundaries
 *    meet iff some edge of one meets some triangle of the other. If the
 *    boundaries are disjoint the solids meet iff a vertex of one lies
 *    inside the other (the boundary of their intersection lies in the two
 *    boundaries, so one boundary meets the other's interior, and a
 *    connected boundary that does not cross the other lies wholly inside
 *    it; every vertex is tried, so several shells would do too), decided
 *    by the parity of a ray's crossings, the ray redrawn whenever it
 *    passes through an edge or lies in a triangle's plane (the vertex is
 *    on no triangle there, so no crossing is at the ray's origin).
 *
 *  - Motion. If the solids are apart at s = 0, the first contact s* > 0
 *    is the least over the pairs of triangles, one of each, of the first
 *    time s1 > 0 at which that pair meets. At s1 the pair's intersection,
 *    convex, has an extreme point on an edge of one that lies in the
 *    other triangle; take an extreme point q of that edge's intersection
 *    with that triangle. Either q is an endpoint of the edge (a vertex on
 *    a triangle), or q is on the triangle's boundary (an edge on an
 *    edge), or q is inside both the edge and the triangle, and then the
 *    edge crosses the triangle's plane transversally there (an edge lying
 *    in the plane would have more of its points in the triangle on both
 *    sides of q): a crossing that a small translation keeps, so the pair
 *    would meet before s1. Hence s* is the least, over every vertex-
 *    triangle pair (both ways) and every edge-edge pair (triangulation
 *    edges, fan diagonals included), of the first time that pair touches;
 *    each pair touching is a contact of the solids, so no pair touches
 *    before s*. (Nothing here needs the solids to have volume: it holds
 *    for placements that rounding flattened, and zero-area triangles, a
 *    segment's or a point's worth, are covered by their edges.)
 *
 *  - One pair, exactly, degenerate or not. Its contacts are the points of
 *    a polytope in a few unknowns: for a vertex p against a triangle
 *    (u, v, w), (alpha, beta, gamma, s) with alpha u + beta v + gamma w -
 *    s D = p, alpha + beta + gamma = 1, alpha, beta, gamma >= 0 and
 *    0 <= s <= 1; for two edges p0 + lambda e + s D = q0 + mu f with
 *    lambda, mu, s in [0, 1]. The first contact is the least s over that
 *    polytope, a bounded one, so it is reached at a vertex: a point where
 *    the equations and the bounds held tight determine every unknown. The
 *    oracle solves the equations alone first: when they determine the
 *    unknowns (the generic case, motion transversal to the face, edges not
 *    parallel to a common plane with D), the polytope is that point or
 *    nothing; otherwise (motion parallel to a face, coplanar or parallel
 *    edges, a vertex sliding in a triangle's plane and entering it across
 *    an edge) it tries every choice of unknowns held at a bound, by exact
 *    Gaussian elimination, and keeps the least s of the solutions that
 *    satisfy every bound. No case analysis of the degeneracies is needed,
 *    and none can be missed.
 *
 *  - End. The meshes placed at fl(v + ta1) and fl(w + tb1) are tested as
 *    the start is. The verdict is (some s* exists) or (the end poses meet).
 *
 * Against it, the library's verdict must agree exactly, and its time t be
 * a multiple of 2^-52 with s* in [t - 2^-52, t] (0 and #NOCT_SWEEP_START
 * when s* = 0; 1 and #NOCT_SWEEP_END when only the end poses meet); where
 * the test knows the library's vertex numbers, the reported features must
 * themselves first touch at s*. Cases: random tetrahedra (grid and random
 * doubles), boxes of both constructors, an L-shaped non-convex mesh,
 * grazes, sliding contact and one ulp of gap, contact at the start, thin
 * walls crossed in one step at high speed; and the invariances (swapping
 * the meshes, moving all four translations or both ends by an exact
 * vector, scaling by powers of two from 2^-332 to 2^332, offsets to 2^40).
 */
#include <check.h>
#include <gmp.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <noctree/mesh.h>
#include <noctree/narrowphase.h>

#include "testgmp.h"
#include "testutil.h"

/* ---- the test's meshes ----------------------------------------------------- */

#define TM_MAXV 16
#define TM_MAXT 32
#define TM_MAXE 48

/* A mesh as the oracle sees it: the vertices and the triangles of the
 * solid, the edges of those triangles, and the library's mesh. */
typedef struct tmesh {
    noctMesh *m;
    size_t nv, nt, ne;
    double v[3 * TM_MAXV];
    uint32_t tri[3 * TM_MAXT];
    uint32_t edge[2 * TM_MAXE];
    bool numbered; /* the library numbers the vertices as v lists them */
} tmesh;

static void tm_add_edge(tmesh *t, uint32_t i, uint32_t j)
{
    if (i > j) {
        uint32_t k = i; i = j; j = k;
    }
    for (size_t e = 0; e < t->ne; ++e)
        if (t->edge[2 * e] == i && t->edge[2 * e + 1] == j)
            return;
    ck_assert(t->ne < TM_MAXE);
    t->edge[2 * t->ne] = i;
    t->edge[2 * t->ne + 1] = j;
    t->ne++;
}

/* The geometry of polygons, each split into a fan from its first corner
 * (for a planar convex polygon any split is the polygon). */
static void tm_geometry(tmesh *t, const double *v, size_t nv, const uint32_t *sizes, size_t np,
                        const uint32_t *idx)
{
    memset(t, 0, sizeof *t);
    ck_assert(nv <= TM_MAXV);
    memcpy(t->v, v, 3 * nv * sizeof(double));
    t->nv = nv;
    size_t k = 0;
    for (size_t p = 0; p < np; ++p) {
        for (uint32_t c = 1; c + 1 < sizes[p]; ++c) {
            ck_assert(t->nt < TM_MAXT);
            uint32_t *tr = &t->tri[3 * t->nt++];
            tr[0] = idx[k];
            tr[1] = idx[k + c];
            tr[2] = idx[k + c + 1];
            tm_add_edge(t, tr[0], tr[1]);
            tm_add_edge(t, tr[1], tr[2]);
            tm_add_edge(t, tr[2], tr[0]);
        }
        k += sizes[p];
    }
}

/* Polygons made into a library mesh too; false if the library refuses
 * them (a degenerate random tetrahedron). */
static bool tm_create(tmesh *t, const double *v, size_t nv, const uint32_t *sizes, size_t np,
                      const uint32_t *idx)
{
    tm_geometry(t, v, nv, sizes, np, idx);
    t->numbered = true;
    return noctMeshCreate(v, nv, sizes, np, idx, &t->m, NULL) == NOCT_OK;
}

static void tm_free(tmesh *t)
{
    noctMeshDestroy(t->m);
    t->m = NULL;
}

static bool tm_tet(tmesh *t, const double p[12])
{
    static const uint32_t sizes[4] = {3, 3, 3, 3};
    static const uint32_t idx[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    return tm_create(t, p, 4, sizes, 4, idx);
}

/* Box corner i has the high x if bit 0, high y if bit 1, high z if bit 2;
 * the faces counter-clockwise from outside. */
static const uint32_t box_quads[24] = {0, 4, 6, 2, 1, 3, 7, 5, 0, 1, 5, 4,
                                       2, 6, 7, 3, 0, 2, 3, 1, 4, 5, 7, 6};
static const uint32_t box_sizes[6] = {4, 4, 4, 4, 4, 4};

/* noctMeshCreateBox(hx, hy, hz): the box [-h, h] (its vertex numbers are
 * the library's own). */
static void tm_box(tmesh *t, double hx, double hy, double hz)
{
    double v[24];
    for (int i = 0; i < 8; ++i) {
        v[3 * i] = i & 1 ? hx : -hx;
        v[3 * i + 1] = i & 2 ? hy : -hy;
        v[3 * i + 2] = i & 4 ? hz : -hz;
    }
    tm_geometry(t, v, 8, box_sizes, 6, box_quads);
    ck_assert_int_eq(noctMeshCreateBox(hx, hy, hz, &t->m, NULL), NOCT_OK);
}

/* Is the double x equal to the real sum of the n terms p[k] * q[k]? */
static bool exact_dot(double x, const double *p, const double *q, int n)
{
    mpq_t s, a, b;
    mpq_inits(s, a, b, NULL);
    for (int k = 0; k < n; ++k) {
        mpq_set_d(a, p[k]);
        mpq_set_d(b, q[k]);
        mpq_mul(a, a, b);
        mpq_add(s, s, a);
    }
    mpq_set_d(a, x);
    bool eq = mpq_equal(s, a) != 0;
    mpq_clears(s, a, b, NULL);
    return eq;
}

/* noctMeshCreateOrientedBox(h, R) for an R whose entries are multiples of
 * 2^-36 and h multiples of 2^-4 (scaled by a power of two), so that every
 * corner R (+-h) is a double, checked: the library's corners, whatever
 * way it rounds, are then these, and the solid is a parallelepiped. */
static void tm_oriented_box(tmesh *t, const double h[3], const double R[9])
{
    double v[24];
    for (int i = 0; i < 8; ++i) {
        const double c[3] = {i & 1 ? h[0] : -h[0], i & 2 ? h[1] : -h[1], i & 4 ? h[2] : -h[2]};
        for (int r = 0; r < 3; ++r) {
            v[3 * i + r] = R[3 * r] * c[0] + R[3 * r + 1] * c[1] + R[3 * r + 2] * c[2];
            ck_assert(exact_dot(v[3 * i + r], &R[3 * r], c, 3));
        }
    }
    tm_geometry(t, v, 8, box_sizes, 6, box_quads);
    ck_assert_int_eq(noctMeshCreateOrientedBox(h, R, &t->m, NULL), NOCT_OK);
}

/* A random rotation rounded to multiples of 2^-36 (orthonormal within
 * about 1e-10, inside the constructor's 1e-9). */
static void dyadic_rotation(uint64_t *rng, double R[9])
{
    noctQuat q;
    test_random_quat(rng, &q);
    const double w = q.w, x = q.x, y = q.y, z = q.z;
    const double M[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
                         2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                         2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)};
    for (int k = 0; k < 9; ++k)
        R[k] = ldexp(nearbyint(ldexp(M[k], 36)), -36);
}

/* A box of half-extents h rotated by R, its corners rounded to double and
 * its faces given as two triangles each (so the solid is exactly those
 * triangles however the corners round), through noctMeshCreate(). */
static void tm_rounded_box(tmesh *t, const double h[3], const double R[9], double scale)
{
    double v[24];
    uint32_t idx[36], sizes[12];
    for (int i = 0; i < 8; ++i) {
        const double c[3] = {i & 1 ? h[0] : -h[0], i & 2 ? h[1] : -h[1], i & 4 ? h[2] : -h[2]};
        for (int r = 0; r < 3; ++r)
            v[3 * i + r] = scale * (R[3 * r] * c[0] + R[3 * r + 1] * c[1] + R[3 * r + 2] * c[2]);
    }
    for (int f = 0; f < 6; ++f) {
        const uint32_t *q = &box_quads[4 * f];
        const uint32_t two[6] = {q[0], q[1], q[2], q[0], q[2], q[3]};
        memcpy(&idx[6 * f], two, sizeof two);
        sizes[2 * f] = sizes[2 * f + 1] = 3;
    }
    ck_assert(tm_create(t, v, 8, sizes, 12, idx));
}

/* The L-shaped prism of make_ell() (testutil.h), scaled by s: the L
 * (0,0) (2,0) (2,1) (1,1) (1,2) (0,2) less (1,1), z from -1/2 to 1/2; its
 * top and bottom each two convex quadrilaterals. */
static void tm_ell(tmesh *t, double s)
{
    static const double P[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
    double v[36];
    for (int i = 0; i < 12; ++i) {
        v[3 * i] = s * (P[i % 6][0] - 1);
        v[3 * i + 1] = s * (P[i % 6][1] - 1);
        v[3 * i + 2] = s * (i < 6 ? -0.5 : 0.5);
    }
    uint32_t sizes[10], idx[40];
    static const uint32_t caps[16] = {6, 7, 8, 9, 6, 9, 10, 11, 0, 3, 2, 1, 0, 5, 4, 3};
    memcpy(idx, caps, sizeof caps);
    for (int f = 0; f < 10; ++f)
        sizes[f] = 4;
    for (uint32_t i = 0; i < 6; ++i) {
        const uint32_t j = (i + 1) % 6;
        const uint32_t side[4] = {i, j, j + 6, i + 6};
        memcpy(&idx[16 + 4 * i], side, sizeof side);
    }
    ck_assert(tm_create(t, v, 12, sizes, 10, idx));
    ck_assert(!noctMeshIsConvex(t->m));
}

/* ---- the oracle -------------------------------------------------------------- */

typedef struct qpt {
    mpq_t x[3];
} qpt;

/* A small linear program: unknowns z[0..n), equations a z = r (m rows),
 * each z[j] >= 0, and z[j] <= 1 where hi[j]. */
typedef struct lp {
    int n, m;
    mpq_t a[4][4], r[4];
    bool hi[4];
} lp;

typedef struct oracle {
    const tmesh *A, *B;
    qpt pa[TM_MAXV], pa1[TM_MAXV], pb[TM_MAXV]; /* A at the start, A moved by D, B */
    qpt ea[TM_MAXV], eb[TM_MAXV];               /* the end placements */
    qpt pm[TM_MAXV];                            /* A moved by s D */
    mpq_t sample;
    mpq_t d[3];
    lp sys;
    mpq_t g[4][5], z[4], t, u, best;
    qpt ray, w0, w1, cr;
    /* the verdict */
    bool start, swept, end, colliding;
    mpq_t first; /* s* when swept */
} oracle;

static oracle *oracle_get(void)
{
    static oracle *o;
    if (o != NULL)
        return o;
    o = calloc(1, sizeof *o);
    ck_assert(o != NULL);
    qpt *sets[6] = {o->pa, o->pa1, o->pb, o->ea, o->eb, o->pm};
    for (int s = 0; s < 6; ++s)
        for (int i = 0; i < TM_MAXV; ++i)
            for (int k = 0; k < 3; ++k)
                mpq_init(sets[s][i].x[k]);
    for (int k = 0; k < 3; ++k) {
        mpq_init(o->d[k]);
        mpq_init(o->ray.x[k]);
        mpq_init(o->w0.x[k]);
        mpq_init(o->w1.x[k]);
        mpq_init(o->cr.x[k]);
    }
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j)
            mpq_init(o->sys.a[i][j]);
        for (int j = 0; j < 5; ++j)
            mpq_init(o->g[i][j]);
        mpq_init(o->sys.r[i]);
        mpq_init(o->z[i]);
    }
    mpq_inits(o->t, o->u, o->best, o->first, o->sample, NULL);
    return o;
}

/* Gaussian elimination to reduced row echelon form of the m x k system
 * g (column k the right-hand side); its rank, or -1 if inconsistent. */
static int lp_gauss(oracle *o, int m, int k)
{
    int row = 0;
    for (int c = 0; c < k && row < m; ++c) {
        int p = row;
        while (p < m && mpq_sgn(o->g[p][c]) == 0)
            ++p;
        if (p == m)
            continue;
        if (p != row)
            for (int j = 0; j <= k; ++j)
                mpq_swap(o->g[p][j], o->g[row][j]);
        for (int j = k; j >= c; --j)
            mpq_div(o->g[row][j], o->g[row][j], o->g[row][c]);
        for (int i = 0; i < m; ++i) {
            if (i == row || mpq_sgn(o->g[i][c]) == 0)
                continue;
            for (int j = k; j >= c; --j) {
                mpq_mul(o->t, o->g[i][c], o->g[row][j]);
                mpq_sub(o->g[i][j], o->g[i][j], o->t);
            }
        }
        ++row;
    }
    for (int i = row; i < m; ++i)
        if (mpq_sgn(o->g[i][k]) != 0)
            return -1;
    return row;
}

enum { LP_INCONSISTENT, LP_NOT_UNIQUE, LP_OUTSIDE, LP_POINT };

/* Hold z[j] at 0 (code 1) or 1 (code 2), the others free (code 0), and
 * solve the equations: LP_POINT with o->z the solution if it is unique
 * and within every bound. */
static int lp_try(oracle *o, const int *code)
{
    const lp *p = &o->sys;
    int free_col[4], k = 0;
    for (int j = 0; j < p->n; ++j)
        if (code[j] == 0)
            free_col[k++] = j;
    for (int i = 0; i < p->m; ++i) {
        for (int c = 0; c < k; ++c)
            mpq_set(o->g[i][c], p->a[i][free_col[c]]);
        mpq_set(o->g[i][k], p->r[i]);
        for (int j = 0; j < p->n; ++j)
            if (code[j] == 2)
                mpq_sub(o->g[i][k], o->g[i][k], p->a[i][j]);
    }
    const int rank = lp_gauss(o, p->m, k);
    if (rank < 0)
        return LP_INCONSISTENT;
    if (rank < k)
        return LP_NOT_UNIQUE;
    for (int j = 0; j < p->n; ++j)
        if (code[j] != 0)
            mpq_set_ui(o->z[j], code[j] == 2, 1);
    for (int c = 0; c < k; ++c)
        mpq_set(o->z[free_col[c]], o->g[c][k]); /* reduced: row c has pivot c */
    for (int j = 0; j < p->n; ++j) {
        if (mpq_sgn(o->z[j]) < 0)
            return LP_OUTSIDE;
        if (p->hi[j] && mpq_cmp_ui(o->z[j], 1, 1) > 0)
            return LP_OUTSIDE;
    }
    return LP_POINT;
}

/* The least z[obj] over the polytope of o->sys into o->best (obj < 0:
 * whether it is empty, alone); false if it is empty. */
static bool lp_min(oracle *o, int obj)
{
    const int n = o->sys.n;
    int code[4] = {0, 0, 0, 0};
    const int whole = lp_try(o, code);
    if (whole == LP_INCONSISTENT || whole == LP_OUTSIDE)
        return false;
    if (whole == LP_POINT) {
        if (obj >= 0)
            mpq_set(o->best, o->z[obj]);
        return true;
    }
    /* The equations leave a line or a plane of solutions: visit the
     * polytope's vertices, every choice of unknowns held at a bound. */
    int combos = 1;
    for (int j = 0; j < n; ++j)
        combos *= o->sys.hi[j] ? 3 : 2;
    bool found = false;
    for (int c = 1; c < combos; ++c) {
        int rest = c;
        for (int j = 0; j < n; ++j) {
            const int base = o->sys.hi[j] ? 3 : 2;
            code[j] = rest % base;
            rest /= base;
        }
        if (lp_try(o, code) != LP_POINT)
            continue;
        if (obj < 0)
            return true;
        if (!found || mpq_cmp(o->z[obj], o->best) < 0)
            mpq_set(o->best, o->z[obj]);
        found = true;
    }
    return found;
}

static void place(qpt *out, const tmesh *t, const double tr[3])
{
    for (size_t i = 0; i < t->nv; ++i)
        for (int k = 0; k < 3; ++k)
            mpq_set_d(out[i].x[k], t->v[3 * i + k] + tr[k]);
}

/* Do the boxes of two lists of points overlap (closed)? Each list is the
 * points p[idx[0..n)] (and q[idx[..]] too when q is not NULL). */
static bool boxes_meet(const qpt *p, const qpt *q, const uint32_t *idx, int n, const qpt *r,
                       const uint32_t *jdx, int m)
{
    for (int k = 0; k < 3; ++k) {
        const mpq_t *lo = &p[idx[0]].x[k], *hi = lo;
        for (int i = 0; i < n; ++i) {
            const mpq_t *c[2] = {&p[idx[i]].x[k], q != NULL ? &q[idx[i]].x[k] : NULL};
            for (int h = 0; h < 2 && c[h] != NULL; ++h) {
                if (mpq_cmp(*c[h], *lo) < 0)
                    lo = c[h];
                if (mpq_cmp(*c[h], *hi) > 0)
                    hi = c[h];
            }
        }
        bool below = true, above = true;
        for (int j = 0; j < m; ++j) {
            below = below && mpq_cmp(r[jdx[j]].x[k], *lo) < 0;
            above = above && mpq_cmp(r[jdx[j]].x[k], *hi) > 0;
        }
        if (below || above)
            return false;
    }
    return true;
}

/* Does the edge x0 x1 of one placed mesh meet the triangle u v w of the
 * other (closed)? lambda (x1 - x0) - alpha u - beta v - gamma w = -x0,
 * alpha + beta + gamma = 1. */
static bool edge_meets_triangle(oracle *o, const qpt *x, const uint32_t *e, const qpt *y,
                                const uint32_t *tr)
{
    if (!boxes_meet(x, NULL, e, 2, y, tr, 3))
        return false;
    lp *p = &o->sys;
    p->n = 4;
    p->m = 4;
    p->hi[0] = true;
    p->hi[1] = p->hi[2] = p->hi[3] = false;
    for (int k = 0; k < 3; ++k) {
        mpq_sub(p->a[k][0], x[e[1]].x[k], x[e[0]].x[k]);
        for (int c = 0; c < 3; ++c)
            mpq_neg(p->a[k][1 + c], y[tr[c]].x[k]);
        mpq_neg(p->r[k], x[e[0]].x[k]);
    }
    mpq_set_ui(p->a[3][0], 0, 1);
    for (int c = 1; c < 4; ++c)
        mpq_set_ui(p->a[3][c], 1, 1);
    mpq_set_ui(p->r[3], 1, 1);
    return lp_min(o, -1);
}

/* o->t = a . (b x c), with o->cr as scratch. */
static void triple(oracle *o, const qpt *a, const qpt *b, const qpt *c)
{
    for (int k = 0; k < 3; ++k) {
        const int i = (k + 1) % 3, j = (k + 2) % 3;
        mpq_mul(o->cr.x[k], b->x[i], c->x[j]);
        mpq_mul(o->u, b->x[j], c->x[i]);
        mpq_sub(o->cr.x[k], o->cr.x[k], o->u);
    }
    mpq_mul(o->t, a->x[0], o->cr.x[0]);
    for (int k = 1; k < 3; ++k) {
        mpq_mul(o->u, a->x[k], o->cr.x[k]);
        mpq_add(o->t, o->t, o->u);
    }
}

/* Is the point p inside the closed solid of the placed mesh y (p is on
 * none of its triangles)? The parity of the crossings of rays from p,
 * each ray given up for the next if it passes through an edge or a vertex
 * or lies in a triangle's plane. */
static bool inside(oracle *o, const qpt *p, const tmesh *m, const qpt *y)
{
    static const double dirs[][3] = {
        {0.7390851332151607, 0.3183098861837907, 0.5772156649015329},
        {-0.2247448713915890, 0.8414709848078965, -0.4142135623730950},
        {0.1234567890123456, -0.6180339887498949, 0.9876543210987654},
        {-0.9, 0.35, 0.0625},
        {0.3, -0.2, -0.95},
        {0.01, 0.02, 1.0},
    };
    for (size_t r = 0; r < sizeof dirs / sizeof dirs[0]; ++r) {
        for (int k = 0; k < 3; ++k)
            mpq_set_d(o->ray.x[k], dirs[r][k]);
        int crossings = 0;
        bool clean = true;
        for (size_t f = 0; f < m->nt && clean; ++f) {
            const uint32_t *tr = &m->tri[3 * f];
            for (int k = 0; k < 3; ++k) {
                mpq_sub(o->w0.x[k], y[tr[1]].x[k], y[tr[0]].x[k]);
                mpq_sub(o->w1.x[k], y[tr[2]].x[k], y[tr[0]].x[k]);
            }
            triple(o, &o->ray, &o->w0, &o->w1); /* o->cr: the normal */
            if (mpq_sgn(o->cr.x[0]) == 0 && mpq_sgn(o->cr.x[1]) == 0 &&
                mpq_sgn(o->cr.x[2]) == 0)
                continue; /* a zero-area triangle bounds nothing */
            int sg[3];
            for (int c = 0; c < 3; ++c) {
                for (int k = 0; k < 3; ++k) {
                    mpq_sub(o->w0.x[k], y[tr[c]].x[k], p->x[k]);
                    mpq_sub(o->w1.x[k], y[tr[(c + 1) % 3]].x[k], p->x[k]);
                }
                triple(o, &o->ray, &o->w0, &o->w1);
                sg[c] = mpq_sgn(o->t);
            }
            const bool pos = sg[0] > 0 || sg[1] > 0 || sg[2] > 0;
            const bool neg = sg[0] < 0 || sg[1] < 0 || sg[2] < 0;
            if (pos && neg)
                continue; /* the ray's line misses the triangle */
            if (sg[0] == 0 || sg[1] == 0 || sg[2] == 0) {
                clean = false; /* through an edge, or in the plane */
                break;
            }
            /* The line crosses the triangle inside; ahead of p iff
             * n . (u - p) has the sign of n . ray, n its normal. */
            for (int k = 0; k < 3; ++k) {
                mpq_sub(o->w0.x[k], y[tr[1]].x[k], y[tr[0]].x[k]);
                mpq_sub(o->w1.x[k], y[tr[2]].x[k], y[tr[0]].x[k]);
            }
            triple(o, &o->ray, &o->w0, &o->w1);
            const int sd = mpq_sgn(o->t);
            qpt up;
            for (int k = 0; k < 3; ++k) {
                mpq_init(up.x[k]);
                mpq_sub(up.x[k], y[tr[0]].x[k], p->x[k]);
            }
            triple(o, &up, &o->w0, &o->w1);
            for (int k = 0; k < 3; ++k)
                mpq_clear(up.x[k]);
            const int su = mpq_sgn(o->t);
            ck_assert(sd != 0 && su != 0);
            crossings += sd == su;
        }
        if (clean)
            return crossings % 2 == 1;
    }
    ck_abort_msg("no clean ray");
    return false;
}

/* Do the closed solids of the placed meshes x (of mesh a) and y (of b)
 * meet? */
static bool solids_meet(oracle *o, const tmesh *a, const qpt *x, const tmesh *b, const qpt *y)
{
    for (size_t e = 0; e < a->ne; ++e)
        for (size_t f = 0; f < b->nt; ++f)
            if (edge_meets_triangle(o, x, &a->edge[2 * e], y, &b->tri[3 * f]))
                return true;
    for (size_t e = 0; e < b->ne; ++e)
        for (size_t f = 0; f < a->nt; ++f)
            if (edge_meets_triangle(o, y, &b->edge[2 * e], x, &a->tri[3 * f]))
                return true;
    for (size_t i = 0; i < a->nv; ++i)
        if (inside(o, &x[i], b, y))
            return true;
    for (size_t i = 0; i < b->nv; ++i)
        if (inside(o, &y[i], a, x))
            return true;
    return false;
}

enum { PAIR_VF, PAIR_FV, PAIR_EE };

/* The first time in [0, 1] at which A's feature fa, moving by s D, touches
 * B's feature fb, into o->best; false if they never touch. PAIR_VF: a
 * vertex of A and a triangle of B; PAIR_FV: a triangle of A and a vertex
 * of B; PAIR_EE: two edges. */
static bool pair_time(oracle *o, int kind, const uint32_t *fa, const uint32_t *fb)
{
    const int na = kind == PAIR_VF ? 1 : kind == PAIR_FV ? 3 : 2;
    const int nb = kind == PAIR_VF ? 3 : kind == PAIR_FV ? 1 : 2;
    if (!boxes_meet(o->pa, o->pa1, fa, na, o->pb, fb, nb))
        return false;
    lp *p = &o->sys;
    if (kind == PAIR_EE) {
        /* lambda (p1 - p0) + mu (q0 - q1) + s D = q0 - p0 */
        p->n = p->m = 3;
        p->hi[0] = p->hi[1] = p->hi[2] = true;
        for (int k = 0; k < 3; ++k) {
            mpq_sub(p->a[k][0], o->pa[fa[1]].x[k], o->pa[fa[0]].x[k]);
            mpq_sub(p->a[k][1], o->pb[fb[0]].x[k], o->pb[fb[1]].x[k]);
            mpq_set(p->a[k][2], o->d[k]);
            mpq_sub(p->r[k], o->pb[fb[0]].x[k], o->pa[fa[0]].x[k]);
        }
        return lp_min(o, 2);
    }
    /* alpha u + beta v + gamma w -+ s D = p, alpha + beta + gamma = 1: the
     * triangle's weights, and the time. */
    const qpt *tri = kind == PAIR_VF ? o->pb : o->pa;
    const uint32_t *ti = kind == PAIR_VF ? fb : fa;
    const qpt *pt = kind == PAIR_VF ? &o->pa[fa[0]] : &o->pb[fb[0]];
    p->n = p->m = 4;
    p->hi[0] = p->hi[1] = p->hi[2] = false;
    p->hi[3] = true;
    for (int k = 0; k < 3; ++k) {
        for (int c = 0; c < 3; ++c)
            mpq_set(p->a[k][c], tri[ti[c]].x[k]);
        if (kind == PAIR_VF)
            mpq_neg(p->a[k][3], o->d[k]);
        else
            mpq_set(p->a[k][3], o->d[k]);
        mpq_set(p->r[k], pt->x[k]);
    }
    for (int c = 0; c < 3; ++c)
        mpq_set_ui(p->a[3][c], 1, 1);
    mpq_set_ui(p->a[3][3], 0, 1);
    mpq_set_ui(p->r[3], 1, 1);
    return lp_min(o, 3);
}

/* Keep o->best as the first contact if it is earlier. */
static void keep_first(oracle *o)
{
    if (!o->swept || mpq_cmp(o->best, o->first) < 0)
        mpq_set(o->first, o->best);
    o->swept = true;
}

/* The oracle's verdict for the case. */
static oracle *oracle_run(const tmesh *a, const double ta0[3], const double ta1[3],
                          const tmesh *b, const double tb0[3], const double tb1[3])
{
    oracle *o = oracle_get();
    o->A = a;
    o->B = b;
    place(o->pa, a, ta0);
    place(o->pb, b, tb0);
    place(o->ea, a, ta1);
    place(o->eb, b, tb1);
    for (int k = 0; k < 3; ++k) {
        mpq_set_d(o->t, ta1[k]);
        mpq_set_d(o->u, ta0[k]);
        mpq_sub(o->d[k], o->t, o->u);
        mpq_set_d(o->t, tb1[k]);
        mpq_sub(o->d[k], o->d[k], o->t);
        mpq_set_d(o->t, tb0[k]);
        mpq_add(o->d[k], o->d[k], o->t);
    }
    for (size_t i = 0; i < a->nv; ++i)
        for (int k = 0; k < 3; ++k)
            mpq_add(o->pa1[i].x[k], o->pa[i].x[k], o->d[k]);
    o->swept = false;
    o->start = solids_meet(o, a, o->pa, b, o->pb);
    if (o->start) {
        o->swept = true;
        mpq_set_ui(o->first, 0, 1);
    } else {
        for (uint32_t i = 0; i < a->nv; ++i)
            for (size_t f = 0; f < b->nt; ++f)
                if (pair_time(o, PAIR_VF, &i, &b->tri[3 * f]))
                    keep_first(o);
        for (size_t f = 0; f < a->nt; ++f)
            for (uint32_t j = 0; j < b->nv; ++j)
                if (pair_time(o, PAIR_FV, &a->tri[3 * f], &j))
                    keep_first(o);
        for (size_t e = 0; e < a->ne; ++e)
            for (size_t f = 0; f < b->ne; ++f)
                if (pair_time(o, PAIR_EE, &a->edge[2 * e], &b->edge[2 * f]))
                    keep_first(o);
    }
    o->end = solids_meet(o, a, o->ea, b, o->eb);
    o->colliding = o->swept || o->end;
    return o;
}

/* Do the solids meet with A moved by o->sample D? */
static bool meet_at_sample(oracle *o)
{
    for (size_t i = 0; i < o->A->nv; ++i)
        for (int k = 0; k < 3; ++k) {
            mpq_mul(o->pm[i].x[k], o->sample, o->d[k]);
            mpq_add(o->pm[i].x[k], o->pm[i].x[k], o->pa[i].x[k]);
        }
    return solids_meet(o, o->A, o->pm, o->B, o->pb);
}

/* The oracle checks itself, by its static test alone: the solids meet at
 * s* and at neither s* (1 - 2^-40) nor s* / 2. */
static bool oracle_consistent(oracle *o)
{
    if (!o->swept || o->start)
        return true;
    mpq_set(o->sample, o->first);
    if (!meet_at_sample(o))
        return false;
    mpq_set_d(o->sample, 1 - 0x1p-40);
    mpq_mul(o->sample, o->sample, o->first);
    if (meet_at_sample(o))
        return false;
    mpq_set_d(o->sample, 0.5);
    mpq_mul(o->sample, o->sample, o->first);
    return !meet_at_sample(o);
}

/* ---- comparing the library with the oracle ---------------------------------- */

typedef struct outcome {
    noctStatus status;
    bool colliding;
    noctSweepHit hit;
} outcome;

static outcome sweep(const tmesh *a, const double ta0[3], const double ta1[3], const tmesh *b,
                     const double tb0[3], const double tb1[3])
{
    outcome r;
    memset(&r, 0xa5, sizeof r);
    r.status = noctCollideSwept(a->m, ta0, ta1, b->m, tb0, tb1, &r.colliding, &r.hit, NULL);
    return r;
}

static const char *feature_name(noctSweepFeature f)
{
    switch (f) {
    case NOCT_SWEEP_NONE: return "none";
    case NOCT_SWEEP_START: return "start";
    case NOCT_SWEEP_VERTEX_FACE: return "vertex-face";
    case NOCT_SWEEP_FACE_VERTEX: return "face-vertex";
    case NOCT_SWEEP_EDGE_EDGE: return "edge-edge";
    case NOCT_SWEEP_END: return "end";
    case NOCT_SWEEP_NEAR: return "near";
    }
    return "?";
}

static void print_vec(FILE *f, const char *name, const double *v)
{
    fprintf(f, "  %s = {%a, %a, %a}\n", name, v[0], v[1], v[2]);
}

/* Print the case, the library's outcome and the oracle's, to stderr (for
 * a reproducer: every input as a hex float), and fail the test. */
static void fail_case(const char *why, const tmesh *a, const double ta0[3], const double ta1[3],
                      const tmesh *b, const double tb0[3], const double tb1[3], const outcome *r,
                      oracle *o)
{
    fprintf(stderr, "check-swept: %s\n", why);
    const tmesh *m[2] = {a, b};
    for (int s = 0; s < 2; ++s) {
        fprintf(stderr, "  mesh %c: %zu vertices, triangles", "AB"[s], m[s]->nv);
        for (size_t f = 0; f < m[s]->nt; ++f)
            fprintf(stderr, " %u,%u,%u", m[s]->tri[3 * f], m[s]->tri[3 * f + 1],
                    m[s]->tri[3 * f + 2]);
        fprintf(stderr, "\n");
        for (size_t i = 0; i < m[s]->nv; ++i)
            fprintf(stderr, "    v%zu = {%a, %a, %a}\n", i, m[s]->v[3 * i], m[s]->v[3 * i + 1],
                    m[s]->v[3 * i + 2]);
    }
    print_vec(stderr, "ta0", ta0);
    print_vec(stderr, "ta1", ta1);
    print_vec(stderr, "tb0", tb0);
    print_vec(stderr, "tb1", tb1);
    fprintf(stderr, "  library: status %d colliding %d time %a feature %s a {%u %u %u} b {%u %u %u}\n",
            (int)r->status, (int)r->colliding, r->hit.time, feature_name(r->hit.feature),
            r->hit.a[0], r->hit.a[1], r->hit.a[2], r->hit.b[0], r->hit.b[1], r->hit.b[2]);
    fprintf(stderr, "  oracle: colliding %d start %d swept %d end %d first %a (%s)\n",
            (int)o->colliding, (int)o->start, (int)o->swept, (int)o->end,
            o->swept ? mpq_get_d(o->first) : 1.0, o->swept ? "" : "none");
    if (o->swept)
        gmp_fprintf(stderr, "  oracle first = %Qd\n", o->first);
    if (o->swept && !o->start) {
        /* the pairs that touch first (A's features, then B's) */
        oracle *w = o;
        const tmesh *A = o->A, *B = o->B;
        for (uint32_t i = 0; i < A->nv; ++i)
            for (size_t f = 0; f < B->nt; ++f)
                if (pair_time(w, PAIR_VF, &i, &B->tri[3 * f]) && mpq_equal(w->best, w->first))
                    fprintf(stderr, "  first: vertex-face {%u} {%u %u %u}\n", i, B->tri[3 * f],
                            B->tri[3 * f + 1], B->tri[3 * f + 2]);
        for (size_t f = 0; f < A->nt; ++f)
            for (uint32_t j = 0; j < B->nv; ++j)
                if (pair_time(w, PAIR_FV, &A->tri[3 * f], &j) && mpq_equal(w->best, w->first))
                    fprintf(stderr, "  first: face-vertex {%u %u %u} {%u}\n", A->tri[3 * f],
                            A->tri[3 * f + 1], A->tri[3 * f + 2], j);
        for (size_t e = 0; e < A->ne; ++e)
            for (size_t f = 0; f < B->ne; ++f)
                if (pair_time(w, PAIR_EE, &A->edge[2 * e], &B->edge[2 * f]) &&
                    mpq_equal(w->best, w->first))
                    fprintf(stderr, "  first: edge-edge {%u %u} {%u %u}\n", A->edge[2 * e],
                            A->edge[2 * e + 1], B->edge[2 * f], B->edge[2 * f + 1]);
    }
    ck_abort_msg("%s (the case is on stderr)", why);
}

/* Is each of the hit's indices UINT32_MAX or a vertex, and those that the
 * feature uses vertices? */
static bool indices_sane(const uint32_t *ix, int used, size_t nv)
{
    for (int k = 0; k < 3; ++k) {
        if (k < used && ix[k] >= nv)
            return false;
        if (k >= used && ix[k] != UINT32_MAX && ix[k] >= nv)
            return false;
    }
    return true;
}

/* Run the library on the case and check it against the oracle; return its
 * outcome. */
static outcome check_case(const tmesh *a, const double ta0[3], const double ta1[3],
                          const tmesh *b, const double tb0[3], const double tb1[3])
{
    oracle *o = oracle_run(a, ta0, ta1, b, tb0, tb1);
    outcome r = sweep(a, ta0, ta1, b, tb0, tb1);
#define FAIL(why) fail_case(why, a, ta0, ta1, b, tb0, tb1, &r, o)
    if (!oracle_consistent(o))
        FAIL("the oracle contradicts itself");
    if (r.status != NOCT_OK)
        FAIL("status");
    if (r.colliding != o->colliding)
        FAIL("verdict differs from the oracle's");
    bool alone;
    if (noctCollideSwept(a->m, ta0, ta1, b->m, tb0, tb1, &alone, NULL, NULL) != NOCT_OK ||
        alone != r.colliding)
        FAIL("verdict without hit differs");
    const noctSweepHit *h = &r.hit;
    if (!(h->time >= 0 && h->time <= 1) || ldexp(h->time, 52) != nearbyint(ldexp(h->time, 52)))
        FAIL("time not a multiple of 2^-52 in [0, 1]");
    int ua = 0, ub = 0;
    switch (h->feature) {
    case NOCT_SWEEP_NONE:
        if (o->colliding || h->time != 1)
            FAIL("feature none");
        break;
    case NOCT_SWEEP_START:
        if (!o->start || h->time != 0)
            FAIL("feature start");
        break;
    case NOCT_SWEEP_END:
        if (o->swept || !o->end || h->time != 1)
            FAIL("feature end");
        break;
    case NOCT_SWEEP_VERTEX_FACE: ua = 1; ub = 3; break;
    case NOCT_SWEEP_FACE_VERTEX: ua = 3; ub = 1; break;
    case NOCT_SWEEP_EDGE_EDGE: ua = 2; ub = 2; break;
    default: FAIL("unknown feature");
    }
    if (o->start && h->feature != NOCT_SWEEP_START)
        FAIL("touching at the start, not reported as start");
    if (!indices_sane(h->a, ua, a->nv) || !indices_sane(h->b, ub, b->nv))
        FAIL("feature indices out of range");
    if (ua > 0) {
        if (!o->swept || o->start)
            FAIL("a feature contact the oracle does not see");
        /* s* in [time - 2^-52, time] */
        mpq_set_d(o->t, h->time);
        if (mpq_cmp(o->first, o->t) > 0)
            FAIL("time before the first contact");
        mpq_set_d(o->u, 0x1p-52);
        mpq_sub(o->t, o->t, o->u);
        if (mpq_cmp(o->t, o->first) > 0)
            FAIL("time more than 2^-52 after the first contact");
        if (a->numbered && b->numbered) {
            const int kind = h->feature == NOCT_SWEEP_VERTEX_FACE ? PAIR_VF
                           : h->feature == NOCT_SWEEP_FACE_VERTEX ? PAIR_FV : PAIR_EE;
            mpq_set_d(o->sample, h->time);
            if (!pair_time(o, kind, h->a, h->b)) {
                FAIL("the reported features never touch");
            } else if (mpq_cmp(o->best, o->sample) > 0) {
                FAIL("the reported features touch after the time");
            }
            /* so they first touch in [s*, time], within the time's 2^-52
             * of the first contact: what the header promises (not that
             * they are the first: see first_features_near_the_end) */
        }
    }
#undef FAIL
    return r;
}

/* Same verdict and time (the features may differ where several touch
 * first). */
static void expect_same(const outcome *x, const outcome *y, const char *what)
{
    ck_assert_msg(x->status == NOCT_OK && y->status == NOCT_OK, "%s: status", what);
    ck_assert_msg(x->colliding == y->colliding && x->hit.time == y->hit.time,
                  "%s: verdict %d time %a, against %d time %a", what, (int)x->colliding,
                  x->hit.time, (int)y->colliding, y->hit.time);
    const bool xs = x->hit.feature == NOCT_SWEEP_START, ys = y->hit.feature == NOCT_SWEEP_START;
    const bool xe = x->hit.feature == NOCT_SWEEP_END, ye = y->hit.feature == NOCT_SWEEP_END;
    ck_assert_msg(xs == ys && xe == ye, "%s: features %s and %s", what,
                  feature_name(x->hit.feature), feature_name(y->hit.feature));
}

/* ---- random cases ------------------------------------------------------------- */

static double grid(uint64_t *rng, int half, double step)
{
    return (double)((int)test_rand_below(rng, (size_t)(2 * half + 1)) - half) * step;
}

static void random_tet(uint64_t *rng, tmesh *t, bool dyadic)
{
    double p[12];
    do {
        for (int k = 0; k < 12; ++k)
            p[k] = dyadic ? grid(rng, 4, 0.25) : 2 * test_uniform(rng) - 1;
    } while (!tm_tet(t, p));
}

/* Translations: on the quarter grid within +-1.5, or random doubles. */
static void random_translation(uint64_t *rng, double t[3], bool dyadic)
{
    for (int k = 0; k < 3; ++k)
        t[k] = dyadic ? grid(rng, 6, 0.25) : 3 * test_uniform(rng) - 1.5;
}

typedef struct motion {
    double ta0[3], ta1[3], tb0[3], tb1[3];
} motion;

static void random_motion(uint64_t *rng, motion *mo, bool dyadic)
{
    random_translation(rng, mo->ta0, dyadic);
    random_translation(rng, mo->ta1, dyadic);
    random_translation(rng, mo->tb0, dyadic);
    /* B stays put a third of the time; a sixth of the time it moves by
     * A's displacement rounded (D zero, or tiny where the rounding is not
     * exact: the end poses then decide) */
    const size_t how = test_rand_below(rng, 6);
    if (how < 2)
        memcpy(mo->tb1, mo->tb0, sizeof mo->tb1);
    else if (how == 2)
        for (int k = 0; k < 3; ++k)
            mo->tb1[k] = mo->tb0[k] + (mo->ta1[k] - mo->ta0[k]);
    else
        random_translation(rng, mo->tb1, dyadic);
}

static outcome check_motion(const tmesh *a, const tmesh *b, const motion *mo)
{
    return check_case(a, mo->ta0, mo->ta1, b, mo->tb0, mo->tb1);
}

/* Counts of what the random runs met, to show they are not vacuous. */
typedef struct tally {
    int cases, colliding, start, end, later;
} tally;

static void count(tally *t, const outcome *r)
{
    t->cases++;
    t->colliding += r->colliding;
    t->start += r->hit.feature == NOCT_SWEEP_START;
    t->end += r->hit.feature == NOCT_SWEEP_END;
    t->later += r->colliding && r->hit.feature != NOCT_SWEEP_START &&
                r->hit.feature != NOCT_SWEEP_END;
}

static void expect_varied(const tally *t, const char *what)
{
    ck_assert_msg(t->colliding > t->cases / 20 && t->later > t->cases / 40 &&
                      t->colliding < t->cases - t->cases / 10,
                  "%s: %d cases, %d colliding, %d at start, %d later, %d at end only", what,
                  t->cases, t->colliding, t->start, t->later, t->end);
}

/* Random tetrahedra and motions: on the grid (many exact touches,
 * parallel edges and coplanar faces), or of random doubles (placement
 * rounds). */
static void random_tetrahedra(uint64_t rng, bool grid, const char *what)
{
    tally t = {0};
    for (int n = 0; n < 100; ++n) {
        tmesh a, b;
        motion mo;
        random_tet(&rng, &a, grid);
        random_tet(&rng, &b, grid);
        random_motion(&rng, &mo, grid);
        outcome r = check_motion(&a, &b, &mo);
        count(&t, &r);
        tm_free(&a);
        tm_free(&b);
    }
    expect_varied(&t, what);
}

/* _i: the seed. */
START_TEST(random_tetrahedra_grid)
{
    random_tetrahedra(0x5eed0000u + (uint64_t)_i, true, "grid tetrahedra");
}
END_TEST

START_TEST(random_tetrahedra_doubles)
{
    random_tetrahedra(0xd0b1e000u + (uint64_t)_i, false, "random tetrahedra");
}
END_TEST

/* A random mesh of the kinds the suite has: 0 a tetrahedron, 1 an
 * axis-aligned box, 2 an oriented box with exact corners, 3 a rotated
 * box with rounded corners, 4 the L. */
static void random_mesh(uint64_t *rng, tmesh *t, int kind)
{
    double h[3], R[9];
    for (int k = 0; k < 3; ++k)
        h[k] = (double)(1 + test_rand_below(rng, 8)) * 0.125;
    switch (kind) {
    case 0: random_tet(rng, t, true); break;
    case 1: tm_box(t, h[0], h[1], h[2]); break;
    case 2:
        dyadic_rotation(rng, R);
        tm_oriented_box(t, h, R);
        break;
    case 3:
        dyadic_rotation(rng, R);
        tm_rounded_box(t, h, R, 1);
        break;
    default: tm_ell(t, 0.5 * (double)(1 + test_rand_below(rng, 2))); break;
    }
}

/* _i: the seed; boxes of both constructors and the L against each other
 * and tetrahedra, on the grid. */
START_TEST(random_boxes_and_ell)
{
    uint64_t rng = 0xb0c5e000u + (uint64_t)_i;
    tally t = {0};
    for (int n = 0; n < 30; ++n) {
        tmesh a, b;
        motion mo;
        random_mesh(&rng, &a, (int)test_rand_below(&rng, 5));
        random_mesh(&rng, &b, (int)test_rand_below(&rng, 5));
        random_motion(&rng, &mo, test_rand_below(&rng, 4) != 0);
        outcome r = check_motion(&a, &b, &mo);
        count(&t, &r);
        tm_free(&a);
        tm_free(&b);
    }
    expect_varied(&t, "boxes and L");
}
END_TEST

/* ---- hard cases of known answer --------------------------------------------- */

static const double zero[3] = {0, 0, 0};

/* The library's time, checked to be s (exact dyadic) or s + 2^-52. */
static void expect_time(const outcome *r, double s)
{
    ck_assert_msg(r->colliding, "no contact, expected one at %a", s);
    ck_assert_msg(r->hit.time == s || r->hit.time == s + 0x1p-52, "time %a, expected %a", r->hit.time,
                  s);
}

/* Unit cubes: A's corner grazes B's at s = 1/2 only, moving across; the
 * same with edges (along z) meeting along a segment; and a tetrahedron's
 * vertex grazing a box's edge. */
START_TEST(grazes)
{
    tmesh a, b;
    tm_box(&a, 0.5, 0.5, 0.5);
    tm_box(&b, 0.5, 0.5, 0.5);
    /* c(s) = (-1, -1, -1) + (s - 1/2) (2, -2, 0) */
    double ta0[3] = {-2, 0, -1}, ta1[3] = {0, -2, -1};
    outcome r = check_case(&a, ta0, ta1, &b, zero, zero);
    expect_time(&r, 0.5);
    ta0[2] = ta1[2] = 0; /* edges along z, meeting along a segment */
    r = check_case(&a, ta0, ta1, &b, zero, zero);
    expect_time(&r, 0.5);
    /* an ulp further out: no contact */
    ta0[0] = -2 - 0x1p-51;
    ta1[0] = -0x1p-51;
    r = check_case(&a, ta0, ta1, &b, zero, zero);
    ck_assert(!r.colliding && r.hit.feature == NOCT_SWEEP_NONE && r.hit.time == 1);
    /* B moving too: the relative motion is the same, the time too */
    double tb0[3] = {0.25, 0.25, 0}, tb1[3] = {0.75, -0.25, 0};
    double ta2[3] = {-1.75, 0.25, 0}, ta3[3] = {0.75, -2.25, 0};
    r = check_case(&a, ta2, ta3, &b, tb0, tb1);
    expect_time(&r, 0.5);
    tm_free(&a);
    tm_free(&b);

    /* The apex (0, 0, 0) of a tetrahedron lying in x >= 0, z >= 0 passes
     * the box's edge x = z = 1/2 at s = 1/4, moving along (1, 0, -1): above
     * the box before, beside it after, touching it at that instant only. */
    static const double apex[12] = {0, 0, 0, 2, 0, 1, 1, -1, 2, 1, 1, 2};
    ck_assert(tm_tet(&a, apex));
    tm_box(&b, 0.5, 0.5, 0.5);
    const double t0[3] = {-0.5, 0, 1.5}, t1[3] = {3.5, 0, -2.5};
    r = check_case(&a, t0, t1, &b, zero, zero);
    expect_time(&r, 0.25);
    ck_assert(r.hit.feature == NOCT_SWEEP_VERTEX_FACE || r.hit.feature == NOCT_SWEEP_EDGE_EDGE);
    const double t2[3] = {-0.5, 0, 1.5 + 0x1p-51}, t3[3] = {3.5, 0, -2.5 + 0x1p-51};
    r = check_case(&a, t2, t3, &b, zero, zero);
    ck_assert(!r.colliding);
    tm_free(&a);

    /* A tetrahedron's edge (-1, 0, 1) (1, 0, -1), the rest of it in
     * x + z >= 0, comes down the diagonal onto the box's edge x = z = 1/2
     * and first touches it at s = 1/4, edge across edge at one point. */
    static const double wedge[12] = {-1, 0, 1, 1, 0, -1, 1, -1, 1, 1, 1, 1};
    ck_assert(tm_tet(&a, wedge));
    const double t4[3] = {1, 0, 1}, t5[3] = {-1, 0, -1};
    r = check_case(&a, t4, t5, &b, zero, zero);
    expect_time(&r, 0.25);
    ck_assert(r.hit.feature == NOCT_SWEEP_EDGE_EDGE);
    tm_free(&a);
    tm_free(&b);
}
END_TEST

/* A cube on top of another, sliding across it: touching face on face
 * from x = -1 on (s = 1/3); the same one ulp higher (never touching); the
 * same at an offset of 2^40 where an ulp is 2^-12. */
START_TEST(sliding)
{
    tmesh a, b;
    tm_box(&a, 0.5, 0.5, 0.5);
    tm_box(&b, 0.5, 0.5, 0.5);
    double ta0[3] = {-3, 0, 1}, ta1[3] = {3, 0, 1};
    outcome r = check_case(&a, ta0, ta1, &b, zero, zero);
    ck_assert(r.colliding && r.hit.feature != NOCT_SWEEP_START);
    ck_assert(r.hit.time == ldexp(ceil(ldexp(1.0 / 3, 52)), -52) ||
              r.hit.time == ldexp(ceil(ldexp(1.0 / 3, 52)), -52) + 0x1p-52);
    /* one ulp apart */
    ta0[2] = ta1[2] = nextafter(1.0, 2.0);
    r = check_case(&a, ta0, ta1, &b, zero, zero);
    ck_assert(!r.colliding);
    /* sliding along while touching from the start */
    double tc0[3] = {0, 0, 1}, tc1[3] = {0.25, 0.75, 1};
    r = check_case(&a, tc0, tc1, &b, zero, zero);
    ck_assert(r.colliding && r.hit.feature == NOCT_SWEEP_START && r.hit.time == 0);
    /* both moving the same way, one ulp apart, far away */
    const double big = 0x1p40;
    double td0[3] = {big - 3, big, big + 1 + 0x1p-12}, td1[3] = {big + 3, big, big + 1 + 0x1p-12};
    double tb0[3] = {big, big, big}, tb1[3] = {big, big, big};
    r = check_case(&a, td0, td1, &b, tb0, tb1);
    ck_assert(!r.colliding);
    td0[2] = td1[2] = big + 1;
    r = check_case(&a, td0, td1, &b, tb0, tb1);
    ck_assert(r.colliding && r.hit.time > 0.33 && r.hit.time < 0.34);
    /* a box lowered onto another, touching at s = 3/4 exactly at the end
     * of the slide along x */
    double te0[3] = {-1, 0, 4}, te1[3] = {0, 0, 0};
    r = check_case(&a, te0, te1, &b, zero, zero);
    expect_time(&r, 0.75);
    tm_free(&a);
    tm_free(&b);
}
END_TEST

/* Contact at the start: overlapping, touching by a face and moving apart,
 * a tetrahedron inside a box (either way round), touching at a corner. */
START_TEST(start_in_contact)
{
    tmesh a, b, c;
    tm_box(&a, 0.5, 0.5, 0.5);
    tm_box(&b, 1, 1, 1);
    c = (tmesh){0};
    ck_assert(tm_tet(&c, (const double[12]){0, 0, 0, 0.5, 0, 0, 0, 0.5, 0, 0, 0, 0.5}));
    const double up[3] = {0, 0, 5}, side[3] = {1.5, 0, 0}, side1[3] = {4, 0, 0};
    outcome r = check_case(&a, zero, up, &b, zero, zero);
    ck_assert(r.hit.feature == NOCT_SWEEP_START && r.hit.time == 0);
    r = check_case(&a, side, side1, &b, zero, zero); /* touching face, leaving */
    ck_assert(r.hit.feature == NOCT_SWEEP_START && r.hit.time == 0);
    r = check_case(&c, (const double[3]){-0.25, -0.25, -0.25}, up, &b, zero, zero);
    ck_assert(r.hit.feature == NOCT_SWEEP_START);
    r = check_case(&b, zero, zero, &c, (const double[3]){-0.25, -0.25, -0.25}, up);
    ck_assert(r.hit.feature == NOCT_SWEEP_START);
    /* touching at a single corner at the start */
    r = check_case(&a, (const double[3]){1.5, 1.5, 1.5}, (const double[3]){3, 3, 1.5}, &b, zero,
                   zero);
    ck_assert(r.hit.feature == NOCT_SWEEP_START);
    /* and the same without hit */
    bool col = false;
    ck_assert_int_eq(noctCollideSwept(a.m, side, side1, b.m, zero, zero, &col, NULL, NULL),
                     NOCT_OK);
    ck_assert(col);
    tm_free(&a);
    tm_free(&b);
    tm_free(&c);
}
END_TEST

/* The end poses placed by fl(v + t1) meet though the exactly moved solids
 * never do: A moves by a displacement that is not representable, so its
 * solid stops short of B by a fraction of an ulp, and the rounded end
 * placement closes the gap. */
START_TEST(end_only)
{
    /* A's right face starts at fl(hx + x0), rounded at the ulp of about
     * 2.5 (the error fixed by hx's low bits, so hx varies); it ends, moved
     * exactly, that rounding away from fl(hx + x1), which a few x1 place
     * at or just past B's left face x = -1/2. Some of these meet only at
     * the end, some in the motion, some never: the oracle tells which. */
    tmesh b;
    tm_box(&b, 0.5, 0.5, 0.5);
    int ends = 0, swept = 0, never = 0;
    uint64_t rng = 77;
    for (int n = 0; n < 100; ++n) {
        tmesh a;
        const double hx = 0.05 + 0.4 * test_uniform(&rng);
        tm_box(&a, hx, 0.5, 0.5);
        const double x0 = -3 + test_uniform(&rng);
        double x1 = -0.5 - hx;
        for (int k = (int)test_rand_below(&rng, 5) - 2; k != 0; k += k > 0 ? -1 : 1)
            x1 = nextafter(x1, k > 0 ? 1 : -1);
        double ta0[3] = {x0, 0.25, 0}, ta1[3] = {x1, 0.25, 0};
        outcome r = check_case(&a, ta0, ta1, &b, zero, zero);
        ends += r.hit.feature == NOCT_SWEEP_END;
        never += !r.colliding;
        swept += r.colliding && r.hit.feature != NOCT_SWEEP_END;
        tm_free(&a);
    }
    ck_assert_msg(ends > 0 && swept > 0 && never > 0, "end only %d, swept %d, never %d", ends,
                  swept, never);
    tm_free(&b);
}
END_TEST

/* A small cube crosses a thin wall within one step at 1e3 to 1e8 times its
 * size: the first contact is found, at the right time; past the wall's
 * edge by an ulp it is not. */
START_TEST(tunnelling)
{
    tmesh wall, bullet;
    tm_box(&wall, 4, 4, 0x1p-6);
    tm_box(&bullet, 0x1p-4, 0x1p-4, 0x1p-4);
    for (double speed = 1e3; speed <= 1e8; speed *= 10) {
        const double L = speed * 0x1p-3;
        double t0[3] = {0.5, -0.25, -L / 2}, t1[3] = {0.5, -0.25, L / 2};
        outcome r = check_case(&bullet, t0, t1, &wall, zero, zero);
        ck_assert(r.colliding && r.hit.feature != NOCT_SWEEP_START &&
                  r.hit.feature != NOCT_SWEEP_END);
        ck_assert(r.hit.time > 0.49 && r.hit.time < 0.5);
        /* grazing the wall's side at x = 4 */
        t0[0] = t1[0] = 4 + 0x1p-4;
        r = check_case(&bullet, t0, t1, &wall, zero, zero);
        ck_assert(r.colliding);
        t0[0] = t1[0] = nextafter(4 + 0x1p-4, 5);
        r = check_case(&bullet, t0, t1, &wall, zero, zero);
        ck_assert(!r.colliding);
        /* the wall moving instead, the other way, and both */
        double w0[3] = {-0.5, 0.25, L / 2}, w1[3] = {-0.5, 0.25, -L / 2};
        r = check_case(&bullet, zero, zero, &wall, w0, w1);
        ck_assert(r.colliding && r.hit.time > 0.49 && r.hit.time < 0.5);
        double b1[3] = {0.5, -0.25, L / 4}, b0[3] = {0.5, -0.25, -L / 4};
        double v0[3] = {0, 0, L / 4}, v1[3] = {0, 0, -L / 4};
        r = check_case(&bullet, b0, b1, &wall, v0, v1);
        ck_assert(r.colliding);
    }
    /* random bullet paths through a tilted thin wall */
    tmesh tilted;
    uint64_t rng = 99;
    double R[9];
    dyadic_rotation(&rng, R);
    tm_rounded_box(&tilted, (const double[3]){2, 2, 0x1p-7}, R, 1);
    for (int n = 0; n < 40; ++n) {
        const double L = 1e3 * pow(10, 5 * test_uniform(&rng)) * 0x1p-3;
        double t0[3], t1[3];
        for (int k = 0; k < 3; ++k) {
            const double dir = 2 * test_uniform(&rng) - 1;
            const double at = test_uniform(&rng) - 0.5;
            t0[k] = at - dir * L;
            t1[k] = at + dir * L;
        }
        check_case(&bullet, t0, t1, &tilted, zero, zero);
    }
    tm_free(&tilted);
    tm_free(&wall);
    tm_free(&bullet);
}
END_TEST

/* ---- invariances ---------------------------------------------------------------- */

/* Is fl(x + w) == x + w exactly? (Knuth's two-sum: the rounding error of
 * the sum, exactly.) */
static bool sum_exact(double x, double w)
{
    const double s = x + w, bw = s - x, bx = s - bw;
    return (x - bx) + (w - bw) == 0;
}

/* Does moving the translation t by w move every placed vertex of m by w
 * exactly? */
static bool shift_exact(const tmesh *m, const double t[3], const double w[3])
{
    for (int k = 0; k < 3; ++k) {
        if (!sum_exact(t[k], w[k]))
            return false;
        for (size_t i = 0; i < m->nv; ++i) {
            const double x = m->v[3 * i + k] + t[k], y = m->v[3 * i + k] + (t[k] + w[k]);
            if (!sum_exact(x, w[k]) || x + w[k] != y)
                return false;
        }
    }
    return true;
}

static void add3(double out[3], const double t[3], const double w[3])
{
    for (int k = 0; k < 3; ++k)
        out[k] = t[k] + w[k];
}

/* _i: the seed. On the grid: swapping the meshes, moving all four
 * translations by w, moving both ends by w: the same verdict and time,
 * each also against the oracle. */
START_TEST(invariances)
{
    uint64_t rng = 0x1a7a0000u + (uint64_t)_i;
    for (int n = 0; n < 10; ++n) {
        tmesh a, b;
        motion mo, m2;
        random_mesh(&rng, &a, (int)test_rand_below(&rng, 5));
        random_mesh(&rng, &b, (int)test_rand_below(&rng, 5));
        random_motion(&rng, &mo, true);
        const outcome r = check_motion(&a, &b, &mo);
        outcome s = check_case(&b, mo.tb0, mo.tb1, &a, mo.ta0, mo.ta1);
        expect_same(&r, &s, "swapped");
        double w[3], g[3];
        for (int k = 0; k < 3; ++k) {
            g[k] = grid(&rng, 64, 0.125);
            w[k] = g[k] + (test_rand_below(&rng, 2) ? 0x1p30 : 0);
        }
        if (!(shift_exact(&a, mo.ta0, w) && shift_exact(&a, mo.ta1, w) &&
              shift_exact(&b, mo.tb0, w) && shift_exact(&b, mo.tb1, w)))
            memcpy(w, g, sizeof w); /* rotated boxes: too many bits for 2^30 */
        ck_assert(shift_exact(&a, mo.ta0, w) && shift_exact(&a, mo.ta1, w) &&
                  shift_exact(&b, mo.tb0, w) && shift_exact(&b, mo.tb1, w));
        add3(m2.ta0, mo.ta0, w);
        add3(m2.ta1, mo.ta1, w);
        add3(m2.tb0, mo.tb0, w);
        add3(m2.tb1, mo.tb1, w);
        s = check_motion(&a, &b, &m2);
        expect_same(&r, &s, "all moved");
        m2 = mo;
        add3(m2.ta1, mo.ta1, w);
        add3(m2.tb1, mo.tb1, w);
        s = check_motion(&a, &b, &m2);
        expect_same(&r, &s, "both ends moved");
        tm_free(&a);
        tm_free(&b);
    }
}
END_TEST

/* A mesh of kind 0 (a tetrahedron), 3 (a rotated box) or 4 (the L) from
 * fixed parameters, scaled by 2^e: its vertices are the scaled ones
 * exactly. */
static void scaled_mesh(tmesh *t, int kind, int e, const double R[9])
{
    if (kind == 0) {
        double p[12] = {0, 0, 0, 0.875, 0.125, 0, 0.25, 0.75, 0.125, 0.375, 0.25, 0.625};
        for (int k = 0; k < 12; ++k)
            p[k] = ldexp(p[k], e);
        ck_assert(tm_tet(t, p));
    } else if (kind == 3) {
        tm_rounded_box(t, (const double[3]){0.5, 0.25, 0.375}, R, ldexp(1, e));
    } else if (kind == 1) {
        tm_box(t, ldexp(0.5, e), ldexp(0.25, e), ldexp(0.75, e));
    } else {
        tm_ell(t, ldexp(0.5, e));
    }
}

/* _i: the seed. The same cases at scales 2^-332 (about 1e-100) to 2^328
 * (translations, at most 6 at scale 1, to about 3e99) and at offsets to
 * 2^40: the same verdict and time as at scale 1, and against the oracle. */
START_TEST(scales_and_offsets)
{
    uint64_t rng = 0x5ca1e000u + (uint64_t)_i;
    static const int exps[] = {-332, -200, -60, -1, 7, 100, 328};
    static const int kinds[] = {0, 1, 3, 4};
    double R[9];
    dyadic_rotation(&rng, R);
    for (int n = 0; n < 4; ++n) {
        const int ka = kinds[test_rand_below(&rng, 4)], kb = kinds[test_rand_below(&rng, 4)];
        motion mo;
        random_motion(&rng, &mo, true);
        tmesh a, b;
        scaled_mesh(&a, ka, 0, R);
        scaled_mesh(&b, kb, 0, R);
        const outcome r = check_motion(&a, &b, &mo);
        tm_free(&a);
        tm_free(&b);
        for (size_t x = 0; x < sizeof exps / sizeof exps[0]; ++x) {
            const int e = exps[x];
            scaled_mesh(&a, ka, e, R);
            scaled_mesh(&b, kb, e, R);
            motion ms;
            for (int k = 0; k < 3; ++k) {
                ms.ta0[k] = ldexp(mo.ta0[k], e);
                ms.ta1[k] = ldexp(mo.ta1[k], e);
                ms.tb0[k] = ldexp(mo.tb0[k], e);
                ms.tb1[k] = ldexp(mo.tb1[k], e);
            }
            const outcome s = check_motion(&a, &b, &ms);
            char what[32];
            snprintf(what, sizeof what, "scale 2^%d", e);
            expect_same(&r, &s, what);
            tm_free(&a);
            tm_free(&b);
        }
        /* offsets: 2^40, 2^20 + 2^39 and so on, exact for these meshes */
        scaled_mesh(&a, ka, 0, R);
        scaled_mesh(&b, kb, 0, R);
        for (int o = 0; o < 3; ++o) {
            double w[3];
            for (int k = 0; k < 3; ++k)
                w[k] = ldexp(1, 20 + (int)test_rand_below(&rng, 21)) * (test_rand_below(&rng, 2) ? 1 : -1);
            if (!(shift_exact(&a, mo.ta0, w) && shift_exact(&a, mo.ta1, w) &&
                  shift_exact(&b, mo.tb0, w) && shift_exact(&b, mo.tb1, w)))
                continue; /* a rounded box's corners may have too many bits */
            motion m2;
            add3(m2.ta0, mo.ta0, w);
            add3(m2.ta1, mo.ta1, w);
            add3(m2.tb0, mo.tb0, w);
            add3(m2.tb1, mo.tb1, w);
            const outcome s = check_motion(&a, &b, &m2);
            expect_same(&r, &s, "offset");
        }
        tm_free(&a);
        tm_free(&b);
    }
}
END_TEST

/* _i: the seed. Random-double tetrahedra of size about 1 at offsets 2^45
 * to 2^52, where an ulp is 2^-7 to 1: placement rounds them hard, often
 * flat or to a segment or a point; the contract is still the placed
 * solids'. */
START_TEST(rounded_flat)
{
    uint64_t rng = 0xf1a70000u + (uint64_t)_i;
    for (int n = 0; n < 20; ++n) {
        tmesh a, b;
        motion mo;
        random_tet(&rng, &a, false);
        random_tet(&rng, &b, false);
        random_motion(&rng, &mo, false);
        double w[3];
        for (int k = 0; k < 3; ++k)
            w[k] = ldexp(1, 45 + (int)test_rand_below(&rng, 8));
        add3(mo.ta0, mo.ta0, w);
        add3(mo.ta1, mo.ta1, w);
        add3(mo.tb0, mo.tb0, w);
        add3(mo.tb1, mo.tb1, w);
        check_motion(&a, &b, &mo);
        tm_free(&a);
        tm_free(&b);
    }
}
END_TEST

/* _i: the seed. Random cases cut short at about their first contact:
 * A's end moved to ta0 + q (ta1 - ta0), q the double next to s* and a few
 * ulps either side, so that the verdict turns on the last bits (touch, or
 * miss by about 1e-16 of the size), for every kind of mesh. */
START_TEST(near_touch)
{
    uint64_t rng = 0x7e0c0000u + (uint64_t)_i;
    int touched = 0, missed = 0, cut = 0;
    for (int n = 0; n < 300 && cut < 10; ++n) {
        tmesh a, b;
        motion mo;
        random_mesh(&rng, &a, (int)test_rand_below(&rng, 5));
        random_mesh(&rng, &b, (int)test_rand_below(&rng, 5));
        random_motion(&rng, &mo, test_rand_below(&rng, 2) != 0);
        oracle *o = oracle_run(&a, mo.ta0, mo.ta1, &b, mo.tb0, mo.tb1);
        if (!o->swept || o->start) {
            tm_free(&a);
            tm_free(&b);
            continue;
        }
        const double q = mpq_get_d(o->first); /* B's end cut at q too */
        cut++;
        for (int k = -2; k <= 2; ++k) {
            double f = q;
            for (int j = 0; j < (k < 0 ? -k : k); ++j)
                f = nextafter(f, k < 0 ? 0 : 1);
            motion m2 = mo;
            for (int c = 0; c < 3; ++c) {
                m2.ta1[c] = mo.ta0[c] + (mo.ta1[c] - mo.ta0[c]) * f;
                m2.tb1[c] = mo.tb0[c] + (mo.tb1[c] - mo.tb0[c]) * f;
            }
            const outcome r = check_motion(&a, &b, &m2);
            touched += r.colliding;
            missed += !r.colliding;
        }
        tm_free(&a);
        tm_free(&b);
    }
    ck_assert_msg(touched > 0 && missed > 0, "touched %d, missed %d", touched, missed);
}
END_TEST

/* The reproducers' meshes, freed by the checked teardown, which runs
 * even when the test fails (as these do), so valgrind sees no leak. */
static tmesh repro[2];

static void repro_teardown(void)
{
    tm_free(&repro[0]);
    tm_free(&repro[1]);
}

/* Found by near_touch (a long run's seed 21; seeds 11, 45 and 99 alike):
 * the first contact is at s* = 1 - 1/5629499534213121, in (1 - 2^-52, 1),
 * by A's edge {2 8} and B's edge {0 1}, so time 1 is right; the library
 * reports A's edge {2 3} with B's {0 1}, which first touch at
 * 1 - 3/36028797018963971, about 1e-16 later, in the same 2^-52 step of
 * the time. The header promises features that touch within the time's
 * 2^-52 (its resolution), not the very first: this case holds it to
 * that. */
/* _i 0: that motion; 1 to 3: the same continued to 2, 4 and 8 times its
 * length: the first contact at about 1/2, 1/4, 1/8, the same two pairs
 * 1e-16 apart, the same features reported (so not a matter of the last
 * step before 1). */
START_TEST(first_features_near_the_end)
{
    tmesh *a = &repro[0], *b = &repro[1];
    tm_ell(a, 0.5);
    static const double p[12] = {0, -0.5, -0.25, -0.25, 0, 0.25, 1, 1, 0.5, 0.5, 0, 1};
    ck_assert(tm_tet(b, p));
    const double ta0[3] = {0, 0x1p-2, 0}, ta1[3] = {0, 0x1p-2, 0x1.5555555555556p-4};
    const double tb0[3] = {0x1.4p+0, 0x1p-1, 0x1.8p-1};
    const double tb1[3] = {0x1.ffffffffffffep-2, 0x1.8p-1, 0x1.555555555555p-4};
    const double m = (double)(1 << _i);
    double ta2[3], tb2[3];
    for (int k = 0; k < 3; ++k) {
        ta2[k] = _i == 0 ? ta1[k] : ta0[k] + m * (ta1[k] - ta0[k]);
        tb2[k] = _i == 0 ? tb1[k] : tb0[k] + m * (tb1[k] - tb0[k]);
    }
    check_case(a, ta0, ta2, b, tb0, tb2);
}
END_TEST

/* ---- the interface ------------------------------------------------------------------ */

START_TEST(bad_translations)
{
    tmesh a, b;
    tm_box(&a, 1, 1, 1);
    tm_box(&b, 1, 1, 1);
    const double bad[] = {NAN, INFINITY, -INFINITY, 1.0000001e100, -2e100, 1e300};
    const noctStatus want[] = {NOCT_ERR_NONFINITE, NOCT_ERR_NONFINITE, NOCT_ERR_NONFINITE,
                               NOCT_ERR_TOO_LARGE, NOCT_ERR_TOO_LARGE, NOCT_ERR_TOO_LARGE};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
        for (int which = 0; which < 4; ++which) {
            for (int k = 0; k < 3; ++k) {
                double t[4][3] = {{0, 0, 0}, {1, 0, 0}, {3, 0, 0}, {3, 0, 0}};
                t[which][k] = bad[i];
                bool col = false;
                noctSweepHit hit;
                ck_assert_int_eq(noctCollideSwept(a.m, t[0], t[1], b.m, t[2], t[3], &col, &hit,
                                                  NULL),
                                 want[i]);
                ck_assert_int_eq(noctCollideSwept(a.m, t[0], t[1], b.m, t[2], t[3], &col, NULL,
                                                  NULL),
                                 want[i]);
            }
        }
    }
    /* at the limit, fine */
    double t0[3] = {1e100, 0, 0}, t1[3] = {-1e100, 0, 0};
    bool col = false;
    noctNarrowStats st = {0};
    ck_assert_int_eq(noctCollideSwept(a.m, t0, t1, b.m, zero, zero, &col, NULL, &st), NOCT_OK);
    ck_assert(col);
    check_case(&a, t0, t1, &b, zero, zero);
    tm_free(&a);
    tm_free(&b);
}
END_TEST

/* One mesh against itself (the same noctMesh for both). */
START_TEST(same_mesh_twice)
{
    tmesh a;
    tm_ell(&a, 1);
    uint64_t rng = 4242;
    for (int n = 0; n < 30; ++n) {
        motion mo;
        random_motion(&rng, &mo, true);
        check_motion(&a, &a, &mo);
    }
    tm_free(&a);
}
END_TEST

static Suite *swept_suite(void)
{
    Suite *s = suite_create("swept");
    TCase *tc = test_case(s, "hard cases", 60, NULL);
    add_tests(tc, grazes, sliding, start_in_contact, end_only, tunnelling, bad_translations,
              same_mesh_twice);
    /* A disagreement with the header, minimised: fails for now. */
    tc = test_case(s, "features touching first", 0, NULL);
    tcase_add_checked_fixture(tc, NULL, repro_teardown);
    tcase_add_loop_test(tc, first_features_near_the_end, 0, 4);
    /* Each random test runs its cases from the seed _i: seed 0 here (under
     * valgrind too), more seeds in the slow case. */
    tc = test_case(s, "random against the oracle", 120, NULL);
    tcase_add_loop_test(tc, random_tetrahedra_grid, 0, 1);
    tcase_add_loop_test(tc, random_tetrahedra_doubles, 0, 1);
    tcase_add_loop_test(tc, random_boxes_and_ell, 0, 1);
    tcase_add_loop_test(tc, rounded_flat, 0, 1);
    tcase_add_loop_test(tc, near_touch, 0, 1);
    tc = test_case(s, "invariances", 120, NULL);
    tcase_add_loop_test(tc, invariances, 0, 1);
    tcase_add_loop_test(tc, scales_and_offsets, 0, 1);

    tc = test_case(s, "random, more seeds", 300, "slow seeds");
    tcase_add_loop_test(tc, random_tetrahedra_grid, 1, 6);
    tcase_add_loop_test(tc, random_tetrahedra_doubles, 1, 4);
    tcase_add_loop_test(tc, random_boxes_and_ell, 1, 8);
    tcase_add_loop_test(tc, rounded_flat, 1, 6);
    tcase_add_loop_test(tc, near_touch, 1, 10);
    tcase_add_loop_test(tc, invariances, 1, 6);
    tcase_add_loop_test(tc, scales_and_offsets, 1, 4);
    return s;
}

int main(void)
{
    test_gmp_pools();
    return run_suite(swept_suite());
}
