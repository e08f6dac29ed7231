/* SPDX-License-Identifier: MIT */
/*
 * Check suite for the octree ADT (include/noctree/octree.h).
 *
 * One test case per operation, each testing the operation's ensures clauses
 * on real trees, including deep and wide ones; a property test of random
 * split/join sequences against a mirror model; and, in the defensive build
 * only, a death test per requires clause. The same file is compiled against
 * both libraries: with NOCT_EFFICIENT it uses the inline accessors and
 * leaves the death tests out.
 */
#include <check.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>

#include <noctree/octree.h>

#include "testutil.h"

/* Split every leaf of the subtree under n until it is depth levels deep. */
static void split_full(octNode *n, int depth)
{
    if (depth == 0)
        return;
    ck_assert(octSplit(n));
    for (int v = OCT_LDB; v <= OCT_RUF; ++v)
        split_full(octChild(n, (octDirection)v), depth - 1);
}

/* Split along one path of the given length, always into child v. */
static octNode *split_path(octNode *n, int length, octDirection v)
{
    for (int i = 0; i < length; ++i) {
        ck_assert(octSplit(n));
        n = octChild(n, v);
    }
    return n;
}

static size_t full_tree_size(int depth)
{
    size_t total = 0, level = 1;
    for (int d = 0; d <= depth; ++d, level *= 8)
        total += level;
    return total;
}

/* ---- octCreate ------------------------------------------------------- */

START_TEST(create_new_root)
{
    octNode *a = octCreate(), *b = octCreate();
    ck_assert_ptr_nonnull(a);
    ck_assert_ptr_nonnull(b);
    ck_assert_ptr_ne(a, b);
    ck_assert_ptr_null(octParent(a));
    ck_assert_int_eq(octChildType(a), OCT_OMEGA);
    ck_assert_int_eq(octGeneration(a), 0);
    ck_assert(!octIsSplit(a));
    ck_assert_ptr_null(octData(a));
    ck_assert_uint_eq(tree_validate(a), 1);
    octDispose(a);
    octDispose(b);
}
END_TEST

/* ---- octDispose ------------------------------------------------------ */

START_TEST(dispose_wide_and_deep)
{
    /* Leaks or double frees here are caught by ASan and valgrind in CI. */
    octNode *wide = octCreate();
    split_full(wide, 4);
    ck_assert_uint_eq(tree_validate(wide), full_tree_size(4));
    octDispose(wide);

    octNode *deep = octCreate();
    octNode *bottom = split_path(deep, 100000, OCT_RDF);
    ck_assert_int_eq(octGeneration(bottom), 100000);
    octDispose(deep);

    octNode *leaf = octCreate();
    octDispose(leaf);
}
END_TEST

/* ---- octClear -------------------------------------------------------- */

START_TEST(clear_kills_every_datum_once)
{
    octNode *root = octCreate();
    split_full(root, 3);
    size_t n;
    octNode **all = tree_nodes(root, &n);
    ck_assert_uint_eq(n, full_tree_size(3));
    /* Data on every third node, the root included. */
    size_t expected = 0;
    for (size_t i = 0; i < n; i += 3, ++expected)
        ck_assert_ptr_null(octSwapData(all[i], item_new((int)i + 1)));
    kill_log_reset();
    octClear(root, item_kill);
    const int *tags;
    ck_assert_uint_eq(kill_log_sorted(&tags), expected);
    for (size_t k = 0; k < expected; ++k)
        ck_assert_int_eq(tags[k], (int)(3 * k) + 1);
    for (size_t i = 0; i < n; ++i)
        ck_assert_ptr_null(octData(all[i]));
    ck_assert_uint_eq(tree_validate(root), n); /* shape unchanged */
    kill_log_reset();
    free(all);
    octDispose(root);
}
END_TEST

