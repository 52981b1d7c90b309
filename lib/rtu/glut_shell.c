/* SPDX-License-Identifier: Apache-2.0 */
/*
 * glut_shell.c - the GLUT-style shell (Kilgard, "The OpenGL Utility
 * Toolkit (GLUT) Programming Interface, API Version 3", 1996, sec. 2-4, 7,
 * 9): initialisation, the window and its Tracelist context, callback
 * registration, timers, frames (rtuSwapBuffers), rtuGet; the main loop
 * goes to the window backend or runs headless (glut_shell.h).
 */
#include "glut_shell.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* __thread is a GNU extension (gcc and clang have it; C11 spells it
 * _Thread_local), as image.c uses it. */
static __thread struct rtu_shell shell;

struct rtu_shell *rtu_shell_state(void)
{
    return &shell;
}

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

double rtu_shell_elapsed(const struct rtu_shell *s)
{
    if (s->headless)
        return s->virtual_ms;
    return s->initialised ? now_ms() - s->start_ms : 0.0;
}

void rtu_shell_warn(const char *function, const char *message)
{
    fprintf(stderr, "rtu: %s: %s\n", function, message);
}

/* "-geometry WxH+X+Y" (each part optional, as X11 geometry strings). */
static void parse_geometry(struct rtu_shell *s, const char *g)
{
    int w, h, x, y, n = 0;
    if (sscanf(g, "%dx%d%n", &w, &h, &n) == 2 && w > 0 && h > 0) {
        s->init_width = w;
        s->init_height = h;
        g += n;
    }
    if (sscanf(g, "%d%d", &x, &y) == 2) {
        s->init_x = x;
        s->init_y = y;
    }
}

void rtuInit(int *argcp, char **argv)
{
    struct rtu_shell *s = &shell;
    int i, out = 1;
    if (s->initialised) {
        rtu_shell_warn("rtuInit", "called twice");
        return;
    }
    memset(s, 0, sizeof(*s));
    s->initialised = 1;
    s->start_ms = now_ms();
    s->init_x = s->init_y = -1;
    s->init_width = 300; /* GLUT's default window */
    s->init_height = 300;
    s->display_mode = RTU_RGBA | RTU_SINGLE;
    snprintf(s->program, sizeof(s->program), "rtu");
    if (argcp && argv && *argcp > 0 && argv[0]) {
        const char *base = strrchr(argv[0], '/');
        snprintf(s->program, sizeof(s->program), "%s", base ? base + 1 : argv[0]);
    }
    if (!argcp || !argv)
        return;
    /* GLUT's X options are taken out of argv; -geometry sets the initial
     * window, the others mean nothing here. */
    for (i = 1; i < *argcp; i++) {
        const char *a = argv[i];
        if (strcmp(a, "-geometry") == 0 && i + 1 < *argcp) {
            parse_geometry(s, argv[++i]);
        } else if (strcmp(a, "-display") == 0 && i + 1 < *argcp) {
            i++;
        } else if (strcmp(a, "-iconic") == 0 || strcmp(a, "-direct") == 0 ||
                   strcmp(a, "-indirect") == 0 || strcmp(a, "-gldebug") == 0 ||
                   strcmp(a, "-sync") == 0) {
        } else {
            argv[out++] = argv[i];
        }
    }
    if (out < *argcp)
        argv[out] = NULL;
    *argcp = out;
}

void rtuInitDisplayMode(unsigned int mode)
{
    shell.display_mode = mode;
}

void rtuInitWindowSize(int width, int height)
{
    if (width > 0 && height > 0) {
        shell.init_width = width;
        shell.init_height = height;
    }
}

void rtuInitWindowPosition(int x, int y)
{
    shell.init_x = x;
    shell.init_y = y;
}

int rtuCreateWindow(const char *title)
{
    struct rtu_shell *s = &shell;
    char reason[RT_REASON_SIZE];
    if (!s->initialised) {
        rtu_shell_warn("rtuCreateWindow", "rtuInit was not called");
        return 0;
    }
    if (s->window) {
        rtu_shell_warn("rtuCreateWindow", "the shell has one window; it exists already");
        return 0;
    }
    snprintf(s->title, sizeof(s->title), "%s", title ? title : "");
    s->width = s->init_width;
    s->height = s->init_height;
    s->x = s->init_x;
    s->y = s->init_y;
    /* The window's Tracelist context, current from here on: the
     * program's rt calls act on it as its gl calls acted on the GL
     * context GLUT made current.  TRACELIST_CONFIG configures it. */
    s->context = rtCreateContextWithReason(getenv("TRACELIST_CONFIG"), sizeof(reason), reason);
    if (!s->context) {
        fprintf(stderr, "rtu: rtuCreateWindow: cannot create a Tracelist context: %s\n", reason);
        exit(EXIT_FAILURE);
    }
    rtMakeCurrent(s->context);
    rtViewport(0, 0, s->width, s->height);
    s->headless = !rtu_window_open(s);
    s->window = 1;
    s->redisplay = 1;
    return 1;
}

