/* SPDX-License-Identifier: Apache-2.0 */
/*
 * gl_light.c - OpenGL's lighting equation and fog factor (see gl_light.h).
 */
#include "render/gl_light.h"

#include <math.h>
#include <string.h>

#include "base/mat4.h"

/* Degrees to radians for the spot cutoff. */
#define GL_LIGHT_PI 3.14159265358979323846

void gl_face_material(const struct scene_material *mat, int back, int color_material,
                      const float color[4], struct gl_face_material *out)
{
    if (back) {
        memcpy(out->ambient, mat->back_ambient, sizeof(out->ambient));
        memcpy(out->diffuse, mat->back_diffuse, sizeof(out->diffuse));
        memcpy(out->specular, mat->back_specular, sizeof(out->specular));
        memcpy(out->emission, mat->back_emission, sizeof(out->emission));
        out->shininess = mat->back_shininess;
    } else {
        memcpy(out->ambient, mat->ambient, sizeof(out->ambient));
        memcpy(out->diffuse, mat->diffuse, sizeof(out->diffuse));
        memcpy(out->specular, mat->specular, sizeof(out->specular));
        memcpy(out->emission, mat->emission, sizeof(out->emission));
        out->shininess = mat->shininess;
    }
    if (!color_material)
        return;
    RTenum face = mat->color_material_face;
    if (face != RT_FRONT_AND_BACK && face != (back ? RT_BACK : RT_FRONT))
        return;
    /* GL 2.1 sec. 2.14.3: the current colour tracks the named parameter. */
    switch (mat->color_material_mode) {
    case RT_AMBIENT:
        memcpy(out->ambient, color, sizeof(out->ambient));
        break;
    case RT_DIFFUSE:
        memcpy(out->diffuse, color, sizeof(out->diffuse));
        break;
    case RT_SPECULAR:
        memcpy(out->specular, color, sizeof(out->specular));
        break;
    case RT_EMISSION:
        memcpy(out->emission, color, sizeof(out->emission));
        break;
    default: /* RT_AMBIENT_AND_DIFFUSE */
        memcpy(out->ambient, color, sizeof(out->ambient));
        memcpy(out->diffuse, color, sizeof(out->diffuse));
        break;
    }
}

static float clamp01(float x)
{
    return x < 0.0f ? 0.0f : (x > 1.0f ? 1.0f : x);
}

float gl_spot_factor(const struct scene_light *l, const float vp[3])
{
    float s[3] = {l->spot_direction[0], l->spot_direction[1], l->spot_direction[2]};
    vec3_normalize(s);
    float cosine = -vec3_dot(vp, s);
    float cutoff = (float)cos((double)l->spot_cutoff * GL_LIGHT_PI / 180.0);
    if (cosine < cutoff)
        return 0.0f;
    return cosine > 0.0f ? powf(cosine, l->spot_exponent) : 0.0f;
}

void gl_light_point_model(const struct scene_light lights[SCENE_MAX_LIGHTS],
                          const struct scene_light_model *lm,
                          const struct gl_face_material *m, const float p[3], const float n[3],
                          float rgba[4])
{
    float c[3];
    for (int k = 0; k < 3; k++)
        c[k] = m->emission[k] + m->ambient[k] * lm->ambient[k];
    for (int i = 0; i < RENDER_MAX_LIGHTS; i++) {
        const struct scene_light *l = &lights[i];
        if (!l->enabled)
            continue;
        float vp[3], factor = 1.0f;
        if (l->position[3] != 0.0f) {
            for (int k = 0; k < 3; k++)
                vp[k] = l->position[k] / l->position[3] - p[k];
            float d = sqrtf(vec3_dot(vp, vp));
            if (d > 0.0f)
                for (int k = 0; k < 3; k++)
                    vp[k] /= d;
            float att = l->attenuation[0] + l->attenuation[1] * d + l->attenuation[2] * d * d;
            factor = att > 0.0f ? 1.0f / att : 1.0f;
            if (l->spot_cutoff != 180.0f) {
                float spot = gl_spot_factor(l, vp);
                if (spot == 0.0f)
                    continue; /* outside the cone: the light adds nothing */
                factor *= spot;
            }
        } else {
            memcpy(vp, l->position, sizeof(vp));
            vec3_normalize(vp);
        }
        float term[3];
        for (int k = 0; k < 3; k++)
            term[k] = m->ambient[k] * l->ambient[k];
        float n_dot_l = vec3_dot(n, vp);
        if (n_dot_l > 0.0f) {
            float h[3];
            if (lm->local_viewer) {
                float e[3] = {-p[0], -p[1], -p[2]};
                vec3_normalize(e);
                for (int k = 0; k < 3; k++)
                    h[k] = vp[k] + e[k];
            } else {
                h[0] = vp[0];
                h[1] = vp[1];
                h[2] = vp[2] + 1.0f;
            }
            vec3_normalize(h);
            float n_dot_h = vec3_dot(n, h);
            float spec = n_dot_h > 0.0f ? powf(n_dot_h, m->shininess)
                                        : (m->shininess == 0.0f ? 1.0f : 0.0f);
            for (int k = 0; k < 3; k++)
                term[k] += n_dot_l * m->diffuse[k] * l->diffuse[k] +
                           spec * m->specular[k] * l->specular[k];
        }
        for (int k = 0; k < 3; k++)
            c[k] += factor * term[k];
    }
    for (int k = 0; k < 3; k++)
        rgba[k] = clamp01(c[k]);
    rgba[3] = clamp01(m->diffuse[3]);
}

float gl_fog_factor(const struct scene_fog *fog, float z)
{
    double f;
    switch (fog->mode) {
    case RT_LINEAR:
        f = fog->end != fog->start ? ((double)fog->end - z) / ((double)fog->end - fog->start)
                                   : 1.0;
        break;
    case RT_EXP2: {
        double dz = (double)fog->density * z;
        f = exp(-dz * dz);
        break;
    }
    default: /* RT_EXP */
        f = exp(-(double)fog->density * z);
        break;
    }
    return clamp01((float)f);
}
