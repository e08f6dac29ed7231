/* SPDX-License-Identifier: MIT */
/*
 * GMP's memory for the suites whose oracles compute in GMP rationals:
 * free lists by size (16-byte classes up to 1 KB; GMP tells the size of
 * each block it frees or grows). Their oracles make and free a few small
 * numbers on every operation, and under valgrind each malloc and free
 * costs some microseconds: check-surfaces ran in 124 s instead of 185.
 * The blocks stay on their lists when a suite ends (reachable, not
 * leaked). Call test_gmp_pools() in main(), before any GMP call.
 */
#ifndef NOCT_TESTS_TESTGMP_H
#define NOCT_TESTS_TESTGMP_H

#include <check.h>
#include <gmp.h>
#include <stdlib.h>
#include <string.h>

#define TEST_GMP_CLASSES 64

static void *test_gmp_pool[TEST_GMP_CLASSES];

static inline void *test_gmp_alloc(size_t n)
{
    const size_t c = (n + 15) / 16;
    void *p = c < TEST_GMP_CLASSES ? test_gmp_pool[c] : NULL;
    if (p != NULL) {
        memcpy(&test_gmp_pool[c], p, sizeof p);
        return p;
    }
    /* (GMP has no way to fail: a suite without memory stops here) */
    p = malloc(c < TEST_GMP_CLASSES ? 16 * (c > 0 ? c : 1) : n);
    ck_assert_ptr_nonnull(p);
    return p;
}

static inline void test_gmp_free(void *p, size_t n)
{
    const size_t c = (n + 15) / 16;
    if (c >= TEST_GMP_CLASSES) {
        free(p);
        return;
    }
    memcpy(p, &test_gmp_pool[c], sizeof p);
    test_gmp_pool[c] = p;
}

static inline void *test_gmp_realloc(void *p, size_t old, size_t n)
{
    if ((old + 15) / 16 == (n + 15) / 16 && (n + 15) / 16 < TEST_GMP_CLASSES)
        return p;
    void *q = test_gmp_alloc(n);
    memcpy(q, p, old < n ? old : n);
    test_gmp_free(p, old);
    return q;
}

static inline void test_gmp_pools(void)
{
    mp_set_memory_functions(test_gmp_alloc, test_gmp_realloc, test_gmp_free);
}

#endif
