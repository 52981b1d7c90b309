/* SPDX-License-Identifier: Apache-2.0 */
/*
 * collapse4_avx2.c - the collapse into the wide layout (collapse4.c)
 * compiled again with AVX2 enabled (CMakeLists.txt gives this file
 * -mavx2 and -ffp-contract=off, no FMA), as build_binned_sah_avx2.c does
 * for the binned builder.  The source is the same, included with its
 * external functions renamed, so every float and double operation is the
 * same IEEE operation in the same order, VEX-encoded (and, where
 * collapse4.c has a form for AVX2, four lanes of doubles at a time in
 * place of two): the same wide nodes and packets byte for byte.
 * accel_collapse_wide_reuse calls this copy when the CPU runs AVX2
 * (build_cpu_runs_avx2).  Under RT_NO_SIMD, or where the compiler does
 * not target AVX2, the unit is absent (accel_collapse_wide_avx2_unit
 * returns NULL).
 */
#include "accel/collapse4_avx2.h"

#include "accel/build_internal.h"

#if defined(__AVX2__) && !defined(RT_NO_SIMD)
#define COLLAPSE_UNIT_AVX2 1
#define accel_collapse_wide_quality accel_collapse_wide_quality_avx2
#define accel_collapse_wide_source accel_collapse_wide_source_avx2
#define accel_collapse_wide_mesh accel_collapse_wide_mesh_avx2
#define accel_collapse_wide_reuse accel_collapse_wide_reuse_avx2
#define accel_collapse_wide_portable accel_collapse_wide_portable_avx2
#define accel_collapse_wide_pool accel_collapse_wide_pool_avx2
#define accel_collapse_wide accel_collapse_wide_avx2
#define accel_collapse4 accel_collapse4_avx2
#define accel_refit4 accel_refit4_avx2
#define accel_set_packet_lane accel_set_packet_lane_avx2
#define bvh4_node_bytes bvh4_node_bytes_avx2
#define bvh4_leaf_bytes bvh4_leaf_bytes_avx2
#define bvh4_release bvh4_release_avx2

#include "accel/collapse4.c"

collapse_wide_fn accel_collapse_wide_avx2_unit(void)
{
    return build_cpu_runs_avx2() ? accel_collapse_wide_source_avx2 : NULL;
}
#else
collapse_wide_fn accel_collapse_wide_avx2_unit(void)
{
    return NULL;
}
#endif
