/* SPDX-License-Identifier: MIT */
/*
 * A scene's records: its world definition, steps, meshes, objects and
 * keyframes, as the reader (scene.c) and the families' builders
 * (families.c) add them, and the scene's end. Nothing here reads a file
 * or builds a world.
 */
#define _POSIX_C_SOURCE 200809L /* strdup */
#include "config.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <noctree/scene.h>

#include "array.h"
#include "families_internal.h"
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
    for (size_t i = 0; i < s->nobjects; ++i)
        free(s->objects[i].name);
    free(s->objects);
    free(s->names);
    free(s->keys);
    free(s->ignores);
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

void noctSceneSetIgnoreInitial(noctScene *s, bool ignore)
{
    NOCT_REQUIRE(s != NULL);
    s->ignore_initial = ignore;
}

bool noctSceneIgnoresInitial(const noctScene *s)
{
    NOCT_REQUIRE(s != NULL);
    return s->ignore_initial;
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

typedef size_t index_pair[2];
NOCT_DEFINE_GROW(grow_ignores, index_pair)

noctStatus noct_scene_add_ignore(noctScene *s, const size_t pair[2])
{
    if (!grow_ignores(&s->ignores, &s->capignores, s->capignores > 0 ? s->nignores + 1 : 16))
        return NOCT_ERR_NOMEM;
    s->ignores[s->nignores][0] = pair[0];
    s->ignores[s->nignores][1] = pair[1];
    ++s->nignores;
    return NOCT_OK;
}

/* ---- object names ---- */

bool noct_scene_name_ok(const char *name)
{
    const size_t n = strlen(name);
    if (n == 0 || n > NOCT_SCENE_NAME_MAX)
        return false;
    const unsigned char c0 = (unsigned char)name[0];
    if (!((c0 >= 'A' && c0 <= 'Z') || (c0 >= 'a' && c0 <= 'z') || c0 == '_'))
        return false;
    for (size_t i = 1; i < n; ++i) {
        const unsigned char c = (unsigned char)name[i];
        if (!((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
              c == '_' || c == '-' || c == '.'))
            return false;
    }
    return true;
}

/* FNV-1a */
static size_t name_hash(const char *name)
{
    uint64_t h = UINT64_C(0xcbf29ce484222325);
    for (; *name != '\0'; ++name)
        h = (h ^ (unsigned char)*name) * UINT64_C(0x100000001b3);
    return (size_t)(h ^ (h >> 32));
}

size_t noct_scene_named(const noctScene *s, const char *name)
{
    if (s->capnames == 0)
        return SIZE_MAX;
    for (size_t at = name_hash(name) & (s->capnames - 1);; at = (at + 1) & (s->capnames - 1)) {
        const size_t v = s->names[at];
        if (v == 0)
            return SIZE_MAX;
        if (strcmp(s->objects[v - 1].name, name) == 0)
            return v - 1;
    }
}

static void put_name(size_t *t, size_t cap, const char *name, size_t value)
{
    size_t at = name_hash(name) & (cap - 1);
    while (t[at] != 0)
        at = (at + 1) & (cap - 1);
    t[at] = value;
}

noctStatus noct_scene_index_name(noctScene *s)
{
    /* at most half full */
    if (2 * (s->nnames + 1) > s->capnames) {
        const size_t cap = s->capnames > 0 ? 2 * s->capnames : 64;
        size_t *t = calloc(cap, sizeof *t);
        if (t == NULL)
            return NOCT_ERR_NOMEM;
        for (size_t i = 0; i < s->capnames; ++i)
            if (s->names[i] != 0)
                put_name(t, cap, s->objects[s->names[i] - 1].name, s->names[i]);
        free(s->names);
        s->names = t;
        s->capnames = cap;
    }
    put_name(s->names, s->capnames, s->objects[s->nobjects - 1].name, s->nobjects);
    ++s->nnames;
    return NOCT_OK;
}

/* The objects the scene's families add, before its object lines. */
static uint64_t family_objects(const noctScene *s)
{
    uint64_t n = 0;
    for (size_t i = 0; i < s->nfamilies; ++i)
        n += s->families[i].family->objects(s->families[i].size);
    return n;
}

size_t noctSceneObjectCount(const noctScene *s)
{
    NOCT_REQUIRE(s != NULL);
    return (size_t)family_objects(s) + s->nobjects;
}

const char *noctSceneObjectName(const noctScene *s, size_t index)
{
    NOCT_REQUIRE(s != NULL);
    const uint64_t first = family_objects(s);
    if (index < first || index - first >= s->nobjects)
        return NULL;
    return s->objects[index - first].name;
}

bool noctSceneFindObject(const noctScene *s, const char *name, size_t *index)
{
    NOCT_REQUIRE(s != NULL && name != NULL && index != NULL);
    const size_t i = noct_scene_named(s, name);
    if (i == SIZE_MAX)
        return false;
    *index = (size_t)family_objects(s) + i;
    return true;
}
