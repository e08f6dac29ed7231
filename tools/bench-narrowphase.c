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
 * --surfaces: the same closed meshes as solids and as surfaces, at the
 * exact level on the same poses (what a surface costs).
 * --weld N: the tolerance weld (noctMeshDataWeld) on about N points of
 * five kinds, three of which took the quadratic weld n^2 / 2 pair tests.
 *
 * Usage: bench-narrowphase [--quick] [--surfaces | --weld N]
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp() */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <noctree/mesh.h>
#include <noctree/narrowphase.h>
#include <noctree/scene.h>
#include <noctree/world.h>

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
 * 1 + bump * (smooth noise), so bump > 0 makes it non-convex; a solid or
 * a surface; written as OFF to `off` too unless it is NULL.
 */
static noctMesh *uv_sphere(int n, int m, const double scale[3], double bump, bool surface,
                           FILE *off)
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
    if (off != NULL) {
        fprintf(off, "OFF\n%zu %zu 0\n", nv, nt);
        for (size_t i = 0; i < nv; ++i)
            fprintf(off, "%.17g %.17g %.17g\n", v[3 * i], v[3 * i + 1], v[3 * i + 2]);
        for (size_t i = 0; i < nt; ++i)
            fprintf(off, "3 %u %u %u\n", idx[3 * i], idx[3 * i + 1], idx[3 * i + 2]);
    }
    noctMesh *mesh;
    noctError err;
    noctStatus st = (surface ? noctMeshCreateSurface : noctMeshCreate)(v, nv, sizes, nt, idx,
                                                                       &mesh, &err);
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

/* ---- --weld N: the tolerance weld's time ------------------------------------------ */

/* Input `kind` of the weld benchmark, about n points, into v (3 n doubles;
 * returns the count) and its tolerance into *eps:
 * 0 "soup": a UV sphere's triangles each with its own three corners, every
 *   corner moved by up to 10^-9 (a CAD export's rounding), eps 10^-7;
 * 1 "cloud": uniform in the unit cube, eps half the mean spacing;
 * 2 "cluster": all within eps of each other;
 * 3 "chain": each 3/4 eps from the next along x;
 * 4 "anti-diagonal": two clusters in diagonally adjacent cells whose every
 *   pair is within eps on two axes and apart on the third (check-meshio's
 *   anti_diagonal()). The three last took the quadratic weld n^2 / 2 pair
 *   tests. */
static size_t weld_input(int kind, size_t n, double *v, double *eps)
{
    if (kind == 0) {
        int segs = (int)sqrt((double)n / 3); /* segs x segs/2 quads, 6 corners each */
        int rings = segs / 2;
        const double pi = 3.14159265358979323846;
        size_t c = 0;
        for (int r = 0; r < rings; ++r)
            for (int s = 0; s < segs; ++s) {
                double q[4][3];
                for (int k = 0; k < 4; ++k) {
                    double th = pi * (r + (k >> 1)) / rings, ph = 2 * pi * (s + (k & 1)) / segs;
                    q[k][0] = sin(th) * cos(ph);
                    q[k][1] = sin(th) * sin(ph);
                    q[k][2] = cos(th);
                }
                static const int tri[6] = {0, 1, 3, 0, 3, 2};
                for (int t = 0; t < 6; ++t, ++c)
                    for (int k = 0; k < 3; ++k)
                        v[3 * c + (size_t)k] = q[tri[t]][k] + (urand() - 0.5) * 2e-9;
            }
        *eps = 1e-7;
        return c;
    }
    for (size_t i = 0; i < n; ++i) {
        double *p = &v[3 * i];
        if (kind == 1) {
            for (int k = 0; k < 3; ++k)
                p[k] = urand();
            *eps = 0.5 / cbrt((double)n);
        } else if (kind == 2) {
            for (int k = 0; k < 3; ++k)
                p[k] = 5 + urand() * 0.5;
            *eps = 1;
        } else if (kind == 3) {
            p[0] = (double)i * 0.75;
            p[1] = urand() * 0.1;
            p[2] = urand() * 0.1;
            *eps = 1;
        } else {
            double s = (double)(i / 2) * 0x1p-19;
            if (i % 2 == 0) {
                p[0] = 0.5 + s;
                p[1] = 0.5 - s;
                p[2] = 0.5 + s;
            } else {
                p[0] = 1.5 + s + 0x1p-20;
                p[1] = 1.5 - s - 0x1p-20;
                p[2] = 1.25;
            }
            *eps = 1;
        }
    }
    return n;
}

