/* SPDX-License-Identifier: Apache-2.0 */
/*
 * list.c - GL display lists: rtNewList, rtEndList, rtCallList,
 * rtCallLists, rtListBase, rtGenLists, rtDeleteLists, rtIsList, and the
 * replay of a list's operations at call time.
 *
 * A list records its geometry relative to its own matrix state (which
 * starts at the identity) and its matrix and state calls as operations
 * (scene/recording.h).  rtCallList replays them in order on the caller's
 * stacks and state, exactly as glCallList executes a list: each geometry
 * segment becomes an instance under the modelview the replay holds where
 * the segment starts, together with the appearance current there (which
 * triangles recorded before the list set a material or colour take), and
 * matrix errors (stack overflow and underflow) are reported at call time.
 * Validation and limits follow Mesa's dlist.c: list 0 is INVALID_VALUE,
 * a nested rtNewList INVALID_OPERATION, calls of undefined lists and calls
 * nested deeper than RT_MAX_LIST_NESTING (64) are ignored.
 *
 * RT_COMPILE does not execute: the calls a list records change the
 * context's state while recording (so that the recording sees them) and
 * rtEndList restores what rtNewList saved; matrix calls never touch the
 * context's stacks.  RT_COMPILE_AND_EXECUTE keeps the state, applies the
 * matrix calls at once and instances the list's segments at rtEndList
 * under the modelview each segment started with.
 */
#include <string.h>

#include "api/context.h"
#include "base/alloc.h"
#include "base/mat4.h"
#include "scene/list.h"

#define LIST_MAX_NESTING 64 /* GL's minimum and Mesa's MAX_LIST_NESTING */

struct list_exec {
    uint32_t segment;
    double m[16];
    struct scene_appearance appearance;
};

int rt_list_compiling(const struct rt_context *ctx)
{
    return ctx->recording.active && ctx->replaying == 0;
}

static void save_state(const struct rt_context *ctx, struct list_saved_state *s)
{
    memcpy(s->normal, ctx->current_normal, sizeof(s->normal));
    memcpy(s->color, ctx->current_color, sizeof(s->color));
    memcpy(s->texcoord, ctx->current_texcoord, sizeof(s->texcoord));
    s->shade_model = ctx->shade_model;
    s->color_material = ctx->color_material;
    s->material = ctx->material;
    s->texture_binding = ctx->texture_binding;
    s->texture_2d = ctx->texture_2d;
    memcpy(s->lights, ctx->render.lights, sizeof(s->lights));
    memcpy(s->global_ambient, ctx->render.global_ambient, sizeof(s->global_ambient));
    s->list_base = ctx->list_base;
    memcpy(s->clip_enabled, ctx->render.vis.clip_enabled, sizeof(s->clip_enabled));
    s->cull_face_enabled = ctx->cull_face_enabled;
    s->cull_face_mode = ctx->cull_face_mode;
    s->normalize_enabled = ctx->normalize_enabled;
    s->rescale_normal_enabled = ctx->rescale_normal_enabled;
    memcpy(s->texgen_enabled, ctx->texgen_enabled, sizeof(s->texgen_enabled));
    memcpy(s->texgen_mode, ctx->texgen_mode, sizeof(s->texgen_mode));
    memcpy(s->texgen_object_plane, ctx->texgen_object_plane, sizeof(s->texgen_object_plane));
    memcpy(s->texgen_eye_plane, ctx->texgen_eye_plane, sizeof(s->texgen_eye_plane));
    s->light_model_two_side = ctx->render.light_model_two_side;
    s->light_model_local_viewer = ctx->render.light_model_local_viewer;
    s->fog = ctx->render.fog;
    s->vis = ctx->render.vis;
    memcpy(s->polygon_mode, ctx->polygon_mode, sizeof(s->polygon_mode));
    s->polygon_offset_fill = ctx->polygon_offset_fill;
    s->color_material_current = ctx->color_material_current;
}

