/* SPDX-License-Identifier: MIT */
/*
 * Private: what the scene families (families.c) need of the world beyond
 * its public API, the meshes it keeps for them. Never installed.
 */
#ifndef NOCT_LIB_WORLD_INTERNAL_H
#define NOCT_LIB_WORLD_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>

#include <noctree/world.h>

/* Room for more meshes the world will own; false without memory. */
bool noct_world_reserve_meshes(noctWorld *w, size_t more);

/* The world owns mesh from now on (destroys it with itself); room for it
 * was reserved. */
void noct_world_own_mesh(noctWorld *w, noctMesh *mesh);

/* How many meshes the world owns. */
size_t noct_world_owned_meshes(const noctWorld *w);

/* Destroy the meshes owned since there were `from` of them. */
void noct_world_destroy_meshes_from(noctWorld *w, size_t from);

#endif /* NOCT_LIB_WORLD_INTERNAL_H */
