/* SPDX-License-Identifier: MIT */
/*
 * The broadphase on its own (broadphase.h), against brute force: random
 * boxes of every size, moved, grown, added and removed, with filters; after
 * every batch of moves the pairs must be exactly those of an all-pairs test
 * of the closed boxes, sorted, and the validation walk must hold; queries
 * against a scan of every box; leaves against the boxes that overlap them;
 * bad input reported by status with nothing changed.
 */
#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 33))
#  include <malloc.h> /* mallinfo2 */
#endif

#include <noctree/broadphase.h>
#include <noctree/mesh.h>
#include <noctree/octree.h>
#include <noctree/world.h>

#include "testutil.h"

static uint64_t rng;
static double uniform(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (double)(rng >> 11) * 0x1p-53;
}

#define MAXP 600

/* The test's own record of every proxy. */
typedef struct model {
    int n;
    bool alive[MAXP];
    noctProxyId id[MAXP];
    double lo[MAXP][3], hi[MAXP][3];
    uint64_t cat[MAXP], mask[MAXP];
} model;

static bool boxes_meet(const double alo[3], const double ahi[3], const double blo[3],
                       const double bhi[3])
{
    for (int k = 0; k < 3; ++k)
        if (ahi[k] < blo[k] || bhi[k] < alo[k])
            return false;
    return true;
}

/* The broadphase's pairs are exactly the brute force's, in order. */
static void check_pairs(noctBroadphase *bp, const model *m)
{
    noctError err;
    ck_assert_int_eq(noctBroadphaseUpdatePairs(bp, &err), NOCT_OK);
    ck_assert_msg(noctBroadphaseValidate(bp, &err) == NOCT_OK, "invalid: %s", err.message);
    const noctProxyPair *p;
    const size_t n = noctBroadphasePairs(bp, &p);
    /* model slots in proxy index order */
    static int by_index[MAXP];
    int live = 0;
    for (int i = 0; i < m->n; ++i)
        if (m->alive[i])
            by_index[live++] = i;
    for (int i = 1; i < live; ++i) /* insertion sort by proxy index */
        for (int j = i; j > 0 && m->id[by_index[j - 1]].index > m->id[by_index[j]].index; --j) {
            const int t = by_index[j];
            by_index[j] = by_index[j - 1];
            by_index[j - 1] = t;
        }
    size_t k = 0;
    for (int x = 0; x < live; ++x)
        for (int y = x + 1; y < live; ++y) {
            const int a = by_index[x], b = by_index[y];
            if (!boxes_meet(m->lo[a], m->hi[a], m->lo[b], m->hi[b]) ||
                !(m->cat[a] & m->mask[b]) || !(m->cat[b] & m->mask[a]))
                continue;
            ck_assert_msg(k < n, "pair (%u, %u) missing: only %zu pairs", m->id[a].index,
                          m->id[b].index, n);
            ck_assert_msg(p[k].a.index == m->id[a].index && p[k].b.index == m->id[b].index,
                          "pair %zu is (%u, %u), expected (%u, %u)", k, p[k].a.index,
                          p[k].b.index, m->id[a].index, m->id[b].index);
            ck_assert_uint_eq(p[k].a.generation, m->id[a].generation);
            ck_assert_uint_eq(p[k].b.generation, m->id[b].generation);
            ++k;
        }
    ck_assert_msg(k == n, "%zu pairs found, %zu expected", n, k);
}

/* A random box: tiny to larger than the scene, some flat or points. */
static void random_box(double lo[3], double hi[3], double scene)
{
    const double u = uniform();
    const double size = u < 0.1 ? 1e-6 : u < 0.8 ? 0.5 * uniform() : u < 0.95 ? 5 * uniform()
                                                                      : 2 * scene * uniform();
    const bool cluster = uniform() < 0.2;
    for (int k = 0; k < 3; ++k) {
        lo[k] = cluster ? 1 + 0.5 * uniform() : scene * uniform();
        hi[k] = lo[k] + (uniform() < 0.05 ? 0 : size * (0.3 + uniform()));
    }
}

static uint64_t random_bits(void)
{
    const double u = uniform();
    return u < 0.7 ? NOCT_FILTER_ALL : (uint64_t)1 << (int)(4 * uniform());
}

static void add_one(noctBroadphase *bp, model *m, int i, double scene)
{
    noctError err;
    random_box(m->lo[i], m->hi[i], scene);
    m->cat[i] = random_bits();
    m->mask[i] = random_bits();
    ck_assert_int_eq(noctBroadphaseAdd(bp, m->lo[i], m->hi[i], &m->alive[i], m->cat[i],
                                       m->mask[i], &m->id[i], &err),
                     NOCT_OK);
    m->alive[i] = true;
}

/* A broadphase at N (the default depth) with n random proxies in a
 * scene of this size, recorded in *m. */
static noctBroadphase *filled(int N, int n, double scene, model *m)
{
    noctBroadphaseDef def = noctDefaultBroadphaseDef();
    def.N = N;
    noctBroadphase *bp;
    ck_assert_int_eq(noctBroadphaseCreate(&def, &bp, NULL), NOCT_OK);
    memset(m, 0, sizeof *m);
    m->n = n;
    for (int i = 0; i < n; ++i)
        add_one(bp, m, i, scene);
    return bp;
}

/* Move proxy i: a little, far, out of the scene, or to a new size. */
static void move_one(noctBroadphase *bp, model *m, int i, double scene)
{
    noctError err;
    const double u = uniform();
    if (u < 0.05) {
        random_box(m->lo[i], m->hi[i], scene);
    } else if (u < 0.08) {
        for (int k = 0; k < 3; ++k) { /* far away, out of the root */
            const double d = scene * (4 + 8 * uniform()) * (uniform() < 0.5 ? -1 : 1);
            m->lo[i][k] += d;
            m->hi[i][k] += d;
        }
    } else if (u < 0.15) {
        for (int k = 0; k < 3; ++k) /* a new size */
            m->hi[i][k] = m->lo[i][k] + (m->hi[i][k] - m->lo[i][k]) * (0.25 + 2 * uniform());
    } else {
        for (int k = 0; k < 3; ++k) {
            const double d = 0.2 * (uniform() - 0.5);
            m->lo[i][k] += d;
            m->hi[i][k] += d;
        }
    }
    ck_assert_int_eq(noctBroadphaseMove(bp, m->id[i], m->lo[i], m->hi[i], &err), NOCT_OK);
}

static const int CONFIG_N[] = {1, 2, 10, NOCT_N_EXHAUSTIVE, NOCT_AUTO};
static const int CONFIG_DEPTH[] = {3, 10, 40, NOCT_AUTO};

