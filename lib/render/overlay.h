/* SPDX-License-Identifier: Apache-2.0 */
/*
 * overlay.h - the bitmaps of a frame (rtBitmap), drawn over its ray
 * traced image.
 *
 * GL draws glBitmap into the framebuffer at the call, over whatever the
 * frame's earlier drawing left there.  A ray traced frame exists only
 * when rtRenderFrame has traced it, so the API keeps the frame's bitmaps
 * here, in call order, and the overlay is applied to the finished image
 * right after the trace, before anyone can read it: the image then holds
 * what GL's would, text over the scene.  The list ends with the frame.
 */
#ifndef RT_RENDER_OVERLAY_H
#define RT_RENDER_OVERLAY_H

#include <stddef.h>
#include <stdint.h>

#include "render/render.h"

/* One bitmap: its lower-left pixel, size, colour, and its rows (bottom to
 * top, MSB first, `stride` bytes apart) at `offset` in the overlay's bits. */
struct render_bitmap {
    /* The number of the frame's instances drawn before it: it goes under
     * rasterised instances from that index on (render.c, docs/text.md). */
    uint32_t order;
    int x, y;
    int width, height;
    size_t stride;
    size_t offset;
    float color[4];
};

struct render_overlay {
    struct render_bitmap *items;
    size_t count, capacity;
    unsigned char *bits;
    size_t bits_used, bits_capacity;
};

/* Appends a bitmap (copying height rows of `stride` bytes from `rows`).
 * Returns 0, or -1 when out of memory (the overlay unchanged). */
int render_overlay_add(struct render_overlay *overlay, uint32_t order, int x, int y, int width,
                       int height, size_t stride, const unsigned char *rows,
                       const float color[4]);
/* Draws the bitmaps from index `from` on whose order is at most `before`
 * into the width x height RGBA image rgba; returns the index of the first
 * one not drawn. */
size_t render_overlay_draw(const struct render_overlay *overlay, size_t from, uint32_t before,
                           float *rgba, int width, int height);
/* Draws every bitmap, in order, into fb: a pixel whose bit is 1 takes
 * the bitmap's colour; pixels outside fb are clipped. */
void render_overlay_apply(const struct render_overlay *overlay, struct render_framebuffer *fb);
/* Forgets the bitmaps, keeping the memory for the next frame. */
void render_overlay_clear(struct render_overlay *overlay);
/* Frees everything and zeroes *overlay. */
void render_overlay_release(struct render_overlay *overlay);

#endif
