/* SPDX-License-Identifier: MIT */
/*
 * Box forms (mesh_internal.h): a mesh of 8 vertices, 3 face and 3 edge
 * directions described as a parallelepiped that the exact level's filter
 * can trust, and the dual that bounds how far its triangles may lie from
 * the ideal box's faces. Geometry only: mesh.c asks it of every mesh it
 * makes, mesh_box.c of every box primitive; the distance's convex path
 * turns a mesh's form with its rotation (noct_box_slot_turned()).
 */
#include "config.h"

#include <float.h>
#include <math.h>
#include <string.h>

#include "internal.h"
#include "mesh_internal.h"
#include "vec3.h"

/*
 * Describe a mesh of 8 vertices with 3 face and 3 edge directions as a
 * parallelepiped (mesh_internal.h), if its vertices are the 8 corners
 * along its edge directions within a tiny deviation. Only a description
 * the filter can trust is kept: dev bounds the exact deviation of every
 * vertex coordinate from its corner, the rounding of its computation
 * included (3 additions and a difference of magnitudes at most S: well
 * under 8 half-ulps of S).
 */
/* The least float at or above x (x >= 0; +inf past the floats). */
static float float_above(double x)
{
    float f = (float)x;
    return (double)f < x ? nextafterf(f, INFINITY) : f;
}

