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
 * The collapse merges a binary subtree into one leaf when its triangles
 * are at most BVH_WIDE_MERGE in consecutive leaf slots (and, in a large
 * layout, a closed one of at most BVH_WIDE_MERGE_LEFT when the area
 * heuristic prefers it); each lane's
 * decision is checked against that definition computed bottom-up over
 * every node (reference_span), also on trees whose node order puts
 * children before parents and whose leaf slots are no longer consecutive
 * (what restructuring can leave).  The meshes
 * are large enough that the pooled paths run (levels of more than
 * COLLAPSE_PARALLEL_MIN wide nodes, more than GATHER_PARALLEL_MIN slots
 * and triangles);
 * the test prints the node counts to show it.  Where the CPU runs the
 * collapse's AVX2 copy (collapse4_avx2.c), its layouts are compared with
 * the portable form's byte for byte, also on a mesh with zero-area
 * triangles.  All of it for both collapses, the greedy one and the
 * optimal one (rtHint(RT_ACCELERATION_HINT, RT_NICEST)), whose wide SAH
 * must be below the greedy one's (the check fails if the DP did not run).
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int failures;

#include "accel/build_parallel.h"
#include "accel/bvh_build.h"
#include "accel/collapse4_avx2.h"
#include "accel/collapse_mesh.h"
#include "accel_testgeo.h"
#include "bvh_contract.h"
#include "base/alloc.h"
#include "base/pool.h"
#include "base/timer.h"
#include "trace/bvh4_layout.h"
#include "trace/intersect.h"
#include "check.h"

#define MAX_THREADS 4
#define REPEATS 2

static int same_wide(const struct bvh4 *a, const struct bvh4 *b)
{
    if (a->width != b->width || a->node_count != b->node_count ||
        a->packet_count != b->packet_count || a->prefetch_top != b->prefetch_top ||
        a->any_longest != b->any_longest || a->dropped != b->dropped ||
        memcmp(&a->leaf_extent, &b->leaf_extent, sizeof a->leaf_extent) != 0)
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

/* The span of binary subtree i, by definition: a leaf's count; an inner
 * node's children's sum when their slot runs are adjacent (either
 * order), else 0.  *first is the first slot when the span is not 0. */
static uint32_t reference_span(const struct bvh *b, uint32_t i, uint32_t *first)
{
    const struct bvh_node *n = &b->nodes[i];
    if (n->count) {
        *first = n->first;
        return n->count;
    }
    uint32_t fl = 0, fr = 0;
    uint32_t sl = reference_span(b, n->first, &fl);
    uint32_t sr = reference_span(b, n->first + 1, &fr);
    if (!sl || !sr)
        return 0;
    if (fl + sl == fr || fr + sr == fl) {
        *first = fl + sl == fr ? fl : fr;
        return sl + sr;
    }
    return 0;
}

/* Slot j's triangle of tri (leaf order) has zero area (intersect.h). */
static int slot_zero(const float *tri, uint32_t j)
{
    const float *v = &tri[9 * (size_t)j];
    return isect_triangle_zero_area(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]);
}

/* Every lane of w (with packets) against reference_span: a leaf lane is a
 * binary leaf or a subtree of span 1..BVH_WIDE_MERGE with those slots
 * (or, where w left zero-area triangles out, of at most BVH_WIDE_MERGE
 * other triangles in at most BVH_WIDE_MAX_LEAF slots), or one of span up
 * to BVH_WIDE_MERGE_LEFT (a closed lane the area heuristic made a leaf:
 * counted in *merged_left); an inner lane none of these (spans above
 * BVH_WIDE_MERGE may be either).  A leaf lane holds its
 * span's triangles of non-zero area (tri, leaf order), its first packet's
 * slot the first of them; the zero-area ones are left out
 * (drop_zero_area), and a lane of only such triangles is not in the node
 * unless it is the node's only lane, then whole.  Every triangle of
 * non-zero area is in exactly one lane, and w->dropped counts the
 * others. */
