/* SPDX-License-Identifier: MIT */
/*
 * The tests' own geometry of random rotated scenes (check-queries,
 * check-near): objects that are boxes or L meshes (unions of two boxes),
 * as the ideal solids they stand for, in long double, with the test's own
 * containment, separating-axis, segment and distance computations; and
 * the worlds that hold them.
 */
#ifndef NOCT_TESTS_TESTGEOM_H
#define NOCT_TESTS_TESTGEOM_H

#include <stdbool.h>
#include <stdint.h>

#include <noctree.h>

#include "testutil.h" /* make_ell */

#define MAXO 48
#define MARGIN 1e-9L

typedef struct piece {
    long double c[3], h[3];
} piece;

typedef struct ideal {
    int npieces;
    piece pc[2];
    long double R[9]; /* rows: world = R local + t */
    long double t[3];
} ideal;

typedef struct scene {
    noctWorld *w;
    int n;
    noctObjectId id[MAXO];
    ideal g[MAXO];
    int kind[MAXO];           /* 0: box primitive, 1: box mesh, 2: L mesh */
    noctMesh *mesh[MAXO];     /* the object's mesh (kinds 1 and 2); the
                                 test's mesh of a box primitive (kind 0) */
    noctTransform x[MAXO];
    uint64_t cat[MAXO], mask[MAXO];
    bool sensor[MAXO];
} scene;

typedef struct obb {
    long double c[3], u[3][3], h[3];
} obb;

typedef struct found {
    int n;
    noctObjectId id[MAXO];
} found;

/* The scenes' RNG (uniform() draws from it) and its first state. */
extern uint64_t rng;
#define RNG_SEED 0x51ed2701u

/* The margin of the worlds new_world() makes (default 0). */
extern double world_margin;

double uniform(void);
void quat_matrix(const noctQuat *q, long double R[9]);

/* The ideal solid of a query's shape at pose x: make_ell()'s L (ell), or
 * a box of half-extents h. */
ideal ideal_shape(const noctTransform *x, bool ell, const double h[3]);
void random_quat(noctQuat *q);
void to_local(const ideal *g, const long double p[3], long double out[3]);
void dir_to_local(const ideal *g, const long double d[3], long double out[3]);
int ideal_contains(const ideal *g, const double p[3]);
obb piece_box(const ideal *g, int j);
int obb_meet(const obb *a, const obb *b);
int union_meet(const ideal *a, const ideal *b);
int ideal_ray(const ideal *g, const double p[3], const double d[3], long double *s,
              long double normal[3], bool *sharp);
noctWorld *new_world(int N, noctAccuracy accuracy);
uint64_t random_bits(void);
void random_scene(scene *s, int n, int N, noctAccuracy accuracy, noctMesh *ell);
void free_scene(scene *s);
/* The definition that makes object i of scene s again (its shape, pose,
 * category, mask and sensor flag as random_scene() drew them); ell the L
 * mesh random_scene() was given. */
noctObjectDef scene_object_def(const scene *s, int i, noctMesh *ell);
bool passes(const scene *s, int i, noctQueryFilter f);
noctQueryFilter random_filter(void);
const noctMesh *mesh_of(const scene *s, int i, const noctMesh *ell);

/* The distance between two objects' ideal solids (0 when they meet), from
 * their edges: each edge's distance to each box of the other, minimised
 * along the edge (a convex function) by ternary search. */
long double ideal_distance(const ideal *a, const ideal *b);

/* A lower bound on the distance between two objects' ideal solids, and so
 * on ideal_distance() (which is never below it: its points lie on a's
 * edges), at a few dozen operations: the gap between the pieces'
 * axis-aligned bounding boxes, each piece's box inside its own. In long
 * double, off by less than 2^-50 of the coordinates. */
long double ideal_distance_lower(const ideal *a, const ideal *b);

/* A #noctObjectFcn for a found: the object's user data must be its handle
 * (random_scene() makes it so). */
bool collect(void *context, noctObjectId id, void *user);

/* Did the query find object i of the scene (with its generation)? */
bool in_found(const found *f, const scene *s, int i);

/* The objects in f are in increasing order of index. */
void expect_index_order(const found *f);

#endif /* NOCT_TESTS_TESTGEOM_H */
