/* SPDX-License-Identifier: MIT */
/*
 * noctSceneWrite(): a scene as a scene file that reads back to the same
 * scene, every number with 17 significant digits (a double's round trip),
 * rotations by the axis and degrees they were given by.
 */
#include "config.h"

#include <errno.h>
#include <inttypes.h>
#include <stdio.h>
#include <string.h>

#include "internal.h"
#include "mesh_internal.h"
#include "scene_internal.h"

static void turn(FILE *f, const char *kw, const scene_turn *t)
{
    if (t->given)
        fprintf(f, " %s %.17g %.17g %.17g %.17g", kw, t->axis[0], t->axis[1], t->axis[2],
                t->degrees);
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
    if (d->N == NOCT_N_EXHAUSTIVE)
        fprintf(f, "N big\n");
    else
        fprintf(f, "N %d\n", d->N);
    fprintf(f, "max-depth %d\naccuracy %s\nmaintenance %s\nsteps %d\n", d->max_depth,
            d->accuracy == NOCT_ACCURACY_BOX      ? "box"
            : d->accuracy == NOCT_ACCURACY_CONVEX ? "convex"
                                                  : "exact",
            d->maintenance == NOCT_MAINTAIN_REBUILD ? "rebuild" : "incremental", s->steps);
    if (d->effects & NOCT_EFFECT_WALLS)
        fprintf(f, "walls %.17g %.17g %.17g %.17g %.17g %.17g\n", d->walls_lo[0], d->walls_lo[1],
                d->walls_lo[2], d->walls_hi[0], d->walls_hi[1], d->walls_hi[2]);
    for (size_t i = 0; i < s->nmeshes; ++i) {
        const scene_mesh *m = &s->meshes[i];
        if (m->box)
            fprintf(f, "mesh %s box %.17g %.17g %.17g\n", m->name, m->half[0], m->half[1],
                    m->half[2]);
        else
            fprintf(f, "mesh %s file %s\n", m->name, m->file);
    }
    for (size_t i = 0; i < s->nfamilies; ++i)
        fprintf(f, "family %s %ld\n", s->families[i].gas ? "gas" : "planes", s->families[i].size);
    for (size_t i = 0; i < s->nobjects; ++i) {
        const scene_object *o = &s->objects[i];
        fprintf(f, "object %s %.17g %.17g %.17g", s->meshes[o->mesh].name, o->pos[0], o->pos[1],
                o->pos[2]);
        if (o->has_velocity)
            fprintf(f, " velocity %.17g %.17g %.17g", o->vel[0], o->vel[1], o->vel[2]);
        else if (o->speed > 0)
            fprintf(f, " %.17g %.17g %.17g %.17g", o->dir[0], o->dir[1], o->dir[2], o->speed);
        turn(f, "rotate", &o->rotate);
        fprintf(f, " type %s", type_name(o->type));
        if (o->category != NOCT_FILTER_ALL || o->mask != NOCT_FILTER_ALL)
            fprintf(f, " filter 0x%" PRIx64 " 0x%" PRIx64, o->category, o->mask);
        if (o->sensor)
            fprintf(f, " sensor");
        turn(f, "spin", &o->spin_turn);
        fprintf(f, "\n");
        for (size_t j = 0; j < o->nkeys; ++j) {
            const scene_key *k = &s->keys[o->first_key + j];
            fprintf(f, "key %" PRIu64 " %.17g %.17g %.17g", k->k.tick, k->k.x.p[0], k->k.x.p[1],
                    k->k.x.p[2]);
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
