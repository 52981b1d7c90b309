/* SPDX-License-Identifier: Apache-2.0 */
/*
 * traverse_avx2.c - the single-BVH walk compiled for AVX2 + FMA
 * (kernels.h).  The build gives this file its instruction-set flags;
 * without them (another architecture or compiler) the table is absent
 * and trace_kernels_avx2 returns NULL.
 */
#include "trace/kernels.h"
#include "trace/packet_kernels.h"

#if defined(__AVX2__)
#define TRACE_WALK_CLOSEST trace_closest_avx2
#define TRACE_WALK_ANY trace_any_avx2
#include "trace/traverse_walk.h"
#define TRACE_WIDE_CLOSEST trace_closest4_avx2
#define TRACE_WIDE_ANY trace_any4_avx2
#define TRACE_WIDE_CLOSEST1 trace_closest1_avx2
#define TRACE_WIDE_ANY1 trace_any1_avx2
#define TRACE_WIDE_LEAF8 trace_leaf8_avx2
#define TRACE_WIDE_WALK1 trace_walk1_avx2
#define TRACE_WIDE_WALK1_COUNTED trace_walk1_counted_avx2
#include "trace/traverse_wide.h"
#define TRACE_TOP_LANES trace_top_lanes_avx2
#define TRACE_TOP_LANES1 trace_top_lanes1_avx2
#include "trace/top_lanes.h"

static const struct trace_kernels table = {
    TRACE_ISA_AVX2, "avx2", trace_closest_avx2, trace_any_avx2,
    trace_closest4_avx2, trace_any4_avx2, trace_closest1_avx2, trace_any1_avx2,
    8,
    trace_closest_packet_avx2, trace_any_packet_avx2, trace_leaf8_avx2,
    trace_top_lanes_avx2, trace_top_lanes1_avx2, trace_packet_init_avx2,
    trace_packet_xform_avx2, trace_walk1_avx2, trace_walk1_counted_avx2,
    trace_closest_packet_arrays_avx2, trace_any_packet_arrays_avx2,
    trace_stream_pair_avx2, trace_stream_counted_avx2};

const struct trace_kernels *trace_kernels_avx2(void)
{
    return &table;
}
#else
const struct trace_kernels *trace_kernels_avx2(void)
{
    return NULL;
}
#endif
