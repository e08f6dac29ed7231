/* SPDX-License-Identifier: MIT */
/*
 * The exact level on turned meshes in a relative frame (turned.h): the
 * hierarchies' boxes stay in their meshes' frames, node pairs are tested
 * as oriented boxes, vertices are placed only when a triangle pair reads
 * them, and containment casts a thin ray down the hierarchy. The answers
 * are those of the exact level on the same placed vertices (transform.h):
 * every decision is still a sign of orient3d or orient2d on them, and
 * every floating-point prune below is conservative by the bounds written
 * out with it.
 *
 * Notation: u = 2^-53, the unit roundoff; |x| of a vector is its largest
 * coordinate's magnitude unless said otherwise; V of a mesh bounds its
 * vertex coordinates (from its box), and all bounds are for the doubles
 * as stored (Ra is the matrix, not the rotation it stands for).
 */
#include "config.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <threads.h>

#include "narrowphase_internal.h"
#include "turned.h"

#define U53 0x1p-53
/* Absorbs the absolute errors of underflowing products and sums. */
#define TINY 0x1p-1000

/* ---- the per-thread vertex caches ----------------------------------------------- */

typedef struct turned_scratch {
    turned_vertex *v[2];
    size_t cap[2];
    uint32_t stamp;
} turned_scratch;

static _Thread_local turned_scratch scratch;
static tss_t scratch_key;
static once_flag scratch_once = ONCE_FLAG_INIT;
static bool scratch_key_made;

/* At a thread's exit: free its caches. */
static void scratch_free(void *s)
{
    turned_scratch *x = s;
    for (int i = 0; i < 2; ++i) {
        free(x->v[i]);
        x->v[i] = NULL;
        x->cap[i] = 0;
    }
}

static void scratch_key_make(void)
{
    scratch_key_made = tss_create(&scratch_key, scratch_free) == thrd_success;
}

/* This thread's caches, with room for na and nb vertices, and a new
 * stamp (no entry carries it). NULL without memory. */
static turned_scratch *scratch_get(size_t na, size_t nb)
{
    call_once(&scratch_once, scratch_key_make);
    turned_scratch *x = &scratch;
    const size_t need[2] = {na, nb};
    for (int i = 0; i < 2; ++i) {
        if (x->cap[i] >= need[i])
            continue;
        size_t cap = x->cap[i] > 0 ? x->cap[i] : 256;
        while (cap < need[i])
            cap *= 2;
        turned_vertex *v = calloc(cap, sizeof *v);
        if (v == NULL)
            return NULL;
        if (x->cap[0] == 0 && x->cap[1] == 0 && scratch_key_made)
            tss_set(scratch_key, x); /* the destructor frees them */
        free(x->v[i]);
        x->v[i] = v;
        x->cap[i] = cap;
    }
    if (++x->stamp == 0) { /* wrapped: no old entry may carry the stamp */
        for (int i = 0; i < 2; ++i)
            for (size_t k = 0; k < x->cap[i]; ++k)
                x->v[i][k].stamp = 0;
        x->stamp = 1;
    }
    return x;
}

/* ---- the frames ------------------------------------------------------------------ */

/* The largest vertex coordinate's magnitude of m (its box's). */
static double mesh_extent(const noctMesh *m)
{
    double V = 0;
    for (int k = 0; k < 3; ++k)
        V = noct_max(V, noct_max(fabs(m->lo[k]), fabs(m->hi[k])));
    return V;
}

