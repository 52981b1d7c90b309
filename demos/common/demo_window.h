/* SPDX-License-Identifier: Apache-2.0 */
/*
 * demo_window.h - showing a Tracelist frame in a GLFW window (built only
 * when the demos have GLFW, RT_HAVE_GLFW).
 */
#ifndef RT_DEMO_WINDOW_H
#define RT_DEMO_WINDOW_H

#include <GLFW/glfw3.h>

/* Reads the width x height frame into pixels (RGBA8) and shows it with
 * glDrawPixels: rtReadPixels returns rows bottom to top, the order
 * glDrawPixels wants.  Then swaps buffers and polls events. */
void demo_present(GLFWwindow *window, int width, int height, unsigned char *pixels);

#endif
