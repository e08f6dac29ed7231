/* SPDX-License-Identifier: MIT */
/* The tests' own geometry of random rotated scenes: see testgeom.h. */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "testgeom.h"
#include "testutil.h"

uint64_t rng = RNG_SEED;

double uniform(void)
{
    return test_uniform(&rng);
}

/* ---- the scenes' ideal geometry ---------------------------------------------- */

/* An object is a union of at most two boxes of its own frame (centre c,
 * half-extents h), rotated by R (the quaternion's matrix, in long double)
 * and translated by t. */




void quat_matrix(const noctQuat *q, long double R[9])
{
    const long double x = q->x, y = q->y, z = q->z, w = q->w;
    const long double n = sqrtl(x * x + y * y + z * z + w * w);
    const long double a = x / n, b = y / n, c = z / n, d = w / n;
    R[0] = 1 - 2 * (b * b + c * c);
    R[1] = 2 * (a * b - c * d);
    R[2] = 2 * (a * c + b * d);
    R[3] = 2 * (a * b + c * d);
    R[4] = 1 - 2 * (a * a + c * c);
    R[5] = 2 * (b * c - a * d);
    R[6] = 2 * (a * c - b * d);
    R[7] = 2 * (b * c + a * d);
    R[8] = 1 - 2 * (a * a + b * b);
}

void random_quat(noctQuat *q)
{
    test_random_quat(&rng, q);
}

/* p in the object's frame: R^T (p - t). */
void to_local(const ideal *g, const long double p[3], long double out[3])
{
    for (int k = 0; k < 3; ++k)
        out[k] = g->R[k] * (p[0] - g->t[0]) + g->R[3 + k] * (p[1] - g->t[1]) +
                 g->R[6 + k] * (p[2] - g->t[2]);
}

void dir_to_local(const ideal *g, const long double d[3], long double out[3])
{
    for (int k = 0; k < 3; ++k)
        out[k] = g->R[k] * d[0] + g->R[3 + k] * d[1] + g->R[6 + k] * d[2];
}

/* 1: certainly in the closed solid, 0: certainly out, -1: within the
 * margin of its boundary. */
int ideal_contains(const ideal *g, const double p[3])
{
    const long double pl[3] = {p[0], p[1], p[2]};
    long double l[3];
    to_local(g, pl, l);
    int verdict = 0;
    for (int j = 0; j < g->npieces; ++j) {
        long double depth = 1e300L; /* (no infinities: valgrind's long double is a double) */
        for (int k = 0; k < 3; ++k)
            depth = fminl(depth, g->pc[j].h[k] - fabsl(l[k] - g->pc[j].c[k]));
        if (depth > MARGIN)
            return 1;
        if (depth >= -MARGIN)
            verdict = -1;
    }
    return verdict;
}

/* A world box of a piece: its 3 axes (R's columns), centre, half-extents. */

obb piece_box(const ideal *g, int j)
{
    obb b;
    for (int k = 0; k < 3; ++k) {
        b.c[k] = g->t[k];
        for (int i = 0; i < 3; ++i)
            b.c[k] += g->R[3 * k + i] * g->pc[j].c[i];
        b.h[k] = g->pc[j].h[k];
        for (int i = 0; i < 3; ++i)
            b.u[k][i] = g->R[3 * i + k]; /* column k */
    }
    return b;
}

/* Separating-axis test of two boxes: 1 they certainly overlap (by more
 * than the margin on every axis), 0 certainly apart, -1 within it. */
int obb_meet(const obb *a, const obb *b)
{
    long double axes[15][3];
    int n = 0;
    for (int i = 0; i < 3; ++i) {
        memcpy(axes[n++], a->u[i], sizeof axes[0]);
        memcpy(axes[n++], b->u[i], sizeof axes[0]);
    }
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const long double *x = a->u[i], *y = b->u[j];
            long double c[3] = {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2],
                                x[0] * y[1] - x[1] * y[0]};
            long double l = sqrtl(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
            if (l < 1e-6L)
                continue; /* parallel edges: the face axes cover it */
            for (int k = 0; k < 3; ++k)
                axes[n][k] = c[k] / l;
            ++n;
        }
    long double least = 1e300L;
    for (int m = 0; m < n; ++m) {
        const long double *u = axes[m];
        long double ra = 0, rb = 0, d = 0;
        for (int i = 0; i < 3; ++i) {
            ra += a->h[i] * fabsl(a->u[i][0] * u[0] + a->u[i][1] * u[1] + a->u[i][2] * u[2]);
            rb += b->h[i] * fabsl(b->u[i][0] * u[0] + b->u[i][1] * u[1] + b->u[i][2] * u[2]);
        }
        for (int k = 0; k < 3; ++k)
            d += (b->c[k] - a->c[k]) * u[k];
        least = fminl(least, ra + rb - fabsl(d));
    }
    return least > MARGIN ? 1 : least < -MARGIN ? 0 : -1;
}

