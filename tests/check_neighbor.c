/* SPDX-License-Identifier: MIT */
/*
 * Check suite for neighbor finding (include/noctree/neighbor.h).
 *
 * Oracles, independent of the library's tables:
 *  - geometry: every table entry is recomputed from the coordinates of an
 *    octant and of the direction's vector, both read off the directions'
 *    names ("RUF" is +x +y +z);
 *  - brute force: a node's neighbor is found from its integer coordinates
 *    (kept as bit strings, so any depth works): step one cell in the
 *    direction, then descend from the root by the target's coordinate bits.
 */
#include <check.h>
#include <math.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>

#include <noctree/neighbor.h>
#include <noctree/octree.h>

#include "testutil.h"

/* ---- geometry from names --------------------------------------------- */

/* The vector of a direction: -1, 0 or +1 per axis, from its name. */
static void dir_vector(octDirection d, int v[3])
{
    v[0] = v[1] = v[2] = 0;
    for (const char *c = octDirToStr(d); *c != '\0'; ++c) {
        switch (*c) {
        case 'L': v[0] = -1; break;
        case 'R': v[0] = +1; break;
        case 'D': v[1] = -1; break;
        case 'U': v[1] = +1; break;
        case 'B': v[2] = -1; break;
        case 'F': v[2] = +1; break;
        default: ck_abort_msg("unexpected name %s", octDirToStr(d));
        }
    }
}

/* The direction with vector v (any components zero), by building its name;
 * OMEGA for the zero vector. */
static octDirection dir_from_vector(const int v[3])
{
    char name[4];
    int n = 0;
    if (v[0]) name[n++] = v[0] > 0 ? 'R' : 'L';
    if (v[1]) name[n++] = v[1] > 0 ? 'U' : 'D';
    if (v[2]) name[n++] = v[2] > 0 ? 'F' : 'B';
    name[n] = '\0';
    return n == 0 ? OCT_OMEGA : octStrToDir(name);
}

static int sign_of(double x)
{
    return (x > 0) - (x < 0);
}

/* Octant O of the parent block [-1, 1]^3 is the unit cube whose centre is
 * 0.5 * (vector of O). */

START_TEST(table_adj_from_geometry)
{
    for (int i = 0; i < OCT_NUM_DIRECTIONS; ++i) {
        int d[3];
        dir_vector((octDirection)i, d);
        for (int o = OCT_LDB; o <= OCT_RUF; ++o) {
            int ov[3];
            dir_vector((octDirection)o, ov);
            /* The octant's closed box meets the parent's I feature (the
             * points with p_a = d_a on each axis I names) iff on each such
             * axis d_a lies in the octant's interval. */
            bool touches = true;
            for (int a = 0; a < 3; ++a) {
                double lo = ov[a] > 0 ? 0 : -1, hi = ov[a] > 0 ? 1 : 0;
                if (d[a] != 0 && (d[a] < lo || d[a] > hi))
                    touches = false;
            }
            ck_assert_msg(octAdj((octDirection)i, (octDirection)o) == touches,
                          "ADJ(%s, %s)", octDirToStr((octDirection)i),
                          octDirToStr((octDirection)o));
        }
    }
}
END_TEST

/* Centre of the unit block next to octant o in direction d, and the index
 * per axis of the size-2 parent block that contains it (0 = O's parent). */
static void neighbor_block(octDirection d, octDirection o, double c[3], int k[3])
{
    int dv[3], ov[3];
    dir_vector(d, dv);
    dir_vector(o, ov);
    for (int a = 0; a < 3; ++a) {
        c[a] = 0.5 * ov[a] + dv[a];
        k[a] = (int)floor((c[a] + 1) / 2);
    }
}

