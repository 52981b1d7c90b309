/* SPDX-License-Identifier: Apache-2.0 */
/*
 * build_binned_sah.c - binned SAH builder (Wald 2007, "On fast construction
 * of SAH-based bounding volume hierarchies", Wald, Ize and Parker's (2008) ref. [20]; Wald, Ize and Parker
 * (2008) sec. 4).
 *
 * Each node projects its primitives' centroids into `bins` equal slices of
 * the centroid bounds on each axis, keeps a count and a box per bin, and
 * evaluates the SAH only at the bins-1 planes between slices, from prefix
 * boxes swept in from both ends.  The steps are separate functions, named
 * as in madmann91/bvh's binned_sah_builder.h: fill_bins (here
 * build_fill_bins, build_internal.h, shared with the parallel builder),
 * find_best_split, partition_refs, and the object-median fallback_split.
 *
 * Conventions: primitives travel as `struct build_ref` (box + caller index, 32
 * bytes) in one array partitioned in place, so every pass over a node is a
 * linear scan.  A "centroid" here is box.min + box.max, twice the true
 * centroid: the factor cancels in every ratio and saves a multiply.
 * The build is sequential and deterministic: ties go to the lower axis and
 * the lower plane, and the median split orders equal centroids by index.
 */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "accel/build_internal.h"
#include "accel/build_median.h"
#include "accel/triangle_box.h"
#include "accel/vec4.h"
#include "base/alloc.h"

/* Primitives travel as struct build_ref (build_median.h): the box plus the
 * caller's index in lane 3 of lo, 32 bytes, loaded as two vec4. */

/* The bins of all three axes (Wald, Ize and Parker (2008) sec. 4: "we track not only the
 * number of triangles in each bin, but also the bounds of all triangles
 * projecting to this bin"): box[axis][bin] = min xyz -, max xyz -. */
struct bins {
    float box[3][BVH_MAX_BINS][8];
    /* count[k][b][0]; the stride of a box, so that build_fill_bins
     * reaches both with one byte offset (build_bin_offsets). */
    uint32_t count[3][BVH_MAX_BINS][8];
};

/* Byte offset of axis k's first bin in bins.box and bins.count. */
static const uint32_t bins_axis_base[4] = {0, BVH_MAX_BINS * 32, 2 * BVH_MAX_BINS * 32, 0};

/* Centroid bounds (of the doubled centroids, see the header comment);
 * lane 3 unused. */
struct cbounds {
    float lo[4];
    float hi[4];
};

/* The result of find_best_split: plane `plane` on `axis` puts bins
 * [0, plane) left.  sah = sum over both children of half area * count
 * (build_internal.h's "cost times area" without the constants). */
struct split {
    int axis;
    int plane;
    float sah;
    uint32_t left_count;
    struct aabb left;
    struct aabb right;
};

/* A node waiting to be processed; its box is already in the node array. */
struct task {
    struct build_range r; /* refs, node and depth (build_internal.h) */
    struct cbounds cb;
};

/* Per-axis mapping centroid -> bin as in Wald 2007: bin = k1 (c - min)
 * with k1 = K / extent (clamped below instead of scaling K by 1 - epsilon).
 * An axis whose centroids do not spread (extent 0, or so small that the
 * scale overflows) is not binned: scale 0 marks it, and maps every
 * centroid to bin 0. */
struct binning {
    struct build_bin_map map;
    int binnable[3];
};

/*
 * Small nodes get fewer bins: at most BINNED_BINS_BASE + n / BINNED_PRIMS_PER_BIN.
 * Embree does the same with a steeper rule (kernels/builders/
 * heuristic_binning.h, BinMapping: num = min(BINS, 4 + 0.05 N)).  The
 * sweep costs O(bins) per node whatever n, and most nodes are small, so
 * without this the sweep dominates the build for many bins.  Measured on
 * 1M random triangles (SAH cost relative to the configured bin count
 * everywhere): +0.02% at 16 bins, +0.04% at 64 bins, for a build ~1.5x
 * faster at 64 bins; Embree's 4 + n/20 cost +0.9% at 16 bins.
 */
#define BINNED_BINS_BASE 4
#define BINNED_PRIMS_PER_BIN 2

