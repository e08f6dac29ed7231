/* SPDX-License-Identifier: MIT */
/*
 * Surfaces (noctMeshCreateSurface()) through every path of the library,
 * against the test's own expectations:
 * - an open box, a closed-surface box and solid cubes: a surface inside a
 *   solid meets it, a solid inside a closed surface does not (a surface
 *   encloses nothing), touching at dyadic coordinates meets, at every
 *   accuracy level (box and convex conservative), turned or not;
 * - random triangle soups on a grid of dyadic coordinates (many touching
 *   and coplanar cases) against the test's own exact separating-axis
 *   decision in 64-bit integers (two closed triangles, or a triangle and
 *   a box, are disjoint iff one of the axes of their thin prisms
 *   separates them strictly), and the box and convex levels conservative
 *   against the exact one;
 * - a world of surfaces and solid boxes against the pairwise call and the
 *   integer decision, and its point queries (on a surface) against them;
 *   turned soups in a world with a margin against noctCollideTransformed()
 *   and noctDistance(), turned again (the world's recycled copies); a
 *   continuous world catching a fast cube on a closed surface's wall;
 * - noctDistance() on surfaces against a brute force over every triangle
 *   pair in long double, and 0 / the gap for containment;
 * - noctCollideSwept() against exact tests at sampled times, and the
 *   closed-form time of a cube inside a closed surface hitting its wall;
 *   noctCollideSweptTransformed() conservative on the same samples;
 * - noctCollideContact() on surfaces; ray hits, shape queries and shape
 *   casts on surfaces;
 * - scene files: `mesh NAME file PATH surface` (and `solid`), written back
 *   as read;
 * - errors: bad surfaces refused with the solid's statuses and messages,
 *   and the hint of a solid asked of an open mesh; noctMeshReadSurface().
 */
#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <noctree.h>

#include "testutil.h"

static uint64_t rng = 20261127;

/* ---- meshes ------------------------------------------------------------------------ */

/* The cube [lo, lo + s]^3 as 6 quads, outward; with open set, the top
 * (z = lo + s) left out. */
static noctMesh *cube(double lo, double s, bool surface, bool open)
{
    double v[24];
    for (int i = 0; i < 8; ++i) {
        v[3 * i] = lo + ((i & 4) ? s : 0);
        v[3 * i + 1] = lo + ((i & 2) ? s : 0);
        v[3 * i + 2] = lo + ((i & 1) ? s : 0);
    }
    static const uint32_t quads[24] = {0, 1, 3, 2, 4, 6, 7, 5, 0, 4, 5, 1,
                                       2, 3, 7, 6, 0, 2, 6, 4, 1, 5, 7, 3};
    const uint32_t sizes[6] = {4, 4, 4, 4, 4, 4};
    noctMesh *m = NULL;
    noctError err = {0};
    const noctStatus st = surface ? noctMeshCreateSurface(v, 8, sizes, open ? 5 : 6, quads, &m,
                                                          &err)
                                  : noctMeshCreate(v, 8, sizes, 6, quads, &m, &err);
    ck_assert_msg(st == NOCT_OK, "%s", err.message);
    return m;
}

/* A soup of nt triangles with integer corners c (9 per triangle), scaled
 * by 1/4 (exact): a surface. */
static noctMesh *soup(const long long *c, size_t nt)
{
    double *v = malloc(9 * nt * sizeof *v);
    uint32_t *idx = malloc(3 * nt * sizeof *idx), *sizes = malloc(nt * sizeof *sizes);
    ck_assert(v != NULL && idx != NULL && sizes != NULL);
    for (size_t i = 0; i < 9 * nt; ++i)
        v[i] = (double)c[i] / 4;
    for (size_t i = 0; i < 3 * nt; ++i)
        idx[i] = (uint32_t)i;
    for (size_t i = 0; i < nt; ++i)
        sizes[i] = 3;
    noctMesh *m = NULL;
    noctError err = {0};
    ck_assert_msg(noctMeshCreateSurface(v, 3 * nt, sizes, nt, idx, &m, &err) == NOCT_OK, "%s",
                  err.message);
    free(v);
    free(idx);
    free(sizes);
    return m;
}

static bool collide(const noctMesh *a, const double ta[3], const noctMesh *b,
                    const double tb[3], noctAccuracy level)
{
    bool hit = false;
    ck_assert_int_eq(noctCollide(a, ta, b, tb, level, &hit, NULL), NOCT_OK);
    return hit;
}

/* The exact verdict, checked symmetric, with the box and convex levels
 * conservative against it. */
static bool exact_checked(const noctMesh *a, const double ta[3], const noctMesh *b,
                          const double tb[3])
{
    const bool hit = collide(a, ta, b, tb, NOCT_ACCURACY_EXACT);
    ck_assert(collide(b, tb, a, ta, NOCT_ACCURACY_EXACT) == hit);
    if (hit) {
        ck_assert(collide(a, ta, b, tb, NOCT_ACCURACY_BOX));
        ck_assert(collide(a, ta, b, tb, NOCT_ACCURACY_CONVEX));
        ck_assert(collide(b, tb, a, ta, NOCT_ACCURACY_CONVEX));
    }
    return hit;
}

/* ---- the test's exact decision: separating axes in integers ------------------------- */

typedef long long ll;

static void isub(const ll a[3], const ll b[3], ll o[3])
{
    for (int k = 0; k < 3; ++k)
        o[k] = a[k] - b[k];
}

static void icross(const ll a[3], const ll b[3], ll o[3])
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

static ll idot(const ll a[3], const ll b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Does axis u separate point sets P and Q strictly? */
static bool separates(const ll (*P)[3], int np, const ll (*Q)[3], int nq, const ll u[3])
{
    if (u[0] == 0 && u[1] == 0 && u[2] == 0)
        return false;
    ll plo = idot(P[0], u), phi = plo, qlo = idot(Q[0], u), qhi = qlo;
    for (int i = 1; i < np; ++i) {
        const ll d = idot(P[i], u);
        plo = d < plo ? d : plo;
        phi = d > phi ? d : phi;
    }
    for (int i = 1; i < nq; ++i) {
        const ll d = idot(Q[i], u);
        qlo = d < qlo ? d : qlo;
        qhi = d > qhi ? d : qhi;
    }
    return phi < qlo || qhi < plo;
}

/* The directions of a thin prism over a triangle: its normal and the
 * normals of its sides (faces, 4), its edges and the normal (edges, 4). */
static void prism(const ll T[3][3], ll face[4][3], ll edge[4][3])
{
    for (int i = 0; i < 3; ++i)
        isub(T[(i + 1) % 3], T[i], edge[i]);
    icross(edge[0], edge[1], face[0]);
    for (int k = 0; k < 3; ++k)
        edge[3][k] = face[0][k];
    for (int i = 0; i < 3; ++i)
        icross(face[0], edge[i], face[i + 1]);
}

/* Do the closed triangles A and B meet? (Non-degenerate, integer.) */
static bool itri_tri(const ll A[3][3], const ll B[3][3])
{
    ll fa[4][3], ea[4][3], fb[4][3], eb[4][3];
    prism(A, fa, ea);
    prism(B, fb, eb);
    for (int i = 0; i < 4; ++i)
        if (separates(A, 3, B, 3, fa[i]) || separates(A, 3, B, 3, fb[i]))
            return false;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            ll u[3];
            icross(ea[i], eb[j], u);
            if (separates(A, 3, B, 3, u))
                return false;
        }
    return true;
}

