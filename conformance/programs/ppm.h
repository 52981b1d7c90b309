/* SPDX-License-Identifier: Apache-2.0 */
/* ppm.h - binary PPM (P6) files of RGBA images with rows bottom to top
 * (glReadPixels order), for the program harnesses and compare_images. */
#ifndef PROGRAMS_PPM_H
#define PROGRAMS_PPM_H

/* Writes rgba (width * height * 4 bytes) as P6, top row first; alpha is
 * dropped.  Returns 1 on success. */
int ppm_write(const char *path, int width, int height, const unsigned char *rgba);

/* Reads a P6 file (maxval 255) into a malloc'ed RGBA buffer, rows bottom
 * to top, alpha 255.  Returns NULL on failure. */
unsigned char *ppm_read(const char *path, int *width, int *height);

#endif /* PROGRAMS_PPM_H */
