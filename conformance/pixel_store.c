/* SPDX-License-Identifier: Apache-2.0 */
/*
 * pixel_store.c - rtPixelStorei / rtPixelStoref (docs/pixelstore.md) and
 * rtTexSubImage2D (docs/textures.md): GL's defaults and errors; RGB
 * textures of odd width unpacked with GL's default alignment 4 (padded
 * rows) and with alignment 1, as classic programs load them; row length
 * and skips; rtReadPixels packing; bitmaps under the unpack state; the
 * client attribute stack around pixel store changes; sub-image updates.
 */
#include "testutil.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define QUAD 700u
#define W 16
#define H 16
static float px[W * H * 4];

static RTint geti(RTenum pname)
{
    RTint v = -12345;
    rtGetIntegerv(pname, &v);
    return v;
}

static const float *pixel(int i, int j)
{
    return px + 4 * (j * W + i);
}

static int rgb_near(const char *file, int line, const float *p, float r, float g, float b)
{
    int ok = fabsf(p[0] - r) <= 1e-5f && fabsf(p[1] - g) <= 1e-5f && fabsf(p[2] - b) <= 1e-5f;
    if (!tu_check(ok, file, line, "pixel colour"))
        fprintf(stderr, "    pixel (%g, %g, %g), expected (%g, %g, %g)\n", p[0], p[1], p[2], r,
                g, b);
    return ok;
}
#define CHECK_RGB(p, r, g, b) rgb_near(__FILE__, __LINE__, (p), (r), (g), (b))

/* The quad covering the view, texture coordinates 0..1, NEAREST, eye
 * light on a white material: each pixel shows its texel exactly. */
static void setup_textured_quad(RTuint tex)
{
    static const float black[4] = {0, 0, 0, 1}, white[4] = {1, 1, 1, 1};
    rtShadingMode(RT_EYE_LIGHT);
    tu_ortho_camera();
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, black);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, white);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_SPECULAR, black);
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, black);
    rtBindTexture(RT_TEXTURE_2D, tex);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MIN_FILTER, RT_NEAREST);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MAG_FILTER, RT_NEAREST);
    rtEnable(RT_TEXTURE_2D);
    rtNewObject(QUAD);
    rtBegin(RT_QUADS);
    rtTexCoord2f(0, 0);
    rtVertex3f(-1, -1, -5);
    rtTexCoord2f(1, 0);
    rtVertex3f(1, -1, -5);
    rtTexCoord2f(1, 1);
    rtVertex3f(1, 1, -5);
    rtTexCoord2f(0, 1);
    rtVertex3f(-1, 1, -5);
    rtEnd();
    rtEndObject();
    /* RT_TEXTURE_2D stays enabled: the object does not enable it itself, so
     * it takes the enable and binding current where it is instanced, as a
     * GL list takes them at glCallList. */
}

static void render(void)
{
    CHECK(tu_scene1(QUAD));
    tu_render_float(W, H, px);
    CHECK_NO_ERR();
}

/* Pixel (i, j) of the 16x16 image shows texel (floor(w (i+0.5)/16),
 * floor(h (j+0.5)/16)) of a w x h texture. */
static const float *texel_pixel(int i, int j, int w, int h)
{
    return pixel((16 * i + 8) / w, (16 * j + 8) / h);
}

