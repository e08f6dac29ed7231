/* SPDX-License-Identifier: MIT */
/*
 * noctree-bench: the report's timing experiment (its Table 1, Figures 9
 * and 10) done with repeats and statistics, at scale, with the time of
 * each stage and what accuracy costs. See noctree-bench(1).
 *
 * Runs are interleaved: each repeat visits every configuration of a
 * section once, in a fresh shuffled order, so that drift of the machine
 * (frequency, other load) spreads over all configurations alike instead
 * of biasing the ones that ran last.
 *
 * Statistics. A cell is the median of its repeats. Per scene, the ratio of
 * the exhaustive median to the best N's median gets a 95% percentile
 * bootstrap interval (resampling each configuration's repeats), and a
 * one-sided permutation test of "the exhaustive run is not slower" on the
 * mean log time (exact over all relabellings up to 20 repeats per side,
 * sampled beyond), multiplied by the number of N compared (Bonferroni),
 * because the best N is picked from the same data.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <noctree.h>

#include "benchutil.h"
#include "toolutil.h"

static const char usage[] =
    "usage: noctree-bench [OPTIONS]\n"
    "The report's timing experiment: Table 1 with statistics, at scale, where\n"
    "the time goes and what accuracy costs. Tables on stdout, CSV files and\n"
    "plots in the output folder.\n"
    "\n"
    "  --sections LIST   comma-separated: table1, stages, accuracy, scale\n"
    "                    (default table1,stages,accuracy)\n"
    "  --all             every section, scale included (tens of minutes)\n"
    "  --quick           small scenes and few steps, to check the tool runs\n"
    "  --repeats R       runs per configuration (default 5; 3 at scale)\n"
    "  --steps S         steps per run (default 200; 50 at scale)\n"
    "  --budget SEC      most seconds an exhaustive run may take; longer runs\n"
    "                    stop early and are extrapolated (default 10)\n"
    "  --out DIR         folder for CSV files and plots (default noctree-bench-out)\n"
    "  --no-plots        do not run gnuplot\n"
    "  --quiet           no progress bar\n"
    "  --help            this text\n"
    "  --version         the version\n"
    "\n"
    "The accuracy section runs the ladder box, convex, exact, exact k=2, exact\n"
    "k=4, exact k=8 (fixed sub-steps), exact auto k (--substep's) and continuous\n"
    "(the reference) on planes:10, gas:1000, notch:64, bullets:1000 (a tenth\n"
    "of its objects thin and fast: they tunnel) and gas:1000+spin (gas:1000, each\n"
    "object turning 12 degrees a step: there the continuous rung is conservative,\n"
    "missed entries count against it and false ones against exact k=32), then\n"
    "the broadphase's settings on bullets:1000 and continuous against exact on\n"
    "gas:10000.\n"
    "\n"
    "Exit status: 0 on success, 1 if a run failed, 2 for bad usage.\n";

enum { SEC_TABLE1 = 1, SEC_STAGES = 2, SEC_ACCURACY = 4, SEC_SCALE = 8 };

typedef struct options {
    unsigned sections;
    bool quick, plots, bar;
    int repeats, steps;     /* 0: the section's default */
    double budget;
    const char *out;
} options;

static options opt = {SEC_TABLE1 | SEC_STAGES | SEC_ACCURACY, false, true, true, 0, 0,
                      10.0, "noctree-bench-out"};

/* ---- randomness and statistics ------------------------------------------ */

static uint64_t rng_state = 0x6e6f637472656521u;

static uint64_t rng_next(void)
{
    return tool_rand(&rng_state);
}

static size_t rng_below(size_t n)
{
    return (size_t)(rng_next() % n);
}

static void shuffle(size_t *v, size_t n)
{
    for (size_t i = n; i > 1; --i) {
        size_t j = rng_below(i), t = v[i - 1];
        v[i - 1] = v[j];
        v[j] = t;
    }
}

/* The median of v[0 .. n), n at most 64, leaving v as it is. */
static double median(const double *v, size_t n)
{
    double t[64];
    if (n == 0 || n > 64)
        return NAN;
    memcpy(t, v, n * sizeof *t);
    return tool_median(t, n);
}

/* Half the range, relative to the median. */
static double spread(const double *v, size_t n)
{
    double lo = INFINITY, hi = -INFINITY;
    for (size_t i = 0; i < n; ++i) {
        lo = fmin(lo, v[i]);
        hi = fmax(hi, v[i]);
    }
    return 0.5 * (hi - lo) / median(v, n);
}

/* 95% percentile bootstrap interval of median(a) / median(b). */
static void bootstrap_ratio(const double *a, const double *b, size_t n, double ci[2])
{
    enum { B = 4000 };
    static double r[B];
    double ra[64], rb[64];
    for (int k = 0; k < B; ++k) {
        for (size_t i = 0; i < n; ++i) {
            ra[i] = a[rng_below(n)];
            rb[i] = b[rng_below(n)];
        }
        r[k] = median(ra, n) / median(rb, n);
    }
    tool_sort(r, B);
    ci[0] = r[(int)(0.025 * B)];
    ci[1] = r[(int)(0.975 * B) - 1];
}

/*
 * One-sided permutation test of H0 "a and b are exchangeable" against
 * "a is slower": the share of relabellings of the 2n runs whose mean log
 * time difference is at least the observed one.
 */
static double permutation_p(const double *a, const double *b, size_t n)
{
    double all[128], total = 0, observed = 0;
    for (size_t i = 0; i < n; ++i) {
        all[i] = log(a[i]);
        all[n + i] = log(b[i]);
        total += all[i] + all[n + i];
        observed += all[i];
    }
    size_t m = 2 * n, hits = 0, count = 0;
    const double eps = 1e-12 * (fabs(observed) + 1);
    if (m <= 20) {
        /* Every subset of n of the 2n runs labelled "a". */
        for (uint32_t mask = 0; mask < (1u << m); ++mask) {
            if ((size_t)__builtin_popcount(mask) != n)
                continue;
            double s = 0;
            for (size_t i = 0; i < m; ++i)
                if (mask & (1u << i))
                    s += all[i];
            ++count;
            hits += s >= observed - eps;
        }
    } else {
        size_t idx[128];
        for (size_t i = 0; i < m; ++i)
            idx[i] = i;
        for (count = 0; count < 20000; ++count) {
            shuffle(idx, m);
            double s = 0;
            for (size_t i = 0; i < n; ++i)
                s += all[idx[i]];
            hits += s >= observed - eps;
        }
        ++hits, ++count; /* the observed labelling itself */
    }
    (void)total;
    return (double)hits / (double)count;
}

/* ---- scenes and runs ------------------------------------------------------ */

typedef struct scene_world {
    noctWorld *w;
    noctScene *scene;
} scene_world;

static void scene_world_free(scene_world *sw)
{
    noctWorldDestroy(sw->w);
    noctSceneDestroy(sw->scene);
    memset(sw, 0, sizeof *sw);
}

/* Build a family (noctSceneFamily(): planes, gas, notch) with the given N,
 * accuracy and extra effects. */
static noctStatus build(const char *spec, int N, noctAccuracy acc, unsigned effects_on,
                        unsigned effects_off, scene_world *sw, noctError *err)
{
    memset(sw, 0, sizeof *sw);
    noctStatus st;
    if ((st = noctSceneFamily(spec, &sw->scene, err)) != NOCT_OK)
        return st;
    noctWorldDef *def = noctSceneDef(sw->scene);
    def->N = N;
    def->accuracy = acc;
    def->effects = (def->effects | effects_on) & ~effects_off;
    return noctSceneBuild(sw->scene, &sw->w, err);
}

/* A colliding pair at a step, for comparing trajectories. */
typedef struct pair_at {
    uint32_t step, a, b;
} pair_at;

typedef struct pair_log {
    pair_at *p;
    size_t n, cap;
} pair_log;

static bool log_pairs(pair_log *l, uint32_t step, const noctPair *p, size_t n)
{
    if (l->n + n > l->cap) {
        size_t cap = l->cap ? l->cap : 1024;
        while (cap < l->n + n)
            cap *= 2;
        pair_at *q = realloc(l->p, cap * sizeof *q);
        if (q == NULL)
            return false;
        l->p = q;
        l->cap = cap;
    }
    for (size_t i = 0; i < n; ++i)
        l->p[l->n++] = (pair_at){step, p[i].a.index, p[i].b.index};
    return true;
}

static int cmp_pair_at(const pair_at *x, const pair_at *y)
{
    if (x->step != y->step)
        return x->step < y->step ? -1 : 1;
    if (x->a != y->a)
        return x->a < y->a ? -1 : 1;
    return (x->b > y->b) - (x->b < y->b);
}

/* Entries only in x, only in y; the first step where they differ. Both
 * logs are sorted (steps in order, pairs sorted within a step). */
