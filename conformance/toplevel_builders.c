/* SPDX-License-Identifier: Apache-2.0 */
/*
 * toplevel_builders.c - the two top-level builders ("toplevel=binned", the
 * default binned SAH over instance boxes, and "toplevel=cellsplit", Wald, Benthin and Slusallek
 * (2003) sec. 4.5's split rule) give bit-identical hits, on scattered,
 * overlapping and coincident instances, and both rebuild only when the
 * instance list changes.
 */
#include "testutil.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define INSTANCES 600
#define RAYS 20000

static unsigned rng = 2024;

static float uniform(void)
{
    rng = rng * 1664525u + 1013904223u;
    return (float)(rng >> 8) / 16777216.0f;
}

/* The same scene in the current context: three objects, INSTANCES
 * instances, a tenth of them stacked on one spot. */
static void build_scene(void)
{
    static const float lo1[3] = {-0.5f, -0.5f, -0.5f}, hi1[3] = {0.5f, 0.5f, 0.5f};
    static const float a[3] = {-1, -1, 0}, b[3] = {1, -1, 0}, c[3] = {0, 1, 0};
    static const float lo3[3] = {-2.0f, -0.1f, -2.0f}, hi3[3] = {2.0f, 0.1f, 2.0f};
    CHECK(tu_define_box(1, lo1, hi1));
    CHECK(tu_define_triangle(2, a, b, c));
    CHECK(tu_define_box(3, lo3, hi3));
    rng = 2024;
    for (int i = 0; i < INSTANCES; i++) {
        rtPushMatrix();
        if (i % 10 == 0) {
            rtTranslatef(1.0f, 1.0f, 1.0f); /* coincident */
        } else {
            rtTranslatef(uniform() * 40 - 20, uniform() * 40 - 20, uniform() * 40 - 20);
            rtRotatef(uniform() * 360, uniform() - 0.5f, uniform() - 0.5f, uniform() - 0.5f);
            rtScalef(0.2f + 2 * uniform(), 0.2f + 2 * uniform(), 0.2f + 2 * uniform());
        }
        rtInstantiateObject((RTuint)(1 + i % 3));
        rtPopMatrix();
    }
}

static void make_rays(RTray *rays)
{
    rng = 77;
    for (int i = 0; i < RAYS; i++) {
        RTray r = {{uniform() * 50 - 25, uniform() * 50 - 25, uniform() * 50 - 25},
                   0.0f,
                   {uniform() - 0.5f, uniform() - 0.5f, uniform() - 0.5f},
                   INFINITY};
        if (i % 4 == 0) { /* axis-parallel */
            r.dir[0] = r.dir[1] = 0.0f;
            r.dir[2] = (i % 8) ? 1.0f : -1.0f;
        }
        rays[i] = r;
    }
}

static RTint geti(RTenum pname)
{
    RTint v = -1;
    rtGetIntegerv(pname, &v);
    return v;
}

static void trace_with(const char *config, const RTray *rays, RThit *hits)
{
    tu_section(config);
    RTcontext ctx = tu_make_context(config);
    CHECK(strstr(rtGetString(RT_CONFIGURATION), strstr(config, "toplevel=")) != NULL);
    build_scene();
    rtTraceRays(RAYS, rays, hits);
    CHECK_NO_ERR();
    CHECK_INT(geti(RT_STAT_TOPLEVEL_BUILDS), 1);
    rtTraceRays(RAYS, rays, hits);
    CHECK_INT(geti(RT_STAT_TOPLEVEL_BUILDS), 0);
    float ms = -1.0f;
    rtGetFloatv(RT_STAT_TOPLEVEL_TIME, &ms);
    CHECK(ms >= 0.0f);
    tu_destroy_context(ctx);
}

int main(void)
{
    static RTray rays[RAYS];
    static RThit binned[RAYS], paper[RAYS];
    make_rays(rays);
    trace_with("threads=2 toplevel=binned", rays, binned);
    trace_with("threads=2 toplevel=cellsplit", rays, paper);
    tu_section("identical hits");
    int differ = 0, hits = 0;
    for (int i = 0; i < RAYS; i++) {
        hits += binned[i].t < INFINITY;
        if (memcmp(&binned[i], &paper[i], sizeof(RThit)) != 0) {
            if (differ < 5)
                printf("   ray %d: binned t=%.9g inst %u prim %u u=%g v=%g; cellsplit t=%.9g "
                       "inst %u prim %u u=%g v=%g\n",
                       i, (double)binned[i].t, binned[i].instance, binned[i].primitive,
                       (double)binned[i].u, (double)binned[i].v, (double)paper[i].t,
                       paper[i].instance, paper[i].primitive, (double)paper[i].u,
                       (double)paper[i].v);
            differ++;
        }
    }
    printf("   %d of %d rays hit; %d differ\n", hits, RAYS, differ);
    CHECK(hits > RAYS / 10);
    CHECK_INT(differ, 0);
    tu_section("bad configuration");
    CHECK(rtCreateContext("toplevel=bsp") == NULL);
    /* The old name of the cell-split rule is gone, not an alias. */
    CHECK(rtCreateContext("toplevel=paper004") == NULL);
    return test_summary("toplevel_builders");
}
