/* SPDX-License-Identifier: Apache-2.0 */
/*
 * context.c - conformance: contexts, configuration strings, rtGetString,
 * rtGetIntegerv/rtGetFloatv defaults, rtEnable/rtDisable/rtIsEnabled,
 * per-thread current context, and calls with no current context.
 *
 * Reference: docs/context.md.
 */
#include "testutil.h"

#include <limits.h>
#include <pthread.h>
#include <stdio.h>
#include <string.h>

static void config_strings(void)
{
    static const char *const good[] = {NULL,
                                       "",
                                       "threads=1",
                                       "threads=256",
                                       "threads=2,bins=8",
                                       "threads=2 bins=8 builder=sweep",
                                       "bins=2",
                                       "bins=256",
                                       "builder=binned",
                                       /* docs/context.md grammar: blanks are
                                        * space, tab, CR and LF, anywhere
                                        * between items; one comma. */
                                       "threads=2\n",
                                       "threads=2\r\n",
                                       "\tthreads=2\tbins=8\n",
                                       " threads=2 , bins=8 ",
                                       "   ",
                                       "threads=10",
                                       "build_threads=0",
                                       "isa=scalar",
                                       "isa=auto",
                                       "threads=1 isa=scalar",
                                       "packets=on",
                                       "packets=off isa=auto"};
    static const char *const bad[] = {"threads=0",    "threads=257", "threads=-1", "threads=",
                                      "threads=abc",  "threads=2x",  "bins=1",     "bins=257",
                                      "builder=foo",  "foo=1",       "threads",    "=2",
                                      "threads=2;bins=8",
                                      /* duplicates, empty items, leading
                                       * zeros, signs, blanks around '=' */
                                      "threads=2 threads=3", "bins=8,bins=8", "threads=01",
                                      "bins=08", "threads=+2", " , ", ",", "threads=1,",
                                      ",threads=1", "threads=1,,bins=4", "threads=1, ,bins=4",
                                      "threads =1", "threads= 1", "build_threads=00",
                                      "isa=", "isa=sse2", "isa=AVX2", "isa=avx2x",
                                      "isa=scalar isa=scalar", "packets=", "packets=ON",
                                      "packets=1", "packets=on packets=off"};
    size_t i;
    tu_section("configuration strings");
    for (i = 0; i < sizeof good / sizeof good[0]; i++) {
        RTcontext ctx = rtCreateContext(good[i]);
        if (!tu_check(ctx != NULL, __FILE__, __LINE__, "valid configuration accepted"))
            fprintf(stderr, "    configuration \"%s\"\n", good[i] ? good[i] : "(null)");
        /* Creating a context does not make it current. */
        CHECK(rtGetCurrentContext() == NULL);
        rtDestroyContext(ctx);
    }
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        RTcontext ctx = rtCreateContext(bad[i]);
        if (!tu_check(ctx == NULL, __FILE__, __LINE__, "invalid configuration rejected"))
            fprintf(stderr, "    configuration \"%s\"\n", bad[i]);
        rtDestroyContext(ctx);
    }
    /* NULL is ignored. */
    rtDestroyContext(NULL);
}

/* rtCreateContextWithReason: the reason for a NULL context, in the
 * caller's buffer (docs/context.md). */
static int reason_is(const char *config, const char *expected)
{
    char reason[RT_REASON_SIZE];
    memset(reason, 'x', sizeof reason);
    RTcontext ctx = rtCreateContextWithReason(config, (RTsizei)sizeof reason, reason);
    int ok = ctx == NULL && strcmp(reason, expected) == 0;
    if (!ok)
        fprintf(stderr, "    \"%s\": context %p, reason \"%s\", expected \"%s\"\n", config,
                (void *)ctx, reason, expected);
    rtDestroyContext(ctx);
    return ok;
}

