/* SPDX-License-Identifier: MIT */
/*
 * Check suite for the file readers: scene files (scene.h) and the OFF and
 * OBJ mesh readers (mesh.h), on what the other suites leave out:
 *  - a NUL byte in a line is an error naming the file and the line, not
 *    the silent end of that line;
 *  - a scene that reads is a scene that builds: what noctSceneBuild()
 *    would reject is reported at read time, at a line;
 *  - directions of any finite non-zero size are directions;
 *  - running out of memory while reading is NOCT_ERR_NOMEM, never a file
 *    read short with NOCT_OK: allocations are made to fail by the tests'
 *    allocator, testalloc.h (glibc only; skipped, saying so, under
 *    AddressSanitizer and wherever the interposition is not in force).
 * The oracles are the files' own contents: the line each was built to
 * fail at, and the objects and vertices it lists.
 */
#define _GNU_SOURCE /* getline */
#include <check.h>
#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <noctree/mesh.h>
#include <noctree/scene.h>
#include <noctree/world.h>

#include "testalloc.h"
#include "testutil.h"

/* ---- an allocator that fails on demand (testalloc.h) ------------------------------ */

/* Allocations counted while armed; the fail_nth-th of them fails (1 is the
 * first; 0 never), and so does every one larger than fail_above (SIZE_MAX:
 * none). */
static void alloc_arm(unsigned long fail_nth, size_t fail_above)
{
    alloc_begin(&(alloc_plan){.fail_at = fail_nth,
                              .fail_above = fail_above == SIZE_MAX ? 0 : fail_above});
}

static void alloc_disarm(void)
{
    alloc_end();
}

/* Whether the tests' allocator is the one the program and the library
 * call: not under AddressSanitizer, nor where a tool (valgrind) replaces
 * malloc in the executable too. Says why when it is not. */
static bool interposed(void)
{
    const char *why = alloc_unavailable();
    if (why != NULL)
        fprintf(stderr, "check-readers: %s: allocation failure tests skipped\n", why);
    return why == NULL;
}

/* ---- files ------------------------------------------------------------------------ */

/* Files are written to a fresh directory of this process, removed at exit. */
static char tmp_dir[64];
static char tmp_files[256][160]; /* every file of a run without fork(), as under valgrind */
static size_t tmp_count;

static void remove_temp(void)
{
    for (size_t i = 0; i < tmp_count; ++i) {
        if (unlink(tmp_files[i]) != 0)
            rmdir(tmp_files[i]);
    }
    rmdir(tmp_dir);
}

static const char *temp_path(const char *name)
{
    if (tmp_dir[0] == '\0') {
        strcpy(tmp_dir, "/tmp/noct-readers-XXXXXX");
        ck_assert_ptr_nonnull(mkdtemp(tmp_dir));
        atexit(remove_temp);
    }
    ck_assert_uint_lt(tmp_count, sizeof tmp_files / sizeof *tmp_files);
    char *path = tmp_files[tmp_count++];
    snprintf(path, sizeof tmp_files[0], "%s/%s", tmp_dir, name);
    return path;
}

/* Write len bytes (NULs included) to a new file called name; returns its
 * path. */
static const char *write_bytes(const char *name, const char *data, size_t len)
{
    const char *path = temp_path(name);
    FILE *f = fopen(path, "wb");
    ck_assert_ptr_nonnull(f);
    ck_assert_uint_eq(fwrite(data, 1, len, f), len);
    ck_assert_int_eq(fclose(f), 0);
    return path;
}

static const char *write_text(const char *name, const char *text)
{
    return write_bytes(name, text, strlen(text));
}

/* The message must name this path and line: "path:line:". */
static void expect_at(const noctError *err, const char *path, long line)
{
    char where[200];
    snprintf(where, sizeof where, "%s:%ld:", path, line);
    ck_assert_msg(strncmp(err->message, where, strlen(where)) == 0,
                  "message '%s' does not start with '%s'", err->message, where);
    ck_assert_int_eq(err->line, line);
}

static const char CUBE_OFF[] =
    "OFF\n"
    "8 6 12\n"
    "0 0 0\n0 0 1\n0 1 0\n0 1 1\n1 0 0\n1 0 1\n1 1 0\n1 1 1\n"
    "4 0 1 3 2\n4 4 6 7 5\n4 0 4 5 1\n4 2 3 7 6\n4 0 2 6 4\n4 1 5 7 3\n";

/* Tetrahedra: unlike the cubes, whose coplanar corners take the exact
 * predicates to GMP (which aborts when it finds no memory), their checks
 * are decided in floating point, so only the readers' own allocations and
 * the mesh's fail. */
static const char TET_OFF[] = "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                              "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";
static const char TET_OBJ[] = "# tetrahedron\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                              "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n";

static const char CUBE_OBJ[] =
    "v 0 0 0\nv 0 0 1\nv 0 1 0\nv 0 1 1\nv 1 0 0\nv 1 0 1\nv 1 1 0\nv 1 1 1\n"
    "f 1 2 4 3\nf 5 7 8 6\nf 1 5 6 2\nf 3 4 8 7\nf 1 3 7 5\nf 2 6 8 4\n";

/* Read and build the scene at path, into *sc and its world, or fail the
 * test. */
static noctWorld *read_and_build(const char *path, noctScene **sc)
{
    noctError err = {0};
    noctStatus st = noctSceneRead(path, sc, &err);
    ck_assert_msg(st == NOCT_OK, "%s: %s", noctStatusString(st), err.message);
    noctWorld *w;
    st = noctSceneBuild(*sc, &w, &err);
    ck_assert_msg(st == NOCT_OK, "build: %s: %s", noctStatusString(st), err.message);
    return w;
}

/* Read and build a scene; returns the number of objects of its world, or
 * fails the test. */
static size_t build_count(const char *path)
{
    noctScene *sc;
    noctWorld *w = read_and_build(path, &sc);
    size_t n = noctWorldObjectCount(w);
    noctWorldDestroy(w);
    noctSceneDestroy(sc);
    return n;
}

/* Expect a scene file (scene) or a mesh file to fail reading with status
 * at line, its message holding what, and no scene or mesh made. */