static void log_diff(const pair_log *x, const pair_log *y, size_t *only_x, size_t *only_y,
                     uint32_t *first)
{
    size_t i = 0, j = 0;
    *only_x = *only_y = 0;
    *first = 0;
    while (i < x->n || j < y->n) {
        int c = i == x->n ? 1 : j == y->n ? -1 : cmp_pair_at(&x->p[i], &y->p[j]);
        if (c == 0) {
            ++i, ++j;
            continue;
        }
        uint32_t s = c < 0 ? x->p[i].step : y->p[j].step;
        if (*first == 0 || s < *first)
            *first = s;
        if (c < 0)
            ++*only_x, ++i;
        else
            ++*only_y, ++j;
    }
}

typedef struct run_result {
    double seconds;      /* for all the steps asked (extrapolated if cut) */
    int steps_run;
    bool extrapolated;
    size_t objects, begins;
    noctWorldCounters c;
} run_result;

/*
 * Run one configuration for `steps` steps, timing the step calls only
 * (setup excluded). With budget > 0 the run stops once it has taken
 * longer, and its time is extrapolated. Logs colliding pairs and
 * contact-begin events when asked.
 */
static const char *n_name(int N, char buf[16]);

static bool run(const char *spec, int N, noctAccuracy acc, unsigned on, unsigned off,
                int steps, double budget, run_result *r, pair_log *colliding,
                pair_log *begins)
{
    scene_world sw;
    noctError err;
    memset(r, 0, sizeof *r);
    if (build(spec, N, acc, on, off, &sw, &err) != NOCT_OK) {
        tool_error("%s: %s", spec, err.message);
        scene_world_free(&sw);
        return false;
    }
    r->objects = noctWorldObjectCount(sw.w);
    double elapsed = 0;
    for (int s = 1; s <= steps; ++s) {
        double t0 = tool_now();
        noctStatus st = noctWorldStep(sw.w, &err);
        elapsed += tool_now() - t0;
        if (st != NOCT_OK) {
            tool_error("%s, N %s, step %d: %s", spec, n_name(N, (char[16]){0}), s,
                       err.message);
            scene_world_free(&sw);
            return false;
        }
        const noctPair *p;
        size_t nb = noctWorldBegan(sw.w, &p);
        r->begins += nb;
        if ((begins && !log_pairs(begins, (uint32_t)s, p, nb)) ||
            (colliding && (nb = noctWorldColliding(sw.w, &p),
                           !log_pairs(colliding, (uint32_t)s, p, nb)))) {
            tool_error("out of memory");
            scene_world_free(&sw);
            return false;
        }
        r->steps_run = s;
        if (budget > 0 && elapsed > budget && s < steps) {
            r->extrapolated = true;
            break;
        }
    }
    r->seconds = elapsed * steps / r->steps_run;
    noctWorldGetCounters(sw.w, &r->c);
    scene_world_free(&sw);
    return true;
}

/* ---- output helpers --------------------------------------------------------- */

static FILE *open_out(const char *name)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", opt.out, name);
    FILE *f = fopen(path, "w");
    if (f == NULL)
        tool_error("%s: %s", path, strerror(errno));
    return f;
}

static bool have_gnuplot(void)
{
    static int known = -1;
    if (known < 0)
        known = system("command -v gnuplot >/dev/null 2>&1") == 0;
    return known;
}

/* Run a gnuplot script written to DIR/name.gp, making DIR/name.svg. */
static void plot(const char *name, const char *script)
{
    if (!opt.plots)
        return;
    if (!have_gnuplot()) {
        static bool told;
        if (!told)
            printf("(plots skipped: gnuplot is not installed; the CSV files hold the data)\n");
        told = true;
        return;
    }
    char path[4096], cmd[8400];
    snprintf(path, sizeof path, "%s/%s.gp", opt.out, name);
    FILE *f = fopen(path, "w");
    if (f == NULL) {
        tool_error("%s: %s", path, strerror(errno));
        return;
    }
    fprintf(f, "set terminal svg size 800,560 dynamic font 'sans,13'\n"
               "set output '%s/%s.svg'\nset datafile separator ','\n"
               "set key outside right\nset grid\n%s",
            opt.out, name, script);
    fclose(f);
    snprintf(cmd, sizeof cmd, "gnuplot '%s'", path);
    fflush(stdout);
    if (system(cmd) != 0)
        tool_error("gnuplot failed on %s", path);
    else
        printf("plot: %s/%s.svg\n", opt.out, name);
}

static const char *n_name(int N, char buf[16])
{
    if (N == NOCT_N_EXHAUSTIVE)
        return "big";
    if (N == NOCT_AUTO)
        return "auto";
    snprintf(buf, 16, "%d", N);
    return buf;
}

/* Short label of a scene: t10 for planes:10, as in the report. */
static const char *scene_label(const char *spec, char buf[32])
{
    if (strncmp(spec, "planes:", 7) == 0)
        snprintf(buf, 32, "t%s", spec + 7);
    else
        snprintf(buf, 32, "%s", spec);
    return buf;
}

/* ---- timing sections: Table 1 and the scale table ---------------------------- */

/* The report's N, the defaults (the world's own choice, what users get),
 * and the exhaustive algorithm last. */
static const int NS[] = {5, 10, 30, 50, NOCT_AUTO, NOCT_N_EXHAUSTIVE};
enum { NN = sizeof NS / sizeof *NS, MAX_REPEATS = 64 };

typedef struct timing {
    const char *spec;
    size_t objects;
    double t[NN][MAX_REPEATS];
    bool extrapolated[NN];
    size_t begins[NN];
} timing;

/* The objects of a built-in scene, without building it. */
static size_t scene_objects(const char *spec)
{
    if (strncmp(spec, "planes:", 7) == 0) {
        size_t side = 2 * (size_t)atol(spec + 7) + 1;
        return 2 * side * side;
    }
    if (strncmp(spec, "notch:", 6) == 0)
        return 2 * (size_t)atol(spec + 6);
    return (size_t)atol(spec + 4); /* gas:N */
}

/*
 * The exhaustive algorithm's seconds per object pair and step, measured on
 * t10. One exhaustive step of a large scene can take far longer than the
 * budget (t300 has 2.6e11 pairs), so such a run is not started: its time
 * is this cost times the pairs and steps, reported as extrapolated.
 */
static double exhaustive_pair_cost(void)
{
    static double cost = -1;
    if (cost < 0) {
        run_result r;
        cost = 0;
        if (run("planes:10", NOCT_N_EXHAUSTIVE, NOCT_ACCURACY_EXACT, 0, 0, 50, 0, &r, NULL,
                NULL))
            cost = r.seconds / 50 / (0.5 * (double)r.objects * (double)(r.objects - 1));
    }
    return cost;
}

static bool timing_section(const char *title, const char *csv, const char *const *specs,
                           size_t nspecs, int repeats, int steps, timing *tm)
{
    size_t nruns = nspecs * NN, done = 0, total = nruns * (size_t)repeats;
    size_t *order = malloc(nruns * sizeof *order);
    FILE *f = open_out(csv);
    if (order == NULL || f == NULL) {
        free(order);
        if (f)
            fclose(f);
        return false;
    }
    fprintf(f, "scene,objects,N,repeat,steps,seconds,extrapolated,steps_run,begins\n");
    for (size_t i = 0; i < nspecs; ++i) {
        memset(&tm[i], 0, sizeof tm[i]);
        tm[i].spec = specs[i];
    }
    printf("\n== %s ==\n", title);
    fflush(stdout);
    bool ok = true;
    for (int rep = 0; rep < repeats && ok; ++rep) {
        for (size_t i = 0; i < nruns; ++i)
            order[i] = i;
        shuffle(order, nruns);
        for (size_t k = 0; k < nruns && ok; ++k) {
            size_t si = order[k] / NN, ni = order[k] % NN;
            char label[64], nb[16];
            snprintf(label, sizeof label, "repeat %d/%d %s N=%s", rep + 1, repeats,
                     specs[si], n_name(NS[ni], nb));
            tool_progress(opt.bar, (long)done, (long)total, label);
            run_result r;
            bool big = NS[ni] == NOCT_N_EXHAUSTIVE;
            double n = (double)scene_objects(specs[si]);
            double predicted = big ? exhaustive_pair_cost() * 0.5 * n * (n - 1) * steps : 0;
            if (predicted > opt.budget) {
                r = (run_result){.seconds = predicted, .extrapolated = true,
                                 .objects = (size_t)n};
            } else {
                ok = run(specs[si], NS[ni], NOCT_ACCURACY_EXACT, 0, 0, steps,
                         big ? opt.budget : 0, &r, NULL, NULL);
                if (!ok)
                    break;
            }
            tm[si].objects = r.objects;
            tm[si].t[ni][rep] = r.seconds;
            tm[si].extrapolated[ni] |= r.extrapolated;
            tm[si].begins[ni] = r.begins;
            fprintf(f, "%s,%zu,%s,%d,%d,%.9g,%d,%d,%zu\n", specs[si], r.objects,
                    n_name(NS[ni], nb), rep + 1, steps, r.seconds, r.extrapolated,
                    r.steps_run, r.begins);
            fflush(f); /* a long run's finished rows survive an interruption */
            ++done;
        }
    }
    tool_progress(opt.bar, (long)total, (long)total, ok ? "done" : "failed");
    free(order);
    fclose(f);
    return ok;
}

