/* SPDX-License-Identifier: Apache-2.0 */
/*
 * frame.c - instance lists, change detection and the top-level build
 * (see frame.h).
 */
#include "scene/frame.h"

#include <string.h>

#include "accel/build_toplevel.h"
#include "base/alloc.h"
#include "base/mat4.h"

void scene_frame_init(struct scene_frame *frame)
{
    memset(frame, 0, sizeof(*frame));
}

void scene_frame_release(struct scene_frame *frame)
{
    scene_immediate_release(&frame->immediate);
    scene_light_sets_release(frame);
    rt_free(frame->pending.items);
    rt_free(frame->committed.items);
    bvh_release(&frame->top);
    bvh4_release(&frame->top_wide);
    rt_free(frame->trace_instances);
    scene_flats_release(&frame->flats);
    scene_frame_init(frame);
}

static int list_reserve(struct scene_instance_list *list, uint32_t count)
{
    if (count <= list->capacity)
        return 0;
    uint32_t cap = list->capacity ? list->capacity : 16;
    while (cap < count) {
        if (cap > UINT32_MAX / 2)
            return -1;
        cap *= 2;
    }
    void *p = rt_realloc_array(list->items, cap, sizeof(*list->items));
    if (!p)
        return -1;
    list->items = p;
    list->capacity = cap;
    return 0;
}

int scene_frame_add_instance(struct scene_frame *frame, struct scene_object *object,
                             const double object_to_world[16], const double world_to_object[16],
                             const double normal_to_world[16])
{
    return scene_frame_add_instance_appearance(frame, object, object_to_world, world_to_object,
                                               normal_to_world, NULL);
}

int scene_frame_add_instance_appearance(struct scene_frame *frame, struct scene_object *object,
                                        const double object_to_world[16],
                                        const double world_to_object[16],
                                        const double normal_to_world[16],
                                        const struct scene_appearance *appearance)
{
    uint32_t count = frame->open ? frame->pending.count : 0;
    if (count == UINT32_MAX || list_reserve(&frame->pending, count + 1))
        return -1;
    if (!frame->open) {
        frame->pending.count = 0;
        frame->open = 1;
        scene_light_sets_restart(frame);
        /* Group numbers count from 1 each frame, so an unchanged frame
         * compares equal (scene_frame_group_begin numbered this one). */
        if (!frame->group_current)
            frame->group_next = 0;
        if (frame->immediate.open || frame->immediate.used)
            scene_immediate_restart(&frame->immediate);
    }
    struct scene_instance *inst = &frame->pending.items[frame->pending.count++];
    memset(inst, 0, sizeof(*inst));
    inst->object = object;
    inst->object_serial = object->serial;
    memcpy(inst->object_to_world, object_to_world, sizeof(inst->object_to_world));
    memcpy(inst->world_to_object, world_to_object, sizeof(inst->world_to_object));
    memcpy(inst->normal_to_world, normal_to_world, sizeof(inst->normal_to_world));
    if (appearance)
        inst->appearance = *appearance;
    if (frame->group_current) {
        inst->group = frame->group_current;
        inst->depth = frame->group_depth;
        inst->root = frame->group_root;
        memcpy(inst->root_to_world, frame->group_m, sizeof(inst->root_to_world));
        memcpy(inst->world_to_root, frame->group_inv, sizeof(inst->world_to_root));
    }
    return 0;
}

void scene_frame_group_begin(struct scene_frame *frame, struct scene_object *root,
                             const double m[16])
{
    frame->group_current = 0;
    if (!frame->open)
        frame->group_next = 0; /* the first call of a new frame */
    if (m[3] != 0.0 || m[7] != 0.0 || m[11] != 0.0 || m[15] != 1.0 ||
        !mat4_invert(frame->group_inv, m))
        return;
    memcpy(frame->group_m, m, sizeof(frame->group_m));
    frame->group_root = root;
    /* Never 0 (no group), also after wrapping. */
    if (++frame->group_next == 0)
        frame->group_next = 1;
    frame->group_current = frame->group_next;
}

void scene_frame_group_end(struct scene_frame *frame)
{
    frame->group_current = 0;
}

void scene_frame_begin(struct scene_frame *frame)
{
    frame->pending.count = 0;
    frame->group_next = 0;
    frame->open = 1;
    scene_immediate_restart(&frame->immediate);
    scene_light_sets_restart(frame);
}

