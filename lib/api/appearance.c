/* SPDX-License-Identifier: Apache-2.0 */
/*
 * appearance.c - materials, lights, the light model, shading modes and
 * render parameters.
 *
 * Materials have a front and a back (GL): RT_FRONT sets the front,
 * RT_BACK the back and RT_FRONT_AND_BACK both.  The RT_FIXED_FUNCTION mode
 * lights back faces with the back material under RT_LIGHT_MODEL_TWO_SIDE;
 * the eye-light and Whitted modes use the front material on both sides.
 * The ray tracing parameters (reflectivity, transparency, index of
 * refraction) have no back: any face sets them.  Light positions and spot
 * directions are transformed by the modelview at the call, as GL.
 */
#include <math.h>
#include <string.h>

#include "api/context.h"
#include "api/enum_names.h"
#include "base/mat4.h"

/* Number of values a material pname takes; 0 for an unknown pname. */
static int material_size(RTenum pname)
{
    switch (pname) {
    case RT_AMBIENT:
    case RT_DIFFUSE:
    case RT_SPECULAR:
    case RT_EMISSION:
    case RT_AMBIENT_AND_DIFFUSE:
        return 4;
    case RT_SHININESS:
    case RT_REFLECTIVITY:
    case RT_TRANSPARENCY:
    case RT_INDEX_OF_REFRACTION:
        return 1;
    default:
        return 0;
    }
}

/* Where pname is kept in m for one side (back non-zero: the back).  The
 * ray tracing parameters have no back: both sides give the one field.
 * pname is one material_size() knows other than RT_AMBIENT_AND_DIFFUSE. */
static float *material_field(struct scene_material *m, RTenum pname, int back)
{
    switch (pname) {
    case RT_AMBIENT:
        return back ? m->back_ambient : m->ambient;
    case RT_DIFFUSE:
        return back ? m->back_diffuse : m->diffuse;
    case RT_SPECULAR:
        return back ? m->back_specular : m->specular;
    case RT_EMISSION:
        return back ? m->back_emission : m->emission;
    case RT_SHININESS:
        return back ? &m->back_shininess : &m->shininess;
    case RT_REFLECTIVITY:
        return &m->reflectivity;
    case RT_TRANSPARENCY:
        return &m->transparency;
    default:
        return &m->ior;
    }
}

/* Writes the n values of pname to the sides of m that face names. */
static void set_material(struct scene_material *m, RTenum face, RTenum pname,
                         const RTfloat *params, int n)
{
    if (face != RT_BACK)
        memcpy(material_field(m, pname, 0), params, (size_t)n * sizeof(float));
    if (face != RT_FRONT)
        memcpy(material_field(m, pname, 1), params, (size_t)n * sizeof(float));
}

/* Number of values a light pname takes; 0 for an unknown pname. */
static int light_size(RTenum pname)
{
    switch (pname) {
    case RT_AMBIENT:
    case RT_DIFFUSE:
    case RT_SPECULAR:
    case RT_POSITION:
        return 4;
    case RT_CONSTANT_ATTENUATION:
    case RT_LINEAR_ATTENUATION:
    case RT_QUADRATIC_ATTENUATION:
    case RT_SPOT_EXPONENT:
    case RT_SPOT_CUTOFF:
        return 1;
    case RT_SPOT_DIRECTION:
        return 3;
    default:
        return 0;
    }
}

/* Where pname is kept in l; pname is one light_size() knows.  Positions
 * and directions are kept in eye coordinates, as GL reports them. */
static float *light_field(struct scene_light *l, RTenum pname)
{
    switch (pname) {
    case RT_AMBIENT:
        return l->ambient;
    case RT_DIFFUSE:
        return l->diffuse;
    case RT_SPECULAR:
        return l->specular;
    case RT_POSITION:
        return l->position;
    case RT_SPOT_DIRECTION:
        return l->spot_direction;
    case RT_SPOT_EXPONENT:
        return &l->spot_exponent;
    case RT_SPOT_CUTOFF:
        return &l->spot_cutoff;
    case RT_CONSTANT_ATTENUATION:
        return &l->attenuation[0];
    case RT_LINEAR_ATTENUATION:
        return &l->attenuation[1];
    default:
        return &l->attenuation[2];
    }
}

