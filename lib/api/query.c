/* SPDX-License-Identifier: Apache-2.0 */
/*
 * query.c - rtTraceRays and rtOccludedRays: batches of rays against the
 * current scene, through the same traversal that renders frames.
 */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "api/context.h"
#include "base/timer.h"

/* Validates a batch; returns 1 when every ray is usable. */
/* 1 when org and dir are finite, dir is not zero, tmin is not NaN and
 * not below 0 (-0.0 is not), and tmax is not NaN; read as bits: a float
 * is finite when its magnitude's bits are below the infinity's, NaN when
 * above, and a tmin of at most the bits of +infinity or exactly those of
 * -0.0 is a number >= 0. */
static unsigned ray_valid(const RTray *r)
{
    uint32_t w[8];
    memcpy(w, r, sizeof(w)); /* org[3], tmin, dir[3], tmax (rt.h) */
    const uint32_t magnitude = 0x7fffffffu, inf = 0x7f800000u;
    unsigned ok = ((w[0] & magnitude) < inf) & ((w[1] & magnitude) < inf) &
                  ((w[2] & magnitude) < inf) & ((w[4] & magnitude) < inf) &
                  ((w[5] & magnitude) < inf) & ((w[6] & magnitude) < inf);
    ok &= ((w[4] | w[5] | w[6]) & magnitude) != 0u;
    ok &= (w[3] <= inf) | (w[3] == 0x80000000u);
    ok &= (w[7] & magnitude) <= inf;
    return ok;
}

typedef char ray_valid_layout[sizeof(RTray) == 8 * sizeof(uint32_t) &&
                                      offsetof(RTray, tmin) == 3 * sizeof(float) &&
                                      offsetof(RTray, dir) == 4 * sizeof(float)
                                  ? 1
                                  : -1];

static int rays_valid(struct rt_context *ctx, const char *caller, RTsizei count,
                      const RTray *rays, const void *out)
{
    if (count < 0 || (count > 0 && (!rays || !out))) {
        rt_error(ctx, RT_INVALID_VALUE, "%s(count=%d, rays=%p, results=%p)", caller, count,
                 (const void *)rays, out);
        return 0;
    }
    /* A pass over every ray before any is traced (an invalid ray anywhere
     * leaves every result as it was), on the calling thread alone: the
     * tests on the bits, without branches, the first failing ray looked
     * for only when there is one. */
    unsigned all_valid = 1;
    for (RTsizei i = 0; i < count; i++)
        all_valid &= ray_valid(&rays[i]);
    if (all_valid)
        return 1;
    for (RTsizei i = 0; i < count; i++) {
        if (!ray_valid(&rays[i])) {
            rt_error(ctx, RT_INVALID_VALUE,
                     "%s: ray %d is invalid (org and dir must be finite, dir non-zero, "
                     "0 <= tmin, tmax not NaN)",
                     caller, i);
            return 0;
        }
    }
    return 1;
}

static int begin_queries(struct rt_context *ctx, const char *caller, RTsizei count,
                         const RTray *rays, const void *out, struct render_job *job)
{
    if (rt_check_outside_object(ctx, caller) || !rays_valid(ctx, caller, count, rays, out))
        return -1;
    memset(&ctx->stats, 0, sizeof(ctx->stats));
    if (rt_prepare_scene(ctx, caller))
        return -1;
    rt_render_job(ctx, job);
    return 0;
}

void rtTraceRays(RTsizei count, const RTray *rays, RThit *hits)
{
    GET_CURRENT_CONTEXT(ctx);
    struct render_job job;
    if (!ctx || begin_queries(ctx, "rtTraceRays", count, rays, hits, &job))
        return;
    double start = rt_now_ms();
    if (render_trace_rays(&job, count, rays, hits, &ctx->stats))
        rt_error(ctx, RT_OUT_OF_MEMORY, "rtTraceRays: out of memory building an object");
    ctx->stats.render_ms = rt_now_ms() - start;
}

void rtOccludedRays(RTsizei count, const RTray *rays, RTboolean *occluded)
{
    GET_CURRENT_CONTEXT(ctx);
    struct render_job job;
    if (!ctx || begin_queries(ctx, "rtOccludedRays", count, rays, occluded, &job))
        return;
    double start = rt_now_ms();
    if (render_occluded_rays(&job, count, rays, occluded, &ctx->stats))
        rt_error(ctx, RT_OUT_OF_MEMORY, "rtOccludedRays: out of memory building an object");
    ctx->stats.render_ms = rt_now_ms() - start;
}
