/* SPDX-License-Identifier: MIT */
/*
 * libFuzzer target: STL mesh files, ASCII and binary (noctMeshRead on a .stl
 * file). A file that fails must fail cleanly, naming itself; a mesh that
 * reads must be a valid solid: see fuzz_mesh.h.
 */
#define _POSIX_C_SOURCE 200809L
#include "fuzz_mesh.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_mesh_file("input.stl", data, size);
    return 0;
}