/*
 * A side's own frame Psi(x) = R^T (x - t), and its bound e: a placed
 * vertex of v maps within e of v.
 *
 * The placement rounds fl(R v) by at most gamma3 sum_j |R_ij v_j| <=
 * 3.01 u 3 rho V (rho = max |R_ij| <= 1.0001, checked), then fl(r + t)
 * by u (3.01 V + |t|): the placed vertex is R v + t + eps with
 * |eps| <= delta = u (13 V + |t|) + TINY. Then Psi(placed) = R^T R v +
 * R^T eps = v + F v + R^T eps, F = R^T R - I: |F v| <= 3 phi V (phi
 * bounds |F_ij|: |fl(R^T R) - I| plus 10 u for the dot products'
 * rounding) and |R^T eps| <= lambda delta (lambda: the largest column
 * sum of |R|, rounded up). e adds 2 u V for the rounding of a node's
 * centre and half-extents (turned_nodes_apart_faces()). false when R is too far
 * from a rotation (rho > 1.0001 or phi > 2^-20), never for
 * noctQuatToMatrix()'s matrices.
 */
static bool side_frame(turned_side *s, double *lambda_out)
{
    const double *R = s->R;
    const double V = mesh_extent(s->m);
    const double delta = U53 * (13 * V + noct_max_abs3(s->t)) + TINY;
    if (!s->turned) {
        s->e = delta + 2 * U53 * V;
        *lambda_out = 1;
        return true;
    }
    double rho = 0, phi = 0, lambda = 0;
    for (int i = 0; i < 3; ++i) {
        double col = 0;
        for (int j = 0; j < 3; ++j) {
            rho = noct_max(rho, fabs(R[3 * i + j]));
            col += fabs(R[3 * j + i]);
            const double g = R[i] * R[j] + R[3 + i] * R[3 + j] + R[6 + i] * R[6 + j];
            phi = noct_max(phi, fabs(g - (i == j ? 1 : 0)));
        }
        lambda = noct_max(lambda, col);
    }
    phi += 10 * U53;
    lambda *= 1 + 4 * U53;
    if (!(rho <= 1.0001) || !(phi <= 0x1p-20))
        return false;
    s->e = 3 * phi * V + lambda * delta + 2 * U53 * V;
    *lambda_out = lambda;
    return true;
}

/*
 * The pair in A's frame (turned.h). With S = Ra^T Rb and U = Ra^T (tb -
 * ta) exact, Psi(B's placed w) = S w + U + Ra^T eps_b. S^ = fl(Ra^T Rb)
 * errs by gamma3 (1 + phi) <= 3.02 u an entry (|col_i| |col_j| <= 1 +
 * phi), so |(S - S^) w| <= 9.1 u VB; U^ = fl(Ra^T fl(tb - ta)) errs by
 * lambda_a (u + gamma3 (1 + u)) D <= 7.1 u D, D = |tb - ta|; and
 * |Ra^T eps_b| <= lambda_a delta_b. The node's centre and half-extents
 * round by u VB each, moved by S^ (row sums <= 1.74): 6.01 u VB. So eB =
 * 16 u VB + 12 u D + lambda_a delta_b bounds how far B's placed vertex
 * maps from S^ w + U^, and eA (side_frame()) A's from v.
 *
 * The node test on an axis xi (|xi|_1 <= 2.0002 for every axis it may
 * take: 1 for A's faces, <= sqrt(3) (1 + phi) for S^'s columns, and
 * <= 2 (1 + phi) for the cross products e_i x S^col_j, whose components
 * are entries of S^, exact): A's node
 * lies in its box (centre ca, half-extents ha) grown by eA, projecting
 * within sum |xi_k| ha_k + |xi|_1 eA of xi.ca; B's in the parallelepiped
 * S^ box + U^ grown by eB, projecting within sum_m hb_m |xi.S^col_m| +
 * |xi|_1 eB of xi.(S^ cb + U^). They are apart when |xi.T| exceeds both
 * radii, T = S^ cb + U^ - ca. Every magnitude the test meets is at most
 * W = VA + 4 VB + |U^| (|S^ cb| <= 3.0003 VB); computing T (6
 * operations), xi.T (3 more, |xi|_1 <= 2.0002), the radii (6 products of
 * coefficients within 9.1 u of their values, |S^|'s and G's, by half-extents
 * <= W) and the gap (2 subtractions) errs by under 100 u W in all. So a
 * computed gap above pad = 2.25 (eA + eB) + 128 u W + TINY proves the
 * nodes' placed triangles apart.
 */