static void defaults_and_errors(void)
{
    tu_section("defaults as GL: alignment 4, the rest 0");
    CHECK_INT(geti(RT_UNPACK_ALIGNMENT), 4);
    CHECK_INT(geti(RT_PACK_ALIGNMENT), 4);
    CHECK_INT(geti(RT_UNPACK_ROW_LENGTH), 0);
    CHECK_INT(geti(RT_UNPACK_SKIP_ROWS), 0);
    CHECK_INT(geti(RT_UNPACK_SKIP_PIXELS), 0);
    CHECK_INT(geti(RT_UNPACK_LSB_FIRST), 0);
    CHECK_INT(geti(RT_UNPACK_SWAP_BYTES), 0);
    CHECK_INT(geti(RT_PACK_ROW_LENGTH), 0);
    CHECK_INT(geti(RT_PACK_SKIP_ROWS), 0);
    CHECK_INT(geti(RT_PACK_SKIP_PIXELS), 0);
    CHECK_NO_ERR();

    tu_section("errors leave the state unchanged");
    rtPixelStorei(RT_UNPACK_ALIGNMENT, 3);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_MSG("rtPixelStorei");
    rtPixelStorei(RT_PACK_ALIGNMENT, 16);
    CHECK_ERR(RT_INVALID_VALUE);
    rtPixelStorei(RT_UNPACK_ALIGNMENT, 0);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_INT(geti(RT_UNPACK_ALIGNMENT), 4);
    CHECK_INT(geti(RT_PACK_ALIGNMENT), 4);
    rtPixelStorei(RT_UNPACK_ROW_LENGTH, -1);
    CHECK_ERR(RT_INVALID_VALUE);
    rtPixelStorei(RT_PACK_SKIP_ROWS, -2);
    CHECK_ERR(RT_INVALID_VALUE);
    rtPixelStorei(RT_UNPACK_SKIP_PIXELS, -3);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_INT(geti(RT_UNPACK_ROW_LENGTH), 0);
    rtPixelStorei(0x0D06, 1);
    CHECK_ERR(RT_INVALID_ENUM);
    rtPixelStorei(RT_TEXTURE_2D, 1);
    CHECK_ERR(RT_INVALID_ENUM);
    rtPixelStoref(RT_UNPACK_ALIGNMENT, 2.5f);
    CHECK_ERR(RT_NO_ERROR); /* rounds to 2 (ties to even) */
    CHECK_INT(geti(RT_UNPACK_ALIGNMENT), 2);
    rtPixelStoref(RT_UNPACK_ROW_LENGTH, 6.7f);
    CHECK_INT(geti(RT_UNPACK_ROW_LENGTH), 7);
    rtPixelStoref(RT_UNPACK_ALIGNMENT, tu_nan());
    CHECK_ERR(RT_INVALID_VALUE);
    rtPixelStoref(RT_UNPACK_LSB_FIRST, 0.5f);
    CHECK_INT(geti(RT_UNPACK_LSB_FIRST), 1);
    rtPixelStorei(RT_UNPACK_LSB_FIRST, 0);
    rtPixelStorei(RT_UNPACK_ROW_LENGTH, 0);
    rtPixelStorei(RT_UNPACK_ALIGNMENT, 4);
    tu_begin_scratch(RT_TRIANGLES);
    rtPixelStorei(RT_UNPACK_ALIGNMENT, 1);
    CHECK_ERR(RT_INVALID_OPERATION);
    tu_end_scratch();
    CHECK_INT(geti(RT_UNPACK_ALIGNMENT), 4);
    CHECK_NO_ERR();
}

/* A 3x2 RGB image: row 0 red, green, blue; row 1 three greys/colours. */
static const float odd_texels[6][3] = {{1, 0, 0},     {0, 1, 0},    {0, 0, 1},
                                       {0.2f, 0.4f, 0.6f}, {0.8f, 1, 0}, {0, 0.2f, 0.4f}};

static void check_odd_texture(void)
{
    for (int j = 0; j < 2; j++)
        for (int i = 0; i < 3; i++) {
            const float *e = odd_texels[3 * j + i];
            CHECK_RGB(texel_pixel(i, j, 3, 2), e[0], e[1], e[2]);
        }
}