void scene_frame_end(struct scene_frame *frame)
{
    frame->open = 0;
}

void scene_frame_continue(struct scene_frame *frame)
{
    frame->open = 1;
}

static void list_forget(struct scene_instance_list *list, const struct scene_object *object)
{
    uint32_t kept = 0;
    for (uint32_t i = 0; i < list->count; i++)
        if (list->items[i].object != object)
            list->items[kept++] = list->items[i];
    list->count = kept;
}

void scene_frame_forget_object(struct scene_frame *frame, const struct scene_object *object)
{
    uint32_t before = frame->committed.count;
    list_forget(&frame->pending, object);
    list_forget(&frame->committed, object);
    if (frame->committed.count != before)
        frame->top_valid = 0;
    /* Flattened hierarchies may hold the object as a member or root. */
    if (frame->flats.count) {
        scene_flats_clear(&frame->flats);
        frame->top_valid = 0;
    }
}

/* The world box of an object box under an affine map: transform the eight
 * corners, in double, and round outwards so the float box contains the
 * exact image. */
static struct aabb transformed_box(const struct aabb *box, const double m[16])
{
    struct aabb out = aabb_empty();
    for (int c = 0; c < 8; c++) {
        double p[3] = {(c & 1) ? box->max[0] : box->min[0], (c & 2) ? box->max[1] : box->min[1],
                       (c & 4) ? box->max[2] : box->min[2]};
        double w[3];
        mat4_transform_point(m, p, w);
        for (int k = 0; k < 3; k++) {
            float lo = (float)w[k], hi = (float)w[k];
            if ((double)lo > w[k])
                lo = nextafterf(lo, -INFINITY);
            if ((double)hi < w[k])
                hi = nextafterf(hi, INFINITY);
            out.min[k] = fminf(out.min[k], lo);
            out.max[k] = fmaxf(out.max[k], hi);
        }
    }
    return out;
}

struct aabb scene_instance_box(const struct scene_instance *instance)
{
    return transformed_box(&instance->object->mesh.bounds, instance->object_to_world);
}

void scene_instance_world_triangle(const struct scene_instance *instance, uint32_t prim,
                                   double p[3][3])
{
    const struct scene_mesh *mesh = &instance->object->mesh;
    const uint32_t *v = &mesh->indices[3 * (size_t)prim];
    for (int i = 0; i < 3; i++) {
        const float *f = &mesh->positions[3 * (size_t)v[i]];
        const double q[3] = {f[0], f[1], f[2]};
        mat4_transform_point(instance->object_to_world, q, p[i]);
    }
}

static int box_is_finite(const struct aabb *b)
{
    for (int k = 0; k < 3; k++)
        if (!isfinite(b->min[k]) || !isfinite(b->max[k]))
            return 0;
    return 1;
}

/* Lists are equal when they name the same objects under bit-identical
 * matrices in the same order.  Changed geometry is caught separately by
 * the serial check in scene_frame_prepare, so that a list issued before an
 * object changed does not look new at every later preparation. */
static int lists_equal(const struct scene_instance_list *a, const struct scene_instance_list *b)
{
    if (a->count != b->count)
        return 0;
    for (uint32_t i = 0; i < a->count; i++) {
        const struct scene_instance *x = &a->items[i], *y = &b->items[i];
        if (x->object != y->object || x->group != y->group || x->depth != y->depth ||
            memcmp(x->object_to_world, y->object_to_world, sizeof(x->object_to_world)) != 0)
            return 0;
    }
    return 1;
}

/* The wide layout's leaf count is a byte: the cell-split rule can leave
 * more coincident instances than that in one leaf, and such a top level
 * keeps the binary walk (the same answers). */
static int top_fits_wide(const struct bvh *top)
{
    for (uint32_t i = 0; i < top->node_count; i++)
        if (top->nodes[i].count > UINT8_MAX)
            return 0;
    return 1;
}

/* 1 when the instance can be hit (its box, rounded outwards, in *box). */
static int instance_box(const struct scene_instance *inst, struct aabb *box)
{
    const struct scene_mesh *mesh = &inst->object->mesh;
    if (mesh->tri_count == 0 || aabb_is_empty(&mesh->bounds) || inst->overlay)
        return 0; /* empty objects are never hit, rasterised ones not traced */
    *box = transformed_box(&mesh->bounds, inst->object_to_world);
    return box_is_finite(box); /* else cannot be bounded in float: unreachable */
}