START_TEST(table_reflect_from_geometry)
{
    for (int i = 0; i < OCT_NUM_DIRECTIONS; ++i) {
        for (int o = OCT_LDB; o <= OCT_RUF; ++o) {
            double c[3];
            int k[3], t[3];
            neighbor_block((octDirection)i, (octDirection)o, c, k);
            for (int a = 0; a < 3; ++a) /* position within its own parent */
                t[a] = sign_of(c[a] - 2 * k[a]);
            ck_assert_int_eq(octReflect((octDirection)i, (octDirection)o),
                             dir_from_vector(t));
        }
    }
}
END_TEST

/* The feature of O's parent crossed by the step to the neighbor: the axes
 * on which the neighbor's parent differs, with their signs. */
static int crossed(octDirection i, octDirection o, int v[3])
{
    double c[3];
    int n = 0;
    neighbor_block(i, o, c, v);
    for (int a = 0; a < 3; ++a)
        n += v[a] != 0;
    return n;
}

/* table(i, o) for directions i from first, against the geometry: the
 * direction of the axes that i crosses out of octant o when they are
 * `axes` in number, else OMEGA. */
static void check_common_table(int first, int axes,
                               octDirection (*table)(octDirection, octDirection),
                               const char *name)
{
    for (int i = first; i <= OCT_RUF; ++i) {
        for (int o = OCT_LDB; o <= OCT_RUF; ++o) {
            int v[3];
            int n = crossed((octDirection)i, (octDirection)o, v);
            octDirection want = n == axes ? dir_from_vector(v) : OCT_OMEGA;
            ck_assert_msg(table((octDirection)i, (octDirection)o) == want, "%s(%s, %s)", name,
                          octDirToStr((octDirection)i), octDirToStr((octDirection)o));
        }
    }
}

START_TEST(table_common_face_from_geometry)
{
    check_common_table(OCT_LD, 1, octCommonFace, "COMMON_FACE");
}
END_TEST

START_TEST(table_common_edge_from_geometry)
{
    check_common_table(OCT_LDB, 2, octCommonEdge, "COMMON_EDGE");
}
END_TEST

/* ---- brute-force neighbors -------------------------------------------- */

/* The vertex direction with bits r, u, f (1 = R, U, F), from its name. */
static octDirection vertex_of(int r, int u, int f)
{
    int v[3] = {r ? 1 : -1, u ? 1 : -1, f ? 1 : -1};
    return dir_from_vector(v);
}

/*
 * The greater-or-equal neighbor of p in direction d by coordinates. p's
 * coordinate on each axis is the string of its ancestors' bits on that axis,
 * most significant (the root's child) first. Stepping by -1, 0 or +1 is
 * binary increment or decrement of that string; a carry out of the top
 * means the cube is outside the root.
 */
static octNode *brute_neighbor(octNode *root, octNode *p, octDirection d)
{
    int g = octGeneration(p);
    int dv[3];
    dir_vector(d, dv);
    unsigned char *bits = malloc(3 * (size_t)(g + 1));
    EXPECT(bits != NULL);
    octNode *n = p;
    for (int l = g - 1; l >= 0; --l, n = octParent(n)) {
        int ov[3];
        dir_vector(octChildType(n), ov);
        for (int a = 0; a < 3; ++a)
            bits[3 * l + a] = ov[a] > 0;
    }
    EXPECT(n == root);
    for (int a = 0; a < 3; ++a) {
        if (dv[a] == 0)
            continue;
        unsigned char stop = dv[a] > 0 ? 0 : 1; /* the bit that absorbs */
        int l = g - 1;
        for (; l >= 0; --l) {
            unsigned char b = bits[3 * l + a];
            bits[3 * l + a] = !b;
            if (b == stop)
                break;
        }
        if (l < 0) { /* carried out of the root */
            free(bits);
            return NULL;
        }
    }
    n = root;
    for (int l = 0; l < g && octIsSplit(n); ++l)
        n = octChild(n, vertex_of(bits[3 * l], bits[3 * l + 1], bits[3 * l + 2]));
    free(bits);
    return n;
}