static void config_reasons(void)
{
    char reason[RT_REASON_SIZE];
    tu_section("rtCreateContextWithReason");
    CHECK(reason_is("threads=2 threads=3", "key 'threads' is given twice"));
    CHECK(reason_is("threads=1,,bins=4", "item 2 is empty (a comma with no key=value before it)"));
    CHECK(reason_is(" , ", "item 1 is empty (a comma with no key=value before it)"));
    CHECK(reason_is("threads=1,", "item 2 is empty (a comma with no key=value after it)"));
    CHECK(reason_is("threads=01", "threads='01': the value must be a decimal integer in "
                                  "[1, 256] without sign or leading zero"));
    CHECK(reason_is("builder=fast", "builder='fast': the value must be binned or sweep"));
    CHECK(reason_is("colour=red", "unknown key 'colour'"));
    CHECK(reason_is("threads", "'threads' is not key=value"));
    /* Success: a context and an empty reason. */
    memset(reason, 'x', sizeof reason);
    RTcontext ctx = rtCreateContextWithReason("threads=2\n", (RTsizei)sizeof reason, reason);
    CHECK(ctx != NULL);
    CHECK(reason[0] == '\0');
    rtDestroyContext(ctx);
    /* A short buffer gets a terminated prefix; none at all is allowed. */
    memset(reason, 'x', sizeof reason);
    CHECK(rtCreateContextWithReason("foo=1", 4, reason) == NULL);
    CHECK(strcmp(reason, "unk") == 0 && reason[4] == 'x');
    CHECK(rtCreateContextWithReason("foo=1", 0, reason) == NULL);
    CHECK(rtCreateContextWithReason("foo=1", 16, NULL) == NULL);
    ctx = rtCreateContextWithReason(NULL, 0, NULL);
    CHECK(ctx != NULL);
    rtDestroyContext(ctx);
}

static void effective_configuration(void)
{
    RTcontext ctx;
    RTint v = -1;
    const char *s;
    tu_section("effective configuration");
    ctx = tu_make_context("threads=3, bins=8 builder=sweep");
    rtGetIntegerv(RT_THREADS, &v);
    CHECK_INT(v, 3);
    v = -1;
    rtGetIntegerv(RT_BVH_BINS, &v);
    CHECK_INT(v, 8);
    s = rtGetString(RT_CONFIGURATION);
    CHECK(s != NULL);
    if (s) {
        CHECK(strstr(s, "threads=3") != NULL);
        CHECK(strstr(s, "bins=8") != NULL);
        CHECK(strstr(s, "builder=sweep") != NULL);
    }
    /* No thread is started until a frame needs one. */
    v = -1;
    rtGetIntegerv(RT_WORKER_THREADS_RUNNING, &v);
    CHECK_INT(v, 0);
    CHECK_NO_ERR();
    tu_destroy_context(ctx);

    ctx = tu_make_context("threads=2");
    v = -1;
    rtGetIntegerv(RT_BVH_BINS, &v);
    CHECK_INT(v, 16); /* default bins */
    s = rtGetString(RT_CONFIGURATION);
    CHECK(s != NULL);
    if (s) {
        CHECK(strstr(s, "threads=2") != NULL);
        CHECK(strstr(s, "bins=16") != NULL);
        CHECK(strstr(s, "builder=binned") != NULL);
    }
    tu_destroy_context(ctx);

    /* isa=: the traversal kernels' instruction set, reported back; the
     * default is the best this machine runs, never below scalar. */
    ctx = tu_make_context("threads=1 isa=scalar");
    s = rtGetString(RT_CONFIGURATION);
    CHECK(s != NULL && strstr(s, "isa=scalar") != NULL);
    tu_destroy_context(ctx);
    ctx = tu_make_context("threads=1");
    s = rtGetString(RT_CONFIGURATION);
    CHECK(s != NULL && (strstr(s, "isa=scalar") || strstr(s, "isa=sse4") ||
                        strstr(s, "isa=avx2") || strstr(s, "isa=avx512")));
    if (s) {
        /* The reported ISA is accepted back, and gives the same string. */
        char config[160];
        const char *isa = strstr(s, "isa=");
        snprintf(config, sizeof(config), "threads=1 %s", isa ? isa : "");
        RTcontext again = rtCreateContext(config);
        CHECK(again != NULL);
        rtDestroyContext(again);
    }
    tu_destroy_context(ctx);

    /* packets=: reported; on by default where the kernels have a packet
     * walk, and off for isa=scalar, which has none. */
    ctx = tu_make_context("threads=1 packets=off");
    s = rtGetString(RT_CONFIGURATION);
    CHECK(s != NULL && strstr(s, "packets=off") != NULL);
    tu_destroy_context(ctx);
    ctx = tu_make_context("threads=1 isa=scalar packets=on");
    s = rtGetString(RT_CONFIGURATION);
    CHECK(s != NULL && strstr(s, "packets=off") != NULL);
    tu_destroy_context(ctx);
    ctx = tu_make_context("threads=1");
    s = rtGetString(RT_CONFIGURATION);
    CHECK(s != NULL && (strstr(s, "packets=on") || strstr(s, "isa=scalar")));
    tu_destroy_context(ctx);

    /* Default thread count: at least one. */
    ctx = tu_make_context(NULL);
    v = -1;
    rtGetIntegerv(RT_THREADS, &v);
    CHECK(v >= 1 && v <= 256);
    tu_destroy_context(ctx);
}

