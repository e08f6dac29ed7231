/* SPDX-License-Identifier: MIT */
/*
 * Distances in a world (noctWorldDistance(), noctWorldQueryNearest(),
 * noctWorldQueryWithin(), noctWorldNearDistances()) against brute forces
 * over every object:
 * - random rotated scenes of box primitives, box meshes and L meshes,
 *   some objects moved and some removed, with filters: each object's
 *   distance against noctDistance() on the test's meshes (bit for bit
 *   where both shapes are meshes; within a tolerance for a box primitive,
 *   whose triangles the test's box mesh splits otherwise) and against the
 *   ideal solids (long double); the nearest against the least of
 *   noctDistance() over every object (same object, ties to the least
 *   index); the objects within a distance against the set noctDistance()
 *   gives;
 * - point queries against the ideal solids: the distance to a union of
 *   boxes is the least over its boxes, 0 inside (certain containment
 *   checked both ways);
 * - exact ties (dyadic boxes about the query) to the least index, and the
 *   same answers from trees of different N and histories;
 * - the nearest's walk (a dense cluster, scattered boxes, queries in the
 *   cluster and far outside, filters, moved and removed objects, trees of
 *   N 1, 4, automatic and exhaustive; max_distance at the best's distance
 *   exactly and just below it; no object passing, none left, an empty
 *   world) against the least of the distances noctWorldQueryWithin()
 *   reports for every object, and a point's against the ideal solids;
 * - points beyond turned boxes' corners, edges and faces at near-tied
 *   distances, at scales 2^-480 to 2^300, against the ideal boxes;
 * - the walk at sizes 2^-300 and 2^300, offsets 2^40 and 1e99, tiny boxes
 *   beside huge ones, dyadic boxes with shared faces and exact ties (at
 *   distance 0 the least index) against noctWorldQueryWithin();
 * - the near pairs' distances against noctWorldDistance() and
 *   noctDistance(), cached until the next step;
 * - bad input: a status, no call.
 */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <noctree.h>

#include "testgeom.h"
#include "testutil.h"

/* How near two distances of the same solids, computed on different
 * triangulations or by the ideal geometry, must be (the scenes' coordinates
 * are below 10; noctDistance() is within 2^-40 of them; the ideal edge
 * searches within about 1e-12). */
#define TOL 1e-9

static noctMesh *ell;

static void make_ell_fixture(void)
{
    ell = make_ell();
}

static void free_ell_fixture(void)
{
    noctMeshDestroy(ell);
}

/* ---- scenes ------------------------------------------------------------------------ */

/* A scene with some objects moved (new transforms) and some removed. */
typedef struct world_scene {
    scene s;
    bool gone[MAXO];
} world_scene;

static void place_ideal(scene *s, int i, const noctTransform *x)
{
    s->x[i] = *x;
    quat_matrix(&x->q, s->g[i].R);
    for (int k = 0; k < 3; ++k)
        s->g[i].t[k] = x->p[k];
}

static void make_scene(world_scene *ws, int n, int N)
{
    memset(ws->gone, 0, sizeof ws->gone);
    random_scene(&ws->s, n, N, NOCT_ACCURACY_EXACT, ell);
    scene *s = &ws->s;
    for (int i = 0; i < s->n; ++i) {
        const double u = uniform();
        if (u < 0.2) {
            noctTransform x;
            for (int k = 0; k < 3; ++k)
                x.p[k] = 6 * uniform();
            random_quat(&x.q);
            ck_assert_int_eq(noctWorldSetTransform(s->w, s->id[i], &x, NULL), NOCT_OK);
            place_ideal(s, i, &x);
        } else if (u < 0.3) {
            ck_assert_int_eq(noctWorldRemove(s->w, s->id[i], NULL), NOCT_OK);
            ws->gone[i] = true;
        }
    }
    if (uniform() < 0.5) /* a tree made by a step, or the one the objects made */
        ck_assert_int_eq(noctWorldStep(s->w, NULL), NOCT_OK);
}

static bool live(const world_scene *ws, int i, noctQueryFilter f)
{
    return !ws->gone[i] && passes(&ws->s, i, f);
}

/* A query's shape: a box primitive (kind 0; mesh is the test's box mesh of
 * it), a box mesh (1), the L mesh (2), or a point (3). */
typedef struct qshape {
    int kind;
    double h[3];
    noctMesh *box;
    noctTransform x;
    ideal g;
} qshape;

static void make_qshape(qshape *q, int kind)
{
    q->kind = kind;
    q->box = NULL;
    for (int k = 0; k < 3; ++k) {
        q->h[k] = 0.1 + 0.5 * uniform();
        q->x.p[k] = -1 + 8 * uniform();
    }
    random_quat(&q->x.q);
    if (uniform() < 0.2)
        q->x.q = (noctQuat){0, 0, 0, 1};
    if (kind == 0 || kind == 1)
        ck_assert_int_eq(noctMeshCreateBox(q->h[0], q->h[1], q->h[2], &q->box, NULL), NOCT_OK);
    q->g.npieces = kind == 2 ? 2 : 1;
    if (kind == 2) {
        q->g.pc[0] = (piece){{0, -0.5L, 0}, {1, 0.5L, 0.5L}};
        q->g.pc[1] = (piece){{-0.5L, 0, 0}, {0.5L, 1, 0.5L}};
    } else {
        q->g.pc[0] = (piece){{0, 0, 0}, {q->h[0], q->h[1], q->h[2]}};
    }
    quat_matrix(&q->x.q, q->g.R);
    for (int k = 0; k < 3; ++k)
        q->g.t[k] = q->x.p[k];
}

/* The arguments the world's queries take for it. */
static const noctMesh *q_mesh(const qshape *q)
{
    return q->kind == 1 ? q->box : q->kind == 2 ? ell : NULL;
}

static const double *q_half(const qshape *q)
{
    return q->kind == 0 ? q->h : NULL;
}

/* The test's mesh of it (for noctDistance()). */
static const noctMesh *q_test_mesh(const qshape *q)
{
    return q->kind == 2 ? ell : q->box;
}

/* The distance from p to an ideal solid: the least over its boxes (0
 * inside one). */
static long double point_ideal(const ideal *g, const double p[3])
{
    long double best = INFINITY;
    for (int j = 0; j < g->npieces; ++j) {
        const obb b = piece_box(g, j);
        long double s = 0;
        for (int i = 0; i < 3; ++i) {
            long double x = 0;
            for (int k = 0; k < 3; ++k)
                x += (p[k] - b.c[k]) * b.u[i][k];
            const long double out = fabsl(x) - b.h[i];
            if (out > 0)
                s += out * out;
        }
        best = fminl(best, sqrtl(s));
    }
    return best;
}

/* The brute force's distance from the query to object i. */
static noctDistanceResult brute(const world_scene *ws, const qshape *q, int i, double max)
{
    noctDistanceResult r;
    const scene *s = &ws->s;
    ck_assert_int_eq(noctDistance(q_test_mesh(q), &q->x, mesh_of(s, i, ell), &s->x[i], max, &r,
                                  NULL, NULL),
                     NOCT_OK);
    return r;
}

/* Both the query and object i are meshes: the world's answer is
 * noctDistance()'s, bit for bit. */
static bool exact_pair(const world_scene *ws, const qshape *q, int i)
{
    return q->kind != 0 && ws->s.kind[i] != 0;
}

