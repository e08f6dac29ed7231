/* SPDX-License-Identifier: MIT */
/*
 * octprint: the report's octPrint as a tool. Builds a scene's N-objects
 * octree, runs it to a given step and prints the tree: the text of
 * octPrint (child type, generation, the node's cube and a leaf's objects),
 * and on request Graphviz dot of the tree and an SVG slice of the cells
 * with the objects' boxes drawn in (as the report's Figures 5 to 7).
 * With --broadphase it does the same for a bare broadphase (broadphase.h)
 * holding the boxes of a box file, with no world. See octprint(1).
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <noctree.h>

#include "toolutil.h"

static const char usage[] =
    "usage: octprint [OPTIONS] SCENE-FILE\n"
    "       octprint [OPTIONS] --scene planes:K|gas:N\n"
    "       octprint [OPTIONS] --broadphase BOX-FILE\n"
    "Print a scene's N-objects octree after a number of steps, or that of a\n"
    "bare broadphase holding the boxes of a box file.\n"
    "\n"
    "  --scene FAMILY     a built-in scene: planes:K or gas:N\n"
    "  --broadphase FILE  a bare broadphase (no world) of the file's boxes: one\n"
    "                     box a line, 'lo_x lo_y lo_z hi_x hi_y hi_z', '#' starts\n"
    "                     a comment; '-' reads standard input; no --step\n"
    "  --step S           run S steps first (default 0: the tree as built)\n"
    "  --N N|big|auto     most objects per octree leaf\n"
    "  --max-depth D|auto deepest octree level, 1 to 40\n"
    "  --dot FILE         also write the tree as Graphviz dot ('-': stdout)\n"
    "  --svg FILE         also draw a slice of the cells and objects as SVG\n"
    "  --slice AXIS=V     the slice: x, y or z equal to V (default: z through\n"
    "                     the middle of the root)\n"
    "  --no-text          do not print the octPrint text\n"
    "  --help             this text\n"
    "  --version          the version\n"
    "\n"
    "Exit status: 0 on success, 1 if the run or a write failed, 2 for bad usage\n"
    "or input.\n";

static const char *const PALETTE[] = {"#4e79a7", "#f28e2b", "#e15759", "#76b7b2",
                                      "#59a14f", "#edc948", "#b07aa1", "#ff9da7"};

static FILE *open_or_stdout(const char *path)
{
    if (strcmp(path, "-") == 0)
        return stdout;
    FILE *f = fopen(path, "w");
    if (f == NULL)
        tool_error("%s: %s", path, strerror(errno));
    return f;
}

static bool close_checked(FILE *f, const char *path)
{
    bool ok = !ferror(f);
    if (f != stdout)
        ok &= fclose(f) == 0;
    else
        ok &= fflush(f) == 0;
    if (!ok)
        tool_error("%s: write error", path);
    return ok;
}

/* ---- Graphviz dot ----------------------------------------------------------- */

static void dot_node(FILE *f, const noctBroadphase *bp, octNode *n, unsigned long *next,
                     unsigned long parent)
{
    unsigned long me = (*next)++;
    size_t count = noctBroadphaseCell(bp, n, NULL, NULL, NULL, 0);
    if (octIsSplit(n))
        fprintf(f, "  n%lu [label=\"%s\\ng%d\"];\n", me, octDirToStr(octChildType(n)),
                octGeneration(n));
    else
        fprintf(f, "  n%lu [label=\"%s\\ng%d\\n%zu obj\", shape=box, style=filled, "
                   "fillcolor=\"%s\"];\n",
                me, octDirToStr(octChildType(n)), octGeneration(n), count,
                count == 0 ? "white" : count == 1 ? "#dbe9f6" : "#f6c6c6");
    if (me != 0)
        fprintf(f, "  n%lu -> n%lu;\n", parent, me);
    if (octIsSplit(n))
        for (int i = 0; i < 8; ++i)
            dot_node(f, bp, octChild(n, (octDirection)(OCT_LDB + i)), next, me);
}

static bool write_dot(const char *path, const noctBroadphase *bp, const char *title)
{
    FILE *f = open_or_stdout(path);
    if (f == NULL)
        return false;
    unsigned long next = 0;
    fprintf(f, "digraph octree {\n  label=\"%s\";\n  node [fontsize=10];\n", title);
    dot_node(f, bp, noctBroadphaseRoot(bp), &next, 0);
    fprintf(f, "}\n");
    return close_checked(f, path);
}

