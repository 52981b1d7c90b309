/* SPDX-License-Identifier: Apache-2.0 */
/*
 * build_internal.h - pieces shared by the top-down BVH builders
 * (build_binned_sah.c, build_sweep_sah.c); not part of the accel interface.
 *
 * Both builders work the same way: a node owns a contiguous range
 * [begin, end) of a primitive array that is partitioned in place; a split
 * allocates the two children as an adjacent pair (left = first, right =
 * first + 1, bvh_layout.h's layout); a leaf records its range.  Nodes are numbered
 * in depth-first order, left subtree first.
 *
 * SAH comparisons are made on "costs times the node's area": with A the
 * node's half area and S = sum over children of A(child) * N(child),
 *     leaf  cost * A = c_isect * N * A
 *     split cost * A = c_trav * A + c_isect * S
 * (MacDonald and Booth 1990), so a node of zero area (all primitives on a
 * line or at a point) needs no division and simply prefers a leaf.
 */
#ifndef RT_ACCEL_BUILD_INTERNAL_H
#define RT_ACCEL_BUILD_INTERNAL_H

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "accel/vec4.h"
#include "accel/build_median.h" /* struct build_ref */
#include "accel/bvh_build.h"

/* Half the surface area of a node's box (the SAH's A). */
static inline float build_node_half_area(const struct bvh_node *node)
{
    struct aabb box;
    for (int k = 0; k < 3; k++) {
        box.min[k] = node->aabb_min[k];
        box.max[k] = node->aabb_max[k];
    }
    return aabb_half_area(&box);
}

/* A node's share of a top-down build: the references [begin, end), the
 * node they become, its depth.  The first member of every builder's
 * task. */
struct build_range {
    uint32_t begin;
    uint32_t end;
    uint32_t node;
    uint32_t depth;
};

/* Writes the xyz lanes of lo and hi (box bounds kept in SIMD registers
 * by the binned, median and parallel builders) into *box. */
static inline void build_store_box(struct aabb *box, vec4 lo, vec4 hi)
{
    float l[4];
    float h[4];
    vec4_store(l, lo);
    vec4_store(h, hi);
    for (int k = 0; k < 3; k++) {
        box->min[k] = l[k];
        box->max[k] = h[k];
    }
}

/* A node's mapping from doubled centroids to bins on the three axes
 * (Wald 2007: bin = k1 (c - min)), shared by the serial and parallel
 * binned builders so that their histograms and partitions classify alike:
 * origin and scale per axis (scale 0 on an axis that is not binned maps
 * every centroid to bin 0), last = bins - 1 in every lane. */
struct build_bin_map {
    vec4 origin;
    vec4 scale;
    vec4 last;
};

/* The doubled centroid of a ref, lane 3 zero. */
static inline vec4 build_ref_centroid(const struct build_ref *r)
{
    return vec4_add(vec4_xyz0(vec4_load(r->lo)), vec4_load(r->hi));
}

/* Bins of a doubled centroid on the three axes: per lane
 * clamp((c - origin) * scale, 0, last), one rounding per operation, then
 * truncated.  Clamped in float before the conversion, so that no input
 * (not even a NaN from a non-finite box) can index outside the bins:
 * max(NaN, 0) is 0. */
static inline void build_bins_of(const struct build_bin_map *m, vec4 centroid, int32_t bin[4])
{
    vec4 f = vec4_mul(vec4_sub(centroid, m->origin), m->scale);
    f = vec4_min(vec4_max(f, vec4_splat(0.0f)), m->last);
    vec4_trunc(bin, f);
}

/* The histograms' form of build_bins_of: the same bins, as byte offsets
 * of 32-byte bin records, axis k's bins starting at byte axis_base[k].
 * One shift and one add for the three axes together instead of an index
 * extension, shift and add per axis in the histogram loops, and the
 * offset addresses a bin's box and, in a parallel array of 32-byte
 * stride, its count. */
