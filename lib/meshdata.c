/* SPDX-License-Identifier: MIT */
/*
 * Mesh data (mesh.h): what a mesh file holds before it is a solid; the
 * welds, the inspection, the repair, the OFF writer, and the solid made
 * of it.
 */
#include "config.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "array.h"
#include "internal.h"
#include "meshdata_internal.h"

NOCT_DEFINE_GROW(grow_doubles, double)
NOCT_DEFINE_GROW(grow_longs, long)
NOCT_DEFINE_GROW(grow_u32, uint32_t)

/* The room to ask for need elements: 64 at first. */
static size_t room(size_t cap, size_t need)
{
    return cap == 0 && need < 64 ? 64 : need;
}

bool noct_data_add_vertex(noctMeshData *d, const double xyz[3], long line)
{
    if (!grow_doubles(&d->v, &d->cap_v, room(d->cap_v, 3 * (d->nv + 1))) ||
        !grow_longs(&d->vline, &d->cap_vline, room(d->cap_vline, d->nv + 1)))
        return false;
    memcpy(&d->v[3 * d->nv], xyz, 3 * sizeof *xyz);
    d->vline[d->nv++] = line;
    return true;
}

bool noct_data_add_polygon(noctMeshData *d, const uint32_t *corners, uint32_t n, long line)
{
    if (!grow_u32(&d->sizes, &d->cap_sizes, room(d->cap_sizes, d->np + 1)) ||
        !grow_longs(&d->pline, &d->cap_pline, room(d->cap_pline, d->np + 1)) ||
        !grow_u32(&d->idx, &d->cap_idx, room(d->cap_idx, d->ni + n)))
        return false;
    memcpy(&d->idx[d->ni], corners, n * sizeof *corners);
    d->ni += n;
    d->sizes[d->np] = n;
    d->pline[d->np++] = line;
    return true;
}

void noctMeshDataDestroy(noctMeshData *data)
{
    if (data == NULL)
        return;
    free(data->v);
    free(data->vline);
    free(data->sizes);
    free(data->pline);
    free(data->idx);
    free(data->path);
    free(data);
}

size_t noctMeshDataVertexCount(const noctMeshData *data)
{
    NOCT_REQUIRE(data != NULL);
    return data->nv;
}

const double *noctMeshDataVertices(const noctMeshData *data)
{
    NOCT_REQUIRE(data != NULL);
    return data->nv > 0 ? data->v : NULL;
}

size_t noctMeshDataPolygonCount(const noctMeshData *data)
{
    NOCT_REQUIRE(data != NULL);
    return data->np;
}

const uint32_t *noctMeshDataPolygonSizes(const noctMeshData *data)
{
    NOCT_REQUIRE(data != NULL);
    return data->np > 0 ? data->sizes : NULL;
}

const uint32_t *noctMeshDataIndices(const noctMeshData *data)
{
    NOCT_REQUIRE(data != NULL);
    return data->ni > 0 ? data->idx : NULL;
}

noctStatus noctMeshDataCreate(const double *vertices, size_t nvertices,
                              const uint32_t *sizes, size_t npolygons,
                              const uint32_t *indices, noctMeshData **data,
                              noctError *err)
{
    NOCT_REQUIRE(data != NULL);
    NOCT_REQUIRE(nvertices == 0 || vertices != NULL);
    NOCT_REQUIRE(npolygons == 0 || sizes != NULL);
    *data = NULL;
    if (nvertices > NOCT_MESH_MAX_VERTICES)
        return noct_fail(err, NOCT_ERR_TOO_LARGE, -1, 0, "%zu vertices (at most %u)",
                         nvertices, (unsigned)NOCT_MESH_MAX_VERTICES);
    for (size_t i = 0; i < 3 * nvertices; ++i)
        if (!isfinite(vertices[i]))
            return noct_fail(err, NOCT_ERR_NONFINITE, (long)(i / 3), 0,
                             "vertex %zu: coordinate %c is %g", i / 3, "xyz"[i % 3],
                             vertices[i]);
    size_t nidx = 0;
    for (size_t p = 0; p < npolygons; ++p) {
        if (sizes[p] < 3)
            return noct_fail(err, NOCT_ERR_DEGENERATE, (long)p, 0,
                             "polygon %zu has %u corners (at least 3)", p, sizes[p]);
        nidx += sizes[p];
        if (nidx > NOCT_MESH_MAX_INDICES)
            return noct_fail(err, NOCT_ERR_TOO_LARGE, (long)p, 0,
                             "more than %u polygon corners", (unsigned)NOCT_MESH_MAX_INDICES);
    }
    NOCT_REQUIRE(nidx == 0 || indices != NULL);
    for (size_t p = 0, base = 0; p < npolygons; base += sizes[p], ++p)
        for (uint32_t c = 0; c < sizes[p]; ++c)
            if (indices[base + c] >= nvertices)
                return noct_fail(err, NOCT_ERR_INDEX, (long)p, 0,
                                 "polygon %zu: vertex index %u out of range (%zu vertices)",
                                 p, indices[base + c], nvertices);
    noctMeshData *d = calloc(1, sizeof *d);
    if (d == NULL)
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    bool ok = true;
    for (size_t i = 0; i < nvertices && ok; ++i)
        ok = noct_data_add_vertex(d, &vertices[3 * i], 0);
    for (size_t p = 0, base = 0; p < npolygons && ok; base += sizes[p], ++p)
        ok = noct_data_add_polygon(d, &indices[base], sizes[p], 0);
    if (!ok) {
        noctMeshDataDestroy(d);
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    }
    *data = d;
    return NOCT_OK;
}

/* ---- welding --------------------------------------------------------------------- */

typedef struct weld_key {
    double k[3];   /* coordinates (exact weld) or cell (tolerance weld) */
    uint32_t i;    /* vertex */
} weld_key;

static int cmp_weld_key(const void *x, const void *y)
{
    const weld_key *a = x, *b = y;
    for (int k = 0; k < 3; ++k)
        if (a->k[k] != b->k[k])
            return a->k[k] < b->k[k] ? -1 : 1;
    return (a->i > b->i) - (a->i < b->i);
}