/* Random scenes in every configuration, checked after every batch. */
START_TEST(pairs_against_brute_force)
{
    const int N = CONFIG_N[_i % 5], depth = CONFIG_DEPTH[_i / 5];
    rng = 0x1234567u + (uint64_t)_i;
    noctBroadphaseDef def = noctDefaultBroadphaseDef();
    def.N = N;
    def.max_depth = depth;
    noctBroadphase *bp;
    noctError err;
    ck_assert_int_eq(noctBroadphaseCreate(&def, &bp, &err), NOCT_OK);
    static model m;
    memset(&m, 0, sizeof m);
    const double scene = 20;
    m.n = 250;
    for (int i = 0; i < m.n; ++i)
        add_one(bp, &m, i, scene);
    check_pairs(bp, &m);
    for (int batch = 0; batch < 30; ++batch) {
        for (int i = 0; i < m.n; ++i) {
            if (!m.alive[i] || i % 5 == 0) /* a fifth never move */
                continue;
            if (uniform() < 0.5)
                move_one(bp, &m, i, scene);
        }
        /* removals and additions, slots reused */
        for (int r = 0; r < 5; ++r) {
            const int i = 1 + (int)(uniform() * (m.n - 1));
            if (m.alive[i]) {
                const noctProxyId old = m.id[i];
                ck_assert_int_eq(noctBroadphaseRemove(bp, old), NOCT_OK);
                m.alive[i] = false;
                ck_assert_int_eq(noctBroadphaseRemove(bp, old), NOCT_ERR_INVALID);
                ck_assert_int_eq(noctBroadphaseMove(bp, old, m.lo[i], m.hi[i], NULL),
                                 NOCT_ERR_INVALID);
                ck_assert_int_eq(noctBroadphaseSetFilter(bp, old, 1, 1), NOCT_ERR_INVALID);
                ck_assert_int_eq(noctBroadphaseProxy(bp, old, NULL, NULL, NULL, NULL, NULL),
                                 NOCT_ERR_INVALID);
            } else {
                add_one(bp, &m, i, scene);
            }
        }
        if (batch % 3 == 0) { /* filters change */
            const int i = (int)(uniform() * m.n);
            if (m.alive[i]) {
                m.cat[i] = random_bits();
                m.mask[i] = random_bits();
                ck_assert_int_eq(noctBroadphaseSetFilter(bp, m.id[i], m.cat[i], m.mask[i]),
                                 NOCT_OK);
            }
        }
        check_pairs(bp, &m);
        size_t live = 0;
        for (int i = 0; i < m.n; ++i)
            live += m.alive[i];
        ck_assert_uint_eq(noctBroadphaseProxyCount(bp), live);
    }
    /* single moves, each checked */
    for (int t = 0; t < 40; ++t) {
        const int i = (int)(uniform() * m.n);
        if (m.alive[i]) {
            move_one(bp, &m, i, scene);
            check_pairs(bp, &m);
        }
    }
    /* what a proxy holds */
    for (int i = 0; i < m.n; ++i)
        if (m.alive[i]) {
            double lo[3], hi[3];
            void *user;
            uint64_t cat, mask;
            ck_assert_int_eq(noctBroadphaseProxy(bp, m.id[i], lo, hi, &user, &cat, &mask),
                             NOCT_OK);
            ck_assert(memcmp(lo, m.lo[i], sizeof lo) == 0 && memcmp(hi, m.hi[i], sizeof hi) == 0);
            ck_assert_ptr_eq(user, &m.alive[i]);
            ck_assert(cat == m.cat[i] && mask == m.mask[i]);
        }
    noctBroadphaseDestroy(bp);
}
END_TEST

/* ---- queries ---------------------------------------------------------------- */

typedef struct seen {
    int calls;
    int stop_after;
    uint32_t idx[MAXP];
    double t[MAXP];
    double clip; /* ray: the fraction to return */
} seen;

/* A point query looking for one proxy. */
typedef struct point_hit {
    int calls;
    noctProxyId want;
    bool seen;
} point_hit;

static bool on_found(void *ctx, noctProxyId id, void *user)
{
    (void)user;
    point_hit *f = ctx;
    ++f->calls;
    f->seen |= id.index == f->want.index && id.generation == f->want.generation;
    return true;
}

static bool on_proxy(void *ctx, noctProxyId id, void *user)
{
    (void)user;
    seen *s = ctx;
    s->idx[s->calls++] = id.index;
    return s->calls != s->stop_after;
}

static double on_ray(void *ctx, noctProxyId id, void *user, double t)
{
    (void)user;
    seen *s = ctx;
    s->idx[s->calls] = id.index;
    s->t[s->calls++] = t;
    return s->calls == s->stop_after ? s->clip : 1;
}

/* The fraction at which the segment o + t d, t in [0, 1], enters the
 * closed box, or -1: a slab test, written here apart from the library. */
static double slab_enter(const double o[3], const double d[3], const double lo[3],
                         const double hi[3])
{
    double t0 = 0, t1 = 1;
    for (int k = 0; k < 3; ++k) {
        /* The near face first: division by d > 0 keeps the order of
         * the faces' differences, by d < 0 reverses it. */
        const double near = d[k] > 0 ? lo[k] : hi[k], far = d[k] > 0 ? hi[k] : lo[k];
        if (d[k] == 0 && (o[k] < lo[k] || o[k] > hi[k]))
            return -1;
        if (d[k] == 0)
            continue;
        const double a = (near - o[k]) / d[k], b = (far - o[k]) / d[k];
        t0 = a > t0 ? a : t0;
        t1 = b < t1 ? b : t1;
        if (t0 > t1)
            return -1;
    }
    return t0;
}

static int cmp_u32(const void *x, const void *y)
{
    const uint32_t a = *(const uint32_t *)x, b = *(const uint32_t *)y;
    return (a > b) - (a < b);
}

START_TEST(queries_against_brute_force)
{
    rng = 0xfeedu + (uint64_t)_i;
    static model m;
    noctBroadphase *bp = filled(_i == 0 ? 2 : 10, 300, 20, &m);
    for (int i = 0; i < m.n; ++i)
        if (i % 3 == 0)
            move_one(bp, &m, i, 20);
    static seen s;
    for (int q = 0; q < 60; ++q) {
        double lo[3], hi[3];
        random_box(lo, hi, 20);
        const noctQueryFilter f = {random_bits(), random_bits()};
        memset(&s, 0, sizeof s);
        s.stop_after = -1;
        ck_assert_int_eq(noctBroadphaseQueryBox(bp, lo, hi, f, on_proxy, &s), NOCT_OK);
        static uint32_t want[MAXP];
        int nw = 0;
        for (int i = 0; i < m.n; ++i)
            if (m.alive[i] && boxes_meet(lo, hi, m.lo[i], m.hi[i]) && (m.cat[i] & f.mask) &&
                (f.category & m.mask[i]))
                want[nw++] = m.id[i].index;
        qsort(want, (size_t)nw, sizeof *want, cmp_u32);
        qsort(s.idx, (size_t)s.calls, sizeof *s.idx, cmp_u32);
        ck_assert_int_eq(s.calls, nw); /* each once */
        ck_assert(memcmp(want, s.idx, (size_t)nw * sizeof *want) == 0);
        /* the same as a point query at a corner of a box */
        const double *pt = m.lo[q % m.n];
        memset(&s, 0, sizeof s);
        s.stop_after = -1;
        ck_assert_int_eq(noctBroadphaseQueryPoint(bp, pt, noctDefaultQueryFilter(), on_proxy, &s),
                         NOCT_OK);
        nw = 0;
        for (int i = 0; i < m.n; ++i)
            if (m.alive[i] && boxes_meet(pt, pt, m.lo[i], m.hi[i]))
                ++nw;
        ck_assert_int_eq(s.calls, nw);
        ck_assert_int_ge(nw, 1); /* its own box */
        /* early stop */
        memset(&s, 0, sizeof s);
        s.stop_after = 1;
        ck_assert_int_eq(noctBroadphaseQueryPoint(bp, pt, noctDefaultQueryFilter(), on_proxy, &s),
                         NOCT_OK);
        ck_assert_int_eq(s.calls, 1);
    }
    /* an infinite box reports every proxy */
    const double inf[3] = {INFINITY, INFINITY, INFINITY}, ninf[3] = {-INFINITY, -INFINITY,
                                                                     -INFINITY};
    memset(&s, 0, sizeof s);
    s.stop_after = -1;
    ck_assert_int_eq(noctBroadphaseQueryBox(bp, ninf, inf, noctDefaultQueryFilter(), on_proxy, &s),
                     NOCT_OK);
    ck_assert_int_eq(s.calls, (int)noctBroadphaseProxyCount(bp));
    /* rays: the set, the order, clipping */
    for (int q = 0; q < 60; ++q) {
        double o[3], d[3];
        for (int k = 0; k < 3; ++k) {
            o[k] = 20 * uniform();
            d[k] = q % 7 == 0 && k == 1 ? 0 : 30 * (uniform() - 0.5);
        }
        memset(&s, 0, sizeof s);
        s.stop_after = -1;
        ck_assert_int_eq(noctBroadphaseRayCast(bp, o, d, noctDefaultQueryFilter(), on_ray, &s),
                         NOCT_OK);
        int nw = 0;
        for (int i = 0; i < m.n; ++i)
            if (m.alive[i] && slab_enter(o, d, m.lo[i], m.hi[i]) >= 0)
                ++nw;
        ck_assert_int_eq(s.calls, nw);
        for (int c = 0; c < s.calls; ++c) {
            int i = 0;
            while (!(m.alive[i] && m.id[i].index == s.idx[c]))
                ++i;
            ck_assert(s.t[c] == slab_enter(o, d, m.lo[i], m.hi[i]));
            if (c > 0)
                ck_assert(s.t[c - 1] < s.t[c] ||
                          (s.t[c - 1] == s.t[c] && s.idx[c - 1] < s.idx[c]));
        }
        if (s.calls >= 3) {
            /* clip at the second hit's t: the third and later are reported
             * only if they enter at that t too */
            const double clip = s.t[1];
            int expect = 0;
            for (int c = 0; c < s.calls; ++c)
                expect += c < 2 || s.t[c] <= clip;
            memset(&s, 0, sizeof s);
            s.stop_after = 2;
            s.clip = clip;
            if (clip > 0) {
                ck_assert_int_eq(
                    noctBroadphaseRayCast(bp, o, d, noctDefaultQueryFilter(), on_ray, &s),
                    NOCT_OK);
                ck_assert_int_eq(s.calls, expect);
            }
            /* 0 stops */
            memset(&s, 0, sizeof s);
            s.stop_after = 1;
            s.clip = 0;
            ck_assert_int_eq(noctBroadphaseRayCast(bp, o, d, noctDefaultQueryFilter(), on_ray, &s),
                             NOCT_OK);
            ck_assert_int_eq(s.calls, 1);
        }
    }
    noctBroadphaseDestroy(bp);
}
END_TEST

