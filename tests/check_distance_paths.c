/* SPDX-License-Identifier: MIT */
/*
 * noctDistance()'s fast paths against independent expectations:
 * - the convex path (GJK, proved by its direction) against the general
 *   path on the same solid: a convex mesh, and the same mesh with a small
 *   hollow pyramid far behind it (not convex, so the general path
 *   answers, and the pyramid is never nearest): the intervals overlap,
 *   each is within the documented accuracy, and the stats say which path
 *   answered;
 * - the general search (nearest pairs first, pruned) against a brute
 *   force over every pair of placed triangles, in long double, on convex
 *   and non-convex meshes: the brute force's distance lies in
 *   [lower, upper] (within its own rounding), and the points lie on the
 *   named triangles;
 * - at sizes 1e-100, 1 and 1e98 and at offsets up to 2^40 of the size;
 * - swapped arguments: the same numbers, the points and triangles
 *   swapped, bit for bit;
 * - max_distance: beyond (lower = max_distance, upper infinite) below the
 *   distance, the same interval as without it above;
 * - touching and crossing solids: 0 exactly.
 */
#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <noctree/mesh.h>
#include <noctree/narrowphase.h>
#include <noctree/transform.h>

#include "testutil.h"

static uint64_t rng = 20261127;

static double urand(void)
{
    return test_uniform(&rng);
}

/* ---- meshes ------------------------------------------------------------------- */

typedef struct shape {
    double *v;
    size_t nv;
    uint32_t *idx;
    size_t nt;
} shape;

/* A UV sphere of n segments and m rings (triangles), radius scaled by sc
 * and multiplied by 1 + bump (smooth noise): convex with bump 0. */
static shape uv_sphere(int n, int m, const double sc[3], double bump)
{
    shape s;
    s.nv = 2 + (size_t)n * (size_t)(m - 1);
    s.nt = 2 * (size_t)n * (size_t)(m - 1);
    s.v = malloc(3 * s.nv * sizeof *s.v);
    s.idx = malloc(3 * s.nt * sizeof *s.idx);
    ck_assert(s.v != NULL && s.idx != NULL);
    const double pi = 3.14159265358979323846;
    size_t k = 0;
    for (int r = 0; r <= m; ++r) {
        const double th = pi * r / m;
        for (int q = 0; q < (r == 0 || r == m ? 1 : n); ++q) {
            const double ph = 2 * pi * q / n;
            const double rad = 1 + bump * sin(3 * th) * cos(4 * ph);
            s.v[3 * k] = sc[0] * rad * sin(th) * cos(ph);
            s.v[3 * k + 1] = sc[1] * rad * sin(th) * sin(ph);
            s.v[3 * k + 2] = sc[2] * rad * cos(th);
            ++k;
        }
    }
    size_t t = 0;
    for (int q = 0; q < n; ++q) {
        const uint32_t a = (uint32_t)(1 + q), b = (uint32_t)(1 + (q + 1) % n);
        s.idx[3 * t] = 0, s.idx[3 * t + 1] = a, s.idx[3 * t + 2] = b, ++t;
        const uint32_t base = (uint32_t)(1 + (m - 2) * n), last = (uint32_t)(s.nv - 1);
        s.idx[3 * t] = last, s.idx[3 * t + 1] = base + (uint32_t)((q + 1) % n);
        s.idx[3 * t + 2] = base + (uint32_t)q, ++t;
    }
    for (int r = 1; r + 1 < m; ++r)
        for (int q = 0; q < n; ++q) {
            const uint32_t a = (uint32_t)(1 + (r - 1) * n + q);
            const uint32_t b = (uint32_t)(1 + (r - 1) * n + (q + 1) % n);
            const uint32_t c = a + (uint32_t)n, d = b + (uint32_t)n;
            s.idx[3 * t] = a, s.idx[3 * t + 1] = c, s.idx[3 * t + 2] = b, ++t;
            s.idx[3 * t] = b, s.idx[3 * t + 1] = c, s.idx[3 * t + 2] = d, ++t;
        }
    ck_assert_uint_eq(t, s.nt);
    return s;
}

