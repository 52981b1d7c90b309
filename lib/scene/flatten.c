/* SPDX-License-Identifier: Apache-2.0 */
/*
 * flatten.c - flattening nested static hierarchies (see flatten.h).
 */
#include "scene/flatten.h"

#include <math.h>
#include <string.h>

#include <rt/rt.h>

#include "base/alloc.h"
#include "base/atomic.h"
#include "base/mat4.h"
#include "base/timer.h"
#include "scene/object.h"

/* Largest flattened group, in triangles: beyond it the copies cost more
 * memory (44 bytes a triangle plus the nodes) than instancing saves in
 * time, which is why instancing exists (Wald, Benthin and Slusallek (2003)
 * sec. 3: "affine" objects keep one structure for all their instances). */
#define FLAT_MAX_TRIANGLES (1u << 21)

/*
 * Cost constants of the model, in units of one ray/box test of the binary
 * walk.  A triangle test (the watertight test of Woop, Benthin and Wald
 * 2013) is about one and a half; a ray transformation into an instance's
 * space (two 3x4 matrix products in double, rounding, and the ray set-up
 * with its divisions, trace_scene_object_ray) about four.  An object's own
 * walk uses the wide layout where the context has one (one SIMD test of
 * 4 or 8 boxes a level, about two units, and log_8 levels), while the
 * flattened walk is binary and per ray (flat_walk.c: its member lookup,
 * transformation cache and per-slot bookkeeping make a level cost about
 * two and a half units), and its leaves change member for about a third
 * of the members the ray meets (the instance tests per ray of rtbench
 * nested).  These were fitted to rtbench nested's CPU times per ray on an
 * AVX2 machine (docs/performance.md): overlap sums 0.8, 2.3 and 7.8 where
 * flattening measured 1.3, 1.3-2.0 and 0.7 times the instanced time, and
 * the model says keep, keep, flatten.
 */
#define COST_BOX 1.0
#define COST_TRIANGLE 1.5
#define COST_TRANSFORM 4.0
#define COST_WIDE_NODE 2.0
#define COST_FLAT_NODE 2.5
#define FLAT_MEMBER_SWITCHES (1.0 / 3.0)
#define LEAF_SIZE 4.0

void scene_flats_init(struct scene_flats *flats)
{
    memset(flats, 0, sizeof(*flats));
}

static void flat_free(struct scene_flat *flat)
{
    if (flat->accel) {
        bvh_release(&flat->accel->bvh);
        rt_free(flat->accel->tri);
        rt_free(flat->accel->member);
        rt_free(flat->accel->prim);
        rt_free(flat->accel);
    }
    pthread_mutex_destroy(&flat->lock);
    rt_free(flat->members);
    rt_free(flat);
}

void scene_flats_clear(struct scene_flats *flats)
{
    for (uint32_t i = 0; i < flats->count; i++)
        flat_free(flats->items[i]);
    flats->count = 0;
}

void scene_flats_release(struct scene_flats *flats)
{
    scene_flats_clear(flats);
    rt_free(flats->items);
    flats->items = NULL;
    flats->capacity = 0;
}

/* The expected cost of an object's own walk over n triangles, for a ray
 * that reaches its root: the levels of a balanced tree down to one leaf,
 * then the leaf's triangles.  width: the wide layout's (0: binary). */
static double object_walk_cost(double n, int width)
{
    const double leaves = n > LEAF_SIZE ? n / LEAF_SIZE : 1.0;
    const double tri = COST_TRIANGLE * (n < LEAF_SIZE ? n : LEAF_SIZE);
    if (width >= 4)
        return COST_WIDE_NODE * (1.0 + log(leaves) / log((double)width)) + tri;
    return COST_BOX * (1.0 + 2.0 * log2(leaves)) + tri;
}