static void strings(void)
{
    RTcontext ctx = tu_make_context("threads=1");
    const char *s;
    tu_section("rtGetString");
    s = rtGetString(RT_VENDOR);
    CHECK(s != NULL && s[0] != '\0');
    s = rtGetString(RT_RENDERER);
    CHECK(s != NULL && s[0] != '\0');
    s = rtGetString(RT_VERSION);
    CHECK(s != NULL);
    if (s)
        CHECK(strncmp(s, "0.1.0", 5) == 0);
    s = rtGetString(RT_EXTENSIONS);
    CHECK(s != NULL); /* may be "" */
    CHECK_NO_ERR();

    tu_capture_errors();
    s = rtGetString(0x1234);
    CHECK(s == NULL);
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK_MSG("rtGetString");
    s = rtGetString(RT_MODELVIEW);
    CHECK(s == NULL);
    CHECK_ERR(RT_INVALID_ENUM);
    tu_destroy_context(ctx);
}

static void integer_defaults(void)
{
    RTcontext ctx = tu_make_context("threads=1");
    RTint v[4];
    RTfloat f[16];
    int k;
    tu_section("rtGetIntegerv/rtGetFloatv defaults");
#define GETI(pname, expected)                                                                  \
    do {                                                                                       \
        v[0] = -777;                                                                           \
        rtGetIntegerv((pname), v);                                                             \
        CHECK_INT(v[0], (expected));                                                           \
        f[0] = -777.0f;                                                                        \
        rtGetFloatv((pname), f);                                                               \
        CHECK_NEAR(f[0], (double)(expected), 0.0);                                             \
    } while (0)
    GETI(RT_MATRIX_MODE, RT_MODELVIEW);
    GETI(RT_MODELVIEW_STACK_DEPTH, 1);
    GETI(RT_PROJECTION_STACK_DEPTH, 1);
    GETI(RT_MAX_MODELVIEW_STACK_DEPTH, 32);
    GETI(RT_MAX_PROJECTION_STACK_DEPTH, 4);
    GETI(RT_MAX_LIGHTS, 8);
    GETI(RT_THREADS, 1);
    GETI(RT_BVH_BINS, 16);
    GETI(RT_OBJECT_COUNT, 0);
    GETI(RT_INSTANCE_COUNT, 0);
    GETI(RT_WORKER_THREADS_RUNNING, 0);
    GETI(RT_SHADING_MODE, RT_FIXED_FUNCTION); /* GL's look by default (issue 10) */
    GETI(RT_MAX_RAY_DEPTH, 3);
    GETI(RT_SHADE_MODEL, RT_SMOOTH);
    GETI(RT_STAT_RAYS, 0);
    GETI(RT_STAT_OBJECT_BUILDS, 0);
    GETI(RT_STAT_TOPLEVEL_BUILDS, 0);
#undef GETI
    for (k = 0; k < 4; k++)
        v[k] = -777;
    rtGetIntegerv(RT_VIEWPORT, v);
    CHECK(v[0] == 0 && v[1] == 0 && v[2] == 0 && v[3] == 0);
    for (k = 0; k < 4; k++)
        f[k] = -777.0f;
    rtGetFloatv(RT_VIEWPORT, f);
    CHECK(f[0] == 0.0f && f[1] == 0.0f && f[2] == 0.0f && f[3] == 0.0f);
    for (k = 0; k < 4; k++)
        f[k] = -777.0f;
    rtGetFloatv(RT_COLOR_CLEAR_VALUE, f);
    CHECK(f[0] == 0.0f && f[1] == 0.0f && f[2] == 0.0f && f[3] == 0.0f);
    rtGetFloatv(RT_LIGHT_MODEL_AMBIENT, f);
    CHECK_NEAR(f[0], 0.2, 1e-6);
    CHECK_NEAR(f[1], 0.2, 1e-6);
    CHECK_NEAR(f[2], 0.2, 1e-6);
    CHECK_NEAR(f[3], 1.0, 1e-6);
    {
        double id[16];
        tu_identity(id);
        CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, id, 0.0);
        CHECK_CURRENT_MATRIX(RT_PROJECTION_MATRIX, id, 0.0);
    }
    f[0] = -1.0f;
    rtGetFloatv(RT_STAT_RENDER_TIME, f);
    CHECK(f[0] >= 0.0f);
    CHECK_NO_ERR();

    tu_section("rtGetIntegerv/rtGetFloatv errors");
    tu_capture_errors();
    v[0] = -777;
    rtGetIntegerv(0x1234, v);
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK_MSG("rtGetIntegerv");
    CHECK_INT(v[0], -777);
    f[0] = -777.0f;
    rtGetFloatv(0x1234, f);
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK_MSG("rtGetFloatv");
    CHECK(f[0] == -777.0f);
    rtGetIntegerv(RT_MATRIX_MODE, NULL);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_MSG("rtGetIntegerv");
    rtGetFloatv(RT_MATRIX_MODE, NULL);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_MSG("rtGetFloatv");
    /* Matrices (and other float-only state) cannot be read as integers. */
    v[0] = -777;
    rtGetIntegerv(RT_MODELVIEW_MATRIX, v);
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK_INT(v[0], -777);
    rtGetIntegerv(RT_PROJECTION_MATRIX, v);
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK_INT(v[0], -777);
    /* So is the rest of the float-only state (docs/context.md). */
    {
        static const RTenum float_only[5] = {RT_COLOR_CLEAR_VALUE, RT_LIGHT_MODEL_AMBIENT,
                                             RT_STAT_BUILD_TIME, RT_STAT_TOPLEVEL_TIME,
                                             RT_STAT_RENDER_TIME};
        for (k = 0; k < 5; k++) {
            rtGetIntegerv(float_only[k], v);
            CHECK_ERR(RT_INVALID_ENUM);
            CHECK_INT(v[0], -777);
        }
    }
    /* Statistics counters are readable as integers and floats; times are floats. */
    rtGetFloatv(RT_STAT_BUILD_TIME, f);
    rtGetFloatv(RT_STAT_TOPLEVEL_TIME, f);
    CHECK_NO_ERR();

    /* Queries are allowed inside rtBegin/rtEnd. */
    tu_section("queries inside rtBegin");
    tu_begin_scratch(RT_TRIANGLES);
    v[0] = -777;
    rtGetIntegerv(RT_MATRIX_MODE, v);
    CHECK_INT(v[0], RT_MODELVIEW);
    rtGetFloatv(RT_MODELVIEW_MATRIX, f);
    CHECK(f[0] == 1.0f);
    CHECK_NO_ERR();
    tu_end_scratch();
    tu_destroy_context(ctx);
}