/* A box of half-extents h as 12 triangles. */
static shape box_shape(const double h[3])
{
    shape s = {malloc(3 * 12 * sizeof(double)), 8, malloc(3 * 16 * sizeof(uint32_t)), 12};
    ck_assert(s.v != NULL && s.idx != NULL);
    for (int i = 0; i < 8; ++i)
        for (int k = 0; k < 3; ++k)
            s.v[3 * i + k] = (i >> (2 - k) & 1) ? h[k] : -h[k];
    static const uint32_t q[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                                     {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    for (int f = 0; f < 6; ++f) {
        const uint32_t t[6] = {q[f][0], q[f][1], q[f][2], q[f][0], q[f][2], q[f][3]};
        memcpy(&s.idx[6 * f], t, sizeof t);
    }
    return s;
}

/* The far component: a small pyramid with a pyramid-shaped hollow under
 * it (not convex at its inner edges), 5 vertices, 6 triangles. */
#define FAR_NV 5
#define FAR_NT 6
static const double far_v[FAR_NV][3] = {{0, 0, 0}, {0.1, 0, 0}, {0, 0.1, 0},
                                        {0.02, 0.02, 0.1}, {0.02, 0.02, 0.03}};
static const uint32_t far_t[FAR_NT][3] = {{0, 1, 3}, {1, 2, 3}, {2, 0, 3},
                                          {1, 0, 4}, {2, 1, 4}, {0, 2, 4}};

/* The mesh of s with every vertex times size (a power of ten or one),
 * with (far) a small hollow pyramid added at far, which makes it non-convex
 * without changing what is nearest another mesh near s. */
static noctMesh *mesh_of(const shape *s, double size, const double *far)
{
    double *v = malloc(3 * (s->nv + FAR_NV) * sizeof *v);
    uint32_t *sizes = malloc((s->nt + FAR_NT) * sizeof *sizes);
    uint32_t *idx = malloc(3 * (s->nt + FAR_NT) * sizeof *idx);
    ck_assert(v != NULL && sizes != NULL && idx != NULL);
    for (size_t i = 0; i < 3 * s->nv; ++i)
        v[i] = s->v[i] * size;
    memcpy(idx, s->idx, 3 * s->nt * sizeof *idx);
    size_t nv = s->nv, nt = s->nt;
    if (far) {
        for (int i = 0; i < FAR_NV; ++i)
            for (int k = 0; k < 3; ++k)
                v[3 * (nv + (size_t)i) + k] = (far[k] + far_v[i][k]) * size;
        for (int i = 0; i < FAR_NT; ++i)
            for (int k = 0; k < 3; ++k)
                idx[3 * (nt + (size_t)i) + k] = (uint32_t)nv + far_t[i][k];
        nv += FAR_NV;
        nt += FAR_NT;
    }
    for (size_t i = 0; i < nt; ++i)
        sizes[i] = 3;
    noctMesh *m = NULL;
    noctError err;
    const noctStatus st = noctMeshCreate(v, nv, sizes, nt, idx, &m, &err);
    ck_assert_msg(st == NOCT_OK, "mesh: %s", err.message);
    free(v);
    free(sizes);
    free(idx);
    return m;
}

static void free_shape(shape *s)
{
    free(s->v);
    free(s->idx);
}

/* ---- the brute force ------------------------------------------------------------ */

typedef long double ld;

/* A mesh's vertices placed as noctDistance() places them: fl(fl(R v) +
 * t), each product rounded, the sums in the order (a + b) + c. */
typedef struct placed_mesh {
    size_t nv, nt;
    double *v;
    uint32_t *tri;
} placed_mesh;

static placed_mesh place(const shape *s, double size, const double *far,
                         const noctTransform *x)
{
    noctMesh *m = mesh_of(s, size, far);
    placed_mesh p;
    p.nv = s->nv + (far ? FAR_NV : 0);
    p.nt = s->nt + (far ? FAR_NT : 0);
    p.v = malloc(3 * p.nv * sizeof *p.v);
    p.tri = malloc(3 * p.nt * sizeof *p.tri);
    ck_assert(p.v != NULL && p.tri != NULL);
    double R[9];
    ck_assert(noctQuatToMatrix(&x->q, R, NULL) == NOCT_OK);
    for (size_t i = 0; i < p.nv; ++i) {
        double u[3];
        for (int k = 0; k < 3; ++k)
            u[k] = s->v[3 * (i < s->nv ? i : 0) + k] * size;
        if (i >= s->nv)
            for (int k = 0; k < 3; ++k)
                u[k] = (far[k] + far_v[i - s->nv][k]) * size;
        for (int r = 0; r < 3; ++r) {
            volatile double a = R[3 * r] * u[0], b = R[3 * r + 1] * u[1],
                            c = R[3 * r + 2] * u[2];
            p.v[3 * i + r] = (a + b) + c + x->p[r];
        }
    }
    memcpy(p.tri, s->idx, 3 * s->nt * sizeof *p.tri);
    for (size_t i = s->nt; i < p.nt; ++i)
        for (int k = 0; k < 3; ++k)
            p.tri[3 * i + k] = (uint32_t)s->nv + far_t[i - s->nt][k];
    noctMeshDestroy(m);
    return p;
}

static void free_placed(placed_mesh *p)
{
    free(p->v);
    free(p->tri);
}

static double magnitude(const placed_mesh *p)
{
    double s = 0;
    for (size_t i = 0; i < 3 * p->nv; ++i)
        s = fmax(s, fabs(p->v[i]));
    return s;
}

/* A power of two that brings magnitude m near 1: the brute force works on
 * coordinates so scaled (exactly), since its products of up to four
 * coordinates would leave double's range at 1e-100 or 1e98, and long
 * double is double under valgrind. */
static ld unit_scale(double m)
{
    return m > 0 ? ldexpl(1, -ilogb(m)) : 1;
}

/* The least distance over all pairs of placed triangles, in long double. */
static ld brute_distance(const placed_mesh *a, const placed_mesh *b)
{
    const ld sc = unit_scale(fmax(magnitude(a), magnitude(b)));
    ld best = INFINITY;
    for (size_t i = 0; i < a->nt; ++i) {
        ld x[3][3];
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 3; ++k)
                x[c][k] = a->v[3 * a->tri[3 * i + c] + k] * sc;
        for (size_t j = 0; j < b->nt; ++j) {
            ld y[3][3];
            for (int c = 0; c < 3; ++c)
                for (int k = 0; k < 3; ++k)
                    y[c][k] = b->v[3 * b->tri[3 * j + c] + k] * sc;
            const ld d = test_tri_tri2(x, y);
            best = d < best ? d : best;
        }
    }
    return sqrtl(best) / sc;
}

/* Distance from p to the placed triangle with these vertex indices. */
static ld point_tri_distance(const placed_mesh *m, const uint32_t t[3], const double p[3])
{
    const ld sc = unit_scale(magnitude(m));
    ld x[3][3], q[3] = {p[0] * sc, p[1] * sc, p[2] * sc};
    for (int c = 0; c < 3; ++c) {
        ck_assert_uint_lt(t[c], m->nv);
        for (int k = 0; k < 3; ++k)
            x[c][k] = m->v[3 * t[c] + k] * sc;
    }
    ld best = test_point_face2(q, x[0], x[1], x[2]);
    for (int e = 0; e < 3; ++e) {
        const ld d = test_point_seg2(q, x[e], x[(e + 1) % 3]);
        best = d < best ? d : best;
    }
    return sqrtl(best) / sc;
}

/* ---- the checks ----------------------------------------------------------------- */

static noctDistanceResult distance(const noctMesh *a, const noctTransform *xa,
                                   const noctMesh *b, const noctTransform *xb, double maxd,
                                   noctNarrowStats *stats)
{
    noctDistanceResult r;
    noctError err;
    const noctStatus st = noctDistance(a, xa, b, xb, maxd, &r, stats, &err);
    ck_assert_msg(st == NOCT_OK, "noctDistance: %s", err.message);
    return r;
}

/* r holds the true distance ref (within the brute force's rounding, eps)
 * and is as accurate as documented; its points lie on its triangles. */
static void expect_sound(const noctDistanceResult *r, ld ref, double mag, double eps,
                         const placed_mesh *pa, const placed_mesh *pb)
{
    ck_assert(!r->colliding && !r->beyond);
    ck_assert_msg(r->lower <= ref + eps && ref <= r->upper + eps,
                  "[%.17g, %.17g] misses %.17Lg", r->lower, r->upper, ref);
    ck_assert(r->lower <= r->distance && r->distance <= r->upper);
    ck_assert_msg(r->upper - r->lower <= 0x1p-40 * fmax(mag, r->upper),
                  "width %g of magnitude %g", r->upper - r->lower, mag);
    ck_assert(point_tri_distance(pa, r->triangle_a, r->point_a) <= 0x1p-47 * mag);
    ck_assert(point_tri_distance(pb, r->triangle_b, r->point_b) <= 0x1p-47 * mag);
}

/* Swapping the meshes swaps the points and triangles, bit for bit. */
static void expect_mirror(const noctDistanceResult *r, const noctDistanceResult *s)
{
    ck_assert(memcmp(&r->distance, &s->distance, sizeof r->distance) == 0);
    ck_assert(memcmp(&r->lower, &s->lower, sizeof r->lower) == 0);
    ck_assert(memcmp(&r->upper, &s->upper, sizeof r->upper) == 0);
    ck_assert(memcmp(r->point_a, s->point_b, sizeof r->point_a) == 0);
    ck_assert(memcmp(r->point_b, s->point_a, sizeof r->point_b) == 0);
    ck_assert(memcmp(r->triangle_a, s->triangle_b, sizeof r->triangle_a) == 0);
    ck_assert(memcmp(r->triangle_b, s->triangle_a, sizeof r->triangle_b) == 0);
    ck_assert(r->colliding == s->colliding && r->beyond == s->beyond);
}

static const double sizes[3] = {1e-100, 1, 1e98};

/* A random pair placement: B at distance gap (in sizes) beyond the sum of
 * the two radii rad, in a random direction, at an offset of up to 2^40
 * sizes; both turned at random (or not). dir receives the direction. */
static void random_pair(double size, double rad, double gap, bool big_offset,
                        noctTransform *xa, noctTransform *xb, double dir[3])
{
    double n = 0;
    do {
        for (int k = 0; k < 3; ++k)
            dir[k] = 2 * urand() - 1;
        n = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    } while (n < 0.1 || n > 1);
    for (int k = 0; k < 3; ++k)
        dir[k] /= n;
    const double off = big_offset ? (size <= 1 ? 0x1p40 * size : 4 * size) : 0;
    *xa = noctIdentityTransform();
    *xb = noctIdentityTransform();
    for (int k = 0; k < 3; ++k) {
        xa->p[k] = off * (k == 0 ? 1 : 0.5);
        xb->p[k] = xa->p[k] + dir[k] * (rad + gap) * size;
    }
    if (urand() < 0.8)
        test_random_quat(&rng, &xa->q);
    if (urand() < 0.8)
        test_random_quat(&rng, &xb->q);
}

/* The convex path against the general path (the same solid with a far
 * hollow pyramid) and the brute force, for boxes and ellipsoids. */
START_TEST(convex_against_general)
{
    const double h1[3] = {0.5, 0.3, 0.7}, h2[3] = {0.4, 0.4, 0.2};
    const double e1[3] = {1, 0.6, 0.8}, e2[3] = {0.7, 0.9, 0.5};
    shape shapes[2][2] = {{box_shape(h1), box_shape(h2)},
                          {uv_sphere(10, 6, e1, 0), uv_sphere(12, 7, e2, 0)}};
    const double rads[2] = {sqrt(0.83) + sqrt(0.36), 1.1 + 0.95};
    int convex_answers = 0, total = 0;
    const int trials = test_rounds(12, 4); /* each gap (trial % 4) and offset (% 3) */
    for (int kind = 0; kind < 2; ++kind)
        for (int si = 0; si < 3; ++si)
            for (int trial = 0; trial < trials; ++trial) {
                const double size = sizes[si];
                const bool big = trial % 3 == 2;
                const double gap = trial % 4 == 0 ? 1e-3 : 0.05 + urand();
                noctTransform xa, xb;
                double dir[3];
                random_pair(size, rads[kind], gap, big, &xa, &xb, dir);
                /* the far pyramid: behind A, away from B */
                const double far[3] = {-dir[0] * 30, -dir[1] * 30, -dir[2] * 30};
                noctMesh *a = mesh_of(&shapes[kind][0], size, NULL);
                noctMesh *a2 = mesh_of(&shapes[kind][0], size, far);
                noctMesh *b = mesh_of(&shapes[kind][1], size, NULL);
                ck_assert(!noctMeshIsConvex(a2));
                noctNarrowStats sc = {0}, sg = {0};
                const noctDistanceResult rc = distance(a, &xa, b, &xb, INFINITY, &sc);
                const noctDistanceResult rg = distance(a2, &xa, b, &xb, INFINITY, &sg);
                ck_assert_uint_eq(sg.convex_tests, 0);
                convex_answers += sc.convex_tests == 1;
                ++total;
                placed_mesh pa = place(&shapes[kind][0], size, NULL, &xa);
                placed_mesh pa2 = place(&shapes[kind][0], size, far, &xa);
                placed_mesh pb = place(&shapes[kind][1], size, NULL, &xb);
                const double mag = fmax(magnitude(&pa), magnitude(&pb));
                const double mag2 = fmax(magnitude(&pa2), magnitude(&pb));
                if (rc.colliding || rg.colliding) {
                    ck_assert(rc.colliding && rg.colliding);
                } else {
                    const ld ref = brute_distance(&pa, &pb);
                    expect_sound(&rc, ref, mag, 0x1p-60 * mag, &pa, &pb);
                    expect_sound(&rg, ref, mag2, 0x1p-60 * mag2, &pa2, &pb);
                    /* the same solid's distance: overlapping intervals */
                    ck_assert(rc.lower <= rg.upper && rg.lower <= rc.upper);
                    ck_assert(fabs(rc.distance - rg.distance) <= 0x1p-40 * mag2);
                }
                noctNarrowStats ss = {0};
                const noctDistanceResult rs = distance(b, &xb, a, &xa, INFINITY, &ss);
                expect_mirror(&rc, &rs);
                ck_assert_uint_eq(ss.convex_tests, sc.convex_tests);
                free_placed(&pa);
                free_placed(&pa2);
                free_placed(&pb);
                noctMeshDestroy(a);
                noctMeshDestroy(a2);
                noctMeshDestroy(b);
            }
    /* the convex path answers nearly every separated pair */
    ck_assert_msg(convex_answers >= total * 3 / 4, "convex path %d of %d", convex_answers,
                  total);
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            free_shape(&shapes[i][j]);
}
END_TEST

/* The general search against the brute force on non-convex meshes, and
 * the box primitives' convex path against it. */
START_TEST(general_against_brute_force)
{
    const double one[3] = {1, 1, 1}, e[3] = {1, 0.7, 0.9};
    shape sa = uv_sphere(12, 7, one, 0.3), sb = uv_sphere(10, 8, e, 0.25);
    const int trials = test_rounds(10, 6); /* every gap (trial % 3) with each offset (% 2) */
    for (int si = 0; si < 3; ++si)
        for (int trial = 0; trial < trials; ++trial) {
            const double size = sizes[si];
            const double gap = trial % 3 == 0 ? 1e-4 : (trial % 3 == 1 ? 0.02 : 0.5 + urand());
            noctTransform xa, xb;
            double dir[3];
            random_pair(size, 2.3, gap, trial % 2 == 1, &xa, &xb, dir);
            noctMesh *a = mesh_of(&sa, size, NULL), *b = mesh_of(&sb, size, NULL);
            ck_assert(!noctMeshIsConvex(a));
            noctNarrowStats st = {0};
            const noctDistanceResult r = distance(a, &xa, b, &xb, INFINITY, &st);
            placed_mesh pa = place(&sa, size, NULL, &xa), pb = place(&sb, size, NULL, &xb);
            const double mag = fmax(magnitude(&pa), magnitude(&pb));
            if (!r.colliding) {
                const ld ref = brute_distance(&pa, &pb);
                expect_sound(&r, ref, mag, 0x1p-60 * mag, &pa, &pb);
                /* the search visits far fewer pairs than the brute force */
                ck_assert_uint_lt(st.triangle_pairs, pa.nt * pb.nt / 4);
            }
            const noctDistanceResult s = distance(b, &xb, a, &xa, INFINITY, NULL);
            expect_mirror(&r, &s);
            free_placed(&pa);
            free_placed(&pb);
            noctMeshDestroy(a);
            noctMeshDestroy(b);
        }
    free_shape(&sa);
    free_shape(&sb);
}
END_TEST

/* Box primitives (noctMeshCreateBox): the convex path answers, within
 * the accuracy of the brute force on their corners. */
START_TEST(box_primitives)
{
    const double h1[3] = {0.5, 0.5, 0.5}, h2[3] = {0.3, 0.8, 0.4};
    shape s1 = box_shape(h1), s2 = box_shape(h2);
    for (int trial = 0; trial < 40; ++trial) {
        noctMesh *a = NULL, *b = NULL;
        ck_assert(noctMeshCreateBox(h1[0], h1[1], h1[2], &a, NULL) == NOCT_OK);
        ck_assert(noctMeshCreateBox(h2[0], h2[1], h2[2], &b, NULL) == NOCT_OK);
        noctTransform xa, xb;
        double dir[3];
        random_pair(1, sqrt(0.75) + sqrt(0.89), 0.01 + urand(), trial % 5 == 4, &xa, &xb, dir);
        noctNarrowStats st = {0};
        const noctDistanceResult r = distance(a, &xa, b, &xb, INFINITY, &st);
        ck_assert_uint_eq(st.convex_tests, 1);
        /* the brute force on the box's own triangles: the same solid */
        placed_mesh pa = place(&s1, 1, NULL, &xa), pb = place(&s2, 1, NULL, &xb);
        const double mag = fmax(magnitude(&pa), magnitude(&pb));
        const ld ref = brute_distance(&pa, &pb);
        ck_assert(r.lower <= ref + 0x1p-60 * mag && ref <= r.upper + 0x1p-60 * mag);
        ck_assert(r.upper - r.lower <= 0x1p-40 * fmax(mag, r.upper));
        ck_assert(fabsl(sqrtl(((ld)r.point_a[0] - r.point_b[0]) * (r.point_a[0] - r.point_b[0]) +
                              ((ld)r.point_a[1] - r.point_b[1]) * (r.point_a[1] - r.point_b[1]) +
                              ((ld)r.point_a[2] - r.point_b[2]) * (r.point_a[2] - r.point_b[2])) -
                        ref) <= 0x1p-45 * mag);
        const noctDistanceResult s = distance(b, &xb, a, &xa, INFINITY, NULL);
        expect_mirror(&r, &s);
        free_placed(&pa);
        free_placed(&pb);
        noctMeshDestroy(a);
        noctMeshDestroy(b);
    }
    free_shape(&s1);
    free_shape(&s2);
}
END_TEST

/* max_distance: beyond below the distance; above it, the interval is the
 * unlimited one's (within the accuracy). Both paths. */
START_TEST(beyond_and_max_distance)
{
    const double h[3] = {0.5, 0.5, 0.5}, one[3] = {1, 1, 1};
    shape shapes[2] = {box_shape(h), uv_sphere(12, 7, one, 0.3)};
    for (int kind = 0; kind < 2; ++kind)
        for (int trial = 0; trial < 8; ++trial) {
            noctMesh *a = mesh_of(&shapes[kind], 1, NULL), *b = mesh_of(&shapes[kind], 1, NULL);
            noctTransform xa, xb;
            double dir[3];
            random_pair(1, kind ? 2.6 : 1.74, 0.2 + urand(), false, &xa, &xb, dir);
            const noctDistanceResult r = distance(a, &xa, b, &xb, INFINITY, NULL);
            ck_assert(!r.colliding && !r.beyond);
            const double mag = 4;
            const noctDistanceResult lo = distance(a, &xa, b, &xb, r.lower * 0.9, NULL);
            ck_assert(lo.beyond && !lo.colliding);
            ck_assert(lo.lower == r.lower * 0.9);
            ck_assert(isinf(lo.upper) && isinf(lo.distance));
            ck_assert_uint_eq(lo.triangle_a[0], NOCT_NO_TRIANGLE);
            const noctDistanceResult hi = distance(a, &xa, b, &xb, r.upper * 1.1, NULL);
            ck_assert(!hi.beyond);
            ck_assert(hi.lower <= r.upper && r.lower <= hi.upper);
            ck_assert(fabs(hi.distance - r.distance) <= 0x1p-40 * mag);
            /* 0: beyond, unless they touch */
            const noctDistanceResult z = distance(a, &xa, b, &xb, 0, NULL);
            ck_assert(z.beyond && z.lower == 0);
            noctMeshDestroy(a);
            noctMeshDestroy(b);
        }
    free_shape(&shapes[0]);
    free_shape(&shapes[1]);
}
END_TEST

/* Touching and crossing solids: 0 exactly, whatever the path. */
START_TEST(touching_is_zero)
{
    noctMesh *a = NULL, *b = NULL;
    ck_assert(noctMeshCreateBox(0.5, 0.5, 0.5, &a, NULL) == NOCT_OK);
    ck_assert(noctMeshCreateBox(0.25, 0.5, 0.5, &b, NULL) == NOCT_OK);
    const double at[4] = {0.75, 0.5, 0.7, 0};
    for (int i = 0; i < 4; ++i) {
        noctTransform xa = noctIdentityTransform(), xb = noctIdentityTransform();
        xb.p[0] = at[i];
        xb.p[1] = i == 3 ? 0.3 : 0;
        noctNarrowStats st = {0};
        const noctDistanceResult r = distance(a, &xa, b, &xb, INFINITY, &st);
        ck_assert(r.colliding && !r.beyond);
        ck_assert(r.distance == 0 && r.lower == 0 && r.upper == 0);
        ck_assert_uint_eq(r.triangle_a[0], NOCT_NO_TRIANGLE);
        const noctDistanceResult z = distance(a, &xa, b, &xb, 0, NULL);
        ck_assert(z.colliding && !z.beyond && z.upper == 0);
    }
    /* just apart: not colliding, a tiny positive interval */
    noctTransform xa = noctIdentityTransform(), xb = noctIdentityTransform();
    xb.p[0] = 0.75 + 0x1p-30;
    const noctDistanceResult r = distance(a, &xa, b, &xb, INFINITY, NULL);
    ck_assert(!r.colliding);
    ck_assert(r.lower <= 0x1p-30 && 0x1p-30 <= r.upper);
    ck_assert(r.upper - r.lower <= 0x1p-40);
    noctMeshDestroy(a);
    noctMeshDestroy(b);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("distance_paths");
    TCase *tc = tcase_create("paths");
    tcase_set_timeout(tc, 600);
    tcase_add_test(tc, convex_against_general);
    tcase_add_test(tc, general_against_brute_force);
    tcase_add_test(tc, box_primitives);
    tcase_add_test(tc, beyond_and_max_distance);
    tcase_add_test(tc, touching_is_zero);
    suite_add_tcase(s, tc);
    return run_suite(s);
}