/* Union-find whose root is the least index of its class. */
static uint32_t uf_find(uint32_t *parent, uint32_t x)
{
    while (parent[x] != x) {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    return x;
}

static void uf_union(uint32_t *parent, uint32_t a, uint32_t b)
{
    a = uf_find(parent, a);
    b = uf_find(parent, b);
    if (a < b)
        parent[b] = a;
    else if (b < a)
        parent[a] = b;
}

/* |a - b| <= eps exactly (a, b finite, eps > 0 finite). The rounded
 * difference s = fl(a - b) decides unless |s| == eps: rounding is monotone
 * and eps is a double, so |a - b| <= eps implies |s| <= eps and |a - b| > eps
 * implies |s| >= eps. When |s| == eps, the exact difference is s + t with
 * t from Knuth's TwoSum (exact: no overflow, since |s| is finite), and
 * |s + t| <= eps iff t is 0 or of the other sign than s. An overflowing
 * difference is infinite, more than eps. */
static bool coord_close(double a, double b, double eps)
{
    double s = a - b;
    if (fabs(s) != eps)
        return fabs(s) < eps;
    double bv = s - a;
    double t = (a - (s - bv)) + (-b - bv);
    return t == 0 || (t < 0) != (s < 0);
}

/* floor(v / eps) exactly, for |v| / eps < 2^53 (so that the cells and
 * their neighbours' numbers, at most 2^53 in magnitude, are exact
 * doubles). The rounded quotient's
 * floor is off by at most one; fma(q, eps, -v) rounds q eps - v once, and
 * the exact value is a multiple of 2^-1074 (q is an integer), so its sign
 * survives the rounding: q eps <= v < (q + 1) eps is checked exactly. */
static double cell_of(double v, double eps)
{
    double q = floor(v / eps);
    while (fma(q, eps, -v) > 0)
        q -= 1;
    while (fma(q + 1, eps, -v) <= 0)
        q += 1;
    return q + 0.0;
}

/* A cell's points sorted by one coordinate. */
typedef struct axis_item {
    double x;
    uint32_t i;
} axis_item;

static int cmp_axis_item(const void *x, const void *y)
{
    const axis_item *a = x, *b = y;
    if (a->x != b->x)
        return a->x < b->x ? -1 : 1;
    return (a->i > b->i) - (a->i < b->i);
}

/* The tolerance weld's state: the keys sorted by cell, the cells (runs of
 * keys), each cell's bounds, its points sorted along each axis (made when
 * first needed) and scratch space for the cell pairs' decisions. */
typedef struct weld_grid {
    const double *v;
    double eps;
    const weld_key *keys;
    size_t ncell;
    size_t *start;          /* cell c is keys[start[c], start[c + 1]) */
    double *lo, *hi;        /* 3 per cell: the bounds of its points */
    axis_item *axis[3];     /* axis[k][start[c] ...]: cell c sorted along k */
    uint8_t *sorted;        /* 3 per cell: whether axis[k] is made */
    uint32_t *best;         /* scratch: prefix bests, a Fenwick tree */
    uint32_t *place;        /* scratch, by vertex: its place along an axis */
    axis_item *order;       /* scratch: the points of B in sweep order */
} weld_grid;

static const axis_item *cell_axis(weld_grid *g, size_t c, int k)
{
    axis_item *a = g->axis[k] + g->start[c];
    size_t n = g->start[c + 1] - g->start[c];
    if (!g->sorted[3 * c + (size_t)k]) {
        for (size_t j = 0; j < n; ++j) {
            uint32_t i = g->keys[g->start[c] + j].i;
            a[j] = (axis_item){g->v[3 * i + (size_t)k], i};
        }
        qsort(a, n, sizeof *a, cmp_axis_item);
        g->sorted[3 * c + (size_t)k] = 1;
    }
    return a;
}

/* The j-th point of cell A's list along axis k, best first: the largest
 * coordinate first if B lies above A on that axis (s = 1), the smallest
 * first if below (s = -1). */
static uint32_t nth_best(const axis_item *list, size_t n, int s, size_t j)
{
    return s > 0 ? list[n - 1 - j].i : list[j].i;
}

/* How many of cell A's points, in that best-first order along axis k, are
 * within eps of coordinate y on axis k: a prefix, since coordinates of A
 * are below (s = 1) or above (s = -1) every coordinate of B on that axis,
 * and the exact |x - y| <= eps is monotone in x then. */
static size_t prefix_close(const weld_grid *g, const axis_item *list, size_t n, int s, int k,
                           double y)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (coord_close(g->v[3 * nth_best(list, n, s, mid) + (size_t)k], y, g->eps))
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

/* The better of points i and j on axis k for direction s. */
static uint32_t better(const double *v, int k, int s, uint32_t i, uint32_t j)
{
    double a = v[3 * i + (size_t)k], b = v[3 * j + (size_t)k];
    return (s > 0 ? a >= b : a <= b) ? i : j;
}

/* Whether some point of cell a and some point of cell b (b's cell is a's
 * plus d, d in {-1, 0, 1}^3, not 0) are within eps on every axis. On an
 * axis where d is 0 both lie in one cell of side eps: within eps. On the
 * others, B's coordinates are all above A's (d = 1) or below (d = -1), and
 * the decision is a dominance question on those m axes: m = 1 by the
 * cells' bounds, m = 2 by A's prefix bests along one axis and a binary
 * search per point of B, m = 3 by a sweep over B in the order of its
 * prefixes along the first axis, with a Fenwick tree of A's bests on the
 * third axis indexed by rank along the second. O((|A| + |B|) log |A|). */
static bool cells_meet(weld_grid *g, size_t a, size_t b, const int d[3])
{
    int ax[3], m = 0;
    for (int k = 0; k < 3; ++k)
        if (d[k] != 0)
            ax[m++] = k;
    const double eps = g->eps;
    /* bounds first: the best pair per axis, the worst pair per axis */
    bool all = true;
    for (int j = 0; j < m; ++j) {
        int k = ax[j];
        double abest = d[k] > 0 ? g->hi[3 * a + (size_t)k] : g->lo[3 * a + (size_t)k];
        double bbest = d[k] > 0 ? g->lo[3 * b + (size_t)k] : g->hi[3 * b + (size_t)k];
        if (!coord_close(abest, bbest, eps))
            return false;
        double aworst = d[k] > 0 ? g->lo[3 * a + (size_t)k] : g->hi[3 * a + (size_t)k];
        double bworst = d[k] > 0 ? g->hi[3 * b + (size_t)k] : g->lo[3 * b + (size_t)k];
        all = all && coord_close(aworst, bworst, eps);
    }
    if (all || m == 1)
        return true;
    size_t na = g->start[a + 1] - g->start[a], nb = g->start[b + 1] - g->start[b];
    const double *v = g->v;
    int k0 = ax[0], k1 = ax[1], s0 = d[k0], s1 = d[k1];
    const axis_item *a0 = cell_axis(g, a, k0);
    if (m == 2) {
        /* best[j]: the best on axis k1 of A's first j + 1 along k0 */
        for (size_t j = 0; j < na; ++j) {
            uint32_t p = nth_best(a0, na, s0, j);
            g->best[j] = j == 0 ? p : better(v, k1, s1, g->best[j - 1], p);
        }
        for (size_t j = 0; j < nb; ++j) {
            const double *q = &v[3 * g->keys[g->start[b] + j].i];
            size_t len = prefix_close(g, a0, na, s0, k0, q[k0]);
            if (len > 0 && coord_close(v[3 * g->best[len - 1] + (size_t)k1], q[k1], eps))
                return true;
        }
        return false;
    }
    int k2 = ax[2], s2 = d[k2];
    const axis_item *a1 = cell_axis(g, a, k1);
    /* place[p]: point p's place along k1, best first; the Fenwick tree
     * best[] over those places holds the best point on k2 */
    for (size_t j = 0; j < na; ++j) {
        g->place[nth_best(a1, na, s1, j)] = (uint32_t)j;
        g->best[j] = UINT32_MAX;
    }
    /* B's points in the order of their prefixes along k0 */
    axis_item *ord = g->order;
    for (size_t j = 0; j < nb; ++j) {
        uint32_t q = g->keys[g->start[b] + j].i;
        ord[j] = (axis_item){(double)prefix_close(g, a0, na, s0, k0, v[3 * q + (size_t)k0]), q};
    }
    qsort(ord, nb, sizeof *ord, cmp_axis_item);
    size_t inserted = 0;
    for (size_t j = 0; j < nb; ++j) {
        size_t len0 = (size_t)ord[j].x;
        const double *q = &v[3 * ord[j].i];
        for (; inserted < len0; ++inserted) {
            uint32_t p = nth_best(a0, na, s0, inserted);
            for (size_t r = (size_t)g->place[p] + 1; r <= na; r += r & (~r + 1))
                g->best[r - 1] = g->best[r - 1] == UINT32_MAX
                                     ? p
                                     : better(v, k2, s2, g->best[r - 1], p);
        }
        size_t len1 = prefix_close(g, a1, na, s1, k1, q[k1]);
        uint32_t p = UINT32_MAX;
        for (size_t r = len1; r > 0; r -= r & (~r + 1))
            if (g->best[r - 1] != UINT32_MAX)
                p = p == UINT32_MAX ? g->best[r - 1] : better(v, k2, s2, p, g->best[r - 1]);
        if (p != UINT32_MAX && coord_close(v[3 * p + (size_t)k2], q[k2], eps))
            return true;
    }
    return false;
}

/* The classes of the tolerance weld (see weld_classes()): cells of side
 * eps, exactly (cell_of()), so that two points of one cell are within eps
 * on every axis and two points within eps lie in the same or adjacent
 * cells. A cell's points are one class at once; each pair of adjacent
 * cells is decided once (the 13 neighbours after it in lexicographic
 * order) by cells_meet(), unless its cells are of one class already.
 * O(n log n) whatever the points: each cell meets at most 26 others, at a
 * cost of O(size log size) each. False if memory runs out. */
static bool weld_tolerance_classes(const noctMeshData *d, double eps, weld_key *keys,
                                   uint32_t *parent)
{
    size_t n = d->nv;
    for (size_t i = 0; i < n; ++i) {
        parent[i] = (uint32_t)i;
        keys[i].i = (uint32_t)i;
        for (int k = 0; k < 3; ++k)
            keys[i].k[k] = cell_of(d->v[3 * i + (size_t)k], eps);
    }
    if (n == 0)
        return true;
    qsort(keys, n, sizeof *keys, cmp_weld_key);
    size_t ncell = 1;
    for (size_t j = 1; j < n; ++j)
        ncell += memcmp(keys[j].k, keys[j - 1].k, sizeof keys[j].k) != 0;
    weld_grid g = {.v = d->v, .eps = eps, .keys = keys, .ncell = ncell};
    g.start = malloc((ncell + 1) * sizeof *g.start);
    g.lo = malloc(3 * ncell * sizeof *g.lo);
    g.hi = malloc(3 * ncell * sizeof *g.hi);
    g.sorted = calloc(3 * ncell, 1);
    g.best = malloc(n * sizeof *g.best);
    g.place = malloc(n * sizeof *g.place);
    g.order = malloc(n * sizeof *g.order);
    bool ok = g.start && g.lo && g.hi && g.sorted && g.best && g.place && g.order;
    for (int k = 0; k < 3; ++k) {
        g.axis[k] = ok ? malloc(n * sizeof *g.axis[k]) : NULL;
        ok = ok && g.axis[k] != NULL;
    }
    if (ok) {
        /* the cells, their bounds; a cell's points are one class (its
         * first key has the least vertex number) */
        size_t c = 0;
        for (size_t j = 0; j < n; ++j) {
            const double *p = &d->v[3 * keys[j].i];
            if (j == 0 || memcmp(keys[j].k, keys[j - 1].k, sizeof keys[j].k) != 0) {
                g.start[c++] = j;
                for (int k = 0; k < 3; ++k)
                    g.lo[3 * (c - 1) + (size_t)k] = g.hi[3 * (c - 1) + (size_t)k] = p[k];
            } else {
                parent[keys[j].i] = keys[g.start[c - 1]].i;
                for (int k = 0; k < 3; ++k) {
                    double *lo = &g.lo[3 * (c - 1) + (size_t)k];
                    double *hi = &g.hi[3 * (c - 1) + (size_t)k];
                    *lo = p[k] < *lo ? p[k] : *lo;
                    *hi = p[k] > *hi ? p[k] : *hi;
                }
            }
        }
        g.start[ncell] = n;
        for (size_t a = 0; a < ncell; ++a) {
            const double *ca = keys[g.start[a]].k;
            for (int dx = 0; dx <= 1; ++dx)
                for (int dy = dx ? -1 : 0; dy <= 1; ++dy)
                    for (int dz = dx || dy ? -1 : 1; dz <= 1; ++dz) {
                        const int dd[3] = {dx, dy, dz};
                        double cell[3] = {ca[0] + dx, ca[1] + dy, ca[2] + dz};
                        /* the cell, by binary search over the cells */
                        size_t lo = a + 1, hi = ncell;
                        while (lo < hi) {
                            size_t mid = lo + (hi - lo) / 2;
                            weld_key probe = {{cell[0], cell[1], cell[2]}, 0};
                            if (cmp_weld_key(&keys[g.start[mid]], &probe) < 0)
                                lo = mid + 1;
                            else
                                hi = mid;
                        }
                        if (lo == ncell ||
                            memcmp(keys[g.start[lo]].k, cell, sizeof cell) != 0)
                            continue;
                        uint32_t ra = uf_find(parent, keys[g.start[a]].i);
                        uint32_t rb = uf_find(parent, keys[g.start[lo]].i);
                        if (ra != rb && cells_meet(&g, a, lo, dd))
                            uf_union(parent, ra, rb);
                    }
        }
        for (size_t i = 0; i < n; ++i)
            parent[i] = uf_find(parent, (uint32_t)i);
    }
    free(g.start);
    free(g.lo);
    free(g.hi);
    free(g.sorted);
    free(g.best);
    free(g.place);
    free(g.order);
    for (int k = 0; k < 3; ++k)
        free(g.axis[k]);
    return ok;
}

/* The classes of the exact weld, as each vertex's least-index
 * representative in parent[]: equal coordinates (with -0 as +0, by adding
 * +0.0). */
static void weld_classes(const noctMeshData *d, weld_key *keys, uint32_t *parent)
{
    size_t n = d->nv;
    for (size_t i = 0; i < n; ++i) {
        parent[i] = (uint32_t)i;
        keys[i].i = (uint32_t)i;
        for (int k = 0; k < 3; ++k)
            keys[i].k[k] = d->v[3 * i + (size_t)k] + 0.0;
    }
    if (n > 0)
        qsort(keys, n, sizeof *keys, cmp_weld_key);
    for (size_t a = 0; a < n;) {
        size_t b = a + 1;
        /* memcmp after +0.0: equal doubles, -0 folded; NaN never here */
        while (b < n && memcmp(keys[b].k, keys[a].k, sizeof keys[a].k) == 0)
            ++b;
        for (size_t j = a + 1; j < b; ++j)
            parent[keys[j].i] = keys[a].i;
        a = b;
    }
}

/* Whether corners c[0, n) repeat a vertex. */
static bool has_repeat(const uint32_t *c, uint32_t n)
{
    for (uint32_t i = 0; i < n; ++i)
        for (uint32_t j = i + 1; j < n; ++j)
            if (c[i] == c[j])
                return true;
    return false;
}

noctStatus noctMeshDataWeld(noctMeshData *data, double tolerance,
                            noctMeshWeldReport *report, noctError *err)
{
    NOCT_REQUIRE(data != NULL);
    noctMeshData *d = data;
    if (report != NULL)
        *report = (noctMeshWeldReport){0, 0};
    if (!(tolerance >= 0) || !isfinite(tolerance))
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0,
                         "the weld tolerance %g is not a finite number >= 0", tolerance);
    if (tolerance > 0)
        for (size_t i = 0; i < 3 * d->nv; ++i)
            if (fabs(d->v[i]) / tolerance >= 0x1p53) /* rounded up or exact: < 2^53 if not */
                return noct_fail(err, NOCT_ERR_INVALID, (long)(i / 3), 0,
                                 "the weld tolerance %g is too small for vertex %zu's "
                                 "coordinate %g (2^53 tolerances or more from 0)",
                                 tolerance, i / 3, d->v[i]);
    size_t n = d->nv;
    weld_key *keys = malloc((n > 0 ? n : 1) * sizeof *keys);
    uint32_t *parent = malloc((n > 0 ? n : 1) * sizeof *parent);
    uint32_t *corners = NULL;
    size_t ccap = 0;
    uint32_t maxsize = 0;
    for (size_t p = 0; p < d->np; ++p)
        maxsize = d->sizes[p] > maxsize ? d->sizes[p] : maxsize;
    if (keys == NULL || parent == NULL || !grow_u32(&corners, &ccap, maxsize + 1)) {
        free(keys);
        free(parent);
        free(corners);
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    }
    bool classes = true;
    if (tolerance > 0)
        classes = weld_tolerance_classes(d, tolerance, keys, parent);
    else
        weld_classes(d, keys, parent);
    free(keys);
    if (!classes) {
        free(parent);
        free(corners);
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    }
    /* From here on nothing allocates: the data changes in place. New
     * numbers: the representatives in order; the others their
     * representative's (a smaller index, numbered already). */
    uint32_t kept = 0;
    for (size_t i = 0; i < n; ++i) {
        if (parent[i] == i) {
            memmove(&d->v[3 * kept], &d->v[3 * i], 3 * sizeof *d->v);
            d->vline[kept] = d->vline[i];
            parent[i] = kept++;
        } else {
            parent[i] = parent[parent[i]];
        }
    }
    size_t welded = n - kept, dropped = 0;
    d->nv = kept;
    size_t out = 0, outp = 0;
    for (size_t p = 0, base = 0; p < d->np; base += d->sizes[p], ++p) {
        uint32_t m = 0, sz = d->sizes[p];
        for (uint32_t c = 0; c < sz; ++c) {
            uint32_t v = parent[d->idx[base + c]];
            if (m == 0 || corners[m - 1] != v)
                corners[m++] = v;
        }
        while (m > 1 && corners[m - 1] == corners[0])
            --m;
        if (m < 3 || has_repeat(corners, m)) {
            ++dropped;
            continue;
        }
        memcpy(&d->idx[out], corners, m * sizeof *corners);
        out += m;
        d->sizes[outp] = m;
        d->pline[outp++] = d->pline[p];
    }
    d->np = outp;
    d->ni = out;
    d->welded += welded;
    d->dropped += dropped;
    free(parent);
    free(corners);
    if (report != NULL)
        *report = (noctMeshWeldReport){welded, dropped};
    return NOCT_OK;
}

