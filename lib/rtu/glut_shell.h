/* SPDX-License-Identifier: Apache-2.0 */
/*
 * glut_shell.h - the state of the GLUT-style window shell and the
 * interfaces between its parts: glut_shell.c (initialisation, the window,
 * callbacks, frames, rtuGet), glut_shell_window.c (the GLFW window and its
 * main loop), glut_shell_headless.c (the environment and the replay of
 * events without a window), glut_shell_menu.c (menus).
 *
 * GLUT keeps one state per program; ours is per thread (like the current
 * context, which the shell makes current in the thread that creates the
 * window), in glut_shell.c.
 */
#ifndef RTU_GLUT_SHELL_H
#define RTU_GLUT_SHELL_H

#include <rt/rt.h>
#include <rt/rtu.h>

#define RTU_SHELL_MAX_MENUS 64
#define RTU_SHELL_MAX_TIMERS 256
#define RTU_SHELL_BUTTONS 3

struct rtu_menu_entry {
    char *label;
    int value;
    int submenu; /* 0: an entry with a value; else the submenu's id */
};

struct rtu_menu {
    int live;
    void (*func)(int value);
    struct rtu_menu_entry *entries;
    int count, capacity;
};

struct rtu_timer {
    double due_ms;
    unsigned long order; /* registration order: equal due times keep it */
    void (*func)(int value);
    int value;
};

struct rtu_shell {
    int initialised;
    char program[128]; /* argv[0] without directories: the default output name */
    unsigned int display_mode;
    int init_x, init_y, init_width, init_height;
    double start_ms; /* rtuInit, on the monotonic clock */

    /* The window (at most one) and its context. */
    int window;          /* 1 while it exists, else 0 */
    int width, height;   /* its size (headless: the output size) */
    int x, y;
    RTcontext context;
    int headless;        /* no GLFW window: events from TRACELIST_EVENTS */
    void *backend;       /* the GLFWwindow */
    char title[256];

    /* Callbacks. */
    void (*display)(void);
    void (*reshape)(int width, int height);
    void (*keyboard)(unsigned char key, int x, int y);
    void (*keyboard_up)(unsigned char key, int x, int y);
    void (*special)(int key, int x, int y);
    void (*special_up)(int key, int x, int y);
    void (*mouse)(int button, int state, int x, int y);
    void (*motion)(int x, int y);
    void (*passive_motion)(int x, int y);
    void (*idle)(void);
    void (*visibility)(int state);

    struct rtu_timer timers[RTU_SHELL_MAX_TIMERS];
    int timer_count;
    unsigned long timer_order;

    struct rtu_menu menus[RTU_SHELL_MAX_MENUS + 1]; /* ids 1 .. MAX */
    int current_menu;
    int attached[RTU_SHELL_BUTTONS]; /* menu id per mouse button, 0: none */
    int open_menu;                   /* window: the menu waiting for a key */

    /* The main loop. */
    int redisplay;
    int leave;
    int modifiers;
    int pending_width, pending_height; /* rtuReshapeWindow, 0: none */
    double virtual_ms; /* headless: the deterministic clock */
    int in_display, swapped;
    unsigned char *frame; /* the last frame, RGBA8, width x height */
    int frame_width, frame_height;
    long frames_rendered;
};

/* The calling thread's shell state. */
struct rtu_shell *rtu_shell_state(void);
/* Milliseconds since rtuInit: the real clock, or headless the virtual one. */
double rtu_shell_elapsed(const struct rtu_shell *s);
/* Prints "rtu: <function>: <message>" (GLUT's warnings go to stderr). */
void rtu_shell_warn(const char *function, const char *message);

/* Calls the reshape callback (or GLUT's default, the viewport). */
void rtu_shell_reshape(struct rtu_shell *s, int width, int height);
/* Calls the display callback; renders the frame if it did not swap. */
void rtu_shell_display(struct rtu_shell *s);
/* Runs the timers due at `now` (those registered meanwhile wait). */
void rtu_shell_run_timers(struct rtu_shell *s, double now);
/* Milliseconds until the next timer, or -1 when there is none. */
double rtu_shell_next_timer(const struct rtu_shell *s, double now);

/* Window backend (glut_shell_window.c): 1 when a window was opened. */
int rtu_window_open(struct rtu_shell *s);
void rtu_window_close(struct rtu_shell *s);
void rtu_window_set_title(struct rtu_shell *s);
void rtu_window_resize(struct rtu_shell *s, int width, int height);
void rtu_window_full_screen(struct rtu_shell *s);
void rtu_window_present(struct rtu_shell *s);
void rtu_window_main_loop(struct rtu_shell *s);

/* Headless (glut_shell_headless.c): reshape, events, frames, the image. */
void rtu_headless_main_loop(struct rtu_shell *s);

/* Menus (glut_shell_menu.c). */
/* Selects the entry labelled `label` ('_' read as a space) of the attached
 * menus and their submenus (all menus when none is attached): calls its
 * menu's callback.  Returns 0 when there is no such entry. */
int rtu_menu_select_label(struct rtu_shell *s, const char *label);
/* Window: opens menu `menu` for keys (prints the keys of its entries). */
void rtu_menu_open(struct rtu_shell *s, int menu);
/* Window: a key while a menu is open; returns 1 when the menu took it. */
int rtu_menu_key(struct rtu_shell *s, int key);
/* Frees every menu. */
void rtu_menu_free_all(struct rtu_shell *s);

#endif
