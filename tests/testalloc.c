/* SPDX-License-Identifier: MIT */
/* The tests' allocator: see testalloc.h. */
#define _GNU_SOURCE /* RTLD_NEXT, valloc, pvalloc */
#include <dlfcn.h>
#include <errno.h>
#include <malloc.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "testalloc.h"

#if defined(__SANITIZE_ADDRESS__)
#  define TA_ASAN 1
#elif defined(__has_feature)
#  if __has_feature(address_sanitizer)
#    define TA_ASAN 1
#  endif
#endif
#ifndef TA_ASAN
#  define TA_ASAN 0
#endif

/* AddressSanitizer owns malloc (defining it here would clash with its
 * interceptors), and the __libc_* entry points are glibc's. */
#if !TA_ASAN && defined(__GLIBC__)
#  define TA_INTERPOSE 1
#else
#  define TA_INTERPOSE 0
#endif

#if TA_INTERPOSE

#if defined(__has_include)
#  if __has_include(<valgrind/valgrind.h>)
#    include <valgrind/valgrind.h>
#    define TA_HAVE_VALGRIND_H 1
#  endif
#endif

/* Live blocks allocated while a run tracks them: an open-addressing table
 * (linear probing, deletion by backward shift) in static storage, since
 * it cannot itself allocate. */
#define LIVE_BITS 16
#define LIVE_CAP ((size_t)1 << LIVE_BITS)
typedef struct live_block {
    void *p;
    void *caller;
} live_block;
/*
 * The state below changes inside glibc calls that glibc's headers declare
 * __leaf__, which tells the compiler they never call back into this file
 * and so never touch its static variables: not so once this file defines
 * malloc. So the scalars are volatile, and BARRIER() stands around the
 * places where counting is switched on and off.
 */
#define BARRIER() __asm__ __volatile__("" ::: "memory")
static live_block live[LIVE_CAP];
static volatile size_t live_n;
static volatile bool live_overflow;

static volatile bool g_on;               /* a run is on */
static volatile int g_busy;              /* paused (the harness's own work) */
static volatile unsigned long g_count;   /* points seen in this run */
static volatile unsigned long g_failed;  /* failures handed out in this run */
static alloc_plan g_plan;
static void *g_callers[ALLOC_CALLERS];

static alloc_filter_fn *g_filter;
static alloc_point_fn *g_on_point;
static alloc_failure_fn *g_on_first_failure;

extern void *__libc_malloc(size_t size);
extern void *__libc_calloc(size_t n, size_t size);
extern void *__libc_realloc(void *p, size_t size);
extern void __libc_free(void *p);
extern void *__libc_memalign(size_t align, size_t size);
extern void *__libc_valloc(size_t size);
extern void *__libc_pvalloc(size_t size);

static size_t live_slot(const void *p)
{
    uintptr_t x = (uintptr_t)p >> 4;
    x *= 0x9e3779b97f4a7c15u;
    return (size_t)(x >> (64 - LIVE_BITS));
}

static void live_add(void *p, void *caller)
{
    if (live_n + 1 >= LIVE_CAP / 2) {
        live_overflow = true; /* the check then fails; the table stays sound */
        return;
    }
    size_t i = live_slot(p);
    while (live[i].p != NULL)
        i = (i + 1) & (LIVE_CAP - 1);
    live[i].p = p;
    live[i].caller = caller;
    ++live_n;
}

static void live_remove(void *p)
{
    if (live_n == 0)
        return;
    size_t i = live_slot(p);
    while (live[i].p != p) {
        if (live[i].p == NULL)
            return; /* allocated outside a run */
        i = (i + 1) & (LIVE_CAP - 1);
    }
    /* Backward shift: move later entries of the probe chain into the hole
     * when their home slot does not lie between the hole and them. */
    size_t hole = i;
    for (size_t j = (i + 1) & (LIVE_CAP - 1); live[j].p != NULL; j = (j + 1) & (LIVE_CAP - 1)) {
        size_t home = live_slot(live[j].p);
        bool stays = hole <= j ? (hole < home && home <= j) : (hole < home || home <= j);
        if (!stays) {
            live[hole] = live[j];
            hole = j;
        }
    }
    live[hole].p = NULL;
    live[hole].caller = NULL;
    --live_n;
}

