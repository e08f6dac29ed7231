/* SPDX-License-Identifier: MIT */
/*
 * The world's queries (query.h) against a brute force of the test's own:
 * - random rotated scenes of box primitives, box meshes and non-convex L
 *   meshes with filters: every point, box, shape and ray query against
 *   the ideal geometry (the rotated boxes the shapes are made of, in long
 *   double), skipping what lies within a margin of a boundary, where the
 *   rounding of the placed vertices decides; and the box and shape
 *   queries against the public narrowphase on every object;
 * - axis-aligned dyadic boxes, where everything is exact: points on
 *   faces, edges and corners, rays along faces and through edges and
 *   corners, zero-length segments, against interval arithmetic;
 * - the same answers from worlds of different N (the tree does not show);
 * - bad input: a status and no call.
 */
#include <check.h>
#include <pthread.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <noctree.h>

#include "testgeom.h"
#include "testutil.h"

/* ---- collecting ------------------------------------------------------------------ */


/* ---- random scenes against the ideal geometry ----------------------------------------- */

/* The random sweeps: _i 0 is a quick run (under valgrind too), 1 the full
 * one (tag slow). */
START_TEST(points_against_geometry)
{
    noctMesh *ell = make_ell();
    int checked = 0, inside = 0;
    for (int round = 0; round < (_i ? 12 : 1); ++round) {
        scene s;
        random_scene(&s, 10 + (int)(30 * uniform()), 1 + round % 5, NOCT_ACCURACY_EXACT, ell);
        for (int q = 0; q < (_i ? 300 : 100); ++q) {
            double p[3];
            for (int k = 0; k < 3; ++k)
                p[k] = -1 + 8 * uniform();
            /* one point in ten is a placed vertex: on the boundary */
            int vertex_of = -1;
            if (q % 10 == 0) {
                vertex_of = (int)(s.n * uniform());
                /* the corner fl(fl(R v) + t) of its box or of the L, in
                 * transform.h's order */
                noctTransform x = s.x[vertex_of];
                double R[9];
                ck_assert_int_eq(noctQuatToMatrix(&x.q, R, NULL), NOCT_OK);
                double local[3];
                if (s.kind[vertex_of] == 2) {
                    local[0] = -1;
                    local[1] = 1;
                    local[2] = 0.5;
                } else {
                    for (int k = 0; k < 3; ++k)
                        local[k] = (double)s.g[vertex_of].pc[0].h[k];
                }
                double r[3];
                for (int k = 0; k < 3; ++k) {
                    volatile double a = R[3 * k] * local[0], b = R[3 * k + 1] * local[1];
                    volatile double c = R[3 * k + 2] * local[2];
                    volatile double ab = a + b;
                    r[k] = ab + c;
                }
                for (int k = 0; k < 3; ++k)
                    p[k] = r[k] + x.p[k];
            }
            noctQueryFilter f = random_filter();
            found got = {0};
            ck_assert_int_eq(noctWorldQueryPoint(s.w, p, f, collect, &got, NULL), NOCT_OK);
            expect_index_order(&got);
            for (int i = 0; i < s.n; ++i) {
                const bool in = in_found(&got, &s, i);
                if (!passes(&s, i, f)) {
                    ck_assert(!in);
                    continue;
                }
                if (i == vertex_of) {
                    ck_assert_msg(in, "a placed vertex is in its closed solid");
                    ++checked;
                    continue;
                }
                const int v = ideal_contains(&s.g[i], p);
                if (v >= 0) {
                    ck_assert_msg(in == (v == 1), "point (%g %g %g) object %d: %d, ideal %d",
                                  p[0], p[1], p[2], i, in, v);
                    ++checked;
                    inside += v;
                }
            }
        }
        free_scene(&s);
    }
    ck_assert_int_gt(checked, _i ? 10000 : 300);
    ck_assert_int_gt(inside, _i ? 150 : 3);
    noctMeshDestroy(ell);
}
END_TEST

/* The box and shape queries against the ideal geometry and against the
 * public narrowphase on every object (a brute force without the tree). */
