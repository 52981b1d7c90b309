/* SPDX-License-Identifier: Apache-2.0 */
/*
 * traverse_sse4.c - the single-BVH walk compiled for SSE4.2
 * (kernels.h).  The build gives this file its instruction-set flags;
 * without them (another architecture or compiler) the table is absent
 * and trace_kernels_sse4 returns NULL.
 */
#include "trace/kernels.h"
#include "trace/packet_kernels.h"
#include "trace/scene_traverse.h"

#if defined(__SSE4_2__)
#define TRACE_WALK_CLOSEST trace_closest_sse4
#define TRACE_WALK_ANY trace_any_sse4
#include "trace/traverse_walk.h"
#define TRACE_WIDE_CLOSEST trace_closest4_sse4
#define TRACE_WIDE_ANY trace_any4_sse4
#define TRACE_WIDE_CLOSEST1 trace_closest1_sse4
#define TRACE_WIDE_ANY1 trace_any1_sse4
#include "trace/traverse_wide.h"

static const struct trace_kernels table = {
    TRACE_ISA_SSE4, "sse4", trace_closest_sse4, trace_any_sse4,
    trace_closest4_sse4, trace_any4_sse4, trace_closest1_sse4, trace_any1_sse4,
    4,
    trace_closest_packet_sse4, trace_any_packet_sse4, NULL, NULL,
    trace_scene_wide_lanes, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL};

const struct trace_kernels *trace_kernels_sse4(void)
{
    return &table;
}
#else
const struct trace_kernels *trace_kernels_sse4(void)
{
    return NULL;
}
#endif
