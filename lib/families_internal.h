/* SPDX-License-Identifier: MIT */
/*
 * Private: the table of the built-in families (families.c), one row per
 * family, through which noctSceneFamily(), the scene reader and writer,
 * noctSceneBuild() and the world.h builders kept for compatibility make
 * every family. Never installed. noctree-sim(1), "FAMILIES OF BOXES",
 * defines each family exactly.
 *
 * Two sorts of rows: the families a scene keeps as a name and a size and
 * whose objects the world gets only when the scene is built (planes, the
 * gas kinds and notch: a gas of 10^6 boxes costs the scene nothing; a
 * scene file names them on a 'family' line; the meshes they share are
 * the scene's), and the families made of the
 * scene's own meshes, objects and keyframes (arms, keyframes).
 */
#ifndef NOCT_LIB_FAMILIES_INTERNAL_H
#define NOCT_LIB_FAMILIES_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include <noctree/scene.h>
#include <noctree/world.h>

typedef struct noct_family noct_family;

/* The meshes a scene makes once for the kept families that share them:
 * planes' unit cube (half-extent 0.5), notch's U-shaped prism and its
 * cube (half-extent 0.15). */
enum { FAM_MESH_UNIT_CUBE, FAM_MESH_NOTCH_U, FAM_MESH_NOTCH_CUBE, FAM_MESHES };

struct noct_family {
    const char *name; /* the NAME of the spec NAME:SIZE */
    char letter;      /* the size's letter in the specs' list: 'K' or 'N' */
    long lo, hi;      /* the size's range */
    const char *unit; /* what the size counts, for the builders' messages */
    int kind;         /* a gas kind (families.c), or -1 */
    bool walls;       /* gas kinds: the container's walls turn the boxes back */
    double volume;    /* gas kinds: the container's volume per box */
    unsigned meshes;  /* bit i: its objects share the scene's FAM_MESH_i */
    /* Families kept by name and size, else NULL: the size's name in a
     * scene file's messages, the objects the family adds, and the builder
     * that adds them to a world (INVALID for a size out of range, NUMERIC,
     * NOMEM, TOO_LARGE; on failure nothing is added); meshes are the
     * scene's shared meshes, those the row asks for made. */
    const char *line_size;
    uint64_t (*objects)(long size);
    noctStatus (*add)(noctWorld *w, const noct_family *f, long size,
                      const noctMesh *const *meshes, noctError *err);
    /* Make the family of the given size (in range) in a new scene:
     * noctSceneFamily(). NOMEM. */
    noctStatus (*make)(noctScene *s, const noct_family *f, long size, noctError *err);
};

/* The family named name[0, len), or NULL. */
const noct_family *noct_family_find(const char *name, size_t len);

/* The family and size of spec "NAME:SIZE"; INVALID for an unknown name,
 * a size that is not an integer or out of range, with the list of the
 * families and their ranges. */
noctStatus noct_family_spec(const char *spec, const noct_family **f, long *size, noctError *err);

/* The families a scene file's 'family' line can name, as a list for a
 * message ("planes, gas, ... or escape"), into buf. */
void noct_family_line_names(char *buf, size_t cap);

/* Keep family f (one with a builder add) of the given size in s, with
 * the shared meshes it needs. NOMEM. */
noctStatus noct_scene_add_family(noctScene *s, const noct_family *f, long size);

#endif /* NOCT_LIB_FAMILIES_INTERNAL_H */
