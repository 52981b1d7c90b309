/* SPDX-License-Identifier: Apache-2.0 */
/*
 * demo_util.h - what every demo program needs around its scene: option
 * parsing helpers and GNU-style messages, --version and --info, a clock,
 * numbered output names, the headless progress line.
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
 * 0, else base with "_%04d" inserted before its extension.  Every demo
 * numbers by the 0-based frame index (gears_0000.png is the first frame). */
void demo_frame_name(char *out, size_t size, const char *base, int index, int numbered);

/* The file name to write: `requested`, or `fallback` when NULL.  A
 * requested name whose extension this build cannot write is refused: a
 * message naming the formats it can write, and NULL.  The fallback (the
 * demo's default .png) becomes .ppm, which rtu always writes, when the
 * build has no PNG writer.  The result lives in `out`. */
const char *demo_output_name(char *out, size_t size, const char *requested, const char *fallback,
                             const char *program);

/* "program: <message>" and "Try 'program --help' for more information." on
 * stderr, as GNU tools say it. */
void demo_usage_error(const char *program, const char *fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* --version: the program's and the library's version (rtGetString on a
 * scratch context); returns the exit status. */
int demo_print_version(const char *program);

/* --info: version, renderer and effective configuration of a context
 * created with `config`; returns the exit status. */
int demo_print_info(const char *program, const char *config);

/* Creates and makes current a context from `config`; on failure prints
 * why and returns NULL. */
void *demo_create_context(const char *program, const char *config);

/* The key bindings every windowed demo shares, for --help. */
#define DEMO_COMMON_KEYS "  q, Esc         quit\n"

/* "program: wrote /absolute/first" (and "... /absolute/last" when they
 * differ) on stdout, so a user finds the images whatever the directory. */
void demo_report_written(const char *program, const char *first, const char *last);

/* Reports a pending Tracelist error on stderr by name (rtuErrorString);
 * returns 1 when there was one. */
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
