/* SPDX-License-Identifier: MIT */
/*
 * Scene files (noctree-scene(5)) and the built-in families. A file is
 * parsed to the end, every line checked, before the caller can build
 * anything from it.
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include <errno.h>
#include <stdarg.h>
#include <limits.h>
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <noctree/scene.h>

#include "families_internal.h"
#include "internal.h"
#include "scene_internal.h"
#include "world_internal.h"

/* ---- parsing ------------------------------------------------------------------ */

typedef struct parser {
    const char *path;
    long line;
    char *save;       /* strtok_r state */
    noctError *err;
    long walls_line;  /* the effects line that last turned the walls on, or 0 */
    bool container;   /* a walls line gave the container */
    uint64_t objects; /* objects the scene will add: lines and families */
} parser;

static noctStatus perr(parser *p, noctStatus st, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* Fail at the current line: "path:line: what". */
static noctStatus perr(parser *p, noctStatus st, const char *fmt, ...)
{
    char what[200];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    return noct_fail(p->err, st, -1, p->line, "%s:%ld: %s", p->path, p->line, what);
}

static char *next(parser *p)
{
    return strtok_r(NULL, " \t\r\n", &p->save);
}

static noctStatus number(parser *p, const char *what, double *out)
{
    char *tok = next(p);
    if (tok == NULL)
        return perr(p, NOCT_ERR_PARSE, "missing %s", what);
    char *end;
    *out = strtod(tok, &end);
    if (end == tok || *end != '\0')
        return perr(p, NOCT_ERR_PARSE, "not a number: '%s'", tok);
    if (!isfinite(*out))
        return perr(p, NOCT_ERR_NONFINITE, "not a finite number: '%s'", tok);
    return NOCT_OK;
}

/* The integer tok (NULL: missing), lo to hi. */
static noctStatus integer_token(parser *p, const char *tok, const char *what, long lo, long hi,
                                long *out)
{
    if (tok == NULL)
        return perr(p, NOCT_ERR_PARSE, "missing %s", what);
    char *end;
    errno = 0;
    *out = strtol(tok, &end, 10);
    if (end == tok || *end != '\0' || errno != 0)
        return perr(p, NOCT_ERR_PARSE, "not an integer: '%s'", tok);
    if (*out < lo || *out > hi) {
        char range[96];
        snprintf(range, sizeof range, "%s %ld is out of range (%ld to %ld)", what, *out,
                 lo, hi);
        return perr(p, NOCT_ERR_INVALID, "%s", range);
    }
    return NOCT_OK;
}

static noctStatus integer(parser *p, const char *what, long lo, long hi, long *out)
{
    return integer_token(p, next(p), what, lo, hi, out);
}

static noctStatus end_of_line(parser *p)
{
    char *tok = next(p);
    return tok ? perr(p, NOCT_ERR_PARSE, "unexpected '%s'", tok) : NOCT_OK;
}

/* A world holds at most 2^31 objects (noctWorldAdd()): count the ones
 * the scene adds, so that a scene read is a scene that builds. */
static noctStatus count_objects(parser *p, uint64_t n)
{
    const uint64_t most = UINT64_C(1) << 31;
    if (n > most - p->objects)
        return perr(p, NOCT_ERR_TOO_LARGE, "the scene would have more than 2^31 objects");
    p->objects += n;
    return NOCT_OK;
}

static noctStatus numbers(parser *p, const char *what, double *out, int n)
{
    for (int i = 0; i < n; ++i) {
        noctStatus st = number(p, what, &out[i]);
        if (st != NOCT_OK)
            return st;
    }
    return NOCT_OK;
}

/* Resolve a mesh file path relative to the scene file's folder. */
static char *relative_path(const char *scene_path, const char *file)
{
    const char *slash = strrchr(scene_path, '/');
    size_t dir = file[0] == '/' || slash == NULL ? 0 : (size_t)(slash - scene_path) + 1;
    char *out = malloc(dir + strlen(file) + 1);
    if (out != NULL) {
        if (dir > 0)
            memcpy(out, scene_path, dir);
        strcpy(out + dir, file);
    }
    return out;
}

static noctStatus parse_mesh(parser *p, noctScene *s)
{
    char *name = next(p), *kind = next(p);
    if (name == NULL || kind == NULL)
        return perr(p, NOCT_ERR_PARSE, "expected 'mesh NAME box|file ...'");
    for (size_t i = 0; i < s->nmeshes; ++i)
        if (strcmp(s->meshes[i].name, name) == 0)
            return perr(p, NOCT_ERR_INVALID, "mesh '%s' is defined twice", name);
    noctMesh *m = NULL;
    noctError inner = {0};
    noctStatus st;
    double h[3] = {0, 0, 0};
    char *full = NULL; /* a file mesh's path, as opened */
    if (strcmp(kind, "box") == 0) {
        if ((st = numbers(p, "half-extent", h, 3)) != NOCT_OK || (st = end_of_line(p)) != NOCT_OK)
            return st;
        /* a box primitive (world.h) when its half-extents suit one, which
         * collides exactly as the mesh would; else the mesh, or its
         * constructor's complaint */
        const bool primitive = noct_check_box_half(h, NULL) == NOCT_OK &&
                               fmax(h[0], fmax(h[1], h[2])) <= NOCT_MAX_COORDINATE;
        st = primitive ? NOCT_OK : noctMeshCreateBox(h[0], h[1], h[2], &m, &inner);
    } else if (strcmp(kind, "file") == 0) {
        char *file = next(p);
        if (file == NULL)
            return perr(p, NOCT_ERR_PARSE, "missing the mesh file name");
        /* the shape's kind: solid (the default) or surface */
        char *shape = next(p);
        const bool surface = shape != NULL && strcmp(shape, "surface") == 0;
        if (shape != NULL && !surface && strcmp(shape, "solid") != 0)
            return perr(p, NOCT_ERR_PARSE, "unknown mesh shape '%s' (solid or surface)", shape);
        if ((st = end_of_line(p)) != NOCT_OK)
            return st;
        full = relative_path(p->path, file);
        if (full == NULL)
            return perr(p, NOCT_ERR_NOMEM, "out of memory");
        st = (surface ? noctMeshReadSurface : noctMeshRead)(full, &m, &inner);
    } else {
        return perr(p, NOCT_ERR_PARSE, "unknown mesh kind '%s' (box or file)", kind);
    }
    if (st != NOCT_OK) {
        free(full);
        return noct_fail(p->err, st, inner.index, p->line, "%s:%ld: mesh '%s': %s",
                         p->path, p->line, name, inner.message);
    }
    st = noct_scene_add_mesh(s, name, m, h, full);
    free(full);
    return st == NOCT_OK ? NOCT_OK : perr(p, st, "out of memory");
}

/* A 64-bit filter word: decimal, or hexadecimal with 0x. */
static noctStatus bits(parser *p, const char *what, uint64_t *out)
{
    char *tok = next(p);
    if (tok == NULL)
        return perr(p, NOCT_ERR_PARSE, "missing %s", what);
    char *end;
    errno = 0;
    /* decimal, or hexadecimal with 0x: a leading zero is not octal */
    const bool hex = tok[0] == '0' && (tok[1] == 'x' || tok[1] == 'X');
    const unsigned long long v = strtoull(tok, &end, hex ? 16 : 10);
    if (end == tok || *end != '\0' || errno != 0 || tok[0] == '-')
        return perr(p, NOCT_ERR_PARSE, "%s: not a 64-bit unsigned integer: '%s'", what, tok);
    *out = (uint64_t)v;
    return NOCT_OK;
}

#define OBJECT_SYNTAX                                                                    \
    "expected 'object MESH X Y Z [DX DY DZ SPEED] [velocity VX VY VZ] "                \
    "[rotate AX AY AZ DEGREES] [type static|kinematic|moving] [filter CATEGORY MASK] "     \
    "[sensor] [spin AX AY AZ DEGREES] [continuous|discrete] [margin D] [name NAME]'"

/* The object attributes' keywords. */
#define ATTRIBUTES 10
static const char *const KW[ATTRIBUTES] = {"velocity", "rotate",     "type",     "filter",
                                           "sensor",   "spin",       "continuous", "discrete",
                                           "margin",   "name"};

/* The object's attributes after its position and legacy motion: each
 * keyword once; *name is the line's 'name' token (NULL without one). */
static noctStatus parse_attributes(parser *p, const noctScene *s, scene_object *o, char *tok,
                                   bool legacy, const char **name)
{
    bool seen[ATTRIBUTES] = {false};
    noctStatus st = NOCT_OK;
    for (; tok != NULL && st == NOCT_OK; tok = next(p)) {
        int k = 0;
        while (k < ATTRIBUTES && strcmp(tok, KW[k]) != 0)
            ++k;
        if (k == ATTRIBUTES)
            return perr(p, NOCT_ERR_PARSE, "unexpected '%s'; " OBJECT_SYNTAX, tok);
        if (seen[k])
            return perr(p, NOCT_ERR_PARSE, "'%s' given twice", tok);
        seen[k] = true;
        if (k == 6 || k == 7) {
            if (seen[13 - k])
                return perr(p, NOCT_ERR_PARSE, "an object is continuous or discrete, not both");
            o->quality = k == 6 ? NOCT_QUALITY_CONTINUOUS : NOCT_QUALITY_DISCRETE;
            continue;
        }
        if (k == 8) {
            if ((st = number(p, "margin", &o->margin)) != NOCT_OK)
                return st;
            if (!(o->margin >= 0 && o->margin <= NOCT_MAX_COORDINATE))
                return perr(p, NOCT_ERR_INVALID, "object margin %g: it must be 0 to %g",
                            o->margin, NOCT_MAX_COORDINATE);
            continue;
        }
        if (k == 9) {
            const char *n = next(p);
            if (n == NULL)
                return perr(p, NOCT_ERR_PARSE, "missing the object's name");
            if (!noct_scene_name_ok(n))
                return perr(p, NOCT_ERR_INVALID,
                            "bad object name '%.80s': 1 to %d letters, digits, '_', '-' or "
                            "'.', the first a letter or '_'",
                            n, NOCT_SCENE_NAME_MAX);
            const size_t other = noct_scene_named(s, n);
            if (other != SIZE_MAX)
                return perr(p, NOCT_ERR_INVALID, "object name '%s' is taken (line %ld)", n,
                            s->objects[other].line);
            *name = n;
            continue;
        }
        if (k == 0) {
            if (legacy)
                return perr(p, NOCT_ERR_PARSE,
                            "an object has a velocity or a direction and speed, not both");
            o->has_velocity = true;
            st = numbers(p, "velocity", o->vel, 3);
        } else if (k == 1) {
            double axis[4];
            if ((st = numbers(p, "rotation axis and angle", axis, 4)) != NOCT_OK)
                return st;
            if (noctQuatFromAxisAngle(axis, axis[3], &o->q) != NOCT_OK)
                return perr(p, NOCT_ERR_INVALID, "a rotation needs a non-zero axis");
            o->rotate = (scene_turn){true, {axis[0], axis[1], axis[2]}, axis[3]};
        } else if (k == 2) {
            char *t = next(p);
            if (t == NULL)
                return perr(p, NOCT_ERR_PARSE, "missing type (static, kinematic or moving)");
            if (strcmp(t, "static") == 0)
                o->type = NOCT_OBJECT_STATIC;
            else if (strcmp(t, "kinematic") == 0)
                o->type = NOCT_OBJECT_KINEMATIC;
            else if (strcmp(t, "moving") == 0)
                o->type = NOCT_OBJECT_MOVING;
            else
                return perr(p, NOCT_ERR_INVALID,
                            "unknown type '%s' (static, kinematic or moving)", t);
            o->has_type = true;
        } else if (k == 4) {
            o->sensor = true;
        } else if (k == 5) {
            double axis[4];
            if ((st = numbers(p, "spin axis and angle", axis, 4)) != NOCT_OK)
                return st;
            if (noctQuatFromAxisAngle(axis, axis[3], &o->spin) != NOCT_OK)
                return perr(p, NOCT_ERR_INVALID, "a spin needs a non-zero axis");
            o->spin_turn = (scene_turn){true, {axis[0], axis[1], axis[2]}, axis[3]};
        } else {
            if ((st = bits(p, "category", &o->category)) != NOCT_OK ||
                (st = bits(p, "mask", &o->mask)) != NOCT_OK)
                return st;
            if (o->category == 0)
                return perr(p, NOCT_ERR_INVALID, "a category of 0 could never pair");
        }
    }
    return st;
}

static bool is_attribute(const char *tok)
{
    for (int k = 0; k < ATTRIBUTES; ++k)
        if (strcmp(tok, KW[k]) == 0)
            return true;
    return false;
}

static noctStatus parse_object(parser *p, noctScene *s)
{
    char *name = next(p);
    if (name == NULL)
        return perr(p, NOCT_ERR_PARSE, OBJECT_SYNTAX);
    size_t mi = s->nmeshes;
    for (size_t i = 0; i < s->nmeshes; ++i)
        if (strcmp(s->meshes[i].name, name) == 0)
            mi = i;
    if (mi == s->nmeshes)
        return perr(p, NOCT_ERR_INVALID, "unknown mesh '%s' (define it first)", name);
    scene_object o = noct_scene_object(mi, (const double[3]){0, 0, 0});
    noctStatus st = numbers(p, "position", o.pos, 3);
    if (st != NOCT_OK)
        return st;
    char *tok = next(p);
    bool legacy = false;
    if (tok != NULL && !is_attribute(tok)) {
        /* the direction's first number: re-parse from it */
        legacy = true;
        char *end;
        o.dir[0] = strtod(tok, &end);
        if (end == tok || *end != '\0')
            return perr(p, NOCT_ERR_PARSE, "unexpected '%s'; " OBJECT_SYNTAX, tok);
        if (!isfinite(o.dir[0]))
            return perr(p, NOCT_ERR_NONFINITE, "not a finite number: '%s'", tok);
        if ((st = numbers(p, "direction", &o.dir[1], 2)) != NOCT_OK ||
            (st = number(p, "speed", &o.speed)) != NOCT_OK)
            return st;
        if (o.speed < 0)
            return perr(p, NOCT_ERR_INVALID, "negative speed");
        /* Scaled as the world scales it, so that (1e-200, 0, 0) and
         * (1e200, 0, 0) are directions like (1, 0, 0), not zero or
         * infinite. */
        double unit[3];
        if (o.speed > 0 && !noct_unit_direction(o.dir, unit))
            return perr(p, NOCT_ERR_INVALID, "a moving object needs a non-zero direction");
        tok = next(p);
    }
    const char *oname = NULL;
    if ((st = parse_attributes(p, s, &o, tok, legacy, &oname)) != NOCT_OK)
        return st;
    if (s->meshes[mi].mesh == NULL) { /* a box primitive: its corners as turned */
        double R[9];
        noctQuatToMatrix(&o.q, R, NULL);
        if (noct_check_box_corners(s->meshes[mi].half, R, NULL) != NOCT_OK)
            return perr(p, NOCT_ERR_TOO_LARGE,
                        "box '%s' as turned puts a corner beyond the coordinate limit", name);
    }
    for (int k = 0; k < 3; ++k)
        if (fabs(o.pos[k]) > NOCT_MAX_COORDINATE)
            return perr(p, NOCT_ERR_TOO_LARGE, "position beyond the coordinate limit");
    if ((st = count_objects(p, 1)) != NOCT_OK)
        return st;
    o.line = p->line;
    if (oname != NULL && (o.name = strdup(oname)) == NULL)
        return perr(p, NOCT_ERR_NOMEM, "out of memory");
    if (noct_scene_add_object(s, &o) != NOCT_OK) {
        free(o.name);
        return perr(p, NOCT_ERR_NOMEM, "out of memory");
    }
    /* (the scene owns the name now, findable or not) */
    if (o.name != NULL && noct_scene_index_name(s) != NOCT_OK)
        return perr(p, NOCT_ERR_NOMEM, "out of memory");
    return NOCT_OK;
}

/* 'key TICK X Y Z [rotate AX AY AZ DEGREES]': a keyframe of the last
 * object line's track. */
static noctStatus parse_key(parser *p, noctScene *s)
{
    if (s->nobjects == 0)
        return perr(p, NOCT_ERR_INVALID, "a key needs an object line above it");
    scene_object *o = &s->objects[s->nobjects - 1];
    if (o->has_velocity || o->speed > 0)
        return perr(p, NOCT_ERR_INVALID,
                    "an object that follows a track has no velocity (nor direction and speed)");
    if (o->has_type && o->type != NOCT_OBJECT_KINEMATIC)
        return perr(p, NOCT_ERR_INVALID, "an object that follows a track is kinematic");
    long tick;
    scene_key key;
    memset(&key, 0, sizeof key);
    noctKeyframe *kf = &key.k;
    noctStatus st = integer(p, "key tick", 0, 9007199254740992L, &tick);
    if (st != NOCT_OK || (st = numbers(p, "key position", kf->x.p, 3)) != NOCT_OK)
        return st;
    kf->tick = (uint64_t)tick;
    kf->x.q = (noctQuat){0, 0, 0, 1};
    char *tok = next(p);
    if (tok != NULL) {
        if (strcmp(tok, "rotate") != 0)
            return perr(p, NOCT_ERR_PARSE,
                        "unexpected '%s'; expected 'key TICK X Y Z [rotate AX AY AZ DEGREES]'",
                        tok);
        double axis[4];
        if ((st = numbers(p, "rotation axis and angle", axis, 4)) != NOCT_OK ||
            (st = end_of_line(p)) != NOCT_OK)
            return st;
        if (noctQuatFromAxisAngle(axis, axis[3], &kf->x.q) != NOCT_OK)
            return perr(p, NOCT_ERR_INVALID, "a rotation needs a non-zero axis");
        key.turn = (scene_turn){true, {axis[0], axis[1], axis[2]}, axis[3]};
    }
    if (o->nkeys > 0 && !(kf->tick > s->keys[s->nkeys - 1].k.tick))
        return perr(p, NOCT_ERR_INVALID, "key tick %llu is not after the previous key's %llu",
                    (unsigned long long)kf->tick,
                    (unsigned long long)s->keys[s->nkeys - 1].k.tick);
    for (int c = 0; c < 3; ++c)
        if (fabs(kf->x.p[c]) > NOCT_MAX_COORDINATE)
            return perr(p, NOCT_ERR_TOO_LARGE, "key position beyond the coordinate limit");
    if (s->meshes[o->mesh].mesh == NULL) { /* a box primitive: its corners as turned */
        double R[9];
        noctQuatToMatrix(&kf->x.q, R, NULL);
        if (noct_check_box_corners(s->meshes[o->mesh].half, R, NULL) != NOCT_OK)
            return perr(p, NOCT_ERR_TOO_LARGE,
                        "the box as turned puts a corner beyond the coordinate limit");
    }
    if (noct_scene_add_key(s, &key) != NOCT_OK)
        return perr(p, NOCT_ERR_NOMEM, "out of memory");
    s->def.effects |= NOCT_EFFECT_TRACK;
    return NOCT_OK;
}

static noctStatus parse_line(parser *p, noctScene *s, char *kw)
{
    noctStatus st;
    long v;
    if (strcmp(kw, "N") == 0) {
        char *tok = next(p);
        if (tok != NULL && (strcmp(tok, "big") == 0 || strcmp(tok, "auto") == 0)) {
            s->def.N = tok[0] == 'b' ? NOCT_N_EXHAUSTIVE : NOCT_AUTO;
            return end_of_line(p);
        }
        if (tok == NULL)
            return perr(p, NOCT_ERR_PARSE, "missing N");
        char *end;
        errno = 0;
        v = strtol(tok, &end, 10);
        if (end == tok || *end != '\0' || errno != 0)
            return perr(p, NOCT_ERR_PARSE, "N must be an integer, 'big' or 'auto', not '%s'",
                        tok);
        if (v < 1 || v > INT_MAX - 1)
            return perr(p, NOCT_ERR_INVALID,
                        "N must be at least 1 and below %d (or 'big' or 'auto'), not '%s'",
                        INT_MAX, tok);
        s->def.N = (int)v;
        return end_of_line(p);
    }
    if (strcmp(kw, "max-depth") == 0) {
        const char *tok = next(p);
        if (tok != NULL && strcmp(tok, "auto") == 0) {
            s->def.max_depth = NOCT_AUTO;
            return end_of_line(p);
        }
        if ((st = integer_token(p, tok, "max-depth", 1, 40, &v)) != NOCT_OK)
            return st;
        s->def.max_depth = (int)v;
        return end_of_line(p);
    }
    if (strcmp(kw, "margin") == 0) {
        double d;
        if ((st = number(p, "margin", &d)) != NOCT_OK || (st = end_of_line(p)) != NOCT_OK)
            return st;
        if (!(d >= 0 && d <= NOCT_MAX_COORDINATE))
            return perr(p, NOCT_ERR_INVALID, "margin %g: it must be 0 to %g", d,
                        NOCT_MAX_COORDINATE);
        s->def.margin = d;
        return NOCT_OK;
    }
    if (strcmp(kw, "steps") == 0) {
        if ((st = integer(p, "steps", 1, 10000000, &v)) != NOCT_OK)
            return st;
        s->steps = (int)v;
        return end_of_line(p);
    }
    if (strcmp(kw, "accuracy") == 0) {
        char *tok = next(p);
        if (tok == NULL)
            return perr(p, NOCT_ERR_PARSE,
                        "missing the accuracy (box, convex, exact or continuous)");
        if (strcmp(tok, "box") == 0)
            s->def.accuracy = NOCT_ACCURACY_BOX;
        else if (strcmp(tok, "convex") == 0)
            s->def.accuracy = NOCT_ACCURACY_CONVEX;
        else if (strcmp(tok, "exact") == 0)
            s->def.accuracy = NOCT_ACCURACY_EXACT;
        else if (strcmp(tok, "continuous") == 0)
            s->def.accuracy = NOCT_ACCURACY_CONTINUOUS;
        else
            return perr(p, NOCT_ERR_INVALID,
                        "unknown accuracy '%s' (box, convex, exact or continuous)", tok);
        return end_of_line(p);
    }
    if (strcmp(kw, "maintenance") == 0) {
        char *tok = next(p);
        if (tok != NULL && strcmp(tok, "incremental") == 0)
            s->def.maintenance = NOCT_MAINTAIN_INCREMENTAL;
        else if (tok != NULL && strcmp(tok, "rebuild") == 0)
            s->def.maintenance = NOCT_MAINTAIN_REBUILD;
        else
            return perr(p, NOCT_ERR_INVALID,
                        "maintenance must be 'incremental' or 'rebuild'");
        return end_of_line(p);
    }
    if (strcmp(kw, "effects") == 0) {
        unsigned e = 0;
        char *tok;
        while ((tok = next(p)) != NULL) {
            if (strcmp(tok, "motion") == 0)
                e |= NOCT_EFFECT_MOTION;
            else if (strcmp(tok, "events") == 0)
                e |= NOCT_EFFECT_EVENTS;
            else if (strcmp(tok, "response") == 0)
                e |= NOCT_EFFECT_RESPONSE;
            else if (strcmp(tok, "walls") == 0)
                e |= NOCT_EFFECT_WALLS;
            else if (strcmp(tok, "substep") == 0)
                e |= NOCT_EFFECT_SUBSTEP;
            else if (strcmp(tok, "spin") == 0)
                e |= NOCT_EFFECT_SPIN;
            else if (strcmp(tok, "track") == 0)
                e |= NOCT_EFFECT_TRACK;
            else if (strcmp(tok, "none") != 0)
                return perr(p, NOCT_ERR_INVALID,
                            "unknown effect '%s' (motion, events, response, walls, "
                            "substep, spin, track, none)",
                            tok);
        }
        s->def.effects = e;
        /* The container may come on a later line: checked at the end. */
        p->walls_line = e & NOCT_EFFECT_WALLS ? p->line : 0;
        return NOCT_OK;
    }
    if (strcmp(kw, "walls") == 0) {
        double w[6];
        if ((st = numbers(p, "wall coordinate", w, 6)) != NOCT_OK || (st = end_of_line(p)) != NOCT_OK)
            return st;
        for (int k = 0; k < 3; ++k) {
            if (!(w[k] < w[k + 3]))
                return perr(p, NOCT_ERR_INVALID, "walls: each low coordinate must be below "
                            "the high one");
            s->def.walls_lo[k] = w[k];
            s->def.walls_hi[k] = w[k + 3];
        }
        s->def.effects |= NOCT_EFFECT_WALLS;
        p->container = true;
        return NOCT_OK;
    }
    if (strcmp(kw, "mesh") == 0)
        return parse_mesh(p, s);
    if (strcmp(kw, "object") == 0)
        return parse_object(p, s);
    if (strcmp(kw, "key") == 0)
        return parse_key(p, s);
    if (strcmp(kw, "family") == 0) {
        char *tok = next(p);
        if (s->nfamilies == sizeof s->families / sizeof *s->families)
            return perr(p, NOCT_ERR_TOO_LARGE, "too many families");
        const noct_family *f = tok != NULL ? noct_family_find(tok, strlen(tok)) : NULL;
        if (f == NULL || f->add == NULL) {
            char names[128];
            noct_family_line_names(names, sizeof names);
            return perr(p, NOCT_ERR_INVALID, "unknown family '%s' (%s)", tok ? tok : "", names);
        }
        long size;
        if ((st = integer(p, f->line_size, f->lo, f->hi, &size)) != NOCT_OK ||
            (st = end_of_line(p)) != NOCT_OK ||
            (st = count_objects(p, f->objects(size))) != NOCT_OK)
            return st;
        if (noct_scene_add_family(s, f, size) != NOCT_OK)
            return perr(p, NOCT_ERR_NOMEM, "out of memory");
        return NOCT_OK;
    }
    return perr(p, NOCT_ERR_PARSE, "unknown statement '%s'", kw);
}

/*
 * Read the next line into *buf and count it: *got tells whether there was
 * one. getline(3) returns -1 at the end of the file, on a read error, and
 * when it finds no memory for a long line; only the last sets errno to
 * ENOMEM without the error indicator, so taking every -1 for the end would
 * silently read a file short. A NUL byte would end the line for the
 * parser, silently too, so it is an error.
 */
static noctStatus scene_line(parser *p, FILE *f, char **buf, size_t *cap, bool *got)
{
    errno = 0;
    ssize_t n = getline(buf, cap, f);
    *got = n >= 0;
    if (n >= 0) {
        ++p->line;
        return memchr(*buf, '\0', (size_t)n) ? perr(p, NOCT_ERR_PARSE, "NUL byte in line")
                                             : NOCT_OK;
    }
    int e = errno;
    if (e != ENOMEM && feof(f) && !ferror(f))
        return NOCT_OK;
    ++p->line; /* the line that could not be read */
    if (e == ENOMEM)
        return perr(p, NOCT_ERR_NOMEM, "out of memory reading the line");
    return perr(p, NOCT_ERR_IO, "read error: %s", strerror(e != 0 ? e : EIO));
}

noctStatus noctSceneRead(const char *path, noctScene **scene, noctError *err)
{
    NOCT_REQUIRE(path != NULL && scene != NULL);
    *scene = NULL;
    FILE *f = fopen(path, "r");
    if (f == NULL) {
        int e = errno;
        return noct_fail(err, e == ENOMEM ? NOCT_ERR_NOMEM : NOCT_ERR_IO, -1, 0,
                         "%s: cannot open: %s", path, strerror(e));
    }
    noctScene *s = noct_scene_new();
    if (s == NULL) {
        fclose(f);
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "%s: out of memory", path);
    }
    parser p = {path, 0, NULL, err, 0, false, 0};
    char *buf = NULL;
    size_t cap = 0;
    noctStatus st;
    bool got;
    while ((st = scene_line(&p, f, &buf, &cap, &got)) == NOCT_OK && got) {
        char *hash = strchr(buf, '#');
        if (hash != NULL)
            *hash = '\0';
        char *kw = strtok_r(buf, " \t\r\n", &p.save);
        if (kw != NULL && (st = parse_line(&p, s, kw)) != NOCT_OK)
            break;
    }
    /* What noctWorldCreate() would reject across lines, at the line that
     * asked for it. */
    if (st == NOCT_OK && (s->def.effects & NOCT_EFFECT_WALLS) && !p.container)
        st = noct_fail(err, NOCT_ERR_INVALID, -1, p.walls_line,
                       "%s:%ld: the walls effect needs a container (a line "
                       "'walls xlo ylo zlo xhi yhi zhi')", path, p.walls_line);
    if (st == NOCT_OK && s->nobjects == 0 && s->nfamilies == 0)
        st = noct_fail(err, NOCT_ERR_INVALID, -1, 0, "%s: the scene has no objects", path);
    free(buf);
    fclose(f);
    if (st != NOCT_OK) {
        noctSceneDestroy(s);
        return st;
    }
    *scene = s;
    return NOCT_OK;
}

