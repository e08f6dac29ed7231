/* SPDX-License-Identifier: MIT */
/*
 * bench-ab: two builds of libnoctree in one process, step for step.
 *
 * Loads two shared libraries (say, the efficient library of main and of a
 * branch) with dlopen(3), each in its own namespace, builds the same
 * built-in family's scene in each, and steps them in turn: on even steps A first,
 * on odd steps B first, so that whatever the machine does to one does it
 * to the other. Prints per scene the median step of each, their ratio
 * B / A with the spread of the per-step ratios (their quartiles), the
 * ratio of their mean steps (B's total time over A's), and
 * fails if the two found different contact-begin counts (or, with a
 * margin, near-pair counts): a faster build that finds other pairs did
 * other work.
 *
 * Usage: bench-ab [--steps S] [--margin D] LIB_A LIB_B SCENE...
 *   SCENE is a built-in family (planes:K, gas:N, keyframes:N, ...); S
 *   defaults to the scene's own steps; D, a world margin (near pairs)
 *   set in both worlds (their near pairs' counts must agree too).
 * Exit status: 0, 1 if a run failed or the events differ, 2 for bad usage.
 */
#define _POSIX_C_SOURCE 200809L
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <noctree/scene.h>
#include <noctree/world.h>

#include "benchutil.h"

typedef struct lib {
    const char *path;
    void *handle;
    noctStatus (*family)(const char *, noctScene **, noctError *);
    noctWorldDef *(*def)(noctScene *);
    noctStatus (*build)(const noctScene *, noctWorld **, noctError *);
    int (*steps)(const noctScene *);
    void (*scene_destroy)(noctScene *);
    noctStatus (*step)(noctWorld *, noctError *);
    size_t (*began)(const noctWorld *, const noctPair **);
    size_t (*near)(const noctWorld *, const noctPair **);
    void (*destroy)(noctWorld *);
} lib;

/* Object pointers to function pointers: POSIX allows it for dlsym. */
#define SYM(l, field, name)                                                       \
    do {                                                                          \
        void *p = dlsym((l)->handle, name);                                       \
        if (p == NULL) {                                                          \
            fprintf(stderr, "bench-ab: %s: no %s\n", (l)->path, name);            \
            return 0;                                                             \
        }                                                                         \
        memcpy(&(l)->field, &p, sizeof p);                                        \
    } while (0)

static int load(lib *l, const char *path)
{
    l->path = path;
    l->handle = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (l->handle == NULL) {
        fprintf(stderr, "bench-ab: %s\n", dlerror());
        return 0;
    }
    SYM(l, family, "noctSceneFamily");
    SYM(l, def, "noctSceneDef");
    SYM(l, build, "noctSceneBuild");
    SYM(l, steps, "noctSceneSteps");
    SYM(l, scene_destroy, "noctSceneDestroy");
    SYM(l, step, "noctWorldStep");
    SYM(l, began, "noctWorldBegan");
    SYM(l, near, "noctWorldNear");
    SYM(l, destroy, "noctWorldDestroy");
    return 1;
}

