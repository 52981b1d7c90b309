/* SPDX-License-Identifier: Apache-2.0 */
/*
 * glut_shell_headless.c - the shell without a window: the environment
 * (TRACELIST_EVENTS, TRACELIST_FRAMES, TRACELIST_SIZE, TRACELIST_OUT), the
 * replay of the events, the deterministic frames and the image
 * (docs/glut.md, "Headless").
 *
 * The order is GLUT's for a window that appears and is then used:
 * visibility, reshape, then the events in the order given (as if typed
 * before the first frame was looked at), then the frames.  Frame k runs
 * at virtual time k * 1000 / 60 ms (rtuGet(RTU_ELAPSED_TIME) reads this
 * clock): the timers due by then, the idle callback, the display
 * callback.  Nothing depends on the real clock, so a run is reproducible.
 */
#include "glut_shell.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_FRAMES 100000
#define MAX_SIDE 16384
#define FRAME_MS (1000.0 / 60.0)

/* A bad variable stops the program, as GLUT's fatal errors do: running on
 * with a misread setting would write a wrong image without a word. */
static void fail(const char *variable, const char *value, const char *why)
{
    fprintf(stderr, "rtu: rtuMainLoop: %s=\"%s\": %s\n", variable, value, why);
    exit(EXIT_FAILURE);
}

static long parse_long(const char *variable, const char *text, long lo, long hi,
                       const char *why)
{
    char *end;
    long v;
    errno = 0;
    v = strtol(text, &end, 10);
    if (errno || end == text || *end != '\0' || v < lo || v > hi)
        fail(variable, text, why);
    return v;
}

static void parse_size(const char *text, int *width, int *height)
{
    char *end;
    long w, h;
    errno = 0;
    w = strtol(text, &end, 10);
    if (errno || end == text || (*end != 'x' && *end != 'X'))
        fail("TRACELIST_SIZE", text, "expected WxH, e.g. 640x480");
    text = end + 1;
    h = strtol(text, &end, 10);
    if (errno || end == text || *end != '\0')
        fail("TRACELIST_SIZE", text, "expected WxH, e.g. 640x480");
    if (w < 1 || h < 1 || w > MAX_SIDE || h > MAX_SIDE)
        fail("TRACELIST_SIZE", text, "width and height must be 1 .. 16384");
    *width = (int)w;
    *height = (int)h;
}

/* The extension of a path ("" when none). */
static const char *extension(const char *path)
{
    const char *dot = strrchr(path, '.');
    const char *slash = strrchr(path, '/');
    return dot && (!slash || dot > slash) ? dot + 1 : "";
}

/* Delivers one event token ("k:x", "k:#27", "s:101", "m:Label"). */
static void replay(struct rtu_shell *s, const char *token)
{
    const char *arg = token + 2;
    if (strlen(token) < 3 || token[1] != ':')
        fail("TRACELIST_EVENTS", token, "expected k:<key>, s:<special key code> or m:<menu label>");
    switch (token[0]) {
    case 'k': {
        int key;
        if (arg[0] == '#' && arg[1] != '\0')
            key = (int)parse_long("TRACELIST_EVENTS", arg + 1, 0, 255,
                                  "k:#<code> needs a code 0 .. 255");
        else if (arg[1] == '\0')
            key = (unsigned char)arg[0];
        else
            fail("TRACELIST_EVENTS", token, "k: takes one character, or #<code> (k:#27 Escape)");
        if (s->keyboard)
            s->keyboard((unsigned char)key, 0, 0);
        if (s->keyboard_up && !s->leave)
            s->keyboard_up((unsigned char)key, 0, 0);
        break;
    }
    case 's': {
        int key = (int)parse_long("TRACELIST_EVENTS", arg, 1, 255,
                                  "s: takes a GLUT special key code (RTU_KEY_UP is 101)");
        if (s->special)
            s->special(key, 0, 0);
        if (s->special_up && !s->leave)
            s->special_up(key, 0, 0);
        break;
    }
    case 'm':
        if (!rtu_menu_select_label(s, arg))
            fail("TRACELIST_EVENTS", token, "no menu entry has this label ('_' is a space)");
        break;
    default:
        fail("TRACELIST_EVENTS", token, "expected k:<key>, s:<special key code> or m:<menu label>");
    }
}

