/*
 * texture.h - 2D texture objects, their table and sampling.
 *
 * A texture is named by a non-zero uint32_t, as a GL texture object.  Its
 * image is stored as 8-bit RGBA texels (GL's unsized RGB/RGBA internal
 * formats are 8 bits per component in practice), row 0 first: texel (i, j)
 * is texels[4 * (j * width + i)] and covers s in [i, i+1)/width, t in
 * [j, j+1)/height, so row 0 is t = 0 as in OpenGL (sec. 3.8 of the OpenGL
 * 1.1 specification).  RGB images store alpha 255.  A 1044x1044 image, the
 * largest of the BART kitchen, takes 4.4 MB.
 *
 * Threading: the table and the textures change only on the API thread,
 * never while a frame or a query runs; render threads only call
 * scene_textures_lookup and scene_texture_sample, which do not write.
 */
#ifndef RT_SCENE_TEXTURE_H
#define RT_SCENE_TEXTURE_H

#include <stdint.h>

/* Largest width or height, RT_MAX_TEXTURE_SIZE: OpenGL 4.6's minimum for
 * MAX_TEXTURE_SIZE, and the largest viewport (context.h). */
#define SCENE_TEXTURE_MAX_SIZE 16384

enum scene_texture_filter { SCENE_FILTER_NEAREST, SCENE_FILTER_LINEAR };
enum scene_texture_wrap { SCENE_WRAP_REPEAT, SCENE_WRAP_CLAMP_TO_EDGE };

struct scene_texture {
    uint32_t name;
    int created;   /* bound at least once (rtIsTexture); 0: only a reserved name */
    int width;     /* 0 while there is no image */
    int height;
    uint8_t *texels; /* 4 * width * height bytes, RGBA; NULL while there is no image */
    enum scene_texture_filter min_filter;
    enum scene_texture_filter mag_filter;
    enum scene_texture_wrap wrap_s;
    enum scene_texture_wrap wrap_t;
};

struct scene_textures {
    struct scene_texture **slots; /* open addressing on name, NULL = free */
    uint32_t capacity;            /* power of two, or 0 */
    uint32_t used;                /* occupied slots (created or reserved) */
    uint32_t next_name;           /* scene_textures_generate search start */
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

/* Replaces the image of tex by `texels` (4 * width * height bytes from
 * rt_malloc; ownership moves), freeing the old one. */
void scene_texture_set_image(struct scene_texture *tex, int width, int height, uint8_t *texels);

/*
 * The colour of tex at texture coordinates (s, t), RGBA in [0, 1], as an
 * OpenGL 1.1 sampler with no mipmaps (sec. 3.8.5): texel centres at
 * (i + 0.5) / width; RT_NEAREST takes the texel containing the point,
 * RT_LINEAR blends the four nearest texels bilinearly; REPEAT uses the
 * fractional part of the coordinate, CLAMP_TO_EDGE never reaches beyond
 * the edge texels.  `filter` is the filter to use (the caller chooses
 * between tex->min_filter and tex->mag_filter).  Total: any float works,
 * however large (u = 1e30 stays in range); a NaN or infinite coordinate
 * is taken as 0.  tex must have an image.
 */
void scene_texture_sample(const struct scene_texture *tex, enum scene_texture_filter filter,
                          float s, float t, float rgba[4]);

#endif
