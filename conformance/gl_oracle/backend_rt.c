/* SPDX-License-Identifier: Apache-2.0 */
/*
 * backend_rt.c - renders an oracle scene with Tracelist and rtu: the side
 * under test.
 *
 * The geometry is recorded into object 1 under the identity modelview and
 * instantiated under the scene's view, as backend_gl.c compiles and calls
 * display list 1.  Shading: the default, RT_FIXED_FUNCTION, GL's look
 * (unlit white unless a scene enables RT_LIGHTING, as the colour oracle's
 * scenes do).  Any recorded error fails the scene.
 */
#include "oracle.h"

#include <rt/rt.h>

#include <stdio.h>

static RTcontext context;

int oracle_rt_init(void)
{
    context = rtCreateContext(NULL);
    if (!context || !rtMakeCurrent(context)) {
        fprintf(stderr, "gl_oracle: cannot create a Tracelist context\n");
        return 0;
    }
    return 1;
}

int oracle_rt_render(const struct oracle_scene *scene, unsigned char *rgba)
{
    static const RTfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    const RTuint object = 1;
    RTenum error;
    rtViewport(0, 0, ORACLE_W, ORACLE_H);
    rtClearColor(ORACLE_BG_R, ORACLE_BG_G, ORACLE_BG_B, 1.0f);
    /* What a scene may have changed (scenes_vis.inc), back to the initial
     * state, as backend_gl.c does. */
    static const RTfloat black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    rtColor4f(1.0f, 1.0f, 1.0f, 1.0f);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, black);
    rtPolygonMode(RT_FRONT_AND_BACK, RT_FILL);
    rtDisable(RT_CULL_FACE);
    rtLineWidth(1.0f);
    rtPointSize(1.0f);
    rtDisable(RT_BLEND);
    rtBlendFunc(RT_ONE, RT_ZERO);
    rtDepthMask(RT_TRUE);
    for (int i = 0; i < 6; i++)
        rtDisable(RT_CLIP_PLANE0 + (RTenum)i);

    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    scene->projection();
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtNewObject(object);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT_AND_DIFFUSE, white);
    scene->shape();
    rtEndObject();
    rtLoadIdentity();
    rtBeginFrame(); /* before the view step, which may draw in immediate mode */
    scene->view();
    rtInstantiateObject(object);
    rtRenderFrame();
    rtReadPixels(0, 0, ORACLE_W, ORACLE_H, RT_RGBA, RT_UNSIGNED_BYTE, rgba);
    rtDeleteObjects(1, &object);
    error = rtGetError();
    if (error != RT_NO_ERROR) {
        fprintf(stderr, "gl_oracle: %s/%s: Tracelist error 0x%x\n", scene->family, scene->name,
                error);
        return 0;
    }
    return 1;
}

void oracle_rt_finish(void)
{
    rtMakeCurrent(NULL);
    rtDestroyContext(context);
    context = NULL;
}
