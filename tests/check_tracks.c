/* SPDX-License-Identifier: MIT */
/*
 * Tracks (#NOCT_EFFECT_TRACK): noctTrackAt() against the test's own
 * interpolation (the documented formula, and long double linear and
 * spherical interpolation); worlds whose objects follow tracks, their
 * poses after every step and their events against a brute force of the
 * narrowphase on every pair, the same in every maintenance mode; a failed
 * step that gives the placements back; removal; bad input; scene files;
 * keyframes' turns (noctKeyTurn) against closed forms, in the track API
 * and through scene files (key ... turn).
 */
#define _POSIX_C_SOURCE 200809L /* mkstemp(3), fdopen(3) */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <noctree.h>

#include "testutil.h"

static uint64_t rng = 0x7ac5u;

static double uniform(void)
{
    return test_uniform(&rng);
}

/* n keyframes at increasing ticks from first, random poses near the
 * origin (within 4), rotations random or (one in four) the previous one. */
static void random_keys(noctKeyframe *k, size_t n, uint64_t first)
{
    uint64_t t = first;
    for (size_t i = 0; i < n; ++i) {
        k[i].tick = t;
        t += 1 + (uint64_t)(20 * uniform());
        for (int c = 0; c < 3; ++c)
            k[i].x.p[c] = 8 * uniform() - 4;
        if (i > 0 && uniform() < 0.25)
            k[i].x.q = k[i - 1].x.q;
        else
            test_random_quat(&rng, &k[i].x.q);
    }
}

/* ---- interpolation -------------------------------------------------------------- */

/* _i: 0 a quick run (under valgrind too), 1 the full one (tag slow). */
START_TEST(interpolation_against_the_formula)
{
    int between = 0;
    for (int round = 0; round < (_i ? 200 : 30); ++round) {
        noctKeyframe k[6];
        const size_t n = 1 + (size_t)(6 * uniform());
        random_keys(k, n, (uint64_t)(5 * uniform()));
        for (uint64_t t = 0; t <= k[n - 1].tick + 3; ++t) {
            noctTransform x;
            noctTrackAt(k, n, t, &x);
            /* the keyframe at or before t, or the first */
            size_t i = 0;
            while (i + 1 < n && k[i + 1].tick <= t)
                ++i;
            if (t <= k[0].tick || t >= k[n - 1].tick || t == k[i].tick) {
                const noctTransform *want = t <= k[0].tick ? &k[0].x
                                           : t >= k[n - 1].tick ? &k[n - 1].x : &k[i].x;
                ck_assert_msg(memcmp(&x, want, sizeof x) == 0, "tick %llu: not the keyframe's",
                              (unsigned long long)t);
                continue;
            }
            ++between;
            const noctKeyframe *a = &k[i], *b = &k[i + 1];
            const double s = (double)(t - a->tick) / (double)(b->tick - a->tick);
            for (int c = 0; c < 3; ++c) {
                /* the documented order, bit for bit */
                volatile double u = 1 - s;
                volatile double l = u * a->x.p[c];
                volatile double r = s * b->x.p[c];
                volatile double want = l + r;
                ck_assert_msg(x.p[c] == want, "position %d at tick %llu: %.17g, formula %.17g",
                              c, (unsigned long long)t, x.p[c], (double)want);
                /* and near the exact interpolation */
                const long double e = (1 - (long double)s) * a->x.p[c] + (long double)s * b->x.p[c];
                ck_assert(fabsl(x.p[c] - e) <= 1e-15L * 8);
            }
            /* the rotation: long double slerp on the shorter arc */
            long double q0[4] = {a->x.q.x, a->x.q.y, a->x.q.z, a->x.q.w};
            long double q1[4] = {b->x.q.x, b->x.q.y, b->x.q.z, b->x.q.w};
            long double d = 0;
            for (int c = 0; c < 4; ++c)
                d += q0[c] * q1[c];
            if (d < 0) {
                for (int c = 0; c < 4; ++c)
                    q1[c] = -q1[c];
                d = -d;
            }
            long double want[4], len = 0;
            if (d > 1 - 1e-12L) {
                for (int c = 0; c < 4; ++c)
                    want[c] = q0[c];
            } else {
                const long double th = acosl(fminl(d, 1)), st = sinl(th);
                for (int c = 0; c < 4; ++c)
                    want[c] = (sinl((1 - s) * th) * q0[c] + sinl(s * th) * q1[c]) / st;
            }
            for (int c = 0; c < 4; ++c)
                len += want[c] * want[c];
            const double got[4] = {x.q.x, x.q.y, x.q.z, x.q.w};
            long double glen = 0;
            for (int c = 0; c < 4; ++c) {
                /* nlerp within 0.9995 of the same rotation differs from
                 * slerp by well under 1e-4 */
                ck_assert_msg(fabsl(got[c] - want[c] / sqrtl(len)) < (d > 0.9995L ? 1e-4L : 1e-12L),
                              "rotation at tick %llu: %.17g, slerp %.17Lg",
                              (unsigned long long)t, got[c], want[c] / sqrtl(len));
                glen += (long double)got[c] * got[c];
            }
            ck_assert(fabsl(glen - 1) < 1e-15L);
        }
    }
    ck_assert_int_gt(between, _i ? 1000 : 100);
}
END_TEST