static inline void build_bin_offsets(const struct build_bin_map *m, vec4 centroid,
                                     const uint32_t axis_base[4], uint32_t off[4])
{
    vec4 f = vec4_mul(vec4_sub(centroid, m->origin), m->scale);
    f = vec4_min(vec4_max(f, vec4_splat(0.0f)), m->last);
    vec4_trunc_offset32(off, f, axis_base);
}

/*
 * The histogram of one node's refs[begin, end) on the three axes (Wald
 * 2007; Wald, Ize and Parker (2008) sec. 4), shared by the serial and the
 * parallel binned builder: the bin_count bins of axis k are 32-byte
 * records at box_base + axis_base[k] + 32 b (box: min xyz -, max xyz -)
 * and, at the same offset from count_base, a record whose first word is
 * the bin's count.  Clears those bins first, then per ref grows the box
 * of its bin on each axis (build_bin_offsets) and counts it.  Every form
 * gives the same bytes: per bin the min and max in ref order, each as
 * minps(bin, ref) and maxps(bin, ref) would give it (NaN and equal zeros
 * included).  build_bins.c has the portable form, build_binned_avx2.c an
 * AVX2 one; build_fill_bins_best picks.
 */
typedef void (*build_fill_bins_fn)(char *box_base, char *count_base, const uint32_t axis_base[4],
                                   int bin_count, const struct build_bin_map *map,
                                   const struct build_ref *refs, uint32_t begin, uint32_t end);
void build_fill_bins(char *box_base, char *count_base, const uint32_t axis_base[4],
                     int bin_count, const struct build_bin_map *map,
                     const struct build_ref *refs, uint32_t begin, uint32_t end);
/* The AVX2 form, or NULL where that unit is absent (no AVX2 compiler
 * target, RT_NO_SIMD) or the CPU does not run AVX2. */
build_fill_bins_fn build_fill_bins_avx2_unit(void);
/* The AVX2 form where it runs, else build_fill_bins. */
build_fill_bins_fn build_fill_bins_best(void);
/* The same bytes, faster for large nodes whose refs are in the input's
 * order (a build's top nodes; the parallel builder's stable partitions
 * keep that order further down): an AVX2 form that fills a node of at
 * least 16,384 refs in four streams (build_binned_avx2.c says why and
 * proves the bytes equal), or NULL as build_fill_bins_avx2_unit;
 * build_fill_bins_ordered_best picks.  The binned builders use it. */
build_fill_bins_fn build_fill_bins_ordered_avx2_unit(void);
build_fill_bins_fn build_fill_bins_ordered_best(void);
/* The ordered form for refs whose boxes the caller has seen free of NaN
 * (all six floats of every ref): the four streams without their NaN
 * checks (build_binned_avx2.c), or NULL as build_fill_bins_avx2_unit.
 * build_fill_bins_ordered_finite_best(finite) picks it when finite is
 * nonzero and it runs, else build_fill_bins_ordered_best's form. */
build_fill_bins_fn build_fill_bins_ordered_finite_avx2_unit(void);
build_fill_bins_fn build_fill_bins_ordered_finite_best(int finite);

/*
 * The AVX2 form of the binned builders' partition of refs by a split's
 * threshold (build_split_threshold: a ref goes left when !(c[axis] >=
 * threshold), c its doubled centroid), or NULL where that unit is absent
 * or the CPU does not run AVX2.  With dst NULL it partitions
 * src[begin, end) in place exactly as build_binned_sah.c's Lomuto loop
 * (the same permutation) and returns the first right slot; otherwise it
 * copies the left refs, in order, to dst from left_dst and the right ones
 * from right_dst, as build_parallel.c's partition_task, and returns the
 * next left slot.  bounds gets the sides' centroid bounds (left lo, left
 * hi, right lo, right hi; lane 3 as in the portable loops), bit for bit
 * those of the portable loops (build_side_grow).
 */
typedef uint32_t (*build_partition_fn)(const struct build_ref *src, struct build_ref *dst,
                                       uint32_t begin, uint32_t end, uint32_t left_dst,
                                       uint32_t right_dst, int axis, float threshold,
                                       float bounds[4][4]);
