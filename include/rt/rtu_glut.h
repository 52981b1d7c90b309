/* SPDX-License-Identifier: Apache-2.0 */
/*
 * rtu_glut.h - the GLUT-style window shell and the GLUT bitmap fonts of
 * rtu (docs/glut.md, docs/text.md).  Included by rt/rtu.h; not meant to
 * be included alone.
 *
 * A GLUT program ports by renaming glut to rtu and GLUT_ to RTU_: the
 * constants have GLUT's values.  rtuCreateWindow creates and makes current
 * a Tracelist context for the window, so the program's gl calls (renamed
 * rt) act on it; rtuSwapBuffers renders the frame and shows it.  With a
 * display (and rtu built with GLFW) the window is a GLFW window; without
 * one, or with TRACELIST_HEADLESS=1, the shell runs headless: it replays
 * the events of TRACELIST_EVENTS, renders TRACELIST_FRAMES frames and
 * writes the last to TRACELIST_OUT (docs/glut.md).
 */
#ifndef RT_RTU_GLUT_H
#define RT_RTU_GLUT_H

#include <rt/rt.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---- GLUT: display modes (rtuInitDisplayMode; GLUT's values) ----------- */
#define RTU_RGB 0
#define RTU_RGBA 0
#define RTU_INDEX 1
#define RTU_SINGLE 0
#define RTU_DOUBLE 2
#define RTU_ACCUM 4
#define RTU_ALPHA 8
#define RTU_DEPTH 16
#define RTU_STENCIL 32
#define RTU_MULTISAMPLE 128
#define RTU_STEREO 256

/* ---- GLUT: input --------------------------------------------------------- */
#define RTU_LEFT_BUTTON 0
#define RTU_MIDDLE_BUTTON 1
#define RTU_RIGHT_BUTTON 2
#define RTU_DOWN 0
#define RTU_UP 1
#define RTU_KEY_F1 1
#define RTU_KEY_F2 2
#define RTU_KEY_F3 3
#define RTU_KEY_F4 4
#define RTU_KEY_F5 5
#define RTU_KEY_F6 6
#define RTU_KEY_F7 7
#define RTU_KEY_F8 8
#define RTU_KEY_F9 9
#define RTU_KEY_F10 10
#define RTU_KEY_F11 11
#define RTU_KEY_F12 12
#define RTU_KEY_LEFT 100
#define RTU_KEY_UP 101
#define RTU_KEY_RIGHT 102
#define RTU_KEY_DOWN 103
#define RTU_KEY_PAGE_UP 104
#define RTU_KEY_PAGE_DOWN 105
#define RTU_KEY_HOME 106
#define RTU_KEY_END 107
#define RTU_KEY_INSERT 108
#define RTU_ACTIVE_SHIFT 1
#define RTU_ACTIVE_CTRL 2
#define RTU_ACTIVE_ALT 4
#define RTU_NOT_VISIBLE 0
#define RTU_VISIBLE 1

/* ---- GLUT: rtuGet ------------------------------------------------------- */
#define RTU_WINDOW_X 100
#define RTU_WINDOW_Y 101
#define RTU_WINDOW_WIDTH 102
#define RTU_WINDOW_HEIGHT 103
#define RTU_WINDOW_DEPTH_SIZE 106
#define RTU_WINDOW_DOUBLEBUFFER 115
#define RTU_WINDOW_RGBA 116
#define RTU_SCREEN_WIDTH 200
#define RTU_SCREEN_HEIGHT 201
#define RTU_MENU_NUM_ITEMS 300
#define RTU_DISPLAY_MODE_POSSIBLE 400
#define RTU_INIT_WINDOW_X 500
#define RTU_INIT_WINDOW_Y 501
#define RTU_INIT_WINDOW_WIDTH 502
#define RTU_INIT_WINDOW_HEIGHT 503
#define RTU_INIT_DISPLAY_MODE 504
#define RTU_ELAPSED_TIME 700

