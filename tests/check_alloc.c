/* SPDX-License-Identifier: MIT */
/*
 * "No abort, ever": every allocation of a scripted workload fails in turn.
 *
 * The tests' allocator (testalloc.h) replaces malloc and its family for
 * the whole process: the test's, libnoctree's, GMP's, qhull's, libccd's
 * and glibc's own allocations (fopen, getline, strdup). While a workload
 * runs, each allocation is an allocation point, numbered from 1, and a
 * live block is remembered with its caller until it is freed.
 *
 * Each part of the workload (the octree ADT with neighbor finding, meshes
 * by every constructor, the OFF/OBJ readers, surfaces (made, read and from
 * data, collided and their distances), scene files and families, a
 * world stepped, changed and emptied at every accuracy and in every
 * maintenance mode, the object model (definitions, the setters that
 * allocate, tracks, spinners, the margin, queries, the scene writer),
 * noctCollide on pairs in contact) is
 * first run twice without failures: a warm-up that takes glibc's one-time
 * allocations out of the count, then the baseline, which gives the number
 * of points n and the result (a hash of everything the part observed).
 * Then, in a child process per run, pass 1 fails only the k-th point and
 * pass 2 every point from the k-th on, and the run must end
 *   - with the baseline's result, or with NOCT_ERR_NOMEM from a function
 *     whose documentation lists it (its noctError saying so too, and its
 *     output pointer NULL);
 *   - with nothing left allocated once everything is destroyed;
 *   - with a valid world (noctWorldValidate) after a failed noctWorldAdd
 *     or noctWorldRemove, which do not say the world is lost; after a
 *     failed noctWorldStep, which says the world should be destroyed, it
 *     only has to be destroyed cleanly;
 *   - without a crash, an exit or a hang.
 * Each failing run prints its part, pass, k, the phase of the workload
 * and the call stack of the failed allocation; each part then prints its
 * distinct failures (by kind and call site in the library).
 *
 * Points whose caller is libgmp are not failed (GMP's default allocator
 * aborts the process), except in the "collide" part, which exists to fail
 * them. Small parts test every point. The large ones (the worlds, a few
 * thousand points, and GMP's tens of thousands in "collide") test every
 * point among the first SAMPLE_HEAD and then one point, at a seeded
 * offset, in each of equal stretches of the rest, and the last point: a
 * deterministic sample that keeps the whole program within seconds.
 *
 * Environment, for debugging:
 *   CK_RUN_CASE=world       one part (Check's own variable)
 *   NOCT_ALLOC_K=k          only the k-th point (both passes unless:)
 *   NOCT_ALLOC_PASS=1|2     only that pass
 *   NOCT_ALLOC_NOFORK=1     run in this process (for gdb; a crash ends it)
 *   NOCT_ALLOC_ALL=1        every point of every part, no sampling
 *   NOCT_ALLOC_GMP=1        fail GMP's allocations in every part
 *   NOCT_ALLOC_VERBOSE=1    print each run's outcome and failure stacks
 *   NOCT_ALLOC_PROFILE=1    print the baseline's points by phase and caller
 *
 * Skipped (exit status 77) under AddressSanitizer, which owns malloc, and
 * under valgrind, which replaces it behind our back; also if the probe
 * allocation does not reach the harness's malloc.
 */
#define _GNU_SOURCE /* dladdr, dl_iterate_phdr */
#include <check.h>
#include <dlfcn.h>
#include <errno.h>
#include <execinfo.h>
#include <inttypes.h>
#include <limits.h>
#include <link.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include <noctree/mesh.h>
#include <noctree/narrowphase.h>
#include <noctree/neighbor.h>
#include <noctree/octree.h>
#include <noctree/query.h>
#include <noctree/scene.h>
#include <noctree/world.h>

#include "testalloc.h"
#include "testutil.h"

/* ==== the harness's side of the allocator (testalloc.h) ==================== */

static volatile unsigned long g_gmp_seen; /* GMP allocations in this run */
static volatile bool g_fail_gmp;          /* GMP's allocations are points too */
static int g_report_fd = -1;  /* the child's pipe to the parent */
static char g_phase[64];      /* what the workload is doing */

/* Where libgmp's code lies, to tell its allocations apart. */
typedef struct code_range {
    uintptr_t lo, hi;
} code_range;
static code_range gmp_code[8];
static int gmp_ranges;

/* The record a run sends at its first injected failure, before anything
 * can crash: its point, the workload's phase and the allocation's stack. */
enum { REC_INJECT = 1, REC_DONE = 2 };
#define MAX_FRAMES 32
typedef struct inject_rec {
    int type;
    unsigned long k;
    char phase[64];
    int nframes;
    void *frames[MAX_FRAMES];
} inject_rec;
static inject_rec g_inject;

static bool in_gmp(const void *caller)
{
    uintptr_t a = (uintptr_t)caller;
    for (int i = 0; i < gmp_ranges; ++i)
        if (a >= gmp_code[i].lo && a < gmp_code[i].hi)
            return true;
    return false;
}

/* NOCT_ALLOC_PROFILE: the baseline's points by phase and caller. */
typedef struct profile_entry {
    char phase[64];
    void *caller;
    unsigned long count;
} profile_entry;
static profile_entry profile[512];
static size_t profile_n;
static bool g_profile;

/* The allocator's filter: GMP's allocations are points only when asked. */
static bool is_point(void *caller)
{
    if (in_gmp(caller)) {
        ++g_gmp_seen;
        if (!g_fail_gmp)
            return false;
    }
    return true;
}

/* At each point: the profile, when asked. */
static void on_point(void *caller)
{
    if (!g_profile)
        return;
    for (size_t i = 0; i < profile_n; ++i)
        if (profile[i].caller == caller && strcmp(profile[i].phase, g_phase) == 0) {
            ++profile[i].count;
            return;
        }
    if (profile_n < sizeof profile / sizeof *profile) {
        memcpy(profile[profile_n].phase, g_phase, sizeof g_phase);
        profile[profile_n].caller = caller;
        profile[profile_n++].count = 1;
    }
}

/* At the run's first injected failure: the record, sent at once. */
static void on_first_failure(unsigned long k)
{
    g_inject.type = REC_INJECT;
    g_inject.k = k;
    memcpy(g_inject.phase, g_phase, sizeof g_phase);
    g_inject.nframes = backtrace(g_inject.frames, MAX_FRAMES);
    if (g_report_fd >= 0) {
        ssize_t w = write(g_report_fd, &g_inject, sizeof g_inject);
        (void)w;
    }
}

static int find_gmp(struct dl_phdr_info *info, size_t size, void *data)
{
    (void)size;
    (void)data;
    if (info->dlpi_name == NULL || strstr(info->dlpi_name, "libgmp.so") == NULL)
        return 0;
    for (int i = 0; i < info->dlpi_phnum && gmp_ranges < 8; ++i) {
        const ElfW(Phdr) *ph = &info->dlpi_phdr[i];
        if (ph->p_type == PT_LOAD && (ph->p_flags & PF_X)) {
            gmp_code[gmp_ranges].lo = info->dlpi_addr + ph->p_vaddr;
            gmp_code[gmp_ranges].hi = info->dlpi_addr + ph->p_vaddr + ph->p_memsz;
            ++gmp_ranges;
        }
    }
    return 0;
}

static void allocator_init(void)
{
    dl_iterate_phdr(find_gmp, NULL);
    /* backtrace() loads libgcc's unwinder (allocating) on first use. */
    void *frames[4];
    (void)backtrace(frames, 4);
    alloc_set_hooks(is_point, on_point, on_first_failure);
}

/* Start a run: every point counted and its live blocks tracked; with
 * fail_at > 0, fail that point (and with rest every later one). */
static void run_begin(unsigned long fail_at, bool rest, bool fail_gmp)
{
    g_gmp_seen = 0;
    g_fail_gmp = fail_gmp;
    memset(&g_inject, 0, sizeof g_inject);
    g_phase[0] = '\0';
    alloc_begin(&(alloc_plan){.fail_at = fail_at, .fail_rest = rest, .track = true});
}