static void restore_state(struct rt_context *ctx, const struct list_saved_state *s)
{
    memcpy(ctx->current_normal, s->normal, sizeof(s->normal));
    memcpy(ctx->current_color, s->color, sizeof(s->color));
    memcpy(ctx->current_texcoord, s->texcoord, sizeof(s->texcoord));
    ctx->shade_model = s->shade_model;
    ctx->color_material = s->color_material;
    ctx->material = s->material;
    ctx->texture_binding = s->texture_binding;
    ctx->texture_2d = s->texture_2d;
    memcpy(ctx->render.lights, s->lights, sizeof(s->lights));
    memcpy(ctx->render.global_ambient, s->global_ambient, sizeof(s->global_ambient));
    ctx->list_base = s->list_base;
    memcpy(ctx->render.vis.clip_enabled, s->clip_enabled, sizeof(s->clip_enabled));
    ctx->cull_face_enabled = s->cull_face_enabled;
    ctx->cull_face_mode = s->cull_face_mode;
    ctx->normalize_enabled = s->normalize_enabled;
    ctx->rescale_normal_enabled = s->rescale_normal_enabled;
    memcpy(ctx->texgen_enabled, s->texgen_enabled, sizeof(s->texgen_enabled));
    memcpy(ctx->texgen_mode, s->texgen_mode, sizeof(s->texgen_mode));
    memcpy(ctx->texgen_object_plane, s->texgen_object_plane, sizeof(s->texgen_object_plane));
    memcpy(ctx->texgen_eye_plane, s->texgen_eye_plane, sizeof(s->texgen_eye_plane));
    ctx->render.light_model_two_side = s->light_model_two_side;
    ctx->render.light_model_local_viewer = s->light_model_local_viewer;
    ctx->render.fog = s->fog;
    /* ctx->material (restored above) already holds the derived fields. */
    /* The raster state a list records (lines.c); rtDepthMask and the clip
     * equations are not restored here. */
    struct render_visibility *vis = &ctx->render.vis;
    vis->blend = s->vis.blend;
    vis->blend_src = s->vis.blend_src;
    vis->blend_dst = s->vis.blend_dst;
    vis->line_width = s->vis.line_width;
    vis->point_size = s->vis.point_size;
    vis->alpha_test = s->vis.alpha_test;
    vis->alpha_func = s->vis.alpha_func;
    vis->alpha_ref = s->vis.alpha_ref;
    vis->offset_factor = s->vis.offset_factor;
    vis->offset_units = s->vis.offset_units;
    memcpy(ctx->polygon_mode, s->polygon_mode, sizeof(s->polygon_mode));
    ctx->polygon_offset_fill = s->polygon_offset_fill;
    ctx->color_material_current = s->color_material_current;
}

/* The appearance geometry drawn now takes; 0 when its light set could not
 * be allocated (RT_OUT_OF_MEMORY recorded: nothing is drawn). */
static int appearance_now(struct rt_context *ctx, struct scene_appearance *a)
{
    a->material = ctx->material;
    a->material.texture = ctx->texture_2d ? ctx->texture_binding : 0;
    a->material.texture_bound = ctx->texture_binding;
    a->material.texture_enabled = (uint32_t)ctx->texture_2d;
    memcpy(a->color, ctx->current_color, sizeof(a->color));
    a->color_material = ctx->color_material;
    rt_clip_now(ctx, &a->clip);
    rt_gl_state_now(ctx, &a->gl);
    a->flat = ctx->shade_model == RT_FLAT;
    rt_raster_now(ctx, &a->raster);
    if (a->gl.light_set != UINT32_MAX)
        return 1;
    rt_error(ctx, RT_OUT_OF_MEMORY, "out of memory for the lights of a list's geometry");
    return 0;
}

/* RT_COMPILE_AND_EXECUTE: notes the modelview and appearance a segment
 * that has just started is instanced with at rtEndList. */
static void capture_segment(struct rt_context *ctx)
{
    const struct scene_recording *rec = &ctx->recording;
    if (ctx->list_mode != RT_COMPILE_AND_EXECUTE || rec->op_count == 0)
        return;
    const struct scene_list_op *last = &rec->ops[rec->op_count - 1];
    if (last->kind != SCENE_OP_SEGMENT || last->a != rec->segment_count)
        return;
    struct list_exec *e = NULL;
    if (ctx->exec_count && ctx->exec[ctx->exec_count - 1].segment == last->a) {
        e = &ctx->exec[ctx->exec_count - 1]; /* the segment restarted here */
    } else {
        if (ctx->exec_count == ctx->exec_capacity) {
            uint32_t cap = ctx->exec_capacity ? 2 * ctx->exec_capacity : 8;
            void *p = rt_realloc_array(ctx->exec, cap, sizeof(*ctx->exec));
            if (!p) {
                ctx->recording.out_of_memory = 1;
                rt_error(ctx, RT_OUT_OF_MEMORY, "rtNewList: out of memory");
                return;
            }
            ctx->exec = p;
            ctx->exec_capacity = cap;
        }
        e = &ctx->exec[ctx->exec_count++];
    }
    e->segment = last->a;
    memcpy(e->m, ctx->modelview.m[ctx->modelview.depth - 1], sizeof(e->m));
    if (!appearance_now(ctx, &e->appearance))
        ctx->exec_count--; /* out of memory (recorded): not drawn */
}