START_TEST(boxes_and_shapes_against_brute_force)
{
    noctMesh *ell = make_ell();
    int checked = 0, met = 0;
    for (int round = 0; round < (_i ? 10 : 1); ++round) {
        scene s;
        random_scene(&s, 10 + (int)(30 * uniform()), 1 + round % 5, NOCT_ACCURACY_EXACT, ell);
        for (int q = 0; q < (_i ? 60 : 20); ++q) {
            noctQueryFilter f = random_filter();
            /* a box */
            double lo[3], hi[3];
            for (int k = 0; k < 3; ++k) {
                lo[k] = -1 + 7 * uniform();
                hi[k] = lo[k] + (q % 7 == 0 ? 0 : 1.5 * uniform()); /* some flat */
            }
            found got = {0};
            ck_assert_int_eq(noctWorldQueryBox(s.w, lo, hi, f, collect, &got, NULL), NOCT_OK);
            expect_index_order(&got);
            ideal box = {1, {{{0}, {0}}}, {1, 0, 0, 0, 1, 0, 0, 0, 1}, {0}};
            for (int k = 0; k < 3; ++k) {
                box.pc[0].c[k] = ((long double)lo[k] + hi[k]) / 2;
                box.pc[0].h[k] = ((long double)hi[k] - lo[k]) / 2;
            }
            for (int i = 0; i < s.n; ++i) {
                const bool in = in_found(&got, &s, i);
                if (!passes(&s, i, f)) {
                    ck_assert(!in);
                    continue;
                }
                const int v = union_meet(&box, &s.g[i]);
                if (v >= 0) {
                    ck_assert_msg(in == (v == 1), "box query, object %d: %d, ideal %d", i, in, v);
                    ++checked;
                    met += v;
                }
            }
            /* a shape: a box primitive or the L, turned */
            noctTransform x;
            for (int k = 0; k < 3; ++k)
                x.p[k] = 6 * uniform();
            random_quat(&x.q);
            const bool is_ell = uniform() < 0.4;
            double h[3];
            for (int k = 0; k < 3; ++k)
                h[k] = 0.1 + 0.8 * uniform();
            noctMesh *hm;
            ck_assert_int_eq(noctMeshCreateBox(h[0], h[1], h[2], &hm, NULL), NOCT_OK);
            got.n = 0;
            ck_assert_int_eq(noctWorldQueryShape(s.w, is_ell ? ell : NULL, h, &x, f, collect,
                                                 &got, NULL),
                             NOCT_OK);
            expect_index_order(&got);
            const ideal sh = ideal_shape(&x, is_ell, h);
            for (int i = 0; i < s.n; ++i) {
                const bool in = in_found(&got, &s, i);
                if (!passes(&s, i, f)) {
                    ck_assert(!in);
                    continue;
                }
                /* the narrowphase, exact, on the same placed shapes */
                bool hit;
                ck_assert_int_eq(noctCollideTransformed(is_ell ? ell : hm, &x,
                                                        mesh_of(&s, i, ell), &s.x[i],
                                                        NOCT_ACCURACY_EXACT, &hit, NULL, NULL),
                                 NOCT_OK);
                ck_assert_msg(in == hit, "shape query, object %d: %d, narrowphase %d", i, in,
                              hit);
                const int v = union_meet(&sh, &s.g[i]);
                if (v >= 0) {
                    ck_assert_msg(in == (v == 1), "shape query, object %d: %d, ideal %d", i,
                                  in, v);
                    ++checked;
                    met += v;
                }
            }
            noctMeshDestroy(hm);
        }
        free_scene(&s);
    }
    ck_assert_int_gt(checked, _i ? 5000 : 100);
    ck_assert_int_gt(met, _i ? 500 : 10);
    noctMeshDestroy(ell);
}
END_TEST

typedef struct hits {
    int n;
    noctRayHit h[MAXO];
} hits;

static bool collect_hit(void *context, const noctRayHit *h)
{
    hits *r = context;
    ck_assert_int_lt(r->n, MAXO);
    r->h[r->n++] = *h;
    return true;
}

START_TEST(rays_against_geometry)
{
    noctMesh *ell = make_ell();
    int checked = 0, hit = 0, normals = 0;
    for (int round = 0; round < (_i ? 12 : 1); ++round) {
        scene s;
        random_scene(&s, 10 + (int)(30 * uniform()), 1 + round % 5, NOCT_ACCURACY_EXACT, ell);
        for (int q = 0; q < (_i ? 200 : 60); ++q) {
            double o[3], d[3];
            for (int k = 0; k < 3; ++k) {
                o[k] = -1 + 8 * uniform();
                d[k] = q % 11 == 0 ? 0 : (uniform() - 0.5) * 12;
            }
            noctQueryFilter f = random_filter();
            hits got = {0};
            ck_assert_int_eq(noctWorldRayCast(s.w, o, d, f, collect_hit, &got, NULL), NOCT_OK);
            for (int k = 1; k < got.n; ++k)
                ck_assert(got.h[k - 1].fraction < got.h[k].fraction ||
                          (got.h[k - 1].fraction == got.h[k].fraction &&
                           got.h[k - 1].id.index < got.h[k].id.index));
            /* the closest is the first */
            noctRayHit first;
            bool any;
            ck_assert_int_eq(noctWorldRayCastClosest(s.w, o, d, f, &first, &any, NULL),
                             NOCT_OK);
            ck_assert(any == (got.n > 0));
            if (any) {
                ck_assert_uint_eq(first.id.index, got.h[0].id.index);
                ck_assert(first.fraction == got.h[0].fraction);
            }
            const double q_end[3] = {o[0] + d[0], o[1] + d[1], o[2] + d[2]};
            const double dd[3] = {q_end[0] - o[0], q_end[1] - o[1], q_end[2] - o[2]};
            for (int i = 0; i < s.n; ++i) {
                const noctRayHit *h = NULL;
                for (int k = 0; k < got.n; ++k)
                    if (got.h[k].id.index == s.id[i].index)
                        h = &got.h[k];
                if (!passes(&s, i, f)) {
                    ck_assert(h == NULL);
                    continue;
                }
                long double sfrac = 0, n[3];
                bool sharp = false;
                const int v = ideal_ray(&s.g[i], o, dd, &sfrac, n, &sharp);
                if (v < 0)
                    continue;
                ++checked;
                ck_assert_msg((h != NULL) == (v == 1),
                              "ray, object %d (kind %d): %d, ideal %d at %.17Lg; origin %a %a %a "
                              "translation %a %a %a",
                              i, s.kind[i], h != NULL, v, sfrac, o[0], o[1], o[2], d[0], d[1],
                              d[2]);
                if (v == 0)
                    continue;
                ++hit;
                ck_assert(h->user_data == &s.id[i]);
                ck_assert_msg(fabsl(h->fraction - sfrac) < 1e-9L, "fraction %.17g, ideal %.17Lg",
                              h->fraction, sfrac);
                for (int k = 0; k < 3; ++k)
                    ck_assert(fabs(h->point[k] - (o[k] + h->fraction * dd[k])) <= 1e-12);
                if (sfrac == 0) {
                    ck_assert(h->fraction == 0 && h->triangle[0] == NOCT_NO_VERTEX);
                    ck_assert(h->normal[0] == 0 && h->normal[1] == 0 && h->normal[2] == 0);
                } else if (sharp) {
                    for (int k = 0; k < 3; ++k)
                        ck_assert_msg(fabsl(h->normal[k] - n[k]) < 1e-9L,
                                      "normal %g %g %g, ideal %Lg %Lg %Lg", h->normal[0],
                                      h->normal[1], h->normal[2], n[0], n[1], n[2]);
                    ++normals;
                    if (s.kind[i] == 0) {
                        /* a box primitive's corners: the face's bit, shared */
                        unsigned both = 7, any_set = 0;
                        for (int c = 0; c < 3; ++c) {
                            ck_assert_uint_lt(h->triangle[c], 8);
                            both &= h->triangle[c];
                            any_set |= h->triangle[c];
                        }
                        ck_assert(both != 0 || any_set != 7);
                    }
                }
            }
        }
        free_scene(&s);
    }
    ck_assert_int_gt(checked, _i ? 5000 : 200);
    ck_assert_int_gt(hit, _i ? 300 : 5);
    ck_assert_int_gt(normals, _i ? 200 : 3);
    noctMeshDestroy(ell);
}
END_TEST

