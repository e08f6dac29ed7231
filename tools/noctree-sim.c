/* SPDX-License-Identifier: MIT */
/*
 * noctree-sim: run a scene (a file, or a built-in family) in the collision
 * world and report its contact events, the pairs colliding at each step or
 * the first collision, and where the time went.
 * See noctree-sim(1) and noctree-scene(5).
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <noctree.h>

#include "toolutil.h"

static const char usage[] =
    "usage: noctree-sim [OPTIONS] SCENE-FILE\n"
    "       noctree-sim [OPTIONS] --scene FAMILY\n"
    "Run a scene in the libnoctree collision world.\n"
    "\n"
    "  --scene FAMILY        a built-in scene: planes:K (the report's t_K), gas:N,\n"
    "                        mixed:N, clusters:N, static:N, escape:N, notch:N,\n"
    "                        bullets:N (thin fast objects that pass through\n"
    "                        others between steps), arms:K (two arms of K links\n"
    "                        in a bay) or keyframes:N\n"
    "  --N N|big|auto        most objects per octree leaf (big: exhaustive; auto,\n"
    "                        the default: chosen from the scene)\n"
    "  --max-depth D|auto    deepest octree level, 1 to 40 (default auto)\n"
    "  --accuracy LEVEL      box, convex, exact or continuous\n"
    "  --maintenance MODE    incremental or rebuild\n"
    "  --steps S             number of steps\n"
    "  --substep             split steps so fast objects cannot pass through others\n"
    "  --margin D            also find the pairs within distance D (near pairs;\n"
    "                        objects' own margins add to it)\n"
    "  --events              print every contact event: STEP begin|end A B\n"
    "  --contacts            print the colliding pairs' contacts after every step:\n"
    "                        STEP contact A B KIND depth D normal X Y Z, then its\n"
    "                        points as STEP point X Y Z DEPTH\n"
    "                        (sensor-begin|sensor-end for sensors, and\n"
    "                        near-begin|near-end with a margin); objects by\n"
    "                        name when the scene names them, else by index\n"
    "  --distance A B        print the distance between objects A and B (names\n"
    "                        or indices) at the start and after every step:\n"
    "                        STEP distance A B D [LOWER, UPPER] and the nearest\n"
    "                        points, or 'colliding'\n"
    "  --near-distances      with --report table or csv and with --events, give\n"
    "                        each near pair's distance\n"
    "  --report FORMAT       the colliding pairs after every step: table, csv or\n"
    "                        gnuplot (a script plotting them against the step)\n"
    "  --output FILE         write the report to FILE, not standard output\n"
    "  --first               stop at the first step with a colliding pair and say\n"
    "                        which objects and their bounding boxes' intersection\n"
    "  --ignore-initial      ignore the pairs colliding at the start (resting\n"
    "                        contact): events, reports and --first see only the\n"
    "                        contacts that begin later\n"
    "  --write-scene FILE    write the scene, with the options above applied, as a\n"
    "                        scene file (- for standard output) and run nothing\n"
    "  --quiet               no progress bar\n"
    "  --help                this text\n"
    "  --version             the version\n"
    "\n"
    "Exit status: 0 on success (with --first, whether or not a pair collided),\n"
    "1 if the simulation failed or the report could not be written, 2 for bad\n"
    "usage or input.\n";

/*
 * --report: after every step, the world's colliding pairs (noctWorldColliding(),
 * objects by index, in its order), kind "collide", and with a margin the
 * pairs within it (noctWorldNear()), kind "near".
 */
typedef enum report_format { REPORT_NONE, REPORT_TABLE, REPORT_CSV, REPORT_GNUPLOT } report_format;

static const char *const report_names[] = {"", "table", "csv", "gnuplot"};

static const char kind_collide[] = "collide";
static const char kind_near[] = "near";

/* The distances (--distance, --near-distances): noctDistance() on the
 * objects' meshes, a box primitive's made once from its half-extents. */
typedef struct distances {
    noctWorld *w;
    noctMesh **box; /* per object index, made when first needed */
    size_t n;
} distances;

/* The distance between objects a and b as they are now; false (said) on
 * failure. */