static int bench_weld(size_t n, int repeats)
{
    static const char *const names[] = {"soup", "cloud", "cluster", "chain", "anti-diagonal"};
    double *v = malloc(3 * n * sizeof *v);
    if (v == NULL)
        die("weld", NOCT_ERR_NOMEM, NULL);
    printf("the tolerance weld (noctMeshDataWeld), about %zu points (median of %d)\n", n,
           repeats);
    printf("%-14s %8s %10s %9s %10s\n", "input", "points", "eps", "kept", "ms");
    for (int kind = 0; kind < 5; ++kind) {
        double eps = 1;
        size_t np = weld_input(kind, n, v, &eps);
        double times[9];
        size_t kept = 0;
        for (int r = 0; r < repeats; ++r) {
            noctMeshData *d;
            noctError err;
            noctStatus st = noctMeshDataCreate(v, np, NULL, 0, NULL, &d, &err);
            if (st != NOCT_OK)
                die("noctMeshDataCreate", st, &err);
            double t0 = tool_now();
            st = noctMeshDataWeld(d, eps, NULL, &err);
            times[r] = 1e3 * (tool_now() - t0);
            if (st != NOCT_OK)
                die("noctMeshDataWeld", st, &err);
            kept = noctMeshDataVertexCount(d);
            noctMeshDataDestroy(d);
        }
        tool_sort(times, (size_t)repeats);
        printf("%-14s %8zu %10.3g %9zu %10.1f\n", names[kind], np, eps, kept,
               tool_rank(times, (size_t)repeats, 1, 2));
        fflush(stdout);
    }
    free(v);
    return EXIT_SUCCESS;
}

/* ---- --surfaces: what a surface costs ---------------------------------------------- */

/* The pair tests of each kind of pair, as functions of their own so that
 * callgrind counts each kind's instructions apart (inclusive cost of
 * collide_solids, collide_surfaces, collide_mixed). */
static noctStatus collide_solids(const noctMesh *a, const double ta[3], const noctMesh *b,
                                 const double tb[3], bool *hit)
{
    return noctCollide(a, ta, b, tb, NOCT_ACCURACY_EXACT, hit, NULL);
}

static noctStatus collide_surfaces(const noctMesh *a, const double ta[3], const noctMesh *b,
                                   const double tb[3], bool *hit)
{
    return noctCollide(a, ta, b, tb, NOCT_ACCURACY_EXACT, hit, NULL);
}

static noctStatus collide_mixed(const noctMesh *a, const double ta[3], const noctMesh *b,
                                const double tb[3], bool *hit)
{
    return noctCollide(a, ta, b, tb, NOCT_ACCURACY_EXACT, hit, NULL);
}

typedef noctStatus (*collide_fn)(const noctMesh *, const double *, const noctMesh *,
                                 const double *, bool *);

/* The world step of a scene file of k objects of one bumpy sphere's mesh
 * (`mesh ball file ball.off`, as a solid or with `surface`), turned and
 * moving in a container with walls (effects motion, events and walls: no
 * response, so both runs move alike), exact level: milliseconds per step
 * (median of the steps), colliding pairs summed over the steps and the
 * contact-begin events. */
static void world_run(const char *dir, bool surface, int k, int steps, double *ms,
                      size_t *colliding, size_t *begins)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s.scene", dir, surface ? "surfaces" : "solids");
    FILE *f = fopen(path, "w");
    if (f == NULL)
        die(path, NOCT_ERR_IO, NULL);
    double side = 2.6 * cbrt((double)k); /* about 1/4 of the box filled */
    fprintf(f, "N auto\naccuracy exact\nsteps %d\neffects motion events walls\n"
            "walls 0 0 0 %.17g %.17g %.17g\nmesh ball file ball.off%s\n", steps, side,
            side, side, surface ? " surface" : "");
    uint64_t rng = 29;
    for (int i = 0; i < k; ++i) {
        double u[8];
        for (int j = 0; j < 8; ++j)
            u[j] = (double)(tool_rand(&rng) >> 11) * 0x1p-53;
        fprintf(f, "object ball %.17g %.17g %.17g  %.17g %.17g %.17g 0.05 "
                "rotate %.17g %.17g 1 %.17g\n", 1.3 + u[0] * (side - 2.6),
                1.3 + u[1] * (side - 2.6), 1.3 + u[2] * (side - 2.6), u[3] - 0.5, u[4] - 0.5,
                u[5] - 0.5, u[6], u[7], 360 * u[6]);
    }
    fclose(f);
    noctScene *sn;
    noctWorld *world;
    noctError err;
    noctStatus st = noctSceneRead(path, &sn, &err);
    if (st != NOCT_OK)
        die("noctSceneRead", st, &err);
    st = noctSceneBuild(sn, &world, &err);
    if (st != NOCT_OK)
        die("noctSceneBuild", st, &err);
    double *t = malloc((size_t)steps * sizeof *t);
    if (t == NULL)
        die("world", NOCT_ERR_NOMEM, NULL);
    *colliding = *begins = 0;
    for (int i = 0; i < steps; ++i) {
        double t0 = tool_now();
        st = noctWorldStep(world, &err);
        t[i] = 1e3 * (tool_now() - t0);
        if (st != NOCT_OK)
            die("noctWorldStep", st, &err);
        const noctPair *pairs;
        *colliding += noctWorldColliding(world, &pairs);
        *begins += noctWorldBegan(world, &pairs);
    }
    tool_sort(t, (size_t)steps);
    *ms = tool_rank(t, (size_t)steps, 1, 2);
    free(t);
    noctWorldDestroy(world);
    noctSceneDestroy(sn);
}

