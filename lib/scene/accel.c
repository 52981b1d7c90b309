/* SPDX-License-Identifier: Apache-2.0 */
/*
 * accel.c - building, refitting, restructuring and swapping an object's
 * acceleration structure (see accel.h).
 */
#include "scene/accel.h"

#include "accel/build_median.h"
#include "accel/build_parallel.h"
#include "accel/collapse_mesh.h"
#include "accel/refit.h"
#include "base/alloc.h"
#include "base/atomic.h"
#include "base/timer.h"
#include "scene/object.h"

/* Whether prim_count leaf-ordered triangles (nine floats each) reach
 * params->rebuild_reuse_min_bytes: the size from which a fresh build
 * leaves them out and a rebuild reuses the replaced array. */
static int triangles_large(const struct bvh_build_params *params, uint32_t prim_count)
{
    return (uint64_t)prim_count * 9 * sizeof(float) >= params->rebuild_reuse_min_bytes;
}

int scene_accel_triangles_at_build(const struct bvh_build_params *params, uint32_t prim_count)
{
    return !params->wide_layout || !prim_count || !triangles_large(params, prim_count);
}

/* The step after every change of the tree's topology: the wide layout
 * traversal reads, the leaf-ordered triangles when this structure keeps
 * them (below), and the cost the update strategies compare.  Returns 0,
 * or -1 on allocation failure (accel->tri unchanged, or regathered in
 * place for accel's tree when it had one; accel->wide unchanged, or
 * released when the collapse itself failed; old unchanged).  Times the
 * collapse into accel->collapse_ms.
 *
 * The leaf-ordered triangles (36 bytes a triangle) are read only by the
 * binary walks: the hit filter's, the ties walk, a table or a structure
 * without a wide layout, and by the refit (accel.h).  A structure keeps
 * them from the start only when scene_accel_triangles_at_build says so
 * (no wide layout to walk: isa=scalar, an empty object; or an array
 * below params->rebuild_reuse_min_bytes, which the heap gives back warm,
 * where the gather and the collapse's sequential read of the copy cost
 * less than the collapse's scattered reads of the mesh), when it
 * replaces one that had them (the object's frames or its refits needed
 * them: a deforming object's rebuild), or when restructuring regathers
 * the array it already has (in place, before the collapse); otherwise the
 * collapse reads the triangles from the mesh (collapse_mesh.h, the same
 * layout byte for byte) and scene_accel_triangles gathers them on first
 * need.
 * The new layout reuses the block of the one it replaces when it fits:
 * accel's own, or old's (may be NULL), whose wide layout is then
 * released (accel_collapse_wide_reuse).  A structure old of as many
 * triangles (a deforming object's rebuild) also gives its leaf-ordered
 * triangles' array, whose pages are in memory, to the new gather when it
 * is at least params->rebuild_reuse_min_bytes (BVH_REBUILD_REUSE_MIN_BYTES
 * says why smaller arrays are not worth it), written only after the
 * collapse has succeeded, so that a failure leaves old whole. */