/* ---- SVG slice ----------------------------------------------------------------- */

typedef struct slice {
    int axis, u, v;  /* the cut axis and the two drawn axes */
    double at;       /* the cut's coordinate */
    double lo[2], scale, height;
} slice;

static double sx(const slice *s, double x)
{
    return 20 + (x - s->lo[0]) * s->scale;
}

static double sy(const slice *s, double y)
{
    return 20 + s->height - (y - s->lo[1]) * s->scale;
}

/* Leaves cut by the plane, as rectangles. */
static void svg_cells(FILE *f, const noctBroadphase *bp, octNode *n, const slice *s)
{
    double lo[3], size;
    size_t count = noctBroadphaseCell(bp, n, lo, &size, NULL, 0);
    if (s->at < lo[s->axis] || s->at > lo[s->axis] + size)
        return;
    if (octIsSplit(n)) {
        for (int i = 0; i < 8; ++i)
            svg_cells(f, bp, octChild(n, (octDirection)(OCT_LDB + i)), s);
        return;
    }
    fprintf(f, "<rect x=\"%.3f\" y=\"%.3f\" width=\"%.3f\" height=\"%.3f\" fill=\"%s\" "
               "stroke=\"#555\" stroke-width=\"0.6\"><title>%s g%d: %zu objects</title>"
               "</rect>\n",
            sx(s, lo[s->u]), sy(s, lo[s->v] + size), size * s->scale, size * s->scale,
            count > 1 ? "#fbeaea" : "white", octDirToStr(octChildType(n)), octGeneration(n),
            count);
}

/* An object (a proxy) of the tree with its box. */
typedef struct obj_box {
    noctProxyId id;
    double lo[3], hi[3];
} obj_box;

typedef struct obj_list {
    obj_box *v;
    size_t n, cap;
    bool failed;
} obj_list;

/* Append the objects of the leaves below n (with repeats). */
static void gather_objects(const noctBroadphase *bp, octNode *n, obj_list *l)
{
    if (octIsSplit(n)) {
        for (int i = 0; i < 8; ++i)
            gather_objects(bp, octChild(n, (octDirection)(OCT_LDB + i)), l);
        return;
    }
    size_t count = noctBroadphaseCell(bp, n, NULL, NULL, NULL, 0);
    noctProxyId *ids = malloc((count + 1) * sizeof *ids);
    if (l->n + count > l->cap) {
        size_t cap = 2 * (l->n + count) + 16;
        obj_box *v = realloc(l->v, cap * sizeof *v);
        if (v != NULL) {
            l->v = v;
            l->cap = cap;
        }
    }
    if (ids == NULL || l->n + count > l->cap) {
        l->failed = true;
        free(ids);
        return;
    }
    noctBroadphaseCell(bp, n, NULL, NULL, ids, count);
    for (size_t i = 0; i < count; ++i)
        l->v[l->n++].id = ids[i];
    free(ids);
}

static int cmp_obj(const void *x, const void *y)
{
    const obj_box *a = x, *b = y;
    return (a->id.index > b->id.index) - (a->id.index < b->id.index);
}

/* Every object of the tree once, with its box; false if out of memory. */
static bool tree_objects(const noctBroadphase *bp, obj_list *l)
{
    *l = (obj_list){0};
    gather_objects(bp, noctBroadphaseRoot(bp), l);
    if (l->failed)
        return false;
    if (l->n > 0)
        qsort(l->v, l->n, sizeof *l->v, cmp_obj);
    size_t m = 0;
    for (size_t i = 0; i < l->n; ++i)
        if ((m == 0 || l->v[m - 1].id.index != l->v[i].id.index) &&
            noctBroadphaseProxy(bp, l->v[i].id, l->v[i].lo, l->v[i].hi, NULL, NULL, NULL) ==
                NOCT_OK)
            l->v[m++] = l->v[i];
    l->n = m;
    return true;
}

