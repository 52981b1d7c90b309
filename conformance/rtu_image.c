/* SPDX-License-Identifier: Apache-2.0 */
/*
 * rtu_image.c - conformance: rtu image I/O (rtuSaveImage, rtuLoadImage,
 * rtuFreeImage, rtuImageFormatSupported, rtuImageError).
 *
 * Pins: exact round trips of the built-in PPM (bytes) and PFM (floats); the
 * on-disk layout of both (header text, PPM rows top to bottom, PFM rows
 * bottom to top in little-endian floats), so a writer and a reader that
 * agree on a wrong layout still fail; reading what other writers produce
 * (comments, 16-bit PPM, big-endian and grey PFM); float <-> byte
 * conversion; PNG through OpenImageIO when the build has it (exact for 8
 * bits, straight alpha kept, orientation cross-checked against the built-in
 * PPM reader); every argument error; truncated and malformed files, also
 * every prefix of a valid file and seeded random corruptions (no crash, no
 * bogus success); the per-thread error message.
 *
 * Files are created in the current directory with the process id in their
 * names and removed at the end.  Reference: docs/rtu.md.
 */
#include "testutil.h"

#include <rt/rtu.h>

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define W 5
#define H 3

static char scratch_names[32][64];
static int scratch_count;

/* A file name in the current directory, unique to this process, removed at exit. */
static const char *scratch(const char *stem, const char *extension)
{
    char *name;
    if (scratch_count == (int)(sizeof scratch_names / sizeof scratch_names[0])) {
        fprintf(stderr, "rtu_image: too many scratch files\n");
        exit(1);
    }
    name = scratch_names[scratch_count++];
    snprintf(name, sizeof scratch_names[0], "rtu_image_%ld_%s.%s", (long)getpid(), stem,
             extension);
    return name;
}

static void remove_scratch(void)
{
    int i;
    for (i = 0; i < scratch_count; i++)
        remove(scratch_names[i]);
}

static unsigned long rng_state = 12345;
static unsigned rng(void)
{
    rng_state = rng_state * 6364136223846793005UL + 1442695040888963407UL;
    return (unsigned)(rng_state >> 33);
}

static void write_bytes(const char *path, const void *data, size_t size)
{
    FILE *f = fopen(path, "wb");
    if (f == NULL || fwrite(data, 1, size, f) != size) {
        fprintf(stderr, "rtu_image: cannot write %s\n", path);
        exit(1);
    }
    fclose(f);
}

/* Reads a whole file into a malloc'ed buffer; *size gets its length. */
static unsigned char *read_bytes(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    unsigned char *data = NULL;
    size_t n = 0;
    size_t cap = 0;
    int c;
    if (f == NULL)
        return NULL;
    while ((c = getc(f)) != EOF) {
        if (n == cap) {
            cap = cap ? cap * 2 : 256;
            data = realloc(data, cap);
            if (data == NULL)
                exit(1);
        }
        data[n++] = (unsigned char)c;
    }
    fclose(f);
    *size = n;
    return data != NULL ? data : malloc(1);
}

static float le_float(const unsigned char *p)
{
    unsigned bits = (unsigned)p[0] | (unsigned)p[1] << 8 | (unsigned)p[2] << 16 |
                    (unsigned)p[3] << 24;
    float f;
    memcpy(&f, &bits, sizeof f);
    return f;
}

static int error_set(void)
{
    const char *e = rtuImageError();
    return e != NULL && e[0] != '\0';
}

/* ------------------------------------------------------------------ tests */