static void list_out_of_memory(struct rt_context *ctx, const char *what)
{
    rt_error(ctx, RT_OUT_OF_MEMORY, "%s: out of memory recording list %u", what,
             ctx->recording.name);
}

int rt_list_matrix(struct rt_context *ctx, const char *caller, enum scene_list_op_kind kind,
                   RTenum mode, const double m[16])
{
    if (!rt_list_compiling(ctx))
        return 0;
    int status = scene_list_matrix_op(&ctx->recording, kind, mode, m);
    if (status == -2) {
        rt_error(ctx, RT_INVALID_VALUE, "%s: the resulting matrix is not finite", caller);
        return 1;
    }
    if (status) {
        list_out_of_memory(ctx, caller);
        return 1;
    }
    if (ctx->list_mode == RT_COMPILE_AND_EXECUTE) {
        rt_matrix_apply(ctx, caller, kind, mode, m);
        capture_segment(ctx);
    }
    return 1;
}

void rt_list_state_changed(struct rt_context *ctx, const char *caller)
{
    if (!rt_list_compiling(ctx))
        return;
    if (scene_list_split(&ctx->recording)) {
        list_out_of_memory(ctx, caller);
        return;
    }
    /* RT_COMPILE_AND_EXECUTE: the new segment is instanced with the
     * state now in effect. */
    capture_segment(ctx);
}

/* The SCENE_MATERIAL_* bit of the per-primitive state a state call sets,
 * 0 for none: what the list's later triangles record rather than inherit.
 * Texture generation has none: a list's triangles always take it from
 * their instance, the list's segments cut at every rtTexGen and
 * RT_TEXTURE_GEN_S / _T change (fixed_function.c), because an eye plane
 * depends on the modelview of the replay. */
static uint32_t state_bit(enum list_state_call what, RTenum b)
{
    switch (what) {
    case LIST_CULL_FACE:
        return SCENE_MATERIAL_CULL_MODE;
    case LIST_FRONT_FACE:
        return SCENE_MATERIAL_FRONT_FACE;
    case LIST_COLOR_MATERIAL: /* set by rtColorMaterial after its write-back */
        return 0;
    case LIST_TEX_ENV:
        return SCENE_MATERIAL_TEX_ENV;
    case LIST_BIND_TEXTURE:
        return SCENE_MATERIAL_TEXTURE;
    case LIST_POLYGON_MODE:
        return (b != RT_BACK ? SCENE_MATERIAL_POLYGON_MODE_FRONT : 0u) |
               (b != RT_FRONT ? SCENE_MATERIAL_POLYGON_MODE_BACK : 0u);
    case LIST_ENABLE:
    case LIST_DISABLE:
        switch (b) {
        case RT_LIGHTING:
            return SCENE_MATERIAL_LIGHTING;
        case RT_CULL_FACE:
            return SCENE_MATERIAL_CULL_ENABLE;
        case RT_TEXTURE_2D:
            return SCENE_MATERIAL_TEXTURE_ENABLE;
        case RT_NORMALIZE:
        case RT_RESCALE_NORMAL:
            return SCENE_MATERIAL_NORMALIZE;
        default:
            return 0;
        }
    default:
        return 0;
    }
}

/* Attribute calls commute with each other: a repeated one replaces the
 * last of its kind among the trailing attribute operations, so a list
 * setting a normal per vertex keeps one operation. */
static int is_attribute(const struct scene_list_op *op)
{
    return op->kind == SCENE_OP_STATE &&
           (op->a == LIST_COLOR || op->a == LIST_NORMAL || op->a == LIST_TEXCOORD);
}