/* ---- edges, duplicates, components --------------------------------------------------- */

typedef struct half_edge {
    uint32_t lo, hi;  /* vertices, lo < hi */
    uint32_t poly;
    uint32_t forward; /* 1 if the polygon runs lo -> hi */
} half_edge;

static int cmp_half_edge(const void *x, const void *y)
{
    const half_edge *a = x, *b = y;
    if (a->lo != b->lo)
        return a->lo < b->lo ? -1 : 1;
    if (a->hi != b->hi)
        return a->hi < b->hi ? -1 : 1;
    return (a->poly > b->poly) - (a->poly < b->poly);
}

/* A polygon's canonical form: its corners from the least, in the
 * direction of the lesser neighbour of it; hashed. */
typedef struct canon {
    uint64_t hash;
    uint32_t poly, start;
    uint32_t backward; /* 1 if the canonical order reverses the polygon's */
} canon;

static int cmp_canon(const void *x, const void *y)
{
    const canon *a = x, *b = y;
    if (a->hash != b->hash)
        return a->hash < b->hash ? -1 : 1;
    return (a->poly > b->poly) - (a->poly < b->poly);
}

static uint32_t canon_at(const noctMeshData *d, const size_t *base, const canon *c, uint32_t k)
{
    uint32_t n = d->sizes[c->poly];
    uint32_t j = c->backward ? (c->start + n - k % n) % n : (c->start + k) % n;
    return d->idx[base[c->poly] + j];
}