static void ppm_round_trip(void)
{
    unsigned char in[W * H * 4];
    unsigned char *out;
    unsigned char *file;
    size_t size = 0;
    RTsizei w = -1, h = -1;
    const char *path = scratch("rgb8", "ppm");
    const char *header = "P6\n5 3\n255\n";
    int i, mismatches = 0;
    tu_section("PPM round trip");
    for (i = 0; i < W * H * 4; i++)
        in[i] = (unsigned char)rng();
    CHECK(rtuSaveImage(path, W, H, RT_UNSIGNED_BYTE, in) == RT_TRUE);
    CHECK(strcmp(rtuImageError(), "") == 0);

    /* On disk: P6 header, then rows top to bottom, alpha dropped. */
    file = read_bytes(path, &size);
    CHECK(file != NULL);
    if (file == NULL)
        return;
    CHECK_INT(size, strlen(header) + W * H * 3);
    CHECK(size >= strlen(header) && memcmp(file, header, strlen(header)) == 0);
    if (size == strlen(header) + W * H * 3) {
        const unsigned char *first_row = file + strlen(header);
        /* File row 0 is memory row H-1 (rtReadPixels rows run bottom to top). */
        CHECK_INT(first_row[0], in[(H - 1) * W * 4 + 0]);
        CHECK_INT(first_row[1], in[(H - 1) * W * 4 + 1]);
        CHECK_INT(first_row[2], in[(H - 1) * W * 4 + 2]);
        CHECK_INT(first_row[3], in[(H - 1) * W * 4 + 4]);
    }
    free(file);

    out = rtuLoadImage(path, &w, &h, RT_UNSIGNED_BYTE);
    CHECK(out != NULL);
    CHECK_INT(w, W);
    CHECK_INT(h, H);
    if (out == NULL)
        return;
    for (i = 0; i < W * H * 4; i++) {
        unsigned char expected = (i % 4 == 3) ? 255 : in[i];
        mismatches += out[i] != expected;
    }
    CHECK_INT(mismatches, 0);
    rtuFreeImage(out);

    /* The extension is case-insensitive. */
    CHECK(rtuSaveImage(scratch("upper", "PPM"), W, H, RT_UNSIGNED_BYTE, in) == RT_TRUE);
}

static void pfm_round_trip(void)
{
    float in[W * H * 4];
    float *out;
    unsigned char *file;
    size_t size = 0;
    RTsizei w = 0, h = 0;
    const char *path = scratch("rgbf", "pfm");
    const char *header = "PF\n5 3\n-1.0\n";
    int i, mismatches = 0;
    tu_section("PFM round trip");
    for (i = 0; i < W * H * 4; i++)
        in[i] = ((float)(int)(rng() % 20001) - 10000.0f) / 997.0f; /* negative, > 1, ... */
    in[0] = 1e-30f;
    in[1] = 3.0e38f;
    in[2] = -0.0f;
    CHECK(rtuSaveImage(path, W, H, RT_FLOAT, in) == RT_TRUE);

    /* On disk: PF header, rows bottom to top, little-endian floats, alpha dropped. */
    file = read_bytes(path, &size);
    CHECK(file != NULL);
    if (file == NULL)
        return;
    CHECK_INT(size, strlen(header) + W * H * 12);
    CHECK(size >= strlen(header) && memcmp(file, header, strlen(header)) == 0);
    if (size == strlen(header) + W * H * 12) {
        const unsigned char *data = file + strlen(header);
        CHECK(le_float(data + 0) == in[0]);
        CHECK(le_float(data + 4) == in[1]);
        CHECK(le_float(data + 12) == in[4]);              /* pixel 1, red */
        CHECK(le_float(data + W * 12 + 8) == in[W * 4 + 2]); /* row 1, pixel 0, blue */
    }
    free(file);

    out = rtuLoadImage(path, &w, &h, RT_FLOAT);
    CHECK(out != NULL);
    CHECK_INT(w, W);
    CHECK_INT(h, H);
    if (out == NULL)
        return;
    for (i = 0; i < W * H * 4; i++) {
        float expected = (i % 4 == 3) ? 1.0f : in[i];
        mismatches += memcmp(&out[i], &expected, sizeof expected) != 0; /* bit-exact, -0 too */
    }
    CHECK_INT(mismatches, 0);
    rtuFreeImage(out);
}

