/* SPDX-License-Identifier: Apache-2.0 */
/*
 * parallel_build_threads.c - the parallel build (build_parallel.h) and
 * the parallel refit (refit.h) on worker pools of 1 to 4 threads,
 * repeated, for ThreadSanitizer (the "threads" label).
 *
 * Every combination of the two-stage build must give, on every pool and
 * in every repetition, the very tree it gives on the calling thread alone
 * (build_parallel.h promises independence of the thread count, which is
 * stronger than determinism per thread count), and that tree must meet
 * bvh_layout.h's contract.  The parallel refits must give the serial refit's
 * bits.  Two builds on two application threads, each with its own pool,
 * must not disturb each other.
 */
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int failures;

#include "accel/build_parallel.h"
#include "accel/bvh_build.h"
#include "accel/refit.h"
#include "accel_testgeo.h"
#include "base/alloc.h"
#include "base/pool.h"
#include "base/timer.h"
#include "bvh_contract.h"

#define MAX_THREADS 4
#define REPEATS 2

static const struct bvh_parallel_params combos[] = {
    {BVH_PARTITION_BINNING, BVH_SUBTREE_SAH},
    {BVH_PARTITION_GRID, BVH_SUBTREE_SAH},
    {BVH_PARTITION_GRID, BVH_SUBTREE_MEDIAN},
    {BVH_PARTITION_BINNING, BVH_SUBTREE_MEDIAN},
};
static const char *const combo_name[] = {"SAH+SAH", "grid+SAH", "grid+BIH", "SAH+BIH"};
#define COMBOS (sizeof(combos) / sizeof(combos[0]))

static void check_builds(const char *scene, const struct tg_mesh *m, struct rt_pool **pools)
{
    struct aabb *boxes = tg_alloc(sizeof(*boxes) * m->tri_count);
    struct aabb *tb = tg_boxes(m);
    memcpy(boxes, tb, sizeof(*boxes) * m->tri_count);
    free(tb);
    uint32_t n = m->tri_count;
    for (size_t c = 0; c < COMBOS; c++) {
        char what[96];
        struct bvh_build_params p;
        bvh_build_params_default(&p);
        /* Median subtrees with the looser leaves of per-frame rebuilds. */
        if (combos[c].subtree == BVH_SUBTREE_MEDIAN)
            p.leaf_growth = BVH_LEAF_GROWTH_REBUILD;
        struct bvh ref;
        if (accel_build_parallel_ex(&ref, boxes, n, &p, &combos[c], NULL)) {
            failures += !CHECKF(0, "%s/%s: build failed", scene, combo_name[c]);
            continue;
        }
        snprintf(what, sizeof(what), "%s/%s", scene, combo_name[c]);
        bvh_check_tree(what, &ref, boxes, n, BVH_MAX_LEAF_SIZE, 1);
        double ms[MAX_THREADS + 1] = {0};
        for (int t = 1; t <= MAX_THREADS; t++) {
            for (int rep = 0; rep < REPEATS; rep++) {
                struct bvh b;
                double t0 = rt_now_ms();
                if (accel_build_parallel_ex(&b, boxes, n, &p, &combos[c], pools[t])) {
                    failures += !CHECKF(0, "%s: build on %d threads failed", what, t);
                    continue;
                }
                ms[t] += rt_now_ms() - t0;
                failures += !CHECKF(bvh_same_tree(&b, &ref),
                         "%s: %d threads (repetition %d) built another tree", what, t, rep);
                bvh_release(&b);
            }
        }
        printf("  %-8s %-8s n=%u nodes %u: ms per build on 1..%d threads:", scene,
               combo_name[c], n, ref.node_count, MAX_THREADS);
        for (int t = 1; t <= MAX_THREADS; t++)
            printf(" %.1f", ms[t] / REPEATS);
        printf("\n");
        bvh_release(&ref);
    }
    free(boxes);
}

/* accel_build_parallel_triangles must give accel_build_parallel's tree
 * on accel_triangle_boxes_pool's boxes, bit for bit, on every pool (also
 * for a mesh small enough for the serial fallback: `count` triangles). */
static void check_triangles(const char *scene, const struct tg_mesh *m, uint32_t count,
                            struct rt_pool **pools)
{
    struct aabb *boxes = accel_triangle_boxes_pool(m->pos, m->idx, count, NULL);
    struct bvh ref;
    if (!boxes || accel_build_parallel(&ref, boxes, count, NULL, NULL)) {
        failures += !CHECKF(0, "%s: boxes or build failed", scene);
        rt_free(boxes);
        return;
    }
    for (int t = 0; t <= MAX_THREADS; t++) {
        struct bvh b;
        if (accel_build_parallel_triangles(&b, m->pos, m->idx, count, NULL, pools[t], NULL)) {
            failures += !CHECKF(0, "%s: triangle build on %d threads failed", scene, t);
            continue;
        }
        failures += !CHECKF(bvh_same_tree(&b, &ref),
                            "%s (%u triangles): the triangle build on %d threads is another tree",
                            scene, count, t);
        bvh_release(&b);
    }
    bvh_release(&ref);
    rt_free(boxes);
}

