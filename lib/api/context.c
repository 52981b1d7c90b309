/* SPDX-License-Identifier: Apache-2.0 */
/*
 * context.c - rtCreateContext, rtDestroyContext, rtMakeCurrent and the
 * per-thread current context.
 *
 * The current-context pointer is the one piece of per-thread state of the
 * library (as in OpenGL); everything else lives in struct rt_context.
 */
#include <ctype.h>
#include <stdarg.h>
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

/*
 * The configuration string (grammar in docs/context.md):
 *   configuration = [ws] [item {sep item}] [ws]
 *   sep           = [ws] "," [ws] | ws
 *   item          = key "=" value         (no blank around "=")
 *   ws            = one or more of space, tab, CR, LF
 * A key may appear once; integers are decimal without sign or leading
 * zero.  Every rejection says why in `reason`, which rtCreateContext
 * cannot record as an error: there is no context yet.
 */
static int config_fail(char *reason, size_t size, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

static int config_fail(char *reason, size_t size, const char *fmt, ...)
{
    if (reason && size > 0) {
        va_list args;
        va_start(args, fmt);
        vsnprintf(reason, size, fmt, args);
        va_end(args);
    }
    return -1;
}

static int config_space(char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

/* Parses a decimal integer in [lo, hi]; returns 0 on success. */
static int parse_int(const char *s, size_t len, int lo, int hi, int *out)
{
    if (len == 0 || len > 9 || (len > 1 && s[0] == '0'))
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

/* Applies the items of `config`; returns 0, or -1 with the reason. */
static int parse_configuration(struct rt_context *ctx, const char *config, char *reason,
                               size_t reason_size)
{
    static const char *const keys[] = {"threads", "toplevel", "build_threads", "bins",
                                       "builder", "isa", "packets", "flatten", "stream"};
    enum { KEY_COUNT = sizeof keys / sizeof keys[0] };
    int seen[KEY_COUNT] = {0};
    const char *p = config;
    int need_item = 0; /* after a comma: an item must follow */
    int item_number = 0;
    while (p && *p) {
        while (config_space(*p))
            p++;
        if (!*p)
            break;
        if (*p == ',')
            return config_fail(reason, reason_size,
                               "item %d is empty (a comma with no key=value before it)",
                               item_number + 1);
        const char *key = p;
        while (*p && *p != '=' && *p != ',' && !config_space(*p))
            p++;
        size_t key_len = (size_t)(p - key);
        if (*p != '=')
            return config_fail(reason, reason_size, "'%.*s' is not key=value", (int)key_len,
                               key);
        const char *value = ++p;
        while (*p && *p != ',' && !config_space(*p))
            p++;
        size_t value_len = (size_t)(p - value);
        item_number++;
        need_item = 0;
        int k;
        for (k = 0; k < KEY_COUNT; k++)
            if (key_is(key, key_len, keys[k]))
                break;
        if (k == KEY_COUNT)
            return config_fail(reason, reason_size, "unknown key '%.*s'", (int)key_len, key);
        if (seen[k]++)
            return config_fail(reason, reason_size, "key '%s' is given twice", keys[k]);
        int bad = 0, lo = 0, hi = 0;
        const char *expect = NULL;
        switch (k) {
        case 0:
            lo = 1, hi = API_MAX_THREADS;
            bad = parse_int(value, value_len, lo, hi, &ctx->threads);
            break;
        case 1:
            if (key_is(value, value_len, "binned"))
                ctx->toplevel_cellsplit = 0;
            else if (key_is(value, value_len, "cellsplit"))
                ctx->toplevel_cellsplit = 1;
            else
                bad = 1, expect = "binned or cellsplit";
            break;
        case 2:
            lo = 0, hi = API_MAX_THREADS;
            bad = parse_int(value, value_len, lo, hi, &ctx->build_threads);
            break;
        case 3:
            lo = 2, hi = BVH_MAX_BINS;
            bad = parse_int(value, value_len, lo, hi, &ctx->build_params.bins);
            break;
        case 5: {
            /* auto: the best this CPU runs; a named ISA this build or
             * CPU lacks is refused (it would not run). */
            enum trace_isa isa;
            if (key_is(value, value_len, "auto"))
                ctx->kernels = trace_kernels_best();
            else if (trace_isa_parse(value, value_len, &isa))
                bad = 1, expect = "auto, scalar, sse4, avx2 or avx512";
            else if (!(ctx->kernels = trace_kernels_get(isa)))
                return config_fail(reason, reason_size,
                                   "isa='%.*s': this build or this CPU cannot run it",
                                   (int)value_len, value);
            break;
        }
        case 6:
            if (key_is(value, value_len, "on"))
                ctx->packets_off = 0;
            else if (key_is(value, value_len, "off"))
                ctx->packets_off = 1;
            else
                bad = 1, expect = "on or off";
            break;
        case 7:
            /* Nested static hierarchies: flattened, instanced, or as the
             * cost model says (scene/flatten.h). */
            if (key_is(value, value_len, "auto"))
                ctx->flatten_mode = SCENE_FLATTEN_AUTO;
            else if (key_is(value, value_len, "on"))
                ctx->flatten_mode = SCENE_FLATTEN_ON;
            else if (key_is(value, value_len, "off"))
                ctx->flatten_mode = SCENE_FLATTEN_OFF;
            else
                bad = 1, expect = "auto, on or off";
            break;
        case 8:
            /* The stream walk for a query's incoherent rays
             * (trace/scene_stream.h): where the layouts say it pays,
             * everywhere it can, or never. */
            if (key_is(value, value_len, "auto"))
                ctx->stream_mode = RT_STREAM_AUTO;
            else if (key_is(value, value_len, "on"))
                ctx->stream_mode = RT_STREAM_ON;
            else if (key_is(value, value_len, "off"))
                ctx->stream_mode = RT_STREAM_OFF;
            else
                bad = 1, expect = "auto, on or off";
            break;
        default:
            if (key_is(value, value_len, "binned"))
                ctx->build_params.builder = BVH_BUILDER_BINNED_SAH;
            else if (key_is(value, value_len, "sweep"))
                ctx->build_params.builder = BVH_BUILDER_SWEEP_SAH;
            else
                bad = 1, expect = "binned or sweep";
            break;
        }
        if (bad && expect)
            return config_fail(reason, reason_size, "%s='%.*s': the value must be %s", keys[k],
                               (int)value_len, value, expect);
        if (bad)
            return config_fail(reason, reason_size,
                               "%s='%.*s': the value must be a decimal integer in [%d, %d] "
                               "without sign or leading zero",
                               keys[k], (int)value_len, value, lo, hi);
        /* The separator: blanks, or one comma with blanks around it. */
        while (config_space(*p))
            p++;
        if (*p == ',') {
            p++;
            need_item = 1;
            while (config_space(*p))
                p++;
        }
    }
    if (need_item)
        return config_fail(reason, reason_size,
                           "item %d is empty (a comma with no key=value after it)",
                           item_number + 1);
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
    r->shading = RENDER_FIXED_FUNCTION; /* GL's look (docs/appearance.md) */
    r->max_depth = 3; /* Wald, Benthin and Slusallek (2003) tables 1 and 2: three reflection levels */
    r->clear_color[3] = 0.0f;
    for (int k = 0; k < 3; k++)
        r->global_ambient[k] = 0.2f;
    r->global_ambient[3] = 1.0f;
    for (int i = 0; i < RENDER_MAX_LIGHTS; i++) {
        struct scene_light *l = &r->lights[i];
        l->ambient[3] = 1.0f;
        /* OpenGL: light 0 is white, the others black. */
        float d = i == 0 ? 1.0f : 0.0f;
        for (int k = 0; k < 3; k++)
            l->diffuse[k] = l->specular[k] = d;
        l->diffuse[3] = l->specular[3] = 1.0f;
        l->position[2] = 1.0f; /* (0, 0, 1, 0): directional, towards +z */
        l->attenuation[0] = 1.0f;
        l->spot_direction[2] = -1.0f;
        l->spot_cutoff = 180.0f;
    }
    r->fog.mode = RT_EXP;
    r->fog.density = 1.0f;
    r->fog.end = 1.0f;
    mat4_identity(r->projection);
    r->vis.line_width = 1.0f;
    r->vis.point_size = 1.0f;
    r->vis.blend_src = RT_ONE;
    r->vis.blend_dst = RT_ZERO;
    r->vis.depth_mask = 1;
    r->vis.alpha_func = RT_ALWAYS;
}

RTcontext rtCreateContext(const char *configuration)
{
    char reason[RT_REASON_SIZE];
    RTcontext ctx = rtCreateContextWithReason(configuration, (RTsizei)sizeof reason, reason);
    /* Nothing is stored to read later (no state outside a context): the
     * reason goes to stderr under TRACELIST_DEBUG, as errors do, and
     * rtCreateContextWithReason hands it to the caller. */
    const char *debug = getenv("TRACELIST_DEBUG");
    if (!ctx && debug && *debug && strcmp(debug, "0") != 0)
        fprintf(stderr, "tracelist: rtCreateContext: %s\n", reason);
    return ctx;
}

RTcontext rtCreateContextWithReason(const char *configuration, RTsizei bufSize, char *reason)
{
    size_t reason_size = bufSize > 0 && reason ? (size_t)bufSize : 0;
    if (reason_size)
        reason[0] = '\0';
    struct rt_context *ctx = rt_calloc(1, sizeof(*ctx));
    if (!ctx) {
        config_fail(reason, reason_size, "out of memory");
        return NULL;
    }
    ctx->threads = online_cpus();
    ctx->build_threads = 1; /* Wald, Ize and Parker (2008) sec. 6: K set by the application */
    bvh_build_params_default(&ctx->build_params);
    ctx->acceleration_hint = RT_DONT_CARE;
    ctx->kernels = trace_kernels_best();
    if (parse_configuration(ctx, configuration, reason, reason_size)) {
        rt_free(ctx);
        return NULL;
    }
    ctx->build_params.wide_layout = (int)ctx->kernels->wide_width;
    /* packets=: the context's own copy of its table, without the packet
     * walks when off (every trace then goes ray by ray); "off" is
     * reported for a table that has none (isa=scalar). */
    ctx->kernel_table = *ctx->kernels;
    if (ctx->packets_off) {
        ctx->kernel_table.closest_packet = NULL;
        ctx->kernel_table.any_packet = NULL;
        ctx->kernel_table.closest_packet_arrays = NULL;
        ctx->kernel_table.any_packet_arrays = NULL;
    }
    /* stream=off: likewise without the stream walks; "off" is reported
     * for a table that has none (scalar, sse4). */
    if (ctx->stream_mode == RT_STREAM_OFF || !ctx->kernel_table.stream_counted) {
        ctx->stream_mode = RT_STREAM_OFF;
        ctx->kernel_table.stream_pair = NULL;
        ctx->kernel_table.stream_counted = NULL;
    }
    ctx->kernels = &ctx->kernel_table;
    snprintf(ctx->configuration, sizeof(ctx->configuration),
             "threads=%d build_threads=%d bins=%d builder=%s toplevel=%s isa=%s packets=%s "
             "flatten=%s stream=%s",
             ctx->threads, ctx->build_threads, ctx->build_params.bins,
             ctx->build_params.builder == BVH_BUILDER_SWEEP_SAH ? "sweep" : "binned",
             ctx->toplevel_cellsplit ? "cellsplit" : "binned", ctx->kernels->name,
             ctx->kernels->closest_packet ? "on" : "off",
             ctx->flatten_mode == SCENE_FLATTEN_ON    ? "on"
             : ctx->flatten_mode == SCENE_FLATTEN_OFF ? "off"
                                                      : "auto",
             ctx->stream_mode == RT_STREAM_ON    ? "on"
             : ctx->stream_mode == RT_STREAM_OFF ? "off"
                                                 : "auto");
    const char *debug = getenv("TRACELIST_DEBUG");
    ctx->debug_print = debug && *debug && strcmp(debug, "0") != 0;

    ctx->matrix_mode = RT_MODELVIEW;
    matrix_stack_init(&ctx->modelview, API_MAX_MODELVIEW_DEPTH);
    matrix_stack_init(&ctx->projection, API_MAX_PROJECTION_DEPTH);
    ctx->current_normal[2] = 1.0f;
    for (int k = 0; k < 4; k++)
        ctx->current_color[k] = 1.0f;
    ctx->current_texcoord[3] = 1.0f; /* GL's initial (0, 0, 0, 1) */
    ctx->shade_model = RT_SMOOTH;
    /* GL's initial raster position: (0, 0, 0, 1), valid, white. */
    ctx->raster_pos[3] = 1.0f;
    ctx->raster_valid = 1;
    for (int k = 0; k < 4; k++)
        ctx->raster_color[k] = 1.0f;
    ctx->polygon_mode[0] = ctx->polygon_mode[1] = RT_FILL;
    scene_material_default(&ctx->material);
    ctx->recording.mesh.bounds = aabb_empty();
    scene_init(&ctx->scene, &ctx->build_params, ctx->build_threads, ctx->toplevel_cellsplit);
    ctx->scene.frame.flats.mode = (enum scene_flatten_mode)ctx->flatten_mode;
    render_state_init(&ctx->render);
    ctx->cull_face_mode = RT_BACK;
    ctx->dither = 1; /* GL's default */
    /* GL's initial planes: s (1, 0, 0, 0), t (0, 1, 0, 0), q and r zero. */
    for (int i = 0; i < RT_TEXGEN_COORDS; i++) {
        ctx->texgen_mode[i] = RT_EYE_LINEAR;
        if (i < 2)
            ctx->texgen_object_plane[i][i] = ctx->texgen_eye_plane[i][i] = 1.0f;
    }
    ctx->unpack.alignment = ctx->pack.alignment = 4; /* GL's default (pixel_store.c) */
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
    scene_list_release(&ctx->recording);
    rt_free(ctx->exec);
    render_framebuffer_release(&ctx->render.fb);
    render_overlay_release(&ctx->overlay);
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