/* ---- GLUT: initialisation and the window (docs/glut.md) ----------------- */
RTAPI void rtuInit(int *argcp, char **argv);
RTAPI void rtuInitDisplayMode(unsigned int mode);
RTAPI void rtuInitWindowSize(int width, int height);
RTAPI void rtuInitWindowPosition(int x, int y);
RTAPI int rtuCreateWindow(const char *title);
RTAPI void rtuDestroyWindow(int window);
RTAPI int rtuGetWindow(void);
RTAPI void rtuSetWindowTitle(const char *title);
RTAPI void rtuReshapeWindow(int width, int height);
RTAPI void rtuFullScreen(void);
RTAPI void rtuPostRedisplay(void);
RTAPI void rtuSwapBuffers(void);
RTAPI void rtuMainLoop(void);
RTAPI void rtuLeaveMainLoop(void);
RTAPI int rtuGet(RTenum state);
RTAPI int rtuGetModifiers(void);

/* ---- GLUT: callbacks ---------------------------------------------------- */
RTAPI void rtuDisplayFunc(void (*func)(void));
RTAPI void rtuReshapeFunc(void (*func)(int width, int height));
RTAPI void rtuKeyboardFunc(void (*func)(unsigned char key, int x, int y));
RTAPI void rtuKeyboardUpFunc(void (*func)(unsigned char key, int x, int y));
RTAPI void rtuSpecialFunc(void (*func)(int key, int x, int y));
RTAPI void rtuSpecialUpFunc(void (*func)(int key, int x, int y));
RTAPI void rtuMouseFunc(void (*func)(int button, int state, int x, int y));
RTAPI void rtuMotionFunc(void (*func)(int x, int y));
RTAPI void rtuPassiveMotionFunc(void (*func)(int x, int y));
RTAPI void rtuIdleFunc(void (*func)(void));
RTAPI void rtuTimerFunc(unsigned int msecs, void (*func)(int value), int value);
RTAPI void rtuVisibilityFunc(void (*func)(int state));

/* ---- GLUT: menus (in a window: mapped to keys; headless: by label) ------ */
RTAPI int rtuCreateMenu(void (*func)(int value));
RTAPI void rtuDestroyMenu(int menu);
RTAPI int rtuGetMenu(void);
RTAPI void rtuSetMenu(int menu);
RTAPI void rtuAddMenuEntry(const char *label, int value);
RTAPI void rtuAddSubMenu(const char *label, int submenu);
RTAPI void rtuAttachMenu(int button);
RTAPI void rtuDetachMenu(int button);

/* ---- GLUT: bitmap fonts (docs/text.md) ---------------------------------- */
/* Opaque font names, as GLUT's; the values are those of GLUT on Windows.
 * The glyphs are Tracelist's own design; advances and heights follow
 * GLUT's fonts (docs/text.md). */
#define RTU_BITMAP_9_BY_15 ((void *)0x0002)
#define RTU_BITMAP_8_BY_13 ((void *)0x0003)
#define RTU_BITMAP_TIMES_ROMAN_10 ((void *)0x0004)
#define RTU_BITMAP_TIMES_ROMAN_24 ((void *)0x0005)
#define RTU_BITMAP_HELVETICA_10 ((void *)0x0006)
#define RTU_BITMAP_HELVETICA_12 ((void *)0x0007)
#define RTU_BITMAP_HELVETICA_18 ((void *)0x0008)
RTAPI void rtuBitmapCharacter(void *font, int character);
RTAPI void rtuBitmapString(void *font, const unsigned char *string);
RTAPI int rtuBitmapWidth(void *font, int character);
RTAPI int rtuBitmapLength(void *font, const unsigned char *string);
RTAPI int rtuBitmapHeight(void *font);

#ifdef __cplusplus
}
#endif

#endif /* RT_RTU_GLUT_H */