static int bins_for(int bins, uint32_t n)
{
    uint32_t adaptive = BINNED_BINS_BASE + n / BINNED_PRIMS_PER_BIN;
    return adaptive < (uint32_t)bins ? (int)adaptive : bins;
}

static void init_binning(struct binning *bn, const struct cbounds *cb, int bin_count)
{
    float scale[3];
    for (int k = 0; k < 3; k++) {
        float extent = cb->hi[k] - cb->lo[k];
        float s = (float)bin_count / extent;
        bn->binnable[k] = extent > 0.0f && s > 0.0f && isfinite(s);
        scale[k] = bn->binnable[k] ? s : 0.0f;
    }
    bn->map.origin = vec4_set(cb->lo[0], cb->lo[1], cb->lo[2], 0.0f);
    bn->map.scale = vec4_set(scale[0], scale[1], scale[2], 0.0f);
    bn->map.last = vec4_splat((float)(bin_count - 1));
}



/* Box and centroid bounds of refs[begin, end). */
static void range_bounds(const struct build_ref *refs, uint32_t begin, uint32_t end,
                         struct aabb *box, struct cbounds *cb)
{
    vec4 lo = vec4_splat(INFINITY);
    vec4 hi = vec4_splat(-INFINITY);
    vec4 clo = lo;
    vec4 chi = hi;
    for (uint32_t i = begin; i < end; i++) {
        lo = vec4_min(lo, vec4_xyz0(vec4_load(refs[i].lo)));
        hi = vec4_max(hi, vec4_load(refs[i].hi));
        vec4 c = build_ref_centroid(&refs[i]);
        clo = vec4_min(clo, c);
        chi = vec4_max(chi, c);
    }
    build_store_box(box, lo, hi);
    vec4_store(cb->lo, clo);
    vec4_store(cb->hi, chi);
}

/* Step 1, projecting every primitive of the node into the bins of each
 * axis (Wald, Ize and Parker (2008) sec. 4; Wald 2007), is
 * build_fill_bins (build_internal.h) or its AVX2 form. */

/* One side of find_best_split's sweep, the three axes one per lane: the
 * side's box as x, y, z columns (lo and hi) and its triangle counts. */
struct sweep3 {
    vec4 lox, loy, loz, hix, hiy, hiz;
    uint32_t count[3];
};

static inline void sweep3_reset(struct sweep3 *s)
{
    s->lox = s->loy = s->loz = vec4_splat(INFINITY);
    s->hix = s->hiy = s->hiz = vec4_splat(-INFINITY);
    s->count[0] = s->count[1] = s->count[2] = 0;
}

/* Grows the side by bin i of every axis (the boxes transposed to x, y, z
 * columns, vec4_transpose3) and returns its counts as floats, lane k for
 * axis k. */
static inline vec4 sweep3_add_bin(struct sweep3 *s, const struct bins *bins, int i)
{
    vec4 x, y, z;
    vec4_transpose3(vec4_load(&bins->box[0][i][0]), vec4_load(&bins->box[1][i][0]),
                    vec4_load(&bins->box[2][i][0]), &x, &y, &z);
    s->lox = vec4_min(s->lox, x);
    s->loy = vec4_min(s->loy, y);
    s->loz = vec4_min(s->loz, z);
    vec4_transpose3(vec4_load(&bins->box[0][i][4]), vec4_load(&bins->box[1][i][4]),
                    vec4_load(&bins->box[2][i][4]), &x, &y, &z);
    s->hix = vec4_max(s->hix, x);
    s->hiy = vec4_max(s->hiy, y);
    s->hiz = vec4_max(s->hiz, z);
    for (int k = 0; k < 3; k++)
        s->count[k] += bins->count[k][i][0];
    return vec4_set((float)s->count[0], (float)s->count[1], (float)s->count[2], 0.0f);
}

static inline vec4 sweep3_half_area(const struct sweep3 *s)
{
    return vec4_half_area3(s->lox, s->loy, s->loz, s->hix, s->hiy, s->hiz);
}

