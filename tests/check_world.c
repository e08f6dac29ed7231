/* SPDX-License-Identifier: MIT */
/*
 * Check suite for the collision world (include/noctree/world.h).
 *
 * Oracles: the closed-form event counts of the planes scenes (noctree-families(7)),
 * identical event sequences across N and maintenance modes, a brute-force
 * all-pairs exact test after every step of random scenes, and the world's
 * whole-structure validation walk after every step.
 */
#define _POSIX_C_SOURCE 200809L /* open_memstream(3) */
#include <check.h>
#include <math.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>

#include <noctree/scene.h>
#include <noctree/world.h>

#include "testutil.h"

static noctWorld *make_world(int N, int depth, noctMaintenance mode)
{
    noctWorldDef def = noctDefaultWorldDef();
    def.N = N;
    def.max_depth = depth;
    def.maintenance = mode;
    noctWorld *w = NULL;
    noctError err;
    ck_assert_msg(noctWorldCreate(&def, &w, &err) == NOCT_OK, "%s", err.message);
    return w;
}

static void step_ok(noctWorld *w)
{
    noctError err;
    noctStatus st = noctWorldStep(w, &err);
    ck_assert_msg(st == NOCT_OK, "step: %s", err.message);
}

static void validate_ok(noctWorld *w)
{
    noctError err;
    noctStatus st = noctWorldValidate(w, &err);
    ck_assert_msg(st == NOCT_OK, "validate: %s", err.message);
}

/* ---- planes: closed-form counts, the same events for every N and mode ---- */

/* Run t_k for 200 steps; return the number of contact-begin events and a
 * hash of the whole event sequence (step, pair) in *hash. */
static size_t run_planes(int k, int N, noctMaintenance mode, int validate_every,
                         uint64_t *hash)
{
    noctMesh *cube;
    ck_assert_int_eq(noctMeshCreateBox(0.5, 0.5, 0.5, &cube, NULL), NOCT_OK);
    noctWorld *w = make_world(N, N == NOCT_AUTO ? NOCT_AUTO : 6, mode);
    ck_assert_int_eq(noctWorldAddPlanes(w, k, cube, NULL), NOCT_OK);
    ck_assert_uint_eq(noctWorldObjectCount(w), (size_t)(2 * (2 * k + 1) * (2 * k + 1)));
    size_t begins = 0;
    uint64_t h = 1469598103934665603u;
    for (int s = 1; s <= 200; ++s) {
        step_ok(w);
        const noctPair *p;
        size_t n = noctWorldBegan(w, &p);
        begins += n;
        for (size_t i = 0; i < n; ++i) {
            h = (h ^ (uint64_t)s) * 1099511628211u;
            h = (h ^ p[i].a.index) * 1099511628211u;
            h = (h ^ p[i].b.index) * 1099511628211u;
            /* Each begin is a facing pair: same row, opposite planes. */
            size_t per = (size_t)((2 * k + 1) * (2 * k + 1));
            EXPECT(p[i].a.index < per && p[i].b.index == p[i].a.index + per);
        }
        if (validate_every > 0 && s % validate_every == 0)
            validate_ok(w);
    }
    noctWorldDestroy(w);
    noctMeshDestroy(cube);
    *hash = h;
    return begins;
}

START_TEST(planes_counts_across_N_and_modes)
{
    static const int ks[] = {0, 1, 2, 3, 5, 10};
    static const int Ns[] = {1, 2, 5, 10, 30, 50, NOCT_N_EXHAUSTIVE, NOCT_AUTO};
    int k = ks[_i];
    size_t want = (size_t)((2 * k + 1) * (2 * k + 1));
    uint64_t first = 0;
    for (size_t n = 0; n < sizeof Ns / sizeof *Ns; ++n)
        for (int mode = 0; mode < 2; ++mode) {
            uint64_t h;
            size_t got = run_planes(k, Ns[n], (noctMaintenance)mode, k <= 3 ? 5 : 50, &h);
            ck_assert_msg(got == want, "t%d, N = %d, mode %d: %zu begins, want %zu", k,
                          Ns[n], mode, got, want);
            if (n == 0 && mode == 0)
                first = h;
            ck_assert_msg(h == first, "t%d, N = %d, mode %d: event sequence differs", k,
                          Ns[n], mode);
        }
}
END_TEST

/* t20 and t30: every N incrementally, and rebuild mode once; the same
 * events throughout. (k <= 10 runs every N in both modes above.) */
START_TEST(planes_t20_t30)
{
    static const int Ns[] = {1, 2, 5, 10, 30, 50, NOCT_N_EXHAUSTIVE, NOCT_AUTO};
    int k = _i == 0 ? 20 : 30;
    size_t want = (size_t)((2 * k + 1) * (2 * k + 1));
    uint64_t first = 0, h;
    for (size_t n = 0; n < sizeof Ns / sizeof *Ns; ++n) {
        ck_assert_uint_eq(run_planes(k, Ns[n], NOCT_MAINTAIN_INCREMENTAL,
                                     n == 3 ? 100 : 0, &h), want);
        if (n == 0)
            first = h;
        ck_assert_msg(h == first, "t%d, N = %d: event sequence differs", k, Ns[n]);
    }
    ck_assert_uint_eq(run_planes(k, 50, NOCT_MAINTAIN_REBUILD, 0, &h), want);
    ck_assert(h == first);
}
END_TEST

/* Step w steps times, validating every 50th: the contact begins, and a
 * hash of their sequence (step, a, b) into *hash. */
static size_t steps_and_hash(noctWorld *w, int steps, uint64_t *hash)
{
    size_t begins = 0;
    uint64_t h = 1469598103934665603u;
    for (int s = 1; s <= steps; ++s) {
        step_ok(w);
        const noctPair *p;
        const size_t nb = noctWorldBegan(w, &p);
        begins += nb;
        for (size_t i = 0; i < nb; ++i)
            h = ((h ^ (uint64_t)s) * 1099511628211u ^ p[i].a.index ^
                 ((uint64_t)p[i].b.index << 32)) * 1099511628211u;
        if (s % 50 == 0)
            validate_ok(w);
    }
    *hash = h;
    return begins;
}

/* gas_1000 (noctree-families(7)): 6 212 contact-begin events in 200 steps, the
 * answer ODE, FCL and a brute-force reference agree on; the same event
 * sequence in both maintenance modes. */
static size_t run_gas(size_t n, int N, noctMaintenance mode, uint64_t *hash)
{
    noctWorldDef def = noctDefaultWorldDef();
    def.N = N;
    def.max_depth = N == NOCT_AUTO ? NOCT_AUTO : 8;
    def.maintenance = mode;
    def.effects |= NOCT_EFFECT_WALLS;
    double lb = noctGasContainerSize(n);
    for (int k = 0; k < 3; ++k) {
        def.walls_lo[k] = 0;
        def.walls_hi[k] = lb;
    }
    noctWorld *w;
    noctError err;
    ck_assert_int_eq(noctWorldCreate(&def, &w, &err), NOCT_OK);
    ck_assert_msg(noctWorldAddGas(w, n, &err) == NOCT_OK, "%s", err.message);
    const size_t begins = steps_and_hash(w, 200, hash);
    noctWorldDestroy(w);
    return begins;
}

START_TEST(gas_1000_known_answer)
{
    uint64_t h1, h2, h3;
    ck_assert_uint_eq(run_gas(1000, 10, NOCT_MAINTAIN_INCREMENTAL, &h1), 6212);
    ck_assert_uint_eq(run_gas(1000, 30, NOCT_MAINTAIN_REBUILD, &h2), 6212);
    ck_assert_uint_eq(run_gas(1000, NOCT_AUTO, NOCT_MAINTAIN_INCREMENTAL, &h3), 6212);
    ck_assert(h1 == h2 && h1 == h3);
}
END_TEST

/* gas_10000: 77 281 events, the reference's answer. */
START_TEST(gas_10000_known_answer)
{
    uint64_t h, h_auto;
    ck_assert_uint_eq(run_gas(10000, 30, NOCT_MAINTAIN_INCREMENTAL, &h), 77281);
    ck_assert_uint_eq(run_gas(10000, NOCT_AUTO, NOCT_MAINTAIN_INCREMENTAL, &h_auto), 77281);
    ck_assert(h == h_auto);
}
END_TEST

/* A family from noctSceneFamily() at N (NOCT_AUTO: the depth too, else
 * depth 10) and maintenance mode, its steps; its begins and their hash. */
static size_t run_family(const char *spec, int N, noctMaintenance mode, uint64_t *hash)
{
    noctScene *sc;
    noctWorld *w;
    noctError err;
    ck_assert_msg(noctSceneFamily(spec, &sc, &err) == NOCT_OK, "%s", err.message);
    noctWorldDef *def = noctSceneDef(sc);
    def->N = N;
    def->max_depth = N == NOCT_AUTO ? NOCT_AUTO : 10;
    def->maintenance = mode;
    ck_assert_msg(noctSceneBuild(sc, &w, &err) == NOCT_OK, "%s", err.message);
    const size_t begins = steps_and_hash(w, noctSceneSteps(sc), hash);
    noctWorldDestroy(w);
    noctSceneDestroy(sc);
    return begins;
}

/* The gas kinds of noctree-families(7) at 1 000 boxes, 200 steps: the
 * counts it publishes, and the same event sequence at the defaults, at
 * N = 5, in rebuild mode and by the exhaustive algorithm (every pair of
 * boxes a candidate: the brute force of the broadphase). */
