/* SPDX-License-Identifier: Apache-2.0 */
/*
 * refit.c - serial and parallel BVH refit and the triangle-copy update
 * (refit.h; Wald, Ize and Parker (2008) sec. 6, "Parallel BVH Refit").
 *
 * One routine computes one node's box from its children or its leaf's
 * primitives (refit_node); everything else only decides the order in
 * which nodes are visited: a reverse sweep over the array (serial), a
 * post-order walk (subtrees, and trees not numbered depth-first), and
 * the seeded task scheme of the paper (parallel).  Since the visit order
 * never enters the arithmetic, all of them give the same bits.
 *
 * Leaf primitives come from one of two sources: a per-primitive box array
 * (accel_refit*) or the leaf-ordered triangle copy (accel_refit_mesh,
 * which first rewrites that copy from the mesh).
 */
#include "accel/refit.h"

#include <assert.h>
#include <math.h>
#include <stddef.h>

#include "accel/build_internal.h"
#include "base/atomic.h"

/*
 * Seeding depth of the parallel refit: the seeder walks the top k levels,
 * with k the smallest depth giving REFIT_TASKS_PER_THREAD subtrees per
 * thread in a balanced tree.  Wald, Ize and Parker (2008) sec. 6 leaves k open; several
 * subtrees per thread let the atomic counter even out unbalanced trees
 * (a refit costs in proportion to the subtree), and the top levels the
 * merging thread refits alone stay a few hundred nodes.
 */
#define REFIT_TASKS_PER_THREAD 8
/* At most 2^REFIT_MAX_SEED_LEVELS subtrees: the seed lists live on the
 * caller's stack (16 KB), so the refit needs no allocation. */
#define REFIT_MAX_SEED_LEVELS 10
#define REFIT_MAX_SEEDS (1u << REFIT_MAX_SEED_LEVELS)
/* Triangle copies per work item of the parallel triangle update: large
 * enough that the atomic counter is noise, small enough to balance. */
#define REFIT_TRIANGLE_CHUNK 4096u

/* Where a leaf's primitives come from: boxes by primitive index, or
 * the leaf-ordered triangle copy (9 floats per slot, already updated). */
struct refit_source {
    const struct aabb *prim_boxes;
    const float *tri;
};

static inline void copy_triangle(float *dst, const float *positions, const uint32_t *vi)
{
    for (int corner = 0; corner < 3; corner++) {
        const float *src = &positions[3 * (size_t)vi[corner]];
        dst[3 * corner + 0] = src[0];
        dst[3 * corner + 1] = src[1];
        dst[3 * corner + 2] = src[2];
    }
}

/* The one place a box is computed (see the file comment). */
static void refit_node(const struct bvh *bvh, uint32_t index, const struct refit_source *src)
{
    struct bvh_node *node = &bvh->nodes[index];
    float lo[3] = {INFINITY, INFINITY, INFINITY};
    float hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    if (node->count) {
        uint32_t end = node->first + node->count;
        for (uint32_t slot = node->first; slot < end; slot++) {
            if (src->prim_boxes) {
                const struct aabb *b = &src->prim_boxes[bvh->prim_index[slot]];
                for (int k = 0; k < 3; k++) {
                    lo[k] = build_min(lo[k], b->min[k]);
                    hi[k] = build_max(hi[k], b->max[k]);
                }
            } else {
                const float *v = &src->tri[9 * (size_t)slot];
                for (int corner = 0; corner < 3; corner++) {
                    for (int k = 0; k < 3; k++) {
                        lo[k] = build_min(lo[k], v[3 * corner + k]);
                        hi[k] = build_max(hi[k], v[3 * corner + k]);
                    }
                }
            }
        }
    } else {
        const struct bvh_node *a = &bvh->nodes[node->first];
        const struct bvh_node *b = &bvh->nodes[node->first + 1];
        for (int k = 0; k < 3; k++) {
            lo[k] = build_min(a->aabb_min[k], b->aabb_min[k]);
            hi[k] = build_max(a->aabb_max[k], b->aabb_max[k]);
        }
    }
    for (int k = 0; k < 3; k++) {
        node->aabb_min[k] = lo[k];
        node->aabb_max[k] = hi[k];
    }
}

/*
 * Post-order walk of the subtree at root with a fixed stack: each entry
 * is a node and how many of its children have been entered.  Depth <=
 * BVH_MAX_DEPTH (bvh_layout.h) bounds the stack; a node whose children are out
 * of range, or that would overflow the stack (both impossible for a valid
 * tree), is treated as done rather than followed.
 */
