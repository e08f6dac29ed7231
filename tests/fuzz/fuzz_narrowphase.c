/* SPDX-License-Identifier: MIT */
/*
 * libFuzzer target: the narrowphase, noctCollide(), on two meshes made
 * from the input at two translations from the input, at every level.
 *
 * Input layout (missing bytes read as 0): a's kind, b's kind, a's
 * translation, b's translation, a shift, then b's shape, then a's shape.
 * Kinds: an axis-aligned box (noctMeshCreateBox), an oriented box (a signed
 * permutation of the axes, or a rotation from a quaternion), a tetrahedron,
 * a cube with one face pushed in or out to an apex (non-convex when in),
 * and, for a only, an OFF file: the rest of the input, through
 * noctMeshRead(). Coordinates are multiples of 1/8 (a grid, so that
 * touching and coplanar cases are common), except for raw translations,
 * which are any 8 bytes as a double (NaN, infinities, huge and tiny).
 *
 * Expectations, from narrowphase.h:
 *  - the status is NOCT_OK for finite translations within
 *    NOCT_MAX_COORDINATE (NOCT_ERR_NUMERIC allowed at the convex level);
 *    else NOCT_ERR_NONFINITE or NOCT_ERR_TOO_LARGE;
 *  - the answer does not depend on the order of the two objects;
 *  - exact implies box (the box level never misses a collision);
 *  - a mesh collides with itself at the same place, exactly;
 *  - two boxes with axis-aligned faces, on the grid, collide exactly when
 *    their closed intervals overlap on every axis (an oracle that shares
 *    nothing with the library), at the box and exact levels;
 *  - on the grid, where every placed vertex is exact, moving both by the
 *    same integer shift does not change the exact answer.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <string.h>

#include <noctree/mesh.h>
#include <noctree/narrowphase.h>

#include "fuzz.h"

typedef struct input {
    const uint8_t *p;
    size_t n;
} input;

static uint8_t take(input *in)
{
    if (in->n == 0)
        return 0;
    --in->n;
    return *in->p++;
}

/* A multiple of 1/8 in [-16, 16). */
static double grid(input *in)
{
    return (int8_t)take(in) / 8.0;
}

/* A multiple of 1/8 in [1/8, 4]. */
static double positive(input *in)
{
    return (1 + take(in) % 32) / 8.0;
}

static double raw(input *in)
{
    uint64_t u = 0;
    for (int i = 0; i < 8; ++i)
        u = u << 8 | take(in);
    double d;
    memcpy(&d, &u, sizeof d);
    return d;
}

/* A translation; false when it is raw (not on the grid). */
static bool translation(input *in, double t[3])
{
    bool on_grid = take(in) % 8 != 7;
    for (int k = 0; k < 3; ++k)
        t[k] = on_grid ? grid(in) : raw(in);
    return on_grid;
}

/* What a made mesh is: whether its placed vertices are exact on the grid,
 * and, for a box with axis-aligned faces, its half-extents. */
typedef struct shape {
    noctMesh *mesh;
    bool exact;      /* coordinates on a grid of 1/64, small */
    bool aligned;    /* a box with axis-aligned faces, centred on 0 */
    double half[3];
} shape;

/* Rotations that map the axes onto the axes: signed permutations with
 * determinant +1, exact in floating point. */
static void signed_permutation(input *in, double r[9], int axis[3])
{
    static const int perms[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1},
                                    {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
    uint8_t b = take(in);
    const int *p = perms[b % 6];
    double sign[3] = {b & 8 ? -1 : 1, b & 16 ? -1 : 1, 1};
    /* odd permutations (the last three) and the two signs fix the third
     * sign so that the determinant is +1 */
    sign[2] = sign[0] * sign[1] * (b % 6 < 3 ? 1 : -1);
    memset(r, 0, 9 * sizeof *r);
    for (int i = 0; i < 3; ++i) {
        r[3 * p[i] + i] = sign[i]; /* column i, the box's axis i, is ±e[p[i]] */
        axis[i] = p[i];
    }
}

static void quaternion_rotation(input *in, double r[9])
{
    double q[4], n = 0;
    for (int i = 0; i < 4; ++i) {
        q[i] = (int8_t)take(in);
        n += q[i] * q[i];
    }
    if (n == 0)
        q[0] = n = 1;
    n = sqrt(n);
    double w = q[0] / n, x = q[1] / n, y = q[2] / n, z = q[3] / n;
    const double m[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
                         2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
                         2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)};
    memcpy(r, m, sizeof m);
}