/*
 * Step 2: the SAH at every plane between bins, on every binnable axis.
 * A sweep from the right stores the right side's area * count for each
 * plane, a sweep from the left completes the cost (Wald 2007).  Planes
 * with an empty side do not split the node and are skipped.  The sweeps
 * accumulate without data-dependent branches (the left one branches only
 * when an axis finds a better plane): an empty bin's box (+inf, -inf) is
 * the identity of min/max, and a plane that follows an empty bin splits
 * exactly like the plane before it, which was seen first and wins the tie.
 * Returns 0 when no plane splits the node, else 1 with *best filled.
 */
static int find_best_split(const struct bins *bins, int bin_count, const struct binning *bn,
                           struct split *best)
{
    /* The three axes side by side, one per lane (lane 3 unused): per
     * bin, the axes' boxes transposed to x, y, z columns (vec4_transpose3),
     * so one min/max per coordinate and one half-area computation serve
     * all three.  Per lane the operations are those of a sweep over one
     * axis at a time (the form this function had before, and the
     * parallel builder's pick_split still has): d = hi - lo,
     * (dx dy + dy dz) + dz dx (vec4_half_area's order), times the count
     * converted to float (counts stay exact integers in scalars), plus
     * the right side's; strict < keeps each axis's first best plane, and
     * the axes are then compared in order, so ties still go to the lower
     * axis and plane, and the same plane wins as axis by axis. */
    float right_sah[BVH_MAX_BINS][4];
    float right_count[BVH_MAX_BINS][4]; /* as floats: only compared with 0 */
    const vec4 zero = vec4_splat(0.0f);
    struct sweep3 acc;
    sweep3_reset(&acc);
    for (int i = bin_count - 1; i > 0; i--) {
        vec4 count = sweep3_add_bin(&acc, bins, i);
        vec4_store(right_count[i], count);
        vec4_store(right_sah[i], vec4_mul(sweep3_half_area(&acc), count));
    }
    sweep3_reset(&acc);
    vec4 lane_best = vec4_splat(INFINITY);
    float lane_sah[4];
    int lane_plane[3] = {0, 0, 0};
    uint32_t lane_left[3] = {0, 0, 0};
    for (int i = 0; i < bin_count - 1; i++) {
        vec4 count = sweep3_add_bin(&acc, bins, i);
        vec4 sah = vec4_add(vec4_mul(sweep3_half_area(&acc), count), vec4_load(right_sah[i + 1]));
        /* An empty side gives inf * 0 = NaN or a meaningless value: such
         * a plane never wins (as if its cost were +inf). */
        uint32_t better = vec4_lt_bits(sah, lane_best) & vec4_ne_bits(count, zero) &
                          vec4_ne_bits(vec4_load(right_count[i + 1]), zero) & 7u;
        if (better) {
            float s[4];
            vec4_store(s, sah);
            vec4_store(lane_sah, lane_best);
            const uint32_t *c = acc.count;
            for (int k = 0; k < 3; k++) {
                if (better >> k & 1u) {
                    lane_sah[k] = s[k];
                    lane_plane[k] = i + 1;
                    lane_left[k] = c[k];
                }
            }
            lane_best = vec4_load(lane_sah);
        }
    }
    vec4_store(lane_sah, lane_best);
    float best_sah = INFINITY;
    int best_axis = -1;
    int best_plane = 0;
    uint32_t best_left_count = 0;
    for (int k = 0; k < 3; k++) {
        if (bn->binnable[k] && lane_sah[k] < best_sah) {
            best_sah = lane_sah[k];
            best_axis = k;
            best_plane = lane_plane[k];
            best_left_count = lane_left[k];
        }
    }
    if (best_axis < 0)
        return 0;
    best->axis = best_axis;
    best->plane = best_plane;
    best->sah = best_sah;
    best->left_count = best_left_count;
    vec4 lo = vec4_splat(INFINITY);
    vec4 hi = vec4_splat(-INFINITY);
    for (int i = 0; i < best_plane; i++) {
        lo = vec4_min(lo, vec4_load(&bins->box[best_axis][i][0]));
        hi = vec4_max(hi, vec4_load(&bins->box[best_axis][i][4]));
    }
    build_store_box(&best->left, lo, hi);
    lo = vec4_splat(INFINITY);
    hi = vec4_splat(-INFINITY);
    for (int i = best_plane; i < bin_count; i++) {
        lo = vec4_min(lo, vec4_load(&bins->box[best_axis][i][0]));
        hi = vec4_max(hi, vec4_load(&bins->box[best_axis][i][4]));
    }
    build_store_box(&best->right, lo, hi);
    return 1;
}

