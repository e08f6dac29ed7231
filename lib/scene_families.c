/* SPDX-License-Identifier: MIT */
/*
 * The families made of objects and tracks, built as scenes (so that
 * noctSceneWrite() writes them as files): arms:K, two robot arms of K
 * links swinging in a bay, and keyframes:N, N boxes moving along
 * keyframes through each other. Their definitions are in noctree-sim(1);
 * the tests check them against an independent computation.
 */
#include "config.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "internal.h"
#include "scene_internal.h"

#define PI 3.14159265358979323846

/* ---- arms:K -------------------------------------------------------------------- */

enum { BAY = 1, LOOSE = 2, ARM_A = 4, ARM_B = 8 };

#define ARMS_STEPS 240

static noctStatus add_box(noctScene *s, const char *name, double hx, double hy, double hz)
{
    return noct_scene_add_mesh(s, name, NULL, (const double[3]){hx, hy, hz}, NULL);
}

static noctStatus add_static(noctScene *s, size_t mesh, double x, double y, double z,
                             uint64_t category, uint64_t mask)
{
    scene_object o = noct_scene_object(mesh, (const double[3]){x, y, z});
    o.type = NOCT_OBJECT_STATIC;
    o.has_type = true;
    o.category = category;
    o.mask = mask;
    return noct_scene_add_object(s, &o);
}

/* Joint j of arm a at tick t, in degrees: a triangle wave between its
 * limits, from the stretched-out end (0) at tick 0. */
static double joint_angle(int a, int j, uint64_t t)
{
    const double period = 40 + 12 * j + 10 * a;
    const double u = (double)t / period;
    const double f = u - floor(u);
    const double tri = 1 - fabs(2 * f - 1);
    return j == 0 ? 80 * tri : -45 * tri;
}

noctStatus noct_scene_arms(noctScene *s, long k, noctError *err)
{
    if (k < 1 || k > 8)
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0, "arms:%ld: K must be 1 to 8", k);
    const double K = (double)k, d = 2 * K - 0.5;
    s->steps = ARMS_STEPS;
    s->def.effects = NOCT_EFFECT_EVENTS | NOCT_EFFECT_TRACK;
    /* meshes: 0 floor, 1 ceiling, 2 x walls, 3 y walls, 4 loose box, 5 link;
     * the floor as deep as the arms reach below it when they curl */
    noctStatus st = NOCT_OK;
    if ((st = add_box(s, "floor", d + 2, 2.5, K)) != NOCT_OK ||
        (st = add_box(s, "ceiling", d + 2, 2.5, 0.25)) != NOCT_OK ||
        (st = add_box(s, "xwall", 0.25, 2.5, K + 1.5)) != NOCT_OK ||
        (st = add_box(s, "ywall", d + 2, 0.25, K + 1.5)) != NOCT_OK ||
        (st = add_box(s, "loose", 0.3, 0.3, 0.3)) != NOCT_OK ||
        (st = add_box(s, "link", 1, 0.2, 0.2)) != NOCT_OK)
        return noct_fail(err, st, -1, 0, "out of memory");
    const uint64_t arms = ARM_A | ARM_B;
    /* the bay: floor, ceiling, -x, +x, -y, +y */
    if ((st = add_static(s, 0, 0, 0, -K, BAY, arms)) != NOCT_OK ||
        (st = add_static(s, 1, 0, 0, 2 * K + 2.25, BAY, arms)) != NOCT_OK ||
        (st = add_static(s, 2, -(d + 1.75), 0, K + 1, BAY, arms)) != NOCT_OK ||
        (st = add_static(s, 2, d + 1.75, 0, K + 1, BAY, arms)) != NOCT_OK ||
        (st = add_static(s, 3, 0, -2.25, K + 1, BAY, arms)) != NOCT_OK ||
        (st = add_static(s, 3, 0, 2.25, K + 1, BAY, arms)) != NOCT_OK)
        return noct_fail(err, st, -1, 0, "out of memory");
    /* loose boxes on the floor, in the arms' plane and beside it */
    for (int m = 0; d - 1.5 - 2.5 * m > 1; ++m) {
        const double x = d - 1.5 - 2.5 * m;
        if ((st = add_static(s, 4, -x, 0, 0.3, LOOSE, arms)) != NOCT_OK ||
            (st = add_static(s, 4, x, 0, 0.3, LOOSE, arms)) != NOCT_OK ||
            (st = add_static(s, 4, -x, 1.2, 0.3, LOOSE, arms)) != NOCT_OK ||
            (st = add_static(s, 4, x, 1.2, 0.3, LOOSE, arms)) != NOCT_OK)
            return noct_fail(err, st, -1, 0, "out of memory");
    }
    /* the links, each with a keyframe at every tick: forward kinematics */
    for (int a = 0; a < 2; ++a) {
        const double side = a == 0 ? 1 : -1;
        for (int j = 0; j < (int)k; ++j) {
            scene_object o = noct_scene_object(5, (const double[3]){0, 0, 0});
            o.type = NOCT_OBJECT_KINEMATIC;
            o.has_type = true;
            o.category = a == 0 ? ARM_A : ARM_B;
            o.mask = BAY | LOOSE | (a == 0 ? ARM_B : ARM_A);
            if ((st = noct_scene_add_object(s, &o)) != NOCT_OK)
                return noct_fail(err, st, -1, 0, "out of memory");
            for (uint64_t t = 0; t <= ARMS_STEPS; ++t) {
                double joint[3] = {-side * d, 0, 1}, phi = 0, u[3];
                for (int i = 0; i <= j; ++i) {
                    phi += joint_angle(a, i, t);
                    u[0] = side * cos(phi * PI / 180);
                    u[1] = 0;
                    u[2] = sin(phi * PI / 180);
                    if (i < j)
                        for (int c = 0; c < 3; ++c)
                            joint[c] += 2 * u[c];
                }
                scene_key key;
                memset(&key, 0, sizeof key);
                key.k.tick = t;
                for (int c = 0; c < 3; ++c)
                    key.k.x.p[c] = joint[c] + u[c];
                key.turn = (scene_turn){true, {0, 1, 0}, a == 0 ? -phi : 180 + phi};
                noctQuatFromAxisAngle(key.turn.axis, key.turn.degrees, &key.k.x.q);
                if ((st = noct_scene_add_key(s, &key)) != NOCT_OK)
                    return noct_fail(err, st, -1, 0, "out of memory");
            }
        }
    }
    return NOCT_OK;
}

