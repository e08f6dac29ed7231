/* SPDX-License-Identifier: MIT */
/*
 * The world's continuous level (accuracy #NOCT_ACCURACY_CONTINUOUS)
 * against independent expectations:
 * - random worlds of box primitives, box meshes and tetrahedra, some
 *   turned (and staying so), fast and slow movers, static and kinematic
 *   objects, teleports, keyframe tracks, filters and sensors, with and
 *   without walls and response, removals and re-creations, velocity and
 *   type changes: after every step the colliding and sensing lists are
 *   the all-pairs brute force of noctCollideSwept() on the test's own
 *   placed meshes from where the last step left each object to where it
 *   is now, the events are the brute force's differences, and every
 *   began contact's hit is noctCollideSwept()'s on the same motion (so
 *   the broadphase's grown boxes hand over every swept pair);
 * - the tunnelling cases: a keyframed cube through a thin wall, a
 *   kinematic object teleported through one, a bullet of a million times
 *   its size per step through a plate, each at a known time; the exact
 *   level sees none of them;
 * - families of static objects: the continuous level's lists are the
 *   exact level's; moving ones: the exact level's are among its own;
 * - allocations failing in continuous steps and in the began hits: a
 *   failed step leaves the world as it was, the retried one gives what a
 *   world without failures gives, and nothing leaks.
 */
#define _POSIX_C_SOURCE 200809L /* mkstemp, fdopen */
#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <noctree/mesh.h>
#include <noctree/narrowphase.h>
#include <noctree/scene.h>
#include <noctree/transform.h>
#include <noctree/world.h>

#include "testalloc.h"
#include "testutil.h"

/* ---- shapes and their placed meshes -------------------------------------------- */

/* The test's shapes, as vertices and triangles, so that a turned copy has
 * the same triangles as the world's (it turns a mesh's fan triangles). */
typedef struct shape {
    double v[24];
    int nv;
    uint32_t tri[36];
    int nt;
} shape;

/* A box's corners (bit 0: +x, bit 1: +y, bit 2: +z), its faces
 * counter-clockwise from outside, each split as the fan from its first
 * corner. */
