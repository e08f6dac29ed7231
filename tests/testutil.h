/* SPDX-License-Identifier: MIT */
/* Helpers shared by the Check suites: a seeded RNG, the whole-tree
 * validation walk, a mirror model of a tree's shape and data, and a
 * non-convex mesh. They use only the public API, so they check the
 * library from the outside. */
#ifndef NOCT_TESTS_TESTUTIL_H
#define NOCT_TESTS_TESTUTIL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include <check.h>

#include <noctree/mesh.h>
#include <noctree/octree.h>
#include <noctree/transform.h>

/* Check marks every passing assertion (_mark_point(): a write(2) to its
 * log, so that a test that crashes or times out can say how far it got).
 * The suites' millions of passing assertions made those writes most of
 * their time: half of check-world's, 1.3 million in check-broadphase,
 * each far dearer under valgrind. So here a passing assertion marks
 * nothing unless the environment sets NOCT_TEST_MARKS=1 (read into
 * test_marks by run_suite()); a failing one fails as Check's own does,
 * with the same message. Without the marks, a test that crashes or times
 * out is reported at its start or its last mark_point(): rerun it with
 * NOCT_TEST_MARKS=1 (a sanitizer's stack trace names the line too). Every
 * ck_assert macro of Check's expands to ck_assert_msg(), so all of them
 * follow. */
extern bool test_marks;
#undef ck_assert_msg
#define ck_assert_msg(expr, ...)                                                         \
    ((expr) ? (test_marks ? _mark_point(__FILE__, __LINE__) : (void)0)                  \
            : _ck_assert_failed(__FILE__, __LINE__, "Assertion '" #expr "' failed",    \
                                __VA_ARGS__))

/* An assertion for hot loops, from before ck_assert_msg() above stopped
 * marking: it costs nothing unless it fails, and then fails the test,
 * naming the file, line and expression. */
