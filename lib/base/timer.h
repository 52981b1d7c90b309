/* SPDX-License-Identifier: Apache-2.0 */
/*
 * timer.h - monotonic wall clock for statistics, and the calling thread's
 * CPU clock for the costs the update strategies weigh (pool.h,
 * rt_pool_work_ms).
 */
#ifndef RT_BASE_TIMER_H
#define RT_BASE_TIMER_H

#include <time.h>

/* Milliseconds on CLOCK_MONOTONIC; only differences are meaningful. */
static inline double rt_now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

/* Milliseconds of CPU time the calling thread has used
 * (CLOCK_THREAD_CPUTIME_ID): unlike the wall clock it does not advance
 * while the thread waits for a core another process holds.  0 where the
 * clock is missing (the cost model then sees no time, and refits). */
static inline double rt_thread_cpu_ms(void)
{
    struct timespec ts;
    if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts) != 0)
        return 0.0;
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

#endif