/* Does the closed triangle T meet the closed box [lo, hi]? */
static bool itri_box(const ll T[3][3], const ll lo[3], const ll hi[3])
{
    ll B[8][3];
    for (int i = 0; i < 8; ++i)
        for (int k = 0; k < 3; ++k)
            B[i][k] = (i >> (2 - k)) & 1 ? hi[k] : lo[k];
    ll f[4][3], e[4][3];
    prism(T, f, e);
    for (int i = 0; i < 4; ++i)
        if (separates(T, 3, (const ll(*)[3])B, 8, f[i]))
            return false;
    for (int a = 0; a < 3; ++a) {
        ll x[3] = {0, 0, 0};
        x[a] = 1;
        if (separates(T, 3, (const ll(*)[3])B, 8, x))
            return false;
        for (int i = 0; i < 4; ++i) {
            ll u[3];
            icross(x, e[i], u);
            if (separates(T, 3, (const ll(*)[3])B, 8, u))
                return false;
        }
    }
    return true;
}

/* A random non-degenerate integer triangle in [lo, lo + span)^3; with
 * flat set, on the plane z = lo (coplanar cases). */
static void random_triangle(ll T[3][3], ll lo, ll span, bool flat)
{
    for (;;) {
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < 3; ++k)
                T[i][k] = flat && k == 2 ? lo : lo + (ll)test_rand_below(&rng, (size_t)span);
        ll a[3], b[3], n[3];
        isub(T[1], T[0], a);
        isub(T[2], T[0], b);
        icross(a, b, n);
        if (n[0] != 0 || n[1] != 0 || n[2] != 0)
            return;
    }
}

/* ---- containment: open and closed boxes ---------------------------------------------- */

START_TEST(kinds_and_containment)
{
    noctMesh *big_solid = cube(0, 4, false, false);
    noctMesh *big_closed = cube(0, 4, true, false);
    noctMesh *big_open = cube(0, 4, true, true);
    noctMesh *small_solid = cube(1, 2, false, false);
    noctMesh *small_surface = cube(1, 2, true, false);
    noctMesh *box = NULL;
    ck_assert_int_eq(noctMeshCreateBox(1, 1, 1, &box, NULL), NOCT_OK);
    ck_assert(!noctMeshIsSurface(big_solid) && !noctMeshIsSurface(box));
    ck_assert(noctMeshIsSurface(big_closed) && noctMeshIsSurface(big_open));
    ck_assert(noctMeshIsConvex(big_solid) && !noctMeshIsConvex(big_closed));
    ck_assert(!noctMeshIsConvex(small_surface));
    ck_assert_uint_eq(noctMeshTriangleCount(big_open), 10);
    const double o[3] = {0, 0, 0};
    /* a solid inside a closed surface: apart (the surface encloses
     * nothing); the box and convex levels conservative: they meet */
    ck_assert(!exact_checked(big_closed, o, small_solid, o));
    ck_assert(!exact_checked(big_open, o, small_solid, o));
    ck_assert(collide(big_closed, o, small_solid, o, NOCT_ACCURACY_BOX));
    ck_assert(collide(big_closed, o, small_solid, o, NOCT_ACCURACY_CONVEX));
    ck_assert(!exact_checked(big_closed, o, small_surface, o));
    ck_assert(!exact_checked(big_closed, o, box, (const double[3]){2, 2, 2}));
    /* a surface inside a solid meets it */
    ck_assert(exact_checked(big_solid, o, small_surface, o));
    ck_assert(exact_checked(small_solid, o, small_surface, o));
    /* solids: unchanged */
    ck_assert(exact_checked(big_solid, o, small_solid, o));
    /* touching at dyadic coordinates: the small cube moved onto a wall
     * (x = 4: its face x in [3, 4] + 0.75 + 0.25) */
    const double touch[3] = {1, 0.25, 0.125};
    ck_assert(exact_checked(big_closed, o, small_solid, touch));
    ck_assert(exact_checked(big_closed, o, small_surface, touch));
    const double past[3] = {1 + 0x1p-40, 0.25, 0.125}; /* a hair beyond the wall */
    ck_assert(exact_checked(big_closed, o, small_solid, past));
    const double gone[3] = {3 + 0x1p-40, 0.25, 0.125}; /* wholly outside, apart */
    ck_assert(!exact_checked(big_closed, o, small_solid, gone));
    ck_assert(!exact_checked(big_closed, o, small_surface, gone));
    /* the open top: a cube through the opening touches no wall... */
    const double up[3] = {0, 0, 2.5}; /* [1, 3]^2 x [3.5, 5.5] */
    ck_assert(!exact_checked(big_open, o, small_solid, up));
    ck_assert(exact_checked(big_closed, o, small_solid, up));
    /* ...and coplanar touching: a square of the top plane z = 4 */
    const double top[3] = {0, 0, 3}; /* [1, 3]^2 x [4, 6] */
    ck_assert(exact_checked(big_closed, o, small_surface, top));
    ck_assert(!exact_checked(big_open, o, small_surface, top));
    const double edge[3] = {-2, 0, 3}; /* [-1, 1] x [1, 3] x [4, 6]: the rim */
    ck_assert(exact_checked(big_open, o, small_surface, edge));
    /* turned together about the big cube's centre: the small cube stays
     * inside, 1 from every wall */
    for (int i = 0; i < 20; ++i) {
        noctTransform xa = noctIdentityTransform(), xb = noctIdentityTransform();
        test_random_quat(&rng, &xa.q);
        xb.q = xa.q;
        double R[9];
        ck_assert_int_eq(noctQuatToMatrix(&xa.q, R, NULL), NOCT_OK);
        for (int k = 0; k < 3; ++k) /* centre c = (2,2,2) stays: p = c - R c */
            xa.p[k] = xb.p[k] = 2 - 2 * (R[3 * k] + R[3 * k + 1] + R[3 * k + 2]);
        bool hit;
        ck_assert_int_eq(noctCollideTransformed(big_closed, &xa, small_solid, &xb,
                                                NOCT_ACCURACY_EXACT, &hit, NULL, NULL),
                         NOCT_OK);
        ck_assert(!hit);
        ck_assert_int_eq(noctCollideTransformed(big_solid, &xa, small_surface, &xb,
                                                NOCT_ACCURACY_EXACT, &hit, NULL, NULL),
                         NOCT_OK);
        ck_assert(hit);
        ck_assert_int_eq(noctCollideTransformed(big_closed, &xa, small_solid, &xb,
                                                NOCT_ACCURACY_CONVEX, &hit, NULL, NULL),
                         NOCT_OK);
        ck_assert(hit);
    }
    noctMeshDestroy(big_solid);
    noctMeshDestroy(big_closed);
    noctMeshDestroy(big_open);
    noctMeshDestroy(small_solid);
    noctMeshDestroy(small_surface);
    noctMeshDestroy(box);
}
END_TEST