#define EXPECT(cond)                                                        \
    do {                                                                    \
        if (!(cond))                                                        \
            ck_abort_msg("%s:%d: expected %s", __FILE__, __LINE__, #cond);  \
    } while (0)

/* The timeout of a test case that names none: Check's own default, 4 s,
 * is too short for a test of 2 s under AddressSanitizer on a loaded CI
 * machine (check-world-efficient's handles_through_churn timed out so). A
 * test that hangs still fails, in a minute. */
#define TEST_DEFAULT_TIMEOUT 60

/* A new test case of s, named name, with a timeout of seconds (0:
 * TEST_DEFAULT_TIMEOUT) and Check's tags (NULL for none): "slow" ones are left
 * out of the runs under valgrind, "death" ones (requires clauses that
 * must abort) where fork() is off (CK_EXCLUDE_TAGS). "seeds" marks a slow
 * case that runs a quick case's checks on more random seeds (not whole
 * scenes, which are "slow" alone): CI's sanitizer build leaves those
 * out, as plain make check runs them. */
TCase *test_case(Suite *s, const char *name, int seconds, const char *tags);

/* The rounds of a loop that repeats the same checks on more random data
 * (more random scenes, pairs or seeds): n, or, where the environment sets
 * NOCT_TEST_ROUNDS_DIVISOR to a whole number d > 1, n / d rounded up, but
 * never fewer than least (at most n): the rounds that every distinct case
 * of the loop needs, say a whole cycle of round % k. tests/valgrind-suite.sh
 * sets it, so that the suites under valgrind run fewer random rounds;
 * plain make check and the sanitizer builds run all n. Only for such
 * loops: distinct cases, scales and edge cases are never cut. */
int test_rounds(int n, int least);

/* add_tests(tc, a, b, ...): tcase_add_test() for each test named. */
void test_add_all(TCase *tc, const TTest *const *tests, size_t n);
#define add_tests(tc, ...)                                                     \
    test_add_all((tc), (const TTest *const[]){__VA_ARGS__},                    \
                 sizeof((const TTest *const[]){__VA_ARGS__}) / sizeof(const TTest *))

/* Run a suite with Check's runner (verbosity from CK_VERBOSITY) and return
 * the process exit status: EXIT_SUCCESS iff every test passed. */
int run_suite(Suite *suite);

/* splitmix64: small, seedable, identical on every platform. The tests'
 * own copy, so that they do not depend on the library's. */
uint64_t test_rand(uint64_t *state);
/* Uniform integer in [0, n). */
size_t test_rand_below(uint64_t *state, size_t n);
/* Uniform double in [0, 1): the top 53 bits of test_rand(). */
double test_uniform(uint64_t *state);
/* A random unit quaternion: a uniform point of the 4-ball (away from its
 * centre) scaled to length 1; draws from test_uniform(state). */
void test_random_quat(uint64_t *state, noctQuat *q);
/* A random direction of length 1, drawn as test_random_quat() draws. */
void test_random_direction(uint64_t *state, double dir[3]);

/* An L-shaped prism: the L (0,0) (2,0) (2,1) (1,1) (1,2) (0,2) less
 * (1,1), z from -1/2 to 1/2; non-convex, its faces convex polygons. Fails
 * the running test unless the library makes it and finds it non-convex. */
noctMesh *make_ell(void);

/* A small tetrahedron of no symmetry (vertices (0, 0, 0), (0.9, 0.1, 0),
 * (0.2, 0.8, 0.1), (0.3, 0.2, 0.7)); fails the test if it cannot be made. */
noctMesh *make_tetrahedron(void);

/* Walk the subtree rooted at top and fail the running test unless:
 * parent and child links agree, each child's type is its slot, generation
 * equals the top's generation plus depth, a node is split iff it has all
 * eight children, the child iterator visits exactly the eight children in
 * vertex order, and (if top is a root) its child type is OMEGA. Returns the
 * number of nodes. Iterative, so it copes with very deep trees. */
size_t tree_validate(octNode *top);

/* Collect the nodes of the subtree rooted at top in pre-order into a
 * malloc'd array; *count receives its length. */
octNode **tree_nodes(octNode *top, size_t *count);

/* A mirror of a tree: the shape and an integer tag per node (0 = no data),
 * kept by plain pointers so it shares no code with the library. */
typedef struct model_node {
    struct model_node *kids[8];
    int tag;
} model_node;

model_node *model_new(void);
void model_free(model_node *m);
/* Fail the running test unless the tree under n has exactly the model's
 * shape and the data of each node is the tag the model expects. */
void model_compare(model_node *m, octNode *n);

/* Client data used by the tests: a tagged cell whose disposal is logged. */
typedef struct test_item {
    int tag;
} test_item;

test_item *item_new(int tag);
/* The octItemDisposer for test_items: frees the item and records its tag. */
void item_kill(void *data);
/* octItemPrinter for test_items: prints "item TAG". */
void item_print(FILE *strm, const void *data);
/* The log of disposed tags since the last reset, sorted ascending. */
void kill_log_reset(void);
size_t kill_log_sorted(const int **tags);

/* Distances in long double for the distance suites' brute forces
 * (testgeom.c). Squared distance from p to segment ab. */
long double test_point_seg2(const long double p[3], const long double a[3],
                            const long double b[3]);
/* Squared distance from p to the plane of triangle abc if its projection
 * falls inside the triangle, else infinity (the edges then decide). */
long double test_point_face2(const long double p[3], const long double a[3],
                             const long double b[3], const long double c[3]);
/* Squared distance between two disjoint closed triangles x and y, by
 * brute force over their vertices' projections and edge pairs, in long
 * double; the caller scales coordinates near 1. */
long double test_tri_tri2(long double x[3][3], long double y[3][3]);

/*
 * A lower bound on the distance between triangles a and b (their
 * vertices, placed), 0 when none is found, in doubles. For any direction
 * u, the gap between the two triangles' projections onto u, over |u|, is
 * at most their distance, whatever u is (u need not come out of its
 * formula exactly). The directions tried: the two normals, the nine
 * edges' cross products, and the line through the nearest two vertices,
 * among which is, up to rounding, the direction of the closest points
 * whenever a vertex meets a face, two edges meet, or two vertices meet.
 * Each u is scaled to a largest component of 1, so each projection u.p
 * errs by at most 3 (3 2^-53) M (M the largest coordinate) plus 3 2^-1074
 * for products below the normal range: E = 2^-49 M + 2^-1070 covers it;
 * the gap's subtraction and the norm's square root err by relative
 * 2^-52 or so, taken off with 2^-50 each.
 */
double test_tri_distance_lower(const double *const a[3], const double *const b[3]);

#endif /* NOCT_TESTS_TESTUTIL_H */