static void expect_same_result(const noctDistanceResult *a, const noctDistanceResult *b)
{
    ck_assert(a->distance == b->distance);
    ck_assert(a->lower == b->lower);
    ck_assert(a->upper == b->upper);
    ck_assert(a->colliding == b->colliding);
    ck_assert(a->beyond == b->beyond);
}

static void expect_interval(const noctDistanceResult *r, long double truth)
{
    ck_assert(r->lower <= r->distance && r->distance <= r->upper);
    ck_assert(r->lower <= truth + 1e-7L && truth - 1e-7L <= r->upper);
    ck_assert(r->upper - r->lower <= 1e-10);
}

typedef struct hits {
    int n;
    noctDistanceHit h[MAXO];
} hits;

static bool collect_hit(void *context, const noctDistanceHit *hit)
{
    hits *h = context;
    ck_assert_int_lt(h->n, MAXO);
    h->h[h->n++] = *hit;
    return true;
}

/* Object i of the scene, by its handle (user data). */
static int object_of(const world_scene *ws, noctObjectId id)
{
    for (int i = 0; i < ws->s.n; ++i)
        if (ws->s.id[i].index == id.index && ws->s.id[i].generation == id.generation)
            return i;
    ck_abort_msg("an unknown object");
    return -1;
}

/* ---- two objects ------------------------------------------------------------------- */

START_TEST(pairs_against_brute_force)
{
    for (int round = 0; round < (_i ? 10 : 2); ++round) {
        world_scene ws;
        make_scene(&ws, 8 + (int)(24 * uniform()), 1 + round % 4);
        scene *s = &ws.s;
        int exact = 0;
        for (int a = 0; a < s->n; ++a)
            for (int b = 0; b < s->n; ++b) {
                noctDistanceResult r;
                noctError err;
                const noctStatus st = noctWorldDistance(s->w, s->id[a], s->id[b], INFINITY,
                                                        &r, &err);
                if (ws.gone[a] || ws.gone[b]) {
                    ck_assert_int_eq(st, NOCT_ERR_INVALID);
                    continue;
                }
                ck_assert_int_eq(st, NOCT_OK);
                noctDistanceResult e;
                ck_assert_int_eq(noctDistance(mesh_of(s, a, ell), &s->x[a], mesh_of(s, b, ell),
                                              &s->x[b], INFINITY, &e, NULL, NULL),
                                 NOCT_OK);
                if (s->kind[a] != 0 && s->kind[b] != 0) {
                    expect_same_result(&r, &e);
                    for (int k = 0; k < 3; ++k) {
                        ck_assert(r.point_a[k] == e.point_a[k]);
                        ck_assert(r.point_b[k] == e.point_b[k]);
                    }
                    ++exact;
                } else {
                    ck_assert(fabs(r.distance - e.distance) <= TOL);
                }
                if (a == b)
                    ck_assert(r.colliding && r.distance == 0);
                expect_interval(&r, a == b ? 0 : ideal_distance(&s->g[a], &s->g[b]));
                /* a finite max_distance: beyond exactly when proved farther */
                const double max = 0.5 * uniform();
                ck_assert_int_eq(noctWorldDistance(s->w, s->id[a], s->id[b], max, &r, NULL),
                                 NOCT_OK);
                if (r.beyond)
                    ck_assert(e.upper > max);
                else
                    ck_assert(e.lower <= max * (1 + 1e-9) + 1e-12);
            }
        ck_assert_int_gt(exact, 0);
        free_scene(s);
    }
}
END_TEST

/* ---- the nearest and the objects within, for shapes ------------------------------------ */

static void check_shape_query(const world_scene *ws, const qshape *q, noctQueryFilter f,
                              double max, int *decided)
{
    const scene *s = &ws->s;
    noctDistanceResult bd[MAXO];
    int best = -1;
    for (int i = 0; i < s->n; ++i) {
        if (!live(ws, i, f))
            continue;
        bd[i] = brute(ws, q, i, INFINITY);
        expect_interval(&bd[i], ideal_distance(&q->g, &s->g[i]));
        if (best < 0 || bd[i].distance < bd[best].distance)
            best = i;
    }
    noctDistanceHit hit;
    bool got;
    ck_assert_int_eq(noctWorldQueryNearest(s->w, q_mesh(q), q_half(q), &q->x, max, f, &hit,
                                           &got, NULL),
                     NOCT_OK);
    if (best < 0 || bd[best].distance > max + TOL) {
        ck_assert(!got);
    } else if (bd[best].distance < max - TOL) {
        ck_assert(got);
    }
    if (got) {
        const int i = object_of(ws, hit.id);
        ck_assert(live(ws, i, f));
        ck_assert(hit.user_data == &s->id[i]);
        ck_assert(hit.result.distance <= max);
        /* no near tie: the same object; a near tie (a box primitive's
         * other triangulation): one of the tied */
        bool tie = false;
        for (int j = 0; j < s->n; ++j)
            tie = tie || (j != best && live(ws, j, f) &&
                          fabs(bd[j].distance - bd[best].distance) <= TOL);
        bool all_exact = true;
        for (int j = 0; j < s->n; ++j)
            all_exact = all_exact && (!live(ws, j, f) || exact_pair(ws, q, j));
        if (!tie || all_exact) {
            ck_assert_int_eq(i, best);
            ++*decided;
        } else {
            ck_assert(fabs(bd[i].distance - bd[best].distance) <= TOL);
        }
        if (exact_pair(ws, q, i))
            expect_same_result(&hit.result, &bd[i]);
        else
            ck_assert(fabs(hit.result.distance - bd[i].distance) <= TOL);
        expect_interval(&hit.result, ideal_distance(&q->g, &s->g[i]));
    }
    /* within max (finite): the set noctDistance() gives */
    const double within = isfinite(max) ? max : 1.5 * uniform();
    hits h = {0};
    ck_assert_int_eq(noctWorldQueryWithin(s->w, q_mesh(q), q_half(q), &q->x, within, f,
                                          collect_hit, &h, NULL),
                     NOCT_OK);
    int k = 0;
    for (int i = 0; i < s->n; ++i) {
        if (!live(ws, i, f))
            continue;
        const noctDistanceResult e = brute(ws, q, i, within);
        const bool expect = !e.beyond && e.lower <= within;
        const bool reported = k < h.n && object_of(ws, h.h[k].id) == i;
        if (exact_pair(ws, q, i) || fabs(bd[i].distance - within) > TOL)
            ck_assert_msg(reported == expect, "object %d: reported %d, expected %d", i,
                          reported, expect);
        if (reported) {
            if (exact_pair(ws, q, i))
                expect_same_result(&h.h[k].result, &e);
            ck_assert(h.h[k].result.lower <= within);
            ++k;
        }
    }
    ck_assert_int_eq(k, h.n); /* in order of index, nothing else */
}

START_TEST(shapes_against_brute_force)
{
    int decided = 0;
    for (int round = 0; round < (_i ? 12 : 3); ++round) {
        world_scene ws;
        make_scene(&ws, 6 + (int)(30 * uniform()), 1 + round % 5);
        for (int t = 0; t < (_i ? 40 : 15); ++t) {
            qshape q;
            make_qshape(&q, t % 3);
            const noctQueryFilter f = random_filter();
            const double u = uniform();
            const double max = u < 0.5 ? (double)INFINITY : u < 0.75 ? 0.3 : 2 * uniform();
            check_shape_query(&ws, &q, f, max, &decided);
            noctMeshDestroy(q.box);
        }
        free_scene(&ws.s);
    }
    ck_assert_int_gt(decided, 10);
}
END_TEST

