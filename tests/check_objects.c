/* SPDX-License-Identifier: MIT */
/*
 * A world that programs drive (world.h, transform.h): quaternions and
 * their matrices against the rotations they name; rotations by multiples
 * of 90 degrees moving hard cases exactly; random rotated scenes of boxes
 * and non-convex meshes, static, kinematic (driven by set-transform) and
 * moving, with filters, teleports, type and velocity changes, removals and
 * additions, checked after every step against a brute force of exact tests
 * on the placed shapes, the events against the brute force's differences,
 * and the motion and response against the test's own run of them; events
 * that follow every change; bad input changing nothing.
 */
#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <noctree/mesh.h>
#include <noctree/narrowphase.h>
#include <noctree/query.h>
#include <noctree/transform.h>
#include <noctree/world.h>

#include "testutil.h"

static uint64_t rng;
static double uniform(void)
{
    return test_uniform(&rng);
}

/* ---- meshes ------------------------------------------------------------------ */

static noctMesh *make_box(double hx, double hy, double hz)
{
    noctMesh *m;
    ck_assert_int_eq(noctMeshCreateBox(hx, hy, hz, &m, NULL), NOCT_OK);
    return m;
}

/* A world with the default parameters but these effects. */
static noctWorld *world_with(unsigned effects)
{
    noctWorldDef wd = noctDefaultWorldDef();
    wd.effects = effects;
    noctWorld *w;
    ck_assert_int_eq(noctWorldCreate(&wd, &w, NULL), NOCT_OK);
    return w;
}

/* ---- rotations ------------------------------------------------------------------ */

static void mat_vec(const double R[9], const double v[3], double out[3])
{
    for (int i = 0; i < 3; ++i)
        out[i] = R[3 * i] * v[0] + R[3 * i + 1] * v[1] + R[3 * i + 2] * v[2];
}

/* Rodrigues' formula, the test's own: the matrix of the rotation by a
 * radians about unit axis u. */
static void rodrigues(const double u[3], double a, double R[9])
{
    const double c = cos(a), s = sin(a), t = 1 - c;
    R[0] = t * u[0] * u[0] + c;
    R[1] = t * u[0] * u[1] - s * u[2];
    R[2] = t * u[0] * u[2] + s * u[1];
    R[3] = t * u[0] * u[1] + s * u[2];
    R[4] = t * u[1] * u[1] + c;
    R[5] = t * u[1] * u[2] - s * u[0];
    R[6] = t * u[0] * u[2] - s * u[1];
    R[7] = t * u[1] * u[2] + s * u[0];
    R[8] = t * u[2] * u[2] + c;
}

START_TEST(quaternions_and_matrices)
{
    double R[9], E[9];
    noctError err;
    const noctQuat one = {0, 0, 0, 1};
    ck_assert_int_eq(noctQuatToMatrix(&one, R, &err), NOCT_OK);
    for (int i = 0; i < 9; ++i)
        ck_assert(R[i] == (i % 4 == 0 ? 1.0 : 0.0));
    /* every quarter turn about each axis: exactly 0, 1 and -1, and the
     * rotation that the axis and angle name */
    for (int axis = 0; axis < 3; ++axis)
        for (int quarter = -4; quarter <= 8; ++quarter) {
            double u[3] = {0, 0, 0};
            u[axis] = 1;
            noctQuat q;
            ck_assert_int_eq(noctQuatFromAxisAngle(u, 90.0 * quarter, &q), NOCT_OK);
            ck_assert_int_eq(noctQuatToMatrix(&q, R, &err), NOCT_OK);
            rodrigues(u, quarter * (3.14159265358979323846 / 2), E);
            for (int i = 0; i < 9; ++i) {
                ck_assert_msg(R[i] == 0 || R[i] == 1 || R[i] == -1,
                              "axis %d, %d quarters: entry %d is %.17g", axis, quarter, i, R[i]);
                ck_assert_msg(R[i] == round(E[i]), "axis %d, %d quarters: entry %d", axis,
                              quarter, i);
            }
        }
    /* random quaternions: the matrix is Rodrigues' within rounding, the
     * same twice, and a near-unit quaternion is normalised */
    rng = 77;
    for (int n = 0; n < 200; ++n) {
        double u[3] = {uniform() - 0.5, uniform() - 0.5, uniform() - 0.5};
        const double l = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        for (int k = 0; k < 3; ++k)
            u[k] /= l;
        const double deg = 720 * uniform() - 360;
        noctQuat q;
        ck_assert_int_eq(noctQuatFromAxisAngle(u, deg, &q), NOCT_OK);
        ck_assert_int_eq(noctQuatToMatrix(&q, R, &err), NOCT_OK);
        rodrigues(u, deg * (3.14159265358979323846 / 180), E);
        for (int i = 0; i < 9; ++i)
            ck_assert_msg(fabs(R[i] - E[i]) < 1e-14, "entry %d: %.17g against %.17g", i, R[i],
                          E[i]);
        double R2[9];
        const noctQuat scaled = {q.x * (1 + 3e-7), q.y * (1 + 3e-7), q.z * (1 + 3e-7),
                                 q.w * (1 + 3e-7)};
        ck_assert_int_eq(noctQuatToMatrix(&scaled, R2, &err), NOCT_OK);
        for (int i = 0; i < 9; ++i)
            ck_assert(fabs(R2[i] - E[i]) < 1e-14);
        double R3[9];
        ck_assert_int_eq(noctQuatToMatrix(&scaled, R3, &err), NOCT_OK);
        ck_assert(memcmp(R2, R3, sizeof R2) == 0);
        /* q and -q: the same rotation */
        const noctQuat neg = {-q.x, -q.y, -q.z, -q.w};
        ck_assert_int_eq(noctQuatToMatrix(&neg, R3, &err), NOCT_OK);
        ck_assert(memcmp(R, R3, sizeof R) == 0);
    }
    /* bad quaternions */
    const noctQuat nan = {NAN, 0, 0, 1}, inf = {0, INFINITY, 0, 0}, big = {0, 0, 0, 1.001},
                   zero = {0, 0, 0, 0};
    ck_assert_int_eq(noctQuatToMatrix(&nan, R, &err), NOCT_ERR_NONFINITE);
    ck_assert(R[0] == 1 && R[1] == 0); /* the identity */
    ck_assert_int_eq(noctQuatToMatrix(&inf, R, &err), NOCT_ERR_NONFINITE);
    ck_assert_int_eq(noctQuatToMatrix(&big, R, &err), NOCT_ERR_INVALID);
    ck_assert_msg(strstr(err.message, "squared length") != NULL, "%s", err.message);
    ck_assert_int_eq(noctQuatToMatrix(&zero, R, &err), NOCT_ERR_INVALID);
    const double zaxis[3] = {0, 0, 0}, nanaxis[3] = {NAN, 0, 1}, x[3] = {1, 0, 0};
    noctQuat q;
    ck_assert_int_eq(noctQuatFromAxisAngle(zaxis, 90, &q), NOCT_ERR_INVALID);
    ck_assert_int_eq(noctQuatFromAxisAngle(nanaxis, 90, &q), NOCT_ERR_NONFINITE);
    ck_assert_int_eq(noctQuatFromAxisAngle(x, INFINITY, &q), NOCT_ERR_NONFINITE);
    ck_assert(q.w == 1 && q.x == 0);
}
END_TEST

/* ---- rotation exactness ----------------------------------------------------- */

/* Hard cases: two meshes and B's offset from A, touching or a hair apart. */
typedef struct hard_case {
    int a, b;         /* 0: unit cube, 1: the L, 2: a flat box */
    double t[3];      /* B's translation (A's is 0) */
} hard_case;

#define HAIR 0x1p-40
static const hard_case HARD[] = {
    {0, 0, {1, 0, 0}},                 /* faces touch */
    {0, 0, {1 + HAIR, 0, 0}},          /* a hair apart */
    {0, 0, {1, 1, 0}},                 /* edges touch */
    {0, 0, {1, 1 + HAIR, 0}},
    {0, 0, {1, 1, 1}},                 /* corners touch */
    {0, 0, {1, 1, 1 + HAIR}},
    {0, 0, {1 - HAIR, 0.5, 0.25}},     /* overlapping a hair */
    {1, 0, {0.5, 0.5, 0}},             /* a cube in the L's notch, touching both arms */
    {1, 0, {0.5 + HAIR, 0.5, 0}},      /* still touching one arm */
    {1, 0, {0.5 + HAIR, 0.5 + HAIR, 0}}, /* in the notch, touching neither */
    {1, 1, {1, 1, 0}},                 /* two Ls, one's notch corner on the other's */
    {1, 1, {2, 0, 0}},                 /* side by side, faces touching */
    {1, 1, {2 + HAIR, 0, 0}},
    {2, 0, {0, 0, 0.5 + 0.0625}},      /* a flat box on a cube's top face */
    {2, 0, {0, 0, 0.5 + 0.0625 + HAIR}},
};

