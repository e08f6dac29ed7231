/* SPDX-License-Identifier: MIT */
/*
 * Mesh files: the OFF, Wavefront OBJ, STL and PLY readers, the choice of
 * reader (assimp's for the other formats: meshio_assimp.c), and
 * noctMeshRead(). Every error names the file, the line (or a binary
 * file's triangle or face) and the problem; a file that fails leaves
 * nothing behind.
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "array.h"
#include "internal.h"
#include "mesh_internal.h"
#include "meshdata_internal.h"

NOCT_DEFINE_GROW(grow_u32, uint32_t)

/* The room to ask for need elements: 64 at first. */
static size_t room(size_t cap, size_t need)
{
    return cap == 0 && need < 64 ? 64 : need;
}

#define add_vertex noct_data_add_vertex
#define add_polygon noct_data_add_polygon

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

static noctStatus read_off(reader *r, noctMeshData *d, noctError *err)
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

static noctStatus read_obj(reader *r, noctMeshData *d, noctError *err)
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

/* ---- STL --------------------------------------------------------------------------- */

static uint32_t le32(const unsigned char *b)
{
    return (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
}

/* The whole file, in a buffer of its size plus one. */
static noctStatus slurp(const char *path, FILE *f, unsigned char **buf, size_t *size,
                        noctError *err)
{
    size_t cap = 0, n = 0;
    unsigned char *b = NULL;
    for (;;) {
        if (n + 1 >= cap) {
            size_t ncap = cap == 0 ? 65536 : 2 * cap;
            unsigned char *nb = ncap > cap ? realloc(b, ncap) : NULL;
            if (nb == NULL) {
                free(b);
                return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "%s: out of memory", path);
            }
            b = nb;
            cap = ncap;
        }
        size_t got = fread(b + n, 1, cap - 1 - n, f);
        n += got;
        if (got == 0)
            break;
    }
    if (ferror(f)) {
        int e = errno;
        free(b);
        return noct_fail(err, NOCT_ERR_IO, -1, 0, "%s: read error: %s", path,
                         strerror(e != 0 ? e : EIO));
    }
    b[n] = 0;
    *buf = b;
    *size = n;
    return NOCT_OK;
}

static noctStatus read_stl_binary(const char *path, const unsigned char *b, uint32_t count,
                                  noctMeshData *d, noctError *err)
{
    d->lines = false;
    d->record = "triangle";
    if ((uint64_t)count * 3 > NOCT_MESH_MAX_VERTICES)
        return noct_fail(err, NOCT_ERR_TOO_LARGE, -1, 0,
                         "%s: %u triangles exceed the limit of %u vertices", path, count,
                         (unsigned)NOCT_MESH_MAX_VERTICES);
    for (uint32_t t = 0; t < count; ++t) {
        const unsigned char *rec = b + 84 + 50 * (size_t)t;
        uint32_t corners[3];
        for (int c = 0; c < 3; ++c) {
            double xyz[3];
            for (int k = 0; k < 3; ++k) {
                uint32_t bits = le32(rec + 12 + 12 * c + 4 * k);
                float x;
                memcpy(&x, &bits, sizeof x);
                xyz[k] = (double)x;
                if (!isfinite(xyz[k]))
                    return noct_fail(err, NOCT_ERR_NONFINITE, (long)t, 0,
                                     "%s: triangle %u: vertex %d: coordinate %c is not "
                                     "finite: %g", path, t, c, "xyz"[k], xyz[k]);
            }
            corners[c] = (uint32_t)d->nv;
            if (!add_vertex(d, xyz, (long)t))
                return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "%s: out of memory", path);
        }
        if (!add_polygon(d, corners, 3, (long)t))
            return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "%s: out of memory", path);
    }
    return NOCT_OK;
}