static void phase(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
static void phase(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(g_phase, sizeof g_phase, fmt, ap);
    va_end(ap);
}

/* ==== outcomes ============================================================= */

/* Kinds of failed checks, worst first. */
typedef enum fail_kind {
    K_NONE,
    K_CRASH,     /* killed by a signal (abort, segfault) */
    K_EXIT,      /* the process exited in the middle of the workload */
    K_HANG,      /* killed by the harness's alarm */
    K_STATUS,    /* a status the function does not document, or an
                    inconsistent noctError / output pointer */
    K_INVALID,   /* noctWorldValidate failed after a failed add or remove */
    K_DIFFERS,   /* NOCT_OK all along, but another result */
    K_LEAK,      /* blocks left after everything was destroyed */
    K_HARNESS    /* the run did not reach its point: a harness problem */
} fail_kind;

static const char *const kind_names[] = {
    "ok", "crash", "exit", "hang", "status", "invalid world", "wrong result", "leak",
    "harness"};

typedef struct outcome {
    int type;            /* REC_DONE */
    fail_kind kind;      /* the first failed check */
    uint64_t digest;     /* the part's observations */
    bool nomem;          /* a documented NOCT_ERR_NOMEM changed the run */
    char nomem_phase[64];
    char diverged[64];   /* the phase whose observation first differed */
    char msg[480];       /* what failed */
    unsigned long points;
    unsigned long injected;
    unsigned long gmp_seen;
    size_t leaks;
    void *leak_callers[3];
} outcome;

static void record(outcome *o, fail_kind kind, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
static void record(outcome *o, fail_kind kind, const char *fmt, ...)
{
    alloc_pause();
    size_t used = strlen(o->msg);
    if (o->kind == K_NONE)
        o->kind = kind;
    if (used + 3 < sizeof o->msg) {
        if (used > 0) {
            strcpy(o->msg + used, "; ");
            used += 2;
        }
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(o->msg + used, sizeof o->msg - used, fmt, ap);
        va_end(ap);
    }
    alloc_resume();
}

/* The baseline's digest after each observation, so that a run whose
 * result differs can say where it first went another way. */
#define TRACE_MAX 65536
static uint64_t trace[TRACE_MAX];
static size_t trace_n;
static enum { TRACE_OFF, TRACE_RECORD, TRACE_COMPARE } trace_mode;
static size_t trace_at;

static void mix(outcome *o, uint64_t x)
{
    o->digest = (o->digest ^ x) * 0x100000001b3u;
    o->digest ^= o->digest >> 29;
    if (trace_mode == TRACE_RECORD && trace_n < TRACE_MAX) {
        trace[trace_n++] = o->digest;
    } else if (trace_mode == TRACE_COMPARE && o->diverged[0] == '\0' && !o->nomem &&
               trace_at < trace_n && trace[trace_at] != o->digest) {
        memcpy(o->diverged, g_phase, sizeof g_phase);
    }
    ++trace_at;
}

static void mix_double(outcome *o, double d)
{
    uint64_t u;
    memcpy(&u, &d, sizeof u);
    mix(o, u);
}

/* A failure the called function documents (for the functions without a
 * status: octCreate's NULL, octSplit's and octPrint's false). */
static void documented(outcome *o)
{
    if (!o->nomem) {
        o->nomem = true;
        memcpy(o->nomem_phase, g_phase, sizeof g_phase);
    }
}

/*
 * Judge the status of a call whose documentation lists NOCT_ERR_NOMEM
 * (nomem_documented) and, on failure, the noctError it filled (err, or
 * NULL if none was passed). expect is the status of the unfailed run.
 * Returns true when the run goes on as in the baseline.
 */
static bool judge(outcome *o, const char *call, noctStatus st, noctStatus expect,
                  const noctError *err, bool nomem_documented)
{
    if (st == expect) {
        if (st != NOCT_OK && err != NULL && err->status != st)
            record(o, K_STATUS, "%s returned %s but its noctError says %s", call,
                 noctStatusString(st), noctStatusString(err->status));
        return true;
    }
    if (st == NOCT_ERR_NOMEM && alloc_failures() > 0) {
        if (!nomem_documented)
            record(o, K_STATUS, "%s returned NOCT_ERR_NOMEM, which its documentation "
                 "does not list", call);
        if (err != NULL && err->status != NOCT_ERR_NOMEM)
            record(o, K_STATUS, "%s returned NOCT_ERR_NOMEM but its noctError says %s (%s)",
                 call, noctStatusString(err->status), err->message);
        documented(o);
        return false;
    }
    record(o, alloc_failures() > 0 ? K_STATUS : K_HARNESS,
         "%s returned %s (%s), expected %s%s", call, noctStatusString(st),
         err != NULL && err->status == st ? err->message : "no message",
         noctStatusString(expect), alloc_failures() > 0 ? " or NOCT_ERR_NOMEM" : "");
    return false;
}

/* A fresh noctError whose status no call sets by accident. */
static noctError fresh_err(void)
{
    noctError e;
    memset(&e, 0, sizeof e);
    e.status = NOCT_STATUS_COUNT;
    return e;
}

/* ==== the workload's data ================================================== */

/* A prism over a 12-pointed star: 50 vertices and 72 convex polygons
 * (24 rectangles, 48 triangles), not convex, and over the 32 vertices
 * from which mesh.c runs qhull for its hull. */
#define STAR_RIM 24
#define STAR_NV (2 * STAR_RIM + 2)
#define STAR_NP (3 * STAR_RIM)
typedef struct star_mesh {
    double v[3 * STAR_NV];
    uint32_t sizes[STAR_NP];
    uint32_t idx[4 * STAR_RIM + 6 * STAR_RIM];
    size_t nidx;
} star_mesh;

static void star_make(star_mesh *s, double scale)
{
    for (int i = 0; i < STAR_RIM; ++i) {
        double a = 6.283185307179586 * i / STAR_RIM;
        double r = (i % 2 == 0 ? 1.0 : 0.5) * scale;
        double x = r * cos(a), y = r * sin(a);
        double *b = &s->v[3 * i], *t = &s->v[3 * (STAR_RIM + i)];
        b[0] = t[0] = x;
        b[1] = t[1] = y;
        b[2] = -0.5 * scale;
        t[2] = 0.5 * scale;
    }
    double *cb = &s->v[3 * 2 * STAR_RIM], *ct = cb + 3;
    cb[0] = cb[1] = ct[0] = ct[1] = 0;
    cb[2] = -0.5 * scale;
    ct[2] = 0.5 * scale;
    size_t p = 0, n = 0;
    for (uint32_t i = 0; i < STAR_RIM; ++i) {
        uint32_t j = (i + 1) % STAR_RIM;
        s->sizes[p++] = 4; /* side: b_i b_j t_j t_i, outward */
        s->idx[n++] = i;
        s->idx[n++] = j;
        s->idx[n++] = STAR_RIM + j;
        s->idx[n++] = STAR_RIM + i;
        s->sizes[p++] = 3; /* top: ct t_i t_j */
        s->idx[n++] = 2 * STAR_RIM + 1;
        s->idx[n++] = STAR_RIM + i;
        s->idx[n++] = STAR_RIM + j;
        s->sizes[p++] = 3; /* bottom: cb b_j b_i */
        s->idx[n++] = 2 * STAR_RIM;
        s->idx[n++] = j;
        s->idx[n++] = i;
    }
    s->nidx = n;
}

static noctStatus star_create(double scale, noctMesh **m, noctError *err)
{
    star_mesh s;
    star_make(&s, scale);
    return noctMeshCreate(s.v, STAR_NV, s.sizes, STAR_NP, s.idx, m, err);
}

/* The files the readers and the scene read, in a temporary folder. */
static char tmpdir[256];
static char path_star_off[300], path_star_obj[300], path_box_off[300], path_bad_off[300];
static char path_scene[300], path_bad_scene[300];

static void write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    if (f == NULL || fputs(text, f) == EOF || fclose(f) != 0) {
        perror(path);
        exit(EXIT_FAILURE);
    }
}

static void write_files(void)
{
    const char *base = getenv("TMPDIR");
    snprintf(tmpdir, sizeof tmpdir, "%s/check-alloc-XXXXXX", base && *base ? base : "/tmp");
    if (mkdtemp(tmpdir) == NULL) {
        perror("mkdtemp");
        exit(EXIT_FAILURE);
    }
    snprintf(path_star_off, sizeof path_star_off, "%s/star.off", tmpdir);
    snprintf(path_star_obj, sizeof path_star_obj, "%s/star.obj", tmpdir);
    snprintf(path_box_off, sizeof path_box_off, "%s/box.off", tmpdir);
    snprintf(path_bad_off, sizeof path_bad_off, "%s/bad.off", tmpdir);
    snprintf(path_scene, sizeof path_scene, "%s/world.scene", tmpdir);
    snprintf(path_bad_scene, sizeof path_bad_scene, "%s/bad.scene", tmpdir);

    star_mesh s;
    star_make(&s, 1.0);
    static char text[32768];
    size_t n = 0;
#define PUT(...) (n += (size_t)snprintf(text + n, sizeof text - n, __VA_ARGS__))
    /* OFF: a comment, colours after some polygons' indices. */
    PUT("OFF\n# a 12-pointed star prism\n%d %d 0\n", STAR_NV, STAR_NP);
    for (int i = 0; i < STAR_NV; ++i)
        PUT("%.17g %.17g %.17g\n", s.v[3 * i], s.v[3 * i + 1], s.v[3 * i + 2]);
    for (size_t p = 0, b = 0; p < STAR_NP; b += s.sizes[p], ++p) {
        PUT("%u", (unsigned)s.sizes[p]);
        for (uint32_t c = 0; c < s.sizes[p]; ++c)
            PUT(" %u", (unsigned)s.idx[b + c]);
        PUT(p % 5 == 0 ? " 255 128 0\n" : "\n");
    }
    write_file(path_star_off, text);
    /* OBJ: the same mesh with every corner form and relative indices. */
    n = 0;
    PUT("# the star prism again\no star\n");
    for (int i = 0; i < STAR_NV; ++i)
        PUT("v %.17g %.17g %.17g\n", s.v[3 * i], s.v[3 * i + 1], s.v[3 * i + 2]);
    PUT("vt 0 0\nvn 0 0 1\ns off\n");
    for (size_t p = 0, b = 0; p < STAR_NP; b += s.sizes[p], ++p) {
        PUT("f");
        for (uint32_t c = 0; c < s.sizes[p]; ++c) {
            unsigned v = s.idx[b + c] + 1;
            switch ((p + c) % 4) {
            case 0: PUT(" %u", v); break;
            case 1: PUT(" %u/1", v); break;
            case 2: PUT(" %u/1/1", v); break;
            default: PUT(" %d//1", (int)v - STAR_NV - 1); break; /* relative */
            }
        }
        PUT("\n");
    }
    write_file(path_star_obj, text);
    write_file(path_box_off,
               "OFF\n8 6 12\n# a 2 x 1 x 1 box\n"
               "-1 -0.5 -0.5\n1 -0.5 -0.5\n1 0.5 -0.5\n-1 0.5 -0.5\n"
               "-1 -0.5 0.5\n1 -0.5 0.5\n1 0.5 0.5\n-1 0.5 0.5\n"
               "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4 0 0 255\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n");
    write_file(path_bad_off,
               "OFF\n8 6 12\n"
               "-1 -0.5 -0.5\n1 -0.5 -0.5\n1 0.5 -0.5\n-1 0.5 -0.5\n"
               "-1 -0.5 0.5\n1 -0.5 0.5\n1 0.5 0.5\n-1 0.5 0.5\n"
               "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 x\n");
    /* The scene: both star files, the box file, a box, moving objects. */
    write_file(path_scene,
               "# check-alloc's scene: meshes from files, objects that collide\n"
               "N 2\nmax-depth 5\nsteps 12\naccuracy exact\n"
               "walls 0 0 0 9 9 9\n"
               "mesh cube box 0.5 0.5 0.5\n"
               "mesh star file star.off\n"
               "mesh star2 file star.obj\n"
               "mesh slab file box.off\n"
               "object cube 2 2 2   1 0 0 0.2\n"
               "object cube 5 2.2 2 -1 0 0 0.2\n"
               "object star 2 5 5   0 1 0 0.15\n"
               "object star2 2 7.5 5.2 0 -1 0 0.15\n"
               "object slab 6 6 6   0 0 1 0.1\n"
               "object slab 6 6.3 8 0 0 -1 0.1\n"
               "object star 4.5 4.5 2  1 1 0 0.1\n"
               "object cube 7 7 2   -1 -1 0 0.12\n"
               "object star2 1 1 8\n"
               "object cube 8 1 8   0 0.3 -1 0.2  # a comment\n");
    write_file(path_bad_scene,
               "N 2\nmesh star file star.off\nobject star 1 1 1\nobject star 3 3 3\n"
               "object nosuchmesh 0 0 0\n");
#undef PUT
}

static void remove_files(void)
{
    const char *paths[] = {path_star_off, path_star_obj, path_box_off, path_bad_off,
                           path_scene, path_bad_scene};
    for (size_t i = 0; i < sizeof paths / sizeof *paths; ++i)
        unlink(paths[i]);
    rmdir(tmpdir);
}

/* ==== the workload's parts ================================================= */

static void mix_mesh(outcome *o, const noctMesh *m)
{
    double lo[3], hi[3];
    noctMeshBounds(m, lo, hi);
    mix(o, noctMeshVertexCount(m));
    mix(o, noctMeshTriangleCount(m));
    mix(o, noctMeshIsConvex(m));
    for (int k = 0; k < 3; ++k) {
        mix_double(o, lo[k]);
        mix_double(o, hi[k]);
    }
}

/* noctCollide on every pair of the meshes at a few offsets, at every
 * accuracy, into the digest. */
static void collide_all(outcome *o, noctMesh *const *m, size_t n)
{
    static const double offsets[][3] = {
        {0, 0, 0}, {0, 0, 1}, {2, 0, 0}, {0.5, 0.25, 0.75}, {1.5, 1.5, 0}, {3, 3, 3},
        {1, 0, 0}};
    static const noctAccuracy levels[] = {NOCT_ACCURACY_BOX, NOCT_ACCURACY_CONVEX,
                                          NOCT_ACCURACY_EXACT};
    const double origin[3] = {0, 0, 0};
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i; j < n; ++j)
            for (size_t t = 0; t < sizeof offsets / sizeof *offsets; ++t)
                for (size_t l = 0; l < 3; ++l) {
                    phase("collide %zu %zu offset %zu %s", i, j, t,
                          noctAccuracyName(levels[l]));
                    bool hit = false;
                    noctStatus st = noctCollide(m[i], origin, m[j], offsets[t], levels[l],
                                                &hit, NULL);
                    if (!judge(o, "noctCollide", st, NOCT_OK, NULL, true))
                        return;
                    mix(o, hit);
                }
}

