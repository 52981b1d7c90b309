/* SPDX-License-Identifier: Apache-2.0 */
/*
 * texture_sample.c - the texture table, mip chains and sampler of
 * scene/texture.h, directly: the values a sample must give (texel centres,
 * bilinear weights, REPEAT and CLAMP_TO_EDGE at and beyond the edges), that
 * any float coordinate (NaN, infinities, 1e30, tiny negatives) and any
 * level of detail stays inside the image, the mip chain's level sizes and
 * hand-computed texels of its levels (the area-weighted box on odd sizes,
 * the 1x1 level being the image's mean), which levels and filters each
 * level of detail selects (GL 1.1 sec. 3.8.1-3.8.2), and that the table
 * finds every name after insertions and backward-shift deletions.
 *
 * Internal test (links the static library).  Non-zero exit on failure.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/alloc.h"
#include "check.h"
#include "scene/texture.h"

static int failures;


#define TW 4
#define TH 3

/* Texel (i, j) of the test image: (40 i + 15, 60 j + 30, 5 i + 7 j, 255). */
static void texel_value(int i, int j, float out[4])
{
    out[0] = (float)(40 * i + 15) / 255.0f;
    out[1] = (float)(60 * j + 30) / 255.0f;
    out[2] = (float)(5 * i + 7 * j) / 255.0f;
    out[3] = 1.0f;
}

/* Gives tex the width x height image level0 (copied) and its mip chain. */
static void set_image(struct scene_texture *tex, int width, int height, const uint8_t *level0)
{
    uint8_t *chain = rt_malloc(4 * scene_texture_chain_texels(width, height));
    if (!chain) {
        failures += !CHECKF(0, "no memory for a %dx%d chain", width, height);
        return;
    }
    memcpy(chain, level0, 4 * (size_t)width * (size_t)height);
    failures += !CHECKF(scene_texture_build_mipmaps(chain, width, height) == 0, "build %dx%d", width, height);
    scene_texture_set_image(tex, width, height, chain);
}

static void make_image(struct scene_texture *tex)
{
    uint8_t texels[4 * TW * TH];
    for (int j = 0; j < TH; j++)
        for (int i = 0; i < TW; i++) {
            uint8_t *p = &texels[4 * (j * TW + i)];
            p[0] = (uint8_t)(40 * i + 15);
            p[1] = (uint8_t)(60 * j + 30);
            p[2] = (uint8_t)(5 * i + 7 * j);
            p[3] = 255;
        }
    set_image(tex, TW, TH, texels);
}

static int same(const float a[4], const float b[4], float tol)
{
    for (int k = 0; k < 4; k++)
        if (!(fabsf(a[k] - b[k]) <= tol))
            return 0;
    return 1;
}

static void sample(const struct scene_texture *tex, enum scene_texture_filter f, float s,
                   float t, float out[4])
{
    scene_texture_sample(tex, f, s, t, out);
}

static void centres(struct scene_texture *tex)
{
    for (int wrap = 0; wrap < 2; wrap++) {
        tex->wrap_s = tex->wrap_t = wrap ? SCENE_WRAP_CLAMP_TO_EDGE : SCENE_WRAP_REPEAT;
        for (int j = 0; j < TH; j++)
            for (int i = 0; i < TW; i++) {
                float s = ((float)i + 0.5f) / TW, t = ((float)j + 0.5f) / TH, e[4], c[4];
                texel_value(i, j, e);
                sample(tex, SCENE_FILTER_NEAREST, s, t, c);
                failures += !CHECKF(same(c, e, 0.0f), "NEAREST centre of texel (%d, %d), wrap %d", i, j, wrap);
                sample(tex, SCENE_FILTER_LINEAR, s, t, c);
                failures += !CHECKF(same(c, e, 1e-6f), "LINEAR centre of texel (%d, %d), wrap %d", i, j, wrap);
                /* Anywhere inside the texel's square, NEAREST gives it. */
                sample(tex, SCENE_FILTER_NEAREST, ((float)i + 0.99f) / TW,
                       ((float)j + 0.01f) / TH, c);
                failures += !CHECKF(same(c, e, 0.0f), "NEAREST inside texel (%d, %d)", i, j);
            }
    }
}

