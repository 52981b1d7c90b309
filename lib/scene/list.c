/* SPDX-License-Identifier: Apache-2.0 */
/*
 * list.c - committing display lists (see list.h).
 */
#include "scene/list.h"

#include <string.h>

#include "base/alloc.h"

struct scene_object *scene_list_segment(struct scene_object *object, uint32_t i)
{
    return i == 0 ? object : object->segments[i - 1];
}

static void free_meshes(struct scene_mesh *meshes, uint32_t count)
{
    for (uint32_t i = 0; i < count; i++)
        scene_mesh_release(&meshes[i]);
    rt_free(meshes);
}

static void drop_segment(struct scene *scene, struct scene_object *segment)
{
    scene_frame_forget_object(&scene->frame, segment);
    scene_async_cancel(&scene->async, segment);
    scene_object_free(segment);
}

int scene_define_list(struct scene *scene, struct scene_object *object,
                      struct scene_mesh *meshes, uint32_t count, struct scene_list_op *ops,
                      uint32_t op_count)
{
    uint32_t extra = count > 1 ? count - 1 : 0;
    struct scene_object **segments = NULL;
    if (extra) {
        segments = rt_calloc(extra, sizeof(*segments));
        if (!segments)
            goto fail;
        for (uint32_t i = 0; i < extra; i++) {
            segments[i] = i < object->segment_count ? object->segments[i]
                                                    : scene_object_create_hidden();
            if (!segments[i]) {
                for (uint32_t k = object->segment_count; k < i; k++)
                    scene_object_free(segments[k]);
                goto fail;
            }
        }
    }
    for (uint32_t i = extra; i < object->segment_count; i++)
        drop_segment(scene, object->segments[i]);
    rt_free(object->segments);
    object->segments = segments;
    object->segment_count = extra;
    for (uint32_t i = 0; i < extra; i++) {
        scene_mesh_compute_bounds(&meshes[i + 1]);
        scene_object_define(NULL, segments[i], &meshes[i + 1], scene->frame_number);
    }
    struct scene_mesh empty;
    memset(&empty, 0, sizeof(empty));
    empty.bounds = aabb_empty();
    struct scene_mesh *first = count ? &meshes[0] : &empty;
    scene_mesh_compute_bounds(first);
    scene_define_object(scene, object, first);
    free_meshes(meshes, count);
    rt_free(object->ops);
    /* Only its own geometry: instantiated without replaying anything. */
    if (op_count == 0 || (op_count == 1 && ops[0].kind == SCENE_OP_SEGMENT)) {
        rt_free(ops);
        ops = NULL;
        op_count = 0;
    }
    object->ops = ops;
    object->op_count = op_count;
    return 0;
fail:
    rt_free(segments);
    free_meshes(meshes, count);
    rt_free(ops);
    return -1;
}
