/* SPDX-License-Identifier: Apache-2.0 */
/*
 * stream_avx2.c - the AVX2 table's stream walk (kernels.h, stream_pair;
 * traverse_pair8.h), compiled with the table's flags in a translation
 * unit of its own.  In traverse_avx2.c beside the table's walks, the
 * stream's four functions changed how GCC compiled 13 of that file's
 * functions (the leaves among them: tri4_lane_test was no longer
 * specialised, one more spill in wide8_packet_closest), so the single
 * walks would have changed with an entry they never call.  Here the
 * stream has its own copies of the leaves and walks (traverse_wide.h's
 * static functions, the same source, so the same answers:
 * conformance/internal/pair8_stream compares it with the table's walk1
 * bit for bit), and traverse_avx2.c compiles to the code it had, with
 * one more pointer in its table.  Without AVX2 the file is empty.
 */
#include "trace/kernels.h"
#include "trace/packet_kernels.h"

#if defined(__AVX2__)
/* traverse_wide.h's entries that the stream does not call (its walks
 * and leaves are static functions, defined for each table that includes
 * it): not emitted, and not warned about here. */
#if defined(__GNUC__)
#pragma GCC diagnostic ignored "-Wunused-function"
#endif
#define TRACE_WALK_CLOSEST stream_closest_avx2
#define TRACE_WALK_ANY stream_any_avx2
#include "trace/traverse_walk.h"
#define TRACE_WIDE_CLOSEST stream_closest4_avx2
#define TRACE_WIDE_ANY stream_any4_avx2
#define TRACE_WIDE_CLOSEST1 stream_closest1_avx2
#define TRACE_WIDE_ANY1 stream_any1_avx2
#define TRACE_WIDE_LEAF8 stream_leaf8_avx2
#define TRACE_WIDE_WALK1 stream_walk1_avx2
#define TRACE_WIDE_WALK1_COUNTED stream_walk1_counted_avx2
#include "trace/traverse_wide.h"
#define TRACE_PAIR8_STREAM stream_pair_choose_avx2
#define TRACE_PAIR8_STREAM_COUNTED stream_counted_choose_avx2
#include "trace/traverse_pair8.h"

trace_stream1_fn trace_stream_pair_avx2(const struct bvh4 *wide, int any_hit)
{
    return stream_pair_choose_avx2(wide, any_hit);
}

trace_stream1_counted_fn trace_stream_counted_avx2(const struct bvh4 *wide, int any_hit)
{
    return stream_counted_choose_avx2(wide, any_hit);
}
#endif