static void bilinear(struct scene_texture *tex)
{
    float c[4], a[4], b[4], e[4];
    tex->wrap_s = tex->wrap_t = SCENE_WRAP_REPEAT;
    /* Halfway between the centres of texels (1, 1) and (2, 1): s = 2/4. */
    sample(tex, SCENE_FILTER_LINEAR, 0.5f, 1.5f / TH, c);
    texel_value(1, 1, a);
    texel_value(2, 1, b);
    for (int k = 0; k < 4; k++)
        e[k] = 0.5f * a[k] + 0.5f * b[k];
    failures += !CHECKF(same(c, e, 1e-6f), "LINEAR halfway in s");
    /* At s = 0 with REPEAT: halfway between texel 3 and texel 0. */
    sample(tex, SCENE_FILTER_LINEAR, 0.0f, 0.5f / TH, c);
    texel_value(3, 0, a);
    texel_value(0, 0, b);
    for (int k = 0; k < 4; k++)
        e[k] = 0.5f * a[k] + 0.5f * b[k];
    failures += !CHECKF(same(c, e, 1e-6f), "LINEAR REPEAT across the edge");
    /* With CLAMP_TO_EDGE: texel 0. */
    tex->wrap_s = SCENE_WRAP_CLAMP_TO_EDGE;
    sample(tex, SCENE_FILTER_LINEAR, 0.0f, 0.5f / TH, c);
    failures += !CHECKF(same(c, b, 1e-6f), "LINEAR CLAMP at the edge");
    sample(tex, SCENE_FILTER_LINEAR, -5.0f, 0.5f / TH, c);
    failures += !CHECKF(same(c, b, 1e-6f), "LINEAR CLAMP beyond the edge");
    texel_value(3, 0, a);
    sample(tex, SCENE_FILTER_LINEAR, 7.0f, 0.5f / TH, c);
    failures += !CHECKF(same(c, a, 1e-6f), "LINEAR CLAMP beyond the far edge");
    /* A quarter of the way from the centre of (0, 0) to (1, 1) in both:
     * weights 9/16, 3/16, 3/16, 1/16. */
    tex->wrap_s = SCENE_WRAP_REPEAT;
    sample(tex, SCENE_FILTER_LINEAR, 0.75f / TW, 0.75f / TH, c);
    float c00[4], c10[4], c01[4], c11[4];
    texel_value(0, 0, c00);
    texel_value(1, 0, c10);
    texel_value(0, 1, c01);
    texel_value(1, 1, c11);
    for (int k = 0; k < 4; k++)
        e[k] = (9.0f * c00[k] + 3.0f * c10[k] + 3.0f * c01[k] + c11[k]) / 16.0f;
    failures += !CHECKF(same(c, e, 1e-6f), "LINEAR weights 9/16, 3/16, 3/16, 1/16");
}

static void repeat_and_non_finite(struct scene_texture *tex)
{
    const float nan = nanf(""), inf = INFINITY;
    float c[4], e[4];
    for (int f = 0; f < 2; f++) {
        enum scene_texture_filter filter = f ? SCENE_FILTER_LINEAR : SCENE_FILTER_NEAREST;
        tex->wrap_s = tex->wrap_t = SCENE_WRAP_REPEAT;
        /* -196.25 repeats to 0.75 exactly, 1e7 and 1e30 to 0. */
        sample(tex, filter, 0.75f, 0.3f, e);
        sample(tex, filter, -196.25f, 0.3f, c);
        failures += !CHECKF(memcmp(c, e, sizeof(c)) == 0, "-196.25 is not 0.75 (filter %d)", f);
        sample(tex, filter, 0.0f, 0.3f, e);
        sample(tex, filter, 1e7f, 0.3f, c);
        failures += !CHECKF(memcmp(c, e, sizeof(c)) == 0, "1e7 is not 0 (filter %d)", f);
        sample(tex, filter, -1e30f, 0.3f, c);
        failures += !CHECKF(memcmp(c, e, sizeof(c)) == 0, "-1e30 is not 0 (filter %d)", f);
        /* NaN and infinities are taken as 0. */
        sample(tex, filter, nan, 0.3f, c);
        failures += !CHECKF(memcmp(c, e, sizeof(c)) == 0, "NaN is not 0 (filter %d)", f);
        sample(tex, filter, inf, 0.3f, c);
        failures += !CHECKF(memcmp(c, e, sizeof(c)) == 0, "inf is not 0 (filter %d)", f);
        sample(tex, filter, -inf, 0.3f, c);
        failures += !CHECKF(memcmp(c, e, sizeof(c)) == 0, "-inf is not 0 (filter %d)", f);
        tex->wrap_s = tex->wrap_t = SCENE_WRAP_CLAMP_TO_EDGE;
        sample(tex, filter, 0.0f, 0.0f, e);
        sample(tex, filter, nan, nan, c);
        failures += !CHECKF(memcmp(c, e, sizeof(c)) == 0, "CLAMP: NaN is not 0 (filter %d)", f);
    }
    /* A tiny negative s is just below 1: the last texel, not the first. */
    tex->wrap_s = tex->wrap_t = SCENE_WRAP_REPEAT;
    texel_value(TW - 1, 0, e);
    sample(tex, SCENE_FILTER_NEAREST, -1e-30f, 0.1f, c);
    failures += !CHECKF(same(c, e, 0.0f), "s = -1e-30 is not in the last texel");
    sample(tex, SCENE_FILTER_NEAREST, -1e-45f, 0.1f, c);
    failures += !CHECKF(same(c, e, 0.0f), "s = -1e-45 is not in the last texel");
    /* s = 1 is s = 0 under REPEAT and the last texel under CLAMP. */
    texel_value(0, 0, e);
    sample(tex, SCENE_FILTER_NEAREST, 1.0f, 0.1f, c);
    failures += !CHECKF(same(c, e, 0.0f), "REPEAT: s = 1 is not texel 0");
    tex->wrap_s = SCENE_WRAP_CLAMP_TO_EDGE;
    texel_value(TW - 1, 0, e);
    sample(tex, SCENE_FILTER_NEAREST, 1.0f, 0.1f, c);
    failures += !CHECKF(same(c, e, 0.0f), "CLAMP: s = 1 is not the last texel");
}

