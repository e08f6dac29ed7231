/* SPDX-License-Identifier: MIT */
/*
 * Check suite for surfaces (noctMeshCreateSurface() and its kin, mesh.h):
 * meshes that need not be closed solids, whose point set is the union of
 * the closed triangles of their polygons' fans (each polygon split from
 * its first corner). Every verdict is compared with the test's own oracle
 * in exact rational arithmetic (GMP's mpq_t on the very doubles placed as
 * transform.h documents: fl(fl(fl(R_i0 v_0 + R_i1 v_1) + R_i2 v_2) + t_i),
 * R from noctQuatToMatrix(); mpq_set_d is exact). The oracle shares no
 * code with the library and was written from the definitions alone:
 *
 *  - Two closed triangles meet iff (non-coplanar) an edge of one meets the
 *    other (the intersection lies on the line of the two planes, and an end
 *    of it is an end of one triangle's chord, on that triangle's boundary)
 *    or (coplanar) an edge of one meets an edge of the other or a corner of
 *    one lies in the other, in 2D on the coordinate plane the normal is
 *    not parallel to. A segment meets a triangle iff, with both ends
 *    strictly on opposite sides of its plane, the three signed volumes of
 *    the segment with the triangle's edges do not have opposite signs; an
 *    end on the plane must lie in the triangle; a segment in the plane is
 *    tested in 2D. All signs are exact determinants in mpq.
 *  - Surface against surface: some pair of triangles meets. Surface
 *    against solid: some triangle meets a boundary triangle of the solid,
 *    or a corner of the surface lies in the closed solid (a triangle that
 *    meets the solid but not its boundary lies in its interior). Solid
 *    against solid: boundaries meet, or a vertex of one lies in the other.
 *    A point lies in the closed solid iff it lies in one of the solid's
 *    convex parts (the test's solids are boxes and tetrahedra, convex, and
 *    an L made of two boxes), on the inner side of (or on) every face.
 *  - Squared distance of two closed triangles that do not meet: the least
 *    of the 6 corner-triangle and 9 edge-edge squared distances, each the
 *    minimum of a convex quadratic (stationary point by Cramer's rule if it
 *    is inside, else clamped point-segment distances), exactly.
 * The oracle itself is checked against the library's long-tested solids:
 * for closed solids it must give noctCollide()'s exact verdict.
 *
 * Against it: noctCollide() and noctCollideTransformed() at the exact
 * level equal the oracle (both orders); the box and convex levels say
 * "meet" whenever the oracle does; noctDistance()'s colliding equals the
 * oracle and [lower, upper] holds the exact distance; a world of surfaces
 * and solids reports exactly the oracle's colliding pairs; STL (binary and
 * ASCII) and OBJ soups read back by noctMeshReadSurface() collide as the
 * mesh they were written from. Cases: random triangle soups on a dyadic
 * grid (touching is frequent) and at random doubles, open boxes against
 * small boxes inside, outside, through the opening and through the walls,
 * a closed shell made a surface (hollow) around a cube, Möbius strips,
 * non-manifold fans, meshes of several pieces, touching cases at dyadic
 * coordinates and one ulp apart (vertex on face, edge on edge, coplanar),
 * at offsets up to 2^30, quarter turns (exact) and general rotations.
 *
 * Disagreements are printed (case, oracle, library) before the test
 * fails, so that a run lists them all.
 */
#define _POSIX_C_SOURCE 200809L

#include <check.h>
#include <gmp.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <noctree/mesh.h>
#include <noctree/narrowphase.h>
#include <noctree/query.h>
#include <noctree/transform.h>
#include <noctree/world.h>

#include "testgmp.h"
#include "testutil.h"


/* ---- disagreements: printed, counted, failed at the end of a test --------------- */

static unsigned nfail;

static void disagree(const char *fmt, ...)
{
    if (nfail++ < 40) {
        va_list ap;
        va_start(ap, fmt);
        fputs("check-surfaces: DISAGREEMENT: ", stderr);
        vfprintf(stderr, fmt, ap);
        fputc('\n', stderr);
        va_end(ap);
    }
}

#define EXPECT_NO_DISAGREEMENT()                                                        \
    ck_assert_msg(nfail == 0, "%u disagreements with the oracle (listed on stderr)", nfail)

/* ---- the test's shapes ---------------------------------------------------------- */

#define SH_MAXV 6400
#define SH_MAXP 2400
#define SH_MAXI 8000

/* A mesh as given to the library: vertices and polygons; a solid or a
 * surface. A non-convex solid lists its convex parts (each a closed convex
 * solid of its own) for the oracle's point-in-solid test. */
typedef struct shape {
    size_t nv, np, ni;
    double v[3 * SH_MAXV];
    uint32_t sz[SH_MAXP];
    uint32_t ix[SH_MAXI];
    bool solid;
    int nparts;
    const struct shape *part[2];
    char name[48];
} shape;

static shape *sh_new(const char *name, bool solid)
{
    shape *s = calloc(1, sizeof *s);
    ck_assert_ptr_nonnull(s);
    s->solid = solid;
    snprintf(s->name, sizeof s->name, "%s", name);
    return s;
}

static uint32_t sh_v(shape *s, double x, double y, double z)
{
    ck_assert(s->nv < SH_MAXV);
    s->v[3 * s->nv] = x;
    s->v[3 * s->nv + 1] = y;
    s->v[3 * s->nv + 2] = z;
    return (uint32_t)s->nv++;
}

static void sh_poly(shape *s, uint32_t n, const uint32_t *c)
{
    ck_assert(s->np < SH_MAXP && s->ni + n <= SH_MAXI);
    s->sz[s->np++] = n;
    memcpy(&s->ix[s->ni], c, n * sizeof *c);
    s->ni += n;
}

static void sh_tri(shape *s, uint32_t a, uint32_t b, uint32_t c)
{
    sh_poly(s, 3, (const uint32_t[]){a, b, c});
}

/* A triangle with its own three corners (a soup's triangle). */
static void sh_soup_tri(shape *s, const double *p, const double *q, const double *r)
{
    uint32_t a = sh_v(s, p[0], p[1], p[2]);
    uint32_t b = sh_v(s, q[0], q[1], q[2]);
    uint32_t c = sh_v(s, r[0], r[1], r[2]);
    sh_tri(s, a, b, c);
}

/* Box corner i has the high x if bit 0, high y if bit 1, high z if bit 2;
 * the faces counter-clockwise seen from outside: -x, +x, -y, +y, -z, +z. */
static const uint32_t box_quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                         {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};

/* The box [lo, hi] with the faces whose bit is set in faces (63: all). */
static void sh_box_into(shape *s, const double lo[3], const double hi[3], unsigned faces)
{
    uint32_t base = (uint32_t)s->nv;
    for (int i = 0; i < 8; ++i)
        sh_v(s, i & 1 ? hi[0] : lo[0], i & 2 ? hi[1] : lo[1], i & 4 ? hi[2] : lo[2]);
    for (int f = 0; f < 6; ++f)
        if (faces >> f & 1) {
            uint32_t c[4];
            for (int k = 0; k < 4; ++k)
                c[k] = base + box_quads[f][k];
            sh_poly(s, 4, c);
        }
}

static shape *sh_box(const char *name, bool solid, double cx, double cy, double cz, double h,
                     unsigned faces)
{
    shape *s = sh_new(name, solid);
    const double lo[3] = {cx - h, cy - h, cz - h}, hi[3] = {cx + h, cy + h, cz + h};
    sh_box_into(s, lo, hi, faces);
    return s;
}