/* The same queries on worlds of different N and accuracy give the same
 * answers: the tree never shows. */
START_TEST(answers_do_not_depend_on_the_tree)
{
    noctMesh *ell = make_ell();
    const uint64_t seed = rng;
    scene a, b;
    random_scene(&a, 40, 1, NOCT_ACCURACY_EXACT, ell);
    rng = seed;
    random_scene(&b, 40, NOCT_N_EXHAUSTIVE, NOCT_ACCURACY_EXACT, ell);
    for (int q = 0; q < (_i ? 200 : 40); ++q) {
        double o[3], d[3], lo[3], hi[3];
        for (int k = 0; k < 3; ++k) {
            o[k] = -1 + 8 * uniform();
            d[k] = (uniform() - 0.5) * 12;
            lo[k] = -1 + 7 * uniform();
            hi[k] = lo[k] + uniform();
        }
        hits ha = {0}, hb = {0};
        ck_assert_int_eq(noctWorldRayCast(a.w, o, d, noctDefaultQueryFilter(), collect_hit,
                                          &ha, NULL),
                         NOCT_OK);
        ck_assert_int_eq(noctWorldRayCast(b.w, o, d, noctDefaultQueryFilter(), collect_hit,
                                          &hb, NULL),
                         NOCT_OK);
        ck_assert_int_eq(ha.n, hb.n);
        for (int k = 0; k < ha.n; ++k) {
            ck_assert(ha.h[k].fraction == hb.h[k].fraction);
            ck_assert(memcmp(ha.h[k].normal, hb.h[k].normal, sizeof ha.h[k].normal) == 0);
            ck_assert(memcmp(ha.h[k].triangle, hb.h[k].triangle, sizeof ha.h[k].triangle) == 0);
            ck_assert_uint_eq(ha.h[k].id.index, hb.h[k].id.index);
        }
        found fa = {0}, fb = {0};
        ck_assert_int_eq(noctWorldQueryBox(a.w, lo, hi, noctDefaultQueryFilter(), collect, &fa,
                                           NULL),
                         NOCT_OK);
        ck_assert_int_eq(noctWorldQueryBox(b.w, lo, hi, noctDefaultQueryFilter(), collect, &fb,
                                           NULL),
                         NOCT_OK);
        ck_assert_int_eq(fa.n, fb.n);
        for (int k = 0; k < fa.n; ++k)
            ck_assert_uint_eq(fa.id[k].index, fb.id[k].index);
    }
    free_scene(&a);
    free_scene(&b);
    noctMeshDestroy(ell);
}
END_TEST

/* ---- exact cases on dyadic axis-aligned boxes ---------------------------------------- */

/* Boxes [c - h, c + h] with dyadic c and h; the test's intervals are exact. */
#define NB 6
static const double BOXC[NB][3] = {{0, 0, 0},   {1, 0, 0},     {0.5, 1.25, 0},
                                   {3, 3, 3},   {3, 3, 3.75},  {-2, 0.5, 0.5}};
static const double BOXH[NB][3] = {{0.5, 0.5, 0.5}, {0.5, 0.25, 0.5}, {0.25, 0.25, 0.25},
                                   {1, 1, 0.5},     {0.5, 0.5, 0.25}, {0.125, 0.5, 1}};

static noctWorld *dyadic_world(noctObjectId *id, noctMesh **mesh)
{
    noctWorld *w = new_world(2, NOCT_ACCURACY_EXACT);
    for (int i = 0; i < NB; ++i) {
        noctObjectDef d = noctDefaultObjectDef();
        memcpy(d.transform.p, BOXC[i], sizeof d.transform.p);
        mesh[i] = NULL;
        if (i % 2) { /* meshes and primitives alike */
            ck_assert_int_eq(noctMeshCreateBox(BOXH[i][0], BOXH[i][1], BOXH[i][2], &mesh[i],
                                               NULL),
                             NOCT_OK);
            d.mesh = mesh[i];
        } else {
            memcpy(d.half_extents, BOXH[i], sizeof d.half_extents);
        }
        d.user_data = &id[i];
        ck_assert_int_eq(noctWorldCreateObject(w, &d, &id[i], NULL), NOCT_OK);
    }
    return w;
}