/* Every float bit pattern class, many times: the sample stays in range
 * (AddressSanitizer catches a read outside the image). */
static void any_float(struct scene_texture *tex)
{
    uint32_t x = 2463534242u;
    for (int n = 0; n < 400000; n++) {
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        uint32_t y = x * 2654435761u;
        float s, t, c[4];
        memcpy(&s, &x, sizeof(s));
        memcpy(&t, &y, sizeof(t));
        tex->wrap_s = (n & 1) ? SCENE_WRAP_CLAMP_TO_EDGE : SCENE_WRAP_REPEAT;
        tex->wrap_t = (n & 2) ? SCENE_WRAP_CLAMP_TO_EDGE : SCENE_WRAP_REPEAT;
        sample(tex, (n & 4) ? SCENE_FILTER_LINEAR : SCENE_FILTER_NEAREST, s, t, c);
        for (int k = 0; k < 4; k++)
            if (!(c[k] >= 0.0f && c[k] <= 1.0f + 1e-6f)) {
                failures += !CHECKF(0, "sample at (%g, %g) gave %g", (double)s, (double)t, (double)c[k]);
                return;
            }
        /* Any level of detail, with every minification filter: the bits
         * of s reused as lambda cover NaN, infinities and huge values. */
        tex->min_filter = (enum scene_texture_filter)(n % 6);
        tex->mag_filter = (n & 8) ? SCENE_FILTER_LINEAR : SCENE_FILTER_NEAREST;
        float lambda = (n & 16) ? s : (float)(y % 2000) / 100.0f - 5.0f;
        scene_texture_sample_lod(tex, lambda, t, s, c);
        for (int k = 0; k < 4; k++)
            if (!(c[k] >= 0.0f && c[k] <= 1.0f + 1e-6f)) {
                failures += !CHECKF(0, "sample at lambda %g gave %g", (double)lambda, (double)c[k]);
                return;
            }
    }
}

/* ---- mip chains --------------------------------------------------------------- */

