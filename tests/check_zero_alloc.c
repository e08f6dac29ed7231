/* SPDX-License-Identifier: MIT */
/*
 * No allocation in the step once sizes settle (issue 17).
 *
 * The tests' allocator (testalloc.h) counts the allocations made while
 * counting is on, with the caller of the first few. Each test warms a
 * workload up, then counts the allocations of a stretch of steps, which
 * must be none:
 * the octree's nodes and cells come from the broadphase's pool, leaf lists
 * and every scratch array keep their capacity. The stretches are chosen so
 * that the trees split and merge leaves throughout (the counters prove
 * it), so that the pool and the kept lists, not a quiet tree, are what is
 * tested.
 *
 * Skipped (exit status 77) under AddressSanitizer and valgrind, which own
 * malloc, as check-alloc is.
 */
#define _GNU_SOURCE /* dladdr */
#include <check.h>
#include <dlfcn.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <noctree/broadphase.h>
#include <noctree/mesh.h>
#include <noctree/scene.h>
#include <noctree/world.h>

#include "testalloc.h"
#include "testutil.h"

/* ---- counting the allocations (testalloc.h) ---------------------------------- */

static void counting_on(void)
{
    alloc_begin(&(alloc_plan){0});
}

/* Stop counting; print the callers of the first allocations, if any. */
static unsigned long counting_off(const char *what)
{
    alloc_end();
    const unsigned long allocs = alloc_points();
    for (unsigned long i = 0; i < allocs && i < ALLOC_CALLERS; ++i) {
        void *caller = alloc_caller(i);
        Dl_info info;
        if (dladdr(caller, &info) != 0 && info.dli_sname != NULL)
            printf("%s: allocation %lu from %s+%#lx in %s\n", what, i + 1, info.dli_sname,
                   (unsigned long)((const char *)caller - (const char *)info.dli_saddr),
                   info.dli_fname);
        else if (dladdr(caller, &info) != 0)
            printf("%s: allocation %lu from %s+%#lx (addr2line -e it)\n", what, i + 1,
                   info.dli_fname,
                   (unsigned long)((const char *)caller - (const char *)info.dli_fbase));
        else
            printf("%s: allocation %lu from %p\n", what, i + 1, caller);
    }
    return allocs;
}

/* ---- the workloads ----------------------------------------------------------- */

#define WARM_UP 800
#define COUNTED 200

/* A built-in family's scene at N and max_depth, warmed up, then counted. */
static void world_stretch(const char *spec, int N, int depth, int warm_up, bool expect_churn)
{
    noctScene *sc;
    noctWorld *w;
    noctError err;
    ck_assert_int_eq(noctSceneFamily(spec, &sc, &err), NOCT_OK);
    noctSceneDef(sc)->N = N;
    noctSceneDef(sc)->max_depth = depth;
    ck_assert_int_eq(noctSceneBuild(sc, &w, &err), NOCT_OK);
    for (int s = 0; s < warm_up; ++s)
        ck_assert_int_eq(noctWorldStep(w, &err), NOCT_OK);
    noctWorldCounters before, after;
    noctWorldGetCounters(w, &before);
    counting_on();
    noctStatus st = NOCT_OK;
    for (int s = 0; s < COUNTED && st == NOCT_OK; ++s)
        st = noctWorldStep(w, &err);
    const unsigned long n = counting_off(spec);
    ck_assert_int_eq(st, NOCT_OK);
    noctWorldGetCounters(w, &after);
    printf("%s, N = %d: %d steps, %lu allocations; %llu splits, %llu merges, %llu leaves "
           "entered, %llu colliding pairs\n",
           spec, N, COUNTED, n, (unsigned long long)(after.splits - before.splits),
           (unsigned long long)(after.merges - before.merges),
           (unsigned long long)(after.leaves_entered - before.leaves_entered),
           (unsigned long long)(after.colliding_pairs - before.colliding_pairs));
    ck_assert_uint_gt(after.colliding_pairs, before.colliding_pairs);
    ck_assert_uint_gt(after.leaves_entered, before.leaves_entered);
    if (expect_churn) {
        ck_assert_uint_gt(after.splits, before.splits);
        ck_assert_uint_gt(after.merges, before.merges);
    }
    ck_assert_uint_eq(n, 0);
    ck_assert_int_eq(noctWorldValidate(w, &err), NOCT_OK);
    noctWorldDestroy(w);
    noctSceneDestroy(sc);
}

