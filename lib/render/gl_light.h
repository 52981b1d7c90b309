/* SPDX-License-Identifier: Apache-2.0 */
/*
 * gl_light.h - OpenGL 1.x's lighting equation (OpenGL 2.1 spec sec.
 * 2.14.1, unchanged since 1.0) evaluated at one point: the RT_FIXED_FUNCTION
 * shading mode (gl_shade.c) evaluates it at a triangle's vertices, as GL
 * does, and interpolates the colours.  Pure functions of their arguments,
 * so the unit test checks them against hand-computed values.
 */
#ifndef RT_RENDER_GL_LIGHT_H
#define RT_RENDER_GL_LIGHT_H

#include "render/render.h"
#include "scene/mesh.h"

/* The material of one face after RT_COLOR_MATERIAL (GL's m_cm terms). */
struct gl_face_material {
    float ambient[4];
    float diffuse[4];
    float specular[4];
    float emission[4];
    float shininess;
};

/* The material of the front (back = 0) or back face of mat, with the
 * colour `color` replacing the rtColorMaterial parameter when
 * color_material is set and the face is one rtColorMaterial names. */
void gl_face_material(const struct scene_material *mat, int back, int color_material,
                      const float color[4], struct gl_face_material *out);

/*
 * GL's lit colour at eye-space point p with eye-space normal n, used as
 * given (RT_NORMALIZE is the caller's: GL lights with the transformed,
 * possibly unnormalised normal):
 *
 *   c = e_cm + a_cm a_cs + sum over enabled lights i of
 *       att_i spot_i (a_cm a_cli + (n . VP_i) d_cm d_cli
 *                     + f_i (n . h_i)^s_rm s_cm s_cli)
 *
 * with VP_i the unit vector from p to the light, att_i = 1 / (k0 + k1 d +
 * k2 d^2) for a positional light (1 for a directional one), spot_i =
 * max(-VP_i . s_dli, 0)^s_rli inside the cutoff cone (0 outside, 1 for a
 * cutoff of 180 or a directional light), f_i = 1 when n . VP_i > 0, h_i the
 * unit half vector of VP_i and (0, 0, 1), or of VP_i and the unit vector to
 * the eye at the origin under RT_LIGHT_MODEL_LOCAL_VIEWER.  Dot products
 * are clamped at 0; each channel of the result clamped to [0, 1]; alpha is
 * the diffuse material's (GL).  The global ambient a_cs and the local
 * viewer are the light model `lm`'s and the lights `lights`: those current
 * when the primitive was drawn (scene/gl_state.h), not the frame's.
 */
void gl_light_point_model(const struct scene_light lights[SCENE_MAX_LIGHTS],
                          const struct scene_light_model *lm,
                          const struct gl_face_material *m, const float p[3], const float n[3],
                          float rgba[4]);

/* GL's spot factor of a positional light with a cutoff other than 180
 * for a point whose unit direction to the light is vp: 0 outside the
 * cone, max(-vp . s, 0)^exponent inside (s the unit spot direction). */
float gl_spot_factor(const struct scene_light *l, const float vp[3]);

/* GL's fog factor for fog coordinate z (docs/fog.md), clamped to [0, 1]:
 * 1 leaves the colour, 0 gives the fog colour. */
float gl_fog_factor(const struct scene_fog *fog, float z);

#endif