/* The L prism as a solid, with its two boxes as its convex parts. */
static shape *sh_ell(void)
{
    static shape *parts[2];
    shape *s = sh_new("solid L", true);
    /* L (0,0) (2,0) (2,1) (1,1) (1,2) (0,2), z in [-1/2, 1/2]. */
    static const double xy[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
    for (int z = 0; z < 2; ++z)
        for (int i = 0; i < 6; ++i)
            sh_v(s, xy[i][0], xy[i][1], z ? 0.5 : -0.5);
    /* Top: two convex quads; bottom likewise, reversed. */
    sh_poly(s, 4, (const uint32_t[]){6, 7, 8, 9});
    sh_poly(s, 4, (const uint32_t[]){6, 9, 10, 11});
    sh_poly(s, 4, (const uint32_t[]){0, 3, 2, 1});
    sh_poly(s, 4, (const uint32_t[]){0, 5, 4, 3});
    for (uint32_t i = 0; i < 6; ++i) {
        uint32_t j = (i + 1) % 6;
        sh_poly(s, 4, (const uint32_t[]){i, j, j + 6, i + 6});
    }
    if (!parts[0]) {
        parts[0] = sh_new("L part x", true);
        sh_box_into(parts[0], (const double[]){0, 0, -0.5}, (const double[]){2, 1, 0.5}, 63);
        parts[1] = sh_new("L part y", true);
        sh_box_into(parts[1], (const double[]){0, 0, -0.5}, (const double[]){1, 2, 0.5}, 63);
    }
    s->nparts = 2;
    s->part[0] = parts[0];
    s->part[1] = parts[1];
    return s;
}

static shape *sh_tetra(const char *name, bool solid, double x, double y, double z, double h)
{
    shape *s = sh_new(name, solid);
    uint32_t a = sh_v(s, x, y, z), b = sh_v(s, x + h, y, z), c = sh_v(s, x, y + h, z),
             d = sh_v(s, x, y, z + h);
    sh_tri(s, a, c, b);
    sh_tri(s, a, b, d);
    sh_tri(s, a, d, c);
    sh_tri(s, b, c, d);
    return s;
}

/* ---- the oracle: exact predicates in mpq ---------------------------------------- */

/* Points are mpq_ptr p with coordinates p[0], p[1], p[2]. Each predicate
 * has its own scratch, so they nest freely. */
static mpq_t o3s[12];
static mpq_t o2s[4];
static bool scratch_ready;

static void scratch_init(void)
{
    if (scratch_ready)
        return;
    for (int i = 0; i < 12; ++i)
        mpq_init(o3s[i]);
    for (int i = 0; i < 4; ++i)
        mpq_init(o2s[i]);
    scratch_ready = true;
}

/* sign of det[b - a, c - a, d - a] = ((b - a) x (c - a)) . (d - a): positive
 * when d lies on the side the counter-clockwise triangle abc faces. */
static int orient3d(mpq_srcptr a, mpq_srcptr b, mpq_srcptr c, mpq_srcptr d)
{
    mpq_t *s = o3s;
    for (int k = 0; k < 3; ++k) {
        mpq_sub(s[k], &b[k], &a[k]);
        mpq_sub(s[3 + k], &c[k], &a[k]);
        mpq_sub(s[6 + k], &d[k], &a[k]);
    }
    /* n = u x v into s[9..11]. */
    mpq_mul(s[9], s[1], s[5]);
    mpq_mul(s[10], s[2], s[4]);
    mpq_sub(s[9], s[9], s[10]); /* n0 */
    mpq_mul(s[10], s[2], s[3]);
    mpq_mul(s[11], s[0], s[5]);
    mpq_sub(s[10], s[10], s[11]); /* n1 */
    mpq_mul(s[11], s[0], s[4]);
    mpq_mul(s[0], s[1], s[3]);
    mpq_sub(s[11], s[11], s[0]); /* n2 */
    mpq_mul(s[9], s[9], s[6]);
    mpq_mul(s[10], s[10], s[7]);
    mpq_mul(s[11], s[11], s[8]);
    mpq_add(s[9], s[9], s[10]);
    mpq_add(s[9], s[9], s[11]);
    return mpq_sgn(s[9]);
}

/* sign of the 2D orientation of a, b, c on coordinates i and j. */
static int orient2d(mpq_srcptr a, mpq_srcptr b, mpq_srcptr c, int i, int j)
{
    mpq_sub(o2s[0], &b[i], &a[i]);
    mpq_sub(o2s[1], &c[j], &a[j]);
    mpq_mul(o2s[0], o2s[0], o2s[1]);
    mpq_sub(o2s[2], &b[j], &a[j]);
    mpq_sub(o2s[3], &c[i], &a[i]);
    mpq_mul(o2s[2], o2s[2], o2s[3]);
    return mpq_cmp(o2s[0], o2s[2]);
}

/* r, collinear with p and q (2D), lies on the closed segment pq. */
static bool on_segment(mpq_srcptr p, mpq_srcptr q, mpq_srcptr r, int i, int j)
{
    const int ax[2] = {i, j};
    for (int t = 0; t < 2; ++t) {
        int k = ax[t];
        mpq_srcptr lo = mpq_cmp(&p[k], &q[k]) <= 0 ? &p[k] : &q[k];
        mpq_srcptr hi = lo == &p[k] ? &q[k] : &p[k];
        if (mpq_cmp(&r[k], lo) < 0 || mpq_cmp(&r[k], hi) > 0)
            return false;
    }
    return true;
}

/* The closed segments pq and rs meet (2D). */
static bool seg_seg_2d(mpq_srcptr p, mpq_srcptr q, mpq_srcptr r, mpq_srcptr s, int i, int j)
{
    int o1 = orient2d(p, q, r, i, j), o2 = orient2d(p, q, s, i, j);
    int o3 = orient2d(r, s, p, i, j), o4 = orient2d(r, s, q, i, j);
    if (o1 * o2 < 0 && o3 * o4 < 0)
        return true;
    return (o1 == 0 && on_segment(p, q, r, i, j)) || (o2 == 0 && on_segment(p, q, s, i, j)) ||
           (o3 == 0 && on_segment(r, s, p, i, j)) || (o4 == 0 && on_segment(r, s, q, i, j));
}

/* p lies in the closed triangle abc (2D; abc not degenerate in 2D). */
static bool point_in_tri_2d(mpq_srcptr p, mpq_srcptr a, mpq_srcptr b, mpq_srcptr c, int i, int j)
{
    int s1 = orient2d(a, b, p, i, j), s2 = orient2d(b, c, p, i, j), s3 = orient2d(c, a, p, i, j);
    bool neg = s1 < 0 || s2 < 0 || s3 < 0, pos = s1 > 0 || s2 > 0 || s3 > 0;
    return !(neg && pos);
}

/* The two coordinates on which triangle abc's projection is not
 * degenerate: those other than an axis its normal is not orthogonal to. */
static void tri_axes(mpq_srcptr a, mpq_srcptr b, mpq_srcptr c, int *i, int *j)
{
    /* The projection on (i, j) is degenerate iff orient2d is 0. */
    static const int pairs[3][2] = {{0, 1}, {1, 2}, {2, 0}};
    for (int t = 0; t < 3; ++t)
        if (orient2d(a, b, c, pairs[t][0], pairs[t][1]) != 0) {
            *i = pairs[t][0];
            *j = pairs[t][1];
            return;
        }
    ck_abort_msg("oracle: degenerate triangle");
}

/* The closed segment pq meets the closed triangle abc (not degenerate). */
static bool seg_tri(mpq_srcptr p, mpq_srcptr q, mpq_srcptr a, mpq_srcptr b, mpq_srcptr c)
{
    int sp = orient3d(a, b, c, p), sq = orient3d(a, b, c, q);
    if (sp * sq > 0)
        return false;
    if (sp == 0 || sq == 0) {
        int i, j;
        tri_axes(a, b, c, &i, &j);
        if (sp == 0 && sq == 0)
            return point_in_tri_2d(p, a, b, c, i, j) || seg_seg_2d(p, q, a, b, i, j) ||
                   seg_seg_2d(p, q, b, c, i, j) || seg_seg_2d(p, q, c, a, i, j);
        return point_in_tri_2d(sp == 0 ? p : q, a, b, c, i, j);
    }
    int v1 = orient3d(p, q, a, b), v2 = orient3d(p, q, b, c), v3 = orient3d(p, q, c, a);
    bool neg = v1 < 0 || v2 < 0 || v3 < 0, pos = v1 > 0 || v2 > 0 || v3 > 0;
    return !(neg && pos);
}

/* The closed triangles abc and def (neither degenerate) meet. */
static bool tri_tri(mpq_srcptr const A[3], mpq_srcptr const B[3])
{
    int sb[3], sa[3];
    for (int k = 0; k < 3; ++k)
        sb[k] = orient3d(A[0], A[1], A[2], B[k]);
    if ((sb[0] > 0 && sb[1] > 0 && sb[2] > 0) || (sb[0] < 0 && sb[1] < 0 && sb[2] < 0))
        return false;
    if (sb[0] == 0 && sb[1] == 0 && sb[2] == 0) {
        int i, j;
        tri_axes(A[0], A[1], A[2], &i, &j);
        for (int e = 0; e < 3; ++e)
            for (int f = 0; f < 3; ++f)
                if (seg_seg_2d(A[e], A[(e + 1) % 3], B[f], B[(f + 1) % 3], i, j))
                    return true;
        return point_in_tri_2d(A[0], B[0], B[1], B[2], i, j) ||
               point_in_tri_2d(B[0], A[0], A[1], A[2], i, j);
    }
    for (int k = 0; k < 3; ++k)
        sa[k] = orient3d(B[0], B[1], B[2], A[k]);
    if ((sa[0] > 0 && sa[1] > 0 && sa[2] > 0) || (sa[0] < 0 && sa[1] < 0 && sa[2] < 0))
        return false;
    for (int e = 0; e < 3; ++e) {
        if (seg_tri(A[e], A[(e + 1) % 3], B[0], B[1], B[2]))
            return true;
        if (seg_tri(B[e], B[(e + 1) % 3], A[0], A[1], A[2]))
            return true;
    }
    return false;
}

/* ---- placed objects ------------------------------------------------------------- */

/* A shape placed by (R, t) as transform.h documents, its vertices in
 * doubles and in mpq, its fan triangles and their boxes. */
typedef struct oobj {
    const shape *s;
    size_t nv, nt;
    double *p;
    mpq_t *q;
    uint32_t (*t)[3];
    double (*box)[6];
    double lo[3], hi[3];
    int nparts;
    struct oobj *part[2];
    bool general; /* turned by a rotation that is not a quarter turn */
} oobj;

static void place_point(const double R[9], const double t[3], const double v[3], double out[3])
{
    for (int i = 0; i < 3; ++i) {
        double r = R[3 * i] * v[0] + R[3 * i + 1] * v[1];
        r = r + R[3 * i + 2] * v[2];
        out[i] = r + t[i];
    }
}

static void transform_matrix(const noctTransform *x, double R[9])
{
    noctError err;
    ck_assert_msg(noctQuatToMatrix(&x->q, R, &err) == NOCT_OK, "%s", err.message);
}

static oobj *oobj_make(const shape *s, const noctTransform *x)
{
    scratch_init();
    double R[9];
    transform_matrix(x, R);
    oobj *o = calloc(1, sizeof *o);
    ck_assert_ptr_nonnull(o);
    o->s = s;
    o->nv = s->nv;
    o->p = malloc(3 * s->nv * sizeof *o->p);
    o->q = malloc(3 * s->nv * sizeof *o->q);
    size_t nt = s->ni - 2 * s->np;
    o->t = malloc((nt ? nt : 1) * sizeof *o->t);
    o->box = malloc((nt ? nt : 1) * sizeof *o->box);
    ck_assert(o->p && o->q && o->t && o->box);
    for (int k = 0; k < 3; ++k) {
        o->lo[k] = INFINITY;
        o->hi[k] = -INFINITY;
    }
    for (size_t i = 0; i < s->nv; ++i) {
        place_point(R, x->p, &s->v[3 * i], &o->p[3 * i]);
        for (int k = 0; k < 3; ++k) {
            mpq_init(o->q[3 * i + k]);
            mpq_set_d(o->q[3 * i + k], o->p[3 * i + k]);
            o->lo[k] = fmin(o->lo[k], o->p[3 * i + k]);
            o->hi[k] = fmax(o->hi[k], o->p[3 * i + k]);
        }
    }
    size_t c = 0;
    for (size_t f = 0; f < s->np; ++f) {
        for (uint32_t k = 1; k + 1 < s->sz[f]; ++k) {
            uint32_t *tr = o->t[o->nt];
            tr[0] = s->ix[c];
            tr[1] = s->ix[c + k];
            tr[2] = s->ix[c + k + 1];
            for (int a = 0; a < 3; ++a) {
                double lo = INFINITY, hi = -INFINITY;
                for (int v = 0; v < 3; ++v) {
                    lo = fmin(lo, o->p[3 * tr[v] + a]);
                    hi = fmax(hi, o->p[3 * tr[v] + a]);
                }
                o->box[o->nt][a] = lo;
                o->box[o->nt][3 + a] = hi;
            }
            o->nt++;
        }
        c += s->sz[f];
    }
    for (int k = 0; k < 9; ++k)
        o->general = o->general || (R[k] != 0 && R[k] != 1 && R[k] != -1);
    o->nparts = s->nparts;
    for (int k = 0; k < s->nparts; ++k)
        o->part[k] = oobj_make(s->part[k], x);
    return o;
}

static void oobj_free(oobj *o)
{
    if (!o)
        return;
    for (size_t i = 0; i < 3 * o->nv; ++i)
        mpq_clear(o->q[i]);
    for (int k = 0; k < o->nparts; ++k)
        oobj_free(o->part[k]);
    free(o->p);
    free(o->q);
    free(o->t);
    free(o->box);
    free(o);
}

static mpq_srcptr ov(const oobj *o, uint32_t v)
{
    return o->q[3 * v];
}

static bool boxes_meet(const double *a, const double *b)
{
    for (int k = 0; k < 3; ++k)
        if (a[k] > b[3 + k] || b[k] > a[3 + k])
            return false;
    return true;
}

/* The sign of orient3d(a, b, c, d) below, in doubles, when the rounding
 * cannot have changed it, else 0: Shewchuk's first filter, the
 * determinant's error at most (7 + 56 2^-53) 2^-53 of its permanent for
 * products in the normal range; 2^-1060 more covers those below it. */
static int orient3d_sure(const double *a, const double *b, const double *c, const double *d)
{
    double u[3], v[3], w[3];
    for (int k = 0; k < 3; ++k) {
        u[k] = b[k] - a[k];
        v[k] = c[k] - a[k];
        w[k] = d[k] - a[k];
    }
    const double det = w[0] * (u[1] * v[2] - u[2] * v[1]) + w[1] * (u[2] * v[0] - u[0] * v[2]) +
                       w[2] * (u[0] * v[1] - u[1] * v[0]);
    const double perm = fabs(w[0]) * (fabs(u[1] * v[2]) + fabs(u[2] * v[1])) +
                        fabs(w[1]) * (fabs(u[2] * v[0]) + fabs(u[0] * v[2])) +
                        fabs(w[2]) * (fabs(u[0] * v[1]) + fabs(u[1] * v[0]));
    if (!isfinite(perm))
        return 0;
    const double bound = 0x1p-49 * perm + 0x1p-1060;
    return det > bound ? 1 : det < -bound ? -1 : 0;
}

/* Are q's three vertices surely on one side of p's plane (then the
 * triangles do not meet)? */
static bool one_side(const double *const p[3], const double *const q[3])
{
    const int s0 = orient3d_sure(p[0], p[1], p[2], q[0]);
    return s0 != 0 && orient3d_sure(p[0], p[1], p[2], q[1]) == s0 &&
           orient3d_sure(p[0], p[1], p[2], q[2]) == s0;
}

/* o's vertex v in doubles. */
static const double *dv(const oobj *o, uint32_t v)
{
    return &o->p[3 * v];
}

static bool tris_meet(const oobj *a, size_t i, const oobj *b, size_t j)
{
    if (!boxes_meet(a->box[i], b->box[j]))
        return false;
    /* most pairs whose boxes meet: one beside the other's plane, sure in
     * doubles, before the rationals */
    const double *const PA[3] = {dv(a, a->t[i][0]), dv(a, a->t[i][1]), dv(a, a->t[i][2])};
    const double *const PB[3] = {dv(b, b->t[j][0]), dv(b, b->t[j][1]), dv(b, b->t[j][2])};
    if (one_side(PA, PB) || one_side(PB, PA))
        return false;
    mpq_srcptr A[3] = {ov(a, a->t[i][0]), ov(a, a->t[i][1]), ov(a, a->t[i][2])};
    mpq_srcptr B[3] = {ov(b, b->t[j][0]), ov(b, b->t[j][1]), ov(b, b->t[j][2])};
    return tri_tri(A, B);
}

/* p lies in the closed convex solid o (its faces facing outwards). */
static bool in_convex(const oobj *o, mpq_srcptr p)
{
    for (size_t i = 0; i < o->nt; ++i)
        if (orient3d(ov(o, o->t[i][0]), ov(o, o->t[i][1]), ov(o, o->t[i][2]), p) > 0)
            return false;
    return true;
}

/* p lies on a closed triangle of o. */
static bool on_triangles(const oobj *o, mpq_srcptr p)
{
    for (size_t i = 0; i < o->nt; ++i) {
        mpq_srcptr a = ov(o, o->t[i][0]), b = ov(o, o->t[i][1]), c = ov(o, o->t[i][2]);
        if (orient3d(a, b, c, p) != 0)
            continue;
        int x, y;
        tri_axes(a, b, c, &x, &y);
        if (point_in_tri_2d(p, a, b, c, x, y))
            return true;
    }
    return false;
}

/* p lies in the closed solid o, by the parity of the crossings of a
 * segment from p to a far point q: each crossing must be proper (q and p
 * strictly on either side of the triangle's plane and the segment strictly
 * inside the triangle), else another q is tried. Needs no convexity: the
 * oracle for solids placed by general rotations, whose faces rounding
 * has bent. */
static bool in_solid_ray(const oobj *o, mpq_srcptr p, uint64_t seed)
{
    if (on_triangles(o, p))
        return true;
    mpq_t q[3];
    for (int k = 0; k < 3; ++k)
        mpq_init(q[k]);
    uint64_t rng = seed;
    for (int attempt = 0; attempt < 64; ++attempt) {
        for (int k = 0; k < 3; ++k) {
            double span = o->hi[k] - o->lo[k] + 1;
            mpq_set_d(q[k], o->hi[k] + span * (1 + test_uniform(&rng)) *
                                           (test_rand_below(&rng, 2) ? 1 : -1) * 3);
        }
        unsigned crossings = 0;
        bool clean = true;
        for (size_t i = 0; i < o->nt && clean; ++i) {
            mpq_srcptr a = ov(o, o->t[i][0]), b = ov(o, o->t[i][1]), c = ov(o, o->t[i][2]);
            int sp = orient3d(a, b, c, p), sq = orient3d(a, b, c, q[0]);
            if (sp * sq > 0)
                continue;
            if (sq == 0) { /* q in the triangle's plane: try another */
                clean = false;
                break;
            }
            if (sp == 0) /* p in the plane, off the triangle: the segment meets */
                continue; /* the plane at p alone */
            int v1 = orient3d(p, q[0], a, b), v2 = orient3d(p, q[0], b, c),
                v3 = orient3d(p, q[0], c, a);
            if (v1 == 0 || v2 == 0 || v3 == 0) {
                bool neg = v1 < 0 || v2 < 0 || v3 < 0, pos = v1 > 0 || v2 > 0 || v3 > 0;
                if (!(neg && pos)) /* through an edge or a corner: ambiguous */
                    clean = false;
                continue;
            }
            crossings += (v1 > 0) == (v2 > 0) && (v2 > 0) == (v3 > 0);
        }
        if (clean) {
            for (int k = 0; k < 3; ++k)
                mpq_clear(q[k]);
            return crossings % 2 == 1;
        }
    }
    ck_abort_msg("oracle: no clean ray");
    return false;
}

static bool in_solid(const oobj *o, mpq_srcptr p)
{
    if (o->general)
        return in_solid_ray(o, p, 0x7a9);
    if (o->nparts == 0)
        return in_convex(o, p);
    for (int k = 0; k < o->nparts; ++k)
        if (in_convex(o->part[k], p))
            return true;
    return false;
}

static bool any_vertex_in(const oobj *from, const oobj *solid)
{
    for (size_t v = 0; v < from->nv; ++v) {
        const double *p = &from->p[3 * v];
        bool out = false;
        for (int k = 0; k < 3; ++k)
            out = out || p[k] < solid->lo[k] || p[k] > solid->hi[k];
        if (!out && in_solid(solid, ov(from, (uint32_t)v)))
            return true;
    }
    return false;
}

/* The oracle's verdict: do the placed a and b meet? */
static bool oracle_meet(const oobj *a, const oobj *b)
{
    double ba[6] = {a->lo[0], a->lo[1], a->lo[2], a->hi[0], a->hi[1], a->hi[2]};
    double bb[6] = {b->lo[0], b->lo[1], b->lo[2], b->hi[0], b->hi[1], b->hi[2]};
    if (!boxes_meet(ba, bb))
        return false;
    for (size_t i = 0; i < a->nt; ++i)
        if (boxes_meet(a->box[i], bb))
            for (size_t j = 0; j < b->nt; ++j)
                if (tris_meet(a, i, b, j))
                    return true;
    if (b->s->solid && any_vertex_in(a, b))
        return true;
    if (a->s->solid && any_vertex_in(b, a))
        return true;
    return false;
}

/* The point p (mpq) lies on the placed object: on one of its closed
 * triangles, or, for a solid, in it. */
static bool oracle_point(const oobj *o, mpq_srcptr p)
{
    if (o->s->solid)
        return in_solid(o, p);
    for (size_t i = 0; i < o->nt; ++i) {
        mpq_srcptr a = ov(o, o->t[i][0]), b = ov(o, o->t[i][1]), c = ov(o, o->t[i][2]);
        if (orient3d(a, b, c, p) != 0)
            continue;
        int x, y;
        tri_axes(a, b, c, &x, &y);
        if (point_in_tri_2d(p, a, b, c, x, y))
            return true;
    }
    return false;
}

/* ---- exact squared distances ------------------------------------------------------ */

static void q_dot(mpq_t r, mpq_t *u, mpq_t *v, mpq_t tmp)
{
    mpq_mul(r, u[0], v[0]);
    mpq_mul(tmp, u[1], v[1]);
    mpq_add(r, r, tmp);
    mpq_mul(tmp, u[2], v[2]);
    mpq_add(r, r, tmp);
}

static void q_sub3(mpq_t *r, mpq_srcptr a, mpq_srcptr b)
{
    for (int k = 0; k < 3; ++k)
        mpq_sub(r[k], &a[k], &b[k]);
}

/* r = squared distance from p to the closed segment ab. */
static void d2_point_seg(mpq_t r, mpq_srcptr p, mpq_srcptr a, mpq_srcptr b)
{
    mpq_t d[3], w[3], dd, t, tmp;
    for (int k = 0; k < 3; ++k)
        mpq_inits(d[k], w[k], NULL);
    mpq_inits(dd, t, tmp, NULL);
    q_sub3(d, b, a);
    q_sub3(w, p, a);
    q_dot(dd, d, d, tmp);
    q_dot(t, w, d, tmp);
    if (mpq_sgn(t) <= 0 || mpq_sgn(dd) == 0)
        mpq_set_ui(t, 0, 1);
    else if (mpq_cmp(t, dd) >= 0)
        mpq_set_ui(t, 1, 1);
    else
        mpq_div(t, t, dd);
    for (int k = 0; k < 3; ++k) {
        mpq_mul(tmp, t, d[k]);
        mpq_sub(w[k], w[k], tmp);
    }
    q_dot(r, w, w, tmp);
    for (int k = 0; k < 3; ++k)
        mpq_clears(d[k], w[k], NULL);
    mpq_clears(dd, t, tmp, NULL);
}

static void q_min(mpq_t best, bool *have, const mpq_t x)
{
    if (!*have || mpq_cmp(x, best) < 0) {
        mpq_set(best, x);
        *have = true;
    }
}

/* r = squared distance from p to the closed triangle abc. */
static void d2_point_tri(mpq_t r, mpq_srcptr p, mpq_srcptr a, mpq_srcptr b, mpq_srcptr c)
{
    mpq_t u[3], v[3], w[3], n[3], e[3], x, tmp;
    for (int k = 0; k < 3; ++k)
        mpq_inits(u[k], v[k], w[k], n[k], e[k], NULL);
    mpq_inits(x, tmp, NULL);
    q_sub3(u, b, a);
    q_sub3(v, c, a);
    for (int k = 0; k < 3; ++k) { /* n = u x v */
        int i = (k + 1) % 3, j = (k + 2) % 3;
        mpq_mul(n[k], u[i], v[j]);
        mpq_mul(tmp, u[j], v[i]);
        mpq_sub(n[k], n[k], tmp);
    }
    /* Inside iff ((q1 - q0) x (p - q0)) . n >= 0 along the three edges. */
    mpq_srcptr cor[3] = {a, b, c};
    bool inside = true;
    for (int s = 0; s < 3 && inside; ++s) {
        mpq_t ed[3];
        for (int k = 0; k < 3; ++k)
            mpq_init(ed[k]);
        q_sub3(ed, cor[(s + 1) % 3], cor[s]);
        q_sub3(w, p, cor[s]);
        for (int k = 0; k < 3; ++k) {
            int i = (k + 1) % 3, j = (k + 2) % 3;
            mpq_mul(e[k], ed[i], w[j]);
            mpq_mul(tmp, ed[j], w[i]);
            mpq_sub(e[k], e[k], tmp);
        }
        q_dot(x, e, n, tmp);
        inside = mpq_sgn(x) >= 0;
        for (int k = 0; k < 3; ++k)
            mpq_clear(ed[k]);
    }
    if (inside) {
        q_sub3(w, p, a);
        q_dot(x, n, w, tmp);
        mpq_mul(x, x, x);
        q_dot(tmp, n, n, r);
        mpq_div(r, x, tmp);
    } else {
        bool have = false;
        for (int s = 0; s < 3; ++s) {
            d2_point_seg(x, p, cor[s], cor[(s + 1) % 3]);
            q_min(r, &have, x);
        }
    }
    for (int k = 0; k < 3; ++k)
        mpq_clears(u[k], v[k], w[k], n[k], e[k], NULL);
    mpq_clears(x, tmp, NULL);
}

/* r = squared distance between the closed segments pq and rs. */
static void d2_seg_seg(mpq_t out, mpq_srcptr p, mpq_srcptr q, mpq_srcptr r, mpq_srcptr s)
{
    mpq_t u[3], v[3], w[3], a, b, c, d, e, det, sn, tn, tmp, x;
    for (int k = 0; k < 3; ++k)
        mpq_inits(u[k], v[k], w[k], NULL);
    mpq_inits(a, b, c, d, e, det, sn, tn, tmp, x, NULL);
    bool have = false;
    d2_point_seg(x, p, r, s);
    q_min(out, &have, x);
    d2_point_seg(x, q, r, s);
    q_min(out, &have, x);
    d2_point_seg(x, r, p, q);
    q_min(out, &have, x);
    d2_point_seg(x, s, p, q);
    q_min(out, &have, x);
    q_sub3(u, q, p);
    q_sub3(v, s, r);
    q_sub3(w, p, r);
    q_dot(a, u, u, tmp);
    q_dot(b, u, v, tmp);
    q_dot(c, v, v, tmp);
    q_dot(d, u, w, tmp);
    q_dot(e, v, w, tmp);
    mpq_mul(det, a, c);
    mpq_mul(tmp, b, b);
    mpq_sub(det, det, tmp);
    if (mpq_sgn(det) > 0) {
        /* Minimise |w + s u - t v|^2: a s - b t = -d, b s - c t = -e. */
        mpq_mul(sn, b, e);
        mpq_mul(tmp, c, d);
        mpq_sub(sn, sn, tmp);
        mpq_div(sn, sn, det);
        mpq_mul(tn, a, e);
        mpq_mul(tmp, b, d);
        mpq_sub(tn, tn, tmp);
        mpq_div(tn, tn, det);
        if (mpq_sgn(sn) >= 0 && mpq_cmp_ui(sn, 1, 1) <= 0 && mpq_sgn(tn) >= 0 &&
            mpq_cmp_ui(tn, 1, 1) <= 0) {
            for (int k = 0; k < 3; ++k) {
                mpq_mul(tmp, sn, u[k]);
                mpq_add(w[k], w[k], tmp);
                mpq_mul(tmp, tn, v[k]);
                mpq_sub(w[k], w[k], tmp);
            }
            q_dot(x, w, w, tmp);
            q_min(out, &have, x);
        }
    }
    for (int k = 0; k < 3; ++k)
        mpq_clears(u[k], v[k], w[k], NULL);
    mpq_clears(a, b, c, d, e, det, sn, tn, tmp, x, NULL);
}

/* r = squared distance between two closed triangles. */
static void d2_tri_tri(mpq_t r, mpq_srcptr const A[3], mpq_srcptr const B[3])
{
    if (tri_tri(A, B)) {
        mpq_set_ui(r, 0, 1);
        return;
    }
    mpq_t x;
    mpq_init(x);
    bool have = false;
    for (int k = 0; k < 3; ++k) {
        d2_point_tri(x, A[k], B[0], B[1], B[2]);
        q_min(r, &have, x);
        d2_point_tri(x, B[k], A[0], A[1], A[2]);
        q_min(r, &have, x);
        for (int l = 0; l < 3; ++l) {
            d2_seg_seg(x, A[k], A[(k + 1) % 3], B[l], B[(l + 1) % 3]);
            q_min(r, &have, x);
        }
    }
    mpq_clear(x);
}

/* r = the exact squared distance between the placed a and b: 0 if they
 * meet, else the least over their boundary triangles. */
static void oracle_d2(mpq_t r, const oobj *a, const oobj *b)
{
    if (oracle_meet(a, b)) {
        mpq_set_ui(r, 0, 1);
        return;
    }
    mpq_t x;
    mpq_init(x);
    bool have = false;
    for (size_t i = 0; i < a->nt; ++i)
        for (size_t j = 0; j < b->nt; ++j) {
            /* Skip pairs whose boxes are clearly farther apart than the best
             * so far (the gap in doubles, with a wide margin for its
             * rounding: a skipped pair cannot be the nearest). */
            if (have) {
                double g2 = 0;
                for (int k = 0; k < 3; ++k) {
                    double g = fmax(0, fmax(b->box[j][k] - a->box[i][3 + k],
                                            a->box[i][k] - b->box[j][3 + k]));
                    g2 += g * g;
                }
                const double up = nextafter(mpq_get_d(r), INFINITY); /* (get_d truncates) */
                if (g2 * (1 - 1e-9) > up * (1 + 1e-9))
                    continue;
                /* the triangles' own lower bound in doubles (testutil.h) */
                const double *const PA[3] = {dv(a, a->t[i][0]), dv(a, a->t[i][1]),
                                             dv(a, a->t[i][2])};
                const double *const PB[3] = {dv(b, b->t[j][0]), dv(b, b->t[j][1]),
                                             dv(b, b->t[j][2])};
                const double L = test_tri_distance_lower(PA, PB);
                if (L * L * (1 - 0x1p-50) - 0x1p-1060 > up)
                    continue;
            }
            mpq_srcptr A[3] = {ov(a, a->t[i][0]), ov(a, a->t[i][1]), ov(a, a->t[i][2])};
            mpq_srcptr B[3] = {ov(b, b->t[j][0]), ov(b, b->t[j][1]), ov(b, b->t[j][2])};
            d2_tri_tri(x, A, B);
            q_min(r, &have, x);
        }
    mpq_clear(x);
}

/* ---- the library's meshes ------------------------------------------------------- */

static noctMesh *lib_mesh(const shape *s)
{
    noctMesh *m = NULL;
    noctError err = {0};
    noctStatus st = s->solid ? noctMeshCreate(s->v, s->nv, s->sz, s->np, s->ix, &m, &err)
                             : noctMeshCreateSurface(s->v, s->nv, s->sz, s->np, s->ix, &m, &err);
    ck_assert_msg(st == NOCT_OK, "%s: %s", s->name, err.message);
    ck_assert_msg(noctMeshIsSurface(m) == !s->solid, "%s: noctMeshIsSurface() is %d", s->name,
                  (int)noctMeshIsSurface(m));
    ck_assert_uint_eq(noctMeshTriangleCount(m), s->ni - 2 * s->np);
    return m;
}

static bool is_identity(const noctTransform *x)
{
    return x->q.x == 0 && x->q.y == 0 && x->q.z == 0 && x->q.w == 1;
}

static noctTransform at(double x, double y, double z)
{
    noctTransform t = noctIdentityTransform();
    t.p[0] = x;
    t.p[1] = y;
    t.p[2] = z;
    return t;
}

/* A quarter turn: k quarter turns about axis (0, 1 or 2), exact. */
static noctQuat quarter(int axis, int k)
{
    double ax[3] = {0, 0, 0};
    ax[axis] = 1;
    noctQuat q;
    ck_assert_int_eq(noctQuatFromAxisAngle(ax, 90.0 * k, &q), NOCT_OK);
    return q;
}

/* Tallies over a test. */
static struct tally {
    unsigned cases, meet, apart, distances;
} tally;

/* Check one placed pair against the oracle: the exact level (noctCollide()
 * for translations, noctCollideTransformed() always, both orders); the box
 * and convex levels conservative; noctDistance() if distance. Returns the
 * oracle's verdict. */
static bool check_pair(const char *label, const shape *sa, const noctMesh *ma,
                       const noctTransform *xa, const shape *sb, const noctMesh *mb,
                       const noctTransform *xb, bool distance)
{
    oobj *a = oobj_make(sa, xa), *b = oobj_make(sb, xb);
    bool want = oracle_meet(a, b);
    tally.cases++;
    if (want)
        tally.meet++;
    else
        tally.apart++;
    noctError err = {0};
    static const noctAccuracy levels[3] = {NOCT_ACCURACY_EXACT, NOCT_ACCURACY_BOX,
                                           NOCT_ACCURACY_CONVEX};
    for (int l = 0; l < 3; ++l) {
        for (int swap = 0; swap < 2; ++swap) {
            bool got = false;
            noctStatus st = swap ? noctCollideTransformed(mb, xb, ma, xa, levels[l], &got, NULL,
                                                          &err)
                                 : noctCollideTransformed(ma, xa, mb, xb, levels[l], &got, NULL,
                                                          &err);
            if (st != NOCT_OK) {
                disagree("%s (%s vs %s), %s level%s: status %d: %s", label, sa->name, sb->name,
                         noctAccuracyName(levels[l]), swap ? " swapped" : "", (int)st,
                         err.message);
                continue;
            }
            if (levels[l] == NOCT_ACCURACY_EXACT ? got != want : (want && !got))
                disagree("%s (%s at (%a %a %a) q (%g %g %g %g) vs %s at (%a %a %a) q (%g %g %g "
                         "%g)), %s level%s: oracle %s, library %s",
                         label, sa->name, xa->p[0], xa->p[1], xa->p[2], xa->q.x, xa->q.y,
                         xa->q.z, xa->q.w, sb->name, xb->p[0], xb->p[1], xb->p[2], xb->q.x,
                         xb->q.y, xb->q.z, xb->q.w, noctAccuracyName(levels[l]),
                         swap ? " (swapped)" : "", want ? "meet" : "apart",
                         got ? "meet" : "apart");
        }
        if (is_identity(xa) && is_identity(xb)) {
            bool got = false;
            noctStatus st = noctCollide(ma, xa->p, mb, xb->p, levels[l], &got, NULL);
            if (st != NOCT_OK || (levels[l] == NOCT_ACCURACY_EXACT ? got != want : want && !got))
                disagree("%s (%s vs %s), noctCollide %s level: status %d, oracle %s, library %s",
                         label, sa->name, sb->name, noctAccuracyName(levels[l]), (int)st,
                         want ? "meet" : "apart", got ? "meet" : "apart");
        }
    }
    {
        bool got = false;
        noctContact contact;
        noctStatus st = noctCollideContact(ma, xa, mb, xb, &got, &contact, &err);
        if (st != NOCT_OK || got != want || (contact.kind == NOCT_CONTACT_NONE) == want)
            disagree("%s (%s vs %s): noctCollideContact status %d, %s, kind %d; oracle %s",
                     label, sa->name, sb->name, (int)st, got ? "meet" : "apart",
                     (int)contact.kind, want ? "meet" : "apart");
    }
    if (distance) {
        tally.distances++;
        noctDistanceResult r;
        noctStatus st = noctDistance(ma, xa, mb, xb, INFINITY, &r, NULL, &err);
        if (st != NOCT_OK) {
            disagree("%s (%s vs %s): noctDistance status %d: %s", label, sa->name, sb->name,
                     (int)st, err.message);
        } else {
            mpq_t d2, x;
            mpq_inits(d2, x, NULL);
            oracle_d2(d2, a, b);
            if (r.colliding != want)
                disagree("%s (%s vs %s): noctDistance colliding %d, oracle %s", label, sa->name,
                         sb->name, (int)r.colliding, want ? "meet" : "apart");
            mpq_set_d(x, r.lower);
            mpq_mul(x, x, x);
            bool lower_ok = r.lower >= 0 && mpq_cmp(x, d2) <= 0;
            mpq_set_d(x, r.upper);
            mpq_mul(x, x, x);
            bool upper_ok = isfinite(r.upper) && mpq_cmp(d2, x) <= 0;
            if (!lower_ok || !upper_ok || r.distance < r.lower || r.distance > r.upper ||
                (want && (r.distance != 0 || r.upper != 0)))
                disagree("%s (%s vs %s): noctDistance [%a, %a] distance %a, exact %.17g", label,
                         sa->name, sb->name, r.lower, r.upper, r.distance,
                         sqrt(mpq_get_d(d2)));
            mpq_clears(d2, x, NULL);
        }
    }
    oobj_free(a);
    oobj_free(b);
    return want;
}

/* check_pair() for shapes made into meshes here. */
static bool check_shapes(const char *label, const shape *sa, const noctTransform *xa,
                         const shape *sb, const noctTransform *xb, bool distance)
{
    noctMesh *ma = lib_mesh(sa), *mb = lib_mesh(sb);
    bool r = check_pair(label, sa, ma, xa, sb, mb, xb, distance);
    noctMeshDestroy(ma);
    noctMeshDestroy(mb);
    return r;
}

static void report_tally(const char *what)
{
    fprintf(stderr, "check-surfaces: %s: %u pairs (%u meet, %u apart), %u distances\n", what,
            tally.cases, tally.meet, tally.apart, tally.distances);
}

/* ---- the oracle checked on solids ----------------------------------------------- */

/* For closed solids the oracle must be the library's long-tested exact
 * verdict: boxes, tetrahedra and the L at dyadic places, touching often. */
START_TEST(oracle_agrees_on_solids)
{
    uint64_t rng = 0x5eed0001;
    shape *pool[4];
    pool[0] = sh_box("solid box 1/2", true, 0, 0, 0, 0.5, 63);
    pool[1] = sh_box("solid box 1/4", true, 0.25, 0, 0, 0.25, 63);
    pool[2] = sh_tetra("solid tetra", true, 0, 0, 0, 1);
    pool[3] = sh_ell();
    noctMesh *m[4];
    for (int i = 0; i < 4; ++i) {
        noctError err;
        ck_assert_msg(noctMeshCreate(pool[i]->v, pool[i]->nv, pool[i]->sz, pool[i]->np,
                                     pool[i]->ix, &m[i], &err) == NOCT_OK,
                      "%s", err.message);
    }
    unsigned meet = 0, n = 0;
    const int rounds = test_rounds(1500, 30); /* each it % 3 and it % 10 */
    for (int it = 0; it < rounds; ++it) {
        int i = (int)test_rand_below(&rng, 4), j = (int)test_rand_below(&rng, 4);
        noctTransform xa = at(0, 0, 0), xb = at(0, 0, 0);
        for (int k = 0; k < 3; ++k)
            xb.p[k] = ((double)test_rand_below(&rng, 11) - 4) * 0.25;
        if (it % 3 == 0)
            xb.q = quarter((int)test_rand_below(&rng, 3), 1 + (int)test_rand_below(&rng, 3));
        oobj *a = oobj_make(pool[i], &xa), *b = oobj_make(pool[j], &xb);
        bool want = oracle_meet(a, b), got;
        ck_assert_int_eq(noctCollideTransformed(m[i], &xa, m[j], &xb, NOCT_ACCURACY_EXACT, &got,
                                                NULL, NULL),
                         NOCT_OK);
        ck_assert_msg(got == want, "oracle %d, library %d: %s vs %s at %g %g %g", want, got,
                      pool[i]->name, pool[j]->name, xb.p[0], xb.p[1], xb.p[2]);
        meet += want;
        ++n;
        if (it % 10 == 0) { /* the distance oracle against noctDistance() on solids */
            noctDistanceResult r;
            ck_assert_int_eq(noctDistance(m[i], &xa, m[j], &xb, INFINITY, &r, NULL, NULL),
                             NOCT_OK);
            mpq_t d2, x;
            mpq_inits(d2, x, NULL);
            oracle_d2(d2, a, b);
            mpq_set_d(x, r.lower);
            mpq_mul(x, x, x);
            ck_assert(mpq_cmp(x, d2) <= 0);
            mpq_set_d(x, r.upper);
            mpq_mul(x, x, x);
            ck_assert(mpq_cmp(d2, x) <= 0);
            ck_assert(r.upper - r.lower < 1e-9);
            mpq_clears(d2, x, NULL);
        }
        oobj_free(a);
        oobj_free(b);
    }
    ck_assert_uint_gt(meet, n / 5);
    ck_assert_uint_lt(meet, n - n / 5);
    for (int i = 0; i < 4; ++i) {
        noctMeshDestroy(m[i]);
        free(pool[i]);
    }
}
END_TEST

/* The oracle's triangle test on hand-made cases of known answer. */
START_TEST(oracle_known_cases)
{
    scratch_init();
    /* Triangles as 9 doubles; expected verdict. */
    static const struct {
        double a[9], b[9];
        bool meet;
    } cases[] = {
        /* vertex on face */
        {{0, 0, 0, 2, 0, 0, 0, 2, 0}, {0.5, 0.5, 0, 1, 0.5, 1, 0.5, 1, 1}, true},
        /* vertex just above */
        {{0, 0, 0, 2, 0, 0, 0, 2, 0}, {0.5, 0.5, 0x1p-60, 1, 0.5, 1, 0.5, 1, 1}, false},
        /* crossing */
        {{0, 0, 0, 2, 0, 0, 0, 2, 0}, {0.5, 0.5, -1, 1, 0.5, 1, 0.5, 1, 1}, true},
        /* crossing the plane outside the triangle */
        {{0, 0, 0, 2, 0, 0, 0, 2, 0}, {3, 3, -1, 3, 4, 1, 4, 3, 1}, false},
        /* edge on edge (y = 0, z = 0 at x = 1) */
        {{0, 0, 0, 2, 0, 0, 0, 0, 2}, {1, -1, 0, 1, 1, 0, 1, 0, -1}, true},
        {{0, 0, 0, 2, 0, 0, 0, 0, 2}, {1, -1, -0x1p-52, 1, 1, -0x1p-52, 1, 0, -1}, false},
        /* coplanar overlap, coplanar touching at a corner, coplanar apart */
        {{0, 0, 0, 2, 0, 0, 0, 2, 0}, {1, 1, 0, 3, 1, 0, 1, 3, 0}, true},
        {{0, 0, 0, 2, 0, 0, 0, 2, 0}, {2, 0, 0, 3, 0, 0, 3, 1, 0}, true},
        {{0, 0, 0, 2, 0, 0, 0, 2, 0}, {0x1.0000000000001p+1, 0, 0, 3, 0, 0, 3, 1, 0}, false},
        /* coplanar, one inside the other */
        {{0, 0, 0, 4, 0, 0, 0, 4, 0}, {1, 1, 0, 2, 1, 0, 1, 2, 0}, true},
        /* corner on corner, not coplanar */
        {{0, 0, 0, 2, 0, 0, 0, 2, 0}, {2, 0, 0, 3, 0, 1, 3, 1, 1}, true},
        /* an edge in the plane crossing the triangle, the third corner off */
        {{0, 0, 0, 2, 0, 0, 0, 2, 0}, {-1, 0.5, 0, 3, 0.5, 0, 1, 0.5, 1}, true},
        {{0, 0, 0, 2, 0, 0, 0, 2, 0}, {-1, 3, 0, 3, 3, 0, 1, 3, 1}, false},
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; ++c) {
        mpq_t q[18];
        for (int k = 0; k < 9; ++k) {
            mpq_init(q[k]);
            mpq_set_d(q[k], cases[c].a[k]);
            mpq_init(q[9 + k]);
            mpq_set_d(q[9 + k], cases[c].b[k]);
        }
        mpq_srcptr A[3] = {q[0], q[3], q[6]}, B[3] = {q[9], q[12], q[15]};
        ck_assert_msg(tri_tri(A, B) == cases[c].meet, "case %zu", c);
        ck_assert_msg(tri_tri(B, A) == cases[c].meet, "case %zu swapped", c);
        mpq_t d2;
        mpq_init(d2);
        d2_tri_tri(d2, A, B);
        ck_assert_msg((mpq_sgn(d2) == 0) == cases[c].meet, "case %zu distance", c);
        mpq_clear(d2);
        for (int k = 0; k < 18; ++k)
            mpq_clear(q[k]);
    }
    /* A distance of closed form: parallel triangles 3/4 apart, edge to edge
     * at a known gap. */
    mpq_t q[18], d2;
    static const double a[9] = {0, 0, 0, 2, 0, 0, 0, 2, 0};
    static const double b[9] = {0, 0, 0.75, 2, 0, 0.75, 0, 2, 0.75};
    static const double c[9] = {3, 3, 1, 4, 4, 1, 3, 4, 5};
    for (int k = 0; k < 9; ++k) {
        mpq_init(q[k]);
        mpq_set_d(q[k], a[k]);
        mpq_init(q[9 + k]);
        mpq_set_d(q[9 + k], b[k]);
    }
    mpq_init(d2);
    mpq_srcptr A[3] = {q[0], q[3], q[6]}, B[3] = {q[9], q[12], q[15]};
    d2_tri_tri(d2, A, B);
    ck_assert(mpq_cmp_ui(d2, 9, 16) == 0);
    for (int k = 0; k < 9; ++k)
        mpq_set_d(q[9 + k], c[k]);
    d2_tri_tri(d2, A, B); /* nearest: (3,3,1) to the hypotenuse point (1,1,0): 4+4+1 */
    ck_assert(mpq_cmp_ui(d2, 9, 1) == 0);
    mpq_clear(d2);
    for (int k = 0; k < 18; ++k)
        mpq_clear(q[k]);
}
END_TEST

/* The oracle's triangle test against a separating-axis test in doubles
 * (two triangles are apart iff one of the 11 axes, their normals and the
 * cross products of their edges, separates them), on random triangles,
 * wherever the floating-point margin is clear of rounding. */
static double sat_gap(const double *A, const double *B)
{
    double ax[11][3];
    int n = 0;
    const double *T[2] = {A, B};
    for (int t = 0; t < 2; ++t) {
        double u[3], v[3];
        for (int k = 0; k < 3; ++k) {
            u[k] = T[t][3 + k] - T[t][k];
            v[k] = T[t][6 + k] - T[t][k];
        }
        ax[n][0] = u[1] * v[2] - u[2] * v[1];
        ax[n][1] = u[2] * v[0] - u[0] * v[2];
        ax[n][2] = u[0] * v[1] - u[1] * v[0];
        ++n;
    }
    for (int e = 0; e < 3; ++e)
        for (int f = 0; f < 3; ++f) {
            double u[3], v[3];
            for (int k = 0; k < 3; ++k) {
                u[k] = A[3 * ((e + 1) % 3) + k] - A[3 * e + k];
                v[k] = B[3 * ((f + 1) % 3) + k] - B[3 * f + k];
            }
            ax[n][0] = u[1] * v[2] - u[2] * v[1];
            ax[n][1] = u[2] * v[0] - u[0] * v[2];
            ax[n][2] = u[0] * v[1] - u[1] * v[0];
            ++n;
        }
    double best = -INFINITY;
    for (int a = 0; a < n; ++a) {
        double len = sqrt(ax[a][0] * ax[a][0] + ax[a][1] * ax[a][1] + ax[a][2] * ax[a][2]);
        if (len < 1e-3)
            continue;
        double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
        for (int t = 0; t < 2; ++t)
            for (int v = 0; v < 3; ++v) {
                double d = (ax[a][0] * T[t][3 * v] + ax[a][1] * T[t][3 * v + 1] +
                            ax[a][2] * T[t][3 * v + 2]) / len;
                lo[t] = fmin(lo[t], d);
                hi[t] = fmax(hi[t], d);
            }
        best = fmax(best, fmax(lo[1] - hi[0], lo[0] - hi[1]));
    }
    return best; /* > 0: apart by that much; < 0: overlapping on every axis */
}

START_TEST(oracle_against_sat)
{
    scratch_init();
    uint64_t rng = 0x5a7;
    unsigned meet = 0, apart = 0;
    const int rounds = test_rounds(20000, 50); /* each it % 50 */
    for (int it = 0; it < rounds; ++it) {
        double A[9], B[9];
        for (int k = 0; k < 9; ++k) {
            A[k] = test_uniform(&rng);
            B[k] = test_uniform(&rng) + 0.25;
        }
        double gap = sat_gap(A, B);
        if (fabs(gap) < 1e-6)
            continue;
        mpq_t q[18];
        for (int k = 0; k < 9; ++k) {
            mpq_init(q[k]);
            mpq_set_d(q[k], A[k]);
            mpq_init(q[9 + k]);
            mpq_set_d(q[9 + k], B[k]);
        }
        mpq_srcptr a[3] = {q[0], q[3], q[6]}, b[3] = {q[9], q[12], q[15]};
        bool m = tri_tri(a, b);
        /* With the degenerate axes skipped, a negative gap can still hide a
         * separation along a skipped axis only for near-parallel edges:
         * such cases are rare and left out by the length test. */
        ck_assert_msg(m == (gap < 0), "iteration %d: oracle %d, gap %g", it, m, gap);
        meet += m;
        apart += !m;
        if (it % 50 == 0) {
            mpq_t d2;
            mpq_init(d2);
            d2_tri_tri(d2, a, b);
            double d = sqrt(mpq_get_d(d2));
            ck_assert(m ? d == 0 : d >= gap * (1 - 1e-12));
            mpq_clear(d2);
        }
        for (int k = 0; k < 18; ++k)
            mpq_clear(q[k]);
    }
    ck_assert_uint_gt(meet, 500u * (unsigned)rounds / 20000);
    ck_assert_uint_gt(apart, 500u * (unsigned)rounds / 20000);
}
END_TEST

/* The two point-in-solid oracles agree where both apply (quarter turns):
 * the convex parts and the ray parity, at grid points in and around the
 * L, a box and a tetrahedron, boundaries included. */
START_TEST(oracle_ray_parity)
{
    scratch_init();
    shape *sh[3] = {sh_ell(), sh_box("box", true, 0.5, 0.5, 0, 0.75, 63),
                    sh_tetra("tetra", true, 0, 0, -0.5, 2)};
    uint64_t rng = 0x9a7;
    unsigned in = 0, out = 0;
    mpq_t p[3];
    for (int k = 0; k < 3; ++k)
        mpq_init(p[k]);
    for (int it = 0; it < 600; ++it) {
        noctTransform x = at(0, 0, 0);
        x.q = quarter((int)test_rand_below(&rng, 3), (int)test_rand_below(&rng, 4));
        oobj *o = oobj_make(sh[it % 3], &x);
        for (int k = 0; k < 3; ++k)
            mpq_set_d(p[k], ((double)test_rand_below(&rng, 19) - 9) * 0.25);
        bool a = in_solid(o, p[0]), b = in_solid_ray(o, p[0], (uint64_t)it);
        ck_assert_msg(a == b, "iteration %d: parts %d, ray %d", it, a, b);
        in += a;
        out += !a;
        oobj_free(o);
    }
    ck_assert_uint_gt(in, 20);
    ck_assert_uint_gt(out, 100);
    for (int k = 0; k < 3; ++k)
        mpq_clear(p[k]);
    for (int i = 0; i < 3; ++i)
        free(sh[i]);
}
END_TEST

static shape *random_soup(uint64_t *rng, int n, double g, const char *name);

/* Soups against solids (the L, a box, a tetrahedron), both turned by
 * general rotations: the oracle's containment by ray parity on the placed
 * (rounded) solid. */
START_TEST(soups_against_turned_solids)
{
    memset(&tally, 0, sizeof tally);
    nfail = 0;
    uint64_t rng = 0x7e5 + (uint64_t)_i;
    shape *sh[3] = {sh_ell(), sh_box("solid box", true, 0.5, 0.5, 0, 0.75, 63),
                    sh_tetra("solid tetra", true, 0, 0, -0.5, 2)};
    noctMesh *m[3];
    for (int i = 0; i < 3; ++i)
        m[i] = lib_mesh(sh[i]);
    for (int it = 0; it < 60; ++it) {
        shape *a = random_soup(&rng, 1 + (int)test_rand_below(&rng, 4), 0, "small soup");
        for (size_t v = 0; v < 3 * a->nv; ++v)
            a->v[v] *= 0.5; /* small: often wholly inside */
        noctMesh *ma = lib_mesh(a);
        for (int p = 0; p < 3; ++p) {
            int j = (int)test_rand_below(&rng, 3);
            noctTransform xa = at(0, 0, 0), xb = at(0, 0, 0);
            test_random_quat(&rng, &xa.q);
            test_random_quat(&rng, &xb.q);
            for (int k = 0; k < 3; ++k)
                xa.p[k] = test_uniform(&rng) * 2 - 0.5;
            check_pair("soup vs turned solid", a, ma, &xa, sh[j], m[j], &xb, p == 0);
        }
        noctMeshDestroy(ma);
        free(a);
    }
    for (int i = 0; i < 3; ++i) {
        noctMeshDestroy(m[i]);
        free(sh[i]);
    }
    report_tally("soups against turned solids");
    ck_assert_uint_gt(tally.meet, 20);
    ck_assert_uint_gt(tally.apart, 20);
    EXPECT_NO_DISAGREEMENT();
}
END_TEST

/* ---- random soups ----------------------------------------------------------------- */

/* A soup of n triangles with coordinates on the grid of step g in [0, 2]
 * (dyadic: touching is frequent) or uniform doubles in [0, 1] (g 0). Some
 * triangles share corners with the previous one. */
static shape *random_soup(uint64_t *rng, int n, double g, const char *name)
{
    shape *s = sh_new(name, false);
    for (int t = 0; t < n; ++t) {
        double p[3][3];
        for (;;) {
            for (int v = 0; v < 3; ++v)
                for (int k = 0; k < 3; ++k)
                    p[v][k] = g > 0 ? (double)test_rand_below(rng, (size_t)(2 / g) + 1) * g
                                    : test_uniform(rng);
            if (t > 0 && test_rand_below(rng, 3) == 0) /* share an edge or a corner */
                memcpy(p[0], &s->v[3 * (s->nv - 1)], sizeof p[0]);
            double u[3], w[3], c[3];
            for (int k = 0; k < 3; ++k) {
                u[k] = p[1][k] - p[0][k];
                w[k] = p[2][k] - p[0][k];
            }
            c[0] = u[1] * w[2] - u[2] * w[1];
            c[1] = u[2] * w[0] - u[0] * w[2];
            c[2] = u[0] * w[1] - u[1] * w[0];
            double area2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
            double d2 = 0;
            for (int a = 0; a < 3; ++a)
                for (int b = 0; b < 3; ++b) {
                    double e = 0;
                    for (int k = 0; k < 3; ++k)
                        e += (p[a][k] - p[b][k]) * (p[a][k] - p[b][k]);
                    d2 = fmax(d2, e);
                }
            if (area2 > 1e-6 * d2 * d2) /* far from the library's 1e-9 */
                break;
        }
        sh_soup_tri(s, p[0], p[1], p[2]);
    }
    return s;
}

START_TEST(random_dyadic_soups)
{
    uint64_t rng = 0xd1ad1c00 + (uint64_t)_i;
    memset(&tally, 0, sizeof tally);
    nfail = 0;
    for (int it = 0; it < 120; ++it) {
        shape *a = random_soup(&rng, 1 + (int)test_rand_below(&rng, 6), 0.25, "dyadic soup A");
        shape *b = random_soup(&rng, 1 + (int)test_rand_below(&rng, 6), 0.25, "dyadic soup B");
        noctMesh *ma = lib_mesh(a), *mb = lib_mesh(b);
        for (int p = 0; p < 6; ++p) {
            noctTransform xa = at(0, 0, 0), xb = at(0, 0, 0);
            for (int k = 0; k < 3; ++k)
                xb.p[k] = ((double)test_rand_below(&rng, 9) - 4) * 0.25;
            if (p >= 3) { /* quarter turns, exact */
                xa.q = quarter((int)test_rand_below(&rng, 3), (int)test_rand_below(&rng, 4));
                xb.q = quarter((int)test_rand_below(&rng, 3), 1 + (int)test_rand_below(&rng, 3));
            }
            if (p == 5) { /* far from the origin: 2^30, still exact */
                for (int k = 0; k < 3; ++k) {
                    xa.p[k] += 0x1p30;
                    xb.p[k] += 0x1p30;
                }
            }
            check_pair("dyadic soups", a, ma, &xa, b, mb, &xb, p == 0 && it % 2 == 0);
        }
        noctMeshDestroy(ma);
        noctMeshDestroy(mb);
        free(a);
        free(b);
    }
    report_tally("random dyadic soups");
    ck_assert_uint_gt(tally.meet, tally.cases / 10);
    ck_assert_uint_gt(tally.apart, tally.cases / 10);
    EXPECT_NO_DISAGREEMENT();
}
END_TEST

START_TEST(random_double_soups)
{
    uint64_t rng = 0xd0b1e000 + (uint64_t)_i;
    memset(&tally, 0, sizeof tally);
    nfail = 0;
    for (int it = 0; it < 100; ++it) {
        shape *a = random_soup(&rng, 1 + (int)test_rand_below(&rng, 8), 0, "double soup A");
        shape *b = random_soup(&rng, 1 + (int)test_rand_below(&rng, 8), 0, "double soup B");
        noctMesh *ma = lib_mesh(a), *mb = lib_mesh(b);
        for (int p = 0; p < 4; ++p) {
            noctTransform xa = at(0, 0, 0), xb = at(0, 0, 0);
            for (int k = 0; k < 3; ++k)
                xb.p[k] = test_uniform(&rng) - 0.5;
            if (p >= 2) { /* general rotations: the oracle places as documented */
                test_random_quat(&rng, &xa.q);
                test_random_quat(&rng, &xb.q);
            }
            check_pair("double soups", a, ma, &xa, b, mb, &xb, p % 2 == 0);
        }
        noctMeshDestroy(ma);
        noctMeshDestroy(mb);
        free(a);
        free(b);
    }
    report_tally("random double soups");
    ck_assert_uint_gt(tally.meet, tally.cases / 10);
    ck_assert_uint_gt(tally.apart, tally.cases / 10);
    EXPECT_NO_DISAGREEMENT();
}
END_TEST

/* ---- open boxes, shells, containment ---------------------------------------------- */

/* The box [-1, 1]^3 without its top (+z) face, a surface, against small
 * boxes (solid and as closed shells made surfaces) on a dyadic grid:
 * inside without contact, on the walls, through the walls, through the
 * opening, outside. */
START_TEST(open_box_against_small_boxes)
{
    memset(&tally, 0, sizeof tally);
    nfail = 0;
    shape *open = sh_box("open box", false, 0, 0, 0, 1, 63 & ~32u);
    shape *small_solid = sh_box("small solid box", true, 0, 0, 0, 0.25, 63);
    shape *small_shell = sh_box("small shell", false, 0, 0, 0, 0.25, 63);
    noctMesh *mo = lib_mesh(open), *ms = lib_mesh(small_solid), *mh = lib_mesh(small_shell);
    static const double xs[] = {0, 0.5, 0.75, 0.875, 1, 1.25, 1.5};
    unsigned inside_apart = 0, opening_apart = 0;
    for (size_t i = 0; i < sizeof xs / sizeof xs[0]; ++i)
        for (int zi = -9; zi <= 9; ++zi) {
            double z = zi * 0.25;
            noctTransform xo = at(0, 0, 0), xs_ = at(xs[i], xs[i] == 0.5 ? 0.25 : 0, z);
            bool m1 = check_pair("open box", open, mo, &xo, small_solid, ms, &xs_, zi % 3 == 0);
            bool m2 = check_pair("open box", open, mo, &xo, small_shell, mh, &xs_, zi % 3 == 0);
            if (m1 != m2)
                disagree("oracle: solid and shell differ against the open box");
            if (xs[i] <= 0.5 && zi > -3 && zi < 3)
                inside_apart += !m1;
            if (xs[i] == 0 && zi >= 3 && zi <= 6)
                opening_apart += !m1;
            /* Quarter turns of the open box turn the opening aside. */
            noctTransform xr = at(0, 0, 0);
            xr.q = quarter(0, 1 + (int)(i % 3));
            check_pair("turned open box", open, mo, &xr, small_solid, ms, &xs_, false);
        }
    ck_assert_uint_eq(inside_apart, 2 * 5);  /* wholly inside: no contact */
    ck_assert_uint_eq(opening_apart, 4);     /* out through the opening */
    /* Concrete expectations, independent of the oracle. */
    bool got;
    noctTransform x0 = at(0, 0, 0), xin = at(0, 0, 0), xfloor = at(0, 0, -0.75),
                  xwall = at(0.875, 0, 0), xtop = at(0, 0, 1.25);
    ck_assert_int_eq(noctCollideTransformed(mo, &x0, ms, &xin, NOCT_ACCURACY_EXACT, &got, NULL,
                                            NULL), NOCT_OK);
    ck_assert(!got);
    ck_assert_int_eq(noctCollideTransformed(mo, &x0, ms, &xfloor, NOCT_ACCURACY_EXACT, &got,
                                            NULL, NULL), NOCT_OK);
    ck_assert(got); /* resting on the floor */
    ck_assert_int_eq(noctCollideTransformed(mo, &x0, ms, &xwall, NOCT_ACCURACY_EXACT, &got,
                                            NULL, NULL), NOCT_OK);
    ck_assert(got); /* through the wall */
    ck_assert_int_eq(noctCollideTransformed(mo, &x0, ms, &xtop, NOCT_ACCURACY_EXACT, &got, NULL,
                                            NULL), NOCT_OK);
    ck_assert(!got); /* above the opening */
    noctMeshDestroy(mo);
    noctMeshDestroy(ms);
    noctMeshDestroy(mh);
    free(open);
    free(small_solid);
    free(small_shell);
    report_tally("open box");
    EXPECT_NO_DISAGREEMENT();
}
END_TEST

/* A surface around a solid does not touch it; a surface inside a solid
 * does; a closed shell made a surface is hollow. */
START_TEST(containment)
{
    memset(&tally, 0, sizeof tally);
    nfail = 0;
    shape *open = sh_box("open box 1", false, 0, 0, 0, 1, 63 & ~32u);
    shape *shell = sh_box("closed shell 1", false, 0, 0, 0, 1, 63);
    shape *cube = sh_box("solid cube 1/2", true, 0, 0, 0, 0.5, 63);
    shape *big = sh_box("solid cube 2", true, 0, 0, 0, 2, 63);
    shape *tet = sh_tetra("surface tetra", false, -0.25, -0.25, -0.25, 0.5);
    shape *ell = sh_ell();
    noctTransform x0 = at(0, 0, 0);
    ck_assert(!check_shapes("open box around a cube", open, &x0, cube, &x0, true));
    ck_assert(!check_shapes("shell around a cube", shell, &x0, cube, &x0, true));
    ck_assert(check_shapes("open box inside a solid", open, &x0, big, &x0, true));
    ck_assert(check_shapes("shell inside a solid", shell, &x0, big, &x0, true));
    ck_assert(check_shapes("tetra surface inside a solid", tet, &x0, cube, &x0, true));
    ck_assert(!check_shapes("tetra surface inside a shell", tet, &x0, shell, &x0, true));
    ck_assert(!check_shapes("shell inside a shell", shell, &x0, tet, &x0, true));
    /* The L's notch: a surface tetra in the notch is apart, in an arm inside. */
    noctTransform notch = at(1.5, 1.5, 0), arm = at(1.5, 0.5, 0), arm2 = at(0.5, 1.5, 0);
    ck_assert(!check_shapes("tetra in the L's notch", tet, &notch, ell, &x0, true));
    ck_assert(check_shapes("tetra in the L's arm", tet, &arm, ell, &x0, true));
    ck_assert(check_shapes("tetra in the L's other arm", tet, &arm2, ell, &x0, true));
    for (int zi = -12; zi <= 12; ++zi) {
        noctTransform xz = at(0, 0, zi * 0.125);
        check_shapes("cube through the open box", cube, &xz, open, &x0, false);
        check_shapes("cube through the shell", cube, &xz, shell, &x0, false);
        check_shapes("open box through the solid", open, &xz, big, &x0, false);
        check_shapes("tetra along the L", tet, &(noctTransform){{1.5, zi * 0.25, 0},
                                                               {0, 0, 0, 1}},
                     ell, &x0, false);
    }
    free(open);
    free(shell);
    free(cube);
    free(big);
    free(tet);
    free(ell);
    report_tally("containment");
    EXPECT_NO_DISAGREEMENT();
}
END_TEST

/* ---- Moebius strips, non-manifold fans, several pieces ---------------------------- */

/* A Moebius strip of n segments about the unit circle, half width w, its
 * coordinates rounded to multiples of 2^-10 (exactly dyadic). */
static shape *mobius(int n, double w)
{
    shape *s = sh_new("Moebius strip", false);
    const double pi = 3.14159265358979323846;
    for (int i = 0; i < n; ++i) {
        double u = 2 * pi * i / n;
        double d[3] = {cos(u / 2) * cos(u), cos(u / 2) * sin(u), sin(u / 2)};
        for (int side = 0; side < 2; ++side) {
            double v = side ? w : -w;
            sh_v(s, round((cos(u) + v * d[0]) * 1024) / 1024,
                 round((sin(u) + v * d[1]) * 1024) / 1024, round(v * d[2] * 1024) / 1024);
        }
    }
    for (int i = 0; i < n; ++i) {
        uint32_t a0 = (uint32_t)(2 * i), a1 = a0 + 1, b0, b1;
        if (i + 1 < n) {
            b0 = a0 + 2;
            b1 = a0 + 3;
        } else { /* the half twist: the sides swap */
            b0 = 1;
            b1 = 0;
        }
        sh_tri(s, a0, b0, b1);
        sh_tri(s, a0, b1, a1);
    }
    return s;
}

/* k triangles around the edge (0,0,-1)-(0,0,1) (a book's pages): the edge
 * is used k times. */
static shape *fan(int k)
{
    shape *s = sh_new("non-manifold fan", false);
    uint32_t lo = sh_v(s, 0, 0, -1), hi = sh_v(s, 0, 0, 1);
    static const double dir[6][2] = {{1, 0}, {0, 1}, {-1, 0.5}, {-0.5, -1}, {0.75, -0.75},
                                     {-1, -0.25}};
    for (int i = 0; i < k; ++i)
        sh_tri(s, lo, hi, sh_v(s, dir[i][0], dir[i][1], 0));
    /* And a bow tie: two triangles sharing a corner only. */
    uint32_t c = sh_v(s, 0, 0, 2);
    sh_tri(s, c, sh_v(s, 1, 0, 3), sh_v(s, 1, 1, 3));
    sh_tri(s, c, sh_v(s, -1, 0, 1.5), sh_v(s, -1, -1, 1.5));
    return s;
}

/* Several pieces: an open box, a lone triangle and a shell, apart. */
static shape *pieces(void)
{
    shape *s = sh_new("several pieces", false);
    sh_box_into(s, (const double[]){0, 0, 0}, (const double[]){1, 1, 1}, 63 & ~2u);
    sh_box_into(s, (const double[]){2, 0, 0}, (const double[]){2.5, 0.5, 0.5}, 63);
    uint32_t a = sh_v(s, 0, 2, 0), b = sh_v(s, 1, 2, 0), c = sh_v(s, 0, 3, 1);
    sh_tri(s, a, b, c);
    /* inconsistently oriented neighbours: the same edge run the same way */
    uint32_t d = sh_v(s, 1, 3, 1);
    sh_tri(s, b, c, d);
    return s;
}

START_TEST(odd_surfaces)
{
    memset(&tally, 0, sizeof tally);
    nfail = 0;
    uint64_t rng = 0x0dd5 + (uint64_t)_i;
    shape *shapes[5] = {mobius(16, 0.25), fan(3), fan(5), pieces(),
                        sh_box("small solid box", true, 0, 0, 0, 0.25, 63)};
    shape *probe_solid = sh_box("probe solid 1/8", true, 0, 0, 0, 0.125, 63);
    shape *probe_tri = random_soup(&rng, 2, 0.25, "probe soup");
    noctMesh *m[5];
    for (int i = 0; i < 5; ++i)
        m[i] = lib_mesh(shapes[i]);
    noctMesh *mps = lib_mesh(probe_solid), *mpt = lib_mesh(probe_tri);
    for (int it = 0; it < 300; ++it) {
        int i = (int)test_rand_below(&rng, 4);
        noctTransform xa = at(0, 0, 0), xb = at(0, 0, 0);
        for (int k = 0; k < 3; ++k)
            xb.p[k] = ((double)test_rand_below(&rng, 25) - 8) * 0.125;
        if (it % 4 == 1)
            xb.q = quarter((int)test_rand_below(&rng, 3), 1 + (int)test_rand_below(&rng, 3));
        if (it % 4 == 3)
            test_random_quat(&rng, &xa.q);
        bool dist = it % 5 == 0;
        switch (it % 3) {
        case 0:
            check_pair("odd vs solid probe", shapes[i], m[i], &xa, probe_solid, mps, &xb, dist);
            break;
        case 1:
            check_pair("odd vs soup probe", shapes[i], m[i], &xa, probe_tri, mpt, &xb, dist);
            break;
        default: {
            int j = (int)test_rand_below(&rng, 5);
            check_pair("odd vs odd", shapes[i], m[i], &xa, shapes[j], m[j], &xb, dist);
        }
        }
    }
    /* Known answers: the strip's own triangles meet a copy of itself; the
     * fan's shared edge meets a box around its middle. */
    noctTransform x0 = at(0, 0, 0), xe = at(0, 0, 0.5);
    ck_assert(check_pair("strip on itself", shapes[0], m[0], &x0, shapes[0], m[0], &x0, true));
    ck_assert(check_pair("fan edge", shapes[1], m[1], &x0, probe_solid, mps, &xe, true));
    for (int i = 0; i < 5; ++i) {
        noctMeshDestroy(m[i]);
        free(shapes[i]);
    }
    noctMeshDestroy(mps);
    noctMeshDestroy(mpt);
    free(probe_solid);
    free(probe_tri);
    report_tally("Moebius, fans, pieces");
    ck_assert_uint_gt(tally.meet, 20);
    ck_assert_uint_gt(tally.apart, 20);
    EXPECT_NO_DISAGREEMENT();
}
END_TEST

/* ---- touching at dyadic coordinates and one ulp apart ---------------------------- */

static shape *one_tri(const char *name, const double p[9])
{
    shape *s = sh_new(name, false);
    sh_soup_tri(s, p, p + 3, p + 6);
    return s;
}

/* Triangle pairs that touch exactly (a corner on a face, on an edge, on a
 * corner; an edge on an edge; coplanar edges and corners), then moved one
 * ulp apart and one ulp into each other, at offsets 0, 1, 2^20 and 2^30
 * (the offsets are exact for the coordinates). */
START_TEST(touching_and_one_ulp)
{
    memset(&tally, 0, sizeof tally);
    nfail = 0;
    static const struct {
        const char *name;
        double a[9], b[9];
        int axis; /* the axis along which b moves apart, and its sign */
        double sign;
    } cases[] = {
        {"corner on face", {0, 0, 0, 2, 0, 0, 0, 2, 0}, {0.5, 0.5, 0, 1, 0.5, 1, 0.5, 1, 1}, 2, 1},
        {"corner on edge", {0, 0, 0, 2, 0, 0, 0, 2, 0}, {1, 0, 0, 1, -1, 1, 2, -1, 1}, 2, 1},
        {"corner on corner", {0, 0, 0, 2, 0, 0, 0, 2, 0}, {2, 0, 0, 3, 0, 1, 3, 1, 1}, 2, 1},
        {"edge on edge", {0, 0, 0, 2, 0, 0, 0, 0, 2}, {1, -1, 0, 1, 1, 0, 1, 0, -1}, 2, -1},
        {"coplanar edges", {0, 0, 0, 2, 0, 0, 0, 2, 0}, {2, 0, 0, 0, 2, 0, 2, 2, 0}, 0, 1},
        {"coplanar corner", {0, 0, 0, 2, 0, 0, 0, 2, 0}, {2, 0, 0, 3, 0, 0, 3, 1, 0}, 0, 1},
        {"edge along face", {0, 0, 0, 2, 0, 0, 0, 2, 0}, {0.25, 0.25, 0, 1, 0.25, 0, 0.5, 0.5,
                                                           1}, 2, 1},
        {"crossing edges in a plane", {0, 0, 0, 2, 0, 0, 0, 2, 0}, {1, -1, 0, 1, 3, 0, 3, 1, 1},
         2, 1},
    };
    static const double offsets[] = {0, 1, 0x1p20, 0x1p30};
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; ++c)
        for (size_t o = 0; o < sizeof offsets / sizeof offsets[0]; ++o)
            for (int mv = -1; mv <= 1; ++mv) {
                double b[9];
                memcpy(b, cases[c].b, sizeof b);
                double off = offsets[o];
                /* Move b by one ulp of its coordinates at the offset: the
                 * whole triangle, along the axis, each corner by the ulp
                 * at its place (so the shift is exact in doubles). */
                shape *sa = one_tri("A", cases[c].a), *sb;
                double ulp = off == 0 ? 0x1p-50 : nextafter(off + 4, INFINITY) - (off + 4);
                for (int v = 0; v < 3; ++v)
                    b[3 * v + cases[c].axis] += mv * cases[c].sign * ulp;
                sb = one_tri("B", b);
                noctTransform xa = at(off, off, off), xb = at(off, off, off);
                char label[80];
                snprintf(label, sizeof label, "%s, offset %g, moved %+d ulp", cases[c].name, off,
                         mv);
                bool want = check_shapes(label, sa, &xa, sb, &xb, off <= 1);
                if (mv == 0)
                    ck_assert_msg(want, "oracle: %s should touch", label);
                if (mv == 1 && off == 0)
                    ck_assert_msg(!want, "oracle: %s should be apart", label);
                /* The same turned a quarter about each axis: still exact. */
                for (int axis = 0; axis < 3; ++axis) {
                    noctTransform ra = xa, rb = xb;
                    ra.q = rb.q = quarter(axis, 1 + (int)(c % 3));
                    bool w2 = check_shapes(label, sa, &ra, sb, &rb, false);
                    if (off == 0)
                        ck_assert_msg(w2 == want, "oracle: %s changed when turned", label);
                }
                free(sa);
                free(sb);
            }
    /* A corner one ulp above a face at offset 1: placed by translation of
     * the corner itself (the triangle at z = 1, the corner at 1 + 2^-52). */
    double a[9] = {0, 0, 1, 2, 0, 1, 0, 2, 1};
    double b[9] = {0.5, 0.5, 0x1.0000000000001p0, 1, 0.5, 2, 0.5, 1, 2};
    shape *sa = one_tri("A at z 1", a), *sb = one_tri("B one ulp above", b);
    noctTransform x0 = at(0, 0, 0);
    ck_assert(!check_shapes("corner one ulp above a face", sa, &x0, sb, &x0, true));
    b[2] = 1;
    free(sb);
    sb = one_tri("B on the face", b);
    ck_assert(check_shapes("corner on a face", sa, &x0, sb, &x0, true));
    free(sa);
    free(sb);
    report_tally("touching and one ulp");
    EXPECT_NO_DISAGREEMENT();
}
END_TEST

