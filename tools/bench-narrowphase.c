/* SPDX-License-Identifier: MIT */
/*
 * bench-narrowphase: what accuracy costs in time.
 *
 * For each scene and each accuracy level: nanoseconds per pair test
 * (median over repeats) on a sample of near-contact pairs, and how often
 * the level's answer differs from the exact level's on that sample (false
 * collisions, missed collisions). Scenes: unit boxes; convex ellipsoids
 * (about 100 triangles); non-convex "bumpy spheres" of 100, 960 and 10 000
 * triangles. Prints a table and writes bench-narrowphase.csv.
 *
 * Usage: bench-narrowphase [--quick]
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <noctree/mesh.h>
#include <noctree/narrowphase.h>

#include "benchutil.h"

static uint64_t rng_state = 2026;

static double urand(void)
{
    return (double)(tool_rand(&rng_state) >> 11) * 0x1p-53;
}

static void die(const char *what, noctStatus st, const noctError *err)
{
    fprintf(stderr, "bench-narrowphase: %s: %s%s%s\n", what, noctStatusString(st),
            err ? ": " : "", err ? err->message : "");
    exit(EXIT_FAILURE);
}

/*
 * A UV sphere of n segments and m rings (2 n (m - 1) triangles), its radius
 * in direction (theta, phi) scaled by (sx, sy, sz) and multiplied by
 * 1 + bump * (smooth noise), so bump > 0 makes it non-convex.
 */
static noctMesh *uv_sphere(int n, int m, const double scale[3], double bump)
{
    size_t nv = 2 + (size_t)n * (size_t)(m - 1), nt = 2 * (size_t)n * (size_t)(m - 1);
    double *v = malloc(3 * nv * sizeof *v);
    uint32_t *sizes = malloc(nt * sizeof *sizes), *idx = malloc(3 * nt * sizeof *idx);
    if (v == NULL || sizes == NULL || idx == NULL)
        die("sphere", NOCT_ERR_NOMEM, NULL);
    const double pi = 3.14159265358979323846;
    double ph = urand() * 6, pk = urand() * 6;
    size_t k = 0;
    for (int r = 0; r <= m; ++r) {
        double theta = pi * r / m;
        for (int s = 0; s < (r == 0 || r == m ? 1 : n); ++s) {
            double phi = 2 * pi * s / n;
            double radius = 1 + bump * (0.5 * sin(3 * theta + ph) * cos(4 * phi + pk) +
                                        0.5 * sin(5 * phi) * sin(2 * theta));
            v[3 * k] = scale[0] * radius * sin(theta) * cos(phi);
            v[3 * k + 1] = scale[1] * radius * sin(theta) * sin(phi);
            v[3 * k + 2] = scale[2] * radius * cos(theta);
            ++k;
        }
    }
    /* vertex 0 the top pole, ring r (1 .. m-1) at 1 + (r-1) n, last the bottom */
    size_t t = 0;
#define RING(r, s) ((uint32_t)(1 + (size_t)((r) - 1) * (size_t)n + (size_t)(((s) + n) % n)))
    for (int s = 0; s < n; ++s) {
        uint32_t tri[3] = {0, RING(1, s), RING(1, s + 1)};
        memcpy(&idx[3 * t++], tri, sizeof tri);
    }
    for (int r = 1; r < m - 1; ++r)
        for (int s = 0; s < n; ++s) {
            uint32_t a = RING(r, s), b = RING(r, s + 1), c = RING(r + 1, s),
                     d = RING(r + 1, s + 1);
            uint32_t t1[3] = {a, c, d}, t2[3] = {a, d, b};
            memcpy(&idx[3 * t++], t1, sizeof t1);
            memcpy(&idx[3 * t++], t2, sizeof t2);
        }
    uint32_t bottom = (uint32_t)(nv - 1);
    for (int s = 0; s < n; ++s) {
        uint32_t tri[3] = {bottom, RING(m - 1, s + 1), RING(m - 1, s)};
        memcpy(&idx[3 * t++], tri, sizeof tri);
    }
#undef RING
    for (size_t i = 0; i < nt; ++i)
        sizes[i] = 3;
    noctMesh *mesh;
    noctError err;
    noctStatus st = noctMeshCreate(v, nv, sizes, nt, idx, &mesh, &err);
    if (st != NOCT_OK)
        die("sphere mesh", st, &err);
    free(v);
    free(sizes);
    free(idx);
    return mesh;
}

typedef struct scene {
    const char *name;
    noctMesh *a, *b;
    double reach;   /* sum of the two meshes' bounding radii */
} scene;

static double bound_radius(const noctMesh *m)
{
    double lo[3], hi[3], r = 0;
    noctMeshBounds(m, lo, hi);
    for (int k = 0; k < 3; ++k)
        r += fmax(fabs(lo[k]), fabs(hi[k])) * fmax(fabs(lo[k]), fabs(hi[k]));
    return sqrt(r);
}

