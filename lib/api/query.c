/* SPDX-License-Identifier: Apache-2.0 */
/*
 * query.c - rtTraceRays and rtOccludedRays: batches of rays against the
 * current scene, through the same traversal that renders frames.
 */
#include <math.h>
#include <stddef.h>
#include <string.h>

#if defined(__SSE2__) && !defined(RT_NO_SIMD)
#include <emmintrin.h>
#endif

#include "api/context.h"
#include "base/timer.h"

/* Validates a batch; returns 1 when every ray is usable. */
/* 1 when org and dir are finite, dir is not zero, tmin is not NaN and
 * not below 0 (-0.0 is not), and tmax is not NaN. */
static unsigned ray_valid(const RTray *r)
{
    int finite = 1;
    for (int k = 0; k < 3; k++)
        finite &= isfinite(r->org[k]) && isfinite(r->dir[k]);
    const int zero = r->dir[0] == 0.0f && r->dir[1] == 0.0f && r->dir[2] == 0.0f;
    return finite && !zero && !isnan(r->tmin) && !isnan(r->tmax) && !(r->tmin < 0.0f);
}

#if defined(__SSE2__) && !defined(RT_NO_SIMD)
/* Whether every ray of rays[0..count) is valid (ray_valid), on the bits
 * in SSE2 lanes without a branch a ray: a magnitude (the sign bit
 * cleared, so a signed compare is an unsigned one) above the infinity's
 * bits is a NaN, at them an infinity; a tmin below 0 has its sign bit
 * set and is not -0.0.  About 20 instructions a ray where ray_valid's
 * compares took 50. */
static int rays_all_valid(const RTray *rays, RTsizei count)
{
    const __m128i magnitude = _mm_set1_epi32(0x7fffffff);
    const __m128i sign = _mm_set1_epi32((int)0x80000000u);
    /* org and dir: bad above the largest finite magnitude; tmax (the
     * second register's lane 3): bad above the infinity. */
    const __m128i finite_max = _mm_set1_epi32(0x7f7fffff);
    const __m128i limit_b = _mm_setr_epi32(0x7f7fffff, 0x7f7fffff, 0x7f7fffff, 0x7f800000);
    const __m128i lanes_012 = _mm_setr_epi32(-1, -1, -1, 0);
    __m128i bad = _mm_setzero_si128();
    unsigned zero_dir = 0;
    for (RTsizei i = 0; i < count; i++) {
        const __m128i a = _mm_loadu_si128((const __m128i *)(const void *)rays[i].org);
        const __m128i b = _mm_loadu_si128((const __m128i *)(const void *)rays[i].dir);
        const __m128i ma = _mm_and_si128(a, magnitude), mb = _mm_and_si128(b, magnitude);
        /* Lanes 0-2: org and dir; lane 3 of a: tmin, NaN or below 0. */
        const __m128i tmin_bad = _mm_or_si128(
            _mm_cmpgt_epi32(ma, _mm_set1_epi32(0x7f800000)),
            _mm_andnot_si128(_mm_cmpeq_epi32(a, sign), _mm_cmplt_epi32(a, _mm_setzero_si128())));
        bad = _mm_or_si128(bad, _mm_and_si128(_mm_cmpgt_epi32(ma, finite_max), lanes_012));
        bad = _mm_or_si128(bad, _mm_andnot_si128(lanes_012, tmin_bad));
        bad = _mm_or_si128(bad, _mm_cmpgt_epi32(mb, limit_b));
        /* dir zero: lanes 0-2 of mb zero (lane 3 cleared, so equal too). */
        zero_dir |= _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(
                        _mm_and_si128(mb, lanes_012), _mm_setzero_si128()))) == 15;
    }
    return _mm_movemask_ps(_mm_castsi128_ps(bad)) == 0 && !zero_dir;
}
#else
static int rays_all_valid(const RTray *rays, RTsizei count)
{
    unsigned all_valid = 1;
    for (RTsizei i = 0; i < count; i++)
        all_valid &= ray_valid(&rays[i]);
    return (int)all_valid;
}
#endif

typedef char ray_valid_layout[sizeof(RTray) == 8 * sizeof(float) &&
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
     * tests without a branch a ray, the first failing ray looked for only
     * when there is one. */
    if (rays_all_valid(rays, count))
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
