/* SPDX-License-Identifier: Apache-2.0 */
/*
 * unit8_split.c - the eight-lane texture lookups' channels b / 255 for
 * every byte b, bit for bit.
 *
 * The lookups of the AVX2 and AVX-512 shading units
 * (scene_texture_sample_lod8 and its two steps prefetch_lod8 and
 * finish_lod8, through shade_texture_lod8_*_unit) take b / 255 without
 * the divider, as the sum b 2^-8 + RN(b RN(1/65280)) (unit8_lanes in
 * scene/texture.c), which is the correctly rounded quotient only because
 * it happens to be for each of the 256 bytes; the product by RN(1/255)
 * alone is not for 126 of them.  The random images of shade_lanes reach
 * a byte's quotient through weights that may hide a last-bit error, so
 * here each byte is looked up with both weights 0: a 256 x 1 image whose
 * texel i holds (i, 255 - i, 7 i mod 256, 255), magnified (lambda -1,
 * level 0), s at texel i's centre (i + 1/2) / 256 and t = 1/2, where the
 * bilinear blend c00 + 0 (c10 - c00) ... gives the texel's own channel.
 * Each lane must be (float)b / 255.0f, and scene_texture_sample_lod's
 * value for the same point.
 */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "base/alloc.h"
#include "check.h"
#include "render/shade.h"
#include "scene/texture.h"

static int failures;

static uint8_t channel(int i, int k)
{
    return (uint8_t)(k == 0 ? i : k == 1 ? 255 - i : (7 * i) & 255);
}

static void check_unit(const char *name, shade_texture_lod8_fn lod8,
                       const struct scene_texture *tex)
{
    int lanes = 0;
    for (int first = 0; first < 256; first += 8) {
        float lambda[8], s[8], t[8], rgb[3][8];
        for (int i = 0; i < 8; i++) {
            lambda[i] = -1.0f;
            s[i] = ((float)(first + i) + 0.5f) / 256.0f; /* exact */
            t[i] = 0.5f;
        }
        memset(rgb, 0x7f, sizeof(rgb));
        if (!CHECKF(lod8(tex, lambda, s, t, rgb), "%s: block at texel %d refused", name,
                    first)) {
            failures++;
            continue;
        }
        for (int i = 0; i < 8; i++) {
            float ref[4];
            scene_texture_sample_lod(tex, lambda[i], s[i], t[i], ref);
            for (int k = 0; k < 3; k++) {
                const uint8_t b = channel(first + i, k);
                const float want = (float)b / 255.0f;
                lanes++;
                failures += !CHECKF(memcmp(&rgb[k][i], &want, sizeof(float)) == 0 &&
                                        memcmp(&ref[k], &want, sizeof(float)) == 0,
                                    "%s: texel %d channel %d (byte %u): %a, scalar %a, "
                                    "not %a",
                                    name, first + i, k, (unsigned)b, (double)rgb[k][i],
                                    (double)ref[k], (double)want);
            }
        }
    }
    printf("unit8_split: %s, %d channels compared\n", name, lanes);
}

int main(void)
{
    struct scene_textures tab;
    scene_textures_init(&tab);
    struct scene_texture *tex = scene_textures_get_or_create(&tab, 1);
    uint8_t *chain = rt_malloc(4 * scene_texture_chain_texels(256, 1));
    if (!tex || !chain) {
        fprintf(stderr, "no memory for a texture\n");
        return 1;
    }
    for (int i = 0; i < 256; i++) {
        for (int k = 0; k < 3; k++)
            chain[4 * i + k] = channel(i, k);
        chain[4 * i + 3] = 255;
    }
    if (scene_texture_build_mipmaps(chain, 256, 1) != 0) {
        fprintf(stderr, "no memory for the mipmaps\n");
        return 1;
    }
    scene_texture_set_image(tex, 256, 1, chain);
    tex->min_filter = SCENE_FILTER_LINEAR_MIPMAP_LINEAR;
    tex->mag_filter = SCENE_FILTER_LINEAR;
    tex->wrap_s = SCENE_WRAP_CLAMP_TO_EDGE;
    tex->wrap_t = SCENE_WRAP_CLAMP_TO_EDGE;

    int units = 0;
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
    const int cpu2 = __builtin_cpu_supports("avx2");
    const int cpu512 = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
                       __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512bw");
#else
    const int cpu2 = 0, cpu512 = 0;
#endif
    const shade_texture_lod8_fn fns[4] = {
        shade_texture_lod8_avx2_unit(), shade_texture_lod8_steps_avx2_unit(),
        shade_texture_lod8_avx512_unit(), shade_texture_lod8_steps_avx512_unit()};
    const char *names[4] = {"avx2 sample_lod8", "avx2 prefetch + finish", "avx512 sample_lod8",
                            "avx512 prefetch + finish"};
    for (int u = 0; u < 4; u++) {
        if (!fns[u] || !(u < 2 ? cpu2 : cpu512)) {
            printf("unit8_split: %s skipped (no unit or CPU)\n", names[u]);
            continue;
        }
        check_unit(names[u], fns[u], tex);
        units++;
    }
    scene_textures_release(&tab);
    printf("unit8_split: %d lookups checked, %d failures\n", units, failures);
    return failures != 0;
}