/* Meshes by every constructor (the star through qhull), then noctCollide
 * on them. */
static void part_meshes(outcome *o)
{
    noctMesh *m[4] = {NULL, NULL, NULL, NULL};
    noctError err = fresh_err();
    static const double half[3] = {0.4, 0.3, 0.6};
    const double c = cos(0.5), s = sin(0.5);
    const double rot[9] = {c, -s, 0, s, c, 0, 0, 0, 1};
    noctStatus st;

    phase("noctMeshCreate star");
    st = star_create(1.0, &m[0], &err);
    if (!judge(o, "noctMeshCreate", st, NOCT_OK, &err, true))
        goto out;
    phase("noctMeshCreateBox");
    err = fresh_err();
    st = noctMeshCreateBox(0.5, 0.25, 1.0, &m[1], &err);
    if (!judge(o, "noctMeshCreateBox", st, NOCT_OK, &err, true))
        goto out;
    phase("noctMeshCreateOrientedBox");
    err = fresh_err();
    st = noctMeshCreateOrientedBox(half, rot, &m[2], &err);
    if (!judge(o, "noctMeshCreateOrientedBox", st, NOCT_OK, &err, true))
        goto out;
    phase("noctMeshCreate star 0.75");
    err = fresh_err();
    st = star_create(0.75, &m[3], &err);
    if (!judge(o, "noctMeshCreate", st, NOCT_OK, &err, true))
        goto out;
    for (int i = 0; i < 4; ++i)
        mix_mesh(o, m[i]);
    collide_all(o, m, 4);
out:
    for (int i = 0; i < 4; ++i) {
        if (m[i] == NULL)
            continue;
        phase("noctMeshDestroy");
        noctMeshDestroy(m[i]);
    }
}

/* The OFF and OBJ readers, a file with a syntax error, and the star read
 * both ways collided with itself. */
static void part_readers(outcome *o)
{
    noctMesh *m[3] = {NULL, NULL, NULL};
    const char *paths[3] = {path_star_off, path_star_obj, path_box_off};
    for (int i = 0; i < 3; ++i) {
        phase("noctMeshRead %s", strrchr(paths[i], '/') + 1);
        noctError err = fresh_err();
        noctStatus st = noctMeshRead(paths[i], &m[i], &err);
        if (st != NOCT_OK && m[i] != NULL)
            record(o, K_STATUS, "noctMeshRead failed but left a mesh");
        if (!judge(o, "noctMeshRead", st, NOCT_OK, &err, true))
            goto out;
        mix_mesh(o, m[i]);
    }
    {
        phase("noctMeshRead bad.off");
        noctMesh *bad = NULL;
        noctError err = fresh_err();
        noctStatus st = noctMeshRead(path_bad_off, &bad, &err);
        if (bad != NULL) {
            record(o, K_STATUS, "noctMeshRead of a bad file gave a mesh");
            noctMeshDestroy(bad);
        }
        if (!judge(o, "noctMeshRead (bad.off)", st, NOCT_ERR_PARSE, &err, true))
            goto out;
        mix(o, (uint64_t)err.line);
    }
    collide_all(o, m, 3);
out:
    for (int i = 0; i < 3; ++i)
        noctMeshDestroy(m[i]);
}

/* Surfaces: the star made a surface from arrays, read from its file as a
 * surface, and from its data, collided with each other and with the
 * solid star at every level, and their distances. */
static void part_surfaces(outcome *o)
{
    noctMesh *m[4] = {NULL, NULL, NULL, NULL};
    noctMeshData *d = NULL;
    noctError err = fresh_err();
    noctStatus st;
    star_mesh sm;
    star_make(&sm, 1.0);
    phase("noctMeshCreateSurface star");
    st = noctMeshCreateSurface(sm.v, STAR_NV, sm.sizes, STAR_NP, sm.idx, &m[0], &err);
    if (!judge(o, "noctMeshCreateSurface", st, NOCT_OK, &err, true))
        goto out;
    phase("noctMeshReadSurface star.off");
    err = fresh_err();
    st = noctMeshReadSurface(path_star_off, &m[1], &err);
    if (st != NOCT_OK && m[1] != NULL)
        record(o, K_STATUS, "noctMeshReadSurface failed but left a mesh");
    if (!judge(o, "noctMeshReadSurface", st, NOCT_OK, &err, true))
        goto out;
    phase("noctMeshDataRead star.obj");
    err = fresh_err();
    st = noctMeshDataRead(path_star_obj, &d, &err);
    if (!judge(o, "noctMeshDataRead", st, NOCT_OK, &err, true))
        goto out;
    phase("noctMeshCreateSurfaceFromData star.obj");
    err = fresh_err();
    st = noctMeshCreateSurfaceFromData(d, &m[2], &err);
    if (!judge(o, "noctMeshCreateSurfaceFromData", st, NOCT_OK, &err, true))
        goto out;
    phase("noctMeshCreate star 0.75");
    err = fresh_err();
    st = star_create(0.75, &m[3], &err);
    if (!judge(o, "noctMeshCreate", st, NOCT_OK, &err, true))
        goto out;
    for (int i = 0; i < 4; ++i) {
        mix_mesh(o, m[i]);
        mix(o, noctMeshIsSurface(m[i]));
    }
    collide_all(o, m, 4);
    for (int i = 0; i < 4; ++i) {
        phase("noctDistance surface %d", i);
        noctTransform x = noctIdentityTransform(), y = noctIdentityTransform();
        y.p[0] = 0.5;
        noctDistanceResult r;
        err = fresh_err();
        st = noctDistance(m[i], &x, m[(i + 1) % 4], &y, INFINITY, &r, NULL, &err);
        if (!judge(o, "noctDistance", st, NOCT_OK, &err, true))
            goto out;
        mix(o, r.colliding);
    }
out:
    noctMeshDataDestroy(d);
    for (int i = 0; i < 4; ++i)
        noctMeshDestroy(m[i]);
}

static void must_be_valid(outcome *o, const noctWorld *w, const char *after);

/* Step a world, hashing its events; false after a failed step (the world
 * is then destroyed, as noctWorldStep's documentation asks). */
static bool steps(outcome *o, noctWorld **w, const char *name, int count)
{
    for (int s = 0; s < count; ++s) {
        phase("%s: noctWorldStep %d", name, s);
        noctError err = fresh_err();
        noctStatus st = noctWorldStep(*w, &err);
        const bool was_nomem = o->nomem;
        if (!judge(o, "noctWorldStep", st, NOCT_OK, &err, true)) {
            /* A failed step leaves the world valid, with every object
             * where it was (noctWorldStep's documentation): so a retry
             * that gets its memory continues exactly as the unfailed run,
             * and the part's result must then be the baseline's. */
            bool retried = false;
            if (st == NOCT_ERR_NOMEM) {
                must_be_valid(o, *w, "a failed noctWorldStep");
                phase("%s: noctWorldStep %d, retried", name, s);
                err = fresh_err();
                retried = noctWorldStep(*w, &err) == NOCT_OK;
            }
            if (!retried) {
                phase("%s: noctWorldDestroy after a failed step", name);
                noctWorldDestroy(*w);
                *w = NULL;
                return false;
            }
            o->nomem = was_nomem; /* recovered: judged against the baseline */
        }
        const noctPair *p;
        size_t n = noctWorldBegan(*w, &p);
        mix(o, 0xb0 + (uint64_t)s);
        for (size_t i = 0; i < n; ++i)
            mix(o, (uint64_t)p[i].a.index << 32 | p[i].b.index);
        n = noctWorldEnded(*w, &p);
        mix(o, 0xe0 + (uint64_t)s);
        for (size_t i = 0; i < n; ++i)
            mix(o, (uint64_t)p[i].a.index << 32 | p[i].b.index);
        mix(o, noctWorldColliding(*w, &p));
    }
    return true;
}

