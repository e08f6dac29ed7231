/* SPDX-License-Identifier: MIT */
/*
 * Check suite for the contacts (noctCollideContact(), noctWorldContacts()).
 *
 * The expectations are the test's own:
 *  - boxes in closed-form configurations (face on face, edge across edge,
 *    a corner into a face, one inside the other), whose minimum
 *    translation and deepest point are known by hand;
 *  - for convex meshes (boxes, rotated or not, and octahedra), the
 *    minimum translation by brute force: the penetration depth of two
 *    convex polytopes is the distance from the origin to the boundary of
 *    the hull of their vertices' differences, found by trying every
 *    triple of differences as a supporting plane (long double);
 *  - every point lies in both solids up to the documented tolerance
 *    2^-30 M (convex: each of the test's own placed triangle planes;
 *    non-convex: within it of both boundaries, by point-triangle
 *    distances), every normal is a unit vector;
 *  - the world's contacts are the pairwise calls', and a world that does
 *    not ask steps exactly as one that does.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <check.h>

#include <noctree/narrowphase.h>
#include <noctree/world.h>

#include "testutil.h"

/* A convex or non-convex test shape: its own copy of the vertices and a
 * fan triangulation of its polygons, and the library's mesh. */
typedef struct tshape {
    double v[16][3];
    int nv;
    int tri[32][3];
    int nt;
    bool convex;
    noctMesh *m;
} tshape;

static void make_shape(tshape *s, const double *v, int nv, const int *sizes, int np,
                       const int *idx, bool convex)
{
    memset(s, 0, sizeof *s);
    s->nv = nv;
    memcpy(s->v, v, (size_t)nv * 3 * sizeof(double));
    uint32_t usizes[16], uidx[64];
    int k = 0;
    for (int p = 0; p < np; ++p) {
        usizes[p] = (uint32_t)sizes[p];
        for (int c = 0; c < sizes[p]; ++c)
            uidx[k + c] = (uint32_t)idx[k + c];
        for (int c = 1; c + 1 < sizes[p]; ++c) {
            s->tri[s->nt][0] = idx[k];
            s->tri[s->nt][1] = idx[k + c];
            s->tri[s->nt][2] = idx[k + c + 1];
            ++s->nt;
        }
        k += sizes[p];
    }
    noctError err;
    ck_assert_msg(noctMeshCreate(v, (size_t)nv, usizes, (size_t)np, uidx, &s->m, &err) ==
                      NOCT_OK,
                  "%s", err.message);
    ck_assert(noctMeshIsConvex(s->m) == convex);
    s->convex = convex;
}

static void make_box(tshape *s, double hx, double hy, double hz)
{
    double v[24];
    for (int i = 0; i < 8; ++i) {
        v[3 * i] = (i & 4) ? hx : -hx;
        v[3 * i + 1] = (i & 2) ? hy : -hy;
        v[3 * i + 2] = (i & 1) ? hz : -hz;
    }
    /* outward, counter-clockwise seen from outside */
    static const int idx[24] = {0, 1, 3, 2, 4, 6, 7, 5, 0, 4, 5, 1,
                                2, 3, 7, 6, 0, 2, 6, 4, 1, 5, 7, 3};
    static const int sizes[6] = {4, 4, 4, 4, 4, 4};
    make_shape(s, v, 8, sizes, 6, idx, true);
}

static void make_octa(tshape *s, double r)
{
    const double v[18] = {r, 0, 0, -r, 0, 0, 0, r, 0, 0, -r, 0, 0, 0, r, 0, 0, -r};
    static const int idx[24] = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4,
                                2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
    static const int sizes[8] = {3, 3, 3, 3, 3, 3, 3, 3};
    make_shape(s, v, 6, sizes, 8, idx, true);
}

