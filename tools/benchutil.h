/* SPDX-License-Identifier: MIT */
/*
 * What the benchmark programs share: a clock, a seeded RNG, the order
 * statistics of repeated timings and their CSV files. Plain C that needs
 * no libnoctree (bench-ab loads the library with dlopen), usable from C++.
 * Not part of the library.
 */
#ifndef NOCT_TOOLS_BENCHUTIL_H
#define NOCT_TOOLS_BENCHUTIL_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Seconds on a monotonic clock. */
double tool_now(void);

/* splitmix64: the next number of the sequence *state seeds. */
uint64_t tool_rand(uint64_t *state);

/* qsort's comparison of two doubles, ascending. */
int tool_cmp_double(const void *x, const void *y);

/* Sort v[0 .. n) ascending. */
void tool_sort(double *v, size_t n);

/* The median of v[0 .. n), n > 0: the middle value, or the mean of the
 * two middle values when n is even. Sorts v. */
double tool_median(double *v, size_t n);

/* Of sorted[0 .. n), n > 0, the value at rank n num / den (rounded down,
 * at most n - 1): the upper median for 1/2, the quartiles for 1/4 and
 * 3/4, the 90th percentile for 9/10. */
double tool_rank(const double *sorted, size_t n, size_t num, size_t den);

/* Open path for writing and write the header line to it; NULL, after
 * perror(path), if it cannot be opened. */
FILE *tool_open_csv(const char *path, const char *header);

#ifdef __cplusplus
}
#endif

#endif /* NOCT_TOOLS_BENCHUTIL_H */
