/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dynamic_threads.c - dynamic scenes give the same images with 1 and 4
 * threads.
 *
 * The animations of dynamic_anim.h - an exploding sphere, a waving cloth,
 * a morphing soup, a 21k-triangle cloth (large enough for updates on the
 * worker threads) and a grid whose resolution changes every frame (rebuilt
 * lazily by whichever render thread reaches it first) - are played for
 * FRAMES frames, every object changing every frame, under each update
 * strategy, animated by rtUpdateVertices and by redefinition.  Each
 * combination is played with threads=1, then with threads=4 on the main
 * thread, then twice more with threads=4 on two application threads at
 * once (contexts share no mutable state).  Every frame's RGBA float image
 * must be identical bit for bit to the threads=1 image, and the closest
 * hits of RAY_COUNT fixed rays must agree with it (same primitive and t,
 * or an equally close triangle; dynamic_anim.h).
 *
 * With RT_TEST_WORKLOAD=small (the sanitizer suites, scripts/test.sh) each
 * playing has FRAMES_SMALL frames instead of FRAMES: the first build, then
 * an update rendered before tracing and one traced before rendering, the
 * same paths and checks as the full run.
 *
 * Named *_threads.c: ctest label "threads", run under ThreadSanitizer.
 * The players make no checks (testutil is single-threaded): they record
 * what they saw and the main thread compares.
 *
 * Reference: docs/dynamic.md.
 */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dynamic_anim.h"
#include "testutil.h"

#define FRAMES 6
#define FRAMES_SMALL 3
#define RAY_COUNT 1500

enum method { BY_UPDATE, BY_REDEFINITION };

static const int kinds[] = {DA_BIG, DA_SPHERE, DA_CLOTH, DA_SOUP, DA_POPPER};
#define KIND_COUNT 5

/* What one playing of an animation saw. */
struct play {
    /* in */
    RTenum strategy;
    enum method method;
    int frames; /* FRAMES, or FRAMES_SMALL */
    const char *config;
    const RTray *rays;
    /* out */
    float *images; /* frames * DA_PIXELS */
    RThit *hits;   /* frames * RAY_COUNT */
    RTenum error;  /* the first error any frame recorded */
    int updates_ok; /* RT_STAT_OBJECT_UPDATES as expected on every frame */
};

/* Plays the animation in a context of its own; thread-safe (uses only its
 * own context and its own struct play). */
static void *play(void *arg)
{
    struct play *p = (struct play *)arg;
    RTcontext ctx = rtCreateContext(p->config);
    p->error = RT_NO_ERROR;
    p->updates_ok = 1;
    if (!ctx || !rtMakeCurrent(ctx)) {
        p->error = RT_INVALID_OPERATION;
        if (ctx)
            rtDestroyContext(ctx);
        return NULL;
    }
    da_camera();
    if (p->method == BY_REDEFINITION)
        rtRenderParameteri(RT_UPDATE_STRATEGY, (RTint)p->strategy);
    for (int f = 0; f < p->frames; f++) {
        for (int i = 0; i < KIND_COUNT; i++) {
            RTuint name = DA_NAME_BASE + (RTuint)kinds[i];
            if (f == 0 || p->method == BY_REDEFINITION)
                da_define(name, kinds[i], f);
            else
                da_update(name, kinds[i], f);
            if (f == 0 && p->method == BY_UPDATE)
                rtObjectParameteri(name, RT_UPDATE_STRATEGY, (RTint)p->strategy);
        }
        da_instantiate(kinds, KIND_COUNT);
        RTint updates = -1;
        if (f % 2) {
            da_render(&p->images[(size_t)f * DA_PIXELS]);
            rtGetIntegerv(RT_STAT_OBJECT_UPDATES, &updates);
            rtTraceRays(RAY_COUNT, p->rays, &p->hits[(size_t)f * RAY_COUNT]);
        } else {
            rtTraceRays(RAY_COUNT, p->rays, &p->hits[(size_t)f * RAY_COUNT]);
            rtGetIntegerv(RT_STAT_OBJECT_UPDATES, &updates);
            da_render(&p->images[(size_t)f * DA_PIXELS]);
        }
        /* Every object but the popper (rebuilt lazily) is updated from
         * frame 1 on. */
        if (updates != (f ? KIND_COUNT - 1 : 0))
            p->updates_ok = 0;
        RTenum e = rtGetError();
        if (p->error == RT_NO_ERROR)
            p->error = e;
    }
    rtMakeCurrent(NULL);
    rtDestroyContext(ctx);
    return NULL;
}