void rt_list_state(struct rt_context *ctx, enum list_state_call what, RTenum b, RTenum c,
                   const float *v, int n)
{
    if (!rt_list_compiling(ctx))
        return;
    struct scene_recording *rec = &ctx->recording;
    if (what == LIST_COLOR)
        rec->color_set = 1;
    if ((what == LIST_ENABLE || what == LIST_DISABLE) && b == RT_COLOR_MATERIAL)
        rec->color_material_set = 1;
    if (what == LIST_MATERIAL) {
        static const struct {
            RTenum pname;
            uint32_t bits;
        } props[] = {{RT_AMBIENT, SCENE_MATERIAL_AMBIENT},
                     {RT_DIFFUSE, SCENE_MATERIAL_DIFFUSE},
                     {RT_AMBIENT_AND_DIFFUSE, SCENE_MATERIAL_AMBIENT | SCENE_MATERIAL_DIFFUSE},
                     {RT_SPECULAR, SCENE_MATERIAL_SPECULAR},
                     {RT_EMISSION, SCENE_MATERIAL_EMISSION},
                     {RT_SHININESS, SCENE_MATERIAL_SHININESS},
                     {RT_REFLECTIVITY, SCENE_MATERIAL_REFLECTIVITY},
                     {RT_TRANSPARENCY, SCENE_MATERIAL_TRANSPARENCY},
                     {RT_INDEX_OF_REFRACTION, SCENE_MATERIAL_IOR}};
        /* The face: RT_FRONT the front bits, RT_BACK the back ones (only
         * GL's five lighting properties have a back side). */
        for (size_t i = 0; i < sizeof(props) / sizeof(props[0]); i++)
            if (props[i].pname == c) {
                uint32_t lit = props[i].bits & (SCENE_MATERIAL_AMBIENT | SCENE_MATERIAL_DIFFUSE |
                                                SCENE_MATERIAL_SPECULAR | SCENE_MATERIAL_EMISSION |
                                                SCENE_MATERIAL_SHININESS);
                if (b != RT_BACK)
                    rec->material_set |= props[i].bits;
                if (b != RT_FRONT)
                    rec->material_set |= lit << SCENE_MATERIAL_BACK_SHIFT;
            }
    }
    rec->material_set |= state_bit(what, b);
    if (what == LIST_SHADE_MODEL)
        rec->shade_model_set = 1;
    if (what == LIST_COLOR || what == LIST_NORMAL || what == LIST_TEXCOORD) {
        for (uint32_t k = rec->op_count; k > 0 && is_attribute(&rec->ops[k - 1]); k--)
            if (rec->ops[k - 1].a == (uint32_t)what) {
                for (int i = 0; i < n; i++)
                    rec->ops[k - 1].v[i] = v[i];
                return;
            }
    }
    if (scene_list_state(rec, (uint32_t)what, b, c, v, n))
        list_out_of_memory(ctx, "state call");
}

/* Places one segment's object under the current modelview. */
static void instance_segment(struct rt_context *ctx, const char *caller,
                             struct scene_object *object, const double m[16],
                             const struct scene_appearance *appearance)
{
    double inverse[16], normal[16];
    /* Rays are transformed into object space by the inverse (Wald, Benthin
     * and Slusallek (2003) sec. 4.4); a matrix that cannot be inverted in
     * double precision, or is not affine, cannot be traced. */
    if (m[3] != 0.0 || m[7] != 0.0 || m[11] != 0.0 || m[15] != 1.0) {
        rt_error(ctx, RT_INVALID_VALUE, "%s(list=%u): the modelview matrix is projective",
                 caller, object->name);
        return;
    }
    if (!mat4_invert(inverse, m) || !mat4_normal_matrix(normal, m)) {
        rt_error(ctx, RT_INVALID_VALUE, "%s(list=%u): the modelview matrix is singular", caller,
                 object->name);
        return;
    }
    if (scene_frame_add_instance_appearance(&ctx->scene.frame, object, m, inverse, normal,
                                            appearance))
        rt_error(ctx, RT_OUT_OF_MEMORY, "%s(list=%u): out of memory", caller, object->name);
    rt_frame_described(ctx);
}