static void chain_sizes(void)
{
    /* max(1, floor(n / 2)) per level down to 1x1, as GL 2.0 sizes them. */
    static const int kitchen[][2] = {{1044, 1044}, {522, 522}, {261, 261}, {130, 130},
                                     {65, 65},     {32, 32},   {16, 16},   {8, 8},
                                     {4, 4},       {2, 2},     {1, 1}};
    static const int wood[][2] = {{128, 256}, {64, 128}, {32, 64}, {16, 32}, {8, 16},
                                  {4, 8},     {2, 4},    {1, 2},   {1, 1}};
    static const int odd[][2] = {{5, 3}, {2, 1}, {1, 1}};
    static const struct {
        const int (*sizes)[2];
        int count;
    } cases[] = {{kitchen, 11}, {wood, 9}, {odd, 3}};
    failures += !CHECKF(scene_texture_level_count(1, 1) == 1, "1x1 has one level");
    failures += !CHECKF(scene_texture_chain_texels(1, 1) == 1, "1x1 chain");
    failures += !CHECKF(scene_texture_level_count(16384, 16384) == SCENE_TEXTURE_MAX_LEVELS, "16384 levels");
    failures += !CHECKF(scene_texture_level_count(16384, 1) == SCENE_TEXTURE_MAX_LEVELS, "16384x1 levels");
    failures += !CHECKF(scene_texture_level_count(1, 3) == 2, "1x3 levels");
    /* 4/3 of level 0 at most: 64x64 adds 32^2 + ... + 1 = 1365. */
    failures += !CHECKF(scene_texture_chain_texels(64, 64) == 4096 + 1365, "64x64 chain");
    failures += !CHECKF(scene_texture_chain_texels(1044, 1044) <= 1044u * 1044u * 4 / 3, "1044 chain");
    for (int c = 0; c < 3; c++) {
        const int w = cases[c].sizes[0][0], h = cases[c].sizes[0][1];
        failures += !CHECKF(scene_texture_level_count(w, h) == cases[c].count, "%dx%d: %d levels", w, h,
               scene_texture_level_count(w, h));
        size_t total = 0;
        for (int k = 0; k < cases[c].count; k++)
            total += (size_t)cases[c].sizes[k][0] * (size_t)cases[c].sizes[k][1];
        failures += !CHECKF(scene_texture_chain_texels(w, h) == total, "%dx%d: chain of %zu texels", w, h,
               scene_texture_chain_texels(w, h));
        /* The level table of a texture with that image. */
        struct scene_texture tex;
        memset(&tex, 0, sizeof(tex));
        uint8_t *chain = rt_calloc(scene_texture_chain_texels(w, h), 4);
        if (!chain) {
            failures += !CHECKF(0, "no memory");
            return;
        }
        failures += !CHECKF(scene_texture_build_mipmaps(chain, w, h) == 0, "build %dx%d", w, h);
        scene_texture_set_image(&tex, w, h, chain);
        failures += !CHECKF(tex.level_count == cases[c].count, "%dx%d: level_count %d", w, h,
               tex.level_count);
        size_t offset = 0;
        for (int k = 0; k < cases[c].count && k < tex.level_count; k++) {
            failures += !CHECKF(tex.levels[k].width == cases[c].sizes[k][0] &&
                       tex.levels[k].height == cases[c].sizes[k][1] &&
                       tex.levels[k].texels == chain + 4 * offset,
                   "%dx%d: level %d is %dx%d", w, h, k, tex.levels[k].width,
                   tex.levels[k].height);
            offset += (size_t)cases[c].sizes[k][0] * (size_t)cases[c].sizes[k][1];
        }
        rt_free(tex.texels);
    }
    /* A failed build allocates nothing and leaves level 0 alone; a 1x1
     * image needs no working memory at all. */
    uint8_t chain[4 * (64 + 16 + 4 + 1)];
    memset(chain, 7, sizeof(chain));
    rt_alloc_fail_after(0);
    int r8 = scene_texture_build_mipmaps(chain, 8, 8);
    int r1 = scene_texture_build_mipmaps(chain, 1, 1);
    rt_alloc_fail_reset();
    failures += !CHECKF(r8 == -1, "a build without memory succeeded");
    failures += !CHECKF(r1 == 0, "a 1x1 build needed memory");
    for (int i = 0; i < 4 * 64; i++)
        if (chain[i] != 7) {
            failures += !CHECKF(0, "a failed build wrote level 0");
            break;
        }
}

/* The 5x3 image of chain_texels: red values below, green 255 - red, blue
 * 77, alpha 255.  Rows from t = 0. */
static const uint8_t odd_red[3][5] = {
    {10, 200, 30, 90, 255}, {0, 100, 50, 250, 20}, {60, 70, 80, 5, 140}};

static void chain_texels(void)
{
    uint8_t chain[4 * (15 + 2 + 1)];
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 5; i++) {
            uint8_t *p = &chain[4 * (j * 5 + i)];
            p[0] = odd_red[j][i];
            p[1] = (uint8_t)(255 - odd_red[j][i]);
            p[2] = 77;
            p[3] = 255;
        }
    failures += !CHECKF(scene_texture_build_mipmaps(chain, 5, 3) == 0, "build 5x3");
    const uint8_t *l1 = &chain[4 * 15], *l2 = &chain[4 * 17];
    /* Level 1 is 2x1.  Its texel 0 covers columns [0, 2.5) of level 0:
     * weights 2/5, 2/5, 1/5 on columns 0, 1, 2, and 1/3 on each row:
     *   red = (2*10 + 2*200 + 30  +  2*0 + 2*100 + 50  +  2*60 + 2*70 + 80) / 15
     *       = (450 + 250 + 340) / 15 = 1040 / 15 = 69.33 -> 69,
     * green = 255 - 69.33 = 185.67 -> 186.  Texel 1 covers [2.5, 5):
     * weights 1/5, 2/5, 2/5 on columns 2, 3, 4:
     *   red = (720 + 590 + 370) / 15 = 112, green 143. */
    failures += !CHECKF(l1[0] == 69 && l1[1] == 186 && l1[2] == 77 && l1[3] == 255,
           "level 1 texel 0 is (%d, %d, %d, %d)", l1[0], l1[1], l1[2], l1[3]);
    failures += !CHECKF(l1[4] == 112 && l1[5] == 143 && l1[6] == 77 && l1[7] == 255,
           "level 1 texel 1 is (%d, %d, %d, %d)", l1[4], l1[5], l1[6], l1[7]);
    /* Level 2, 1x1: the mean of the 15 texels, red 1360 / 15 = 90.67 ->
     * 91, green 164.33 -> 164.  (From the rounded level 1, (69 + 112) / 2
     * = 90.5 would not be the mean: levels are made from unrounded ones.) */
    failures += !CHECKF(l2[0] == 91 && l2[1] == 164 && l2[2] == 77 && l2[3] == 255,
           "level 2 is (%d, %d, %d, %d)", l2[0], l2[1], l2[2], l2[3]);
    /* Level 0 is untouched. */
    failures += !CHECKF(chain[0] == 10 && chain[4 * 14] == 140, "level 0 changed");
}

