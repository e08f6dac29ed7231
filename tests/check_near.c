/* SPDX-License-Identifier: MIT */
/*
 * The margin (noctWorldDef::margin, noctWorldNear(), noctWorldQueryNear())
 * against the test's own distances between the ideal solids (testgeom.c:
 * from their edges, by ternary search, in long double): on random rotated
 * scenes of boxes and L meshes with filters and sensors, moved every step,
 * a pair within the margin is never missed and one clearly beyond it is
 * never near; colliding pairs are near; the near events are the lists'
 * differences step to step, removals included; the box level uses the
 * boxes; a failed step keeps the lists; bad margins get a status. The
 * objects' own margins against noctDistance()'s proved intervals.
 */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <noctree.h>

#include "testgeom.h"
#include "testutil.h"

/* May objects i and j pair: filters, no sensor? */
static bool may_pair(const scene *s, int i, int j)
{
    return !s->sensor[i] && !s->sensor[j] && (s->cat[i] & s->mask[j]) != 0 &&
           (s->cat[j] & s->mask[i]) != 0;
}

static int index_of(const scene *s, uint32_t slot)
{
    for (int i = 0; i < s->n; ++i)
        if (s->id[i].index == slot)
            return i;
    return -1;
}

static bool in_list(const noctPair *p, size_t n, noctObjectId a, noctObjectId b)
{
    for (size_t k = 0; k < n; ++k)
        if (p[k].a.index == a.index && p[k].b.index == b.index &&
            p[k].a.generation == a.generation && p[k].b.generation == b.generation)
            return true;
    return false;
}

/* Teleport object i to a random pose (the test keeps its ideal pose). */
static void teleport(scene *s, int i)
{
    noctTransform x;
    for (int k = 0; k < 3; ++k)
        x.p[k] = 6 * uniform();
    random_quat(&x.q);
    ck_assert_int_eq(noctWorldSetTransform(s->w, s->id[i], &x, NULL), NOCT_OK);
    s->x[i] = x;
    quat_matrix(&x.q, s->g[i].R);
    for (int k = 0; k < 3; ++k)
        s->g[i].t[k] = x.p[k];
}

/* The slack the library allows beyond the margin (2^-40 of the largest
 * coordinate, here under 10), and the test's own doubt. */
#define BEYOND 1e-9L

/* _i: 0 a quick run (under valgrind too), 1 the full one (tag slow). */
/* The L-shaped mesh the random scenes use, made for each test by the
 * test cases' fixture. */
/* The near verdict got for two objects dist apart (ideal) with margin d,
 * on a step: checked where dist is clear of d by BEYOND; 0 within, 1
 * beyond, 2 too close to tell. */
static int near_verdict(bool got, long double dist, double d, int step, int i, int j)
{
    if (dist <= d - BEYOND) {
        ck_assert_msg(got, "step %d: objects %d and %d, %.12Lg apart, not near (margin %g)",
                      step, i, j, dist, d);
        return 0;
    }
    if (dist > d + BEYOND) {
        ck_assert_msg(!got, "step %d: objects %d and %d, %.12Lg apart, near (margin %g)", step,
                      i, j, dist, d);
        return 1;
    }
    return 2;
}

/* The ideal distance of a and b for a verdict at margin d: ideal_distance(),
 * or, when the pieces' boxes alone put the solids beyond d by twice
 * BEYOND (the bound's own rounding far below that), that lower bound: the
 * same verdict, beyond, without the edges' searches (most pairs of a
 * random scene, which made those searches most of the suite's time). */
static long double distance_for(const ideal *a, const ideal *b, double d)
{
    const long double lower = ideal_distance_lower(a, b);
    return lower > d + 2 * BEYOND ? lower : ideal_distance(a, b);
}

static noctMesh *ell;

/* Also restarts the scenes' RNG: each test draws the same scenes in one
 * process (CK_FORK=no, as under valgrind) as in its own forked one. */
static void make_ell_fixture(void)
{
    rng = RNG_SEED;
    ell = make_ell();
}

static void free_ell_fixture(void)
{
    noctMeshDestroy(ell);
    ell = NULL;
}

START_TEST(near_pairs_against_geometry)
{
    int within = 0, beyond = 0, skipped = 0, events = 0, removed_ended = 0;
    const int rounds = _i ? 4 : 1;
    for (int round = 0; round < rounds; ++round) {
        world_margin = 0.05 + 0.6 * uniform();
        const double d = world_margin;
        scene s;
        random_scene(&s, 10 + (int)(25 * uniform()), 1 + round % 4, NOCT_ACCURACY_EXACT, ell);
        world_margin = 0;
        noctPair prev[MAXO * MAXO / 2];
        size_t nprev = 0;
        for (int step = 0; step < 12; ++step) {
            for (int i = 0; i < s.n; ++i)
                if (uniform() < 0.3 && !(i == 0 && step > 6))
                    teleport(&s, i);
            /* From step 4 no object has a filter (all bits: the world's
             * sweeps then skip the filters' test), from step 8 the last
             * one has a filter that pairs with nothing (mask 0): the
             * test's own filters follow (may_pair) */
            if (step == 4 || step == 8)
                for (int i = step == 4 ? 0 : s.n - 1; i < s.n; ++i) {
                    s.cat[i] = step == 4 ? NOCT_FILTER_ALL : 1;
                    s.mask[i] = step == 4 ? NOCT_FILTER_ALL : 0;
                    ck_assert_int_eq(noctWorldSetFilter(s.w, s.id[i], s.cat[i], s.mask[i], NULL),
                                     NOCT_OK);
                }
            /* one object goes at step 6: its near pairs end at once */
            noctObjectId gone = {UINT32_MAX, 0};
            if (step == 6) {
                gone = s.id[0];
                ck_assert_int_eq(noctWorldRemove(s.w, gone, NULL), NOCT_OK);
            }
            ck_assert_int_eq(noctWorldStep(s.w, NULL), NOCT_OK);
            const noctPair *near, *col, *b, *e;
            const size_t nn = noctWorldNear(s.w, &near);
            const size_t nc = noctWorldColliding(s.w, &col);
            const size_t nb = noctWorldNearBegan(s.w, &b), ne = noctWorldNearEnded(s.w, &e);
            /* sorted, no sensors, filters kept */
            for (size_t k = 0; k < nn; ++k) {
                ck_assert_uint_lt(near[k].a.index, near[k].b.index);
                if (k > 0)
                    ck_assert(near[k - 1].a.index < near[k].a.index ||
                              (near[k - 1].a.index == near[k].a.index &&
                               near[k - 1].b.index < near[k].b.index));
                const int i = index_of(&s, near[k].a.index), j = index_of(&s, near[k].b.index);
                ck_assert(i >= 0 && j >= 0 && may_pair(&s, i, j));
            }
            /* colliding pairs are near */
            for (size_t k = 0; k < nc; ++k)
                ck_assert(in_list(near, nn, col[k].a, col[k].b));
            /* every pair that may pair, against the ideal distance */
            for (int i = 0; i < s.n; ++i)
                for (int j = i + 1; j < s.n; ++j) {
                    if (!may_pair(&s, i, j) || (step >= 6 && (i == 0 || j == 0)))
                        continue;
                    const long double dist = distance_for(&s.g[i], &s.g[j], d);
                    noctObjectId a = s.id[i], c = s.id[j];
                    if (a.index > c.index) {
                        const noctObjectId t = a;
                        a = c;
                        c = t;
                    }
                    const bool got = in_list(near, nn, a, c);
                    const int v = near_verdict(got, dist, d, step, i, j);
                    within += v == 0;
                    beyond += v == 1;
                    skipped += v == 2;
                }
            /* the events: this list against the last */
            for (size_t k = 0; k < nn; ++k)
                ck_assert(in_list(b, nb, near[k].a, near[k].b) ==
                          !in_list(prev, nprev, near[k].a, near[k].b));
            for (size_t k = 0; k < nprev; ++k)
                ck_assert(in_list(e, ne, prev[k].a, prev[k].b) ==
                          !in_list(near, nn, prev[k].a, prev[k].b));
            ck_assert_uint_le(nb, nn);
            ck_assert_uint_le(ne, nprev);
            if (gone.index != UINT32_MAX)
                for (size_t k = 0; k < nprev; ++k)
                    if (prev[k].a.index == gone.index || prev[k].b.index == gone.index) {
                        ck_assert(in_list(e, ne, prev[k].a, prev[k].b));
                        ++removed_ended;
                    }
            events += (int)(nb + ne);
            if (nn > 0)
                memcpy(prev, near, nn * sizeof *near);
            nprev = nn;
        }
        free_scene(&s);
    }
    ck_assert_int_gt(within, _i ? 150 : 10);
    ck_assert_int_gt(beyond, _i ? 1500 : 100);
    ck_assert_int_lt(skipped, (within + beyond) / 100 + 5);
    ck_assert_int_gt(events, _i ? 100 : 5);
    ck_assert_int_ge(removed_ended, _i ? 1 : 0);
}
END_TEST

/* At the box level, the boxes decide. */
/*
 * The world's near pairs against noctWorldQueryNear() with each object's
 * own shape, pose, filter and the world's margin: the query takes every
 * candidate to the separating-axis test and the triangles' distances,
 * never to the world's shortcut of two points of the box forms proved
 * within the margin (world_near.c), so both must give the same pairs, on
 * random worlds of boxes (whose pairs the shortcut decides) and L meshes,
 * at random margins, over steps of random teleports. Pairs that are near
 * but not colliding between boxes are counted: the shortcut's ground.
 */
START_TEST(near_pairs_against_the_query)
{
    int pairs = 0, near_boxes = 0;
    const int rounds = _i ? 16 : 4;
    for (int round = 0; round < rounds; ++round) {
        world_margin = 0.05 + 0.6 * uniform();
        const double d = world_margin;
        scene s;
        random_scene(&s, 15 + (int)(20 * uniform()), 1 + round % 4, NOCT_ACCURACY_EXACT, ell);
        world_margin = 0;
        for (int step = 0; step < 6; ++step) {
            for (int i = 0; i < s.n; ++i)
                if (uniform() < 0.4)
                    teleport(&s, i);
            ck_assert_int_eq(noctWorldStep(s.w, NULL), NOCT_OK);
            const noctPair *near, *col;
            const size_t nn = noctWorldNear(s.w, &near);
            const size_t nc = noctWorldColliding(s.w, &col);
            size_t seen = 0;
            for (int i = 0; i < s.n; ++i) {
                if (s.sensor[i])
                    continue;
                double h[3];
                for (int k = 0; k < 3; ++k)
                    h[k] = (double)s.g[i].pc[0].h[k];
                found got = {0};
                ck_assert_int_eq(noctWorldQueryNear(s.w, s.kind[i] == 0 ? NULL : s.kind[i] == 1 ? s.mesh[i] : ell,
                                                    h, &s.x[i], d,
                                                    (noctQueryFilter){s.cat[i], s.mask[i]},
                                                    collect, &got, NULL),
                                 NOCT_OK);
                for (int j = 0; j < s.n; ++j) {
                    if (j == i || s.sensor[j])
                        continue;
                    bool in = false;
                    for (int k = 0; k < got.n; ++k)
                        in = in || got.id[k].index == s.id[j].index;
                    noctObjectId a = s.id[i], c = s.id[j];
                    if (a.index > c.index) {
                        const noctObjectId t = a;
                        a = c;
                        c = t;
                    }
                    const bool listed = in_list(near, nn, a, c);
                    ck_assert_msg(listed == in, "objects %d and %d: near %d, query %d (margin %g)",
                                  i, j, listed, in, d);
                    if (i < j && listed) {
                        ++seen;
                        if (s.kind[i] < 2 && s.kind[j] < 2 && !in_list(col, nc, a, c))
                            ++near_boxes;
                    }
                    pairs += i < j;
                }
            }
            ck_assert_uint_eq(seen, nn); /* and no pair beyond them */
        }
        free_scene(&s);
    }
    ck_assert_int_gt(pairs, _i ? 12000 : 3000);
    ck_assert_int_gt(near_boxes, _i ? 120 : 25);
}
END_TEST

