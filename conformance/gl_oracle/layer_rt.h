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
#define ORACLE_SCENE_COUNT oracle_scene_count_rt

#endif /* ORACLE_LAYER_H */