/* Print the table (rows N, columns scenes) and the statistics; write the
 * statistics CSV. */
static void timing_report(const char *stats_csv, const char *medians_csv, timing *tm,
                          size_t nspecs, int repeats, int steps)
{
    char lb[32], nb[16];
    FILE *mf = open_out(medians_csv);
    if (mf) {
        fprintf(mf, "scene,objects");
        for (int ni = 0; ni < NN; ++ni)
            fprintf(mf, ",N_%s", n_name(NS[ni], nb));
        for (size_t i = 0; i < nspecs; ++i) {
            fprintf(mf, "\n%s,%zu", tm[i].spec, tm[i].objects);
            for (int ni = 0; ni < NN; ++ni)
                fprintf(mf, ",%.9g", median(tm[i].t[ni], (size_t)repeats));
        }
        fputc('\n', mf);
        fclose(mf);
    }
    printf("seconds for %d steps, median of %d interleaved runs (+-: half the range, "
           "%% of the median; ~: extrapolated, not measured: the exhaustive run would\n"
           "have taken more than the %g s budget, so it was cut, or not started and its\n"
           "time is t10's exhaustive cost per pair times the pairs)\n",
           steps, repeats, opt.budget);
    for (size_t c0 = 0; c0 < nspecs; c0 += 6) {
        size_t c1 = c0 + 6 < nspecs ? c0 + 6 : nspecs;
        printf("\n%-8s", "set");
        for (size_t i = c0; i < c1; ++i)
            printf(" %15s", scene_label(tm[i].spec, lb));
        printf("\n%-8s", "objects");
        for (size_t i = c0; i < c1; ++i)
            printf(" %15zu", tm[i].objects);
        for (int ni = 0; ni < NN; ++ni) {
            printf("\nN=%-6s", n_name(NS[ni], nb));
            for (size_t i = c0; i < c1; ++i) {
                char cell[40];
                snprintf(cell, sizeof cell, "%s%.3g +-%.0f%%", tm[i].extrapolated[ni] ? "~" : "",
                         median(tm[i].t[ni], (size_t)repeats),
                         100 * spread(tm[i].t[ni], (size_t)repeats));
                printf(" %15s", cell);
            }
        }
        printf("\n");
    }
    FILE *f = open_out(stats_csv);
    if (f)
        fprintf(f, "scene,objects,best_N,ratio,ci_low,ci_high,p_adjusted,significant,"
                   "extrapolated,begins_agree\n");
    printf("\nexhaustive (N=big) against the best N, per set: ratio of medians, 95%% "
           "bootstrap interval,\none-sided permutation p (x%d for picking the best N)\n",
           NN - 1);
    printf("%-12s %9s %7s %9s %19s %9s  %s\n", "set", "objects", "best N", "big/best",
           "95% interval", "p", "octree faster?");
    const char *first = NULL;
    size_t first_objects = 0;
    for (size_t i = 0; i < nspecs; ++i) {
        int best = 0;
        for (int ni = 1; ni < NN - 1; ++ni)
            if (median(tm[i].t[ni], (size_t)repeats) < median(tm[i].t[best], (size_t)repeats))
                best = ni;
        const double *big = tm[i].t[NN - 1], *bt = tm[i].t[best];
        double ratio = median(big, (size_t)repeats) / median(bt, (size_t)repeats), ci[2];
        bootstrap_ratio(big, bt, (size_t)repeats, ci);
        double p = fmin(1, (NN - 1) * permutation_p(big, bt, (size_t)repeats));
        bool extrap = tm[i].extrapolated[NN - 1];
        bool sig = !extrap && p < 0.05 && ci[0] > 1;
        /* The smallest p the exact test can give: (NN - 1) / C(2r, r). */
        double pmin = NN - 1;
        for (int k = 1; k <= repeats; ++k)
            pmin *= (double)k / (double)(repeats + k);
        bool testable = pmin < 0.05;
        bool agree = true;
        for (int ni = 0; ni < NN; ++ni)
            agree &= tm[i].extrapolated[ni] || tm[i].begins[ni] == tm[i].begins[best];
        if (sig && first == NULL) {
            first = tm[i].spec;
            first_objects = tm[i].objects;
        }
        char ivl[48];
        snprintf(ivl, sizeof ivl, "[%.3g, %.3g]", ci[0], ci[1]);
        printf("%-12s %9zu %7s %9.3g %19s %9.3g  %s%s\n", scene_label(tm[i].spec, lb),
               tm[i].objects, n_name(NS[best], nb), ratio, ivl, p,
               extrap ? "not tested (extrapolated)" : sig ? "yes, significantly"
               : !testable ? "untestable: too few repeats (use 5)"
               : ratio > 1 ? "not significantly" : "no",
               agree ? "" : "  (EVENT COUNTS DIFFER ACROSS N)");
        if (f)
            fprintf(f, "%s,%zu,%s,%.6g,%.6g,%.6g,%.6g,%d,%d,%d\n", tm[i].spec, tm[i].objects,
                    n_name(NS[best], nb), ratio, ci[0], ci[1], p, sig, extrap, agree);
    }
    if (f)
        fclose(f);
    if (first)
        printf("smallest set at which the octree is significantly faster: %s (%zu objects)\n",
               scene_label(first, lb), first_objects);
    else
        printf("no set at which the octree is significantly faster\n");
    fflush(stdout);
}

/* The line of each N in the timing plots: the report's N in four colours,
 * the defaults (what a program gets) thick and black, the exhaustive
 * algorithm in red. */
static const char *const n_colour[NN] = {"#1b9e77", "#d95f02", "#7570b3", "#e6ab02",
                                         "#000000", "#d62728"};

/* Tics 1, 2, 5, 10, 20, ... for a log axis from `lo` up: gnuplot's own
 * log tics are one per decade, too few to read a span of one decade. */
static int log_tics(char *buf, size_t size, const char *axis, double lo)
{
    int n = snprintf(buf, size, "set %s (", axis);
    for (double d = lo; d < lo * 1.1e10; d *= 10)
        for (int k = 0; k < 3; ++k)
            n += snprintf(buf + n, size - (size_t)n, "%s%.6g", d == lo && k == 0 ? "" : ", ",
                          d * (k == 0 ? 1 : k == 1 ? 2 : 5));
    return n + snprintf(buf + n, size - (size_t)n, ")\n");
}

/* A plot of a per-N medians CSV (columns scene, objects, then one per N,
 * the exhaustive algorithm last). */
typedef struct timing_chart {
    const char *name, *medians, *title, *ylabel;
    double scale;      /* y = median seconds times this ... */
    bool per_object;   /* ... divided by the objects */
    bool speedup;      /* y = the exhaustive median over each N's instead */
    bool logscale;     /* both axes */
    double xmin;       /* sets with fewer objects are left out (and do not
                        * stretch the axes) */
    bool has_gas;      /* a second line per N for the gas scenes (dashed) */
} timing_chart;

static void timing_plot(const timing_chart *c)
{
    static const char *const family[2] = {"planes", "gas"};
    char script[8192];
    int n = snprintf(script, sizeof script, "set title \"%s\"\nset xlabel 'objects'\n"
                     "set ylabel \"%s\"\n", c->title, c->ylabel);
    if (c->logscale) {
        n += snprintf(script + n, sizeof script - (size_t)n, "set logscale xy\n"
                      "set format xy '%%g'\n");
        n += log_tics(script + n, sizeof script - (size_t)n, "xtics", 1);
        n += log_tics(script + n, sizeof script - (size_t)n, "ytics", 1e-9);
    }
    n += snprintf(script + n, sizeof script - (size_t)n, "plot ");
    for (int ni = 0; ni < (c->speedup ? NN - 1 : NN); ++ni)
        for (int fam = 0; fam < (c->has_gas ? 2 : 1); ++fam) {
            char nb[16], y[64];
            if (c->speedup)
                snprintf(y, sizeof y, "$%d/$%d", NN + 2, ni + 3);
            else
                snprintf(y, sizeof y, "$%d*%.17g%s", ni + 3, c->scale,
                         c->per_object ? "/$2" : "");
            n += snprintf(script + n, sizeof script - (size_t)n,
                          "%s'%s/%s' skip 1 using ($2 >= %g ? $2 : NaN):"
                          "(strstrt(strcol(1), '%s') == 1 && $2 >= %g ? %s : NaN) "
                          "with linespoints lc rgb '%s' lw %g dt %d pt %d title 'N = %s%s'",
                          ni + fam ? ", \\\n     " : "", opt.out, c->medians, c->xmin,
                          family[fam], c->xmin, y, n_colour[ni],
                          NS[ni] == NOCT_AUTO ? 3.0 : 1.5, fam + 1, ni + 4,
                          n_name(NS[ni], nb), c->has_gas ? (fam ? " gas" : " planes") : "");
        }
    snprintf(script + n, sizeof script - (size_t)n, "\n");
    plot(c->name, script);
}

