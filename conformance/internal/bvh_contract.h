/* SPDX-License-Identifier: Apache-2.0 */
/*
 * bvh_contract.h - checks shared by the dynamic-scene accel tests
 * (builders_dynamic.c, refit.c, parallel_build_threads.c): bvh_layout.h's output
 * contract for any builder, hits against the brute-force intersector, and
 * bit-exact tree comparison.  Header-only, like accel_testgeo.h, whose
 * geometry it uses, and check.h's CHECKF.  The checks count into the including
 * test's `static int failures`, which must be declared before the
 * #include.
 *
 * bvh_check_tree is the same list of invariants as builders.c's
 * check_tree (which is file-static there), including the one the
 * reverse-sweep refit (refit.h) relies on: every inner node's children
 * have larger indices than the node.
 */
#ifndef RT_CONFORMANCE_BVH_CONTRACT_H
#define RT_CONFORMANCE_BVH_CONTRACT_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accel/bvh_build.h"
#include "accel_testgeo.h"
#include "trace/trace.h"

static inline int bc_box_inside(const float in_min[3], const float in_max[3],
                                const float out_min[3], const float out_max[3])
{
    for (int k = 0; k < 3; k++) {
        if (!(in_min[k] >= out_min[k]) || !(in_max[k] <= out_max[k]))
            return 0;
    }
    return 1;
}

/* Every structural invariant of bvh_layout.h for a tree over boxes[0, n), leaves
 * of at most max_leaf.  finite == 0 skips the box containment checks
 * (input with NaN).  Returns the number of failures it added. */
static inline int bvh_check_tree(const char *what, const struct bvh *b,
                                 const struct aabb *boxes, uint32_t n, uint32_t max_leaf,
                                 int finite)
{
    int before = failures;
    if (n == 0) {
        failures += !CHECKF(
                 b->node_count == 0 && !b->nodes && b->prim_count == 0 && b->depth == 0,
                 "%s: empty tree", what);
        return failures - before;
    }
    failures += !CHECKF(b->prim_count == n, "%s: prim_count %u != %u", what, b->prim_count, n);
    failures += !CHECKF(b->node_count >= 1 && b->node_count <= 2 * n - 1,
             "%s: node_count %u for %u prims", what, b->node_count, n);
    if (failures != before)
        return failures - before;
    uint8_t *seen = tg_alloc(n);
    uint8_t *covered = tg_alloc(n);
    uint8_t *visited = tg_alloc(b->node_count);
    uint32_t *stack_node = tg_alloc(sizeof(uint32_t) * (b->node_count + 1));
    uint32_t *stack_depth = tg_alloc(sizeof(uint32_t) * (b->node_count + 1));
    memset(seen, 0, n);
    memset(covered, 0, n);
    memset(visited, 0, b->node_count);
    for (uint32_t i = 0; i < n && failures == before; i++) {
        uint32_t p = b->prim_index[i];
        failures += !CHECKF(p < n && !seen[p], "%s: prim_index[%u] = %u repeated or out of range",
                 what, i, p);
        if (p < n)
            seen[p] = 1;
    }
    uint32_t sp = 0;
    uint32_t visited_count = 0;
    uint32_t max_depth = 0;
    stack_node[sp] = 0;
    stack_depth[sp++] = 0;
    while (sp > 0 && failures == before) {
        sp--;
        uint32_t ni = stack_node[sp];
        uint32_t d = stack_depth[sp];
        failures += !CHECKF(ni < b->node_count && !visited[ni], "%s: node %u reached twice", what,
                 ni);
        if (failures != before)
            break;
        visited[ni] = 1;
        visited_count++;
        if (d > max_depth)
            max_depth = d;
        const struct bvh_node *node = &b->nodes[ni];
        if (node->count) {
            failures += !CHECKF(
                     node->count <= max_leaf && node->first < n && node->count <= n - node->first,
                     "%s: leaf %u holds [%u, +%u)", what, ni, node->first, node->count);
            if (failures != before)
                break;
            for (uint32_t s = node->first; s < node->first + node->count; s++) {
                failures += !CHECKF(!covered[s], "%s: slot %u in two leaves", what, s);
                covered[s] = 1;
                const struct aabb *pb = &boxes[b->prim_index[s]];
                if (finite)
                    failures += !CHECKF(
                             bc_box_inside(pb->min, pb->max, node->aabb_min, node->aabb_max),
                             "%s: leaf %u does not contain prim %u", what, ni, b->prim_index[s]);
            }
        } else {
            /* Children after their parent: the refit's reverse sweep
             * (refit.h) and the absence of cycles both rest on it. */
            failures += !CHECKF(node->first > ni && node->first + 1 < b->node_count,
                     "%s: inner %u has children %u, %u", what, ni, node->first, node->first + 1);
            if (failures != before)
                break;
            for (uint32_t c = node->first; c <= node->first + 1; c++) {
                if (finite)
                    failures += !CHECKF(
                             bc_box_inside(b->nodes[c].aabb_min, b->nodes[c].aabb_max,
                                           node->aabb_min, node->aabb_max),
                             "%s: node %u outside its parent %u", what, c, ni);
                stack_node[sp] = c;
                stack_depth[sp++] = d + 1;
            }
        }
    }
    if (failures == before) {
        failures += !CHECKF(visited_count == b->node_count, "%s: %u of %u nodes reachable", what,
                 visited_count, b->node_count);
        for (uint32_t s = 0; s < n && failures == before; s++)
            failures += !CHECKF(covered[s], "%s: slot %u in no leaf", what, s);
        failures += !CHECKF(max_depth == b->depth && b->depth <= BVH_MAX_DEPTH,
                 "%s: depth %u recorded %u (max %d)", what, max_depth, b->depth, BVH_MAX_DEPTH);
    }
    free(seen);
    free(covered);
    free(visited);
    free(stack_node);
    free(stack_depth);
    return failures - before;
}