/*
 * Step 3: moves the primitives left of the chosen plane to the front of
 * [begin, end) and returns the first right slot.  Each primitive is
 * classified by one comparison with the least coordinate binned at or
 * above the plane (build_split_threshold), found with build_bins_of, the
 * very computation build_fill_bins counted it with, so the sides match
 * the bin counts.  Computes each side's centroid bounds on the way, for
 * the children's binning.  Where the CPU runs AVX2 the same loop runs as
 * build_partition_fn's AVX2 form (build_binned_avx2.c).
 *
 * Lomuto's scheme without branches: every element is swapped with the
 * first right slot, which advances only past left ones.  The sides are
 * effectively random, so a branch per element would mispredict about half
 * the time (the observation behind Edelkamp and Weiss 2016,
 * "BlockQuicksort"); measured 4x faster than Hoare's scheme on 1M refs.
 * The side bounds are kept without a select either (build_side_offset,
 * build_internal.h).
 */
static uint32_t partition_refs(struct build_ref *refs, uint32_t begin, uint32_t end,
                               const struct binning *bn, const struct split *s,
                               build_partition_fn avx2, struct cbounds *left_cb,
                               struct cbounds *right_cb)
{
    const int axis = s->axis;
    float origin[4];
    float scale[4];
    vec4_store(origin, bn->map.origin);
    vec4_store(scale, bn->map.scale);
    const float t = build_split_threshold(&bn->map, axis, s->plane, origin[axis], scale[axis]);
    if (avx2) {
        /* The same loop in AVX2 (build_internal.h, build_partition_fn). */
        float bounds[4][4];
        uint32_t first_right = avx2(refs, NULL, begin, end, 0, 0, axis, t, bounds);
        memcpy(left_cb->lo, bounds[0], sizeof(left_cb->lo));
        memcpy(left_cb->hi, bounds[1], sizeof(left_cb->hi));
        memcpy(right_cb->lo, bounds[2], sizeof(right_cb->lo));
        memcpy(right_cb->hi, bounds[3], sizeof(right_cb->hi));
        return first_right;
    }
    const vec4 threshold = vec4_splat(t);
    vec4 llo = vec4_splat(INFINITY);
    vec4 lhi = vec4_splat(-INFINITY);
    vec4 rlo = llo;
    vec4 rhi = lhi;
    uint32_t first_right = begin;
    for (uint32_t i = begin; i < end; i++) {
        struct build_ref x = refs[i];
        vec4 c = build_ref_centroid(&x);
        const uint32_t left = ((vec4_ge_bits(c, threshold) >> axis) & 1u) ^ 1u;
        build_side_grow(c, left, &llo, &lhi, &rlo, &rhi);
        refs[i] = refs[first_right];
        refs[first_right] = x;
        first_right += left;
    }
    vec4_store(left_cb->lo, llo);
    vec4_store(left_cb->hi, lhi);
    vec4_store(right_cb->lo, rlo);
    vec4_store(right_cb->hi, rhi);
    return first_right;
}

/*
 * Step 2b, for nodes of at most BINNED_EXACT_MAX primitives: the exact
 * SAH over their centroids sorted on each axis (a sweep as in
 * build_sweep_sah.c).  Most nodes of a tree are this small (a 1M-triangle
 * build has ~400k nodes of 2 primitives) and for them clearing and
 * sweeping bins costs several times more than sorting a handful of keys;
 * the exact sweep also evaluates every cut a bin plane could make (a plane
 * cuts the sorted order) and more, so the tree can only get better.
 */
#define BINNED_EXACT_MAX 8

struct small_split {
    int axis;
    uint32_t pos; /* the first `pos` of `order` go left */
    float sah;
    uint8_t order[BINNED_EXACT_MAX];
};

