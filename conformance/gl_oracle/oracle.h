/* SPDX-License-Identifier: Apache-2.0 */
/*
 * oracle.h - the OpenGL oracle: scenes written once (scenes.inc, against
 * the macro layer of layer_gl.h / layer_rt.h), rendered by Mesa's OSMesa
 * with Mesa's libGLU and by Tracelist with rtu, and compared per pixel.
 *
 * A scene is three functions called in this order by both backends:
 * projection() with the projection matrix current and loaded with the
 * identity; shape() with the modelview matrix the identity, recorded into
 * display list / object 1; view() on the identity modelview matrix, after
 * which list / object 1 is called / instantiated.  So the geometry is
 * recorded under the identity in both, as a GLU or GLUT call compiled
 * into a display list.
 *
 * Both render ORACLE_W x ORACLE_H pixels, cleared to ORACLE_BACKGROUND
 * (magenta, which no shaded surface here produces), the geometry white.
 * Images are RGBA8, rows bottom to top (glReadPixels / rtReadPixels).
 */
#ifndef ORACLE_ORACLE_H
#define ORACLE_ORACLE_H

#define ORACLE_W 160
#define ORACLE_H 160
#define ORACLE_BG_R 1.0f
#define ORACLE_BG_G 0.0f
#define ORACLE_BG_B 1.0f

struct oracle_scene {
    const char *family; /* the docs page's row: "quadrics", "glut", "projections" */
    const char *name;
    void (*projection)(void);
    void (*shape)(void);
    void (*view)(void);
    /* 0: compare coverage only; otherwise also the colour of pixels both
     * cover, each channel within this many 8-bit steps. */
    int colour_tolerance;
};

extern const struct oracle_scene oracle_scenes_gl[];
extern const struct oracle_scene oracle_scenes_rt[];
extern const int oracle_scene_count_gl;
extern const int oracle_scene_count_rt;

/* Render one scene into rgba (ORACLE_W * ORACLE_H * 4 bytes).  Return 0
 * and print why on failure (no OSMesa context; a Tracelist error). */
int oracle_gl_init(void);
int oracle_gl_render(const struct oracle_scene *scene, unsigned char *rgba);
void oracle_gl_finish(void);
int oracle_rt_init(void);
int oracle_rt_render(const struct oracle_scene *scene, unsigned char *rgba);
void oracle_rt_finish(void);

#endif /* ORACLE_ORACLE_H */