/*
 * The checks the material and light calls share, each recording its error
 * under caller's name and returning 0 when the argument is bad, 1 when it
 * is good.  A call runs them in GL's order (mode, enums, values).
 */

/* face (named arg in the message) is RT_FRONT, RT_BACK or RT_FRONT_AND_BACK. */
static int check_face(struct rt_context *ctx, const char *caller, const char *arg, RTenum face)
{
    if (face == RT_FRONT || face == RT_BACK || face == RT_FRONT_AND_BACK)
        return 1;
    char b1[RT_ENUM_STRING_SIZE];
    rt_error(ctx, RT_INVALID_ENUM, "%s(%s=%s): not a face", caller, arg, rt_enum_string(face, b1));
    return 0;
}

/* which is RT_LIGHT0 .. RT_LIGHT0 + RENDER_MAX_LIGHTS - 1. */
static int check_light(struct rt_context *ctx, const char *caller, RTenum which)
{
    if (which >= RT_LIGHT0 && which < RT_LIGHT0 + RENDER_MAX_LIGHTS)
        return 1;
    char b1[RT_ENUM_STRING_SIZE];
    rt_error(ctx, RT_INVALID_ENUM, "%s(light=%s): not RT_LIGHT0 .. RT_LIGHT7", caller,
             rt_enum_string(which, b1));
    return 0;
}

/* pname is a kind ("material", "light") parameter this call takes (known
 * non-zero), then params is not NULL. */
static int check_pname(struct rt_context *ctx, const char *caller, RTenum pname, int known,
                       const char *kind, const void *params)
{
    char b1[RT_ENUM_STRING_SIZE];
    if (!known) {
        rt_error(ctx, RT_INVALID_ENUM, "%s(pname=%s): not a %s parameter", caller,
                 rt_enum_string(pname, b1), kind);
        return 0;
    }
    if (!params) {
        rt_error(ctx, RT_INVALID_VALUE, "%s(params=NULL)", caller);
        return 0;
    }
    return 1;
}

/* GL's ranges of the scalar material and light parameters: shininess and
 * the spot exponent in [0, 128], reflectivity and transparency in [0, 1],
 * the index of refraction > 0, the spot cutoff in [0, 90] or 180, the
 * attenuations >= 0.  Vector parameters take any finite value. */
static int out_of_range(RTenum pname, float v)
{
    switch (pname) {
    case RT_SHININESS:
    case RT_SPOT_EXPONENT:
        return v < 0.0f || v > 128.0f;
    case RT_REFLECTIVITY:
    case RT_TRANSPARENCY:
        return v < 0.0f || v > 1.0f;
    case RT_INDEX_OF_REFRACTION:
        return !(v > 0.0f);
    case RT_SPOT_CUTOFF:
        return (v < 0.0f || v > 90.0f) && v != 180.0f;
    case RT_CONSTANT_ATTENUATION:
    case RT_LINEAR_ATTENUATION:
    case RT_QUADRATIC_ATTENUATION:
        return v < 0.0f;
    default:
        return 0;
    }
}

/* params[0 .. n) are finite and, for a scalar pname, in GL's range. */
static int check_values(struct rt_context *ctx, const char *caller, RTenum pname,
                        const RTfloat *params, int n)
{
    if (!rt_check_finite(ctx, caller, params, n))
        return 0;
    if (n == 1 && out_of_range(pname, params[0])) {
        char b1[RT_ENUM_STRING_SIZE];
        rt_error(ctx, RT_INVALID_VALUE, "%s(pname=%s, value=%g): out of range", caller,
                 rt_enum_string(pname, b1), (double)params[0]);
        return 0;
    }
    return 1;
}

