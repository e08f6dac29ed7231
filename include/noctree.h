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
#include <noctree/status.h>
#include <noctree/mesh.h>
#include <noctree/transform.h>
#include <noctree/narrowphase.h>
#include <noctree/broadphase.h>
#include <noctree/world.h>
#include <noctree/query.h>
#include <noctree/scene.h>

#endif /* NOCTREE_H */
