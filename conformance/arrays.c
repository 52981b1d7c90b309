/* SPDX-License-Identifier: Apache-2.0 */
/*
 * arrays.c - conformance: vertex arrays.  rtEnableClientState/
 * rtDisableClientState, rtVertexPointer/rtNormalPointer/rtColorPointer/
 * rtTexCoordPointer (sizes, types, strides, errors that keep the previous
 * pointer), rtDrawArrays and rtDrawElements (every mode and index type)
 * compared with the equivalent rtBegin/rtVertex object, and the rule that
 * arrays are copied at the call.
 *
 * Reference: docs/arrays.md.
 */
#include "testutil.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define REF 200u /* built with rtBegin/rtVertex */
#define ARR 201u /* built from arrays */

/* The test polygon: a fan/polygon-friendly convex-ish ring of 7 points at
 * half-integer coordinates (so they are exact in every vertex type after
 * scaling by 2), in the plane z = 0. */
#define NV 7
static const float ring[NV][3] = {{0, 0, 0},     {2, 0, 0},   {2.5f, 1, 0}, {1.5f, 2, 0},
                                  {0.5f, 2.5f, 0}, {-1, 2, 0}, {-1.5f, 0.5f, 0}};

/* Zigzag for strips (even bottom, odd top). */
static const float zig[NV][3] = {{0, 0, 0}, {0, 1, 0},  {1, 0, 0},  {1.5f, 1, 0},
                                 {2, 0, 0}, {3, 1, 0},  {3.5f, 0, 0}};

static const RTenum modes[6] = {RT_TRIANGLES, RT_TRIANGLE_STRIP, RT_TRIANGLE_FAN,
                                RT_QUADS,     RT_QUAD_STRIP,     RT_POLYGON};
static const char *const mode_names[6] = {"RT_TRIANGLES", "RT_TRIANGLE_STRIP",
                                          "RT_TRIANGLE_FAN", "RT_QUADS", "RT_QUAD_STRIP",
                                          "RT_POLYGON"};

static const float (*verts_for(RTenum mode))[3]
{
    return (mode == RT_TRIANGLE_STRIP || mode == RT_QUAD_STRIP) ? zig : ring;
}

static void define_reference(RTenum mode, const float (*v)[3], int first, int count)
{
    int k;
    rtNewObject(REF);
    rtBegin(mode);
    for (k = first; k < first + count; k++)
        rtVertex3fv(v[k]);
    rtEnd();
    rtEndObject();
}

/*
 * Compares ARR with REF: same triangle count, and the same hit (primitive,
 * t, u, v) for a grid of rays over the test area.  Each object is put alone
 * in the scene in turn.
 */
#define GRID 24
static int compare_with_reference(const char *what)
{
    static RThit ref_hits[GRID * GRID], arr_hits[GRID * GRID];
    RTray rays[GRID * GRID];
    int i, j, ok = 1, hits = 0;
    for (j = 0; j < GRID; j++)
        for (i = 0; i < GRID; i++)
            rays[j * GRID + i] = tu_ray(-2.0f + 6.0f * ((float)i + 0.37f) / GRID,
                                        -0.5f + 4.0f * ((float)j + 0.61f) / GRID, 3, 0, 0, -1);
    ok &= CHECK_INT(tu_object_triangles(ARR), tu_object_triangles(REF));
    CHECK(tu_scene1(REF));
    rtTraceRays(GRID * GRID, rays, ref_hits);
    CHECK(tu_scene1(ARR));
    rtTraceRays(GRID * GRID, rays, arr_hits);
    CHECK_NO_ERR();
    for (i = 0; i < GRID * GRID; i++) {
        const RThit *a = &ref_hits[i], *b = &arr_hits[i];
        if (a->primitive != RT_INVALID_ID)
            hits++;
        if (a->primitive != b->primitive || a->t != b->t || fabsf(a->u - b->u) > 1e-6f ||
            fabsf(a->v - b->v) > 1e-6f) {
            ok &= tu_check(0, __FILE__, __LINE__, "array object hit == reference hit");
            fprintf(stderr, "    %s, ray %d: reference prim %u t %g u %g v %g, array prim %u t %g u %g v %g\n",
                    what, i, a->primitive, a->t, a->u, a->v, b->primitive, b->t, b->u, b->v);
            break;
        }
    }
    /* The comparison must not be vacuous. */
    ok &= tu_check(hits > 20 || tu_object_triangles(REF) == 0, __FILE__, __LINE__,
                   "reference object is hit");
    if (!ok)
        fprintf(stderr, "    in: %s\n", what);
    return ok;
}

