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
#include "base/atomic.h"
#include "base/mat4.h"

static RT_THREAD_LOCAL struct rt_context *current_context;

struct rt_context *rt_current_context(void)
{
    return current_context;
}

static int online_cpus(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    if (n < 1)
        return 1;
    return n > API_MAX_THREADS ? API_MAX_THREADS : (int)n;
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
            if (parse_int(value, value_len, 1, API_MAX_THREADS, &ctx->threads))
                return -1;
        } else if (key_is(key, key_len, "toplevel")) {
            if (key_is(value, value_len, "binned"))
                ctx->toplevel_cellsplit = 0;
            else if (key_is(value, value_len, "cellsplit"))
                ctx->toplevel_cellsplit = 1;
            else
                return -1;
        } else if (key_is(key, key_len, "build_threads")) {
            if (parse_int(value, value_len, 0, API_MAX_THREADS, &ctx->build_threads))
                return -1;
        } else if (key_is(key, key_len, "bins")) {
            if (parse_int(value, value_len, 2, BVH_MAX_BINS, &ctx->build_params.bins))
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
    if (parse_configuration(ctx, configuration)) {
        rt_free(ctx);
        return NULL;
    }
    snprintf(ctx->configuration, sizeof(ctx->configuration),
             "threads=%d build_threads=%d bins=%d builder=%s toplevel=%s", ctx->threads,
             ctx->build_threads, ctx->build_params.bins,
             ctx->build_params.builder == BVH_BUILDER_SWEEP_SAH ? "sweep" : "binned",
             ctx->toplevel_cellsplit ? "cellsplit" : "binned");
    const char *debug = getenv("TRACELIST_DEBUG");
    ctx->debug_print = debug && *debug && strcmp(debug, "0") != 0;

    ctx->matrix_mode = RT_MODELVIEW;
    matrix_stack_init(&ctx->modelview, API_MAX_MODELVIEW_DEPTH);
    matrix_stack_init(&ctx->projection, API_MAX_PROJECTION_DEPTH);
    ctx->current_normal[2] = 1.0f;
    for (int k = 0; k < 4; k++)
        ctx->current_color[k] = 1.0f;
    ctx->shade_model = RT_SMOOTH;
    scene_material_default(&ctx->material);
    ctx->recording.mesh.bounds = aabb_empty();
    scene_init(&ctx->scene, &ctx->build_params, ctx->build_threads, ctx->toplevel_cellsplit);
    render_state_init(&ctx->render);
    return ctx;
}

void rtDestroyContext(RTcontext ctx)
{
    if (!ctx)
        return;
    /* Destroying a context another thread has current would leave that
     * thread with a dangling pointer: refuse, as documented. */
    if (current_context != ctx && rt_atomic_load_acquire(&ctx->bound))
        return;
    if (current_context == ctx)
        current_context = NULL;
    rt_pool_destroy(ctx->pool);
    scene_release(&ctx->scene);
    scene_mesh_release(&ctx->recording.mesh);
    render_framebuffer_release(&ctx->render.fb);
    rt_free(ctx);
}

RTboolean rtMakeCurrent(RTcontext ctx)
{
    if (ctx == current_context)
        return RT_TRUE;
    /* A context is current in at most one thread (as a GL context). */
    if (ctx && rt_atomic_exchange_acq_rel(&ctx->bound, 1))
        return RT_FALSE;
    if (current_context)
        rt_atomic_store_release(&current_context->bound, 0);
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
