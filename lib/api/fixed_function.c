/* SPDX-License-Identifier: Apache-2.0 */
/*
 * fixed_function.c - the rest of GL 1.x's fixed-function state that ported
 * programs set: rtFog (per primitive, carried by the instance of the
 * geometry, scene/gl_state.h; docs/fog.md), rtTexEnv and rtTexGen
 * (recorded with the triangles, as GL applies them per primitive;
 * docs/textures.md), all three recorded in display lists, and
 * the names with no ray tracing meaning, accepted with no effect after
 * GL's own validation (docs/appearance.md, "Accepted no-ops").
 */
#include <math.h>
#include <string.h>

#include "api/context.h"
#include "api/enum_names.h"
#include "base/mat4.h"

static void fog(const char *caller, RTenum pname, const RTfloat *params, int vector)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, caller))
        return;
    char b1[RT_ENUM_STRING_SIZE];
    if (pname != RT_FOG_MODE && pname != RT_FOG_DENSITY && pname != RT_FOG_START &&
        pname != RT_FOG_END && (pname != RT_FOG_COLOR || !vector)) {
        rt_error(ctx, RT_INVALID_ENUM, "%s(pname=%s): not a fog parameter%s", caller,
                 rt_enum_string(pname, b1),
                 pname == RT_FOG_COLOR ? " for a scalar call" : "");
        return;
    }
    if (!params) {
        rt_error(ctx, RT_INVALID_VALUE, "%s(params=NULL)", caller);
        return;
    }
    const int n = pname == RT_FOG_COLOR ? 4 : 1;
    if (!rt_check_finite(ctx, caller, params, n))
        return;
    struct scene_fog *f = &ctx->render.fog;
    switch (pname) {
    case RT_FOG_MODE: {
        RTenum mode = (RTenum)params[0];
        if ((float)mode != params[0] ||
            (mode != RT_LINEAR && mode != RT_EXP && mode != RT_EXP2)) {
            rt_error(ctx, RT_INVALID_ENUM, "%s(RT_FOG_MODE, %s): not RT_LINEAR, RT_EXP or RT_EXP2",
                     caller, rt_enum_string(mode, b1));
            return;
        }
        break;
    }
    case RT_FOG_DENSITY:
        if (params[0] < 0.0f) {
            rt_error(ctx, RT_INVALID_VALUE, "%s(RT_FOG_DENSITY, %g): negative", caller,
                     (double)params[0]);
            return;
        }
        break;
    default:
        break;
    }
    rt_list_state(ctx, LIST_FOG, pname, 0, params, n);
    switch (pname) {
    case RT_FOG_MODE:
        f->mode = (RTenum)params[0];
        break;
    case RT_FOG_DENSITY:
        f->density = params[0];
        break;
    case RT_FOG_START:
        f->start = params[0];
        break;
    case RT_FOG_END:
        f->end = params[0];
        break;
    default:
        /* GL clamps the fog colour to [0, 1]. */
        for (int k = 0; k < 4; k++)
            f->color[k] = params[k] < 0.0f ? 0.0f : (params[k] > 1.0f ? 1.0f : params[k]);
        break;
    }
    /* Per primitive: a list's later geometry gets a segment of its own. */
    rt_list_state_changed(ctx, caller);
}

uint32_t rt_light_set_now(struct rt_context *ctx)
{
    const struct scene_frame *f = &ctx->scene.frame;
    /* The table restarts when the next instance starts a new list
     * (scene_frame_light_set): then the cached index is stale. */
    if (ctx->light_set_cached && (f->open || f->light_sets_fresh) &&
        ctx->light_set_serial == f->light_sets_serial &&
        memcmp(ctx->light_set_lights, ctx->render.lights, sizeof(ctx->light_set_lights)) == 0)
        return ctx->light_set_index;
    uint32_t index = scene_frame_light_set(&ctx->scene.frame, ctx->render.lights);
    if (index == UINT32_MAX) { /* the caller records the error */
        ctx->light_set_cached = 0;
        return index;
    }
    ctx->light_set_cached = 1;
    ctx->light_set_index = index;
    ctx->light_set_serial = f->light_sets_serial;
    memcpy(ctx->light_set_lights, ctx->render.lights, sizeof(ctx->light_set_lights));
    return index;
}