/* ---- points ------------------------------------------------------------------------- */

START_TEST(points_against_geometry)
{
    int inside = 0, outside = 0;
    for (int round = 0; round < (_i ? 12 : 3); ++round) {
        world_scene ws;
        make_scene(&ws, 6 + (int)(30 * uniform()), 1 + round % 5);
        scene *s = &ws.s;
        for (int t = 0; t < (_i ? 200 : 60); ++t) {
            noctTransform x = noctIdentityTransform();
            for (int k = 0; k < 3; ++k)
                x.p[k] = -2 + 10 * uniform();
            if (t % 3 == 0) { /* near an object's origin: often inside */
                const int i = (int)(s->n * uniform());
                for (int k = 0; k < 3; ++k)
                    x.p[k] = s->x[i].p[k] - 0.4 + 0.8 * uniform();
            }
            random_quat(&x.q); /* ignored for a point */
            const noctQueryFilter f = random_filter();
            long double bd[MAXO];
            int best = -1;
            for (int i = 0; i < s->n; ++i) {
                if (!live(&ws, i, f))
                    continue;
                bd[i] = point_ideal(&s->g[i], x.p);
                if (best < 0 || bd[i] < bd[best])
                    best = i;
            }
            noctDistanceHit hit;
            bool got;
            ck_assert_int_eq(noctWorldQueryNearest(s->w, NULL, NULL, &x, INFINITY, f, &hit,
                                                   &got, NULL),
                             NOCT_OK);
            ck_assert(got == (best >= 0));
            if (!got)
                continue;
            const int i = object_of(&ws, hit.id);
            const noctDistanceResult *r = &hit.result;
            ck_assert(live(&ws, i, f));
            ck_assert(fabsl(bd[i] - bd[best]) <= TOL);
            expect_interval(r, bd[i]);
            for (int k = 0; k < 3; ++k) {
                ck_assert(r->point_a[k] == x.p[k]);
                ck_assert_uint_eq(r->triangle_a[k], NOCT_NO_TRIANGLE);
            }
            /* exact containment, both ways */
            const int c = ideal_contains(&s->g[i], x.p);
            if (r->colliding) {
                ck_assert_int_ne(c, 0);
                ck_assert(r->distance == 0 && r->lower == 0 && r->upper == 0);
                ++inside;
            } else {
                ck_assert_int_ne(c, 1);
                /* point_b on the object's boundary, as far as distance */
                ck_assert(point_ideal(&s->g[i], r->point_b) <= TOL);
                long double d2 = 0;
                for (int k = 0; k < 3; ++k)
                    d2 += (long double)(r->point_b[k] - x.p[k]) * (r->point_b[k] - x.p[k]);
                ck_assert(fabsl(sqrtl(d2) - r->distance) <= TOL);
                ck_assert_uint_ne(r->triangle_b[0], NOCT_NO_TRIANGLE);
                ++outside;
            }
            for (int j = 0; j < s->n; ++j)
                if (live(&ws, j, f) && ideal_contains(&s->g[j], x.p) == 1)
                    ck_assert(r->colliding);
            /* within: the objects nearer than d, by the ideal distances */
            const double d = uniform() < 0.2 ? 0 : 1.2 * uniform();
            hits h = {0};
            ck_assert_int_eq(noctWorldQueryWithin(s->w, NULL, NULL, &x, d, f, collect_hit, &h,
                                                  NULL),
                             NOCT_OK);
            int k = 0;
            for (int j = 0; j < s->n; ++j) {
                if (!live(&ws, j, f))
                    continue;
                const bool reported = k < h.n && object_of(&ws, h.h[k].id) == j;
                if (fabsl(bd[j] - d) > TOL)
                    ck_assert(reported == (bd[j] <= d));
                if (reported) {
                    expect_interval(&h.h[k].result, bd[j]);
                    ++k;
                }
            }
            ck_assert_int_eq(k, h.n);
            /* the nearest's result is the one within reports */
            ck_assert_int_eq(noctWorldQueryWithin(s->w, NULL, NULL, &x, r->upper, f,
                                                  collect_hit, &(hits){0}, NULL),
                             NOCT_OK);
        }
        free_scene(s);
    }
    ck_assert_int_gt(inside, 5);
    ck_assert_int_gt(outside, 50);
}
END_TEST

/* Points near a turned box primitive's faces, edges and corners, from
 * 1e-3 inside to 1e-3 outside (and on them): the nearest's colliding (its
 * containment, which the world first asks of the object's box form,
 * noct_point_slot_decide()) against noctWorldQueryPoint() (the exact
 * containment alone), and, where the offset is larger than the corners'
 * rounding, against the ideal box; the distance's interval against the
 * ideal distance. */
static bool contains_fcn(void *context, noctObjectId id, void *user)
{
    (void)id;
    (void)user;
    *(bool *)context = true;
    return true;
}

/* The nearest object to point x, with no limit and no filter (one must
 * be found). */
static noctDistanceHit nearest_to_point(const noctWorld *w, const noctTransform *x)
{
    noctDistanceHit hit;
    bool got;
    ck_assert_int_eq(noctWorldQueryNearest(w, NULL, NULL, x, INFINITY, noctDefaultQueryFilter(),
                                           &hit, &got, NULL),
                     NOCT_OK);
    ck_assert(got);
    return hit;
}

START_TEST(points_at_box_boundaries)
{
    static const double offsets[] = {-1e-3, -1e-6, -1e-9, -1e-12, -1e-14, 0,
                                     1e-14,  1e-12, 1e-9,  1e-6,   1e-3};
    const int noff = (int)(sizeof offsets / sizeof *offsets);
    int deep_in = 0, deep_out = 0, shallow = 0;
    /* rounds 0-7 a box primitive, 8-15 a mesh object of noctMeshCreateBox()
     * (its slot from the turned mesh's own box form) */
    for (int round = 0; round < 16; ++round) {
        noctWorld *w = new_world(0, NOCT_ACCURACY_EXACT);
        noctObjectDef def = noctDefaultObjectDef();
        ideal g;
        memset(&g, 0, sizeof g);
        double h[3];
        for (int k = 0; k < 3; ++k)
            h[k] = 0.1 + 2 * uniform();
        noctMesh *mesh = NULL;
        if (round >= 8) {
            ck_assert_int_eq(noctMeshCreateBox(h[0], h[1], h[2], &mesh, NULL), NOCT_OK);
            def.mesh = mesh;
        } else {
            memcpy(def.half_extents, h, sizeof h);
        }
        g.npieces = 1;
        g.pc[0] = (piece){{0, 0, 0}, {h[0], h[1], h[2]}};
        for (int k = 0; k < 3; ++k)
            def.transform.p[k] = g.t[k] = (round % 2 ? 1000 : 1) * (-5 + 10 * uniform());
        random_quat(&def.transform.q);
        quat_matrix(&def.transform.q, g.R);
        noctObjectId id;
        ck_assert_int_eq(noctWorldCreateObject(w, &def, &id, NULL), NOCT_OK);
        for (int t = 0; t < 300; ++t) {
            /* a point of the surface (local): one, two or three
             * coordinates at a face, the rest inside */
            long double l[3], n[3] = {0, 0, 0};
            const int at = 1 + t % 3;
            for (int k = 0; k < 3; ++k) {
                const long double s = uniform() < 0.5 ? -1 : 1;
                l[k] = k < at ? s * h[k] : (-1 + 2 * (long double)uniform()) * h[k];
                if (k < at)
                    n[k] = s;
            }
            const double off = offsets[t % noff];
            noctTransform x = noctIdentityTransform();
            for (int k = 0; k < 3; ++k) {
                long double v = g.t[k];
                for (int j = 0; j < 3; ++j)
                    v += g.R[3 * k + j] * (l[j] + off * n[j]);
                x.p[k] = (double)v;
            }
            bool in = false;
            ck_assert_int_eq(noctWorldQueryPoint(w, x.p, noctDefaultQueryFilter(), contains_fcn,
                                                 &in, NULL),
                             NOCT_OK);
            const noctDistanceHit hit = nearest_to_point(w, &x);
            ck_assert(hit.result.colliding == in);
            if (fabs(off) >= 1e-9) {
                ck_assert(in == (off < 0));
                ++*(off < 0 ? &deep_in : &deep_out);
            } else {
                ++shallow;
            }
            if (in) {
                for (int k = 0; k < 3; ++k)
                    ck_assert(hit.result.point_a[k] == x.p[k] &&
                              hit.result.point_b[k] == x.p[k]);
                ck_assert(hit.result.distance == 0 && hit.result.upper == 0);
            } else { /* the interval, within the accuracy at this place */
                const noctDistanceResult *r = &hit.result;
                const long double truth = point_ideal(&g, x.p), tol = 1e-7L;
                ck_assert(r->lower <= r->distance && r->distance <= r->upper);
                ck_assert(r->lower <= truth + tol && truth - tol <= r->upper);
                ck_assert(r->upper - r->lower <= 0x1p-38 * 1e4);
            }
        }
        noctWorldDestroy(w);
        noctMeshDestroy(mesh);
    }
    ck_assert_int_gt(deep_in, 1000);
    ck_assert_int_gt(deep_out, 1000);
    ck_assert_int_gt(shallow, 1000);
}
END_TEST

