/* SPDX-License-Identifier: Apache-2.0 */
/*
 * overlay_oracle.c - the OpenGL oracle's overlay test (docs/gl_oracle.md,
 * docs/overlay_geometry.md): the scenes of overlay_scene.inc, geometry
 * drawn under a projection or viewport other than the 3D scene's (a HUD
 * under a pushed gluOrtho2D, a background drawn first, a minimap inset),
 * rendered by OSMesa and by Tracelist (which traces the scene and
 * rasterises the rest), compared per pixel: a pixel matches when every
 * channel is within TOLERANCE 8-bit steps.
 *
 * Usage: conf_gl_oracle_overlay [--out DIR] [--docs DIR]: writes a
 * GL | Tracelist | difference row per scene to DIR/overlay.png or
 * DIR/gl_oracle_overlay.png.
 */
#include <GL/gl.h>

#include <rt/rt.h>
#include <rt/rtu.h>

#include "oracle.h"
#include "overlay_oracle.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PIXELS ((size_t)ORACLE_W * ORACLE_H)
#define GAP 4
#define ROW_W (3 * ORACLE_W + 2 * GAP)
#define TOLERANCE 3
/* Matching pixels per scene the test asks for. */
#define MIN_MATCH 99.9

struct overlay_scene {
    const char *name;
    void (*draw_gl)(void);
    void (*draw_rt)(void);
};

#define SCENE(n) {#n, overlay_##n##_gl, overlay_##n##_rt}
static const struct overlay_scene scenes[] = {
    SCENE(panel), SCENE(crosshair), SCENE(depth_on),
    SCENE(background), SCENE(lit), SCENE(text_panel), SCENE(unpushed),
    SCENE(textured),
};
#define SCENE_COUNT ((int)(sizeof scenes / sizeof scenes[0]))

void overlay_pattern(unsigned char *bits, int width, int height, unsigned seed)
{
    const int stride = ((width + 7) / 8 + 3) / 4 * 4;
    unsigned state = seed * 2654435761u + 12345u;
    int i;
    for (i = 0; i < stride * height; i++) {
        state = state * 1103515245u + 12345u;
        bits[i] = (unsigned char)(state >> 16);
    }
}

static const float light0_position[4] = {0.0f, 0.0f, 1.0f, 0.0f};
static const float default_ambient[4] = {0.2f, 0.2f, 0.2f, 1.0f};
static const float default_diffuse[4] = {0.8f, 0.8f, 0.8f, 1.0f};

static int render_gl(const struct overlay_scene *s, unsigned char *rgba)
{
    GLenum error;
    (void)oracle_gl_render; /* the scene renderer of the other test */
    glViewport(0, 0, ORACLE_W, ORACLE_H);
    glClearColor(ORACLE_BG_R, ORACLE_BG_G, ORACLE_BG_B, 1.0f);
    glDisable(GL_BLEND);
    glDisable(GL_LIGHTING);
    glDisable(GL_COLOR_MATERIAL);
    glShadeModel(GL_SMOOTH);
    glColor4f(1.0f, 1.0f, 1.0f, 1.0f);
    glLineWidth(1.0f);
    glPointSize(1.0f);
    glDepthMask(GL_TRUE);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glLightfv(GL_LIGHT0, GL_POSITION, light0_position);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, default_ambient);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, default_diffuse);
    glNewList(1, GL_COMPILE);
    overlay_shape_gl();
    glEndList();
    glNewList(2, GL_COMPILE);
    overlay_panel_list_gl();
    glEndList();
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    s->draw_gl();
    glFinish();
    glDeleteLists(1, 2);
    error = glGetError();
    if (error != GL_NO_ERROR) {
        fprintf(stderr, "gl_oracle/overlay: %s: GL error 0x%x\n", s->name, error);
        return 0;
    }
    glReadPixels(0, 0, ORACLE_W, ORACLE_H, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    return 1;
}

static int render_rt(const struct overlay_scene *s, unsigned char *rgba)
{
    RTenum error;
    rtViewport(0, 0, ORACLE_W, ORACLE_H);
    rtClearColor(ORACLE_BG_R, ORACLE_BG_G, ORACLE_BG_B, 1.0f);
    rtDisable(RT_BLEND);
    rtDisable(RT_LIGHTING);
    rtDisable(RT_COLOR_MATERIAL);
    rtShadeModel(RT_SMOOTH);
    rtColor4f(1.0f, 1.0f, 1.0f, 1.0f);
    rtLineWidth(1.0f);
    rtPointSize(1.0f);
    rtDepthMask(RT_TRUE);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtLightfv(RT_LIGHT0, RT_POSITION, light0_position);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, default_ambient);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, default_diffuse);
    rtNewList(1, RT_COMPILE);
    overlay_shape_rt();
    rtEndList();
    rtNewList(2, RT_COMPILE);
    overlay_panel_list_rt();
    rtEndList();
    rtClear(RT_COLOR_BUFFER_BIT | RT_DEPTH_BUFFER_BIT);
    s->draw_rt();
    rtReadPixels(0, 0, ORACLE_W, ORACLE_H, RT_RGBA, RT_UNSIGNED_BYTE, rgba);
    rtDeleteLists(1, 2);
    error = rtGetError();
    if (error != RT_NO_ERROR) {
        fprintf(stderr, "gl_oracle/overlay: %s: Tracelist error 0x%x\n", s->name, error);
        return 0;
    }
    return 1;
}