static bool write_svg(const char *path, const noctBroadphase *bp, int axis, double at,
                      bool at_given, const char *title)
{
    static const char *names = "xyz";
    double lo[3], size, olo[3] = {1e308, 1e308, 1e308}, ohi[3] = {-1e308, -1e308, -1e308};
    noctBroadphaseCell(bp, noctBroadphaseRoot(bp), lo, &size, NULL, 0);
    obj_list objs;
    if (!tree_objects(bp, &objs)) {
        free(objs.v);
        tool_error("out of memory");
        return false;
    }
    for (size_t i = 0; i < objs.n; ++i)
        for (int k = 0; k < 3; ++k) {
            olo[k] = objs.v[i].lo[k] < olo[k] ? objs.v[i].lo[k] : olo[k];
            ohi[k] = objs.v[i].hi[k] > ohi[k] ? objs.v[i].hi[k] : ohi[k];
        }
    slice s = {axis, axis == 0 ? 1 : 0, axis == 2 ? 1 : 2, 0, {0, 0}, 0, 760};
    /* The view: the objects' extent in the drawn axes with a margin, or the
     * root when there are no objects; by default the cut goes through the
     * middle of the objects. */
    double view = size;
    s.lo[0] = lo[s.u];
    s.lo[1] = lo[s.v];
    if (olo[0] <= ohi[0]) {
        double eu = ohi[s.u] - olo[s.u], ev = ohi[s.v] - olo[s.v];
        view = 1.1 * (eu > ev ? eu : ev) + 1e-9;
        s.lo[0] = 0.5 * (olo[s.u] + ohi[s.u]) - view / 2;
        s.lo[1] = 0.5 * (olo[s.v] + ohi[s.v]) - view / 2;
        s.at = at_given ? at : 0.5 * (olo[axis] + ohi[axis]);
    } else {
        s.at = at_given ? at : lo[axis] + size / 2;
    }
    s.scale = 760 / view;
    FILE *f = open_or_stdout(path);
    if (f == NULL) {
        free(objs.v);
        return false;
    }
    fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
               "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"800\" height=\"860\" "
               "viewBox=\"0 0 800 860\" font-family=\"sans-serif\" font-size=\"14\">\n"
               "<rect width=\"800\" height=\"860\" fill=\"white\"/>\n"
               "<clipPath id=\"view\"><rect x=\"20\" y=\"20\" width=\"760\" "
               "height=\"760\"/></clipPath>\n<g clip-path=\"url(#view)\">\n");
    svg_cells(f, bp, noctBroadphaseRoot(bp), &s);
    /* The object boxes the plane cuts. */
    for (size_t i = 0; i < objs.n; ++i) {
        const obj_box *o = &objs.v[i];
        if (s.at < o->lo[axis] || s.at > o->hi[axis])
            continue;
        fprintf(f, "<rect x=\"%.3f\" y=\"%.3f\" width=\"%.3f\" height=\"%.3f\" "
                   "fill=\"%s\" fill-opacity=\"0.55\" stroke=\"#222\" stroke-width=\"0.8\">"
                   "<title>object %u</title></rect>\n",
                sx(&s, o->lo[s.u]), sy(&s, o->hi[s.v]), (o->hi[s.u] - o->lo[s.u]) * s.scale,
                (o->hi[s.v] - o->lo[s.v]) * s.scale, PALETTE[o->id.index % 8], o->id.index);
    }
    free(objs.v);
    fprintf(f, "</g>\n<text x=\"20\" y=\"808\">%s</text>\n"
               "<text x=\"20\" y=\"830\">leaves and object boxes cut by %c = %.6g (%c to "
               "the right, %c up); shaded: leaves with 2+ objects</text>\n</svg>\n",
            title, names[axis], s.at, names[s.u], names[s.v]);
    return close_checked(f, path);
}

/* ---- a bare broadphase from a box file (--broadphase) ------------------------ */

/*
 * Add the boxes of a box file to bp: one box a line, "lo_x lo_y lo_z hi_x
 * hi_y hi_z" (closed; lo <= hi on every axis), '#' to the end of a line a
 * comment, blank lines skipped; "-" reads standard input. Box k (from 0,
 * in the file's order) is proxy k of the new broadphase. Returns 0, or 2
 * after printing "FILE:LINE: problem" (or "FILE: problem").
 */
