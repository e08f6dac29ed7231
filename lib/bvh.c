/* SPDX-License-Identifier: MIT */
/*
 * Bounding-volume hierarchies (bvh.h): the builder, which mesh.c calls for
 * every mesh it makes, and the walk of one tree against a box. The pair
 * walk is inline, in bvh.h.
 */
#include "config.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bvh.h"

/* ---- the builder ------------------------------------------------------------ */

typedef struct bvh_build {
    noctMesh *m;
    uint32_t *order;    /* triangle permutation being partitioned */
    double *centroid;   /* 3 per triangle */
} bvh_build;

static void tri_bounds(const noctMesh *m, uint32_t t, double lo[3], double hi[3])
{
    for (int k = 0; k < 3; ++k) {
        lo[k] = INFINITY;
        hi[k] = -INFINITY;
    }
    for (int c = 0; c < 3; ++c) {
        const double *p = &m->v[3 * m->tri[3 * t + c]];
        for (int k = 0; k < 3; ++k) {
            lo[k] = noct_min(lo[k], p[k]);
            hi[k] = noct_max(hi[k], p[k]);
        }
    }
}

/* Reorder order[0, n) so that order[k] holds the triangle whose centroid
 * has the k-th smallest coordinate on axis, with no larger one before it
 * and no smaller one after it (quickselect, Hoare partition). */
static void select_kth(uint32_t *order, uint32_t n, uint32_t k,
                       const double *centroid, int axis)
{
    uint32_t lo = 0, hi = n - 1;
    while (lo < hi) {
        double pivot = centroid[3 * order[lo + (hi - lo) / 2] + axis];
        uint32_t i = lo, j = hi;
        while (i <= j) {
            while (centroid[3 * order[i] + axis] < pivot)
                ++i;
            while (centroid[3 * order[j] + axis] > pivot)
                --j;
            if (i <= j) {
                uint32_t t = order[i];
                order[i] = order[j];
                order[j] = t;
                ++i;
                if (j == 0)
                    break;
                --j;
            }
        }
        if (k <= j)
            hi = j;
        else if (k >= i)
            lo = i;
        else
            return;
    }
}

/* Build the subtree for order[first, first + count) into node index n;
 * nodes are handed out from *next. Median split on the longest axis of the
 * centroids. Depth is about log2(count / NOCT_BVH_LEAF). */
static void bvh_split(bvh_build *b, uint32_t n, uint32_t first, uint32_t count,
                      uint32_t *next)
{
    bvh_node *node = &b->m->nodes[n];
    double clo[3] = {INFINITY, INFINITY, INFINITY};
    double chi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int k = 0; k < 3; ++k) {
        node->lo[k] = INFINITY;
        node->hi[k] = -INFINITY;
    }
    for (uint32_t i = first; i < first + count; ++i) {
        double lo[3], hi[3];
        tri_bounds(b->m, b->order[i], lo, hi);
        for (int k = 0; k < 3; ++k) {
            node->lo[k] = noct_min(node->lo[k], lo[k]);
            node->hi[k] = noct_max(node->hi[k], hi[k]);
            clo[k] = noct_min(clo[k], b->centroid[3 * b->order[i] + k]);
            chi[k] = noct_max(chi[k], b->centroid[3 * b->order[i] + k]);
        }
    }
    if (count <= NOCT_BVH_LEAF) {
        node->first = first;
        node->count = count;
        return;
    }
    int axis = 0;
    for (int k = 1; k < 3; ++k)
        if (chi[k] - clo[k] > chi[axis] - clo[axis])
            axis = k;
    uint32_t half = count / 2;
    select_kth(&b->order[first], count, half, b->centroid, axis);
    uint32_t left = *next;
    *next += 2;
    node->first = left;
    node->count = 0;
    bvh_split(b, left, first, half, next);
    bvh_split(b, left + 1, first + half, count - half, next);
}

void noct_bvh_build_with(noctMesh *m, uint32_t *order, double *centroid, uint32_t *tri)
{
    bvh_build b = {m, order, centroid};
    for (uint32_t t = 0; t < m->nt; ++t) {
        b.order[t] = t;
        for (int k = 0; k < 3; ++k)
            b.centroid[3 * t + k] = (m->v[3 * m->tri[3 * t] + k] +
                                     m->v[3 * m->tri[3 * t + 1] + k] +
                                     m->v[3 * m->tri[3 * t + 2] + k]) / 3;
    }
    uint32_t next = 1;
    bvh_split(&b, 0, 0, (uint32_t)m->nt, &next);
    m->nnodes = next;
    for (uint32_t t = 0; t < m->nt; ++t)
        memcpy(&tri[3 * t], &m->tri[3 * b.order[t]], 3 * sizeof *tri);
}

noctStatus noct_bvh_build(noctMesh *m, noctError *err)
{
    m->nodes = malloc(2 * m->nt * sizeof *m->nodes);
    uint32_t *order = malloc(m->nt * sizeof *order);
    double *centroid = malloc(3 * m->nt * sizeof *centroid);
    uint32_t *tri = malloc(3 * m->nt * sizeof *tri);
    if (m->nodes == NULL || order == NULL || centroid == NULL || tri == NULL) {
        free(order);
        free(centroid);
        free(tri);
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    }
    noct_bvh_build_with(m, order, centroid, tri);
    free(m->tri);
    m->tri = tri;
    free(order);
    free(centroid);
    return NOCT_OK;
}

/* ---- the walk against a box ------------------------------------------------- */

bool noct_bvh_box_walk(const noct_placed_mesh *B, const double lo[3], const double hi[3],
                       noct_bvh_triangle_fn *fn, void *context)
{
    static const double zero[3] = {0, 0, 0};
    const noctMesh *m = B->m;
    uint32_t stack[64];
    size_t top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const bvh_node *n = &m->nodes[stack[--top]];
        if (!noct_boxes_overlap(n->lo, n->hi, B->t, lo, hi, zero))
            continue;
        if (n->count == 0) {
            /* a BVH is at most 33 deep, and the stack holds one node a
             * level and one more: the overflow cannot happen */
            NOCT_INVARIANT(top + 2 <= sizeof stack / sizeof *stack);
            if (top + 2 > sizeof stack / sizeof *stack)
                return true;
            stack[top++] = n->first;
            stack[top++] = n->first + 1;
            continue;
        }
        for (uint32_t i = n->first; i < n->first + n->count; ++i) {
            double a[3], b[3], c[3];
            noct_place_vertex(B, m->tri[3 * i], a);
            noct_place_vertex(B, m->tri[3 * i + 1], b);
            noct_place_vertex(B, m->tri[3 * i + 2], c);
            if (fn(context, i, a, b, c))
                return true;
        }
    }
    return false;
}