START_TEST(clear_subtree_only)
{
    octNode *root = octCreate();
    split_full(root, 2);
    octNode *sub = octChild(root, OCT_LUF);
    octSwapData(root, item_new(1));
    octSwapData(octChild(root, OCT_RDB), item_new(2));
    octSwapData(sub, item_new(3));
    octSwapData(octChild(sub, OCT_RUF), item_new(4));
    kill_log_reset();
    octClear(sub, item_kill);
    const int *tags;
    ck_assert_uint_eq(kill_log_sorted(&tags), 2);
    ck_assert_int_eq(tags[0], 3);
    ck_assert_int_eq(tags[1], 4);
    ck_assert_int_eq(((test_item *)octData(root))->tag, 1);
    ck_assert_int_eq(((test_item *)octData(octChild(root, OCT_RDB)))->tag, 2);
    /* An empty subtree may be cleared without a disposer. */
    octClear(sub, NULL);
    kill_log_reset();
    octClear(root, item_kill);
    ck_assert_uint_eq(kill_log_sorted(&tags), 2);
    kill_log_reset();
    octDispose(root);
}
END_TEST

/* ---- octParent ------------------------------------------------------- */

START_TEST(parent_links)
{
    octNode *root = octCreate();
    ck_assert_ptr_null(octParent(root));
    octNode *bottom = split_path(root, 50, OCT_LDF);
    int up = 0;
    for (octNode *n = bottom; n != root; n = octParent(n))
        ++up;
    ck_assert_int_eq(up, 50);
    for (int v = OCT_LDB; v <= OCT_RUF; ++v)
        ck_assert_ptr_eq(octParent(octChild(root, (octDirection)v)), root);
    octDispose(root);
}
END_TEST

/* ---- octChild -------------------------------------------------------- */

START_TEST(child_of_leaf_and_split)
{
    octNode *root = octCreate();
    for (int v = OCT_LDB; v <= OCT_RUF; ++v)
        ck_assert_ptr_null(octChild(root, (octDirection)v));
    ck_assert(octSplit(root));
    for (int v = OCT_LDB; v <= OCT_RUF; ++v) {
        octNode *c = octChild(root, (octDirection)v);
        ck_assert_ptr_nonnull(c);
        ck_assert_int_eq(octChildType(c), v);
        for (int w = OCT_LDB; w < v; ++w)
            ck_assert_ptr_ne(octChild(root, (octDirection)w), c);
    }
    octDispose(root);
}
END_TEST

/* ---- octChildType ---------------------------------------------------- */

START_TEST(child_type_of_root_and_children)
{
    octNode *root = octCreate();
    ck_assert_int_eq(octChildType(root), OCT_OMEGA);
    octNode *n = split_path(root, 3, OCT_RUB);
    ck_assert_int_eq(octChildType(n), OCT_RUB);
    ck_assert(octSplit(n));
    for (int v = OCT_LDB; v <= OCT_RUF; ++v)
        ck_assert_int_eq(octChildType(octChild(n, (octDirection)v)), v);
    ck_assert_int_eq(octChildType(root), OCT_OMEGA);
    octDispose(root);
}
END_TEST

/* ---- octIsSplit ------------------------------------------------------ */

START_TEST(is_split_tracks_split_and_join)
{
    octNode *root = octCreate();
    ck_assert(!octIsSplit(root));
    ck_assert(octSplit(root));
    ck_assert(octIsSplit(root));
    ck_assert(!octIsSplit(octChild(root, OCT_LDB)));
    octJoin(root, NULL);
    ck_assert(!octIsSplit(root));
    octDispose(root);
}
END_TEST

/* ---- octSplit -------------------------------------------------------- */

START_TEST(split_gives_eight_empty_leaves)
{
    octNode *root = octCreate();
    octNode *n = split_path(root, 7, OCT_LUB);
    test_item *mine = item_new(42);
    octSwapData(n, mine);
    ck_assert(octSplit(n));
    ck_assert_ptr_eq(octData(n), mine); /* own datum untouched */
    for (int v = OCT_LDB; v <= OCT_RUF; ++v) {
        octNode *c = octChild(n, (octDirection)v);
        ck_assert_int_eq(octGeneration(c), 8);
        ck_assert_ptr_null(octData(c));
        ck_assert(!octIsSplit(c));
    }
    ck_assert_uint_eq(tree_validate(root), 7 * 8 + 1 + 8);
    free(octSwapData(n, NULL));
    octDispose(root);
}
END_TEST

