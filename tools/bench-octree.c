/* SPDX-License-Identifier: MIT */
/*
 * bench-octree: nanoseconds per octree ADT operation.
 *
 * Built twice from this file: against the defensive library and, with
 * NOCT_EFFICIENT, against the efficient one (inline accessors). Each binary
 * prints CSV rows "flavour,operation,ns_per_op,ops_per_repeat"; the script
 * tools/bench-octree.sh runs both and prints the efficient/defensive
 * ratios. Each figure is the median of the repeats.
 *
 * The neighbor rows time octGtEqFaceNeighbor(), octGtEqEdgeNeighbor() and
 * octGtEqVertexNeighbor() from random leaves of a random tree of depth 8,
 * in random directions of each kind.
 *
 * Usage: bench-octree [REPEATS [DEPTH]]   (defaults 7 and 6)
 */
#define _POSIX_C_SOURCE 200809L
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include <noctree/neighbor.h>
#include <noctree/octree.h>

#include "benchutil.h"

#ifdef NOCT_EFFICIENT
#  define FLAVOUR "efficient"
#else
#  define FLAVOUR "defensive"
#endif

static volatile uintptr_t sink;

static double now_ns(void)
{
    return 1e9 * tool_now();
}

/* Split breadth-first down to depth; returns the number of splits. The
 * leaves of the last level are collected in *leaves. */
static size_t build(octNode *root, int depth, octNode ***leaves, size_t *nleaves)
{
    size_t cap = 1, len = 1, splits = 0;
    octNode **level = malloc(sizeof *level);
    if (level == NULL)
        exit(EXIT_FAILURE);
    level[0] = root;
    for (int d = 0; d < depth; ++d) {
        cap = len * 8;
        octNode **next = malloc(cap * sizeof *next);
        if (next == NULL)
            exit(EXIT_FAILURE);
        size_t k = 0;
        for (size_t i = 0; i < len; ++i) {
            if (!octSplit(level[i])) {
                fputs("bench-octree: out of memory\n", stderr);
                exit(EXIT_FAILURE);
            }
            ++splits;
            for (int v = OCT_LDB; v <= OCT_RUF; ++v)
                next[k++] = octChild(level[i], (octDirection)v);
        }
        free(level);
        level = next;
        len = k;
    }
    *leaves = level;
    *nleaves = len;
    return splits;
}

static uint64_t rng_state = 42;

static uint64_t rng(void)
{
    return tool_rand(&rng_state);
}

/* A random tree of depth 8: full to depth 3, then random leaves split. */
static octNode *random_tree(octNode ***leaves, size_t *nleaves)
{
    octNode *root = octCreate(), **lv;
    size_t n;
    if (root == NULL)
        exit(EXIT_FAILURE);
    build(root, 3, &lv, &n);
    size_t cap = n * 64;
    lv = realloc(lv, cap * sizeof *lv);
    if (lv == NULL)
        exit(EXIT_FAILURE);
    for (int s = 0; s < 30000 && n + 8 <= cap; ++s) {
        size_t i = (size_t)(rng() % n);
        octNode *leaf = lv[i];
        if (octGeneration(leaf) >= 8 || !octSplit(leaf))
            continue;
        lv[i] = octChild(leaf, OCT_LDB);
        for (int v = OCT_LDF; v <= OCT_RUF; ++v)
            lv[n++] = octChild(leaf, (octDirection)v);
    }
    *leaves = lv;
    *nleaves = n;
    return root;
}

static void bench_neighbors(double *face, double *edge, double *vertex,
                            size_t *queries)
{
    octNode **leaves;
    size_t nleaves;
    octNode *root = random_tree(&leaves, &nleaves);
    enum { Q = 1 << 20 };
    static octNode *from[Q];
    static octDirection dir[3][Q];
    for (size_t q = 0; q < Q; ++q) {
        from[q] = leaves[rng() % nleaves];
        dir[0][q] = (octDirection)(OCT_L + rng() % 6);
        dir[1][q] = (octDirection)(OCT_LD + rng() % 12);
        dir[2][q] = (octDirection)(OCT_LDB + rng() % 8);
    }
    uintptr_t acc = 0;
    double t0 = now_ns();
    for (size_t q = 0; q < Q; ++q)
        acc += (uintptr_t)octGtEqFaceNeighbor(from[q], dir[0][q]);
    double t1 = now_ns();
    for (size_t q = 0; q < Q; ++q)
        acc += (uintptr_t)octGtEqEdgeNeighbor(from[q], dir[1][q]);
    double t2 = now_ns();
    for (size_t q = 0; q < Q; ++q)
        acc += (uintptr_t)octGtEqVertexNeighbor(from[q], dir[2][q]);
    double t3 = now_ns();
    sink = acc;
    *face = (t1 - t0) / Q;
    *edge = (t2 - t1) / Q;
    *vertex = (t3 - t2) / Q;
    *queries = Q;
    free(leaves);
    octDispose(root);
}

