/* SPDX-License-Identifier: MIT */
/*
 * Ignored pairs (noctWorldIgnorePair(), noctWorldIgnoreTouching()): the
 * handles' contracts; the events of a pair ignored and no longer ignored;
 * near pairs; the pairs touching at the start against a brute force of
 * the narrowphase on every pair (exact) and of the boxes (the box level),
 * with filters and sensors; scene files' 'ignore' lines.
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

static uint64_t rng = 0x19e0u;

static double uniform(void)
{
    return test_uniform(&rng);
}

/* A world of effects with a box of half-extent h at p; its handle. */
static noctObjectId add_box(noctWorld *w, double h, double x, double y, double z)
{
    noctObjectDef d = noctDefaultObjectDef();
    d.half_extents[0] = d.half_extents[1] = d.half_extents[2] = h;
    d.transform.p[0] = x;
    d.transform.p[1] = y;
    d.transform.p[2] = z;
    d.type = NOCT_OBJECT_KINEMATIC;
    noctObjectId id;
    ck_assert_int_eq(noctWorldCreateObject(w, &d, &id, NULL), NOCT_OK);
    return id;
}

static noctWorld *new_world(unsigned effects, double margin)
{
    noctWorldDef wd = noctDefaultWorldDef();
    wd.effects = effects;
    wd.margin = margin;
    noctWorld *w;
    ck_assert_int_eq(noctWorldCreate(&wd, &w, NULL), NOCT_OK);
    return w;
}

static bool same(noctObjectId a, noctObjectId b)
{
    return a.index == b.index && a.generation == b.generation;
}

