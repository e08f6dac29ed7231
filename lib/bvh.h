/* SPDX-License-Identifier: MIT */
/*
 * Private: bounding-volume hierarchies over a mesh's triangles (bvh.c
 * builds them) and the walks over them. Never installed.
 *
 * A mesh's BVH is a binary tree of boxes, nodes[0] the root, at most
 * NOCT_BVH_LEAF triangles a leaf (the triangles in BVH order), built by
 * median splits on the longest axis of the centroids, so at most about
 * log2(triangles) deep. A walk places boxes and triangles at a mesh's
 * translation t: fl(v + t) is monotone in v, so a placed box holds its
 * placed triangles exactly, with no padding.
 *
 * One pair walk serves every question on two meshes (collision, the
 * margin, and the walks to come): it descends the pair of trees, asks the
 * caller's prune test of each pair of nodes and hands each pair of placed
 * triangles of two leaves to the caller's pair test. It is always inlined
 * and its tests are static functions of the caller's file, so the
 * compiler inlines them too and the hot loops pay no indirect call.
 */
#ifndef NOCT_LIB_BVH_H
#define NOCT_LIB_BVH_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "internal.h"
#include "mesh_internal.h"

/* Triangles per BVH leaf, at most. */
#define NOCT_BVH_LEAF 4

/* Build m's BVH (m->nodes, m->nnodes) and put m->tri in its order; NOMEM. */
noctStatus noct_bvh_build(noctMesh *m, noctError *err);

/* The same without allocating: m->nodes has room for its nodes (how many
 * depends on m->nt alone: median splits), order, centroid and tri for
 * m->nt, 3 m->nt and 3 m->nt entries. m->tri is left as it was; tri gets
 * its triangles in BVH order, order[t] the index in m->tri of the
 * triangle at BVH position t. */
void noct_bvh_build_with(noctMesh *m, uint32_t *order, double *centroid, uint32_t *tri);

/* A mesh placed at translation t. */
typedef struct noct_placed_mesh {
    const noctMesh *m;
    double t[3];
} noct_placed_mesh;

/* Vertex vi of o as placed: fl(v + t). */
static inline void noct_place_vertex(const noct_placed_mesh *o, uint32_t vi, double out[3])
{
    const double *v = &o->m->v[3 * vi];
    out[0] = v[0] + o->t[0];
    out[1] = v[1] + o->t[1];
    out[2] = v[2] + o->t[2];
}

/* Closed boxes [alo, ahi] + ta and [blo, bhi] + tb overlap. */
static inline bool noct_boxes_overlap(const double alo[3], const double ahi[3],
                                      const double ta[3], const double blo[3],
                                      const double bhi[3], const double tb[3])
{
    for (int k = 0; k < 3; ++k)
        if (ahi[k] + ta[k] < blo[k] + tb[k] || bhi[k] + tb[k] < alo[k] + ta[k])
            return false;
    return true;
}

/* Which node of a pair a walk splits: A's unless B's is the inner one
 * and A's a leaf, or B's box is the larger (the sum of its extents). */
static inline bool noct_bvh_split_a(const bvh_node *na, const bvh_node *nb)
{
    double sa = 0, sb = 0;
    for (int k = 0; k < 3; ++k) {
        sa += na->hi[k] - na->lo[k];
        sb += nb->hi[k] - nb->lo[k];
    }
    return nb->count > 0 || (na->count == 0 && sa >= sb);
}

/* The pair walk's tests: prune says a pair of nodes holds nothing of
 * interest; pair decides a pair of placed triangles (A's triangle i, B's
 * triangle j, in BVH order), true to stop. */
typedef bool noct_bvh_prune_fn(void *context, const bvh_node *na, const bvh_node *nb);
typedef bool noct_bvh_pair_fn(void *context, uint32_t i, double a[3][3], uint32_t j,
                              double b[3][3]);

/* Node pairs a pair walk keeps pending, at most: the trees of meshes
 * within the size limits are far shallower. */
#define NOCT_BVH_PAIR_STACK 256

/*
 * Walk the pairs of nodes of A's and B's BVHs from the roots: a pair that
 * prune rejects is dropped; a pair of leaves has its triangle pairs
 * placed and handed to pair, A's triangle first, until pair returns true;
 * otherwise the node with the larger box (or the inner one) is split.
 * Returns true if pair did, or (conservatively: never reached within the
 * size limits) if the stack would overflow.
 */
static NOCT_ALWAYS_INLINE bool noct_bvh_pair_walk(const noct_placed_mesh *A,
                                                  const noct_placed_mesh *B,
                                                  noct_bvh_prune_fn *prune,
                                                  noct_bvh_pair_fn *pair, void *context)
{
    struct { uint32_t a, b; } stack[NOCT_BVH_PAIR_STACK];
    size_t top = 0;
    stack[top].a = 0;
    stack[top++].b = 0;
    while (top > 0) {
        --top;
        const bvh_node *na = &A->m->nodes[stack[top].a];
        const bvh_node *nb = &B->m->nodes[stack[top].b];
        if (prune(context, na, nb))
            continue;
        if (na->count > 0 && nb->count > 0) {
            for (uint32_t i = na->first; i < na->first + na->count; ++i) {
                double ta[3][3];
                for (int c = 0; c < 3; ++c)
                    noct_place_vertex(A, A->m->tri[3 * i + c], ta[c]);
                for (uint32_t j = nb->first; j < nb->first + nb->count; ++j) {
                    double tb[3][3];
                    for (int c = 0; c < 3; ++c)
                        noct_place_vertex(B, B->m->tri[3 * j + c], tb[c]);
                    if (pair(context, i, ta, j, tb))
                        return true;
                }
            }
            continue;
        }
        const bool split_a = noct_bvh_split_a(na, nb);
        const uint32_t ia = stack[top].a, ib = stack[top].b;
        NOCT_INVARIANT(top + 2 <= NOCT_BVH_PAIR_STACK);
        if (top + 2 > NOCT_BVH_PAIR_STACK)
            return true; /* the conservative answer */
        if (split_a) {
            stack[top].a = na->first;     stack[top++].b = ib;
            stack[top].a = na->first + 1; stack[top++].b = ib;
        } else {
            stack[top].a = ia; stack[top++].b = nb->first;
            stack[top].a = ia; stack[top++].b = nb->first + 1;
        }
    }
    return false;
}

/* The box walk's test: placed triangle i (a, b, c) of the mesh, true to
 * stop. */
typedef bool noct_bvh_triangle_fn(void *context, uint32_t i, double a[3], double b[3],
                                  double c[3]);

/* Call fn for each placed triangle of B whose leaf's placed box meets the
 * box [lo, hi], in the BVH's order, until it returns true; true if one
 * did (or, never within the size limits, if the stack would overflow). */
bool noct_bvh_box_walk(const noct_placed_mesh *B, const double lo[3], const double hi[3],
                       noct_bvh_triangle_fn *fn, void *context);

#endif /* NOCT_LIB_BVH_H */