/* ---- segments: the ordered walk against a sorted scan ------------------------------ */

/*
 * What a ray callback returns, so that the test can replay it: every hit
 * (1); the closest (t, clipping there, plus a slack); stop at the k-th
 * call (0, or NaN); clip at the k-th call's t, then return 7 (more than
 * the segment: no change).
 */
enum { RAY_ALL, RAY_CLOSEST, RAY_STOP, RAY_NAN, RAY_CLIP_ONCE, RAY_POLICIES };

typedef struct ray_log {
    int policy, k;
    double slack;
    int calls;
    uint32_t idx[MAXP], gen[MAXP];
    double t[MAXP];
} ray_log;

static double ray_answer(const ray_log *r, int call, double t)
{
    switch (r->policy) {
    case RAY_CLOSEST:
        return t + r->slack;
    case RAY_STOP:
        return call == r->k ? 0 : 1;
    case RAY_NAN:
        return call == r->k ? NAN : 1;
    case RAY_CLIP_ONCE:
        return call == r->k ? t : 7;
    default:
        return 1;
    }
}

static double on_ray_logged(void *ctx, noctProxyId id, void *user, double t)
{
    (void)user;
    ray_log *r = ctx;
    if (r->calls == MAXP)
        return 0; /* (more calls than proxies: the comparison fails) */
    r->idx[r->calls] = id.index;
    r->gen[r->calls] = id.generation;
    r->t[r->calls] = t;
    ++r->calls;
    return ray_answer(r, r->calls, t);
}

typedef struct ray_want {
    double t;
    int slot;
    uint32_t index;
} ray_want;

static int cmp_ray_want(const void *x, const void *y)
{
    const ray_want *a = x, *b = y;
    if (a->t != b->t)
        return a->t < b->t ? -1 : 1;
    return (a->index > b->index) - (a->index < b->index);
}

/* The cast against the brute force: every live proxy the filter passes,
 * entered at slab_enter's t, sorted by (t, index), replayed through the
 * policy with the clip the documentation describes. Returns the hits
 * the segment meets (before any clip). */
static int check_ray(noctBroadphase *bp, const model *m, const double o[3], const double d[3],
                     noctQueryFilter f, int policy, int k, double slack)
{
    static ray_want want[MAXP];
    int nw = 0;
    for (int i = 0; i < m->n; ++i) {
        if (!m->alive[i] || !(m->cat[i] & f.mask) || !(f.category & m->mask[i]))
            continue;
        const double t = slab_enter(o, d, m->lo[i], m->hi[i]);
        if (t >= 0)
            want[nw++] = (ray_want){t, i, m->id[i].index};
    }
    qsort(want, (size_t)nw, sizeof *want, cmp_ray_want);
    static ray_log got;
    memset(&got, 0, sizeof got);
    got.policy = policy;
    got.k = k;
    got.slack = slack;
    ck_assert_int_eq(noctBroadphaseRayCast(bp, o, d, f, on_ray_logged, &got), NOCT_OK);
    /* the replay */
    ray_log replay = {.policy = policy, .k = k, .slack = slack};
    double max = 1;
    int n = 0;
    while (n < nw && want[n].t <= max) {
        ++n;
        const double r = ray_answer(&replay, n, want[n - 1].t);
        if (!(r > 0))
            break;
        max = r < max ? r : max;
    }
    ck_assert_msg(got.calls == n,
                  "segment (%a %a %a) + (%a %a %a), policy %d: %d calls, expected %d of %d",
                  o[0], o[1], o[2], d[0], d[1], d[2], policy, got.calls, n, nw);
    for (int c = 0; c < n; ++c) {
        const int i = want[c].slot;
        ck_assert_msg(got.idx[c] == m->id[i].index && got.gen[c] == m->id[i].generation &&
                          got.t[c] == want[c].t,
                      "call %d: proxy %u at %a, expected %u at %a (policy %d)", c, got.idx[c],
                      got.t[c], m->id[i].index, want[c].t, policy);
    }
    return nw;
}

/* Up to MAX_LEAVES leaf cubes of the tree, sampled. */
#define MAX_LEAVES 256
typedef struct leaf_set {
    int n, seen;
    double lo[MAX_LEAVES][3], size[MAX_LEAVES];
} leaf_set;

static void gather_leaves(const noctBroadphase *bp, const octNode *n, leaf_set *s)
{
    if (octIsSplit(n)) {
        for (int i = 0; i < 8; ++i)
            gather_leaves(bp, octChild(n, (octDirection)(OCT_LDB + i)), s);
        return;
    }
    int at = s->n < MAX_LEAVES ? s->n++ : (int)((s->seen + 1) * uniform());
    ++s->seen;
    if (at < MAX_LEAVES)
        noctBroadphaseCell(bp, n, s->lo[at], &s->size[at], NULL, 0);
}

/* The configurations of rays_against_brute_force: N, depth, and where
 * the scene lies (offset) and how large its unit is. Unit 0: 2^-24 of
 * the offset (a scene that still splits), -1: 256 ulps of it (a leaf or
 * two, every t rounded). */
static const struct {
    int N, depth;
    double offset, unit;
} RAY_CONFIG[] = {
    {1, 40, 0, 1},          {2, 10, 0, 1},           {10, NOCT_AUTO, 0, 1},
    {NOCT_AUTO, NOCT_AUTO, 0, 1}, {2, 40, 0, 1e-300},  {2, 40, 0, 1e97},
    {2, 40, 3e12, 0},       {1, 40, -7.25e15, 0},    {2, 40, 1e90, 0},
    {2, 40, -1048576.1, -1}, {10, 40, 9e99, -1},
};

/* A point of the scene: offset + unit x, x in [0, 20). */
#define RAY_SCENE 20