/* A large odd-sized image of noise: its 1x1 level is its mean. */
static void chain_mean_large(void)
{
    const int w = 1043, h = 517;
    uint8_t *chain = rt_malloc(4 * scene_texture_chain_texels(w, h));
    if (!chain) {
        failures += !CHECKF(0, "no memory");
        return;
    }
    uint32_t x = 88172645u;
    double sum[4] = {0, 0, 0, 0};
    for (size_t i = 0; i < 4 * (size_t)w * (size_t)h; i++) {
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        chain[i] = (uint8_t)((i % 4 == 3) ? 255 : (x >> 24) / (1 + i % 4));
        sum[i % 4] += chain[i];
    }
    failures += !CHECKF(scene_texture_build_mipmaps(chain, w, h) == 0, "build %dx%d", w, h);
    const uint8_t *last = &chain[4 * (scene_texture_chain_texels(w, h) - 1)];
    for (int c = 0; c < 4; c++) {
        double mean = sum[c] / ((double)w * h);
        failures += !CHECKF(fabs(last[c] - mean) <= 0.5 + 1e-3, "1x1 channel %d is %d, mean %.4f", c, last[c],
               mean);
    }
    rt_free(chain);
}

static void level_selection(void)
{
    struct scene_texture tex;
    memset(&tex, 0, sizeof(tex));
    uint8_t level0[4 * 15];
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 5; i++) {
            uint8_t *p = &level0[4 * (j * 5 + i)];
            p[0] = odd_red[j][i];
            p[1] = (uint8_t)(255 - odd_red[j][i]);
            p[2] = 77;
            p[3] = 255;
        }
    set_image(&tex, 5, 3, level0);
    tex.wrap_s = tex.wrap_t = SCENE_WRAP_REPEAT;
    /* (0.3, 0.4): between texel centres at every level, so NEAREST and
     * LINEAR differ on levels 0 and 1. */
    const float s = 0.3f, t = 0.4f;
    float lv[3][2][4], c[4];
    for (int k = 0; k < 3; k++)
        for (int f = 0; f < 2; f++)
            scene_texture_sample_level(&tex, k, f ? SCENE_FILTER_LINEAR : SCENE_FILTER_NEAREST,
                                       s, t, lv[k][f]);
    failures += !CHECKF(!same(lv[0][0], lv[0][1], 1e-3f) && !same(lv[1][0], lv[1][1], 1e-3f) &&
               !same(lv[0][1], lv[1][1], 1e-3f) && !same(lv[1][1], lv[2][1], 1e-3f),
           "the test point does not tell levels and filters apart");
    static const struct {
        enum scene_texture_filter min, mag;
        float lambda;
        int level, linear; /* the expected single lookup */
    } single[] = {
        /* Magnification: lambda <= c, level 0 with the MAG filter. */
        {SCENE_FILTER_LINEAR_MIPMAP_LINEAR, SCENE_FILTER_NEAREST, 0.0f, 0, 0},
        {SCENE_FILTER_LINEAR_MIPMAP_LINEAR, SCENE_FILTER_NEAREST, -INFINITY, 0, 0},
        {SCENE_FILTER_NEAREST_MIPMAP_NEAREST, SCENE_FILTER_LINEAR, -3.0f, 0, 1},
        /* c = 0.5 for LINEAR magnification with NEAREST_MIPMAP_*: still a
         * magnification at 0.4; with NEAREST magnification c = 0 and the
         * minification filter takes level 0 (lambda <= 1/2) with NEAREST. */
        {SCENE_FILTER_NEAREST_MIPMAP_NEAREST, SCENE_FILTER_LINEAR, 0.4f, 0, 1},
        {SCENE_FILTER_NEAREST_MIPMAP_LINEAR, SCENE_FILTER_LINEAR, 0.5f, 0, 1},
        {SCENE_FILTER_NEAREST_MIPMAP_NEAREST, SCENE_FILTER_NEAREST, 0.4f, 0, 0},
        /* LINEAR_MIPMAP_NEAREST keeps c = 0: minification at 0.4. */
        {SCENE_FILTER_LINEAR_MIPMAP_NEAREST, SCENE_FILTER_NEAREST, 0.4f, 0, 1},
        /* The nearest level: d = ceil(lambda + 1/2) - 1, q = 2 beyond. */
        {SCENE_FILTER_LINEAR_MIPMAP_NEAREST, SCENE_FILTER_NEAREST, 0.5f, 0, 1},
        {SCENE_FILTER_LINEAR_MIPMAP_NEAREST, SCENE_FILTER_NEAREST, 0.51f, 1, 1},
        {SCENE_FILTER_LINEAR_MIPMAP_NEAREST, SCENE_FILTER_NEAREST, 1.5f, 1, 1},
        {SCENE_FILTER_NEAREST_MIPMAP_NEAREST, SCENE_FILTER_NEAREST, 1.51f, 2, 0},
        {SCENE_FILTER_NEAREST_MIPMAP_NEAREST, SCENE_FILTER_NEAREST, 1e30f, 2, 0},
        {SCENE_FILTER_LINEAR_MIPMAP_NEAREST, SCENE_FILTER_NEAREST, INFINITY, 2, 1},
        /* *_MIPMAP_LINEAR at whole lambdas and from q on: one level. */
        {SCENE_FILTER_LINEAR_MIPMAP_LINEAR, SCENE_FILTER_LINEAR, 1.0f, 1, 1},
        {SCENE_FILTER_NEAREST_MIPMAP_LINEAR, SCENE_FILTER_NEAREST, 2.0f, 2, 0},
        {SCENE_FILTER_LINEAR_MIPMAP_LINEAR, SCENE_FILTER_NEAREST, 40.0f, 2, 1},
        /* Non-mipmapped minification: level 0 whatever lambda. */
        {SCENE_FILTER_NEAREST, SCENE_FILTER_LINEAR, 3.0f, 0, 0},
        {SCENE_FILTER_LINEAR, SCENE_FILTER_NEAREST, 3.0f, 0, 1},
        {SCENE_FILTER_LINEAR, SCENE_FILTER_NEAREST, -3.0f, 0, 0},
    };
    for (size_t n = 0; n < sizeof(single) / sizeof(single[0]); n++) {
        tex.min_filter = single[n].min;
        tex.mag_filter = single[n].mag;
        scene_texture_sample_lod(&tex, single[n].lambda, s, t, c);
        failures += !CHECKF(same(c, lv[single[n].level][single[n].linear], 0.0f),
               "case %zu (lambda %g): not level %d %s", n, (double)single[n].lambda,
               single[n].level, single[n].linear ? "LINEAR" : "NEAREST");
    }
    /* A NaN lambda is a magnification. */
    tex.min_filter = SCENE_FILTER_LINEAR_MIPMAP_LINEAR;
    tex.mag_filter = SCENE_FILTER_NEAREST;
    scene_texture_sample_lod(&tex, nanf(""), s, t, c);
    failures += !CHECKF(same(c, lv[0][0], 0.0f), "NaN lambda is not a magnification");
    /* Between levels: (1 - frac) of d1 plus frac of d1 + 1. */
    static const float lambdas[] = {0.25f, 1.25f, 1.875f};
    for (int f = 0; f < 2; f++) {
        tex.min_filter = f ? SCENE_FILTER_LINEAR_MIPMAP_LINEAR : SCENE_FILTER_NEAREST_MIPMAP_LINEAR;
        for (int n = 0; n < 3; n++) {
            const float lambda = lambdas[n], fr = lambda - floorf(lambda);
            const int d1 = (int)lambda;
            float e[4];
            for (int k = 0; k < 4; k++)
                e[k] = (1.0f - fr) * lv[d1][f][k] + fr * lv[d1 + 1][f][k];
            scene_texture_sample_lod(&tex, lambda, s, t, c);
            failures += !CHECKF(same(c, e, 1e-6f), "MIPMAP_LINEAR (%d) at lambda %g", f, (double)lambda);
        }
    }
    rt_free(tex.texels);
}