/* The same for the flattened walk (binary, flat_walk.c). */
static double flat_walk_cost(double n)
{
    const double leaves = n > LEAF_SIZE ? n / LEAF_SIZE : 1.0;
    return COST_FLAT_NODE * (1.0 + 2.0 * log2(leaves)) +
           COST_TRIANGLE * (n < LEAF_SIZE ? n : LEAF_SIZE);
}

/*
 * The cost model, per ray entering the group's box, with the surface
 * area heuristic's probabilities (MacDonald and Booth 1990: a ray that
 * meets a box meets a box inside it with the ratio of their areas).
 * Kept as instances: the top-level walk down to the members (about two
 * box tests per level of a tree over the n member boxes), then each
 * member the ray meets costs a transformation and a walk of its own tree
 * from its root.  Their sum S = sum_k A_k / A_group grows with the
 * overlap of the members' boxes, the cost Wald, Benthin and Slusallek
 * (2003) sec. 6 names ("Bounding Volume Overlap": in the overlap every
 * object is intersected in turn) beside the transformation cost per
 * object ("Transformation Cost").  Flattened: one walk over all N
 * triangles, whose boxes no longer overlap more than the triangles do,
 * plus the transformations of the members whose triangles the ray tests
 * (the flat walk tests each in its member's space, flat_walk.h).
 */
int scene_flat_decide(const struct scene_flats *flats, const struct scene_flat_candidate *c,
                      uint32_t n, float group_half_area, int changed, int wide_width,
                      int *not_static)
{
    *not_static = 0;
    if (flats->mode == SCENE_FLATTEN_OFF || n == 0)
        return 0;
    if (flats->mode == SCENE_FLATTEN_ON)
        return 1;
    /* Only a static hierarchy: no part moved relative to the root since
     * the last top level, and no member is an object the runtime updates
     * (classified affine or unstructured, or hinted so). */
    if (changed) {
        *not_static = 1;
        return 0;
    }
    double total = 0.0, overlap = 0.0, instanced = 0.0;
    for (uint32_t k = 0; k < n; k++) {
        const struct scene_object *o = c[k].object;
        if (o->class_hint != RT_AUTOMATIC && o->class_hint != RT_STATIC)
            return 0; /* hinted dynamic: for good */
        if (o->current_class != RT_STATIC) {
            *not_static = 1; /* classified dynamic at the last preparation */
            return 0;
        }
        total += c[k].triangles;
        const double p = group_half_area > 0.0f ? c[k].half_area / group_half_area : 1.0;
        overlap += p;
        instanced += p * (COST_TRANSFORM + object_walk_cost(c[k].triangles, wide_width));
    }
    if (total > FLAT_MAX_TRIANGLES)
        return 0;
    instanced += COST_BOX * 2.0 * log2((double)n);
    const double flattened =
        COST_TRANSFORM * (1.0 + FLAT_MEMBER_SWITCHES * overlap) + flat_walk_cost(total);
    return flattened < instanced;
}

/*
 * Two calls of one list place its members under matrices relative to the
 * root that are equal in exact arithmetic, but computed as root^-1 *
 * member in double they differ in the last bits from call to call.  They
 * share an entry when every element agrees within 2^-30 of the matrix's
 * magnitude: the entry's boxes (built with the first call's matrices) then
 * hold the other call's triangles with room to spare (each box is padded
 * by 2^-16 of its magnitude, padded_box), and each call's triangles are
 * still tested with its own members' matrices (flat_walk.h), so the
 * answers stay the instance path's.
 */
static int same_matrix(const double a[16], const double b[16])
{
    double mag = 0.0;
    for (int i = 0; i < 16; i++)
        mag = fabs(a[i]) > mag ? fabs(a[i]) : mag;
    const double tol = 0x1p-30 * (mag > 1.0 ? mag : 1.0);
    for (int i = 0; i < 16; i++)
        if (!(fabs(a[i] - b[i]) <= tol))
            return 0;
    return 1;
}