START_TEST(rays_against_brute_force)
{
    const double offset = RAY_CONFIG[_i].offset;
    double unit = RAY_CONFIG[_i].unit;
    const double ulp = nextafter(fabs(offset), INFINITY) - fabs(offset);
    if (unit == 0)
        unit = fabs(offset) * 0x1p-24;
    else if (unit < 0)
        unit = 256 * ulp / RAY_SCENE;
    rng = 0x5a9e + (uint64_t)_i;
    noctBroadphaseDef def = noctDefaultBroadphaseDef();
    def.N = RAY_CONFIG[_i].N;
    def.max_depth = RAY_CONFIG[_i].depth;
    noctBroadphase *bp;
    noctError err;
    ck_assert_int_eq(noctBroadphaseCreate(&def, &bp, &err), NOCT_OK);
    static model m;
    memset(&m, 0, sizeof m);
    m.n = 400;
    for (int i = 0; i < m.n; ++i) {
        double lo[3], hi[3];
        random_box(lo, hi, RAY_SCENE);
        for (int k = 0; k < 3; ++k) {
            m.lo[i][k] = offset + unit * lo[k];
            m.hi[i][k] = offset + unit * hi[k];
        }
        m.cat[i] = random_bits();
        m.mask[i] = random_bits();
        ck_assert_int_eq(noctBroadphaseAdd(bp, m.lo[i], m.hi[i], NULL, m.cat[i], m.mask[i],
                                           &m.id[i], &err),
                         NOCT_OK);
        m.alive[i] = true;
    }
    int met = 0, clipped = 0, through_corners = 0;
    for (int round = 0; round < 4; ++round) {
        /* some proxies move, some go and come back (new generations) */
        for (int i = 0; i < m.n; ++i) {
            const double u = uniform();
            if (u < 0.1 && m.alive[i]) {
                ck_assert_int_eq(noctBroadphaseRemove(bp, m.id[i]), NOCT_OK);
                m.alive[i] = false;
            } else if (u < 0.2 && !m.alive[i]) {
                ck_assert_int_eq(noctBroadphaseAdd(bp, m.lo[i], m.hi[i], NULL, m.cat[i],
                                                   m.mask[i], &m.id[i], &err),
                                 NOCT_OK);
                m.alive[i] = true;
            } else if (u < 0.4 && m.alive[i]) {
                const double step = unit * floor(16 * (uniform() - 0.5)) / 8;
                for (int k = 0; k < 3; ++k) {
                    m.lo[i][k] += step;
                    m.hi[i][k] += step;
                }
                ck_assert_int_eq(noctBroadphaseMove(bp, m.id[i], m.lo[i], m.hi[i], &err),
                                 NOCT_OK);
            }
        }
        ck_assert_msg(noctBroadphaseValidate(bp, &err) == NOCT_OK, "invalid: %s", err.message);
        static leaf_set leaves;
        leaves.n = leaves.seen = 0;
        gather_leaves(bp, noctBroadphaseRoot(bp), &leaves);
        for (int q = 0; q < 150; ++q) {
            double o[3], d[3];
            const int kind = q % 9, a = (int)(3 * uniform());
            const int leaf = (int)(leaves.n * uniform());
            const double *cl = leaves.lo[leaf], cs = leaves.size[leaf];
            const int slot = (int)(m.n * uniform());
            for (int k = 0; k < 3; ++k) {
                o[k] = offset + unit * RAY_SCENE * uniform();
                d[k] = unit * RAY_SCENE * (uniform() - 0.5);
            }
            switch (kind) {
            case 1: /* along an edge of a leaf, past its corners */
                for (int k = 0; k < 3; ++k) {
                    o[k] = cl[k] + (uniform() < 0.5 ? 0 : cs);
                    d[k] = 0;
                }
                o[a] = cl[a] - cs;
                d[a] = 3 * cs;
                break;
            case 2: /* in the plane of a leaf's face */
                o[a] = cl[a] + (uniform() < 0.5 ? 0 : cs);
                d[a] = 0;
                break;
            case 3: /* through a leaf's corner, with dyadic steps: exactly */
                for (int k = 0; k < 3; ++k) {
                    const double v = cs * floor(8 * uniform() - 4) / 4;
                    o[k] = cl[k] + (k == a ? cs : 0) - v;
                    d[k] = 2 * v;
                }
                ++through_corners;
                break;
            case 4: /* zero length, at a box's corner, a leaf's corner or anywhere */
                for (int k = 0; k < 3; ++k) {
                    if (q % 3 == 0)
                        o[k] = m.lo[slot][k];
                    else if (q % 3 == 1)
                        o[k] = cl[k];
                    d[k] = 0;
                }
                break;
            case 5: /* parallel to an axis */
                for (int k = 0; k < 3; ++k)
                    d[k] = k == a ? d[k] : 0;
                break;
            case 6: /* in the plane of a box's face */
                o[a] = m.hi[slot][a];
                d[a] = 0;
                break;
            case 7: /* across the whole scene, corner to corner */
                for (int k = 0; k < 3; ++k) {
                    o[k] = offset + unit * (k == a ? RAY_SCENE : -1);
                    d[k] = unit * (RAY_SCENE + 1) * (k == a ? -1 : 1);
                }
                break;
            case 8: /* from inside a box */
                for (int k = 0; k < 3; ++k)
                    o[k] = m.lo[slot][k] + (m.hi[slot][k] - m.lo[slot][k]) * uniform();
                break;
            default:
                break;
            }
            const noctQueryFilter f =
                q % 4 == 0 ? (noctQueryFilter){random_bits(), random_bits()}
                           : noctDefaultQueryFilter();
            const int policy = q % RAY_POLICIES;
            const int k = 1 + (int)(4 * uniform());
            const double slack = uniform() < 0.5 ? 0 : 0x1p-10 * uniform();
            const int n = check_ray(bp, &m, o, d, f, policy, k, slack);
            met += n;
            clipped += n > 1 && policy != RAY_ALL;
            /* and every hit, whatever the policy drew */
            if (policy != RAY_ALL)
                check_ray(bp, &m, o, d, f, RAY_ALL, 0, 0);
        }
    }
    /* the rays met boxes, many of them, and the clips cut lists short */
    ck_assert_int_gt(met, 500);
    ck_assert_int_gt(clipped, 50);
    ck_assert_int_gt(through_corners, 40);
    noctBroadphaseDestroy(bp);
}
END_TEST

/* The heap in use (glibc's mallinfo2, 2.33 on; valgrind's malloc reports
 * 0 there, and then the test cannot look). */
static size_t heap_in_use(void)
{
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 33))
    const struct mallinfo2 mi = mallinfo2();
    return mi.uordblks + mi.hblkhd;
#else
    return 0;
#endif
}

typedef struct first_call {
    int calls;
    double t;
    size_t heap; /* in use at the first call */
} first_call;

static double on_ray_closest(void *ctx, noctProxyId id, void *user, double t)
{
    (void)id;
    (void)user;
    first_call *f = ctx;
    if (f->calls++ == 0) {
        f->heap = heap_in_use();
        f->t = t;
    }
    return t;
}

/*
 * The walk hands out a hit as soon as no leaf still to come can hold one
 * before it, and a closest cast ends there: a segment along a row of
 * five hundred boxes gets its one call before the query has gathered more
 * than a few leaves (it holds no heap memory then, where gathering every
 * box first takes 16 bytes for each).
 */
