/*
 * rtu.h - the Tracelist utility library (the analogue of GLU).
 *
 * Built only on rt.h: everything here could be written by an application.
 * Camera helpers multiply the current matrix exactly as their GLU
 * namesakes do; image I/O goes through OpenImageIO when the library was
 * built with it and falls back to binary PPM (8 bit) / PFM (float)
 * otherwise.  Compiles as strict C99 and as C++.
 */
#ifndef RT_RTU_H
#define RT_RTU_H

#include <rt/rt.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Multiplies the current matrix by a perspective projection (gluPerspective).
 * fovy in degrees; records RT_INVALID_VALUE (through the core entry point
 * it calls) for fovy outside (0, 180), aspect <= 0, zNear <= 0 or
 * zFar <= zNear, and then changes nothing. */
RTAPI void rtuPerspective(RTdouble fovy, RTdouble aspect, RTdouble zNear, RTdouble zFar);

/* Multiplies the current matrix by a viewing transform (gluLookAt).  A
 * degenerate frame (eye == center, or up parallel to the view direction)
 * changes nothing and records RT_INVALID_VALUE. */
RTAPI void rtuLookAt(RTdouble eyeX, RTdouble eyeY, RTdouble eyeZ, RTdouble centerX,
                     RTdouble centerY, RTdouble centerZ, RTdouble upX, RTdouble upY,
                     RTdouble upZ);

/*
 * Writes an RGBA image as read by rtReadPixels (rows bottom to top, 4
 * components per pixel), type RT_UNSIGNED_BYTE or RT_FLOAT.  The format
 * follows the file name's extension: .ppm and .pfm are always available;
 * others (.png, .exr, .jpg, ...) need OpenImageIO.  Returns RT_TRUE on
 * success; RT_FALSE on a bad argument, an unsupported extension or an I/O
 * error, with a reason available from rtuImageError().
 */
RTAPI RTboolean rtuSaveImage(const char *path, RTsizei width, RTsizei height, RTenum type,
                             const void *pixels);

/*
 * Reads an image into a newly allocated RGBA buffer of the given type
 * (RT_UNSIGNED_BYTE or RT_FLOAT), rows bottom to top like rtReadPixels.
 * .ppm (P6, maxval 255) and .pfm are always available; other formats need
 * OpenImageIO.  Returns NULL on failure (reason from rtuImageError());
 * release with rtuFreeImage.
 */
RTAPI void *rtuLoadImage(const char *path, RTsizei *width, RTsizei *height, RTenum type);
RTAPI void rtuFreeImage(void *pixels);

/* RT_TRUE when rtuSaveImage can write files with this extension ("png"). */
RTAPI RTboolean rtuImageFormatSupported(const char *extension);

/* The reason the last rtuSaveImage/rtuLoadImage on this thread failed. */
RTAPI const char *rtuImageError(void);

#ifdef __cplusplus
}
#endif

#endif /* RT_RTU_H */
