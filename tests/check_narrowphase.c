/* SPDX-License-Identifier: MIT */
/*
 * Check suite for meshes and the narrowphase (mesh.h, narrowphase.h).
 *
 * Oracles, independent of the library:
 *  - hard cases built from exact coordinates whose answer is known by
 *    construction (touching faces, edges crossing at a point, a vertex on a
 *    face, coplanar faces, containment, tilted boxes resting on a face with
 *    the gap read off the placed vertices);
 *  - the separating-axis theorem in exact integer arithmetic, for random
 *    tetrahedra and boxes with small integer coordinates (where touching is
 *    common), and for random non-convex star-shaped meshes through their
 *    decomposition into cone tetrahedra.
 * Each hard case is also checked with the objects swapped, both moved by
 * exact offsets, and the mesh's vertices and polygons listed in another
 * order; and at every level for the documented one-sided errors.
 */
#define _POSIX_C_SOURCE 200809L
#include <check.h>
#include <limits.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <noctree/mesh.h>
#include <noctree/narrowphase.h>

#include "testutil.h"

/* ---- building meshes ------------------------------------------------------- */

typedef struct poly_list {
    double v[64 * 3];
    size_t nv;
    uint32_t sizes[64];
    uint32_t idx[256];
    size_t np, ni;
} poly_list;

static void pl_vertex(poly_list *p, double x, double y, double z)
{
    p->v[3 * p->nv] = x;
    p->v[3 * p->nv + 1] = y;
    p->v[3 * p->nv + 2] = z;
    p->nv++;
}

static void pl_poly(poly_list *p, int n, const uint32_t *c)
{
    p->sizes[p->np++] = (uint32_t)n;
    for (int i = 0; i < n; ++i)
        p->idx[p->ni++] = c[i];
}

/* The list with vertices renumbered by a random permutation, polygons in a
 * random order, each polygon starting at a random corner if 'rotate'. */
static poly_list pl_shuffle(const poly_list *p, uint64_t *rng, bool rotate)
{
    poly_list q = {0};
    uint32_t perm[64], order[64], start[64];
    for (size_t i = 0; i < p->nv; ++i)
        perm[i] = (uint32_t)i;
    for (size_t i = p->nv; i > 1; --i) {
        size_t j = test_rand_below(rng, i);
        uint32_t t = perm[i - 1]; perm[i - 1] = perm[j]; perm[j] = t;
    }
    q.nv = p->nv;
    for (size_t i = 0; i < p->nv; ++i)
        memcpy(&q.v[3 * perm[i]], &p->v[3 * i], 3 * sizeof(double));
    size_t base = 0;
    for (size_t i = 0; i < p->np; ++i) {
        order[i] = (uint32_t)i;
        start[i] = (uint32_t)base;
        base += p->sizes[i];
    }
    for (size_t i = p->np; i > 1; --i) {
        size_t j = test_rand_below(rng, i);
        uint32_t t = order[i - 1]; order[i - 1] = order[j]; order[j] = t;
    }
    for (size_t k = 0; k < p->np; ++k) {
        uint32_t pi = order[k], n = p->sizes[pi], c[16];
        size_t r = rotate ? test_rand_below(rng, n) : 0;
        for (uint32_t i = 0; i < n; ++i)
            c[i] = perm[p->idx[start[pi] + (i + r) % n]];
        pl_poly(&q, (int)n, c);
    }
    return q;
}

static noctMesh *pl_mesh(const poly_list *p)
{
    noctMesh *m = NULL;
    noctError err;
    noctStatus st = noctMeshCreate(p->v, p->nv, p->sizes, p->np, p->idx, &m, &err);
    ck_assert_msg(st == NOCT_OK, "mesh: %s", st == NOCT_OK ? "" : err.message);
    return m;
}

