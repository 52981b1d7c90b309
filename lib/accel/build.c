/* SPDX-License-Identifier: Apache-2.0 */
/*
 * build.c - builder dispatch, parameters, BVH lifetime and the gather of
 * triangles into leaf order (see bvh_layout.h), plus the allocation helpers the
 * builders share (build_internal.h).
 *
 * Ownership: a struct bvh owns its nodes and prim_index arrays, both from
 * rt_malloc/rt_realloc_array; bvh_release returns them.
 */
#include "accel/bvh_build.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

#include "accel/build_internal.h"
#include "accel/triangle_box.h"
#include "base/alloc.h"
#include "base/pool.h"

#if defined(__SSE2__) && !defined(RT_NO_SIMD)
#include <xmmintrin.h>
#endif

void bvh_build_params_default(struct bvh_build_params *params)
{
    params->builder = BVH_BUILDER_BINNED_SAH;
    params->bins = BVH_DEFAULT_BINS;
    params->max_leaf_size = BVH_MAX_LEAF_SIZE;
    params->c_trav = BVH_C_TRAV;
    params->c_isect = BVH_C_ISECT;
    params->leaf_growth = 1.0f;
    params->wide_layout = 1;
    params->collapse = 0; /* BVH_COLLAPSE_GREEDY */
    params->rebuild_reuse_min_bytes = BVH_REBUILD_REUSE_MIN_BYTES;
}

void accel_build_params_normalize(struct bvh_build_params *out,
                                  const struct bvh_build_params *params)
{
    struct bvh_build_params d;
    bvh_build_params_default(&d);
    if (!params) {
        *out = d;
        return;
    }
    *out = *params;
    if (out->builder != BVH_BUILDER_BINNED_SAH && out->builder != BVH_BUILDER_SWEEP_SAH)
        out->builder = d.builder;
    if (out->bins < 2)
        out->bins = 2;
    if (out->bins > BVH_MAX_BINS)
        out->bins = BVH_MAX_BINS;
    if (out->max_leaf_size < 1)
        out->max_leaf_size = 1;
    if (out->max_leaf_size > BVH_MAX_LEAF_SIZE)
        out->max_leaf_size = BVH_MAX_LEAF_SIZE;
    if (!isfinite(out->c_trav) || !(out->c_trav >= 0.0f))
        out->c_trav = d.c_trav;
    if (!isfinite(out->c_isect) || !(out->c_isect > 0.0f))
        out->c_isect = d.c_isect;
    if (!isfinite(out->leaf_growth) || !(out->leaf_growth >= 1.0f))
        out->leaf_growth = d.leaf_growth;
}

int accel_build_alloc(struct bvh *out, uint32_t prim_count)
{
    memset(out, 0, sizeof(*out));
    /* A binary tree with n leaves' worth of primitives has at most 2n - 1
     * nodes; node indices are 32-bit. */
    if (prim_count == 0 || prim_count > (UINT32_MAX - 1) / 2 + 1)
        return -1;
    size_t max_nodes = 2 * (size_t)prim_count - 1;
    out->nodes = rt_realloc_array(NULL, max_nodes, sizeof(*out->nodes));
    out->prim_index = rt_realloc_array(NULL, prim_count, sizeof(*out->prim_index));
    if (!out->nodes || !out->prim_index) {
        bvh_release(out);
        return -1;
    }
    out->prim_count = prim_count;
    return 0;
}

void accel_build_finish(struct bvh *out, uint32_t node_count, uint32_t depth)
{
    out->node_count = node_count;
    out->depth = depth;
    struct bvh_node *shrunk = rt_realloc_array(out->nodes, node_count, sizeof(*out->nodes));
    if (shrunk)
        out->nodes = shrunk;
}

int accel_build(struct bvh *out, const struct aabb *prim_boxes, uint32_t prim_count,
                const struct bvh_build_params *params)
{
    struct bvh_build_params p;
    accel_build_params_normalize(&p, params);
    if (p.builder == BVH_BUILDER_SWEEP_SAH)
        return accel_build_sweep_sah(out, prim_boxes, prim_count, &p);
    return accel_build_binned_sah(out, prim_boxes, prim_count, &p);
}

void *build_spare_refs(uint64_t ref_bytes, struct rt_large_block *map)
{
    memset(map, 0, sizeof(*map));
    if (ref_bytes < BUILD_SPARE_MIN || ref_bytes > SIZE_MAX / 4 / BUILD_SPARE_FACTOR)
        return NULL;
    void *p = rt_malloc_large((size_t)(BUILD_SPARE_FACTOR * ref_bytes), map);
    if (p && !map->bytes) {
        rt_free_large(map); /* an rt_malloc block, not a mapping */
        p = NULL;
    }
    return p;
}

