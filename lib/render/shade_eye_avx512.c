/* SPDX-License-Identifier: Apache-2.0 */
/*
 * shade_eye_avx512.c - the eye light's batch of hits (shade_eye_hits), its
 * block pipeline (shade_eye_block_begin, shade_eye_block_end) and
 * everything they call in the shading, surface and texture files,
 * compiled again with AVX-512 enabled (CMakeLists.txt gives this file
 * -mavx512f, -mavx512vl, -mavx512bw, -mavx512dq, -mavx2 and
 * -ffp-contract=off, no FMA), as shade_eye_avx2.c compiles them for AVX2:
 * the same source with its external functions renamed (suffix _avx512),
 * so every float operation is the same IEEE operation in the same order.
 * Under __AVX512F__ surface.c takes a block's levels of detail by the
 * triangle's texel map in one eight-lane vector (lod_fast_oct, the two
 * quads of lod_fast_quad together, each lane its operations), so the same
 * lambdas.  shade_eye_hits calls this copy when the context's traversal
 * table is AVX-512, and the frame's AVX-512 packet loop (render_avx512.c)
 * its block pipeline (trace/kernels.c has checked that the CPU and the
 * operating system run AVX-512F, VL, BW and DQ then).  Under RT_NO_SIMD,
 * or where the compiler does not target AVX-512, the unit is absent
 * (shade_eye_hits_avx512_unit returns NULL).
 */
#include <stddef.h>

#if defined(__AVX2__) && defined(__AVX512F__) && defined(__AVX512DQ__) && \
    defined(__AVX512VL__) && !defined(RT_NO_SIMD)
/* Every path of the AVX2 copy (the block pipeline of shade_eye_block_begin
 * and _end included); SURFACE_OCTS in surface.c adds the eight-lane
 * levels of detail. */
#define SHADE_UNIT_AVX2 1

#define SHADE_EYE_SUFFIX _avx512
#include "render/shade_eye_unit.h"

#include "render/shade.c"
#include "render/surface.c"
#include "scene/texture.c"

shade_eye_hits_fn shade_eye_hits_avx512_unit(void)
{
    return shade_eye_hits_avx512;
}

shade_texture_lod8_fn shade_texture_lod8_avx512_unit(void)
{
    return scene_texture_sample_lod8_avx512;
}

static int lod8_steps(const struct scene_texture *tex, const float lambda[8], const float s[8],
                      const float t[8], float rgb[3][8])
{
    struct scene_texture_lookup8 lookup;
    if (!scene_texture_prefetch_lod8(tex, lambda, s, t, &lookup))
        return 0;
    scene_texture_finish_lod8(&lookup, rgb);
    return 1;
}

shade_texture_lod8_fn shade_texture_lod8_steps_avx512_unit(void)
{
    return lod8_steps;
}

/* lod_fast_oct for the test that the lanes it decides are lod_ray's (the
 * four hits in lanes 0 to 3 and again in lanes 4 to 7; a lane counts as
 * decided when both copies are, with the same lambda). */
static int lod_fast_lanes8(const struct surface_lod *l, int level_count, const float dir[4][3],
                           const float ng[4][3], const float width[4], float fast[4],
                           float ref[4])
{
    struct surface_lod_fast f;
    lod_fast_init(l, &f);
    int mask = 0;
    if (f.state > 0) {
        __m512d d[3], g[3];
        for (int k = 0; k < 3; k++) {
            d[k] = _mm512_setr_pd(dir[0][k], dir[1][k], dir[2][k], dir[3][k], dir[0][k],
                                  dir[1][k], dir[2][k], dir[3][k]);
            g[k] = _mm512_setr_pd(ng[0][k], ng[1][k], ng[2][k], ng[3][k], ng[0][k], ng[1][k],
                                  ng[2][k], ng[3][k]);
        }
        const __m512d w = _mm512_setr_pd(width[0], width[1], width[2], width[3], width[0],
                                         width[1], width[2], width[3]);
        float lambda[8];
        const double top = lod_top(level_count);
        const int m8 = lod_fast_oct(&f, l->n, d, g, w, _mm512_set1_pd(top * top), lambda);
        mask = m8 & m8 >> 4 & 15;
        for (int i = 0; i < 4; i++) {
            fast[i] = lambda[i];
            if (memcmp(&lambda[i], &lambda[4 + i], sizeof(float)) != 0)
                mask &= ~(1 << i);
        }
    }
    for (int i = 0; i < 4; i++)
        ref[i] = lod_ray(l, level_count, ng[i], dir[i], width[i]);
    return mask;
}

shade_lod_fast_fn shade_lod_fast_avx512_unit(void)
{
    return lod_fast_lanes8;
}

static void log2_oct_half(const double x[8], double half[8])
{
    _mm512_storeu_pd(half, lanes_log2_8_half(_mm512_loadu_pd(x)));
}

shade_log2_oct_half_fn shade_log2_oct_half_avx512_unit(void)
{
    return log2_oct_half;
}
#else
#include "render/shade.h"

shade_eye_hits_fn shade_eye_hits_avx512_unit(void)
{
    return NULL;
}

shade_texture_lod8_fn shade_texture_lod8_avx512_unit(void)
{
    return NULL;
}

shade_texture_lod8_fn shade_texture_lod8_steps_avx512_unit(void)
{
    return NULL;
}

shade_lod_fast_fn shade_lod_fast_avx512_unit(void)
{
    return NULL;
}

shade_log2_oct_half_fn shade_log2_oct_half_avx512_unit(void)
{
    return NULL;
}
#endif
