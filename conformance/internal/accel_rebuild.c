/* SPDX-License-Identifier: Apache-2.0 */
/*
 * accel_rebuild.c - a deforming object's rebuild into the memory of the
 * structure it replaces (scene_accel_rebuild, scene/accel.c): the new
 * structure is the one a fresh build makes, byte for byte (binary tree,
 * leaf-ordered triangles, wide layout), with the serial and the parallel
 * builder and every layout width; the replaced structure's triangle
 * array is the one the new structure owns (so a change that stopped the
 * reuse fails here); a refit after the rebuild finds the triangles and
 * the layout it needs and gives the fresh structure's refit; and a
 * rebuild that fails at any one allocation leaves the replaced structure
 * as it was (a refit of it then still gives the fresh one's refit).
 * A fresh build with a wide layout leaves the leaf-ordered triangles out
 * from params.rebuild_reuse_min_bytes of them (0 here)
 * (scene_accel_triangles gathers them on first need, a first refit
 * allocates them): they are compared with a gather of the structure's
 * tree, and a failure of either allocation leaves the structure as it
 * was and usable.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accel/bvh_build.h"
#include "accel_testgeo.h"
#include "base/alloc.h"
#include "base/pool.h"
#include "check.h"
#include "scene/accel.h"
#include "trace/bvh4_layout.h"

static int failures;

/* The structure's leaf-ordered triangles, or for one that has none
 * (a fresh build) a gather of its tree over g, which scene_accel_triangles
 * would give; *owned is set when the caller frees it. */
static const float *triangles_of(const struct scene_accel *a, const struct scene_accel_geometry *g,
                                 float **owned)
{
    *owned = NULL;
    if (a->tri)
        return a->tri;
    *owned = accel_gather_triangles(&a->bvh, g->positions, g->indices);
    return *owned;
}

/* The bytes traversal and refit read: the binary tree, the leaf-ordered
 * triangles (had or gathered over g) and the wide layout (its refit
 * tables too). */
static int same_accel(const struct scene_accel *a, const struct scene_accel *b,
                      const struct scene_accel_geometry *g)
{
    const struct bvh *x = &a->bvh, *y = &b->bvh;
    if (x->node_count != y->node_count || x->prim_count != y->prim_count ||
        x->depth != y->depth ||
        memcmp(x->nodes, y->nodes, (size_t)x->node_count * sizeof(*x->nodes)) != 0 ||
        memcmp(x->prim_index, y->prim_index, (size_t)x->prim_count * sizeof(uint32_t)) != 0)
        return 0;
    float *own_a, *own_b;
    const float *ta = triangles_of(a, g, &own_a), *tb = triangles_of(b, g, &own_b);
    const int same_tri = ta && tb && memcmp(ta, tb, 9 * sizeof(float) * x->prim_count) == 0;
    free(own_a);
    free(own_b);
    if (!same_tri)
        return 0;
    const struct bvh4 *p = &a->wide, *q = &b->wide;
    if (p->width != q->width || p->node_count != q->node_count ||
        p->packet_count != q->packet_count)
        return 0;
    if (!p->node_count)
        return 1;
    const void *np = p->width == 8 ? (const void *)p->nodes8 : (const void *)p->nodes;
    const void *nq = q->width == 8 ? (const void *)q->nodes8 : (const void *)q->nodes;
    return memcmp(np, nq, bvh4_node_bytes(p)) == 0 &&
           memcmp(p->packets, q->packets, bvh4_leaf_bytes(p)) == 0 &&
           memcmp(p->packet_slot, q->packet_slot, p->packet_count * sizeof(uint32_t)) == 0 &&
           memcmp(p->source, q->source, (size_t)p->node_count * p->width * sizeof(uint32_t)) == 0;
}

