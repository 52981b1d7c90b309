/* SPDX-License-Identifier: Apache-2.0 */
/*
 * async_build.c - the asynchronous rebuild thread (see async_build.h).
 */
#include "scene/async_build.h"

#include <string.h>

#include "base/alloc.h"
#include "scene/accel.h"

enum job_state { JOB_QUEUED, JOB_RUNNING, JOB_DONE };

struct scene_async_job {
    struct scene_async_job *next;
    struct scene_object *owner; /* NULL once cancelled */
    enum job_state state;
    uint32_t serial;   /* owner->serial at the snapshot */
    uint32_t topology; /* owner->topology_serial at the snapshot */
    uint32_t tri_count;
    float *positions;  /* snapshot, 3 per vertex */
    uint32_t *indices; /* snapshot, 3 per triangle */
    struct scene_accel *result; /* when JOB_DONE; NULL if the build failed */
};

static void job_free(struct scene_async_job *job)
{
    if (!job)
        return;
    rt_free(job->positions);
    rt_free(job->indices);
    scene_accel_release(job->result);
    rt_free(job);
}

void scene_async_init(struct scene_async_builder *b, int threads,
                      const struct bvh_build_params *params)
{
    memset(b, 0, sizeof(*b));
    b->threads = threads;
    b->params = *params;
    b->params.builder = BVH_BUILDER_BINNED_SAH;
    pthread_mutex_init(&b->lock, NULL);
    pthread_cond_init(&b->wake, NULL);
}

/* Builds the structure for a snapshot; NULL on allocation failure. */
static struct scene_accel *build_snapshot(struct scene_async_builder *b,
                                          const struct scene_async_job *job)
{
    struct scene_accel_geometry g = {job->positions, job->indices, job->tri_count};
    struct scene_accel *accel = scene_accel_build(&g, &b->params, SCENE_ACCEL_PARALLEL, b->pool, NULL);
    if (accel) {
        accel->serial = job->serial;
        accel->topology = job->topology;
    }
    return accel;
}

static void *build_thread(void *arg)
{
    struct scene_async_builder *b = arg;
    /* The K threads of Wald, Ize and Parker (2008) sec. 6: this one and K - 1 workers. */
    struct rt_pool *pool = rt_pool_create(b->threads);
    pthread_mutex_lock(&b->lock);
    b->pool = pool;
    for (;;) {
        while (!b->quit && !b->head)
            pthread_cond_wait(&b->wake, &b->lock);
        if (b->quit)
            break;
        struct scene_async_job *job = b->head;
        b->head = job->next;
        if (!b->head)
            b->tail = NULL;
        job->next = NULL;
        job->state = JOB_RUNNING;
        pthread_mutex_unlock(&b->lock);

        struct scene_accel *result = build_snapshot(b, job);

        pthread_mutex_lock(&b->lock);
        if (!job->owner) {
            /* Cancelled while running: nobody will collect it. */
            scene_accel_release(result);
            job_free(job);
            continue;
        }
        job->result = result;
        job->state = JOB_DONE;
    }
    b->pool = NULL;
    pthread_mutex_unlock(&b->lock);
    rt_pool_destroy(pool);
    return NULL;
}

int scene_async_threads_running(const struct scene_async_builder *b)
{
    return b->started ? b->threads : 0;
}

int scene_async_request(struct scene_async_builder *b, struct scene_object *object)
{
    if (object->async_job)
        return 0; /* one build in flight per object */
    const struct scene_mesh *mesh = &object->mesh;
    struct scene_async_job *job = rt_calloc(1, sizeof(*job));
    if (!job)
        return -1;
    job->positions = rt_malloc((size_t)mesh->vertex_count * 3 * sizeof(float));
    job->indices = rt_malloc((size_t)mesh->tri_count * 3 * sizeof(uint32_t));
    if (!job->positions || !job->indices) {
        job_free(job);
        return -1;
    }
    memcpy(job->positions, mesh->positions, (size_t)mesh->vertex_count * 3 * sizeof(float));
    memcpy(job->indices, mesh->indices, (size_t)mesh->tri_count * 3 * sizeof(uint32_t));
    job->tri_count = mesh->tri_count;
    job->serial = object->serial;
    job->topology = object->topology_serial;
    job->owner = object;
    job->state = JOB_QUEUED;

    pthread_mutex_lock(&b->lock);
    if (!b->started) {
        if (pthread_create(&b->thread, NULL, build_thread, b) != 0) {
            pthread_mutex_unlock(&b->lock);
            job_free(job);
            return -1;
        }
        b->started = 1;
    }
    if (b->tail)
        b->tail->next = job;
    else
        b->head = job;
    b->tail = job;
    object->async_job = job;
    pthread_cond_signal(&b->wake);
    pthread_mutex_unlock(&b->lock);
    return 0;
}

struct scene_accel *scene_async_collect(struct scene_async_builder *b, struct scene_object *object)
{
    struct scene_accel *result = NULL;
    pthread_mutex_lock(&b->lock);
    struct scene_async_job *job = object->async_job;
    if (job && job->state == JOB_DONE) {
        result = job->result;
        job->result = NULL;
        object->async_job = NULL;
        job_free(job);
    }
    pthread_mutex_unlock(&b->lock);
    return result;
}

/* Unlinks a queued job from the queue (lock held). */
static void unqueue(struct scene_async_builder *b, struct scene_async_job *job)
{
    struct scene_async_job *prev = NULL;
    for (struct scene_async_job *j = b->head; j; prev = j, j = j->next) {
        if (j != job)
            continue;
        if (prev)
            prev->next = j->next;
        else
            b->head = j->next;
        if (b->tail == j)
            b->tail = prev;
        return;
    }
}

void scene_async_cancel(struct scene_async_builder *b, struct scene_object *object)
{
    pthread_mutex_lock(&b->lock);
    struct scene_async_job *job = object->async_job;
    if (job) {
        object->async_job = NULL;
        job->owner = NULL;
        if (job->state == JOB_QUEUED) {
            unqueue(b, job);
            job_free(job);
        } else if (job->state == JOB_DONE) {
            job_free(job);
        }
        /* JOB_RUNNING: the build thread frees it when it finishes. */
    }
    pthread_mutex_unlock(&b->lock);
}

void scene_async_release(struct scene_async_builder *b)
{
    pthread_mutex_lock(&b->lock);
    b->quit = 1;
    pthread_cond_broadcast(&b->wake);
    pthread_mutex_unlock(&b->lock);
    if (b->started)
        pthread_join(b->thread, NULL);
    /* The thread is gone: free what is left (queued jobs; a job that was
     * running has been freed or marked done). */
    for (struct scene_async_job *j = b->head; j;) {
        struct scene_async_job *next = j->next;
        if (j->owner)
            j->owner->async_job = NULL;
        job_free(j);
        j = next;
    }
    b->head = b->tail = NULL;
    pthread_mutex_destroy(&b->lock);
    pthread_cond_destroy(&b->wake);
}