static void play_init(struct play *p, RTenum strategy, enum method method, const char *config,
                      const RTray *rays)
{
    memset(p, 0, sizeof(*p));
    p->strategy = strategy;
    p->method = method;
    p->frames = tu_small_workload() ? FRAMES_SMALL : FRAMES;
    p->config = config;
    p->rays = rays;
    p->images = (float *)calloc((size_t)p->frames * DA_PIXELS, sizeof(float));
    p->hits = (RThit *)calloc((size_t)p->frames * RAY_COUNT, sizeof(RThit));
}

static void play_free(struct play *p)
{
    free(p->images);
    free(p->hits);
}

/* Compares a threads=4 playing with the threads=1 one. */
static void compare(const struct play *base, const struct play *p, const char *what,
                    struct da_compare_stats *st, long *hits_not_bitwise)
{
    char label[160];
    CHECK_INT(p->error, RT_NO_ERROR);
    CHECK(p->updates_ok);
    for (int f = 0; f < p->frames; f++) {
        snprintf(label, sizeof label, "%s by %s, %s, frame %d", da_strategy_name(p->strategy),
                 p->method == BY_UPDATE ? "rtUpdateVertices" : "redefinition", what, f);
        CHECK_INT(da_compare_images(&p->images[(size_t)f * DA_PIXELS],
                                    &base->images[(size_t)f * DA_PIXELS], label),
                  0);
        CHECK_INT(da_compare_hits(&p->hits[(size_t)f * RAY_COUNT],
                                  &base->hits[(size_t)f * RAY_COUNT], RAY_COUNT, label, st),
                  0);
        if (memcmp(&p->hits[(size_t)f * RAY_COUNT], &base->hits[(size_t)f * RAY_COUNT],
                   RAY_COUNT * sizeof(RThit)) != 0)
            (*hits_not_bitwise)++;
    }
}

int main(void)
{
    RTray *rays = (RTray *)malloc(RAY_COUNT * sizeof(RTray));
    struct da_compare_stats st;
    long not_bitwise = 0;
    memset(&st, 0, sizeof st);
    da_rays(rays, RAY_COUNT, 777u);

    for (int m = 0; m < 2; m++)
        for (int s = 0; s < DA_STRATEGY_COUNT; s++) {
            char section[96];
            struct play base, main_thread, app[2];
            pthread_t tid[2];
            snprintf(section, sizeof section, "%s by %s: threads=1 vs threads=4",
                     da_strategy_name(da_strategies[s]),
                     m == BY_UPDATE ? "rtUpdateVertices" : "redefinition");
            tu_section(section);
            play_init(&base, da_strategies[s], (enum method)m, "threads=1", rays);
            play_init(&main_thread, da_strategies[s], (enum method)m, "threads=4", rays);
            play(&base);
            play(&main_thread);
            CHECK_INT(base.error, RT_NO_ERROR);
            CHECK(base.updates_ok);
            compare(&base, &main_thread, "threads=4", &st, &not_bitwise);
            for (int t = 0; t < 2; t++) {
                play_init(&app[t], da_strategies[s], (enum method)m, "threads=4", rays);
                CHECK_INT(pthread_create(&tid[t], NULL, play, &app[t]), 0);
            }
            for (int t = 0; t < 2; t++) {
                pthread_join(tid[t], NULL);
                compare(&base, &app[t], t ? "threads=4 on application thread 2"
                                          : "threads=4 on application thread 1",
                        &st, &not_bitwise);
                play_free(&app[t]);
            }
            play_free(&base);
            play_free(&main_thread);
        }
    printf("compared %ld rays (%ld hits): %ld ties at equal distance, %ld mismatches; %ld "
           "frames whose hits were not bit-identical to threads=1\n",
           st.rays, st.hits, st.ties, st.mismatches, not_bitwise);
    free(rays);
    return test_summary("dynamic_threads");
}