/* The next non-empty line's first token, which must be want (any case). */
static noctStatus stl_expect(reader *r, const char *want, noctError *err)
{
    noctStatus st = NOCT_OK;
    char *tok = first_token(r, &st, err);
    if (tok == NULL)
        return st != NOCT_OK ? st : fail_at(r, err, NOCT_ERR_PARSE, "file ends inside a facet",
                                            NULL);
    if (strcasecmp(tok, want) != 0) {
        char what[48];
        snprintf(what, sizeof what, "expected '%s', found", want);
        return fail_at(r, err, NOCT_ERR_PARSE, what, tok);
    }
    return NOCT_OK;
}

static noctStatus read_stl_ascii(reader *r, noctMeshData *d, noctError *err)
{
    d->lines = true;
    noctStatus st = NOCT_OK;
    char *tok = first_token(r, &st, err);
    if (tok == NULL)
        return st != NOCT_OK ? st : fail_at(r, err, NOCT_ERR_PARSE, "empty file", NULL);
    if (strcasecmp(tok, "solid") != 0)
        return fail_at(r, err, NOCT_ERR_PARSE,
                       "not an STL file: neither binary (84 + 50 n bytes) nor ASCII "
                       "(starting with 'solid'), found", tok);
    for (;;) {
        if ((tok = first_token(r, &st, err)) == NULL)
            return st != NOCT_OK ? st : fail_at(r, err, NOCT_ERR_PARSE,
                                                "file ends without 'endsolid'", NULL);
        if (strcasecmp(tok, "endsolid") == 0) {
            if ((tok = first_token(r, &st, err)) == NULL)
                return st;
            if (strcasecmp(tok, "solid") != 0)
                return fail_at(r, err, NOCT_ERR_PARSE, "expected 'solid' or the end, found",
                               tok);
            continue;
        }
        if (strcasecmp(tok, "facet") != 0)
            return fail_at(r, err, NOCT_ERR_PARSE, "expected 'facet' or 'endsolid', found",
                           tok);
        long line = r->line;
        if ((st = stl_expect(r, "outer", err)) != NOCT_OK)
            return st;
        tok = token(r);
        if (tok == NULL || strcasecmp(tok, "loop") != 0)
            return fail_at(r, err, NOCT_ERR_PARSE, "expected 'outer loop'", NULL);
        uint32_t corners[3];
        for (int c = 0; c < 3; ++c) {
            if ((st = stl_expect(r, "vertex", err)) != NOCT_OK)
                return st;
            double xyz[3];
            if ((st = read_xyz(r, token(r), xyz, err)) != NOCT_OK)
                return st;
            if (d->nv >= NOCT_MESH_MAX_VERTICES)
                return fail_at(r, err, NOCT_ERR_TOO_LARGE, "too many vertices", NULL);
            corners[c] = (uint32_t)d->nv;
            if (!add_vertex(d, xyz, r->line))
                return fail_at(r, err, NOCT_ERR_NOMEM, "out of memory", NULL);
        }
        if ((st = stl_expect(r, "endloop", err)) != NOCT_OK ||
            (st = stl_expect(r, "endfacet", err)) != NOCT_OK)
            return st;
        if (!add_polygon(d, corners, 3, line))
            return fail_at(r, err, NOCT_ERR_NOMEM, "out of memory", NULL);
    }
}

static noctStatus read_stl(reader *r, noctMeshData *d, noctError *err)
{
    unsigned char *b = NULL;
    size_t size = 0;
    noctStatus st = slurp(r->path, r->f, &b, &size, err);
    if (st != NOCT_OK)
        return st;
    uint32_t count = size >= 84 ? le32(b + 80) : 0;
    if (size >= 84 && (uint64_t)size == 84 + 50 * (uint64_t)count) {
        st = read_stl_binary(r->path, b, count, d, err);
    } else if (memchr(b, '\0', size) != NULL) {
        if (size < 84)
            st = noct_fail(err, NOCT_ERR_PARSE, -1, 0,
                           "%s: binary STL of %zu bytes, shorter than its 84-byte header",
                           r->path, size);
        else
            st = noct_fail(err, NOCT_ERR_PARSE, -1, 0,
                           "%s: binary STL whose header counts %u triangles, which take "
                           "%llu bytes, but the file has %zu (truncated, or a wrong "
                           "triangle count)", r->path, count,
                           (unsigned long long)(84 + 50 * (uint64_t)count), size);
    } else if (size == 0) {
        st = noct_fail(err, NOCT_ERR_PARSE, -1, 0, "%s: empty file", r->path);
    } else {
        FILE *mem = fmemopen(b, size, "r");
        if (mem == NULL) {
            st = noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "%s: out of memory", r->path);
        } else {
            FILE *file = r->f;
            r->f = mem;
            st = read_stl_ascii(r, d, err);
            r->f = file;
            fclose(mem);
        }
    }
    free(b);
    return st;
}