static bool dyadic_contains(int i, const double p[3])
{
    for (int k = 0; k < 3; ++k)
        if (p[k] < BOXC[i][k] - BOXH[i][k] || p[k] > BOXC[i][k] + BOXH[i][k])
            return false;
    return true;
}

/* The segment p + s d against box i, exactly (its numbers dyadic): the
 * least s in [0, 1], or -1. */
static double dyadic_ray(int i, const double p[3], const double d[3])
{
    double lo = 0, hi = 1;
    for (int k = 0; k < 3; ++k) {
        const double a = BOXC[i][k] - BOXH[i][k] - p[k], b = BOXC[i][k] + BOXH[i][k] - p[k];
        if (d[k] == 0) {
            if (a > 0 || b < 0)
                return -1;
            continue;
        }
        double s0 = a / d[k], s1 = b / d[k];
        if (s0 > s1) {
            double t = s0;
            s0 = s1;
            s1 = t;
        }
        lo = fmax(lo, s0);
        hi = fmin(hi, s1);
    }
    return lo <= hi ? lo : -1;
}

START_TEST(exact_points_on_faces_edges_and_corners)
{
    noctObjectId id[NB];
    noctMesh *mesh[NB];
    noctWorld *w = dyadic_world(id, mesh);
    int on = 0;
    for (int i = 0; i < NB; ++i)
        for (int code = 0; code < 27; ++code) { /* -1, 0, +1 on each axis */
            for (int out = 0; out < 2; ++out) {
                double p[3];
                int c = code;
                for (int k = 0; k < 3; ++k, c /= 3) {
                    const int sgn = c % 3 - 1;
                    p[k] = BOXC[i][k] + sgn * BOXH[i][k];
                    if (out && sgn != 0)
                        p[k] += sgn * 0x1p-30; /* just outside */
                }
                found got = {0};
                ck_assert_int_eq(noctWorldQueryPoint(w, p, noctDefaultQueryFilter(), collect,
                                                     &got, NULL),
                                 NOCT_OK);
                for (int j = 0; j < NB; ++j) {
                    bool in = false;
                    for (int k = 0; k < got.n; ++k)
                        in = in || got.id[k].index == id[j].index;
                    ck_assert_msg(in == dyadic_contains(j, p),
                                  "point (%a %a %a), box %d: %d", p[0], p[1], p[2], j, in);
                    on += in;
                }
                /* a zero-length segment is the same point */
                hits hz = {0};
                ck_assert_int_eq(noctWorldRayCast(w, p, (double[3]){0, 0, 0},
                                                  noctDefaultQueryFilter(), collect_hit, &hz,
                                                  NULL),
                                 NOCT_OK);
                ck_assert_int_eq(hz.n, got.n);
                for (int k = 0; k < hz.n; ++k)
                    ck_assert(hz.h[k].fraction == 0 && hz.h[k].triangle[0] == NOCT_NO_VERTEX);
            }
        }
    ck_assert_int_gt(on, 6 * 27);
    noctWorldDestroy(w);
    for (int i = 0; i < NB; ++i)
        noctMeshDestroy(mesh[i]);
}
END_TEST

START_TEST(exact_rays_along_faces_and_through_edges)
{
    noctObjectId id[NB];
    noctMesh *mesh[NB];
    noctWorld *w = dyadic_world(id, mesh);
    int hitting = 0, cases = 0;
    /* From points on a dyadic grid around each box, in directions along
     * the axes and the diagonals: they run along faces, graze edges and
     * pass through corners exactly. */
    for (int i = 0; i < NB; ++i)
        for (int code = 0; code < 27; ++code)
            for (int dir = 0; dir < 26; ++dir) {
                double p[3], d[3];
                int c = code, e = dir < 13 ? dir : dir + 1;
                for (int k = 0; k < 3; ++k, c /= 3, e /= 3) {
                    p[k] = BOXC[i][k] + (c % 3 - 1) * BOXH[i][k] * 2;
                    d[k] = (e % 3 - 1) * BOXH[i][k] * 4;
                }
                hits got = {0};
                ck_assert_int_eq(noctWorldRayCast(w, p, d, noctDefaultQueryFilter(),
                                                  collect_hit, &got, NULL),
                                 NOCT_OK);
                ++cases;
                for (int j = 0; j < NB; ++j) {
                    const noctRayHit *h = NULL;
                    for (int k = 0; k < got.n; ++k)
                        if (got.h[k].id.index == id[j].index)
                            h = &got.h[k];
                    const double s = dyadic_ray(j, p, d);
                    ck_assert_msg((h != NULL) == (s >= 0),
                                  "ray (%a %a %a) + s (%a %a %a), box %d: %d, exact %g", p[0],
                                  p[1], p[2], d[0], d[1], d[2], j, h != NULL, s);
                    if (h != NULL) {
                        ++hitting;
                        ck_assert_msg(fabs(h->fraction - s) <= 1e-15, "fraction %a, exact %a",
                                      h->fraction, s);
                    }
                }
            }
    ck_assert_int_gt(hitting, cases / 4);
    noctWorldDestroy(w);
    for (int i = 0; i < NB; ++i)
        noctMeshDestroy(mesh[i]);
}
END_TEST

/* ---- normals at every scale ------------------------------------------------------------ */

/*
 * A box primitive (and a box mesh) of half-extent h, turned by 30 degrees
 * about z, at the origin, from h = 1e-300 to 1e95: a ray along each face
 * normal (the rotation's columns, either sign) from 3h out enters through
 * that face at a third of its length, and the hit's normal is unit and
 * that face's. Then a box far from the origin for its size (half 1/16 at
 * 6e99), whose placed corners round to one point: the hit is flagged, and
 * its normal is the unit vector against the ray.
 */