void noct_box_form_of(const double *v, const double *const d[3], const uint32_t *tri,
                      size_t nt, box_form *b, bool *has_box, box_dual *x, bool *has_dual)
{
    *has_box = *has_dual = false;
    double c[3] = {0, 0, 0};
    for (size_t i = 0; i < 8; ++i)
        for (int k = 0; k < 3; ++k)
            c[k] += v[3 * i + k] / 8;
    double dual[3][3]; /* dual[i].d[j] = (i == j) * det */
    noct_cross3(d[1], d[2], dual[0]);
    noct_cross3(d[2], d[0], dual[1]);
    noct_cross3(d[0], d[1], dual[2]);
    double det = noct_dot3(d[0], dual[0]);
    if (!(fabs(det) > 1e-6))
        return;
    double coef[8][3], h[3] = {0, 0, 0};
    unsigned seen = 0;
    for (size_t i = 0; i < 8; ++i) {
        double r[3];
        noct_sub3(&v[3 * i], c, r);
        unsigned pattern = 0;
        for (int j = 0; j < 3; ++j) {
            coef[i][j] = noct_dot3(r, dual[j]) / det;
            if (coef[i][j] == 0)
                return;
            pattern |= (coef[i][j] > 0 ? 1u : 0u) << j;
            h[j] += fabs(coef[i][j]) / 8;
        }
        seen |= 1u << pattern;
    }
    if (seen != 0xffu)
        return; /* not one vertex at each corner */
    memcpy(b->c, c, sizeof c);
    for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k)
            b->e[j][k] = h[j] * d[j][k];
    double dev = 0, S = 0, V = 0;
    for (size_t i = 0; i < 8; ++i)
        for (int k = 0; k < 3; ++k) {
            double corner = c[k], mag = fabs(c[k]);
            for (int j = 0; j < 3; ++j) {
                corner += coef[i][j] > 0 ? b->e[j][k] : -b->e[j][k];
                mag += fabs(b->e[j][k]);
            }
            dev = fmax(dev, fabs(v[3 * i + k] - corner));
            S = fmax(S, mag);
            V = fmax(V, fabs(v[3 * i + k]));
        }
    dev = dev * (1 + 0x1p-50) + 8 * 0x1p-53 * (S + V);
    if (!(dev <= 1e-9 * fmax(h[0], fmax(h[1], h[2]))))
        return; /* too far from a box to be worth the description */
    b->size = S + dev;
    b->dev = float_above(dev);
    for (int i = 0; i < 3; ++i)
        b->own[i] = float_above(fabs(noct_dot3(b->e[i], b->e[0])) + fabs(noct_dot3(b->e[i], b->e[1])) +
                                fabs(noct_dot3(b->e[i], b->e[2])));
    *has_box = true;

    /* The dual, for the witness: every triangle on a face of the ideal box
     * (its three corners agree in one sign), and a well-conditioned box.
     * With it, the corners' vertices and the faces' triangles (two on
     * each face: 8 vertices of a closed mesh make 12 triangles). */
    unsigned on_face[6] = {0, 0, 0, 0, 0, 0};
    for (size_t i = 0; i < 8; ++i) {
        unsigned pattern = 0;
        for (int j = 0; j < 3; ++j)
            pattern |= (coef[i][j] > 0 ? 1u : 0u) << j;
        x->corner[pattern] = (uint8_t)i;
    }
    for (size_t t = 0; t < nt; ++t) {
        unsigned agree = 7;
        const double *q0 = coef[tri[3 * t]];
        for (int corner = 1; corner < 3; ++corner) {
            const double *q = coef[tri[3 * t + corner]];
            for (int j = 0; j < 3; ++j)
                if ((q[j] > 0) != (q0[j] > 0))
                    agree &= ~(1u << j);
        }
        if (agree == 0 || nt != 12)
            return;
        for (int j = 0; j < 3; ++j)
            if (agree & (1u << j)) {
                const unsigned f = 2 * (unsigned)j + (q0[j] > 0 ? 1u : 0u);
                if (on_face[f] == 2)
                    return;
                x->face[f][on_face[f]++] = (uint8_t)t;
            }
    }
    double eta = 0, mag = 0, gmax = 0;
    for (int i = 0; i < 3; ++i) {
        for (int k = 0; k < 3; ++k)
            x->g[i][k] = dual[i][k] / (det * h[i]);
        gmax = fmax(gmax, fabs(x->g[i][0]) + fabs(x->g[i][1]) + fabs(x->g[i][2]));
    }
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            eta = fmax(eta, fabs(noct_dot3(x->g[i], b->e[j]) - (i == j)));
            for (int k = 0; k < 3; ++k)
                mag = fmax(mag, fabs(x->g[i][k] * b->e[j][k]));
        }
    eta = eta * (1 + 0x1p-50) + 16 * 0x1p-53 * 3 * mag;
    if (!(eta <= 1e-14))
        return;
    x->eta = eta;
    x->gmax = gmax * (1 + 0x1p-50);
    x->shrink = float_above((2 * x->gmax * (double)b->dev + 8 * eta + 2e-15) * (1 + 0x1p-50));
    /* a box about the origin: every vertex (+-h0, +-h1, +-h2), each sign
     * pattern once */
    unsigned signs = 0;
    bool same = true;
    for (int i = 0; i < 8; ++i) {
        const double *p = &v[3 * i];
        same = same && fabs(p[0]) == fabs(v[0]) && fabs(p[1]) == fabs(v[1]) &&
               fabs(p[2]) == fabs(v[2]);
        x->sign[i] = (uint8_t)((p[0] > 0 ? 4u : 0u) | (p[1] > 0 ? 2u : 0u) | (p[2] > 0 ? 1u : 0u));
        signs |= 1u << x->sign[i];
    }
    x->about_origin = same && signs == 0xffu;
    x->frame_plus = 0;
    unsigned used = 0;
    for (int j = 0; j < 3 && x->about_origin; ++j) {
        const unsigned c7 = x->sign[x->corner[7]];
        const unsigned bit = c7 ^ x->sign[x->corner[7 ^ (1u << j)]];
        if ((bit != 1 && bit != 2 && bit != 4) || (used & bit)) {
            x->about_origin = false;
            break;
        }
        used |= bit;
        x->frame_axis[j] = (uint8_t)(bit == 4 ? 0 : bit == 2 ? 1 : 2);
        if (c7 & bit)
            x->frame_plus |= (uint8_t)(1u << j);
    }
    double lo = INFINITY, hi = 0;
    for (int i = 0; i < 3; ++i) {
        const double n = noct_norm3(b->e[i]);
        lo = noct_min(lo, n);
        hi = noct_max(hi, n);
    }
    x->far_from_flat = lo > 1e-6 * hi && (double)b->dev <= 0x1p-30 * lo;
    *has_dual = true;
}

/*
 * The slot of m's box form turned by R (mesh_internal.h), made of the
 * form, not of the turned vertices. A vertex v lies within dev of its
 * corner c + sum s_j e[j] (per coordinate); its turned vertex fl(R v)
 * then lies within, per coordinate k (rho_k = sum_l |R_kl|),
 *   rho_k dev                                  (R applied to the deviation)
 * + g3 rho_k (V + |c|_inf + sum_j |e[j]|_inf)  (rounding fl(R v), fl(R c),
 *                                               fl(R e[j]): 3 roundings each)
 * of the corner fl(R c) + sum s_j fl(R e[j]) of the turned form, with
 * g3 = 3u / (1 - 3u) < 4u (u = 2^-53) and V, |c|_inf, |e[j]|_inf each at
 * most the form's size: under rho (dev + 20 u size), rounded up by the
 * factor 1 + 2^-40 for its own few roundings. The dual is made afresh of
 * the turned half-edges (g[i] = e[j] x e[k] / det), its error eta bounded
 * as box_form_of() bounds it, so the slot's shrink, and with it the
 * oriented-box test's proof (noct_box_decide()), hold for the turned
 * vertices placed as fl(fl(R v) + t). The triangles lie on the faces of
 * the turned form as they lie on the form's (the same corners). No dual
 * (shrink +inf) when m has none or eta is not tiny; has_box 0 when m has
 * no form.
 */