int main(int argc, char **argv)
{
    int repeats = argc > 1 ? atoi(argv[1]) : 7;
    int depth = argc > 2 ? atoi(argv[2]) : 6;
    if (repeats < 1 || repeats > 1000 || depth < 2 || depth > 8) {
        fputs("usage: bench-octree [REPEATS (1-1000) [DEPTH (2-8)]]\n", stderr);
        return 2;
    }
    enum { SPLIT, JOIN, CHILD, PARENT, DATA, FACE, EDGE, VERTEX, NOPS };
    static const char *const names[NOPS] = {
        "split", "join", "child", "parent", "data+swap",
        "face-nbr", "edge-nbr", "vertex-nbr"};
    double *t[NOPS];
    size_t ops[NOPS] = {0};
    for (int o = 0; o < NOPS; ++o)
        if ((t[o] = malloc((size_t)repeats * sizeof **t)) == NULL)
            return EXIT_FAILURE;

    for (int r = 0; r < repeats; ++r) {
        octNode *root = octCreate();
        octNode **leaves;
        size_t nleaves;
        double t0 = now_ns();
        ops[SPLIT] = build(root, depth, &leaves, &nleaves);
        t[SPLIT][r] = (now_ns() - t0) / (double)ops[SPLIT];

        /* child: random root-to-leaf descents. */
        size_t walks = 200000;
        uintptr_t acc = 0;
        t0 = now_ns();
        for (size_t w = 0; w < walks; ++w) {
            uint64_t bits = rng();
            octNode *n = root;
            while (octIsSplit(n)) {
                n = octChild(n, (octDirection)(OCT_LDB + (bits & 7)));
                bits >>= 3;
            }
            acc += (uintptr_t)n;
        }
        ops[CHILD] = walks * (size_t)depth;
        t[CHILD][r] = (now_ns() - t0) / (double)ops[CHILD];

        /* parent: leaf-to-root ascents from random leaves. */
        t0 = now_ns();
        for (size_t w = 0; w < walks; ++w) {
            octNode *n = leaves[rng() % nleaves];
            while (octParent(n) != NULL)
                n = octParent(n);
            acc += (uintptr_t)n;
        }
        ops[PARENT] = walks * (size_t)depth;
        t[PARENT][r] = (now_ns() - t0) / (double)ops[PARENT];

        /* data: read and swap the datum of every leaf. */
        t0 = now_ns();
        for (int pass = 0; pass < 8; ++pass)
            for (size_t i = 0; i < nleaves; ++i)
                acc += (uintptr_t)octSwapData(leaves[i], octData(leaves[i]));
        ops[DATA] = 8 * nleaves;
        t[DATA][r] = (now_ns() - t0) / (double)ops[DATA];
        sink = acc;

        /* join: every node of the last split level, each with 8 leaves. */
        size_t njoin = nleaves / 8;
        t0 = now_ns();
        for (size_t i = 0; i < njoin; ++i)
            octJoin(octParent(leaves[8 * i]), NULL);
        ops[JOIN] = njoin;
        t[JOIN][r] = (now_ns() - t0) / (double)njoin;
        free(leaves);
        octDispose(root);

        bench_neighbors(&t[FACE][r], &t[EDGE][r], &t[VERTEX][r], &ops[FACE]);
        ops[EDGE] = ops[VERTEX] = ops[FACE];
    }

    for (int o = 0; o < NOPS; ++o) {
        printf("%s,%s,%.2f,%zu\n", FLAVOUR, names[o], tool_median(t[o], (size_t)repeats),
               ops[o]);
        free(t[o]);
    }
    return EXIT_SUCCESS;
}