static void enable_disable(void)
{
    RTcontext ctx = tu_make_context("threads=1");
    int i;
    tu_section("rtEnable/rtDisable/rtIsEnabled");
    tu_capture_errors();
    for (i = 0; i < 8; i++)
        CHECK(rtIsEnabled(RT_LIGHT0 + (RTenum)i) == RT_FALSE);
    CHECK(rtIsEnabled(RT_COLOR_MATERIAL) == RT_FALSE);
    CHECK_NO_ERR();
    for (i = 0; i < 8; i++) {
        rtEnable(RT_LIGHT0 + (RTenum)i);
        CHECK(rtIsEnabled(RT_LIGHT0 + (RTenum)i) == RT_TRUE);
        rtDisable(RT_LIGHT0 + (RTenum)i);
        CHECK(rtIsEnabled(RT_LIGHT0 + (RTenum)i) == RT_FALSE);
    }
    rtEnable(RT_COLOR_MATERIAL);
    CHECK(rtIsEnabled(RT_COLOR_MATERIAL) == RT_TRUE);
    CHECK_NO_ERR();

    /* Bad caps: error, and nothing changes. */
    rtEnable(RT_LIGHT0 + 8);
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK_MSG("rtEnable");
    rtDisable(RT_LIGHT0 + 8);
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK_MSG("rtDisable");
    CHECK(rtIsEnabled(RT_LIGHT0 + 8) == RT_FALSE);
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK_MSG("rtIsEnabled");
    rtDisable(RT_VERTEX_ARRAY); /* a client-state array is not a capability */
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK(rtIsEnabled(RT_COLOR_MATERIAL) == RT_TRUE);
    CHECK_NO_ERR();

    /* Inside rtBegin: RT_INVALID_OPERATION, state unchanged. */
    tu_begin_scratch(RT_TRIANGLES);
    rtDisable(RT_COLOR_MATERIAL);
    CHECK_ERR(RT_INVALID_OPERATION);
    CHECK_MSG("rtDisable");
    rtEnable(RT_LIGHT0);
    CHECK_ERR(RT_INVALID_OPERATION);
    CHECK_MSG("rtEnable");
    CHECK(rtIsEnabled(RT_COLOR_MATERIAL) == RT_FALSE);
    CHECK_ERR(RT_INVALID_OPERATION);
    CHECK_MSG("rtIsEnabled");
    tu_end_scratch();
    CHECK(rtIsEnabled(RT_COLOR_MATERIAL) == RT_TRUE);
    CHECK(rtIsEnabled(RT_LIGHT0) == RT_FALSE);
    CHECK_NO_ERR();
    /* Allowed inside an object (outside rtBegin): recorded, as in a GL
     * display list, so it takes effect when the list is called. */
    rtNewObject(5);
    rtEnable(RT_LIGHT0 + 1);
    rtEndObject();
    CHECK(rtIsEnabled(RT_LIGHT0 + 1) == RT_FALSE);
    rtInstantiateObject(5);
    CHECK(rtIsEnabled(RT_LIGHT0 + 1) == RT_TRUE);
    CHECK_NO_ERR();
    tu_destroy_context(ctx);
}