/* ---- octJoin --------------------------------------------------------- */

START_TEST(join_removes_all_descendants)
{
    octNode *root = octCreate();
    split_full(root, 2);
    octNode *deep = split_path(octChild(octChild(root, OCT_RDF), OCT_LDB), 5,
                               OCT_LDB);
    octSwapData(root, item_new(1));
    octSwapData(octChild(root, OCT_LUB), item_new(2));
    octSwapData(deep, item_new(3));
    octSwapData(octChild(octChild(root, OCT_RUF), OCT_RUF), item_new(4));
    kill_log_reset();
    octJoin(root, item_kill);
    const int *tags;
    ck_assert_uint_eq(kill_log_sorted(&tags), 3);
    ck_assert_int_eq(tags[0], 2);
    ck_assert_int_eq(tags[1], 3);
    ck_assert_int_eq(tags[2], 4);
    ck_assert(!octIsSplit(root));
    ck_assert_int_eq(((test_item *)octData(root))->tag, 1); /* kept */
    ck_assert_uint_eq(tree_validate(root), 1);
    /* The node can be split again, and gets fresh empty children. */
    ck_assert(octSplit(root));
    ck_assert_uint_eq(tree_validate(root), 9);
    for (int v = OCT_LDB; v <= OCT_RUF; ++v)
        ck_assert_ptr_null(octData(octChild(root, (octDirection)v)));
    kill_log_reset();
    octClear(root, item_kill);
    kill_log_reset();
    octDispose(root);
}
END_TEST

START_TEST(join_inner_node_leaves_rest)
{
    octNode *root = octCreate();
    split_full(root, 3);
    octNode *mid = octChild(root, OCT_RDB);
    octJoin(mid, NULL);
    ck_assert_uint_eq(tree_validate(root), full_tree_size(3) - 72);
    ck_assert(octIsSplit(octChild(root, OCT_RDF)));
    octDispose(root);
}
END_TEST

/* ---- octGeneration --------------------------------------------------- */

START_TEST(generation_is_depth)
{
    octNode *root = octCreate();
    ck_assert_int_eq(octGeneration(root), 0);
    octNode *n = root;
    for (int g = 1; g <= 1000; ++g) {
        ck_assert(octSplit(n));
        n = octChild(n, (octDirection)(OCT_LDB + g % 8));
        ck_assert_int_eq(octGeneration(n), g);
    }
    octDispose(root);
}
END_TEST

/* ---- octData / octSwapData ------------------------------------------- */

START_TEST(data_and_swap)
{
    octNode *root = octCreate();
    int a = 1, b = 2;
    ck_assert_ptr_null(octSwapData(root, &a));
    ck_assert_ptr_eq(octData(root), &a);
    ck_assert_ptr_eq(octSwapData(root, &b), &a);
    ck_assert_ptr_eq(octData(root), &b);
    ck_assert(octSplit(root));
    octNode *c = octChild(root, OCT_RUF);
    ck_assert_ptr_null(octSwapData(c, &a));
    ck_assert_ptr_eq(octData(c), &a);
    ck_assert_ptr_eq(octData(root), &b); /* independent per node */
    ck_assert_ptr_eq(octSwapData(c, NULL), &a);
    ck_assert_ptr_eq(octSwapData(root, NULL), &b);
    ck_assert_ptr_null(octData(root));
    octDispose(root);
}
END_TEST

/* ---- octInitChildIterator / octNextChild ----------------------------- */