START_TEST(ray_normals_at_every_scale)
{
    static const double scales[] = {1e-300, 1e-200, 1e-100, 1e-81, 1e-80, 1e-10, 1,
                                    1e10,   1e77,   5e77,   1e80,  1e95};
    const double z[3] = {0, 0, 1};
    noctQuat q;
    ck_assert_int_eq(noctQuatFromAxisAngle(z, 30, &q), NOCT_OK);
    double R[9];
    ck_assert_int_eq(noctQuatToMatrix(&q, R, NULL), NOCT_OK);
    for (size_t i = 0; i < sizeof scales / sizeof *scales; ++i)
        for (int kind = 0; kind < 2; ++kind) {
            const double h = scales[i];
            noctWorld *w;
            noctError err;
            ck_assert_int_eq(noctWorldCreate(&(noctWorldDef){.effects = 0}, &w, &err), NOCT_OK);
            noctMesh *mesh = NULL;
            noctObjectDef d = noctDefaultObjectDef();
            if (kind == 0) {
                d.half_extents[0] = d.half_extents[1] = d.half_extents[2] = h;
            } else {
                ck_assert_int_eq(noctMeshCreateBox(h, h, h, &mesh, &err), NOCT_OK);
                d.mesh = mesh;
            }
            d.transform.q = q;
            noctObjectId id;
            ck_assert_msg(noctWorldCreateObject(w, &d, &id, &err) == NOCT_OK, "h %g: %s", h,
                          err.message);
            /* along each of the six face normals (the rotation's columns,
             * either way), from 3h out to 3h beyond */
            for (int face = 0; face < 6; ++face) {
                const int c = face / 2;
                const double sgn = face % 2 ? -1 : 1;
                double o[3], t[3];
                for (int k = 0; k < 3; ++k) {
                    o[k] = 3 * h * sgn * R[3 * k + c];
                    t[k] = -6 * h * sgn * R[3 * k + c];
                }
                noctRayHit hit;
                bool any = false;
                ck_assert_int_eq(noctWorldRayCastClosest(w, o, t, noctDefaultQueryFilter(), &hit,
                                                         &any, &err),
                                 NOCT_OK);
                ck_assert_msg(any, "h %g, face %d: no hit", h, face);
                ck_assert(!hit.flat);
                double len2 = 0, along = 0;
                for (int k = 0; k < 3; ++k) {
                    len2 += hit.normal[k] * hit.normal[k];
                    along += hit.normal[k] * sgn * R[3 * k + c];
                }
                ck_assert_msg(fabs(len2 - 1) <= 1e-14, "h %g, face %d: |normal|^2 = %.17g", h,
                              face, len2);
                ck_assert_msg(along >= 1 - 1e-12, "h %g, face %d: normal . face = %.17g", h,
                              face, along);
                ck_assert_msg(fabs(hit.fraction - 1.0 / 3) <= 1e-12, "h %g: fraction %.17g", h,
                              hit.fraction);
            }
            noctWorldDestroy(w);
            noctMeshDestroy(mesh);
        }
    /* squashed: half 1/16 at (6e99, 6e99, 6e99) rounds to a point as placed */
    noctWorld *w;
    ck_assert_int_eq(noctWorldCreate(&(noctWorldDef){.effects = 0}, &w, NULL), NOCT_OK);
    noctObjectDef d = noctDefaultObjectDef();
    d.half_extents[0] = d.half_extents[1] = d.half_extents[2] = 0.0625;
    d.transform.p[0] = d.transform.p[1] = d.transform.p[2] = 6e99;
    d.transform.q = q;
    noctObjectId id;
    ck_assert_int_eq(noctWorldCreateObject(w, &d, &id, NULL), NOCT_OK);
    const double o[3] = {6e99, 6e99 - 1e90, 6e99}, t[3] = {0, 2e90, 0};
    noctRayHit hit;
    bool any = false;
    ck_assert_int_eq(noctWorldRayCastClosest(w, o, t, noctDefaultQueryFilter(), &hit, &any,
                                             NULL),
                     NOCT_OK);
    ck_assert(any);
    ck_assert(hit.flat);
    ck_assert_msg(hit.normal[0] == 0 && hit.normal[1] == -1 && hit.normal[2] == 0,
                  "normal (%g %g %g)", hit.normal[0], hit.normal[1], hit.normal[2]);
    /* the point lies at 6e99; the segment's end o + t is rounded there,
     * to a unit in the last place of 6e99 */
    const double want = (6e99 - o[1]) / t[1], ulp = nextafter(6e99, INFINITY) - 6e99;
    ck_assert_msg(fabs(hit.fraction - want) <= 4 * ulp / t[1], "fraction %.17g, want %.17g",
                  hit.fraction, want);
    noctWorldDestroy(w);
}
END_TEST

/* ---- arrays, stopping, bad input ------------------------------------------------------- */

static bool stop_at_first(void *context, noctObjectId id, void *user)
{
    (void)id;
    (void)user;
    ++*(int *)context;
    return false;
}