/* Frame f's positions of m's vertices: base moved by a smooth field. */
static void deform(float *pos, const float *base, uint32_t vertices, int f)
{
    for (uint32_t v = 0; v < vertices; v++) {
        const float *b = &base[3 * (size_t)v];
        float *p = &pos[3 * (size_t)v];
        p[0] = b[0] + 0.01f * f * sinf(7.0f * b[1]);
        p[1] = b[1] + 0.02f * f * cosf(5.0f * b[2]);
        p[2] = b[2] - 0.01f * f * sinf(3.0f * b[0]);
    }
}

static void check_mesh(const char *name, const struct tg_mesh *m, struct rt_pool *pool)
{
    float *pos = tg_alloc(sizeof(float) * 3 * (size_t)m->vertex_count);
    for (int layout = 0; layout < 3; layout++) {
        for (int par = 0; par < 2; par++) {
            struct bvh_build_params params;
            bvh_build_params_default(&params);
            params.builder = BVH_BUILDER_BINNED_SAH;
            params.wide_layout = layout == 0 ? 0 : layout == 1 ? 4 : 8;
            /* These meshes are below the default's 32 MiB of triangles. */
            params.rebuild_reuse_min_bytes = 0;
            const enum scene_accel_builder builder =
                par ? SCENE_ACCEL_PARALLEL : SCENE_ACCEL_SERIAL;
            struct rt_pool *p = par ? pool : NULL;
            deform(pos, m->pos, m->vertex_count, 0);
            struct scene_accel_geometry g = {pos, m->idx, m->tri_count};
            struct scene_accel *cur = scene_accel_build(&g, &params, builder, p, NULL);
            failures += !CHECKF(cur != NULL, "%s: first build failed", name);
            if (cur) {
                /* Left out with a wide layout, made with the structure
                 * without one (every walk then reads them). */
                failures += !CHECKF((cur->tri == NULL) == (params.wide_layout != 0),
                                    "%s, layout %d: the fresh build's triangles %s", name,
                                    params.wide_layout, cur->tri ? "made" : "missing");
                /* A frame's first need (scene_accel_triangles), as a
                 * blended frame's ties walk asks: then the object's
                 * rebuilds keep them, into the replaced array. */
                failures += !CHECKF(scene_accel_triangles(cur, &g) != NULL && cur->tri != NULL,
                                    "%s: the lazy gather failed", name);
            }
            for (int f = 1; f <= 3 && cur; f++) {
                deform(pos, m->pos, m->vertex_count, f);
                struct scene_accel *fresh = scene_accel_build(&g, &params, builder, p, NULL);
                const float *old_tri = cur->tri;
                struct scene_accel *rebuilt =
                    scene_accel_rebuild(&g, &params, builder, p, NULL, cur);
                if (!CHECKF(fresh && rebuilt, "%s: build or rebuild failed (frame %d)", name,
                            f)) {
                    failures++;
                    scene_accel_release(fresh);
                    scene_accel_release(rebuilt);
                    break;
                }
                failures += !CHECKF(same_accel(rebuilt, fresh, &g),
                                    "%s, layout %d, %s: the rebuild (frame %d) differs from a "
                                    "fresh build",
                                    name, params.wide_layout, par ? "parallel" : "serial", f);
                failures += !CHECKF(rebuilt->tri == old_tri && cur->tri == NULL,
                                    "%s: the rebuild did not take the replaced structure's "
                                    "triangles",
                                    name);
                scene_accel_release(cur);
                cur = rebuilt;
                /* The next frame's positions by refit, on both: the rebuilt
                 * structure has what the refit needs. */
                deform(pos, m->pos, m->vertex_count, f + 10);
                failures += !CHECKF(scene_accel_refit(cur, &g, &params, p) == 0 &&
                                        scene_accel_refit(fresh, &g, &params, p) == 0 &&
                                        fresh->tri != NULL,
                                    "%s: a refit failed or left its triangles out", name);
                failures += !CHECKF(same_accel(cur, fresh, &g),
                                    "%s, layout %d: a refit after the rebuild differs", name,
                                    params.wide_layout);
                scene_accel_release(fresh);
            }
            /* Every single allocation failure of a rebuild: NULL and the
             * replaced structure as it was, or the fresh build's bytes. */
            if (cur) {
                deform(pos, m->pos, m->vertex_count, 20);
                struct scene_accel *before = scene_accel_build(&g, &params, builder, p, NULL);
                scene_accel_release(cur);
                cur = scene_accel_build(&g, &params, builder, p, NULL);
                if (cur)
                    scene_accel_triangles(cur, &g);
                deform(pos, m->pos, m->vertex_count, 21);
                struct scene_accel *target = scene_accel_build(&g, &params, builder, p, NULL);
                int survived = 0, failed = 0;
                for (long n = 0; n < 40 && before && target && cur; n++) {
                    rt_alloc_fail_once(n);
                    struct scene_accel *next =
                        scene_accel_rebuild(&g, &params, builder, p, NULL, cur);
                    const long injected = rt_alloc_failures();
                    rt_alloc_fail_reset();
                    if (!injected) {
                        /* n past the rebuild's allocations: done. */
                        scene_accel_release(next);
                        break;
                    }
                    if (next) {
                        survived++;
                        failures += !CHECKF(same_accel(next, target, &g),
                                            "%s: rebuild with allocation %ld failed differs",
                                            name, n);
                        scene_accel_release(next);
                    } else {
                        failed++;
                        /* deform back: cur must still be frame 20's. */
                        deform(pos, m->pos, m->vertex_count, 20);
                        failures += !CHECKF(same_accel(cur, before, &g),
                                            "%s: a failed rebuild (allocation %ld) changed the "
                                            "replaced structure",
                                            name, n);
                        deform(pos, m->pos, m->vertex_count, 21);
                        continue;
                    }
                    /* A surviving rebuild took cur's memory: start over. */
                    scene_accel_release(cur);
                    deform(pos, m->pos, m->vertex_count, 20);
                    cur = scene_accel_build(&g, &params, builder, p, NULL);
                    if (cur)
                        scene_accel_triangles(cur, &g);
                    deform(pos, m->pos, m->vertex_count, 21);
                }
                failures += !CHECKF(failed > 0, "%s: no rebuild failed", name);
                printf("  %-7s layout %d %-8s: %d rebuilds failed, %d survived one failed "
                       "allocation\n",
                       name, params.wide_layout, par ? "parallel" : "serial", failed, survived);
                scene_accel_release(before);
                scene_accel_release(target);
            }
            scene_accel_release(cur);
        }
    }
    free(pos);
}