static bool distance_of(distances *d, noctObjectId a, noctObjectId b, noctDistanceResult *r)
{
    const noctMesh *m[2];
    noctTransform x[2];
    const noctObjectId id[2] = {a, b};
    noctError err;
    for (int k = 0; k < 2; ++k) {
        if (noctWorldGetTransform(d->w, id[k], &x[k]) != NOCT_OK || id[k].index >= d->n) {
            tool_error("object %u is gone", id[k].index);
            return false;
        }
        m[k] = noctWorldGetMesh(d->w, id[k]);
        if (m[k] == NULL) { /* a box primitive: its box as a mesh, once */
            noctMesh **box = &d->box[id[k].index];
            double h[3];
            if (*box == NULL && (noctWorldGetHalfExtents(d->w, id[k], h) != NOCT_OK ||
                                 noctMeshCreateBox(h[0], h[1], h[2], box, &err) != NOCT_OK)) {
                tool_error("object %u: no box mesh: %s", id[k].index, err.message);
                return false;
            }
            m[k] = *box;
        }
    }
    if (noctDistance(m[0], &x[0], m[1], &x[1], INFINITY, r, NULL, &err) != NOCT_OK) {
        tool_error("distance between objects %u and %u: %s", a.index, b.index, err.message);
        return false;
    }
    return true;
}

/* An object as the output names it: its name in the scene, else its
 * index. */
static const char *label(const noctScene *scene, uint32_t index, char buf[24])
{
    const char *name = noctSceneObjectName(scene, index);
    if (name != NULL)
        return name;
    snprintf(buf, 24, "%u", index);
    return buf;
}

typedef struct report {
    report_format format;
    FILE *out;
    const char *path; /* --output, or NULL for standard output */
    size_t most;      /* gnuplot: the most pairs at one step */
    int steps;        /* gnuplot: the steps written */
    bool near;        /* a margin: near pairs too */
    const noctScene *scene; /* the objects' names */
    distances *dist;  /* --near-distances: the near pairs' distances */
    bool failed;      /* a distance could not be had */
} report;

/* Write PREFIX and S in single quotes for gnuplot, which substitutes nothing
 * inside them ('' is a quote); control characters, which they cannot hold,
 * as '?'. PREFIX is the program's own text, S a name it was given. */
static void gnuplot_quote(FILE *f, const char *prefix, const char *s)
{
    fputc('\'', f);
    fputs(prefix, f);
    for (; *s != '\0'; ++s)
        if (*s == '\'')
            fputs("''", f);
        else
            fputc((unsigned char)*s < 0x20 || *s == 0x7f ? '?' : *s, f);
    fputc('\'', f);
}

/* The header of the report; svg is the plot's file for gnuplot, or NULL
 * for standard output. */
static void report_begin(report *r, const char *scene, const char *svg)
{
    switch (r->format) {
    case REPORT_NONE:
        break;
    case REPORT_TABLE:
        fprintf(r->out, "%8s  %-7s  %5s  %s\n", "step", "kind", "count", "pairs");
        break;
    case REPORT_CSV:
        fputs(r->dist != NULL ? "step,kind,a,b,distance\n" : "step,kind,a,b\n", r->out);
        break;
    case REPORT_GNUPLOT:
        fputs("# noctree-sim --report gnuplot: the colliding pairs after each step.\n", r->out);
        if (svg != NULL) {
            fputs("# Run it with gnuplot; it draws the plot in SVG to ", r->out);
            gnuplot_quote(r->out, "", svg);
            fputs(".\n", r->out);
        } else {
            fputs("# Run it with gnuplot; it writes the plot in SVG to standard output.\n",
                  r->out);
        }
        fputs("set terminal svg size 800,480 dynamic font 'sans,12'\n", r->out);
        if (svg != NULL) {
            fputs("set output ", r->out);
            gnuplot_quote(r->out, "", svg);
            fputc('\n', r->out);
        }
        fputs("set title ", r->out);
        gnuplot_quote(r->out, "colliding pairs per step: ", scene);
        fputs(" noenhanced\nset xlabel 'step'\nset ylabel 'colliding pairs'\n"
              "set grid\nset key top right\n"
              "# one row a step: the step, then its pairs of each kind\n"
              "$data << EOD\n",
              r->out);
        fputs(r->near ? "# step collide near\n" : "# step collide\n", r->out);
        break;
    }
}

/* A near pair's distance for the report (its value), or "" when not
 * asked for (or, said, when it could not be had). */
static const char *near_distance(report *r, noctPair p, char buf[32])
{
    noctDistanceResult d;
    buf[0] = '\0';
    if (r->dist == NULL)
        return buf;
    if (!distance_of(r->dist, p.a, p.b, &d)) {
        r->failed = true;
        return buf;
    }
    return tool_format_double(d.distance, buf);
}