static void client_state_and_pointers(void)
{
    static const float good[NV][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    static const float other[NV][3] = {{5, 5, 0}, {6, 5, 0}, {5, 6, 0}};
    tu_section("client state and pointer errors");
    rtEnableClientState(0x1234);
    CHECK_ERR(RT_INVALID_ENUM);
    rtEnableClientState(RT_LIGHT0);
    CHECK_ERR(RT_INVALID_ENUM);
    rtDisableClientState(RT_COLOR_MATERIAL);
    CHECK_ERR(RT_INVALID_ENUM);
    rtEnableClientState(RT_VERTEX_ARRAY);
    rtEnableClientState(RT_NORMAL_ARRAY);
    rtEnableClientState(RT_COLOR_ARRAY);
    rtEnableClientState(RT_TEXTURE_COORD_ARRAY);
    rtDisableClientState(RT_NORMAL_ARRAY);
    rtDisableClientState(RT_COLOR_ARRAY);
    rtDisableClientState(RT_TEXTURE_COORD_ARRAY);
    CHECK_NO_ERR();

    /* A valid pointer, then failing calls: the valid one stays. */
    rtVertexPointer(3, RT_FLOAT, 0, good);
    rtVertexPointer(1, RT_FLOAT, 0, other);
    CHECK_ERR(RT_INVALID_VALUE);
    rtVertexPointer(5, RT_FLOAT, 0, other);
    CHECK_ERR(RT_INVALID_VALUE);
    rtVertexPointer(3, RT_FLOAT, -12, other);
    CHECK_ERR(RT_INVALID_VALUE);
    rtVertexPointer(3, RT_UNSIGNED_BYTE, 0, other);
    CHECK_ERR(RT_INVALID_ENUM);
    rtVertexPointer(3, RT_BYTE, 0, other);
    CHECK_ERR(RT_INVALID_ENUM);
    rtVertexPointer(3, RT_UNSIGNED_INT, 0, other);
    CHECK_ERR(RT_INVALID_ENUM);
    rtVertexPointer(5, RT_BYTE, 0, other); /* enum before value */
    CHECK_ERR(RT_INVALID_ENUM);
    rtNewObject(ARR);
    rtBegin(RT_TRIANGLES);
    rtVertexPointer(3, RT_FLOAT, 0, other);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtEnableClientState(RT_VERTEX_ARRAY);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtDisableClientState(RT_VERTEX_ARRAY);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtEnd();
    rtDrawArrays(RT_TRIANGLES, 0, 3);
    rtEndObject();
    CHECK_NO_ERR();
    CHECK_INT(tu_object_triangles(ARR), 1);
    CHECK(tu_scene1(ARR));
    CHECK_TRIANGLE(good[0], good[1], good[2], 0, ARR, 0);

    /* Other pointers' errors. */
    rtNormalPointer(RT_UNSIGNED_BYTE, 0, other);
    CHECK_ERR(RT_INVALID_ENUM);
    rtNormalPointer(RT_UNSIGNED_SHORT, 0, other);
    CHECK_ERR(RT_INVALID_ENUM);
    rtNormalPointer(RT_FLOAT, -1, other);
    CHECK_ERR(RT_INVALID_VALUE);
    rtColorPointer(2, RT_FLOAT, 0, other);
    CHECK_ERR(RT_INVALID_VALUE);
    rtColorPointer(5, RT_FLOAT, 0, other);
    CHECK_ERR(RT_INVALID_VALUE);
    rtColorPointer(4, RT_SHORT, 0, other);
    CHECK_ERR(RT_INVALID_ENUM);
    rtColorPointer(4, RT_FLOAT, -4, other);
    CHECK_ERR(RT_INVALID_VALUE);
    rtTexCoordPointer(0, RT_FLOAT, 0, other);
    CHECK_ERR(RT_INVALID_VALUE);
    rtTexCoordPointer(5, RT_FLOAT, 0, other);
    CHECK_ERR(RT_INVALID_VALUE);
    rtTexCoordPointer(2, RT_BYTE, 0, other);
    CHECK_ERR(RT_INVALID_ENUM);
    rtTexCoordPointer(2, RT_FLOAT, -2, other);
    CHECK_ERR(RT_INVALID_VALUE);
    /* Every valid size/type combination is accepted. */
    {
        static const RTenum vtypes[4] = {RT_SHORT, RT_INT, RT_FLOAT, RT_DOUBLE};
        static const RTenum ntypes[5] = {RT_BYTE, RT_SHORT, RT_INT, RT_FLOAT, RT_DOUBLE};
        static const RTenum ctypes[3] = {RT_UNSIGNED_BYTE, RT_FLOAT, RT_DOUBLE};
        int s, t;
        for (t = 0; t < 4; t++) {
            for (s = 2; s <= 4; s++)
                rtVertexPointer(s, vtypes[t], 0, other);
            for (s = 1; s <= 4; s++)
                rtTexCoordPointer(s, vtypes[t], 8, other);
        }
        for (t = 0; t < 5; t++)
            rtNormalPointer(ntypes[t], 0, other);
        for (t = 0; t < 3; t++)
            for (s = 3; s <= 4; s++)
                rtColorPointer(s, ctypes[t], 0, other);
        /* NULL pointers are accepted here; drawing checks them. */
        rtVertexPointer(3, RT_FLOAT, 0, NULL);
        rtNormalPointer(RT_FLOAT, 0, NULL);
        rtColorPointer(3, RT_FLOAT, 0, NULL);
        rtTexCoordPointer(2, RT_FLOAT, 0, NULL);
        CHECK_NO_ERR();
    }
    rtDisableClientState(RT_VERTEX_ARRAY);
}

static void draw_errors(void)
{
    static const float v[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    static const RTubyte idx[3] = {0, 1, 2};
    float bad[4][3];
    double badd[4][3];
    tu_section("rtDrawArrays / rtDrawElements errors");
    rtVertexPointer(3, RT_FLOAT, 0, v);
    rtEnableClientState(RT_VERTEX_ARRAY);
    /* Outside an object: immediate mode (docs/lists.md), no error. */
    rtBeginFrame();
    rtDrawArrays(RT_TRIANGLES, 0, 3);
    CHECK_NO_ERR();
    rtDrawElements(RT_TRIANGLES, 3, RT_UNSIGNED_BYTE, idx);
    CHECK_NO_ERR();
    rtBeginFrame();

    rtNewObject(ARR);
    rtDrawArrays(RT_TRIANGLES, 0, 3); /* triangle 0 */
    CHECK_NO_ERR();
    rtDrawArrays(0x1234, 0, 3);
    CHECK_ERR(RT_INVALID_ENUM);
    rtDrawArrays(RT_TRIANGLES, -1, 3);
    CHECK_ERR(RT_INVALID_VALUE);
    rtDrawArrays(RT_TRIANGLES, 0, -3);
    CHECK_ERR(RT_INVALID_VALUE);
    rtDrawElements(0x1234, 3, RT_UNSIGNED_BYTE, idx);
    CHECK_ERR(RT_INVALID_ENUM);
    rtDrawElements(RT_TRIANGLES, 3, RT_BYTE, idx);
    CHECK_ERR(RT_INVALID_ENUM);
    rtDrawElements(RT_TRIANGLES, 3, RT_FLOAT, idx);
    CHECK_ERR(RT_INVALID_ENUM);
    rtDrawElements(RT_TRIANGLES, -1, RT_UNSIGNED_BYTE, idx);
    CHECK_ERR(RT_INVALID_VALUE);
    rtDrawElements(RT_TRIANGLES, 3, RT_UNSIGNED_BYTE, NULL);
    CHECK_ERR(RT_INVALID_VALUE);
    /* count 0 draws nothing and is no error. */
    rtDrawArrays(RT_TRIANGLES, 0, 0);
    rtDrawElements(RT_TRIANGLES, 0, RT_UNSIGNED_INT, idx);
    CHECK_NO_ERR();
    /* Inside rtBegin. */
    rtBegin(RT_TRIANGLES);
    rtDrawArrays(RT_TRIANGLES, 0, 3);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtDrawElements(RT_TRIANGLES, 3, RT_UNSIGNED_BYTE, idx);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtEnd();
    /* Vertex array disabled, or its pointer NULL. */
    rtDisableClientState(RT_VERTEX_ARRAY);
    rtDrawArrays(RT_TRIANGLES, 0, 3);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtDrawElements(RT_TRIANGLES, 3, RT_UNSIGNED_BYTE, idx);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtEnableClientState(RT_VERTEX_ARRAY);
    rtVertexPointer(3, RT_FLOAT, 0, NULL);
    rtDrawArrays(RT_TRIANGLES, 0, 3);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtVertexPointer(3, RT_FLOAT, 0, v);
    /* An enabled attribute array with a NULL pointer. */
    rtNormalPointer(RT_FLOAT, 0, NULL);
    rtEnableClientState(RT_NORMAL_ARRAY);
    rtDrawArrays(RT_TRIANGLES, 0, 3);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtDisableClientState(RT_NORMAL_ARRAY);
    rtColorPointer(4, RT_FLOAT, 0, NULL);
    rtEnableClientState(RT_COLOR_ARRAY);
    rtDrawElements(RT_TRIANGLES, 3, RT_UNSIGNED_BYTE, idx);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtDisableClientState(RT_COLOR_ARRAY);
    rtTexCoordPointer(2, RT_FLOAT, 0, NULL);
    rtEnableClientState(RT_TEXTURE_COORD_ARRAY);
    rtDrawArrays(RT_TRIANGLES, 0, 3);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtDisableClientState(RT_TEXTURE_COORD_ARRAY);
    /* A disabled attribute array's NULL pointer does not matter. */
    rtDrawArrays(RT_TRIANGLES, 1, 3); /* triangle 1 */
    CHECK_NO_ERR();
    /* A non-finite vertex anywhere in the batch: nothing of it is recorded. */
    memcpy(bad, v, sizeof bad);
    bad[3][1] = tu_nan();
    rtVertexPointer(3, RT_FLOAT, 0, bad);
    rtDrawArrays(RT_TRIANGLE_STRIP, 0, 4);
    CHECK_ERR(RT_INVALID_VALUE);
    bad[3][1] = tu_inf();
    rtDrawArrays(RT_TRIANGLES, 1, 3);
    CHECK_ERR(RT_INVALID_VALUE);
    {
        static const RTushort us[6] = {0, 1, 2, 1, 2, 3};
        rtDrawElements(RT_TRIANGLES, 6, RT_UNSIGNED_SHORT, us);
        CHECK_ERR(RT_INVALID_VALUE);
    }
    {
        int r, c;
        for (r = 0; r < 4; r++)
            for (c = 0; c < 3; c++)
                badd[r][c] = v[r][c];
        badd[0][2] = -tu_inf_d();
        rtVertexPointer(3, RT_DOUBLE, 0, badd);
        rtDrawArrays(RT_TRIANGLES, 0, 3);
        CHECK_ERR(RT_INVALID_VALUE);
    }
    /* A size-4 vertex with w = 0 is not finite after the division by w. */
    {
        static const float h4[3][4] = {{0, 0, 0, 1}, {1, 0, 0, 1}, {0, 1, 0, 0}};
        rtVertexPointer(4, RT_FLOAT, 0, h4);
        rtDrawArrays(RT_TRIANGLES, 0, 3);
        CHECK_ERR(RT_INVALID_VALUE);
    }
    rtEndObject();
    CHECK_NO_ERR();
    CHECK_INT(tu_object_triangles(ARR), 2);
    CHECK(tu_scene1(ARR));
    CHECK_TRIANGLE(v[0], v[1], v[2], 0, ARR, 0);
    /* Triangle 1 is (v1, v2, v3); it shares only an edge with triangle 0. */
    CHECK_TRIANGLE(v[1], v[2], v[3], 1, ARR, 0);
    rtDisableClientState(RT_VERTEX_ARRAY);
}

static void every_mode(void)
{
    int m, first;
    tu_section("rtDrawArrays in every mode == rtBegin/rtVertex");
    rtEnableClientState(RT_VERTEX_ARRAY);
    for (m = 0; m < 6; m++) {
        const float(*v)[3] = verts_for(modes[m]);
        for (first = 0; first <= 1; first++) {
            int count = NV - first;
            char what[96];
            snprintf(what, sizeof what, "rtDrawArrays(%s, %d, %d)", mode_names[m], first, count);
            define_reference(modes[m], v, first, count);
            rtVertexPointer(3, RT_FLOAT, 0, v);
            rtNewObject(ARR);
            rtDrawArrays(modes[m], first, count);
            rtEndObject();
            CHECK_NO_ERR();
            compare_with_reference(what);
        }
    }

    tu_section("rtDrawElements with every index type == rtBegin/rtVertex");
    {
        /* The vertices stored in reverse; the indices put them back in order. */
        float rev[NV][3];
        RTubyte ub[NV];
        RTushort us[NV];
        RTuint ui[NV];
        int k, t;
        for (m = 0; m < 6; m++) {
            const float(*v)[3] = verts_for(modes[m]);
            for (k = 0; k < NV; k++) {
                memcpy(rev[NV - 1 - k], v[k], sizeof rev[0]);
                ub[k] = (RTubyte)(NV - 1 - k);
                us[k] = (RTushort)(NV - 1 - k);
                ui[k] = (RTuint)(NV - 1 - k);
            }
            define_reference(modes[m], v, 0, NV);
            rtVertexPointer(3, RT_FLOAT, 0, rev);
            for (t = 0; t < 3; t++) {
                static const RTenum types[3] = {RT_UNSIGNED_BYTE, RT_UNSIGNED_SHORT,
                                                RT_UNSIGNED_INT};
                const void *ptr = t == 0 ? (const void *)ub : t == 1 ? (const void *)us : (const void *)ui;
                char what[96];
                snprintf(what, sizeof what, "rtDrawElements(%s, index type %d)", mode_names[m], t);
                rtNewObject(ARR);
                rtDrawElements(modes[m], NV, types[t], ptr);
                rtEndObject();
                CHECK_NO_ERR();
                compare_with_reference(what);
            }
        }
    }
    /* Indices may repeat vertices. */
    {
        static const float sq[4][3] = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
        static const RTuint ui[6] = {0, 1, 2, 0, 2, 3};
        rtVertexPointer(3, RT_FLOAT, 0, sq);
        rtNewObject(ARR);
        rtDrawElements(RT_TRIANGLES, 6, RT_UNSIGNED_INT, ui);
        rtEndObject();
        CHECK_NO_ERR();
        CHECK_INT(tu_object_triangles(ARR), 2);
        CHECK(tu_scene1(ARR));
        CHECK_TRIANGLE(sq[0], sq[1], sq[2], 0, ARR, 0);
        CHECK_TRIANGLE(sq[0], sq[2], sq[3], 1, ARR, 0);
    }
    rtDisableClientState(RT_VERTEX_ARRAY);
}

/* ARR as one rtDrawArrays(RT_TRIANGLE_FAN, 0, NV) of the vertex array
 * (size, type, stride, ptr), under a scale of 1/2 inside the list when
 * `halve` (integer positions stored doubled), compared with REF. */
static void check_fan(RTint size, RTenum type, RTsizei stride, const void *ptr, int halve,
                      const char *what)
{
    rtVertexPointer(size, type, stride, ptr);
    rtNewObject(ARR);
    if (halve) {
        rtPushMatrix();
        rtScalef(0.5f, 0.5f, 0.5f);
    }
    rtDrawArrays(RT_TRIANGLE_FAN, 0, NV);
    if (halve)
        rtPopMatrix();
    rtEndObject();
    if (!CHECK_NO_ERR())
        fprintf(stderr, "    in: %s\n", what);
    compare_with_reference(what);
}

static void types_sizes_strides(void)
{
    int k;
    tu_section("vertex types, sizes and strides");
    rtEnableClientState(RT_VERTEX_ARRAY);
    define_reference(RT_TRIANGLE_FAN, ring, 0, NV);
    /* RT_SHORT and RT_INT, size 4 with w = 2 (coordinates stored doubled). */
    {
        RTshort s4[NV][4];
        RTint i4[NV][4];
        for (k = 0; k < NV; k++) {
            s4[k][0] = (RTshort)(2 * ring[k][0]);
            s4[k][1] = (RTshort)(2 * ring[k][1]);
            s4[k][2] = (RTshort)(2 * ring[k][2]);
            s4[k][3] = 2;
            i4[k][0] = (RTint)(2 * ring[k][0]);
            i4[k][1] = (RTint)(2 * ring[k][1]);
            i4[k][2] = (RTint)(2 * ring[k][2]);
            i4[k][3] = 2;
        }
        check_fan(4, RT_SHORT, 0, s4, 0, "RT_SHORT size 4, w = 2");
        check_fan(4, RT_INT, 0, i4, 0, "RT_INT size 4, w = 2");
    }
    /* RT_FLOAT and RT_DOUBLE, size 2 (z = 0), tightly packed. */
    {
        float f2[NV][2];
        double d2[NV][2];
        for (k = 0; k < NV; k++) {
            f2[k][0] = ring[k][0];
            f2[k][1] = ring[k][1];
            d2[k][0] = ring[k][0];
            d2[k][1] = ring[k][1];
        }
        check_fan(2, RT_FLOAT, 0, f2, 0, "RT_FLOAT size 2");
        check_fan(2, RT_DOUBLE, 0, d2, 0, "RT_DOUBLE size 2");
    }
    /* Interleaved records: stride in bytes, position not at offset 0. */
    {
        struct rec_f {
            float pad;
            float xyz[3];
            float normal[3];
        } rf[NV];
        struct rec_d {
            double xyz[3];
            double junk;
        } rd[NV];
        struct rec_s {
            RTshort id;
            RTshort xyz[3];
            RTshort junk[3];
        } rs[NV];
        struct rec_i {
            RTint xyz[3];
            RTint junk;
        } ri[NV];
        for (k = 0; k < NV; k++) {
            rf[k].pad = 1e30f;
            memcpy(rf[k].xyz, ring[k], sizeof rf[k].xyz);
            rf[k].normal[0] = rf[k].normal[1] = 0;
            rf[k].normal[2] = 1;
            rd[k].xyz[0] = ring[k][0];
            rd[k].xyz[1] = ring[k][1];
            rd[k].xyz[2] = ring[k][2];
            rd[k].junk = 7;
            rs[k].id = (RTshort)k;
            rs[k].xyz[0] = (RTshort)(2 * ring[k][0]);
            rs[k].xyz[1] = (RTshort)(2 * ring[k][1]);
            rs[k].xyz[2] = 0;
            rs[k].junk[0] = rs[k].junk[1] = rs[k].junk[2] = 999;
            ri[k].xyz[0] = (RTint)(2 * ring[k][0]);
            ri[k].xyz[1] = (RTint)(2 * ring[k][1]);
            ri[k].xyz[2] = 0;
            ri[k].junk = -999;
        }
        check_fan(3, RT_FLOAT, (RTsizei)sizeof rf[0], rf[0].xyz, 0,
                  "RT_FLOAT size 3, interleaved stride");
        check_fan(3, RT_DOUBLE, (RTsizei)sizeof rd[0], rd, 0, "RT_DOUBLE size 3, stride 32");
        /* Integer positions are not normalised: scale by 1/2 to compare
         * (inside the list, whose vertices its own matrix transforms). */
        check_fan(3, RT_SHORT, (RTsizei)sizeof rs[0], rs[0].xyz, 1,
                  "RT_SHORT size 3, interleaved stride, under scale 1/2");
        check_fan(3, RT_INT, (RTsizei)sizeof ri[0], ri, 1,
                  "RT_INT size 3, stride 16, under scale 1/2");
    }
    /* The modelview at the call transforms array vertices. */
    {
        float moved[NV][3];
        for (k = 0; k < NV; k++) {
            moved[k][0] = ring[k][0] + 1;
            moved[k][1] = ring[k][1];
            moved[k][2] = ring[k][2] - 2;
        }
        define_reference(RT_TRIANGLE_FAN, moved, 0, NV);
        rtVertexPointer(3, RT_FLOAT, 0, ring);
        rtNewObject(ARR);
        rtTranslatef(1, 0, -2);
        rtDrawArrays(RT_TRIANGLE_FAN, 0, NV);
        rtEndObject();
        rtLoadIdentity();
        CHECK_NO_ERR();
        compare_with_reference("rtDrawArrays under translate(1, 0, -2)");
    }
    rtDisableClientState(RT_VERTEX_ARRAY);
}

static void copied_at_call(void)
{
    float v[NV][3];
    tu_section("arrays are read at the call");
    memcpy(v, ring, sizeof v);
    define_reference(RT_POLYGON, ring, 0, NV);
    rtEnableClientState(RT_VERTEX_ARRAY);
    rtVertexPointer(3, RT_FLOAT, 0, v);
    rtNewObject(ARR);
    rtDrawArrays(RT_POLYGON, 0, NV);
    /* Scribble over the array before the definition ends, and after. */
    memset(v, 0, sizeof v);
    rtEndObject();
    v[1][0] = 1e6f;
    CHECK_NO_ERR();
    compare_with_reference("array changed after rtDrawArrays");
    rtDisableClientState(RT_VERTEX_ARRAY);
}

/* ---- attribute arrays, seen in pixels ------------------------------------------------ */

#define W 8
#define H 8
static float px[W * H * 4];

static const float quad[4][3] = {{-0.9f, -0.9f, -5}, {0.9f, -0.9f, -5}, {0.9f, 0.9f, -5},
                                 {-0.9f, 0.9f, -5}};

static void draw_quad_and_render(void)
{
    rtVertexPointer(3, RT_FLOAT, 0, quad);
    rtEnableClientState(RT_VERTEX_ARRAY);
    rtNewObject(ARR);
    rtDrawArrays(RT_QUADS, 0, 4);
    rtEndObject();
    CHECK_NO_ERR();
    CHECK(tu_scene1(ARR));
    tu_render_float(W, H, px);
    CHECK_NO_ERR();
}

static int centre_is(float r, float g, float b)
{
    const float *p = px + 4 * ((H / 2) * W + W / 2);
    int ok = fabsf(p[0] - r) <= 0.01f && fabsf(p[1] - g) <= 0.01f && fabsf(p[2] - b) <= 0.01f;
    if (!ok)
        fprintf(stderr, "    centre pixel (%g, %g, %g), expected (%g, %g, %g)\n", p[0], p[1],
                p[2], r, g, b);
    return ok;
}

static void attribute_arrays(void)
{
    static const float no_ambient[4] = {0, 0, 0, 1};
    tu_section("colour and normal arrays");
    tu_ortho_camera();
    rtShadingMode(RT_EYE_LIGHT);
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, no_ambient);
    rtEnable(RT_COLOR_MATERIAL);
    rtColor3f(1, 1, 1);
    /* Colour arrays of each type; 0.5 as a byte is 128/255. */
    {
        static const RTubyte cb[4][4] = {
            {255, 128, 0, 255}, {255, 128, 0, 255}, {255, 128, 0, 255}, {255, 128, 0, 255}};
        static const float cf[4][3] = {{0, 0.5f, 1}, {0, 0.5f, 1}, {0, 0.5f, 1}, {0, 0.5f, 1}};
        static const double cd[4][4] = {
            {0.25, 1, 0.75, 1}, {0.25, 1, 0.75, 1}, {0.25, 1, 0.75, 1}, {0.25, 1, 0.75, 1}};
        rtEnableClientState(RT_COLOR_ARRAY);
        rtColorPointer(4, RT_UNSIGNED_BYTE, 0, cb);
        draw_quad_and_render();
        CHECK(centre_is(1, 128.0f / 255.0f, 0));
        rtColorPointer(3, RT_FLOAT, 0, cf);
        draw_quad_and_render();
        CHECK(centre_is(0, 0.5f, 1));
        rtColorPointer(4, RT_DOUBLE, 0, cd);
        draw_quad_and_render();
        CHECK(centre_is(0.25f, 1, 0.75f));
        rtDisableClientState(RT_COLOR_ARRAY);
        /* Disabled: the current colour applies. */
        rtColor3f(0.5f, 0.25f, 1);
        draw_quad_and_render();
        CHECK(centre_is(0.5f, 0.25f, 1));
        rtColor3f(1, 1, 1);
    }
    /* Normal arrays of each type, all at 45 degrees: |cos| = 0.7071. */
    {
        static const RTbyte nb[4][3] = {{90, 0, 90}, {90, 0, 90}, {90, 0, 90}, {90, 0, 90}};
        static const RTshort ns[4][3] = {
            {20000, 0, 20000}, {20000, 0, 20000}, {20000, 0, 20000}, {20000, 0, 20000}};
        static const RTint ni[4][3] = {{1 << 29, 0, 1 << 29},
                                       {1 << 29, 0, 1 << 29},
                                       {1 << 29, 0, 1 << 29},
                                       {1 << 29, 0, 1 << 29}};
        static const float nf[4][3] = {
            {0.7071f, 0, 0.7071f}, {0.7071f, 0, 0.7071f}, {0.7071f, 0, 0.7071f}, {0.7071f, 0, 0.7071f}};
        static const double nd[4][4] = {{0.7071, 0, 0.7071, 99},
                                        {0.7071, 0, 0.7071, 99},
                                        {0.7071, 0, 0.7071, 99},
                                        {0.7071, 0, 0.7071, 99}};
        const float c = 0.70710678f;
        rtEnableClientState(RT_NORMAL_ARRAY);
        rtNormalPointer(RT_BYTE, 0, nb);
        draw_quad_and_render();
        CHECK(centre_is(c, c, c));
        rtNormalPointer(RT_SHORT, 0, ns);
        draw_quad_and_render();
        CHECK(centre_is(c, c, c));
        rtNormalPointer(RT_INT, 0, ni);
        draw_quad_and_render();
        CHECK(centre_is(c, c, c));
        rtNormalPointer(RT_FLOAT, 0, nf);
        draw_quad_and_render();
        CHECK(centre_is(c, c, c));
        rtNormalPointer(RT_DOUBLE, (RTsizei)(4 * sizeof(double)), nd);
        draw_quad_and_render();
        CHECK(centre_is(c, c, c));
        rtDisableClientState(RT_NORMAL_ARRAY);
        /* No normal array and no rtNormal in the definition: geometric normal. */
        draw_quad_and_render();
        CHECK(centre_is(1, 1, 1));
    }
    /* Texture coordinates of each type are accepted and do not change the
     * geometry. */
    {
        static const float tf[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        static const RTshort ts[4][4] = {{0, 0, 0, 1}, {1, 0, 0, 1}, {1, 1, 0, 1}, {0, 1, 0, 1}};
        rtEnableClientState(RT_TEXTURE_COORD_ARRAY);
        rtTexCoordPointer(2, RT_FLOAT, 0, tf);
        draw_quad_and_render();
        CHECK(centre_is(1, 1, 1));
        CHECK_INT(tu_object_triangles(ARR), 2);
        rtTexCoordPointer(4, RT_SHORT, 0, ts);
        draw_quad_and_render();
        CHECK(centre_is(1, 1, 1));
        rtDisableClientState(RT_TEXTURE_COORD_ARRAY);
    }
    rtDisable(RT_COLOR_MATERIAL);
    rtDisableClientState(RT_VERTEX_ARRAY);
    CHECK_NO_ERR();
}

int main(void)
{
    RTcontext ctx = tu_make_context("threads=2");
    tu_capture_errors();
    client_state_and_pointers();
    draw_errors();
    every_mode();
    types_sizes_strides();
    copied_at_call();
    attribute_arrays();
    tu_destroy_context(ctx);
    return test_summary("arrays");
}