static void refit_subtree(const struct bvh *bvh, uint32_t root, const struct refit_source *src)
{
    struct {
        uint32_t node;
        uint32_t entered;
    } stack[BVH_MAX_DEPTH + 2];
    uint32_t sp = 0;
    stack[sp].node = root;
    stack[sp].entered = 0;
    sp++;
    while (sp > 0) {
        uint32_t ni = stack[sp - 1].node;
        const struct bvh_node *node = &bvh->nodes[ni];
        uint32_t entered = stack[sp - 1].entered;
        int valid_inner = !node->count && node->first < bvh->node_count - 1;
        assert(node->count || valid_inner);
        if (valid_inner && entered < 2 && sp < BVH_MAX_DEPTH + 2) {
            stack[sp - 1].entered = entered + 1;
            stack[sp].node = node->first + entered;
            stack[sp].entered = 0;
            sp++;
            continue;
        }
        if (node->count || valid_inner)
            refit_node(bvh, ni, src);
        sp--;
    }
}

/* Serial refit: reverse sweep while every inner node's children follow
 * it (the builders' numbering), else the post-order walk. */
static void refit_serial(struct bvh *bvh, const struct refit_source *src)
{
    uint32_t n = bvh->node_count;
    for (uint32_t i = n; i-- > 0;) {
        const struct bvh_node *node = &bvh->nodes[i];
        if (!node->count && !(node->first > i && node->first < n - 1)) {
            /* Children before the parent: this sweep would read stale
             * boxes.  Nothing written so far is wrong (each box written
             * was computed from already final children), but the walk
             * recomputes everything, which is simpler to reason about. */
            refit_subtree(bvh, 0, src);
            return;
        }
        refit_node(bvh, i, src);
    }
}

/* ------------------------------------------------------------ parallel */

struct refit_shared {
    struct bvh *bvh;
    const struct refit_source *src;
    const uint32_t *tasks; /* subtree roots, and leaves above the seed depth */
    uint32_t task_count;
    const uint32_t *top; /* inner nodes above the seed depth, in pre-order */
    uint32_t top_count;
    uint32_t next_task; /* atomic */
    uint32_t finished;  /* atomic */
};

static void refit_task(void *arg, int worker)
{
    (void)worker;
    struct refit_shared *sh = arg;
    for (;;) {
        uint32_t t = rt_atomic_fetch_add_relaxed(&sh->next_task, 1);
        if (t >= sh->task_count)
            return;
        refit_subtree(sh->bvh, sh->tasks[t], sh->src);
        /* Release this subtree's boxes; the last thread acquires all of
         * them (the increments form one release sequence) and merges the
         * top: "the last thread to finish a subtree update also performs
         * the final merge" (Wald, Ize and Parker (2008) sec. 6). */
        uint32_t done = rt_atomic_add_fetch_acq_rel(&sh->finished, 1);
        if (done == sh->task_count) {
            for (uint32_t i = sh->top_count; i-- > 0;)
                refit_node(sh->bvh, sh->top[i], sh->src);
        }
    }
}

/*
 * The seeder (Wald, Ize and Parker (2008) sec. 6): walks the top `levels` levels from the
 * root in pre-order, recording inner nodes above that depth in top[] and
 * the nodes at that depth, and leaves above it, in tasks[].  Reverse
 * pre-order visits children before parents, which is the merge order.
 */
static void seed(const struct bvh *bvh, uint32_t levels, uint32_t *tasks, uint32_t *task_count,
                 uint32_t *top, uint32_t *top_count)
{
    struct {
        uint32_t node;
        uint32_t depth;
    } stack[REFIT_MAX_SEED_LEVELS + 2];
    uint32_t sp = 0;
    uint32_t nt = 0;
    uint32_t ntop = 0;
    stack[sp].node = 0;
    stack[sp].depth = 0;
    sp++;
    while (sp > 0) {
        sp--;
        uint32_t ni = stack[sp].node;
        uint32_t depth = stack[sp].depth;
        const struct bvh_node *node = &bvh->nodes[ni];
        if (node->count || depth == levels || !(node->first < bvh->node_count - 1)) {
            tasks[nt++] = ni;
            continue;
        }
        top[ntop++] = ni;
        /* Right pushed first: left subtree first, as the builders number. */
        stack[sp].node = node->first + 1;
        stack[sp].depth = depth + 1;
        sp++;
        stack[sp].node = node->first;
        stack[sp].depth = depth + 1;
        sp++;
    }
    *task_count = nt;
    *top_count = ntop;
}

