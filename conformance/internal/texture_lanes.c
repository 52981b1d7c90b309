/* SPDX-License-Identifier: Apache-2.0 */
/*
 * texture_lanes.c - the eight-lane texture lookup of the shading's AVX2
 * copy (scene_texture_sample_lod8, through shade_texture_lod8_avx2_unit)
 * against scene_texture_sample_lod, bit for bit: textures of odd and
 * power-of-two sizes down to 1x1, REPEAT and CLAMP_TO_EDGE on each axis,
 * levels of detail at and around every level boundary, the last level,
 * magnifications, zeros, infinities and NaN, coordinates near texel
 * edges, negative, large and non-finite.  A block it refuses (a
 * coordinate of 2^31 or more, other filters) must be refused whole.
 * Skipped where the unit is absent or the CPU has no AVX2.
 *
 * Internal test (links the static library).  Non-zero exit on failure.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "base/alloc.h"
#include "check.h"
#include "render/shade.h"
#include "scene/texture.h"

static uint32_t rng = 2463534242u;

static uint32_t next(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 17;
    rng ^= rng << 5;
    return rng;
}

static float uniform(float lo, float hi)
{
    return lo + (hi - lo) * (float)(next() >> 8) / 16777216.0f;
}

static int set_random_image(struct scene_texture *tex, int w, int h)
{
    uint8_t *chain = rt_malloc(4 * scene_texture_chain_texels(w, h));
    if (!chain)
        return 0;
    for (size_t k = 0; k < 4 * (size_t)w * (size_t)h; k++)
        chain[k] = (uint8_t)next();
    if (scene_texture_build_mipmaps(chain, w, h) != 0) {
        rt_free(chain);
        return 0;
    }
    scene_texture_set_image(tex, w, h, chain);
    return 1;
}

/* A level of detail: special values, level boundaries and their float
 * neighbours, or anything in [-2, q + 3]. */
static float any_lambda(int q)
{
    switch (next() % 8) {
    case 0: {
        const float special[] = {NAN, -INFINITY, INFINITY, 0.0f, -0.0f, 1e-30f, -1e-30f};
        return special[next() % 7];
    }
    case 1:
    case 2: {
        const float b = (float)(int)(next() % (unsigned)(q + 2));
        const int step = (int)(next() % 3) - 1;
        return step < 0 ? nextafterf(b, -INFINITY) : step > 0 ? nextafterf(b, INFINITY) : b;
    }
    default:
        return uniform(-2.0f, (float)q + 3.0f);
    }
}

/* A coordinate: near texel edges of some level, in [-3, 3], large or
 * special. */
static float any_coord(int n)
{
    switch (next() % 10) {
    case 0: {
        const float special[] = {NAN, -INFINITY, INFINITY, 0.0f, -0.0f, 1.0f, -1.0f, 1e-30f,
                                 -1e-30f, 2.0f, 1e7f, -1e9f};
        return special[next() % 12];
    }
    case 1:
    case 2: {
        const float e = (float)(int)(next() % (unsigned)(2 * n + 1)) / (float)n;
        return (next() & 1) ? nextafterf(e, -INFINITY) : e;
    }
    default:
        return uniform(-3.0f, 3.0f);
    }
}

int main(void)
{
    const shade_texture_lod8_fn lod8 = shade_texture_lod8_avx2_unit();
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
    const int cpu = __builtin_cpu_supports("avx2");
#else
    const int cpu = 0;
#endif
    if (!lod8 || !cpu) {
        printf("texture_lanes: skipped (no AVX2 unit or CPU)\n");
        return 0;
    }
    struct scene_textures tab;
    scene_textures_init(&tab);
    struct scene_texture *tex = scene_textures_get_or_create(&tab, 1);
    const int sizes[][2] = {{1, 1}, {1, 7}, {5, 3}, {4, 4}, {64, 16}, {37, 129}, {128, 128},
                            {300, 5}};
    int failures = 0, lanes = 0, refused = 0;
    for (size_t z = 0; z < sizeof(sizes) / sizeof(sizes[0]); z++) {
        if (!tex || !set_random_image(tex, sizes[z][0], sizes[z][1])) {
            fprintf(stderr, "no memory for a texture\n");
            return 1;
        }
        const int q = tex->level_count - 1;
        const int n = sizes[z][0] > sizes[z][1] ? sizes[z][0] : sizes[z][1];
        for (int block = 0; block < 20000; block++) {
            tex->min_filter = SCENE_FILTER_LINEAR_MIPMAP_LINEAR;
            tex->mag_filter = SCENE_FILTER_LINEAR;
            if (block % 97 == 0)
                tex->min_filter = SCENE_FILTER_NEAREST_MIPMAP_LINEAR; /* refused */
            tex->wrap_s = (next() & 1) ? SCENE_WRAP_CLAMP_TO_EDGE : SCENE_WRAP_REPEAT;
            tex->wrap_t = (next() & 1) ? SCENE_WRAP_CLAMP_TO_EDGE : SCENE_WRAP_REPEAT;
            float lambda[8], s[8], t[8], rgb[3][8], want[8][4];
            for (int i = 0; i < 8; i++) {
                lambda[i] = any_lambda(q);
                s[i] = any_coord(n);
                t[i] = any_coord(n);
            }
            memset(rgb, 0x7f, sizeof(rgb));
            const int took = lod8(tex, lambda, s, t, rgb);
            int big = 0;
            for (int i = 0; i < 8; i++)
                big |= (isfinite(s[i]) && fabsf(s[i]) >= 0x1p31f) ||
                       (isfinite(t[i]) && fabsf(t[i]) >= 0x1p31f);
            const int should = !big && tex->min_filter == SCENE_FILTER_LINEAR_MIPMAP_LINEAR;
            failures += !CHECKF(took == should, "size %dx%d block %d: took %d, expected %d",
                                sizes[z][0], sizes[z][1], block, took, should);
            if (!took) {
                refused++;
                continue;
            }
            for (int i = 0; i < 8; i++) {
                scene_texture_sample_lod(tex, lambda[i], s[i], t[i], want[i]);
                int same = 1;
                for (int k = 0; k < 3; k++)
                    same &= memcmp(&rgb[k][i], &want[i][k], sizeof(float)) == 0;
                lanes++;
                failures += !CHECKF(same,
                                    "size %dx%d lane %d: lambda %a s %a t %a wrap %d %d: "
                                    "(%a %a %a) against (%a %a %a)",
                                    sizes[z][0], sizes[z][1], i, (double)lambda[i], (double)s[i],
                                    (double)t[i], (int)tex->wrap_s, (int)tex->wrap_t,
                                    (double)rgb[0][i], (double)rgb[1][i], (double)rgb[2][i],
                                    (double)want[i][0], (double)want[i][1], (double)want[i][2]);
                if (failures > 20)
                    break;
            }
            if (failures > 20)
                break;
        }
    }
    scene_textures_release(&tab);
    printf("texture_lanes: %d lanes compared, %d blocks refused\n", lanes, refused);
    printf("texture_lanes: %s (%d failed checks)\n", failures ? "FAILED" : "passed", failures);
    return failures != 0;
}
