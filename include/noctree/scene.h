/* SPDX-License-Identifier: MIT */
/**
 * @file noctree/scene.h
 * @brief Scenes: a world's parameters, meshes and objects, from a text file
 * or a built-in family.
 *
 * @defgroup noctree_scene Scenes
 * @brief Scene files (noctree-scene(5)) and the built-in families
 * (noctree-families(7), the @ref families "families page").
 *
 * A scene is read completely, and every line checked, before anything is
 * built: a file with an error anywhere yields an error naming the file,
 * the line and the problem, and nothing else. Reading checks everything
 * that building the world would reject, so a scene that reads builds
 * (memory permitting). A scene owns its meshes; a world built from it
 * borrows them, so destroy the world first.
 * @{
 */
#ifndef NOCTREE_SCENE_H
#define NOCTREE_SCENE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#include <noctree/export.h>
#include <noctree/status.h>
#include <noctree/world.h>

#ifdef __cplusplus
extern "C" {
#endif

/** @brief A parsed scene; opaque. */
typedef struct noctScene noctScene;

/**
 * @brief Read a scene file.
 * @param[in]  path  The file; mesh files it names are relative to its
 *                   folder.
 * @param[out] scene Receives the scene on success, NULL otherwise.
 * @param[out] err   Receives the details of a failure, or NULL; its
 *                   message starts with `path:line:` (just `path:` when
 *                   the file cannot be opened, has no objects, or no
 *                   memory is left to start reading it).
 * @pre @p path and @p scene are not NULL.
 * @post On #NOCT_OK, noctSceneBuild() fails for no reason in the file:
 *       only for want of memory, for parameters changed through
 *       noctSceneDef(), or (so unlikely that no case is known) for a
 *       rotation whose rounded vertices make a mesh degenerate. A
 *       direction is any finite vector other than zero, however large or
 *       small its components (the world normalizes it).
 * @return #NOCT_OK; #NOCT_ERR_IO if the file cannot be opened or read;
 *         #NOCT_ERR_NOMEM if memory runs out, opening and reading lines
 *         included (never a scene read short); #NOCT_ERR_PARSE for a
 *         syntax error or a NUL byte in a line; #NOCT_ERR_NONFINITE for a
 *         number that is not finite; #NOCT_ERR_INVALID for a value out of
 *         range, an unknown name, an object name given twice (the
 *         message names the line of the first), a scene without objects, or the walls
 *         effect without a container (named at the `effects` line that
 *         turns it on); #NOCT_ERR_TOO_LARGE for a position beyond
 *         #NOCT_MAX_COORDINATE or more than 2^31 objects; any status of
 *         the mesh readers and constructors.
 */
NOCT_API noctStatus noctSceneRead(const char *path, noctScene **scene,
                                  noctError *err);

/**
 * @brief Make a built-in scene family: `planes:K` (t_K), `gas:N`,
 *        `mixed:N`, `clusters:N`, `static:N`, `escape:N`, `bullets:N`,
 *        `notch:N`, `arms:K` or `keyframes:N`.
 *
 * - `planes:K` (K 0 to 1000) and `gas:N` (N 1 to 10^7): the report's
 *   test sets and a gas of oriented boxes, 200 steps with the default
 *   world parameters (gas with its container walls).
 * - `mixed:N`, `clusters:N`, `static:N` and `escape:N` (N 1 to 10^7):
 *   kinds of gas with boxes of sizes over a factor of 8, in dense
 *   clusters, nine in ten static, and escaping outward without walls.
 * - `bullets:N` (N 1 to 10^7): N objects of which one in ten is a thin
 *   plate flying fast enough to pass through others between two steps;
 *   `notch:N` (N 1 to 10^6): N non-convex prisms, each with a cube moving
 *   in its notch, near contact all the time.
 * - `arms:K` (K 1 to 8): two robot arms of K links each (box primitives,
 *   length 2) swinging at revolute joints in a bay of six static walls,
 *   with static boxes loose on its floor; every link follows a track with
 *   a keyframe at every tick (forward kinematics of its joints' angles,
 *   each a triangle wave between its limits), 240 steps, effects events
 *   and track. The arms meet only when both are stretched out. Filters
 *   keep walls from pairing with walls and the loose boxes, and links
 *   from pairing with their own arm's.
 * - `keyframes:N` (N 1 to 10^5): N boxes of random sizes moving through
 *   each other along tracks of 5 random keyframes (ticks 0, 50, ..., 200),
 *   200 steps, effects events and track.
 *
 * noctree-families(7) defines every family exactly.
 * @param[in]  spec  The family and its size.
 * @param[out] scene Receives the scene on success, NULL otherwise.
 * @param[out] err   Receives the details of a failure, or NULL.
 * @pre @p spec and @p scene are not NULL.
 * @post On #NOCT_OK, the scene, as noctSceneRead() would give it from the
 *       file noctSceneWrite() writes of it.
 * @return #NOCT_OK; #NOCT_ERR_INVALID for an unknown family or size;
 *         #NOCT_ERR_NOMEM.
 */
NOCT_API noctStatus noctSceneFamily(const char *spec, noctScene **scene,
                                    noctError *err);

/**
 * @brief Write a scene as a scene file (noctree-scene(5)).
 * @param[in]  scene The scene.
 * @param[in]  f     Where to write it, open for writing.
 * @param[out] err   Receives the details of a failure, or NULL.
 * @pre @p scene and @p f are not NULL.
 * @post On #NOCT_OK, f holds a file from which noctSceneRead() gives the
 *       same scene: the world parameters as noctSceneDef() has them now,
 *       the steps, every mesh (a mesh read from a file by the path it was
 *       opened by), object, key and family, every number written so that
 *       it reads back bit for bit (rotations as the axis and degrees they
 *       were given by, so that they make the same quaternions; keys'
 *       turns as turns), the objects' margins and names, the `ignore`
 *       lines and `ignore initial` included.
 * @return #NOCT_OK, or #NOCT_ERR_IO if writing failed (the message says
 *         why).
 */
NOCT_API noctStatus noctSceneWrite(const noctScene *scene, FILE *f, noctError *err);

/**
 * @brief Destroy a scene and its meshes.
 * @param[in] scene A scene, or NULL.
 */
NOCT_API void noctSceneDestroy(noctScene *scene);

/**
 * @brief The scene's world parameters, which a caller may adjust before
 *        noctSceneBuild().
 * @param[in] scene A scene.
 * @pre @p scene is not NULL.
 * @return A pointer into the scene.
 */
NOCT_API noctWorldDef *noctSceneDef(noctScene *scene);

/**
 * @brief The number of steps the scene asks for.
 * @param[in] scene A scene.
 * @pre @p scene is not NULL.
 * @return The step count (default 200).
 */
NOCT_API int noctSceneSteps(const noctScene *scene);

/**
 * @brief Build a world from the scene.
 *
 * The world gets the scene's objects and their tracks
 * (noctWorldSetTrackTurns() for keys with turns), then the pairs of its
 * `ignore NAME NAME` lines are ignored (noctWorldIgnorePair()), and last,
 * with `ignore initial` (noctSceneSetIgnoreInitial()), the pairs touching
 * (noctWorldIgnoreTouching()).
 * @param[in]  scene The scene; must outlive the world.
 * @param[out] world Receives the new world on success, NULL otherwise.
 * @param[out] err   Receives the details of a failure, or NULL.
 * @pre @p scene and @p world are not NULL.
 * @return #NOCT_OK; #NOCT_ERR_NOMEM; for parameters changed through
 *         noctSceneDef(), any status of noctWorldCreate(). (For a scene
 *         from noctSceneRead() or noctSceneFamily(), nothing else of
 *         noctWorldAdd() and the family builders can fail.)
 */
NOCT_API noctStatus noctSceneBuild(const noctScene *scene, noctWorld **world,
                                   noctError *err);

/**
 * @brief Make the worlds built from the scene ignore, or not, the pairs
 *        touching at the start (noctree-scene(5): `ignore initial`).
 *
 * With it, noctSceneBuild() calls noctWorldIgnoreTouching() on the world
 * it built, after its objects, tracks and `ignore NAME NAME` lines: the
 * steps report only the contacts that begin after the start.
 * @param[in] scene  A scene.
 * @param[in] ignore Whether to ignore them.
 * @pre @p scene is not NULL.
 * @post noctSceneIgnoresInitial(scene) == ignore, and noctSceneWrite()
 *       writes the line when it is true.
 */
NOCT_API void noctSceneSetIgnoreInitial(noctScene *scene, bool ignore);

/**
 * @brief Does the scene ignore the pairs touching at the start?
 * @param[in] scene A scene.
 * @pre @p scene is not NULL.
 * @return Whether it does (`ignore initial`, noctSceneSetIgnoreInitial()).
 */
NOCT_API bool noctSceneIgnoresInitial(const noctScene *scene);

/** Longest object name, in bytes (noctree-scene(5), `name`). */
#define NOCT_SCENE_NAME_MAX 64

/**
 * @brief How many objects a world built from the scene holds.
 *
 * noctSceneBuild() adds the objects of the scene's families first (in
 * the order of their lines), then those of its object lines, in order: an
 * object's index here is its handle's index in a world just built from it.
 * @param[in] scene A scene.
 * @pre @p scene is not NULL.
 * @return The number of objects.
 */
NOCT_API size_t noctSceneObjectCount(const noctScene *scene);

/**
 * @brief An object's name (noctree-scene(5): an object line's `name`).
 *
 * Names are unique within a scene, 1 to #NOCT_SCENE_NAME_MAX bytes of
 * ASCII letters, digits, `_`, `-` and `.`, the first a letter or `_` (so
 * a name is never a number).
 * @param[in] scene A scene.
 * @param[in] index The object, numbered as noctSceneObjectCount() says.
 * @pre @p scene is not NULL.
 * @return Its name, valid while the scene is; NULL for an object without
 *         one (a family's, or a line without `name`) or an index out of
 *         range.
 */
NOCT_API const char *noctSceneObjectName(const noctScene *scene, size_t index);

/**
 * @brief Find an object by its name.
 * @param[in]  scene A scene.
 * @param[in]  name  The name (compared byte for byte).
 * @param[out] index Receives the object's index (as noctSceneObjectName()
 *                   numbers them) when it is found; untouched otherwise.
 * @pre @p scene, @p name and @p index are not NULL.
 * @post Finding takes time independent of the number of objects (a hash
 *       table made as the scene was read).
 * @return Whether an object has that name.
 */
NOCT_API bool noctSceneFindObject(const noctScene *scene, const char *name, size_t *index);

#ifdef __cplusplus
}
#endif

/** @} */
#endif /* NOCTREE_SCENE_H */