static void conversions(void)
{
    float f[4 * 4] = {0.2f, 1.5f, -1.0f, 0.5f,   /* 51, 255, 0 */
                      0.0f, 1.0f, 0.5f, 1.0f,    /* 0, 255, 128 (127.5 rounds up) */
                      0.49f / 255.0f, 0.51f / 255.0f, 254.49f / 255.0f, 0.0f,
                      0.0f, 0.0f, 0.0f, 0.0f};
    unsigned char b[4 * 4] = {0, 1, 51, 7, 128, 254, 255, 9, 3, 4, 5, 6, 7, 8, 9, 10};
    const char *ppm = scratch("conv", "ppm");
    const char *pfm = scratch("conv", "pfm");
    unsigned char *bytes;
    float *floats;
    RTsizei w = 0, h = 0;
    int i;
    tu_section("float <-> byte conversion");
    f[12] = tu_nan();
    f[13] = tu_inf();
    f[14] = -tu_inf();
    /* Floats written as PPM: round(clamp(f, 0, 1) * 255), NaN -> 0. */
    CHECK(rtuSaveImage(ppm, 4, 1, RT_FLOAT, f) == RT_TRUE);
    bytes = rtuLoadImage(ppm, &w, &h, RT_UNSIGNED_BYTE);
    CHECK(bytes != NULL);
    if (bytes != NULL) {
        static const unsigned char expected[4 * 4] = {51, 255, 0,   255, 0, 255, 128, 255,
                                                      0,  1,   254, 255, 0, 255, 0,   255};
        for (i = 0; i < 16; i++)
            CHECK_INT(bytes[i], expected[i]);
        rtuFreeImage(bytes);
    }
    /* The same file read as floats: byte / 255. */
    floats = rtuLoadImage(ppm, &w, &h, RT_FLOAT);
    CHECK(floats != NULL);
    if (floats != NULL) {
        CHECK(floats[0] == 51.0f / 255.0f);
        CHECK(floats[1] == 1.0f);
        CHECK(floats[3] == 1.0f);
        rtuFreeImage(floats);
    }
    /* Bytes written as PFM are byte / 255 and come back exactly as bytes. */
    CHECK(rtuSaveImage(pfm, 4, 1, RT_UNSIGNED_BYTE, b) == RT_TRUE);
    floats = rtuLoadImage(pfm, &w, &h, RT_FLOAT);
    CHECK(floats != NULL);
    if (floats != NULL) {
        CHECK(floats[1] == 1.0f / 255.0f);
        CHECK(floats[5] == 254.0f / 255.0f);
        CHECK(floats[7] == 1.0f);
        rtuFreeImage(floats);
    }
    bytes = rtuLoadImage(pfm, &w, &h, RT_UNSIGNED_BYTE);
    CHECK(bytes != NULL);
    if (bytes != NULL) {
        for (i = 0; i < 16; i++)
            CHECK_INT(bytes[i], (i % 4 == 3) ? 255 : b[i]);
        rtuFreeImage(bytes);
    }
}

/* Files as other programs write them. */
static void foreign_files(void)
{
    const char *path = scratch("foreign", "ppm");
    unsigned char *bytes;
    float *floats;
    RTsizei w = 0, h = 0;
    tu_section("foreign PPM/PFM files");
    {
        /* Comments and odd whitespace in the header; 2x2; rows top to bottom. */
        const char text[] = "P6 # made by hand\n# another comment\n2\t2\r\n255\n"
                            "\x01\x02\x03\x04\x05\x06"
                            "\x07\x08\x09\x0a\x0b\x0c";
        write_bytes(path, text, sizeof text - 1);
        bytes = rtuLoadImage(path, &w, &h, RT_UNSIGNED_BYTE);
        CHECK(bytes != NULL);
        CHECK_INT(w, 2);
        CHECK_INT(h, 2);
        if (bytes != NULL) {
            /* The file's top row is memory row 1. */
            CHECK_INT(bytes[0], 7);
            CHECK_INT(bytes[4], 10);
            CHECK_INT(bytes[8], 1);
            CHECK_INT(bytes[14], 6);
            CHECK_INT(bytes[15], 255);
            rtuFreeImage(bytes);
        }
    }
    {
        /* 16-bit samples, big-endian, maxval 1000. */
        const char text[] = "P6\n1 1\n1000\n\x03\xe8\x01\xf4\x00\x00";
        write_bytes(path, text, sizeof text - 1);
        bytes = rtuLoadImage(path, &w, &h, RT_UNSIGNED_BYTE);
        CHECK(bytes != NULL);
        if (bytes != NULL) {
            CHECK_INT(bytes[0], 255);
            CHECK_INT(bytes[1], 128); /* 500/1000 -> 127.5 -> 128 */
            CHECK_INT(bytes[2], 0);
            rtuFreeImage(bytes);
        }
        floats = rtuLoadImage(path, &w, &h, RT_FLOAT);
        CHECK(floats != NULL);
        if (floats != NULL) {
            CHECK(floats[1] == 0.5f);
            rtuFreeImage(floats);
        }
    }
    {
        /* A big-endian (positive scale) grey "Pf", named .ppm: the reader goes by content. */
        const unsigned char text[] = {'P', 'f', '\n', '2', ' ', '1', '\n', '2', '.', '5', '\n',
                                      0x3f, 0x80, 0x00, 0x00, 0xc0, 0x00, 0x00, 0x00};
        write_bytes(path, text, sizeof text);
        floats = rtuLoadImage(path, &w, &h, RT_FLOAT);
        CHECK(floats != NULL);
        CHECK_INT(w, 2);
        CHECK_INT(h, 1);
        if (floats != NULL) {
            CHECK(floats[0] == 1.0f && floats[1] == 1.0f && floats[2] == 1.0f);
            CHECK(floats[3] == 1.0f);
            CHECK(floats[4] == -2.0f && floats[6] == -2.0f);
            rtuFreeImage(floats);
        }
    }
}

