/* SPDX-License-Identifier: Apache-2.0 */
/*
 * glut_window.c - the shell's main loop ended by the program: reshape
 * with the window size before the first display, an idle callback that
 * posts redisplays, rtuLeaveMainLoop after the third display, then
 * rtuMainLoop returns with the window's context released.  ctest runs it
 * headless (TRACELIST_HEADLESS=1, more frames asked than it draws: the
 * last frame drawn is written) and, where GLFW and xvfb-run exist, in a
 * real window.
 */
#include <rt/rt.h>
#include <rt/rtu.h>

#include "check.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int displays, reshapes, first_display_after_reshape = -1;
static int reshape_w, reshape_h;

static void reshape(int w, int h)
{
    reshapes++;
    reshape_w = w;
    reshape_h = h;
    rtViewport(0, 0, w, h);
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtuPerspective(40.0, (double)w / h, 1.0, 20.0);
    rtMatrixMode(RT_MODELVIEW);
}

static void display(void)
{
    if (displays == 0)
        first_display_after_reshape = reshapes > 0;
    displays++;
    rtLoadIdentity();
    rtTranslated(0.0, 0.0, -5.0);
    rtRotated(20.0 * displays, 0.0, 1.0, 0.0);
    rtBeginFrame();
    rtInstantiateObject(1);
    rtColor3f(1, 1, 1);
    rtWindowPos2i(2, 2);
    rtuBitmapString(RTU_BITMAP_8_BY_13, (const unsigned char *)"frame");
    rtuSwapBuffers();
    if (displays == 3)
        rtuLeaveMainLoop();
}

static void idle(void)
{
    rtuPostRedisplay();
}

int main(int argc, char **argv)
{
    rtuInit(&argc, argv);
    rtuInitDisplayMode(RTU_RGB | RTU_DOUBLE | RTU_DEPTH);
    rtuInitWindowSize(64, 48);
    CHECK_INT(rtuCreateWindow("glut window"), 1);
    rtNewObject(1);
    rtuSolidTeapot(1.0);
    rtEndObject();
    rtuDisplayFunc(display);
    rtuReshapeFunc(reshape);
    rtuIdleFunc(idle);
    CHECK_INT(rtuGet(RTU_WINDOW_WIDTH), 64);
    rtuMainLoop();
    CHECK_INT(displays, 3);
    CHECK_INT(first_display_after_reshape, 1);
    CHECK(reshapes >= 1);
    CHECK_INT(reshape_w, 64);
    CHECK_INT(reshape_h, 48);
    CHECK(rtGetCurrentContext() == NULL || getenv("TRACELIST_HEADLESS") != NULL);
    return test_summary("glut/window");
}
