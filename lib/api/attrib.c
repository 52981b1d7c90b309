/* SPDX-License-Identifier: Apache-2.0 */
/*
 * attrib.c - the attribute stacks: rtPushAttrib, rtPopAttrib,
 * rtPushClientAttrib, rtPopClientAttrib (GL 1.5 sec. 6.1.14 and tables
 * 6.5 ff., which say which state each group holds).
 *
 * A push copies the state of every group into the new entry together with
 * the mask; a pop restores the groups of that mask only, so state outside
 * them keeps the value it has at the pop, as in GL.  Both stacks are
 * RT_MAX_ATTRIB_STACK_DEPTH (16, GL's minimum) deep; a push on a full
 * stack records RT_STACK_OVERFLOW, a pop of an empty one
 * RT_STACK_UNDERFLOW, and neither is allowed inside rtBegin/rtEnd
 * (RT_INVALID_OPERATION).  RT_HINT_BIT saves the one hint with state,
 * RT_ACCELERATION_HINT (GL 1.5 sec. 5.6: the hint group is every
 * hint's mode); GL's own hints have none here.  Bits without a Tracelist
 * meaning (stipple, scissor, pixel mode, evaluators, accumulation,
 * stencil) are accepted and save nothing, as the state they name does
 * not exist here.
 *
 * rtPushAttrib and rtPopAttrib are recorded in display lists and run when
 * the list is called, as GL's (the client stack is not: GL executes
 * glPushClientAttrib at once, also while compiling).  While an RT_COMPILE
 * list is recorded they also act on the context, as every recorded state
 * call does here (list.c), so that the list's later geometry is recorded
 * with the state the pop gives it; rtEndList then drops what the list
 * pushed, and a pop below the depth the list started at is recorded only.
 *
 * Where the state lives: ctx->material holds the lighting enable and the
 * colour-material face and mode (LIGHTING and ENABLE), the texture
 * environment (TEXTURE) and derived copies of culling, normalisation and
 * texgen, which rt_sync_fixed_function recomputes from the context's
 * switches after a pop.
 */
#include <string.h>

#include "api/context.h"

/* Every bit GL 1.x names, so that nothing else is silently a group. */
#define ATTRIB_GROUP_BITS RT_ALL_ATTRIB_BITS

static void save(const struct rt_context *ctx, struct attrib_entry *e)
{
    memcpy(e->current_color, ctx->current_color, sizeof(e->current_color));
    memcpy(e->current_normal, ctx->current_normal, sizeof(e->current_normal));
    memcpy(e->current_texcoord, ctx->current_texcoord, sizeof(e->current_texcoord));
    memcpy(e->raster_pos, ctx->raster_pos, sizeof(e->raster_pos));
    memcpy(e->raster_color, ctx->raster_color, sizeof(e->raster_color));
    e->raster_valid = ctx->raster_valid;
    e->material = ctx->material;
    rt_color_material_write(ctx, &e->material); /* the colours GL holds */
    e->color_material = ctx->color_material;
    e->shade_model = ctx->shade_model;
    e->texture_binding = ctx->texture_binding;
    e->texture_2d = ctx->texture_2d;
    memcpy(e->polygon_mode, ctx->polygon_mode, sizeof(e->polygon_mode));
    e->cull_face_enabled = ctx->cull_face_enabled;
    e->cull_face_mode = ctx->cull_face_mode;
    e->normalize_enabled = ctx->normalize_enabled;
    e->rescale_normal_enabled = ctx->rescale_normal_enabled;
    e->depth_test = ctx->depth_test;
    e->dither = ctx->dither;
    e->polygon_offset_fill = ctx->polygon_offset_fill;
    memcpy(e->texgen_enabled, ctx->texgen_enabled, sizeof(e->texgen_enabled));
    memcpy(e->texgen_mode, ctx->texgen_mode, sizeof(e->texgen_mode));
    memcpy(e->texgen_object_plane, ctx->texgen_object_plane, sizeof(e->texgen_object_plane));
    memcpy(e->texgen_eye_plane, ctx->texgen_eye_plane, sizeof(e->texgen_eye_plane));
    memcpy(e->lights, ctx->render.lights, sizeof(e->lights));
    memcpy(e->global_ambient, ctx->render.global_ambient, sizeof(e->global_ambient));
    e->light_model_two_side = ctx->render.light_model_two_side;
    e->light_model_local_viewer = ctx->render.light_model_local_viewer;
    e->fog = ctx->render.fog;
    e->vis = ctx->render.vis;
    memcpy(e->clear_color, ctx->render.clear_color, sizeof(e->clear_color));
    memcpy(e->viewport, ctx->render.viewport, sizeof(e->viewport));
    /* While a list is recorded its matrix calls change the recording's
     * mode (scene/recording.h), not the context's under RT_COMPILE. */
    e->matrix_mode = rt_list_compiling(ctx) ? ctx->recording.matrix_mode : ctx->matrix_mode;
    e->list_base = ctx->list_base;
    e->acceleration_hint = ctx->acceleration_hint;
}