/* ---- PLY ----------------------------------------------------------------------------- */

enum { PLY_MAX_ELEMENTS = 32, PLY_MAX_PROPS = 64 };

typedef enum ply_type { PLY_I8, PLY_U8, PLY_I16, PLY_U16, PLY_I32, PLY_U32, PLY_F32,
                        PLY_F64 } ply_type;

static const struct {
    const char *name, *alias;
    unsigned size;
} ply_types[] = {{"char", "int8", 1}, {"uchar", "uint8", 1}, {"short", "int16", 2},
                 {"ushort", "uint16", 2}, {"int", "int32", 4}, {"uint", "uint32", 4},
                 {"float", "float32", 4}, {"double", "float64", 8}};

typedef struct ply_prop {
    ply_type type;       /* a list's items' */
    ply_type count_type; /* a list's count's */
    bool list;
    int role;            /* 0 skipped, 1-3 x y z, 4 the face's corners */
} ply_prop;

typedef struct ply_element {
    char name[32];
    unsigned long count;
    int role;            /* 0 skipped, 1 vertex, 2 face */
    size_t nprops;
    ply_prop props[PLY_MAX_PROPS];
} ply_element;

typedef struct ply {
    int format;          /* 0 ascii, 1 little endian, 2 big endian */
    size_t nelements;
    ply_element el[PLY_MAX_ELEMENTS];
} ply;

static bool ply_type_of(const char *name, ply_type *t)
{
    for (size_t i = 0; i < sizeof ply_types / sizeof *ply_types; ++i)
        if (strcmp(name, ply_types[i].name) == 0 || strcmp(name, ply_types[i].alias) == 0) {
            *t = (ply_type)i;
            return true;
        }
    return false;
}

