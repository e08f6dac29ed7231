/* SPDX-License-Identifier: MIT */
/*
 * The tests' allocator (check-alloc, check-zero-alloc, check-readers).
 *
 * testalloc.c defines malloc, calloc, realloc, free and the rest of the
 * family glibc's manual ("Replacing malloc") lists, forwarding to
 * __libc_malloc and friends. ELF interposition sends every allocation of
 * the process to them: the test's, libnoctree's, and those of the
 * libraries it uses and of glibc itself (fopen, getline, strdup).
 *
 * Between alloc_begin() and alloc_end(), outside alloc_pause(), each
 * allocation is a point, numbered from 1: counted, its caller (return
 * address) kept for the first ALLOC_CALLERS, and made to fail as the plan
 * says. realloc(p, 0) with p not NULL frees p and is not a point.
 *
 * Only in a program built without AddressSanitizer (which owns malloc)
 * and against glibc; elsewhere the functions below do nothing and
 * alloc_unavailable() says why. A program linking this module must ask
 * alloc_unavailable() before relying on it: valgrind, for one, replaces
 * malloc in the executable too.
 */
#ifndef NOCT_TESTS_TESTALLOC_H
#define NOCT_TESTS_TESTALLOC_H

#include <stdbool.h>
#include <stddef.h>

/* What the allocator does with the points of a run. */
typedef struct alloc_plan {
    unsigned long fail_at; /* the point that fails (1: the first); 0: none */
    bool fail_rest;        /* and every point after it */
    size_t fail_above;     /* every point asking for more bytes fails; 0: none */
    bool track;            /* remember the live blocks and their callers */
} alloc_plan;

/* Why the allocator is not the program's, or NULL when it is: built with
 * AddressSanitizer, not glibc, under valgrind, or a probe allocation that
 * does not reach it. The first call also sets the module up (before any
 * run; it may allocate), so call it early in main. */
const char *alloc_unavailable(void);

/* Start a run: counts, failures and the table of live blocks emptied. */
void alloc_begin(const alloc_plan *plan);

/* End the run; its counts stay readable until the next alloc_begin(). */
void alloc_end(void);

/* Allocations in between are not points (the harness's own set-up and
 * checks inside a run). Nests. */
void alloc_pause(void);
void alloc_resume(void);

/* Points seen in the run. */
unsigned long alloc_points(void);

/* Failures handed out in the run. */
unsigned long alloc_failures(void);

/* The caller of point i (0 for the first), for i < ALLOC_CALLERS and
 * i < alloc_points(). */
#define ALLOC_CALLERS 8
void *alloc_caller(unsigned long i);

/* With plan.track: the blocks allocated in the run (points or not) and
 * not freed yet. Fills callers[0 .. max) with some of their callers. */
size_t alloc_live(void *callers[], size_t max);

/* The table of live blocks ran full (it then tracks no more). */
bool alloc_live_overflowed(void);

/* Hooks for one harness (check-alloc), NULL for none. They run inside the
 * allocator, so they must not allocate, except on_first_failure, around
 * which the run is paused.
 *   filter(caller): whether an allocation is a point at all;
 *   on_point(caller): called at each point;
 *   on_first_failure(k): called at the run's first failure, point k. */
typedef bool alloc_filter_fn(void *caller);
typedef void alloc_point_fn(void *caller);
typedef void alloc_failure_fn(unsigned long k);
void alloc_set_hooks(alloc_filter_fn *filter, alloc_point_fn *on_point,
                     alloc_failure_fn *on_first_failure);

#endif /* NOCT_TESTS_TESTALLOC_H */