/* GL_LIGHTING_BIT (GL 1.5 table 6.11 ff.): the material colours, the
 * colour-material switch, face and mode, the lighting enable, shade
 * model, every light (its enable included) and the light model. */
static void restore_lighting(struct rt_context *ctx, const struct attrib_entry *e)
{
    struct scene_material *m = &ctx->material;
    const struct scene_material *s = &e->material;
    memcpy(m->ambient, s->ambient, sizeof(m->ambient));
    memcpy(m->diffuse, s->diffuse, sizeof(m->diffuse));
    memcpy(m->specular, s->specular, sizeof(m->specular));
    memcpy(m->emission, s->emission, sizeof(m->emission));
    m->shininess = s->shininess;
    m->reflectivity = s->reflectivity;
    m->transparency = s->transparency;
    m->ior = s->ior;
    memcpy(m->back_ambient, s->back_ambient, sizeof(m->back_ambient));
    memcpy(m->back_diffuse, s->back_diffuse, sizeof(m->back_diffuse));
    memcpy(m->back_specular, s->back_specular, sizeof(m->back_specular));
    memcpy(m->back_emission, s->back_emission, sizeof(m->back_emission));
    m->back_shininess = s->back_shininess;
    m->color_material_face = s->color_material_face;
    m->color_material_mode = s->color_material_mode;
    m->lighting = s->lighting;
    ctx->color_material = e->color_material;
    /* The material as pushed (with the colour GL had written into it,
     * save): the tracked properties hold it until the colour changes. */
    ctx->color_material_current = 0;
    ctx->shade_model = e->shade_model;
    memcpy(ctx->render.lights, e->lights, sizeof(e->lights));
    memcpy(ctx->render.global_ambient, e->global_ambient, sizeof(e->global_ambient));
    ctx->render.light_model_two_side = e->light_model_two_side;
    ctx->render.light_model_local_viewer = e->light_model_local_viewer;
}

/* GL_ENABLE_BIT: every capability rtEnable knows. */
static void restore_enables(struct rt_context *ctx, const struct attrib_entry *e)
{
    ctx->material.lighting = e->material.lighting;
    /* As rtEnable / rtDisable(RT_COLOR_MATERIAL) (get.c): the tracking
     * that ends leaves the colour in the material. */
    if (ctx->color_material && !e->color_material)
        rt_color_material_settle(ctx, "rtPopAttrib");
    else if (!ctx->color_material && e->color_material)
        ctx->color_material_current = 1;
    ctx->color_material = e->color_material;
    ctx->texture_2d = e->texture_2d;
    ctx->cull_face_enabled = e->cull_face_enabled;
    ctx->normalize_enabled = e->normalize_enabled;
    ctx->rescale_normal_enabled = e->rescale_normal_enabled;
    ctx->render.fog.enabled = e->fog.enabled;
    memcpy(ctx->texgen_enabled, e->texgen_enabled, sizeof(e->texgen_enabled));
    ctx->render.vis.blend = e->vis.blend;
    ctx->render.vis.alpha_test = e->vis.alpha_test;
    ctx->depth_test = e->depth_test;
    ctx->dither = e->dither;
    ctx->polygon_offset_fill = e->polygon_offset_fill;
    for (int i = 0; i < RENDER_MAX_LIGHTS; i++)
        ctx->render.lights[i].enabled = e->lights[i].enabled;
    memcpy(ctx->render.vis.clip_enabled, e->vis.clip_enabled, sizeof(e->vis.clip_enabled));
}

