/* SPDX-License-Identifier: Apache-2.0 */
/*
 * timer.h - monotonic wall clock for statistics.
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

#endif