int union_meet(const ideal *a, const ideal *b)
{
    int verdict = 0;
    for (int i = 0; i < a->npieces; ++i)
        for (int j = 0; j < b->npieces; ++j) {
            obb x = piece_box(a, i), y = piece_box(b, j);
            int v = obb_meet(&x, &y);
            if (v == 1)
                return 1;
            if (v < 0)
                verdict = -1;
        }
    return verdict;
}

/* The segment p + s d, s in [0, 1], against the object: -1 within the
 * margin, else whether it meets the solid and, if so, the least s and
 * the world normal of the face it enters (0 when it starts inside);
 * *sharp: that face is certain (the entry is not near an edge). */
int ideal_ray(const ideal *g, const double p[3], const double d[3], long double *s,
                     long double normal[3], bool *sharp)
{
    const long double pw[3] = {p[0], p[1], p[2]}, dw[3] = {d[0], d[1], d[2]};
    long double pl[3], dl[3];
    to_local(g, pw, pl);
    dir_to_local(g, dw, dl);
    const long double len = sqrtl(dw[0] * dw[0] + dw[1] * dw[1] + dw[2] * dw[2]);
    int verdict = 0;
    long double best = 1e300L;
    bool any = false;
    for (int j = 0; j < g->npieces; ++j) {
        long double lo = 0, hi = 1, second = -1e300L;
        int axis = -1, sign = 0;
        bool uncertain = false;
        for (int k = 0; k < 3 && hi >= lo; ++k) {
            const long double a = g->pc[j].c[k] - g->pc[j].h[k] - pl[k];
            const long double b = g->pc[j].c[k] + g->pc[j].h[k] - pl[k];
            if (fabsl(dl[k]) < 1e-300L) {
                if (a > MARGIN || b < -MARGIN) {
                    hi = -1;
                } else if (a > -MARGIN || b < MARGIN) {
                    uncertain = true;
                }
                continue;
            }
            long double s0 = a / dl[k], s1 = b / dl[k];
            int sg = -1;
            if (s0 > s1) {
                long double tmp = s0;
                s0 = s1;
                s1 = tmp;
                sg = 1;
            }
            if (s0 > lo) {
                second = fmaxl(second, lo);
                lo = s0;
                axis = k;
                sign = sg;
            } else {
                second = fmaxl(second, s0);
            }
            hi = fminl(hi, s1);
        }
        const long double gap = (hi - lo) * len;
        if (uncertain || fabsl(gap) <= MARGIN || (lo > 0 && lo * len <= MARGIN) ||
            (hi < 1 && fabsl(1 - lo) * len <= MARGIN)) {
            verdict = -1;
            continue;
        }
        if (gap < 0)
            continue;
        if (!any || lo < best) {
            best = lo;
            any = true;
            for (int k = 0; k < 3; ++k)
                normal[k] = axis < 0 ? 0 : sign * g->R[3 * k + axis];
            *sharp = axis < 0 || (lo - second) * len > 1e-6L;
        }
    }
    if (verdict < 0)
        return -1;
    if (!any)
        return 0;
    *s = best;
    return 1;
}

/* ---- building scenes --------------------------------------------------------------- */

double world_margin = 0;

noctWorld *new_world(int N, noctAccuracy accuracy)
{
    noctWorldDef wd = noctDefaultWorldDef();
    wd.effects = NOCT_EFFECT_EVENTS;
    wd.N = N;
    wd.accuracy = accuracy;
    wd.margin = world_margin;
    noctWorld *w;
    ck_assert_int_eq(noctWorldCreate(&wd, &w, NULL), NOCT_OK);
    return w;
}