static noctStatus ply_header(reader *r, ply *h, noctError *err)
{
    noctStatus st = NOCT_OK;
    char *tok = first_token(r, &st, err);
    if (tok == NULL)
        return st != NOCT_OK ? st : fail_at(r, err, NOCT_ERR_PARSE, "empty file", NULL);
    if (strcmp(tok, "ply") != 0)
        return fail_at(r, err, NOCT_ERR_PARSE, "expected the 'ply' header, found", tok);
    bool have_format = false;
    for (;;) {
        if (!next_line(r, &st, err))
            return st != NOCT_OK ? st : fail_at(r, err, NOCT_ERR_PARSE,
                                                "file ends in the header (no 'end_header')",
                                                NULL);
        char *kw = token(r);
        if (kw == NULL || strcmp(kw, "comment") == 0 || strcmp(kw, "obj_info") == 0)
            continue;
        if (strcmp(kw, "end_header") == 0)
            break;
        if (strcmp(kw, "format") == 0) {
            char *f = token(r);
            if (f != NULL && strcmp(f, "ascii") == 0)
                h->format = 0;
            else if (f != NULL && strcmp(f, "binary_little_endian") == 0)
                h->format = 1;
            else if (f != NULL && strcmp(f, "binary_big_endian") == 0)
                h->format = 2;
            else
                return fail_at(r, err, NOCT_ERR_PARSE, "unsupported PLY format", f);
            have_format = true;
        } else if (strcmp(kw, "element") == 0) {
            char *name = token(r), *count = token(r);
            unsigned long n;
            if (name == NULL || count == NULL || !parse_count(count, &n))
                return fail_at(r, err, NOCT_ERR_PARSE, "expected 'element NAME COUNT'", NULL);
            if (h->nelements == PLY_MAX_ELEMENTS)
                return fail_at(r, err, NOCT_ERR_PARSE, "too many PLY elements", NULL);
            ply_element *e = &h->el[h->nelements++];
            memset(e, 0, sizeof *e);
            snprintf(e->name, sizeof e->name, "%s", name);
            e->count = n;
            e->role = strcmp(name, "vertex") == 0 ? 1 : strcmp(name, "face") == 0 ? 2 : 0;
            if (e->role == 1 && n > NOCT_MESH_MAX_VERTICES)
                return fail_at(r, err, NOCT_ERR_TOO_LARGE, "too many vertices", NULL);
            if (e->role == 2 && n > NOCT_MESH_MAX_INDICES / 3)
                return fail_at(r, err, NOCT_ERR_TOO_LARGE, "too many faces", NULL);
        } else if (strcmp(kw, "property") == 0) {
            if (h->nelements == 0)
                return fail_at(r, err, NOCT_ERR_PARSE, "a property before any element", NULL);
            ply_element *e = &h->el[h->nelements - 1];
            if (e->nprops == PLY_MAX_PROPS)
                return fail_at(r, err, NOCT_ERR_PARSE, "too many properties", NULL);
            ply_prop *p = &e->props[e->nprops++];
            memset(p, 0, sizeof *p);
            char *t = token(r);
            if (t == NULL)
                return fail_at(r, err, NOCT_ERR_PARSE, "expected a property type", NULL);
            if (strcmp(t, "list") == 0) {
                p->list = true;
                t = token(r);
                if (t == NULL || !ply_type_of(t, &p->count_type))
                    return fail_at(r, err, NOCT_ERR_PARSE, "unsupported PLY list count type",
                                   t);
                if (p->count_type >= PLY_F32)
                    return fail_at(r, err, NOCT_ERR_PARSE,
                                   "a PLY list count must be of an integer type, not", t);
                t = token(r);
            }
            if (t == NULL || !ply_type_of(t, &p->type))
                return fail_at(r, err, NOCT_ERR_PARSE, "unsupported PLY property type", t);
            char *name = token(r);
            if (name == NULL)
                return fail_at(r, err, NOCT_ERR_PARSE, "expected a property name", NULL);
            int axis = strcmp(name, "x") == 0 ? 1 : strcmp(name, "y") == 0 ? 2
                     : strcmp(name, "z") == 0 ? 3 : 0;
            if (e->role == 1 && axis > 0) {
                if (p->list)
                    return fail_at(r, err, NOCT_ERR_PARSE, "a vertex coordinate is a list:",
                                   name);
                p->role = axis;
            }
            if (e->role == 2 &&
                (strcmp(name, "vertex_indices") == 0 || strcmp(name, "vertex_index") == 0)) {
                if (!p->list || p->type >= PLY_F32)
                    return fail_at(r, err, NOCT_ERR_PARSE,
                                   "a face's corners must be a list of integers:", name);
                p->role = 4;
            }
        } else {
            return fail_at(r, err, NOCT_ERR_PARSE, "unsupported PLY header line", kw);
        }
    }
    if (!have_format)
        return fail_at(r, err, NOCT_ERR_PARSE, "no 'format' line in the header", NULL);
    for (size_t i = 0; i < h->nelements; ++i) {
        ply_element *e = &h->el[i];
        int seen = 0;
        for (size_t j = 0; j < e->nprops; ++j)
            seen |= e->props[j].role > 0 ? 1 << e->props[j].role : 0;
        if (e->role == 1 && (seen & 0xe) != 0xe)
            return fail_at(r, err, NOCT_ERR_PARSE, "the vertex element lacks x, y or z", NULL);
        if (e->role == 2 && !(seen & 0x10))
            return fail_at(r, err, NOCT_ERR_PARSE,
                           "the face element has no 'vertex_indices' list", NULL);
    }
    return NOCT_OK;
}

