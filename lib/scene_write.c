/* SPDX-License-Identifier: MIT */
/*
 * noctSceneWrite(): a scene as a scene file that reads back to the same
 * scene, every number in the fewest digits that read back to it,
 * rotations by the axis and degrees they were given by.
 */
#include "config.h"

#include <errno.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "families_internal.h"
#include "internal.h"
#include "scene_internal.h"

/* x in the fewest significant digits (15 to 17) that read back to it. */
static const char *num(char buf[32], double x)
{
    for (int digits = 15; digits <= 17; ++digits) {
        snprintf(buf, 32, "%.*g", digits, x);
        if (strtod(buf, NULL) == x)
            break;
    }
    return buf;
}

/* " a b c" for three numbers. */
static void nums(FILE *f, const double *x, int n)
{
    char b[32];
    for (int i = 0; i < n; ++i)
        fprintf(f, " %s", num(b, x[i]));
}

static void turn(FILE *f, const char *kw, const scene_turn *t)
{
    if (!t->given)
        return;
    fprintf(f, " %s", kw);
    nums(f, t->axis, 3);
    nums(f, &t->degrees, 1);
}

static const char *type_name(noctObjectType t)
{
    return t == NOCT_OBJECT_STATIC ? "static" : t == NOCT_OBJECT_KINEMATIC ? "kinematic" : "moving";
}

noctStatus noctSceneWrite(const noctScene *s, FILE *f, noctError *err)
{
    NOCT_REQUIRE(s != NULL && f != NULL);
    const noctWorldDef *d = &s->def;
    fprintf(f, "# a libnoctree scene (noctree-scene(5)), written by noctSceneWrite()\n");
    if (d->N == NOCT_N_EXHAUSTIVE || d->N == NOCT_AUTO)
        fprintf(f, "N %s\n", d->N == NOCT_AUTO ? "auto" : "big");
    else
        fprintf(f, "N %d\n", d->N);
    if (d->max_depth == NOCT_AUTO)
        fprintf(f, "max-depth auto\n");
    else
        fprintf(f, "max-depth %d\n", d->max_depth);
    fprintf(f, "accuracy %s\nmaintenance %s\nsteps %d\n", noctAccuracyName(d->accuracy),
            d->maintenance == NOCT_MAINTAIN_REBUILD ? "rebuild" : "incremental", s->steps);
    if (d->margin > 0) {
        char b[32];
        fprintf(f, "margin %s\n", num(b, d->margin));
    }
    if (d->effects & NOCT_EFFECT_WALLS) {
        fprintf(f, "walls");
        nums(f, d->walls_lo, 3);
        nums(f, d->walls_hi, 3);
        fprintf(f, "\n");
    }
    for (size_t i = 0; i < s->nmeshes; ++i) {
        const scene_mesh *m = &s->meshes[i];
        if (m->box) {
            fprintf(f, "mesh %s box", m->name);
            nums(f, m->half, 3);
            fprintf(f, "\n");
        } else
            fprintf(f, "mesh %s file %s%s\n", m->name, m->file,
                    noctMeshIsSurface(m->mesh) ? " surface" : "");
    }
    for (size_t i = 0; i < s->nfamilies; ++i)
        fprintf(f, "family %s %ld\n", s->families[i].family->name, s->families[i].size);
    for (size_t i = 0; i < s->nobjects; ++i) {
        const scene_object *o = &s->objects[i];
        fprintf(f, "object %s", s->meshes[o->mesh].name);
        nums(f, o->pos, 3);
        if (o->has_velocity) {
            fprintf(f, " velocity");
            nums(f, o->vel, 3);
        } else if (o->speed > 0) {
            nums(f, o->dir, 3);
            nums(f, &o->speed, 1);
        }
        turn(f, "rotate", &o->rotate);
        fprintf(f, " type %s", type_name(o->type));
        if (o->category != NOCT_FILTER_ALL || o->mask != NOCT_FILTER_ALL)
            fprintf(f, " filter 0x%" PRIx64 " 0x%" PRIx64, o->category, o->mask);
        if (o->sensor)
            fprintf(f, " sensor");
        turn(f, "spin", &o->spin_turn);
        if (o->quality != NOCT_QUALITY_WORLD)
            fprintf(f, o->quality == NOCT_QUALITY_CONTINUOUS ? " continuous" : " discrete");
        if (o->margin > 0) {
            char b[32];
            fprintf(f, " margin %s", num(b, o->margin));
        }
        if (o->name != NULL)
            fprintf(f, " name %s", o->name);
        fprintf(f, "\n");
        for (size_t j = 0; j < o->nkeys; ++j) {
            const scene_key *k = &s->keys[o->first_key + j];
            fprintf(f, "key %" PRIu64, k->k.tick);
            nums(f, k->k.x.p, 3);
            turn(f, "rotate", &k->turn);
            fprintf(f, "\n");
        }
    }
    /* Last: the keys and walls lines above turn effects on, and this line
     * replaces them all with the scene's. */
    static const struct {
        unsigned bit;
        const char *name;
    } EFFECTS[] = {{NOCT_EFFECT_MOTION, "motion"},   {NOCT_EFFECT_EVENTS, "events"},
                   {NOCT_EFFECT_RESPONSE, "response"}, {NOCT_EFFECT_WALLS, "walls"},
                   {NOCT_EFFECT_SUBSTEP, "substep"}, {NOCT_EFFECT_SPIN, "spin"},
                   {NOCT_EFFECT_TRACK, "track"}};
    fprintf(f, "effects");
    for (size_t i = 0; i < sizeof EFFECTS / sizeof *EFFECTS; ++i)
        if (d->effects & EFFECTS[i].bit)
            fprintf(f, " %s", EFFECTS[i].name);
    fprintf(f, "%s\n", d->effects == 0 ? " none" : "");
    errno = 0;
    if (fflush(f) != 0 || ferror(f))
        return noct_fail(err, NOCT_ERR_IO, -1, 0, "writing the scene: %s",
                         strerror(errno != 0 ? errno : EIO));
    return NOCT_OK;
}