/* noctWorldValidate, uncounted, after a failed call that leaves the world
 * usable. */
static void must_be_valid(outcome *o, const noctWorld *w, const char *after)
{
    alloc_pause();
    noctError err = fresh_err();
    noctStatus st = noctWorldValidate(w, &err);
    alloc_resume();
    if (st != NOCT_OK)
        record(o, K_INVALID, "after %s, noctWorldValidate: %s", after, err.message);
}

/* Scene files: read (the meshes they name through the readers), built,
 * stepped; the family scenes (gas, whose world owns its meshes, and
 * planes); and a file with an error. */
static void part_scene(outcome *o)
{
    noctScene *sc = NULL;
    noctWorld *w = NULL;
    noctError err = fresh_err();
    noctStatus st;

    phase("noctSceneRead");
    st = noctSceneRead(path_scene, &sc, &err);
    if (st != NOCT_OK && sc != NULL)
        record(o, K_STATUS, "noctSceneRead failed but left a scene");
    if (!judge(o, "noctSceneRead", st, NOCT_OK, &err, true))
        goto out;
    mix(o, (uint64_t)noctSceneSteps(sc));
    phase("noctSceneBuild");
    err = fresh_err();
    st = noctSceneBuild(sc, &w, &err);
    if (st != NOCT_OK && w != NULL)
        record(o, K_STATUS, "noctSceneBuild failed but left a world");
    if (!judge(o, "noctSceneBuild", st, NOCT_OK, &err, true))
        goto out;
    mix(o, noctWorldObjectCount(w));
    if (!steps(o, &w, "scene", noctSceneSteps(sc)))
        goto out;
    phase("scene: noctWorldDestroy");
    noctWorldDestroy(w);
    w = NULL;
    phase("noctSceneDestroy");
    noctSceneDestroy(sc);
    sc = NULL;

    /* the two families, each built small and stepped */
    static const struct {
        const char *spec, *name;
        int N, steps;
    } families[] = {{"gas:24", "gas", 3, 4}, {"planes:1", "planes", 2, 12}};
    for (size_t f = 0; f < sizeof families / sizeof *families; ++f) {
        phase("noctSceneFamily %s", families[f].spec);
        err = fresh_err();
        st = noctSceneFamily(families[f].spec, &sc, &err);
        if (!judge(o, "noctSceneFamily", st, NOCT_OK, &err, true))
            goto out;
        noctSceneDef(sc)->N = families[f].N;
        noctSceneDef(sc)->max_depth = 4;
        phase("noctSceneBuild %s", families[f].spec);
        err = fresh_err();
        st = noctSceneBuild(sc, &w, &err);
        if (st != NOCT_OK && w != NULL)
            record(o, K_STATUS, "noctSceneBuild failed but left a world");
        if (!judge(o, "noctSceneBuild", st, NOCT_OK, &err, true))
            goto out;
        if (!steps(o, &w, families[f].name, families[f].steps))
            goto out;
        phase("%s: noctWorldDestroy", families[f].name);
        noctWorldDestroy(w);
        w = NULL;
        noctSceneDestroy(sc);
        sc = NULL;
    }

    phase("noctSceneRead bad.scene");
    err = fresh_err();
    st = noctSceneRead(path_bad_scene, &sc, &err);
    if (sc != NULL)
        record(o, K_STATUS, "noctSceneRead of a bad file gave a scene");
    if (judge(o, "noctSceneRead (bad.scene)", st, NOCT_ERR_INVALID, &err, true))
        mix(o, (uint64_t)err.line);
out:
    phase("scene: clean-up");
    noctWorldDestroy(w);
    noctSceneDestroy(sc);
}

/* The world part's meshes, made uncounted: its points are the world's. */
typedef struct world_meshes {
    noctMesh *m[4];
} world_meshes;

static bool world_meshes_make(outcome *o, world_meshes *wm)
{
    static const double half[3] = {0.45, 0.3, 0.35};
    const double c = cos(0.7), s = sin(0.7);
    const double rot[9] = {1, 0, 0, 0, c, -s, 0, s, c};
    memset(wm, 0, sizeof *wm);
    alloc_pause();
    bool ok = noctMeshCreateBox(0.5, 0.5, 0.5, &wm->m[0], NULL) == NOCT_OK &&
              noctMeshCreateBox(0.8, 0.3, 0.4, &wm->m[1], NULL) == NOCT_OK &&
              noctMeshCreateOrientedBox(half, rot, &wm->m[2], NULL) == NOCT_OK &&
              star_create(0.6, &wm->m[3], NULL) == NOCT_OK;
    alloc_resume();
    if (!ok)
        record(o, K_HARNESS, "cannot make the world's meshes");
    return ok;
}

static void world_meshes_free(world_meshes *wm)
{
    for (int i = 0; i < 4; ++i)
        noctMeshDestroy(wm->m[i]);
}

/* A seeded object: mesh, position in [1, side - 1]^3, direction, speed. */
static void random_object(uint64_t *rng, double side, int *mesh, double pos[3],
                          double dir[3], double *speed)
{
    *mesh = (int)test_rand_below(rng, 4);
    double len = 0;
    for (int k = 0; k < 3; ++k) {
        pos[k] = 1 + (side - 2) * (double)(test_rand(rng) >> 11) * 0x1p-53;
        dir[k] = (double)(test_rand(rng) >> 11) * 0x1p-52 - 1;
        len += dir[k] * dir[k];
    }
    len = sqrt(len);
    for (int k = 0; k < 3; ++k)
        dir[k] = len > 0.1 ? dir[k] / len : (k == 0);
    *speed = 0.05 + 0.2 * (double)(test_rand(rng) >> 11) * 0x1p-53;
}

typedef struct world_spec {
    const char *name;
    int objects;
    int steps;
    double side;
    int N;
    noctAccuracy accuracy;
    noctMaintenance maintenance;
    unsigned extra_effects;
    uint64_t seed;
} world_spec;

/* Add object i of the spec; false if the run cannot go on as in the
 * baseline. A documented NOCT_ERR_NOMEM leaves the world valid and the
 * run goes on without the object. */
static bool add_object(outcome *o, noctWorld *w, const world_meshes *wm, uint64_t *rng,
                       const world_spec *sp, noctObjectId *id, bool *alive)
{
    int mesh;
    double pos[3], dir[3], speed;
    random_object(rng, sp->side, &mesh, pos, dir, &speed);
    noctError err = fresh_err();
    noctStatus st = noctWorldAdd(w, wm->m[mesh], pos, dir, speed, id, &err);
    *alive = st == NOCT_OK;
    if (judge(o, "noctWorldAdd", st, NOCT_OK, &err, true))
        return true;
    if (st == NOCT_ERR_NOMEM)
        must_be_valid(o, w, "a failed noctWorldAdd");
    return o->kind == K_NONE;
}

/* Remove an object; a failure other than a documented one stops the run. */
static bool remove_object(outcome *o, noctWorld *w, noctObjectId id, bool *alive)
{
    noctStatus st = noctWorldRemove(w, id, NULL);
    if (st == NOCT_OK) {
        *alive = false;
        return true;
    }
    /* noctWorldRemove does not list NOCT_ERR_NOMEM: judge() says so. */
    judge(o, "noctWorldRemove", st, NOCT_OK, NULL, false);
    if (st == NOCT_ERR_NOMEM)
        must_be_valid(o, w, "a failed noctWorldRemove");
    return o->kind == K_NONE;
}

/*
 * A world: create, add the objects, step a third of the steps, remove a
 * sixth of the objects, step, add a few (into the freed slots), step the
 * rest, then remove every object (hashing the positions) and destroy.
 */
static void run_world(outcome *o, const world_spec *sp)
{
    world_meshes wm;
    if (!world_meshes_make(o, &wm))
        return;
    const int total = sp->objects + sp->objects / 8;
    noctObjectId ids[128];
    bool alive[128] = {false};
    uint64_t rng = sp->seed;
    noctWorld *w = NULL;
    int added = 0;

    noctWorldDef def = noctDefaultWorldDef();
    def.N = sp->N;
    def.max_depth = 5;
    def.accuracy = sp->accuracy;
    def.maintenance = sp->maintenance;
    def.effects |= NOCT_EFFECT_WALLS | sp->extra_effects;
    for (int k = 0; k < 3; ++k) {
        def.walls_lo[k] = 0;
        def.walls_hi[k] = sp->side;
    }
    phase("%s: noctWorldCreate", sp->name);
    noctError err = fresh_err();
    noctStatus st = noctWorldCreate(&def, &w, &err);
    if (st != NOCT_OK && w != NULL)
        record(o, K_STATUS, "noctWorldCreate failed but left a world");
    if (!judge(o, "noctWorldCreate", st, NOCT_OK, &err, true))
        goto out;
    for (; added < sp->objects; ++added) {
        phase("%s: noctWorldAdd %d", sp->name, added);
        if (!add_object(o, w, &wm, &rng, sp, &ids[added], &alive[added]))
            goto out;
    }
    if (!steps(o, &w, sp->name, sp->steps / 3))
        goto out;
    for (int i = 0; i < sp->objects; i += 6) {
        if (!alive[i])
            continue;
        phase("%s: noctWorldRemove %d", sp->name, i);
        if (!remove_object(o, w, ids[i], &alive[i]))
            goto out;
    }
    if (!steps(o, &w, sp->name, sp->steps / 3))
        goto out;
    for (; added < total; ++added) {
        phase("%s: noctWorldAdd %d", sp->name, added);
        if (!add_object(o, w, &wm, &rng, sp, &ids[added], &alive[added]))
            goto out;
    }
    if (!steps(o, &w, sp->name, sp->steps - 2 * (sp->steps / 3)))
        goto out;
    mix(o, noctWorldObjectCount(w));
    for (int i = 0; i < added; ++i) {
        if (!alive[i])
            continue;
        double pos[3], dir[3];
        if (noctWorldObject(w, ids[i], pos, dir) != NOCT_OK) {
            record(o, K_STATUS, "noctWorldObject rejects a live object");
            goto out;
        }
        for (int k = 0; k < 3; ++k) {
            mix_double(o, pos[k]);
            mix_double(o, dir[k]);
        }
        phase("%s: noctWorldRemove %d at the end", sp->name, i);
        if (!remove_object(o, w, ids[i], &alive[i]))
            goto out;
    }
    mix(o, noctWorldObjectCount(w));
    must_be_valid(o, w, "removing every object");
out:
    if (w != NULL) {
        phase("%s: noctWorldDestroy", sp->name);
        noctWorldDestroy(w);
    }
    world_meshes_free(&wm);
}

