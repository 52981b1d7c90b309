/* SPDX-License-Identifier: Apache-2.0 */
/*
 * font.c - rtuBitmapCharacter, rtuBitmapString, rtuBitmapWidth,
 * rtuBitmapLength, rtuBitmapHeight: GLUT's bitmap text (Kilgard 1996,
 * sec. 10.1) with rtu's glyphs (font_internal.h).
 *
 * As GLUT, a character is one glBitmap (here rtBitmap) at the current
 * raster position that advances it by the character's width: the glyph's
 * lower-left corner lies DESCENT dots below the baseline, and the glyph is
 * centred in its advance.  Only printable ASCII has glyphs; other codes
 * draw nothing and do not move the position.
 */
#include "font_internal.h"
#include "report.h"

#include <rt/rtu.h>

#include <stdint.h>
#include <string.h>

/* The font behind an RTU_BITMAP_* name, NULL (and an error recorded
 * against `caller`) for anything else. */
static const struct rtu_font *lookup(void *font, const char *caller)
{
    const uintptr_t id = (uintptr_t)font;
    if (id < 2 || id >= 2 + RTU_FONT_COUNT) {
        rtu_record_error(RT_INVALID_VALUE, caller, "not one of the RTU_BITMAP_* fonts");
        return NULL;
    }
    return &rtu_fonts[id - 2];
}

static const struct rtu_glyph *glyph(int character)
{
    if (character < RTU_FONT_FIRST || character >= RTU_FONT_FIRST + RTU_FONT_GLYPHS)
        return NULL;
    return &rtu_glyphs[character - RTU_FONT_FIRST];
}

static void draw(const struct rtu_font *f, int character)
{
    /* Rows of up to 5 * RTU_FONT_MAX_SCALE = 10 bits: 2 bytes, padded to
     * GL's 4-byte row alignment. */
    enum { STRIDE = 4 };
    unsigned char bits[RTU_FONT_ROWS * RTU_FONT_MAX_SCALE * STRIDE];
    const struct rtu_glyph *g = glyph(character);
    const int s = f->scale;
    int width, height, advance, offset, r, dy, i, k;
    if (!g)
        return;
    width = g->width * s;
    height = RTU_FONT_ROWS * s;
    advance = f->advance[character - RTU_FONT_FIRST];
    offset = advance > width ? (advance - width) / 2 : 0;
    memset(bits, 0, sizeof(bits));
    for (r = 0; r < RTU_FONT_ROWS; r++)
        for (dy = 0; dy < s; dy++) {
            unsigned char *row = bits + (size_t)(r * s + dy) * STRIDE;
            for (i = 0; i < g->width; i++)
                if (g->rows[r] & (0x80u >> i))
                    for (k = 0; k < s; k++)
                        row[(i * s + k) / 8] |= (unsigned char)(0x80u >> ((i * s + k) % 8));
        }
    rtBitmap(width, height, (RTfloat)-offset, (RTfloat)(RTU_FONT_DESCENT * s), (RTfloat)advance,
             0.0f, bits);
}

void rtuBitmapCharacter(void *font, int character)
{
    const struct rtu_font *f = lookup(font, "rtuBitmapCharacter");
    if (f)
        draw(f, character);
}

void rtuBitmapString(void *font, const unsigned char *string)
{
    const struct rtu_font *f = lookup(font, "rtuBitmapString");
    int line = 0;
    if (!f || !string)
        return;
    for (; *string; string++) {
        const struct rtu_glyph *g = glyph(*string);
        if (*string == '\n') {
            /* freeglut's glutBitmapString: back to the line's start, one
             * line height down. */
            rtBitmap(0, 0, 0.0f, 0.0f, (RTfloat)-line, (RTfloat)-f->height, NULL);
            line = 0;
        } else if (g) {
            draw(f, *string);
            line += f->advance[*string - RTU_FONT_FIRST];
        }
    }
}

int rtuBitmapWidth(void *font, int character)
{
    const struct rtu_font *f = lookup(font, "rtuBitmapWidth");
    if (!f || !glyph(character))
        return 0;
    return f->advance[character - RTU_FONT_FIRST];
}

int rtuBitmapLength(void *font, const unsigned char *string)
{
    const struct rtu_font *f = lookup(font, "rtuBitmapLength");
    int longest = 0, line = 0;
    if (!f || !string)
        return 0;
    for (; *string; string++) {
        if (*string == '\n') {
            line = 0;
        } else if (glyph(*string)) {
            line += f->advance[*string - RTU_FONT_FIRST];
            if (line > longest)
                longest = line;
        }
    }
    return longest;
}

int rtuBitmapHeight(void *font)
{
    const struct rtu_font *f = lookup(font, "rtuBitmapHeight");
    return f ? f->height : 0;
}
