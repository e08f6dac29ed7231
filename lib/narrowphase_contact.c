/* SPDX-License-Identifier: MIT */
/*
 * The narrowphase's contacts (noctCollideContact(), noctWorldContacts()):
 * where two colliding placed solids meet, and for convex ones how deep.
 *
 * The points come from one walk of the two hierarchies: every pair of
 * triangles that meet (decided exactly, tri_tri) gives the points where
 * an edge of one crosses the other, computed in floating point. For convex
 * shapes, the vertices of each inside the other (decided exactly) are
 * added, so that the candidates are the vertices of the overlap; the
 * minimum translation is the separating-axis minimum over the triangles'
 * normals and the cross products of the edge pairs that span faces of the
 * Minkowski difference; and each candidate moves to the middle of the
 * overlap's chord along the normal. The candidates are then reduced to a
 * few, as physics engines reduce their manifolds. See narrowphase.h,
 * noctContact, for what each field means.
 */
#include "config.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "array.h"
#include "narrowphase_internal.h"
#include "vec3.h"

typedef double point3[3];
NOCT_DEFINE_GROW(grow_points, point3)

/* What the walk gathers. */
typedef struct gather {
    exact_ctx x;
    double (*p)[3];  /* the candidate points */
    size_t n, cap;
    bool nomem;
    double wsum[3];  /* sum of len (n_A - n_B) over the pairs that meet */
    double usum[3];  /* the same unweighted */
} gather;

static void add_point(gather *g, const double p[3])
{
    if (g->nomem)
        return;
    if (!grow_points(&g->p, &g->cap, g->n + 1)) {
        g->nomem = true;
        return;
    }
    memcpy(g->p[g->n++], p, sizeof g->p[0]);
}

/* det[u0 - p; u1 - p; u2 - p] in floating point: orient3d's value. */
static double det_of(double u[3][3], const double p[3])
{
    double a[3], b[3], c[3], bc[3];
    noct_sub3(u[0], p, a);
    noct_sub3(u[1], p, b);
    noct_sub3(u[2], p, c);
    noct_cross3(b, c, bc);
    return noct_dot3(a, bc);
}

/* p + s (q - p), s clamped to [0, 1]. */
static void lerp(const double p[3], const double q[3], double s, double out[3])
{
    s = s < 0 ? 0 : s > 1 ? 1 : s;
    for (int k = 0; k < 3; ++k)
        out[k] = p[k] + s * (q[k] - p[k]);
}

/* Coplanar closed segments pq and ab that meet (decided exactly): where
 * they cross, or, collinear, the ends of their overlap. */
static void add_crossing(gather *g, const double p[3], const double q[3], const double a[3],
                         const double b[3])
{
    double d1[3], d2[3], cr[3], ap[3], c2[3], out[3];
    noct_sub3(q, p, d1);
    noct_sub3(b, a, d2);
    noct_cross3(d1, d2, cr);
    const double den = noct_dot3(cr, cr);
    if (den > 1e-24 * noct_dot3(d1, d1) * noct_dot3(d2, d2)) {
        noct_sub3(a, p, ap);
        noct_cross3(ap, d2, c2);
        lerp(p, q, noct_dot3(c2, cr) / den, out);
        add_point(g, out);
        return;
    }
    /* Collinear: the overlap's ends, along the axis pq spans most. */
    int k = 0;
    for (int i = 1; i < 3; ++i)
        if (fabs(d1[i]) > fabs(d1[k]))
            k = i;
    if (d1[k] == 0) {
        add_point(g, p);
        return;
    }
    const double lo = noct_max(noct_min(p[k], q[k]), noct_min(a[k], b[k]));
    const double hi = noct_min(noct_max(p[k], q[k]), noct_max(a[k], b[k]));
    lerp(p, q, (lo - p[k]) / d1[k], out);
    add_point(g, out);
    lerp(p, q, (hi - p[k]) / d1[k], out);
    add_point(g, out);
}

