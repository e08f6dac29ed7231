/* SPDX-License-Identifier: MIT */
/**
 * @file noctree/scene.h
 * @brief Scenes: a world's parameters, meshes and objects, from a text file
 * or a built-in family.
 *
 * @defgroup noctree_scene Scenes
 * @brief Scene files (noctree-scene(5)) and the built-in families of
 * SCENES.md.
 *
 * A scene is read completely, and every line checked, before anything is
 * built: a file with an error anywhere yields an error naming the file,
 * the line and the problem, and nothing else. A scene owns its meshes; a
 * world built from it borrows them, so destroy the world first.
 * @{
 */
#ifndef NOCTREE_SCENE_H
#define NOCTREE_SCENE_H

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
 *                   message starts with `path:line:`.
 * @pre @p path and @p scene are not NULL.
 * @return #NOCT_OK; #NOCT_ERR_IO; #NOCT_ERR_PARSE for a syntax error;
 *         #NOCT_ERR_INVALID for a value out of range or an unknown name;
 *         any status of the mesh readers and constructors.
 */
NOCT_API noctStatus noctSceneRead(const char *path, noctScene **scene,
                                  noctError *err);

/**
 * @brief Make a built-in scene family: `planes:K` (t_K) or `gas:N`.
 * @param[in]  spec  The family and its size.
 * @param[out] scene Receives the scene on success, NULL otherwise.
 * @param[out] err   Receives the details of a failure, or NULL.
 * @pre @p spec and @p scene are not NULL.
 * @post The scene runs 200 steps with the default world parameters (gas
 *       with its container walls).
 * @return #NOCT_OK; #NOCT_ERR_INVALID for an unknown family or size.
 */
NOCT_API noctStatus noctSceneFamily(const char *spec, noctScene **scene,
                                    noctError *err);

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
 * @param[in]  scene The scene; must outlive the world.
 * @param[out] world Receives the new world on success, NULL otherwise.
 * @param[out] err   Receives the details of a failure, or NULL.
 * @pre @p scene and @p world are not NULL.
 * @return #NOCT_OK, or any status of noctWorldCreate(), noctWorldAdd() and
 *         the family builders.
 */
NOCT_API noctStatus noctSceneBuild(const noctScene *scene, noctWorld **world,
                                   noctError *err);

#ifdef __cplusplus
}
#endif

/** @} */
#endif /* NOCTREE_SCENE_H */