void rt_gl_state_now(struct rt_context *ctx, struct scene_gl_state *gl)
{
    memset(gl, 0, sizeof(*gl));
    /* The fog parameters only while fog is enabled, so that changing them
     * with fog off does not cut segments. */
    if (ctx->render.fog.enabled)
        gl->fog = ctx->render.fog;
    gl->light_model.two_side = ctx->render.light_model_two_side;
    gl->light_model.local_viewer = ctx->render.light_model_local_viewer;
    memcpy(gl->light_model.ambient, ctx->render.global_ambient, sizeof(gl->light_model.ambient));
    gl->light_set = rt_light_set_now(ctx);
}

void rtFogf(RTenum pname, RTfloat param)
{
    fog("rtFogf", pname, &param, 0);
}

void rtFogi(RTenum pname, RTint param)
{
    RTfloat f = (RTfloat)param;
    fog("rtFogi", pname, &f, 0);
}

void rtFogfv(RTenum pname, const RTfloat *params)
{
    fog("rtFogfv", pname, params, 1);
}

static void tex_env(const char *caller, RTenum target, RTenum pname, const RTfloat *params,
                    int vector)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, caller))
        return;
    char b1[RT_ENUM_STRING_SIZE];
    if (target != RT_TEXTURE_ENV) {
        rt_error(ctx, RT_INVALID_ENUM, "%s(target=%s): not RT_TEXTURE_ENV", caller,
                 rt_enum_string(target, b1));
        return;
    }
    if (pname != RT_TEXTURE_ENV_MODE && (pname != RT_TEXTURE_ENV_COLOR || !vector)) {
        rt_error(ctx, RT_INVALID_ENUM, "%s(pname=%s): not a texture environment parameter%s",
                 caller, rt_enum_string(pname, b1),
                 pname == RT_TEXTURE_ENV_COLOR ? " for a scalar call" : "");
        return;
    }
    if (!params) {
        rt_error(ctx, RT_INVALID_VALUE, "%s(params=NULL)", caller);
        return;
    }
    if (pname == RT_TEXTURE_ENV_COLOR && !rt_check_finite(ctx, caller, params, 4))
        return;
    struct scene_material m = ctx->material;
    if (pname == RT_TEXTURE_ENV_MODE) {
        RTenum mode = (RTenum)params[0];
        if ((float)mode != params[0] || (mode != RT_MODULATE && mode != RT_REPLACE &&
                                         mode != RT_DECAL && mode != RT_BLEND)) {
            rt_error(ctx, RT_INVALID_ENUM,
                     "%s(RT_TEXTURE_ENV_MODE, %s): not RT_MODULATE, RT_REPLACE, RT_DECAL or "
                     "RT_BLEND",
                     caller, rt_enum_string(mode, b1));
            return;
        }
        rt_list_state(ctx, LIST_TEX_ENV, pname, 0, params, 1);
        m.tex_env_mode = mode;
    } else {
        rt_list_state(ctx, LIST_TEX_ENV, pname, 0, params, 4);
        for (int k = 0; k < 4; k++)
            m.tex_env_color[k] = params[k] < 0.0f ? 0.0f : (params[k] > 1.0f ? 1.0f : params[k]);
    }
    if (memcmp(&m, &ctx->material, sizeof(m)) == 0)
        return;
    ctx->material = m;
    ctx->recording.material_index = -1;
}

void rtTexEnvi(RTenum target, RTenum pname, RTint param)
{
    RTfloat f = (RTfloat)param;
    tex_env("rtTexEnvi", target, pname, &f, 0);
}

void rtTexEnvf(RTenum target, RTenum pname, RTfloat param)
{
    tex_env("rtTexEnvf", target, pname, &param, 0);
}