/* General rotations with exact touching: A, a dyadic soup, turned by a
 * random rotation and placed; B a triangle with a corner at a placed
 * corner of A (or one ulp off it), and either a second corner at the
 * placed other end of A's edge or its other corners away from A. Whether they touch
 * depends on the last bit of A's placement: the library must place A by
 * the documented rule. */
START_TEST(touching_after_rotation)
{
    memset(&tally, 0, sizeof tally);
    nfail = 0;
    uint64_t rng = 0x70770 + (uint64_t)_i;
    for (int it = 0; it < 60; ++it) {
        shape *a = random_soup(&rng, 3, 0.25, "turned soup");
        noctMesh *ma = lib_mesh(a);
        noctTransform xa = at(0, 0, 0);
        test_random_quat(&rng, &xa.q);
        for (int k = 0; k < 3; ++k)
            xa.p[k] = test_uniform(&rng) * 4 - 2;
        oobj *oa = oobj_make(a, &xa);
        for (int j = 0; j < 6; ++j) {
            const uint32_t *t = oa->t[test_rand_below(&rng, oa->nt)];
            double c[3], ctr[3] = {0, 0, 0};
            for (size_t v = 0; v < oa->nv; ++v)
                for (int k = 0; k < 3; ++k)
                    ctr[k] += oa->p[3 * v + k] / (double)oa->nv;
            for (int k = 0; k < 3; ++k)
                c[k] = oa->p[3 * t[0] + k];
            if (j >= 4) /* one ulp off, along a random axis */
                c[j % 3] = nextafter(c[j % 3], j == 4 ? INFINITY : -INFINITY);
            /* The other corners: away from the centre, spread sideways. */
            double d[3], q1[3], q2[3];
            for (int k = 0; k < 3; ++k)
                d[k] = c[k] - ctr[k];
            double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) + 1e-3;
            for (int k = 0; k < 3; ++k) {
                /* j 0 and 2: B's second corner is A's placed second corner,
                 * so B runs along A's edge, exactly */
                q1[k] = j % 2 || j >= 4 ? c[k] + 2 * d[k] / len + (k == 0 ? 0.5 : 0)
                                        : oa->p[3 * t[1] + k];
                q2[k] = c[k] + 2 * d[k] / len + (k == 1 ? 0.5 : 0);
            }
            shape *b = sh_new("triangle at a placed corner or edge", false);
            sh_soup_tri(b, c, q1, q2);
            noctMesh *mb = lib_mesh(b);
            noctTransform x0 = at(0, 0, 0);
            bool want = check_pair("touching after a rotation", a, ma, &xa, b, mb, &x0, j < 2);
            if (j < 4)
                ck_assert_msg(want, "oracle: a placed corner or edge point must touch");
            noctMeshDestroy(mb);
            free(b);
        }
        oobj_free(oa);
        noctMeshDestroy(ma);
        free(a);
    }
    report_tally("touching after rotation");
    EXPECT_NO_DISAGREEMENT();
}
END_TEST