static void table(void)
{
    struct scene_textures tab;
    scene_textures_init(&tab);
    failures += !CHECKF(scene_textures_lookup(&tab, 0) == NULL, "lookup(0) in an empty table");
    failures += !CHECKF(scene_textures_lookup(&tab, 5) == NULL, "lookup(5) in an empty table");
    failures += !CHECKF(scene_textures_get_or_create(&tab, 0) == NULL, "0 is not a texture name");
    /* Names that collide in a small table, inserted and removed in turn. */
    for (uint32_t i = 1; i <= 2000; i++) {
        struct scene_texture *tex = scene_textures_get_or_create(&tab, i * 16u);
        failures += !CHECKF(tex && tex->name == i * 16u, "create %u", i * 16u);
        failures += !CHECKF(tex && tex->min_filter == SCENE_FILTER_LINEAR &&
                   tex->mag_filter == SCENE_FILTER_LINEAR && tex->wrap_s == SCENE_WRAP_REPEAT &&
                   tex->wrap_t == SCENE_WRAP_REPEAT && !tex->texels && !tex->created,
               "defaults of %u", i * 16u);
    }
    for (uint32_t i = 1; i <= 2000; i += 2)
        scene_textures_remove(&tab, i * 16u);
    scene_textures_remove(&tab, 0);
    scene_textures_remove(&tab, 7);
    for (uint32_t i = 1; i <= 2000; i++) {
        struct scene_texture *tex = scene_textures_lookup(&tab, i * 16u);
        failures += !CHECKF((tex != NULL) == (i % 2 == 0), "lookup %u after removals", i * 16u);
    }
    failures += !CHECKF(tab.table.used == 1000, "used %u", tab.table.used);
    /* Generated names avoid those in use and are distinct. */
    uint32_t names[100];
    failures += !CHECKF(scene_textures_generate(&tab, 100, names) == 0, "generate");
    for (int i = 0; i < 100; i++) {
        failures += !CHECKF(names[i] != 0 && (names[i] % 32 != 0 || names[i] > 32000), "name %u in use",
               names[i]);
        for (int j = 0; j < i; j++)
            failures += !CHECKF(names[i] != names[j], "name %u twice", names[i]);
        failures += !CHECKF(scene_textures_lookup(&tab, names[i]) != NULL, "generated %u not reserved",
               names[i]);
    }
    /* A failed generation reserves and writes nothing. */
    uint32_t before = tab.table.used, out[3] = {7, 7, 7};
    rt_alloc_fail_after(0);
    int r = scene_textures_generate(&tab, 3, out);
    rt_alloc_fail_reset();
    failures += !CHECKF(r == -1 && tab.table.used == before && out[0] == 7 && out[1] == 7 && out[2] == 7,
           "failed generate changed something");
    scene_textures_release(&tab);
    failures += !CHECKF(tab.table.capacity == 0 && tab.table.used == 0, "release");
}