static void table_line(report *r, int s, const char *kind, const noctPair *p, size_t n)
{
    if (n == 0)
        return;
    fprintf(r->out, "%8d  %-7s  %5zu ", s, kind, n);
    for (size_t i = 0; i < n; ++i) {
        char a[24], b[24], d[32];
        fprintf(r->out, " %s-%s", label(r->scene, p[i].a.index, a),
                label(r->scene, p[i].b.index, b));
        if (kind == kind_near && r->dist != NULL)
            fprintf(r->out, "(%s)", near_distance(r, p[i], d));
    }
    fputc('\n', r->out);
}

static void csv_lines(report *r, int s, const char *kind, const noctPair *p, size_t n)
{
    for (size_t i = 0; i < n; ++i) {
        char a[24], b[24], d[32];
        fprintf(r->out, "%d,%s,%s,%s", s, kind, label(r->scene, p[i].a.index, a),
                label(r->scene, p[i].b.index, b));
        if (r->dist != NULL)
            fprintf(r->out, ",%s", kind == kind_near ? near_distance(r, p[i], d) : "");
        fputc('\n', r->out);
    }
}

/* The n pairs p colliding after step s, and the nn pairs q near. */
static void report_step(report *r, int s, const noctPair *p, size_t n, const noctPair *q,
                        size_t nn)
{
    switch (r->format) {
    case REPORT_NONE:
        break;
    case REPORT_TABLE:
        table_line(r, s, kind_collide, p, n);
        table_line(r, s, kind_near, q, nn);
        break;
    case REPORT_CSV:
        csv_lines(r, s, kind_collide, p, n);
        csv_lines(r, s, kind_near, q, nn);
        break;
    case REPORT_GNUPLOT:
        if (r->near)
            fprintf(r->out, "%d %zu %zu\n", s, n, nn);
        else
            fprintf(r->out, "%d %zu\n", s, n);
        if (n > r->most)
            r->most = n;
        if (nn > r->most)
            r->most = nn;
        r->steps = s;
        break;
    }
}

/* The end of the report: gnuplot's plot of the rows written. */
static void report_end(report *r)
{
    if (r->format != REPORT_GNUPLOT)
        return;
    /* Fixed ranges, so that a run of one step or without a collision
     * draws without gnuplot's warnings about an empty range; whole ticks. */
    fprintf(r->out, "EOD\nset xrange [0:%d]\nset yrange [0:%zu]\n", r->steps > 0 ? r->steps : 1,
            r->most + 1);
    if (r->most < 10)
        fputs("set ytics 1\n", r->out);
    fputs("plot $data using 1:2 with steps linewidth 2 title 'colliding pairs'", r->out);
    if (r->near)
        fputs(", \\\n     $data using 1:3 with steps linewidth 2 dashtype 2 title 'pairs within "
              "the margin'",
              r->out);
    fputc('\n', r->out);
}

static int pair_order(const void *x, const void *y)
{
    const noctPair *a = x, *b = y;
    if (a->a.index != b->a.index)
        return a->a.index < b->a.index ? -1 : 1;
    return (a->b.index > b->b.index) - (a->b.index < b->b.index);
}

/* With sub-steps, a pair can meet and part within one step: it is in the
 * step's began list but not in its colliding list, the last sub-step's,
 * which is all that --report and --first see. Find the first such pair. */
static bool parted_within(const noctPair *began, size_t nb, const noctPair *col, size_t nc,
                          noctPair *pair)
{
    for (size_t i = 0; i < nb; ++i)
        if (nc == 0 || bsearch(&began[i], col, nc, sizeof *col, pair_order) == NULL) {
            *pair = began[i];
            return true;
        }
    return false;
}

/* --contacts: the contact of each colliding pair after step s
 * (noctWorldContacts()), a line each and a line per point. */
static bool print_contacts(FILE *out, noctWorld *w, int s, const noctScene *scene,
                           noctError *err)
{
    static const char *const kinds[] = {"none", "convex", "crossing", "contained"};
    const noctPair *p;
    const noctContact *c;
    size_t n;
    noctWorldColliding(w, &p);
    if (noctWorldContacts(w, &c, &n, err) != NOCT_OK)
        return false;
    for (size_t i = 0; i < n; ++i) {
        char d[32], x[32], y[32], z[32], la[24], lb[24];
        fprintf(out, "%d contact %s %s %s depth %s normal %s %s %s\n", s,
                label(scene, p[i].a.index, la), label(scene, p[i].b.index, lb),
                kinds[c[i].kind], tool_format_double(c[i].depth, d),
                tool_format_double(c[i].normal[0], x), tool_format_double(c[i].normal[1], y),
                tool_format_double(c[i].normal[2], z));
        for (unsigned k = 0; k < c[i].count; ++k)
            fprintf(out, "%d point %s %s %s %s\n", s, tool_format_double(c[i].points[k][0], x),
                    tool_format_double(c[i].points[k][1], y),
                    tool_format_double(c[i].points[k][2], z),
                    tool_format_double(c[i].point_depth[k], d));
    }
    return true;
}