static void replay_state(const struct scene_list_op *op)
{
    float v[16];
    for (int i = 0; i < 16; i++)
        v[i] = (float)op->v[i];
    switch ((enum list_state_call)op->a) {
    case LIST_COLOR:
        rtColor4fv(v);
        break;
    case LIST_NORMAL:
        rtNormal3fv(v);
        break;
    case LIST_TEXCOORD:
        rtTexCoord4fv(v);
        break;
    case LIST_MATERIAL:
        rtMaterialfv(op->b, op->c, v);
        break;
    case LIST_SHADE_MODEL:
        rtShadeModel(op->b);
        break;
    case LIST_ENABLE:
        rtEnable(op->b);
        break;
    case LIST_DISABLE:
        rtDisable(op->b);
        break;
    case LIST_BIND_TEXTURE:
        rtBindTexture(op->b, op->c);
        break;
    case LIST_LIGHT:
        rtLightfv(op->b, op->c, v);
        break;
    case LIST_LIGHT_MODEL:
        rtLightModelfv(op->b, v);
        break;
    case LIST_LIST_BASE:
        rtListBase(op->b);
        break;
    case LIST_CLIP_PLANE:
        /* The equation in double, as recorded; transformed by the
         * modelview current at the call, as glCallList executes it. */
        rtClipPlane(op->b, op->v);
        break;
    case LIST_CULL_FACE:
        rtCullFace(op->b);
        break;
    case LIST_FRONT_FACE:
        rtFrontFace(op->b);
        break;
    case LIST_COLOR_MATERIAL:
        rtColorMaterial(op->b, op->c);
        break;
    case LIST_TEX_ENV:
        rtTexEnvfv(RT_TEXTURE_ENV, op->b, v);
        break;
    case LIST_TEX_GEN:
        /* An eye plane is transformed by the modelview at the call, as
         * glCallList executes glTexGen. */
        rtTexGenfv(op->b, op->c, v);
        break;
    case LIST_FOG:
        rtFogfv(op->b, v);
        break;
    case LIST_BLEND_FUNC:
        rtBlendFunc(op->b, op->c);
        break;
    case LIST_POLYGON_MODE:
        rtPolygonMode(op->b, op->c);
        break;
    case LIST_LINE_WIDTH:
        rtLineWidth(v[0]);
        break;
    case LIST_POINT_SIZE:
        rtPointSize(v[0]);
        break;
    case LIST_ALPHA_FUNC:
        rtAlphaFunc(op->b, v[0]);
        break;
    case LIST_POLYGON_OFFSET:
        rtPolygonOffset(v[0], v[1]);
        break;
    case LIST_PUSH_ATTRIB:
        rtPushAttrib(op->b);
        break;
    case LIST_POP_ATTRIB:
        rtPopAttrib();
        break;
    case LIST_CLEAR:
        rtClear(op->b);
        break;
    case LIST_RASTER_POS:
        rtRasterPos4dv(op->v);
        break;
    case LIST_WINDOW_POS:
        rtWindowPos3dv(op->v);
        break;
    case LIST_VERTEX:
        rtVertex3dv(op->v);
        break;
    case LIST_BITMAP:      /* rt_call_list's */
    case LIST_BITMAP_DATA: /* read by rt_bitmap_replay */
        break;
    }
}