static void blit(unsigned char *dst, int x, const unsigned char *src)
{
    int row;
    for (row = 0; row < ORACLE_H; row++)
        memcpy(dst + 4 * ((size_t)row * ROW_W + (size_t)x), src + 4 * (size_t)row * ORACLE_W,
               4 * (size_t)ORACLE_W);
}

int main(int argc, char **argv)
{
    static unsigned char gl[4 * PIXELS], rt[4 * PIXELS], diff[4 * PIXELS];
    const size_t row_bytes = 4 * (size_t)ROW_W * (ORACLE_H + GAP);
    unsigned char *sheet = malloc(row_bytes * SCENE_COUNT);
    const char *out_dir = NULL, *docs_dir = NULL;
    int k, failed = 0;
    for (k = 1; k + 1 < argc; k += 2) {
        if (strcmp(argv[k], "--out") == 0)
            out_dir = argv[k + 1];
        else if (strcmp(argv[k], "--docs") == 0)
            docs_dir = argv[k + 1];
    }
    if (!sheet || !oracle_gl_init() || !oracle_rt_init())
        return 1;
    memset(sheet, 64, row_bytes * SCENE_COUNT);
    for (k = 0; k < SCENE_COUNT; k++) {
        size_t i, off = 0;
        double match;
        if (!render_gl(&scenes[k], gl) || !render_rt(&scenes[k], rt))
            return 1;
        for (i = 0; i < PIXELS; i++) {
            const unsigned char *a = gl + 4 * i, *b = rt + 4 * i;
            unsigned char *d = diff + 4 * i;
            int c, worst = 0;
            for (c = 0; c < 3; c++) {
                const int e = abs((int)a[c] - (int)b[c]);
                worst = e > worst ? e : worst;
            }
            d[0] = d[1] = d[2] = 0;
            d[3] = 255;
            if (worst > TOLERANCE) {
                if (getenv("OVERLAY_ORACLE_VERBOSE") && off < 40)
                    printf("  (%d, %d): GL %d %d %d, Tracelist %d %d %d\n", (int)(i % ORACLE_W),
                           (int)(i / ORACLE_W), a[0], a[1], a[2], b[0], b[1], b[2]);
                off++;
                d[0] = 255; /* red: differs */
            } else if (a[0] != 255 || a[1] != 0 || a[2] != 255) {
                d[0] = d[1] = d[2] = 96; /* grey: drawn, matching */
            }
        }
        match = 100.0 * (double)(PIXELS - off) / (double)PIXELS;
        printf("gl_oracle/overlay/%s: %.3f%% of the pixels match (%zu differ by more than %d)\n",
               scenes[k].name, match, off, TOLERANCE);
        if (match < MIN_MATCH) {
            printf("gl_oracle/overlay/%s: FAILED (at least %.1f%% must match)\n", scenes[k].name,
                   MIN_MATCH);
            failed = 1;
        }
        /* Rows top to bottom in the image: scene k at row SCENE_COUNT-1-k
         * of the bottom-up sheet. */
        {
            unsigned char *row = sheet + row_bytes * (size_t)(SCENE_COUNT - 1 - k);
            blit(row, 0, gl);
            blit(row, ORACLE_W + GAP, rt);
            blit(row, 2 * (ORACLE_W + GAP), diff);
        }
    }
    for (k = 0; k < 2; k++) {
        const char *dir = k ? docs_dir : out_dir;
        char path[1024];
        if (!dir)
            continue;
        snprintf(path, sizeof path, "%s/%s.%s", dir, k ? "gl_oracle_overlay" : "overlay",
                 rtuImageFormatSupported("png") ? "png" : "ppm");
        if (!rtuSaveImage(path, ROW_W, (ORACLE_H + GAP) * SCENE_COUNT, RT_UNSIGNED_BYTE,
                          sheet)) {
            fprintf(stderr, "gl_oracle/overlay: %s\n", rtuImageError());
            failed = 1;
        }
    }
    free(sheet);
    oracle_gl_finish();
    oracle_rt_finish();
    return failed;
}
