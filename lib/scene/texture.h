/* SPDX-License-Identifier: Apache-2.0 */
/*
 * texture.h - 2D texture objects, their table, their mipmaps and sampling.
 *
 * A texture is named by a non-zero uint32_t, as a GL texture object.  Its
 * image is stored as 8-bit RGBA texels (GL's unsized RGB/RGBA internal
 * formats are 8 bits per component in practice), row 0 first: texel (i, j)
 * of a level w x h is texels[4 * (j * w + i)] and covers s in
 * [i, i+1)/w, t in [j, j+1)/h, so row 0 is t = 0 as in OpenGL (sec. 3.8 of
 * the OpenGL 1.1 specification).  RGB images store alpha 255.
 *
 * Every image carries its complete mip chain, generated from level 0 when
 * the image is set (GL_GENERATE_MIPMAP; levels > 0 cannot be uploaded):
 * level k+1 is max(1, floor(w_k / 2)) x max(1, floor(h_k / 2)), as in
 * OpenGL 2.0 for non-power-of-two sizes, down to 1x1.  The levels lie one
 * after the other in one block, level 0 first; the chain adds at most 1/3
 * to level 0 (a 1044x1044 image, the largest of the BART kitchen, takes
 * 4.4 MB, 5.8 MB with its chain).
 *
 * Threading: the table and the textures change only on the API thread,
 * never while a frame or a query runs; render threads only call
 * scene_textures_lookup and the samplers, which do not write.
 */
#ifndef RT_SCENE_TEXTURE_H
#define RT_SCENE_TEXTURE_H

#include <stddef.h>
#include <stdint.h>

#include "base/name_table.h"

/* Largest width or height, RT_MAX_TEXTURE_SIZE: OpenGL 4.6's minimum for
 * MAX_TEXTURE_SIZE, and the largest viewport (context.h). */
#define SCENE_TEXTURE_MAX_SIZE 16384
/* Levels of the largest chain: 16384 = 2^14 halves 14 times to 1. */
#define SCENE_TEXTURE_MAX_LEVELS 15

/* GL's filters.  The first two filter within one level and are the only
 * magnification filters; the mipmapped ones (minification only) choose
 * levels by the level of detail, then filter within a level with NEAREST
 * (NEAREST_MIPMAP_*) or LINEAR (LINEAR_MIPMAP_*). */
enum scene_texture_filter {
    SCENE_FILTER_NEAREST,
    SCENE_FILTER_LINEAR,
    SCENE_FILTER_NEAREST_MIPMAP_NEAREST,
    SCENE_FILTER_LINEAR_MIPMAP_NEAREST,
    SCENE_FILTER_NEAREST_MIPMAP_LINEAR,
    SCENE_FILTER_LINEAR_MIPMAP_LINEAR
};
enum scene_texture_wrap { SCENE_WRAP_REPEAT, SCENE_WRAP_CLAMP_TO_EDGE };

/* One level of a mip chain: its size and its texels inside the chain. */
struct scene_texture_level {
    int width;
    int height;
    const uint8_t *texels; /* 4 * width * height bytes, RGBA */
};

struct scene_texture {
    uint32_t name;
    int created;   /* bound at least once (rtIsTexture); 0: only a reserved name */
    int width;     /* of level 0; 0 while there is no image */
    int height;
    uint8_t *texels; /* the chain, level 0 first (4 bytes a texel); NULL while no image */
    int level_count; /* levels in the chain, down to 1x1; 0 while there is no image */
    struct scene_texture_level levels[SCENE_TEXTURE_MAX_LEVELS];
    enum scene_texture_filter min_filter;
    enum scene_texture_filter mag_filter;
    enum scene_texture_wrap wrap_s;
    enum scene_texture_wrap wrap_t;
    int opaque; /* internal format RGB: alpha 255 whatever the data (rtTexSubImage2D) */
};

struct scene_textures {
    struct name_table table; /* name -> struct scene_texture (created or reserved) */
};

void scene_textures_init(struct scene_textures *table);
/* Frees every texture and its image; leaves an empty table. */
void scene_textures_release(struct scene_textures *table);

/* The entry for name, or NULL (always NULL for 0).  Reserved names that
 * were never bound have an entry with created == 0. */
struct scene_texture *scene_textures_lookup(const struct scene_textures *table, uint32_t name);

/* The entry for name (non-zero), created without an image and with the
 * default parameters if absent; NULL on allocation failure, leaving the
 * table unchanged. */
struct scene_texture *scene_textures_get_or_create(struct scene_textures *table, uint32_t name);

/* Writes n unused names and reserves each.  Returns 0, or -1 on allocation
 * failure having reserved and written nothing. */
int scene_textures_generate(struct scene_textures *table, uint32_t n, uint32_t *names);

/* Removes and frees the entry for name; no-op for 0 or an unknown name. */
void scene_textures_remove(struct scene_textures *table, uint32_t name);

/* Levels of the chain of a width x height image (1 .. SCENE_TEXTURE_MAX_LEVELS
 * for sizes 1 .. SCENE_TEXTURE_MAX_SIZE): 1 + floor(log2(max(width, height))). */
int scene_texture_level_count(int width, int height);

/* Texels in a width x height image and all its levels, the size of the
 * block scene_texture_set_image takes (in units of 4 bytes). */
size_t scene_texture_chain_texels(int width, int height);