START_TEST(rays_stop_early)
{
    noctBroadphaseDef def = noctDefaultBroadphaseDef();
    def.N = 2;
    noctBroadphase *bp;
    noctError err;
    ck_assert_int_eq(noctBroadphaseCreate(&def, &bp, &err), NOCT_OK);
    enum { ROW = 500 };
    for (int i = 0; i < ROW; ++i) {
        const double lo[3] = {i, 0, 0}, hi[3] = {i + 0.5, 0.5, 0.5};
        noctProxyId id;
        ck_assert_int_eq(noctBroadphaseAdd(bp, lo, hi, NULL, NOCT_FILTER_ALL, NOCT_FILTER_ALL,
                                           &id, &err),
                         NOCT_OK);
        ck_assert_uint_eq(id.index, (uint32_t)i);
    }
    ck_assert_int_eq(noctBroadphaseUpdatePairs(bp, &err), NOCT_OK);
    const double o[3] = {-1, 0.25, 0.25}, d[3] = {ROW + 2, 0, 0};
    /* every hit, in order */
    static ray_log all;
    memset(&all, 0, sizeof all);
    all.policy = RAY_ALL;
    ck_assert_int_eq(noctBroadphaseRayCast(bp, o, d, noctDefaultQueryFilter(), on_ray_logged,
                                           &all),
                     NOCT_OK);
    ck_assert_int_eq(all.calls, ROW);
    for (int c = 0; c < ROW; ++c)
        ck_assert(all.idx[c] == (uint32_t)c && all.t[c] == (c + 1.0) / (ROW + 2));
    /* the closest: one call, the first box */
    first_call f = {0, 0, 0};
    const size_t before = heap_in_use();
    ck_assert_int_eq(noctBroadphaseRayCast(bp, o, d, noctDefaultQueryFilter(), on_ray_closest,
                                           &f),
                     NOCT_OK);
    ck_assert_int_eq(f.calls, 1);
    ck_assert(f.t == 1.0 / (ROW + 2));
    if (before > 0) /* (not under valgrind) */
        ck_assert_msg(f.heap == before, "%zu bytes of heap in use at the first call",
                      f.heap - before);
    noctBroadphaseDestroy(bp);
}
END_TEST

static bool on_pair(void *ctx, noctProxyId a, void *ua, noctProxyId b, void *ub)
{
    (void)ua;
    (void)ub;
    seen *s = ctx;
    ck_assert_uint_lt(a.index, b.index);
    s->idx[s->calls++] = a.index;
    return s->calls != s->stop_after;
}

/* ---- leaves, counters, the fast path ----------------------------------------------- */

typedef struct walk {
    const noctBroadphase *bp;
    const model *m;
    uint64_t nodes, leaves;
} walk;

static void walk_tree(walk *w, octNode *n)
{
    ++w->nodes;
    if (octIsSplit(n)) {
        ck_assert_uint_eq(noctBroadphaseCell(w->bp, n, NULL, NULL, NULL, 0), 0);
        for (int i = 0; i < 8; ++i)
            walk_tree(w, octChild(n, (octDirection)(OCT_LDB + i)));
        return;
    }
    ++w->leaves;
    double lo[3], size;
    static noctProxyId ids[MAXP];
    const size_t n_in = noctBroadphaseCell(w->bp, n, lo, &size, ids, MAXP);
    const double hi[3] = {lo[0] + size, lo[1] + size, lo[2] + size};
    size_t want = 0;
    for (int i = 0; i < w->m->n; ++i)
        if (w->m->alive[i] && boxes_meet(lo, hi, w->m->lo[i], w->m->hi[i])) {
            ++want;
            bool found = false;
            for (size_t j = 0; j < n_in; ++j)
                found = found || (ids[j].index == w->m->id[i].index &&
                                  ids[j].generation == w->m->id[i].generation);
            ck_assert_msg(found, "proxy %u overlaps a leaf that does not list it",
                          w->m->id[i].index);
        }
    ck_assert_uint_eq(n_in, want);
}

/* ---- the automatic settings ---------------------------------------------------- */

static int cmp_int(const void *a, const void *b)
{
    return *(const int *)a - *(const int *)b;
}

/* broadphase.h's rule for the automatic depth, from the test's own boxes:
 * D(e) = 1 + max{d : e <= root 2^-(d+1)} (40 at most) for every live box,
 * and D of the 99th percentile counted from the largest boxes; at least 1.
 * (Up to 4096 proxies, every one is in the sample.) */
static int expected_depth(const model *m, double root)
{
    static int D[MAXP];
    int n = 0;
    for (int i = 0; i < m->n; ++i) {
        if (!m->alive[i])
            continue;
        double e = 0;
        for (int k = 0; k < 3; ++k)
            e = fmax(e, m->hi[i][k] - m->lo[i][k]);
        int d = 0;
        while (d < 40 && e <= ldexp(root, -(d + 1)))
            ++d;
        D[n++] = d;
    }
    if (n == 0)
        return 1;
    qsort(D, (size_t)n, sizeof *D, cmp_int);
    const int at = D[n - n / 100 - 1];
    return at < 1 ? 1 : at;
}

static double root_size(const noctBroadphase *bp)
{
    double lo[3], size = 0;
    noctBroadphaseCell(bp, noctBroadphaseRoot(bp), lo, &size, NULL, 0);
    return size;
}

static uint64_t rebuilds_of(const noctBroadphase *bp)
{
    noctBroadphaseCounters c;
    noctBroadphaseGetCounters(bp, &c);
    return c.rebuilds;
}

/*
 * The defaults choose N and the depth at every build, from the boxes then
 * live; a population that grows or shrinks by more than a factor of 4
 * since the last choice builds again (and one that does not, does not
 * for that reason); settings given as numbers are kept whatever happens.
 * After every operation the test checks the settings in force against
 * its own reading of the rule, and the pairs against brute force.
 */
START_TEST(automatic_settings)
{
    rng = 0xa17u + (uint64_t)_i;
    noctBroadphaseDef def = noctDefaultBroadphaseDef();
    ck_assert_int_eq(def.N, NOCT_AUTO);
    ck_assert_int_eq(def.max_depth, NOCT_AUTO);
    const bool fixed = _i == 1;
    if (fixed) {
        def.N = 7;
        def.max_depth = 9;
    }
    noctBroadphase *bp;
    noctError err;
    ck_assert_int_eq(noctBroadphaseCreate(&def, &bp, &err), NOCT_OK);
    static model m;
    memset(&m, 0, sizeof m);
    size_t chosen_for = 0, live = 0;
    int want_depth = fixed ? 9 : 40;
    uint64_t rebuilds = 0, depths_seen = 0; /* bit d: depth d was chosen */
    /* After an operation: a build chose again (the test's expectation of
     * the depth follows), and none was owed and skipped. */
    #define AFTER(op_grows)                                                                \
        do {                                                                               \
            const uint64_t r = rebuilds_of(bp);                                            \
            if (!fixed && ((op_grows) ? live > 4 * chosen_for : live * 4 < chosen_for))   \
                ck_assert_msg(r > rebuilds, "%zu proxies, chosen for %zu: no new choice",  \
                              live, chosen_for);                                           \
            if (r > rebuilds && !fixed) {                                                  \
                chosen_for = live;                                                         \
                want_depth = expected_depth(&m, root_size(bp));                            \
            }                                                                              \
            rebuilds = r;                                                                  \
            int N_now, depth_now;                                                          \
            noctBroadphaseGetSettings(bp, &N_now, &depth_now);                             \
            ck_assert_int_eq(N_now, fixed ? 7 : 128);                                      \
            ck_assert_int_eq(depth_now, want_depth);                                       \
            depths_seen |= (uint64_t)1 << depth_now;                                       \
        } while (0)
    /* 150 boxes of every size, then 400 small ones that need a deeper
     * tree, then most of them removed */
    m.n = 550;
    for (int i = 0; i < m.n; ++i) {
        if (i < 150) {
            add_one(bp, &m, i, 20);
        } else {
            for (int k = 0; k < 3; ++k) {
                m.lo[i][k] = 20 * uniform();
                m.hi[i][k] = m.lo[i][k] + 1e-3;
            }
            ck_assert_int_eq(noctBroadphaseAdd(bp, m.lo[i], m.hi[i], NULL, NOCT_FILTER_ALL,
                                               NOCT_FILTER_ALL, &m.id[i], &err), NOCT_OK);
            m.cat[i] = m.mask[i] = NOCT_FILTER_ALL;
            m.alive[i] = true;
        }
        ++live;
        AFTER(true);
    }
    check_pairs(bp, &m);
    for (int i = 0; i < m.n; ++i)
        if (i % 8 != 0) {
            ck_assert_int_eq(noctBroadphaseRemove(bp, m.id[i]), NOCT_OK);
            m.alive[i] = false;
            --live;
            /* a removal owes the new choice to the next search */
            ck_assert_int_eq(noctBroadphaseUpdatePairs(bp, &err), NOCT_OK);
            AFTER(false);
        }
    check_pairs(bp, &m);
    /* the choice followed the population (a constant would pass the rest) */
    ck_assert(fixed ? depths_seen == (uint64_t)1 << 9 : (depths_seen & (depths_seen - 1)) != 0);
    #undef AFTER
    noctBroadphaseDestroy(bp);
}
END_TEST