static octNode *by_kind(octNode *p, octDirection d)
{
    if (OCT_IS_FACE(d))
        return octGtEqFaceNeighbor(p, d);
    if (OCT_IS_EDGE(d))
        return octGtEqEdgeNeighbor(p, d);
    return octGtEqVertexNeighbor(p, d);
}

/* Every node, all 26 directions, against brute force. Returns the number
 * of queries whose answer was a node (so callers can check the trees were
 * not trivial). */
static size_t check_all_neighbors(octNode *root)
{
    size_t n, found = 0;
    octNode **all = tree_nodes(root, &n);
    for (size_t i = 0; i < n; ++i) {
        for (int d = 0; d < OCT_NUM_DIRECTIONS; ++d) {
            octNode *want = brute_neighbor(root, all[i], (octDirection)d);
            octNode *got = by_kind(all[i], (octDirection)d);
            if (got != want)
                ck_abort_msg("neighbor %s of a generation %d node: got %p, "
                             "want %p", octDirToStr((octDirection)d),
                             octGeneration(all[i]), (void *)got, (void *)want);
            EXPECT(octGtEqNeighbor(all[i], (octDirection)d) == want);
            found += want != NULL;
        }
    }
    free(all);
    return found;
}

/* Random tree: split random leaves below max_depth. */
static octNode *random_tree(uint64_t *rng, int splits, int max_depth)
{
    octNode *root = octCreate();
    ck_assert(octSplit(root));
    for (int s = 0; s < splits; ++s) {
        size_t n;
        octNode **all = tree_nodes(root, &n);
        octNode *pick = all[test_rand_below(rng, n)];
        if (!octIsSplit(pick) && octGeneration(pick) < max_depth)
            ck_assert(octSplit(pick));
        free(all);
    }
    return root;
}

START_TEST(neighbors_random_trees)
{
    uint64_t rng = 1000 + (uint64_t)_i;
    octNode *root = random_tree(&rng, 120, 8);
    ck_assert_uint_gt(check_all_neighbors(root), 1000);
    octDispose(root);
}
END_TEST

START_TEST(neighbors_full_tree)
{
    octNode *root = octCreate();
    size_t n;
    ck_assert(octSplit(root));
    for (int level = 1; level < 3; ++level) {
        octNode **all = tree_nodes(root, &n);
        for (size_t i = 0; i < n; ++i)
            if (!octIsSplit(all[i]))
                ck_assert(octSplit(all[i]));
        free(all);
    }
    ck_assert_uint_eq(tree_validate(root), 1 + 8 + 64 + 512);
    check_all_neighbors(root);
    /* In a full tree every interior leaf has all 26 neighbors at its own
     * generation. */
    octNode *inner = octChild(octChild(octChild(root, OCT_LDB), OCT_RUF), OCT_RUF);
    for (int d = 0; d < OCT_NUM_DIRECTIONS; ++d) {
        octNode *q = octGtEqNeighbor(inner, (octDirection)d);
        ck_assert_ptr_nonnull(q);
        ck_assert_int_eq(octGeneration(q), 3);
    }
    octDispose(root);
}
END_TEST

/* A deep single path with a mirror path next to it, so that queries climb
 * and descend far more than 64 levels (past the on-stack climb buffer). */
START_TEST(neighbors_deep_paths)
{
    const int depth = 150;
    octNode *root = octCreate();
    octNode *a = root, *b = root;
    ck_assert(octSplit(root));
    a = octChild(root, OCT_LDB);
    b = octChild(root, OCT_RDB);
    for (int l = 1; l < depth; ++l) {
        ck_assert(octSplit(a));
        ck_assert(octSplit(b));
        a = octChild(a, OCT_RUF); /* hugs the x = 0.5 plane from the left */
        b = octChild(b, OCT_LUF); /* and from the right */
    }
    ck_assert_int_eq(octGeneration(a), depth);
    ck_assert_ptr_eq(octGtEqFaceNeighbor(a, OCT_R), b);
    ck_assert_ptr_eq(octGtEqFaceNeighbor(b, OCT_L), a);
    ck_assert_ptr_eq(brute_neighbor(root, a, OCT_R), b);
    /* Along the path, every node against brute force; and random other
     * nodes deep on a random path. */
    check_all_neighbors(root);
    uint64_t rng = 77;
    octNode *c = octChild(root, OCT_LUB);
    for (int l = 0; l < 100; ++l) {
        ck_assert(octSplit(c));
        c = octChild(c, (octDirection)(OCT_LDB + test_rand_below(&rng, 8)));
    }
    check_all_neighbors(root);
    octDispose(root);
}
END_TEST