void rtTexEnvfv(RTenum target, RTenum pname, const RTfloat *params)
{
    tex_env("rtTexEnvfv", target, pname, params, 1);
}

/* rtTexGen*: GL 1.1 sec. 2.10.4.  The eye plane is transformed by the
 * inverse of the modelview at the call, as GL: p_eye = p M^-1. */
static void tex_gen(const char *caller, RTenum coord, RTenum pname, const RTfloat *params,
                    int vector)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, caller))
        return;
    char b1[RT_ENUM_STRING_SIZE];
    if (coord != RT_S && coord != RT_T && coord != RT_R && coord != RT_Q) {
        rt_error(ctx, RT_INVALID_ENUM, "%s(coord=%s): not RT_S, RT_T, RT_R or RT_Q", caller,
                 rt_enum_string(coord, b1));
        return;
    }
    int plane = pname == RT_OBJECT_PLANE || pname == RT_EYE_PLANE;
    if (pname != RT_TEXTURE_GEN_MODE && (!plane || !vector)) {
        rt_error(ctx, RT_INVALID_ENUM, "%s(pname=%s): not a texture generation parameter%s",
                 caller, rt_enum_string(pname, b1), plane ? " for a scalar call" : "");
        return;
    }
    if (!params) {
        rt_error(ctx, RT_INVALID_VALUE, "%s(params=NULL)", caller);
        return;
    }
    const int i = coord == RT_S   ? SCENE_TEXGEN_S
                  : coord == RT_T ? SCENE_TEXGEN_T
                  : coord == RT_Q ? SCENE_TEXGEN_Q
                                  : RT_TEXGEN_R;
    if (pname != RT_TEXTURE_GEN_MODE && !rt_check_finite(ctx, caller, params, 4))
        return;
    if (pname == RT_TEXTURE_GEN_MODE) {
        RTenum mode = (RTenum)params[0];
        if ((float)mode != params[0] ||
            (mode != RT_OBJECT_LINEAR && mode != RT_EYE_LINEAR && mode != RT_SPHERE_MAP)) {
            rt_error(ctx, RT_INVALID_ENUM,
                     "%s(RT_TEXTURE_GEN_MODE, %s): not RT_OBJECT_LINEAR, RT_EYE_LINEAR or "
                     "RT_SPHERE_MAP",
                     caller, rt_enum_string(mode, b1));
            return;
        }
        /* GL 1.1 sec. 2.10.4: the sphere map generates s and t only
         * (Mesa: GL_INVALID_ENUM for r and q). */
        if (mode == RT_SPHERE_MAP && (coord == RT_Q || coord == RT_R)) {
            rt_error(ctx, RT_INVALID_ENUM, "%s(coord=%s, RT_TEXTURE_GEN_MODE, RT_SPHERE_MAP): "
                     "the sphere map generates s and t only",
                     caller, rt_enum_string(coord, b1));
            return;
        }
        rt_list_state(ctx, LIST_TEX_GEN, coord, pname, params, 1);
        ctx->texgen_mode[i] = mode;
    } else {
        rt_list_state(ctx, LIST_TEX_GEN, coord, pname, params, 4);
        if (pname == RT_OBJECT_PLANE) {
            memcpy(ctx->texgen_object_plane[i], params, 4 * sizeof(float));
        } else {
            double inv[16], out[4];
            if (!mat4_invert(inv, ctx->modelview.m[ctx->modelview.depth - 1])) {
                /* GL leaves a singular modelview undefined; keep the plane. */
                for (int k = 0; k < 4; k++)
                    out[k] = params[k];
            } else {
                /* Row vector times M^-1: column c of the inverse. */
                for (int c = 0; c < 4; c++)
                    out[c] = params[0] * inv[4 * c] + params[1] * inv[4 * c + 1] +
                             params[2] * inv[4 * c + 2] + params[3] * inv[4 * c + 3];
            }
            float f[4];
            for (int k = 0; k < 4; k++)
                f[k] = (float)out[k];
            if (!rt_check_finite(ctx, caller, f, 4))
                return;
            memcpy(ctx->texgen_eye_plane[i], f, sizeof(f));
        }
    }
    /* r is kept, not used (context.h, RT_TEXGEN_R): no geometry changes. */
    if (i == RT_TEXGEN_R)
        return;
    rt_sync_fixed_function(ctx);
    /* A list's triangles take texture generation from their instance (an
     * eye plane recorded in a list is transformed by the modelview of its
     * replay, as glCallList executes glTexGen): later geometry gets a
     * segment of its own. */
    rt_list_state_changed(ctx, caller);
}

