/* SPDX-License-Identifier: Apache-2.0 */
/*
 * pool.c - the worker pool (see pool.h).
 *
 * threads - 1 workers wait on a condition variable; rt_pool_run wakes
 * them for one task, runs worker 0 on the calling thread, and waits until
 * every worker has finished.  Work inside a task is shared dynamically
 * (the task hands out tiles or ray chunks through an atomic counter), so
 * the pool itself does no scheduling.  Created on the first frame that
 * needs it: a context that never renders never starts a thread.
 *
 * A shared task (rt_pool_run_shared, rt_pool_run_range) does not wait
 * for a worker that has not started it by the time the caller has run
 * out of work: a worker takes one of the task's `unclaimed` places under
 * the lock before it reads fn and arg, and the caller, once its own fn
 * has returned, withdraws the places still open.  Waking a worker costs
 * 7-20 us on an idle core and up to milliseconds on a loaded machine
 * (measured in a two-thread BVH build: about half of its 21-33 tasks
 * waited more than 0.5 ms for the worker), and the caller used to wait
 * out that delay even when it had done the whole task alone.
 */
#include "base/pool.h"

#include <pthread.h>
#include <stdint.h>

#include "base/alloc.h"
#include "base/atomic.h"
#include "base/timer.h"

#include <unistd.h>

struct rt_pool {
    int threads;
    pthread_t *workers;
    pthread_mutex_t lock;
    pthread_cond_t wake;
    pthread_cond_t done;
    uint64_t generation; /* bumped per task */
    int pending;         /* workers still running the current task */
    int unclaimed;       /* workers that may still start the current task */
    int quit;
    rt_task_fn fn;
    void *arg;
    /* rt_pool_work_ms: CPU ms all threads have spent in tasks (workers
     * add theirs under lock), the caller's part of it, and the divisor. */
    double task_cpu_ms;
    double caller_task_cpu_ms;
    int parallel;
};

struct worker_start {
    struct rt_pool *pool;
    int index;
};

static void *worker_main(void *p)
{
    struct worker_start *start = p;
    struct rt_pool *pool = start->pool;
    int index = start->index;
    rt_free(start);
    uint64_t seen = 0;
    pthread_mutex_lock(&pool->lock);
    for (;;) {
        while (!pool->quit && pool->generation == seen)
            pthread_cond_wait(&pool->wake, &pool->lock);
        if (pool->quit)
            break;
        seen = pool->generation;
        /* The caller of a shared task withdrew the places left when it
         * finished: the task (and its arg) may be gone. */
        if (pool->unclaimed == 0)
            continue;
        pool->unclaimed--;
        rt_task_fn fn = pool->fn;
        void *arg = pool->arg;
        pthread_mutex_unlock(&pool->lock);
        double cpu = rt_thread_cpu_ms();
        fn(arg, index);
        cpu = rt_thread_cpu_ms() - cpu;
        pthread_mutex_lock(&pool->lock);
        pool->task_cpu_ms += cpu;
        if (--pool->pending == 0)
            pthread_cond_signal(&pool->done);
    }
    pthread_mutex_unlock(&pool->lock);
    return NULL;
}

struct rt_pool *rt_pool_create(int threads)
{
    if (threads < 2)
        return NULL;
    struct rt_pool *pool = rt_calloc(1, sizeof(*pool));
    if (!pool)
        return NULL;
    pool->workers = rt_calloc((size_t)threads - 1, sizeof(pthread_t));
    if (!pool->workers) {
        rt_free(pool);
        return NULL;
    }
    pthread_mutex_init(&pool->lock, NULL);
    pthread_cond_init(&pool->wake, NULL);
    pthread_cond_init(&pool->done, NULL);
    pool->threads = 1;
    for (int i = 1; i < threads; i++) {
        struct worker_start *start = rt_malloc(sizeof(*start));
        if (!start)
            break;
        start->pool = pool;
        start->index = i;
        if (pthread_create(&pool->workers[i - 1], NULL, worker_main, start) != 0) {
            rt_free(start);
            break;
        }
        pool->threads++;
    }
    /* Fewer threads than asked (resource limits) still render correctly. */
    long online = sysconf(_SC_NPROCESSORS_ONLN);
    pool->parallel = online > 0 && online < pool->threads ? (int)online : pool->threads;
    return pool;
}

