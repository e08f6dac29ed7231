/* SPDX-License-Identifier: MIT */
/*
 * noctree-mesh: inspect mesh files (OFF, OBJ, STL, PLY and, with assimp,
 * glTF and the rest) and say whether each is a solid libnoctree takes,
 * and if not why; optionally repair one and write it as OFF.
 */
#include "config.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <noctree/mesh.h>

#include "toolutil.h"

static const char usage[] =
    "usage: noctree-mesh [OPTIONS] FILE...\n"
    "Read each mesh file, weld its vertices (exactly, or within --weld-tolerance),\n"
    "and print what it is: counts, edges, components, orientation, volume, and\n"
    "whether it is a closed solid noctree reads (noctMeshRead), or why not, and\n"
    "whether it loads as a surface (noctMeshReadSurface).\n"
    "\n"
    "  --weld-tolerance EPS  merge vertices whose coordinates each differ by at\n"
    "                        most EPS, transitively (default 0: only vertices\n"
    "                        with equal coordinates)\n"
    "  --repair              also remove duplicate polygons and orient each\n"
    "                        component consistently, outwards if closed; the\n"
    "                        inspection is of the repaired mesh\n"
    "  --output OUT.off      write the welded (and repaired) mesh as OFF (one FILE)\n"
    "  --help                this text\n"
    "  --version             the version\n"
    "\n"
    "Exit status: 0 if every file is a solid, 1 if one is not, 2 for bad usage or\n"
    "a file that cannot be read (the message names the file and line).\n";

static const char *yes(bool b)
{
    return b ? "yes" : "no";
}

static void print_edges(const char *what, size_t n, uint32_t (*first)[2], const size_t *uses)
{
    printf("%s edges: %zu", what, n);
    for (size_t i = 0; i < n && i < NOCT_MESH_REPORT_FIRST; ++i) {
        printf("%s %u-%u", i == 0 ? " (first" : ",", first[i][0], first[i][1]);
        if (uses != NULL)
            printf(" used %zu times", uses[i]);
    }
    printf("%s\n", n > 0 ? ")" : "");
}

/* 0 solid, 1 not, 2 error. */
static int one_file(const char *path, double eps, bool repair, const char *output)
{
    noctMeshData *d;
    noctError err;
    if (noctMeshDataRead(path, &d, &err) != NOCT_OK) {
        tool_error("%s", err.message);
        return 2;
    }
    noctMeshRepairReport rr = {0, 0, 0, 0, 0};
    noctStatus st = repair ? noctMeshDataRepair(d, eps, &rr, &err)
                           : noctMeshDataWeld(d, eps, NULL, &err);
    noctMeshReport r;
    if (st == NOCT_OK)
        st = noctMeshDataInspect(d, &r, &err);
    if (st == NOCT_OK && output != NULL)
        st = noctMeshDataWriteOff(d, output, &err);
    /* whether it loads as a surface (noctMeshReadSurface()), and if not why */
    noctError serr = {0};
    noctMesh *surface = NULL;
    noctStatus sst = NOCT_OK;
    if (st == NOCT_OK) {
        sst = noctMeshCreateSurfaceFromData(d, &surface, &serr);
        noctMeshDestroy(surface);
        if (sst == NOCT_ERR_NOMEM) {
            st = sst;
            err = serr;
        }
    }
    noctMeshDataDestroy(d);
    if (st != NOCT_OK) {
        tool_error("%s: %s", path, err.message);
        return 2;
    }
    char vol[32];
    printf("file: %s\n", path);
    printf("vertices: %zu\n", r.vertices);
    printf("welded vertices: %zu\n", r.welded_vertices);
    printf("unused vertices: %zu\n", r.unused_vertices);
    printf("polygons: %zu\n", r.polygons);
    printf("triangles: %zu\n", r.triangles);
    printf("dropped polygons: %zu\n", r.dropped_polygons);
    printf("duplicate polygons: %zu\n", r.duplicate_polygons);
    printf("skipped points and lines: %zu\n", r.skipped_primitives);
    if (repair)
        printf("repaired: %zu duplicates removed, %zu polygons flipped, %zu unorientable "
               "components\n", rr.removed_duplicates, rr.flipped_polygons,
               rr.unorientable_components);
    printf("edges: %zu\n", r.edges);
    print_edges("boundary", r.boundary_edges, r.boundary_first, NULL);
    print_edges("non-manifold", r.nonmanifold_edges, r.nonmanifold_first, r.nonmanifold_uses);
    print_edges("misoriented", r.misoriented_edges, r.misoriented_first, NULL);
    printf("components: %zu\n", r.components);
    printf("closed: %s\n", yes(r.closed));
    printf("orientable: %s\n", yes(r.orientable));
    printf("oriented: %s\n", yes(r.oriented));
    if (r.has_volume)
        printf("volume: %s\n", tool_format_double(r.volume, vol));
    else
        printf("volume: none (not closed and oriented)\n");
    if (r.solid)
        printf("solid: yes\n");
    else
        printf("solid: no: %s\n", r.reason);
    if (sst != NOCT_OK)
        printf("surface: no: %s\n", serr.message);
    else if (r.solid)
        printf("surface: yes\n");
    else
        printf("surface: yes: it loads as a surface (noctMeshReadSurface(), or 'surface' "
               "after a scene file's mesh)\n");
    return r.solid ? 0 : 1;
}

int main(int argc, char **argv)
{
    tool_name = "noctree-mesh";
    double eps = 0;
    bool repair = false;
    const char *output = NULL;
    int first = argc, nfiles = 0;
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i];
        if (tool_help_or_version(a, usage))
            return 0;
        if (strcmp(a, "--weld-tolerance") == 0 && i + 1 < argc) {
            if (!tool_parse_double(argv[++i], 0, 1e100, &eps))
                return tool_usage_error("--weld-tolerance must be a number >= 0, not '%s'",
                                        argv[i]);
        } else if (strcmp(a, "--repair") == 0) {
            repair = true;
        } else if (strcmp(a, "--output") == 0 && i + 1 < argc) {
            output = argv[++i];
        } else if (strcmp(a, "--") == 0) {
            first = first < i + 1 ? first : i + 1;
            nfiles += argc - i - 1;
            break;
        } else if (a[0] == '-' && a[1] != '\0') {
            return tool_usage_error("unknown option or missing value: '%s'", a);
        } else {
            first = first < i ? first : i;
            ++nfiles;
        }
    }
    if (nfiles == 0)
        return tool_usage_error("give at least one mesh file");
    if (output != NULL && nfiles != 1)
        return tool_usage_error("--output takes one mesh file, not %d", nfiles);
    int status = 0, printed = 0;
    bool options_done = false;
    for (int i = first; i < argc; ++i) {
        const char *a = argv[i];
        if (!options_done && strcmp(a, "--") == 0) {
            options_done = true;
            continue;
        }
        if (!options_done && (strcmp(a, "--weld-tolerance") == 0 || strcmp(a, "--output") == 0)) {
            ++i;
            continue;
        }
        if (!options_done && a[0] == '-' && a[1] != '\0')
            continue;
        if (printed++ > 0)
            printf("\n");
        fflush(stdout);
        int s = one_file(a, eps, repair, output);
        status = s > status ? s : status;
    }
    return status;
}