/* The colours of m that rtColorMaterial(face, mode) names: up to four
 * (RT_AMBIENT_AND_DIFFUSE of both faces).  Returns how many. */
static int tracked_colours(struct scene_material *m, RTenum face, RTenum mode, float *out[4])
{
    int n = 0;
    for (int back = 0; back < 2; back++) {
        if (face != RT_FRONT_AND_BACK && face != (back ? RT_BACK : RT_FRONT))
            continue;
        if (mode == RT_AMBIENT || mode == RT_AMBIENT_AND_DIFFUSE)
            out[n++] = back ? m->back_ambient : m->ambient;
        if (mode == RT_DIFFUSE || mode == RT_AMBIENT_AND_DIFFUSE)
            out[n++] = back ? m->back_diffuse : m->diffuse;
        if (mode == RT_SPECULAR)
            out[n++] = back ? m->back_specular : m->specular;
        if (mode == RT_EMISSION)
            out[n++] = back ? m->back_emission : m->emission;
    }
    return n;
}

/*
 * GL 2.1 sec. 2.14.3: while RT_COLOR_MATERIAL is enabled the material
 * properties rtColorMaterial names take the current colour whenever it
 * changes, and when the enable or the tracked properties change; a
 * property no longer tracked keeps the last colour.  Tracelist writes the
 * colour lazily: while the enable is on, the tracked properties are the
 * current colour by definition (the renderer takes the vertex colour for
 * them, gl_light.c, and rtGetMaterialfv reports it), and this writes it
 * into the material where the tracking ends (rtDisable, rtColorMaterial,
 * rtPushAttrib), so that rtColor costs nothing more while tracking.
 * After rtPopAttrib restored a material, the tracked properties hold the
 * restored values until the colour next changes (color_material_current).
 */
void rt_color_material_write(const struct rt_context *ctx, struct scene_material *m)
{
    if (!ctx->color_material || !ctx->color_material_current)
        return;
    float *dst[4];
    int n = tracked_colours(m, m->color_material_face, m->color_material_mode, dst);
    for (int i = 0; i < n; i++)
        memcpy(dst[i], ctx->current_color, 4 * sizeof(float));
}

void rt_color_material_settle(struct rt_context *ctx, const char *caller)
{
    if (!ctx->color_material)
        return;
    struct scene_material m = ctx->material;
    rt_color_material_write(ctx, &m);
    /* What rtColorMaterial tracks next takes the current colour. */
    ctx->color_material_current = 1;
    if (memcmp(&m, &ctx->material, sizeof(m)) != 0) {
        ctx->material = m;
        ctx->recording.material_index = -1;
    }
    if (!rt_list_compiling(ctx))
        return;
    struct scene_recording *rec = &ctx->recording;
    rec->material_index = -1;
    if (rec->color_set && rec->color_material_set &&
        (rec->material_set & SCENE_MATERIAL_COLOR_MATERIAL_MODE)) {
        /* The list set the colour, the enable and rtColorMaterial itself:
         * what GL writes is known now, and the list's later triangles
         * record it as the list's own material.  A list that names no
         * rtColorMaterial writes the properties the caller's names at
         * the call (GL 2.1 sec. 2.14.3 takes the mode current when the
         * write happens), so it takes the path below. */
        const RTenum face = ctx->material.color_material_face;
        const RTenum mode = ctx->material.color_material_mode;
        uint32_t bits = 0;
        if (mode == RT_AMBIENT || mode == RT_AMBIENT_AND_DIFFUSE)
            bits |= SCENE_MATERIAL_AMBIENT;
        if (mode == RT_DIFFUSE || mode == RT_AMBIENT_AND_DIFFUSE)
            bits |= SCENE_MATERIAL_DIFFUSE;
        if (mode == RT_SPECULAR)
            bits |= SCENE_MATERIAL_SPECULAR;
        if (mode == RT_EMISSION)
            bits |= SCENE_MATERIAL_EMISSION;
        if (face != RT_BACK)
            rec->material_set |= bits;
        if (face != RT_FRONT)
            rec->material_set |= bits << SCENE_MATERIAL_BACK_SHIFT;
        return;
    }
    /* Otherwise the colour written is the one current at the call (the
     * caller's): the list's later triangles take their colours from the
     * instance of a segment of their own, which carries the material as
     * the replay left it. */
    const uint32_t colours = SCENE_MATERIAL_AMBIENT | SCENE_MATERIAL_DIFFUSE |
                             SCENE_MATERIAL_SPECULAR | SCENE_MATERIAL_EMISSION;
    rec->material_set &= ~(colours | colours << SCENE_MATERIAL_BACK_SHIFT);
    rt_list_state_changed(ctx, caller);
}

