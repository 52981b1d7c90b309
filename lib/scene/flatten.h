/* SPDX-License-Identifier: Apache-2.0 */
/*
 * flatten.h - the acceleration strategy of a nested static hierarchy: the
 * segments one application-level call of a display list places (through
 * its nested calls, rtCallList / rtInstantiateObject inside rtNewList /
 * rtNewObject) are either kept as instances of the two-level hierarchy
 * (Wald, Benthin and Slusallek (2003) sec. 4.4), or flattened into one
 * BVH over all their triangles in the space of the called list (the
 * "root"), whichever the cost model below says (flatten=auto), or as the
 * configuration forces (flatten=on|off, docs/context.md).
 *
 * Either way the answers are the same bit for bit: the flattened BVH is
 * only an acceleration structure (trace/flat_walk.h argues it), so the
 * choice changes speed and memory only.
 *
 * Laziness: the decision needs only the members' triangle counts and
 * boxes; the flattened BVH is built by the first ray that reaches the
 * group (scene_flat_acquire, under the entry's lock, as objects are built
 * on demand: Wald, Benthin and Slusallek (2003) sec. 3), and the members'
 * own structures are then never built for rays.
 *
 * Invalidation: an entry remembers its members (object, its serial, and
 * the member's matrix relative to the root).  A redefined child (by name:
 * a new definition bumps the serial, and the replay places new segments)
 * or a moved part no longer matches, and a new entry is made; entries no
 * top level uses are freed at the next top-level build.  Calls of the same
 * list with the same inner structure share one entry (one flattened BVH
 * instanced several times).
 */
#ifndef RT_SCENE_FLATTEN_H
#define RT_SCENE_FLATTEN_H

#include <pthread.h>
#include <stdint.h>

#include "accel/bvh_build.h"
#include "trace/flat_walk.h"

struct scene_object;

/* flatten= */
enum scene_flatten_mode {
    SCENE_FLATTEN_AUTO = 0,
    SCENE_FLATTEN_ON,
    SCENE_FLATTEN_OFF
};

struct scene_flat_member {
    struct scene_object *object;
    uint32_t serial;
    double rel[16]; /* member matrix relative to the root (root^-1 * member) */
};

/* The built structure (trace_flat's arrays). */
struct scene_flat_accel {
    struct bvh bvh;
    float *tri;
    uint32_t *member;
    uint32_t *prim;
    double build_ms;
};

struct scene_flat {
    struct scene_object *root; /* the list the application called */
    struct scene_flat_member *members;
    uint32_t member_count;
    uint64_t triangles;
    struct bvh_build_params params;
    int used; /* by the current top level */
    pthread_mutex_t lock;
    struct scene_flat_accel *accel; /* NULL until built; acquire loads */
};

/* The cache of entries, and what the last top-level build chose. */
struct scene_flats {
    struct scene_flat **items;
    uint32_t count, capacity;
    enum scene_flatten_mode mode;
    /* Of the last top-level build: nested groups seen, flattened. */
    uint32_t groups, flattened;
    /* A group was kept as instances because it was not static (it
     * changed, or a member was not classified static): the top level is
     * rebuilt once the frame has advanced, to decide again. */
    int retry;
    uint64_t retry_frame;
};

void scene_flats_init(struct scene_flats *flats);
void scene_flats_release(struct scene_flats *flats);
/* Frees every entry (an object was deleted: entries may name it). */
void scene_flats_clear(struct scene_flats *flats);

/* What the cost model needs of one member. */
struct scene_flat_candidate {
    uint32_t triangles;   /* of its object */
    float half_area;      /* of its world box */
    const struct scene_object *object;
};

/* 1 when the group of n members (box: the union's half area) should be
 * flattened under flats->mode; `changed` says its inner structure differs
 * from the entry the same root had before (not static); wide_width is
 * the objects' wide layout (bvh_build_params.wide_layout, 0: binary).
 * *not_static is set when auto refused because the group is not static
 * (the answer may change in a later frame). */
int scene_flat_decide(const struct scene_flats *flats, const struct scene_flat_candidate *c,
                      uint32_t n, float group_half_area, int changed, int wide_width,
                      int *not_static);

/* The entry for root with these members (copied), found or made, and
 * marked used; *changed is set when none matched but the root had one
 * from an earlier top level (its hierarchy changed since: not static).
 * An entry is kept for an instanced group too, as the record of its last
 * structure.  NULL on allocation failure. */
struct scene_flat *scene_flats_get(struct scene_flats *flats, struct scene_object *root,
                                   const struct scene_flat_member *members, uint32_t n,
                                   const struct bvh_build_params *params, int *changed);

/* Marks every entry unused; scene_flats_sweep frees the unused ones. */
void scene_flats_unmark(struct scene_flats *flats);
void scene_flats_sweep(struct scene_flats *flats);

/* The built structure (building it on first use); NULL on allocation
 * failure.  Safe from render threads. */
const struct scene_flat_accel *scene_flat_acquire(struct scene_flat *flat, int *built_now);

#endif