START_TEST(iterator_visits_each_child_once)
{
    octNode *root = octCreate();
    ck_assert(octSplit(root));
    octInitChildIterator(root);
    octNode *c = NULL, *seen[8];
    int count = 0;
    while (octNextChild(root, &c)) {
        ck_assert_int_lt(count, 8);
        ck_assert_ptr_eq(octParent(c), root);
        for (int i = 0; i < count; ++i)
            ck_assert_ptr_ne(seen[i], c);
        seen[count++] = c;
    }
    ck_assert_int_eq(count, 8);
    /* Exhausted: stays false and leaves *N2 alone. */
    octNode *untouched = root;
    ck_assert(!octNextChild(root, &untouched));
    ck_assert_ptr_eq(untouched, root);
    /* Re-initializing starts over. */
    octInitChildIterator(root);
    ck_assert(octNextChild(root, &c));
    ck_assert_ptr_eq(c, octChild(root, OCT_LDB));
    octDispose(root);
}
END_TEST

START_TEST(iterator_nests_over_different_nodes)
{
    octNode *root = octCreate();
    split_full(root, 2);
    int pairs = 0;
    octNode *a, *b;
    octInitChildIterator(root);
    while (octNextChild(root, &a)) {
        octInitChildIterator(a);
        while (octNextChild(a, &b)) {
            ck_assert_ptr_eq(octParent(b), a);
            ++pairs;
        }
    }
    ck_assert_int_eq(pairs, 64);
    octDispose(root);
}
END_TEST

/* ---- octPrint -------------------------------------------------------- */

static char *print_to_string(octNode *n, octItemPrinter *prnt)
{
    FILE *f = tmpfile();
    ck_assert_ptr_nonnull(f);
    ck_assert(octPrint(n, prnt, f));
    long len = ftell(f);
    ck_assert_int_gt(len, 0);
    char *buf = malloc((size_t)len + 1);
    ck_assert_ptr_nonnull(buf);
    rewind(f);
    ck_assert_uint_eq(fread(buf, 1, (size_t)len, f), (size_t)len);
    buf[len] = '\0';
    fclose(f);
    return buf;
}

START_TEST(print_subtree)
{
    octNode *root = octCreate();
    ck_assert(octSplit(root));
    octNode *ruf = octChild(root, OCT_RUF);
    ck_assert(octSplit(octChild(root, OCT_LDB)));
    octSwapData(root, item_new(7));
    octSwapData(octChild(octChild(root, OCT_LDB), OCT_LDF), item_new(9));
    char *text = print_to_string(root, item_print);
    ck_assert_str_eq(text,
        "OMEGA 0: item 7\n"
        "  LDB 1\n"
        "    LDB 2\n"
        "    LDF 2: item 9\n"
        "    LUB 2\n" "    LUF 2\n" "    RDB 2\n" "    RDF 2\n"
        "    RUB 2\n" "    RUF 2\n"
        "  LDF 1\n" "  LUB 1\n" "  LUF 1\n" "  RDB 1\n" "  RDF 1\n"
        "  RUB 1\n" "  RUF 1\n");
    free(text);
    /* Without a printer only the structure is printed. */
    text = print_to_string(octChild(root, OCT_LDB), NULL);
    ck_assert_str_eq(text,
        "LDB 1\n"
        "  LDB 2\n" "  LDF 2\n" "  LUB 2\n" "  LUF 2\n"
        "  RDB 2\n" "  RDF 2\n" "  RUB 2\n" "  RUF 2\n");
    free(text);
    text = print_to_string(ruf, item_print);
    ck_assert_str_eq(text, "RUF 1\n");
    free(text);
    kill_log_reset();
    octClear(root, item_kill);
    kill_log_reset();
    octDispose(root);
}
END_TEST

START_TEST(print_reports_write_errors)
{
    FILE *full = fopen("/dev/full", "w");
    ck_assert_msg(full != NULL, "/dev/full is needed for this test");
    setvbuf(full, NULL, _IONBF, 0);
    octNode *root = octCreate();
    ck_assert(octSplit(root));
    ck_assert(!octPrint(root, NULL, full));
    fclose(full);
    octDispose(root);
}
END_TEST

/* ---- octDirToStr / octStrToDir / octParseDir ------------------------- */