/* ---- worlds ------------------------------------------------------------------------ */

#define NOBJ 12

typedef struct tracked {
    noctWorld *w;
    noctObjectId id[NOBJ];
    noctKeyframe keys[NOBJ][5];
    size_t nkeys[NOBJ];
    noctMesh *mesh[NOBJ]; /* each object's mesh (the test's of a box primitive) */
} tracked;

static void build(tracked *t, noctMaintenance mode, int N, unsigned effects)
{
    noctWorldDef wd = noctDefaultWorldDef();
    wd.effects = effects;
    wd.maintenance = mode;
    wd.N = N;
    ck_assert_int_eq(noctWorldCreate(&wd, &t->w, NULL), NOCT_OK);
    for (int i = 0; i < NOBJ; ++i) {
        double h[3];
        for (int c = 0; c < 3; ++c)
            h[c] = 0.3 + 0.5 * uniform();
        ck_assert_int_eq(noctMeshCreateBox(h[0], h[1], h[2], &t->mesh[i], NULL), NOCT_OK);
        noctObjectDef d = noctDefaultObjectDef();
        if (i % 2)
            d.mesh = t->mesh[i];
        else
            memcpy(d.half_extents, h, sizeof h);
        d.type = NOCT_OBJECT_KINEMATIC;
        ck_assert_int_eq(noctWorldCreateObject(t->w, &d, &t->id[i], NULL), NOCT_OK);
        t->nkeys[i] = i == NOBJ - 1 ? 0 : 1 + (size_t)(5 * uniform()); /* one untracked */
        random_keys(t->keys[i], t->nkeys[i], 0);
        if (t->nkeys[i] > 0)
            ck_assert_int_eq(noctWorldSetTrack(t->w, t->id[i], t->keys[i], t->nkeys[i], NULL),
                             NOCT_OK);
    }
}

static void destroy(tracked *t)
{
    noctWorldDestroy(t->w);
    for (int i = 0; i < NOBJ; ++i)
        noctMeshDestroy(t->mesh[i]);
}

/* The colliding pairs, by brute force: the narrowphase on every pair at
 * the poses the world reports. */
static int brute(const tracked *t, noctPair *out)
{
    int n = 0;
    for (int i = 0; i < NOBJ; ++i)
        for (int j = i + 1; j < NOBJ; ++j) {
            noctTransform a, b;
            ck_assert_int_eq(noctWorldGetTransform(t->w, t->id[i], &a), NOCT_OK);
            ck_assert_int_eq(noctWorldGetTransform(t->w, t->id[j], &b), NOCT_OK);
            bool hit;
            ck_assert_int_eq(noctCollideTransformed(t->mesh[i], &a, t->mesh[j], &b,
                                                    NOCT_ACCURACY_EXACT, &hit, NULL, NULL),
                             NOCT_OK);
            if (hit)
                out[n++] = (noctPair){t->id[i], t->id[j]};
        }
    return n;
}

/* _i: 0 a quick run (under valgrind too), 1 the full one (tag slow). */
START_TEST(worlds_follow_their_tracks)
{
    const uint64_t seed = rng;
    int events = 0;
    /* the same tracks in three configurations: the same poses and events */
    static const struct { noctMaintenance mode; int N; } CONF[3] = {
        {NOCT_MAINTAIN_INCREMENTAL, 2}, {NOCT_MAINTAIN_REBUILD, 4},
        {NOCT_MAINTAIN_INCREMENTAL, NOCT_N_EXHAUSTIVE}};
    for (int round = 0; round < (_i ? 6 : 1); ++round) {
        noctPair log[3][120][NOBJ * NOBJ / 2];
        int nlog[3][120];
        const uint64_t start = rng;
        for (int c = 0; c < 3; ++c) {
            rng = start;
            tracked t;
            build(&t, CONF[c].mode, CONF[c].N, NOCT_EFFECT_EVENTS | NOCT_EFFECT_TRACK);
            const uint64_t steps = _i ? 120 : 30;
            for (uint64_t step = 1; step <= steps; ++step) {
                ck_assert_int_eq(noctWorldStep(t.w, NULL), NOCT_OK);
                ck_assert_uint_eq(noctWorldTick(t.w), step);
                for (int i = 0; i < NOBJ; ++i) {
                    noctTransform x, want;
                    ck_assert_int_eq(noctWorldGetTransform(t.w, t.id[i], &x), NOCT_OK);
                    if (t.nkeys[i] == 0)
                        continue;
                    noctTrackAt(t.keys[i], t.nkeys[i], step, &want);
                    ck_assert_msg(memcmp(&x, &want, sizeof x) == 0,
                                  "object %d at step %llu is not on its track", i,
                                  (unsigned long long)step);
                }
                noctPair want[NOBJ * NOBJ / 2];
                const int nw = brute(&t, want);
                const noctPair *got;
                const size_t ng = noctWorldColliding(t.w, &got);
                ck_assert_int_eq((int)ng, nw);
                for (int k = 0; k < nw; ++k) {
                    ck_assert_uint_eq(got[k].a.index, want[k].a.index);
                    ck_assert_uint_eq(got[k].b.index, want[k].b.index);
                }
                if (ng > 0)
                    memcpy(log[c][step - 1], got, ng * sizeof *got);
                nlog[c][step - 1] = (int)ng;
                const noctPair *b;
                events += (int)noctWorldBegan(t.w, &b);
            }
            ck_assert_int_eq(noctWorldValidate(t.w, NULL), NOCT_OK);
            destroy(&t);
        }
        for (int c = 1; c < 3; ++c)
            for (int k = 0; k < (_i ? 120 : 30); ++k) {
                ck_assert_int_eq(nlog[c][k], nlog[0][k]);
                ck_assert(nlog[0][k] == 0 ||
                          memcmp(log[c][k], log[0][k], (size_t)nlog[0][k] * sizeof(noctPair)) == 0);
            }
    }
    ck_assert_int_gt(events, _i ? 50 : 5);
    (void)seed;
}
END_TEST

