/* SPDX-License-Identifier: Apache-2.0 */
/*
 * refit.c - BVH refit and triangle-copy update (refit.h) against
 * references computed from scratch.
 *
 * Meshes (a closed sphere, a soup, a height field) are built by the
 * binned, median and grid+BIH builders, then every vertex moves at random
 * (small wobble and large jumps).  After accel_refit every node box must
 * equal, bit for bit, the union of the boxes of all primitives below it
 * computed naively per node; the triangle copy must equal a fresh
 * accel_gather_triangles; accel_refit_mesh must give both at once; the
 * parallel versions on pools of 1 to 4 threads must give the same bits
 * as the serial ones; and tracing the refit tree must give the brute-
 * force hits of the moved mesh.  A tree renumbered so that children come
 * before their parents (what a restructuring may leave) must refit just
 * as well, and the empty and one-primitive trees must be left valid.
 */
#include <math.h>
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
#include "trace/trace.h"

#define MAX_THREADS 4

/* Naive reference: the union of the prim boxes of every slot under node
 * ni, from scratch (no child box is reused). */
static void naive_box(const struct bvh *b, uint32_t ni, const struct aabb *boxes,
                      struct aabb *out)
{
    const struct bvh_node *n = &b->nodes[ni];
    if (n->count) {
        *out = aabb_empty();
        for (uint32_t s = n->first; s < n->first + n->count; s++)
            aabb_grow(out, &boxes[b->prim_index[s]]);
        return;
    }
    struct aabb l;
    struct aabb r;
    naive_box(b, n->first, boxes, &l);
    naive_box(b, n->first + 1, boxes, &r);
    *out = l;
    aabb_grow(out, &r);
}

static void check_boxes(const char *what, const struct bvh *b, const struct aabb *boxes)
{
    int before = failures;
    for (uint32_t i = 0; i < b->node_count && failures - before < 3; i++) {
        struct aabb want;
        naive_box(b, i, boxes, &want);
        failures += !CHECKF(
                 memcmp(b->nodes[i].aabb_min, want.min, sizeof(want.min)) == 0 &&
                     memcmp(b->nodes[i].aabb_max, want.max, sizeof(want.max)) == 0,
                 "%s: node %u box (%g %g %g)-(%g %g %g), union of its primitives (%g %g %g)-(%g "
                 "%g %g)",
                 what, i, (double)b->nodes[i].aabb_min[0], (double)b->nodes[i].aabb_min[1],
                 (double)b->nodes[i].aabb_min[2], (double)b->nodes[i].aabb_max[0],
                 (double)b->nodes[i].aabb_max[1], (double)b->nodes[i].aabb_max[2],
                 (double)want.min[0], (double)want.min[1], (double)want.min[2],
                 (double)want.max[0], (double)want.max[1], (double)want.max[2]);
    }
}

static struct bvh copy_tree(const struct bvh *b)
{
    struct bvh c = *b;
    c.nodes = tg_alloc(sizeof(*c.nodes) * (b->node_count ? b->node_count : 1));
    c.prim_index = tg_alloc(sizeof(uint32_t) * (b->prim_count ? b->prim_count : 1));
    if (b->node_count)
        memcpy(c.nodes, b->nodes, sizeof(*c.nodes) * b->node_count);
    if (b->prim_count)
        memcpy(c.prim_index, b->prim_index, sizeof(uint32_t) * b->prim_count);
    return c;
}

static void free_copy(struct bvh *c)
{
    free(c->nodes);
    free(c->prim_index);
}

static int same_nodes(const struct bvh *a, const struct bvh *b)
{
    return a->node_count == b->node_count &&
           memcmp(a->nodes, b->nodes, sizeof(*a->nodes) * a->node_count) == 0;
}

/* Moves every vertex: a wobble of +-wobble, and every 17th vertex jumps
 * by up to +-jump (which stretches its triangles across the mesh). */
static void move_vertices(struct tg_mesh *m, float wobble, float jump, struct tg_rng *r)
{
    for (uint32_t v = 0; v < m->vertex_count; v++) {
        for (int k = 0; k < 3; k++) {
            float d = wobble * tg_range(r, -1.0f, 1.0f);
            if (v % 17 == 0)
                d += jump * tg_range(r, -1.0f, 1.0f);
            m->pos[3 * (size_t)v + k] += d;
        }
    }
}

/*
 * Renumbers the nodes so that sibling pairs appear in reverse order of
 * their creation: every child pair then lies before its parent (the root
 * stays at 0), which breaks the order the reverse sweep relies on, as a
 * restructuring may.  Same tree, same boxes.
 */
