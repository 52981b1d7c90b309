/* SPDX-License-Identifier: Apache-2.0 */
/*
 * build_parallel.h - the two-stage parallel BVH build of Wald, Ize and Parker (2008) sec. 5.
 *
 * Stage 1 partitions the primitives coarsely with all threads together,
 * either by parallel binning (every split of the top levels is a binned
 * SAH split, its histogram filled by all threads) or by a uniform grid
 * over the centroids with BIH-like nodes over the grid cells.  Stage 2
 * builds the resulting subtrees, largest first, one per thread at a time,
 * with a serial builder: the binned (or sweep) SAH builder of bvh_layout.h or
 * the median builder of build_median.h.  The combinations are the paper's
 * "SAH+SAH" (binning, SAH), "grid+SAH" and "grid+BIH" (grid, median).
 *
 * Also declares the median builder (build_median.h), the serial rebuild
 * this file's grid+BIH parallelises.
 */
#ifndef RT_ACCEL_BUILD_PARALLEL_H
#define RT_ACCEL_BUILD_PARALLEL_H

#include <stdint.h>

#include "accel/build_median.h"
#include "accel/bvh_build.h"
#include "base/alloc.h"
#include "base/pool.h"

/* Stage 1 (Wald, Ize and Parker (2008) sec. 5, "Coarse Scene Partitioning"). */
enum bvh_partition {
    BVH_PARTITION_BINNING, /* parallel binning: SAH splits at the top */
    BVH_PARTITION_GRID     /* per-thread grids, spatial median at the top */
};

/* Stage 2 (Wald, Ize and Parker (2008) sec. 5, "Parallel subtree building"). */
enum bvh_subtree_builder {
    BVH_SUBTREE_SAH,   /* accel_build with the build params (binned or sweep) */
    BVH_SUBTREE_MEDIAN /* the median builder, build_median.h */
};

struct bvh_parallel_params {
    enum bvh_partition partition;
    enum bvh_subtree_builder subtree;
};

/* Fills *params with SAH+SAH (binning, SAH), the best quality. */
void bvh_parallel_params_default(struct bvh_parallel_params *params);

/*
 * Builds a BVH over prim_count boxes on the threads of pool, with the
 * combination `parallel` selects (NULL: the default, SAH+SAH).  params as
 * for accel_build (NULL: defaults; normalized); with BVH_SUBTREE_SAH,
 * params->builder picks the subtree builder, so the sweep builder can be
 * parallelised too.  params->leaf_growth is honoured by median subtrees
 * only (the SAH builders of bvh_layout.h do not read it).  Unknown enum values
 * in *parallel are taken as the defaults.
 *
 * Output contract as accel_build (bvh_layout.h): every primitive in exactly one
 * leaf, leaves of 1..max_leaf_size, depth <= BVH_MAX_DEPTH for any input,
 * children after their parent, node_count the number of reachable nodes
 * (the subtrees are built into preassigned ranges and then compacted), 0
 * primitives give the empty BVH.  The tree differs from accel_build's at
 * the top, not in what a ray hits.
 *
 * Deterministic, and independent of the number of threads: the coarse
 * partition is a stable partition whose result does not depend on how
 * the work was shared out, and every subtree is built by a deterministic
 * serial builder, so 1, 2 or 16 threads give the same tree bit for bit
 * (for finite boxes: boxes with NaN give a valid tree that may depend on
 * the thread count).
 * pool NULL runs everything on the calling thread; the pool must not be
 * running another task.  Returns 0, or -1 with *out zeroed on allocation
 * failure (or prim_count > 2^31).  Thread-safe for distinct outputs and
 * pools.
 */
int accel_build_parallel_ex(struct bvh *out, const struct aabb *prim_boxes, uint32_t prim_count,
                            const struct bvh_build_params *params,
                            const struct bvh_parallel_params *parallel, struct rt_pool *pool);

/* accel_build_parallel_ex with the default combination, SAH+SAH, on the
 * boxes of triangles 0..prim_count-1 (vertex indices indices[3j..3j+2]
 * into positions, xyz per vertex; not checked), which the set-up computes
 * as it writes its refs: the tree of accel_build_parallel on
 * accel_triangle_boxes_pool's boxes, bit for bit, without the box array
 * (a million triangles: 24 MB less written, read and, in a fresh block,
 * zeroed by the kernel a build).  Same contract and return values.
 * spare (may be NULL) receives, on success, the mapping in which a large
 * build (build_parallel.c, refs[1]'s spare) kept its scratch, pages
 * already in memory, for accel_collapse_wide_reuse to write the wide
 * layout into; the caller frees it with rt_free_large whether taken or
 * not (a zeroed handle otherwise, and on failure). */
int accel_build_parallel_triangles(struct bvh *out, const float *positions,
                                   const uint32_t *indices, uint32_t prim_count,
                                   const struct bvh_build_params *params, struct rt_pool *pool,
                                   struct rt_large_block *spare);

/* accel_build_parallel_ex with the default combination, SAH+SAH. */
int accel_build_parallel(struct bvh *out, const struct aabb *prim_boxes, uint32_t prim_count,
                         const struct bvh_build_params *params, struct rt_pool *pool);

#endif
