/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Tutorial 5: a headless render loop (docs/tutorials/05-render-loop.md).
 *
 * What an interactive program does every frame, without a window: describe
 * the frame in immediate mode (set the camera, re-issue the instances),
 * rtRenderFrame, rtReadPixels, and use the pixels (here: write every
 * fourth frame to a numbered image and keep a checksum).  The statistics
 * show that only the first frame builds the objects' BVHs; later frames
 * only move instances, which costs a top-level rebuild.
 *
 * Usage: tutorial05_render_loop [FRAMES [OUT_PREFIX]]   (default 12 frames, "tutorial05")
 */
#include <rt/rt.h>
#include <rt/rtu.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#define W 160
#define H 120

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* A flat-shaded octahedron: eight triangles. */
static void octahedron(RTuint name, const float colour[4])
{
    static const float v[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    static const int faces[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                    {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    rtNewObject(name);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT_AND_DIFFUSE, colour);
    rtShadeModel(RT_FLAT);
    rtBegin(RT_TRIANGLES);
    for (int f = 0; f < 8; f++) {
        const float *a = v[faces[f][0]], *b = v[faces[f][1]], *c = v[faces[f][2]];
        rtNormal3f(a[0] + b[0] + c[0], a[1] + b[1] + c[1], a[2] + b[2] + c[2]);
        rtVertex3fv(a);
        rtVertex3fv(b);
        rtVertex3fv(c);
    }
    rtEnd();
    rtEndObject();
}

int main(int argc, char **argv)
{
    int frames = argc > 1 ? atoi(argv[1]) : 12;
    const char *prefix = argc > 2 ? argv[2] : "tutorial05";
    if (frames < 1 || frames > 100000) {
        fprintf(stderr, "usage: tutorial05_render_loop [FRAMES [OUT_PREFIX]]\n");
        return 2;
    }
    RTcontext context = rtCreateContext("threads=2");
    if (context == NULL || !rtMakeCurrent(context)) {
        fprintf(stderr, "tutorial05: cannot create a context\n");
        return 1;
    }
    static const float gold[4] = {0.9f, 0.7f, 0.2f, 1}, teal[4] = {0.1f, 0.6f, 0.6f, 1};
    octahedron(1, gold);
    octahedron(2, teal);

    static const float light[4] = {1, 2, 3, 0};
    rtLightfv(RT_LIGHT0, RT_POSITION, light);
    rtEnable(RT_LIGHT0);
    rtShadingMode(RT_WHITTED);
    rtClearColor(0, 0, 0, 1);
    rtViewport(0, 0, W, H);
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtuPerspective(45.0, (double)W / H, 0.1, 100.0);
    rtMatrixMode(RT_MODELVIEW);

    unsigned char *pixels = malloc((size_t)W * H * 4);
    if (pixels == NULL)
        return 1;
    unsigned long checksum_first = 0;
    int ok = 1, builds_after_first = 0, changed_frames = 0;
    double start = now();
    for (int frame = 0; frame < frames; frame++) {
        float angle = 7.5f * (float)frame;
        /* Describe the frame: the camera (a modelview transform), then the
         * instances, a ring of eight alternating octahedra turning. */
        rtLoadIdentity();
        rtTranslatef(0, -0.5f, -9);
        rtRotatef(20, 1, 0, 0);
        for (int i = 0; i < 8; i++) {
            rtPushMatrix();
            rtRotatef(angle + 45.0f * (float)i, 0, 1, 0);
            rtTranslatef(3, 0, 0);
            rtRotatef(2.0f * angle, 1, 1, 0);
            rtScalef(0.6f, 0.6f, 0.6f);
            rtInstantiateObject(i % 2 ? 2u : 1u);
            rtPopMatrix();
        }
        rtRenderFrame(); /* renders, and ends the frame's instance list */
        rtReadPixels(0, 0, W, H, RT_RGBA, RT_UNSIGNED_BYTE, pixels);

        unsigned long checksum = 0;
        for (size_t k = 0; k < (size_t)W * H * 4; k++)
            checksum = checksum * 31u + pixels[k];
        if (frame == 0)
            checksum_first = checksum;
        else
            changed_frames += checksum != checksum_first;

        RTint object_builds = 0, toplevel_builds = 0;
        RTfloat ms = 0;
        rtGetIntegerv(RT_STAT_OBJECT_BUILDS, &object_builds);
        rtGetIntegerv(RT_STAT_TOPLEVEL_BUILDS, &toplevel_builds);
        rtGetFloatv(RT_STAT_RENDER_TIME, &ms);
        if (frame > 0)
            builds_after_first += object_builds;
        printf("frame %04d: %.2f ms, object BVH builds %d, top-level builds %d\n", frame,
               (double)ms, object_builds, toplevel_builds);
        if (frame % 4 == 0) {
            char path[512];
            snprintf(path, sizeof path, "%s_%04d.ppm", prefix, frame);
            ok = ok && rtuSaveImage(path, W, H, RT_UNSIGNED_BYTE, pixels);
        }
    }
    double seconds = now() - start;
    printf("%d frames in %.3f s = %.1f fps\n", frames, seconds, frames / seconds);
    /* Every frame after the first shows the ring elsewhere (7.5 degrees a
     * step: it comes back to the first picture only after 90 degrees). */
    ok = ok && rtGetError() == RT_NO_ERROR && builds_after_first == 0 &&
         changed_frames >= (frames < 12 ? frames : 12) - 1;
    free(pixels);
    rtDestroyContext(context);
    printf("tutorial05: %s\n", ok ? "ok" : "FAILED");
    return ok ? 0 : 1;
}
