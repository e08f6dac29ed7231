/* SPDX-License-Identifier: MIT */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

TCase *test_case(Suite *s, const char *name, int seconds, const char *tags)
{
    TCase *tc = tcase_create(name);
    if (tags != NULL)
        tcase_set_tags(tc, tags);
    tcase_set_timeout(tc, seconds > 0 ? seconds : TEST_DEFAULT_TIMEOUT);
    suite_add_tcase(s, tc);
    return tc;
}

void test_add_all(TCase *tc, const TTest *const *tests, size_t n)
{
    for (size_t i = 0; i < n; ++i)
        tcase_add_test(tc, tests[i]);
}

bool test_marks;

int run_suite(Suite *suite)
{
    const char *marks = getenv("NOCT_TEST_MARKS");
    test_marks = marks != NULL && strcmp(marks, "1") == 0;
    SRunner *sr = srunner_create(suite);
    srunner_run_all(sr, CK_ENV);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

int test_rounds(int n, int least)
{
    const char *v = getenv("NOCT_TEST_ROUNDS_DIVISOR");
    char *end;
    const long d = v != NULL ? strtol(v, &end, 10) : 1;
    if (v == NULL || end == v || *end != '\0' || d <= 1)
        return n;
    const long r = (n + d - 1) / d;
    return r >= least ? (int)r : least < n ? least : n;
}

uint64_t test_rand(uint64_t *state)
{
    uint64_t z = (*state += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}

size_t test_rand_below(uint64_t *state, size_t n)
{
    return (size_t)(test_rand(state) % n);
}

double test_uniform(uint64_t *state)
{
    return (double)(test_rand(state) >> 11) * 0x1p-53;
}

/* A uniform point of the n-ball away from its centre, scaled to length 1. */
static void random_unit(uint64_t *state, double *c, int n)
{
    double l;
    do {
        l = 0;
        for (int k = 0; k < n; ++k) {
            c[k] = 2 * test_uniform(state) - 1;
            l += c[k] * c[k];
        }
    } while (l < 0.01 || l > 1);
    l = sqrt(l);
    for (int k = 0; k < n; ++k)
        c[k] /= l;
}

void test_random_quat(uint64_t *state, noctQuat *q)
{
    double c[4];
    random_unit(state, c, 4);
    *q = (noctQuat){c[0], c[1], c[2], c[3]};
}

void test_random_direction(uint64_t *state, double dir[3])
{
    random_unit(state, dir, 3);
}

noctMesh *make_ell(void)
{
    static const double P[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
    double v[36];
    for (int i = 0; i < 12; ++i) {
        v[3 * i] = P[i % 6][0] - 1;
        v[3 * i + 1] = P[i % 6][1] - 1;
        v[3 * i + 2] = i < 6 ? -0.5 : 0.5;
    }
    uint32_t sizes[10], idx[40];
    size_t n = 0, k = 0;
    const uint32_t faces[4][4] = {{6, 7, 8, 9}, {6, 9, 10, 11}, {0, 3, 2, 1}, {0, 5, 4, 3}};
    for (int f = 0; f < 4; ++f) {
        sizes[n++] = 4;
        for (int c = 0; c < 4; ++c)
            idx[k++] = faces[f][c];
    }
    for (uint32_t i = 0; i < 6; ++i) {
        const uint32_t j = (i + 1) % 6;
        sizes[n++] = 4;
        idx[k++] = i;
        idx[k++] = j;
        idx[k++] = j + 6;
        idx[k++] = i + 6;
    }
    noctMesh *m;
    noctError err;
    ck_assert_msg(noctMeshCreate(v, 12, sizes, n, idx, &m, &err) == NOCT_OK, "%s", err.message);
    ck_assert(!noctMeshIsConvex(m));
    return m;
}

/* A growable stack of nodes with their depth below the walk's top. */
typedef struct {
    octNode **node;
    int *depth;
    size_t len, cap;
} node_stack;

static void push(node_stack *s, octNode *n, int depth)
{
    if (s->len == s->cap) {
        s->cap = s->cap ? 2 * s->cap : 64;
        s->node = realloc(s->node, s->cap * sizeof *s->node);
        s->depth = realloc(s->depth, s->cap * sizeof *s->depth);
        EXPECT(s->node != NULL);
        EXPECT(s->depth != NULL);
    }
    s->node[s->len] = n;
    s->depth[s->len] = depth;
    s->len++;
}

size_t tree_validate(octNode *top)
{
    node_stack s = {0};
    size_t count = 0;
    int gen0 = octGeneration(top);

    EXPECT(gen0 >= 0);
    if (octParent(top) == NULL) {
        EXPECT(octChildType(top) == OCT_OMEGA);
        EXPECT(gen0 == 0);
    }
    push(&s, top, 0);
    while (s.len > 0) {
        s.len--;
        octNode *n = s.node[s.len];
        int depth = s.depth[s.len];
        count++;
        EXPECT(octGeneration(n) == gen0 + depth);
        if (n != top) {
            octNode *p = octParent(n);
            EXPECT(p != NULL);
            EXPECT(octChild(p, octChildType(n)) == n);
        }
        if (!octIsSplit(n)) {
            for (int v = OCT_LDB; v <= OCT_RUF; ++v)
                EXPECT(octChild(n, (octDirection)v) == NULL);
            continue;
        }
        octNode *kids[8];
        for (int v = OCT_LDB; v <= OCT_RUF; ++v) {
            octNode *c = octChild(n, (octDirection)v);
            EXPECT(c != NULL);
            EXPECT(c != n);
            EXPECT(octParent(c) == n);
            EXPECT((int)octChildType(c) == v);
            for (int w = OCT_LDB; w < v; ++w)
                EXPECT(kids[w - OCT_LDB] != c);
            kids[v - OCT_LDB] = c;
        }
        octInitChildIterator(n);
        octNode *c = NULL;
        for (int i = 0; i < 8; ++i) {
            EXPECT(octNextChild(n, &c));
            EXPECT(c == kids[i]);
        }
        EXPECT(!octNextChild(n, &c));
        for (int i = 7; i >= 0; --i)
            push(&s, kids[i], depth + 1);
    }
    free(s.node);
    free(s.depth);
    return count;
}

octNode **tree_nodes(octNode *top, size_t *count)
{
    node_stack s = {0};
    size_t len = 0, cap = 64;
    octNode **out = malloc(cap * sizeof *out);
    EXPECT(out != NULL);
    push(&s, top, 0);
    while (s.len > 0) {
        octNode *n = s.node[--s.len];
        if (len == cap) {
            cap *= 2;
            out = realloc(out, cap * sizeof *out);
            EXPECT(out != NULL);
        }
        out[len++] = n;
        for (int v = OCT_RUF; v >= OCT_LDB && octIsSplit(n); --v)
            push(&s, octChild(n, (octDirection)v), 0);
    }
    free(s.node);
    free(s.depth);
    *count = len;
    return out;
}

model_node *model_new(void)
{
    model_node *m = calloc(1, sizeof *m);
    EXPECT(m != NULL);
    return m;
}

void model_free(model_node *m)
{
    if (m == NULL)
        return;
    for (int i = 0; i < 8; ++i)
        model_free(m->kids[i]);
    free(m);
}

void model_compare(model_node *m, octNode *n)
{
    const test_item *item = octData(n);
    EXPECT((item ? item->tag : 0) == m->tag);
    EXPECT(octIsSplit(n) == (m->kids[0] != NULL));
    for (int i = 0; i < 8 && m->kids[0] != NULL; ++i)
        model_compare(m->kids[i], octChild(n, (octDirection)(OCT_LDB + i)));
}

static int *kill_log;
static size_t kill_len, kill_cap;

test_item *item_new(int tag)
{
    test_item *it = malloc(sizeof *it);
    EXPECT(it != NULL);
    it->tag = tag;
    return it;
}

void item_kill(void *data)
{
    test_item *it = data;
    EXPECT(it != NULL);
    if (kill_len == kill_cap) {
        kill_cap = kill_cap ? 2 * kill_cap : 64;
        kill_log = realloc(kill_log, kill_cap * sizeof *kill_log);
        EXPECT(kill_log != NULL);
    }
    kill_log[kill_len++] = it->tag;
    free(it);
}

void item_print(FILE *strm, const void *data)
{
    const test_item *it = data;
    fprintf(strm, "item %d", it->tag);
}

void kill_log_reset(void)
{
    free(kill_log);
    kill_log = NULL;
    kill_len = kill_cap = 0;
}

static int cmp_int(const void *a, const void *b)
{
    int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

size_t kill_log_sorted(const int **tags)
{
    if (kill_len > 0)
        qsort(kill_log, kill_len, sizeof *kill_log, cmp_int);
    *tags = kill_log;
    return kill_len;
}

noctMesh *make_tetrahedron(void)
{
    static const double v[12] = {0, 0, 0, 0.9, 0.1, 0, 0.2, 0.8, 0.1, 0.3, 0.2, 0.7};
    static const uint32_t sizes[4] = {3, 3, 3, 3};
    static const uint32_t idx[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    noctMesh *m;
    ck_assert_int_eq(noctMeshCreate(v, 4, sizes, 4, idx, &m, NULL), NOCT_OK);
    return m;
}

static void sub3(const double *p, const double *q, double out[3])
{
    for (int k = 0; k < 3; ++k)
        out[k] = p[k] - q[k];
}

static void cross3(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* (testutil.h) */
double test_tri_distance_lower(const double *const a[3], const double *const b[3])
{
    double M = 0;
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k)
            M = fmax(M, fmax(fabs(a[i][k]), fabs(b[i][k])));
    double u[14][3], ea[3][3], eb[3][3];
    for (int i = 0; i < 3; ++i) {
        sub3(a[(i + 1) % 3], a[i], ea[i]);
        sub3(b[(i + 1) % 3], b[i], eb[i]);
    }
    int n = 0;
    cross3(ea[0], ea[1], u[n++]);
    cross3(eb[0], eb[1], u[n++]);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            cross3(ea[i], eb[j], u[n++]);
    double best = INFINITY;
    int bi = 0, bj = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double d[3];
            sub3(b[j], a[i], d);
            const double q = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            if (q < best) {
                best = q;
                bi = i;
                bj = j;
            }
        }
    sub3(b[bj], a[bi], u[n++]);
    const double E = 0x1p-49 * M + 0x1p-1070;
    double lower = 0;
    for (int t = 0; t < n; ++t) {
        const double big = fmax(fabs(u[t][0]), fmax(fabs(u[t][1]), fabs(u[t][2])));
        if (!(big > 0) || !isfinite(big))
            continue;
        double v[3];
        for (int k = 0; k < 3; ++k)
            v[k] = u[t][k] / big;
        double alo = INFINITY, ahi = -INFINITY, blo = INFINITY, bhi = -INFINITY;
        for (int i = 0; i < 3; ++i) {
            const double pa = v[0] * a[i][0] + v[1] * a[i][1] + v[2] * a[i][2];
            const double pb = v[0] * b[i][0] + v[1] * b[i][1] + v[2] * b[i][2];
            alo = fmin(alo, pa);
            ahi = fmax(ahi, pa);
            blo = fmin(blo, pb);
            bhi = fmax(bhi, pb);
        }
        const double gap = fmax(blo - ahi, alo - bhi) * (1 - 0x1p-50) - 2 * E;
        if (!(gap > 0))
            continue;
        const double norm = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) * (1 + 0x1p-50);
        lower = fmax(lower, gap / norm * (1 - 0x1p-50));
    }
    return lower;
}
