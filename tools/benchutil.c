/* SPDX-License-Identifier: MIT */
/* What the benchmark programs share: see benchutil.h. */
#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <time.h>

#include "benchutil.h"

double tool_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

uint64_t tool_rand(uint64_t *state)
{
    uint64_t z = (*state += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}

int tool_cmp_double(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

void tool_sort(double *v, size_t n)
{
    qsort(v, n, sizeof *v, tool_cmp_double);
}

double tool_median(double *v, size_t n)
{
    tool_sort(v, n);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double tool_rank(const double *sorted, size_t n, size_t num, size_t den)
{
    size_t i = n * num / den;
    return sorted[i < n ? i : n - 1];
}

FILE *tool_open_csv(const char *path, const char *header)
{
    FILE *f = fopen(path, "w");
    if (f == NULL)
        perror(path);
    else
        fprintf(f, "%s\n", header);
    return f;
}
