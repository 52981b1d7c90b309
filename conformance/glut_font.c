/* SPDX-License-Identifier: Apache-2.0 */
/*
 * glut_font.c - rtu's bitmap fonts (docs/text.md): GLUT's metrics (line
 * heights, advances of fixed and proportional fonts, string lengths with
 * newlines), the glyph placed in its cell (lower-left DESCENT below the
 * baseline, centred in its advance, scaled by 2 in the large fonts) pixel
 * for pixel, the raster position advanced as GLUT's, rtuBitmapString's
 * newline, and bad fonts reported.
 */
#include <rt/rt.h>
#include <rt/rtu.h>

#include "testutil.h"

#include <string.h>

#define W 96
#define H 48

static float image[W * H * 4];

static void render(void)
{
    rtRenderFrame();
    rtReadPixels(0, 0, W, H, RT_RGBA, RT_FLOAT, image);
}

static int ink(int x, int y)
{
    return image[4 * (y * W + x)] == 1.0f;
}

/* Ink pixels in the rectangle [x0, x1) x [y0, y1). */
static int count(int x0, int y0, int x1, int y1)
{
    int x, y, n = 0;
    for (y = y0; y < y1; y++)
        for (x = x0; x < x1; x++)
            n += ink(x, y);
    return n;
}

static void test_metrics(void)
{
    CHECK_INT(rtuBitmapHeight(RTU_BITMAP_8_BY_13), 14);
    CHECK_INT(rtuBitmapHeight(RTU_BITMAP_9_BY_15), 16);
    CHECK_INT(rtuBitmapHeight(RTU_BITMAP_TIMES_ROMAN_10), 14);
    CHECK_INT(rtuBitmapHeight(RTU_BITMAP_TIMES_ROMAN_24), 29);
    CHECK_INT(rtuBitmapHeight(RTU_BITMAP_HELVETICA_10), 14);
    CHECK_INT(rtuBitmapHeight(RTU_BITMAP_HELVETICA_12), 16);
    CHECK_INT(rtuBitmapHeight(RTU_BITMAP_HELVETICA_18), 23);
    CHECK_INT(rtuBitmapWidth(RTU_BITMAP_8_BY_13, 'W'), 8);
    CHECK_INT(rtuBitmapWidth(RTU_BITMAP_8_BY_13, 'i'), 8);
    CHECK_INT(rtuBitmapWidth(RTU_BITMAP_9_BY_15, 'i'), 9);
    CHECK_INT(rtuBitmapWidth(RTU_BITMAP_TIMES_ROMAN_10, 'W'), 10);
    CHECK_INT(rtuBitmapWidth(RTU_BITMAP_TIMES_ROMAN_24, 'W'), 23);
    CHECK_INT(rtuBitmapWidth(RTU_BITMAP_HELVETICA_10, 'i'), 2);
    CHECK_INT(rtuBitmapWidth(RTU_BITMAP_HELVETICA_12, 'W'), 11);
    CHECK_INT(rtuBitmapWidth(RTU_BITMAP_HELVETICA_18, 'T'), 12);
    CHECK_INT(rtuBitmapWidth(RTU_BITMAP_HELVETICA_18, '\n'), 0);
    CHECK_INT(rtuBitmapWidth(RTU_BITMAP_HELVETICA_18, 200), 0);
    CHECK_INT(rtuBitmapLength(RTU_BITMAP_HELVETICA_12, (const unsigned char *)"iW"), 3 + 11);
    CHECK_INT(rtuBitmapLength(RTU_BITMAP_8_BY_13, (const unsigned char *)"ab\ncde\nf"), 24);
    CHECK_INT(rtuBitmapLength(RTU_BITMAP_8_BY_13, NULL), 0);
    CHECK_NO_ERR();
    /* Not a font: reported, nothing drawn. */
    CHECK_INT(rtuBitmapWidth((void *)0x0001, 'a'), 0);
    CHECK_ERR(RT_INVALID_VALUE);
    rtuBitmapCharacter(NULL, 'a');
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_INT(rtuBitmapHeight((void *)0x0009), 0);
    CHECK_ERR(RT_INVALID_VALUE);
}

static void test_drawing(void)
{
    float pos[4];
    int x;
    rtViewport(0, 0, W, H);
    rtClearColor(0, 0, 0, 0);
    rtColor3f(1, 1, 1);
    /* 'T' of 8x13 at (10, 10): glyph 5 wide centred in 8 (from x = 11),
     * its cell from y = 10 - 2 (descent); the bar on the cap line y = 16,
     * the stem at x = 13 from the baseline y = 10 up. */
    rtWindowPos2i(10, 10);
    rtuBitmapCharacter(RTU_BITMAP_8_BY_13, 'T');
    rtGetFloatv(RT_CURRENT_RASTER_POSITION, pos);
    CHECK_NEAR(pos[0], 18.0, 0.0);
    CHECK_NEAR(pos[1], 10.0, 0.0);
    /* 'T' of Helvetica 18 at (40, 10): dots of 2 x 2 pixels, 10 wide
     * centred in 12 (from x = 41), the cell from y = 10 - 4. */
    rtWindowPos2i(40, 10);
    rtuBitmapCharacter(RTU_BITMAP_HELVETICA_18, 'T');
    /* A string with a newline at (60, 30): back to x = 60, 14 down. */
    rtWindowPos2i(60, 30);
    rtuBitmapString(RTU_BITMAP_8_BY_13, (const unsigned char *)"ab\n.");
    rtGetFloatv(RT_CURRENT_RASTER_POSITION, pos);
    CHECK_NEAR(pos[0], 68.0, 0.0);
    CHECK_NEAR(pos[1], 16.0, 0.0);
    CHECK_NO_ERR();
    render();
    for (x = 11; x < 16; x++)
        CHECKF(ink(x, 16), "8x13 'T' bar at x = %d", x);
    CHECK(!ink(10, 16) && !ink(16, 16) && !ink(11, 17) && !ink(11, 15));
    CHECK_INT(count(13, 10, 14, 17), 7);
    CHECK_INT(count(8, 0, 20, 40), 5 + 6); /* the whole glyph: bar and stem */
    for (x = 41; x < 51; x++)
        CHECKF(ink(x, 22) && ink(x, 23), "Helvetica 18 'T' bar at x = %d", x);
    CHECK(!ink(40, 22) && !ink(51, 23) && !ink(41, 24));
    CHECK_INT(count(45, 10, 47, 24), 28); /* the stem: 2 wide, 7 dots of 2 */
    CHECK_INT(count(38, 0, 56, 40), 4 * (5 + 6));
    /* The '.' of the second line: one dot on the baseline y = 16, at the
     * centre of its 8 cell (glyph width 1, from x = 60 + 3). */
    CHECK(ink(63, 16));
    CHECK_INT(count(58, 8, 70, 20), 1);
    CHECK(count(60, 30, 76, 40) > 10); /* "ab" on the first line */
}

int main(void)
{
    RTcontext ctx = tu_make_context("threads=2");
    test_metrics();
    test_drawing();
    tu_destroy_context(ctx);
    return test_summary("glut_font");
}