static bool same_id(noctProxyId a, noctProxyId b)
{
    return a.index == b.index && a.generation == b.generation;
}

static bool collect_pair(void *context, noctProxyId a, void *ua, noctProxyId b, void *ub)
{
    (void)ua;
    (void)ub;
    noctProxyPair **at = context;
    *(*at)++ = (noctProxyPair){a, b};
    return true;
}

/*
 * Removals between searches: the list then holds the last search's pairs
 * but those naming a removed proxy, in order, whether it is read by
 * noctBroadphasePairs() or noctBroadphaseForEachPair(), and whatever was
 * added in the freed slots meanwhile (new generations, not in the list
 * until the next search).
 */
START_TEST(removals_drop_their_pairs)
{
    rng = 0x7e3u;
    static model m;
    noctBroadphase *bp = filled(4, 300, 8, &m);
    noctError err;
    ck_assert_int_eq(noctBroadphaseUpdatePairs(bp, &err), NOCT_OK);
    const noctProxyPair *p;
    const size_t n0 = noctBroadphasePairs(bp, &p);
    static noctProxyPair before[MAXP * MAXP / 2], got[MAXP * MAXP / 2];
    ck_assert_uint_lt(n0, sizeof before / sizeof *before);
    memcpy(before, p, n0 * sizeof *p);
    size_t nb = n0;
    for (int round = 0; round < 2; ++round) {
        for (int i = round; i < m.n; i += 3)
            if (m.alive[i]) {
                ck_assert_int_eq(noctBroadphaseRemove(bp, m.id[i]), NOCT_OK);
                m.alive[i] = false;
            }
        for (int i = m.n; i < m.n + 20; ++i) /* into freed slots */
            add_one(bp, &m, i, 8);
        m.n += 20;
        size_t want = 0;
        for (size_t k = 0; k < nb; ++k) {
            bool a_live = false, b_live = false;
            for (int i = 0; i < m.n; ++i) {
                a_live = a_live || (m.alive[i] && same_id(m.id[i], before[k].a));
                b_live = b_live || (m.alive[i] && same_id(m.id[i], before[k].b));
            }
            if (a_live && b_live)
                before[want++] = before[k];
        }
        /* the first read drops the pairs: one way, then the other */
        noctProxyPair *at = got;
        size_t calls = 0, n = 0;
        if (round == 0)
            calls = noctBroadphaseForEachPair(bp, collect_pair, &at);
        n = noctBroadphasePairs(bp, &p);
        if (round == 1)
            calls = noctBroadphaseForEachPair(bp, collect_pair, &at);
        ck_assert_uint_eq(n, want);
        ck_assert_uint_eq(calls, want);
        for (size_t k = 0; k < want; ++k) {
            ck_assert(same_id(p[k].a, before[k].a) && same_id(p[k].b, before[k].b));
            ck_assert(same_id(got[k].a, before[k].a) && same_id(got[k].b, before[k].b));
        }
        ck_assert_uint_lt(want, nb);
        nb = want;
    }
    check_pairs(bp, &m); /* and the next search has every pair again */
    noctBroadphaseDestroy(bp);
}
END_TEST

START_TEST(leaves_and_counters)
{
    rng = 77;
    noctBroadphaseDef def = noctDefaultBroadphaseDef();
    def.N = 2;
    noctBroadphase *bp;
    noctError err;
    ck_assert_int_eq(noctBroadphaseCreate(&def, &bp, &err), NOCT_OK);
    ck_assert_ptr_null(noctBroadphaseRoot(bp));
    static model m;
    memset(&m, 0, sizeof m);
    m.n = 200;
    for (int i = 0; i < m.n; ++i)
        add_one(bp, &m, i, 10);
    for (int round = 0; round < 3; ++round) {
        walk w = {bp, &m, 0, 0};
        walk_tree(&w, noctBroadphaseRoot(bp));
        noctBroadphaseCounters c;
        noctBroadphaseGetCounters(bp, &c);
        ck_assert_uint_eq(c.nodes, w.nodes);
        ck_assert_uint_eq(c.leaves, w.leaves);
        ck_assert_uint_eq(c.proxies, noctBroadphaseProxyCount(bp));
        ck_assert_uint_eq(c.leaves, 1 + 7 * (c.nodes - c.leaves)); /* 8 children each */
        for (int i = 0; i < m.n; ++i)
            move_one(bp, &m, i, 10);
    }
    noctBroadphaseDestroy(bp);
}
END_TEST

START_TEST(fast_path_and_pair_callbacks)
{
    noctBroadphaseDef def = noctDefaultBroadphaseDef();
    def.N = 1;
    noctBroadphase *bp;
    noctError err;
    ck_assert_int_eq(noctBroadphaseCreate(&def, &bp, &err), NOCT_OK);
    /* a row of small boxes 1 apart, each 0.1 wide: the root splits */
    noctProxyId id[16];
    for (int i = 0; i < 16; ++i) {
        const double lo[3] = {i, 0.45, 0.45}, hi[3] = {i + 0.1, 0.55, 0.55};
        ck_assert_int_eq(noctBroadphaseAdd(bp, lo, hi, NULL, NOCT_FILTER_ALL, NOCT_FILTER_ALL,
                                           &id[i], &err),
                         NOCT_OK);
    }
    noctBroadphaseCounters a, b;
    noctBroadphaseGetCounters(bp, &a);
    ck_assert_uint_gt(a.splits, 0);
    /* a tiny move inside the leaf: the fast test settles it */
    const double lo[3] = {5.001, 0.45, 0.45}, hi[3] = {5.101, 0.55, 0.55};
    ck_assert_int_eq(noctBroadphaseMove(bp, id[5], lo, hi, &err), NOCT_OK);
    noctBroadphaseGetCounters(bp, &b);
    ck_assert_uint_eq(b.moves, a.moves + 1);
    ck_assert_uint_eq(b.inside_fast, a.inside_fast + 1);
    ck_assert_uint_eq(b.leaves_entered, a.leaves_entered);
    /* overlapping chains: i with i + 1 when they are 0.5 wide */
    for (int i = 0; i < 16; ++i) {
        const double l[3] = {i, 0, 0}, h[3] = {i + 1, 1, 1};
        ck_assert_int_eq(noctBroadphaseMove(bp, id[i], l, h, &err), NOCT_OK);
    }
    ck_assert_int_eq(noctBroadphaseUpdatePairs(bp, &err), NOCT_OK);
    const noctProxyPair *p;
    ck_assert_uint_eq(noctBroadphasePairs(bp, &p), 15); /* touching faces count */
    for (size_t i = 0; i < 15; ++i)
        ck_assert(p[i].a.index == id[i].index && p[i].b.index == id[i + 1].index);
    static seen s;
    memset(&s, 0, sizeof s);
    s.stop_after = -1;
    ck_assert_uint_eq(noctBroadphaseForEachPair(bp, on_pair, &s), 15);
    ck_assert_int_eq(s.calls, 15);
    for (int i = 0; i < 15; ++i)
        ck_assert_uint_eq(s.idx[i], id[i].index);
    memset(&s, 0, sizeof s);
    s.stop_after = 4;
    ck_assert_uint_eq(noctBroadphaseForEachPair(bp, on_pair, &s), 4);
    ck_assert_int_eq(s.calls, 4);
    noctBroadphaseDestroy(bp);
}
END_TEST

/* ---- bad input ------------------------------------------------------------------------ */