/* Flat soups: every triangle in the plane z = 0 (or x = y), so that nearly
 * every pair is coplanar: overlapping, touching at edges and corners, or
 * apart; and the same scaled by 2^-300 and 2^290 (exactly). */
START_TEST(flat_and_scaled_soups)
{
    memset(&tally, 0, sizeof tally);
    nfail = 0;
    uint64_t rng = 0xf1a7 + (uint64_t)_i;
    static const double scales[3] = {1, 0x1p-300, 0x1p290};
    for (int it = 0; it < 90; ++it) {
        shape *sh[2];
        double scale = scales[it % 3];
        for (int i = 0; i < 2; ++i) {
            sh[i] = random_soup(&rng, 1 + (int)test_rand_below(&rng, 4), 0.25, "flat soup");
            for (size_t v = 0; v < sh[i]->nv; ++v) {
                double *p = &sh[i]->v[3 * v];
                if (it % 2)
                    p[2] = 0;
                else
                    p[1] = p[0];
                for (int k = 0; k < 3; ++k)
                    p[k] *= scale;
            }
            /* Drop triangles the flattening made degenerate (exactly). */
            shape *t = sh_new(it % 2 ? "flat soup z" : "flat soup x=y", false);
            for (size_t f = 0; f < sh[i]->np; ++f) {
                const double *p0 = &sh[i]->v[3 * sh[i]->ix[3 * f]];
                const double *p1 = &sh[i]->v[3 * sh[i]->ix[3 * f + 1]];
                const double *p2 = &sh[i]->v[3 * sh[i]->ix[3 * f + 2]];
                double u[3], w[3];
                for (int k = 0; k < 3; ++k) {
                    u[k] = (p1[k] - p0[k]) / scale;
                    w[k] = (p2[k] - p0[k]) / scale;
                }
                double cz = u[0] * w[1] - u[1] * w[0], cx = u[1] * w[2] - u[2] * w[1],
                       cy = u[2] * w[0] - u[0] * w[2];
                double area2 = cx * cx + cy * cy + cz * cz, d2 = 0;
                for (int k = 0; k < 3; ++k)
                    d2 = fmax(d2, fmax(u[k] * u[k], w[k] * w[k]));
                if (area2 > 1e-4 * d2 * d2)
                    sh_soup_tri(t, p0, p1, p2);
            }
            free(sh[i]);
            sh[i] = t;
        }
        if (sh[0]->np == 0 || sh[1]->np == 0) {
            free(sh[0]);
            free(sh[1]);
            continue;
        }
        noctMesh *m0 = lib_mesh(sh[0]), *m1 = lib_mesh(sh[1]);
        for (int p = 0; p < 4; ++p) {
            noctTransform x0 = at(0, 0, 0), x1 = at(0, 0, 0);
            /* slide within the plane: along x (and y for z = 0, z for x = y) */
            x1.p[0] = ((double)test_rand_below(&rng, 9) - 4) * 0.25 * scale;
            if (it % 2)
                x1.p[1] = ((double)test_rand_below(&rng, 9) - 4) * 0.25 * scale;
            else
                x1.p[1] = x1.p[0];
            if (p == 3)
                x0.q = x1.q = quarter((int)test_rand_below(&rng, 3), 1);
            check_pair("flat soups", sh[0], m0, &x0, sh[1], m1, &x1, p == 0 && scale == 1);
        }
        noctMeshDestroy(m0);
        noctMeshDestroy(m1);
        free(sh[0]);
        free(sh[1]);
    }
    report_tally("flat and scaled soups");
    ck_assert_uint_gt(tally.meet, tally.cases / 5);
    ck_assert_uint_gt(tally.apart, tally.cases / 10);
    EXPECT_NO_DISAGREEMENT();
}
END_TEST

