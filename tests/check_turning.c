/* SPDX-License-Identifier: MIT */
/*
 * The conservative level for turning motions (noctCollideSweptTransformed()
 * and the continuous worlds' pairs with an object that turns in a step),
 * against the test's own geometry:
 * - it never misses a contact: random pairs of boxes, tetrahedra and L
 *   meshes move between random transforms (at least one turning, by up to
 *   179 degrees, some by under 4), the test's own long double slerp and
 *   lerp sampled densely with the exact level (noctCollideTransformed()),
 *   refined by bisection before the first colliding sample and by a finer
 *   sampling where the solids come nearest; a colliding sample must be
 *   reported, no later than its time;
 * - what it reports is near: at a reported time the test's own distance
 *   between the solids (long double, its own triangles of the meshes:
 *   vertex-triangle and edge-edge distances, 0 when the exact level finds
 *   them colliding) is within the documented bound eps, plus the
 *   placements' rounding; how many reports are false and how far is
 *   printed;
 * - with no turn it is noctCollideSwept() on meshes the test rotated
 *   itself as transform.h places vertices, hit for hit;
 * - worlds: a spinning bar passes a cube between steps (seen only at the
 *   continuous level, at the steps that sweep the diagonal), a keyframed
 *   bar turns through a thin wall, and a teleport with a new rotation;
 * - bad transforms get noctTransformCheck()'s status.
 */
#include <check.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <noctree.h>

#include "testutil.h"

static uint64_t rng = 0x7e41u;

static double uniform(void)
{
    return test_uniform(&rng);
}

/* ---- the test's own shapes ------------------------------------------------------ */

/* A mesh and the test's copy of its solid: vertices and a triangulation of
 * its boundary (any triangulation serves for distances). */
typedef struct shape {
    noctMesh *m;
    int nv, nt;
    long double v[12][3];
    int tri[20][3];
    long double r; /* farthest vertex from the origin */
    uint32_t sizes[10], idx[40];
    int npoly; /* the polygons, to make the mesh (or a rotated copy) */
} shape;

/* Orient polygon poly of s (convex solid: its vertices' centroid inside)
 * counter-clockwise seen from outside. */
static void orient_convex(shape *s, uint32_t *poly, uint32_t n)
{
    long double c[3] = {0, 0, 0}, e1[3], e2[3], nrm[3];
    for (int i = 0; i < s->nv; ++i)
        for (int k = 0; k < 3; ++k)
            c[k] += s->v[i][k] / s->nv;
    for (int k = 0; k < 3; ++k) {
        e1[k] = s->v[poly[1]][k] - s->v[poly[0]][k];
        e2[k] = s->v[poly[2]][k] - s->v[poly[0]][k];
    }
    nrm[0] = e1[1] * e2[2] - e1[2] * e2[1];
    nrm[1] = e1[2] * e2[0] - e1[0] * e2[2];
    nrm[2] = e1[0] * e2[1] - e1[1] * e2[0];
    long double out = 0;
    for (int k = 0; k < 3; ++k)
        out += nrm[k] * (s->v[poly[0]][k] - c[k]);
    if (out < 0)
        for (uint32_t i = 0; i < n / 2; ++i) {
            uint32_t t = poly[i];
            poly[i] = poly[n - 1 - i];
            poly[n - 1 - i] = t;
        }
}

/* The triangles (fans of the polygons) and the radius, from the polygons. */
static void finish_shape(shape *s)
{
    s->nt = 0;
    uint32_t k = 0;
    for (int p = 0; p < s->npoly; ++p) {
        for (uint32_t c = 1; c + 1 < s->sizes[p]; ++c) {
            s->tri[s->nt][0] = (int)s->idx[k];
            s->tri[s->nt][1] = (int)s->idx[k + c];
            s->tri[s->nt][2] = (int)s->idx[k + c + 1];
            ++s->nt;
        }
        k += s->sizes[p];
    }
    s->r = 0;
    for (int i = 0; i < s->nv; ++i)
        s->r = fmaxl(s->r, sqrtl(s->v[i][0] * s->v[i][0] + s->v[i][1] * s->v[i][1] +
                                 s->v[i][2] * s->v[i][2]));
}

/* Make s's mesh from its own vertices, each rotated by R as transform.h
 * places them (R NULL: not rotated). */
static noctMesh *mesh_of_shape(const shape *s, const double *R)
{
    double v[36];
    for (int i = 0; i < s->nv; ++i) {
        for (int r = 0; r < 3; ++r) {
            if (R == NULL) {
                v[3 * i + r] = (double)s->v[i][r];
                continue;
            }
            volatile double a = R[3 * r] * (double)s->v[i][0];
            volatile double b = R[3 * r + 1] * (double)s->v[i][1];
            volatile double ab = a + b;
            volatile double c = R[3 * r + 2] * (double)s->v[i][2];
            v[3 * i + r] = ab + c;
        }
    }
    noctMesh *m;
    noctError err;
    ck_assert_msg(noctMeshCreate(v, (size_t)s->nv, s->sizes, (size_t)s->npoly, s->idx, &m,
                                 &err) == NOCT_OK,
                  "%s", err.message);
    return m;
}

/* kind 0: a box of half-extents h, as noctMeshCreateBox() makes it (own:
 * made by noctMeshCreate() from the test's polygons instead); 1: the kit's
 * tetrahedron; 2: the kit's L. */
