/* SPDX-License-Identifier: Apache-2.0 */
/*
 * demo_window.c - see demo_window.h.
 */
#include "demo_window.h"

#include <rt/rt.h>

void demo_present(GLFWwindow *window, int width, int height, unsigned char *pixels)
{
    rtReadPixels(0, 0, width, height, RT_RGBA, RT_UNSIGNED_BYTE, pixels);
    glViewport(0, 0, width, height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRasterPos2f(-1.0f, -1.0f);
    glDrawPixels(width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    glfwSwapBuffers(window);
    glfwPollEvents();
}
