/* SPDX-License-Identifier: Apache-2.0 */
/*
 * oracle_main.c - the OpenGL oracle test: renders every scene of
 * scenes.inc with Mesa (OSMesa + libGLU) and with Tracelist (+ rtu) and
 * compares the two images pixel by pixel.
 *
 * A pixel is "covered" when it is not the clear colour.  It matches when
 * both images cover it or neither does, and, for scenes with a colour
 * tolerance (none yet: Tracelist has no GL shading mode), when a pixel
 * both cover has every channel within that tolerance.  The test prints the
 * percentage of matching pixels per scene and fails a scene below
 * ORACLE_MIN_MATCH percent.
 *
 * Usage: conf_gl_oracle [--out DIR] [--docs DIR]
 *   --out DIR   write each scene's GL | Tracelist | difference image to
 *               DIR/<family>_<name>.png (.ppm without OpenImageIO)
 *   --docs DIR  write one side-by-side sheet per family to
 *               DIR/gl_oracle_<family>.png (for docs/gl_oracle.md)
 * Difference colours: white both cover, red only GL, green only
 * Tracelist, black neither; yellow a colour mismatch.
 */
#include "oracle.h"

#include <rt/rt.h>
#include <rt/rtu.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Matching pixels, percent of the image, below which a scene fails.  The
 * two renderers sample the same pixel centres, so they differ only where a
 * centre lies within rounding of an edge (GL's fixed-point rasterizer vs.
 * the ray/triangle test): at most 2 of the 25600 pixels in every scene
 * today (99.992%).  99.9% (25 pixels) leaves room for that and still
 * fails a sphere whose slices are turned by a quarter slice (55 pixels). */
#define ORACLE_MIN_MATCH 99.9

#define PIXELS ((size_t)ORACLE_W * ORACLE_H)

/* Scenes with limits of their own (docs/gl_oracle.md).  sparse: lines or
 * points only, which cover fewer pixels than the check against an empty
 * GL image expects (2% of the image): 0.25% then.  min_match: a threshold
 * other than ORACLE_MIN_MATCH (a wireframe over its own surface z-fights
 * in GL, and the stitch pixels land differently). */
static const struct {
    const char *label;
    int sparse;
    double min_match;
} scene_limits[] = {
    {"lines/segments_width1", 1, 0.0},     {"lines/strips_loops_wide", 1, 0.0},
    {"lines/points_sizes", 1, 0.0},        {"lines/wireframe_over_fill", 0, 99.5},
    {"lines/polygon_mode_line", 1, 0.0},   {"lines/polygon_mode_point", 1, 0.0},
    {"lines/vertex_arrays", 1, 0.0},       {"clip/lines_and_points", 1, 0.0},
    {"lines/points_on_pixel_edges", 1, 0.0}, {"lines/widths_immediate", 1, 0.0},
    {"polymode/culled_wire_and_points", 1, 0.0}, {"polymode/own_line_list_call_culls", 1, 0.0},
};

static void limits_of(const char *label, int *sparse, double *min_match)
{
    size_t i;
    *sparse = 0;
    *min_match = ORACLE_MIN_MATCH;
    for (i = 0; i < sizeof scene_limits / sizeof scene_limits[0]; i++)
        if (strcmp(scene_limits[i].label, label) == 0) {
            *sparse = scene_limits[i].sparse;
            if (scene_limits[i].min_match > 0.0)
                *min_match = scene_limits[i].min_match;
        }
}
/* The sheet of a family: scenes in rows of two triptychs. */
#define PANEL_GAP 4
#define SHEET_COLUMNS 2
#define TRIPTYCH_W (3 * ORACLE_W + 2 * PANEL_GAP)

static int covered(const unsigned char *p)
{
    return p[0] != (unsigned char)(ORACLE_BG_R * 255) || p[1] != (unsigned char)(ORACLE_BG_G * 255) ||
           p[2] != (unsigned char)(ORACLE_BG_B * 255);
}

struct comparison {
    size_t gl_covered, rt_covered, gl_only, rt_only, colour_off;
    double match_percent;
};

/* Compares and fills diff (RGBA8) with the difference image. */
static void compare(const struct oracle_scene *scene, const unsigned char *gl,
                    const unsigned char *rt, unsigned char *diff, struct comparison *c)
{
    size_t i, mismatched;
    memset(c, 0, sizeof *c);
    for (i = 0; i < PIXELS; i++) {
        const unsigned char *a = gl + 4 * i, *b = rt + 4 * i;
        unsigned char *d = diff + 4 * i;
        const int ca = covered(a), cb = covered(b);
        unsigned char r = 0, g = 0, bl = 0;
        c->gl_covered += ca;
        c->rt_covered += cb;
        if (ca && cb) {
            r = g = bl = 255;
            if (scene->colour_tolerance > 0) {
                int k, off = 0;
                for (k = 0; k < 3; k++)
                    off |= abs((int)a[k] - (int)b[k]) > scene->colour_tolerance;
                if (off) {
                    c->colour_off++;
                    bl = 0;
                }
            }
        } else if (ca) {
            c->gl_only++;
            r = 255;
        } else if (cb) {
            c->rt_only++;
            g = 255;
        }
        d[0] = r;
        d[1] = g;
        d[2] = bl;
        d[3] = 255;
    }
    mismatched = c->gl_only + c->rt_only + c->colour_off;
    c->match_percent = 100.0 * (double)(PIXELS - mismatched) / (double)PIXELS;
}