static void restore(struct rt_context *ctx, const struct attrib_entry *e)
{
    const RTbitfield mask = e->mask;
    if (mask & RT_CURRENT_BIT) {
        memcpy(ctx->current_color, e->current_color, sizeof(e->current_color));
        memcpy(ctx->current_normal, e->current_normal, sizeof(e->current_normal));
        memcpy(ctx->current_texcoord, e->current_texcoord, sizeof(e->current_texcoord));
        memcpy(ctx->raster_pos, e->raster_pos, sizeof(e->raster_pos));
        memcpy(ctx->raster_color, e->raster_color, sizeof(e->raster_color));
        ctx->raster_valid = e->raster_valid;
    }
    if (mask & RT_ENABLE_BIT)
        restore_enables(ctx, e);
    if (mask & RT_LIGHTING_BIT)
        restore_lighting(ctx, e);
    if (mask & RT_POLYGON_BIT) {
        ctx->cull_face_enabled = e->cull_face_enabled;
        ctx->cull_face_mode = e->cull_face_mode;
        ctx->material.front_cw = e->material.front_cw;
        memcpy(ctx->polygon_mode, e->polygon_mode, sizeof(e->polygon_mode));
        ctx->polygon_offset_fill = e->polygon_offset_fill;
        ctx->render.vis.offset_factor = e->vis.offset_factor;
        ctx->render.vis.offset_units = e->vis.offset_units;
    }
    if (mask & RT_LINE_BIT)
        ctx->render.vis.line_width = e->vis.line_width;
    if (mask & RT_POINT_BIT)
        ctx->render.vis.point_size = e->vis.point_size;
    if (mask & RT_FOG_BIT)
        ctx->render.fog = e->fog;
    if (mask & RT_TEXTURE_BIT) {
        ctx->texture_2d = e->texture_2d;
        ctx->texture_binding = e->texture_binding;
        ctx->material.tex_env_mode = e->material.tex_env_mode;
        memcpy(ctx->material.tex_env_color, e->material.tex_env_color,
               sizeof(e->material.tex_env_color));
        memcpy(ctx->texgen_enabled, e->texgen_enabled, sizeof(e->texgen_enabled));
        memcpy(ctx->texgen_mode, e->texgen_mode, sizeof(e->texgen_mode));
        memcpy(ctx->texgen_object_plane, e->texgen_object_plane, sizeof(e->texgen_object_plane));
        memcpy(ctx->texgen_eye_plane, e->texgen_eye_plane, sizeof(e->texgen_eye_plane));
    }
    if (mask & RT_TRANSFORM_BIT) {
        if (rt_list_compiling(ctx))
            ctx->recording.matrix_mode = e->matrix_mode;
        if (!rt_list_compiling(ctx) || ctx->list_mode == RT_COMPILE_AND_EXECUTE)
            ctx->matrix_mode = e->matrix_mode;
        memcpy(ctx->render.vis.clip_plane, e->vis.clip_plane, sizeof(e->vis.clip_plane));
        memcpy(ctx->render.vis.clip_enabled, e->vis.clip_enabled, sizeof(e->vis.clip_enabled));
        ctx->normalize_enabled = e->normalize_enabled;
        ctx->rescale_normal_enabled = e->rescale_normal_enabled;
    }
    if (mask & RT_COLOR_BUFFER_BIT) {
        ctx->render.vis.blend = e->vis.blend;
        ctx->render.vis.blend_src = e->vis.blend_src;
        ctx->render.vis.blend_dst = e->vis.blend_dst;
        ctx->render.vis.alpha_test = e->vis.alpha_test;
        ctx->render.vis.alpha_func = e->vis.alpha_func;
        ctx->render.vis.alpha_ref = e->vis.alpha_ref;
        memcpy(ctx->render.clear_color, e->clear_color, sizeof(e->clear_color));
        ctx->dither = e->dither;
    }
    if (mask & RT_DEPTH_BUFFER_BIT) {
        ctx->depth_test = e->depth_test;
        ctx->render.vis.depth_mask = e->vis.depth_mask;
    }
    if (mask & RT_VIEWPORT_BIT)
        memcpy(ctx->render.viewport, e->viewport, sizeof(e->viewport));
    if (mask & RT_LIST_BIT)
        ctx->list_base = e->list_base;
    if (mask & RT_HINT_BIT)
        ctx->acceleration_hint = e->acceleration_hint;
    /* The material is interned by value: a changed one is looked up again
     * for the next triangle, and its derived fields follow the switches. */
    ctx->recording.material_index = -1;
    rt_sync_fixed_function(ctx);
    /* Clip planes, fog, the light model and the raster state travel with a
     * list's segments (list.c): the geometry after the pop starts one. */
    rt_list_state_changed(ctx, "rtPopAttrib");
}

