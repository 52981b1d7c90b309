/*
 * demo_util.h - what every demo program needs around its scene: option
 * parsing, a clock, numbered output names, the headless progress line.
 * Plain C99 on rt.h and rtu.h; nothing here is part of the library.
 */
#ifndef RT_DEMO_UTIL_H
#define RT_DEMO_UTIL_H

#include <stddef.h>

/* Seconds on a monotonic clock. */
double demo_now(void);

/* A whole decimal number in [min, max] into *value; 0 on anything else. */
int demo_parse_int(const char *text, int min, int max, int *value);

/* "WxH" with both in [1, 16384] (rtViewport's limit); 0 on anything else. */
int demo_parse_size(const char *text, int *width, int *height);

/* The name of frame `index` of a sequence: base itself when `numbered` is
 * 0, else base with "_%04d" inserted before its extension. */
void demo_frame_name(char *out, size_t size, const char *base, int index, int numbered);

/* The file name to write: `requested`, or `fallback` when NULL; when this
 * build cannot write the extension (PNG without OpenImageIO), the same name
 * with .ppm, which rtu always writes, with a note on stderr naming `program`.
 * The result lives in `out`. */
const char *demo_output_name(char *out, size_t size, const char *requested, const char *fallback,
                             const char *program);

/* Reports a pending Tracelist error on stderr; returns 1 when there was one. */
int demo_report_error(const char *program, const char *when);

/* Reads the framebuffer (width x height RGBA8 into pixels) and writes it;
 * returns 0 (with a message) on failure. */
int demo_save_frame(const char *program, const char *path, int width, int height,
                    unsigned char *pixels);

/* One headless progress report: a bar on a terminal (rewritten in place),
 * else a line every tenth of the run.  done of total frames, `elapsed`
 * seconds so far, `frame_ms` the mean per-frame time to report and
 * `detail` (may be NULL) an extra field. */
void demo_progress(const char *program, int done, int total, double elapsed, double frame_ms,
                   const char *detail);

#endif