START_TEST(buffers_stopping_and_bad_input)
{
    noctObjectId id[NB];
    noctMesh *mesh[NB];
    noctWorld *w = dyadic_world(id, mesh);
    const double lo[3] = {-10, -10, -10}, hi[3] = {10, 10, 10};
    noctObjectId ids[3];
    noctObjectBuffer buf = {ids, 3, 0};
    ck_assert_int_eq(noctWorldQueryBox(w, lo, hi, noctDefaultQueryFilter(), noctCollectObjects,
                                       &buf, NULL),
                     NOCT_OK);
    ck_assert_uint_eq(buf.count, NB);
    for (int k = 0; k < 3; ++k)
        ck_assert_uint_eq(ids[k].index, id[k].index);
    int calls = 0;
    ck_assert_int_eq(noctWorldQueryBox(w, lo, hi, noctDefaultQueryFilter(), stop_at_first,
                                       &calls, NULL),
                     NOCT_OK);
    ck_assert_int_eq(calls, 1);
    noctRayHit hb[2];
    noctRayHitBuffer rb = {hb, 2, 0};
    ck_assert_int_eq(noctWorldRayCast(w, (double[3]){-5, 0.125, 0.125}, (double[3]){10, 0, 0},
                                      noctDefaultQueryFilter(), noctCollectRayHits, &rb, NULL),
                     NOCT_OK);
    ck_assert_uint_eq(rb.count, 3); /* boxes 5, 0, 1 along y = z = 1/8 */
    ck_assert_uint_eq(hb[0].id.index, id[5].index);
    ck_assert(hb[0].fraction == (-2.125 + 5) / 10);
    ck_assert_msg(hb[0].normal[0] == -1 && hb[0].normal[1] == 0 && hb[0].normal[2] == 0,
                  "normal %g %g %g, triangle %u %u %u", hb[0].normal[0], hb[0].normal[1],
                  hb[0].normal[2], hb[0].triangle[0], hb[0].triangle[1], hb[0].triangle[2]);
    ck_assert_uint_eq(hb[1].id.index, id[0].index);
    /* bad input: a status, an error naming it, no call */
    noctError err;
    calls = 0;
    const double nan3[3] = {NAN, 0, 0}, far3[3] = {2e100, 0, 0};
    ck_assert_int_eq(noctWorldQueryPoint(w, nan3, noctDefaultQueryFilter(), stop_at_first,
                                         &calls, &err),
                     NOCT_ERR_NONFINITE);
    ck_assert_ptr_nonnull(strstr(err.message, "not finite"));
    ck_assert_int_eq(noctWorldQueryPoint(w, far3, noctDefaultQueryFilter(), stop_at_first,
                                         &calls, &err),
                     NOCT_ERR_TOO_LARGE);
    ck_assert_int_eq(noctWorldQueryBox(w, hi, lo, noctDefaultQueryFilter(), stop_at_first,
                                       &calls, &err),
                     NOCT_ERR_INVALID);
    ck_assert_int_eq(noctWorldRayCast(w, lo, (double[3]){INFINITY, 0, 0},
                                      noctDefaultQueryFilter(), collect_hit, &calls, &err),
                     NOCT_ERR_NONFINITE);
    ck_assert_int_eq(noctWorldRayCast(w, (double[3]){9e99, 0, 0}, (double[3]){9e99, 0, 0},
                                      noctDefaultQueryFilter(), collect_hit, &calls, &err),
                     NOCT_ERR_TOO_LARGE);
    /* a ray by direction and distance: a zero direction is an error */
    noctRayHit rh;
    bool any = true;
    ck_assert_int_eq(noctWorldRayCastAlong(w, (double[3]){-5, 0.125, 0.125}, (double[3]){0, 0, 0},
                                           10, noctDefaultQueryFilter(), &rh, &any, &err),
                     NOCT_ERR_INVALID);
    ck_assert(!any);
    ck_assert_ptr_nonnull(strstr(err.message, "non-zero direction"));
    ck_assert_int_eq(noctWorldRayCastAlong(w, lo, (double[3]){NAN, 1, 0}, 10,
                                           noctDefaultQueryFilter(), &rh, &any, &err),
                     NOCT_ERR_NONFINITE);
    ck_assert_int_eq(noctWorldRayCastAlong(w, lo, (double[3]){1, 0, 0}, -1,
                                           noctDefaultQueryFilter(), &rh, &any, &err),
                     NOCT_ERR_INVALID);
    /* any length of direction: the same first hit, box 5 at 2.875 along x */
    const double dirs[3][3] = {{1e-200, 0, 0}, {1, 0, 0}, {1e200, 0, 0}};
    for (int k = 0; k < 3; ++k) {
        ck_assert_int_eq(noctWorldRayCastAlong(w, (double[3]){-5, 0.125, 0.125}, dirs[k], 10,
                                               noctDefaultQueryFilter(), &rh, &any, &err),
                         NOCT_OK);
        ck_assert(any && rh.id.index == id[5].index && rh.fraction == 0.2875);
        ck_assert(rh.point[0] == -2.125);
    }
    ck_assert_int_eq(noctWorldRayCastAlong(w, (double[3]){-5, 0.125, 0.125}, dirs[1], 2,
                                           noctDefaultQueryFilter(), &rh, &any, &err),
                     NOCT_OK);
    ck_assert(!any); /* it stops short of the box, 2.875 away */
    noctTransform x = noctIdentityTransform();
    x.q.w = 2; /* far from unit length */
    ck_assert_int_eq(noctWorldQueryShape(w, NULL, (double[3]){1, 1, 1}, &x,
                                         noctDefaultQueryFilter(), stop_at_first, &calls, &err),
                     NOCT_ERR_INVALID);
    x = noctIdentityTransform();
    ck_assert_int_eq(noctWorldQueryShape(w, NULL, (double[3]){-1, 1, 1}, &x,
                                         noctDefaultQueryFilter(), stop_at_first, &calls, &err),
                     NOCT_ERR_INVALID);
    ck_assert_int_eq(calls, 0);
    noctWorldDestroy(w);
    for (int i = 0; i < NB; ++i)
        noctMeshDestroy(mesh[i]);
}
END_TEST

