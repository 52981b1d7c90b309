/*
 * object.c - the object table and lazy BVH construction (see object.h).
 */
#include "scene/object.h"

#include <rt/rt.h>

#include <string.h>

#include "base/alloc.h"
#include "base/timer.h"
#include "scene/update.h"

#define OBJECT_TABLE_MIN_CAPACITY 64u

void scene_objects_init(struct scene_objects *table)
{
    memset(table, 0, sizeof(*table));
    table->next_name = 1;
}

void scene_accel_release(struct scene_accel *accel)
{
    if (!accel)
        return;
    bvh_release(&accel->bvh);
    rt_free(accel->tri);
    if (accel->restructure_state_ready)
        accel_restructure_state_release(&accel->restructure_state);
    rt_free(accel);
}

static void object_free(struct scene_object *object)
{
    scene_mesh_release(&object->mesh);
    scene_accel_release(object->accel);
    pthread_mutex_destroy(&object->build_lock);
    rt_free(object);
}

void scene_objects_release(struct scene_objects *table)
{
    for (uint32_t i = 0; i < table->capacity; i++)
        if (table->slots[i])
            object_free(table->slots[i]);
    rt_free(table->slots);
    scene_objects_init(table);
}

/* Fibonacci hashing of the name into a power-of-two table. */
static uint32_t slot_of(const struct scene_objects *table, uint32_t name)
{
    return (uint32_t)((name * 2654435769u) & (table->capacity - 1));
}

struct scene_object *scene_objects_lookup(const struct scene_objects *table, uint32_t name)
{
    if (!table->capacity || name == 0)
        return NULL;
    for (uint32_t i = slot_of(table, name);; i = (i + 1) & (table->capacity - 1)) {
        struct scene_object *o = table->slots[i];
        if (!o)
            return NULL;
        if (o->name == name)
            return o;
    }
}

static void insert_slot(struct scene_object **slots, uint32_t capacity, struct scene_object *o)
{
    uint32_t i = (uint32_t)((o->name * 2654435769u) & (capacity - 1));
    while (slots[i])
        i = (i + 1) & (capacity - 1);
    slots[i] = o;
}

/* Keeps the load factor under 1/2; -1 on allocation failure. */
static int ensure_room(struct scene_objects *table, uint32_t extra)
{
    uint64_t needed = ((uint64_t)table->used + extra) * 2;
    if (needed <= table->capacity)
        return 0;
    uint64_t cap = table->capacity ? table->capacity : OBJECT_TABLE_MIN_CAPACITY;
    while (cap < needed)
        cap *= 2;
    if (cap > (1u << 31))
        return -1;
    struct scene_object **slots = rt_calloc(cap, sizeof(*slots));
    if (!slots)
        return -1;
    for (uint32_t i = 0; i < table->capacity; i++)
        if (table->slots[i])
            insert_slot(slots, (uint32_t)cap, table->slots[i]);
    rt_free(table->slots);
    table->slots = slots;
    table->capacity = (uint32_t)cap;
    return 0;
}

static struct scene_object *object_new(uint32_t name)
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

struct scene_object *scene_objects_get_or_create(struct scene_objects *table, uint32_t name)
{
    struct scene_object *o = scene_objects_lookup(table, name);
    if (o)
        return o;
    if (ensure_room(table, 1))
        return NULL;
    o = object_new(name);
    if (!o)
        return NULL;
    insert_slot(table->slots, table->capacity, o);
    table->used++;
    return o;
}

int scene_objects_generate(struct scene_objects *table, uint32_t n, uint32_t *names)
{
    if (n == 0)
        return 0;
    if (n > (1u << 30) || ensure_room(table, n))
        return -1;
    struct scene_object **fresh = rt_calloc(n, sizeof(*fresh));
    if (!fresh)
        return -1;
    uint32_t candidate = table->next_name;
    for (uint32_t i = 0; i < n; i++) {
        /* Skip 0 and names already in use; the table is at most half full
         * of 2^32 - 1 names, so this terminates. */
        while (candidate == 0 || scene_objects_lookup(table, candidate))
            candidate++;
        /* Names within this batch are distinct because candidate only
         * grows (wrap-around would need 2^32 names). */
        fresh[i] = object_new(candidate);
        if (!fresh[i]) {
            for (uint32_t j = 0; j < i; j++)
                object_free(fresh[j]);
            rt_free(fresh);
            return -1;
        }
        names[i] = candidate++;
    }
    for (uint32_t i = 0; i < n; i++) {
        insert_slot(table->slots, table->capacity, fresh[i]);
        table->used++;
    }
    table->next_name = candidate;
    rt_free(fresh);
    return 0;
}

void scene_objects_remove(struct scene_objects *table, uint32_t name)
{
    if (!table->capacity || name == 0)
        return;
    uint32_t mask = table->capacity - 1;
    uint32_t i = slot_of(table, name);
    while (table->slots[i] && table->slots[i]->name != name)
        i = (i + 1) & mask;
    struct scene_object *o = table->slots[i];
    if (!o)
        return;
    if (o->defined)
        table->defined--;
    table->used--;
    table->slots[i] = NULL;
    object_free(o);
    /* Backward-shift deletion keeps linear probing chains intact. */
    for (uint32_t j = (i + 1) & mask; table->slots[j]; j = (j + 1) & mask) {
        struct scene_object *moved = table->slots[j];
        table->slots[j] = NULL;
        insert_slot(table->slots, table->capacity, moved);
    }
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
    if (!object->defined)
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
    return __atomic_load_n(&object->accel, __ATOMIC_ACQUIRE);
}

const struct scene_accel *scene_object_acquire(struct scene_object *object,
                                               const struct scene_update_config *config,
                                               int *built_now)
{
    *built_now = 0;
    struct scene_accel *accel = __atomic_load_n(&object->accel, __ATOMIC_ACQUIRE);
    /* object->serial changes only on the API thread between frames. */
    if (accel && accel->serial == object->serial)
        return accel;
    pthread_mutex_lock(&object->build_lock);
    const struct scene_accel *current = object->accel;
    if (!current || current->serial != object->serial) {
        /* Inside a frame: no pool (it is running this very task). */
        struct scene_update_config serial_config = *config;
        serial_config.pool = NULL;
        current = scene_object_update(object, &serial_config);
        *built_now = current != NULL;
    }
    pthread_mutex_unlock(&object->build_lock);
    return current;
}