/* --first: the line for the first pair colliding after step s, with its
 * contact box, the intersection of the objects' placed bounding boxes. */
static bool print_first(const noctWorld *w, const noctScene *scene, int s, noctPair pair)
{
    double alo[3], ahi[3], blo[3], bhi[3], lo[3], hi[3];
    if (noctWorldObjectBox(w, pair.a, alo, ahi) != NOCT_OK ||
        noctWorldObjectBox(w, pair.b, blo, bhi) != NOCT_OK) {
        tool_error("step %d: no box for the pair %u-%u", s, pair.a.index, pair.b.index);
        return false;
    }
    for (int k = 0; k < 3; ++k) {
        lo[k] = alo[k] > blo[k] ? alo[k] : blo[k];
        hi[k] = ahi[k] < bhi[k] ? ahi[k] : bhi[k];
    }
    char b[6][32], na[24], nb[24];
    printf("first collision at step %d: objects %s and %s, contact box (%s, %s, %s) "
           "(%s, %s, %s)\n",
           s, label(scene, pair.a.index, na), label(scene, pair.b.index, nb),
           tool_format_double(lo[0], b[0]),
           tool_format_double(lo[1], b[1]), tool_format_double(lo[2], b[2]),
           tool_format_double(hi[0], b[3]), tool_format_double(hi[1], b[4]),
           tool_format_double(hi[2], b[5]));
    return true;
}

/* --first with continuous detection: the pair that touched first within
 * step s, when and where (noctWorldBeganHits()). */
static void print_first_time(const noctScene *scene, int s, const noctPair *began,
                             const noctSweepHit *hits, size_t n)
{
    size_t best = 0;
    for (size_t i = 1; i < n; ++i)
        if (hits[i].time < hits[best].time)
            best = i;
    const noctSweepHit *h = &hits[best];
    char b[4][32], na[24], nb[24];
    printf("first collision at step %d, time %s of the step: objects %s and %s, "
           "touching at (%s, %s, %s)\n",
           s, tool_format_double(h->time, b[0]), label(scene, began[best].a.index, na),
           label(scene, began[best].b.index, nb),
           tool_format_double(h->point[0], b[1]), tool_format_double(h->point[1], b[2]),
           tool_format_double(h->point[2], b[3]));
}

/* --events: the n pairs p of an event kind after step s, each with its
 * distance when dist is not NULL (--near-distances); false if a distance
 * could not be had. */
static bool print_events(FILE *f, int s, const char *kind, const noctPair *p, size_t n,
                         const noctScene *scene, distances *dist)
{
    for (size_t i = 0; i < n; ++i) {
        char a[24], b[24], d[32];
        fprintf(f, "%d %s %s %s", s, kind, label(scene, p[i].a.index, a),
                label(scene, p[i].b.index, b));
        if (dist != NULL) {
            noctDistanceResult r;
            if (!distance_of(dist, p[i].a, p[i].b, &r))
                return false;
            fprintf(f, " distance %s", tool_format_double(r.distance, d));
        }
        fputc('\n', f);
    }
    return true;
}

/* --distance: the line for objects a and b after step s (0: the start). */
static bool print_distance(FILE *f, int s, distances *dist, const noctScene *scene,
                           noctObjectId a, noctObjectId b)
{
    noctDistanceResult r;
    if (!distance_of(dist, a, b, &r))
        return false;
    char na[24], nb[24], v[9][32];
    fprintf(f, "%d distance %s %s %s [%s, %s]", s, label(scene, a.index, na),
            label(scene, b.index, nb), tool_format_double(r.distance, v[0]),
            tool_format_double(r.lower, v[1]), tool_format_double(r.upper, v[2]));
    if (r.colliding)
        fputs(" colliding\n", f);
    else
        fprintf(f, " points (%s, %s, %s) (%s, %s, %s)\n", tool_format_double(r.point_a[0], v[3]),
                tool_format_double(r.point_a[1], v[4]), tool_format_double(r.point_a[2], v[5]),
                tool_format_double(r.point_b[0], v[6]), tool_format_double(r.point_b[1], v[7]),
                tool_format_double(r.point_b[2], v[8]));
    return true;
}

/* The handles of the objects of a world just built, by index (id may be
 * NULL: only any_margin wanted), and whether any has a margin of its own. */