/* A failed call that says nothing changed: the world valid (its slots
 * all live or free) and holding the objects it held. */
static void unchanged(outcome *o, const noctWorld *w, size_t objects, const char *after)
{
    must_be_valid(o, w, after);
    if (noctWorldObjectCount(w) != objects)
        record(o, K_INVALID, "after %s, %zu objects, not %zu", after,
               noctWorldObjectCount(w), objects);
}

/*
 * The object model beyond noctWorldAdd: objects made from definitions
 * (meshes turned, box primitives, the first spinner, whose angular
 * velocity makes the world's array), the setters that allocate (a
 * turning transform, an angular velocity, a track), a world with a
 * margin stepped with its tracks and spinners, queries into collecting
 * arrays, and the scene writer. After every failed call the world must
 * be valid, with no slot lost, and hold the objects it held; a further
 * object made afterwards must get a slot within the ones there are.
 */
static void part_objects(outcome *o)
{
    noctMesh *cube = NULL;
    noctWorld *w = NULL;
    noctScene *sc = NULL;
    noctError err = fresh_err();
    const double z[3] = {0, 0, 1};
    phase("objects: noctMeshCreateBox");
    noctStatus st = noctMeshCreateBox(0.5, 0.5, 0.5, &cube, &err);
    if (!judge(o, "noctMeshCreateBox", st, NOCT_OK, &err, true))
        goto out;
    noctWorldDef def = noctDefaultWorldDef();
    def.effects |= NOCT_EFFECT_SPIN | NOCT_EFFECT_TRACK;
    def.margin = 0.25;
    phase("objects: noctWorldCreate");
    err = fresh_err();
    st = noctWorldCreate(&def, &w, &err);
    if (!judge(o, "noctWorldCreate", st, NOCT_OK, &err, true))
        goto out;
    enum { NOBJ = 12 };
    noctObjectId ids[NOBJ];
    for (int i = 0; i < NOBJ; ++i) {
        noctObjectDef d = noctDefaultObjectDef();
        if (i % 3 == 0) {
            d.mesh = cube;
        } else {
            d.half_extents[0] = 0.4;
            d.half_extents[1] = 0.3;
            d.half_extents[2] = 0.2;
        }
        d.transform.p[0] = 0.7 * i;
        d.transform.p[1] = 0.3 * (i % 4);
        if (i % 2)
            noctQuatFromAxisAngle(z, 30.0 * i, &d.transform.q);
        if (i == 7) /* the first spinner: the world's array is made */
            noctQuatFromAxisAngle(z, 10, &d.angular_velocity);
        d.velocity[0] = 0.05 * (i % 3 - 1);
        const size_t before = noctWorldObjectCount(w);
        phase("objects: noctWorldCreateObject %d", i);
        err = fresh_err();
        st = noctWorldCreateObject(w, &d, &ids[i], &err);
        if (!judge(o, "noctWorldCreateObject", st, NOCT_OK, &err, true)) {
            unchanged(o, w, before, "a failed noctWorldCreateObject");
            goto out;
        }
        mix(o, ids[i].index);
    }
    const size_t all = noctWorldObjectCount(w);
    for (int i = 0; i < NOBJ; i += 2) {
        noctTransform x;
        noctWorldGetTransform(w, ids[i], &x);
        noctQuatFromAxisAngle(z, 45.0 + i, &x.q); /* a new rotation: a new turned mesh */
        phase("objects: noctWorldSetTransform %d", i);
        err = fresh_err();
        st = noctWorldSetTransform(w, ids[i], &x, &err);
        if (!judge(o, "noctWorldSetTransform", st, NOCT_OK, &err, true)) {
            unchanged(o, w, all, "a failed noctWorldSetTransform");
            goto out;
        }
    }
    noctQuat spin;
    noctQuatFromAxisAngle(z, -5, &spin);
    phase("objects: noctWorldSetAngularVelocity");
    err = fresh_err();
    st = noctWorldSetAngularVelocity(w, ids[3], &spin, &err);
    if (!judge(o, "noctWorldSetAngularVelocity", st, NOCT_OK, &err, true)) {
        unchanged(o, w, all, "a failed noctWorldSetAngularVelocity");
        goto out;
    }
    noctKeyframe keys[3];
    for (int k = 0; k < 3; ++k) {
        keys[k].tick = (uint64_t)(2 * k);
        keys[k].x = (noctTransform){{1.0 * k, 2, 0}, {0, 0, 0, 1}};
        noctQuatFromAxisAngle(z, 60.0 * k, &keys[k].x.q);
    }
    phase("objects: noctWorldSetTrack");
    err = fresh_err();
    st = noctWorldSetTrack(w, ids[4], keys, 3, &err);
    if (!judge(o, "noctWorldSetTrack", st, NOCT_OK, &err, true)) {
        unchanged(o, w, all, "a failed noctWorldSetTrack");
        goto out;
    }
    /* and a cube mesh on the same track: turned into its recycled copy
     * from the second step on, which a failed step gives back */
    phase("objects: noctWorldSetTrack (a mesh)");
    err = fresh_err();
    st = noctWorldSetTrack(w, ids[6], keys, 3, &err);
    if (!judge(o, "noctWorldSetTrack", st, NOCT_OK, &err, true)) {
        unchanged(o, w, all, "a failed noctWorldSetTrack");
        goto out;
    }
    if (!steps(o, &w, "objects", 6))
        goto out;
    const noctPair *p;
    mix(o, noctWorldNear(w, &p));
    mix(o, noctWorldColliding(w, &p));
    /* queries: they only read the world */
    noctObjectId found[NOBJ];
    noctObjectBuffer buf = {found, NOBJ, 0};
    const double lo[3] = {-1, -1, -1}, hi[3] = {4, 1, 1}, at[3] = {0.7, 0.3, 0};
    const double from[3] = {-2, 0.1, 0.05}, along[3] = {12, 0, 0};
    phase("objects: noctWorldQueryBox");
    err = fresh_err();
    st = noctWorldQueryBox(w, lo, hi, noctDefaultQueryFilter(), noctCollectObjects, &buf, &err);
    if (!judge(o, "noctWorldQueryBox", st, NOCT_OK, &err, true))
        goto out;
    mix(o, buf.count);
    buf.count = 0;
    phase("objects: noctWorldQueryPoint");
    err = fresh_err();
    st = noctWorldQueryPoint(w, at, noctDefaultQueryFilter(), noctCollectObjects, &buf, &err);
    if (!judge(o, "noctWorldQueryPoint", st, NOCT_OK, &err, true))
        goto out;
    mix(o, buf.count);
    buf.count = 0;
    phase("objects: noctWorldQueryNear");
    err = fresh_err();
    st = noctWorldQueryNear(w, cube, NULL, &(noctTransform){{2, 0, 0}, {0, 0, 0, 1}}, 0.5,
                            noctDefaultQueryFilter(), noctCollectObjects, &buf, &err);
    if (!judge(o, "noctWorldQueryNear", st, NOCT_OK, &err, true))
        goto out;
    mix(o, buf.count);
    noctRayHit hits[NOBJ];
    noctRayHitBuffer hb = {hits, NOBJ, 0};
    phase("objects: noctWorldRayCast");
    err = fresh_err();
    st = noctWorldRayCast(w, from, along, noctDefaultQueryFilter(), noctCollectRayHits, &hb,
                          &err);
    if (!judge(o, "noctWorldRayCast", st, NOCT_OK, &err, true))
        goto out;
    mix(o, hb.count);
    noctRayHit first;
    bool any = false;
    phase("objects: noctWorldRayCastClosest");
    err = fresh_err();
    st = noctWorldRayCastClosest(w, from, along, noctDefaultQueryFilter(), &first, &any, &err);
    if (!judge(o, "noctWorldRayCastClosest", st, NOCT_OK, &err, true))
        goto out;
    mix(o, any);
    if (any)
        mix_double(o, first.fraction);
    /* removal and a new object in the freed slot: no slot was lost */
    phase("objects: noctWorldRemove");
    if (noctWorldRemove(w, ids[5], NULL) != NOCT_OK) {
        record(o, K_STATUS, "noctWorldRemove rejects a live object");
        goto out;
    }
    noctObjectDef d = noctDefaultObjectDef();
    d.mesh = cube;
    noctQuatFromAxisAngle(z, 15, &d.angular_velocity);
    phase("objects: noctWorldCreateObject into a freed slot");
    err = fresh_err();
    st = noctWorldCreateObject(w, &d, &ids[5], &err);
    if (!judge(o, "noctWorldCreateObject", st, NOCT_OK, &err, true)) {
        unchanged(o, w, all - 1, "a failed noctWorldCreateObject");
        goto out;
    }
    mix(o, ids[5].index);
    /* the scene writer */
    phase("objects: noctSceneFamily");
    err = fresh_err();
    st = noctSceneFamily("arms:1", &sc, &err);
    if (!judge(o, "noctSceneFamily", st, NOCT_OK, &err, true))
        goto out;
    alloc_pause(); /* the test's own file */
    FILE *f = tmpfile();
    alloc_resume();
    if (f == NULL) {
        record(o, K_HARNESS, "tmpfile failed");
        goto out;
    }
    phase("objects: noctSceneWrite");
    err = fresh_err();
    st = noctSceneWrite(sc, f, &err);
    mix(o, (uint64_t)ftell(f));
    alloc_pause();
    fclose(f);
    alloc_resume();
    /* stdio's buffer is allocated at the first write: its failure is a
     * failed write, NOCT_ERR_IO, as documented */
    if (st == NOCT_ERR_IO && alloc_failures() > 0)
        documented(o);
    else
        judge(o, "noctSceneWrite", st, NOCT_OK, &err, false);
out:
    phase("objects: destroy");
    noctSceneDestroy(sc);
    noctWorldDestroy(w);
    noctMeshDestroy(cube);
}