static void slot_turned(const box_form *b, bool has_dual, const double R[9], noct_box_slot *s)
{
    s->has_box = 1;
    s->shrink = INFINITY;
    double rho = 0;
    for (int k = 0; k < 3; ++k)
        rho = noct_max(rho, fabs(R[3 * k]) + fabs(R[3 * k + 1]) + fabs(R[3 * k + 2]));
    noct_rotate(R, b->c, s->c);
    for (int j = 0; j < 3; ++j)
        noct_rotate(R, b->e[j], s->e[j]);
    const double dev = rho * ((double)b->dev + 20 * 0x1p-53 * b->size) * (1 + 0x1p-40);
    double size = 0;
    for (int k = 0; k < 3; ++k)
        size = noct_max(size, fabs(s->c[k]) + fabs(s->e[0][k]) + fabs(s->e[1][k]) +
                                  fabs(s->e[2][k]));
    s->size = (size + dev) * (1 + 0x1p-50);
    s->dev = float_above(dev);
    for (int i = 0; i < 3; ++i)
        s->own[i] = float_above(fabs(noct_dot3(s->e[i], s->e[0])) +
                             fabs(noct_dot3(s->e[i], s->e[1])) +
                             fabs(noct_dot3(s->e[i], s->e[2])));
    if (!has_dual)
        return;
    double g[3][3];
    noct_cross3(s->e[1], s->e[2], g[0]);
    noct_cross3(s->e[2], s->e[0], g[1]);
    noct_cross3(s->e[0], s->e[1], g[2]);
    const double det = noct_dot3(s->e[0], g[0]);
    if (!(fabs(det) > 0) || !isfinite(det))
        return;
    double eta = 0, mag = 0, gmax = 0;
    for (int i = 0; i < 3; ++i) {
        for (int k = 0; k < 3; ++k)
            g[i][k] /= det;
        gmax = noct_max(gmax, fabs(g[i][0]) + fabs(g[i][1]) + fabs(g[i][2]));
    }
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            eta = noct_max(eta, fabs(noct_dot3(g[i], s->e[j]) - (i == j)));
            for (int k = 0; k < 3; ++k)
                mag = noct_max(mag, fabs(g[i][k] * s->e[j][k]));
        }
    eta = eta * (1 + 0x1p-50) + 16 * 0x1p-53 * 3 * mag;
    if (!(eta <= 1e-14))
        return;
    gmax *= 1 + 0x1p-50;
    s->shrink = float_above((2 * gmax * (double)s->dev + 8 * eta + 2e-15) * (1 + 0x1p-50));
}

void noct_box_slot_turned(const noctMesh *m, const double R[9], noct_box_slot *s)
{
    s->has_box = 0;
    s->shrink = INFINITY;
    if (m->has_box)
        slot_turned(&m->box, m->has_dual, R, s);
}

/* A box primitive's form is exact: centre 0, half-edges the half-extents
 * along the axes, no deviation; its corners fl(R (+-h)) (noct_box_corners())
 * are the turned vertices the slot describes, its triangles on its faces. */
void noct_box_slot_of_half(const double half[3], const double R[9], noct_box_slot *s)
{
    box_form b;
    memset(&b, 0, sizeof b);
    for (int j = 0; j < 3; ++j)
        b.e[j][j] = half[j];
    b.size = fmax(half[0], fmax(half[1], half[2]));
    slot_turned(&b, true, R, s);
}

void noct_mesh_box_form(noctMesh *m)
{
    m->has_box = m->has_dual = false;
    if (m->nv != 8 || m->nsat_faces != 3 || m->nsat_edges != 3)
        return;
    const double *const d[3] = {m->axis[3].u, m->axis[4].u, m->axis[5].u};
    noct_box_form_of(m->v, d, m->tri, m->nt, &m->box, &m->has_box, &m->dual, &m->has_dual);
}