START_TEST(gas_kinds_known_answers)
{
    static const struct {
        const char *spec;
        size_t begins;
    } kinds[] = {{"mixed:1000", 2290},
                 {"clusters:1000", 45451},
                 {"static:1000", 2079},
                 {"escape:1000", 1977}};
    uint64_t h[4];
    const size_t got = run_family(kinds[_i].spec, NOCT_AUTO, NOCT_MAINTAIN_INCREMENTAL, &h[0]);
    ck_assert_msg(got == kinds[_i].begins, "%s: %zu begins, want %zu", kinds[_i].spec, got,
                  kinds[_i].begins);
    ck_assert_uint_eq(run_family(kinds[_i].spec, 5, NOCT_MAINTAIN_INCREMENTAL, &h[1]), got);
    ck_assert_uint_eq(run_family(kinds[_i].spec, NOCT_AUTO, NOCT_MAINTAIN_REBUILD, &h[2]), got);
    ck_assert_uint_eq(
        run_family(kinds[_i].spec, NOCT_N_EXHAUSTIVE, NOCT_MAINTAIN_INCREMENTAL, &h[3]), got);
    ck_assert(h[0] == h[1] && h[0] == h[2] && h[0] == h[3]);
}
END_TEST

/*
 * The automatic settings are a pure function of what the world holds: two
 * worlds made alike choose alike, build the same tree (the same splits,
 * merges, rebuilds and leaves entered, step by step) and give the same
 * events; and the choice follows the world: a world that grows by more
 * than a factor of 4 between steps chooses again (a rebuild), one that
 * grows by less does not for that reason.
 */
START_TEST(automatic_settings_are_deterministic)
{
    noctWorld *w[2];
    for (int i = 0; i < 2; ++i) {
        noctScene *sc;
        noctError err;
        ck_assert_int_eq(noctSceneFamily("clusters:3000", &sc, &err), NOCT_OK);
        ck_assert_int_eq(noctSceneBuild(sc, &w[i], &err), NOCT_OK);
        noctSceneDestroy(sc);
    }
    for (int s = 0; s < 40; ++s) {
        step_ok(w[0]);
        step_ok(w[1]);
        noctWorldCounters c[2];
        int N[2], depth[2];
        for (int i = 0; i < 2; ++i) {
            noctWorldGetCounters(w[i], &c[i]);
            noctBroadphaseGetSettings(noctWorldBroadphase(w[i]), &N[i], &depth[i]);
        }
        ck_assert_int_eq(N[0], 128);
        ck_assert_int_eq(N[0], N[1]);
        ck_assert_int_eq(depth[0], depth[1]);
        ck_assert_uint_eq(c[0].splits, c[1].splits);
        ck_assert_uint_eq(c[0].merges, c[1].merges);
        ck_assert_uint_eq(c[0].rebuilds, c[1].rebuilds);
        ck_assert_uint_eq(c[0].leaves_entered, c[1].leaves_entered);
        const noctPair *p[2];
        const size_t n = noctWorldBegan(w[0], &p[0]);
        ck_assert_uint_eq(noctWorldBegan(w[1], &p[1]), n);
        ck_assert(n == 0 || memcmp(p[0], p[1], n * sizeof *p[0]) == 0);
    }
    validate_ok(w[0]);
    /* growth: 100 more boxes do not rebuild for the count (the last
     * choice was made for at least 1 365 of the 3 000: the builds at 1, 5,
     * 21, 85, 341 and 1 365 added, and any later growth of the root);
     * 12 500 more (over 4 times any count up to 3 100) do */
    noctMesh *cube;
    ck_assert_int_eq(noctMeshCreateBox(0.25, 0.25, 0.25, &cube, NULL), NOCT_OK);
    noctWorldCounters before, after;
    const double zero[3] = {0, 0, 0};
    for (int phase = 0; phase < 2; ++phase) {
        noctWorldGetCounters(w[0], &before);
        const int more = phase == 0 ? 100 : 12500;
        for (int i = 0; i < more; ++i) {
            /* inside the clusters' container: no root growth */
            const double at[3] = {1 + (i % 20), 1 + (i / 20 % 20), 1 + (i / 400) * 0.5};
            noctObjectId id;
            ck_assert_int_eq(noctWorldAdd(w[0], cube, at, zero, 0, &id, NULL), NOCT_OK);
        }
        step_ok(w[0]);
        noctWorldGetCounters(w[0], &after);
        if (phase == 0)
            ck_assert_uint_eq(after.rebuilds, before.rebuilds);
        else
            ck_assert_uint_gt(after.rebuilds, before.rebuilds);
        validate_ok(w[0]);
    }
    noctWorldDestroy(w[0]);
    noctWorldDestroy(w[1]);
    noctMeshDestroy(cube);
}
END_TEST

/* The facing pair of ring r first overlaps at step 51 + 2 r and reverses. */
START_TEST(planes_timing_and_reversal)
{
    noctMesh *cube;
    ck_assert_int_eq(noctMeshCreateBox(0.5, 0.5, 0.5, &cube, NULL), NOCT_OK);
    noctWorld *w = make_world(5, 6, NOCT_MAINTAIN_INCREMENTAL);
    ck_assert_int_eq(noctWorldAddPlanes(w, 2, cube, NULL), NOCT_OK);
    int first_step[3] = {0, 0, 0};
    for (int s = 1; s <= 200; ++s) {
        step_ok(w);
        const noctPair *p;
        size_t n = noctWorldBegan(w, &p);
        for (size_t i = 0; i < n; ++i) {
            int row = (int)p[i].a.index; /* index = (i + k) (2k+1) + (j + k) */
            int ii = row / 5 - 2, jj = row % 5 - 2;
            int r = abs(ii) > abs(jj) ? abs(ii) : abs(jj);
            if (first_step[r] == 0)
                first_step[r] = s;
            ck_assert_int_eq(s, 51 + 2 * r);
            double d[3];
            ck_assert_int_eq(noctWorldObject(w, p[i].a, NULL, d), NOCT_OK);
            ck_assert(d[0] == -1.0); /* the left cube now moves left */
        }
    }
    ck_assert(first_step[0] == 51 && first_step[1] == 53 && first_step[2] == 55);
    noctWorldDestroy(w);
    noctMeshDestroy(cube);
}
END_TEST

/* ---- random scenes against brute force ------------------------------------ */

static int cmp_pair(const void *x, const void *y)
{
    const noctPair *a = x, *b = y;
    if (a->a.index != b->a.index)
        return a->a.index < b->a.index ? -1 : 1;
    return (a->b.index > b->b.index) - (a->b.index < b->b.index);
}

/* A test's memory of its last brute-force answers (zeroed before the
 * first, brute_memo_free() after the last): a pair whose two objects have
 * the same meshes and positions as at the last step collides as it did
 * then (noctCollide() answers the same for the same arguments), which
 * spares the exact tests of a pile that stands still. */
typedef struct brute_memo {
    int n;
    double (*p)[3];
    const noctMesh **m;
    bool *hit; /* n by n */
} brute_memo;

static void brute_memo_free(brute_memo *b)
{
    free(b->p);
    free(b->m);
    free(b->hit);
}

/* After a step: the world's colliding pairs are the sorted brute-force
 * answer, noctCollide() on every pair of the n objects (or its memo, when
 * memo is not NULL). Returns how many pairs collide. */
static size_t expect_brute_force_memo(noctWorld *w, const noctObjectId *ids,
                                      const noctMesh *const *mesh_of, int n, int step,
                                      brute_memo *memo)
{
    noctPair *want = malloc(((size_t)n * (size_t)n / 2 + 1) * sizeof *want);
    double (*pos)[3] = malloc((size_t)n * sizeof *pos);
    bool *same = calloc((size_t)n, sizeof *same);
    ck_assert(want != NULL && pos != NULL && same != NULL);
    for (int i = 0; i < n; ++i)
        ck_assert_int_eq(noctWorldObject(w, ids[i], pos[i], NULL), NOCT_OK);
    if (memo != NULL && memo->n != n) {
        brute_memo_free(memo);
        memo->n = n;
        memo->p = malloc((size_t)n * sizeof *memo->p);
        memo->m = calloc((size_t)n, sizeof *memo->m);
        memo->hit = calloc((size_t)n * (size_t)n, sizeof *memo->hit);
        ck_assert(memo->p != NULL && memo->m != NULL && memo->hit != NULL);
    } else if (memo != NULL) {
        for (int i = 0; i < n; ++i)
            same[i] = memo->m[i] == mesh_of[i] && memcmp(memo->p[i], pos[i], sizeof pos[i]) == 0;
    }
    size_t nwant = 0;
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j) {
            bool hit;
            if (same[i] && same[j])
                hit = memo->hit[(size_t)i * (size_t)n + (size_t)j];
            else
                ck_assert_int_eq(noctCollide(mesh_of[i], pos[i], mesh_of[j], pos[j],
                                             NOCT_ACCURACY_EXACT, &hit, NULL),
                                 NOCT_OK);
            if (memo != NULL)
                memo->hit[(size_t)i * (size_t)n + (size_t)j] = hit;
            if (hit)
                want[nwant++] = (noctPair){ids[i], ids[j]};
        }
    if (memo != NULL)
        for (int i = 0; i < n; ++i) {
            memcpy(memo->p[i], pos[i], sizeof pos[i]);
            memo->m[i] = mesh_of[i];
        }
    free(pos);
    free(same);
    qsort(want, nwant, sizeof *want, cmp_pair);
    const noctPair *got;
    size_t ngot = noctWorldColliding(w, &got);
    ck_assert_msg(ngot == nwant, "step %d: %zu colliding pairs, brute force %zu", step, ngot,
                  nwant);
    for (size_t i = 0; i < nwant; ++i)
        EXPECT(got[i].a.index == want[i].a.index && got[i].b.index == want[i].b.index);
    free(want);
    return nwant;
}

static size_t expect_brute_force(noctWorld *w, const noctObjectId *ids,
                                 const noctMesh *const *mesh_of, int n, int step)
{
    return expect_brute_force_memo(w, ids, mesh_of, n, step, NULL);
}