static int read_boxes(const char *path, noctBroadphase *bp, size_t *count)
{
    static const char axes[] = "xyz";
    const char *name = strcmp(path, "-") == 0 ? "(stdin)" : path;
    FILE *f = strcmp(path, "-") == 0 ? stdin : fopen(path, "r");
    if (f == NULL) {
        tool_error("%s: %s", name, strerror(errno));
        return 2;
    }
    char *line = NULL;
    size_t cap = 0;
    long lineno = 0;
    int status = 0;
    *count = 0;
    while (status == 0 && getline(&line, &cap, f) >= 0) {
        ++lineno;
        char *hash = strchr(line, '#');
        if (hash != NULL)
            *hash = '\0';
        double v[6];
        int n = 0;
        char *save = NULL;
        for (char *tok = strtok_r(line, " \t\r\n\v\f", &save); tok != NULL && status == 0;
             tok = strtok_r(NULL, " \t\r\n\v\f", &save)) {
            char *end;
            errno = 0;
            double x = strtod(tok, &end);
            if (n == 6) {
                tool_error("%s:%ld: more than 6 numbers (lo_x lo_y lo_z hi_x hi_y hi_z)", name,
                           lineno);
                status = 2;
            } else if (end == tok || *end != '\0') {
                tool_error("%s:%ld: '%s' is not a number", name, lineno, tok);
                status = 2;
            } else if (isnan(x)) {
                tool_error("%s:%ld: '%s': a coordinate is not a number (NaN)", name, lineno, tok);
                status = 2;
            } else if (isinf(x)) {
                tool_error("%s:%ld: '%s': a coordinate is infinite or out of range", name,
                           lineno, tok);
                status = 2;
            } else {
                v[n++] = x;
            }
        }
        if (status != 0 || n == 0)
            continue;
        if (n < 6) {
            tool_error("%s:%ld: %d number%s, want 6 (lo_x lo_y lo_z hi_x hi_y hi_z)", name,
                       lineno, n, n == 1 ? "" : "s");
            status = 2;
            continue;
        }
        for (int k = 0; k < 3 && status == 0; ++k)
            if (v[k] > v[k + 3]) {
                tool_error("%s:%ld: inverted box: lo_%c %.17g > hi_%c %.17g", name, lineno,
                           axes[k], v[k], axes[k], v[k + 3]);
                status = 2;
            }
        noctProxyId id;
        noctError err;
        if (status == 0 && noctBroadphaseAdd(bp, v, v + 3, NULL, NOCT_FILTER_ALL,
                                             NOCT_FILTER_ALL, &id, &err) != NOCT_OK) {
            tool_error("%s:%ld: %s", name, lineno, err.message);
            status = 2;
        }
        *count += status == 0;
    }
    if (status == 0 && ferror(f)) {
        tool_error("%s: read error", name);
        status = 2;
    }
    if (status == 0 && *count == 0) {
        tool_error("%s: no boxes", name);
        status = 2;
    }
    free(line);
    if (f != stdin)
        fclose(f);
    return status;
}

/* ---- main ------------------------------------------------------------------------- */