/* Without the effect the tracks are kept and nothing follows them. */
START_TEST(without_the_effect_nothing_moves)
{
    tracked t;
    build(&t, NOCT_MAINTAIN_INCREMENTAL, 10, NOCT_EFFECT_EVENTS);
    noctTransform before[NOBJ];
    for (int i = 0; i < NOBJ; ++i) {
        ck_assert_int_eq(noctWorldGetTransform(t.w, t.id[i], &before[i]), NOCT_OK);
        if (t.nkeys[i] > 0) { /* placed at once, at tick 0 */
            noctTransform want;
            noctTrackAt(t.keys[i], t.nkeys[i], 0, &want);
            ck_assert(memcmp(&before[i], &want, sizeof want) == 0);
        }
    }
    for (int step = 0; step < 30; ++step)
        ck_assert_int_eq(noctWorldStep(t.w, NULL), NOCT_OK);
    for (int i = 0; i < NOBJ; ++i) {
        noctTransform x;
        ck_assert_int_eq(noctWorldGetTransform(t.w, t.id[i], &x), NOCT_OK);
        ck_assert(memcmp(&x, &before[i], sizeof x) == 0);
        const noctKeyframe *k;
        ck_assert_uint_eq(noctWorldGetTrack(t.w, t.id[i], &k), t.nkeys[i]);
    }
    destroy(&t);
}
END_TEST

/* A step that fails after the tracks placed their objects gives them
 * back: a moving object that would leave the coordinate range fails the
 * motion stage, which runs after the tracks. */
