/* SPDX-License-Identifier: Apache-2.0 */
/*
 * image_internal.h - the split between image.c (C, built-in PPM/PFM, the
 * public rtu image entry points) and image_oiio.cpp (C++, OpenImageIO).
 *
 * image.c owns argument checking and the per-thread error message;
 * image_oiio.cpp is compiled only when the library is built with
 * OpenImageIO (RTU_HAVE_OIIO) and is reached only through these three
 * functions.  They are hidden: nothing here is part of the rtu ABI.
 *
 * Pixel convention on both sides of the split is the one of rtReadPixels:
 * tightly packed RGBA, 4 components per pixel, rows bottom to top.
 * is_float selects RTfloat components (non-zero) or RTubyte (zero).
 */
#ifndef RT_RTU_IMAGE_INTERNAL_H
#define RT_RTU_IMAGE_INTERNAL_H

#include <stddef.h>

#if defined(__GNUC__)
#define RTU_HIDDEN __attribute__((visibility("hidden")))
#else
#define RTU_HIDDEN
#endif

/* Longest error message kept by rtuImageError(), terminator included. */
#define RTU_IMAGE_ERROR_SIZE 512

#ifdef __cplusplus
extern "C" {
#endif

/*
 * Writes width x height RGBA pixels to path in the format OpenImageIO picks
 * from the extension.  The caller has checked every argument (path non-NULL,
 * sizes positive, pixels non-NULL).  Alpha is written when the format can
 * hold it and dropped otherwise.  Returns 1 on success; 0 on failure with a
 * NUL-terminated reason in error[0..error_size).  Never throws.
 */
RTU_HIDDEN int rtu_oiio_save(const char *path, int width, int height, int is_float,
                             const void *pixels, char *error, size_t error_size);

/*
 * Reads the first subimage of path into a malloc'ed RGBA buffer (free()
 * releases it), converting channels (1: grey, 2: grey+alpha, 3: RGB with
 * alpha 1, 4 or more: the first four) and the component type.  Stores the
 * size in *width and *height only on success.  Returns NULL on failure
 * with a reason in error.  Never throws.
 */
RTU_HIDDEN void *rtu_oiio_load(const char *path, int *width, int *height, int is_float,
                               char *error, size_t error_size);

/* 1 when OpenImageIO can write files with this extension (no dot), else 0. */
RTU_HIDDEN int rtu_oiio_can_write(const char *extension);

#ifdef __cplusplus
}
#endif

#endif /* RT_RTU_IMAGE_INTERNAL_H */