int main(int argc, char **argv)
{
    tool_name = "octprint";
    tool_scene_args sa = {0};
    const char *dot = NULL, *svg = NULL, *opt_slice = NULL, *boxes = NULL;
    long steps = 0;
    bool text = true, steps_given = false;
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i];
        bool has = i + 1 < argc;
        if (tool_help_or_version(a, usage)) {
            return 0;
        } else if (strcmp(a, "--no-text") == 0) {
            text = false;
        } else if (strcmp(a, "--dot") == 0 && has) {
            dot = argv[++i];
        } else if (strcmp(a, "--svg") == 0 && has) {
            svg = argv[++i];
        } else if (strcmp(a, "--slice") == 0 && has) {
            opt_slice = argv[++i];
        } else if (strcmp(a, "--broadphase") == 0 && has) {
            if (boxes != NULL)
                return tool_usage_error("more than one --broadphase file: '%s'", argv[i + 1]);
            boxes = argv[++i];
        } else if (strcmp(a, "--step") == 0 && has) {
            if (!tool_parse_long(argv[++i], 0, 10000000, &steps))
                return tool_usage_error("--step must be 0 to 10000000, not '%s'", argv[i]);
            steps_given = true;
        } else {
            int took = tool_scene_arg(&sa, argc, argv, &i);
            if (took < 0)
                return 2;
            if (took == 0)
                return tool_usage_error("unknown option or missing value: '%s'", a);
        }
    }
    int axis = 2;
    double at = 0;
    if (opt_slice != NULL) {
        const char *p = strchr("xyz", opt_slice[0]);
        if (opt_slice[0] == '\0' || p == NULL || opt_slice[1] != '=' ||
            !tool_parse_double(opt_slice + 2, -1e100, 1e100, &at))
            return tool_usage_error("--slice must look like z=0.5, not '%s'", opt_slice);
        axis = (int)(p - "xyz");
    }
    if (dot && svg && strcmp(dot, "-") == 0 && strcmp(svg, "-") == 0)
        return tool_usage_error("--dot and --svg cannot both write to stdout");
    if (boxes != NULL && (sa.family != NULL || sa.file != NULL))
        return tool_usage_error("give a scene or --broadphase FILE, not both");
    if (boxes != NULL && steps_given)
        return tool_usage_error("--step needs a scene: a bare broadphase does not move");

    noctScene *scene = NULL;
    noctWorld *w = NULL;
    noctBroadphase *own = NULL; /* the bare broadphase of --broadphase */
    const noctBroadphase *bp;
    noctError err;
    int status = 0;
    size_t objects;
    const char *source;
    bool auto_N, auto_depth;
    if (boxes != NULL) {
        noctBroadphaseDef bdef = noctDefaultBroadphaseDef();
        if (sa.set_N)
            bdef.N = sa.N;
        if (sa.set_depth)
            bdef.max_depth = sa.depth;
        if (noctBroadphaseCreate(&bdef, &own, &err) != NOCT_OK) {
            tool_error("%s", err.message);
            return 2;
        }
        int bad = read_boxes(boxes, own, &objects);
        if (bad) {
            noctBroadphaseDestroy(own);
            return bad;
        }
        bp = own;
        source = strcmp(boxes, "-") == 0 ? "(stdin)" : boxes;
        auto_N = bdef.N == NOCT_AUTO;
        auto_depth = bdef.max_depth == NOCT_AUTO;
    } else {
        int bad = tool_scene_load(&sa, &scene);
        if (bad)
            return bad;
        noctWorldDef *def = noctSceneDef(scene);
        if (noctSceneBuild(scene, &w, &err) != NOCT_OK) {
            tool_error("%s", err.message);
            noctSceneDestroy(scene);
            return 2;
        }
        for (long s = 1; s <= steps && status == 0; ++s)
            if (noctWorldStep(w, &err) != NOCT_OK) {
                tool_error("step %ld: %s", s, err.message);
                status = 1;
            }
        bp = noctWorldBroadphase(w);
        objects = noctWorldObjectCount(w);
        source = sa.family ? sa.family : sa.file;
        auto_N = def->N == NOCT_AUTO;
        auto_depth = def->max_depth == NOCT_AUTO;
    }
    /* the settings in force, and whether the world or broadphase chose them */
    int N, depth;
    noctBroadphaseGetSettings(bp, &N, &depth);
    char title[256], nb[16], when[32] = "";
    snprintf(nb, sizeof nb, "%d", N);
    if (w != NULL)
        snprintf(when, sizeof when, ", step %ld", steps);
    snprintf(title, sizeof title, "%s%s, N = %s%s, max depth %d%s%s", source,
             w != NULL ? "" : " (broadphase)", N == NOCT_N_EXHAUSTIVE ? "big" : nb,
             auto_N ? " (auto)" : "", depth, auto_depth ? " (auto)" : "", when);
    if (status == 0 && text) {
        if (w != NULL)
            printf("# %s: %zu objects; each line: child type, generation: cube (low corner, "
                   "edge) and a leaf's objects\n", title, objects);
        else
            printf("# %s: %zu boxes; each line: child type, generation: cube (low corner, "
                   "edge) and a leaf's objects (boxes, from 0 in the file's order)\n",
                   title, objects);
        if (!octPrint(noctBroadphaseRoot(bp), noctBroadphasePrintCell, stdout) ||
            fflush(stdout) != 0) {
            tool_error("write error on stdout");
            status = 1;
        }
    }
    if (status == 0 && dot && !write_dot(dot, bp, title))
        status = 1;
    if (status == 0 && svg && !write_svg(svg, bp, axis, at, opt_slice != NULL, title))
        status = 1;
    noctWorldDestroy(w);
    noctSceneDestroy(scene);
    noctBroadphaseDestroy(own);
    return status;
}
