/* SPDX-License-Identifier: Apache-2.0 */
/*
 * build_toplevel.h - Wald, Benthin and Slusallek's (2003) fast top-level construction over
 * instance boxes (sec. 4.5), as an alternative to the binned SAH builder
 * for the top level.
 */
#ifndef RT_ACCEL_BUILD_TOPLEVEL_H
#define RT_ACCEL_BUILD_TOPLEVEL_H

#include <stdint.h>

#include "accel/bvh_build.h"

/*
 * Builds a BVH over instance boxes with the split rule of Wald, Benthin and Slusallek (2003) sec.
 * 4.5: axes in order of the cell's extent; among the box borders on that
 * axis, the one nearest the cell centre on the side holding more boxes
 * (so the plane lies between the cell centre and the object median).
 * Wald, Benthin and Slusallek (2003) builds a BSP; in a BVH each box goes to the side holding its
 * centroid and a child's cell is its side of the plane.  A cell with no
 * border that separates its boxes becomes a leaf, as in the paper; the
 * depth guard of the other builders (object-median splits near
 * BVH_MAX_DEPTH) keeps the tree traversable for any input.
 *
 * Same contract as accel_build (bvh_layout.h), params ignored.  Returns 0, or -1
 * with *out zeroed on allocation failure.
 */
int accel_build_toplevel_cellsplit(struct bvh *out, const struct aabb *boxes, uint32_t count);

#endif
