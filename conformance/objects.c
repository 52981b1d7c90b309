/* SPDX-License-Identifier: Apache-2.0 */
/*
 * objects.c - conformance: rtGenObjects, rtNewObject/rtEndObject (nesting,
 * redefinition, the previous definition staying in use while recording),
 * rtDeleteObjects, rtIsObject, rtGetObjectiv/fv (triangle counts, lazy
 * builds, bounds) and RT_OBJECT_COUNT.
 *
 * Reference: docs/objects.md, docs/statistics.md.
 */
#include "testutil.h"

static RTint object_count(void)
{
    RTint n = -1;
    rtGetIntegerv(RT_OBJECT_COUNT, &n);
    return n;
}

static void gen_objects(void)
{
    RTuint a[8], b[8], sentinel[2] = {111, 222};
    int i, j;
    tu_section("rtGenObjects");
    for (i = 0; i < 8; i++)
        a[i] = b[i] = 0;
    rtGenObjects(8, a);
    rtGenObjects(8, b);
    CHECK_NO_ERR();
    for (i = 0; i < 8; i++) {
        CHECK(a[i] != 0 && b[i] != 0);
        /* A generated name is not yet an object. */
        CHECK(rtIsObject(a[i]) == RT_FALSE);
        for (j = 0; j < 8; j++) {
            if (j != i)
                CHECK(a[i] != a[j] && b[i] != b[j]);
            CHECK(a[i] != b[j]); /* never handed out twice */
        }
    }
    CHECK_INT(object_count(), 0);
    /* n == 0 is a no-op, also with NULL. */
    rtGenObjects(0, NULL);
    CHECK_NO_ERR();
    /* Errors write nothing. */
    rtGenObjects(-1, sentinel);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK(sentinel[0] == 111 && sentinel[1] == 222);
    rtGenObjects(2, NULL);
    CHECK_ERR(RT_INVALID_VALUE);

    /* Names the application chose itself are not handed out. */
    for (i = 1; i <= 16; i++)
        CHECK(tu_define_quad((RTuint)(1000 + i), 0, 0, 1, 1, 0));
    rtGenObjects(8, a);
    for (i = 0; i < 8; i++)
        CHECK(a[i] < 1001 || a[i] > 1016);
    /* A generated name becomes an object once defined. */
    CHECK(tu_define_quad(a[0], 0, 0, 1, 1, 0));
    CHECK(rtIsObject(a[0]) == RT_TRUE);
    {
        RTuint all[16];
        for (i = 0; i < 16; i++)
            all[i] = (RTuint)(1001 + i);
        rtDeleteObjects(16, all);
        rtDeleteObjects(1, a);
    }
    CHECK_INT(object_count(), 0);
    CHECK_NO_ERR();
}

