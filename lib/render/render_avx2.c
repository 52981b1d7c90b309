/* SPDX-License-Identifier: Apache-2.0 */
/*
 * render_avx2.c - the frame's tile loop with packets (render_tile_packets)
 * and everything it calls in render.c, compiled again with AVX2 enabled
 * (CMakeLists.txt gives this file -mavx2, -mfma and -ffp-contract=off:
 * FMA only where the source asks for it, in the row fill's quotients by
 * a frame-constant w, base/quotient_known.h).
 * render.c is included with its external functions renamed (suffix
 * _avx2); under __AVX2__ it unprojects a row of pixel centres and makes
 * a block row's four camera rays in the 256-bit double lanes
 * (RENDER_QUADS), each lane the operations of the pairs in their order,
 * so the same rays, cones and pixels bit for bit.  What the change buys
 * is half the divider instructions (sqrtpd, divpd) of the camera rays,
 * which bound that code.  render_tile calls this copy's packet loop when
 * the scene's traversal table is AVX2, or AVX-512 where the AVX-512 copy
 * (render_avx512.c) is absent (trace/kernels.c has checked that the CPU
 * and the operating system run AVX2 and FMA then).  Under
 * RT_NO_SIMD, or where the compiler does not target AVX2, the unit is
 * absent (render_tile_packets_avx2_unit returns NULL).
 */
#include <stddef.h>

#if defined(__AVX2__) && !defined(RT_NO_SIMD)
#define RENDER_UNIT_AVX2 1

#define RENDER_SUFFIX _avx2
#include "render/render_unit.h"

#include "render/render.c"

render_tile_packets_fn render_tile_packets_avx2_unit(void)
{
    return render_tile_packets;
}

render_unproject_rows_fn render_unproject_rows_avx2_unit(void)
{
    return render_unproject_rows;
}
#else
#include "render/render.h"

render_tile_packets_fn render_tile_packets_avx2_unit(void)
{
    return NULL;
}

render_unproject_rows_fn render_unproject_rows_avx2_unit(void)
{
    return NULL;
}
#endif
