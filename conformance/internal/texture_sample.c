/*
 * texture_sample.c - the texture table and sampler of scene/texture.h,
 * directly: the values a sample must give (texel centres, bilinear
 * weights, REPEAT and CLAMP_TO_EDGE at and beyond the edges), that any
 * float coordinate (NaN, infinities, 1e30, tiny negatives) stays inside the
 * image, and that the table finds every name after insertions and
 * backward-shift deletions.
 *
 * Internal test (links the static library).  Non-zero exit on failure.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/alloc.h"
#include "scene/texture.h"

static int failures;

#define EXPECT(cond, ...)                                                                          \
    do {                                                                                           \
        if (!(cond)) {                                                                             \
            if (failures++ < 20) {                                                                 \
                fprintf(stderr, "%s:%d: ", __FILE__, __LINE__);                                    \
                fprintf(stderr, __VA_ARGS__);                                                      \
                fprintf(stderr, "\n");                                                             \
            }                                                                                      \
        }                                                                                          \
    } while (0)

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

static void make_image(struct scene_texture *tex)
{
    uint8_t *texels = rt_malloc(4 * TW * TH);
    for (int j = 0; j < TH; j++)
        for (int i = 0; i < TW; i++) {
            uint8_t *p = &texels[4 * (j * TW + i)];
            p[0] = (uint8_t)(40 * i + 15);
            p[1] = (uint8_t)(60 * j + 30);
            p[2] = (uint8_t)(5 * i + 7 * j);
            p[3] = 255;
        }
    scene_texture_set_image(tex, TW, TH, texels);
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
                EXPECT(same(c, e, 0.0f), "NEAREST centre of texel (%d, %d), wrap %d", i, j, wrap);
                sample(tex, SCENE_FILTER_LINEAR, s, t, c);
                EXPECT(same(c, e, 1e-6f), "LINEAR centre of texel (%d, %d), wrap %d", i, j, wrap);
                /* Anywhere inside the texel's square, NEAREST gives it. */
                sample(tex, SCENE_FILTER_NEAREST, ((float)i + 0.99f) / TW,
                       ((float)j + 0.01f) / TH, c);
                EXPECT(same(c, e, 0.0f), "NEAREST inside texel (%d, %d)", i, j);
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
    EXPECT(same(c, e, 1e-6f), "LINEAR halfway in s");
    /* At s = 0 with REPEAT: halfway between texel 3 and texel 0. */
    sample(tex, SCENE_FILTER_LINEAR, 0.0f, 0.5f / TH, c);
    texel_value(3, 0, a);
    texel_value(0, 0, b);
    for (int k = 0; k < 4; k++)
        e[k] = 0.5f * a[k] + 0.5f * b[k];
    EXPECT(same(c, e, 1e-6f), "LINEAR REPEAT across the edge");
    /* With CLAMP_TO_EDGE: texel 0. */
    tex->wrap_s = SCENE_WRAP_CLAMP_TO_EDGE;
    sample(tex, SCENE_FILTER_LINEAR, 0.0f, 0.5f / TH, c);
    EXPECT(same(c, b, 1e-6f), "LINEAR CLAMP at the edge");
    sample(tex, SCENE_FILTER_LINEAR, -5.0f, 0.5f / TH, c);
    EXPECT(same(c, b, 1e-6f), "LINEAR CLAMP beyond the edge");
    texel_value(3, 0, a);
    sample(tex, SCENE_FILTER_LINEAR, 7.0f, 0.5f / TH, c);
    EXPECT(same(c, a, 1e-6f), "LINEAR CLAMP beyond the far edge");
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
    EXPECT(same(c, e, 1e-6f), "LINEAR weights 9/16, 3/16, 3/16, 1/16");
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
        EXPECT(memcmp(c, e, sizeof(c)) == 0, "-196.25 is not 0.75 (filter %d)", f);
        sample(tex, filter, 0.0f, 0.3f, e);
        sample(tex, filter, 1e7f, 0.3f, c);
        EXPECT(memcmp(c, e, sizeof(c)) == 0, "1e7 is not 0 (filter %d)", f);
        sample(tex, filter, -1e30f, 0.3f, c);
        EXPECT(memcmp(c, e, sizeof(c)) == 0, "-1e30 is not 0 (filter %d)", f);
        /* NaN and infinities are taken as 0. */
        sample(tex, filter, nan, 0.3f, c);
        EXPECT(memcmp(c, e, sizeof(c)) == 0, "NaN is not 0 (filter %d)", f);
        sample(tex, filter, inf, 0.3f, c);
        EXPECT(memcmp(c, e, sizeof(c)) == 0, "inf is not 0 (filter %d)", f);
        sample(tex, filter, -inf, 0.3f, c);
        EXPECT(memcmp(c, e, sizeof(c)) == 0, "-inf is not 0 (filter %d)", f);
        tex->wrap_s = tex->wrap_t = SCENE_WRAP_CLAMP_TO_EDGE;
        sample(tex, filter, 0.0f, 0.0f, e);
        sample(tex, filter, nan, nan, c);
        EXPECT(memcmp(c, e, sizeof(c)) == 0, "CLAMP: NaN is not 0 (filter %d)", f);
    }
    /* A tiny negative s is just below 1: the last texel, not the first. */
    tex->wrap_s = tex->wrap_t = SCENE_WRAP_REPEAT;
    texel_value(TW - 1, 0, e);
    sample(tex, SCENE_FILTER_NEAREST, -1e-30f, 0.1f, c);
    EXPECT(same(c, e, 0.0f), "s = -1e-30 is not in the last texel");
    sample(tex, SCENE_FILTER_NEAREST, -1e-45f, 0.1f, c);
    EXPECT(same(c, e, 0.0f), "s = -1e-45 is not in the last texel");
    /* s = 1 is s = 0 under REPEAT and the last texel under CLAMP. */
    texel_value(0, 0, e);
    sample(tex, SCENE_FILTER_NEAREST, 1.0f, 0.1f, c);
    EXPECT(same(c, e, 0.0f), "REPEAT: s = 1 is not texel 0");
    tex->wrap_s = SCENE_WRAP_CLAMP_TO_EDGE;
    texel_value(TW - 1, 0, e);
    sample(tex, SCENE_FILTER_NEAREST, 1.0f, 0.1f, c);
    EXPECT(same(c, e, 0.0f), "CLAMP: s = 1 is not the last texel");
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
                EXPECT(0, "sample at (%g, %g) gave %g", (double)s, (double)t, (double)c[k]);
                return;
            }
    }
}

