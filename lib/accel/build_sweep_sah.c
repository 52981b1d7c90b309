/* SPDX-License-Identifier: Apache-2.0 */
/*
 * build_sweep_sah.c - full sweep SAH builder: the quality reference.
 *
 * At every node the SAH (MacDonald and Booth 1990) is evaluated at every
 * split between consecutive centroids on each axis, from prefix boxes
 * swept in from both ends: the "sweep" build of Wald, Boulos and Shirley
 * 2007 ("Ray tracing deformable scenes using dynamic bounding volume
 * hierarchies", Wald, Ize and Parker's (2008) ref. [22]) that Wald, Ize and Parker (2008) table 1 takes as
 * the 100% reference.
 *
 * To stay O(n log n) the three axes are sorted once, up front, and kept
 * sorted (the idea of Wald and Havran 2006, "On building fast kd-trees for
 * ray tracing, and on doing that in O(N log N)"; madmann91/bvh's
 * sweep_sah_builder.h does the same for BVHs): each node owns the same
 * range [begin, end) of three arrays, one per axis, each holding the
 * node's primitives in centroid order on its axis.  A split cuts the
 * chosen axis' array where the sweep said and marks each primitive's
 * side; the two other arrays are partitioned stably by that mark, which
 * keeps them sorted.
 *
 * Conventions as in build_binned_sah.c: centroid = box.min + box.max
 * (twice the centroid); equal centroids are ordered by the caller's index;
 * ties between splits go to the lower axis and the earlier position.
 */
#include <assert.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "accel/build_internal.h"
#include "base/alloc.h"

/* A primitive in one axis' array: its box, the caller's index and its
 * centroid on that array's axis (the sort key). */
struct sref {
    float lo[3];
    uint32_t id;
    float hi[3];
    float key;
};
typedef char sref_is_32_bytes[sizeof(struct sref) == 32 ? 1 : -1];

/* Where to cut: the first `pos` entries of axis `axis`' array go left. */
struct cut {
    int axis;
    uint32_t pos;
    double sah; /* sum over both sides of half area * count */
};

struct sweep_state {
    struct sref *axis_refs[3];
    struct sref *tmp;       /* scratch for the stable partitions */
    uint8_t *goes_left;     /* by caller's index */
    double *right_sah;      /* by position in the node's range */
    uint64_t *sort_keys[2]; /* radix sort buffers (setup only) */
};

/* Stable LSD radix sort of n 64-bit words on their upper 32 bits, 8 bits
 * per pass.  The result ends up back in keys[0]. */
static void radix_sort_upper32(uint64_t *keys[2], size_t n)
{
    uint64_t *src = keys[0];
    uint64_t *dst = keys[1];
    for (int shift = 32; shift < 64; shift += 8) {
        size_t offset[256] = {0};
        for (size_t i = 0; i < n; i++)
            offset[(src[i] >> shift) & 0xff]++;
        size_t sum = 0;
        for (int b = 0; b < 256; b++) {
            size_t c = offset[b];
            offset[b] = sum;
            sum += c;
        }
        for (size_t i = 0; i < n; i++)
            dst[offset[(src[i] >> shift) & 0xff]++] = src[i];
        uint64_t *t = src;
        src = dst;
        dst = t;
    }
    /* Four passes: the sorted data is back in keys[0]. */
}

/* Fills axis k's array with all primitives in (centroid, index) order. */
static void presort_axis(struct sweep_state *st, const struct aabb *boxes, uint32_t n, int k)
{
    uint64_t *keys = st->sort_keys[0];
    for (uint32_t i = 0; i < n; i++) {
        float c = boxes[i].min[k] + boxes[i].max[k];
        keys[i] = (uint64_t)build_float_order(c) << 32 | i;
    }
    /* Stable on keys already in index order, so equal centroids keep
     * ascending index. */
    radix_sort_upper32(st->sort_keys, n);
    struct sref *a = st->axis_refs[k];
    for (uint32_t i = 0; i < n; i++) {
        uint32_t id = (uint32_t)keys[i];
        for (int j = 0; j < 3; j++) {
            a[i].lo[j] = boxes[id].min[j];
            a[i].hi[j] = boxes[id].max[j];
        }
        a[i].id = id;
        a[i].key = boxes[id].min[k] + boxes[id].max[k];
    }
}