typedef struct handles {
    noctObjectId *id;
    size_t n;
    const noctWorld *w;
    bool any_margin;
} handles;

static void find_handles(handles *h)
{
    for (size_t i = 0; i < h->n && i <= UINT32_MAX; ++i) {
        noctObjectId id;
        double m = 0;
        if (noctWorldObjectAt(h->w, (uint32_t)i, &id) != NOCT_OK)
            continue;
        if (h->id != NULL)
            h->id[i] = id;
        if (noctWorldGetMargin(h->w, id, &m) == NOCT_OK && m > 0)
            h->any_margin = true;
    }
}

/* An object named on the command line: its name, or its index. */
static bool resolve_object(const noctScene *scene, const char *arg, size_t *index)
{
    if (noctSceneFindObject(scene, arg, index))
        return true;
    long v;
    const size_t n = noctSceneObjectCount(scene);
    if (n > 0 && tool_parse_long(arg, 0, n - 1 < 0x7fffffff ? (long)(n - 1) : 0x7fffffff, &v)) {
        *index = (size_t)v;
        return true;
    }
    return false;
}

int main(int argc, char **argv)
{
    tool_scene_args sa = {0};
    const char *opt_acc = NULL,
               *opt_maint = NULL;
    long steps = 0;
    bool events = false, quiet = false, substep = false, first = false, contacts = false;
    bool near_distances = false, ignore_initial = false;
    const char *dist_arg[2] = {NULL, NULL}; /* --distance A B */
    const char *write_scene = NULL;
    double margin = -1; /* --margin, if given */
    report rep = {.format = REPORT_NONE};
    tool_name = "noctree-sim";
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i];
        bool has_value = i + 1 < argc;
        if (tool_help_or_version(a, usage)) {
            return 0;
        } else if (strcmp(a, "--events") == 0) {
            events = true;
        } else if (strcmp(a, "--contacts") == 0) {
            contacts = true;
        } else if (strcmp(a, "--quiet") == 0) {
            quiet = true;
        } else if (strcmp(a, "--substep") == 0) {
            substep = true;
        } else if (strcmp(a, "--first") == 0) {
            first = true;
        } else if (strcmp(a, "--ignore-initial") == 0) {
            ignore_initial = true;
        } else if (strcmp(a, "--near-distances") == 0) {
            near_distances = true;
        } else if (strcmp(a, "--distance") == 0 && i + 2 < argc) {
            dist_arg[0] = argv[++i];
            dist_arg[1] = argv[++i];
        } else if (strcmp(a, "--report") == 0 && has_value) {
            const char *f = argv[++i];
            rep.format = REPORT_NONE;
            for (int k = REPORT_TABLE; k <= REPORT_GNUPLOT; ++k)
                if (strcmp(f, report_names[k]) == 0)
                    rep.format = (report_format)k;
            if (rep.format == REPORT_NONE)
                return tool_usage_error("--report must be table, csv or gnuplot, not '%s'", f);
        } else if (strcmp(a, "--output") == 0 && has_value) {
            rep.path = argv[++i];
        } else if (strcmp(a, "--margin") == 0 && has_value) {
            char *end;
            margin = strtod(argv[++i], &end);
            if (end == argv[i] || *end != '\0' || !(margin >= 0 && margin <= 1e100))
                return tool_usage_error("--margin must be a distance from 0 to 1e100, not '%s'",
                                        argv[i]);
        } else if (strcmp(a, "--write-scene") == 0 && has_value) {
            write_scene = argv[++i];
        } else if (strcmp(a, "--accuracy") == 0 && has_value) {
            opt_acc = argv[++i];
        } else if (strcmp(a, "--maintenance") == 0 && has_value) {
            opt_maint = argv[++i];
        } else if (strcmp(a, "--steps") == 0 && has_value) {
            if (!tool_parse_long(argv[++i], 1, 10000000, &steps))
                return tool_usage_error("--steps must be 1 to 10000000, not '%s'", argv[i]);
        } else {
            int took = tool_scene_arg(&sa, argc, argv, &i);
            if (took < 0)
                return 2;
            if (took == 0)
                return tool_usage_error("unknown option or missing value: '%s'", a);
        }
    }

    if (first && rep.format != REPORT_NONE)
        return tool_usage_error("--first and --report cannot be combined");
    if (rep.path != NULL && rep.format == REPORT_NONE)
        return tool_usage_error("--output needs --report");
    if (near_distances && rep.format == REPORT_GNUPLOT)
        return tool_usage_error("--near-distances needs --report table or csv (or --events), "
                                "not gnuplot");
    if (near_distances && rep.format == REPORT_NONE && !events)
        return tool_usage_error("--near-distances needs --report table or csv, or --events");
    /* The gnuplot script draws its plot in the --output name with .svg for
     * its extension: that must be another file, and a name gnuplot can hold. */
    if (rep.format == REPORT_GNUPLOT && rep.path != NULL) {
        for (const char *c = rep.path; *c != '\0'; ++c)
            if ((unsigned char)*c < 0x20 || *c == 0x7f)
                return tool_usage_error("--output: a gnuplot script cannot name a plot file "
                                        "holding a control character");
        char *svg = tool_with_extension(rep.path, ".svg");
        if (svg == NULL)
            return tool_error("out of memory"), 1;
        bool itself = strcmp(svg, rep.path) == 0;
        free(svg);
        if (itself)
            return tool_usage_error("--output '%s': the script would draw its plot over "
                                    "itself; give it another extension, such as .gp",
                                    rep.path);
    }

    noctScene *scene;
    noctError err;
    int bad = tool_scene_load(&sa, &scene);
    if (bad)
        return bad;
    size_t dist_index[2] = {0, 0};
    for (int k = 0; k < 2 && dist_arg[0] != NULL; ++k)
        if (!resolve_object(scene, dist_arg[k], &dist_index[k])) {
            const size_t n = noctSceneObjectCount(scene);
            noctSceneDestroy(scene);
            return tool_usage_error("--distance: no object '%s' (a name in the scene, or an "
                                    "index below its %zu objects)",
                                    dist_arg[k], n);
        }
    noctWorldDef *def = noctSceneDef(scene);
    if (opt_acc != NULL && !tool_parse_accuracy(opt_acc, &def->accuracy))
        return noctSceneDestroy(scene), tool_usage_error("--accuracy must be box, convex, exact or continuous, not '%s'", opt_acc);
    if (opt_maint != NULL) {
        if (strcmp(opt_maint, "incremental") == 0)
            def->maintenance = NOCT_MAINTAIN_INCREMENTAL;
        else if (strcmp(opt_maint, "rebuild") == 0)
            def->maintenance = NOCT_MAINTAIN_REBUILD;
        else
            return noctSceneDestroy(scene), tool_usage_error("--maintenance must be incremental or rebuild, not '%s'", opt_maint);
    }
    if (substep)
        def->effects |= NOCT_EFFECT_SUBSTEP;
    if (ignore_initial)
        noctSceneSetIgnoreInitial(scene, true);
    if (margin >= 0)
        def->margin = margin;
    int nsteps = steps > 0 ? (int)steps : noctSceneSteps(scene);
    if (write_scene != NULL) {
        const bool to_stdout = strcmp(write_scene, "-") == 0;
        FILE *f = to_stdout ? stdout : fopen(write_scene, "w");
        if (f == NULL) {
            tool_error("%s: cannot open: %s", write_scene, strerror(errno));
            noctSceneDestroy(scene);
            return 2;
        }
        noctStatus st = noctSceneWrite(scene, f, &err);
        if ((!to_stdout && fclose(f) != 0 && st == NOCT_OK) ||
            (to_stdout && fflush(stdout) != 0 && st == NOCT_OK)) {
            st = NOCT_ERR_IO;
            snprintf(err.message, sizeof err.message, "writing the scene: %s",
                     strerror(errno));
        }
        if (st != NOCT_OK)
            tool_error("%s: %s", write_scene, err.message);
        noctSceneDestroy(scene);
        return st == NOCT_OK ? 0 : 1;
    }

    noctWorld *w;
    if (noctSceneBuild(scene, &w, &err) != NOCT_OK) {
        tool_error("%s", err.message);
        noctSceneDestroy(scene);
        return 2;
    }
    /* near pairs: the world's margin, or an object's own */
    const size_t nobjects = noctSceneObjectCount(scene);
    handles hs = {NULL, nobjects, w, false};
    if (dist_arg[0] != NULL && (hs.id = calloc(nobjects, sizeof *hs.id)) == NULL) {
        tool_error("out of memory");
        noctWorldDestroy(w);
        noctSceneDestroy(scene);
        return 1;
    }
    find_handles(&hs);
    rep.near = def->margin > 0 || hs.any_margin;
    rep.scene = scene;
    distances dist = {w, NULL, nobjects};
    if ((dist_arg[0] != NULL || near_distances) &&
        (dist.box = calloc(nobjects > 0 ? nobjects : 1, sizeof *dist.box)) == NULL) {
        tool_error("out of memory");
        free(hs.id);
        noctWorldDestroy(w);
        noctSceneDestroy(scene);
        return 1;
    }
    distances *near_dist = near_distances ? &dist : NULL;
    rep.dist = near_dist;
    noctObjectId dist_id[2] = {{0, 0}, {0, 0}};
    if (dist_arg[0] != NULL) {
        dist_id[0] = hs.id[dist_index[0]];
        dist_id[1] = hs.id[dist_index[1]];
    }
    free(hs.id);
    double ratio = noctWorldMaxStepRatio(w);
    const bool continuous = def->accuracy == NOCT_ACCURACY_CONTINUOUS;
    if (ratio > 0.5 && !(def->effects & NOCT_EFFECT_SUBSTEP) && !continuous)
        tool_error("warning: an object moves %.2f times its smallest "
                "size per step; objects can pass through each other unseen (the "
                "report's fidelity constraint): use --accuracy continuous or --substep",
                ratio);
    /* The report goes to --output or standard output; in the second case
     * the events and the summary go to standard error, so that standard
     * output holds only the report. */
    FILE *info = stdout;
    rep.out = stdout;
    if (rep.format != REPORT_NONE) {
        char *svg = NULL;
        if (rep.path != NULL) {
            if (rep.format == REPORT_GNUPLOT &&
                (svg = tool_with_extension(rep.path, ".svg")) == NULL) {
                tool_error("out of memory");
                noctWorldDestroy(w);
                noctSceneDestroy(scene);
                return 1;
            }
            rep.out = fopen(rep.path, "w");
            if (rep.out == NULL) {
                tool_error("cannot open '%s' for writing: %s", rep.path, strerror(errno));
                free(svg);
                noctWorldDestroy(w);
                noctSceneDestroy(scene);
                return 2;
            }
        } else {
            info = stderr;
        }
        report_begin(&rep, sa.family != NULL ? sa.family : sa.file, svg);
        free(svg);
    }
    bool bar = !quiet && !events && !contacts && dist_arg[0] == NULL && isatty(STDERR_FILENO);
    size_t begins = 0, ends = 0, sensor_events = 0, near_events[2] = {0, 0};
    int status = 0, stopped = 0;
    bool told_parted = false;
    if (dist_arg[0] != NULL && !print_distance(info, 0, &dist, scene, dist_id[0], dist_id[1]))
        status = 1;
    for (int s = 1; s <= nsteps && status == 0; ++s) {
        if (noctWorldStep(w, &err) != NOCT_OK) {
            tool_progress_end();
            tool_error("step %d: %s", s, err.message);
            status = 1;
            break;
        }
        const noctPair *p, *began;
        size_t nbegan = noctWorldBegan(w, &began);
        begins += nbegan;
        const noctSweepHit *hits = NULL;
        size_t nhits = 0;
        /* with continuous detection (the world's, or an object's) */
        if (nbegan > 0 && (events || first) &&
            noctWorldBeganHits(w, &hits, &nhits, &err) != NOCT_OK) {
            tool_progress_end();
            tool_error("step %d: %s", s, err.message);
            status = 1;
            break;
        }
        for (size_t i = 0; events && i < nbegan; ++i) {
            char la[24], lb[24];
            fprintf(info, "%d begin %s %s", s, label(scene, began[i].a.index, la),
                    label(scene, began[i].b.index, lb));
            if (i < nhits) {
                char t[32];
                fprintf(info, " at %s%s", tool_format_double(hits[i].time, t),
                        hits[i].conservative ? " near" : "");
            }
            fputc('\n', info);
        }
        size_t ne = noctWorldEnded(w, &p);
        ends += ne;
        if (events)
            print_events(info, s, "end", p, ne, scene, NULL);
        size_t nb = noctWorldSensorBegan(w, &p);
        sensor_events += nb;
        if (events)
            print_events(info, s, "sensor-begin", p, nb, scene, NULL);
        ne = noctWorldSensorEnded(w, &p);
        sensor_events += ne;
        if (events)
            print_events(info, s, "sensor-end", p, ne, scene, NULL);
        nb = noctWorldNearBegan(w, &p);
        near_events[0] += nb;
        if (events && !print_events(info, s, "near-begin", p, nb, scene, near_dist))
            status = 1;
        ne = noctWorldNearEnded(w, &p);
        near_events[1] += ne;
        if (events && status == 0 && !print_events(info, s, "near-end", p, ne, scene, near_dist))
            status = 1;
        if (dist_arg[0] != NULL && status == 0 &&
            !print_distance(info, s, &dist, scene, dist_id[0], dist_id[1]))
            status = 1;
        if (status != 0) {
            tool_progress_end();
            break;
        }
        if (contacts && !print_contacts(info, w, s, scene, &err)) {
            tool_progress_end();
            tool_error("step %d: %s", s, err.message);
            status = 1;
            break;
        }
        if (rep.format != REPORT_NONE || first) {
            size_t nc = noctWorldColliding(w, &p);
            noctPair gone;
            if (!told_parted && parted_within(began, nbegan, p, nc, &gone)) {
                tool_progress_end();
                char la[24], lb[24];
                tool_error("warning: step %d: objects %s and %s met and parted within the "
                           "step's sub-steps; %s only the pairs colliding at the end of a step",
                           s, label(scene, gone.a.index, la), label(scene, gone.b.index, lb),
                           first ? "--first sees" : "the report lists");
                told_parted = true;
            }
            const noctPair *q;
            const size_t nn = noctWorldNear(w, &q);
            report_step(&rep, s, p, nc, q, nn);
            if (rep.failed) {
                tool_progress_end();
                status = 1;
                break;
            }
            if (first && nc > 0) {
                tool_progress_end();
                if (nhits > 0)
                    print_first_time(scene, s, began, hits, nhits);
                else if (!print_first(w, scene, s, p[0]))
                    status = 1;
                stopped = s;
                break;
            }
        }
        if (s % 5 == 0 || s == nsteps) {
            char label[48];
            snprintf(label, sizeof label, "step %d/%d", s, nsteps);
            tool_progress(bar, s, nsteps, label);
        }
    }
    report_end(&rep);
    if (rep.out != stdout) {
        if (fclose(rep.out) != 0) {
            tool_error("cannot write '%s': %s", rep.path, strerror(errno));
            status = 1;
        }
    } else if (rep.format != REPORT_NONE && (fflush(stdout) != 0 || ferror(stdout))) {
        tool_error("cannot write the report: %s", strerror(errno));
        status = 1;
    }
    if (status == 0 && first) {
        if (stopped == 0)
            printf("no collision in %d steps\n", nsteps);
    } else if (status == 0) {
        noctWorldCounters c;
        noctWorldGetCounters(w, &c);
        const noctPair *p;
        double total = c.seconds_motion + c.seconds_maintenance + c.seconds_pairs +
                       c.seconds_response;
        fprintf(info, "objects %zu\nsteps %d\nN %s%.0d\naccuracy %s\n",
                noctWorldObjectCount(w), nsteps, def->N == NOCT_N_EXHAUSTIVE ? "big" : "",
                def->N == NOCT_N_EXHAUSTIVE ? 0 : def->N, noctAccuracyName(def->accuracy));
        fprintf(info, "contact begins %zu\ncontact ends %zu\ncolliding at the end %zu\n",
                begins, ends, noctWorldColliding(w, &p));
        if (sensor_events > 0 || noctWorldSensing(w, &p) > 0)
            fprintf(info, "sensor events %zu\nsensing at the end %zu\n", sensor_events,
                    noctWorldSensing(w, &p));
        if (rep.near)
            fprintf(info, "margin %s\nnear begins %zu\nnear ends %zu\nnear at the end %zu\n",
                    tool_format_double(def->margin, (char[32]){0}), near_events[0],
                    near_events[1], noctWorldNear(w, &p));
        double levels = c.narrow.seconds_convex + c.narrow.seconds_exact;
        fprintf(info, "time per step %.3f ms (motion %.3f, maintenance %.3f, pair search and "
                "box tests %.3f, convex level %.3f, exact level %.3f, events and "
                "response %.3f)\n",
                1e3 * total / nsteps, 1e3 * c.seconds_motion / nsteps,
                1e3 * c.seconds_maintenance / nsteps,
                1e3 * (c.seconds_pairs - levels) / nsteps,
                1e3 * c.narrow.seconds_convex / nsteps, 1e3 * c.narrow.seconds_exact / nsteps,
                1e3 * c.seconds_response / nsteps);
        fprintf(info, "per step: %.1f candidate pairs, %.1f tested, %.1f colliding; %.1f "
                "neighbor queries, %.2f splits, %.2f merges\n",
                (double)c.candidate_pairs / nsteps, (double)c.tested_pairs / nsteps,
                (double)c.colliding_pairs / nsteps, (double)c.neighbor_queries / nsteps,
                (double)c.splits / nsteps, (double)c.merges / nsteps);
    }
    for (size_t i = 0; dist.box != NULL && i < nobjects; ++i)
        noctMeshDestroy(dist.box[i]);
    free(dist.box);
    noctWorldDestroy(w);
    noctSceneDestroy(scene);
    return status;
}