static bool same_canon(const noctMeshData *d, const size_t *base, const canon *a,
                       const canon *b)
{
    if (d->sizes[a->poly] != d->sizes[b->poly])
        return false;
    for (uint32_t k = 0; k < d->sizes[a->poly]; ++k)
        if (canon_at(d, base, a, k) != canon_at(d, base, b, k))
            return false;
    return true;
}

/* Everything the inspection and the repair need to know of the topology. */
typedef struct topo {
    size_t *base;       /* first corner of each polygon */
    half_edge *he;      /* sorted */
    uint32_t *first;    /* duplicates: the first polygon like each, */
    uint8_t *reversed;  /* and whether it runs the other way */
    uint32_t *comp;     /* the root (least polygon) of each polygon's component */
    uint8_t *flip;      /* parity to the root: flip to run like it */
    uint8_t *comp_open; /* per root: an edge of the component is not used twice */
    uint8_t *comp_bad;  /* per root: the component is not orientable */
} topo;

static void topo_free(topo *t)
{
    free(t->base);
    free(t->he);
    free(t->first);
    free(t->reversed);
    free(t->comp);
    free(t->flip);
    free(t->comp_open);
    free(t->comp_bad);
}

/* Union-find with parity: flip[x] is x's parity relative to comp[x]. */
static uint32_t pfind(topo *t, uint32_t x, uint8_t *parity)
{
    uint8_t p = 0;
    uint32_t r = x;
    while (t->comp[r] != r) {
        p ^= t->flip[r];
        r = t->comp[r];
    }
    uint8_t q = p;
    while (t->comp[x] != x) {
        uint32_t next = t->comp[x];
        uint8_t nq = q ^ t->flip[x];
        t->comp[x] = r;
        t->flip[x] = q;
        x = next;
        q = nq;
    }
    *parity = p;
    return r;
}