/* While an RT_COMPILE list is recorded from the application: the push or
 * pop is recorded; returns 1 when it must not act on the context. */
static int compile_only_push(struct rt_context *ctx, RTbitfield mask)
{
    const float none = 0.0f;
    if (!rt_list_compiling(ctx))
        return 0;
    rt_list_state(ctx, LIST_PUSH_ATTRIB, mask, 0, &none, 0);
    if (ctx->list_mode != RT_COMPILE)
        return 0;
    if (ctx->attrib_depth == API_MAX_ATTRIB_STACK_DEPTH || ctx->attrib_skipped) {
        ctx->attrib_skipped++; /* the error is the call's, when it runs */
        return 1;
    }
    return 0;
}

static int compile_only_pop(struct rt_context *ctx)
{
    const float none = 0.0f;
    if (!rt_list_compiling(ctx))
        return 0;
    rt_list_state(ctx, LIST_POP_ATTRIB, 0, 0, &none, 0);
    if (ctx->list_mode != RT_COMPILE)
        return 0;
    if (ctx->attrib_skipped) {
        ctx->attrib_skipped--;
        return 1;
    }
    return ctx->attrib_depth <= ctx->attrib_list_base;
}

void rt_attrib_list_end(struct rt_context *ctx)
{
    if (ctx->attrib_depth > ctx->attrib_list_base)
        ctx->attrib_depth = ctx->attrib_list_base;
    ctx->attrib_skipped = 0;
}

void rtPushAttrib(RTbitfield mask)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtPushAttrib"))
        return;
    if (compile_only_push(ctx, mask))
        return;
    if (ctx->attrib_depth == API_MAX_ATTRIB_STACK_DEPTH) {
        rt_error(ctx, RT_STACK_OVERFLOW, "rtPushAttrib(mask=0x%x): the stack holds %d entries",
                 mask, API_MAX_ATTRIB_STACK_DEPTH);
        return;
    }
    struct attrib_entry *e = &ctx->attrib_stack[ctx->attrib_depth++];
    save(ctx, e);
    e->mask = mask & ATTRIB_GROUP_BITS;
}

void rtPopAttrib(void)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtPopAttrib"))
        return;
    if (compile_only_pop(ctx))
        return;
    if (ctx->attrib_depth == 0) {
        rt_error(ctx, RT_STACK_UNDERFLOW, "rtPopAttrib: the stack is empty");
        return;
    }
    restore(ctx, &ctx->attrib_stack[--ctx->attrib_depth]);
}

void rtPushClientAttrib(RTbitfield mask)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtPushClientAttrib"))
        return;
    if (ctx->client_attrib_depth == API_MAX_CLIENT_ATTRIB_STACK_DEPTH) {
        rt_error(ctx, RT_STACK_OVERFLOW,
                 "rtPushClientAttrib(mask=0x%x): the stack holds %d entries", mask,
                 API_MAX_CLIENT_ATTRIB_STACK_DEPTH);
        return;
    }
    struct client_attrib_entry *e = &ctx->client_attrib_stack[ctx->client_attrib_depth++];
    e->mask = mask;
    e->vertex_array = ctx->vertex_array;
    e->normal_array = ctx->normal_array;
    e->color_array = ctx->color_array;
    e->texcoord_array = ctx->texcoord_array;
    e->unpack = ctx->unpack;
    e->pack = ctx->pack;
}

void rtPopClientAttrib(void)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtPopClientAttrib"))
        return;
    if (ctx->client_attrib_depth == 0) {
        rt_error(ctx, RT_STACK_UNDERFLOW, "rtPopClientAttrib: the stack is empty");
        return;
    }
    const struct client_attrib_entry *e = &ctx->client_attrib_stack[--ctx->client_attrib_depth];
    if (e->mask & RT_CLIENT_VERTEX_ARRAY_BIT) {
        ctx->vertex_array = e->vertex_array;
        ctx->normal_array = e->normal_array;
        ctx->color_array = e->color_array;
        ctx->texcoord_array = e->texcoord_array;
    }
    if (e->mask & RT_CLIENT_PIXEL_STORE_BIT) {
        ctx->unpack = e->unpack;
        ctx->pack = e->pack;
    }
}