/* Fills order[k][0, n) with 0..n-1 sorted by the refs' centroids on axis
 * k (build_float_order of lo[k] + hi[k]), ties in slot order.  By
 * rank counting: O(n^2) comparisons but no data-dependent branch, which
 * for n <= 8 beats any comparison sort (an insertion sort here measured
 * three times slower, from mispredicted branches).  Each pair is compared
 * once: for j < i, j comes first exactly when key[j] <= key[i].  The
 * keys are build_float_order values, a total order, so the ranks are a
 * permutation whatever the input. */
static void sort_small3(const struct build_ref *refs, uint32_t n,
                        uint8_t order[3][BINNED_EXACT_MAX])
{
    /* The three axes at once, one per lane: key of ref i = its doubled
     * centroid (lo + hi, the scalar sum per lane) as an ordered integer
     * (vec4_order_key: the signed form of build_float_order).  For j < i,
     * gt = -1 when key[j] > key[i], i.e. when j does not come first, so
     * rank[i] += 1 + gt and rank[j] -= gt; the 1s are rank[i]'s start
     * value i. */
    vec4i key[BINNED_EXACT_MAX];
    vec4i rank[BINNED_EXACT_MAX];
    for (uint32_t i = 0; i < n; i++) {
        key[i] = vec4_order_key(build_ref_centroid(&refs[i]));
        rank[i] = vec4i_splat((int32_t)i);
    }
    for (uint32_t i = 1; i < n; i++) {
        for (uint32_t j = 0; j < i; j++) {
            vec4i gt = vec4i_gt(key[j], key[i]);
            rank[i] = vec4i_add(rank[i], gt);
            rank[j] = vec4i_sub(rank[j], gt);
        }
    }
    for (uint32_t i = 0; i < n; i++) {
        int32_t r[4];
        vec4i_store(r, rank[i]);
        for (int k = 0; k < 3; k++)
            order[k][r[k]] = (uint8_t)i;
    }
}

static int find_small_split(const struct build_ref *refs, uint32_t n, struct small_split *best)
{
    if (n == 2) {
        /* One possible split, whatever the axis: the commonest node of
         * all, so it skips the sorts. */
        best->axis = 0;
        best->pos = 1;
        best->order[0] = 0;
        best->order[1] = 1;
        best->sah = vec4_half_area(vec4_xyz0(vec4_load(refs[0].lo)), vec4_load(refs[0].hi)) +
                    vec4_half_area(vec4_xyz0(vec4_load(refs[1].lo)), vec4_load(refs[1].hi));
        return 1;
    }
    uint8_t order[3][BINNED_EXACT_MAX];
    float right_sah[BINNED_EXACT_MAX];
    float best_sah = INFINITY;
    int best_axis = -1;
    uint32_t best_pos = 0;
    sort_small3(refs, n, order);
    for (int k = 0; k < 3; k++) {
        const uint8_t *o = order[k];
        vec4 lo = vec4_splat(INFINITY);
        vec4 hi = vec4_splat(-INFINITY);
        for (uint32_t i = n - 1; i > 0; i--) {
            lo = vec4_min(lo, vec4_xyz0(vec4_load(refs[o[i]].lo)));
            hi = vec4_max(hi, vec4_load(refs[o[i]].hi));
            right_sah[i] = vec4_half_area(lo, hi) * (float)(n - i);
        }
        lo = vec4_splat(INFINITY);
        hi = vec4_splat(-INFINITY);
        for (uint32_t i = 0; i + 1 < n; i++) {
            lo = vec4_min(lo, vec4_xyz0(vec4_load(refs[o[i]].lo)));
            hi = vec4_max(hi, vec4_load(refs[o[i]].hi));
            float sah = vec4_half_area(lo, hi) * (float)(i + 1) + right_sah[i + 1];
            if (sah < best_sah) {
                best_sah = sah;
                best_axis = k;
                best_pos = i + 1;
            }
        }
    }
    if (best_axis < 0)
        return 0;
    best->axis = best_axis;
    best->pos = best_pos;
    best->sah = best_sah;
    memcpy(best->order, order[best_axis], n);
    return 1;
}