uint64_t random_bits(void)
{
    return uniform() < 0.6 ? NOCT_FILTER_ALL : (uint64_t)1 << (int)(3 * uniform());
}

/* n random objects in [0, 6]^3 (the same for the same seed). */
void random_scene(scene *s, int n, int N, noctAccuracy accuracy, noctMesh *ell)
{
    memset(s, 0, sizeof *s);
    s->w = new_world(N, accuracy);
    s->n = n;
    for (int i = 0; i < n; ++i) {
        noctObjectDef d = noctDefaultObjectDef();
        ideal *g = &s->g[i];
        s->kind[i] = (int)(3 * uniform());
        double h[3];
        for (int k = 0; k < 3; ++k)
            h[k] = 0.15 + 0.6 * uniform();
        for (int k = 0; k < 3; ++k)
            d.transform.p[k] = 6 * uniform();
        if (uniform() < 0.15)
            d.transform.q = (noctQuat){0, 0, 0, 1};
        else
            random_quat(&d.transform.q);
        if (s->kind[i] == 2) {
            d.mesh = ell;
            g->npieces = 2;
            g->pc[0] = (piece){{0, -0.5L, 0}, {1, 0.5L, 0.5L}};
            g->pc[1] = (piece){{-0.5L, 0, 0}, {0.5L, 1, 0.5L}};
        } else {
            ck_assert_int_eq(noctMeshCreateBox(h[0], h[1], h[2], &s->mesh[i], NULL), NOCT_OK);
            if (s->kind[i] == 0)
                memcpy(d.half_extents, h, sizeof h);
            else
                d.mesh = s->mesh[i];
            g->npieces = 1;
            g->pc[0] = (piece){{0, 0, 0}, {h[0], h[1], h[2]}};
        }
        quat_matrix(&d.transform.q, g->R);
        for (int k = 0; k < 3; ++k)
            g->t[k] = d.transform.p[k];
        d.category = s->cat[i] = random_bits();
        d.mask = s->mask[i] = random_bits();
        d.sensor = s->sensor[i] = uniform() < 0.1;
        d.user_data = &s->id[i];
        s->x[i] = d.transform;
        ck_assert_int_eq(noctWorldCreateObject(s->w, &d, &s->id[i], NULL), NOCT_OK);
    }
}

noctObjectDef scene_object_def(const scene *s, int i, noctMesh *ell)
{
    noctObjectDef d = noctDefaultObjectDef();
    d.transform = s->x[i];
    if (s->kind[i] == 2) {
        d.mesh = ell;
    } else if (s->kind[i] == 1) {
        d.mesh = s->mesh[i];
    } else {
        for (int k = 0; k < 3; ++k)
            d.half_extents[k] = (double)s->g[i].pc[0].h[k];
    }
    d.category = s->cat[i];
    d.mask = s->mask[i];
    d.sensor = s->sensor[i];
    return d;
}

void free_scene(scene *s)
{
    noctWorldDestroy(s->w);
    for (int i = 0; i < s->n; ++i)
        noctMeshDestroy(s->mesh[i]);
}

bool passes(const scene *s, int i, noctQueryFilter f)
{
    return (s->cat[i] & f.mask) != 0 && (f.category & s->mask[i]) != 0;
}

noctQueryFilter random_filter(void)
{
    noctQueryFilter f = noctDefaultQueryFilter();
    if (uniform() < 0.4) {
        f.category = random_bits();
        f.mask = random_bits();
    }
    return f;
}

/* The object's mesh as the test places it (for the narrowphase brute
 * force): its own mesh, or the test's mesh of its box primitive. */
const noctMesh *mesh_of(const scene *s, int i, const noctMesh *ell)
{
    return s->kind[i] == 2 ? ell : s->mesh[i];
}


/* ---- distances ----------------------------------------------------------------------- */

/* The distance from p to the solid box b. */
static long double point_box(const obb *b, const long double p[3])
{
    long double s = 0;
    for (int i = 0; i < 3; ++i) {
        long double x = 0;
        for (int k = 0; k < 3; ++k)
            x += (p[k] - b->c[k]) * b->u[i][k];
        const long double out = fabsl(x) - b->h[i];
        if (out > 0)
            s += out * out;
    }
    return sqrtl(s);
}

