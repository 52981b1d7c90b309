/* SPDX-License-Identifier: Apache-2.0 */
/*
 * name_table.h - names to items: the table behind objects (rtGenObjects,
 * rtNewObject) and textures (rtGenTextures, rtBindTexture).
 *
 * GL-style names are non-zero uint32_t chosen by the application or handed
 * out by *_generate.  Open addressing with linear probing on the name:
 * Fibonacci hashing into a power-of-two table, load factor under 1/2,
 * backward-shift deletion.  The table owns its slots only; items belong to
 * the caller, which frees them (iterate slots[0..capacity) before
 * name_table_release).
 */
#ifndef RT_BASE_NAME_TABLE_H
#define RT_BASE_NAME_TABLE_H

#include <stdint.h>

struct name_entry {
    uint32_t name; /* 0: free slot */
    void *item;
};

struct name_table {
    struct name_entry *slots;
    uint32_t capacity;     /* power of two, or 0 */
    uint32_t used;         /* occupied slots */
    uint32_t next_name;    /* name_table_generate search start */
    uint32_t min_capacity; /* first allocation, a power of two */
};

void name_table_init(struct name_table *t, uint32_t min_capacity);
/* Frees the slots (not the items) and leaves an empty table. */
void name_table_release(struct name_table *t);

/* The item named `name`, or NULL (always NULL for 0). */
void *name_table_lookup(const struct name_table *t, uint32_t name);

/* The item named `name` (non-zero), made by create(name) and inserted if
 * absent; NULL on allocation failure, leaving the table unchanged. */
void *name_table_get_or_create(struct name_table *t, uint32_t name,
                               void *(*create)(uint32_t name));

/* Makes n items for n unused names with create and inserts them, then
 * writes the names.  Returns 0, or -1 on allocation failure having
 * destroyed what it made, inserted nothing and written nothing. */
int name_table_generate(struct name_table *t, uint32_t n, uint32_t *names,
                        void *(*create)(uint32_t name), void (*destroy)(void *item));

/* Removes `name` and returns its item for the caller to free; NULL (and
 * no change) for 0 or an unknown name. */
void *name_table_remove(struct name_table *t, uint32_t name);

#endif
