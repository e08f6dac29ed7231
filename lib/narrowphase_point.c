/* SPDX-License-Identifier: MIT */
/*
 * The distance from a point to a placed solid (the world's point queries:
 * noctWorldQueryNearest() and noctWorldQueryWithin() without a shape),
 * with the proved interval of noctDistance(): 0 when the solid contains
 * the point (decided exactly, noct_point_in_solid()), else the distance
 * to its boundary, searched over the mesh's hierarchy nearer child first,
 * pruning boxes farther than the best so far; the lower bound is proved
 * over the triangles the best leaves, as narrowphase_distance.c proves
 * it for two triangles (the gap on separating axes, less its rounding).
 */
#include "config.h"

#include <math.h>
#include <string.h>

#include "narrowphase_internal.h"

/* Squared distance from p to the placed box [lo, hi] + t, each gap scaled
 * before it is squared. */
static double box_dist2(const double p[3], const bvh_node *n, const double t[3], double scale)
{
    double s = 0;
    for (int k = 0; k < 3; ++k) {
        const double g =
            noct_max(noct_max((n->lo[k] + t[k]) - p[k], p[k] - (n->hi[k] + t[k])), 0) * scale;
        s += g * g;
    }
    return s;
}

/* The point of segment ab nearest p, in floating point. */
static void point_seg_nearest(const double p[3], const double a[3], const double b[3],
                              double out[3])
{
    double ab[3], ap[3];
    noct_sub3(b, a, ab);
    noct_sub3(p, a, ap);
    const double l2 = noct_dot3(ab, ab);
    double u = l2 > 0 ? noct_dot3(ap, ab) / l2 : 0;
    u = noct_min(noct_max(u, 0), 1);
    for (int k = 0; k < 3; ++k)
        out[k] = a[k] + u * ab[k];
}

static double dist2(const double a[3], const double b[3])
{
    double d[3];
    noct_sub3(a, b, d);
    return noct_dot3(d, d);
}

/* The point of closed triangle t nearest p, in floating point: by the
 * Voronoi regions of its corners, edges and face; a triangle too flat for
 * the face's formula is decided by its edges. */
static void point_tri_nearest(const double p[3], double t[3][3], double out[3])
{
    const double *a = t[0], *b = t[1], *c = t[2];
    double ab[3], ac[3], ap[3], bp[3], cp[3];
    noct_sub3(b, a, ab);
    noct_sub3(c, a, ac);
    noct_sub3(p, a, ap);
    const double d1 = noct_dot3(ab, ap), d2 = noct_dot3(ac, ap);
    if (d1 <= 0 && d2 <= 0) {
        noct_copy3(a, out);
        return;
    }
    noct_sub3(p, b, bp);
    const double d3 = noct_dot3(ab, bp), d4 = noct_dot3(ac, bp);
    if (d3 >= 0 && d4 <= d3) {
        noct_copy3(b, out);
        return;
    }
    noct_sub3(p, c, cp);
    const double d5 = noct_dot3(ab, cp), d6 = noct_dot3(ac, cp);
    if (d6 >= 0 && d5 <= d6) {
        noct_copy3(c, out);
        return;
    }
    const double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
    const double sum = va + vb + vc;
    if (sum > 0 && va >= 0 && vb >= 0 && vc >= 0) {
        const double v = vb / sum, w = vc / sum;
        for (int k = 0; k < 3; ++k)
            out[k] = a[k] + ab[k] * v + ac[k] * w;
        return;
    }
    /* outside the face's prism, or flat: the nearest of the edges' points */
    double best = INFINITY, q[3];
    for (int e = 0; e < 3; ++e) {
        point_seg_nearest(p, t[e], t[(e + 1) % 3], q);
        const double d = dist2(p, q);
        if (d < best) {
            best = d;
            noct_copy3(q, out);
        }
    }
}

/* The gap between p and the triangle along u proved, as
 * narrowphase_distance.c's proved_gap(): (the projections' gap less twice
 * an allowance for their rounding) over |u|, or 0; s bounds every
 * coordinate. */