START_TEST(random_scenes_against_brute_force)
{
    uint64_t rng = 99 + (uint64_t)_i;
    noctMaintenance mode = _i % 2 ? NOCT_MAINTAIN_REBUILD : NOCT_MAINTAIN_INCREMENTAL;
    int N = 1 + (int)(_i % 4) * 3;
    noctWorld *w = make_world(N, 7, mode);
    enum { NOBJ = 70, NMESH = 5 };
    noctMesh *meshes[NMESH];
    /* From tiny to larger than a node; dyadic sizes so touching happens. */
    static const double half[NMESH] = {0x1p-6, 0.25, 0.5, 1.5, 4};
    for (int m = 0; m < NMESH; ++m)
        ck_assert_int_eq(noctMeshCreateBox(half[m], half[m] * 0.75, half[m] * 0.5,
                                           &meshes[m], NULL), NOCT_OK);
    noctObjectId ids[NOBJ];
    const noctMesh *mesh_of[NOBJ];
    for (int i = 0; i < NOBJ; ++i) {
        bool cluster = i < NOBJ / 2;
        double pos[3], dir[3];
        for (int k = 0; k < 3; ++k) {
            pos[k] = cluster ? (double)test_rand_below(&rng, 16) * 0.25
                             : (double)test_rand_below(&rng, 64) * 0.5 - 16;
            dir[k] = (double)test_rand_below(&rng, 3) - 1;
        }
        if (dir[0] == 0 && dir[1] == 0 && dir[2] == 0)
            dir[0] = 1;
        /* A fifth static; a few fast (several node sizes per step). */
        double speed = i % 5 == 0 ? 0 : i % 7 == 0 ? 3.0 : 0.25;
        mesh_of[i] = meshes[test_rand_below(&rng, NMESH)];
        ck_assert_int_eq(noctWorldAdd(w, mesh_of[i], pos, dir, speed, &ids[i], NULL),
                         NOCT_OK);
    }
    validate_ok(w);
    for (int s = 0; s < 40; ++s) {
        step_ok(w);
        validate_ok(w);
        expect_brute_force(w, ids, mesh_of, NOBJ, s);
    }
    noctWorldCounters c;
    noctWorldGetCounters(w, &c);
    ck_assert_uint_gt(c.colliding_pairs, 0);
    if (mode == NOCT_MAINTAIN_INCREMENTAL) {
        ck_assert_uint_gt(c.neighbor_queries, 0);
        ck_assert_uint_gt(c.leaves_left, 0);
    }
    noctWorldDestroy(w);
    for (int m = 0; m < NMESH; ++m)
        noctMeshDestroy(meshes[m]);
}
END_TEST

/* Small walled worlds with N of 1 to 3: objects keep crossing leaves, so
 * leaves split and merge back all the time, under nodes whose count of
 * distinct objects the world keeps between removals (try_merge). After
 * every step the tree is valid (no mergeable siblings left) and the
 * colliding pairs are brute force's. */
START_TEST(walled_small_worlds_split_and_merge)
{
    uint64_t rng = 7919 * (uint64_t)_i + 1;
    noctWorldDef def = noctDefaultWorldDef();
    def.N = 1 + _i % 3;
    def.max_depth = 3 + _i % 4;
    def.effects |= NOCT_EFFECT_WALLS;
    for (int k = 0; k < 3; ++k) {
        def.walls_lo[k] = 0;
        def.walls_hi[k] = 4 + _i % 5;
    }
    noctWorld *w;
    ck_assert_int_eq(noctWorldCreate(&def, &w, NULL), NOCT_OK);
    enum { NMESH = 3, MAXOBJ = 37 };
    static const double half[NMESH] = {0.1, 0.3, 0.7};
    noctMesh *meshes[NMESH];
    for (int m = 0; m < NMESH; ++m)
        ck_assert_int_eq(noctMeshCreateBox(half[m], half[m], half[m], &meshes[m], NULL),
                         NOCT_OK);
    const int n = 8 + _i % 30;
    noctObjectId ids[MAXOBJ];
    const noctMesh *mesh_of[MAXOBJ];
    for (int i = 0; i < n; ++i) {
        double pos[3], dir[3];
        for (int k = 0; k < 3; ++k) {
            pos[k] = (double)test_rand_below(&rng, 1024) / 1024 * def.walls_hi[k];
            dir[k] = (double)test_rand_below(&rng, 1024) / 1024 - 0.5;
        }
        const double speed = 0.02 + 0.2 * (double)test_rand_below(&rng, 1024) / 1024;
        mesh_of[i] = meshes[test_rand_below(&rng, NMESH)];
        ck_assert_int_eq(noctWorldAdd(w, mesh_of[i], pos, dir, speed, &ids[i], NULL), NOCT_OK);
    }
    for (int s = 0; s < 150; ++s) {
        step_ok(w);
        validate_ok(w);
        expect_brute_force(w, ids, mesh_of, n, s);
    }
    noctWorldCounters c;
    noctWorldGetCounters(w, &c);
    ck_assert_uint_gt(c.merges, 0);
    noctWorldDestroy(w);
    for (int m = 0; m < NMESH; ++m)
        noctMeshDestroy(meshes[m]);
}
END_TEST

/* Slow cubes in a walled box: most leaves' pairs are too far apart to
 * meet for some steps, and the pair search skips them; after every step
 * the colliding pairs still equal the brute-force answer. */
START_TEST(skipped_leaves_against_brute_force)
{
    noctMesh *cube;
    ck_assert_int_eq(noctMeshCreateBox(0.25, 0.25, 0.25, &cube, NULL), NOCT_OK);
    noctWorldDef def = noctDefaultWorldDef();
    def.N = 4;
    def.max_depth = 8;
    def.effects |= NOCT_EFFECT_WALLS;
    for (int k = 0; k < 3; ++k) {
        def.walls_lo[k] = 0;
        def.walls_hi[k] = 10;
    }
    noctWorld *w;
    ck_assert_int_eq(noctWorldCreate(&def, &w, NULL), NOCT_OK);
    enum { NOBJ = 90, STEPS = 150 };
    noctObjectId ids[NOBJ];
    uint64_t rng = 4242;
    for (int i = 0; i < NOBJ; ++i) {
        double pos[3], dir[3];
        for (int k = 0; k < 3; ++k) {
            pos[k] = (double)test_rand_below(&rng, 1000) / 100.0;
            dir[k] = (double)test_rand_below(&rng, 1000) / 500.0 - 1;
        }
        double len = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
        for (int k = 0; k < 3; ++k)
            dir[k] = len > 0 ? dir[k] / len : k == 0;
        double speed = i % 9 == 0 ? 0 : 0.01 + (double)test_rand_below(&rng, 90) / 1000.0;
        ck_assert_int_eq(noctWorldAdd(w, cube, pos, dir, speed, &ids[i], NULL), NOCT_OK);
    }
    const noctMesh *mesh_of[NOBJ];
    for (int i = 0; i < NOBJ; ++i)
        mesh_of[i] = cube;
    for (int s = 0; s < STEPS; ++s) {
        step_ok(w);
        expect_brute_force(w, ids, mesh_of, NOBJ, s);
    }
    noctWorldCounters c;
    noctWorldGetCounters(w, &c);
    /* the scene does what it is for: contacts, and leaves skipped */
    ck_assert_uint_gt(c.colliding_pairs, 20);
    ck_assert_uint_gt(c.leaves_skipped, c.leaves_visited / 4);
    noctWorldDestroy(w);
    noctMeshDestroy(cube);
}
END_TEST

/* A big static cube holding 120 small moving ones: its pairs are a long
 * run of one first object in the colliding list (sorted by qsort, not by
 * insertion), and the list still equals the sorted brute-force answer. */
START_TEST(many_partners_sorted)
{
    noctMesh *big, *small;
    ck_assert_int_eq(noctMeshCreateBox(4, 4, 4, &big, NULL), NOCT_OK);
    ck_assert_int_eq(noctMeshCreateBox(0.3, 0.3, 0.3, &small, NULL), NOCT_OK);
    noctWorld *w = make_world(6, 8, NOCT_MAINTAIN_INCREMENTAL);
    enum { NSMALL = 120 };
    noctObjectId ids[NSMALL + 1];
    const double origin[3] = {0, 0, 0}, x[3] = {1, 0, 0};
    ck_assert_int_eq(noctWorldAdd(w, big, origin, x, 0, &ids[0], NULL), NOCT_OK);
    uint64_t rng = 77;
    for (int i = 1; i <= NSMALL; ++i) {
        double pos[3], dir[3];
        for (int k = 0; k < 3; ++k) {
            pos[k] = 7 * ((double)test_rand_below(&rng, 1000) / 1000.0) - 3.5;
            dir[k] = (double)test_rand_below(&rng, 1000) / 500.0 - 1;
        }
        double len = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
        for (int k = 0; k < 3; ++k)
            dir[k] = len > 0 ? dir[k] / len : k == 0;
        ck_assert_int_eq(noctWorldAdd(w, small, pos, dir, 0.05, &ids[i], NULL), NOCT_OK);
    }
    const noctMesh *mesh_of[NSMALL + 1];
    for (int i = 0; i <= NSMALL; ++i)
        mesh_of[i] = i ? small : big;
    for (int s = 0; s < 5; ++s) {
        step_ok(w);
        /* the big cube's run and more */
        ck_assert_uint_gt(expect_brute_force(w, ids, mesh_of, NSMALL + 1, s), NSMALL);
    }
    noctWorldDestroy(w);
    noctMeshDestroy(big);
    noctMeshDestroy(small);
}
END_TEST

/* Objects that leave the initial root make the tree grow, and collisions
 * out there are still found. */
