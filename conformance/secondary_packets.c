/* SPDX-License-Identifier: Apache-2.0 */
/*
 * secondary_packets.c - conformance: Whitted shadow rays and ray queries
 * traced as 8-ray packets (packets=on, the default; trace/packet_scene.h)
 * see the surfaces that GL's per-primitive state removes exactly as
 * single rays do (render/secondary.h): the image with packets on is the
 * image with packets off, bit for bit, with the same RT_STAT_RAYS, and
 * each occluder's shadow is there or not as its state says.  A packet
 * path that walked without the hit filter would shadow the floor under
 * the cutout's transparent half, the clipped-away occluder and the
 * see-through blended one.
 *
 * Scene: rtOrtho(0, N, 0, N, -10, 10), the eye looking down -z, a white
 * floor at z = 0 and occluders at z = 4, a directional light along
 * (1, 0, 1): an occluder over x in [a, b] shadows the floor's pixels
 * a - 4 .. b - 5.  Every 4 x 2 block of camera rays that hits the floor
 * sends eight parallel shadow rays, one packet.
 *
 * - cutout over [8, 16], alpha-tested (RT_GREATER 0.5), its left half of
 *   alpha 0: floor pixels 4 .. 7 lit, 8 .. 11 dark (the camera sees the
 *   floor through the left half there);
 * - occluder over [20, 28] drawn under a clip plane that removes it:
 *   floor pixels 16 .. 23 lit;
 * - occluder over [30, 34] blended (RT_SRC_ALPHA, RT_ONE_MINUS_SRC_ALPHA,
 *   alpha 0.3): floor pixels 26 .. 29 lit;
 * - opaque occluder over [40, 44]: floor pixels 36 .. 39 dark.
 *
 * A second frame adds a glass plate at z = 0.25 over the whole floor,
 * blended (see-through, so shadow rays pass it), transparent (index of
 * refraction 1: the refracted camera ray goes on straight down) and a
 * little reflective: the floor is then seen through refracted rays at
 * depth 1 (and behind the blended plate, hits that are not a camera
 * packet's first), whose shadow rays go ray by ray through the same
 * filter, while the plate's own shadow rays go as packets.  The bands of
 * the row must be as in the first frame: equal where lit, equal and
 * darker where shadowed.
 *
 * Queries: rows of eight parallel rays from the floor towards the light
 * (rtOccludedRays and rtTraceRays) under the clip plane's occluder and
 * under the opaque one, packets on and off: the same answers, and the
 * clipped occluder is not there.
 *
 * Reference: docs/clip_planes.md, docs/alpha_test.md, docs/blending.md,
 * docs/queries.md.
 */
#include "testutil.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define N 48
#define FLOOR 900u
#define CUTOUT 901u
#define CLIPPED 902u
#define BLENDED 903u
#define OPAQUE 904u
#define GLASS 905u
#define QUERY_RAYS 32

static void quad(float x0, float x1, float z)
{
    rtBegin(RT_QUADS);
    rtNormal3f(0.0f, 0.0f, 1.0f);
    rtVertex3f(x0, 0.0f, z);
    rtVertex3f(x1, 0.0f, z);
    rtVertex3f(x1, (float)N, z);
    rtVertex3f(x0, (float)N, z);
    rtEnd();
}

static void object(RTuint name, float x0, float x1, float alpha)
{
    const float diffuse[4] = {1.0f, 1.0f, 1.0f, alpha};
    rtNewObject(name);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, diffuse);
    quad(x0, x1, 4.0f);
    rtEndObject();
}

static void define_scene(void)
{
    static const float black[4] = {0, 0, 0, 1}, white[4] = {1, 1, 1, 1};
    static const float clear[4] = {1, 1, 1, 0};
    static const float light_dir[4] = {1, 0, 1, 0};
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtOrtho(0.0, N, 0.0, N, -10.0, 10.0);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtShadingMode(RT_WHITTED);
    rtClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, black);
    rtLightfv(RT_LIGHT0, RT_POSITION, light_dir);
    rtEnable(RT_LIGHT0);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, black);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_SPECULAR, black);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, white);
    rtNewObject(FLOOR);
    quad(-16.0f, 64.0f, 0.0f);
    rtEndObject();
    rtNewObject(CUTOUT);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, clear);
    quad(8.0f, 12.0f, 4.0f);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, white);
    quad(12.0f, 16.0f, 4.0f);
    rtEndObject();
    object(CLIPPED, 20.0f, 28.0f, 1.0f);
    object(BLENDED, 30.0f, 34.0f, 0.3f);
    object(OPAQUE, 40.0f, 44.0f, 1.0f);
    const float glass[4] = {0.5f, 0.5f, 1.0f, 0.5f};
    rtNewObject(GLASS);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, glass);
    rtMaterialf(RT_FRONT_AND_BACK, RT_TRANSPARENCY, 0.5f);
    rtMaterialf(RT_FRONT_AND_BACK, RT_REFLECTIVITY, 0.25f);
    rtMaterialf(RT_FRONT_AND_BACK, RT_INDEX_OF_REFRACTION, 1.0f);
    quad(-16.0f, 64.0f, 0.25f);
    rtEndObject();
}