/* Run one scene in both, with world margin D; 0 on failure. */
static int run(lib *ab, const char *spec, int steps_opt, double margin)
{
    noctScene *scene[2] = {NULL, NULL};
    noctWorld *world[2] = {NULL, NULL};
    noctError err;
    int ok = 1, steps = steps_opt;
    for (int i = 0; i < 2 && ok; ++i) {
        if (ab[i].family(spec, &scene[i], &err) == NOCT_OK)
            ab[i].def(scene[i])->margin = margin;
        if (scene[i] == NULL || ab[i].build(scene[i], &world[i], &err) != NOCT_OK) {
            fprintf(stderr, "bench-ab: %s with %s: %s\n", spec, ab[i].path, err.message);
            ok = 0;
        }
        if (ok && steps <= 0)
            steps = ab[i].steps(scene[i]);
    }
    double *t[2] = {calloc((size_t)steps + 1, sizeof(double)),
                    calloc((size_t)steps + 1, sizeof(double))};
    double *ratio = calloc((size_t)steps + 1, sizeof(double));
    size_t begins[2] = {0, 0}, nears[2] = {0, 0};
    if (t[0] == NULL || t[1] == NULL || ratio == NULL)
        ok = 0;
    for (int s = 0; s < steps && ok; ++s) {
        for (int turn = 0; turn < 2 && ok; ++turn) {
            const int i = (s + turn) % 2;
            const double t0 = tool_now();
            if (ab[i].step(world[i], &err) != NOCT_OK) {
                fprintf(stderr, "bench-ab: %s step %d with %s: %s\n", spec, s, ab[i].path,
                        err.message);
                ok = 0;
            }
            t[i][s] = tool_now() - t0;
            const noctPair *p;
            begins[i] += ab[i].began(world[i], &p);
            nears[i] += ab[i].near(world[i], &p);
        }
        ratio[s] = t[1][s] / t[0][s];
    }
    if (ok) {
        const size_t n = (size_t)steps;
        double sum[2] = {0, 0};
        for (size_t k = 0; k < n; ++k) {
            sum[0] += t[0][k];
            sum[1] += t[1][k];
        }
        tool_sort(t[0], n);
        tool_sort(t[1], n);
        tool_sort(ratio, n);
        printf("%-14s %6d %12.3f %12.3f %8.3f   %.3f-%.3f %8.3f %10zu%s\n", spec, steps,
               1e3 * tool_rank(t[0], n, 1, 2), 1e3 * tool_rank(t[1], n, 1, 2),
               tool_rank(ratio, n, 1, 2), tool_rank(ratio, n, 1, 4),
               tool_rank(ratio, n, 3, 4), sum[1] / sum[0], begins[0],
               begins[0] == begins[1] && nears[0] == nears[1] ? "" : "  EVENTS DIFFER");
        fflush(stdout);
        ok = begins[0] == begins[1] && nears[0] == nears[1];
    }
    for (int i = 0; i < 2; ++i) {
        if (world[i] != NULL)
            ab[i].destroy(world[i]);
        if (scene[i] != NULL)
            ab[i].scene_destroy(scene[i]);
        free(t[i]);
    }
    free(ratio);
    return ok;
}

int main(int argc, char **argv)
{
    int steps = 0, a = 1;
    double margin = 0;
    for (;;) {
        if (a + 1 < argc && strcmp(argv[a], "--steps") == 0) {
            steps = atoi(argv[a + 1]);
            a += 2;
            if (steps < 1) {
                fprintf(stderr, "bench-ab: --steps needs a positive count\n");
                return 2;
            }
        } else if (a + 1 < argc && strcmp(argv[a], "--margin") == 0) {
            char *end;
            margin = strtod(argv[a + 1], &end);
            a += 2;
            if (*end != '\0' || !(margin >= 0 && margin < 1e300)) {
                fprintf(stderr, "bench-ab: --margin needs a finite distance of 0 or more\n");
                return 2;
            }
        } else
            break;
    }
    if (argc - a < 3 || strcmp(argv[1], "--help") == 0) {
        fprintf(stderr, "usage: bench-ab [--steps S] [--margin D] LIB_A LIB_B SCENE...\n");
        return 2;
    }
    lib ab[2];
    memset(ab, 0, sizeof ab);
    if (!load(&ab[0], argv[a]) || !load(&ab[1], argv[a + 1]))
        return 1;
    printf("A: %s\nB: %s\n", argv[a], argv[a + 1]);
    printf("%-14s %6s %12s %12s %8s   %-11s %8s %10s\n", "scene", "steps", "A ms/step",
           "B ms/step", "B/A", "quartiles", "B/A mean", "begins");
    int ok = 1;
    for (int i = a + 2; i < argc; ++i)
        ok = run(ab, argv[i], steps, margin) && ok;
    dlclose(ab[0].handle);
    dlclose(ab[1].handle);
    return ok ? 0 : 1;
}