START_TEST(bad_input_changes_nothing)
{
    noctBroadphaseDef def = noctDefaultBroadphaseDef();
    noctBroadphase *bp;
    noctError err;
    def.N = -1;
    ck_assert_int_eq(noctBroadphaseCreate(&def, &bp, &err), NOCT_ERR_INVALID);
    ck_assert_ptr_null(bp);
    def = noctDefaultBroadphaseDef();
    def.max_depth = 41;
    ck_assert_int_eq(noctBroadphaseCreate(&def, &bp, &err), NOCT_ERR_INVALID);
    def.max_depth = -1;
    ck_assert_int_eq(noctBroadphaseCreate(&def, &bp, &err), NOCT_ERR_INVALID);
    def = noctDefaultBroadphaseDef();
    def.bounds_lo[1] = NAN;
    ck_assert_int_eq(noctBroadphaseCreate(&def, &bp, &err), NOCT_ERR_NONFINITE);
    def = noctDefaultBroadphaseDef();
    ck_assert_int_eq(noctBroadphaseCreate(&def, &bp, &err), NOCT_OK);
    const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
    noctProxyId a, b;
    ck_assert_int_eq(noctBroadphaseAdd(bp, lo, hi, NULL, NOCT_FILTER_ALL, NOCT_FILTER_ALL, &a,
                                       &err),
                     NOCT_OK);
    ck_assert_int_eq(noctBroadphaseAdd(bp, lo, hi, NULL, NOCT_FILTER_ALL, NOCT_FILTER_ALL, &b,
                                       &err),
                     NOCT_OK);
    const double nan3[3] = {0, NAN, 0}, inf3[3] = {INFINITY, 1, 1}, big[3] = {0, 0, 1e101},
                 low[3] = {2, 0, 0};
    struct {
        const double *lo, *hi;
        noctStatus st;
    } bad[] = {{nan3, hi, NOCT_ERR_NONFINITE},
               {lo, inf3, NOCT_ERR_NONFINITE},
               {low, hi, NOCT_ERR_INVALID},
               {lo, big, NOCT_ERR_TOO_LARGE}};
    for (size_t i = 0; i < sizeof bad / sizeof *bad; ++i) {
        noctProxyId c = {7, 7};
        ck_assert_int_eq(noctBroadphaseAdd(bp, bad[i].lo, bad[i].hi, NULL, NOCT_FILTER_ALL,
                                           NOCT_FILTER_ALL, &c, &err),
                         bad[i].st);
        ck_assert_uint_eq(c.index, 0);
        ck_assert_uint_eq(c.generation, 0);
        ck_assert_int_eq(noctBroadphaseMove(bp, a, bad[i].lo, bad[i].hi, &err), bad[i].st);
        ck_assert_uint_eq(noctBroadphaseProxyCount(bp), 2);
        double plo[3], phi[3];
        ck_assert_int_eq(noctBroadphaseProxy(bp, a, plo, phi, NULL, NULL, NULL), NOCT_OK);
        ck_assert(memcmp(plo, lo, sizeof lo) == 0 && memcmp(phi, hi, sizeof hi) == 0);
    }
    ck_assert_int_eq(noctBroadphaseUpdatePairs(bp, &err), NOCT_OK);
    const noctProxyPair *p;
    ck_assert_uint_eq(noctBroadphasePairs(bp, &p), 1);
    ck_assert_int_eq(noctBroadphaseQueryBox(bp, nan3, hi, noctDefaultQueryFilter(), on_proxy,
                                            NULL),
                     NOCT_ERR_NONFINITE);
    ck_assert_int_eq(noctBroadphaseQueryBox(bp, low, hi, noctDefaultQueryFilter(), on_proxy,
                                            NULL),
                     NOCT_ERR_INVALID);
    ck_assert_int_eq(noctBroadphaseQueryPoint(bp, inf3, noctDefaultQueryFilter(), on_proxy,
                                              NULL),
                     NOCT_ERR_NONFINITE);
    ck_assert_int_eq(noctBroadphaseRayCast(bp, lo, nan3, noctDefaultQueryFilter(), on_ray, NULL),
                     NOCT_ERR_NONFINITE);
    /* removal drops the pair from the list */
    ck_assert_int_eq(noctBroadphaseRemove(bp, b), NOCT_OK);
    ck_assert_uint_eq(noctBroadphasePairs(bp, &p), 0);
    noctBroadphaseDestroy(bp);
    noctBroadphaseDestroy(NULL);
}
END_TEST

/* ---- the world's broadphase ------------------------------------------------------ */

START_TEST(world_broadphase_is_the_objects)
{
    noctWorldDef def = noctDefaultWorldDef();
    def.effects |= NOCT_EFFECT_WALLS;
    const double side = noctGasContainerSize(500);
    for (int k = 0; k < 3; ++k) {
        def.walls_lo[k] = 0;
        def.walls_hi[k] = side;
    }
    noctWorld *w;
    noctError err;
    ck_assert_int_eq(noctWorldCreate(&def, &w, &err), NOCT_OK);
    ck_assert_int_eq(noctWorldAddGas(w, 500, &err), NOCT_OK);
    for (int s = 0; s < 20; ++s)
        ck_assert_int_eq(noctWorldStep(w, &err), NOCT_OK);
    const noctBroadphase *bp = noctWorldBroadphase(w);
    ck_assert_uint_eq(noctBroadphaseProxyCount(bp), 500);
    ck_assert_int_eq(noctBroadphaseValidate(bp, &err), NOCT_OK);
    /* every object's handle is its proxy's, with the same box */
    static seen s;
    memset(&s, 0, sizeof s);
    s.stop_after = -1;
    const double lo[3] = {0, 0, 0}, hi[3] = {side / 2, side / 2, side / 2};
    ck_assert_int_eq(noctBroadphaseQueryBox(bp, lo, hi, noctDefaultQueryFilter(), on_proxy, &s),
                     NOCT_OK);
    int want = 0;
    for (uint32_t i = 0; i < 500; ++i) {
        noctObjectId id = {i, 1};
        double olo[3], ohi[3], plo[3], phi[3];
        ck_assert_int_eq(noctWorldObjectBox(w, id, olo, ohi), NOCT_OK);
        ck_assert_int_eq(noctBroadphaseProxy(bp, id, plo, phi, NULL, NULL, NULL), NOCT_OK);
        ck_assert(memcmp(olo, plo, sizeof olo) == 0 && memcmp(ohi, phi, sizeof ohi) == 0);
        want += boxes_meet(lo, hi, olo, ohi);
    }
    ck_assert_int_eq(s.calls, want);
    ck_assert_int_gt(want, 0);
    noctWorldDestroy(w);
}
END_TEST

/*
 * Category 0: the broadphase takes it (noctBroadphaseAdd() and
 * noctBroadphaseSetFilter()) and the proxy is parked: it pairs with
 * nothing, whatever the other's mask, and no query finds it, whatever its
 * filter; a category again brings its pairs and queries back. The world
 * refuses 0 (an object that can never pair is a mistake there), at
 * creation and in noctWorldSetFilter(), and changes nothing.
 */
static void count_finds(const noctBroadphase *bp, int want)
{
    const noctQueryFilter every = {NOCT_FILTER_ALL, NOCT_FILTER_ALL};
    const double lo[3] = {-5, -5, -5}, hi[3] = {5, 5, 5}, p[3] = {0.5, 0.5, 0.5};
    const double origin[3] = {-5, 0.5, 0.5}, along[3] = {10, 0, 0};
    static seen s;
    memset(&s, 0, sizeof s);
    s.stop_after = -1;
    ck_assert_int_eq(noctBroadphaseQueryBox(bp, lo, hi, every, on_proxy, &s), NOCT_OK);
    ck_assert_int_eq(s.calls, want);
    s.calls = 0;
    ck_assert_int_eq(noctBroadphaseQueryPoint(bp, p, every, on_proxy, &s), NOCT_OK);
    ck_assert_int_eq(s.calls, want);
    s.calls = 0;
    ck_assert_int_eq(noctBroadphaseRayCast(bp, origin, along, every, on_ray, &s), NOCT_OK);
    ck_assert_int_eq(s.calls, want);
    for (int i = 0; i < s.calls; ++i)
        ck_assert_uint_eq(s.idx[i], (uint32_t)i);
}

