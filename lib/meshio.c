/* SPDX-License-Identifier: MIT */
/*
 * Mesh files: OFF and Wavefront OBJ readers. Every error names the file,
 * the line and the problem; a file that fails leaves nothing behind.
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "array.h"
#include "internal.h"
#include "mesh_internal.h"

/* Growable arrays of what a file lists, with the line of each vertex and
 * polygon so that validation errors can name it. */
typedef struct mesh_data {
    double *v;        /* 3 per vertex */
    long *vline;      /* line of each vertex */
    uint32_t *sizes;  /* corners of each polygon */
    long *pline;      /* line of each polygon */
    uint32_t *idx;    /* the corners */
    size_t nv, np, ni;
    size_t cap_v, cap_vline, cap_sizes, cap_pline, cap_idx;
} mesh_data;

static void data_free(mesh_data *d)
{
    free(d->v);
    free(d->vline);
    free(d->sizes);
    free(d->idx);
    free(d->pline);
}

NOCT_DEFINE_GROW(grow_doubles, double)
NOCT_DEFINE_GROW(grow_longs, long)
NOCT_DEFINE_GROW(grow_u32, uint32_t)

/* The room to ask for need elements: 64 at first. */
static size_t room(size_t cap, size_t need)
{
    return cap == 0 && need < 64 ? 64 : need;
}

static bool add_vertex(mesh_data *d, const double xyz[3], long line)
{
    if (!grow_doubles(&d->v, &d->cap_v, room(d->cap_v, 3 * (d->nv + 1))) ||
        !grow_longs(&d->vline, &d->cap_vline, room(d->cap_vline, d->nv + 1)))
        return false;
    memcpy(&d->v[3 * d->nv], xyz, 3 * sizeof *xyz);
    d->vline[d->nv++] = line;
    return true;
}

static bool add_polygon(mesh_data *d, const uint32_t *corners, uint32_t n, long line)
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

/* ---- tokens ------------------------------------------------------------------ */

typedef struct reader {
    const char *path;
    FILE *f;
    char *buf;
    size_t cap;
    long line;
    char *pos;   /* next unread character of the current line */
} reader;

static noctStatus fail_at(const reader *r, noctError *err, noctStatus st,
                          const char *what, const char *tok)
{
    char where[32] = "";
    if (r->line > 0)
        snprintf(where, sizeof where, ":%ld", r->line);
    return noct_fail(err, st, -1, r->line, "%s%s: %s%s%s%s", r->path, where, what,
                     tok ? " '" : "", tok ? tok : "", tok ? "'" : "");
}

/*
 * Read the next line, with its comment (from '#') cut off: true if there
 * was one, false at the end of the file or on a failure (*st set).
 * getline(3) returns -1 at the end of the file, on a read error, and when
 * it finds no memory for a long line; only the last sets errno to ENOMEM
 * without the error indicator, so taking every -1 for the end would
 * silently read a file short. A NUL byte would end the line for the
 * tokenizer, silently too, so it is an error.
 */
static bool next_line(reader *r, noctStatus *st, noctError *err)
{
    errno = 0;
    ssize_t n = getline(&r->buf, &r->cap, r->f);
    if (n < 0) {
        int e = errno;
        if (e != ENOMEM && feof(r->f) && !ferror(r->f))
            return false;
        ++r->line; /* the line that could not be read */
        *st = e == ENOMEM ? noct_fail(err, NOCT_ERR_NOMEM, -1, r->line,
                                      "%s:%ld: out of memory reading the line",
                                      r->path, r->line)
                          : noct_fail(err, NOCT_ERR_IO, -1, r->line,
                                      "%s:%ld: read error: %s", r->path, r->line,
                                      strerror(e != 0 ? e : EIO));
        return false;
    }
    ++r->line;
    if (memchr(r->buf, '\0', (size_t)n) != NULL) {
        *st = fail_at(r, err, NOCT_ERR_PARSE, "NUL byte in line", NULL);
        return false;
    }
    char *hash = strchr(r->buf, '#');
    if (hash != NULL)
        *hash = '\0';
    r->pos = r->buf;
    return true;
}