build_partition_fn build_partition_avx2_unit(void);

/* 1 when the CPU and the operating system run AVX2 (the compiler's cpuid
 * wrapper, as trace/kernels.c), else 0; always 0 where the AVX2 unit is
 * absent. */
int build_cpu_runs_avx2(void);

/* What the binned builder's set-up reads: the caller's boxes, or (boxes
 * NULL) the triangles of positions and indices, whose boxes it computes
 * itself (triangle_box.h; accel_build_triangles). */
struct build_source {
    const struct aabb *boxes;
    const float *positions;
    const uint32_t *indices;
};

/*
 * Bytes of build refs from which a builder asked for a spare
 * (accel_build_triangles, accel_build_parallel_triangles) keeps a ref
 * buffer in a mapping of BUILD_SPARE_FACTOR times its size
 * (rt_malloc_large: 2 MB aligned, advised for huge pages) that the
 * caller's collapse then takes over for the wide layout
 * (rt_malloc_large_reuse), so that the layout's first pages are pages
 * the build already touched.  A build that large (a million triangles:
 * 32 MB of refs) finds its refs fresh anyway (a heap block of that size
 * is a mapping of its own, unmapped when freed), and the layout is a
 * fresh mapping every one-shot build.  Three times: an 8-wide layout
 * takes about 70 bytes a triangle against the refs' 32, and
 * rt_malloc_large_reuse takes a spare of up to about twice the layout.
 * Smaller builds (the kitchen, the soup: 3.5 MB of refs) keep a heap
 * block, which comes back warm from the last build.  build_parallel.c
 * (the comment on refs[1]'s spare) has the measurements.
 */
#define BUILD_SPARE_MIN ((uint64_t)16 << 20)
#define BUILD_SPARE_FACTOR 3u

/* A ref buffer of ref_bytes for a build asked for a spare: a mapping of
 * BUILD_SPARE_FACTOR times its size in *map when ref_bytes is at least
 * BUILD_SPARE_MIN, else NULL with *map zeroed (the caller takes a heap
 * block, as it does when the mapping fails).  Both builders' spares
 * (build_binned_sah_source, accel_build_parallel_triangles). */
struct rt_large_block;
void *build_spare_refs(uint64_t ref_bytes, struct rt_large_block *map);

/*
 * The binned SAH build (accel_build_binned_sah) of src's prim_count
 * boxes: the refs' set-up reads the boxes or computes them from the
 * triangles (the same floats either way, so the same tree), and also
 * computes the root's bounds.  With spare non-NULL (zeroed first) and at
 * least BUILD_SPARE_MIN bytes of refs, the refs are a mapping handed to
 * the caller in *spare after the build, for accel_collapse_wide_reuse;
 * the caller frees it with rt_free_large if the collapse does not take
 * it.  simd as build_binned_sah_forms.  params need not be normalized.
 */
struct rt_large_block;
int build_binned_sah_source(struct bvh *out, const struct build_source *src, uint32_t prim_count,
                            const struct bvh_build_params *params, int simd,
                            struct rt_large_block *spare);
/* build_binned_sah_source compiled for AVX2 (build_binned_sah_avx2.c: the
 * same source, the same trees), or NULL where that unit is absent or the
 * CPU does not run AVX2. */
typedef int (*build_binned_fn)(struct bvh *out, const struct build_source *src,
                               uint32_t prim_count, const struct bvh_build_params *params,
                               int simd, struct rt_large_block *spare);
build_binned_fn accel_build_binned_sah_avx2_unit(void);
/* accel_build_binned_sah with its AVX2 forms (the AVX2 copy of the
 * builder, histogram and partition) where simd is non-zero and the CPU
 * runs them, or with the portable ones (SSE2 encoding) where simd is 0:
 * the same tree either way (tested by internal/builders). */
int build_binned_sah_forms(struct bvh *out, const struct aabb *prim_boxes, uint32_t prim_count,
                           const struct bvh_build_params *params, int simd);