/*
 * The group of instances [begin, end) of one application-level call
 * (flatten.h): when it is nested and the cost model (or flatten=on) says
 * so, one top-level slot tops[*n] for the flattened hierarchy, its
 * members appended to members[*m]; else nothing (returns 0) and the
 * caller places them one by one.  -1 on allocation failure.
 */
static int place_group(struct scene_frame *frame, const struct bvh_build_params *params,
                       uint32_t begin, uint32_t end, struct aabb *boxes,
                       struct trace_instance *tops, uint32_t *n, struct trace_instance *members,
                       uint32_t *m)
{
    const struct scene_instance_list *list = &frame->committed;
    uint32_t count = 0, nested = 0;
    for (uint32_t i = begin; i < end; i++)
        nested |= list->items[i].depth > 1;
    if (!nested || end - begin < 2)
        return 0;
    struct scene_flat_member *fm = rt_calloc(end - begin, sizeof(*fm));
    struct scene_flat_candidate *cand = rt_calloc(end - begin, sizeof(*cand));
    if (!fm || !cand) {
        rt_free(fm);
        rt_free(cand);
        return -1;
    }
    struct aabb group_box = aabb_empty();
    for (uint32_t i = begin; i < end; i++) {
        const struct scene_instance *inst = &list->items[i];
        struct aabb box;
        if (!instance_box(inst, &box))
            continue;
        aabb_grow(&group_box, &box);
        fm[count].object = inst->object;
        fm[count].serial = inst->object->serial;
        mat4_mul(fm[count].rel, inst->world_to_root, inst->object_to_world);
        cand[count].object = inst->object;
        cand[count].triangles = inst->object->mesh.tri_count;
        cand[count].half_area = aabb_half_area(&box);
        count++;
    }
    int changed = 0, placed = 0;
    struct scene_flat *flat = NULL;
    if (count >= 2) {
        frame->flats.groups++;
        flat = scene_flats_get(&frame->flats, list->items[begin].root, fm, count, params,
                               &changed);
        if (!flat) {
            rt_free(fm);
            rt_free(cand);
            return -1;
        }
        int not_static = 0;
        placed = scene_flat_decide(&frame->flats, cand, count, aabb_half_area(&group_box),
                                   changed, params->wide_layout, &not_static);
        frame->flats.retry |= not_static;
    }
    rt_free(fm);
    rt_free(cand);
    if (!placed)
        return 0;
    frame->flats.flattened++;
    struct trace_instance *top = &tops[*n];
    memset(top, 0, sizeof(*top));
    trace_instance_set_rows(top, list->items[begin].world_to_root);
    top->object = flat;
    top->member_base = *m; /* relative to the members; build_top adds the tops */
    top->member_count = count;
    top->instance_id = begin; /* never compared: hits report the members */
    boxes[*n] = group_box;
    for (uint32_t i = begin; i < end; i++) {
        const struct scene_instance *inst = &list->items[i];
        struct aabb box;
        if (!instance_box(inst, &box))
            continue;
        struct trace_instance *ti = &members[(*m)++];
        memset(ti, 0, sizeof(*ti));
        trace_instance_set_rows(ti, inst->world_to_object);
        ti->instance_id = i;
        ti->object = inst->object;
    }
    (*n)++;
    return 1;
}