START_TEST(root_grows)
{
    noctMesh *cube;
    ck_assert_int_eq(noctMeshCreateBox(0.5, 0.5, 0.5, &cube, NULL), NOCT_OK);
    noctWorld *w = make_world(2, 8, NOCT_MAINTAIN_INCREMENTAL);
    const double a[3] = {0, 0, 0}, b[3] = {100, 0, 0}, toward[3] = {1, 0, 0},
                 back[3] = {-1, 0, 0};
    noctObjectId ia, ib;
    ck_assert_int_eq(noctWorldAdd(w, cube, a, toward, 1, &ia, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldAdd(w, cube, b, back, 0, &ib, NULL), NOCT_OK);
    int hits = 0;
    for (int s = 0; s < 120; ++s) {
        step_ok(w);
        validate_ok(w);
        const noctPair *p;
        hits += (int)noctWorldBegan(w, &p);
    }
    ck_assert_int_eq(hits, 1);
    noctWorldCounters c;
    noctWorldGetCounters(w, &c);
    ck_assert_uint_ge(c.rebuilds, 1);
    noctWorldDestroy(w);
    noctMeshDestroy(cube);
}
END_TEST

/* A world of N with static cubes at (-20, -20, -20) and (20, 20, 20),
 * and its root's cube: both statics lie below the root's middle in y
 * (the root reaches at least 20.5 + 41 / 2 above the lower one), so the
 * upper y half holds none. */
static noctWorld *world_with_statics(int N, const noctMesh *cube, double lo[3], double *size)
{
    noctWorld *w = make_world(N, 6, NOCT_MAINTAIN_INCREMENTAL);
    const double s1[3] = {-20, -20, -20}, s2[3] = {20, 20, 20}, d0[3] = {1, 0, 0};
    noctObjectId id;
    ck_assert_int_eq(noctWorldAdd(w, cube, s1, d0, 0, &id, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldAdd(w, cube, s2, d0, 0, &id, NULL), NOCT_OK);
    noctWorldCell(w, noctWorldRoot(w), lo, size, NULL, 0);
    ck_assert(s2[1] + 0.5 < lo[1] + *size / 2);
    return w;
}

/* The box [lo, hi] as a mesh of six quads, its vertices where they are
 * (not about the origin, as noctMeshCreateBox() makes them). */
static noctMesh *make_cuboid(const double lo[3], const double hi[3])
{
    const double v[24] = {lo[0], lo[1], lo[2], hi[0], lo[1], lo[2], hi[0], hi[1], lo[2],
                          lo[0], hi[1], lo[2], lo[0], lo[1], hi[2], hi[0], lo[1], hi[2],
                          hi[0], hi[1], hi[2], lo[0], hi[1], hi[2]};
    const uint32_t sizes[6] = {4, 4, 4, 4, 4, 4};
    const uint32_t idx[24] = {0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4,
                              2, 3, 7, 6, 0, 4, 7, 3, 1, 2, 6, 5};
    noctMesh *m;
    ck_assert_int_eq(noctMeshCreate(v, 8, sizes, 6, idx, &m, NULL), NOCT_OK);
    return m;
}

/* A box whose face lies on the root's face, creeping outward by less than
 * a double a step: at the first step its side still rounds onto the face,
 * at the second it is one double beyond, and the tree must grow then. (A
 * home block taken while the box touched the face would reach out of the
 * root, and the fast test would pass the box outside it.) */
START_TEST(root_face_creeper_grows)
{
    noctMesh *cube;
    ck_assert_int_eq(noctMeshCreateBox(0.5, 0.5, 0.5, &cube, NULL), NOCT_OK);
    double lo[3], size;
    noctWorld *w = world_with_statics(2, cube, lo, &size);
    const double d0[3] = {1, 0, 0};
    noctObjectId id;
    const double x = lo[0] + size; /* the root's +x face */
    /* A unit box [x - 1, x] in x, placed at the origin in x, in the free
     * quarter of the root that straddlers_take_the_fast_path uses. */
    const double y = lo[1] + 0.75 * size, z = lo[2] + 0.25 * size;
    const double slab_lo[3] = {x - 1, -0.5, -0.5}, slab_hi[3] = {x, 0.5, 0.5};
    noctMesh *slab = make_cuboid(slab_lo, slab_hi);
    /* 0.3 of a double at x a step: x + 0.3 u rounds to x, x + 0.6 u to
     * the next double. */
    const double u = nextafter(x, INFINITY) - x, p[3] = {0, y, z};
    ck_assert_int_eq(noctWorldAdd(w, slab, p, d0, 0.3 * u, &id, NULL), NOCT_OK);
    double blo[3], bhi[3];
    for (int s = 1; s <= 3; ++s) {
        step_ok(w);
        validate_ok(w);
        ck_assert_int_eq(noctWorldObjectBox(w, id, blo, bhi), NOCT_OK);
        ck_assert(s == 1 ? bhi[0] == x : bhi[0] > x);
    }
    noctWorldCounters c;
    noctWorldGetCounters(w, &c);
    ck_assert_uint_ge(c.rebuilds, 2); /* the first tree, then the growth */
    noctWorldDestroy(w);
    noctMeshDestroy(slab);
    noctMeshDestroy(cube);
}
END_TEST

/* ---- effects cost nothing when off --------------------------------------- */

START_TEST(effects_off_cost_nothing)
{
    noctMesh *cube;
    ck_assert_int_eq(noctMeshCreateBox(0.5, 0.5, 0.5, &cube, NULL), NOCT_OK);
    for (int variant = 0; variant < 3; ++variant) {
        noctWorldDef def = noctDefaultWorldDef();
        def.effects = variant == 0 ? 0u
                    : variant == 1 ? (unsigned)NOCT_EFFECT_MOTION
                                   : (unsigned)(NOCT_EFFECT_MOTION | NOCT_EFFECT_EVENTS);
        noctWorld *w;
        ck_assert_int_eq(noctWorldCreate(&def, &w, NULL), NOCT_OK);
        ck_assert_int_eq(noctWorldAddPlanes(w, 1, cube, NULL), NOCT_OK);
        noctWorldCounters built; /* building the tree is not a step's work */
        noctWorldGetCounters(w, &built);
        for (int s = 0; s < 80; ++s)
            step_ok(w);
        noctWorldCounters c;
        noctWorldGetCounters(w, &c);
        c.splits -= built.splits;
        c.leaves_entered -= built.leaves_entered;
        c.rebuilds -= built.rebuilds;
        ck_assert_uint_eq(c.steps, 80);
        ck_assert_uint_eq(c.reversals, 0); /* no response in any variant */
        ck_assert(c.seconds_response == 0 || variant == 2);
        if (variant == 0) { /* detection only: nothing moves or is maintained */
            ck_assert_uint_eq(c.moved, 0);
            ck_assert(c.seconds_motion == 0 && c.seconds_maintenance == 0);
            ck_assert_uint_eq(c.inside_fast + c.leaves_left + c.leaves_entered +
                              c.neighbor_queries + c.splits + c.merges, 0);
        } else {
            ck_assert_uint_eq(c.moved, 80 * 18);
        }
        if (variant < 2)
            ck_assert_uint_eq(c.events, 0);
        else
            ck_assert_uint_gt(c.events, 0);
        noctWorldDestroy(w);
    }
    /* A world of static objects does no maintenance either. */
    noctWorld *w = make_world(2, 6, NOCT_MAINTAIN_INCREMENTAL);
    const double p[3] = {0, 0, 0}, d[3] = {1, 0, 0};
    noctObjectId id;
    for (int i = 0; i < 5; ++i)
        ck_assert_int_eq(noctWorldAdd(w, cube, p, d, 0, &id, NULL), NOCT_OK);
    noctWorldCounters built, c;
    noctWorldGetCounters(w, &built);
    for (int s = 0; s < 10; ++s)
        step_ok(w);
    noctWorldGetCounters(w, &c);
    ck_assert_uint_eq(c.moved + c.inside_fast + c.neighbor_queries + c.leaves_left, 0);
    ck_assert_uint_eq(c.splits + c.leaves_entered + c.rebuilds,
                      built.splits + built.leaves_entered + built.rebuilds);
    ck_assert(c.seconds_maintenance == 0);
    noctWorldDestroy(w);
    noctMeshDestroy(cube);
}
END_TEST

/* An object straddling two leaves and moving along their common face
 * keeps the same leaves until it nears the block's far side: the fast
 * test passes it with no neighbor query for exactly the steps its box
 * stays strictly inside the block (counted here from the root's cube);
 * the step it reaches the block's side runs the enter check. */
START_TEST(straddlers_take_the_fast_path)
{
    noctMesh *cube;
    ck_assert_int_eq(noctMeshCreateBox(0.5, 0.5, 0.5, &cube, NULL), NOCT_OK);
    double lo[3], size;
    noctWorld *w = world_with_statics(1, cube, lo, &size);
    const double down[3] = {0, -1, 0};
    noctObjectId id;
    /* On the root's x mid-plane, in the upper y half, the lower z half:
     * two leaves of half the root's size, which hold no static object. */
    const double p[3] = {lo[0] + size / 2, lo[1] + 0.75 * size, lo[2] + size / 4};
    ck_assert_int_eq(noctWorldAdd(w, cube, p, down, 1, &id, NULL), NOCT_OK);
    validate_ok(w);
    double y = p[1], block_lo = lo[1] + size / 2;
    noctWorldCounters before, after;
    int fast_steps = 0;
    for (int s = 0; s < 200; ++s) {
        noctWorldGetCounters(w, &before);
        step_ok(w);
        validate_ok(w);
        noctWorldGetCounters(w, &after);
        y += -1.0;
        bool inside = -0.5 + y > block_lo; /* and below the root's top */
        if (!inside) {
            ck_assert_uint_eq(after.inside_fast, before.inside_fast);
            ck_assert_uint_gt(after.neighbor_queries, before.neighbor_queries);
            break;
        }
        ck_assert_uint_eq(after.inside_fast, before.inside_fast + 1);
        ck_assert_uint_eq(after.neighbor_queries, before.neighbor_queries);
        ck_assert_uint_eq(after.leaves_left + after.leaves_entered,
                          before.leaves_left + before.leaves_entered);
        ++fast_steps;
    }
    /* From y = 0.75 size down to the block's side at 0.5 size + 0.5. */
    ck_assert_int_eq(fast_steps, (int)ceil(size / 4 - 0.5) - 1);
    noctWorldDestroy(w);
    noctMeshDestroy(cube);
}
END_TEST

/* The fast test decides on positions (lib/world.c: home_block), so it
 * must agree with the placed box to the last bit. A box whose mesh lies
 * far from its origin (its low side is fl(m + p), m about 1000) creeps
 * down onto a leaf's face in exact steps, reaching it at step K exactly:
 * a box that touches the face overlaps the leaf beyond, so that step
 * fails the fast test, where every step before it passes. */
START_TEST(fast_test_at_the_rounding_edge)
{
    noctMesh *cube;
    ck_assert_int_eq(noctMeshCreateBox(0.5, 0.5, 0.5, &cube, NULL), NOCT_OK);
    double lo[3], size;
    noctWorld *w = world_with_statics(1, cube, lo, &size); /* upper y half free */
    const double down[3] = {0, -1, 0};
    noctObjectId id;
    const double face = lo[1] + size / 2, m = 1000.3;
    const double far_lo[3] = {-0.5, m, -0.5}, far_hi[3] = {0.5, m + 1, 0.5};
    noctMesh *far = make_cuboid(far_lo, far_hi);
    /* q: the position whose box's low side is the face. Both differences
     * are exact (Sterbenz), and so are the steps of 2^-20 from it. */
    const double q = face - m, speed = 0x1p-20;
    ck_assert(m + q == face);
    enum { K = 6 };
    const double p[3] = {lo[0] + size / 4, q + K * speed, lo[2] + size / 4};
    ck_assert_int_eq(noctWorldAdd(w, far, p, down, speed, &id, NULL), NOCT_OK);
    step_ok(w); /* the first step takes the home block */
    validate_ok(w);
    noctWorldCounters before, after;
    for (int s = 2; s <= K; ++s) {
        noctWorldGetCounters(w, &before);
        step_ok(w);
        validate_ok(w);
        noctWorldGetCounters(w, &after);
        double blo[3], bhi[3];
        ck_assert_int_eq(noctWorldObjectBox(w, id, blo, bhi), NOCT_OK);
        ck_assert(blo[1] == face + (K - s) * speed);
        ck_assert_uint_eq(after.inside_fast, before.inside_fast + (s < K));
        if (s < K)
            ck_assert_uint_eq(after.leaves_entered, before.leaves_entered);
        else /* the leaves below the face */
            ck_assert_uint_gt(after.leaves_entered, before.leaves_entered);
    }
    noctWorldDestroy(w);
    noctMeshDestroy(far);
    noctMeshDestroy(cube);
}
END_TEST

/* An object that moves beyond NOCT_MAX_COORDINATE stops the step with an
 * error, in both maintenance modes. Its leaf reaches far beyond the
 * limit, so its fast test would pass there (home_of() keeps the
 * positions it passes within the limit). */
START_TEST(runaway_object_is_an_error)
{
    noctMesh *cube;
    ck_assert_int_eq(noctMeshCreateBox(0.5, 0.5, 0.5, &cube, NULL), NOCT_OK);
    for (int mode = 0; mode < 2; ++mode) {
        noctWorld *w = make_world(1, 6, mode ? NOCT_MAINTAIN_REBUILD : NOCT_MAINTAIN_INCREMENTAL);
        const double d0[3] = {1, 0, 0}, s1[3] = {-0.9e100, 0, 0}, s2[3] = {0, 0.9e100, 0};
        const double speed = 1e86;
        double x = NOCT_MAX_COORDINATE - 3 * speed;
        const double p[3] = {x, 0, 0};
        noctObjectId id;
        ck_assert_int_eq(noctWorldAdd(w, cube, s1, d0, 0, &id, NULL), NOCT_OK);
        ck_assert_int_eq(noctWorldAdd(w, cube, s2, d0, 0, &id, NULL), NOCT_OK);
        ck_assert_int_eq(noctWorldAdd(w, cube, p, d0, speed, &id, NULL), NOCT_OK);
        int s = 0;
        for (;; ++s) {
            x += speed;
            noctError err;
            noctStatus st = noctWorldStep(w, &err);
            if (x > NOCT_MAX_COORDINATE) {
                ck_assert_int_eq(st, NOCT_ERR_TOO_LARGE);
                ck_assert_msg(strstr(err.message, "object 2 would move beyond") != NULL, "%s",
                              err.message);
                /* Rolled back: the object is where the last step left it,
                 * the world is whole, and a retry fails the same way. */
                double at[3];
                ck_assert_int_eq(noctWorldObject(w, id, at, NULL), NOCT_OK);
                ck_assert(at[0] == x - speed && at[1] == 0 && at[2] == 0);
                validate_ok(w);
                ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_ERR_TOO_LARGE);
                ck_assert_int_eq(noctWorldObject(w, id, at, NULL), NOCT_OK);
                ck_assert(at[0] == x - speed);
                break;
            }
            ck_assert_msg(st == NOCT_OK, "step: %s", err.message);
            validate_ok(w);
        }
        ck_assert_int_ge(s, 2); /* it took the fast path before */
        noctWorldDestroy(w);
    }
    noctMeshDestroy(cube);
}
END_TEST

/* Thin plates closing at 2 per step skip past each other between steps;
 * with sub-steps they meet once and turn back. */
START_TEST(substeps_stop_tunnelling)
{
    noctMesh *plate;
    ck_assert_int_eq(noctMeshCreateBox(0.1, 2, 2, &plate, NULL), NOCT_OK);
    for (int with = 0; with < 2; ++with) {
        noctWorldDef def = noctDefaultWorldDef();
        if (with)
            def.effects |= NOCT_EFFECT_SUBSTEP;
        noctWorld *w;
        ck_assert_int_eq(noctWorldCreate(&def, &w, NULL), NOCT_OK);
        const double pa[3] = {-5, 0, 0}, pb[3] = {5.3, 0, 0};
        const double right[3] = {1, 0, 0}, left[3] = {-1, 0, 0};
        noctObjectId a, b;
        ck_assert_int_eq(noctWorldAdd(w, plate, pa, right, 1, &a, NULL), NOCT_OK);
        ck_assert_int_eq(noctWorldAdd(w, plate, pb, left, 1, &b, NULL), NOCT_OK);
        ck_assert(noctWorldMaxStepRatio(w) == 5);
        size_t begins = 0;
        for (int s = 0; s < 10; ++s) {
            step_ok(w);
            validate_ok(w);
            const noctPair *p;
            begins += noctWorldBegan(w, &p);
        }
        noctWorldCounters c;
        noctWorldGetCounters(w, &c);
        double pos[3];
        ck_assert_int_eq(noctWorldObject(w, a, pos, NULL), NOCT_OK);
        if (with) {
            ck_assert_uint_eq(begins, 1);
            ck_assert_uint_eq(c.substeps, 10 * 10);
            ck_assert(pos[0] < -3); /* it turned back */
        } else {
            ck_assert_uint_eq(begins, 0); /* tunnelled */
            ck_assert_uint_eq(c.substeps, 0);
            ck_assert(pos[0] > 4);
        }
        noctWorldDestroy(w);
    }
    noctMeshDestroy(plate);
}
END_TEST

/* ---- bounded work whatever the overlap --------------------------------------- */

/* Walk the tree: the number of nodes, and per object (by index, below
 * max_index) the number of leaves that list it. */
static size_t count_tree(noctWorld *w, octNode *n, size_t *spans, size_t max_index)
{
    if (octIsSplit(n)) {
        size_t nodes = 1;
        for (int i = 0; i < 8; ++i)
            nodes += count_tree(w, octChild(n, (octDirection)(OCT_LDB + i)), spans, max_index);
        return nodes;
    }
    size_t count = noctWorldCell(w, n, NULL, NULL, NULL, 0);
    noctObjectId *got = malloc((count + 1) * sizeof *got);
    ck_assert(got != NULL);
    noctWorldCell(w, n, NULL, NULL, got, count);
    for (size_t j = 0; j < count; ++j) {
        ck_assert_uint_lt(got[j].index, max_index);
        ++spans[got[j].index];
    }
    free(got);
    return 1;
}

/* The largest number of leaves any object is in; the tree's nodes in
 * *nodes. */
static size_t most_spans(noctWorld *w, size_t max_index, size_t *nodes)
{
    size_t *spans = calloc(max_index, sizeof *spans), most = 0;
    ck_assert(spans != NULL);
    *nodes = count_tree(w, noctWorldRoot(w), spans, max_index);
    for (size_t i = 0; i < max_index; ++i)
        most = spans[i] > most ? spans[i] : most;
    free(spans);
    return most;
}

/* Objects stacked at one point, two cubes sharing a face and three boxes
 * moving through the stack, at the defaults, at N = 1 and at max-depth
 * 40: leaves are never split for objects larger than their children, so
 * the tree stays small and every unit box is in at most 27 leaves (it
 * overlaps at most 3 of the leaves of at least its size on each axis).
 * Before the rule, the defaults hung at the 11th coincident box and N = 1
 * split the shared face down to the maximum depth. Colliding pairs
 * against brute force at every step. */
START_TEST(stacks_stop_splitting)
{
    static const int config[][2] = {{10, 10}, {1, 12}, {1, 40}, {3, 40}};
    const int N = config[_i][0], depth = config[_i][1];
    noctMesh *cube;
    ck_assert_int_eq(noctMeshCreateBox(0.5, 0.5, 0.5, &cube, NULL), NOCT_OK);
    noctWorld *w = make_world(N, depth, NOCT_MAINTAIN_INCREMENTAL);
    enum { STACK = 60, n = STACK + 5 };
    noctObjectId ids[n];
    const noctMesh *mesh_of[n];
    const double zero[3] = {0, 0, 0};
    for (int i = 0; i < n; ++i) {
        const double stack[3] = {0.3, 0.3, 0.3}, face_a[3] = {10, 0, 0},
                     face_b[3] = {11, 0, 0};
        const double mover[3] = {-6.0 - i % 3, 0.1 * (i % 3), 0.2};
        const double right[3] = {1, 0, 0};
        const double *at = i < STACK ? stack : i == STACK ? face_a : i == STACK + 1 ? face_b
                                                                                    : mover;
        const double speed = i < STACK + 2 ? 0 : 0.25;
        ck_assert_int_eq(noctWorldAdd(w, cube, at, speed ? right : zero, speed, &ids[i], NULL),
                         NOCT_OK);
        mesh_of[i] = cube;
    }
    brute_memo memo = {0}; /* (the stack stands still) */
    for (int s = 0; s < 60; ++s) {
        step_ok(w);
        validate_ok(w);
        expect_brute_force_memo(w, ids, mesh_of, n, s, &memo);
        size_t nodes, most = most_spans(w, n, &nodes);
        ck_assert_uint_le(most, 27);
        ck_assert_uint_le(nodes, 2000);
    }
    brute_memo_free(&memo);
    noctWorldDestroy(w);
    noctMeshDestroy(cube);
}
END_TEST

/* Many coincident objects at N = 1 and max-depth 40: each is added into
 * the few leaves of its size (no split can part them), and removed again,
 * leaving an empty, valid world; fewer, stepped, all collide. */
START_TEST(coincident_objects_add_and_remove)
{
    noctMesh *cube;
    ck_assert_int_eq(noctMeshCreateBox(0.5, 0.5, 0.5, &cube, NULL), NOCT_OK);
    noctWorld *w = make_world(1, 40, NOCT_MAINTAIN_INCREMENTAL);
    enum { n = 20000 };
    noctObjectId *ids = malloc(n * sizeof *ids);
    ck_assert(ids != NULL);
    const double at[3] = {0.25, 0.25, 0.25}, zero[3] = {0, 0, 0};
    for (int i = 0; i < n; ++i)
        ck_assert_int_eq(noctWorldAdd(w, cube, at, zero, 0, &ids[i], NULL), NOCT_OK);
    validate_ok(w);
    size_t nodes, most = most_spans(w, n, &nodes);
    ck_assert_uint_le(most, 27);
    ck_assert_uint_le(nodes, 1 + 8 * 8);
    for (int i = 0; i < n; ++i)
        ck_assert_int_eq(noctWorldRemove(w, ids[i], NULL), NOCT_OK);
    validate_ok(w);
    ck_assert_uint_eq(noctWorldObjectCount(w), 0);
    /* fewer, stepped: every pair collides */
    enum { m = 1200 };
    for (int i = 0; i < m; ++i)
        ck_assert_int_eq(noctWorldAdd(w, cube, at, zero, 0, &ids[i], NULL), NOCT_OK);
    step_ok(w);
    validate_ok(w);
    const noctPair *p;
    ck_assert_uint_eq(noctWorldColliding(w, &p), (size_t)m * (m - 1) / 2);
    free(ids);
    noctWorldDestroy(w);
    noctMeshDestroy(cube);
}
END_TEST

/* A k x k x k pile of unit cubes, each touching its neighbours (closed
 * solids: a shared face, edge or corner counts), at N = 1 and max-depth
 * 40: ((3k - 2)^3 - k^3) / 2 colliding pairs, every cube in at most 27
 * leaves. */
START_TEST(touching_pile)
{
    noctMesh *cube;
    ck_assert_int_eq(noctMeshCreateBox(0.5, 0.5, 0.5, &cube, NULL), NOCT_OK);
    noctWorld *w = make_world(1, 40, NOCT_MAINTAIN_INCREMENTAL);
    enum { k = 7, n = k * k * k };
    const double zero[3] = {0, 0, 0};
    noctObjectId id;
    for (int i = 0; i < n; ++i) {
        const double at[3] = {i % k + 0.5, i / k % k + 0.5, i / (k * k) + 0.5};
        ck_assert_int_eq(noctWorldAdd(w, cube, at, zero, 0, &id, NULL), NOCT_OK);
    }
    step_ok(w);
    validate_ok(w);
    const noctPair *p;
    ck_assert_uint_eq(noctWorldColliding(w, &p),
                      ((3 * k - 2) * (3 * k - 2) * (3 * k - 2) - n) / 2);
    size_t nodes, most = most_spans(w, n, &nodes);
    ck_assert_uint_le(most, 27);
    noctWorldDestroy(w);
    noctMeshDestroy(cube);
}
END_TEST

/* An object far away grows the root; once it is gone the root shrinks
 * back around the others at the next step, so they are in leaves of
 * their own size again rather than in one leaf of the maximum depth. */
START_TEST(root_shrinks_back)
{
    noctMesh *cube;
    ck_assert_int_eq(noctMeshCreateBox(0.5, 0.5, 0.5, &cube, NULL), NOCT_OK);
    noctWorld *w = make_world(10, 10, NOCT_MAINTAIN_INCREMENTAL);
    const double zero[3] = {0, 0, 0};
    noctObjectId id;
    for (int i = 0; i < 200; ++i) {
        const double at[3] = {3.0 * (i % 10), 3.0 * (i / 10), 0};
        ck_assert_int_eq(noctWorldAdd(w, cube, at, zero, 0, &id, NULL), NOCT_OK);
    }
    double lo[3], size_before, size;
    noctWorldCell(w, noctWorldRoot(w), lo, &size_before, NULL, 0);
    ck_assert(size_before < 1000);
    const double far[3] = {1e50, 0, 0};
    ck_assert_int_eq(noctWorldAdd(w, cube, far, zero, 0, &id, NULL), NOCT_OK);
    step_ok(w);
    noctWorldCell(w, noctWorldRoot(w), lo, &size, NULL, 0);
    ck_assert(size > 1e50);
    ck_assert_int_eq(noctWorldRemove(w, id, NULL), NOCT_OK);
    step_ok(w);
    validate_ok(w);
    noctWorldCell(w, noctWorldRoot(w), lo, &size, NULL, 0);
    ck_assert_msg(size == size_before, "root %g, was %g", size, size_before);
    /* and it takes part again: the leaves are small */
    size_t nodes, most = most_spans(w, 200, &nodes);
    ck_assert_uint_le(most, 8);
    ck_assert_uint_gt(nodes, 8);
    noctWorldDestroy(w);
    noctMeshDestroy(cube);
}
END_TEST

/* Sub-stepping has a documented cap: a step that would need more than
 * NOCT_MAX_SUBSTEPS fails, naming the object, and moves nothing (before,
 * the cap was silent and the cubes passed through each other). Just
 * under the cap the cubes meet. */
START_TEST(substep_cap_is_a_status)
{
    noctMesh *cube;
    ck_assert_int_eq(noctMeshCreateBox(0.5, 0.5, 0.5, &cube, NULL), NOCT_OK);
    for (int fast = 0; fast < 2; ++fast) {
        noctWorldDef def = noctDefaultWorldDef();
        def.effects |= NOCT_EFFECT_SUBSTEP;
        noctWorld *w;
        ck_assert_int_eq(noctWorldCreate(&def, &w, NULL), NOCT_OK);
        const double speed = fast ? 1e7 : 2e5;
        const double pa[3] = {-speed, 0, 0}, pb[3] = {speed + 0.5, 0, 0};
        const double right[3] = {1, 0, 0}, left[3] = {-1, 0, 0};
        noctObjectId a, b;
        ck_assert_int_eq(noctWorldAdd(w, cube, pa, right, speed, &a, NULL), NOCT_OK);
        ck_assert_int_eq(noctWorldAdd(w, cube, pb, left, speed, &b, NULL), NOCT_OK);
        noctError err;
        noctStatus st = noctWorldStep(w, &err);
        double pos[3];
        ck_assert_int_eq(noctWorldObject(w, a, pos, NULL), NOCT_OK);
        if (fast) {
            ck_assert_int_eq(st, NOCT_ERR_TOO_LARGE);
            ck_assert_msg(strstr(err.message, "object 0 moves") != NULL, "%s", err.message);
            ck_assert(pos[0] == -speed);
        } else {
            ck_assert_msg(st == NOCT_OK, "%s", err.message);
            const noctPair *p;
            size_t began = noctWorldBegan(w, &p);
            ck_assert_uint_eq(began, 1);
        }
        noctWorldDestroy(w);
    }
    noctMeshDestroy(cube);
}
END_TEST

/* Directions: a static object's is ignored (NaN included); a moving
 * one's is any finite non-zero vector, however large or small. */
START_TEST(directions_whole_range)
{
    noctMesh *cube;
    ck_assert_int_eq(noctMeshCreateBox(0.5, 0.5, 0.5, &cube, NULL), NOCT_OK);
    noctWorld *w = make_world(10, 10, NOCT_MAINTAIN_INCREMENTAL);
    const double at[3] = {0, 0, 0}, nan3[3] = {NAN, 0, 0};
    noctObjectId id;
    ck_assert_int_eq(noctWorldAdd(w, cube, at, nan3, 0, &id, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldAdd(w, cube, at, nan3, 1, &id, NULL), NOCT_ERR_NONFINITE);
    static const double dirs[][3] = {{1e200, 0, 0},  {1e-200, 0, 0}, {4.9e-324, 0, 0},
                                     {3e300, 4e300, 0}, {3e-310, 4e-310, 0}, {0, 0, -1e308}};
    static const double unit[][3] = {{1, 0, 0}, {1, 0, 0}, {1, 0, 0},
                                     {0.6, 0.8, 0}, {0.6, 0.8, 0}, {0, 0, -1}};
    for (size_t i = 0; i < sizeof dirs / sizeof *dirs; ++i) {
        const double p[3] = {10.0 * (double)(i + 1), 0, 0};
        noctError err;
        ck_assert_msg(noctWorldAdd(w, cube, p, dirs[i], 1, &id, &err) == NOCT_OK, "%zu: %s", i,
                      err.message);
        double d[3];
        ck_assert_int_eq(noctWorldObject(w, id, NULL, d), NOCT_OK);
        for (int k = 0; k < 3; ++k)
            ck_assert_msg(fabs(d[k] - unit[i][k]) < 1e-15, "%zu: %g", i, d[k]);
    }
    const double zero[3] = {0, 0, 0};
    ck_assert_int_eq(noctWorldAdd(w, cube, at, zero, 1, &id, NULL), NOCT_ERR_INVALID);
    noctWorldDestroy(w);
    noctMeshDestroy(cube);
}
END_TEST

/* A broken structure is reported as such (NOCT_ERR_INVARIANT), not as a
 * numerical failure. The test breaks one on purpose: the root's cell. */
START_TEST(validate_reports_invariant)
{
    noctMesh *cube;
    ck_assert_int_eq(noctMeshCreateBox(0.5, 0.5, 0.5, &cube, NULL), NOCT_OK);
    noctWorld *w = make_world(10, 10, NOCT_MAINTAIN_INCREMENTAL);
    const double at[3] = {0, 0, 0};
    noctObjectId id;
    ck_assert_int_eq(noctWorldAdd(w, cube, at, at, 0, &id, NULL), NOCT_OK);
    validate_ok(w);
    octNode *root = noctWorldRoot(w);
    void *cell = octSwapData(root, NULL);
    noctError err;
    ck_assert_int_eq(noctWorldValidate(w, &err), NOCT_ERR_INVARIANT);
    ck_assert_int_eq(err.status, NOCT_ERR_INVARIANT);
    ck_assert_str_eq(noctStatusString(NOCT_ERR_INVARIANT), "internal invariant broken");
    octSwapData(root, cell);
    validate_ok(w);
    noctWorldDestroy(w);
    noctMeshDestroy(cube);
}
END_TEST

/* ---- handles and bad input -------------------------------------------------- */

START_TEST(handles_and_bad_input)
{
    noctMesh *cube;
    ck_assert_int_eq(noctMeshCreateBox(0.5, 0.5, 0.5, &cube, NULL), NOCT_OK);
    noctWorld *w = make_world(2, 6, NOCT_MAINTAIN_INCREMENTAL);
    const double p[3] = {0, 0, 0}, q[3] = {0.5, 0, 0}, d[3] = {1, 0, 0};
    noctObjectId a, b, c;
    ck_assert_int_eq(noctWorldAdd(w, cube, p, d, 0, &a, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldAdd(w, cube, q, d, 0, &b, NULL), NOCT_OK);
    step_ok(w);
    const noctPair *pairs;
    ck_assert_uint_eq(noctWorldColliding(w, &pairs), 1);
    ck_assert_int_eq(noctWorldRemove(w, a, NULL), NOCT_OK);
    /* the last step's lists stay, a's pair with its stale handle */
    ck_assert_uint_eq(noctWorldColliding(w, &pairs), 1);
    ck_assert_uint_eq(pairs[0].a.generation, a.generation);
    ck_assert_int_eq(noctWorldRemove(w, a, NULL), NOCT_ERR_INVALID);
    ck_assert_int_eq(noctWorldObject(w, a, NULL, NULL), NOCT_ERR_INVALID);
    ck_assert_int_eq(noctWorldAdd(w, cube, p, d, 0, &c, NULL), NOCT_OK);
    ck_assert_uint_eq(c.index, a.index);          /* the slot is reused */
    ck_assert_uint_ne(c.generation, a.generation); /* with a new generation */
    ck_assert_int_eq(noctWorldObject(w, a, NULL, NULL), NOCT_ERR_INVALID);
    ck_assert_int_eq(noctWorldObject(w, c, NULL, NULL), NOCT_OK);
    noctObjectId bogus = {999, 1};
    ck_assert_int_eq(noctWorldRemove(w, bogus, NULL), NOCT_ERR_INVALID);
    validate_ok(w);
    /* the next step ends a's pair and begins c's, in a's old slot */
    step_ok(w);
    ck_assert_uint_eq(noctWorldEnded(w, &pairs), 1);
    ck_assert_uint_eq(pairs[0].a.index, a.index);
    ck_assert_uint_eq(pairs[0].a.generation, a.generation);
    ck_assert_uint_eq(pairs[0].b.generation, b.generation);
    ck_assert_uint_eq(noctWorldBegan(w, &pairs), 1);
    ck_assert_uint_eq(pairs[0].a.generation, c.generation);
    ck_assert_uint_eq(noctWorldColliding(w, &pairs), 1);
    noctError err;
    const double nan3[3] = {NAN, 0, 0}, zero[3] = {0, 0, 0}, far[3] = {1e200, 0, 0};
    ck_assert_int_eq(noctWorldAdd(w, cube, nan3, d, 1, &c, &err), NOCT_ERR_NONFINITE);
    ck_assert_int_eq(noctWorldAdd(w, cube, p, zero, 1, &c, &err), NOCT_ERR_INVALID);
    ck_assert_int_eq(noctWorldAdd(w, cube, p, d, -1, &c, &err), NOCT_ERR_INVALID);
    ck_assert_int_eq(noctWorldAdd(w, cube, p, d, INFINITY, &c, &err), NOCT_ERR_NONFINITE);
    ck_assert_int_eq(noctWorldAdd(w, cube, far, d, 1, &c, &err), NOCT_ERR_TOO_LARGE);
    ck_assert_int_eq(noctWorldAddPlanes(w, -1, cube, &err), NOCT_ERR_INVALID);
    ck_assert_uint_eq(noctWorldObjectCount(w), 2);
    noctWorldDestroy(w);

    noctWorldDef def = noctDefaultWorldDef();
    def.N = -1;
    ck_assert_int_eq(noctWorldCreate(&def, &w, &err), NOCT_ERR_INVALID);
    ck_assert_ptr_null(w);
    def = noctDefaultWorldDef();
    def.max_depth = 41;
    ck_assert_int_eq(noctWorldCreate(&def, &w, &err), NOCT_ERR_INVALID);
    def = noctDefaultWorldDef();
    def.effects = 1u << 9;
    ck_assert_int_eq(noctWorldCreate(&def, &w, &err), NOCT_ERR_INVALID);
    noctMeshDestroy(cube);
}
END_TEST

/* ---- inspecting the tree: noctWorldCell, noctWorldObjectBox, the printer ---- */

/* Check every leaf below n against a brute force over the objects' boxes;
 * return the number of leaves. */
static size_t check_leaves(noctWorld *w, octNode *n, const noctObjectId *ids, size_t nids)
{
    if (octIsSplit(n)) {
        ck_assert_uint_eq(noctWorldCell(w, n, NULL, NULL, NULL, 0), 0);
        size_t leaves = 0;
        for (int i = 0; i < 8; ++i)
            leaves += check_leaves(w, octChild(n, (octDirection)(OCT_LDB + i)), ids, nids);
        return leaves;
    }
    double lo[3], size;
    noctObjectId got[256];
    size_t count = noctWorldCell(w, n, lo, &size, got, 256);
    ck_assert_uint_le(count, 256);
    size_t expected = 0;
    for (size_t i = 0; i < nids; ++i) {
        double blo[3], bhi[3];
        ck_assert_int_eq(noctWorldObjectBox(w, ids[i], blo, bhi), NOCT_OK);
        bool overlap = true;
        for (int k = 0; k < 3; ++k)
            overlap &= bhi[k] >= lo[k] && blo[k] <= lo[k] + size;
        if (!overlap)
            continue;
        ++expected;
        bool listed = false;
        for (size_t j = 0; j < count; ++j)
            listed |= got[j].index == ids[i].index && got[j].generation == ids[i].generation;
        ck_assert_msg(listed, "object %u overlaps a leaf but is not listed", ids[i].index);
    }
    ck_assert_uint_eq(count, expected);
    return 1;
}

START_TEST(inspect_tree)
{
    noctWorld *w = make_world(2, 6, NOCT_MAINTAIN_INCREMENTAL);
    noctMesh *cube;
    noctError err;
    ck_assert_int_eq(noctMeshCreateBox(0.5, 0.5, 0.5, &cube, &err), NOCT_OK);
    noctObjectId ids[40];
    uint64_t rng = 7;
    for (size_t i = 0; i < 40; ++i) {
        double p[3], d[3] = {1, 0, 0};
        for (int k = 0; k < 3; ++k)
            p[k] = 20 * (double)(test_rand(&rng) >> 11) * 0x1p-53;
        ck_assert_int_eq(noctWorldAdd(w, cube, p, d, 0.3, &ids[i], &err), NOCT_OK);
    }
    for (int s = 0; s < 5; ++s) {
        step_ok(w);
        ck_assert_uint_gt(check_leaves(w, noctWorldRoot(w), ids, 40), 8);
    }
    /* A box is the mesh's box placed at the position. */
    double pos[3], lo[3], hi[3];
    ck_assert_int_eq(noctWorldObject(w, ids[3], pos, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldObjectBox(w, ids[3], lo, hi), NOCT_OK);
    for (int k = 0; k < 3; ++k) {
        ck_assert_double_eq(lo[k], pos[k] - 0.5);
        ck_assert_double_eq(hi[k], pos[k] + 0.5);
    }
    ck_assert_int_eq(noctWorldRemove(w, ids[3], NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldObjectBox(w, ids[3], lo, hi), NOCT_ERR_INVALID);
    noctWorldDestroy(w);

    /* The printer, through octPrint, on a one-leaf world. */
    w = make_world(10, 6, NOCT_MAINTAIN_INCREMENTAL);
    double p0[3] = {0, 0, 0}, p1[3] = {0.75, 0, 0}, d[3] = {1, 0, 0};
    noctObjectId a, b;
    ck_assert_int_eq(noctWorldAdd(w, cube, p0, d, 0, &a, &err), NOCT_OK);
    ck_assert_int_eq(noctWorldAdd(w, cube, p1, d, 0, &b, &err), NOCT_OK);
    step_ok(w);
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    ck_assert_ptr_nonnull(f);
    ck_assert(octPrint(noctWorldRoot(w), noctWorldPrintCell, f));
    fclose(f);
    double rlo[3], rsize;
    ck_assert_uint_eq(noctWorldCell(w, noctWorldRoot(w), rlo, &rsize, NULL, 0), 2);
    char expected[256];
    snprintf(expected, sizeof expected, "OMEGA 0: lo (%.10g, %.10g, %.10g) size %.10g; "
             "objects %u %u\n", rlo[0], rlo[1], rlo[2], rsize, a.index, b.index);
    ck_assert_str_eq(text, expected);
    /* The root holds both boxes. */
    ck_assert(rlo[0] <= -0.5 && rlo[0] + rsize >= 1.25);
    free(text);
    noctWorldDestroy(w);
    noctMeshDestroy(cube);
}
END_TEST

/* The first leaf below n, depth first. */
static octNode *first_leaf(octNode *n)
{
    while (octIsSplit(n))
        n = octChild(n, OCT_LDB);
    return n;
}

/*
 * Handles through churn. Objects of four sizes, in random order, move
 * along the axes; every few steps a sixth are removed and others added
 * (reusing indices). After every step: the tree validates, the colliding
 * pairs are the brute-force answer, the leaves list exactly the handles
 * whose boxes overlap them (and the printer names the same), each handle's
 * box has its own mesh's size, removed handles are refused, and every
 * position equals the test's own run of the dynamics (p += v, v reversed
 * once per step by each begin event): a reversal given to the wrong
 * object would show.
 */
START_TEST(handles_through_churn)
{
    enum { NOBJ = 60, NMESH = 4 };
    static const double half[NMESH] = {0.25, 0.375, 0.5, 0.75};
    noctMesh *meshes[NMESH];
    for (int m = 0; m < NMESH; ++m)
        ck_assert_int_eq(noctMeshCreateBox(half[m], half[m], half[m], &meshes[m], NULL),
                         NOCT_OK);
    noctWorld *w = make_world(3, 7, NOCT_MAINTAIN_INCREMENTAL);
    noctObjectId ids[NOBJ], gone[NOBJ * 2];
    const noctMesh *mesh_of[NOBJ];
    int size_of[NOBJ];
    double pos[NOBJ][3], vel[NOBJ][3];
    size_t ngone = 0;
    uint64_t rng = 2026;
    for (int i = 0; i < NOBJ; ++i) {
        int m = (int)test_rand_below(&rng, NMESH), axis = (int)test_rand_below(&rng, 3);
        double dir[3] = {0, 0, 0};
        dir[axis] = test_rand_below(&rng, 2) ? 1 : -1;
        const double speed = i % 6 == 0 ? 0 : 0.125;
        for (int k = 0; k < 3; ++k) {
            pos[i][k] = (double)test_rand_below(&rng, 64) * 0.25 - 8;
            vel[i][k] = speed * dir[k];
        }
        size_of[i] = m;
        mesh_of[i] = meshes[m];
        ck_assert_int_eq(noctWorldAdd(w, meshes[m], pos[i], dir, speed, &ids[i], NULL),
                         NOCT_OK);
    }
    for (int s = 1; s <= 60; ++s) {
        step_ok(w);
        validate_ok(w);
        for (int i = 0; i < NOBJ; ++i)
            for (int k = 0; k < 3; ++k)
                pos[i][k] += vel[i][k];
        const noctPair *p;
        size_t n = noctWorldBegan(w, &p);
        bool turned[NOBJ] = {false};
        for (size_t e = 0; e < n; ++e)
            for (int i = 0; i < NOBJ; ++i)
                if ((ids[i].index == p[e].a.index || ids[i].index == p[e].b.index) &&
                    !turned[i]) {
                    turned[i] = true;
                    for (int k = 0; k < 3; ++k)
                        vel[i][k] = -vel[i][k];
                }
        expect_brute_force(w, ids, mesh_of, NOBJ, s);
        check_leaves(w, noctWorldRoot(w), ids, NOBJ);
        for (int i = 0; i < NOBJ; ++i) {
            double q[3], lo[3], hi[3];
            ck_assert_int_eq(noctWorldObject(w, ids[i], q, NULL), NOCT_OK);
            ck_assert_int_eq(noctWorldObjectBox(w, ids[i], lo, hi), NOCT_OK);
            for (int k = 0; k < 3; ++k) {
                EXPECT(q[k] == pos[i][k]);
                EXPECT(hi[k] - lo[k] == 2 * half[size_of[i]]);
            }
        }
        for (size_t g = 0; g < ngone; ++g) {
            double q[3];
            ck_assert_int_eq(noctWorldObject(w, gone[g], q, NULL), NOCT_ERR_INVALID);
        }
        /* The printer names a leaf's objects as noctWorldCell() does. */
        octNode *leaf = first_leaf(noctWorldRoot(w));
        noctObjectId in[NOBJ];
        size_t count = noctWorldCell(w, leaf, NULL, NULL, in, NOBJ);
        char *text = NULL;
        size_t len = 0;
        FILE *f = open_memstream(&text, &len);
        ck_assert_ptr_nonnull(f);
        noctWorldPrintCell(f, octData(leaf));
        fclose(f);
        const char *list = strstr(text, "; objects");
        ck_assert(count == 0 ? list == NULL : list != NULL);
        for (size_t j = 0; j < count; ++j) {
            unsigned got;
            int used;
            ck_assert_int_eq(sscanf(list + (j == 0 ? 9 : 0), " %u%n", &got, &used), 1);
            ck_assert_uint_eq(got, in[j].index);
            list += (j == 0 ? 9 : 0) + used;
        }
        free(text);
        if (s % 6 == 0)
            for (int r = 0; r < NOBJ / 6; ++r) {
                int i = (int)test_rand_below(&rng, NOBJ);
                ck_assert_int_eq(noctWorldRemove(w, ids[i], NULL), NOCT_OK);
                gone[ngone++] = ids[i];
                ck_assert_int_eq(noctWorldAdd(w, mesh_of[i], pos[i], (double[3]){1, 0, 0},
                                              0.125, &ids[i], NULL),
                                 NOCT_OK);
                vel[i][0] = 0.125;
                vel[i][1] = vel[i][2] = 0;
            }
    }
    noctWorldCounters c;
    noctWorldGetCounters(w, &c);
    ck_assert_uint_gt(c.reversals, 0);
    noctWorldDestroy(w);
    for (int m = 0; m < NMESH; ++m)
        noctMeshDestroy(meshes[m]);
}
END_TEST

#ifndef NOCT_EFFICIENT
START_TEST(die_null_world)
{
    switch (_i) {
    case 0: noctWorldStep(NULL, NULL); break;
    case 1: noctWorldCreate(NULL, NULL, NULL); break;
    default: noctWorldValidate(NULL, NULL); break;
    }
}
END_TEST
#endif

int main(void)
{
    Suite *s = suite_create("world");
    TCase *tc = test_case(s, "planes", 600, "slow");
    tcase_add_loop_test(tc, planes_counts_across_N_and_modes, 0, 6);
    tcase_add_loop_test(tc, planes_t20_t30, 0, 2);
    tcase_add_test(tc, gas_1000_known_answer);
    tcase_add_test(tc, gas_10000_known_answer);
    tcase_add_loop_test(tc, gas_kinds_known_answers, 0, 4);
    tcase_add_test(tc, planes_timing_and_reversal);
    tc = test_case(s, "random scenes", 300, NULL);
    tcase_add_loop_test(tc, random_scenes_against_brute_force, 0, 2);
    add_tests(tc, root_grows, automatic_settings_are_deterministic, root_face_creeper_grows,
              many_partners_sorted, skipped_leaves_against_brute_force);
    tcase_add_loop_test(tc, walled_small_worlds_split_and_merge, 0, 12);
    tc = test_case(s, "more random scenes", 300, "slow seeds");
    tcase_add_loop_test(tc, random_scenes_against_brute_force, 2, 8);
    tc = test_case(s, "bounded work", 120, NULL);
    tcase_add_loop_test(tc, stacks_stop_splitting, 0, 4);
    add_tests(tc, coincident_objects_add_and_remove, touching_pile, root_shrinks_back,
              substep_cap_is_a_status, directions_whole_range, validate_reports_invariant);

    tc = test_case(s, "effects and handles", 0, NULL);
    add_tests(tc, effects_off_cost_nothing, straddlers_take_the_fast_path,
              fast_test_at_the_rounding_edge, runaway_object_is_an_error, substeps_stop_tunnelling,
              handles_and_bad_input, inspect_tree, handles_through_churn);
#ifndef NOCT_EFFICIENT
    TCase *d = test_case(s, "requires clauses", 0, "death");
    tcase_add_loop_test_raise_signal(d, die_null_world, SIGABRT, 0, 3);
#endif
    return run_suite(s);
}