START_TEST(dir_names_round_trip)
{
    static const char *const expect[] = {
        "L", "R", "D", "U", "B", "F", "LD", "LU", "LB", "LF", "RD", "RU",
        "RB", "RF", "DB", "DF", "UB", "UF", "LDB", "LDF", "LUB", "LUF",
        "RDB", "RDF", "RUB", "RUF", "OMEGA"};
    for (int d = 0; d <= OCT_OMEGA; ++d) {
        const char *s = octDirToStr((octDirection)d);
        ck_assert_str_eq(s, expect[d]);
        ck_assert_int_eq(octStrToDir(s), d);
        char lower[8];
        size_t i = 0;
        for (; s[i] != '\0'; ++i)
            lower[i] = (char)(s[i] - 'A' + 'a');
        lower[i] = '\0';
        ck_assert_int_eq(octStrToDir(lower), d);
    }
    ck_assert_int_eq(octStrToDir("rUf"), OCT_RUF);
    ck_assert_int_eq(octStrToDir("Omega"), OCT_OMEGA);
}
END_TEST

START_TEST(parse_dir_rejects_bad_names)
{
    octDirection d = OCT_LD;
    static const char *const bad[] = {"", "X", "LDBX", "LL", "RUF ", " L",
                                      "OMEGAX", "ω", "DL"};
    for (size_t i = 0; i < sizeof bad / sizeof *bad; ++i) {
        ck_assert(!octParseDir(bad[i], &d));
        ck_assert_int_eq(d, OCT_LD); /* unchanged */
    }
    ck_assert(!octParseDir(NULL, &d));
    ck_assert(octParseDir("lub", &d));
    ck_assert_int_eq(d, OCT_LUB);
}
END_TEST

/* ---- the short names -------------------------------------------------- */

int short_names_match(void); /* short_names.c */

START_TEST(short_names_alias_prefixed)
{
    ck_assert(short_names_match());
}
END_TEST

/* ---- random split/join sequences against the model -------------------- */

/* Model side of octJoin: collect the tags of every descendant of m and
 * drop them. */
static void model_join(model_node *m, int **tags, size_t *n)
{
    for (int i = 0; i < 8; ++i) {
        model_node *k = m->kids[i];
        if (k == NULL)
            continue;
        if (k->tag != 0) {
            *tags = realloc(*tags, (*n + 1) * sizeof **tags);
            (*tags)[(*n)++] = k->tag;
        }
        model_join(k, tags, n);
        free(k);
        m->kids[i] = NULL;
    }
}

/* The model node at the same path as n (found by climbing n). */
static model_node *model_find(model_node *root, octNode *n)
{
    int path[4096], len = 0;
    for (; octParent(n) != NULL; n = octParent(n)) {
        ck_assert_int_lt(len, 4096);
        path[len++] = octChildType(n) - OCT_LDB;
    }
    model_node *m = root;
    while (len > 0)
        m = m->kids[path[--len]];
    return m;
}

static int cmp_tag(const void *a, const void *b)
{
    return *(const int *)a - *(const int *)b;
}

START_TEST(random_split_join_sequences)
{
    uint64_t rng = 0x5eed0000u + (uint64_t)_i;
    octNode *root = octCreate();
    model_node *model = model_new();
    int next_tag = 1;
    for (int step = 0; step < 400; ++step) {
        size_t n;
        octNode **all = tree_nodes(root, &n);
        octNode *pick = all[test_rand_below(&rng, n)];
        model_node *m = model_find(model, pick);
        unsigned op = (unsigned)test_rand_below(&rng, 10);
        if (op < 3) { /* attach or replace data */
            test_item *old = octSwapData(pick, item_new(next_tag));
            free(old);
            m->tag = next_tag++;
        } else if (!octIsSplit(pick) && octGeneration(pick) < 12) {
            ck_assert(octSplit(pick));
            for (int i = 0; i < 8; ++i)
                m->kids[i] = model_new();
        } else if (octIsSplit(pick)) {
            int *want = NULL;
            size_t nwant = 0;
            model_join(m, &want, &nwant);
            kill_log_reset();
            octJoin(pick, item_kill);
            const int *got;
            ck_assert_uint_eq(kill_log_sorted(&got), nwant);
            if (nwant > 0)
                qsort(want, nwant, sizeof *want, cmp_tag);
            for (size_t k = 0; k < nwant; ++k)
                ck_assert_int_eq(got[k], want[k]);
            free(want);
        }
        free(all);
        tree_validate(root);
        model_compare(model, root);
    }
    kill_log_reset();
    octClear(root, item_kill);
    kill_log_reset();
    octDispose(root);
    model_free(model);
}
END_TEST

