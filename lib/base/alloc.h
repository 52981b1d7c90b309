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
