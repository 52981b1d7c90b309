/* SPDX-License-Identifier: Apache-2.0 */
/*
 * build_median.h - the cheap builders for per-frame rebuilds: the spatial-
 * median ("BIH-style") builder of Wald, Ize and Parker (2008) table 1 and the looser leaf
 * criterion of Wald, Benthin and Slusallek (2003) sec. 4.3, plus the pieces of them that the
 * two-stage parallel builder (build_parallel.c) builds its subtrees with.
 *
 * Same conventions as the other builders (bvh_layout.h, build_internal.h): a node
 * owns a contiguous range of a reference array that is partitioned in
 * place, children are allocated as an adjacent pair after their parent
 * (depth-first numbering, left subtree first, so every child index is
 * greater than its parent's), and a "centroid" is box.min + box.max.
 */
#ifndef RT_ACCEL_BUILD_MEDIAN_H
#define RT_ACCEL_BUILD_MEDIAN_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "accel/bvh_build.h"

/*
 * The leaf-growth factor we recommend for rebuild-every-frame objects
 * (bvh_build_params.leaf_growth; Wald, Benthin and Slusallek (2003) sec. 4.3: "we currently
 * increase the tolerance threshold by a constant factor for each level of
 * subdivision", no value given).  With 1.1 the tolerance reaches 2 at
 * depth 8, 4 at depth 15 and the cap of 8 at depth 22: objects of a few
 * thousand triangles keep SAH-sized leaves, large ones stop two or three
 * levels early.  Measured on 1M triangles (a sphere mesh and a random
 * soup), median builder: build time -20% / -27% for SAH cost +8% / +21%;
 * 1.15 saves only 6 more points of build time (-26% / -32%) for +18% /
 * +43%, 1.08 gives -15% / -22% for +3% / +9%.  A rebuilt object is
 * traced by one frame's rays only, so a build-dominated frame gains from
 * the knee of that curve, 1.1.
 */
#define BVH_LEAF_GROWTH_REBUILD 1.1f

/*
 * Spatial-median build: each node is split at the middle of its centroid
 * bounds on their longest axis (Wachter and Keller 2006, "Instant ray
 * tracing: the bounding interval hierarchy", as Wald, Ize and Parker (2008) table 1's "BIH"
 * row), at the object median when that leaves a side empty or the depth
 * guard (build_internal.h) requires it.  A node of at most max_leaf_size
 * primitives becomes a leaf when the SAH (MacDonald and Booth 1990) does
 * not favour the split, or at once when params->leaf_growth allows it
 * (bvh_layout.h).  params->bins and params->builder are ignored.
 *
 * Same contract as accel_build (bvh_layout.h): NULL params means the defaults,
 * out-of-range fields are normalized; 0 primitives give the empty BVH;
 * depth <= BVH_MAX_DEPTH for any input, any number of identical boxes
 * included; every primitive in exactly one leaf; deterministic.  Returns
 * 0, or -1 with *out zeroed on allocation failure.  Thread-safe for
 * distinct outputs.  The fastest builder, and the lowest quality.
 */
int accel_build_median(struct bvh *out, const struct aabb *prim_boxes, uint32_t prim_count,
                       const struct bvh_build_params *params);

/*
 * The looser leaf criterion (Wald, Benthin and Slusallek (2003) sec. 4.3) as a table: tol[d] =
 * min(max_leaf_size, floor(g^d)) for d = 0..BVH_MAX_DEPTH, g =
 * params->leaf_growth, computed by repeated float multiplication so that
 * every machine gets the same table (powf's last bit is not portable).
 * params must be normalized; tol[d] >= 1 always, and all 1 when g is 1.
 */
void build_leaf_tolerance(const struct bvh_build_params *params,
                          uint32_t tol[BVH_MAX_DEPTH + 1]);

/*
 * A primitive on its way through a builder: its box plus the caller's
 * index, 32 bytes, loaded as two vec4 (vec4.h).  lo[3] holds the index's
 * bits (build_ref_id; masked off before any arithmetic), hi[3] is 0.
 * Shared by build_median.c and build_parallel.c.
 */
struct build_ref {
    float lo[4];
    float hi[4];
};
typedef char build_ref_is_32_bytes[sizeof(struct build_ref) == 32 ? 1 : -1];

/* Fills *ref from box and index id. */
static inline void build_ref_set(struct build_ref *ref, const struct aabb *box, uint32_t id)
{
    for (int k = 0; k < 3; k++) {
        ref->lo[k] = box->min[k];
        ref->hi[k] = box->max[k];
    }
    memcpy(&ref->lo[3], &id, sizeof(id));
    ref->hi[3] = 0.0f;
}

static inline uint32_t build_ref_id(const struct build_ref *ref)
{
    uint32_t id;
    memcpy(&id, &ref->lo[3], sizeof(id));
    return id;
}

static inline void build_ref_set_id(struct build_ref *ref, uint32_t id)
{
    memcpy(&ref->lo[3], &id, sizeof(id));
}

/*
 * The median builder's core, for build_parallel.c's subtrees: builds a
 * tree over refs[0, n) (n >= 1, reordered in place) into nodes[0, 2n - 1)
 * with the root at nodes[0], child indices relative to `nodes` and leaf
 * slots relative to `refs`.  depth0 is the depth of the root in the whole
 * tree: the depth guard and the leaf tolerance count from it, and the
 * caller must guarantee depth0 + ceil_log2(n) <= BVH_MAX_DEPTH
 * (build_internal.h's invariant); then every node's depth is at most
 * BVH_MAX_DEPTH.  params must be normalized.  Sets *node_count and
 * *max_depth (absolute, i.e. counted from depth0).  Never fails, no
 * allocation; thread-safe for distinct node and ref arrays.
 */
void build_median_refs(struct bvh_node *nodes, struct build_ref *refs, uint32_t n,
                       uint32_t depth0, const struct bvh_build_params *params,
                       uint32_t *node_count, uint32_t *max_depth);

/*
 * Reorders refs[0, n) so that refs[nth] is the element a full sort by
 * centroid on `axis` (ties by index) would put there, with none greater
 * before it and none smaller after it: the object median when nth = n/2.
 * Introselect, O(n) expected and O(n log n) worst case; total and
 * deterministic for any input, NaN included.
 */
void build_select_nth(struct build_ref *refs, size_t n, size_t nth, int axis);

#endif