static void grow_sref(struct aabb *box, const struct sref *r)
{
    for (int k = 0; k < 3; k++) {
        box->min[k] = build_min(box->min[k], r->lo[k]);
        box->max[k] = build_max(box->max[k], r->hi[k]);
    }
}

static struct aabb range_box(const struct sref *a, uint32_t n)
{
    struct aabb box = aabb_empty();
    for (uint32_t i = 0; i < n; i++)
        grow_sref(&box, &a[i]);
    return box;
}

/*
 * The sweep on one axis: right to left, store
 * area * count of every suffix; left to right, add the prefix's and keep
 * the cheapest cut.  Updates *best when this axis has a strictly cheaper
 * cut, so earlier axes win ties.
 */
static void sweep_axis(const struct sref *a, uint32_t n, int axis, double *right_sah,
                       struct cut *best)
{
    struct aabb box = aabb_empty();
    for (uint32_t i = n - 1; i > 0; i--) {
        grow_sref(&box, &a[i]);
        right_sah[i] = (double)aabb_half_area(&box) * (double)(n - i);
    }
    box = aabb_empty();
    for (uint32_t i = 0; i + 1 < n; i++) {
        grow_sref(&box, &a[i]);
        double sah = (double)aabb_half_area(&box) * (double)(i + 1) + right_sah[i + 1];
        if (sah < best->sah) {
            best->axis = axis;
            best->pos = i + 1;
            best->sah = sah;
        }
    }
}

/* Keeps the order of a[0, n) within each side: the entries marked left
 * first, then the others.  Returns the number marked left. */
static uint32_t stable_partition(struct sref *a, uint32_t n, const uint8_t *goes_left,
                                 struct sref *tmp)
{
    uint32_t l = 0;
    uint32_t r = 0;
    for (uint32_t i = 0; i < n; i++) {
        if (goes_left[a[i].id])
            a[l++] = a[i];
        else
            tmp[r++] = a[i];
    }
    memcpy(a + l, tmp, (size_t)r * sizeof(*a));
    return l;
}

/* Cuts the node's range: the first pos entries of the chosen axis' array
 * go left; the other two arrays follow, stably. */
static void apply_cut(struct sweep_state *st, const struct build_range *t, const struct cut *c)
{
    uint32_t n = t->end - t->begin;
    const struct sref *a = st->axis_refs[c->axis] + t->begin;
    for (uint32_t i = 0; i < n; i++)
        st->goes_left[a[i].id] = i < c->pos;
    for (int k = 0; k < 3; k++) {
        if (k == c->axis)
            continue;
        uint32_t l = stable_partition(st->axis_refs[k] + t->begin, n, st->goes_left, st->tmp);
        /* Every array holds the node's primitives, so the sides agree. */
        assert(l == c->pos);
        (void)l;
    }
}

static void free_state(struct sweep_state *st)
{
    for (int k = 0; k < 3; k++)
        rt_free(st->axis_refs[k]);
    rt_free(st->tmp);
    rt_free(st->goes_left);
    rt_free(st->right_sah);
    rt_free(st->sort_keys[0]);
    rt_free(st->sort_keys[1]);
}

static int alloc_state(struct sweep_state *st, uint32_t n)
{
    memset(st, 0, sizeof(*st));
    for (int k = 0; k < 3; k++)
        st->axis_refs[k] = rt_realloc_array(NULL, n, sizeof(struct sref));
    st->tmp = rt_realloc_array(NULL, n, sizeof(struct sref));
    st->goes_left = rt_malloc(n);
    st->right_sah = rt_realloc_array(NULL, n, sizeof(double));
    st->sort_keys[0] = rt_realloc_array(NULL, n, sizeof(uint64_t));
    st->sort_keys[1] = rt_realloc_array(NULL, n, sizeof(uint64_t));
    if (!st->axis_refs[0] || !st->axis_refs[1] || !st->axis_refs[2] || !st->tmp ||
        !st->goes_left || !st->right_sah || !st->sort_keys[0] || !st->sort_keys[1]) {
        free_state(st);
        return -1;
    }
    return 0;
}