void rtu_headless_main_loop(struct rtu_shell *s)
{
    const char *frames_text = getenv("TRACELIST_FRAMES");
    const char *size_text = getenv("TRACELIST_SIZE");
    const char *out = getenv("TRACELIST_OUT");
    const char *events = getenv("TRACELIST_EVENTS");
    char default_out[160];
    long frames = 1, k;
    int width = s->width, height = s->height;

    /* Every variable is checked before any callback runs. */
    if (frames_text)
        frames = parse_long("TRACELIST_FRAMES", frames_text, 1, MAX_FRAMES,
                            "frames must be an integer 1 .. 100000");
    if (size_text)
        parse_size(size_text, &width, &height);
    if (!out || !*out) {
        if (out)
            fail("TRACELIST_OUT", out, "an empty file name");
        snprintf(default_out, sizeof(default_out), "%s.%s", s->program,
                 rtuImageFormatSupported("png") ? "png" : "ppm");
        out = default_out;
    } else if (!rtuImageFormatSupported(extension(out))) {
        fail("TRACELIST_OUT", out,
             "rtuSaveImage cannot write this extension (.ppm and .pfm always work)");
    }
    if (events) {
        /* Check every token's form first (menu labels can only be
         * checked when they are selected: menus may be made later). */
        const char *p = events;
        while (*p) {
            while (*p == ' ')
                p++;
            if (*p && (p[1] != ':' || !p[2] || p[2] == ' ' || !strchr("ksm", p[0]))) {
                char token[64];
                size_t n = strcspn(p, " ");
                snprintf(token, sizeof(token), "%.*s", (int)(n < 63 ? n : 63), p);
                fail("TRACELIST_EVENTS", token,
                     "expected k:<key>, s:<special key code> or m:<menu label>");
            }
            p += strcspn(p, " ");
        }
    }

    s->virtual_ms = 0.0;
    if (s->visibility)
        s->visibility(RTU_VISIBLE);
    if (!s->leave)
        rtu_shell_reshape(s, width, height);
    if (events) {
        const char *p = events;
        while (*p && !s->leave) {
            char token[512];
            size_t n;
            while (*p == ' ')
                p++;
            n = strcspn(p, " ");
            if (n == 0)
                break;
            if (n >= sizeof(token))
                fail("TRACELIST_EVENTS", p, "an event longer than 511 characters");
            memcpy(token, p, n);
            token[n] = '\0';
            p += n;
            replay(s, token);
        }
    }
    for (k = 0; k < frames && !s->leave && s->window; k++) {
        s->virtual_ms = (double)k * FRAME_MS;
        rtu_shell_run_timers(s, s->virtual_ms);
        if (s->pending_width && !s->leave) {
            rtu_shell_reshape(s, s->pending_width, s->pending_height);
            s->pending_width = s->pending_height = 0;
        }
        if (s->idle && !s->leave)
            s->idle();
        if (!s->leave)
            rtu_shell_display(s);
    }
    if (s->frames_rendered == 0 || !s->frame) {
        fprintf(stderr, "rtu: rtuMainLoop: no frame was rendered; %s not written\n", out);
        exit(EXIT_FAILURE);
    }
    if (!rtuSaveImage(out, s->frame_width, s->frame_height, RT_UNSIGNED_BYTE, s->frame)) {
        fprintf(stderr, "rtu: rtuMainLoop: %s\n", rtuImageError());
        exit(EXIT_FAILURE);
    }
    fprintf(stderr, "rtu: wrote %s (%dx%d, frame %ld)\n", out, s->frame_width, s->frame_height,
            s->frames_rendered);
}
