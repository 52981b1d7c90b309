/* SPDX-License-Identifier: Apache-2.0 */
/*
 * object.c - the object table and lazy BVH construction (see object.h).
 */
#include "scene/object.h"

#include <rt/rt.h>

#include <string.h>

#include "base/alloc.h"
#include "base/name_table.h"
#include "base/atomic.h"
#include "scene/accel.h"

#define OBJECT_TABLE_MIN_CAPACITY 64u

void scene_objects_init(struct scene_objects *table)
{
    name_table_init(&table->table, OBJECT_TABLE_MIN_CAPACITY);
    table->defined = 0;
}

static void *object_new(uint32_t name);

static void object_free(void *item)
{
    struct scene_object *object = item;
    for (uint32_t i = 0; i < object->segment_count; i++)
        object_free(object->segments[i]);
    rt_free(object->segments);
    rt_free(object->ops);
    scene_mesh_release(&object->mesh);
    scene_accel_release(object->accel);
    pthread_mutex_destroy(&object->build_lock);
    rt_free(object);
}

void scene_objects_release(struct scene_objects *table)
{
    for (uint32_t i = 0; i < table->table.capacity; i++)
        if (table->table.slots[i].name)
            object_free(table->table.slots[i].item);
    name_table_release(&table->table);
    scene_objects_init(table);
}

struct scene_object *scene_objects_lookup(const struct scene_objects *table, uint32_t name)
{
    return name_table_lookup(&table->table, name);
}

static void *object_new(uint32_t name)
{
    struct scene_object *o = rt_calloc(1, sizeof(*o));
    if (!o)
        return NULL;
    o->name = name;
    o->mesh.bounds = aabb_empty();
    o->class_hint = RT_AUTOMATIC;
    o->strategy_hint = RT_AUTOMATIC;
    o->current_class = RT_STATIC;
    if (pthread_mutex_init(&o->build_lock, NULL) != 0) {
        rt_free(o);
        return NULL;
    }
    return o;
}

struct scene_object *scene_object_create_hidden(void)
{
    return object_new(0);
}

void scene_object_free(struct scene_object *object)
{
    if (object)
        object_free(object);
}

struct scene_object *scene_objects_get_or_create(struct scene_objects *table, uint32_t name)
{
    return name_table_get_or_create(&table->table, name, object_new);
}

int scene_objects_generate(struct scene_objects *table, uint32_t n, uint32_t *names)
{
    return name_table_generate(&table->table, n, names, object_new, object_free);
}

void scene_objects_remove(struct scene_objects *table, uint32_t name)
{
    struct scene_object *o = name_table_remove(&table->table, name);
    if (!o)
        return;
    if (o->defined)
        table->defined--;
    object_free(o);
}

static int same_topology(const struct scene_mesh *a, const struct scene_mesh *b)
{
    return a->vertex_count == b->vertex_count && a->tri_count == b->tri_count &&
           memcmp(a->indices, b->indices, 3 * sizeof(uint32_t) * a->tri_count) == 0;
}

void scene_object_define(struct scene_objects *table, struct scene_object *object,
                         struct scene_mesh *mesh, uint64_t frame)
{
    int keep = object->defined && object->accel && same_topology(&object->mesh, mesh);
    scene_mesh_release(&object->mesh);
    object->mesh = *mesh;
    memset(mesh, 0, sizeof(*mesh));
    mesh->bounds = aabb_empty();
    if (!keep) {
        scene_accel_release(object->accel);
        object->accel = NULL;
        object->topology_serial++;
    }
    if (!object->defined && table)
        table->defined++;
    object->defined = 1;
    object->serial++;
    object->changed_frame = frame;
}

void scene_object_touch(struct scene_object *object, uint64_t frame)
{
    scene_mesh_compute_bounds(&object->mesh);
    object->serial++;
    object->changed_frame = frame;
}

const struct scene_accel *scene_object_peek(const struct scene_object *object)
{
    return rt_atomic_load_acquire(&object->accel);
}

int scene_object_values(const struct scene_object *object, unsigned pname, double v[6])
{
    const struct scene_accel *accel = scene_object_peek(object);
    switch (pname) {
    case RT_OBJECT_TRIANGLES:
        v[0] = object->mesh.tri_count;
        return 1;
    case RT_OBJECT_BUILT:
        /* A structure kept stale for a refit does not count until the
         * update that brings it up to date. */
        v[0] = accel && accel->serial == object->serial ? 1.0 : 0.0;
        return 1;
    case RT_OBJECT_BVH_NODES:
        v[0] = accel ? accel->bvh.node_count : 0;
        return 1;
    case RT_OBJECT_SAH_COST:
        v[0] = accel ? accel->sah_cost : 0.0;
        return 1;
    case RT_OBJECT_BUILD_TIME:
        v[0] = accel ? accel->build_ms : 0.0;
        return 1;
    case RT_OBJECT_CLASS:
        v[0] = object->current_class;
        return 1;
    case RT_UPDATE_STRATEGY:
        v[0] = object->last_strategy ? object->last_strategy : object->strategy_hint;
        return 1;
    case RT_OBJECT_REBUILDS:
        v[0] = (double)object->rebuilds;
        return 1;
    case RT_OBJECT_REFITS:
        v[0] = (double)object->refits;
        return 1;
    case RT_OBJECT_VERTICES:
        v[0] = object->mesh.vertex_count;
        return 1;
    case RT_ACCELERATION_HINT:
        v[0] = object->acceleration_hint;
        return 1;
    case RT_OBJECT_UPDATE_TIME:
        v[0] = object->update_ms;
        return 1;
    case RT_OBJECT_BOUNDS:
        for (int k = 0; k < 3; k++) {
            int empty = aabb_is_empty(&object->mesh.bounds);
            v[k] = empty ? 0.0 : object->mesh.bounds.min[k];
            v[3 + k] = empty ? 0.0 : object->mesh.bounds.max[k];
        }
        return 6;
    default:
        return 0;
    }
}