/* The points where the edges of triangle t meet triangle u. */
static void edges_cross(gather *g, double t[3][3], double u[3][3])
{
    int s[3];
    for (int i = 0; i < 3; ++i)
        s[i] = o3(&g->x, u[0], u[1], u[2], t[i]);
    for (int e = 0; e < 3; ++e) {
        const int f = (e + 1) % 3;
        const double *p = t[e], *q = t[f];
        if (!seg_tri(&g->x, p, q, s[e], s[f], u[0], u[1], u[2]))
            continue;
        if (s[e] == 0 && s[f] == 0) {
            /* In u's plane: its ends inside u, and where it crosses u's
             * edges. */
            if (seg_tri(&g->x, p, p, 0, 0, u[0], u[1], u[2]))
                add_point(g, p);
            if (seg_tri(&g->x, q, q, 0, 0, u[0], u[1], u[2]))
                add_point(g, q);
            for (int c = 0; c < 3; ++c)
                if (seg_seg_3d(&g->x, p, q, u[c], u[(c + 1) % 3]))
                    add_crossing(g, p, q, u[c], u[(c + 1) % 3]);
        } else if (s[e] == 0) {
            add_point(g, p);
        } else if (s[f] == 0) {
            add_point(g, q);
        } else {
            const double dp = det_of(u, p), dq = det_of(u, q);
            double out[3];
            lerp(p, q, dp != dq ? dp / (dp - dq) : 0.5, out);
            add_point(g, out);
        }
    }
}

/* The unit outward normal of a placed triangle (0 if it has no area as
 * placed). */
static void tri_normal(double t[3][3], double n[3])
{
    double e1[3], e2[3], c[3];
    noct_sub3(t[1], t[0], e1);
    noct_sub3(t[2], t[0], e2);
    noct_cross3(e1, e2, c);
    noct_unit3(c, n);
}

static bool prune_apart(void *context, const bvh_node *na, const bvh_node *nb)
{
    const placed *const *ab = context;
    return !noct_boxes_overlap(na->lo, na->hi, ab[0]->t, nb->lo, nb->hi, ab[1]->t);
}

typedef struct walk_ctx {
    const placed *ab[2]; /* first: prune_apart reads it as its context */
    gather *g;
} walk_ctx;

static bool pair_points(void *context, uint32_t i, double a[3][3], uint32_t j, double b[3][3])
{
    (void)i;
    (void)j;
    walk_ctx *w = context;
    gather *g = w->g;
    if (!tri_tri(&g->x, a, b))
        return false;
    const size_t first = g->n;
    edges_cross(g, a, b);
    edges_cross(g, b, a);
    if (g->nomem)
        return true;
    /* The pair's intersection segment: its longest span of points. */
    double len = 0;
    for (size_t k = first; k < g->n; ++k)
        for (size_t l = k + 1; l < g->n; ++l) {
            double d[3];
            noct_sub3(g->p[k], g->p[l], d);
            len = noct_max(len, noct_norm3(d));
        }
    double na[3], nb[3];
    tri_normal(a, na);
    tri_normal(b, nb);
    for (int k = 0; k < 3; ++k) {
        g->wsum[k] += len * (na[k] - nb[k]);
        g->usum[k] += na[k] - nb[k];
    }
    return false;
}

static bool prune_ctx(void *context, const bvh_node *na, const bvh_node *nb)
{
    walk_ctx *w = context;
    return prune_apart(w->ab, na, nb);
}

/* ---- convex shapes: the minimum translation ----------------------------------- */

/* A placed triangle's plane: unit outward n, n.x = d on it. */
typedef struct plane4 {
    double n[3], d;
} plane4;

/* An edge of the solid: its direction and its two triangles' normals. */
typedef struct solid_edge {
    double p[3], dir[3];
    const double *n1, *n2;
} solid_edge;

typedef struct dir_key {
    uint32_t lo, hi, tri;
} dir_key;

static int by_key(const void *p, const void *q)
{
    const dir_key *a = p, *b = q;
    if (a->lo != b->lo)
        return a->lo < b->lo ? -1 : 1;
    if (a->hi != b->hi)
        return a->hi < b->hi ? -1 : 1;
    return (a->tri > b->tri) - (a->tri < b->tri);
}

/* What the convex level needs of one placed shape. */
typedef struct convex_shape {
    const placed *o;
    plane4 *plane;     /* nt */
    double (*hull)[3]; /* nhull placed hull vertices */
    size_t nhull;
    solid_edge *edge;
    size_t nedge;
} convex_shape;

static void convex_free(convex_shape *c)
{
    free(c->plane);
    free(c->hull);
    free(c->edge);
}

