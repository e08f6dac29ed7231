/* SPDX-License-Identifier: MIT */
/*
 * Private: turned meshes decided in a relative frame (narrowphase_turned.c),
 * as FCL and RAPID decide oriented boxes, made exact. Never installed.
 *
 * A turned mesh keeps its hierarchy's boxes in its own frame. For a pair
 * of meshes placed at (Ra, ta) and (Rb, tb), each placed vertex being
 * fl(fl(R v) + t) (transform.h), the pair is looked at through the
 * affine map Psi(x) = Ra^T (x - ta), exact (Ra^T is the transpose of the
 * double matrix, and near a rotation, so Psi is one-to-one and two sets
 * meet iff their images do). A's placed vertex of v maps to
 * v + F v + Ra^T e (F = Ra^T Ra - I, e its placement's rounding), within
 * eA of v; B's placed vertex of w maps to S w + U + ... with S = Ra^T Rb
 * and U = Ra^T (tb - ta), computed once per call (S^, U^) and within eB
 * of S^ w + U^. So a node of A holds triangles inside its box grown by
 * eA, and a node of B triangles inside the parallelepiped S^ box + U^
 * grown by eB: the oriented-box test on A's 3 axes and the columns of
 * S^, with an allowance for its own rounding, proves a pair of nodes apart without turning a box or a
 * vertex (narrowphase_turned.c, turned_pair_setup(), writes the bounds
 * out). A vertex is rotated and placed only when a triangle pair reads
 * it, bit for bit as transform.h places it, and kept for the rest of the
 * call in a per-thread cache, stamped per call.
 */
#ifndef NOCT_LIB_TURNED_H
#define NOCT_LIB_TURNED_H

#include <stdbool.h>
#include <stdint.h>

#include "internal.h"
#include "mesh_internal.h"

/* A placed vertex in the cache, and the call that placed it. */
typedef struct turned_vertex {
    double p[3];
    uint32_t stamp;
    uint32_t pad_;
} turned_vertex;

/* One mesh of a turned pair: its placement and its cache. */
typedef struct turned_side {
    const noctMesh *m;
    double R[9];        /* rows; the identity when not turned */
    double t[3];
    bool turned;
    turned_vertex *cache; /* m->nv entries */
    uint32_t stamp;
    /* Psi_m(x) = R^T (x - t), the mesh's own frame: a placed vertex of
     * v maps within e of v (turned_side_frame()). */
    double e;
} turned_side;

/* Vertex vi of s, placed: fl(fl(R v) + t), as noct_rotate() and the
 * placement compute it (-ffp-contract=off: no fused multiply-add), or
 * fl(v + t) when not turned. */
static NOCT_ALWAYS_INLINE const double *turned_vertex_of(turned_side *s, uint32_t vi)
{
    turned_vertex *c = &s->cache[vi];
    if (c->stamp != s->stamp) {
        const double *v = &s->m->v[3 * vi];
        if (s->turned) {
            const double *R = s->R;
            for (int i = 0; i < 3; ++i) {
                const double r = (R[3 * i] * v[0] + R[3 * i + 1] * v[1]) + R[3 * i + 2] * v[2];
                c->p[i] = r + s->t[i];
            }
        } else {
            for (int i = 0; i < 3; ++i)
                c->p[i] = v[i] + s->t[i];
        }
        c->stamp = s->stamp;
    }
    return c->p;
}

/* Triangle i (BVH order) of s, placed, into x. */
static NOCT_ALWAYS_INLINE void turned_triangle(turned_side *s, uint32_t i, double x[3][3])
{
    for (int c = 0; c < 3; ++c) {
        const double *p = turned_vertex_of(s, s->m->tri[3 * i + c]);
        x[c][0] = p[0];
        x[c][1] = p[1];
        x[c][2] = p[2];
    }
}

/* A pair of placed meshes in A's frame. */
typedef struct turned_pair {
    turned_side s[2];
    double S[9];        /* S^ = fl(Ra^T Rb), rows */
    double aS[9];       /* |S^| */
    double U[3];        /* U^ = fl(Ra^T fl(tb - ta)) */
    double G[9];        /* |S^col_j . S^col_m|, B's radius on its own axes */
    double pad;         /* the node test's allowance (turned_pair_setup()) */
} turned_pair;

/* Set up the pair (a at xa's (Ra, ta), b at (Rb, tb); turned says which
 * turn), the caches from this thread's scratch. false without memory, or
 * (never for the matrices noctQuatToMatrix() makes) when a matrix is too
 * far from a rotation for the bounds: the caller then decides otherwise. */
bool turned_pair_setup(turned_pair *p, const noctMesh *a, const double Ra[9],
                       const double ta[3], bool ta_turned, const noctMesh *b,
                       const double Rb[9], const double tb[3], bool tb_turned);

/* B's node nb in A's frame: its centre S^ cb + U^ (c) and its radii on
 * A's axes, |S^| hb (r); a walk that splits A keeps them for the B node
 * it does not split. */
static NOCT_ALWAYS_INLINE void turned_node_b(const turned_pair *p, const bvh_node *nb,
                                             double c[3], double r[3])
{
    double cb[3], hb[3];
    for (int k = 0; k < 3; ++k) {
        cb[k] = 0.5 * (nb->lo[k] + nb->hi[k]);
        hb[k] = 0.5 * (nb->hi[k] - nb->lo[k]);
    }
    const double *S = p->S, *aS = p->aS;
    for (int k = 0; k < 3; ++k) {
        c[k] = (S[3 * k] * cb[0] + S[3 * k + 1] * cb[1]) + S[3 * k + 2] * cb[2] + p->U[k];
        r[k] = aS[3 * k] * hb[0] + aS[3 * k + 1] * hb[1] + aS[3 * k + 2] * hb[2];
    }
}

/*
 * The oriented-box test of node na of A against node nb of B (given also
 * by turned_node_b()'s c and r): true when an axis proves their placed
 * triangles apart (the gap beyond the pad), false when it cannot. The
 * axes are A's faces, then B's (the columns of S^). The nine cross
 * products of an edge of each would prove more pairs apart, but the
 * exact level's walk measured more instructions with them (164.5 against
 * 141.8 million on 900 soup poses of bench-peers --soups): they cost
 * more than the descents they save.
 */
static NOCT_ALWAYS_INLINE bool turned_nodes_apart_faces(const turned_pair *p,
                                                        const bvh_node *na,
                                                        const bvh_node *nb,
                                                        const double c[3], const double r[3])
{
    double ca[3], ha[3], T[3];
    for (int k = 0; k < 3; ++k) {
        ca[k] = 0.5 * (na->lo[k] + na->hi[k]);
        ha[k] = 0.5 * (na->hi[k] - na->lo[k]);
        T[k] = c[k] - ca[k];
        if (fabs(T[k]) - ha[k] - r[k] > p->pad)
            return true;
    }
    double hb[3];
    for (int k = 0; k < 3; ++k)
        hb[k] = 0.5 * (nb->hi[k] - nb->lo[k]);
    const double *S = p->S, *aS = p->aS;
    for (int j = 0; j < 3; ++j) {
        const double d = S[j] * T[0] + S[3 + j] * T[1] + S[6 + j] * T[2];
        const double ra = aS[j] * ha[0] + aS[3 + j] * ha[1] + aS[6 + j] * ha[2];
        const double rb = p->G[3 * j] * hb[0] + p->G[3 * j + 1] * hb[1] + p->G[3 * j + 2] * hb[2];
        if (fabs(d) - ra - rb > p->pad)
            return true;
    }
    return false;
}

#endif /* NOCT_LIB_TURNED_H */