static int finish_layout(struct scene_accel *accel, const struct scene_accel_geometry *geom,
                         const struct bvh_build_params *params, struct rt_pool *pool,
                         struct scene_accel *old, struct rt_large_block *scratch)
{
    const int keep_tri = scene_accel_triangles_at_build(params, accel->bvh.prim_count) ||
                         accel->tri || (old && old->tri);
    const int reuse_old_tri = !accel->tri && old && old->tri && accel->bvh.prim_count &&
                              old->bvh.prim_count == accel->bvh.prim_count &&
                              triangles_large(params, accel->bvh.prim_count);
    float *tri = NULL;
    if (accel->tri) {
        /* Restructuring (the same triangles, a new leaf order): regathered
         * in place before the collapse, which then reads the copy; this
         * cannot fail, and the tree it follows is already the new one. */
        accel_gather_triangles_into(&accel->bvh, geom->positions, geom->indices, pool,
                                    accel->tri);
        tri = accel->tri;
    } else if (keep_tri && !reuse_old_tri) {
        tri = accel_gather_triangles_pool(&accel->bvh, geom->positions, geom->indices, pool);
        if (!tri)
            return -1;
    }
    struct bvh4 wide = {0};
    const uint32_t width = params->wide_layout == 8 ? 8u : 4u;
    double start = rt_now_ms();
    struct rt_large_block *spare = old ? &old->wide.raw : &accel->wide.raw;
    /* No layout block to reuse (a first build): the build's scratch
     * mapping, if it left one (accel_build_parallel_triangles), whose
     * pages it touched already; the caller frees it if not taken. */
    if (!spare->bytes && scratch && scratch->bytes)
        spare = scratch;
    /* A structure that will be refit (restructuring's, which runs on a
     * deforming object, or a deforming object's rebuild: both had their
     * leaf-ordered triangles, which only a refit or a frame needs) keeps
     * the zero-area triangles in its layout, so that its refits stay in
     * place (accel_refit4); any other leaves them out, which no answer
     * sees (collapse4.c, drop_zero_area), and its first refit collapses
     * again (scene_accel_refit). */
    const int refit_likely = accel->tri || (old && old->tri);
    const struct collapse_triangles tris = {tri, tri ? NULL : geom->positions,
                                            tri ? NULL : geom->indices, refit_likely};
    if (params->wide_layout &&
        accel_collapse_wide_source(&wide, &accel->bvh, &tris, width, pool, spare,
                                   params->collapse)) {
        /* The tree may have changed under the old wide layout
         * (restructuring): drop it, so traversal takes the binary walk. */
        bvh4_release(&accel->wide);
        if (tri != accel->tri)
            rt_free(tri);
        return -1;
    }
    accel->collapse_ms = params->wide_layout ? rt_now_ms() - start : 0.0;
    if (reuse_old_tri) {
        /* Nothing fails from here on.  old is released right after
         * (scene_accel_rebuild's contract), without its triangles. */
        tri = old->tri;
        old->tri = NULL;
        accel_gather_triangles_into(&accel->bvh, geom->positions, geom->indices, pool, tri);
    }
    if (old)
        bvh4_release(&old->wide); /* its block may be the new layout's */
    if (tri != accel->tri)
        rt_free(accel->tri);
    accel->tri = tri;
    bvh4_release(&accel->wide);
    accel->wide = wide;
    accel->sah_cost = accel_sah_cost(&accel->bvh, params->c_trav, params->c_isect);
    return 0;
}

struct scene_accel *scene_accel_build(const struct scene_accel_geometry *geom,
                                      const struct bvh_build_params *params,
                                      enum scene_accel_builder builder, struct rt_pool *pool,
                                      const struct scene_preempt_hook *hook)
{
    return scene_accel_rebuild(geom, params, builder, pool, hook, NULL);
}

struct scene_accel *scene_accel_rebuild(const struct scene_accel_geometry *geom,
                                        const struct bvh_build_params *params,
                                        enum scene_accel_builder builder, struct rt_pool *pool,
                                        const struct scene_preempt_hook *hook,
                                        struct scene_accel *old)
{
    double start = rt_now_ms(), work = rt_pool_work_ms(pool);
    if (hook && hook->fn)
        hook->fn(hook->user);
    struct scene_accel *accel = rt_calloc(1, sizeof(*accel));
    struct rt_large_block scratch = {0};
    /* The parallel and the serial SAH builders compute the triangles'
     * boxes as they set up their refs (no box array: fewer fresh pages a
     * build); the median builder takes boxes. */
    struct aabb *boxes =
        builder != SCENE_ACCEL_MEDIAN
            ? NULL
            : accel_triangle_boxes_pool(geom->positions, geom->indices, geom->tri_count, pool);
    if (!accel || (builder == SCENE_ACCEL_MEDIAN && !boxes))
        goto fail;
    int status;
    if (builder == SCENE_ACCEL_MEDIAN)
        status = accel_build_median(&accel->bvh, boxes, geom->tri_count, params);
    else if (builder == SCENE_ACCEL_PARALLEL)
        status = accel_build_parallel_triangles(&accel->bvh, geom->positions, geom->indices,
                                                geom->tri_count, params, pool, &scratch);
    else
        /* The refs' mapping only when no old layout's block will take the
         * new layout (finish_layout): otherwise a heap block, which a
         * rebuild finds warm from the last one. */
        status = accel_build_triangles(&accel->bvh, geom->positions, geom->indices,
                                       geom->tri_count, params,
                                       old && old->wide.raw.bytes ? NULL : &scratch);
    if (status || finish_layout(accel, geom, params, pool, old, &scratch))
        goto fail;
    rt_free_large(&scratch);
    rt_free(boxes);
    accel->built_sah_cost = accel->sah_cost;
    accel->build_ms = rt_now_ms() - start;
    accel->build_cost_ms = rt_pool_work_ms(pool) - work;
    return accel;
fail:
    rt_free_large(&scratch);
    rt_free(boxes);
    scene_accel_release(accel);
    return NULL;
}