static void odd_width_rgb(void)
{
    const RTuint tex = 71;
    setup_textured_quad(tex);

    tu_section("odd-width RGB texture, GL's default alignment 4: rows padded to 12 bytes");
    {
        /* 9 bytes of texels and 3 bytes of padding a row; the padding
         * holds values that would show if it were read as texels. */
        static const unsigned char padded[24] = {255, 0,   0,   0,   255, 0,   0,  0,
                                                 255, 77,  77,  77,  51,  102, 153, 204,
                                                 255, 0,   0,   51,  102, 77,  77, 77};
        rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGB, 3, 2, 0, RT_RGB, RT_UNSIGNED_BYTE, padded);
        CHECK_NO_ERR();
        render();
        check_odd_texture();
    }

    tu_section("odd-width RGB texture after rtPixelStorei(RT_UNPACK_ALIGNMENT, 1)");
    {
        static const unsigned char tight[18] = {255, 0,   0,   0,   255, 0,  0, 0,  255,
                                                51,  102, 153, 204, 255, 0,  0, 51, 102};
        rtPixelStorei(RT_UNPACK_ALIGNMENT, 1);
        rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGB, 3, 2, 0, RT_RGB, RT_UNSIGNED_BYTE, tight);
        rtPixelStorei(RT_UNPACK_ALIGNMENT, 4);
        CHECK_NO_ERR();
        render();
        check_odd_texture();
    }

    tu_section("alignment 8 and 2 with a 1-texel-wide RGB image");
    {
        /* 3 bytes a row: alignment 8 pads to 8, alignment 2 to 4. */
        static const unsigned char a8[16] = {255, 0, 0, 9, 9, 9, 9, 9, 0, 0, 255, 9, 9, 9, 9, 9};
        static const unsigned char a2[8] = {0, 255, 0, 9, 255, 255, 0, 9};
        rtPixelStorei(RT_UNPACK_ALIGNMENT, 8);
        rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGB, 1, 2, 0, RT_RGB, RT_UNSIGNED_BYTE, a8);
        render();
        CHECK_RGB(pixel(8, 2), 1, 0, 0);
        CHECK_RGB(pixel(8, 13), 0, 0, 1);
        rtPixelStorei(RT_UNPACK_ALIGNMENT, 2);
        rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGB, 1, 2, 0, RT_RGB, RT_UNSIGNED_BYTE, a2);
        render();
        CHECK_RGB(pixel(8, 2), 0, 1, 0);
        CHECK_RGB(pixel(8, 13), 1, 1, 0);
        rtPixelStorei(RT_UNPACK_ALIGNMENT, 4);
    }

    tu_section("row length and skips: a 2x2 window of a 4x3 RGBA image");
    {
        unsigned char big[4 * 3 * 4];
        for (int k = 0; k < 12; k++) {
            big[4 * k + 0] = (unsigned char)(20 * k);
            big[4 * k + 1] = 0;
            big[4 * k + 2] = 0;
            big[4 * k + 3] = 255;
        }
        rtPixelStorei(RT_UNPACK_ROW_LENGTH, 4);
        rtPixelStorei(RT_UNPACK_SKIP_PIXELS, 1);
        rtPixelStorei(RT_UNPACK_SKIP_ROWS, 1);
        rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGBA, 2, 2, 0, RT_RGBA, RT_UNSIGNED_BYTE, big);
        rtPixelStorei(RT_UNPACK_ROW_LENGTH, 0);
        rtPixelStorei(RT_UNPACK_SKIP_PIXELS, 0);
        rtPixelStorei(RT_UNPACK_SKIP_ROWS, 0);
        CHECK_NO_ERR();
        render();
        /* Texel (i, j) is big's pixel (1 + i, 1 + j), index 4 (1 + j) + 1 + i. */
        for (int j = 0; j < 2; j++)
            for (int i = 0; i < 2; i++)
                CHECK_RGB(texel_pixel(i, j, 2, 2), 20.0f * (4 * (1 + j) + 1 + i) / 255.0f, 0, 0);
    }

    tu_section("RT_UNPACK_SWAP_BYTES on RT_FLOAT data");
    {
        float f[3] = {1.0f, 0.0f, 1.0f};
        unsigned char swapped[12];
        for (int c = 0; c < 3; c++) {
            unsigned char b[4];
            memcpy(b, &f[c], 4);
            for (int k = 0; k < 4; k++)
                swapped[4 * c + k] = b[3 - k];
        }
        rtPixelStorei(RT_UNPACK_SWAP_BYTES, 1);
        rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGB, 1, 1, 0, RT_RGB, RT_FLOAT, swapped);
        rtPixelStorei(RT_UNPACK_SWAP_BYTES, 0);
        render();
        CHECK_RGB(pixel(8, 8), 1, 0, 1);
    }
}