static int same_members(const struct scene_flat *f, const struct scene_flat_member *m,
                        uint32_t n)
{
    if (f->member_count != n)
        return 0;
    for (uint32_t k = 0; k < n; k++)
        if (f->members[k].object != m[k].object || f->members[k].serial != m[k].serial ||
            !same_matrix(f->members[k].rel, m[k].rel))
            return 0;
    return 1;
}

struct scene_flat *scene_flats_get(struct scene_flats *flats, struct scene_object *root,
                                   const struct scene_flat_member *members, uint32_t n,
                                   const struct bvh_build_params *params, int *changed)
{
    *changed = 0;
    int root_seen_before = 0;
    for (uint32_t i = 0; i < flats->count; i++) {
        struct scene_flat *f = flats->items[i];
        if (f->root != root)
            continue;
        if (same_members(f, members, n)) {
            f->used = 1;
            return f;
        }
        if (!f->used)
            root_seen_before = 1;
    }
    *changed = root_seen_before;
    if (flats->count == flats->capacity) {
        uint32_t cap = flats->capacity ? 2 * flats->capacity : 8;
        void *p = rt_realloc_array(flats->items, cap, sizeof(*flats->items));
        if (!p)
            return NULL;
        flats->items = p;
        flats->capacity = cap;
    }
    struct scene_flat *f = rt_calloc(1, sizeof(*f));
    if (!f)
        return NULL;
    f->members = rt_calloc(n, sizeof(*f->members));
    if (!f->members) {
        rt_free(f);
        return NULL;
    }
    memcpy(f->members, members, n * sizeof(*members));
    f->member_count = n;
    f->root = root;
    f->params = *params;
    for (uint32_t k = 0; k < n; k++)
        f->triangles += members[k].object->mesh.tri_count;
    pthread_mutex_init(&f->lock, NULL);
    f->used = 1;
    flats->items[flats->count++] = f;
    return f;
}

void scene_flats_unmark(struct scene_flats *flats)
{
    for (uint32_t i = 0; i < flats->count; i++)
        flats->items[i]->used = 0;
}

void scene_flats_sweep(struct scene_flats *flats)
{
    uint32_t kept = 0;
    for (uint32_t i = 0; i < flats->count; i++) {
        if (flats->items[i]->used)
            flats->items[kept++] = flats->items[i];
        else
            flat_free(flats->items[i]);
    }
    flats->count = kept;
}

/*
 * The box of a triangle in the root's space, padded.  Why padded: the
 * flat walk culls boxes in the root's space with the ray transformed by
 * the root's inverse, while the winning t comes from the member's own
 * space with the ray transformed by the member's inverse
 * (trace_scene_object_ray).  isect_triangle puts that t's point inside
 * the triangle's box in the member's space exactly (intersect.h), but the
 * two rounded ray transformations and the vertices' transformation here
 * (in double, rounded once to float) each differ from the exact map by a
 * few float ulps of the coordinates involved.  Padding every box by 2^-16
 * of its coordinates' magnitude (and of its extent) is a hundred times
 * those ulps; the box test itself keeps Ize's far scaling.  Padding only
 * makes the walk test more triangles, never changes an answer, since the
 * hit rule is order-free (flat_walk.h).  The residual assumption is the
 * one the top level already makes for instance boxes (frame.c): a ray
 * origin much farther from the group than its size, relative to the
 * padding, could still cull a grazing hit.
 */
static struct aabb padded_box(const float *p0, const float *p1, const float *p2,
                              const double rel[16])
{
    struct aabb box = aabb_empty();
    const float *v[3] = {p0, p1, p2};
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < 3; i++) {
        double q[3] = {v[i][0], v[i][1], v[i][2]}, w[3];
        mat4_transform_point(rel, q, w);
        for (int k = 0; k < 3; k++) {
            lo[k] = w[k] < lo[k] ? w[k] : lo[k];
            hi[k] = w[k] > hi[k] ? w[k] : hi[k];
        }
    }
    for (int k = 0; k < 3; k++) {
        const double mag = fabs(lo[k]) > fabs(hi[k]) ? fabs(lo[k]) : fabs(hi[k]);
        const double pad = 0x1p-16 * (mag + (hi[k] - lo[k])) + 0x1p-120;
        box.min[k] = (float)(lo[k] - pad);
        box.max[k] = (float)(hi[k] + pad);
        if ((double)box.min[k] > lo[k] - pad)
            box.min[k] = nextafterf(box.min[k], -INFINITY);
        if ((double)box.max[k] < hi[k] + pad)
            box.max[k] = nextafterf(box.max[k], INFINITY);
    }
    return box;
}

