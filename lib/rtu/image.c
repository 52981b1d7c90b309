/* SPDX-License-Identifier: Apache-2.0 */
/*
 * image.c - rtu image I/O: rtuSaveImage, rtuLoadImage, rtuFreeImage,
 * rtuImageFormatSupported, rtuImageError.
 *
 * Pixels in memory are what rtReadPixels returns: tightly packed RGBA,
 * RTubyte (RT_UNSIGNED_BYTE) or RTfloat (RT_FLOAT) components, rows bottom
 * to top.  Two formats are built in and always available:
 *
 *   PPM  binary "P6" (Netpbm): header "P6 <w> <h> <maxval>", then rows top
 *        to bottom, RGB.  Written with maxval 255; read with any maxval
 *        1..65535 (two bytes per sample, big-endian, above 255).  Alpha is
 *        dropped on writing and set to opaque on reading.
 *   PFM  "PF" (RGB) / "Pf" (grey) portable float map: header
 *        "PF\n<w> <h>\n<scale>\n", then rows BOTTOM to top (the same order as
 *        rtReadPixels), 32-bit IEEE floats, little-endian when scale < 0,
 *        big-endian when scale > 0.  Written as RGB, little-endian, scale
 *        -1.0; the magnitude of the scale is ignored on reading.
 *
 * rtuSaveImage picks the format from the extension (case-insensitive);
 * rtuLoadImage from the file's first two bytes, so a PPM or PFM is read by
 * the built-in reader whatever it is called.  Anything else goes to
 * OpenImageIO when the library was built with it (RTU_HAVE_OIIO,
 * image_oiio.cpp) and fails with a message otherwise.
 *
 * Float <-> byte conversion: byte = round(clamp(f, 0, 1) * 255) (NaN -> 0),
 * the rounding of rtReadPixels; float = byte / 255.
 *
 * Errors: every entry point returns a failure value instead of crashing on
 * bad arguments, unreadable, truncated or malformed files, and leaves a
 * reason in a per-thread buffer read by rtuImageError().  That buffer
 * (`image_error`, __thread) is the only thread-local state in rtu; rtu
 * keeps no other global state, so these functions may be called from any
 * number of threads at once, with or without a current context.
 */
#include <rt/rt.h>
#include <rt/rtu.h>

#include "image_internal.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/*
 * Largest width or height rtuLoadImage accepts from a PPM/PFM header, and
 * the largest pixel count.  They bound what a malformed header can make us
 * allocate (4 GiB of float RGBA at the pixel limit) and keep every size
 * computation below far from overflow.  16384 is rtViewport's limit; we
 * accept four times that per side for images that are not framebuffers.
 * tag-rtu-image-limits: image_oiio.cpp applies the same limits.
 */
#define RTU_IMAGE_MAX_SIDE 65536L
#define RTU_IMAGE_MAX_PIXELS (1L << 28)

/* The reason the last rtuSaveImage/rtuLoadImage on this thread failed ("" after a success). */
/* __thread is a GNU extension (gcc and clang have it; C11 spells it
 * _Thread_local), as lib/base/atomic.h documents for the core library. */
static __thread char image_error[RTU_IMAGE_ERROR_SIZE];

static void set_error(const char *fmt, ...)
{
    va_list args;
    va_start(args, fmt);
    vsnprintf(image_error, sizeof image_error, fmt, args);
    va_end(args);
}

/* "what: <strerror(errno)>", thread-safely (XSI strerror_r). */
static void set_errno_error(const char *what)
{
    char reason[128];
    int saved = errno;
    if (saved == 0 || strerror_r(saved, reason, sizeof reason) != 0)
        snprintf(reason, sizeof reason, "error %d", saved);
    set_error("%s: %s", what, reason);
}

/* Prefixes the pending reason with the entry point and the file name. */
static void prefix_error(const char *caller, const char *path)
{
    char reason[RTU_IMAGE_ERROR_SIZE];
    memcpy(reason, image_error, sizeof reason);
    set_error("%s(%s): %s", caller, path, reason);
}

/* ---------------------------------------------------------------- helpers */

static char ascii_lower(char c)
{
    return (c >= 'A' && c <= 'Z') ? (char)(c - 'A' + 'a') : c;
}

/* Case-insensitive ASCII comparison (locale-independent, unlike strcasecmp). */
static int extension_is(const char *extension, const char *lower)
{
    while (*extension != '\0' && *lower != '\0') {
        if (ascii_lower(*extension) != *lower)
            return 0;
        extension++;
        lower++;
    }
    return *extension == '\0' && *lower == '\0';
}

