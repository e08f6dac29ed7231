/* SPDX-License-Identifier: MIT */
/*
 * bench-world: the collision world on the built-in families (noctree-families(7)).
 *
 * For each scene and N (5, 10, 30 and 50 at depth 8, and the defaults:
 * both chosen by the world): per-step wall time (median and 90th percentile
 * over the steps), ns per object per step, setup time, the contact-begin
 * events (which must not depend on N), the peak memory of the run, and the
 * ratio of the exhaustive algorithm's median to this N's. Each run is a
 * child process, so its peak memory is its own. Exhaustive runs are left
 * out above --max-exhaustive objects (default 2000): they cost n^2 per
 * step, and no figure is extrapolated here. Writes bench-world.csv.
 *
 * Usage: bench-world [--quick] [--overlap] [--steps S] [--max-exhaustive N]
 *                    [SCENE...]
 *        bench-world --rays Q [--repeats R] [gas:N...]
 *        bench-world --margin D [--quick] [--steps S] [FAMILY:N...]
 *   SCENE is planes:K or gas:N (default planes:10 planes:30 planes:100
 *   planes:300 gas:10000 gas:100000, which takes several minutes; rows
 *   are printed as they finish; --quick: planes:3 gas:200, 20 steps).
 *   --overlap: instead, the overlap workloads of world.h's overlap rule
 *   (coincident objects added, 10^5 and 10^6; coincident objects added
 *   and stepped, 10^3 and 10^4, whose every pair collides; a pile of
 *   touching cubes, 10^4 and 10^5) at the defaults (the settings the
 *   world chose, marked a:), at N = 1 and at max-depth 40, with time and
 *   peak memory; with --quick, small sizes that only check it runs.
 *   --rays Q: instead, Q segments across each gas scene's container
 *   (default gas:10000 gas:100000), closest and all hits (rays_bench()).
 *   --margin D: instead, what a margin of D costs the step: each SCENE
 *   (any family, default keyframes:2000 gas:100000) built twice, without
 *   a margin and with D, the two worlds stepped in turn in this one
 *   process, every noctWorldStep() call timed whole (the tracks'
 *   placements included); median and mean per step and their ratios
 *   (margin_bench()).
 *   --sweep: instead, N and the maximum depth over every family of
 *   noctSceneFamily() at 1 000 to 1 000 000 objects (--sizes, --families,
 *   --repeats; see sweep_bench()), the defaults marked; writes
 *   bench-sweep.csv.
 */
#define _DEFAULT_SOURCE /* wait4(2): the peak memory of one child */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <noctree/query.h>
#include <noctree/scene.h>
#include <noctree/world.h>

#include "benchutil.h"

typedef struct result {
    double median, p90, setup;
    size_t objects, begins;
    int ok;
} result;

/* Run one configuration, the family as noctSceneFamily() makes it;
 * called in a child process. Exhaustive runs above max_exhaustive
 * objects are skipped (ok = 2). */
static result run(const char *scene, int N, int steps, int max_exhaustive)
{
    result r = {0};
    noctScene *sc;
    noctError err;
    if (noctSceneFamily(scene, &sc, &err) != NOCT_OK) {
        fprintf(stderr, "bench-world: %s: %s\n", scene, err.message);
        return r;
    }
    noctSceneDef(sc)->N = N;
    noctSceneDef(sc)->max_depth = N == NOCT_AUTO ? NOCT_AUTO : 8;
    double t0 = tool_now();
    noctWorld *w;
    if (noctSceneBuild(sc, &w, &err) != NOCT_OK) {
        fprintf(stderr, "bench-world: %s: %s\n", scene, err.message);
        return r;
    }
    r.setup = tool_now() - t0;
    r.objects = noctWorldObjectCount(w);
    if (N == NOCT_N_EXHAUSTIVE && r.objects > (size_t)max_exhaustive) {
        r.ok = 2;
        noctWorldDestroy(w);
        noctSceneDestroy(sc);
        return r;
    }
    double *t = malloc((size_t)steps * sizeof *t);
    for (int s = 0; s < steps; ++s) {
        double a = tool_now();
        if (noctWorldStep(w, &err) != NOCT_OK) {
            fprintf(stderr, "bench-world: %s: %s\n", scene, err.message);
            return r;
        }
        t[s] = tool_now() - a;
        const noctPair *p;
        r.begins += noctWorldBegan(w, &p);
    }
    tool_sort(t, (size_t)steps);
    r.median = tool_rank(t, (size_t)steps, 1, 2);
    r.p90 = tool_rank(t, (size_t)steps, 9, 10);
    r.ok = 1;
    free(t);
    noctWorldDestroy(w);
    noctSceneDestroy(sc);
    return r;
}