/* Six turned boxes about a point, each placed so that the point is at a
 * chosen distance from its corner, edge or face (D (1 + delta r), r in
 * [0, 1), delta 1e-2 to 1e-4: near ties), at scales 1, 2^-300, 2^300 and
 * 2^-480 (where the face axes' squares are too small for the three-axis
 * bound, which then stands aside), near the origin and 100 scales out:
 * the nearest object and its interval against the ideal boxes' distances
 * (long double). A point near a corner or an edge is farther than each of
 * the face axes' gaps alone, and the world skips an object whose three
 * gaps together prove it beyond the best (noct_point_apart_by()); a bound
 * larger than the truth by 1 % skips the true nearest here when a
 * farther object is searched first (made to fail so with the bound
 * 1.0001 times too large). At 2^300 a point beyond a face once got an
 * edge's point (the triangle's closed form overflowed): an interval
 * 0.4 % wide, and the wrong object. */
START_TEST(points_near_corners_and_ties)
{
    static const double scales[4] = {1, 0x1p-300, 0x1p300, 0x1p-480};
    static const double deltas[3] = {1e-2, 1e-3, 1e-4};
    int checked = 0, corner_best = 0;
    for (int v = 0; v < 8; ++v) {
        const double S = scales[v % 4], off = v >= 4 ? 100 * S : 0;
        for (int t = 0; t < 40; ++t) {
            noctWorld *w = new_world(t % 2 ? 1 : NOCT_AUTO, NOCT_ACCURACY_EXACT);
            const double delta = deltas[t % 3];
            double p[3];
            for (int k = 0; k < 3; ++k)
                p[k] = off + S * (-1 + 2 * uniform());
            ideal g[6];
            long double truth[6];
            int at[6];
            for (int i = 0; i < 6; ++i) {
                noctObjectDef d = noctDefaultObjectDef();
                memset(&g[i], 0, sizeof g[i]);
                g[i].npieces = 1;
                for (int k = 0; k < 3; ++k) {
                    d.half_extents[k] = S * (0.1 + 0.5 * uniform());
                    g[i].pc[0].h[k] = d.half_extents[k];
                }
                random_quat(&d.transform.q);
                quat_matrix(&d.transform.q, g[i].R);
                /* the point in the box's frame: beyond the faces of the
                 * first at[i] axes (a corner, an edge or a face), by a
                 * vector of length D in their positive cone */
                at[i] = 3 - i % 3;
                const long double D = S * 0.5L * (1 + delta * (long double)uniform());
                long double a[3] = {0, 0, 0}, n2 = 0, l[3];
                for (int k = 0; k < at[i]; ++k) {
                    a[k] = 0.05L + (long double)uniform();
                    n2 += a[k] * a[k];
                }
                for (int k = 0; k < 3; ++k) {
                    const long double sgn = uniform() < 0.5 ? -1 : 1;
                    l[k] = k < at[i] ? sgn * (g[i].pc[0].h[k] + D * a[k] / sqrtl(n2))
                                     : 0.9L * (-1 + 2 * (long double)uniform()) * g[i].pc[0].h[k];
                }
                for (int k = 0; k < 3; ++k) {
                    long double c = p[k];
                    for (int j = 0; j < 3; ++j)
                        c -= g[i].R[3 * k + j] * l[j];
                    d.transform.p[k] = (double)c;
                    g[i].t[k] = d.transform.p[k];
                }
                noctObjectId id;
                ck_assert_int_eq(noctWorldCreateObject(w, &d, &id, NULL), NOCT_OK);
                ck_assert_uint_eq(id.index, (unsigned)i);
                truth[i] = point_ideal(&g[i], p);
                ck_assert(fabsl(truth[i] - D) <= 1e-9L * (S + off));
            }
            int best = 0, second = -1;
            for (int i = 1; i < 6; ++i) {
                if (truth[i] < truth[best]) {
                    second = best;
                    best = i;
                } else if (second < 0 || truth[i] < truth[second]) {
                    second = i;
                }
            }
            noctTransform x = noctIdentityTransform();
            memcpy(x.p, p, sizeof p);
            const noctDistanceHit hit = nearest_to_point(w, &x);
            const noctDistanceResult *r = &hit.result;
            const long double tol = 1e-9L * (S + off);
            ck_assert(!r->colliding);
            ck_assert(r->lower <= r->distance && r->distance <= r->upper);
            ck_assert(r->lower <= truth[best] + tol && truth[best] - tol <= r->upper);
            const int hi = (int)hit.id.index;
            long double d2 = 0;
            for (int k = 0; k < 3; ++k)
                d2 += ((long double)r->point_b[k] - p[k]) * ((long double)r->point_b[k] - p[k]);
            ck_assert(point_ideal(&g[hi], r->point_b) <= tol);
            ck_assert(fabsl(sqrtl(d2) - truth[hi]) <= tol);
            if (truth[second] - truth[best] > 4 * tol) {
                ck_assert_uint_eq(hit.id.index, (unsigned)best);
                ++checked;
                corner_best += at[best] > 1;
            }
            noctWorldDestroy(w);
        }
    }
    ck_assert_int_gt(checked, 250);
    ck_assert_int_gt(corner_best, 150);
}
END_TEST

/* ---- ties and trees ------------------------------------------------------------------- */

/* Six unit boxes at distance 2 (faces at +-3 .. +-5 of the origin on each
 * axis) made in a shuffled order: a point, a box or a cube at the origin
 * is equally far from all of them, exactly. */