/* Empty the table; it is empty already but after a leak, and clearing a
 * clean table would only copy its pages in each child process. */
static void live_reset(void)
{
    if (live_n > 0 || live_overflow)
        memset(live, 0, sizeof live);
    live_n = 0;
    live_overflow = false;
}

/* Is this allocation (of size bytes) a point, and does it fail? */
static bool point_fails(void *caller, size_t size)
{
    if (!g_on || g_busy)
        return false;
    if (g_filter != NULL && !g_filter(caller))
        return false;
    unsigned long k = ++g_count;
    if (k <= ALLOC_CALLERS)
        g_callers[k - 1] = caller;
    if (g_on_point != NULL)
        g_on_point(caller);
    const unsigned long at = g_plan.fail_at;
    bool fails = (at != 0 && (k == at || (k > at && g_plan.fail_rest))) ||
                 (g_plan.fail_above != 0 && size > g_plan.fail_above);
    if (!fails)
        return false;
    if (g_failed++ == 0 && g_on_first_failure != NULL) {
        ++g_busy;
        g_on_first_failure(k);
        --g_busy;
    }
    errno = ENOMEM;
    return true;
}

static void *track(void *p, void *caller)
{
    if (p != NULL && g_on && !g_busy && g_plan.track)
        live_add(p, caller);
    return p;
}

void *malloc(size_t size)
{
    void *caller = __builtin_return_address(0);
    if (point_fails(caller, size))
        return NULL;
    return track(__libc_malloc(size), caller);
}

void *calloc(size_t n, size_t size)
{
    void *caller = __builtin_return_address(0);
    size_t total;
    if (__builtin_mul_overflow(n, size, &total))
        total = SIZE_MAX;
    if (point_fails(caller, total))
        return NULL;
    return track(__libc_calloc(n, size), caller);
}

static void *realloc_from(void *p, size_t size, void *caller)
{
    if (p != NULL && size == 0) { /* glibc frees p */
        live_remove(p);
        return __libc_realloc(p, 0);
    }
    if (point_fails(caller, size))
        return NULL; /* p stays allocated, as realloc promises */
    void *q = __libc_realloc(p, size);
    if (q != NULL && p != NULL)
        live_remove(p);
    return track(q, caller);
}

void *realloc(void *p, size_t size)
{
    return realloc_from(p, size, __builtin_return_address(0));
}

void *reallocarray(void *p, size_t n, size_t size)
{
    if (size != 0 && n > SIZE_MAX / size) {
        errno = ENOMEM;
        return NULL;
    }
    return realloc_from(p, n * size, __builtin_return_address(0));
}

void free(void *p)
{
    if (p == NULL)
        return;
    live_remove(p);
    __libc_free(p);
}

void *memalign(size_t align, size_t size)
{
    void *caller = __builtin_return_address(0);
    if (point_fails(caller, size))
        return NULL;
    return track(__libc_memalign(align, size), caller);
}

void *aligned_alloc(size_t align, size_t size)
{
    void *caller = __builtin_return_address(0);
    if (point_fails(caller, size))
        return NULL;
    return track(__libc_memalign(align, size), caller);
}

int posix_memalign(void **out, size_t align, size_t size)
{
    void *caller = __builtin_return_address(0);
    if (align < sizeof(void *) || (align & (align - 1)) != 0)
        return EINVAL;
    if (point_fails(caller, size))
        return ENOMEM;
    void *p = track(__libc_memalign(align, size), caller);
    if (p == NULL)
        return ENOMEM;
    *out = p;
    return 0;
}

void *valloc(size_t size)
{
    void *caller = __builtin_return_address(0);
    if (point_fails(caller, size))
        return NULL;
    return track(__libc_valloc(size), caller);
}