/*
 * The binned SAH build of refs[0, prim_count) (prim_count >= 1, refs set
 * by build_ref_set) in place: the refs end in leaf order, the nodes are
 * written from nodes[0] (the root) on, at most 2 prim_count - 1 of them,
 * and *node_count and *depth (counted from the root) are set.  params
 * must be normalized (accel_build_params_normalize).  The tree depends
 * on the refs' boxes and order only, and on their ids only through the
 * order of the ids (the median fallback's ties), so a range of refs with
 * ascending ids builds the tree that the same boxes numbered 0 ..
 * prim_count - 1 do.  This is build_binned_sah_forms after its set-up,
 * and what the parallel builder's SAH subtrees run (build_parallel.c)
 * without a copy of their boxes.  simd as there.  Returns 0, or -1 on
 * allocation failure (the bins), with the nodes and refs' order then
 * undefined.
 */
int build_binned_sah_refs(struct bvh_node *nodes, struct build_ref *refs, uint32_t prim_count,
                          const struct bvh_build_params *params, int simd, uint32_t *node_count,
                          uint32_t *depth);
typedef int (*build_binned_refs_fn)(struct bvh_node *nodes, struct build_ref *refs,
                                    uint32_t prim_count, const struct bvh_build_params *params,
                                    int simd, uint32_t *node_count, uint32_t *depth);
/* build_binned_sah_refs of the AVX2 copy, or NULL (as
 * accel_build_binned_sah_avx2_unit). */
build_binned_refs_fn build_binned_sah_refs_avx2_unit(void);

/* Maps a float to an unsigned integer with the same order (negatives
 * reversed), and every NaN to a fixed place: a total order even for input
 * that breaks the contract, so sorts and selections built on it cannot
 * run out of their range.  -0 sorts just below +0. */
static inline uint32_t build_float_order(float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof(u));
    return u ^ ((u >> 31) ? 0xffffffffu : 0x80000000u);
}

/* The float whose build_float_order key is k (k the key of a non-NaN). */
static inline float build_float_of_order(uint32_t k)
{
    uint32_t u = (k & 0x80000000u) ? k ^ 0x80000000u : ~k;
    float f;
    memcpy(&f, &u, sizeof(f));
    return f;
}

/* build_bins_of's bin on `axis` of a centroid whose coordinate on that
 * axis is x. */
static inline int32_t build_bin_at(const struct build_bin_map *m, int axis, float x)
{
    int32_t bin[4];
    build_bins_of(m, vec4_splat(x), bin);
    return bin[axis];
}

/*
 * The partitions' side test as one comparison: for a split at `plane`
 * (1 <= plane <= bins - 1) on a binned axis (origin finite, scale finite
 * and positive), the least non-NaN float t with build_bin_at(t) >= plane,
 * so that a centroid coordinate c lies in a bin below the plane exactly
 * when !(c >= t).  That holds because the bin is a non-decreasing function
 * of c (a subtraction, a multiplication by a positive scale, a clamp and
 * a truncation, each monotone under IEEE rounding; -0 and +0 give the
 * same bin), -inf is in bin 0 and +inf in the last; a NaN is in bin 0 and
 * fails c >= t, so it stays left too.  Found by searching the float order
 * (build_float_order) with the very bin computation: from the estimate
 * origin + plane / scale outwards in doubling steps, then by bisection;
 * a few evaluations per node, as the estimate is off by a few ulps.
 */