static void new_end_object(void)
{
    RTint v = -1;
    tu_section("rtNewObject / rtEndObject");
    /* Name 0 is invalid and starts no recording. */
    rtNewObject(0);
    CHECK_ERR(RT_INVALID_VALUE);
    rtEndObject();
    CHECK_ERR(RT_INVALID_OPERATION);
    CHECK(rtIsObject(0) == RT_FALSE);

    /* Any non-zero name may be used without rtGenObjects. */
    CHECK(tu_define_quad(0xFFFFFFFEu, 0, 0, 1, 1, 0));
    CHECK(rtIsObject(0xFFFFFFFEu) == RT_TRUE);

    /* An empty definition is a valid object. */
    rtNewObject(20);
    CHECK(rtIsObject(20) == RT_FALSE); /* not defined until rtEndObject */
    rtEndObject();
    CHECK_NO_ERR();
    CHECK(rtIsObject(20) == RT_TRUE);
    CHECK_INT(tu_object_triangles(20), 0);
    {
        float bounds[6] = {9, 9, 9, 9, 9, 9};
        float sah = -1;
        int k;
        rtGetObjectfv(20, RT_OBJECT_BOUNDS, bounds);
        for (k = 0; k < 6; k++)
            CHECK(bounds[k] == 0.0f);
        rtGetObjectfv(20, RT_OBJECT_SAH_COST, &sah);
        CHECK(sah == 0.0f);
    }
    /* An rtBegin block with no vertex, or too few, gives no triangle. */
    rtNewObject(21);
    rtBegin(RT_TRIANGLES);
    rtEnd();
    rtBegin(RT_QUADS);
    rtVertex2f(0, 0);
    rtVertex2f(1, 0);
    rtVertex2f(1, 1);
    rtEnd();
    rtEndObject();
    CHECK_NO_ERR();
    CHECK_INT(tu_object_triangles(21), 0);

    /* Nested rtNewObject: error, the outer recording goes on. */
    rtNewObject(22);
    rtBegin(RT_TRIANGLES);
    rtVertex2f(0, 0);
    rtVertex2f(1, 0);
    rtVertex2f(0, 1);
    rtEnd();
    rtNewObject(23);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtBegin(RT_TRIANGLES);
    rtVertex2f(0, 0);
    rtVertex2f(1, 0);
    rtVertex2f(0, 1);
    rtEnd();
    rtEndObject();
    CHECK_NO_ERR();
    CHECK_INT(tu_object_triangles(22), 2);
    CHECK(rtIsObject(23) == RT_FALSE);
    /* Exactly one recording was open. */
    rtEndObject();
    CHECK_ERR(RT_INVALID_OPERATION);

    /* rtNewObject inside rtBegin: error, the block goes on. */
    rtNewObject(24);
    rtBegin(RT_TRIANGLES);
    rtVertex2f(0, 0);
    rtNewObject(25);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtVertex2f(1, 0);
    rtVertex2f(0, 1);
    /* rtEndObject inside rtBegin: error, nothing ends. */
    rtEndObject();
    CHECK_ERR(RT_INVALID_OPERATION);
    rtVertex2f(5, 0);
    rtVertex2f(6, 0);
    rtVertex2f(5, 1);
    rtEnd();
    rtEndObject();
    CHECK_NO_ERR();
    CHECK_INT(tu_object_triangles(24), 2);
    CHECK(rtIsObject(25) == RT_FALSE);

    /* Live object count. */
    v = object_count();
    CHECK_INT(v, 5); /* 0xFFFFFFFE, 20, 21, 22 and 24 */
}

static void redefinition(void)
{
    float bounds[6];
    tu_section("redefinition");
    CHECK(tu_define_quad(30, 0, 0, 1, 1, 0)); /* 2 triangles */
    rtNewObject(30);
    /* The previous definition stays in use while recording. */
    CHECK(rtIsObject(30) == RT_TRUE);
    CHECK_INT(tu_object_triangles(30), 2);
    rtBegin(RT_TRIANGLES);
    rtVertex3f(5, 5, 5);
    rtVertex3f(6, 5, 5);
    rtVertex3f(5, 6, 5);
    rtEnd();
    CHECK_INT(tu_object_triangles(30), 2);
    rtEndObject();
    CHECK_NO_ERR();
    CHECK_INT(tu_object_triangles(30), 1);
    rtGetObjectfv(30, RT_OBJECT_BOUNDS, bounds);
    CHECK_NEAR(bounds[0], 5, 0);
    CHECK_NEAR(bounds[4], 6, 0);
    /* Redefining as empty keeps the object, with no triangles. */
    rtNewObject(30);
    rtEndObject();
    CHECK(rtIsObject(30) == RT_TRUE);
    CHECK_INT(tu_object_triangles(30), 0);
    CHECK_NO_ERR();
    /* Redefinition does not change the object count. */
    {
        RTint before = object_count();
        CHECK(tu_define_quad(30, 0, 0, 1, 1, 0));
        CHECK_INT(object_count(), before);
    }
}

static void delete_objects(void)
{
    RTuint list[5];
    RTint before;
    tu_section("rtDeleteObjects");
    CHECK(tu_define_quad(40, 0, 0, 1, 1, 0));
    CHECK(tu_define_quad(41, 0, 0, 1, 1, 0));
    before = object_count();
    /* 0 and unknown names are ignored silently. */
    list[0] = 0;
    list[1] = 40;
    list[2] = 987654;
    list[3] = 40; /* twice */
    rtDeleteObjects(4, list);
    CHECK_NO_ERR();
    CHECK(rtIsObject(40) == RT_FALSE);
    CHECK(rtIsObject(41) == RT_TRUE);
    CHECK_INT(object_count(), before - 1);
    rtDeleteObjects(0, NULL);
    CHECK_NO_ERR();
    /* Errors delete nothing. */
    list[0] = 41;
    rtDeleteObjects(-1, list);
    CHECK_ERR(RT_INVALID_VALUE);
    rtDeleteObjects(1, NULL);
    CHECK_ERR(RT_INVALID_VALUE);
    rtNewObject(42);
    rtDeleteObjects(1, list);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtBegin(RT_TRIANGLES);
    rtDeleteObjects(1, list);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtEnd();
    rtEndObject();
    CHECK_NO_ERR();
    CHECK(rtIsObject(41) == RT_TRUE);
    CHECK(rtIsObject(42) == RT_TRUE);
    /* A deleted name is free: rtGetObjectiv fails, redefining works. */
    list[0] = 41;
    rtDeleteObjects(1, list);
    {
        RTint n = -5;
        rtGetObjectiv(41, RT_OBJECT_TRIANGLES, &n);
        CHECK_ERR(RT_INVALID_VALUE);
        CHECK_INT(n, -5);
    }
    CHECK(tu_define_quad(41, 0, 0, 2, 2, 0));
    CHECK(rtIsObject(41) == RT_TRUE);
    CHECK_INT(tu_object_triangles(41), 2);
    /* A generated, never-defined name can be deleted (freeing it). */
    rtGenObjects(1, list);
    rtDeleteObjects(1, list);
    CHECK_NO_ERR();
    CHECK(rtIsObject(list[0]) == RT_FALSE);
}

