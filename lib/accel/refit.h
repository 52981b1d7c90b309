/* SPDX-License-Identifier: Apache-2.0 */
/*
 * refit.h - refitting a BVH to moved primitives without changing its
 * topology (Wald, Ize and Parker (2008) sec. 6, "Parallel BVH Refit"), and updating the
 * leaf-ordered triangle copy that traversal reads (accel_gather_triangles
 * in accel/bvh_build.h).
 *
 * Who calls what: the runtime refits objects through accel_refit_mesh
 * alone (scene/accel.c).  accel_refit and accel_refit_parallel refit from
 * per-primitive boxes, the general form (any primitive, e.g. instance
 * boxes) against which internal/refit and internal/parallel_build_threads
 * check accel_refit_mesh bit for bit; accel_refit_triangles(_parallel)
 * are accel_refit_mesh's first step, exposed so the tests can check that
 * step alone.  They stay as the reference the production path is held to.
 *
 * A refit recomputes every node box bottom-up: a leaf's box is the union
 * of its primitives' boxes, an inner node's the union of its two
 * children's.  Unions are taken with min/max as build_internal.h's
 * build_min/build_max (minps/maxps semantics), each node from its
 * children in a fixed order (left then right, leaf slots in slot order),
 * so a node's box is a function of its subtree alone: the serial and the
 * parallel refit give the same boxes bit for bit, for any thread count,
 * and for finite input they are the exact unions.
 *
 * Order: every builder numbers nodes depth-first and allocates children
 * after their parent, so a reverse sweep over the node array sees
 * children first; the serial refit uses that sweep, checks the property
 * on the way (one comparison per inner node), and falls back to a
 * post-order walk from the root for a tree that breaks it (one
 * restructured in place, say).  Either way the result is the same.
 *
 * Contracts shared by all functions: bvh is a valid tree (child and slot
 * indices in range, depth <= BVH_MAX_DEPTH), as every builder makes it;
 * an empty BVH is left alone.  Nothing here allocates or fails.  The
 * caller must not trace the BVH (or read tri) during a refit.
 * Thread-safe for distinct BVHs.  pool NULL (or a pool of 1 thread)
 * means the calling thread does everything; the pool must not be running
 * another task (rt_pool_run is not reentrant).
 */
#ifndef RT_ACCEL_REFIT_H
#define RT_ACCEL_REFIT_H

#include <stdint.h>

#include "accel/bvh_build.h"
#include "base/pool.h"

/*
 * Recomputes every node box of bvh from prim_boxes (indexed by the
 * caller's primitive index, i.e. by prim_index's values, as for
 * accel_build).  Boxes may be anything, even non-finite: the result is
 * then meaningless but the same as the parallel refit's.
 */
void accel_refit(struct bvh *bvh, const struct aabb *prim_boxes);

/*
 * The same result as accel_refit, on the threads of pool: one thread
 * seeds (walks the top levels and records the subtree roots below them,
 * and the leaves above), every thread takes subtrees from an atomic
 * counter and refits them, and the thread that finishes the last subtree
 * refits the top levels (Wald, Ize and Parker (2008) sec. 6).
 */
void accel_refit_parallel(struct bvh *bvh, const struct aabb *prim_boxes, struct rt_pool *pool);

/*
 * Rewrites tri, the 9 * prim_count floats made by accel_gather_triangles
 * for this bvh, from new vertex positions (same indices, unchecked: the
 * caller validated them when it gathered).  The result equals a fresh
 * accel_gather_triangles.  The parallel version hands out slot chunks
 * through an atomic counter.
 */
void accel_refit_triangles(const struct bvh *bvh, float *tri, const float *positions,
                           const uint32_t *indices);
void accel_refit_triangles_parallel(const struct bvh *bvh, float *tri, const float *positions,
                                    const uint32_t *indices, struct rt_pool *pool);

/*
 * Both, without a per-triangle box array: rewrites tri from the mesh
 * (as accel_refit_triangles_parallel), then refits the boxes from tri,
 * each leaf's box over its triangles' vertices.  The boxes equal
 * accel_refit's with per-triangle boxes over the three vertices (for
 * finite positions); tri equals accel_refit_triangles'.  The cheapest
 * refit when the caller has no triangle boxes at hand: one random pass
 * over the vertices, one sequential pass over tri.  pool may be NULL.
 */
void accel_refit_mesh(struct bvh *bvh, float *tri, const float *positions,
                      const uint32_t *indices, struct rt_pool *pool);

#endif
