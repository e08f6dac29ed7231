/* SPDX-License-Identifier: MIT */
/*
 * broadphase-demo: libnoctree's broadphase on its own, for a program with
 * a narrowphase of its own.
 *
 * A floor of 8 x 8 tiles and 6 crates falling onto it: the tiles are in
 * category 1 and do not pair with each other (mask 2), the crates are in
 * category 2 and pair with everything. Each frame the crates move, the
 * broadphase finds the pairs whose boxes overlap, and the demo prints
 * them; then a box query, a point query and a ray cast for the closest
 * crate. Build it with
 *   cc broadphase-demo.c $(pkg-config --cflags --libs noctree)
 */
#include <stdio.h>

#include <noctree/broadphase.h>

#define TILES 64
#define CRATES 6

static bool print_pair(void *context, noctProxyId a, void *user_a, noctProxyId b,
                       void *user_b)
{
    (void)a;
    (void)b;
    size_t *count = context;
    printf(" %s-%s", (const char *)user_a, (const char *)user_b);
    ++*count;
    return true;
}

static bool count_proxy(void *context, noctProxyId id, void *user_data)
{
    (void)id;
    (void)user_data;
    ++*(int *)context;
    return true;
}

/* The closest crate along the ray: clip the ray at each one found. */
static double closest(void *context, noctProxyId id, void *user_data, double t)
{
    (void)id;
    const char **name = context;
    *name = user_data;
    return t;
}

static int fail(const char *what, const noctError *err)
{
    fprintf(stderr, "broadphase-demo: %s: %s\n", what, err->message);
    return 1;
}

int main(void)
{
    static const char *const tile_name = "tile";
    static const char *const crate_names[CRATES] = {"A", "B", "C", "D", "E", "F"};
    noctBroadphaseDef def = noctDefaultBroadphaseDef();
    def.N = 4;
    noctBroadphase *bp;
    noctError err;
    if (noctBroadphaseCreate(&def, &bp, &err) != NOCT_OK)
        return fail("create", &err);

    /* the floor: tiles 1 x 1, side by side, their top at z = 0 */
    for (int i = 0; i < TILES; ++i) {
        const double lo[3] = {i % 8, i / 8, -0.5}, hi[3] = {i % 8 + 1, i / 8 + 1, 0};
        noctProxyId id;
        if (noctBroadphaseAdd(bp, lo, hi, (void *)tile_name, 1, 2, &id, &err) != NOCT_OK)
            return fail("add a tile", &err);
    }
    /* the crates, 0.8 wide, at heights 1 to 6 */
    noctProxyId crate[CRATES];
    double x[CRATES], z[CRATES];
    for (int c = 0; c < CRATES; ++c) {
        x[c] = 0.5 + 1.2 * c;
        z[c] = 1 + c;
        const double lo[3] = {x[c], 3.1, z[c]}, hi[3] = {x[c] + 0.8, 3.9, z[c] + 0.8};
        if (noctBroadphaseAdd(bp, lo, hi, (void *)crate_names[c], 2, NOCT_FILTER_ALL,
                              &crate[c], &err) != NOCT_OK)
            return fail("add a crate", &err);
    }

    size_t total = 0;
    for (int frame = 0; frame < 8; ++frame) {
        /* the crates fall 0.5 a frame and stop on the floor */
        for (int c = 0; c < CRATES; ++c) {
            z[c] = z[c] - 0.5 < 0 ? 0 : z[c] - 0.5;
            const double lo[3] = {x[c], 3.1, z[c]}, hi[3] = {x[c] + 0.8, 3.9, z[c] + 0.8};
            if (noctBroadphaseMove(bp, crate[c], lo, hi, &err) != NOCT_OK)
                return fail("move", &err);
        }
        if (noctBroadphaseUpdatePairs(bp, &err) != NOCT_OK)
            return fail("pairs", &err);
        printf("frame %d:", frame);
        size_t n = 0;
        noctBroadphaseForEachPair(bp, print_pair, &n);
        printf(" (%zu pairs)\n", n);
        total += n;
    }

    /* queries: what lies in the floor's left half, what is at a point,
     * and the first crate a ray along x meets */
    const double qlo[3] = {0, 0, -1}, qhi[3] = {4, 8, 1};
    int in_box = 0, at_point = 0;
    if (noctBroadphaseQueryBox(bp, qlo, qhi, noctDefaultQueryFilter(), count_proxy,
                               &in_box) != NOCT_OK)
        return 1;
    const double point[3] = {2.5, 3.5, 0};
    if (noctBroadphaseQueryPoint(bp, point, noctDefaultQueryFilter(), count_proxy,
                                 &at_point) != NOCT_OK)
        return 1;
    const noctQueryFilter crates_only = {NOCT_FILTER_ALL, 2};
    const double origin[3] = {-5, 3.5, 0.4}, along[3] = {20, 0, 0};
    const char *first = "none";
    if (noctBroadphaseRayCast(bp, origin, along, crates_only, closest, &first) != NOCT_OK)
        return 1;
    printf("box query: %d proxies\npoint query: %d proxies\nray: first crate %s\n", in_box,
           at_point, first);

    noctBroadphaseCounters counters;
    noctBroadphaseGetCounters(bp, &counters);
    printf("proxies %llu, leaves %llu, splits %llu\n", (unsigned long long)counters.proxies,
           (unsigned long long)counters.leaves, (unsigned long long)counters.splits);
    printf("pairs total %zu\n", total);
    noctBroadphaseDestroy(bp);
    return 0;
}