static void refit_parallel(struct bvh *bvh, const struct refit_source *src, struct rt_pool *pool)
{
    int threads = rt_pool_threads(pool);
    if (threads < 2 || bvh->node_count < 3) {
        refit_serial(bvh, src);
        return;
    }
    uint32_t levels = build_ceil_log2((uint32_t)threads * REFIT_TASKS_PER_THREAD);
    if (levels > REFIT_MAX_SEED_LEVELS)
        levels = REFIT_MAX_SEED_LEVELS;
    /* A binary tree has at most 2^levels nodes at depth `levels`, plus
     * leaves above it: at most 2^levels tasks in all, 2^levels - 1 tops. */
    uint32_t tasks[REFIT_MAX_SEEDS];
    uint32_t top[REFIT_MAX_SEEDS];
    struct refit_shared sh;
    sh.bvh = bvh;
    sh.src = src;
    sh.tasks = tasks;
    sh.top = top;
    sh.next_task = 0;
    sh.finished = 0;
    seed(bvh, levels, tasks, &sh.task_count, top, &sh.top_count);
    rt_pool_run_shared(pool, refit_task, &sh);
}

void accel_refit(struct bvh *bvh, const struct aabb *prim_boxes)
{
    struct refit_source src = {prim_boxes, NULL};
    refit_serial(bvh, &src);
}

void accel_refit_parallel(struct bvh *bvh, const struct aabb *prim_boxes, struct rt_pool *pool)
{
    struct refit_source src = {prim_boxes, NULL};
    refit_parallel(bvh, &src, pool);
}

/* ------------------------------------------------------------ triangles */

static void copy_slots(const struct bvh *bvh, float *tri, const float *positions,
                       const uint32_t *indices, uint32_t begin, uint32_t end)
{
    for (uint32_t slot = begin; slot < end; slot++)
        copy_triangle(&tri[9 * (size_t)slot], positions,
                      &indices[3 * (size_t)bvh->prim_index[slot]]);
}

void accel_refit_triangles(const struct bvh *bvh, float *tri, const float *positions,
                           const uint32_t *indices)
{
    copy_slots(bvh, tri, positions, indices, 0, bvh->prim_count);
}

struct triangle_shared {
    const struct bvh *bvh;
    float *tri;
    const float *positions;
    const uint32_t *indices;
    uint32_t next_chunk; /* atomic */
};

static void triangle_task(void *arg, int worker)
{
    (void)worker;
    struct triangle_shared *sh = arg;
    const uint32_t count = sh->bvh->prim_count;
    for (;;) {
        uint32_t chunk = rt_atomic_fetch_add_relaxed(&sh->next_chunk, 1);
        /* In 64 bits: the last chunk's end may pass 2^32. */
        uint64_t begin = (uint64_t)chunk * REFIT_TRIANGLE_CHUNK;
        if (begin >= count)
            return;
        uint64_t end = begin + REFIT_TRIANGLE_CHUNK;
        copy_slots(sh->bvh, sh->tri, sh->positions, sh->indices, (uint32_t)begin,
                   end < count ? (uint32_t)end : count);
    }
}

void accel_refit_triangles_parallel(const struct bvh *bvh, float *tri, const float *positions,
                                    const uint32_t *indices, struct rt_pool *pool)
{
    if (rt_pool_threads(pool) < 2 || bvh->prim_count <= REFIT_TRIANGLE_CHUNK) {
        accel_refit_triangles(bvh, tri, positions, indices);
        return;
    }
    struct triangle_shared sh = {bvh, tri, positions, indices, 0};
    rt_pool_run_shared(pool, triangle_task, &sh);
}

void accel_refit_mesh(struct bvh *bvh, float *tri, const float *positions,
                      const uint32_t *indices, struct rt_pool *pool)
{
    /* Two passes, not Wald, Ize and Parker's (2008) interleaving: the triangle update in
     * slot order keeps many vertex fetches in flight, and the refit then
     * reads tri sequentially.  Fused into the refit's node walk, each
     * leaf's dependent fetches (slot -> indices -> positions) waited
     * behind the walk's mispredicted leaf/inner branches: 3.5x slower
     * on 1M triangles. */
    accel_refit_triangles_parallel(bvh, tri, positions, indices, pool);
    struct refit_source src = {NULL, tri};
    refit_parallel(bvh, &src, pool);
}
