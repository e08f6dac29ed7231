/* SPDX-License-Identifier: MIT */
/*
 * noctree-sim: run a scene (a file, or a built-in family) in the collision
 * world and report its contact events and where the time went.
 * See noctree-sim(1) and noctree-scene(5).
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <noctree.h>

#include "toolutil.h"

static const char usage[] =
    "usage: noctree-sim [OPTIONS] SCENE-FILE\n"
    "       noctree-sim [OPTIONS] --scene planes:K|gas:N\n"
    "Run a scene in the libnoctree collision world.\n"
    "\n"
    "  --scene FAMILY        a built-in scene: planes:K (the report's t_K) or gas:N\n"
    "  --N N|big             most objects per octree leaf (big: exhaustive)\n"
    "  --max-depth D         deepest octree level, 1 to 40\n"
    "  --accuracy LEVEL      box, convex or exact\n"
    "  --maintenance MODE    incremental or rebuild\n"
    "  --steps S             number of steps\n"
    "  --substep             split steps so fast objects cannot pass through others\n"
    "  --events              print every contact event: STEP begin|end A B\n"
    "                        (and sensor-begin|sensor-end for sensors)\n"
    "  --quiet               no progress bar\n"
    "  --help                this text\n"
    "  --version             the version\n"
    "\n"
    "Exit status: 0 on success, 1 if the simulation failed, 2 for bad usage or input.\n";

int main(int argc, char **argv)
{
    tool_scene_args sa = {0};
    const char *opt_acc = NULL,
               *opt_maint = NULL;
    long steps = 0;
    bool events = false, quiet = false, substep = false;
    tool_name = "noctree-sim";
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i];
        bool has_value = i + 1 < argc;
        if (strcmp(a, "--help") == 0) {
            fputs(usage, stdout);
            return 0;
        } else if (strcmp(a, "--version") == 0) {
            printf("noctree-sim %s\n", NOCT_VERSION_STRING);
            return 0;
        } else if (strcmp(a, "--events") == 0) {
            events = true;
        } else if (strcmp(a, "--quiet") == 0) {
            quiet = true;
        } else if (strcmp(a, "--substep") == 0) {
            substep = true;
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

    noctScene *scene;
    noctError err;
    int bad = tool_scene_load(&sa, &scene);
    if (bad)
        return bad;
    noctWorldDef *def = noctSceneDef(scene);
    if (opt_acc != NULL && !tool_parse_accuracy(opt_acc, &def->accuracy))
        return noctSceneDestroy(scene), tool_usage_error("--accuracy must be box, convex or exact, not '%s'", opt_acc);
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
    int nsteps = steps > 0 ? (int)steps : noctSceneSteps(scene);

    noctWorld *w;
    if (noctSceneBuild(scene, &w, &err) != NOCT_OK) {
        tool_error("%s", err.message);
        noctSceneDestroy(scene);
        return 2;
    }
    double ratio = noctWorldMaxStepRatio(w);
    if (ratio > 0.5 && !(def->effects & NOCT_EFFECT_SUBSTEP))
        tool_error("warning: an object moves %.2f times its smallest "
                "size per step; objects can pass through each other unseen (the "
                "report's fidelity constraint): use --substep", ratio);
    bool bar = !quiet && !events && isatty(STDERR_FILENO);
    size_t begins = 0, ends = 0, sensor_events = 0;
    int status = 0;
    for (int s = 1; s <= nsteps; ++s) {
        if (noctWorldStep(w, &err) != NOCT_OK) {
            tool_error("step %d: %s", s, err.message);
            status = 1;
            break;
        }
        const noctPair *p;
        size_t nb = noctWorldBegan(w, &p);
        begins += nb;
        for (size_t i = 0; events && i < nb; ++i)
            printf("%d begin %u %u\n", s, p[i].a.index, p[i].b.index);
        size_t ne = noctWorldEnded(w, &p);
        ends += ne;
        for (size_t i = 0; events && i < ne; ++i)
            printf("%d end %u %u\n", s, p[i].a.index, p[i].b.index);
        nb = noctWorldSensorBegan(w, &p);
        sensor_events += nb;
        for (size_t i = 0; events && i < nb; ++i)
            printf("%d sensor-begin %u %u\n", s, p[i].a.index, p[i].b.index);
        ne = noctWorldSensorEnded(w, &p);
        sensor_events += ne;
        for (size_t i = 0; events && i < ne; ++i)
            printf("%d sensor-end %u %u\n", s, p[i].a.index, p[i].b.index);
        if (s % 5 == 0 || s == nsteps) {
            char label[48];
            snprintf(label, sizeof label, "step %d/%d", s, nsteps);
            tool_progress(bar, s, nsteps, label);
        }
    }
    if (status == 0) {
        noctWorldCounters c;
        noctWorldGetCounters(w, &c);
        const noctPair *p;
        double total = c.seconds_motion + c.seconds_maintenance + c.seconds_pairs +
                       c.seconds_response;
        printf("objects %zu\nsteps %d\nN %s%.0d\naccuracy %s\n", noctWorldObjectCount(w),
               nsteps, def->N == NOCT_N_EXHAUSTIVE ? "big" : "",
               def->N == NOCT_N_EXHAUSTIVE ? 0 : def->N, noctAccuracyName(def->accuracy));
        printf("contact begins %zu\ncontact ends %zu\ncolliding at the end %zu\n", begins,
               ends, noctWorldColliding(w, &p));
        if (sensor_events > 0 || noctWorldSensing(w, &p) > 0)
            printf("sensor events %zu\nsensing at the end %zu\n", sensor_events,
                   noctWorldSensing(w, &p));
        double levels = c.narrow.seconds_convex + c.narrow.seconds_exact;
        printf("time per step %.3f ms (motion %.3f, maintenance %.3f, pair search and "
               "box tests %.3f, convex level %.3f, exact level %.3f, events and "
               "response %.3f)\n",
               1e3 * total / nsteps, 1e3 * c.seconds_motion / nsteps,
               1e3 * c.seconds_maintenance / nsteps,
               1e3 * (c.seconds_pairs - levels) / nsteps,
               1e3 * c.narrow.seconds_convex / nsteps, 1e3 * c.narrow.seconds_exact / nsteps,
               1e3 * c.seconds_response / nsteps);
        printf("per step: %.1f candidate pairs, %.1f tested, %.1f colliding; %.1f "
               "neighbor queries, %.2f splits, %.2f merges\n",
               (double)c.candidate_pairs / nsteps, (double)c.tested_pairs / nsteps,
               (double)c.colliding_pairs / nsteps, (double)c.neighbor_queries / nsteps,
               (double)c.splits / nsteps, (double)c.merges / nsteps);
    }
    noctWorldDestroy(w);
    noctSceneDestroy(scene);
    return status;
}
