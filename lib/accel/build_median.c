/* SPDX-License-Identifier: Apache-2.0 */
/*
 * build_median.c - the spatial-median ("BIH-style") builder and the looser
 * leaf criterion (build_median.h).
 *
 * Wald, Ize and Parker (2008) table 1 compares the sweep SAH, the binned SAH and a
 * "median-split BIH-style build" (Wachter and Keller 2006): the median
 * build is 1.7-3.3x faster than 16-bin binning and gives 72-87% of the
 * sweep build's render speed.  It is the cheapest rebuild the runtime
 * has, and what the grid-based parallel build uses below its grid (Wald, Ize and Parker
 * (2008) sec. 5, "grid+BIH").
 *
 * Unlike a BIH, a small node (at most max_leaf_size primitives) keeps its
 * split only when the SAH favours it, which costs nothing but the node's
 * own partition and buys most of the gap to the SAH builders (measured
 * on 1M triangles: SAH cost 1.07-1.10x the sweep build's with it,
 * 1.3-1.5x with leaves cut at max_leaf_size as a BIH would, for a build
 * only 20-30% faster).
 *
 * Each node makes one pass over its primitives: the partition at the
 * middle of the centroid bounds' longest axis computes both children's
 * boxes and centroid bounds on the way, so no pass is spent on bounds.
 * The object-median fallback (a side would be empty, or the depth guard
 * of build_internal.h) costs a selection and two bounds passes, and only
 * happens on degenerate input.
 *
 * Conventions as in build_binned_sah.c: refs are struct build_ref (box +
 * index, 32 bytes) partitioned in place; centroid = min + max (doubled);
 * the object median orders equal centroids by index, so the build is
 * deterministic.
 */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "accel/build_internal.h"
#include "accel/build_median.h"
#include "accel/vec4.h"
#include "base/alloc.h"

/* A node waiting to be processed; its box is already in the node array.
 * clo/chi: its centroid bounds (lane 3 unused). */
struct mtask {
    struct build_range r; /* refs, node and depth (build_internal.h) */
    float clo[4];
    float chi[4];
};

void build_leaf_tolerance(const struct bvh_build_params *params,
                          uint32_t tol[BVH_MAX_DEPTH + 1])
{
    /* Wald, Benthin and Slusallek (2003) sec. 4.3: "the deeper the subdivision, the more triangles
     * will be tolerated per cell ... increase the tolerance threshold by
     * a constant factor for each level".  Starting at 1, not at the
     * paper's "2 or 3 triangles per cell": where the tolerance makes no
     * leaf our builders still let the SAH decide (the static criterion),
     * so that a factor of 1 is exactly the static build. */
    const uint32_t cap = (uint32_t)params->max_leaf_size;
    float g = params->leaf_growth;
    float t = 1.0f;
    for (int d = 0; d <= BVH_MAX_DEPTH; d++) {
        tol[d] = t >= (float)cap ? cap : (uint32_t)t;
        if (tol[d] < 1)
            tol[d] = 1;
        if (t < (float)cap)
            t *= g;
    }
}

static inline vec4 ref_lo(const struct build_ref *r)
{
    return vec4_xyz0(vec4_load(r->lo));
}

/* Box and centroid bounds of refs[begin, end). */
static void range_bounds(const struct build_ref *refs, uint32_t begin, uint32_t end,
                         struct aabb *box, float clo[4], float chi[4])
{
    vec4 lo = vec4_splat(INFINITY);
    vec4 hi = vec4_splat(-INFINITY);
    vec4 cl = lo;
    vec4 ch = hi;
    for (uint32_t i = begin; i < end; i++) {
        vec4 l = ref_lo(&refs[i]);
        vec4 h = vec4_load(refs[i].hi);
        vec4 c = vec4_add(l, h);
        lo = vec4_min(lo, l);
        hi = vec4_max(hi, h);
        cl = vec4_min(cl, c);
        ch = vec4_max(ch, c);
    }
    build_store_box(box, lo, hi);
    vec4_store(clo, cl);
    vec4_store(chi, ch);
}

