/* SPDX-License-Identifier: MIT */
/*
 * The scene families arms:K and keyframes:N (issue 19; noctree-sim(1)
 * defines them) against an independent oracle: the test computes every
 * object's ideal pose after every step from the definition alone, in
 * long double (the arms' forward kinematics; the keyframes' own linear
 * interpolation and shorter-arc spherical interpolation), and decides
 * every pair with its own separating-axis test of two oriented boxes.
 * It calls neither noctTrackAt() nor the narrowphase: the world is only
 * built, stepped and read (objects, filters, poses, the colliding list
 * and the events). Poses must agree within 1e-12; pairs the filters
 * forbid must never be listed.
 *
 * A pair is certain when the oracle's margin exceeds EPS (1e-9) on the
 * deciding side: apart (some axis separates by more), or colliding (every
 * axis overlaps by more). Certain pairs must be in the world's list iff
 * colliding; the rest are counted as ambiguous and must be rare. The
 * oracle itself is checked first, without the families: closed-form
 * facts of the arms and a second box test (edges clipped against boxes).
 */
#include <check.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <noctree.h>

#include "testutil.h"

typedef long double ld;

static const ld PI_L = 3.141592653589793238462643383279502884L;
/* The margin beyond which the oracle is sure: far above the difference
 * between the ideal poses and the library's (double, ~1e-14). */
static const ld EPS = 1e-9L;
/* Cross axes of edges closer to parallel than this are not trusted to
 * show an overlap (see obb_test()). */
static const ld NEAR_PARALLEL = 1e-6L;

/* ---- geometry ------------------------------------------------------------------------------- */

/* An oriented box: the solid c + sum_k s_k h_k ax[k], |s_k| <= 1. */
typedef struct obb {
    ld c[3];
    ld ax[3][3]; /* ax[k]: the box's own axis k, placed (column k of R) */
    ld h[3];
    ld q[4];     /* its rotation as a quaternion x, y, z, w */
} obb;