/*
 * The sampler as it was written before its look-up table and division-free
 * index wrapping (floor from the library, the remainder of a division, the
 * division by 255 per channel): the sampler must give its values bit for
 * bit, since every image hash depends on them.
 */
static double ref_reduce(float s, enum scene_texture_wrap wrap)
{
    double d = isfinite(s) ? (double)s : 0.0;
    if (wrap == SCENE_WRAP_REPEAT) {
        double f = d - floor(d);
        return f < 1.0 ? f : 0x1.fffffffffffffp-1;
    }
    return fmin(fmax(d, -1.0), 2.0);
}

static int ref_wrap(long i, int n, enum scene_texture_wrap wrap)
{
    if (wrap == SCENE_WRAP_REPEAT) {
        i %= n;
        return (int)(i < 0 ? i + n : i);
    }
    return i < 0 ? 0 : i >= n ? n - 1 : (int)i;
}

static void ref_texel(const struct scene_texture_level *lv, int i, int j, float rgba[4])
{
    const uint8_t *p = &lv->texels[4 * ((size_t)j * (size_t)lv->width + (size_t)i)];
    for (int k = 0; k < 4; k++)
        rgba[k] = (float)p[k] / 255.0f;
}

static void ref_sample_level(const struct scene_texture *tex, int level, int linear, float s,
                             float t, float rgba[4])
{
    const struct scene_texture_level *lv = &tex->levels[level];
    const int w = lv->width, h = lv->height;
    const double u = ref_reduce(s, tex->wrap_s) * w;
    const double v = ref_reduce(t, tex->wrap_t) * h;
    if (!linear) {
        ref_texel(lv, ref_wrap((long)floor(u), w, tex->wrap_s),
                  ref_wrap((long)floor(v), h, tex->wrap_t), rgba);
        return;
    }
    const double uc = u - 0.5, vc = v - 0.5;
    const double fi = floor(uc), fj = floor(vc);
    const float a = (float)(uc - fi), b = (float)(vc - fj);
    const int i0 = ref_wrap((long)fi, w, tex->wrap_s), i1 = ref_wrap((long)fi + 1, w, tex->wrap_s);
    const int j0 = ref_wrap((long)fj, h, tex->wrap_t), j1 = ref_wrap((long)fj + 1, h, tex->wrap_t);
    float c00[4], c10[4], c01[4], c11[4];
    ref_texel(lv, i0, j0, c00);
    ref_texel(lv, i1, j0, c10);
    ref_texel(lv, i0, j1, c01);
    ref_texel(lv, i1, j1, c11);
    for (int k = 0; k < 4; k++) {
        float bottom = c00[k] + a * (c10[k] - c00[k]);
        float top = c01[k] + a * (c11[k] - c01[k]);
        rgba[k] = bottom + b * (top - bottom);
    }
}

/* Every byte value in a 7 x 37 image (odd sizes, all 256 values in each
 * channel), every level, both filters and wraps, trilinear between
 * levels, at coordinates on and beside texel edges and centres,
 * negative, large and not finite. */
