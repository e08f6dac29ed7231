/* SPDX-License-Identifier: MIT */
/*
 * A scene's records: its world definition, steps, meshes, objects and
 * keyframes, as the reader (scene.c) and the families' builders
 * (families.c) add them, and the scene's end. Nothing here reads a file
 * or builds a world.
 */
#define _POSIX_C_SOURCE 200809L /* strdup */
#include "config.h"

#include <stdlib.h>
#include <string.h>

#include <noctree/scene.h>

#include "array.h"
#include "internal.h"
#include "scene_internal.h"

void noctSceneDestroy(noctScene *s)
{
    if (s == NULL)
        return;
    for (size_t i = 0; i < s->nmeshes; ++i) {
        free(s->meshes[i].name);
        free(s->meshes[i].file);
        noctMeshDestroy(s->meshes[i].mesh);
    }
    free(s->meshes);
    free(s->objects);
    free(s->keys);
    for (size_t i = 0; i < sizeof s->shared / sizeof *s->shared; ++i)
        noctMeshDestroy(s->shared[i]);
    free(s);
}

noctWorldDef *noctSceneDef(noctScene *s)
{
    NOCT_REQUIRE(s != NULL);
    return &s->def;
}

int noctSceneSteps(const noctScene *s)
{
    NOCT_REQUIRE(s != NULL);
    return s->steps;
}

noctScene *noct_scene_new(void)
{
    noctScene *s = calloc(1, sizeof *s);
    if (s != NULL) {
        s->def = noctDefaultWorldDef();
        s->steps = 200;
    }
    return s;
}

NOCT_DEFINE_GROW(grow_meshes, scene_mesh)
NOCT_DEFINE_GROW(grow_objects, scene_object)
NOCT_DEFINE_GROW(grow_keys, scene_key)

noctStatus noct_scene_add_mesh(noctScene *s, const char *name, noctMesh *m, const double h[3],
                               const char *file)
{
    if (!grow_meshes(&s->meshes, &s->capmeshes, s->capmeshes > 0 ? s->nmeshes + 1 : 8)) {
        noctMeshDestroy(m);
        return NOCT_ERR_NOMEM;
    }
    scene_mesh *sm = &s->meshes[s->nmeshes];
    memset(sm, 0, sizeof *sm);
    sm->name = strdup(name);
    sm->file = file != NULL ? strdup(file) : NULL;
    if (sm->name == NULL || (file != NULL && sm->file == NULL)) {
        free(sm->name);
        free(sm->file);
        noctMeshDestroy(m);
        return NOCT_ERR_NOMEM;
    }
    memcpy(sm->half, h, sizeof sm->half);
    sm->box = file == NULL;
    sm->mesh = m;
    ++s->nmeshes;
    return NOCT_OK;
}

scene_object noct_scene_object(size_t mesh, const double pos[3])
{
    scene_object o;
    memset(&o, 0, sizeof o);
    o.mesh = mesh;
    memcpy(o.pos, pos, sizeof o.pos);
    o.q = o.spin = (noctQuat){0, 0, 0, 1};
    o.type = NOCT_OBJECT_MOVING;
    o.category = o.mask = NOCT_FILTER_ALL;
    return o;
}

noctStatus noct_scene_add_object(noctScene *s, const scene_object *o)
{
    if (!grow_objects(&s->objects, &s->capobjects, s->capobjects > 0 ? s->nobjects + 1 : 64))
        return NOCT_ERR_NOMEM;
    s->objects[s->nobjects++] = *o;
    return NOCT_OK;
}

/* The last object follows a track: it is kinematic. */
noctStatus noct_scene_add_key(noctScene *s, const scene_key *k)
{
    if (!grow_keys(&s->keys, &s->capkeys, s->capkeys > 0 ? s->nkeys + 1 : 64))
        return NOCT_ERR_NOMEM;
    scene_object *o = &s->objects[s->nobjects - 1];
    if (o->nkeys == 0)
        o->first_key = s->nkeys;
    s->keys[s->nkeys++] = *k;
    ++o->nkeys;
    o->type = NOCT_OBJECT_KINEMATIC;
    return NOCT_OK;
}