/* ---- threads ------------------------------------------------------------------- */

#define NQ 120

typedef struct answers {
    int box[NQ][MAXO + 1], point[NQ][MAXO + 1], ray[NQ][MAXO + 1];
} answers;

typedef struct job {
    const scene *s;
    const double (*q)[6];
    answers *a;
    bool ok;
} job;

static bool count_into(void *context, noctObjectId id, void *user)
{
    (void)user;
    int *row = context;
    row[++row[0]] = (int)id.index;
    return row[0] < MAXO;
}

static bool count_hit_into(void *context, const noctRayHit *h)
{
    int *row = context;
    row[++row[0]] = (int)h->id.index;
    return row[0] < MAXO;
}

static void *run_queries(void *arg)
{
    job *j = arg;
    j->ok = true;
    const noctQueryFilter all = noctDefaultQueryFilter();
    for (int k = 0; k < NQ; ++k) {
        const double *q = j->q[k];
        const double hi[3] = {q[0] + 1, q[1] + 1, q[2] + 1};
        j->a->box[k][0] = j->a->point[k][0] = j->a->ray[k][0] = 0;
        j->ok = j->ok &&
                noctWorldQueryBox(j->s->w, q, hi, all, count_into, j->a->box[k], NULL) == NOCT_OK &&
                noctWorldQueryPoint(j->s->w, q, all, count_into, j->a->point[k], NULL) == NOCT_OK &&
                noctWorldRayCast(j->s->w, q, &q[3], all, count_hit_into, j->a->ray[k], NULL) ==
                    NOCT_OK;
    }
    return NULL;
}

/* Queries only read the world: two threads querying it at once get what
 * one gets alone. */
START_TEST(queries_from_two_threads)
{
    noctMesh *ell = make_ell();
    scene s;
    random_scene(&s, 40, 2, NOCT_ACCURACY_EXACT, ell);
    ck_assert_int_eq(noctWorldStep(s.w, NULL), NOCT_OK);
    static double q[NQ][6];
    for (int k = 0; k < NQ; ++k)
        for (int c = 0; c < 6; ++c)
            q[k][c] = c < 3 ? -1 + 8 * uniform() : 6 * (uniform() - 0.5);
    static answers alone, two[2];
    job ref = {&s, (const double (*)[6])q, &alone, false};
    run_queries(&ref);
    ck_assert(ref.ok);
    job jobs[2] = {{&s, (const double (*)[6])q, &two[0], false},
                   {&s, (const double (*)[6])q, &two[1], false}};
    pthread_t th[2];
    for (int t = 0; t < 2; ++t)
        ck_assert_int_eq(pthread_create(&th[t], NULL, run_queries, &jobs[t]), 0);
    for (int t = 0; t < 2; ++t)
        ck_assert_int_eq(pthread_join(th[t], NULL), 0);
    int total = 0;
    for (int t = 0; t < 2; ++t) {
        ck_assert(jobs[t].ok);
        ck_assert(memcmp(&two[t], &alone, sizeof alone) == 0);
    }
    for (int k = 0; k < NQ; ++k)
        total += alone.box[k][0] + alone.point[k][0] + alone.ray[k][0];
    ck_assert_int_gt(total, NQ);
    free_scene(&s);
    noctMeshDestroy(ell);
}
END_TEST

/* ---- a moving shape ------------------------------------------------------------------ */

/* noctWorldCastShape() against the narrowphase on every object: random
 * unturned boxes (primitives of dyadic half-extents, whose meshes the
 * test makes), filters, casts long and short; the first hit is the least
 * time over the objects the filter lets through, ties to the least
 * index. And a hand-worked case: a cube cast through a thin wall. */