/* A climb longer than the on-stack buffer whose direction changes on the
 * way: P is 150 levels deep with x bits 0 1 1 ... 1 and y bits 0 for the
 * top 100 levels, 1 below. Its RU climb goes up as RU for 50 levels, then
 * continues as R (the common face) to the root's child. The neighbor's side
 * is split down to P's generation, so the descent uses every level. */
START_TEST(neighbors_deep_direction_change)
{
    const int depth = 150;
    octNode *root = octCreate(), *p = root;
    for (int g = 1; g <= depth; ++g) {
        ck_assert(octSplit(p));
        p = octChild(p, vertex_of(g > 1, g > 100, 1));
    }
    octNode *q = brute_neighbor(root, p, OCT_RU);
    ck_assert_ptr_nonnull(q);
    while (octGeneration(q) < depth) {
        ck_assert(octSplit(q));
        q = brute_neighbor(root, p, OCT_RU);
    }
    ck_assert_ptr_eq(octGtEqEdgeNeighbor(p, OCT_RU), q);
    ck_assert_ptr_eq(octGtEqVertexNeighbor(p, OCT_RUF), brute_neighbor(root, p, OCT_RUF));
    check_all_neighbors(root);
    octDispose(root);
}
END_TEST

START_TEST(neighbors_after_random_edits)
{
    uint64_t rng = 5000 + (uint64_t)_i;
    octNode *root = random_tree(&rng, 80, 6);
    for (int step = 0; step < 60; ++step) {
        size_t n;
        octNode **all = tree_nodes(root, &n);
        octNode *pick = all[test_rand_below(&rng, n)];
        if (octIsSplit(pick) && octParent(pick) != NULL)
            octJoin(pick, NULL);
        else if (!octIsSplit(pick) && octGeneration(pick) < 8)
            ck_assert(octSplit(pick));
        free(all);
        if (step % 10 == 9) {
            tree_validate(root);
            check_all_neighbors(root);
        }
    }
    octDispose(root);
}
END_TEST

START_TEST(root_and_leaves_of_larger_size)
{
    octNode *root = octCreate();
    for (int d = 0; d < OCT_NUM_DIRECTIONS; ++d)
        ck_assert_ptr_null(octGtEqNeighbor(root, (octDirection)d));
    ck_assert(octSplit(root));
    octNode *ldb = octChild(root, OCT_LDB);
    ck_assert(octSplit(ldb));
    octNode *small = octChild(ldb, OCT_RUF);
    /* Its R, U and F neighbors and their edges and vertex are the larger
     * leaves RDB, LUB, LDF, ... of the root. */
    ck_assert_ptr_eq(octGtEqFaceNeighbor(small, OCT_R), octChild(root, OCT_RDB));
    ck_assert_ptr_eq(octGtEqFaceNeighbor(small, OCT_U), octChild(root, OCT_LUB));
    ck_assert_ptr_eq(octGtEqFaceNeighbor(small, OCT_F), octChild(root, OCT_LDF));
    ck_assert_ptr_eq(octGtEqEdgeNeighbor(small, OCT_RU), octChild(root, OCT_RUB));
    ck_assert_ptr_eq(octGtEqVertexNeighbor(small, OCT_RUF), octChild(root, OCT_RUF));
    /* Inside its own parent: equal-size siblings. */
    ck_assert_ptr_eq(octGtEqFaceNeighbor(small, OCT_L), octChild(ldb, OCT_LUF));
    ck_assert_ptr_eq(octGtEqVertexNeighbor(small, OCT_LDB), octChild(ldb, OCT_LDB));
    /* Outside the root. */
    ck_assert_ptr_null(octGtEqFaceNeighbor(octChild(ldb, OCT_LDB), OCT_L));
    ck_assert_ptr_null(octGtEqEdgeNeighbor(octChild(ldb, OCT_LDF), OCT_LD));
    ck_assert_ptr_null(octGtEqVertexNeighbor(octChild(ldb, OCT_RDB), OCT_RDB));
    ck_assert_ptr_eq(octGtEqEdgeNeighbor(small, OCT_RD), octChild(root, OCT_RDB));
    /* A split neighbor of equal size is returned as it is. */
    ck_assert_ptr_eq(octGtEqFaceNeighbor(octChild(root, OCT_RDB), OCT_L), ldb);
    ck_assert(octIsSplit(octGtEqFaceNeighbor(octChild(root, OCT_RDB), OCT_L)));
    octDispose(root);
}
END_TEST