static void expect_failure(bool scene, const char *name, const char *text, size_t len,
                           noctStatus want, long line, const char *what)
{
    const char *path = write_bytes(name, text, len);
    noctScene *sc = (noctScene *)1;
    noctMesh *m = (noctMesh *)1;
    noctError err = {0};
    noctStatus st = scene ? noctSceneRead(path, &sc, &err) : noctMeshRead(path, &m, &err);
    ck_assert_msg(st == want, "%s: got %s (%s), want %s", name, noctStatusString(st),
                  err.message, noctStatusString(want));
    ck_assert_ptr_null(scene ? (void *)sc : (void *)m);
    expect_at(&err, path, line);
    ck_assert_msg(strstr(err.message, what) != NULL, "'%s' lacks '%s'", err.message,
                  what);
}

static void expect_scene(const char *name, const char *text, size_t len, noctStatus want,
                         long line, const char *what)
{
    expect_failure(true, name, text, len, want, line, what);
}

static void expect_mesh(const char *name, const char *text, size_t len, noctStatus want,
                        long line, const char *what)
{
    expect_failure(false, name, text, len, want, line, what);
}

/* ---- NUL bytes ------------------------------------------------------------------ */

/* Each file would read without error if the line ended at its NUL: the
 * rest of the line (which the readers used to drop) is what the file
 * says, so reading it short would be wrong. */
START_TEST(nul_byte_in_scene)
{
    static const char scene[] = "mesh a box 1 1 1\n"
                                "object a 0 0 0\0 1 0 0 0.5\n"
                                "object a 5 0 0\n";
    expect_scene("nul.scene", scene, sizeof scene - 1, NOCT_ERR_PARSE, 2,
                 "NUL byte in line");
    /* In a comment too: the line is still not what the file says. */
    static const char comment[] = "mesh a box 1 1 1 # a\0b\nobject a 0 0 0\n";
    expect_scene("nul-comment.scene", comment, sizeof comment - 1, NOCT_ERR_PARSE, 1,
                 "NUL byte in line");
    /* The last line, without a newline. */
    static const char last[] = "mesh a box 1 1 1\nobject a 0 0 0\0";
    expect_scene("nul-last.scene", last, sizeof last - 1, NOCT_ERR_PARSE, 2,
                 "NUL byte in line");
}
END_TEST

START_TEST(nul_byte_in_off)
{
    char off[sizeof CUBE_OFF + 8];
    size_t len = sizeof CUBE_OFF - 1;
    memcpy(off, CUBE_OFF, sizeof CUBE_OFF);
    /* line 4 is "0 0 1": make it "0 0 1\0 5" */
    char *at = strstr(off, "0 0 1\n") + 5;
    memmove(at + 3, at, (size_t)(off + len - at) + 1);
    memcpy(at, "\0 5", 3);
    expect_mesh("nul.off", off, len + 3, NOCT_ERR_PARSE, 4, "NUL byte in line");
    /* in the colour part of a face line, which the reader otherwise skips */
    memcpy(off, CUBE_OFF, sizeof CUBE_OFF);
    at = strstr(off, "4 1 5 7 3\n") + 9;
    memcpy(at, " 1\0 2\n", 6);
    expect_mesh("nul-face.off", off, (size_t)(at - off) + 6, NOCT_ERR_PARSE, 16,
                "NUL byte in line");
}
END_TEST

START_TEST(nul_byte_in_obj)
{
    char obj[sizeof CUBE_OBJ + 16];
    memcpy(obj, CUBE_OBJ, sizeof CUBE_OBJ);
    size_t len = sizeof CUBE_OBJ - 1;
    /* the last face line "f 2 6 8 4" gets "\0 l 1 2" before its newline */
    memcpy(obj + len - 1, "\0 l 1 2\n", 8);
    expect_mesh("nul.obj", obj, len + 7, NOCT_ERR_PARSE, 14, "NUL byte in line");
    /* a NUL alone on a line between statements */
    memcpy(obj, "v 0 0 0\n\0\nv 1 0 0\n", 18);
    expect_mesh("nul-line.obj", obj, 18, NOCT_ERR_PARSE, 2, "NUL byte in line");
}
END_TEST

/* A mesh file with a NUL, named by a scene: both files and lines. */
START_TEST(nul_byte_in_scene_mesh)
{
    static const char obj[] = "v 0 0 0\nv 1 0 0\0\n";
    const char *mpath = write_bytes("nul-mesh.obj", obj, sizeof obj - 1);
    const char *spath = write_text("nul-mesh.scene", "N 2\nmesh m file nul-mesh.obj\n"
                                                     "object m 0 0 0\n");
    noctScene *sc = (noctScene *)1;
    noctError err = {0};
    ck_assert_int_eq(noctSceneRead(spath, &sc, &err), NOCT_ERR_PARSE);
    ck_assert_ptr_null(sc);
    expect_at(&err, spath, 2);
    char inner[200];
    snprintf(inner, sizeof inner, "%s:2: NUL byte in line", mpath);
    ck_assert_msg(strstr(err.message, inner) != NULL, "'%s' lacks '%s'", err.message,
                  inner);
}
END_TEST

/* ---- read errors ------------------------------------------------------------------ */

/* A directory opens for reading and fails at the first read (EISDIR). */
START_TEST(read_error_is_io)
{
    const char *dir = temp_path("dir.off");
    ck_assert_int_eq(mkdir(dir, 0700), 0);
    noctMesh *m = (noctMesh *)1;
    noctError err = {0};
    ck_assert_int_eq(noctMeshRead(dir, &m, &err), NOCT_ERR_IO);
    ck_assert_ptr_null(m);
    expect_at(&err, dir, 1);
    ck_assert_msg(strstr(err.message, "read error") != NULL, "%s", err.message);
    const char *sdir = temp_path("dir.scene");
    ck_assert_int_eq(mkdir(sdir, 0700), 0);
    noctScene *sc = (noctScene *)1;
    ck_assert_int_eq(noctSceneRead(sdir, &sc, &err), NOCT_ERR_IO);
    ck_assert_ptr_null(sc);
    expect_at(&err, sdir, 1);
}
END_TEST

/* ---- what building would reject, at read time ---------------------------------- */