/* The text after the last '.' of the file name part of path ("" if none). */
static const char *path_extension(const char *path)
{
    const char *base = path;
    const char *p;
    const char *dot = NULL;
    for (p = path; *p != '\0'; p++) {
        if (*p == '/' || *p == '\\')
            base = p + 1;
    }
    for (p = base; *p != '\0'; p++) {
        if (*p == '.')
            dot = p;
    }
    return dot != NULL ? dot + 1 : "";
}

static unsigned char float_to_byte(float f)
{
    if (!(f > 0.0f)) /* also NaN */
        return 0;
    if (f >= 1.0f)
        return 255;
    return (unsigned char)(f * 255.0f + 0.5f);
}

/* Bytes of one image in memory, or 0 when it would not fit in a size_t. */
static size_t image_bytes(long width, long height, int is_float)
{
    size_t pixel = 4 * (is_float ? sizeof(float) : 1);
    if ((size_t)width > SIZE_MAX / pixel / (size_t)height)
        return 0;
    return (size_t)width * (size_t)height * pixel;
}

/* IEEE single <-> 4 bytes, explicit byte order, independent of the host's. */
static void put_float_le(unsigned char *out, float f)
{
    uint32_t bits;
    memcpy(&bits, &f, sizeof bits);
    out[0] = (unsigned char)(bits & 0xFFu);
    out[1] = (unsigned char)((bits >> 8) & 0xFFu);
    out[2] = (unsigned char)((bits >> 16) & 0xFFu);
    out[3] = (unsigned char)((bits >> 24) & 0xFFu);
}

static float get_float(const unsigned char *in, int little_endian)
{
    uint32_t bits;
    float f;
    if (little_endian)
        bits = (uint32_t)in[0] | (uint32_t)in[1] << 8 | (uint32_t)in[2] << 16 |
               (uint32_t)in[3] << 24;
    else
        bits = (uint32_t)in[3] | (uint32_t)in[2] << 8 | (uint32_t)in[1] << 16 |
               (uint32_t)in[0] << 24;
    memcpy(&f, &bits, sizeof f);
    return f;
}

/* ---------------------------------------------------------------- writers */

/* Writes rows top to bottom: file row r is memory row height-1-r. */
static int write_ppm(FILE *f, int width, int height, int is_float, const void *pixels)
{
    unsigned char *row = malloc((size_t)width * 3);
    int y;
    if (row == NULL) {
        set_error("out of memory");
        return 0;
    }
    if (fprintf(f, "P6\n%d %d\n255\n", width, height) < 0)
        goto write_failed;
    for (y = height - 1; y >= 0; y--) {
        size_t first = (size_t)y * (size_t)width * 4;
        int x;
        for (x = 0; x < width; x++) {
            int c;
            for (c = 0; c < 3; c++) {
                size_t i = first + (size_t)x * 4 + (size_t)c;
                row[x * 3 + c] = is_float ? float_to_byte(((const float *)pixels)[i])
                                          : ((const unsigned char *)pixels)[i];
            }
        }
        if (fwrite(row, 3, (size_t)width, f) != (size_t)width)
            goto write_failed;
    }
    free(row);
    return 1;

write_failed:
    free(row);
    set_errno_error("write error");
    return 0;
}

/* Writes rows bottom to top, the order of memory. */
static int write_pfm(FILE *f, int width, int height, int is_float, const void *pixels)
{
    unsigned char *row = malloc((size_t)width * 12);
    int y;
    if (row == NULL) {
        set_error("out of memory");
        return 0;
    }
    if (fprintf(f, "PF\n%d %d\n-1.0\n", width, height) < 0)
        goto write_failed;
    for (y = 0; y < height; y++) {
        size_t first = (size_t)y * (size_t)width * 4;
        int x;
        for (x = 0; x < width; x++) {
            int c;
            for (c = 0; c < 3; c++) {
                size_t i = first + (size_t)x * 4 + (size_t)c;
                float v = is_float ? ((const float *)pixels)[i]
                                   : (float)((const unsigned char *)pixels)[i] / 255.0f;
                put_float_le(row + (x * 3 + c) * 4, v);
            }
        }
        if (fwrite(row, 12, (size_t)width, f) != (size_t)width)
            goto write_failed;
    }
    free(row);
    return 1;

write_failed:
    free(row);
    set_errno_error("write error");
    return 0;
}