START_TEST(large_full_tree)
{
    octNode *root = octCreate();
    split_full(root, 6);
    ck_assert_uint_eq(tree_validate(root), full_tree_size(6));
    octJoin(octChild(root, OCT_LUF), NULL);
    ck_assert_uint_eq(tree_validate(root),
                      full_tree_size(6) - (full_tree_size(5) - 1));
    octDispose(root);
}
END_TEST

/* ---- death tests: one per requires clause (defensive build only) ------ */
#ifndef NOCT_EFFICIENT

static void kill_nothing(void *data) { (void)data; }

START_TEST(die_dispose_non_root)
{
    octNode *root = octCreate();
    octSplit(root);
    octDispose(octChild(root, OCT_LDB));
}
END_TEST

START_TEST(die_dispose_with_data)
{
    static int x;
    octNode *root = octCreate();
    octSplit(root);
    octSwapData(octChild(root, OCT_RUF), &x);
    octDispose(root);
}
END_TEST

START_TEST(die_clear_without_disposer)
{
    static int x;
    octNode *root = octCreate();
    octSwapData(root, &x);
    octClear(root, NULL);
}
END_TEST

START_TEST(die_child_of_face)
{
    octNode *root = octCreate();
    octSplit(root);
    octChild(root, OCT_L);
}
END_TEST

START_TEST(die_child_of_edge)
{
    octNode *root = octCreate();
    octChild(root, OCT_UF);
}
END_TEST

START_TEST(die_child_of_omega)
{
    octNode *root = octCreate();
    octChild(root, OCT_OMEGA);
}
END_TEST

START_TEST(die_split_twice)
{
    octNode *root = octCreate();
    octSplit(root);
    octSplit(root);
}
END_TEST

START_TEST(die_join_leaf)
{
    octNode *root = octCreate();
    octJoin(root, kill_nothing);
}
END_TEST

START_TEST(die_join_without_disposer)
{
    static int x;
    octNode *root = octCreate();
    octSplit(root);
    octSplit(octChild(root, OCT_LDB));
    octSwapData(octChild(octChild(root, OCT_LDB), OCT_RUF), &x);
    octJoin(root, NULL);
}
END_TEST

START_TEST(die_init_iterator_on_leaf)
{
    octNode *root = octCreate();
    octInitChildIterator(root);
}
END_TEST

START_TEST(die_next_child_uninitialized)
{
    octNode *root = octCreate(), *c;
    octSplit(root);
    octNextChild(root, &c);
}
END_TEST

START_TEST(die_next_child_after_join)
{
    octNode *root = octCreate(), *c;
    octSplit(root);
    octInitChildIterator(root);
    octJoin(root, NULL);
    octNextChild(root, &c);
}
END_TEST

START_TEST(die_print_null_stream)
{
    octNode *root = octCreate();
    octPrint(root, NULL, NULL);
}
END_TEST

START_TEST(die_str_to_dir_invalid)
{
    octStrToDir("north");
}
END_TEST

START_TEST(die_str_to_dir_null)
{
    octStrToDir(NULL);
}
END_TEST

START_TEST(die_dir_to_str_out_of_range)
{
    octDirToStr((octDirection)(OCT_OMEGA + 1));
}
END_TEST