/* The frame: floor and occluders, and the glass plate when `glass`. */
static void draw_frame(int glass)
{
    static const double keep_below_2[4] = {0.0, 0.0, -1.0, 2.0};
    rtBeginFrame();
    rtInstantiateObject(FLOOR);
    rtEnable(RT_ALPHA_TEST);
    rtAlphaFunc(RT_GREATER, 0.5f);
    rtInstantiateObject(CUTOUT);
    rtDisable(RT_ALPHA_TEST);
    rtAlphaFunc(RT_ALWAYS, 0.0f);
    rtClipPlane(RT_CLIP_PLANE0, keep_below_2);
    rtEnable(RT_CLIP_PLANE0);
    rtInstantiateObject(CLIPPED);
    rtDisable(RT_CLIP_PLANE0);
    rtEnable(RT_BLEND);
    rtBlendFunc(RT_SRC_ALPHA, RT_ONE_MINUS_SRC_ALPHA);
    rtInstantiateObject(BLENDED);
    rtDisable(RT_BLEND);
    rtInstantiateObject(OPAQUE);
    if (glass) {
        rtEnable(RT_BLEND);
        rtBlendFunc(RT_SRC_ALPHA, RT_ONE_MINUS_SRC_ALPHA);
        rtInstantiateObject(GLASS);
        rtDisable(RT_BLEND);
    }
    CHECK_NO_ERR();
}

/* Rows of eight parallel rays from the floor towards the light, from
 * x = x0 + 0.5 .. x0 + 3.5 at two heights y (a 4 x 2 block). */
static void query_rays(RTray *rays)
{
    static const float x0[QUERY_RAYS / 8] = {16.0f, 20.0f, 36.0f, 4.0f};
    for (int i = 0; i < QUERY_RAYS; i++) {
        RTray *r = &rays[i];
        r->org[0] = x0[i / 8] + 0.5f + (float)(i % 4);
        r->org[1] = 10.5f + (float)(i / 4 % 2);
        r->org[2] = 0.0f;
        r->tmin = 1e-3f;
        r->dir[0] = 1.0f;
        r->dir[1] = 0.0f;
        r->dir[2] = 1.0f;
        r->tmax = INFINITY;
    }
}

struct result {
    float image[4 * N * N];
    float glass[4 * N * N]; /* the frame with the glass plate */
    RThit hits[QUERY_RAYS];
    RTboolean occluded[QUERY_RAYS];
    RTint rays;
    RTint glass_rays;
};

/* 0 when the configuration cannot run here (an ISA the CPU lacks). */
static int run(const char *config, struct result *out)
{
    RTcontext ctx = rtCreateContext(config);
    if (!ctx)
        return 0;
    rtMakeCurrent(ctx);
    define_scene();
    draw_frame(0);
    tu_render_float(N, N, out->image);
    rtGetIntegerv(RT_STAT_RAYS, &out->rays);
    RTray rays[QUERY_RAYS];
    query_rays(rays);
    rtTraceRays(QUERY_RAYS, rays, out->hits);
    rtOccludedRays(QUERY_RAYS, rays, out->occluded);
    draw_frame(1);
    tu_render_float(N, N, out->glass);
    rtGetIntegerv(RT_STAT_RAYS, &out->glass_rays);
    CHECK_NO_ERR();
    tu_destroy_context(ctx);
    return 1;
}

static float floor_red(const struct result *r, int x)
{
    return r->image[4 * ((N / 2) * N + x)];
}

static int lit(const struct result *r, int x)
{
    return fabsf(floor_red(r, x) - 0.70710677f) < 1e-3f;
}

static int dark(const struct result *r, int x)
{
    return floor_red(r, x) < 1e-6f;
}

/* Pixels x0 .. x1 of the middle row all lit (want 1) or all dark (0). */
static int band(const struct result *r, int x0, int x1, int want)
{
    for (int x = x0; x <= x1; x++)
        if (want ? !lit(r, x) : !dark(r, x))
            return 0;
    return 1;
}

static float glass_red(const struct result *r, int x)
{
    return r->glass[4 * ((N / 2) * N + x)];
}

/* Pixels x0 .. x1 of the glass frame's middle row all equal to pixel 0
 * (want 1, lit) or to pixel 8 (want 0, shadowed). */
