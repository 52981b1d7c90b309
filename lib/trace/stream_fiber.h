/* SPDX-License-Identifier: Apache-2.0 */
/*
 * stream_fiber.h - kernels.h's stream_fiber: a stream's rays walked two
 * (or more) at a time on one thread, each by walk1's walk on a coroutine
 * of its own (walk_fiber.h says why), switching where a walk is about to
 * wait on memory.  Included by a SIMD unit with the 8-wide walk after
 * traverse_wide.h (traverse_avx2.c), with TRACE_WIDE_STREAM_FIBER
 * defined as the chooser's name; its functions come after every walk of
 * the unit, so the unit's other functions keep their code and places.
 *
 * Each ray's walk is WIDE8_WALK1's over walk_wide8_ray_leaf8 (the walk
 * kernels.h's walk1 returns), from a third copy of its text
 * (traverse_wide8_ray.h with WIDE8_RAY_FIBER) whose only additions are
 * the yields: the same node tests, leaves, order and stack, so the same
 * answer for every ray, written to the caller's arrays at the ray's
 * index (conformance/internal/stream_fiber checks it bit for bit).
 */
#include <rt/rt.h>

#include "trace/walk_fiber.h"

#if TRACE_FIBER && defined(TRACE_WIDE_STREAM_FIBER)

/* The yield at a leaf (traverse_wide8_ray.h): the packet lines the leaf
 * reads (n triangles from p: 160-byte packets, so three lines for a
 * packet and six for two wherever they start), then the other walks. */
#define WIDE8_FIBER_LEAF_YIELD(fiber, p, n)                                                      \
    do {                                                                                         \
        const char *wide_fl_ = (const char *)(const void *)(p);                                  \
        _mm_prefetch(wide_fl_, _MM_HINT_T0);                                                     \
        _mm_prefetch(wide_fl_ + 64, _MM_HINT_T0);                                                \
        _mm_prefetch(wide_fl_ + 159, _MM_HINT_T0);                                               \
        if ((n) > 4) {                                                                           \
            _mm_prefetch(wide_fl_ + 192, _MM_HINT_T0);                                           \
            _mm_prefetch(wide_fl_ + 256, _MM_HINT_T0);                                           \
            _mm_prefetch(wide_fl_ + 319, _MM_HINT_T0);                                           \
        }                                                                                        \
        trace_fiber_yield(fiber);                                                                \
    } while (0)

/* The yield at an inner node the walk goes to next: its four lines (a
 * closest-hit walk has requested them already), then the other walks.
 * WIDE8_FIBER_NODES 0 leaves the nodes without a yield.  Measured on a
 * Zen 3 core (EPYC, 32 MB L3), bumpy's random rays (a 60 MB layout),
 * ours/Embree: walk1 0.89; leaf yields only, 2 or 4 rays in flight 1.08
 * and 1.10; leaf and node yields 1.13 and 1.45, 8 in flight as 4
 * (docs/performance-log.md, round 60); the node yields cost 344
 * instructions a soup random ray (callgrind, 2125 -> 2469 with two rays
 * in flight). */
#ifndef WIDE8_FIBER_NODES
#define WIDE8_FIBER_NODES 1
#endif
/* The nodes of the top three levels: the collapse numbers the nodes
 * breadth first (collapse4.c), so these are the first 1 + 8 + 64 (18 KB),
 * which every walk visits and which stay in the caches; a yield there
 * overlaps nothing.  Without their yields, four rays in flight,
 * ours/Embree: bumpy's random rays 1.445 -> 1.495, the kitchen's 0.685
 * -> 0.755, gears' 0.68 -> 0.79, the soup's level; bumpy's random rays
 * 1208 -> 1114 instructions (callgrind; walk1 899). */
#ifndef WIDE8_FIBER_HOT_NODES
#define WIDE8_FIBER_HOT_NODES 73u
#endif
#define WIDE8_FIBER_NODE_YIELD(fiber, node)                                                      \
    do {                                                                                         \
        if (WIDE8_FIBER_NODES && cur >= WIDE8_FIBER_HOT_NODES) {                                 \
            if (any_hit)                                                                         \
                WIDE_PREFETCH_LINES(node, 4);                                                    \
            trace_fiber_yield(fiber);                                                            \
        }                                                                                        \
    } while (0)

#define WIDE8_RAY walk_wide8_ray_leaf8_fiber
#define WIDE8_RAY_LEAF8 1
#define WIDE8_RAY_FIBER 1
#include "trace/traverse_wide8_ray.h"
#undef WIDE8_RAY
#undef WIDE8_RAY_LEAF8
#undef WIDE8_RAY_FIBER

typedef int (*wide8_fiber_walk_fn)(const struct bvh4 *wide, const float org[3],
                                   const float dir[3], float tmin, float t_max,
                                   struct trace_hit *hit, struct trace_fiber *fiber);

/* WIDE8_WALK1 without counters, its walk the fiber copy: the same
 * set-up, the same float walk for a ray whose tmin is not >= 0 (it does
 * not yield: a cold path). */