static int build_top(struct scene_frame *frame, const struct bvh_build_params *params)
{
    const struct scene_instance_list *list = &frame->committed;
    struct aabb *boxes = rt_calloc(list->count, sizeof(*boxes));
    /* A flattened group takes a slot of its own besides its members'. */
    struct trace_instance *tis = rt_calloc(2 * (size_t)list->count, sizeof(*tis));
    struct trace_instance *members = rt_calloc(list->count, sizeof(*members));
    struct bvh top;
    memset(&top, 0, sizeof(top));
    if (!boxes || !tis || !members)
        goto fail;
    uint32_t n = 0, m = 0;
    scene_flats_unmark(&frame->flats);
    frame->flats.groups = frame->flats.flattened = 0;
    frame->flats.retry = 0;
    for (uint32_t i = 0; i < list->count;) {
        const struct scene_instance *inst = &list->items[i];
        if (inst->group) {
            uint32_t end = i + 1;
            while (end < list->count && list->items[end].group == inst->group)
                end++;
            int status = place_group(frame, params, i, end, boxes, tis, &n, members, &m);
            if (status < 0)
                goto fail;
            if (status) {
                i = end;
                continue;
            }
            for (; i < end; i++) {
                struct aabb box;
                if (!instance_box(&list->items[i], &box))
                    continue;
                boxes[n] = box;
                trace_instance_set_rows(&tis[n], list->items[i].world_to_object);
                tis[n].instance_id = i;
                tis[n].object = list->items[i].object;
                n++;
            }
            continue;
        }
        struct aabb box;
        if (instance_box(inst, &box)) {
            boxes[n] = box;
            trace_instance_set_rows(&tis[n], inst->world_to_object);
            tis[n].instance_id = i;
            tis[n].object = inst->object;
            n++;
        }
        i++;
    }
    /* The members after the top-level slots (scene_traverse.h). */
    for (uint32_t i = 0; i < n; i++)
        if (tis[i].member_count)
            tis[i].member_base += n;
    memcpy(&tis[n], members, m * sizeof(*members));
    rt_free(members);
    members = NULL;
    int status = frame->toplevel_cellsplit ? accel_build_toplevel_cellsplit(&top, boxes, n)
                                          : accel_build(&top, boxes, n, params);
    if (status)
        goto fail;
    struct bvh4 wide;
    memset(&wide, 0, sizeof(wide));
    if (params->wide_layout && top_fits_wide(&top) &&
        accel_collapse_wide(&wide, &top, NULL, params->wide_layout == 8 ? 8u : 4u)) {
        bvh_release(&top);
        goto fail;
    }
    rt_free(boxes);
    bvh_release(&frame->top);
    bvh4_release(&frame->top_wide);
    rt_free(frame->trace_instances);
    frame->top = top;
    frame->top_wide = wide;
    frame->trace_instances = tis;
    frame->trace_instance_count = n + m;
    frame->top_valid = 1;
    scene_flats_sweep(&frame->flats); /* the old top level is gone */
    return 0;
fail:
    rt_free(boxes);
    rt_free(tis);
    rt_free(members);
    return -1;
}

/* Stamps the objects of instances that differ from the instance at the
 * same position of the old list. */
static void mark_moved(const struct scene_instance_list *old, const struct scene_instance_list *now,
                       uint64_t frame_number)
{
    for (uint32_t i = 0; i < now->count; i++) {
        const struct scene_instance *x = &now->items[i];
        if (i >= old->count || old->items[i].object != x->object ||
            memcmp(old->items[i].object_to_world, x->object_to_world,
                   sizeof(x->object_to_world)) != 0)
            x->object->moved_frame = frame_number;
    }
}

/*
 * 1 when the viewport an instance was drawn under is an inset of the
 * frame's: not empty, not the frame's, and inside it (a minimap, a rear
 * view).  A viewport that is larger or elsewhere is taken as the program
 * setting the frame's viewport after drawing, which Tracelist's own
 * frames allow (the viewport current at rtRenderFrame is the image's).
 */
static int is_inset(const int32_t vp[4], const int32_t frame[4])
{
    if (vp[2] <= 0 || vp[3] <= 0 || memcmp(vp, frame, 4 * sizeof(*vp)) == 0)
        return 0;
    return vp[0] >= frame[0] && vp[1] >= frame[1] &&
           (int64_t)vp[0] + vp[2] <= (int64_t)frame[0] + frame[2] &&
           (int64_t)vp[1] + vp[3] <= (int64_t)frame[1] + frame[3];
}

/* Distinct projections weighed by choose_trace_projection; instances
 * under further ones do not vote (they are rasterised). */
#define FRAME_PROJECTION_CANDIDATES 8

/*
 * A GL frame's traced projection: the draw-time projection (among the
 * instances drawn in the frame's viewport, not an inset) of the most
 * triangles drawn with the depth test on, then of the most triangles,
 * then the earliest drawn; the caller's (the projection current at the
 * render) when no triangle was drawn.
 *
 * GL programs often set a HUD's projection without pushing it (the scene
 * under gluPerspective, then glLoadIdentity and gluOrtho2D for the HUD,
 * then the swap), which leaves the HUD's current when the frame is
 * rendered.  Ray casting gives each pixel its nearest surface, which is
 * GL's image only for geometry drawn with the depth test on; geometry
 * drawn without it (HUDs, backgrounds) gets its visibility from the
 * draw order, which only rasterising it reproduces.  So the depth-tested
 * triangles choose the camera, and the rest is rasterised as GL draws it:
 * the image is GL's whichever projection wins, the choice only decides
 * what gets the ray tracer's effects.
 */