/* Planes, hull and edges of o; false without memory. */
static bool convex_make(const placed *o, convex_shape *c)
{
    const noctMesh *m = o->m;
    memset(c, 0, sizeof *c);
    c->o = o;
    c->plane = malloc(m->nt * sizeof *c->plane);
    c->hull = malloc(m->nhull * sizeof *c->hull);
    dir_key *keys = malloc(3 * m->nt * sizeof *keys);
    c->edge = malloc((3 * m->nt / 2 + 1) * sizeof *c->edge);
    if (c->plane == NULL || c->hull == NULL || keys == NULL || c->edge == NULL) {
        free(keys);
        convex_free(c);
        return false;
    }
    c->nhull = m->nhull;
    for (size_t i = 0; i < m->nhull; ++i)
        noct_place_vertex(o, m->hull[i], c->hull[i]);
    for (size_t t = 0; t < m->nt; ++t) {
        double v[3][3];
        for (int k = 0; k < 3; ++k)
            noct_place_vertex(o, m->tri[3 * t + k], v[k]);
        tri_normal(v, c->plane[t].n);
        c->plane[t].d = noct_dot3(c->plane[t].n, v[0]);
        for (int k = 0; k < 3; ++k) {
            const uint32_t p = m->tri[3 * t + k], q = m->tri[3 * t + (k + 1) % 3];
            keys[3 * t + k] = (dir_key){p < q ? p : q, p < q ? q : p, (uint32_t)t};
        }
    }
    qsort(keys, 3 * m->nt, sizeof *keys, by_key);
    /* Each edge is two triangles'; one between coplanar triangles (a
     * polygon's diagonal) is no edge of the solid. */
    for (size_t i = 0; i + 1 < 3 * m->nt; ++i) {
        const dir_key *k = &keys[i], *l = &keys[i + 1];
        if (k->lo != l->lo || k->hi != l->hi)
            continue;
        const double *n1 = c->plane[k->tri].n, *n2 = c->plane[l->tri].n;
        ++i;
        if (noct_dot3(n1, n2) > 1 - 1e-9)
            continue;
        double p[3], q[3];
        noct_place_vertex(o, k->lo, p);
        noct_place_vertex(o, k->hi, q);
        solid_edge *e = &c->edge[c->nedge++];
        memcpy(e->p, p, sizeof e->p);
        noct_sub3(q, p, e->dir);
        e->n1 = n1;
        e->n2 = n2;
    }
    free(keys);
    return true;
}

static void project(const convex_shape *c, const double u[3], double *lo, double *hi)
{
    *lo = INFINITY;
    *hi = -INFINITY;
    for (size_t i = 0; i < c->nhull; ++i) {
        const double d = noct_dot3(u, c->hull[i]);
        *lo = noct_min(*lo, d);
        *hi = noct_max(*hi, d);
    }
}

/* The least overlap so far and its normal (B moves along it). */
typedef struct best_axis {
    double depth;
    double normal[3];
    const solid_edge *ea, *eb; /* the edges whose cross product it is, or
                                  NULL for a triangle's normal */
} best_axis;

static void try_axis(const convex_shape *A, const convex_shape *B, const double u[3],
                     const solid_edge *ea, const solid_edge *eb, best_axis *best)
{
    if (u[0] == 0 && u[1] == 0 && u[2] == 0)
        return;
    double alo, ahi, blo, bhi;
    project(A, u, &alo, &ahi);
    project(B, u, &blo, &bhi);
    const double up = ahi - blo, down = bhi - alo;
    const double d = noct_min(up, down);
    if (d < best->depth) {
        best->depth = d;
        best->ea = ea;
        best->eb = eb;
        const double s = up <= down ? 1 : -1;
        for (int k = 0; k < 3; ++k)
            best->normal[k] = s * u[k];
    }
}