static double proved_gap(const double axis[3], const double p[3], double t[3][3], double s)
{
    double u[3];
    if (!noct_gap_axis(axis, u))
        return 0;
    const double l1 = fabs(u[0]) + fabs(u[1]) + fabs(u[2]);
    double tmax = -INFINITY, tmin = INFINITY;
    for (int i = 0; i < 3; ++i) {
        const double x = noct_dot3(u, t[i]);
        tmax = noct_max(tmax, x);
        tmin = noct_min(tmin, x);
    }
    const double pp = noct_dot3(u, p);
    /* each projection errs by at most 4 ulp of l1 s (and NOCT_GAP_TINY
     * where it underflows); the difference one more */
    const double err = 0x1p-50 * l1 * s + NOCT_GAP_TINY;
    return noct_gap_over(noct_max(pp - tmax, tmin - pp) - 2 * err, u);
}

/* A proved lower bound on the distance from p to closed triangle t: the
 * largest gap over the axes that may hold the direction from p to its
 * nearest point (the direction to the computed point first, then the
 * face's normal, p to each corner, the perpendicular from each edge's line
 * to p); it stops once a gap reaches enough (the caller keeps the least
 * bound over triangles: one at least enough changes nothing). */
static double point_tri_lower_bound(const double p[3], double t[3][3], double enough)
{
    double s = 0;
    for (int k = 0; k < 3; ++k) {
        s = noct_max(s, fabs(p[k]));
        for (int i = 0; i < 3; ++i)
            s = noct_max(s, fabs(t[i][k]));
    }
    double u[3], v[3], w[3], q[3];
    point_tri_nearest(p, t, q);
    noct_sub3(p, q, u);
    double best = proved_gap(u, p, t, s);
    if (best >= enough)
        return best;
    double e[3][3];
    for (int i = 0; i < 3; ++i)
        noct_sub3(t[(i + 1) % 3], t[i], e[i]);
    cross_into(e[0], e[1], u);
    best = noct_max(best, proved_gap(u, p, t, s));
    for (int i = 0; i < 3 && best < enough; ++i) {
        noct_sub3(p, t[i], v);
        best = noct_max(best, proved_gap(v, p, t, s));
        cross_into(e[i], v, w);
        cross_into(w, e[i], u);
        best = noct_max(best, proved_gap(u, p, t, s));
    }
    return best;
}

/* Squared distance from p to the box of triangle x, a lower bound on the
 * squared distance to it (all scaled alike). */
static double tri_box_dist2(const double p[3], double x[3][3])
{
    double s = 0;
    for (int k = 0; k < 3; ++k) {
        const double lo = noct_min(x[0][k], noct_min(x[1][k], x[2][k]));
        const double hi = noct_max(x[0][k], noct_max(x[1][k], x[2][k]));
        const double g = noct_max(noct_max(lo - p[k], p[k] - hi), 0);
        s += g * g;
    }
    return s;
}

/* The walk's state: p and the mesh (both scaled by scale when tiny). */
typedef struct point_walk {
    const noctMesh *m;
    const double *t;
    const double *p;      /* the point */
    double ps[3];         /* and scaled */
    double scale;
    double best2, q[3];   /* the best squared distance and point (scaled) */
    uint32_t tri;         /* its triangle (BVH order) */
    bool found;
} point_walk;

static void placed_triangle(const point_walk *w, uint32_t i, double x[3][3])
{
    for (int c = 0; c < 3; ++c) {
        const double *v = &w->m->v[3 * w->m->tri[3 * i + c]];
        for (int k = 0; k < 3; ++k)
            x[c][k] = (v[k] + w->t[k]) * w->scale;
    }
}

/* Node stack depth: the hierarchies are far shallower (bvh.h). */
#define POINT_STACK 256

