/* SPDX-License-Identifier: Apache-2.0 */
/*
 * shade_oracle.c - the OpenGL colour oracle: every scene of
 * shade_scenes.inc (lighting switches, faces, fog, texture environment,
 * texture coordinate generation)
 * rendered by Mesa's OSMesa and by Tracelist in its default
 * RT_FIXED_FUNCTION mode, compared per pixel for coverage AND colour.
 *
 * Coverage as in oracle_main.c (a pixel is covered when it is not the
 * clear colour).  Colour: of the pixels both cover, the share whose three
 * channels all lie within the scene's tolerance (3 of 255) of GL's.  A
 * scene passes with coverage matching on at least SHADE_MIN_COVERAGE
 * percent of the image and colour matching on at least SHADE_MIN_COLOUR
 * percent of the covered pixels.  The table prints both percentages and
 * the largest channel difference.
 *
 * Usage: conf_gl_shade_oracle [--out DIR] [--docs DIR]
 *   --out DIR   each scene's GL | Tracelist | difference to DIR/shade_<family>_<name>.png
 *   --docs DIR  one sheet per family, DIR/gl_oracle_<family>.png
 * Difference image: the absolute colour difference times 16 (white where
 * only one side covers).
 */
#include "oracle.h"

#include <rt/rt.h>
#include <rt/rtu.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SHADE_MIN_COVERAGE 99.5
#define SHADE_MIN_COLOUR 99.0

#define PIXELS ((size_t)ORACLE_W * ORACLE_H)
#define PANEL_GAP 4
#define SHEET_COLUMNS 2
#define TRIPTYCH_W (3 * ORACLE_W + 2 * PANEL_GAP)

static int covered(const unsigned char *p)
{
    return p[0] != 255 || p[1] != 0 || p[2] != 255;
}

struct shade_comparison {
    size_t both, coverage_off, colour_ok;
    int max_diff;
    double coverage_percent, colour_percent;
};

static void compare(const struct oracle_scene *scene, const unsigned char *gl,
                    const unsigned char *rt, unsigned char *diff, struct shade_comparison *c)
{
    size_t i;
    memset(c, 0, sizeof *c);
    for (i = 0; i < PIXELS; i++) {
        const unsigned char *a = gl + 4 * i, *b = rt + 4 * i;
        unsigned char *d = diff + 4 * i;
        const int ca = covered(a), cb = covered(b);
        int k, worst = 0;
        d[3] = 255;
        if (ca != cb) {
            c->coverage_off++;
            d[0] = d[1] = d[2] = 255;
            continue;
        }
        for (k = 0; k < 3; k++) {
            int delta = abs((int)a[k] - (int)b[k]);
            worst = delta > worst ? delta : worst;
            d[k] = (unsigned char)(delta * 16 > 255 ? 255 : delta * 16);
        }
        if (!ca)
            continue;
        c->both++;
        c->colour_ok += worst <= scene->colour_tolerance;
        c->max_diff = worst > c->max_diff ? worst : c->max_diff;
    }
    c->coverage_percent = 100.0 * (double)(PIXELS - c->coverage_off) / (double)PIXELS;
    c->colour_percent = c->both ? 100.0 * (double)c->colour_ok / (double)c->both : 0.0;
}

static void blit(unsigned char *dst, int dst_w, int dst_h, int x, int y, const unsigned char *src,
                 int src_w, int src_h)
{
    int row;
    for (row = 0; row < src_h; row++) {
        int dst_row = dst_h - 1 - (y + src_h - 1 - row);
        memcpy(dst + 4 * ((size_t)dst_row * dst_w + x), src + 4 * (size_t)row * src_w,
               4 * (size_t)src_w);
    }
}

static void fill(unsigned char *img, size_t pixels, unsigned char grey)
{
    size_t i;
    for (i = 0; i < pixels; i++) {
        img[4 * i] = img[4 * i + 1] = img[4 * i + 2] = grey;
        img[4 * i + 3] = 255;
    }
}

static int save(const char *path, int w, int h, const unsigned char *rgba)
{
    if (!rtuSaveImage(path, w, h, RT_UNSIGNED_BYTE, rgba)) {
        fprintf(stderr, "gl_shade_oracle: cannot write %s: %s\n", path, rtuImageError());
        return 0;
    }
    return 1;
}

