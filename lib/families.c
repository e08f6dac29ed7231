/* SPDX-License-Identifier: MIT */
/*
 * The built-in families of noctree-families(7), one row each in
 * FAMILIES below: the report's planes t_k, the gas of oriented boxes and
 * its kinds (mixed, clusters, static, escape), the bullets that tunnel,
 * the robot arms and the keyframed boxes. Each row has the family's name, its size's range and
 * its builders (families_internal.h); noctSceneFamily(), the scene files'
 * 'family' lines (noctree-scene(5)), noctSceneWrite() and noctSceneBuild()
 * go through the table, and so do the world.h builders kept for
 * compatibility. Families are not part of the world's core: they build
 * through its API. The tests check them against an independent
 * computation.
 */
#include "config.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <noctree/world.h>

#include "families_internal.h"
#include "internal.h"
#include "scene_internal.h"
#include "world_internal.h"

#define PI 3.14159265358979323846

/* The rows of FAMILIES, in the order of the specs' list. */
enum { FAM_PLANES, FAM_GAS, FAM_MIXED, FAM_CLUSTERS, FAM_STATIC, FAM_ESCAPE, FAM_BULLETS,
       FAM_NOTCH, FAM_ARMS, FAM_KEYFRAMES, FAM_ROWS };

/* The kinds of gas: the plain one, mixed sizes, dense clusters, mostly
 * static, escaping outward. */
enum { GAS_UNIFORM, GAS_MIXED, GAS_CLUSTERS, GAS_STATIC, GAS_ESCAPE };

/* splitmix64, and its doubles in [0, 1), as noctree-families(7) defines them: the
 * gas's draws (from 42) and the keyframes' (from 1234). */