/* Checked once, in the baseline: the exact world splits and merges
 * leaves and its objects collide, or the part would test less than it
 * claims. */
static bool world_exercised(const world_spec *sp, char *why, size_t n)
{
    world_meshes wm;
    outcome o;
    memset(&o, 0, sizeof o);
    if (!world_meshes_make(&o, &wm))
        return false;
    noctWorldDef def = noctDefaultWorldDef();
    def.N = sp->N;
    def.max_depth = 5;
    def.accuracy = sp->accuracy;
    def.effects |= NOCT_EFFECT_WALLS;
    for (int k = 0; k < 3; ++k)
        def.walls_hi[k] = sp->side;
    noctWorld *w = NULL;
    bool ok = noctWorldCreate(&def, &w, NULL) == NOCT_OK;
    uint64_t rng = sp->seed;
    for (int i = 0; ok && i < sp->objects; ++i) {
        int mesh;
        double pos[3], dir[3], speed;
        noctObjectId id;
        random_object(&rng, sp->side, &mesh, pos, dir, &speed);
        ok = noctWorldAdd(w, wm.m[mesh], pos, dir, speed, &id, NULL) == NOCT_OK;
    }
    for (int s = 0; ok && s < sp->steps; ++s)
        ok = noctWorldStep(w, NULL) == NOCT_OK && noctWorldValidate(w, NULL) == NOCT_OK;
    noctWorldCounters c;
    if (ok) {
        noctWorldGetCounters(w, &c);
        snprintf(why, n, "%" PRIu64 " splits, %" PRIu64 " merges, %" PRIu64 " events, %"
                 PRIu64 " GMP fallbacks", c.splits, c.merges, c.events, c.narrow.exact_fallbacks);
        ok = c.splits > 0 && c.merges > 0 && c.events > 0;
    } else {
        snprintf(why, n, "the world failed without injected failures");
    }
    noctWorldDestroy(w);
    world_meshes_free(&wm);
    return ok;
}

static const world_spec world_exact = {"world", 40, 30, 8.0, 3, NOCT_ACCURACY_EXACT,
                                       NOCT_MAINTAIN_INCREMENTAL, 0, 12345};

static void part_world(outcome *o)
{
    run_world(o, &world_exact);
}

/* The other accuracy levels and modes, on smaller worlds. */
static void part_world_levels(outcome *o)
{
    static const world_spec specs[] = {
        {"box", 20, 12, 6.0, 3, NOCT_ACCURACY_BOX, NOCT_MAINTAIN_INCREMENTAL, 0, 7},
        {"convex", 20, 12, 6.0, 3, NOCT_ACCURACY_CONVEX, NOCT_MAINTAIN_INCREMENTAL, 0, 8},
        {"rebuild", 20, 9, 6.0, 2, NOCT_ACCURACY_EXACT, NOCT_MAINTAIN_REBUILD, 0, 9},
        {"substep", 16, 6, 6.0, 3, NOCT_ACCURACY_EXACT, NOCT_MAINTAIN_INCREMENTAL,
         NOCT_EFFECT_SUBSTEP, 10},
        {"exhaustive", 16, 6, 6.0, NOCT_N_EXHAUSTIVE, NOCT_ACCURACY_EXACT,
         NOCT_MAINTAIN_INCREMENTAL, 0, 11}};
    for (size_t i = 0; i < sizeof specs / sizeof *specs; ++i) {
        run_world(o, &specs[i]);
        if (o->kind != K_NONE)
            return;
    }
}

/* noctCollide on pairs that touch exactly, so that the exact level's
 * orientation tests fall back to GMP: this part fails GMP's allocations. */
static void part_collide(outcome *o)
{
    world_meshes wm;
    if (!world_meshes_make(o, &wm))
        return;
    noctMesh *star = NULL;
    alloc_pause();
    noctStatus st = star_create(1.0, &star, NULL);
    alloc_resume();
    if (st != NOCT_OK) {
        record(o, K_HARNESS, "cannot make the star");
        world_meshes_free(&wm);
        return;
    }
    /* Faces flush at z = 0.5 (an integer offset moves the star exactly),
     * then the other meshes against the star and each other. */
    static const double offsets[][3] = {{0, 0, 1}, {0, 0, -1}, {0, 0, 1.25}, {2, 0, 0},
                                        {0.25, 0.5, 1}, {1.5, 0, 0}};
    const double origin[3] = {0, 0, 0};
    noctMesh *all[5] = {star, wm.m[0], wm.m[1], wm.m[2], wm.m[3]};
    for (size_t i = 0; i < 5 && o->kind == K_NONE && !o->nomem; ++i)
        for (size_t j = i; j < 5; ++j)
            for (size_t t = 0; t < sizeof offsets / sizeof *offsets; ++t) {
                phase("noctCollide %zu %zu offset %zu", i, j, t);
                bool hit = false;
                noctNarrowStats stats;
                memset(&stats, 0, sizeof stats);
                st = noctCollide(all[i], origin, all[j], offsets[t], NOCT_ACCURACY_EXACT,
                                 &hit, &stats);
                if (!judge(o, "noctCollide", st, NOCT_OK, NULL, true))
                    goto out;
                mix(o, hit);
            }
out:
    noctMeshDestroy(star);
    world_meshes_free(&wm);
}

/* The octree ADT and neighbor finding on their own: octCreate and
 * octSplit (whose failures their documentation lists: NULL, and false
 * with the node unchanged), octGtEqNeighbor over the tree, octPrint to a
 * memory stream that cannot grow (false, or the whole text), octJoin,
 * octClear and octDispose. */
static int octree_tags[1024];
static unsigned octree_killed;

static void octree_kill(void *data)
{
    octree_killed += (unsigned)*(int *)data;
}

static void octree_print(FILE *strm, const void *data)
{
    fprintf(strm, "tag %d", *(const int *)data);
}

static void part_octree(outcome *o)
{
    enum { MAX_NODES = 1 + 8 * 100 };
    static octNode *nodes[MAX_NODES];
    size_t nn = 0;
    uint64_t rng = 0x0c7;

    phase("octCreate");
    octNode *root = octCreate();
    if (root == NULL) {
        documented(o);
        return;
    }
    nodes[nn++] = root;
    for (int i = 0; i < 100; ++i) {
        octNode *n = nodes[test_rand_below(&rng, nn)];
        if (octIsSplit(n) || octGeneration(n) >= 6)
            continue;
        phase("octSplit %d", i);
        if (!octSplit(n)) {
            /* Documented: false, and the node unchanged and still a leaf. */
            if (octIsSplit(n) || octChild(n, OCT_LDB) != NULL)
                record(o, K_STATUS, "octSplit failed but the node is split");
            documented(o);
            continue;
        }
        for (int v = OCT_LDB; v <= OCT_RUF; ++v)
            nodes[nn++] = octChild(n, (octDirection)v);
    }
    alloc_pause();
    size_t count = tree_validate(root);
    alloc_resume();
    if (count != nn)
        record(o, K_STATUS, "the tree has %zu nodes, %zu were made", count, nn);
    mix(o, nn);
    /* Neighbors: the result's index among the nodes (or none). */
    phase("octGtEqNeighbor");
    for (int q = 0; q < 300; ++q) {
        octNode *n = nodes[test_rand_below(&rng, nn)];
        octDirection d = (octDirection)test_rand_below(&rng, OCT_RUF + 1);
        octNode *r = octGtEqNeighbor(n, d);
        size_t at = nn;
        for (size_t i = 0; i < nn && r != NULL; ++i)
            if (nodes[i] == r) {
                at = i;
                break;
            }
        if (r != NULL && at == nn)
            record(o, K_STATUS, "octGtEqNeighbor returned a node not in the tree");
        mix(o, at);
    }
    /* Data on every leaf, printed. */
    for (size_t i = 0; i < nn; ++i) {
        octree_tags[i] = (int)i + 1;
        if (!octIsSplit(nodes[i]))
            octSwapData(nodes[i], &octree_tags[i]);
    }
    phase("octPrint");
    char *text = NULL;
    size_t len = 0;
    alloc_pause();
    FILE *f = open_memstream(&text, &len);
    alloc_resume();
    if (f != NULL) {
        bool printed = octPrint(root, octree_print, f);
        alloc_pause();
        bool closed = fclose(f) == 0;
        alloc_resume();
        if (printed && closed) {
            for (size_t i = 0; i < len; ++i)
                mix(o, (unsigned char)text[i]);
        } else if (!printed) {
            documented(o); /* a write failed */
        }
        free(text);
    }
    /* Join a few internal nodes (their leaves' data to the disposer),
     * clear and dispose. */
    phase("octJoin");
    octree_killed = 0;
    for (size_t i = 1; i < nn; i += 7)
        if (octIsSplit(nodes[i]) && octParent(nodes[i]) != NULL) {
            octJoin(nodes[i], octree_kill);
            break;
        }
    phase("octClear");
    octClear(root, octree_kill);
    mix(o, octree_killed);
    phase("octDispose");
    octDispose(root);
}

/* ==== the runner =========================================================== */

typedef void part_fn(outcome *o);

/* Run a part with the allocator counting, failing point fail_at (and with
 * rest every later one); fill the outcome's counts and leak check. */