/* ---- random soups against the integer decision ------------------------------------- */

START_TEST(soups_against_integers)
{
    int met = 0, coplanar_met = 0;
    for (int trial = 0; trial < 600; ++trial) {
        const size_t na = 1 + test_rand_below(&rng, 4), nb = 1 + test_rand_below(&rng, 4);
        const bool flat = trial % 3 == 0;
        ll A[4][3][3], B[4][3][3];
        for (size_t i = 0; i < na; ++i)
            random_triangle(A[i], 0, 9, flat);
        for (size_t i = 0; i < nb; ++i)
            random_triangle(B[i], 0, 9, flat);
        noctMesh *a = soup(&A[0][0][0], na), *b = soup(&B[0][0][0], nb);
        /* B translated by an integer vector (times 1/4, exact) */
        ll shift[3];
        for (int k = 0; k < 3; ++k)
            shift[k] = flat && k == 2 ? 0 : (ll)test_rand_below(&rng, 9) - 4;
        bool want = false;
        for (size_t i = 0; i < na && !want; ++i)
            for (size_t j = 0; j < nb && !want; ++j) {
                ll T[3][3];
                for (int c = 0; c < 3; ++c)
                    for (int k = 0; k < 3; ++k)
                        T[c][k] = B[j][c][k] + shift[k];
                want = itri_tri((const ll(*)[3])A[i], (const ll(*)[3])T);
            }
        const double ta[3] = {0, 0, 0};
        const double tb[3] = {(double)shift[0] / 4, (double)shift[1] / 4, (double)shift[2] / 4};
        const bool got = exact_checked(a, ta, b, tb);
        ck_assert_msg(got == want, "trial %d: exact %d, integers %d", trial, got, want);
        met += want;
        coplanar_met += want && flat;
        /* the transformed call with identity rotations: the same */
        noctTransform xa = noctIdentityTransform(), xb = noctIdentityTransform();
        memcpy(xb.p, tb, sizeof tb);
        bool hit;
        ck_assert_int_eq(noctCollideTransformed(a, &xa, b, &xb, NOCT_ACCURACY_EXACT, &hit, NULL,
                                                NULL), NOCT_OK);
        ck_assert(hit == want);
        noctMeshDestroy(a);
        noctMeshDestroy(b);
    }
    /* the sample holds both answers, coplanar meetings included */
    ck_assert_int_gt(met, 100);
    ck_assert_int_lt(met, 550);
    ck_assert_int_gt(coplanar_met, 30);
}
END_TEST

START_TEST(soups_against_solid_boxes)
{
    int met = 0, inside = 0;
    for (int trial = 0; trial < 600; ++trial) {
        const size_t na = 1 + test_rand_below(&rng, 3);
        ll A[3][3][3];
        for (size_t i = 0; i < na; ++i)
            random_triangle(A[i], 0, 9, trial % 4 == 0);
        noctMesh *a = soup(&A[0][0][0], na);
        /* a box of integer (times 1/4) half-extents and centre */
        ll h[3], c[3], lo[3], hi[3];
        for (int k = 0; k < 3; ++k) {
            const bool big = trial % 5 == 1; /* often around the whole soup */
            h[k] = big ? 5 : 1 + (ll)test_rand_below(&rng, 6);
            c[k] = big ? 4 : (ll)test_rand_below(&rng, 13) - 2;
            lo[k] = c[k] - h[k];
            hi[k] = c[k] + h[k];
        }
        noctMesh *b = NULL;
        ck_assert_int_eq(noctMeshCreateBox((double)h[0] / 4, (double)h[1] / 4, (double)h[2] / 4,
                                           &b, NULL), NOCT_OK);
        bool want = false, all_in = true;
        for (size_t i = 0; i < na; ++i) {
            want = want || itri_box((const ll(*)[3])A[i], lo, hi);
            for (int v = 0; v < 3; ++v)
                for (int k = 0; k < 3; ++k)
                    all_in = all_in && lo[k] < A[i][v][k] && A[i][v][k] < hi[k];
        }
        const double ta[3] = {0, 0, 0};
        const double tb[3] = {(double)c[0] / 4, (double)c[1] / 4, (double)c[2] / 4};
        const bool got = exact_checked(a, ta, b, tb);
        ck_assert_msg(got == want, "trial %d: exact %d, integers %d", trial, got, want);
        met += want;
        inside += all_in;
        noctMeshDestroy(a);
        noctMeshDestroy(b);
    }
    ck_assert_int_gt(met, 100);
    ck_assert_int_lt(met, 550);
    ck_assert_int_gt(inside, 50); /* soups wholly inside a box: met by containment */
}
END_TEST

/* ---- the world ------------------------------------------------------------------------ */

#define WN 24

static bool count_hit(void *context, noctObjectId id, void *user)
{
    (void)id;
    ++*(int *)context;
    (void)user;
    return true;
}

