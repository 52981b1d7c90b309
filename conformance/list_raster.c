/* SPDX-License-Identifier: Apache-2.0 */
/*
 * list_raster.c - what GL allows in and around display lists beyond
 * geometry and state (docs/lists.md): rtClear compiled into a list and
 * run at the call; rtRasterPos / rtWindowPos / rtBitmap compiled into
 * lists (the Red Book's bitmap font: one list per character, called with
 * rtCallLists), unpacked when compiled; rtCallList between rtBegin and
 * rtEnd, the list's vertices continuing the open primitive, in immediate
 * mode and inside a list's own block; errors where GL has them.
 */
#include "testutil.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define W 32
#define H 16
static float img[W * H * 4];

static const float *pixel(int x, int y)
{
    return &img[4 * (y * W + x)];
}

static int is_rgb(int x, int y, float r, float g, float b)
{
    const float *p = pixel(x, y);
    return fabsf(p[0] - r) < 1e-4f && fabsf(p[1] - g) < 1e-4f && fabsf(p[2] - b) < 1e-4f;
}
#define CHECK_PIXEL(x, y, r, g, b)                                                            \
    CHECKF(is_rgb((x), (y), (r), (g), (b)), "pixel (%d, %d) is (%g, %g, %g)", (x), (y),       \
           pixel((x), (y))[0], pixel((x), (y))[1], pixel((x), (y))[2])

/* Window coordinates: one unit a pixel, unlit colours (GL's default). */
static void window_camera(void)
{
    rtShadingMode(RT_FIXED_FUNCTION);
    rtDisable(RT_LIGHTING);
    rtViewport(0, 0, W, H);
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtOrtho(0, W, 0, H, -10, 10);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtClearColor(0, 0, 0, 1);
}

static void read_frame(void)
{
    rtFinish();
    rtReadPixels(0, 0, W, H, RT_RGBA, RT_FLOAT, img);
}

static void quad(float x0, float y0, float x1, float y1)
{
    rtBegin(RT_QUADS);
    rtVertex3f(x0, y0, 0);
    rtVertex3f(x1, y0, 0);
    rtVertex3f(x1, y1, 0);
    rtVertex3f(x0, y1, 0);
    rtEnd();
}

static void clear_in_list(void)
{
    tu_section("rtClear compiled into a list, run at the call");
    window_camera();
    rtNewList(400, RT_COMPILE);
    rtClear(RT_COLOR_BUFFER_BIT | RT_DEPTH_BUFFER_BIT);
    rtEndList();
    CHECK_NO_ERR();
    /* The frame: a red quad, then the list clears it, then a green one. */
    rtClear(RT_COLOR_BUFFER_BIT);
    rtColor3f(1, 0, 0);
    quad(0, 0, 16, 16);
    rtCallList(400);
    rtColor3f(0, 1, 0);
    quad(16, 0, 32, 16);
    read_frame();
    CHECK_NO_ERR();
    CHECK_PIXEL(8, 8, 0, 0, 0);  /* cleared by the list */
    CHECK_PIXEL(24, 8, 0, 1, 0); /* drawn after it */

    tu_section("a list whose rtClear mask is bad: recorded, the error at the call");
    rtNewList(401, RT_COMPILE);
    rtClear(0x1);
    rtEndList();
    CHECK_NO_ERR();
    rtCallList(401);
    CHECK_ERR(RT_INVALID_VALUE);

    tu_section("RT_COMPILE does not clear; rtClear between rtBegin and rtEnd is still an error");
    rtClear(RT_COLOR_BUFFER_BIT);
    rtColor3f(1, 0, 0);
    quad(0, 0, 16, 16);
    rtNewList(402, RT_COMPILE);
    rtClear(RT_COLOR_BUFFER_BIT);
    rtEndList();
    read_frame();
    CHECK_PIXEL(8, 8, 1, 0, 0);
    rtBegin(RT_TRIANGLES);
    rtClear(RT_COLOR_BUFFER_BIT);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtEnd();
    CHECK_NO_ERR();
    rtDeleteLists(400, 3);
}