static void png_through_oiio(void)
{
    unsigned char in[W * H * 4];
    unsigned char *out;
    RTsizei w = 0, h = 0;
    int i, mismatches = 0;
    tu_section("PNG (OpenImageIO)");
    if (!rtuImageFormatSupported("png")) {
        const char *path = scratch("nopng", "png");
        printf("rtu_image: PNG not supported in this build; checking the refusal only\n");
        for (i = 0; i < W * H * 4; i++)
            in[i] = 0;
        CHECK(rtuSaveImage(path, W, H, RT_UNSIGNED_BYTE, in) == RT_FALSE);
        CHECK(error_set());
        return;
    }
    for (i = 0; i < W * H * 4; i++)
        in[i] = (unsigned char)rng();
    /* Straight alpha: a colour under alpha 0 must survive. */
    in[0] = 200;
    in[1] = 100;
    in[2] = 50;
    in[3] = 0;
    {
        const char *path = scratch("rgba8", "png");
        CHECK(rtuSaveImage(path, W, H, RT_UNSIGNED_BYTE, in) == RT_TRUE);
        out = rtuLoadImage(path, &w, &h, RT_UNSIGNED_BYTE);
        CHECK(out != NULL);
        CHECK_INT(w, W);
        CHECK_INT(h, H);
        if (out != NULL) {
            for (i = 0; i < W * H * 4; i++)
                mismatches += out[i] != in[i];
            CHECK_INT(mismatches, 0);
            rtuFreeImage(out);
        }
    }
    /* Orientation against the format: OpenImageIO writes a .pnm as binary PPM,
     * which the built-in reader (rows top to bottom) reads back. */
    if (rtuImageFormatSupported("pnm")) {
        const char *path = scratch("oiio", "pnm");
        CHECK(rtuSaveImage(path, W, H, RT_UNSIGNED_BYTE, in) == RT_TRUE);
        out = rtuLoadImage(path, &w, &h, RT_UNSIGNED_BYTE);
        CHECK(out != NULL);
        if (out != NULL) {
            mismatches = 0;
            for (i = 0; i < W * H * 4; i++)
                mismatches += out[i] != ((i % 4 == 3) ? 255 : in[i]);
            CHECK_INT(mismatches, 0);
            rtuFreeImage(out);
        }
    }
    /* Floats through PNG are quantised to at least 8 bits. */
    {
        float f[W * H * 4];
        float *back;
        const char *path = scratch("rgbaf", "png");
        double worst = 0.0;
        for (i = 0; i < W * H * 4; i++)
            f[i] = (float)(rng() % 1001) / 1000.0f;
        CHECK(rtuSaveImage(path, W, H, RT_FLOAT, f) == RT_TRUE);
        back = rtuLoadImage(path, &w, &h, RT_FLOAT);
        CHECK(back != NULL);
        if (back != NULL) {
            for (i = 0; i < W * H * 4; i++)
                if (fabs((double)back[i] - (double)f[i]) > worst)
                    worst = fabs((double)back[i] - (double)f[i]);
            CHECK(worst <= 0.5 / 255.0 + 1e-6);
            rtuFreeImage(back);
        }
    }
    /* A PNG file that is not a PNG fails cleanly. */
    {
        const char *path = scratch("bad", "png");
        write_bytes(path, "\x89PNG\r\n\x1a\nnot really", 18);
        w = h = 77;
        CHECK(rtuLoadImage(path, &w, &h, RT_UNSIGNED_BYTE) == NULL);
        CHECK(error_set());
        CHECK_INT(w, 77);
    }
}