/* Read one value of type t: from the text (ASCII) or the bytes. *what
 * names the element and instance for the messages. */
static noctStatus ply_value(reader *r, const ply *h, ply_type t, double *out,
                            const char *ename, unsigned long inst, noctError *err)
{
    if (h->format == 0) {
        char *tok;
        noctStatus st = NOCT_OK;
        while ((tok = token(r)) == NULL)
            if (!next_line(r, &st, err))
                return st != NOCT_OK ? st
                                     : noct_fail(err, NOCT_ERR_PARSE, -1, r->line,
                                                 "%s:%ld: file ends in %s %lu", r->path,
                                                 r->line, ename, inst);
        char *end;
        errno = 0;
        if (t >= PLY_F32) {
            *out = strtod(tok, &end);
        } else {
            long long v = strtoll(tok, &end, 10);
            *out = (double)v;
        }
        if (end == tok || *end != '\0' || (t < PLY_F32 && errno != 0))
            return fail_at(r, err, NOCT_ERR_PARSE, t >= PLY_F32 ? "not a number:"
                                                                : "not an integer:", tok);
        return NOCT_OK;
    }
    unsigned char b[8];
    unsigned size = ply_types[t].size;
    if (fread(b, 1, size, r->f) != size) {
        if (ferror(r->f))
            return noct_fail(err, NOCT_ERR_IO, -1, 0, "%s: read error: %s", r->path,
                             strerror(errno != 0 ? errno : EIO));
        return noct_fail(err, NOCT_ERR_PARSE, (long)inst, 0, "%s: %s %lu: file ends early",
                         r->path, ename, inst);
    }
    if (h->format == 2)
        for (unsigned i = 0; i < size / 2; ++i) {
            unsigned char tmp = b[i];
            b[i] = b[size - 1 - i];
            b[size - 1 - i] = tmp;
        }
    uint64_t u = 0;
    for (unsigned i = 0; i < size; ++i)
        u |= (uint64_t)b[i] << (8 * i);
    switch (t) {
    case PLY_I8: *out = (double)(int8_t)u; break;
    case PLY_U8: *out = (double)(uint8_t)u; break;
    case PLY_I16: *out = (double)(int16_t)(uint16_t)u; break;
    case PLY_U16: *out = (double)(uint16_t)u; break;
    case PLY_I32: *out = (double)(int32_t)(uint32_t)u; break;
    case PLY_U32: *out = (double)(uint32_t)u; break;
    case PLY_F32: {
        uint32_t bits = (uint32_t)u;
        float f;
        memcpy(&f, &bits, sizeof f);
        *out = (double)f;
        break;
    }
    case PLY_F64: memcpy(out, &u, sizeof *out); break;
    }
    return NOCT_OK;
}

/* A failure at the current line (ASCII) or without one (binary: the
 * message names the element instead). */
static noctStatus ply_fail(const reader *r, bool text, noctError *err, noctStatus st,
                           long index, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 6, 7)))
#endif
    ;

static noctStatus ply_fail(const reader *r, bool text, noctError *err, noctStatus st,
                           long index, const char *fmt, ...)
{
    char what[NOCT_ERROR_MESSAGE_SIZE];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    if (text)
        return noct_fail(err, st, index, r->line, "%s:%ld: %s", r->path, r->line, what);
    return noct_fail(err, st, index, 0, "%s: %s", r->path, what);
}