/* Bounds accumulated by the partition for one side. */
struct side {
    vec4 lo, hi;   /* box */
    vec4 clo, chi; /* centroid bounds */
};

/*
 * The spatial-median partition: moves refs with centroid < plane on
 * `axis` to the front of [begin, end) and returns the first right slot;
 * fills both sides' boxes and centroid bounds.  Branch-free Lomuto, as
 * build_binned_sah.c's partition_refs (measured there 4x faster than
 * Hoare's scheme on random input, where the side is unpredictable).
 */
static uint32_t partition_spatial(struct build_ref *refs, uint32_t begin, uint32_t end, int axis,
                                  float plane, struct side *left, struct side *right)
{
    const vec4 inf = vec4_splat(INFINITY);
    const vec4 neg_inf = vec4_splat(-INFINITY);
    struct side l = {inf, neg_inf, inf, neg_inf};
    struct side r = l;
    uint32_t first_right = begin;
    for (uint32_t i = begin; i < end; i++) {
        struct build_ref x = refs[i];
        vec4 lo = ref_lo(&x);
        vec4 hi = vec4_load(x.hi);
        vec4 c = vec4_add(lo, hi);
        /* The same float sum as lane `axis` of c (one rounding). */
        float cs = x.lo[axis] + x.hi[axis];
        int is_left = cs < plane;
        l.lo = vec4_min(l.lo, vec4_select(is_left, lo, inf));
        l.hi = vec4_max(l.hi, vec4_select(is_left, hi, neg_inf));
        l.clo = vec4_min(l.clo, vec4_select(is_left, c, inf));
        l.chi = vec4_max(l.chi, vec4_select(is_left, c, neg_inf));
        r.lo = vec4_min(r.lo, vec4_select(is_left, inf, lo));
        r.hi = vec4_max(r.hi, vec4_select(is_left, neg_inf, hi));
        r.clo = vec4_min(r.clo, vec4_select(is_left, inf, c));
        r.chi = vec4_max(r.chi, vec4_select(is_left, neg_inf, c));
        refs[i] = refs[first_right];
        refs[first_right] = x;
        first_right += (uint32_t)is_left;
    }
    *left = l;
    *right = r;
    return first_right;
}


/* Axis of the largest centroid extent (the lowest on ties); *extent
 * receives it (not > 0 when the centroids coincide or are not finite). */
static int longest_axis(const float clo[4], const float chi[4], float *extent)
{
    int axis = 0;
    float e = chi[0] - clo[0];
    for (int k = 1; k < 3; k++) {
        float ek = chi[k] - clo[k];
        if (ek > e) {
            e = ek;
            axis = k;
        }
    }
    *extent = e;
    return axis;
}