static void material(const char *caller, RTenum face, RTenum pname, const RTfloat *params,
                     int scalar_only)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx)
        return;
    int n = material_size(pname);
    if (!check_face(ctx, caller, "face", face) ||
        !check_pname(ctx, caller, pname, n != 0 && (!scalar_only || n == 1), "material",
                     params) ||
        !check_values(ctx, caller, pname, params, n))
        return;
    rt_list_state(ctx, LIST_MATERIAL, face, pname, params, n);
    struct scene_material m = ctx->material;
    if (pname == RT_AMBIENT_AND_DIFFUSE) {
        set_material(&m, face, RT_AMBIENT, params, n);
        set_material(&m, face, RT_DIFFUSE, params, n);
    } else {
        set_material(&m, face, pname, params, n);
    }
    /* GL ignores a material call for the properties RT_COLOR_MATERIAL
     * tracks while it is enabled (they keep the current colour). */
    if (ctx->color_material) {
        float *keep[4], *now[4];
        int tracked = tracked_colours(&m, m.color_material_face, m.color_material_mode, keep);
        tracked_colours(&ctx->material, m.color_material_face, m.color_material_mode, now);
        for (int i = 0; i < tracked; i++)
            memcpy(keep[i], now[i], 4 * sizeof(float));
    }
    if (memcmp(&m, &ctx->material, sizeof(m)) == 0)
        return; /* unchanged: keep the interned index (Mesa compares first) */
    ctx->material = m;
    ctx->recording.material_index = -1;
}

void rtMaterialf(RTenum face, RTenum pname, RTfloat param)
{
    /* Padded to the size of a vector pname: the compiler cannot see that
     * scalar_only keeps the 4-float paths from reading it. */
    const RTfloat params[4] = {param, 0.0f, 0.0f, 0.0f};
    material("rtMaterialf", face, pname, params, 1);
}

void rtMaterialfv(RTenum face, RTenum pname, const RTfloat *params)
{
    material("rtMaterialfv", face, pname, params, 0);
}

static void light(const char *caller, RTenum which, RTenum pname, const RTfloat *params,
                  int scalar_only)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, caller))
        return;
    int n = light_size(pname);
    if (!check_light(ctx, caller, which) ||
        !check_pname(ctx, caller, pname, n != 0 && (!scalar_only || n == 1), "light", params) ||
        !check_values(ctx, caller, pname, params, n))
        return;
    rt_list_state(ctx, LIST_LIGHT, which, pname, params, n);
    float f[4];
    memcpy(f, params, (size_t)n * sizeof(float));
    if (pname == RT_POSITION || pname == RT_SPOT_DIRECTION) {
        /* Transformed by the modelview at the call (GL), in double: a
         * position by the whole matrix, a direction by its upper 3x3. */
        const double *m = ctx->modelview.m[ctx->modelview.depth - 1];
        if (pname == RT_POSITION) {
            double p[4] = {params[0], params[1], params[2], params[3]};
            for (int r = 0; r < 4; r++)
                f[r] = (float)(m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r] * p[3]);
        } else {
            for (int r = 0; r < 3; r++)
                f[r] = (float)(m[r] * params[0] + m[4 + r] * params[1] + m[8 + r] * params[2]);
        }
        if (!rt_check_finite(ctx, caller, f, n))
            return;
    }
    memcpy(light_field(&ctx->render.lights[which - RT_LIGHT0], pname), f,
           (size_t)n * sizeof(float));
    /* Per primitive (scene/gl_state.h): a list's later geometry gets a
     * segment whose instance carries the lights as they are there. */
    rt_list_state_changed(ctx, caller);
}

