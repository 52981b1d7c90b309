/* SPDX-License-Identifier: Apache-2.0 */
/*
 * frame.h - instances and the immediate-mode frame (Wald, Benthin and Slusallek (2003) sec. 4.1).
 *
 * The application re-issues its instances every frame, as it would call
 * glCallList.  Instances go to the `pending` list; before rays are traced
 * the pending list is compared with the committed one (same objects, same
 * definitions, same matrices, same order).  Only when they differ is the
 * committed list replaced and the top-level BVH rebuilt, so re-issuing an
 * unchanged frame costs a comparison and no build.
 *
 * The top level is a BVH over the world-space boxes of the instances'
 * object boxes (Wald, Benthin and Slusallek (2003) sec. 4.5 builds a BSP over the same boxes; we
 * use the binned SAH builder over boxes, and rays are clipped exactly by
 * the object box in object space by the object BVH's root).
 */
#ifndef RT_SCENE_FRAME_H
#define RT_SCENE_FRAME_H

#include <stdint.h>

#include "accel/bvh_build.h"
#include "scene/clip.h"
#include "scene/flatten.h"
#include "scene/gl_state.h"
#include "scene/object.h"
#include "scene/raster_state.h"
#include "scene/recording.h"
#include "trace/scene_traverse.h"

/* The appearance current when an instance was issued: what its triangles
 * with inherited material properties or TRI_INHERIT_COLOR (mesh.h) take. */
struct scene_appearance {
    struct scene_material material;
    float color[4];
    int color_material; /* RT_COLOR_MATERIAL enabled */
    /* The clip planes the instance's geometry was drawn under (clip.h):
     * every instance carries its own, as GL clips per primitive. */
    struct scene_clip clip;
    /* Fog and the light model the geometry was drawn under (gl_state.h),
     * per primitive as GL. */
    struct scene_gl_state gl;
    /* rtShadeModel(RT_FLAT) at the call: what triangles recorded in a
     * list before it set a shade model take (TRI_INHERIT_SHADE, mesh.h). */
    int flat;
    /* The blend, alpha-test, polygon-offset, line-width and point-size
     * state it was drawn under (raster_state.h), per primitive as GL. */
    struct scene_raster raster;
};

struct scene_instance {
    struct scene_object *object;
    uint32_t object_serial;     /* object->serial when issued */
    double object_to_world[16]; /* the modelview at rtInstantiateObject */
    double world_to_object[16];
    double normal_to_world[16]; /* inverse transpose of object_to_world */
    struct scene_appearance appearance;
    /* The application-level list call that placed it (flatten.h): 0
     * outside any, else a number shared by the segments of one call;
     * depth its nesting level (1: the called list's own segment), root
     * the called list and root_to_world / world_to_root the modelview at
     * the call and its inverse. */
    uint32_t group;
    uint32_t depth;
    struct scene_object *root;
    double root_to_world[16];
    double world_to_root[16];
    /* 1 when it was drawn under a projection or viewport other than the
     * frame's (scene_frame.trace_projection): not traced, rasterised as GL
     * draws it (render/raster.h).  Set by scene_frame_prepare. */
    uint8_t overlay;
};

struct scene_instance_list {
    struct scene_instance *items;
    uint32_t count;
    uint32_t capacity;
};

/*
 * Immediate mode: rtBegin/rtEnd and draw calls outside display lists.
 * The frame's immediate geometry is cut into segments, one per run of
 * blocks under the same modelview; segment i of a frame is recorded in
 * the modelview's object space and instanced under it, through the
 * hidden object slots[i], which persists from frame to frame.  When a
 * segment is committed it is compared with what its slot holds: equal
 * geometry keeps the slot as it is (static class, no build); a new
 * definition with the same connectivity keeps the stale structure for the
 * update strategies (unstructured class: refit or rebuild); otherwise it
 * is rebuilt.  The same mesh under a new modelview is an instance that
 * moved (affine class).  A modelview that cannot be inverted leaves the
 * vertices transformed in the recording, under an identity instance.
 */
