/* SPDX-License-Identifier: Apache-2.0 */
/* overlay_rt.c - the overlay oracle's scenes compiled against Tracelist. */
#include "layer_rt.h"
#define OVERLAY(name) overlay_##name##_rt
#include "overlay_scene.inc"