START_TEST(die_null_node)
{
    /* Each accessor's implicit clause: N is a node. _i selects which. */
    switch (_i) {
    case 0: octParent(NULL); break;
    case 1: octChildType(NULL); break;
    case 2: octIsSplit(NULL); break;
    case 3: octGeneration(NULL); break;
    case 4: octData(NULL); break;
    case 5: octSwapData(NULL, NULL); break;
    case 6: octChild(NULL, OCT_LDB); break;
    case 7: octSplit(NULL); break;
    case 8: octDispose(NULL); break;
    default: octClear(NULL, NULL); break;
    }
}
END_TEST
#endif /* !NOCT_EFFICIENT */

static TCase *tcase(Suite *s, const char *name, const TTest *t)
{
    TCase *tc = test_case(s, name, 60, NULL);
    tcase_add_test(tc, t);
    return tc;
}

static Suite *octree_suite(void)
{
    Suite *s = suite_create("octree");
    tcase(s, "octCreate", create_new_root);
    tcase(s, "octDispose", dispose_wide_and_deep);
    TCase *tc = tcase(s, "octClear", clear_kills_every_datum_once);
    tcase_add_test(tc, clear_subtree_only);
    tcase(s, "octParent", parent_links);
    tcase(s, "octChild", child_of_leaf_and_split);
    tcase(s, "octChildType", child_type_of_root_and_children);
    tcase(s, "octIsSplit", is_split_tracks_split_and_join);
    tcase(s, "octSplit", split_gives_eight_empty_leaves);
    tc = tcase(s, "octJoin", join_removes_all_descendants);
    tcase_add_test(tc, join_inner_node_leaves_rest);
    tcase(s, "octGeneration", generation_is_depth);
    tcase(s, "octData/octSwapData", data_and_swap);
    tc = tcase(s, "octNextChild", iterator_visits_each_child_once);
    tcase_add_test(tc, iterator_nests_over_different_nodes);
    tc = tcase(s, "octPrint", print_subtree);
    tcase_add_test(tc, print_reports_write_errors);
    tc = tcase(s, "octDirToStr/octStrToDir", dir_names_round_trip);
    tcase_add_test(tc, parse_dir_rejects_bad_names);
    tcase_add_test(tc, short_names_alias_prefixed);
    tc = tcase(s, "random trees", large_full_tree);
    tcase_add_loop_test(tc, random_split_join_sequences, 0, 8);

#ifndef NOCT_EFFICIENT
    TCase *d = test_case(s, "requires clauses", 0, "death");
    tcase_add_test_raise_signal(d, die_dispose_non_root, SIGABRT);
    tcase_add_test_raise_signal(d, die_dispose_with_data, SIGABRT);
    tcase_add_test_raise_signal(d, die_clear_without_disposer, SIGABRT);
    tcase_add_test_raise_signal(d, die_child_of_face, SIGABRT);
    tcase_add_test_raise_signal(d, die_child_of_edge, SIGABRT);
    tcase_add_test_raise_signal(d, die_child_of_omega, SIGABRT);
    tcase_add_test_raise_signal(d, die_split_twice, SIGABRT);
    tcase_add_test_raise_signal(d, die_join_leaf, SIGABRT);
    tcase_add_test_raise_signal(d, die_join_without_disposer, SIGABRT);
    tcase_add_test_raise_signal(d, die_init_iterator_on_leaf, SIGABRT);
    tcase_add_test_raise_signal(d, die_next_child_uninitialized, SIGABRT);
    tcase_add_test_raise_signal(d, die_next_child_after_join, SIGABRT);
    tcase_add_test_raise_signal(d, die_print_null_stream, SIGABRT);
    tcase_add_test_raise_signal(d, die_str_to_dir_invalid, SIGABRT);
    tcase_add_test_raise_signal(d, die_str_to_dir_null, SIGABRT);
    tcase_add_test_raise_signal(d, die_dir_to_str_out_of_range, SIGABRT);
    tcase_add_loop_test_raise_signal(d, die_null_node, SIGABRT, 0, 10);
#endif
    return s;
}

int main(void)
{
    return run_suite(octree_suite());
}