/* A big soup (a few thousand small triangles on a dyadic grid, many
 * touching each other) against small probes: the library's hierarchy
 * walk, against the oracle's exhaustive one. */
START_TEST(big_soup)
{
    memset(&tally, 0, sizeof tally);
    nfail = 0;
    uint64_t rng = 0xb16 + (uint64_t)_i;
    shape *big = sh_new("big soup", false);
    for (int t = 0; t < 2000 && big->nv + 3 <= SH_MAXV; ++t) {
        double p[3][3], o[3];
        for (int k = 0; k < 3; ++k)
            o[k] = (double)test_rand_below(&rng, 32) * 0.125;
        for (;;) {
            for (int v = 0; v < 3; ++v)
                for (int k = 0; k < 3; ++k)
                    p[v][k] = o[k] + (double)test_rand_below(&rng, 5) * 0.0625;
            double u[3], w[3];
            for (int k = 0; k < 3; ++k) {
                u[k] = p[1][k] - p[0][k];
                w[k] = p[2][k] - p[0][k];
            }
            if (u[1] * w[2] != u[2] * w[1] || u[2] * w[0] != u[0] * w[2] ||
                u[0] * w[1] != u[1] * w[0])
                break;
        }
        sh_soup_tri(big, p[0], p[1], p[2]);
    }
    shape *probe = sh_box("probe", true, 0, 0, 0, 0.0625, 63);
    shape *shell = sh_box("probe shell", false, 0, 0, 0, 0.0625, 63);
    shape *tri = random_soup(&rng, 2, 0.0625, "probe soup");
    noctMesh *mb = lib_mesh(big), *mp = lib_mesh(probe), *ms = lib_mesh(shell),
             *mt = lib_mesh(tri);
    for (int it = 0; it < 150; ++it) {
        noctTransform x0 = at(0, 0, 0), xp = at(0, 0, 0);
        for (int k = 0; k < 3; ++k)
            xp.p[k] = (double)test_rand_below(&rng, 72) * 0.0625 - 0.25;
        if (it % 2)
            xp.q = quarter((int)test_rand_below(&rng, 3), 1 + (int)test_rand_below(&rng, 3));
        switch (it % 3) {
        case 0:
            check_pair("big soup", big, mb, &x0, probe, mp, &xp, it % 10 == 0);
            break;
        case 1:
            check_pair("big soup", big, mb, &x0, shell, ms, &xp, it % 10 == 1);
            break;
        default:
            check_pair("big soup", big, mb, &x0, tri, mt, &xp, it % 10 == 2);
        }
    }
    noctMeshDestroy(mb);
    noctMeshDestroy(mp);
    noctMeshDestroy(ms);
    noctMeshDestroy(mt);
    free(big);
    free(probe);
    free(shell);
    free(tri);
    report_tally("big soup");
    ck_assert_uint_gt(tally.meet, 20);
    ck_assert_uint_gt(tally.apart, 20);
    EXPECT_NO_DISAGREEMENT();
}
END_TEST

