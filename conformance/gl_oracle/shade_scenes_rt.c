/* SPDX-License-Identifier: Apache-2.0 */
/* shade_scenes_rt.c - the colour oracle's scenes compiled against Tracelist. */
#include "layer_rt.h"
#define O_ENUM RTenum
#include "shade_scenes.inc"