static void corner(const obb *b, int i, long double out[3])
{
    for (int k = 0; k < 3; ++k) {
        out[k] = b->c[k];
        for (int j = 0; j < 3; ++j)
            out[k] += ((i >> j) & 1 ? 1 : -1) * b->h[j] * b->u[j][k];
    }
}

/* The least distance from a's edges to the solid b. */
static long double edges_to(const obb *a, const obb *b)
{
    long double best = 1e300L;
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 3; ++j) {
            if ((i >> j) & 1)
                continue;
            long double p[3], q[3];
            corner(a, i, p);
            corner(a, i | 1 << j, q);
            long double lo = 0, hi = 1;
            for (int it = 0; it < 64; ++it) { /* (2/3)^64 < 1e-11 */
                const long double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
                long double x1[3], x2[3];
                for (int k = 0; k < 3; ++k) {
                    x1[k] = p[k] + m1 * (q[k] - p[k]);
                    x2[k] = p[k] + m2 * (q[k] - p[k]);
                }
                if (point_box(b, x1) <= point_box(b, x2))
                    hi = m2;
                else
                    lo = m1;
            }
            long double x[3];
            for (int k = 0; k < 3; ++k)
                x[k] = p[k] + (lo + hi) / 2 * (q[k] - p[k]);
            best = fminl(best, point_box(b, x));
        }
    return best;
}

long double ideal_distance(const ideal *a, const ideal *b)
{
    long double best = 1e300L;
    for (int i = 0; i < a->npieces; ++i)
        for (int j = 0; j < b->npieces; ++j) {
            const obb x = piece_box(a, i), y = piece_box(b, j);
            best = fminl(best, fminl(edges_to(&x, &y), edges_to(&y, &x)));
        }
    return best;
}

/* Piece j of g's axis-aligned bounding box. */
static void piece_aabb(const ideal *g, int j, long double lo[3], long double hi[3])
{
    const obb b = piece_box(g, j);
    for (int k = 0; k < 3; ++k) {
        long double e = 0;
        for (int i = 0; i < 3; ++i)
            e += fabsl(b.u[i][k]) * b.h[i];
        lo[k] = b.c[k] - e;
        hi[k] = b.c[k] + e;
    }
}

long double ideal_distance_lower(const ideal *a, const ideal *b)
{
    long double best = 1e300L;
    for (int i = 0; i < a->npieces; ++i)
        for (int j = 0; j < b->npieces; ++j) {
            long double alo[3], ahi[3], blo[3], bhi[3], s = 0;
            piece_aabb(a, i, alo, ahi);
            piece_aabb(b, j, blo, bhi);
            for (int k = 0; k < 3; ++k) {
                const long double gap = fmaxl(blo[k] - ahi[k], alo[k] - bhi[k]);
                if (gap > 0)
                    s += gap * gap;
            }
            best = fminl(best, sqrtl(s));
        }
    return best;
}

/* ---- what overlap queries found ---------------------------------------------------- */

bool collect(void *context, noctObjectId id, void *user)
{
    found *f = context;
    ck_assert(user != NULL && ((noctObjectId *)user)->index == id.index);
    ck_assert_int_lt(f->n, MAXO);
    f->id[f->n++] = id;
    return true;
}

bool in_found(const found *f, const scene *s, int i)
{
    for (int k = 0; k < f->n; ++k)
        if (f->id[k].index == s->id[i].index) {
            ck_assert_uint_eq(f->id[k].generation, s->id[i].generation);
            return true;
        }
    return false;
}

void expect_index_order(const found *f)
{
    for (int k = 1; k < f->n; ++k)
        ck_assert_uint_lt(f->id[k - 1].index, f->id[k].index);
}

ideal ideal_shape(const noctTransform *x, bool ell, const double h[3])
{
    ideal sh = {0};
    quat_matrix(&x->q, sh.R);
    for (int k = 0; k < 3; ++k)
        sh.t[k] = x->p[k];
    if (ell) {
        sh.npieces = 2;
        sh.pc[0] = (piece){{0, -0.5L, 0}, {1, 0.5L, 0.5L}};
        sh.pc[1] = (piece){{-0.5L, 0, 0}, {0.5L, 1, 0.5L}};
    } else {
        sh.npieces = 1;
        sh.pc[0] = (piece){{0, 0, 0}, {h[0], h[1], h[2]}};
    }
    return sh;
}