/* The nearest triangle within sqrt(best2), nearer child first. */
static void nearest_walk(point_walk *w)
{
    uint32_t stack[POINT_STACK];
    size_t top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const bvh_node *n = &w->m->nodes[stack[--top]];
        if (box_dist2(w->p, n, w->t, w->scale) >= w->best2)
            continue;
        if (n->count > 0) {
            for (uint32_t i = n->first; i < n->first + n->count; ++i) {
                double x[3][3], q[3];
                placed_triangle(w, i, x);
                if (tri_box_dist2(w->ps, x) >= w->best2)
                    continue;
                point_tri_nearest(w->ps, x, q);
                const double d2 = dist2(w->ps, q);
                if (d2 < w->best2) {
                    w->best2 = d2;
                    noct_copy3(q, w->q);
                    w->tri = i;
                    w->found = true;
                }
            }
            continue;
        }
        NOCT_INVARIANT(top + 2 <= POINT_STACK);
        const double d0 = box_dist2(w->p, &w->m->nodes[n->first], w->t, w->scale);
        const double d1 = box_dist2(w->p, &w->m->nodes[n->first + 1], w->t, w->scale);
        /* the nearer child on top */
        stack[top++] = d0 <= d1 ? n->first + 1 : n->first;
        stack[top++] = d0 <= d1 ? n->first : n->first + 1;
    }
}

/* The least lower bound over the triangles within reach (scaled). */
static double lower_walk(const point_walk *w, double reach, double lower)
{
    const double reach2 = reach * reach;
    uint32_t stack[POINT_STACK];
    size_t top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const bvh_node *n = &w->m->nodes[stack[--top]];
        if (box_dist2(w->p, n, w->t, w->scale) > reach2)
            continue;
        if (n->count > 0) {
            for (uint32_t i = n->first; i < n->first + n->count; ++i) {
                double x[3][3];
                placed_triangle(w, i, x);
                if (tri_box_dist2(w->ps, x) > reach2)
                    continue;
                lower = noct_min(lower, point_tri_lower_bound(w->ps, x, lower));
            }
            continue;
        }
        NOCT_INVARIANT(top + 2 <= POINT_STACK);
        stack[top++] = n->first;
        stack[top++] = n->first + 1;
    }
    return lower;
}

/* Meshes of at most this many vertices try the hull's bound first. */
#define HULL_BOUND_VERTICES 64

/* A proved lower bound on the distance from p to the solid, from the hull
 * of its placed vertices, which holds it: the gap between p and every
 * placed vertex along u (p less the nearest point, then the normal of the
 * nearest triangle: sharper when the point is near), less the rounding
 * of the projections, as proved_gap(); 0 if none separates them. */
static double hull_lower_bound(const point_walk *w, const double q[3])
{
    const noctMesh *m = w->m;
    double s = 0;
    for (int k = 0; k < 3; ++k)
        s = noct_max(s, fabs(w->ps[k]));
    double x[3][3], axes[2][3];
    placed_triangle(w, w->tri, x);
    noct_sub3(w->ps, q, axes[0]);
    double e1[3], e2[3];
    noct_sub3(x[1], x[0], e1);
    noct_sub3(x[2], x[0], e2);
    cross_into(e1, e2, axes[1]);
    double pv[3 * HULL_BOUND_VERTICES];
    for (size_t i = 0; i < m->nv; ++i)
        for (int k = 0; k < 3; ++k) {
            pv[3 * i + k] = (m->v[3 * i + k] + w->t[k]) * w->scale;
            s = noct_max(s, fabs(pv[3 * i + k]));
        }
    double best = 0;
    for (int a = 0; a < 2; ++a) {
        double u[3];
        if (!noct_gap_axis(axes[a], u))
            continue;
        const double l1 = fabs(u[0]) + fabs(u[1]) + fabs(u[2]);
        double vmax = -INFINITY, vmin = INFINITY;
        for (size_t i = 0; i < m->nv; ++i) {
            const double y = noct_dot3(u, &pv[3 * i]);
            vmax = noct_max(vmax, y);
            vmin = noct_min(vmin, y);
        }
        const double pp = noct_dot3(u, w->ps);
        const double gap = noct_max(pp - vmax, vmin - pp) - 2 * (0x1p-50 * l1 * s + NOCT_GAP_TINY);
        best = noct_max(best, noct_gap_over(gap, u));
    }
    return best;
}

