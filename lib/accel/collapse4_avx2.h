/* SPDX-License-Identifier: Apache-2.0 */
/*
 * collapse4_avx2.h - the collapse into the wide layout compiled for AVX2
 * (collapse4_avx2.c), which accel_collapse_wide_reuse calls where the
 * CPU runs it.
 */
#ifndef RT_ACCEL_COLLAPSE4_AVX2_H
#define RT_ACCEL_COLLAPSE4_AVX2_H

#include <stdint.h>

#include "accel/collapse_mesh.h"
#include "trace/bvh_collapse.h"

struct bvh4;
struct bvh;
struct rt_pool;
struct rt_large_block;

typedef int (*collapse_wide_fn)(struct bvh4 *out, const struct bvh *bvh,
                                const struct collapse_triangles *tris, uint32_t width,
                                struct rt_pool *pool, struct rt_large_block *spare,
                                enum bvh_collapse collapse);

/* accel_collapse_wide_source compiled for AVX2 (the same source, the same
 * bytes), or NULL where that unit is absent or the CPU does not run
 * AVX2. */
collapse_wide_fn accel_collapse_wide_avx2_unit(void);

/* accel_collapse_wide_reuse without the AVX2 copy: the portable form (SSE2
 * or plain C), for the test that compares the two byte for byte
 * (internal/collapse_threads). */
int accel_collapse_wide_portable(struct bvh4 *out, const struct bvh *bvh,
                                 const struct collapse_triangles *tris, uint32_t width,
                                 struct rt_pool *pool, struct rt_large_block *spare,
                                 enum bvh_collapse collapse);

#endif
