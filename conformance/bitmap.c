/* SPDX-License-Identifier: Apache-2.0 */
/*
 * bitmap.c - rtRasterPos, rtWindowPos, rtBitmap (docs/text.md): the
 * raster position transformed and clipped as GL's, the raster colour
 * latched at the call, bitmaps unpacked as GL unpacks them (rows bottom
 * to top, MSB first, rows padded to 4 bytes) and drawn pixel-exactly over
 * the traced image, the raster position moved, the list ending with the
 * frame; errors.
 */
#include <rt/rt.h>
#include <rt/rtu.h>

#include "testutil.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define W 64
#define H 48

static float image[W * H * 4];

/* Renders the (empty) frame in window coordinates and reads it back. */
static void render(void)
{
    rtRenderFrame();
    rtReadPixels(0, 0, W, H, RT_RGBA, RT_FLOAT, image);
}

static const float *pixel(int x, int y)
{
    return &image[4 * (y * W + x)];
}

static int is_color(int x, int y, const float c[4])
{
    return memcmp(pixel(x, y), c, sizeof(float[4])) == 0;
}

static void window_camera(void)
{
    rtViewport(0, 0, W, H);
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtOrtho(0, W, 0, H, -1, 1);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
}

/* The bit (i, j) of a GL bitmap with rows bottom to top, MSB first. */
static int bit(const unsigned char *bits, int width, int i, int j)
{
    const int stride = ((width + 7) / 8 + 3) / 4 * 4;
    return (bits[j * stride + i / 8] >> (7 - i % 8)) & 1;
}

/* Every pixel is `ink` where bitmap (at lower-left x0, y0) has a 1 and
 * the clear colour elsewhere.  Returns the mismatches. */
static int compare_bitmap(const unsigned char *bits, int width, int height, int x0, int y0,
                          const float ink[4], const float clear[4])
{
    int x, y, bad = 0;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            const int i = x - x0, j = y - y0;
            const int on = i >= 0 && j >= 0 && i < width && j < height && bit(bits, width, i, j);
            bad += !is_color(x, y, on ? ink : clear);
        }
    return bad;
}

static void test_unpack_and_place(void)
{
    /* 10 x 3: two bytes of bits a row, padded to 4.  Row 0 (bottom) is
     * 1000000001, row 1 0110011000, row 2 (top) 1111111111. */
    static const unsigned char bits[3 * 4] = {0x80, 0x40, 0xEE, 0xEE, 0x66, 0x00, 0xEE, 0xEE,
                                              0xFF, 0xC0, 0xEE, 0xEE};
    static const float red[4] = {1, 0, 0, 1}, clear[4] = {0, 0, 0, 0};
    float pos[4], color[4];
    RTint valid = -1;
    window_camera();
    rtClearColor(0, 0, 0, 0);
    rtColor3f(1, 0, 0);
    rtRasterPos2i(10, 5);
    rtColor3f(0, 1, 0); /* after rtRasterPos: not the raster colour */
    rtGetFloatv(RT_CURRENT_RASTER_POSITION, pos);
    rtGetIntegerv(RT_CURRENT_RASTER_POSITION_VALID, &valid);
    rtGetFloatv(RT_CURRENT_RASTER_COLOR, color);
    CHECK_NEAR(pos[0], 10.0, 1e-5);
    CHECK_NEAR(pos[1], 5.0, 1e-5);
    CHECK_NEAR(pos[2], 0.5, 1e-6);
    CHECK_NEAR(pos[3], 1.0, 0.0);
    CHECK_INT(valid, 1);
    CHECK(memcmp(color, red, sizeof color) == 0);
    /* xorig 1.5, yorig 0.25: lower-left at floor(8.5), floor(4.75). */
    rtBitmap(10, 3, 1.5f, 0.25f, 12.0f, 1.0f, bits);
    rtGetFloatv(RT_CURRENT_RASTER_POSITION, pos);
    CHECK_NEAR(pos[0], 22.0, 1e-5);
    CHECK_NEAR(pos[1], 6.0, 1e-5);
    CHECK_NO_ERR();
    render();
    CHECK_NO_ERR();
    CHECK_INT(compare_bitmap(bits, 10, 3, 8, 4, red, clear), 0);
    CHECK(is_color(8, 4, red) && is_color(9, 4, clear) && is_color(17, 4, red));
    CHECK(is_color(9, 5, red) && is_color(8, 5, clear) && is_color(17, 6, red));

    /* The frame ended: the next frame has no bitmap. */
    render();
    CHECK_INT(compare_bitmap(bits, 10, 3, -100, -100, red, clear), 0);

    /* A bitmap half outside the window is clipped; two bitmaps in call
     * order, the later one over the earlier. */
    {
        static const unsigned char block[2 * 4] = {0xFF, 0, 0, 0, 0xFF, 0, 0, 0};
        static const float blue[4] = {0, 0, 1, 0.5f};
        rtColor4f(0, 0, 1, 0.5f);
        rtWindowPos2i(-3, H - 1);
        rtBitmap(8, 2, 0, 0, 0, 0, block);
        CHECK_NO_ERR();
        render();
        CHECK_INT(compare_bitmap(block, 8, 2, -3, H - 1, blue, clear), 0);
    }
    /* rtBeginFrame drops the bitmaps of the frame being described. */
    rtWindowPos2i(0, 0);
    rtBitmap(10, 3, 0, 0, 0, 0, bits);
    rtBeginFrame();
    render();
    CHECK_INT(compare_bitmap(bits, 10, 3, -100, -100, red, clear), 0);
}