int accel_build_sweep_sah(struct bvh *out, const struct aabb *prim_boxes, uint32_t prim_count,
                          const struct bvh_build_params *params)
{
    struct bvh_build_params p;
    int start = accel_build_begin(out, &p, params, prim_count);
    if (start <= 0)
        return start;
    struct sweep_state st;
    if (alloc_state(&st, prim_count)) {
        bvh_release(out);
        return -1;
    }
    for (int k = 0; k < 3; k++)
        presort_axis(&st, prim_boxes, prim_count, k);
    rt_free(st.sort_keys[0]);
    rt_free(st.sort_keys[1]);
    st.sort_keys[0] = NULL;
    st.sort_keys[1] = NULL;

    struct aabb root_box = range_box(st.axis_refs[0], prim_count);
    build_set_box(&out->nodes[0], &root_box);
    struct build_range stack[BUILD_STACK_SIZE];
    stack[0].begin = 0;
    stack[0].end = prim_count;
    stack[0].node = 0;
    stack[0].depth = 0;
    uint32_t sp = 1;
    uint32_t node_count = 1;
    uint32_t max_depth = 0;
    const uint32_t max_leaf = (uint32_t)p.max_leaf_size;
    while (sp > 0) {
        struct build_range task = stack[--sp];
        struct bvh_node *node = &out->nodes[task.node];
        uint32_t n = task.end - task.begin;
        if (task.depth > max_depth)
            max_depth = task.depth;
        if (n <= 1 || (n <= max_leaf && build_must_split_median(task.depth, n))) {
            build_set_leaf(node, task.begin, n);
            continue;
        }

        /* Centroid extent per axis straight from the sorted arrays. */
        float extent[3];
        int spread = 0;
        for (int k = 0; k < 3; k++) {
            const struct sref *a = st.axis_refs[k];
            extent[k] = a[task.end - 1].key - a[task.begin].key;
            spread |= extent[k] > 0.0f;
        }

        struct cut c;
        int use_sah = 0;
        if (spread && !build_must_split_median(task.depth, n)) {
            c.axis = 0;
            c.pos = 0;
            c.sah = HUGE_VAL;
            for (int k = 0; k < 3; k++)
                sweep_axis(st.axis_refs[k] + task.begin, n, k, st.right_sah, &c);
            if (c.pos > 0) {
                struct aabb node_box;
                for (int k = 0; k < 3; k++) {
                    node_box.min[k] = node->aabb_min[k];
                    node_box.max[k] = node->aabb_max[k];
                }
                double area = aabb_half_area(&node_box);
                double leaf_cost = (double)p.c_isect * (double)n * area;
                double split_cost = (double)p.c_trav * area + (double)p.c_isect * c.sah;
                use_sah = split_cost < leaf_cost;
            }
        }
        if (!use_sah && n <= max_leaf) {
            build_set_leaf(node, task.begin, n);
            continue;
        }
        if (!use_sah) {
            /* Object median (build_internal.h's depth guard), on the axis
             * of largest centroid extent; with coincident centroids every
             * array is in index order and any cut is as good. */
            c.axis = 0;
            for (int k = 1; k < 3; k++) {
                if (extent[k] > extent[c.axis])
                    c.axis = k;
            }
            c.pos = n / 2;
        }
        apply_cut(&st, &task, &c);

        const struct sref *a = st.axis_refs[c.axis] + task.begin;
        struct aabb left_box = range_box(a, c.pos);
        struct aabb right_box = range_box(a + c.pos, n - c.pos);
        struct build_range left, right;
        build_split(out->nodes, &task, task.begin + c.pos, &left_box, &right_box, &node_count,
                    &left, &right);
        stack[sp++] = right;
        stack[sp++] = left;
    }

    const struct sref *a = st.axis_refs[0];
    for (uint32_t i = 0; i < prim_count; i++)
        out->prim_index[i] = a[i].id;
    free_state(&st);
    accel_build_finish(out, node_count, max_depth);
    return 0;
}