int main(int argc, char **argv)
{
    const char *out_dir = NULL, *docs_dir = NULL;
    const char *families[] = {"lighting", "faces", "fog", "texenv", "texgen", "per_primitive",
                              "texcoord4"};
    enum { FAMILIES = 7 };
    unsigned char *gl, *rt, *diff, *triptych, *sheets[FAMILIES] = {NULL};
    int sheet_w = SHEET_COLUMNS * TRIPTYCH_W + (SHEET_COLUMNS - 1) * 3 * PANEL_GAP;
    int sheet_h[FAMILIES] = {0}, placed[FAMILIES] = {0};
    int i, f, failures = 0;
    const char *ext = rtuImageFormatSupported("png") ? "png" : "ppm";
    for (i = 1; i + 1 < argc; i += 2) {
        if (strcmp(argv[i], "--out") == 0)
            out_dir = argv[i + 1];
        else if (strcmp(argv[i], "--docs") == 0)
            docs_dir = argv[i + 1];
    }
    if (oracle_scene_count_gl != oracle_scene_count_rt) {
        fprintf(stderr, "gl_shade_oracle: scene lists differ\n");
        return 1;
    }
    gl = malloc(4 * PIXELS);
    rt = malloc(4 * PIXELS);
    diff = malloc(4 * PIXELS);
    triptych = malloc(4 * (size_t)TRIPTYCH_W * ORACLE_H);
    if (!gl || !rt || !diff || !triptych || !oracle_gl_init() || !oracle_rt_init())
        return 1;
    for (f = 0; f < FAMILIES; f++) {
        int n = 0, rows;
        for (i = 0; i < oracle_scene_count_gl; i++)
            n += strcmp(oracle_scenes_gl[i].family, families[f]) == 0;
        rows = (n + SHEET_COLUMNS - 1) / SHEET_COLUMNS;
        sheet_h[f] = rows > 0 ? rows * ORACLE_H + (rows - 1) * PANEL_GAP : 0;
        if (docs_dir && rows > 0) {
            sheets[f] = malloc(4 * (size_t)sheet_w * (size_t)sheet_h[f]);
            if (!sheets[f])
                return 1;
            fill(sheets[f], (size_t)sheet_w * (size_t)sheet_h[f], 255);
        }
    }
    printf("%-34s %10s %9s %9s %8s\n", "scene", "coverage %", "colour %", "max diff",
           "pixels");
    for (i = 0; i < oracle_scene_count_gl; i++) {
        const struct oracle_scene *scene = &oracle_scenes_gl[i];
        struct shade_comparison c;
        char label[128];
        int ok;
        snprintf(label, sizeof label, "%s/%s", scene->family, scene->name);
        if (!oracle_gl_render(scene, gl) || !oracle_rt_render(&oracle_scenes_rt[i], rt)) {
            printf("%-34s FAILED (render)\n", label);
            failures++;
            continue;
        }
        compare(scene, gl, rt, diff, &c);
        ok = c.coverage_percent >= SHADE_MIN_COVERAGE && c.colour_percent >= SHADE_MIN_COLOUR &&
             c.both >= PIXELS / 50;
        printf("%-34s %10.3f %9.3f %9d %8zu%s\n", label, c.coverage_percent, c.colour_percent,
               c.max_diff, c.both, ok ? "" : "  FAILED");
        failures += !ok;
        fill(triptych, (size_t)TRIPTYCH_W * ORACLE_H, 64);
        blit(triptych, TRIPTYCH_W, ORACLE_H, 0, 0, gl, ORACLE_W, ORACLE_H);
        blit(triptych, TRIPTYCH_W, ORACLE_H, ORACLE_W + PANEL_GAP, 0, rt, ORACLE_W, ORACLE_H);
        blit(triptych, TRIPTYCH_W, ORACLE_H, 2 * (ORACLE_W + PANEL_GAP), 0, diff, ORACLE_W,
             ORACLE_H);
        if (out_dir) {
            char path[1024];
            snprintf(path, sizeof path, "%s/shade_%s_%s.%s", out_dir, scene->family,
                     scene->name, ext);
            failures += !save(path, TRIPTYCH_W, ORACLE_H, triptych);
        }
        for (f = 0; f < FAMILIES; f++)
            if (sheets[f] && strcmp(scene->family, families[f]) == 0) {
                int x = (placed[f] % SHEET_COLUMNS) * (TRIPTYCH_W + 3 * PANEL_GAP);
                int y = (placed[f] / SHEET_COLUMNS) * (ORACLE_H + PANEL_GAP);
                blit(sheets[f], sheet_w, sheet_h[f], x, y, triptych, TRIPTYCH_W, ORACLE_H);
                placed[f]++;
            }
    }
    for (f = 0; f < FAMILIES; f++)
        if (sheets[f]) {
            char path[1024];
            snprintf(path, sizeof path, "%s/gl_oracle_%s.%s", docs_dir, families[f], ext);
            failures += !save(path, sheet_w, sheet_h[f], sheets[f]);
            free(sheets[f]);
        }
    oracle_gl_finish();
    oracle_rt_finish();
    free(gl);
    free(rt);
    free(diff);
    free(triptych);
    printf("gl_shade_oracle: %d scenes, %d failed (coverage >= %.1f%% of the image, colour "
           "within %d/255 on >= %.1f%% of covered pixels)\n",
           oracle_scene_count_gl, failures, SHADE_MIN_COVERAGE, 3, SHADE_MIN_COLOUR);
    return failures != 0;
}
