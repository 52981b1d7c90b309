/* SPDX-License-Identifier: Apache-2.0 */
/*
 * light_set.c - the frame's table of distinct light sets (see frame.h).
 *
 * GL lights a vertex with the lights enabled, and their parameters, as
 * they are when the vertex is specified (OpenGL 2.1 spec sec. 2.14.1), so
 * the lights are per-primitive state like the light model (gl_state.h).
 * A light set is about a kilobyte; an instance keeps a 4-byte index into
 * this table instead, and equal sets share an entry, so that a frame
 * whose primitives all see the same lights holds one.
 */
#include <string.h>

#include "base/alloc.h"
#include "scene/frame.h"

/* FNV-1a over the set's bytes: every field is 4 bytes wide, so equal
 * sets hash equally. */
static uint32_t set_hash(const struct scene_light_set *set)
{
    const unsigned char *p = (const unsigned char *)set;
    uint32_t h = 2166136261u;
    for (size_t i = 0; i < sizeof(*set); i++)
        h = (h ^ p[i]) * 16777619u;
    return h;
}

static void table_release(struct scene_light_sets *t)
{
    rt_free(t->items);
    rt_free(t->hashes);
    memset(t, 0, sizeof(*t));
}

static int table_reserve(struct scene_light_sets *t, uint32_t count)
{
    if (count <= t->capacity)
        return 0;
    uint32_t cap = t->capacity ? t->capacity : 4;
    while (cap < count) {
        if (cap > UINT32_MAX / 2)
            return -1;
        cap *= 2;
    }
    void *items = rt_realloc_array(t->items, cap, sizeof(*t->items));
    if (!items)
        return -1;
    t->items = items;
    void *hashes = rt_realloc_array(t->hashes, cap, sizeof(*t->hashes));
    if (!hashes)
        return -1;
    t->hashes = hashes;
    t->capacity = cap;
    return 0;
}

void scene_light_sets_restart(struct scene_frame *frame)
{
    if (frame->light_sets_fresh) { /* restarted for this list already */
        frame->light_sets_fresh = 0;
        return;
    }
    frame->pending_lights.count = 0;
    frame->light_sets_serial++;
}

uint32_t scene_frame_light_set(struct scene_frame *frame,
                               const struct scene_light lights[SCENE_MAX_LIGHTS])
{
    /* The instance this is for starts the next list: restart the table
     * now, and not again when the list starts. */
    if (!frame->open && !frame->light_sets_fresh) {
        scene_light_sets_restart(frame);
        frame->light_sets_fresh = 1;
    }
    struct scene_light_set set;
    memset(&set, 0, sizeof(set));
    for (int i = 0; i < SCENE_MAX_LIGHTS; i++)
        if (lights[i].enabled)
            set.light[i] = lights[i];
    uint32_t h = set_hash(&set);
    struct scene_light_sets *t = &frame->pending_lights;
    for (uint32_t i = t->count; i > 0; i--) /* the latest first */
        if (t->hashes[i - 1] == h && memcmp(&t->items[i - 1], &set, sizeof(set)) == 0)
            return i - 1;
    if (t->count == UINT32_MAX - 1 || table_reserve(t, t->count + 1))
        return UINT32_MAX;
    t->items[t->count] = set;
    t->hashes[t->count] = h;
    return t->count++;
}

int scene_light_sets_commit(struct scene_frame *frame)
{
    const struct scene_light_sets *p = &frame->pending_lights;
    struct scene_light_sets *c = &frame->committed_lights;
    if (table_reserve(c, p->count))
        return -1;
    if (p->count) {
        memcpy(c->items, p->items, p->count * sizeof(*p->items));
        memcpy(c->hashes, p->hashes, p->count * sizeof(*p->hashes));
    }
    c->count = p->count;
    return 0;
}

void scene_light_sets_release(struct scene_frame *frame)
{
    table_release(&frame->pending_lights);
    table_release(&frame->committed_lights);
}