static void check_lanes(const char *what, const struct bvh4 *w, const struct bvh *b,
                        const float *tri, int greedy, uint32_t *merged_left)
{
    int bad = 0;
    uint32_t in_lanes = 0, zero = 0;
    *merged_left = 0;
    for (uint32_t j = 0; j < b->prim_count; j++)
        zero += (uint32_t)slot_zero(tri, j);
    for (uint32_t n = 0; n < w->node_count && !bad; n++) {
        uint32_t lanes = 0;
        for (uint32_t l = 0; l < w->width; l++)
            lanes += w->source[n * w->width + l] != UINT32_MAX;
        for (uint32_t l = 0; l < w->width; l++) {
            uint32_t i = w->source[n * w->width + l];
            if (i == UINT32_MAX)
                continue;
            uint32_t count = w->width == 8 ? w->nodes8[n].count[l] : w->nodes[n].count[l];
            uint32_t child = w->width == 8 ? w->nodes8[n].child[l] : w->nodes[n].child[l];
            uint32_t first = 0;
            uint32_t span = reference_span(b, i, &first);
            int binary_leaf = b->nodes[i].count != 0;
            uint32_t live = 0, first_live = UINT32_MAX;
            for (uint32_t j = first; span != 0 && j < first + span; j++) {
                if (!slot_zero(tri, j)) {
                    live++;
                    first_live = first_live == UINT32_MAX ? j : first_live;
                }
            }
            /* A greedy layout that left zero-area triangles out merges
             * a subtree by its other triangles (small_span_live): one
             * packet of them, in at most BVH_WIDE_MAX_LEAF slots (the
             * optimal collapse's costs count every triangle). */
            int must_leaf = binary_leaf || (span != 0 && span <= BVH_WIDE_MERGE) ||
                            (greedy && w->dropped && span != 0 && span <= BVH_WIDE_MAX_LEAF &&
                             live <= BVH_WIDE_MERGE);
            int may_leaf = must_leaf || (span != 0 && span <= BVH_WIDE_MERGE_LEFT);
            const int whole = live == 0 && lanes == 1 && count == span &&
                              w->packet_slot[child] == first;
            if (count == 0)
                bad |= must_leaf;
            else if (!may_leaf ||
                     !(whole || (count == live && w->packet_slot[child] == first_live)))
                bad = 1;
            else if (!must_leaf)
                (*merged_left)++;
            in_lanes += whole ? 0 : count;
        }
    }
    if (!bad)
        bad = in_lanes + zero != b->prim_count || w->dropped > zero;
    failures += !CHECKF(!bad, "%s: a lane's leaf decision differs from the span definition", what);
}

/* Child pairs moved to mirrored positions (children before parents). */
static void mirror_nodes(struct bvh *b)
{
    uint32_t n = b->node_count;
    if (n < 3)
        return;
    uint32_t pairs = (n - 1) / 2;
    struct bvh_node *old = tg_alloc(n * sizeof(*old));
    memcpy(old, b->nodes, n * sizeof(*old));
    for (uint32_t i = 0; i < n; i++) {
        struct bvh_node node = old[i];
        if (!node.count)
            node.first = 1 + 2 * (pairs - 1 - (node.first - 1) / 2);
        uint32_t j = i == 0 ? 0 : 1 + 2 * (pairs - 1 - (i - 1) / 2) + (i - 1) % 2;
        b->nodes[j] = node;
    }
    free(old);
}

/* Exchanges the slots of some pairs of leaves of equal count, so some
 * subtrees no longer cover consecutive slots. */
static void scramble_slots(struct bvh *b)
{
    uint32_t last = UINT32_MAX;
    uint32_t k = 0;
    for (uint32_t i = 0; i < b->node_count; i++) {
        if (!b->nodes[i].count)
            continue;
        if (last != UINT32_MAX && b->nodes[last].count == b->nodes[i].count && k++ % 3 == 0) {
            uint32_t t = b->nodes[last].first;
            b->nodes[last].first = b->nodes[i].first;
            b->nodes[i].first = t;
            last = UINT32_MAX;
            continue;
        }
        last = i;
    }
}