/* ---- exact-enough distances between triangles, in long double ---------------- */

typedef long double ld;

static ld ld_dot(const ld a[3], const ld b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Squared distance from p to segment ab, in long double. */
long double test_point_seg2(const ld p[3], const ld a[3], const ld b[3])
{
    ld d[3], w[3];
    for (int k = 0; k < 3; ++k) {
        d[k] = b[k] - a[k];
        w[k] = p[k] - a[k];
    }
    const ld dd = ld_dot(d, d);
    ld t = dd > 0 ? ld_dot(w, d) / dd : 0;
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    ld g[3];
    for (int k = 0; k < 3; ++k)
        g[k] = w[k] - t * d[k];
    return ld_dot(g, g);
}

/* Squared distance between segments, by minimising over a fine
 * parametrisation's closed form: the unconstrained optimum if interior,
 * else the four endpoint-to-segment distances. */
static ld seg_seg2(const ld p[3], const ld q[3], const ld a[3], const ld b[3])
{
    ld best = test_point_seg2(p, a, b);
    ld x = test_point_seg2(q, a, b);
    best = x < best ? x : best;
    x = test_point_seg2(a, p, q);
    best = x < best ? x : best;
    x = test_point_seg2(b, p, q);
    best = x < best ? x : best;
    ld d1[3], d2[3], r[3];
    for (int k = 0; k < 3; ++k) {
        d1[k] = q[k] - p[k];
        d2[k] = b[k] - a[k];
        r[k] = p[k] - a[k];
    }
    const ld A = ld_dot(d1, d1), B = ld_dot(d1, d2), C = ld_dot(d2, d2), D = ld_dot(d1, r),
             E = ld_dot(d2, r);
    const ld den = A * C - B * B;
    if (den > 1e-30L * A * C) {
        const ld s = (B * E - C * D) / den, t = (A * E - B * D) / den;
        if (s > 0 && s < 1 && t > 0 && t < 1) {
            ld g[3];
            for (int k = 0; k < 3; ++k)
                g[k] = r[k] + s * d1[k] - t * d2[k];
            x = ld_dot(g, g);
            best = x < best ? x : best;
        }
    }
    return best;
}

/* Squared distance from p to the plane of abc if its projection falls
 * inside the triangle, else infinity (the edges then decide). */
long double test_point_face2(const ld p[3], const ld a[3], const ld b[3], const ld c[3])
{
    ld e1[3], e2[3], n[3], w[3];
    for (int k = 0; k < 3; ++k) {
        e1[k] = b[k] - a[k];
        e2[k] = c[k] - a[k];
        w[k] = p[k] - a[k];
    }
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    const ld nn = ld_dot(n, n);
    if (!(nn > 0))
        return INFINITY;
    const ld h = ld_dot(w, n) / nn;
    ld x[3];
    for (int k = 0; k < 3; ++k)
        x[k] = p[k] - h * n[k];
    const ld *v[3] = {a, b, c};
    for (int i = 0; i < 3; ++i) {
        ld f[3], g[3], cr[3];
        for (int k = 0; k < 3; ++k) {
            f[k] = v[(i + 1) % 3][k] - v[i][k];
            g[k] = x[k] - v[i][k];
        }
        cr[0] = f[1] * g[2] - f[2] * g[1];
        cr[1] = f[2] * g[0] - f[0] * g[2];
        cr[2] = f[0] * g[1] - f[1] * g[0];
        if (ld_dot(cr, n) < 0)
            return INFINITY;
    }
    return h * h * nn;
}

/* Squared distance between two disjoint triangles. */
long double test_tri_tri2(ld x[3][3], ld y[3][3])
{
    ld best = INFINITY;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const ld d = seg_seg2(x[i], x[(i + 1) % 3], y[j], y[(j + 1) % 3]);
            best = d < best ? d : best;
        }
    for (int i = 0; i < 3; ++i) {
        ld d = test_point_face2(x[i], y[0], y[1], y[2]);
        best = d < best ? d : best;
        d = test_point_face2(y[i], x[0], x[1], x[2]);
        best = d < best ? d : best;
    }
    return best;
}