/* ---- where the time goes ------------------------------------------------------ */

static bool stages_section(const char *const *specs, size_t nspecs, int N, int repeats,
                           int steps)
{
    enum { EXACT, CONVEX, NCFG, NV = 7 };
    static const noctAccuracy acc[NCFG] = {NOCT_ACCURACY_EXACT, NOCT_ACCURACY_CONVEX};
    printf("\n== Where the time goes (N = %s, ms per step, median of %d runs) ==\n",
           n_name(N, (char[16]){0}),
           repeats);
    printf("a run at exact accuracy, and one at convex accuracy for its convex level;\n"
           "pair search includes the box tests; the narrowphase levels are the\n"
           "world's loop over the pairs whose boxes overlap\n");
    FILE *f = open_out("stages.csv");
    if (f == NULL)
        return false;
    fprintf(f, "scene,objects,N,motion_ms,maintenance_ms,pair_search_ms,convex_level_ms,"
               "exact_level_ms,response_ms,total_ms,candidate_pairs,tested_pairs,"
               "neighbor_queries,exact_fallbacks,same_trajectory\n");
    printf("%-12s %8s %8s %11s %11s %8s %8s %9s %8s  %s\n", "scene", "objects", "motion",
           "maintenance", "pair search", "convex", "exact", "response", "total",
           "per step: candidates, tested, neighbor queries");
    size_t total = nspecs * NCFG * (size_t)repeats, done = 0;
    for (size_t i = 0; i < nspecs; ++i) {
        double v[NCFG][NV][MAX_REPEATS];
        run_result r, first[NCFG];
        for (int rep = 0; rep < repeats; ++rep)
            for (int c = 0; c < NCFG; ++c) {
                char label[64];
                snprintf(label, sizeof label, "%s run %d/%d", specs[i], rep + 1, repeats);
                tool_progress(opt.bar, (long)done++, (long)total, label);
                if (!run(specs[i], N, acc[c], 0, 0, steps, 0, &r, NULL, NULL)) {
                    fclose(f);
                    return false;
                }
                if (rep == 0)
                    first[c] = r;
                const noctWorldCounters *k = &r.c;
                double levels = k->narrow.seconds_convex + k->narrow.seconds_exact;
                double part[NV] = {k->seconds_motion, k->seconds_maintenance,
                                   k->seconds_pairs - levels, k->narrow.seconds_convex,
                                   k->narrow.seconds_exact, k->seconds_response,
                                   k->seconds_motion + k->seconds_maintenance +
                                       k->seconds_pairs + k->seconds_response};
                for (int p = 0; p < NV; ++p)
                    v[c][p][rep] = 1e3 * part[p] / steps;
            }
        tool_progress(opt.bar, (long)done, (long)total, "");
        size_t n = (size_t)repeats;
        double m[NV];
        for (int p = 0; p < NV; ++p)
            m[p] = median(v[EXACT][p], n);
        m[3] = median(v[CONVEX][3], n);
        bool same = first[EXACT].begins == first[CONVEX].begins;
        const noctWorldCounters *k = &first[EXACT].c;
        char lb[32];
        printf("%-12s %8zu %8.3f %11.3f %11.3f %8.3f %8.3f %9.3f %8.3f  %.0f, %.0f, %.0f%s\n",
               scene_label(specs[i], lb), first[EXACT].objects, m[0], m[1], m[2], m[3], m[4],
               m[5], m[6], (double)k->candidate_pairs / steps,
               (double)k->tested_pairs / steps, (double)k->neighbor_queries / steps,
               same ? "" : " (convex run took another path)");
        fprintf(f, "%s,%zu,%d,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.1f,%.1f,%.1f,%llu,%d\n",
                specs[i], first[EXACT].objects, N, m[0], m[1], m[2], m[3], m[4], m[5], m[6],
                (double)k->candidate_pairs / steps, (double)k->tested_pairs / steps,
                (double)k->neighbor_queries / steps,
                (unsigned long long)k->narrow.exact_fallbacks, same);
        fflush(stdout);
    }
    fclose(f);
    return true;
}

/* ---- what accuracy costs -------------------------------------------------------- */

/*
 * The ladder, from the cheapest rung up; the last rung, exact continuous
 * detection, is the reference. Each rung is one row per scene in
 * accuracy.csv and one marker in the chart, whatever their number.
 *
 * What a rung answers at a step: the pairs it saw touching at some instant
 * it looked at, from the step's start (the previous step's end) to its
 * end. The reference looks at every instant of the step's straight-line
 * motion, start and end included (world.h's continuous level: its
 * colliding list). The discrete levels look at the start and the end (the
 * previous and this step's colliding lists); with k fixed sub-steps, at
 * the start and at the k sub-steps' ends (the bench steps a world whose
 * velocities are divided by k, k times a step, and joins the colliding
 * lists); with the automatic k (#NOCT_EFFECT_SUBSTEP), at the start and at
 * every sub-step the world took: this step's colliding list, the pairs
 * that began and those that ended at one of its sub-steps. So no rung is
 * charged for the instant its samples share with the reference's
 * definition, and every rung's answer comes from the same definition.
 * A contact begins at a step where a pair is in the answer and was not in
 * the previous step's: the events of every rung, the reference's included,
 * follow from its answers the same way.
 *
 * The same paths for every rung: detection must not change where objects
 * go, so the runs have no response (a missed contact would otherwise turn
 * nothing, and the rungs would be compared on different trajectories), and
 * the container's walls are applied by the bench after each whole step,
 * as the world would (an object outside the container on an axis and
 * moving outward has that velocity component negated), not at every
 * sub-step. The sub-stepped rungs move by v / k k times, which may differ
 * from p + v in the last bits.
 */
typedef struct rung {
    const char *name; /* the CSV's rung column and the chart's legend (no commas) */
    noctAccuracy accuracy;
    unsigned effects;
    int k;            /* fixed sub-steps, done by the bench; 1 for none */
} rung;

static const rung rungs[] = {
    {"box", NOCT_ACCURACY_BOX, 0, 1},
    {"convex", NOCT_ACCURACY_CONVEX, 0, 1},
    {"exact", NOCT_ACCURACY_EXACT, 0, 1},
    {"exact k=2", NOCT_ACCURACY_EXACT, 0, 2},
    {"exact k=4", NOCT_ACCURACY_EXACT, 0, 4},
    {"exact k=8", NOCT_ACCURACY_EXACT, 0, 8},
    {"exact auto k", NOCT_ACCURACY_EXACT, NOCT_EFFECT_SUBSTEP, 1},
    {"continuous", NOCT_ACCURACY_CONTINUOUS, 0, 1},
};
enum { NRUNGS = sizeof rungs / sizeof *rungs, REFERENCE = NRUNGS - 1 };

/*
 * The turning scene, a family's spec followed by "+spin" (gas:1000+spin):
 * the family's scene, then every object given an angular velocity of
 * SPIN_DEGREES per step about an axis drawn from its index i: with
 * h = (i + 1) * 2654435761 mod 2^32, the axis (h mod 1024 - 511.5,
 * (h >> 10) mod 1024 - 511.5, (h >> 20) mod 1024 - 511.5), never zero; and
 * #NOCT_EFFECT_SPIN on for every rung (only moving objects turn). With k
 * fixed sub-steps the bench divides the turn as it divides the velocity:
 * SPIN_DEGREES / k about the same axis, once per sub-step, so the k
 * sub-steps' ends lie on the motion the continuous level sweeps (the
 * shorter arc and the straight line), and k = 2, 4 and 8 sample a subset
 * of DENSE's instants. The automatic k turns the whole angle before its
 * first sub-step (#NOCT_EFFECT_SPIN), its samples off that motion.
 *
 * No rung is exact there: the continuous level is conservative for turning
 * objects (world.h, "Turning: conservative"): it misses nothing and may
 * report near misses. So its row is named CONSERVATIVE, and the scene has
 * two references: missed entries and begins are counted against the
 * conservative rung (it misses nothing, so a rung's true misses are at
 * most these), false entries and begins against DENSE, the exact level at
 * 32 fixed sub-steps (its samples are contacts, so a rung's true false
 * reports are at most these; DENSE can itself miss a contact between its
 * samples). Both counts are upper bounds.
 */
enum { SPIN_DEGREES = 12 };
static const char SPIN_SUFFIX[] = "+spin";
static const char CONSERVATIVE[] = "conservative continuous";
static const rung DENSE = {"exact k=32", NOCT_ACCURACY_EXACT, 0, 32};

/* Whether spec is a turning scene; its family's spec into base. */
static bool spin_scene(const char *spec, char base[64])
{
    const size_t n = strlen(spec), m = sizeof SPIN_SUFFIX - 1;
    const bool spin = n > m && strcmp(spec + n - m, SPIN_SUFFIX) == 0;
    snprintf(base, 64, "%.*s", (int)(spin ? n - m : n), spec);
    return spin;
}