/* rt_pool_run, and with `shared` rt_pool_run_shared (see the top). */
static void run_task(struct rt_pool *pool, rt_task_fn fn, void *arg, int shared)
{
    if (!pool || pool->threads < 2) {
        fn(arg, 0);
        return;
    }
    pthread_mutex_lock(&pool->lock);
    pool->fn = fn;
    pool->arg = arg;
    pool->pending = pool->threads - 1;
    pool->unclaimed = pool->threads - 1;
    pool->generation++;
    pthread_cond_broadcast(&pool->wake);
    pthread_mutex_unlock(&pool->lock);

    double cpu = rt_thread_cpu_ms();
    fn(arg, 0);
    cpu = rt_thread_cpu_ms() - cpu;

    pthread_mutex_lock(&pool->lock);
    if (shared) {
        pool->pending -= pool->unclaimed;
        pool->unclaimed = 0;
    }
    while (pool->pending > 0)
        pthread_cond_wait(&pool->done, &pool->lock);
    pool->task_cpu_ms += cpu;
    pool->caller_task_cpu_ms += cpu;
    pthread_mutex_unlock(&pool->lock);
}

void rt_pool_run(struct rt_pool *pool, rt_task_fn fn, void *arg)
{
    run_task(pool, fn, arg, 0);
}

void rt_pool_run_shared(struct rt_pool *pool, rt_task_fn fn, void *arg)
{
    run_task(pool, fn, arg, 1);
}

/* rt_pool_run_range's shared state. */
struct range_job {
    rt_range_fn fn;
    void *arg;
    uint32_t begin;
    uint32_t end;
    uint32_t chunk;
    uint32_t next; /* atomic: the next chunk */
};

static void range_task(void *arg, int worker)
{
    struct range_job *job = arg;
    (void)worker;
    for (;;) {
        const uint64_t k = rt_atomic_fetch_add_relaxed(&job->next, 1u);
        const uint64_t lo = (uint64_t)job->begin + k * job->chunk;
        if (lo >= job->end)
            return;
        const uint64_t hi = lo + job->chunk < job->end ? lo + job->chunk : job->end;
        job->fn(job->arg, (uint32_t)lo, (uint32_t)hi);
    }
}

void rt_pool_run_range(struct rt_pool *pool, uint32_t begin, uint32_t end, uint32_t chunk,
                       uint32_t min_parallel, rt_range_fn fn, void *arg)
{
    if (begin >= end)
        return;
    if (rt_pool_threads(pool) < 2 || end - begin < min_parallel) {
        fn(arg, begin, end);
        return;
    }
    struct range_job job = {fn, arg, begin, end, chunk, 0};
    rt_pool_run_shared(pool, range_task, &job);
}

double rt_pool_work_ms(const struct rt_pool *pool)
{
    double own = rt_thread_cpu_ms();
    if (!pool || pool->threads < 2)
        return own;
    /* Written under the lock by tasks that have all finished: the caller
     * took the lock after them in rt_pool_run. */
    return own - pool->caller_task_cpu_ms + pool->task_cpu_ms / (double)pool->parallel;
}

int rt_pool_threads(const struct rt_pool *pool)
{
    return pool ? pool->threads : 1;
}

void rt_pool_destroy(struct rt_pool *pool)
{
    if (!pool)
        return;
    pthread_mutex_lock(&pool->lock);
    pool->quit = 1;
    pthread_cond_broadcast(&pool->wake);
    pthread_mutex_unlock(&pool->lock);
    for (int i = 0; i < pool->threads - 1; i++)
        pthread_join(pool->workers[i], NULL);
    pthread_mutex_destroy(&pool->lock);
    pthread_cond_destroy(&pool->wake);
    pthread_cond_destroy(&pool->done);
    rt_free(pool->workers);
    rt_free(pool);
}
