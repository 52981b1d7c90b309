/* SPDX-License-Identifier: Apache-2.0 */
/*
 * material_oracle.c - RT_COLOR_MATERIAL's write-back against Mesa's
 * OSMesa: the same sequences of colour, material, colour-material,
 * enable, attribute-stack and display-list calls made on a GL context and
 * on a Tracelist one, and after every call the material GL reports
 * (glGetMaterialfv: ambient, diffuse, specular and emission of the front
 * and the back) compared with what rtGetMaterialfv reports, exactly.
 *
 * GL writes the current colour into the material properties
 * glColorMaterial names whenever the colour changes while
 * GL_COLOR_MATERIAL is enabled, when it is enabled, and when the tracked
 * properties are switched while it is; the last colour stays in a
 * property that is no longer tracked (OpenGL 2.1 spec sec. 2.14.3).
 * (Mesa writes lazily, when it flushes the current values; the query
 * after every call flushes, so it shows the specification's values.)
 * Under GL_COMPILE the comparison waits for glEndList: Tracelist's state
 * follows the list while it records and comes back at rtEndList.
 */
#include <GL/osmesa.h>
#include <GL/gl.h>

#include <rt/rt.h>

#include <stdio.h>
#include <string.h>

enum op_kind {
    OP_COLOR,          /* a: r g b a */
    OP_COLOR_MATERIAL, /* face, mode */
    OP_ENABLE,         /* GL_COLOR_MATERIAL */
    OP_DISABLE,
    OP_MATERIAL,       /* face, pname, a */
    OP_PUSH_LIGHTING,
    OP_PUSH_CURRENT_LIGHTING,
    OP_POP,
    OP_NEW_LIST,       /* face = list, pname = mode (0: GL_COMPILE, 1: and execute) */
    OP_END_LIST,
    OP_CALL_LIST,      /* face = list */
    OP_TRIANGLE,       /* a triangle with a colour per vertex: a, then a reversed */
    OP_END
};

struct op {
    enum op_kind kind;
    int face, pname; /* 0 front, 1 back, 2 both; 0 ambient, 1 diffuse, 2 a&d, 3 specular, 4 emission */
    float a[4];
};

static const GLenum gl_faces[3] = {GL_FRONT, GL_BACK, GL_FRONT_AND_BACK};
static const RTenum rt_faces[3] = {RT_FRONT, RT_BACK, RT_FRONT_AND_BACK};
static const GLenum gl_pnames[5] = {GL_AMBIENT, GL_DIFFUSE, GL_AMBIENT_AND_DIFFUSE, GL_SPECULAR,
                                    GL_EMISSION};
static const RTenum rt_pnames[5] = {RT_AMBIENT, RT_DIFFUSE, RT_AMBIENT_AND_DIFFUSE, RT_SPECULAR,
                                    RT_EMISSION};

#define RED {0.9f, 0.1f, 0.1f, 1.0f}
#define GREEN {0.1f, 0.8f, 0.2f, 1.0f}
#define BLUE {0.2f, 0.3f, 0.9f, 0.5f}
#define GREY {0.4f, 0.4f, 0.4f, 1.0f}

/* Each sequence starts from GL's initial state (a fresh context). */
static const struct op seq_switch[] = {
    {OP_COLOR_MATERIAL, 0, 0, {0}}, /* front ambient */
    {OP_ENABLE, 0, 0, {0}},         /* writes the current colour (white) */
    {OP_COLOR, 0, 0, RED},
    {OP_COLOR_MATERIAL, 0, 1, {0}}, /* front diffuse: red stays in ambient */
    {OP_COLOR, 0, 0, GREEN},
    {OP_COLOR_MATERIAL, 2, 3, {0}}, /* both specular */
    {OP_COLOR, 0, 0, BLUE},
    {OP_DISABLE, 0, 0, {0}},
    {OP_COLOR, 0, 0, GREY}, /* disabled: no write */
    {OP_END, 0, 0, {0}}};

static const struct op seq_material_while_tracked[] = {
    {OP_COLOR, 0, 0, RED},
    {OP_ENABLE, 0, 0, {0}}, /* front and back ambient and diffuse := red */
    {OP_MATERIAL, 2, 1, GREEN},
    {OP_MATERIAL, 2, 3, GREEN},
    {OP_COLOR, 0, 0, BLUE},
    {OP_MATERIAL, 0, 2, GREY},
    {OP_DISABLE, 0, 0, {0}},
    {OP_MATERIAL, 1, 0, GREEN},
    {OP_END, 0, 0, {0}}};