START_TEST(contracts)
{
    noctWorld *w = new_world(NOCT_EFFECT_EVENTS, 0);
    noctObjectId a = add_box(w, 1, 0, 0, 0), b = add_box(w, 1, 1, 0, 0), c = add_box(w, 1, 5, 0, 0);
    noctError err;
    ck_assert(!noctWorldPairIgnored(w, a, b));
    ck_assert_int_eq(noctWorldIgnorePair(w, b, a, true, &err), NOCT_OK);
    ck_assert(noctWorldPairIgnored(w, a, b) && noctWorldPairIgnored(w, b, a));
    ck_assert(!noctWorldPairIgnored(w, a, c) && !noctWorldPairIgnored(w, b, c));
    ck_assert_int_eq(noctWorldIgnorePair(w, a, b, true, &err), NOCT_OK); /* twice: no change */
    ck_assert_int_eq(noctWorldIgnorePair(w, a, c, false, &err), NOCT_OK); /* not ignored */
    ck_assert(noctWorldPairIgnored(w, a, b) && !noctWorldPairIgnored(w, a, c));
    ck_assert_int_eq(noctWorldIgnorePair(w, a, a, true, &err), NOCT_ERR_INVALID);
    ck_assert_ptr_nonnull(strstr(err.message, "itself"));
    ck_assert(!noctWorldPairIgnored(w, a, a));
    ck_assert_int_eq(noctWorldIgnorePair(w, a, c, true, &err), NOCT_OK);
    /* removal forgets the object's pairs; its slot's next object is new */
    ck_assert_int_eq(noctWorldRemove(w, b, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldIgnorePair(w, a, b, true, &err), NOCT_ERR_INVALID);
    ck_assert_ptr_nonnull(strstr(err.message, "stale"));
    ck_assert_int_eq(noctWorldIgnorePair(w, b, a, false, &err), NOCT_ERR_INVALID);
    ck_assert(!noctWorldPairIgnored(w, a, b));
    noctObjectId b2 = add_box(w, 1, 1, 0, 0);
    ck_assert_uint_eq(b2.index, b.index);
    ck_assert(!noctWorldPairIgnored(w, a, b2));
    ck_assert(noctWorldPairIgnored(w, a, c)); /* the others stay */
    ck_assert_int_eq(noctWorldIgnorePair(w, a, c, false, &err), NOCT_OK);
    ck_assert(!noctWorldPairIgnored(w, a, c));
    noctWorldDestroy(w);
}
END_TEST

static bool count(void *context, noctObjectId id, void *user_data)
{
    (void)id;
    (void)user_data;
    ++*(size_t *)context;
    return true;
}

/* Two boxes that overlap, and a third near them: colliding and near
 * until ignored, ended then, begun again when no longer ignored. */
START_TEST(events_follow_the_ignoring)
{
    noctWorld *w = new_world(NOCT_EFFECT_EVENTS, 0.5);
    noctObjectId a = add_box(w, 1, 0, 0, 0), b = add_box(w, 1, 1.5, 0, 0),
                 c = add_box(w, 1, 0, 2.25, 0);
    const noctPair *p;
    ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    ck_assert_uint_eq(noctWorldColliding(w, &p), 1);
    ck_assert(same(p[0].a, a) && same(p[0].b, b));
    ck_assert_uint_eq(noctWorldNear(w, &p), 3); /* a-b, a-c (0.25 apart), b-c */
    ck_assert_int_eq(noctWorldIgnorePair(w, a, b, true, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldIgnorePair(w, c, a, true, NULL), NOCT_OK);
    /* nothing changes until the next step */
    ck_assert_uint_eq(noctWorldColliding(w, &p), 1);
    ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    ck_assert_uint_eq(noctWorldColliding(w, &p), 0);
    ck_assert_uint_eq(noctWorldEnded(w, &p), 1);
    ck_assert(same(p[0].a, a) && same(p[0].b, b));
    ck_assert_uint_eq(noctWorldBegan(w, &p), 0);
    ck_assert_uint_eq(noctWorldNear(w, &p), 1);
    ck_assert(same(p[0].a, b) && same(p[0].b, c));
    ck_assert_uint_eq(noctWorldNearEnded(w, &p), 2);
    /* the contacts see none */
    const noctContact *contacts;
    size_t n;
    ck_assert_int_eq(noctWorldContacts(w, &contacts, &n, NULL), NOCT_OK);
    ck_assert_uint_eq(n, 0);
    ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    ck_assert_uint_eq(noctWorldEnded(w, &p), 0);
    /* queries search no pairs: both objects as before */
    size_t found = 0;
    const double lo[3] = {0.25, -0.5, -0.5}, hi[3] = {0.75, 0.5, 0.5};
    ck_assert_int_eq(noctWorldQueryBox(w, lo, hi, noctDefaultQueryFilter(), count, &found, NULL),
                     NOCT_OK);
    ck_assert_uint_eq(found, 2);
    ck_assert_int_eq(noctWorldIgnorePair(w, b, a, false, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    ck_assert_uint_eq(noctWorldBegan(w, &p), 1);
    ck_assert(same(p[0].a, a) && same(p[0].b, b));
    ck_assert_uint_eq(noctWorldColliding(w, &p), 1);
    ck_assert_uint_eq(noctWorldNearBegan(w, &p), 1);
    noctWorldDestroy(w);
}
END_TEST

/* ---- the pairs touching at the start ------------------------------------------------- */

#define NOBJ 40

typedef struct scene {
    noctWorld *w;
    noctObjectId id[NOBJ];
    noctMesh *mesh[NOBJ]; /* the test's mesh of each box */
    uint64_t category[NOBJ], mask[NOBJ];
    bool sensor[NOBJ];
} scene;

/* Boxes, turned at random, crowded so that about a third of the pairs
 * that could touch do; some with filters, some sensors. */
static void build(scene *s, noctAccuracy accuracy)
{
    noctWorldDef wd = noctDefaultWorldDef();
    wd.effects = NOCT_EFFECT_EVENTS;
    wd.accuracy = accuracy;
    ck_assert_int_eq(noctWorldCreate(&wd, &s->w, NULL), NOCT_OK);
    for (int i = 0; i < NOBJ; ++i) {
        double h[3];
        for (int c = 0; c < 3; ++c)
            h[c] = 0.2 + 0.6 * uniform();
        ck_assert_int_eq(noctMeshCreateBox(h[0], h[1], h[2], &s->mesh[i], NULL), NOCT_OK);
        noctObjectDef d = noctDefaultObjectDef();
        if (i % 3 == 0)
            d.mesh = s->mesh[i];
        else
            memcpy(d.half_extents, h, sizeof h);
        for (int c = 0; c < 3; ++c)
            d.transform.p[c] = 6 * uniform();
        test_random_quat(&rng, &d.transform.q);
        d.type = i % 5 == 0 ? NOCT_OBJECT_STATIC : NOCT_OBJECT_KINEMATIC;
        d.category = i % 4 == 1 ? 2 : 1;
        d.mask = i % 7 == 2 ? 1 : NOCT_FILTER_ALL; /* some never meet category 2 */
        d.sensor = i % 9 == 4;
        s->category[i] = d.category;
        s->mask[i] = d.mask;
        s->sensor[i] = d.sensor;
        ck_assert_int_eq(noctWorldCreateObject(s->w, &d, &s->id[i], NULL), NOCT_OK);
    }
}

static void destroy(scene *s)
{
    noctWorldDestroy(s->w);
    for (int i = 0; i < NOBJ; ++i)
        noctMeshDestroy(s->mesh[i]);
}

/* Would a step pair i and j at all (filters, sensors)? */
static bool may_pair(const scene *s, int i, int j)
{
    return (s->category[i] & s->mask[j]) != 0 && (s->category[j] & s->mask[i]) != 0 &&
           !(s->sensor[i] && s->sensor[j]);
}

/* Do i and j touch, by brute force: the narrowphase on the test's meshes
 * (exact), or the placed boxes (the box level)? */
static bool touch(const scene *s, int i, int j, noctAccuracy accuracy)
{
    if (accuracy == NOCT_ACCURACY_BOX) {
        double alo[3], ahi[3], blo[3], bhi[3];
        ck_assert_int_eq(noctWorldObjectBox(s->w, s->id[i], alo, ahi), NOCT_OK);
        ck_assert_int_eq(noctWorldObjectBox(s->w, s->id[j], blo, bhi), NOCT_OK);
        for (int c = 0; c < 3; ++c)
            if (ahi[c] < blo[c] || bhi[c] < alo[c])
                return false;
        return true;
    }
    noctTransform a, b;
    ck_assert_int_eq(noctWorldGetTransform(s->w, s->id[i], &a), NOCT_OK);
    ck_assert_int_eq(noctWorldGetTransform(s->w, s->id[j], &b), NOCT_OK);
    bool hit;
    ck_assert_int_eq(noctCollideTransformed(s->mesh[i], &a, s->mesh[j], &b, NOCT_ACCURACY_EXACT,
                                            &hit, NULL, NULL),
                     NOCT_OK);
    return hit;
}

/* _i: the accuracy, exact or box. */
START_TEST(touching_against_a_brute_force)
{
    const noctAccuracy accuracy = _i ? NOCT_ACCURACY_BOX : NOCT_ACCURACY_EXACT;
    int touching_total = 0;
    for (int round = 0; round < 6; ++round) {
        scene s;
        build(&s, accuracy);
        /* one pair ignored beforehand: not counted again */
        bool pre = false;
        for (int i = 0; i < NOBJ && !pre; ++i)
            for (int j = i + 1; j < NOBJ && !pre; ++j)
                if (may_pair(&s, i, j) && touch(&s, i, j, accuracy)) {
                    ck_assert_int_eq(noctWorldIgnorePair(s.w, s.id[i], s.id[j], true, NULL),
                                     NOCT_OK);
                    pre = true;
                }
        size_t count;
        noctError err;
        ck_assert_msg(noctWorldIgnoreTouching(s.w, &count, &err) == NOCT_OK, "%s", err.message);
        size_t want = 0;
        for (int i = 0; i < NOBJ; ++i)
            for (int j = i + 1; j < NOBJ; ++j) {
                const bool t = may_pair(&s, i, j) && touch(&s, i, j, accuracy);
                want += t;
                ck_assert_msg(noctWorldPairIgnored(s.w, s.id[i], s.id[j]) == t,
                              "round %d, pair %d-%d: ignored %d, touching %d", round, i, j,
                              !t, t);
            }
        ck_assert_uint_eq(count + pre, want);
        touching_total += (int)want;
        /* a step where nothing moves: no contact at all */
        ck_assert_int_eq(noctWorldStep(s.w, NULL), NOCT_OK);
        const noctPair *p;
        ck_assert_uint_eq(noctWorldColliding(s.w, &p), 0);
        ck_assert_uint_eq(noctWorldSensing(s.w, &p), 0);
        /* again: nothing new */
        ck_assert_int_eq(noctWorldIgnoreTouching(s.w, &count, NULL), NOCT_OK);
        ck_assert_uint_eq(count, 0);
        /* a kinematic object moved onto another it did not touch: that
         * pair alone begins */
        int mover = -1, other = -1;
        for (int i = 1; i < NOBJ && mover < 0; ++i)
            for (int j = 0; j < NOBJ && mover < 0; ++j)
                if (i % 5 != 0 && j != i && may_pair(&s, i, j) && !s.sensor[i] &&
                    !s.sensor[j] && !noctWorldPairIgnored(s.w, s.id[i], s.id[j])) {
                    mover = i;
                    other = j;
                }
        ck_assert_int_ge(mover, 0);
        noctTransform x;
        ck_assert_int_eq(noctWorldGetTransform(s.w, s.id[other], &x), NOCT_OK);
        ck_assert_int_eq(noctWorldSetTransform(s.w, s.id[mover], &x, NULL), NOCT_OK);
        ck_assert_int_eq(noctWorldStep(s.w, NULL), NOCT_OK);
        const size_t nb = noctWorldBegan(s.w, &p);
        size_t want_began = 0;
        for (int j = 0; j < NOBJ; ++j)
            if (j != mover && may_pair(&s, mover, j) && !s.sensor[j] && !s.sensor[mover] &&
                !noctWorldPairIgnored(s.w, s.id[mover], s.id[j]) &&
                touch(&s, mover, j, accuracy))
                ++want_began;
        ck_assert_uint_ge(want_began, 1);
        ck_assert_uint_eq(nb, want_began);
        for (size_t k = 0; k < nb; ++k)
            ck_assert(p[k].a.index == s.id[mover].index || p[k].b.index == s.id[mover].index);
        destroy(&s);
    }
    ck_assert_int_gt(touching_total, 30); /* the test saw touching pairs */
}
END_TEST

/* ---- scene files ------------------------------------------------------------------------- */

static char *write_scene(const char *text)
{
    static char path[64];
    strcpy(path, "/tmp/check-ignore-XXXXXX");
    int fd = mkstemp(path);
    ck_assert_int_ge(fd, 0);
    FILE *f = fdopen(fd, "w");
    ck_assert_ptr_nonnull(f);
    fputs(text, f);
    fclose(f);
    return path;
}

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

/* A block resting on a floor, and a box that falls onto the block:
 * without ignoring, the first contact is at step 1 (the block on the
 * floor); with 'ignore initial' or 'ignore block floor', the falling
 * box's (its bottom at 3.5 - 0.5 s after step s, on the block's top at
 * z = 1 at s = 5). */
START_TEST(scene_ignores)
{
    static const char *const BASE =
        "effects motion events\n"
        "mesh floor box 5 5 0.5\nmesh block box 0.5 0.5 0.5\n"
        "object floor 0 0 -0.5 type static name floor\n"
        "object block 0 0 0.5 type static name block\n" /* on the floor, z 0 to 1 */
        "object block 0 0 4 velocity 0 0 -0.5 name falling\n"; /* z 3.5 to 4.5 */
    static const struct { const char *extra; int first; size_t ignored; } CASES[] = {
        {"", 1, 0},
        {"ignore initial\n", 5, 1},
        {"ignore block floor\n", 5, 1},
        {"ignore falling block\n", 1, 1},
        {"ignore floor block\nignore initial\n", 5, 1},
    };
    for (size_t c = 0; c < sizeof CASES / sizeof *CASES; ++c) {
        char text[1024];
        snprintf(text, sizeof text, "%s%s", BASE, CASES[c].extra);
        char *path = write_scene(text);
        noctScene *s;
        noctError err;
        ck_assert_msg(noctSceneRead(path, &s, &err) == NOCT_OK, "%s", err.message);
        unlink(path);
        ck_assert(noctSceneIgnoresInitial(s) == (strstr(CASES[c].extra, "initial") != NULL));
        noctWorld *w;
        ck_assert_int_eq(noctSceneBuild(s, &w, &err), NOCT_OK);
        const noctObjectId floor = {0, 1}, block = {1, 1}, falling = {2, 1};
        size_t ignored = noctWorldPairIgnored(w, floor, block) +
                         noctWorldPairIgnored(w, floor, falling) +
                         noctWorldPairIgnored(w, block, falling);
        ck_assert_uint_eq(ignored, CASES[c].ignored);
        int first = 0;
        for (int step = 1; step <= 8 && first == 0; ++step) {
            ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
            const noctPair *p;
            if (noctWorldColliding(w, &p) > 0)
                first = step;
        }
        ck_assert_msg(first == CASES[c].first, "case %zu: first contact at step %d, want %d", c,
                      first, CASES[c].first);
        noctWorldDestroy(w);
        noctSceneDestroy(s);
    }
    /* set on a scene read without it */
    char *path = write_scene(BASE);
    noctScene *s;
    ck_assert_int_eq(noctSceneRead(path, &s, NULL), NOCT_OK);
    unlink(path);
    ck_assert(!noctSceneIgnoresInitial(s));
    noctSceneSetIgnoreInitial(s, true);
    ck_assert(noctSceneIgnoresInitial(s));
    noctWorld *w;
    ck_assert_int_eq(noctSceneBuild(s, &w, NULL), NOCT_OK);
    ck_assert(noctWorldPairIgnored(w, (noctObjectId){0, 1}, (noctObjectId){1, 1}));
    noctWorldDestroy(w);
    noctSceneDestroy(s);

    char text[1024];
    snprintf(text, sizeof text, "%s%s", BASE, "ignore floor nowhere\n");
    scene_error(text, NOCT_ERR_INVALID, ":7: ignore: no object named 'nowhere' above this line");
    snprintf(text, sizeof text, "%s%s", BASE, "ignore block block\n");
    scene_error(text, NOCT_ERR_INVALID, ":7: ignore: 'block' is the same object twice");
    snprintf(text, sizeof text, "%s%s", BASE, "ignore everything\n");
    scene_error(text, NOCT_ERR_PARSE, ":7: expected 'ignore initial' or 'ignore NAME NAME'");
    snprintf(text, sizeof text, "%s%s", BASE, "ignore\n");
    scene_error(text, NOCT_ERR_PARSE, ":7: expected 'ignore initial'");
    snprintf(text, sizeof text, "%s%s", BASE, "ignore floor block falling\n");
    scene_error(text, NOCT_ERR_PARSE, ":7: unexpected 'falling'");
    scene_error("ignore a b\nmesh c box 1 1 1\nobject c 0 0 0 name a\nobject c 0 0 0 name b\n",
                NOCT_ERR_INVALID, ":1: ignore: no object named 'a' above");
    /* an object named 'initial' is a name like another */
    scene_error("mesh c box 1 1 1\nobject c 0 0 0 name initial\nobject c 0 0 0 name b\n"
                "ignore initial b\nignore initial\n",
                NOCT_OK, NULL);
}
END_TEST

static Suite *ignore_suite(void)
{
    Suite *s = suite_create("ignore");
    TCase *tc = test_case(s, "ignore", 120, NULL);
    add_tests(tc, contracts, events_follow_the_ignoring, scene_ignores);
    tcase_add_loop_test(tc, touching_against_a_brute_force, 0, 2);
    return s;
}

int main(void)
{
    return run_suite(ignore_suite());
}
