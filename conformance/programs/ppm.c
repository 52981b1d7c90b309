/* SPDX-License-Identifier: Apache-2.0 */
/* ppm.c - binary PPM (P6) reading and writing (ppm.h). */
#include "ppm.h"

#include <stdio.h>
#include <stdlib.h>

int ppm_write(const char *path, int width, int height, const unsigned char *rgba)
{
    FILE *f = fopen(path, "wb");
    int x, y, ok;
    if (!f)
        return 0;
    fprintf(f, "P6\n%d %d\n255\n", width, height);
    for (y = height - 1; y >= 0; y--)
        for (x = 0; x < width; x++)
            fwrite(rgba + 4 * ((size_t)y * width + x), 1, 3, f);
    ok = !ferror(f);
    return fclose(f) == 0 && ok;
}

unsigned char *ppm_read(const char *path, int *width, int *height)
{
    FILE *f = fopen(path, "rb");
    unsigned char *rgba = NULL;
    int w, h, maxval, x, y;
    if (!f)
        return NULL;
    if (fscanf(f, "P6 %d %d %d", &w, &h, &maxval) == 3 && maxval == 255 && w > 0 && h > 0 &&
        w < 16384 && h < 16384 && fgetc(f) != EOF) {
        rgba = malloc((size_t)w * h * 4);
        for (y = h - 1; rgba && y >= 0; y--)
            for (x = 0; x < w; x++) {
                unsigned char *p = rgba + 4 * ((size_t)y * w + x);
                if (fread(p, 1, 3, f) != 3) {
                    free(rgba);
                    rgba = NULL;
                    break;
                }
                p[3] = 255;
            }
    }
    fclose(f);
    if (rgba) {
        *width = w;
        *height = h;
    }
    return rgba;
}