void rtTexGeni(RTenum coord, RTenum pname, RTint param)
{
    RTfloat f = (RTfloat)param;
    tex_gen("rtTexGeni", coord, pname, &f, 0);
}

void rtTexGenf(RTenum coord, RTenum pname, RTfloat param)
{
    tex_gen("rtTexGenf", coord, pname, &param, 0);
}

void rtTexGenfv(RTenum coord, RTenum pname, const RTfloat *params)
{
    tex_gen("rtTexGenfv", coord, pname, params, 1);
}

/* ---- Accepted no-ops: GL's checks, then nothing ------------------------- */

static struct rt_context *no_op_context(const char *caller)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, caller))
        return NULL;
    return ctx;
}

static void bad_enum(struct rt_context *ctx, const char *caller, const char *what, RTenum e)
{
    char b1[RT_ENUM_STRING_SIZE];
    rt_error(ctx, RT_INVALID_ENUM, "%s(%s=%s)", caller, what, rt_enum_string(e, b1));
}

void rtHint(RTenum target, RTenum mode)
{
    struct rt_context *ctx = no_op_context("rtHint");
    if (!ctx)
        return;
    /* As Mesa's _mesa_Hint: an unknown target or mode is RT_INVALID_ENUM
     * and changes nothing. */
    if ((target < RT_PERSPECTIVE_CORRECTION_HINT || target > RT_FOG_HINT) &&
        target != RT_ACCELERATION_HINT)
        bad_enum(ctx, "rtHint", "target", target);
    else if (mode != RT_DONT_CARE && mode != RT_FASTEST && mode != RT_NICEST)
        bad_enum(ctx, "rtHint", "mode", mode);
    else if (target == RT_ACCELERATION_HINT)
        ctx->acceleration_hint = mode;
}

static int is_buffer(RTenum mode)
{
    return mode == RT_NONE || (mode >= RT_FRONT_LEFT && mode <= RT_FRONT_AND_BACK);
}

void rtDrawBuffer(RTenum mode)
{
    struct rt_context *ctx = no_op_context("rtDrawBuffer");
    if (ctx && !is_buffer(mode))
        bad_enum(ctx, "rtDrawBuffer", "mode", mode);
}

void rtReadBuffer(RTenum mode)
{
    struct rt_context *ctx = no_op_context("rtReadBuffer");
    if (ctx && (mode == RT_NONE || !is_buffer(mode)))
        bad_enum(ctx, "rtReadBuffer", "mode", mode);
}

void rtDepthFunc(RTenum func)
{
    struct rt_context *ctx = no_op_context("rtDepthFunc");
    if (ctx && (func < RT_NEVER || func > RT_ALWAYS))
        bad_enum(ctx, "rtDepthFunc", "func", func);
}

void rtDepthRange(RTdouble zNear, RTdouble zFar)
{
    (void)zNear;
    (void)zFar;
    no_op_context("rtDepthRange"); /* GL clamps; nothing is invalid */
}

void rtClearDepth(RTdouble depth)
{
    (void)depth;
    no_op_context("rtClearDepth");
}

void rtLockArraysEXT(RTint first, RTsizei count)
{
    struct rt_context *ctx = no_op_context("rtLockArraysEXT");
    if (ctx && (first < 0 || count <= 0))
        rt_error(ctx, RT_INVALID_VALUE, "rtLockArraysEXT(first=%d, count=%d)", first, count);
}

void rtUnlockArraysEXT(void)
{
    no_op_context("rtUnlockArraysEXT");
}