/* The separating-axis minimum (see noctContact). */
static void min_translation(const convex_shape *A, const convex_shape *B, best_axis *best)
{
    best->depth = INFINITY;
    best->normal[0] = best->normal[1] = 0;
    best->normal[2] = 1;
    best->ea = best->eb = NULL;
    for (size_t t = 0; t < A->o->m->nt; ++t)
        try_axis(A, B, A->plane[t].n, NULL, NULL, best);
    for (size_t t = 0; t < B->o->m->nt; ++t)
        try_axis(A, B, B->plane[t].n, NULL, NULL, best);
    /* Edge pairs: a face of the Minkowski difference A - B when the arc
     * of A's edge normals (a, b) and the arc of the negated normals of B's
     * (c, d) cross on the sphere: each arc's ends on the two sides of the
     * other's great circle. The test keeps ties (a superset of axes only
     * adds overlaps no less than the minimum). */
    for (size_t i = 0; i < A->nedge; ++i) {
        const solid_edge *ea = &A->edge[i];
        double bxa[3];
        noct_cross3(ea->n2, ea->n1, bxa);
        for (size_t j = 0; j < B->nedge; ++j) {
            const solid_edge *eb = &B->edge[j];
            const double c[3] = {-eb->n1[0], -eb->n1[1], -eb->n1[2]};
            const double d[3] = {-eb->n2[0], -eb->n2[1], -eb->n2[2]};
            double dxc[3];
            noct_cross3(d, c, dxc);
            if (noct_dot3(c, bxa) * noct_dot3(d, bxa) > 1e-20 ||
                noct_dot3(ea->n1, dxc) * noct_dot3(ea->n2, dxc) > 1e-20)
                continue; /* (the slack keeps the near ties, which rounding
                             could otherwise drop) */
            double cr[3], u[3];
            noct_cross3(ea->dir, eb->dir, cr);
            double la = noct_norm3(ea->dir), lb = noct_norm3(eb->dir);
            if (noct_norm3(cr) <= 1e-9 * la * lb)
                continue; /* parallel: the faces' normals cover it */
            noct_unit3(cr, u);
            try_axis(A, B, u, ea, eb, best);
        }
    }
}

/* The middle of the closest points of the segments of edges ea and eb
 * (not parallel: their cross product is an axis). */
static void edges_middle(const solid_edge *ea, const solid_edge *eb, double mid[3])
{
    const double *d1 = ea->dir, *d2 = eb->dir;
    double r[3];
    noct_sub3(ea->p, eb->p, r);
    const double a = noct_dot3(d1, d1), e = noct_dot3(d2, d2), b = noct_dot3(d1, d2);
    const double c = noct_dot3(d1, r), f = noct_dot3(d2, r);
    const double den = a * e - b * b;
    double s = den > 0 ? (b * f - c * e) / den : 0;
    s = s < 0 ? 0 : s > 1 ? 1 : s;
    double t = (b * s + f) / e;
    if (t < 0 || t > 1) {
        t = t < 0 ? 0 : 1;
        s = (b * t - c) / a;
        s = s < 0 ? 0 : s > 1 ? 1 : s;
    }
    for (int k = 0; k < 3; ++k)
        mid[k] = ((ea->p[k] + s * d1[k]) + (eb->p[k] + t * d2[k])) / 2;
}

/* The edge of c whose ends both project within tol of the extreme h of
 * c's hull on u (the edge that supports it there), or NULL. */
static const solid_edge *support_edge(const convex_shape *c, const double u[3], double h,
                                      double sign, double tol)
{
    for (size_t i = 0; i < c->nedge; ++i) {
        const solid_edge *e = &c->edge[i];
        double q[3];
        noct_add3(e->p, e->dir, q);
        if (sign * (noct_dot3(u, e->p) - h) >= -tol && sign * (noct_dot3(u, q) - h) >= -tol)
            return e;
    }
    return NULL;
}

/* When the minimum is an edge pair's: the middle of the closest points of
 * the edges of A and B that support the overlap along the normal (edge
 * pairs along the same axis give the same overlap, so the one the search
 * kept need not be these). false if there are no such edges. */
static bool supporting_edges(const convex_shape *A, const convex_shape *B,
                             const best_axis *best, double tol, double mid[3])
{
    double alo, ahi, blo, bhi, cr[3];
    project(A, best->normal, &alo, &ahi);
    project(B, best->normal, &blo, &bhi);
    const solid_edge *ea = support_edge(A, best->normal, ahi, 1, tol);
    const solid_edge *eb = support_edge(B, best->normal, blo, -1, tol);
    if (ea == NULL || eb == NULL)
        return false;
    noct_cross3(ea->dir, eb->dir, cr);
    if (noct_norm3(cr) <= 1e-9 * noct_norm3(ea->dir) * noct_norm3(eb->dir))
        return false;
    edges_middle(ea, eb, mid);
    return true;
}