static void check_mesh(const char *scene, const struct tg_mesh *m, struct rt_pool **pools,
                       int variant)
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
    if (variant == 1)
        mirror_nodes(&b);
    if (variant == 2)
        scramble_slots(&b);
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
    double greedy_sah[2] = {0, 0}; /* per width, the greedy layout's wide SAH (2:1) */
    /* Greedy 4- and 8-wide, then optimal (pass / 2) 4- and 8-wide. */
    for (int pass = 0; pass < 4 && tri; pass++) {
        const int opt = pass / 2;
        const uint32_t width = pass % 2 ? 8u : 4u;
        /* The optimal collapse only makes triangle layouts (range leaves
         * are always greedy). */
        for (int ranges = 0; ranges < 2 - opt; ranges++) {
            const enum bvh_collapse collapse = opt ? BVH_COLLAPSE_OPTIMAL : BVH_COLLAPSE_GREEDY;
            const float *leaves = ranges ? NULL : tri;
            struct bvh4 ref;
            if (accel_collapse_wide_quality(&ref, &b, leaves, width, NULL, NULL, collapse)) {
                failures += !CHECKF(0, "%s: collapse failed", scene);
                continue;
            }
            if (!ranges) {
                /* The optimal collapse minimises the wide SAH at its
                 * costs (node 2, packet 1, collapse4.c DP_NODE_COST), so
                 * its layout's is at most the greedy one's; lower on
                 * every mesh here but the tiny one (the test fails if
                 * the DP did not run). */
                const double sah = accel_wide_sah_cost(&ref, 2.0, 1.0);
                if (!opt) {
                    greedy_sah[width / 8] = sah;
                } else {
                    const double g = greedy_sah[width / 8];
                    failures += !CHECKF(sah <= g * (1.0 + 1e-9),
                                        "%s: %u-wide: optimal collapse's SAH %.6f above the "
                                        "greedy %.6f", scene, width, sah, g);
                    if (strcmp(scene, "tiny") != 0)
                        failures += !CHECKF(sah < g, "%s: %u-wide: optimal SAH %.6f not below "
                                            "greedy %.6f", scene, width, sah, g);
                    printf("  %-7s %u-wide: wide SAH (2:1) greedy %.4f, optimal %.4f\n", scene,
                           width, g, sah);
                }
            }
            /* The AVX2 copy (which the calls here take where the CPU
             * runs it) against the portable form, byte for byte. */
            if (accel_collapse_wide_avx2_unit()) {
                struct bvh4 portable;
                const struct collapse_triangles tris = {leaves, NULL, NULL, 0};
                if (accel_collapse_wide_portable(&portable, &b, &tris, width, NULL, NULL,
                                                 collapse)) {
                    failures += !CHECKF(0, "%s: portable collapse failed", scene);
                } else {
                    failures += !CHECKF(same_wide(&portable, &ref),
                                        "%s: %u-wide%s: the AVX2 collapse differs from the "
                                        "portable one",
                                        scene, width, ranges ? " (range leaves)" : "");
                    bvh4_release(&portable);
                }
            }
            /* The packets read from the mesh through prim_index in place
             * of the gathered copy (collapse_mesh.h): the same layout
             * byte for byte, on one thread and on a pool, in this unit
             * and in the portable one; the scrambled and mirrored trees
             * (variants 1, 2) put the slots out of the mesh's order. */
            for (int t = 0; t < 3 && !ranges; t++) {
                struct bvh4 from_mesh;
                const struct collapse_triangles mesh_tris = {NULL, m->pos, m->idx, 0};
                const int rc =
                    t == 2 ? accel_collapse_wide_portable(&from_mesh, &b, &mesh_tris, width,
                                                          pools[2], NULL, collapse)
                           : accel_collapse_wide_mesh(&from_mesh, &b, m->pos, m->idx, width,
                                                      t ? pools[2] : NULL, NULL, collapse);
                if (rc) {
                    failures += !CHECKF(0, "%s: collapse from the mesh failed", scene);
                    continue;
                }
                failures += !CHECKF(same_wide(&from_mesh, &ref),
                                    "%s: %u-wide%s: the collapse from the mesh (%s) differs "
                                    "from the one from the gathered triangles",
                                    scene, width, opt ? " optimal" : "",
                                    t == 0 ? "one thread" : t == 1 ? "two threads" : "portable");
                bvh4_release(&from_mesh);
            }
            uint32_t merged_left = 0;
            if (!ranges) {
                check_lanes(scene, &ref, &b, leaves, !opt, &merged_left);
                /* The zero-area mesh's layouts leave triangles out. */
                if (!strcmp(scene, "zero-area"))
                    failures += !CHECKF(ref.dropped > 0, "zero-area: no triangle left out");
                /* The two-packet leaves are made in large layouts only:
                 * on the soup as built (its 8-wide layout is about 4 MB)
                 * and never on the tiny mesh. */
                if (!opt && variant == 0 && !strcmp(scene, "soup") && width == 8)
                    failures += !CHECKF(merged_left > 0, "soup: no two-packet leaf");
                if (!strcmp(scene, "tiny"))
                    failures += !CHECKF(merged_left == 0, "tiny: a two-packet leaf");
            }
            double ms[MAX_THREADS + 1] = {0};
            for (int t = 1; t <= MAX_THREADS; t++) {
                for (int rep = 0; rep < REPEATS; rep++) {
                    struct bvh4 w;
                    double t0 = rt_now_ms();
                    if (accel_collapse_wide_quality(&w, &b, leaves, width, pools[t], NULL,
                                                    collapse)) {
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
            printf("  %-7s %-9s %-7s %u-wide %-7s binary nodes %u, wide nodes %u, packets %u "
                   "(two-packet leaves %u): ms on 1..%d threads:",
                   scene, variant == 0 ? "built" : variant == 1 ? "mirrored" : "scrambled",
                   opt ? "optimal" : "greedy", width, ranges ? "ranges" : "packets", b.node_count, ref.node_count,
                   ref.packet_count, merged_left, MAX_THREADS);
            for (int t = 1; t <= MAX_THREADS; t++)
                printf(" %.1f", ms[t] / REPEATS);
            printf("\n");
            bvh4_release(&ref);
        }
    }
    rt_free(tri);
    bvh_release(&b);
}

/* A build large enough that the parallel builder keeps its second ref
 * buffer as a mapping for the collapse (accel_build_parallel_triangles'
 * spare, build_parallel.c SCRATCH_SPARE_MIN: 16 MiB of refs): the layout
 * written into that block, whose tail the build wrote and the collapse
 * gives back (rt_large_release_tail), must be byte for byte the one of a
 * fresh block, on two threads as on one.  Nothing else in the suite
 * reaches that path (rtbench's bumpy does). */
static void check_spare(const struct tg_mesh *m, struct rt_pool **pools)
{
    /* t = 0: the serial builder's entry (accel_build_triangles), whose
     * tree must also be accel_build's on the triangles' boxes. */
    for (int t = 0; t <= 2; t++) {
        struct bvh b;
        struct rt_large_block spare;
        if (t ? accel_build_parallel_triangles(&b, m->pos, m->idx, m->tri_count, NULL, pools[t],
                                               &spare)
              : accel_build_triangles(&b, m->pos, m->idx, m->tri_count, NULL, &spare)) {
            failures += !CHECKF(0, "spare: build on %d threads failed", t);
            continue;
        }
        if (!t) {
            struct aabb *boxes = accel_triangle_boxes_pool(m->pos, m->idx, m->tri_count, NULL);
            struct bvh ref;
            const int built = boxes && !accel_build(&ref, boxes, m->tri_count, NULL);
            failures += !CHECKF(built && bvh_same_tree(&b, &ref),
                                "spare: the serial entry's tree is not accel_build's");
            if (built)
                bvh_release(&ref);
            rt_free(boxes);
        }
        failures += !CHECKF(spare.base != NULL, "spare: a %u-triangle build left no mapping",
                            m->tri_count);
        float *tri = accel_gather_triangles_pool(&b, m->pos, m->idx, pools[t]);
        struct bvh4 fresh, reused;
        if (!tri || accel_collapse_wide_pool(&fresh, &b, tri, 8, pools[t])) {
            failures += !CHECKF(0, "spare: gather or collapse failed");
        } else {
            const size_t bytes = spare.bytes;
            const void *block = spare.base;
            printf("  spare: %zu bytes, layout %llu bytes\n", bytes,
                   (unsigned long long)(bvh4_node_bytes(&fresh) + bvh4_leaf_bytes(&fresh)));
            if (accel_collapse_wide_reuse(&reused, &b, tri, 8, pools[t], &spare)) {
                failures += !CHECKF(0, "spare: collapse into the spare failed");
            } else {
                failures += !CHECKF(spare.base == NULL && reused.raw.base == block,
                                    "spare: the layout did not take the build's mapping");
                failures += !CHECKF(same_wide(&reused, &fresh),
                                    "spare: the layout in the build's mapping differs "
                                    "(%d threads)", t);
                printf("  spare (%d threads): %u triangles, a %zu MB mapping, %u nodes\n", t,
                       m->tri_count, bytes >> 20, reused.node_count);
                bvh4_release(&reused);
            }
            bvh4_release(&fresh);
        }
        rt_free_large(&spare);
        rt_free(tri);
        bvh_release(&b);
    }
}

/*
 * The item pool's retry (collapse4.c, COLLAPSE_POOL_FIRST_BYTES): a mesh
 * this large gathers its items first in a pool smaller than the worst
 * case, and when that pass fails (the pool runs out, or here an item's
 * own allocation fails on purpose) gathers every item again in the worst
 * case's pool.  The layout must be the one the collapse makes without a
 * failure, and a failure that is not retried must leave no layout.
 */
static void check_pool_retry(const struct tg_mesh *m, struct rt_pool *pool)
{
    struct bvh b;
    if (accel_build_parallel_triangles(&b, m->pos, m->idx, m->tri_count, NULL, pool, NULL)) {
        failures += !CHECKF(0, "pool retry: build failed");
        return;
    }
    float *tri = accel_gather_triangles_pool(&b, m->pos, m->idx, pool);
    struct bvh4 ref;
    if (!tri || accel_collapse_wide_pool(&ref, &b, tri, 8, pool)) {
        failures += !CHECKF(0, "pool retry: gather or collapse failed");
        rt_free(tri);
        bvh_release(&b);
        return;
    }
    int retried = 0;
    /* The first few allocations are the collapse's own arrays (a failure
     * there fails it); the items' follow. */
    for (long k = 0; k < 12; k++) {
        struct bvh4 w;
        rt_alloc_fail_once(k);
        const int rc = accel_collapse_wide_pool(&w, &b, tri, 8, pool);
        const long injected = rt_alloc_failures();
        rt_alloc_fail_reset();
        if (rc) {
            failures += !CHECKF(injected > 0 && w.node_count == 0,
                                "pool retry: failure %ld left a layout", k);
            continue;
        }
        if (injected) {
            retried++;
            failures += !CHECKF(same_wide(&w, &ref),
                                "pool retry: the layout after failure %ld differs", k);
        }
        bvh4_release(&w);
    }
    printf("  pool retry: %u triangles, %d collapses survived one failed allocation\n",
           m->tri_count, retried);
    failures += !CHECKF(retried > 0, "pool retry: no collapse survived a failed allocation");
    bvh4_release(&ref);
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
    for (int variant = 0; variant < 3; variant++)
        check_mesh("soup", &soup, pools, variant);
    /* Zero-area triangles (a corner repeated), whose packet lanes are NaN
     * (accel_set_packet_lane), in every lane position of a packet. */
    struct tg_mesh degenerate;
    tg_soup(&degenerate, 20000, 1.0f, 0.02f, &r);
    for (uint32_t t = 0; t < degenerate.tri_count; t++) {
        uint32_t *ix = &degenerate.idx[3 * (size_t)t];
        if (t % 7 == 0)
            ix[2] = ix[1];
        else if (t % 11 == 0)
            ix[1] = ix[0];
    }
    check_mesh("zero-area", &degenerate, pools, 0);
    tg_mesh_free(&degenerate);
    check_mesh("sphere", &sphere, pools, 0);
    check_mesh("tiny", &tiny, pools, 0);
    struct tg_mesh large;
    tg_soup(&large, 540000, 1.0f, 0.005f, &r);
    check_spare(&large, pools);
    check_pool_retry(&large, pools[2]);
    tg_mesh_free(&large);
    tg_mesh_free(&soup);
    tg_mesh_free(&sphere);
    tg_mesh_free(&tiny);
    for (int t = 1; t <= MAX_THREADS; t++)
        rt_pool_destroy(pools[t]);
    printf("collapse_threads: %s (%d failures, %.0f ms)\n", failures ? "FAIL" : "ok", failures,
           rt_now_ms() - t0);
    return failures ? 1 : 0;
}