static void bitmaps_in_lists(void)
{
    tu_section("rtWindowPos and rtBitmap compiled into a list");
    window_camera();
    static const unsigned char bar[4] = {0xFF, 0, 0, 0}; /* 8 pixels, one row */
    rtWindowPos2i(20, 10);
    rtNewList(410, RT_COMPILE);
    rtWindowPos2i(2, 3);
    rtBitmap(8, 1, 0, 0, 10, 0, bar);
    rtEndList();
    CHECK_NO_ERR();
    float pos[4];
    rtGetFloatv(RT_CURRENT_RASTER_POSITION, pos);
    CHECK(pos[0] == 20.0f && pos[1] == 10.0f); /* RT_COMPILE ran nothing */
    rtClear(RT_COLOR_BUFFER_BIT);
    rtColor3f(1, 1, 0);
    rtCallList(410);
    read_frame();
    CHECK_NO_ERR();
    for (int x = 2; x < 10; x++)
        CHECK_PIXEL(x, 3, 1, 1, 0);
    CHECK_PIXEL(1, 3, 0, 0, 0);
    CHECK_PIXEL(10, 3, 0, 0, 0);
    rtGetFloatv(RT_CURRENT_RASTER_POSITION, pos);
    CHECK(pos[0] == 12.0f); /* moved by the list's bitmap */

    tu_section("the Red Book bitmap font: one list per character, rtCallLists");
    /* Two 3x3 glyphs: 'A' a filled square, 'B' a single centre pixel;
     * rows of 1 byte under RT_UNPACK_ALIGNMENT 1, unpacked when compiled
     * (the alignment changes back before the lists run). */
    static const unsigned char glyph_a[3] = {0xE0, 0xE0, 0xE0};
    static const unsigned char glyph_b[3] = {0x00, 0x40, 0x00};
    RTuint base = rtGenLists(128);
    CHECK(base != 0);
    rtPixelStorei(RT_UNPACK_ALIGNMENT, 1);
    rtNewList(base + 'A', RT_COMPILE);
    rtBitmap(3, 3, 0, 0, 4, 0, glyph_a);
    rtEndList();
    rtNewList(base + 'B', RT_COMPILE);
    rtBitmap(3, 3, 0, 0, 4, 0, glyph_b);
    rtEndList();
    rtPixelStorei(RT_UNPACK_ALIGNMENT, 4);
    CHECK_NO_ERR();
    rtClear(RT_COLOR_BUFFER_BIT);
    rtColor3f(1, 1, 1);
    rtWindowPos2i(4, 8);
    rtListBase(base);
    rtCallLists(3, RT_UNSIGNED_BYTE, "ABA");
    rtListBase(0);
    read_frame();
    CHECK_NO_ERR();
    CHECK_PIXEL(4, 8, 1, 1, 1);  /* A at x 4..6 */
    CHECK_PIXEL(6, 10, 1, 1, 1);
    CHECK_PIXEL(8, 8, 0, 0, 0);  /* B at x 8..10: only its centre */
    CHECK_PIXEL(9, 9, 1, 1, 1);
    CHECK_PIXEL(12, 9, 1, 1, 1); /* A again at x 12..14 */
    CHECK_PIXEL(15, 9, 0, 0, 0);
    rtDeleteLists(base, 128);

    tu_section("rtRasterPos in a list is transformed when the list runs");
    rtNewList(411, RT_COMPILE);
    rtRasterPos2f(1, 1);
    rtBitmap(1, 1, 0, 0, 0, 0, bar);
    rtEndList();
    rtClear(RT_COLOR_BUFFER_BIT);
    rtPushMatrix();
    rtTranslatef(5, 4, 0);
    rtCallList(411);
    rtPopMatrix();
    read_frame();
    CHECK_NO_ERR();
    CHECK_PIXEL(6, 5, 1, 1, 1);
    CHECK_PIXEL(1, 1, 0, 0, 0);

    tu_section("RT_COMPILE_AND_EXECUTE draws and records");
    rtClear(RT_COLOR_BUFFER_BIT);
    rtNewList(412, RT_COMPILE_AND_EXECUTE);
    rtWindowPos2i(0, 0);
    rtBitmap(8, 1, 0, 0, 0, 0, bar);
    rtEndList();
    read_frame();
    CHECK_PIXEL(0, 0, 1, 1, 1);
    CHECK_NO_ERR();
    rtDeleteLists(410, 3);
}