struct scene_immediate {
    struct scene_recording rec; /* the open segment's geometry */
    int open;
    double matrix[16];       /* the open segment's modelview (its instance matrix) */
    double block_matrix[16]; /* what its blocks transform vertices by */
    struct scene_object **slots;
    struct scene_mesh *staged; /* per slot: the segment recorded this frame */
    uint8_t *is_staged;        /* per slot: staged holds a mesh to commit */
    uint32_t used, capacity; /* slots used by this frame; allocated */
    uint64_t kept, redefined; /* segments committed unchanged / changed, ever */
    struct scene_clip clip;   /* the open segment's clip planes (its instance's) */
    struct scene_gl_state gl; /* the open segment's fog and light model */
    struct scene_raster raster; /* the open segment's raster state (its instance's) */
};

/* The distinct light sets (gl_state.h) the primitives of one frame were
 * drawn under, referenced by index from scene_gl_state.light_set. */
struct scene_light_sets {
    struct scene_light_set *items;
    uint32_t *hashes; /* per item, to skip most comparisons */
    uint32_t count, capacity;
};

struct scene_frame {
    struct scene_instance_list pending;
    int open; /* pending is the list being described */
    struct scene_instance_list committed;

    /* The top level over `committed`; valid when top_valid.  Built with
     * the binned SAH over instance boxes, or with Wald, Benthin and Slusallek (2003) sec. 4.5's
     * rule when toplevel_cellsplit is set ("toplevel=cellsplit"). */
    int top_valid;
    int toplevel_cellsplit;
    struct bvh top;
    /* `top` collapsed to the context's wide layout (params->wide_layout:
     * 4 or 8 wide, range leaves of instance slots) after every top-level
     * build, walked by the SIMD tables; node_count 0 when there is none
     * (isa=scalar), and then the binary walk over `top` runs. */
    struct bvh4 top_wide;
    struct trace_instance *trace_instances; /* one per non-empty instance */
    uint32_t trace_instance_count;

    struct scene_immediate immediate;

    /* The light sets of `pending`'s instances, and of `committed`'s
     * (copied at scene_frame_prepare with the instances' appearance).
     * light_sets_serial changes whenever pending_lights restarts, so that
     * a caller caching an index knows when it is stale; light_sets_fresh:
     * restarted already for the list the next instance starts. */
    struct scene_light_sets pending_lights, committed_lights;
    uint64_t light_sets_serial;
    int light_sets_fresh;
    /* Nested static hierarchies (flatten.h): the entries, and the group
     * the instances being added belong to (scene_frame_group_begin). */
    struct scene_flats flats;
    uint32_t group_next, group_current, group_depth;
    struct scene_object *group_root;
    double group_m[16], group_inv[16];

    /* The viewport and projection the frame is traced through, set before
     * scene_frame_prepare; with overlay_enabled (GL frames, started by
     * rtClear), scene_frame_prepare replaces the projection by the
     * draw-time projection of the most depth-tested triangles (frame.c),
     * and instances drawn under another one are not traced
     * (scene_instance.overlay).  The comparison happens here, at
     * preparation, because only then is the frame's projection known; an
     * instance drawn under the frame's costs a memcmp. */
    int overlay_enabled;
    int32_t trace_viewport[4];
    double trace_projection[16];
};

void scene_frame_init(struct scene_frame *frame);
void scene_frame_release(struct scene_frame *frame);

/* Appends an instance to the frame being described (starting a new list
 * if the last frame ended).  Returns 0, -1 on allocation failure. */
int scene_frame_add_instance(struct scene_frame *frame, struct scene_object *object,
                             const double object_to_world[16], const double world_to_object[16],
                             const double normal_to_world[16]);

/* The same with the appearance current at the call (NULL: none). */
int scene_frame_add_instance_appearance(struct scene_frame *frame, struct scene_object *object,
                                        const double object_to_world[16],
                                        const double world_to_object[16],
                                        const double normal_to_world[16],
                                        const struct scene_appearance *appearance);