/* Move p to the middle of the chord of the overlap along n through it; the
 * chord's length. A plane p is outside of (by rounding) does not cut the
 * chord on its side of p, so the point moves no farther out than p is. */
static double chord_middle(const convex_shape *const S[2], const double n[3], double p[3])
{
    double lo = -INFINITY, hi = INFINITY;
    for (int s = 0; s < 2; ++s)
        for (size_t t = 0; t < S[s]->o->m->nt; ++t) {
            const plane4 *pl = &S[s]->plane[t];
            const double mn = noct_dot3(pl->n, n);
            const double slack = noct_max(0, pl->d - noct_dot3(pl->n, p));
            if (mn > 0)
                hi = noct_min(hi, slack / mn);
            else if (mn < 0)
                lo = noct_max(lo, slack / mn);
        }
    if (!isfinite(lo) || !isfinite(hi))
        return 0; /* not closed along n: never for a solid */
    const double mid = (lo + hi) / 2;
    for (int k = 0; k < 3; ++k)
        p[k] += mid * n[k];
    return hi - lo;
}

/* ---- the reduction ------------------------------------------------------------- */

/* ((q1 - q0) x (q - q0)) . n: twice the signed area in the plane normal
 * to n. */
static double area_n(const double q0[3], const double q1[3], const double q[3],
                     const double n[3])
{
    double e[3], f[3], c[3];
    noct_sub3(q1, q0, e);
    noct_sub3(q, q0, f);
    noct_cross3(e, f, c);
    return noct_dot3(c, n);
}

/* |p - q| in the plane normal to n. */
static double dist_n(const double p[3], const double q[3], const double n[3])
{
    double d[3];
    noct_sub3(p, q, d);
    const double a = noct_dot3(d, n);
    for (int k = 0; k < 3; ++k)
        d[k] -= a * n[k];
    return noct_norm3(d);
}

/* Keep at most 4 of the n candidates p (depth[i] each, or NULL): see
 * noctContact. */
static void reduce(double (*p)[3], const double *depth, size_t n, const double nrm[3],
                   double tol, noctContact *c)
{
    size_t pick[4], k = 0;
    /* The first: the deepest (within tol), of those the farthest from the
     * candidates' mean, so that among equals it is a corner. */
    double deepest = -INFINITY, mean[3] = {0, 0, 0};
    for (size_t i = 0; i < n; ++i) {
        deepest = noct_max(deepest, depth != NULL ? depth[i] : 0);
        for (int j = 0; j < 3; ++j)
            mean[j] += p[i][j] / (double)n;
    }
    size_t i0 = 0;
    double out = -1;
    for (size_t i = 0; i < n; ++i) {
        if (depth != NULL && depth[i] < deepest - tol)
            continue;
        const double d = dist_n(p[i], mean, nrm);
        if (d > out) {
            out = d;
            i0 = i;
        }
    }
    pick[k++] = i0;
    size_t i1 = i0;
    double far = tol;
    for (size_t i = 0; i < n; ++i) {
        const double d = dist_n(p[i], p[i0], nrm);
        if (d > far) {
            far = d;
            i1 = i;
        }
    }
    if (i1 != i0) {
        pick[k++] = i1;
        size_t i2 = i0;
        double big = tol * far;
        for (size_t i = 0; i < n; ++i) {
            const double a = fabs(area_n(p[i0], p[i1], p[i], nrm));
            if (a > big) {
                big = a;
                i2 = i;
            }
        }
        if (i2 != i0) {
            pick[k++] = i2;
            /* The triangle counter-clockwise about n; the point that adds
             * the most area outside one of its edges. */
            size_t t[3] = {i0, i1, i2};
            if (area_n(p[i0], p[i1], p[i2], nrm) < 0) {
                t[1] = i2;
                t[2] = i1;
            }
            size_t i3 = i0;
            double add = tol * far;
            for (size_t i = 0; i < n; ++i)
                for (int e = 0; e < 3; ++e) {
                    const double a = -area_n(p[t[e]], p[t[(e + 1) % 3]], p[i], nrm);
                    if (a > add) {
                        add = a;
                        i3 = i;
                    }
                }
            if (i3 != i0)
                pick[k++] = i3;
        }
    }
    c->count = (unsigned)k;
    for (size_t i = 0; i < k; ++i) {
        memcpy(c->points[i], p[pick[i]], sizeof c->points[i]);
        c->point_depth[i] = depth != NULL ? depth[pick[i]] : 0;
    }
}

