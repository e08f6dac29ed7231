/* SPDX-License-Identifier: MIT */
/*
 * octree-demo: a first libnoctree program.
 *
 * Builds an N-objects octree over a handful of named points, N = 2, as in
 * the report's Figures 5-7: a leaf that receives its third point splits and
 * hands its points to its children. Then prints the tree with octPrint().
 *
 * Build against an installed copy:
 *   cc octree-demo.c $(pkg-config --cflags --libs noctree)
 *   cc octree-demo.c $(pkg-config --cflags --libs noctree-efficient)
 */
#include <stdio.h>
#include <stdlib.h>

#include <noctree/octree.h>

enum { N = 2, MAX_DEPTH = 8, MAX_POINTS = 8 };

typedef struct point {
    const char *name;
    double x, y, z;
} point;

/* A leaf's datum: the points it holds. A leaf holds at most N points unless
 * it is at MAX_DEPTH; the demo inserts at most MAX_POINTS points in all. */
typedef struct bucket {
    int count;
    const point *pts[MAX_POINTS];
} bucket;

/* Insert p into the subtree of n, the cell with centre c and half-size h.
 * The bits of a child's offset from OCT_LDB are R (+x), U (+y), F (+z). */
static int insert(octNode *n, const point *p, const double c[3], double h)
{
    if (octIsSplit(n)) {
        int r = p->x >= c[0], u = p->y >= c[1], f = p->z >= c[2];
        double q = h / 2;
        double cc[3] = {c[0] + (r ? q : -q), c[1] + (u ? q : -q),
                        c[2] + (f ? q : -q)};
        octNode *k = octChild(n, (octDirection)(OCT_LDB + 4 * r + 2 * u + f));
        return insert(k, p, cc, q);
    }
    bucket *b = octData(n);
    if (b == NULL) {
        if ((b = calloc(1, sizeof *b)) == NULL)
            return -1;
        octSwapData(n, b);
    }
    b->pts[b->count++] = p;
    if (b->count <= N || octGeneration(n) == MAX_DEPTH)
        return 0;
    /* The N+1st point: split, and hand every point to the child holding it
     * (which may split in turn). */
    if (!octSplit(n))
        return -1;
    octSwapData(n, NULL);
    int status = 0;
    for (int i = 0; i < b->count && status == 0; ++i)
        status = insert(n, b->pts[i], c, h);
    free(b);
    return status;
}

static void print_bucket(FILE *strm, const void *data)
{
    const bucket *b = data;
    for (int i = 0; i < b->count; ++i)
        fprintf(strm, "%s%s", i ? ", " : "", b->pts[i]->name);
}

static void free_bucket(void *data)
{
    free(data);
}

int main(void)
{
    static const point pts[] = {
        {"left", 0.10, 0.50, 0.50},  {"centre", 0.48, 0.52, 0.50},
        {"near", 0.45, 0.55, 0.55},
        {"right", 0.56, 0.50, 0.50}, {"top", 0.30, 0.90, 0.20},
        {"corner", 0.95, 0.05, 0.95}};
    _Static_assert(sizeof pts / sizeof *pts <= MAX_POINTS, "too many points");
    octNode *root = octCreate();
    if (root == NULL) {
        fputs("octree-demo: out of memory\n", stderr);
        return EXIT_FAILURE;
    }
    const double centre[3] = {0.5, 0.5, 0.5};
    for (size_t i = 0; i < sizeof pts / sizeof *pts; ++i) {
        if (insert(root, &pts[i], centre, 0.5) != 0) {
            fputs("octree-demo: out of memory\n", stderr);
            return EXIT_FAILURE;
        }
    }
    printf("N-objects octree, N = %d, of %zu points in the unit cube:\n", N,
           sizeof pts / sizeof *pts);
    bool ok = octPrint(root, print_bucket, stdout);
    octClear(root, free_bucket);
    octDispose(root);
    return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