START_TEST(category_zero_parks_a_proxy)
{
    noctBroadphaseDef def = noctDefaultBroadphaseDef();
    noctBroadphase *bp;
    noctError err;
    ck_assert_int_eq(noctBroadphaseCreate(&def, &bp, &err), NOCT_OK);
    const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
    noctProxyId a, b;
    ck_assert_int_eq(noctBroadphaseAdd(bp, lo, hi, NULL, 1, NOCT_FILTER_ALL, &a, &err),
                     NOCT_OK);
    ck_assert_int_eq(noctBroadphaseAdd(bp, lo, hi, NULL, 0, NOCT_FILTER_ALL, &b, &err),
                     NOCT_OK);
    const noctProxyPair *pairs;
    ck_assert_int_eq(noctBroadphaseUpdatePairs(bp, &err), NOCT_OK);
    ck_assert_uint_eq(noctBroadphasePairs(bp, &pairs), 0);
    count_finds(bp, 1);
    ck_assert_int_eq(noctBroadphaseSetFilter(bp, b, 1, NOCT_FILTER_ALL), NOCT_OK);
    ck_assert_int_eq(noctBroadphaseUpdatePairs(bp, &err), NOCT_OK);
    ck_assert_uint_eq(noctBroadphasePairs(bp, &pairs), 1);
    count_finds(bp, 2);
    ck_assert_int_eq(noctBroadphaseSetFilter(bp, b, 0, NOCT_FILTER_ALL), NOCT_OK);
    uint64_t cat = 1, mask = 0;
    ck_assert_int_eq(noctBroadphaseProxy(bp, b, NULL, NULL, NULL, &cat, &mask), NOCT_OK);
    ck_assert(cat == 0 && mask == NOCT_FILTER_ALL);
    ck_assert_int_eq(noctBroadphaseUpdatePairs(bp, &err), NOCT_OK);
    ck_assert_uint_eq(noctBroadphasePairs(bp, &pairs), 0);
    count_finds(bp, 1);
    ck_assert_int_eq(noctBroadphaseValidate(bp, &err), NOCT_OK);
    noctBroadphaseDestroy(bp);

    noctWorldDef wd = noctDefaultWorldDef();
    noctWorld *w;
    ck_assert_int_eq(noctWorldCreate(&wd, &w, &err), NOCT_OK);
    noctObjectDef d = noctDefaultObjectDef();
    d.half_extents[0] = d.half_extents[1] = d.half_extents[2] = 0.5;
    d.category = 0;
    noctObjectId id;
    ck_assert_int_eq(noctWorldCreateObject(w, &d, &id, &err), NOCT_ERR_INVALID);
    ck_assert_uint_eq(noctWorldObjectCount(w), 0);
    d.category = 1;
    ck_assert_int_eq(noctWorldCreateObject(w, &d, &id, &err), NOCT_OK);
    ck_assert_int_eq(noctWorldSetFilter(w, id, 0, NOCT_FILTER_ALL, &err), NOCT_ERR_INVALID);
    ck_assert_int_eq(noctWorldGetFilter(w, id, &cat, &mask), NOCT_OK);
    ck_assert(cat == 1 && mask == NOCT_FILTER_ALL);
    noctWorldDestroy(w);
}
END_TEST

/*
 * Far from the origin, cells must stay wider than the coordinates'
 * rounding: coincident points and boxes of a few ulps, at offsets from 10
 * to 1e99, moved by a few ulps at a time, give exactly the brute force's
 * pairs, every proxy is found by a point query at its corner, and the tree
 * stays small (no runaway splitting into cells narrower than an ulp).
 */
static const double FAR_OFFSETS[] = {10.5, 1003.3, -1048576.1, 3e12, -7.25e15, 1e90, -9e99};

START_TEST(far_from_the_origin)
{
    const double offset = FAR_OFFSETS[_i / 3];
    const int n_of[] = {1, 3, 10};
    const int depth_of[] = {40, 10, 40};
    rng = 0xfa12 + (uint64_t)_i;
    noctBroadphaseDef def = noctDefaultBroadphaseDef();
    def.N = n_of[_i % 3];
    def.max_depth = depth_of[_i % 3];
    noctBroadphase *bp;
    noctError err;
    ck_assert_int_eq(noctBroadphaseCreate(&def, &bp, &err), NOCT_OK);
    static model m;
    memset(&m, 0, sizeof m);
    m.n = 48;
    /* a scene some hundred ulps across */
    const double ulp = nextafter(fabs(offset), INFINITY) - fabs(offset);
    const double scene = 256 * ulp;
    for (int i = 0; i < m.n; ++i) {
        const bool point = i < 12; /* a dozen coincident points */
        for (int k = 0; k < 3; ++k) {
            m.lo[i][k] = point ? offset : offset + scene * floor(16 * uniform()) / 16;
            m.hi[i][k] = point ? offset : m.lo[i][k] + scene * floor(8 * uniform()) / 16;
        }
        m.cat[i] = m.mask[i] = NOCT_FILTER_ALL;
        ck_assert_int_eq(noctBroadphaseAdd(bp, m.lo[i], m.hi[i], NULL, NOCT_FILTER_ALL,
                                           NOCT_FILTER_ALL, &m.id[i], &err),
                         NOCT_OK);
        m.alive[i] = true;
    }
    for (int round = 0; round < 20; ++round) {
        check_pairs(bp, &m);
        for (int i = 0; i < m.n; ++i) {
            point_hit f = {0, m.id[i], false};
            ck_assert_int_eq(noctBroadphaseQueryPoint(bp, m.lo[i], noctDefaultQueryFilter(),
                                                      on_found, &f),
                             NOCT_OK);
            ck_assert_msg(f.seen, "proxy %d not found at its corner (offset %g)", i, offset);
        }
        noctBroadphaseCounters c;
        noctBroadphaseGetCounters(bp, &c);
        ck_assert_msg(c.nodes <= 8 * 40 * (uint64_t)m.n, "%llu nodes for %d proxies",
                      (unsigned long long)c.nodes, m.n);
        for (int i = 12; i < m.n; ++i) { /* a few ulps at a time */
            for (int k = 0; k < 3; ++k) {
                const double d = scene * floor(8 * uniform() - 4) / 64;
                m.lo[i][k] += d;
                m.hi[i][k] += d;
            }
            ck_assert_int_eq(noctBroadphaseMove(bp, m.id[i], m.lo[i], m.hi[i], &err), NOCT_OK);
        }
    }
    noctBroadphaseDestroy(bp);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("broadphase");
    TCase *tc = test_case(s, "brute force", 300, NULL);
    tcase_add_loop_test(tc, pairs_against_brute_force, 0, 20);
    tcase_add_loop_test(tc, queries_against_brute_force, 0, 2);
    tcase_add_loop_test(tc, rays_against_brute_force, 0,
                        (int)(sizeof RAY_CONFIG / sizeof *RAY_CONFIG));
    tcase_add_test(tc, rays_stop_early);
    tc = test_case(s, "tree", 0, NULL);
    tcase_add_loop_test(tc, automatic_settings, 0, 2);
    add_tests(tc, removals_drop_their_pairs, leaves_and_counters, fast_path_and_pair_callbacks,
              world_broadphase_is_the_objects);
    tcase_add_loop_test(tc, far_from_the_origin, 0,
                        3 * (int)(sizeof FAR_OFFSETS / sizeof *FAR_OFFSETS));
    tc = test_case(s, "bad input", 0, NULL);
    tcase_add_test(tc, bad_input_changes_nothing);
    tcase_add_test(tc, category_zero_parks_a_proxy);
    return run_suite(s);
}
