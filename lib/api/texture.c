/* SPDX-License-Identifier: Apache-2.0 */
/*
 * texture.c - 2D texture objects as in OpenGL 1.1: rtGenTextures,
 * rtDeleteTextures, rtIsTexture, rtBindTexture, rtTexImage2D and
 * rtTexParameteri.  The table and the sampler are scene/texture.c; the
 * RT_TEXTURE_2D capability and the binding and size queries are get.c.
 *
 * Deviations from GL 1.1 (docs/textures.md): there is no default texture
 * object, so with 0 bound rtTexImage2D and rtTexParameteri record
 * RT_INVALID_OPERATION; an upload of level 0 generates the other mipmap
 * levels from it (GL_GENERATE_MIPMAP), again after every
 * rtTexSubImage2D, and a later upload of level k > 0 replaces level k of
 * that chain, which must then have its size; images are stored as 8-bit
 * RGBA whatever the upload type.  Pixels are unpacked as GL unpacks them,
 * under the rtPixelStorei state (pixel_store.c): rows aligned to
 * RT_UNPACK_ALIGNMENT (4 by default, so an RGB image of odd width has
 * padded rows, as in GL), RT_UNPACK_ROW_LENGTH, the skips and byte
 * swapping of RT_FLOAT data.
 *
 * Triangles keep the texture's name, not its image (scene/recording.c,
 * current_material), so every change made here shows in the next frame of
 * every object textured with that name.  Nothing here runs during a frame:
 * the calls are synchronous and the renderer only reads the table.
 */
#include <math.h>
#include <string.h>

#include "api/context.h"
#include "base/alloc.h"

void rtGenTextures(RTsizei n, RTuint *textures)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtGenTextures"))
        return;
    if (n < 0 || (n > 0 && !textures)) {
        rt_error(ctx, RT_INVALID_VALUE, "rtGenTextures(n=%d, textures=%p)", n,
                 (void *)textures);
        return;
    }
    if (scene_textures_generate(&ctx->scene.textures, (uint32_t)n, textures))
        rt_error(ctx, RT_OUT_OF_MEMORY, "rtGenTextures(n=%d): out of memory", n);
}

void rtDeleteTextures(RTsizei n, const RTuint *textures)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtDeleteTextures"))
        return;
    if (n < 0 || (n > 0 && !textures)) {
        rt_error(ctx, RT_INVALID_VALUE, "rtDeleteTextures(n=%d, textures=%p)", n,
                 (const void *)textures);
        return;
    }
    for (RTsizei i = 0; i < n; i++) {
        /* 0 and unknown names are ignored, as glDeleteTextures does. */
        if (textures[i] != 0 && textures[i] == ctx->texture_binding)
            ctx->texture_binding = 0;
        scene_textures_remove(&ctx->scene.textures, textures[i]);
    }
}

RTboolean rtIsTexture(RTuint texture)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtIsTexture"))
        return RT_FALSE;
    /* A name from rtGenTextures is a texture only once bound (GL 1.1). */
    const struct scene_texture *tex = scene_textures_lookup(&ctx->scene.textures, texture);
    return tex && tex->created ? RT_TRUE : RT_FALSE;
}

void rtBindTexture(RTenum target, RTuint texture)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtBindTexture"))
        return;
    if (target != RT_TEXTURE_2D) {
        rt_error(ctx, RT_INVALID_ENUM, "rtBindTexture(target=0x%x)", target);
        return;
    }
    if (texture != 0) {
        struct scene_texture *tex = scene_textures_get_or_create(&ctx->scene.textures, texture);
        if (!tex) {
            rt_error(ctx, RT_OUT_OF_MEMORY, "rtBindTexture(texture=%u): out of memory",
                     texture);
            return;
        }
        tex->created = 1;
    }
    rt_list_state(ctx, LIST_BIND_TEXTURE, target, texture, NULL, 0);
    ctx->texture_binding = texture;
}

/* The texture that rtTexImage2D and rtTexParameteri change, or NULL after
 * recording RT_INVALID_OPERATION (none bound, or inside rtBegin/rtEnd). */
static struct scene_texture *bound_texture(struct rt_context *ctx, const char *caller)
{
    if (rt_check_outside_begin(ctx, caller))
        return NULL;
    struct scene_texture *tex = scene_textures_lookup(&ctx->scene.textures, ctx->texture_binding);
    if (!tex)
        rt_error(ctx, RT_INVALID_OPERATION, "%s: no texture is bound (bind a non-zero name)",
                 caller);
    return tex;
}