static struct bvh reverse_numbering(const struct bvh *b)
{
    struct bvh c = copy_tree(b);
    uint32_t n = b->node_count;
    if (n < 3)
        return c;
    uint32_t *map = tg_alloc(sizeof(uint32_t) * n);
    map[0] = 0;
    /* Pairs (1,2), (3,4), ... become (n-2,n-1), ..., (1,2) reversed. */
    for (uint32_t i = 1; i < n; i += 2) {
        uint32_t pair = (i - 1) / 2;
        uint32_t pairs = (n - 1) / 2;
        uint32_t to = 1 + 2 * (pairs - 1 - pair);
        map[i] = to;
        map[i + 1] = to + 1;
    }
    for (uint32_t i = 0; i < n; i++) {
        struct bvh_node node = b->nodes[i];
        if (!node.count)
            node.first = map[node.first];
        c.nodes[map[i]] = node;
    }
    free(map);
    return c;
}

static void check_mesh(const char *scene, struct tg_mesh *m, struct rt_pool **pools,
                       struct tg_rng *r)
{
    struct aabb *boxes = tg_boxes(m);
    uint32_t n = m->tri_count;
    struct bvh trees[3];
    const char *names[3] = {"binned", "median", "grid+BIH"};
    struct bvh_parallel_params gridbih = {BVH_PARTITION_GRID, BVH_SUBTREE_MEDIAN};
    int ok[3];
    ok[0] = accel_build(&trees[0], boxes, n, NULL) == 0;
    ok[1] = accel_build_median(&trees[1], boxes, n, NULL) == 0;
    ok[2] = accel_build_parallel_ex(&trees[2], boxes, n, NULL, &gridbih, NULL) == 0;
    float *tri[3];
    for (int t = 0; t < 3; t++) {
        failures += !CHECKF(ok[t], "%s: %s build failed", scene, names[t]);
        tri[t] = ok[t] ? accel_gather_triangles(&trees[t], m->pos, m->idx) : NULL;
        if (ok[t] && !tri[t]) {
            failures += !CHECKF(0, "%s: gather failed", scene);
            bvh_release(&trees[t]);
            ok[t] = 0;
        }
    }
    double refit_ms = 0.0;
    for (int frame = 0; frame < 3; frame++) {
        move_vertices(m, 0.01f, frame == 1 ? 0.5f : 0.0f, r);
        free(boxes);
        boxes = tg_boxes(m);
        struct bc_rays rays;
        bc_rays_make(&rays, m, 500, 1000 + (uint64_t)frame);
        for (int t = 0; t < 3; t++) {
            if (!ok[t])
                continue;
            char what[96];
            snprintf(what, sizeof(what), "%s/%s frame %d", scene, names[t], frame);
            struct bvh *b = &trees[t];
            struct bvh before = copy_tree(b);

            /* Serial refit: boxes equal the naive unions, the tree stays
             * valid, and a second refit changes nothing. */
            double t0 = rt_now_ms();
            accel_refit(b, boxes);
            refit_ms += rt_now_ms() - t0;
            check_boxes(what, b, boxes);
            bvh_check_tree(what, b, boxes, n, BVH_MAX_LEAF_SIZE, 1);
            struct bvh serial = copy_tree(b);
            accel_refit(b, boxes);
            failures += !CHECKF(same_nodes(b, &serial), "%s: refit not idempotent", what);

            /* Triangle copy: equal to a fresh gather. */
            accel_refit_triangles(b, tri[t], m->pos, m->idx);
            float *fresh = accel_gather_triangles(b, m->pos, m->idx);
            failures += !CHECKF(fresh && memcmp(fresh, tri[t], 9 * sizeof(float) * n) == 0,
                     "%s: refit triangles differ from a fresh gather", what);

            /* Parallel versions: the same bits for 1..MAX_THREADS threads. */
            for (int th = 1; th <= MAX_THREADS; th++) {
                struct bvh par = copy_tree(&before);
                accel_refit_parallel(&par, boxes, pools[th]);
                failures += !CHECKF(same_nodes(&par, &serial),
                         "%s: parallel refit on %d threads differs", what, th);
                float *ptri = tg_alloc(9 * sizeof(float) * n);
                memset(ptri, 0, 9 * sizeof(float) * n);
                accel_refit_triangles_parallel(&par, ptri, m->pos, m->idx, pools[th]);
                failures += !CHECKF(fresh && memcmp(ptri, fresh, 9 * sizeof(float) * n) == 0,
                         "%s: parallel triangle refit on %d threads differs", what, th);
                /* Both at once, from the mesh. */
                memcpy(par.nodes, before.nodes, sizeof(*par.nodes) * par.node_count);
                memset(ptri, 0, 9 * sizeof(float) * n);
                accel_refit_mesh(&par, ptri, m->pos, m->idx, th == 1 ? NULL : pools[th]);
                failures += !CHECKF(
                         same_nodes(&par, &serial) && fresh &&
                             memcmp(ptri, fresh, 9 * sizeof(float) * n) == 0,
                         "%s: accel_refit_mesh on %d threads differs", what, th);
                free(ptri);
                free_copy(&par);
            }
            rt_free(fresh);

            /* Children before parents: the fallback walk, same boxes. */
            struct bvh rev = reverse_numbering(&before);
            accel_refit(&rev, boxes);
            check_boxes("reverse-numbered", &rev, boxes);
            struct bvh rev_par = reverse_numbering(&before);
            accel_refit_parallel(&rev_par, boxes, pools[MAX_THREADS]);
            failures += !CHECKF(same_nodes(&rev, &rev_par),
                     "%s: reverse-numbered parallel refit differs", what);
            free_copy(&rev);
            free_copy(&rev_par);

            /* What a ray hits: the moved mesh's brute-force hits. */
            uint32_t hits = bc_check_hits(what, b, tri[t], &rays);
            failures += !CHECKF(hits > rays.count / 8, "%s: only %u of %u rays hit", what, hits,
                     rays.count);
            free_copy(&serial);
            free_copy(&before);
        }
        bc_rays_free(&rays);
    }
    printf("  %-8s n=%6u: serial refits %.1f ms in all\n", scene, n, refit_ms);
    for (int t = 0; t < 3; t++) {
        if (ok[t]) {
            rt_free(tri[t]);
            bvh_release(&trees[t]);
        }
    }
    free(boxes);
}