/* Run fn(arg, out) in a child process, so that the peak memory it reports
 * (*peak_kib) is the run's own, and copy its size-byte result to out.
 * False if the child could not be run or failed. */
static bool in_child(void (*fn)(const void *arg, void *out), const void *arg, void *out,
                     size_t size, long *peak_kib)
{
    int fds[2];
    if (pipe(fds) != 0) {
        perror("bench-world: pipe");
        return false;
    }
    fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) {
        close(fds[0]);
        fn(arg, out);
        ssize_t wr = write(fds[1], out, size);
        _exit(wr == (ssize_t)size ? 0 : 1);
    }
    close(fds[1]);
    ssize_t got = pid > 0 ? read(fds[0], out, size) : -1;
    close(fds[0]);
    int status;
    struct rusage ru;
    if (pid < 0 || wait4(pid, &status, 0, &ru) < 0)
        return false;
    *peak_kib = ru.ru_maxrss;
    return got == (ssize_t)size && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

/* ---- overlap: bounded work whatever the objects share ------------------- */

typedef struct overlap_result {
    double add_s, step_s;
    size_t objects, pairs;
    int N, depth; /* in force at the end */
    int ok;
} overlap_result;

/* One overlap workload in a child process: n coincident unit boxes
 * (kind 0, added only; kind 1, added and stepped) or a k x k x k pile of
 * touching unit cubes (kind 2, n = k^3, added and stepped). */
static overlap_result overlap_run(int kind, size_t n, int N, int depth)
{
    overlap_result r = {0};
    noctWorldDef def = noctDefaultWorldDef();
    def.N = N;
    def.max_depth = depth;
    noctMesh *cube = NULL;
    noctWorld *w = NULL;
    noctError err;
    if (noctMeshCreateBox(0.5, 0.5, 0.5, &cube, &err) != NOCT_OK ||
        noctWorldCreate(&def, &w, &err) != NOCT_OK) {
        fprintf(stderr, "bench-world: %s\n", err.message);
        return r;
    }
    size_t k = 1;
    while (kind == 2 && (k + 1) * (k + 1) * (k + 1) <= n)
        ++k;
    if (kind == 2)
        n = k * k * k;
    const double zero[3] = {0, 0, 0};
    double t0 = tool_now();
    for (size_t i = 0; i < n; ++i) {
        const double at[3] = {kind == 2 ? (double)(i % k) : 0.25,
                              kind == 2 ? (double)(i / k % k) : 0.25,
                              kind == 2 ? (double)(i / (k * k)) : 0.25};
        noctObjectId id;
        if (noctWorldAdd(w, cube, at, zero, 0, &id, &err) != NOCT_OK) {
            fprintf(stderr, "bench-world: add %zu: %s\n", i, err.message);
            return r;
        }
    }
    r.add_s = tool_now() - t0;
    r.objects = n;
    if (kind > 0) {
        t0 = tool_now();
        if (noctWorldStep(w, &err) != NOCT_OK) {
            fprintf(stderr, "bench-world: step: %s\n", err.message);
            return r;
        }
        r.step_s = tool_now() - t0;
        const noctPair *p;
        r.pairs = noctWorldColliding(w, &p);
    }
    noctBroadphaseGetSettings(noctWorldBroadphase(w), &r.N, &r.depth);
    noctWorldDestroy(w);
    noctMeshDestroy(cube);
    r.ok = 1;
    return r;
}

typedef struct overlap_job {
    int kind;
    size_t n;
    int N, depth;
} overlap_job;

static void overlap_child(const void *arg, void *out)
{
    const overlap_job *j = arg;
    *(overlap_result *)out = overlap_run(j->kind, j->n, j->N, j->depth);
}

/* Print the overlap workloads at the defaults, at N = 1 and at
 * max-depth 40, each at two sizes ten times apart: time and memory per
 * object (plus pair) that stay flat from the smaller to the larger size
 * are linear. */
