/* SPDX-License-Identifier: Apache-2.0 */
/*
 * glut_events.c - a small GLUT-style program run by the headless shell
 * (docs/glut.md): ctest sets TRACELIST_HEADLESS=1, TRACELIST_SIZE,
 * TRACELIST_FRAMES=3, TRACELIST_OUT and TRACELIST_EVENTS (a key, a special
 * key, a menu label with a space, a key by code) and this program checks,
 * after rtuMainLoop returns, that its callbacks ran in GLUT's order
 * (visibility, reshape before display, the events in order, then per
 * frame the due timers, idle, display) with the deterministic clock, and
 * that the image written has what the last display drew: the clear colour
 * the menu chose, the square the special key moved, the text's bitmap.
 * The same program run with bad variables must stop with a clear message
 * (the other ctest entries, by their output).
 */
#include <rt/rt.h>
#include <rt/rtu.h>

#include "check.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static char events[2048];
static int idle_calls;
static float clear_rgb[3] = {0.0f, 0.0f, 0.0f};
static float square_y = -0.5f;
static int window_w, window_h;

static void note(const char *fmt, int a, int b)
{
    char line[96];
    snprintf(line, sizeof line, fmt, a, b);
    if (strlen(events) + strlen(line) + 2 < sizeof events) {
        strcat(events, line);
        strcat(events, ";");
    }
}

static void reshape(int w, int h)
{
    note("reshape %dx%d", w, h);
    window_w = w;
    window_h = h;
    rtViewport(0, 0, w, h);
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtOrtho(-1, 1, -1, 1, -1, 1);
    rtMatrixMode(RT_MODELVIEW);
}

static void display(void)
{
    static const RTubyte block[4 * 4] = {0xF0, 0, 0, 0, 0xF0, 0, 0, 0, 0xF0, 0, 0, 0,
                                         0xF0, 0, 0, 0};
    note("display t=%d", rtuGet(RTU_ELAPSED_TIME), 0);
    rtClearColor(clear_rgb[0], clear_rgb[1], clear_rgb[2], 1.0f);
    rtNewObject(1);
    rtBegin(RT_QUADS);
    rtNormal3f(0, 0, 1);
    rtVertex2f(-0.25f, square_y);
    rtVertex2f(0.25f, square_y);
    rtVertex2f(0.25f, square_y + 0.5f);
    rtVertex2f(-0.25f, square_y + 0.5f);
    rtEnd();
    rtEndObject();
    rtLoadIdentity();
    rtInstantiateObject(1);
    rtColor3f(1.0f, 1.0f, 0.0f);
    rtWindowPos2i(2, 2);
    rtBitmap(4, 4, 0, 0, 4, 0, block);
    rtuSwapBuffers();
}

static void keyboard(unsigned char key, int x, int y)
{
    (void)x;
    (void)y;
    note("key %d", key, 0);
    if (key == 'r')
        clear_rgb[0] = 1.0f;
}

static void keyboard_up(unsigned char key, int x, int y)
{
    (void)x;
    (void)y;
    note("keyup %d", key, 0);
}

static void special(int key, int x, int y)
{
    (void)x;
    (void)y;
    note("special %d", key, 0);
    if (key == RTU_KEY_UP)
        square_y += 0.5f;
}

static void menu(int value)
{
    note("menu %d (current %d)", value, rtuGetMenu());
    if (value == 3) {
        clear_rgb[0] = 0.0f;
        clear_rgb[2] = 1.0f;
    }
}

static void timer(int value)
{
    note("timer %d t=%d", value, rtuGet(RTU_ELAPSED_TIME));
}

static void idle(void)
{
    idle_calls++;
}

static void visibility(int state)
{
    note("visible %d", state, 0);
}

static int same(const unsigned char *p, int r, int g, int b)
{
    return p[0] == r && p[1] == g && p[2] == b;
}

static void check_image(const char *path)
{
    RTsizei w = 0, h = 0;
    unsigned char *img = rtuLoadImage(path, &w, &h, RT_UNSIGNED_BYTE);
    CHECKF(img != NULL, "cannot read %s: %s", path, rtuImageError());
    if (!img)
        return;
    CHECK_INT(w, 80);
    CHECK_INT(h, 60);
    if (w == 80 && h == 60) {
        /* Rows bottom to top.  The menu made the background blue. */
        CHECK(same(img + 4 * (5 * 80 + 70), 0, 0, 255));
        /* The special key moved the square up: it covers (40, 40), not
         * (40, 10). */
        CHECK(!same(img + 4 * (40 * 80 + 40), 0, 0, 255));
        CHECK(same(img + 4 * (10 * 80 + 40), 0, 0, 255));
        /* The bitmap: 4 x 4 yellow at (2, 2), over the background. */
        CHECK(same(img + 4 * (2 * 80 + 2), 255, 255, 0));
        CHECK(same(img + 4 * (5 * 80 + 5), 255, 255, 0));
        CHECK(same(img + 4 * (6 * 80 + 6), 0, 0, 255));
    }
    rtuFreeImage(img);
}

int main(int argc, char **argv)
{
    int top, sub;
    const char *expected =
        "visible 1;reshape 80x60;key 114;keyup 114;special 101;menu 3 (current 2);"
        "menu 9 (current 1);key 32;keyup 32;"
        "timer 5 t=0;display t=0;display t=16;timer 7 t=33;display t=33;";
    rtuInit(&argc, argv);
    rtuInitDisplayMode(RTU_RGB | RTU_DOUBLE | RTU_DEPTH);
    rtuInitWindowSize(40, 30);
    rtuInitWindowPosition(10, 10);
    CHECK_INT(rtuGet(RTU_INIT_WINDOW_WIDTH), 40);
    CHECK_INT(rtuGet(RTU_INIT_DISPLAY_MODE), RTU_DOUBLE | RTU_DEPTH);
    CHECK_INT(rtuCreateWindow("glut events"), 1);
    CHECK(rtGetCurrentContext() != NULL);
    rtuDisplayFunc(display);
    rtuReshapeFunc(reshape);
    rtuKeyboardFunc(keyboard);
    rtuKeyboardUpFunc(keyboard_up);
    rtuSpecialFunc(special);
    rtuIdleFunc(idle);
    rtuVisibilityFunc(visibility);
    sub = rtuCreateMenu(menu);
    rtuAddMenuEntry("Deep one", 9);
    top = rtuCreateMenu(menu);
    rtuAddMenuEntry("Red", 1);
    rtuAddMenuEntry("Blue sky", 3);
    rtuAddSubMenu("More", sub);
    rtuAttachMenu(RTU_RIGHT_BUTTON);
    CHECK_INT(rtuGetMenu(), top);
    CHECK_INT(rtuGet(RTU_MENU_NUM_ITEMS), 3);
    rtuTimerFunc(30, timer, 7);
    rtuTimerFunc(0, timer, 5);
    rtuMainLoop();
    CHECKF(strcmp(events, expected) == 0, "callbacks ran as\n  %s\nexpected\n  %s", events,
           expected);
    CHECK_INT(idle_calls, 3);
    CHECK_INT(window_w, 80);
    check_image(getenv("TRACELIST_OUT"));
    return test_summary("glut/events");
}
