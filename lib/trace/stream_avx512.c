/* SPDX-License-Identifier: Apache-2.0 */
/*
 * stream_avx512.c - the AVX-512 table's stream walk (kernels.h,
 * stream_pair; traverse_pair8.h): the same source as stream_avx2.c,
 * compiled with the AVX-512 table's flags in a translation unit of its
 * own (stream_avx2.c says why not beside the table's walks).  The
 * stream's node test stays traverse_pair8.h's (isect_box's slabs on
 * eight lanes, as the AVX2 table's walk1), so the answers and counts are
 * the AVX2 stream's; the leaves are traverse_wide.h's AVX-512 forms, and
 * the compiler may use the EVEX encodings and 32 vector registers.
 * Without AVX-512 (F, VL, BW, DQ) the file is empty.
 */
#include "trace/kernels.h"
#include "trace/packet_kernels.h"

#if defined(__AVX512VL__)
/* traverse_wide.h's entries that the stream does not call: not emitted,
 * and not warned about here (as in stream_avx2.c). */
#if defined(__GNUC__)
#pragma GCC diagnostic ignored "-Wunused-function"
#endif
#define TRACE_WALK_CLOSEST stream_closest_avx512
#define TRACE_WALK_ANY stream_any_avx512
#include "trace/traverse_walk.h"
#define TRACE_WIDE_CLOSEST stream_closest4_avx512
#define TRACE_WIDE_ANY stream_any4_avx512
#define TRACE_WIDE_CLOSEST1 stream_closest1_avx512
#define TRACE_WIDE_ANY1 stream_any1_avx512
#define TRACE_WIDE_LEAF8 stream_leaf8_avx512
#define TRACE_WIDE_WALK1 stream_walk1_avx512
#define TRACE_WIDE_WALK1_COUNTED stream_walk1_counted_avx512
#include "trace/traverse_wide.h"
#define TRACE_PAIR8_STREAM stream_pair_choose_avx512
#define TRACE_PAIR8_STREAM_COUNTED stream_counted_choose_avx512
#include "trace/traverse_pair8.h"

trace_stream1_fn trace_stream_pair_avx512(const struct bvh4 *wide, int any_hit)
{
    return stream_pair_choose_avx512(wide, any_hit);
}

trace_stream1_counted_fn trace_stream_counted_avx512(const struct bvh4 *wide, int any_hit)
{
    return stream_counted_choose_avx512(wide, any_hit);
}
#endif