/* A mesh's construction failed: only for the documented reasons of bad
 * input, never anything else. */
static void made_or_refused(noctStatus st, const noctError *err)
{
    FUZZ_CHECK(st == NOCT_OK || st == NOCT_ERR_DEGENERATE || st == NOCT_ERR_INVALID ||
               st == NOCT_ERR_NOMEM,
               "%s: %s", noctStatusString(st), err->message);
}

static bool make(input *in, int kind, shape *s)
{
    noctError err = {0};
    noctStatus st;
    memset(s, 0, sizeof *s);
    switch (kind) {
    case 0: { /* an axis-aligned box */
        for (int k = 0; k < 3; ++k)
            s->half[k] = positive(in);
        st = noctMeshCreateBox(s->half[0], s->half[1], s->half[2], &s->mesh, &err);
        s->exact = s->aligned = true;
        break;
    }
    case 1: { /* an oriented box */
        double half[3], r[9];
        for (int k = 0; k < 3; ++k)
            half[k] = positive(in);
        if (take(in) & 1) {
            int axis[3];
            signed_permutation(in, r, axis);
            for (int i = 0; i < 3; ++i)
                s->half[axis[i]] = half[i];
            s->exact = s->aligned = true;
        } else {
            quaternion_rotation(in, r);
        }
        st = noctMeshCreateOrientedBox(half, r, &s->mesh, &err);
        break;
    }
    case 2: { /* a tetrahedron, either way round */
        double v[12];
        for (int i = 0; i < 12; ++i)
            v[i] = grid(in);
        static const uint32_t sizes[4] = {3, 3, 3, 3};
        static const uint32_t idx[12] = {0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2};
        st = noctMeshCreate(v, 4, sizes, 4, idx, &s->mesh, &err);
        s->exact = true;
        break;
    }
    default: { /* a cube of half-side h, its +z face pushed to an apex */
        double h = positive(in), depth = (take(in) % 32 - 16) / 8.0; /* [-2, 1.875] */
        double v[27];
        for (int i = 0; i < 8; ++i) {
            v[3 * i] = i & 4 ? h : -h;
            v[3 * i + 1] = i & 2 ? h : -h;
            v[3 * i + 2] = i & 1 ? h : -h;
        }
        v[24] = v[25] = 0;
        v[26] = (1 - depth) * h;
        static const uint32_t sizes[9] = {4, 4, 4, 4, 4, 3, 3, 3, 3};
        static const uint32_t idx[32] = {0, 1, 3, 2, 4, 6, 7, 5, 0, 4, 5, 1, 2, 3, 7, 6,
                                         0, 2, 6, 4, 1, 5, 8, 5, 7, 8, 7, 3, 8, 3, 1, 8};
        st = noctMeshCreate(v, 9, sizes, 9, idx, &s->mesh, &err);
        s->exact = true;
        break;
    }
    }
    made_or_refused(st, &err);
    return st == NOCT_OK;
}

/* a as an OFF file: the rest of the input. */
static bool make_off(input *in, shape *s)
{
    memset(s, 0, sizeof *s);
    const char *path = fuzz_file("input.off", in->p, in->n);
    in->n = 0;
    noctError err = {0};
    noctStatus st = noctMeshRead(path, &s->mesh, &err);
    if (st != NOCT_OK)
        fuzz_failed_read(st, s->mesh, &err, path);
    return st == NOCT_OK;
}

