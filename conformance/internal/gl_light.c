/* SPDX-License-Identifier: Apache-2.0 */
/*
 * gl_light.c - OpenGL's lighting equation and fog factor of
 * lib/render/gl_light.c against values computed by hand from the OpenGL
 * 2.1 spec (sec. 2.14.1 and 3.10): directional and positional lights,
 * attenuation, the spot cone and exponent, the local viewer's half vector,
 * back materials and every rtColorMaterial mode, an unnormalised normal
 * used as given, and the three fog modes.
 *
 * Internal test (links the static library).  Non-zero exit on failure.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "render/gl_light.h"

#define TOL 1e-5

/* GL's defaults: global ambient 0.2, light 0 white with black ambient at
 * (0, 0, 1, 0), the other lights off. */
static void default_state(struct render_state *st)
{
    memset(st, 0, sizeof(*st));
    for (int k = 0; k < 3; k++)
        st->global_ambient[k] = 0.2f;
    st->global_ambient[3] = 1.0f;
    struct scene_light *l = &st->lights[0];
    l->enabled = 1;
    for (int k = 0; k < 3; k++)
        l->diffuse[k] = l->specular[k] = 1.0f;
    l->ambient[3] = l->diffuse[3] = l->specular[3] = 1.0f;
    l->position[2] = 1.0f;
    l->attenuation[0] = 1.0f;
    l->spot_direction[2] = -1.0f;
    l->spot_cutoff = 180.0f;
}

/* gl_light_point_model under the light model st holds, as a primitive
 * drawn with it would be lit. */
static void gl_light_point(const struct render_state *st, const struct gl_face_material *m,
                           const float p[3], const float n[3], float rgba[4])
{
    struct scene_light_model lm;
    memset(&lm, 0, sizeof(lm));
    lm.two_side = st->light_model_two_side;
    lm.local_viewer = st->light_model_local_viewer;
    memcpy(lm.ambient, st->global_ambient, sizeof(lm.ambient));
    gl_light_point_model(st->lights, &lm, m, p, n, rgba);
}

static void front(const struct scene_material *mat, struct gl_face_material *fm)
{
    static const float white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    gl_face_material(mat, 0, 0, white, fm);
}