bool turned_pair_setup(turned_pair *p, const noctMesh *a, const double Ra[9],
                       const double ta[3], bool ta_turned, const noctMesh *b,
                       const double Rb[9], const double tb[3], bool tb_turned)
{
    turned_scratch *x = scratch_get(a->nv, b->nv);
    if (x == NULL)
        return false;
    const noctMesh *m[2] = {a, b};
    const double *R[2] = {Ra, Rb}, *t[2] = {ta, tb};
    const bool turned[2] = {ta_turned, tb_turned};
    double lambda[2];
    for (int i = 0; i < 2; ++i) {
        turned_side *s = &p->s[i];
        s->m = m[i];
        memcpy(s->R, R[i], sizeof s->R);
        memcpy(s->t, t[i], sizeof s->t);
        s->turned = turned[i];
        s->cache = x->v[i];
        s->stamp = x->stamp;
        if (!side_frame(s, &lambda[i]))
            return false;
        if (!turned[i]) {
            static const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
            memcpy(s->R, I, sizeof s->R);
        }
    }
    const double *A = p->s[0].R, *B = p->s[1].R;
    double smax = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            p->S[3 * i + j] = (A[i] * B[j] + A[3 + i] * B[3 + j]) + A[6 + i] * B[6 + j];
            p->aS[3 * i + j] = fabs(p->S[3 * i + j]);
            smax = noct_max(smax, p->aS[3 * i + j]);
        }
    if (!(smax <= 1.0001))
        return false;
    const double d[3] = {tb[0] - ta[0], tb[1] - ta[1], tb[2] - ta[2]};
    for (int i = 0; i < 3; ++i)
        p->U[i] = (A[i] * d[0] + A[3 + i] * d[1]) + A[6 + i] * d[2];
    for (int j = 0; j < 3; ++j)
        for (int m2 = 0; m2 < 3; ++m2)
            p->G[3 * j + m2] = fabs(p->S[j] * p->S[m2] + p->S[3 + j] * p->S[3 + m2] +
                                    p->S[6 + j] * p->S[6 + m2]);
    const double VA = mesh_extent(a), VB = mesh_extent(b);
    const double D = noct_max_abs3(d) * (1 + U53);
    const double dB = U53 * (13 * VB + noct_max_abs3(tb)) + TINY;
    const double eB = 16 * U53 * VB + 12 * U53 * D + lambda[0] * dB;
    const double W = VA + 4 * VB + noct_max_abs3(p->U);
    p->pad = (2.25 * (p->s[0].e + eB) + 128 * U53 * W + TINY) * (1 + 8 * U53);
    return true;
}

/* ---- the boundaries: node pairs as oriented boxes ------------------------------- */

/* The placed box of a triangle. */
static inline void tri_box(double x[3][3], double lo[3], double hi[3])
{
    for (int k = 0; k < 3; ++k) {
        lo[k] = noct_min(x[0][k], noct_min(x[1][k], x[2][k]));
        hi[k] = noct_max(x[0][k], noct_max(x[1][k], x[2][k]));
    }
}

static inline bool boxes_meet(const double alo[3], const double ahi[3], const double blo[3],
                              const double bhi[3])
{
    return !(ahi[0] < blo[0] || bhi[0] < alo[0] || ahi[1] < blo[1] || bhi[1] < alo[1] ||
             ahi[2] < blo[2] || bhi[2] < alo[2]);
}

/*
 * Do the placed boundaries meet? The pair walk of bvh.h with the
 * oriented-box test as its prune; at a pair of leaves, every pair of
 * placed triangles whose placed boxes meet (exact: they are the placed
 * vertices' own boxes) is decided by tri_tri(). true also if the stack
 * would overflow (never within the size limits).
 */