noctStatus noctSceneFamily(const char *spec, noctScene **scene, noctError *err)
{
    NOCT_REQUIRE(spec != NULL && scene != NULL);
    *scene = NULL;
    const noct_family *f;
    long size;
    noctStatus st = noct_family_spec(spec, &f, &size, err);
    if (st != NOCT_OK)
        return st;
    noctScene *s = noct_scene_new();
    if (s == NULL)
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    if ((st = f->make(s, f, size, err)) != NOCT_OK) {
        noctSceneDestroy(s);
        return st;
    }
    *scene = s;
    return NOCT_OK;
}

noctStatus noctSceneBuild(const noctScene *s, noctWorld **world, noctError *err)
{
    NOCT_REQUIRE(s != NULL && world != NULL);
    *world = NULL;
    noctWorld *w;
    noctStatus st = noctWorldCreate(&s->def, &w, err);
    if (st != NOCT_OK)
        return st;
    /* the families' objects, made now: the scene keeps only their sizes */
    for (size_t i = 0; i < s->nfamilies && st == NOCT_OK; ++i) {
        const scene_family *f = &s->families[i];
        st = f->family->add(w, f->family, f->size, (const noctMesh *const *)s->shared, err);
    }
    if (st == NOCT_OK && s->nobjects > 0)
        st = noctWorldReserve(w, s->nobjects, err);
    for (size_t i = 0; i < s->nobjects && st == NOCT_OK; ++i) {
        const scene_object *o = &s->objects[i];
        const scene_mesh *sm = &s->meshes[o->mesh];
        noctObjectDef d = noctDefaultObjectDef();
        d.mesh = sm->mesh;
        memcpy(d.half_extents, sm->half, sizeof d.half_extents);
        memcpy(d.transform.p, o->pos, sizeof d.transform.p);
        d.transform.q = o->q;
        d.type = o->type;
        d.category = o->category;
        d.mask = o->mask;
        d.sensor = o->sensor;
        d.quality = o->quality;
        d.angular_velocity = o->spin;
        d.margin = o->margin;
        double speed = 0;
        if (o->has_velocity) {
            memcpy(d.velocity, o->vel, sizeof d.velocity);
        } else if (o->speed > 0) {
            /* direction and speed: the velocity as noctWorldAdd() makes it */
            double unit[3];
            noct_unit_direction(o->dir, unit); /* checked when read */
            for (int k = 0; k < 3; ++k)
                d.velocity[k] = o->speed * unit[k];
            speed = o->speed;
        }
        noctObjectId id;
        st = noct_world_add_object(w, &d, speed, &id, err);
        if (st == NOCT_OK && o->nkeys > 0) {
            noctKeyframe *k = malloc(o->nkeys * sizeof *k);
            if (k == NULL) {
                st = noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
                break;
            }
            for (size_t j = 0; j < o->nkeys; ++j)
                k[j] = s->keys[o->first_key + j].k;
            st = noctWorldSetTrack(w, id, k, o->nkeys, err);
            free(k);
        }
    }
    if (st != NOCT_OK) {
        noctWorldDestroy(w);
        return st;
    }
    *world = w;
    return NOCT_OK;
}
