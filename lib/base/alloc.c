/*
 * alloc.c - allocation wrapper with fault injection (see alloc.h).
 */
#include "base/alloc.h"

#include <stdint.h>
#include <stdlib.h>

/* Remaining successful allocations before injected failures start; < 0
 * means never.  Accessed atomically: builds and renders allocate from
 * worker threads. */
static long fail_countdown = -1;
static long failures;
/* rt_alloc_fail_once: only the one allocation fails. */
static int fail_once;

static int injected_failure(void)
{
    long n = __atomic_load_n(&fail_countdown, __ATOMIC_RELAXED);
    if (n < 0)
        return 0;
    if (n == 0) {
        __atomic_add_fetch(&failures, 1, __ATOMIC_RELAXED);
        if (__atomic_load_n(&fail_once, __ATOMIC_RELAXED))
            __atomic_store_n(&fail_countdown, -1, __ATOMIC_RELAXED);
        return 1;
    }
    /* Several threads may race on the last unit; the count only needs to
     * be approximately N under concurrency and exact single-threaded. */
    __atomic_sub_fetch(&fail_countdown, 1, __ATOMIC_RELAXED);
    return 0;
}

void *rt_malloc(size_t size)
{
    if (injected_failure())
        return NULL;
    return malloc(size ? size : 1);
}

void *rt_calloc(size_t count, size_t size)
{
    if (size && count > SIZE_MAX / size)
        return NULL;
    if (injected_failure())
        return NULL;
    return calloc(count ? count : 1, size ? size : 1);
}

void *rt_realloc_array(void *ptr, size_t count, size_t size)
{
    if (size && count > SIZE_MAX / size)
        return NULL;
    if (injected_failure())
        return NULL;
    size_t bytes = count * size;
    return realloc(ptr, bytes ? bytes : 1);
}

void rt_free(void *ptr)
{
    free(ptr);
}

void rt_alloc_fail_after(long n)
{
    __atomic_store_n(&fail_once, 0, __ATOMIC_RELAXED);
    __atomic_store_n(&fail_countdown, n, __ATOMIC_RELAXED);
}

void rt_alloc_fail_once(long n)
{
    __atomic_store_n(&fail_once, 1, __ATOMIC_RELAXED);
    __atomic_store_n(&fail_countdown, n, __ATOMIC_RELAXED);
}

void rt_alloc_fail_reset(void)
{
    __atomic_store_n(&fail_countdown, -1, __ATOMIC_RELAXED);
    __atomic_store_n(&fail_once, 0, __ATOMIC_RELAXED);
    __atomic_store_n(&failures, 0, __ATOMIC_RELAXED);
}

long rt_alloc_failures(void)
{
    return __atomic_load_n(&failures, __ATOMIC_RELAXED);
}