static const struct op seq_begin_end[] = {
    {OP_COLOR_MATERIAL, 1, 4, {0}}, /* back emission */
    {OP_ENABLE, 0, 0, {0}},
    {OP_TRIANGLE, 0, 0, RED}, /* the last vertex colour stays */
    {OP_COLOR_MATERIAL, 0, 0, {0}},
    {OP_TRIANGLE, 0, 0, GREEN},
    {OP_DISABLE, 0, 0, {0}},
    {OP_END, 0, 0, {0}}};

static const struct op seq_attrib[] = {
    {OP_COLOR, 0, 0, RED},
    {OP_COLOR_MATERIAL, 0, 1, {0}},
    {OP_ENABLE, 0, 0, {0}},
    {OP_PUSH_LIGHTING, 0, 0, {0}},
    {OP_COLOR_MATERIAL, 0, 3, {0}},
    {OP_COLOR, 0, 0, GREEN},
    {OP_POP, 0, 0, {0}}, /* diffuse back to red (the pushed), tracked again */
    {OP_COLOR, 0, 0, BLUE},
    {OP_PUSH_CURRENT_LIGHTING, 0, 0, {0}},
    {OP_DISABLE, 0, 0, {0}},
    {OP_COLOR, 0, 0, GREY},
    {OP_POP, 0, 0, {0}},
    {OP_DISABLE, 0, 0, {0}},
    {OP_END, 0, 0, {0}}};

/* In lists: the calls are recorded, not executed, under GL_COMPILE, and
 * executed at glCallList with the colour current then. */
static const struct op seq_lists[] = {
    {OP_NEW_LIST, 1, 0, {0}},
    {OP_COLOR_MATERIAL, 0, 0, {0}},
    {OP_ENABLE, 0, 0, {0}},
    {OP_TRIANGLE, 0, 0, RED},
    {OP_COLOR_MATERIAL, 0, 1, {0}},
    {OP_TRIANGLE, 0, 0, GREEN},
    {OP_END_LIST, 0, 0, {0}},
    {OP_NEW_LIST, 2, 0, {0}},
    {OP_DISABLE, 0, 0, {0}},
    {OP_END_LIST, 0, 0, {0}},
    {OP_NEW_LIST, 3, 1, {0}}, /* compile and execute */
    {OP_COLOR_MATERIAL, 2, 4, {0}},
    {OP_ENABLE, 0, 0, {0}},
    {OP_COLOR, 0, 0, GREY},
    {OP_DISABLE, 0, 0, {0}},
    {OP_END_LIST, 0, 0, {0}},
    {OP_COLOR, 0, 0, BLUE},
    {OP_CALL_LIST, 1, 0, {0}},
    {OP_COLOR, 0, 0, RED},
    {OP_CALL_LIST, 2, 0, {0}}, /* the disable: red stays in the diffuse */
    {OP_COLOR, 0, 0, BLUE},
    {OP_CALL_LIST, 3, 0, {0}},
    {OP_END, 0, 0, {0}}};

static void apply_gl(const struct op *o)
{
    switch (o->kind) {
    case OP_COLOR:
        glColor4fv(o->a);
        break;
    case OP_COLOR_MATERIAL:
        glColorMaterial(gl_faces[o->face], gl_pnames[o->pname]);
        break;
    case OP_ENABLE:
        glEnable(GL_COLOR_MATERIAL);
        break;
    case OP_DISABLE:
        glDisable(GL_COLOR_MATERIAL);
        break;
    case OP_MATERIAL:
        glMaterialfv(gl_faces[o->face], gl_pnames[o->pname], o->a);
        break;
    case OP_PUSH_LIGHTING:
        glPushAttrib(GL_LIGHTING_BIT);
        break;
    case OP_PUSH_CURRENT_LIGHTING:
        glPushAttrib(GL_LIGHTING_BIT | GL_CURRENT_BIT | GL_ENABLE_BIT);
        break;
    case OP_POP:
        glPopAttrib();
        break;
    case OP_NEW_LIST:
        glNewList((GLuint)o->face, o->pname ? GL_COMPILE_AND_EXECUTE : GL_COMPILE);
        break;
    case OP_END_LIST:
        glEndList();
        break;
    case OP_CALL_LIST:
        glCallList((GLuint)o->face);
        break;
    case OP_TRIANGLE: {
        const float rev[4] = {o->a[2], o->a[1], o->a[0], o->a[3]};
        glBegin(GL_TRIANGLES);
        glColor4fv(rev);
        glVertex3f(0.0f, 0.0f, -1.0f);
        glVertex3f(1.0f, 0.0f, -1.0f);
        glColor4fv(o->a);
        glVertex3f(0.0f, 1.0f, -1.0f);
        glEnd();
        break;
    }
    case OP_END:
        break;
    }
}