static void run_part(part_fn *fn, unsigned long fail_at, bool rest, bool fail_gmp,
                     outcome *o)
{
    memset(o, 0, sizeof *o);
    trace_at = 0;
    if (trace_mode == TRACE_RECORD)
        trace_n = 0;
    o->type = REC_DONE;
    o->digest = 1469598103934665603u;
    run_begin(fail_at, rest, fail_gmp);
    fn(o);
    alloc_end();
    o->points = alloc_points();
    o->injected = alloc_failures();
    o->gmp_seen = g_gmp_seen;
    o->leaks = alloc_live(o->leak_callers, 3);
    if (alloc_live_overflowed())
        record(o, K_HARNESS, "the harness's table of live blocks overflowed");
    if (o->leaks > 0)
        record(o, K_LEAK, "%zu block%s still allocated after everything was destroyed",
             o->leaks, o->leaks == 1 ? "" : "s");
}

/* ---- symbols, for the report ---- */

typedef struct sym_cache {
    const void *addr;
    char text[300];  /* "f (file.c:12), inlined in g (file.c:34)" */
    char inner[96];  /* f */
    char outer[96];  /* g, or f */
} sym_cache;
static sym_cache syms[1024];
static size_t nsyms;

/* strncpy that always terminates. */
static void copy_str(char *dst, size_t n, const char *src)
{
    size_t len = strlen(src);
    if (len >= n)
        len = n - 1;
    memcpy(dst, src, len);
    dst[len] = '\0';
}

static const char *base_name(const char *path)
{
    const char *s = strrchr(path, '/');
    return s ? s + 1 : path;
}

/* Look a return address up: addr2line (debug information names the
 * static and inlined functions dladdr cannot), else dladdr's symbol,
 * else module+offset. */
static const sym_cache *lookup_symbol(const void *addr)
{
    for (size_t i = 0; i < nsyms; ++i)
        if (syms[i].addr == addr)
            return &syms[i];
    sym_cache *c = nsyms < sizeof syms / sizeof *syms ? &syms[nsyms++] : &syms[0];
    memset(c, 0, sizeof *c);
    c->addr = addr;
    Dl_info info;
    if (dladdr(addr, &info) == 0 || info.dli_fname == NULL) {
        snprintf(c->text, sizeof c->text, "%p", addr);
        snprintf(c->inner, sizeof c->inner, "%p", addr);
        memcpy(c->outer, c->inner, sizeof c->outer);
        return c;
    }
    uintptr_t off = (uintptr_t)addr - (uintptr_t)info.dli_fbase - 1;
    snprintf(c->text, sizeof c->text, "%s+0x%" PRIxPTR, base_name(info.dli_fname), off);
    if (info.dli_sname != NULL)
        snprintf(c->text, sizeof c->text, "%s (%s)", info.dli_sname, base_name(info.dli_fname));
    copy_str(c->inner, sizeof c->inner, c->text);
    c->inner[strcspn(c->inner, " ")] = '\0';
    memcpy(c->outer, c->inner, sizeof c->outer);
    char cmd[700];
    snprintf(cmd, sizeof cmd, "addr2line -f -i -p -e '%s' 0x%" PRIxPTR " 2>/dev/null",
             info.dli_fname, off);
    FILE *p = popen(cmd, "r");
    if (p == NULL)
        return c;
    char line[400], text[300] = "";
    size_t used = 0;
    int n = 0;
    while (fgets(line, sizeof line, p) != NULL) {
        line[strcspn(line, "\n")] = '\0';
        const char *fn = line;
        if (strncmp(fn, " (inlined by) ", 14) == 0)
            fn += 14;
        char *at = strstr(fn, " at ");
        if (fn[0] == '?' || at == NULL || strstr(at, "??") != NULL)
            break;
        *at = '\0';
        char *disc = strstr(at + 4, " (discriminator");
        if (disc)
            *disc = '\0';
        if (n == 0)
            copy_str(c->inner, sizeof c->inner, fn);
        copy_str(c->outer, sizeof c->outer, fn);
        if (used < sizeof text)
            used += (size_t)snprintf(text + used, sizeof text - used, "%s%s (%s)",
                                     n == 0 ? "" : ", inlined in ", fn, base_name(at + 4));
        ++n;
    }
    pclose(p);
    if (n > 0)
        snprintf(c->text, sizeof c->text, "%s", text);
    return c;
}

static const char *symbolize(const void *addr)
{
    return lookup_symbol(addr)->text;
}

static bool is_library_frame(const void *addr)
{
    Dl_info info;
    return dladdr(addr, &info) != 0 && info.dli_fname != NULL &&
           strstr(base_name(info.dli_fname), "libnoctree") != NULL;
}

static bool is_harness_frame(const void *addr)
{
    Dl_info info;
    if (dladdr(addr, &info) == 0 || info.dli_fname == NULL)
        return false;
    static Dl_info self;
    static bool have_self;
    if (!have_self) {
        have_self = dladdr((void *)(uintptr_t)&run_part, &self) != 0;
    }
    return have_self && info.dli_fbase == self.dli_fbase;
}

/* The allocation's stack, from its caller to the harness's part. */
static void print_stack(const inject_rec *r, const char *indent)
{
    int first = 0;
    while (first < r->nframes && is_harness_frame(r->frames[first]))
        ++first; /* backtrace() and malloc itself */
    for (int i = first; i < r->nframes; ++i) {
        printf("%s%s %s\n", indent, i == first ? "at" : "<-", symbolize(r->frames[i]));
        if (is_harness_frame(r->frames[i]))
            break; /* the workload's caller; Check's frames add nothing */
    }
}

/* The call site a failure is grouped by: the function that allocated,
 * then the innermost and the outermost functions of libnoctree on the
 * stack (the one that asked, and the API function called). */
static void site_name(const inject_rec *r, char *out, size_t n)
{
    int first = 0;
    while (first < r->nframes && is_harness_frame(r->frames[first]))
        ++first;
    if (first >= r->nframes) {
        snprintf(out, n, "?");
        return;
    }
    int inner = -1, outer = -1;
    for (int i = first; i < r->nframes; ++i)
        if (is_library_frame(r->frames[i])) {
            if (inner < 0)
                inner = i;
            outer = i;
        }
    const char *names[3];
    int k = 0;
    names[k++] = lookup_symbol(r->frames[first])->inner;
    if (inner >= 0) {
        const char *a = lookup_symbol(r->frames[inner])->inner;
        const char *b = lookup_symbol(r->frames[outer])->outer;
        if (strcmp(a, names[0]) != 0)
            names[k++] = a;
        if (strcmp(b, names[k - 1]) != 0)
            names[k++] = b;
    }
    size_t used = 0;
    out[0] = '\0';
    for (int i = 0; i < k && used < n; ++i)
        used += (size_t)snprintf(out + used, n - used, "%s%s", i ? " < " : "", names[i]);
}

/* ---- one run in a child process ---- */

typedef struct run_result {
    fail_kind kind;
    char msg[640];
    bool have_inject;
    inject_rec inject;
    bool have_done;
    outcome done;
} run_result;

static bool env_flag(const char *name)
{
    const char *v = getenv(name);
    return v != NULL && *v != '\0' && strcmp(v, "0") != 0;
}

static void judge_done(const outcome *base, run_result *rr)
{
    const outcome *d = &rr->done;
    if (d->kind != K_NONE) {
        rr->kind = d->kind;
        snprintf(rr->msg, sizeof rr->msg, "%s", d->msg);
    } else if (d->injected == 0) {
        rr->kind = K_HARNESS;
        snprintf(rr->msg, sizeof rr->msg, "the run never reached its point (%lu points): "
                 "the allocations are not deterministic", d->points);
    } else if (!d->nomem && d->digest != base->digest) {
        rr->kind = K_DIFFERS;
        snprintf(rr->msg, sizeof rr->msg, "no call reported the failure, but the result "
                 "differs from the unfailed run's, first at phase '%s'", d->diverged);
    }
    if (d->kind == K_LEAK || (d->leaks > 0 && rr->kind != K_NONE)) {
        size_t used = strlen(rr->msg);
        for (int i = 0; i < 3 && d->leak_callers[i] != NULL; ++i)
            used += (size_t)snprintf(rr->msg + used, used < sizeof rr->msg ? sizeof rr->msg - used : 0,
                                     "%s %s", i == 0 ? "; allocated by" : ",",
                                     symbolize(d->leak_callers[i]));
    }
}

static void run_child(part_fn *fn, const outcome *base, unsigned long k, bool rest,
                      bool fail_gmp, run_result *rr)
{
    memset(rr, 0, sizeof *rr);
    if (env_flag("NOCT_ALLOC_NOFORK")) {
        run_part(fn, k, rest, fail_gmp, &rr->done);
        rr->have_done = true;
        rr->inject = g_inject;
        rr->have_inject = g_inject.type == REC_INJECT;
        judge_done(base, rr);
        return;
    }
    int fd[2];
    if (pipe(fd) != 0) {
        rr->kind = K_HARNESS;
        snprintf(rr->msg, sizeof rr->msg, "pipe: %s", strerror(errno));
        return;
    }
    fflush(stdout);
    fflush(stderr);
    pid_t pid = fork();
    if (pid < 0) {
        rr->kind = K_HARNESS;
        snprintf(rr->msg, sizeof rr->msg, "fork: %s", strerror(errno));
        close(fd[0]);
        close(fd[1]);
        return;
    }
    if (pid == 0) {
        close(fd[0]);
        g_report_fd = fd[1];
        alarm(60);
        outcome o;
        run_part(fn, k, rest, fail_gmp, &o);
        ssize_t w = write(fd[1], &o, sizeof o);
        _exit(w == (ssize_t)sizeof o ? 0 : 3);
    }
    close(fd[1]);
    static char buf[sizeof(inject_rec) + sizeof(outcome)];
    size_t got = 0;
    for (;;) {
        ssize_t r = read(fd[0], buf + got, sizeof buf - got);
        if (r < 0 && errno == EINTR)
            continue;
        if (r <= 0)
            break;
        got += (size_t)r;
        if (got == sizeof buf)
            break;
    }
    close(fd[0]);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
        ;
    size_t at = 0;
    int type;
    if (got >= sizeof type) {
        memcpy(&type, buf, sizeof type);
        if (type == REC_INJECT && got >= sizeof(inject_rec)) {
            memcpy(&rr->inject, buf, sizeof(inject_rec));
            rr->have_inject = true;
            at = sizeof(inject_rec);
        }
    }
    if (got - at >= sizeof(outcome)) {
        memcpy(&rr->done, buf + at, sizeof(outcome));
        rr->have_done = rr->done.type == REC_DONE;
    }
    if (WIFSIGNALED(status)) {
        int sig = WTERMSIG(status);
        rr->kind = sig == SIGALRM ? K_HANG : K_CRASH;
        snprintf(rr->msg, sizeof rr->msg, "%s (signal %d, %s)",
                 sig == SIGALRM ? "no end after 60 s" : "killed", sig, strsignal(sig));
    } else if (!rr->have_done) {
        rr->kind = K_EXIT;
        snprintf(rr->msg, sizeof rr->msg, "the process exited with status %d in the middle "
                 "of the workload", WIFEXITED(status) ? WEXITSTATUS(status) : -1);
    } else {
        judge_done(base, rr);
    }
}