static ld dot3(const ld a[3], const ld b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static ld norm3(const ld a[3])
{
    return sqrtl(dot3(a, a));
}

static void cross3(const ld a[3], const ld b[3], ld out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

static ld radians(ld degrees)
{
    return degrees * PI_L / 180;
}

/* The rotation by an angle about an axis: (sin(a/2) u, cos(a/2)), u the
 * unit axis. */
static void quat_axis_angle(const ld axis[3], ld degrees, ld q[4])
{
    const ld n = norm3(axis), half = radians(degrees) / 2, s = sinl(half);
    for (int k = 0; k < 3; ++k)
        q[k] = s * axis[k] / n;
    q[3] = cosl(half);
}

/* Set b's rotation (and axes) from a unit quaternion. */
static void obb_rotate(obb *b, const ld q[4])
{
    const ld x = q[0], y = q[1], z = q[2], w = q[3];
    const ld R[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                        {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                        {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
    for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 3; ++i)
            b->ax[k][i] = R[i][k];
    memcpy(b->q, (const ld[4]){x, y, z, w}, sizeof b->q);
}

static void obb_set(obb *b, ld cx, ld cy, ld cz, ld hx, ld hy, ld hz)
{
    b->c[0] = cx;
    b->c[1] = cy;
    b->c[2] = cz;
    b->h[0] = hx;
    b->h[1] = hy;
    b->h[2] = hz;
    obb_rotate(b, (const ld[4]){0, 0, 0, 1});
}

/* The box's extent along the unit direction L: half the width of its
 * projection. */
static ld radius_along(const obb *b, const ld L[3])
{
    return b->h[0] * fabsl(dot3(b->ax[0], L)) + b->h[1] * fabsl(dot3(b->ax[1], L)) +
           b->h[2] * fabsl(dot3(b->ax[2], L));
}

enum verdict { APART, AMBIGUOUS, COLLIDING };

typedef struct sat {
    enum verdict verdict;
    ld sep;        /* the largest separation over the axes (> 0: apart by it;
                      < 0: the least overlap of the boxes' projections) */
    int axis;      /* which: 0-2 a's faces, 3-5 b's, 6-14 a_i x b_j, -1 the
                      bounding spheres */
    bool edge_only;/* apart, though every face axis shows an overlap */
} sat;

/*
 * The separating-axis test of two oriented boxes, with a margin.
 *
 * Any unit direction along which the projections are apart by more than
 * EPS proves the boxes apart, so every axis, however it was rounded,
 * counts for that. For the other side, the 15 axes' overlaps all beyond
 * EPS prove a common point. A cross axis a_i x b_j of length 0 (edges
 * exactly parallel) is not needed: the two boxes then project, along that
 * edge direction, to rectangles whose edge normals are face axes. A cross
 * axis shorter than NEAR_PARALLEL (edges parallel within angle e) is too
 * poorly conditioned to be trusted: it is left out of the overlap check,
 * and the other axes must overlap by EPS + 8 e (|T| + |h_a| + |h_b|)
 * instead, which covers turning one box by e so that the edges become
 * parallel, and back (a common point at depth above that survives it).
 */
static sat obb_test(const obb *a, const obb *b)
{
    ld T[3];
    for (int k = 0; k < 3; ++k)
        T[k] = b->c[k] - a->c[k];
    const ld ra = norm3(a->h), rb = norm3(b->h), dist = norm3(T);
    sat r = {APART, dist - ra - rb, -1, false};
    if (r.sep > EPS) /* the bounding spheres are apart */
        return r;
    ld worst_all = -INFINITY, worst_trusted = -INFINITY, worst_face = -INFINITY;
    ld parallel = 0;
    int arg = -1;
    for (int i = 0; i < 15; ++i) {
        ld L[3];
        if (i < 3)
            memcpy(L, a->ax[i], sizeof L);
        else if (i < 6)
            memcpy(L, b->ax[i - 3], sizeof L);
        else
            cross3(a->ax[(i - 6) / 3], b->ax[(i - 6) % 3], L);
        const ld n = norm3(L);
        if (n == 0)
            continue;
        for (int k = 0; k < 3; ++k)
            L[k] /= n;
        const ld s = fabsl(dot3(T, L)) - radius_along(a, L) - radius_along(b, L);
        if (s > worst_all) {
            worst_all = s;
            arg = i;
        }
        if (i < 6 && s > worst_face)
            worst_face = s;
        if (i >= 6 && n < NEAR_PARALLEL) {
            if (n > parallel)
                parallel = n;
            continue;
        }
        if (s > worst_trusted)
            worst_trusted = s;
    }
    r.sep = worst_all;
    r.axis = arg;
    if (worst_all > EPS) {
        r.verdict = APART;
        r.edge_only = worst_face < -EPS;
        return r;
    }
    const ld margin = EPS + 8 * parallel * (dist + ra + rb);
    r.verdict = worst_all < -EPS && worst_trusted < -margin ? COLLIDING : AMBIGUOUS;
    return r;
}

/* A second test, for checking the first: two convex solids meet iff an
 * edge of one meets the other (every vertex of their intersection lies on
 * an edge of one of them). An edge is clipped against the box's slabs,
 * grown by grow on every side. */
static bool segment_meets(const obb *b, const ld p0[3], const ld p1[3], ld grow)
{
    ld lo = 0, hi = 1;
    for (int k = 0; k < 3; ++k) {
        ld d0[3], d1[3];
        for (int i = 0; i < 3; ++i) {
            d0[i] = p0[i] - b->c[i];
            d1[i] = p1[i] - b->c[i];
        }
        const ld s0 = dot3(d0, b->ax[k]), s1 = dot3(d1, b->ax[k]), h = b->h[k] + grow;
        const ld ds = s1 - s0;
        if (ds == 0) {
            if (fabsl(s0) > h)
                return false;
            continue;
        }
        ld t0 = (-h - s0) / ds, t1 = (h - s0) / ds;
        if (t0 > t1) {
            const ld t = t0;
            t0 = t1;
            t1 = t;
        }
        if (t0 > lo)
            lo = t0;
        if (t1 < hi)
            hi = t1;
        if (lo > hi)
            return false;
    }
    return true;
}

static void obb_corner(const obb *b, int bits, ld out[3])
{
    for (int i = 0; i < 3; ++i) {
        out[i] = b->c[i];
        for (int k = 0; k < 3; ++k)
            out[i] += (bits >> k & 1 ? 1 : -1) * b->h[k] * b->ax[k][i];
    }
}

static bool edges_meet(const obb *a, const obb *b, ld grow)
{
    for (int s = 0; s < 2; ++s) {
        const obb *x = s ? b : a, *y = s ? a : b;
        for (int v = 0; v < 8; ++v)
            for (int k = 0; k < 3; ++k) {
                if (v >> k & 1)
                    continue;
                ld p0[3], p1[3];
                obb_corner(x, v, p0);
                obb_corner(x, v | 1 << k, p1);
                if (segment_meets(y, p0, p1, grow))
                    return true;
            }
    }
    return false;
}

/* ---- the arms ------------------------------------------------------------------------------- */

enum kind {
    FLOOR, CEILING, XWALL, YWALL, LOOSE_REACH, LOOSE_BESIDE, LINK_A, LINK_B
};

typedef struct arms {
    int K;
    ld d;
    size_t n, nloose, first_link;
    obb box[64];
    enum kind kind[64];
    int index[64]; /* a link's j, a loose box's place in the list */
    uint64_t cat[64], mask[64];
} arms;

static void arms_init(arms *s, int K)
{
    memset(s, 0, sizeof *s);
    s->K = K;
    s->d = 2 * (ld)K - 0.5L;
    const ld d = s->d, hz = K + 1.5L;
    size_t n = 0;
    static const enum kind wall_kind[6] = {FLOOR, CEILING, XWALL, XWALL, YWALL, YWALL};
    const ld wall[6][6] = {{0, 0, -K, d + 2, 2.5L, K},
                           {0, 0, 2 * K + 2.25L, d + 2, 2.5L, 0.25L},
                           {-(d + 1.75L), 0, K + 1, 0.25L, 2.5L, hz},
                           {d + 1.75L, 0, K + 1, 0.25L, 2.5L, hz},
                           {0, -2.25L, K + 1, d + 2, 0.25L, hz},
                           {0, 2.25L, K + 1, d + 2, 0.25L, hz}};
    for (int w = 0; w < 6; ++w, ++n) {
        obb_set(&s->box[n], wall[w][0], wall[w][1], wall[w][2], wall[w][3], wall[w][4],
                wall[w][5]);
        s->kind[n] = wall_kind[w];
        s->index[n] = w;
        s->cat[n] = 1;
        s->mask[n] = 4 | 8;
    }
    for (int m = 0; d - 1.5L - 2.5L * m > 1; ++m) {
        const ld x = d - 1.5L - 2.5L * m;
        const ld place[4][2] = {{-x, 0}, {x, 0}, {-x, 1.2L}, {x, 1.2L}};
        for (int p = 0; p < 4; ++p, ++n) {
            obb_set(&s->box[n], place[p][0], place[p][1], 0.3L, 0.3L, 0.3L, 0.3L);
            s->kind[n] = p < 2 ? LOOSE_REACH : LOOSE_BESIDE;
            s->index[n] = (int)(n - 6);
            s->cat[n] = 2;
            s->mask[n] = 4 | 8;
        }
    }
    s->nloose = n - 6;
    s->first_link = n;
    for (int a = 0; a < 2; ++a)
        for (int j = 0; j < K; ++j, ++n) {
            s->kind[n] = a ? LINK_B : LINK_A;
            s->index[n] = j;
            s->cat[n] = a ? 8 : 4;
            s->mask[n] = a ? (1 | 2 | 4) : (1 | 2 | 8);
            obb_set(&s->box[n], 0, 0, 0, 1, 0.2L, 0.2L);
        }
    s->n = n;
}

/* The tri wave of the spec, exactly: t / P's fractional part f is
 * (t mod P) / P, and tri = 1 - |2 f - 1| = 1 - |2 (t mod P) - P| / P. */
static ld tri(uint64_t t, uint64_t P)
{
    const long long r = (long long)(t % P);
    return 1 - (ld)llabs(2 * r - (long long)P) / (ld)P;
}

/* Place arm a's links for joint angles theta[0..K-1] (degrees). */
static void arms_place(arms *s, int a, const ld *theta)
{
    ld J[3] = {a ? s->d : -s->d, 0, 1}, phi = 0;
    for (int j = 0; j < s->K; ++j) {
        phi += theta[j];
        const ld u[3] = {(a ? -1 : 1) * cosl(radians(phi)), 0, sinl(radians(phi))};
        obb *b = &s->box[s->first_link + (size_t)(a * s->K + j)];
        for (int k = 0; k < 3; ++k) {
            b->c[k] = J[k] + u[k];
            J[k] += 2 * u[k];
        }
        ld q[4];
        quat_axis_angle((const ld[3]){0, 1, 0}, a ? 180 + phi : -phi, q);
        obb_rotate(b, q);
    }
}

static void arms_at(arms *s, uint64_t t)
{
    for (int a = 0; a < 2; ++a) {
        ld theta[8];
        for (int j = 0; j < s->K; ++j)
            theta[j] = (j == 0 ? 80 : -45) * tri(t, (uint64_t)(40 + 12 * j + 10 * a));
        arms_place(s, a, theta);
    }
}

static const char *arms_name(const arms *s, size_t i, char *buf, size_t len)
{
    static const char *WALL[6] = {"floor", "ceiling", "-x wall", "+x wall", "-y wall",
                                  "+y wall"};
    switch (s->kind[i]) {
    case LINK_A:
    case LINK_B:
        snprintf(buf, len, "arm %c link %d", s->kind[i] == LINK_A ? 'A' : 'B', s->index[i]);
        break;
    case LOOSE_REACH:
    case LOOSE_BESIDE:
        snprintf(buf, len, "loose box %d at (%.2Lf, %.2Lf, 0.3)", s->index[i], s->box[i].c[0],
                 s->box[i].c[1]);
        break;
    default:
        snprintf(buf, len, "%s", WALL[s->index[i]]);
    }
    return buf;
}

/* The classes of pairs that the counts keep apart. */
enum pclass {
    ARM_ARM, LINK_FLOOR, LINK_CEILING, LINK_XWALL, LINK_YWALL, LINK_LOOSE, LINK_BESIDE,
    SAME_ARM, WALL_WALL, WALL_LOOSE, LOOSE_LOOSE, OTHER, NCLASS
};

static const char *const CLASS_NAME[NCLASS] = {
    "arm-arm", "link-floor", "link-ceiling", "link-x-wall", "link-y-wall", "link-loose",
    "link-beside", "same-arm", "wall-wall", "wall-loose", "loose-loose", "box-box"};

static enum pclass arms_class(const arms *s, size_t i, size_t j)
{
    enum kind a = s->kind[i], b = s->kind[j]; /* i < j: walls, loose boxes, A, B */
    if (a >= LINK_A && b >= LINK_A)
        return a == b ? SAME_ARM : ARM_ARM;
    if (b >= LINK_A) {
        static const enum pclass BY_KIND[6] = {LINK_FLOOR, LINK_CEILING, LINK_XWALL,
                                               LINK_YWALL, LINK_LOOSE, LINK_BESIDE};
        return BY_KIND[a];
    }
    if (a <= YWALL)
        return b <= YWALL ? WALL_WALL : WALL_LOOSE;
    return LOOSE_LOOSE;
}

/* ---- keyframes ------------------------------------------------------------------------------ */

typedef struct keyed {
    size_t n;
    ld (*h)[3];
    ld (*p)[5][3];
    ld (*q)[5][4];
    obb *box;
} keyed;

/* A uniform long double in [0, 1): splitmix64's top 53 bits. */
static ld draw(uint64_t *state)
{
    return (ld)(test_rand(state) >> 11) * 0x1p-53L;
}

static void keyed_init(keyed *s, size_t n)
{
    s->n = n;
    s->h = malloc(n * sizeof *s->h);
    s->p = malloc(n * sizeof *s->p);
    s->q = malloc(n * sizeof *s->q);
    s->box = malloc(n * sizeof *s->box);
    ck_assert(s->h && s->p && s->q && s->box);
    uint64_t state = 1234;
    const ld L = 4 * cbrtl((ld)n);
    for (size_t i = 0; i < n; ++i) {
        for (int k = 0; k < 3; ++k)
            s->h[i][k] = 0.25L + 0.5L * draw(&state);
        for (int f = 0; f < 5; ++f) {
            for (int k = 0; k < 3; ++k)
                s->p[i][f][k] = L * draw(&state);
            const ld zz = 2 * draw(&state) - 1, az = 360 * draw(&state);
            const ld r = sqrtl(1 - zz * zz);
            const ld axis[3] = {r * cosl(radians(az)), r * sinl(radians(az)), zz};
            quat_axis_angle(axis, 360 * draw(&state) - 180, s->q[i][f]);
        }
        memset(&s->box[i], 0, sizeof s->box[i]);
        memcpy(s->box[i].h, s->h[i], sizeof s->h[i]);
    }
}

static void keyed_free(keyed *s)
{
    free(s->h);
    free(s->p);
    free(s->q);
    free(s->box);
}

/* The rotation s of the way from q0 to q1 on the shorter arc: spherical,
 * or normalised linear for nearly equal rotations (d > 0.9995) as
 * world.h states. *unsure is set when d is too near 0 (which arc) or
 * 0.9995 (which formula) for the library's double dot product to agree. */
static void interpolate(const ld q0[4], const ld q1in[4], ld s, ld out[4], bool *unsure)
{
    ld q1[4], d = 0;
    for (int k = 0; k < 4; ++k)
        d += q0[k] * q1in[k];
    *unsure = fabsl(d) < 1e-12L || fabsl(fabsl(d) - 0.9995L) < 1e-12L;
    for (int k = 0; k < 4; ++k)
        q1[k] = d < 0 ? -q1in[k] : q1in[k];
    d = fabsl(d);
    ld a = 1 - s, b = s;
    if (d <= 0.9995L) {
        const ld t = acosl(d > 1 ? 1 : d);
        a = sinl((1 - s) * t) / sinl(t);
        b = sinl(s * t) / sinl(t);
    }
    ld len = 0;
    for (int k = 0; k < 4; ++k) {
        out[k] = a * q0[k] + b * q1[k];
        len += out[k] * out[k];
    }
    len = sqrtl(len);
    for (int k = 0; k < 4; ++k)
        out[k] /= len;
}

/* The poses at tick t; unsure[i] for an object whose rotation the
 * oracle cannot pin down. */
static void keyed_at(keyed *s, uint64_t t, bool *unsure)
{
    const uint64_t f = t >= 200 ? 4 : t / 50;
    const ld u = f == 4 ? 0 : (ld)(t - 50 * f) / 50;
    for (size_t i = 0; i < s->n; ++i) {
        obb *b = &s->box[i];
        unsure[i] = false;
        if (u == 0) {
            memcpy(b->c, s->p[i][f], sizeof b->c);
            obb_rotate(b, s->q[i][f]);
            continue;
        }
        for (int k = 0; k < 3; ++k)
            b->c[k] = (1 - u) * s->p[i][f][k] + u * s->p[i][f + 1][k];
        ld q[4];
        interpolate(s->q[i][f], s->q[i][f + 1], u, q, &unsure[i]);
        obb_rotate(b, q);
    }
}

/* ---- comparing with a world ----------------------------------------------------------------- */

typedef struct tally {
    long checks;             /* certain verdicts compared with the world */
    long ambiguous;          /* pairs the filters allow that were skipped */
    long unsure_objects;     /* object-steps whose pose was left out */
    long colliding[NCLASS];  /* certain colliding verdicts, by class */
    long steps_with[NCLASS]; /* steps with at least one, by class */
    long apart_close;        /* certain apart, though the spheres overlap */
    long edge_only;          /* of those, apart by a cross axis only */
    long forbidden_overlap;  /* pairs the filters forbid whose boxes meet */
    long world_pairs;        /* pairs the world listed */
    long events;             /* began and ended events, checked */
    long mismatches;
    long pose_checks;
    char first[512];
} tally;

static void mismatch(tally *t, const char *line)
{
    if (t->mismatches < 25) {
        printf("  MISMATCH %s\n", line);
        fflush(stdout);
    }
    if (t->mismatches++ == 0)
        snprintf(t->first, sizeof t->first, "%s", line);
}

/* A scene as the oracle sees it: its boxes at the current tick. */
typedef struct view {
    const char *spec;
    size_t n;
    const obb *box;
    const bool *unsure;         /* or NULL */
    const uint64_t *cat, *mask; /* or NULL: every bit */
    const arms *arms;           /* for names and classes, or NULL */
} view;

static const char *name_of(const view *v, size_t i, char *buf, size_t len)
{
    if (v->arms)
        return arms_name(v->arms, i, buf, len);
    snprintf(buf, len, "box %zu", i);
    return buf;
}

static bool allowed(const view *v, size_t i, size_t j)
{
    if (v->cat == NULL)
        return true;
    return (v->cat[i] & v->mask[j]) && (v->cat[j] & v->mask[i]);
}

/* The world's poses against the oracle's, within 1e-12 (the rotation up
 * to the sign of its quaternion, q and -q being the same rotation). */
static void compare_poses(const view *v, const noctWorld *w, uint64_t tick, tally *t)
{
    for (size_t i = 0; i < v->n; ++i) {
        if (v->unsure && v->unsure[i])
            continue;
        noctTransform x;
        ck_assert_int_eq(noctWorldGetTransform(w, (noctObjectId){(uint32_t)i, 1}, &x), NOCT_OK);
        const obb *b = &v->box[i];
        ld dp = 0, dq = 0, dn = 0;
        for (int k = 0; k < 3; ++k)
            dp = fmaxl(dp, fabsl(x.p[k] - b->c[k]));
        const double got[4] = {x.q.x, x.q.y, x.q.z, x.q.w};
        for (int k = 0; k < 4; ++k) {
            dq = fmaxl(dq, fabsl(got[k] - b->q[k]));
            dn = fmaxl(dn, fabsl(got[k] + b->q[k]));
        }
        ++t->pose_checks;
        if (dp > 1e-12L || fminl(dq, dn) > 1e-12L) {
            char line[512], nm[96];
            snprintf(line, sizeof line,
                     "%s tick %llu: %s at (%.15g, %.15g, %.15g) q (%.15g, %.15g, %.15g, %.15g); "
                     "oracle (%.15Lg, %.15Lg, %.15Lg) q (%.15Lg, %.15Lg, %.15Lg, %.15Lg)",
                     v->spec, (unsigned long long)tick, name_of(v, i, nm, sizeof nm), x.p[0],
                     x.p[1], x.p[2], got[0], got[1], got[2], got[3], b->c[0], b->c[1], b->c[2],
                     b->q[0], b->q[1], b->q[2], b->q[3]);
            mismatch(t, line);
        }
    }
}

/* Every pair at the current tick: the oracle's verdicts, counted, and
 * (with a world) compared with its colliding list. */
static void compare_pairs(const view *v, const noctWorld *w, uint64_t tick, tally *t)
{
    const size_t n = v->n;
    unsigned char *listed = calloc(n * n, 1);
    ck_assert_ptr_nonnull(listed);
    char line[512], na[96], nb[96];
    if (w != NULL) {
        const noctPair *p;
        const size_t np = noctWorldColliding(w, &p);
        t->world_pairs += (long)np;
        for (size_t k = 0; k < np; ++k) {
            const size_t i = p[k].a.index, j = p[k].b.index;
            EXPECT(p[k].a.generation == 1 && p[k].b.generation == 1);
            EXPECT(i < j && j < n);
            EXPECT(k == 0 || p[k - 1].a.index < i ||
                   (p[k - 1].a.index == i && p[k - 1].b.index < j)); /* sorted, once */
            listed[i * n + j] = 1;
        }
    }
    bool seen[NCLASS] = {false};
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 1; j < n; ++j) {
            const enum pclass cl = v->arms ? arms_class(v->arms, i, j) : OTHER;
            const sat r = obb_test(&v->box[i], &v->box[j]);
            if (!allowed(v, i, j)) {
                t->forbidden_overlap += r.verdict != APART;
                if (r.verdict == COLLIDING) {
                    ++t->colliding[cl];
                    seen[cl] = true;
                }
                if (listed[i * n + j]) {
                    snprintf(line, sizeof line,
                             "%s step %llu: the world lists (%zu, %zu) [%s, %s], which the "
                             "filters forbid",
                             v->spec, (unsigned long long)tick, i, j,
                             name_of(v, i, na, sizeof na), name_of(v, j, nb, sizeof nb));
                    mismatch(t, line);
                }
                continue;
            }
            if (r.verdict == AMBIGUOUS || (v->unsure && (v->unsure[i] || v->unsure[j]))) {
                ++t->ambiguous;
                continue;
            }
            ++t->checks;
            if (r.verdict == COLLIDING) {
                ++t->colliding[cl];
                seen[cl] = true;
            } else if (r.axis >= 0) {
                ++t->apart_close;
                t->edge_only += r.edge_only;
            }
            if (w != NULL && (r.verdict == COLLIDING) != (listed[i * n + j] != 0)) {
                snprintf(line, sizeof line,
                         "%s step %llu: pair (%zu, %zu) [%s, %s]: oracle %s (%s %.12Lg on axis "
                         "%d), world %s",
                         v->spec, (unsigned long long)tick, i, j, name_of(v, i, na, sizeof na),
                         name_of(v, j, nb, sizeof nb),
                         r.verdict == COLLIDING ? "colliding" : "apart",
                         r.verdict == COLLIDING ? "least overlap" : "separation",
                         fabsl(r.sep), r.axis, listed[i * n + j] ? "colliding" : "apart");
                mismatch(t, line);
            }
        }
    for (int c = 0; c < NCLASS; ++c)
        t->steps_with[c] += seen[c];
    free(listed);
}

static void print_tally(const char *spec, const tally *t)
{
    printf("%s: %ld pair checks, %ld ambiguous skipped, %ld unsure object-steps, %ld poses; "
           "world pairs %ld, events %ld; apart though spheres meet %ld (by an edge axis "
           "only %ld); forbidden pairs meeting %ld; colliding:",
           spec, t->checks, t->ambiguous, t->unsure_objects, t->pose_checks, t->world_pairs,
           t->events, t->apart_close, t->edge_only, t->forbidden_overlap);
    for (int c = 0; c < NCLASS; ++c)
        if (t->colliding[c] > 0)
            printf(" %s %ld (%ld steps)", CLASS_NAME[c], t->colliding[c], t->steps_with[c]);
    printf("%s\n", t->mismatches ? " MISMATCHES" : "");
    fflush(stdout);
}

/* The events of the step: began = colliding now and not before, ended =
 * before and not now (prev: the last step's list, kept by the caller). */
static void compare_events(const noctWorld *w, noctPair **prev, size_t *nprev, tally *t)
{
    const noctPair *now, *began, *ended;
    const size_t nnow = noctWorldColliding(w, &now);
    const size_t nb = noctWorldBegan(w, &began), ne = noctWorldEnded(w, &ended);
    size_t i = 0, j = 0, kb = 0, ke = 0;
    while (i < *nprev || j < nnow) {
        const uint64_t a = i < *nprev ? (uint64_t)(*prev)[i].a.index << 32 | (*prev)[i].b.index
                                      : UINT64_MAX;
        const uint64_t b = j < nnow ? (uint64_t)now[j].a.index << 32 | now[j].b.index
                                    : UINT64_MAX;
        if (a == b) {
            ++i;
            ++j;
        } else if (a < b) { /* ended */
            EXPECT(ke < ne && ended[ke].a.index == (*prev)[i].a.index &&
                   ended[ke].b.index == (*prev)[i].b.index);
            ++ke;
            ++i;
        } else { /* began */
            EXPECT(kb < nb && began[kb].a.index == now[j].a.index &&
                   began[kb].b.index == now[j].b.index);
            ++kb;
            ++j;
        }
    }
    EXPECT(kb == nb && ke == ne);
    t->events += (long)(nb + ne);
    *prev = realloc(*prev, (nnow + 1) * sizeof **prev);
    ck_assert_ptr_nonnull(*prev);
    if (nnow > 0)
        memcpy(*prev, now, nnow * sizeof *now);
    *nprev = nnow;
}

/* Build the family's world, or fail the test with the library's message. */
static noctWorld *build_family(const char *spec, noctScene **scene)
{
    noctError err;
    memset(&err, 0, sizeof err);
    const noctStatus st = noctSceneFamily(spec, scene, &err);
    ck_assert_msg(st == NOCT_OK, "noctSceneFamily(\"%s\"): %s", spec, err.message);
    noctWorld *w;
    ck_assert_msg(noctSceneBuild(*scene, &w, &err) == NOCT_OK, "noctSceneBuild(%s): %s", spec,
                  err.message);
    const noctWorldDef *def = noctSceneDef(*scene);
    ck_assert_int_eq(def->N, NOCT_AUTO);
    ck_assert_int_eq(def->accuracy, NOCT_ACCURACY_EXACT);
    ck_assert_uint_eq(def->effects, NOCT_EFFECT_EVENTS | NOCT_EFFECT_TRACK);
    return w;
}

/* The world's objects: their number, half-extents and filters. */
static void compare_objects(const view *v, const noctWorld *w)
{
    ck_assert_uint_eq(noctWorldObjectCount(w), v->n);
    for (size_t i = 0; i < v->n; ++i) {
        const noctObjectId id = {(uint32_t)i, 1};
        double h[3];
        ck_assert_int_eq(noctWorldGetHalfExtents(w, id, h), NOCT_OK);
        for (int k = 0; k < 3; ++k)
            ck_assert_msg(fabsl(h[k] - v->box[i].h[k]) < 1e-15L,
                          "%s: object %zu half-extent %d is %.17g, spec %.17Lg", v->spec, i, k,
                          h[k], v->box[i].h[k]);
        uint64_t cat, mask;
        ck_assert_int_eq(noctWorldGetFilter(w, id, &cat, &mask), NOCT_OK);
        if (v->cat) {
            ck_assert_msg(cat == v->cat[i] && mask == v->mask[i],
                          "%s: object %zu filter (%llu, %llu), spec (%llu, %llu)", v->spec, i,
                          (unsigned long long)cat, (unsigned long long)mask,
                          (unsigned long long)v->cat[i], (unsigned long long)v->mask[i]);
        } else {
            ck_assert(cat == NOCT_FILTER_ALL && mask == NOCT_FILTER_ALL);
        }
    }
}

/* ---- the oracle on its own ------------------------------------------------------------------ */

START_TEST(sat_closed_form)
{
    obb a, b;
    /* unit cubes (half 1) along x: apart, colliding, touching */
    obb_set(&a, 0, 0, 0, 1, 1, 1);
    obb_set(&b, 2.5L, 0, 0, 1, 1, 1);
    sat r = obb_test(&a, &b);
    ck_assert(r.verdict == APART && fabsl(r.sep - 0.5L) < 1e-15L);
    b.c[0] = 1.5L;
    r = obb_test(&a, &b);
    ck_assert(r.verdict == COLLIDING && fabsl(r.sep + 0.5L) < 1e-15L);
    b.c[0] = 2;
    ck_assert(obb_test(&a, &b).verdict == AMBIGUOUS);
    b.c[0] = 2 + 2e-9L;
    ck_assert(obb_test(&a, &b).verdict == APART);
    b.c[0] = 2 - 2e-9L;
    ck_assert(obb_test(&a, &b).verdict == COLLIDING);
    b.c[0] = 2 + 5e-10L;
    ck_assert(obb_test(&a, &b).verdict == AMBIGUOUS);
    /* a cube turned 45 degrees about z reaches sqrt 2 along x */
    ld q[4];
    quat_axis_angle((const ld[3]){0, 0, 1}, 45, q);
    obb_rotate(&a, q);
    b.c[0] = 1 + sqrtl(2) + 0.1L;
    ck_assert(obb_test(&a, &b).verdict == APART);
    b.c[0] = 1 + sqrtl(2) - 0.1L;
    ck_assert(obb_test(&a, &b).verdict == COLLIDING);
    /* edge against edge: a turned 45 degrees about z (an edge along z at
     * x = sqrt 2), b 45 degrees about y (an edge along y at x = c -
     * sqrt 2). They meet iff c <= 2 sqrt 2 (the cross axis, x), while
     * every face axis overlaps for c < 1 + 1.7071 sqrt 2 = 3.414. */
    quat_axis_angle((const ld[3]){0, 1, 0}, 45, q);
    obb_rotate(&b, q);
    b.c[0] = 3.2L;
    r = obb_test(&a, &b);
    ck_assert(r.verdict == APART && r.edge_only && r.axis >= 6);
    ck_assert(fabsl(r.sep - (3.2L - 2 * sqrtl(2))) < 1e-15L);
    b.c[0] = 2.7L;
    ck_assert(obb_test(&a, &b).verdict == COLLIDING);
    b.c[0] = 2 * sqrtl(2);
    ck_assert(obb_test(&a, &b).verdict == AMBIGUOUS);
    /* the same boxes nearly parallel: a cross axis of edges 1e-8 apart
     * cannot be trusted to show an overlap of 1e-8 */
    obb_set(&a, 0, 0, 0, 1, 1, 1);
    obb_set(&b, 2 - 1e-8L, 0, 0, 1, 1, 1);
    quat_axis_angle((const ld[3]){1, 1, 0}, 1e-7L, q);
    obb_rotate(&b, q);
    ck_assert(obb_test(&a, &b).verdict == AMBIGUOUS);
    b.c[0] = 2 - 1e-4L;
    ck_assert(obb_test(&a, &b).verdict == COLLIDING);
}
END_TEST

/* The separating-axis test against the clipping test, on random boxes:
 * turned anyhow, about a shared axis, or not at all. */
START_TEST(sat_against_clipping)
{
    uint64_t st = 0xfa3115u;
    long n[3] = {0, 0, 0}, edge = 0;
    for (int round = 0; round < 40000; ++round) {
        obb box[2];
        for (int o = 0; o < 2; ++o) {
            obb *b = &box[o];
            obb_set(b, 0, 0, 0, 0.1L + 1.4L * draw(&st), 0.1L + 1.4L * draw(&st),
                    0.1L + 1.4L * draw(&st));
            for (int k = 0; k < 3; ++k)
                b->c[k] = o ? 5 * draw(&st) - 2.5L : 0;
            const int how = round % 4;
            ld axis[3] = {0, 1, 0}, q[4];
            if (how == 0)
                for (int k = 0; k < 3; ++k)
                    axis[k] = 2 * draw(&st) - 1;
            if (how != 3 && norm3(axis) > 0.01L) {
                quat_axis_angle(axis, 360 * draw(&st) - 180, q);
                obb_rotate(b, q);
            }
        }
        const sat r = obb_test(&box[0], &box[1]);
        ++n[r.verdict];
        edge += r.edge_only;
        if (r.verdict == COLLIDING)
            ck_assert_msg(edges_meet(&box[0], &box[1], -1e-12L), "round %d: SAT colliding (%Lg)",
                          round, r.sep);
        else if (r.verdict == APART)
            ck_assert_msg(!edges_meet(&box[0], &box[1], 1e-12L), "round %d: SAT apart (%Lg)",
                          round, r.sep);
    }
    ck_assert_int_gt(n[APART], 5000);
    ck_assert_int_gt(n[COLLIDING], 5000);
    ck_assert_int_lt(n[AMBIGUOUS], 40);
    ck_assert_int_gt(edge, 100);
}
END_TEST

/* Closed-form facts of the arms, on the oracle alone. */
START_TEST(arms_closed_form)
{
    for (int K = 1; K <= 8; ++K) {
        arms s;
        arms_init(&s, K);
        const ld d = 2 * K - 0.5L;
        /* four loose boxes per m while x_m = d - 1.5 - 2.5 m > 1 (for K = 4,
         * x_2 = 1 exactly: not one more) */
        static const size_t LOOSE[9] = {0, 0, 4, 8, 8, 12, 16, 20, 24};
        ck_assert_uint_eq(s.nloose, LOOSE[K]);
        ck_assert_uint_eq(s.n, 6 + LOOSE[K] + 2 * (size_t)K);
        /* tick 0: both arms straight along x at z = 1 */
        arms_at(&s, 0);
        for (int a = 0; a < 2; ++a)
            for (int j = 0; j < K; ++j) {
                const obb *b = &s.box[s.first_link + (size_t)(a * K + j)];
                const ld cx = a ? d - 2 * j - 1 : -d + 2 * j + 1;
                ck_assert(fabsl(b->c[0] - cx) < 1e-15L && b->c[1] == 0 &&
                          fabsl(b->c[2] - 1) < 1e-15L);
                ck_assert(fabsl(b->ax[0][0] - (a ? -1 : 1)) < 1e-15L);
            }
        /* the last links overlap between x = -0.5 and 0.5: by 0.4 across */
        const size_t lastA = s.first_link + (size_t)K - 1, lastB = s.first_link + 2 * (size_t)K - 1;
        sat r = obb_test(&s.box[lastA], &s.box[lastB]);
        ck_assert(r.verdict == COLLIDING && fabsl(r.sep + 0.4L) < 1e-15L);
        /* and nothing else that the filters allow meets */
        for (size_t i = 0; i < s.n; ++i)
            for (size_t j = i + 1; j < s.n; ++j)
                if ((s.cat[i] & s.mask[j]) && (s.cat[j] & s.mask[i]) &&
                    !(i == lastA && j == lastB))
                    ck_assert_msg(obb_test(&s.box[i], &s.box[j]).verdict == APART,
                                  "arms:%d tick 0: %zu and %zu", K, i, j);
        /* at any tick, every link's own x axis is u_j, from J_j to J_j+1 */
        arms_at(&s, 37);
        for (int a = 0; a < 2; ++a) {
            ld J[3] = {a ? d : -d, 0, 1}, phi = 0;
            for (int j = 0; j < K; ++j) {
                phi += (j == 0 ? 80 : -45) * tri(37, (uint64_t)(40 + 12 * j + 10 * a));
                const obb *b = &s.box[s.first_link + (size_t)(a * K + j)];
                const ld u[3] = {(a ? -1 : 1) * cosl(radians(phi)), 0, sinl(radians(phi))};
                for (int k = 0; k < 3; ++k) {
                    ck_assert(fabsl(b->ax[0][k] - u[k]) < 1e-15L);
                    ck_assert(fabsl(b->c[k] - (J[k] + u[k])) < 1e-15L);
                    J[k] += 2 * u[k];
                }
                ck_assert(fabsl(b->ax[1][1] - 1) < 1e-15L); /* turned about y only */
            }
        }
    }
    /* the tri wave: 0 at t = 0, 1 at half a period, linear between */
    ck_assert(tri(0, 40) == 0 && tri(20, 40) == 1 && tri(40, 40) == 0 && tri(10, 40) == 0.5L);
    ck_assert(tri(25, 50) == 1 && fabsl(tri(20, 50) - 0.8L) < 1e-18L &&
              fabsl(tri(95, 50) - 0.2L) < 1e-18L);

    /* arms:1 at tick 20: A's shoulder at 80 degrees (period 40), B's at
     * 64 (period 50, f = 0.4): tips at x = -1.5 + 2 cos 80 and 1.5 - 2 cos 64 */
    arms s;
    arms_init(&s, 1);
    arms_at(&s, 20);
    const obb *A = &s.box[s.first_link], *B = &s.box[s.first_link + 1];
    ck_assert(fabsl(A->c[0] - (-1.5L + cosl(radians(80)))) < 1e-15L);
    ck_assert(fabsl(A->c[2] - (1 + sinl(radians(80)))) < 1e-15L);
    ck_assert(fabsl(B->c[0] - (1.5L - cosl(radians(64)))) < 1e-15L);
    ck_assert(obb_test(A, B).verdict == APART);

    /* arms:2, arm A bent (0, -45): link 1 goes below the floor, its lowest
     * corner at z = 1 - 2 sin 45 - 0.2 cos 45; bent (0, -20), it stays
     * 1 - 2 sin 20 - 0.2 cos 20 = 0.128 above it */
    arms_init(&s, 2);
    arms_at(&s, 0);
    const size_t floor_ = 0, a1 = s.first_link + 1;
    arms_place(&s, 0, (const ld[2]){0, -45});
    sat r = obb_test(&s.box[floor_], &s.box[a1]);
    ck_assert(r.verdict == COLLIDING);
    ck_assert(fabsl(r.sep + (2 * sinl(radians(45)) + 0.2L * cosl(radians(45)) - 1)) < 1e-15L);
    arms_place(&s, 0, (const ld[2]){0, -20});
    r = obb_test(&s.box[floor_], &s.box[a1]);
    ck_assert(r.verdict == APART);
    ck_assert(fabsl(r.sep - (1 - 2 * sinl(radians(20)) - 0.2L * cosl(radians(20)))) < 1e-15L);
    ck_assert_int_eq(r.axis, 2); /* the floor's z axis */

    /* arms:3, arm B (0, 0, -45): link 2 from (1.5, 0, 1) down to the left
     * cuts the corner (1.2, 0.6) of the loose box at x = 1.5, 0.0707 from
     * its centre line; bent by -20 it passes 0.0733 above the corner */
    arms_init(&s, 3);
    ck_assert(s.kind[6 + 5] == LOOSE_REACH && s.box[6 + 5].c[0] == 1.5L);
    const size_t b2 = s.first_link + 5;
    arms_place(&s, 1, (const ld[3]){0, 0, -45});
    ck_assert(fabsl(s.box[b2].c[0] - (1.5L - cosl(radians(45)))) < 1e-15L);
    ck_assert(obb_test(&s.box[6 + 5], &s.box[b2]).verdict == COLLIDING);
    arms_place(&s, 1, (const ld[3]){0, 0, -20});
    r = obb_test(&s.box[6 + 5], &s.box[b2]);
    ck_assert(r.verdict == APART);
    ck_assert(fabsl(r.sep - (0.4L * sinl(radians(70)) - 0.3L * cosl(radians(70)) - 0.2L)) <
              1e-15L);
    /* the boxes beside the plane (y 0.9 to 1.5) are beyond any link's y
     * (-0.2 to 0.2) */
    ck_assert(s.kind[6 + 7] == LOOSE_BESIDE);
    ck_assert(obb_test(&s.box[6 + 7], &s.box[b2]).verdict == APART);
}
END_TEST

/* The angle between two unit quaternions on the shorter arc, as
 * 2 asin(|a - b| / 2) with b's sign making a . b >= 0 (well conditioned
 * for small angles, unlike acos of the dot product). */
static ld arc(const ld a[4], const ld b[4])
{
    ld d = 0, l = 0;
    for (int k = 0; k < 4; ++k)
        d += a[k] * b[k];
    for (int k = 0; k < 4; ++k) {
        const ld x = a[k] - (d < 0 ? -b[k] : b[k]);
        l += x * x;
    }
    return 2 * asinl(sqrtl(l) / 2);
}

/* The keyframes' interpolation on its own: the keyframes at their ticks,
 * the midpoint of the shorter arc, and a constant angular speed. */
START_TEST(keyframes_closed_form)
{
    keyed s;
    keyed_init(&s, 20);
    /* the first draws of splitmix64 from 1234, by the spec's formula */
    uint64_t st = 1234;
    const ld h0 = 0.25L + 0.5L * (ld)(test_rand(&st) >> 11) * 0x1p-53L;
    ck_assert(s.h[0][0] == h0);
    ck_assert(4 * cbrtl(20) > 10.857L && 4 * cbrtl(20) < 10.858L);
    bool unsure[20];
    int shorter = 0;
    for (size_t i = 0; i < s.n; ++i)
        for (int f = 0; f < 4; ++f) {
            const ld *q0 = s.q[i][f], *q1 = s.q[i][f + 1];
            ld d = 0;
            for (int k = 0; k < 4; ++k)
                d += q0[k] * q1[k];
            shorter += d < 0;
            if (fabsl(d) > 0.9995L)
                continue; /* normalised linear: not of constant speed */
            const ld sg = d < 0 ? -1 : 1, theta = arc(q0, q1);
            ld mid[4], len = 0, qs[4];
            for (int k = 0; k < 4; ++k) {
                mid[k] = q0[k] + sg * q1[k];
                len += mid[k] * mid[k];
            }
            bool u;
            interpolate(q0, q1, 0.5L, qs, &u);
            for (int k = 0; k < 4; ++k)
                ck_assert(fabsl(qs[k] - mid[k] / sqrtl(len)) < 1e-15L);
            for (int step = 0; step <= 50; step += 10) {
                interpolate(q0, q1, step / 50.0L, qs, &u);
                ck_assert(fabsl(arc(q0, qs) - theta * step / 50) < 1e-12L);
            }
        }
    ck_assert_int_gt(shorter, 5); /* the shorter arc matters here */
    keyed_at(&s, 150, unsure);
    for (int k = 0; k < 3; ++k)
        ck_assert(s.box[7].c[k] == s.p[7][3][k]);
    keyed_at(&s, 175, unsure);
    for (int k = 0; k < 3; ++k)
        ck_assert(fabsl(s.box[7].c[k] - (s.p[7][3][k] + s.p[7][4][k]) / 2) < 1e-15L);
    keyed_free(&s);
}
END_TEST

/* ---- the families against the oracle -------------------------------------------------------- */

/* One tick, the oracle's poses already at it: the world (when there is
 * one) stepped, its poses and events compared; then the pairs. */
static void step_and_compare(const view *v, noctWorld *w, uint64_t tick, noctPair **prev,
                             size_t *nprev, tally *t)
{
    if (w != NULL) {
        noctError err;
        ck_assert_msg(noctWorldStep(w, &err) == NOCT_OK, "%s step %llu: %s", v->spec,
                      (unsigned long long)tick, err.message);
        ck_assert_uint_eq(noctWorldTick(w), tick);
        compare_poses(v, w, tick, t);
        compare_events(w, prev, nprev, t);
    }
    compare_pairs(v, w, tick, t);
}

/* The end of a run: its tally printed, the world (when there is one)
 * validated and destroyed with its scene. */
static void end_run(const view *v, noctWorld *w, noctScene *scene, noctPair *prev,
                    const tally *t)
{
    print_tally(v->spec, t);
    if (w != NULL) {
        ck_assert_int_eq(noctWorldValidate(w, NULL), NOCT_OK);
        noctWorldDestroy(w);
        noctSceneDestroy(scene);
    }
    free(prev);
}

static void check_arms(int K, bool with_world)
{
    char spec[32];
    snprintf(spec, sizeof spec, "arms:%d", K);
    arms s;
    arms_init(&s, K);
    noctScene *scene = NULL;
    noctWorld *w = NULL;
    const view v = {spec, s.n, s.box, NULL, s.cat, s.mask, &s};
    tally t;
    memset(&t, 0, sizeof t);
    noctPair *prev = NULL;
    size_t nprev = 0;
    if (with_world) {
        w = build_family(spec, &scene);
        ck_assert_int_eq(noctSceneSteps(scene), 240);
        compare_objects(&v, w);
        arms_at(&s, 0);
        compare_poses(&v, w, 0, &t);
    }
    for (uint64_t tick = 1; tick <= 240; ++tick) {
        arms_at(&s, tick);
        step_and_compare(&v, w, tick, &prev, &nprev, &t);
    }
    end_run(&v, w, scene, prev, &t);
    ck_assert_msg(t.mismatches == 0, "%s: %ld disagreements with the oracle; the first: %s",
                  spec, t.mismatches, t.first);
    /* the scene is not vacuous: its pairs collide and part */
    ck_assert_int_lt(t.ambiguous * 100, t.checks + t.ambiguous); /* under 1% */
    /* (the oracle finds, steps with arm-arm / link-floor / link-loose
     * pairs: arms:1 62/0/0, arms:2 28/14/0, arms:3 13/86/76, arms:5
     * 7/168/131, arms:8 5/235/203) */
    ck_assert_int_ge(t.steps_with[ARM_ARM], 5);
    ck_assert_int_lt(t.steps_with[ARM_ARM], 240);
    if (K >= 2)
        ck_assert_int_ge(t.steps_with[LINK_FLOOR], 10);
    if (K >= 3)
        ck_assert_int_ge(t.steps_with[LINK_LOOSE], 50);
    ck_assert_int_lt(t.steps_with[LINK_FLOOR], 240);
    /* pairs the filters forbid meet all the time: the walls at their 12
     * corners, the loose boxes on the floor (touching), adjacent links */
    ck_assert_int_eq(t.colliding[WALL_WALL], 240 * 12);
    ck_assert_int_ge(t.forbidden_overlap, 240 * (12 + (long)s.nloose + (K - 1) * 2));
    if (K >= 2)
        ck_assert_int_gt(t.colliding[SAME_ARM], 0);
    /* out of reach: beside the arms' plane, the y walls, the ceiling */
    ck_assert_int_eq(t.colliding[LINK_BESIDE], 0);
    ck_assert_int_eq(t.colliding[LINK_YWALL], 0);
    ck_assert_int_eq(t.colliding[LINK_CEILING], 0);
}

START_TEST(arms_oracle_alone)
{
    check_arms(_i, false);
}
END_TEST

START_TEST(arms_world)
{
    static const int K[4] = {1, 2, 3, 5};
    check_arms(K[_i], true);
}
END_TEST

static void check_keyframes(size_t N, bool with_world)
{
    char spec[32];
    snprintf(spec, sizeof spec, "keyframes:%zu", N);
    keyed s;
    keyed_init(&s, N);
    bool *unsure = calloc(N, sizeof *unsure);
    ck_assert_ptr_nonnull(unsure);
    noctScene *scene = NULL;
    noctWorld *w = NULL;
    const view v = {spec, N, s.box, unsure, NULL, NULL, NULL};
    tally t;
    memset(&t, 0, sizeof t);
    noctPair *prev = NULL;
    size_t nprev = 0;
    if (with_world) {
        w = build_family(spec, &scene);
        ck_assert_int_eq(noctSceneSteps(scene), 200);
        compare_objects(&v, w);
        keyed_at(&s, 0, unsure);
        compare_poses(&v, w, 0, &t);
    }
    for (uint64_t tick = 1; tick <= 200; ++tick) {
        keyed_at(&s, tick, unsure);
        for (size_t i = 0; i < N; ++i)
            t.unsure_objects += unsure[i];
        step_and_compare(&v, w, tick, &prev, &nprev, &t);
    }
    end_run(&v, w, scene, prev, &t);
    free(unsure);
    keyed_free(&s);
    ck_assert_msg(t.mismatches == 0, "%s: %ld disagreements with the oracle; the first: %s",
                  spec, t.mismatches, t.first);
    ck_assert_int_lt(t.ambiguous * 100, t.checks + t.ambiguous); /* under 1% */
    ck_assert_int_eq(t.checks + t.ambiguous, 200 * (long)(N * (N - 1) / 2));
    ck_assert_int_gt(t.colliding[OTHER], (long)N);
    ck_assert_int_gt(t.apart_close, (long)N / 4);
    ck_assert_int_gt(t.steps_with[OTHER], 100);
}

START_TEST(keyframes_oracle_alone)
{
    check_keyframes(_i == 0 ? 20 : 200, false);
}
END_TEST

START_TEST(keyframes_world)
{
    check_keyframes(_i == 0 ? 20 : 200, true);
}
END_TEST

/* notch:N against noctree-sim(1)'s definition, read here: each pair's
 * prism and cube where the LCG puts them, with their velocities; the
 * prism's solid (a point in its notch is outside, one in a bar inside);
 * and the events at every N and maintenance mode those of the exhaustive
 * algorithm. */
START_TEST(notch_by_definition)
{
    const long n = 10, g = 4; /* ceil(sqrt(10)) */
    noctScene *sc;
    noctError err;
    ck_assert_int_eq(noctSceneFamily("notch:10", &sc, &err), NOCT_OK);
    noctWorld *w;
    ck_assert_int_eq(noctSceneBuild(sc, &w, &err), NOCT_OK);
    ck_assert_uint_eq(noctWorldObjectCount(w), 2 * (size_t)n);
    uint64_t s = 42;
    for (long i = 0; i < n; ++i) {
        s = s * 6364136223846793005u + 1442695040888963407u;
        const double r = (double)(s >> 11) * 0x1p-53;
        const double base[3] = {5.0 * (double)(i % g), 5.0 * (double)(i / g), 0};
        const double cube[3] = {base[0] + 0.25 + 0.15 + r * (3 - 0.5 - 0.3), base[1] + 1.5, 0.5};
        const double dir = i % 4 < 2 ? 1 : -1, speed = i % 2 ? 0.7 : 0.04;
        const noctObjectId u = {(uint32_t)(2 * i), 1}, c = {(uint32_t)(2 * i + 1), 1};
        double p[3], v[3], lo[3], hi[3];
        noctObjectType type;
        ck_assert_int_eq(noctWorldObject(w, u, p, NULL), NOCT_OK);
        ck_assert(p[0] == base[0] && p[1] == base[1] && p[2] == 0);
        ck_assert_int_eq(noctWorldGetVelocity(w, u, v), NOCT_OK);
        ck_assert(v[0] == 0 && v[1] == 0 && v[2] == 0);
        ck_assert_int_eq(noctWorldObjectBox(w, u, lo, hi), NOCT_OK);
        ck_assert(lo[0] == base[0] && hi[0] == base[0] + 3 && hi[1] == base[1] + 3 && hi[2] == 1);
        ck_assert_int_eq(noctWorldObject(w, c, p, NULL), NOCT_OK);
        ck_assert_msg(p[0] == cube[0] && p[1] == cube[1] && p[2] == cube[2],
                      "cube %ld at (%g, %g, %g)", i, p[0], p[1], p[2]);
        ck_assert_int_eq(noctWorldGetVelocity(w, c, v), NOCT_OK);
        ck_assert(fabs(v[0] - dir * speed) <= 1e-15 && v[1] == 0 && v[2] == 0);
        ck_assert_int_eq(noctWorldGetType(w, c, &type), NOCT_OK);
        ck_assert_int_eq(type, NOCT_OBJECT_MOVING);
        ck_assert_int_eq(noctWorldObjectBox(w, c, lo, hi), NOCT_OK);
        ck_assert(fabs(hi[0] - lo[0] - 0.3) <= 1e-12 && fabs(hi[2] - lo[2] - 0.3) <= 1e-12);
    }
    /* the prism's solid: its notch is empty, its bars are not */
    const noctMesh *m = noctWorldGetMesh(w, (noctObjectId){0, 1});
    ck_assert_ptr_nonnull(m);
    bool hit;
    noctMesh *probe;
    ck_assert_int_eq(noctMeshCreateBox(0.01, 0.01, 0.01, &probe, &err), NOCT_OK);
    ck_assert_int_eq(noctCollide(m, (const double[3]){0, 0, 0}, probe,
                                 (const double[3]){1.5, 1.5, 0.5}, NOCT_ACCURACY_EXACT, &hit,
                                 NULL), NOCT_OK);
    ck_assert(!hit);
    ck_assert_int_eq(noctCollide(m, (const double[3]){0, 0, 0}, probe,
                                 (const double[3]){0.125, 1.5, 0.5}, NOCT_ACCURACY_EXACT, &hit,
                                 NULL), NOCT_OK);
    ck_assert(hit);
    noctMeshDestroy(probe);
    noctWorldDestroy(w);
    /* the same events at N = 1, 2 and the defaults as exhaustively */
    uint64_t hashes[4];
    const int Ns[4] = {NOCT_N_EXHAUSTIVE, 1, 2, NOCT_AUTO};
    for (int k = 0; k < 4; ++k) {
        noctSceneDef(sc)->N = Ns[k];
        ck_assert_int_eq(noctSceneBuild(sc, &w, &err), NOCT_OK);
        uint64_t h = 1469598103934665603u, began = 0;
        for (int step = 0; step < 200; ++step) {
            ck_assert_int_eq(noctWorldStep(w, &err), NOCT_OK);
            const noctPair *pairs;
            const size_t nb = noctWorldBegan(w, &pairs);
            began += nb;
            for (size_t j = 0; j < nb; ++j)
                h = (h ^ (pairs[j].a.index * 131u + pairs[j].b.index + (uint64_t)step * 7919u)) *
                    1099511628211u;
        }
        hashes[k] = h;
        ck_assert_msg(began > 0, "notch: no contact in 200 steps");
        ck_assert_msg(hashes[k] == hashes[0], "N = %d: other events than the exhaustive", Ns[k]);
        noctWorldDestroy(w);
    }
    noctSceneDestroy(sc);
}
END_TEST

/* bullets:N against noctree-sim(1)'s definition, read here: every
 * object where the draws put it, its size, type and velocity; two builds
 * the same; and the family's point: without sub-steps the exact level,
 * looking at each step's start and end, misses contacts that continuous
 * detection finds, and finds none that it does not. */
static uint64_t bullets_hash(noctScene *sc, noctAccuracy acc, uint64_t *entries)
{
    noctError err;
    noctWorld *w;
    noctSceneDef(sc)->accuracy = acc;
    noctSceneDef(sc)->effects = NOCT_EFFECT_MOTION | NOCT_EFFECT_EVENTS;
    ck_assert_int_eq(noctSceneBuild(sc, &w, &err), NOCT_OK);
    uint64_t h = 1469598103934665603u;
    *entries = 0;
    for (int step = 0; step < 40; ++step) {
        ck_assert_int_eq(noctWorldStep(w, &err), NOCT_OK);
        const noctPair *p;
        const size_t n = noctWorldColliding(w, &p);
        *entries += n;
        for (size_t j = 0; j < n; ++j)
            h = (h ^ (p[j].a.index * 131u + p[j].b.index + (uint64_t)step * 7919u)) *
                1099511628211u;
    }
    noctWorldDestroy(w);
    return h;
}

START_TEST(bullets_by_definition)
{
    const size_t n = 200;
    noctScene *sc;
    noctError err;
    ck_assert_int_eq(noctSceneFamily("bullets:200", &sc, &err), NOCT_OK);
    noctWorld *w;
    ck_assert_int_eq(noctSceneBuild(sc, &w, &err), NOCT_OK);
    ck_assert_uint_eq(noctWorldObjectCount(w), n);
    const noctWorldDef *def = noctSceneDef(sc);
    const double L = cbrt(10.0 * (double)n);
    ck_assert(def->effects & NOCT_EFFECT_WALLS);
    for (int k = 0; k < 3; ++k)
        ck_assert(def->walls_lo[k] == 0 && def->walls_hi[k] == L);
    uint64_t s = 4242;
    size_t bullets = 0, plates = 0, boxes = 0;
    for (size_t i = 0; i < n; ++i) {
        const noctObjectId id = {(uint32_t)i, 1};
        double at[3], p[3], v[3], lo[3], hi[3];
        noctObjectType type;
        for (int k = 0; k < 3; ++k)
            at[k] = L * (double)draw(&s);
        ck_assert_int_eq(noctWorldObject(w, id, p, NULL), NOCT_OK);
        ck_assert_msg(p[0] == at[0] && p[1] == at[1] && p[2] == at[2], "object %zu misplaced",
                      i);
        ck_assert_int_eq(noctWorldGetVelocity(w, id, v), NOCT_OK);
        ck_assert_int_eq(noctWorldGetType(w, id, &type), NOCT_OK);
        if (i % 10 <= 2) {
            const int a = (int)(3 * draw(&s)) % 3;
            const bool bullet = i % 10 == 0;
            ck_assert_int_eq(noctWorldObjectBox(w, id, lo, hi), NOCT_OK);
            for (int k = 0; k < 3; ++k) {
                const double h = k == a ? 0.02 : bullet ? 0.3 : 1.0;
                ck_assert_msg(fabs(hi[k] - lo[k] - 2 * h) <= 1e-12, "object %zu's size", i);
            }
            if (bullet) {
                const double dir = draw(&s) < 0.5 ? 1 : -1;
                for (int k = 0; k < 3; ++k)
                    ck_assert(v[k] == (k == a ? 0.5 * dir : 0));
                ck_assert_int_eq(type, NOCT_OBJECT_MOVING);
                ++bullets;
            } else {
                ck_assert(v[0] == 0 && v[1] == 0 && v[2] == 0);
                ck_assert_int_eq(type, NOCT_OBJECT_STATIC);
                ++plates;
            }
        } else {
            for (int k = 0; k < 8; ++k) /* sizes, turn, direction */
                (void)draw(&s);
            ck_assert(fabs(sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) - 0.05) <= 1e-12);
            ck_assert_int_eq(type, NOCT_OBJECT_MOVING);
            ++boxes;
        }
    }
    ck_assert_uint_eq(bullets, 20);
    ck_assert_uint_eq(plates, 40);
    ck_assert_uint_eq(boxes, 140);
    noctWorldDestroy(w);
    /* determinism: the same answers from two scenes */
    noctScene *again;
    ck_assert_int_eq(noctSceneFamily("bullets:200", &again, &err), NOCT_OK);
    uint64_t e1, e2;
    ck_assert(bullets_hash(sc, NOCT_ACCURACY_EXACT, &e1) ==
              bullets_hash(again, NOCT_ACCURACY_EXACT, &e2));
    noctSceneDestroy(again);
    /* the exact level's step answers (its start and end: the colliding
     * lists before and after) within the continuous level's, and fewer */
    noctWorld *x, *c;
    noctSceneDef(sc)->effects = NOCT_EFFECT_MOTION | NOCT_EFFECT_EVENTS;
    noctSceneDef(sc)->accuracy = NOCT_ACCURACY_EXACT;
    ck_assert_int_eq(noctSceneBuild(sc, &x, &err), NOCT_OK);
    noctSceneDef(sc)->accuracy = NOCT_ACCURACY_CONTINUOUS;
    ck_assert_int_eq(noctSceneBuild(sc, &c, &err), NOCT_OK);
    size_t seen = 0, missed = 0;
    noctPair *before = NULL;
    size_t nbefore = 0;
    for (int step = 0; step < 40; ++step) {
        ck_assert_int_eq(noctWorldStep(x, &err), NOCT_OK);
        ck_assert_int_eq(noctWorldStep(c, &err), NOCT_OK);
        const noctPair *px, *pc;
        const size_t nx = noctWorldColliding(x, &px), nc = noctWorldColliding(c, &pc);
        for (int side = 0; side < 2; ++side) {
            const noctPair *q = side ? before : px;
            const size_t nq = side ? nbefore : nx;
            for (size_t j = 0; j < nq; ++j) {
                bool found = false;
                for (size_t k = 0; k < nc && !found; ++k)
                    found = pc[k].a.index == q[j].a.index && pc[k].b.index == q[j].b.index;
                ck_assert_msg(found, "step %d: exact sees (%u, %u), continuous does not",
                              step + 1, q[j].a.index, q[j].b.index);
            }
        }
        for (size_t k = 0; k < nc; ++k) {
            bool found = false;
            for (int side = 0; side < 2 && !found; ++side) {
                const noctPair *q = side ? before : px;
                const size_t nq = side ? nbefore : nx;
                for (size_t j = 0; j < nq && !found; ++j)
                    found = pc[k].a.index == q[j].a.index && pc[k].b.index == q[j].b.index;
            }
            if (found)
                ++seen;
            else
                ++missed;
        }
        free(before);
        before = malloc((nx ? nx : 1) * sizeof *before);
        ck_assert_ptr_nonnull(before);
        memcpy(before, px, nx * sizeof *px);
        nbefore = nx;
    }
    ck_assert_msg(seen > 0 && missed > 0, "bullets: exact saw %zu, missed %zu", seen, missed);
    free(before);
    noctWorldDestroy(x);
    noctWorldDestroy(c);
    noctSceneDestroy(sc);
}
END_TEST

START_TEST(bad_family_specs)
{
    static const char *const BAD[] = {"arms:0", "arms:9", "keyframes:0", "arms:x",
                                      "arms:", "arms:3x", "arms:-1", "keyframes:100001",
                                      "keyframes:", "keyframe:5", "arm:3",
                                      "bullets:0", "bullets:10000001", "bullet:5"};
    for (size_t i = 0; i < sizeof BAD / sizeof *BAD; ++i) {
        static char not_null;
        noctScene *s = (noctScene *)(void *)&not_null;
        noctError err;
        memset(&err, 0, sizeof err);
        ck_assert_msg(noctSceneFamily(BAD[i], &s, &err) == NOCT_ERR_INVALID, "'%s' accepted",
                      BAD[i]);
        ck_assert_ptr_null(s);
        ck_assert_int_eq(err.status, NOCT_ERR_INVALID);
        ck_assert_msg(err.message[0] != '\0', "'%s': no message", BAD[i]);
    }
    /* the ends of the ranges are families */
    static const char *const GOOD[] = {"arms:1", "arms:8", "keyframes:1", "keyframes:100000",
                                       "bullets:1"};
    for (size_t i = 0; i < sizeof GOOD / sizeof *GOOD; ++i) {
        noctScene *s;
        noctError err;
        ck_assert_msg(noctSceneFamily(GOOD[i], &s, &err) == NOCT_OK, "'%s': %s", GOOD[i],
                      err.message);
        noctSceneDestroy(s);
    }
}
END_TEST

static Suite *families_suite(void)
{
    Suite *s = suite_create("families");
    TCase *tc = test_case(s, "oracle", 60, NULL);
    add_tests(tc, sat_closed_form, arms_closed_form, keyframes_closed_form);
    tcase_add_loop_test(tc, arms_oracle_alone, 1, 3);
    tcase_add_loop_test(tc, keyframes_oracle_alone, 0, 1);
    /* the larger cases: left out under valgrind */
    TCase *big = test_case(s, "oracle, large", 120, "slow");
    tcase_add_test(big, sat_against_clipping);
    tcase_add_loop_test(big, arms_oracle_alone, 3, 9);
    tcase_add_loop_test(big, keyframes_oracle_alone, 1, 2);
    tcase_add_loop_test(big, arms_world, 2, 4);
    tcase_add_loop_test(big, keyframes_world, 1, 2);
    tc = test_case(s, "families", 120, NULL);
    tcase_add_loop_test(tc, arms_world, 0, 2);
    tcase_add_loop_test(tc, keyframes_world, 0, 1);
    add_tests(tc, notch_by_definition, bullets_by_definition, bad_family_specs);
    return s;
}

int main(void)
{
    return run_suite(families_suite());
}
