/* SPDX-License-Identifier: Apache-2.0 */
/*
 * compare_images.c - the comparison of the programs' two builds: a GL
 * image (Mesa) and a Tracelist image of the same program, per pixel.
 *
 *   compare_images GL.ppm RT.ppm --background R,G,B [--coverage P]
 *                  [--tolerance T] [--colour P] [--diff DIFF.ppm]
 *
 * A pixel is covered when some channel differs from the background (the
 * program's clear colour, given as GL floats) by more than one 8-bit step
 * (the two may round the clear colour differently).  Coverage matches
 * where both images cover a pixel or neither does; the colour of a pixel
 * both cover matches when every channel is within T steps.  Coverage is
 * measured against what GL draws, not against the whole image (where a
 * small object would hide any difference): the pixels covered by one image
 * only, as a percentage of the pixels GL covers, are the coverage error,
 * and coverage matches to 100% minus that.  Passes when coverage matches
 * to at least P% (default 98), at least P% of the pixels both cover match
 * in colour (default 95, T default 12), and
 * the GL image covers at least 2% of the image (an empty GL image would
 * let an empty Tracelist image pass).  Comparing an image with itself
 * checks the GL side alone.  The difference image: white both cover and
 * match, yellow both cover but the colour is off, red only GL covers,
 * green only Tracelist, black neither.
 */
#include "ppm.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int covered(const unsigned char *p, const int background[3])
{
    int k;
    for (k = 0; k < 3; k++)
        if (abs((int)p[k] - background[k]) > 1)
            return 1;
    return 0;
}

int main(int argc, char **argv)
{
    const char *diff_path = NULL;
    double min_coverage = 98.0, min_colour = 95.0, coverage, colour;
    int tolerance = 12, background[3] = {-1000, -1000, -1000};
    int gw, gh, rw, rh, i;
    size_t n, k, gl_px = 0, rt_px = 0, gl_only = 0, rt_only = 0, both = 0, colour_ok = 0;
    unsigned char *gl, *rt, *diff;
    int pass;
    for (i = 3; i + 1 < argc; i += 2) {
        if (strcmp(argv[i], "--background") == 0) {
            float c[3];
            int j;
            if (sscanf(argv[i + 1], "%f,%f,%f", &c[0], &c[1], &c[2]) != 3)
                break;
            for (j = 0; j < 3; j++)
                background[j] = (int)(c[j] * 255.0f + 0.5f);
        } else if (strcmp(argv[i], "--coverage") == 0)
            min_coverage = atof(argv[i + 1]);
        else if (strcmp(argv[i], "--tolerance") == 0)
            tolerance = atoi(argv[i + 1]);
        else if (strcmp(argv[i], "--colour") == 0)
            min_colour = atof(argv[i + 1]);
        else if (strcmp(argv[i], "--diff") == 0)
            diff_path = argv[i + 1];
        else
            break;
    }
    if (argc < 3 || i < argc || background[0] == -1000) {
        fprintf(stderr, "usage: compare_images GL.ppm RT.ppm --background R,G,B [--coverage P] "
                        "[--tolerance T] [--colour P] [--diff DIFF.ppm]\n");
        return 2;
    }
    gl = ppm_read(argv[1], &gw, &gh);
    rt = ppm_read(argv[2], &rw, &rh);
    if (!gl || !rt) {
        fprintf(stderr, "compare_images: cannot read %s\n", !gl ? argv[1] : argv[2]);
        return 1;
    }
    if (gw != rw || gh != rh) {
        fprintf(stderr, "compare_images: sizes differ: %dx%d and %dx%d\n", gw, gh, rw, rh);
        return 1;
    }
    n = (size_t)gw * gh;
    diff = malloc(4 * n);
    if (!diff)
        return 1;
    for (k = 0; k < n; k++) {
        const unsigned char *a = gl + 4 * k, *b = rt + 4 * k;
        unsigned char *d = diff + 4 * k;
        int ca = covered(a, background), cb = covered(b, background);
        d[0] = d[1] = d[2] = 0;
        d[3] = 255;
        gl_px += ca;
        rt_px += cb;
        if (ca && cb) {
            int c, off = 0;
            for (c = 0; c < 3; c++)
                off |= abs((int)a[c] - (int)b[c]) > tolerance;
            both++;
            colour_ok += !off;
            d[0] = d[1] = 255;
            d[2] = off ? 0 : 255;
        } else if (ca) {
            gl_only++;
            d[0] = 255;
        } else if (cb) {
            rt_only++;
            d[1] = 255;
        }
    }
    coverage = gl_px ? 100.0 - 100.0 * (double)(gl_only + rt_only) / (double)gl_px : 0.0;
    if (coverage < 0.0)
        coverage = 0.0;
    colour = both ? 100.0 * (double)colour_ok / (double)both : 100.0;
    pass = coverage >= min_coverage && colour >= min_colour && gl_px >= n / 50;
    printf("compare_images: %.3f%% of the image matches; coverage %.3f%% of GL's (GL %zu px, "
           "Tracelist %zu px, GL only %zu, Tracelist only %zu; need %.1f%%); colour %.3f%% of "
           "%zu px within %d steps (need %.1f%%): %s\n",
           100.0 * (double)(n - gl_only - rt_only - (both - colour_ok)) / (double)n, coverage,
           gl_px, rt_px, gl_only, rt_only, min_coverage, colour, both, tolerance, min_colour,
           pass ? "PASS" : "FAIL");
    if (gl_px < n / 50)
        printf("compare_images: the GL image covers less than 2%% of the pixels\n");
    if (diff_path && !ppm_write(diff_path, gw, gh, diff)) {
        fprintf(stderr, "compare_images: cannot write %s\n", diff_path);
        pass = 0;
    }
    free(gl);
    free(rt);
    free(diff);
    return !pass;
}
