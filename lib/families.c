/* SPDX-License-Identifier: MIT */
/*
 * The benchmark scene families of SCENES.md, built in a world through its
 * public API: the report's planes t_k and the gas of oriented boxes. They
 * are not part of the world's core; the tools, the tests and scene files
 * (noctree-scene(5)) use them. The world only keeps the meshes a family
 * makes (world_internal.h).
 */
#include "config.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <noctree/world.h>

#include "families_internal.h"
#include "internal.h"
#include "world_internal.h"

/* Undo a scene builder's additions after a failure: remove the n objects
 * it added (removal cannot fail). */
static noctStatus fam_unbuild(noctWorld *w, noctObjectId *ids, size_t n, noctStatus st)
{
    for (size_t i = 0; i < n; ++i)
        noctWorldRemove(w, ids[i], NULL);
    free(ids);
    return st;
}

noctStatus noctWorldAddPlanes(noctWorld *w, int k, const noctMesh *unit_cube,
                              noctError *err)
{
    NOCT_REQUIRE(w != NULL && unit_cube != NULL);
    if (k < 0 || k > 1000)
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0,
                         "planes: %d rings; it must be 0 to 1000", k);
    const size_t total = 2 * (size_t)(2 * k + 1) * (size_t)(2 * k + 1);
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
                noctStatus st = noctWorldAdd(w, unit_cube, pos, dir, 0.05, &ids[n], err);
                if (st != NOCT_OK)
                    return fam_unbuild(w, ids, n, st);
                ++n;
            }
    }
    free(ids);
    return NOCT_OK;
}

double noctGasContainerSize(size_t n)
{
    return cbrt(10.0 * (double)n);
}

/* splitmix64, and its doubles in [0, 1), as SCENES.md defines them. */
static uint64_t fam_splitmix64(uint64_t *state)
{
    uint64_t z = (*state += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}

static double fam_unit_draw(uint64_t *state)
{
    return (double)(fam_splitmix64(state) >> 11) * 0x1p-53;
}

/* The gas kinds, in the order of noct_gas_kind: the family's name, and
 * whether the container's walls turn the boxes back. */
static const struct {
    const char *name;
    bool walls;
} GAS_KINDS[NOCT_GAS_KINDS] = {
    {"gas", true}, {"mixed", true}, {"clusters", true}, {"static", true}, {"escape", false},
};

const char *noct_gas_kind_name(noct_gas_kind kind)
{
    return GAS_KINDS[kind].name;
}

bool noct_gas_kind_walls(noct_gas_kind kind)
{
    return GAS_KINDS[kind].walls;
}

bool noct_gas_kind_of(const char *name, size_t len, noct_gas_kind *kind)
{
    for (int k = 0; k < NOCT_GAS_KINDS; ++k)
        if (strlen(GAS_KINDS[k].name) == len && strncmp(GAS_KINDS[k].name, name, len) == 0) {
            *kind = (noct_gas_kind)k;
            return true;
        }
    return false;
}

double noct_gas_kind_container(noct_gas_kind kind, size_t n)
{
    /* mixed: the mean volume of a box is E[scale^3] = 4.7625 times the
     * gas's, so the container holds five times the gas's volume (about
     * the same tenth filled) */
    return kind == NOCT_GAS_MIXED ? cbrt(50.0 * (double)n) : noctGasContainerSize(n);
}

/* A box's scale in the mixed kind, from its extra draw w. */
static double mixed_scale(double w)
{
    return w < 0.5 ? 0.5 : w < 0.8 ? 1 : w < 0.95 ? 2 : 4;
}

noctStatus noct_world_add_gas_kind(noctWorld *w, noct_gas_kind kind, size_t n, noctError *err)
{
    if (n < 1 || n > 10000000)
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0, "%s: %zu boxes; it must be 1 to 10000000",
                         noct_gas_kind_name(kind), n);
    /* room for them all at once: no per-slot array grows by doubling */
    noctStatus rst = noctWorldReserve(w, n, err);
    if (rst != NOCT_OK)
        return rst;
    const size_t nclusters = (n + 999) / 1000;
    noctObjectId *ids = malloc(n * sizeof *ids);
    double *cluster = kind == NOCT_GAS_CLUSTERS ? malloc(3 * nclusters * sizeof *cluster) : NULL;
    if (ids == NULL || (kind == NOCT_GAS_CLUSTERS && cluster == NULL)) {
        free(ids);
        free(cluster);
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    }
    const double pi = 3.141592653589793;
    const double lb = noct_gas_kind_container(kind, n);
    uint64_t state = 42;
    for (size_t c = 0; c < 3 * nclusters && cluster != NULL; ++c)
        cluster[c] = lb * fam_unit_draw(&state);
    noctStatus st = NOCT_OK;
    size_t i = 0;
    for (; i < n; ++i) {
        double half[3];
        for (int k = 0; k < 3; ++k)
            half[k] = 0.25 + 0.5 * fam_unit_draw(&state);
        double u1 = fam_unit_draw(&state), u2 = fam_unit_draw(&state);
        double u3 = fam_unit_draw(&state);
        double x = sqrt(1 - u1) * sin(2 * pi * u2), y = sqrt(1 - u1) * cos(2 * pi * u2);
        double z = sqrt(u1) * sin(2 * pi * u3), qw = sqrt(u1) * cos(2 * pi * u3);
        double centre[3];
        for (int k = 0; k < 3; ++k)
            centre[k] = kind == NOCT_GAS_CLUSTERS
                            ? cluster[3 * (i % nclusters) + (size_t)k] +
                                  15 * (fam_unit_draw(&state) - 0.5)
                            : lb * fam_unit_draw(&state);
        double dz = 2 * fam_unit_draw(&state) - 1, phi = 2 * pi * fam_unit_draw(&state);
        double dir[3] = {sqrt(1 - dz * dz) * cos(phi), sqrt(1 - dz * dz) * sin(phi), dz};
        double speed = 0.05;
        noctObjectDef d = noctDefaultObjectDef();
        if (kind == NOCT_GAS_MIXED) {
            const double s = mixed_scale(fam_unit_draw(&state));
            for (int k = 0; k < 3; ++k)
                half[k] *= s;
        } else if (kind == NOCT_GAS_STATIC && !(fam_unit_draw(&state) < 0.1)) {
            speed = 0;
            d.type = NOCT_OBJECT_STATIC;
        } else if (kind == NOCT_GAS_ESCAPE) {
            speed = 0.2;
            for (int k = 0; k < 3; ++k)
                dir[k] = centre[k] - lb / 2;
        }
        /* a box primitive turned by (x, y, z, qw), whose matrix SCENES.md
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
                           noct_gas_kind_name(kind), i);
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

noctStatus noctWorldAddGas(noctWorld *w, size_t n, noctError *err)
{
    NOCT_REQUIRE(w != NULL);
    return noct_world_add_gas_kind(w, NOCT_GAS_UNIFORM, n, err);
}
