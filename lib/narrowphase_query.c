/* SPDX-License-Identifier: MIT */
/*
 * The narrowphase's queries on one placed mesh: is a point in the solid
 * (exactly; on the boundary counts), and where does a segment first meet
 * it (the entered triangle, its fraction and unit normal). The world's
 * point and ray queries ask them (world_query.c).
 */
#include "config.h"

#include <math.h>
#include <string.h>

#include "narrowphase_internal.h"

typedef struct point_on {
    const double *p;
    exact_ctx x;
} point_on;

static bool point_on_triangle(void *context, uint32_t i, double a[3], double b[3], double c[3])
{
    (void)i;
    const point_on *q = context;
    return o3(&q->x, a, b, c, q->p) == 0 && seg_tri(&q->x, q->p, q->p, 0, 0, a, b, c);
}

/* Is p on a triangle of B (closed)? */
static bool on_boundary(const placed *B, const double p[3], const exact_ctx *x)
{
    point_on q = {p, *x};
    return noct_bvh_box_walk(B, p, p, point_on_triangle, &q);
}

noctStatus noct_point_in_solid(const noctMesh *m, const double t[3], const double p[3],
                               bool *inside)
{
    const placed B = {m, {t[0], t[1], t[2]}};
    const exact_ctx x = {NULL};
    *inside = false;
    if (!noct_boxes_overlap(m->lo, m->hi, t, p, p, (const double[3]){0, 0, 0}))
        return NOCT_OK;
    if (on_boundary(&B, p, &x)) {
        *inside = true;
        return NOCT_OK;
    }
    return noct_contains(&B, p, &x, inside);
}

/* Where segment pq, known to meet closed triangle abc and not to start on
 * it, meets it first: the fraction along pq, in floating point, in
 * [0, 1]. Crossing its plane: where the plane's function changes sign.
 * In its plane: the least fraction at which pq meets an edge, in the
 * projection that keeps the triangle's area. */
static double entry_fraction(const double p[3], const double q[3], const double a[3],
                             const double b[3], const double c[3], const double n[3], bool flat)
{
    double d[3];
    for (int k = 0; k < 3; ++k)
        d[k] = q[k] - p[k];
    if (!flat) {
        double fp = 0, fq = 0;
        for (int k = 0; k < 3; ++k) {
            fp += n[k] * (p[k] - a[k]);
            fq += n[k] * (q[k] - a[k]);
        }
        const double f = fp != fq ? fp / (fp - fq) : 0;
        return f > 0 ? (f < 1 ? f : 1) : 0;
    }
    int drop = 0;
    for (int k = 1; k < 3; ++k)
        if (fabs(n[k]) > fabs(n[drop]))
            drop = k;
    const int i = (drop + 1) % 3, j = (drop + 2) % 3;
    const double *const v[3] = {a, b, c};
    double best = 1;
    for (int e = 0; e < 3; ++e) {
        const double *u = v[e], *w = v[(e + 1) % 3];
        const double ex = w[i] - u[i], ey = w[j] - u[j];
        const double den = d[i] * ey - d[j] * ex;
        if (den == 0)
            continue;
        const double rx = u[i] - p[i], ry = u[j] - p[j];
        const double s = (rx * ey - ry * ex) / den;  /* along pq */
        const double r = (rx * d[j] - ry * d[i]) / den; /* along the edge */
        if (s >= 0 && s < best && r >= -1e-12 && r <= 1 + 1e-12)
            best = s;
    }
    return best;
}

/* The unit vector along u x v into n, computed on u and v scaled by
 * powers of two so that no product overflows or underflows, at any edge
 * length a mesh may have; false (n = 0) if u x v is 0 as computed: a
 * triangle without area as placed. */
static bool unit_cross(const double u[3], const double v[3], double n[3])
{
    double us[3], vs[3], c[3];
    n[0] = n[1] = n[2] = 0;
    if (!noct_scale_to_unit(u, us) || !noct_scale_to_unit(v, vs))
        return false;
    noct_cross3(us, vs, c);
    return noct_unit3(c, n);
}

/* The first triangle segment pq enters, so far. */
typedef struct segment_entry {
    const double *p, *q;
    exact_ctx x;
    double best;
    uint32_t triangle;
    double *normal;
    bool flat;            /* that triangle has no area as placed */
    bool surface;         /* a surface's: the normal faces the segment's start */
} segment_entry;

static bool segment_meets(void *context, uint32_t i, double a[3], double b[3], double c[3])
{
    segment_entry *e = context;
    const int s1 = o3(&e->x, a, b, c, e->p), s2 = o3(&e->x, a, b, c, e->q);
    if (!seg_tri(&e->x, e->p, e->q, s1, s2, a, b, c))
        return false;
    double u[3], v[3], nn[3], d[3];
    for (int k = 0; k < 3; ++k) {
        u[k] = b[k] - a[k];
        v[k] = c[k] - a[k];
        d[k] = e->q[k] - e->p[k];
    }
    const bool area = unit_cross(u, v, nn);
    double f;
    if (area) {
        f = entry_fraction(e->p, e->q, a, b, c, nn, s1 == 0 && s2 == 0);
    } else {
        /* a point or a segment as placed (a shape far from the origin
         * for its size): where pq passes nearest its first corner, which
         * is within the triangle's extent of the meeting point */
        double num = 0, den = 0;
        for (int k = 0; k < 3; ++k) {
            num += (a[k] - e->p[k]) * d[k];
            den += d[k] * d[k];
        }
        f = den > 0 && num > 0 ? (num < den ? num / den : 1) : 0;
    }
    if (f < e->best || (f == e->best && i < e->triangle)) {
        e->best = f;
        e->triangle = i;
        e->flat = !area;
        if (area) {
            const bool away = e->surface && nn[0] * d[0] + nn[1] * d[1] + nn[2] * d[2] > 0;
            for (int k = 0; k < 3; ++k)
                e->normal[k] = away ? -nn[k] : nn[k];
        } else { /* against the segment: a normal a program can use */
            const double back[3] = {-d[0], -d[1], -d[2]};
            noct_unit3(back, e->normal);
        }
    }
    return false; /* on: the least fraction */
}

noctStatus noct_segment_hit(const noctMesh *m, const double t[3], const double p[3],
                            const double q[3], bool *hit, double *fraction,
                            uint32_t *triangle, double normal[3], bool *flat)
{
    const placed B = {m, {t[0], t[1], t[2]}};
    const exact_ctx x = {NULL};
    *hit = false;
    *flat = false;
    *triangle = UINT32_MAX;
    normal[0] = normal[1] = normal[2] = 0;
    double slo[3], shi[3];
    for (int k = 0; k < 3; ++k) {
        slo[k] = noct_min(p[k], q[k]);
        shi[k] = noct_max(p[k], q[k]);
    }
    static const double zero[3] = {0, 0, 0};
    if (!noct_boxes_overlap(m->lo, m->hi, t, slo, shi, zero))
        return NOCT_OK;
    bool inside;
    noctStatus st = noct_point_in_solid(m, t, p, &inside);
    if (st != NOCT_OK)
        return st;
    if (inside) {
        *hit = true;
        *fraction = 0;
        return NOCT_OK;
    }
    segment_entry e = {p, q, x, INFINITY, UINT32_MAX, normal, false, m->surface};
    noct_bvh_box_walk(&B, slo, shi, segment_meets, &e);
    *triangle = e.triangle;
    *flat = e.flat;
    const double best = e.best;
    if (*triangle != UINT32_MAX) {
        *hit = true;
        *fraction = best;
    }
    return NOCT_OK;
}