int accel_build_triangles(struct bvh *out, const float *positions, const uint32_t *indices,
                          uint32_t prim_count, const struct bvh_build_params *params,
                          struct rt_large_block *spare)
{
    struct bvh_build_params p;
    accel_build_params_normalize(&p, params);
    if (p.builder == BVH_BUILDER_BINNED_SAH) {
        const struct build_source src = {NULL, positions, indices};
        return build_binned_sah_source(out, &src, prim_count, &p, 1, spare);
    }
    if (spare)
        memset(spare, 0, sizeof(*spare));
    struct aabb *boxes = accel_triangle_boxes_pool(positions, indices, prim_count, NULL);
    if (!boxes) {
        memset(out, 0, sizeof(*out));
        return -1;
    }
    const int rc = accel_build_sweep_sah(out, boxes, prim_count, &p);
    rt_free(boxes);
    return rc;
}

int accel_build_begin(struct bvh *out, struct bvh_build_params *p,
                      const struct bvh_build_params *params, uint32_t prim_count)
{
    accel_build_params_normalize(p, params);
    if (prim_count == 0) {
        memset(out, 0, sizeof(*out));
        return 0;
    }
    return accel_build_alloc(out, prim_count) ? -1 : 1;
}

void bvh_release(struct bvh *bvh)
{
    rt_free(bvh->nodes);
    rt_free(bvh->prim_index);
    memset(bvh, 0, sizeof(*bvh));
}

/* The gather's inputs and output. */
struct gather_job {
    const struct bvh *bvh;
    const float *positions;
    const uint32_t *indices;
    float *tri;
};

/* Slots (and triangles, for the boxes) per chunk: 64 KB of leaf-ordered
 * triangles written per chunk, few enough chunks that the shared counter
 * costs nothing. */
#define GATHER_CHUNK 2048u
/* Below this many slots the gather stays on the calling thread: it is
 * shorter than waking the pool. */
#define GATHER_PARALLEL_MIN 16384u

static void gather_slots(void *arg, uint32_t begin, uint32_t end)
{
    const struct gather_job *g = arg;
    for (uint32_t slot = begin; slot < end; slot++)
        accel_gather_triangle(&g->tri[9 * (size_t)slot], g->positions, g->indices,
                              g->bvh->prim_index[slot]);
}

float *accel_gather_triangles_pool(const struct bvh *bvh, const float *positions,
                                   const uint32_t *indices, struct rt_pool *pool)
{
    /* One byte even for an empty BVH, so that NULL always means failure. */
    float *tri = rt_realloc_array(NULL, bvh->prim_count ? 9 * (size_t)bvh->prim_count : 1,
                                  sizeof(*tri));
    if (!tri)
        return NULL;
    accel_gather_triangles_into(bvh, positions, indices, pool, tri);
    return tri;
}

void accel_gather_triangles_into(const struct bvh *bvh, const float *positions,
                                 const uint32_t *indices, struct rt_pool *pool, float *tri)
{
    struct gather_job g = {bvh, positions, indices, tri};
    rt_pool_run_range(pool, 0, bvh->prim_count, GATHER_CHUNK, GATHER_PARALLEL_MIN, gather_slots,
                      &g);
}

/* The triangle boxes' inputs and output. */
struct boxes_job {
    const float *positions;
    const uint32_t *indices;
    struct aabb *boxes;
};

/* The boxes of triangles [begin, end) (triangle_box.h: the SSE2 form
 * where there is one, the same floats as the portable form). */
static void triangle_boxes(void *arg, uint32_t begin, uint32_t end)
{
    const struct boxes_job *b = arg;
#if defined(__SSE2__) && !defined(RT_NO_SIMD)
    for (uint32_t j = begin; j < end; j++) {
        __m128 lo, hi;
        triangle_box4(b->positions, b->indices, j, &lo, &hi);
        /* min xyz and max x in one store, max yz in a second: the box is
         * 24 bytes, and a 16-byte store of max would reach the next. */
        const __m128 t = _mm_shuffle_ps(lo, hi, _MM_SHUFFLE(0, 0, 2, 2)); /* lo2 lo2 hi0 hi0 */
        float *dst = (float *)(void *)&b->boxes[j];
        _mm_storeu_ps(dst, _mm_shuffle_ps(lo, t, _MM_SHUFFLE(2, 0, 1, 0)));
        _mm_storel_pi((__m64 *)(void *)(dst + 4), _mm_shuffle_ps(hi, hi, _MM_SHUFFLE(3, 3, 2, 1)));
    }
#else
    for (uint32_t j = begin; j < end; j++)
        b->boxes[j] = triangle_box(b->positions, b->indices, j);
#endif
}

struct aabb *accel_triangle_boxes_pool(const float *positions, const uint32_t *indices,
                                       uint32_t count, struct rt_pool *pool)
{
    struct aabb *boxes = rt_realloc_array(NULL, count ? count : 1, sizeof(*boxes));
    if (!boxes)
        return NULL;
    struct boxes_job b = {positions, indices, boxes};
    rt_pool_run_range(pool, 0, count, GATHER_CHUNK, GATHER_PARALLEL_MIN, triangle_boxes, &b);
    return boxes;
}

float *accel_gather_triangles(const struct bvh *bvh, const float *positions,
                              const uint32_t *indices)
{
    return accel_gather_triangles_pool(bvh, positions, indices, NULL);
}
