/* SPDX-License-Identifier: Apache-2.0 */
/*
 * bvh_build.h - the builders' interface: parameters, accel_build and the
 * two SAH builders, the SAH cost, leaf-order triangle gathering.
 *
 * A BVH (trace/bvh_layout.h) is built over an array of primitive boxes
 * (triangles for objects, instance boxes for the top level): the builders
 * never see triangles, RT_ enums or the context, so each is testable alone.
 */
#ifndef RT_ACCEL_BVH_BUILD_H
#define RT_ACCEL_BVH_BUILD_H

#include <stddef.h>
#include <stdint.h>

#include "base/aabb.h"
#include "trace/bvh_layout.h"

/* Bins of the binned SAH build.  Wald, Ize and Parker (2008) sec. 4 and table 1: 16 bins
 * are within a few percent of the sweep build, 4 already usable. */
#define BVH_DEFAULT_BINS 16
#define BVH_MAX_BINS 256
/* SAH constants (MacDonald and Booth 1990): the cost of one traversal step
 * and of one primitive test, in the same unit.  Ratio 1:1 as in tinybvh's
 * C_TRAV/C_INT defaults; only the ratio matters. */
#define BVH_C_TRAV 1.0f
#define BVH_C_ISECT 1.0f
/* Leaves never hold more primitives than this: larger ones are split at
 * the object median even when the SAH prefers a leaf. */
#define BVH_MAX_LEAF_SIZE 8

enum bvh_builder {
    BVH_BUILDER_BINNED_SAH, /* Wald 2007; Wald, Ize and Parker (2008) sec. 4 */
    BVH_BUILDER_SWEEP_SAH   /* full sweep over sorted centroids: the quality reference */
};

struct bvh_build_params {
    enum bvh_builder builder;
    int bins;          /* binned builder only: 2..BVH_MAX_BINS */
    int max_leaf_size; /* 1..BVH_MAX_LEAF_SIZE */
    float c_trav;
    float c_isect;
    /* Looser leaf criterion for per-frame rebuilds (Wald, Benthin and Slusallek (2003) sec. 4.3):
     * a node at depth d with at most min(max_leaf_size, floor(g^d))
     * primitives becomes a leaf without any split being evaluated, g =
     * leaf_growth.  1 (the default) switches it off; values below 1 or
     * not finite are treated as 1.  Read by the median builder and the
     * parallel build's median subtrees (build_median.h, which names the
     * recommended value, BVH_LEAF_GROWTH_REBUILD).  TODO(issue "dynamic
     * scenes"): the binned and sweep builders do not read it yet. */
    float leaf_growth;
    /* Not read by the builders: whoever finishes a build (scene/accel.c)
     * also collapses it into the wide traversal layout (collapse4.c):
     * 8-wide when this is 8, 4-wide for any other non-zero value (the
     * default is 1), none for 0.  The context sets it to its kernels'
     * wide_width: 0 when they walk only the binary tree (isa=scalar), so
     * no time or memory goes to a layout nothing reads, 8 for AVX2. */
    int wide_layout;
    /* Not read by the builders either: the collapse that makes the wide
     * layout, an enum bvh_collapse (trace/bvh4_layout.h): 0 the greedy
     * one (the default), 1 the optimal one.  An object's quality builds
     * take the object's RT_ACCELERATION_HINT (scene/update.c). */
    int collapse;
    /* Not read by the builders: a rebuild that replaces a structure of as
     * many triangles (scene_accel_rebuild) writes the new leaf-ordered
     * triangles into the replaced structure's array when that array is
     * at least this many bytes, the default BVH_REBUILD_REUSE_MIN_BYTES;
     * 0 always (the tests). */
    uint64_t rebuild_reuse_min_bytes;
};

/* glibc's largest mmap threshold on 64-bit targets (DEFAULT_MMAP_THRESHOLD_MAX,
 * 32 MiB): an array at least this large is a fresh mapping every time it
 * is allocated, whose pages the kernel zeroes at their first write (on
 * this project's virtual machine 0.09-1.1 ms of system time per MB,
 * performance-log b11).  Smaller arrays usually come back warm from the
 * heap, and there reusing the replaced array saves no page while reading
 * the mesh twice (the collapse and the gather, in prim_index order) costs
 * the cache misses of a second pass: the exploding torus (250,000
 * triangles, 9 MB) rebuilt every frame took 4-8 % more CPU with the reuse
 * (performance-log, round 39 b12). */
#define BVH_REBUILD_REUSE_MIN_BYTES ((uint64_t)32 << 20)

/* Fills *params with the defaults above (binned SAH, 16 bins). */
void bvh_build_params_default(struct bvh_build_params *params);

/*
 * Builds a BVH over prim_count boxes.  prim_boxes must be finite and
 * non-empty (min <= max); degenerate (flat or point) boxes are fine, as
 * are any number of identical boxes: when the centroids cannot be
 * separated the builder splits at the object median, so depth stays
 * bounded by BVH_MAX_DEPTH.  Boxes that break the contract (NaN, inf)
 * give a valid tree (each primitive in exactly one leaf, depth bounded)
 * with meaningless bounds, never a crash.
 *
 * params NULL means the defaults; fields out of range are brought into
 * range (accel_build_params_normalize in build_internal.h: bins and
 * max_leaf_size clamped, a bad cost or builder replaced by its default).
 * *out is output only: whatever it held is overwritten, not released.
 * Leaves hold 1..max_leaf_size primitives.  With prim_count == 0 the
 * result is the empty BVH above and 0 is returned.
 *
 * On success returns 0 and *out owns freshly allocated arrays (release
 * with bvh_release).  On allocation failure (or prim_count > 2^31, whose
 * 2n - 1 nodes would not fit the 32-bit indices) returns -1 and *out is
 * left zeroed.  Deterministic: the same input gives the same tree, on any
 * machine (the SIMD and plain C paths compute the same floats).
 * Thread-safe for distinct outputs.
 *
 * accel_build dispatches on params->builder; the two builders can also
 * be called directly (they ignore params->builder).  The binned builder
 * uses fewer bins than params->bins for small nodes (at most 4 + n/2) and
 * an exact sweep for nodes of at most 8 primitives, see
 * build_binned_sah.c.
 */
