/* SPDX-License-Identifier: MIT */
/*
 * Private: a scene, never installed.
 *
 *   scene_records.c  its records: the world definition, meshes, objects,
 *                    keyframes, and its end
 *   families.c       the built-in families, one table (families_internal.h)
 *   scene.c          scene files read, families named, scenes built
 *   scene_write.c    scenes written back as files
 */
#ifndef NOCT_LIB_SCENE_INTERNAL_H
#define NOCT_LIB_SCENE_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include <noctree/scene.h>
#include <noctree/world.h>

typedef struct scene_mesh {
    char *name;
    noctMesh *mesh;  /* NULL for a box primitive */
    double half[3];  /* a box primitive's half-extents, or a box mesh's */
    bool box;        /* 'box' (else 'file') */
    char *file;      /* the file a mesh was read from, as opened */
} scene_mesh;

/* A rotation as the scene gives it: an axis and degrees, which make the
 * quaternion through noctQuatFromAxisAngle() (so that writing them back
 * gives the same quaternion). */
typedef struct scene_turn {
    bool given;
    double axis[3], degrees;
} scene_turn;

/* A keyframe as read, with its rotation as given. */
typedef struct scene_key {
    noctKeyframe k;
    scene_turn turn;
    bool by; /* 'turn' (from the previous key through turn's angle), not
                'rotate' */
} scene_key;

typedef struct scene_object {
    size_t mesh;
    double pos[3], dir[3], speed;
    bool has_velocity;       /* a velocity vector, not dir and speed */
    double vel[3];
    noctQuat q;              /* from 'rotate', else the identity */
    scene_turn rotate, spin_turn; /* as given, for noctSceneWrite() */
    noctObjectType type;
    uint64_t category, mask;
    bool sensor;
    noctMotionQuality quality; /* 'continuous' or 'discrete', else the world's */
    noctQuat spin;           /* from 'spin', else the identity */
    bool has_type;           /* 'type' given */
    size_t first_key, nkeys; /* its keyframes in noctScene.keys */
    double margin;           /* its own margin (noctObjectDef::margin) */
    char *name;              /* 'name', owned; NULL without one */
    long line;               /* the line that gave it, for messages */
} scene_object;

/* A family kept by name and size, whose objects the world gets when the
 * scene is built (families_internal.h). */
typedef struct scene_family {
    const struct noct_family *family;
    long size;
} scene_family;

struct noctScene {
    noctWorldDef def;
    int steps;
    scene_mesh *meshes;
    size_t nmeshes, capmeshes;
    scene_object *objects;
    size_t nobjects, capobjects;
    scene_key *keys;         /* the objects' tracks, each object's in a row */
    size_t nkeys, capkeys;
    size_t (*ignores)[2];    /* 'ignore NAME NAME': indexes in objects */
    size_t nignores, capignores;
    bool ignore_initial;     /* 'ignore initial' */
    scene_family families[16];
    size_t nfamilies;
    /* the objects' names: an open-addressing table of 1 + the index in
     * objects of each named object (0: empty), by noct_scene_name_hash() */
    size_t *names;
    size_t capnames, nnames;
    /* the meshes the kept families share (families_internal.h,
     * FAM_MESH_*), made when a family that needs one is added */
    noctMesh *shared[3];
};

/* ---- scene_records.c ---- */

/* A scene with the defaults (the world's, 200 steps) and nothing in it;
 * NULL without memory. */
noctScene *noct_scene_new(void);

/* Add a mesh (m, or NULL for a box primitive of half-extents h; file: the
 * path it was read from, or NULL for a box); takes m, destroying it on
 * failure. NOMEM. */
noctStatus noct_scene_add_mesh(noctScene *s, const char *name, noctMesh *m, const double h[3],
                               const char *file);

/* Add an object, and keyframes to the last object (the scene's rules
 * checked by the caller). NOMEM. */
noctStatus noct_scene_add_object(noctScene *s, const scene_object *o);
noctStatus noct_scene_add_key(noctScene *s, const scene_key *k);

/* Ignore the pair of object lines pair[0] and pair[1] (checked by the
 * caller). NOMEM. */
noctStatus noct_scene_add_ignore(noctScene *s, const size_t pair[2]);

/* A scene_object with the defaults of an object line: not moving, not
 * turned, moving type, every filter bit, no margin, no name. */
scene_object noct_scene_object(size_t mesh, const double pos[3]);

/* The object line named name, or SIZE_MAX. */
size_t noct_scene_named(const noctScene *s, const char *name);

/* Make the last object's name (o->name, already unique) findable. NOMEM
 * (then the name is still the object's, but not findable: the caller
 * fails the scene). */
noctStatus noct_scene_index_name(noctScene *s);

/* Is name a valid object name (noctree-scene(5))? */
bool noct_scene_name_ok(const char *name);

#endif /* NOCT_LIB_SCENE_INTERNAL_H */