void rtuDestroyWindow(int window)
{
    struct rtu_shell *s = &shell;
    if (window != 1 || !s->window) {
        rtu_shell_warn("rtuDestroyWindow", "no such window");
        return;
    }
    if (!s->headless)
        rtu_window_close(s);
    if (rtGetCurrentContext() == s->context)
        rtMakeCurrent(NULL);
    rtDestroyContext(s->context);
    s->context = NULL;
    s->window = 0;
    s->leave = 1;
}

int rtuGetWindow(void)
{
    return shell.window;
}

void rtuSetWindowTitle(const char *title)
{
    struct rtu_shell *s = &shell;
    if (!s->window)
        return;
    snprintf(s->title, sizeof(s->title), "%s", title ? title : "");
    if (!s->headless)
        rtu_window_set_title(s);
}

void rtuReshapeWindow(int width, int height)
{
    struct rtu_shell *s = &shell;
    if (!s->window || width <= 0 || height <= 0) {
        rtu_shell_warn("rtuReshapeWindow", "needs a window and a size > 0");
        return;
    }
    if (s->headless) {
        s->pending_width = width;
        s->pending_height = height;
    } else {
        rtu_window_resize(s, width, height);
    }
}

void rtuFullScreen(void)
{
    if (shell.window && !shell.headless)
        rtu_window_full_screen(&shell);
}

void rtuPostRedisplay(void)
{
    shell.redisplay = 1;
}

void rtuDisplayFunc(void (*func)(void)) { shell.display = func; }
void rtuReshapeFunc(void (*func)(int, int)) { shell.reshape = func; }
void rtuKeyboardFunc(void (*func)(unsigned char, int, int)) { shell.keyboard = func; }
void rtuKeyboardUpFunc(void (*func)(unsigned char, int, int)) { shell.keyboard_up = func; }
void rtuSpecialFunc(void (*func)(int, int, int)) { shell.special = func; }
void rtuSpecialUpFunc(void (*func)(int, int, int)) { shell.special_up = func; }
void rtuMouseFunc(void (*func)(int, int, int, int)) { shell.mouse = func; }
void rtuMotionFunc(void (*func)(int, int)) { shell.motion = func; }
void rtuPassiveMotionFunc(void (*func)(int, int)) { shell.passive_motion = func; }
void rtuIdleFunc(void (*func)(void)) { shell.idle = func; }
void rtuVisibilityFunc(void (*func)(int)) { shell.visibility = func; }

void rtuTimerFunc(unsigned int msecs, void (*func)(int value), int value)
{
    struct rtu_shell *s = &shell;
    struct rtu_timer *t;
    if (!func)
        return;
    if (s->timer_count >= RTU_SHELL_MAX_TIMERS) {
        rtu_shell_warn("rtuTimerFunc", "too many pending timers (256)");
        return;
    }
    t = &s->timers[s->timer_count++];
    t->due_ms = rtu_shell_elapsed(s) + msecs;
    t->order = s->timer_order++;
    t->func = func;
    t->value = value;
}

void rtu_shell_run_timers(struct rtu_shell *s, double now)
{
    /* Only timers registered before this pass run in it, earliest due
     * first (then in registration order); a timer that registers itself
     * again runs in a later pass. */
    const unsigned long before = s->timer_order;
    for (;;) {
        int best = -1, i;
        for (i = 0; i < s->timer_count; i++) {
            const struct rtu_timer *t = &s->timers[i];
            if (t->due_ms > now || t->order >= before)
                continue;
            if (best < 0 || t->due_ms < s->timers[best].due_ms ||
                (t->due_ms == s->timers[best].due_ms && t->order < s->timers[best].order))
                best = i;
        }
        if (best < 0 || s->leave)
            return;
        {
            const struct rtu_timer t = s->timers[best];
            s->timers[best] = s->timers[--s->timer_count];
            t.func(t.value);
        }
    }
}

double rtu_shell_next_timer(const struct rtu_shell *s, double now)
{
    double next = -1.0;
    int i;
    for (i = 0; i < s->timer_count; i++) {
        double wait = s->timers[i].due_ms - now;
        if (wait < 0.0)
            wait = 0.0;
        if (next < 0.0 || wait < next)
            next = wait;
    }
    return next;
}

void rtu_shell_reshape(struct rtu_shell *s, int width, int height)
{
    s->width = width;
    s->height = height;
    if (s->reshape)
        s->reshape(width, height);
    else
        rtViewport(0, 0, width, height); /* GLUT's default reshape */
    s->redisplay = 1;
}

/* Renders the frame and keeps it (window: shows it).  The framebuffer is
 * as large as the viewport reaches; the part of the window it does not
 * cover stays black. */