/* A rung's name on a scene: the continuous rung is conservative on a
 * turning scene. */
static const char *rung_name(const rung *r, bool spin)
{
    return spin && r == &rungs[REFERENCE] ? CONSERVATIVE : r->name;
}

/* Object i's angular velocity on a turning scene, at k sub-steps a step. */
static noctStatus spin_of(size_t i, int k, noctQuat *q)
{
    const uint32_t h = (uint32_t)((i + 1) * 2654435761u);
    const double axis[3] = {(double)(h & 1023) - 511.5, (double)(h >> 10 & 1023) - 511.5,
                            (double)(h >> 20 & 1023) - 511.5};
    return noctQuatFromAxisAngle(axis, (double)SPIN_DEGREES / k, q);
}

static const char *rung_substeps(const rung *r, char buf[16])
{
    if (r->effects & NOCT_EFFECT_SUBSTEP)
        return "auto";
    snprintf(buf, 16, "%d", r->k);
    return buf;
}

/* A step's answer being gathered: pairs, sorted and made unique once. */
typedef struct pair_set {
    noctPair *p;
    size_t n, cap;
} pair_set;

static bool set_add(pair_set *s, const noctPair *p, size_t n)
{
    if (n == 0) /* p may be NULL then, and memcpy may not take it */
        return true;
    if (s->n + n > s->cap) {
        size_t cap = s->cap ? s->cap : 1024;
        while (cap < s->n + n)
            cap *= 2;
        noctPair *q = realloc(s->p, cap * sizeof *q);
        if (q == NULL)
            return false;
        s->p = q;
        s->cap = cap;
    }
    memcpy(s->p + s->n, p, n * sizeof *p);
    s->n += n;
    return true;
}

static int cmp_pair(const void *x, const void *y)
{
    const noctPair *a = x, *b = y;
    if (a->a.index != b->a.index)
        return a->a.index < b->a.index ? -1 : 1;
    return (a->b.index > b->b.index) - (a->b.index < b->b.index);
}

static void set_close(pair_set *s)
{
    if (s->n == 0)
        return;
    qsort(s->p, s->n, sizeof *s->p, cmp_pair);
    size_t m = 1;
    for (size_t i = 1; i < s->n; ++i)
        if (cmp_pair(&s->p[i], &s->p[m - 1]) != 0)
            s->p[m++] = s->p[i];
    s->n = m;
}

/* The begins that follow from answers: the entries of a whose pair is not
 * in a at the step before. */
static bool log_begins(const pair_log *a, pair_log *b)
{
    size_t prev = 0, prev_end = 0; /* the step before's entries */
    for (size_t i = 0; i < a->n;) {
        size_t j = i;
        while (j < a->n && a->p[j].step == a->p[i].step)
            ++j;
        bool adjacent = i > 0 && a->p[i - 1].step + 1 == a->p[i].step;
        size_t q = prev;
        for (size_t e = i; e < j; ++e) {
            while (adjacent && q < prev_end && cmp_pair_at(&(pair_at){a->p[e].step - 1,
                                                                  a->p[e].a, a->p[e].b},
                                                        &a->p[q]) > 0)
                ++q;
            bool seen = adjacent && q < prev_end && a->p[q].a == a->p[e].a &&
                        a->p[q].b == a->p[e].b;
            if (!seen) {
                if (b->n == b->cap) {
                    size_t cap = b->cap ? 2 * b->cap : 1024;
                    pair_at *r = realloc(b->p, cap * sizeof *r);
                    if (r == NULL)
                        return false;
                    b->p = r;
                    b->cap = cap;
                }
                b->p[b->n++] = a->p[e];
            }
        }
        prev = i;
        prev_end = j;
        i = j;
    }
    return true;
}

/* Where a ladder run is done: the broadphase's settings. */
typedef struct settings {
    int N, max_depth;
} settings;

/* Negate the outward velocity components of the objects outside the
 * container [lo, hi] (the world's walls rule), through the API. */
static bool apply_walls(noctWorld *w, size_t n, const double lo[3], const double hi[3])
{
    for (size_t i = 0; i < n; ++i) {
        const noctObjectId id = {(uint32_t)i, 1};
        double p[3], v[3];
        if (noctWorldGetVelocity(w, id, v) != NOCT_OK ||
            noctWorldObject(w, id, p, NULL) != NOCT_OK)
            return false;
        bool flip = false;
        for (int k = 0; k < 3; ++k)
            if ((p[k] < lo[k] && v[k] < 0) || (p[k] > hi[k] && v[k] > 0)) {
                v[k] = -v[k];
                flip = true;
            }
        if (flip && noctWorldSetVelocity(w, id, v, NULL) != NOCT_OK)
            return false;
    }
    return true;
}

/*
 * One run of a rung on a scene at the given settings: its milliseconds per
 * step (the step calls only) and, when asked, its answers (see above).
 */
static bool ladder_run(const char *spec, settings at, const rung *rg, int steps, double *ms,
                       pair_log *answers)
{
    noctScene *scene = NULL;
    noctWorld *w = NULL;
    noctError err;
    pair_set now = {0}, last = {0};
    bool ok = false;
    char base[64];
    const bool spin = spin_scene(spec, base);
    if (noctSceneFamily(base, &scene, &err) != NOCT_OK) {
        tool_error("%s: %s", spec, err.message);
        return false;
    }
    noctWorldDef *def = noctSceneDef(scene);
    const bool walls = (def->effects & NOCT_EFFECT_WALLS) != 0;
    def->N = at.N;
    def->max_depth = at.max_depth;
    def->accuracy = rg->accuracy;
    def->effects = (def->effects | NOCT_EFFECT_MOTION | NOCT_EFFECT_EVENTS | rg->effects |
                    (spin ? NOCT_EFFECT_SPIN : 0)) &
                   ~(NOCT_EFFECT_RESPONSE | NOCT_EFFECT_WALLS);
    if (noctSceneBuild(scene, &w, &err) != NOCT_OK) {
        tool_error("%s: %s", spec, err.message);
        goto done;
    }
    const size_t n = noctWorldObjectCount(w);
    for (size_t i = 0; i < n && spin; ++i) {
        noctQuat q;
        if (spin_of(i, rg->k, &q) != NOCT_OK ||
            noctWorldSetAngularVelocity(w, (noctObjectId){(uint32_t)i, 1}, &q, &err) !=
                NOCT_OK) {
            tool_error("%s: object %zu cannot turn", spec, i);
            goto done;
        }
    }
    for (size_t i = 0; i < n && rg->k > 1; ++i) {
        const noctObjectId id = {(uint32_t)i, 1};
        double v[3];
        if (noctWorldGetVelocity(w, id, v) != NOCT_OK) {
            tool_error("%s: object %zu is not at slot %zu", spec, i, i);
            goto done;
        }
        if (v[0] == 0 && v[1] == 0 && v[2] == 0)
            continue;
        for (int c = 0; c < 3; ++c)
            v[c] /= rg->k;
        if (noctWorldSetVelocity(w, id, v, &err) != NOCT_OK) {
            tool_error("%s: %s", spec, err.message);
            goto done;
        }
    }
    const bool continuous = rg->accuracy == NOCT_ACCURACY_CONTINUOUS;
    const bool auto_k = (rg->effects & NOCT_EFFECT_SUBSTEP) != 0;
    double elapsed = 0;
    for (int s = 1; s <= steps; ++s) {
        now.n = 0;
        if (!continuous && !auto_k && !set_add(&now, last.p, last.n))
            goto nomem;
        for (int j = 0; j < rg->k; ++j) {
            double t0 = tool_now();
            noctStatus st = noctWorldStep(w, &err);
            elapsed += tool_now() - t0;
            if (st != NOCT_OK) {
                tool_error("%s, %s, step %d: %s", spec, rung_name(rg, spin), s,
                           err.message);
                goto done;
            }
            if (answers == NULL)
                continue;
            const noctPair *p;
            size_t np = noctWorldColliding(w, &p);
            if (!set_add(&now, p, np))
                goto nomem;
            if (auto_k) {
                np = noctWorldBegan(w, &p);
                if (!set_add(&now, p, np))
                    goto nomem;
                np = noctWorldEnded(w, &p);
                if (!set_add(&now, p, np))
                    goto nomem;
            }
            if (j + 1 == rg->k) {
                np = noctWorldColliding(w, &p);
                last.n = 0;
                if (!set_add(&last, p, np))
                    goto nomem;
            }
        }
        if (walls && !apply_walls(w, n, def->walls_lo, def->walls_hi)) {
            tool_error("%s: the walls failed", spec);
            goto done;
        }
        if (answers != NULL) {
            set_close(&now);
            if (!log_pairs(answers, (uint32_t)s, now.p, now.n))
                goto nomem;
        }
    }
    *ms = 1e3 * elapsed / steps;
    ok = true;
    goto done;
nomem:
    tool_error("out of memory");
done:
    free(now.p);
    free(last.p);
    noctWorldDestroy(w);
    noctSceneDestroy(scene);
    return ok;
}