int accel_build(struct bvh *out, const struct aabb *prim_boxes, uint32_t prim_count,
                const struct bvh_build_params *params);
/*
 * accel_build on the boxes of triangles 0..prim_count-1 (vertex indices
 * indices[3j..3j+2] into positions, not checked), the boxes
 * accel_triangle_boxes_pool would return, and the same tree bit for bit;
 * the binned builder computes each box as it sets up its ref, without a
 * box array (the sweep builder takes one).  With spare non-NULL it is
 * zeroed, and a large binned build (build_internal.h, BUILD_SPARE_MIN)
 * hands its refs' mapping over in it for the caller's collapse
 * (accel_collapse_wide_reuse), as accel_build_parallel_triangles does;
 * the caller frees it with rt_free_large when the collapse did not take
 * it (also after a failure of the collapse).  On failure *spare stays
 * zeroed.
 */
struct rt_large_block;
int accel_build_triangles(struct bvh *out, const float *positions, const uint32_t *indices,
                          uint32_t prim_count, const struct bvh_build_params *params,
                          struct rt_large_block *spare);
int accel_build_binned_sah(struct bvh *out, const struct aabb *prim_boxes,
                           uint32_t prim_count, const struct bvh_build_params *params);
int accel_build_sweep_sah(struct bvh *out, const struct aabb *prim_boxes,
                          uint32_t prim_count, const struct bvh_build_params *params);

/* Frees the arrays of *bvh and zeroes it; safe on a zeroed bvh. */
void bvh_release(struct bvh *bvh);

/*
 * SAH cost of a finished tree (MacDonald and Booth 1990): the sum over
 * inner nodes of A(n)/A(root) * c_trav plus the sum over leaves of
 * A(n)/A(root) * count * c_isect, A = surface area.  0 for an empty tree,
 * and 0 when the root's area is 0 (every primitive on one line).
 * Computed in double.  Used to compare builders: cost / cost(sweep) is
 * the quality ratio.
 */
double accel_sah_cost(const struct bvh *bvh, float c_trav, float c_isect);

/*
 * Copies triangle vertices into leaf order for traversal: returns an
 * array of 9 * bvh->prim_count floats, slot i holding v0, v1, v2 of
 * triangle prim_index[i], where triangle j has vertex indices
 * indices[3j..3j+2] into positions (xyz per vertex).  The indices are
 * not checked: the caller validates them.  For an empty BVH the result
 * is a valid pointer to no data.  NULL on allocation failure.  Caller
 * frees with rt_free.
 */
float *accel_gather_triangles(const struct bvh *bvh, const float *positions,
                              const uint32_t *indices);

/* accel_gather_triangles with the slots shared between the threads of
 * pool (base/pool.h; NULL or a one-thread pool: the calling thread
 * alone); the same floats on any pool.  Uses the pool for the duration
 * of the call. */
struct rt_pool;
/* The gather's copy of one triangle: the three vertices
 * indices[3 * prim ..] of positions (xyz each), float for float into
 * dst[0 .. 9).  The collapse from the mesh (collapse_mesh.h) reads its
 * packets' triangles through it too, so both give the same floats. */
static inline void accel_gather_triangle(float *dst, const float *positions,
                                         const uint32_t *indices, uint32_t prim)
{
    const uint32_t *vi = &indices[3 * (size_t)prim];
    for (int corner = 0; corner < 3; corner++) {
        const float *src = &positions[3 * (size_t)vi[corner]];
        dst[3 * corner + 0] = src[0];
        dst[3 * corner + 1] = src[1];
        dst[3 * corner + 2] = src[2];
    }
}
float *accel_gather_triangles_pool(const struct bvh *bvh, const float *positions,
                                   const uint32_t *indices, struct rt_pool *pool);
/* accel_gather_triangles_pool into tri, an array of at least
 * 9 * bvh->prim_count floats the caller owns (a replaced structure's
 * copy, whose pages are in memory already): every float of the first
 * 9 * prim_count written, so the same floats as a fresh array.  Cannot
 * fail. */
void accel_gather_triangles_into(const struct bvh *bvh, const float *positions,
                                 const uint32_t *indices, struct rt_pool *pool, float *tri);

/* The bounds of triangles 0..count-1 (vertex indices indices[3j..3j+2]
 * into positions, xyz per vertex; not checked), each grown from an empty
 * box by its three vertices in order, with the triangles shared between
 * the threads of pool (NULL or a one-thread pool: the calling thread
 * alone; the same bits on any pool).  Returns an array of count boxes
 * (a valid pointer for count 0), NULL on allocation failure; the caller
 * frees it with rt_free. */
struct aabb *accel_triangle_boxes_pool(const float *positions, const uint32_t *indices,
                                       uint32_t count, struct rt_pool *pool);

#endif
