/* SPDX-License-Identifier: Apache-2.0 */
/*
 * name_table.c - see name_table.h.
 */
#include "base/name_table.h"

#include <string.h>

#include "base/alloc.h"

void name_table_init(struct name_table *t, uint32_t min_capacity)
{
    memset(t, 0, sizeof(*t));
    t->next_name = 1;
    t->min_capacity = min_capacity;
}

void name_table_release(struct name_table *t)
{
    rt_free(t->slots);
    name_table_init(t, t->min_capacity);
}

/* Fibonacci hashing of the name into a power-of-two table. */
static uint32_t slot_of(uint32_t capacity, uint32_t name)
{
    return (uint32_t)((name * 2654435769u) & (capacity - 1));
}

void *name_table_lookup(const struct name_table *t, uint32_t name)
{
    if (!t->capacity || name == 0)
        return NULL;
    for (uint32_t i = slot_of(t->capacity, name);; i = (i + 1) & (t->capacity - 1)) {
        if (t->slots[i].name == 0)
            return NULL;
        if (t->slots[i].name == name)
            return t->slots[i].item;
    }
}

static void insert_slot(struct name_entry *slots, uint32_t capacity, struct name_entry e)
{
    uint32_t i = slot_of(capacity, e.name);
    while (slots[i].name)
        i = (i + 1) & (capacity - 1);
    slots[i] = e;
}

/* Keeps the load factor under 1/2 with `extra` more entries; -1 on
 * allocation failure (unchanged). */
static int ensure_room(struct name_table *t, uint32_t extra)
{
    uint64_t needed = ((uint64_t)t->used + extra) * 2;
    if (needed <= t->capacity)
        return 0;
    uint64_t cap = t->capacity ? t->capacity : t->min_capacity;
    while (cap < needed)
        cap *= 2;
    if (cap > (1u << 31))
        return -1;
    struct name_entry *slots = rt_calloc(cap, sizeof(*slots));
    if (!slots)
        return -1;
    for (uint32_t i = 0; i < t->capacity; i++)
        if (t->slots[i].name)
            insert_slot(slots, (uint32_t)cap, t->slots[i]);
    rt_free(t->slots);
    t->slots = slots;
    t->capacity = (uint32_t)cap;
    return 0;
}

static void insert(struct name_table *t, uint32_t name, void *item)
{
    struct name_entry e = {name, item};
    insert_slot(t->slots, t->capacity, e);
    t->used++;
}

void *name_table_get_or_create(struct name_table *t, uint32_t name,
                               void *(*create)(uint32_t name))
{
    void *item = name_table_lookup(t, name);
    if (item || name == 0)
        return item;
    if (ensure_room(t, 1) || !(item = create(name)))
        return NULL;
    insert(t, name, item);
    return item;
}

int name_table_generate(struct name_table *t, uint32_t n, uint32_t *names,
                        void *(*create)(uint32_t name), void (*destroy)(void *item))
{
    if (n == 0)
        return 0;
    if (n > (1u << 30) || ensure_room(t, n))
        return -1;
    struct name_entry *fresh = rt_calloc(n, sizeof(*fresh));
    if (!fresh)
        return -1;
    uint32_t candidate = t->next_name;
    for (uint32_t i = 0; i < n; i++) {
        /* Skip 0 and names in use; the table is at most half full of
         * 2^32 - 1 names, so this terminates.  Names within the batch are
         * distinct because candidate only grows. */
        while (candidate == 0 || name_table_lookup(t, candidate))
            candidate++;
        fresh[i].name = candidate;
        fresh[i].item = create(candidate++);
        if (!fresh[i].item) {
            for (uint32_t j = 0; j < i; j++)
                destroy(fresh[j].item);
            rt_free(fresh);
            return -1;
        }
    }
    /* Names go out only once every item exists: a failure writes none. */
    for (uint32_t i = 0; i < n; i++) {
        insert(t, fresh[i].name, fresh[i].item);
        names[i] = fresh[i].name;
    }
    t->next_name = candidate;
    rt_free(fresh);
    return 0;
}

void *name_table_remove(struct name_table *t, uint32_t name)
{
    if (!t->capacity || name == 0)
        return NULL;
    uint32_t mask = t->capacity - 1;
    uint32_t i = slot_of(t->capacity, name);
    while (t->slots[i].name && t->slots[i].name != name)
        i = (i + 1) & mask;
    if (!t->slots[i].name)
        return NULL;
    void *item = t->slots[i].item;
    t->used--;
    t->slots[i].name = 0;
    t->slots[i].item = NULL;
    /* Backward-shift deletion keeps linear probing chains intact. */
    for (uint32_t j = (i + 1) & mask; t->slots[j].name; j = (j + 1) & mask) {
        struct name_entry moved = t->slots[j];
        t->slots[j].name = 0;
        t->slots[j].item = NULL;
        insert_slot(t->slots, t->capacity, moved);
    }
    return item;
}