START_TEST(world_against_pairs)
{
    for (int round = 0; round < 6; ++round) {
        noctWorldDef wd = noctDefaultWorldDef();
        wd.effects = NOCT_EFFECT_EVENTS;
        wd.accuracy = round % 3 == 0 ? NOCT_ACCURACY_CONVEX : NOCT_ACCURACY_EXACT;
        noctWorld *w = NULL;
        ck_assert_int_eq(noctWorldCreate(&wd, &w, NULL), NOCT_OK);
        noctMesh *mesh[WN];
        ll tri[WN][2][3][3];
        size_t nt[WN];
        ll shift[WN][3];
        bool is_box[WN];
        ll lo[WN][3], hi[WN][3];
        noctObjectId id[WN];
        for (int i = 0; i < WN; ++i) {
            for (int k = 0; k < 3; ++k)
                shift[i][k] = (ll)test_rand_below(&rng, 24);
            is_box[i] = i % 4 == 3;
            noctObjectDef d = noctDefaultObjectDef();
            if (is_box[i]) {
                ll h[3];
                for (int k = 0; k < 3; ++k) {
                    h[k] = 1 + (ll)test_rand_below(&rng, 4);
                    lo[i][k] = shift[i][k] - h[k];
                    hi[i][k] = shift[i][k] + h[k];
                }
                ck_assert_int_eq(noctMeshCreateBox((double)h[0] / 4, (double)h[1] / 4,
                                                   (double)h[2] / 4, &mesh[i], NULL), NOCT_OK);
                nt[i] = 0;
            } else {
                nt[i] = 1 + test_rand_below(&rng, 2);
                for (size_t t = 0; t < nt[i]; ++t)
                    random_triangle(tri[i][t], 0, 7, i % 5 == 0);
                mesh[i] = soup(&tri[i][0][0][0], nt[i]);
            }
            d.mesh = mesh[i];
            d.type = NOCT_OBJECT_STATIC;
            d.sensor = i % 7 == 6;
            for (int k = 0; k < 3; ++k)
                d.transform.p[k] = (double)shift[i][k] / 4;
            ck_assert_int_eq(noctWorldCreateObject(w, &d, &id[i], NULL), NOCT_OK);
        }
        ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
        bool want[WN][WN];
        int nwant = 0, nsense = 0;
        for (int i = 0; i < WN; ++i)
            for (int j = i + 1; j < WN; ++j) {
                /* the integer decision over the placed triangles */
                bool m = false;
                for (int s = 0; s < 2 && !m; ++s) {
                    const int p = s ? j : i, q = s ? i : j;
                    if (is_box[p] && is_box[q]) {
                        bool ov = true;
                        for (int k = 0; k < 3; ++k)
                            ov = ov && lo[p][k] <= hi[q][k] && lo[q][k] <= hi[p][k];
                        m = ov;
                        break;
                    }
                    if (is_box[p])
                        continue;
                    for (size_t t = 0; t < nt[p] && !m; ++t) {
                        ll T[3][3];
                        for (int c = 0; c < 3; ++c)
                            for (int k = 0; k < 3; ++k)
                                T[c][k] = tri[p][t][c][k] + shift[p][k];
                        if (is_box[q]) {
                            m = itri_box((const ll(*)[3])T, lo[q], hi[q]);
                            continue;
                        }
                        for (size_t u = 0; u < nt[q] && !m; ++u) {
                            ll U[3][3];
                            for (int c = 0; c < 3; ++c)
                                for (int k = 0; k < 3; ++k)
                                    U[c][k] = tri[q][u][c][k] + shift[q][k];
                            m = itri_tri((const ll(*)[3])T, (const ll(*)[3])U);
                        }
                    }
                }
                double pi[3], pj[3];
                for (int k = 0; k < 3; ++k) {
                    pi[k] = (double)shift[i][k] / 4;
                    pj[k] = (double)shift[j][k] / 4;
                }
                bool pair = collide(mesh[i], pi, mesh[j], pj, wd.accuracy);
                if (wd.accuracy == NOCT_ACCURACY_EXACT)
                    ck_assert_msg(pair == m, "pair %d %d: pairwise %d, integers %d", i, j, pair,
                                  m);
                else
                    ck_assert(pair || !m);
                want[i][j] = pair;
                const bool sensing = i % 7 == 6 || j % 7 == 6;
                nwant += pair && !sensing;
                nsense += pair && sensing;
            }
        const noctPair *got;
        const size_t ngot = noctWorldColliding(w, &got);
        ck_assert_uint_eq(ngot, (size_t)nwant);
        for (size_t p = 0; p < ngot; ++p)
            ck_assert(want[got[p].a.index][got[p].b.index]);
        ck_assert_uint_eq(noctWorldSensing(w, &got), (size_t)nsense);
        ck_assert_uint_eq(noctWorldBegan(w, &got), (size_t)nwant);
        /* point queries: a surface's vertex is on it; the centre of a
         * triangle's circumscribed box, off a non-flat... only by the
         * integer decision: count objects holding each soup's vertex */
        for (int i = 0; i < WN; ++i) {
            if (is_box[i])
                continue;
            const double p[3] = {(double)(tri[i][0][1][0] + shift[i][0]) / 4,
                                 (double)(tri[i][0][1][1] + shift[i][1]) / 4,
                                 (double)(tri[i][0][1][2] + shift[i][2]) / 4};
            ll P[3][3];
            for (int c = 0; c < 3; ++c)
                for (int k = 0; k < 3; ++k)
                    P[c][k] = tri[i][0][1][k] + shift[i][k];
            int expect = 0;
            for (int j = 0; j < WN; ++j) {
                bool on = false;
                if (is_box[j]) {
                    on = true;
                    for (int k = 0; k < 3; ++k)
                        on = on && lo[j][k] <= P[0][k] && P[0][k] <= hi[j][k];
                } else {
                    /* the point as a degenerate triangle: on a triangle
                     * iff no axis of that triangle's prism separates */
                    for (size_t t = 0; t < nt[j] && !on; ++t) {
                        ll T[3][3], f[4][3], e[4][3];
                        for (int c = 0; c < 3; ++c)
                            for (int k = 0; k < 3; ++k)
                                T[c][k] = tri[j][t][c][k] + shift[j][k];
                        prism((const ll(*)[3])T, f, e);
                        on = true;
                        for (int a = 0; a < 4 && on; ++a)
                            on = !separates((const ll(*)[3])T, 3, (const ll(*)[3])P, 1, f[a]);
                    }
                }
                expect += on;
            }
            int n = 0;
            ck_assert_int_eq(noctWorldQueryPoint(w, p, (noctQueryFilter){~0ull, ~0ull}, count_hit,
                                                 &n, NULL), NOCT_OK);
            ck_assert_int_eq(n, expect);
        }
        noctWorldDestroy(w);
        for (int i = 0; i < WN; ++i)
            noctMeshDestroy(mesh[i]);
    }
}
END_TEST

/* A random soup of nt triangles near c, of size about s (real coordinates). */
static noctMesh *real_soup(size_t nt, const double c[3], double s, double *v);

/* Turned soups and boxes in a world with a margin: its colliding pairs
 * are noctCollideTransformed()'s, its near pairs those noctDistance()
 * proves within the margin; turned again (the world's recycled turned
 * copies), the same. */
