/* SPDX-License-Identifier: Apache-2.0 */
/*
 * collapse_merge.c - the greedy collapse's merge limit per layout
 * (collapse4.c, collapse_merge_limit; bvh4_layout.h,
 * BVH_WIDE_MERGE_SURFACE): a layout of surfaces of an estimated 1 to 16
 * MB merges binary subtrees of at most BVH_WIDE_MERGE_SURFACE triangles
 * into one leaf lane, every other layout (a volume, a smaller or a
 * larger one, the optimal collapse's) at most BVH_WIDE_MERGE.
 *
 * Checked on the layouts themselves, not only on the recorded limit: in a
 * wide node that is not full, gather stopped because no lane could be
 * opened, so each leaf lane there is a binary leaf or a merged subtree
 * within the limit; with BVH_WIDE_MERGE on the sphere below, such lanes
 * of four triangles are many.  The answers over these layouts are
 * kernel_bits' (its 43,200-triangle sphere, refitted too).
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

static int failures;

#include "accel/bvh_build.h"
#include "accel_testgeo.h"
#include "base/alloc.h"
#include "trace/bvh4_layout.h"
#include "check.h"

/* The triangles of binary subtree i (every leaf's count). */
static uint32_t subtree_triangles(const struct bvh *b, uint32_t i)
{
    const struct bvh_node *n = &b->nodes[i];
    if (n->count)
        return n->count;
    return subtree_triangles(b, n->first) + subtree_triangles(b, n->first + 1);
}

/* The leaf lanes of non-full nodes that hold a merged subtree (not a
 * binary leaf) of more than `merge` triangles; *merged the merged lanes
 * of non-full nodes. */
static uint32_t lanes_beyond(const struct bvh4 *w, const struct bvh *b, uint32_t merge,
                             uint32_t *merged)
{
    uint32_t beyond = 0;
    *merged = 0;
    for (uint32_t n = 0; n < w->node_count; n++) {
        uint32_t lanes = 0;
        for (uint32_t l = 0; l < w->width; l++)
            lanes += w->source[n * w->width + l] != UINT32_MAX;
        if (lanes == w->width)
            continue;
        for (uint32_t l = 0; l < lanes; l++) {
            const uint32_t i = w->source[n * w->width + l];
            const uint8_t count = w->width == 8 ? w->nodes8[n].count[l] : w->nodes[n].count[l];
            if (!count || b->nodes[i].count)
                continue;
            (*merged)++;
            beyond += subtree_triangles(b, i) > merge;
        }
    }
    return beyond;
}

static void check_mesh(const char *name, struct tg_mesh *m, enum bvh_collapse collapse,
                       uint32_t expect)
{
    struct aabb *boxes = tg_boxes(m);
    struct bvh bvh;
    if (accel_build(&bvh, boxes, m->tri_count, NULL)) {
        fprintf(stderr, "out of memory\n");
        exit(1);
    }
    float *tri = accel_gather_triangles(&bvh, m->pos, m->idx);
    const double crossings = accel_binary_child_crossings(&bvh, BVH_WIDE_CROSSINGS_SAMPLE);
    for (uint32_t width = 4; width <= 8; width += 4) {
        struct bvh4 w;
        if (!tri || accel_collapse_wide_quality(&w, &bvh, tri, width, NULL, NULL, collapse)) {
            fprintf(stderr, "out of memory\n");
            exit(1);
        }
        uint32_t merged = 0;
        const uint32_t beyond = lanes_beyond(&w, &bvh, expect, &merged);
        const uint32_t beyond3 = lanes_beyond(&w, &bvh, 3, &merged);
        printf("  %s, %u triangles, %s, bvh%u: binary child crossings %.3f, merge %u; "
               "merged lanes in non-full nodes %u, of more than 3 triangles %u\n",
               name, m->tri_count, collapse == BVH_COLLAPSE_GREEDY ? "greedy" : "optimal",
               width, crossings, w.merge, merged, beyond3);
        failures += !CHECKF(w.merge == expect, "%s bvh%u: merge limit %u, expected %u", name,
                            width, w.merge, expect);
        failures += !CHECKF(beyond == 0, "%s bvh%u: %u merged lanes beyond %u triangles", name,
                            width, beyond, expect);
        if (expect == BVH_WIDE_MERGE)
            failures += !CHECKF(beyond3 > 0,
                   "%s bvh%u: no merged lane of four triangles (the check would not see "
                   "the limit)", name, width);
        bvh4_release(&w);
    }
    rt_free(tri);
    bvh_release(&bvh);
    free(boxes);
}

int main(void)
{
    printf("collapse_merge:\n");
    const double origin[3] = {0.0, 0.0, 0.0};
    struct tg_mesh m;
    /* 43,200 triangles of a surface: about 2.7 MB estimated. */
    tg_cube_sphere(&m, 60, 1, 1.0, origin);
    check_mesh("sphere", &m, BVH_COLLAPSE_GREEDY, BVH_WIDE_MERGE_SURFACE);
    check_mesh("sphere", &m, BVH_COLLAPSE_OPTIMAL, BVH_WIDE_MERGE);
    tg_mesh_free(&m);
    /* 6,912: below BVH_WIDE_PREFETCH_BYTES. */
    tg_cube_sphere(&m, 24, 1, 1.0, origin);
    check_mesh("small sphere", &m, BVH_COLLAPSE_GREEDY, BVH_WIDE_MERGE);
    tg_mesh_free(&m);
    /* 270,000: at BVH_WIDE_STREAM_BYTES and beyond. */
    tg_cube_sphere(&m, 150, 1, 1.0, origin);
    check_mesh("large sphere", &m, BVH_COLLAPSE_GREEDY, BVH_WIDE_MERGE);
    tg_mesh_free(&m);
    /* A volume of 60,000 triangles, the size of the first sphere's band. */
    struct tg_rng r;
    tg_seed(&r, 7);
    tg_soup(&m, 60000, 1.0f, 0.02f, &r);
    check_mesh("soup", &m, BVH_COLLAPSE_GREEDY, BVH_WIDE_MERGE);
    tg_mesh_free(&m);
    printf("  %s (%d failures)\n", failures ? "FAIL" : "ok", failures);
    return failures ? 1 : 0;
}