/* The L prism of testutil.h (make_ell), with the test's own copy. */
static void make_ell_shape(tshape *s)
{
    static const double P[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
    double v[36];
    for (int i = 0; i < 12; ++i) {
        v[3 * i] = P[i % 6][0] - 1;
        v[3 * i + 1] = P[i % 6][1] - 1;
        v[3 * i + 2] = i < 6 ? -0.5 : 0.5;
    }
    int sizes[10], idx[40], n = 0, k = 0;
    const int faces[4][4] = {{6, 7, 8, 9}, {6, 9, 10, 11}, {0, 3, 2, 1}, {0, 5, 4, 3}};
    for (int f = 0; f < 4; ++f) {
        sizes[n++] = 4;
        for (int c = 0; c < 4; ++c)
            idx[k++] = faces[f][c];
    }
    for (int i = 0; i < 6; ++i) {
        const int j = (i + 1) % 6;
        sizes[n++] = 4;
        idx[k++] = i;
        idx[k++] = j;
        idx[k++] = j + 6;
        idx[k++] = i + 6;
    }
    make_shape(s, v, 12, sizes, n, idx, false);
}

static noctTransform xf(const noctQuat *q, double x, double y, double z)
{
    noctTransform t = noctIdentityTransform();
    if (q != NULL)
        t.q = *q;
    t.p[0] = x;
    t.p[1] = y;
    t.p[2] = z;
    return t;
}

static noctQuat axis_angle(double ax, double ay, double az, double deg)
{
    noctQuat q;
    ck_assert(noctQuatFromAxisAngle((double[3]){ax, ay, az}, deg, &q) == NOCT_OK);
    return q;
}

/* The shape's vertices placed by x (as the library places them, up to an
 * ulp or so: fl(R v) in row order, then + p). */
static void placed(const tshape *s, const noctTransform *x, long double out[][3])
{
    double R[9];
    ck_assert(noctQuatToMatrix(&x->q, R, NULL) == NOCT_OK);
    for (int i = 0; i < s->nv; ++i)
        for (int r = 0; r < 3; ++r) {
            const double rv = R[3 * r] * s->v[i][0] + R[3 * r + 1] * s->v[i][1] +
                              R[3 * r + 2] * s->v[i][2];
            out[i][r] = (long double)(rv + x->p[r]);
        }
}

static void lsub(const long double a[3], const long double b[3], long double o[3])
{
    for (int k = 0; k < 3; ++k)
        o[k] = a[k] - b[k];
}

static void lcross(const long double a[3], const long double b[3], long double o[3])
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

static long double ldot(const long double a[3], const long double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* The largest magnitude of a placed coordinate: M of the tolerance. */
static double magnitude2(long double a[][3], int na, long double b[][3], int nb)
{
    long double m = 0;
    for (int i = 0; i < na; ++i)
        for (int k = 0; k < 3; ++k)
            m = fmaxl(m, fabsl(a[i][k]));
    for (int i = 0; i < nb; ++i)
        for (int k = 0; k < 3; ++k)
            m = fmaxl(m, fabsl(b[i][k]));
    return (double)m;
}

/* The farthest p lies outside a convex shape's placed triangle planes. */
static long double outside_convex(const tshape *s, long double v[][3], const double p[3])
{
    long double worst = -INFINITY;
    const long double q[3] = {p[0], p[1], p[2]};
    for (int t = 0; t < s->nt; ++t) {
        long double e1[3], e2[3], n[3], d[3];
        lsub(v[s->tri[t][1]], v[s->tri[t][0]], e1);
        lsub(v[s->tri[t][2]], v[s->tri[t][0]], e2);
        lcross(e1, e2, n);
        const long double len = sqrtl(ldot(n, n));
        lsub(q, v[s->tri[t][0]], d);
        worst = fmaxl(worst, ldot(n, d) / len);
    }
    return worst;
}

/* Distance from p to triangle abc (long double; by the closest point on
 * the plane if inside, else on the edges). */
static long double seg_dist(const long double p[3], const long double a[3],
                            const long double b[3])
{
    long double ab[3], ap[3];
    lsub(b, a, ab);
    lsub(p, a, ap);
    long double t = ldot(ap, ab) / ldot(ab, ab);
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    long double d[3];
    for (int k = 0; k < 3; ++k)
        d[k] = p[k] - (a[k] + t * ab[k]);
    return sqrtl(ldot(d, d));
}

static long double tri_dist(const long double p[3], const long double a[3],
                            const long double b[3], const long double c[3])
{
    long double e1[3], e2[3], n[3], ap[3];
    lsub(b, a, e1);
    lsub(c, a, e2);
    lcross(e1, e2, n);
    lsub(p, a, ap);
    const long double nn = ldot(n, n), h = ldot(ap, n) / nn;
    long double q[3];
    for (int k = 0; k < 3; ++k)
        q[k] = p[k] - h * n[k];
    /* q inside: barycentric signs */
    long double qa[3], qb[3], qc[3], x1[3], x2[3], x3[3];
    lsub(a, q, qa);
    lsub(b, q, qb);
    lsub(c, q, qc);
    lcross(qa, qb, x1);
    lcross(qb, qc, x2);
    lcross(qc, qa, x3);
    if (ldot(x1, n) >= 0 && ldot(x2, n) >= 0 && ldot(x3, n) >= 0)
        return fabsl(h) * sqrtl(nn);
    return fminl(seg_dist(p, a, b), fminl(seg_dist(p, b, c), seg_dist(p, c, a)));
}

static long double boundary_dist(const tshape *s, long double v[][3], const double p[3])
{
    const long double q[3] = {p[0], p[1], p[2]};
    long double best = INFINITY;
    for (int t = 0; t < s->nt; ++t)
        best = fminl(best, tri_dist(q, v[s->tri[t][0]], v[s->tri[t][1]], v[s->tri[t][2]]));
    return best;
}

/* The brute-force penetration depth: the least distance from the origin
 * to a supporting plane of the hull of the differences a_i - b_j. */
static long double brute_depth(long double a[][3], int na, long double b[][3], int nb)
{
    long double d[256][3];
    int n = 0;
    for (int i = 0; i < na; ++i)
        for (int j = 0; j < nb; ++j)
            lsub(a[i], b[j], d[n++]);
    long double scale = 0;
    for (int i = 0; i < n; ++i)
        scale = fmaxl(scale, sqrtl(ldot(d[i], d[i])));
    long double best = INFINITY;
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j)
            for (int k = j + 1; k < n; ++k) {
                long double e1[3], e2[3], nrm[3];
                lsub(d[j], d[i], e1);
                lsub(d[k], d[i], e2);
                lcross(e1, e2, nrm);
                const long double len = sqrtl(ldot(nrm, nrm));
                if (len <= 1e-9L * scale * scale)
                    continue;
                for (int c = 0; c < 3; ++c)
                    nrm[c] /= len;
                const long double off = ldot(nrm, d[i]);
                int above = 0, below = 0;
                for (int m = 0; m < n && !(above && below); ++m) {
                    const long double s = ldot(nrm, d[m]) - off;
                    above |= s > 1e-12L * scale;
                    below |= s < -1e-12L * scale;
                }
                if (above && below)
                    continue;
                best = fminl(best, fabsl(off));
            }
    return best;
}

/* max over the differences of (a_i - b_j) . n: the support of A - B. */
static long double support_diff(long double a[][3], int na, long double b[][3], int nb,
                                const double n[3])
{
    const long double u[3] = {n[0], n[1], n[2]};
    long double ha = -INFINITY, lb = INFINITY;
    for (int i = 0; i < na; ++i)
        ha = fmaxl(ha, ldot(a[i], u));
    for (int j = 0; j < nb; ++j)
        lb = fminl(lb, ldot(b[j], u));
    return ha - lb;
}

static void expect_unit(const noctContact *c)
{
    const double len = sqrt(c->normal[0] * c->normal[0] + c->normal[1] * c->normal[1] +
                            c->normal[2] * c->normal[2]);
    ck_assert_msg(fabs(len - 1) < 1e-12, "normal length %.17g", len);
}

/* Every point of a contact of two convex shapes in both, within the
 * documented tolerance; and the contact's normal and depth against the
 * brute force. */
static void check_convex(const tshape *a, const noctTransform *xa, const tshape *b,
                         const noctTransform *xb, const noctContact *c)
{
    long double va[16][3], vb[16][3];
    placed(a, xa, va);
    placed(b, xb, vb);
    const double M = magnitude2(va, a->nv, vb, b->nv), tol = 0x1p-30 * M;
    ck_assert_int_eq(c->kind, NOCT_CONTACT_CONVEX);
    expect_unit(c);
    ck_assert_uint_ge(c->count, 1);
    ck_assert_uint_le(c->count, NOCT_CONTACT_POINTS);
    for (unsigned i = 0; i < c->count; ++i) {
        ck_assert_msg(outside_convex(a, va, c->points[i]) <= tol, "point %u outside A by %Lg",
                      i, outside_convex(a, va, c->points[i]));
        ck_assert_msg(outside_convex(b, vb, c->points[i]) <= tol, "point %u outside B by %Lg",
                      i, outside_convex(b, vb, c->points[i]));
        /* a chord along the normal lies in the projections' overlap */
        ck_assert(c->point_depth[i] >= 0 && c->point_depth[i] <= c->depth + 1e-12 * M);
    }
    const long double bd = brute_depth(va, a->nv, vb, b->nv);
    ck_assert_msg(fabsl(bd - c->depth) <= 1e-12L * M, "depth %.17g, brute force %.17Lg",
                  c->depth, bd);
    /* the normal is the minimum's: A - B reaches exactly depth along it */
    const long double sd = support_diff(va, a->nv, vb, b->nv, c->normal);
    ck_assert_msg(fabsl(sd - c->depth) <= 1e-12L * M, "support %.17Lg, depth %.17g", sd,
                  c->depth);
    /* the first point is the deepest */
    for (unsigned i = 1; i < c->count; ++i)
        ck_assert(c->point_depth[i] <= c->point_depth[0] + tol);
}

static noctContact contact_of(const tshape *a, const noctTransform *xa, const tshape *b,
                              const noctTransform *xb, bool expect)
{
    noctContact c;
    bool colliding;
    noctError err;
    ck_assert_msg(noctCollideContact(a->m, xa, b->m, xb, &colliding, &c, &err) == NOCT_OK, "%s",
                  err.message);
    ck_assert(colliding == expect);
    bool exact;
    ck_assert(noctCollideTransformed(a->m, xa, b->m, xb, NOCT_ACCURACY_EXACT, &exact, NULL,
                                     NULL) == NOCT_OK);
    ck_assert(exact == colliding);
    ck_assert((c.kind == NOCT_CONTACT_NONE) == !colliding);
    return c;
}

static bool has_point(const noctContact *c, double x, double y, double z, double tol)
{
    for (unsigned i = 0; i < c->count; ++i)
        if (fabs(c->points[i][0] - x) <= tol && fabs(c->points[i][1] - y) <= tol &&
            fabs(c->points[i][2] - z) <= tol)
            return true;
    return false;
}

START_TEST(test_face_face)
{
    tshape a, b;
    make_box(&a, 1, 1, 1);
    make_box(&b, 1, 1, 1);
    const noctTransform xa = xf(NULL, 0, 0, 0), xb = xf(NULL, 1.5, 0.25, 0.125);
    noctContact c = contact_of(&a, &xa, &b, &xb, true);
    check_convex(&a, &xa, &b, &xb, &c);
    ck_assert(c.depth == 0.5);
    ck_assert(c.normal[0] == 1 && c.normal[1] == 0 && c.normal[2] == 0);
    ck_assert(!c.contained);
    /* the corners of the overlap's face, half way through it */
    ck_assert_uint_eq(c.count, 4);
    const double ys[2] = {-0.75, 1}, zs[2] = {-0.875, 1};
    for (int i = 0; i < 4; ++i)
        ck_assert(has_point(&c, 0.75, ys[i & 1], zs[i >> 1], 1e-15));
    for (int i = 0; i < 4; ++i)
        ck_assert(c.point_depth[i] == 0.5);
    /* B on the other side: the normal turns round */
    const noctTransform xc = xf(NULL, -1.75, 0, 0);
    c = contact_of(&a, &xa, &b, &xc, true);
    check_convex(&a, &xa, &b, &xc, &c);
    ck_assert(c.depth == 0.25 && c.normal[0] == -1);
    /* touching face to face: depth 0, colliding */
    const noctTransform xt = xf(NULL, 0, 2, 0);
    c = contact_of(&a, &xa, &b, &xt, true);
    ck_assert(c.depth == 0 && c.normal[1] == 1);
    ck_assert_uint_eq(c.count, 4);
    /* apart: nothing */
    const noctTransform xn = xf(NULL, 0, 2.0000001, 0);
    c = contact_of(&a, &xa, &b, &xn, false);
    ck_assert_uint_eq(c.count, 0);
    noctMeshDestroy(a.m);
    noctMeshDestroy(b.m);
}
END_TEST

START_TEST(test_edge_edge)
{
    /* A turned 45 degrees about z: its edge along z at x = sqrt 2; B
     * turned 45 degrees about y: its edge along y at x = px - sqrt 2. */
    tshape a, b;
    make_box(&a, 1, 1, 1);
    make_box(&b, 1, 1, 1);
    const noctQuat qa = axis_angle(0, 0, 1, 45), qb = axis_angle(0, 1, 0, 45);
    const double d = 0.125, s2 = sqrt(2.0);
    const noctTransform xa = xf(&qa, 0, 0, 0), xb = xf(&qb, 2 * s2 - d, 0, 0);
    noctContact c = contact_of(&a, &xa, &b, &xb, true);
    check_convex(&a, &xa, &b, &xb, &c);
    ck_assert_msg(fabs(c.depth - d) < 1e-14, "depth %.17g", c.depth);
    ck_assert(fabs(c.normal[0] - 1) < 1e-14);
    /* the deepest point: where the edges cross, half way */
    ck_assert(fabs(c.points[0][0] - (s2 - d / 2)) < 1e-14);
    ck_assert(fabs(c.points[0][1]) < 1e-14 && fabs(c.points[0][2]) < 1e-14);
    ck_assert(fabs(c.point_depth[0] - d) < 1e-14);
    noctMeshDestroy(a.m);
    noctMeshDestroy(b.m);
}
END_TEST

START_TEST(test_vertex_face)
{
    /* B's corner (1, 1, 1) turned to point along -x, d into A's +x face. */
    tshape a, b;
    make_box(&a, 1, 1, 1);
    make_box(&b, 1, 1, 1);
    const double deg = acos(-1 / sqrt(3.0)) * 180 / acos(-1.0);
    const noctQuat qb = axis_angle(0, 1, -1, deg); /* (1,1,1) x (-1,0,0) */
    const double d = 0.0625, s3 = sqrt(3.0);
    const noctTransform xa = xf(NULL, 0, 0, 0), xb = xf(&qb, 1 + s3 - d, 0, 0);
    noctContact c = contact_of(&a, &xa, &b, &xb, true);
    check_convex(&a, &xa, &b, &xb, &c);
    ck_assert_msg(fabs(c.depth - d) < 1e-13, "depth %.17g", c.depth);
    ck_assert(fabs(c.normal[0] - 1) < 1e-13);
    ck_assert(fabs(c.points[0][0] - (1 - d / 2)) < 1e-13);
    ck_assert(fabs(c.points[0][1]) < 1e-13 && fabs(c.points[0][2]) < 1e-13);
    ck_assert(fabs(c.point_depth[0] - d) < 1e-13);
    /* the others: where B's edges from the corner cross A's face */
    ck_assert_uint_eq(c.count, 4);
    for (unsigned i = 1; i < c.count; ++i)
        ck_assert(fabs(c.points[i][0] - 1) < 1e-13 && fabs(c.point_depth[i]) < 1e-13);
    noctMeshDestroy(a.m);
    noctMeshDestroy(b.m);
}
END_TEST

START_TEST(test_containment)
{
    tshape big, small, ell;
    make_box(&big, 3, 3, 3);
    make_box(&small, 0.5, 0.5, 0.5);
    make_ell_shape(&ell);
    const noctTransform xa = xf(NULL, 0, 0, 0), xb = xf(NULL, 0.5, 0.25, 0);
    noctContact c = contact_of(&big, &xa, &small, &xb, true);
    check_convex(&big, &xa, &small, &xb, &c);
    ck_assert(c.contained);
    /* out through +x: 3 - 0 */
    ck_assert(c.depth == 3 && c.normal[0] == 1);
    ck_assert_uint_eq(c.count, 4);
    for (int i = 0; i < 4; ++i) {
        ck_assert(c.points[i][0] == 0.5 && c.point_depth[i] == 1);
        ck_assert(fabs(c.points[i][1] - 0.25) == 0.5 && fabs(c.points[i][2]) == 0.5);
    }
    /* the small box inside the L's arm (x in [-1, 1], y in [-1, 0]) */
    tshape tiny;
    make_box(&tiny, 0.125, 0.125, 0.125);
    const noctTransform xt = xf(NULL, 0.5, -0.5, 0);
    c = contact_of(&ell, &xa, &tiny, &xt, true);
    ck_assert_int_eq(c.kind, NOCT_CONTACT_CONTAINED);
    ck_assert(c.contained && c.depth == 0);
    ck_assert_uint_eq(c.count, 1);
    /* the inner box's first vertex, placed; the normal centre to centre */
    ck_assert(c.points[0][0] == 0.375 && c.points[0][1] == -0.625 && c.points[0][2] == -0.125);
    expect_unit(&c);
    /* the L's centre is its hull's: the mean of its 12 vertices */
    double ce[3] = {0, 0, 0};
    for (int i = 0; i < 12; ++i)
        for (int k = 0; k < 3; ++k)
            ce[k] += ell.v[i][k] / 12;
    double d[3] = {0.5 - ce[0], -0.5 - ce[1], 0 - ce[2]};
    const double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (int k = 0; k < 3; ++k)
        ck_assert(fabs(c.normal[k] - d[k] / len) < 1e-12);
    /* the tiny box in the notch: nothing */
    const noctTransform xn = xf(NULL, 0.5, 0.5, 0);
    c = contact_of(&ell, &xa, &tiny, &xn, false);
    noctMeshDestroy(big.m);
    noctMeshDestroy(small.m);
    noctMeshDestroy(tiny.m);
    noctMeshDestroy(ell.m);
}
END_TEST

static void random_convex_pairs(tshape *a, tshape *b, int trials, uint64_t seed)
{
    uint64_t rng = seed;
    int hits = 0;
    for (int t = 0; t < trials; ++t) {
        noctQuat qa, qb;
        test_random_quat(&rng, &qa);
        test_random_quat(&rng, &qb);
        if (t % 4 == 0)
            qa = (noctQuat){0, 0, 0, 1};
        const noctTransform xa = xf(&qa, test_uniform(&rng) - 0.5, test_uniform(&rng) - 0.5,
                                    test_uniform(&rng) - 0.5);
        const noctTransform xb = xf(&qb, 3 * test_uniform(&rng) - 1.5,
                                    3 * test_uniform(&rng) - 1.5, 3 * test_uniform(&rng) - 1.5);
        noctContact c;
        bool colliding;
        ck_assert(noctCollideContact(a->m, &xa, b->m, &xb, &colliding, &c, NULL) == NOCT_OK);
        if (!colliding) {
            ck_assert_int_eq(c.kind, NOCT_CONTACT_NONE);
            continue;
        }
        ++hits;
        check_convex(a, &xa, b, &xb, &c);
    }
    ck_assert_int_gt(hits, trials / 4);
}

START_TEST(test_rotated_boxes)
{
    tshape a, b;
    make_box(&a, 1, 0.5, 0.75);
    make_box(&b, 0.5, 1, 0.25);
    random_convex_pairs(&a, &b, 300, 7);
    noctMeshDestroy(a.m);
    noctMeshDestroy(b.m);
}
END_TEST

START_TEST(test_octahedra)
{
    tshape a, b, box;
    make_octa(&a, 1);
    make_octa(&b, 0.75);
    make_box(&box, 0.5, 0.5, 0.5);
    random_convex_pairs(&a, &b, 300, 11);
    random_convex_pairs(&a, &box, 200, 13);
    noctMeshDestroy(a.m);
    noctMeshDestroy(b.m);
    noctMeshDestroy(box.m);
}
END_TEST

/* A non-convex pair: every point on both boundaries, the normal a unit
 * vector, no depth. */
static void check_crossing(const tshape *a, const noctTransform *xa, const tshape *b,
                           const noctTransform *xb, const noctContact *c)
{
    long double va[16][3], vb[16][3];
    placed(a, xa, va);
    placed(b, xb, vb);
    const double tol = 0x1p-30 * magnitude2(va, a->nv, vb, b->nv);
    ck_assert_int_eq(c->kind, NOCT_CONTACT_CROSSING);
    ck_assert(!c->contained && c->depth == 0);
    expect_unit(c);
    ck_assert_uint_ge(c->count, 1);
    for (unsigned i = 0; i < c->count; ++i) {
        ck_assert_msg(boundary_dist(a, va, c->points[i]) <= tol, "off A by %Lg",
                      boundary_dist(a, va, c->points[i]));
        ck_assert_msg(boundary_dist(b, vb, c->points[i]) <= tol, "off B by %Lg",
                      boundary_dist(b, vb, c->points[i]));
        ck_assert(c->point_depth[i] == 0);
    }
}

START_TEST(test_nonconvex)
{
    tshape ell, box;
    make_ell_shape(&ell);
    make_box(&box, 0.25, 0.25, 0.25);
    const noctTransform xa = xf(NULL, 0, 0, 0);
    /* the box pushed into the L's top face from above (+z): the normal
     * is +z, from the L towards the box */
    const noctTransform xb = xf(NULL, -0.5, -0.5, 0.625);
    noctContact c = contact_of(&ell, &xa, &box, &xb, true);
    check_crossing(&ell, &xa, &box, &xb, &c);
    ck_assert(fabs(c.normal[2] - 1) < 1e-12);
    /* the crossing is the square where the box's sides cut the face */
    ck_assert_uint_eq(c.count, 4);
    for (int i = 0; i < 4; ++i)
        ck_assert(has_point(&c, -0.5 + ((i & 1) ? 0.25 : -0.25),
                            -0.5 + ((i & 2) ? 0.25 : -0.25), 0.5, 1e-15));
    /* the box in the notch's corner, across the two inner faces */
    uint64_t rng = 5;
    int hits = 0;
    for (int t = 0; t < 200; ++t) {
        noctQuat qb;
        test_random_quat(&rng, &qb);
        const noctTransform xr = xf(&qb, 1.5 * test_uniform(&rng) - 0.25,
                                    1.5 * test_uniform(&rng) - 0.25,
                                    test_uniform(&rng) - 0.5);
        noctContact r;
        bool colliding;
        ck_assert(noctCollideContact(ell.m, &xa, box.m, &xr, &colliding, &r, NULL) == NOCT_OK);
        if (!colliding || r.kind == NOCT_CONTACT_CONTAINED)
            continue;
        ++hits;
        check_crossing(&ell, &xa, &box, &xr, &r);
    }
    ck_assert_int_gt(hits, 20);
    /* two Ls */
    const noctTransform xl = xf(NULL, 0.5, 0.5, 0.25);
    c = contact_of(&ell, &xa, &ell, &xl, true);
    check_crossing(&ell, &xa, &ell, &xl, &c);
    noctMeshDestroy(ell.m);
    noctMeshDestroy(box.m);
}
END_TEST

START_TEST(test_far_and_scaled)
{
    /* Far from the origin and small: the tolerance is relative to M. */
    tshape a, b;
    make_octa(&a, 1e-3);
    make_octa(&b, 1e-3);
    const noctQuat q = axis_angle(1, 2, 3, 30);
    const noctTransform xa = xf(NULL, 1e4, -2e4, 3e4), xb = xf(&q, 1e4 + 1.5e-3, -2e4, 3e4);
    noctContact c = contact_of(&a, &xa, &b, &xb, true);
    long double va[16][3], vb[16][3];
    placed(&a, &xa, va);
    placed(&b, &xb, vb);
    const double M = magnitude2(va, a.nv, vb, b.nv);
    ck_assert_int_eq(c.kind, NOCT_CONTACT_CONVEX);
    ck_assert(fabsl(brute_depth(va, a.nv, vb, b.nv) - c.depth) <= 1e-12L * M);
    for (unsigned i = 0; i < c.count; ++i) {
        ck_assert(outside_convex(&a, va, c.points[i]) <= 0x1p-30 * M);
        ck_assert(outside_convex(&b, vb, c.points[i]) <= 0x1p-30 * M);
    }
    noctMeshDestroy(a.m);
    noctMeshDestroy(b.m);
}
END_TEST

/* A small world of meshes (some turned) and box primitives. */
static noctWorld *contact_world(const tshape *const *shapes, int ns, int n, uint64_t seed,
                                bool moving)
{
    noctWorldDef def = noctDefaultWorldDef();
    noctWorld *w;
    ck_assert(noctWorldCreate(&def, &w, NULL) == NOCT_OK);
    uint64_t rng = seed;
    for (int i = 0; i < n; ++i) {
        noctObjectDef od = noctDefaultObjectDef();
        const int k = (int)test_rand_below(&rng, (size_t)ns + 1);
        if (k == ns) {
            od.mesh = NULL;
            od.half_extents[0] = 0.25 + 0.5 * test_uniform(&rng);
            od.half_extents[1] = 0.25 + 0.5 * test_uniform(&rng);
            od.half_extents[2] = 0.25 + 0.5 * test_uniform(&rng);
        } else {
            od.mesh = shapes[k]->m;
        }
        if (i % 2 == 0)
            test_random_quat(&rng, &od.transform.q);
        for (int a = 0; a < 3; ++a) {
            od.transform.p[a] = 6 * test_uniform(&rng);
            od.velocity[a] = moving ? 0.05 * (test_uniform(&rng) - 0.5) : 0;
        }
        noctObjectId id;
        ck_assert(noctWorldCreateObject(w, &od, &id, NULL) == NOCT_OK);
    }
    return w;
}

START_TEST(test_world)
{
    tshape octa, box, ell;
    make_octa(&octa, 0.75);
    make_box(&box, 0.5, 0.25, 0.75);
    make_ell_shape(&ell);
    const tshape *shapes[3] = {&octa, &box, &ell};
    noctWorld *w = contact_world(shapes, 3, 40, 3, true);
    size_t total = 0;
    for (int step = 0; step < 10; ++step) {
        ck_assert(noctWorldStep(w, NULL) == NOCT_OK);
        const noctPair *pairs;
        const size_t np = noctWorldColliding(w, &pairs);
        const noctContact *cs, *again;
        size_t n, n2;
        ck_assert(noctWorldContacts(w, &cs, &n, NULL) == NOCT_OK);
        ck_assert_uint_eq(n, np);
        ck_assert(noctWorldContacts(w, &again, &n2, NULL) == NOCT_OK);
        ck_assert(again == cs && n2 == n); /* kept, not made again */
        for (size_t i = 0; i < n; ++i) {
            noctTransform ta, tb;
            ck_assert(noctWorldGetTransform(w, pairs[i].a, &ta) == NOCT_OK);
            ck_assert(noctWorldGetTransform(w, pairs[i].b, &tb) == NOCT_OK);
            const noctMesh *ma = noctWorldGetMesh(w, pairs[i].a);
            const noctMesh *mb = noctWorldGetMesh(w, pairs[i].b);
            ck_assert_int_ne(cs[i].kind, NOCT_CONTACT_NONE); /* exact level */
            expect_unit(&cs[i]);
            if (ma == NULL || mb == NULL) {
                ck_assert(cs[i].kind == NOCT_CONTACT_CONVEX ||
                          (ma != NULL && !noctMeshIsConvex(ma)) ||
                          (mb != NULL && !noctMeshIsConvex(mb)));
                continue; /* a box primitive: no mesh to compare with */
            }
            noctContact c;
            bool colliding;
            ck_assert(noctCollideContact(ma, &ta, mb, &tb, &colliding, &c, NULL) == NOCT_OK);
            ck_assert(colliding);
            ck_assert_msg(memcmp(&c, &cs[i], sizeof c) == 0, "pair %zu differs", i);
            ++total;
        }
    }
    ck_assert_uint_gt(total, 5);
    noctWorldDestroy(w);
    noctMeshDestroy(octa.m);
    noctMeshDestroy(box.m);
    noctMeshDestroy(ell.m);
}
END_TEST

START_TEST(test_world_box_primitives)
{
    /* Two box primitives, one turned: their contact is that of the boxes
     * as meshes, face on face known by hand. */
    noctWorldDef def = noctDefaultWorldDef();
    noctWorld *w;
    ck_assert(noctWorldCreate(&def, &w, NULL) == NOCT_OK);
    noctObjectDef od = noctDefaultObjectDef();
    od.half_extents[0] = od.half_extents[1] = od.half_extents[2] = 1;
    noctObjectId ia, ib;
    ck_assert(noctWorldCreateObject(w, &od, &ia, NULL) == NOCT_OK);
    od.transform.q = axis_angle(0, 0, 1, 90); /* the same box, turned onto itself */
    od.transform.p[0] = 1.75;
    od.transform.p[1] = 0.5;
    ck_assert(noctWorldCreateObject(w, &od, &ib, NULL) == NOCT_OK);
    ck_assert(noctWorldStep(w, NULL) == NOCT_OK);
    const noctContact *cs;
    size_t n;
    ck_assert(noctWorldContacts(w, &cs, &n, NULL) == NOCT_OK);
    ck_assert_uint_eq(n, 1);
    ck_assert_int_eq(cs[0].kind, NOCT_CONTACT_CONVEX);
    ck_assert(fabs(cs[0].depth - 0.25) < 1e-15);
    ck_assert(fabs(cs[0].normal[0] - 1) < 1e-15);
    ck_assert_uint_eq(cs[0].count, 4);
    ck_assert(has_point(&cs[0], 0.875, -0.5, -1, 1e-15));
    ck_assert(has_point(&cs[0], 0.875, 1, 1, 1e-15));
    /* after the next step, b removed before asking: the pair is still
     * listed, with no contact */
    ck_assert(noctWorldStep(w, NULL) == NOCT_OK);
    ck_assert(noctWorldRemove(w, ib, NULL) == NOCT_OK);
    ck_assert(noctWorldContacts(w, &cs, &n, NULL) == NOCT_OK);
    ck_assert_uint_eq(n, 1);
    ck_assert_int_eq(cs[0].kind, NOCT_CONTACT_NONE);
    ck_assert_uint_eq(cs[0].count, 0);
    ck_assert(cs[0].depth == 0 && cs[0].normal[0] == 0);
    /* and none once a step ends the pair */
    ck_assert(noctWorldStep(w, NULL) == NOCT_OK);
    ck_assert(noctWorldContacts(w, &cs, &n, NULL) == NOCT_OK);
    ck_assert(n == 0 && cs == NULL);
    noctWorldDestroy(w);
}
END_TEST

START_TEST(test_world_pays_nothing)
{
    /* Two equal worlds, one asked for its contacts after every step: the
     * steps do the same work, counter for counter. */
    tshape octa, box;
    make_octa(&octa, 0.75);
    make_box(&box, 0.5, 0.25, 0.75);
    const tshape *shapes[2] = {&octa, &box};
    noctWorld *w1 = contact_world(shapes, 2, 60, 9, true);
    noctWorld *w2 = contact_world(shapes, 2, 60, 9, true);
    size_t asked = 0;
    for (int step = 0; step < 30; ++step) {
        ck_assert(noctWorldStep(w1, NULL) == NOCT_OK);
        ck_assert(noctWorldStep(w2, NULL) == NOCT_OK);
        const noctContact *cs;
        size_t n;
        ck_assert(noctWorldContacts(w2, &cs, &n, NULL) == NOCT_OK);
        asked += n;
        const noctPair *p1, *p2;
        ck_assert_uint_eq(noctWorldColliding(w1, &p1), noctWorldColliding(w2, &p2));
    }
    ck_assert_uint_gt(asked, 0);
    noctWorldCounters c1, c2;
    noctWorldGetCounters(w1, &c1);
    noctWorldGetCounters(w2, &c2);
    ck_assert_uint_eq(c1.candidate_pairs, c2.candidate_pairs);
    ck_assert_uint_eq(c1.tested_pairs, c2.tested_pairs);
    ck_assert_uint_eq(c1.colliding_pairs, c2.colliding_pairs);
    ck_assert_uint_eq(c1.narrow.exact_tests, c2.narrow.exact_tests);
    ck_assert_uint_eq(c1.narrow.triangle_pairs, c2.narrow.triangle_pairs);
    ck_assert_uint_eq(c1.narrow.containment_tests, c2.narrow.containment_tests);
    /* a world that never asked: an empty answer costs nothing either */
    noctWorldDestroy(w1);
    noctWorldDestroy(w2);
    noctMeshDestroy(octa.m);
    noctMeshDestroy(box.m);
}
END_TEST

static Suite *contacts_suite(void)
{
    Suite *s = suite_create("contacts");
    TCase *tc = test_case(s, "closed form", 0, NULL);
    add_tests(tc, test_face_face, test_edge_edge, test_vertex_face, test_containment,
              test_far_and_scaled);
    tc = test_case(s, "brute force", 60, NULL);
    add_tests(tc, test_rotated_boxes, test_octahedra, test_nonconvex);
    tc = test_case(s, "world", 60, NULL);
    add_tests(tc, test_world, test_world_box_primitives, test_world_pays_nothing);
    return s;
}

int main(void)
{
    return run_suite(contacts_suite());
}