static inline float build_split_threshold(const struct build_bin_map *m, int axis,
                                          int32_t plane, float origin, float scale)
{
    uint32_t lo = build_float_order(-INFINITY); /* bin below the plane */
    uint32_t hi = build_float_order(INFINITY);  /* bin at or above it */
    float guess = origin + (float)plane / scale;
    if (guess == guess) {
        uint32_t k = build_float_order(guess);
        k = k <= lo ? lo + 1 : k > hi ? hi : k;
        if (build_bin_at(m, axis, build_float_of_order(k)) >= plane) {
            hi = k;
            for (uint64_t step = 1; hi - lo > 1; step *= 2) {
                uint32_t p = hi - lo > step ? hi - (uint32_t)step : lo + 1;
                if (build_bin_at(m, axis, build_float_of_order(p)) < plane) {
                    lo = p;
                    break;
                }
                hi = p;
            }
        } else {
            lo = k;
            for (uint64_t step = 1; hi - lo > 1; step *= 2) {
                uint32_t p = hi - lo > step ? lo + (uint32_t)step : hi - 1;
                if (build_bin_at(m, axis, build_float_of_order(p)) >= plane) {
                    hi = p;
                    break;
                }
                lo = p;
            }
        }
    }
    while (hi - lo > 1) {
        uint32_t mid = lo + (hi - lo) / 2;
        if (build_bin_at(m, axis, build_float_of_order(mid)) >= plane)
            hi = mid;
        else
            lo = mid;
    }
    return build_float_of_order(hi);
}

/*
 * The partitions' side bounds without a select: a centroid on side
 * `left` (1 left, 0 right) is added build_side_offset[left][j] before it
 * joins bound j (0 left lo, 1 left hi, 2 right lo, 3 right hi, by min for
 * lo and max for hi).  -0 keeps any finite value bit for bit, +inf and
 * -inf are the identities of min and max, so for finite centroids the
 * bounds are those of selecting the centroid or the identity, in four
 * additions instead of twelve mask operations.
 */
#define BUILD_KEEP -0.0f, -0.0f, -0.0f, -0.0f
#define BUILD_DROP_LO INFINITY, INFINITY, INFINITY, INFINITY
#define BUILD_DROP_HI -INFINITY, -INFINITY, -INFINITY, -INFINITY
static const float build_side_offset[2][4][4] = {
    {{BUILD_DROP_LO}, {BUILD_DROP_HI}, {BUILD_KEEP}, {BUILD_KEEP}},
    {{BUILD_KEEP}, {BUILD_KEEP}, {BUILD_DROP_LO}, {BUILD_DROP_HI}}};
#undef BUILD_KEEP
#undef BUILD_DROP_LO
#undef BUILD_DROP_HI

/* Grows the side bounds of a partition by centroid c on side `left`
 * (build_side_offset's four additions). */
static inline void build_side_grow(vec4 c, uint32_t left, vec4 *llo, vec4 *lhi, vec4 *rlo,
                                   vec4 *rhi)
{
    const float(*off)[4] = build_side_offset[left];
    *llo = vec4_min(*llo, vec4_add(c, vec4_load(off[0])));
    *lhi = vec4_max(*lhi, vec4_add(c, vec4_load(off[1])));
    *rlo = vec4_min(*rlo, vec4_add(c, vec4_load(off[2])));
    *rhi = vec4_max(*rhi, vec4_add(c, vec4_load(off[3])));
}

/* Smallest k with 2^k >= n: the depth an object-median subtree over n
 * primitives needs to reach single-primitive leaves.  0 for n <= 1. */
static inline uint32_t build_ceil_log2(uint32_t n)
{
    /* The bit length of n - 1; a loop over k cost up to 80 instructions
     * a call, twice a node (1 % of a build of 880 triangles). */
#if defined(__GNUC__)
    return n <= 1 ? 0u : 32u - (uint32_t)__builtin_clz(n - 1);
#else
    uint32_t k = 0;
    while (k < 32 && ((uint64_t)1 << k) < n)
        k++;
    return k;
#endif
}

/*
 * Depth guard, the same in every builder.  Invariant: a node at depth d
 * with n primitives has d + ceil_log2(n) <= BVH_MAX_DEPTH (true at the
 * root, since n < 2^32 and BVH_MAX_DEPTH >= 32).  An object-median split
 * keeps it (each half has at most ceil(n/2) primitives, one level deeper).
 * An arbitrary split leaves a child with up to n - 1 primitives, so it is
 * allowed only when d + 1 + ceil_log2(n - 1) <= BVH_MAX_DEPTH; otherwise
 * the builder must split at the object median.  Returns 1 in that case.
 */
static inline int build_must_split_median(uint32_t depth, uint32_t n)
{
    return depth + 1 + build_ceil_log2(n - 1) > BVH_MAX_DEPTH;
}