static bool turned_boundaries_meet(turned_pair *p, const exact_ctx *x, noctNarrowStats *st)
{
    turned_side *A = &p->s[0], *B = &p->s[1];
    const bvh_node *nodes_a = A->m->nodes, *nodes_b = B->m->nodes;
    /* each pending pair keeps its B node's centre and radii in A's frame
     * (turned_node_b()), which a split of A leaves as they are */
    struct { uint32_t a, b; double c[3], r[3]; } stack[NOCT_BVH_PAIR_STACK];
    size_t top = 0;
    stack[top].a = 0;
    stack[top].b = 0;
    turned_node_b(p, &nodes_b[0], stack[top].c, stack[top].r);
    ++top;
    uint64_t pairs = 0, tris = 0;
    bool met = false;
    while (top > 0 && !met) {
        --top;
        const uint32_t ia = stack[top].a, ib = stack[top].b;
        const bvh_node *na = &nodes_a[ia], *nb = &nodes_b[ib];
        ++pairs;
        if (turned_nodes_apart_faces(p, na, nb, stack[top].c, stack[top].r))
            continue;
        if (na->count > 0 && nb->count > 0) {
            /* B's leaf in chunks (made meshes' leaves hold NOCT_BVH_LEAF) */
            for (uint32_t j0 = 0; j0 < nb->count && !met; j0 += NOCT_BVH_LEAF) {
                const uint32_t nj = nb->count - j0 < NOCT_BVH_LEAF ? nb->count - j0
                                                                    : NOCT_BVH_LEAF;
                double tb[NOCT_BVH_LEAF][3][3], blo[NOCT_BVH_LEAF][3], bhi[NOCT_BVH_LEAF][3];
                for (uint32_t j = 0; j < nj; ++j) {
                    turned_triangle(B, nb->first + j0 + j, tb[j]);
                    tri_box(tb[j], blo[j], bhi[j]);
                }
                for (uint32_t i = na->first; i < na->first + na->count && !met; ++i) {
                    double ta[3][3], alo[3], ahi[3];
                    turned_triangle(A, i, ta);
                    tri_box(ta, alo, ahi);
                    for (uint32_t j = 0; j < nj; ++j) {
                        if (!boxes_meet(alo, ahi, blo[j], bhi[j]))
                            continue;
                        ++tris;
                        if (tri_tri(x, ta, tb[j])) {
                            met = true;
                            break;
                        }
                    }
                }
            }
            continue;
        }
        const bool split_a = noct_bvh_split_a(na, nb);
        NOCT_INVARIANT(top + 2 <= NOCT_BVH_PAIR_STACK);
        if (top + 2 > NOCT_BVH_PAIR_STACK) {
            met = true; /* the conservative answer */
            break;
        }
        if (split_a) {
            /* the entry popped is still in place at stack[top] */
            stack[top + 1] = stack[top];
            stack[top].a = na->first;
            stack[top + 1].a = na->first + 1;
            top += 2;
        } else {
            for (uint32_t c = 0; c < 2; ++c) {
                stack[top].a = ia;
                stack[top].b = nb->first + c;
                turned_node_b(p, &nodes_b[nb->first + c], stack[top].c, stack[top].r);
                ++top;
            }
        }
    }
    if (st) {
        st->bvh_pairs += pairs;
        st->triangle_pairs += tris;
    }
    return met;
}

/* ---- containment: a thin ray down the hierarchy --------------------------------- */

/* Psi_s(x) = R^T (x - t), in floating point. */
static inline void to_frame(const turned_side *s, const double x[3], double out[3])
{
    const double d[3] = {x[0] - s->t[0], x[1] - s->t[1], x[2] - s->t[2]};
    const double *R = s->R;
    for (int i = 0; i < 3; ++i)
        out[i] = (R[i] * d[0] + R[3 + i] * d[1]) + R[6 + i] * d[2];
}