static void sub_image(void)
{
    const RTuint tex = 72;
    setup_textured_quad(tex);
    static const unsigned char base[16] = {255, 0, 0, 255, 0, 255, 0, 255,
                                           0, 0, 255, 255, 255, 255, 255, 255};

    tu_section("rtTexSubImage2D replaces a rectangle, keeps the rest");
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGBA, 2, 2, 0, RT_RGBA, RT_UNSIGNED_BYTE, base);
    {
        static const unsigned char yellow[3] = {255, 255, 0};
        rtTexSubImage2D(RT_TEXTURE_2D, 0, 1, 0, 1, 1, RT_RGB, RT_UNSIGNED_BYTE, yellow);
        CHECK_NO_ERR();
        render();
        CHECK_RGB(texel_pixel(0, 0, 2, 2), 1, 0, 0);
        CHECK_RGB(texel_pixel(1, 0, 2, 2), 1, 1, 0);
        CHECK_RGB(texel_pixel(0, 1, 2, 2), 0, 0, 1);
        CHECK_RGB(texel_pixel(1, 1, 2, 2), 1, 1, 1);
    }

    tu_section("rtTexSubImage2D unpacks with the pixel store (odd width, alignment 4)");
    {
        /* A 3x2 image, then a 1x2 column of RGB at x = 1: 3 bytes a row,
         * padded to 4. */
        static const unsigned char grey[24] = {0};
        static const unsigned char column[8] = {0, 255, 0, 99, 255, 0, 255, 99};
        rtPixelStorei(RT_UNPACK_ALIGNMENT, 1);
        rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGB, 3, 2, 0, RT_RGB, RT_UNSIGNED_BYTE, grey);
        rtPixelStorei(RT_UNPACK_ALIGNMENT, 4);
        rtTexSubImage2D(RT_TEXTURE_2D, 0, 1, 0, 1, 2, RT_RGB, RT_UNSIGNED_BYTE, column);
        CHECK_NO_ERR();
        render();
        CHECK_RGB(texel_pixel(0, 0, 3, 2), 0, 0, 0);
        CHECK_RGB(texel_pixel(1, 0, 3, 2), 0, 1, 0);
        CHECK_RGB(texel_pixel(1, 1, 3, 2), 1, 0, 1);
        CHECK_RGB(texel_pixel(2, 1, 3, 2), 0, 0, 0);
    }

    tu_section("rtTexSubImage2D errors change nothing");
    {
        static const unsigned char white[16] = {255, 255, 255, 255, 255, 255, 255, 255,
                                                255, 255, 255, 255, 255, 255, 255, 255};
        rtTexSubImage2D(0x0DE0, 0, 0, 0, 1, 1, RT_RGBA, RT_UNSIGNED_BYTE, white);
        CHECK_ERR(RT_INVALID_ENUM);
        CHECK_MSG("rtTexSubImage2D");
        rtTexSubImage2D(RT_TEXTURE_2D, 0, 0, 0, 1, 1, 0x1909, RT_UNSIGNED_BYTE, white);
        CHECK_ERR(RT_INVALID_ENUM);
        rtTexSubImage2D(RT_TEXTURE_2D, 0, 0, 0, 1, 1, RT_RGBA, RT_UNSIGNED_SHORT, white);
        CHECK_ERR(RT_INVALID_ENUM);
        rtTexSubImage2D(RT_TEXTURE_2D, 1, 0, 0, 1, 1, RT_RGBA, RT_UNSIGNED_BYTE, white);
        CHECK_ERR(RT_INVALID_VALUE);
        rtTexSubImage2D(RT_TEXTURE_2D, 0, -1, 0, 1, 1, RT_RGBA, RT_UNSIGNED_BYTE, white);
        CHECK_ERR(RT_INVALID_VALUE);
        rtTexSubImage2D(RT_TEXTURE_2D, 0, 0, 0, 4, 1, RT_RGBA, RT_UNSIGNED_BYTE, white);
        CHECK_ERR(RT_INVALID_VALUE);
        rtTexSubImage2D(RT_TEXTURE_2D, 0, 2, 1, 2, 2, RT_RGBA, RT_UNSIGNED_BYTE, white);
        CHECK_ERR(RT_INVALID_VALUE);
        rtTexSubImage2D(RT_TEXTURE_2D, 0, 0, 0, -1, 1, RT_RGBA, RT_UNSIGNED_BYTE, white);
        CHECK_ERR(RT_INVALID_VALUE);
        rtTexSubImage2D(RT_TEXTURE_2D, 0, 3, 2, 0, 0, RT_RGBA, RT_UNSIGNED_BYTE, white);
        CHECK_NO_ERR(); /* an empty rectangle at the corner is inside */
        render();
        CHECK_RGB(texel_pixel(1, 0, 3, 2), 0, 1, 0);
        CHECK_RGB(texel_pixel(0, 0, 3, 2), 0, 0, 0);
        /* A texture without an image, and no texture at all. */
        rtBindTexture(RT_TEXTURE_2D, 73);
        rtTexSubImage2D(RT_TEXTURE_2D, 0, 0, 0, 1, 1, RT_RGBA, RT_UNSIGNED_BYTE, white);
        CHECK_ERR(RT_INVALID_OPERATION);
        rtBindTexture(RT_TEXTURE_2D, 0);
        rtTexSubImage2D(RT_TEXTURE_2D, 0, 0, 0, 1, 1, RT_RGBA, RT_UNSIGNED_BYTE, white);
        CHECK_ERR(RT_INVALID_OPERATION);
        tu_begin_scratch(RT_TRIANGLES);
        rtTexSubImage2D(RT_TEXTURE_2D, 0, 0, 0, 1, 1, RT_RGBA, RT_UNSIGNED_BYTE, white);
        CHECK_ERR(RT_INVALID_OPERATION);
        tu_end_scratch();
    }

    tu_section("an RT_RGB texture stays opaque under RGBA sub-images");
    {
        static const unsigned char rgb[12] = {10, 10, 10, 0, 20, 20, 20, 0,
                                              30, 30, 30, 0};
        static const unsigned char half[4] = {255, 0, 0, 128};
        rtBindTexture(RT_TEXTURE_2D, tex);
        rtPixelStorei(RT_UNPACK_ALIGNMENT, 1);
        rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGB, 2, 2, 0, RT_RGB, RT_UNSIGNED_BYTE, rgb);
        rtPixelStorei(RT_UNPACK_ALIGNMENT, 4);
        rtTexSubImage2D(RT_TEXTURE_2D, 0, 0, 0, 1, 1, RT_RGBA, RT_UNSIGNED_BYTE, half);
        CHECK_NO_ERR();
        render();
        CHECK_RGB(texel_pixel(0, 0, 2, 2), 1, 0, 0);
        CHECK(pixel(2, 2)[3] == 1.0f);
    }
}