/* The next whitespace-separated token of the current line, or NULL. */
static char *token(reader *r)
{
    while (*r->pos != '\0' && isspace((unsigned char)*r->pos))
        ++r->pos;
    if (*r->pos == '\0')
        return NULL;
    char *start = r->pos;
    while (*r->pos != '\0' && !isspace((unsigned char)*r->pos))
        ++r->pos;
    if (*r->pos != '\0')
        *r->pos++ = '\0';
    return start;
}

static bool parse_double(const char *tok, double *out)
{
    char *end;
    errno = 0;
    *out = strtod(tok, &end);
    return end != tok && *end == '\0';
}

static bool parse_count(const char *tok, unsigned long *out)
{
    char *end;
    if (!isdigit((unsigned char)*tok))
        return false;
    errno = 0;
    *out = strtoul(tok, &end, 10);
    return *end == '\0' && errno == 0;
}

/* Parse one coordinate token (NULL if the line ended). */
static noctStatus parse_coord(const reader *r, const char *tok, double *out,
                              noctError *err)
{
    if (tok == NULL)
        return fail_at(r, err, NOCT_ERR_PARSE, "expected 3 coordinates", NULL);
    if (!parse_double(tok, out))
        return fail_at(r, err, NOCT_ERR_PARSE, "not a number:", tok);
    if (!isfinite(*out))
        return fail_at(r, err, NOCT_ERR_NONFINITE, "coordinate is not finite:", tok);
    return NOCT_OK;
}

/* Read the coordinates of a vertex: first (already read) and two more. */
static noctStatus read_xyz(reader *r, const char *first, double xyz[3],
                           noctError *err)
{
    noctStatus st = parse_coord(r, first, &xyz[0], err);
    for (int k = 1; k < 3 && st == NOCT_OK; ++k)
        st = parse_coord(r, token(r), &xyz[k], err);
    return st;
}

/* ---- OFF ----------------------------------------------------------------------- */

/* The next non-empty line's first token, or NULL at the end of the file. */
static char *first_token(reader *r, noctStatus *st, noctError *err)
{
    while (next_line(r, st, err)) {
        char *tok = token(r);
        if (tok != NULL)
            return tok;
    }
    return NULL;
}