/*
 * A box (a box-form mesh with a dual or a box view: its corners and faces
 * known, noct_box_topology()), unscaled or scaled down (huge
 * coordinates; scaled up, the walk takes it): the point's nearest feature in
 * closed form, clamped in the frame of the ideal box its placed corners
 * describe (checked rectangular), then the nearest point of that placed
 * feature (a corner, an edge, or the nearer of a face's two triangles),
 * as the walk would find it among the triangles. Sets w's best when
 * nearer than it; false when the point is in the ideal box (the walk
 * then looks). The proof that follows does not depend on it.
 */
static bool box_nearest(point_walk *w)
{
    const uint8_t *corner;
    const uint8_t (*face)[2];
    const noctMesh *m = w->m;
    if (m->nv != 8 || w->scale > 1 || !noct_box_topology(m, &corner, &face))
        return false;
    double P[8][3];
    for (int i = 0; i < 8; ++i)
        for (int k = 0; k < 3; ++k)
            P[i][k] = (m->v[3 * corner[i] + k] + w->t[k]) * w->scale; /* by corner */
    double c[3], d[3], x[3], h[3];
    for (int k = 0; k < 3; ++k) {
        c[k] = P[0][k] + (P[7][k] - P[0][k]) / 2;
        d[k] = w->ps[k] - c[k];
    }
    double u[3][3];
    for (int j = 0; j < 3; ++j) {
        double e[3];
        noct_sub3(P[7], P[7 ^ (1u << j)], e);
        const double n = noct_norm3(e);
        if (!(n > 0))
            return false;
        h[j] = n / 2;
        for (int k = 0; k < 3; ++k)
            u[j][k] = e[k] / n;
        x[j] = noct_dot3(u[j], d);
    }
    if (!(fabs(noct_dot3(u[0], u[1])) <= 1e-9 && fabs(noct_dot3(u[0], u[2])) <= 1e-9 &&
          fabs(noct_dot3(u[1], u[2])) <= 1e-9))
        return false;
    unsigned base = 0, free = 0;
    for (int j = 0; j < 3; ++j) {
        if (fabs(x[j]) > h[j])
            base |= (x[j] > 0 ? 1u : 0u) << j;
        else
            free |= 1u << j;
    }
    if (free == 7)
        return false;
    double q[3];
    uint32_t tri = 0;
    const uint32_t v0 = corner[base];
    const uint32_t v1 = corner[(free & (free - 1)) == 0 ? base | free : base];
    if ((free & (free - 1)) == 0) { /* a corner or an edge: a side of a triangle */
        if (free == 0)
            noct_copy3(P[base], q);
        else
            point_seg_nearest(w->ps, P[base], P[base | free], q);
        for (uint32_t i = 0; i < m->nt; ++i) {
            const uint32_t *v = &m->tri[3 * i];
            if ((v[0] == v0 || v[1] == v0 || v[2] == v0) &&
                (v[0] == v1 || v[1] == v1 || v[2] == v1)) {
                tri = i;
                break;
            }
        }
    } else { /* a face: the nearer of its two triangles */
        const unsigned j = 7 ^ free;
        const int k = j == 1 ? 0 : j == 2 ? 1 : 2;
        const uint8_t *two = face[2 * k + ((base >> k) & 1u)];
        double best = INFINITY;
        for (int i = 0; i < 2; ++i) {
            double y[3][3], z[3];
            placed_triangle(w, two[i], y);
            point_tri_nearest(w->ps, y, z);
            const double d2 = dist2(w->ps, z);
            if (d2 < best) {
                best = d2;
                noct_copy3(z, q);
                tri = two[i];
            }
        }
    }
    const double d2 = dist2(w->ps, q);
    if (d2 < w->best2) {
        w->best2 = d2;
        noct_copy3(q, w->q);
        w->tri = tri;
        w->found = true;
    }
    return true;
}