static void check_refits(const char *scene, struct tg_mesh *m, struct rt_pool **pools)
{
    struct aabb *boxes = tg_boxes(m);
    uint32_t n = m->tri_count;
    struct bvh b;
    if (accel_build_parallel(&b, boxes, n, NULL, pools[2])) {
        failures += !CHECKF(0, "%s: build failed", scene);
        free(boxes);
        return;
    }
    float *tri = accel_gather_triangles(&b, m->pos, m->idx);
    struct tg_rng r;
    tg_seed(&r, 8);
    for (uint32_t v = 0; v < 3 * m->vertex_count; v++)
        m->pos[v] += 0.05f * tg_range(&r, -1.0f, 1.0f);
    free(boxes);
    boxes = tg_boxes(m);
    size_t node_bytes = sizeof(*b.nodes) * b.node_count;
    struct bvh_node *original = tg_alloc(node_bytes);
    struct bvh_node *serial = tg_alloc(node_bytes);
    float *serial_tri = tg_alloc(9 * sizeof(float) * n);
    memcpy(original, b.nodes, node_bytes);
    accel_refit(&b, boxes);
    memcpy(serial, b.nodes, node_bytes);
    accel_refit_triangles(&b, tri, m->pos, m->idx);
    memcpy(serial_tri, tri, 9 * sizeof(float) * n);
    bvh_check_tree("refit", &b, boxes, n, BVH_MAX_LEAF_SIZE, 1);
    for (int t = 1; t <= MAX_THREADS; t++) {
        for (int rep = 0; rep < REPEATS; rep++) {
            memcpy(b.nodes, original, node_bytes);
            memset(tri, 0, 9 * sizeof(float) * n);
            accel_refit_parallel(&b, boxes, pools[t]);
            accel_refit_triangles_parallel(&b, tri, m->pos, m->idx, pools[t]);
            failures += !CHECKF(
                     memcmp(b.nodes, serial, node_bytes) == 0 &&
                         memcmp(tri, serial_tri, 9 * sizeof(float) * n) == 0,
                     "%s: parallel refit on %d threads differs", scene, t);
            memcpy(b.nodes, original, node_bytes);
            memset(tri, 0, 9 * sizeof(float) * n);
            accel_refit_mesh(&b, tri, m->pos, m->idx, pools[t]);
            failures += !CHECKF(
                     memcmp(b.nodes, serial, node_bytes) == 0 &&
                         memcmp(tri, serial_tri, 9 * sizeof(float) * n) == 0,
                     "%s: accel_refit_mesh on %d threads differs", scene, t);
        }
    }
    free(original);
    free(serial);
    free(serial_tri);
    rt_free(tri);
    bvh_release(&b);
    free(boxes);
}

/* Two application threads, each building with its own pool. */
struct concurrent {
    const struct aabb *boxes;
    uint32_t n;
    struct bvh_parallel_params parallel;
    struct bvh result;
    int status;
};

static void *concurrent_build(void *arg)
{
    struct concurrent *c = arg;
    struct rt_pool *pool = rt_pool_create(2);
    c->status = accel_build_parallel_ex(&c->result, c->boxes, c->n, NULL, &c->parallel, pool);
    rt_pool_destroy(pool);
    return NULL;
}

static void check_concurrent(const struct tg_mesh *m)
{
    struct aabb *boxes = tg_boxes(m);
    struct concurrent job[2];
    pthread_t thread[2];
    for (int i = 0; i < 2; i++) {
        memset(&job[i], 0, sizeof(job[i]));
        job[i].boxes = boxes;
        job[i].n = m->tri_count;
        job[i].parallel = combos[2 * i];
        if (pthread_create(&thread[i], NULL, concurrent_build, &job[i]) != 0) {
            fprintf(stderr, "cannot start a thread\n");
            exit(2);
        }
    }
    for (int i = 0; i < 2; i++) {
        pthread_join(thread[i], NULL);
        failures += !CHECKF(job[i].status == 0, "concurrent build %d failed", i);
        struct bvh ref;
        if (job[i].status == 0 &&
            accel_build_parallel_ex(&ref, boxes, m->tri_count, NULL, &job[i].parallel, NULL) ==
                0) {
            failures += !CHECKF(bvh_same_tree(&ref, &job[i].result), "concurrent build %d differs",
                     i);
            bvh_release(&ref);
        }
        bvh_release(&job[i].result);
    }
    free(boxes);
}

int main(void)
{
    double t0 = rt_now_ms();
    printf("parallel_build_threads:\n");
    struct rt_pool *pools[MAX_THREADS + 1];
    pools[0] = NULL;
    for (int t = 1; t <= MAX_THREADS; t++) {
        pools[t] = rt_pool_create(t);
        failures += !CHECKF(rt_pool_threads(pools[t]) == t, "pool of %d threads has %d", t,
                 rt_pool_threads(pools[t]));
    }
    struct tg_rng r;
    tg_seed(&r, 5);
    struct tg_mesh soup, sphere;
    /* Large enough for a few dozen subtrees (PARALLEL_MIN_SUBTREE). */
    tg_soup(&soup, 50000, 1.0f, 0.02f, &r);
    const double origin[3] = {0.0, 0.0, 0.0};
    tg_cube_sphere(&sphere, 50, 1, 1.0, origin);
    check_builds("soup", &soup, pools);
    check_builds("sphere", &sphere, pools);
    check_triangles("soup", &soup, soup.tri_count, pools);
    check_triangles("sphere", &sphere, sphere.tri_count, pools);
    check_triangles("soup", &soup, 100, pools);
    check_refits("soup", &soup, pools);
    check_refits("sphere", &sphere, pools);
    check_concurrent(&sphere);
    tg_mesh_free(&soup);
    tg_mesh_free(&sphere);
    for (int t = 1; t <= MAX_THREADS; t++)
        rt_pool_destroy(pools[t]);
    printf("parallel_build_threads: %s (%d failures, %.0f ms)\n", failures ? "FAIL" : "ok",
           failures, rt_now_ms() - t0);
    return failures ? 1 : 0;
}