static void render_frame(struct rtu_shell *s)
{
    RTint vp[4] = {0, 0, 0, 0};
    int w = s->width, h = s->height, fw, fh, row;
    size_t bytes = (size_t)w * (size_t)h * 4;
    /* A display that ends with glFlush before glutSwapBuffers had its GL
     * frame traced by the flush: when nothing was drawn since, that image
     * is the frame, as GL's swap shows the buffer the flush completed
     * (state changed after the flush draws nothing in GL either). */
    RTint current = RT_FALSE;
    rtGetIntegerv(RT_FRAME_CURRENT, &current);
    if (!current)
        rtRenderFrame();
    rtGetIntegerv(RT_VIEWPORT, vp);
    fw = vp[0] + vp[2] < w ? vp[0] + vp[2] : w;
    fh = vp[1] + vp[3] < h ? vp[1] + vp[3] : h;
    if (s->frame_width != w || s->frame_height != h) {
        unsigned char *grown = realloc(s->frame, bytes ? bytes : 4);
        if (!grown) {
            rtu_shell_warn("rtuSwapBuffers", "out of memory");
            return;
        }
        s->frame = grown;
        s->frame_width = w;
        s->frame_height = h;
    }
    memset(s->frame, 0, bytes);
    if (fw > 0 && fh > 0) {
        unsigned char *tmp = malloc((size_t)fw * (size_t)fh * 4);
        if (!tmp) {
            rtu_shell_warn("rtuSwapBuffers", "out of memory");
            return;
        }
        rtReadPixels(0, 0, fw, fh, RT_RGBA, RT_UNSIGNED_BYTE, tmp);
        for (row = 0; row < fh; row++)
            memcpy(s->frame + (size_t)row * w * 4, tmp + (size_t)row * fw * 4, (size_t)fw * 4);
        free(tmp);
    }
    s->frames_rendered++;
    if (!s->headless)
        rtu_window_present(s);
}

void rtuSwapBuffers(void)
{
    struct rtu_shell *s = &shell;
    if (!s->window || rtGetCurrentContext() != s->context) {
        rtu_shell_warn("rtuSwapBuffers", "no window, or its context is not current");
        return;
    }
    s->swapped = 1;
    render_frame(s);
}

void rtu_shell_display(struct rtu_shell *s)
{
    s->redisplay = 0;
    if (!s->display)
        return;
    s->in_display = 1;
    s->swapped = 0;
    s->display();
    s->in_display = 0;
    /* A single-buffered program ends its display with glFlush, which
     * renames to nothing: render its frame here. */
    if (!s->swapped && s->window && !s->leave)
        render_frame(s);
}

void rtuMainLoop(void)
{
    struct rtu_shell *s = &shell;
    if (!s->window) {
        rtu_shell_warn("rtuMainLoop", "no window was created");
        exit(EXIT_FAILURE);
    }
    if (!s->display) {
        /* GLUT: "no display callback registered for window". */
        rtu_shell_warn("rtuMainLoop", "no display callback registered for the window");
        exit(EXIT_FAILURE);
    }
    s->leave = 0;
    if (s->headless)
        rtu_headless_main_loop(s);
    else
        rtu_window_main_loop(s);
    rtu_menu_free_all(s);
    free(s->frame);
    s->frame = NULL;
    s->frame_width = s->frame_height = 0;
}

void rtuLeaveMainLoop(void)
{
    shell.leave = 1;
}

int rtuGetModifiers(void)
{
    return shell.modifiers;
}

int rtuGet(RTenum state)
{
    const struct rtu_shell *s = &shell;
    switch (state) {
    case RTU_WINDOW_X:
        return s->window ? s->x : 0;
    case RTU_WINDOW_Y:
        return s->window ? s->y : 0;
    case RTU_WINDOW_WIDTH:
        return s->window ? s->width : 0;
    case RTU_WINDOW_HEIGHT:
        return s->window ? s->height : 0;
    case RTU_WINDOW_DEPTH_SIZE:
        return s->window && (s->display_mode & RTU_DEPTH) ? 24 : 0;
    case RTU_WINDOW_DOUBLEBUFFER:
        return s->window && (s->display_mode & RTU_DOUBLE) ? 1 : 0;
    case RTU_WINDOW_RGBA:
        return s->window ? 1 : 0;
    case RTU_SCREEN_WIDTH:
        return s->window ? s->width : 0;
    case RTU_SCREEN_HEIGHT:
        return s->window ? s->height : 0;
    case RTU_MENU_NUM_ITEMS:
        return s->current_menu ? s->menus[s->current_menu].count : 0;
    case RTU_DISPLAY_MODE_POSSIBLE:
        /* Colour index, stereo and multisampling have no ray traced
         * meaning; every RGBA mode is possible. */
        return (s->display_mode & (RTU_INDEX | RTU_STEREO)) == 0;
    case RTU_INIT_WINDOW_X:
        return s->init_x;
    case RTU_INIT_WINDOW_Y:
        return s->init_y;
    case RTU_INIT_WINDOW_WIDTH:
        return s->init_width;
    case RTU_INIT_WINDOW_HEIGHT:
        return s->init_height;
    case RTU_INIT_DISPLAY_MODE:
        return (int)s->display_mode;
    case RTU_ELAPSED_TIME:
        return (int)rtu_shell_elapsed(s);
    default:
        /* GLUT warns and returns -1 for a state it does not know. */
        {
            char message[64];
            snprintf(message, sizeof(message), "unknown state %u", state);
            rtu_shell_warn("rtuGet", message);
        }
        return -1;
    }
}