#define WIDE8_WALK1_FIBER(name, any_hit, leave_early)                                           \
    static int name(const struct bvh4 *wide, const float org[3], const float dir[3],            \
                    float tmin, float t_max, struct trace_hit *hit,                             \
                    struct trace_fiber *fiber) WIDE_NOINLINE;                                   \
    static int name(const struct bvh4 *wide, const float org[3], const float dir[3],            \
                    float tmin, float t_max, struct trace_hit *hit, struct trace_fiber *fiber)  \
    {                                                                                           \
        struct trace_ray ray;                                                                   \
        struct ray_lanes lanes;                                                                 \
        trace_ray_setup_lanes(&ray, &lanes, org, dir, tmin);                                    \
        struct wide_ray_state rs;                                                               \
        struct wide_state *const s = &rs.s;                                                     \
        const int any_walk = (any_hit) != 0;                                                    \
        wide_state_init1(s, &ray, t_max, any_walk, 0, hit);                                     \
        if (!(tmin >= 0.0f) || WIDE8_WALK1_FAR(wide, any_hit) ||                                \
            WIDE8_FUSED_UNCOVERED(rs, lanes, any_hit))                                          \
            return wide8_walk_end(s, wide8_walk_tmin_other(wide, s, any_walk, 0), any_hit, 0,  \
                                  NULL);                                                        \
        if (any_hit)                                                                            \
            tri4_ray_init_scalar_lanes(&s->r4, &lanes, tmin);                                   \
        else                                                                                    \
            tri4_ray_init_node_org(&s->r4, &lanes, tmin);                                       \
        const int done = walk_wide8_ray_leaf8_fiber(wide, s, any_hit, 0, leave_early, &lanes,   \
                                                    fiber);                                     \
        return wide8_walk_end(s, done, any_hit, 0, NULL);                                       \
    }

WIDE8_WALK1_FIBER(wide8_walk1_fiber_closest, 0, 0)
WIDE8_WALK1_FIBER(wide8_walk1_fiber_closest_early, 0, 1)
WIDE8_WALK1_FIBER(wide8_walk1_fiber_any, 1, 1)
WIDE8_WALK1_FIBER(wide8_walk1_fiber_any_longest, WIDE_ANY_LONGEST, 1)

/* The most coroutines a stream runs at once, and each one's stack: the
 * walk's frame is about 6 KB (its three stacks of WIDE_STACK entries),
 * a leaf's a few hundred bytes. */
#define WIDE8_STREAM_FIBERS_MAX 4
#define WIDE8_STREAM_FIBER_STACK (20 * 1024)

/* What the coroutines share: the rays, the next one not yet taken, the
 * answers' arrays, and the stack pointer of the caller that started
 * them (the last coroutine to end resumes it). */
struct wide8_stream_job {
    const struct bvh4 *wide;
    wide8_fiber_walk_fn walk;
    const RTray *rays;
    uint32_t count;
    uint32_t next;
    struct trace_hit *hits;
    int *answers;
    void *caller_sp;
};

/* A coroutine's body: the stream's next ray until none is left, each
 * answer at its ray's index. */
static void wide8_stream_fiber_body(struct trace_fiber *f) WIDE_NOINLINE;
static void wide8_stream_fiber_body(struct trace_fiber *f)
{
    struct wide8_stream_job *const job = f->job;
    for (;;) {
        const uint32_t i = job->next;
        if (i >= job->count)
            break;
        job->next = i + 1;
        const RTray *r = &job->rays[i];
        job->answers[i] = job->walk(job->wide, r->org, r->dir, r->tmin, r->tmax,
                                    job->hits ? &job->hits[i] : NULL, f);
    }
    trace_fiber_exit(f, job->caller_sp);
}

static void wide8_stream_run(const struct bvh4 *wide, wide8_fiber_walk_fn ray_walk,
                             const RTray *rays, uint32_t count, unsigned fibers,
                             struct trace_hit *hits, int *answers)
{
    if (!count)
        return;
    if (fibers < 1)
        fibers = 1;
    if (fibers > WIDE8_STREAM_FIBERS_MAX)
        fibers = WIDE8_STREAM_FIBERS_MAX;
    if (fibers > count)
        fibers = count;
    struct wide8_stream_job job = {wide, ray_walk, rays, count, 0, hits, answers, NULL};
    struct trace_fiber ring[WIDE8_STREAM_FIBERS_MAX];
    uint64_t stacks[WIDE8_STREAM_FIBERS_MAX][WIDE8_STREAM_FIBER_STACK / sizeof(uint64_t)];
    for (unsigned k = 0; k < fibers; k++) {
        trace_fiber_prepare(&ring[k], stacks[k], sizeof(stacks[k]), wide8_stream_fiber_body,
                            &job);
        ring[k].next = &ring[(k + 1) % fibers];
        ring[k].prev = &ring[(k + fibers - 1) % fibers];
    }
    trace_fiber_switch(&job.caller_sp, ring[0].sp);
}

#define WIDE8_STREAM(name, ray_walk)                                                              \
    static void name(const struct bvh4 *wide, const RTray *rays, uint32_t count,                \
                     unsigned fibers, struct trace_hit *hits, int *answers)                     \
    {                                                                                           \
        wide8_stream_run(wide, ray_walk, rays, count, fibers, hits, answers);                     \
    }
WIDE8_STREAM(wide8_stream_closest, wide8_walk1_fiber_closest)
WIDE8_STREAM(wide8_stream_closest_early, wide8_walk1_fiber_closest_early)
WIDE8_STREAM(wide8_stream_any, wide8_walk1_fiber_any)
WIDE8_STREAM(wide8_stream_any_longest, wide8_walk1_fiber_any_longest)

/* kernels.h's stream_fiber: the stream whose walks are the ones
 * TRACE_WIDE_WALK1 returns for the layout (whether it pays there is
 * trace_stream_fiber_pays's question). */
static trace_stream_fn TRACE_WIDE_STREAM_FIBER(const struct bvh4 *wide, int any_hit)
{
    if (wide->width != 8 || !wide->node_count)
        return NULL;
    if (any_hit)
        return wide->any_longest ? wide8_stream_any_longest : wide8_stream_any;
    return wide->prefetch_top ? wide8_stream_closest_early : wide8_stream_closest;
}
#endif
