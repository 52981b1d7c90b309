/* SPDX-License-Identifier: Apache-2.0 */
/* shade_scenes_gl.c - the colour oracle's scenes compiled against OpenGL. */
#include "layer_gl.h"
#define O_ENUM GLenum
#include "shade_scenes.inc"