int main(void)
{
    struct render_state st;
    struct scene_material mat;
    struct gl_face_material fm;
    float c[4];
    const float origin[3] = {0.0f, 0.0f, 0.0f};
    const float up[3] = {0.0f, 0.0f, 1.0f};

    tu_section("directional light, default material");
    default_state(&st);
    scene_material_default(&mat);
    front(&mat, &fm);
    gl_light_point(&st, &fm, origin, up, c);
    /* 0.2 * 0.2 (global ambient) + 0.8 * 1 (n . l = 1). */
    CHECK_NEAR(c[0], 0.84, TOL);
    CHECK_NEAR(c[3], 1.0, TOL);
    const float tilted[3] = {0.8660254f /* sin 60 degrees */, 0.0f, 0.5f};
    gl_light_point(&st, &fm, origin, tilted, c);
    CHECK_NEAR(c[1], 0.04 + 0.8 * 0.5, TOL);
    const float away[3] = {0.0f, 0.0f, -1.0f};
    gl_light_point(&st, &fm, origin, away, c);
    CHECK_NEAR(c[2], 0.04, TOL); /* facing away: ambient only */

    tu_section("attenuation");
    st.lights[0].position[2] = 5.0f;
    st.lights[0].position[3] = 1.0f;
    st.lights[0].attenuation[0] = 1.0f;
    st.lights[0].attenuation[1] = 0.5f;
    st.lights[0].attenuation[2] = 0.25f;
    gl_light_point(&st, &fm, origin, up, c);
    /* d = 5: 1 / (1 + 2.5 + 6.25). */
    CHECK_NEAR(c[0], 0.04 + 0.8 / 9.75, TOL);

    tu_section("spot cutoff and exponent");
    default_state(&st);
    st.lights[0].position[2] = 5.0f;
    st.lights[0].position[3] = 1.0f;
    st.lights[0].spot_cutoff = 30.0f;
    st.lights[0].spot_exponent = 2.0f;
    const float inside[3] = {1.0f, 0.0f, 0.0f};
    gl_light_point(&st, &fm, inside, up, c);
    /* cos = 5 / sqrt(26) = n . VP; spot = cos^2; 0.04 + 0.8 cos^3. */
    CHECK_NEAR(c[0], 0.7942928, 1e-5);
    const float outside[3] = {5.0f, 0.0f, 0.0f};
    gl_light_point(&st, &fm, outside, up, c);
    CHECK_NEAR(c[0], 0.04, TOL); /* 45 degrees off the axis: outside 30 */
    st.lights[0].spot_cutoff = 180.0f;
    gl_light_point(&st, &fm, outside, up, c);
    CHECK_NEAR(c[0], 0.04 + 0.8 * sqrt(0.5), TOL); /* no spot */

    tu_section("specular: infinite and local viewer");
    default_state(&st);
    scene_material_default(&mat);
    memset(mat.ambient, 0, 3 * sizeof(float));
    memset(mat.diffuse, 0, 3 * sizeof(float));
    mat.specular[0] = mat.specular[1] = mat.specular[2] = 1.0f;
    mat.shininess = 10.0f;
    front(&mat, &fm);
    const float p[3] = {1.0f, 0.0f, -1.0f};
    gl_light_point(&st, &fm, p, up, c);
    CHECK_NEAR(c[0], 1.0, TOL); /* h = (0, 0, 1) */
    st.light_model_local_viewer = 1;
    gl_light_point(&st, &fm, p, up, c);
    /* h = normalise((0,0,1) + (-1,0,1)/sqrt 2): n . h = 0.9238795, ^10. */
    CHECK_NEAR(c[0], 0.4530576, 1e-5);

    tu_section("back material and rtColorMaterial faces and modes");
    scene_material_default(&mat);
    const float back_diffuse[4] = {0.0f, 0.5f, 0.0f, 0.25f};
    memcpy(mat.back_diffuse, back_diffuse, sizeof(back_diffuse));
    const float red[4] = {1.0f, 0.0f, 0.0f, 1.0f};
    gl_face_material(&mat, 1, 0, red, &fm);
    CHECK_NEAR(fm.diffuse[1], 0.5, TOL);
    CHECK_NEAR(fm.ambient[0], 0.2, TOL);
    default_state(&st);
    gl_light_point(&st, &fm, origin, up, c);
    CHECK_NEAR(c[0], 0.04, TOL);
    CHECK_NEAR(c[1], 0.54, TOL);
    CHECK_NEAR(c[3], 0.25, TOL); /* alpha: the diffuse material's */
    gl_face_material(&mat, 0, 0, red, &fm);
    CHECK_NEAR(fm.diffuse[1], 0.8, TOL);
    /* Color material: the default (front and back, ambient and diffuse). */
    gl_face_material(&mat, 1, 1, red, &fm);
    CHECK(fm.diffuse[0] == 1.0f && fm.ambient[0] == 1.0f && fm.diffuse[1] == 0.0f);
    mat.color_material_face = RT_FRONT;
    gl_face_material(&mat, 1, 1, red, &fm);
    CHECK_NEAR(fm.diffuse[1], 0.5, TOL); /* back untouched */
    gl_face_material(&mat, 0, 1, red, &fm);
    CHECK(fm.diffuse[0] == 1.0f);
    mat.color_material_face = RT_BACK;
    gl_face_material(&mat, 0, 1, red, &fm);
    CHECK_NEAR(fm.diffuse[0], 0.8, TOL); /* front untouched */
    mat.color_material_face = RT_FRONT_AND_BACK;
    const RTenum modes[4] = {RT_AMBIENT, RT_DIFFUSE, RT_SPECULAR, RT_EMISSION};
    for (int i = 0; i < 4; i++) {
        mat.color_material_mode = modes[i];
        gl_face_material(&mat, 0, 1, red, &fm);
        CHECKF(fm.ambient[0] == (i == 0 ? 1.0f : 0.2f) &&
                   fm.diffuse[0] == (i == 1 ? 1.0f : 0.8f) &&
                   fm.specular[0] == (i == 2 ? 1.0f : 0.0f) &&
                   fm.emission[0] == (i == 3 ? 1.0f : 0.0f),
               "mode %d", i);
    }
    mat.color_material_mode = RT_EMISSION;
    gl_face_material(&mat, 0, 1, red, &fm);
    gl_light_point(&st, &fm, origin, away, c);
    CHECK_NEAR(c[0], 1.0, TOL); /* the colour as emission */

    tu_section("the normal is used as given (RT_NORMALIZE is the caller's)");
    scene_material_default(&mat);
    mat.diffuse[0] = 0.2f;
    front(&mat, &fm);
    const float long_normal[3] = {0.0f, 0.0f, 2.0f};
    gl_light_point(&st, &fm, origin, long_normal, c);
    CHECK_NEAR(c[0], 0.04 + 0.2 * 2.0, TOL);
    gl_light_point(&st, &fm, origin, up, c);
    CHECK_NEAR(c[0], 0.04 + 0.2, TOL);

    tu_section("fog factor");
    struct scene_fog fog = {1, RT_LINEAR, 0.5f, 1.0f, 5.0f, {0, 0, 0, 0}};
    CHECK_NEAR(gl_fog_factor(&fog, 2.0f), 0.75, TOL);
    CHECK_NEAR(gl_fog_factor(&fog, 9.0f), 0.0, TOL);
    CHECK_NEAR(gl_fog_factor(&fog, 0.0f), 1.0, TOL);
    fog.mode = RT_EXP;
    CHECK_NEAR(gl_fog_factor(&fog, 3.0f), 0.2231302, 1e-6);
    fog.mode = RT_EXP2;
    CHECK_NEAR(gl_fog_factor(&fog, 3.0f), 0.1053992, 1e-6);

    return test_summary("internal/gl_light");
}