static void choose_trace_projection(struct scene_frame *frame)
{
    struct {
        uint32_t first;
        uint64_t depth_tris, tris;
    } cand[FRAME_PROJECTION_CANDIDATES];
    uint32_t n = 0;
    const struct scene_instance_list *list = &frame->committed;
    for (uint32_t i = 0; i < list->count; i++) {
        const struct scene_instance *inst = &list->items[i];
        const struct scene_raster *r = &inst->appearance.raster;
        const uint64_t tris = inst->object->mesh.tri_count;
        if (tris == 0 || is_inset(r->viewport, frame->trace_viewport))
            continue;
        uint32_t k = 0;
        while (k < n && memcmp(list->items[cand[k].first].appearance.raster.projection,
                               r->projection, sizeof(r->projection)) != 0)
            k++;
        if (k == n) {
            if (n == FRAME_PROJECTION_CANDIDATES)
                continue;
            cand[n].first = i;
            cand[n].depth_tris = cand[n].tris = 0;
            n++;
        }
        cand[k].tris += tris;
        if (r->depth_test)
            cand[k].depth_tris += tris;
    }
    if (n == 0)
        return;
    uint32_t best = 0; /* candidates are in draw order: ties keep the earliest */
    for (uint32_t k = 1; k < n; k++)
        if (cand[k].depth_tris > cand[best].depth_tris ||
            (cand[k].depth_tris == cand[best].depth_tris && cand[k].tris > cand[best].tris))
            best = k;
    memcpy(frame->trace_projection, list->items[cand[best].first].appearance.raster.projection,
           sizeof(frame->trace_projection));
}

int scene_frame_prepare(struct scene_frame *frame, const struct bvh_build_params *params,
                        uint64_t frame_number, int *toplevel_built)
{
    *toplevel_built = 0;
    if (frame->open) {
        scene_immediate_commit(frame, frame_number);
        /* The instances' light-set indices refer to pending_lights. */
        if (scene_light_sets_commit(frame))
            return -1;
    }
    if (frame->open && !lists_equal(&frame->pending, &frame->committed)) {
        mark_moved(&frame->committed, &frame->pending, frame_number);
        if (list_reserve(&frame->committed, frame->pending.count))
            return -1;
        memcpy(frame->committed.items, frame->pending.items,
               frame->pending.count * sizeof(*frame->pending.items));
        frame->committed.count = frame->pending.count;
        frame->top_valid = 0;
    } else if (frame->open) {
        /* Same instances: only the call-time appearance can differ, which
         * shading reads and the top level does not. */
        for (uint32_t i = 0; i < frame->pending.count; i++)
            frame->committed.items[i].appearance = frame->pending.items[i].appearance;
    }
    /* A redefined object changes its box even when the list is the same. */
    for (uint32_t i = 0; i < frame->committed.count; i++) {
        struct scene_instance *inst = &frame->committed.items[i];
        if (inst->object_serial != inst->object->serial) {
            inst->object_serial = inst->object->serial;
            frame->top_valid = 0;
        }
    }
    if (frame->overlay_enabled)
        choose_trace_projection(frame);
    /* Drawn under another projection or viewport than the frame's: out of
     * the top level (rasterised), which changes with the classification. */
    for (uint32_t i = 0; i < frame->committed.count; i++) {
        struct scene_instance *inst = &frame->committed.items[i];
        const struct scene_raster *r = &inst->appearance.raster;
        const uint8_t overlay =
            frame->overlay_enabled &&
            (memcmp(r->projection, frame->trace_projection, sizeof(r->projection)) != 0 ||
             is_inset(r->viewport, frame->trace_viewport));
        if (inst->overlay != overlay) {
            inst->overlay = overlay;
            frame->top_valid = 0;
        }
    }
    /* A nested group kept as instances because it was not static is
     * decided again once a frame has passed (flatten.h). */
    if (frame->top_valid && frame->flats.retry && frame_number > frame->flats.retry_frame)
        frame->top_valid = 0;
    if (frame->top_valid)
        return 0;
    if (build_top(frame, params))
        return -1;
    frame->flats.retry_frame = frame_number;
    *toplevel_built = 1;
    return 0;
}