/*
 * Checks that the colour comparison works: on one rendered image against itself
 * (all match) and against a copy with the covered pixels' red channel
 * moved by tolerance + 1 (every covered pixel a colour mismatch) and by
 * the tolerance itself (none).  Returns 1 when it behaves.
 */
static int colour_comparison_works(const unsigned char *image, unsigned char *copy,
                                   unsigned char *diff)
{
    struct oracle_scene scene = {"self", "colour", NULL, NULL, NULL, 3};
    struct comparison c;
    size_t i, covered_pixels = 0;
    int ok;
    compare(&scene, image, image, diff, &c);
    ok = c.match_percent == 100.0 && c.colour_off == 0;
    for (i = 0; i < PIXELS; i++) {
        memcpy(copy + 4 * i, image + 4 * i, 4);
        if (covered(image + 4 * i)) {
            covered_pixels++;
            copy[4 * i] = (unsigned char)(image[4 * i] > 128 ? image[4 * i] - 4 : image[4 * i] + 4);
        }
    }
    compare(&scene, image, copy, diff, &c);
    ok &= c.colour_off == covered_pixels && covered_pixels > 0;
    for (i = 0; i < PIXELS; i++)
        if (covered(image + 4 * i))
            copy[4 * i] = (unsigned char)(image[4 * i] > 128 ? image[4 * i] - 3 : image[4 * i] + 3);
    compare(&scene, image, copy, diff, &c);
    ok &= c.colour_off == 0;
    if (!ok)
        fprintf(stderr, "gl_oracle: the colour comparison does not work\n");
    return ok;
}

/* Copies an RGBA8 image (rows bottom to top) into a larger one at (x, y)
 * from its top-left corner. */