START_TEST(a_failed_step_gives_the_placements_back)
{
    tracked t;
    build(&t, NOCT_MAINTAIN_INCREMENTAL, 2, NOCT_EFFECT_EVENTS | NOCT_EFFECT_TRACK |
                                                NOCT_EFFECT_MOTION);
    for (int step = 0; step < 5; ++step)
        ck_assert_int_eq(noctWorldStep(t.w, NULL), NOCT_OK);
    noctObjectDef d = noctDefaultObjectDef();
    d.mesh = t.mesh[1];
    d.transform.p[0] = 9.9e99;
    d.velocity[0] = 1e99;
    noctObjectId far;
    ck_assert_int_eq(noctWorldCreateObject(t.w, &d, &far, NULL), NOCT_OK);
    noctTransform before[NOBJ];
    for (int i = 0; i < NOBJ; ++i)
        ck_assert_int_eq(noctWorldGetTransform(t.w, t.id[i], &before[i]), NOCT_OK);
    const noctPair *p;
    const size_t ncol = noctWorldColliding(t.w, &p);
    noctError err;
    ck_assert_int_eq(noctWorldStep(t.w, &err), NOCT_ERR_TOO_LARGE);
    ck_assert_uint_eq(noctWorldTick(t.w), 5);
    for (int i = 0; i < NOBJ; ++i) {
        noctTransform x;
        ck_assert_int_eq(noctWorldGetTransform(t.w, t.id[i], &x), NOCT_OK);
        ck_assert_msg(memcmp(&x, &before[i], sizeof x) == 0, "object %d was not given back", i);
    }
    ck_assert_uint_eq(noctWorldColliding(t.w, &p), ncol);
    /* without the runaway the step goes on where it was */
    ck_assert_int_eq(noctWorldRemove(t.w, far, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldStep(t.w, NULL), NOCT_OK);
    ck_assert_uint_eq(noctWorldTick(t.w), 6);
    for (int i = 0; i < NOBJ; ++i) {
        if (t.nkeys[i] == 0)
            continue;
        noctTransform x, want;
        ck_assert_int_eq(noctWorldGetTransform(t.w, t.id[i], &x), NOCT_OK);
        noctTrackAt(t.keys[i], t.nkeys[i], 6, &want);
        ck_assert(memcmp(&x, &want, sizeof x) == 0);
    }
    ck_assert_int_eq(noctWorldValidate(t.w, NULL), NOCT_OK);
    destroy(&t);
}
END_TEST

START_TEST(removal_and_replacement)
{
    tracked t;
    build(&t, NOCT_MAINTAIN_INCREMENTAL, 3, NOCT_EFFECT_EVENTS | NOCT_EFFECT_TRACK);
    /* remove a tracked object in the middle of the list: the others go on */
    ck_assert_int_eq(noctWorldRemove(t.w, t.id[3], NULL), NOCT_OK);
    const noctKeyframe *k;
    ck_assert_uint_eq(noctWorldGetTrack(t.w, t.id[3], &k), 0);
    ck_assert_ptr_null(k);
    noctObjectDef d = noctDefaultObjectDef();
    d.mesh = t.mesh[1];
    noctObjectId again;
    ck_assert_int_eq(noctWorldCreateObject(t.w, &d, &again, NULL), NOCT_OK);
    ck_assert_uint_eq(again.index, t.id[3].index); /* the slot, reused: no track */
    ck_assert_uint_eq(noctWorldGetTrack(t.w, again, &k), 0);
    /* a new track replaces the old; an empty one ends it */
    noctKeyframe nk[2];
    random_keys(nk, 2, 3);
    ck_assert_int_eq(noctWorldSetTrack(t.w, t.id[0], nk, 2, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldSetTrack(t.w, t.id[2], NULL, 0, NULL), NOCT_OK);
    noctTransform held;
    ck_assert_int_eq(noctWorldGetTransform(t.w, t.id[2], &held), NOCT_OK);
    for (uint64_t step = 1; step <= 40; ++step) {
        ck_assert_int_eq(noctWorldStep(t.w, NULL), NOCT_OK);
        for (int i = 0; i < NOBJ; ++i) {
            if (i == 3)
                continue;
            noctTransform x, want;
            ck_assert_int_eq(noctWorldGetTransform(t.w, t.id[i], &x), NOCT_OK);
            if (i == 0)
                noctTrackAt(nk, 2, step, &want);
            else if (i == 2)
                want = held;
            else if (t.nkeys[i] > 0)
                noctTrackAt(t.keys[i], t.nkeys[i], step, &want);
            else
                continue;
            ck_assert_msg(memcmp(&x, &want, sizeof x) == 0, "object %d, step %llu", i,
                          (unsigned long long)step);
        }
    }
    ck_assert_uint_eq(noctWorldGetTrack(t.w, t.id[0], &k), 2);
    ck_assert(memcmp(k, nk, sizeof nk) == 0);
    destroy(&t);
}
END_TEST

START_TEST(bad_tracks)
{
    tracked t;
    build(&t, NOCT_MAINTAIN_INCREMENTAL, 3, NOCT_EFFECT_EVENTS | NOCT_EFFECT_TRACK);
    const noctKeyframe *before;
    const size_t nbefore = noctWorldGetTrack(t.w, t.id[0], &before);
    noctTransform xbefore;
    ck_assert_int_eq(noctWorldGetTransform(t.w, t.id[0], &xbefore), NOCT_OK);
    noctKeyframe k[3];
    noctError err;
    random_keys(k, 3, 0);
    k[2].tick = k[1].tick; /* a duplicate tick */
    ck_assert_int_eq(noctWorldSetTrack(t.w, t.id[0], k, 3, &err), NOCT_ERR_INVALID);
    ck_assert_ptr_nonnull(strstr(err.message, "keyframe 2"));
    random_keys(k, 3, 0);
    k[1].tick = k[0].tick > 0 ? k[0].tick - 1 : 0; /* out of order */
    ck_assert_int_eq(noctWorldSetTrack(t.w, t.id[0], k, 3, &err), NOCT_ERR_INVALID);
    random_keys(k, 3, 0);
    k[1].x.p[2] = NAN;
    ck_assert_int_eq(noctWorldSetTrack(t.w, t.id[0], k, 3, &err), NOCT_ERR_NONFINITE);
    ck_assert_ptr_nonnull(strstr(err.message, "keyframe 1"));
    random_keys(k, 3, 0);
    k[2].x.q.w += 0.5; /* far from unit length */
    ck_assert_int_eq(noctWorldSetTrack(t.w, t.id[0], k, 3, &err), NOCT_ERR_INVALID);
    random_keys(k, 3, 0);
    k[0].x.p[0] = 1e101;
    ck_assert_int_eq(noctWorldSetTrack(t.w, t.id[0], k, 3, &err), NOCT_ERR_TOO_LARGE);
    /* nothing changed */
    const noctKeyframe *after;
    ck_assert_uint_eq(noctWorldGetTrack(t.w, t.id[0], &after), nbefore);
    ck_assert(memcmp(after, t.keys[0], nbefore * sizeof *after) == 0);
    noctTransform x;
    ck_assert_int_eq(noctWorldGetTransform(t.w, t.id[0], &x), NOCT_OK);
    ck_assert(memcmp(&x, &xbefore, sizeof x) == 0);
    /* a stale handle */
    noctObjectId gone = t.id[5];
    ck_assert_int_eq(noctWorldRemove(t.w, gone, NULL), NOCT_OK);
    random_keys(k, 3, 0);
    ck_assert_int_eq(noctWorldSetTrack(t.w, gone, k, 3, &err), NOCT_ERR_INVALID);
    ck_assert_uint_eq(noctWorldGetTrack(t.w, gone, &after), 0);
    destroy(&t);
}
END_TEST

/* ---- scene files ------------------------------------------------------------------------- */

static char *write_scene(const char *text)
{
    static char path[64];
    strcpy(path, "/tmp/check-tracks-XXXXXX");
    int fd = mkstemp(path);
    ck_assert_int_ge(fd, 0);
    FILE *f = fdopen(fd, "w");
    ck_assert_ptr_nonnull(f);
    fputs(text, f);
    fclose(f);
    return path;
}

/* The scene's error: its status and, in its message, want (NULL: none). */
static void scene_error(const char *text, noctStatus status, const char *want)
{
    char *path = write_scene(text);
    noctScene *s;
    noctError err;
    const noctStatus st = noctSceneRead(path, &s, &err);
    unlink(path);
    ck_assert_msg(st == status, "%s: status %d, want %d (%s)", text, st, status, err.message);
    if (st != NOCT_OK) {
        ck_assert_msg(strstr(err.message, want) != NULL, "message '%s' lacks '%s'", err.message,
                      want);
        return;
    }
    noctSceneDestroy(s);
}

START_TEST(scene_keys)
{
    /* a bar swinging a quarter turn about z over 10 ticks near a static
     * block at x = 1.5 that it never reaches */
    char *path = write_scene("N 2\nsteps 12\neffects events\n"
                             "mesh bar box 1 0.1 0.1\nmesh block box 0.25 0.25 0.25\n"
                             "object block 1.5 0 0 type static\n"
                             "object bar 0 0 0\n"
                             "key 0 0 0 0\n"
                             "key 10 0 0 0 rotate 0 0 1 90   # a quarter turn\n");
    noctScene *s;
    noctError err;
    ck_assert_msg(noctSceneRead(path, &s, &err) == NOCT_OK, "%s", err.message);
    unlink(path);
    ck_assert(noctSceneDef(s)->effects & NOCT_EFFECT_TRACK);
    noctWorld *w;
    ck_assert_int_eq(noctSceneBuild(s, &w, &err), NOCT_OK);
    noctObjectId bar = {1, 1}; /* the second object, its slot new: generation 1 */
    const noctKeyframe *k;
    ck_assert_uint_eq(noctWorldGetTrack(w, bar, &k), 2);
    ck_assert_uint_eq(k[1].tick, 10);
    ck_assert(k[1].x.q.z == k[1].x.q.w); /* 45 degrees half-angle: exact sines */
    noctObjectType type;
    ck_assert_int_eq(noctWorldGetType(w, bar, &type), NOCT_OK);
    ck_assert_int_eq(type, NOCT_OBJECT_KINEMATIC);
    int colliding_steps = 0, last = 0;
    for (int step = 1; step <= 12; ++step) {
        ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
        const noctPair *p;
        if (noctWorldColliding(w, &p) > 0) {
            ++colliding_steps;
            last = step;
        }
    }
    /* The bar (x from -1 to 1) never reaches the block (x from 1.25). */
    ck_assert_int_eq(colliding_steps, 0);
    ck_assert_int_eq(last, 0);
    noctWorldDestroy(w);
    noctSceneDestroy(s);

    /* a block at x = 0.9 within the bar's reach at the start only: the bar
     * leaves it once its tip's y passes 0.25 + 0.1 */
    path = write_scene("N 2\nsteps 12\neffects events track\n"
                       "mesh bar box 1 0.1 0.1\nmesh block box 0.1 0.1 0.1\n"
                       "object block 0.9 0 0 type static\n"
                       "object bar 0 0 0 type kinematic\n"
                       "key 0 0 0 0\nkey 10 0 0 0 rotate 0 0 1 90\n");
    ck_assert_msg(noctSceneRead(path, &s, &err) == NOCT_OK, "%s", err.message);
    unlink(path);
    ck_assert_int_eq(noctSceneBuild(s, &w, &err), NOCT_OK);
    colliding_steps = 0;
    for (int step = 1; step <= 12; ++step) {
        ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
        const noctPair *p;
        colliding_steps += noctWorldColliding(w, &p) > 0;
        noctTransform x;
        ck_assert_int_eq(noctWorldGetTransform(w, bar, &x), NOCT_OK);
        /* a quarter turn in 10 ticks: 9 degrees a tick about z */
        const double a = 9.0 * (step < 10 ? step : 10) * 3.14159265358979323846 / 180;
        ck_assert(fabs(x.q.z - sin(a / 2)) < 1e-12 && fabs(x.q.w - cos(a / 2)) < 1e-12);
    }
    /* The block (x 0.8 to 1, y -0.1 to 0.1) meets the bar turned by a
     * while its corner (0.8, 0.1), in the bar's frame, is not below the
     * bar's lower face: -0.8 sin a + 0.1 cos a >= -0.1, that is
     * cot(a / 2) >= 8, a <= 14.25 degrees: step 1 (9 degrees), not step 2
     * (18 degrees) nor after. */
    ck_assert_int_eq(colliding_steps, 1);
    noctWorldDestroy(w);
    noctSceneDestroy(s);

    scene_error("mesh c box 1 1 1\nkey 0 0 0 0\n", NOCT_ERR_INVALID,
                ":2: a key needs an object line above it");
    scene_error("mesh c box 1 1 1\nobject c 0 0 0\nkey 5 0 0 0\nkey 5 1 0 0\n",
                NOCT_ERR_INVALID, ":4: key tick 5 is not after the previous key's 5");
    scene_error("mesh c box 1 1 1\nobject c 0 0 0\nkey 5 0 0 0\nkey 4 1 0 0\n",
                NOCT_ERR_INVALID, ":4: key tick 4 is not after");
    scene_error("mesh c box 1 1 1\nobject c 0 0 0\nkey 0 nan 0 0\n", NOCT_ERR_NONFINITE, ":3:");
    scene_error("mesh c box 1 1 1\nobject c 0 0 0\nkey -1 0 0 0\n", NOCT_ERR_INVALID, ":3:");
    scene_error("mesh c box 1 1 1\nobject c 0 0 0 velocity 1 0 0\nkey 0 0 0 0\n",
                NOCT_ERR_INVALID, ":3: an object that follows a track has no velocity");
    scene_error("mesh c box 1 1 1\nobject c 0 0 0 type static\nkey 0 0 0 0\n",
                NOCT_ERR_INVALID, ":3: an object that follows a track is kinematic");
    scene_error("mesh c box 1 1 1\nobject c 0 0 0\nkey 0 0 0 0 rotate 0 0 0 90\n",
                NOCT_ERR_INVALID, ":3: a rotation needs a non-zero axis");
    scene_error("mesh c box 1 1 1\nobject c 0 0 0\nkey 0 0 0 0 spin 0 0 1 90\n",
                NOCT_ERR_PARSE, ":3: unexpected 'spin'");
    scene_error("mesh c box 1 1 1\nobject c 0 0 0\nkey 0 2e100 0 0\n", NOCT_ERR_TOO_LARGE,
                ":3: key position beyond");
    scene_error("mesh c box 1 1 1\nobject c 0 0 0\nkey 0 0 0 0\nkey 3 1 1 1 rotate 1 0 0 30\n",
                NOCT_OK, NULL);
}
END_TEST

/* ---- turns ------------------------------------------------------------------------------ */

#define PI_L 3.141592653589793238462643383279502884L

/* Does q turn (1, 0, 0) to (cos a, sin a, 0) and keep z, for a in
 * degrees (the closed form of a turn about z)? */
static void turned_by(const noctQuat *q, long double degrees, const char *where)
{
    double R[9];
    ck_assert_int_eq(noctQuatToMatrix(q, R, NULL), NOCT_OK);
    const long double a = degrees * PI_L / 180;
    const double want[9] = {(double)cosl(a), (double)-sinl(a), 0, (double)sinl(a),
                            (double)cosl(a), 0, 0, 0, 1};
    for (int k = 0; k < 9; ++k)
        ck_assert_msg(fabs(R[k] - want[k]) < 1e-12, "%s: entry %d is %.17g, want %.17g (%Lg "
                      "degrees)", where, k, R[k], want[k], degrees);
}

/* A key of 270 degrees about z after one of 0: with a turn, the object
 * turns through 270 (90 at a third of the time, 180 at two thirds, 67.5
 * and 135 at a quarter and half); without, the shorter arc, -90. */
START_TEST(turns_honour_the_angle)
{
    noctKeyframe k[3] = {{0, noctIdentityTransform()}, {300, noctIdentityTransform()},
                         {308, noctIdentityTransform()}};
    const double z[3] = {0, 0, 1};
    ck_assert_int_eq(noctQuatFromAxisAngle(z, 270, &k[1].x.q), NOCT_OK);
    k[2].x.q = k[1].x.q; /* then twice round in 8 ticks: back where it was */
    const noctKeyTurn turns[3] = {{{0, 0, 0}, 0}, {{0, 0, 1}, 270}, {{0, 0, 2}, -720}};
    static const struct { uint64_t tick; long double turn, shorter; } AT[] = {
        {0, 0, 0},          {75, 67.5L, -22.5L}, {100, 90, -30},    {150, 135, -45},
        {200, 180, -60},    {300, 270, -90},     {301, 180, -90},   {302, 90, -90},
        {304, -90, -90},    {306, 90, -90},      {308, 270, -90},   {400, 270, -90}};
    for (size_t i = 0; i < sizeof AT / sizeof *AT; ++i) {
        noctTransform x;
        char where[64];
        noctTrackAtTurns(k, turns, 3, AT[i].tick, &x);
        snprintf(where, sizeof where, "turn, tick %llu", (unsigned long long)AT[i].tick);
        turned_by(&x.q, AT[i].turn, where);
        noctTrackAt(k, 3, AT[i].tick, &x);
        snprintf(where, sizeof where, "shorter arc, tick %llu", (unsigned long long)AT[i].tick);
        turned_by(&x.q, AT[i].shorter, where);
        /* no turns: noctTrackAt() bit for bit */
        noctTransform y;
        noctTrackAtTurns(k, NULL, 3, AT[i].tick, &y);
        ck_assert(memcmp(&x, &y, sizeof x) == 0);
    }
    /* a world: the object's poses after each step, the same */
    noctWorldDef wd = noctDefaultWorldDef();
    wd.effects = NOCT_EFFECT_TRACK;
    noctWorld *w;
    ck_assert_int_eq(noctWorldCreate(&wd, &w, NULL), NOCT_OK);
    noctObjectDef d = noctDefaultObjectDef();
    d.half_extents[0] = 1;
    d.half_extents[1] = d.half_extents[2] = 0.1;
    d.type = NOCT_OBJECT_KINEMATIC;
    noctObjectId id;
    ck_assert_int_eq(noctWorldCreateObject(w, &d, &id, NULL), NOCT_OK);
    noctError err;
    ck_assert_msg(noctWorldSetTrackTurns(w, id, k, turns, 3, &err) == NOCT_OK, "%s",
                  err.message);
    const noctKeyTurn *kept;
    ck_assert_uint_eq(noctWorldGetTrackTurns(w, id, &kept), 3);
    ck_assert(memcmp(&kept[1], &turns[1], 2 * sizeof *kept) == 0);
    for (uint64_t t = 1; t <= 310; ++t) {
        ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
        noctTransform x, want;
        ck_assert_int_eq(noctWorldGetTransform(w, id, &x), NOCT_OK);
        noctTrackAtTurns(k, turns, 3, t, &want);
        ck_assert(memcmp(&x.q, &want.q, sizeof x.q) == 0);
        if (t == 100 || t == 200) {
            char where[32];
            snprintf(where, sizeof where, "world, step %llu", (unsigned long long)t);
            turned_by(&x.q, t == 100 ? 90 : 180, where);
        }
    }
    /* set again without turns: none kept */
    ck_assert_int_eq(noctWorldSetTrack(w, id, k, 3, NULL), NOCT_OK);
    ck_assert_uint_eq(noctWorldGetTrackTurns(w, id, &kept), 0);
    ck_assert_ptr_null(kept);
    noctWorldDestroy(w);
}
END_TEST

START_TEST(bad_turns)
{
    tracked t;
    build(&t, NOCT_MAINTAIN_INCREMENTAL, 3, NOCT_EFFECT_EVENTS | NOCT_EFFECT_TRACK);
    const noctKeyframe *before;
    const size_t nbefore = noctWorldGetTrack(t.w, t.id[0], &before);
    noctKeyframe k[2] = {{0, noctIdentityTransform()}, {4, noctIdentityTransform()}};
    const double z[3] = {0, 0, 1};
    ck_assert_int_eq(noctQuatFromAxisAngle(z, 270, &k[1].x.q), NOCT_OK);
    noctKeyTurn turns[2] = {{{0, 0, 0}, 0}, {{0, 0, 1}, 270}};
    noctError err;
    ck_assert_int_eq(noctWorldSetTrackTurns(t.w, t.id[1], k, turns, 2, &err), NOCT_OK);
    turns[1].axis[1] = NAN;
    ck_assert_int_eq(noctWorldSetTrackTurns(t.w, t.id[0], k, turns, 2, &err),
                     NOCT_ERR_NONFINITE);
    ck_assert_ptr_nonnull(strstr(err.message, "keyframe 1"));
    turns[1] = (noctKeyTurn){{0, 0, 1}, INFINITY};
    ck_assert_int_eq(noctWorldSetTrackTurns(t.w, t.id[0], k, turns, 2, &err),
                     NOCT_ERR_NONFINITE);
    /* 270 + 360 also ends at the key's rotation, but is 157.5 a tick; 720
     * is 180 a tick, half a turn: too fast */
    turns[1] = (noctKeyTurn){{0, 0, 1}, 630};
    ck_assert_int_eq(noctWorldSetTrackTurns(t.w, t.id[0], k, turns, 2, &err), NOCT_OK);
    turns[1] = (noctKeyTurn){{0, 0, 1}, 990};
    ck_assert_int_eq(noctWorldSetTrackTurns(t.w, t.id[0], k, turns, 2, &err), NOCT_ERR_INVALID);
    ck_assert_ptr_nonnull(strstr(err.message, "half a turn a tick"));
    /* a turn that does not lead to the key's rotation */
    turns[1] = (noctKeyTurn){{0, 0, 1}, 90};
    ck_assert_int_eq(noctWorldSetTrackTurns(t.w, t.id[0], k, turns, 2, &err), NOCT_ERR_INVALID);
    ck_assert_ptr_nonnull(strstr(err.message, "does not give its rotation"));
    turns[1] = (noctKeyTurn){{1, 0, 0}, 270};
    ck_assert_int_eq(noctWorldSetTrackTurns(t.w, t.id[0], k, turns, 2, &err), NOCT_ERR_INVALID);
    /* turns[0] is not read */
    turns[0] = (noctKeyTurn){{NAN, 0, 0}, NAN};
    turns[1] = (noctKeyTurn){{0, 0, 1}, -90};
    ck_assert_int_eq(noctWorldSetTrackTurns(t.w, t.id[2], k, turns, 2, &err), NOCT_OK);
    /* the failures changed nothing: object 0 keeps its track, turns and all */
    const noctKeyframe *after;
    const noctKeyTurn *kept;
    ck_assert_uint_eq(noctWorldGetTrack(t.w, t.id[0], &after), 2);
    ck_assert_uint_eq(noctWorldGetTrackTurns(t.w, t.id[0], &kept), 2);
    ck_assert(kept[1].degrees == 630);
    (void)nbefore;
    (void)before;
    destroy(&t);
}
END_TEST

/* The same 270 degrees through a scene file (key ... turn), and what
 * turn lines may not do. */
START_TEST(scene_turns)
{
    char *path = write_scene("steps 300\n"
                             "mesh bar box 1 0.1 0.1\n"
                             "object bar 0 0 0 name bar\n"
                             "key 0 0 0 0\n"
                             "key 300 0 0 0 turn 0 0 1 270  # three quarters round\n"
                             "key 304 0 0 0 turn 0 0 1 -360\n");
    noctScene *s;
    noctError err;
    ck_assert_msg(noctSceneRead(path, &s, &err) == NOCT_OK, "%s", err.message);
    unlink(path);
    noctWorld *w;
    ck_assert_int_eq(noctSceneBuild(s, &w, &err), NOCT_OK);
    noctObjectId bar = {0, 1};
    const noctKeyframe *k;
    ck_assert_uint_eq(noctWorldGetTrack(w, bar, &k), 3);
    turned_by(&k[1].x.q, 270, "key 300");
    turned_by(&k[2].x.q, -90, "key 304");
    const noctKeyTurn *t;
    ck_assert_uint_eq(noctWorldGetTrackTurns(w, bar, &t), 3);
    ck_assert(t[1].degrees == 270 && t[2].degrees == -360);
    for (int step = 1; step <= 304; ++step) {
        ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
        noctTransform x;
        ck_assert_int_eq(noctWorldGetTransform(w, bar, &x), NOCT_OK);
        char where[32];
        snprintf(where, sizeof where, "scene, step %d", step);
        long double want = step <= 300 ? 270.0L * step / 300 : 270 - 90.0L * (step - 300);
        if (step % 25 == 0 || step > 300)
            turned_by(&x.q, want, where);
    }
    noctWorldDestroy(w);
    noctSceneDestroy(s);

    scene_error("mesh c box 1 1 1\nobject c 0 0 0\nkey 0 0 0 0 turn 0 0 1 90\n",
                NOCT_ERR_INVALID, ":3: a key's turn needs a key before it");
    scene_error("mesh c box 1 1 1\nobject c 0 0 0\nkey 0 0 0 0\nkey 2 0 0 0 turn 0 0 1 360\n",
                NOCT_ERR_INVALID, ":4: a turn of 360 degrees in 2 ticks is half a turn a tick");
    scene_error("mesh c box 1 1 1\nobject c 0 0 0\nkey 0 0 0 0\nkey 2 0 0 0 turn 0 0 0 90\n",
                NOCT_ERR_INVALID, ":4: a turn needs a non-zero axis");
    scene_error("mesh c box 1 1 1\nobject c 0 0 0\nkey 0 0 0 0\nkey 2 0 0 0 turn 0 0 1\n",
                NOCT_ERR_PARSE, ":4: missing turn axis and angle");
    scene_error("mesh c box 1 1 1\nobject c 0 0 0\nkey 0 0 0 0\nkey 2 0 0 0 turn 0 0 1 inf\n",
                NOCT_ERR_NONFINITE, ":4:");
    scene_error("mesh c box 1 1 1\nobject c 0 0 0\nkey 0 0 0 0\nkey 2 0 0 0 turn 0 0 1 359\n",
                NOCT_OK, NULL);
}
END_TEST

static Suite *tracks_suite(void)
{
    Suite *s = suite_create("tracks");
    TCase *tc = test_case(s, "tracks", 300, NULL);
    tcase_add_loop_test(tc, interpolation_against_the_formula, 0, 1);
    tcase_add_loop_test(tc, worlds_follow_their_tracks, 0, 1);
    add_tests(tc, without_the_effect_nothing_moves, a_failed_step_gives_the_placements_back,
              removal_and_replacement, bad_tracks, scene_keys, turns_honour_the_angle,
              bad_turns, scene_turns);
    TCase *full = test_case(s, "tracks, full", 300, "slow seeds");
    tcase_add_loop_test(full, interpolation_against_the_formula, 1, 2);
    tcase_add_loop_test(full, worlds_follow_their_tracks, 1, 2);
    return s;
}

int main(void)
{
    return run_suite(tracks_suite());
}
