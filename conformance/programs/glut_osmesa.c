/* SPDX-License-Identifier: Apache-2.0 */
/*
 * glut_osmesa.c - the headless GLUT subset of shim/GL/glut.h over OSMesa:
 * the GL side of the GLUT programs' comparison.  It follows the headless
 * rules of the Tracelist rtu shell (docs/glcompat.md):
 *
 *   TRACELIST_SIZE    WxH, replaces the glutInitWindowSize size
 *   TRACELIST_EVENTS  space-separated: "k:x" a key ("k:#27" by its code),
 *                     "s:101" a special key code, "m:Label" a menu entry by
 *                     its label ('_' for a space); replayed in order after
 *                     the reshape callback
 *   TRACELIST_FRAMES  display calls (default 1), each after the idle callback
 *   TRACELIST_OUT     the file of the last frame (binary PPM)
 *
 * glutMainLoop does all of it and exits: status 1 when a GL error was
 * recorded or the file could not be written.
 */
#include <GL/glut.h>
#include <GL/osmesa.h>

#include "../gl_oracle/glut_gl.h"
#include "ppm.h"
#include "rtu/font_internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_MENU_ENTRIES 32

struct menu_entry {
    char label[64];
    int value;
};

static struct {
    int width, height;
    OSMesaContext context;
    unsigned char *buffer;
    void (*display)(void);
    void (*reshape)(int, int);
    void (*keyboard)(unsigned char, int, int);
    void (*special)(int, int, int);
    void (*idle)(void);
    void (*menu)(int);
    struct menu_entry entries[MAX_MENU_ENTRIES];
    int entry_count, errors;
    const char *program;
} glut;

static void collect_errors(const char *where)
{
    GLenum error;
    while ((error = glGetError()) != GL_NO_ERROR) {
        fprintf(stderr, "glut_osmesa: GL error 0x%x %s\n", error, where);
        glut.errors++;
    }
}

void glutInit(int *argcp, char **argv)
{
    glut.width = glut.height = 300; /* GLUT's default window size */
    glut.program = (*argcp > 0 && argv[0]) ? argv[0] : "glut";
}

void glutInitDisplayMode(unsigned int mode)
{
    (void)mode; /* always RGBA with a depth buffer */
}

void glutInitWindowSize(int width, int height)
{
    glut.width = width;
    glut.height = height;
}

void glutInitWindowPosition(int x, int y)
{
    (void)x;
    (void)y;
}

int glutCreateWindow(const char *title)
{
    const char *size = getenv("TRACELIST_SIZE");
    int w, h;
    (void)title;
    if (size && sscanf(size, "%dx%d", &w, &h) == 2 && w > 0 && h > 0) {
        glut.width = w;
        glut.height = h;
    }
    glut.context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    glut.buffer = malloc((size_t)glut.width * glut.height * 4);
    if (!glut.context || !glut.buffer ||
        !OSMesaMakeCurrent(glut.context, glut.buffer, GL_UNSIGNED_BYTE, glut.width, glut.height)) {
        fprintf(stderr, "glut_osmesa: cannot create an OSMesa context\n");
        exit(1);
    }
    return 1;
}

void glutDisplayFunc(void (*func)(void)) { glut.display = func; }
void glutReshapeFunc(void (*func)(int, int)) { glut.reshape = func; }
void glutKeyboardFunc(void (*func)(unsigned char, int, int)) { glut.keyboard = func; }
void glutSpecialFunc(void (*func)(int, int, int)) { glut.special = func; }
void glutIdleFunc(void (*func)(void)) { glut.idle = func; }
void glutSwapBuffers(void) { glFinish(); }
void glutPostRedisplay(void) { }

int glutCreateMenu(void (*func)(int))
{
    glut.menu = func;
    glut.entry_count = 0;
    return 1;
}

void glutAddMenuEntry(const char *label, int value)
{
    if (glut.entry_count < MAX_MENU_ENTRIES) {
        struct menu_entry *e = &glut.entries[glut.entry_count++];
        snprintf(e->label, sizeof e->label, "%s", label);
        e->value = value;
    }
}

void glutAttachMenu(int button)
{
    (void)button;
}

int glutGet(GLenum state)
{
    switch (state) {
    case GLUT_WINDOW_WIDTH:
        return glut.width;
    case GLUT_WINDOW_HEIGHT:
        return glut.height;
    default:
        return 0; /* GLUT_ELAPSED_TIME: time stands still headless */
    }
}

/* One event of TRACELIST_EVENTS; returns 0 for one it does not know. */
static int replay(const char *event)
{
    if (strncmp(event, "k:", 2) == 0 && event[2] && (!event[3] || event[2] == '#')) {
        int key = event[2] == '#' ? atoi(event + 3) : (unsigned char)event[2];
        if (key < 0 || key > 255)
            return 0;
        if (glut.keyboard)
            glut.keyboard((unsigned char)key, 0, 0);
        return 1;
    }
    if (strncmp(event, "s:", 2) == 0) {
        if (glut.special)
            glut.special(atoi(event + 2), 0, 0);
        return 1;
    }
    if (strncmp(event, "m:", 2) == 0) {
        char label[64];
        int i;
        snprintf(label, sizeof label, "%s", event + 2);
        for (i = 0; label[i]; i++)
            if (label[i] == '_')
                label[i] = ' ';
        for (i = 0; i < glut.entry_count; i++)
            if (strcmp(glut.entries[i].label, label) == 0) {
                glut.menu(glut.entries[i].value);
                return 1;
            }
    }
    fprintf(stderr, "glut_osmesa: unknown event \"%s\"\n", event);
    return 0;
}