/* Bit-exact equality of two trees (nodes, prim_index, counts, depth). */
static inline int bvh_same_tree(const struct bvh *a, const struct bvh *b)
{
    return a->node_count == b->node_count && a->prim_count == b->prim_count &&
           a->depth == b->depth &&
           (a->node_count == 0 ||
            memcmp(a->nodes, b->nodes, sizeof(*a->nodes) * a->node_count) == 0) &&
           (a->prim_count == 0 ||
            memcmp(a->prim_index, b->prim_index, sizeof(uint32_t) * a->prim_count) == 0);
}

/*
 * A set of rays through a mesh's bounds with their brute-force closest
 * hits (trace_closest_brute_force), computed once and compared against
 * any number of trees.  Half the rays aim inside a random triangle, so
 * that many hit; the others are random.
 */
struct bc_rays {
    uint32_t count;
    struct trace_ray *rays;
    int *found;
    struct trace_hit *hits;
};

static inline void bc_rays_make(struct bc_rays *s, const struct tg_mesh *m, uint32_t count,
                                uint64_t seed)
{
    struct tg_rng r;
    tg_seed(&r, seed);
    struct aabb bounds = aabb_empty();
    for (uint32_t v = 0; v < m->vertex_count; v++)
        aabb_grow_point(&bounds, &m->pos[3 * (size_t)v]);
    float size = 0.0f;
    for (int k = 0; k < 3; k++)
        size = fmaxf(size, bounds.max[k] - bounds.min[k]);
    s->rays = tg_alloc(sizeof(*s->rays) * count);
    s->found = tg_alloc(sizeof(*s->found) * count);
    s->hits = tg_alloc(sizeof(*s->hits) * count);
    s->count = 0;
    while (s->count < count) {
        float org[3];
        float target[3];
        for (int k = 0; k < 3; k++) {
            float c = 0.5f * (bounds.min[k] + bounds.max[k]);
            org[k] = c + size * tg_range(&r, -1.0f, 1.0f);
            target[k] = tg_range(&r, bounds.min[k], bounds.max[k]);
        }
        if (s->count % 2 && m->tri_count) {
            /* A point well inside a random triangle.  Not a vertex: a
             * grazing ray through a vertex can get a t from the plane of
             * a nearly parallel triangle that lies outside that
             * triangle's box, where no traversal looks (traversal.c's
             * domain, not the builders'). */
            uint32_t t = tg_below(&r, m->tri_count);
            float a = tg_range(&r, 0.05f, 0.9f);
            float b = tg_range(&r, 0.05f, 0.95f - a);
            for (int k = 0; k < 3; k++)
                target[k] = (1.0f - a - b) * tg_vertex(m, t, 0)[k] + a * tg_vertex(m, t, 1)[k] +
                            b * tg_vertex(m, t, 2)[k];
        }
        float dir[3];
        vec3_sub(dir, target, org);
        if (vec3_dot(dir, dir) == 0.0f)
            continue;
        uint32_t i = s->count++;
        trace_ray_init(&s->rays[i], org, dir, 0.0f);
        s->found[i] = trace_closest_brute_force(m->pos, m->idx, m->tri_count, &s->rays[i],
                                                INFINITY, &s->hits[i]);
    }
}

static inline void bc_rays_free(struct bc_rays *s)
{
    free(s->rays);
    free(s->found);
    free(s->hits);
    memset(s, 0, sizeof(*s));
}

/*
 * Closest hits of tree b (triangles tri in leaf order) against the
 * reference, by hit as traversal.c does: both find a hit or neither; on
 * the same primitive t, u, v are identical; on different primitives (two
 * at the same distance) t agrees within 1e-6 relative.  Returns the
 * number of rays that hit, so a caller can see they were not all misses.
 */
static inline uint32_t bc_check_hits(const char *what, const struct bvh *b, const float *tri,
                                     const struct bc_rays *s)
{
    uint32_t hits = 0;
    int before = failures;
    for (uint32_t i = 0; i < s->count && failures - before < 5; i++) {
        const struct trace_hit *ref = &s->hits[i];
        struct trace_hit got;
        int found = trace_closest(b, tri, &s->rays[i], INFINITY, &got, NULL);
        failures += !CHECKF(found == s->found[i], "%s: ray %u: hit %d, brute force %d", what, i,
                 found, s->found[i]);
        if (!found || !s->found[i])
            continue;
        hits++;
        if (got.prim == ref->prim)
            failures += !CHECKF(got.t == ref->t && got.u == ref->u && got.v == ref->v,
                     "%s: ray %u: prim %u t %.9g vs %.9g", what, i, got.prim, got.t, ref->t);
        else
            failures += !CHECKF(fabsf(got.t - ref->t) <= 1e-6f * fabsf(ref->t),
                     "%s: ray %u: prim %u t %.9g, brute force prim %u t %.9g", what, i, got.prim,
                     got.t, ref->prim, ref->t);
    }
    return hits;
}

#endif
