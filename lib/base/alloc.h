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
#include <stdint.h>

void *rt_malloc(size_t size);
void *rt_calloc(size_t count, size_t size);
/* realloc of count*size bytes, overflow-checked. */
void *rt_realloc_array(void *ptr, size_t count, size_t size);
void rt_free(void *ptr);
/* The first 64-byte (cache line) aligned address in block, or NULL for
 * NULL: for an array allocated 64 bytes longer than it needs, which the
 * caller frees through the pointer it allocated.  For arrays of 32-byte
 * records that SIMD loops load and store whole (the builders' refs and
 * bin histograms): with malloc's 16-byte alignment a record straddles two
 * cache lines every other time whenever the block starts 16 bytes past a
 * 32-byte boundary, which depends on the heap's history, not on the build
 * (a mapped block always does: it starts 16 bytes into its first page).
 * Measured: the kitchen's one-thread build 9 % slower when its bins and
 * refs sat at 48 mod 64 instead of 32.  Not posix_memalign: its blocks
 * changed how glibc reuses the heap between builds (a one-thread build of
 * a million triangles then found its 32 MB of refs fresh every build:
 * 15-25 % slower).  The alignment is for speed only; no access relies
 * on it. */
static inline void *rt_align64(void *block)
{
    return block ? (void *)(((uintptr_t)block + 63) & ~(uintptr_t)63) : NULL;
}

/* count records of size bytes (size > 0) starting on a 64-byte boundary
 * (rt_align64) in a block 64 bytes longer, which *block receives for
 * rt_free; NULL (and *block NULL) on overflow or failure.  The block is
 * rt_realloc_array's, so the heap sees the same requests as an
 * unaligned array of count + 64 / size records. */
static inline void *rt_alloc_array64(size_t count, size_t size, void **block)
{
    *block = count <= (SIZE_MAX - 64) / size ? rt_realloc_array(NULL, count * size + 64, 1)
                                             : NULL;
    return rt_align64(*block);
}

/* A large, long-lived, read-mostly block (an object's wide traversal
 * layout): `size` bytes aligned to 64, which on Linux come from a fresh
 * anonymous mapping aligned to 2 MB and advised for transparent huge pages
 * (madvise MADV_HUGEPAGE) before any byte of it is touched, so that a
 * random ray's node and leaf loads miss the TLB less (Embree advises its
 * blocks the same way); elsewhere, or for a block under 2 MB, rt_malloc.
 * Fails like rt_malloc (and counts for the fault-injection hooks below).
 * *handle receives what rt_free_large needs; the block is not zeroed.
 *
 * Why two huge-page paths.  rt_malloc, rt_calloc and rt_realloc_array
 * also offer huge pages, to every block of 4 MB or more, but only as a
 * hint on what malloc returns (the build's blocks: fewer page faults).
 * That hint cannot stand in for this function: glibc serves a block below
 * its mmap threshold from its heap, and the threshold rises to the size of
 * every mapped block freed (up to 32 MB), so after the first rebuild a
 * layout of 2 to 32 MB can come from heap memory that the advice does not
 * turn into huge pages.  Measured (AnonHugePages of /proc/self/smaps_rollup
 * after writing the block): a 3 MB block asked of rt_malloc padded and
 * aligned to 2 MB gets 0 kB of huge pages once a 20 MB block was freed,
 * from here 4096 kB; a 74 MB one (bumpy's layout) gets all of it either
 * way.  Nor can the malloc family use a mapping of its own: rt_free and
 * rt_realloc_array receive no size and cannot tell a mapping from a heap
 * block, and the build's arrays grow by realloc.  So the blocks that are
 * walked by random rays for a whole frame take this path, and the
 * short-lived ones the hint. */
struct rt_large_block {
    void *base;   /* what was allocated */
    size_t bytes; /* the mapping's length, 0 for an rt_malloc block */
};
void *rt_malloc_large(size_t size, struct rt_large_block *handle);
/* Frees a block of rt_malloc_large; safe on a zeroed handle. */
void rt_free_large(struct rt_large_block *handle);
/* rt_malloc_large, but taking *spare's mapping instead when it holds
 * `size` bytes from its 2 MB aligned start and is no larger than about
 * twice that (2 size + 4 MB: a shrinking object does not keep a block
 * much larger than its layout): *handle then receives it, *spare is
 * zeroed, and the same aligned address is returned, its old bytes left
 * as they were.  A rebuilt object's new layout so reuses the pages of its
 * old one, which are already in memory: a fresh mapping's pages are
 * zeroed by the kernel at their first write (11-18 % of the samples of
 * a one-thread benchmark of builds of a million triangles, all under the
 * layout's writes: perf on the development machine).  Otherwise (no
 * spare, an rt_malloc block, too small or too large) *spare is left
 * alone and this is rt_malloc_large; spare may be NULL.  Taking the
 * spare allocates nothing and never fails. */
void *rt_malloc_large_reuse(size_t size, struct rt_large_block *handle,
                            struct rt_large_block *spare);

/* Gives the pages of a block of rt_malloc_large back to the system past
 * the first `used` bytes from p (the address rt_malloc_large or
 * rt_malloc_large_reuse returned): the whole 2 MB pages after them, which
 * read as zeros if touched again (Linux madvise MADV_DONTNEED; nothing
 * for an rt_malloc block or elsewhere).  The mapping keeps its length.
 * For a block taken over from a larger one whose tail was written (a
 * parallel build's scratch, accel_build_parallel_triangles): the layout
 * does not hold those pages for its lifetime. */
void rt_large_release_tail(const struct rt_large_block *handle, const void *p, size_t used);

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