/*
 * The Pareto front of one scene's rungs, cheapest first: the rungs that no
 * other rung matches or beats in both time and error while beating them in
 * one. Along it the time rises and the error falls. Returns its length.
 */
static int pareto_front(const double *ms, const size_t *error, int *front)
{
    int n = 0;
    for (int c = 0; c < NRUNGS; ++c) {
        bool dominated = false;
        for (int d = 0; d < NRUNGS && !dominated; ++d)
            dominated = ms[d] <= ms[c] && error[d] <= error[c] &&
                        (ms[d] < ms[c] || error[d] < error[c]);
        if (dominated)
            continue;
        int k = n++;
        for (; k > 0 && ms[front[k - 1]] > ms[c]; --k)
            front[k] = front[k - 1];
        front[k] = c;
    }
    return n;
}

/* A rung's errors against the reference's answers and begins. */
typedef struct rung_errors {
    size_t fx, mx, bmissed, bfalse;
    uint32_t first;
} rung_errors;

static rung_errors compare(const pair_log *ans, const pair_log *beg, const pair_log *ref_ans,
                           const pair_log *ref_beg)
{
    rung_errors e;
    uint32_t d;
    log_diff(ans, ref_ans, &e.fx, &e.mx, &e.first);
    log_diff(beg, ref_beg, &e.bfalse, &e.bmissed, &d);
    if (d && (e.first == 0 || d < e.first))
        e.first = d;
    return e;
}

/* On a turning scene: missed entries and begins against the conservative
 * rung's, false ones against DENSE's; the first step that differs from
 * either reference. */
static rung_errors compare_turning(const pair_log *ans, const pair_log *beg,
                                   const pair_log *cons_ans, const pair_log *cons_beg,
                                   const pair_log *dense_ans, const pair_log *dense_beg)
{
    rung_errors e = {0};
    size_t unused;
    uint32_t d[4];
    log_diff(ans, dense_ans, &e.fx, &unused, &d[0]);
    log_diff(ans, cons_ans, &unused, &e.mx, &d[1]);
    log_diff(beg, dense_beg, &e.bfalse, &unused, &d[2]);
    log_diff(beg, cons_beg, &unused, &e.bmissed, &d[3]);
    for (int i = 0; i < 4; ++i)
        if (d[i] && (e.first == 0 || d[i] < e.first))
            e.first = d[i];
    return e;
}

/*
 * The broadphase's settings on the tunnelling scene: the exact and the
 * continuous rungs at a few N and maximum depths, their answers against
 * the same rung's at the defaults (which the ladder ran). Costs only:
 * each row must differ in nothing.
 */
static bool settings_table(const char *spec, int repeats, int steps, const pair_log *exact,
                           const pair_log *cont)
{
    static const settings at[] = {{8, NOCT_AUTO}, {64, NOCT_AUTO}, {NOCT_AUTO, 4},
                                  {NOCT_N_EXHAUSTIVE, NOCT_AUTO}};
    static const int which[] = {2, REFERENCE};
    FILE *f = open_out("accuracy-settings.csv");
    if (f == NULL)
        return false;
    fprintf(f, "scene,rung,N,max_depth,ms_per_step,differs\n");
    printf("\nThe broadphase's settings on %s: costs that never change the answers\n"
           "(differs: (pair, step) entries unlike the same rung's at the defaults)\n",
           spec);
    printf("%-12s %-6s %-9s %10s %8s\n", "rung", "N", "max depth", "ms/step", "differs");
    bool ok = true;
    for (size_t r = 0; r < sizeof which / sizeof *which && ok; ++r)
        for (size_t a = 0; a < sizeof at / sizeof *at && ok; ++a) {
            const rung *rg = &rungs[which[r]];
            double t[MAX_REPEATS];
            pair_log ans = {0};
            for (int rep = 0; rep < repeats && ok; ++rep)
                ok = ladder_run(spec, at[a], rg, steps, &t[rep], rep == 0 ? &ans : NULL);
            if (!ok) {
                free(ans.p);
                break;
            }
            size_t x, y;
            uint32_t d;
            log_diff(&ans, which[r] == REFERENCE ? cont : exact, &x, &y, &d);
            char nb[16], db[16];
            snprintf(db, sizeof db, "%d", at[a].max_depth);
            const char *depth = at[a].max_depth == NOCT_AUTO ? "auto" : db;
            double ms = median(t, (size_t)repeats);
            printf("%-12s %-6s %-9s %10.4f %8zu\n", rg->name, n_name(at[a].N, nb), depth, ms,
                   x + y);
            fprintf(f, "%s,%s,%s,%s,%.6g,%zu\n", spec, rg->name, n_name(at[a].N, nb), depth, ms,
                    x + y);
            free(ans.p);
        }
    fclose(f);
    return ok;
}

/* The continuous level's cost on a scene where nothing tunnels, against
 * the exact level's in the same run (interleaved repeats), with the
 * family's own effects (walls, response): issue 27's target is at most 2. */
static bool continuous_cost(const char *spec, int repeats, int steps)
{
    double t[2][MAX_REPEATS];
    const rung *two[2] = {&rungs[2], &rungs[REFERENCE]};
    for (int rep = 0; rep < repeats; ++rep)
        for (int c = 0; c < 2; ++c) {
            run_result r;
            const int cc = rep % 2 ? 1 - c : c;
            if (!run(spec, NOCT_AUTO, two[cc]->accuracy, 0, 0, steps, 0, &r, NULL, NULL))
                return false;
            t[cc][rep] = 1e3 * r.seconds / steps;
        }
    const double e = median(t[0], (size_t)repeats), c = median(t[1], (size_t)repeats);
    printf("\nContinuous against exact on %s (the family's effects, %d steps, median of %d "
           "interleaved runs):\nexact %.3f ms/step, continuous %.3f ms/step: %.2f times "
           "(target: at most 2)\n", spec, steps, repeats, e, c, c / e);
    FILE *f = open_out("accuracy-continuous.csv");
    if (f == NULL)
        return false;
    fprintf(f, "scene,steps,repeats,exact_ms_per_step,continuous_ms_per_step,ratio\n"
               "%s,%d,%d,%.6g,%.6g,%.4f\n", spec, steps, repeats, e, c, c / e);
    fclose(f);
    return true;
}