/* Immediate mode.  scene_immediate_segment makes the open segment the
 * one of `modelview`, `clip`, `gl` and `raster` (committing the open one
 * if its modelview, clip planes, fog, light model or raster state differ,
 * starting the frame's list if the last frame ended) and returns the
 * recording vertices go to; its block_matrix is what blocks transform
 * by.  NULL on allocation failure.  scene_immediate_commit commits the
 * open segment (scene_frame_prepare does it first); 0, -1 on allocation
 * failure. */
struct scene_recording *scene_immediate_segment(struct scene_frame *frame,
                                                const double modelview[16],
                                                const struct scene_clip *clip,
                                                const struct scene_gl_state *gl,
                                                const struct scene_raster *raster);
void scene_immediate_commit(struct scene_frame *frame, uint64_t frame_number);
/* Ends the open segment (the next block starts a new one). */
void scene_immediate_close(struct scene_frame *frame);
/* Drops the segments recorded and not committed (a new frame). */
void scene_immediate_restart(struct scene_immediate *im);
void scene_immediate_release(struct scene_immediate *im);

/*
 * The index in the frame's table of the light set `lights` (the eight as
 * current now; disabled ones are zeroed in the entry) for an instance
 * about to be added: equal sets share one entry.  When the last frame
 * ended, the table restarts for the next one first.  UINT32_MAX on
 * allocation failure (shading then takes the frame's lights).
 * (light_set.c)
 */
uint32_t scene_frame_light_set(struct scene_frame *frame,
                               const struct scene_light lights[SCENE_MAX_LIGHTS]);
/* pending_lights restarts with the instance list (frame.c); committed
 * takes a copy of it (scene_frame_prepare).  0, -1 on allocation failure. */
void scene_light_sets_restart(struct scene_frame *frame);
int scene_light_sets_commit(struct scene_frame *frame);
void scene_light_sets_release(struct scene_frame *frame);
/* The instances added until scene_frame_group_end come from one call of
 * root under modelview m (flatten.h); group_depth (set by the caller)
 * is their nesting level.  A singular m starts no group. */
void scene_frame_group_begin(struct scene_frame *frame, struct scene_object *root,
                             const double m[16]);
void scene_frame_group_end(struct scene_frame *frame);

/* Starts a new, empty list (rtBeginFrame). */
void scene_frame_begin(struct scene_frame *frame);

/* Ends the frame: the next instance starts a new list (rtRenderFrame). */
void scene_frame_end(struct scene_frame *frame);

/* Reopens the frame just ended: what is drawn next adds to its list and
 * its immediate segments (a GL frame goes on after glFlush until the next
 * glClear, as GL's framebuffer keeps what was drawn). */
void scene_frame_continue(struct scene_frame *frame);

/* The world-space box of an instance (its object's box under its
 * matrix, rounded outwards). */
struct aabb scene_instance_box(const struct scene_instance *instance);

/* The world-space (eye-space) vertices of triangle `prim` of an
 * instance, in double under its matrix: instances with equal matrices
 * give equal points, which the face and shared-edge tests rely on. */
void scene_instance_world_triangle(const struct scene_instance *instance, uint32_t prim,
                                   double p[3][3]);

/* Drops every instance of the object from both lists (rtDeleteObjects). */
void scene_frame_forget_object(struct scene_frame *frame, const struct scene_object *object);

/*
 * Makes the committed list current and the top level valid.  When the
 * list changes, the objects of instances whose matrix differs from the
 * instance at the same position before get moved_frame = frame_number
 * (the affine class of Wald, Benthin and Slusallek (2003) sec. 3).  Returns 0
 * with *toplevel_built = 1 if a top-level build happened, 0 if nothing
 * changed; -1 on allocation failure (the previous committed scene stays).
 */
int scene_frame_prepare(struct scene_frame *frame, const struct bvh_build_params *params,
                        uint64_t frame_number, int *toplevel_built);

#endif