static void argument_errors(void)
{
    unsigned char px[4 * 4] = {0};
    const char *path = scratch("args", "ppm");
    RTsizei w = 33, h = 44;
    tu_section("argument errors");
    CHECK(rtuSaveImage(NULL, 2, 2, RT_UNSIGNED_BYTE, px) == RT_FALSE);
    CHECK(error_set());
    CHECK(rtuSaveImage("", 2, 2, RT_UNSIGNED_BYTE, px) == RT_FALSE);
    CHECK(rtuSaveImage(path, 0, 2, RT_UNSIGNED_BYTE, px) == RT_FALSE);
    CHECK(strstr(rtuImageError(), "rtuSaveImage") != NULL);
    CHECK(rtuSaveImage(path, 2, -1, RT_UNSIGNED_BYTE, px) == RT_FALSE);
    CHECK(rtuSaveImage(path, -2, -2, RT_UNSIGNED_BYTE, px) == RT_FALSE);
    CHECK(rtuSaveImage(path, 2, 2, RT_INT, px) == RT_FALSE);
    CHECK(rtuSaveImage(path, 2, 2, 0, px) == RT_FALSE);
    CHECK(rtuSaveImage(path, 2, 2, RT_UNSIGNED_BYTE, NULL) == RT_FALSE);
    /* None of those created the file. */
    CHECK(fopen(path, "rb") == NULL);
    CHECK(rtuSaveImage(scratch("noext", ""), 2, 2, RT_UNSIGNED_BYTE, px) == RT_FALSE);
    CHECK(rtuSaveImage(scratch("unknown", "qqqq"), 2, 2, RT_UNSIGNED_BYTE, px) == RT_FALSE);
    CHECK(error_set());
    CHECK(rtuSaveImage("no-such-directory-rtu/x.ppm", 2, 2, RT_UNSIGNED_BYTE, px) == RT_FALSE);
    CHECK(error_set());

    /* A success clears the message. */
    CHECK(rtuSaveImage(path, 2, 2, RT_UNSIGNED_BYTE, px) == RT_TRUE);
    CHECK(strcmp(rtuImageError(), "") == 0);

    CHECK(rtuLoadImage(NULL, &w, &h, RT_UNSIGNED_BYTE) == NULL);
    CHECK(error_set());
    CHECK(rtuLoadImage("", &w, &h, RT_UNSIGNED_BYTE) == NULL);
    CHECK(rtuLoadImage(path, NULL, &h, RT_UNSIGNED_BYTE) == NULL);
    CHECK(rtuLoadImage(path, &w, NULL, RT_UNSIGNED_BYTE) == NULL);
    CHECK(rtuLoadImage(path, &w, &h, RT_DOUBLE) == NULL);
    CHECK(strstr(rtuImageError(), "rtuLoadImage") != NULL);
    CHECK(rtuLoadImage("no-such-file-rtu.ppm", &w, &h, RT_UNSIGNED_BYTE) == NULL);
    CHECK(strstr(rtuImageError(), "no-such-file-rtu.ppm") != NULL);
    /* Failures leave the sizes alone. */
    CHECK_INT(w, 33);
    CHECK_INT(h, 44);

    rtuFreeImage(NULL);

    CHECK(rtuImageFormatSupported("ppm") == RT_TRUE);
    CHECK(rtuImageFormatSupported("PFM") == RT_TRUE);
    CHECK(rtuImageFormatSupported(".ppm") == RT_TRUE);
    CHECK(rtuImageFormatSupported(NULL) == RT_FALSE);
    CHECK(rtuImageFormatSupported("") == RT_FALSE);
    CHECK(rtuImageFormatSupported(".") == RT_FALSE);
    CHECK(rtuImageFormatSupported("qqqq") == RT_FALSE);
}