/* Boxes and leaf-ordered triangles in one pass over the leaves (Wald, Ize and Parker (2008)
 * sec. 6 interleaves the two the same way): the refit updates the layout
 * in place, so finish_layout's gather is not needed, only the cost.  The
 * topology is unchanged, so the wide layout keeps its shape and only
 * takes the refitted boxes and triangles (timed into
 * accel->wide_refit_ms).  A structure without its leaf-ordered triangles
 * (a fresh build, finish_layout) gets the array here, once: the refit
 * writes every float of it (accel_refit_mesh rewrites the triangles from
 * the mesh before it reads them), and keeps it for the next refits. */
int scene_accel_refit(struct scene_accel *accel, const struct scene_accel_geometry *geom,
                      const struct bvh_build_params *params, struct rt_pool *pool)
{
    if (!accel->tri) {
        const uint32_t n = accel->bvh.prim_count;
        accel->tri = rt_realloc_array(NULL, n ? 9 * (size_t)n : 1, sizeof(float));
        if (!accel->tri)
            return -1;
    }
    accel_refit_mesh(&accel->bvh, accel->tri, geom->positions, geom->indices, pool);
    double start = rt_now_ms();
    if (accel_refit4(&accel->wide, &accel->bvh, accel->tri)) {
        /* The collapse left zero-area triangles out of the layout
         * (bvh4_layout.h, dropped), and the moved vertices may have given
         * one an area: a new layout over the refit tree, with them kept,
         * so that the next refits are in place again.  Should it fail,
         * the layout goes and traversal takes the binary walk (as
         * finish_layout). */
        const struct collapse_triangles tris = {accel->tri, NULL, NULL, 1};
        struct bvh4 wide = {0};
        if (accel_collapse_wide_source(&wide, &accel->bvh, &tris, accel->wide.width, pool,
                                       &accel->wide.raw, params->collapse))
            bvh4_release(&accel->wide);
        else {
            bvh4_release(&accel->wide);
            accel->wide = wide;
        }
    }
    accel->wide_refit_ms = rt_now_ms() - start;
    accel->sah_cost = accel_sah_cost(&accel->bvh, params->c_trav, params->c_isect);
    return 0;
}

const float *scene_accel_triangles(struct scene_accel *accel,
                                   const struct scene_accel_geometry *geom)
{
    const float *tri = rt_atomic_load_acquire(&accel->tri);
    if (tri)
        return tri;
    float *gathered = accel_gather_triangles(&accel->bvh, geom->positions, geom->indices);
    /* Whole before it is seen: readers load accel->tri with acquire. */
    if (gathered)
        rt_atomic_store_release(&accel->tri, gathered);
    return gathered;
}

int scene_accel_restructure(struct scene_accel *accel, const struct scene_accel_geometry *geom,
                            const struct bvh_build_params *params,
                            const struct accel_restructure_params *measured,
                            double rays_per_frame)
{
    struct aabb *boxes =
        accel_triangle_boxes_pool(geom->positions, geom->indices, geom->tri_count, NULL);
    if (!boxes)
        return -1;
    if (!accel->restructure_state_ready) {
        accel_restructure_state_init(&accel->restructure_state);
        accel->restructure_state_ready = 1;
    }
    struct accel_restructure_params rp = *measured;
    rp.rays_per_frame = rays_per_frame;
    struct accel_restructure_stats stats;
    int status =
        accel_restructure(&accel->bvh, boxes, &accel->restructure_state, &rp, &stats);
    rt_free(boxes);
    if (status)
        return -1;
    /* Restructuring moves primitives between leaves: regather. */
    return finish_layout(accel, geom, params, NULL, NULL, NULL);
}

void scene_accel_install(struct scene_object *object, struct scene_accel *fresh)
{
    struct scene_accel *old = object->accel;
    rt_atomic_store_release(&object->accel, fresh);
    scene_accel_release(old);
    object->rebuilds++;
}

void scene_accel_release(struct scene_accel *accel)
{
    if (!accel)
        return;
    bvh_release(&accel->bvh);
    rt_free(accel->tri);
    bvh4_release(&accel->wide);
    if (accel->restructure_state_ready)
        accel_restructure_state_release(&accel->restructure_state);
    rt_free(accel);
}