/* The same closed bumpy spheres as solids and as surfaces (noctMeshCreate
 * and noctMeshCreateSurface of the same triangles), at the exact level on
 * the same near-contact poses: nanoseconds per pair test and the hits.
 * The verdicts differ only where one lies wholly inside the other: a
 * solid contains it, a surface encloses nothing. Then the world step of a
 * scene of such spheres, solids against surfaces (world_run()). */
static int bench_surfaces(bool quick)
{
    static const struct {
        const char *name;
        int n, m;
    } shapes[] = {{"bumpy-100", 10, 6}, {"bumpy-960", 32, 16}, {"bumpy-10000", 100, 51}};
    const double one[3] = {1, 1, 1};
    const int repeats = quick ? 1 : 5;
    printf("solids against surfaces: the same closed meshes, exact level, the same "
           "near-contact poses (median of %d)\n", repeats);
    printf("%-12s %6s %-17s %10s %7s %7s %6s\n", "scene", "tris", "kinds", "ns/pair", "hits",
           "pairs", "ratio");
    for (size_t s = 0; s < sizeof shapes / sizeof *shapes; ++s) {
        /* the same random spheres: the generator restarted per shape */
        rng_state = 2026 + s;
        noctMesh *sa = uv_sphere(shapes[s].n, shapes[s].m, one, 0.3, false, NULL);
        noctMesh *sb = uv_sphere(shapes[s].n, shapes[s].m, one, 0.3, false, NULL);
        rng_state = 2026 + s;
        noctMesh *fa = uv_sphere(shapes[s].n, shapes[s].m, one, 0.3, true, NULL);
        noctMesh *fb = uv_sphere(shapes[s].n, shapes[s].m, one, 0.3, true, NULL);
        size_t tris = noctMeshTriangleCount(sa);
        size_t npairs = quick ? 200 : tris > 5000 ? 2000 : 20000;
        double reach = bound_radius(sa) + bound_radius(sb);
        double (*tb)[3] = malloc(npairs * sizeof *tb);
        if (tb == NULL)
            die("sample", NOCT_ERR_NOMEM, NULL);
        for (size_t i = 0; i < npairs; ++i) {
            /* from 0 (concentric: one inside the other for solids) to just
             * beyond touching */
            double z = 2 * urand() - 1, phi = 2 * 3.14159265358979 * urand();
            double d = reach * 1.05 * urand();
            tb[i][0] = d * sqrt(1 - z * z) * cos(phi);
            tb[i][1] = d * sqrt(1 - z * z) * sin(phi);
            tb[i][2] = d * z;
        }
        const double ta[3] = {0, 0, 0};
        const struct {
            const char *kinds;
            noctMesh *a, *b;
            collide_fn fn;
        } combos[] = {{"solid-solid", sa, sb, collide_solids},
                      {"surface-surface", fa, fb, collide_surfaces},
                      {"solid-surface", sa, fb, collide_mixed}};
        double base = 0;
        for (size_t c = 0; c < 3; ++c) {
            double times[5];
            size_t hits = 0;
            collide_fn volatile fn = combos[c].fn; /* called, not inlined */
            for (int r = 0; r < repeats; ++r) {
                double t0 = tool_now();
                for (size_t i = 0; i < npairs; ++i) {
                    bool hit;
                    noctStatus st = fn(combos[c].a, ta, combos[c].b, tb[i], &hit);
                    if (st != NOCT_OK)
                        die("noctCollide", st, NULL);
                    hits += r == 0 && hit;
                }
                times[r] = 1e9 * (tool_now() - t0) / (double)npairs;
            }
            tool_sort(times, (size_t)repeats);
            double ns = tool_rank(times, (size_t)repeats, 1, 2);
            if (c == 0)
                base = ns;
            printf("%-12s %6zu %-17s %10.0f %7zu %7zu %6.2f\n", shapes[s].name, tris,
                   combos[c].kinds, ns, hits, npairs, ns / base);
            fflush(stdout);
        }
        free(tb);
        noctMeshDestroy(sa);
        noctMeshDestroy(sb);
        noctMeshDestroy(fa);
        noctMeshDestroy(fb);
    }
    char dir[] = "/tmp/bench-narrowphase-XXXXXX";
    if (mkdtemp(dir) == NULL)
        die("mkdtemp", NOCT_ERR_IO, NULL);
    const int k = quick ? 20 : 200, steps = quick ? 10 : 200;
    printf("\nthe world step: %d objects of one mesh, exact level, motion, events and walls, "
           "%d steps (median)\n", k, steps);
    printf("%-12s %6s %-9s %10s %10s %7s %6s\n", "mesh", "tris", "kind", "ms/step",
           "colliding", "begins", "ratio");
    for (size_t s = 0; s < 2; ++s) {
        char off[600];
        snprintf(off, sizeof off, "%s/ball.off", dir);
        FILE *f = fopen(off, "w");
        if (f == NULL)
            die(off, NOCT_ERR_IO, NULL);
        rng_state = 2026 + s;
        noctMesh *ball = uv_sphere(shapes[s + 1].n, shapes[s + 1].m, one, 0.3, false, f);
        fclose(f);
        size_t tris = noctMeshTriangleCount(ball);
        noctMeshDestroy(ball);
        double base = 0;
        for (int surface = 0; surface < 2; ++surface) {
            double ms;
            size_t colliding, begins;
            world_run(dir, surface, k, steps, &ms, &colliding, &begins);
            if (!surface)
                base = ms;
            printf("%-12s %6zu %-9s %10.3f %10zu %7zu %6.2f\n", shapes[s + 1].name, tris,
                   surface ? "surfaces" : "solids", ms, colliding, begins, ms / base);
            fflush(stdout);
            char path[600];
            snprintf(path, sizeof path, "%s/%s.scene", dir, surface ? "surfaces" : "solids");
            remove(path);
        }
        remove(off);
    }
    rmdir(dir);
    return EXIT_SUCCESS;
}