/* The empty tree is left alone; one primitive becomes its new box. */
static void check_tiny(struct rt_pool **pools)
{
    struct bvh empty;
    memset(&empty, 0, sizeof(empty));
    struct aabb box = {{1.0f, 2.0f, 3.0f}, {4.0f, 5.0f, 6.0f}};
    accel_refit(&empty, &box);
    accel_refit_parallel(&empty, &box, pools[2]);
    float none[9];
    accel_refit_triangles(&empty, none, NULL, NULL);
    accel_refit_triangles_parallel(&empty, none, NULL, NULL, pools[2]);
    accel_refit_mesh(&empty, none, NULL, NULL, pools[2]);
    failures += !CHECKF(empty.node_count == 0 && !empty.nodes, "empty tree touched");

    struct bvh one;
    if (accel_build(&one, &box, 1, NULL)) {
        failures += !CHECKF(0, "1-prim build");
        return;
    }
    struct aabb moved = {{-1.0f, -2.0f, -3.0f}, {0.5f, 0.5f, 0.5f}};
    for (int th = 1; th <= MAX_THREADS; th++) {
        accel_refit_parallel(&one, &moved, pools[th]);
        failures += !CHECKF(
                 memcmp(one.nodes[0].aabb_min, moved.min, sizeof(moved.min)) == 0 &&
                     memcmp(one.nodes[0].aabb_max, moved.max, sizeof(moved.max)) == 0,
                 "1 prim refit on %d threads", th);
        accel_refit(&one, &box);
    }
    float v[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    uint32_t idx[3] = {0, 1, 2};
    float tri[9];
    accel_refit_mesh(&one, tri, v, idx, pools[2]);
    failures += !CHECKF(
             memcmp(tri, v, sizeof(v)) == 0 && one.nodes[0].aabb_min[0] == 0.0f &&
                 one.nodes[0].aabb_max[1] == 1.0f && one.nodes[0].aabb_max[2] == 0.0f,
             "1 prim refit_mesh");
    bvh_release(&one);
}

int main(void)
{
    double t0 = rt_now_ms();
    printf("refit:\n");
    struct rt_pool *pools[MAX_THREADS + 1];
    pools[0] = NULL;
    for (int t = 1; t <= MAX_THREADS; t++)
        pools[t] = rt_pool_create(t);
    check_tiny(pools);

    struct tg_rng r;
    tg_seed(&r, 42);
    struct tg_mesh sphere, soup, terrain;
    const double origin[3] = {0.0, 0.0, 0.0};
    tg_cube_sphere(&sphere, 40, 1, 1.0, origin);
    tg_soup(&soup, 30000, 1.0f, 0.02f, &r);
    tg_terrain(&terrain, 90, &r);
    check_mesh("sphere", &sphere, pools, &r);
    check_mesh("soup", &soup, pools, &r);
    check_mesh("terrain", &terrain, pools, &r);
    tg_mesh_free(&sphere);
    tg_mesh_free(&soup);
    tg_mesh_free(&terrain);

    for (int t = 1; t <= MAX_THREADS; t++)
        rt_pool_destroy(pools[t]);
    printf("refit: %s (%d failures, %.0f ms)\n", failures ? "FAIL" : "ok", failures,
           rt_now_ms() - t0);
    return failures ? 1 : 0;
}
