/* SPDX-License-Identifier: MIT */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <noctree/world.h>

#include "toolutil.h"

const char *tool_name = "noctree";

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
    else if (tool_parse_long(s, 1, INT_MAX - 1, &n))
        *N = (int)n;
    else
        return false;
    return true;
}

bool tool_parse_accuracy(const char *s, noctAccuracy *accuracy)
{
    static const noctAccuracy all[] = {NOCT_ACCURACY_BOX, NOCT_ACCURACY_CONVEX,
                                       NOCT_ACCURACY_EXACT};
    for (size_t i = 0; i < sizeof all / sizeof *all; ++i)
        if (strcmp(s, noctAccuracyName(all[i])) == 0) {
            *accuracy = all[i];
            return true;
        }
    return false;
}

double tool_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void tool_progress(bool on, long done, long total, const char *label)
{
    if (!on || total <= 0)
        return;
    enum { WIDTH = 40 };
    int filled = (int)((long long)WIDTH * done / total);
    fprintf(stderr, "\r[%.*s%*s] %3d%% %-32.32s", filled,
            "########################################", WIDTH - filled, "",
            (int)(100LL * done / total), label ? label : "");
    if (done >= total)
        fputc('\n', stderr);
    fflush(stderr);
}