static bool accuracy_section(const char *const *specs, size_t nspecs, int repeats, int steps,
                             size_t *objects, const char *tunnel, const char *big)
{
    printf("\n== What accuracy costs (N and depth auto, %d steps, time: median of %d runs) ==\n",
           steps, repeats);
    printf("reference: exact continuous. A rung's answer at a step: the pairs it saw\n"
           "touching from the step's start to its end (the reference: at any instant; the\n"
           "others: at the start, the end and each sub-step's end). false/missed: (pair,\n"
           "step) entries the reference lacks/has; begins missed/false: contact-begin\n"
           "events (a pair in the answer that was not at the step before); error = false\n"
           "+ missed + begins missed; diverges: first step that differs ('-': never).\n"
           "No response, and the walls applied after whole steps: every rung follows the\n"
           "same paths. x exact: time over the exact rung's.\n");
    for (size_t i = 0; i < nspecs; ++i) {
        char base[64];
        if (spin_scene(specs[i], base))
            printf("%s (turning, %d degrees a step): no rung is exact; the continuous\n"
                   "rung is conservative (misses nothing, may report near misses). missed\n"
                   "and begins missed: against it; false and begins false: against %s,\n"
                   "whose samples are contacts; both upper bounds. diverges: first step\n"
                   "unlike either.\n",
                   specs[i], SPIN_DEGREES, DENSE.name);
    }
    FILE *f = open_out("accuracy.csv");
    FILE *ff = open_out("accuracy-front.csv");
    if (f == NULL || ff == NULL) {
        if (f)
            fclose(f);
        if (ff)
            fclose(ff);
        return false;
    }
    fprintf(f, "scene,objects,rung,accuracy,substeps,ms_per_step,colliding_per_step,false,"
               "missed,begins,begins_missed,begins_false,error,first_divergence\n");
    fprintf(ff, "scene,rung,ms_per_step,error\n");
    size_t total = nspecs * NRUNGS * (size_t)repeats, done = 0;
    for (size_t i = 0; i < nspecs; ++i) {
        char base[64];
        total += spin_scene(specs[i], base); /* DENSE's run */
    }
    bool ok = true;
    const settings defaults = {NOCT_AUTO, NOCT_AUTO};
    pair_log keep_exact = {0}, keep_cont = {0};
    for (size_t i = 0; i < nspecs && ok; ++i) {
        printf("\n%-23s %10s %7s %10s %9s %9s %8s %8s %8s %9s %9s\n", "rung", "ms/step",
               "x exact", "colliding", "false", "missed", "begins", "b.missed", "b.false",
               "error", "diverges");
        char base[64];
        const bool spin = spin_scene(specs[i], base);
        pair_log ans[NRUNGS] = {{0}}, beg[NRUNGS] = {{0}}, dense_ans = {0}, dense_beg = {0};
        double t[NRUNGS][MAX_REPEATS], ms[NRUNGS], dense_ms = 0;
        size_t error[NRUNGS];
        if (spin) {
            tool_progress(opt.bar, (long)done++, (long)total, DENSE.name);
            ok = ladder_run(specs[i], defaults, &DENSE, steps, &dense_ms, &dense_ans);
            if (ok && !log_begins(&dense_ans, &dense_beg)) {
                tool_error("out of memory");
                ok = false;
            }
        }
        for (int rep = 0; rep < repeats && ok; ++rep)
            for (int c = 0; c < NRUNGS && ok; ++c) {
                char label[64];
                snprintf(label, sizeof label, "%s run %d/%d", specs[i], rep + 1, repeats);
                tool_progress(opt.bar, (long)done++, (long)total, label);
                ok = ladder_run(specs[i], defaults, &rungs[c], steps, &t[c][rep],
                                rep == 0 ? &ans[c] : NULL);
            }
        tool_progress(opt.bar, (long)done, (long)total, "");
        for (int c = 0; c < NRUNGS && ok; ++c)
            if (!log_begins(&ans[c], &beg[c])) {
                tool_error("out of memory");
                ok = false;
            }
        if (ok) {
            noctScene *sc;
            if (noctSceneFamily(base, &sc, NULL) == NOCT_OK) {
                noctWorld *w;
                if (noctSceneBuild(sc, &w, NULL) == NOCT_OK) {
                    objects[i] = noctWorldObjectCount(w);
                    noctWorldDestroy(w);
                }
                noctSceneDestroy(sc);
            }
            printf("%s (%zu objects)\n", scene_label(specs[i], (char[32]){0}), objects[i]);
        }
        for (int c = 0; c < NRUNGS && ok; ++c) {
            rung_errors e =
                spin ? compare_turning(&ans[c], &beg[c], &ans[REFERENCE], &beg[REFERENCE],
                                       &dense_ans, &dense_beg)
                     : compare(&ans[c], &beg[c], &ans[REFERENCE], &beg[REFERENCE]);
            char ds[16], sb[16];
            snprintf(ds, sizeof ds, "%u", e.first);
            ms[c] = median(t[c], (size_t)repeats);
            error[c] = e.fx + e.mx + e.bmissed;
            printf("%-23s %10.4f %7.2f %10.1f %9zu %9zu %8zu %8zu %8zu %9zu %9s\n",
                   rung_name(&rungs[c], spin), ms[c], ms[c] / median(t[2], (size_t)repeats),
                   (double)ans[c].n / steps, e.fx, e.mx, beg[c].n, e.bmissed, e.bfalse,
                   error[c], e.first ? ds : "-");
            fprintf(f, "%s,%zu,%s,%s,%s,%.6g,%.3f,%zu,%zu,%zu,%zu,%zu,%zu,%u\n", specs[i],
                    objects[i], rung_name(&rungs[c], spin),
                    noctAccuracyName(rungs[c].accuracy), rung_substeps(&rungs[c], sb), ms[c],
                    (double)ans[c].n / steps, e.fx, e.mx, beg[c].n, e.bmissed, e.bfalse,
                    error[c], e.first);
        }
        if (ok) {
            int front[NRUNGS], nf = pareto_front(ms, error, front);
            for (int k = 0; k < nf; ++k)
                fprintf(ff, "%s,%s,%.6g,%zu\n", specs[i], rung_name(&rungs[front[k]], spin),
                        ms[front[k]], error[front[k]]);
        }
        if (ok && spin) {
            size_t dx, dm;
            uint32_t d;
            log_diff(&dense_ans, &ans[REFERENCE], &dx, &dm, &d);
            printf("%s (the false reference, one run): %.4f ms/step, %.1f colliding per "
                   "step;\nthe conservative rung's entries it lacks: %zu (its misses or the "
                   "conservative rung's near misses), its entries the conservative rung "
                   "lacks: %zu\n",
                   DENSE.name, dense_ms, (double)dense_ans.n / steps, dm, dx);
        }
        free(dense_ans.p);
        free(dense_beg.p);
        if (ok && strcmp(specs[i], tunnel) == 0) {
            keep_exact = ans[2];
            keep_cont = ans[REFERENCE];
            ans[2] = ans[REFERENCE] = (pair_log){0};
        }
        for (int c = 0; c < NRUNGS; ++c) {
            free(ans[c].p);
            free(beg[c].p);
        }
        fflush(stdout);
    }
    fclose(f);
    fclose(ff);
    if (ok)
        ok = settings_table(tunnel, repeats, steps, &keep_exact, &keep_cont);
    free(keep_exact.p);
    free(keep_cont.p);
    if (ok)
        ok = continuous_cost(big, repeats, opt.quick ? 10 : 50);
    return ok;
}

/*
 * The accuracy chart: one panel per scene, time per step against error
 * (false + missed (pair, step) entries + missed begins), both on log scales.
 * The error axis is placed at 1 + error and labelled in errors, so an
 * error-free rung sits on the dashed line marked 0 instead of at minus
 * infinity. One marker per rung, named in a legend under the panels; the
 * Pareto front circled and joined.
 */
static void accuracy_plot(const char *const *specs, const size_t *objects, size_t nspecs)
{
    char *script = NULL;
    size_t size = 0;
    FILE *s = open_memstream(&script, &size);
    if (s == NULL) {
        tool_error("out of memory");
        return;
    }
    /* The legend: the line marked 0, the front and the rungs, four to a row. */
    int rows = (NRUNGS + 2 + 3) / 4;
    double bottom = 0.14 + 0.04 * rows;
    fprintf(s, "set terminal svg size %zu,560 dynamic font 'sans,12'\n"
               "set output '%s/accuracy.svg'\n"
               "f = '%s/accuracy.csv'\nfront = '%s/accuracy-front.csv'\n"
               "err(s) = strcol('scene') eq s ? column('error') + 1 : NaN\n"
               "set logscale y\n",
            nspecs > 2 ? 400 * nspecs : 800, opt.out, opt.out, opt.out);
    char tics[1024];
    log_tics(tics, sizeof tics, "xtics", 1e-4);
    fputs("set ytics (\"0\" 1, \"1\" 2, \"10\" 11, \"100\" 101", s);
    for (int e = 3; e <= 12; ++e)
        fprintf(s, ", \"10^{%d}\" %.0f", e, pow(10, e) + 1);
    fprintf(s, ")\nset multiplot layout 1,%zu title 'What accuracy costs: time against error "
               "(reference: exact continuous, turning: see the text; the Pareto front circled "
               "and joined)' "
               "margins 0.08,0.98,%g,0.86 spacing 0.05,0\n",
            nspecs, bottom);
    for (size_t i = 0; i < nspecs; ++i) {
        char lb[32];
        /* The panel's own ranges, from its rows, with room around the
         * markers. Times less than 3 times apart get a linear axis: a log
         * axis would show no tic, and over such a span looks the same. */
        fprintf(s, "set autoscale xy\nstats f using 'ms_per_step':(err('%s')) nooutput\n"
                   "if (STATS_max_x < 3 * STATS_min_x) {\n"
                   "  unset logscale x\n  set xlabel 'ms per step'\n"
                   "  d = 0.15 * (STATS_max_x - STATS_min_x) + 0.02 * STATS_min_x\n"
                   "  r = (STATS_max_x - STATS_min_x + 2 * d) / 4\n"
                   "  p = 10 ** floor(log10(r))\n"
                   "  step = (r <= p ? 1 : r <= 2 * p ? 2 : r <= 5 * p ? 5 : 10) * p\n"
                   "  set xtics step\n"
                   "  set xrange [STATS_min_x - d : STATS_max_x + d]\n"
                   "} else {\n"
                   "  set logscale x\n  %s"
                   "  set xlabel 'ms per step (log scale)'\n"
                   "  set xrange [STATS_min_x / 1.4 : STATS_max_x * 1.4]\n"
                   "}\n"
                   "set yrange [0.6 : STATS_max_y < 11 ? 20 : STATS_max_y * 4]\n"
                   "set title '%s (%zu objects)'\n",
                specs[i], tics, scene_label(specs[i], lb), objects[i]);
        if (i == 0)
            fprintf(s, "set ylabel 'false + missed (pair, step) entries + missed begins (log of 1 + error)'\n"
                       "set key at screen 0.5, 0.02 center bottom vertical maxrows %d "
                       "reverse Left width 2 samplen 2\n", rows);
        else
            fprintf(s, "unset ylabel\nunset key\n");
        fprintf(s, "plot 1 with lines lc 'grey40' dt 2 title 'error free (0)', \\\n"
                   "  front using 'ms_per_step':(strcol('scene') eq '%s' ? "
                   "column('error') + 1 : NaN) with linespoints lc 'grey60' lw 2 pt 6 ps 3.2 "
                   "title 'Pareto front'",
                specs[i]);
        /* Colours that stay apart; open markers large and filled ones small,
         * so that a filled marker on an open one leaves both visible. */
        static const int pt[] = {4, 8, 6, 5, 9, 7, 12, 13, 10, 11, 14, 15};
        static const char *const lc[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728",
                                         "#9467bd", "#8c564b", "#e377c2", "#17becf",
                                         "#7f7f7f", "#bcbd22", "#000000", "#aec7e8"};
        enum { NSTYLE = sizeof pt / sizeof *pt };
        for (int c = 0; c < NRUNGS; ++c)
            fprintf(s, ", \\\n  f using 'ms_per_step':(strcol('rung') eq '%s'%s%s%s ? "
                       "err('%s') : NaN) with points lc rgb '%s' pt %d ps %g title '%s%s'",
                    rungs[c].name, c == REFERENCE ? " || strcol('rung') eq '" : "",
                    c == REFERENCE ? CONSERVATIVE : "", c == REFERENCE ? "'" : "", specs[i],
                    lc[c % NSTYLE], pt[c % NSTYLE], pt[c % NSTYLE] % 2 ? 1.2 : 2.0,
                    rungs[c].name, c == REFERENCE ? " (conservative when turning)" : "");
        fputc('\n', s);
    }
    fputs("unset multiplot\n", s);
    if (fclose(s) != 0) {
        free(script);
        tool_error("out of memory");
        return;
    }
    plot("accuracy", script);
    free(script);
}