START_TEST(world_turned_and_near)
{
    enum { N = 16 };
    const double margin = 0.25;
    noctWorldDef wd = noctDefaultWorldDef();
    wd.effects = NOCT_EFFECT_EVENTS;
    wd.margin = margin;
    noctWorld *w = NULL;
    ck_assert_int_eq(noctWorldCreate(&wd, &w, NULL), NOCT_OK);
    noctMesh *mesh[N];
    noctTransform x[N];
    noctObjectId id[N];
    double v[72];
    for (int i = 0; i < N; ++i) {
        const double o[3] = {0, 0, 0};
        if (i % 4 == 3)
            ck_assert_int_eq(noctMeshCreateBox(0.3, 0.5, 0.4, &mesh[i], NULL), NOCT_OK);
        else
            mesh[i] = real_soup(1 + test_rand_below(&rng, 8), o, 1.5, v);
        x[i] = noctIdentityTransform();
        noctObjectDef d = noctDefaultObjectDef();
        d.mesh = mesh[i];
        d.type = NOCT_OBJECT_KINEMATIC;
        d.transform = x[i];
        ck_assert_int_eq(noctWorldCreateObject(w, &d, &id[i], NULL), NOCT_OK);
    }
    int colliding = 0, near = 0, apart = 0;
    for (int round = 0; round < 4; ++round) {
        for (int i = 0; i < N; ++i) {
            test_random_quat(&rng, &x[i].q);
            for (int k = 0; k < 3; ++k)
                x[i].p[k] = 3 * test_uniform(&rng);
            ck_assert_int_eq(noctWorldSetTransform(w, id[i], &x[i], NULL), NOCT_OK);
        }
        ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
        const noctPair *got, *gnear;
        const size_t ngot = noctWorldColliding(w, &got), nnear = noctWorldNear(w, &gnear);
        size_t want = 0, want_near = 0, gi = 0, ni = 0;
        for (int i = 0; i < N; ++i)
            for (int j = i + 1; j < N; ++j) {
                bool hit;
                ck_assert_int_eq(noctCollideTransformed(mesh[i], &x[i], mesh[j], &x[j],
                                                        NOCT_ACCURACY_EXACT, &hit, NULL, NULL),
                                 NOCT_OK);
                noctDistanceResult r;
                ck_assert_int_eq(noctDistance(mesh[i], &x[i], mesh[j], &x[j], INFINITY, &r, NULL,
                                              NULL), NOCT_OK);
                ck_assert(r.colliding == hit);
                const bool in_list = gi < ngot && got[gi].a.index == (uint32_t)i &&
                                     got[gi].b.index == (uint32_t)j;
                ck_assert_msg(in_list == hit, "round %d pair %d %d: world %d, pairwise %d",
                              round, i, j, in_list, hit);
                gi += in_list;
                want += hit;
                const bool is_near = ni < nnear && gnear[ni].a.index == (uint32_t)i &&
                                     gnear[ni].b.index == (uint32_t)j;
                ni += is_near;
                /* the margin's verdict is sure away from its edge */
                if (r.upper < margin * (1 - 1e-9))
                    ck_assert_msg(is_near, "pair %d %d at %g not near", i, j, r.upper);
                else if (r.lower > margin * (1 + 1e-9))
                    ck_assert_msg(!is_near, "pair %d %d at %g near", i, j, r.lower);
                want_near += is_near;
                colliding += hit;
                near += is_near && !hit;
                apart += !is_near;
            }
        ck_assert_uint_eq(ngot, want);
        ck_assert_uint_eq(nnear, want_near);
    }
    ck_assert_int_gt(colliding, 10);
    ck_assert_int_gt(near, 3);
    ck_assert_int_gt(apart, 10);
    noctWorldDestroy(w);
    for (int i = 0; i < N; ++i)
        noctMeshDestroy(mesh[i]);
}
END_TEST

/* A continuous world: a cube inside a closed surface, moving fast enough
 * to pass its wall within one step, is caught on the wall; one that moves
 * inside never touches it (no containment into a surface at the start). */
START_TEST(continuous_world)
{
    noctMesh *bay = cube(0, 4, true, false);
    noctMesh *small = cube(-0.5, 1, false, false);
    for (int fast = 0; fast < 2; ++fast) {
        noctWorldDef wd = noctDefaultWorldDef();
        wd.effects = NOCT_EFFECT_EVENTS | NOCT_EFFECT_MOTION;
        wd.accuracy = NOCT_ACCURACY_CONTINUOUS;
        noctWorld *w = NULL;
        ck_assert_int_eq(noctWorldCreate(&wd, &w, NULL), NOCT_OK);
        noctObjectDef d = noctDefaultObjectDef();
        d.mesh = bay;
        d.type = NOCT_OBJECT_STATIC;
        noctObjectId a, b;
        ck_assert_int_eq(noctWorldCreateObject(w, &d, &a, NULL), NOCT_OK);
        d.mesh = small;
        d.type = NOCT_OBJECT_MOVING;
        d.transform.p[0] = d.transform.p[1] = d.transform.p[2] = 2;
        d.velocity[0] = fast ? 8 : 0.5; /* from [1.5, 2.5]: past x = 4 in one step */
        ck_assert_int_eq(noctWorldCreateObject(w, &d, &b, NULL), NOCT_OK);
        ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
        const noctPair *p;
        ck_assert_uint_eq(noctWorldBegan(w, &p), fast ? 1 : 0);
        noctWorldDestroy(w);
    }
    noctMeshDestroy(bay);
    noctMeshDestroy(small);
}
END_TEST

/* ---- distances ------------------------------------------------------------------------ */

typedef long double ld;

/* A random soup of nt triangles near c, of size about s (real coordinates). */
static noctMesh *real_soup(size_t nt, const double c[3], double s, double *v)
{
    uint32_t idx[3 * 8], sizes[8];
    for (size_t i = 0; i < 9 * nt; ++i)
        v[i] = c[i % 3] + s * (test_uniform(&rng) - 0.5);
    for (size_t i = 0; i < 3 * nt; ++i)
        idx[i] = (uint32_t)i;
    for (size_t i = 0; i < nt; ++i)
        sizes[i] = 3;
    noctMesh *m = NULL;
    noctError err = {0};
    ck_assert_msg(noctMeshCreateSurface(v, 3 * nt, sizes, nt, idx, &m, &err) == NOCT_OK, "%s",
                  err.message);
    return m;
}

START_TEST(distance_against_brute_force)
{
    int apart = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const size_t na = 1 + test_rand_below(&rng, 8), nb = 1 + test_rand_below(&rng, 8);
        double va[72], vb[72];
        const double ca[3] = {0, 0, 0};
        const double cb[3] = {2 * test_uniform(&rng), 2 * test_uniform(&rng), test_uniform(&rng)};
        noctMesh *a = real_soup(na, ca, 1.5, va), *b = real_soup(nb, cb, 1.5, vb);
        noctTransform xa = noctIdentityTransform(), xb = noctIdentityTransform();
        noctDistanceResult r;
        ck_assert_int_eq(noctDistance(a, &xa, b, &xb, INFINITY, &r, NULL, NULL), NOCT_OK);
        ld best = INFINITY;
        for (size_t i = 0; i < na; ++i)
            for (size_t j = 0; j < nb; ++j) {
                ld x[3][3], y[3][3];
                for (int c = 0; c < 3; ++c)
                    for (int k = 0; k < 3; ++k) {
                        x[c][k] = va[9 * i + 3 * c + k];
                        y[c][k] = vb[9 * j + 3 * c + k];
                    }
                const ld d = test_tri_tri2(x, y);
                best = d < best ? d : best;
            }
        const ld ref = sqrtl(best);
        const bool hit = collide(a, ca, b, ca, NOCT_ACCURACY_EXACT);
        ck_assert(r.colliding == hit);
        if (hit) {
            /* crossing triangles: the pairs' distances miss the crossing,
             * but no pair can be apart by more than rounding where one
             * crosses: nothing to compare but 0 */
            ck_assert(r.distance == 0 && r.lower == 0 && r.upper == 0);
        } else {
            ++apart;
            ck_assert_msg(r.lower <= ref + 1e-12L && ref <= r.upper + 1e-12L,
                          "trial %d: [%.17g, %.17g] misses %.17Lg", trial, r.lower, r.upper, ref);
        }
        noctMeshDestroy(a);
        noctMeshDestroy(b);
    }
    ck_assert_int_gt(apart, 50);
    /* containment: a surface inside a solid meets it (0); a solid inside
     * a closed surface is 1 from it */
    noctMesh *big_closed = cube(0, 4, true, false), *small_solid = cube(1, 2, false, false);
    noctMesh *big_solid = cube(0, 4, false, false), *small_surface = cube(1, 2, true, false);
    noctTransform x = noctIdentityTransform();
    noctDistanceResult r;
    ck_assert_int_eq(noctDistance(big_closed, &x, small_solid, &x, INFINITY, &r, NULL, NULL),
                     NOCT_OK);
    ck_assert(!r.colliding);
    ck_assert(r.lower <= 1 && 1 <= r.upper && r.upper - r.lower < 1e-9);
    ck_assert_int_eq(noctDistance(big_solid, &x, small_surface, &x, INFINITY, &r, NULL, NULL),
                     NOCT_OK);
    ck_assert(r.colliding && r.distance == 0);
    ck_assert_int_eq(noctDistance(small_surface, &x, big_closed, &x, INFINITY, &r, NULL, NULL),
                     NOCT_OK);
    ck_assert(!r.colliding && r.lower <= 1 && 1 <= r.upper);
    noctMeshDestroy(big_closed);
    noctMeshDestroy(small_solid);
    noctMeshDestroy(big_solid);
    noctMeshDestroy(small_surface);
}
END_TEST

