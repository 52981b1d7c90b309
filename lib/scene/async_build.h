/* SPDX-License-Identifier: Apache-2.0 */
/*
 * async_build.h - asynchronous rebuilds on K build threads (Wald, Ize and Parker (2008)
 * sec. 6).
 *
 * While an object's new BVH is built in the background from a snapshot of
 * its vertices, the render threads keep refitting and tracing the last
 * finished one.  When a build lands it is swapped in by pointer, refit to
 * the current vertices (it was built from vertices one or more frames
 * old, as in the paper), and the next build starts from a new snapshot.
 *
 * The paper double-buffers vertices and swaps pointers; we copy the
 * positions into the job instead (12 bytes per vertex, cheaper than the
 * refit that runs anyway), because the application owns the only copy of
 * the current vertices through rtUpdateVertices and may overwrite them
 * while the build runs.  A job owns everything it reads, so deleting or
 * redefining its object only cancels it.
 *
 * Threads: none until the first job; then one build thread that runs jobs
 * in order, each with a parallel build on its own pool of K threads
 * (itself included).  K = 0 disables asynchronous builds.
 */
#ifndef RT_SCENE_ASYNC_BUILD_H
#define RT_SCENE_ASYNC_BUILD_H

#include <pthread.h>
#include <stdint.h>

#include "base/pool.h"
#include "scene/object.h"

struct scene_async_job;

struct scene_async_builder {
    int threads; /* K */
    int started;
    int quit;
    pthread_t thread;
    pthread_mutex_t lock;
    pthread_cond_t wake;
    struct scene_async_job *head, *tail; /* queued, oldest first */
    struct rt_pool *pool;                /* K threads; created by the build thread */
    struct bvh_build_params params;
};

/* Prepares a builder for K threads (no thread is started). */
void scene_async_init(struct scene_async_builder *b, int threads,
                      const struct bvh_build_params *params);
/* Cancels every job, joins the thread, frees everything. */
void scene_async_release(struct scene_async_builder *b);

/* Threads the builder runs now (0 before its first job). */
int scene_async_threads_running(const struct scene_async_builder *b);

/*
 * Queues a rebuild of object from a snapshot of its current vertices,
 * unless one is already in flight for it.  Starts the build thread on
 * first use.  Returns 0, or -1 on allocation failure (nothing queued).
 */
int scene_async_request(struct scene_async_builder *b, struct scene_object *object);

/*
 * If the object's job has finished, hands over its structure (built for
 * the object's topology at snapshot time, vertices of the snapshot) and
 * frees the job; returns NULL while it is still running or none exists.
 * The structure's serial is the object serial the snapshot was taken at.
 */
struct scene_accel *scene_async_collect(struct scene_async_builder *b, struct scene_object *object);

/* Cancels the object's job, if any (redefinition, deletion). */
void scene_async_cancel(struct scene_async_builder *b, struct scene_object *object);

#endif