/* Writes a built-in format; on failure removes the partial file and leaves a reason. */
static int save_builtin(const char *path, int is_pfm, int width, int height, int is_float,
                        const void *pixels)
{
    FILE *f = fopen(path, "wb");
    int ok;
    if (f == NULL) {
        set_errno_error("cannot open for writing");
        return 0;
    }
    ok = is_pfm ? write_pfm(f, width, height, is_float, pixels)
                : write_ppm(f, width, height, is_float, pixels);
    if (fclose(f) != 0 && ok) {
        set_errno_error("write error");
        ok = 0;
    }
    if (!ok)
        remove(path); /* do not leave a truncated file behind */
    return ok;
}

/* ---------------------------------------------------------------- readers */

static int is_space(int c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

/*
 * Reads one header token of at most size-1 characters into buf, after
 * whitespace and '#' comments (to the end of the line).  The character
 * ending the token must be whitespace and is consumed: after the last
 * header field that is the single separator before the pixel data.
 * Returns 1, or 0 on EOF, an over-long token, a NUL byte or a bad terminator.
 */
static int read_token(FILE *f, char *buf, size_t size)
{
    size_t n = 0;
    int c = getc(f);
    for (;;) {
        while (is_space(c))
            c = getc(f);
        if (c != '#')
            break;
        while (c != EOF && c != '\n' && c != '\r')
            c = getc(f);
    }
    while (c != EOF && !is_space(c) && c != '#') {
        if (n + 1 >= size || c == '\0')
            return 0;
        buf[n++] = (char)c;
        c = getc(f);
    }
    buf[n] = '\0';
    return n > 0 && is_space(c);
}

/* A decimal header field in [min, max]; 0 when missing or out of range. */
static int read_header_long(FILE *f, long min, long max, long *value)
{
    char buf[24];
    long v = 0;
    size_t i;
    if (!read_token(f, buf, sizeof buf))
        return 0;
    for (i = 0; buf[i] != '\0'; i++) {
        if (buf[i] < '0' || buf[i] > '9')
            return 0;
        v = v * 10 + (buf[i] - '0');
        if (v > max)
            return 0;
    }
    if (v < min)
        return 0;
    *value = v;
    return 1;
}

/*
 * Checks that at least `needed` bytes follow the current position, so a
 * header that promises more data than the file has fails before the
 * allocation.  Streams that cannot seek pass; their short reads fail later.
 */
static int enough_data(FILE *f, double needed)
{
    long here = ftell(f);
    long end;
    if (here < 0 || fseek(f, 0, SEEK_END) != 0)
        return 1;
    end = ftell(f);
    if (fseek(f, here, SEEK_SET) != 0)
        return 0;
    return end >= 0 && (double)(end - here) >= needed;
}

static int check_dimensions(long width, long height)
{
    if (width > RTU_IMAGE_MAX_PIXELS / height) {
        set_error("image of %ld x %ld pixels is larger than the limit of %ld pixels", width,
                  height, RTU_IMAGE_MAX_PIXELS);
        return 0;
    }
    return 1;
}

/* The buffers of a body of h rows of row_bytes each in the file (format:
 * "PPM" or "PFM", for the messages): 1 with a row and the RGBA image
 * allocated, else 0 with the error set and nothing allocated.  A file
 * shorter than the header promises fails here, before the image is
 * allocated. */
static int body_buffers(FILE *f, const char *format, long w, long h, size_t row_bytes,
                        int is_float, unsigned char **row, unsigned char **out)
{
    if (!enough_data(f, (double)row_bytes * (double)h)) {
        set_error("truncated %s data (%ld x %ld pixels promised)", format, w, h);
        return 0;
    }
    *row = malloc(row_bytes);
    *out = malloc(image_bytes(w, h, is_float));
    if (*row == NULL || *out == NULL) {
        free(*row);
        free(*out);
        set_error("out of memory");
        return 0;
    }
    return 1;
}

/* Reads a P6 body after the magic; returns the RGBA image or NULL. */
static void *read_ppm(FILE *f, long *width, long *height, int is_float)
{
    long w, h, maxval;
    size_t sample_bytes, row_bytes;
    unsigned char *row;
    unsigned char *out;
    long y;
    if (!read_header_long(f, 1, RTU_IMAGE_MAX_SIDE, &w) ||
        !read_header_long(f, 1, RTU_IMAGE_MAX_SIDE, &h) ||
        !read_header_long(f, 1, 65535, &maxval)) {
        set_error("malformed PPM header");
        return NULL;
    }
    if (!check_dimensions(w, h))
        return NULL;
    sample_bytes = maxval > 255 ? 2 : 1;
    row_bytes = (size_t)w * 3 * sample_bytes;
    if (!body_buffers(f, "PPM", w, h, row_bytes, is_float, &row, &out))
        return NULL;
    for (y = 0; y < h; y++) {
        /* File rows run top to bottom; memory rows bottom to top. */
        size_t first = (size_t)(h - 1 - y) * (size_t)w * 4;
        long x;
        if (fread(row, 1, row_bytes, f) != row_bytes) {
            free(row);
            free(out);
            set_error("truncated PPM data");
            return NULL;
        }
        for (x = 0; x < w; x++) {
            int c;
            for (c = 0; c < 4; c++) {
                size_t i = first + (size_t)x * 4 + (size_t)c;
                long s = maxval;
                if (c < 3) {
                    size_t k = ((size_t)x * 3 + (size_t)c) * sample_bytes;
                    s = sample_bytes == 2 ? (long)row[k] << 8 | row[k + 1] : row[k];
                    if (s > maxval)
                        s = maxval;
                }
                if (is_float)
                    ((float *)out)[i] = (float)s / (float)maxval;
                else if (maxval == 255)
                    out[i] = (unsigned char)s;
                else
                    out[i] = (unsigned char)((s * 255 + maxval / 2) / maxval);
            }
        }
    }
    free(row);
    *width = w;
    *height = h;
    return out;
}

/* Reads a PF (channels 3) or Pf (channels 1) body after the magic. */
static void *read_pfm(FILE *f, int channels, long *width, long *height, int is_float)
{
    char scale_text[64];
    char *end;
    double scale;
    long w, h;
    int little_endian;
    size_t row_bytes;
    unsigned char *row;
    unsigned char *out;
    long y;
    if (!read_header_long(f, 1, RTU_IMAGE_MAX_SIDE, &w) ||
        !read_header_long(f, 1, RTU_IMAGE_MAX_SIDE, &h) ||
        !read_token(f, scale_text, sizeof scale_text)) {
        set_error("malformed PFM header");
        return NULL;
    }
    scale = strtod(scale_text, &end);
    if (*end != '\0' || !isfinite(scale) || scale == 0.0) {
        set_error("malformed PFM header: scale '%s'", scale_text);
        return NULL;
    }
    little_endian = scale < 0.0;
    if (!check_dimensions(w, h))
        return NULL;
    row_bytes = (size_t)w * (size_t)channels * 4;
    if (!body_buffers(f, "PFM", w, h, row_bytes, is_float, &row, &out))
        return NULL;
    for (y = 0; y < h; y++) {
        /* PFM rows run bottom to top, like memory. */
        size_t first = (size_t)y * (size_t)w * 4;
        long x;
        if (fread(row, 1, row_bytes, f) != row_bytes) {
            free(row);
            free(out);
            set_error("truncated PFM data");
            return NULL;
        }
        for (x = 0; x < w; x++) {
            int c;
            for (c = 0; c < 4; c++) {
                size_t i = first + (size_t)x * 4 + (size_t)c;
                float v = 1.0f;
                if (c < 3) {
                    int from = channels == 3 ? c : 0;
                    v = get_float(row + ((size_t)x * (size_t)channels + (size_t)from) * 4,
                                  little_endian);
                }
                if (is_float)
                    ((float *)out)[i] = v;
                else
                    out[i] = float_to_byte(v);
            }
        }
    }
    free(row);
    *width = w;
    *height = h;
    return out;
}

/* ---------------------------------------------------------------- entry points */

static int check_type(RTenum type, const char *caller)
{
    if (type != RT_UNSIGNED_BYTE && type != RT_FLOAT) {
        set_error("%s: type 0x%04X is neither RT_UNSIGNED_BYTE nor RT_FLOAT", caller,
                  (unsigned)type);
        return 0;
    }
    return 1;
}

RTboolean rtuSaveImage(const char *path, RTsizei width, RTsizei height, RTenum type,
                       const void *pixels)
{
    const char *extension;
    int is_float = type == RT_FLOAT;
    image_error[0] = '\0';
    if (path == NULL || path[0] == '\0') {
        set_error("rtuSaveImage: no file name");
        return RT_FALSE;
    }
    if (width <= 0 || height <= 0) {
        set_error("rtuSaveImage(%s): size %d x %d is not positive", path, (int)width,
                  (int)height);
        return RT_FALSE;
    }
    if (!check_type(type, "rtuSaveImage"))
        return RT_FALSE;
    if (pixels == NULL) {
        set_error("rtuSaveImage(%s): pixels is NULL", path);
        return RT_FALSE;
    }
    if (image_bytes(width, height, is_float) == 0) {
        set_error("rtuSaveImage(%s): size %d x %d is too large", path, (int)width,
                  (int)height);
        return RT_FALSE;
    }
    extension = path_extension(path);
    if (extension_is(extension, "ppm") || extension_is(extension, "pfm")) {
        errno = 0;
        if (save_builtin(path, extension_is(extension, "pfm"), width, height, is_float,
                         pixels))
            return RT_TRUE;
        prefix_error("rtuSaveImage", path);
        return RT_FALSE;
    }
#ifdef RTU_HAVE_OIIO
    if (extension[0] != '\0') {
        char reason[RTU_IMAGE_ERROR_SIZE];
        if (rtu_oiio_save(path, width, height, is_float, pixels, reason, sizeof reason))
            return RT_TRUE;
        set_error("rtuSaveImage(%s): %s", path, reason);
        return RT_FALSE;
    }
#endif
    if (extension[0] == '\0')
        set_error("rtuSaveImage(%s): no file extension to choose the format by", path);
    else
        set_error("rtuSaveImage(%s): format '%s' is not supported (this build reads and "
                  "writes .ppm and .pfm only; other formats need OpenImageIO)",
                  path, extension);
    return RT_FALSE;
}

void *rtuLoadImage(const char *path, RTsizei *width, RTsizei *height, RTenum type)
{
    FILE *f;
    int magic0, magic1;
    long w = 0, h = 0;
    void *pixels = NULL;
    int is_float = type == RT_FLOAT;
    image_error[0] = '\0';
    if (path == NULL || path[0] == '\0') {
        set_error("rtuLoadImage: no file name");
        return NULL;
    }
    if (width == NULL || height == NULL) {
        set_error("rtuLoadImage(%s): width or height is NULL", path);
        return NULL;
    }
    if (!check_type(type, "rtuLoadImage"))
        return NULL;
    errno = 0;
    f = fopen(path, "rb");
    if (f == NULL) {
        set_errno_error("cannot open");
        prefix_error("rtuLoadImage", path);
        return NULL;
    }
    magic0 = getc(f);
    magic1 = getc(f);
    if (magic0 == 'P' && magic1 == '6') {
        pixels = read_ppm(f, &w, &h, is_float);
    } else if (magic0 == 'P' && (magic1 == 'F' || magic1 == 'f')) {
        pixels = read_pfm(f, magic1 == 'F' ? 3 : 1, &w, &h, is_float);
    } else {
        fclose(f);
#ifdef RTU_HAVE_OIIO
        {
            char reason[RTU_IMAGE_ERROR_SIZE];
            int iw = 0, ih = 0;
            pixels = rtu_oiio_load(path, &iw, &ih, is_float, reason, sizeof reason);
            if (pixels == NULL) {
                set_error("rtuLoadImage(%s): %s", path, reason);
                return NULL;
            }
            *width = iw;
            *height = ih;
            return pixels;
        }
#else
        set_error("rtuLoadImage(%s): not a binary PPM (P6) or PFM file (other formats need "
                  "OpenImageIO)",
                  path);
        return NULL;
#endif
    }
    fclose(f);
    if (pixels == NULL) {
        prefix_error("rtuLoadImage", path);
        return NULL;
    }
    *width = (RTsizei)w;
    *height = (RTsizei)h;
    return pixels;
}

void rtuFreeImage(void *pixels)
{
    free(pixels);
}

RTboolean rtuImageFormatSupported(const char *extension)
{
    if (extension == NULL)
        return RT_FALSE;
    if (extension[0] == '.')
        extension++;
    if (extension_is(extension, "ppm") || extension_is(extension, "pfm"))
        return RT_TRUE;
#ifdef RTU_HAVE_OIIO
    if (extension[0] != '\0' && rtu_oiio_can_write(extension))
        return RT_TRUE;
#endif
    return RT_FALSE;
}

const char *rtuImageError(void)
{
    return image_error;
}