/* ---- a part's two passes ---- */

/* Parts with more points than their sample_max (ALL: never) test the
 * first SAMPLE_HEAD and a sample of the rest, sample_max in all. */
#define SAMPLE_HEAD 100
#define ALL ULONG_MAX

/* Distinct failures of a part, by kind and call site. */
typedef struct distinct {
    fail_kind kind;
    char site[200];
    unsigned count;
    int pass;
    unsigned long k;
    char phase[64];
    char msg[640];
    inject_rec inject;
    bool have_inject;
} distinct;

static void check_part(const char *name, part_fn *fn, bool fail_gmp_here, bool need_points,
                       unsigned long sample_max)
{
    const bool fail_gmp = fail_gmp_here || env_flag("NOCT_ALLOC_GMP");
    const bool verbose = env_flag("NOCT_ALLOC_VERBOSE");
    outcome warm, base;
    trace_mode = TRACE_OFF;
    run_part(fn, 0, false, fail_gmp, &warm);
    trace_mode = TRACE_RECORD;
    g_profile = env_flag("NOCT_ALLOC_PROFILE");
    profile_n = 0;
    run_part(fn, 0, false, fail_gmp, &base);
    g_profile = false;
    trace_mode = TRACE_COMPARE;
    for (size_t i = 0; i < profile_n; ++i)
        if (profile[i].count >= 10)
            printf("profile %s: %lu points in phase '%s' from %s\n", name, profile[i].count,
                   profile[i].phase, symbolize(profile[i].caller));
    ck_assert_msg(base.kind == K_NONE && !base.nomem, "%s: the unfailed run fails: %s", name,
                  base.msg);
    ck_assert_msg(warm.digest == base.digest, "%s: two unfailed runs disagree", name);
    const unsigned long n = base.points;
    ck_assert_msg(n > 0 || !need_points, "%s: no allocation points", name);

    unsigned long only_k = 0;
    int only_pass = 0;
    if (getenv("NOCT_ALLOC_K") != NULL)
        only_k = strtoul(getenv("NOCT_ALLOC_K"), NULL, 10);
    if (getenv("NOCT_ALLOC_PASS") != NULL)
        only_pass = atoi(getenv("NOCT_ALLOC_PASS"));
    /* The points to fail: every one, or the first SAMPLE_HEAD and then one
     * in each of sample_max - SAMPLE_HEAD - 1 equal stretches, at a seeded
     * offset (so that a periodic allocation pattern is not always hit at
     * the same place), and the last. */
    const bool sample = n > sample_max && !env_flag("NOCT_ALLOC_ALL");
    unsigned long *ks = malloc(((sample ? sample_max : n) + 1) * sizeof *ks);
    ck_assert(ks != NULL);
    size_t nks = 0;
    if (only_k) {
        ks[nks++] = only_k;
    } else if (!sample) {
        for (unsigned long k = 1; k <= n; ++k)
            ks[nks++] = k;
    } else {
        for (unsigned long k = 1; k <= SAMPLE_HEAD; ++k)
            ks[nks++] = k;
        const unsigned long rest = n - SAMPLE_HEAD, m = sample_max - SAMPLE_HEAD - 1;
        uint64_t rng = 0x5eed;
        for (unsigned long i = 0; i < m; ++i) {
            unsigned long lo = SAMPLE_HEAD + 1 + rest * i / m;
            unsigned long hi = SAMPLE_HEAD + rest * (i + 1) / m;
            if (hi >= lo && hi < n)
                ks[nks++] = lo + (unsigned long)test_rand_below(&rng, hi - lo + 1);
        }
        ks[nks++] = n;
    }
    printf("%s: %lu allocation points, %s; %lu GMP allocations (%s)\n", name, n,
           only_k ? "one tested (NOCT_ALLOC_K)"
                  : sample ? "the first 100 and a deterministic sample of the rest tested"
                           : "every one tested",
           base.gmp_seen, fail_gmp ? "points too" : "never failed");

    static distinct dist[64];
    size_t ndist = 0;
    unsigned runs = 0, failures = 0;
    for (int pass = 1; pass <= 2; ++pass) {
        if (only_pass && pass != only_pass)
            continue;
        for (size_t ki = 0; ki < nks; ++ki) {
            const unsigned long this_k = ks[ki];
            run_result rr;
            run_child(fn, &base, this_k, pass == 2, fail_gmp, &rr);
            ++runs;
            const char *ph = rr.have_inject ? rr.inject.phase : "?";
            if (rr.kind == K_NONE && verbose)
                printf("ok   %s pass %d k=%lu phase '%s': %s%s%s\n", name, pass, this_k, ph,
                       rr.done.nomem ? "documented failure at '" : "same result",
                       rr.done.nomem ? rr.done.nomem_phase : "", rr.done.nomem ? "'" : "");
            if (rr.kind != K_NONE)
                printf("FAIL %s pass %d (%s) k=%lu phase '%s': %s%s%s\n", name, pass,
                       pass == 1 ? "this point fails" : "every point from it fails", this_k,
                       ph, kind_names[rr.kind], rr.msg[0] ? ": " : "", rr.msg);
            if (rr.kind != K_NONE) {
                ++failures;
                if (rr.have_inject && (verbose || only_k))
                    print_stack(&rr.inject, "        ");
                char site[200] = "?";
                if (rr.have_inject)
                    site_name(&rr.inject, site, sizeof site);
                size_t d = 0;
                while (d < ndist && !(dist[d].kind == rr.kind && strcmp(dist[d].site, site) == 0))
                    ++d;
                if (d == ndist && ndist < sizeof dist / sizeof *dist) {
                    distinct *x = &dist[ndist++];
                    memset(x, 0, sizeof *x);
                    x->kind = rr.kind;
                    memcpy(x->site, site, sizeof x->site);
                    x->pass = pass;
                    x->k = this_k;
                    memcpy(x->phase, ph, sizeof x->phase - 1);
                    memcpy(x->msg, rr.msg, sizeof x->msg);
                    x->inject = rr.inject;
                    x->have_inject = rr.have_inject;
                }
                if (d < ndist)
                    dist[d].count++;
            }
        }
    }
    free(ks);
    printf("%s: %u runs, %u failed", name, runs, failures);
    if (ndist > 0)
        printf("; %zu distinct failures (kind and call site):", ndist);
    putchar('\n');
    for (size_t d = 0; d < ndist; ++d) {
        const distinct *x = &dist[d];
        printf("  [%zu] %s at %s, %u run%s; first: pass %d k=%lu phase '%s': %s\n", d + 1,
               kind_names[x->kind], x->site, x->count, x->count == 1 ? "" : "s", x->pass,
               x->k, x->phase, x->msg);
        if (x->have_inject)
            print_stack(&x->inject, "      ");
    }
    fflush(stdout);
    ck_assert_msg(failures == 0, "%s: %u of %u runs with failed allocations failed (%zu "
                  "distinct problems; see the output above)", name, failures, runs, ndist);
}

START_TEST(octree)
{
    check_part("octree", part_octree, false, true, ALL);
}
END_TEST

START_TEST(meshes)
{
    check_part("meshes", part_meshes, false, true, ALL);
}
END_TEST

START_TEST(readers)
{
    check_part("readers", part_readers, false, true, ALL);
}
END_TEST

START_TEST(surfaces)
{
    check_part("surfaces", part_surfaces, false, true, ALL);
}
END_TEST

START_TEST(scene)
{
    check_part("scene", part_scene, false, true, ALL);
}
END_TEST

START_TEST(world)
{
    char why[200];
    ck_assert_msg(world_exercised(&world_exact, why, sizeof why),
                  "the world part does not split, merge and collide: %s", why);
    printf("world: unfailed, %s\n", why);
    check_part("world", part_world, false, true, 600);
}
END_TEST

START_TEST(world_levels)
{
    check_part("world-levels", part_world_levels, false, true, 600);
}
END_TEST

START_TEST(objects)
{
    check_part("objects", part_objects, false, true, ALL);
}
END_TEST

START_TEST(collide)
{
    check_part("collide", part_collide, true, false, 300);
}
END_TEST

/* A test case of its own for each part, with time for its runs. */
static TCase *part_case(Suite *s, const char *name)
{
    return test_case(s, name, 300, NULL);
}

int main(void)
{
    const char *why = alloc_unavailable();
    if (why != NULL) {
        printf("skipped: %s\n", why);
        return 77;
    }
    allocator_init();
    write_files();
    Suite *s = suite_create("alloc");
    tcase_add_test(part_case(s, "octree"), octree);
    tcase_add_test(part_case(s, "meshes"), meshes);
    tcase_add_test(part_case(s, "readers"), readers);
    tcase_add_test(part_case(s, "surfaces"), surfaces);
    tcase_add_test(part_case(s, "scene"), scene);
    tcase_add_test(part_case(s, "world"), world);
    tcase_add_test(part_case(s, "world-levels"), world_levels);
    tcase_add_test(part_case(s, "objects"), objects);
    tcase_add_test(part_case(s, "collide"), collide);
    int rc = run_suite(s);
    remove_files();
    return rc;
}