void rt_call_list(struct rt_context *ctx, const char *caller, RTuint name)
{
    /* Mesa's execute_list: undefined names and calls nested deeper than
     * the limit (which also ends self-calls and cycles) do nothing. */
    if (ctx->call_depth >= LIST_MAX_NESTING)
        return;
    struct scene_object *object = scene_objects_lookup(&ctx->scene.objects, name);
    if (!object || !object->defined)
        return;
    /* The segments of one application-level call form a group that the
     * top level may flatten (scene/flatten.h); group_depth is the
     * nesting level of the segments placed now. */
    if (ctx->call_depth == 0)
        scene_frame_group_begin(&ctx->scene.frame, object,
                                ctx->modelview.m[ctx->modelview.depth - 1]);
    ctx->call_depth++;
    ctx->scene.frame.group_depth = (uint32_t)ctx->call_depth;
    ctx->replaying++;
    /* Called between rtBegin and rtEnd (GL allows it): the list's vertex
     * and attribute calls continue the open primitive; primitives of its
     * own and matrix calls are errors there, as glBegin and the matrix
     * calls are between glBegin and glEnd. */
    const int in_block = ctx->block.active;
    if (object->op_count == 0 && in_block &&
        (object->mesh.vertex_count > 0 || object->mesh.lines.vertex_count > 0))
        rt_error(ctx, RT_INVALID_OPERATION,
                 "%s(list=%u): the list draws primitives of its own, not allowed between "
                 "rtBegin and rtEnd",
                 caller, name);
    if (object->op_count == 0 && !in_block) {
        struct scene_appearance a;
        if (appearance_now(ctx, &a))
            instance_segment(ctx, caller, object, ctx->modelview.m[ctx->modelview.depth - 1],
                             &a);
    }
    for (uint32_t k = 0; k < object->op_count; k++) {
        const struct scene_list_op *op = &object->ops[k];
        switch ((enum scene_list_op_kind)op->kind) {
        case SCENE_OP_SEGMENT: {
            const struct scene_mesh *seg = &scene_list_segment(object, op->a)->mesh;
            if (in_block && seg->vertex_count == 0 && seg->lines.vertex_count == 0)
                break; /* a list without primitives keeps its (empty) first mesh */
            if (in_block) {
                rt_error(ctx, RT_INVALID_OPERATION,
                         "%s(list=%u): the list draws primitives of its own, not allowed "
                         "between rtBegin and rtEnd",
                         caller, name);
                break;
            }
            struct scene_appearance a;
            if (appearance_now(ctx, &a))
                instance_segment(ctx, caller, scene_list_segment(object, op->a),
                                 ctx->modelview.m[ctx->modelview.depth - 1], &a);
            break;
        }
        case SCENE_OP_CALL:
            rt_call_list(ctx, caller, op->b ? ctx->list_base + op->a : op->a);
            break;
        case SCENE_OP_STATE:
            if (op->a == LIST_BITMAP) /* with its rows in the operations after it */
                k += rt_bitmap_replay(ctx, op, object->op_count - k) - 1;
            else
                replay_state(op);
            break;
        default:
            if (in_block) {
                rt_error(ctx, RT_INVALID_OPERATION,
                         "%s(list=%u): a matrix call between rtBegin and rtEnd", caller, name);
                break;
            }
            rt_matrix_apply(ctx, caller, (enum scene_list_op_kind)op->kind, op->a, op->v);
            break;
        }
    }
    ctx->replaying--;
    ctx->call_depth--;
    ctx->scene.frame.group_depth = (uint32_t)ctx->call_depth;
    if (ctx->call_depth == 0)
        scene_frame_group_end(&ctx->scene.frame);
}

/* A call from the application (rtCallList, rtCallLists, rtInstantiateObject). */
static void call(struct rt_context *ctx, const char *caller, RTuint name, int add_base)
{
    /* A list recorded inside its own rtBegin/rtEnd keeps that block's
     * vertices in one mesh: a call there is expanded into the block when
     * recorded (its vertices and attributes join the primitive), not kept
     * by name. */
    if (rt_list_compiling(ctx) && !ctx->block.active) {
        if (scene_list_call(&ctx->recording, name, add_base)) {
            list_out_of_memory(ctx, caller);
            return;
        }
        if (ctx->list_mode != RT_COMPILE_AND_EXECUTE)
            return;
        rt_call_list(ctx, caller, add_base ? ctx->list_base + name : name);
        capture_segment(ctx);
        return;
    }
    rt_call_list(ctx, caller, add_base ? ctx->list_base + name : name);
}

void rtNewList(RTuint list, RTenum mode)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtNewList"))
        return;
    if (list == 0) {
        rt_error(ctx, RT_INVALID_VALUE, "rtNewList(list=0): 0 is not a list name");
        return;
    }
    if (mode != RT_COMPILE && mode != RT_COMPILE_AND_EXECUTE) {
        rt_error(ctx, RT_INVALID_ENUM, "rtNewList(mode=0x%x)", mode);
        return;
    }
    if (ctx->recording.active) {
        rt_error(ctx, RT_INVALID_OPERATION,
                 "rtNewList(%u): lists cannot nest (list %u is being defined)", list,
                 ctx->recording.name);
        return;
    }
    if (scene_list_begin(&ctx->recording, list, ctx->matrix_mode))
        /* Recording goes on (out_of_memory set): rtEndList keeps the old
         * definition, and the calls in between are consumed as GL's. */
        rt_error(ctx, RT_OUT_OF_MEMORY, "rtNewList(%u): out of memory", list);
    save_state(ctx, &ctx->saved);
    ctx->recording_object = 0;
    ctx->attrib_list_base = ctx->attrib_depth; /* attrib.c */
    ctx->attrib_skipped = 0;
    ctx->list_mode = mode;
    ctx->exec_count = 0;
    capture_segment(ctx);
}

