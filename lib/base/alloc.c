/* SPDX-License-Identifier: Apache-2.0 */
/*
 * alloc.c - allocation wrapper (see alloc.h), with fault injection in
 * its test-only build, and the two huge-page paths for large blocks
 * (why two: alloc.h).
 */
/* madvise and MAP_ANONYMOUS are not POSIX 2008: the build's
 * _POSIX_C_SOURCE alone does not declare them. */
#if defined(__linux__)
#define _DEFAULT_SOURCE
#endif

#include "base/alloc.h"
#if defined(RT_ALLOC_FAULT_INJECTION)
#include "base/atomic.h"
#endif

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#if defined(__linux__)
#include <sys/mman.h>
#endif

/*
 * Blocks of at least this many bytes are offered transparent huge pages
 * (Linux madvise(MADV_HUGEPAGE); nothing elsewhere).  A BVH build over a
 * million triangles writes about 200 MB of fresh blocks (build refs,
 * nodes, leaf-ordered triangles, the wide layout); with 4 KB pages that is
 * some 50000 page faults, a fifth of the build's time measured on the
 * development machine (kernel "madvise" mode), and with 2 MB pages a few
 * hundred.  Smaller blocks are left alone: they come from the malloc heap
 * and would gain little.  Only a hint: the allocation never fails because
 * of it, and the kernel may ignore it.
 */
#define RT_ALLOC_HUGE_MIN ((size_t)4 << 20)
/* 2 MB: the x86-64 huge page (rt_malloc_large maps whole ones). */
#define RT_ALLOC_HUGE_PAGE ((size_t)2 << 20)

static void *advise_huge(void *block, size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (block && bytes >= RT_ALLOC_HUGE_MIN) {
        /* Only whole huge pages inside the block can be backed by one. */
        const uintptr_t page = RT_ALLOC_HUGE_PAGE;
        uintptr_t begin = ((uintptr_t)block + page - 1) & ~(page - 1);
        uintptr_t end = ((uintptr_t)block + bytes) & ~(page - 1);
        if (end > begin)
            (void)madvise((void *)begin, (size_t)(end - begin), MADV_HUGEPAGE);
    }
#else
    (void)bytes;
#endif
    return block;
}

#if defined(RT_ALLOC_FAULT_INJECTION)
/* The test-only build of this file (tracelist_fault, see alloc.h): the
 * one place the library keeps state outside a context, and no shipped
 * library or tool links it.
 * Remaining successful allocations before injected failures start; < 0
 * means never.  Accessed atomically: builds and renders allocate from
 * worker threads. */
static long fail_countdown = -1;
static long failures;
/* rt_alloc_fail_once: only the one allocation fails. */
static int fail_once;

static int injected_failure(void)
{
    long n = rt_atomic_load_relaxed(&fail_countdown);
    if (n < 0)
        return 0;
    if (n == 0) {
        rt_atomic_add_fetch_relaxed(&failures, 1);
        if (rt_atomic_load_relaxed(&fail_once))
            rt_atomic_store_relaxed(&fail_countdown, -1);
        return 1;
    }
    /* Several threads may race on the last unit; the count only needs to
     * be approximately N under concurrency and exact single-threaded. */
    rt_atomic_sub_fetch_relaxed(&fail_countdown, 1);
    return 0;
}
#else
/* The library proper: no hook, no state. */
static int injected_failure(void)
{
    return 0;
}
#endif

void *rt_malloc(size_t size)
{
    if (injected_failure())
        return NULL;
    return advise_huge(malloc(size ? size : 1), size);
}

void *rt_calloc(size_t count, size_t size)
{
    if (size && count > SIZE_MAX / size)
        return NULL;
    if (injected_failure())
        return NULL;
    return advise_huge(calloc(count ? count : 1, size ? size : 1), count * size);
}

void *rt_realloc_array(void *ptr, size_t count, size_t size)
{
    if (size && count > SIZE_MAX / size)
        return NULL;
    if (injected_failure())
        return NULL;
    size_t bytes = count * size;
    return advise_huge(realloc(ptr, bytes ? bytes : 1), bytes);
}

void rt_free(void *ptr)
{
    free(ptr);
}