START_TEST(box_level_uses_the_boxes)
{
    int checked = 0, nears = 0;
    for (int round = 0; round < (_i ? 4 : 1); ++round) {
        world_margin = 0.1 + 0.5 * uniform();
        const double d = world_margin;
        scene s;
        random_scene(&s, 30, 3, NOCT_ACCURACY_BOX, ell);
        world_margin = 0;
        ck_assert_int_eq(noctWorldStep(s.w, NULL), NOCT_OK);
        const noctPair *near;
        const size_t nn = noctWorldNear(s.w, &near);
        for (int i = 0; i < s.n; ++i)
            for (int j = i + 1; j < s.n; ++j) {
                if (!may_pair(&s, i, j))
                    continue;
                double alo[3], ahi[3], blo[3], bhi[3];
                ck_assert_int_eq(noctWorldObjectBox(s.w, s.id[i], alo, ahi), NOCT_OK);
                ck_assert_int_eq(noctWorldObjectBox(s.w, s.id[j], blo, bhi), NOCT_OK);
                long double g2 = 0;
                for (int k = 0; k < 3; ++k) {
                    const long double g = fmaxl(fmaxl((long double)blo[k] - ahi[k],
                                                      (long double)alo[k] - bhi[k]),
                                                0);
                    g2 += g * g;
                }
                const long double dist = sqrtl(g2);
                const bool got = in_list(near, nn, s.id[i], s.id[j]);
                if (fabsl(dist - d) > BEYOND) {
                    ck_assert(got == (dist < d));
                    ++checked;
                    nears += got;
                }
            }
        free_scene(&s);
    }
    ck_assert_int_gt(checked, _i ? 1000 : 200);
    ck_assert_int_gt(nears, _i ? 50 : 5);
}
END_TEST

START_TEST(query_near_against_geometry)
{
    int within = 0, beyond = 0;
    for (int round = 0; round < (_i ? 3 : 1); ++round) {
        scene s;
        random_scene(&s, 30, 2, NOCT_ACCURACY_EXACT, ell);
        for (int q = 0; q < (_i ? 40 : 10); ++q) {
            const double d = q % 5 == 0 ? 0 : 0.8 * uniform();
            noctTransform x;
            for (int k = 0; k < 3; ++k)
                x.p[k] = 6 * uniform();
            random_quat(&x.q);
            const bool is_ell = uniform() < 0.4;
            double h[3];
            for (int k = 0; k < 3; ++k)
                h[k] = 0.1 + 0.6 * uniform();
            const ideal sh = ideal_shape(&x, is_ell, h);
            const noctQueryFilter f = random_filter();
            found got = {0};
            ck_assert_int_eq(noctWorldQueryNear(s.w, is_ell ? ell : NULL, h, &x, d, f, collect,
                                                &got, NULL),
                             NOCT_OK);
            for (int i = 0; i < s.n; ++i) {
                bool in = false;
                for (int k = 0; k < got.n; ++k)
                    in = in || got.id[k].index == s.id[i].index;
                if (!passes(&s, i, f)) {
                    ck_assert(!in);
                    continue;
                }
                const long double dist = distance_for(&sh, &s.g[i], d);
                if (dist <= d - BEYOND) {
                    ck_assert_msg(in, "query: object %d %.12Lg away, not within %g", i, dist, d);
                    ++within;
                } else if (dist > d + BEYOND) {
                    ck_assert_msg(!in, "query: object %d %.12Lg away, within %g", i, dist, d);
                    ++beyond;
                }
            }
        }
        free_scene(&s);
    }
    ck_assert_int_gt(within, _i ? 150 : 10);
    ck_assert_int_gt(beyond, _i ? 1500 : 100);
}
END_TEST

START_TEST(no_margin_no_near_and_bad_margins)
{
    scene s;
    random_scene(&s, 20, 2, NOCT_ACCURACY_EXACT, ell);
    for (int step = 0; step < 3; ++step) {
        ck_assert_int_eq(noctWorldStep(s.w, NULL), NOCT_OK);
        const noctPair *p;
        ck_assert_uint_eq(noctWorldNear(s.w, &p), 0);
        ck_assert_uint_eq(noctWorldNearBegan(s.w, &p), 0);
    }
    noctWorldDef wd = noctDefaultWorldDef();
    noctWorld *w;
    noctError err;
    wd.margin = NAN;
    ck_assert_int_eq(noctWorldCreate(&wd, &w, &err), NOCT_ERR_NONFINITE);
    ck_assert_ptr_null(w);
    wd.margin = -1;
    ck_assert_int_eq(noctWorldCreate(&wd, &w, &err), NOCT_ERR_INVALID);
    ck_assert_ptr_nonnull(strstr(err.message, "margin"));
    wd.margin = 2e100;
    ck_assert_int_eq(noctWorldCreate(&wd, &w, &err), NOCT_ERR_INVALID);
    noctTransform x = noctIdentityTransform();
    found got = {0};
    const double h[3] = {1, 1, 1};
    ck_assert_int_eq(noctWorldQueryNear(s.w, NULL, h, &x, NAN, noctDefaultQueryFilter(),
                                        collect, &got, &err),
                     NOCT_ERR_NONFINITE);
    ck_assert_int_eq(noctWorldQueryNear(s.w, NULL, h, &x, -0.5, noctDefaultQueryFilter(),
                                        collect, &got, &err),
                     NOCT_ERR_INVALID);
    ck_assert_int_eq(got.n, 0);
    free_scene(&s);
}
END_TEST

/* A step that fails (an object would leave the coordinate range) keeps the
 * near list and reports no near events. */