static void call_inside_begin(void)
{
    tu_section("rtCallList between rtBegin and rtEnd: the list's vertices join the primitive");
    window_camera();
    /* Two vertices and a colour, recorded outside any rtBegin. */
    rtNewList(420, RT_COMPILE);
    rtColor3f(0, 0, 1);
    rtVertex3f(16, 0, 0);
    rtVertex3f(16, 16, 0);
    rtEndList();
    CHECK_NO_ERR();
    rtClear(RT_COLOR_BUFFER_BIT);
    rtColor3f(1, 1, 1);
    rtShadeModel(RT_FLAT); /* the last vertex's colour (GL's provoking vertex) */
    rtBegin(RT_TRIANGLES);
    rtVertex3f(0, 0, 0);
    rtCallList(420);
    rtEnd();
    rtShadeModel(RT_SMOOTH);
    CHECK_NO_ERR();
    read_frame();
    CHECK_PIXEL(12, 6, 0, 0, 1);
    CHECK_PIXEL(24, 6, 0, 0, 0);
    float c[4];
    rtGetFloatv(RT_CURRENT_COLOR, c);
    CHECK(c[2] == 1.0f && c[0] == 0.0f); /* the list's colour stays current */

    tu_section("rtCallLists between rtBegin and rtEnd");
    rtNewList(421, RT_COMPILE);
    rtVertex3f(32, 0, 0);
    rtEndList();
    rtNewList(422, RT_COMPILE);
    rtVertex3f(32, 16, 0);
    rtEndList();
    rtClear(RT_COLOR_BUFFER_BIT);
    rtShadeModel(RT_FLAT);
    rtColor3f(0, 1, 0);
    rtBegin(RT_TRIANGLES);
    rtVertex3f(16, 0, 0);
    const RTuint two[2] = {421, 422};
    rtCallLists(2, RT_UNSIGNED_INT, two);
    rtEnd();
    rtShadeModel(RT_SMOOTH);
    read_frame();
    CHECK_NO_ERR();
    CHECK_PIXEL(28, 6, 0, 1, 0);
    CHECK_PIXEL(8, 6, 0, 0, 0);

    tu_section("a call inside a list's own rtBegin/rtEnd is expanded into the block");
    rtNewList(423, RT_COMPILE);
    rtColor3f(1, 0, 0);
    rtBegin(RT_TRIANGLES);
    rtVertex3f(0, 0, 0);
    rtCallList(421);
    rtVertex3f(0, 16, 0);
    rtEnd();
    rtEndList();
    CHECK_NO_ERR();
    rtClear(RT_COLOR_BUFFER_BIT);
    rtCallList(423);
    read_frame();
    CHECK_NO_ERR();
    CHECK_PIXEL(4, 8, 1, 0, 0);

    tu_section("errors: a list with primitives or matrix calls called between rtBegin and rtEnd");
    rtNewList(424, RT_COMPILE);
    quad(0, 0, 4, 4);
    rtEndList();
    rtNewList(425, RT_COMPILE);
    rtTranslatef(1, 0, 0);
    rtEndList();
    rtClear(RT_COLOR_BUFFER_BIT);
    rtBegin(RT_TRIANGLES);
    rtCallList(424);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtCallList(425);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtEnd();
    CHECK_NO_ERR();
    float m[16];
    rtGetFloatv(RT_MODELVIEW_MATRIX, m);
    CHECK(m[12] == 0.0f);
    /* Bare vertices called where no primitive is open do nothing (Mesa). */
    rtCallList(420);
    CHECK_NO_ERR();
    read_frame();
    CHECK_PIXEL(2, 2, 0, 0, 0);
    rtDeleteLists(420, 6);
}

int main(void)
{
    RTcontext ctx = tu_make_context("threads=2");
    tu_capture_errors();
    clear_in_list();
    bitmaps_in_lists();
    call_inside_begin();
    tu_destroy_context(ctx);
    return test_summary("list_raster");
}