static void read_pixels_packing(void)
{
    tu_section("rtReadPixels: RT_PACK_ALIGNMENT 8 pads a 3-pixel RGBA byte row to 16");
    const float clear[4] = {0.2f, 0.4f, 0.6f, 1.0f};
    rtClearColor(clear[0], clear[1], clear[2], clear[3]);
    rtBeginFrame();
    rtViewport(0, 0, 8, 4);
    rtRenderFrame();
    CHECK_NO_ERR();
    const unsigned char c[4] = {51, 102, 153, 255};
    unsigned char out[64];
    memset(out, 0xEE, sizeof(out));
    rtPixelStorei(RT_PACK_ALIGNMENT, 8);
    rtReadPixels(0, 0, 3, 2, RT_RGBA, RT_UNSIGNED_BYTE, out);
    CHECK_NO_ERR();
    for (int row = 0; row < 2; row++) {
        for (int i = 0; i < 12; i++)
            CHECK_INT(out[16 * row + i], c[i % 4]);
        if (row == 0)
            for (int i = 12; i < 16; i++)
                CHECK_INT(out[i], 0xEE); /* padding untouched */
    }
    CHECK_INT(out[28], 0xEE);
    rtPixelStorei(RT_PACK_ALIGNMENT, 4);

    tu_section("rtReadPixels: row length and skips place the rectangle in a larger image");
    memset(out, 0xEE, sizeof(out));
    rtPixelStorei(RT_PACK_ROW_LENGTH, 4);
    rtPixelStorei(RT_PACK_SKIP_PIXELS, 1);
    rtPixelStorei(RT_PACK_SKIP_ROWS, 2);
    rtReadPixels(0, 0, 2, 1, RT_RGBA, RT_UNSIGNED_BYTE, out);
    rtPixelStorei(RT_PACK_ROW_LENGTH, 0);
    rtPixelStorei(RT_PACK_SKIP_PIXELS, 0);
    rtPixelStorei(RT_PACK_SKIP_ROWS, 0);
    CHECK_NO_ERR();
    /* Row 2 of a 4-pixel-wide image starts at byte 32; skip 1 pixel: 36. */
    for (int i = 0; i < 36; i++)
        if (out[i] != 0xEE)
            CHECKF(0, "byte %d written (%d)", i, out[i]);
    for (int i = 36; i < 44; i++)
        CHECK_INT(out[i], c[i % 4]);
    CHECK_INT(out[44], 0xEE);

    tu_section("rtReadPixels: RT_PACK_SWAP_BYTES on RT_FLOAT");
    {
        unsigned char f[16];
        rtPixelStorei(RT_PACK_SWAP_BYTES, 1);
        rtReadPixels(0, 0, 1, 1, RT_RGBA, RT_FLOAT, f);
        rtPixelStorei(RT_PACK_SWAP_BYTES, 0);
        unsigned char b[4], expect[4];
        float one = 1.0f;
        memcpy(expect, &one, 4);
        for (int k = 0; k < 4; k++)
            b[k] = f[12 + 3 - k];
        CHECK(memcmp(b, expect, 4) == 0);
    }
    rtClearColor(0, 0, 0, 0);
}