/* ---- no current context ------------------------------------------------------ */

static void no_context_calls(void)
{
    RTint iv[4] = {-777, -777, -777, -777};
    RTfloat fv[16];
    RTuint names[2] = {0, 0};
    RTray ray = {{0, 0, 5}, 0, {0, 0, -1}, 100};
    RThit hit = {-1.0f, -1.0f, -1.0f, 7u, 7u, 7u};
    RTboolean occ = 77;
    unsigned char px[4] = {9, 9, 9, 9};
    int k;
    for (k = 0; k < 16; k++)
        fv[k] = -777.0f;
    tu_section("no current context");
    CHECK(rtGetCurrentContext() == NULL);
    /* Every entry point is a silent no-op; queries return 0 / NULL / RT_FALSE
     * and write nothing (a zero written is tolerated for the v-queries). */
    CHECK_INT(rtGetError(), RT_NO_ERROR);
    CHECK(rtGetString(RT_VERSION) == NULL);
    rtGetIntegerv(RT_MATRIX_MODE, iv);
    CHECK(iv[0] == -777 || iv[0] == 0);
    rtGetFloatv(RT_MODELVIEW_MATRIX, fv);
    CHECK(fv[0] == -777.0f || fv[0] == 0.0f);
    CHECK(rtIsEnabled(RT_LIGHT0) == RT_FALSE);
    CHECK(rtIsObject(1) == RT_FALSE);
    rtGenObjects(2, names);
    CHECK(names[0] == 0 && names[1] == 0);
    iv[0] = -777;
    rtGetObjectiv(1, RT_OBJECT_TRIANGLES, iv);
    CHECK(iv[0] == -777 || iv[0] == 0);
    rtGetObjectfv(1, RT_OBJECT_SAH_COST, fv);
    rtErrorCallback(NULL, NULL);
    rtEnable(RT_LIGHT0);
    rtDisable(RT_LIGHT0);
    rtNewObject(1);
    rtBegin(RT_TRIANGLES);
    rtVertex2f(0, 0);
    rtVertex2d(0, 0);
    rtVertex3f(0, 0, 0);
    rtVertex3d(0, 0, 0);
    rtVertex2fv(NULL);
    rtVertex2dv(NULL);
    rtVertex3fv(NULL);
    rtVertex3dv(NULL);
    rtNormal3f(0, 0, 1);
    rtNormal3fv(NULL);
    rtTexCoord2f(0, 0);
    rtTexCoord2fv(NULL);
    rtColor3f(1, 1, 1);
    rtColor3fv(NULL);
    rtColor4f(1, 1, 1, 1);
    rtColor4fv(NULL);
    rtShadeModel(RT_FLAT);
    rtEnd();
    rtEndObject();
    rtDeleteObjects(2, names);
    rtEnableClientState(RT_VERTEX_ARRAY);
    rtDisableClientState(RT_VERTEX_ARRAY);
    rtVertexPointer(3, RT_FLOAT, 0, NULL);
    rtNormalPointer(RT_FLOAT, 0, NULL);
    rtColorPointer(3, RT_FLOAT, 0, NULL);
    rtTexCoordPointer(2, RT_FLOAT, 0, NULL);
    rtDrawArrays(RT_TRIANGLES, 0, 3);
    rtDrawElements(RT_TRIANGLES, 3, RT_UNSIGNED_INT, NULL);
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtLoadMatrixf(NULL);
    rtLoadMatrixd(NULL);
    rtMultMatrixf(NULL);
    rtMultMatrixd(NULL);
    rtTranslatef(1, 2, 3);
    rtTranslated(1, 2, 3);
    rtRotatef(30, 0, 0, 1);
    rtRotated(30, 0, 0, 1);
    rtScalef(2, 2, 2);
    rtScaled(2, 2, 2);
    rtFrustum(-1, 1, -1, 1, 1, 10);
    rtOrtho(-1, 1, -1, 1, 1, 10);
    rtPushMatrix();
    rtPopMatrix();
    rtPopMatrix();
    rtInstantiateObject(1);
    rtBeginFrame();
    rtMaterialf(RT_FRONT, RT_SHININESS, 5);
    rtMaterialfv(RT_FRONT, RT_DIFFUSE, NULL);
    rtLightf(RT_LIGHT0, RT_CONSTANT_ATTENUATION, 1);
    rtLightfv(RT_LIGHT0, RT_DIFFUSE, NULL);
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, NULL);
    rtShadingMode(RT_WHITTED);
    rtRenderParameteri(RT_MAX_RAY_DEPTH, 5);
    rtViewport(0, 0, 4, 4);
    rtClearColor(1, 0, 0, 1);
    rtRenderFrame();
    rtFinish();
    rtReadPixels(0, 0, 1, 1, RT_RGBA, RT_UNSIGNED_BYTE, px);
    CHECK(px[0] == 9 && px[3] == 9);
    rtTraceRays(1, &ray, &hit);
    CHECK(hit.t == -1.0f && hit.object == 7u);
    rtOccludedRays(1, &ray, &occ);
    CHECK(occ == 77);
    rtMakeCurrent(NULL);
    CHECK(rtGetCurrentContext() == NULL);

    /* None of that reached a context made current afterwards. */
    {
        RTcontext ctx = tu_make_context("threads=1");
        double id[16];
        RTint v = -1;
        tu_identity(id);
        CHECK_INT(rtGetError(), RT_NO_ERROR);
        CHECK_CURRENT_MATRIX(RT_PROJECTION_MATRIX, id, 0.0);
        CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, id, 0.0);
        rtGetIntegerv(RT_MATRIX_MODE, &v);
        CHECK_INT(v, RT_MODELVIEW);
        CHECK(rtIsObject(1) == RT_FALSE);
        CHECK(rtIsEnabled(RT_LIGHT0) == RT_FALSE);
        tu_destroy_context(ctx);
    }
}