START_TEST(ties_to_the_least_index)
{
    noctWorld *w = new_world(1, NOCT_ACCURACY_EXACT);
    noctMesh *cube;
    ck_assert_int_eq(noctMeshCreateBox(1, 1, 1, &cube, NULL), NOCT_OK);
    static const int order[6] = {3, 0, 5, 1, 4, 2};
    noctObjectId id[6];
    for (int i = 0; i < 6; ++i) {
        noctObjectDef d = noctDefaultObjectDef();
        const int axis = order[i] / 2;
        d.transform.p[axis] = order[i] % 2 ? -4 : 4;
        if (i % 2)
            d.mesh = cube;
        else
            d.half_extents[0] = d.half_extents[1] = d.half_extents[2] = 1;
        ck_assert_int_eq(noctWorldCreateObject(w, &d, &id[i], NULL), NOCT_OK);
    }
    noctMesh *q, *q2;
    ck_assert_int_eq(noctMeshCreateBox(0.5, 0.5, 0.5, &q, NULL), NOCT_OK);
    ck_assert_int_eq(noctMeshCreateBox(1.25, 1.25, 1.25, &q2, NULL), NOCT_OK);
    const double half[3] = {0.5, 0.5, 0.5};
    for (int removed = 0; removed < 5; ++removed) {
        for (int kind = 0; kind < 3; ++kind) {
            noctTransform x = noctIdentityTransform();
            noctDistanceHit hit;
            bool got;
            ck_assert_int_eq(noctWorldQueryNearest(w, kind == 1 ? q : NULL,
                                                   kind == 0 ? half : NULL, &x, INFINITY,
                                                   noctDefaultQueryFilter(), &hit, &got,
                                                   NULL),
                             NOCT_OK);
            ck_assert(got);
            ck_assert_uint_eq(hit.id.index, id[removed].index);
            ck_assert(hit.result.distance == (kind == 2 ? 3 : 2.5));
            hits h = {0};
            ck_assert_int_eq(noctWorldQueryWithin(w, kind == 1 ? q : NULL,
                                                  kind == 0 ? half : NULL, &x,
                                                  kind == 2 ? 3 : 2.5, noctDefaultQueryFilter(),
                                                  collect_hit, &h, NULL),
                             NOCT_OK);
            ck_assert_int_eq(h.n, 6 - removed);
            ck_assert_int_eq(noctWorldQueryWithin(w, kind == 1 ? q : NULL,
                                                  kind == 0 ? half : NULL, &x,
                                                  kind == 2 ? 2.9 : 2.4, noctDefaultQueryFilter(),
                                                  collect_hit, &(hits){0}, NULL),
                             NOCT_OK);
            /* a box meeting two of them (+x, index 1, and +y, index 5): 0,
             * the least index */
            if (removed < 2 && kind < 2) {
                const double big[3] = {1.25, 1.25, 1.25};
                x.p[0] = x.p[1] = 2;
                ck_assert_int_eq(noctWorldQueryNearest(w, kind == 1 ? q2 : NULL,
                                                       kind == 0 ? big : NULL, &x, INFINITY,
                                                       noctDefaultQueryFilter(), &hit, &got,
                                                       NULL),
                                 NOCT_OK);
                ck_assert(got && hit.result.colliding && hit.result.distance == 0);
                ck_assert_uint_eq(hit.id.index, id[1].index);
            }
        }
        ck_assert_int_eq(noctWorldRemove(w, id[removed], NULL), NOCT_OK);
        ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    }
    noctMeshDestroy(q);
    noctMeshDestroy(q2);
    noctMeshDestroy(cube);
    noctWorldDestroy(w);
}
END_TEST

START_TEST(the_tree_does_not_show)
{
    const uint64_t seed = rng;
    world_scene ws[3];
    static const int N[3] = {1, 4, NOCT_N_EXHAUSTIVE};
    for (int v = 0; v < 3; ++v) {
        rng = seed;
        make_scene(&ws[v], 40, N[v]);
        /* histories: steps, a teleport away and back */
        for (int t = 0; t < v; ++t)
            ck_assert_int_eq(noctWorldStep(ws[v].s.w, NULL), NOCT_OK);
    }
    for (int t = 0; t < 100; ++t) {
        qshape q;
        make_qshape(&q, t % 4 == 3 ? 2 : t % 4);
        const bool point = t % 5 == 4;
        noctDistanceHit hit[3];
        bool got[3];
        for (int v = 0; v < 3; ++v)
            ck_assert_int_eq(noctWorldQueryNearest(ws[v].s.w, point ? NULL : q_mesh(&q),
                                                   point ? NULL : q_half(&q), &q.x, INFINITY,
                                                   noctDefaultQueryFilter(), &hit[v], &got[v],
                                                   NULL),
                             NOCT_OK);
        for (int v = 1; v < 3; ++v) {
            ck_assert(got[v] == got[0]);
            ck_assert_uint_eq(hit[v].id.index, hit[0].id.index);
            expect_same_result(&hit[v].result, &hit[0].result);
        }
        noctMeshDestroy(q.box);
    }
    for (int v = 0; v < 3; ++v)
        free_scene(&ws[v].s);
}
END_TEST

/* ---- the nearest's walk ------------------------------------------------------------------ */

#define WALK_OBJECTS 360

/* A world for the walk: a dense cluster of small turned boxes in the unit
 * cube (many in one leaf for a large N) and others scattered over
 * [-20, 20]^3, some with filters, some moved and some removed; the ideal
 * solids beside it. */
typedef struct walk_world {
    noctWorld *w;
    int n;
    noctObjectId id[WALK_OBJECTS];
    ideal g[WALK_OBJECTS];
    uint64_t cat[WALK_OBJECTS], mask[WALK_OBJECTS];
    bool gone[WALK_OBJECTS];
} walk_world;

static void walk_place(walk_world *ww, int i, noctTransform *x, bool cluster)
{
    for (int k = 0; k < 3; ++k)
        x->p[k] = cluster ? uniform() : -20 + 40 * uniform();
    random_quat(&x->q);
    quat_matrix(&x->q, ww->g[i].R);
    for (int k = 0; k < 3; ++k)
        ww->g[i].t[k] = x->p[k];
}

static void make_walk_world(walk_world *ww, int n, int N)
{
    memset(ww, 0, sizeof *ww);
    ww->w = new_world(N, NOCT_ACCURACY_EXACT);
    ww->n = n;
    for (int i = 0; i < n; ++i) {
        noctObjectDef d = noctDefaultObjectDef();
        const bool cluster = i % 4 != 3;
        double h[3];
        for (int k = 0; k < 3; ++k)
            h[k] = cluster ? 0.02 + 0.08 * uniform() : 0.2 + 0.8 * uniform();
        memcpy(d.half_extents, h, sizeof h);
        ww->g[i].npieces = 1;
        ww->g[i].pc[0] = (piece){{0, 0, 0}, {h[0], h[1], h[2]}};
        walk_place(ww, i, &d.transform, cluster);
        d.category = ww->cat[i] = random_bits();
        d.mask = ww->mask[i] = random_bits();
        d.user_data = &ww->id[i];
        ck_assert_int_eq(noctWorldCreateObject(ww->w, &d, &ww->id[i], NULL), NOCT_OK);
    }
    for (int i = 0; i < n; ++i) {
        const double u = uniform();
        if (u < 0.1) {
            noctTransform x;
            walk_place(ww, i, &x, uniform() < 0.5);
            ck_assert_int_eq(noctWorldSetTransform(ww->w, ww->id[i], &x, NULL), NOCT_OK);
        } else if (u < 0.2) {
            ck_assert_int_eq(noctWorldRemove(ww->w, ww->id[i], NULL), NOCT_OK);
            ww->gone[i] = true;
        }
    }
    if (uniform() < 0.5)
        ck_assert_int_eq(noctWorldStep(ww->w, NULL), NOCT_OK);
}