static uint64_t fam_splitmix64(uint64_t *state)
{
    uint64_t z = (*state += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}

static double fam_draw(uint64_t *state)
{
    return (double)(fam_splitmix64(state) >> 11) * 0x1p-53;
}

/* INVALID: f's size (as text) out of its range. */
static noctStatus fam_range(const noct_family *f, const char *size, noctError *err)
{
    return noct_fail(err, NOCT_ERR_INVALID, -1, 0, "%s: %s %s; it must be %ld to %ld", f->name,
                     size, f->unit, f->lo, f->hi);
}

static noctStatus fam_check(const noct_family *f, long size, noctError *err)
{
    if (size >= f->lo && size <= f->hi)
        return NOCT_OK;
    char text[24];
    snprintf(text, sizeof text, "%ld", size);
    return fam_range(f, text, err);
}

/* Undo a builder's additions after a failure: remove the n objects it
 * added (removal cannot fail). */
static noctStatus fam_unbuild(noctWorld *w, noctObjectId *ids, size_t n, noctStatus st)
{
    for (size_t i = 0; i < n; ++i)
        noctWorldRemove(w, ids[i], NULL);
    free(ids);
    return st;
}

/* ---- the families a scene keeps by name and size ------------------------------- */

static uint64_t fam_planes_objects(long k)
{
    return 2 * (uint64_t)(2 * k + 1) * (uint64_t)(2 * k + 1);
}

static noctStatus fam_planes_add(noctWorld *w, const noct_family *f, long size,
                                 const noctMesh *const *meshes, noctError *err)
{
    const noctMesh *unit_cube = meshes[FAM_MESH_UNIT_CUBE];
    NOCT_REQUIRE(w != NULL && unit_cube != NULL);
    noctStatus st = fam_check(f, size, err);
    if (st != NOCT_OK)
        return st;
    const int k = (int)size;
    const size_t total = (size_t)fam_planes_objects(size);
    noctObjectId *ids = malloc(total * sizeof *ids);
    if (ids == NULL)
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    size_t n = 0;
    for (int side = 0; side < 2; ++side) {
        const double dir[3] = {side == 0 ? 1 : -1, 0, 0};
        for (int i = -k; i <= k; ++i)
            for (int j = -k; j <= k; ++j) {
                int r = abs(i) > abs(j) ? abs(i) : abs(j);
                double x = 3.02 + 0.1 * r;
                double pos[3] = {side == 0 ? -x : x, 2.0 * i, 2.0 * j};
                st = noctWorldAdd(w, unit_cube, pos, dir, 0.05, &ids[n], err);
                if (st != NOCT_OK)
                    return fam_unbuild(w, ids, n, st);
                ++n;
            }
    }
    free(ids);
    return NOCT_OK;
}

/* notch:N, N pairs of a static U-shaped prism and a cube moving in its
 * notch (noctree-sim(1) defines it). */
#define NOTCH_T 0.25

static uint64_t fam_notch_objects(long n)
{
    return 2 * (uint64_t)n;
}

/* The U-shaped prism: the outline below, counter-clockwise seen from +z,
 * from z = 0 to 1, its caps cut into triangles. */
static noctStatus fam_notch_mesh(noctMesh **u, noctError *err)
{
    const double t = NOTCH_T;
    const double outline[8][2] = {{0, 0}, {3, 0}, {3, 3}, {3 - t, 3},
                                  {3 - t, t}, {t, t}, {t, 3}, {0, 3}};
    static const uint32_t cap[6][3] = {{0, 1, 4}, {0, 4, 5}, {1, 2, 3},
                                       {1, 3, 4}, {0, 5, 6}, {0, 6, 7}};
    double v[16 * 3];
    for (int i = 0; i < 16; ++i) {
        v[3 * i] = outline[i % 8][0];
        v[3 * i + 1] = outline[i % 8][1];
        v[3 * i + 2] = i < 8 ? 0 : 1;
    }
    uint32_t idx[28 * 3], sizes[28];
    size_t n = 0;
    for (int i = 0; i < 6; ++i) {
        const uint32_t top[3] = {cap[i][0] + 8, cap[i][1] + 8, cap[i][2] + 8};
        const uint32_t bottom[3] = {cap[i][0], cap[i][2], cap[i][1]};
        memcpy(&idx[n], top, sizeof top);
        memcpy(&idx[n + 3], bottom, sizeof bottom);
        n += 6;
    }
    for (uint32_t i = 0; i < 8; ++i) {
        const uint32_t j = (i + 1) % 8;
        const uint32_t side[6] = {i, j, j + 8, i, j + 8, i + 8};
        memcpy(&idx[n], side, sizeof side);
        n += 6;
    }
    for (int i = 0; i < 28; ++i)
        sizes[i] = 3;
    return noctMeshCreate(v, 16, sizes, 28, idx, u, err);
}

static noctStatus fam_notch_add(noctWorld *w, const noct_family *f, long size,
                                const noctMesh *const *meshes, noctError *err)
{
    const noctMesh *u = meshes[FAM_MESH_NOTCH_U], *cube = meshes[FAM_MESH_NOTCH_CUBE];
    NOCT_REQUIRE(w != NULL && u != NULL && cube != NULL);
    noctStatus st = fam_check(f, size, err);
    if (st != NOCT_OK)
        return st;
    const long n = size, g = (long)ceil(sqrt((double)n));
    noctObjectId *ids = malloc((size_t)fam_notch_objects(n) * sizeof *ids);
    if (ids == NULL)
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    uint64_t seed = 42;
    size_t k = 0;
    for (long i = 0; i < n; ++i) {
        const double base[3] = {5.0 * (double)(i % g), 5.0 * (double)(i / g), 0};
        seed = seed * 6364136223846793005u + 1442695040888963407u; /* an LCG */
        const double r = (double)(seed >> 11) * 0x1p-53;
        const double at[3] = {base[0] + NOTCH_T + 0.15 + r * (3 - 2 * NOTCH_T - 0.3),
                              base[1] + 1.5, 0.5};
        const double dir[3] = {i % 4 < 2 ? 1 : -1, 0, 0};
        if ((st = noctWorldAdd(w, u, base, dir, 0, &ids[k], err)) != NOCT_OK)
            return fam_unbuild(w, ids, k, st);
        ++k;
        if ((st = noctWorldAdd(w, cube, at, dir, i % 2 ? 0.7 : 0.04, &ids[k], err)) != NOCT_OK)
            return fam_unbuild(w, ids, k, st);
        ++k;
    }
    free(ids);
    return NOCT_OK;
}

/* The side of a gas kind's container [0, L]^3 for n boxes. */
static double fam_container(const noct_family *f, size_t n)
{
    return cbrt(f->volume * (double)n);
}

/* A box's scale in the mixed kind, from its extra draw w. */
static double fam_mixed_scale(double w)
{
    return w < 0.5 ? 0.5 : w < 0.8 ? 1 : w < 0.95 ? 2 : 4;
}

static uint64_t fam_gas_objects(long n)
{
    return (uint64_t)n;
}

static noctStatus fam_gas_add(noctWorld *w, const noct_family *f, long size,
                              const noctMesh *const *meshes, noctError *err)
{
    NOCT_REQUIRE(w != NULL);
    (void)meshes;
    noctStatus st = fam_check(f, size, err);
    if (st != NOCT_OK)
        return st;
    const int kind = f->kind;
    const size_t n = (size_t)size;
    /* room for them all at once: no per-slot array grows by doubling */
    if ((st = noctWorldReserve(w, n, err)) != NOCT_OK)
        return st;
    const size_t nclusters = (n + 999) / 1000;
    noctObjectId *ids = malloc(n * sizeof *ids);
    double *cluster = kind == GAS_CLUSTERS ? malloc(3 * nclusters * sizeof *cluster) : NULL;
    if (ids == NULL || (kind == GAS_CLUSTERS && cluster == NULL)) {
        free(ids);
        free(cluster);
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    }
    const double pi = 3.141592653589793;
    const double lb = fam_container(f, n);
    uint64_t state = 42;
    for (size_t c = 0; c < 3 * nclusters && cluster != NULL; ++c)
        cluster[c] = lb * fam_draw(&state);
    size_t i = 0;
    for (; i < n; ++i) {
        double half[3];
        for (int k = 0; k < 3; ++k)
            half[k] = 0.25 + 0.5 * fam_draw(&state);
        double u1 = fam_draw(&state), u2 = fam_draw(&state);
        double u3 = fam_draw(&state);
        double x = sqrt(1 - u1) * sin(2 * pi * u2), y = sqrt(1 - u1) * cos(2 * pi * u2);
        double z = sqrt(u1) * sin(2 * pi * u3), qw = sqrt(u1) * cos(2 * pi * u3);
        double centre[3];
        for (int k = 0; k < 3; ++k)
            centre[k] = kind == GAS_CLUSTERS
                            ? cluster[3 * (i % nclusters) + (size_t)k] +
                                  15 * (fam_draw(&state) - 0.5)
                            : lb * fam_draw(&state);
        double dz = 2 * fam_draw(&state) - 1, phi = 2 * pi * fam_draw(&state);
        double dir[3] = {sqrt(1 - dz * dz) * cos(phi), sqrt(1 - dz * dz) * sin(phi), dz};
        double speed = 0.05;
        noctObjectDef d = noctDefaultObjectDef();
        if (kind == GAS_MIXED) {
            const double s = fam_mixed_scale(fam_draw(&state));
            for (int k = 0; k < 3; ++k)
                half[k] *= s;
        } else if (kind == GAS_STATIC && !(fam_draw(&state) < 0.1)) {
            speed = 0;
            d.type = NOCT_OBJECT_STATIC;
        } else if (kind == GAS_ESCAPE) {
            speed = 0.2;
            for (int k = 0; k < 3; ++k)
                dir[k] = centre[k] - lb / 2;
        }
        /* a box primitive turned by (x, y, z, qw), whose matrix noctree-families(7)
         * gives: noctQuatToMatrix() computes that formula, in the same
         * order, and neither normalises nor snaps these quaternions
         * (tests/check_objects.c checks the first 100 000; the first
         * 3 000 000 were checked once); with the velocity noctWorldAdd()
         * would give it */
        memcpy(d.half_extents, half, sizeof half);
        memcpy(d.transform.p, centre, sizeof centre);
        d.transform.q = (noctQuat){x, y, z, qw};
        double unit[3];
        if (speed > 0 && !noct_unit_direction(dir, unit)) {
            st = noct_fail(err, NOCT_ERR_NUMERIC, (long)i, 0, "%s: box %zu has no direction",
                           f->name, i);
            break;
        }
        for (int k = 0; k < 3; ++k)
            d.velocity[k] = speed > 0 ? speed * unit[k] : 0;
        st = noct_world_add_object(w, &d, speed, &ids[i], err);
        if (st != NOCT_OK)
            break;
    }
    free(cluster);
    if (st != NOCT_OK)
        return fam_unbuild(w, ids, i, st);
    free(ids);
    return NOCT_OK;
}

/*
 * bullets:N (noctree-sim(1) defines it): a gas of boxes in the gas's
 * container with thin static plates, and one object in ten a bullet, a
 * thin square plate flying along its thin axis at 12.5 times its
 * thickness a step, so that it passes through plates and other bullets
 * between two steps. Object i is, by i mod 10: 0 a bullet, 1 and 2 a
 * plate, else a box; the draws, from splitmix64 seeded 4242, in the order
 * the code below makes them.
 */
#define BULLET_HALF 0.3
#define BULLET_THIN 0.02
#define BULLET_SPEED 0.5
#define PLATE_HALF 1.0
#define PLATE_THIN 0.02

static noctStatus fam_bullets_add(noctWorld *w, const noct_family *f, long size,
                                  const noctMesh *const *meshes, noctError *err)
{
    NOCT_REQUIRE(w != NULL);
    (void)meshes;
    noctStatus st = fam_check(f, size, err);
    if (st != NOCT_OK)
        return st;
    const size_t n = (size_t)size;
    if ((st = noctWorldReserve(w, n, err)) != NOCT_OK)
        return st;
    noctObjectId *ids = malloc(n * sizeof *ids);
    if (ids == NULL)
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    const double lb = fam_container(f, n);
    uint64_t state = 4242;
    size_t i = 0;
    for (; i < n; ++i) {
        noctObjectDef d = noctDefaultObjectDef();
        for (int k = 0; k < 3; ++k)
            d.transform.p[k] = lb * fam_draw(&state);
        if (i % 10 <= 2) {
            /* a bullet or a plate: thin along axis a, square across it;
             * a bullet flies along +a or -a */
            const int a = (int)(3 * fam_draw(&state)) % 3;
            const bool bullet = i % 10 == 0;
            for (int k = 0; k < 3; ++k)
                d.half_extents[k] = k == a ? (bullet ? BULLET_THIN : PLATE_THIN)
                                           : (bullet ? BULLET_HALF : PLATE_HALF);
            if (bullet)
                d.velocity[a] = fam_draw(&state) < 0.5 ? BULLET_SPEED : -BULLET_SPEED;
            else
                d.type = NOCT_OBJECT_STATIC;
        } else {
            /* a box of the gas: sizes, a turn and a direction as the
             * gas's, at its speed */
            for (int k = 0; k < 3; ++k)
                d.half_extents[k] = 0.25 + 0.5 * fam_draw(&state);
            const double u1 = fam_draw(&state), u2 = fam_draw(&state), u3 = fam_draw(&state);
            d.transform.q = (noctQuat){sqrt(1 - u1) * sin(2 * PI * u2),
                                       sqrt(1 - u1) * cos(2 * PI * u2),
                                       sqrt(u1) * sin(2 * PI * u3), sqrt(u1) * cos(2 * PI * u3)};
            const double dz = 2 * fam_draw(&state) - 1, phi = 2 * PI * fam_draw(&state);
            const double dir[3] = {sqrt(1 - dz * dz) * cos(phi), sqrt(1 - dz * dz) * sin(phi),
                                   dz};
            double unit[3];
            if (!noct_unit_direction(dir, unit)) {
                st = noct_fail(err, NOCT_ERR_NUMERIC, (long)i, 0, "%s: box %zu has no direction",
                               f->name, i);
                break;
            }
            for (int k = 0; k < 3; ++k)
                d.velocity[k] = 0.05 * unit[k];
        }
        const double speed = i % 10 == 0 ? BULLET_SPEED : i % 10 <= 2 ? 0 : 0.05;
        if ((st = noct_world_add_object(w, &d, speed, &ids[i], err)) != NOCT_OK)
            break;
    }
    if (st != NOCT_OK)
        return fam_unbuild(w, ids, i, st);
    free(ids);
    return NOCT_OK;
}

/* noctSceneFamily() for planes and the gas kinds: the family kept by
 * name and size, and a gas kind's container walls. */
static noctStatus fam_kept_make(noctScene *s, const noct_family *f, long size, noctError *err)
{
    if (noct_scene_add_family(s, f, size) != NOCT_OK)
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    if (f->walls) {
        const double lb = fam_container(f, (size_t)size);
        for (int k = 0; k < 3; ++k) {
            s->def.walls_lo[k] = 0;
            s->def.walls_hi[k] = lb;
        }
        s->def.effects |= NOCT_EFFECT_WALLS;
    }
    return NOCT_OK;
}

/* ---- arms:K -------------------------------------------------------------------- */

enum { BAY = 1, LOOSE = 2, ARM_A = 4, ARM_B = 8 };

#define ARMS_STEPS 240

static noctStatus fam_add_box(noctScene *s, const char *name, double hx, double hy, double hz)
{
    return noct_scene_add_mesh(s, name, NULL, (const double[3]){hx, hy, hz}, NULL);
}

static noctStatus fam_add_static(noctScene *s, size_t mesh, double x, double y, double z,
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
static double fam_joint_angle(int a, int j, uint64_t t)
{
    const double period = 40 + 12 * j + 10 * a;
    const double u = (double)t / period;
    const double f = u - floor(u);
    const double tri = 1 - fabs(2 * f - 1);
    return j == 0 ? 80 * tri : -45 * tri;
}

static noctStatus fam_arms_make(noctScene *s, const noct_family *f, long k, noctError *err)
{
    NOCT_REQUIRE(k >= f->lo && k <= f->hi);
    (void)f;
    const double K = (double)k, d = 2 * K - 0.5;
    s->steps = ARMS_STEPS;
    s->def.effects = NOCT_EFFECT_EVENTS | NOCT_EFFECT_TRACK;
    /* meshes: 0 floor, 1 ceiling, 2 x walls, 3 y walls, 4 loose box, 5 link;
     * the floor as deep as the arms reach below it when they curl */
    noctStatus st = NOCT_OK;
    if ((st = fam_add_box(s, "floor", d + 2, 2.5, K)) != NOCT_OK ||
        (st = fam_add_box(s, "ceiling", d + 2, 2.5, 0.25)) != NOCT_OK ||
        (st = fam_add_box(s, "xwall", 0.25, 2.5, K + 1.5)) != NOCT_OK ||
        (st = fam_add_box(s, "ywall", d + 2, 0.25, K + 1.5)) != NOCT_OK ||
        (st = fam_add_box(s, "loose", 0.3, 0.3, 0.3)) != NOCT_OK ||
        (st = fam_add_box(s, "link", 1, 0.2, 0.2)) != NOCT_OK)
        return noct_fail(err, st, -1, 0, "out of memory");
    const uint64_t arms = ARM_A | ARM_B;
    /* the bay: floor, ceiling, -x, +x, -y, +y */
    if ((st = fam_add_static(s, 0, 0, 0, -K, BAY, arms)) != NOCT_OK ||
        (st = fam_add_static(s, 1, 0, 0, 2 * K + 2.25, BAY, arms)) != NOCT_OK ||
        (st = fam_add_static(s, 2, -(d + 1.75), 0, K + 1, BAY, arms)) != NOCT_OK ||
        (st = fam_add_static(s, 2, d + 1.75, 0, K + 1, BAY, arms)) != NOCT_OK ||
        (st = fam_add_static(s, 3, 0, -2.25, K + 1, BAY, arms)) != NOCT_OK ||
        (st = fam_add_static(s, 3, 0, 2.25, K + 1, BAY, arms)) != NOCT_OK)
        return noct_fail(err, st, -1, 0, "out of memory");
    /* loose boxes on the floor, in the arms' plane and beside it */
    for (int m = 0; d - 1.5 - 2.5 * m > 1; ++m) {
        const double x = d - 1.5 - 2.5 * m;
        if ((st = fam_add_static(s, 4, -x, 0, 0.3, LOOSE, arms)) != NOCT_OK ||
            (st = fam_add_static(s, 4, x, 0, 0.3, LOOSE, arms)) != NOCT_OK ||
            (st = fam_add_static(s, 4, -x, 1.2, 0.3, LOOSE, arms)) != NOCT_OK ||
            (st = fam_add_static(s, 4, x, 1.2, 0.3, LOOSE, arms)) != NOCT_OK)
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
                    phi += fam_joint_angle(a, i, t);
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

static noctStatus fam_keyframes_make(noctScene *s, const noct_family *f, long n,
                                     noctError *err)
{
    NOCT_REQUIRE(n >= f->lo && n <= f->hi);
    (void)f;
    s->steps = KEYFRAMES_STEPS;
    s->def.effects = NOCT_EFFECT_EVENTS | NOCT_EFFECT_TRACK;
    const double L = 4 * cbrt((double)n);
    uint64_t st64 = 1234;
    noctStatus st;
    for (long i = 0; i < n; ++i) {
        double h[3];
        for (int c = 0; c < 3; ++c)
            h[c] = 0.25 + 0.5 * fam_draw(&st64);
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
                key.k.x.p[c] = L * fam_draw(&st64);
            const double zz = 2 * fam_draw(&st64) - 1, az = 360 * fam_draw(&st64);
            const double r = sqrt(1 - zz * zz);
            key.turn = (scene_turn){true, {r * cos(az * PI / 180), r * sin(az * PI / 180), zz},
                                    360 * fam_draw(&st64) - 180};
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

/* ---- the table ------------------------------------------------------------------ */

/* One row per family (families_internal.h says what each field means);
 * the gas kinds' containers hold ten times the volume of n gas boxes,
 * the mixed kind's fifty (its boxes' mean volume is E[scale^3] = 4.7625
 * times the gas's, so it is about the same tenth filled). Rows with the
 * same letter and range next to each other share a clause of the specs'
 * list. */
#define FAM_KEPT(row, nm, k, w, v)                                                         \
    [row] = {.name = nm, .letter = 'N', .lo = 1, .hi = 10000000, .unit = "boxes",         \
             .kind = k, .walls = w, .volume = v, .line_size = "boxes",                    \
             .objects = fam_gas_objects, .add = fam_gas_add, .make = fam_kept_make}

static const noct_family FAMILIES[FAM_ROWS] = {
    [FAM_PLANES] = {.name = "planes", .letter = 'K', .lo = 0, .hi = 1000, .unit = "rings",
                    .kind = -1, .meshes = 1u << FAM_MESH_UNIT_CUBE,
                    .line_size = "planes rings",
                    .objects = fam_planes_objects, .add = fam_planes_add,
                    .make = fam_kept_make},
    FAM_KEPT(FAM_GAS, "gas", GAS_UNIFORM, true, 10.0),
    FAM_KEPT(FAM_MIXED, "mixed", GAS_MIXED, true, 50.0),
    FAM_KEPT(FAM_CLUSTERS, "clusters", GAS_CLUSTERS, true, 10.0),
    FAM_KEPT(FAM_STATIC, "static", GAS_STATIC, true, 10.0),
    FAM_KEPT(FAM_ESCAPE, "escape", GAS_ESCAPE, false, 10.0),
    [FAM_BULLETS] = {.name = "bullets", .letter = 'N', .lo = 1, .hi = 10000000,
                     .unit = "objects", .kind = -1, .walls = true, .volume = 10.0,
                     .line_size = "objects", .objects = fam_gas_objects,
                     .add = fam_bullets_add, .make = fam_kept_make},
    [FAM_NOTCH] = {.name = "notch", .letter = 'N', .lo = 1, .hi = 1000000, .unit = "pairs",
                   .kind = -1,
                   .meshes = 1u << FAM_MESH_NOTCH_U | 1u << FAM_MESH_NOTCH_CUBE,
                   .line_size = "notch pairs", .objects = fam_notch_objects,
                   .add = fam_notch_add, .make = fam_kept_make},
    [FAM_ARMS] = {.name = "arms", .letter = 'K', .lo = 1, .hi = 8, .unit = "links",
                  .kind = -1, .make = fam_arms_make},
    [FAM_KEYFRAMES] = {.name = "keyframes", .letter = 'N', .lo = 1, .hi = 100000,
                       .unit = "boxes", .kind = -1, .make = fam_keyframes_make},
};

const noct_family *noct_family_find(const char *name, size_t len)
{
    for (size_t i = 0; i < FAM_ROWS; ++i)
        if (strlen(FAMILIES[i].name) == len && strncmp(FAMILIES[i].name, name, len) == 0)
            return &FAMILIES[i];
    return NULL;
}

/* Append to the message in buf (cap bytes, *len used), cut at its end. */
static void fam_append(char *buf, size_t cap, size_t *len, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

static void fam_append(char *buf, size_t cap, size_t *len, const char *fmt, ...)
{
    if (*len + 1 >= cap)
        return;
    va_list ap;
    va_start(ap, fmt);
    const int n = vsnprintf(buf + *len, cap - *len, fmt, ap);
    va_end(ap);
    if (n > 0)
        *len = *len + (size_t)n < cap ? *len + (size_t)n : cap - 1;
}

/* "a:N with N 1 to 8; b:K, c:K or d:K with K 0 to 9; or e:N with N 1 to 5":
 * the rows in order, each run of rows with the same letter and range in
 * one clause. */
static void fam_spec_list(char *buf, size_t cap)
{
    size_t len = 0;
    buf[0] = '\0';
    for (size_t i = 0, j; i < FAM_ROWS; i = j) {
        const noct_family *f = &FAMILIES[i];
        for (j = i + 1; j < FAM_ROWS && FAMILIES[j].letter == f->letter &&
                        FAMILIES[j].lo == f->lo && FAMILIES[j].hi == f->hi;
             ++j)
            ;
        if (i > 0)
            fam_append(buf, cap, &len, "; %s", j == FAM_ROWS ? "or " : "");
        for (size_t r = i; r < j; ++r)
            fam_append(buf, cap, &len, "%s%s:%c", r == i ? "" : r + 1 == j ? " or " : ", ",
                       FAMILIES[r].name, f->letter);
        fam_append(buf, cap, &len, " with %c %ld to %ld", f->letter, f->lo, f->hi);
    }
}

noctStatus noct_family_spec(const char *spec, const noct_family **f, long *size, noctError *err)
{
    const char *colon = strchr(spec, ':');
    char *end = NULL;
    errno = 0;
    *size = colon ? strtol(colon + 1, &end, 10) : -1;
    const bool number = colon && end != colon + 1 && *end == '\0' && errno == 0;
    *f = number ? noct_family_find(spec, (size_t)(colon - spec)) : NULL;
    if (*f != NULL && *size >= (*f)->lo && *size <= (*f)->hi)
        return NOCT_OK;
    char list[NOCT_ERROR_MESSAGE_SIZE];
    fam_spec_list(list, sizeof list);
    return noct_fail(err, NOCT_ERR_INVALID, -1, 0, "unknown scene '%s' (%s)", spec, list);
}

void noct_family_line_names(char *buf, size_t cap)
{
    size_t len = 0, n = 0, last = 0;
    buf[0] = '\0';
    for (size_t i = 0; i < FAM_ROWS; ++i)
        if (FAMILIES[i].add != NULL)
            last = i;
    for (size_t i = 0; i < FAM_ROWS; ++i)
        if (FAMILIES[i].add != NULL)
            fam_append(buf, cap, &len, "%s%s", n++ == 0 ? "" : i == last ? " or " : ", ",
                       FAMILIES[i].name);
}

noctStatus noct_scene_add_family(noctScene *s, const noct_family *f, long size)
{
    NOCT_REQUIRE(f->add != NULL && s->nfamilies < sizeof s->families / sizeof *s->families);
    for (int i = 0; i < FAM_MESHES; ++i) {
        if (!(f->meshes & 1u << i) || s->shared[i] != NULL)
            continue;
        noctStatus st = i == FAM_MESH_NOTCH_U ? fam_notch_mesh(&s->shared[i], NULL)
                        : noctMeshCreateBox(i == FAM_MESH_UNIT_CUBE ? 0.5 : 0.15,
                                            i == FAM_MESH_UNIT_CUBE ? 0.5 : 0.15,
                                            i == FAM_MESH_UNIT_CUBE ? 0.5 : 0.15, &s->shared[i],
                                            NULL);
        if (st != NOCT_OK)
            return st;
    }
    s->families[s->nfamilies++] = (scene_family){f, size};
    return NOCT_OK;
}

/* ---- world.h's builders, kept until the next SONAME change ------------------------- */

noctStatus noctWorldAddPlanes(noctWorld *w, int k, const noctMesh *unit_cube,
                              noctError *err)
{
    NOCT_REQUIRE(w != NULL && unit_cube != NULL);
    const noctMesh *meshes[FAM_MESHES] = {[FAM_MESH_UNIT_CUBE] = unit_cube};
    return fam_planes_add(w, &FAMILIES[FAM_PLANES], k, meshes, err);
}

double noctGasContainerSize(size_t n)
{
    return fam_container(&FAMILIES[FAM_GAS], n);
}

noctStatus noctWorldAddGas(noctWorld *w, size_t n, noctError *err)
{
    NOCT_REQUIRE(w != NULL);
    const noct_family *f = &FAMILIES[FAM_GAS];
    if (n > (size_t)f->hi) { /* the size as given, not as a long */
        char text[24];
        snprintf(text, sizeof text, "%zu", n);
        return fam_range(f, text, err);
    }
    return fam_gas_add(w, f, (long)n, NULL, err);
}