/* Puts the node's refs in the chosen order; returns the first right slot. */
static uint32_t apply_small_split(struct build_ref *refs, uint32_t begin, uint32_t n,
                                  const struct small_split *s)
{
    struct build_ref tmp[BINNED_EXACT_MAX];
    for (uint32_t i = 0; i < n; i++)
        tmp[i] = refs[begin + s->order[i]];
    memcpy(&refs[begin], tmp, n * sizeof(*tmp));
    return begin + s->pos;
}


/*
 * Step 4, the fallback: split [begin, end) at the object median, i.e. into
 * halves of floor(n/2) and ceil(n/2) primitives (which is what keeps the
 * depth bounded, build_internal.h).  Along the axis of largest centroid
 * extent when the centroids spread at all; when they coincide on every
 * axis (thousands of identical triangles, say) the order is irrelevant and
 * the range is simply cut in two.  Returns the first right slot.
 */
static uint32_t fallback_split(struct build_ref *refs, uint32_t begin, uint32_t end,
                               const struct cbounds *cb)
{
    uint32_t n = end - begin;
    uint32_t mid = begin + n / 2;
    int axis = 0;
    float extent = cb->hi[0] - cb->lo[0];
    for (int k = 1; k < 3; k++) {
        float e = cb->hi[k] - cb->lo[k];
        if (e > extent) {
            extent = e;
            axis = k;
        }
    }
    if (extent > 0.0f)
        build_select_nth(refs + begin, n, n / 2, axis);
    return mid;
}

static int centroids_coincide(const struct cbounds *cb)
{
    return !(cb->hi[0] > cb->lo[0]) && !(cb->hi[1] > cb->lo[1]) && !(cb->hi[2] > cb->lo[2]);
}

/* The build of refs[0, prim_count) whose bounds (range_bounds') are
 * root_box and root_cb: build_binned_sah_refs after its bounds pass, or
 * build_binned_sah_source after a set-up that computed them. */
