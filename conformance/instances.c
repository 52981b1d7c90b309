/* SPDX-License-Identifier: Apache-2.0 */
/*
 * instances.c - conformance: rtInstantiateObject and immediate-mode frames.
 *
 * Instance and object ids in hits, the instance matrix captured at the call,
 * redefinition showing in existing instances, deletion removing them, the
 * frame rules (the list issued since the last rtRenderFrame is the scene;
 * no new instance keeps the scene; rtBeginFrame starts an empty list) and
 * the top-level statistics: re-issuing an identical list costs no top-level
 * build, moving one instance costs one.
 *
 * Reference: docs/instances.md.
 */
#include "testutil.h"

#include <math.h>
#include <stdio.h>

#define A 300u
#define B 301u

static RTint geti(RTenum pname)
{
    RTint v = -12345;
    rtGetIntegerv(pname, &v);
    return v;
}

static void instantiate_errors(void)
{
    RTint count;
    RThit h;
    tu_section("rtInstantiateObject errors change nothing");
    CHECK(tu_define_quad(A, 0, 0, 1, 1, 0));
    rtBeginFrame();
    rtInstantiateObject(A);
    CHECK_NO_ERR();
    /* Not an object: ignored without an error, as glCallList. */
    rtInstantiateObject(0);
    CHECK_NO_ERR();
    rtInstantiateObject(9999);
    CHECK_NO_ERR();
    {
        RTuint g = 0;
        rtGenObjects(1, &g);
        rtInstantiateObject(g); /* generated, never defined */
        CHECK_NO_ERR();
    }
    /* Singular modelview. */
    rtPushMatrix();
    rtScalef(1, 1, 0);
    rtInstantiateObject(A);
    CHECK_ERR(RT_INVALID_VALUE);
    rtLoadIdentity();
    {
        static const double rank2[16] = {1, 2, 0, 0, 2, 4, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        rtLoadMatrixd(rank2);
        rtInstantiateObject(A);
        CHECK_ERR(RT_INVALID_VALUE);
    }
    /* A modelview whose inverse is not finite. */
    rtLoadIdentity();
    rtScaled(1e-310, 1, 1);
    rtInstantiateObject(A);
    CHECK_ERR(RT_INVALID_VALUE);
    rtPopMatrix();
    /* Inside an object it records a call (docs/lists.md); inside rtBegin
     * it is an error. */
    rtNewObject(B);
    rtInstantiateObject(A);
    CHECK_NO_ERR();
    rtBegin(RT_TRIANGLES);
    rtInstantiateObject(A);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtEnd();
    rtEndObject();
    CHECK_NO_ERR();
    rtFinish();
    CHECK_NO_ERR();
    count = geti(RT_INSTANCE_COUNT);
    CHECK_INT(count, 1);
    /* The only instance is A at the identity. */
    h = tu_trace_down(0.5f, 0.5f);
    CHECK_INT(h.object, A);
    CHECK_INT(h.instance, 0);
    CHECK_NEAR(h.t, 10, 1e-5);
    /* B (empty) was never instantiated: nothing else is hit. */
    h = tu_trace_down(5, 5);
    CHECK(h.t == tu_inf());
    /* rtBeginFrame inside an object: error, the scene is unchanged. */
    rtNewObject(B);
    rtBeginFrame();
    CHECK_ERR(RT_INVALID_OPERATION);
    rtEndObject();
    rtFinish();
    h = tu_trace_down(0.5f, 0.5f);
    CHECK_INT(h.object, A);
    CHECK_NO_ERR();
}

static void ids_and_matrices(void)
{
    RThit h;
    tu_section("instance ids, object ids, instance matrices");
    CHECK(tu_define_quad(A, 0, 0, 1, 1, 0));
    CHECK(tu_define_box(B, (const float[3]){0, 0, 0}, (const float[3]){1, 1, 1}));
    rtBeginFrame();
    rtLoadIdentity();
    rtPushMatrix();
    rtTranslatef(0, 0, 0);
    rtInstantiateObject(A); /* instance 0: quad at x in [0,1] */
    rtTranslatef(2, 0, 0);
    rtInstantiateObject(B); /* instance 1: box at x in [2,3] */
    rtTranslatef(2, 0, 0);
    rtInstantiateObject(A); /* instance 2: quad at x in [4,5] */
    rtPopMatrix();
    rtPushMatrix();
    rtTranslatef(6, 0, 0);
    rtScalef(2, 1, 0.5f);   /* non-uniform scale */
    rtInstantiateObject(B); /* instance 3: box x in [6,8], z in [0,0.5] */
    rtPopMatrix();
    /* The matrix is captured at the call: this does not move instance 3. */
    rtTranslatef(100, 0, 0);
    rtLoadIdentity();
    rtFinish();
    CHECK_NO_ERR();
    CHECK_INT(geti(RT_INSTANCE_COUNT), 4);
    h = tu_trace_down(0.5f, 0.5f);
    CHECK_INT(h.instance, 0);
    CHECK_INT(h.object, A);
    CHECK_NEAR(h.t, 10, 1e-5);
    h = tu_trace_down(2.5f, 0.5f);
    CHECK_INT(h.instance, 1);
    CHECK_INT(h.object, B);
    CHECK_NEAR(h.t, 9, 1e-5);
    h = tu_trace_down(4.5f, 0.5f);
    CHECK_INT(h.instance, 2);
    CHECK_INT(h.object, A);
    /* Through a non-uniformly scaled instance t stays in world units. */
    h = tu_trace_down(7.5f, 0.5f);
    CHECK_INT(h.instance, 3);
    CHECK_INT(h.object, B);
    CHECK_NEAR(h.t, 9.5, 1e-5);
    h = tu_trace(7.5f, 0.5f, 10, 0, 0, -4); /* t in units of dir */
    CHECK_NEAR(h.t, 9.5 / 4, 1e-5);
    h = tu_trace(5.5f, 0.5f, 0.25f, 1, 0, 0); /* from the side: face x = 6 */
    CHECK_INT(h.instance, 3);
    CHECK_NEAR(h.t, 0.5, 1e-5);
    h = tu_trace_down(100.5f, 0.5f);
    CHECK(h.t == tu_inf());
    /* u, v and primitive ids are those of the object's own triangles. */
    {
        static const float a[3] = {4, 0, 0}, b[3] = {5, 0, 0}, c[3] = {5, 1, 0}, d[3] = {4, 1, 0};
        CHECK_TRIANGLE(a, b, c, 0, A, 2);
        CHECK_TRIANGLE(a, c, d, 1, A, 2);
    }
    /* A rotated instance: the quad rotated 90 degrees about z. */
    rtBeginFrame();
    rtPushMatrix();
    rtTranslatef(10, 0, 0);
    rtRotatef(90, 0, 0, 1); /* (x, y) -> (-y, x) */
    rtInstantiateObject(A);
    rtPopMatrix();
    rtFinish();
    {
        static const float a[3] = {10, 0, 0}, b[3] = {10, 1, 0}, c[3] = {9, 1, 0}, d[3] = {9, 0, 0};
        CHECK_TRIANGLE(a, b, c, 0, A, 0);
        CHECK_TRIANGLE(a, c, d, 1, A, 0);
    }
    CHECK_NO_ERR();
}

static void redefine_and_delete(void)
{
    RThit h;
    RTuint name;
    tu_section("redefinition shows in instances; deletion removes them");
    CHECK(tu_define_quad(A, 0, 0, 1, 1, 0));
    CHECK(tu_define_quad(B, 0, 0, 1, 1, 0));
    rtBeginFrame();
    rtInstantiateObject(A);
    rtPushMatrix();
    rtTranslatef(3, 0, 0);
    rtInstantiateObject(B);
    rtInstantiateObject(A); /* instance 2: A at x + 3, coincides with B but 1 unit up */
    rtPopMatrix();
    rtFinish();
    CHECK_NO_ERR();
    /* Redefine A without re-issuing anything: both instances of A change. */
    CHECK(tu_define_quad(A, 0, 0, 1, 1, 1)); /* now at z = 1 */
    h = tu_trace_down(0.5f, 0.5f);
    CHECK_INT(h.object, A);
    CHECK_INT(h.instance, 0);
    CHECK_NEAR(h.t, 9, 1e-5);
    h = tu_trace_down(3.5f, 0.5f);
    CHECK_INT(h.object, A);
    CHECK_INT(h.instance, 2);
    CHECK_NEAR(h.t, 9, 1e-5);
    /* The same after rtFinish and after a render. */
    rtFinish();
    h = tu_trace_down(0.5f, 0.5f);
    CHECK_NEAR(h.t, 9, 1e-5);
    rtRenderFrame();
    h = tu_trace_down(0.5f, 0.5f);
    CHECK_NEAR(h.t, 9, 1e-5);
    /* Redefined as empty: the instances are still there but hit nothing. */
    rtNewObject(A);
    rtEndObject();
    h = tu_trace_down(0.5f, 0.5f);
    CHECK(h.t == tu_inf());
    h = tu_trace_down(3.5f, 0.5f);
    CHECK_INT(h.object, B);
    CHECK_NEAR(h.t, 10, 1e-5);
    CHECK(tu_define_quad(A, 0, 0, 1, 1, 1));
    /* Deleting A removes its instances from the scene; B, issued between
     * them, moves up to instance 0. */
    name = A;
    rtDeleteObjects(1, &name);
    CHECK_NO_ERR();
    h = tu_trace_down(0.5f, 0.5f);
    CHECK(h.t == tu_inf());
    CHECK(h.object == RT_INVALID_ID);
    h = tu_trace_down(3.5f, 0.5f);
    CHECK_INT(h.object, B);
    CHECK_INT(h.instance, 0);
    CHECK_NEAR(h.t, 10, 1e-5);
    CHECK_INT(geti(RT_INSTANCE_COUNT), 1);
    rtFinish();
    rtRenderFrame();
    h = tu_trace_down(0.5f, 0.5f);
    CHECK(h.t == tu_inf());
    /* A new object under the deleted name does not bring the old instances back. */
    CHECK(tu_define_quad(A, 0, 0, 1, 1, 0));
    rtFinish();
    h = tu_trace_down(0.5f, 0.5f);
    CHECK(h.t == tu_inf());
    CHECK_NO_ERR();
}

static void frames(void)
{
    RThit h;
    int i;
    tu_section("immediate-mode frames");
    CHECK(tu_define_quad(A, 0, 0, 1, 1, 0));
    CHECK(tu_define_quad(B, 0, 0, 1, 1, 0));
    tu_ortho_camera();
    rtViewport(0, 0, 4, 4);

    /* Frame 1: A at the origin. */
    rtBeginFrame();
    rtInstantiateObject(A);
    rtRenderFrame();
    CHECK_NO_ERR();
    CHECK_INT(geti(RT_INSTANCE_COUNT), 1);
    /* Frame 2: nothing issued: the scene stays (and nothing is rebuilt). */
    rtRenderFrame();
    CHECK_INT(geti(RT_STAT_TOPLEVEL_BUILDS), 0);
    CHECK_INT(geti(RT_INSTANCE_COUNT), 1);
    h = tu_trace_down(0.5f, 0.5f);
    CHECK_INT(h.object, A);
    /* Frame 3: the identical list again: no top-level build. */
    rtInstantiateObject(A);
    rtRenderFrame();
    CHECK_INT(geti(RT_STAT_TOPLEVEL_BUILDS), 0);
    CHECK_INT(geti(RT_INSTANCE_COUNT), 1);
    /* Frame 4: A moved: one top-level build; the new list replaced the old. */
    rtPushMatrix();
    rtTranslatef(2, 0, 0);
    rtInstantiateObject(A);
    rtPopMatrix();
    rtRenderFrame();
    CHECK_INT(geti(RT_STAT_TOPLEVEL_BUILDS), 1);
    CHECK_INT(geti(RT_INSTANCE_COUNT), 1);
    h = tu_trace_down(0.5f, 0.5f);
    CHECK(h.t == tu_inf());
    h = tu_trace_down(2.5f, 0.5f);
    CHECK_INT(h.object, A);
    CHECK_INT(h.instance, 0);
    /* Frame 5: two instances, then frame 6 the same two in the other order:
     * not identical, one build each. */
    rtInstantiateObject(A);
    rtInstantiateObject(B);
    rtRenderFrame();
    CHECK_INT(geti(RT_STAT_TOPLEVEL_BUILDS), 1);
    CHECK_INT(geti(RT_INSTANCE_COUNT), 2);
    rtInstantiateObject(B);
    rtInstantiateObject(A);
    rtRenderFrame();
    CHECK_INT(geti(RT_STAT_TOPLEVEL_BUILDS), 1);
    /* A and B coincide; whichever is hit, its instance id follows the new order. */
    h = tu_trace_down(0.5f, 0.5f);
    CHECK((h.object == B && h.instance == 0) || (h.object == A && h.instance == 1));
    rtInstantiateObject(B);
    rtInstantiateObject(A);
    rtRenderFrame();
    CHECK_INT(geti(RT_STAT_TOPLEVEL_BUILDS), 0);
    /* A tiny move still counts as a change. */
    rtInstantiateObject(B);
    rtPushMatrix();
    rtTranslatef(0, 0, 1e-3f);
    rtInstantiateObject(A);
    rtPopMatrix();
    rtRenderFrame();
    CHECK_INT(geti(RT_STAT_TOPLEVEL_BUILDS), 1);
    h = tu_trace_down(0.5f, 0.5f);
    CHECK_INT(h.object, A);
    CHECK_INT(h.instance, 1);
    /* Same with rtFinish ending frames through rtBeginFrame. */
    rtBeginFrame();
    rtInstantiateObject(B);
    rtFinish();
    CHECK_INT(geti(RT_STAT_TOPLEVEL_BUILDS), 1);
    rtBeginFrame();
    rtInstantiateObject(B);
    rtFinish();
    CHECK_INT(geti(RT_STAT_TOPLEVEL_BUILDS), 0);
    rtRenderFrame();
    CHECK_INT(geti(RT_STAT_TOPLEVEL_BUILDS), 0);
    /* rtFinish commits but does not end the frame: later instances append. */
    rtBeginFrame();
    rtInstantiateObject(A);
    rtFinish();
    rtPushMatrix();
    rtTranslatef(2, 0, 0);
    rtInstantiateObject(B);
    rtPopMatrix();
    rtFinish();
    CHECK_INT(geti(RT_INSTANCE_COUNT), 2);
    h = tu_trace_down(0.5f, 0.5f);
    CHECK_INT(h.object, A);
    CHECK_INT(h.instance, 0);
    h = tu_trace_down(2.5f, 0.5f);
    CHECK_INT(h.object, B);
    CHECK_INT(h.instance, 1);
    /* Queries trace the list described so far, without rtFinish ... */
    rtBeginFrame();
    rtInstantiateObject(B);
    h = tu_trace_down(0.5f, 0.5f);
    CHECK_INT(h.object, B);
    CHECK_INT(geti(RT_INSTANCE_COUNT), 1);
    /* ... and right after rtRenderFrame the next instance starts a new list
     * that queries already see. */
    rtRenderFrame();
    rtPushMatrix();
    rtTranslatef(2, 0, 0);
    rtInstantiateObject(A);
    rtPopMatrix();
    h = tu_trace_down(0.5f, 0.5f);
    CHECK(h.t == tu_inf());
    h = tu_trace_down(2.5f, 0.5f);
    CHECK_INT(h.object, A);
    CHECK_INT(h.instance, 0);
    rtRenderFrame();
    CHECK_NO_ERR();
    /* An empty list through rtBeginFrame. */
    rtBeginFrame();
    rtFinish();
    CHECK_INT(geti(RT_INSTANCE_COUNT), 0);
    h = tu_trace_down(0.5f, 0.5f);
    CHECK(h.t == tu_inf());
    CHECK(h.instance == RT_INVALID_ID);
    /* Many instances, reissued unchanged over several frames. */
    for (i = 0; i < 3; i++) {
        int k;
        for (k = 0; k < 200; k++) {
            rtPushMatrix();
            rtTranslatef((float)(k % 20) * 2.0f, (float)(k / 20) * 2.0f, 0);
            rtInstantiateObject(k % 2 ? A : B);
            rtPopMatrix();
        }
        rtRenderFrame();
        CHECK_INT(geti(RT_STAT_TOPLEVEL_BUILDS), i == 0 ? 1 : 0);
        CHECK_INT(geti(RT_INSTANCE_COUNT), 200);
    }
    h = tu_trace_down(2.0f * 7 + 0.5f, 2.0f * 3 + 0.5f);
    CHECK_INT(h.instance, 67); /* k = 3 * 20 + 7 */
    CHECK_INT(h.object, A);
    CHECK_NO_ERR();
    rtViewport(0, 0, 0, 0);
}

int main(void)
{
    RTcontext ctx = tu_make_context("threads=2");
    tu_capture_errors();
    instantiate_errors();
    ids_and_matrices();
    redefine_and_delete();
    frames();
    tu_destroy_context(ctx);
    return test_summary("instances");
}