static int overlap_bench(bool quick)
{
    static const int configs[][2] = {{NOCT_AUTO, NOCT_AUTO}, {1, 10}, {10, 40}};
    static const char *names[] = {"coincident, added", "coincident, added+stepped",
                                  "touching pile"};
    const size_t sizes[3][2] = {{quick ? 1000 : 100000, quick ? 10000 : 1000000},
                                {quick ? 100 : 1000, quick ? 300 : 10000},
                                {quick ? 125 : 10000, quick ? 1000 : 100000}};
    printf("\noverlap: work per object (and per colliding pair) at two sizes\n");
    printf("%-26s %6s %6s %9s %11s %9s %9s %10s %12s\n", "workload", "N", "depth",
           "objects", "pairs", "add s", "step s", "peak MiB", "ns/(obj+pr)");
    for (int kind = 0; kind < 3; ++kind)
        for (size_t c = 0; c < sizeof configs / sizeof *configs; ++c)
            for (int z = 0; z < 2; ++z) {
                const overlap_job job = {kind, sizes[kind][z], configs[c][0], configs[c][1]};
                overlap_result r = {0};
                long peak = 0;
                const bool ran = in_child(overlap_child, &job, &r, sizeof r, &peak);
                if (!ran || !r.ok) {
                    printf("%-26s %6d %6d   failed\n", names[kind], configs[c][0],
                           configs[c][1]);
                    return EXIT_FAILURE;
                }
                /* the settings in force, "a:" when the world chose them */
                char nb[16], db[16];
                snprintf(nb, sizeof nb, "%s%d", configs[c][0] == NOCT_AUTO ? "a:" : "", r.N);
                snprintf(db, sizeof db, "%s%d", configs[c][1] == NOCT_AUTO ? "a:" : "",
                         r.depth);
                printf("%-26s %6s %6s %9zu %11zu %9.3f %9.3f %10.1f %12.1f\n", names[kind], nb,
                       db, r.objects, r.pairs, r.add_s, r.step_s, (double)peak / 1024,
                       1e9 * (r.add_s + r.step_s) / (double)(r.objects + r.pairs));
            }
    return 0;
}


/* ---- sweep: N and the depth over every family, the automatic choice marked -- */

/* The sweep's families: a name and how its size spec is made for about n
 * objects (0: not at that size). */
static const char *const SWEEP_FAMILIES[] = {"planes", "gas",    "mixed",     "clusters",
                                             "static", "escape", "keyframes", "arms"};
#define SWEEP_NFAMILIES (sizeof SWEEP_FAMILIES / sizeof *SWEEP_FAMILIES)

/* The spec of family f at about n objects into buf; false if the family
 * has no such size (keyframes stop at 10^5; arms is one size, shown with
 * 1 000). */
static bool sweep_spec(size_t f, long n, char *buf, size_t size)
{
    const char *name = SWEEP_FAMILIES[f];
    if (strcmp(name, "planes") == 0) {
        long k = 0; /* the t_k with 2 (2k+1)^2 nearest n */
        while (labs(2 * (2 * (k + 1) + 1) * (2 * (k + 1) + 1) - n) <
               labs(2 * (2 * k + 1) * (2 * k + 1) - n))
            ++k;
        snprintf(buf, size, "planes:%ld", k);
    } else if (strcmp(name, "arms") == 0) {
        if (n != 1000)
            return false;
        snprintf(buf, size, "arms:8");
    } else if (strcmp(name, "keyframes") == 0 && n > 100000) {
        return false;
    } else {
        snprintf(buf, size, "%s:%ld", name, n);
    }
    return true;
}

typedef struct sweep_job {
    char spec[32];
    int N, depth, steps;
} sweep_job;

typedef struct sweep_result {
    double median, setup;
    size_t objects, begins;
    int N, depth; /* in force after the last step */
    int ok;
} sweep_result;

/* One configuration in a child process: the family as noctSceneFamily()
 * makes it, at N and depth (NOCT_AUTO for the choice), steps steps. */
static void sweep_child(const void *arg, void *out)
{
    const sweep_job *j = arg;
    sweep_result *r = out;
    memset(r, 0, sizeof *r);
    noctScene *sc;
    noctWorld *w;
    noctError err;
    if (noctSceneFamily(j->spec, &sc, &err) != NOCT_OK) {
        fprintf(stderr, "bench-world: %s: %s\n", j->spec, err.message);
        return;
    }
    noctSceneDef(sc)->N = j->N;
    noctSceneDef(sc)->max_depth = j->depth;
    double t0 = tool_now();
    if (noctSceneBuild(sc, &w, &err) != NOCT_OK) {
        fprintf(stderr, "bench-world: %s: %s\n", j->spec, err.message);
        return;
    }
    r->setup = tool_now() - t0;
    r->objects = noctWorldObjectCount(w);
    double *t = malloc((size_t)j->steps * sizeof *t);
    for (int s = 0; s < j->steps; ++s) {
        double a = tool_now();
        if (noctWorldStep(w, &err) != NOCT_OK) {
            fprintf(stderr, "bench-world: %s: %s\n", j->spec, err.message);
            return;
        }
        t[s] = tool_now() - a;
        const noctPair *p;
        r->begins += noctWorldBegan(w, &p);
    }
    tool_sort(t, (size_t)j->steps);
    r->median = tool_rank(t, (size_t)j->steps, 1, 2);
    noctBroadphaseGetSettings(noctWorldBroadphase(w), &r->N, &r->depth);
    free(t);
    noctWorldDestroy(w);
    noctSceneDestroy(sc);
    r->ok = 1;
}

