/* SPDX-License-Identifier: MIT */
/**
 * @file noctree.h
 * @brief Umbrella header: includes every public libnoctree header.
 */
#ifndef NOCTREE_H
#define NOCTREE_H

#include <noctree/version.h>
#include <noctree/octree.h>
#include <noctree/neighbor.h>

#endif /* NOCTREE_H */
