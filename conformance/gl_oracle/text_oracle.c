/* SPDX-License-Identifier: Apache-2.0 */
/*
 * text_oracle.c - the OpenGL oracle's text test (docs/gl_oracle.md,
 * docs/text.md): the scene of text_scene.inc rendered by OSMesa (a sphere
 * in a display list, then glRasterPos/glWindowPos and glBitmap, with the
 * depth test off for the bitmaps as programs draw text) and by Tracelist
 * (rtRasterPos/rtWindowPos and rtBitmap, drawn over the traced image).
 *
 * Bitmap pixels carry the raster colour exactly (yellow or cyan, which no
 * shaded surface here produces), so the text is compared pixel for pixel:
 * every pixel must be text of the same colour in both images or text in
 * neither.  The rest is compared by coverage as the other scenes (the
 * sphere's shading differs: GL draws it unlit white).
 *
 * Usage: conf_gl_oracle_text [--out DIR] [--docs DIR]: write the GL |
 * Tracelist | difference triptych to DIR/text.png or
 * DIR/gl_oracle_text.png.
 */
#include <GL/gl.h>

#include <rt/rt.h>
#include <rt/rtu.h>

#include "oracle.h"
#include "text_oracle.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PIXELS ((size_t)ORACLE_W * ORACLE_H)
#define GAP 4
#define TRIPTYCH_W (3 * ORACLE_W + 2 * GAP)
/* Coverage of the sphere: as the other scenes (oracle_main.c). */
#define MIN_MATCH 99.9

void text_pattern(unsigned char *bits, int width, int height, unsigned seed)
{
    const int stride = ((width + 7) / 8 + 3) / 4 * 4;
    unsigned state = seed * 2654435761u + 12345u;
    int i;
    memset(bits, 0, (size_t)stride * (size_t)height);
    for (i = 0; i < stride * height; i++) {
        state = state * 1103515245u + 12345u;
        bits[i] = (unsigned char)(state >> 16);
    }
}

static int render_gl(unsigned char *rgba)
{
    GLenum error;
    (void)oracle_gl_render; /* the scene renderer of the other test */
    glViewport(0, 0, ORACLE_W, ORACLE_H);
    glClearColor(ORACLE_BG_R, ORACLE_BG_G, ORACLE_BG_B, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_LIGHTING);
    glColor3f(1.0f, 1.0f, 1.0f);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    text_projection_gl();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glNewList(1, GL_COMPILE);
    text_shape_gl();
    glEndList();
    text_view_gl();
    glCallList(1);
    glDeleteLists(1, 1);
    glDisable(GL_DEPTH_TEST);
    text_overlay_gl();
    glFinish();
    error = glGetError();
    if (error != GL_NO_ERROR) {
        fprintf(stderr, "gl_oracle/text: GL error 0x%x\n", error);
        return 0;
    }
    glReadPixels(0, 0, ORACLE_W, ORACLE_H, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    return 1;
}

static int render_rt(unsigned char *rgba)
{
    static const RTfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    const RTuint object = 1;
    RTenum error;
    rtViewport(0, 0, ORACLE_W, ORACLE_H);
    rtClearColor(ORACLE_BG_R, ORACLE_BG_G, ORACLE_BG_B, 1.0f);
    rtColor3f(1.0f, 1.0f, 1.0f);
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    text_projection_rt();
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtNewObject(object);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT_AND_DIFFUSE, white);
    text_shape_rt();
    rtEndObject();
    text_view_rt();
    rtBeginFrame();
    rtInstantiateObject(object);
    text_overlay_rt();
    rtRenderFrame();
    rtReadPixels(0, 0, ORACLE_W, ORACLE_H, RT_RGBA, RT_UNSIGNED_BYTE, rgba);
    rtDeleteObjects(1, &object);
    error = rtGetError();
    if (error != RT_NO_ERROR) {
        fprintf(stderr, "gl_oracle/text: Tracelist error 0x%x\n", error);
        return 0;
    }
    return 1;
}