static bool valid_translation(const double t[3])
{
    for (int k = 0; k < 3; ++k)
        if (!(fabs(t[k]) <= NOCT_MAX_COORDINATE))
            return false;
    return true;
}

/* Both orders at one level; returns the answer (or -1 for a failure that
 * the translations explain). */
static int collide_both(const shape *a, const double ta[3], const shape *b,
                        const double tb[3], noctAccuracy level)
{
    bool h1 = false, h2 = false;
    noctStatus s1 = noctCollide(a->mesh, ta, b->mesh, tb, level, &h1, NULL);
    noctStatus s2 = noctCollide(b->mesh, tb, a->mesh, ta, level, &h2, NULL);
    const char *name = noctAccuracyName(level);
    if (!valid_translation(ta) || !valid_translation(tb)) {
        FUZZ_CHECK((s1 == NOCT_ERR_NONFINITE || s1 == NOCT_ERR_TOO_LARGE) &&
                   (s2 == NOCT_ERR_NONFINITE || s2 == NOCT_ERR_TOO_LARGE),
                   "%s: bad translations gave %s and %s", name, noctStatusString(s1),
                   noctStatusString(s2));
        return -1;
    }
    if (level == NOCT_ACCURACY_CONVEX && (s1 == NOCT_ERR_NUMERIC || s2 == NOCT_ERR_NUMERIC))
        return -1;
    FUZZ_CHECK(s1 == NOCT_OK && s2 == NOCT_OK, "%s: %s and %s", name, noctStatusString(s1),
               noctStatusString(s2));
    FUZZ_CHECK(h1 == h2, "%s: a with b %d, b with a %d", name, (int)h1, (int)h2);
    return h1;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    input in = {data, size};
    int kind_a = take(&in) % 5, kind_b = take(&in) % 4;
    double ta[3], tb[3], shift[3];
    bool grid_a = translation(&in, ta), grid_b = translation(&in, tb);
    for (int k = 0; k < 3; ++k)
        shift[k] = (int8_t)take(&in) % 32;
    shape a, b;
    if (!make(&in, kind_b, &b))
        return 0;
    if (!(kind_a == 4 ? make_off(&in, &a) : make(&in, kind_a, &a))) {
        noctMeshDestroy(b.mesh);
        return 0;
    }

    int box = collide_both(&a, ta, &b, tb, NOCT_ACCURACY_BOX);
    collide_both(&a, ta, &b, tb, NOCT_ACCURACY_CONVEX);
    int exact = collide_both(&a, ta, &b, tb, NOCT_ACCURACY_EXACT);
    if (exact >= 0) {
        FUZZ_CHECK(!exact || box, "exact says collide, box says apart");
        bool self = false;
        FUZZ_CHECK(noctCollide(a.mesh, ta, a.mesh, ta, NOCT_ACCURACY_EXACT, &self, NULL) ==
                       NOCT_OK && self,
                   "a mesh does not collide with itself");
    }
    bool on_grid = exact >= 0 && grid_a && grid_b && a.exact && b.exact;
    if (on_grid && a.aligned && b.aligned) {
        bool overlap = true;
        for (int k = 0; k < 3; ++k)
            overlap = overlap && fabs(ta[k] - tb[k]) <= a.half[k] + b.half[k];
        FUZZ_CHECK(exact == overlap && box == overlap,
                   "boxes: intervals say %d, exact %d, box %d", (int)overlap, exact, box);
    }
    if (on_grid) {
        double sa[3], sb[3];
        for (int k = 0; k < 3; ++k) {
            sa[k] = ta[k] + shift[k];
            sb[k] = tb[k] + shift[k];
        }
        int moved = collide_both(&a, sa, &b, sb, NOCT_ACCURACY_EXACT);
        FUZZ_CHECK(moved == exact, "shifted by (%g, %g, %g): %d, in place: %d", shift[0],
                   shift[1], shift[2], moved, exact);
    }
    noctMeshDestroy(a.mesh);
    noctMeshDestroy(b.mesh);
    return 0;
}