static bool walk_live(const walk_world *ww, int i, noctQueryFilter f)
{
    return !ww->gone[i] && (ww->cat[i] & f.mask) != 0 && (f.category & ww->mask[i]) != 0;
}

/* The brute force: every object, by noctWorldQueryWithin() over a distance
 * that holds them all (the broadphase's box query, not the walk), with
 * the distances the world computes; the least (distance, index) within
 * max. */
typedef struct walk_all {
    double max;
    int count;
    bool got;
    uint32_t index;
    double distance;
    double d[WALK_OBJECTS]; /* by index: the computed distances */
} walk_all;

static bool walk_collect(void *context, const noctDistanceHit *hit)
{
    walk_all *a = context;
    ck_assert_uint_lt(hit->id.index, WALK_OBJECTS);
    a->d[hit->id.index] = hit->result.distance;
    ++a->count;
    if (hit->result.distance <= a->max &&
        (!a->got || hit->result.distance < a->distance ||
         (hit->result.distance == a->distance && hit->id.index < a->index))) {
        a->got = true;
        a->index = hit->id.index;
        a->distance = hit->result.distance;
    }
    return true;
}

/* The query against the brute force (and, for a point, against the ideal
 * solids); returns the brute force's best distance (INFINITY: none). */
static double check_walk_query(const walk_world *ww, const double *half, const noctTransform *x,
                               double max, noctQueryFilter f)
{
    walk_all a;
    memset(&a, 0, sizeof a);
    a.max = max;
    for (int i = 0; i < WALK_OBJECTS; ++i)
        a.d[i] = NAN;
    ck_assert_int_eq(noctWorldQueryWithin(ww->w, NULL, half, x, 1e7, f, walk_collect, &a, NULL),
                     NOCT_OK);
    int live = 0;
    for (int i = 0; i < ww->n; ++i)
        live += walk_live(ww, i, f);
    ck_assert_int_eq(a.count, live);
    noctDistanceHit hit;
    bool got;
    ck_assert_int_eq(noctWorldQueryNearest(ww->w, NULL, half, x, max, f, &hit, &got, NULL),
                     NOCT_OK);
    ck_assert(got == a.got);
    if (!got)
        return a.got ? a.distance : (double)INFINITY;
    const uint32_t i = hit.id.index;
    ck_assert(walk_live(ww, (int)i, f));
    ck_assert(hit.user_data == &ww->id[i]);
    ck_assert(hit.id.generation == ww->id[i].generation);
    ck_assert(hit.result.distance <= max);
    if (half == NULL) { /* a point's distance does not depend on the search's max */
        ck_assert_uint_eq(i, a.index);
        ck_assert(hit.result.distance == a.distance);
        /* and against the ideal solids */
        long double best = INFINITY;
        for (int j = 0; j < ww->n; ++j)
            if (walk_live(ww, j, f))
                best = fminl(best, point_ideal(&ww->g[j], x->p));
        const long double mine = point_ideal(&ww->g[i], x->p);
        ck_assert(mine - best <= TOL);
        ck_assert(hit.result.lower <= mine + 1e-9L && mine - 1e-9L <= hit.result.upper);
    } else { /* the same object but in a near tie */
        ck_assert(fabs(hit.result.distance - a.distance) <= TOL);
        if (i != a.index)
            ck_assert(fabs(a.d[i] - a.distance) <= TOL);
    }
    return a.distance;
}

START_TEST(walk_against_brute_force)
{
    static const int N[4] = {1, 4, NOCT_AUTO, NOCT_N_EXHAUSTIVE};
    int queries = 0, cut = 0;
    for (int v = 0; v < 4; ++v) {
        walk_world ww;
        make_walk_world(&ww, WALK_OBJECTS, N[v]);
        for (int t = 0; t < 40; ++t) {
            noctTransform x;
            const int where = t % 4;
            for (int k = 0; k < 3; ++k)
                x.p[k] = where == 0   ? uniform()                 /* in the cluster */
                         : where == 1 ? -22 + 44 * uniform()      /* among the others */
                         : where == 2 ? 1e3 * (1 + uniform())     /* far outside */
                                      : -1e6 * (1 + uniform());
            random_quat(&x.q);
            double half[3];
            for (int k = 0; k < 3; ++k)
                half[k] = 0.05 + 0.5 * uniform();
            const bool point = t % 3 != 2;
            const noctQueryFilter f = t % 5 == 4 ? random_filter() : noctDefaultQueryFilter();
            const double *h = point ? NULL : half;
            const double best = check_walk_query(&ww, h, &x, INFINITY, f);
            ++queries;
            if (!isfinite(best))
                continue;
            /* a max_distance at the best's distance, exactly: found; just
             * below it (for a point, whose distance does not depend on the
             * search's max): nothing */
            check_walk_query(&ww, h, &x, best, f);
            if (point && best > 0) {
                ck_assert(!isfinite(check_walk_query(&ww, h, &x, nextafter(best, 0), f)));
                ++cut;
            }
            check_walk_query(&ww, h, &x, best * uniform(), f);
        }
        /* a filter no object passes, then every object removed */
        noctTransform x = noctIdentityTransform();
        const noctQueryFilter none = {0, 0};
        noctDistanceHit hit;
        bool got = true;
        ck_assert_int_eq(noctWorldQueryNearest(ww.w, NULL, NULL, &x, INFINITY, none, &hit, &got,
                                               NULL),
                         NOCT_OK);
        ck_assert(!got);
        for (int i = 0; i < ww.n; ++i)
            if (!ww.gone[i]) {
                ck_assert_int_eq(noctWorldRemove(ww.w, ww.id[i], NULL), NOCT_OK);
                ww.gone[i] = true;
            }
        for (int step = 0; step < 2; ++step) {
            got = true;
            ck_assert_int_eq(noctWorldQueryNearest(ww.w, NULL, NULL, &x, INFINITY,
                                                   noctDefaultQueryFilter(), &hit, &got, NULL),
                             NOCT_OK);
            ck_assert(!got);
            ck_assert_int_eq(noctWorldStep(ww.w, NULL), NOCT_OK);
        }
        noctWorldDestroy(ww.w);
    }
    ck_assert_int_gt(cut, 20);
    ck_assert_int_eq(queries, 160);
    /* an empty world */
    noctWorld *w = new_world(1, NOCT_ACCURACY_EXACT);
    noctTransform x = noctIdentityTransform();
    const double half[3] = {1, 1, 1};
    noctDistanceHit hit;
    bool got = true;
    ck_assert_int_eq(noctWorldQueryNearest(w, NULL, half, &x, INFINITY,
                                           noctDefaultQueryFilter(), &hit, &got, NULL),
                     NOCT_OK);
    ck_assert(!got);
    noctWorldDestroy(w);
}
END_TEST

/* The walk at the extreme scales: dyadic boxes on a grid (faces shared,
 * many exact ties, boxes nested and overlapping) at sizes 2^-300 and
 * 2^300, offset by 2^40 of their size, off by 1e99 with queries up to
 * 4e99 from them, and tiny boxes beside huge ones in one tree; point
 * and box queries on the grid (ties at distance 0), between, far
 * outside, with filters; max_distance 0, the best's distance and just
 * below it. The answer against the least (distance, index) over every
 * object of noctWorldQueryWithin() (the box query, not the walk): the
 * same object and distance for points and at distance 0, a near tie
 * otherwise. */
