/* SPDX-License-Identifier: Apache-2.0 */
/*
 * alloc.h - the one allocation wrapper of the library.
 *
 * Every allocation in lib/ goes through these functions so that a test can
 * make the Nth allocation fail and walk every RT_OUT_OF_MEMORY path (the
 * idea of SQLite's sqlite3FaultSim).  They behave like malloc/calloc/
 * realloc/free; rt_realloc_array leaves the old block untouched on failure.
 * A request whose size computation would overflow returns NULL.
 * Thread-safe.
 */
#ifndef RT_BASE_ALLOC_H
#define RT_BASE_ALLOC_H

#include <stddef.h>

void *rt_malloc(size_t size);
void *rt_calloc(size_t count, size_t size);
/* realloc of count*size bytes, overflow-checked. */
void *rt_realloc_array(void *ptr, size_t count, size_t size);
void rt_free(void *ptr);

/* A large, long-lived, read-mostly block (an object's wide traversal
 * layout): `size` bytes aligned to 64, which on Linux come from a fresh
 * anonymous mapping aligned to 2 MB and advised for transparent huge pages
 * (madvise MADV_HUGEPAGE) before any byte of it is touched, so that a
 * random ray's node and leaf loads miss the TLB less (Embree advises its
 * blocks the same way); elsewhere, or for a block under 2 MB, rt_malloc.
 * Fails like rt_malloc (and counts for the fault-injection hooks below).
 * *handle receives what rt_free_large needs; the block is not zeroed. */
struct rt_large_block {
    void *base;   /* what was allocated */
    size_t bytes; /* the mapping's length, 0 for an rt_malloc block */
};
void *rt_malloc_large(size_t size, struct rt_large_block *handle);
/* Frees a block of rt_malloc_large; safe on a zeroed handle. */
void rt_free_large(struct rt_large_block *handle);

/* Test hook: after `n` more successful allocations every allocation fails
 * until rt_alloc_fail_reset() (n < 0 disables).  Process-wide: this is the
 * single piece of global mutable state outside a context, and only the
 * fault-injection tests touch it. */
void rt_alloc_fail_after(long n);
/* Test hook: only the allocation after `n` more successful ones fails; the
 * ones after it succeed again (a single allocation failure). */
void rt_alloc_fail_once(long n);
void rt_alloc_fail_reset(void);
/* Allocations that failed on purpose since the last reset. */
long rt_alloc_failures(void);

#endif