static void test_clipped_and_transformed(void)
{
    static const unsigned char one[4] = {0x80, 0, 0, 0};
    static const float white[4] = {1, 1, 1, 1}, clear[4] = {0, 0, 0, 0};
    double mv[16], pr[16], wx, wy, wz;
    const RTint viewport[4] = {4, 2, W - 4, H - 2}; /* framebuffer W x H */
    RTint valid = -1;
    float pos[4];
    int k;
    window_camera();
    rtColor3f(1, 1, 1);
    /* Outside the view volume (x < 0): invalid; rtBitmap then draws
     * nothing and does not move the position. */
    rtRasterPos2f(-0.5f, 5.0f);
    rtGetIntegerv(RT_CURRENT_RASTER_POSITION_VALID, &valid);
    CHECK_INT(valid, 0);
    rtBitmap(1, 1, 0, 0, 5, 5, one);
    render();
    CHECK_INT(compare_bitmap(one, 1, 1, -100, -100, white, clear), 0);
    /* Behind the far plane (z = -2 maps beyond 1): invalid too. */
    rtRasterPos3f(5.0f, 5.0f, -2.0f);
    rtGetIntegerv(RT_CURRENT_RASTER_POSITION_VALID, &valid);
    CHECK_INT(valid, 0);
    /* rtWindowPos is always valid. */
    rtWindowPos2f(-10.0f, 300.0f);
    rtGetIntegerv(RT_CURRENT_RASTER_POSITION_VALID, &valid);
    CHECK_INT(valid, 1);

    /* A perspective camera, a moved modelview and an offset viewport: the
     * position is gluProject's. */
    rtViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtuPerspective(40.0, 1.3, 0.5, 20.0);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtTranslated(0.3, -0.2, -5.0);
    rtRotated(30.0, 0.0, 1.0, 0.0);
    {
        float f[16];
        rtGetFloatv(RT_MODELVIEW_MATRIX, f);
        for (k = 0; k < 16; k++)
            mv[k] = f[k];
        rtGetFloatv(RT_PROJECTION_MATRIX, f);
        for (k = 0; k < 16; k++)
            pr[k] = f[k];
    }
    CHECK(rtuProject(0.7, 0.4, -0.5, mv, pr, viewport, &wx, &wy, &wz));
    rtRasterPos3d(0.7, 0.4, -0.5);
    rtGetFloatv(RT_CURRENT_RASTER_POSITION, pos);
    rtGetIntegerv(RT_CURRENT_RASTER_POSITION_VALID, &valid);
    CHECK_INT(valid, 1);
    CHECK_NEAR(pos[0], wx, 1e-3);
    CHECK_NEAR(pos[1], wy, 1e-3);
    CHECK_NEAR(pos[2], wz, 1e-5);
    rtBitmap(1, 1, 0, 0, 0, 0, one);
    render();
    CHECK_INT(compare_bitmap(one, 1, 1, (int)floor(wx), (int)floor(wy), white, clear), 0);
    /* rtRasterPos4 with w: (2x, 2y, 2z, 2) is the same point. */
    rtRasterPos4d(1.4, 0.8, -1.0, 2.0);
    rtGetFloatv(RT_CURRENT_RASTER_POSITION, pos);
    CHECK_NEAR(pos[0], wx, 1e-3);
    CHECK_NEAR(pos[1], wy, 1e-3);
    /* Behind the eye: invalid. */
    rtRasterPos3d(0.0, 0.0, 10.0);
    rtGetIntegerv(RT_CURRENT_RASTER_POSITION_VALID, &valid);
    CHECK_INT(valid, 0);
    CHECK_NO_ERR();
    rtBeginFrame();
}