START_TEST(walls_need_a_container)
{
    static const char *const body = "mesh a box 1 1 1\nobject a 0 0 0 1 0 0 0.1\n";
    char text[256];
    /* the effect on line 2, never a container: the error names line 2 */
    snprintf(text, sizeof text, "N 4\neffects motion walls\n%s", body);
    expect_scene("walls.scene", text, strlen(text), NOCT_ERR_INVALID, 2,
                 "the walls effect needs a container");
    /* a later effects line that turns them on again is the one named */
    snprintf(text, sizeof text, "effects walls\neffects motion\n%seffects walls events\n",
             body);
    expect_scene("walls2.scene", text, strlen(text), NOCT_ERR_INVALID, 5,
                 "the walls effect needs a container");
    /* a container before or after the effect line, or the effect turned
     * off again: these read, and build */
    snprintf(text, sizeof text, "effects motion walls\n%swalls -5 -5 -5 5 5 5\n", body);
    ck_assert_uint_eq(build_count(write_text("walls-after.scene", text)), 1);
    snprintf(text, sizeof text, "walls -5 -5 -5 5 5 5\neffects walls\n%s", body);
    ck_assert_uint_eq(build_count(write_text("walls-before.scene", text)), 1);
    snprintf(text, sizeof text, "effects walls\neffects motion events\n%s", body);
    ck_assert_uint_eq(build_count(write_text("walls-off.scene", text)), 1);
    snprintf(text, sizeof text, "walls 0 0 0 1 1 1\neffects none\n%s", body);
    ck_assert_uint_eq(build_count(write_text("walls-none.scene", text)), 1);
}
END_TEST

/* Every world parameter a scene can set, at its limits, reads and builds;
 * just beyond them, fails at its line. */