static shape box_shape(double hx, double hy, double hz)
{
    static const uint32_t faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                         {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    shape s = {.nv = 8, .nt = 12};
    for (int i = 0; i < 8; ++i) {
        s.v[3 * i] = i & 1 ? hx : -hx;
        s.v[3 * i + 1] = i & 2 ? hy : -hy;
        s.v[3 * i + 2] = i & 4 ? hz : -hz;
    }
    for (int f = 0; f < 6; ++f) {
        const uint32_t *q = faces[f];
        const uint32_t t[6] = {q[0], q[1], q[2], q[0], q[2], q[3]};
        memcpy(&s.tri[6 * f], t, sizeof t);
    }
    return s;
}

/* The kit's tetrahedron (make_tetrahedron()), vertex for vertex. */
static shape tet_shape(void)
{
    static const double v[12] = {0, 0, 0, 0.9, 0.1, 0, 0.2, 0.8, 0.1, 0.3, 0.2, 0.7};
    static const uint32_t idx[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    shape s = {.nv = 4, .nt = 4};
    memcpy(s.v, v, sizeof v);
    memcpy(s.tri, idx, sizeof idx);
    return s;
}

/* The shape turned by q as transform.h places it: each coordinate
 * fl(fl(fl(R_i0 v_0) + fl(R_i1 v_1)) + fl(R_i2 v_2)), no fused
 * multiply-add (volatile keeps each rounding). */
static noctMesh *shape_mesh(const shape *s, const noctQuat *q)
{
    double R[9], v[24];
    ck_assert_int_eq(noctQuatToMatrix(q, R, NULL), NOCT_OK);
    for (int i = 0; i < s->nv; ++i)
        for (int r = 0; r < 3; ++r) {
            volatile double p0 = R[3 * r] * s->v[3 * i];
            volatile double p1 = R[3 * r + 1] * s->v[3 * i + 1];
            volatile double p2 = R[3 * r + 2] * s->v[3 * i + 2];
            volatile double sum = p0 + p1;
            v[3 * i + r] = sum + p2;
        }
    uint32_t sizes[12];
    for (int t = 0; t < s->nt; ++t)
        sizes[t] = 3;
    noctMesh *m;
    noctError err;
    ck_assert_msg(noctMeshCreate(v, (size_t)s->nv, sizes, (size_t)s->nt, s->tri, &m, &err) ==
                      NOCT_OK,
                  "%s", err.message);
    return m;
}

/* A box primitive's mesh: the oriented box of its half-extents and
 * rotation (the mesh the world makes of it for its triangles). */
static noctMesh *primitive_mesh(const double half[3], const noctQuat *q)
{
    double R[9];
    ck_assert_int_eq(noctQuatToMatrix(q, R, NULL), NOCT_OK);
    noctMesh *m;
    ck_assert_int_eq(noctMeshCreateOrientedBox(half, R, &m, NULL), NOCT_OK);
    return m;
}

/* ---- pair lists ---------------------------------------------------------------- */

static int cmp_pair(const void *x, const void *y)
{
    const noctPair *a = x, *b = y;
    if (a->a.index != b->a.index)
        return a->a.index < b->a.index ? -1 : 1;
    if (a->b.index != b->b.index)
        return a->b.index < b->b.index ? -1 : 1;
    return 0;
}

static bool same_id(noctObjectId a, noctObjectId b)
{
    return a.index == b.index && a.generation == b.generation;
}

static bool same_pair(noctPair p, noctPair q)
{
    return same_id(p.a, q.a) && same_id(p.b, q.b);
}

typedef struct plist {
    size_t n, cap;
    noctPair *p;
} plist;

static void plist_push(plist *l, noctPair p)
{
    if (l->n == l->cap) {
        l->cap = l->cap ? 2 * l->cap : 64;
        l->p = realloc(l->p, l->cap * sizeof *l->p);
        ck_assert_ptr_nonnull(l->p);
    }
    l->p[l->n++] = p;
}

static bool plist_has(const plist *l, noctPair p)
{
    for (size_t i = 0; i < l->n; ++i)
        if (same_pair(l->p[i], p))
            return true;
    return false;
}

/* out = a less b, sorted (a and b sorted, by handle). */
static void plist_minus(const plist *a, const plist *b, plist *out)
{
    out->n = 0;
    for (size_t i = 0; i < a->n; ++i)
        if (!plist_has(b, a->p[i]))
            plist_push(out, a->p[i]);
}

static void plist_copy(plist *dst, const noctPair *p, size_t n)
{
    dst->n = 0;
    for (size_t i = 0; i < n; ++i)
        plist_push(dst, p[i]);
}

/* The world's list is the expected one, in order. */
static void expect_list(const char *what, int step, const noctPair *got, size_t ngot,
                        const plist *want)
{
    size_t i = 0;
    while (i < ngot && i < want->n && same_pair(got[i], want->p[i]))
        ++i;
    if (i == ngot && i == want->n)
        return;
    char first[160] = "";
    if (i < ngot)
        snprintf(first, sizeof first, "; the world has (%u.%u, %u.%u)", got[i].a.index,
                 got[i].a.generation, got[i].b.index, got[i].b.generation);
    if (i < want->n) {
        size_t k = strlen(first);
        snprintf(first + k, sizeof first - k, "; expected (%u.%u, %u.%u)", want->p[i].a.index,
                 want->p[i].a.generation, want->p[i].b.index, want->p[i].b.generation);
    }
    ck_abort_msg("step %d: %s: the world lists %zu pairs, the brute force %zu; first "
                 "difference at %zu%s",
                 step, what, ngot, want->n, i, first);
}

static bool same_hit(const noctSweepHit *x, const noctSweepHit *y)
{
    return x->time == y->time && x->feature == y->feature &&
           memcmp(x->a, y->a, sizeof x->a) == 0 && memcmp(x->b, y->b, sizeof x->b) == 0 &&
           memcmp(x->point, y->point, sizeof x->point) == 0;
}

/* Room for n pairs, so that pushing them does not allocate. */
static void plist_reserve(plist *l, size_t n)
{
    if (l->cap < n) {
        l->cap = n;
        l->p = realloc(l->p, n * sizeof *l->p);
        ck_assert_ptr_nonnull(l->p);
    }
}

/* ---- random worlds against the brute force ------------------------------------- */

#define MAXN 200
#define NSHAPES 4 /* a tetrahedron and three box meshes */
#define SIDE 24.0 /* the objects start in [0, SIDE]^3, the walls' container */

typedef struct cobj {
    bool alive;
    noctObjectId id;
    int shape;           /* -1: a box primitive */
    double half[3];      /* a box primitive's half-extents */
    noctQuat q;          /* its rotation, fixed */
    noctMesh *placed;    /* the test's mesh as turned (owned), or NULL: */
    const noctMesh *use; /* the mesh the brute force places */
    double lo[3], hi[3]; /* its bounds */
    uint64_t cat, mask;
    bool sensor;
    noctMotionQuality quality;
    double start[3]; /* where the last step left it, or where it was made */
} cobj;

typedef struct harness {
    uint64_t rng;
    noctWorld *w;
    shape shapes[NSHAPES];
    noctMesh *meshes[NSHAPES]; /* the world's meshes, unturned */
    int n;
    cobj o[MAXN];
    unsigned effects;
    bool cont_world; /* the world's accuracy is continuous (else exact) */
    bool churn; /* remove and re-create objects between steps */
    plist colliding, sensing, prev_colliding, prev_sensing, tmp;
    noctNarrowStats swept_pairs; /* the brute force's work */
    size_t began_seen, hits_seen, fast_seen;
} harness;

static double uni(harness *h)
{
    return test_uniform(&h->rng);
}

static uint64_t random_bits(harness *h)
{
    return uni(h) < 0.7 ? NOCT_FILTER_ALL : (uint64_t)1 << (int)(3 * uni(h));
}

/* A velocity: mostly slow, a third fast (several times an object's size
 * per step), some zero. */
static void random_velocity(harness *h, double v[3])
{
    const double u = uni(h);
    const double scale = u < 0.1 ? 0 : u < 0.65 ? 0.3 : 6;
    for (int k = 0; k < 3; ++k)
        v[k] = scale * (2 * uni(h) - 1);
}

static void random_position(harness *h, double p[3])
{
    for (int k = 0; k < 3; ++k)
        p[k] = SIDE * uni(h);
}

/* Give object i a track of translation-only keys, from the current tick
 * on: a jump now, then keys 1 to 4 steps apart, far apart (fast). Only
 * for objects not turned: between keys of the same rotation the track
 * normalises the interpolated quaternion, which may change its last bits
 * (a tiny turn), but not the identity's. */
static void random_track(harness *h, int i)
{
    cobj *c = &h->o[i];
    if (c->q.w != 1)
        return;
    const uint64_t t0 = noctWorldTick(h->w);
    noctKeyframe keys[4];
    uint64_t t = t0;
    for (int k = 0; k < 4; ++k) {
        keys[k].tick = t;
        keys[k].x.q = c->q;
        random_position(h, keys[k].x.p);
        t += 1 + test_rand_below(&h->rng, 4);
    }
    noctError err;
    ck_assert_msg(noctWorldSetTrack(h->w, c->id, keys, 4, &err) == NOCT_OK, "%s",
                  err.message);
}

static void add_object(harness *h, int i)
{
    cobj *c = &h->o[i];
    noctObjectDef d = noctDefaultObjectDef();
    const double u = uni(h);
    c->q = (noctQuat){0, 0, 0, 1};
    if (uni(h) < 0.2)
        test_random_quat(&h->rng, &c->q);
    const bool turned = c->q.w != 1;
    if (u < 0.4) {
        c->shape = -1;
        for (int k = 0; k < 3; ++k)
            c->half[k] = d.half_extents[k] = 0.05 + 0.7 * uni(h);
        c->placed = primitive_mesh(c->half, &c->q);
        c->use = c->placed;
    } else {
        c->shape = (int)test_rand_below(&h->rng, NSHAPES);
        d.mesh = h->meshes[c->shape];
        c->placed = turned ? shape_mesh(&h->shapes[c->shape], &c->q) : NULL;
        c->use = turned ? c->placed : h->meshes[c->shape];
    }
    noctMeshBounds(c->use, c->lo, c->hi);
    d.transform.q = c->q;
    random_position(h, d.transform.p);
    const double t = uni(h);
    d.type = t < 0.15 ? NOCT_OBJECT_STATIC : t < 0.3 ? NOCT_OBJECT_KINEMATIC
                                                     : NOCT_OBJECT_MOVING;
    random_velocity(h, d.velocity);
    c->cat = d.category = random_bits(h);
    c->mask = d.mask = random_bits(h);
    c->sensor = d.sensor = uni(h) < 0.05;
    const double qu = uni(h);
    c->quality = d.quality = qu < 0.7    ? NOCT_QUALITY_WORLD
                             : qu < 0.85 ? NOCT_QUALITY_DISCRETE
                                         : NOCT_QUALITY_CONTINUOUS;
    noctError err;
    ck_assert_msg(noctWorldCreateObject(h->w, &d, &c->id, &err) == NOCT_OK, "%s", err.message);
    memcpy(c->start, d.transform.p, sizeof c->start);
    c->alive = true;
    if (d.type == NOCT_OBJECT_KINEMATIC && uni(h) < 0.4)
        random_track(h, i);
}

static void remove_object(harness *h, int i)
{
    cobj *c = &h->o[i];
    ck_assert_int_eq(noctWorldRemove(h->w, c->id, NULL), NOCT_OK);
    noctMeshDestroy(c->placed);
    c->placed = NULL;
    c->alive = false;
}

/* cont: the world is continuous; else one in three is exact. */
static void harness_init(harness *h, uint64_t seed, int n, bool churn, bool cont)
{
    memset(h, 0, sizeof *h);
    h->rng = seed;
    h->churn = churn;
    h->shapes[0] = tet_shape();
    h->shapes[1] = box_shape(0.5, 0.5, 0.5);
    h->shapes[2] = box_shape(0.1, 0.4, 0.25);
    h->shapes[3] = box_shape(1.5, 0.05, 0.6); /* a plate */
    for (int s = 0; s < NSHAPES; ++s)
        h->meshes[s] = shape_mesh(&h->shapes[s], &(noctQuat){0, 0, 0, 1});
    noctWorldDef wd = noctDefaultWorldDef();
    /* most worlds continuous; the rest exact, with their continuous
     * objects (noctObjectDef::quality) swept alone */
    h->cont_world = uni(h) < 0.7 || cont;
    wd.accuracy = h->cont_world ? NOCT_ACCURACY_CONTINUOUS : NOCT_ACCURACY_EXACT;
    wd.effects = NOCT_EFFECT_EVENTS | NOCT_EFFECT_TRACK;
    if (uni(h) < 0.85)
        wd.effects |= NOCT_EFFECT_MOTION;
    if (uni(h) < 0.5)
        wd.effects |= NOCT_EFFECT_RESPONSE;
    if (uni(h) < 0.5) {
        wd.effects |= NOCT_EFFECT_WALLS;
        for (int k = 0; k < 3; ++k) {
            wd.walls_lo[k] = 0;
            wd.walls_hi[k] = SIDE;
        }
    }
    const double u = uni(h);
    wd.N = u < 0.4 ? NOCT_AUTO : u < 0.7 ? 2 : 8;
    if (uni(h) < 0.2)
        wd.maintenance = NOCT_MAINTAIN_REBUILD;
    h->effects = wd.effects;
    noctError err;
    ck_assert_msg(noctWorldCreate(&wd, &h->w, &err) == NOCT_OK, "%s", err.message);
    h->n = n;
    for (int i = 0; i < n; ++i)
        add_object(h, i);
}

static void harness_free(harness *h)
{
    noctWorldDestroy(h->w);
    for (int i = 0; i < h->n; ++i)
        noctMeshDestroy(h->o[i].placed);
    for (int s = 0; s < NSHAPES; ++s)
        noctMeshDestroy(h->meshes[s]);
    free(h->colliding.p);
    free(h->sensing.p);
    free(h->prev_colliding.p);
    free(h->prev_sensing.p);
    free(h->tmp.p);
}

/* The changes a program makes between steps: teleports, velocities,
 * types, tracks, and with churn removals and re-creations. */
/* Is c's motion tested continuously (its quality, or the world's)? */
static bool is_continuous(const harness *h, const cobj *c)
{
    return c->quality == NOCT_QUALITY_CONTINUOUS ||
           (c->quality == NOCT_QUALITY_WORLD && h->cont_world);
}

static void between_steps(harness *h)
{
    noctError err;
    for (int i = 0; i < h->n; ++i) {
        cobj *c = &h->o[i];
        if (!c->alive) {
            if (uni(h) < 0.5)
                add_object(h, i);
            continue;
        }
        const double u = uni(h);
        if (u < 0.04) { /* a teleport, as far as the fast movers go */
            noctTransform x;
            ck_assert_int_eq(noctWorldGetTransform(h->w, c->id, &x), NOCT_OK);
            for (int k = 0; k < 3; ++k)
                x.p[k] += 8 * (2 * uni(h) - 1);
            ck_assert_msg(noctWorldSetTransform(h->w, c->id, &x, &err) == NOCT_OK, "%s",
                          err.message);
        } else if (u < 0.07) {
            double v[3];
            random_velocity(h, v);
            ck_assert_int_eq(noctWorldSetVelocity(h->w, c->id, v, NULL), NOCT_OK);
        } else if (u < 0.09) {
            const noctObjectType t = (noctObjectType)test_rand_below(&h->rng, 3);
            ck_assert_int_eq(noctWorldSetType(h->w, c->id, t, NULL), NOCT_OK);
        } else if (u < 0.1) {
            random_track(h, i);
        } else if (u < 0.11) {
            ck_assert_int_eq(noctWorldSetTrack(h->w, c->id, NULL, 0, NULL), NOCT_OK);
        } else if (u < 0.13) {
            /* a new quality: an object that becomes continuous starts its
             * next step where it is */
            const bool was = is_continuous(h, c);
            c->quality = (noctMotionQuality)test_rand_below(&h->rng, 3);
            ck_assert_int_eq(noctWorldSetMotionQuality(h->w, c->id, c->quality, NULL), NOCT_OK);
            noctMotionQuality back;
            ck_assert_int_eq(noctWorldGetMotionQuality(h->w, c->id, &back), NOCT_OK);
            ck_assert_int_eq(back, c->quality);
            if (!was && is_continuous(h, c)) {
                noctTransform x;
                ck_assert_int_eq(noctWorldGetTransform(h->w, c->id, &x), NOCT_OK);
                memcpy(c->start, x.p, sizeof c->start);
            }
        } else if (h->churn && u < 0.16) {
            remove_object(h, i);
            if (uni(h) < 0.5)
                add_object(h, i); /* at once: the freed slot, a new generation */
        }
    }
}

/* The swept boxes of two objects apart by more than rounding: they
 * cannot touch (the test's own filter before noctCollideSwept()). */
static bool swept_apart(const cobj *a, const double a0[3], const double a1[3], const cobj *b,
                        const double b0[3], const double b1[3])
{
    for (int k = 0; k < 3; ++k) {
        const double alo = a->lo[k] + fmin(a0[k], a1[k]);
        const double ahi = a->hi[k] + fmax(a0[k], a1[k]);
        const double blo = b->lo[k] + fmin(b0[k], b1[k]);
        const double bhi = b->hi[k] + fmax(b0[k], b1[k]);
        const double pad = 1e-9 * (1 + fabs(alo) + fabs(ahi) + fabs(blo) + fabs(bhi));
        if (ahi + pad < blo || bhi + pad < alo)
            return true;
    }
    return false;
}

/* Object i and j in the world's order (the smaller index first). */
static void ordered(const harness *h, int *i, int *j)
{
    if (h->o[*i].id.index > h->o[*j].id.index) {
        int t = *i;
        *i = *j;
        *j = t;
    }
}

/* Where objects i and j start as the world's continuous level takes
 * them: a pair without a continuous object is tested where the step left
 * both; with one, a discrete object is taken where the step left it. */
static void starts(const harness *h, int i, int j, double end[][3], const double **a0,
                   const double **b0)
{
    const cobj *a = &h->o[i], *b = &h->o[j];
    const bool ca = is_continuous(h, a), cb = is_continuous(h, b);
    *a0 = ca && (ca || cb) ? a->start : end[i];
    *b0 = cb && (ca || cb) ? b->start : end[j];
}

static void swept(harness *h, int i, int j, double end[][3], bool *hit,
                  noctSweepHit *where)
{
    const cobj *a = &h->o[i], *b = &h->o[j];
    const double *a0, *b0;
    starts(h, i, j, end, &a0, &b0);
    noctStatus st = noctCollideSwept(a->use, a0, end[i], b->use, b0, end[j], hit, where,
                                     &h->swept_pairs);
    ck_assert_int_eq(st, NOCT_OK);
}

/* One step of the world, checked against the brute force. */
static void step_and_check(harness *h, int step)
{
    noctError err;
    ck_assert_msg(noctWorldStep(h->w, &err) == NOCT_OK, "step %d: %s", step, err.message);
    ck_assert_msg(noctWorldValidate(h->w, &err) == NOCT_OK, "step %d: %s", step, err.message);
    static double end[MAXN][3];
    for (int i = 0; i < h->n; ++i)
        if (h->o[i].alive) {
            noctTransform x;
            ck_assert_int_eq(noctWorldGetTransform(h->w, h->o[i].id, &x), NOCT_OK);
            EXPECT(memcmp(&x.q, &h->o[i].q, sizeof x.q) == 0); /* no turning */
            memcpy(end[i], x.p, sizeof end[i]);
            double d2 = 0;
            for (int k = 0; k < 3; ++k)
                d2 += (end[i][k] - h->o[i].start[k]) * (end[i][k] - h->o[i].start[k]);
            if (d2 > 4)
                ++h->fast_seen;
        }
    /* the brute force over every pair the filters allow */
    plist *prev_c = &h->prev_colliding, *prev_s = &h->prev_sensing;
    plist t;
    t = *prev_c, *prev_c = h->colliding, h->colliding = t;
    t = *prev_s, *prev_s = h->sensing, h->sensing = t;
    h->colliding.n = h->sensing.n = 0;
    for (int i = 0; i < h->n; ++i)
        for (int j = i + 1; j < h->n; ++j) {
            const cobj *a = &h->o[i], *b = &h->o[j];
            if (!a->alive || !b->alive || (a->sensor && b->sensor))
                continue;
            if (!(a->cat & b->mask) || !(b->cat & a->mask))
                continue;
            const double *a0, *b0;
            starts(h, i, j, end, &a0, &b0);
            if (swept_apart(a, a0, end[i], b, b0, end[j]))
                continue;
            int x = i, y = j;
            ordered(h, &x, &y);
            bool hit;
            swept(h, x, y, end, &hit, NULL);
            if (hit)
                plist_push(a->sensor || b->sensor ? &h->sensing : &h->colliding,
                           (noctPair){h->o[x].id, h->o[y].id});
        }
    if (h->colliding.n > 1) /* qsort may not take NULL, even for none */
        qsort(h->colliding.p, h->colliding.n, sizeof *h->colliding.p, cmp_pair);
    if (h->sensing.n > 1)
        qsort(h->sensing.p, h->sensing.n, sizeof *h->sensing.p, cmp_pair);
    const noctPair *p;
    size_t np = noctWorldColliding(h->w, &p);
    expect_list("colliding", step, p, np, &h->colliding);
    np = noctWorldSensing(h->w, &p);
    expect_list("sensing", step, p, np, &h->sensing);
    /* the events: the differences of consecutive lists */
    plist_minus(&h->colliding, prev_c, &h->tmp);
    np = noctWorldBegan(h->w, &p);
    expect_list("began", step, p, np, &h->tmp);
    h->began_seen += np;
    /* each began contact's hit: noctCollideSwept()'s on the same motion */
    const noctSweepHit *hits;
    size_t nh;
    ck_assert_msg(noctWorldBeganHits(h->w, &hits, &nh, &err) == NOCT_OK, "%s", err.message);
    ck_assert_uint_eq(nh, np);
    for (size_t k = 0; k < nh; ++k) {
        int i = -1, j = -1;
        for (int m = 0; m < h->n; ++m)
            if (h->o[m].alive) {
                if (same_id(h->o[m].id, p[k].a))
                    i = m;
                if (same_id(h->o[m].id, p[k].b))
                    j = m;
            }
        ck_assert(i >= 0 && j >= 0);
        bool hit;
        noctSweepHit want;
        swept(h, i, j, end, &hit, &want);
        const noctSweepHit *got = &hits[k];
        if (!is_continuous(h, &h->o[i]) && !is_continuous(h, &h->o[j])) {
            /* a discrete pair: found where the step left it */
            ck_assert(hit);
            ck_assert(got->time == 1 && got->feature == NOCT_SWEEP_END);
            continue;
        }
        /* The world turns a mesh from its own triangle list, which need not
         * be in the order the test gave: where several features touch
         * first at once it may name another of them. The time is the
         * same. */
        const bool own = !(h->o[i].shape >= 0 && h->o[i].placed != NULL) &&
                         !(h->o[j].shape >= 0 && h->o[j].placed != NULL);
        if (!(hit && (own ? same_hit(got, &want) : got->time == want.time))) {
            noctObjectType ta, tb;
            noctWorldGetType(h->w, p[k].a, &ta);
            noctWorldGetType(h->w, p[k].b, &tb);
            ck_abort_msg("step %d, began pair (%u, %u) of types %d and %d, moved by "
                         "(%g %g %g) and (%g %g %g): the world's hit at %.17g feature %d "
                         "(%u %u %u / %u %u %u), noctCollideSwept's at %.17g feature %d "
                         "(%u %u %u / %u %u %u)",
                         step, p[k].a.index, p[k].b.index, (int)ta, (int)tb,
                         end[i][0] - h->o[i].start[0], end[i][1] - h->o[i].start[1],
                         end[i][2] - h->o[i].start[2], end[j][0] - h->o[j].start[0],
                         end[j][1] - h->o[j].start[1], end[j][2] - h->o[j].start[2],
                         got->time, (int)got->feature,
                         got->a[0], got->a[1], got->a[2], got->b[0], got->b[1], got->b[2],
                         want.time, (int)want.feature, want.a[0], want.a[1], want.a[2],
                         want.b[0], want.b[1], want.b[2]);
        }
        if (want.feature != NOCT_SWEEP_START)
            ++h->hits_seen;
    }
    plist_minus(prev_c, &h->colliding, &h->tmp);
    np = noctWorldEnded(h->w, &p);
    expect_list("ended", step, p, np, &h->tmp);
    plist_minus(&h->sensing, prev_s, &h->tmp);
    np = noctWorldSensorBegan(h->w, &p);
    expect_list("sensor began", step, p, np, &h->tmp);
    plist_minus(prev_s, &h->sensing, &h->tmp);
    np = noctWorldSensorEnded(h->w, &p);
    expect_list("sensor ended", step, p, np, &h->tmp);
    /* the next step starts where this one left each object */
    for (int i = 0; i < h->n; ++i)
        if (h->o[i].alive)
            memcpy(h->o[i].start, end[i], sizeof end[i]);
}

static void run_random_world(uint64_t seed, bool churn, int steps, size_t *began,
                             size_t *hits, size_t *fast)
{
    harness *h = malloc(sizeof *h);
    ck_assert_ptr_nonnull(h);
    uint64_t r = seed;
    const int n = 30 + (int)test_rand_below(&r, 171);
    harness_init(h, seed * 7919 + 1, n, churn, false);
    for (int s = 1; s <= steps; ++s) {
        step_and_check(h, s);
        between_steps(h);
    }
    *began += h->began_seen;
    *hits += h->hits_seen;
    *fast += h->fast_seen;
    harness_free(h);
    free(h);
}

/* _i: the world's seed; quick runs, under valgrind too. */
START_TEST(random_worlds_against_brute_force)
{
    size_t began = 0, hits = 0, fast = 0;
    for (int r = 0; r < 2; ++r)
        run_random_world((uint64_t)(4 * _i + r + 1), r == 1, 12, &began, &hits, &fast);
    /* the runs see contacts begin after the start, and fast motions */
    ck_assert_uint_gt(began, 10);
    ck_assert_uint_gt(hits, 5);
    ck_assert_uint_gt(fast, 20);
}
END_TEST

/* The same at length (tag slow). */
START_TEST(random_worlds_long)
{
    size_t began = 0, hits = 0, fast = 0;
    for (int r = 0; r < 6; ++r)
        run_random_world((uint64_t)(1000 + 6 * _i + r), r % 2 == 1, 30, &began, &hits, &fast);
    ck_assert_uint_gt(hits, 20);
}
END_TEST

/* ---- tunnelling ---------------------------------------------------------------- */

static const char TUNNEL_SCENE[] = "steps 4\n"
                                   "accuracy continuous\n"
                                   "mesh cube box 0.5 0.5 0.5\n"
                                   "mesh wall box 0.05 2 2\n"
                                   "object wall 0 0 0 type static\n"
                                   "object cube -3 0 0\n"
                                   "key 0 -3 0 0\n"
                                   "key 1 -3 0 0\n"
                                   "key 2 3 0 0\n";

/* The scene file, in a temporary file, read. */
static noctScene *read_scene(const char *text)
{
    char path[] = "/tmp/check-continuous-XXXXXX";
    const int fd = mkstemp(path);
    ck_assert_int_ge(fd, 0);
    FILE *f = fdopen(fd, "w");
    ck_assert_ptr_nonnull(f);
    ck_assert_int_eq(fputs(text, f) >= 0, 1);
    ck_assert_int_eq(fclose(f), 0);
    noctScene *sc;
    noctError err;
    const noctStatus st = noctSceneRead(path, &sc, &err);
    unlink(path);
    ck_assert_msg(st == NOCT_OK, "%s", err.message);
    return sc;
}

/* The time a hit gives for a first contact at the real time t: a
 * multiple of 2^-52 in [t, t + 2^-52] (t computed in long double, far
 * finer than 2^-52). */
static void expect_time(double got, long double t)
{
    ck_assert_msg((long double)got >= t - 1e-18L && (long double)got - 0x1p-52L <= t + 1e-18L,
                  "hit at %.17g, first contact at %.17Lg", got, t);
    ck_assert(ldexp(got, 52) == floor(ldexp(got, 52)));
}

/* Steps the world; the pair (0, 1) must begin at step `begins` with its
 * first contact at t, end at step `ends`, and be in no list otherwise. */
static void expect_tunnel(noctWorld *w, int steps, int begins, int ends, long double t)
{
    noctError err;
    for (int s = 1; s <= steps; ++s) {
        ck_assert_msg(noctWorldStep(w, &err) == NOCT_OK, "%s", err.message);
        const noctPair *p;
        const size_t nc = noctWorldColliding(w, &p);
        const size_t nb = noctWorldBegan(w, &p);
        const size_t ne = noctWorldEnded(w, &p);
        ck_assert_msg(nc == (size_t)(s == begins) && nb == (size_t)(s == begins) &&
                          ne == (size_t)(s == ends),
                      "step %d: %zu colliding, %zu began, %zu ended", s, nc, nb, ne);
        const noctSweepHit *hits;
        size_t nh;
        ck_assert_int_eq(noctWorldBeganHits(w, &hits, &nh, &err), NOCT_OK);
        ck_assert_uint_eq(nh, nb);
        if (nb == 1) {
            noctWorldBegan(w, &p);
            ck_assert_uint_eq(p[0].a.index, 0);
            ck_assert_uint_eq(p[0].b.index, 1);
            expect_time(hits[0].time, t);
            ck_assert(hits[0].feature == NOCT_SWEEP_VERTEX_FACE ||
                      hits[0].feature == NOCT_SWEEP_FACE_VERTEX ||
                      hits[0].feature == NOCT_SWEEP_EDGE_EDGE);
        }
    }
}

START_TEST(keyframed_cube_through_a_wall)
{
    /* the cube's face at -2.5 + 6 t meets the wall's at -fl(0.05) */
    const long double t = (2.5L - (long double)0.05) / 6;
    for (int level = 0; level < 2; ++level) {
        noctScene *sc = read_scene(TUNNEL_SCENE);
        ck_assert_int_eq(noctSceneSteps(sc), 4);
        if (level == 1)
            noctSceneDef(sc)->accuracy = NOCT_ACCURACY_EXACT;
        noctWorld *w;
        noctError err;
        ck_assert_msg(noctSceneBuild(sc, &w, &err) == NOCT_OK, "%s", err.message);
        if (level == 0)
            expect_tunnel(w, 4, 2, 3, t);
        else
            expect_tunnel(w, 4, 0, 0, 0); /* the exact level sees nothing */
        noctWorldDestroy(w);
        noctSceneDestroy(sc);
    }
}
END_TEST

/* The began hits asked for after a removal: the pair whose object went
 * gets no hit, and nothing fails. */
START_TEST(hits_after_a_removal)
{
    noctScene *sc = read_scene(TUNNEL_SCENE);
    noctWorld *w;
    noctError err;
    ck_assert_msg(noctSceneBuild(sc, &w, &err) == NOCT_OK, "%s", err.message);
    for (int s = 0; s < 2; ++s)
        ck_assert_msg(noctWorldStep(w, &err) == NOCT_OK, "%s", err.message);
    const noctPair *p;
    ck_assert_uint_eq(noctWorldBegan(w, &p), 1);
    const noctPair began = p[0];
    ck_assert_int_eq(noctWorldRemove(w, began.b, NULL), NOCT_OK);
    const noctSweepHit *hits;
    size_t n;
    ck_assert_int_eq(noctWorldBeganHits(w, &hits, &n, NULL), NOCT_OK);
    ck_assert_uint_eq(n, 1);
    ck_assert_int_eq(hits[0].feature, NOCT_SWEEP_NONE);
    ck_assert_msg(noctWorldStep(w, &err) == NOCT_OK, "%s", err.message);
    noctWorldDestroy(w);
    noctSceneDestroy(sc);
}
END_TEST

/* A world of a static thin plate (object 0) and another object (1). */
static noctWorld *plate_world(noctAccuracy level, const noctMesh *plate, const noctMesh *other,
                              const double p[3], noctObjectType type, const double v[3],
                              noctObjectId *id)
{
    noctWorldDef wd = noctDefaultWorldDef();
    wd.accuracy = level;
    wd.effects = NOCT_EFFECT_MOTION | NOCT_EFFECT_EVENTS; /* no response: it would turn
                                                              the bullet back through */
    noctWorld *w;
    ck_assert_int_eq(noctWorldCreate(&wd, &w, NULL), NOCT_OK);
    noctObjectDef d = noctDefaultObjectDef();
    d.mesh = plate;
    d.type = NOCT_OBJECT_STATIC;
    ck_assert_int_eq(noctWorldCreateObject(w, &d, id, NULL), NOCT_OK);
    d.mesh = other;
    d.type = type;
    memcpy(d.transform.p, p, sizeof d.transform.p);
    memcpy(d.velocity, v, sizeof d.velocity);
    ck_assert_int_eq(noctWorldCreateObject(w, &d, id, NULL), NOCT_OK);
    return w;
}

START_TEST(teleport_through_a_wall)
{
    noctMesh *wall, *cube;
    ck_assert_int_eq(noctMeshCreateBox(0.05, 2, 2, &wall, NULL), NOCT_OK);
    ck_assert_int_eq(noctMeshCreateBox(0.5, 0.5, 0.5, &cube, NULL), NOCT_OK);
    const long double t = (2.5L - (long double)0.05) / 6;
    for (int level = 0; level < 2; ++level) {
        noctObjectId id;
        noctWorld *w = plate_world(level ? NOCT_ACCURACY_EXACT : NOCT_ACCURACY_CONTINUOUS,
                                   wall, cube, (double[3]){-3, 0.25, 0},
                                   NOCT_OBJECT_KINEMATIC, (double[3]){0, 0, 0}, &id);
        ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
        const noctPair *p;
        ck_assert_uint_eq(noctWorldColliding(w, &p), 0);
        /* between steps, from -3 to 3: through the wall */
        noctTransform x = noctIdentityTransform();
        x.p[0] = 3;
        x.p[1] = 0.25;
        ck_assert_int_eq(noctWorldSetTransform(w, id, &x, NULL), NOCT_OK);
        expect_tunnel(w, 3, level ? 0 : 1, level ? 0 : 2, t);
        noctWorldDestroy(w);
    }
    noctMeshDestroy(wall);
    noctMeshDestroy(cube);
}
END_TEST

START_TEST(bullet_through_a_plate)
{
    noctMesh *plate, *bullet;
    ck_assert_int_eq(noctMeshCreateBox(0.01, 1, 1, &plate, NULL), NOCT_OK);
    ck_assert_int_eq(noctMeshCreateBox(0.0005, 0.0005, 0.0005, &bullet, NULL), NOCT_OK);
    /* 1e-3 wide, 1e3 a step, from x = -500 to 500; its face, placed at
     * fl(-500 + 0.0005), then at that + 1000 t, meets the plate's at -0.01 */
    volatile double face = -500.0 + 0.0005;
    const long double t = (-(long double)0.01 - (long double)face) / 1000;
    for (int level = 0; level < 2; ++level) {
        noctObjectId id;
        noctWorld *w = plate_world(level ? NOCT_ACCURACY_EXACT : NOCT_ACCURACY_CONTINUOUS,
                                   plate, bullet, (double[3]){-500, 0.3, -0.2},
                                   NOCT_OBJECT_MOVING, (double[3]){1e3, 0, 0}, &id);
        expect_tunnel(w, 3, level ? 0 : 1, level ? 0 : 2, t);
        noctWorldDestroy(w);
    }
    /* the same bullet at rest for a step, then fired: its velocity set
     * between steps (so it is both placed and a mover, as in its first
     * step above; the began hit once took it as not moving) */
    noctObjectId id;
    noctWorld *w = plate_world(NOCT_ACCURACY_CONTINUOUS, plate, bullet,
                               (double[3]){-500, 0.3, -0.2}, NOCT_OBJECT_MOVING,
                               (double[3]){0, 0, 0}, &id);
    expect_tunnel(w, 1, 0, 0, 0);
    ck_assert_int_eq(noctWorldSetVelocity(w, id, (double[3]){1e3, 0, 0}, NULL), NOCT_OK);
    expect_tunnel(w, 2, 1, 2, t);
    noctWorldDestroy(w);
    noctMeshDestroy(plate);
    noctMeshDestroy(bullet);
}
END_TEST

/* ---- the discrete levels -------------------------------------------------------- */

static void expect_same_lists(const char *what, int step, const noctPair *a, size_t na,
                              const noctPair *b, size_t nb)
{
    ck_assert_msg(na == nb, "%s, step %d: %zu pairs against %zu", what, step, na, nb);
    for (size_t i = 0; i < na; ++i)
        EXPECT(same_pair(a[i], b[i]));
}

/* Families without motion: the continuous level's lists, events and
 * hits (all at the start) are the exact level's. */
START_TEST(static_families_as_exact)
{
    static const char *const families[] = {"gas:400", "clusters:300", "mixed:300",
                                           "static:400"};
    for (size_t f = 0; f < sizeof families / sizeof *families; ++f) {
        noctWorld *w[2];
        noctScene *sc[2];
        for (int l = 0; l < 2; ++l) {
            ck_assert_int_eq(noctSceneFamily(families[f], &sc[l], NULL), NOCT_OK);
            noctWorldDef *def = noctSceneDef(sc[l]);
            def->accuracy = l ? NOCT_ACCURACY_CONTINUOUS : NOCT_ACCURACY_EXACT;
            def->effects = (def->effects & ~(unsigned)NOCT_EFFECT_MOTION) | NOCT_EFFECT_EVENTS;
            noctError err;
            ck_assert_msg(noctSceneBuild(sc[l], &w[l], &err) == NOCT_OK, "%s", err.message);
        }
        size_t seen = 0;
        for (int s = 1; s <= 3; ++s) {
            const noctPair *a, *b;
            size_t na, nb;
            for (int l = 0; l < 2; ++l)
                ck_assert_int_eq(noctWorldStep(w[l], NULL), NOCT_OK);
            na = noctWorldColliding(w[0], &a);
            nb = noctWorldColliding(w[1], &b);
            expect_same_lists(families[f], s, a, na, b, nb);
            seen += na;
            na = noctWorldSensing(w[0], &a);
            nb = noctWorldSensing(w[1], &b);
            expect_same_lists(families[f], s, a, na, b, nb);
            na = noctWorldBegan(w[0], &a);
            nb = noctWorldBegan(w[1], &b);
            expect_same_lists(families[f], s, a, na, b, nb);
            ck_assert_uint_eq(nb, s == 1 ? seen : 0);
            const noctSweepHit *hits;
            size_t nh;
            ck_assert_int_eq(noctWorldBeganHits(w[1], &hits, &nh, NULL), NOCT_OK);
            ck_assert_uint_eq(nh, nb);
            for (size_t i = 0; i < nh; ++i)
                EXPECT(hits[i].feature == NOCT_SWEEP_START && hits[i].time == 0);
            /* a discrete world has no hits */
            ck_assert_int_eq(noctWorldBeganHits(w[0], &hits, &nh, NULL), NOCT_OK);
            ck_assert_ptr_null(hits);
            ck_assert_uint_eq(nh, 0);
        }
        ck_assert_msg(seen > 0, "%s: no pairs", families[f]);
        for (int l = 0; l < 2; ++l) {
            noctWorldDestroy(w[l]);
            noctSceneDestroy(sc[l]);
        }
    }
}
END_TEST

/* Families in motion, without response (so both worlds move alike): the
 * pairs colliding at the end of a step are among the swept ones. */
START_TEST(moving_families_contain_exact)
{
    /* objects turned but not turning */
    static const char *const families[] = {"gas:300", "escape:200", "clusters:200"};
    for (size_t f = 0; f < sizeof families / sizeof *families; ++f) {
        noctWorld *w[2];
        noctScene *sc[2];
        for (int l = 0; l < 2; ++l) {
            ck_assert_int_eq(noctSceneFamily(families[f], &sc[l], NULL), NOCT_OK);
            noctWorldDef *def = noctSceneDef(sc[l]);
            def->accuracy = l ? NOCT_ACCURACY_CONTINUOUS : NOCT_ACCURACY_EXACT;
            def->effects = (def->effects & ~(unsigned)NOCT_EFFECT_RESPONSE) |
                           NOCT_EFFECT_EVENTS;
            ck_assert_int_eq(noctSceneBuild(sc[l], &w[l], NULL), NOCT_OK);
        }
        for (int s = 1; s <= 30; ++s) {
            const noctPair *a, *b;
            for (int l = 0; l < 2; ++l)
                ck_assert_int_eq(noctWorldStep(w[l], NULL), NOCT_OK);
            const size_t na = noctWorldColliding(w[0], &a);
            const size_t nb = noctWorldColliding(w[1], &b);
            size_t j = 0;
            for (size_t i = 0; i < na; ++i) {
                while (j < nb && cmp_pair(&b[j], &a[i]) < 0)
                    ++j;
                ck_assert_msg(j < nb && same_pair(a[i], b[j]),
                              "%s, step %d: exact pair (%u, %u) not swept", families[f], s,
                              a[i].a.index, a[i].b.index);
            }
        }
        for (int l = 0; l < 2; ++l) {
            noctWorldDestroy(w[l]);
            noctSceneDestroy(sc[l]);
        }
    }
}
END_TEST

/* Turning objects go through the conservative level (check-turning
 * tests it): here, that a scene of turning arms steps without failing. */
START_TEST(spinning_does_not_fail)
{
    noctScene *sc;
    ck_assert_int_eq(noctSceneFamily("arms:3", &sc, NULL), NOCT_OK);
    noctSceneDef(sc)->accuracy = NOCT_ACCURACY_CONTINUOUS;
    noctWorld *w;
    ck_assert_int_eq(noctSceneBuild(sc, &w, NULL), NOCT_OK);
    noctError err;
    for (int s = 0; s < 60; ++s) {
        ck_assert_msg(noctWorldStep(w, &err) == NOCT_OK, "%s", err.message);
        const noctSweepHit *hits;
        size_t nh;
        ck_assert_int_eq(noctWorldBeganHits(w, &hits, &nh, NULL), NOCT_OK);
    }
    ck_assert_msg(noctWorldValidate(w, &err) == NOCT_OK, "%s", err.message);
    noctWorldDestroy(w);
    noctSceneDestroy(sc);
}
END_TEST

/* ---- allocations failing --------------------------------------------------------- */

/* What a step of the reference run gave. */
typedef struct outcome {
    plist colliding, began, ended, sensing;
    noctSweepHit hits[256];
    size_t nhits;
} outcome;

/* A small world of fast objects; seeded, so each build is the same. */
static harness *alloc_harness(void)
{
    harness *h = malloc(sizeof *h);
    ck_assert_ptr_nonnull(h);
    harness_init(h, 4242, 40, true, true);
    return h;
}

/* The changes before step s (1 to 4): made without the test's rng, so
 * every run makes the same ones. */
static void scripted_changes(harness *h, int s)
{
    if (s == 2) {
        noctTransform x;
        ck_assert_int_eq(noctWorldGetTransform(h->w, h->o[0].id, &x), NOCT_OK);
        x.p[0] += 7;
        ck_assert_int_eq(noctWorldSetTransform(h->w, h->o[0].id, &x, NULL), NOCT_OK);
        ck_assert_int_eq(noctWorldSetVelocity(h->w, h->o[1].id, (double[3]){5, -4, 3}, NULL),
                         NOCT_OK);
    }
    if (s == 3) {
        remove_object(h, 2);
        h->rng = 99; /* the re-created object the same every run */
        add_object(h, 2);
        ck_assert_int_eq(noctWorldSetType(h->w, h->o[3].id, NOCT_OBJECT_STATIC, NULL),
                         NOCT_OK);
    }
    if (s == 4) {
        h->rng = 7;
        random_track(h, 4);
    }
}

static void record(noctWorld *w, outcome *o)
{
    const noctPair *p;
    size_t n = noctWorldColliding(w, &p);
    plist_copy(&o->colliding, p, n);
    n = noctWorldBegan(w, &p);
    plist_copy(&o->began, p, n);
    n = noctWorldEnded(w, &p);
    plist_copy(&o->ended, p, n);
    n = noctWorldSensing(w, &p);
    plist_copy(&o->sensing, p, n);
}

static void free_outcome(outcome *o)
{
    free(o->colliding.p);
    free(o->began.p);
    free(o->ended.p);
    free(o->sensing.p);
}

static void expect_outcome(noctWorld *w, const outcome *o, int s, unsigned long k)
{
    const noctPair *p;
    size_t n = noctWorldColliding(w, &p);
    if (!(n == o->colliding.n && (n == 0 || memcmp(p, o->colliding.p, n * sizeof *p) == 0)))
        ck_abort_msg("step %d, allocation %lu failing: colliding list differs", s, k);
    n = noctWorldBegan(w, &p);
    if (!(n == o->began.n && (n == 0 || memcmp(p, o->began.p, n * sizeof *p) == 0)))
        ck_abort_msg("step %d, allocation %lu failing: began list differs", s, k);
    n = noctWorldEnded(w, &p);
    if (!(n == o->ended.n && (n == 0 || memcmp(p, o->ended.p, n * sizeof *p) == 0)))
        ck_abort_msg("step %d, allocation %lu failing: ended list differs", s, k);
    n = noctWorldSensing(w, &p);
    if (!(n == o->sensing.n && (n == 0 || memcmp(p, o->sensing.p, n * sizeof *p) == 0)))
        ck_abort_msg("step %d, allocation %lu failing: sensing list differs", s, k);
}

#define ALLOC_STEPS 4

START_TEST(allocations_failing)
{
    const char *why = alloc_unavailable();
    if (why != NULL) {
        fprintf(stderr, "check-continuous: %s: allocation failure tests skipped\n", why);
        return;
    }
    /* the reference run, without failures */
    static outcome ref[ALLOC_STEPS + 1];
    memset(ref, 0, sizeof ref);
    harness *h = alloc_harness();
    for (int s = 1; s <= ALLOC_STEPS; ++s) {
        scripted_changes(h, s);
        ck_assert_int_eq(noctWorldStep(h->w, NULL), NOCT_OK);
        record(h->w, &ref[s]);
        const noctSweepHit *hits;
        ck_assert_int_eq(noctWorldBeganHits(h->w, &hits, &ref[s].nhits, NULL), NOCT_OK);
        ck_assert_uint_le(ref[s].nhits, 256);
        if (ref[s].nhits > 0)
            memcpy(ref[s].hits, hits, ref[s].nhits * sizeof *hits);
    }
    harness_free(h);
    free(h);
    /* positions and velocities before a failing step, and after */
    static double pos[2][MAXN][3], vel[2][MAXN][3];
    static outcome before; /* its lists' room made outside the runs */
    plist_reserve(&before.colliding, 4096);
    plist_reserve(&before.began, 4096);
    plist_reserve(&before.ended, 4096);
    plist_reserve(&before.sensing, 4096);
    unsigned long failed_steps = 0, failed_hits = 0;
    for (int s = 1; s <= ALLOC_STEPS; ++s)
        for (int phase = 0; phase < 2; ++phase) /* the step, then the hits */
            for (unsigned long k = 1;; ++k) {
                void *callers[4];
                alloc_begin(&(alloc_plan){.fail_at = k, .track = true});
                alloc_pause();
                h = alloc_harness();
                for (int r = 1; r < s; ++r) {
                    scripted_changes(h, r);
                    EXPECT(noctWorldStep(h->w, NULL) == NOCT_OK);
                }
                scripted_changes(h, s);
                record(h->w, &before);
                for (int i = 0; i < h->n; ++i)
                    if (h->o[i].alive) {
                        EXPECT(noctWorldObject(h->w, h->o[i].id, pos[0][i], NULL) == NOCT_OK);
                        EXPECT(noctWorldGetVelocity(h->w, h->o[i].id, vel[0][i]) == NOCT_OK);
                    }
                const uint64_t tick = noctWorldTick(h->w);
                noctError err;
                if (phase == 0)
                    alloc_resume();
                noctStatus st = noctWorldStep(h->w, &err);
                if (phase == 0)
                    alloc_pause();
                bool failed = alloc_failures() > 0;
                if (st != NOCT_OK) {
                    /* as before the step, the events empty */
                    if (!(st == NOCT_ERR_NOMEM && failed))
                        ck_abort_msg("step %d, allocation %lu failing: %s (%s)", s, k,
                                     noctStatusString(st), err.message);
                    ++failed_steps;
                    const noctPair *p;
                    EXPECT(noctWorldTick(h->w) == tick);
                    size_t n = noctWorldColliding(h->w, &p);
                    EXPECT(n == before.colliding.n &&
                           (n == 0 || memcmp(p, before.colliding.p, n * sizeof *p) == 0));
                    n = noctWorldSensing(h->w, &p);
                    EXPECT(n == before.sensing.n &&
                           (n == 0 || memcmp(p, before.sensing.p, n * sizeof *p) == 0));
                    EXPECT(noctWorldBegan(h->w, &p) == 0 && noctWorldEnded(h->w, &p) == 0);
                    for (int i = 0; i < h->n; ++i)
                        if (h->o[i].alive) {
                            EXPECT(noctWorldObject(h->w, h->o[i].id, pos[1][i], NULL) ==
                                   NOCT_OK);
                            EXPECT(noctWorldGetVelocity(h->w, h->o[i].id, vel[1][i]) ==
                                   NOCT_OK);
                            EXPECT(memcmp(pos[0][i], pos[1][i], sizeof pos[0][i]) == 0);
                            EXPECT(memcmp(vel[0][i], vel[1][i], sizeof vel[0][i]) == 0);
                        }
                    EXPECT(noctWorldValidate(h->w, NULL) == NOCT_OK);
                    /* retried, it gives what the reference step gave */
                    st = noctWorldStep(h->w, &err);
                    EXPECT(st == NOCT_OK);
                }
                expect_outcome(h->w, &ref[s], s, k);
                const noctSweepHit *hits;
                size_t nh = 0;
                if (phase == 1)
                    alloc_resume();
                st = noctWorldBeganHits(h->w, &hits, &nh, &err);
                if (phase == 1) {
                    alloc_pause();
                    failed = alloc_failures() > 0;
                }
                if (st != NOCT_OK) {
                    EXPECT(st == NOCT_ERR_NOMEM && failed && nh == 0);
                    ++failed_hits;
                    st = noctWorldBeganHits(h->w, &hits, &nh, &err);
                    EXPECT(st == NOCT_OK);
                }
                EXPECT(nh == ref[s].nhits);
                for (size_t i = 0; i < nh; ++i)
                    EXPECT(same_hit(&hits[i], &ref[s].hits[i]));
                EXPECT(noctWorldValidate(h->w, NULL) == NOCT_OK);
                /* the world goes on as the reference's */
                if (s < ALLOC_STEPS) {
                    scripted_changes(h, s + 1);
                    EXPECT(noctWorldStep(h->w, NULL) == NOCT_OK);
                    expect_outcome(h->w, &ref[s + 1], s + 1, k);
                }
                harness_free(h);
                free(h);
                alloc_resume();
                alloc_end();
                const size_t live = alloc_live(callers, 4);
                ck_assert_msg(live == 0 && !alloc_live_overflowed(),
                              "step %d, allocation %lu failing: %zu blocks leaked", s, k,
                              live);
                if (!failed)
                    break; /* fewer than k allocations: all were tried */
            }
    free_outcome(&before);
    for (int s = 1; s <= ALLOC_STEPS; ++s)
        free_outcome(&ref[s]);
    /* the first steps allocate (arrays sized, the grown boxes' scratch) */
    ck_assert_uint_gt(failed_steps, 0);
    ck_assert_uint_gt(failed_hits, 0);
}
END_TEST

/* ---- the suite ------------------------------------------------------------------- */

int main(void)
{
    alloc_unavailable(); /* sets the allocator up, before any run */
    Suite *s = suite_create("continuous");
    TCase *tc = test_case(s, "random worlds", 120, NULL);
    tcase_add_loop_test(tc, random_worlds_against_brute_force, 0, 4);
    tc = test_case(s, "random worlds, long", 600, "slow seeds");
    tcase_add_loop_test(tc, random_worlds_long, 0, 4);
    tc = test_case(s, "tunnelling", 0, NULL);
    add_tests(tc, keyframed_cube_through_a_wall, teleport_through_a_wall, bullet_through_a_plate,
              hits_after_a_removal);
    tc = test_case(s, "discrete levels", 120, NULL);
    add_tests(tc, static_families_as_exact, moving_families_contain_exact,
              spinning_does_not_fail);
    tc = test_case(s, "out of memory", 300, NULL);
    add_tests(tc, allocations_failing);
    return run_suite(s);
}