/*
 * The bound on to_frame()'s error for points x of magnitude |x - t| <=
 * D: fl(x - t) errs by u D, the product by gamma3 lambda (1 + u) D, the
 * difference moved by R^T (lambda <= 1.7322): under 8 u D; 16 u D + TINY
 * with room.
 */
static inline double frame_error(const double x[3], const turned_side *s)
{
    double D = 0;
    for (int k = 0; k < 3; ++k)
        D = noct_max(D, fabs(x[k] - s->t[k]));
    return 16 * U53 * D * (1 + 4 * U53) + TINY;
}

/*
 * Is point p (placed; not on out's boundary) inside out's solid? The
 * parity of the crossings of out's placed surface by a segment pq, q
 * outside it, as noct_contains() counts them (exactly, with a new q when
 * the count would be ambiguous), but counting only the triangles of the
 * leaves the segment may reach: the segment runs along out's own x axis
 * (q = p + L (c0 + a c1 + b c2), c the columns of R, |a|, |b| < 2^-9),
 * so that in out's frame it is thin, and its box there, grown by the
 * error of mapping it (frame_error()) and by out's own e (side_frame()),
 * meets only the nodes near the ray. A node whose box, grown so, misses
 * the segment's box holds no triangle the segment meets. q is outside
 * out's solid: its image lies beyond the root box grown likewise on the
 * x axis, and the solid lies in the hull of its placed vertices, inside
 * that box. *in_box is false when p maps outside out's grown root box:
 * then it is outside without a ray.
 */
static noctStatus turned_contains(turned_side *out, const double p[3], const exact_ctx *x,
                                  bool *inside, bool *in_box)
{
    const noctMesh *m = out->m;
    *inside = false;
    *in_box = false;
    if (m->surface) /* encloses nothing */
        return NOCT_OK;
    const bvh_node *root = &m->nodes[0];
    double pp[3];
    to_frame(out, p, pp);
    const double ep = frame_error(p, out) + out->e;
    for (int k = 0; k < 3; ++k)
        if (pp[k] < root->lo[k] - 2 * ep || pp[k] > root->hi[k] + 2 * ep)
            return NOCT_OK;
    *in_box = true;
    const double V = mesh_extent(m);
    uint64_t seed = 0x9e3779b97f4a7c15u;
    for (int attempt = 0; attempt < 64; ++attempt) {
        double f[2];
        for (int k = 0; k < 2; ++k) {
            seed = seed * 6364136223846793005u + 1442695040888963407u;
            f[k] = ((double)(seed >> 11) * 0x1p-53 - 0.5) * 0x1p-8;
        }
        const double *R = out->R;
        const double dir[3] = {R[0] + f[0] * R[1] + f[1] * R[2],
                               R[3] + f[0] * R[4] + f[1] * R[5],
                               R[6] + f[0] * R[7] + f[1] * R[8]};
        double L = (root->hi[0] - pp[0]) + (root->hi[0] - root->lo[0]) + 8 * ep +
                   0x1p-30 * (V + noct_max_abs3(p) + noct_max_abs3(out->t)) + TINY;
        double q[3], qq[3], pad = 0;
        bool beyond = false;
        for (int grow = 0; grow < 60 && !beyond; ++grow, L *= 2) {
            for (int k = 0; k < 3; ++k)
                q[k] = p[k] + L * dir[k];
            to_frame(out, q, qq);
            /* the segment's image lies within es of the box of pp and
             * qq; a node's placed triangles within out->e of its box;
             * the sums below round by under 4 u of the magnitudes */
            const double es = noct_max(frame_error(p, out), frame_error(q, out));
            pad = (2 * (es + out->e) +
                   4 * U53 * (V + noct_max_abs3(pp) + noct_max_abs3(qq))) * (1 + 8 * U53);
            beyond = qq[0] > root->hi[0] + 2 * pad;
        }
        if (!beyond)
            return NOCT_ERR_NUMERIC;
        double slo[3], shi[3];
        for (int k = 0; k < 3; ++k) {
            slo[k] = noct_min(pp[k], qq[k]) - pad;
            shi[k] = noct_max(pp[k], qq[k]) + pad;
        }
        bool ambiguous = false;
        unsigned crossings = 0;
        uint32_t stack[64];
        size_t top = 0;
        stack[top++] = 0;
        while (top > 0 && !ambiguous) {
            const bvh_node *n = &m->nodes[stack[--top]];
            if (n->hi[0] < slo[0] || n->lo[0] > shi[0] || n->hi[1] < slo[1] ||
                n->lo[1] > shi[1] || n->hi[2] < slo[2] || n->lo[2] > shi[2])
                continue;
            if (n->count == 0) {
                /* a BVH is at most 33 deep: never overflows */
                NOCT_INVARIANT(top + 2 <= sizeof stack / sizeof *stack);
                if (top + 2 > sizeof stack / sizeof *stack)
                    return NOCT_ERR_INVARIANT;
                stack[top++] = n->first;
                stack[top++] = n->first + 1;
                continue;
            }
            for (uint32_t t = n->first; t < n->first + n->count && !ambiguous; ++t) {
                double tr[3][3];
                turned_triangle(out, t, tr);
                const int r = noct_parity_step(x, p, q, tr[0], tr[1], tr[2]);
                ambiguous = r < 0;
                crossings += r > 0;
            }
        }
        if (!ambiguous) {
            *inside = crossings % 2 == 1;
            return NOCT_OK;
        }
    }
    return NOCT_ERR_NUMERIC;
}