int main(int argc, char **argv)
{
    bool quick = argc > 1 && strcmp(argv[1], "--quick") == 0;
    if (argc > 1 && !quick) {
        fputs("usage: bench-narrowphase [--quick]\n", stderr);
        return 2;
    }
    noctMesh *box;
    noctError err;
    noctStatus st = noctMeshCreateBox(0.5, 0.5, 0.5, &box, &err);
    if (st != NOCT_OK)
        die("box", st, &err);
    const double ell1[3] = {1, 0.6, 0.4}, ell2[3] = {0.5, 1, 0.7}, one[3] = {1, 1, 1};
    scene scenes[] = {
        {"box-box", box, box, 0},
        {"convex-100", uv_sphere(10, 6, ell1, 0), uv_sphere(10, 6, ell2, 0), 0},
        {"bumpy-100", uv_sphere(10, 6, one, 0.3), uv_sphere(10, 6, one, 0.3), 0},
        {"bumpy-960", uv_sphere(32, 16, one, 0.3), uv_sphere(32, 16, one, 0.3), 0},
        {"bumpy-10000", uv_sphere(100, 51, one, 0.3), uv_sphere(100, 51, one, 0.3), 0},
    };
    const size_t nscenes = sizeof scenes / sizeof *scenes;
    const int repeats = quick ? 1 : 5;
    FILE *csv = tool_open_csv("bench-narrowphase.csv", "scene,triangles,level,ns_per_pair,"
                              "false_collisions,missed_collisions,pairs,gmp_fallbacks");
    if (csv == NULL)
        return EXIT_FAILURE;
    printf("narrowphase: the cost of accuracy on near-contact pairs (median of %d)\n",
           repeats);
    printf("%-12s %6s %-7s %12s %9s %9s %7s %9s\n", "scene", "tris", "level",
           "ns/pair", "false+", "missed", "pairs", "gmp");
    for (size_t s = 0; s < nscenes; ++s) {
        scene *sc = &scenes[s];
        size_t tris = noctMeshTriangleCount(sc->a);
        size_t npairs = quick ? 200 : tris > 5000 ? 2000 : 20000;
        double ra = bound_radius(sc->a), rb = bound_radius(sc->b);
        /* Near contact: B's centre at a random direction and a distance
         * that puts the two bounding spheres from 40 % to 105 % of just
         * touching, so every outcome occurs. */
        double (*tb)[3] = malloc(npairs * sizeof *tb);
        bool *exact = malloc(npairs * sizeof *exact);
        if (tb == NULL || exact == NULL)
            die("sample", NOCT_ERR_NOMEM, NULL);
        for (size_t i = 0; i < npairs; ++i) {
            double z = 2 * urand() - 1, phi = 2 * 3.14159265358979 * urand();
            double d = (ra + rb) * (0.4 + 0.65 * urand());
            tb[i][0] = d * sqrt(1 - z * z) * cos(phi);
            tb[i][1] = d * sqrt(1 - z * z) * sin(phi);
            tb[i][2] = d * z;
        }
        const double ta[3] = {0, 0, 0};
        for (int level = NOCT_ACCURACY_EXACT; level >= NOCT_ACCURACY_BOX; --level) {
            double times[5];
            size_t fp = 0, fn = 0;
            noctNarrowStats stats = {0};
            for (int r = 0; r < repeats; ++r) {
                double t0 = tool_now();
                for (size_t i = 0; i < npairs; ++i) {
                    bool hit;
                    st = noctCollide(sc->a, ta, sc->b, tb[i], (noctAccuracy)level, &hit,
                                     r == 0 ? &stats : NULL);
                    if (st != NOCT_OK)
                        die("noctCollide", st, NULL);
                    if (r == 0) {
                        if (level == NOCT_ACCURACY_EXACT)
                            exact[i] = hit;
                        fp += hit && !exact[i];
                        fn += !hit && exact[i];
                    }
                }
                times[r] = 1e9 * (tool_now() - t0) / (double)npairs;
            }
            tool_sort(times, (size_t)repeats);
            double ns = tool_rank(times, (size_t)repeats, 1, 2);
            const char *name = noctAccuracyName((noctAccuracy)level);
            printf("%-12s %6zu %-7s %12.0f %9zu %9zu %7zu %9llu\n", sc->name, tris, name,
                   ns, fp, fn, npairs, (unsigned long long)stats.exact_fallbacks);
            fprintf(csv, "%s,%zu,%s,%.1f,%zu,%zu,%zu,%llu\n", sc->name, tris, name, ns, fp,
                    fn, npairs, (unsigned long long)stats.exact_fallbacks);
            fflush(stdout);
        }
        free(tb);
        free(exact);
    }
    fclose(csv);
    puts("(false+ and missed are counted against the exact level; raw figures in "
         "bench-narrowphase.csv)");
    for (size_t s = 0; s < nscenes; ++s) {
        if (scenes[s].a != box)
            noctMeshDestroy(scenes[s].a);
        if (scenes[s].b != box)
            noctMeshDestroy(scenes[s].b);
    }
    noctMeshDestroy(box);
    return EXIT_SUCCESS;
}