/* A task on a builder's explicit stack: one node still to be processed.
 * Depth-first processing with both children pushed keeps at most
 * depth + 1 tasks, so BVH_MAX_DEPTH + 2 entries always suffice. */
#define BUILD_STACK_SIZE (BVH_MAX_DEPTH + 2)

/*
 * Copies *params (NULL: the defaults) into *out with every field brought
 * into range: an unknown builder becomes the binned SAH, bins is clamped
 * to [2, BVH_MAX_BINS], max_leaf_size to [1, BVH_MAX_LEAF_SIZE], a
 * non-finite or negative c_trav and a non-finite or non-positive c_isect
 * take their defaults.  Never fails.
 */
void accel_build_params_normalize(struct bvh_build_params *out,
                                  const struct bvh_build_params *params);

/*
 * Allocates out->nodes for the worst case of 2n - 1 nodes and
 * out->prim_index for n slots, n = prim_count >= 1, and zeroes the other
 * fields.  Returns 0, or -1 with *out zeroed when an allocation fails or
 * 2n - 1 does not fit in 32 bits.
 */
int accel_build_alloc(struct bvh *out, uint32_t prim_count);

/*
 * The start every top-down builder shares: normalizes params into *p
 * (accel_build_params_normalize), gives the empty BVH for prim_count == 0
 * (*out is output only: what it held is never freed), and allocates the
 * arrays otherwise.  Returns 1 when there is a tree to build, 0 when the
 * empty BVH is the result, -1 on allocation failure (*out zeroed): the
 * builder returns the value when it is not 1.
 */
int accel_build_begin(struct bvh *out, struct bvh_build_params *p,
                      const struct bvh_build_params *params, uint32_t prim_count);

/* Records node_count and depth and returns the unused tail of the node
 * array to the allocator (keeping the larger block if shrinking fails). */
void accel_build_finish(struct bvh *out, uint32_t node_count, uint32_t depth);

/* Node writers, so that both builders fill the layout the same way. */
static inline void build_set_box(struct bvh_node *node, const struct aabb *box)
{
    for (int k = 0; k < 3; k++) {
        node->aabb_min[k] = box->min[k];
        node->aabb_max[k] = box->max[k];
    }
}

static inline void build_set_leaf(struct bvh_node *node, uint32_t first_slot, uint32_t count)
{
    node->first = first_slot;
    node->count = count;
}

static inline void build_set_inner(struct bvh_node *node, uint32_t left_child)
{
    node->first = left_child;
    node->count = 0;
}

/* min/max written as the comparison the x86 minps/maxps instructions
 * perform (second operand returned when unordered), so that a compiler
 * emits one instruction for each instead of a libm call: fminf's NaN and
 * signed-zero rules are not needed for finite boxes. */
static inline float build_min(float a, float b)
{
    return a < b ? a : b;
}

static inline float build_max(float a, float b)
{
    return a > b ? a : b;
}

/*
 * The step of every top-down builder's task loop once it has chosen to
 * split `range` at mid: the node becomes an inner node over a fresh
 * adjacent pair of children (left = first, right = first + 1) taken from
 * *node_count, with the given boxes, and *left, *right receive the
 * children's ranges.  The caller pushes right before left so the left
 * subtree is numbered (and built) first.
 */
static inline void build_split(struct bvh_node *nodes, const struct build_range *range,
                               uint32_t mid, const struct aabb *left_box,
                               const struct aabb *right_box, uint32_t *node_count,
                               struct build_range *left, struct build_range *right)
{
    uint32_t child = *node_count;
    *node_count += 2;
    build_set_inner(&nodes[range->node], child);
    build_set_box(&nodes[child], left_box);
    build_set_box(&nodes[child + 1], right_box);
    left->begin = range->begin;
    left->end = mid;
    left->node = child;
    left->depth = range->depth + 1;
    right->begin = mid;
    right->end = range->end;
    right->node = child + 1;
    right->depth = range->depth + 1;
}

#endif
