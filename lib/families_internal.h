/* SPDX-License-Identifier: MIT */
/*
 * Private: the kinds of gas that families.c builds (noct_world_add_gas_kind),
 * for the scene reader, writer and noctSceneFamily(). Never installed.
 * noctree-sim(1), "FAMILIES OF BOXES", defines each kind exactly.
 */
#ifndef NOCT_LIB_FAMILIES_INTERNAL_H
#define NOCT_LIB_FAMILIES_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>

#include <noctree/world.h>

/* The gas of SCENES.md and its variants: mixed sizes, dense clusters,
 * mostly static, escaping outward. */
typedef enum noct_gas_kind {
    NOCT_GAS_UNIFORM,
    NOCT_GAS_MIXED,
    NOCT_GAS_CLUSTERS,
    NOCT_GAS_STATIC,
    NOCT_GAS_ESCAPE,
    NOCT_GAS_KINDS
} noct_gas_kind;

/* The kind's family name ("gas", "mixed", ...). */
const char *noct_gas_kind_name(noct_gas_kind kind);

/* The kind whose name is name[0, len), if any. */
bool noct_gas_kind_of(const char *name, size_t len, noct_gas_kind *kind);

/* Whether the kind's boxes bounce off the walls of its container. */
bool noct_gas_kind_walls(noct_gas_kind kind);

/* The side of the kind's container [0, L]^3 for n boxes. */
double noct_gas_kind_container(noct_gas_kind kind, size_t n);

/* Add n boxes of the kind (1 to 10^7) to w. INVALID, NUMERIC, NOMEM; on
 * failure nothing is added. */
noctStatus noct_world_add_gas_kind(noctWorld *w, noct_gas_kind kind, size_t n, noctError *err);

#endif /* NOCT_LIB_FAMILIES_INTERNAL_H */
