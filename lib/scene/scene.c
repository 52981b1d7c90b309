/* SPDX-License-Identifier: Apache-2.0 */
/*
 * scene.c - a scene's life and the changes made to it between frames
 * (see scene.h).  Preparation for a frame is in prepare.c.
 */
#include "scene/scene.h"

#include <rt/rt.h>
#include <string.h>

void scene_init(struct scene *scene, const struct bvh_build_params *params, int build_threads,
                int toplevel_cellsplit)
{
    memset(scene, 0, sizeof(*scene));
    scene->build_params = *params;
    scene->build_threads = build_threads;
    scene->default_strategy = RT_AUTOMATIC;
    /* Until a frame has been measured: 5 ns a step, this machine's order
     * of magnitude (bench/rtbench trace). */
    scene->ms_per_test = 5e-6;
    accel_restructure_params_default(&scene->restructure_params);
    scene_objects_init(&scene->objects);
    scene_textures_init(&scene->textures);
    scene_async_init(&scene->async, build_threads, params);
    scene_frame_init(&scene->frame);
    scene->frame.toplevel_cellsplit = toplevel_cellsplit;
}

void scene_release(struct scene *scene)
{
    /* Jobs first (their objects go next), then the build thread. */
    const struct name_table *table = &scene->objects.table;
    for (uint32_t i = 0; i < table->capacity; i++)
        if (table->slots[i].name) {
            struct scene_object *object = table->slots[i].item;
            for (uint32_t k = 0; k < object->segment_count; k++)
                scene_async_cancel(&scene->async, object->segments[k]);
            scene_async_cancel(&scene->async, object);
        }
    /* The hidden objects of immediate mode (frame.h). */
    for (uint32_t i = 0; i < scene->frame.immediate.capacity; i++)
        if (scene->frame.immediate.slots[i])
            scene_async_cancel(&scene->async, scene->frame.immediate.slots[i]);
    scene_async_release(&scene->async);
    scene_frame_release(&scene->frame);
    scene_objects_release(&scene->objects);
    scene_textures_release(&scene->textures);
}

void scene_define_object(struct scene *scene, struct scene_object *object,
                         struct scene_mesh *mesh)
{
    if (object->defined)
        scene->changes.redefined++;
    else
        scene->changes.defined++;
    scene_object_define(&scene->objects, object, mesh, scene->frame_number);
}

void scene_delete_object(struct scene *scene, uint32_t name)
{
    struct scene_object *object = scene_objects_lookup(&scene->objects, name);
    if (!object)
        return;
    if (object->defined)
        scene->changes.deleted++;
    for (uint32_t i = 0; i < object->segment_count; i++) {
        /* A display list's hidden segments go with it. */
        scene_frame_forget_object(&scene->frame, object->segments[i]);
        scene_async_cancel(&scene->async, object->segments[i]);
    }
    scene_frame_forget_object(&scene->frame, object);
    scene_async_cancel(&scene->async, object);
    scene_objects_remove(&scene->objects, name);
}

double scene_array_component(const void *data, int is_double, size_t stride, size_t i, int c)
{
    const unsigned char *p = (const unsigned char *)data + i * stride;
    if (!is_double) {
        float f;
        memcpy(&f, p + c * sizeof(float), sizeof(f));
        return f;
    }
    double d;
    memcpy(&d, p + c * sizeof(double), sizeof(d));
    return d;
}

void scene_update_vertices(struct scene *scene, struct scene_object *object, int normals,
                           uint32_t first, uint32_t count, const void *data, int is_double,
                           size_t stride)
{
    if (count == 0)
        return; /* nothing changes, so nothing is stale (Mesa compares first) */
    struct scene_mesh *mesh = &object->mesh;
    float *dst = normals ? mesh->normals : mesh->positions;
    for (uint32_t i = 0; i < count; i++)
        for (int c = 0; c < 3; c++)
            dst[3 * ((size_t)first + i) + c] =
                (float)scene_array_component(data, is_double, stride, i, c);
    if (normals) {
        mesh->has_normals = 1;
        return; /* shading data only: nothing to update for traversal */
    }
    scene_object_touch(object, scene->frame_number);
    scene->changes.touched++;
}
