/* SPDX-License-Identifier: Apache-2.0 */
/*
 * gl_state.h - the fragment-side GL state a primitive was drawn under that
 * is not a property of its triangles' material: fog (OpenGL 1.1 sec. 3.9)
 * and the light model (sec. 2.13.1).  GL applies the values current when a
 * primitive is drawn, so, like the clip planes (clip.h), they travel with
 * the instance of the geometry (scene_appearance, frame.h): a program that
 * draws one object unfogged and, after rtEnable(RT_FOG), another fogged
 * gets both as GL draws them.  Immediate-mode segments and display-list
 * segments are cut where the state changes.  The lights (enables,
 * positions, colours, attenuation, spot) are such state too (sec. 2.14.1:
 * a vertex is lit by the lights as they are when it is specified).  All fields 4 bytes wide and
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

/* GL's eight lights (OpenGL 2.1 spec sec. 2.14.1). */
#define SCENE_MAX_LIGHTS 8

/* One light as rtLight left it: positions and spot directions already in
 * eye space (transformed by the modelview at the rtLight call, as GL). */
struct scene_light {
    int enabled;
    float ambient[4];
    float diffuse[4];
    float specular[4];
    float position[4]; /* world (eye) space; w = 0: direction towards the light */
    float attenuation[3]; /* constant, linear, quadratic */
    /* Spot light (GL): the direction in eye space (transformed by the
     * modelview's upper 3x3 at the call), exponent, cutoff in degrees
     * (180: no spot). */
    float spot_direction[3];
    float spot_exponent;
    float spot_cutoff;
};

/* The lights a primitive is lit by: the eight as current at its draw,
 * the parameters of disabled ones zeroed (they light nothing, so moving a
 * disabled light leaves the set equal). */
struct scene_light_set {
    struct scene_light light[SCENE_MAX_LIGHTS];
};

struct scene_gl_state {
    struct scene_fog fog;
    struct scene_light_model light_model;
    /* The lights enabled at the draw with their parameters then: an index
     * into the frame's table of distinct light sets (frame.h,
     * scene_frame_light_set), so that an instance stays small and a frame
     * that never changes its lights between primitives has one entry. */
    uint32_t light_set;
};

#endif
