/* SPDX-License-Identifier: Apache-2.0 */
/*
 * overlay.c - the frame's bitmaps and their drawing over the image
 * (overlay.h).
 */
#include "render/overlay.h"

#include <string.h>

#include "base/alloc.h"

/* Grows *buffer (of *capacity elements of `size` bytes) to hold `needed`
 * elements, doubling.  Returns 0, or -1 with the buffer unchanged. */
static int reserve(void **buffer, size_t *capacity, size_t needed, size_t size)
{
    if (needed <= *capacity)
        return 0;
    size_t cap = *capacity ? *capacity : 16;
    while (cap < needed) {
        if (cap > ((size_t)-1) / 2)
            return -1;
        cap *= 2;
    }
    void *grown = rt_realloc_array(*buffer, cap, size);
    if (!grown)
        return -1;
    *buffer = grown;
    *capacity = cap;
    return 0;
}

int render_overlay_add(struct render_overlay *overlay, uint32_t order, int x, int y, int width,
                       int height, size_t stride, const unsigned char *rows,
                       const float color[4])
{
    const size_t bytes = stride * (size_t)height;
    if (height > 0 && bytes / (size_t)height != stride)
        return -1;
    if (reserve((void **)&overlay->items, &overlay->capacity, overlay->count + 1,
                sizeof(*overlay->items)))
        return -1;
    if (bytes > ((size_t)-1) - overlay->bits_used ||
        reserve((void **)&overlay->bits, &overlay->bits_capacity, overlay->bits_used + bytes, 1))
        return -1;
    struct render_bitmap *b = &overlay->items[overlay->count++];
    b->order = order;
    b->x = x;
    b->y = y;
    b->width = width;
    b->height = height;
    b->stride = stride;
    b->offset = overlay->bits_used;
    memcpy(b->color, color, sizeof(b->color));
    if (bytes)
        memcpy(overlay->bits + overlay->bits_used, rows, bytes);
    overlay->bits_used += bytes;
    return 0;
}

static void draw_bitmap(const struct render_bitmap *b, const unsigned char *bits,
                        float *rgba, int width, int height)
{
    /* Clip to the framebuffer in 64-bit arithmetic: x + width may
     * overflow an int for positions far outside the window. */
    long long i0 = b->x < 0 ? -(long long)b->x : 0;
    long long j0 = b->y < 0 ? -(long long)b->y : 0;
    long long i1 = b->width, j1 = b->height;
    if ((long long)b->x + i1 > width)
        i1 = (long long)width - b->x;
    if ((long long)b->y + j1 > height)
        j1 = (long long)height - b->y;
    for (long long j = j0; j < j1; j++) {
        const unsigned char *row = bits + b->offset + (size_t)j * b->stride;
        const size_t line = (size_t)(b->y + j) * (size_t)width;
        for (long long i = i0; i < i1; i++)
            if (row[i >> 3] & (0x80u >> (i & 7)))
                memcpy(&rgba[4 * (line + (size_t)(b->x + i))], b->color, sizeof(b->color));
    }
}

void render_overlay_apply(const struct render_overlay *overlay, struct render_framebuffer *fb)
{
    if (fb->rgba)
        render_overlay_draw(overlay, 0, UINT32_MAX, fb->rgba, fb->width, fb->height);
}

size_t render_overlay_draw(const struct render_overlay *overlay, size_t from, uint32_t before,
                           float *rgba, int width, int height)
{
    size_t k = from;
    for (; k < overlay->count && overlay->items[k].order <= before; k++)
        draw_bitmap(&overlay->items[k], overlay->bits, rgba, width, height);
    return k;
}

void render_overlay_clear(struct render_overlay *overlay)
{
    overlay->count = 0;
    overlay->bits_used = 0;
}

void render_overlay_release(struct render_overlay *overlay)
{
    rt_free(overlay->items);
    rt_free(overlay->bits);
    memset(overlay, 0, sizeof(*overlay));
}