static noctStatus read_off(reader *r, mesh_data *d, noctError *err)
{
    noctStatus st = NOCT_OK;
    char *tok = first_token(r, &st, err);
    if (tok == NULL)
        return st != NOCT_OK ? st : fail_at(r, err, NOCT_ERR_PARSE, "empty file", NULL);
    if (strcmp(tok, "OFF") != 0)
        return fail_at(r, err, NOCT_ERR_PARSE, "expected the OFF header, found", tok);
    /* The counts may follow on the header's line or on the next one. */
    tok = token(r);
    if (tok == NULL && (tok = first_token(r, &st, err)) == NULL)
        return st != NOCT_OK ? st : fail_at(r, err, NOCT_ERR_PARSE,
                                            "missing the vertex and face counts", NULL);
    unsigned long counts[3];
    for (int i = 0; i < 3; ++i) {
        if (i > 0 && (tok = token(r)) == NULL)
            return fail_at(r, err, NOCT_ERR_PARSE,
                           "expected 3 counts (vertices faces edges)", NULL);
        if (!parse_count(tok, &counts[i]))
            return fail_at(r, err, NOCT_ERR_PARSE, "not a count:", tok);
    }
    if (counts[0] > NOCT_MESH_MAX_VERTICES || counts[1] > NOCT_MESH_MAX_INDICES / 3)
        return noct_fail(err, NOCT_ERR_TOO_LARGE, -1, r->line,
                         "%s:%ld: %lu vertices and %lu faces exceed the limits "
                         "(%u vertices, %u faces)", r->path, r->line, counts[0],
                         counts[1], (unsigned)NOCT_MESH_MAX_VERTICES,
                         (unsigned)NOCT_MESH_MAX_INDICES / 3);
    for (unsigned long i = 0; i < counts[0]; ++i) {
        if ((tok = first_token(r, &st, err)) == NULL)
            return st != NOCT_OK ? st : fail_at(r, err, NOCT_ERR_PARSE,
                                                "file ends before all vertices", NULL);
        double xyz[3];
        noctStatus s2 = read_xyz(r, tok, xyz, err);
        if (s2 != NOCT_OK)
            return s2;
        if (!add_vertex(d, xyz, r->line))
            return fail_at(r, err, NOCT_ERR_NOMEM, "out of memory", NULL);
    }
    uint32_t *corners = NULL;
    size_t ccap = 0;
    for (unsigned long f = 0; f < counts[1] && st == NOCT_OK; ++f) {
        if ((tok = first_token(r, &st, err)) == NULL) {
            if (st == NOCT_OK)
                st = fail_at(r, err, NOCT_ERR_PARSE, "file ends before all faces", NULL);
            break;
        }
        unsigned long n;
        if (!parse_count(tok, &n) || n < 3 || n > 1000000) {
            st = fail_at(r, err, NOCT_ERR_PARSE,
                         "expected a face's corner count (3 to 1000000), found", tok);
            break;
        }
        if (d->ni + n > NOCT_MESH_MAX_INDICES) {
            st = fail_at(r, err, NOCT_ERR_TOO_LARGE, "too many face corners", NULL);
            break;
        }
        if (!grow_u32(&corners, &ccap, room(ccap, n))) {
            st = fail_at(r, err, NOCT_ERR_NOMEM, "out of memory", NULL);
            break;
        }
        for (unsigned long c = 0; c < n && st == NOCT_OK; ++c) {
            char *t = token(r);
            unsigned long i;
            if (t == NULL)
                st = fail_at(r, err, NOCT_ERR_PARSE, "face has fewer corners than its count",
                             NULL);
            else if (!parse_count(t, &i))
                st = fail_at(r, err, NOCT_ERR_PARSE, "not a vertex index:", t);
            else if (i >= counts[0])
                st = noct_fail(err, NOCT_ERR_INDEX, (long)f, r->line,
                               "%s:%ld: face %lu: vertex index %lu out of range "
                               "(%lu vertices)", r->path, r->line, f, i, counts[0]);
            else
                corners[c] = (uint32_t)i;
        }
        if (st == NOCT_OK && !add_polygon(d, corners, (uint32_t)n, r->line))
            st = fail_at(r, err, NOCT_ERR_NOMEM, "out of memory", NULL);
    }
    free(corners);
    return st;
}

/* ---- OBJ ----------------------------------------------------------------------- */

/* An OBJ face corner: "i", "i/t", "i/t/n" or "i//n"; 1-based, or negative
 * for relative to the end of the vertices read so far. Returns NOCT_OK,
 * NOCT_ERR_PARSE for a malformed corner or NOCT_ERR_INDEX for one that
 * names no vertex read so far. */
static noctStatus obj_corner(const char *tok, size_t nv, uint32_t *out)
{
    char *end;
    errno = 0;
    long i = strtol(tok, &end, 10);
    if (end == tok || (*end != '\0' && *end != '/') || errno != 0)
        return NOCT_ERR_PARSE;
    long idx = i > 0 ? i - 1 : (long)nv + i;
    if (i == 0 || idx < 0 || (size_t)idx >= nv)
        return NOCT_ERR_INDEX;
    *out = (uint32_t)idx;
    return NOCT_OK;
}

