/*
 * context.c - rtCreateContext, rtDestroyContext, rtMakeCurrent and the
 * per-thread current context.
 *
 * The current-context pointer is the one piece of per-thread state of the
 * library (as in OpenGL); everything else lives in struct rt_context.
 */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "api/context.h"
#include "base/alloc.h"
#include "base/mat4.h"

static __thread struct rt_context *current_context;

struct rt_context *rt_current_context(void)
{
    return current_context;
}

static int online_cpus(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    if (n < 1)
        return 1;
    return n > RT_MAX_THREADS ? RT_MAX_THREADS : (int)n;
}

/* Parses a decimal integer in [lo, hi]; returns 0 on success. */
static int parse_int(const char *s, size_t len, int lo, int hi, int *out)
{
    if (len == 0 || len > 9)
        return -1;
    int v = 0;
    for (size_t i = 0; i < len; i++) {
        if (!isdigit((unsigned char)s[i]))
            return -1;
        v = v * 10 + (s[i] - '0');
    }
    if (v < lo || v > hi)
        return -1;
    *out = v;
    return 0;
}

static int key_is(const char *key, size_t len, const char *name)
{
    return strlen(name) == len && memcmp(key, name, len) == 0;
}

/* Applies "key=value" pairs separated by spaces or commas; returns 0, or
 * -1 on an unknown key or bad value. */
static int parse_configuration(struct rt_context *ctx, const char *config)
{
    const char *p = config;
    while (p && *p) {
        while (*p == ' ' || *p == ',' || *p == '\t')
            p++;
        if (!*p)
            break;
        const char *key = p;
        while (*p && *p != '=' && *p != ' ' && *p != ',')
            p++;
        if (*p != '=')
            return -1;
        size_t key_len = (size_t)(p - key);
        const char *value = ++p;
        while (*p && *p != ' ' && *p != ',' && *p != '\t')
            p++;
        size_t value_len = (size_t)(p - value);
        if (key_is(key, key_len, "threads")) {
            if (parse_int(value, value_len, 1, RT_MAX_THREADS, &ctx->threads))
                return -1;
        } else if (key_is(key, key_len, "toplevel")) {
            if (key_is(value, value_len, "binned"))
                ctx->toplevel_paper004 = 0;
            else if (key_is(value, value_len, "paper004"))
                ctx->toplevel_paper004 = 1;
            else
                return -1;
        } else if (key_is(key, key_len, "build_threads")) {
            if (parse_int(value, value_len, 0, RT_MAX_THREADS, &ctx->build_threads))
                return -1;
        } else if (key_is(key, key_len, "bins")) {
            if (parse_int(value, value_len, 2, BVH_MAX_BINS, &ctx->build_params.bins))
                return -1;
        } else if (key_is(key, key_len, "isa")) {
            /* auto: the best this CPU runs; a named ISA this build or
             * CPU lacks is refused (it would not run). */
            enum trace_isa isa;
            if (key_is(value, value_len, "auto"))
                ctx->kernels = trace_kernels_best();
            else if (trace_isa_parse(value, value_len, &isa) ||
                     !(ctx->kernels = trace_kernels_get(isa)))
                return -1;
        } else if (key_is(key, key_len, "builder")) {
            if (key_is(value, value_len, "binned"))
                ctx->build_params.builder = BVH_BUILDER_BINNED_SAH;
            else if (key_is(value, value_len, "sweep"))
                ctx->build_params.builder = BVH_BUILDER_SWEEP_SAH;
            else
                return -1;
        } else {
            return -1;
        }
    }
    return 0;
}

static void matrix_stack_init(struct matrix_stack *s, int max_depth)
{
    s->depth = 1;
    s->max_depth = max_depth;
    mat4_identity(s->m[0]);
}

static void render_state_init(struct render_state *r)
{
    memset(r, 0, sizeof(*r));
    r->shading = RENDER_EYE_LIGHT;
    r->max_depth = 3; /* paper 004 tables 1 and 2: three reflection levels */
    r->clear_color[3] = 0.0f;
    for (int k = 0; k < 3; k++)
        r->global_ambient[k] = 0.2f;
    r->global_ambient[3] = 1.0f;
    for (int i = 0; i < RENDER_MAX_LIGHTS; i++) {
        struct render_light *l = &r->lights[i];
        l->ambient[3] = 1.0f;
        /* OpenGL: light 0 is white, the others black. */
        float d = i == 0 ? 1.0f : 0.0f;
        for (int k = 0; k < 3; k++)
            l->diffuse[k] = l->specular[k] = d;
        l->diffuse[3] = l->specular[3] = 1.0f;
        l->position[2] = 1.0f; /* (0, 0, 1, 0): directional, towards +z */
        l->attenuation[0] = 1.0f;
    }
    mat4_identity(r->projection);
}