/* ---- main ------------------------------------------------------------------------ */

static bool parse_sections(const char *s, unsigned *out)
{
    static const struct { const char *name; unsigned bit; } all[] = {
        {"table1", SEC_TABLE1}, {"stages", SEC_STAGES},
        {"accuracy", SEC_ACCURACY}, {"scale", SEC_SCALE}};
    *out = 0;
    while (*s) {
        size_t len = strcspn(s, ",");
        unsigned bit = 0;
        for (size_t i = 0; i < sizeof all / sizeof *all; ++i)
            if (strlen(all[i].name) == len && strncmp(s, all[i].name, len) == 0)
                bit = all[i].bit;
        if (bit == 0)
            return false;
        *out |= bit;
        s += len + (s[len] == ',');
    }
    return *out != 0;
}

int main(int argc, char **argv)
{
    tool_name = "noctree-bench";
    bool quiet = false;
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i];
        bool has = i + 1 < argc;
        long v;
        if (tool_help_or_version(a, usage)) {
            return 0;
        } else if (strcmp(a, "--quick") == 0) {
            opt.quick = true;
        } else if (strcmp(a, "--all") == 0) {
            opt.sections = SEC_TABLE1 | SEC_STAGES | SEC_ACCURACY | SEC_SCALE;
        } else if (strcmp(a, "--no-plots") == 0) {
            opt.plots = false;
        } else if (strcmp(a, "--quiet") == 0) {
            quiet = true;
        } else if (strcmp(a, "--sections") == 0 && has) {
            if (!parse_sections(argv[++i], &opt.sections))
                return tool_usage_error("--sections takes table1, stages, accuracy and "
                                        "scale separated by commas, not '%s'", argv[i]);
        } else if (strcmp(a, "--repeats") == 0 && has) {
            if (!tool_parse_long(argv[++i], 2, MAX_REPEATS, &v))
                return tool_usage_error("--repeats must be 2 to %d, not '%s'", MAX_REPEATS,
                                        argv[i]);
            opt.repeats = (int)v;
        } else if (strcmp(a, "--steps") == 0 && has) {
            if (!tool_parse_long(argv[++i], 1, 100000, &v))
                return tool_usage_error("--steps must be 1 to 100000, not '%s'", argv[i]);
            opt.steps = (int)v;
        } else if (strcmp(a, "--budget") == 0 && has) {
            if (!tool_parse_double(argv[++i], 0.001, 1e6, &opt.budget))
                return tool_usage_error("--budget must be a number of seconds from 0.001 "
                                        "to 1e6, not '%s'", argv[i]);
        } else if (strcmp(a, "--out") == 0 && has) {
            opt.out = argv[++i];
            if (*opt.out == '\0')
                return tool_usage_error("--out needs a folder name");
        } else {
            return tool_usage_error("unknown option or missing value: '%s'", a);
        }
    }
    opt.bar = !quiet && isatty(STDERR_FILENO);
    if (mkdir(opt.out, 0777) != 0 && errno != EEXIST) {
        tool_error("cannot create %s: %s", opt.out, strerror(errno));
        return 2;
    }
    struct stat sb;
    if (stat(opt.out, &sb) != 0 || !S_ISDIR(sb.st_mode)) {
        tool_error("%s is not a folder", opt.out);
        return 2;
    }

    printf("noctree-bench %s: exact accuracy unless said, the efficient library, one "
           "thread%s\n", NOCT_VERSION_STRING, opt.quick ? ", QUICK MODE (timings "
           "are not meaningful)" : "");
    int status = 0;
    if (opt.sections & SEC_TABLE1) {
        static const char *full[] = {"planes:0", "planes:1", "planes:2", "planes:3",
                                     "planes:4", "planes:5", "planes:6", "planes:7",
                                     "planes:8", "planes:9", "planes:10"};
        size_t n = opt.quick ? 4 : 11;
        int repeats = opt.repeats ? opt.repeats : opt.quick ? 3 : 5;
        int steps = opt.steps ? opt.steps : opt.quick ? 20 : 200;
        timing tm[11];
        if (timing_section("Table 1, reproduced: the report's test sets t0 ... t10",
                           "table1.csv", full, n, repeats, steps, tm)) {
            timing_report("table1-stats.csv", "table1-medians.csv", tm, n, repeats, steps);
            char ylabel[64];
            snprintf(ylabel, sizeof ylabel, "seconds for %d steps", steps);
            timing_plot(&(timing_chart){
                .name = "fig9", .medians = "table1-medians.csv",
                .title = "Figure 9: test set size against time (log scales)",
                .ylabel = ylabel, .scale = 1, .logscale = true});
            timing_plot(&(timing_chart){
                .name = "fig10", .medians = "table1-medians.csv",
                .title = "Figure 10: the right-hand side of Figure 9, as speed-ups",
                .ylabel = "times faster than the exhaustive algorithm (its time / the time at N)",
                .speedup = true, .xmin = opt.quick ? 0 : 338});
        } else {
            status = 1;
        }
    }
    if (opt.sections & SEC_SCALE) {
        static const char *full[] = {"planes:30", "planes:50", "planes:100", "planes:300",
                                     "gas:10000", "gas:100000"};
        static const char *quick[] = {"planes:6", "gas:500"};
        size_t n = opt.quick ? 2 : 6;
        int repeats = opt.repeats ? opt.repeats : 3;
        int steps = opt.steps ? opt.steps : opt.quick ? 10 : 50;
        timing tm[6];
        if (timing_section("At scale", "scale.csv", opt.quick ? quick : full, n, repeats,
                           steps, tm)) {
            timing_report("scale-stats.csv", "scale-medians.csv", tm, n, repeats, steps);
            timing_plot(&(timing_chart){
                .name = "scaling", .medians = "scale-medians.csv",
                .title = "Scaling: ns per object per step (planes and gas)",
                .ylabel = "ns per object per step", .scale = 1e9 / steps,
                .per_object = true, .logscale = true, .xmin = opt.quick ? 1 : 1000,
                .has_gas = true});
        } else {
            status = 1;
        }
    }
    if (status == 0 && (opt.sections & SEC_STAGES)) {
        static const char *full[] = {"planes:10", "planes:30", "gas:1000", "gas:10000"};
        static const char *quick[] = {"planes:3", "gas:200"};
        if (!stages_section(opt.quick ? quick : full, opt.quick ? 2 : 4, NOCT_AUTO,
                            opt.repeats ? opt.repeats : 3,
                            opt.steps ? opt.steps : opt.quick ? 20 : 200))
            status = 1;
    }
    if (status == 0 && (opt.sections & SEC_ACCURACY)) {
        static const char *full[] = {"planes:10", "gas:1000", "notch:64", "bullets:1000",
                                     "gas:1000+spin"};
        static const char *quick[] = {"planes:2", "gas:100", "notch:8", "bullets:200",
                                      "gas:100+spin"};
        size_t objects[5] = {0};
        const char *const *specs = opt.quick ? quick : full;
        if (accuracy_section(specs, 5, opt.repeats ? opt.repeats : 3,
                             opt.steps ? opt.steps : opt.quick ? 60 : 200, objects, specs[3],
                             opt.quick ? "gas:1000" : "gas:10000"))
            accuracy_plot(specs, objects, 5);
        else
            status = 1;
    }
    printf("\nCSV files%s in %s/\n", opt.plots && have_gnuplot() ? " and plots" : "",
           opt.out);
    return status;
}