static void apply_rt(const struct op *o)
{
    switch (o->kind) {
    case OP_COLOR:
        rtColor4fv(o->a);
        break;
    case OP_COLOR_MATERIAL:
        rtColorMaterial(rt_faces[o->face], rt_pnames[o->pname]);
        break;
    case OP_ENABLE:
        rtEnable(RT_COLOR_MATERIAL);
        break;
    case OP_DISABLE:
        rtDisable(RT_COLOR_MATERIAL);
        break;
    case OP_MATERIAL:
        rtMaterialfv(rt_faces[o->face], rt_pnames[o->pname], o->a);
        break;
    case OP_PUSH_LIGHTING:
        rtPushAttrib(RT_LIGHTING_BIT);
        break;
    case OP_PUSH_CURRENT_LIGHTING:
        rtPushAttrib(RT_LIGHTING_BIT | RT_CURRENT_BIT | RT_ENABLE_BIT);
        break;
    case OP_POP:
        rtPopAttrib();
        break;
    case OP_NEW_LIST:
        rtNewList((RTuint)o->face, o->pname ? RT_COMPILE_AND_EXECUTE : RT_COMPILE);
        break;
    case OP_END_LIST:
        rtEndList();
        break;
    case OP_CALL_LIST:
        rtCallList((RTuint)o->face);
        break;
    case OP_TRIANGLE: {
        const float rev[4] = {o->a[2], o->a[1], o->a[0], o->a[3]};
        rtBegin(RT_TRIANGLES);
        rtColor4fv(rev);
        rtVertex3f(0.0f, 0.0f, -1.0f);
        rtVertex3f(1.0f, 0.0f, -1.0f);
        rtColor4fv(o->a);
        rtVertex3f(0.0f, 1.0f, -1.0f);
        rtEnd();
        break;
    }
    case OP_END:
        break;
    }
}

/* Compares the four colours of both faces; returns the mismatches. */
static int compare(const char *name, int step)
{
    static const char *props[4] = {"ambient", "diffuse", "specular", "emission"};
    static const GLenum gp[4] = {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION};
    static const RTenum rp[4] = {RT_AMBIENT, RT_DIFFUSE, RT_SPECULAR, RT_EMISSION};
    int bad = 0;
    for (int f = 0; f < 2; f++)
        for (int p = 0; p < 4; p++) {
            GLfloat g[4];
            RTfloat r[4];
            glGetMaterialfv(gl_faces[f], gp[p], g);
            rtGetMaterialfv(rt_faces[f], rp[p], r);
            if (memcmp(g, r, sizeof(g)) != 0) {
                fprintf(stderr,
                        "%s step %d: %s %s: GL (%g %g %g %g), Tracelist (%g %g %g %g)\n", name,
                        step, f ? "back" : "front", props[p], (double)g[0], (double)g[1],
                        (double)g[2], (double)g[3], (double)r[0], (double)r[1], (double)r[2],
                        (double)r[3]);
                bad++;
            }
        }
    return bad;
}

static int run(const char *name, const struct op *ops)
{
    static unsigned char buffer[16 * 16 * 4];
    OSMesaContext gl = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    RTcontext rt = rtCreateContext(NULL);
    if (!gl || !OSMesaMakeCurrent(gl, buffer, GL_UNSIGNED_BYTE, 16, 16) || !rt ||
        !rtMakeCurrent(rt)) {
        fprintf(stderr, "material_oracle: cannot create the contexts\n");
        return 1;
    }
    int bad = compare(name, 0), compiling = 0;
    for (int i = 0; ops[i].kind != OP_END; i++) {
        apply_gl(&ops[i]);
        apply_rt(&ops[i]);
        if (ops[i].kind == OP_NEW_LIST)
            compiling = ops[i].pname == 0;
        else if (ops[i].kind == OP_END_LIST)
            compiling = 0;
        /* Under GL_COMPILE GL's state does not change; Tracelist's
         * changes while the list records and comes back at rtEndList
         * (docs/lists.md): compared after the list. */
        if (!compiling)
            bad += compare(name, i + 1);
    }
    if (glGetError() != GL_NO_ERROR) {
        fprintf(stderr, "%s: GL recorded an error\n", name);
        bad++;
    }
    if (rtGetError() != RT_NO_ERROR) {
        fprintf(stderr, "%s: Tracelist recorded an error\n", name);
        bad++;
    }
    rtMakeCurrent(NULL);
    rtDestroyContext(rt);
    OSMesaDestroyContext(gl);
    printf("%-28s %s\n", name, bad ? "FAILED" : "ok");
    return bad != 0;
}

int main(void)
{
    int failed = 0;
    failed += run("switch_tracked_property", seq_switch);
    failed += run("material_while_tracked", seq_material_while_tracked);
    failed += run("colours_in_begin_end", seq_begin_end);
    failed += run("attribute_stack", seq_attrib);
    failed += run("display_lists", seq_lists);
    printf("material_oracle: %d of 5 sequences failed\n", failed);
    return failed != 0;
}