RTcontext rtCreateContext(const char *configuration)
{
    struct rt_context *ctx = rt_calloc(1, sizeof(*ctx));
    if (!ctx)
        return NULL;
    ctx->threads = online_cpus();
    ctx->build_threads = 1; /* paper 000 sec. 6: K set by the application */
    bvh_build_params_default(&ctx->build_params);
    ctx->kernels = trace_kernels_best();
    if (parse_configuration(ctx, configuration)) {
        rt_free(ctx);
        return NULL;
    }
    snprintf(ctx->configuration, sizeof(ctx->configuration),
             "threads=%d build_threads=%d bins=%d builder=%s toplevel=%s isa=%s", ctx->threads,
             ctx->build_threads, ctx->build_params.bins,
             ctx->build_params.builder == BVH_BUILDER_SWEEP_SAH ? "sweep" : "binned",
             ctx->toplevel_paper004 ? "paper004" : "binned", ctx->kernels->name);
    const char *debug = getenv("TRACELIST_DEBUG");
    ctx->debug_print = debug && *debug && strcmp(debug, "0") != 0;

    ctx->default_strategy = RT_AUTOMATIC;
    /* Until a frame has been measured: 5 ns a step, this machine's order
     * of magnitude (bench/rtbench trace). */
    ctx->ms_per_test = 5e-6;
    accel_restructure_params_default(&ctx->restructure_params);
    ctx->matrix_mode = RT_MODELVIEW;
    matrix_stack_init(&ctx->modelview, RT_MAX_MODELVIEW_DEPTH);
    matrix_stack_init(&ctx->projection, RT_MAX_PROJECTION_DEPTH);
    ctx->current_normal[2] = 1.0f;
    for (int k = 0; k < 4; k++)
        ctx->current_color[k] = 1.0f;
    ctx->shade_model = RT_SMOOTH;
    scene_material_default(&ctx->material);
    ctx->recording.mesh.bounds = aabb_empty();
    scene_objects_init(&ctx->objects);
    scene_textures_init(&ctx->textures);
    scene_async_init(&ctx->async, ctx->build_threads, &ctx->build_params);
    scene_frame_init(&ctx->frame);
    ctx->frame.toplevel_paper004 = ctx->toplevel_paper004;
    render_state_init(&ctx->render);
    return ctx;
}

void rtDestroyContext(RTcontext ctx)
{
    if (!ctx)
        return;
    /* Destroying a context another thread has current would leave that
     * thread with a dangling pointer: refuse, as documented. */
    if (current_context != ctx && __atomic_load_n(&ctx->bound, __ATOMIC_ACQUIRE))
        return;
    if (current_context == ctx)
        current_context = NULL;
    rt_pool_destroy(ctx->pool);
    /* Jobs first (their objects go next), then the build thread. */
    for (uint32_t i = 0; i < ctx->objects.table.capacity; i++)
        if (ctx->objects.table.slots[i].name)
            scene_async_cancel(&ctx->async, ctx->objects.table.slots[i].item);
    scene_async_release(&ctx->async);
    scene_mesh_release(&ctx->recording.mesh);
    scene_frame_release(&ctx->frame);
    scene_objects_release(&ctx->objects);
    scene_textures_release(&ctx->textures);
    rt_free(ctx->render.framebuffer);
    rt_free(ctx);
}

RTboolean rtMakeCurrent(RTcontext ctx)
{
    if (ctx == current_context)
        return RT_TRUE;
    /* A context is current in at most one thread (as a GL context). */
    if (ctx && __atomic_exchange_n(&ctx->bound, 1, __ATOMIC_ACQ_REL))
        return RT_FALSE;
    if (current_context)
        __atomic_store_n(&current_context->bound, 0, __ATOMIC_RELEASE);
    current_context = ctx;
    return RT_TRUE;
}

RTcontext rtGetCurrentContext(void)
{
    return current_context;
}

struct rt_pool *rt_context_pool(struct rt_context *ctx)
{
    if (!ctx->pool && ctx->threads > 1)
        ctx->pool = rt_pool_create(ctx->threads);
    return ctx->pool;
}