#define SWEEP_MAX_CONFIGS 16
#define SWEEP_MAX_REPEATS 9

/*
 * For each family and size: N in {5, 10, 20, 30, 50, 80, 128} at the
 * automatic depth, the depths 6, 8, 10 and 14 at the automatic N, and the
 * defaults (both automatic); each configuration repeats times, the
 * configurations taking turns in every repeat, in a new order each time;
 * a row is the median over
 * the repeats of each run's median step, and the peak memory's median.
 * Under each family and size: the defaults' step time and memory over
 * those of the fastest hand-picked setting (the sweep's best). The events
 * must not depend on the settings: the tool fails if they do.
 */
static int sweep_bench(const long *sizes, int nsizes, const char *const *fams, int nfams,
                       int repeats, int steps_arg)
{
    static const int sweep_N[] = {5, 10, 20, 30, 50, 80, 128};
    static const int sweep_depth[] = {6, 8, 10, 14};
    FILE *csv = tool_open_csv("bench-sweep.csv", "family,size,objects,setting,N,depth,steps,"
                                                 "repeats,median_s,setup_s,begins,peak_kib");
    if (csv == NULL)
        return EXIT_FAILURE;
    printf("sweep: N and the maximum depth, each row the median of %d interleaved runs\n",
           repeats);
    printf("%-16s %8s %-14s %4s %5s %11s %9s %10s %9s\n", "scene", "objects", "setting", "N",
           "depth", "median ms", "setup s", "peak MiB", "begins");
    int status = EXIT_SUCCESS;
    for (int si = 0; si < nsizes; ++si)
        for (size_t f = 0; f < SWEEP_NFAMILIES; ++f) {
            bool wanted = nfams == 0;
            for (int i = 0; i < nfams; ++i)
                wanted = wanted || strcmp(fams[i], SWEEP_FAMILIES[f]) == 0;
            sweep_job base;
            if (!wanted || !sweep_spec(f, sizes[si], base.spec, sizeof base.spec))
                continue;
            /* fewer steps for the largest sizes: a step of 10^6 objects
             * takes about a second at small N */
            base.steps = steps_arg > 0 ? steps_arg : sizes[si] >= 1000000 ? 10
                                                 : sizes[si] >= 100000   ? 40
                                                                         : 100;
            sweep_job jobs[SWEEP_MAX_CONFIGS];
            char names[SWEEP_MAX_CONFIGS][16];
            int nj = 0;
            jobs[nj] = base;
            jobs[nj].N = jobs[nj].depth = NOCT_AUTO;
            snprintf(names[nj++], sizeof *names, "defaults");
            for (size_t i = 0; i < sizeof sweep_N / sizeof *sweep_N; ++i) {
                jobs[nj] = base;
                jobs[nj].N = sweep_N[i];
                jobs[nj].depth = NOCT_AUTO;
                snprintf(names[nj++], sizeof *names, "N %d", sweep_N[i]);
            }
            for (size_t i = 0; i < sizeof sweep_depth / sizeof *sweep_depth; ++i) {
                jobs[nj] = base;
                jobs[nj].N = NOCT_AUTO;
                jobs[nj].depth = sweep_depth[i];
                snprintf(names[nj++], sizeof *names, "depth %d", sweep_depth[i]);
            }
            double med[SWEEP_MAX_CONFIGS][SWEEP_MAX_REPEATS];
            double peak[SWEEP_MAX_CONFIGS][SWEEP_MAX_REPEATS];
            sweep_result res[SWEEP_MAX_CONFIGS];
            bool failed = false;
            /* each round in a new order (a seeded shuffle), so that
             * neither the machine's drift nor a place in the round
             * favours a configuration */
            uint64_t seed = 0x5eedu + (uint64_t)si * 131 + f;
            int order[SWEEP_MAX_CONFIGS];
            for (int j = 0; j < nj; ++j)
                order[j] = j;
            for (int rep = 0; rep < repeats && !failed; ++rep) {
                for (int j = nj - 1; j > 0; --j) {
                    seed = seed * 6364136223846793005u + 1442695040888963407u;
                    const int k = (int)((seed >> 33) % (uint64_t)(j + 1)), t = order[j];
                    order[j] = order[k];
                    order[k] = t;
                }
                for (int jj = 0; jj < nj && !failed; ++jj) {
                    const int j = order[jj];
                    long kib = 0;
                    failed = !in_child(sweep_child, &jobs[j], &res[j], sizeof res[j], &kib) ||
                             !res[j].ok;
                    med[j][rep] = res[j].median;
                    peak[j][rep] = (double)kib;
                }
                for (int j = 0; j < nj && !failed; ++j)
                    if (res[j].begins != res[0].begins) {
                        printf("%-16s %s gives %zu begins, the defaults %zu: events differ\n",
                               base.spec, names[j], res[j].begins, res[0].begins);
                        failed = true;
                    }
            }
            if (failed) {
                printf("%-16s failed\n", base.spec);
                status = EXIT_FAILURE;
                continue;
            }
            double m[SWEEP_MAX_CONFIGS], pk[SWEEP_MAX_CONFIGS];
            int best = 1;
            for (int j = 0; j < nj; ++j) {
                m[j] = tool_median(med[j], (size_t)repeats);
                pk[j] = tool_median(peak[j], (size_t)repeats);
                if (j > 0 && m[j] < m[best])
                    best = j;
                printf("%-16s %8zu %-14s %4d %5d %11.3f %9.2f %10.1f %9zu\n", base.spec,
                       res[j].objects, names[j], res[j].N, res[j].depth, 1e3 * m[j],
                       res[j].setup, pk[j] / 1024, res[j].begins);
                fprintf(csv, "%s,%ld,%zu,%s,%d,%d,%d,%d,%.6g,%.4f,%zu,%.0f\n",
                        SWEEP_FAMILIES[f], sizes[si], res[j].objects, names[j], res[j].N,
                        res[j].depth, base.steps, repeats, m[j], res[j].setup, res[j].begins,
                        pk[j]);
            }
            printf("%-16s defaults/best (%s): time %.2f, memory %.2f\n", base.spec,
                   names[best], m[0] / m[best], pk[0] / pk[best]);
            fflush(stdout);
        }
    fclose(csv);
    puts("(defaults: N and depth chosen by the world; each hand-picked row keeps the other "
         "automatic; raw figures in bench-sweep.csv)");
    return status;
}