void rtLightf(RTenum which, RTenum pname, RTfloat param)
{
    const RTfloat params[4] = {param, 0.0f, 0.0f, 0.0f};
    light("rtLightf", which, pname, params, 1);
}

void rtLightfv(RTenum which, RTenum pname, const RTfloat *params)
{
    light("rtLightfv", which, pname, params, 0);
}

/* rtLightModel*: the ambient colour (vector forms only), the local
 * viewer and two-sided lighting (any form; non-zero is true). */
static void light_model(const char *caller, RTenum pname, const RTfloat *params, int vector)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, caller))
        return;
    char b1[RT_ENUM_STRING_SIZE];
    if (pname != RT_LIGHT_MODEL_LOCAL_VIEWER && pname != RT_LIGHT_MODEL_TWO_SIDE &&
        (pname != RT_LIGHT_MODEL_AMBIENT || !vector)) {
        rt_error(ctx, RT_INVALID_ENUM, "%s(pname=%s): not a light model parameter%s", caller,
                 rt_enum_string(pname, b1),
                 pname == RT_LIGHT_MODEL_AMBIENT ? " for a scalar call" : "");
        return;
    }
    if (!params) {
        rt_error(ctx, RT_INVALID_VALUE, "%s(params=NULL)", caller);
        return;
    }
    if (!rt_check_finite(ctx, caller, params, pname == RT_LIGHT_MODEL_AMBIENT ? 4 : 1))
        return;
    rt_list_state(ctx, LIST_LIGHT_MODEL, pname, 0, params,
                  pname == RT_LIGHT_MODEL_AMBIENT ? 4 : 1);
    if (pname == RT_LIGHT_MODEL_AMBIENT)
        memcpy(ctx->render.global_ambient, params, 4 * sizeof(float));
    else if (pname == RT_LIGHT_MODEL_TWO_SIDE)
        ctx->render.light_model_two_side = params[0] != 0.0f;
    else
        ctx->render.light_model_local_viewer = params[0] != 0.0f;
    /* Per primitive (scene/gl_state.h): a list's later geometry gets a
     * segment whose instance carries the light model current there. */
    rt_list_state_changed(ctx, caller);
}

void rtLightModelfv(RTenum pname, const RTfloat *params)
{
    light_model("rtLightModelfv", pname, params, 1);
}

void rtLightModelf(RTenum pname, RTfloat param)
{
    light_model("rtLightModelf", pname, &param, 0);
}

void rtLightModeli(RTenum pname, RTint param)
{
    RTfloat f = (RTfloat)param;
    light_model("rtLightModeli", pname, &f, 0);
}

void rtLightModeliv(RTenum pname, const RTint *params)
{
    /* GL maps integer colours linearly, the largest integer to 1.0. */
    RTfloat f[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    if (params) {
        int n = pname == RT_LIGHT_MODEL_AMBIENT ? 4 : 1;
        for (int i = 0; i < n; i++)
            f[i] = pname == RT_LIGHT_MODEL_AMBIENT ? (RTfloat)((double)params[i] / 2147483647.0)
                                                  : (RTfloat)params[i];
    }
    light_model("rtLightModeliv", pname, params ? f : NULL, 1);
}

void rtShadingMode(RTenum mode)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtShadingMode"))
        return;
    char b1[RT_ENUM_STRING_SIZE];
    if (mode != RT_EYE_LIGHT && mode != RT_WHITTED && mode != RT_FIXED_FUNCTION) {
        rt_error(ctx, RT_INVALID_ENUM,
                 "rtShadingMode(mode=%s): not RT_FIXED_FUNCTION, RT_EYE_LIGHT or RT_WHITTED",
                 rt_enum_string(mode, b1));
        return;
    }
    ctx->render.shading = mode == RT_WHITTED       ? RENDER_WHITTED
                          : mode == RT_EYE_LIGHT ? RENDER_EYE_LIGHT
                                                 : RENDER_FIXED_FUNCTION;
}