static void is_object(void)
{
    tu_section("rtIsObject");
    CHECK(tu_define_quad(50, 0, 0, 1, 1, 0));
    CHECK(rtIsObject(50) == RT_TRUE);
    CHECK(rtIsObject(0) == RT_FALSE);
    CHECK(rtIsObject(51) == RT_FALSE);
    CHECK(rtIsObject(0xFFFFFFFFu) == RT_FALSE);
    CHECK_NO_ERR();
    /* Inside an object: allowed. */
    rtNewObject(52);
    CHECK(rtIsObject(50) == RT_TRUE);
    CHECK_NO_ERR();
    /* Inside rtBegin: error, RT_FALSE even for an object. */
    rtBegin(RT_TRIANGLES);
    CHECK(rtIsObject(50) == RT_FALSE);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtEnd();
    rtEndObject();
    CHECK_NO_ERR();
}

static void object_queries(void)
{
    RTint iv[2];
    float fv[6];
    RThit h;
    float lo[3] = {-1, -2, -3}, hi[3] = {1, 2, 3};
    int k;
    tu_section("rtGetObjectiv / rtGetObjectfv");
    CHECK(tu_define_box(60, lo, hi));
    CHECK_INT(tu_object_triangles(60), 12);
    rtGetObjectfv(60, RT_OBJECT_BOUNDS, fv);
    for (k = 0; k < 3; k++) {
        CHECK_NEAR(fv[k], lo[k], 0);
        CHECK_NEAR(fv[3 + k], hi[k], 0);
    }
    /* Lazy construction: nothing is built before a ray needs it. */
    iv[0] = -1;
    rtGetObjectiv(60, RT_OBJECT_BUILT, iv);
    CHECK_INT(iv[0], RT_FALSE);
    iv[0] = -1;
    rtGetObjectiv(60, RT_OBJECT_BVH_NODES, iv);
    CHECK_INT(iv[0], 0);
    fv[0] = -1;
    rtGetObjectfv(60, RT_OBJECT_SAH_COST, fv);
    CHECK(fv[0] == 0.0f);
    CHECK(tu_define_grid(61, 8, 8, 100, 100, 101, 101, 0));
    CHECK_INT(tu_object_triangles(61), 128);
    /* Instantiating and finishing builds the top level only. */
    rtBeginFrame();
    rtInstantiateObject(60);
    rtInstantiateObject(61);
    rtFinish();
    CHECK_NO_ERR();
    rtGetObjectiv(60, RT_OBJECT_BUILT, iv);
    CHECK_INT(iv[0], RT_FALSE);
    /* A ray into the box builds the box but not the grid. */
    h = tu_trace(0, 0, 10, 0, 0, -1);
    CHECK_INT(h.object, 60);
    CHECK_NEAR(h.t, 7, 1e-5);
    rtGetObjectiv(60, RT_OBJECT_BUILT, iv);
    CHECK_INT(iv[0], RT_TRUE);
    rtGetObjectiv(60, RT_OBJECT_BVH_NODES, iv);
    CHECK(iv[0] >= 1);
    rtGetObjectfv(60, RT_OBJECT_SAH_COST, fv);
    CHECK(fv[0] > 0.0f);
    rtGetObjectfv(60, RT_OBJECT_BUILD_TIME, fv);
    CHECK(fv[0] >= 0.0f);
    rtGetObjectiv(61, RT_OBJECT_BUILT, iv);
    CHECK_INT(iv[0], RT_FALSE);
    iv[0] = -1;
    rtGetIntegerv(RT_STAT_OBJECT_BUILDS, iv);
    CHECK_INT(iv[0], 1);
    /* The next query builds nothing new. */
    h = tu_trace(0.5f, 0.5f, 10, 0, 0, -1);
    rtGetIntegerv(RT_STAT_OBJECT_BUILDS, iv);
    CHECK_INT(iv[0], 0);
    /* Now the grid. */
    h = tu_trace(100.3f, 100.6f, 10, 0, 0, -1);
    CHECK_INT(h.object, 61);
    rtGetObjectiv(61, RT_OBJECT_BUILT, iv);
    CHECK_INT(iv[0], RT_TRUE);
    rtGetIntegerv(RT_STAT_OBJECT_BUILDS, iv);
    CHECK_INT(iv[0], 1);
    CHECK_NO_ERR();
    /* Redefinition drops the build. */
    CHECK(tu_define_box(60, lo, hi));
    rtGetObjectiv(60, RT_OBJECT_BUILT, iv);
    CHECK_INT(iv[0], RT_FALSE);
    CHECK_NO_ERR();

    /* Errors write nothing. */
    iv[0] = -7;
    rtGetObjectiv(60, 0x1234, iv);
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK_INT(iv[0], -7);
    rtGetObjectiv(999, RT_OBJECT_TRIANGLES, iv);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_INT(iv[0], -7);
    rtGetObjectiv(0, RT_OBJECT_TRIANGLES, iv);
    CHECK_ERR(RT_INVALID_VALUE);
    rtGetObjectiv(60, RT_OBJECT_TRIANGLES, NULL);
    CHECK_ERR(RT_INVALID_VALUE);
    fv[0] = -7;
    rtGetObjectfv(60, RT_MATRIX_MODE, fv);
    CHECK_ERR(RT_INVALID_ENUM);
    rtGetObjectfv(999, RT_OBJECT_BOUNDS, fv);
    CHECK_ERR(RT_INVALID_VALUE);
    rtGetObjectfv(60, RT_OBJECT_BOUNDS, NULL);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK(fv[0] == -7.0f);
    /* A generated but undefined name is not an object. */
    {
        RTuint g = 0;
        rtGenObjects(1, &g);
        rtGetObjectiv(g, RT_OBJECT_TRIANGLES, iv);
        CHECK_ERR(RT_INVALID_VALUE);
    }
    /* Integer properties convert to float; float-only ones are not integers. */
    fv[0] = -7;
    rtGetObjectfv(60, RT_OBJECT_TRIANGLES, fv);
    CHECK_NO_ERR();
    CHECK(fv[0] == 12.0f);
    rtGetObjectfv(60, RT_OBJECT_BUILT, fv);
    CHECK(fv[0] == 0.0f);
    iv[0] = -7;
    rtGetObjectiv(60, RT_OBJECT_SAH_COST, iv);
    CHECK_ERR(RT_INVALID_ENUM);
    rtGetObjectiv(60, RT_OBJECT_BUILD_TIME, iv);
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK_INT(iv[0], -7);
    /* The enum is checked before the name (STYLE.md sec. 3 order). */
    rtGetObjectiv(999, 0x1234, iv);
    CHECK_ERR(RT_INVALID_ENUM);
}

static void count_and_scale(void)
{
    RTint before = object_count();
    int i;
    tu_section("many objects");
    for (i = 0; i < 500; i++) {
        rtNewObject((RTuint)(5000 + i));
        rtBegin(RT_TRIANGLES);
        rtVertex3f((float)i, 0, 0);
        rtVertex3f((float)i + 1, 0, 0);
        rtVertex3f((float)i, 1, 0);
        rtEnd();
        rtEndObject();
    }
    CHECK_NO_ERR();
    CHECK_INT(object_count(), before + 500);
    for (i = 0; i < 500; i += 2) {
        RTuint n = (RTuint)(5000 + i);
        rtDeleteObjects(1, &n);
    }
    CHECK_INT(object_count(), before + 250);
    CHECK(rtIsObject(5001) == RT_TRUE);
    CHECK(rtIsObject(5002) == RT_FALSE);
    CHECK_NO_ERR();
}

int main(void)
{
    RTcontext ctx = tu_make_context("threads=1");
    tu_capture_errors();
    gen_objects();
    new_end_object();
    redefinition();
    delete_objects();
    is_object();
    object_queries();
    count_and_scale();
    tu_destroy_context(ctx);
    return test_summary("objects");
}