noctStatus noct_point_distance_placed(const double p[3], const noctMesh *m, const double t[3],
                                      double max_distance, bool outside, noctDistanceResult *r)
{
    memset(r, 0, sizeof *r);
    for (int k = 0; k < 3; ++k)
        r->triangle_a[k] = r->triangle_b[k] = NOCT_NO_TRIANGLE;
    double mag = 0;
    for (int k = 0; k < 3; ++k)
        mag = noct_max(mag, noct_max(fabs(p[k]), noct_max(fabs(m->lo[k] + t[k]),
                                                          fabs(m->hi[k] + t[k]))));
    /* Tiny coordinates scaled up (exactly), as noctDistance() does, and
     * huge ones down: the nearest point of a triangle multiplies four
     * coordinates (point_tri_nearest()), which overflows beyond 2^255 and
     * made the face's point an edge's (an interval 0.4 % wide at 2^300).
     * Scaling up by a power of two is exact here (mag < 2^-200); scaling
     * down is exact except where a coordinate falls below 2^-1022
     * (one under 2^-822 at mag 2^200): it moves by at most 2^-1075
     * (scaled), which the proofs' allowances cover (each projection's
     * 2^-50 l1 s exceeds l1 2^-1075 once s >= 2^-1024, and a gap under
     * 2^-1000 counts as 0: noct_gap_over()); the computed nearest point
     * may move as much (2^-1075 / scale), within the accuracy. */
    double scale = 1;
    if (mag > 0 && (mag < 0x1p-200 || mag > 0x1p200))
        scale = noct_pow2(-ilogb(mag));
    const double slack = 0x1p-40 * noct_max(mag, isfinite(max_distance) ? max_distance : 0);
    const double reach_max = isfinite(max_distance)
                                 ? (max_distance * (1 + 0x1p-40) + slack) * scale
                                 : (double)INFINITY;
    point_walk w = {m, t, p, {p[0] * scale, p[1] * scale, p[2] * scale}, scale, INFINITY,
                    {0, 0, 0}, 0, false};
    const bool far = box_dist2(p, &m->nodes[0], t, scale) > reach_max * reach_max;
    if (!far) {
        /* outside the placed box, outside the solid (fl(v + t) is
         * monotone: the placed box holds the placed vertices) */
        bool inside = !outside;
        for (int k = 0; k < 3; ++k)
            inside = inside && m->lo[k] + t[k] <= p[k] && p[k] <= m->hi[k] + t[k];
        if (inside) {
            const noctStatus st = noct_point_in_solid(m, t, p, &inside);
            if (st != NOCT_OK)
                return st;
        }
        if (inside) {
            r->colliding = true;
            noct_copy3(p, r->point_a);
            noct_copy3(p, r->point_b);
            return NOCT_OK;
        }
        w.best2 = reach_max * reach_max;
        if (!box_nearest(&w))
            nearest_walk(&w);
    }
    const double slack_s = slack * scale, allow = 0x1p-47 * mag * scale;
    if (!w.found) {
        /* Nothing within the reach in floating point: prove it. */
        if (far || lower_walk(&w, reach_max, INFINITY) > max_distance * scale) {
            r->beyond = true;
            r->lower = max_distance;
            r->distance = r->upper = INFINITY;
            return NOCT_OK;
        }
        w.best2 = INFINITY;
        nearest_walk(&w);
        NOCT_INVARIANT(w.found);
    }
    const double d = sqrt(w.best2);
    const double upper = d * (1 + 0x1p-50) + 2 * allow;
    /* A small mesh (a box, a convex shape) first tries the hull of its
     * vertices, proved on one or two axes; the walk over the triangles
     * within reach when that is not within the accuracy noctDistance()
     * promises (a point nearest a dent of a non-convex mesh). */
    double lower = m->nv <= HULL_BOUND_VERTICES ? hull_lower_bound(&w, w.q) : 0;
    if (!(upper - lower <= 0x1p-41 * noct_max(mag * scale, upper)))
        lower = noct_max(lower, lower_walk(&w, upper * (1 + 0x1p-40) + slack_s, upper));
    r->lower = lower / scale;
    r->upper = upper / scale;
    r->distance = noct_min(noct_max(d / scale, r->lower), r->upper);
    noct_copy3(p, r->point_a);
    for (int k = 0; k < 3; ++k) {
        r->point_b[k] = w.q[k] / scale;
        r->triangle_b[k] = m->tri[3 * w.tri + k];
    }
    return NOCT_OK;
}