/* Where an upload's pixels are in client memory (rt_pixel_layout). */
struct upload {
    const unsigned char *pixels;
    RTenum type;
    size_t components, size, first, stride;
    int swap;
};

static void upload_init(struct upload *u, const struct rt_context *ctx, const void *pixels,
                        RTenum format, RTenum type, int width)
{
    u->pixels = pixels;
    u->type = type;
    u->components = format == RT_RGB ? 3 : 4;
    u->size = type == RT_FLOAT ? sizeof(float) : 1;
    u->swap = ctx->unpack.swap_bytes;
    rt_pixel_layout(&ctx->unpack, width, (int)u->components, (int)u->size, &u->first,
                    &u->stride);
}

/* Component c of pixel (i, j) of an upload, as an 8-bit value: RT_FLOAT
 * is clamped to [0, 1] (NaN to 0) and rounded, as rtReadPixels
 * converts. */
static uint8_t upload_component(const struct upload *u, size_t i, size_t j, size_t c)
{
    const unsigned char *p =
        u->pixels + u->first + j * u->stride + (i * u->components + c) * u->size;
    if (u->type == RT_UNSIGNED_BYTE)
        return *p;
    unsigned char b[sizeof(float)];
    for (size_t k = 0; k < sizeof(float); k++)
        b[k] = p[u->swap ? sizeof(float) - 1 - k : k];
    float f;
    memcpy(&f, b, sizeof(f));
    f = fminf(fmaxf(f, 0.0f), 1.0f); /* fmaxf(NaN, 0) is 0 */
    return (uint8_t)lrintf(f * 255.0f);
}

/* Writes the upload's width x height pixels into the RGBA texels of a
 * level `level_width` wide at (x, y); alpha 255 where the data has none
 * or the texture is opaque. */
static void unpack_pixels(const struct upload *u, int width, int height, uint8_t *texels,
                          int level_width, int x, int y, int opaque)
{
    for (size_t j = 0; j < (size_t)height; j++)
        for (size_t i = 0; i < (size_t)width; i++) {
            uint8_t *t = &texels[4 * (((size_t)y + j) * (size_t)level_width + (size_t)x + i)];
            if (!u->pixels) {
                t[0] = t[1] = t[2] = 0; /* NULL: a black image */
                t[3] = 255;
                continue;
            }
            for (size_t c = 0; c < 3; c++)
                t[c] = upload_component(u, i, j, c);
            t[3] = u->components == 4 && !opaque ? upload_component(u, i, j, 3) : 255;
        }
}

/* Level k > 0 given by the program, as GL 1.1 programs load their own
 * mipmaps (each level a picture of its own, e.g. of another colour): it
 * replaces level k of the chain generated from level 0, so level 0 comes
 * first and level k must have the chain's size there, max(1, w >> k) x
 * max(1, h >> k).  GL also accepts other sizes, and levels before level 0,
 * and leaves the texture incomplete until they agree; Tracelist records
 * RT_INVALID_VALUE for them instead, so the difference is not silent. */
static void upload_level(struct rt_context *ctx, struct scene_texture *tex, RTint level,
                         RTsizei width, RTsizei height, RTenum format, RTenum type,
                         const void *pixels, int opaque)
{
    if (!tex->texels || level >= tex->level_count || width != tex->levels[level].width ||
        height != tex->levels[level].height) {
        rt_error(ctx, RT_INVALID_VALUE,
                 "rtTexImage2D(level=%d, width=%d, height=%d): level %d must have the size of "
                 "level %d of the chain of level 0, which is uploaded first (%s)",
                 level, width, height, level, level,
                 tex->texels ? "this chain has fewer levels or another size there"
                             : "no level 0 yet");
        return;
    }
    uint8_t *dst = tex->texels + (tex->levels[level].texels - tex->texels);
    struct upload u;
    upload_init(&u, ctx, pixels, format, type, width);
    unpack_pixels(&u, width, height, dst, width, 0, 0, opaque);
}