/* ---- rays: segments across a whole gas container ----------------------------- */

/* For each gas scene, q segments from a random point of the container's
 * face x = 0 to one of the face x = side (so each crosses every layer of
 * the gas), cast as noctWorldRayCastClosest() and as noctWorldRayCast()
 * (every hit): us per segment (median of the repeats) and the hits found.
 * A closest cast should cost about what the gas before its first hit
 * costs, however long the segment. */
static bool count_ray_hit(void *context, const noctRayHit *hit)
{
    (void)hit;
    ++*(size_t *)context;
    return true;
}

static int rays_bench(const char *const *scenes, int nscenes, int q, int repeats)
{
    printf("segments across the container, %d per scene, median of %d runs\n", q, repeats);
    printf("%-12s %8s %-8s %10s %10s\n", "scene", "objects", "cast", "us each", "found");
    for (int s = 0; s < nscenes; ++s) {
        if (strncmp(scenes[s], "gas:", 4) != 0) {
            fprintf(stderr, "bench-world: --rays runs on gas scenes only: %s\n", scenes[s]);
            return EXIT_FAILURE;
        }
        const size_t n = (size_t)atol(scenes[s] + 4);
        const double side = noctGasContainerSize(n);
        noctScene *sc;
        noctWorld *w;
        noctError err;
        if (noctSceneFamily(scenes[s], &sc, &err) != NOCT_OK ||
            noctSceneBuild(sc, &w, &err) != NOCT_OK) {
            fprintf(stderr, "bench-world: %s: %s\n", scenes[s], err.message);
            return EXIT_FAILURE;
        }
        noctSceneDestroy(sc);
        double *seg = malloc((size_t)q * 6 * sizeof *seg), times[2][16];
        if (seg == NULL)
            return EXIT_FAILURE;
        uint64_t st = 12345;
        for (int i = 0; i < 6 * q; ++i) {
            st = st * 6364136223846793005u + 1442695040888963407u;
            seg[i] = side * (double)(st >> 11) * 0x1p-53;
        }
        for (int i = 0; i < q; ++i) { /* (0, y, z) to (side, y', z') */
            double *g = seg + 6 * i;
            g[0] = 0;
            g[3] = side;
            g[4] -= g[1];
            g[5] -= g[2];
        }
        const noctQueryFilter all = noctDefaultQueryFilter();
        size_t found[2] = {0, 0};
        bool ok = true;
        for (int r = 0; r < repeats; ++r) {
            found[0] = found[1] = 0;
            double t = tool_now();
            for (int i = 0; i < q; ++i) {
                noctRayHit h;
                bool any;
                ok = ok && noctWorldRayCastClosest(w, seg + 6 * i, seg + 6 * i + 3, all, &h,
                                                   &any, &err) == NOCT_OK;
                found[0] += any;
            }
            times[0][r] = tool_now() - t;
            t = tool_now();
            for (int i = 0; i < q; ++i)
                ok = ok && noctWorldRayCast(w, seg + 6 * i, seg + 6 * i + 3, all,
                                            count_ray_hit, &found[1], &err) == NOCT_OK;
            times[1][r] = tool_now() - t;
        }
        noctWorldDestroy(w);
        free(seg);
        if (!ok) {
            fprintf(stderr, "bench-world: %s: %s\n", scenes[s], err.message);
            return EXIT_FAILURE;
        }
        for (int c = 0; c < 2; ++c) {
            printf("%-12s %8zu %-8s %10.2f %10zu\n", scenes[s], n, c ? "all" : "closest",
                   1e6 * tool_median(times[c], (size_t)repeats) / q, found[c]);
        }
    }
    return EXIT_SUCCESS;
}

