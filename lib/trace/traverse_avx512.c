/* SPDX-License-Identifier: Apache-2.0 */
/*
 * traverse_avx512.c - the single-BVH walk compiled for AVX-512 (F, VL, BW, DQ)
 * (kernels.h).  The build gives this file its instruction-set flags;
 * without them (another architecture or compiler) the table is absent
 * and trace_kernels_avx512 returns NULL.
 */
#include "trace/kernels.h"
#include "trace/packet_kernels.h"

#if defined(__AVX512VL__)
#define TRACE_WALK_CLOSEST trace_closest_avx512
#define TRACE_WALK_ANY trace_any_avx512
#include "trace/traverse_walk.h"
#define TRACE_WIDE_CLOSEST trace_closest4_avx512
#define TRACE_WIDE_ANY trace_any4_avx512
#define TRACE_WIDE_CLOSEST1 trace_closest1_avx512
#define TRACE_WIDE_ANY1 trace_any1_avx512
#define TRACE_WIDE_LEAF8 trace_leaf8_avx512
#define TRACE_WIDE_WALK1 trace_walk1_avx512
#define TRACE_WIDE_WALK1_COUNTED trace_walk1_counted_avx512
#define TRACE_WIDE_CLOSEST1_CTZ trace_closest1_ctz_avx512
#define TRACE_WIDE_ANY1_CTZ trace_any1_ctz_avx512
#define TRACE_WIDE_WALK1_CTZ trace_walk1_ctz_avx512
#define TRACE_WIDE_WALK1_COUNTED_CTZ trace_walk1_counted_ctz_avx512
#include "trace/traverse_wide.h"
#define TRACE_TOP_LANES trace_top_lanes_avx512
#define TRACE_TOP_LANES1 trace_top_lanes1_avx512
#include "trace/top_lanes.h"

static const struct trace_kernels table = {
    TRACE_ISA_AVX512, "avx512", trace_closest_avx512, trace_any_avx512,
    trace_closest4_avx512, trace_any4_avx512, trace_closest1_avx512, trace_any1_avx512,
    8,
    trace_closest_packet_avx512, trace_any_packet_avx512, trace_leaf8_avx512,
    trace_top_lanes_avx512, trace_top_lanes1_avx512, trace_packet_init_avx512,
    trace_packet_xform_avx512, trace_walk1_avx512, trace_walk1_counted_avx512,
    trace_closest_packet_arrays_avx512, trace_any_packet_arrays_avx512,
    /* The AVX2 table's stream (kernels.h, stream_pair). */
    trace_stream_pair_avx2, trace_stream_counted_avx2};

/* The same table with the single-ray walks whose front child comes by
 * the trailing-zero count (closest1, any1, walk1, walk1_counted:
 * traverse_wide.h's walk_wide8_ray_leaf8_ctz); every other entry is
 * table's. */
static const struct trace_kernels table_ctz = {
    TRACE_ISA_AVX512, "avx512", trace_closest_avx512, trace_any_avx512,
    trace_closest4_avx512, trace_any4_avx512, trace_closest1_ctz_avx512, trace_any1_ctz_avx512,
    8,
    trace_closest_packet_avx512, trace_any_packet_avx512, trace_leaf8_avx512,
    trace_top_lanes_avx512, trace_top_lanes1_avx512, trace_packet_init_avx512,
    trace_packet_xform_avx512, trace_walk1_ctz_avx512, trace_walk1_counted_ctz_avx512,
    trace_closest_packet_arrays_avx512, trace_any_packet_arrays_avx512,
    trace_stream_pair_avx2, trace_stream_counted_avx2};

const struct trace_kernels *trace_kernels_avx512(void)
{
    return &table;
}

const struct trace_kernels *trace_kernels_avx512_ctz(void)
{
    return &table_ctz;
}
#else
const struct trace_kernels *trace_kernels_avx512(void)
{
    return NULL;
}

const struct trace_kernels *trace_kernels_avx512_ctz(void)
{
    return NULL;
}
#endif