static void blit(unsigned char *dst, int dst_w, int dst_h, int x, int y,
                 const unsigned char *src)
{
    int row;
    for (row = 0; row < ORACLE_H; row++) {
        /* Source row `row` from the bottom is destination row
         * y + ORACLE_H - 1 - row from the top, i.e. dst_h - 1 - that from
         * the bottom. */
        int dst_row = dst_h - 1 - (y + ORACLE_H - 1 - row);
        memcpy(dst + 4 * ((size_t)dst_row * dst_w + x), src + 4 * (size_t)row * ORACLE_W,
               4 * (size_t)ORACLE_W);
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

static const char *image_extension(void)
{
    return rtuImageFormatSupported("png") ? "png" : "ppm";
}

static int save(const char *path, int w, int h, const unsigned char *rgba)
{
    if (!rtuSaveImage(path, w, h, RT_UNSIGNED_BYTE, rgba)) {
        fprintf(stderr, "gl_oracle: cannot write %s: %s\n", path, rtuImageError());
        return 0;
    }
    return 1;
}

int main(int argc, char **argv)
{
    const char *out_dir = NULL, *docs_dir = NULL;
    unsigned char *gl, *rt, *diff, *triptych, **sheets;
    int i, failures = 0, f;
    const char *families[] = {"quadrics", "glut", "projections", "lists", "lines", "blend", "clip",
                              "polymode"};
    const int family_count = 8;
    int family_scenes[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    for (i = 1; i + 1 < argc; i += 2) {
        if (strcmp(argv[i], "--out") == 0)
            out_dir = argv[i + 1];
        else if (strcmp(argv[i], "--docs") == 0)
            docs_dir = argv[i + 1];
    }
    if (oracle_scene_count_gl != oracle_scene_count_rt) {
        fprintf(stderr, "gl_oracle: scene lists differ\n");
        return 1;
    }
    gl = malloc(4 * PIXELS);
    rt = malloc(4 * PIXELS);
    diff = malloc(4 * PIXELS);
    triptych = malloc(4 * (size_t)TRIPTYCH_W * ORACLE_H);
    sheets = calloc((size_t)family_count, sizeof *sheets);
    if (!gl || !rt || !diff || !triptych || !sheets || !oracle_gl_init() || !oracle_rt_init())
        return 1;
    for (i = 0; i < oracle_scene_count_gl; i++)
        for (f = 0; f < family_count; f++)
            family_scenes[f] += strcmp(oracle_scenes_gl[i].family, families[f]) == 0;
    if (docs_dir)
        for (f = 0; f < family_count; f++) {
            int rows = (family_scenes[f] + SHEET_COLUMNS - 1) / SHEET_COLUMNS;
            int w = SHEET_COLUMNS * TRIPTYCH_W + (SHEET_COLUMNS - 1) * 3 * PANEL_GAP;
            int h = rows * ORACLE_H + (rows - 1) * PANEL_GAP;
            sheets[f] = malloc(4 * (size_t)w * (size_t)h);
            if (!sheets[f])
                return 1;
            fill(sheets[f], (size_t)w * (size_t)h, 255);
        }

    printf("%-36s %9s %8s %8s %7s %7s %7s\n", "scene", "match %", "GL px", "RT px", "GL-only",
           "RT-only", "colour");
    for (i = 0; i < oracle_scene_count_gl; i++) {
        const struct oracle_scene *scene = &oracle_scenes_gl[i];
        struct comparison c;
        char label[128];
        int ok = oracle_gl_render(scene, gl) && oracle_rt_render(&oracle_scenes_rt[i], rt);
        snprintf(label, sizeof label, "%s/%s", scene->family, scene->name);
        if (!ok) {
            printf("%-36s FAILED (render)\n", label);
            failures++;
            continue;
        }
        /* (Before this scene's comparison: it uses diff as scratch.) */
        if (i == 0 && !colour_comparison_works(rt, triptych, diff))
            failures++;
        compare(scene, gl, rt, diff, &c);
        {
            int sparse, bad;
            double min_match;
            limits_of(label, &sparse, &min_match);
            /* An empty GL image would make any empty Tracelist image pass. */
            bad = c.match_percent < min_match || c.gl_covered < (sparse ? PIXELS / 400 : PIXELS / 50);
            printf("%-36s %9.3f %8zu %8zu %7zu %7zu %7zu%s\n", label, c.match_percent,
                   c.gl_covered, c.rt_covered, c.gl_only, c.rt_only, c.colour_off,
                   bad ? "  FAILED" : "");
            failures += bad;
        }
        fill(triptych, (size_t)TRIPTYCH_W * ORACLE_H, 64);
        blit(triptych, TRIPTYCH_W, ORACLE_H, 0, 0, gl);
        blit(triptych, TRIPTYCH_W, ORACLE_H, ORACLE_W + PANEL_GAP, 0, rt);
        blit(triptych, TRIPTYCH_W, ORACLE_H, 2 * (ORACLE_W + PANEL_GAP), 0, diff);
        if (out_dir) {
            char path[1024];
            snprintf(path, sizeof path, "%s/%s_%s.%s", out_dir, scene->family, scene->name,
                     image_extension());
            if (!save(path, TRIPTYCH_W, ORACLE_H, triptych))
                failures++;
        }
        if (docs_dir)
            for (f = 0; f < family_count; f++)
                if (strcmp(scene->family, families[f]) == 0) {
                    /* The scene's index within its family places it. */
                    int k, index = 0, rows, w, h, x, y, row;
                    for (k = 0; k < i; k++)
                        index += strcmp(oracle_scenes_gl[k].family, families[f]) == 0;
                    rows = (family_scenes[f] + SHEET_COLUMNS - 1) / SHEET_COLUMNS;
                    w = SHEET_COLUMNS * TRIPTYCH_W + (SHEET_COLUMNS - 1) * 3 * PANEL_GAP;
                    h = rows * ORACLE_H + (rows - 1) * PANEL_GAP;
                    x = (index % SHEET_COLUMNS) * (TRIPTYCH_W + 3 * PANEL_GAP);
                    y = (index / SHEET_COLUMNS) * (ORACLE_H + PANEL_GAP);
                    for (row = 0; row < ORACLE_H; row++) {
                        int dst_row = h - 1 - (y + ORACLE_H - 1 - row);
                        memcpy(sheets[f] + 4 * ((size_t)dst_row * w + x),
                               triptych + 4 * (size_t)row * TRIPTYCH_W, 4 * (size_t)TRIPTYCH_W);
                    }
                }
    }
    if (docs_dir)
        for (f = 0; f < family_count; f++) {
            char path[1024];
            int rows = (family_scenes[f] + SHEET_COLUMNS - 1) / SHEET_COLUMNS;
            int w = SHEET_COLUMNS * TRIPTYCH_W + (SHEET_COLUMNS - 1) * 3 * PANEL_GAP;
            int h = rows * ORACLE_H + (rows - 1) * PANEL_GAP;
            snprintf(path, sizeof path, "%s/gl_oracle_%s.%s", docs_dir, families[f],
                     image_extension());
            if (!save(path, w, h, sheets[f]))
                failures++;
            free(sheets[f]);
        }
    oracle_gl_finish();
    oracle_rt_finish();
    free(gl);
    free(rt);
    free(diff);
    free(triptych);
    free(sheets);
    printf("gl_oracle: %d scenes, %d failed (threshold %.1f%% matching pixels)\n",
           oracle_scene_count_gl, failures, ORACLE_MIN_MATCH);
    return failures != 0;
}
