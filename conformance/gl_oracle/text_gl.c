/* SPDX-License-Identifier: Apache-2.0 */
/* text_gl.c - the oracle's text scene compiled against OpenGL (glWindowPos
 * is GL 1.4: its prototype needs GL_GLEXT_PROTOTYPES). */
#define GL_GLEXT_PROTOTYPES 1
#include "layer_gl.h"
#include <GL/glext.h>
#define TEXT(name) text_##name##_gl
#include "text_scene.inc"
