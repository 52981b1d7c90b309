/* SPDX-License-Identifier: Apache-2.0 */
/*
 * demo_util.c - see demo_util.h.
 */
#include "demo_util.h"

#include <rt/rt.h>
#include <rt/rtu.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

double demo_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

int demo_parse_int(const char *text, int min, int max, int *value)
{
    char *end;
    long v;
    if (text == NULL || text[0] == '\0')
        return 0;
    v = strtol(text, &end, 10);
    if (*end != '\0' || v < min || v > max)
        return 0;
    *value = (int)v;
    return 1;
}

int demo_parse_size(const char *text, int *width, int *height)
{
    char buf[32];
    char *x;
    if (text == NULL || strlen(text) >= sizeof buf)
        return 0;
    strcpy(buf, text);
    x = strchr(buf, 'x');
    if (x == NULL)
        return 0;
    *x = '\0';
    return demo_parse_int(buf, 1, 16384, width) && demo_parse_int(x + 1, 1, 16384, height);
}

void demo_frame_name(char *out, size_t size, const char *base, int index, int numbered)
{
    const char *slash = strrchr(base, '/');
    const char *dot = strrchr(slash != NULL ? slash : base, '.');
    if (!numbered) {
        snprintf(out, size, "%s", base);
        return;
    }
    if (dot == NULL)
        dot = base + strlen(base);
    snprintf(out, size, "%.*s_%04d%s", (int)(dot - base), base, index, dot);
}

/* The writable formats, for messages: "ppm, pfm" and what OIIO adds. */
static void writable_formats(char *out, size_t size)
{
    static const char *const candidates[] = {"png", "jpg", "exr", "tif", "bmp", "ppm", "pfm"};
    size_t used = 0;
    out[0] = '\0';
    for (size_t i = 0; i < sizeof candidates / sizeof candidates[0]; i++)
        if (rtuImageFormatSupported(candidates[i]) && used < size)
            used += (size_t)snprintf(out + used, size - used, "%s%s", used ? ", " : "",
                                     candidates[i]);
}

const char *demo_output_name(char *out, size_t size, const char *requested, const char *fallback,
                             const char *program)
{
    const char *base = requested != NULL ? requested : fallback;
    const char *slash = strrchr(base, '/');
    const char *dot = strrchr(slash != NULL ? slash : base, '.');
    const char *extension = dot != NULL ? dot + 1 : "";
    if (strlen(base) + 5 > size) {
        fprintf(stderr, "%s: output name too long\n", program);
        return NULL;
    }
    if (rtuImageFormatSupported(extension)) {
        snprintf(out, size, "%s", base);
        return out;
    }
    if (requested != NULL) {
        char formats[128];
        writable_formats(formats, sizeof formats);
        if (extension[0] == '\0')
            demo_usage_error(program, "'%s' has no extension; this build writes %s", base,
                             formats);
        else
            demo_usage_error(program, "cannot write '.%s' files; this build writes %s",
                             extension, formats);
        return NULL;
    }
    snprintf(out, size, "%.*s.ppm", (int)(dot != NULL ? dot - base : (long)strlen(base)), base);
    return out;
}

void demo_usage_error(const char *program, const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "%s: ", program);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fprintf(stderr, "\nTry '%s --help' for more information.\n", program);
}

void *demo_create_context(const char *program, const char *config)
{
    char reason[RT_REASON_SIZE];
    RTcontext context = rtCreateContextWithReason(config, (RTsizei)sizeof reason, reason);
    if (context == NULL) {
        fprintf(stderr, "%s: cannot create a Tracelist context with configuration \"%s\": %s\n",
                program, config, reason);
        return NULL;
    }
    if (!rtMakeCurrent(context)) {
        fprintf(stderr, "%s: cannot make the Tracelist context current\n", program);
        rtDestroyContext(context);
        return NULL;
    }
    return context;
}