static const double *hard_rotation(int r, double R[9], noctQuat *q)
{
    /* r = 0: the identity; 1..9: a, b, c quarter turns about x, y, z; 10,
     * 11: two composed (x then z, y then x), as quaternion products */
    const double axes[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    if (r == 0) {
        *q = (noctQuat){0, 0, 0, 1};
    } else if (r <= 9) {
        ck_assert_int_eq(noctQuatFromAxisAngle(axes[(r - 1) / 3], 90.0 * ((r - 1) % 3 + 1), q),
                         NOCT_OK);
    } else {
        noctQuat p, s;
        ck_assert_int_eq(noctQuatFromAxisAngle(axes[r == 10 ? 0 : 1], 90, &p), NOCT_OK);
        ck_assert_int_eq(noctQuatFromAxisAngle(axes[r == 10 ? 2 : 0], r == 10 ? 90 : 270, &s),
                         NOCT_OK);
        /* s * p: p first */
        *q = (noctQuat){s.w * p.x + s.x * p.w + s.y * p.z - s.z * p.y,
                        s.w * p.y - s.x * p.z + s.y * p.w + s.z * p.x,
                        s.w * p.z + s.x * p.y - s.y * p.x + s.z * p.w,
                        s.w * p.w - s.x * p.x - s.y * p.y - s.z * p.z};
    }
    ck_assert_int_eq(noctQuatToMatrix(q, R, NULL), NOCT_OK);
    return R;
}

/* Add hard-case shape k (HARD's numbering) at x to a world: its mesh, or,
 * for the boxes when primitive, a box primitive of the same corners. */
static void add_hard_object(noctWorld *w, noctMesh *const mesh[3], int k, bool primitive,
                            const noctTransform *x)
{
    static const double HALF[3][3] = {{0.5, 0.5, 0.5}, {0, 0, 0}, {0.75, 0.5, 0.0625}};
    noctObjectDef d = noctDefaultObjectDef();
    d.mesh = mesh[k];
    if (primitive && k != 1) {
        d.mesh = NULL;
        memcpy(d.half_extents, HALF[k], sizeof d.half_extents);
    }
    d.transform = *x;
    noctObjectId id;
    ck_assert_int_eq(noctWorldCreateObject(w, &d, &id, NULL), NOCT_OK);
}

START_TEST(quarter_turns_are_exact)
{
    noctMesh *mesh[3] = {make_box(0.5, 0.5, 0.5), make_ell(), make_box(0.75, 0.5, 0.0625)};
    const size_t ncases = sizeof HARD / sizeof *HARD;
    for (size_t c = 0; c < ncases; ++c) {
        const hard_case *h = &HARD[c];
        const double zero[3] = {0, 0, 0};
        bool want;
        ck_assert_int_eq(noctCollide(mesh[h->a], zero, mesh[h->b], h->t, NOCT_ACCURACY_EXACT,
                                     &want, NULL),
                         NOCT_OK);
        for (int r = 0; r < 12; ++r) {
            double R[9];
            noctQuat q;
            hard_rotation(r, R, &q);
            for (int i = 0; i < 9; ++i)
                ck_assert(R[i] == 0 || R[i] == 1 || R[i] == -1);
            /* the whole case turned about a dyadic point and moved by a
             * dyadic offset: exact */
            const double off[3] = {3.25, -7.5, 1024};
            noctTransform xa = {{off[0], off[1], off[2]}, q}, xb = xa;
            double rt[3];
            mat_vec(R, h->t, rt);
            for (int k = 0; k < 3; ++k)
                xb.p[k] = off[k] + rt[k];
            bool got;
            noctError err;
            ck_assert_msg(noctCollideTransformed(mesh[h->a], &xa, mesh[h->b], &xb,
                                                 NOCT_ACCURACY_EXACT, &got, NULL,
                                                 &err) == NOCT_OK,
                          "%s", err.message);
            ck_assert_msg(got == want, "case %zu, rotation %d: %d, unrotated %d", c, r, got,
                          want);
            /* and in a world */
            noctWorld *w = world_with(NOCT_EFFECT_EVENTS);
            /* the boxes as box primitives in every other rotation */
            add_hard_object(w, mesh, h->a, r % 2 != 0, &xa);
            add_hard_object(w, mesh, h->b, r % 2 != 0, &xb);
            ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
            const noctPair *p;
            ck_assert_msg(noctWorldColliding(w, &p) == (size_t)want,
                          "world: case %zu, rotation %d", c, r);
            ck_assert_int_eq(noctWorldValidate(w, NULL), NOCT_OK);
            noctWorldDestroy(w);
        }
    }
    for (int i = 0; i < 3; ++i)
        noctMeshDestroy(mesh[i]);
}
END_TEST

/* ---- the gas family as box primitives ---------------------------------------- */

static uint64_t gas_state;
static double gas_draw(void) /* noctree-families(7): splitmix64, then 53 bits */
{
    return test_uniform(&gas_state);
}

/* gas is built of box primitives turned by its quaternions: their
 * matrices must be noctree-families(7)'s, bit for bit (the formula, with no
 * normalisation or snapping), and the boxes its boxes. The test draws
 * the scene itself, as noctree-families(7) defines it. */
START_TEST(gas_boxes_are_the_scenes)
{
    const size_t n = 100000;
    noctWorldDef wd = noctDefaultWorldDef();
    noctWorld *w;
    ck_assert_int_eq(noctWorldCreate(&wd, &w, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldAddGas(w, n, NULL), NOCT_OK);
    ck_assert_uint_eq(noctWorldObjectCount(w), n);
    const double pi = 3.141592653589793, lb = noctGasContainerSize(n);
    gas_state = 42;
    for (uint32_t i = 0; i < n; ++i) {
        double half[3], centre[3];
        for (int k = 0; k < 3; ++k)
            half[k] = 0.25 + 0.5 * gas_draw();
        const double u1 = gas_draw(), u2 = gas_draw(), u3 = gas_draw();
        const double x = sqrt(1 - u1) * sin(2 * pi * u2), y = sqrt(1 - u1) * cos(2 * pi * u2);
        const double z = sqrt(u1) * sin(2 * pi * u3), qw = sqrt(u1) * cos(2 * pi * u3);
        const double r[9] = {
            1 - 2 * (y * y + z * z), 2 * (x * y - z * qw), 2 * (x * z + y * qw),
            2 * (x * y + z * qw), 1 - 2 * (x * x + z * z), 2 * (y * z - x * qw),
            2 * (x * z - y * qw), 2 * (y * z + x * qw), 1 - 2 * (x * x + y * y)};
        for (int k = 0; k < 3; ++k)
            centre[k] = lb * gas_draw();
        gas_draw(); /* the direction's two draws */
        gas_draw();
        const noctObjectId id = {i, 1};
        noctTransform t;
        double h[3], R[9];
        ck_assert_int_eq(noctWorldGetTransform(w, id, &t), NOCT_OK);
        ck_assert(memcmp(t.p, centre, sizeof centre) == 0);
        ck_assert_int_eq(noctQuatToMatrix(&t.q, R, NULL), NOCT_OK);
        ck_assert_msg(memcmp(R, r, sizeof R) == 0, "gas box %u: not noctree-families(7)'s matrix", i);
        ck_assert_int_eq(noctWorldGetHalfExtents(w, id, h), NOCT_OK);
        ck_assert(memcmp(h, half, sizeof half) == 0);
    }
    noctWorldDestroy(w);
}
END_TEST

/* ---- random rotated scenes against brute force ---------------------------------- */

#define MAXO 48
#define NMESH 5

typedef struct model {
    noctMesh *mesh[NMESH + MAXO]; /* the shared meshes, then each box
                                     primitive's own, for the brute force */
    double radius[NMESH + MAXO]; /* bounds |v| over the mesh's vertices */
    bool alive[MAXO];
    noctObjectId id[MAXO];
    int mesh_of[MAXO];
    noctTransform x[MAXO];
    double vel[MAXO][3];
    noctQuat spin[MAXO];
    noctObjectType type[MAXO];
    uint64_t cat[MAXO], mask[MAXO];
    bool sensor[MAXO];
    /* the pairs colliding and sensing after the last step */
    int npairs, nsense;
    noctPair pairs[MAXO * MAXO / 2], sense[MAXO * MAXO / 2];
} model;

static uint64_t random_bits(void)
{
    return uniform() < 0.6 ? NOCT_FILTER_ALL : (uint64_t)1 << (int)(3 * uniform());
}

static void random_place(noctTransform *x)
{
    for (int k = 0; k < 3; ++k)
        x->p[k] = 6 * uniform();
    if (uniform() < 0.15)
        x->q = (noctQuat){0, 0, 0, 1};
    else
        test_random_quat(&rng, &x->q);
}

static void add_random(noctWorld *w, model *m, int i)
{
    noctObjectDef d = noctDefaultObjectDef();
    m->mesh_of[i] = (int)(NMESH * uniform());
    d.mesh = m->mesh[m->mesh_of[i]];
    if (uniform() < 0.3) { /* a box primitive, and the test's mesh of it */
        for (int k = 0; k < 3; ++k)
            d.half_extents[k] = 0.1 + 0.6 * uniform();
        d.mesh = NULL;
        m->mesh_of[i] = NMESH + i;
        noctMeshDestroy(m->mesh[NMESH + i]);
        ck_assert_int_eq(noctMeshCreateBox(d.half_extents[0], d.half_extents[1],
                                           d.half_extents[2], &m->mesh[NMESH + i], NULL),
                         NOCT_OK);
        m->radius[NMESH + i] = sqrt(d.half_extents[0] * d.half_extents[0] +
                                    d.half_extents[1] * d.half_extents[1] +
                                    d.half_extents[2] * d.half_extents[2]);
    }
    random_place(&m->x[i]);
    d.transform = m->x[i];
    const double u = uniform();
    m->type[i] = u < 0.2 ? NOCT_OBJECT_STATIC : u < 0.45 ? NOCT_OBJECT_KINEMATIC
                                                         : NOCT_OBJECT_MOVING;
    d.type = m->type[i];
    for (int k = 0; k < 3; ++k)
        m->vel[i][k] = d.velocity[k] = 0.15 * (uniform() - 0.5);
    m->cat[i] = d.category = random_bits();
    m->mask[i] = d.mask = random_bits();
    m->sensor[i] = d.sensor = uniform() < 0.1;
    m->spin[i] = (noctQuat){0, 0, 0, 1};
    if (uniform() < 0.2) { /* a turn of up to 20 degrees a step */
        const double axis[3] = {uniform() - 0.5, uniform() - 0.5, uniform() - 0.5};
        ck_assert_int_eq(noctQuatFromAxisAngle(axis, 20 * uniform(), &m->spin[i]), NOCT_OK);
    }
    d.angular_velocity = m->spin[i];
    d.user_data = &m->alive[i];
    noctError err;
    ck_assert_msg(noctWorldCreateObject(w, &d, &m->id[i], &err) == NOCT_OK, "%s", err.message);
    m->alive[i] = true;
}

static int cmp_pair(const void *x, const void *y)
{
    const noctPair *a = x, *b = y;
    if (a->a.index != b->a.index)
        return a->a.index < b->a.index ? -1 : 1;
    if (a->b.index != b->b.index)
        return a->b.index < b->b.index ? -1 : 1;
    return 0;
}

/* The brute force: every pair of live objects that the filters allow,
 * tested by noctCollideTransformed() on the model's transforms (after a
 * bounding-sphere test of the test's own), by handle, sorted: the pairs
 * of objects that are not sensors in out, those of a sensor and an
 * object that is not one in sense (*nsense of them). */
static int brute_force(const model *m, noctPair *out, noctPair *sense, int *nsense)
{
    int n = 0;
    *nsense = 0;
    for (int i = 0; i < MAXO; ++i)
        for (int j = 0; j < MAXO; ++j) {
            if (!m->alive[i] || !m->alive[j] || m->id[i].index >= m->id[j].index)
                continue;
            if (!(m->cat[i] & m->mask[j]) || !(m->cat[j] & m->mask[i]))
                continue;
            if (m->sensor[i] && m->sensor[j])
                continue;
            double d2 = 0;
            for (int k = 0; k < 3; ++k)
                d2 += (m->x[i].p[k] - m->x[j].p[k]) * (m->x[i].p[k] - m->x[j].p[k]);
            const double r = m->radius[m->mesh_of[i]] + m->radius[m->mesh_of[j]];
            if (d2 > r * r * 1.0001)
                continue;
            bool hit;
            noctError err;
            ck_assert_msg(noctCollideTransformed(m->mesh[m->mesh_of[i]], &m->x[i],
                                                 m->mesh[m->mesh_of[j]], &m->x[j],
                                                 NOCT_ACCURACY_EXACT, &hit, NULL,
                                                 &err) == NOCT_OK,
                          "%s", err.message);
            if (hit && (m->sensor[i] || m->sensor[j]))
                sense[(*nsense)++] = (noctPair){m->id[i], m->id[j]};
            else if (hit)
                out[n++] = (noctPair){m->id[i], m->id[j]};
        }
    qsort(out, (size_t)n, sizeof *out, cmp_pair);
    qsort(sense, (size_t)*nsense, sizeof *sense, cmp_pair);
    return n;
}

static bool same_id(noctObjectId a, noctObjectId b)
{
    return a.index == b.index && a.generation == b.generation;
}

static bool has_pair(const noctPair *l, int n, noctPair p)
{
    for (int i = 0; i < n; ++i)
        if (same_id(l[i].a, p.a) && same_id(l[i].b, p.b))
            return true;
    return false;
}

/* The world's list equals the expected one, in order. */
static void lists_equal(const char *what, const noctPair *got, size_t ngot,
                        const noctPair *want, int nwant, int step)
{
    ck_assert_msg(ngot == (size_t)nwant, "step %d: %zu %s pairs, brute force %d", step, ngot,
                  what, nwant);
    for (int i = 0; i < nwant; ++i)
        ck_assert_msg(same_id(got[i].a, want[i].a) && same_id(got[i].b, want[i].b),
                      "step %d: %s pair %d is (%u, %u), brute force (%u, %u)", step, what, i,
                      got[i].a.index, got[i].b.index, want[i].a.index, want[i].b.index);
}

static int model_of(const model *m, noctObjectId id)
{
    for (int i = 0; i < MAXO; ++i)
        if (m->alive[i] && same_id(m->id[i], id))
            return i;
    return -1;
}

/* Between steps: what a program does to its objects. */
static void drive(noctWorld *w, model *m)
{
    noctError err;
    for (int i = 0; i < MAXO; ++i) {
        if (!m->alive[i])
            continue;
        const double u = uniform();
        if (m->type[i] == NOCT_OBJECT_KINEMATIC) { /* driven every frame */
            for (int k = 0; k < 3; ++k)
                m->x[i].p[k] += 0.1 * (uniform() - 0.5);
            if (uniform() < 0.3)
                test_random_quat(&rng, &m->x[i].q);
            ck_assert_msg(noctWorldSetTransform(w, m->id[i], &m->x[i], &err) == NOCT_OK, "%s",
                          err.message);
        } else if (u < 0.03) { /* a teleport, anywhere */
            random_place(&m->x[i]);
            ck_assert_msg(noctWorldSetTransform(w, m->id[i], &m->x[i], &err) == NOCT_OK, "%s",
                          err.message);
        } else if (u < 0.05) {
            for (int k = 0; k < 3; ++k)
                m->vel[i][k] = 0.15 * (uniform() - 0.5);
            ck_assert_int_eq(noctWorldSetVelocity(w, m->id[i], m->vel[i], &err), NOCT_OK);
        } else if (u < 0.06) {
            m->type[i] = uniform() < 0.5 ? NOCT_OBJECT_MOVING : NOCT_OBJECT_STATIC;
            ck_assert_int_eq(noctWorldSetType(w, m->id[i], m->type[i], &err), NOCT_OK);
        } else if (u < 0.08) {
            m->cat[i] = random_bits();
            m->mask[i] = random_bits();
            ck_assert_int_eq(noctWorldSetFilter(w, m->id[i], m->cat[i], m->mask[i], &err),
                             NOCT_OK);
        } else if (u < 0.09) {
            ck_assert_int_eq(noctWorldRemove(w, m->id[i], &err), NOCT_OK);
            m->alive[i] = false;
        } else if (u < 0.10) {
            m->sensor[i] = !m->sensor[i];
            ck_assert_int_eq(noctWorldSetSensor(w, m->id[i], m->sensor[i], &err), NOCT_OK);
        }
    }
    for (int i = 0; i < MAXO; ++i)
        if (!m->alive[i] && uniform() < 0.3)
            add_random(w, m, i);
}

/* How many pairs the last check_events() found ended. */
static int last_ended;

typedef size_t list_fcn(const noctWorld *, const noctPair **);

/* The world's began and ended lists (from began_fn, ended_fn) against the
 * differences between the brute force's pairs now and before; the began
 * ones into began_out (if not NULL), their number into *nb. */
static void check_events(const noctWorld *w, const char *what, list_fcn *began_fn,
                         list_fcn *ended_fn, const noctPair *now, int n,
                         const noctPair *before, int nbefore, int step, noctPair *began_out,
                         int *nb)
{
    static noctPair began[MAXO * MAXO / 2], ended[MAXO * MAXO / 2];
    int b = 0, e = 0;
    for (int i = 0; i < n; ++i)
        if (!has_pair(before, nbefore, now[i]))
            began[b++] = now[i];
    for (int i = 0; i < nbefore; ++i)
        if (!has_pair(now, n, before[i]))
            ended[e++] = before[i];
    char name[32];
    const noctPair *p;
    snprintf(name, sizeof name, "%s began", what);
    size_t np = began_fn(w, &p);
    lists_equal(name, p, np, began, b, step);
    snprintf(name, sizeof name, "%s ended", what);
    np = ended_fn(w, &p);
    lists_equal(name, p, np, ended, e, step);
    if (began_out != NULL)
        memcpy(began_out, began, (size_t)b * sizeof *began);
    if (nb != NULL)
        *nb = b;
    last_ended = e;
}

START_TEST(rotated_scenes_against_brute_force)
{
    /* _i: 0 motion, events and response; 1 detection only (events, no
     * motion); 2 rebuild maintenance; 3 N = 1 */
    rng = 0x0b1ec7 + (uint64_t)_i;
    static model m;
    memset(&m, 0, sizeof m);
    m.mesh[0] = make_box(0.5, 0.5, 0.5);
    m.mesh[1] = make_ell();
    m.mesh[2] = make_box(0.9, 0.1, 0.3);
    m.mesh[3] = make_box(0.125, 0.125, 0.125);
    m.mesh[4] = make_ell();
    for (int i = 0; i < NMESH; ++i) {
        double lo[3], hi[3];
        noctMeshBounds(m.mesh[i], lo, hi);
        double r = 0;
        for (int k = 0; k < 3; ++k)
            r += fmax(fabs(lo[k]), fabs(hi[k])) * fmax(fabs(lo[k]), fabs(hi[k]));
        m.radius[i] = sqrt(r);
    }
    noctWorldDef wd = noctDefaultWorldDef();
    if (_i == 0)
        wd.effects |= NOCT_EFFECT_SPIN;
    if (_i == 1)
        wd.effects = NOCT_EFFECT_EVENTS;
    if (_i == 2)
        wd.maintenance = NOCT_MAINTAIN_REBUILD;
    wd.N = _i == 3 ? 1 : 4;
    noctWorld *w;
    ck_assert_int_eq(noctWorldCreate(&wd, &w, NULL), NOCT_OK);
    for (int i = 0; i < 30; ++i)
        add_random(w, &m, i);
    const bool motion = (wd.effects & NOCT_EFFECT_MOTION) != 0;
    const bool response = (wd.effects & NOCT_EFFECT_RESPONSE) != 0;
    static noctPair now[MAXO * MAXO / 2], sensing[MAXO * MAXO / 2];
    long total_pairs = 0, total_began = 0, total_ended = 0, total_sensed = 0;
    for (int step = 0; step < 40; ++step) {
        if (step > 0)
            drive(w, &m);
        noctError err;
        ck_assert_msg(noctWorldStep(w, &err) == NOCT_OK, "step %d: %s", step, err.message);
        /* the test's own spin, then motion: q <- w q, p += v */
        if (wd.effects & NOCT_EFFECT_SPIN)
            for (int i = 0; i < MAXO; ++i)
                if (m.alive[i] && m.type[i] == NOCT_OBJECT_MOVING &&
                    !(m.spin[i].x == 0 && m.spin[i].y == 0 && m.spin[i].z == 0 &&
                      m.spin[i].w == 1))
                    m.x[i].q = noctQuatCompose(&m.spin[i], &m.x[i].q);
        if (motion)
            for (int i = 0; i < MAXO; ++i)
                if (m.alive[i] && m.type[i] == NOCT_OBJECT_MOVING)
                    for (int k = 0; k < 3; ++k)
                        m.x[i].p[k] += m.vel[i][k];
        int ns;
        const int n = brute_force(&m, now, sensing, &ns);
        const noctPair *p;
        size_t np = noctWorldColliding(w, &p);
        lists_equal("colliding", p, np, now, n, step);
        np = noctWorldSensing(w, &p);
        lists_equal("sensing", p, np, sensing, ns, step);
        total_sensed += ns;
        check_events(w, "sensor", noctWorldSensorBegan, noctWorldSensorEnded, sensing, ns,
                     m.sense, m.nsense, step, NULL, NULL);
        memcpy(m.sense, sensing, (size_t)ns * sizeof *sensing);
        m.nsense = ns;
        /* events: the brute force's differences */
        static noctPair began[MAXO * MAXO / 2];
        int nb;
        check_events(w, "contact", noctWorldBegan, noctWorldEnded, now, n, m.pairs, m.npairs,
                     step, began, &nb);
        const int ne = last_ended;
        total_pairs += n;
        total_began += nb;
        total_ended += ne;
        memcpy(m.pairs, now, (size_t)n * sizeof *now);
        m.npairs = n;
        /* the response: moving objects in a pair that began turn back */
        if (response) {
            bool turn[MAXO] = {false};
            for (int i = 0; i < nb; ++i) {
                const int a = model_of(&m, began[i].a), b = model_of(&m, began[i].b);
                ck_assert(a >= 0 && b >= 0);
                turn[a] = turn[b] = true;
            }
            for (int i = 0; i < MAXO; ++i)
                if (turn[i] && m.type[i] == NOCT_OBJECT_MOVING)
                    for (int k = 0; k < 3; ++k)
                        m.vel[i][k] = -m.vel[i][k];
        }
        /* the world's objects are the model's */
        for (int i = 0; i < MAXO; ++i) {
            if (!m.alive[i])
                continue;
            noctTransform x;
            double v[3];
            ck_assert_int_eq(noctWorldGetTransform(w, m.id[i], &x), NOCT_OK);
            ck_assert_msg(memcmp(x.p, m.x[i].p, sizeof x.p) == 0, "step %d: object %d moved", step,
                          i);
            ck_assert(memcmp(&x.q, &m.x[i].q, sizeof x.q) == 0);
            ck_assert_int_eq(noctWorldGetVelocity(w, m.id[i], v), NOCT_OK);
            ck_assert_msg(memcmp(v, m.vel[i], sizeof v) == 0, "step %d: object %d's velocity",
                          step, i);
            ck_assert(noctWorldGetUserData(w, m.id[i]) == &m.alive[i]);
            if (m.mesh_of[i] < NMESH) {
                ck_assert(noctWorldGetMesh(w, m.id[i]) == m.mesh[m.mesh_of[i]]);
            } else {
                double half[3], lo[3], hi[3];
                ck_assert(noctWorldGetMesh(w, m.id[i]) == NULL);
                ck_assert_int_eq(noctWorldGetHalfExtents(w, m.id[i], half), NOCT_OK);
                noctMeshBounds(m.mesh[m.mesh_of[i]], lo, hi);
                ck_assert(half[0] == hi[0] && half[1] == hi[1] && half[2] == hi[2]);
            }
            bool sensor;
            ck_assert_int_eq(noctWorldGetSensor(w, m.id[i], &sensor), NOCT_OK);
            ck_assert(sensor == m.sensor[i]);
        }
        ck_assert_msg(noctWorldValidate(w, &err) == NOCT_OK, "step %d: %s", step, err.message);
    }
    /* the scenes are busy enough to mean something */
    ck_assert_int_gt(total_pairs, 200);
    ck_assert_int_gt(total_began, 40);
    ck_assert_int_gt(total_ended, 40);
    ck_assert_int_gt(total_sensed, 10);
    noctWorldDestroy(w);
    for (int i = 0; i < NMESH + MAXO; ++i)
        noctMeshDestroy(m.mesh[i]);
}
END_TEST

/* ---- events that follow every change ------------------------------------------ */

static size_t began_n(noctWorld *w)
{
    const noctPair *p;
    return noctWorldBegan(w, &p);
}

static size_t ended_n(noctWorld *w)
{
    const noctPair *p;
    return noctWorldEnded(w, &p);
}

START_TEST(events_follow_changes)
{
    noctMesh *cube = make_box(0.5, 0.5, 0.5);
    noctWorld *w = world_with(NOCT_EFFECT_EVENTS);
    noctObjectDef d = noctDefaultObjectDef();
    d.mesh = cube;
    d.type = NOCT_OBJECT_KINEMATIC;
    noctObjectId a, b, c, e;
    ck_assert_int_eq(noctWorldCreateObject(w, &d, &a, NULL), NOCT_OK);
    d.transform.p[0] = 5;
    ck_assert_int_eq(noctWorldCreateObject(w, &d, &b, NULL), NOCT_OK);
    d.transform.p[0] = 20;
    ck_assert_int_eq(noctWorldCreateObject(w, &d, &c, NULL), NOCT_OK);
    d.transform.p[0] = 20.5;
    ck_assert_int_eq(noctWorldCreateObject(w, &d, &e, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    ck_assert_uint_eq(began_n(w), 1); /* (c, e) */
    /* a teleport into contact begins */
    noctTransform x = noctIdentityTransform();
    x.p[0] = 1; /* faces touch */
    ck_assert_int_eq(noctWorldSetTransform(w, b, &x, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    const noctPair *p;
    ck_assert_uint_eq(noctWorldBegan(w, &p), 1);
    ck_assert(same_id(p[0].a, a) && same_id(p[0].b, b));
    /* a rotation that turns b away: a 45 degree turn about z of the cube
     * at x = 1.75 reaches to 1.75 - sqrt(1/2) > 1/2 */
    const double zaxis[3] = {0, 0, 1};
    x.p[0] = 1.75;
    ck_assert_int_eq(noctQuatFromAxisAngle(zaxis, 45, &x.q), NOCT_OK);
    ck_assert_int_eq(noctWorldSetTransform(w, b, &x, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    ck_assert_uint_eq(noctWorldEnded(w, &p), 1);
    ck_assert(same_id(p[0].a, a) && same_id(p[0].b, b));
    /* ... and a smaller offset turned brings it back into contact */
    x.p[0] = 1.2;
    ck_assert_int_eq(noctWorldSetTransform(w, b, &x, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    ck_assert_uint_eq(began_n(w), 1);
    /* filtered out: ends; allowed again: begins */
    ck_assert_int_eq(noctWorldSetFilter(w, b, 2, 0, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    ck_assert_uint_eq(ended_n(w), 1);
    ck_assert_uint_eq(began_n(w), 0);
    ck_assert_int_eq(noctWorldSetFilter(w, b, 2, NOCT_FILTER_ALL, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    ck_assert_uint_eq(began_n(w), 1);
    uint64_t cat, mask;
    ck_assert_int_eq(noctWorldGetFilter(w, b, &cat, &mask), NOCT_OK);
    ck_assert(cat == 2 && mask == NOCT_FILTER_ALL);
    /* a step with no change: no events */
    ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    ck_assert_uint_eq(began_n(w) + ended_n(w), 0);
    /* removing c: its pair ends at the next step; removing it clears no
     * other list */
    ck_assert_int_eq(noctWorldSetTransform(w, b, &x, NULL), NOCT_OK); /* no change */
    x = noctIdentityTransform();
    x.p[0] = 5;
    ck_assert_int_eq(noctWorldSetTransform(w, b, &x, NULL), NOCT_OK); /* away */
    ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    ck_assert_uint_eq(ended_n(w), 1);
    ck_assert_int_eq(noctWorldRemove(w, c, NULL), NOCT_OK);
    ck_assert_uint_eq(ended_n(w), 1); /* the last step's, still */
    ck_assert_uint_eq(noctWorldColliding(w, &p), 1);
    ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    ck_assert_uint_eq(noctWorldEnded(w, &p), 1);
    ck_assert(same_id(p[0].a, c) && same_id(p[0].b, e));
    ck_assert_uint_eq(noctWorldColliding(w, &p), 0);
    ck_assert_int_eq(noctWorldValidate(w, NULL), NOCT_OK);
    noctWorldDestroy(w);
    noctMeshDestroy(cube);
}
END_TEST

/* A leaf whose boxes were far apart at its last sweep is skipped while
 * they cannot have closed the gap: a teleport within the leaf, or a turn
 * that grows a box, must still be seen at the next step. */
START_TEST(teleports_within_a_leaf)
{
    noctMesh *cube = make_box(0.5, 0.5, 0.5);
    for (int turn = 0; turn < 2; ++turn) {
        noctWorld *w = world_with(NOCT_EFFECT_EVENTS);
        noctObjectDef d = noctDefaultObjectDef();
        d.mesh = cube;
        d.type = NOCT_OBJECT_KINEMATIC;
        noctObjectId id[3];
        for (int i = 0; i < 3; ++i) {
            d.transform.p[0] = turn && i == 1 ? 1.2 : 3 * i;
            ck_assert_int_eq(noctWorldCreateObject(w, &d, &id[i], NULL), NOCT_OK);
        }
        for (int s = 0; s < 6; ++s) /* the leaf is swept, then skipped */
            ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
        noctWorldCounters c;
        noctWorldGetCounters(w, &c);
        ck_assert_uint_gt(c.leaves_skipped, 0);
        const noctPair *p;
        ck_assert_uint_eq(noctWorldColliding(w, &p), 0);
        noctTransform x = noctIdentityTransform();
        if (turn) { /* at 1.2, a 45 degree turn reaches to 1.2 - 0.707 */
            const double zaxis[3] = {0, 0, 1};
            x.p[0] = 1.2;
            ck_assert_int_eq(noctQuatFromAxisAngle(zaxis, 45, &x.q), NOCT_OK);
        } else {
            x.p[0] = 1;
        }
        ck_assert_int_eq(noctWorldSetTransform(w, id[1], &x, NULL), NOCT_OK);
        ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
        ck_assert_msg(noctWorldColliding(w, &p) == 1, "turn %d: the teleport was missed", turn);
        ck_assert_uint_eq(noctWorldBegan(w, &p), 1);
        noctWorldDestroy(w);
    }
    noctMeshDestroy(cube);
}
END_TEST

/* ---- angular velocity ------------------------------------------------------ */

/* Composition against the matrices: R(a b) = R(a) R(b) within rounding,
 * and composing unit quaternions stays unit length. */
START_TEST(quaternions_compose)
{
    rng = 991;
    for (int n = 0; n < 500; ++n) {
        noctQuat a, b;
        double u[3] = {uniform() - 0.5, uniform() - 0.5, uniform() - 0.5}, v[3];
        ck_assert_int_eq(noctQuatFromAxisAngle(u, 360 * uniform(), &a), NOCT_OK);
        for (int k = 0; k < 3; ++k)
            v[k] = uniform() - 0.5;
        ck_assert_int_eq(noctQuatFromAxisAngle(v, 360 * uniform(), &b), NOCT_OK);
        const noctQuat c = noctQuatCompose(&a, &b);
        double Ra[9], Rb[9], Rc[9];
        ck_assert_int_eq(noctQuatToMatrix(&a, Ra, NULL), NOCT_OK);
        ck_assert_int_eq(noctQuatToMatrix(&b, Rb, NULL), NOCT_OK);
        ck_assert_int_eq(noctQuatToMatrix(&c, Rc, NULL), NOCT_OK);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                double e = 0;
                for (int k = 0; k < 3; ++k)
                    e += Ra[3 * i + k] * Rb[3 * k + j];
                ck_assert_msg(fabs(Rc[3 * i + j] - e) < 1e-14, "entry %d %d", i, j);
            }
    }
    /* a thousand small turns in a row stay a unit quaternion */
    noctQuat q = {0, 0, 0, 1}, w;
    const double axis[3] = {1, 2, 3};
    ck_assert_int_eq(noctQuatFromAxisAngle(axis, 1.7, &w), NOCT_OK);
    for (int n = 0; n < 1000; ++n)
        q = noctQuatCompose(&w, &q);
    const double len = q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w;
    ck_assert_msg(fabs(len - 1) < 1e-14, "squared length %.17g", len);
}
END_TEST

/* A bar turning a quarter turn a step about z: its matrix is exactly the
 * k-th quarter turn, its box alternates, it meets a crate on the x axis
 * every other step (begin, end, ...), and after four steps it is back
 * where it began, bit for bit; an L mesh turning along does the same. */
START_TEST(spin_quarter_turns)
{
    noctMesh *ell = make_ell();
    noctWorld *w = world_with(NOCT_EFFECT_MOTION | NOCT_EFFECT_EVENTS | NOCT_EFFECT_SPIN);
    const double z[3] = {0, 0, 1};
    noctObjectDef d = noctDefaultObjectDef();
    d.half_extents[0] = 1;
    d.half_extents[1] = 0.5;
    d.half_extents[2] = 0.25;
    ck_assert_int_eq(noctQuatFromAxisAngle(z, 90, &d.angular_velocity), NOCT_OK);
    noctObjectId bar, crate, l;
    ck_assert_int_eq(noctWorldCreateObject(w, &d, &bar, NULL), NOCT_OK);
    d.mesh = ell;
    d.transform.p[0] = 10;
    ck_assert_int_eq(noctWorldCreateObject(w, &d, &l, NULL), NOCT_OK);
    d = noctDefaultObjectDef();
    d.type = NOCT_OBJECT_STATIC;
    d.half_extents[0] = d.half_extents[1] = d.half_extents[2] = 0.25;
    d.transform.p[0] = 1.2; /* 0.95 to 1.45: within the bar along x, not along y */
    ck_assert_int_eq(noctWorldCreateObject(w, &d, &crate, NULL), NOCT_OK);
    double lo0[3], hi0[3], llo0[3], lhi0[3];
    ck_assert_int_eq(noctWorldObjectBox(w, bar, lo0, hi0), NOCT_OK);
    ck_assert_int_eq(noctWorldObjectBox(w, l, llo0, lhi0), NOCT_OK);
    const noctPair *p;
    for (int k = 1; k <= 8; ++k) {
        ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
        noctTransform x;
        double R[9], lo[3], hi[3];
        ck_assert_int_eq(noctWorldGetTransform(w, bar, &x), NOCT_OK);
        ck_assert_int_eq(noctQuatToMatrix(&x.q, R, NULL), NOCT_OK);
        const double c[4] = {1, 0, -1, 0}, sn[4] = {0, 1, 0, -1};
        const double want[9] = {c[k % 4], -sn[k % 4], 0, sn[k % 4], c[k % 4], 0, 0, 0, 1};
        for (int i = 0; i < 9; ++i)
            ck_assert_msg(R[i] == want[i], "step %d: entry %d is %.17g", k, i, R[i]);
        ck_assert_int_eq(noctWorldObjectBox(w, bar, lo, hi), NOCT_OK);
        const bool along_x = k % 2 == 0;
        ck_assert(hi[0] == (along_x ? 1 : 0.5) && hi[1] == (along_x ? 0.5 : 1));
        /* the crate: touching every other step */
        ck_assert_uint_eq(noctWorldColliding(w, &p), along_x ? 1 : 0);
        if (k > 1) /* (before step 1 nothing was colliding yet) */
            ck_assert_uint_eq(along_x ? noctWorldBegan(w, &p) : noctWorldEnded(w, &p), 1);
        if (k % 4 == 0) { /* back where they began */
            ck_assert(memcmp(lo, lo0, sizeof lo) == 0 && memcmp(hi, hi0, sizeof hi) == 0);
            ck_assert_int_eq(noctWorldObjectBox(w, l, lo, hi), NOCT_OK);
            ck_assert(memcmp(lo, llo0, sizeof lo) == 0 && memcmp(hi, lhi0, sizeof hi) == 0);
        }
        ck_assert_int_eq(noctWorldValidate(w, NULL), NOCT_OK);
    }
    /* without the effect, the angular velocity is kept and unused */
    noctQuat q;
    ck_assert_int_eq(noctWorldGetAngularVelocity(w, bar, &q), NOCT_OK);
    ck_assert(fabs(q.z - sqrt(0.5)) < 1e-16);
    ck_assert_int_eq(noctWorldGetAngularVelocity(w, crate, &q), NOCT_OK);
    ck_assert(q.x == 0 && q.y == 0 && q.z == 0 && q.w == 1);
    /* bad angular velocities, a status and nothing changed */
    noctError err;
    const noctQuat nan = {NAN, 0, 0, 1}, longer = {0, 0, 0, 1.5};
    ck_assert_int_eq(noctWorldSetAngularVelocity(w, bar, &nan, &err), NOCT_ERR_NONFINITE);
    ck_assert_msg(strstr(err.message, "angular velocity") != NULL, "%s", err.message);
    ck_assert_int_eq(noctWorldSetAngularVelocity(w, bar, &longer, &err), NOCT_ERR_INVALID);
    d = noctDefaultObjectDef();
    d.half_extents[0] = d.half_extents[1] = d.half_extents[2] = 1;
    d.angular_velocity = longer;
    noctObjectId bad;
    ck_assert_int_eq(noctWorldCreateObject(w, &d, &bad, &err), NOCT_ERR_INVALID);
    ck_assert_int_eq(noctWorldGetAngularVelocity(w, bar, &q), NOCT_OK);
    ck_assert(fabs(q.z - sqrt(0.5)) < 1e-16);
    ck_assert_uint_eq(noctWorldObjectCount(w), 3);
    /* a step that fails after the spin gives the turn back */
    d = noctDefaultObjectDef();
    d.half_extents[0] = d.half_extents[1] = d.half_extents[2] = 1;
    d.transform.p[0] = 1e100 - 1e90;
    d.velocity[0] = 1e91; /* beyond the coordinate limit in one step */
    noctObjectId runaway;
    ck_assert_int_eq(noctWorldCreateObject(w, &d, &runaway, NULL), NOCT_OK);
    noctTransform held;
    double hlo[3], hhi[3], lo[3], hi[3];
    ck_assert_int_eq(noctWorldGetTransform(w, bar, &held), NOCT_OK);
    ck_assert_int_eq(noctWorldObjectBox(w, bar, hlo, hhi), NOCT_OK);
    ck_assert_int_eq(noctWorldStep(w, &err), NOCT_ERR_TOO_LARGE);
    noctTransform now;
    ck_assert_int_eq(noctWorldGetTransform(w, bar, &now), NOCT_OK);
    ck_assert(memcmp(&now, &held, sizeof now) == 0);
    ck_assert_int_eq(noctWorldObjectBox(w, bar, lo, hi), NOCT_OK);
    ck_assert(memcmp(lo, hlo, sizeof lo) == 0 && memcmp(hi, hhi, sizeof hi) == 0);
    ck_assert_int_eq(noctWorldValidate(w, &err), NOCT_OK);
    ck_assert_int_eq(noctWorldRemove(w, runaway, &err), NOCT_OK);
    ck_assert_int_eq(noctWorldStep(w, &err), NOCT_OK); /* and now it turns */
    ck_assert_int_eq(noctWorldGetTransform(w, bar, &now), NOCT_OK);
    ck_assert(memcmp(&now.q, &held.q, sizeof now.q) != 0);
    ck_assert_int_eq(noctWorldValidate(w, &err), NOCT_OK);
    /* stopped: it stays where it is */
    const noctQuat none = {0, 0, 0, 1};
    ck_assert_int_eq(noctWorldSetAngularVelocity(w, bar, &none, &err), NOCT_OK);
    noctTransform before, after;
    ck_assert_int_eq(noctWorldGetTransform(w, bar, &before), NOCT_OK);
    ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldGetTransform(w, bar, &after), NOCT_OK);
    ck_assert(memcmp(&before, &after, sizeof before) == 0);
    noctWorldDestroy(w);
    noctMeshDestroy(ell);
}
END_TEST

/* ---- bad input changes nothing ------------------------------------------------- */

/* (a marker for the table below: refused only when turned) */
#define NOCT_ERR_OK_IF_UNTURNED NOCT_STATUS_COUNT

START_TEST(bad_input_changes_nothing)
{
    noctMesh *cube = make_box(0.5, 0.5, 0.5);
    noctWorld *w;
    ck_assert_int_eq(noctWorldCreate(&(noctWorldDef){.N = -1}, &w, NULL), NOCT_ERR_INVALID);
    noctWorldDef wd = noctDefaultWorldDef();
    ck_assert_int_eq(noctWorldCreate(&wd, &w, NULL), NOCT_OK);
    noctObjectDef d = noctDefaultObjectDef();
    d.mesh = cube;
    d.velocity[0] = 0.25;
    noctObjectId a;
    ck_assert_int_eq(noctWorldCreateObject(w, &d, &a, NULL), NOCT_OK);
    noctError err;
    noctObjectId bad;
    noctObjectDef e = d;
    e.transform.q = (noctQuat){NAN, 0, 0, 1};
    ck_assert_int_eq(noctWorldCreateObject(w, &e, &bad, &err), NOCT_ERR_NONFINITE);
    e.transform.q = (noctQuat){0, 0, 0.1, 1};
    ck_assert_int_eq(noctWorldCreateObject(w, &e, &bad, &err), NOCT_ERR_INVALID);
    e = d;
    e.transform.p[1] = INFINITY;
    ck_assert_int_eq(noctWorldCreateObject(w, &e, &bad, &err), NOCT_ERR_NONFINITE);
    e = d;
    e.transform.p[1] = 1e101;
    ck_assert_int_eq(noctWorldCreateObject(w, &e, &bad, &err), NOCT_ERR_TOO_LARGE);
    e = d;
    e.velocity[2] = NAN;
    ck_assert_int_eq(noctWorldCreateObject(w, &e, &bad, &err), NOCT_ERR_NONFINITE);
    ck_assert_msg(strstr(err.message, "velocity") != NULL, "%s", err.message);
    e = d;
    e.category = 0;
    ck_assert_int_eq(noctWorldCreateObject(w, &e, &bad, &err), NOCT_ERR_INVALID);
    e = d;
    e.type = (noctObjectType)7;
    ck_assert_int_eq(noctWorldCreateObject(w, &e, &bad, &err), NOCT_ERR_INVALID);
    /* box primitives: no mesh and no half-extents, or bad ones */
    static const struct {
        double h[3];
        noctStatus st;
    } boxes[] = {
        {{0, 0, 0}, NOCT_ERR_INVALID},         {{NAN, 1, 1}, NOCT_ERR_NONFINITE},
        {{1, INFINITY, 1}, NOCT_ERR_NONFINITE}, {{-1, 1, 1}, NOCT_ERR_INVALID},
        {{1, 1, 1e-310}, NOCT_ERR_INVALID},    {{1, 1, 1e-10}, NOCT_ERR_DEGENERATE},
        {{3e100, 1, 3e100}, NOCT_ERR_TOO_LARGE}, {{1e100, 1e100, 1e100}, NOCT_ERR_OK_IF_UNTURNED},
    };
    for (size_t i = 0; i < sizeof boxes / sizeof *boxes; ++i) {
        e = d;
        e.mesh = NULL;
        memcpy(e.half_extents, boxes[i].h, sizeof e.half_extents);
        /* the last, turned by 45 degrees, puts corners beyond the limit */
        const double z[3] = {0, 0, 1};
        if (boxes[i].st == NOCT_ERR_OK_IF_UNTURNED)
            ck_assert_int_eq(noctQuatFromAxisAngle(z, 45, &e.transform.q), NOCT_OK);
        const noctStatus want =
            boxes[i].st == NOCT_ERR_OK_IF_UNTURNED ? NOCT_ERR_TOO_LARGE : boxes[i].st;
        ck_assert_msg(noctWorldCreateObject(w, &e, &bad, &err) == want, "box %zu: %s", i,
                      err.message);
    }
    ck_assert(bad.index == 0 && bad.generation == 0);
    ck_assert_uint_eq(noctWorldObjectCount(w), 1);
    /* the setters: a status, nothing changed */
    noctTransform x = noctIdentityTransform();
    x.q = (noctQuat){0, 0, 0, 2};
    ck_assert_int_eq(noctWorldSetTransform(w, a, &x, &err), NOCT_ERR_INVALID);
    x.q = (noctQuat){0, INFINITY, 0, 1};
    ck_assert_int_eq(noctWorldSetTransform(w, a, &x, &err), NOCT_ERR_NONFINITE);
    const double nanv[3] = {0, NAN, 0};
    ck_assert_int_eq(noctWorldSetVelocity(w, a, nanv, &err), NOCT_ERR_NONFINITE);
    ck_assert_int_eq(noctWorldSetFilter(w, a, 0, 1, &err), NOCT_ERR_INVALID);
    ck_assert_int_eq(noctWorldSetType(w, a, (noctObjectType)-1, &err), NOCT_ERR_INVALID);
    noctTransform got;
    double v[3];
    noctObjectType t;
    uint64_t cat, mask;
    ck_assert_int_eq(noctWorldGetTransform(w, a, &got), NOCT_OK);
    ck_assert(got.p[0] == 0 && got.p[1] == 0 && got.q.w == 1 && got.q.x == 0);
    ck_assert_int_eq(noctWorldGetVelocity(w, a, v), NOCT_OK);
    ck_assert(v[0] == 0.25 && v[1] == 0 && v[2] == 0);
    ck_assert_int_eq(noctWorldGetType(w, a, &t), NOCT_OK);
    ck_assert_int_eq(t, NOCT_OBJECT_MOVING);
    ck_assert_int_eq(noctWorldGetFilter(w, a, &cat, &mask), NOCT_OK);
    ck_assert(cat == NOCT_FILTER_ALL && mask == NOCT_FILTER_ALL);
    /* stale handles */
    ck_assert_int_eq(noctWorldRemove(w, a, &err), NOCT_OK);
    x = noctIdentityTransform();
    ck_assert_int_eq(noctWorldSetTransform(w, a, &x, &err), NOCT_ERR_INVALID);
    ck_assert_msg(strstr(err.message, "handle") != NULL, "%s", err.message);
    ck_assert_int_eq(noctWorldSetVelocity(w, a, v, &err), NOCT_ERR_INVALID);
    ck_assert_int_eq(noctWorldSetType(w, a, NOCT_OBJECT_STATIC, &err), NOCT_ERR_INVALID);
    ck_assert_int_eq(noctWorldSetFilter(w, a, 1, 1, &err), NOCT_ERR_INVALID);
    ck_assert_int_eq(noctWorldSetUserData(w, a, &err, &err), NOCT_ERR_INVALID);
    ck_assert_int_eq(noctWorldRemove(w, a, &err), NOCT_ERR_INVALID);
    ck_assert_int_eq(noctWorldGetTransform(w, a, &got), NOCT_ERR_INVALID);
    ck_assert_int_eq(noctWorldGetVelocity(w, a, v), NOCT_ERR_INVALID);
    ck_assert_int_eq(noctWorldGetType(w, a, &t), NOCT_ERR_INVALID);
    ck_assert_int_eq(noctWorldGetFilter(w, a, &cat, &mask), NOCT_ERR_INVALID);
    ck_assert(noctWorldGetUserData(w, a) == NULL);
    ck_assert(noctWorldGetMesh(w, a) == NULL);
    ck_assert_int_eq(noctWorldValidate(w, NULL), NOCT_OK);
    /* the narrowphase with transforms */
    bool hit;
    noctTransform y = noctIdentityTransform();
    y.q.w = 0.5;
    ck_assert_int_eq(noctCollideTransformed(cube, &x, cube, &y, NOCT_ACCURACY_EXACT, &hit, NULL,
                                            &err),
                     NOCT_ERR_INVALID);
    y = noctIdentityTransform();
    y.p[2] = NAN;
    ck_assert_int_eq(noctCollideTransformed(cube, &x, cube, &y, NOCT_ACCURACY_EXACT, &hit, NULL,
                                            &err),
                     NOCT_ERR_NONFINITE);
    noctWorldDestroy(w);
    noctMeshDestroy(cube);
}
END_TEST

/* A box primitive whose half-extents the world accepts (finite, at most
 * twice NOCT_MAX_COORDINATE) but whose corners, as turned, lie beyond
 * NOCT_MAX_COORDINATE: no mesh can be made of it (noctMeshCreate() refuses
 * such vertices), yet its exact tests may need one. The world must either
 * refuse the object when it is made or turned, or test it: not fail every
 * step for want of memory that is there. */
START_TEST(box_corners_beyond_the_limit)
{
    const double zaxis[3] = {0, 0, 1};
    for (int turn = 0; turn < 2; ++turn) {
        noctWorld *w = world_with(NOCT_EFFECT_EVENTS);
        noctObjectDef d = noctDefaultObjectDef();
        d.type = NOCT_OBJECT_STATIC;
        /* turn 0: half-extents 1.5e100, corners at 1.5e100; turn 1:
         * half-extents 1e100 turned 45 degrees about z, corners at 1.41e100 */
        const double h = turn ? 1e100 : 1.5e100;
        d.half_extents[0] = d.half_extents[1] = d.half_extents[2] = h;
        if (turn)
            ck_assert_int_eq(noctQuatFromAxisAngle(zaxis, 45, &d.transform.q), NOCT_OK);
        noctObjectId big, small;
        noctError err;
        const noctStatus st = noctWorldCreateObject(w, &d, &big, &err);
        if (st != NOCT_OK) { /* refused: as the mesh would be */
            ck_assert_int_eq(st, NOCT_ERR_TOO_LARGE);
            noctWorldDestroy(w);
            continue;
        }
        /* a unit cube inside it: the step asks for the big box's mesh
         * (its box form decides nothing at this size) */
        d = noctDefaultObjectDef();
        d.half_extents[0] = d.half_extents[1] = d.half_extents[2] = 0.5;
        ck_assert_int_eq(noctWorldCreateObject(w, &d, &small, &err), NOCT_OK);
        for (int s = 0; s < 2; ++s) {
            const noctStatus ss = noctWorldStep(w, &err);
            ck_assert_msg(ss == NOCT_OK, "turn %d, step %d: %s: %s", turn, s,
                          noctStatusString(ss), err.message);
        }
        const noctPair *p;
        ck_assert_uint_eq(noctWorldColliding(w, &p), 1);
        noctWorldDestroy(w);
    }
}
END_TEST

/* A velocity vector is used bit for bit: after k steps the position is
 * the k-fold sum, whatever its length. */
START_TEST(velocity_bit_for_bit)
{
    noctMesh *cube = make_box(0.5, 0.5, 0.5);
    noctWorld *w = world_with(NOCT_EFFECT_MOTION);
    noctObjectDef d = noctDefaultObjectDef();
    d.mesh = cube;
    const double v[3] = {0.1, -1.0 / 3, 1e-7};
    memcpy(d.velocity, v, sizeof v);
    noctObjectId a;
    ck_assert_int_eq(noctWorldCreateObject(w, &d, &a, NULL), NOCT_OK);
    double p[3] = {0, 0, 0};
    for (int s = 0; s < 50; ++s) {
        ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
        for (int k = 0; k < 3; ++k)
            p[k] += v[k];
    }
    noctTransform x;
    ck_assert_int_eq(noctWorldGetTransform(w, a, &x), NOCT_OK);
    ck_assert(memcmp(x.p, p, sizeof p) == 0);
    /* kinematic: the velocity is kept, not used */
    ck_assert_int_eq(noctWorldSetType(w, a, NOCT_OBJECT_KINEMATIC, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldGetTransform(w, a, &x), NOCT_OK);
    ck_assert(memcmp(x.p, p, sizeof p) == 0);
    double got[3];
    ck_assert_int_eq(noctWorldGetVelocity(w, a, got), NOCT_OK);
    ck_assert(memcmp(got, v, sizeof v) == 0);
    ck_assert_int_eq(noctWorldSetType(w, a, NOCT_OBJECT_MOVING, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    for (int k = 0; k < 3; ++k)
        p[k] += v[k];
    ck_assert_int_eq(noctWorldGetTransform(w, a, &x), NOCT_OK);
    ck_assert(memcmp(x.p, p, sizeof p) == 0);
    ck_assert_int_eq(noctWorldValidate(w, NULL), NOCT_OK);
    noctWorldDestroy(w);
    noctMeshDestroy(cube);
}
END_TEST

/* ---- spinning meshes: recycled turned copies are new meshes -------------------- */

/* A star prism (42 vertices, not convex: its hull is qhull's), for
 * spinning_meshes_are_fresh_meshes with the kit's tetrahedron. */
static noctMesh *make_star(void)
{
    enum { K = 20 }; /* ring vertices, alternately far and near */
    double v[3 * (2 * K + 2)];
    uint32_t sizes[3 * K], idx[3 * K + 3 * K + 4 * K];
    for (int i = 0; i < K; ++i) {
        const double a = 6.283185307179586 * i / K, r = i % 2 ? 0.3 : 0.6;
        for (int ring = 0; ring < 2; ++ring) {
            v[3 * (ring * K + i)] = r * cos(a);
            v[3 * (ring * K + i) + 1] = r * sin(a);
            v[3 * (ring * K + i) + 2] = ring ? 0.25 : -0.25;
        }
    }
    const uint32_t cb = 2 * K, ct = 2 * K + 1;
    v[3 * cb] = v[3 * cb + 1] = v[3 * ct] = v[3 * ct + 1] = 0;
    v[3 * cb + 2] = -0.25;
    v[3 * ct + 2] = 0.25;
    size_t n = 0;
    for (uint32_t i = 0; i < K; ++i) {
        const uint32_t j = (i + 1) % K;
        sizes[3 * i] = 3; /* bottom */
        idx[n++] = cb, idx[n++] = j, idx[n++] = i;
        sizes[3 * i + 1] = 3; /* top */
        idx[n++] = ct, idx[n++] = K + i, idx[n++] = K + j;
        sizes[3 * i + 2] = 4; /* side */
        idx[n++] = i, idx[n++] = j, idx[n++] = K + j, idx[n++] = K + i;
    }
    noctMesh *m;
    noctError err;
    ck_assert_msg(noctMeshCreate(v, 2 * K + 2, sizes, 3 * K, idx, &m, &err) == NOCT_OK, "%s",
                  err.message);
    ck_assert(!noctMeshIsConvex(m));
    return m;
}

/* The hits of a ray, in the world's order. */
typedef struct hits {
    noctRayHit hit[64];
    size_t n;
} hits;

static bool keep_hit(void *context, const noctRayHit *hit)
{
    hits *h = context;
    ck_assert(h->n < 64);
    h->hit[h->n++] = *hit;
    return true;
}

/* A world at accuracy with these effects. */
static noctWorld *spin_world(unsigned effects, noctAccuracy accuracy)
{
    noctWorldDef wd = noctDefaultWorldDef();
    wd.effects = effects;
    wd.accuracy = accuracy;
    noctWorld *w;
    ck_assert_int_eq(noctWorldCreate(&wd, &w, NULL), NOCT_OK);
    return w;
}

/*
 * Issue 31: spinning mesh objects (an L, a tetrahedron, a box mesh, a
 * star prism whose hull is qhull's) and tracked ones turn into recycled
 * copies. Every step must answer as a world made anew with the objects
 * where the spinning one has them, whose turned meshes are all new: the
 * same colliding pairs (at the exact level, also those of
 * noctCollideTransformed(); _i = 1 at the convex level, which reads the
 * hulls and their centres), and the same ray hits bit for bit (fraction,
 * point, normal and triangle: the vertices and the BVH).
 */
START_TEST(spinning_meshes_are_fresh_meshes)
{
    enum { NOBJ = 16, STEPS = 100 };
    const noctAccuracy accuracy = _i ? NOCT_ACCURACY_CONVEX : NOCT_ACCURACY_EXACT;
    noctMesh *shapes[4] = {make_ell(), make_tetrahedron(), make_box(0.4, 0.3, 0.2), make_star()};
    noctWorld *w = spin_world(NOCT_EFFECT_EVENTS | NOCT_EFFECT_SPIN | NOCT_EFFECT_TRACK,
                              accuracy);
    noctObjectId id[NOBJ];
    const noctMesh *shape_of[NOBJ];
    rng = 0x5b1e;
    for (int i = 0; i < NOBJ; ++i) {
        noctObjectDef d = noctDefaultObjectDef();
        d.mesh = shape_of[i] = shapes[i % 4];
        /* a 4 by 4 grid of spacing 0.7: neighbours meet as they turn */
        d.transform.p[0] = 0.7 * (i % 4);
        d.transform.p[1] = 0.7 * (i / 4);
        test_random_quat(&rng, &d.transform.q);
        const double axis[3] = {uniform() - 0.5, uniform() - 0.5, uniform() - 0.5};
        ck_assert_int_eq(noctQuatFromAxisAngle(axis, 3 + 10 * uniform(), &d.angular_velocity),
                         NOCT_OK);
        ck_assert_int_eq(noctWorldCreateObject(w, &d, &id[i], NULL), NOCT_OK);
        ck_assert_uint_eq(id[i].index, (unsigned)i);
    }
    /* two of them follow tracks instead (kinematic: they do not spin) */
    for (int i = 0; i < 2; ++i) {
        noctKeyframe keys[4];
        for (int k = 0; k < 4; ++k) {
            keys[k].tick = (uint64_t)(30 * k);
            keys[k].x.p[0] = 0.7 * (1 + i) + 0.1 * k;
            keys[k].x.p[1] = 0.7 * (1 + 2 * i);
            keys[k].x.p[2] = 0;
            test_random_quat(&rng, &keys[k].x.q);
        }
        const noctObjectId t = id[5 + 5 * i];
        ck_assert_int_eq(noctWorldSetType(w, t, NOCT_OBJECT_KINEMATIC, NULL), NOCT_OK);
        ck_assert_int_eq(noctWorldSetTrack(w, t, keys, 4, NULL), NOCT_OK);
    }
    long pairs = 0, changes = 0, nhits = 0;
    for (int step = 0; step < STEPS; ++step) {
        noctError err;
        ck_assert_msg(noctWorldStep(w, &err) == NOCT_OK, "step %d: %s", step, err.message);
        ck_assert_msg(noctWorldValidate(w, &err) == NOCT_OK, "step %d: %s", step, err.message);
        /* the reference: a world made now, every turned mesh new */
        noctWorld *f = spin_world(NOCT_EFFECT_EVENTS, accuracy);
        noctTransform x[NOBJ];
        for (int i = 0; i < NOBJ; ++i) {
            ck_assert_int_eq(noctWorldGetTransform(w, id[i], &x[i]), NOCT_OK);
            noctObjectDef d = noctDefaultObjectDef();
            d.mesh = shape_of[i];
            d.transform = x[i];
            noctObjectId fid;
            ck_assert_int_eq(noctWorldCreateObject(f, &d, &fid, NULL), NOCT_OK);
            ck_assert_uint_eq(fid.index, (unsigned)i);
        }
        ck_assert_int_eq(noctWorldStep(f, NULL), NOCT_OK);
        const noctPair *p, *q;
        const size_t np = noctWorldColliding(w, &p), nq = noctWorldColliding(f, &q);
        ck_assert_msg(np == nq, "step %d: %zu pairs, anew %zu", step, np, nq);
        for (size_t k = 0; k < np; ++k)
            ck_assert_msg(p[k].a.index == q[k].a.index && p[k].b.index == q[k].b.index,
                          "step %d: pair %zu differs", step, k);
        if (accuracy == NOCT_ACCURACY_EXACT) { /* and noctCollide's own turned meshes */
            size_t k = 0;
            for (int i = 0; i < NOBJ; ++i)
                for (int j = i + 1; j < NOBJ; ++j) {
                    bool hit;
                    ck_assert_int_eq(noctCollideTransformed(shape_of[i], &x[i], shape_of[j],
                                                            &x[j], accuracy, &hit, NULL, NULL),
                                     NOCT_OK);
                    if (!hit)
                        continue;
                    ck_assert_msg(k < np && p[k].a.index == (unsigned)i &&
                                      p[k].b.index == (unsigned)j,
                                  "step %d: pair %d %d missing", step, i, j);
                    ++k;
                }
            ck_assert_msg(k == np, "step %d: %zu pairs, not %zu", step, np, k);
        }
        /* rays along the grid's rows and columns, a little off centre */
        for (int r = 0; r < 8; ++r) {
            const double o[3] = {r < 4 ? -1 : 0.7 * (r - 4) + 0.05,
                                 r < 4 ? 0.7 * r + 0.03 : -1, 0.02 * (r % 3)};
            const double d[3] = {r < 4 ? 4.5 : 0, r < 4 ? 0 : 4.5, 0};
            static hits a, b;
            a.n = b.n = 0;
            ck_assert_int_eq(noctWorldRayCast(w, o, d, noctDefaultQueryFilter(), keep_hit, &a,
                                              NULL), NOCT_OK);
            ck_assert_int_eq(noctWorldRayCast(f, o, d, noctDefaultQueryFilter(), keep_hit, &b,
                                              NULL), NOCT_OK);
            ck_assert_msg(a.n == b.n, "step %d, ray %d: %zu hits, anew %zu", step, r, a.n, b.n);
            for (size_t k = 0; k < a.n; ++k) {
                const noctRayHit *u = &a.hit[k], *v = &b.hit[k];
                ck_assert_msg(u->id.index == v->id.index && u->fraction == v->fraction &&
                                  memcmp(u->point, v->point, sizeof u->point) == 0 &&
                                  memcmp(u->normal, v->normal, sizeof u->normal) == 0 &&
                                  memcmp(u->triangle, v->triangle, sizeof u->triangle) == 0,
                              "step %d, ray %d: hit %zu differs", step, r, k);
            }
            nhits += (long)a.n;
        }
        noctWorldDestroy(f);
        pairs += (long)np;
        changes += (long)noctWorldBegan(w, &p) + (long)noctWorldEnded(w, &p);
    }
    printf("spinning meshes (%s): %d steps, %ld colliding pairs, %ld began or ended, %ld ray "
           "hits\n",
           _i ? "convex" : "exact", STEPS, pairs, changes, nhits);
    ck_assert_int_gt(pairs, 200);
    ck_assert_int_gt(changes, 20);
    ck_assert_int_gt(nhits, 500);
    noctWorldDestroy(w);
    for (int i = 0; i < 4; ++i)
        noctMeshDestroy(shapes[i]);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("objects");
    TCase *tc = test_case(s, "transforms", 120, NULL);
    tcase_add_test(tc, quaternions_and_matrices);
    tcase_add_test(tc, quarter_turns_are_exact);
    /* slow under valgrind, where it is left out (tests/local.mk) */
    tc = test_case(s, "gas", 120, "slow");
    tcase_add_test(tc, gas_boxes_are_the_scenes);
    tc = test_case(s, "driven worlds", 300, NULL);
    tcase_add_loop_test(tc, rotated_scenes_against_brute_force, 0, 4);
    add_tests(tc, events_follow_changes, quaternions_compose, spin_quarter_turns,
              teleports_within_a_leaf, velocity_bit_for_bit, bad_input_changes_nothing,
              box_corners_beyond_the_limit);
    tcase_add_loop_test(tc, spinning_meshes_are_fresh_meshes, 0, 2);
    return run_suite(s);
}