static void bitmaps(void)
{
    tu_section("rtBitmap rows under RT_UNPACK_ALIGNMENT 1, LSB first and skip pixels");
    rtViewport(0, 0, W, H);
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtOrtho(0, W, 0, H, -1, 1);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtClearColor(0, 0, 0, 1);
    /* A 9x2 bitmap: row 0 has only pixel 8 set, row 1 only pixel 0. With
     * alignment 1 the rows are 2 bytes; GL's default 4 would read row 1
     * from byte 4. */
    static const unsigned char tight[4] = {0x00, 0x80, 0x80, 0x00};
    rtBeginFrame();
    rtColor3f(1, 1, 1);
    rtWindowPos2i(2, 2);
    rtPixelStorei(RT_UNPACK_ALIGNMENT, 1);
    rtBitmap(9, 2, 0, 0, 0, 0, tight);
    rtPixelStorei(RT_UNPACK_ALIGNMENT, 4);
    tu_render_float(W, H, px);
    CHECK_NO_ERR();
    CHECK_RGB(pixel(10, 2), 1, 1, 1);
    CHECK_RGB(pixel(2, 3), 1, 1, 1);
    CHECK_RGB(pixel(2, 2), 0, 0, 0);
    CHECK_RGB(pixel(10, 3), 0, 0, 0);

    /* LSB first and 3 skipped pixels: bit 3 of byte 0 is pixel 0. */
    static const unsigned char lsb[4] = {0x08, 0, 0, 0};
    rtBeginFrame();
    rtWindowPos2i(5, 5);
    rtPixelStorei(RT_UNPACK_LSB_FIRST, 1);
    rtPixelStorei(RT_UNPACK_SKIP_PIXELS, 3);
    rtBitmap(2, 1, 0, 0, 0, 0, lsb);
    rtPixelStorei(RT_UNPACK_LSB_FIRST, 0);
    rtPixelStorei(RT_UNPACK_SKIP_PIXELS, 0);
    tu_render_float(W, H, px);
    CHECK_NO_ERR();
    CHECK_RGB(pixel(5, 5), 1, 1, 1);
    CHECK_RGB(pixel(6, 5), 0, 0, 0);
}