START_TEST(gas_steps)
{
    world_stretch("gas:2000", 10, 10, WARM_UP, true);
    /* at the defaults the leaves are fewer and larger (N = 128), and the
     * largest list each size class must hold settles later: measured, the
     * last new array came after about 2 400 steps */
    world_stretch("gas:2000", NOCT_AUTO, NOCT_AUTO, 5 * WARM_UP, false);
}
END_TEST

START_TEST(splitting_steps)
{
    /* at N = 3 the gas's leaves split and merge all the time */
    world_stretch("gas:2000", 3, 10, WARM_UP, true);
}
END_TEST

/* A detection-only world that the program drives: gas's boxes, made
 * kinematic, each placed every frame with noctWorldSetTransform() along
 * the path the world's own motion would give it (p += v, turned back at
 * the container's walls and, by the program, at contact begins). Once
 * sizes settle, placing and stepping allocate nothing. */
START_TEST(driven_frames)
{
    const size_t n = 2000;
    noctWorldDef wd = noctDefaultWorldDef();
    wd.effects = NOCT_EFFECT_EVENTS;
    wd.N = wd.max_depth = 10;
    noctWorld *src, *w;
    noctError err;
    ck_assert_int_eq(noctWorldCreate(&wd, &src, &err), NOCT_OK);
    ck_assert_int_eq(noctWorldAddGas(src, n, &err), NOCT_OK);
    ck_assert_int_eq(noctWorldCreate(&wd, &w, &err), NOCT_OK);
    static noctTransform x[2000];
    static double v[2000][3];
    static noctObjectId id[2000];
    static int turned[2000];
    for (uint32_t i = 0; i < n; ++i) {
        const noctObjectId s = {i, 1};
        noctObjectDef d = noctDefaultObjectDef();
        ck_assert_int_eq(noctWorldGetHalfExtents(src, s, d.half_extents), NOCT_OK);
        ck_assert_int_eq(noctWorldGetTransform(src, s, &x[i]), NOCT_OK);
        ck_assert_int_eq(noctWorldGetVelocity(src, s, v[i]), NOCT_OK);
        d.transform = x[i];
        d.type = NOCT_OBJECT_KINEMATIC;
        ck_assert_int_eq(noctWorldCreateObject(w, &d, &id[i], &err), NOCT_OK);
    }
    noctWorldDestroy(src);
    const double L = noctGasContainerSize(n);
    noctWorldCounters before, after;
    unsigned long allocs = 0;
    noctStatus st = NOCT_OK;
    for (int f = 0; f < WARM_UP + COUNTED && st == NOCT_OK; ++f) {
        if (f == WARM_UP) {
            noctWorldGetCounters(w, &before);
            counting_on();
        }
        for (uint32_t i = 0; i < n && st == NOCT_OK; ++i) {
            for (int k = 0; k < 3; ++k) {
                x[i].p[k] += v[i][k];
                if ((x[i].p[k] < 0 && v[i][k] < 0) || (x[i].p[k] > L && v[i][k] > 0))
                    v[i][k] = -v[i][k];
            }
            st = noctWorldSetTransform(w, id[i], &x[i], &err);
        }
        if (st == NOCT_OK)
            st = noctWorldStep(w, &err);
        /* the response, the program's: each box in a pair that began
         * turns back once */
        const noctPair *p;
        const size_t nb = noctWorldBegan(w, &p);
        for (size_t b = 0; b < nb; ++b)
            for (int side = 0; side < 2; ++side) {
                const uint32_t i = side ? p[b].b.index : p[b].a.index;
                if (turned[i] == f + 1)
                    continue;
                turned[i] = f + 1;
                for (int k = 0; k < 3; ++k)
                    v[i][k] = -v[i][k];
            }
    }
    allocs = counting_off("driven");
    ck_assert_msg(st == NOCT_OK, "%s", err.message);
    noctWorldGetCounters(w, &after);
    printf("driven gas:2000: %d frames, %lu allocations; %llu leaves entered, %llu colliding "
           "pairs\n",
           COUNTED, allocs, (unsigned long long)(after.leaves_entered - before.leaves_entered),
           (unsigned long long)(after.colliding_pairs - before.colliding_pairs));
    /* the same boxes on the same paths as gas_steps' world: the same
     * colliding pairs, step by step, as its motion and response give */
    ck_assert_uint_eq(after.colliding_pairs - before.colliding_pairs, 12831);
    ck_assert_uint_gt(after.leaves_entered, before.leaves_entered);
    ck_assert_uint_eq(allocs, 0);
    ck_assert_int_eq(noctWorldValidate(w, &err), NOCT_OK);
    noctWorldDestroy(w);
}
END_TEST