/* Join polygons a and b so that their parities differ by rel; false if
 * they are joined already with the other relation. */
static bool punion(topo *t, uint32_t a, uint32_t b, uint8_t rel)
{
    uint8_t pa, pb;
    uint32_t ra = pfind(t, a, &pa), rb = pfind(t, b, &pb);
    if (ra == rb)
        return (pa ^ pb) == rel;
    if (ra < rb) {
        t->comp[rb] = ra;
        t->flip[rb] = pa ^ pb ^ rel;
    } else {
        t->comp[ra] = rb;
        t->flip[ra] = pa ^ pb ^ rel;
    }
    return true;
}

static noctStatus topo_build(const noctMeshData *d, topo *t, noctError *err)
{
    size_t np = d->np, ni = d->ni, one = 1;
    memset(t, 0, sizeof *t);
    t->base = malloc((np > 0 ? np : one) * sizeof *t->base);
    t->he = malloc((ni > 0 ? ni : one) * sizeof *t->he);
    t->first = malloc((np > 0 ? np : one) * sizeof *t->first);
    t->reversed = calloc(np > 0 ? np : one, 1);
    t->comp = malloc((np > 0 ? np : one) * sizeof *t->comp);
    t->flip = calloc(np > 0 ? np : one, 1);
    t->comp_open = calloc(np > 0 ? np : one, 1);
    t->comp_bad = calloc(np > 0 ? np : one, 1);
    canon *cn = malloc((np > 0 ? np : one) * sizeof *cn);
    if (t->base == NULL || t->he == NULL || t->first == NULL || t->reversed == NULL ||
        t->comp == NULL || t->flip == NULL || t->comp_open == NULL || t->comp_bad == NULL ||
        cn == NULL) {
        free(cn);
        topo_free(t);
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    }
    size_t k = 0;
    for (size_t p = 0, base = 0; p < np; base += d->sizes[p], ++p) {
        t->base[p] = base;
        t->comp[p] = (uint32_t)p;
        t->first[p] = (uint32_t)p;
        uint32_t n = d->sizes[p];
        const uint32_t *c = &d->idx[base];
        uint32_t start = 0;
        for (uint32_t i = 0; i < n; ++i) {
            uint32_t a = c[i], b = c[(i + 1) % n];
            t->he[k++] = (half_edge){a < b ? a : b, a < b ? b : a, (uint32_t)p, a < b};
            if (c[i] < c[start])
                start = i;
        }
        cn[p].poly = (uint32_t)p;
        cn[p].start = start;
        cn[p].backward = c[(start + n - 1) % n] < c[(start + 1) % n];
        uint64_t h = 1469598103934665603u;
        for (uint32_t j = 0; j < n; ++j) {
            h ^= canon_at(d, t->base, &cn[p], j);
            h *= 1099511628211u;
        }
        cn[p].hash = h;
    }
    if (ni > 0)
        qsort(t->he, ni, sizeof *t->he, cmp_half_edge);
    if (np > 0)
        qsort(cn, np, sizeof *cn, cmp_canon);
    for (size_t a = 0; a < np;) {
        size_t b = a + 1;
        while (b < np && cn[b].hash == cn[a].hash)
            ++b;
        for (size_t i = a + 1; i < b; ++i)
            for (size_t j = a; j < i; ++j)
                if (t->first[cn[j].poly] == cn[j].poly && same_canon(d, t->base, &cn[j], &cn[i])) {
                    t->first[cn[i].poly] = cn[j].poly;
                    t->reversed[cn[i].poly] = cn[i].backward != cn[j].backward;
                    break;
                }
        a = b;
    }
    free(cn);
    /* Components and orientation: every edge joins its polygons; an edge
     * used twice asks them to run it opposite ways (parity: flip one iff
     * they run it alike). */
    for (size_t a = 0; a < ni;) {
        size_t b = a + 1;
        while (b < ni && t->he[b].lo == t->he[a].lo && t->he[b].hi == t->he[a].hi)
            ++b;
        if (b - a == 2) {
            if (!punion(t, t->he[a].poly, t->he[a + 1].poly,
                        t->he[a].forward == t->he[a + 1].forward))
                t->comp_bad[t->he[a].poly] = 1; /* marked on its root below */
        } else {
            for (size_t j = a + 1; j < b; ++j)
                if (!punion(t, t->he[a].poly, t->he[j].poly, 0)) /* joined either way */
                    punion(t, t->he[a].poly, t->he[j].poly, 1);
        }
        a = b;
    }
    uint8_t par;
    for (size_t p = 0; p < np; ++p)
        pfind(t, (uint32_t)p, &par);
    for (size_t p = 0; p < np; ++p)
        if (t->comp_bad[p] && t->comp[p] != p) {
            t->comp_bad[t->comp[p]] = 1;
            t->comp_bad[p] = 0;
        }
    for (size_t a = 0; a < ni;) {
        size_t b = a + 1;
        while (b < ni && t->he[b].lo == t->he[a].lo && t->he[b].hi == t->he[a].hi)
            ++b;
        if (b - a != 2)
            t->comp_open[t->comp[t->he[a].poly]] = 1;
        a = b;
    }
    return NOCT_OK;
}