/* ---- continuous detection --------------------------------------------------------- */

START_TEST(swept_against_samples)
{
    enum { SAMPLES = 32 };
    int hits = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const size_t na = 1 + test_rand_below(&rng, 3), nb = 1 + test_rand_below(&rng, 3);
        ll A[3][3][3], B[3][3][3];
        for (size_t i = 0; i < na; ++i)
            random_triangle(A[i], 0, 9, trial % 4 == 0);
        for (size_t i = 0; i < nb; ++i)
            random_triangle(B[i], 0, 9, trial % 4 == 0);
        noctMesh *a = soup(&A[0][0][0], na);
        noctMesh *b = trial % 2 ? soup(&B[0][0][0], nb) : cube(0.5, 1, false, false);
        double ta0[3], ta1[3];
        const double tb[3] = {0, 0, 0};
        for (int k = 0; k < 3; ++k) {
            ta0[k] = trial % 4 == 0 && k == 2 ? 0 : ((double)test_rand_below(&rng, 17) - 8) / 4;
            ta1[k] = trial % 4 == 0 && k == 2 ? 0 : ((double)test_rand_below(&rng, 17) - 8) / 4;
        }
        bool swept;
        noctSweepHit h;
        ck_assert_int_eq(noctCollideSwept(a, ta0, ta1, b, tb, tb, &swept, &h, NULL), NOCT_OK);
        int first = -1;
        for (int s = 0; s <= SAMPLES && first < 0; ++s) {
            double t[3]; /* exact: quarters times s / 32 */
            for (int k = 0; k < 3; ++k)
                t[k] = ta0[k] + (ta1[k] - ta0[k]) * s / SAMPLES;
            if (collide(a, t, b, tb, NOCT_ACCURACY_EXACT))
                first = s;
        }
        if (first >= 0) {
            ++hits;
            ck_assert_msg(swept, "trial %d: sample %d collides, the sweep misses it", trial,
                          first);
            ck_assert(h.time <= (double)first / SAMPLES);
        }
        if (!swept)
            ck_assert(first < 0);
        /* turning level: conservative on the same motion */
        noctTransform x0 = noctIdentityTransform(), x1 = noctIdentityTransform(),
                      y = noctIdentityTransform();
        memcpy(x0.p, ta0, sizeof ta0);
        memcpy(x1.p, ta1, sizeof ta1);
        bool turning;
        ck_assert_int_eq(noctCollideSweptTransformed(a, &x0, &x1, b, &y, &y, &turning, NULL, NULL,
                                                     NULL), NOCT_OK);
        ck_assert(turning || !swept);
        noctMeshDestroy(a);
        noctMeshDestroy(b);
    }
    ck_assert_int_gt(hits, 30);
    /* a cube inside a closed surface: no contact at the start; it reaches
     * the wall x = 4 at time 1/2 (from [1, 3] by 2 a step), never if it
     * stays inside */
    noctMesh *big_closed = cube(0, 4, true, false), *small_solid = cube(1, 2, false, false);
    const double o[3] = {0, 0, 0}, end[3] = {2, 0, 0}, near_end[3] = {0.75, 0, 0.5};
    bool hit;
    noctSweepHit h;
    ck_assert_int_eq(noctCollideSwept(small_solid, o, end, big_closed, o, o, &hit, &h, NULL),
                     NOCT_OK);
    ck_assert(hit && h.time == 0.5);
    ck_assert_int_eq(noctCollideSwept(small_solid, o, near_end, big_closed, o, o, &hit, &h,
                                      NULL), NOCT_OK);
    ck_assert(!hit);
    noctMeshDestroy(big_closed);
    noctMeshDestroy(small_solid);
}
END_TEST

/* ---- contacts and rays ------------------------------------------------------------ */