/* ---- octVectorToDirections ------------------------------------------- */

static size_t quantize(double x, double y, double z, octDirection out[8])
{
    for (int i = 0; i < 8; ++i)
        out[i] = (octDirection)-1;
    size_t n = octVectorToDirections(x, y, z, out);
    ck_assert_uint_le(n, 7);
    ck_assert_int_eq(out[n], OCT_OMEGA);
    return n;
}

static void expect_list(double x, double y, double z, const char *want)
{
    octDirection out[8];
    size_t n = quantize(x, y, z, out);
    char got[64] = "";
    for (size_t i = 0; i < n; ++i) {
        strcat(got, i ? " " : "");
        strcat(got, octDirToStr(out[i]));
    }
    ck_assert_str_eq(got, want);
}

START_TEST(vector_examples)
{
    expect_list(1, 0, 0, "R");
    expect_list(-1, 0, 0, "L");
    expect_list(0, 2, 0, "U");
    expect_list(0, 0, 1, "F"); /* +z is front, as documented */
    expect_list(0, 0, -1, "B");
    expect_list(0, 0, 0, "");
    expect_list(-0.0, 0.0, -0.0, "");
    expect_list(1, -2, 3, "R D F RD RF DF RDF");
    expect_list(-1, 1, -1, "L U B LU LB UB LUB");
    expect_list(0, 1, -1, "U B UB");
    expect_list(-1, 0, 1, "L F LF");
    expect_list(1e-300, 0, -INFINITY, "R B RB");
}
END_TEST

/* Property: the list is exactly the non-empty subsets of the moving axes,
 * each with the component's sign, every one a direction an object moving
 * that way can cross into; and for each listed direction the motion points
 * into that neighbor (positive dot product with the direction's vector). */
START_TEST(vector_property)
{
    uint64_t rng = 99;
    for (int t = 0; t < 20000; ++t) {
        double v[3];
        for (int a = 0; a < 3; ++a) {
            uint64_t r = test_rand(&rng);
            v[a] = (r % 4 == 0) ? 0.0 : ((double)(r >> 11) * 0x1p-53 - 0.5);
        }
        octDirection out[8];
        size_t n = quantize(v[0], v[1], v[2], out);
        int moving = (v[0] != 0) + (v[1] != 0) + (v[2] != 0);
        EXPECT(n == (size_t)((1 << moving) - 1));
        for (size_t i = 0; i < n; ++i) {
            int d[3];
            dir_vector(out[i], d);
            for (int a = 0; a < 3; ++a)
                EXPECT(d[a] == 0 || d[a] == sign_of(v[a]));
            for (size_t j = 0; j < i; ++j)
                EXPECT(out[j] != out[i]);
            if (i > 0) { /* faces, then edges, then the vertex */
                int prev[3];
                dir_vector(out[i - 1], prev);
                int np = !!prev[0] + !!prev[1] + !!prev[2];
                int nc = !!d[0] + !!d[1] + !!d[2];
                EXPECT(np < nc || (np == nc && out[i - 1] < out[i]));
            }
        }
    }
}
END_TEST

