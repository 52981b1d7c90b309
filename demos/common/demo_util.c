/*
 * demo_util.c - see demo_util.h.
 */
#include "demo_util.h"

#include <rt/rt.h>
#include <rt/rtu.h>
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

const char *demo_output_name(char *out, size_t size, const char *requested, const char *fallback,
                             const char *program)
{
    const char *base = requested != NULL ? requested : fallback;
    const char *slash = strrchr(base, '/');
    const char *dot = strrchr(slash != NULL ? slash : base, '.');
    const char *extension = dot != NULL ? dot + 1 : "";
    if (rtuImageFormatSupported(extension) || strlen(base) + 5 > size) {
        snprintf(out, size, "%s", base);
        return out;
    }
    snprintf(out, size, "%.*s.ppm", (int)(dot != NULL ? dot - base : (long)strlen(base)), base);
    if (requested != NULL && extension[0] == '\0')
        fprintf(stderr, "%s: '%s' has no extension; writing %s\n", program, base, out);
    else if (requested != NULL)
        fprintf(stderr, "%s: this build cannot write '%s' files; writing %s instead\n", program,
                extension, out);
    return out;
}

int demo_report_error(const char *program, const char *when)
{
    RTenum error = rtGetError();
    if (error == RT_NO_ERROR)
        return 0;
    fprintf(stderr, "%s: Tracelist error 0x%04X %s\n", program, (unsigned)error, when);
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