/* Loads path and requires a clean failure: NULL, a message, sizes untouched. */
static int load_fails(const char *path)
{
    RTsizei w = 91, h = 92;
    void *p = rtuLoadImage(path, &w, &h, RT_FLOAT);
    int ok = p == NULL && error_set() && w == 91 && h == 92;
    rtuFreeImage(p);
    return ok;
}

static void malformed_files(void)
{
    static const char *const bad[] = {
        "",                                   /* empty */
        "P",                                  /* magic cut */
        "P6",                                 /* no header */
        "P6\n",                               /* no width */
        "P6\n2 2\n",                          /* no maxval */
        "P6\n2 2\n255",                       /* no separator after maxval */
        "P6\n2 2\n255\n\x01\x02\x03",         /* data truncated */
        "P6\n0 2\n255\n",                     /* zero width */
        "P6\n2 0\n255\n",                     /* zero height */
        "P6\n-2 2\n255\n\x01",                /* negative width */
        "P6\n2 2\n0\n\x01",                   /* maxval 0 */
        "P6\n1 1\n65536\n\x01\x02\x03",       /* maxval too large */
        "P6\n99999999999999999999 1\n255\n",  /* width overflows */
        "P6\n60000 60000\n255\n\x01\x02",     /* huge, truncated: must not allocate */
        "P6\n1e3 2\n255\n",                   /* not an integer */
        "P6\n2 2\n255#\n",                    /* junk after maxval */
        "PF\n1 1\n0\n\x01\x02\x03\x04\x01\x02\x03\x04\x01\x02\x03\x04", /* scale 0 */
        "PF\n1 1\nnan\n\x01\x02\x03\x04\x01\x02\x03\x04\x01\x02\x03\x04",
        "PF\n1 1\n-1.0x\n\x01\x02\x03\x04\x01\x02\x03\x04\x01\x02\x03\x04",
        "PF\n2 1\n-1.0\n\x01\x02\x03\x04",    /* truncated */
        "Pf\n1 1\n-1.0\n\x01\x02",            /* truncated grey */
        "GIF89a garbage garbage",
        "\x89PNG\r\n\x1a\n\x00\x00\x00\x0dIHDR",
    };
    const char *path = scratch("bad", "ppm");
    size_t i;
    tu_section("malformed files");
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        write_bytes(path, bad[i], strlen(bad[i]));
        if (!tu_check(load_fails(path), __FILE__, __LINE__, "malformed file rejected"))
            fprintf(stderr, "    case %d\n", (int)i);
    }
    /* A header with a NUL byte in it, and all the data. */
    write_bytes(path, "P6\n2\0 2\n255\n123456789abc", 24);
    CHECK(load_fails(path));
    /* ASCII PPM is not built in: only OpenImageIO reads it. */
    {
        RTsizei w = 0, h = 0;
        unsigned char *p;
        write_bytes(path, "P3\n1 1\n255\n1 2 3\n", 18);
        p = rtuLoadImage(path, &w, &h, RT_UNSIGNED_BYTE);
        if (rtuImageFormatSupported("png")) {
            CHECK(p != NULL && w == 1 && h == 1 && p[0] == 1 && p[1] == 2 && p[2] == 3);
        } else {
            CHECK(p == NULL && error_set());
        }
        rtuFreeImage(p);
    }
    /* A directory is not an image. */
    CHECK(load_fails("."));
}

