/* SPDX-License-Identifier: MIT */
/* The library's one clock (foundation floor): the world's counters time
 * its stages with it. */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include <time.h>

#include "internal.h"

double noct_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}