void build_median_refs(struct bvh_node *nodes, struct build_ref *refs, uint32_t n,
                       uint32_t depth0, const struct bvh_build_params *params,
                       uint32_t *node_count_out, uint32_t *max_depth_out)
{
    uint32_t tol[BVH_MAX_DEPTH + 1];
    build_leaf_tolerance(params, tol);
    const uint32_t max_leaf = (uint32_t)params->max_leaf_size;

    struct mtask stack[BUILD_STACK_SIZE];
    struct aabb root_box;
    range_bounds(refs, 0, n, &root_box, stack[0].clo, stack[0].chi);
    build_set_box(&nodes[0], &root_box);
    stack[0].r.begin = 0;
    stack[0].r.end = n;
    stack[0].r.node = 0;
    stack[0].r.depth = depth0;

    uint32_t sp = 1;
    uint32_t node_count = 1;
    uint32_t max_depth = depth0;
    while (sp > 0) {
        struct mtask task = stack[--sp];
        struct bvh_node *node = &nodes[task.r.node];
        uint32_t count = task.r.end - task.r.begin;
        if (task.r.depth > max_depth)
            max_depth = task.r.depth;
        /* The caller's invariant keeps depth <= BVH_MAX_DEPTH; the clamp
         * only protects the table against a broken caller. */
        uint32_t tol_here = tol[task.r.depth <= BVH_MAX_DEPTH ? task.r.depth : BVH_MAX_DEPTH];
        int forced_median = build_must_split_median(task.r.depth, count);
        /* Wald, Benthin and Slusallek (2003) sec. 4.3's looser criterion first: it exists to save
         * the split's work.  Then the leaves the depth guard forces (as
         * in build_binned_sah.c). */
        if (count <= tol_here || (count <= max_leaf && forced_median)) {
            build_set_leaf(node, task.r.begin, count);
            continue;
        }

        struct mtask left;
        struct mtask right;
        struct aabb left_box;
        struct aabb right_box;
        uint32_t mid = task.r.begin;
        float extent;
        int axis = longest_axis(task.clo, task.chi, &extent);
        int spatial = 0;
        if (!forced_median && extent > 0.0f) {
            /* Wachter and Keller 2006 split the node's box; like Wald, Ize and Parker's
             * (2008) binning we split the centroid bounds, which never
             * leaves a side empty unless the midpoint rounds onto a
             * bound. */
            float plane = 0.5f * (task.clo[axis] + task.chi[axis]);
            struct side ls;
            struct side rs;
            mid = partition_spatial(refs, task.r.begin, task.r.end, axis, plane, &ls, &rs);
            spatial = mid != task.r.begin && mid != task.r.end;
            if (spatial) {
                build_store_box(&left_box, ls.lo, ls.hi);
                build_store_box(&right_box, rs.lo, rs.hi);
                vec4_store(left.clo, ls.clo);
                vec4_store(left.chi, ls.chi);
                vec4_store(right.clo, rs.clo);
                vec4_store(right.chi, rs.chi);
            }
        }
        if (!spatial) {
            /* Object median: halves of floor(n/2) and ceil(n/2), which
             * is what keeps the depth bounded (build_internal.h).  Equal
             * centroids on every axis need no ordering at all. */
            mid = task.r.begin + count / 2;
            if (extent > 0.0f)
                build_select_nth(refs + task.r.begin, count, count / 2, axis);
            range_bounds(refs, task.r.begin, mid, &left_box, left.clo, left.chi);
            range_bounds(refs, mid, task.r.end, &right_box, right.clo, right.chi);
        }
        if (count <= max_leaf) {
            /* Small node: keep the split only if the SAH favours it
             * (build_internal.h: costs compared multiplied by the area).
             * The partition has reordered the range, which a leaf does
             * not mind. */
            float area = build_node_half_area(node);
            float leaf_cost = params->c_isect * (float)count * area;
            float split_cost =
                params->c_trav * area +
                params->c_isect * (aabb_half_area(&left_box) * (float)(mid - task.r.begin) +
                                   aabb_half_area(&right_box) * (float)(task.r.end - mid));
            if (!(split_cost < leaf_cost)) {
                build_set_leaf(node, task.r.begin, count);
                continue;
            }
        }

        build_split(nodes, &task.r, mid, &left_box, &right_box, &node_count, &left.r,
                    &right.r);
        /* Right first, so the left subtree is numbered (and built) first. */
        stack[sp++] = right;
        stack[sp++] = left;
    }
    *node_count_out = node_count;
    *max_depth_out = max_depth;
}

int accel_build_median(struct bvh *out, const struct aabb *prim_boxes, uint32_t prim_count,
                       const struct bvh_build_params *params)
{
    struct bvh_build_params p;
    int start = accel_build_begin(out, &p, params, prim_count);
    if (start <= 0)
        return start;
    void *refs_block;
    struct build_ref *refs = rt_alloc_array64(prim_count, sizeof(*refs), &refs_block);
    if (!refs) {
        bvh_release(out);
        return -1;
    }
    for (uint32_t i = 0; i < prim_count; i++)
        build_ref_set(&refs[i], &prim_boxes[i], i);
    uint32_t node_count;
    uint32_t depth;
    build_median_refs(out->nodes, refs, prim_count, 0, &p, &node_count, &depth);
    for (uint32_t i = 0; i < prim_count; i++)
        out->prim_index[i] = build_ref_id(&refs[i]);
    rt_free(refs_block);
    accel_build_finish(out, node_count, depth);
    return 0;
}
