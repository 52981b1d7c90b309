/* SPDX-License-Identifier: Apache-2.0 */
/* overlay_gl.c - the overlay oracle's scenes compiled against OpenGL. */
#include "layer_gl.h"
#define OVERLAY(name) overlay_##name##_gl
#include "overlay_scene.inc"
