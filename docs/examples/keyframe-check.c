/* SPDX-License-Identifier: MIT */
/*
 * keyframe-check: an animator's check of a keyframed scene, through the
 * library: what `noctree-sim --first SCENE` does.
 *
 * It reads a scene file (noctree-scene(5): objects with names and key
 * lines, as animation.scene beside this file), builds its world, steps it
 * frame by frame and stops at the first step after which two objects
 * collide. It prints that step, the two objects by name (or index) and
 * where they meet: the intersection of their placed bounding boxes or,
 * with continuous detection, the time within the step and a point where
 * they first touched. Its line is noctree-sim's, character for character.
 * Build and run it with
 *   cc keyframe-check.c $(pkg-config --cflags --libs noctree)
 *   ./a.out animation.scene
 */
#include <stdio.h>
#include <stdlib.h>

#include <noctree/scene.h>
#include <noctree/world.h>

/* The shortest decimal that reads back as x (as noctree-sim prints). */
static const char *num(double x, char buf[32])
{
    for (int digits = 1; digits <= 17; ++digits) {
        snprintf(buf, 32, "%.*g", digits, x);
        if (strtod(buf, NULL) == x)
            break;
    }
    return buf;
}

/* An object by its name in the scene, else by its index. */
static const char *label(const noctScene *scene, uint32_t index, char buf[32])
{
    const char *name = noctSceneObjectName(scene, index);
    if (name != NULL)
        return name;
    snprintf(buf, 32, "%u", index);
    return buf;
}

/* Where a pair meets: the intersection of the two objects' boxes. */
static int print_box(const noctWorld *w, const noctScene *scene, int step, noctPair pair)
{
    double alo[3], ahi[3], blo[3], bhi[3], lo[3], hi[3];
    if (noctWorldObjectBox(w, pair.a, alo, ahi) != NOCT_OK ||
        noctWorldObjectBox(w, pair.b, blo, bhi) != NOCT_OK)
        return 1;
    for (int k = 0; k < 3; ++k) {
        lo[k] = alo[k] > blo[k] ? alo[k] : blo[k];
        hi[k] = ahi[k] < bhi[k] ? ahi[k] : bhi[k];
    }
    char a[32], b[32], n[6][32];
    printf("first collision at step %d: objects %s and %s, contact box (%s, %s, %s) "
           "(%s, %s, %s)\n",
           step, label(scene, pair.a.index, a), label(scene, pair.b.index, b),
           num(lo[0], n[0]), num(lo[1], n[1]), num(lo[2], n[2]), num(hi[0], n[3]),
           num(hi[1], n[4]), num(hi[2], n[5]));
    return 0;
}

/* With continuous detection: the pair that touched first within the step. */
static void print_time(const noctScene *scene, int step, const noctPair *began,
                       const noctSweepHit *hits, size_t n)
{
    size_t best = 0;
    for (size_t i = 1; i < n; ++i)
        if (hits[i].time < hits[best].time)
            best = i;
    char a[32], b[32], t[32], x[32], y[32], z[32];
    printf("first collision at step %d, time %s of the step: objects %s and %s, "
           "touching at (%s, %s, %s)\n",
           step, num(hits[best].time, t), label(scene, began[best].a.index, a),
           label(scene, began[best].b.index, b), num(hits[best].point[0], x),
           num(hits[best].point[1], y), num(hits[best].point[2], z));
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: keyframe-check SCENE\n");
        return 2;
    }
    noctScene *scene;
    noctWorld *w;
    noctError err;
    if (noctSceneRead(argv[1], &scene, &err) != NOCT_OK) {
        fprintf(stderr, "keyframe-check: %s\n", err.message); /* file:line: problem */
        return 1;
    }
    if (noctSceneBuild(scene, &w, &err) != NOCT_OK) {
        fprintf(stderr, "keyframe-check: %s\n", err.message);
        noctSceneDestroy(scene);
        return 1;
    }
    const int steps = noctSceneSteps(scene);
    int status = 0, found = 0;
    for (int step = 1; step <= steps && !found && status == 0; ++step) {
        if (noctWorldStep(w, &err) != NOCT_OK) {
            fprintf(stderr, "keyframe-check: step %d: %s\n", step, err.message);
            status = 1;
            break;
        }
        const noctPair *colliding, *began;
        if (noctWorldColliding(w, &colliding) == 0)
            continue;
        /* continuous detection (the scene's accuracy or an object's) tells when */
        const size_t nbegan = noctWorldBegan(w, &began);
        const noctSweepHit *hits = NULL;
        size_t nhits = 0;
        if (nbegan > 0 && noctWorldBeganHits(w, &hits, &nhits, &err) != NOCT_OK) {
            fprintf(stderr, "keyframe-check: step %d: %s\n", step, err.message);
            status = 1;
            break;
        }
        if (nhits > 0)
            print_time(scene, step, began, hits, nhits);
        else
            status = print_box(w, scene, step, colliding[0]);
        found = 1;
    }
    if (status == 0 && !found)
        printf("no collision in %d steps\n", steps);
    noctWorldDestroy(w); /* the world first: it borrows the scene's meshes */
    noctSceneDestroy(scene);
    return status;
}