void rtNewObject(RTuint name)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtNewObject"))
        return;
    if (ctx->recording.active) {
        rt_error(ctx, RT_INVALID_OPERATION,
                 "rtNewObject(%u): objects cannot nest (object %u is being defined)", name,
                 ctx->recording.name);
        return;
    }
    if (name == 0) {
        rt_error(ctx, RT_INVALID_VALUE, "rtNewObject(0): 0 is not an object name");
        return;
    }
    rtNewList(name, RT_COMPILE);
    ctx->recording_object = ctx->recording.active;
}

static void end_list(const char *caller)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, caller))
        return;
    struct scene_recording *rec = &ctx->recording;
    if (!rec->active) {
        rt_error(ctx, RT_INVALID_OPERATION, "%s: no matching %s", caller,
                 strcmp(caller, "rtEndList") == 0 ? "rtNewList" : "rtNewObject");
        return;
    }
    rec->active = 0;
    if (ctx->list_mode == RT_COMPILE) {
        restore_state(ctx, &ctx->saved); /* GL_COMPILE executed nothing */
        rt_attrib_list_end(ctx);
    }
    uint32_t *map = NULL;
    struct scene_object *object = NULL;
    if (!rec->out_of_memory) {
        object = scene_objects_get_or_create(&ctx->scene.objects, rec->name);
        map = rt_calloc(scene_list_segment_count(rec), sizeof(*map));
        if (!object || !map)
            rt_error(ctx, RT_OUT_OF_MEMORY, "%s: out of memory creating list %u", caller,
                     rec->name);
    }
    struct scene_mesh *meshes = NULL;
    struct scene_list_op *ops = NULL;
    uint32_t count = 0, op_count = 0;
    int reported = rec->out_of_memory || !object || !map;
    if (rec->out_of_memory || !object || !map ||
        scene_list_finish(rec, &meshes, &count, &ops, &op_count, map) ||
        scene_define_list(&ctx->scene, object, meshes, count, ops, op_count)) {
        /* The error was recorded where memory ran out; the incomplete
         * definition is dropped and the old one stays. */
        if (!reported)
            rt_error(ctx, RT_OUT_OF_MEMORY, "%s: out of memory defining list %u", caller,
                     rec->name);
        scene_list_release(rec);
        scene_mesh_release(&rec->mesh);
        rt_free(map);
        return;
    }
    /* The definition's acceleration hint, read now and not at the (lazy)
     * build: the mode current when the object was defined, as a GL
     * display list keeps the state it was compiled with. */
    object->acceleration_hint = ctx->acceleration_hint;
    for (uint32_t i = 0; i < object->segment_count; i++)
        object->segments[i]->acceleration_hint = ctx->acceleration_hint;
    if (ctx->list_mode == RT_COMPILE_AND_EXECUTE)
        for (uint32_t i = 0; i < ctx->exec_count; i++) {
            const struct list_exec *e = &ctx->exec[i];
            if (map[e->segment] != UINT32_MAX)
                instance_segment(ctx, caller, scene_list_segment(object, map[e->segment]), e->m,
                                 &e->appearance);
        }
    ctx->exec_count = 0;
    rt_free(map);
}

void rtEndList(void)
{
    end_list("rtEndList");
}

void rtEndObject(void)
{
    end_list("rtEndObject");
}

void rtCallList(RTuint list)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx) /* allowed between rtBegin and rtEnd, as glCallList */
        return;
    call(ctx, "rtCallList", list, 0);
}

void rtInstantiateObject(RTuint name)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtInstantiateObject"))
        return;
    call(ctx, "rtInstantiateObject", name, 0);
}