/*
 * --margin D: the same scene without a margin and with D, the two worlds
 * stepped in turn (one step of each, then the next), so that both see the
 * same machine; each noctWorldStep() timed whole. The margin changes no
 * motion (near pairs are reported, not answered), so both worlds run the
 * same steps.
 */
static int margin_bench(const char *const *scenes, int nscenes, double margin, int steps)
{
    printf("what a margin of %g costs a step: %d steps of each world, in turn, "
           "noctWorldStep() timed whole\n", margin, steps);
    printf("%-16s %8s %11s %11s %11s %11s %8s %8s %10s\n", "scene", "objects",
           "median ms", "margin ms", "mean ms", "margin ms", "x median", "x mean",
           "near/step");
    for (int s = 0; s < nscenes; ++s) {
        noctWorld *w[2] = {NULL, NULL};
        noctError err;
        for (int k = 0; k < 2; ++k) {
            noctScene *sc;
            if (noctSceneFamily(scenes[s], &sc, &err) != NOCT_OK) {
                fprintf(stderr, "bench-world: %s: %s\n", scenes[s], err.message);
                noctWorldDestroy(w[0]);
                return EXIT_FAILURE;
            }
            noctSceneDef(sc)->margin = k == 0 ? 0 : margin;
            noctStatus st = noctSceneBuild(sc, &w[k], &err);
            noctSceneDestroy(sc);
            if (st != NOCT_OK) {
                fprintf(stderr, "bench-world: %s: %s\n", scenes[s], err.message);
                noctWorldDestroy(w[0]);
                return EXIT_FAILURE;
            }
        }
        double *t = malloc(2 * (size_t)steps * sizeof *t), sum[2] = {0, 0};
        if (t == NULL) {
            noctWorldDestroy(w[0]);
            noctWorldDestroy(w[1]);
            fputs("bench-world: out of memory\n", stderr);
            return EXIT_FAILURE;
        }
        size_t near = 0;
        for (int i = 0; i < steps; ++i) {
            for (int k = 0; k < 2; ++k) {
                double a = tool_now();
                if (noctWorldStep(w[k], &err) != NOCT_OK) {
                    fprintf(stderr, "bench-world: %s: %s\n", scenes[s], err.message);
                    free(t);
                    noctWorldDestroy(w[0]);
                    noctWorldDestroy(w[1]);
                    return EXIT_FAILURE;
                }
                t[(size_t)k * (size_t)steps + (size_t)i] = tool_now() - a;
                sum[k] += t[(size_t)k * (size_t)steps + (size_t)i];
            }
            const noctPair *p;
            near += noctWorldNear(w[1], &p);
        }
        double med[2];
        for (int k = 0; k < 2; ++k) {
            tool_sort(t + (size_t)k * (size_t)steps, (size_t)steps);
            med[k] = tool_rank(t + (size_t)k * (size_t)steps, (size_t)steps, 1, 2);
        }
        printf("%-16s %8zu %11.3f %11.3f %11.3f %11.3f %8.2f %8.2f %10.1f\n", scenes[s],
               noctWorldObjectCount(w[0]), 1e3 * med[0], 1e3 * med[1], 1e3 * sum[0] / steps,
               1e3 * sum[1] / steps, med[1] / med[0], sum[1] / sum[0], (double)near / steps);
        fflush(stdout);
        free(t);
        noctWorldDestroy(w[0]);
        noctWorldDestroy(w[1]);
    }
    return EXIT_SUCCESS;
}

