/* SPDX-License-Identifier: Apache-2.0 */
/*
 * layer_rt.h - the oracle's macro layer bound to Tracelist and rtu: the
 * same names as layer_gl.h, each mapped to its Tracelist equivalent.
 */
#ifndef ORACLE_LAYER_H
#define ORACLE_LAYER_H

#include <rt/rt.h>
#include <rt/rtu.h>

#define O_GL(name) rt##name
#define O_GLC(name) RT_##name
#define O_GLU(name) rtu##name
#define O_GLUC(name) RTU_##name
#define O_GLUT(name) rtu##name
#define O_QUADRIC RTUquadric
#define O_INT RTint
#define ORACLE_SCENES oracle_scenes_rt

/* An unlit surface colour: GL's glColor4f with lighting off is what the
 * eye light shows of an emissive material with no ambient and diffuse
 * (and blending takes the alpha from the diffuse material). */
#define O_UNLIT_COLOR(r, g, b, a) oracle_unlit_color(r, g, b, a)
static inline void oracle_unlit_color(float r, float g, float b, float a)
{
    const RTfloat emission[4] = {r, g, b, 1.0f}, black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    const RTfloat diffuse[4] = {0.0f, 0.0f, 0.0f, a};
    rtColor4f(r, g, b, a);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, emission);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, black);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, diffuse);
}
#define ORACLE_SCENE_COUNT oracle_scene_count_rt

#endif /* ORACLE_LAYER_H */