void rt_sync_fixed_function(struct rt_context *ctx)
{
    struct scene_material m = ctx->material;
    m.cull_mode = ctx->cull_face_mode == RT_FRONT  ? SCENE_CULL_FRONT
                  : ctx->cull_face_mode == RT_BACK ? SCENE_CULL_BACK
                                                   : SCENE_CULL_BOTH;
    m.cull_face = ctx->cull_face_enabled ? (uint8_t)m.cull_mode : (uint8_t)SCENE_CULL_NONE;
    m.normalize = ctx->normalize_enabled        ? SCENE_NORMALIZE_ON
                  : ctx->rescale_normal_enabled ? SCENE_NORMALIZE_RESCALE
                                                : SCENE_NORMALIZE_OFF;
    for (int i = 0; i < SCENE_TEXGEN_COORDS; i++) {
        /* Planes only while generating, so the disabled ones do not split
         * materials. */
        int on = ctx->texgen_enabled[i];
        m.texgen_mode[i] = on ? ctx->texgen_mode[i] : 0;
        for (int k = 0; k < 4; k++) {
            m.texgen_object_plane[i][k] = on ? ctx->texgen_object_plane[i][k] : 0.0f;
            m.texgen_eye_plane[i][k] = on ? ctx->texgen_eye_plane[i][k] : 0.0f;
        }
    }
    for (int i = 0; i < 2; i++)
        m.polygon_mode[i] = ctx->polygon_mode[i] == RT_FILL ? 0 : (uint16_t)ctx->polygon_mode[i];
    if (memcmp(&m, &ctx->material, sizeof(m)) == 0)
        return;
    ctx->material = m;
    ctx->recording.material_index = -1;
}

void rtColorMaterial(RTenum face, RTenum mode)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtColorMaterial"))
        return;
    if (!check_face(ctx, "rtColorMaterial", "face", face))
        return;
    char b1[RT_ENUM_STRING_SIZE];
    if (mode != RT_AMBIENT && mode != RT_DIFFUSE && mode != RT_SPECULAR && mode != RT_EMISSION &&
        mode != RT_AMBIENT_AND_DIFFUSE) {
        rt_error(ctx, RT_INVALID_ENUM, "rtColorMaterial(mode=%s): not a material colour",
                 rt_enum_string(mode, b1));
        return;
    }
    rt_list_state(ctx, LIST_COLOR_MATERIAL, face, mode, NULL, 0);
    /* In a list that has named no mode yet the properties tracked so far
     * are the caller's at the call, whatever they are while recording:
     * the write is then left to the call (rt_color_material_settle), even
     * for a mode equal to the recording's.  The list's later triangles
     * record the mode as the list's own only after that. */
    const int compiling = rt_list_compiling(ctx);
    const int named =
        compiling && (ctx->recording.material_set & SCENE_MATERIAL_COLOR_MATERIAL_MODE);
    if (ctx->material.color_material_face != face || ctx->material.color_material_mode != mode ||
        (compiling && !named)) {
        /* The properties tracked so far keep the current colour; the new
         * ones take it (by definition, rt_color_material_write). */
        rt_color_material_settle(ctx, "rtColorMaterial");
    }
    if (compiling)
        ctx->recording.material_set |= SCENE_MATERIAL_COLOR_MATERIAL_MODE;
    if (ctx->material.color_material_face == face && ctx->material.color_material_mode == mode)
        return;
    ctx->material.color_material_face = face;
    ctx->material.color_material_mode = mode;
    ctx->recording.material_index = -1;
}

