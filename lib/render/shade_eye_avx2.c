/* SPDX-License-Identifier: Apache-2.0 */
/*
 * shade_eye_avx2.c - the eye light's batch of hits (shade_eye_hits) and
 * everything it calls in the shading, surface and texture files, compiled
 * again with AVX2 enabled (CMakeLists.txt gives this file -mavx2 and
 * -ffp-contract=off, no FMA).  The source is the same: shade.c,
 * surface.c and texture.c are included with their external functions
 * renamed (suffix _avx2), so every float operation is the same IEEE
 * operation in the same order, only encoded with VEX (three operands,
 * no register copies before each SSE operation) and free to use the
 * wider registers where the compiler finds independent lanes; sqrt and
 * division are correctly rounded in every encoding and the libm calls
 * (log2, hypot) are the same functions, so the colours are the same bit
 * for bit.  shade_eye_hits calls this copy when the context's traversal
 * table is AVX2, or AVX-512 where the AVX-512 copy (shade_eye_avx512.c)
 * is absent (trace/kernels.c has checked that the CPU and the operating
 * system run AVX2 then), so isa= chooses the shading too.
 * Under RT_NO_SIMD, or where the compiler does not target AVX2, the unit
 * is absent (shade_eye_hits_avx2_unit returns NULL).
 */
#include <stddef.h>

#if defined(__AVX2__) && !defined(RT_NO_SIMD)
#define SHADE_UNIT_AVX2 1

#define SHADE_EYE_SUFFIX _avx2
#include "render/shade_eye_unit.h"

#include "render/shade.c"
#include "render/surface.c"
#include "scene/texture.c"

shade_eye_hits_fn shade_eye_hits_avx2_unit(void)
{
    return shade_eye_hits_avx2;
}

shade_texture_lod8_fn shade_texture_lod8_avx2_unit(void)
{
    return scene_texture_sample_lod8_avx2;
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

shade_texture_lod8_fn shade_texture_lod8_steps_avx2_unit(void)
{
    return lod8_steps;
}

static void log2_quad(const double x[4], double out[4], double half[4])
{
    _mm256_storeu_pd(out, lanes_log2_4(_mm256_loadu_pd(x)));
    _mm256_storeu_pd(half, lanes_log2_4_half(_mm256_loadu_pd(x)));
}

shade_log2_quad_fn shade_log2_quad_avx2_unit(void)
{
    return log2_quad;
}

static int lod_fast_lanes(const struct surface_lod *l, int level_count, const float dir[4][3],
                          const float ng[4][3], const float width[4], float fast[4], float ref[4])
{
    struct surface_lod_fast f;
    lod_fast_init(l, &f);
    int mask = 0;
    if (f.state > 0) {
        __m256d d[3], g[3];
        for (int k = 0; k < 3; k++) {
            d[k] = _mm256_set_pd(dir[3][k], dir[2][k], dir[1][k], dir[0][k]);
            g[k] = _mm256_set_pd(ng[3][k], ng[2][k], ng[1][k], ng[0][k]);
        }
        const __m256d w = _mm256_set_pd(width[3], width[2], width[1], width[0]);
        struct lod_fast_broadcast b;
        lod_fast_quad_lanes(&f, l->n, lod_top(level_count), &b);
        mask = lod_fast_quad(&b, d, g, w, fast);
    }
    for (int i = 0; i < 4; i++)
        ref[i] = lod_ray(l, level_count, ng[i], dir[i], width[i]);
    return mask;
}

shade_lod_fast_fn shade_lod_fast_avx2_unit(void)
{
    return lod_fast_lanes;
}

/* lod_quad_lanes on four hits, every lane on triangle part l (shared as
 * the one-triangle block gives it, or not as a mixed block's lanes each
 * point to their own part): shade_lod_quad_fn (shade.h). */
static void lod_quad_unit(const struct surface_lod *l, int shared, int level_count,
                          const float dir[4][3], const float ng[4][3], const float width[4],
                          float quad[4])
{
    const struct surface_lod *const l4[4] = {l, l, l, l};
    float lane_g[3][TRACE_PACKET], lane_d[3][TRACE_PACKET], lane_w[TRACE_PACKET];
    float lambda[TRACE_PACKET];
    for (int i = 0; i < TRACE_PACKET; i++) {
        for (int k = 0; k < 3; k++) {
            lane_g[k][i] = ng[i % 4][k];
            lane_d[k][i] = dir[i % 4][k];
        }
        lane_w[i] = width[i % 4];
    }
    __m256d d[3], g[3];
    for (int k = 0; k < 3; k++) {
        d[k] = _mm256_set_pd(dir[3][k], dir[2][k], dir[1][k], dir[0][k]);
        g[k] = _mm256_set_pd(ng[3][k], ng[2][k], ng[1][k], ng[0][k]);
    }
    const __m256d w = _mm256_set_pd(width[3], width[2], width[1], width[0]);
    lod_quad_lanes(l4, shared, d, g, w, lod_top(level_count), level_count, 0, lane_w, lane_g,
                   lane_d, lambda);
    for (int i = 0; i < 4; i++)
        quad[i] = lambda[i];
}

shade_lod_quad_fn shade_lod_quad_avx2_unit(void)
{
    return lod_quad_unit;
}
#else
#include "render/shade.h"

shade_eye_hits_fn shade_eye_hits_avx2_unit(void)
{
    return NULL;
}

shade_texture_lod8_fn shade_texture_lod8_avx2_unit(void)
{
    return NULL;
}

shade_texture_lod8_fn shade_texture_lod8_steps_avx2_unit(void)
{
    return NULL;
}

shade_log2_quad_fn shade_log2_quad_avx2_unit(void)
{
    return NULL;
}

shade_lod_fast_fn shade_lod_fast_avx2_unit(void)
{
    return NULL;
}

shade_lod_quad_fn shade_lod_quad_avx2_unit(void)
{
    return NULL;
}
#endif
