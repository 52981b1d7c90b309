/* SPDX-License-Identifier: Apache-2.0 */
/*
 * query.c - rtTraceRays and rtOccludedRays: batches of rays against the
 * current scene, through the same traversal that renders frames.
 */
#include <math.h>
#include <string.h>

#include "api/context.h"
#include "base/timer.h"

/* Validates a batch; returns 1 when every ray is usable. */
static int rays_valid(struct rt_context *ctx, const char *caller, RTsizei count,
                      const RTray *rays, const void *out)
{
    if (count < 0 || (count > 0 && (!rays || !out))) {
        rt_error(ctx, RT_INVALID_VALUE, "%s(count=%d, rays=%p, results=%p)", caller, count,
                 (const void *)rays, out);
        return 0;
    }
    for (RTsizei i = 0; i < count; i++) {
        const RTray *r = &rays[i];
        int finite = 1;
        for (int k = 0; k < 3; k++)
            finite &= isfinite(r->org[k]) && isfinite(r->dir[k]);
        int zero = r->dir[0] == 0.0f && r->dir[1] == 0.0f && r->dir[2] == 0.0f;
        if (!finite || zero || isnan(r->tmin) || isnan(r->tmax) || r->tmin < 0.0f) {
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