typedef struct scale_all {
    int n;
    double d[2 * WALK_OBJECTS];
} scale_all;

static bool scale_collect(void *context, const noctDistanceHit *hit)
{
    scale_all *a = context;
    ck_assert_uint_lt(hit->id.index, 2 * WALK_OBJECTS);
    a->d[hit->id.index] = hit->result.distance;
    ++a->n;
    return true;
}

static double scale_check(noctWorld *w, const double *half, const noctTransform *x, double max,
                          noctQueryFilter f)
{
    scale_all a;
    a.n = 0;
    for (int i = 0; i < 2 * WALK_OBJECTS; ++i)
        a.d[i] = NAN;
    ck_assert_int_eq(noctWorldQueryWithin(w, NULL, half, x, 1e100, f, scale_collect, &a, NULL),
                     NOCT_OK);
    bool got = false;
    uint32_t bi = 0;
    double bd = INFINITY;
    for (int i = 0; i < 2 * WALK_OBJECTS; ++i)
        if (!isnan(a.d[i]) && a.d[i] <= max && (!got || a.d[i] < bd)) {
            got = true;
            bi = (uint32_t)i;
            bd = a.d[i];
        }
    noctDistanceHit hit;
    bool hit_got;
    ck_assert_int_eq(noctWorldQueryNearest(w, NULL, half, x, max, f, &hit, &hit_got, NULL),
                     NOCT_OK);
    ck_assert(hit_got == got);
    if (!hit_got)
        return bd;
    if (half == NULL || bd == 0) {
        ck_assert_uint_eq(hit.id.index, bi);
        ck_assert(hit.result.distance == bd);
    } else {
        ck_assert(fabs(hit.result.distance - bd) <= 1e-9 * bd);
    }
    return bd;
}

START_TEST(walk_at_extreme_scales)
{
    static const int N[3] = {1, 2, NOCT_AUTO};
    for (int v = 0; v < 5; ++v) {
        const double scale = v == 1 ? 0x1p-300 : v == 2 ? 0x1p300 : 1;
        const double off = v == 3 ? 0x1p40 : v == 4 ? 1e99 : 0;
        const bool mixed = v == 0;
        noctWorld *w = new_world(N[v % 3], NOCT_ACCURACY_EXACT);
        noctObjectId id[WALK_OBJECTS];
        const int n = 120;
        for (int i = 0; i < n; ++i) {
            noctObjectDef d = noctDefaultObjectDef();
            const int kind = (int)(4 * uniform());
            for (int k = 0; k < 3; ++k) {
                const double h = kind == 0   ? 0.5
                                 : kind == 1 ? 0x1p-20
                                 : kind == 2 ? 0.25 * (1 + (int)(4 * uniform()))
                                             : 2;
                const double p = (double)((int)(16 * uniform()) - 8) * 0.5;
                d.half_extents[k] = mixed ? (i % 7 == 0 ? h * 1e50 : h * 0x1p-300) : h * scale;
                d.transform.p[k] = mixed ? (i % 7 == 0 ? p * 1e51 : p * 0x1p-299) : off + p * scale;
            }
            if (uniform() < 0.3)
                random_quat(&d.transform.q);
            if (uniform() < 0.2) {
                d.category = (uint64_t)1 << (int)(3 * uniform());
                d.mask = uniform() < 0.5 ? NOCT_FILTER_ALL : (uint64_t)1 << (int)(3 * uniform());
            }
            ck_assert_int_eq(noctWorldCreateObject(w, &d, &id[i], NULL), NOCT_OK);
        }
        for (int i = 0; i < n; ++i)
            if (uniform() < 0.1)
                ck_assert_int_eq(noctWorldRemove(w, id[i], NULL), NOCT_OK);
        if (uniform() < 0.5)
            ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
        for (int t = 0; t < 40; ++t) {
            noctTransform x = noctIdentityTransform();
            const int where = t % 5;
            double half[3];
            for (int k = 0; k < 3; ++k) {
                const double p = where == 0   ? (double)((int)(16 * uniform()) - 8) * 0.5
                                 : where == 1 ? 10 * uniform() - 5
                                 : where == 2 ? 1e3 * (1 + uniform())
                                 : where == 3 ? -1e6
                                              : (double)((int)(16 * uniform()) - 8) * 0.25;
                half[k] = (t % 3 == 2 ? 0.25 * (1 + (int)(3 * uniform())) : 0.5) * scale;
                x.p[k] = off + p * scale;
                if (mixed) {
                    x.p[k] = where < 2 ? p * 0x1p-300 : where == 2 ? p * 1e45 : p;
                    half[k] = where < 2 ? half[k] * 0x1p-300 : half[k];
                }
                if (v == 4 && where >= 2)
                    x.p[k] = (uniform() < 0.5 ? -4e99 : 4e99) * (uniform() < 0.5 ? 1 : 0.5);
            }
            const double *h = t % 3 == 0 ? half : NULL;
            noctQueryFilter f = noctDefaultQueryFilter();
            if (t % 4 == 3) {
                f.category = (uint64_t)1 << (int)(3 * uniform());
                f.mask = (uint64_t)1 << (int)(3 * uniform());
            }
            const double best = scale_check(w, h, &x, INFINITY, f);
            scale_check(w, h, &x, 0, f);
            if (isfinite(best)) {
                scale_check(w, h, &x, best, f);
                if (best > 0 && h == NULL)
                    ck_assert(!isfinite(scale_check(w, h, &x, nextafter(best, 0), f)));
            }
        }
        noctWorldDestroy(w);
    }
}
END_TEST

/* ---- the near pairs ---------------------------------------------------------------------- */

START_TEST(near_distances_against_pairs)
{
    int pairs = 0;
    for (int round = 0; round < (_i ? 8 : 2); ++round) {
        const double margin = world_margin = 0.2 + 0.3 * uniform();
        world_scene ws;
        make_scene(&ws, 10 + (int)(30 * uniform()), 1 + round % 4);
        world_margin = 0;
        scene *s = &ws.s;
        ck_assert_int_eq(noctWorldStep(s->w, NULL), NOCT_OK);
        const noctPair *p;
        const size_t n = noctWorldNear(s->w, &p);
        const noctDistanceResult *r, *again;
        size_t m;
        ck_assert_int_eq(noctWorldNearDistances(s->w, &r, &m, NULL), NOCT_OK);
        ck_assert_uint_eq(m, n);
        for (size_t i = 0; i < n; ++i) {
            noctDistanceResult e;
            ck_assert_int_eq(noctWorldDistance(s->w, p[i].a, p[i].b, INFINITY, &e, NULL),
                             NOCT_OK);
            expect_same_result(&r[i], &e);
            const int a = object_of(&ws, p[i].a), b = object_of(&ws, p[i].b);
            ck_assert(r[i].lower <= margin + 1e-9);
            expect_interval(&r[i], ideal_distance(&s->g[a], &s->g[b]));
            ++pairs;
        }
        ck_assert_int_eq(noctWorldNearDistances(s->w, &again, &m, NULL), NOCT_OK);
        ck_assert(again == r && m == n); /* kept, not made again */
        /* a step makes them again; an object removed before the first
         * call gets NaN */
        ck_assert_int_eq(noctWorldStep(s->w, NULL), NOCT_OK);
        const size_t n2 = noctWorldNear(s->w, &p);
        if (n2 > 0) {
            const noctObjectId gone = p[0].a;
            ck_assert_int_eq(noctWorldRemove(s->w, gone, NULL), NOCT_OK);
            ck_assert_int_eq(noctWorldNearDistances(s->w, &r, &m, NULL), NOCT_OK);
            ck_assert_uint_eq(m, n2);
            ck_assert(isnan(r[0].distance) && isnan(r[0].lower) && isnan(r[0].upper));
            for (size_t i = 0; i < m; ++i)
                if (p[i].a.index != gone.index && p[i].b.index != gone.index)
                    ck_assert(!isnan(r[i].distance));
        }
        free_scene(s);
    }
    ck_assert_int_gt(pairs, 5);
    /* no margin: nothing, and nothing made */
    noctWorld *w = new_world(1, NOCT_ACCURACY_EXACT);
    ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    const noctDistanceResult *r = (const noctDistanceResult *)1;
    size_t m = 7;
    ck_assert_int_eq(noctWorldNearDistances(w, &r, &m, NULL), NOCT_OK);
    ck_assert(r == NULL && m == 0);
    noctWorldDestroy(w);
}
END_TEST