static int glass_band(const struct result *r, int x0, int x1, int want)
{
    const float v = glass_red(r, want ? 0 : 8);
    for (int x = x0; x <= x1; x++)
        if (glass_red(r, x) != v)
            return 0;
    return 1;
}

static void check_shadows(const char *config, const struct result *r)
{
    CHECKF(band(r, 0, 3, 1), "%s: open floor lit", config);
    CHECKF(band(r, 4, 7, 1), "%s: floor under the cutout's transparent half lit", config);
    CHECKF(band(r, 8, 11, 0), "%s: floor under the cutout's opaque half dark", config);
    CHECKF(band(r, 16, 23, 1), "%s: floor under the clipped-away occluder lit", config);
    CHECKF(band(r, 26, 29, 1), "%s: floor under the see-through blended occluder lit",
           config);
    CHECKF(band(r, 36, 39, 0), "%s: floor under the opaque occluder dark", config);
    CHECKF(glass_red(r, 8) < glass_red(r, 0), "%s: glass frame: shadow darker (%g, %g)", config,
           glass_red(r, 8), glass_red(r, 0));
    CHECKF(glass_band(r, 0, 7, 1), "%s: glass frame: open floor and cutout's transparent half",
           config);
    CHECKF(glass_band(r, 8, 11, 0), "%s: glass frame: cutout's opaque half", config);
    CHECKF(glass_band(r, 16, 19, 1), "%s: glass frame: clipped-away occluder", config);
    CHECKF(glass_band(r, 26, 29, 1), "%s: glass frame: see-through blended occluder", config);
    CHECKF(glass_band(r, 36, 39, 0), "%s: glass frame: opaque occluder", config);
    /* Queries: the clip plane removes CLIPPED (rays 0 .. 15 pass it);
     * OPAQUE stops rays 16 .. 23; the alpha test does not apply to
     * queries, so the cutout stops rays 24 .. 31. */
    for (int i = 0; i < QUERY_RAYS; i++) {
        const int blocked = i >= 16;
        CHECKF(r->occluded[i] == (blocked ? RT_TRUE : RT_FALSE), "%s: occluded[%d] = %d",
               config, i, (int)r->occluded[i]);
        const RTuint want = i < 16 ? RT_INVALID_ID : i < 24 ? OPAQUE : CUTOUT;
        CHECKF(r->hits[i].object == want, "%s: hit %d object %u, want %u", config, i,
               (unsigned)r->hits[i].object, (unsigned)want);
    }
}

int main(void)
{
    tu_section("filtered shadow rays and queries: packets on = packets off, bit for bit");
    static struct result ref, got;
    static const char *configs[] = {"threads=1 isa=avx2",        "threads=2 isa=avx2",
                                    "threads=1 isa=avx512",      "threads=2 isa=avx512",
                                    "threads=1 isa=sse4",        "threads=1 isa=avx2 packets=off",
                                    "threads=1 isa=avx512 packets=off"};
    CHECK(run("threads=1 isa=scalar", &ref));
    check_shadows("threads=1 isa=scalar", &ref);
    int ran = 0;
    for (size_t c = 0; c < sizeof(configs) / sizeof(configs[0]); c++) {
        if (!run(configs[c], &got)) {
            printf("  skipped (not in this build or on this CPU): %s\n", configs[c]);
            continue;
        }
        ran++;
        check_shadows(configs[c], &got);
        CHECKF(memcmp(ref.image, got.image, sizeof(ref.image)) == 0, "%s: image differs",
               configs[c]);
        CHECKF(memcmp(ref.hits, got.hits, sizeof(ref.hits)) == 0, "%s: hits differ",
               configs[c]);
        CHECKF(memcmp(ref.occluded, got.occluded, sizeof(ref.occluded)) == 0,
               "%s: occlusion answers differ", configs[c]);
        CHECKF(ref.rays == got.rays, "%s: RT_STAT_RAYS %d, reference %d", configs[c],
               (int)got.rays, (int)ref.rays);
        CHECKF(memcmp(ref.glass, got.glass, sizeof(ref.glass)) == 0,
               "%s: glass frame's image differs", configs[c]);
        CHECKF(ref.glass_rays == got.glass_rays, "%s: glass frame: RT_STAT_RAYS %d, reference %d",
               configs[c], (int)got.glass_rays, (int)ref.glass_rays);
    }
    /* Packets walk the wide layout of the SIMD tables: a build with the
     * scalar table only (RT_NO_SIMD, another architecture) has none to
     * compare; any other must have run at least one configuration. */
    if (tu_config_available("isa=sse4") || tu_config_available("isa=avx2") ||
        tu_config_available("isa=avx512"))
        CHECK(ran > 0);
    else
        printf("  skipped: this build has the scalar table only (no packets)\n");
    return test_summary("secondary_packets");
}
