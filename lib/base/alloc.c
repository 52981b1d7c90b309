/* SPDX-License-Identifier: Apache-2.0 */
/*
 * alloc.c - allocation wrapper with fault injection (see alloc.h).
 */
#include "base/alloc.h"
#include "base/atomic.h"

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
