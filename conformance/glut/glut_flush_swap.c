/* SPDX-License-Identifier: Apache-2.0 */
/*
 * glut_flush_swap.c - a display that ends with glFlush and then
 * glutSwapBuffers traces its frame once (RT_FRAMES_TRACED): the swap shows
 * the image the flush traced.  Something drawn after the flush is traced
 * by the swap (the frame is no longer current).  Before the first rtClear
 * (no GL frame yet) every swap traces, as before.  ctest runs it
 * headless.
 */
#include <rt/rt.h>
#include <rt/rtu.h>

#include "check.h"

#include <stdio.h>

static int displays;
static RTint traced_in_display[3];

static RTint frames_traced(void)
{
    RTint n = -1;
    rtGetIntegerv(RT_FRAMES_TRACED, &n);
    return n;
}

static void quad(float x0, float x1)
{
    rtBegin(RT_QUADS);
    rtVertex3f(x0, -0.5f, 0.0f);
    rtVertex3f(x1, -0.5f, 0.0f);
    rtVertex3f(x1, 0.5f, 0.0f);
    rtVertex3f(x0, 0.5f, 0.0f);
    rtEnd();
}

/* Red at pixel (x, y) of the last traced image. */
static int red_at(int x, int y)
{
    RTubyte px[4] = {0, 0, 0, 0};
    rtReadPixels(x, y, 1, 1, RT_RGBA, RT_UNSIGNED_BYTE, px);
    return px[0] > 200 && px[1] < 50 && px[2] < 50;
}

static void display(void)
{
    RTint before = frames_traced();
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtColor3f(1, 0, 0);
    switch (displays) {
    case 0: /* glClear, draw, glFlush, glutSwapBuffers: one trace */
        rtClear(RT_COLOR_BUFFER_BIT | RT_DEPTH_BUFFER_BIT);
        quad(-0.9f, -0.1f);
        rtFlush();
        CHECK_INT(rtGetError(), RT_NO_ERROR);
        rtuSwapBuffers();
        break;
    case 1: /* drawn after the flush: the swap traces again and shows it */
        rtClear(RT_COLOR_BUFFER_BIT | RT_DEPTH_BUFFER_BIT);
        quad(-0.9f, -0.1f);
        rtFlush();
        quad(0.1f, 0.9f);
        rtuSwapBuffers();
        CHECK(red_at(48, 24));
        break;
    default: /* glFlush with nothing drawn since the swap: no trace */
        rtClear(RT_COLOR_BUFFER_BIT | RT_DEPTH_BUFFER_BIT);
        quad(-0.9f, -0.1f);
        rtuSwapBuffers();
        CHECK_INT(rtGetError(), RT_NO_ERROR);
        rtFlush();
        rtuSwapBuffers();
        break;
    }
    if (!red_at(16, 24))
        fprintf(stderr, "display %d: not red\n", displays);
    CHECK(red_at(16, 24));
    traced_in_display[displays] = frames_traced() - before;
    displays++;
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
    CHECK_INT(rtuCreateWindow("flush and swap"), 1);
    RTint current = -1;
    rtGetIntegerv(RT_FRAME_CURRENT, &current);
    CHECK_INT(current, RT_FALSE); /* no GL frame yet */
    CHECK_INT(frames_traced(), 0);
    rtuDisplayFunc(display);
    rtuIdleFunc(idle);
    rtuMainLoop();
    CHECK_INT(displays, 3);
    CHECK_INT(traced_in_display[0], 1);
    CHECK_INT(traced_in_display[1], 2);
    CHECK_INT(traced_in_display[2], 1);
    return test_summary("glut/flush_swap");
}
