/* SPDX-License-Identifier: MIT */
/*
 * libFuzzer target: scene files (noctSceneRead), beside two mesh files
 * they may name (tet.off and cube.obj). A file that fails must fail
 * cleanly, naming itself; a file that reads must build (a scene that
 * reads builds: scene.h), and a small world built from it must take a
 * step and pass the world's validation walk.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <noctree/scene.h>
#include <noctree/world.h>

#include "fuzz.h"

/* Whether every family the input could name is small enough to build in
 * a few milliseconds: any "gas" or "planes" followed by a number counts,
 * wherever it is. */
static bool families_small(const uint8_t *data, size_t size)
{
    static const struct {
        const char *word;
        long most;
    } limits[] = {{"gas", 200}, {"planes", 3}};
    char *text = malloc(size + 1);
    if (text == NULL)
        return false;
    memcpy(text, data, size);
    text[size] = '\0';
    bool small = true;
    for (size_t i = 0; i < size && small; ++i)
        for (size_t k = 0; k < sizeof limits / sizeof *limits; ++k) {
            size_t len = strlen(limits[k].word);
            if (i + len <= size && memcmp(text + i, limits[k].word, len) == 0) {
                errno = 0;
                long n = strtol(text + i + len, NULL, 10);
                small = small && errno == 0 && n <= limits[k].most;
            }
        }
    free(text);
    return small;
}

/* Mesh files beside the input, for its "mesh NAME file" lines. */
static const char TET_OFF[] = "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                              "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";
static const char CUBE_OBJ[] = "v 0 0 0\nv 0 0 1\nv 0 1 0\nv 0 1 1\nv 1 0 0\nv 1 0 1\n"
                               "v 1 1 0\nv 1 1 1\nf 1 2 4 3\nf 5 7 8 6\nf 1 5 6 2\n"
                               "f 3 4 8 7\nf 1 3 7 5\nf 2 6 8 4\n";

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static bool meshes;
    if (!meshes) {
        fuzz_file("tet.off", (const uint8_t *)TET_OFF, sizeof TET_OFF - 1);
        fuzz_file("cube.obj", (const uint8_t *)CUBE_OBJ, sizeof CUBE_OBJ - 1);
        meshes = true;
    }
    const char *path = fuzz_file("input.scene", data, size);
    noctScene *sc = (noctScene *)&sc; /* must be overwritten */
    noctError err = {0};
    noctStatus st = noctSceneRead(path, &sc, &err);
    if (st != NOCT_OK) {
        fuzz_failed_read(st, sc, &err, path);
        return 0;
    }
    FUZZ_CHECK(sc != NULL, "no scene");
    FUZZ_CHECK(noctSceneSteps(sc) >= 1, "steps %d", noctSceneSteps(sc));
    if (families_small(data, size)) {
        noctWorld *w = NULL;
        st = noctSceneBuild(sc, &w, &err);
        FUZZ_CHECK(st == NOCT_OK || st == NOCT_ERR_NOMEM,
                   "a scene that reads must build: %s: %s", noctStatusString(st),
                   err.message);
        /* One step, unless sub-steps would make it long. */
        if (st == NOCT_OK && noctWorldMaxStepRatio(w) <= 1) {
            st = noctWorldStep(w, &err);
            FUZZ_CHECK(st == NOCT_OK || st == NOCT_ERR_TOO_LARGE || st == NOCT_ERR_NOMEM ||
                       st == NOCT_ERR_NUMERIC,
                       "step: %s: %s", noctStatusString(st), err.message);
            st = noctWorldValidate(w, &err);
            FUZZ_CHECK(st == NOCT_OK || st == NOCT_ERR_NOMEM, "validate: %s: %s",
                       noctStatusString(st), err.message);
        }
        noctWorldDestroy(w);
    }
    noctSceneDestroy(sc);
    return 0;
}
