/* SPDX-License-Identifier: Apache-2.0 */
/*
 * packet_avx2.c - the packet walk compiled for AVX2 + FMA
 * (packet_kernels.h): the set-up of a packet's rays (packet_init.h), the
 * walks (packet_wide.h) and the instances' transform (packet_xform.h),
 * in a unit apart from the single walk's (traverse_avx2.c, whose table
 * names these functions).  The build gives this file traverse_avx2.c's
 * flags; without them the file defines nothing.
 */
#include "trace/packet_kernels.h"

#if defined(__AVX2__)
/* The single walk's pieces the packet walk reuses, and its fallback, with
 * none of the single-ray entries (traverse_wide.h). */
#define TRACE_WIDE_PACKET_PIECES
#include "trace/traverse_walk.h"
#include "trace/traverse_wide.h"
/* packet_init.h before packet_wide.h: the arrays entries set their rays
 * up with its pieces. */
#define TRACE_PACKET_INIT trace_packet_init_avx2
#include "trace/packet_init.h"
#define TRACE_PACKET_CLOSEST trace_closest_packet_avx2
#define TRACE_PACKET_ANY trace_any_packet_avx2
#define TRACE_PACKET_CLOSEST_ARRAYS trace_closest_packet_arrays_avx2
#define TRACE_PACKET_ANY_ARRAYS trace_any_packet_arrays_avx2
#include "trace/packet_wide.h"
#define TRACE_PACKET_XFORM trace_packet_xform_avx2
#include "trace/packet_xform.h"
#endif
