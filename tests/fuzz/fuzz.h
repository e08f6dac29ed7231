/* SPDX-License-Identifier: MIT */
/*
 * Shared by the fuzz targets (libFuzzer). The readers take paths, so each
 * input is written to a file in a temporary folder of this process first;
 * the folder and its files go at exit. A broken expectation prints what
 * it was and aborts, which libFuzzer reports as a crash with the input.
 */
#ifndef NOCT_FUZZ_H
#define NOCT_FUZZ_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <noctree/status.h>

#define FUZZ_CHECK(cond, ...)                                                 \
    do {                                                                      \
        if (!(cond)) {                                                        \
            fprintf(stderr, "%s:%d: fuzz check failed: %s: ", __FILE__,       \
                    __LINE__, #cond);                                         \
            fprintf(stderr, __VA_ARGS__);                                     \
            fputc('\n', stderr);                                              \
            abort();                                                          \
        }                                                                     \
    } while (0)

static char fuzz_dir[64];
static char fuzz_paths[4][128];
static int fuzz_npaths;

static void fuzz_cleanup(void)
{
    for (int i = 0; i < fuzz_npaths; ++i)
        unlink(fuzz_paths[i]);
    if (fuzz_dir[0] != '\0')
        rmdir(fuzz_dir);
}

/* Write the input to a file called name (its extension picks the format)
 * and return its path. */
static const char *fuzz_file(const char *name, const uint8_t *data, size_t size)
{
    if (fuzz_dir[0] == '\0') {
        const char *tmp = getenv("TMPDIR");
        snprintf(fuzz_dir, sizeof fuzz_dir, "%s/noct-fuzz-XXXXXX",
                 tmp && *tmp && strlen(tmp) < 40 ? tmp : "/tmp");
        if (mkdtemp(fuzz_dir) == NULL) {
            perror("fuzz: mkdtemp");
            abort();
        }
        atexit(fuzz_cleanup);
    }
    char path[128];
    snprintf(path, sizeof path, "%s/%s", fuzz_dir, name);
    int i = 0;
    while (i < fuzz_npaths && strcmp(fuzz_paths[i], path) != 0)
        ++i;
    if (i == fuzz_npaths) {
        FUZZ_CHECK(i < 4, "more than 4 file names");
        strcpy(fuzz_paths[fuzz_npaths++], path);
    }
    FILE *f = fopen(path, "wb");
    if (f == NULL || fwrite(data, 1, size, f) != size || fclose(f) != 0) {
        perror("fuzz: writing the input");
        abort();
    }
    return fuzz_paths[i];
}

/* A failed read: a real status, no result, a message that starts with
 * the file's path, and with "path:line:" when it names a line. */
static void fuzz_failed_read(noctStatus st, const void *result, const noctError *err,
                             const char *path)
{
    FUZZ_CHECK(st > NOCT_OK && st < NOCT_STATUS_COUNT, "status %d", (int)st);
    FUZZ_CHECK(result == NULL, "a failed read left a result");
    FUZZ_CHECK(err->status == st, "noctError says %d, the call %d", (int)err->status,
               (int)st);
    FUZZ_CHECK(strncmp(err->message, path, strlen(path)) == 0,
               "the message does not name the file: '%s'", err->message);
    char where[160];
    snprintf(where, sizeof where, "%s:%ld:", path, err->line);
    FUZZ_CHECK(err->line <= 0 || strncmp(err->message, where, strlen(where)) == 0,
               "line %ld, but the message is '%s'", err->line, err->message);
}

#endif /* NOCT_FUZZ_H */
