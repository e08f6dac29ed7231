/* SPDX-License-Identifier: MIT */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <noctree/version.h>
#include <noctree/world.h>

#include "toolutil.h"

const char *tool_name = "noctree";

bool tool_help_or_version(const char *arg, const char *usage)
{
    if (strcmp(arg, "--help") == 0)
        fputs(usage, stdout);
    else if (strcmp(arg, "--version") == 0)
        printf("%s %s\n", tool_name, NOCT_VERSION_STRING);
    else
        return false;
    return true;
}

int tool_usage_error(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "%s: ", tool_name);
    vfprintf(stderr, fmt, ap);
    fprintf(stderr, "\nTry '%s --help'.\n", tool_name);
    va_end(ap);
    return 2;
}

void tool_error(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "%s: ", tool_name);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
}

bool tool_parse_long(const char *s, long lo, long hi, long *out)
{
    char *end;
    errno = 0;
    *out = strtol(s, &end, 10);
    return end != s && *end == '\0' && errno == 0 && *out >= lo && *out <= hi;
}

bool tool_parse_double(const char *s, double lo, double hi, double *out)
{
    char *end;
    errno = 0;
    *out = strtod(s, &end);
    return end != s && *end == '\0' && errno == 0 && isfinite(*out) && *out >= lo &&
           *out <= hi;
}

bool tool_parse_N(const char *s, int *N)
{
    long n;
    if (strcmp(s, "big") == 0)
        *N = NOCT_N_EXHAUSTIVE;
    else if (strcmp(s, "auto") == 0)
        *N = NOCT_AUTO;
    else if (tool_parse_long(s, 1, INT_MAX - 1, &n))
        *N = (int)n;
    else
        return false;
    return true;
}

bool tool_parse_accuracy(const char *s, noctAccuracy *accuracy)
{
    static const noctAccuracy all[] = {NOCT_ACCURACY_BOX, NOCT_ACCURACY_CONVEX,
                                       NOCT_ACCURACY_EXACT, NOCT_ACCURACY_CONTINUOUS};
    for (size_t i = 0; i < sizeof all / sizeof *all; ++i)
        if (strcmp(s, noctAccuracyName(all[i])) == 0) {
            *accuracy = all[i];
            return true;
        }
    return false;
}

int tool_scene_arg(tool_scene_args *a, int argc, char **argv, int *i)
{
    const char *arg = argv[*i];
    bool has = *i + 1 < argc;
    long v;
    if (strcmp(arg, "--scene") == 0 && has) {
        a->family = argv[++*i];
    } else if (strcmp(arg, "--N") == 0 && has) {
        if (!tool_parse_N(argv[++*i], &a->N))
            return tool_usage_error("--N must be a positive integer, 'big' or 'auto', not '%s'",
                                    argv[*i]), -1;
        a->set_N = true;
    } else if (strcmp(arg, "--max-depth") == 0 && has) {
        if (strcmp(argv[++*i], "auto") == 0)
            v = NOCT_AUTO;
        else if (!tool_parse_long(argv[*i], 1, 40, &v))
            return tool_usage_error("--max-depth must be 1 to 40 or 'auto', not '%s'", argv[*i]),
                   -1;
        a->depth = (int)v;
        a->set_depth = true;
    } else if (arg[0] == '-' && arg[1] != '\0') {
        return 0;
    } else if (a->file == NULL) {
        a->file = arg;
    } else {
        return tool_usage_error("more than one scene file: '%s'", arg), -1;
    }
    return 1;
}

int tool_scene_load(const tool_scene_args *a, noctScene **scene)
{
    if ((a->family == NULL) == (a->file == NULL))
        return tool_usage_error("give one scene: a file or --scene FAMILY");
    noctError err;
    noctStatus st = a->family ? noctSceneFamily(a->family, scene, &err)
                              : noctSceneRead(a->file, scene, &err);
    if (st != NOCT_OK) {
        tool_error("%s", err.message);
        return 2;
    }
    noctWorldDef *def = noctSceneDef(*scene);
    if (a->set_N)
        def->N = a->N;
    if (a->set_depth)
        def->max_depth = a->depth;
    return 0;
}

const char *tool_format_double(double x, char buf[32])
{
    for (int digits = 1; digits <= 17; ++digits) {
        snprintf(buf, 32, "%.*g", digits, x);
        if (strtod(buf, NULL) == x)
            break;
    }
    return buf;
}

char *tool_with_extension(const char *path, const char *ext)
{
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    const char *dot = strrchr(base, '.');
    size_t keep = dot != NULL && dot != base ? (size_t)(dot - path) : strlen(path);
    char *s = malloc(keep + strlen(ext) + 1);
    if (s != NULL) {
        memcpy(s, path, keep);
        strcpy(s + keep, ext);
    }
    return s;
}

/* A bar is drawn and its line not yet ended. */
static bool progress_open;

void tool_progress(bool on, long done, long total, const char *label)
{
    if (!on || total <= 0)
        return;
    progress_open = done < total;
    enum { WIDTH = 40 };
    int filled = (int)((long long)WIDTH * done / total);
    fprintf(stderr, "\r[%.*s%*s] %3d%% %-32.32s", filled,
            "########################################", WIDTH - filled, "",
            (int)(100LL * done / total), label ? label : "");
    if (done >= total)
        fputc('\n', stderr);
    fflush(stderr);
}

void tool_progress_end(void)
{
    if (progress_open)
        fputc('\n', stderr);
    progress_open = false;
}