/* Slivers: triangles whose third corner lies 2^-k off the line of the
 * other two (k up to 24, well above the library's 1e-9 of the size), met
 * by other slivers and small triangles exactly on them, or one ulp off. */
START_TEST(slivers)
{
    memset(&tally, 0, sizeof tally);
    nfail = 0;
    uint64_t rng = 0x5117e5 + (uint64_t)_i;
    for (int it = 0; it < 80; ++it) {
        int k = 8 + (int)test_rand_below(&rng, 17);
        double h = ldexp(1, -k);
        double a0[3] = {0, 0, 0}, a1[3] = {2, 0, 0}, a2[3] = {1, h, 0};
        shape *a = sh_new("sliver", false);
        sh_soup_tri(a, a0, a1, a2);
        /* B: a sliver crossing A's plane along x = c, or standing on it. */
        double c = (double)(1 + test_rand_below(&rng, 7)) * 0.25;
        double z = it % 3 == 0 ? 0 : it % 3 == 1 ? ldexp(1, -60) : -ldexp(1, -60);
        double y = (double)test_rand_below(&rng, 5) * h / 4;
        double b0[3] = {c, y, z}, b1[3] = {c, y + h, 1}, b2[3] = {c + h, y, 1};
        shape *b = sh_new("sliver on it", false);
        sh_soup_tri(b, b0, b1, b2);
        noctTransform x0 = at(0, 0, 0);
        check_shapes("slivers", a, &x0, b, &x0, it % 4 == 0);
        noctTransform xr = x0;
        xr.q = quarter((int)(it % 3), 1);
        check_shapes("slivers turned", a, &xr, b, &xr, false);
        free(a);
        free(b);
    }
    report_tally("slivers");
    ck_assert_uint_gt(tally.meet, 20);
    ck_assert_uint_gt(tally.apart, 20);
    EXPECT_NO_DISAGREEMENT();
}
END_TEST