/* Axis-aligned box [lo, hi] as 6 quads. */
static poly_list pl_box(const double lo[3], const double hi[3])
{
    poly_list p = {0};
    for (int i = 0; i < 8; ++i)
        pl_vertex(&p, (i & 4) ? hi[0] : lo[0], (i & 2) ? hi[1] : lo[1],
                  (i & 1) ? hi[2] : lo[2]);
    static const uint32_t q[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                                     {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    for (int f = 0; f < 6; ++f)
        pl_poly(&p, 4, q[f]);
    return p;
}

/* Tetrahedron a b c d, oriented outward whatever the order given. */
static poly_list pl_tetra(const double pts[4][3])
{
    poly_list p = {0};
    for (int i = 0; i < 4; ++i)
        pl_vertex(&p, pts[i][0], pts[i][1], pts[i][2]);
    static const uint32_t f[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
    for (int i = 0; i < 4; ++i)
        pl_poly(&p, 3, f[i]); /* the library fixes an inside-out result */
    return p;
}

/* ---- checking a pair at every level ------------------------------------------ */

static bool collide(const noctMesh *a, const double ta[3], const noctMesh *b,
                    const double tb[3], noctAccuracy level)
{
    bool hit = false;
    noctStatus st = noctCollide(a, ta, b, tb, level, &hit, NULL);
    ck_assert_msg(st == NOCT_OK, "noctCollide: %s", noctStatusString(st));
    return hit;
}

/* The exact answer must be want, both ways round; box must not miss it;
 * the convex level must not miss it unless the contact is a mere touch
 * (deep says whether it is more). */
static void expect_pair(const noctMesh *a, const double ta[3], const noctMesh *b,
                        const double tb[3], bool want, bool deep)
{
    bool ab = collide(a, ta, b, tb, NOCT_ACCURACY_EXACT);
    bool ba = collide(b, tb, a, ta, NOCT_ACCURACY_EXACT);
    ck_assert_msg(ab == want && ba == want, "exact: got %d/%d, want %d", ab, ba,
                  want);
    bool box = collide(a, ta, b, tb, NOCT_ACCURACY_BOX);
    bool cvx = collide(a, ta, b, tb, NOCT_ACCURACY_CONVEX);
    ck_assert_int_eq(cvx, collide(b, tb, a, ta, NOCT_ACCURACY_CONVEX));
    if (want) {
        ck_assert_msg(box, "box level missed a collision");
        if (deep)
            ck_assert_msg(cvx, "convex level missed a deep collision");
    }
}

/* Moving both objects by off changes nothing exactly iff every placed
 * coordinate fl(v + t) gains off without rounding and t + off is exact. */
static bool offset_exact(const poly_list *p, const double t[3], double off)
{
    for (int k = 0; k < 3; ++k) {
        double to = t[k] + off;
        if (to - off != t[k])
            return false;
        for (size_t i = 0; i < p->nv; ++i) {
            double placed = p->v[3 * i + k] + t[k];
            if (placed + off != p->v[3 * i + k] + to || (placed + off) - off != placed)
                return false;
        }
    }
    return true;
}

/* A hard case: meshes from poly lists, translations, the known answer.
 * Checked as given, swapped, moved by every offset that is exact for the
 * case (at least one must be), and shuffled. */
static void hard_case(const poly_list *pa, const double ta[3], const poly_list *pb,
                      const double tb[3], bool want, bool deep, bool dyadic)
{
    noctMesh *a = pl_mesh(pa), *b = pl_mesh(pb);
    expect_pair(a, ta, b, tb, want, deep);
    if (dyadic) {
        static const double offsets[] = {0x1p40, 1e6, 1 << 20, 1024, -3, 1, 0x1p-8,
                                         0x1p-30};
        int applied = 0;
        for (size_t i = 0; i < sizeof offsets / sizeof *offsets; ++i) {
            double off = offsets[i];
            if (!offset_exact(pa, ta, off) || !offset_exact(pb, tb, off))
                continue;
            double oa[3] = {ta[0] + off, ta[1] + off, ta[2] + off};
            double ob[3] = {tb[0] + off, tb[1] + off, tb[2] + off};
            expect_pair(a, oa, b, ob, want, deep);
            ++applied;
        }
        ck_assert_msg(applied > 0, "no exact offset for this case");
    }
    uint64_t rng = 4242;
    for (int s = 0; s < 4; ++s) {
        poly_list qa = pl_shuffle(pa, &rng, true), qb = pl_shuffle(pb, &rng, true);
        noctMesh *sa = pl_mesh(&qa), *sb = pl_mesh(&qb);
        expect_pair(sa, ta, sb, tb, want, deep);
        noctMeshDestroy(sa);
        noctMeshDestroy(sb);
    }
    noctMeshDestroy(a);
    noctMeshDestroy(b);
}

static const double ORIGIN[3] = {0, 0, 0};

/* ---- hard cases -------------------------------------------------------------- */

START_TEST(faces_exactly_touching)
{
    /* Sizes from 1/128 to 1024: unit cube scaled, the second one exactly
     * one edge length along x (touching), or 2^-40 of it further. */
    for (int e = -7; e <= 10; e += 1) {
        double s = ldexp(1, e);
        double lo[3] = {-s / 2, -s / 2, -s / 2}, hi[3] = {s / 2, s / 2, s / 2};
        poly_list box = pl_box(lo, hi);
        double touch[3] = {s, 0, 0}, gap[3] = {s + ldexp(s, -40), 0, 0};
        double deep[3] = {s / 2, s / 4, 0};
        hard_case(&box, ORIGIN, &box, touch, true, false, true);
        hard_case(&box, ORIGIN, &box, gap, false, false, true);
        hard_case(&box, ORIGIN, &box, deep, true, true, true);
    }
}
END_TEST

START_TEST(edges_crossing_at_a_point)
{
    /* A's top edge runs along x at z = 0, B's bottom edge along y at z = 0:
     * they cross at the origin and touch nowhere else. */
    const double a[4][3] = {{-1, 0, 0}, {1, 0, 0}, {0, 1, -1}, {0, -1, -1}};
    const double b[4][3] = {{0, -1, 0}, {0, 1, 0}, {1, 0, 1}, {-1, 0, 1}};
    poly_list pa = pl_tetra(a), pb = pl_tetra(b);
    hard_case(&pa, ORIGIN, &pb, ORIGIN, true, false, true);
    const double up[3] = {0, 0, 0x1p-50}, down[3] = {0, 0, -0x1p-50};
    hard_case(&pa, ORIGIN, &pb, up, false, false, true);
    hard_case(&pa, ORIGIN, &pb, down, true, false, true);
    /* Moved sideways along B's edge the crossing point stays on both. */
    const double side[3] = {0, 0.5, 0};
    hard_case(&pa, ORIGIN, &pb, side, true, false, true);
}
END_TEST

START_TEST(vertex_exactly_on_face)
{
    double lo[3] = {-1, -1, -1}, hi[3] = {1, 1, 0.5};
    poly_list box = pl_box(lo, hi);
    /* Apex down at (0.25, 0.125, 0.5), exactly on the box's top face. */
    const double t[4][3] = {{0.25, 0.125, 0.5}, {1.25, 0.125, 1.5},
                            {-0.75, 1.125, 1.5}, {-0.75, -0.875, 1.5}};
    poly_list tet = pl_tetra(t);
    hard_case(&box, ORIGIN, &tet, ORIGIN, true, false, true);
    const double up[3] = {0, 0, 0x1p-52}, down[3] = {0, 0, -0x1p-52};
    hard_case(&box, ORIGIN, &tet, up, false, false, true);
    hard_case(&box, ORIGIN, &tet, down, true, false, true);
    /* On the face's edge and on its corner. */
    const double to_edge[3] = {0.75, 0, 0}, to_corner[3] = {0.75, 0.875, 0};
    hard_case(&box, ORIGIN, &tet, to_edge, true, false, true);
    hard_case(&box, ORIGIN, &tet, to_corner, true, false, true);
    const double beyond[3] = {0.75 + 0x1p-50, 0.875, 0};
    hard_case(&box, ORIGIN, &tet, beyond, false, false, true);
}
END_TEST

START_TEST(coplanar_overlapping_faces)
{
    double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
    poly_list box = pl_box(lo, hi);
    /* Stacked, sharing part of the z = 1 plane; and side by side sharing
     * only an edge; and only a corner. */
    const double stacked[3] = {0.5, 0.25, 1}, edge[3] = {1, 0, 1},
                 corner[3] = {1, 1, 1}, apart[3] = {1, 1, 1 + 0x1p-52};
    hard_case(&box, ORIGIN, &box, stacked, true, false, true);
    hard_case(&box, ORIGIN, &box, edge, true, false, true);
    hard_case(&box, ORIGIN, &box, corner, true, false, true);
    hard_case(&box, ORIGIN, &box, apart, false, false, true);
    /* Coplanar triangles of two tetrahedra in z = 0 overlapping. */
    const double a[4][3] = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, -2}};
    const double b[4][3] = {{1, 1, 0}, {5, 1, 0}, {1, 5, 0}, {2, 2, 3}};
    poly_list pa = pl_tetra(a), pb = pl_tetra(b);
    hard_case(&pa, ORIGIN, &pb, ORIGIN, true, false, true);
    const double away[3] = {3, 3, 0};
    hard_case(&pa, ORIGIN, &pb, away, false, false, true);
}
END_TEST

START_TEST(parallel_and_nearly_parallel)
{
    /* Parallel edges one ulp apart, and a face tilted by 2^-40 over another. */
    const double a[4][3] = {{-1, 0, 0}, {1, 0, 0}, {0, 1, -1}, {0, -1, -1}};
    const double b[4][3] = {{-1, 0, 0x1p-52}, {1, 0, 0x1p-52}, {0, 1, 1}, {0, -1, 1}};
    poly_list pa = pl_tetra(a), pb = pl_tetra(b);
    hard_case(&pa, ORIGIN, &pb, ORIGIN, false, false, true);
    const double b2[4][3] = {{-1, 0, 0}, {1, 0, 0}, {0, 1, 1}, {0, -1, 1}};
    poly_list pb2 = pl_tetra(b2);
    hard_case(&pa, ORIGIN, &pb2, ORIGIN, true, false, true);
    double lo[3] = {-1, -1, -1}, hi[3] = {1, 1, 0};
    poly_list box = pl_box(lo, hi);
    const double tilt[4][3] = {{-1, -1, 0x1p-40}, {1, -1, 0}, {1, 1, 0x1p-40},
                               {0, 0, 1}};
    poly_list pt = pl_tetra(tilt);
    hard_case(&box, ORIGIN, &pt, ORIGIN, true, false, true); /* touches at (1,-1,0) */
    const double lift[3] = {0, 0, 0x1p-60};
    hard_case(&box, ORIGIN, &pt, lift, false, false, true);
}
END_TEST

/* A box tilted about two axes rests its lowest corner on an axis-aligned
 * slab's top face. Its corners are rounded, so the truth is read off the
 * placed vertices exactly as the library places them: it collides iff its
 * lowest placed vertex is at or below the face. Gaps of a few ulps,
 * about 1e-15 of the size, at sizes 0.01 to 1000. */
START_TEST(tilted_boxes_near_contact)
{
    const double c = cos(0.3), s = sin(0.3), c2 = cos(0.7), s2 = sin(0.7);
    /* R = Rx(0.7) * Ry(0.3) */
    const double rot[9] = {c, 0, s, s2 * s, c2, -s2 * c, -c2 * s, s2, c2 * c};
    static const double sizes[] = {0.01, 0.1, 1, 10, 1000};
    for (size_t si = 0; si < sizeof sizes / sizeof *sizes; ++si) {
        double h = sizes[si];
        const double half[3] = {h, 0.5 * h, 0.25 * h};
        noctMesh *tilted = NULL, *slab = NULL;
        ck_assert_int_eq(noctMeshCreateOrientedBox(half, rot, &tilted, NULL), NOCT_OK);
        ck_assert_int_eq(noctMeshCreateBox(8 * h, 8 * h, h, &slab, NULL), NOCT_OK);
        double lo[3], hi[3];
        noctMeshBounds(tilted, lo, hi);
        const double ts[3] = {0, 0, 0}; /* slab top at z = h */
        for (int k = -3; k <= 3; ++k) {
            double tb[3] = {0.125 * h, -0.25 * h, h - lo[2] + k * 0x1p-52 * h};
            /* The oracle: the lowest placed z against the face. */
            double lowest = INFINITY;
            double probe_t[3] = {tb[0], tb[1], tb[2]};
            for (int corner = 0; corner < 8; ++corner) {
                double loc[3] = {(corner & 4) ? half[0] : -half[0],
                                 (corner & 2) ? half[1] : -half[1],
                                 (corner & 1) ? half[2] : -half[2]};
                double z = rot[6] * loc[0] + rot[7] * loc[1] + rot[8] * loc[2];
                lowest = fmin(lowest, z + probe_t[2]);
            }
            bool want = lowest <= h;
            expect_pair(slab, ts, tilted, tb, want, false);
        }
        noctMeshDestroy(tilted);
        noctMeshDestroy(slab);
    }
}
END_TEST

START_TEST(tiny_and_far)
{
    /* 1e-6-sized boxes (2^-20), touching, apart, overlapping; then unit
     * boxes at 1e6, 2^40 and 1e15 from the origin. */
    double e = 0x1p-20;
    double lo[3] = {-e, -e, -e}, hi[3] = {e, e, e};
    poly_list tiny = pl_box(lo, hi);
    const double touch[3] = {2 * e, 0, 0}, apart[3] = {2 * e + 0x1p-70, 0, 0},
                 over[3] = {e, e, e};
    hard_case(&tiny, ORIGIN, &tiny, touch, true, false, true);
    hard_case(&tiny, ORIGIN, &tiny, apart, false, false, true);
    hard_case(&tiny, ORIGIN, &tiny, over, true, true, true);
    double ulo[3] = {-0.5, -0.5, -0.5}, uhi[3] = {0.5, 0.5, 0.5};
    poly_list unit = pl_box(ulo, uhi);
    static const double far[] = {1e6, 0x1p40, 1e15};
    for (size_t i = 0; i < 3; ++i) {
        double ta[3] = {far[i], -far[i], far[i]};
        double tt[3] = {far[i] + 1, -far[i], far[i]};
        double tg[3] = {far[i] + 1 + 2 * 0x1p-52 * far[i], -far[i], far[i]};
        hard_case(&unit, ta, &unit, tt, true, false, false);
        hard_case(&unit, ta, &unit, tg, false, false, false);
    }
}
END_TEST

START_TEST(containment_and_identity)
{
    double blo[3] = {-4, -4, -4}, bhi[3] = {4, 4, 4};
    double slo[3] = {-1, -1, -1}, shi[3] = {1, 1, 1};
    poly_list big = pl_box(blo, bhi), small = pl_box(slo, shi);
    const double inside[3] = {1.5, -2, 0.25};
    hard_case(&big, ORIGIN, &small, inside, true, true, true);
    /* Inside and touching the inner wall from within. */
    const double wall[3] = {3, 0, 0};
    hard_case(&big, ORIGIN, &small, wall, true, true, true);
    /* Identical solids in the same place. */
    hard_case(&small, ORIGIN, &small, ORIGIN, true, true, true);
    const double t[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    poly_list tet = pl_tetra(t);
    hard_case(&tet, ORIGIN, &tet, ORIGIN, true, true, true);
    /* A tetrahedron inside a box, its vertex only one ulp from a wall. */
    const double in[4][3] = {{-1 + 0x1p-52, 0, 0}, {0, 0.5, 0}, {0, 0, 0.5},
                             {0, -0.5, -0.5}};
    poly_list pin = pl_tetra(in);
    hard_case(&small, ORIGIN, &pin, ORIGIN, true, true, true);
}
END_TEST

/* ---- random convex pairs against exact SAT ---------------------------------- */

typedef struct ipoly {
    long long v[8][3];
    int nv;
    int faces[12][3]; /* outward triangles */
    int nf;
    int edges[18][2];
    int ne;
} ipoly;

static void cross_ll(const long long a[3], const long long b[3], long long out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

static void project(const ipoly *p, const long long ax[3], const long long t[3],
                    long long *lo, long long *hi)
{
    *lo = LLONG_MAX;
    *hi = LLONG_MIN;
    for (int i = 0; i < p->nv; ++i) {
        long long d = 0;
        for (int k = 0; k < 3; ++k)
            d += ax[k] * (p->v[i][k] + t[k]);
        if (d < *lo) *lo = d;
        if (d > *hi) *hi = d;
    }
}

/* Closed convex polytopes a + ta and b + tb intersect, by the separating
 * axis theorem over face normals and edge-pair cross products. */
static bool sat_intersect(const ipoly *a, const long long ta[3], const ipoly *b,
                          const long long tb[3])
{
    long long axes[64 + 324][3];
    int na = 0;
    const ipoly *ps[2] = {a, b};
    for (int s = 0; s < 2; ++s)
        for (int f = 0; f < ps[s]->nf; ++f) {
            const long long *p0 = ps[s]->v[ps[s]->faces[f][0]];
            const long long *p1 = ps[s]->v[ps[s]->faces[f][1]];
            const long long *p2 = ps[s]->v[ps[s]->faces[f][2]];
            long long u[3], w[3];
            for (int k = 0; k < 3; ++k) {
                u[k] = p1[k] - p0[k];
                w[k] = p2[k] - p0[k];
            }
            cross_ll(u, w, axes[na++]);
        }
    for (int i = 0; i < a->ne; ++i)
        for (int j = 0; j < b->ne; ++j) {
            long long u[3], w[3];
            for (int k = 0; k < 3; ++k) {
                u[k] = a->v[a->edges[i][1]][k] - a->v[a->edges[i][0]][k];
                w[k] = b->v[b->edges[j][1]][k] - b->v[b->edges[j][0]][k];
            }
            cross_ll(u, w, axes[na++]);
        }
    for (int i = 0; i < na; ++i) {
        if (axes[i][0] == 0 && axes[i][1] == 0 && axes[i][2] == 0)
            continue;
        long long alo, ahi, blo, bhi;
        project(a, axes[i], ta, &alo, &ahi);
        project(b, axes[i], tb, &blo, &bhi);
        if (ahi < blo || bhi < alo)
            return false;
    }
    return true;
}

static void ipoly_tetra(ipoly *p, uint64_t *rng, int range)
{
    for (;;) {
        for (int i = 0; i < 4; ++i)
            for (int k = 0; k < 3; ++k)
                p->v[i][k] = (long long)test_rand_below(rng, (size_t)(2 * range + 1)) - range;
        long long u[3], w[3], n[3], d = 0;
        for (int k = 0; k < 3; ++k) {
            u[k] = p->v[1][k] - p->v[0][k];
            w[k] = p->v[2][k] - p->v[0][k];
        }
        cross_ll(u, w, n);
        for (int k = 0; k < 3; ++k)
            d += n[k] * (p->v[3][k] - p->v[0][k]);
        if (d == 0)
            continue; /* flat: draw again */
        p->nv = 4;
        /* Orient so that each face's normal points away from the 4th vertex. */
        static const int f[4][3] = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {0, 2, 3}};
        static const int e[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
        p->nf = 4;
        for (int i = 0; i < 4; ++i) {
            p->faces[i][0] = f[i][0];
            p->faces[i][1] = d > 0 ? f[i][2] : f[i][1];
            p->faces[i][2] = d > 0 ? f[i][1] : f[i][2];
        }
        p->ne = 6;
        memcpy(p->edges, e, sizeof e);
        return;
    }
}

static noctMesh *ipoly_mesh(const ipoly *p)
{
    poly_list l = {0};
    for (int i = 0; i < p->nv; ++i)
        pl_vertex(&l, (double)p->v[i][0], (double)p->v[i][1], (double)p->v[i][2]);
    for (int f = 0; f < p->nf; ++f) {
        uint32_t c[3] = {(uint32_t)p->faces[f][0], (uint32_t)p->faces[f][1],
                         (uint32_t)p->faces[f][2]};
        pl_poly(&l, 3, c);
    }
    return pl_mesh(&l);
}

START_TEST(random_tetrahedra_against_sat)
{
    uint64_t rng = 31337 + (uint64_t)_i;
    int hits = 0, misses = 0;
    noctNarrowStats stats = {0};
    for (int trial = 0; trial < 400; ++trial) {
        ipoly a, b;
        ipoly_tetra(&a, &rng, 3);
        ipoly_tetra(&b, &rng, 3);
        long long ta[3] = {0, 0, 0}, tb[3];
        for (int k = 0; k < 3; ++k)
            tb[k] = (long long)test_rand_below(&rng, 7) - 3;
        bool want = sat_intersect(&a, ta, &b, tb);
        noctMesh *ma = ipoly_mesh(&a), *mb = ipoly_mesh(&b);
        double da[3] = {0, 0, 0}, db[3] = {(double)tb[0], (double)tb[1], (double)tb[2]};
        bool got = false;
        ck_assert_int_eq(noctCollide(ma, da, mb, db, NOCT_ACCURACY_EXACT, &got, &stats),
                         NOCT_OK);
        if (got != want)
            ck_abort_msg("trial %d: exact %d, SAT %d", trial, got, want);
        EXPECT(collide(mb, db, ma, da, NOCT_ACCURACY_EXACT) == want);
        if (want)
            EXPECT(collide(ma, da, mb, db, NOCT_ACCURACY_BOX));
        hits += want;
        misses += !want;
        noctMeshDestroy(ma);
        noctMeshDestroy(mb);
    }
    ck_assert_int_gt(hits, 40); /* both outcomes well represented */
    ck_assert_int_gt(misses, 40);
    /* Both ways to a hit were taken: a point proved inside both, and
     * (for touching integer tetrahedra, which share no inner point) the
     * triangle tests. */
    ck_assert_uint_gt(stats.witnesses, 0);
    ck_assert_uint_lt(stats.witnesses, (uint64_t)hits);
    ck_assert_uint_gt(stats.triangle_pairs, 0);
}
END_TEST

/* Tetrahedra whose bases lie in the plane z = 0, one apex below and one
 * above: they meet exactly where their bases overlap, so every answer goes
 * through the coplanar branch of the edge-triangle test. */
START_TEST(random_coplanar_bases_against_sat)
{
    uint64_t rng = 4711 + (uint64_t)_i;
    int hits = 0, misses = 0;
    for (int trial = 0; trial < 300; ++trial) {
        ipoly t[2];
        for (int s = 0; s < 2; ++s) {
            for (;;) {
                for (int i = 0; i < 3; ++i) {
                    t[s].v[i][0] = (long long)test_rand_below(&rng, 9) - 4;
                    t[s].v[i][1] = (long long)test_rand_below(&rng, 9) - 4;
                    t[s].v[i][2] = 0;
                }
                long long area = (t[s].v[1][0] - t[s].v[0][0]) * (t[s].v[2][1] - t[s].v[0][1]) -
                                 (t[s].v[1][1] - t[s].v[0][1]) * (t[s].v[2][0] - t[s].v[0][0]);
                if (area != 0)
                    break;
            }
            t[s].v[3][0] = (long long)test_rand_below(&rng, 5) - 2;
            t[s].v[3][1] = (long long)test_rand_below(&rng, 5) - 2;
            t[s].v[3][2] = s == 0 ? -3 : 3;
            t[s].nv = 4;
            static const int f[4][3] = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {0, 2, 3}};
            static const int e[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
            t[s].nf = 4;
            memcpy(t[s].faces, f, sizeof f);
            t[s].ne = 6;
            memcpy(t[s].edges, e, sizeof e);
        }
        const long long zero[3] = {0, 0, 0};
        bool want = sat_intersect(&t[0], zero, &t[1], zero);
        noctMesh *ma = ipoly_mesh(&t[0]), *mb = ipoly_mesh(&t[1]);
        bool got = collide(ma, ORIGIN, mb, ORIGIN, NOCT_ACCURACY_EXACT);
        if (got != want)
            ck_abort_msg("trial %d: exact %d, SAT %d", trial, got, want);
        EXPECT(collide(mb, ORIGIN, ma, ORIGIN, NOCT_ACCURACY_EXACT) == want);
        hits += want;
        misses += !want;
        noctMeshDestroy(ma);
        noctMeshDestroy(mb);
    }
    ck_assert_int_gt(hits, 30);
    ck_assert_int_gt(misses, 30);
}
END_TEST

/* ---- random non-convex star-shaped meshes ------------------------------------ */

/* A cube with corners (±2, ±2, ±2) whose 6 face centres sit at r (1 to 4)
 * along their axes: 24 triangles (corner, corner, centre). With r < 2 the
 * face is dented: the solid is not convex. It is star-shaped about the
 * origin, so it is exactly the union of the 24 tetrahedra (origin,
 * triangle). */
typedef struct star {
    long long v[14][3];
    int tri[24][3];
} star;

static void make_star(star *s, uint64_t *rng)
{
    for (int i = 0; i < 8; ++i) {
        s->v[i][0] = (i & 4) ? 2 : -2;
        s->v[i][1] = (i & 2) ? 2 : -2;
        s->v[i][2] = (i & 1) ? 2 : -2;
    }
    /* Faces: axis, sign, and the 4 corners counter-clockwise from outside. */
    static const int quad[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                                   {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    static const int axis[6] = {0, 0, 1, 1, 2, 2}, sign[6] = {-1, 1, -1, 1, -1, 1};
    for (int f = 0; f < 6; ++f) {
        long long r = 1 + (long long)test_rand_below(rng, 4);
        long long *c = s->v[8 + f];
        c[0] = c[1] = c[2] = 0;
        c[axis[f]] = sign[f] * r;
        for (int e = 0; e < 4; ++e) {
            s->tri[4 * f + e][0] = quad[f][e];
            s->tri[4 * f + e][1] = quad[f][(e + 1) % 4];
            s->tri[4 * f + e][2] = 8 + f;
        }
    }
}

static noctMesh *star_mesh(const star *s)
{
    poly_list l = {0};
    for (int i = 0; i < 14; ++i)
        pl_vertex(&l, (double)s->v[i][0], (double)s->v[i][1], (double)s->v[i][2]);
    for (int t = 0; t < 24; ++t) {
        uint32_t c[3] = {(uint32_t)s->tri[t][0], (uint32_t)s->tri[t][1],
                         (uint32_t)s->tri[t][2]};
        pl_poly(&l, 3, c);
    }
    return pl_mesh(&l);
}

static void cone(const star *s, int t, ipoly *p)
{
    memset(p, 0, sizeof *p);
    p->nv = 4;
    for (int k = 0; k < 3; ++k) {
        p->v[0][k] = 0;
        p->v[1][k] = s->v[s->tri[t][0]][k];
        p->v[2][k] = s->v[s->tri[t][1]][k];
        p->v[3][k] = s->v[s->tri[t][2]][k];
    }
    static const int f[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
    static const int e[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
    p->nf = 4;
    memcpy(p->faces, f, sizeof f); /* normals' sign is irrelevant to SAT */
    p->ne = 6;
    memcpy(p->edges, e, sizeof e);
}

START_TEST(random_star_meshes_against_cones)
{
    uint64_t rng = 777 + (uint64_t)_i;
    int hits = 0, misses = 0, nonconvex = 0;
    for (int trial = 0; trial < 30; ++trial) {
        star a, b;
        make_star(&a, &rng);
        make_star(&b, &rng);
        long long tb[3];
        for (int k = 0; k < 3; ++k)
            tb[k] = (long long)test_rand_below(&rng, 11) - 5;
        const long long ta[3] = {0, 0, 0};
        bool want = false;
        for (int i = 0; i < 24 && !want; ++i) {
            ipoly ca;
            cone(&a, i, &ca);
            for (int j = 0; j < 24 && !want; ++j) {
                ipoly cb;
                cone(&b, j, &cb);
                want = sat_intersect(&ca, ta, &cb, tb);
            }
        }
        noctMesh *ma = star_mesh(&a), *mb = star_mesh(&b);
        nonconvex += !noctMeshIsConvex(ma);
        double da[3] = {0, 0, 0}, db[3] = {(double)tb[0], (double)tb[1], (double)tb[2]};
        bool got = collide(ma, da, mb, db, NOCT_ACCURACY_EXACT);
        if (got != want)
            ck_abort_msg("trial %d: exact %d, cones %d", trial, got, want);
        EXPECT(collide(mb, db, ma, da, NOCT_ACCURACY_EXACT) == want);
        if (want) {
            EXPECT(collide(ma, da, mb, db, NOCT_ACCURACY_BOX));
        }
        hits += want;
        misses += !want;
        noctMeshDestroy(ma);
        noctMeshDestroy(mb);
    }
    ck_assert_int_gt(hits, 3);
    ck_assert_int_gt(misses, 3);
    ck_assert_int_gt(nonconvex, 10);
}
END_TEST

/* noctCollideTransformed() at the exact level decides turned meshes on
 * rotated views (vertices rotated, hierarchy refitted), not on rotated
 * meshes: its answers must be noctCollide()'s on meshes made of the
 * vertices placed as transform.h says, fl(fl(R0 v0 + R1 v1) + R2 v2).
 * The star meshes' triangles are large beside their coordinates; shifted
 * by 2^20 (integers: exact) each triangle is tiny beside the mesh's
 * distance from its origin, so the views check each rotated triangle. */
static noctMesh *star_rotated(const star *s, const double R[9], double shift)
{
    poly_list l = {0};
    for (int i = 0; i < 14; ++i) {
        double v[3], r[3];
        for (int k = 0; k < 3; ++k)
            v[k] = (double)s->v[i][k] + shift;
        for (int k = 0; k < 3; ++k)
            r[k] = (R[3 * k] * v[0] + R[3 * k + 1] * v[1]) + R[3 * k + 2] * v[2];
        pl_vertex(&l, r[0], r[1], r[2]);
    }
    for (int t = 0; t < 24; ++t) {
        uint32_t c[3] = {(uint32_t)s->tri[t][0], (uint32_t)s->tri[t][1],
                         (uint32_t)s->tri[t][2]};
        pl_poly(&l, 3, c);
    }
    return pl_mesh(&l);
}

START_TEST(turned_views_match_rotated_meshes)
{
    uint64_t rng = 4242 + (uint64_t)_i;
    const double shift = _i == 1 ? 0x1p20 : 0;
    int hits = 0, misses = 0;
    for (int trial = 0; trial < 200; ++trial) {
        star a, b;
        make_star(&a, &rng);
        make_star(&b, &rng);
        noctTransform xa = noctIdentityTransform(), xb = noctIdentityTransform();
        test_random_quat(&rng, &xa.q);
        if (trial % 4 != 0) /* sometimes only one of them turned */
            test_random_quat(&rng, &xb.q);
        double Ra[9], Rb[9];
        ck_assert_int_eq(noctQuatToMatrix(&xa.q, Ra, NULL), NOCT_OK);
        ck_assert_int_eq(noctQuatToMatrix(&xb.q, Rb, NULL), NOCT_OK);
        /* the shifted meshes' centres, rotated, brought back near 0 */
        for (int k = 0; k < 3; ++k) {
            xa.p[k] = -(Ra[3 * k] + Ra[3 * k + 1] + Ra[3 * k + 2]) * shift;
            xb.p[k] = -(Rb[3 * k] + Rb[3 * k + 1] + Rb[3 * k + 2]) * shift +
                      ((double)test_rand_below(&rng, 1u << 20) / 0x1p20 - 0.5) * 14;
        }
        noctMesh *ma = star_mesh(&a), *mb = star_mesh(&b);
        noctMesh *shifted_a = NULL, *shifted_b = NULL;
        if (shift != 0) {
            const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
            shifted_a = star_rotated(&a, I, shift);
            shifted_b = star_rotated(&b, I, shift);
        }
        noctMesh *ra = star_rotated(&a, Ra, shift), *rb = star_rotated(&b, Rb, shift);
        bool got, want = collide(ra, xa.p, rb, xb.p, NOCT_ACCURACY_EXACT);
        const noctMesh *A = shift != 0 ? shifted_a : ma, *B = shift != 0 ? shifted_b : mb;
        ck_assert_int_eq(noctCollideTransformed(A, &xa, B, &xb, NOCT_ACCURACY_EXACT, &got, NULL,
                                                NULL),
                         NOCT_OK);
        if (got != want)
            ck_abort_msg("trial %d: transformed %d, rotated meshes %d", trial, got, want);
        ck_assert_int_eq(noctCollideTransformed(B, &xb, A, &xa, NOCT_ACCURACY_EXACT, &got, NULL,
                                                NULL),
                         NOCT_OK);
        ck_assert_int_eq(got, want);
        hits += want;
        misses += !want;
        noctMeshDestroy(ma);
        noctMeshDestroy(mb);
        noctMeshDestroy(ra);
        noctMeshDestroy(rb);
        noctMeshDestroy(shifted_a);
        noctMeshDestroy(shifted_b);
    }
    ck_assert_int_gt(hits, 20);
    ck_assert_int_gt(misses, 20);
}
END_TEST

/* A mesh of several pieces (separate cubes, each closed and outward) is
 * one solid, their union: a box that holds one cube wholly, its
 * boundary crossing none, meets it, whichever piece that is. The oracle:
 * closed intervals of the axis-aligned cubes and box (integers, exact),
 * then the same on a 90-degree turn about z (exact too). */
START_TEST(pieces_inside_another_solid)
{
    uint64_t rng = 99 + (uint64_t)_i;
    int hits = 0, contained = 0, misses = 0;
    for (int trial = 0; trial < 60; ++trial) {
        const int n = 2 + (int)test_rand_below(&rng, 3);
        poly_list l = {0};
        double lo[4][3], hi[4][3];
        for (int c = 0; c < n; ++c) {
            for (int k = 0; k < 3; ++k) {
                lo[c][k] = (double)(k == 0 ? 10 * c : 0);
                hi[c][k] = lo[c][k] + 1 + (double)test_rand_below(&rng, 2);
            }
            poly_list cube = pl_box(lo[c], hi[c]);
            const uint32_t base = (uint32_t)l.nv;
            for (size_t v = 0; v < cube.nv; ++v)
                pl_vertex(&l, cube.v[3 * v], cube.v[3 * v + 1], cube.v[3 * v + 2]);
            for (size_t f = 0; f < cube.np; ++f) {
                uint32_t q[4];
                for (int e = 0; e < 4; ++e)
                    q[e] = base + cube.idx[4 * f + (size_t)e];
                pl_poly(&l, 4, q);
            }
        }
        noctMesh *pieces = pl_mesh(&l);
        /* a box around a random cube, or between two, or off to a side */
        const int around = (int)test_rand_below(&rng, (size_t)n + 1);
        double blo[3], bhi[3];
        for (int k = 0; k < 3; ++k) {
            const double c = around < n ? (lo[around][k] + hi[around][k]) / 2
                                        : (k == 0 ? 5 : 0.5);
            const double h = 2 + (double)test_rand_below(&rng, 3);
            blo[k] = c - h;
            bhi[k] = c + h;
        }
        if (around == n) /* between the first two cubes, touching neither */
            blo[0] = hi[0][0] + 1, bhi[0] = 9;
        poly_list bl = pl_box(blo, bhi);
        noctMesh *box = pl_mesh(&bl);
        bool want = false, crossed = false;
        for (int c = 0; c < n; ++c) {
            bool meet = true, inside = true;
            for (int k = 0; k < 3; ++k) {
                meet = meet && lo[c][k] <= bhi[k] && blo[k] <= hi[c][k];
                inside = inside && blo[k] < lo[c][k] && hi[c][k] < bhi[k];
            }
            want = want || meet;
            crossed = crossed || (meet && !inside);
        }
        const double zero[3] = {0, 0, 0};
        for (int turn = 0; turn < 2; ++turn) {
            noctTransform xa = noctIdentityTransform(), xb = noctIdentityTransform();
            if (turn == 1) { /* both turned by 90 degrees about z: exact */
                const double z[3] = {0, 0, 1};
                ck_assert_int_eq(noctQuatFromAxisAngle(z, 90, &xa.q), NOCT_OK);
                xb.q = xa.q;
            }
            bool got;
            if (turn == 0) {
                EXPECT(collide(pieces, zero, box, zero, NOCT_ACCURACY_EXACT) == want);
                EXPECT(collide(box, zero, pieces, zero, NOCT_ACCURACY_EXACT) == want);
            }
            ck_assert_int_eq(noctCollideTransformed(pieces, &xa, box, &xb,
                                                    NOCT_ACCURACY_EXACT, &got, NULL, NULL),
                             NOCT_OK);
            ck_assert_msg(got == want, "trial %d turn %d: %d, want %d", trial, turn, got, want);
            ck_assert_int_eq(noctCollideTransformed(box, &xb, pieces, &xa,
                                                    NOCT_ACCURACY_EXACT, &got, NULL, NULL),
                             NOCT_OK);
            ck_assert_int_eq(got, want);
            noctDistanceResult r;
            ck_assert_int_eq(noctDistance(pieces, &xa, box, &xb, INFINITY, &r, NULL, NULL),
                             NOCT_OK);
            ck_assert_msg(r.colliding == want && (r.distance == 0) == want,
                          "trial %d turn %d: distance %g colliding %d, want %d", trial, turn,
                          r.distance, r.colliding, want);
            noctContact ct;
            ck_assert_int_eq(noctCollideContact(pieces, &xa, box, &xb, &got, &ct, NULL),
                             NOCT_OK);
            ck_assert_int_eq(got, want);
            if (want && !crossed)
                ck_assert_int_eq(ct.kind, NOCT_CONTACT_CONTAINED);
        }
        hits += want && crossed;
        contained += want && !crossed;
        misses += !want;
        noctMeshDestroy(pieces);
        noctMeshDestroy(box);
    }
    ck_assert_int_gt(contained, 5);
    ck_assert_int_gt(misses, 5);
    (void)hits;
}
END_TEST

/* ---- turned pairs in a relative frame against meshes of placed vertices ------- */

/* A mesh as vertices and triangles, for the turned pairs' tests. */
typedef struct tmesh {
    double *v;
    size_t nv;
    uint32_t *tri;
    size_t nt;
} tmesh;

static void tmesh_free(tmesh *m)
{
    free(m->v);
    free(m->tri);
}

/* A bumpy sphere: n around, r rings (poles apart), radius
 * s (1 + 0.3 sin(3 theta) cos(4 phi)) (not convex); or, with bumps
 * false, a box of half-extents s, s / 2, s / 3 (whose turned faces the
 * node test's axes meet head on). Centred at c. */
static tmesh make_tmesh(int n, int r, double s, bool bumps, const double c[3])
{
    tmesh m = {0};
    if (!bumps) {
        m.v = malloc(24 * sizeof *m.v);
        m.tri = malloc(36 * sizeof *m.tri);
        ck_assert(m.v != NULL && m.tri != NULL);
        const double h[3] = {s, s / 2, s / 3};
        for (int i = 0; i < 8; ++i)
            for (int k = 0; k < 3; ++k)
                m.v[3 * i + k] = c[k] + ((i >> (2 - k)) & 1 ? h[k] : -h[k]);
        static const int quad[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                                       {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
        for (int f = 0; f < 6; ++f) {
            const uint32_t q[4] = {(uint32_t)quad[f][0], (uint32_t)quad[f][1],
                                   (uint32_t)quad[f][2], (uint32_t)quad[f][3]};
            const uint32_t t[6] = {q[0], q[1], q[2], q[0], q[2], q[3]};
            memcpy(&m.tri[6 * f], t, sizeof t);
        }
        m.nv = 8;
        m.nt = 12;
        return m;
    }
    m.nv = (size_t)(n * (r - 1) + 2);
    m.nt = (size_t)(2 * n * (r - 1));
    m.v = malloc(3 * m.nv * sizeof *m.v);
    m.tri = malloc(3 * m.nt * sizeof *m.tri);
    ck_assert(m.v != NULL && m.tri != NULL);
    const double pi = 3.14159265358979323846;
    size_t nv = 0, nt = 0;
    for (int i = 0; i <= r; ++i) {
        const double th = pi * i / r;
        for (int j = 0; j < ((i == 0 || i == r) ? 1 : n); ++j) {
            const double ph = 2 * pi * j / n;
            const double rad = s * (1 + 0.3 * sin(3 * th) * cos(4 * ph));
            m.v[3 * nv] = c[0] + rad * sin(th) * cos(ph);
            m.v[3 * nv + 1] = c[1] + rad * sin(th) * sin(ph);
            m.v[3 * nv + 2] = c[2] + rad * cos(th);
            ++nv;
        }
    }
    const uint32_t south = (uint32_t)(m.nv - 1);
    for (int i = 0; i < r - 1; ++i)
        for (int j = 0; j < n; ++j) {
            const uint32_t a = (uint32_t)(1 + i * n + j), b = (uint32_t)(1 + i * n + (j + 1) % n);
            if (i == 0) {
                const uint32_t t[3] = {0, a, b};
                memcpy(&m.tri[3 * nt++], t, sizeof t);
            }
            if (i + 1 < r - 1) {
                const uint32_t c2 = a + (uint32_t)n, d = b + (uint32_t)n;
                const uint32_t t[6] = {a, c2, d, a, d, b};
                memcpy(&m.tri[3 * nt], t, sizeof t);
                nt += 2;
            } else {
                const uint32_t t[3] = {south, b, a};
                memcpy(&m.tri[3 * nt++], t, sizeof t);
            }
        }
    ck_assert_uint_eq(nt, m.nt);
    return m;
}

/* The mesh of m's vertices, each turned by R as transform.h says,
 * fl(fl(R0 v0 + R1 v1) + R2 v2) (R NULL: as they are). */
static noctMesh *tmesh_made(const tmesh *m, const double *R)
{
    double *v = malloc(3 * m->nv * sizeof *v);
    uint32_t *sizes = malloc(m->nt * sizeof *sizes);
    ck_assert(v != NULL && sizes != NULL);
    for (size_t i = 0; i < m->nv; ++i)
        for (int k = 0; k < 3; ++k) {
            const double *w = &m->v[3 * i];
            v[3 * i + k] = R == NULL ? w[k]
                                     : (R[3 * k] * w[0] + R[3 * k + 1] * w[1]) + R[3 * k + 2] * w[2];
        }
    for (size_t t = 0; t < m->nt; ++t)
        sizes[t] = 3;
    noctMesh *out = NULL;
    noctError err;
    const noctStatus st = noctMeshCreate(v, m->nv, sizes, m->nt, m->tri, &out, &err);
    ck_assert_msg(st == NOCT_OK, "mesh: %s", st == NOCT_OK ? "" : err.message);
    free(v);
    free(sizes);
    return out;
}

/* noctCollideTransformed() on the meshes (both orders) against noctCollide()
 * on meshes made of their turned vertices, at the same translations. */
static bool turned_agree(const noctMesh *A, const noctTransform *xa, const noctMesh *ra,
                         const noctMesh *B, const noctTransform *xb, const noctMesh *rb,
                         const char *what, int trial)
{
    const bool want = collide(ra, xa->p, rb, xb->p, NOCT_ACCURACY_EXACT);
    bool got = !want;
    ck_assert_int_eq(noctCollideTransformed(A, xa, B, xb, NOCT_ACCURACY_EXACT, &got, NULL, NULL),
                     NOCT_OK);
    ck_assert_msg(got == want, "%s trial %d: turned %d, placed meshes %d", what, trial, got,
                  want);
    ck_assert_int_eq(noctCollideTransformed(B, xb, A, xa, NOCT_ACCURACY_EXACT, &got, NULL, NULL),
                     NOCT_OK);
    ck_assert_msg(got == want, "%s trial %d (swapped): turned %d, placed meshes %d", what,
                  trial, got, want);
    return want;
}

/*
 * The exact level on turned meshes (narrowphase_turned.c) decides in a
 * relative frame, pruning node pairs by oriented boxes with an allowance
 * for rounding, and reads the vertices it places lazily: its answers must
 * be noctCollide()'s on meshes made of the placed vertices, exactly.
 * _i = 0: random poses of two bumpy spheres (non-convex, deep
 * hierarchies), sometimes one unturned; 1: grazing poses, found by
 * bisecting the reference's answer along a direction to two adjacent
 * translations that differ, for bumpy spheres and for boxes turned alike
 * (face against face: the node test's own axes meet the contact head
 * on), both sides of the flip tested; 2: a small sphere in a large one
 * (containment, no boundary crossing) or near it; 3: _i 0's poses at an
 * offset of 2^30, and at scales 2^-300 and 2^300.
 */
START_TEST(turned_pairs_match_placed_meshes)
{
    uint64_t rng = 777 + (uint64_t)_i;
    int hits = 0, misses = 0, flips = 0;
    const int trials = _i == 1 ? 40 : 60;
    for (int trial = 0; trial < trials; ++trial) {
        double scale = 1, off = 0;
        if (_i == 3) {
            const int kind = trial % 3;
            off = kind == 0 ? 0x1p30 : 0;
            scale = kind == 1 ? 0x1p-300 : kind == 2 ? 0x1p300 : 1;
        }
        const bool boxes = _i == 1 && trial % 2 == 1;
        const double zero[3] = {0, 0, 0};
        double ca[3] = {off, off, off};
        tmesh ma = make_tmesh(12 + (int)test_rand_below(&rng, 20), 6 + (int)test_rand_below(&rng, 10),
                              scale, !boxes, _i == 3 ? ca : zero);
        const double sb = _i == 2 ? 0.2 * scale : scale * (0.5 + test_uniform(&rng));
        tmesh mb = make_tmesh(10 + (int)test_rand_below(&rng, 20), 6 + (int)test_rand_below(&rng, 8),
                              _i == 2 ? sb : sb, !boxes, zero);
        if (_i == 2) { /* the large one three times the size */
            for (size_t k = 0; k < 3 * ma.nv; ++k)
                ma.v[k] *= 3;
        }
        noctMesh *A = tmesh_made(&ma, NULL), *B = tmesh_made(&mb, NULL);
        noctTransform xa = noctIdentityTransform(), xb = noctIdentityTransform();
        test_random_quat(&rng, &xa.q);
        if (boxes)
            xb.q = xa.q; /* face against face */
        else if (trial % 5 != 0)
            test_random_quat(&rng, &xb.q);
        double Ra[9], Rb[9];
        ck_assert_int_eq(noctQuatToMatrix(&xa.q, Ra, NULL), NOCT_OK);
        ck_assert_int_eq(noctQuatToMatrix(&xb.q, Rb, NULL), NOCT_OK);
        /* A's centre, turned, brought back near 0 */
        for (int k = 0; k < 3; ++k)
            xa.p[k] = -(Ra[3 * k] + Ra[3 * k + 1] + Ra[3 * k + 2]) * off;
        noctMesh *ra = tmesh_made(&ma, Ra), *rb = tmesh_made(&mb, Rb);
        double dir[3];
        if (boxes) { /* along A's first face normal */
            for (int k = 0; k < 3; ++k)
                dir[k] = Ra[3 * k];
        } else {
            double n2 = 0;
            for (int k = 0; k < 3; ++k) {
                dir[k] = test_uniform(&rng) - 0.5;
                n2 += dir[k] * dir[k];
            }
            for (int k = 0; k < 3; ++k)
                dir[k] /= sqrt(n2);
        }
        if (_i == 1) {
            /* from coinciding centres (meeting) to 10 sizes apart */
            double lo = 0, hi = 10 * scale;
            for (int step = 0; step < 200; ++step) {
                const double mid = lo + (hi - lo) / 2;
                if (mid == lo || mid == hi)
                    break;
                for (int k = 0; k < 3; ++k)
                    xb.p[k] = xa.p[k] + mid * dir[k];
                if (collide(ra, xa.p, rb, xb.p, NOCT_ACCURACY_EXACT))
                    lo = mid;
                else
                    hi = mid;
            }
            const double at[2] = {lo, hi};
            for (int side = 0; side < 2; ++side) {
                for (int k = 0; k < 3; ++k)
                    xb.p[k] = xa.p[k] + at[side] * dir[k];
                const bool want = turned_agree(A, &xa, ra, B, &xb, rb, "grazing", trial);
                flips += want != (side == 1);
                hits += want;
                misses += !want;
            }
        } else {
            const double spread = (_i == 2 ? 3.2 : 2.6) * scale;
            for (int pose = 0; pose < 20; ++pose) {
                for (int k = 0; k < 3; ++k)
                    xb.p[k] = xa.p[k] + spread * (2 * test_uniform(&rng) - 1);
                const bool want = turned_agree(A, &xa, ra, B, &xb, rb, "random", trial);
                hits += want;
                misses += !want;
            }
        }
        noctMeshDestroy(A);
        noctMeshDestroy(B);
        noctMeshDestroy(ra);
        noctMeshDestroy(rb);
        tmesh_free(&ma);
        tmesh_free(&mb);
    }
    ck_assert_int_gt(hits, 20);
    ck_assert_int_gt(misses, 20);
    if (_i == 1) /* the bisection ended on the flip every time */
        ck_assert_int_eq(flips, 2 * trials);
}
END_TEST

/* The convex level on hulls never misses a collision with real depth, and
 * on convex solids agrees with the exact level except within its
 * tolerance of touching. */
START_TEST(convex_level_one_sided)
{
    uint64_t rng = 2024;
    int checked = 0;
    for (int trial = 0; trial < 300; ++trial) {
        star a, b;
        make_star(&a, &rng);
        make_star(&b, &rng);
        noctMesh *ma = star_mesh(&a), *mb = star_mesh(&b);
        /* Non-integer offsets: touching is then essentially impossible. */
        double da[3] = {0, 0, 0}, db[3];
        for (int k = 0; k < 3; ++k)
            db[k] = ((double)test_rand_below(&rng, 1u << 20) / (1u << 20) - 0.5) * 12;
        bool exact = collide(ma, da, mb, db, NOCT_ACCURACY_EXACT);
        bool cvx = collide(ma, da, mb, db, NOCT_ACCURACY_CONVEX);
        if (exact)
            EXPECT(cvx);
        if (noctMeshIsConvex(ma) && noctMeshIsConvex(mb)) {
            EXPECT(cvx == exact);
            ++checked;
        }
        noctMeshDestroy(ma);
        noctMeshDestroy(mb);
    }
    ck_assert_int_gt(checked, 0);
}
END_TEST

/* ---- mesh validation ----------------------------------------------------------- */

static noctStatus try_mesh(const poly_list *p, noctError *err)
{
    noctMesh *m = (noctMesh *)1;
    noctStatus st = noctMeshCreate(p->v, p->nv, p->sizes, p->np, p->idx, &m, err);
    if (st == NOCT_OK)
        noctMeshDestroy(m);
    else
        ck_assert_ptr_null(m);
    return st;
}

START_TEST(bad_meshes_are_rejected)
{
    double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
    poly_list good = pl_box(lo, hi), p;
    noctError err;
    ck_assert_int_eq(try_mesh(&good, &err), NOCT_OK);

    p = good;
    p.v[3 * 5 + 1] = NAN;
    ck_assert_int_eq(try_mesh(&p, &err), NOCT_ERR_NONFINITE);
    ck_assert_int_eq(err.index, 5);
    ck_assert_msg(strstr(err.message, "vertex 5") != NULL, "%s", err.message);
    p.v[3 * 5 + 1] = INFINITY;
    ck_assert_int_eq(try_mesh(&p, &err), NOCT_ERR_NONFINITE);

    p = good;
    p.idx[9] = 8; /* polygon 2 names vertex 8 of 8 */
    ck_assert_int_eq(try_mesh(&p, &err), NOCT_ERR_INDEX);
    ck_assert_int_eq(err.index, 2);

    p = good;
    p.np = 5; /* a face missing: open */
    ck_assert_int_eq(try_mesh(&p, &err), NOCT_ERR_OPEN);

    p = good; /* one face reversed */
    uint32_t t = p.idx[4 * 3 + 1];
    p.idx[4 * 3 + 1] = p.idx[4 * 3 + 3];
    p.idx[4 * 3 + 3] = t;
    ck_assert_int_eq(try_mesh(&p, &err), NOCT_ERR_ORIENTATION);

    p = good; /* a repeated corner */
    p.idx[1] = p.idx[0];
    ck_assert_int_eq(try_mesh(&p, &err), NOCT_ERR_DEGENERATE);
    ck_assert_int_eq(err.index, 0);

    p = good; /* a bent face: vertex 7 (1,1,1) lifted out of x = 1 */
    p.v[3 * 7] = 1.25;
    ck_assert_int_eq(try_mesh(&p, &err), NOCT_ERR_NONPLANAR);

    p = good; /* a non-convex (bow-tie) quad */
    t = p.idx[1];
    p.idx[1] = p.idx[2];
    p.idx[2] = t;
    noctStatus st = try_mesh(&p, &err);
    ck_assert(st == NOCT_ERR_NONCONVEX || st == NOCT_ERR_DEGENERATE);

    poly_list flat = {0}; /* four coplanar triangles: no volume */
    const double pts[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    for (int i = 0; i < 4; ++i)
        pl_vertex(&flat, pts[i][0], pts[i][1], pts[i][2]);
    const uint32_t f[4][3] = {{0, 1, 2}, {1, 3, 2}, {0, 2, 1}, {1, 2, 3}};
    for (int i = 0; i < 4; ++i)
        pl_poly(&flat, 3, f[i]);
    ck_assert_int_ne(try_mesh(&flat, &err), NOCT_OK);

    poly_list tiny = good;
    tiny.nv = 3;
    ck_assert_int_eq(try_mesh(&tiny, &err), NOCT_ERR_DEGENERATE);

    /* An inside-out mesh is accepted as the same solid. */
    p = good;
    for (size_t i = 0; i < p.np; ++i) {
        t = p.idx[4 * i + 1];
        p.idx[4 * i + 1] = p.idx[4 * i + 3];
        p.idx[4 * i + 3] = t;
    }
    noctMesh *m = pl_mesh(&p), *g = pl_mesh(&good);
    const double touch[3] = {1, 0, 0}, apart[3] = {1 + 0x1p-40, 0, 0};
    ck_assert(collide(m, ORIGIN, g, touch, NOCT_ACCURACY_EXACT));
    ck_assert(!collide(m, ORIGIN, g, apart, NOCT_ACCURACY_EXACT));
    noctMeshDestroy(m);
    noctMeshDestroy(g);
}
END_TEST

START_TEST(box_constructors)
{
    noctMesh *m = NULL;
    noctError err;
    ck_assert_int_eq(noctMeshCreateBox(1, 2, 3, &m, &err), NOCT_OK);
    double lo[3], hi[3];
    noctMeshBounds(m, lo, hi);
    ck_assert(lo[0] == -1 && lo[1] == -2 && lo[2] == -3);
    ck_assert(hi[0] == 1 && hi[1] == 2 && hi[2] == 3);
    ck_assert_uint_eq(noctMeshVertexCount(m), 8);
    ck_assert_uint_eq(noctMeshTriangleCount(m), 12);
    ck_assert(noctMeshIsConvex(m));
    noctMeshDestroy(m);
    ck_assert_int_eq(noctMeshCreateBox(0, 1, 1, &m, &err), NOCT_ERR_INVALID);
    ck_assert_ptr_null(m);
    ck_assert_int_eq(noctMeshCreateBox(-1, 1, 1, &m, &err), NOCT_ERR_INVALID);
    ck_assert_int_eq(noctMeshCreateBox(NAN, 1, 1, &m, &err), NOCT_ERR_NONFINITE);
    ck_assert_int_eq(noctMeshCreateBox(1, INFINITY, 1, &m, &err), NOCT_ERR_NONFINITE);
    const double half[3] = {1, 1, 1};
    const double shear[9] = {1, 0.5, 0, 0, 1, 0, 0, 0, 1};
    const double mirror[9] = {-1, 0, 0, 0, 1, 0, 0, 0, 1};
    const double ident[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    ck_assert_int_eq(noctMeshCreateOrientedBox(half, shear, &m, &err), NOCT_ERR_INVALID);
    ck_assert_int_eq(noctMeshCreateOrientedBox(half, mirror, &m, &err), NOCT_ERR_INVALID);
    ck_assert_int_eq(noctMeshCreateOrientedBox(half, ident, &m, &err), NOCT_OK);
    ck_assert(noctMeshIsConvex(m));
    noctMeshDestroy(m);
}
END_TEST

/* ---- mesh files ------------------------------------------------------------------ */

/* Write text to a new file named NAME in a fresh temporary directory;
 * returns its path (valid until the next call). */
static const char *write_temp(const char *name, const char *text)
{
    static char dir[64], path[128];
    if (dir[0] == '\0') {
        strcpy(dir, "/tmp/noct-test-XXXXXX");
        ck_assert_ptr_nonnull(mkdtemp(dir));
    }
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    fputs(text, f);
    fclose(f);
    return path;
}

static const char CUBE_OFF[] =
    "OFF\n"
    "# a unit cube\n"
    "8 6 12\n"
    "0 0 0\n0 0 1\n0 1 0\n0 1 1\n1 0 0\n1 0 1\n1 1 0\n1 1 1\n"
    "4 0 1 3 2\n4 4 6 7 5\n4 0 4 5 1\n4 2 3 7 6\n4 0 2 6 4\n"
    "4 1 5 7 3 255 0 0\n";

static const char CUBE_OBJ[] =
    "# a unit cube\n"
    "o cube\n"
    "v 0 0 0\nv 0 0 1\nv 0 1 0\nv 0 1 1\nv 1 0 0\nv 1 0 1\nv 1 1 0\nv 1 1 1\n"
    "vn 0 0 1\nvt 0 0\n"
    "s off\n"
    "f 1/1/1 2/1/1 4/1/1 3/1/1\n"
    "f 5//1 7//1 8//1 6//1\n"
    "f 1 5 6 2\n"
    "f 3 4 8 7\n"
    "f -8 -6 -2 -4\n"
    "f 2 6 8 4\n";

/* Read text as a file called name and expect status and a message that
 * contains want (the file name and line, typically). */
static void expect_read(const char *name, const char *text, noctStatus status,
                        const char *want)
{
    const char *path = write_temp(name, text);
    noctMesh *m = (noctMesh *)1;
    noctError err = {0};
    noctStatus st = noctMeshRead(path, &m, &err);
    ck_assert_msg(st == status, "%s: got %s (%s), want %s", name,
                  noctStatusString(st), err.message, noctStatusString(status));
    if (st == NOCT_OK) {
        ck_assert_uint_ge(noctMeshVertexCount(m), 4);
        noctMeshDestroy(m);
        return;
    }
    ck_assert_ptr_null(m);
    ck_assert_msg(strstr(err.message, path) != NULL, "no path in '%s'", err.message);
    ck_assert_msg(strstr(err.message, want) != NULL, "'%s' lacks '%s'", err.message,
                  want);
}

START_TEST(read_off_files)
{
    expect_read("cube.off", CUBE_OFF, NOCT_OK, "");
    expect_read("inline.OFF", "OFF 4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n", NOCT_OK, "");
    expect_read("empty.off", "", NOCT_ERR_PARSE, "empty file");
    expect_read("header.off", "OFX\n8 6 12\n", NOCT_ERR_PARSE, ":1: expected the OFF header");
    expect_read("number.off", "OFF\n8 6 12\n0 0 0\n0 0 1x\n", NOCT_ERR_PARSE,
                ":4: not a number: '1x'");
    expect_read("nan.off", "OFF\n8 6 12\n0 0 0\nnan 0 1\n", NOCT_ERR_NONFINITE, ":4:");
    expect_read("short.off", "OFF\n8 6 12\n0 0 0\n0 0\n", NOCT_ERR_PARSE,
                ":4: expected 3 coordinates");
    expect_read("truncated.off", "OFF\n8 6 12\n0 0 0\n", NOCT_ERR_PARSE,
                "file ends before all vertices");
    expect_read("huge.off", "OFF\n999999999999 1 0\n", NOCT_ERR_TOO_LARGE, ":2:");
    expect_read("negative.off", "OFF\n-8 6 12\n", NOCT_ERR_PARSE, "not a count");
    char bad_index[sizeof CUBE_OFF + 16];
    strcpy(bad_index, CUBE_OFF);
    *strstr(bad_index, "4 0 4 5 1") = '\0';
    strcat(bad_index, "4 0 4 5 9\n4 2 3 7 6\n4 0 2 6 4\n4 1 5 7 3\n");
    expect_read("index.off", bad_index, NOCT_ERR_INDEX, ":14: face 2: vertex index 9");
    char open[sizeof CUBE_OFF];
    strcpy(open, CUBE_OFF);
    *strstr(open, "4 1 5 7 3") = '\0';
    expect_read("open.off", open, NOCT_ERR_PARSE, "file ends before all faces");
    char five[sizeof CUBE_OFF];
    strcpy(five, CUBE_OFF);
    memcpy(strstr(five, "8 6 12"), "8 5 12", 6);
    expect_read("open2.off", five, NOCT_ERR_OPEN, ": not a closed, consistently oriented "
                "solid: 4 boundary edges, first 1-3, 1-5, 3-7 (noctMeshReadSurface() "
                "reads it as a surface; noctree-mesh(1)");
    expect_read("count.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n2 0 1\n",
                NOCT_ERR_PARSE, ":7: expected a face's corner count");
}
END_TEST

START_TEST(read_obj_files)
{
    expect_read("cube.obj", CUBE_OBJ, NOCT_OK, "");
    expect_read("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 5\n",
                NOCT_ERR_INDEX, ":5: face 0: bad vertex reference '5'");
    expect_read("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", NOCT_ERR_INDEX,
                ":4:");
    expect_read("line.obj", "v 0 0 0\nv 1 0 0\nl 1 2\n", NOCT_ERR_PARSE,
                ":3: unsupported statement 'l'");
    expect_read("coords.obj", "v 0 0\n", NOCT_ERR_PARSE, ":1: expected 3 coordinates");
    expect_read("inf.obj", "v 0 0 inf\n", NOCT_ERR_NONFINITE, ":1:");
    expect_read("face.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n", NOCT_ERR_PARSE,
                ":3: a face needs at least 3 corners");
    expect_read("garbage.obj", "v 0 0 0\nf a b c\n", NOCT_ERR_PARSE,
                "bad vertex reference 'a'");
    expect_read("suffix.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1x 2 3\n",
                NOCT_ERR_PARSE, ":4: face 0: bad vertex reference '1x'");
    expect_read("relative.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n",
                NOCT_ERR_INDEX, "bad vertex reference '-4'");
    /* Validation errors name the face's line. */
    char reversed[sizeof CUBE_OBJ];
    strcpy(reversed, CUBE_OBJ);
    memcpy(strstr(reversed, "f 1 5 6 2"), "f 2 6 5 1", 9);
    expect_read("reversed.obj", reversed, NOCT_ERR_ORIENTATION, "4 misoriented edges, first 0-1");
    expect_read("format.xyzw", "solid\n", NOCT_ERR_INVALID, "unknown mesh format");
    noctMesh *m = (noctMesh *)1;
    noctError err;
    ck_assert_int_eq(noctMeshRead("/nonexistent/dir/x.off", &m, &err), NOCT_ERR_IO);
    ck_assert_ptr_null(m);
    ck_assert(strstr(err.message, "/nonexistent/dir/x.off: cannot open") != NULL);
}
END_TEST

START_TEST(status_strings)
{
    for (int s = 0; s < NOCT_STATUS_COUNT; ++s) {
        const char *t = noctStatusString((noctStatus)s);
        ck_assert_ptr_nonnull(t);
        ck_assert_uint_gt(strlen(t), 3);
        for (int u = 0; u < s; ++u)
            ck_assert_str_ne(t, noctStatusString((noctStatus)u));
    }
    ck_assert_str_eq(noctStatusString((noctStatus)999), "unknown status");
    ck_assert_str_eq(noctAccuracyName(NOCT_ACCURACY_EXACT), "exact");
    ck_assert_str_eq(noctAccuracyName((noctAccuracy)7), "unknown");
}
END_TEST

START_TEST(collide_rejects_bad_input)
{
    noctMesh *m = NULL;
    ck_assert_int_eq(noctMeshCreateBox(1, 1, 1, &m, NULL), NOCT_OK);
    bool hit = true;
    const double bad[3] = {NAN, 0, 0}, inf[3] = {0, INFINITY, 0};
    ck_assert_int_eq(noctCollide(m, bad, m, ORIGIN, NOCT_ACCURACY_EXACT, &hit, NULL),
                     NOCT_ERR_NONFINITE);
    ck_assert_int_eq(noctCollide(m, ORIGIN, m, inf, NOCT_ACCURACY_BOX, &hit, NULL),
                     NOCT_ERR_NONFINITE);
    const double huge[3] = {1.7e308, 0, 0};
    ck_assert_int_eq(noctCollide(m, huge, m, ORIGIN, NOCT_ACCURACY_CONVEX, &hit, NULL),
                     NOCT_ERR_TOO_LARGE);
    ck_assert_int_eq(noctCollide(m, ORIGIN, m, ORIGIN, (noctAccuracy)9, &hit, NULL),
                     NOCT_ERR_INVALID);
    /* Counters: a box reject never reaches a costlier stage. */
    noctNarrowStats st = {0};
    const double far[3] = {5, 0, 0};
    ck_assert_int_eq(noctCollide(m, ORIGIN, m, far, NOCT_ACCURACY_EXACT, &hit, &st),
                     NOCT_OK);
    ck_assert(!hit);
    ck_assert_uint_eq(st.box_tests, 1);
    ck_assert_uint_eq(st.box_rejects, 1);
    ck_assert_uint_eq(st.exact_tests + st.convex_tests + st.triangle_pairs, 0);
    noctMeshDestroy(m);
}
END_TEST

/* The separating-axis filter proves a pair apart that only the exact
 * stage could otherwise, and never rejects one that touches. */

/* Each level's time goes to its own counter, and only a level that ran
 * takes time. */
START_TEST(level_timings)
{
    noctMesh *box;
    noctError err;
    ck_assert_int_eq(noctMeshCreateBox(1, 1, 1, &box, &err), NOCT_OK);
    const double ta[3] = {0, 0, 0}, near[3] = {1.5, 0.2, 0}, far[3] = {9, 0, 0};
    static const noctAccuracy levels[] = {NOCT_ACCURACY_BOX, NOCT_ACCURACY_CONVEX,
                                          NOCT_ACCURACY_EXACT};
    for (int l = 0; l < 3; ++l) {
        noctNarrowStats st = {0};
        bool hit;
        ck_assert_int_eq(noctCollide(box, ta, box, far, levels[l], &hit, &st), NOCT_OK);
        ck_assert(!hit);
        ck_assert(st.seconds_convex == 0 && st.seconds_exact == 0); /* box rejects */
        for (int i = 0; i < 200; ++i) {
            ck_assert_int_eq(noctCollide(box, ta, box, near, levels[l], &hit, &st), NOCT_OK);
            ck_assert(hit);
        }
        ck_assert(l == 1 ? st.seconds_convex > 0 : st.seconds_convex == 0);
        ck_assert(l == 2 ? st.seconds_exact > 0 : st.seconds_exact == 0);
    }
    noctMeshDestroy(box);
}
END_TEST

START_TEST(sat_filter_rejects_soundly)
{
    const double c = sqrt(0.5);
    const double rz[9] = {c, -c, 0, c, c, 0, 0, 0, 1}, half[3] = {1, 1, 1};
    noctMesh *d;
    ck_assert_int_eq(noctMeshCreateOrientedBox(half, rz, &d, NULL), NOCT_OK);
    noctNarrowStats st = {0};
    bool hit = true;
    const double apart[3] = {1.5, 1.5, 0}; /* boxes overlap, diamonds do not */
    ck_assert_int_eq(noctCollide(d, ORIGIN, d, apart, NOCT_ACCURACY_EXACT, &hit, &st),
                     NOCT_OK);
    ck_assert(!hit);
    ck_assert_uint_eq(st.box_rejects, 0);
    ck_assert_uint_eq(st.sat_rejects, 1);
    ck_assert_uint_eq(st.triangle_pairs, 0);
    const double deep[3] = {1, 1, 0};
    ck_assert_int_eq(noctCollide(d, ORIGIN, d, deep, NOCT_ACCURACY_EXACT, &hit, &st),
                     NOCT_OK);
    ck_assert(hit);
    ck_assert_uint_eq(st.sat_rejects, 1);
    /* deep: the centre of the boxes' overlap is inside both diamonds */
    ck_assert_uint_eq(st.witnesses, 1);
    ck_assert_uint_eq(st.triangle_pairs, 0);
    noctMeshDestroy(d);
    /* Touching axis-aligned boxes: the filter must let them through. */
    noctMesh *b;
    ck_assert_int_eq(noctMeshCreateBox(0.5, 0.5, 0.5, &b, NULL), NOCT_OK);
    const double touch[3] = {1, 0.25, 0};
    noctNarrowStats s2 = {0};
    ck_assert_int_eq(noctCollide(b, ORIGIN, b, touch, NOCT_ACCURACY_EXACT, &hit, &s2),
                     NOCT_OK);
    ck_assert(hit);
    ck_assert_uint_eq(s2.sat_rejects, 0);
    /* Touching solids share no inner point: no witness, the triangles
     * decide. */
    ck_assert_uint_eq(s2.witnesses, 0);
    ck_assert_uint_gt(s2.triangle_pairs, 0);
    noctMeshDestroy(b);
}
END_TEST

/* A random rotation matrix (row-major) from a unit quaternion. */
static void random_rotation(uint64_t *rng, double r[9])
{
    double q[4], len = 0;
    for (int k = 0; k < 4; ++k) {
        q[k] = (double)(test_rand(rng) >> 11) * 0x1p-53 - 0.5;
        len += q[k] * q[k];
    }
    len = sqrt(len);
    double x = q[0] / len, y = q[1] / len, z = q[2] / len, w = q[3] / len;
    const double m[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
                         2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
                         2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)};
    memcpy(r, m, sizeof m);
}

/* The largest gap between two oriented boxes over the first naxes of the
 * 15 axes of the separating-axis theorem (A's axes, B's, then their cross
 * products), from the rotation matrices rather than the meshes:
 * positive = apart. */
static double obb_gap_on(const double ha[3], const double ra[9], const double ta[3],
                         const double hb[3], const double rb[9], const double tb[3], int naxes)
{
    double axes[15][3];
    int n = 0;
    for (int i = 0; i < 3; ++i, ++n)
        for (int k = 0; k < 3; ++k)
            axes[n][k] = ra[3 * k + i];
    for (int i = 0; i < 3; ++i, ++n)
        for (int k = 0; k < 3; ++k)
            axes[n][k] = rb[3 * k + i];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j, ++n) {
            const double *p = axes[i], *q = axes[3 + j];
            axes[n][0] = p[1] * q[2] - p[2] * q[1];
            axes[n][1] = p[2] * q[0] - p[0] * q[2];
            axes[n][2] = p[0] * q[1] - p[1] * q[0];
        }
    double best = -INFINITY;
    for (int a = 0; a < naxes; ++a) {
        const double *u = axes[a];
        double len = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        if (len < 1e-6)
            continue;
        double ra_ = 0, rb_ = 0;
        for (int i = 0; i < 3; ++i) {
            double da = 0, db = 0;
            for (int k = 0; k < 3; ++k) {
                da += u[k] * ra[3 * k + i];
                db += u[k] * rb[3 * k + i];
            }
            ra_ += ha[i] * fabs(da);
            rb_ += hb[i] * fabs(db);
        }
        double d = 0;
        for (int k = 0; k < 3; ++k)
            d += u[k] * (tb[k] - ta[k]);
        best = fmax(best, (fabs(d) - ra_ - rb_) / len);
    }
    return best;
}

/* Over all 15 axes. */
static double obb_gap(const double ha[3], const double ra[9], const double ta[3],
                      const double hb[3], const double rb[9], const double tb[3])
{
    return obb_gap_on(ha, ra, ta, hb, rb, tb, 15);
}

/* Randomly rotated boxes, whose rounded corners leave their faces only
 * nearly planar: every pair that the theorem's 15 axes separate by a clear
 * gap is rejected by the filter, with no triangle test (an edge-edge axis
 * is as much a proof as a face axis), and every pair they cannot separate
 * collides. */
START_TEST(sat_filter_rotated_boxes)
{
    uint64_t rng = 0x5a7b0c5ULL + (uint64_t)_i;
    size_t apart = 0, edge_only = 0, overlapping = 0;
    for (int trial = 0; trial < 400; ++trial) {
        double ha[3], hb[3], ra[9], rb[9], tb[3];
        for (int k = 0; k < 3; ++k) {
            ha[k] = 0.25 + 0.5 * (double)(test_rand(&rng) >> 11) * 0x1p-53;
            hb[k] = 0.25 + 0.5 * (double)(test_rand(&rng) >> 11) * 0x1p-53;
            tb[k] = 2.4 * (double)(test_rand(&rng) >> 11) * 0x1p-53 - 1.2;
        }
        random_rotation(&rng, ra);
        random_rotation(&rng, rb);
        noctMesh *a, *b;
        ck_assert_int_eq(noctMeshCreateOrientedBox(ha, ra, &a, NULL), NOCT_OK);
        ck_assert_int_eq(noctMeshCreateOrientedBox(hb, rb, &b, NULL), NOCT_OK);
        double gap = obb_gap(ha, ra, ORIGIN, hb, rb, tb);
        noctNarrowStats st = {0};
        bool hit;
        ck_assert_int_eq(noctCollide(a, ORIGIN, b, tb, NOCT_ACCURACY_EXACT, &hit, &st),
                         NOCT_OK);
        if (gap > 1e-9) {
            EXPECT(!hit);
            if (st.box_rejects == 0) {
                EXPECT(st.sat_rejects == 1);
                EXPECT(st.triangle_pairs == 0);
                ++apart;
                /* no face axis separates: only an edge pair does */
                edge_only += obb_gap_on(ha, ra, ORIGIN, hb, rb, tb, 6) < 0;
            }
        } else if (gap < -1e-9) {
            EXPECT(hit);
            /* two boxes that overlap are proven so on their box forms */
            EXPECT(st.witnesses == 1 && st.triangle_pairs == 0 && st.bvh_pairs == 0);
            ++overlapping;
        }
        noctMeshDestroy(a);
        noctMeshDestroy(b);
    }
    /* the sample exercises what it claims to */
    ck_assert_uint_gt(apart, 20);
    ck_assert_uint_gt(edge_only, 2);
    ck_assert_uint_gt(overlapping, 20);
}
END_TEST

/* The unit cube [0, 1]^3 as 12 triangles, its corner (1, 1, 1) moved by
 * dx along x. */
static noctMesh *unit_box_moved_corner(double dx)
{
    double v[24];
    for (int i = 0; i < 8; ++i) { /* bit 2: +x, bit 1: +y, bit 0: +z */
        v[3 * i] = (i & 4) ? 1 : 0;
        v[3 * i + 1] = (i & 2) ? 1 : 0;
        v[3 * i + 2] = (i & 1) ? 1 : 0;
    }
    v[3 * 7] += dx;
    static const uint32_t quads[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                                         {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    uint32_t sizes[12], idx[36];
    for (int f = 0; f < 6; ++f) {
        const uint32_t t[6] = {quads[f][0], quads[f][1], quads[f][2],
                               quads[f][0], quads[f][2], quads[f][3]};
        memcpy(&idx[6 * f], t, sizeof t);
        sizes[2 * f] = sizes[2 * f + 1] = 3;
    }
    noctMesh *m;
    ck_assert_int_eq(noctMeshCreate(v, 8, sizes, 12, idx, &m, NULL), NOCT_OK);
    return m;
}

/* A box with one corner pushed out by 2^-33 along x, as 12 triangles:
 * its vertices are a box's corners only within that deviation. Another
 * box touching exactly that corner collides (closed solids), so no
 * filter may take the box it approximates for the mesh. A diamond off
 * that corner, its face 1e-3 from it and its bounding box overlapping
 * the mesh's, is separated by the filter without a triangle test. */
START_TEST(sat_filter_nearly_a_box)
{
    const double delta = 0x1p-33;
    noctMesh *a = unit_box_moved_corner(delta), *b;
    noctError err;
    ck_assert_int_eq(noctMeshCreateBox(0.5, 0.5, 0.5, &b, &err), NOCT_OK);
    const double c = sqrt(0.5);
    const double rz[9] = {c, -c, 0, c, c, 0, 0, 0, 1}, half[3] = {0.5, 0.5, 0.5};
    noctMesh *d;
    ck_assert_int_eq(noctMeshCreateOrientedBox(half, rz, &d, &err), NOCT_OK);
    const double touch[3] = {1.5 + delta, 1.25, 1.25}; /* b's face x = 1 + delta */
    for (int swap = 0; swap < 2; ++swap) {
        noctNarrowStats st = {0};
        bool hit = false;
        ck_assert_int_eq(swap ? noctCollide(b, touch, a, ORIGIN, NOCT_ACCURACY_EXACT, &hit, &st)
                              : noctCollide(a, ORIGIN, b, touch, NOCT_ACCURACY_EXACT, &hit, &st),
                         NOCT_OK);
        ck_assert(hit);
        ck_assert_uint_eq(st.sat_rejects, 0);
        /* the diamond's face x + y = 2 + 2s - sqrt(1/2) passes 1e-3 / sqrt(2)
         * beyond the corner's x + y = 2 + delta */
        const double sq = sqrt(0.5), off = 0.5 * (sq + 2e-3);
        const double away[3] = {1 + off, 1 + off, 0.5};
        noctNarrowStats s2 = {0};
        ck_assert_int_eq(swap ? noctCollide(d, away, a, ORIGIN, NOCT_ACCURACY_EXACT, &hit, &s2)
                              : noctCollide(a, ORIGIN, d, away, NOCT_ACCURACY_EXACT, &hit, &s2),
                         NOCT_OK);
        ck_assert(!hit);
        ck_assert_uint_eq(s2.box_rejects, 0);
        ck_assert_uint_eq(s2.sat_rejects, 1);
        ck_assert_uint_eq(s2.triangle_pairs, 0);
    }
    noctMeshDestroy(a);
    noctMeshDestroy(b);
    noctMeshDestroy(d);
}
END_TEST

/* The same box with that corner pushed in instead: the ideal box its
 * vertices approximate holds points its solid does not. A tiny cube just
 * beyond the dented face, inside the ideal box, is apart from the mesh,
 * and a witness that took the ideal box for the solid would say it
 * collides, as would the separating-axis proof on boxes not shrunk by
 * the deviation (their edges are parallel: no edge-pair axis); one deep
 * inside collides. */
START_TEST(witness_nearly_a_box)
{
    const double delta = 0x1p-33;
    noctMesh *a = unit_box_moved_corner(-delta), *tiny;
    const double h = 0x1p-40;
    ck_assert_int_eq(noctMeshCreateBox(h, h, h, &tiny, NULL), NOCT_OK);
    /* Near (y, z) = (1, 1) the +x face is x = 1 - delta min(y, z) to within
     * delta^2: the cube's x >= 1 - delta/2 - h lies beyond it. */
    const double beyond[3] = {1 - delta / 2, 1 - delta / 64, 1 - delta / 64};
    const double deep[3] = {1 - 2 * delta, 1 - delta / 64, 1 - delta / 64};
    for (int swap = 0; swap < 2; ++swap) {
        noctNarrowStats st = {0};
        bool hit = true;
        ck_assert_int_eq(swap ? noctCollide(tiny, beyond, a, ORIGIN, NOCT_ACCURACY_EXACT, &hit, &st)
                              : noctCollide(a, ORIGIN, tiny, beyond, NOCT_ACCURACY_EXACT, &hit, &st),
                         NOCT_OK);
        ck_assert(!hit);
        ck_assert_uint_eq(st.box_rejects, 0);
        ck_assert_int_eq(swap ? noctCollide(tiny, deep, a, ORIGIN, NOCT_ACCURACY_EXACT, &hit, &st)
                              : noctCollide(a, ORIGIN, tiny, deep, NOCT_ACCURACY_EXACT, &hit, &st),
                         NOCT_OK);
        ck_assert(hit);
    }
    noctMeshDestroy(a);
    noctMeshDestroy(tiny);
}
END_TEST

/* ---- every scale, every position ------------------------------------------------ */

/* The scales of the documented range the tests visit: near both ends of it
 * and between, where squares and cubes of coordinates leave the doubles. */
static const double SCALES[] = {1e-300, 1e-150, 1e75, 1e99};
#define NSCALES (sizeof SCALES / sizeof *SCALES)

static poly_list pl_scaled(const poly_list *p, double s)
{
    poly_list q = *p;
    for (size_t i = 0; i < 3 * p->nv; ++i)
        q.v[i] = p->v[i] * s;
    return q;
}

/* p moved by (off, off, off); every coordinate must move exactly. */
static poly_list pl_moved(const poly_list *p, double off)
{
    poly_list q = *p;
    for (size_t i = 0; i < 3 * p->nv; ++i) {
        q.v[i] = p->v[i] + off;
        ck_assert_msg(q.v[i] - off == p->v[i], "offset %g is not exact", off);
    }
    return q;
}

/* The L-shaped prism: the L (0,0) (2,0) (2,1) (1,1) (1,2) (0,2) between
 * z = 0 and z = 1. With 'split' each cap is two convex quadrilaterals
 * along the diagonal (0,0)-(1,1), a valid non-convex solid; without, each
 * cap is the L itself, a non-convex polygon. */
static poly_list pl_lprism(bool split)
{
    static const double L[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
    poly_list p = {0};
    for (int z = 0; z < 2; ++z)
        for (int i = 0; i < 6; ++i)
            pl_vertex(&p, L[i][0], L[i][1], z);
    if (split) {
        const uint32_t top1[4] = {6, 7, 8, 9}, top2[4] = {6, 9, 10, 11};
        const uint32_t bot1[4] = {3, 2, 1, 0}, bot2[4] = {5, 4, 3, 0};
        pl_poly(&p, 4, top1);
        pl_poly(&p, 4, top2);
        pl_poly(&p, 4, bot1);
        pl_poly(&p, 4, bot2);
    } else {
        const uint32_t top[6] = {6, 7, 8, 9, 10, 11}, bot[6] = {5, 4, 3, 2, 1, 0};
        pl_poly(&p, 6, top);
        pl_poly(&p, 6, bot);
    }
    for (uint32_t i = 0; i < 6; ++i) {
        uint32_t j = (i + 1) % 6;
        const uint32_t side[4] = {i, j, j + 6, i + 6};
        pl_poly(&p, 4, side);
    }
    return p;
}

/* Create a mesh; its status, and its convexity flag when created. */
static noctStatus try_convex(const poly_list *p, bool *convex, noctError *err)
{
    noctMesh *m = NULL;
    noctStatus st = noctMeshCreate(p->v, p->nv, p->sizes, p->np, p->idx, &m, err);
    if (st == NOCT_OK) {
        *convex = noctMeshIsConvex(m);
        noctMeshDestroy(m);
    } else {
        ck_assert_ptr_null(m);
    }
    return st;
}

static void expect_valid(const poly_list *p, bool convex, double s, const char *what)
{
    noctError err;
    bool got = !convex;
    noctStatus st = try_convex(p, &got, &err);
    ck_assert_msg(st == NOCT_OK, "%s at scale %g: %s", what, s,
                  st == NOCT_OK ? "" : err.message);
    ck_assert_msg(got == convex, "%s at scale %g: convex %d", what, s, got);
}

static void expect_refused(const poly_list *p, noctStatus want, const char *why, double s,
                           const char *what)
{
    noctError err;
    bool convex;
    noctStatus st = try_convex(p, &convex, &err);
    ck_assert_msg(st == want, "%s at scale %g: got %s, want %s", what, s,
                  noctStatusString(st), noctStatusString(want));
    ck_assert_msg(strstr(err.message, why) != NULL, "%s at scale %g: '%s' does not say '%s'",
                  what, s, err.message, why);
}

/* Boxes, tetrahedra and an L-shaped prism are valid at every scale, with
 * their convexity; their degenerate, bent and non-convex variants are
 * refused for that reason at every scale; and the polygon tolerance is
 * relative to the polygon: a face bent by 2^-33 of its size passes and
 * one bent by 2^-24 does not, a box 1e-6 thin passes and one 1e-10 thin
 * has faces without area, whatever the scale. */
START_TEST(meshes_at_every_scale)
{
    double lo[3] = {-1, -1, -1}, hi[3] = {1, 1, 1};
    const poly_list box = pl_box(lo, hi);
    const double reg[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const double skew[4][3] = {{1, 2, 3}, {-2, 1, 0}, {0, -3, 1}, {2, 2, -2}};
    const poly_list tet = pl_tetra(reg), sk = pl_tetra(skew);
    const poly_list ell = pl_lprism(true), lcap = pl_lprism(false);
    const double flat_pts[4][3] = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {2, 2, 0}};
    const double line_pts[4][3] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 1}};
    const poly_list flat = pl_tetra(flat_pts), line = pl_tetra(line_pts);
    poly_list bent = box, nearly = box, thin = box, slab = box;
    /* corner (1, 1, 1) into the box, off the face x = 1: the faces' fan
     * diagonals from corner 7 fold inwards */
    bent.v[3 * 7] -= 0x1p-23;
    nearly.v[3 * 7] -= 0x1p-32;
    for (int i = 0; i < 8; ++i) {
        thin.v[3 * i + 2] *= 1e-10;
        slab.v[3 * i + 2] *= 1e-6;
    }
    for (size_t i = 0; i < NSCALES; ++i) {
        double s = SCALES[i];
        poly_list p;
        p = pl_scaled(&box, s);
        expect_valid(&p, true, s, "box");
        p = pl_scaled(&tet, s);
        expect_valid(&p, true, s, "tetrahedron");
        p = pl_scaled(&sk, s);
        expect_valid(&p, true, s, "skew tetrahedron");
        p = pl_scaled(&ell, s);
        expect_valid(&p, false, s, "L prism");
        p = pl_scaled(&nearly, s);
        expect_valid(&p, false, s, "box bent by 2^-33");
        p = pl_scaled(&slab, s);
        expect_valid(&p, true, s, "slab 1e-6 thin");
        p = pl_scaled(&flat, s);
        expect_refused(&p, NOCT_ERR_DEGENERATE, "volume", s, "flat tetrahedron");
        p = pl_scaled(&line, s);
        expect_refused(&p, NOCT_ERR_DEGENERATE, "no area", s, "collinear face");
        p = pl_scaled(&thin, s);
        expect_refused(&p, NOCT_ERR_DEGENERATE, "no area", s, "box 1e-10 thin");
        p = pl_scaled(&bent, s);
        expect_refused(&p, NOCT_ERR_NONPLANAR, "plane", s, "box bent by 2^-24");
        p = pl_scaled(&lcap, s);
        expect_refused(&p, NOCT_ERR_NONCONVEX, "not convex", s, "L-shaped face");
    }
}
END_TEST

/* The box constructors over the documented range: what they accept, and
 * what they refuse for the reasons their documentation gives. */
START_TEST(box_constructors_at_every_scale)
{
    static const double sizes[] = {0x1p-1022, 1e-300, 1e-150, 1e75, 1e99, 1e100};
    /* a rotation about no axis of the frame (entries rounded) */
    const double rot[9] = {0.36, -0.48, 0.8, 0.8, 0.6, 0, -0.48, 0.64, 0.6};
    noctMesh *m = NULL;
    noctError err;
    for (size_t i = 0; i < sizeof sizes / sizeof *sizes; ++i) {
        double s = sizes[i];
        noctStatus st = noctMeshCreateBox(s, s / 2, s * 0x1p-28, &m, &err);
        ck_assert_msg(st == NOCT_OK, "box %g: %s", s, st == NOCT_OK ? "" : err.message);
        ck_assert(noctMeshIsConvex(m));
        double lo[3], hi[3];
        noctMeshBounds(m, lo, hi);
        ck_assert(lo[0] == -s && hi[1] == s / 2 && hi[2] == s * 0x1p-28);
        noctMeshDestroy(m);
        ck_assert_int_eq(noctMeshCreateBox(s * 0x1p-30, s, s, &m, &err), NOCT_ERR_DEGENERATE);
        ck_assert_ptr_null(m);
        ck_assert_msg(strstr(err.message, "thin") != NULL, "%s", err.message);
        if (s > 1e99)
            continue; /* its rotated corners go past the limit */
        const double half[3] = {s < 1 ? 4 * s : s, s < 1 ? 2 * s : s / 2, s < 1 ? s : s / 4};
        st = noctMeshCreateOrientedBox(half, rot, &m, &err);
        ck_assert_msg(st == NOCT_OK, "oriented box %g: %s", s, st == NOCT_OK ? "" : err.message);
        noctMeshDestroy(m);
        const double sliver[3] = {s < 1 ? s * 0x1p30 : s, s < 1 ? s * 0x1p30 : s,
                                  s < 1 ? s : s * 0x1p-30};
        ck_assert_int_eq(noctMeshCreateOrientedBox(sliver, rot, &m, &err), NOCT_ERR_DEGENERATE);
        ck_assert_msg(strstr(err.message, "thin") != NULL, "%s", err.message);
    }
    /* subnormal half-extents are fine: the corners are exact */
    ck_assert_int_eq(noctMeshCreateBox(0x1p-1074, 0x1p-1074, 0x1p-1073, &m, &err), NOCT_OK);
    ck_assert(noctMeshIsConvex(m));
    noctMeshDestroy(m);
    ck_assert_int_eq(noctMeshCreateBox(2e100, 1e100, 1e100, &m, &err), NOCT_ERR_TOO_LARGE);
    ck_assert_ptr_null(m);
    const double huge[3] = {1e100, 1e100, 1e100};
    ck_assert_int_eq(noctMeshCreateOrientedBox(huge, rot, &m, &err), NOCT_ERR_TOO_LARGE);
    const double below[3] = {1, 1, 0x1p-1030};
    ck_assert_int_eq(noctMeshCreateOrientedBox(below, rot, &m, &err), NOCT_ERR_INVALID);
    ck_assert_ptr_null(m);
}
END_TEST

/* The exact level's answer, both ways round, must be want, and the box
 * level must not miss it. (Not the convex level: libccd's GJK has
 * absolute tolerances.) */
static void expect_exact(const noctMesh *a, const double ta[3], const noctMesh *b,
                         const double tb[3], bool want)
{
    bool ab = collide(a, ta, b, tb, NOCT_ACCURACY_EXACT);
    bool ba = collide(b, tb, a, ta, NOCT_ACCURACY_EXACT);
    ck_assert_msg(ab == want && ba == want, "exact: got %d/%d, want %d", ab, ba, want);
    if (want)
        ck_assert(collide(a, ta, b, tb, NOCT_ACCURACY_BOX));
}

/* Two boxes of each scale (the power of two at or below it, so that the
 * placements are exact) touch, overlap and miss exactly as at scale 1:
 * the exact level on meshes at the ends of the range. */
START_TEST(collide_at_every_scale)
{
    for (size_t i = 0; i < NSCALES; ++i) {
        double s = ldexp(1, ilogb(SCALES[i]));
        noctMesh *a, *b;
        ck_assert_int_eq(noctMeshCreateBox(s, s, s, &a, NULL), NOCT_OK);
        ck_assert_int_eq(noctMeshCreateBox(s / 2, s / 4, s, &b, NULL), NOCT_OK);
        const double touch[3] = {1.5 * s, 0.5 * s, 0}, over[3] = {1.25 * s, 0.5 * s, 0};
        const double miss[3] = {1.5 * s * (1 + 0x1p-40), 0.5 * s, 0};
        const double corner[3] = {1.5 * s, 1.25 * s, 2 * s};
        expect_exact(a, ORIGIN, b, touch, true);
        expect_exact(a, ORIGIN, b, over, true);
        expect_exact(a, ORIGIN, b, miss, false);
        expect_exact(a, ORIGIN, b, corner, true);
        noctMeshDestroy(a);
        noctMeshDestroy(b);
    }
}
END_TEST

/* The separating-axis filter has its axes, face normals and edge
 * directions, at every scale: two tetrahedra whose bounding boxes overlap
 * but which a face plane of one separates are told apart by the filter,
 * without a triangle test. (Not at 1e-300: the filter's margin is at
 * least 1e-300, to cover underflow, so there it never separates.) */
START_TEST(filter_axes_at_every_scale)
{
    const double reg[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const poly_list tet = pl_tetra(reg);
    static const double scales[] = {1e-150, 1, 1e75, 1e99};
    for (size_t i = 0; i < sizeof scales / sizeof *scales; ++i) {
        double s = scales[i];
        poly_list p = pl_scaled(&tet, s);
        noctMesh *m = pl_mesh(&p);
        const double t[3] = {0.6 * s, 0.6 * s, 0.6 * s};
        noctNarrowStats st = {0};
        bool hit = true;
        ck_assert_int_eq(noctCollide(m, ORIGIN, m, t, NOCT_ACCURACY_EXACT, &hit, &st), NOCT_OK);
        ck_assert(!hit);
        ck_assert_msg(st.sat_rejects == 1 && st.triangle_pairs == 0,
                      "scale %g: %llu filter rejects, %llu triangle pairs", s,
                      (unsigned long long)st.sat_rejects,
                      (unsigned long long)st.triangle_pairs);
        noctMeshDestroy(m);
    }
}
END_TEST

/* A rotation with rational entries (denominator 325), Rz Rx Rz for the
 * Pythagorean angles (3, 4, 5) and (5, 12, 13), times 325: a box whose
 * half-extents are 325 times integers has integer corners and exactly
 * planar faces. */
static void rational_rotation(long long r[9])
{
    const long long z[9] = {3, -4, 0, 4, 3, 0, 0, 0, 5};      /* / 5 */
    const long long x[9] = {13, 0, 0, 0, 5, -12, 0, 12, 5};   /* / 13 */
    long long zx[9];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            zx[3 * i + j] = 0;
            for (int k = 0; k < 3; ++k)
                zx[3 * i + j] += z[3 * i + k] * x[3 * k + j];
        }
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            r[3 * i + j] = 0;
            for (int k = 0; k < 3; ++k)
                r[3 * i + j] += zx[3 * i + k] * z[3 * k + j];
        }
    /* an orthogonal matrix times 325: its columns are orthogonal and of
     * length 325 */
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            ck_assert(r[i] * r[j] + r[3 + i] * r[3 + j] + r[6 + i] * r[6 + j] ==
                      (i == j ? 325 * 325 : 0));
}

/* The tilted box: half-extents (3, 2, 1) * 325 rotated by that rotation,
 * scaled by 2^-12 (corners within 1/2 of the origin, on the 2^-12 grid),
 * as 6 exactly planar quadrilaterals; no face is parallel to an axis. */
static poly_list pl_tilted_box(void)
{
    long long r[9];
    rational_rotation(r);
    const long long h[3] = {3, 2, 1};
    poly_list p = {0};
    for (int i = 0; i < 8; ++i) {
        long long c[3];
        const long long s[3] = {(i & 4) ? 1 : -1, (i & 2) ? 1 : -1, (i & 1) ? 1 : -1};
        for (int k = 0; k < 3; ++k)
            c[k] = r[3 * k] * s[0] * h[0] + r[3 * k + 1] * s[1] * h[1] +
                   r[3 * k + 2] * s[2] * h[2];
        pl_vertex(&p, (double)c[0] * 0x1p-12, (double)c[1] * 0x1p-12, (double)c[2] * 0x1p-12);
    }
    static const uint32_t q[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                                     {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    for (int f = 0; f < 6; ++f)
        pl_poly(&p, 4, q[f]);
    return p;
}

/* A UV sphere of radius 1: 8 slices, 5 stacks, 64 triangles, its vertices
 * rounded to the 2^-12 grid (the finest that 2^40 + x keeps exact). */
static poly_list pl_sphere(void)
{
    const double pi = 3.14159265358979323846;
    poly_list p = {0};
    pl_vertex(&p, 0, 0, -1);
    for (int st = 1; st < 5; ++st) {
        double phi = pi * st / 5 - pi / 2, z = sin(phi), r = cos(phi);
        for (int sl = 0; sl < 8; ++sl) {
            double th = 2 * pi * sl / 8;
            pl_vertex(&p, round(r * cos(th) * 4096) / 4096, round(r * sin(th) * 4096) / 4096,
                      round(z * 4096) / 4096);
        }
    }
    pl_vertex(&p, 0, 0, 1);
    for (uint32_t sl = 0; sl < 8; ++sl) {
        uint32_t n = (sl + 1) % 8;
        const uint32_t bottom[3] = {0, 1 + n, 1 + sl}, top[3] = {33, 25 + sl, 25 + n};
        pl_poly(&p, 3, bottom);
        pl_poly(&p, 3, top);
        for (uint32_t st = 0; st < 3; ++st) {
            uint32_t a = 1 + 8 * st + sl, b = 1 + 8 * st + n;
            const uint32_t t1[3] = {a, b, b + 8}, t2[3] = {a, b + 8, a + 8};
            pl_poly(&p, 3, t1);
            pl_poly(&p, 3, t2);
        }
    }
    return p;
}

/* The vertex of p with the least z, which must be the only one there. */
static const double *lowest_vertex(const poly_list *p)
{
    size_t best = 0;
    for (size_t i = 1; i < p->nv; ++i)
        if (p->v[3 * i + 2] < p->v[3 * best + 2])
            best = i;
    for (size_t i = 0; i < p->nv; ++i)
        ck_assert(i == best || p->v[3 * i + 2] > p->v[3 * best + 2]);
    return &p->v[3 * best];
}

/* The tilted box and the sphere moved exactly to 1e6, 1e9 and 2^40 from
 * the origin are accepted as at the origin, with the same convexity, and
 * a cube under their lowest vertex touches them, overlaps them when
 * raised and misses them when lowered by 2^-10, wherever they are. */
START_TEST(meshes_at_every_position)
{
    static const double offsets[] = {0, 1e6, 1e9, 0x1p40};
    const poly_list shapes[2] = {pl_tilted_box(), pl_sphere()};
    static const char *const names[2] = {"tilted box", "sphere"};
    noctMesh *cube;
    ck_assert_int_eq(noctMeshCreateBox(0.25, 0.25, 0.25, &cube, NULL), NOCT_OK);
    for (int k = 0; k < 2; ++k) {
        bool convex0 = false;
        for (size_t i = 0; i < sizeof offsets / sizeof *offsets; ++i) {
            double off = offsets[i];
            poly_list p = pl_moved(&shapes[k], off);
            noctError err;
            noctMesh *m = NULL;
            noctStatus st = noctMeshCreate(p.v, p.nv, p.sizes, p.np, p.idx, &m, &err);
            ck_assert_msg(st == NOCT_OK, "%s at %g: %s", names[k], off,
                          st == NOCT_OK ? "" : err.message);
            if (i == 0)
                convex0 = noctMeshIsConvex(m);
            ck_assert_msg(noctMeshIsConvex(m) == convex0, "%s at %g: convexity", names[k], off);
            const double *low = lowest_vertex(&p);
            const double touch[3] = {low[0], low[1], low[2] - 0.25};
            const double over[3] = {low[0], low[1], touch[2] + 0x1p-10};
            const double miss[3] = {low[0], low[1], touch[2] - 0x1p-10};
            expect_pair(m, ORIGIN, cube, touch, true, false);
            expect_pair(m, ORIGIN, cube, over, true, true);
            expect_pair(m, ORIGIN, cube, miss, false, false);
            noctMeshDestroy(m);
        }
        if (k == 0)
            ck_assert(convex0);
    }
    noctMeshDestroy(cube);
}
END_TEST

#ifndef NOCT_EFFICIENT
START_TEST(die_null_arguments)
{
    noctMesh *m = NULL;
    bool hit;
    double lo[3];
    noctMeshCreateBox(1, 1, 1, &m, NULL);
    switch (_i) {
    case 0: noctMeshCreate(NULL, 0, NULL, 0, NULL, NULL, NULL); break;
    case 1: noctCollide(m, NULL, m, ORIGIN, NOCT_ACCURACY_BOX, &hit, NULL); break;
    case 2: noctCollide(m, ORIGIN, m, ORIGIN, NOCT_ACCURACY_BOX, NULL, NULL); break;
    case 3: noctMeshBounds(m, lo, NULL); break;
    case 4: noctMeshRead(NULL, &m, NULL); break;
    default: noctMeshCreateBox(1, 1, 1, NULL, NULL); break;
    }
}
END_TEST
#endif

static Suite *narrowphase_suite(void)
{
    Suite *s = suite_create("narrowphase");
    TCase *tc = test_case(s, "hard cases", 300, NULL);
    add_tests(tc, faces_exactly_touching, edges_crossing_at_a_point, vertex_exactly_on_face,
              coplanar_overlapping_faces, parallel_and_nearly_parallel, tilted_boxes_near_contact,
              tiny_and_far, containment_and_identity);

    tc = test_case(s, "random against brute force", 300, NULL);
    tcase_add_loop_test(tc, random_tetrahedra_against_sat, 0, 4);
    tcase_add_loop_test(tc, random_coplanar_bases_against_sat, 0, 4);
    tcase_add_loop_test(tc, random_star_meshes_against_cones, 0, 4);
    tcase_add_loop_test(tc, turned_views_match_rotated_meshes, 0, 2);
    tcase_add_loop_test(tc, pieces_inside_another_solid, 0, 2);
    tcase_add_loop_test(tc, turned_pairs_match_placed_meshes, 0, 4);
    tcase_add_test(tc, convex_level_one_sided);

    tc = test_case(s, "meshes and files", 0, NULL);
    add_tests(tc, bad_meshes_are_rejected, box_constructors, read_off_files, read_obj_files,
              status_strings, collide_rejects_bad_input, sat_filter_rejects_soundly);
    tcase_add_loop_test(tc, sat_filter_rotated_boxes, 0, 2);
    add_tests(tc, sat_filter_nearly_a_box, witness_nearly_a_box, level_timings);

    tc = test_case(s, "scale and position", 60, NULL);
    add_tests(tc, meshes_at_every_scale, box_constructors_at_every_scale, collide_at_every_scale,
              filter_axes_at_every_scale, meshes_at_every_position);

#ifndef NOCT_EFFICIENT
    TCase *d = test_case(s, "requires clauses", 0, "death");
    tcase_add_loop_test_raise_signal(d, die_null_arguments, SIGABRT, 0, 6);
#endif
    return s;
}

int main(void)
{
    return run_suite(narrowphase_suite());
}