static void make_shape(shape *s, int kind, const double h[3], bool own)
{
    memset(s, 0, sizeof *s);
    if (kind == 0) {
        static const uint32_t quads[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                             {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
        s->nv = 8;
        for (int i = 0; i < 8; ++i)
            for (int k = 0; k < 3; ++k)
                s->v[i][k] = (i >> k & 1) ? h[k] : -h[k];
        s->npoly = 6;
        for (int f = 0; f < 6; ++f) {
            s->sizes[f] = 4;
            memcpy(&s->idx[4 * f], quads[f], sizeof quads[f]);
            orient_convex(s, &s->idx[4 * f], 4);
        }
        if (own) {
            finish_shape(s);
            s->m = mesh_of_shape(s, NULL);
        } else {
            ck_assert_int_eq(noctMeshCreateBox(h[0], h[1], h[2], &s->m, NULL), NOCT_OK);
            finish_shape(s);
        }
    } else if (kind == 1) {
        static const long double P[4][3] = {
            {0, 0, 0}, {0.9L, 0.1L, 0}, {0.2L, 0.8L, 0.1L}, {0.3L, 0.2L, 0.7L}};
        static const uint32_t tris[4][3] = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
        s->nv = 4;
        for (int i = 0; i < 4; ++i)
            for (int k = 0; k < 3; ++k)
                s->v[i][k] = (double)P[i][k]; /* the mesh's doubles */
        s->npoly = 4;
        for (int f = 0; f < 4; ++f) {
            s->sizes[f] = 3;
            memcpy(&s->idx[3 * f], tris[f], sizeof tris[f]);
            orient_convex(s, &s->idx[3 * f], 3);
        }
        finish_shape(s);
        s->m = own ? mesh_of_shape(s, NULL) : make_tetrahedron();
    } else {
        /* testutil.c's make_ell(), polygon for polygon */
        static const double P[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
        static const uint32_t faces[4][4] = {
            {6, 7, 8, 9}, {6, 9, 10, 11}, {0, 3, 2, 1}, {0, 5, 4, 3}};
        s->nv = 12;
        for (int i = 0; i < 12; ++i) {
            s->v[i][0] = P[i % 6][0] - 1;
            s->v[i][1] = P[i % 6][1] - 1;
            s->v[i][2] = i < 6 ? -0.5L : 0.5L;
        }
        uint32_t n = 0, k = 0;
        for (int f = 0; f < 4; ++f) {
            s->sizes[n++] = 4;
            for (int c = 0; c < 4; ++c)
                s->idx[k++] = faces[f][c];
        }
        for (uint32_t i = 0; i < 6; ++i) {
            const uint32_t j = (i + 1) % 6;
            s->sizes[n++] = 4;
            s->idx[k++] = i;
            s->idx[k++] = j;
            s->idx[k++] = j + 6;
            s->idx[k++] = i + 6;
        }
        s->npoly = (int)n;
        finish_shape(s);
        s->m = own ? mesh_of_shape(s, NULL) : make_ell();
    }
}

static void random_shape(shape *s, bool own)
{
    const int kind = (int)test_rand_below(&rng, 3);
    double h[3];
    for (int k = 0; k < 3; ++k)
        h[k] = 0.1 + 0.9 * uniform();
    make_shape(s, kind, h, own);
}

/* ---- the test's own motion: long double slerp and lerp ------------------------- */

typedef struct motion {
    noctTransform x0, x1;
    long double q0[4], q1[4]; /* q1 on q0's side: the shorter arc */
    long double half;         /* half the turn's angle */
} motion;

static void motion_init(motion *mo, const noctTransform *x0, const noctTransform *x1)
{
    mo->x0 = *x0;
    mo->x1 = *x1;
    const long double a[4] = {x0->q.x, x0->q.y, x0->q.z, x0->q.w};
    const long double b[4] = {x1->q.x, x1->q.y, x1->q.z, x1->q.w};
    long double na = 0, nb = 0, d = 0;
    for (int k = 0; k < 4; ++k) {
        na += a[k] * a[k];
        nb += b[k] * b[k];
    }
    for (int k = 0; k < 4; ++k) {
        mo->q0[k] = a[k] / sqrtl(na);
        mo->q1[k] = b[k] / sqrtl(nb);
        d += mo->q0[k] * mo->q1[k];
    }
    if (d < 0) {
        for (int k = 0; k < 4; ++k)
            mo->q1[k] = -mo->q1[k];
        d = -d;
    }
    mo->half = acosl(fminl(d, 1));
}

/* The turn's angle. */
static long double motion_angle(const motion *mo)
{
    return 2 * mo->half;
}

static long double motion_travel(const motion *mo)
{
    long double l = 0;
    for (int k = 0; k < 3; ++k) {
        const long double d = (long double)mo->x1.p[k] - mo->x0.p[k];
        l += d * d;
    }
    return sqrtl(l);
}

/* The pose at time s: the rotation matrix and translation in long double,
 * and the transform that the library is handed for it (the ends bit for
 * bit). */
static void motion_at(const motion *mo, long double s, long double R[9], long double t[3],
                      noctTransform *x)
{
    long double q[4];
    if (mo->half < 1e-30L) {
        memcpy(q, mo->q0, sizeof q);
    } else {
        const long double sh = sinl(mo->half);
        const long double a = sinl((1 - s) * mo->half) / sh, b = sinl(s * mo->half) / sh;
        long double n = 0;
        for (int k = 0; k < 4; ++k) {
            q[k] = a * mo->q0[k] + b * mo->q1[k];
            n += q[k] * q[k];
        }
        for (int k = 0; k < 4; ++k)
            q[k] /= sqrtl(n);
    }
    const long double X = q[0], Y = q[1], Z = q[2], W = q[3];
    R[0] = 1 - 2 * (Y * Y + Z * Z);
    R[1] = 2 * (X * Y - Z * W);
    R[2] = 2 * (X * Z + Y * W);
    R[3] = 2 * (X * Y + Z * W);
    R[4] = 1 - 2 * (X * X + Z * Z);
    R[5] = 2 * (Y * Z - X * W);
    R[6] = 2 * (X * Z - Y * W);
    R[7] = 2 * (Y * Z + X * W);
    R[8] = 1 - 2 * (X * X + Y * Y);
    for (int k = 0; k < 3; ++k)
        t[k] = mo->x0.p[k] + s * ((long double)mo->x1.p[k] - mo->x0.p[k]);
    if (x == NULL)
        return;
    if (s == 0) {
        *x = mo->x0;
    } else if (s == 1) {
        *x = mo->x1;
    } else {
        x->q = (noctQuat){(double)X, (double)Y, (double)Z, (double)W};
        for (int k = 0; k < 3; ++k)
            x->p[k] = (double)t[k];
    }
}

/* The shape's vertices at a pose. */
static void place(const shape *s, const long double R[9], const long double t[3],
                  long double w[12][3])
{
    for (int i = 0; i < s->nv; ++i)
        for (int r = 0; r < 3; ++r)
            w[i][r] = R[3 * r] * s->v[i][0] + R[3 * r + 1] * s->v[i][1] +
                      R[3 * r + 2] * s->v[i][2] + t[r];
}

/* ---- the test's own distances (long double) ------------------------------------ */

/* A distance or time farther than any here: finite, since valgrind
 * computes long double in double precision and mishandles its infinity. */
#define FAR 1e300L

static long double dot3(const long double a[3], const long double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void sub3(const long double a[3], const long double b[3], long double d[3])
{
    for (int k = 0; k < 3; ++k)
        d[k] = a[k] - b[k];
}

/* Squared distance from p to the triangle abc: the closest point by its
 * Voronoi region (vertices, edges, face). */
static long double point_triangle2(const long double p[3], const long double a[3],
                                   const long double b[3], const long double c[3])
{
    long double ab[3], ac[3], ap[3], bp[3], cp[3], q[3];
    sub3(b, a, ab);
    sub3(c, a, ac);
    sub3(p, a, ap);
    const long double d1 = dot3(ab, ap), d2 = dot3(ac, ap);
    if (d1 <= 0 && d2 <= 0)
        return dot3(ap, ap);
    sub3(p, b, bp);
    const long double d3 = dot3(ab, bp), d4 = dot3(ac, bp);
    if (d3 >= 0 && d4 <= d3)
        return dot3(bp, bp);
    const long double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        const long double v = d1 / (d1 - d3);
        for (int k = 0; k < 3; ++k)
            q[k] = a[k] + v * ab[k] - p[k];
        return dot3(q, q);
    }
    sub3(p, c, cp);
    const long double d5 = dot3(ab, cp), d6 = dot3(ac, cp);
    if (d6 >= 0 && d5 <= d6)
        return dot3(cp, cp);
    const long double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        const long double w = d2 / (d2 - d6);
        for (int k = 0; k < 3; ++k)
            q[k] = a[k] + w * ac[k] - p[k];
        return dot3(q, q);
    }
    const long double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        const long double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        for (int k = 0; k < 3; ++k)
            q[k] = b[k] + w * (c[k] - b[k]) - p[k];
        return dot3(q, q);
    }
    const long double den = 1 / (va + vb + vc), v = vb * den, w = vc * den;
    for (int k = 0; k < 3; ++k)
        q[k] = a[k] + ab[k] * v + ac[k] * w - p[k];
    return dot3(q, q);
}

static long double clamp01(long double x)
{
    return x < 0 ? 0 : x > 1 ? 1 : x;
}

/* Squared distance between the segments p1q1 and p2q2. */
static long double segment_segment2(const long double p1[3], const long double q1[3],
                                    const long double p2[3], const long double q2[3])
{
    long double d1[3], d2[3], r[3];
    sub3(q1, p1, d1);
    sub3(q2, p2, d2);
    sub3(p1, p2, r);
    const long double a = dot3(d1, d1), e = dot3(d2, d2), f = dot3(d2, r);
    long double s, t;
    if (a <= 0 && e <= 0) {
        s = t = 0;
    } else if (a <= 0) {
        s = 0;
        t = clamp01(f / e);
    } else {
        const long double c = dot3(d1, r);
        if (e <= 0) {
            t = 0;
            s = clamp01(-c / a);
        } else {
            const long double b = dot3(d1, d2), den = a * e - b * b;
            s = den > 0 ? clamp01((b * f - c * e) / den) : 0;
            t = (b * s + f) / e;
            if (t < 0) {
                t = 0;
                s = clamp01(-c / a);
            } else if (t > 1) {
                t = 1;
                s = clamp01((b - c) / a);
            }
        }
    }
    long double d[3];
    for (int k = 0; k < 3; ++k)
        d[k] = (p1[k] + d1[k] * s) - (p2[k] + d2[k] * t);
    return dot3(d, d);
}

/* The distance between two triangles that do not cross: the least of
 * their vertex-triangle and edge-edge distances. */
static long double triangle_triangle(long double A[3][3], long double B[3][3])
{
    long double m = FAR;
    for (int i = 0; i < 3; ++i) {
        m = fminl(m, point_triangle2(A[i], B[0], B[1], B[2]));
        m = fminl(m, point_triangle2(B[i], A[0], A[1], A[2]));
        for (int j = 0; j < 3; ++j)
            m = fminl(m, segment_segment2(A[i], A[(i + 1) % 3], B[j], B[(j + 1) % 3]));
    }
    return sqrtl(m);
}

/* The distance between the two shapes placed at wa, wb, taken as not
 * colliding: the least distance between their boundaries' triangles. */
static long double boundary_distance(const shape *a, long double wa[12][3], const shape *b,
                                     long double wb[12][3])
{
    long double m = FAR;
    for (int i = 0; i < a->nt; ++i) {
        long double A[3][3];
        for (int c = 0; c < 3; ++c)
            memcpy(A[c], wa[a->tri[i][c]], sizeof A[c]);
        for (int j = 0; j < b->nt; ++j) {
            long double B[3][3];
            for (int c = 0; c < 3; ++c)
                memcpy(B[c], wb[b->tri[j][c]], sizeof B[c]);
            m = fminl(m, triangle_triangle(A, B));
        }
    }
    return m;
}

/* A cheaper stand-in to find where the solids come nearest: the least
 * vertex-triangle distance either way. */
static long double vertex_distance(const shape *a, long double wa[12][3], const shape *b,
                                   long double wb[12][3])
{
    long double m = FAR;
    for (int i = 0; i < a->nv; ++i)
        for (int j = 0; j < b->nt; ++j)
            m = fminl(m, point_triangle2(wa[i], wb[b->tri[j][0]], wb[b->tri[j][1]],
                                         wb[b->tri[j][2]]));
    for (int i = 0; i < b->nv; ++i)
        for (int j = 0; j < a->nt; ++j)
            m = fminl(m, point_triangle2(wb[i], wa[a->tri[j][0]], wa[a->tri[j][1]],
                                         wa[a->tri[j][2]]));
    return sqrtl(m);
}

/* ---- a pair in motion ----------------------------------------------------------- */

typedef struct pair {
    shape *a, *b;
    motion ma, mb;
    long calls; /* exact tests made */
} pair;

/* Do the solids collide at time s of the test's motion (the exact level
 * on the test's rounded pose)? A sphere test first: every point of a
 * shape is within r of its origin. */
static bool collides_at(pair *P, long double s)
{
    long double Ra[9], Rb[9], ta[3], tb[3], d[3];
    noctTransform xa, xb;
    motion_at(&P->ma, s, Ra, ta, &xa);
    motion_at(&P->mb, s, Rb, tb, &xb);
    sub3(ta, tb, d);
    if (sqrtl(dot3(d, d)) > (P->a->r + P->b->r) * (1 + 1e-12L) + 1e-12L)
        return false;
    bool hit;
    noctError err;
    ++P->calls;
    const noctStatus st = noctCollideTransformed(P->a->m, &xa, P->b->m, &xb,
                                                 NOCT_ACCURACY_EXACT, &hit, NULL, &err);
    ck_assert_msg(st == NOCT_OK, "%s", err.message);
    return hit;
}

/* The distance between the solids at time s (0 when they collide). */
static long double distance_at(pair *P, long double s)
{
    if (collides_at(P, s))
        return 0;
    long double Ra[9], Rb[9], ta[3], tb[3], wa[12][3], wb[12][3];
    motion_at(&P->ma, s, Ra, ta, NULL);
    motion_at(&P->mb, s, Rb, tb, NULL);
    place(P->a, Ra, ta, wa);
    place(P->b, Rb, tb, wb);
    return boundary_distance(P->a, wa, P->b, wb);
}

static long double proxy_at(const pair *P, long double s)
{
    long double Ra[9], Rb[9], ta[3], tb[3], wa[12][3], wb[12][3], d[3];
    motion_at(&P->ma, s, Ra, ta, NULL);
    motion_at(&P->mb, s, Rb, tb, NULL);
    sub3(ta, tb, d);
    const long double gap = sqrtl(dot3(d, d)) - P->a->r - P->b->r;
    if (gap > 0)
        return gap;
    place(P->a, Ra, ta, wa);
    place(P->b, Rb, tb, wb);
    return vertex_distance(P->a, wa, P->b, wb);
}

/* The documented bound eps (narrowphase.h), and the placements' rounding
 * (2^-36 of the coordinates' magnitude). */
static long double eps_of(const pair *P, long double *rounding)
{
    const long double ra = P->a->r, rb = P->b->r;
    const long double sa = motion_travel(&P->ma) + ra * motion_angle(&P->ma);
    const long double sb = motion_travel(&P->mb) + rb * motion_angle(&P->mb);
    long double mag = 0;
    const motion *m[2] = {&P->ma, &P->mb};
    const long double r[2] = {ra, rb};
    for (int i = 0; i < 2; ++i) {
        long double e = r[i];
        for (int k = 0; k < 3; ++k)
            e = fmaxl(e, fmaxl(fabsl((long double)m[i]->x0.p[k]),
                               fabsl((long double)m[i]->x1.p[k])) + r[i]);
        mag += e;
    }
    *rounding = 0x1p-36L * mag;
    return fmaxl(0x1p-20L * (ra + rb), (sa + sb) / 1024);
}

/* ---- 1, 2: never misses, reports only near ------------------------------------- */

/* The summary of the random pairs. */
typedef struct tally {
    int pairs, contacts, reports, near_reports, false_reports;
    long double worst_false;  /* largest distance / eps of a false report */
    long double worst_near;   /* of any near report */
    long double least_lead;   /* least (first colliding sample - time) */
    long calls;
} tally;

/* Sample count along the motion, refinement samples, bisection steps. */
#define SAMPLES 2000
#define REFINE 400
#define BISECT 40
/* Time the test's own pose rounding may shift a contact by, at most. */
#define TIME_TOL 1e-9L

static void check_pair(pair *P, tally *T)
{
    bool colliding;
    noctSweepHit hit;
    noctError err;
    const noctStatus st = noctCollideSweptTransformed(P->a->m, &P->ma.x0, &P->ma.x1, P->b->m,
                                                      &P->mb.x0, &P->mb.x1, &colliding, &hit,
                                                      NULL, &err);
    ck_assert_msg(st == NOCT_OK, "%s", err.message);
    ++T->pairs;

    /* The earliest colliding time found: dense samples, then bisection
     * before the first colliding one. */
    long double first = FAR;
    long double prev = 0;
    for (int i = 0; i <= SAMPLES; ++i) {
        const long double s = (long double)i / SAMPLES;
        if (collides_at(P, s)) {
            long double lo = prev, hi = s;
            for (int k = 0; i > 0 && k < BISECT; ++k) {
                const long double mid = (lo + hi) / 2;
                if (collides_at(P, mid))
                    hi = mid;
                else
                    lo = mid;
            }
            first = hi;
            break;
        }
        prev = s;
    }
    if (first == FAR) {
        /* none: a finer look where they come nearest (every 10th sample
         * by the vertex distance) */
        long double best = FAR;
        int at = 0;
        for (int i = 0; i <= SAMPLES; i += 10) {
            const long double d = proxy_at(P, (long double)i / SAMPLES);
            if (d < best) {
                best = d;
                at = i;
            }
        }
        const long double lo = fmaxl(0, (long double)(at - 10) / SAMPLES);
        const long double hi = fminl(1, (long double)(at + 10) / SAMPLES);
        for (int i = 0; i <= REFINE; ++i) {
            const long double s = lo + (hi - lo) * i / REFINE;
            if (collides_at(P, s)) {
                first = s;
                break;
            }
        }
    }

    const bool turns = memcmp(&P->ma.x0.q, &P->ma.x1.q, sizeof(noctQuat)) != 0 ||
                       memcmp(&P->mb.x0.q, &P->mb.x1.q, sizeof(noctQuat)) != 0;
    if (first != FAR) {
        ++T->contacts;
        ck_assert_msg(colliding,
                      "missed contact: a collides with b at time %.21Lg of the motion "
                      "(A %a %a %a q %a %a %a %a -> %a %a %a q %a %a %a %a; "
                      "B %a %a %a q %a %a %a %a -> %a %a %a q %a %a %a %a)",
                      first, P->ma.x0.p[0], P->ma.x0.p[1], P->ma.x0.p[2], P->ma.x0.q.x,
                      P->ma.x0.q.y, P->ma.x0.q.z, P->ma.x0.q.w, P->ma.x1.p[0], P->ma.x1.p[1],
                      P->ma.x1.p[2], P->ma.x1.q.x, P->ma.x1.q.y, P->ma.x1.q.z, P->ma.x1.q.w,
                      P->mb.x0.p[0], P->mb.x0.p[1], P->mb.x0.p[2], P->mb.x0.q.x,
                      P->mb.x0.q.y, P->mb.x0.q.z, P->mb.x0.q.w, P->mb.x1.p[0], P->mb.x1.p[1],
                      P->mb.x1.p[2], P->mb.x1.q.x, P->mb.x1.q.y, P->mb.x1.q.z, P->mb.x1.q.w);
        ck_assert_msg(hit.time <= first + TIME_TOL,
                      "late: reported at %.17g, colliding at %.21Lg", hit.time, first);
        T->least_lead = fminl(T->least_lead, first - hit.time);
    }
    ck_assert(hit.time >= 0 && hit.time <= 1);
    if (!colliding) {
        ck_assert_int_eq(hit.feature, NOCT_SWEEP_NONE);
        T->calls += P->calls;
        return;
    }
    ++T->reports;
    ck_assert(hit.feature != NOCT_SWEEP_NONE);
    ck_assert(hit.conservative == turns);
    if (hit.feature == NOCT_SWEEP_START)
        ck_assert(hit.time == 0);
    if (hit.feature == NOCT_SWEEP_END)
        ck_assert(hit.time == 1);
    long double rounding;
    const long double eps = eps_of(P, &rounding);
    if (hit.feature == NOCT_SWEEP_NEAR || first == FAR) {
        /* within eps at the reported time, on the test's own pose: the
         * slack is the placements' rounding as documented, the margin
         * test's (2^-40 of the magnitude, twice) and the test's own
         * (far less) */
        const long double d = distance_at(P, hit.time);
        ck_assert_msg(d <= eps + 2 * rounding,
                      "reported at %.17g (feature %d) while %.6Lg apart: eps %.6Lg", hit.time,
                      (int)hit.feature, d, eps);
        if (hit.feature == NOCT_SWEEP_NEAR) {
            ++T->near_reports;
            T->worst_near = fmaxl(T->worst_near, d / eps);
        }
        if (first == FAR) {
            ++T->false_reports;
            T->worst_false = fmaxl(T->worst_false, d / eps);
        }
    }
    T->calls += P->calls;
}

/* A random turn of q by up to max_deg degrees. */
static void turn(const noctQuat *q, double max_deg, noctQuat *out)
{
    double axis[3];
    noctQuat by;
    for (int k = 0; k < 3; ++k)
        axis[k] = uniform() - 0.5;
    ck_assert_int_eq(noctQuatFromAxisAngle(axis, max_deg * (0.02 + 0.98 * uniform()), &by),
                     NOCT_OK);
    *out = noctQuatCompose(&by, q);
}

/* A random motion of a: from near the origin, by up to 3 units; turning
 * by up to 179 degrees (one in four: under 4). */
static void random_motion(noctTransform *x0, noctTransform *x1, bool turning)
{
    for (int k = 0; k < 3; ++k) {
        x0->p[k] = 3 * uniform() - 1.5;
        x1->p[k] = x0->p[k] + (uniform() < 0.2 ? 0 : 3 * uniform() - 1.5);
    }
    test_random_quat(&rng, &x0->q);
    if (turning)
        turn(&x0->q, uniform() < 0.25 ? 4 : 179, &x1->q);
    else
        x1->q = x0->q;
}

static void print_tally(const char *name, const tally *T)
{
    printf("%s: %d pairs, %d with a contact sampled, %d reported (%d near), %d false "
           "(farthest %.3Lg eps; near reports at most %.3Lg eps), least lead %.3Lg, "
           "%ld exact tests\n",
           name, T->pairs, T->contacts, T->reports, T->near_reports, T->false_reports,
           T->worst_false, T->worst_near, T->least_lead, T->calls);
    fflush(stdout);
}

/* _i: 0 a quick run (under valgrind too), 1 the full one (tag slow). */
START_TEST(never_misses_reports_only_near)
{
    tally T = {.pairs = 0};
    T.least_lead = FAR;
    const int rounds = _i ? 400 : 24;
    for (int round = 0; round < rounds; ++round) {
        shape a, b;
        random_shape(&a, false);
        random_shape(&b, false);
        pair P = {.a = &a, .b = &b};
        /* a starting apart, so that the motion decides */
        noctTransform xa0, xa1, xb0, xb1;
        bool apart = false;
        for (int tries = 0; tries < 20 && !apart; ++tries) {
            const int who = (int)test_rand_below(&rng, 3); /* a, b or both turn */
            random_motion(&xa0, &xa1, who != 1);
            random_motion(&xb0, &xb1, who != 0);
            bool hit;
            ck_assert_int_eq(noctCollideTransformed(a.m, &xa0, b.m, &xb0, NOCT_ACCURACY_EXACT,
                                                    &hit, NULL, NULL),
                             NOCT_OK);
            apart = !hit;
        }
        motion_init(&P.ma, &xa0, &xa1);
        motion_init(&P.mb, &xb0, &xb1);
        check_pair(&P, &T);
        noctMeshDestroy(a.m);
        noctMeshDestroy(b.m);
    }
    print_tally(_i ? "turning, full" : "turning", &T);
    ck_assert_int_gt(T.contacts, rounds / 8);
    ck_assert_int_gt(T.pairs - T.reports, rounds / 8);
}
END_TEST

/* Grazing: b placed so that a's motion just reaches it (or just fails
 * to): from a random motion that collides, b moved back along the
 * direction between the two until the contact is as short as the
 * bisection can make it. */
START_TEST(grazing_contacts)
{
    tally T = {.pairs = 0};
    T.least_lead = FAR;
    const int rounds = _i ? 120 : 8;
    for (int round = 0; round < rounds;) {
        shape a, b;
        random_shape(&a, false);
        random_shape(&b, false);
        pair P = {.a = &a, .b = &b};
        noctTransform xa0, xa1, xb;
        random_motion(&xa0, &xa1, true);
        xb.q = (noctQuat){0, 0, 0, 1};
        test_random_quat(&rng, &xb.q);
        /* b where a is at mid-motion, then pushed out along a random
         * direction until no sample of a's motion meets it */
        long double R[9], t[3];
        motion_init(&P.ma, &xa0, &xa1);
        motion_at(&P.ma, 0.25L + 0.5L * uniform(), R, t, NULL);
        double dir[3];
        for (int k = 0; k < 3; ++k)
            dir[k] = uniform() - 0.5;
        long double lo = 0, hi = 0;
        bool found = false;
        for (hi = 0.25L; hi < 8; hi *= 2) {
            for (int k = 0; k < 3; ++k)
                xb.p[k] = (double)(t[k] + hi * dir[k]);
            motion_init(&P.mb, &xb, &xb);
            bool any = false;
            for (int i = 0; i <= 200 && !any; ++i)
                any = collides_at(&P, (long double)i / 200);
            if (!any) {
                found = true;
                break;
            }
            lo = hi;
        }
        if (found) {
            /* the last distance of push that still meets a sample */
            for (int k = 0; k < 30; ++k) {
                const long double mid = (lo + hi) / 2;
                for (int c = 0; c < 3; ++c)
                    xb.p[c] = (double)(t[c] + mid * dir[c]);
                motion_init(&P.mb, &xb, &xb);
                bool any = false;
                for (int i = 0; i <= 200 && !any; ++i)
                    any = collides_at(&P, (long double)i / 200);
                if (any)
                    lo = mid;
                else
                    hi = mid;
            }
            bool start;
            ck_assert_int_eq(noctCollideTransformed(a.m, &xa0, b.m, &xb, NOCT_ACCURACY_EXACT,
                                                    &start, NULL, NULL),
                             NOCT_OK);
            if (!start) {
                P.calls = 0;
                check_pair(&P, &T);
                ++round;
            }
        }
        noctMeshDestroy(a.m);
        noctMeshDestroy(b.m);
    }
    print_tally(_i ? "grazing, full" : "grazing", &T);
}
END_TEST

/* ---- 3: no turn, the exact level ------------------------------------------------ */

/* The same edge or triangle, whatever the order of its vertices. */
static bool same_feature(const uint32_t x[3], const uint32_t y[3])
{
    int n = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            n += x[i] == y[j] && x[i] != UINT32_MAX;
    int m = 0;
    for (int i = 0; i < 3; ++i)
        m += x[i] != UINT32_MAX;
    int l = 0;
    for (int i = 0; i < 3; ++i)
        l += y[i] != UINT32_MAX;
    return n == m && m == l;
}

/* The same hit: time and kind bit for bit, the same features (an edge may
 * be named from either end: the test's own meshes may list it the other
 * way round), the point within its rounding. */
static bool same_hit(const noctSweepHit *x, const noctSweepHit *y)
{
    bool near = true;
    for (int k = 0; k < 3; ++k)
        near = near && fabs(x->point[k] - y->point[k]) <= 1e-12 * (1 + fabs(y->point[k]));
    return memcmp(&x->time, &y->time, sizeof x->time) == 0 && x->feature == y->feature &&
           same_feature(x->a, y->a) && same_feature(x->b, y->b) && near &&
           x->conservative == y->conservative;
}

START_TEST(without_a_turn_it_is_the_swept_test)
{
    int hits = 0, rounds = 150;
    for (int round = 0; round < rounds; ++round) {
        shape a, b;
        random_shape(&a, true);
        random_shape(&b, true);
        noctTransform xa0, xa1, xb0, xb1;
        random_motion(&xa0, &xa1, false);
        random_motion(&xb0, &xb1, false);
        if (round % 5 == 0)
            xa0.q = xa1.q = (noctQuat){0, 0, 0, 1};
        /* the meshes rotated by the test, as transform.h places them */
        double Ra[9], Rb[9];
        ck_assert_int_eq(noctQuatToMatrix(&xa0.q, Ra, NULL), NOCT_OK);
        ck_assert_int_eq(noctQuatToMatrix(&xb0.q, Rb, NULL), NOCT_OK);
        noctMesh *ra = mesh_of_shape(&a, Ra), *rb = mesh_of_shape(&b, Rb);
        bool c1, c2;
        noctSweepHit h1, h2;
        ck_assert_int_eq(noctCollideSweptTransformed(a.m, &xa0, &xa1, b.m, &xb0, &xb1, &c1, &h1,
                                                     NULL, NULL),
                         NOCT_OK);
        ck_assert_int_eq(
            noctCollideSwept(ra, xa0.p, xa1.p, rb, xb0.p, xb1.p, &c2, &h2, NULL), NOCT_OK);
        ck_assert_msg(c1 == c2, "round %d: verdict %d, swept test %d", round, c1, c2);
        ck_assert_msg(same_hit(&h1, &h2),
                      "round %d: hit at %a (%d: %u %u %u / %u %u %u, point %a %a %a), swept test "
                      "%a (%d: %u %u %u / %u %u %u, point %a %a %a)",
                      round, h1.time, (int)h1.feature, h1.a[0], h1.a[1], h1.a[2], h1.b[0],
                      h1.b[1], h1.b[2], h1.point[0], h1.point[1], h1.point[2], h2.time,
                      (int)h2.feature, h2.a[0], h2.a[1], h2.a[2], h2.b[0], h2.b[1], h2.b[2],
                      h2.point[0], h2.point[1], h2.point[2]);
        ck_assert(!h1.conservative);
        hits += c1;
        /* and the verdict alone */
        ck_assert_int_eq(noctCollideSweptTransformed(a.m, &xa0, &xa1, b.m, &xb0, &xb1, &c1, NULL,
                                                     NULL, NULL),
                         NOCT_OK);
        ck_assert(c1 == c2);
        noctMeshDestroy(ra);
        noctMeshDestroy(rb);
        noctMeshDestroy(a.m);
        noctMeshDestroy(b.m);
    }
    ck_assert_int_gt(hits, rounds / 10);
    ck_assert_int_lt(hits, rounds - rounds / 10);
}
END_TEST

/* ---- 4: worlds ------------------------------------------------------------------ */

static const double PI = 3.14159265358979323846;

/* The angle (radians, from 0) at which a bar of half-thickness w turning
 * counter-clockwise about z from the x axis first touches a convex
 * polygon of corners c: the least over corners of the angle at which the
 * bar's leading face reaches it, polar angle less asin(w / radius). */
static double first_touch(const double (*c)[2], int n, double w)
{
    double least = INFINITY;
    for (int i = 0; i < n; ++i) {
        const double r = hypot(c[i][0], c[i][1]);
        least = fmin(least, atan2(c[i][1], c[i][0]) - asin(w / r));
    }
    return least;
}

static noctWorld *continuous_world(noctAccuracy accuracy, unsigned effects)
{
    noctWorldDef wd = noctDefaultWorldDef();
    wd.accuracy = accuracy;
    wd.effects = effects;
    noctWorld *w;
    ck_assert_int_eq(noctWorldCreate(&wd, &w, NULL), NOCT_OK);
    return w;
}

START_TEST(a_spinning_bar_sweeps_a_cube)
{
    /* the cube's corners in the xy plane: its first touch with the bar
     * (half-thickness 0.05) at 36.87 degrees, its last before 90 */
    const double corners[4][2] = {{0.55, 0.55}, {0.65, 0.55}, {0.65, 0.65}, {0.55, 0.65}};
    const double touch = first_touch(corners, 4, 0.05) / (PI / 2);
    ck_assert(touch > 0.4 && touch < 0.42);
    for (int level = 0; level < 2; ++level) {
        noctWorld *w = continuous_world(level ? NOCT_ACCURACY_CONTINUOUS : NOCT_ACCURACY_EXACT,
                                        NOCT_EFFECT_MOTION | NOCT_EFFECT_EVENTS |
                                            NOCT_EFFECT_SPIN);
        noctObjectDef bar = noctDefaultObjectDef();
        bar.half_extents[0] = 1;
        bar.half_extents[1] = bar.half_extents[2] = 0.05;
        ck_assert_int_eq(noctQuatFromAxisAngle((const double[3]){0, 0, 1}, 90,
                                               &bar.angular_velocity),
                         NOCT_OK);
        noctObjectDef cube = noctDefaultObjectDef();
        cube.half_extents[0] = cube.half_extents[1] = cube.half_extents[2] = 0.05;
        cube.transform.p[0] = cube.transform.p[1] = 0.6;
        cube.type = NOCT_OBJECT_STATIC;
        noctObjectId ib, ic;
        ck_assert_int_eq(noctWorldCreateObject(w, &bar, &ib, NULL), NOCT_OK);
        ck_assert_int_eq(noctWorldCreateObject(w, &cube, &ic, NULL), NOCT_OK);
        for (int step = 1; step <= 8; ++step) {
            ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
            const noctPair *p;
            const size_t n = noctWorldColliding(w, &p);
            const size_t began = noctWorldBegan(w, &p);
            const size_t ended = noctWorldEnded(w, &p);
            const noctSweepHit *hits;
            size_t nh;
            ck_assert_int_eq(noctWorldBeganHits(w, &hits, &nh, NULL), NOCT_OK);
            if (!level) {
                /* the exact level sees the bar at 90-degree poses only */
                ck_assert_msg(n == 0, "exact level, step %d: %zu colliding", step, n);
                ck_assert_uint_eq(nh, 0);
                continue;
            }
            /* steps 1, 3, ... sweep 0 to 90, 180 to 270 degrees: the
             * diagonal at 45 and 225 */
            const bool odd = step % 2 == 1;
            ck_assert_msg(n == (odd ? 1u : 0u), "continuous level, step %d: %zu colliding", step,
                          n);
            ck_assert_uint_eq(began, odd ? 1u : 0u);
            ck_assert_uint_eq(ended, odd ? 0u : 1u);
            ck_assert_uint_eq(nh, began);
            if (odd) {
                ck_assert(hits[0].conservative);
                ck_assert_int_eq(hits[0].feature, NOCT_SWEEP_NEAR);
                /* near before the touch, by about eps over the speed */
                ck_assert_msg(hits[0].time <= touch && hits[0].time > touch - 0.01,
                              "step %d: hit at %.17g, touch at %.17g", step, hits[0].time,
                              touch);
            }
        }
        noctWorldDestroy(w);
    }
}
END_TEST

START_TEST(a_keyframed_bar_turns_through_a_thin_wall)
{
    /* the bar turns 90 degrees and moves 0.2 along x from tick 0 to 1,
     * then stays; the wall (x 0.49 to 0.51, y 0.3 to 0.7) lies across
     * its path at 45 degrees, clear of both ends */
    for (int level = 0; level < 2; ++level) {
        noctWorld *w = continuous_world(level ? NOCT_ACCURACY_CONTINUOUS : NOCT_ACCURACY_EXACT,
                                        NOCT_EFFECT_EVENTS | NOCT_EFFECT_TRACK);
        noctObjectDef bar = noctDefaultObjectDef();
        bar.half_extents[0] = 1;
        bar.half_extents[1] = bar.half_extents[2] = 0.05;
        bar.type = NOCT_OBJECT_KINEMATIC;
        noctObjectDef wall = noctDefaultObjectDef();
        wall.half_extents[0] = 0.01;
        wall.half_extents[1] = wall.half_extents[2] = 0.2;
        wall.transform.p[0] = wall.transform.p[1] = 0.5;
        wall.type = NOCT_OBJECT_STATIC;
        noctObjectId ib, iw;
        ck_assert_int_eq(noctWorldCreateObject(w, &bar, &ib, NULL), NOCT_OK);
        ck_assert_int_eq(noctWorldCreateObject(w, &wall, &iw, NULL), NOCT_OK);
        noctKeyframe k[3];
        k[0].tick = 0;
        k[0].x = noctIdentityTransform();
        k[1].tick = 1;
        k[1].x = noctIdentityTransform();
        k[1].x.p[0] = 0.2;
        ck_assert_int_eq(noctQuatFromAxisAngle((const double[3]){0, 0, 1}, 90, &k[1].x.q),
                         NOCT_OK);
        k[2] = k[1];
        k[2].tick = 2;
        ck_assert_int_eq(noctWorldSetTrack(w, ib, k, 3, NULL), NOCT_OK);
        int seen[4] = {0};
        for (int step = 1; step <= 3; ++step) {
            ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
            const noctPair *p;
            seen[step] = (int)noctWorldColliding(w, &p);
            const noctSweepHit *hits;
            size_t nh;
            ck_assert_int_eq(noctWorldBeganHits(w, &hits, &nh, NULL), NOCT_OK);
            if (level && step == 1) {
                ck_assert_uint_eq(nh, 1);
                ck_assert(hits[0].conservative);
                ck_assert_int_eq(hits[0].feature, NOCT_SWEEP_NEAR);
                ck_assert(hits[0].time > 0 && hits[0].time < 0.5);
            }
        }
        /* the exact level never sees it; the continuous one at step 1,
         * and no more once the bar stands still (step 2 is exact again:
         * the same rotation bit for bit) */
        ck_assert_int_eq(seen[1], (level ? 1 : 0));
        ck_assert_int_eq(seen[2], 0);
        ck_assert_int_eq(seen[3], 0);

        /* a teleport with a new rotation back through the wall: seen at
         * the continuous level; the same rotation moved clear of the wall
         * is not */
        ck_assert_int_eq(noctWorldSetTrack(w, ib, NULL, 0, NULL), NOCT_OK);
        noctTransform x = k[1].x;
        x.q = (noctQuat){0, 0, 0, 1};
        ck_assert_int_eq(noctWorldSetTransform(w, ib, &x, NULL), NOCT_OK);
        ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
        const noctPair *p;
        ck_assert_int_eq(noctWorldColliding(w, &p), (level ? 1 : 0));
        const noctSweepHit *hits;
        size_t nh;
        ck_assert_int_eq(noctWorldBeganHits(w, &hits, &nh, NULL), NOCT_OK);
        ck_assert_uint_eq(nh, level ? 1u : 0u);
        if (level)
            ck_assert(hits[0].conservative);
        x.p[1] = -3;
        ck_assert_int_eq(noctWorldSetTransform(w, ib, &x, NULL), NOCT_OK);
        ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
        ck_assert_int_eq(noctWorldColliding(w, &p), 0);
        noctWorldDestroy(w);
    }
}
END_TEST

/* ---- 5: bad input --------------------------------------------------------------- */

START_TEST(bad_transforms)
{
    noctMesh *box, *ell = make_ell();
    ck_assert_int_eq(noctMeshCreateBox(1, 1, 1, &box, NULL), NOCT_OK);
    const noctTransform good = noctIdentityTransform();
    noctTransform turned = good;
    ck_assert_int_eq(noctQuatFromAxisAngle((const double[3]){1, 2, 3}, 70, &turned.q), NOCT_OK);
    noctTransform bad[10];
    for (int i = 0; i < 10; ++i)
        bad[i] = turned;
    bad[0].q.x = NAN;
    bad[1].q.w = INFINITY;
    bad[2].q = (noctQuat){0, 0, 0, 0};
    bad[3].q = (noctQuat){0, 0, 0, 2};
    bad[4].q = (noctQuat){1, 1, 1, 1};
    bad[5].q.w = -NAN;
    bad[6].p[1] = NAN;
    bad[7].p[2] = -INFINITY;
    bad[8].p[0] = 2e100;
    bad[9].q = (noctQuat){0, 0, 0, 1 + 1e-7}; /* within the tolerance: good */
    for (int i = 0; i < 10; ++i) {
        noctError want_err;
        const noctStatus want = noctTransformCheck(&bad[i], &want_err);
        ck_assert_int_eq(want == NOCT_OK, i == 9);
        for (int slot = 0; slot < 4; ++slot) {
            const noctTransform *x[4] = {&good, &turned, &good, &good};
            x[slot] = &bad[i];
            bool colliding = true;
            noctSweepHit hit;
            noctError err;
            const noctStatus st = noctCollideSweptTransformed(box, x[0], x[1], ell, x[2], x[3],
                                                              &colliding, &hit, NULL, &err);
            ck_assert_msg(st == want, "transform %d in slot %d: %s, noctTransformCheck %s", i,
                          slot, noctStatusString(st), noctStatusString(want));
            if (st != NOCT_OK)
                ck_assert_int_eq(err.status, want);
        }
    }
    /* the world: a NaN angular velocity or key is refused as the check says */
    noctWorld *w = continuous_world(NOCT_ACCURACY_CONTINUOUS,
                                    NOCT_EFFECT_MOTION | NOCT_EFFECT_SPIN | NOCT_EFFECT_TRACK);
    noctObjectDef d = noctDefaultObjectDef();
    d.mesh = ell;
    noctObjectId id;
    ck_assert_int_eq(noctWorldCreateObject(w, &d, &id, NULL), NOCT_OK);
    for (int i = 0; i < 9; ++i) {
        if (i >= 6)
            continue; /* translations: no quaternion to give */
        double R[9];
        ck_assert_int_eq(noctWorldSetAngularVelocity(w, id, &bad[i].q, NULL),
                         noctQuatToMatrix(&bad[i].q, R, NULL));
    }
    for (int i = 0; i < 10; ++i) {
        noctKeyframe k[2] = {{0, good}, {3, bad[i]}};
        ck_assert_int_eq(noctWorldSetTrack(w, id, k, 2, NULL), noctTransformCheck(&bad[i], NULL));
    }
    /* the world still steps */
    for (int step = 0; step < 4; ++step)
        ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    noctWorldDestroy(w);
    noctMeshDestroy(box);
    noctMeshDestroy(ell);
}
END_TEST

static Suite *turning_suite(void)
{
    Suite *s = suite_create("turning");
    TCase *tc = test_case(s, "turning", 300, NULL);
    tcase_add_loop_test(tc, never_misses_reports_only_near, 0, 1);
    tcase_add_loop_test(tc, grazing_contacts, 0, 1);
    add_tests(tc, without_a_turn_it_is_the_swept_test, a_spinning_bar_sweeps_a_cube,
              a_keyframed_bar_turns_through_a_thin_wall, bad_transforms);
    TCase *full = test_case(s, "turning, full", 600, "slow seeds");
    tcase_add_loop_test(full, never_misses_reports_only_near, 1, 2);
    tcase_add_loop_test(full, grazing_contacts, 1, 2);
    return s;
}

int main(void)
{
    return run_suite(turning_suite());
}