/* 6 times the signed volume of the polygons' fans, each flipped as asked
 * (flip may be NULL), about the point o; per component root into per[]
 * (if not NULL). */
static double fan_volume(const noctMeshData *d, const topo *t, const double o[3],
                         bool use_flip, double *per)
{
    double total = 0;
    for (size_t p = 0; p < d->np; ++p) {
        const uint32_t *c = &d->idx[t->base[p]];
        double sum = 0;
        for (uint32_t i = 1; i + 1 < d->sizes[p]; ++i) {
            const double *p0 = &d->v[3 * c[0]], *p1 = &d->v[3 * c[i]], *p2 = &d->v[3 * c[i + 1]];
            double a[3], b[3], e[3];
            for (int k = 0; k < 3; ++k) {
                a[k] = p0[k] - o[k];
                b[k] = p1[k] - o[k];
                e[k] = p2[k] - o[k];
            }
            sum += a[0] * (b[1] * e[2] - b[2] * e[1]) + a[1] * (b[2] * e[0] - b[0] * e[2]) +
                   a[2] * (b[0] * e[1] - b[1] * e[0]);
        }
        if (use_flip && t->flip[p])
            sum = -sum;
        total += sum;
        if (per != NULL)
            per[t->comp[p]] += sum;
    }
    return total;
}

static void lowest_corner(const noctMeshData *d, double o[3])
{
    for (int k = 0; k < 3; ++k)
        o[k] = d->nv > 0 ? d->v[k] : 0;
    for (size_t i = 0; i < d->nv; ++i)
        for (int k = 0; k < 3; ++k)
            o[k] = fmin(o[k], d->v[3 * i + k]);
}

/* Append to buf (of size NOCT_ERROR_MESSAGE_SIZE) as snprintf would. */
static void append(char *buf, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

static void append(char *buf, const char *fmt, ...)
{
    size_t len = strlen(buf);
    if (len + 1 >= NOCT_ERROR_MESSAGE_SIZE)
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf + len, NOCT_ERROR_MESSAGE_SIZE - len, fmt, ap);
    va_end(ap);
}

static void append_edges(char *buf, size_t count, const char *what,
                         uint32_t (*first)[2], const size_t *uses)
{
    if (count == 0)
        return;
    append(buf, "%s%zu %s edge%s, first", buf[0] ? "; " : "", count, what,
           count == 1 ? "" : "s");
    for (size_t i = 0; i < count && i < NOCT_MESH_REPORT_FIRST; ++i) {
        append(buf, "%s %u-%u", i > 0 ? "," : "", first[i][0], first[i][1]);
        if (uses != NULL)
            append(buf, " (%zu polygons)", uses[i]);
    }
}