/*
 * Fills levels 1 .. of the chain `chain` (scene_texture_chain_texels(width,
 * height) texels) from its level 0, the first width * height texels.  Each
 * level is the previous one filtered by the area-weighted box (polyphase
 * box, see texture.c), so odd sizes are filtered properly and each level's
 * mean is the mean of level 0 up to the final rounding to 8 bits.  Returns
 * 0, or -1 when the small working buffer cannot be allocated (levels > 0
 * are then unspecified; level 0 is never written).  Sizes 1 ..
 * SCENE_TEXTURE_MAX_SIZE.
 */
int scene_texture_build_mipmaps(uint8_t *chain, int width, int height);

/* Replaces the image of tex by `chain`, a width x height image followed by
 * its mip levels as scene_texture_build_mipmaps leaves them (from
 * rt_malloc; ownership moves), freeing the old one. */
void scene_texture_set_image(struct scene_texture *tex, int width, int height, uint8_t *chain);

/*
 * The colour of level `level` (0 .. level_count - 1) of tex at texture
 * coordinates (s, t), RGBA in [0, 1], filtered within the level as OpenGL
 * 1.1 does (sec. 3.8.1): texel centres at (i + 0.5) / w for a level w
 * texels wide; SCENE_FILTER_NEAREST takes the texel containing the point,
 * SCENE_FILTER_LINEAR blends the four nearest texels bilinearly (a
 * mipmapped filter is taken as its within-level filter); REPEAT uses the
 * fractional part of the coordinate, CLAMP_TO_EDGE never reaches beyond
 * the edge texels.  Total: any float works, however large (u = 1e30 stays
 * in range); a NaN or infinite coordinate is taken as 0.  tex must have an
 * image.
 */
void scene_texture_sample_level(const struct scene_texture *tex, int level,
                                enum scene_texture_filter filter, float s, float t,
                                float rgba[4]);

/* scene_texture_sample_level on level 0. */
void scene_texture_sample(const struct scene_texture *tex, enum scene_texture_filter filter,
                          float s, float t, float rgba[4]);

/*
 * The colour of tex at (s, t) for the level of detail `lambda` (log2 of
 * the level-0 texels a pixel's footprint spans; the caller computes it),
 * as OpenGL 1.1 sec. 3.8.1-3.8.2 chooses filters and levels: lambda <= c
 * is a magnification, level 0 with tex->mag_filter, where c is 0.5 when
 * the magnification filter is LINEAR and the minification filter
 * NEAREST_MIPMAP_NEAREST or NEAREST_MIPMAP_LINEAR, and 0 otherwise;
 * lambda > c uses tex->min_filter: NEAREST and LINEAR on level 0,
 * *_MIPMAP_NEAREST the level nearest to lambda, *_MIPMAP_LINEAR the two
 * levels around it blended by frac(lambda), clamped to the last level.
 * A NaN lambda is taken as a magnification.  tex must have an image.
 */
void scene_texture_sample_lod(const struct scene_texture *tex, float lambda, float s, float t,
                              float rgba[4]);

#if defined(__AVX2__) && !defined(RT_NO_SIMD)
/*
 * scene_texture_sample_lod of eight lookups on one texture in the AVX2
 * lanes (the shading's AVX2 copy, render/shade_eye_avx2.c, renames it):
 * rgb[k][i] is channel k (red, green, blue; alpha is not computed) of
 * lookup i at (s[i], t[i]) for lambda[i], the same floats bit for bit.
 * Returns 0, having written nothing, when it does not take the block: a
 * texture other than LINEAR_MIPMAP_LINEAR minified and LINEAR magnified,
 * or a coordinate of 2^31 or more in magnitude.
 */
int scene_texture_sample_lod8(const struct scene_texture *tex, const float lambda[8],
                              const float s[8], const float t[8], float rgb[3][8]);

/* scene_texture_sample_lod8 in two steps, so that a caller can give the
 * core other work while the texels come into the cache (render/render.c's
 * pipeline of blocks): what decides the loads, their addresses kept and
 * their cache lines asked for (scene_texture_prefetch_lod8), then the
 * loads and the blends (scene_texture_finish_lod8).  The texels' offsets
 * and the weights are kept as they were computed (int32 offsets, float
 * weights), so the two give sample_lod8's floats bit for bit. */
struct scene_texture_lookup8 {
    const struct scene_texture *tex;
    /* The texels' byte offsets from level 0's first texel: level (fine,
     * coarse), corner (00, 10, 01, 11), lane. */
    int32_t offset[2][4][8];
    float a[2][8], b[2][8]; /* a level's horizontal and vertical weights */
    float f[8];             /* the coarse level's blend weight */
    float two[8];           /* all ones where a lane blends two levels */
    int levels;             /* 2 when a lane blends two levels, else 1 */
};

/* scene_texture_sample_lod8 up to its texel loads into *out, the lines
 * of the block's corner lanes prefetched (a hint: no value is read);
 * returns 0, having written nothing, where sample_lod8 does not take the
 * block. */
int scene_texture_prefetch_lod8(const struct scene_texture *tex, const float lambda[8],
                             const float s[8], const float t[8],
                             struct scene_texture_lookup8 *out);

/* The rest of scene_texture_sample_lod8 from *in: the texels' loads and
 * the blends, sample_lod8's rgb. */
void scene_texture_finish_lod8(const struct scene_texture_lookup8 *in, float rgb[3][8]);
#endif

#endif
