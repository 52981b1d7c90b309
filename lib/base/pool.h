/* SPDX-License-Identifier: Apache-2.0 */
/*
 * pool.h - a minimal pthread worker pool shared by rendering and parallel
 * builds.
 *
 * A pool of `threads` runs a task as threads - 1 workers plus the calling
 * thread; the task shares its work out itself (atomic counters), so the
 * pool does no scheduling (rt_pool_run_range is that sharing for a range
 * of independent items).  Pools are created when first needed: a
 * context that never renders or builds in parallel starts no thread.
 */
#ifndef RT_BASE_POOL_H
#define RT_BASE_POOL_H

#include <stdint.h>

struct rt_pool;
typedef void (*rt_task_fn)(void *arg, int worker);

/* NULL when threads < 2 (or on allocation failure): callers treat a NULL
 * pool as "run on the calling thread only".  May start fewer threads than
 * asked when the system refuses more; rt_pool_threads tells. */
struct rt_pool *rt_pool_create(int threads);

/* Runs fn(arg, w) for w = 0..threads-1, w = 0 on the caller, and returns
 * when all have finished.  pool may be NULL: then fn(arg, 0) runs alone.
 * Not reentrant: one task at a time per pool. */
void rt_pool_run(struct rt_pool *pool, rt_task_fn fn, void *arg);

/* As rt_pool_run for a task whose threads share its work through a
 * counter of its own, so that any thread may do all of it: fn(arg, 0)
 * runs on the caller, and fn(arg, w) for w > 0 on the workers that start
 * before the caller's fn has returned; the call returns when those have
 * finished, without waiting for a worker to wake up to find nothing
 * left.  fn must not depend on w running (no per-worker share or
 * scratch that is not optional). */
void rt_pool_run_shared(struct rt_pool *pool, rt_task_fn fn, void *arg);

/* Runs fn(arg, lo, hi) over the items [begin, end) in chunks of `chunk`
 * (> 0) that the pool's threads take in turn from a shared counter, or
 * once over the whole range on the calling thread when the pool has
 * fewer than two threads or the range holds fewer than min_parallel
 * items (shorter than waking the workers).  When fn's work on an item
 * depends on nothing but the item, what it writes is the same on any
 * pool.  A shared task (rt_pool_run_shared): a worker that wakes after
 * the last chunk was taken is not waited for.  Uses the pool for the
 * duration of the call. */
typedef void (*rt_range_fn)(void *arg, uint32_t lo, uint32_t hi);
void rt_pool_run_range(struct rt_pool *pool, uint32_t begin, uint32_t end, uint32_t chunk,
                       uint32_t min_parallel, rt_range_fn fn, void *arg);

/* Threads a task runs on, the caller included; 1 for NULL. */
int rt_pool_threads(const struct rt_pool *pool);

/*
 * A clock of the work the calling thread and the pool do, for costs that
 * must not depend on the machine's load (RT_AUTOMATIC's build cost and
 * time per traversal step, lib/scene/update.c).  It advances by the
 * calling thread's CPU time outside pool tasks plus 1/P of the CPU time
 * all the pool's threads spend in tasks, P the threads that can run at
 * once (the pool's threads, at most the online processors): the time the
 * work would take on an otherwise idle machine, tasks shared evenly, which
 * is what it costs a frame.  Thread CPU time does not advance while
 * another process holds the core, so a time slice lost to another process
 * costs nothing here where the wall clock charges all of it.  Only
 * differences taken on the thread that calls rt_pool_run mean anything;
 * pool may be NULL (the calling thread's CPU time alone).
 */
double rt_pool_work_ms(const struct rt_pool *pool);

/* Joins the workers and frees the pool; NULL is ignored. */
void rt_pool_destroy(struct rt_pool *pool);

#endif