static void test_errors(void)
{
    static const unsigned char one[4] = {0x80, 0, 0, 0};
    window_camera();
    rtWindowPos2i(1, 1);
    rtBitmap(-1, 1, 0, 0, 0, 0, one);
    CHECK_ERR(RT_INVALID_VALUE);
    rtBitmap(1, 1, tu_nan(), 0, 0, 0, one);
    CHECK_ERR(RT_INVALID_VALUE);
    rtRasterPos3f(1, tu_inf(), 0);
    CHECK_ERR(RT_INVALID_VALUE);
    rtRasterPos2fv(NULL);
    CHECK_ERR(RT_INVALID_VALUE);
    rtWindowPos3dv(NULL);
    CHECK_ERR(RT_INVALID_VALUE);
    tu_begin_scratch(RT_TRIANGLES);
    rtBitmap(1, 1, 0, 0, 0, 0, one);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtRasterPos2i(1, 1);
    CHECK_ERR(RT_INVALID_OPERATION);
    tu_end_scratch();
    CHECK_NO_ERR();
    /* GL compiles raster positions into lists (conformance/list_raster.c):
     * recorded, not executed under RT_COMPILE. */
    rtWindowPos2i(5, 6);
    rtNewObject(77);
    rtWindowPos2i(1, 1);
    CHECK_ERR(RT_NO_ERROR);
    rtEndObject();
    {
        float pos[4];
        rtGetFloatv(RT_CURRENT_RASTER_POSITION, pos);
        CHECK_NEAR(pos[0], 5.0, 0.0);
    }
    rtDeleteObjects(1, (const RTuint[]){77});
    /* A NULL bitmap only moves the position (GL's idiom). */
    {
        float pos[4];
        rtWindowPos2i(3, 4);
        rtBitmap(0, 0, 0, 0, 2.5f, -1.0f, NULL);
        rtGetFloatv(RT_CURRENT_RASTER_POSITION, pos);
        CHECK_NEAR(pos[0], 5.5, 0.0);
        CHECK_NEAR(pos[1], 3.0, 0.0);
    }
    CHECK_NO_ERR();
}

/* A GL frame (begun by rtClear) rendered twice, as a GLUT program's
 * glFlush followed by glutSwapBuffers renders it: GL's framebuffer still
 * holds the text at the swap, so the second image has it too; the next
 * rtClear ends it.  Last: it leaves the context in GL frames. */
static void test_gl_frame_rendered_twice(void)
{
    static const unsigned char bits[3 * 4] = {0x80, 0x40, 0xEE, 0xEE, 0x66, 0x00, 0xEE, 0xEE,
                                              0xFF, 0xC0, 0xEE, 0xEE};
    static const float yellow[4] = {1, 1, 0, 1}, clear[4] = {0, 0, 0, 0};
    window_camera();
    rtClearColor(0, 0, 0, 0);
    rtClear(RT_COLOR_BUFFER_BIT | RT_DEPTH_BUFFER_BIT);
    rtColor3f(1, 1, 0);
    rtWindowPos2i(5, 7);
    rtBitmap(10, 3, 0, 0, 0, 0, bits);
    rtFlush();
    rtReadPixels(0, 0, W, H, RT_RGBA, RT_FLOAT, image);
    CHECK_INT(compare_bitmap(bits, 10, 3, 5, 7, yellow, clear), 0);
    render(); /* the buffer swap's render of the same frame */
    CHECK_INT(compare_bitmap(bits, 10, 3, 5, 7, yellow, clear), 0);
    rtClear(RT_COLOR_BUFFER_BIT);
    render();
    CHECK_INT(compare_bitmap(bits, 10, 3, -100, -100, yellow, clear), 0);
    CHECK_NO_ERR();
}

int main(void)
{
    RTcontext ctx = tu_make_context("threads=2");
    {
        float pos[4], color[4];
        RTint valid = 0;
        /* GL's initial state: (0, 0, 0, 1), valid, white. */
        rtGetFloatv(RT_CURRENT_RASTER_POSITION, pos);
        rtGetFloatv(RT_CURRENT_RASTER_COLOR, color);
        rtGetIntegerv(RT_CURRENT_RASTER_POSITION_VALID, &valid);
        CHECK(pos[0] == 0 && pos[1] == 0 && pos[2] == 0 && pos[3] == 1);
        CHECK(color[0] == 1 && color[1] == 1 && color[2] == 1 && color[3] == 1);
        CHECK_INT(valid, 1);
    }
    test_unpack_and_place();
    test_clipped_and_transformed();
    test_errors();
    test_gl_frame_rendered_twice();
    tu_destroy_context(ctx);
    return test_summary("bitmap");
}