static void table(void)
{
    struct scene_textures tab;
    scene_textures_init(&tab);
    EXPECT(scene_textures_lookup(&tab, 0) == NULL, "lookup(0) in an empty table");
    EXPECT(scene_textures_lookup(&tab, 5) == NULL, "lookup(5) in an empty table");
    EXPECT(scene_textures_get_or_create(&tab, 0) == NULL, "0 is not a texture name");
    /* Names that collide in a small table, inserted and removed in turn. */
    for (uint32_t i = 1; i <= 2000; i++) {
        struct scene_texture *tex = scene_textures_get_or_create(&tab, i * 16u);
        EXPECT(tex && tex->name == i * 16u, "create %u", i * 16u);
        EXPECT(tex && tex->min_filter == SCENE_FILTER_LINEAR &&
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
        EXPECT((tex != NULL) == (i % 2 == 0), "lookup %u after removals", i * 16u);
    }
    EXPECT(tab.used == 1000, "used %u", tab.used);
    /* Generated names avoid those in use and are distinct. */
    uint32_t names[100];
    EXPECT(scene_textures_generate(&tab, 100, names) == 0, "generate");
    for (int i = 0; i < 100; i++) {
        EXPECT(names[i] != 0 && (names[i] % 32 != 0 || names[i] > 32000), "name %u in use",
               names[i]);
        for (int j = 0; j < i; j++)
            EXPECT(names[i] != names[j], "name %u twice", names[i]);
        EXPECT(scene_textures_lookup(&tab, names[i]) != NULL, "generated %u not reserved",
               names[i]);
    }
    /* A failed generation reserves and writes nothing. */
    uint32_t before = tab.used, out[3] = {7, 7, 7};
    rt_alloc_fail_after(0);
    int r = scene_textures_generate(&tab, 3, out);
    rt_alloc_fail_reset();
    EXPECT(r == -1 && tab.used == before && out[0] == 7 && out[1] == 7 && out[2] == 7,
           "failed generate changed something");
    scene_textures_release(&tab);
    EXPECT(tab.capacity == 0 && tab.used == 0, "release");
}

int main(void)
{
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
    table();
    printf("texture_sample: %s (%d failed checks)\n", failures ? "FAILED" : "passed", failures);
    return failures != 0;
}