typedef struct scene_job {
    const char *scene;
    int N, steps, max_exhaustive;
} scene_job;

/* One row of the scene table; the exhaustive run is skipped (ok 2) above
 * the cap. */
static void scene_child(const void *arg, void *out)
{
    const scene_job *j = arg;
    result *r = out;
    *r = run(j->scene, j->N, j->steps, j->max_exhaustive);
}

int main(int argc, char **argv)
{
    int steps = 200, max_exhaustive = 2000, nscenes = 0, repeats = 3, nsizes = 0;
    int nfams = 0;
    const char *scenes[32], *fams[SWEEP_NFAMILIES];
    long sizes[8];
    bool quick = false, overlap = false, sweep = false, steps_given = false;
    int rays = 0;
    double margin = -1;
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--quick") == 0)
            quick = true;
        else if (strcmp(argv[i], "--overlap") == 0)
            overlap = true;
        else if (strcmp(argv[i], "--sweep") == 0)
            sweep = true;
        else if (strcmp(argv[i], "--rays") == 0 && i + 1 < argc)
            rays = atoi(argv[++i]);
        else if (strcmp(argv[i], "--margin") == 0 && i + 1 < argc) {
            char *end;
            margin = strtod(argv[++i], &end);
            if (end == argv[i] || *end != '\0' || !(margin > 0 && margin <= 1e100)) {
                fprintf(stderr, "bench-world: --margin must be a distance above 0, not '%s'\n",
                        argv[i]);
                return 2;
            }
        } else if (strcmp(argv[i], "--repeats") == 0 && i + 1 < argc)
            repeats = atoi(argv[++i]);
        else if (strcmp(argv[i], "--sizes") == 0 && i + 1 < argc) {
            for (char *tok = strtok(argv[++i], ","); tok != NULL && nsizes < 8;
                 tok = strtok(NULL, ","))
                sizes[nsizes++] = atol(tok);
        } else if (strcmp(argv[i], "--families") == 0 && i + 1 < argc) {
            for (char *tok = strtok(argv[++i], ","); tok != NULL && nfams < (int)SWEEP_NFAMILIES;
                 tok = strtok(NULL, ","))
                fams[nfams++] = tok;
        } else if (strcmp(argv[i], "--steps") == 0 && i + 1 < argc) {
            steps = atoi(argv[++i]);
            steps_given = true;
        }
        else if (strcmp(argv[i], "--max-exhaustive") == 0 && i + 1 < argc)
            max_exhaustive = atoi(argv[++i]);
        else if (strchr(argv[i], ':') != NULL &&
                 nscenes < 32)
            scenes[nscenes++] = argv[i];
        else {
            fprintf(stderr, "usage: bench-world [--quick] [--overlap] [--steps S] "
                            "[--max-exhaustive N] [planes:K | gas:N]...\n"
                            "       bench-world --sweep [--quick] [--sizes N,...] "
                            "[--families F,...] [--steps S] [--repeats R]\n"
                            "       bench-world --rays Q [--repeats R] [gas:N]...\n"
                            "       bench-world --margin D [--steps S] [FAMILY:N]...\n");
            return 2;
        }
    }
    if (overlap)
        return overlap_bench(quick);
    if (margin > 0) {
        const char *def_margin[] = {"keyframes:2000", "gas:100000"};
        if (steps < 1 || steps > 100000) {
            fputs("bench-world: --steps must be 1 to 100000\n", stderr);
            return 2;
        }
        if (quick)
            def_margin[0] = "keyframes:200", def_margin[1] = "gas:2000", steps = 20;
        return nscenes > 0 ? margin_bench(scenes, nscenes, margin, steps)
                           : margin_bench(def_margin, 2, margin, steps);
    }
    if (rays != 0) {
        if (rays < 1 || repeats < 1 || repeats > 15) {
            fputs("bench-world: --rays must be at least 1, --repeats 1 to 15\n", stderr);
            return 2;
        }
        static const char *def_gas[] = {"gas:10000", "gas:100000"};
        return nscenes > 0 ? rays_bench(scenes, nscenes, rays, repeats)
                           : rays_bench(def_gas, 2, rays, repeats);
    }
    if (sweep) {
        for (int f = 0; f < nfams; ++f) {
            bool known = false;
            for (size_t k = 0; k < SWEEP_NFAMILIES; ++k)
                known = known || strcmp(fams[f], SWEEP_FAMILIES[k]) == 0;
            if (!known) {
                fprintf(stderr, "bench-world: unknown family '%s'\n", fams[f]);
                return 2;
            }
        }
        for (int z = 0; z < nsizes; ++z)
            if (sizes[z] < 1 || sizes[z] > 10000000) {
                fputs("bench-world: --sizes must be 1 to 10000000\n", stderr);
                return 2;
            }
        if (repeats < 1 || repeats > SWEEP_MAX_REPEATS || (steps_given && (steps < 1 ||
                                                                          steps > 100000))) {
            fprintf(stderr, "bench-world: --repeats must be 1 to %d, --steps 1 to 100000\n",
                    SWEEP_MAX_REPEATS);
            return 2;
        }
        if (nsizes == 0) {
            static const long def_sizes[] = {1000, 10000, 100000, 1000000};
            nsizes = quick ? 1 : 4;
            sizes[0] = quick ? 300 : def_sizes[0];
            for (int z = 1; z < nsizes; ++z)
                sizes[z] = def_sizes[z];
        }
        if (quick) {
            repeats = 1;
            steps = 10;
            steps_given = true;
        }
        return sweep_bench(sizes, nsizes, fams, nfams, repeats, steps_given ? steps : 0);
    }
    if (steps < 1 || steps > 100000) {
        fputs("bench-world: --steps must be 1 to 100000\n", stderr);
        return 2;
    }
    if (nscenes == 0) {
        static const char *def_scenes[] = {"planes:10",  "planes:30", "planes:100",
                                           "planes:300", "gas:10000", "gas:100000"};
        static const char *quick_scenes[] = {"planes:3", "gas:200"};
        const char **src = quick ? quick_scenes : def_scenes;
        nscenes = quick ? 2 : 6;
        for (int i = 0; i < nscenes; ++i)
            scenes[i] = src[i];
    }
    if (quick)
        steps = 20;
    static const int Ns[] = {NOCT_N_EXHAUSTIVE, 5, 10, 30, 50, NOCT_AUTO};
    FILE *csv = tool_open_csv("bench-world.csv", "scene,objects,N,steps,median_s,p90_s,"
                                                 "ns_per_object_step,setup_s,begins,peak_kib,"
                                                 "exhaustive_ratio");
    if (csv == NULL)
        return EXIT_FAILURE;
    printf("collision world, %d steps per run, single thread\n", steps);
    printf("%-12s %8s %5s %11s %11s %9s %8s %8s %10s %8s\n", "scene", "objects", "N",
           "median ms", "p90 ms", "ns/obj", "setup s", "begins", "peak MiB",
           "big/N");
    for (int s = 0; s < nscenes; ++s) {
        double big_median = 0;
        for (size_t ni = 0; ni < sizeof Ns / sizeof *Ns; ++ni) {
            const scene_job job = {scenes[s], Ns[ni], steps, max_exhaustive};
            result r = {0};
            long peak = 0;
            const bool ran = in_child(scene_child, &job, &r, sizeof r, &peak);
            const char *nname = Ns[ni] == NOCT_N_EXHAUSTIVE ? "big"
                                : Ns[ni] == NOCT_AUTO       ? "auto"
                                                            : NULL;
            char nbuf[16];
            if (nname == NULL) {
                snprintf(nbuf, sizeof nbuf, "%d", Ns[ni]);
                nname = nbuf;
            }
            if (!ran || r.ok == 0) {
                printf("%-12s %8s %5s   failed\n", scenes[s], "", nname);
                continue;
            }
            if (r.ok == 2) {
                printf("%-12s %8s %5s   skipped: exhaustive above %d objects\n",
                       scenes[s], "", nname, max_exhaustive);
                continue;
            }
            if (Ns[ni] == NOCT_N_EXHAUSTIVE)
                big_median = r.median;
            double ratio = big_median > 0 ? big_median / r.median : 0;
            const double peak_mib = (double)peak / 1024;
            printf("%-12s %8zu %5s %11.3f %11.3f %9.0f %8.2f %8zu %10.1f ", scenes[s],
                   r.objects, nname, 1e3 * r.median, 1e3 * r.p90,
                   1e9 * r.median / (double)r.objects, r.setup, r.begins, peak_mib);
            if (ratio > 0)
                printf("%8.2f\n", ratio);
            else
                printf("%8s\n", "-");
            fprintf(csv, "%s,%zu,%s,%d,%.6g,%.6g,%.1f,%.3f,%zu,%ld,%.3f\n", scenes[s],
                    r.objects, nname, steps, r.median, r.p90,
                    1e9 * r.median / (double)r.objects, r.setup, r.begins, peak, ratio);
            fflush(stdout);
        }
    }
    fclose(csv);
    puts("(big/N: the exhaustive median over this N's, measured in this run; "
         "raw figures in bench-world.csv)");
    return EXIT_SUCCESS;
}