/* Below params.rebuild_reuse_min_bytes (the default on a small mesh) a
 * fresh build has its triangles, and the rebuild leaves the replaced
 * structure's triangles alone and still gives a fresh build's bytes. */
static void check_small_keeps_old(const struct tg_mesh *m)
{
    float *pos = tg_alloc(sizeof(float) * 3 * (size_t)m->vertex_count);
    struct bvh_build_params params;
    bvh_build_params_default(&params);
    params.wide_layout = 8;
    failures += !CHECKF((uint64_t)m->tri_count * 36 < params.rebuild_reuse_min_bytes,
                        "the small mesh is not below the default threshold");
    deform(pos, m->pos, m->vertex_count, 0);
    struct scene_accel_geometry g = {pos, m->idx, m->tri_count};
    struct scene_accel *cur = scene_accel_build(&g, &params, SCENE_ACCEL_SERIAL, NULL, NULL);
    /* Below the threshold a fresh build makes the triangles with the
     * structure (scene_accel_triangles_at_build). */
    failures += !CHECKF(!cur || cur->tri, "small mesh: the fresh build left its triangles out");
    deform(pos, m->pos, m->vertex_count, 1);
    struct scene_accel *fresh = scene_accel_build(&g, &params, SCENE_ACCEL_SERIAL, NULL, NULL);
    const float *old_tri = cur ? cur->tri : NULL;
    struct scene_accel *rebuilt =
        cur ? scene_accel_rebuild(&g, &params, SCENE_ACCEL_SERIAL, NULL, NULL, cur) : NULL;
    if (CHECKF(cur && fresh && rebuilt, "small mesh: a build failed")) {
        failures += !CHECKF(cur->tri == old_tri && rebuilt->tri != old_tri,
                            "small mesh: the rebuild took the replaced triangles below the "
                            "threshold");
        failures += !CHECKF(same_accel(rebuilt, fresh, &g), "small mesh: the rebuild differs");
    } else {
        failures++;
    }
    scene_accel_release(cur);
    scene_accel_release(fresh);
    scene_accel_release(rebuilt);
    free(pos);
}