static void reference_bits(void)
{
    struct scene_textures tab;
    scene_textures_init(&tab);
    struct scene_texture *tex = scene_textures_get_or_create(&tab, 1);
    if (!CHECKF(tex != NULL, "texture")) {
        failures++;
        return;
    }
    enum { RW = 7, RH = 37 };
    uint8_t texels[4 * RW * RH];
    for (int i = 0; i < RW * RH; i++)
        for (int k = 0; k < 4; k++)
            texels[4 * i + k] = (uint8_t)((i + 64 * k) * 3 % 256);
    set_image(tex, RW, RH, texels);
    const float special[] = {0.0f,  -0.0f,     1.0f,      -1.0f,   0.5f,     1e-30f, -1e-30f,
                             1e30f, -1e30f,    3.999999f, -2.5f,   16777216.0f, INFINITY, NAN,
                             1.0f / 7.0f, -1.0f / 37.0f, 0.99999994f, 2.0f, -2.0000002f};
    const int nspecial = (int)(sizeof(special) / sizeof(special[0]));
    unsigned seed = 12345u;
    int bad = 0;
    for (int wrap = 0; wrap < 4; wrap++) {
        tex->wrap_s = (wrap & 1) ? SCENE_WRAP_CLAMP_TO_EDGE : SCENE_WRAP_REPEAT;
        tex->wrap_t = (wrap & 2) ? SCENE_WRAP_CLAMP_TO_EDGE : SCENE_WRAP_REPEAT;
        for (int n = 0; n < 4000; n++) {
            float st[2];
            for (int c = 0; c < 2; c++) {
                seed = seed * 1103515245u + 12345u;
                const unsigned r = seed >> 8;
                if (r % 5 == 0)
                    st[c] = special[r % (unsigned)nspecial];
                else if (r % 5 == 1) /* a texel edge or centre of some level, nudged */
                    st[c] = nextafterf((float)(r % 75) / (2.0f * (c ? RH : RW)),
                                       (r & 1) ? INFINITY : -INFINITY);
                else
                    st[c] = ((float)(r % 100000) / 10000.0f - 5.0f);
            }
            for (int level = 0; level < tex->level_count; level++)
                for (int linear = 0; linear < 2; linear++) {
                    float got[4], want[4];
                    scene_texture_sample_level(tex, level,
                                               linear ? SCENE_FILTER_LINEAR : SCENE_FILTER_NEAREST,
                                               st[0], st[1], got);
                    ref_sample_level(tex, level, linear, st[0], st[1], want);
                    if (memcmp(got, want, sizeof(got)) != 0 && bad++ < 5)
                        CHECKF(0, "level %d %s wrap %d at (%a, %a): %a %a %a %a, want %a %a %a %a",
                               level, linear ? "linear" : "nearest", wrap, st[0], st[1], got[0],
                               got[1], got[2], got[3], want[0], want[1], want[2], want[3]);
                }
            /* Trilinear between each pair of levels (the sampler reduces
             * the coordinates once for both): fine + f (coarse - fine). */
            tex->min_filter = SCENE_FILTER_LINEAR_MIPMAP_LINEAR;
            tex->mag_filter = SCENE_FILTER_LINEAR;
            for (int level = 0; level + 1 < tex->level_count; level++) {
                const float lambda = (float)level + (float)(n % 7 + 1) / 8.0f;
                float got[4], want[4], fine[4], coarse[4];
                scene_texture_sample_lod(tex, lambda, st[0], st[1], got);
                ref_sample_level(tex, level, 1, st[0], st[1], fine);
                ref_sample_level(tex, level + 1, 1, st[0], st[1], coarse);
                const float f = lambda - (float)level;
                for (int k = 0; k < 4; k++)
                    want[k] = fine[k] + f * (coarse[k] - fine[k]);
                if (memcmp(got, want, sizeof(got)) != 0 && bad++ < 5)
                    CHECKF(0, "lambda %a wrap %d at (%a, %a): %a %a %a %a, want %a %a %a %a",
                           lambda, wrap, st[0], st[1], got[0], got[1], got[2], got[3], want[0],
                           want[1], want[2], want[3]);
            }
        }
    }
    failures += bad;
    scene_textures_release(&tab);
}

int main(void)
{
    reference_bits();
    struct scene_textures tab;
    scene_textures_init(&tab);
    struct scene_texture *tex = scene_textures_get_or_create(&tab, 1);
    if (!tex) {
        fprintf(stderr, "cannot create a texture\n");
        return 1;
    }
    make_image(tex);
    centres(tex);
    bilinear(tex);
    repeat_and_non_finite(tex);
    any_float(tex);
    scene_textures_release(&tab);
    chain_sizes();
    chain_texels();
    chain_mean_large();
    level_selection();
    table();
    printf("texture_sample: %s (%d failed checks)\n", failures ? "FAILED" : "passed", failures);
    return failures != 0;
}
