/* SPDX-License-Identifier: Apache-2.0 */
/* scenes_gl.c - the oracle scenes compiled against OpenGL. */
#include "layer_gl.h"
#include "scenes.inc"