START_TEST(cast_shape_against_the_narrowphase)
{
    enum { NOBJ = 100 };
    int nhit = 0, starts = 0;
    for (int round = 0; round < 6; ++round) {
        noctWorldDef def = noctDefaultWorldDef();
        def.N = 1 + round % 4;
        noctWorld *w;
        ck_assert_int_eq(noctWorldCreate(&def, &w, NULL), NOCT_OK);
        noctMesh *mesh[NOBJ];
        double pos[NOBJ][3];
        uint64_t cat[NOBJ];
        noctObjectId id[NOBJ];
        for (int i = 0; i < NOBJ; ++i) {
            noctObjectDef d = noctDefaultObjectDef();
            for (int k = 0; k < 3; ++k) {
                d.half_extents[k] = (1 + (int)(8 * uniform())) / 16.0;
                pos[i][k] = d.transform.p[k] = (int)(64 * uniform()) / 8.0;
            }
            d.category = cat[i] = (uint64_t)1 << (int)(3 * uniform());
            d.type = NOCT_OBJECT_STATIC;
            ck_assert_int_eq(noctWorldCreateObject(w, &d, &id[i], NULL), NOCT_OK);
            ck_assert_int_eq(noctMeshCreateBox(d.half_extents[0], d.half_extents[1],
                                               d.half_extents[2], &mesh[i], NULL),
                             NOCT_OK);
        }
        for (int q = 0; q < 40; ++q) {
            double h[3], t[3];
            noctTransform x = {.q = {0, 0, 0, 1}};
            for (int k = 0; k < 3; ++k) {
                h[k] = (1 + (int)(4 * uniform())) / 16.0;
                x.p[k] = -1 + 10 * uniform();
                t[k] = (q % 4 == 0 ? 100 : 8) * (uniform() - 0.5);
            }
            noctMesh *hm;
            ck_assert_int_eq(noctMeshCreateBox(h[0], h[1], h[2], &hm, NULL), NOCT_OK);
            noctQueryFilter f = noctDefaultQueryFilter();
            f.mask = (uint64_t)(1 + (int)(7 * uniform()));
            noctShapeHit got;
            bool any;
            ck_assert_int_eq(noctWorldCastShape(w, q % 2 ? hm : NULL, h, &x, t, f, &got, &any,
                                                NULL),
                             NOCT_OK);
            double end[3] = {x.p[0] + t[0], x.p[1] + t[1], x.p[2] + t[2]};
            int best = -1;
            noctSweepHit bh = {0};
            for (int i = 0; i < NOBJ; ++i) {
                if ((cat[i] & f.mask) == 0)
                    continue;
                bool c;
                noctSweepHit sh;
                ck_assert_int_eq(noctCollideSwept(hm, x.p, end, mesh[i], pos[i], pos[i], &c, &sh,
                                                  NULL),
                                 NOCT_OK);
                if (c && (best < 0 || sh.time < bh.time)) {
                    best = i;
                    bh = sh;
                }
            }
            ck_assert_int_eq(any, best >= 0);
            if (any) {
                ck_assert_uint_eq(got.id.index, id[best].index);
                /* the same time; the features may differ where several
                 * touch first at once, and a primitive's view is not
                 * triangulated as noctMeshCreateBox() is */
                ck_assert(got.sweep.time == bh.time);
                ck_assert_int_eq(got.sweep.feature == NOCT_SWEEP_START,
                                 bh.feature == NOCT_SWEEP_START);
                ++nhit;
                starts += bh.time == 0;
            }
            noctMeshDestroy(hm);
        }
        for (int i = 0; i < NOBJ; ++i)
            noctMeshDestroy(mesh[i]);
        noctWorldDestroy(w);
    }
    ck_assert_int_gt(nhit, 30);
    ck_assert_int_gt(starts, 0);

    /* By hand: a cube of half-size 1/2 from x = -3 to 3 meets a wall of
     * half-thickness 1/16 at the origin when its face reaches -1/16:
     * (3 - 1/2 - 1/16) / 6 = 0.40625; the filter can hide the wall. */
    noctWorldDef def = noctDefaultWorldDef();
    noctWorld *w;
    ck_assert_int_eq(noctWorldCreate(&def, &w, NULL), NOCT_OK);
    noctObjectDef d = noctDefaultObjectDef();
    d.half_extents[0] = 0.0625;
    d.half_extents[1] = d.half_extents[2] = 2;
    d.category = 2;
    noctObjectId wall;
    ck_assert_int_eq(noctWorldCreateObject(w, &d, &wall, NULL), NOCT_OK);
    noctTransform x = {.q = {0, 0, 0, 1}, .p = {-3, 0, 0}};
    noctShapeHit got;
    bool any;
    ck_assert_int_eq(noctWorldCastShape(w, NULL, (double[3]){0.5, 0.5, 0.5}, &x,
                                        (double[3]){6, 0, 0}, noctDefaultQueryFilter(), &got,
                                        &any, NULL),
                     NOCT_OK);
    ck_assert(any);
    ck_assert(got.sweep.time == 0.40625);
    ck_assert(got.sweep.point[0] == -0.0625);
    noctQueryFilter f = noctDefaultQueryFilter();
    f.mask = 1;
    ck_assert_int_eq(noctWorldCastShape(w, NULL, (double[3]){0.5, 0.5, 0.5}, &x,
                                        (double[3]){6, 0, 0}, f, &got, &any, NULL),
                     NOCT_OK);
    ck_assert(!any);
    ck_assert_int_eq(noctWorldCastShape(w, NULL, (double[3]){0.5, 0.5, 0.5}, &x,
                                        (double[3]){NAN, 0, 0}, f, &got, &any, NULL),
                     NOCT_ERR_NONFINITE);
    ck_assert(!any);
    ck_assert_int_eq(noctWorldCastShape(w, NULL, (double[3]){0.5, 0.5, 0.5}, &x,
                                        (double[3]){2e100, 0, 0}, f, &got, &any, NULL),
                     NOCT_ERR_TOO_LARGE);
    noctWorldDestroy(w);
}
END_TEST

static Suite *queries_suite(void)
{
    Suite *s = suite_create("queries");
    TCase *tc = test_case(s, "queries", 300, NULL);
    tcase_add_loop_test(tc, points_against_geometry, 0, 1);
    tcase_add_loop_test(tc, boxes_and_shapes_against_brute_force, 0, 1);
    tcase_add_loop_test(tc, rays_against_geometry, 0, 1);
    tcase_add_loop_test(tc, answers_do_not_depend_on_the_tree, 0, 1);
    add_tests(tc, exact_points_on_faces_edges_and_corners, exact_rays_along_faces_and_through_edges,
              ray_normals_at_every_scale, buffers_stopping_and_bad_input, queries_from_two_threads,
              cast_shape_against_the_narrowphase);
    TCase *full = test_case(s, "queries, full", 300, "slow seeds");
    tcase_add_loop_test(full, points_against_geometry, 1, 2);
    tcase_add_loop_test(full, boxes_and_shapes_against_brute_force, 1, 2);
    tcase_add_loop_test(full, rays_against_geometry, 1, 2);
    tcase_add_loop_test(full, answers_do_not_depend_on_the_tree, 1, 2);
    return s;
}

int main(void)
{
    return run_suite(queries_suite());
}
