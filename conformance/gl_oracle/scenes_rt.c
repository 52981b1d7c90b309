/* SPDX-License-Identifier: Apache-2.0 */
/* scenes_rt.c - the oracle scenes compiled against Tracelist. */
#include "layer_rt.h"
#include "scenes.inc"