/* 1 yellow text, 2 cyan text, 0 anything else. */
static int text_class(const unsigned char *p)
{
    if (p[0] == 255 && p[1] == 255 && p[2] == 0)
        return 1;
    if (p[0] == 0 && p[1] == 255 && p[2] == 255)
        return 2;
    return 0;
}

static int covered(const unsigned char *p)
{
    return p[0] != 255 || p[1] != 0 || p[2] != 255;
}

static void blit(unsigned char *dst, int x, const unsigned char *src)
{
    int row;
    for (row = 0; row < ORACLE_H; row++)
        memcpy(dst + 4 * ((size_t)row * TRIPTYCH_W + (size_t)x), src + 4 * (size_t)row * ORACLE_W,
               4 * (size_t)ORACLE_W);
}

int main(int argc, char **argv)
{
    static unsigned char gl[4 * PIXELS], rt[4 * PIXELS], diff[4 * PIXELS];
    static unsigned char triptych[4 * (size_t)TRIPTYCH_W * ORACLE_H];
    size_t i, text_gl = 0, text_rt = 0, text_off = 0, cover_off = 0;
    const char *out_dir = NULL, *docs_dir = NULL;
    double match;
    int k, failed = 0;
    for (k = 1; k + 1 < argc; k += 2) {
        if (strcmp(argv[k], "--out") == 0)
            out_dir = argv[k + 1];
        else if (strcmp(argv[k], "--docs") == 0)
            docs_dir = argv[k + 1];
    }
    if (!oracle_gl_init() || !oracle_rt_init())
        return 1;
    if (!render_gl(gl) || !render_rt(rt))
        return 1;
    for (i = 0; i < PIXELS; i++) {
        const unsigned char *a = gl + 4 * i, *b = rt + 4 * i;
        unsigned char *d = diff + 4 * i;
        const int ta = text_class(a), tb = text_class(b);
        text_gl += ta != 0;
        text_rt += tb != 0;
        d[0] = d[1] = d[2] = 0;
        d[3] = 255;
        if (ta != tb) {
            text_off++;
            d[0] = d[1] = 255; /* yellow: a text mismatch */
        } else if (ta) {
            d[0] = d[1] = d[2] = 160; /* grey: text in both */
        } else if (covered(a) != covered(b)) {
            cover_off++;
            d[covered(a) ? 0 : 1] = 255; /* red: GL only, green: Tracelist only */
        } else if (covered(a)) {
            d[0] = d[1] = d[2] = 255;
        }
    }
    match = 100.0 * (double)(PIXELS - cover_off) / (double)PIXELS;
    printf("gl_oracle/text: text pixels GL %zu, Tracelist %zu, differing %zu; "
           "coverage elsewhere %.3f%% (%zu pixels differ)\n",
           text_gl, text_rt, text_off, match, cover_off);
    if (text_off != 0 || text_gl < 500 || match < MIN_MATCH) {
        printf("gl_oracle/text: FAILED (text must match pixel for pixel; coverage >= %.1f%%)\n",
               MIN_MATCH);
        failed = 1;
    }
    memset(triptych, 64, sizeof triptych);
    blit(triptych, 0, gl);
    blit(triptych, ORACLE_W + GAP, rt);
    blit(triptych, 2 * (ORACLE_W + GAP), diff);
    for (k = 0; k < 2; k++) {
        const char *dir = k ? docs_dir : out_dir;
        char path[1024];
        if (!dir)
            continue;
        snprintf(path, sizeof path, "%s/%s.%s", dir, k ? "gl_oracle_text" : "text",
                 rtuImageFormatSupported("png") ? "png" : "ppm");
        if (!rtuSaveImage(path, TRIPTYCH_W, ORACLE_H, RT_UNSIGNED_BYTE, triptych)) {
            fprintf(stderr, "gl_oracle/text: %s\n", rtuImageError());
            failed = 1;
        }
    }
    oracle_gl_finish();
    oracle_rt_finish();
    return failed;
}
