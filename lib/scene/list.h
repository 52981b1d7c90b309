/* SPDX-License-Identifier: Apache-2.0 */
/*
 * list.h - committing a display list's definition (its segments and
 * operations, recording.h) to an object, without an API context.
 */
#ifndef RT_SCENE_LIST_H
#define RT_SCENE_LIST_H

#include "scene/recording.h"
#include "scene/scene.h"

/*
 * Swaps in a list recorded by scene_list_finish: meshes[0] (an empty mesh
 * when count is 0) becomes the object's definition, meshes[1..] the hidden
 * segment objects (reused by position, so a redefinition with the same
 * connectivity keeps their structures for a refit), ops its operations.
 * A list that is only its own geometry keeps no operations.  Ownership of
 * the meshes (released and freed here) and of ops moves.  0, or -1 on
 * allocation failure having changed nothing (everything is freed).
 */
int scene_define_list(struct scene *scene, struct scene_object *object,
                      struct scene_mesh *meshes, uint32_t count, struct scene_list_op *ops,
                      uint32_t op_count);

/* The object of segment i of a list (0: the object itself). */
struct scene_object *scene_list_segment(struct scene_object *object, uint32_t i);

#endif