/* The lazily made triangles when their allocation fails: the gather
 * (scene_accel_triangles) and a first refit report it and leave the
 * structure as it was, and the next call succeeds with a gather's bytes
 * (lib/api reports the frame's failure as RT_OUT_OF_MEMORY). */
static void check_lazy_failures(const struct tg_mesh *m)
{
    float *pos = tg_alloc(sizeof(float) * 3 * (size_t)m->vertex_count);
    struct bvh_build_params params;
    bvh_build_params_default(&params);
    params.wide_layout = 8;
    params.rebuild_reuse_min_bytes = 0; /* left out however small */
    deform(pos, m->pos, m->vertex_count, 0);
    struct scene_accel_geometry g = {pos, m->idx, m->tri_count};
    struct scene_accel *a = scene_accel_build(&g, &params, SCENE_ACCEL_SERIAL, NULL, NULL);
    struct scene_accel *b = scene_accel_build(&g, &params, SCENE_ACCEL_SERIAL, NULL, NULL);
    if (!CHECKF(a && b && !a->tri, "lazy: the builds failed or made the triangles")) {
        failures++;
        goto done;
    }
    rt_alloc_fail_once(0);
    const float *tri = scene_accel_triangles(a, &g);
    const long injected = rt_alloc_failures();
    rt_alloc_fail_reset();
    failures += !CHECKF(injected == 1 && tri == NULL && a->tri == NULL && same_accel(a, b, &g),
                        "lazy: a failed gather was not reported or changed the structure");
    tri = scene_accel_triangles(a, &g);
    failures += !CHECKF(tri && tri == a->tri && same_accel(a, b, &g),
                        "lazy: the gather after a failure differs");
    failures += !CHECKF(scene_accel_triangles(a, &g) == tri, "lazy: the gather is not kept");
    /* A first refit without the triangles: its one allocation. */
    deform(pos, m->pos, m->vertex_count, 1);
    rt_alloc_fail_once(0);
    const int status = scene_accel_refit(b, &g, &params, NULL);
    rt_alloc_fail_reset();
    deform(pos, m->pos, m->vertex_count, 0);
    failures += !CHECKF(status == -1 && b->tri == NULL && same_accel(a, b, &g),
                        "lazy: a failed first refit was not reported or changed the structure");
    deform(pos, m->pos, m->vertex_count, 1);
    failures += !CHECKF(scene_accel_refit(a, &g, &params, NULL) == 0 &&
                            scene_accel_refit(b, &g, &params, NULL) == 0 && b->tri &&
                            same_accel(a, b, &g),
                        "lazy: the refit after a failure differs");
done:
    scene_accel_release(a);
    scene_accel_release(b);
    free(pos);
}

int main(void)
{
    printf("accel_rebuild:\n");
    struct rt_pool *pool = rt_pool_create(2);
    struct tg_rng r;
    tg_seed(&r, 39);
    struct tg_mesh soup, sphere;
    tg_soup(&soup, 30000, 1.0f, 0.02f, &r);
    const double origin[3] = {0.0, 0.0, 0.0};
    tg_cube_sphere(&sphere, 40, 1, 1.0, origin);
    check_mesh("soup", &soup, pool);
    check_mesh("sphere", &sphere, pool);
    check_small_keeps_old(&soup);
    check_lazy_failures(&sphere);
    tg_mesh_free(&soup);
    tg_mesh_free(&sphere);
    rt_pool_destroy(pool);
    printf("accel_rebuild: %s (%d failures)\n", failures ? "FAIL" : "ok", failures);
    return failures ? 1 : 0;
}