START_TEST(a_failed_step_keeps_the_near_pairs)
{
    noctWorldDef wd = noctDefaultWorldDef();
    wd.effects = NOCT_EFFECT_EVENTS | NOCT_EFFECT_MOTION;
    wd.margin = 0.5;
    noctWorld *w;
    ck_assert_int_eq(noctWorldCreate(&wd, &w, NULL), NOCT_OK);
    noctObjectDef od = noctDefaultObjectDef();
    od.half_extents[0] = od.half_extents[1] = od.half_extents[2] = 0.5;
    od.type = NOCT_OBJECT_STATIC;
    noctObjectId a, b, far;
    ck_assert_int_eq(noctWorldCreateObject(w, &od, &a, NULL), NOCT_OK);
    od.transform.p[0] = 1.25; /* 0.25 apart: near, not colliding */
    ck_assert_int_eq(noctWorldCreateObject(w, &od, &b, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    const noctPair *p;
    ck_assert_uint_eq(noctWorldColliding(w, &p), 0);
    ck_assert_uint_eq(noctWorldNear(w, &p), 1);
    ck_assert_uint_eq(noctWorldNearBegan(w, &p), 1);
    od.type = NOCT_OBJECT_MOVING;
    od.transform.p[0] = 9.9e99;
    od.velocity[0] = 1e99;
    ck_assert_int_eq(noctWorldCreateObject(w, &od, &far, NULL), NOCT_OK);
    noctError err;
    ck_assert_int_eq(noctWorldStep(w, &err), NOCT_ERR_TOO_LARGE);
    ck_assert_uint_eq(noctWorldNear(w, &p), 1);
    ck_assert_uint_eq(p[0].a.index, a.index);
    ck_assert_uint_eq(p[0].b.index, b.index);
    ck_assert_uint_eq(noctWorldNearBegan(w, &p), 0);
    ck_assert_uint_eq(noctWorldNearEnded(w, &p), 0);
    /* without it, the next step goes on: the pair stays near, no event */
    ck_assert_int_eq(noctWorldRemove(w, far, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    ck_assert_uint_eq(noctWorldNear(w, &p), 1);
    ck_assert_uint_eq(noctWorldNearBegan(w, &p), 0);
    ck_assert_uint_eq(noctWorldNearEnded(w, &p), 0);
    /* moved 0.75 apart: the pair ends */
    noctTransform x = noctIdentityTransform();
    x.p[0] = 1.75;
    ck_assert_int_eq(noctWorldSetTransform(w, b, &x, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    ck_assert_uint_eq(noctWorldNear(w, &p), 0);
    ck_assert_uint_eq(noctWorldNearEnded(w, &p), 1);
    noctWorldDestroy(w);
}
END_TEST

/*
 * Objects' own margins (noctObjectDef::margin, noctWorldSetMargin()): on
 * random scenes, some objects with a margin (set at creation or later,
 * changed and taken away between steps), with and without a world margin,
 * every pair that may pair against the library's proved distance
 * (noctDistance(), an independent search over the triangles): a pair
 * whose distance's upper bound is within its margin, W + (m_a + m_b),
 * must be near; one whose lower bound is beyond it by more than the
 * slack must not. The world validates after every step, and the near
 * events are the lists' differences.
 */
START_TEST(object_margins_against_distance)
{
    int within = 0, beyond = 0, events = 0, own = 0;
    const int rounds = _i ? 6 : 2;
    for (int round = 0; round < rounds; ++round) {
        world_margin = round % 2 == 0 ? 0 : 0.3 * uniform();
        const double W = world_margin;
        scene s;
        random_scene(&s, 10 + (int)(20 * uniform()), 1 + round % 4, NOCT_ACCURACY_EXACT, ell);
        world_margin = 0;
        double m[MAXO];
        for (int i = 0; i < s.n; ++i) {
            m[i] = uniform() < 0.5 ? 0 : 0.4 * uniform();
            ck_assert_int_eq(noctWorldSetMargin(s.w, s.id[i], m[i], NULL), NOCT_OK);
        }
        noctPair prev[MAXO * MAXO / 2];
        size_t nprev = 0;
        for (int step = 0; step < 8; ++step) {
            for (int i = 0; i < s.n; ++i) {
                if (uniform() < 0.3)
                    teleport(&s, i);
                if (uniform() < 0.2) { /* a new margin, none, or a large one */
                    const double u = uniform();
                    m[i] = u < 0.3 ? 0 : u < 0.9 ? 0.4 * uniform() : 1 + uniform();
                    ck_assert_int_eq(noctWorldSetMargin(s.w, s.id[i], m[i], NULL), NOCT_OK);
                }
                double got;
                ck_assert_int_eq(noctWorldGetMargin(s.w, s.id[i], &got), NOCT_OK);
                ck_assert(got == m[i]);
            }
            ck_assert_int_eq(noctWorldStep(s.w, NULL), NOCT_OK);
            ck_assert_int_eq(noctWorldValidate(s.w, NULL), NOCT_OK);
            const noctPair *near, *b, *e;
            const size_t nn = noctWorldNear(s.w, &near);
            const size_t nb = noctWorldNearBegan(s.w, &b), ne = noctWorldNearEnded(s.w, &e);
            for (int i = 0; i < s.n; ++i)
                for (int j = i + 1; j < s.n; ++j) {
                    noctObjectId a = s.id[i], c = s.id[j];
                    if (a.index > c.index) {
                        const noctObjectId t = a;
                        a = c;
                        c = t;
                    }
                    const bool got = in_list(near, nn, a, c);
                    if (!may_pair(&s, i, j)) {
                        ck_assert(!got);
                        continue;
                    }
                    const double d = W + (m[i] + m[j]);
                    noctDistanceResult r;
                    ck_assert_int_eq(noctDistance(mesh_of(&s, i, ell), &s.x[i],
                                                  mesh_of(&s, j, ell), &s.x[j], INFINITY, &r,
                                                  NULL, NULL),
                                     NOCT_OK);
                    ck_assert(r.lower <= r.upper);
                    if (r.upper <= d) {
                        ck_assert_msg(got, "objects %d and %d, [%.17g, %.17g] apart, not near "
                                      "(pair margin %.17g)", i, j, r.lower, r.upper, d);
                        ++within;
                        own += W < r.lower; /* near by the objects' own margins */
                    } else if (r.lower > d + 2 * (double)BEYOND) {
                        ck_assert_msg(!got, "objects %d and %d, [%.17g, %.17g] apart, near "
                                      "(pair margin %.17g)", i, j, r.lower, r.upper, d);
                        ++beyond;
                    }
                }
            for (size_t k = 0; k < nn; ++k)
                ck_assert(in_list(b, nb, near[k].a, near[k].b) ==
                          !in_list(prev, nprev, near[k].a, near[k].b));
            for (size_t k = 0; k < nprev; ++k)
                ck_assert(in_list(e, ne, prev[k].a, prev[k].b) ==
                          !in_list(near, nn, prev[k].a, prev[k].b));
            events += (int)(nb + ne);
            if (nn > 0)
                memcpy(prev, near, nn * sizeof *near);
            nprev = nn;
        }
        /* every margin taken away: in a world without one, the near pairs
         * end at the next step, and none come after */
        for (int i = 0; i < s.n; ++i)
            ck_assert_int_eq(noctWorldSetMargin(s.w, s.id[i], 0, NULL), NOCT_OK);
        ck_assert_int_eq(noctWorldStep(s.w, NULL), NOCT_OK);
        ck_assert_int_eq(noctWorldValidate(s.w, NULL), NOCT_OK);
        const noctPair *p;
        if (W == 0) {
            ck_assert_uint_eq(noctWorldNear(s.w, &p), 0);
            ck_assert_uint_eq(noctWorldNearEnded(s.w, &p), nprev);
            ck_assert_int_eq(noctWorldStep(s.w, NULL), NOCT_OK);
            ck_assert_uint_eq(noctWorldNearEnded(s.w, &p), 0);
        }
        free_scene(&s);
    }
    ck_assert_int_gt(within, _i ? 150 : 40);
    ck_assert_int_gt(own, _i ? 60 : 15);
    ck_assert_int_gt(beyond, _i ? 1000 : 300);
    ck_assert_int_gt(events, _i ? 60 : 15);
}
END_TEST

/* noctWorldQueryNear() counts each object's own margin: an object is
 * reported within the query's margin plus its own, against noctDistance(). */
START_TEST(query_near_with_object_margins)
{
    int within = 0, beyond = 0, own = 0;
    for (int round = 0; round < (_i ? 3 : 1); ++round) {
        scene s;
        random_scene(&s, 30, 2, NOCT_ACCURACY_EXACT, ell);
        double m[MAXO];
        for (int i = 0; i < s.n; ++i) {
            m[i] = uniform() < 0.5 ? 0 : 0.5 * uniform();
            ck_assert_int_eq(noctWorldSetMargin(s.w, s.id[i], m[i], NULL), NOCT_OK);
        }
        for (int q = 0; q < (_i ? 40 : 12); ++q) {
            const double d = q % 4 == 0 ? 0 : 0.5 * uniform();
            noctTransform x;
            for (int k = 0; k < 3; ++k)
                x.p[k] = 6 * uniform();
            random_quat(&x.q);
            found got = {0};
            ck_assert_int_eq(noctWorldQueryNear(s.w, ell, NULL, &x, d, noctDefaultQueryFilter(),
                                                collect, &got, NULL),
                             NOCT_OK);
            for (int i = 0; i < s.n; ++i) {
                bool in = false;
                for (int k = 0; k < got.n; ++k)
                    in = in || got.id[k].index == s.id[i].index;
                noctDistanceResult r;
                ck_assert_int_eq(noctDistance(ell, &x, mesh_of(&s, i, ell), &s.x[i], INFINITY,
                                              &r, NULL, NULL),
                                 NOCT_OK);
                const double reach = d + m[i];
                if (r.upper <= reach) {
                    ck_assert_msg(in, "query: object %d [%.17g, %.17g] away, not within %g",
                                  i, r.lower, r.upper, reach);
                    ++within;
                    own += d < r.lower;
                } else if (r.lower > reach + 2 * (double)BEYOND) {
                    ck_assert_msg(!in, "query: object %d [%.17g, %.17g] away, within %g", i,
                                  r.lower, r.upper, reach);
                    ++beyond;
                }
            }
            /* the shape query ignores the margins: only what collides */
            found hit = {0};
            ck_assert_int_eq(noctWorldQueryShape(s.w, ell, NULL, &x, noctDefaultQueryFilter(),
                                                 collect, &hit, NULL),
                             NOCT_OK);
            for (int k = 0; k < hit.n; ++k) {
                const int i = index_of(&s, hit.id[k].index);
                noctDistanceResult r;
                ck_assert_int_eq(noctDistance(ell, &x, mesh_of(&s, i, ell), &s.x[i], INFINITY,
                                              &r, NULL, NULL),
                                 NOCT_OK);
                ck_assert(r.colliding);
            }
        }
        free_scene(&s);
    }
    ck_assert_int_gt(within, _i ? 100 : 20);
    ck_assert_int_gt(own, _i ? 20 : 4);
    ck_assert_int_gt(beyond, _i ? 600 : 150);
}
END_TEST

/* Two boxes 0.25 apart in a world without a margin: near only when their
 * skins meet; the setters' and the definition's bad margins. */
START_TEST(object_margin_setters_and_errors)
{
    noctWorldDef wd = noctDefaultWorldDef();
    wd.effects = NOCT_EFFECT_EVENTS;
    noctWorld *w;
    ck_assert_int_eq(noctWorldCreate(&wd, &w, NULL), NOCT_OK);
    noctObjectDef od = noctDefaultObjectDef();
    ck_assert(od.margin == 0);
    od.half_extents[0] = od.half_extents[1] = od.half_extents[2] = 0.5;
    od.type = NOCT_OBJECT_STATIC;
    noctObjectId a, b, c, bad;
    ck_assert_int_eq(noctWorldCreateObject(w, &od, &a, NULL), NOCT_OK);
    od.transform.p[0] = 1.25;
    od.margin = 0.125;
    ck_assert_int_eq(noctWorldCreateObject(w, &od, &b, NULL), NOCT_OK);
    od.transform.p[0] = 40;
    od.margin = 0;
    ck_assert_int_eq(noctWorldCreateObject(w, &od, &c, NULL), NOCT_OK);
    double m = -1;
    ck_assert_int_eq(noctWorldGetMargin(w, a, &m), NOCT_OK);
    ck_assert(m == 0);
    ck_assert_int_eq(noctWorldGetMargin(w, b, &m), NOCT_OK);
    ck_assert(m == 0.125);
    const noctPair *p;
    ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    ck_assert_uint_eq(noctWorldNear(w, &p), 0); /* 0.125 < 0.25 */
    /* a skin of 0.125 on each: they meet */
    ck_assert_int_eq(noctWorldSetMargin(w, a, 0.125, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldValidate(w, NULL), NOCT_OK);
    ck_assert_uint_eq(noctWorldNear(w, &p), 1);
    ck_assert_uint_eq(p[0].a.index, a.index);
    ck_assert_uint_eq(p[0].b.index, b.index);
    ck_assert_uint_eq(noctWorldNearBegan(w, &p), 1);
    /* a far object's large margin reaches them both; then goes down (the
     * largest goes stale) and the pairs it made end */
    ck_assert_int_eq(noctWorldSetMargin(w, c, 39, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldValidate(w, NULL), NOCT_OK);
    ck_assert_uint_eq(noctWorldNear(w, &p), 3);
    ck_assert_int_eq(noctWorldSetMargin(w, c, 1, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldValidate(w, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldValidate(w, NULL), NOCT_OK);
    ck_assert_uint_eq(noctWorldNear(w, &p), 1);
    ck_assert_uint_eq(noctWorldNearEnded(w, &p), 2);
    /* bad margins change nothing */
    noctError err;
    const double bads[] = {NAN, INFINITY, -INFINITY, -0.5, 2e100};
    const noctStatus want[] = {NOCT_ERR_NONFINITE, NOCT_ERR_NONFINITE, NOCT_ERR_NONFINITE,
                               NOCT_ERR_INVALID, NOCT_ERR_INVALID};
    for (int k = 0; k < 5; ++k) {
        ck_assert_int_eq(noctWorldSetMargin(w, a, bads[k], &err), want[k]);
        ck_assert_ptr_nonnull(strstr(err.message, "margin"));
        ck_assert_int_eq(noctWorldGetMargin(w, a, &m), NOCT_OK);
        ck_assert(m == 0.125);
        od.margin = bads[k];
        ck_assert_int_eq(noctWorldCreateObject(w, &od, &bad, &err), want[k]);
        ck_assert_uint_eq(bad.index, 0);
        ck_assert_uint_eq(bad.generation, 0);
    }
    ck_assert_uint_eq(noctWorldObjectCount(w), 3);
    od.margin = NOCT_MAX_COORDINATE; /* the largest allowed */
    ck_assert_int_eq(noctWorldCreateObject(w, &od, &bad, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldRemove(w, bad, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldValidate(w, NULL), NOCT_OK);
    /* stale handles */
    ck_assert_int_eq(noctWorldSetMargin(w, bad, 1, &err), NOCT_ERR_INVALID);
    ck_assert_int_eq(noctWorldGetMargin(w, bad, &m), NOCT_ERR_INVALID);
    /* the skins taken away: without a world margin, the pair ends and the
     * world keeps no near pairs */
    ck_assert_int_eq(noctWorldSetMargin(w, a, 0, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldSetMargin(w, b, 0, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldSetMargin(w, c, 0, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    ck_assert_uint_eq(noctWorldNear(w, &p), 0);
    ck_assert_uint_eq(noctWorldNearEnded(w, &p), 1);
    ck_assert_int_eq(noctWorldValidate(w, NULL), NOCT_OK);
    noctWorldDestroy(w);
}
END_TEST

/*
 * The world's near pairs come from its leaves (each leaf sweeps the boxes
 * that may have a near pair whose lower corner it owns): on worlds of
 * small leaves (N = 1 to 3), whose objects drift a little every step
 * across the leaves' faces (leaves split and merge), with objects' own
 * margins set and changed as they go and objects removed and made again,
 * the near pairs and their events are those of a twin world of a single
 * leaf (N big), where every pair meets in the one sweep, step by step.
 */
START_TEST(near_pairs_across_leaves)
{
    int near_seen = 0, margins_set = 0;
    const int rounds = _i ? 12 : 3;
    for (int round = 0; round < rounds; ++round) {
        world_margin = round % 3 == 2 ? 0 : 0.02 + 0.4 * uniform();
        scene s;
        random_scene(&s, 20 + (int)(20 * uniform()), 1 + round % 3, NOCT_ACCURACY_EXACT, ell);
        noctWorld *twin = new_world(NOCT_N_EXHAUSTIVE, NOCT_ACCURACY_EXACT);
        world_margin = 0;
        noctObjectDef defs[MAXO];
        for (int i = 0; i < s.n; ++i) {
            const noctObjectDef d = scene_object_def(&s, i, ell);
            defs[i] = d;
            noctObjectId id;
            ck_assert_int_eq(noctWorldCreateObject(twin, &d, &id, NULL), NOCT_OK);
            ck_assert_uint_eq(id.index, s.id[i].index);
        }
        noctObjectId tid[MAXO];
        for (int i = 0; i < s.n; ++i)
            tid[i] = (noctObjectId){s.id[i].index, s.id[i].generation};
        for (int step = 0; step < 16; ++step) {
            for (int i = 0; i < s.n; ++i) {
                for (int k = 0; k < 3; ++k)
                    s.x[i].p[k] = fmin(6, fmax(0, s.x[i].p[k] + 0.3 * (uniform() - 0.5)));
                ck_assert_int_eq(noctWorldSetTransform(s.w, s.id[i], &s.x[i], NULL), NOCT_OK);
                ck_assert_int_eq(noctWorldSetTransform(twin, tid[i], &s.x[i], NULL), NOCT_OK);
                if (uniform() < 0.08) { /* a margin of its own, or none again */
                    const double m = uniform() < 0.3 ? 0 : 0.3 * uniform();
                    ck_assert_int_eq(noctWorldSetMargin(s.w, s.id[i], m, NULL), NOCT_OK);
                    ck_assert_int_eq(noctWorldSetMargin(twin, tid[i], m, NULL), NOCT_OK);
                    ++margins_set;
                }
            }
            if (step % 5 == 4) { /* one object goes and comes back */
                const int i = (int)(s.n * uniform());
                ck_assert_int_eq(noctWorldRemove(s.w, s.id[i], NULL), NOCT_OK);
                ck_assert_int_eq(noctWorldRemove(twin, tid[i], NULL), NOCT_OK);
                defs[i].transform = s.x[i];
                defs[i].user_data = &s.id[i];
                ck_assert_int_eq(noctWorldCreateObject(s.w, &defs[i], &s.id[i], NULL), NOCT_OK);
                defs[i].user_data = NULL;
                ck_assert_int_eq(noctWorldCreateObject(twin, &defs[i], &tid[i], NULL), NOCT_OK);
                ck_assert_uint_eq(tid[i].index, s.id[i].index);
            }
            ck_assert_int_eq(noctWorldStep(s.w, NULL), NOCT_OK);
            ck_assert_int_eq(noctWorldStep(twin, NULL), NOCT_OK);
            const noctPair *p, *q;
            const size_t np = noctWorldNear(s.w, &p), nq = noctWorldNear(twin, &q);
            ck_assert_uint_eq(np, nq);
            for (size_t k = 0; k < np; ++k)
                ck_assert_msg(p[k].a.index == q[k].a.index && p[k].b.index == q[k].b.index,
                              "step %d: near pair %zu is (%u, %u), in the twin (%u, %u)", step,
                              k, p[k].a.index, p[k].b.index, q[k].a.index, q[k].b.index);
            near_seen += (int)np;
            ck_assert_uint_eq(noctWorldNearBegan(s.w, &p), noctWorldNearBegan(twin, &q));
            ck_assert_uint_eq(noctWorldNearEnded(s.w, &p), noctWorldNearEnded(twin, &q));
        }
        noctWorldDestroy(twin);
        free_scene(&s);
    }
    ck_assert_int_gt(near_seen, _i ? 2000 : 400);
    ck_assert_int_gt(margins_set, _i ? 200 : 40);
}
END_TEST

/* Is the pair of objects a and b (either order) in the near list? */
static bool near_now(noctWorld *w, noctObjectId a, noctObjectId b)
{
    const noctPair *p;
    const size_t n = noctWorldNear(w, &p);
    if (a.index > b.index) {
        const noctObjectId t = a;
        a = b;
        b = t;
    }
    return in_list(p, n, a, b);
}

/* Object b (a box mesh of half-extents h, or the L when h is NULL) of a
 * two-object world placed at x, in the world and in the test's ideal g. */
static void place(noctWorld *w, noctObjectId id, ideal *g, const noctTransform *x,
                  const double *h)
{
    ck_assert_int_eq(noctWorldSetTransform(w, id, x, NULL), NOCT_OK);
    *g = ideal_shape(x, h == NULL, h);
}

/* The rotation by angle a about z. */
static noctQuat about_z(double a)
{
    return (noctQuat){0, 0, sin(a / 2), cos(a / 2)};
}

/*
 * The proofs the near stage keeps from one step to the next (hints,
 * world_near.c) must never decide a pair by themselves: two unit boxes
 * (box meshes, with duals, so that the witness and the separating axes
 * decide them) at margin 0.3, one of them moved in steps of 0.0123, far
 * less than what a near proof has to spare, towards the other, through
 * the margin, into contact and back out; then turned about its centre
 * after a near proof (so that the gap grows beyond the margin) and after
 * an apart proof along x (so that it shrinks within it); then jumps by
 * set-transform; then removed and its slot given to objects of other
 * shapes (a smaller box, the L, which has no dual) placed near where the
 * old one was apart and apart where it was near. Every step's near pair
 * against the test's own distance of the ideal solids (testgeom.c).
 */
START_TEST(kept_proofs_cross_the_margin)
{
    const double d = 0.3, unit[3] = {0.5, 0.5, 0.5}, small[3] = {0.2, 0.3, 0.25};
    world_margin = d;
    noctWorld *w = new_world(2 + _i, NOCT_ACCURACY_EXACT);
    world_margin = 0;
    noctMesh *box, *other;
    ck_assert_int_eq(noctMeshCreateBox(0.5, 0.5, 0.5, &box, NULL), NOCT_OK);
    ck_assert_int_eq(noctMeshCreateBox(small[0], small[1], small[2], &other, NULL), NOCT_OK);
    noctObjectDef def = noctDefaultObjectDef();
    def.mesh = box;
    noctObjectId a, b;
    ck_assert_int_eq(noctWorldCreateObject(w, &def, &a, NULL), NOCT_OK);
    def.transform.p[0] = 3;
    ck_assert_int_eq(noctWorldCreateObject(w, &def, &b, NULL), NOCT_OK);
    int near_seen = 0, apart_seen = 0, changes = 0;
    bool was = false;
    const ideal ga = ideal_shape(&(noctTransform){{0, 0, 0}, {0, 0, 0, 1}}, false, unit);
    ideal gb;
    /* the step's answer against the ideal distance */
#define EXPECT_STEP()                                                                     \
    do {                                                                                  \
        ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);                                \
        const long double dist = ideal_distance(&ga, &gb);                                \
        const bool got = near_now(w, a, b);                                               \
        if (dist <= d - BEYOND)                                                           \
            ck_assert_msg(got, "%.12Lg apart, not near (line %d)", dist, __LINE__);       \
        else if (dist > d + BEYOND)                                                       \
            ck_assert_msg(!got, "%.12Lg apart, near (line %d)", dist, __LINE__);          \
        near_seen += got;                                                                 \
        apart_seen += !got;                                                               \
        changes += got != was;                                                            \
        was = got;                                                                        \
    } while (0)
    /* Turned by 45 degrees about z and raised by 0.7 on y, the box's
     * bounding box reaches nearer than the box: where the bounding boxes
     * are 0.22-0.3 apart along x the boxes are apart (beyond the margin)
     * and pass the bounding boxes' test, so that apart proofs are made and
     * kept, and a kept apart proof decides the pair wrongly as soon as
     * the box comes within the margin. In small steps from a gap of the
     * bounding boxes of 0.6 to an overlap of 0.1 and back (near proofs
     * kept, wrong as soon as the box leaves the margin), drifting a
     * little along y as well. */
    const double corner = 0.5 * sqrt(2);
    noctTransform x = {{0, 0, 0}, about_z(0.7853981633974483)};
    for (int k = 0; k <= 2 * 57; ++k) {
        const int t = k <= 57 ? k : 2 * 57 - k;
        x.p[0] = 0.5 + corner + 0.6 - 0.0123 * t;
        x.p[1] = 0.7 + 0.002 * (k % 7);
        place(w, b, &gb, &x, unit);
        EXPECT_STEP();
    }
    x = (noctTransform){{0, 0, 0}, {0, 0, 0, 1}};
    /* near at a gap of 0.25, then turned by 45 degrees about z: nearer
     * (0.043); and near at 0.25 turned, then turned back: 0.457, apart */
    x = (noctTransform){{1.25, 0, 0}, {0, 0, 0, 1}};
    place(w, b, &gb, &x, unit);
    EXPECT_STEP();
    x.q = about_z(0.7853981633974483);
    place(w, b, &gb, &x, unit);
    EXPECT_STEP();
    x.p[0] = 1.25 + 0.5 * (sqrt(2) - 1);
    place(w, b, &gb, &x, unit);
    EXPECT_STEP(); /* turned, gap 0.25 */
    x.q = (noctQuat){0, 0, 0, 1};
    place(w, b, &gb, &x, unit);
    EXPECT_STEP(); /* 0.457: apart */
    ck_assert(!was);
    /* apart along x at 0.45, then turned: 0.243, near */
    x.p[0] = 1.45;
    place(w, b, &gb, &x, unit);
    EXPECT_STEP();
    x.q = about_z(0.7853981633974483);
    place(w, b, &gb, &x, unit);
    EXPECT_STEP();
    ck_assert(was);
    /* turned a little each step, the gap shrinking from 0.45 */
    for (int k = 0; k < 40; ++k) {
        x.q = about_z(0.02 * k);
        x.p[0] = 1.45 - 0.002 * k;
        place(w, b, &gb, &x, unit);
        EXPECT_STEP();
    }
    /* jumps: near, far, near at 0.29, apart at 0.31, touching */
    const double jumps[] = {1.1, 7, 1.29, 1.31, 1.0, 1.299, 1.301, 5, 1.2};
    x.q = (noctQuat){0, 0, 0, 1};
    for (size_t k = 0; k < sizeof jumps / sizeof *jumps; ++k) {
        x.p[0] = jumps[k];
        x.p[2] = 0.01 * (double)k;
        place(w, b, &gb, &x, unit);
        EXPECT_STEP();
    }
    /* the slot given to other objects: near where the last was apart
     * (the smaller box at x 0.9, a gap of 0.2 where a unit box at 1.9
     * had 0.9), apart where it was near (the L, at a gap of 0.5 beyond
     * its extents, where the unit box at 1.2 was near) */
    const struct {
        double last, next;
        const double *h;
    } swaps[] = {{1.9, 0.5 + 0.2 + small[0], small}, {1.2, 2.5, NULL},
                 {1.25, 0.5 + 0.35 + small[0], small}, {2.5, 1.55, NULL},
                 {1.1, 1.62, unit}};
    const double *cur = unit; /* the shape in the slot: NULL, the L */
    for (size_t r = 0; r < 2 * sizeof swaps / sizeof *swaps; ++r) {
        const size_t k = r % (sizeof swaps / sizeof *swaps);
        const bool turned = r >= sizeof swaps / sizeof *swaps; /* (see above) */
        x = (noctTransform){{swaps[k].last, turned ? 0.7 : 0, 0}, {0, 0, 0, 1}};
        if (turned)
            x.q = about_z(0.7853981633974483);
        place(w, b, &gb, &x, cur);
        EXPECT_STEP();
        const uint32_t slot = b.index;
        ck_assert_int_eq(noctWorldRemove(w, b, NULL), NOCT_OK);
        def = noctDefaultObjectDef();
        cur = swaps[k].h;
        def.mesh = cur == NULL ? ell : cur == small ? other : box;
        def.transform = x;
        def.transform.p[0] = swaps[k].next;
        ck_assert_int_eq(noctWorldCreateObject(w, &def, &b, NULL), NOCT_OK);
        ck_assert_uint_eq(b.index, slot);
        gb = ideal_shape(&def.transform, cur == NULL, cur);
        EXPECT_STEP();
    }
#undef EXPECT_STEP
    ck_assert_int_gt(near_seen, 60);
    ck_assert_int_gt(apart_seen, 40);
    ck_assert_int_gt(changes, 12);
    noctWorldDestroy(w);
    noctMeshDestroy(box);
    noctMeshDestroy(other);
}
END_TEST

/*
 * Random scenes of boxes and L meshes drifting in small steps (each
 * object by up to a fifth of the margin a step, so that kept proofs
 * mostly hold), a few turned a little or teleported each step, one
 * removed and made again in its slot every few steps: every pair's near
 * answer against the ideal distance, every step.
 */
START_TEST(kept_proofs_against_geometry)
{
    int within = 0, beyond = 0, skipped = 0;
    const int rounds = _i ? 6 : 2;
    /* fewer steps under valgrind; twelve keep three of the removals */
    const int steps = test_rounds(30, 12);
    for (int round = 0; round < rounds; ++round) {
        world_margin = 0.05 + 0.5 * uniform();
        const double d = world_margin;
        scene s;
        random_scene(&s, 12 + (int)(20 * uniform()), 1 + round % 4, NOCT_ACCURACY_EXACT, ell);
        world_margin = 0;
        for (int step = 0; step < steps; ++step) {
            for (int i = 0; i < s.n; ++i) {
                const double r = uniform();
                if (r < 0.03) {
                    teleport(&s, i);
                    continue;
                }
                for (int k = 0; k < 3; ++k)
                    s.x[i].p[k] = fmin(6, fmax(0, s.x[i].p[k] + 0.4 * d * (uniform() - 0.5)));
                if (r < 0.1) { /* a small turn */
                    noctQuat q = s.x[i].q, t;
                    random_quat(&t);
                    const double f = 0.05;
                    q = (noctQuat){q.x + f * t.x, q.y + f * t.y, q.z + f * t.z, q.w + f * t.w};
                    const double n = sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
                    s.x[i].q = (noctQuat){q.x / n, q.y / n, q.z / n, q.w / n};
                }
                ck_assert_int_eq(noctWorldSetTransform(s.w, s.id[i], &s.x[i], NULL), NOCT_OK);
                quat_matrix(&s.x[i].q, s.g[i].R);
                for (int k = 0; k < 3; ++k)
                    s.g[i].t[k] = s.x[i].p[k];
            }
            if (step % 4 == 3) { /* one goes and comes back elsewhere */
                const int i = (int)(s.n * uniform());
                const uint32_t slot = s.id[i].index;
                ck_assert_int_eq(noctWorldRemove(s.w, s.id[i], NULL), NOCT_OK);
                noctObjectDef def = scene_object_def(&s, i, ell);
                for (int k = 0; k < 3; ++k)
                    def.transform.p[k] = 6 * uniform();
                def.user_data = &s.id[i];
                ck_assert_int_eq(noctWorldCreateObject(s.w, &def, &s.id[i], NULL), NOCT_OK);
                ck_assert_uint_eq(s.id[i].index, slot);
                s.x[i] = def.transform;
                for (int k = 0; k < 3; ++k)
                    s.g[i].t[k] = def.transform.p[k];
            }
            ck_assert_int_eq(noctWorldStep(s.w, NULL), NOCT_OK);
            const noctPair *near;
            const size_t nn = noctWorldNear(s.w, &near);
            for (int i = 0; i < s.n; ++i)
                for (int j = i + 1; j < s.n; ++j) {
                    if (!may_pair(&s, i, j))
                        continue;
                    const long double dist = distance_for(&s.g[i], &s.g[j], d);
                    noctObjectId a = s.id[i], c = s.id[j];
                    if (a.index > c.index) {
                        const noctObjectId t = a;
                        a = c;
                        c = t;
                    }
                    const bool got = in_list(near, nn, a, c);
                    const int v = near_verdict(got, dist, d, step, i, j);
                    within += v == 0;
                    beyond += v == 1;
                    skipped += v == 2;
                }
        }
        free_scene(&s);
    }
    ck_assert_int_gt(within, (_i ? 300 : 100) * steps / 30);
    ck_assert_int_gt(beyond, (_i ? 3000 : 1000) * steps / 30);
    ck_assert_int_lt(skipped, (within + beyond) / 100 + 5);
}
END_TEST

/* Move object i of scene s to x (the test's ideal pose too). */
static void move_to(scene *s, int i, const noctTransform *x)
{
    ck_assert_int_eq(noctWorldSetTransform(s->w, s->id[i], x, NULL), NOCT_OK);
    s->x[i] = *x;
    quat_matrix(&x->q, s->g[i].R);
    for (int k = 0; k < 3; ++k)
        s->g[i].t[k] = x->p[k];
}

/*
 * The near stage keeps its candidate pairs from one step to the next
 * while the boxes move less than the list's skin (world_near.c,
 * near_candidates()): the near pairs of every step must be those of the
 * test's own distances whatever happens between steps. Random scenes
 * of small leaves (N = 1 to 3), every object drifting by a few
 * hundredths a step (so that lists last several steps) with runs of
 * steps where nothing moves, and between steps: an object's jump by
 * about a margin or more (twice), objects' own margins set and cleared, a sensor
 * made and unmade, filters changed, an object removed and made again in
 * its slot. Each step, every pair that may pair against its ideal
 * distance and its margin (the world's and the objects' own); the test
 * fails when a list is used after a box moved beyond its skin or an
 * object changed, which it was checked to do.
 */
START_TEST(kept_candidates_against_geometry)
{
    int within = 0, beyond = 0, skipped = 0, changes = 0;
    const int rounds = _i ? 6 : 2;
    for (int round = 0; round < rounds; ++round) {
        world_margin = 0.05 + 0.4 * uniform();
        const double W = world_margin;
        scene s;
        random_scene(&s, 15 + (int)(20 * uniform()), 1 + round % 3, NOCT_ACCURACY_EXACT, ell);
        world_margin = 0;
        double own[MAXO] = {0}, v[MAXO][3];
        for (int i = 0; i < s.n; ++i)
            for (int k = 0; k < 3; ++k)
                v[i][k] = 0.04 * (uniform() - 0.5);
        for (int step = 0; step < 40; ++step) {
            const bool still = step >= 20 && step < 26;
            for (int i = 0; i < s.n && !still; ++i) {
                noctTransform x = s.x[i];
                for (int k = 0; k < 3; ++k) {
                    x.p[k] += v[i][k];
                    if (x.p[k] < 0 || x.p[k] > 6)
                        v[i][k] = -v[i][k];
                }
                move_to(&s, i, &x);
            }
            const int i = (int)(s.n * uniform());
            switch (step % 6) {
            case 1: { /* a jump of about a margin, or farther (seldom: the
                       * world then keeps no list for a few steps) */
                if (step != 13 && step != 31)
                    break;
                noctTransform x = s.x[i];
                const double far = (0.5 + 2 * uniform()) * (W + 0.3);
                const int k = (int)(3 * uniform());
                x.p[k] += x.p[k] < 3 ? far : -far;
                move_to(&s, i, &x);
                break;
            }
            case 2: /* an own margin, or none again */
                own[i] = uniform() < 0.4 ? 0 : 0.3 * uniform();
                ck_assert_int_eq(noctWorldSetMargin(s.w, s.id[i], own[i], NULL), NOCT_OK);
                break;
            case 3: /* a sensor made or unmade */
                s.sensor[i] = !s.sensor[i];
                ck_assert_int_eq(noctWorldSetSensor(s.w, s.id[i], s.sensor[i], NULL), NOCT_OK);
                break;
            case 4: /* a filter changed */
                s.cat[i] = uniform() < 0.5 ? NOCT_FILTER_ALL : random_bits();
                s.mask[i] = uniform() < 0.5 ? NOCT_FILTER_ALL : random_bits();
                ck_assert_int_eq(noctWorldSetFilter(s.w, s.id[i], s.cat[i], s.mask[i], NULL),
                                 NOCT_OK);
                break;
            case 5: /* gone, and made again in its slot (no margin of its own) */
                if (step % 12 == 5) {
                    ck_assert_int_eq(noctWorldRemove(s.w, s.id[i], NULL), NOCT_OK);
                    noctObjectDef d = scene_object_def(&s, i, ell);
                    d.user_data = &s.id[i];
                    const uint32_t slot = s.id[i].index;
                    ck_assert_int_eq(noctWorldCreateObject(s.w, &d, &s.id[i], NULL), NOCT_OK);
                    ck_assert_uint_eq(s.id[i].index, slot);
                    own[i] = 0;
                }
                break;
            default:
                break;
            }
            changes += step % 6 > 1;
            ck_assert_int_eq(noctWorldStep(s.w, NULL), NOCT_OK);
            const noctPair *near;
            const size_t nn = noctWorldNear(s.w, &near);
            for (size_t k = 0; k < nn; ++k) {
                const int a = index_of(&s, near[k].a.index), b = index_of(&s, near[k].b.index);
                ck_assert(a >= 0 && b >= 0 && may_pair(&s, a, b));
            }
            for (int a = 0; a < s.n; ++a)
                for (int b = a + 1; b < s.n; ++b) {
                    if (!may_pair(&s, a, b))
                        continue;
                    const double d = W + (own[a] + own[b]);
                    const long double dist = distance_for(&s.g[a], &s.g[b], d);
                    const bool got = near_now(s.w, s.id[a], s.id[b]);
                    const int verdict = near_verdict(got, dist, d, step, a, b);
                    within += verdict == 0;
                    beyond += verdict == 1;
                    skipped += verdict == 2;
                }
        }
        free_scene(&s);
    }
    ck_assert_int_gt(within, _i ? 1000 : 200);
    ck_assert_int_gt(beyond, _i ? 10000 : 2000);
    ck_assert_int_lt(skipped, (within + beyond) / 100 + 5);
    ck_assert_int_gt(changes, rounds * 20);
}
END_TEST

/* The near pairs of world w (stepped) and of a world made afresh from its
 * objects as they are now (their shapes, poses, margins, sensors, filters
 * and types, and the pairs it ignores), stepped once without motion: the
 * same pairs, bit for bit (the fresh world keeps no list older than its
 * one step). Returns the pairs. */
static size_t same_as_fresh(noctWorld *w, const noctWorldDef *def, int step)
{
    enum { SLOTS = 256 };
    noctWorldDef d = *def;
    d.effects = NOCT_EFFECT_EVENTS;
    noctWorld *f;
    ck_assert_int_eq(noctWorldCreate(&d, &f, NULL), NOCT_OK);
    uint32_t map[SLOTS];
    noctObjectId a[SLOTS], b[SLOTS];
    int n = 0;
    for (uint32_t s = 0; s < SLOTS; ++s) {
        map[s] = UINT32_MAX;
        noctObjectId id;
        if (noctWorldObjectAt(w, s, &id) != NOCT_OK)
            continue;
        noctObjectDef o = noctDefaultObjectDef();
        o.mesh = noctWorldGetMesh(w, id);
        if (o.mesh == NULL)
            ck_assert_int_eq(noctWorldGetHalfExtents(w, id, o.half_extents), NOCT_OK);
        ck_assert_int_eq(noctWorldGetTransform(w, id, &o.transform), NOCT_OK);
        ck_assert_int_eq(noctWorldGetMargin(w, id, &o.margin), NOCT_OK);
        ck_assert_int_eq(noctWorldGetSensor(w, id, &o.sensor), NOCT_OK);
        ck_assert_int_eq(noctWorldGetFilter(w, id, &o.category, &o.mask), NOCT_OK);
        ck_assert_int_eq(noctWorldGetType(w, id, &o.type), NOCT_OK);
        ck_assert_int_eq(noctWorldCreateObject(f, &o, &b[n], NULL), NOCT_OK);
        map[s] = b[n].index;
        a[n++] = id;
    }
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j)
            if (noctWorldPairIgnored(w, a[i], a[j]))
                ck_assert_int_eq(noctWorldIgnorePair(f, b[i], b[j], true, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldStep(f, NULL), NOCT_OK);
    const noctPair *p, *q;
    const size_t np = noctWorldNear(w, &p), nq = noctWorldNear(f, &q);
    ck_assert_msg(np == nq, "step %d: %zu near pairs, %zu in the fresh world", step, np, nq);
    /* (the fresh world's slots follow the old ones' order: the same
     * order of pairs) */
    for (size_t k = 0; k < np; ++k)
        ck_assert_msg(map[p[k].a.index] == q[k].a.index && map[p[k].b.index] == q[k].b.index,
                      "step %d: near pair (%u, %u), in the fresh world (%u, %u)", step,
                      p[k].a.index, p[k].b.index, q[k].a.index, q[k].b.index);
    noctWorldDestroy(f);
    return np;
}

/*
 * A kept list made where the columns (world_near.c, columns_all()) would
 * test more pairs than their budget: 250 small boxes in a rod, every
 * box within the reach of most others on the rod's axis and all of them
 * in one column, drifting slowly (lists are made, from the leaves'
 * sweeps or, over their budget too, not at all): every pair whose
 * distance (noctWorldDistance()'s interval) is within the margin is
 * near, none beyond it by more than the slack, and the near pairs are a
 * world's made afresh, every step, at N = 1 (many leaves) and N = 8.
 */
START_TEST(kept_candidates_of_a_crowded_column)
{
    for (int round = 0; round < 2; ++round) {
        noctWorldDef def = noctDefaultWorldDef();
        def.N = round == 0 ? 1 : 8;
        def.margin = 0.3;
        def.effects = NOCT_EFFECT_EVENTS | NOCT_EFFECT_MOTION;
        noctWorld *w;
        ck_assert_int_eq(noctWorldCreate(&def, &w, NULL), NOCT_OK);
        enum { NO = 250 };
        noctObjectId id[NO];
        for (int i = 0; i < NO; ++i) {
            noctObjectDef d = noctDefaultObjectDef();
            for (int k = 0; k < 3; ++k)
                d.half_extents[k] = 0.02 + 0.03 * uniform();
            d.transform.p[0] = uniform();
            d.transform.p[1] = 0.1 * uniform();
            d.transform.p[2] = 0.1 * uniform();
            random_quat(&d.transform.q);
            ck_assert_int_eq(noctWorldCreateObject(w, &d, &id[i], NULL), NOCT_OK);
            const double v[3] = {0.002 * (uniform() - 0.5), 0.002 * (uniform() - 0.5),
                                 0.002 * (uniform() - 0.5)};
            ck_assert_int_eq(noctWorldSetVelocity(w, id[i], v, NULL), NOCT_OK);
        }
        size_t pairs = 0;
        for (int step = 0; step < 12; ++step) {
            ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
            /* against the distances (slots are the objects' order),
             * once a round on a step that uses a list, then against a
             * fresh world (which makes a list of its own: the distances
             * check the making too) */
            for (int i = 0; i < NO && step == 2 + 3 * round; ++i) {
                static bool is_near[NO][NO];
                if (i == 0) {
                    memset(is_near, 0, sizeof is_near);
                    const noctPair *p;
                    const size_t np = noctWorldNear(w, &p);
                    for (size_t k = 0; k < np; ++k)
                        is_near[p[k].a.index][p[k].b.index] = true;
                }
                ck_assert_uint_eq(id[i].index, (unsigned)i);
                for (int j = i + 1; j < NO; ++j) {
                    noctDistanceResult r;
                    ck_assert_int_eq(noctWorldDistance(w, id[i], id[j], INFINITY, &r, NULL),
                                     NOCT_OK);
                    if (r.upper <= def.margin)
                        ck_assert_msg(is_near[i][j], "step %d: (%d, %d) at %g not near", step,
                                      i, j, r.upper);
                    else if (r.lower > def.margin * (1 + 0x1p-30) + 0x1p-30)
                        ck_assert_msg(!is_near[i][j], "step %d: (%d, %d) at %g near", step, i,
                                      j, r.lower);
                }
            }
            pairs += same_as_fresh(w, &def, step);
        }
        /* (most of the 31 125 pairs are within the margin) */
        ck_assert_uint_gt(pairs, 12 * 10000);
        noctWorldDestroy(w);
    }
}
END_TEST

/*
 * The kept candidates (world_near.c, near_candidates()) against a world
 * made afresh after every step: random scenes of box primitives and box
 * meshes at the scales 1, 2^-300 (about 2^-260) and 2^280 (offset 2^40
 * of their size), moving slowly (lists serve) with runs of fast motion
 * (lists dropped) and of none, spinning, and between steps random edits
 * (margins set, cleared and made the largest, sensors, filters, types,
 * ignored pairs, teleports near and far, a jump away and back before the
 * step, objects removed, made again in their slot at the same place,
 * made anew, and one sent far so that the world grows): the same near
 * pairs every step.
 */
START_TEST(kept_candidates_against_a_fresh_world)
{
    const int rounds = _i ? 24 : 3;
    size_t pairs = 0;
    for (int round = 0; round < rounds; ++round) {
        const double sc = round % 3 == 0 ? 1 : round % 3 == 1 ? 0x1p-300 : 0x1p280;
        const double off = round % 3 == 1 ? 0x1p-260 : round % 3 == 2 ? 0x1p40 * sc : 0;
        noctMesh *cube;
        ck_assert_int_eq(noctMeshCreateBox(0.3 * sc, 0.2 * sc, 0.25 * sc, &cube, NULL), NOCT_OK);
        noctWorldDef def = noctDefaultWorldDef();
        def.N = 1 + round % 4;
        def.accuracy = round % 2 ? NOCT_ACCURACY_BOX : NOCT_ACCURACY_EXACT;
        def.margin = round % 4 == 3 ? 0 : sc * 0.3 * uniform();
        def.effects = NOCT_EFFECT_EVENTS | NOCT_EFFECT_MOTION | NOCT_EFFECT_SPIN;
        noctWorld *w;
        ck_assert_int_eq(noctWorldCreate(&def, &w, NULL), NOCT_OK);
        enum { NO = 40 };
        noctObjectId id[NO];
        bool alive[NO];
        const int n = 15 + (int)(25 * uniform());
        for (int i = 0; i < n; ++i) {
            noctObjectDef d = noctDefaultObjectDef();
            if (uniform() < 0.3)
                d.mesh = cube;
            else
                for (int k = 0; k < 3; ++k)
                    d.half_extents[k] = sc * (0.1 + 0.4 * uniform());
            for (int k = 0; k < 3; ++k)
                d.transform.p[k] = off + sc * 6 * uniform();
            random_quat(&d.transform.q);
            d.margin = uniform() < 0.5 ? 0 : sc * 0.4 * uniform();
            d.sensor = uniform() < 0.1;
            d.category = random_bits();
            d.mask = random_bits();
            ck_assert_int_eq(noctWorldCreateObject(w, &d, &id[i], NULL), NOCT_OK);
            alive[i] = true;
        }
        for (int step = 0; step < 50; ++step) {
            const bool still = (step / 10) % 3 == 1;
            const double speed = (step / 7) % 4 == 3 ? 0.5 : 0.01;
            for (int i = 0; i < n; ++i) {
                if (!alive[i])
                    continue;
                if (still || uniform() < 0.1) {
                    double v[3] = {0, 0, 0};
                    for (int k = 0; k < 3 && !still; ++k)
                        v[k] = sc * speed * (2 * uniform() - 1);
                    ck_assert_int_eq(noctWorldSetVelocity(w, id[i], v, NULL), NOCT_OK);
                }
                noctTransform x;
                ck_assert_int_eq(noctWorldGetTransform(w, id[i], &x), NOCT_OK);
                for (int k = 0; k < 3; ++k)
                    if (x.p[k] < off - sc || x.p[k] > off + 7 * sc) {
                        x.p[k] = off + sc * 6 * uniform();
                        ck_assert_int_eq(noctWorldSetTransform(w, id[i], &x, NULL), NOCT_OK);
                    }
            }
            for (int e = (int)(3 * uniform()); e > 0; --e) {
                const int i = (int)(n * uniform());
                int what = (int)(11 * uniform());
                if (!alive[i]) { /* made anew */
                    noctObjectDef d = noctDefaultObjectDef();
                    d.mesh = cube;
                    for (int k = 0; k < 3; ++k)
                        d.transform.p[k] = off + sc * 6 * uniform();
                    ck_assert_int_eq(noctWorldCreateObject(w, &d, &id[i], NULL), NOCT_OK);
                    alive[i] = true;
                    continue;
                }
                /* (the edits that make the list again, seldom) */
                if (what <= 3 && uniform() < 0.7)
                    what = 4 + (int)(7 * uniform());
                noctTransform x, y;
                ck_assert_int_eq(noctWorldGetTransform(w, id[i], &x), NOCT_OK);
                switch (what) {
                case 0: { /* a margin, none, or the largest */
                    const double m = uniform() < 0.4   ? 0
                                     : uniform() < 0.2 ? sc * 0.8
                                                       : sc * 0.4 * uniform();
                    ck_assert_int_eq(noctWorldSetMargin(w, id[i], m, NULL), NOCT_OK);
                    break;
                }
                case 1: {
                    bool s;
                    ck_assert_int_eq(noctWorldGetSensor(w, id[i], &s), NOCT_OK);
                    ck_assert_int_eq(noctWorldSetSensor(w, id[i], !s, NULL), NOCT_OK);
                    break;
                }
                case 2: { /* gone, and made again in its slot at the same place */
                    noctObjectDef d = noctDefaultObjectDef();
                    d.mesh = noctWorldGetMesh(w, id[i]);
                    if (d.mesh == NULL)
                        ck_assert_int_eq(noctWorldGetHalfExtents(w, id[i], d.half_extents),
                                         NOCT_OK);
                    d.transform = x;
                    ck_assert_int_eq(noctWorldGetMargin(w, id[i], &d.margin), NOCT_OK);
                    if (uniform() < 0.5)
                        d.margin = uniform() < 0.5 ? 0 : sc * 0.4 * uniform();
                    ck_assert_int_eq(noctWorldGetFilter(w, id[i], &d.category, &d.mask), NOCT_OK);
                    const uint32_t slot = id[i].index;
                    ck_assert_int_eq(noctWorldRemove(w, id[i], NULL), NOCT_OK);
                    ck_assert_int_eq(noctWorldCreateObject(w, &d, &id[i], NULL), NOCT_OK);
                    ck_assert_uint_eq(id[i].index, slot);
                    break;
                }
                case 3:
                    ck_assert_int_eq(noctWorldRemove(w, id[i], NULL), NOCT_OK);
                    alive[i] = false;
                    break;
                case 4:
                    ck_assert_int_eq(noctWorldSetFilter(w, id[i], random_bits(), random_bits(),
                                                        NULL),
                                     NOCT_OK);
                    break;
                case 5: /* a teleport near or far */
                    for (int k = 0; k < 3; ++k)
                        x.p[k] += sc * (uniform() < 0.5 ? 0.05 : 1) * (2 * uniform() - 1);
                    ck_assert_int_eq(noctWorldSetTransform(w, id[i], &x, NULL), NOCT_OK);
                    break;
                case 6: { /* a spin, or none */
                    const double a = uniform() < 0.3 ? 0 : 0.02 * uniform();
                    const noctQuat q = {sin(a), 0, 0, cos(a)};
                    ck_assert_int_eq(noctWorldSetAngularVelocity(w, id[i], &q, NULL), NOCT_OK);
                    break;
                }
                case 7: {
                    const noctObjectType t[3] = {NOCT_OBJECT_STATIC, NOCT_OBJECT_KINEMATIC,
                                                 NOCT_OBJECT_MOVING};
                    ck_assert_int_eq(noctWorldSetType(w, id[i], t[(int)(3 * uniform())], NULL),
                                     NOCT_OK);
                    break;
                }
                case 8: { /* a pair ignored or not */
                    const int j = (int)(n * uniform());
                    if (j != i && alive[j])
                        ck_assert_int_eq(noctWorldIgnorePair(w, id[i], id[j], uniform() < 0.7,
                                                             NULL),
                                         NOCT_OK);
                    break;
                }
                case 9: /* away and back before the step: no motion */
                    y = x;
                    y.p[0] += sc * 1000;
                    ck_assert_int_eq(noctWorldSetTransform(w, id[i], &y, NULL), NOCT_OK);
                    ck_assert_int_eq(noctWorldSetTransform(w, id[i], &x, NULL), NOCT_OK);
                    break;
                default: /* far: the world grows */
                    if (uniform() < 0.3) {
                        x.p[1] = off + sc * (uniform() < 0.5 ? 60 : -60);
                        ck_assert_int_eq(noctWorldSetTransform(w, id[i], &x, NULL), NOCT_OK);
                    }
                    break;
                }
            }
            ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
            pairs += same_as_fresh(w, &def, step);
        }
        noctWorldDestroy(w);
        noctMeshDestroy(cube);
    }
    ck_assert_uint_gt(pairs, (size_t)rounds * 100);
}
END_TEST

/* The same list of pairs, by slot and generation, in worlds w and t. */
static void same_pairs(const char *what, const noctPair *p, size_t np, const noctPair *q,
                       size_t nq, int round, int step)
{
    ck_assert_msg(np == nq, "round %d step %d: %zu %s pairs, %zu without the margin", round,
                  step, np, what, nq);
    for (size_t k = 0; k < np; ++k)
        ck_assert_msg(p[k].a.index == q[k].a.index && p[k].b.index == q[k].b.index &&
                          p[k].a.generation == q[k].a.generation &&
                          p[k].b.generation == q[k].b.generation,
                      "round %d step %d: %s pair (%u, %u), without the margin (%u, %u)", round,
                      step, what, p[k].a.index, p[k].b.index, q[k].a.index, q[k].b.index);
}

/* Step the twins w[0] (with the margins) and w[1] (without) once each;
 * the same colliding and sensing pairs and contact events after it. Adds
 * 1 to *skipped when w[0]'s step visited and skipped no leaf (it left the
 * search out); returns the colliding pairs. */
static size_t step_twins(noctWorld *w[2], int round, int step, size_t *skipped)
{
    noctWorldCounters c0, c1;
    noctWorldGetCounters(w[0], &c0);
    for (int t = 0; t < 2; ++t)
        ck_assert_int_eq(noctWorldStep(w[t], NULL), NOCT_OK);
    noctWorldGetCounters(w[0], &c1);
    *skipped += c1.leaves_visited == c0.leaves_visited && c1.leaves_skipped == c0.leaves_skipped;
    size_t (*const lists[4])(const noctWorld *, const noctPair **) = {
        noctWorldColliding, noctWorldSensing, noctWorldBegan, noctWorldEnded};
    const char *const names[4] = {"colliding", "sensing", "began", "ended"};
    size_t colliding = 0;
    for (int l = 0; l < 4; ++l) {
        const noctPair *p[2];
        size_t np[2];
        for (int t = 0; t < 2; ++t)
            np[t] = lists[l](w[t], &p[t]);
        same_pairs(names[l], p[0], np[0], p[1], np[1], round, step);
        if (l == 0)
            colliding = np[0];
    }
    return colliding;
}

/*
 * A step with a margin takes its colliding pairs from the near stage's
 * candidates, and its few sensors' pairs from queries of their boxes, and
 * leaves the pair search out (world_near.c, noct_world_near_pairs()); the
 * search comes back when more than one object in 16 is a sensor or the
 * last margin goes, with the reach of the steps it left out (the leaves'
 * kept pairs and budgets are from before them).
 * Against a twin world without any margin, made and edited alike and
 * stepped in turn, whose pairs the search alone finds: the same colliding
 * and sensing pairs and contact events after every step (with the
 * response on, a pair missed would also change the motion). Random scenes
 * of box primitives and box meshes drifting at two speeds (lists kept,
 * and dropped), moving, kinematic and static, with filters that turn
 * pairs away and pairs ignored, whose own margins are set in some runs of
 * steps and all cleared in others (and a world margin in some rounds),
 * with a large sensor and another one for a few steps now and then (the
 * search left out or not, by the scene's size), teleports (seldom: each
 * makes every leaf sweep), removals and objects made anew; at N 1 to 64
 * and big, at the box, convex, exact and continuous accuracies, in the
 * incremental and rebuild modes. The leaves' counters show that most
 * steps with a margin left the search out.
 */
START_TEST(colliding_pairs_with_a_margin_against_the_search)
{
    const int rounds = _i ? 20 : 5;
    size_t pairs = 0, skipped = 0;
    for (int round = 0; round < rounds; ++round) {
        noctMesh *cube;
        ck_assert_int_eq(noctMeshCreateBox(0.3, 0.2, 0.25, &cube, NULL), NOCT_OK);
        noctWorldDef def = noctDefaultWorldDef();
        def.N = round % 5 == 4 ? NOCT_N_EXHAUSTIVE : 1 << 2 * (round % 4);
        const noctAccuracy acc[4] = {NOCT_ACCURACY_EXACT, NOCT_ACCURACY_BOX,
                                     NOCT_ACCURACY_CONVEX, NOCT_ACCURACY_CONTINUOUS};
        def.accuracy = acc[round % 4];
        def.maintenance = round % 3 == 2 ? NOCT_MAINTAIN_REBUILD : NOCT_MAINTAIN_INCREMENTAL;
        def.effects = NOCT_EFFECT_EVENTS | NOCT_EFFECT_MOTION | NOCT_EFFECT_RESPONSE;
        noctWorldDef def0 = def;
        def.margin = round % 3 == 1 ? 0.15 : 0;
        noctWorld *w[2]; /* w[0] with the margins, w[1] without */
        ck_assert_int_eq(noctWorldCreate(&def, &w[0], NULL), NOCT_OK);
        ck_assert_int_eq(noctWorldCreate(&def0, &w[1], NULL), NOCT_OK);
        enum { NO = 60 };
        noctObjectId id[NO];
        bool alive[NO];
        const int n = 30 + (int)(30 * uniform());
        const noctObjectType types[3] = {NOCT_OBJECT_MOVING, NOCT_OBJECT_KINEMATIC,
                                         NOCT_OBJECT_STATIC};
        for (int i = 0; i < n; ++i) {
            noctObjectDef d = noctDefaultObjectDef();
            if (uniform() < 0.3)
                d.mesh = cube;
            else
                for (int k = 0; k < 3; ++k)
                    d.half_extents[k] = 0.1 + 0.3 * uniform();
            for (int k = 0; k < 3; ++k) {
                d.transform.p[k] = 5 * uniform();
                d.velocity[k] = 0.02 * (2 * uniform() - 1);
            }
            if (uniform() < 0.2) { /* (a mask of a few bits turns most pairs away) */
                d.category = random_bits();
                d.mask = random_bits() & random_bits();
            }
            d.type = uniform() < 0.8 ? types[0] : types[1 + (int)(2 * uniform())];
            for (int t = 0; t < 2; ++t)
                ck_assert_int_eq(noctWorldCreateObject(w[t], &d, &id[i], NULL), NOCT_OK);
            alive[i] = true;
        }
        int sensor = -1;
        noctObjectId sensor_id;
        for (int step = 0; step < 90; ++step) {
            /* margins on in steps [0, 30) and [45, 90) but for a few
             * objects in [60, 75); a sensor in [5, 9) and [50, 54); fast
             * in [36, 45) and [81, 90) */
            const bool margins = step < 30 || step >= 45;
            const double speed = step % 45 >= 36 ? 0.3 : round % 2 ? 0.005 : 0.02;
            for (int i = 0; i < n; ++i) {
                if (!alive[i])
                    continue;
                if (step % 15 == 0 || step % 9 == 0) {
                    const double m = !margins || (step >= 60 && step < 75 && i % 4 != 0)
                                         ? 0
                                         : 0.3 * uniform();
                    ck_assert_int_eq(noctWorldSetMargin(w[0], id[i], m, NULL), NOCT_OK);
                }
                noctTransform x;
                ck_assert_int_eq(noctWorldGetTransform(w[0], id[i], &x), NOCT_OK);
                bool out = false;
                for (int k = 0; k < 3; ++k)
                    out |= x.p[k] < -1 || x.p[k] > 6;
                /* (a teleport makes a large reach: every leaf is swept) */
                if (out || (step % 10 == 3 && uniform() < 0.05)) { /* back in, or a teleport */
                    for (int k = 0; k < 3; ++k)
                        x.p[k] = 5 * uniform();
                    for (int t = 0; t < 2; ++t)
                        ck_assert_int_eq(noctWorldSetTransform(w[t], id[i], &x, NULL), NOCT_OK);
                }
                if (step % 9 == 0) {
                    double v[3];
                    for (int k = 0; k < 3; ++k)
                        v[k] = speed * (2 * uniform() - 1);
                    for (int t = 0; t < 2; ++t)
                        ck_assert_int_eq(noctWorldSetVelocity(w[t], id[i], v, NULL), NOCT_OK);
                }
            }
            if (step == 5 || step == 50) { /* a large sensor in the middle, or one of them */
                noctObjectDef d = noctDefaultObjectDef();
                d.sensor = true;
                for (int k = 0; k < 3; ++k) {
                    d.half_extents[k] = 1;
                    d.transform.p[k] = 2.5;
                }
                for (int t = 0; t < 2; ++t)
                    ck_assert_int_eq(noctWorldCreateObject(w[t], &d, &sensor_id, NULL), NOCT_OK);
                for (sensor = (int)(n * uniform()); !alive[sensor]; sensor = (sensor + 1) % n)
                    ;
                for (int t = 0; t < 2; ++t)
                    ck_assert_int_eq(noctWorldSetSensor(w[t], id[sensor], true, NULL), NOCT_OK);
            }
            if (step == 9 || step == 54) {
                for (int t = 0; t < 2; ++t)
                    ck_assert_int_eq(noctWorldRemove(w[t], sensor_id, NULL), NOCT_OK);
                if (alive[sensor])
                    for (int t = 0; t < 2; ++t)
                        ck_assert_int_eq(noctWorldSetSensor(w[t], id[sensor], false, NULL),
                                         NOCT_OK);
            }
            const int e = (int)(n * uniform()), f = (int)(n * uniform());
            const double what = uniform();
            if (what < 0.15) { /* gone, or made anew */
                if (alive[e]) {
                    for (int t = 0; t < 2; ++t)
                        ck_assert_int_eq(noctWorldRemove(w[t], id[e], NULL), NOCT_OK);
                } else {
                    noctObjectDef d = noctDefaultObjectDef();
                    d.mesh = cube;
                    for (int k = 0; k < 3; ++k)
                        d.transform.p[k] = 5 * uniform();
                    for (int t = 0; t < 2; ++t)
                        ck_assert_int_eq(noctWorldCreateObject(w[t], &d, &id[e], NULL), NOCT_OK);
                }
                alive[e] = !alive[e];
            } else if (what < 0.3 && alive[e]) {
                const noctObjectType ty = types[(int)(3 * uniform())];
                for (int t = 0; t < 2; ++t)
                    ck_assert_int_eq(noctWorldSetType(w[t], id[e], ty, NULL), NOCT_OK);
            } else if (what < 0.45 && alive[e]) {
                const uint64_t cat = random_bits(), mask = random_bits() | random_bits();
                for (int t = 0; t < 2; ++t)
                    ck_assert_int_eq(noctWorldSetFilter(w[t], id[e], cat, mask, NULL), NOCT_OK);
            } else if (what < 0.7 && alive[e] && alive[f] && e != f) {
                const bool ignore = uniform() < 0.7;
                for (int t = 0; t < 2; ++t)
                    ck_assert_int_eq(noctWorldIgnorePair(w[t], id[e], id[f], ignore, NULL),
                                     NOCT_OK);
            }
            pairs += step_twins(w, round, step, &skipped);
        }
        for (int t = 0; t < 2; ++t)
            noctWorldDestroy(w[t]);
        noctMeshDestroy(cube);
    }
    ck_assert_uint_gt(pairs, (size_t)rounds * 200);
    /* (most steps with a margin, not all: sensors, the exhaustive
     * rounds, objects too fast for a list in some) */
    ck_assert_uint_gt(skipped, (size_t)rounds * 30);
}
END_TEST

/*
 * The search after steps that left it out spends their reach: two rows
 * of boxes in one leaf (N above their count: the root is the leaf, which
 * no box enters or leaves), each box closing in on its partner in the
 * other row by 0.02 a step. The first steps search (the leaf is swept,
 * and its boxes, 0.8 apart at least, are skipped while that lasts), the
 * next 40 take their pairs from the margin's candidates (the partners
 * meet on the way), then the margins go and the search comes back. A
 * search that spent only its own step's reach would skip the leaf and
 * miss the colliding pairs; the twin world without margins, searched
 * every step, has them.
 */
START_TEST(the_search_after_skipped_steps_spends_their_reach)
{
    noctWorldDef def = noctDefaultWorldDef();
    def.N = 64;
    def.effects = NOCT_EFFECT_EVENTS | NOCT_EFFECT_MOTION;
    noctWorld *w[2];
    for (int t = 0; t < 2; ++t)
        ck_assert_int_eq(noctWorldCreate(&def, &w[t], NULL), NOCT_OK);
    enum { ROW = 10 };
    noctObjectId id[2 * ROW];
    for (int i = 0; i < 2 * ROW; ++i) {
        noctObjectDef d = noctDefaultObjectDef();
        for (int k = 0; k < 3; ++k)
            d.half_extents[k] = 0.1;
        d.transform.p[0] = i < ROW ? 0 : 1;
        d.transform.p[1] = 1.0 * (i % ROW);
        d.velocity[0] = i < ROW ? 0.01 : -0.01;
        for (int t = 0; t < 2; ++t)
            ck_assert_int_eq(noctWorldCreateObject(w[t], &d, &id[i], NULL), NOCT_OK);
    }
    size_t met = 0, skipped = 0;
    for (int step = 0; step < 60; ++step) {
        if (step == 5 || step == 45)
            for (int i = 0; i < 2 * ROW; ++i)
                ck_assert_int_eq(noctWorldSetMargin(w[0], id[i], step == 5 ? 0.05 : 0, NULL),
                                 NOCT_OK);
        const size_t colliding = step_twins(w, 0, step, &skipped);
        if (step >= 45)
            met += colliding;
    }
    /* (the partners meet at step 39 and overlap to the end) */
    ck_assert_uint_ge(met, ROW);
    ck_assert_uint_ge(skipped, 35);
    for (int t = 0; t < 2; ++t)
        noctWorldDestroy(w[t]);
}
END_TEST

/*
 * Kept proofs at the extreme scales (2^-200 and 2^200; the hints' floats
 * hold coefficients, which have no scale, and axes, which may overflow or
 * vanish as floats), with slots given to objects of another shape (a box
 * primitive's slot to a box mesh of other sizes and back), objects' own
 * margins set and cleared between steps, small turns and jumps: every
 * pair against noctWorldDistance()'s bracket (near when its upper bound
 * is inside the margin, not near when its lower bound is beyond it, by a
 * relative 1e-9).
 */
START_TEST(kept_proofs_at_extreme_scales)
{
    enum { NO = 30 };
    int within = 0, beyond = 0;
    const int steps = test_rounds(60, 20); /* fewer random steps under valgrind */
    for (int v = 0; v < 3; ++v) {
        const double scale = v == 0 ? 1 : v == 1 ? 0x1p-200 : 0x1p200;
        noctMesh *box[2];
        ck_assert_int_eq(noctMeshCreateBox(0.5 * scale, 0.3 * scale, 0.7 * scale, &box[0], NULL),
                         NOCT_OK);
        ck_assert_int_eq(noctMeshCreateBox(0.2 * scale, 0.9 * scale, 0.4 * scale, &box[1], NULL),
                         NOCT_OK);
        noctWorldDef wd = noctDefaultWorldDef();
        wd.effects = NOCT_EFFECT_EVENTS;
        wd.margin = (0.05 + 0.3 * uniform()) * scale;
        wd.N = v == 1 ? 2 : NOCT_AUTO;
        noctWorld *w;
        ck_assert_int_eq(noctWorldCreate(&wd, &w, NULL), NOCT_OK);
        noctObjectId id[NO];
        noctTransform x[NO];
        double m[NO];
        bool alive[NO];
        for (int step = 0; step < steps; ++step) {
            for (int i = 0; i < NO; ++i) {
                const double u = uniform();
                if (step == 0 || (!alive[i] && u < 0.3)) {
                    noctObjectDef d = noctDefaultObjectDef();
                    const int kind = (int)(3 * uniform());
                    if (kind == 0)
                        for (int k = 0; k < 3; ++k)
                            d.half_extents[k] = (0.2 + 0.8 * uniform()) * scale;
                    else
                        d.mesh = box[kind - 1];
                    for (int k = 0; k < 3; ++k)
                        d.transform.p[k] = 6 * uniform() * scale;
                    random_quat(&d.transform.q);
                    d.margin = uniform() < 0.3 ? 0.3 * uniform() * scale : 0;
                    ck_assert_int_eq(noctWorldCreateObject(w, &d, &id[i], NULL), NOCT_OK);
                    x[i] = d.transform;
                    m[i] = d.margin;
                    alive[i] = true;
                    continue;
                }
                if (!alive[i])
                    continue;
                if (u < 0.03) {
                    ck_assert_int_eq(noctWorldRemove(w, id[i], NULL), NOCT_OK);
                    alive[i] = false;
                    continue;
                }
                if (u < 0.06) {
                    m[i] = uniform() < 0.3 ? 0 : 0.3 * uniform() * scale;
                    ck_assert_int_eq(noctWorldSetMargin(w, id[i], m[i], NULL), NOCT_OK);
                }
                if (u < 0.5) {
                    for (int k = 0; k < 3; ++k)
                        x[i].p[k] += 0.05 * (uniform() - 0.5) * scale;
                } else if (u < 0.6) { /* a small turn */
                    noctQuat q = x[i].q, t;
                    random_quat(&t);
                    const double f = 0.02;
                    q = (noctQuat){q.x + f * t.x, q.y + f * t.y, q.z + f * t.z, q.w + f * t.w};
                    const double n = sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
                    x[i].q = (noctQuat){q.x / n, q.y / n, q.z / n, q.w / n};
                } else if (u < 0.62) {
                    for (int k = 0; k < 3; ++k)
                        x[i].p[k] = 6 * uniform() * scale;
                }
                ck_assert_int_eq(noctWorldSetTransform(w, id[i], &x[i], NULL), NOCT_OK);
            }
            ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
            const noctPair *near;
            const size_t nn = noctWorldNear(w, &near);
            for (int i = 0; i < NO; ++i)
                for (int j = i + 1; j < NO; ++j) {
                    if (!alive[i] || !alive[j])
                        continue;
                    const double d = wd.margin + (m[i] + m[j]);
                    noctDistanceResult r;
                    ck_assert_int_eq(noctWorldDistance(w, id[i], id[j], INFINITY, &r, NULL),
                                     NOCT_OK);
                    noctObjectId a = id[i], c = id[j];
                    if (a.index > c.index) {
                        const noctObjectId t = a;
                        a = c;
                        c = t;
                    }
                    const bool got = in_list(near, nn, a, c);
                    if (r.upper < d * (1 - 1e-9)) {
                        ck_assert_msg(got, "scale %g step %d: %d and %d not near", scale, step, i,
                                      j);
                        ++within;
                    } else if (r.lower > d * (1 + 1e-9)) {
                        ck_assert_msg(!got, "scale %g step %d: %d and %d near", scale, step, i, j);
                        ++beyond;
                    }
                }
        }
        noctWorldDestroy(w);
        noctMeshDestroy(box[0]);
        noctMeshDestroy(box[1]);
    }
    ck_assert_int_gt(within, 1000 * steps / 60);
    ck_assert_int_gt(beyond, 10000 * steps / 60);
}
END_TEST

static Suite *near_suite(void)
{
    Suite *s = suite_create("near");
    TCase *tc = test_case(s, "near", 300, NULL);
    tcase_add_checked_fixture(tc, make_ell_fixture, free_ell_fixture);
    tcase_add_loop_test(tc, near_pairs_against_geometry, 0, 1);
    tcase_add_loop_test(tc, box_level_uses_the_boxes, 0, 1);
    tcase_add_loop_test(tc, query_near_against_geometry, 0, 1);
    tcase_add_test(tc, no_margin_no_near_and_bad_margins);
    tcase_add_test(tc, a_failed_step_keeps_the_near_pairs);
    tcase_add_loop_test(tc, near_pairs_against_the_query, 0, 1);
    tcase_add_loop_test(tc, object_margins_against_distance, 0, 1);
    tcase_add_loop_test(tc, query_near_with_object_margins, 0, 1);
    tcase_add_test(tc, object_margin_setters_and_errors);
    tcase_add_loop_test(tc, near_pairs_across_leaves, 0, 1);
    tcase_add_loop_test(tc, kept_proofs_cross_the_margin, 0, 1);
    tcase_add_loop_test(tc, kept_proofs_against_geometry, 0, 1);
    tcase_add_test(tc, kept_proofs_at_extreme_scales);
    tcase_add_loop_test(tc, kept_candidates_against_geometry, 0, 1);
    tcase_add_loop_test(tc, kept_candidates_against_a_fresh_world, 0, 1);
    tcase_add_test(tc, kept_candidates_of_a_crowded_column);
    tcase_add_loop_test(tc, colliding_pairs_with_a_margin_against_the_search, 0, 1);
    tcase_add_test(tc, the_search_after_skipped_steps_spends_their_reach);
    TCase *full = test_case(s, "near, full", 300, "slow seeds");
    tcase_add_checked_fixture(full, make_ell_fixture, free_ell_fixture);
    tcase_add_loop_test(full, near_pairs_against_geometry, 1, 2);
    tcase_add_loop_test(full, box_level_uses_the_boxes, 1, 2);
    tcase_add_loop_test(full, query_near_against_geometry, 1, 2);
    tcase_add_loop_test(full, near_pairs_against_the_query, 1, 2);
    tcase_add_loop_test(full, object_margins_against_distance, 1, 2);
    tcase_add_loop_test(full, query_near_with_object_margins, 1, 2);
    tcase_add_loop_test(full, near_pairs_across_leaves, 1, 2);
    tcase_add_loop_test(full, kept_proofs_cross_the_margin, 1, 2);
    tcase_add_loop_test(full, kept_proofs_against_geometry, 1, 2);
    tcase_add_loop_test(full, kept_candidates_against_geometry, 1, 2);
    tcase_add_loop_test(full, kept_candidates_against_a_fresh_world, 1, 2);
    tcase_add_loop_test(full, colliding_pairs_with_a_margin_against_the_search, 1, 2);
    return s;
}

int main(void)
{
    return run_suite(near_suite());
}
