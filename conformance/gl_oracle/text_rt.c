/* SPDX-License-Identifier: Apache-2.0 */
/* text_rt.c - the oracle's text scene compiled against Tracelist. */
#include "layer_rt.h"
#define TEXT(name) text_##name##_rt
#include "text_scene.inc"
