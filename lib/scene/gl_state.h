/* SPDX-License-Identifier: Apache-2.0 */
/*
 * gl_state.h - the fragment-side GL state a primitive was drawn under that
 * is not a property of its triangles' material: fog (OpenGL 1.1 sec. 3.9)
 * and the light model (sec. 2.13.1).  GL applies the values current when a
 * primitive is drawn, so, like the clip planes (clip.h), they travel with
 * the instance of the geometry (scene_appearance, frame.h): a program that
 * draws one object unfogged and, after rtEnable(RT_FOG), another fogged
 * gets both as GL draws them.  Immediate-mode segments and display-list
 * segments are cut where the state changes.  All fields 4 bytes wide and
 * every struct zeroed before it is filled, so equal states compare equal
 * with memcmp.
 */
#ifndef RT_SCENE_GL_STATE_H
#define RT_SCENE_GL_STATE_H

#include <stdint.h>

/* rtFog (docs/fog.md). */
struct scene_fog {
    int enabled;   /* rtEnable(RT_FOG) */
    uint32_t mode; /* RT_LINEAR, RT_EXP, RT_EXP2 */
    float density, start, end;
    float color[4];
};

/* rtLightModel. */
struct scene_light_model {
    int two_side;
    int local_viewer;
    float ambient[4]; /* RT_LIGHT_MODEL_AMBIENT */
};

struct scene_gl_state {
    struct scene_fog fog;
    struct scene_light_model light_model;
};

#endif