noctStatus noctMeshDataInspect(const noctMeshData *data, noctMeshReport *report,
                               noctError *err)
{
    NOCT_REQUIRE(data != NULL && report != NULL);
    const noctMeshData *d = data;
    noctMeshReport *r = report;
    memset(r, 0, sizeof *r);
    r->vertices = d->nv;
    r->polygons = d->np;
    r->welded_vertices = d->welded;
    r->dropped_polygons = d->dropped;
    r->skipped_primitives = d->skipped;
    for (size_t p = 0; p < d->np; ++p)
        r->triangles += d->sizes[p] - 2;
    topo t;
    noctStatus st = topo_build(d, &t, err);
    if (st != NOCT_OK)
        return st;
    /* unused and coincident vertices */
    uint8_t *used = calloc(d->nv > 0 ? d->nv : 1, 1);
    weld_key *keys = malloc((d->nv > 0 ? d->nv : 1) * sizeof *keys);
    uint32_t *parent = malloc((d->nv > 0 ? d->nv : 1) * sizeof *parent);
    double *per = calloc(d->np > 0 ? d->np : 1, sizeof *per);
    if (used == NULL || keys == NULL || parent == NULL || per == NULL) {
        free(used);
        free(keys);
        free(parent);
        free(per);
        topo_free(&t);
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    }
    for (size_t i = 0; i < d->ni; ++i)
        used[d->idx[i]] = 1;
    weld_classes(d, keys, parent);
    for (size_t i = 0; i < d->nv; ++i) {
        r->unused_vertices += !used[i];
        r->coincident_vertices += parent[i] != i;
    }
    free(used);
    free(keys);
    free(parent);
    for (size_t p = 0; p < d->np; ++p) {
        r->duplicate_polygons += t.first[p] != p;
        r->components += t.comp[p] == p;
    }
    r->orientable = true;
    for (size_t p = 0; p < d->np; ++p)
        if (t.comp_bad[p])
            r->orientable = false;
    for (size_t a = 0; a < d->ni;) {
        size_t b = a + 1;
        while (b < d->ni && t.he[b].lo == t.he[a].lo && t.he[b].hi == t.he[a].hi)
            ++b;
        const uint32_t e[2] = {t.he[a].lo, t.he[a].hi};
        ++r->edges;
        if (b - a == 1) {
            if (r->boundary_edges < NOCT_MESH_REPORT_FIRST)
                memcpy(r->boundary_first[r->boundary_edges], e, sizeof e);
            ++r->boundary_edges;
        } else if (b - a > 2) {
            if (r->nonmanifold_edges < NOCT_MESH_REPORT_FIRST) {
                memcpy(r->nonmanifold_first[r->nonmanifold_edges], e, sizeof e);
                r->nonmanifold_uses[r->nonmanifold_edges] = b - a;
            }
            ++r->nonmanifold_edges;
        } else if (t.he[a].forward == t.he[a + 1].forward) {
            if (r->misoriented_edges < NOCT_MESH_REPORT_FIRST)
                memcpy(r->misoriented_first[r->misoriented_edges], e, sizeof e);
            ++r->misoriented_edges;
        }
        a = b;
    }
    r->closed = r->boundary_edges == 0 && r->nonmanifold_edges == 0;
    r->oriented = r->misoriented_edges == 0;
    if (r->closed && r->oriented && d->np > 0) {
        double o[3];
        lowest_corner(d, o);
        r->has_volume = true;
        r->volume = fan_volume(d, &t, o, false, NULL) / 6;
    }
    free(per);
    topo_free(&t);
    if (d->np == 0) {
        r->status = NOCT_ERR_DEGENERATE;
        snprintf(r->reason, sizeof r->reason, "no polygons");
    } else if (!r->closed || !r->oriented) {
        r->status = r->closed ? NOCT_ERR_ORIENTATION : NOCT_ERR_OPEN;
        append_edges(r->reason, r->boundary_edges, "boundary", r->boundary_first, NULL);
        append_edges(r->reason, r->nonmanifold_edges, "non-manifold", r->nonmanifold_first,
                     r->nonmanifold_uses);
        append_edges(r->reason, r->misoriented_edges, "misoriented", r->misoriented_first,
                     NULL);
        if (r->misoriented_edges > 0)
            append(r->reason, " (two polygons run along each the same way%s)",
                   r->orientable ? "; orientable: a repair orients it" : "; not orientable");
    } else {
        noctMesh *m = NULL;
        noctError inner = {0};
        r->status = noctMeshCreateFromData(d, &m, &inner);
        noctMeshDestroy(m);
        if (r->status == NOCT_ERR_NOMEM)
            return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
        if (r->status != NOCT_OK)
            snprintf(r->reason, sizeof r->reason, "%s", inner.message);
    }
    r->solid = r->status == NOCT_OK;
    return NOCT_OK;
}

/* ---- repair ---------------------------------------------------------------------------- */

static void reverse_polygon(noctMeshData *d, size_t base, uint32_t n)
{
    /* keep the first corner, reverse the rest: the same fan, turned over */
    for (uint32_t i = 1, j = n - 1; i < j; ++i, --j) {
        uint32_t tmp = d->idx[base + i];
        d->idx[base + i] = d->idx[base + j];
        d->idx[base + j] = tmp;
    }
}