static int binned_build_refs(struct bvh_node *nodes, struct build_ref *refs, uint32_t prim_count,
                             const struct bvh_build_params *params, int simd,
                             const struct aabb *root_box, const struct cbounds *root_cb,
                             uint32_t *node_count_out, uint32_t *depth_out)
{
    const struct bvh_build_params p = *params;
    /* Aligned to 64 (rt_align64): fill_bins stores whole 32-byte records. */
    void *bins_block;
    struct bins *bins = rt_alloc_array64(1, sizeof(struct bins), &bins_block);
    if (!bins)
        return -1;

    /* The top nodes' refs are in the input's order (the in-place
     * partition keeps the left side's order): the form that fills a
     * large node in four streams (build_internal.h). */
    const build_fill_bins_fn fill = simd ? build_fill_bins_ordered_best() : build_fill_bins;
    const build_partition_fn partition_avx2 = simd ? build_partition_avx2_unit() : NULL;
    char *bin_box = (char *)bins->box;
    char *bin_count_base = (char *)bins->count;
    struct task stack[BUILD_STACK_SIZE];
    struct task *t = &stack[0];
    t->cb = *root_cb;
    build_set_box(&nodes[0], root_box);
    t->r.begin = 0;
    t->r.end = prim_count;
    t->r.node = 0;
    t->r.depth = 0;

    uint32_t sp = 1;
    uint32_t node_count = 1;
    uint32_t max_depth = 0;
    const uint32_t max_leaf = (uint32_t)p.max_leaf_size;
    while (sp > 0) {
        struct task task = stack[--sp];
        struct bvh_node *node = &nodes[task.r.node];
        uint32_t n = task.r.end - task.r.begin;
        if (task.r.depth > max_depth)
            max_depth = task.r.depth;

        /* Decide between a leaf, an SAH split and the median fallback
         * (the order of madmann91/bvh's top_down_sah_builder.h). */
        if (n <= 1 || (n <= max_leaf && build_must_split_median(task.r.depth, n))) {
            build_set_leaf(node, task.r.begin, n);
            continue;
        }
        enum { SPLIT_MEDIAN, SPLIT_BINNED, SPLIT_SMALL } kind = SPLIT_MEDIAN;
        struct split s = {0};
        struct small_split ss;
        /* Zeroed although only SPLIT_BINNED reads it after init_binning:
         * gcc -O2 with TSan cannot see that and warns. */
        struct binning bn;
        memset(&bn, 0, sizeof(bn));
        if (!centroids_coincide(&task.cb) && !build_must_split_median(task.r.depth, n)) {
            float sah = 0.0f;
            if (n <= BINNED_EXACT_MAX) {
                if (find_small_split(&refs[task.r.begin], n, &ss)) {
                    kind = SPLIT_SMALL;
                    sah = ss.sah;
                }
            } else {
                int bin_count = bins_for(p.bins, n);
                init_binning(&bn, &task.cb, bin_count);
                fill(bin_box, bin_count_base, bins_axis_base, bin_count, &bn.map, refs,
                     task.r.begin, task.r.end);
                if (find_best_split(bins, bin_count, &bn, &s)) {
                    kind = SPLIT_BINNED;
                    sah = s.sah;
                }
            }
            /* build_internal.h: costs compared multiplied by the area. */
            float area = build_node_half_area(node);
            float leaf_cost = p.c_isect * (float)n * area;
            float split_cost = p.c_trav * area + p.c_isect * sah;
            if (!(split_cost < leaf_cost))
                kind = SPLIT_MEDIAN;
        }
        if (kind == SPLIT_MEDIAN && n <= max_leaf) {
            build_set_leaf(node, task.r.begin, n);
            continue;
        }

        uint32_t mid = task.r.begin;
        struct task left;
        struct task right;
        struct aabb left_box;
        struct aabb right_box;
        if (kind == SPLIT_BINNED) {
            mid = partition_refs(refs, task.r.begin, task.r.end, &bn, &s, partition_avx2,
                                 &left.cb, &right.cb);
            left_box = s.left;
            right_box = s.right;
            /* partition_refs classifies exactly as build_fill_bins
             * counted, so this cannot fail; if it ever did, the boxes
             * taken from the bins would be wrong, so split again from
             * scratch. */
            if (mid - task.r.begin != s.left_count)
                kind = SPLIT_MEDIAN;
        }
        if (kind != SPLIT_BINNED) {
            if (kind == SPLIT_SMALL)
                mid = apply_small_split(refs, task.r.begin, n, &ss);
            else
                mid = fallback_split(refs, task.r.begin, task.r.end, &task.cb);
            range_bounds(refs, task.r.begin, mid, &left_box, &left.cb);
            range_bounds(refs, mid, task.r.end, &right_box, &right.cb);
        }

        build_split(nodes, &task.r, mid, &left_box, &right_box, &node_count, &left.r,
                    &right.r);
        /* Right first, so the left subtree is numbered (and built) first. */
        stack[sp++] = right;
        stack[sp++] = left;
    }

    rt_free(bins_block);
    *node_count_out = node_count;
    *depth_out = max_depth;
    return 0;
}

int build_binned_sah_refs(struct bvh_node *nodes, struct build_ref *refs, uint32_t prim_count,
                          const struct bvh_build_params *params, int simd, uint32_t *node_count_out,
                          uint32_t *depth_out)
{
#if !defined(BUILD_BINNED_UNIT_AVX2)
    /* The same source compiled for AVX2, where it runs
     * (build_binned_sah_avx2.c): the same tree in fewer instructions. */
    const build_binned_refs_fn avx2 = simd ? build_binned_sah_refs_avx2_unit() : NULL;
    if (avx2)
        return avx2(nodes, refs, prim_count, params, simd, node_count_out, depth_out);
#endif
    struct aabb root_box;
    struct cbounds root_cb;
    range_bounds(refs, 0, prim_count, &root_box, &root_cb);
    return binned_build_refs(nodes, refs, prim_count, params, simd, &root_box, &root_cb,
                             node_count_out, depth_out);
}

/* A ref's box into the bounds as range_bounds grows them, from the ref's
 * own lo (lane 3 cleared: it holds the id) and hi. */
static inline void bounds_grow(vec4 l, vec4 h, vec4 *lo, vec4 *hi, vec4 *clo, vec4 *chi)
{
    const vec4 c = vec4_add(l, h);
    *lo = vec4_min(*lo, l);
    *hi = vec4_max(*hi, h);
    *clo = vec4_min(*clo, c);
    *chi = vec4_max(*chi, c);
}

