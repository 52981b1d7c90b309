/* SPDX-License-Identifier: Apache-2.0 */
/*
 * render_avx512.c - the frame's tile loop with packets (render_tile_packets)
 * and everything it calls in render.c, compiled again with AVX-512
 * enabled (CMakeLists.txt gives this file -mavx512f, -mavx512vl,
 * -mavx512bw, -mavx512dq, -mavx2, -mfma and -ffp-contract=off: FMA only
 * where the source asks for it, as in the AVX2 copy), as
 * render_avx2.c compiles it for AVX2: render.c included with its
 * external functions renamed (suffix _avx512), the camera rays four at a
 * time as there, so the same rays, cones and pixels bit for bit.  What
 * this copy adds is the eye light's block pipeline of the AVX-512
 * shading copy (shade_eye_block_begin_avx512 and _end_avx512,
 * shade_eye_avx512.c) in place of the AVX2 one.  render_tile calls this
 * copy's packet loop when the scene's traversal table is AVX-512
 * (trace/kernels.c has checked that the CPU and the operating system run
 * AVX-512F, VL, BW and DQ, AVX2 and FMA then).  Under RT_NO_SIMD, or
 * where the compiler does not target AVX-512, the unit is absent
 * (render_tile_packets_avx512_unit returns NULL).
 */
#include <stddef.h>

/* The shading unit's condition (shade_eye_avx512.c), whose block
 * pipeline this copy calls. */
#if defined(__AVX2__) && defined(__AVX512F__) && defined(__AVX512DQ__) && \
    defined(__AVX512VL__) && !defined(RT_NO_SIMD)
/* The AVX2 copy's paths (the camera rays in quads, the eye light's block
 * pipeline), with the AVX-512 shading's pipeline. */
#define RENDER_UNIT_AVX2 1
#define RENDER_UNIT_AVX512 1

#define RENDER_SUFFIX _avx512
#include "render/render_unit.h"

#include "render/render.c"

render_tile_packets_fn render_tile_packets_avx512_unit(void)
{
    return render_tile_packets;
}

render_unproject_rows_fn render_unproject_rows_avx512_unit(void)
{
    return render_unproject_rows;
}
#else
#include "render/render.h"

render_tile_packets_fn render_tile_packets_avx512_unit(void)
{
    return NULL;
}

render_unproject_rows_fn render_unproject_rows_avx512_unit(void)
{
    return NULL;
}
#endif