static struct scene_flat_accel *build(const struct scene_flat *flat)
{
    const double start = rt_now_ms();
    uint64_t n64 = flat->triangles;
    if (n64 > UINT32_MAX / 9)
        return NULL;
    uint32_t n = (uint32_t)n64;
    struct scene_flat_accel *a = rt_calloc(1, sizeof(*a));
    struct aabb *boxes = rt_calloc(n ? n : 1, sizeof(*boxes));
    uint32_t *member = rt_calloc(n ? n : 1, sizeof(*member));
    uint32_t *prim = rt_calloc(n ? n : 1, sizeof(*prim));
    if (!a || !boxes || !member || !prim)
        goto fail;
    uint32_t i = 0;
    for (uint32_t k = 0; k < flat->member_count; k++) {
        const struct scene_mesh *mesh = &flat->members[k].object->mesh;
        for (uint32_t t = 0; t < mesh->tri_count; t++, i++) {
            const uint32_t *idx = &mesh->indices[3 * (size_t)t];
            boxes[i] = padded_box(&mesh->positions[3 * (size_t)idx[0]],
                                  &mesh->positions[3 * (size_t)idx[1]],
                                  &mesh->positions[3 * (size_t)idx[2]], flat->members[k].rel);
            member[i] = k;
            prim[i] = t;
        }
    }
    if (accel_build(&a->bvh, boxes, n, &flat->params))
        goto fail;
    rt_free(boxes);
    boxes = NULL;
    /* Leaf order: the object-space vertices of each slot's triangle (the
     * floats its object's own structure gathers), its member and its
     * primitive. */
    a->tri = rt_calloc(9 * (size_t)(n ? n : 1), sizeof(float));
    a->member = rt_calloc(n ? n : 1, sizeof(uint32_t));
    a->prim = rt_calloc(n ? n : 1, sizeof(uint32_t));
    if (!a->tri || !a->member || !a->prim)
        goto fail;
    for (uint32_t s = 0; s < a->bvh.prim_count; s++) {
        const uint32_t j = a->bvh.prim_index[s];
        const struct scene_mesh *mesh = &flat->members[member[j]].object->mesh;
        const uint32_t *idx = &mesh->indices[3 * (size_t)prim[j]];
        for (int c = 0; c < 3; c++)
            memcpy(&a->tri[9 * (size_t)s + 3 * c], &mesh->positions[3 * (size_t)idx[c]],
                   3 * sizeof(float));
        a->member[s] = member[j];
        a->prim[s] = prim[j];
    }
    rt_free(member);
    rt_free(prim);
    a->build_ms = rt_now_ms() - start;
    return a;
fail:
    if (a) {
        bvh_release(&a->bvh);
        rt_free(a->tri);
        rt_free(a->member);
        rt_free(a->prim);
        rt_free(a);
    }
    rt_free(boxes);
    rt_free(member);
    rt_free(prim);
    return NULL;
}

const struct scene_flat_accel *scene_flat_acquire(struct scene_flat *flat, int *built_now)
{
    *built_now = 0;
    struct scene_flat_accel *a = rt_atomic_load_acquire(&flat->accel);
    if (a)
        return a;
    pthread_mutex_lock(&flat->lock);
    a = flat->accel;
    if (!a) {
        a = build(flat);
        if (a) {
            rt_atomic_store_release(&flat->accel, a);
            *built_now = 1;
        }
    }
    pthread_mutex_unlock(&flat->lock);
    return a;
}