/* Continuous detection of translating surfaces, where the oracle can say:
 * without motion it is the exact verdict; with motion it must say
 * colliding whenever the oracle finds them meeting at one of the times
 * k/16 (at which, for dyadic motions, the placement is exact), and must
 * say apart when the swept bounding boxes are apart. */
START_TEST(swept_surfaces)
{
    memset(&tally, 0, sizeof tally);
    nfail = 0;
    uint64_t rng = 0x5e97 + (uint64_t)_i;
    unsigned hits = 0;
    for (int it = 0; it < 60; ++it) {
        shape *a = random_soup(&rng, 1 + (int)test_rand_below(&rng, 4), 0.25, "swept soup A");
        shape *b = it % 2 ? random_soup(&rng, 1 + (int)test_rand_below(&rng, 4), 0.25,
                                        "swept soup B")
                          : sh_box("swept solid box", true, 0, 0, 0, 0.25, 63);
        noctMesh *ma = lib_mesh(a), *mb = lib_mesh(b);
        double ta[3] = {0, 0, 0}, tb0[3], tb1[3];
        for (int k = 0; k < 3; ++k) {
            tb0[k] = ((double)test_rand_below(&rng, 9) - 4) * 0.5;
            tb1[k] = ((double)test_rand_below(&rng, 9) - 4) * 0.5;
        }
        bool got;
        noctSweepHit hit;
        /* no motion */
        noctTransform xa = at(0, 0, 0), xb0 = at(tb0[0], tb0[1], tb0[2]);
        bool want = check_pair("swept, no motion", a, ma, &xa, b, mb, &xb0, false);
        ck_assert_int_eq(noctCollideSwept(ma, ta, ta, mb, tb0, tb0, &got, &hit, NULL), NOCT_OK);
        if (got != want)
            disagree("swept without motion: oracle %d, library %d", want, got);
        /* motion */
        ck_assert_int_eq(noctCollideSwept(ma, ta, ta, mb, tb0, tb1, &got, &hit, NULL), NOCT_OK);
        bool sampled = false;
        for (int t = 0; t <= 16 && !sampled; ++t) {
            noctTransform xt = at(0, 0, 0);
            for (int k = 0; k < 3; ++k)
                xt.p[k] = tb0[k] + (tb1[k] - tb0[k]) * t / 16; /* exact: multiples of 2^-5 */
            oobj *oa = oobj_make(a, &xa), *ob = oobj_make(b, &xt);
            sampled = oracle_meet(oa, ob);
            oobj_free(oa);
            oobj_free(ob);
        }
        if (sampled && !got)
            disagree("swept %s vs %s from (%g %g %g) to (%g %g %g): they meet on the way, "
                     "library apart", a->name, b->name, tb0[0], tb0[1], tb0[2], tb1[0], tb1[1],
                     tb1[2]);
        hits += sampled;
        /* The transformed sweep (the world's continuous level's, conservative
         * when turning): turning a quarter on the way, B must be found
         * wherever the oracle finds it at the ends. */
        {
            noctTransform xb1 = at(tb1[0], tb1[1], tb1[2]);
            xb1.q = quarter(2, 1);
            bool gt = false;
            noctError err;
            noctStatus st = noctCollideSweptTransformed(ma, &xa, &xa, mb, &xb0, &xb1, &gt, &hit,
                                                        NULL, &err);
            oobj *oa = oobj_make(a, &xa), *ob = oobj_make(b, &xb1);
            bool at_end = oracle_meet(oa, ob);
            oobj_free(oa);
            oobj_free(ob);
            if (st != NOCT_OK || ((want || at_end) && !gt))
                disagree("turning sweep %s vs %s: status %d, library %d; oracle at the start "
                         "%d, at the end %d",
                         a->name, b->name, (int)st, gt, want, at_end);
        }
        bool boxes_apart = false;
        {
            double alo[3], ahi[3], blo[3], bhi[3];
            noctMeshBounds(ma, alo, ahi);
            noctMeshBounds(mb, blo, bhi);
            for (int k = 0; k < 3; ++k)
                boxes_apart = boxes_apart || blo[k] + fmin(tb0[k], tb1[k]) > ahi[k] ||
                              bhi[k] + fmax(tb0[k], tb1[k]) < alo[k];
        }
        if (boxes_apart && got)
            disagree("swept: boxes apart, library colliding");
        noctMeshDestroy(ma);
        noctMeshDestroy(mb);
        free(a);
        free(b);
    }
    ck_assert_uint_gt(hits, 5);
    EXPECT_NO_DISAGREEMENT();
}
END_TEST

/* ---- the world ---------------------------------------------------------------------- */

static int object_of(const noctObjectId *ids, int n, noctObjectId id)
{
    for (int k = 0; k < n; ++k)
        if (ids[k].index == id.index && ids[k].generation == id.generation)
            return k;
    ck_abort_msg("unknown object reported");
    return -1;
}

/* Compare a query's objects with the oracle's list (want[k] for object k). */
static void compare_found(const char *what, int step, const noctObjectBuffer *buf,
                          const noctObjectId *ids, const bool *want, int n)
{
    bool *got = calloc((size_t)n, sizeof *got);
    ck_assert(buf->count <= buf->capacity);
    for (size_t k = 0; k < buf->count; ++k)
        got[object_of(ids, n, buf->ids[k])] = true;
    for (int k = 0; k < n; ++k)
        if (got[k] != want[k])
            disagree("world step %d, %s: object #%d reported %d, oracle %d", step, what, k,
                     (int)got[k], (int)want[k]);
    free(got);
}

/* The world's queries against the oracle: a shape query with each shape
 * (surfaces and solids) at a dyadic place and quarter turn; box queries;
 * point queries at the objects' vertices, their edges' midpoints
 * (exact: on the surface) and grid points. */
static void world_queries(noctWorld *w, const noctObjectId *ids, oobj *const *o, int n,
                          shape *const *shapes, noctMesh *const *m, int nshape, uint64_t *rng,
                          int step)
{
    noctObjectId found[64];
    noctObjectBuffer buf = {found, 64, 0};
    bool want[64];
    ck_assert(n <= 64);
    noctQueryFilter all = noctDefaultQueryFilter();
    for (int q = 0; q < nshape; ++q) {
        noctTransform x = at(0, 0, 0);
        for (int k = 0; k < 3; ++k)
            x.p[k] = (double)test_rand_below(rng, 17) * 0.25;
        x.q = quarter((int)test_rand_below(rng, 3), (int)test_rand_below(rng, 4));
        oobj *qo = oobj_make(shapes[q], &x);
        for (int k = 0; k < n; ++k)
            want[k] = oracle_meet(qo, o[k]);
        buf.count = 0;
        noctError err;
        ck_assert_msg(noctWorldQueryShape(w, m[q], NULL, &x, all, noctCollectObjects, &buf,
                                          &err) == NOCT_OK,
                      "%s", err.message);
        char what[80];
        snprintf(what, sizeof what, "shape query %s", shapes[q]->name);
        compare_found(what, step, &buf, ids, want, n);
        oobj_free(qo);
    }
    for (int q = 0; q < 4; ++q) {
        double lo[3], hi[3];
        for (int k = 0; k < 3; ++k) {
            lo[k] = (double)test_rand_below(rng, 16) * 0.25;
            hi[k] = lo[k] + (double)(1 + test_rand_below(rng, 4)) * 0.125;
        }
        shape *bs = sh_new("query box", true);
        sh_box_into(bs, lo, hi, 63);
        noctTransform x0 = at(0, 0, 0);
        oobj *bo = oobj_make(bs, &x0);
        for (int k = 0; k < n; ++k)
            want[k] = oracle_meet(bo, o[k]);
        buf.count = 0;
        ck_assert_int_eq(noctWorldQueryBox(w, lo, hi, all, noctCollectObjects, &buf, NULL),
                         NOCT_OK);
        compare_found("box query", step, &buf, ids, want, n);
        oobj_free(bo);
        free(bs);
    }
    mpq_t pq[3];
    for (int k = 0; k < 3; ++k)
        mpq_init(pq[k]);
    for (int q = 0; q < 24; ++q) {
        double p[3];
        const oobj *src = o[test_rand_below(rng, (size_t)n)];
        uint32_t tri = (uint32_t)test_rand_below(rng, src->nt);
        const uint32_t *t = src->t[tri];
        int kind = q % 3;
        for (int k = 0; k < 3; ++k) {
            if (kind == 0)
                p[k] = src->p[3 * t[0] + k];
            else if (kind == 1)
                p[k] = (src->p[3 * t[0] + k] + src->p[3 * t[1] + k]) / 2; /* exact here */
            else
                p[k] = (double)test_rand_below(rng, 33) * 0.125;
            mpq_set_d(pq[k], p[k]);
        }
        for (int k = 0; k < n; ++k)
            want[k] = oracle_point(o[k], pq[0]);
        buf.count = 0;
        ck_assert_int_eq(noctWorldQueryPoint(w, p, all, noctCollectObjects, &buf, NULL),
                         NOCT_OK);
        char what[80];
        snprintf(what, sizeof what, "point query (%g %g %g)", p[0], p[1], p[2]);
        compare_found(what, step, &buf, ids, want, n);
    }
    for (int k = 0; k < 3; ++k)
        mpq_clear(pq[k]);
}

/* A world of surfaces and solids, at dyadic places and quarter turns:
 * after each step its colliding pairs are the oracle's, over all pairs;
 * the began and ended lists are the differences from the step before. */
START_TEST(world_against_brute_force)
{
    nfail = 0;
    uint64_t rng = 0x3011d + (uint64_t)_i;
    enum { NSHAPE = 9, NOBJ = 36, NSTEP = 6 };
    shape *shapes[NSHAPE] = {
        sh_box("open box", false, 0, 0, 0, 0.5, 63 & ~32u),
        sh_box("shell", false, 0, 0, 0, 0.25, 63),
        mobius(12, 0.125),
        fan(4),
        random_soup(&rng, 6, 0.25, "world soup"),
        sh_box("solid box", true, 0, 0, 0, 0.25, 63),
        sh_tetra("solid tetra", true, 0, 0, 0, 0.5),
        sh_ell(),
        sh_box("box primitive", true, 0, 0, 0, 0.375, 63),
    };
    noctMesh *m[NSHAPE];
    for (int i = 0; i < NSHAPE; ++i)
        m[i] = lib_mesh(shapes[i]);
    noctWorldDef def = noctDefaultWorldDef();
    def.effects = NOCT_EFFECT_EVENTS; /* no motion: the test places them */
    noctWorld *w;
    noctError err;
    ck_assert_msg(noctWorldCreate(&def, &w, &err) == NOCT_OK, "%s", err.message);
    noctObjectId ids[NOBJ];
    int kind[NOBJ];
    noctTransform x[NOBJ];
    for (int i = 0; i < NOBJ; ++i) {
        kind[i] = (int)test_rand_below(&rng, NSHAPE);
        x[i] = at(0, 0, 0);
        for (int k = 0; k < 3; ++k)
            x[i].p[k] = (double)test_rand_below(&rng, 17) * 0.25;
        if (i % 2)
            x[i].q = quarter((int)test_rand_below(&rng, 3), (int)test_rand_below(&rng, 4));
        noctObjectDef od = noctDefaultObjectDef();
        od.mesh = m[kind[i]];
        if (kind[i] == NSHAPE - 1) { /* a box primitive: the mesh of its corners */
            od.mesh = NULL;
            od.half_extents[0] = od.half_extents[1] = od.half_extents[2] = 0.375;
        }
        od.transform = x[i];
        ck_assert_msg(noctWorldCreateObject(w, &od, &ids[i], &err) == NOCT_OK, "%s",
                      err.message);
    }
    bool *prev = calloc(NOBJ * NOBJ, sizeof *prev), *cur = calloc(NOBJ * NOBJ, sizeof *cur);
    ck_assert(prev && cur);
    unsigned total = 0;
    for (int s = 0; s < NSTEP; ++s) {
        if (s > 0)
            for (int i = 0; i < NOBJ; i += 3) { /* move a third */
                for (int k = 0; k < 3; ++k)
                    x[i].p[k] = (double)test_rand_below(&rng, 17) * 0.25;
                x[i].q = quarter((int)test_rand_below(&rng, 3), (int)test_rand_below(&rng, 4));
                ck_assert_int_eq(noctWorldSetTransform(w, ids[i], &x[i], NULL), NOCT_OK);
            }
        ck_assert_msg(noctWorldStep(w, &err) == NOCT_OK, "%s", err.message);
        oobj *o[NOBJ];
        for (int i = 0; i < NOBJ; ++i)
            o[i] = oobj_make(shapes[kind[i]], &x[i]);
        size_t want = 0;
        for (int i = 0; i < NOBJ; ++i)
            for (int j = i + 1; j < NOBJ; ++j) {
                cur[i * NOBJ + j] = oracle_meet(o[i], o[j]);
                want += cur[i * NOBJ + j];
            }
        total += (unsigned)want;
        /* The objects' indices: ids[i].index; map back. */
        const noctPair *got;
        size_t ngot = noctWorldColliding(w, &got);
        bool *seen = calloc(NOBJ * NOBJ, sizeof *seen);
        for (size_t p = 0; p < ngot; ++p) {
            int i = -1, j = -1;
            for (int k = 0; k < NOBJ; ++k) {
                if (ids[k].index == got[p].a.index)
                    i = k;
                if (ids[k].index == got[p].b.index)
                    j = k;
            }
            ck_assert(i >= 0 && j >= 0);
            int lo = i < j ? i : j, hi = i < j ? j : i;
            seen[lo * NOBJ + hi] = true;
            if (!cur[lo * NOBJ + hi])
                disagree("world step %d: %s (#%d) and %s (#%d) colliding, oracle apart", s,
                         shapes[kind[lo]]->name, lo, shapes[kind[hi]]->name, hi);
        }
        for (int i = 0; i < NOBJ; ++i)
            for (int j = i + 1; j < NOBJ; ++j)
                if (cur[i * NOBJ + j] && !seen[i * NOBJ + j])
                    disagree("world step %d: %s (#%d) at (%g %g %g) and %s (#%d) at (%g %g %g) "
                             "not colliding, oracle meet",
                             s, shapes[kind[i]]->name, i, x[i].p[0], x[i].p[1], x[i].p[2],
                             shapes[kind[j]]->name, j, x[j].p[0], x[j].p[1], x[j].p[2]);
        if (ngot != want)
            disagree("world step %d: %zu colliding pairs, oracle %zu", s, ngot, want);
        /* Events: began = now and not before; ended = before and not now. */
        const noctPair *ev;
        size_t nb = noctWorldBegan(w, &ev), ne;
        size_t wb = 0, we = 0;
        for (int i = 0; i < NOBJ * NOBJ; ++i) {
            wb += cur[i] && !prev[i];
            we += prev[i] && !cur[i];
        }
        ne = noctWorldEnded(w, &ev);
        if (nb != wb || ne != we)
            disagree("world step %d: %zu began, %zu ended; oracle %zu, %zu", s, nb, ne, wb, we);
        free(seen);
        memcpy(prev, cur, NOBJ * NOBJ * sizeof *cur);
        world_queries(w, ids, o, NOBJ, shapes, m, NSHAPE, &rng, s);
        for (int i = 0; i < NOBJ; ++i)
            oobj_free(o[i]);
    }
    fprintf(stderr, "check-surfaces: world: %d objects, %d steps, %u colliding pairs\n", NOBJ,
            NSTEP, total);
    ck_assert_uint_gt(total, 10);
    free(prev);
    free(cur);
    noctWorldDestroy(w);
    for (int i = 0; i < NSHAPE; ++i) {
        noctMeshDestroy(m[i]);
        free(shapes[i]);
    }
    EXPECT_NO_DISAGREEMENT();
}
END_TEST

/* ---- reading soups -------------------------------------------------------------- */

static char tmpdir[64];