START_TEST(contacts_and_rays)
{
    noctMesh *big_closed = cube(0, 4, true, false), *small_solid = cube(1, 2, false, false);
    noctMesh *big_solid = cube(0, 4, false, false), *small_surface = cube(1, 2, true, false);
    noctTransform x = noctIdentityTransform(), y = noctIdentityTransform();
    bool hit;
    noctContact c;
    ck_assert_int_eq(noctCollideContact(big_closed, &x, small_solid, &x, &hit, &c, NULL),
                     NOCT_OK);
    ck_assert(!hit && c.kind == NOCT_CONTACT_NONE && c.count == 0);
    ck_assert_int_eq(noctCollideContact(big_solid, &x, small_surface, &x, &hit, &c, NULL),
                     NOCT_OK);
    ck_assert(hit && c.kind != NOCT_CONTACT_NONE && c.contained && c.count > 0);
    for (unsigned i = 0; i < c.count; ++i) /* the points lie in both: on the small cube */
        for (int k = 0; k < 3; ++k)
            ck_assert(c.points[i][k] >= 1 && c.points[i][k] <= 3);
    y.p[0] = 1.5; /* the small cube [2.5, 4.5] x [1, 3]^2 crosses the wall x = 4 */
    ck_assert_int_eq(noctCollideContact(big_closed, &x, small_solid, &y, &hit, &c, NULL),
                     NOCT_OK);
    ck_assert(hit && c.kind != NOCT_CONTACT_NONE && !c.contained && c.count > 0);
    for (unsigned i = 0; i < c.count; ++i) /* on the wall, within the small cube */
        ck_assert(fabs(c.points[i][0] - 4) < 1e-12 && c.points[i][1] >= 1 - 1e-12 &&
                  c.points[i][1] <= 3 + 1e-12);
    /* rays in a world: from inside the closed surface, the wall is hit
     * at distance 1.5, its normal facing the ray's start */
    noctWorldDef wd = noctDefaultWorldDef();
    wd.effects = NOCT_EFFECT_EVENTS;
    noctWorld *w;
    ck_assert_int_eq(noctWorldCreate(&wd, &w, NULL), NOCT_OK);
    noctObjectDef d = noctDefaultObjectDef();
    d.mesh = big_closed;
    d.type = NOCT_OBJECT_STATIC;
    noctObjectId id;
    ck_assert_int_eq(noctWorldCreateObject(w, &d, &id, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    noctRayHit rh;
    memset(&rh, 0, sizeof rh);
    const double from[3] = {2.5, 2, 2}, dir[3] = {1, 0, 0};
    ck_assert_int_eq(noctWorldRayCastAlong(w, from, dir, 10, (noctQueryFilter){~0ull, ~0ull},
                                             &rh, &hit, NULL), NOCT_OK);
    ck_assert(hit);
    ck_assert(fabs(rh.point[0] - 4) < 1e-12);
    ck_assert(rh.normal[0] < -0.999);
    const double out[3] = {6, 2, 2}, back[3] = {-1, 0, 0};
    ck_assert_int_eq(noctWorldRayCastAlong(w, out, back, 10, (noctQueryFilter){~0ull, ~0ull},
                                             &rh, &hit, NULL), NOCT_OK);
    ck_assert(hit && fabs(rh.point[0] - 4) < 1e-12 && rh.normal[0] > 0.999);
    /* a point inside the closed surface is not on it; one on a wall is */
    int n = 0;
    ck_assert_int_eq(noctWorldQueryPoint(w, from, (noctQueryFilter){~0ull, ~0ull}, count_hit, &n,
                                         NULL), NOCT_OK);
    ck_assert_int_eq(n, 0);
    const double wall[3] = {4, 2.5, 1};
    ck_assert_int_eq(noctWorldQueryPoint(w, wall, (noctQueryFilter){~0ull, ~0ull}, count_hit, &n,
                                         NULL), NOCT_OK);
    ck_assert_int_eq(n, 1);
    /* shape queries: a cube inside the bay does not meet it, nor a
     * cube beside it; one across its wall does; a surface cube in it
     * neither. Cast along x, the cube inside reaches the wall x = 4 at
     * 1/4 of a translation of 4 (from [1, 3]) */
    noctTransform q = noctIdentityTransform();
    const noctMesh *shapes[2] = {small_solid, small_surface};
    for (int i = 0; i < 2; ++i) {
        q.p[0] = 0;
        n = 0;
        ck_assert_int_eq(noctWorldQueryShape(w, shapes[i], NULL, &q,
                                             (noctQueryFilter){~0ull, ~0ull}, count_hit, &n,
                                             NULL), NOCT_OK);
        ck_assert_int_eq(n, 0);
        q.p[0] = 1.5;
        ck_assert_int_eq(noctWorldQueryShape(w, shapes[i], NULL, &q,
                                             (noctQueryFilter){~0ull, ~0ull}, count_hit, &n,
                                             NULL), NOCT_OK);
        ck_assert_int_eq(n, 1);
        q.p[0] = 0;
        noctShapeHit sh;
        const double along[3] = {4, 0, 0};
        ck_assert_int_eq(noctWorldCastShape(w, shapes[i], NULL, &q, along,
                                            (noctQueryFilter){~0ull, ~0ull}, &sh, &hit, NULL),
                         NOCT_OK);
        ck_assert(hit && sh.sweep.time == 0.25);
    }
    noctWorldDestroy(w);
    noctMeshDestroy(big_closed);
    noctMeshDestroy(small_solid);
    noctMeshDestroy(big_solid);
    noctMeshDestroy(small_surface);
}
END_TEST

/* ---- errors and files --------------------------------------------------------------- */

static void expect_error(noctStatus want, const char *text, const double *v, size_t nv,
                         const uint32_t *sizes, size_t np, const uint32_t *idx)
{
    noctMesh *m = (noctMesh *)1;
    noctError err = {0};
    const noctStatus st = noctMeshCreateSurface(v, nv, sizes, np, idx, &m, &err);
    ck_assert_msg(st == want, "got %s (%s), want %s", noctStatusString(st), err.message,
                  noctStatusString(want));
    ck_assert_ptr_null(m);
    ck_assert_msg(strstr(err.message, text) != NULL, "'%s' lacks '%s'", err.message, text);
}

START_TEST(errors)
{
    double v[15] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 2, 2, 0};
    const uint32_t s3[2] = {3, 3}, s4[1] = {4};
    const uint32_t good[6] = {0, 1, 2, 1, 3, 2};
    noctMesh *m = NULL;
    ck_assert_int_eq(noctMeshCreateSurface(v, 4, s3, 2, good, &m, NULL), NOCT_OK);
    ck_assert(noctMeshIsSurface(m));
    noctMeshDestroy(m);
    /* the same two triangles as a solid: open, with the hint */
    noctError err = {0};
    ck_assert_int_eq(noctMeshCreate(v, 4, s3, 2, good, &m, &err), NOCT_ERR_DEGENERATE);
    const double tet[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    const uint32_t three[9] = {0, 2, 1, 0, 1, 3, 0, 3, 2}, s33[4] = {3, 3, 3, 3};
    ck_assert_int_eq(noctMeshCreate(tet, 4, s33, 3, three, &m, &err), NOCT_ERR_DEGENERATE);
    const uint32_t four_open[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 0, 1, 2};
    ck_assert_int_eq(noctMeshCreate(tet, 4, s33, 4, four_open, &m, &err), NOCT_ERR_OPEN);
    ck_assert_msg(strstr(err.message, "not 2") && strstr(err.message, "noctMeshCreateSurface()"),
                  "%s", err.message);
    ck_assert_int_eq(noctMeshCreateSurface(tet, 4, s33, 4, four_open, &m, NULL), NOCT_OK);
    noctMeshDestroy(m);
    /* refused surfaces */
    expect_error(NOCT_ERR_DEGENERATE, "at least 3 vertices and 1 polygon", v, 4, s3, 0, good);
    expect_error(NOCT_ERR_DEGENERATE, "at least 3 vertices", v, 2, s3, 1, (uint32_t[]){0, 1, 0});
    expect_error(NOCT_ERR_INDEX, "polygon 1: vertex index 7", v, 5, s3, 2,
                 (uint32_t[]){0, 1, 2, 1, 7, 2});
    expect_error(NOCT_ERR_DEGENERATE, "polygon 1 has no area", v, 5, s3, 2,
                 (uint32_t[]){0, 1, 2, 0, 3, 4});
    expect_error(NOCT_ERR_DEGENERATE, "polygon 0: vertex 1 appears twice", v, 5, s3, 1,
                 (uint32_t[]){0, 1, 1});
    double dart[12] = {0, 0, 0, 4, 0, 0, 1, 1, 0, 0, 4, 0};
    expect_error(NOCT_ERR_NONCONVEX, "polygon 0 is not convex", dart, 4, s4, 1,
                 (uint32_t[]){0, 1, 2, 3});
    double bent[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0.5, 0, 1, 0};
    expect_error(NOCT_ERR_NONPLANAR, "polygon 0: vertex", bent, 4, s4, 1,
                 (uint32_t[]){0, 1, 2, 3});
    double nan_v[9] = {0, 0, 0, 1, 0, 0, 0, NAN, 0};
    expect_error(NOCT_ERR_NONFINITE, "vertex 2: coordinate y", nan_v, 3, s3, 1,
                 (uint32_t[]){0, 1, 2});
    double big[9] = {0, 0, 0, 1e101, 0, 0, 0, 1, 0};
    expect_error(NOCT_ERR_TOO_LARGE, "vertex 1: coordinate x", big, 3, s3, 1,
                 (uint32_t[]){0, 1, 2});
    /* files: an open STL soup is no solid, and reads as a surface */
    char path[64];
    snprintf(path, sizeof path, "/tmp/check-surface-%ld.stl", (long)getpid());
    FILE *f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    fputs("solid open\n", f);
    const char *facets[2] = {"0 0 0\nvertex 1 0 0\nvertex 0 1 0\n",
                             "1 0 0\nvertex 1 1 0\nvertex 0 1 0\n"};
    for (int i = 0; i < 2; ++i)
        fprintf(f, "facet normal 0 0 1\nouter loop\nvertex %sendloop\nendfacet\n", facets[i]);
    fputs("endsolid open\n", f);
    fclose(f);
    ck_assert_int_eq(noctMeshRead(path, &m, &err), NOCT_ERR_DEGENERATE);
    ck_assert_int_eq(noctMeshReadSurface(path, &m, &err), NOCT_OK);
    ck_assert(noctMeshIsSurface(m));
    ck_assert_uint_eq(noctMeshVertexCount(m), 4); /* welded */
    ck_assert_uint_eq(noctMeshTriangleCount(m), 2);
    noctMeshDestroy(m);
    noctMeshData *data;
    ck_assert_int_eq(noctMeshDataRead(path, &data, NULL), NOCT_OK);
    ck_assert_int_eq(noctMeshCreateSurfaceFromData(data, &m, NULL), NOCT_OK);
    ck_assert_uint_eq(noctMeshVertexCount(m), 6); /* not welded */
    noctMeshDestroy(m);
    noctMeshDataDestroy(data);
    unlink(path);
}
END_TEST

/* ---- scene files ----------------------------------------------------------------------- */

static char *write_file(const char *name, const char *text)
{
    static char path[8][96];
    static int next;
    char *p = path[next++ % 8];
    snprintf(p, sizeof path[0], "/tmp/check-surface-%ld-%s", (long)getpid(), name);
    FILE *f = fopen(p, "w");
    ck_assert_ptr_nonnull(f);
    fputs(text, f);
    fclose(f);
    return p;
}

/* How many objects of the built world hold point p. */
static int objects_at(const noctScene *sc, const double p[3])
{
    noctWorld *w = NULL;
    noctError err = {0};
    ck_assert_msg(noctSceneBuild(sc, &w, &err) == NOCT_OK, "%s", err.message);
    ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    int n = 0;
    ck_assert_int_eq(noctWorldQueryPoint(w, p, (noctQueryFilter){~0ull, ~0ull}, count_hit, &n,
                                         NULL), NOCT_OK);
    noctWorldDestroy(w);
    return n;
}

START_TEST(scene_files)
{
    const char *off = "OFF\n8 6 0\n0 0 0\n0 0 4\n0 4 0\n0 4 4\n4 0 0\n4 0 4\n4 4 0\n4 4 4\n"
                      "4 0 1 3 2\n4 4 6 7 5\n4 0 4 5 1\n4 2 3 7 6\n4 0 2 6 4\n4 1 5 7 3\n";
    char *box = write_file("bay.off", off);
    char text[512];
    const double centre[3] = {2, 2, 2}, wall[3] = {4, 2, 2};
    const char *shapes[3] = {" surface", " solid", ""};
    for (int i = 0; i < 3; ++i) {
        snprintf(text, sizeof text, "mesh bay file %s%s\nobject bay 0 0 0 type static\n", box,
                 shapes[i]);
        noctScene *sc = NULL;
        noctError err = {0};
        ck_assert_msg(noctSceneRead(write_file("bay.scene", text), &sc, &err) == NOCT_OK, "%s",
                      err.message);
        /* a surface holds its walls, not its inside; a solid both */
        ck_assert_int_eq(objects_at(sc, centre), i == 0 ? 0 : 1);
        ck_assert_int_eq(objects_at(sc, wall), 1);
        /* written back, it says what it is, and reads back the same */
        char *out = write_file("out.scene", "");
        FILE *f = fopen(out, "w");
        ck_assert_ptr_nonnull(f);
        ck_assert_int_eq(noctSceneWrite(sc, f, NULL), NOCT_OK);
        fclose(f);
        noctSceneDestroy(sc);
        f = fopen(out, "r");
        char line[256];
        bool said = false;
        while (fgets(line, sizeof line, f))
            said = said || (strstr(line, "mesh bay file") && strstr(line, " surface"));
        fclose(f);
        ck_assert(said == (i == 0));
        ck_assert_int_eq(noctSceneRead(out, &sc, NULL), NOCT_OK);
        ck_assert_int_eq(objects_at(sc, centre), i == 0 ? 0 : 1);
        noctSceneDestroy(sc);
        unlink(out);
    }
    /* an unknown shape: an error at its line */
    snprintf(text, sizeof text, "mesh bay file %s hollow\nobject bay 0 0 0\n", box);
    const char *bad = write_file("bad.scene", text);
    noctScene *sc = NULL;
    noctError err = {0};
    ck_assert_int_eq(noctSceneRead(bad, &sc, &err), NOCT_ERR_PARSE);
    ck_assert_msg(strstr(err.message, ":1: unknown mesh shape 'hollow'") != NULL, "%s",
                  err.message);
    unlink(bad);
    unlink(box);
    unlink(write_file("bay.scene", ""));
}
END_TEST

int main(void)
{
    Suite *s = suite_create("surface_paths");
    TCase *tc = tcase_create("surfaces");
    tcase_set_timeout(tc, 600);
    tcase_add_test(tc, kinds_and_containment);
    tcase_add_test(tc, soups_against_integers);
    tcase_add_test(tc, soups_against_solid_boxes);
    tcase_add_test(tc, world_against_pairs);
    tcase_add_test(tc, world_turned_and_near);
    tcase_add_test(tc, continuous_world);
    tcase_add_test(tc, distance_against_brute_force);
    tcase_add_test(tc, swept_against_samples);
    tcase_add_test(tc, contacts_and_rays);
    tcase_add_test(tc, errors);
    tcase_add_test(tc, scene_files);
    suite_add_tcase(s, tc);
    return run_suite(s);
}
