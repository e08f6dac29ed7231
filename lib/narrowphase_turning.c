/* SPDX-License-Identifier: MIT */
/*
 * Continuous detection of turning motions: the conservative level
 * (noctCollideSweptTransformed(), and the world's pairs where an object
 * turns during a step).
 *
 * A shape (a mesh, or a box primitive's half-extents) moves from (q0, p0)
 * to (q1, p1): at time t in [0, 1] its rotation is the shorter-arc
 * interpolation of q0 and q1 and its translation p0 + t (p1 - p0). A
 * point at distance r from the shape's origin then moves at most
 * s = |p1 - p0| + r theta per unit of time, theta the turn's angle. So if
 * at time t the two solids are more than (sA + sB) dt apart, they cannot
 * meet before t + dt: conservative advancement, with the margin's proved
 * lower bound (noct_solids_within()) as the distance. Where no interval
 * can be proved free before the bound falls under eps (narrowphase.h),
 * they are reported near. The placements at a time t are rounded (the
 * rotated vertices, the interpolated quaternion, the translation): a
 * slack of 2^-36 of the coordinates' magnitude, added to every distance
 * asked, covers that rounding and the margin's own slack by far.
 */
#include "config.h"

#include <float.h>
#include <math.h>
#include <string.h>

#include <noctree/narrowphase.h>

#include "narrowphase_internal.h"
#include "vec3.h"

/* Most placements the advancement tests (narrowphase.h says about
 * 25 000): 2 / 1024 of the motion per advance at least, each after at
 * most about a dozen halvings. A pair that would need more (never, by
 * that count) is reported near, the conservative answer. */
#define MAX_TESTS 30000

/* The shape at a time of its motion. */
typedef struct posed {
    const noctMesh *m;
    noctMesh *owned;      /* a rotated copy, freed by unpose() */
    noctMesh view;        /* a box primitive's corners */
    bvh_node leaf;
    double v[24];
    double t[3];
    noct_box_slot slot;   /* its box form, when has_box */
} posed;

static void unpose(posed *P)
{
    noctMeshDestroy(P->owned);
    P->owned = NULL;
}

static noctStatus pose_at(const noct_turning *T, double time, posed *P)
{
    noctQuat q = time == 0 ? T->q0 : time == 1 ? T->q1 : noct_quat_slerp(&T->q0, &T->q1, time);
    double R[9];
    noctStatus st = noctQuatToMatrix(&q, R, NULL);
    if (st != NOCT_OK)
        return st;
    P->owned = NULL;
    for (int k = 0; k < 3; ++k)
        P->t[k] = time == 0   ? T->p0[k]
                  : time == 1 ? T->p1[k]
                              : T->p0[k] + time * (T->p1[k] - T->p0[k]);
    P->slot.has_box = 0;
    if (T->shape == NULL) {
        noct_box_corners(T->half, R, P->v);
        noct_box_view(P->v, &P->view, &P->leaf);
        P->m = &P->view;
        double lo[3], hi[3];
        noct_box_slot_of_box(T->half, R, &P->slot, lo, hi);
        return NOCT_OK;
    }
    if (noct_is_identity(R)) {
        P->m = T->shape;
    } else {
        st = noct_mesh_rotated(T->shape, R, &P->owned, NULL);
        P->m = P->owned;
    }
    if (st == NOCT_OK && P->m->has_box)
        noct_box_slot_fill(P->m, &P->slot);
    return st;
}

/* Are the two placed solids within d of each other (never false when
 * they are)? Two boxes first by their box forms' separating axes. */
static bool within(const posed *A, const posed *B, double d)
{
    if (A->slot.has_box && B->slot.has_box &&
        noct_box_apart_by(&A->slot, A->t, &B->slot, B->t, d))
        return false;
    return noct_solids_within(A->m, A->t, B->m, B->t, d);
}

/* The farthest any of the shape's points is from its origin, rounded up. */
static double radius_of(const noct_turning *T)
{
    double r2 = 0;
    if (T->shape == NULL) {
        r2 = noct_dot3(T->half, T->half);
    } else {
        for (size_t i = 0; i < T->shape->nv; ++i)
            r2 = noct_max(r2, noct_dot3(&T->shape->v[3 * i], &T->shape->v[3 * i]));
    }
    return sqrt(r2) * (1 + 0x1p-40);
}

/* The turn's angle, rounded up (acos near 1 loses half the digits: the
 * bound adds 2^-24), as a rate: for turns under about 3.6 degrees the
 * interpolation is normalized linear (noct_quat_slerp()), whose angle
 * grows unevenly, at most 1 + phi^2 / 12 times the mean rate for a half
 * angle phi (under 1e-4 there): the bound allows 2^-10 more. */
static double angle_of(const noct_turning *T)
{
    const noctQuat *a = &T->q0, *b = &T->q1;
    double d = fabs(a->x * b->x + a->y * b->y + a->z * b->z + a->w * b->w);
    return 2 * acos(noct_min(d, 1)) * (1 + 0x1p-10) + 0x1p-24;
}

/* How far any point of the shape moves per unit of time, at most. */
static double speed_of(const noct_turning *T, double r)
{
    double d[3];
    noct_sub3(T->p1, T->p0, d);
    double len = noct_norm3(d) * (1 + 0x1p-40);
    bool turns = memcmp(&T->q0, &T->q1, sizeof T->q0) != 0;
    return len + (turns ? r * angle_of(T) : 0);
}

/* Magnitude of the coordinates the motion's placements reach. */
static double magnitude_of(const noct_turning *T, double r)
{
    double m = r;
    for (int k = 0; k < 3; ++k)
        m = noct_max(m, noct_max(fabs(T->p0[k]), fabs(T->p1[k])) + r);
    return m;
}

