/* SPDX-License-Identifier: Apache-2.0 */
/*
 * glut_shell_window.c - the shell's window: GLFW when rtu was built with
 * it (RTU_HAVE_GLFW) and a display is there; otherwise there is no window
 * and the shell runs headless (glut_shell_headless.c).
 *
 * The window shows each frame by glDrawPixels of rtReadPixels (rows bottom
 * to top, the order glDrawPixels wants).  GLFW's input is translated to
 * GLUT's callbacks: printable characters (and Enter, Escape, Tab,
 * Backspace, Delete, control letters) to the keyboard callback, function,
 * arrow and page keys to the special callback with GLUT's codes, buttons
 * to GLUT's (left 0, middle 1, right 2) with y down from the top as GLUT
 * gives it; a button with a menu attached opens the menu instead
 * (glut_shell_menu.c).
 */
#include "glut_shell.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef RTU_HAVE_GLFW

#include <GLFW/glfw3.h>

static int glut_modifiers(int mods)
{
    return ((mods & GLFW_MOD_SHIFT) ? RTU_ACTIVE_SHIFT : 0) |
           ((mods & GLFW_MOD_CONTROL) ? RTU_ACTIVE_CTRL : 0) |
           ((mods & GLFW_MOD_ALT) ? RTU_ACTIVE_ALT : 0);
}

static void cursor(GLFWwindow *w, int *x, int *y)
{
    double cx, cy;
    glfwGetCursorPos(w, &cx, &cy);
    *x = (int)cx;
    *y = (int)cy;
}

/* GLUT's special key code of a GLFW key, 0 for none. */
static int special_code(int key)
{
    if (key >= GLFW_KEY_F1 && key <= GLFW_KEY_F12)
        return RTU_KEY_F1 + (key - GLFW_KEY_F1);
    switch (key) {
    case GLFW_KEY_LEFT: return RTU_KEY_LEFT;
    case GLFW_KEY_UP: return RTU_KEY_UP;
    case GLFW_KEY_RIGHT: return RTU_KEY_RIGHT;
    case GLFW_KEY_DOWN: return RTU_KEY_DOWN;
    case GLFW_KEY_PAGE_UP: return RTU_KEY_PAGE_UP;
    case GLFW_KEY_PAGE_DOWN: return RTU_KEY_PAGE_DOWN;
    case GLFW_KEY_HOME: return RTU_KEY_HOME;
    case GLFW_KEY_END: return RTU_KEY_END;
    case GLFW_KEY_INSERT: return RTU_KEY_INSERT;
    default: return 0;
    }
}

/* The ASCII code of keys GLFW gives no character for, 0 for none. */
static int control_code(int key, int mods)
{
    if ((mods & GLFW_MOD_CONTROL) && key >= GLFW_KEY_A && key <= GLFW_KEY_Z)
        return key - GLFW_KEY_A + 1;
    switch (key) {
    case GLFW_KEY_ENTER: case GLFW_KEY_KP_ENTER: return 13;
    case GLFW_KEY_ESCAPE: return 27;
    case GLFW_KEY_TAB: return 9;
    case GLFW_KEY_BACKSPACE: return 8;
    case GLFW_KEY_DELETE: return 127;
    default: return 0;
    }
}

static void deliver_key(struct rtu_shell *s, GLFWwindow *w, int code, int up)
{
    int x, y;
    if (!up && rtu_menu_key(s, code))
        return;
    cursor(w, &x, &y);
    if (up && s->keyboard_up)
        s->keyboard_up((unsigned char)code, x, y);
    else if (!up && s->keyboard)
        s->keyboard((unsigned char)code, x, y);
}

static void on_key(GLFWwindow *w, int key, int scancode, int action, int mods)
{
    struct rtu_shell *s = rtu_shell_state();
    int code, x, y;
    (void)scancode;
    s->modifiers = glut_modifiers(mods);
    code = special_code(key);
    if (code) {
        cursor(w, &x, &y);
        if (action != GLFW_RELEASE && s->special)
            s->special(code, x, y);
        else if (action == GLFW_RELEASE && s->special_up)
            s->special_up(code, x, y);
        return;
    }
    code = control_code(key, mods);
    if (code)
        deliver_key(s, w, code, action == GLFW_RELEASE);
    else if (action == GLFW_RELEASE && key >= 32 && key < 127 && s->keyboard_up)
        deliver_key(s, w, (mods & GLFW_MOD_SHIFT) ? key : (key >= 'A' && key <= 'Z' ? key + 32 : key), 1);
}

static void on_char(GLFWwindow *w, unsigned int codepoint)
{
    struct rtu_shell *s = rtu_shell_state();
    if (codepoint < 256)
        deliver_key(s, w, (int)codepoint, 0);
}

static void on_button(GLFWwindow *w, int button, int action, int mods)
{
    struct rtu_shell *s = rtu_shell_state();
    int glut_button, x, y;
    s->modifiers = glut_modifiers(mods);
    glut_button = button == GLFW_MOUSE_BUTTON_LEFT     ? RTU_LEFT_BUTTON
                  : button == GLFW_MOUSE_BUTTON_MIDDLE ? RTU_MIDDLE_BUTTON
                  : button == GLFW_MOUSE_BUTTON_RIGHT  ? RTU_RIGHT_BUTTON
                                                       : -1;
    if (glut_button < 0)
        return;
    if (s->attached[glut_button]) {
        if (action == GLFW_PRESS)
            rtu_menu_open(s, s->attached[glut_button]);
        return;
    }
    cursor(w, &x, &y);
    if (s->mouse)
        s->mouse(glut_button, action == GLFW_PRESS ? RTU_DOWN : RTU_UP, x, y);
}