void rtCullFace(RTenum mode)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtCullFace"))
        return;
    if (!check_face(ctx, "rtCullFace", "mode", mode))
        return;
    rt_list_state(ctx, LIST_CULL_FACE, mode, 0, NULL, 0);
    ctx->cull_face_mode = mode;
    rt_sync_fixed_function(ctx);
}

void rtFrontFace(RTenum mode)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtFrontFace"))
        return;
    char b1[RT_ENUM_STRING_SIZE];
    if (mode != RT_CW && mode != RT_CCW) {
        rt_error(ctx, RT_INVALID_ENUM, "rtFrontFace(mode=%s): not RT_CW or RT_CCW",
                 rt_enum_string(mode, b1));
        return;
    }
    rt_list_state(ctx, LIST_FRONT_FACE, mode, 0, NULL, 0);
    uint8_t cw = mode == RT_CW;
    if (ctx->material.front_cw == cw)
        return;
    ctx->material.front_cw = cw;
    ctx->recording.material_index = -1;
}

void rtGetMaterialfv(RTenum face, RTenum pname, RTfloat *params)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtGetMaterialfv"))
        return;
    char b1[RT_ENUM_STRING_SIZE];
    if (face != RT_FRONT && face != RT_BACK) {
        rt_error(ctx, RT_INVALID_ENUM, "rtGetMaterialfv(face=%s): not RT_FRONT or RT_BACK",
                 rt_enum_string(face, b1));
        return;
    }
    int n = material_size(pname);
    if (!check_pname(ctx, "rtGetMaterialfv", pname, n != 0 && pname != RT_AMBIENT_AND_DIFFUSE,
                     "material", params))
        return;
    /* The tracked properties hold the current colour while
     * RT_COLOR_MATERIAL is enabled (rt_color_material_write). */
    struct scene_material settled = ctx->material;
    rt_color_material_write(ctx, &settled);
    memcpy(params, material_field(&settled, pname, face == RT_BACK), (size_t)n * sizeof(float));
}

void rtGetLightfv(RTenum which, RTenum pname, RTfloat *params)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtGetLightfv"))
        return;
    int n = light_size(pname);
    if (!check_light(ctx, "rtGetLightfv", which) ||
        !check_pname(ctx, "rtGetLightfv", pname, n != 0, "light", params))
        return;
    memcpy(params, light_field(&ctx->render.lights[which - RT_LIGHT0], pname),
           (size_t)n * sizeof(float));
}

void rtRenderParameteri(RTenum pname, RTint param)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtRenderParameteri"))
        return;
    if (pname == RT_UPDATE_STRATEGY) {
        if (!rt_strategy_is_valid((RTenum)param)) {
            char b1[RT_ENUM_STRING_SIZE];
            rt_error(ctx, RT_INVALID_ENUM, "rtRenderParameteri(RT_UPDATE_STRATEGY, %s)",
                     rt_enum_string((RTenum)param, b1));
            return;
        }
        ctx->scene.default_strategy = (RTenum)param;
        return;
    }
    if (pname != RT_MAX_RAY_DEPTH) {
        char b1[RT_ENUM_STRING_SIZE];
        rt_error(ctx, RT_INVALID_ENUM, "rtRenderParameteri(pname=%s)", rt_enum_string(pname, b1));
        return;
    }
    if (param < 0 || param > API_MAX_RAY_DEPTH_LIMIT) {
        rt_error(ctx, RT_INVALID_VALUE, "rtRenderParameteri(RT_MAX_RAY_DEPTH, %d): not in 0..%d",
                 param, API_MAX_RAY_DEPTH_LIMIT);
        return;
    }
    ctx->render.max_depth = param;
}