static noctStatus read_ply(reader *r, noctMeshData *d, noctError *err)
{
    ply *h = calloc(1, sizeof *h);
    if (h == NULL)
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "%s: out of memory", r->path);
    noctStatus st = ply_header(r, h, err);
    uint32_t *corners = NULL;
    size_t ccap = 0;
    d->lines = h->format == 0;
    d->record = h->format == 0 ? NULL : "face";
    if (st == NOCT_OK && h->format == 0)
        r->pos = r->buf + strlen(r->buf); /* past end_header */
    bool have_vertex = false;
    for (size_t i = 0; st == NOCT_OK && i < h->nelements; ++i) {
        const ply_element *e = &h->el[i];
        have_vertex = have_vertex || e->role == 1;
        for (unsigned long k = 0; k < e->count && st == NOCT_OK; ++k) {
            double xyz[3] = {0, 0, 0};
            uint32_t n = 0;
            long line = r->line;
            for (size_t j = 0; j < e->nprops && st == NOCT_OK; ++j) {
                const ply_prop *p = &e->props[j];
                double v;
                if (!p->list) {
                    st = ply_value(r, h, p->type, &v, e->name, k, err);
                    if (st == NOCT_OK && p->role >= 1 && p->role <= 3) {
                        if (!isfinite(v) && d->lines)
                            st = noct_fail(err, NOCT_ERR_NONFINITE, (long)k, r->line,
                                           "%s:%ld: vertex %lu: coordinate %c is not finite",
                                           r->path, r->line, k, "xyz"[p->role - 1]);
                        else if (!isfinite(v))
                            st = noct_fail(err, NOCT_ERR_NONFINITE, (long)k, 0,
                                           "%s: vertex %lu: coordinate %c is not finite",
                                           r->path, k, "xyz"[p->role - 1]);
                        xyz[p->role - 1] = v;
                    }
                    continue;
                }
                double count;
                st = ply_value(r, h, p->count_type, &count, e->name, k, err);
                if (st != NOCT_OK)
                    break;
                if (count < 0 || count > 1000000) {
                    st = ply_fail(r, d->lines, err, NOCT_ERR_PARSE, (long)k,
                                  "%s %lu: list of %g items (0 to 1000000)", e->name, k,
                                  count);
                    break;
                }
                if (p->role == 4) {
                    line = r->line;
                    if (count < 3) {
                        st = ply_fail(r, d->lines, err, NOCT_ERR_PARSE, (long)k,
                                      "face %lu has %g corners (at least 3)", k, count);
                        break;
                    }
                    if (!grow_u32(&corners, &ccap, room(ccap, (size_t)count))) {
                        st = noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "%s: out of memory",
                                       r->path);
                        break;
                    }
                }
                for (uint32_t c = 0; c < (uint32_t)count && st == NOCT_OK; ++c) {
                    st = ply_value(r, h, p->type, &v, e->name, k, err);
                    if (st != NOCT_OK || p->role != 4)
                        continue;
                    if (v < 0 || v >= (double)UINT32_MAX)
                        st = ply_fail(r, d->lines, err, NOCT_ERR_INDEX, (long)k,
                                      "face %lu: vertex index %.0f out of range", k, v);
                    else
                        corners[n++] = (uint32_t)v;
                }
            }
            if (st != NOCT_OK)
                break;
            if (e->role == 1 && !add_vertex(d, xyz, h->format == 0 ? line : (long)k))
                st = noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "%s: out of memory", r->path);
            if (e->role == 2) {
                if (d->ni + n > NOCT_MESH_MAX_INDICES)
                    st = noct_fail(err, NOCT_ERR_TOO_LARGE, -1, 0, "%s: too many face corners",
                                   r->path);
                else if (!add_polygon(d, corners, n, h->format == 0 ? line : (long)k))
                    st = noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "%s: out of memory", r->path);
            }
        }
    }
    if (st == NOCT_OK && !have_vertex)
        st = noct_fail(err, NOCT_ERR_PARSE, -1, 0, "%s: no vertex element", r->path);
    for (size_t p = 0, base = 0; p < d->np && st == NOCT_OK; base += d->sizes[p], ++p)
        for (uint32_t c = 0; c < d->sizes[p] && st == NOCT_OK; ++c)
            if (d->idx[base + c] >= d->nv) {
                if (d->lines)
                    st = noct_fail(err, NOCT_ERR_INDEX, (long)p, d->pline[p],
                                   "%s:%ld: face %zu: vertex index %u out of range "
                                   "(%zu vertices)", r->path, d->pline[p], p,
                                   d->idx[base + c], d->nv);
                else
                    st = noct_fail(err, NOCT_ERR_INDEX, (long)p, 0,
                                   "%s: face %zu: vertex index %u out of range (%zu vertices)",
                                   r->path, p, d->idx[base + c], d->nv);
            }
    free(corners);
    free(h);
    return st;
}