void *pvalloc(size_t size)
{
    void *caller = __builtin_return_address(0);
    if (point_fails(caller, size))
        return NULL;
    return track(__libc_pvalloc(size), caller);
}

/* The blocks are glibc's, so glibc's answer is right; found once, before
 * any run, since dlsym may allocate. */
static size_t (*libc_usable_size)(void *);

size_t malloc_usable_size(void *p)
{
    return p != NULL && libc_usable_size != NULL ? libc_usable_size(p) : 0;
}

const char *alloc_unavailable(void)
{
    if (libc_usable_size == NULL) {
        void *sym = dlsym(RTLD_NEXT, "malloc_usable_size");
        memcpy(&libc_usable_size, &sym, sizeof sym);
    }
#ifdef TA_HAVE_VALGRIND_H
    if (RUNNING_ON_VALGRIND)
        return "running under valgrind, which replaces malloc";
#endif
    const char *pre = getenv("LD_PRELOAD");
    if (pre != NULL && strstr(pre, "vgpreload") != NULL)
        return "running under valgrind, which replaces malloc";
    /* The probe: an allocation must reach this allocator. */
    void *(*volatile alloc)(size_t) = malloc;
    alloc_begin(&(alloc_plan){.track = true});
    void *p = alloc(24);
    alloc_end();
    bool seen = g_count == 1 && live_n == 1;
    free(p);
    live_reset();
    if (!seen)
        return "malloc does not reach the test's allocator (another allocator is "
               "interposed)";
    return NULL;
}

void alloc_begin(const alloc_plan *plan)
{
    live_reset();
    g_count = 0;
    g_failed = 0;
    g_plan = *plan;
    memset(g_callers, 0, sizeof g_callers);
    BARRIER();
    g_on = true;
    BARRIER();
}

void alloc_end(void)
{
    BARRIER();
    g_on = false;
    BARRIER();
}

void alloc_pause(void)
{
    BARRIER();
    ++g_busy;
    BARRIER();
}

void alloc_resume(void)
{
    BARRIER();
    --g_busy;
    BARRIER();
}

unsigned long alloc_points(void)
{
    return g_count;
}

unsigned long alloc_failures(void)
{
    return g_failed;
}

void *alloc_caller(unsigned long i)
{
    return i < ALLOC_CALLERS ? g_callers[i] : NULL;
}

size_t alloc_live(void *callers[], size_t max)
{
    size_t found = 0;
    for (size_t i = 0; i < LIVE_CAP && found < max && found < live_n; ++i)
        if (live[i].p != NULL)
            callers[found++] = live[i].caller;
    return live_n;
}

bool alloc_live_overflowed(void)
{
    return live_overflow;
}

void alloc_set_hooks(alloc_filter_fn *filter, alloc_point_fn *on_point,
                     alloc_failure_fn *on_first_failure)
{
    g_filter = filter;
    g_on_point = on_point;
    g_on_first_failure = on_first_failure;
}

#else /* !TA_INTERPOSE: no allocator of the test's own here */

const char *alloc_unavailable(void)
{
#  if TA_ASAN
    return "built with AddressSanitizer, which owns malloc";
#  else
    return "not built against glibc, whose allocator the test's forwards to";
#  endif
}

void alloc_begin(const alloc_plan *plan)
{
    (void)plan;
}

void alloc_end(void)
{
}

void alloc_pause(void)
{
}

void alloc_resume(void)
{
}

unsigned long alloc_points(void)
{
    return 0;
}

unsigned long alloc_failures(void)
{
    return 0;
}

void *alloc_caller(unsigned long i)
{
    (void)i;
    return NULL;
}

size_t alloc_live(void *callers[], size_t max)
{
    (void)callers;
    (void)max;
    return 0;
}

bool alloc_live_overflowed(void)
{
    return false;
}

void alloc_set_hooks(alloc_filter_fn *filter, alloc_point_fn *on_point,
                     alloc_failure_fn *on_first_failure)
{
    (void)filter;
    (void)on_point;
    (void)on_first_failure;
}

#endif /* TA_INTERPOSE */
