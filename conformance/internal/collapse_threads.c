/* SPDX-License-Identifier: Apache-2.0 */
/*
 * collapse_threads.c - the triangle boxes and the gather into leaf order
 * (bvh_build.h) and the collapse to the wide layout (trace/bvh4_layout.h)
 * on worker pools of 1 to 4 threads, repeated, for ThreadSanitizer (the
 * "threads" label).
 *
 * All three promise the bytes they give on the calling thread alone: the
 * boxes, the leaf-ordered triangles, and the wide nodes (order bits included),
 * packets, binary sources and packet slots, for widths 4 and 8, with
 * triangles and with range leaves (the top level's).  Byte identity is
 * stronger than equal answers: traversal reads nothing else.  The meshes
 * are large enough that the pooled paths run (levels of more than
 * COLLAPSE_PARALLEL_MIN wide nodes, more than GATHER_PARALLEL_MIN slots
 * and triangles);
 * the test prints the node counts to show it.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int failures;

#include "accel/build_parallel.h"
#include "accel/bvh_build.h"
#include "accel_testgeo.h"
#include "base/alloc.h"
#include "base/pool.h"
#include "base/timer.h"
#include "trace/bvh4_layout.h"
#include "check.h"

#define MAX_THREADS 4
#define REPEATS 2

static int same_wide(const struct bvh4 *a, const struct bvh4 *b)
{
    if (a->width != b->width || a->node_count != b->node_count ||
        a->packet_count != b->packet_count || a->prefetch_top != b->prefetch_top)
        return 0;
    const void *na = a->width == 8 ? (const void *)a->nodes8 : (const void *)a->nodes;
    const void *nb = b->width == 8 ? (const void *)b->nodes8 : (const void *)b->nodes;
    if (a->node_count && memcmp(na, nb, bvh4_node_bytes(a)) != 0)
        return 0;
    if (a->packet_count && (memcmp(a->packets, b->packets, bvh4_leaf_bytes(a)) != 0 ||
                            memcmp(a->packet_slot, b->packet_slot,
                                   a->packet_count * sizeof(uint32_t)) != 0))
        return 0;
    return a->node_count == 0 ||
           memcmp(a->source, b->source, (size_t)a->node_count * a->width * sizeof(uint32_t)) == 0;
}

static void check_mesh(const char *scene, const struct tg_mesh *m, struct rt_pool **pools)
{
    struct aabb *boxes = tg_boxes(m);
    struct aabb *own = accel_triangle_boxes_pool(m->pos, m->idx, m->tri_count, NULL);
    failures += !CHECKF(own != NULL, "%s: boxes failed", scene);
    for (int t = 1; t <= MAX_THREADS && own; t++) {
        for (int rep = 0; rep < REPEATS; rep++) {
            struct aabb *other = accel_triangle_boxes_pool(m->pos, m->idx, m->tri_count, pools[t]);
            failures += !CHECKF(other && memcmp(other, own, m->tri_count * sizeof(*own)) == 0,
                                "%s: boxes on %d threads (repetition %d) differ", scene, t, rep);
            rt_free(other);
        }
    }
    rt_free(own);
    struct bvh b;
    if (accel_build_parallel(&b, boxes, m->tri_count, NULL, pools[2])) {
        failures += !CHECKF(0, "%s: build failed", scene);
        free(boxes);
        return;
    }
    free(boxes);
    float *tri = accel_gather_triangles(&b, m->pos, m->idx);
    failures += !CHECKF(tri != NULL, "%s: gather failed", scene);
    for (int t = 1; t <= MAX_THREADS && tri; t++) {
        for (int rep = 0; rep < REPEATS; rep++) {
            float *other = accel_gather_triangles_pool(&b, m->pos, m->idx, pools[t]);
            failures += !CHECKF(other && memcmp(other, tri, 9 * sizeof(float) * b.prim_count) == 0,
                                "%s: gather on %d threads (repetition %d) differs", scene, t,
                                rep);
            rt_free(other);
        }
    }
    for (uint32_t width = 4; width <= 8 && tri; width += 4) {
        for (int ranges = 0; ranges < 2; ranges++) {
            const float *leaves = ranges ? NULL : tri;
            struct bvh4 ref;
            if (accel_collapse_wide(&ref, &b, leaves, width)) {
                failures += !CHECKF(0, "%s: collapse failed", scene);
                continue;
            }
            double ms[MAX_THREADS + 1] = {0};
            for (int t = 1; t <= MAX_THREADS; t++) {
                for (int rep = 0; rep < REPEATS; rep++) {
                    struct bvh4 w;
                    double t0 = rt_now_ms();
                    if (accel_collapse_wide_pool(&w, &b, leaves, width, pools[t])) {
                        failures += !CHECKF(0, "%s: collapse on %d threads failed", scene, t);
                        continue;
                    }
                    ms[t] += rt_now_ms() - t0;
                    failures += !CHECKF(same_wide(&w, &ref),
                                        "%s: %u-wide%s on %d threads (repetition %d) differs",
                                        scene, width, ranges ? " (range leaves)" : "", t, rep);
                    bvh4_release(&w);
                }
            }
            printf("  %-7s %u-wide %-7s binary nodes %u, wide nodes %u, packets %u: ms on 1..%d "
                   "threads:",
                   scene, width, ranges ? "ranges" : "packets", b.node_count, ref.node_count,
                   ref.packet_count, MAX_THREADS);
            for (int t = 1; t <= MAX_THREADS; t++)
                printf(" %.1f", ms[t] / REPEATS);
            printf("\n");
            bvh4_release(&ref);
        }
    }
    rt_free(tri);
    bvh_release(&b);
}

int main(void)
{
    double t0 = rt_now_ms();
    printf("collapse_threads:\n");
    struct rt_pool *pools[MAX_THREADS + 1];
    pools[0] = NULL;
    for (int t = 1; t <= MAX_THREADS; t++)
        pools[t] = rt_pool_create(t);
    struct tg_rng r;
    tg_seed(&r, 11);
    struct tg_mesh soup, sphere, tiny;
    tg_soup(&soup, 60000, 1.0f, 0.02f, &r);
    const double origin[3] = {0.0, 0.0, 0.0};
    tg_cube_sphere(&sphere, 60, 1, 1.0, origin);
    /* Below every threshold: the pool is asked and not used. */
    tg_soup(&tiny, 300, 1.0f, 0.05f, &r);
    check_mesh("soup", &soup, pools);
    check_mesh("sphere", &sphere, pools);
    check_mesh("tiny", &tiny, pools);
    tg_mesh_free(&soup);
    tg_mesh_free(&sphere);
    tg_mesh_free(&tiny);
    for (int t = 1; t <= MAX_THREADS; t++)
        rt_pool_destroy(pools[t]);
    printf("collapse_threads: %s (%d failures, %.0f ms)\n", failures ? "FAIL" : "ok", failures,
           rt_now_ms() - t0);
    return failures ? 1 : 0;
}
