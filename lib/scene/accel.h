/* SPDX-License-Identifier: Apache-2.0 */
/*
 * accel.h - an object's acceleration structure: the one owner of building,
 * refitting, restructuring, swapping in and releasing a struct scene_accel.
 *
 * Every path that changes a structure (first build, rebuild, refit,
 * selective restructuring, an asynchronous build landing) goes through
 * this file, and each ends in the same step, finish_layout in accel.c,
 * which produces what traversal reads (the wide layout, and the
 * leaf-ordered triangles when the structure keeps them from the start)
 * and the tree's SAH cost.  A new traversal layout (wide nodes, say) is made
 * there and nowhere else.
 *
 * The strategy deciding which of these runs lives in update.c; the
 * background thread that runs asynchronous builds in async_build.c.
 */
#ifndef RT_SCENE_ACCEL_H
#define RT_SCENE_ACCEL_H

#include <stdint.h>

#include "accel/restructure.h"
#include "base/pool.h"
#include "trace/bvh4_layout.h"
#include "accel/bvh_build.h"

struct scene_object;

struct scene_accel {
    struct bvh bvh;
    /* Leaf-ordered vertices (accel_gather_triangles), for the binary
     * walks and the refit; NULL until first needed when the structure has
     * a wide layout (finish_layout in accel.c says when it is made with
     * the structure): scene_accel_triangles makes it.  Published with a
     * release store; render threads load it with acquire. */
    float *tri;
    struct bvh4 wide; /* the wide traversal layout of bvh, 4- or 8-wide (bvh4_layout.h) */
    uint32_t serial;   /* the object's serial this structure reflects */
    uint32_t topology; /* the object's topology serial it was built for */
    double sah_cost;       /* of the tree as it is now */
    double built_sah_cost; /* right after the last full build (rebuild heuristic) */
    double build_ms;       /* the last full build, wall clock (RT_OBJECT_BUILD_TIME) */
    /* The same build by rt_pool_work_ms (base/pool.h): CPU time, the
     * pool's tasks counted as the share of a frame they take; what
     * RT_AUTOMATIC weighs, since it does not grow with the load. */
    double build_cost_ms;
    /* The wide layout's share of the work (rtbench dynamic reports them):
     * the last collapse (full build or restructure, included in build_ms
     * for a build; 0 when no wide layout is made) and the last refit of
     * the wide layout from the refitted binary tree (0 before any refit). */
    double collapse_ms;
    double wide_refit_ms;
    /* Per-node life times and scratch of selective restructuring (Yoon, Curtis and Manocha
     * (2007)), initialised by its first use. */
    struct accel_restructure_state restructure_state;
    int restructure_state_ready;
};

/* Which builder a full build uses. */
enum scene_accel_builder {
    SCENE_ACCEL_SERIAL,   /* accel_build with params->builder */
    SCENE_ACCEL_MEDIAN,   /* accel_build_median (build_median.h) */
    SCENE_ACCEL_PARALLEL  /* accel_build_parallel on pool (pool may be NULL) */
};

/* The geometry a structure is built over: tri_count triangles indexing
 * positions (xyz per vertex).  Borrowed, never freed here. */
struct scene_accel_geometry {
    const float *positions;
    const uint32_t *indices;
    uint32_t tri_count;
};

/* A test hook (internal/automatic_cost): fn(user) is called once inside
 * every region whose time the automatic strategy weighs (each full build
 * here, the frame's tracing in lib/api/frame.c), where a preemption by
 * another process could land.  NULL in normal use. */
struct scene_preempt_hook {
    void (*fn)(void *user);
    void *user;
};

/*
 * A fresh structure over geom (serial and topology left 0 for the caller
 * to stamp).  pool (may be NULL) also shares the gather into leaf order
 * and the collapse to the wide layout, for any builder: the same bytes
 * as without it.  Unless scene_accel_triangles_at_build, the
 * leaf-ordered triangles are left out (tri NULL) until
 * scene_accel_triangles or a refit makes them.  Times itself into build_ms (wall) and build_cost_ms
 * (rt_pool_work_ms); hook may be NULL.  NULL on allocation failure.
 */
struct scene_accel *scene_accel_build(const struct scene_accel_geometry *geom,
                                      const struct bvh_build_params *params,
                                      enum scene_accel_builder builder, struct rt_pool *pool,
                                      const struct scene_preempt_hook *hook);
/* 1 when a fresh build of prim_count triangles makes the leaf-ordered
 * triangles with the structure: without a wide layout (every walk reads
 * them), for no triangles, and below params->rebuild_reuse_min_bytes of
 * them (BVH_REBUILD_REUSE_MIN_BYTES says why); 0 when it leaves them to
 * their first need.  rtbench's build row follows it. */
int scene_accel_triangles_at_build(const struct bvh_build_params *params, uint32_t prim_count);

/* scene_accel_build for a structure that replaces `old` (may be NULL):
 * the new wide layout is written into the old one's block when that fits
 * (accel_collapse_wide_reuse), and the new leaf-ordered triangles into
 * old's array when it has as many triangles (a deforming object) and is
 * at least params->rebuild_reuse_min_bytes, whose pages are already in
 * memory (a structure replacing one that had leaf-ordered triangles has
 * them from the start: the object's frames or refits needed them); so
 * old loses its wide layout and, then, its triangles once the new
 * structure is made (it keeps its binary tree; it is only to be
 * released then).  On
 * failure old is as it was.  For the synchronous rebuild, where old is
 * replaced and freed right after; not while another thread may walk
 * old. */
struct scene_accel *scene_accel_rebuild(const struct scene_accel_geometry *geom,
                                        const struct bvh_build_params *params,
                                        enum scene_accel_builder builder, struct rt_pool *pool,
                                        const struct scene_preempt_hook *hook,
                                        struct scene_accel *old);

/* Refits boxes and leaf-ordered triangles in place to geom's current
 * positions (same connectivity).  Allocates only the leaf-ordered
 * triangles' array, when the structure has none yet (a fresh build
 * leaves it out), and keeps it.  0, or -1 when that allocation fails
 * (accel unchanged). */
int scene_accel_refit(struct scene_accel *accel, const struct scene_accel_geometry *geom,
                       const struct bvh_build_params *params, struct rt_pool *pool);

/* The structure's leaf-ordered triangles over geom (the positions it
 * reflects), gathered now on first need and kept: what the binary walks
 * read (the hit filter's walk, the ties walk, a table without a wide
 * walk).  NULL on allocation failure (accel unchanged, still usable;
 * the next call tries again).  Not thread-safe for one structure: the
 * caller holds the object's build_lock (scene_object_triangles,
 * update.h), or no other thread can reach accel. */
const float *scene_accel_triangles(struct scene_accel *accel,
                                   const struct scene_accel_geometry *geom);

/* Selective restructuring (Yoon, Curtis and Manocha (2007)) of accel to geom's positions, with
 * the measured constants and rays_per_frame.  0, or -1 on allocation
 * failure (accel stays valid). */
int scene_accel_restructure(struct scene_accel *accel, const struct scene_accel_geometry *geom,
                            const struct bvh_build_params *params,
                            const struct accel_restructure_params *measured,
                            double rays_per_frame);

/* Publishes fresh as the object's structure (release store, so render
 * threads that load it with acquire see it whole) and frees the old one.
 * Counts a rebuild. */
void scene_accel_install(struct scene_object *object, struct scene_accel *fresh);

/* Frees a structure and everything it owns; NULL is ignored. */
void scene_accel_release(struct scene_accel *accel);

#endif