int demo_print_version(const char *program)
{
    RTcontext context = demo_create_context(program, "threads=1");
    if (context == NULL)
        return 1;
    printf("%s (Tracelist demos) %s\nlibrary: Tracelist %s\n", program, RT_VERSION_STRING,
           rtGetString(RT_VERSION));
    printf("License: Apache-2.0 <https://www.apache.org/licenses/LICENSE-2.0>\n");
    rtDestroyContext(context);
    return 0;
}

int demo_print_info(const char *program, const char *config)
{
    RTcontext context = demo_create_context(program, config);
    if (context == NULL)
        return 1;
    RTint threads = 0;
    rtGetIntegerv(RT_THREADS, &threads);
    printf("%s: Tracelist %s (headers %s)\n", program, rtGetString(RT_VERSION),
           RT_VERSION_STRING);
    printf("vendor:        %s\n", rtGetString(RT_VENDOR));
    printf("renderer:      %s\n", rtGetString(RT_RENDERER));
    printf("configuration: %s\n", rtGetString(RT_CONFIGURATION));
    printf("threads:       %d\n", (int)threads);
    printf("image formats: ");
    char formats[128];
    writable_formats(formats, sizeof formats);
    printf("%s\n", formats);
    rtDestroyContext(context);
    return 0;
}

/* path made absolute against the working directory (the file may be a
 * pattern's first member, so no realpath). */
static const char *absolute(char *out, size_t size, const char *path)
{
    char cwd[4096];
    if (path[0] == '/' || getcwd(cwd, sizeof cwd) == NULL)
        return path;
    snprintf(out, size, "%s/%s", cwd, path[0] == '.' && path[1] == '/' ? path + 2 : path);
    return out;
}

void demo_report_written(const char *program, const char *first, const char *last)
{
    char a[8200], b[8200];
    if (last == NULL || strcmp(first, last) == 0) {
        printf("%s: wrote %s\n", program, absolute(a, sizeof a, first));
        return;
    }
    printf("%s: wrote %s ... %s\n", program, absolute(a, sizeof a, first),
           absolute(b, sizeof b, last));
}

int demo_report_error(const char *program, const char *when)
{
    RTenum error = rtGetError();
    const char *text;
    if (error == RT_NO_ERROR)
        return 0;
    text = rtuErrorString(error);
    fprintf(stderr, "%s: Tracelist error %s (0x%04X) %s\n", program,
            text != NULL ? text : "unknown", (unsigned)error, when);
    return 1;
}

int demo_save_frame(const char *program, const char *path, int width, int height,
                    unsigned char *pixels)
{
    rtReadPixels(0, 0, width, height, RT_RGBA, RT_UNSIGNED_BYTE, pixels);
    if (demo_report_error(program, "reading the frame"))
        return 0;
    if (!rtuSaveImage(path, width, height, RT_UNSIGNED_BYTE, pixels)) {
        fprintf(stderr, "%s: %s\n", program, rtuImageError());
        return 0;
    }
    return 1;
}

void demo_progress(const char *program, int done, int total, double elapsed, double frame_ms,
                   const char *detail)
{
    static const int width = 24;
    int tty = isatty(fileno(stderr));
    int step = total / 10 > 0 ? total / 10 : 1;
    if (!tty && done != total && done % step != 0)
        return;
    char bar[64];
    int filled = total > 0 ? (int)((long)width * done / total) : width;
    for (int i = 0; i < width; i++)
        bar[i] = i < filled ? '#' : '.';
    bar[width] = '\0';
    double eta = done > 0 ? elapsed / done * (total - done) : 0.0;
    fprintf(stderr, "%s%s: [%s] %d/%d frames  %.1f ms/frame  ETA %dm%02ds%s%s%s",
            tty ? "\r" : "", program, bar, done, total, frame_ms, (int)(eta / 60.0),
            (int)eta % 60, detail ? "  " : "", detail ? detail : "", tty ? "   " : "\n");
    if (tty && done == total)
        fputc('\n', stderr);
}