static void on_cursor(GLFWwindow *w, double cx, double cy)
{
    struct rtu_shell *s = rtu_shell_state();
    const int pressed = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS ||
                        glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS ||
                        glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
    if (pressed && s->motion)
        s->motion((int)cx, (int)cy);
    else if (!pressed && s->passive_motion)
        s->passive_motion((int)cx, (int)cy);
}

static void on_refresh(GLFWwindow *w)
{
    (void)w;
    rtu_shell_state()->redisplay = 1;
}

static int display_present(void)
{
    const char *headless = getenv("TRACELIST_HEADLESS");
    const char *x11 = getenv("DISPLAY");
    const char *wayland = getenv("WAYLAND_DISPLAY");
    if (headless && *headless && strcmp(headless, "0") != 0)
        return 0;
    return (x11 && *x11) || (wayland && *wayland);
}

int rtu_window_open(struct rtu_shell *s)
{
    GLFWwindow *w;
    if (!display_present() || !glfwInit())
        return 0;
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    w = glfwCreateWindow(s->width, s->height, s->title, NULL, NULL);
    if (!w) {
        glfwTerminate();
        return 0;
    }
    if (s->x >= 0 && s->y >= 0)
        glfwSetWindowPos(w, s->x, s->y);
    glfwMakeContextCurrent(w);
    glfwSwapInterval(0);
    glfwSetKeyCallback(w, on_key);
    glfwSetCharCallback(w, on_char);
    glfwSetMouseButtonCallback(w, on_button);
    glfwSetCursorPosCallback(w, on_cursor);
    glfwSetWindowRefreshCallback(w, on_refresh);
    s->backend = w;
    return 1;
}

void rtu_window_close(struct rtu_shell *s)
{
    if (!s->backend)
        return;
    glfwDestroyWindow((GLFWwindow *)s->backend);
    glfwTerminate();
    s->backend = NULL;
}

void rtu_window_set_title(struct rtu_shell *s)
{
    if (s->backend)
        glfwSetWindowTitle((GLFWwindow *)s->backend, s->title);
}

void rtu_window_resize(struct rtu_shell *s, int width, int height)
{
    if (s->backend)
        glfwSetWindowSize((GLFWwindow *)s->backend, width, height);
}

void rtu_window_full_screen(struct rtu_shell *s)
{
    if (s->backend)
        glfwMaximizeWindow((GLFWwindow *)s->backend);
}

void rtu_window_present(struct rtu_shell *s)
{
    GLFWwindow *w = (GLFWwindow *)s->backend;
    int fb_width, fb_height;
    if (!w || !s->frame)
        return;
    glfwGetFramebufferSize(w, &fb_width, &fb_height);
    glViewport(0, 0, fb_width, fb_height);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRasterPos2f(-1.0f, -1.0f);
    glDrawPixels(s->frame_width, s->frame_height, GL_RGBA, GL_UNSIGNED_BYTE, s->frame);
    glfwSwapBuffers(w);
}

void rtu_window_main_loop(struct rtu_shell *s)
{
    GLFWwindow *w = (GLFWwindow *)s->backend;
    int width = -1, height = -1;
    if (s->visibility)
        s->visibility(RTU_VISIBLE);
    while (s->window && !s->leave && !glfwWindowShouldClose(w)) {
        int fw, fh;
        double wait;
        glfwGetFramebufferSize(w, &fw, &fh);
        if ((fw != width || fh != height) && fw > 0 && fh > 0) {
            width = fw;
            height = fh;
            rtu_shell_reshape(s, width, height);
        }
        if (s->redisplay && width > 0)
            rtu_shell_display(s);
        if (s->leave || !s->window)
            break;
        rtu_shell_run_timers(s, rtu_shell_elapsed(s));
        if (s->leave || !s->window)
            break;
        if (s->idle) {
            s->idle();
            glfwPollEvents();
            continue;
        }
        if (s->redisplay) {
            glfwPollEvents();
            continue;
        }
        wait = rtu_shell_next_timer(s, rtu_shell_elapsed(s));
        if (wait < 0.0)
            glfwWaitEvents();
        else
            glfwWaitEventsTimeout(wait / 1000.0);
    }
    if (s->window) {
        rtu_window_close(s);
        if (rtGetCurrentContext() == s->context)
            rtMakeCurrent(NULL);
        rtDestroyContext(s->context);
        s->context = NULL;
        s->window = 0;
    }
}

#else /* !RTU_HAVE_GLFW: headless only */

int rtu_window_open(struct rtu_shell *s)
{
    (void)s;
    return 0;
}

void rtu_window_close(struct rtu_shell *s) { (void)s; }
void rtu_window_set_title(struct rtu_shell *s) { (void)s; }
void rtu_window_full_screen(struct rtu_shell *s) { (void)s; }
void rtu_window_present(struct rtu_shell *s) { (void)s; }
void rtu_window_main_loop(struct rtu_shell *s) { (void)s; }

void rtu_window_resize(struct rtu_shell *s, int width, int height)
{
    (void)s;
    (void)width;
    (void)height;
}

#endif