void rtTexImage2D(RTenum target, RTint level, RTint internalformat, RTsizei width,
                  RTsizei height, RTint border, RTenum format, RTenum type, const void *pixels)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx)
        return;
    struct scene_texture *tex = bound_texture(ctx, "rtTexImage2D");
    if (!tex)
        return;
    if (target != RT_TEXTURE_2D) {
        rt_error(ctx, RT_INVALID_ENUM, "rtTexImage2D(target=0x%x)", target);
        return;
    }
    if (format != RT_RGB && format != RT_RGBA) {
        rt_error(ctx, RT_INVALID_ENUM, "rtTexImage2D(format=0x%x)", format);
        return;
    }
    if (type != RT_UNSIGNED_BYTE && type != RT_FLOAT) {
        rt_error(ctx, RT_INVALID_ENUM, "rtTexImage2D(type=0x%x)", type);
        return;
    }
    if (level < 0 || level >= SCENE_TEXTURE_MAX_LEVELS) {
        rt_error(ctx, RT_INVALID_VALUE, "rtTexImage2D(level=%d): levels 0..%d", level,
                 SCENE_TEXTURE_MAX_LEVELS - 1);
        return;
    }
    /* GL 1.1 takes the component count (3, 4) or a format name. */
    int opaque = internalformat == 3 || internalformat == (RTint)RT_RGB;
    if (!opaque && internalformat != 4 && internalformat != (RTint)RT_RGBA) {
        rt_error(ctx, RT_INVALID_VALUE, "rtTexImage2D(internalformat=0x%x)",
                 (unsigned)internalformat);
        return;
    }
    if (width < 1 || height < 1 || width > SCENE_TEXTURE_MAX_SIZE ||
        height > SCENE_TEXTURE_MAX_SIZE || border != 0) {
        rt_error(ctx, RT_INVALID_VALUE,
                 "rtTexImage2D(width=%d, height=%d, border=%d): sizes 1..%d, border 0", width,
                 height, border, SCENE_TEXTURE_MAX_SIZE);
        return;
    }
    if (level > 0) {
        upload_level(ctx, tex, level, width, height, format, type, pixels, opaque);
        return;
    }
    /* The whole mip chain in one block, level 0 first. */
    uint8_t *texels = rt_malloc(4 * scene_texture_chain_texels(width, height));
    if (!texels) {
        rt_error(ctx, RT_OUT_OF_MEMORY, "rtTexImage2D(width=%d, height=%d): out of memory",
                 width, height);
        return;
    }
    struct upload u;
    upload_init(&u, ctx, pixels, format, type, width);
    unpack_pixels(&u, width, height, texels, width, 0, 0, opaque);
    /* Built here, on the API thread, whatever the filters: a later
     * rtTexParameteri can choose a mipmapped filter without any work. */
    if (scene_texture_build_mipmaps(texels, width, height)) {
        rt_free(texels);
        rt_error(ctx, RT_OUT_OF_MEMORY,
                 "rtTexImage2D(width=%d, height=%d): out of memory for the mipmaps", width,
                 height);
        return;
    }
    scene_texture_set_image(tex, width, height, texels);
    tex->opaque = opaque;
}

void rtTexSubImage2D(RTenum target, RTint level, RTint xoffset, RTint yoffset, RTsizei width,
                     RTsizei height, RTenum format, RTenum type, const void *pixels)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx)
        return;
    /* Mesa's texsubimage_error_check order: target, format and type,
     * level, then the texture and the rectangle. */
    if (rt_check_outside_begin(ctx, "rtTexSubImage2D"))
        return;
    if (target != RT_TEXTURE_2D) {
        rt_error(ctx, RT_INVALID_ENUM, "rtTexSubImage2D(target=0x%x)", target);
        return;
    }
    if (format != RT_RGB && format != RT_RGBA) {
        rt_error(ctx, RT_INVALID_ENUM, "rtTexSubImage2D(format=0x%x)", format);
        return;
    }
    if (type != RT_UNSIGNED_BYTE && type != RT_FLOAT) {
        rt_error(ctx, RT_INVALID_ENUM, "rtTexSubImage2D(type=0x%x)", type);
        return;
    }
    if (level != 0) {
        rt_error(ctx, RT_INVALID_VALUE,
                 "rtTexSubImage2D(level=%d): only level 0 (levels > 0 are generated from it)",
                 level);
        return;
    }
    struct scene_texture *tex = bound_texture(ctx, "rtTexSubImage2D");
    if (!tex)
        return;
    if (!tex->texels) {
        rt_error(ctx, RT_INVALID_OPERATION,
                 "rtTexSubImage2D: texture %u has no image (rtTexImage2D first)", tex->name);
        return;
    }
    if (width < 0 || height < 0 || xoffset < 0 || yoffset < 0 ||
        xoffset > tex->width - width || yoffset > tex->height - height) {
        rt_error(ctx, RT_INVALID_VALUE,
                 "rtTexSubImage2D(xoffset=%d, yoffset=%d, width=%d, height=%d): the "
                 "texture is %dx%d",
                 xoffset, yoffset, width, height, tex->width, tex->height);
        return;
    }
    if (width == 0 || height == 0 || !pixels)
        return; /* nothing to copy (GL leaves NULL undefined; Mesa copies nothing) */
    struct upload u;
    upload_init(&u, ctx, pixels, format, type, width);
    unpack_pixels(&u, width, height, tex->texels, tex->width, xoffset, yoffset, tex->opaque);
    if (scene_texture_build_mipmaps(tex->texels, tex->width, tex->height))
        rt_error(ctx, RT_OUT_OF_MEMORY,
                 "rtTexSubImage2D: out of memory rebuilding the mipmaps of texture %u",
                 tex->name);
}