static noctStatus placed_meet(const posed *A, const posed *B, bool *hit, noctNarrowStats *st)
{
    if (!noct_boxes_overlap(A->m->lo, A->m->hi, A->t, B->m->lo, B->m->hi, B->t)) {
        *hit = false;
        return NOCT_OK;
    }
    return noct_collide_overlapping(A->m, A->t, B->m, B->t, NOCT_ACCURACY_EXACT, hit, st);
}

static void report(noctSweepHit *hit, double time, noctSweepFeature f, const posed *A,
                   const posed *B)
{
    if (hit == NULL)
        return;
    hit->time = time;
    hit->feature = f;
    hit->conservative = true;
    noct_box_overlap_centre(A->m, A->t, B->m, B->t, hit->point);
}

noctStatus noct_collide_turning(const noct_turning *TA, const noct_turning *TB, bool *colliding,
                                noctSweepHit *hit, noctNarrowStats *stats)
{
    if (hit != NULL) {
        noct_sweep_hit_none(hit);
        hit->conservative = true;
    }
    const double ra = radius_of(TA), rb = radius_of(TB);
    const double speed = (speed_of(TA, ra) + speed_of(TB, rb)) * (1 + 0x1p-40);
    const double slack = 0x1p-36 * (magnitude_of(TA, ra) + magnitude_of(TB, rb));
    const double eps = noct_max(0x1p-20 * (ra + rb), speed / 1024);
    posed A, B;
    noctStatus st;
    double time = 0;
    int tests = 0;
    *colliding = false;
    if ((st = pose_at(TA, 0, &A)) != NOCT_OK)
        return st;
    if ((st = pose_at(TB, 0, &B)) != NOCT_OK) {
        unpose(&A);
        return st;
    }
    bool touch;
    st = placed_meet(&A, &B, &touch, stats);
    if (st == NOCT_OK && touch) {
        *colliding = true;
        report(hit, 0, NOCT_SWEEP_START, &A, &B);
    }
    /* Each advance tries twice the last interval first (at most what is
     * left): about two tests an advance, where starting from the rest
     * would halve down to it each time. */
    double last = 1;
    while (st == NOCT_OK && !*colliding && time < 1) {
        double dt = noct_min(2 * last, 1 - time);
        for (;;) {
            const double reach = speed * dt + slack;
            if (++tests <= MAX_TESTS && !within(&A, &B, reach)) {
                time = dt == 1 - time ? 1 : time + dt;
                last = dt;
                break;
            }
            if (tests > MAX_TESTS || reach <= eps + slack) {
                /* within reach of each other now: near */
                *colliding = true;
                report(hit, time, NOCT_SWEEP_NEAR, &A, &B);
                break;
            }
            dt /= 2;
        }
        if (*colliding)
            break;
        unpose(&A);
        unpose(&B);
        if ((st = pose_at(TA, time, &A)) != NOCT_OK)
            return st;
        if ((st = pose_at(TB, time, &B)) != NOCT_OK) {
            unpose(&A);
            return st;
        }
        if (time == 1) {
            st = placed_meet(&A, &B, &touch, stats);
            if (st == NOCT_OK && touch) {
                *colliding = true;
                report(hit, 1, NOCT_SWEEP_END, &A, &B);
            }
        }
    }
    unpose(&A);
    unpose(&B);
    return st;
}

noctStatus noctCollideSweptTransformed(const noctMesh *a, const noctTransform *xa0,
                                       const noctTransform *xa1, const noctMesh *b,
                                       const noctTransform *xb0, const noctTransform *xb1,
                                       bool *colliding, noctSweepHit *hit,
                                       noctNarrowStats *stats, noctError *err)
{
    NOCT_REQUIRE(a != NULL && xa0 != NULL && xa1 != NULL && b != NULL);
    NOCT_REQUIRE(xb0 != NULL && xb1 != NULL && colliding != NULL);
    const noctTransform *x[4] = {xa0, xa1, xb0, xb1};
    for (int i = 0; i < 4; ++i) {
        noctStatus st = noctTransformCheck(x[i], err);
        if (st != NOCT_OK)
            return st;
    }
    const bool turns = memcmp(&xa0->q, &xa1->q, sizeof xa0->q) != 0 ||
                       memcmp(&xb0->q, &xb1->q, sizeof xb0->q) != 0;
    noctStatus st = NOCT_OK;
    if (turns) {
        const noct_turning A = {a, NULL, xa0->q, xa1->q, xa0->p, xa1->p};
        const noct_turning B = {b, NULL, xb0->q, xb1->q, xb0->p, xb1->p};
        st = noct_collide_turning(&A, &B, colliding, hit, stats);
    } else {
        /* Neither turns: the exact level on the meshes as rotated. */
        posed A, B;
        const noct_turning TA = {a, NULL, xa0->q, xa0->q, xa0->p, xa0->p};
        const noct_turning TB = {b, NULL, xb0->q, xb0->q, xb0->p, xb0->p};
        st = pose_at(&TA, 0, &A);
        if (st == NOCT_OK && (st = pose_at(&TB, 0, &B)) != NOCT_OK)
            unpose(&A);
        if (st == NOCT_OK) {
            st = noctCollideSwept(A.m, xa0->p, xa1->p, B.m, xb0->p, xb1->p, colliding, hit,
                                  stats);
            unpose(&A);
            unpose(&B);
        }
    }
    if (st != NOCT_OK)
        noct_fail(err, st, -1, 0, "swept collision test: %s", noctStatusString(st));
    return st;
}