/* ---- the choice of reader, and noctMeshRead() ----------------------------------------- */

noctStatus noctMeshDataRead(const char *path, noctMeshData **data, noctError *err)
{
    NOCT_REQUIRE(path != NULL && data != NULL);
    *data = NULL;
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(slash != NULL ? slash : path, '.');
    static const char *const native[] = {".off", ".obj", ".stl", ".ply"};
    int kind = -1;
    for (int i = 0; i < 4; ++i)
        if (dot != NULL && strcasecmp(dot, native[i]) == 0)
            kind = i;
    noctMeshData *d = calloc(1, sizeof *d);
    char *copy = d != NULL ? malloc(strlen(path) + 1) : NULL;
    if (copy == NULL) {
        free(d);
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "%s: out of memory", path);
    }
    d->path = strcpy(copy, path);
    noctStatus st;
    if (kind < 0) {
        st = noct_read_assimp(path, d, err);
    } else {
        reader r = {path, fopen(path, kind >= 2 ? "rb" : "r"), NULL, 0, 0, NULL};
        if (r.f == NULL) {
            int e = errno;
            noctMeshDataDestroy(d);
            return noct_fail(err, e == ENOMEM ? NOCT_ERR_NOMEM : NOCT_ERR_IO, -1, 0,
                             "%s: cannot open: %s", path, strerror(e));
        }
        d->lines = true;
        switch (kind) {
        case 0: st = read_off(&r, d, err); break;
        case 1: st = read_obj(&r, d, err); break;
        case 2: st = read_stl(&r, d, err); break;
        default: st = read_ply(&r, d, err); break;
        }
        fclose(r.f);
        free(r.buf);
    }
    if (st != NOCT_OK) {
        noctMeshDataDestroy(d);
        return st;
    }
    *data = d;
    return NOCT_OK;
}

/* noctMeshRead() (surface false) and noctMeshReadSurface(). */
static noctStatus mesh_read(const char *path, bool surface, noctMesh **mesh, noctError *err)
{
    NOCT_REQUIRE(path != NULL && mesh != NULL);
    *mesh = NULL;
    noctMeshData *d;
    noctStatus st = noctMeshDataRead(path, &d, err);
    if (st != NOCT_OK)
        return st;
    st = noctMeshDataWeld(d, 0, NULL, err);
    if (st == NOCT_OK)
        st = (surface ? noctMeshCreateSurfaceFromData : noctMeshCreateFromData)(d, mesh, err);
    if (!surface && (st == NOCT_ERR_OPEN || st == NOCT_ERR_ORIENTATION)) {
        noctMeshReport rep;
        noctStatus ist = noctMeshDataInspect(d, &rep, err);
        if (ist != NOCT_OK)
            st = ist;
        else if (rep.reason[0] != '\0')
            noct_fail(err, st, -1, 0, "%s: not a closed, consistently oriented solid: %s "
                      "(noctMeshReadSurface() reads it as a surface; noctree-mesh(1) "
                      "inspects and repairs mesh files)", path, rep.reason);
    }
    if (st == NOCT_ERR_NOMEM)
        noct_fail(err, st, -1, 0, "%s: out of memory", path);
    noctMeshDataDestroy(d);
    return st;
}

noctStatus noctMeshRead(const char *path, noctMesh **mesh, noctError *err)
{
    return mesh_read(path, false, mesh, err);
}

noctStatus noctMeshReadSurface(const char *path, noctMesh **mesh, noctError *err)
{
    return mesh_read(path, true, mesh, err);
}