/* ---- the contact ---------------------------------------------------------------- */

/* M of the tolerance: the largest magnitude of the placed boxes. */
static double magnitude(const placed *A, const placed *B)
{
    double m = 0;
    for (int k = 0; k < 3; ++k) {
        m = noct_max(m, noct_max(fabs(A->m->lo[k] + A->t[k]), fabs(A->m->hi[k] + A->t[k])));
        m = noct_max(m, noct_max(fabs(B->m->lo[k] + B->t[k]), fabs(B->m->hi[k] + B->t[k])));
    }
    return m;
}

/* Add the vertices of O's hull that lie in S's solid (exactly). */
static noctStatus add_inside(gather *g, const placed *O, const placed *S)
{
    const double zero[3] = {0, 0, 0};
    for (size_t i = 0; i < O->m->nhull; ++i) {
        double p[3];
        noct_place_vertex(O, O->m->hull[i], p);
        if (!noct_boxes_overlap(S->m->lo, S->m->hi, S->t, p, p, zero))
            continue;
        bool in;
        noctStatus st = noct_point_in_solid(S->m, S->t, p, &in);
        if (st != NOCT_OK)
            return st;
        if (in)
            add_point(g, p);
    }
    return g->nomem ? NOCT_ERR_NOMEM : NOCT_OK;
}

static noctStatus contact_convex(const placed *A, const placed *B, gather *g, double tol,
                                 noctContact *c)
{
    const bool crossed = g->n > 0;
    noctStatus st = add_inside(g, A, B);
    if (st == NOCT_OK)
        st = add_inside(g, B, A);
    if (st != NOCT_OK || g->n == 0)
        return st; /* no point in both: no contact */
    convex_shape sa, sb;
    if (!convex_make(A, &sa))
        return NOCT_ERR_NOMEM;
    if (!convex_make(B, &sb)) {
        convex_free(&sa);
        return NOCT_ERR_NOMEM;
    }
    best_axis best;
    min_translation(&sa, &sb, &best);
    if (best.ea != NULL) {
        /* Edge across edge: the deepest point is between the edges, in
         * no vertex of the overlap; added when it is in both solids. */
        double mid[3];
        bool in_a = false, in_b = false;
        if (supporting_edges(&sa, &sb, &best, tol, mid))
            st = noct_point_in_solid(A->m, A->t, mid, &in_a);
        if (st == NOCT_OK && in_a)
            st = noct_point_in_solid(B->m, B->t, mid, &in_b);
        if (st == NOCT_OK && in_a && in_b)
            add_point(g, mid);
        if (st == NOCT_OK && g->nomem)
            st = NOCT_ERR_NOMEM;
        if (st != NOCT_OK) {
            convex_free(&sa);
            convex_free(&sb);
            return st;
        }
    }
    double *depth = malloc(g->n * sizeof *depth);
    if (depth == NULL) {
        convex_free(&sa);
        convex_free(&sb);
        return NOCT_ERR_NOMEM;
    }
    const convex_shape *const S[2] = {&sa, &sb};
    for (size_t i = 0; i < g->n; ++i)
        depth[i] = chord_middle(S, best.normal, g->p[i]);
    c->kind = NOCT_CONTACT_CONVEX;
    memcpy(c->normal, best.normal, sizeof c->normal);
    c->depth = noct_max(0, best.depth); /* touching, as rounded */
    c->contained = !crossed;
    reduce(g->p, depth, g->n, c->normal, tol, c);
    free(depth);
    convex_free(&sa);
    convex_free(&sb);
    return NOCT_OK;
}

/* The centre-to-centre direction, or +z. */
static void centres(const placed *A, const placed *B, double n[3])
{
    double d[3];
    for (int k = 0; k < 3; ++k)
        d[k] = (B->m->centre[k] + B->t[k]) - (A->m->centre[k] + A->t[k]);
    if (!noct_unit3(d, n)) {
        n[0] = n[1] = 0;
        n[2] = 1;
    }
}