static void client_stack(void)
{
    tu_section("rtPushClientAttrib / rtPopClientAttrib: pixel store and vertex arrays");
    CHECK_INT(geti(RT_MAX_CLIENT_ATTRIB_STACK_DEPTH), 16);
    CHECK_INT(geti(RT_CLIENT_ATTRIB_STACK_DEPTH), 0);
    static const float verts[9] = {0};
    rtPushClientAttrib(RT_CLIENT_ALL_ATTRIB_BITS);
    CHECK_INT(geti(RT_CLIENT_ATTRIB_STACK_DEPTH), 1);
    rtPixelStorei(RT_UNPACK_ALIGNMENT, 1);
    rtPixelStorei(RT_PACK_ROW_LENGTH, 9);
    rtEnableClientState(RT_VERTEX_ARRAY);
    rtVertexPointer(3, RT_FLOAT, 0, verts);
    rtPopClientAttrib();
    CHECK_INT(geti(RT_CLIENT_ATTRIB_STACK_DEPTH), 0);
    CHECK_INT(geti(RT_UNPACK_ALIGNMENT), 4);
    CHECK_INT(geti(RT_PACK_ROW_LENGTH), 0);
    CHECK(!rtIsEnabled(RT_VERTEX_ARRAY));
    CHECK_NO_ERR();

    /* Only the groups in the mask. */
    rtPushClientAttrib(RT_CLIENT_VERTEX_ARRAY_BIT);
    rtPixelStorei(RT_UNPACK_ALIGNMENT, 2);
    rtEnableClientState(RT_NORMAL_ARRAY);
    rtPopClientAttrib();
    CHECK_INT(geti(RT_UNPACK_ALIGNMENT), 2);
    CHECK(!rtIsEnabled(RT_NORMAL_ARRAY));
    rtPushClientAttrib(RT_CLIENT_PIXEL_STORE_BIT);
    rtPixelStorei(RT_UNPACK_ALIGNMENT, 8);
    rtEnableClientState(RT_COLOR_ARRAY);
    rtPopClientAttrib();
    CHECK_INT(geti(RT_UNPACK_ALIGNMENT), 2);
    CHECK(rtIsEnabled(RT_COLOR_ARRAY));
    rtDisableClientState(RT_COLOR_ARRAY);
    rtPixelStorei(RT_UNPACK_ALIGNMENT, 4);
    CHECK_NO_ERR();

    tu_section("client stack overflow and underflow");
    rtPopClientAttrib();
    CHECK_ERR(RT_STACK_UNDERFLOW);
    for (int i = 0; i < 16; i++)
        rtPushClientAttrib(RT_CLIENT_PIXEL_STORE_BIT);
    CHECK_NO_ERR();
    rtPixelStorei(RT_UNPACK_ALIGNMENT, 1);
    rtPushClientAttrib(RT_CLIENT_PIXEL_STORE_BIT);
    CHECK_ERR(RT_STACK_OVERFLOW);
    CHECK_INT(geti(RT_CLIENT_ATTRIB_STACK_DEPTH), 16);
    for (int i = 0; i < 16; i++)
        rtPopClientAttrib();
    CHECK_NO_ERR();
    CHECK_INT(geti(RT_UNPACK_ALIGNMENT), 4);
    tu_begin_scratch(RT_TRIANGLES);
    rtPushClientAttrib(RT_CLIENT_PIXEL_STORE_BIT);
    CHECK_ERR(RT_INVALID_OPERATION);
    tu_end_scratch();
    CHECK_INT(geti(RT_CLIENT_ATTRIB_STACK_DEPTH), 0);

    tu_section("client state is not compiled into lists");
    rtNewList(720, RT_COMPILE);
    rtPixelStorei(RT_UNPACK_ALIGNMENT, 1);
    rtPushClientAttrib(RT_CLIENT_PIXEL_STORE_BIT);
    rtEndList();
    CHECK_INT(geti(RT_UNPACK_ALIGNMENT), 1);
    CHECK_INT(geti(RT_CLIENT_ATTRIB_STACK_DEPTH), 1);
    rtPopClientAttrib();
    rtPixelStorei(RT_UNPACK_ALIGNMENT, 4);
    rtCallList(720);
    CHECK_INT(geti(RT_UNPACK_ALIGNMENT), 4);
    CHECK_INT(geti(RT_CLIENT_ATTRIB_STACK_DEPTH), 0);
    CHECK_NO_ERR();
}

int main(void)
{
    RTcontext ctx = tu_make_context("threads=2");
    tu_capture_errors();
    defaults_and_errors();
    odd_width_rgb();
    sub_image();
    read_pixels_packing();
    bitmaps();
    client_stack();
    tu_destroy_context(ctx);
    return test_summary("pixel_store");
}
