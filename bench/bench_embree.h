/* SPDX-License-Identifier: Apache-2.0 */
/*
 * bench_embree.h - what the Embree paths of rtbench share (bench_embree.c,
 * bench_dynamic.c, bench_error.c; only with RT_HAVE_EMBREE): our RTray as
 * Embree's single ray, and the device's error callback.
 *
 * Inline on purpose: the ray set-up runs once per ray inside the timed
 * Embree loops, where a call into another file would add to Embree's
 * figure and not to ours.
 */
#ifndef RT_BENCH_BENCH_EMBREE_H
#define RT_BENCH_BENCH_EMBREE_H

#include <embree3/rtcore.h>

#include "bench.h"

/* Embree's ray for r, the same query as ours: origin, direction (not
 * normalised) and the interval (tnear = tmin, tfar = tmax); time 0, every
 * mask bit, no id or flags.  For rtcOccluded1. */
static inline void bench_embree_ray(const RTray *r, struct RTCRay *ray)
{
    ray->org_x = r->org[0];
    ray->org_y = r->org[1];
    ray->org_z = r->org[2];
    ray->tnear = r->tmin;
    ray->dir_x = r->dir[0];
    ray->dir_y = r->dir[1];
    ray->dir_z = r->dir[2];
    ray->time = 0.0f;
    ray->tfar = r->tmax;
    ray->mask = 0xFFFFFFFFu;
    ray->id = 0;
    ray->flags = 0;
}

/* bench_embree_ray with no hit yet (geometry, primitive and instance
 * invalid), as rtcIntersect1 requires. */
static inline void bench_embree_ray_hit(const RTray *r, struct RTCRayHit *rh)
{
    bench_embree_ray(r, &rh->ray);
    rh->hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh->hit.primID = RTC_INVALID_GEOMETRY_ID;
    rh->hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
}

/* rtcSetDeviceErrorFunction's callback: Embree's error on the progress
 * stream (the report itself stays clean). */
static inline void bench_embree_error(void *user, enum RTCError code, const char *message)
{
    (void)user;
    report_progress("rtbench: Embree error %d: %s\n", (int)code, message ? message : "");
}

#endif