static noctStatus contact_crossing(const placed *A, const placed *B, gather *g, double tol,
                                   noctContact *c)
{
    if (g->n == 0) {
        /* No boundaries meet: a piece of one inside the other, or apart
         * (each piece of a boundary lies wholly in or out). */
        const placed *outer[2] = {A, B}, *inner[2] = {B, A};
        for (int s = 0; s < 2; ++s)
            for (size_t i = 0; i < inner[s]->m->npieces; ++i) {
                double p[3];
                bool in;
                noct_place_vertex(inner[s], inner[s]->m->piece[i], p);
                noctStatus st = noct_point_in_solid(outer[s]->m, outer[s]->t, p, &in);
                if (st != NOCT_OK)
                    return st;
                if (in) {
                    c->kind = NOCT_CONTACT_CONTAINED;
                    c->contained = true;
                    centres(A, B, c->normal);
                    c->count = 1;
                    memcpy(c->points[0], p, sizeof c->points[0]);
                    return NOCT_OK;
                }
            }
        return NOCT_OK;
    }
    c->kind = NOCT_CONTACT_CROSSING;
    if (!noct_unit3(g->wsum, c->normal) && !noct_unit3(g->usum, c->normal))
        centres(A, B, c->normal);
    reduce(g->p, NULL, g->n, c->normal, tol, c);
    return NOCT_OK;
}

noctStatus noct_contact_placed(const noctMesh *a, const double ta[3], bool a_convex,
                               const noctMesh *b, const double tb[3], bool b_convex,
                               noctContact *contact)
{
    memset(contact, 0, sizeof *contact);
    contact->kind = NOCT_CONTACT_NONE;
    const placed A = {a, {ta[0], ta[1], ta[2]}}, B = {b, {tb[0], tb[1], tb[2]}};
    if (!noct_boxes_overlap(a->lo, a->hi, ta, b->lo, b->hi, tb))
        return NOCT_OK;
    gather g = {.x = {NULL}};
    walk_ctx w = {{&A, &B}, &g};
    noct_bvh_pair_walk(&A, &B, prune_ctx, pair_points, &w);
    noctStatus st = NOCT_OK;
    if (g.nomem)
        st = NOCT_ERR_NOMEM;
    else {
        const double tol = 0x1p-30 * magnitude(&A, &B);
        st = a_convex && b_convex ? contact_convex(&A, &B, &g, tol, contact)
                                  : contact_crossing(&A, &B, &g, tol, contact);
    }
    free(g.p);
    if (st != NOCT_OK)
        memset(contact, 0, sizeof *contact);
    return st;
}

/* A mesh the contact treats as convex: convex, or box-shaped (a rotated
 * box, whose rounded corners bend its faces by an ulp, is the hull of
 * its corners within that). */
static bool convexish(const noctMesh *m)
{
    return m->convex || m->has_box;
}

noctStatus noctCollideContact(const noctMesh *a, const noctTransform *xa, const noctMesh *b,
                              const noctTransform *xb, bool *colliding, noctContact *contact,
                              noctError *err)
{
    NOCT_REQUIRE(a != NULL && xa != NULL && b != NULL && xb != NULL && colliding != NULL &&
                 contact != NULL);
    memset(contact, 0, sizeof *contact);
    contact->kind = NOCT_CONTACT_NONE;
    const noctTransform *x[2] = {xa, xb};
    const noctMesh *m[2] = {a, b};
    noctMesh *rotated[2] = {NULL, NULL};
    noctStatus st = noct_meshes_rotated(m, x, rotated, err);
    if (st == NOCT_OK) {
        st = noctCollide(m[0], xa->p, m[1], xb->p, NOCT_ACCURACY_EXACT, colliding, NULL);
        if (st == NOCT_OK && *colliding)
            st = noct_contact_placed(m[0], xa->p, convexish(a), m[1], xb->p, convexish(b),
                                     contact);
        if (st != NOCT_OK)
            noct_fail(err, st, -1, 0, "contact: %s", noctStatusString(st));
    }
    noctMeshDestroy(rotated[0]);
    noctMeshDestroy(rotated[1]);
    return st;
}