int main(int argc, char **argv)
{
    bool quick = false, weld = false, surfaces = false;
    size_t weld_n = 200000;
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--quick") == 0) {
            quick = true;
        } else if (strcmp(argv[i], "--surfaces") == 0) {
            surfaces = true;
        } else if (strcmp(argv[i], "--weld") == 0 && i + 1 < argc &&
                   strtoul(argv[i + 1], NULL, 10) >= 100) {
            weld = true;
            weld_n = strtoul(argv[++i], NULL, 10);
        } else {
            fputs("usage: bench-narrowphase [--quick] [--surfaces | --weld N]\n", stderr);
            return 2;
        }
    }
    if (weld)
        return bench_weld(weld_n, quick ? 1 : 3);
    if (surfaces)
        return bench_surfaces(quick);
    noctMesh *box;
    noctError err;
    noctStatus st = noctMeshCreateBox(0.5, 0.5, 0.5, &box, &err);
    if (st != NOCT_OK)
        die("box", st, &err);
    const double ell1[3] = {1, 0.6, 0.4}, ell2[3] = {0.5, 1, 0.7}, one[3] = {1, 1, 1};
    scene scenes[] = {
        {"box-box", box, box, 0},
        {"convex-100", uv_sphere(10, 6, ell1, 0, false, NULL),
         uv_sphere(10, 6, ell2, 0, false, NULL), 0},
        {"bumpy-100", uv_sphere(10, 6, one, 0.3, false, NULL),
         uv_sphere(10, 6, one, 0.3, false, NULL), 0},
        {"bumpy-960", uv_sphere(32, 16, one, 0.3, false, NULL),
         uv_sphere(32, 16, one, 0.3, false, NULL), 0},
        {"bumpy-10000", uv_sphere(100, 51, one, 0.3, false, NULL),
         uv_sphere(100, 51, one, 0.3, false, NULL), 0},
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
