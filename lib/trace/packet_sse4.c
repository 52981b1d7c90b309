/* SPDX-License-Identifier: Apache-2.0 */
/*
 * packet_sse4.c - the packet walk compiled for SSE4.2 (packet_kernels.h,
 * packet_wide.h), in a unit apart from the single walk's
 * (traverse_sse4.c, whose table names these functions).  The build gives
 * this file traverse_sse4.c's flags; without them the file defines
 * nothing.
 */
#include "trace/packet_kernels.h"

#if defined(__SSE4_2__)
/* The single walk's pieces the packet walk reuses, and its fallback, with
 * none of the single-ray entries (traverse_wide.h). */
#define TRACE_WIDE_PACKET_PIECES
#include "trace/traverse_walk.h"
#include "trace/traverse_wide.h"
#define TRACE_PACKET_CLOSEST trace_closest_packet_sse4
#define TRACE_PACKET_ANY trace_any_packet_sse4
#include "trace/packet_wide.h"
#endif