void *rt_malloc_large(size_t size, struct rt_large_block *handle)
{
    memset(handle, 0, sizeof(*handle));
#if defined(__linux__) && defined(MADV_HUGEPAGE) && defined(MAP_ANONYMOUS)
    if (size >= RT_ALLOC_HUGE_PAGE && size <= SIZE_MAX - 2 * RT_ALLOC_HUGE_PAGE) {
        if (injected_failure())
            return NULL;
        /* Room to align the start to 2 MB and to end on a 2 MB boundary:
         * the kernel backs only whole, aligned 2 MB ranges with huge
         * pages. */
        const size_t bytes = (size + 2 * RT_ALLOC_HUGE_PAGE - 1) & ~(RT_ALLOC_HUGE_PAGE - 1);
        void *map = mmap(NULL, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (map == MAP_FAILED)
            return NULL;
        const uintptr_t page = RT_ALLOC_HUGE_PAGE;
        char *p = (char *)(((uintptr_t)map + page - 1) & ~(page - 1));
        /* Advice only: on failure (THP disabled) the block is still good. */
        (void)madvise(p, bytes - (size_t)(p - (char *)map), MADV_HUGEPAGE);
        handle->base = map;
        handle->bytes = bytes;
        return p;
    }
#endif
    /* 64-byte alignment by hand: C99 has no aligned_alloc. */
    if (size > SIZE_MAX - 63)
        return NULL;
    void *raw = rt_malloc(size + 63);
    if (!raw)
        return NULL;
    handle->base = raw;
    return (void *)(((uintptr_t)raw + 63) & ~(uintptr_t)63);
}

void rt_free_large(struct rt_large_block *handle)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE) && defined(MAP_ANONYMOUS)
    if (handle->bytes) {
        (void)munmap(handle->base, handle->bytes);
        memset(handle, 0, sizeof(*handle));
        return;
    }
#endif
    rt_free(handle->base);
    memset(handle, 0, sizeof(*handle));
}

void *rt_malloc_large_reuse(size_t size, struct rt_large_block *handle,
                            struct rt_large_block *spare)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE) && defined(MAP_ANONYMOUS)
    if (spare && spare->bytes && size <= SIZE_MAX / 4 &&
        spare->bytes <= 2 * size + 2 * RT_ALLOC_HUGE_PAGE) {
        const uintptr_t page = RT_ALLOC_HUGE_PAGE;
        char *p = (char *)(((uintptr_t)spare->base + page - 1) & ~(page - 1));
        if ((size_t)((char *)spare->base + spare->bytes - p) >= size) {
            *handle = *spare;
            memset(spare, 0, sizeof(*spare));
            return p;
        }
    }
#else
    (void)spare;
#endif
    return rt_malloc_large(size, handle);
}

void rt_large_release_tail(const struct rt_large_block *handle, const void *p, size_t used)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE) && defined(MAP_ANONYMOUS)
    if (!handle->bytes)
        return;
    const uintptr_t page = RT_ALLOC_HUGE_PAGE;
    const uintptr_t end = (uintptr_t)handle->base + handle->bytes;
    if ((uintptr_t)p < (uintptr_t)handle->base || (uintptr_t)p > end ||
        used > end - (uintptr_t)p)
        return;
    const uintptr_t from = ((uintptr_t)p + used + page - 1) & ~(page - 1);
    if (from < end)
        (void)madvise((void *)from, (size_t)(end - from), MADV_DONTNEED);
#else
    (void)handle;
    (void)p;
    (void)used;
#endif
}

#if defined(RT_ALLOC_FAULT_INJECTION)
void rt_alloc_fail_after(long n)
{
    rt_atomic_store_relaxed(&fail_once, 0);
    rt_atomic_store_relaxed(&fail_countdown, n);
}

void rt_alloc_fail_once(long n)
{
    rt_atomic_store_relaxed(&fail_once, 1);
    rt_atomic_store_relaxed(&fail_countdown, n);
}

void rt_alloc_fail_reset(void)
{
    rt_atomic_store_relaxed(&fail_countdown, -1);
    rt_atomic_store_relaxed(&fail_once, 0);
    rt_atomic_store_relaxed(&failures, 0);
}

long rt_alloc_failures(void)
{
    return rt_atomic_load_relaxed(&failures);
}
#endif