void glutMainLoop(void)
{
    const char *events = getenv("TRACELIST_EVENTS");
    const char *frames_text = getenv("TRACELIST_FRAMES");
    const char *out = getenv("TRACELIST_OUT");
    int frames = frames_text ? atoi(frames_text) : 1, frame, failed = 0;
    if (glut.reshape)
        glut.reshape(glut.width, glut.height);
    else
        glViewport(0, 0, glut.width, glut.height);
    if (events) {
        char copy[1024], *event;
        snprintf(copy, sizeof copy, "%s", events);
        for (event = strtok(copy, " "); event; event = strtok(NULL, " "))
            failed |= !replay(event);
    }
    for (frame = 0; frame < (frames > 0 ? frames : 1); frame++) {
        if (glut.idle)
            glut.idle();
        if (glut.display)
            glut.display();
        collect_errors("in a frame");
    }
    glFinish();
    if (!ppm_write(out ? out : "glut.ppm", glut.width, glut.height, glut.buffer)) {
        fprintf(stderr, "glut_osmesa: cannot write %s\n", out ? out : "glut.ppm");
        failed = 1;
    }
    OSMesaDestroyContext(glut.context);
    free(glut.buffer);
    exit(failed || glut.errors != 0);
}

void glutSolidSphere(GLdouble radius, GLint slices, GLint stacks) { oracle_glutSolidSphere(radius, slices, stacks); }
void glutSolidCube(GLdouble size) { oracle_glutSolidCube(size); }
void glutSolidCone(GLdouble base, GLdouble height, GLint slices, GLint stacks) { oracle_glutSolidCone(base, height, slices, stacks); }
void glutSolidTorus(GLdouble inner, GLdouble outer, GLint sides, GLint rings) { oracle_glutSolidTorus(inner, outer, sides, rings); }
void glutSolidTeapot(GLdouble size) { oracle_glutSolidTeapot(size); }

/* GLUT 3's wire cube: each face a line loop, with its normal. */
void glutWireCube(GLdouble size)
{
    static const GLfloat n[6][3] = {{-1, 0, 0}, {0, 1, 0}, {1, 0, 0},
                                    {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    static const int faces[6][4] = {{0, 1, 2, 3}, {3, 2, 6, 7}, {7, 6, 5, 4},
                                    {4, 5, 1, 0}, {5, 6, 2, 1}, {7, 4, 0, 3}};
    GLfloat v[8][3];
    int i;
    v[0][0] = v[1][0] = v[2][0] = v[3][0] = (GLfloat)(-size / 2);
    v[4][0] = v[5][0] = v[6][0] = v[7][0] = (GLfloat)(size / 2);
    v[0][1] = v[1][1] = v[4][1] = v[5][1] = (GLfloat)(-size / 2);
    v[2][1] = v[3][1] = v[6][1] = v[7][1] = (GLfloat)(size / 2);
    v[0][2] = v[3][2] = v[4][2] = v[7][2] = (GLfloat)(-size / 2);
    v[1][2] = v[2][2] = v[5][2] = v[6][2] = (GLfloat)(size / 2);
    for (i = 5; i >= 0; i--) {
        glBegin(GL_LINE_LOOP);
        glNormal3fv(n[i]);
        glVertex3fv(v[faces[i][0]]);
        glVertex3fv(v[faces[i][1]]);
        glVertex3fv(v[faces[i][2]]);
        glVertex3fv(v[faces[i][3]]);
        glEnd();
    }
}

/* GLUT 3's wire sphere: a GLU sphere in the GLU_LINE style, smooth normals. */
void glutWireSphere(GLdouble radius, GLint slices, GLint stacks)
{
    GLUquadric *q = gluNewQuadric();
    gluQuadricDrawStyle(q, GLU_LINE);
    gluQuadricNormals(q, GLU_SMOOTH);
    gluSphere(q, radius, slices, stacks);
    gluDeleteQuadric(q);
}

/* GLUT's bitmap characters with glBitmap, GLUT's way: one bitmap per
 * character at the raster position, which it advances by the character's
 * width.  The glyphs are rtu's (lib/rtu/font_data.c: the real GLUT fonts'
 * pixels are not ours to copy), each dot scaled and the glyph centred in
 * its advance as rtu's font.c does, so the two builds draw the same
 * pixels when their raster positions agree. */
void glutBitmapCharacter(void *font, int character)
{
    const size_t id = (size_t)font;
    const struct rtu_font *f;
    const struct rtu_glyph *g;
    GLubyte bits[RTU_FONT_ROWS * RTU_FONT_MAX_SCALE][4];
    int s, width, advance, offset, r, dy, i, k;
    if (id < 2 || id >= 2 + RTU_FONT_COUNT || character < RTU_FONT_FIRST ||
        character >= RTU_FONT_FIRST + RTU_FONT_GLYPHS)
        return;
    f = &rtu_fonts[id - 2];
    g = &rtu_glyphs[character - RTU_FONT_FIRST];
    s = f->scale;
    width = g->width * s;
    advance = f->advance[character - RTU_FONT_FIRST];
    offset = advance > width ? (advance - width) / 2 : 0;
    memset(bits, 0, sizeof bits);
    for (r = 0; r < RTU_FONT_ROWS; r++)
        for (dy = 0; dy < s; dy++)
            for (i = 0; i < g->width; i++)
                if (g->rows[r] & (0x80u >> i))
                    for (k = 0; k < s; k++)
                        bits[r * s + dy][(i * s + k) / 8] |= (GLubyte)(0x80u >> ((i * s + k) % 8));
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glBitmap(width, RTU_FONT_ROWS * s, (GLfloat)-offset, (GLfloat)(RTU_FONT_DESCENT * s),
             (GLfloat)advance, 0.0f, &bits[0][0]);
}