/* With the boundaries apart: does a piece of in's boundary lie inside
 * out's solid? One vertex of each piece is asked. */
static noctStatus turned_piece_inside(turned_side *in, turned_side *out, const exact_ctx *x,
                                      noctNarrowStats *st, bool *inside)
{
    *inside = false;
    if (out->m->surface)
        return NOCT_OK;
    for (size_t i = 0; i < in->m->npieces; ++i) {
        double p[3];
        memcpy(p, turned_vertex_of(in, in->m->piece[i]), sizeof p);
        bool in_box;
        const noctStatus s = turned_contains(out, p, x, inside, &in_box);
        if (st && in_box)
            ++st->containment_tests;
        if (s != NOCT_OK || *inside)
            return s;
    }
    return NOCT_OK;
}

/* ---- the exact level ------------------------------------------------------------ */

noctStatus noct_collide_exact_turned(const noctMesh *a, const noctTransform *xa,
                                     const noctMesh *b, const noctTransform *xb,
                                     double R[2][9], const bool turned[2],
                                     bool *colliding, noctNarrowStats *stats, noctError *err)
{
    turned_pair p;
    if ((turned[0] && !a->turn_fine) || (turned[1] && !b->turn_fine) ||
        !turned_pair_setup(&p, a, R[0], xa->p, turned[0], b, R[1], xb->p, turned[1]))
        return noct_collide_exact_views(a, xa, b, xb, R, turned, colliding, stats, err);
    exact_ctx x = {stats ? &stats->exact_fallbacks : NULL};
    if (stats)
        ++stats->exact_tests;
    if (turned_boundaries_meet(&p, &x, stats)) {
        *colliding = true;
        return NOCT_OK;
    }
    for (int i = 0; i < 2; ++i) {
        bool inside;
        const noctStatus st = turned_piece_inside(&p.s[i], &p.s[1 - i], &x, stats, &inside);
        if (st != NOCT_OK)
            return noct_fail(err, st, -1, 0, "collision test: %s", noctStatusString(st));
        if (inside) {
            *colliding = true;
            return NOCT_OK;
        }
    }
    *colliding = false;
    return NOCT_OK;
}