/* The filter or wrap value for pname, or -1 when param is not one.  The
 * mipmapped filters are minification filters only (GL 1.1 sec. 3.8.2). */
static int parameter_value(RTenum pname, RTint param)
{
    if (pname == RT_TEXTURE_MIN_FILTER || pname == RT_TEXTURE_MAG_FILTER) {
        if (param == (RTint)RT_NEAREST)
            return SCENE_FILTER_NEAREST;
        if (param == (RTint)RT_LINEAR)
            return SCENE_FILTER_LINEAR;
        if (pname == RT_TEXTURE_MAG_FILTER)
            return -1;
        switch (param) {
        case (RTint)RT_NEAREST_MIPMAP_NEAREST:
            return SCENE_FILTER_NEAREST_MIPMAP_NEAREST;
        case (RTint)RT_LINEAR_MIPMAP_NEAREST:
            return SCENE_FILTER_LINEAR_MIPMAP_NEAREST;
        case (RTint)RT_NEAREST_MIPMAP_LINEAR:
            return SCENE_FILTER_NEAREST_MIPMAP_LINEAR;
        case (RTint)RT_LINEAR_MIPMAP_LINEAR:
            return SCENE_FILTER_LINEAR_MIPMAP_LINEAR;
        default:
            return -1;
        }
    }
    if (param == (RTint)RT_REPEAT)
        return SCENE_WRAP_REPEAT;
    if (param == (RTint)RT_CLAMP_TO_EDGE)
        return SCENE_WRAP_CLAMP_TO_EDGE;
    return -1;
}

void rtTexParameteri(RTenum target, RTenum pname, RTint param)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx)
        return;
    struct scene_texture *tex = bound_texture(ctx, "rtTexParameteri");
    if (!tex)
        return;
    if (target != RT_TEXTURE_2D) {
        rt_error(ctx, RT_INVALID_ENUM, "rtTexParameteri(target=0x%x)", target);
        return;
    }
    if (pname != RT_TEXTURE_MIN_FILTER && pname != RT_TEXTURE_MAG_FILTER &&
        pname != RT_TEXTURE_WRAP_S && pname != RT_TEXTURE_WRAP_T) {
        rt_error(ctx, RT_INVALID_ENUM, "rtTexParameteri(pname=0x%x)", pname);
        return;
    }
    int value = parameter_value(pname, param);
    if (value < 0) {
        rt_error(ctx, RT_INVALID_ENUM, "rtTexParameteri(pname=0x%x, param=0x%x)", pname,
                 (unsigned)param);
        return;
    }
    switch (pname) {
    case RT_TEXTURE_MIN_FILTER:
        tex->min_filter = (enum scene_texture_filter)value;
        break;
    case RT_TEXTURE_MAG_FILTER:
        tex->mag_filter = (enum scene_texture_filter)value;
        break;
    case RT_TEXTURE_WRAP_S:
        tex->wrap_s = (enum scene_texture_wrap)value;
        break;
    default:
        tex->wrap_t = (enum scene_texture_wrap)value;
        break;
    }
}