/* ---- death tests ------------------------------------------------------- */
#ifndef NOCT_EFFICIENT

START_TEST(die_adj)
{
    if (_i == 0)
        octAdj(OCT_L, OCT_L);      /* O not a vertex */
    else
        octAdj(OCT_OMEGA, OCT_LDB); /* I not a direction */
}
END_TEST

START_TEST(die_reflect)
{
    if (_i == 0)
        octReflect(OCT_L, OCT_RU);
    else
        octReflect(OCT_OMEGA, OCT_RUF);
}
END_TEST

START_TEST(die_common_face)
{
    if (_i == 0)
        octCommonFace(OCT_L, OCT_LDB);   /* I a face */
    else
        octCommonFace(OCT_LD, OCT_OMEGA); /* O not a vertex */
}
END_TEST

START_TEST(die_common_edge)
{
    if (_i == 0)
        octCommonEdge(OCT_LD, OCT_LDB);  /* I an edge */
    else
        octCommonEdge(OCT_LDB, OCT_L);   /* O not a vertex */
}
END_TEST

START_TEST(die_neighbor_wrong_kind)
{
    octNode *root = octCreate();
    switch (_i) {
    case 0: octGtEqFaceNeighbor(root, OCT_LD); break;
    case 1: octGtEqEdgeNeighbor(root, OCT_L); break;
    case 2: octGtEqVertexNeighbor(root, OCT_LU); break;
    case 3: octGtEqNeighbor(root, OCT_OMEGA); break;
    case 4: octGtEqFaceNeighbor(NULL, OCT_L); break;
    case 5: octGtEqEdgeNeighbor(NULL, OCT_LD); break;
    default: octGtEqVertexNeighbor(NULL, OCT_LDB); break;
    }
}
END_TEST

START_TEST(die_vector_nan)
{
    octDirection out[8];
    octVectorToDirections(1, NAN, 0, out);
}
END_TEST
#endif

static Suite *neighbor_suite(void)
{
    Suite *s = suite_create("neighbor");
    TCase *tc = test_case(s, "tables", 0, NULL);
    add_tests(tc, table_adj_from_geometry, table_reflect_from_geometry,
              table_common_face_from_geometry, table_common_edge_from_geometry);

    tc = test_case(s, "greater-or-equal neighbors", 120, NULL);
    tcase_add_test(tc, root_and_leaves_of_larger_size);
    tcase_add_loop_test(tc, neighbors_random_trees, 0, 12);
    add_tests(tc, neighbors_full_tree, neighbors_deep_paths, neighbors_deep_direction_change);
    tcase_add_loop_test(tc, neighbors_after_random_edits, 0, 6);

    tc = test_case(s, "octVectorToDirections", 0, NULL);
    tcase_add_test(tc, vector_examples);
    tcase_add_test(tc, vector_property);

#ifndef NOCT_EFFICIENT
    TCase *d = test_case(s, "requires clauses", 0, "death");
    tcase_add_loop_test_raise_signal(d, die_adj, SIGABRT, 0, 2);
    tcase_add_loop_test_raise_signal(d, die_reflect, SIGABRT, 0, 2);
    tcase_add_loop_test_raise_signal(d, die_common_face, SIGABRT, 0, 2);
    tcase_add_loop_test_raise_signal(d, die_common_edge, SIGABRT, 0, 2);
    tcase_add_loop_test_raise_signal(d, die_neighbor_wrong_kind, SIGABRT, 0, 7);
    tcase_add_test_raise_signal(d, die_vector_nan, SIGABRT);
#endif
    return s;
}

int main(void)
{
    return run_suite(neighbor_suite());
}