START_TEST(scene_limits)
{
    ck_assert_uint_eq(build_count(write_text("limits.scene",
        "N 1\nmax-depth 40\naccuracy box\nmaintenance rebuild\n"
        "effects motion events response walls substep\n"
        "walls -1e100 -1e100 -1e100 1e100 1e100 1e100\n"
        "mesh a box 1 1 1\nobject a 1e100 -1e100 0\nobject a -1e100 0 1e100 0 0 1 1e300\n"
        "family planes 0\nfamily gas 1\n")), 2 + 2 + 1);
    ck_assert_uint_eq(build_count(write_text("big.scene",
        "N big\nmax-depth 1\naccuracy convex\nmaintenance incremental\neffects none\n"
        "mesh a box 1 1 1\nobject a 0 0 0\n")), 1);
    static const struct {
        const char *text;
        noctStatus st;
        long line;
        const char *what;
    } bad[] = {
        {"mesh a box 1 1 1\nN 0\n", NOCT_ERR_INVALID, 2, "N must be at least 1"},
        {"N 2147483647\n", NOCT_ERR_INVALID, 1, "N must be"},
        {"max-depth 0\n", NOCT_ERR_INVALID, 1, "max-depth 0 is out of range"},
        {"max-depth 41\n", NOCT_ERR_INVALID, 1, "max-depth 41 is out of range"},
        {"accuracy perfect\n", NOCT_ERR_INVALID, 1, "unknown accuracy"},
        {"maintenance lazy\n", NOCT_ERR_INVALID, 1, "maintenance must be"},
        {"effects motion gravity\n", NOCT_ERR_INVALID, 1, "unknown effect 'gravity'"},
        {"walls 0 0 0 1 0 1\n", NOCT_ERR_INVALID, 1, "walls: each low coordinate"},
        {"walls 0 0 0 1 1 inf\n", NOCT_ERR_NONFINITE, 1, "not a finite number"},
        {"family planes 1001\n", NOCT_ERR_INVALID, 1, "out of range"},
        {"family gas 0\n", NOCT_ERR_INVALID, 1, "out of range"},
        {"family gas 10000001\n", NOCT_ERR_INVALID, 1, "out of range"},
        {"mesh a box 1 1 1\n\nobject a 0 1.1e100 0\n", NOCT_ERR_TOO_LARGE, 3,
         "coordinate limit"},
        {"mesh a box 1 1 1\nobject a 0 0 0 1 0 0 -1\n", NOCT_ERR_INVALID, 2,
         "negative speed"},
        {"mesh a box 1 1 1\nobject a 0 0 0 0 0 0 1\n", NOCT_ERR_INVALID, 2,
         "non-zero direction"},
        {"mesh a box 1 1 1\nobject a 0 0 0 -0 0 -0 1e-300\n", NOCT_ERR_INVALID, 2,
         "non-zero direction"},
        {"mesh a box 1 1 1\nobject a 0 0 0 1 0 0 1e309\n", NOCT_ERR_NONFINITE, 2,
         "not a finite number"},
        {"mesh a box 1 1 1\nobject b 0 0 0\n", NOCT_ERR_INVALID, 2, "unknown mesh 'b'"},
        {"mesh a box 1 1 1\nobject a 0 0 0 rotate 0 0 0 90\n", NOCT_ERR_INVALID, 2,
         "non-zero axis"},
        {"mesh a box 1 1 1\nobject a 0 0 0 rotate 1 0 0 nan\n", NOCT_ERR_NONFINITE, 2,
         "not a finite number"},
        {"mesh a box 1 1 1\nobject a 0 0 0 rotate 1 0 0\n", NOCT_ERR_PARSE, 2,
         "missing rotation axis and angle"},
        {"mesh a box 1 1 1\nobject a 0 0 0 velocity 1 inf 0\n", NOCT_ERR_NONFINITE, 2,
         "not a finite number"},
        {"mesh a box 1 1 1\nobject a 0 0 0 1 0 0 1 velocity 1 0 0\n", NOCT_ERR_PARSE, 2,
         "not both"},
        {"mesh a box 1 1 1\nobject a 0 0 0 velocity 1 0 0 velocity 1 0 0\n",
         NOCT_ERR_PARSE, 2, "given twice"},
        {"mesh a box 1 1 1\nobject a 0 0 0 type floating\n", NOCT_ERR_INVALID, 2,
         "unknown type 'floating'"},
        {"mesh a box 1 1 1\nobject a 0 0 0 filter 0 1\n", NOCT_ERR_INVALID, 2,
         "category of 0"},
        {"mesh a box 1 1 1\nobject a 0 0 0 filter 1 -1\n", NOCT_ERR_PARSE, 2,
         "mask: not a 64-bit"},
        {"mesh a box 1 1 1\nobject a 0 0 0 filter 1 0x10000000000000000\n", NOCT_ERR_PARSE,
         2, "mask: not a 64-bit"},
        {"mesh a box 1 1 1\nobject a 0 0 0 twirl 1 0 0\n", NOCT_ERR_PARSE, 2,
         "unexpected 'twirl'"},
        {"mesh a box 1 1 1\nobject a 0 0 0 spin 1 0 0\n", NOCT_ERR_PARSE, 2,
         "missing spin axis and angle"},
        {"mesh a box 1 1 1\nobject a 0 0 0 spin 0 0 0 10\n", NOCT_ERR_INVALID, 2,
         "a spin needs a non-zero axis"},
        {"mesh a box 1 1 1\nobject a 0 0 0 sensor sensor\n", NOCT_ERR_PARSE, 2,
         "'sensor' given twice"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof *bad; ++i) {
        char name[32];
        snprintf(name, sizeof name, "bad%zu.scene", i);
        expect_scene(name, bad[i].text, strlen(bad[i].text), bad[i].st, bad[i].line,
                     bad[i].what);
    }
}
END_TEST

/* Rotations, velocity vectors, types and filters reach the world. */
START_TEST(object_attributes)
{
    const char *path = write_text("attributes.scene",
        "effects motion events spin\nmesh a box 0.5 0.25 0.125\n"
        "object a 0 0 0 rotate 0 0 1 90 velocity 0.1 -0.2 0.3 filter 0x6 3\n"
        "object a 5 0 0 1 0 0 0.5 rotate 1 1 0 30 type kinematic\n"
        "object a 0 5 0 type static\n"
        "object a 0 0 5 velocity 1e-3 0 0 type moving sensor spin 0 0 1 90\n");
    noctScene *sc;
    noctWorld *w = read_and_build(path, &sc);
    ck_assert_uint_eq(noctWorldObjectCount(w), 4);
    noctObjectId id[4];
    for (uint32_t i = 0; i < 4; ++i)
        id[i] = (noctObjectId){i, 1};
    noctTransform x;
    double v[3], lo[3], hi[3];
    noctObjectType t;
    uint64_t cat, mask;
    /* a quarter turn about z: the box's x and y half-extents swap */
    ck_assert_int_eq(noctWorldGetTransform(w, id[0], &x), NOCT_OK);
    ck_assert(fabs(x.q.z - sqrt(0.5)) < 1e-16 && x.q.w == x.q.z && x.q.x == 0);
    ck_assert_int_eq(noctWorldObjectBox(w, id[0], lo, hi), NOCT_OK);
    ck_assert(lo[0] == -0.25 && hi[0] == 0.25 && lo[1] == -0.5 && hi[1] == 0.5);
    ck_assert_int_eq(noctWorldGetVelocity(w, id[0], v), NOCT_OK);
    ck_assert(v[0] == 0.1 && v[1] == -0.2 && v[2] == 0.3);
    ck_assert_int_eq(noctWorldGetFilter(w, id[0], &cat, &mask), NOCT_OK);
    ck_assert(cat == 6 && mask == 3);
    ck_assert_int_eq(noctWorldGetType(w, id[1], &t), NOCT_OK);
    ck_assert_int_eq(t, NOCT_OBJECT_KINEMATIC);
    ck_assert_int_eq(noctWorldGetVelocity(w, id[1], v), NOCT_OK);
    ck_assert(v[0] == 0.5 && v[1] == 0 && v[2] == 0); /* kept, not used */
    ck_assert_int_eq(noctWorldGetTransform(w, id[1], &x), NOCT_OK);
    ck_assert(fabs(x.q.w - cos(15 * 3.14159265358979323846 / 180)) < 1e-15);
    ck_assert_int_eq(noctWorldGetType(w, id[2], &t), NOCT_OK);
    ck_assert_int_eq(t, NOCT_OBJECT_STATIC);
    ck_assert_int_eq(noctWorldGetType(w, id[3], &t), NOCT_OK);
    ck_assert_int_eq(t, NOCT_OBJECT_MOVING);
    bool sensor;
    ck_assert_int_eq(noctWorldGetSensor(w, id[3], &sensor), NOCT_OK);
    ck_assert(sensor);
    ck_assert_int_eq(noctWorldGetSensor(w, id[2], &sensor), NOCT_OK);
    ck_assert(!sensor);
    /* a quarter turn a step about z: after one step, x and y swap */
    noctQuat spin;
    ck_assert_int_eq(noctWorldGetAngularVelocity(w, id[3], &spin), NOCT_OK);
    ck_assert(fabs(spin.z - sqrt(0.5)) < 1e-16 && spin.x == 0);
    /* 'mesh a box' is a box primitive */
    ck_assert(noctWorldGetMesh(w, id[0]) == NULL);
    ck_assert_int_eq(noctWorldGetHalfExtents(w, id[0], v), NOCT_OK);
    ck_assert(v[0] == 0.5 && v[1] == 0.25 && v[2] == 0.125);
    ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    ck_assert_int_eq(noctWorldGetTransform(w, id[0], &x), NOCT_OK);
    ck_assert(x.p[0] == 0.1 && x.p[1] == -0.2 && x.p[2] == 0.3);
    ck_assert_int_eq(noctWorldGetTransform(w, id[1], &x), NOCT_OK);
    ck_assert(x.p[0] == 5 && x.p[1] == 0); /* kinematic: not moved */
    ck_assert_int_eq(noctWorldObjectBox(w, id[3], lo, hi), NOCT_OK);
    ck_assert(hi[0] - lo[0] == 0.5 && hi[1] - lo[1] == 1); /* turned */
    ck_assert_int_eq(noctWorldValidate(w, NULL), NOCT_OK);
    noctWorldDestroy(w);
    noctSceneDestroy(sc);
}
END_TEST

/* noctree-scene(5): a filter word is "decimal, or hexadecimal with 0x":
 * a leading zero is not octal. */
START_TEST(filter_words_are_decimal)
{
    const char *path = write_text("decimal.scene",
                                  "mesh a box 0.5 0.5 0.5\nobject a 0 0 0 filter 010 08\n");
    noctScene *sc;
    noctError err = {0};
    noctStatus st = noctSceneRead(path, &sc, &err);
    ck_assert_msg(st == NOCT_OK, "%s: %s", noctStatusString(st), err.message);
    noctWorld *w;
    ck_assert_int_eq(noctSceneBuild(sc, &w, &err), NOCT_OK);
    uint64_t cat, mask;
    ck_assert_int_eq(noctWorldGetFilter(w, (noctObjectId){0, 1}, &cat, &mask), NOCT_OK);
    ck_assert_msg(cat == 10 && mask == 8, "filter 010 08 read as %llu %llu",
                  (unsigned long long)cat, (unsigned long long)mask);
    noctWorldDestroy(w);
    noctSceneDestroy(sc);
}
END_TEST

/* Directions are compared with the largest component taken out first:
 * (1e-200, 0, 0) is not zero, nor is (1e200, 0, 0) infinite. */
START_TEST(tiny_and_huge_directions)
{
    const char *path = write_text("directions.scene",
        "N 2\nmesh a box 0.5 0.5 0.5\n"
        "object a 0 0 0    1e-200 0 0 0.25\n"
        "object a 10 0 0   0 -1e200 0 0.25\n"
        "object a 0 10 0   0 0 4.9e-324 0.25\n"
        "object a 0 0 10   1e-200 -1e-200 0 0.25\n"
        "object a 10 10 10 1.5e308 1.5e308 1.5e308 0.25\n");
    noctScene *sc;
    noctWorld *w = read_and_build(path, &sc);
    ck_assert_uint_eq(noctWorldObjectCount(w), 5);
    const double h = sqrt(0.5), t = sqrt(1.0 / 3);
    const double want[5][3] = {{1, 0, 0}, {0, -1, 0}, {0, 0, 1}, {h, -h, 0}, {t, t, t}};
    for (uint32_t i = 0; i < 5; ++i) {
        noctObjectId id = {i, 1};
        double pos[3], dir[3];
        ck_assert_int_eq(noctWorldObject(w, id, pos, dir), NOCT_OK);
        for (int k = 0; k < 3; ++k)
            ck_assert_msg(fabs(dir[k] - want[i][k]) <= 1e-15, "object %u: direction "
                          "(%g, %g, %g)", i, dir[0], dir[1], dir[2]);
    }
    /* they move by speed 0.25 along those directions */
    ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    double pos[3];
    ck_assert_int_eq(noctWorldObject(w, (noctObjectId){0, 1}, pos, NULL), NOCT_OK);
    ck_assert(pos[0] == 0.25 && pos[1] == 0 && pos[2] == 0);
    ck_assert_int_eq(noctWorldObject(w, (noctObjectId){1, 1}, pos, NULL), NOCT_OK);
    ck_assert(pos[0] == 10 && pos[1] == -0.25 && pos[2] == 0);
    noctWorldDestroy(w);
    noctSceneDestroy(sc);
}
END_TEST

/* ---- running out of memory -------------------------------------------------------- */

/* A comment line of size bytes ("#xxx...\n"). */
static char *long_comment(size_t size)
{
    char *line = malloc(size + 1);
    ck_assert_ptr_nonnull(line);
    line[0] = '#';
    memset(line + 1, 'x', size - 2);
    line[size - 1] = '\n';
    line[size] = '\0';
    return line;
}

/* getline(3) grows its buffer for a 1 MiB line; with every allocation
 * above 64 KiB failing, it fails with ENOMEM, which the readers took for
 * the end of the file: the lines after it were dropped, and the file read
 * as OK (or as a file that ends too early). */
START_TEST(getline_nomem_is_nomem)
{
    if (!interposed())
        return;
    const size_t big = (size_t)1 << 20, limit = (size_t)1 << 16;
    char *comment = long_comment(big);
    size_t cap = big + 1024;
    char *text = malloc(cap);
    ck_assert_ptr_nonnull(text);

    snprintf(text, cap, "mesh a box 1 1 1\nobject a 0 0 0\n%sobject a 5 0 0\n", comment);
    const char *spath = write_text("long.scene", text);
    ck_assert_uint_eq(build_count(spath), 2); /* with memory, both objects */
    noctScene *sc = (noctScene *)1;
    noctError err = {0};
    alloc_arm(0, limit);
    noctStatus st = noctSceneRead(spath, &sc, &err);
    alloc_disarm();
    ck_assert_uint_gt(alloc_failures(), 0);
    ck_assert_msg(st == NOCT_ERR_NOMEM, "scene: got %s (%s)", noctStatusString(st),
                  err.message);
    ck_assert_ptr_null(sc);
    expect_at(&err, spath, 3);
    ck_assert_msg(strstr(err.message, "out of memory") != NULL, "%s", err.message);

    /* OFF: the comment among the vertices */
    const char *at = strstr(CUBE_OFF, "0 1 1\n");
    snprintf(text, cap, "%.*s%s%s", (int)(at - CUBE_OFF), CUBE_OFF, comment, at);
    const char *opath = write_text("long.off", text);
    noctMesh *m = NULL;
    ck_assert_int_eq(noctMeshRead(opath, &m, NULL), NOCT_OK);
    noctMeshDestroy(m);
    m = (noctMesh *)1;
    alloc_arm(0, limit);
    st = noctMeshRead(opath, &m, &err);
    alloc_disarm();
    ck_assert_msg(st == NOCT_ERR_NOMEM, "off: got %s (%s)", noctStatusString(st),
                  err.message);
    ck_assert_ptr_null(m);
    expect_at(&err, opath, 6);

    /* OBJ: the comment after the cube, before a line that is an error */
    snprintf(text, cap, "%s%sl 1 2\n", CUBE_OBJ, comment);
    const char *jpath = write_text("long.obj", text);
    ck_assert_int_eq(noctMeshRead(jpath, &m, &err), NOCT_ERR_PARSE);
    m = (noctMesh *)1;
    alloc_arm(0, limit);
    st = noctMeshRead(jpath, &m, &err);
    alloc_disarm();
    ck_assert_msg(st == NOCT_ERR_NOMEM, "obj: got %s (%s)", noctStatusString(st),
                  err.message);
    ck_assert_ptr_null(m);
    expect_at(&err, jpath, 15);
    free(text);
    free(comment);
}
END_TEST

/* Each allocation in turn fails, once, while a scene naming an OFF and an
 * OBJ file is read: the reading fails with NOCT_ERR_NOMEM (fopen's
 * included), or succeeds with the whole scene; nothing else. (No box
 * meshes: see TET_OFF.) */
START_TEST(every_allocation_failing)
{
    if (!interposed())
        return;
    write_text("tet.off", TET_OFF);
    write_text("tet.obj", TET_OBJ);
    const char *path = write_text("sweep.scene",
        "# two meshes, five objects\n"
        "N 2\nmesh off file tet.off\nmesh obj file tet.obj\n"
        "object obj 0 0 0\nobject off 3 0 0 1 0 0 0.1\nobject obj 6 0 0\n"
        "object off 9 0 0 name nine margin 0.5\nobject obj 12 0 0 0 1e-200 0 1 name twelve\n");
    ck_assert_uint_eq(build_count(path), 5);
    unsigned long nomem = 0, ok = 0;
    for (unsigned long n = 1;; ++n) {
        noctScene *sc = (noctScene *)1;
        noctError err = {0};
        alloc_arm(n, SIZE_MAX);
        noctStatus st = noctSceneRead(path, &sc, &err);
        alloc_disarm();
        bool failed = alloc_failures() > 0;
        if (st == NOCT_OK) {
            ++ok;
            noctWorld *w;
            ck_assert_int_eq(noctSceneBuild(sc, &w, &err), NOCT_OK);
            ck_assert_msg(noctWorldObjectCount(w) == 5, "allocation %lu failing: "
                          "read short", n);
            noctWorldDestroy(w);
            noctSceneDestroy(sc);
        } else {
            ck_assert_msg(st == NOCT_ERR_NOMEM && failed, "allocation %lu failing: %s (%s)",
                          n, noctStatusString(st), err.message);
            ck_assert_ptr_null(sc);
            ck_assert_msg(strstr(err.message, "out of memory") != NULL ||
                          strstr(err.message, "Cannot allocate memory") != NULL,
                          "allocation %lu failing: '%s'", n, err.message);
            ++nomem;
        }
        if (!failed)
            break; /* the read made fewer than n allocations: all were tried */
    }
    ck_assert_uint_gt(nomem, 10);
    ck_assert_uint_gt(ok, 0);
}
END_TEST

/* The same for each mesh format alone. */
START_TEST(every_allocation_failing_mesh)
{
    if (!interposed())
        return;
    const char *paths[2] = {write_text("each.off", TET_OFF),
                            write_text("each.obj", TET_OBJ)};
    for (int i = 0; i < 2; ++i) {
        unsigned long nomem = 0;
        for (unsigned long n = 1;; ++n) {
            noctMesh *m = (noctMesh *)1;
            noctError err = {0};
            alloc_arm(n, SIZE_MAX);
            noctStatus st = noctMeshRead(paths[i], &m, &err);
            alloc_disarm();
            bool failed = alloc_failures() > 0;
            if (st == NOCT_OK) {
                ck_assert_uint_eq(noctMeshVertexCount(m), 4);
                ck_assert_uint_eq(noctMeshTriangleCount(m), 4);
                noctMeshDestroy(m);
            } else {
                ck_assert_msg(st == NOCT_ERR_NOMEM && failed, "%s, allocation %lu "
                              "failing: %s (%s)", paths[i], n, noctStatusString(st),
                              err.message);
                ck_assert_ptr_null(m);
                ck_assert_msg(strncmp(err.message, paths[i], strlen(paths[i])) == 0,
                              "'%s' does not name the file", err.message);
                ++nomem;
            }
            if (!failed)
                break;
        }
        ck_assert_uint_gt(nomem, 3);
    }
}
END_TEST

/* ---- writing scenes back ------------------------------------------------------ */

/* The text noctSceneWrite() gives for sc (malloc'd). */
static char *written(const noctScene *sc)
{
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    ck_assert_ptr_nonnull(f);
    noctError err;
    ck_assert_int_eq(noctSceneWrite(sc, f, &err), NOCT_OK);
    ck_assert_int_eq(fclose(f), 0);
    return text;
}

/* Two scenes give the same objects, poses and colliding pairs at every
 * step. */
static void same_runs(const noctScene *a, const noctScene *b)
{
    ck_assert_int_eq(noctSceneSteps(a), noctSceneSteps(b));
    noctWorld *wa, *wb;
    noctError err;
    ck_assert_int_eq(noctSceneBuild(a, &wa, &err), NOCT_OK);
    ck_assert_int_eq(noctSceneBuild(b, &wb, &err), NOCT_OK);
    const size_t n = noctWorldObjectCount(wa);
    ck_assert_uint_eq(noctWorldObjectCount(wb), n);
    /* the same pairs ignored (scene files' ignore lines) */
    ck_assert(noctSceneIgnoresInitial(a) == noctSceneIgnoresInitial(b));
    for (uint32_t i = 0; i < n && n <= 200; ++i)
        for (uint32_t j = i + 1; j < n; ++j)
            ck_assert(noctWorldPairIgnored(wa, (noctObjectId){i, 1}, (noctObjectId){j, 1}) ==
                      noctWorldPairIgnored(wb, (noctObjectId){i, 1}, (noctObjectId){j, 1}));
    for (int step = 0; step < noctSceneSteps(a); ++step) {
        ck_assert_int_eq(noctWorldStep(wa, &err), NOCT_OK);
        ck_assert_int_eq(noctWorldStep(wb, &err), NOCT_OK);
        const noctPair *pa, *pb;
        size_t na = noctWorldColliding(wa, &pa), nb = noctWorldColliding(wb, &pb);
        ck_assert_uint_eq(na, nb);
        ck_assert(na == 0 || memcmp(pa, pb, na * sizeof *pa) == 0);
        na = noctWorldNear(wa, &pa);
        nb = noctWorldNear(wb, &pb);
        ck_assert_uint_eq(na, nb);
        ck_assert(na == 0 || memcmp(pa, pb, na * sizeof *pa) == 0);
        if (step % 37 == 0)
            for (uint32_t i = 0; i < n; ++i) {
                noctTransform xa, xb;
                ck_assert_int_eq(noctWorldGetTransform(wa, (noctObjectId){i, 1}, &xa), NOCT_OK);
                ck_assert_int_eq(noctWorldGetTransform(wb, (noctObjectId){i, 1}, &xb), NOCT_OK);
                ck_assert(memcmp(&xa, &xb, sizeof xa) == 0);
                double ma, mb;
                ck_assert_int_eq(noctWorldGetMargin(wa, (noctObjectId){i, 1}, &ma), NOCT_OK);
                ck_assert_int_eq(noctWorldGetMargin(wb, (noctObjectId){i, 1}, &mb), NOCT_OK);
                ck_assert(memcmp(&ma, &mb, sizeof ma) == 0);                const noctKeyTurn *ta, *tb;
                const size_t nt = noctWorldGetTrackTurns(wa, (noctObjectId){i, 1}, &ta);
                ck_assert_uint_eq(noctWorldGetTrackTurns(wb, (noctObjectId){i, 1}, &tb), nt);
                ck_assert(nt == 0 || memcmp(ta, tb, nt * sizeof *ta) == 0);
            }
    }
    noctWorldDestroy(wa);
    noctWorldDestroy(wb);
}

/* Every family, and a file with every statement and attribute, written
 * and read back: the same text when written again, and the same runs. */
START_TEST(scenes_written_read_back)
{
    const char *off = write_text("cube.off", CUBE_OFF);
    char text[2048];
    snprintf(text, sizeof text,
             "N big\nmax-depth 12\naccuracy continuous\nmaintenance rebuild\nsteps 60\nmargin 0.25\n"
             "walls -10 -10 -10 10 10 10\n"
             "mesh a box 0.5 0.25 0.125\nmesh f file %s\n"
             "object a 0 0 0 rotate 0 0 1 90 velocity 0.1 -0.2 0.3 filter 0x6 3\n"
             "object a 5 0 0 1 0 0 0.5 rotate 1 1 0 30 type kinematic\n"
             "object f 0.3 5 0 type static sensor name the.sensor\n"
             "object a 0 0 5 velocity 1e-3 0 0 type moving spin 0 0 1 7.5 margin 0.1\n"
             "object f 1 1 1 name _keyed-1 margin 1e-300\n"
             "key 0 1 1 1\nkey 7 2 1.5 1 rotate 0 1 0 33.3\nkey 20 -1 0 0\n"
             "key 30 -1 0 0 turn 0 0 1 270\nkey 31 -1 0 0 turn 1 1 0 -179.5\n"
             "ignore _keyed-1 the.sensor\nignore initial\n"
             "effects motion events response walls spin track\n",
             off);
    const char *path = write_text("all.scene", text);
    const char *const specs[] = {"arms:1",     "arms:3",       "keyframes:25", "gas:40",
                                 "mixed:40",   "clusters:40",  "static:40",    "escape:40",
                                 "planes:1",   "notch:5",      "bullets:30",   path};
    for (size_t i = 0; i < sizeof specs / sizeof *specs; ++i) {
        noctScene *a, *b;
        noctError err;
        noctStatus st = i + 1 < sizeof specs / sizeof *specs ? noctSceneFamily(specs[i], &a, &err)
                                                              : noctSceneRead(specs[i], &a, &err);
        ck_assert_msg(st == NOCT_OK, "%s: %s", specs[i], err.message);
        char *t1 = written(a);
        char name[32];
        snprintf(name, sizeof name, "written%zu.scene", i);
        const char *copy = write_text(name, t1);
        st = noctSceneRead(copy, &b, &err);
        ck_assert_msg(st == NOCT_OK, "%s written: %s", specs[i], err.message);
        char *t2 = written(b);
        ck_assert_msg(strcmp(t1, t2) == 0, "%s: written twice, not the same", specs[i]);
        if (specs[i] != path) /* the defaults, written as such */
            ck_assert_msg(strstr(t1, "N auto\nmax-depth auto\n") != NULL, "%s:\n%s", specs[i],
                          t1);
        if (specs[i] != path && strncmp(specs[i], "arms", 4) != 0 &&
            strncmp(specs[i], "keyframes", 9) != 0) { /* a family line */
            char line[48];
            snprintf(line, sizeof line, "family %.*s %s\n", (int)strcspn(specs[i], ":"),
                     specs[i], strchr(specs[i], ':') + 1);
            ck_assert_msg(strstr(t1, line) != NULL, "'%s' not in:\n%s", line, t1);
        }
        if (specs[i] == path) { /* every attribute, as given */
            static const char *const LINES[] = {
                "N big\n", "max-depth 12\n", "maintenance rebuild\n", "steps 60\n",
                "margin 0.25\n",
                "walls -10 -10 -10 10 10 10\n", "mesh a box 0.5 0.25 0.125\n",
                "object a 0 0 0 velocity 0.1 -0.2 0.3 rotate 0 0 1 90 type moving "
                "filter 0x6 0x3\n",
                "object a 5 0 0 1 0 0 0.5 rotate 1 1 0 30 type kinematic\n",
                "object f 0.3 5 0 type static sensor name the.sensor\n",
                " spin 0 0 1 7.5 margin 0.1\n",
                "object f 1 1 1 type kinematic margin 1e-300 name _keyed-1\n",
                "key 7 2 1.5 1 rotate 0 1 0 33.3\n",
                "key 20 -1 0 0\n", "key 30 -1 0 0 turn 0 0 1 270\n",
                "key 31 -1 0 0 turn 1 1 0 -179.5\n", "ignore _keyed-1 the.sensor\n",
                "ignore initial\n", "effects motion events response walls spin track\n"};
            for (size_t k = 0; k < sizeof LINES / sizeof *LINES; ++k)
                ck_assert_msg(strstr(t1, LINES[k]) != NULL, "'%s' not in:\n%s", LINES[k], t1);
        }
        ck_assert_uint_eq(noctSceneDef(a)->effects, noctSceneDef(b)->effects);
        ck_assert_uint_eq(noctSceneObjectCount(a), noctSceneObjectCount(b));
        for (size_t k = 0; k < noctSceneObjectCount(a); ++k) {
            const char *na = noctSceneObjectName(a, k), *nb = noctSceneObjectName(b, k);
            ck_assert((na == NULL) == (nb == NULL));
            ck_assert(na == NULL || strcmp(na, nb) == 0);
        }
        same_runs(a, b);
        free(t1);
        free(t2);
        noctSceneDestroy(a);
        noctSceneDestroy(b);
    }
    /* a failing stream: a status, not silence */
    noctScene *a;
    ck_assert_int_eq(noctSceneFamily("arms:2", &a, NULL), NOCT_OK);
    FILE *full = fopen("/dev/full", "w");
    if (full != NULL) {
        noctError err;
        ck_assert_int_eq(noctSceneWrite(a, full, &err), NOCT_ERR_IO);
        ck_assert_ptr_nonnull(strstr(err.message, "writing the scene"));
        fclose(full);
    }
    noctSceneDestroy(a);
}
END_TEST

/* Objects' margins and names: read, built, found; and every way to get
 * them wrong, at its line. */
START_TEST(object_margins_and_names)
{
    const char *path = write_text("names.scene",
        "mesh a box 0.5 0.5 0.5\n"
        "family planes 0\n" /* two objects first, without names */
        "object a 0 0 5 margin 0.25 name left\n"
        "object a 3 0 5 name Right_2.b-c\n"
        "object a 6 0 5 margin 1e100\n");
    noctScene *sc;
    noctWorld *w = read_and_build(path, &sc);
    ck_assert_uint_eq(noctSceneObjectCount(sc), 5);
    ck_assert_uint_eq(noctWorldObjectCount(w), 5);
    static const char *const NAMES[5] = {NULL, NULL, "left", "Right_2.b-c", NULL};
    static const double MARGINS[5] = {0, 0, 0.25, 0, 1e100};
    for (size_t i = 0; i < 5; ++i) {
        const char *n = noctSceneObjectName(sc, i);
        ck_assert(NAMES[i] == NULL ? n == NULL : n != NULL && strcmp(n, NAMES[i]) == 0);
        double m;
        ck_assert_int_eq(noctWorldGetMargin(w, (noctObjectId){(uint32_t)i, 1}, &m), NOCT_OK);
        ck_assert(m == MARGINS[i]);
        size_t at = 99;
        if (NAMES[i] != NULL) {
            ck_assert(noctSceneFindObject(sc, NAMES[i], &at));
            ck_assert_uint_eq(at, i);
        }
    }
    ck_assert_ptr_null(noctSceneObjectName(sc, 5));
    ck_assert_ptr_null(noctSceneObjectName(sc, SIZE_MAX));
    size_t at = 99;
    ck_assert(!noctSceneFindObject(sc, "right_2.b-c", &at)); /* case counts */
    ck_assert(!noctSceneFindObject(sc, "", &at));
    ck_assert_uint_eq(at, 99);
    /* the third object's skin reaches nothing 2 away; the fifth's, all */
    ck_assert_int_eq(noctWorldStep(w, NULL), NOCT_OK);
    const noctPair *p;
    ck_assert_uint_eq(noctWorldNear(w, &p), 4);
    noctWorldDestroy(w);
    noctSceneDestroy(sc);

    /* many names: every one found (the table grows) */
    char big[64 * 1024] = "mesh a box 0.5 0.5 0.5\n";
    size_t len = strlen(big);
    for (int i = 0; i < 1000; ++i)
        len += (size_t)snprintf(big + len, sizeof big - len, "object a %d 0 0 name o%d\n", 2 * i,
                                i);
    path = write_text("many.scene", big);
    ck_assert_int_eq(noctSceneRead(path, &sc, NULL), NOCT_OK);
    for (int i = 0; i < 1000; ++i) {
        char n[16];
        snprintf(n, sizeof n, "o%d", i);
        ck_assert(noctSceneFindObject(sc, n, &at));
        ck_assert_uint_eq(at, (size_t)i);
    }
    noctSceneDestroy(sc);

    static const char M[] = "mesh a box 1 1 1\n";
    char text[512];
    struct {
        const char *line;
        noctStatus st;
        long at;
        const char *what;
    } const BAD[] = {
        {"object a 0 0 0 margin nan\n", NOCT_ERR_NONFINITE, 2, "not a finite number"},
        {"object a 0 0 0 margin inf\n", NOCT_ERR_NONFINITE, 2, "not a finite number"},
        {"object a 0 0 0 margin -0.5\n", NOCT_ERR_INVALID, 2, "margin -0.5: it must be 0 to"},
        {"object a 0 0 0 margin 2e100\n", NOCT_ERR_INVALID, 2, "it must be 0 to"},
        {"object a 0 0 0 margin\n", NOCT_ERR_PARSE, 2, "missing margin"},
        {"object a 0 0 0 margin 1 margin 1\n", NOCT_ERR_PARSE, 2, "'margin' given twice"},
        {"object a 0 0 0 name\n", NOCT_ERR_PARSE, 2, "missing the object's name"},
        {"object a 0 0 0 name 7up\n", NOCT_ERR_INVALID, 2, "bad object name '7up'"},
        {"object a 0 0 0 name a/b\n", NOCT_ERR_INVALID, 2, "bad object name 'a/b'"},
        {"object a 0 0 0 name x name y\n", NOCT_ERR_PARSE, 2, "'name' given twice"},
        {"object a 0 0 0 name x\nobject a 1 0 0\n\nobject a 0 0 0 name x\n", NOCT_ERR_INVALID,
         5, "object name 'x' is taken (line 2)"},
        {"object a 0 0 0 name "
         "a1234567890123456789012345678901234567890123456789012345678901234\n",
         NOCT_ERR_INVALID, 2, "bad object name"},
    };
    for (size_t i = 0; i < sizeof BAD / sizeof *BAD; ++i) {
        snprintf(text, sizeof text, "%s%s", M, BAD[i].line);
        char name[32];
        snprintf(name, sizeof name, "bad%zu.scene", i);
        expect_scene(name, text, strlen(text), BAD[i].st, BAD[i].at, BAD[i].what);
    }
    /* 64 bytes is the longest name */
    snprintf(text, sizeof text, "%sobject a 0 0 0 name "
             "a123456789012345678901234567890123456789012345678901234567890123\n", M);
    ck_assert_uint_eq(build_count(write_text("long.scene", text)), 1);
}
END_TEST

static Suite *readers_suite(void)
{
    Suite *s = suite_create("readers");
    TCase *tc = test_case(s, "NUL bytes and read errors", 0, NULL);
    add_tests(tc, nul_byte_in_scene, nul_byte_in_off, nul_byte_in_obj, nul_byte_in_scene_mesh,
              read_error_is_io);

    tc = test_case(s, "read what builds", 0, NULL);
    add_tests(tc, walls_need_a_container, scene_limits, tiny_and_huge_directions, object_attributes,
              filter_words_are_decimal, scenes_written_read_back, object_margins_and_names);

    tc = test_case(s, "out of memory", 120, NULL);
    add_tests(tc, getline_nomem_is_nomem, every_allocation_failing, every_allocation_failing_mesh);
    return s;
}

int main(void)
{
    return run_suite(readers_suite());
}