static noctStatus read_obj(reader *r, mesh_data *d, noctError *err)
{
    static const char *const ignored[] = {"vn", "vt", "vp", "o", "g", "s",
                                          "usemtl", "mtllib"};
    uint32_t *corners = NULL;
    size_t ccap = 0;
    noctStatus st = NOCT_OK;
    while (st == NOCT_OK && next_line(r, &st, err)) {
        char *kw = token(r);
        if (kw == NULL)
            continue;
        if (strcmp(kw, "v") == 0) {
            double xyz[3];
            st = read_xyz(r, token(r), xyz, err);
            if (st == NOCT_OK && d->nv >= NOCT_MESH_MAX_VERTICES)
                st = fail_at(r, err, NOCT_ERR_TOO_LARGE, "too many vertices", NULL);
            if (st == NOCT_OK && !add_vertex(d, xyz, r->line))
                st = fail_at(r, err, NOCT_ERR_NOMEM, "out of memory", NULL);
        } else if (strcmp(kw, "f") == 0) {
            uint32_t n = 0;
            char *t;
            while (st == NOCT_OK && (t = token(r)) != NULL) {
                noctStatus cs;
                if (!grow_u32(&corners, &ccap, room(ccap, n + 1)))
                    st = fail_at(r, err, NOCT_ERR_NOMEM, "out of memory", NULL);
                else if ((cs = obj_corner(t, d->nv, &corners[n])) != NOCT_OK)
                    st = noct_fail(err, cs, (long)d->np, r->line,
                                   "%s:%ld: face %zu: bad vertex reference '%s' "
                                   "(%zu vertices so far)", r->path, r->line,
                                   d->np, t, d->nv);
                else
                    ++n;
            }
            if (st == NOCT_OK && n < 3)
                st = fail_at(r, err, NOCT_ERR_PARSE, "a face needs at least 3 corners",
                             NULL);
            if (st == NOCT_OK && d->ni + n > NOCT_MESH_MAX_INDICES)
                st = fail_at(r, err, NOCT_ERR_TOO_LARGE, "too many face corners", NULL);
            if (st == NOCT_OK && !add_polygon(d, corners, n, r->line))
                st = fail_at(r, err, NOCT_ERR_NOMEM, "out of memory", NULL);
        } else {
            bool known = false;
            for (size_t i = 0; i < sizeof ignored / sizeof *ignored; ++i)
                known = known || strcmp(kw, ignored[i]) == 0;
            if (!known)
                st = fail_at(r, err, NOCT_ERR_PARSE, "unsupported statement", kw);
        }
    }
    free(corners);
    return st;
}

/* ---- entry point ---------------------------------------------------------------- */

noctStatus noctMeshRead(const char *path, noctMesh **mesh, noctError *err)
{
    NOCT_REQUIRE(path != NULL && mesh != NULL);
    *mesh = NULL;
    const char *dot = strrchr(path, '.');
    bool off = dot != NULL && strcasecmp(dot, ".off") == 0;
    bool obj = dot != NULL && strcasecmp(dot, ".obj") == 0;
    if (!off && !obj)
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0,
                         "%s: unknown mesh format (expected a .off or .obj file)",
                         path);
    reader r = {path, fopen(path, "r"), NULL, 0, 0, NULL};
    if (r.f == NULL) {
        int e = errno;
        return noct_fail(err, e == ENOMEM ? NOCT_ERR_NOMEM : NOCT_ERR_IO, -1, 0,
                         "%s: cannot open: %s", path, strerror(e));
    }
    mesh_data d = {0};
    noctStatus st = off ? read_off(&r, &d, err) : read_obj(&r, &d, err);
    fclose(r.f);
    free(r.buf);
    if (st == NOCT_OK) {
        noctError inner = {0};
        st = noctMeshCreate(d.v, d.nv, d.sizes, d.np, d.idx, mesh, &inner);
        if (st != NOCT_OK) {
            /* Name the line of the vertex or polygon the problem is at. */
            long line = 0;
            if (inner.index >= 0 && st == NOCT_ERR_NONFINITE && (size_t)inner.index < d.nv)
                line = d.vline[inner.index];
            else if (inner.index >= 0 && (size_t)inner.index < d.np)
                line = d.pline[inner.index];
            if (line > 0)
                noct_fail(err, st, inner.index, line, "%s:%ld: %s", path, line,
                          inner.message);
            else
                noct_fail(err, st, inner.index, 0, "%s: %s", path, inner.message);
        }
    }
    data_free(&d);
    return st;
}