static const char *tmp_path(const char *name)
{
    static char path[4][160];
    static int turn;
    if (tmpdir[0] == '\0') {
        strcpy(tmpdir, "/tmp/check-surfaces-XXXXXX");
        ck_assert_ptr_nonnull(mkdtemp(tmpdir));
    }
    char *p = path[turn++ % 4];
    snprintf(p, sizeof path[0], "%s/%s", tmpdir, name);
    return p;
}

/* The soup's fan triangles, each with its own corners. */
static void write_stl_binary(const shape *s, const char *path)
{
    FILE *f = fopen(path, "wb");
    ck_assert_ptr_nonnull(f);
    char header[80] = "solid written by check-surfaces (a binary file all the same)";
    fwrite(header, 1, 80, f);
    uint32_t n = (uint32_t)(s->ni - 2 * s->np);
    unsigned char b[4];
    for (int k = 0; k < 4; ++k)
        b[k] = (unsigned char)(n >> (8 * k));
    fwrite(b, 1, 4, f);
    size_t c = 0;
    for (size_t p = 0; p < s->np; ++p) {
        for (uint32_t k = 1; k + 1 < s->sz[p]; ++k) {
            float rec[12] = {0};
            const uint32_t v[3] = {s->ix[c], s->ix[c + k], s->ix[c + k + 1]};
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) {
                    rec[3 + 3 * i + j] = (float)s->v[3 * v[i] + j];
                    ck_assert((double)rec[3 + 3 * i + j] == s->v[3 * v[i] + j]);
                }
            for (int i = 0; i < 12; ++i) {
                uint32_t u;
                memcpy(&u, &rec[i], 4);
                for (int k2 = 0; k2 < 4; ++k2)
                    b[k2] = (unsigned char)(u >> (8 * k2));
                fwrite(b, 1, 4, f);
            }
            fwrite("\0\0", 1, 2, f);
        }
        c += s->sz[p];
    }
    ck_assert_int_eq(fclose(f), 0);
}

static void write_stl_ascii(const shape *s, const char *path)
{
    FILE *f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    fprintf(f, "solid soup\n");
    size_t c = 0;
    for (size_t p = 0; p < s->np; ++p) {
        for (uint32_t k = 1; k + 1 < s->sz[p]; ++k) {
            const uint32_t v[3] = {s->ix[c], s->ix[c + k], s->ix[c + k + 1]};
            fprintf(f, "  facet normal 0 0 0\n    outer loop\n");
            for (int i = 0; i < 3; ++i)
                fprintf(f, "      vertex %.17g %.17g %.17g\n", s->v[3 * v[i]],
                        s->v[3 * v[i] + 1], s->v[3 * v[i] + 2]);
            fprintf(f, "    endloop\n  endfacet\n");
        }
        c += s->sz[p];
    }
    fprintf(f, "endsolid soup\n");
    ck_assert_int_eq(fclose(f), 0);
}

static void write_obj(const shape *s, const char *path)
{
    FILE *f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    fprintf(f, "# written by check-surfaces\no soup\n");
    for (size_t i = 0; i < s->nv; ++i)
        fprintf(f, "v %.17g %.17g %.17g\n", s->v[3 * i], s->v[3 * i + 1], s->v[3 * i + 2]);
    fprintf(f, "vn 0 0 1\ng pieces\ns off\n");
    size_t c = 0;
    for (size_t p = 0; p < s->np; ++p) {
        fputc('f', f);
        for (uint32_t k = 0; k < s->sz[p]; ++k)
            fprintf(f, " %u//1", s->ix[c + k] + 1);
        fputc('\n', f);
        c += s->sz[p];
    }
    ck_assert_int_eq(fclose(f), 0);
}

/* The message names an edge: "edge" and then two vertex numbers a-b. */
static bool names_edge(const char *msg)
{
    const char *e = strstr(msg, "edge");
    if (!e)
        return false;
    for (const char *c = e; *c; ++c) {
        unsigned x, y;
        int n = 0;
        if (c[0] >= '0' && c[0] <= '9' && (c == msg || c[-1] < '0' || c[-1] > '9') &&
            sscanf(c, "%u-%u%n", &x, &y, &n) == 2 && n > 0)
            return true;
    }
    return false;
}

/* A non-manifold fan written as STL: refused as a solid, naming an edge;
 * read as a surface, it collides as the fan. */
START_TEST(read_nonmanifold_stl)
{
    nfail = 0;
    memset(&tally, 0, sizeof tally);
    shape *f = fan(4);
    noctMesh *orig = lib_mesh(f);
    const char *path = tmp_path("fan.stl");
    write_stl_ascii(f, path);
    noctMesh *m = NULL;
    noctError err = {0};
    noctStatus st = noctMeshRead(path, &m, &err);
    ck_assert_msg(st == NOCT_ERR_OPEN || st == NOCT_ERR_ORIENTATION, "status %d", (int)st);
    ck_assert_msg(names_edge(err.message), "%s", err.message);
    ck_assert_msg(strstr(err.message, "fan.stl") != NULL, "%s", err.message);
    ck_assert_msg(noctMeshReadSurface(path, &m, &err) == NOCT_OK, "%s", err.message);
    ck_assert(noctMeshIsSurface(m));
    ck_assert(!noctMeshIsConvex(m));
    shape *probe = sh_box("probe", true, 0, 0, 0, 0.125, 63);
    noctMesh *mp = lib_mesh(probe);
    for (int zi = -10; zi <= 10; ++zi)
        for (int xi = -6; xi <= 6; xi += 3) {
            noctTransform x0 = at(0, 0, 0), xp = at(xi * 0.125, 0.125, zi * 0.125);
            bool want = check_pair("fan.stl", f, m, &x0, probe, mp, &xp, false);
            bool a;
            ck_assert_int_eq(noctCollideTransformed(orig, &x0, mp, &xp, NOCT_ACCURACY_EXACT, &a,
                                                    NULL, NULL), NOCT_OK);
            if (a != want)
                disagree("fan from arrays: %d, oracle %d", a, want);
        }
    remove(path);
    rmdir(tmpdir);
    tmpdir[0] = '\0';
    noctMeshDestroy(m);
    noctMeshDestroy(orig);
    noctMeshDestroy(mp);
    free(f);
    free(probe);
    report_tally("non-manifold STL");
    ck_assert_uint_gt(tally.meet, 5);
    EXPECT_NO_DISAGREEMENT();
}
END_TEST

/* A soup written as binary STL, ASCII STL and OBJ reads back as a surface
 * that collides as the original does, against probes on a dyadic grid. */
START_TEST(read_soups)
{
    nfail = 0;
    memset(&tally, 0, sizeof tally);
    uint64_t rng = 0x57105 + (uint64_t)_i;
    shape *soup = random_soup(&rng, 12, 0.25, "read soup");
    /* and an open box and a fan in the same file: several pieces */
    sh_box_into(soup, (const double[]){3, 0, 0}, (const double[]){4, 1, 1}, 63 & ~32u);
    shape *probe = sh_box("probe", true, 0, 0, 0, 0.125, 63);
    shape *ptri = random_soup(&rng, 2, 0.25, "probe soup");
    noctMesh *orig = lib_mesh(soup), *mp = lib_mesh(probe), *mt = lib_mesh(ptri);
    const char *names[3] = {"soup.stl", "soup-ascii.stl", "soup.obj"};
    for (int f = 0; f < 3; ++f) {
        const char *path = tmp_path(names[f]);
        if (f == 0)
            write_stl_binary(soup, path);
        else if (f == 1)
            write_stl_ascii(soup, path);
        else
            write_obj(soup, path);
        noctMesh *m = NULL;
        noctError err = {0};
        ck_assert_msg(noctMeshReadSurface(path, &m, &err) == NOCT_OK, "%s", err.message);
        ck_assert(noctMeshIsSurface(m));
        ck_assert_uint_eq(noctMeshTriangleCount(m), noctMeshTriangleCount(orig));
        double lo[3], hi[3], lo0[3], hi0[3];
        noctMeshBounds(m, lo, hi);
        noctMeshBounds(orig, lo0, hi0);
        for (int k = 0; k < 3; ++k)
            ck_assert(lo[k] == lo0[k] && hi[k] == hi0[k]);
        /* noctMeshRead() refuses it (open), naming an edge. */
        noctMesh *solid = NULL;
        noctStatus st = noctMeshRead(path, &solid, &err);
        ck_assert_msg(st == NOCT_ERR_OPEN || st == NOCT_ERR_ORIENTATION, "%s: status %d", path,
                      (int)st);
        ck_assert_ptr_null(solid);
        ck_assert_msg(names_edge(err.message), "%s", err.message);
        ck_assert_msg(strstr(err.message, names[f]) != NULL, "%s", err.message);
        /* Surface from data: the same. */
        noctMeshData *data;
        ck_assert_int_eq(noctMeshDataRead(path, &data, NULL), NOCT_OK);
        noctMesh *md = NULL;
        ck_assert_msg(noctMeshCreateSurfaceFromData(data, &md, &err) == NOCT_OK, "%s",
                      err.message);
        ck_assert(noctMeshIsSurface(md));
        noctMeshDataDestroy(data);
        for (int it = 0; it < 60; ++it) {
            noctTransform x0 = at(0, 0, 0), xp = at(0, 0, 0);
            for (int k = 0; k < 3; ++k)
                xp.p[k] = ((double)test_rand_below(&rng, 21) - 2) * 0.25;
            if (it % 2)
                xp.q = quarter((int)test_rand_below(&rng, 3), (int)test_rand_below(&rng, 4));
            const shape *ps = it % 3 ? probe : ptri;
            const noctMesh *pm = it % 3 ? mp : mt;
            bool want = check_pair(names[f], soup, m, &x0, ps, pm, &xp, false);
            bool a, b;
            ck_assert_int_eq(noctCollideTransformed(orig, &x0, pm, &xp, NOCT_ACCURACY_EXACT, &a,
                                                    NULL, NULL), NOCT_OK);
            ck_assert_int_eq(noctCollideTransformed(md, &x0, pm, &xp, NOCT_ACCURACY_EXACT, &b,
                                                    NULL, NULL), NOCT_OK);
            if (a != want || b != want)
                disagree("%s: read %d, from arrays %d, from data %d", names[f], want, a, b);
        }
        noctMeshDestroy(m);
        noctMeshDestroy(md);
        remove(path);
    }
    rmdir(tmpdir);
    tmpdir[0] = '\0';
    noctMeshDestroy(orig);
    noctMeshDestroy(mp);
    noctMeshDestroy(mt);
    free(soup);
    free(probe);
    free(ptri);
    report_tally("read soups");
    EXPECT_NO_DISAGREEMENT();
}
END_TEST

/* noctMeshCreateSurface() refuses what noctMeshCreate() refuses about
 * polygons and numbers, and accepts open, non-manifold, inconsistent
 * meshes; noctMeshIsSurface() tells them from solids. */
START_TEST(creation_refusals)
{
    noctMesh *m = NULL;
    noctError err;
    const double v[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0.5, 2, 0, 0, 0.5, 0.25, 0};
    const uint32_t tri[] = {0, 1, 2};
    const uint32_t sz3[] = {3}, sz4[] = {4};
    ck_assert_int_eq(noctMeshCreateSurface(v, 6, sz3, 1, tri, &m, &err), NOCT_OK);
    ck_assert(noctMeshIsSurface(m));
    ck_assert_uint_eq(noctMeshTriangleCount(m), 1);
    noctMeshDestroy(m);
    double bad[18];
    memcpy(bad, v, sizeof bad);
    bad[4] = NAN;
    ck_assert_int_eq(noctMeshCreateSurface(bad, 6, sz3, 1, tri, &m, &err), NOCT_ERR_NONFINITE);
    ck_assert_ptr_null(m);
    bad[4] = 1e101;
    ck_assert_int_eq(noctMeshCreateSurface(bad, 6, sz3, 1, tri, &m, &err), NOCT_ERR_TOO_LARGE);
    ck_assert_int_eq(noctMeshCreateSurface(v, 6, sz3, 1, (const uint32_t[]){0, 1, 6}, &m, &err),
                     NOCT_ERR_INDEX);
    /* collinear: no area */
    ck_assert_int_eq(noctMeshCreateSurface(v, 6, sz3, 1, (const uint32_t[]){0, 1, 4}, &m, &err),
                     NOCT_ERR_DEGENERATE);
    ck_assert_int_eq(noctMeshCreateSurface(v, 6, sz3, 1, (const uint32_t[]){0, 1, 1}, &m, &err),
                     NOCT_ERR_DEGENERATE);
    /* a non-planar quad, a non-convex one */
    ck_assert_int_eq(noctMeshCreateSurface(v, 6, sz4, 1, (const uint32_t[]){0, 1, 3, 2}, &m,
                                           &err), NOCT_ERR_NONPLANAR);
    ck_assert_int_eq(noctMeshCreateSurface(v, 6, sz4, 1, (const uint32_t[]){0, 4, 5, 2}, &m,
                                           &err), NOCT_ERR_NONCONVEX);
    ck_assert_ptr_null(m);
    /* Solids are not surfaces. */
    ck_assert_int_eq(noctMeshCreateBox(1, 1, 1, &m, NULL), NOCT_OK);
    ck_assert(!noctMeshIsSurface(m));
    noctMeshDestroy(m);
    /* A closed box given as a surface is a surface (hollow: see containment). */
    shape *s = sh_box("shell", false, 0, 0, 0, 1, 63);
    ck_assert_int_eq(noctMeshCreateSurface(s->v, s->nv, s->sz, s->np, s->ix, &m, &err), NOCT_OK);
    ck_assert(noctMeshIsSurface(m));
    noctMeshDestroy(m);
    free(s);
}
END_TEST

static Suite *surfaces_suite(void)
{
    Suite *s = suite_create("surfaces");
    TCase *tc = test_case(s, "oracle", 60, NULL);
    add_tests(tc, oracle_known_cases, oracle_against_sat, oracle_agrees_on_solids,
              oracle_ray_parity);
    tc = test_case(s, "creation", 30, NULL);
    add_tests(tc, creation_refusals);
    tc = test_case(s, "soups", 120, NULL);
    tcase_add_loop_test(tc, random_dyadic_soups, 0, 2);
    tcase_add_loop_test(tc, random_double_soups, 0, 2);
    tcase_add_loop_test(tc, touching_after_rotation, 0, 2);
    tcase_add_loop_test(tc, flat_and_scaled_soups, 0, 2);
    add_tests(tc, big_soup, slivers, swept_surfaces);
    tcase_add_loop_test(tc, soups_against_turned_solids, 0, 2);
    tc = test_case(s, "shapes", 120, NULL);
    add_tests(tc, open_box_against_small_boxes, containment, touching_and_one_ulp);
    tcase_add_loop_test(tc, odd_surfaces, 0, 2);
    tc = test_case(s, "world and files", 120, NULL);
    tcase_add_loop_test(tc, world_against_brute_force, 0, 3);
    tcase_add_loop_test(tc, read_soups, 0, 2);
    add_tests(tc, read_nonmanifold_stl);
    /* More seeds of the random cases, left out under valgrind. */
    tc = test_case(s, "more seeds", 600, "slow seeds");
    tcase_add_loop_test(tc, random_dyadic_soups, 2, 8);
    tcase_add_loop_test(tc, random_double_soups, 2, 5);
    tcase_add_loop_test(tc, odd_surfaces, 2, 5);
    tcase_add_loop_test(tc, touching_after_rotation, 2, 6);
    tcase_add_loop_test(tc, flat_and_scaled_soups, 2, 6);
    tcase_add_loop_test(tc, world_against_brute_force, 3, 6);
    tcase_add_loop_test(tc, big_soup, 1, 4);
    tcase_add_loop_test(tc, slivers, 1, 6);
    tcase_add_loop_test(tc, swept_surfaces, 1, 6);
    tcase_add_loop_test(tc, soups_against_turned_solids, 2, 8);
    return s;
}

int main(void)
{
    test_gmp_pools();
    return run_suite(surfaces_suite());
}