/* ---- keyframes:N ------------------------------------------------------------------- */

#define KEYFRAMES_STEPS 200
#define KEYFRAMES_KEYS 5

static uint64_t splitmix64(uint64_t *state)
{
    uint64_t z = (*state += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}

static double draw(uint64_t *state)
{
    return (double)(splitmix64(state) >> 11) * 0x1p-53;
}

noctStatus noct_scene_keyframes(noctScene *s, long n, noctError *err)
{
    if (n < 1 || n > 100000)
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0, "keyframes:%ld: N must be 1 to 100000",
                         n);
    s->steps = KEYFRAMES_STEPS;
    s->def.effects = NOCT_EFFECT_EVENTS | NOCT_EFFECT_TRACK;
    const double L = 4 * cbrt((double)n);
    uint64_t st64 = 1234;
    noctStatus st;
    for (long i = 0; i < n; ++i) {
        double h[3];
        for (int c = 0; c < 3; ++c)
            h[c] = 0.25 + 0.5 * draw(&st64);
        char name[32];
        snprintf(name, sizeof name, "box%ld", i);
        if ((st = noct_scene_add_mesh(s, name, NULL, h, NULL)) != NOCT_OK)
            return noct_fail(err, st, -1, 0, "out of memory");
        scene_object o = noct_scene_object(s->nmeshes - 1, (const double[3]){0, 0, 0});
        o.type = NOCT_OBJECT_KINEMATIC;
        o.has_type = true;
        if ((st = noct_scene_add_object(s, &o)) != NOCT_OK)
            return noct_fail(err, st, -1, 0, "out of memory");
        for (int j = 0; j < KEYFRAMES_KEYS; ++j) {
            scene_key key;
            memset(&key, 0, sizeof key);
            key.k.tick = (uint64_t)(j * (KEYFRAMES_STEPS / (KEYFRAMES_KEYS - 1)));
            for (int c = 0; c < 3; ++c)
                key.k.x.p[c] = L * draw(&st64);
            const double zz = 2 * draw(&st64) - 1, az = 360 * draw(&st64);
            const double r = sqrt(1 - zz * zz);
            key.turn = (scene_turn){true, {r * cos(az * PI / 180), r * sin(az * PI / 180), zz},
                                    360 * draw(&st64) - 180};
            if (noctQuatFromAxisAngle(key.turn.axis, key.turn.degrees, &key.k.x.q) != NOCT_OK) {
                /* (never: the axis's z is +-1 when its x and y are 0) */
                key.turn = (scene_turn){false, {0, 0, 0}, 0};
                key.k.x.q = (noctQuat){0, 0, 0, 1};
            }
            if ((st = noct_scene_add_key(s, &key)) != NOCT_OK)
                return noct_fail(err, st, -1, 0, "out of memory");
        }
    }
    return NOCT_OK;
}