static uint64_t rng = 0x9e3779b97f4a7c15u;
static double uniform(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (double)(rng >> 11) * 0x1p-53;
}

static double count_ray(void *ctx, noctProxyId id, void *user, double t)
{
    (void)id;
    (void)user;
    (void)t;
    ++*(size_t *)ctx;
    return 1; /* every box along the segment */
}

/* The public broadphase: boxes bouncing in a cube, moved and searched each
 * frame, some growing and shrinking, and a ray cast across it. */
START_TEST(broadphase_frames)
{
    enum { n = 1500 };
    static double lo[n][3], hi[n][3], v[n][3];
    static noctProxyId id[n];
    const double side = 40;
    noctBroadphaseDef def = noctDefaultBroadphaseDef();
    def.N = 2;
    noctBroadphase *bp;
    noctError err;
    ck_assert_int_eq(noctBroadphaseCreate(&def, &bp, &err), NOCT_OK);
    for (int i = 0; i < n; ++i) {
        const double s = 0.2 + 0.6 * uniform();
        for (int k = 0; k < 3; ++k) {
            lo[i][k] = (side - s) * uniform();
            hi[i][k] = lo[i][k] + s;
            v[i][k] = 0.2 * (uniform() - 0.5);
        }
        ck_assert_int_eq(noctBroadphaseAdd(bp, lo[i], hi[i], NULL, NOCT_FILTER_ALL,
                                           NOCT_FILTER_ALL, &id[i], &err),
                         NOCT_OK);
    }
    noctBroadphaseCounters before, after;
    size_t pairs = 0, rays = 0;
    unsigned long allocs = 0;
    int failures = 0;
    for (int f = 0; f < WARM_UP + COUNTED; ++f) {
        if (f == WARM_UP) {
            noctBroadphaseGetCounters(bp, &before);
            counting_on();
        }
        for (int i = 0; i < n; ++i) {
            for (int k = 0; k < 3; ++k) {
                if ((lo[i][k] + v[i][k] < 0) || (hi[i][k] + v[i][k] > side))
                    v[i][k] = -v[i][k];
                lo[i][k] += v[i][k];
                hi[i][k] += v[i][k];
            }
            if (i % 97 == f % 97) /* now and then a box changes size */
                hi[i][0] = lo[i][0] + (hi[i][0] - lo[i][0] < 0.5 ? 0.8 : 0.3);
            /* (no ck_assert while counting: Check's bookkeeping allocates) */
            failures += noctBroadphaseMove(bp, id[i], lo[i], hi[i], &err) != NOCT_OK;
        }
        failures += noctBroadphaseUpdatePairs(bp, &err) != NOCT_OK;
        const noctProxyPair *p;
        if (f >= WARM_UP)
            pairs += noctBroadphasePairs(bp, &p);
        /* a ray across the cube, meeting a few dozen boxes: the query
         * allocates nothing either */
        const double o[3] = {0, side / 2 + f % 7, side / 2}, dir[3] = {side, 0, 0};
        failures += noctBroadphaseRayCast(bp, o, dir, noctDefaultQueryFilter(), count_ray,
                                          &rays) != NOCT_OK;
    }
    allocs = counting_off("broadphase");
    ck_assert_int_eq(failures, 0);
    noctBroadphaseGetCounters(bp, &after);
    printf("broadphase, N = 2: %d frames, %lu allocations; %llu splits, %llu merges, %zu "
           "pairs\n",
           COUNTED, allocs, (unsigned long long)(after.splits - before.splits),
           (unsigned long long)(after.merges - before.merges), pairs);
    ck_assert_uint_gt(after.splits, before.splits);
    ck_assert_uint_gt(after.merges, before.merges);
    ck_assert_uint_gt(pairs, 0);
    ck_assert_uint_gt(rays, 0);
    ck_assert_uint_eq(allocs, 0);
    ck_assert_int_eq(noctBroadphaseValidate(bp, &err), NOCT_OK);
    noctBroadphaseDestroy(bp);
}
END_TEST


/* ---- spinning meshes (issue 31) ---------------------------------------------- */

/* Mesh objects that spin (an L, a tetrahedron, a box mesh from
 * noctMeshCreateBox()) in a grid where neighbours meet as they turn, and
 * two that follow rotating tracks: each turns into the copy its last
 * step replaced, so once every object has one, stepping allocates
 * nothing. */