/* ---- current context per thread --------------------------------------------- */

struct thread_probe {
    RTcontext ctx;         /* context the thread tries to bind */
    RTcontext seen_before; /* rtGetCurrentContext() in the thread at start */
    RTboolean bound;       /* rtMakeCurrent(ctx) result */
};

static void *probe_thread(void *arg)
{
    struct thread_probe *p = (struct thread_probe *)arg;
    p->seen_before = rtGetCurrentContext();
    p->bound = rtMakeCurrent(p->ctx);
    if (p->bound)
        rtMakeCurrent(NULL);
    return NULL;
}

static void per_thread_current(void)
{
    RTcontext a, b;
    struct thread_probe p;
    pthread_t th;
    tu_section("current context is per thread");
    a = tu_make_context("threads=1");
    CHECK(rtGetCurrentContext() == a);

    /* Another thread starts with no context and cannot bind ours. */
    memset(&p, 0, sizeof p);
    p.ctx = a;
    CHECK(pthread_create(&th, NULL, probe_thread, &p) == 0);
    pthread_join(th, NULL);
    CHECK(p.seen_before == NULL);
    CHECK(p.bound == RT_FALSE);
    CHECK(rtGetCurrentContext() == a);

    /* Once we release it, the other thread may bind it (and release it). */
    rtMakeCurrent(NULL);
    CHECK(rtGetCurrentContext() == NULL);
    memset(&p, 0, sizeof p);
    p.ctx = a;
    CHECK(pthread_create(&th, NULL, probe_thread, &p) == 0);
    pthread_join(th, NULL);
    CHECK(p.bound == RT_TRUE);
    CHECK(rtMakeCurrent(a) == RT_TRUE);
    CHECK(rtGetCurrentContext() == a);
    /* Destroying the current context unbinds it. */
    rtDestroyContext(a);
    CHECK(rtGetCurrentContext() == NULL);

    a = tu_make_context("threads=1");
    b = rtCreateContext("threads=1");
    CHECK(b != NULL);
    CHECK(tu_define_quad(10, 0, 0, 1, 1, 0));
    rtPopMatrix(); /* error pending in a only */
    CHECK(rtMakeCurrent(b) == RT_TRUE);
    CHECK(rtGetCurrentContext() == b);
    CHECK_INT(rtGetError(), RT_NO_ERROR);
    CHECK(rtIsObject(10) == RT_FALSE);
    CHECK(rtMakeCurrent(a) == RT_TRUE);
    CHECK_ERR(RT_STACK_UNDERFLOW);
    CHECK(rtIsObject(10) == RT_TRUE);
    /* Binding a context that is current in this thread again is fine. */
    CHECK(rtMakeCurrent(a) == RT_TRUE);
    /* Destroying a context that is not current leaves the current one bound. */
    rtDestroyContext(b);
    CHECK(rtGetCurrentContext() == a);
    CHECK(rtIsObject(10) == RT_TRUE);
    tu_destroy_context(a);
}

static void get_error_semantics(void)
{
    RTcontext ctx = tu_make_context("threads=1");
    RTint depth = -1;
    tu_section("rtGetError keeps the first error");
    CHECK_INT(rtGetError(), RT_NO_ERROR);
    rtPopMatrix();                /* RT_STACK_UNDERFLOW */
    rtMatrixMode(0x1234);         /* RT_INVALID_ENUM, not stored */
    rtTranslatef(tu_nan(), 0, 0); /* RT_INVALID_VALUE, not stored */
    CHECK_INT(rtGetError(), RT_STACK_UNDERFLOW);
    CHECK_INT(rtGetError(), RT_NO_ERROR);
    rtGetIntegerv(RT_MODELVIEW_STACK_DEPTH, &depth);
    CHECK_INT(depth, 1);
    tu_destroy_context(ctx);
}

int main(void)
{
    config_strings();
    config_reasons();
    effective_configuration();
    strings();
    integer_defaults();
    enable_disable();
    no_context_calls();
    per_thread_current();
    get_error_semantics();
    return test_summary("context");
}
