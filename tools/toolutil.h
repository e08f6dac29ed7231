/* SPDX-License-Identifier: MIT */
/*
 * What the command-line tools share: usage errors, number and option
 * parsing, scene arguments and the progress bar (benchutil.h: the clock
 * and the statistics). Not part of the library.
 */
#ifndef NOCT_TOOLS_TOOLUTIL_H
#define NOCT_TOOLS_TOOLUTIL_H

#include <stdbool.h>

#include <noctree/narrowphase.h>
#include <noctree/scene.h>

/* The tool's name, for messages; set once by main. */
extern const char *tool_name;

/* Print "NAME: message" and a pointer to --help on stderr; return 2, the
 * exit status for bad usage or input. */
int tool_usage_error(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/* --help (usage on stdout) and --version ("NAME VERSION"): true if arg is
 * one of them, printed; the program then exits 0. */
bool tool_help_or_version(const char *arg, const char *usage);

/* Print "NAME: message" on stderr. */
void tool_error(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/* s is a whole decimal integer in [lo, hi]. */
bool tool_parse_long(const char *s, long lo, long hi, long *out);

/* s is a whole finite decimal number in [lo, hi]. */
bool tool_parse_double(const char *s, double lo, double hi, double *out);

/* s is a positive integer, "big" (NOCT_N_EXHAUSTIVE) or "auto" (NOCT_AUTO). */
bool tool_parse_N(const char *s, int *N);

/* s is "box", "convex" or "exact". */
bool tool_parse_accuracy(const char *s, noctAccuracy *accuracy);

/* The scene a tool runs: a file or --scene FAMILY, with --N and
 * --max-depth when given (set_N, set_depth), else the scene's own. */
typedef struct tool_scene_args {
    const char *family, *file;
    int N, depth;
    bool set_N, set_depth;
} tool_scene_args;

/* If argv[*i] is --scene, --N or --max-depth with a value, or a scene
 * file, take it (moving *i past the value) and return 1; return 0 for any
 * other argument; print a usage error and return -1 for a bad value or a
 * second scene file. */
int tool_scene_arg(tool_scene_args *a, int argc, char **argv, int *i);

/* Read the scene (exactly one must have been given) and apply --N and
 * --max-depth. Returns 0, or the exit status 2 after printing the error. */
int tool_scene_load(const tool_scene_args *a, noctScene **scene);

/* Write x in the fewest significant digits (at most 17) that read back as
 * exactly x, as %g writes them: 1.25, 2, -0.5, 0.1. Returns buf. */
const char *tool_format_double(double x, char buf[32]);

/* PATH with its extension replaced by EXT (".svg"): the extension is the
 * part of the last path component from its last dot, unless that dot
 * starts the component; without one, EXT is added. A string from malloc,
 * or NULL when memory runs out. */
char *tool_with_extension(const char *path, const char *ext);

/* Draw "[####    ]  40% label" on stderr when it is a terminal and bars
 * are on; done == total ends the line. */
void tool_progress(bool on, long done, long total, const char *label);

/* End the progress bar's line when a run stops before done == total. */
void tool_progress_end(void);

#endif /* NOCT_TOOLS_TOOLUTIL_H */