START_TEST(spinning_meshes)
{
    enum { SIDE = 6, NOBJ = SIDE * SIDE };
    noctMesh *shapes[3] = {make_ell(), make_tetrahedron(), NULL};
    ck_assert_int_eq(noctMeshCreateBox(0.4, 0.3, 0.2, &shapes[2], NULL), NOCT_OK);
    noctWorldDef wd = noctDefaultWorldDef();
    wd.effects = NOCT_EFFECT_EVENTS | NOCT_EFFECT_SPIN | NOCT_EFFECT_TRACK;
    noctWorld *w;
    noctError err;
    ck_assert_int_eq(noctWorldCreate(&wd, &w, &err), NOCT_OK);
    noctObjectId id[NOBJ];
    for (int i = 0; i < NOBJ; ++i) {
        noctObjectDef d = noctDefaultObjectDef();
        d.mesh = shapes[i % 3];
        d.transform.p[0] = 0.7 * (i % SIDE);
        d.transform.p[1] = 0.7 * (i / SIDE);
        const double axis[3] = {uniform() - 0.5, uniform() - 0.5, uniform() - 0.5};
        ck_assert_int_eq(noctQuatFromAxisAngle(axis, 360 * uniform(), &d.transform.q), NOCT_OK);
        ck_assert_int_eq(noctQuatFromAxisAngle(axis, 2 + 5 * uniform(), &d.angular_velocity),
                         NOCT_OK);
        ck_assert_int_eq(noctWorldCreateObject(w, &d, &id[i], &err), NOCT_OK);
    }
    /* two tracked (kinematic: they do not spin), turning all along */
    enum { NKEYS = (WARM_UP + COUNTED) / 25 + 2 };
    static noctKeyframe keys[NKEYS];
    for (int t = 0; t < 2; ++t) {
        const double axis[3] = {1, 2 - t, 3};
        for (int k = 0; k < NKEYS; ++k) {
            keys[k].tick = (uint64_t)(25 * k);
            keys[k].x.p[0] = 0.7 * (2 + t) + 0.05 * (k % 3);
            keys[k].x.p[1] = 0.7 * (1 + 2 * t);
            keys[k].x.p[2] = 0;
            ck_assert_int_eq(noctQuatFromAxisAngle(axis, 37.0 * k, &keys[k].x.q), NOCT_OK);
        }
        const noctObjectId o = id[SIDE + 2 + 2 * SIDE * t];
        ck_assert_int_eq(noctWorldSetType(w, o, NOCT_OBJECT_KINEMATIC, &err), NOCT_OK);
        ck_assert_int_eq(noctWorldSetTrack(w, o, keys, NKEYS, &err), NOCT_OK);
    }
    for (int s = 0; s < WARM_UP; ++s)
        ck_assert_int_eq(noctWorldStep(w, &err), NOCT_OK);
    noctWorldCounters before, after;
    noctWorldGetCounters(w, &before);
    size_t changes = 0;
    counting_on();
    noctStatus st = NOCT_OK;
    for (int s = 0; s < COUNTED && st == NOCT_OK; ++s) {
        st = noctWorldStep(w, &err);
        const noctPair *p;
        changes += noctWorldBegan(w, &p) + noctWorldEnded(w, &p);
    }
    const unsigned long n = counting_off("spinning meshes");
    ck_assert_msg(st == NOCT_OK, "%s", err.message);
    noctWorldGetCounters(w, &after);
    printf("spinning meshes: %d steps, %lu allocations; %llu colliding pairs, %zu began or "
           "ended\n",
           COUNTED, n, (unsigned long long)(after.colliding_pairs - before.colliding_pairs),
           changes);
    /* the objects turn into and out of contact all along */
    ck_assert_uint_gt(after.colliding_pairs - before.colliding_pairs, 1000);
    ck_assert_uint_gt(changes, 50);
    ck_assert_uint_eq(n, 0);
    /* and the recycled copies are the meshes turned anew, bit for bit */
    ck_assert_msg(noctWorldValidate(w, &err) == NOCT_OK, "%s", err.message);
    noctWorldDestroy(w);
    for (int i = 0; i < 3; ++i)
        noctMeshDestroy(shapes[i]);
}
END_TEST


int main(void)
{
    const char *why = alloc_unavailable();
    if (why != NULL) {
        printf("skipped: %s\n", why);
        return 77;
    }
    Suite *s = suite_create("zero-alloc");
    TCase *tc = test_case(s, "steps", 300, NULL);
    add_tests(tc, gas_steps, splitting_steps, broadphase_frames, driven_frames, spinning_meshes);
    return run_suite(s);
}