/*
 * The refs' set-up: refs[i] from box i of src (the caller's boxes, or
 * the triangles' boxes computed here, triangle_box.h, the very floats
 * accel_triangle_boxes_pool stores), and in the same pass the root's
 * box and centroid bounds, the values range_bounds would compute over
 * the refs just written (the same vec4 operations on the same lanes in
 * the same order: min and max of the box's lo with lane 3 cleared and
 * of its hi, whose lane 3 is +0, and of their sum), so the build that
 * follows is the one build_binned_sah_refs makes, without a second pass
 * over the refs (32 MB for a million triangles).
 */
static void setup_refs(struct build_ref *refs, const struct build_source *src, uint32_t n,
                       struct aabb *root_box, struct cbounds *root_cb)
{
    vec4 lo = vec4_splat(INFINITY);
    vec4 hi = vec4_splat(-INFINITY);
    vec4 clo = lo;
    vec4 chi = hi;
    if (src->boxes) {
        for (uint32_t i = 0; i < n; i++) {
            build_ref_set(&refs[i], &src->boxes[i], i);
            bounds_grow(vec4_xyz0(vec4_load(refs[i].lo)), vec4_load(refs[i].hi), &lo, &hi, &clo,
                        &chi);
        }
    } else {
        for (uint32_t i = 0; i < n; i++) {
            vec4 l, h;
            triangle_ref_set(&refs[i], src->positions, src->indices, i, &l, &h);
            bounds_grow(l, h, &lo, &hi, &clo, &chi);
        }
    }
    build_store_box(root_box, lo, hi);
    vec4_store(root_cb->lo, clo);
    vec4_store(root_cb->hi, chi);
}

int build_binned_sah_source(struct bvh *out, const struct build_source *src, uint32_t prim_count,
                            const struct bvh_build_params *params, int simd,
                            struct rt_large_block *spare)
{
#if !defined(BUILD_BINNED_UNIT_AVX2)
    /* The whole build in the AVX2 copy where it runs: the refs' set-up
     * and prim_index loops too. */
    const build_binned_fn avx2 = simd ? accel_build_binned_sah_avx2_unit() : NULL;
    if (avx2)
        return avx2(out, src, prim_count, params, simd, spare);
#endif
    if (spare)
        memset(spare, 0, sizeof(*spare));
    struct bvh_build_params p;
    int start = accel_build_begin(out, &p, params, prim_count);
    if (start <= 0)
        return start;
    /* The refs in a mapping for the caller's collapse when asked for and
     * large (BUILD_SPARE_MIN), else a heap block. */
    struct rt_large_block map = {0};
    void *refs_block = NULL;
    struct build_ref *refs =
        spare ? build_spare_refs((uint64_t)prim_count * sizeof(*refs), &map) : NULL;
    if (!refs)
        refs = rt_alloc_array64(prim_count, sizeof(*refs), &refs_block);
    if (!refs) {
        bvh_release(out);
        return -1;
    }
    struct aabb root_box;
    struct cbounds root_cb;
    setup_refs(refs, src, prim_count, &root_box, &root_cb);
    uint32_t node_count;
    uint32_t max_depth;
    if (binned_build_refs(out->nodes, refs, prim_count, &p, simd, &root_box, &root_cb,
                          &node_count, &max_depth)) {
        rt_free(refs_block);
        rt_free_large(&map);
        bvh_release(out);
        return -1;
    }
    for (uint32_t i = 0; i < prim_count; i++)
        out->prim_index[i] = build_ref_id(&refs[i]);
    rt_free(refs_block);
    if (spare)
        *spare = map; /* nothing reads the refs now */
    accel_build_finish(out, node_count, max_depth);
    return 0;
}

int build_binned_sah_forms(struct bvh *out, const struct aabb *prim_boxes, uint32_t prim_count,
                           const struct bvh_build_params *params, int simd)
{
    const struct build_source src = {prim_boxes, NULL, NULL};
    return build_binned_sah_source(out, &src, prim_count, params, simd, NULL);
}

int accel_build_binned_sah(struct bvh *out, const struct aabb *prim_boxes, uint32_t prim_count,
                           const struct bvh_build_params *params)
{
    return build_binned_sah_forms(out, prim_boxes, prim_count, params, 1);
}