noctStatus noctMeshDataRepair(noctMeshData *data, double tolerance,
                              noctMeshRepairReport *report, noctError *err)
{
    NOCT_REQUIRE(data != NULL);
    noctMeshData *d = data;
    noctMeshRepairReport rep = {0, 0, 0, 0, 0};
    if (report != NULL)
        *report = rep;
    noctMeshWeldReport w;
    noctStatus st = noctMeshDataWeld(d, tolerance, &w, err);
    if (st != NOCT_OK)
        return st;
    rep.welded_vertices = w.welded_vertices;
    rep.dropped_polygons = w.dropped_polygons;
    /* Duplicates by their net orientation. */
    topo t;
    if ((st = topo_build(d, &t, err)) != NOCT_OK)
        return st;
    long *net = calloc(d->np > 0 ? d->np : 1, sizeof *net);
    uint8_t *keep = malloc(d->np > 0 ? d->np : 1);
    if (net == NULL || keep == NULL) {
        free(net);
        free(keep);
        topo_free(&t);
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    }
    bool any = false;
    for (size_t p = 0; p < d->np; ++p) {
        net[t.first[p]] += t.reversed[p] ? -1 : 1;
        any = any || t.first[p] != p;
        keep[p] = t.first[p] == p;
    }
    if (any) {
        uint8_t *seen_rev = calloc(d->np, 1);
        if (seen_rev == NULL) {
            free(net);
            free(keep);
            topo_free(&t);
            return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
        }
        for (size_t p = 0; p < d->np; ++p) {
            uint32_t f = t.first[p];
            if (f == p)
                keep[p] = net[p] > 0;
            else if (net[f] < 0 && t.reversed[p] && !seen_rev[f])
                keep[p] = seen_rev[f] = 1;
        }
        free(seen_rev);
        size_t out = 0, outp = 0;
        for (size_t p = 0; p < d->np; ++p) {
            if (!keep[p]) {
                ++rep.removed_duplicates;
                continue;
            }
            memmove(&d->idx[out], &d->idx[t.base[p]], d->sizes[p] * sizeof *d->idx);
            out += d->sizes[p];
            d->sizes[outp] = d->sizes[p];
            d->pline[outp++] = d->pline[p];
        }
        d->np = outp;
        d->ni = out;
        topo_free(&t);
        if ((st = topo_build(d, &t, err)) != NOCT_OK) {
            free(net);
            free(keep);
            return st;
        }
    }
    free(keep);
    /* Orient: flip to run like the component's root; then turn the closed,
     * orientable components of negative volume. */
    free(net);
    double *per = calloc(d->np > 0 ? d->np : 1, sizeof *per);
    if (per == NULL) {
        topo_free(&t);
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    }
    double o[3];
    lowest_corner(d, o);
    fan_volume(d, &t, o, true, per);
    for (size_t p = 0; p < d->np; ++p) {
        uint32_t root = t.comp[p];
        bool turn = !t.comp_open[root] && !t.comp_bad[root] && per[root] < 0;
        if ((t.flip[p] != 0) != turn) {
            reverse_polygon(d, t.base[p], d->sizes[p]);
            ++rep.flipped_polygons;
        }
    }
    for (size_t p = 0; p < d->np; ++p)
        rep.unorientable_components += t.comp[p] == p && t.comp_bad[p];
    free(per);
    topo_free(&t);
    if (report != NULL)
        *report = rep;
    return NOCT_OK;
}

/* ---- output and solids ----------------------------------------------------------------- */

noctStatus noctMeshDataWriteOff(const noctMeshData *data, const char *path, noctError *err)
{
    NOCT_REQUIRE(data != NULL && path != NULL);
    FILE *f = fopen(path, "w");
    if (f == NULL) {
        int e = errno;
        return noct_fail(err, NOCT_ERR_IO, -1, 0, "%s: cannot write: %s", path, strerror(e));
    }
    fprintf(f, "OFF\n%zu %zu 0\n", data->nv, data->np);
    for (size_t i = 0; i < data->nv; ++i)
        fprintf(f, "%.17g %.17g %.17g\n", data->v[3 * i], data->v[3 * i + 1],
                data->v[3 * i + 2]);
    for (size_t p = 0, base = 0; p < data->np; base += data->sizes[p], ++p) {
        fprintf(f, "%u", data->sizes[p]);
        for (uint32_t c = 0; c < data->sizes[p]; ++c)
            fprintf(f, " %u", data->idx[base + c]);
        fputc('\n', f);
    }
    bool bad = ferror(f) != 0;
    if (fclose(f) != 0 || bad) {
        int e = errno;
        return noct_fail(err, NOCT_ERR_IO, -1, 0, "%s: write error: %s", path,
                         strerror(e != 0 ? e : EIO));
    }
    return NOCT_OK;
}

/* noctMeshCreateFromData() (surface false) and
 * noctMeshCreateSurfaceFromData(). */
static noctStatus create_from_data(const noctMeshData *data, bool surface, noctMesh **mesh,
                                   noctError *err)
{
    NOCT_REQUIRE(data != NULL && mesh != NULL);
    const noctMeshData *d = data;
    noctError inner = {0};
    noctStatus st = (surface ? noctMeshCreateSurface : noctMeshCreate)(d->v, d->nv, d->sizes,
                                                                     d->np, d->idx, mesh,
                                                                     &inner);
    if (st == NOCT_OK)
        return st;
    /* Name the line (or record) of the vertex or polygon at fault. */
    long at = 0;
    bool found = false;
    if (inner.index >= 0 && st == NOCT_ERR_NONFINITE && (size_t)inner.index < d->nv) {
        at = d->vline[inner.index];
        found = true;
    } else if (inner.index >= 0 && st != NOCT_ERR_NONFINITE && (size_t)inner.index < d->np) {
        at = d->pline[inner.index];
        found = true;
    }
    if (d->path == NULL)
        return noct_fail(err, st, inner.index, 0, "%s", inner.message);
    if (found && d->lines && at > 0)
        return noct_fail(err, st, inner.index, at, "%s:%ld: %s", d->path, at, inner.message);
    if (found && d->record != NULL)
        return noct_fail(err, st, inner.index, 0, "%s: %s %ld: %s", d->path, d->record, at,
                         inner.message);
    return noct_fail(err, st, inner.index, 0, "%s: %s", d->path, inner.message);
}

noctStatus noctMeshCreateFromData(const noctMeshData *data, noctMesh **mesh, noctError *err)
{
    return create_from_data(data, false, mesh, err);
}

noctStatus noctMeshCreateSurfaceFromData(const noctMeshData *data, noctMesh **mesh,
                                         noctError *err)
{
    return create_from_data(data, true, mesh, err);
}