/* Element k of the array of rtCallLists as GL reads it. */
static RTuint list_id(RTenum type, const void *lists, RTsizei k)
{
    const unsigned char *b = lists;
    switch (type) {
    case RT_BYTE:
        return (RTuint)(RTint)((const signed char *)lists)[k];
    case RT_UNSIGNED_BYTE:
        return b[k];
    case RT_SHORT:
        return (RTuint)(RTint)((const short *)lists)[k];
    case RT_UNSIGNED_SHORT:
        return ((const unsigned short *)lists)[k];
    case RT_INT:
        return (RTuint)((const int *)lists)[k];
    case RT_UNSIGNED_INT:
        return ((const unsigned int *)lists)[k];
    case RT_FLOAT:
        return (RTuint)(RTint)((const float *)lists)[k];
    case RT_2_BYTES:
        return (RTuint)b[2 * k] * 256u + b[2 * k + 1];
    case RT_3_BYTES:
        return ((RTuint)b[3 * k] * 256u + b[3 * k + 1]) * 256u + b[3 * k + 2];
    default: /* RT_4_BYTES */
        return (((RTuint)b[4 * k] * 256u + b[4 * k + 1]) * 256u + b[4 * k + 2]) * 256u +
               b[4 * k + 3];
    }
}

void rtCallLists(RTsizei n, RTenum type, const void *lists)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx) /* allowed between rtBegin and rtEnd, as glCallList */
        return;
    switch (type) {
    case RT_BYTE:
    case RT_UNSIGNED_BYTE:
    case RT_SHORT:
    case RT_UNSIGNED_SHORT:
    case RT_INT:
    case RT_UNSIGNED_INT:
    case RT_FLOAT:
    case RT_2_BYTES:
    case RT_3_BYTES:
    case RT_4_BYTES:
        break;
    default:
        rt_error(ctx, RT_INVALID_ENUM, "rtCallLists(type=0x%x)", type);
        return;
    }
    if (n < 0) {
        rt_error(ctx, RT_INVALID_VALUE, "rtCallLists(n=%d)", n);
        return;
    }
    if (!lists)
        return; /* nothing to call (Mesa) */
    for (RTsizei k = 0; k < n; k++)
        call(ctx, "rtCallLists", list_id(type, lists, k), 1);
}

void rtListBase(RTuint base)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtListBase"))
        return;
    const float none = 0.0f;
    rt_list_state(ctx, LIST_LIST_BASE, base, 0, &none, 0);
    ctx->list_base = base;
}

RTuint rtGenLists(RTsizei range)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtGenLists"))
        return 0;
    if (range < 0) {
        rt_error(ctx, RT_INVALID_VALUE, "rtGenLists(range=%d)", range);
        return 0;
    }
    if (range == 0)
        return 0;
    /* The first block of `range` unused names (Mesa's
     * _mesa_HashFindFreeKeyBlock), then each reserved as glGenLists
     * creates empty lists. */
    const struct scene_objects *table = &ctx->scene.objects;
    uint64_t base = 1;
    for (uint64_t k = 0; k < (uint64_t)range;) {
        if (base + (uint64_t)range - 1 > UINT32_MAX)
            return 0; /* no block left: GL returns 0 */
        if (scene_objects_lookup(table, (uint32_t)(base + k))) {
            base = base + k + 1;
            k = 0;
        } else {
            k++;
        }
    }
    for (RTsizei k = 0; k < range; k++)
        if (!scene_objects_get_or_create(&ctx->scene.objects, (uint32_t)base + (uint32_t)k)) {
            for (RTsizei j = 0; j < k; j++)
                scene_delete_object(&ctx->scene, (uint32_t)base + (uint32_t)j);
            rt_error(ctx, RT_OUT_OF_MEMORY, "rtGenLists(range=%d): out of memory", range);
            return 0;
        }
    return (RTuint)base;
}

void rtDeleteLists(RTuint list, RTsizei range)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtDeleteLists"))
        return;
    if (range < 0) {
        rt_error(ctx, RT_INVALID_VALUE, "rtDeleteLists(list=%u, range=%d)", list, range);
        return;
    }
    for (uint64_t k = 0; k < (uint64_t)range && (uint64_t)list + k <= UINT32_MAX; k++)
        if (list + k != 0)
            scene_delete_object(&ctx->scene, (uint32_t)(list + k));
}

RTboolean rtIsList(RTuint list)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtIsList"))
        return RT_FALSE;
    /* As Mesa: names reserved by rtGenLists are (empty) lists. */
    return list && scene_objects_lookup(&ctx->scene.objects, list) ? RT_TRUE : RT_FALSE;
}