/* ---- bad input ------------------------------------------------------------------------ */

static bool never(void *context, const noctDistanceHit *hit)
{
    (void)context;
    (void)hit;
    ck_abort_msg("called on bad input");
    return true;
}

START_TEST(bad_input)
{
    noctWorld *w = new_world(1, NOCT_ACCURACY_EXACT);
    noctObjectDef d = noctDefaultObjectDef();
    d.half_extents[0] = d.half_extents[1] = d.half_extents[2] = 1;
    noctObjectId a, b;
    ck_assert_int_eq(noctWorldCreateObject(w, &d, &a, NULL), NOCT_OK);
    d.transform.p[0] = 5;
    ck_assert_int_eq(noctWorldCreateObject(w, &d, &b, NULL), NOCT_OK);
    noctDistanceResult r;
    noctError err;
    ck_assert_int_eq(noctWorldDistance(w, a, b, NAN, &r, &err), NOCT_ERR_NONFINITE);
    ck_assert_int_eq(noctWorldDistance(w, a, b, -1, &r, &err), NOCT_ERR_INVALID);
    ck_assert_int_eq(noctWorldDistance(w, a, b, INFINITY, &r, &err), NOCT_OK);
    ck_assert(r.distance == 3 && !r.colliding);
    ck_assert_int_eq(noctWorldDistance(w, a, b, 2.5, &r, &err), NOCT_OK);
    ck_assert(r.beyond);
    ck_assert_int_eq(noctWorldDistance(w, a, (noctObjectId){77, 0}, 1, &r, &err),
                     NOCT_ERR_INVALID);
    noctTransform x = noctIdentityTransform();
    noctDistanceHit hit;
    bool got = true;
    const noctQueryFilter f = noctDefaultQueryFilter();
    ck_assert_int_eq(noctWorldQueryNearest(w, NULL, NULL, &x, NAN, f, &hit, &got, &err),
                     NOCT_ERR_NONFINITE);
    ck_assert(!got);
    ck_assert_int_eq(noctWorldQueryNearest(w, NULL, NULL, &x, -0.5, f, &hit, &got, &err),
                     NOCT_ERR_INVALID);
    ck_assert_int_eq(noctWorldQueryWithin(w, NULL, NULL, &x, NAN, f, never, NULL, &err),
                     NOCT_ERR_NONFINITE);
    ck_assert_int_eq(noctWorldQueryWithin(w, NULL, NULL, &x, -1, f, never, NULL, &err),
                     NOCT_ERR_INVALID);
    ck_assert_int_eq(noctWorldQueryWithin(w, NULL, NULL, &x, 1e101, f, never, NULL, &err),
                     NOCT_ERR_INVALID);
    x.p[1] = 2e100;
    ck_assert_int_eq(noctWorldQueryNearest(w, NULL, NULL, &x, 1, f, &hit, &got, &err),
                     NOCT_ERR_TOO_LARGE);
    ck_assert_int_eq(noctWorldQueryWithin(w, NULL, NULL, &x, 1, f, never, NULL, &err),
                     NOCT_ERR_TOO_LARGE);
    x.p[1] = NAN;
    ck_assert_int_eq(noctWorldQueryWithin(w, NULL, NULL, &x, 1, f, never, NULL, &err),
                     NOCT_ERR_NONFINITE);
    x.p[1] = 0;
    const double bad_half[3] = {1, -1, 1};
    ck_assert_int_eq(noctWorldQueryWithin(w, NULL, bad_half, &x, 1, f, never, NULL, &err),
                     NOCT_ERR_INVALID);
    x.q = (noctQuat){0, 0, 0, 0};
    const double half[3] = {1, 1, 1};
    ck_assert_int_ne(noctWorldQueryNearest(w, NULL, half, &x, 1, f, &hit, &got, &err),
                     NOCT_OK);
    ck_assert(!got);
    /* a point's rotation is ignored */
    ck_assert_int_eq(noctWorldQueryNearest(w, NULL, NULL, &x, INFINITY, f, &hit, &got, &err),
                     NOCT_OK);
    ck_assert(got && hit.id.index == a.index && hit.result.colliding);
    /* removed: never found again, and its handle is stale */
    ck_assert_int_eq(noctWorldRemove(w, a, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldDistance(w, a, b, 1, &r, &err), NOCT_ERR_INVALID);
    x.q = (noctQuat){0, 0, 0, 1};
    ck_assert_int_eq(noctWorldQueryNearest(w, NULL, NULL, &x, INFINITY, f, &hit, &got, &err),
                     NOCT_OK);
    ck_assert(got && hit.id.index == b.index && hit.result.distance == 4);
    ck_assert_int_eq(noctWorldQueryNearest(w, NULL, NULL, &x, 3.5, f, &hit, &got, &err),
                     NOCT_OK);
    ck_assert(!got);
    noctWorldDestroy(w);
}
END_TEST

static Suite *distance_world_suite(void)
{
    Suite *s = suite_create("distance_world");
    TCase *tc = test_case(s, "distance world", 300, NULL);
    tcase_add_checked_fixture(tc, make_ell_fixture, free_ell_fixture);
    tcase_add_loop_test(tc, pairs_against_brute_force, 0, 1);
    tcase_add_loop_test(tc, shapes_against_brute_force, 0, 1);
    tcase_add_loop_test(tc, points_against_geometry, 0, 1);
    tcase_add_test(tc, ties_to_the_least_index);
    tcase_add_test(tc, the_tree_does_not_show);
    tcase_add_test(tc, walk_against_brute_force);
    tcase_add_test(tc, walk_at_extreme_scales);
    tcase_add_test(tc, points_at_box_boundaries);
    tcase_add_test(tc, points_near_corners_and_ties);
    tcase_add_loop_test(tc, near_distances_against_pairs, 0, 1);
    tcase_add_test(tc, bad_input);
    TCase *full = test_case(s, "distance world, full", 600, "slow seeds");
    tcase_add_checked_fixture(full, make_ell_fixture, free_ell_fixture);
    tcase_add_loop_test(full, pairs_against_brute_force, 1, 2);
    tcase_add_loop_test(full, shapes_against_brute_force, 1, 2);
    tcase_add_loop_test(full, points_against_geometry, 1, 2);
    tcase_add_loop_test(full, near_distances_against_pairs, 1, 2);
    return s;
}

int main(void)
{
    return run_suite(distance_world_suite());
}
