/* SPDX-License-Identifier: Apache-2.0 */
/*
 * alloc.h - the one allocation wrapper of the library.
 *
 * Every allocation in lib/ goes through these functions so that a test can
 * make the Nth allocation fail and walk every RT_OUT_OF_MEMORY path (the
 * idea of SQLite's sqlite3FaultSim; the hooks, at the end, exist in a
 * test-only build of the library).  They behave like malloc/calloc/
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
 * layout): `size` bytes aligned to 64 from rt_malloc.  A block of 4 MB
 * or more (the size from which every rt_malloc block gets the
 * transparent-huge-page hint, madvise MADV_HUGEPAGE on Linux) is also
 * aligned to 2 MB and padded to whole 2 MB pages, so that the hint covers
 * all of it: a random ray's node and leaf loads then miss the TLB less
 * (Embree advises its BVH blocks the same way).  A fault in advised
 * memory not yet touched gets a huge page at once; memory touched before
 * keeps its 4 KB pages until the kernel's khugepaged collapses them.
 * glibc maps every block above its mmap threshold (at most 32 MB) fresh,
 * but may serve a smaller one from freed heap memory.
 * Fails like rt_malloc (one allocation for the fault-injection hooks
 * below).  *handle receives what rt_free_large needs; the block is not
 * zeroed. */
struct rt_large_block {
    void *base; /* what rt_malloc returned */
};
void *rt_malloc_large(size_t size, struct rt_large_block *handle);
/* Frees a block of rt_malloc_large; safe on a zeroed handle. */
void rt_free_large(struct rt_large_block *handle);

#if defined(RT_ALLOC_FAULT_INJECTION)
/*
 * Fault injection, in the test-only build of this file only: the CMake
 * target tracelist_fault (the internal objects with alloc.c compiled with
 * RT_ALLOC_FAULT_INJECTION, which it also defines for whatever links it),
 * linked by the conformance tests that call these hooks.  Its counters
 * are process-wide, the one piece of mutable state outside a context:
 * allocations come from worker threads (a per-thread hook would miss
 * them) and from layers (accel, trace) that never see a context (a
 * per-context hook would have to be passed down every call that
 * allocates).  The libraries, rtbench and the other tests have neither
 * the counters nor the hooks; there every allocation is plain.
 */
/* After `n` more successful allocations every allocation fails until
 * rt_alloc_fail_reset() (n < 0 disables). */
void rt_alloc_fail_after(long n);
/* Only the allocation after `n` more successful ones fails; the ones
 * after it succeed again (a single allocation failure). */
void rt_alloc_fail_once(long n);
void rt_alloc_fail_reset(void);
/* Allocations that failed on purpose since the last reset. */
long rt_alloc_failures(void);
#endif

#endif