/* Every proper prefix of a valid file fails; random corruptions never crash. */
static void fuzz(void)
{
    static const char *const extensions[] = {"ppm", "pfm"};
    const char *path = scratch("fuzz", "pgm");
    int e;
    tu_section("truncation and corruption");
    for (e = 0; e < 2; e++) {
        unsigned char px[3 * 2 * 4];
        const char *good = scratch("fuzzsrc", extensions[e]);
        unsigned char *file;
        size_t size = 0, n;
        int k, rejected = 0, tried = 0;
        for (k = 0; k < (int)sizeof px; k++)
            px[k] = (unsigned char)rng();
        CHECK(rtuSaveImage(good, 3, 2, RT_UNSIGNED_BYTE, px) == RT_TRUE);
        file = read_bytes(good, &size);
        CHECK(file != NULL && size > 0);
        if (file == NULL)
            continue;
        for (n = 0; n < size; n++) {
            write_bytes(path, file, n);
            tried++;
            rejected += load_fails(path);
        }
        CHECK_INT(rejected, tried);
        /* Flip bytes of the header and data; a load may succeed (a changed
         * value) or fail, but a success must report a sane size. */
        for (k = 0; k < 2000; k++) {
            unsigned char *copy = malloc(size);
            RTsizei w = 0, h = 0;
            void *p;
            int flips = 1 + (int)(rng() % 3);
            memcpy(copy, file, size);
            while (flips-- > 0) {
                size_t at = rng() % (size < 24 ? size : 24);
                copy[at] = (unsigned char)rng();
            }
            write_bytes(path, copy, size);
            free(copy);
            p = rtuLoadImage(path, &w, &h, (k & 1) ? RT_FLOAT : RT_UNSIGNED_BYTE);
            if (p != NULL) {
                rtuFreeImage(p);
                if (!tu_check(w > 0 && h > 0 && (long)w * h <= (long)size, __FILE__, __LINE__,
                              "corrupted file gives a sane size"))
                    break;
            } else if (!tu_check(error_set(), __FILE__, __LINE__, "failure has a message")) {
                break;
            }
        }
        free(file);
    }
}

/* A failing write (the device is full) reports the error and leaves no file. */
static void write_errors(void)
{
    const char *link_name = scratch("full", "ppm");
    unsigned char px[64 * 64 * 4] = {0};
    tu_section("write errors");
    if (symlink("/dev/full", link_name) != 0) {
        printf("rtu_image: no symlink to /dev/full; write-error check skipped\n");
        return;
    }
    CHECK(rtuSaveImage(link_name, 64, 64, RT_UNSIGNED_BYTE, px) == RT_FALSE);
    CHECK(error_set());
}

static char thread_message[256];

static void *thread_body(void *arg)
{
    unsigned char px[4] = {1, 2, 3, 4};
    (void)arg;
    /* This thread starts with an empty message and its calls do not touch main's. */
    snprintf(thread_message, sizeof thread_message, "%s", rtuImageError());
    rtuSaveImage(NULL, 1, 1, RT_UNSIGNED_BYTE, px);
    return NULL;
}

static void per_thread_message(void)
{
    pthread_t thread;
    char before[256];
    tu_section("per-thread message");
    CHECK(rtuLoadImage("no-such-file-rtu.pfm", (RTsizei[]){0}, (RTsizei[]){0}, RT_FLOAT) ==
          NULL);
    snprintf(before, sizeof before, "%s", rtuImageError());
    CHECK(before[0] != '\0');
    CHECK(pthread_create(&thread, NULL, thread_body, NULL) == 0);
    pthread_join(thread, NULL);
    CHECK(strcmp(thread_message, "") == 0);
    CHECK(strcmp(rtuImageError(), before) == 0);
}

/*
 * OpenImageIO 2.4's PNG reader loses an error string when libpng longjmps
 * out of its read callback on a truncated file (PNGInput::PngReadCallback);
 * the leak is theirs.  LeakSanitizer (the ASan runs of this suite) reads
 * these hooks: the suppression names the leaking function, and the slow
 * unwinder is needed to see it through libpng, which has no frame pointers
 * (with the fast one the stack stops in libstdc++ and no suppression by
 * library name matches).  They must be visible to the sanitizer runtime,
 * which gcc links as a shared library, so they override the build's hidden
 * default visibility.  Without a sanitizer nothing calls them.
 */
#if defined(__GNUC__)
#define SANITIZER_HOOK __attribute__((visibility("default"), used))
#else
#define SANITIZER_HOOK
#endif
SANITIZER_HOOK const char *__lsan_default_suppressions(void);
SANITIZER_HOOK const char *__lsan_default_suppressions(void)
{
    return "leak:PngReadCallback\n";
}
SANITIZER_HOOK const char *__asan_default_options(void);
SANITIZER_HOOK const char *__asan_default_options(void)
{
    return "fast_unwind_on_malloc=0";
}

int main(void)
{
    ppm_round_trip();
    pfm_round_trip();
    conversions();
    foreign_files();
    png_through_oiio();
    argument_errors();
    malformed_files();
    fuzz();
    write_errors();
    per_thread_message();
    remove_scratch();
    return test_summary("rtu_image");
}
