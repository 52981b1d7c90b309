/* SPDX-License-Identifier: Apache-2.0 */
/*
 * build_parallel.c - the two-stage parallel build (build_parallel.h;
 * Wald, Ize and Parker (2008) sec. 5).
 *
 * Setup: all threads convert the input boxes into refs (struct build_ref,
 * build_median.h) and reduce the root's box and centroid bounds.
 *
 * Stage 1 makes the top of the tree and a list of subtrees, each a
 * contiguous range of refs, until every subtree has at most subtree_max
 * primitives (PARALLEL_SUBTREES below):
 *   binning: level by level, all threads fill binned-SAH histograms for
 *     chunks of every open node, one thread merges them and picks each
 *     node's split, then all threads partition their chunks into the two
 *     children's ranges, at offsets known from the chunks' own bin counts
 *     ("PARALLEL BINNING"); a node of at most defer_max refs that is
 *     still to be split is deferred to stage 2 instead, where one thread
 *     makes the same splits depth first (PARALLEL_DEFER_PER_THREAD);
 *   grid: every thread bins its 1/T of the centroids into its own grid,
 *     one thread merges the counts, builds BIH-like nodes over the grid
 *     (spatial median in cell units) down to blocks of cells that become
 *     subtrees, and all threads scatter their refs into the blocks'
 *     ranges ("GRID-BASED SPLITTING").
 * Both partitions are stable (each side keeps the input order), and
 * bounds are merged with min/max, which are exact, so the result does not
 * depend on how the work was shared out: the tree is the same for every
 * thread count (for finite input; with NaN a min/max depends on the order
 * of its operands, and with it on the chunking).
 *
 * Stage 2: subtrees and deferred nodes sorted by descending size are
 * handed out by an atomic counter; each subtree is built by a serial
 * builder on its refs in place,
 * directly into a block of 2m - 1 nodes of its own (a subtree of m
 * primitives needs at most that many; build_subtree says why not a range
 * of one scratch array, as in the paper): the median builder
 * or the binned SAH builder's build_binned_sah_refs (the sweep SAH
 * builder allocates its own arrays; see build_sah_subtree).  The deferred
 * nodes' top nodes are then merged into the top array and all top nodes
 * numbered breadth first, as the level-by-level stage 1 numbers them.
 *
 * Stage 3: the subtrees used fewer nodes than reserved, so they are
 * compacted, in parallel, into the final array: the top nodes first
 * (indices 0 .. top_count - 1, each subtree's root in the slot its parent
 * reserved for it), then each subtree's other nodes, in primitive order.
 * Finally the top nodes' boxes are computed bottom-up from their children
 * (stage 1 of the grid variant never computes boxes).
 */
#include "accel/build_parallel.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "accel/build_internal.h"
#include "accel/triangle_box.h"
#include "accel/vec4.h"
#include "base/alloc.h"
#include "base/atomic.h"

/*
 * Subtree size target of stage 1: max(PARALLEL_MIN_SUBTREE, n /
 * PARALLEL_SUBTREES).  Wald, Ize and Parker (2008) sec. 5 does not give its numbers.  64
 * subtrees keep 8 threads busy with the largest-first hand-out even when
 * the SAH splits unevenly, and stay a fixed number, so the tree does not
 * depend on the thread count.  Below PARALLEL_MIN_SUBTREE primitives a
 * subtree builds in well under a millisecond, less than waking the pool
 * for another level costs.
 */
#define PARALLEL_SUBTREES 64u
#define PARALLEL_MIN_SUBTREE 2048u

/*
 * Deferred nodes (struct deferred): stage 1 splits a node level by level,
 * all threads on every level, only while it has more than defer_max =
 * n / (PARALLEL_DEFER_PER_THREAD T) refs; a smaller node that stage 1
 * would still split is finished by one thread in stage 2, depth first,
 * its last stage-1 levels and then its subtrees, so that its refs stay in
 * that thread's caches instead of every level of stage 1 streaming all n
 * refs through memory.  Embree's builders do the same (parallel binning
 * at the top, one task per subtree below a size threshold).  With about
 * 4 items per thread (plus the subtrees) the largest-first hand-out
 * stays balanced.  Measured on bumpy (1M triangles, one thread's CPU
 * time of the whole binary build): 297-309 ms without deferral, 268-298
 * ms deferring below 32,768 refs, 278-282 below 131,072, 264-268 below
 * 250,000: the more of the tree one thread builds depth first the less
 * the work.  Which nodes are deferred changes neither the splits nor the
 * numbering (renumber_top), so the tree is the same for every thread
 * count.
 */
#define PARALLEL_DEFER_PER_THREAD 4u

/* Work items per thread and level of stage 1, and their least size:
 * several per thread even out uneven nodes; below the minimum the atomic
 * counter and the per-chunk histograms cost more than they balance. */
#define PARALLEL_CHUNKS_PER_THREAD 4u
#define PARALLEL_MIN_CHUNK 8192u

/*
 * Grid of the grid partition: about n / GRID_PRIMS_PER_CELL cells, at most
 * GRID_MAX_CELLS (32^3) and GRID_MAX_RES per axis, each axis a power of
 * two so that the BIH-like nodes split blocks exactly in half.  The paper
 * gives no resolution; 16 primitives per cell puts a few hundred cells in
 * each subtree, enough to balance the nodes over the grid, while the T
 * per-thread grids stay small (T * 128 KB at most).
 */
#define GRID_PRIMS_PER_CELL 16u
#define GRID_MAX_LEVELS 15 /* log2(GRID_MAX_CELLS) */
#define GRID_MAX_CELLS (1u << GRID_MAX_LEVELS)
#define GRID_MAX_RES 1024u

/* ------------------------------------------------------------ state */

/* One subtree of stage 2. */
struct subtree {
    uint32_t begin; /* its refs and leaf slots: [begin, end) */
    uint32_t end;
    uint32_t slot;  /* its root's index among the top nodes */
    uint32_t depth; /* depth of its root */
    struct build_ref *refs; /* the buffer holding refs[begin, end) */
    /* Set by stage 2: */
    const struct bvh_node *nodes; /* its nodes, root at [0], indices relative */
    struct bvh sah; /* a sweep SAH subtree's own arrays, to free */
    void *block; /* its own node block (build_subtree), to free */
    uint32_t node_count;
    uint32_t max_depth; /* absolute */
    /* Set by stage 3: */
    uint32_t final_base; /* index of nodes[1] in the final array */
};

/* A node of stage 1's binning that is still to be split. */
struct open_node {
    uint32_t begin;
    uint32_t end;
    uint32_t slot;
    uint32_t depth;
    float clo[4]; /* centroid bounds, lane 3 unused */
    float chi[4];
    struct aabb box;
    /* The binning of this level (Wald 2007's k1 mapping, as in
     * build_binned_sah.c): bin = (c - origin) * scale clamped to
     * [0, bins - 1]; scale 0 on an axis whose centroids do not spread. */
    float origin[3];
    float scale[3];
    int binnable[3];
    /* The split picked (axis < 0: none). */
    int axis;
    int plane;
    float threshold; /* the plane as build_split_threshold's coordinate */
    uint32_t left_count;
    struct aabb left_box;
    struct aabb right_box;
    uint32_t first_chunk;
    uint32_t chunk_count;
};

/* A piece of an open node's range handled by one thread at a time. */
struct chunk {
    uint32_t node; /* index into the level's open nodes */
    uint32_t begin;
    uint32_t end;
    uint32_t left_dst; /* partition: where its left and right refs go */
    uint32_t right_dst;
    float lclo[4]; /* partition: its children's centroid bounds */
    float lchi[4];
    float rclo[4];
    float rchi[4];
};

/*
 * A node of stage 1 that one thread finishes in stage 2: its own stage-1
 * splits (the same binning, pick_split and stable partition, in one
 * chunk), depth first, each subtree built as soon as it is cut off, while
 * its refs are still in the cache.  Its top nodes and subtrees are kept
 * here and merged into the pbuild's after stage 2 (merge_deferred).
 * Local top index 0 stands for the node itself (global slot node.slot);
 * its other top nodes and its subtrees' slots are local indices.
 */
struct deferred {
    struct open_node node;
    int src; /* buffer holding its refs */
    struct bvh_node *top;
    uint32_t top_count;
    uint32_t top_cap;
    struct subtree *subtrees;
    uint32_t subtree_count;
    uint32_t subtree_cap;
};

/* A thread's nodes of stage 2 (build_subtree): the subtrees it builds,
 * one after the other, each in the nodes it used. */
struct node_arena {
    struct bvh_node *nodes;
    void *block; /* what nodes were allocated as (rt_alloc_array64) */
    size_t cap;  /* nodes */
    size_t used;
    int tried; /* the allocation was made (nodes NULL: it failed) */
};

struct pbuild {
    /* The input: boxes, or (boxes NULL) the triangles whose boxes the
     * set-up computes itself (accel_build_parallel_triangles). */
    const struct aabb *boxes;
    const float *positions;
    const uint32_t *indices;
    uint32_t n;
    struct bvh_build_params p;
    struct bvh_parallel_params pp;
    struct rt_pool *pool;
    uint32_t threads;
    uint32_t subtree_max;
    /* Stage-1 nodes of at most this many refs (and more than
     * subtree_max) are deferred to stage 2 (struct deferred). */
    uint32_t defer_max;

    struct build_ref *refs[2];
    void *refs_block[2]; /* what refs[] were allocated as (rt_align64) */
    /* With a spare asked for (accel_build_parallel_triangles) and a large
     * build: refs[1]'s mapping (build_spare_refs), for the caller. */
    struct rt_large_block scratch;

    /* Top nodes of stage 1: count 0 = inner (first = child pair), count
     * 1 = the root slot of a subtree. */
    struct bvh_node *top;
    uint32_t top_count;
    uint32_t top_cap;

    struct subtree *subtrees;
    uint32_t subtree_count;
    uint32_t subtree_cap;

    struct deferred *deferred;
    uint32_t deferred_count;
    uint32_t deferred_cap;

    /* Work shared by the current phase. */
    uint32_t next;   /* atomic work counter */
    int failed;      /* atomic: an allocation failed in stage 2 */
    uint32_t chunk_size;
    uint32_t chunk_count;

    /* setup */
    struct chunk *chunks;
    struct aabb *chunk_box;
    int nan_seen; /* atomic: a ref's box holds a NaN (setup_task) */

    /* binning */
    int bins;
    build_fill_bins_fn fill; /* the histogram loop (build_internal.h) */
    build_partition_fn partition_avx2; /* NULL: the portable partition loop */
    struct open_node *open;
    uint32_t open_count;
    int src; /* buffer the open nodes' refs are in */
    float (*hist_box)[8];  /* per chunk: 3 * bins boxes (min xyz -, max xyz -) */
    /* per chunk: 3 * bins counts, [0] of each: the stride of hist_box,
     * so that bin_task reaches both with one byte offset
     * (build_bin_offsets) */
    uint32_t (*hist_count)[8];
    void *hist_box_block; /* what they were allocated as (rt_align64) */
    void *hist_count_block;

    /* grid */
    uint32_t res[3];
    float grid_origin[3];
    float grid_scale[3];
    uint32_t *cell_of;  /* per ref */
    uint32_t *counts;   /* threads x cells: counts, then scatter offsets */

    /* stage 2 and 3 */
    uint32_t *prim_index; /* the output's */
    uint32_t *order;      /* stage 2's items by descending size: subtrees
                           * (index < subtree_count), then deferred nodes */
    struct node_arena *arenas; /* one per thread */
    struct bvh_node *final_nodes;
};

static uint32_t chunk_of(struct pbuild *b)
{
    return rt_atomic_fetch_add_relaxed(&b->next, 1);
}

/* Room for `need` (>= 1) elements of `size` bytes in array, whose
 * capacity is *cap: returns the array, moved if it had to grow (by
 * doubling), or NULL on allocation failure with the old array intact. */
static void *reserve(void *array, uint32_t *cap, uint32_t need, size_t size)
{
    if (need <= *cap)
        return array;
    uint32_t c = *cap ? *cap : 16;
    while (c < need)
        c = c > UINT32_MAX / 2 ? UINT32_MAX : 2 * c;
    void *p = rt_realloc_array(array, c, size);
    if (p)
        *cap = c;
    return p;
}

/* Appends a top node pair to *top (count *count, capacity *cap),
 * returns the index of its first node or UINT32_MAX on allocation
 * failure. */
static uint32_t pair_in(struct bvh_node **top, uint32_t *count, uint32_t *cap)
{
    struct bvh_node *t = reserve(*top, cap, *count + 2, sizeof(*t));
    if (!t)
        return UINT32_MAX;
    *top = t;
    uint32_t first = *count;
    memset(&t[first], 0, 2 * sizeof(*t));
    t[first].count = 1;
    t[first + 1].count = 1;
    *count += 2;
    return first;
}

static uint32_t top_pair(struct pbuild *b)
{
    return pair_in(&b->top, &b->top_count, &b->top_cap);
}

/* Appends a subtree over refs[begin, end) to *all (count *count,
 * capacity *cap); NULL on allocation failure. */
static struct subtree *subtree_in(struct subtree **all, uint32_t *count, uint32_t *cap,
                                  uint32_t begin, uint32_t end, uint32_t slot, uint32_t depth,
                                  struct build_ref *refs)
{
    struct subtree *a = reserve(*all, cap, *count + 1, sizeof(*a));
    if (!a)
        return NULL;
    *all = a;
    struct subtree *s = &a[(*count)++];
    memset(s, 0, sizeof(*s));
    s->begin = begin;
    s->end = end;
    s->slot = slot;
    s->depth = depth;
    s->refs = refs;
    return s;
}

static int add_subtree(struct pbuild *b, uint32_t begin, uint32_t end, uint32_t slot,
                       uint32_t depth, int buffer)
{
    return subtree_in(&b->subtrees, &b->subtree_count, &b->subtree_cap, begin, end, slot, depth,
                      b->refs[buffer])
               ? 0
               : -1;
}

/* Splits [0, total) into chunks of b->chunk_size for the setup phase. */
static void plan_flat_chunks(struct pbuild *b, uint32_t total)
{
    uint32_t size = (total + b->threads * PARALLEL_CHUNKS_PER_THREAD - 1) /
                    (b->threads * PARALLEL_CHUNKS_PER_THREAD);
    b->chunk_size = size > PARALLEL_MIN_CHUNK ? size : PARALLEL_MIN_CHUNK;
    b->chunk_count = (uint32_t)(((uint64_t)total + b->chunk_size - 1) / b->chunk_size);
}

/* Every task run here takes its chunks from b->next, so the caller may
 * do all of it: a worker that wakes late is not waited for (pool.h). */
static void run(struct pbuild *b, rt_task_fn fn)
{
    b->next = 0;
    rt_pool_run_shared(b->pool, fn, b);
}

/* Grows the bounds by ref r; returns its doubled centroid lo + hi. */
static vec4 box_grow_ref(vec4 *lo, vec4 *hi, vec4 *clo, vec4 *chi, const struct build_ref *r)
{
    vec4 l = vec4_xyz0(vec4_load(r->lo));
    vec4 h = vec4_load(r->hi);
    vec4 c = vec4_add(l, h);
    *lo = vec4_min(*lo, l);
    *hi = vec4_max(*hi, h);
    *clo = vec4_min(*clo, c);
    *chi = vec4_max(*chi, c);
    return c;
}

/* ------------------------------------------------------------ setup */

/* Wald, Ize and Parker (2008) sec. 5, "Setup": each thread prepares a share of the refs
 * and reduces their bounds; chunk_box[2c] = box, [2c + 1] = centroid
 * bounds of chunk c. */
static void setup_task(void *arg, int worker)
{
    (void)worker;
    struct pbuild *b = arg;
    uint32_t c;
    while ((c = chunk_of(b)) < b->chunk_count) {
        uint32_t begin = c * b->chunk_size;
        uint32_t end = b->n - begin < b->chunk_size ? b->n : begin + b->chunk_size;
        vec4 lo = vec4_splat(INFINITY);
        vec4 hi = vec4_splat(-INFINITY);
        vec4 clo = lo;
        vec4 chi = hi;
        /* Lanes 0-2 of lo + hi are NaN when the box's lo or hi is (or
         * holds infinities of both signs: a false alarm, which only
         * costs the NaN checks of the four-stream histogram). */
        uint32_t nan = 0;
        if (b->boxes) {
            for (uint32_t i = begin; i < end; i++) {
                struct build_ref *r = &b->refs[0][i];
                build_ref_set(r, &b->boxes[i], i);
                const vec4 cen = box_grow_ref(&lo, &hi, &clo, &chi, r);
                nan |= vec4_ne_bits(cen, cen);
            }
        } else {
            /* The box accel_triangle_boxes_pool would have stored
             * (triangle_box.h), straight into the ref: the same floats,
             * so the same refs and the same tree. */
            for (uint32_t i = begin; i < end; i++) {
                struct build_ref *r = &b->refs[0][i];
                vec4 l, h;
                triangle_ref_set(r, b->positions, b->indices, i, &l, &h);
                const vec4 cen = vec4_add(l, h);
                lo = vec4_min(lo, l);
                hi = vec4_max(hi, h);
                clo = vec4_min(clo, cen);
                chi = vec4_max(chi, cen);
                nan |= vec4_ne_bits(cen, cen);
            }
        }
        if (nan & 7u)
            rt_atomic_store_relaxed(&b->nan_seen, 1);
        float l[4], h[4], cl[4], ch[4];
        vec4_store(l, lo);
        vec4_store(h, hi);
        vec4_store(cl, clo);
        vec4_store(ch, chi);
        for (int k = 0; k < 3; k++) {
            b->chunk_box[2 * c].min[k] = l[k];
            b->chunk_box[2 * c].max[k] = h[k];
            b->chunk_box[2 * c + 1].min[k] = cl[k];
            b->chunk_box[2 * c + 1].max[k] = ch[k];
        }
    }
}

/* ------------------------------------------------------------ binning */

/* The node's bin mapping (build_internal.h), the one the histogram and
 * the partition both classify with. */
static struct build_bin_map bin_map_of(const struct open_node *o, int last)
{
    struct build_bin_map m;
    m.origin = vec4_set(o->origin[0], o->origin[1], o->origin[2], 0.0f);
    m.scale = vec4_set(o->scale[0], o->scale[1], o->scale[2], 0.0f);
    m.last = vec4_splat((float)last);
    return m;
}

static void init_binning(struct open_node *o, int bins)
{
    for (int k = 0; k < 3; k++) {
        float extent = o->chi[k] - o->clo[k];
        float s = (float)bins / extent;
        o->binnable[k] = extent > 0.0f && s > 0.0f && isfinite(s);
        o->origin[k] = o->clo[k];
        o->scale[k] = o->binnable[k] ? s : 0.0f;
    }
}

/* Phase A: each chunk's histogram, for the three axes (Wald 2007; Wald, Ize and Parker
 * (2008) sec. 5: "each of the T threads computes a bin histogram ... for
 * one T-th of the triangles"). */
static void bin_task(void *arg, int worker)
{
    (void)worker;
    struct pbuild *b = arg;
    const int bins = b->bins;
    const struct build_ref *refs = b->refs[b->src];
    /* Byte offset of axis k's first bin in a chunk's histogram. */
    const uint32_t axis_base[4] = {0, (uint32_t)bins * 32u, 2u * (uint32_t)bins * 32u, 0};
    uint32_t c;
    while ((c = chunk_of(b)) < b->chunk_count) {
        const struct chunk *ch = &b->chunks[c];
        const struct build_bin_map map = bin_map_of(&b->open[ch->node], bins - 1);
        b->fill((char *)&b->hist_box[(size_t)c * 3 * bins],
                (char *)&b->hist_count[(size_t)c * 3 * bins], axis_base, bins, &map, refs,
                ch->begin, ch->end);
    }
}

/*
 * Merges the node's chunk histograms and picks the best binned SAH plane
 * (Wald 2007; the sweeps of build_binned_sah.c's find_best_split: ties to
 * the lower axis and plane).  Sets o->axis (-1: no plane splits the node
 * or the SAH prefers a leaf), plane, left_count and the children's boxes.
 */
static void pick_split(const struct pbuild *b, struct open_node *o, const float (*hist_box)[8],
                       const uint32_t (*hist_count)[8])
{
    const int bins = b->bins;
    float box[3 * BVH_MAX_BINS][8];
    uint32_t count[3 * BVH_MAX_BINS];
    for (int i = 0; i < 3 * bins; i++) {
        vec4 lo = vec4_splat(INFINITY);
        vec4 hi = vec4_splat(-INFINITY);
        uint32_t cnt = 0;
        for (uint32_t c = o->first_chunk; c < o->first_chunk + o->chunk_count; c++) {
            const float *cb = hist_box[(size_t)c * 3 * bins + i];
            lo = vec4_min(lo, vec4_load(&cb[0]));
            hi = vec4_max(hi, vec4_load(&cb[4]));
            cnt += hist_count[(size_t)c * 3 * bins + i][0];
        }
        vec4_store(&box[i][0], lo);
        vec4_store(&box[i][4], hi);
        count[i] = cnt;
    }
    float right_sah[BVH_MAX_BINS];
    uint32_t right_count[BVH_MAX_BINS];
    float best_sah = INFINITY;
    o->axis = -1;
    for (int k = 0; k < 3; k++) {
        if (!o->binnable[k])
            continue;
        const float(*kb)[8] = &box[k * bins];
        const uint32_t *kc = &count[k * bins];
        vec4 lo = vec4_splat(INFINITY);
        vec4 hi = vec4_splat(-INFINITY);
        uint32_t cnt = 0;
        for (int i = bins - 1; i > 0; i--) {
            lo = vec4_min(lo, vec4_load(&kb[i][0]));
            hi = vec4_max(hi, vec4_load(&kb[i][4]));
            cnt += kc[i];
            right_count[i] = cnt;
            right_sah[i] = vec4_half_area(lo, hi) * (float)cnt;
        }
        lo = vec4_splat(INFINITY);
        hi = vec4_splat(-INFINITY);
        cnt = 0;
        for (int i = 0; i < bins - 1; i++) {
            lo = vec4_min(lo, vec4_load(&kb[i][0]));
            hi = vec4_max(hi, vec4_load(&kb[i][4]));
            cnt += kc[i];
            float sah = vec4_half_area(lo, hi) * (float)cnt + right_sah[i + 1];
            sah = cnt != 0 && right_count[i + 1] != 0 ? sah : INFINITY;
            if (sah < best_sah) {
                best_sah = sah;
                o->axis = k;
                o->plane = i + 1;
                o->left_count = cnt;
            }
        }
    }
    if (o->axis < 0)
        return;
    /* build_internal.h: costs compared multiplied by the node's area. */
    float area = aabb_half_area(&o->box);
    float leaf_cost = b->p.c_isect * (float)(o->end - o->begin) * area;
    float split_cost = b->p.c_trav * area + b->p.c_isect * best_sah;
    if (!(split_cost < leaf_cost)) {
        /* Overlapping primitives: the serial builder would split at the
         * object median; its subtree build will. */
        o->axis = -1;
        return;
    }
    const float(*kb)[8] = &box[o->axis * bins];
    vec4 lo = vec4_splat(INFINITY);
    vec4 hi = vec4_splat(-INFINITY);
    for (int i = 0; i < o->plane; i++) {
        lo = vec4_min(lo, vec4_load(&kb[i][0]));
        hi = vec4_max(hi, vec4_load(&kb[i][4]));
    }
    build_store_box(&o->left_box, lo, hi);
    lo = vec4_splat(INFINITY);
    hi = vec4_splat(-INFINITY);
    for (int i = o->plane; i < bins; i++) {
        lo = vec4_min(lo, vec4_load(&kb[i][0]));
        hi = vec4_max(hi, vec4_load(&kb[i][4]));
    }
    build_store_box(&o->right_box, lo, hi);
    const struct build_bin_map map = bin_map_of(o, bins - 1);
    o->threshold =
        build_split_threshold(&map, o->axis, o->plane, o->origin[o->axis], o->scale[o->axis]);
}

/* Phase C: every chunk of a splitting node copies its left refs to its
 * part of the left child's range and its right refs to the right's, in
 * order (Wald, Ize and Parker (2008) sec. 5: "copies the two halves into the respective
 * regions ... predetermined by the known sizes of all threads' bins"). */
static void partition_chunk(const struct pbuild *b, const struct build_ref *src,
                            struct build_ref *dst, const struct open_node *o, struct chunk *ch)
{
    const int axis = o->axis;
    if (b->partition_avx2) {
        /* The same loop in AVX2 (build_internal.h, build_partition_fn). */
        float bounds[4][4];
        b->partition_avx2(src, dst, ch->begin, ch->end, ch->left_dst, ch->right_dst, axis,
                          o->threshold, bounds);
        memcpy(ch->lclo, bounds[0], sizeof(ch->lclo));
        memcpy(ch->lchi, bounds[1], sizeof(ch->lchi));
        memcpy(ch->rclo, bounds[2], sizeof(ch->rclo));
        memcpy(ch->rchi, bounds[3], sizeof(ch->rchi));
        return;
    }
    const vec4 threshold = vec4_splat(o->threshold);
    uint32_t li = ch->left_dst;
    uint32_t ri = ch->right_dst;
    vec4 llo = vec4_splat(INFINITY);
    vec4 lhi = vec4_splat(-INFINITY);
    vec4 rlo = llo;
    vec4 rhi = lhi;
    for (uint32_t i = ch->begin; i < ch->end; i++) {
        const struct build_ref *r = &src[i];
        vec4 cen = build_ref_centroid(r);
        /* !(c >= threshold): bin below the plane (build_split_threshold). */
        const uint32_t left = ((vec4_ge_bits(cen, threshold) >> axis) & 1u) ^ 1u;
        build_side_grow(cen, left, &llo, &lhi, &rlo, &rhi);
        dst[left ? li : ri] = *r;
        li += left;
        ri += 1 - left;
    }
    vec4_store(ch->lclo, llo);
    vec4_store(ch->lchi, lhi);
    vec4_store(ch->rclo, rlo);
    vec4_store(ch->rchi, rhi);
}

static void partition_task(void *arg, int worker)
{
    (void)worker;
    struct pbuild *b = arg;
    const struct build_ref *src = b->refs[b->src];
    struct build_ref *dst = b->refs[!b->src];
    uint32_t c;
    while ((c = chunk_of(b)) < b->chunk_count) {
        struct chunk *ch = &b->chunks[c];
        const struct open_node *o = &b->open[ch->node];
        if (o->axis >= 0)
            partition_chunk(b, src, dst, o, ch);
    }
}

/* The two children of split node o, whose chunks are chunks[0,
 * o->chunk_count), as open nodes in slots pair and pair + 1: their
 * ranges, boxes (from the bins) and centroid bounds (merged from the
 * chunks' partitions, in chunk order). */
static void make_kids(const struct open_node *o, const struct chunk *chunks, uint32_t pair,
                      struct open_node kid[2])
{
    memset(kid, 0, 2 * sizeof(*kid));
    for (int s = 0; s < 2; s++) {
        kid[s].depth = o->depth + 1;
        kid[s].slot = pair + (uint32_t)s;
        for (int k = 0; k < 4; k++) {
            kid[s].clo[k] = INFINITY;
            kid[s].chi[k] = -INFINITY;
        }
    }
    kid[0].begin = o->begin;
    kid[0].end = o->begin + o->left_count;
    kid[1].begin = kid[0].end;
    kid[1].end = o->end;
    kid[0].box = o->left_box;
    kid[1].box = o->right_box;
    for (uint32_t k = 0; k < o->chunk_count; k++) {
        const struct chunk *ch = &chunks[k];
        for (int a = 0; a < 3; a++) {
            kid[0].clo[a] = build_min(kid[0].clo[a], ch->lclo[a]);
            kid[0].chi[a] = build_max(kid[0].chi[a], ch->lchi[a]);
            kid[1].clo[a] = build_min(kid[1].clo[a], ch->rclo[a]);
            kid[1].chi[a] = build_max(kid[1].chi[a], ch->rchi[a]);
        }
    }
}

/* Queues a child of stage 1: another open node if it is still large
 * (and the depth guard of build_internal.h allows an SAH split below it),
 * else a subtree in buffer `buffer`. */
static int queue_child(struct pbuild *b, struct open_node *next, uint32_t *next_count,
                       const struct open_node *child, int buffer)
{
    uint32_t m = child->end - child->begin;
    if (m > b->subtree_max && !build_must_split_median(child->depth, m)) {
        if (m > b->defer_max) {
            next[(*next_count)++] = *child;
            return 0;
        }
        struct deferred *all =
            reserve(b->deferred, &b->deferred_cap, b->deferred_count + 1, sizeof(*all));
        if (!all)
            return -1;
        b->deferred = all;
        struct deferred *d = &b->deferred[b->deferred_count++];
        memset(d, 0, sizeof(*d));
        d->node = *child;
        d->src = buffer;
        return 0;
    }
    return add_subtree(b, child->begin, child->end, child->slot, child->depth, buffer);
}

static int stage1_binning(struct pbuild *b, const struct open_node *root)
{
    b->bins = b->p.bins;
    /* Stage 1's and the deferred nodes' partitions are stable, so a
     * node's refs stay in mesh order: the histogram form for such refs
     * (build_internal.h, build_fill_bins_ordered_finite_best), without the NaN
     * checks when the set-up saw no NaN (stage 1 and the deferred nodes
     * only move the set-up's refs). */
    b->fill = build_fill_bins_ordered_finite_best(!rt_atomic_load_relaxed(&b->nan_seen));
    b->partition_avx2 = build_partition_avx2_unit();
    b->src = 0;
    struct open_node *next = NULL;
    uint32_t open_cap = 0;
    uint32_t next_cap = 0;
    int status = -1;
    b->open = reserve(b->open, &open_cap, 1, sizeof(*b->open));
    if (!b->open)
        return -1;
    b->open[0] = *root;
    b->open_count = 1;
    uint32_t chunk_cap = 0;
    uint32_t hist_cap = 0;
    while (b->open_count > 0) {
        /* Plan this level's chunks. */
        uint64_t total = 0;
        for (uint32_t i = 0; i < b->open_count; i++)
            total += b->open[i].end - b->open[i].begin;
        uint64_t size = (total + b->threads * PARALLEL_CHUNKS_PER_THREAD - 1) /
                        (b->threads * PARALLEL_CHUNKS_PER_THREAD);
        if (size < PARALLEL_MIN_CHUNK)
            size = PARALLEL_MIN_CHUNK;
        uint32_t chunks = 0;
        for (uint32_t i = 0; i < b->open_count; i++) {
            uint32_t m = b->open[i].end - b->open[i].begin;
            chunks += (uint32_t)((m + size - 1) / size);
        }
        struct chunk *chunk_array = reserve(b->chunks, &chunk_cap, chunks, sizeof(*chunk_array));
        if (!chunk_array)
            goto out;
        b->chunks = chunk_array;
        uint32_t hist_need = chunks * 3 * (uint32_t)b->bins;
        if (hist_need > hist_cap) {
            /* Fresh blocks, not realloc (every chunk's histogram is
             * filled anew each level), aligned to 64: fill stores whole
             * 32-byte records (rt_align64). */
            rt_free(b->hist_box_block);
            rt_free(b->hist_count_block);
            b->hist_box = rt_alloc_array64(hist_need, sizeof(*b->hist_box), &b->hist_box_block);
            b->hist_count =
                rt_alloc_array64(hist_need, sizeof(*b->hist_count), &b->hist_count_block);
            if (!b->hist_box || !b->hist_count)
                goto out;
            hist_cap = hist_need;
        }
        uint32_t c = 0;
        for (uint32_t i = 0; i < b->open_count; i++) {
            struct open_node *o = &b->open[i];
            init_binning(o, b->bins);
            o->first_chunk = c;
            for (uint32_t begin = o->begin; begin < o->end; begin += (uint32_t)size) {
                struct chunk *ch = &b->chunks[c++];
                ch->node = i;
                ch->begin = begin;
                ch->end = o->end - begin < size ? o->end : begin + (uint32_t)size;
            }
            o->chunk_count = c - o->first_chunk;
        }
        b->chunk_count = c;
        run(b, bin_task);

        /* One thread merges and picks every node's split. */
        for (uint32_t i = 0; i < b->open_count; i++) {
            struct open_node *o = &b->open[i];
            pick_split(b, o, b->hist_box, b->hist_count);
            if (o->axis < 0)
                continue;
            uint32_t left_dst = o->begin;
            uint32_t right_dst = o->begin + o->left_count;
            for (uint32_t k = o->first_chunk; k < o->first_chunk + o->chunk_count; k++) {
                const uint32_t(*cnt)[8] =
                    &b->hist_count[(size_t)k * 3 * b->bins + o->axis * b->bins];
                uint32_t left = 0;
                for (int bin = 0; bin < o->plane; bin++)
                    left += cnt[bin][0];
                b->chunks[k].left_dst = left_dst;
                b->chunks[k].right_dst = right_dst;
                left_dst += left;
                right_dst += (b->chunks[k].end - b->chunks[k].begin) - left;
            }
        }
        run(b, partition_task);

        /* Children: the next level's open nodes, or subtrees. */
        struct open_node *next_array = reserve(next, &next_cap, 2 * b->open_count, sizeof(*next));
        if (!next_array)
            goto out;
        next = next_array;
        uint32_t next_count = 0;
        for (uint32_t i = 0; i < b->open_count; i++) {
            struct open_node *o = &b->open[i];
            if (o->axis < 0) {
                if (add_subtree(b, o->begin, o->end, o->slot, o->depth, b->src))
                    goto out;
                continue;
            }
            uint32_t pair = top_pair(b);
            if (pair == UINT32_MAX)
                goto out;
            build_set_inner(&b->top[o->slot], pair);
            struct open_node kid[2];
            make_kids(o, &b->chunks[o->first_chunk], pair, kid);
            for (int s = 0; s < 2; s++) {
                if (queue_child(b, next, &next_count, &kid[s], !b->src))
                    goto out;
            }
        }
        struct open_node *t = b->open;
        b->open = next;
        next = t;
        uint32_t tc = open_cap;
        open_cap = next_cap;
        next_cap = tc;
        b->open_count = next_count;
        b->src = !b->src;
    }
    status = 0;
out:
    rt_free(next);
    return status;
}

/* ------------------------------------------------------------ grid */

static inline uint32_t grid_coord(const struct pbuild *b, float c, int k)
{
    float f = (c - b->grid_origin[k]) * b->grid_scale[k];
    float last = (float)(b->res[k] - 1);
    f = f > 0.0f ? f : 0.0f;
    f = f < last ? f : last;
    return (uint32_t)f;
}

static inline uint32_t cell_index(const struct pbuild *b, uint32_t x, uint32_t y, uint32_t z)
{
    return (z * b->res[1] + y) * b->res[0] + x;
}

/* Worker w's static share of the refs: per-thread grids need the same
 * share in the count and the scatter pass. */
static void worker_range(const struct pbuild *b, int worker, uint32_t *begin, uint32_t *end)
{
    *begin = (uint32_t)((uint64_t)b->n * (uint32_t)worker / b->threads);
    *end = (uint32_t)((uint64_t)b->n * ((uint32_t)worker + 1) / b->threads);
}

/* Wald, Ize and Parker (2008) sec. 5: "Each of the T threads create their own copy of that
 * grid, then takes one T-th of the triangles, and ... bins each triangle
 * into the cell that its centroid projects to." */
static void grid_count_task(void *arg, int worker)
{
    struct pbuild *b = arg;
    uint32_t begin, end;
    worker_range(b, worker, &begin, &end);
    uint32_t cells = b->res[0] * b->res[1] * b->res[2];
    uint32_t *count = &b->counts[(size_t)worker * cells];
    memset(count, 0, cells * sizeof(*count));
    const struct build_ref *refs = b->refs[0];
    for (uint32_t i = begin; i < end; i++) {
        const struct build_ref *r = &refs[i];
        uint32_t x = grid_coord(b, r->lo[0] + r->hi[0], 0);
        uint32_t y = grid_coord(b, r->lo[1] + r->hi[1], 1);
        uint32_t z = grid_coord(b, r->lo[2] + r->hi[2], 2);
        uint32_t cell = cell_index(b, x, y, z);
        b->cell_of[i] = cell;
        count[cell]++;
    }
}

static void grid_scatter_task(void *arg, int worker)
{
    struct pbuild *b = arg;
    uint32_t begin, end;
    worker_range(b, worker, &begin, &end);
    uint32_t cells = b->res[0] * b->res[1] * b->res[2];
    uint32_t *offset = &b->counts[(size_t)worker * cells];
    const struct build_ref *src = b->refs[0];
    struct build_ref *dst = b->refs[1];
    for (uint32_t i = begin; i < end; i++)
        dst[offset[b->cell_of[i]]++] = src[i];
}

/* A block of cells [lo, hi) per axis. */
struct block {
    uint32_t lo[3];
    uint32_t hi[3];
    uint32_t slot;
    uint32_t depth;
};

/* Primitives in a block, from the summed-volume table sv of size
 * (res + 1)^3 (unsigned wrap-around cancels in the sum). */
static uint32_t block_count(const struct pbuild *b, const uint32_t *sv, const uint32_t lo[3],
                            const uint32_t hi[3])
{
    uint32_t sx = b->res[0] + 1;
    uint32_t sy = b->res[1] + 1;
#define SV(x, y, z) sv[((size_t)(z) * sy + (y)) * sx + (x)]
    return SV(hi[0], hi[1], hi[2]) - SV(lo[0], hi[1], hi[2]) - SV(hi[0], lo[1], hi[2]) -
           SV(hi[0], hi[1], lo[2]) + SV(lo[0], lo[1], hi[2]) + SV(lo[0], hi[1], lo[2]) +
           SV(hi[0], lo[1], lo[2]) - SV(lo[0], lo[1], lo[2]);
#undef SV
}

/* Grid resolution: powers of two, doubling the axis with the longest
 * cells until about n / GRID_PRIMS_PER_CELL cells.  Integer doubling and
 * float division only, so every machine picks the same grid. */
static void plan_grid(struct pbuild *b, const float clo[4], const float chi[4])
{
    uint32_t target = b->n / GRID_PRIMS_PER_CELL;
    if (target > GRID_MAX_CELLS)
        target = GRID_MAX_CELLS;
    float extent[3];
    for (int k = 0; k < 3; k++) {
        extent[k] = chi[k] - clo[k];
        b->res[k] = 1;
    }
    uint32_t cells = 1;
    while (cells * 2 <= target) {
        int axis = -1;
        float longest = 0.0f;
        for (int k = 0; k < 3; k++) {
            float cell = extent[k] / (float)b->res[k];
            if (isfinite(cell) && cell > longest && b->res[k] < GRID_MAX_RES) {
                longest = cell;
                axis = k;
            }
        }
        if (axis < 0)
            break;
        b->res[axis] *= 2;
        cells *= 2;
    }
    for (int k = 0; k < 3; k++) {
        float s = (float)b->res[k] / extent[k];
        b->grid_origin[k] = clo[k];
        b->grid_scale[k] = extent[k] > 0.0f && isfinite(s) ? s : 0.0f;
    }
}

/*
 * BIH-like nodes over the grid (Wald, Ize and Parker (2008) sec. 5: "one of the threads
 * builds the BVH nodes that represent that grid, which is very similar to
 * Wachter's BIH technique"): a block is halved in cell units across its
 * longest side in space; an empty half is dropped without a node; a block
 * of at most subtree_max primitives, or of one cell, becomes a subtree.
 * Assigns each cell its range start in stage 2's ref order (blocks in
 * depth-first order, cells in z, y, x order within a block) in *start.
 */
static int grid_nodes(struct pbuild *b, const uint32_t *sv, uint32_t *start)
{
    /* Depth first, right pushed before left: at most one entry per
     * level plus one, and every level halves the cells. */
    struct block stack[GRID_MAX_LEVELS + 2];
    uint32_t sp = 0;
    struct block root = {{0, 0, 0}, {b->res[0], b->res[1], b->res[2]}, 0, 0};
    stack[sp++] = root;
    uint32_t offset = 0;
    while (sp > 0) {
        struct block blk = stack[--sp];
        uint32_t count = block_count(b, sv, blk.lo, blk.hi);
        for (;;) {
            int axis = -1;
            float longest = 0.0f;
            for (int k = 0; k < 3; k++) {
                if (blk.hi[k] - blk.lo[k] < 2)
                    continue;
                float side = (float)(blk.hi[k] - blk.lo[k]) / b->grid_scale[k];
                if (axis < 0 || side > longest) {
                    axis = k;
                    longest = side;
                }
            }
            if (axis < 0 || count <= b->subtree_max ||
                build_must_split_median(blk.depth, count)) {
                if (add_subtree(b, offset, offset + count, blk.slot, blk.depth, 1))
                    return -1;
                for (uint32_t z = blk.lo[2]; z < blk.hi[2]; z++)
                    for (uint32_t y = blk.lo[1]; y < blk.hi[1]; y++)
                        for (uint32_t x = blk.lo[0]; x < blk.hi[0]; x++) {
                            uint32_t cell = cell_index(b, x, y, z);
                            uint32_t in_cell = start[cell];
                            start[cell] = offset;
                            offset += in_cell;
                        }
                break;
            }
            struct block half[2] = {blk, blk};
            uint32_t mid = blk.lo[axis] + (blk.hi[axis] - blk.lo[axis]) / 2;
            half[0].hi[axis] = mid;
            half[1].lo[axis] = mid;
            uint32_t left = block_count(b, sv, half[0].lo, half[0].hi);
            if (left == 0 || left == count) {
                /* One half empty: no node, keep halving the other. */
                blk = left == 0 ? half[1] : half[0];
                continue;
            }
            uint32_t pair = top_pair(b);
            if (pair == UINT32_MAX)
                return -1;
            build_set_inner(&b->top[blk.slot], pair);
            for (int s = 0; s < 2; s++) {
                half[s].slot = pair + (uint32_t)s;
                half[s].depth = blk.depth + 1;
            }
            /* Right first: the left block is laid out first. */
            stack[sp++] = half[1];
            stack[sp++] = half[0];
            break;
        }
    }
    return 0;
}

static int stage1_grid(struct pbuild *b, const float clo[4], const float chi[4])
{
    plan_grid(b, clo, chi);
    uint32_t cells = b->res[0] * b->res[1] * b->res[2];
    size_t sv_size = (size_t)(b->res[0] + 1) * (b->res[1] + 1) * (b->res[2] + 1);
    b->cell_of = rt_realloc_array(NULL, b->n, sizeof(*b->cell_of));
    b->counts = rt_realloc_array(NULL, (size_t)b->threads * cells, sizeof(*b->counts));
    uint32_t *sv = rt_calloc(sv_size, sizeof(*sv));
    uint32_t *start = rt_realloc_array(NULL, cells, sizeof(*start));
    int status = -1;
    if (!b->cell_of || !b->counts || !sv || !start)
        goto out;
    rt_pool_run(b->pool, grid_count_task, b);

    /* One thread merges the grids ("the T grids are merged") into
     * per-cell totals and the summed-volume table. */
    uint32_t sx = b->res[0] + 1;
    uint32_t sy = b->res[1] + 1;
    for (uint32_t z = 0; z < b->res[2]; z++)
        for (uint32_t y = 0; y < b->res[1]; y++)
            for (uint32_t x = 0; x < b->res[0]; x++) {
                uint32_t cell = cell_index(b, x, y, z);
                uint32_t total = 0;
                for (uint32_t w = 0; w < b->threads; w++)
                    total += b->counts[(size_t)w * cells + cell];
                start[cell] = total;
                size_t i = ((size_t)(z + 1) * sy + (y + 1)) * sx + (x + 1);
                sv[i] = total + sv[i - 1] + sv[i - sx] + sv[i - sx * sy] - sv[i - sx - 1] -
                        sv[i - sx * sy - 1] - sv[i - sx * sy - sx] + sv[i - sx * sy - sx - 1];
            }
    if (grid_nodes(b, sv, start))
        goto out;
    /* Each thread's scatter offsets: the cell's start plus what the
     * threads before it put there, so the scatter is a stable partition. */
    for (uint32_t cell = 0; cell < cells; cell++) {
        uint32_t offset = start[cell];
        for (uint32_t w = 0; w < b->threads; w++) {
            uint32_t *c = &b->counts[(size_t)w * cells + cell];
            uint32_t here = *c;
            *c = offset;
            offset += here;
        }
    }
    rt_pool_run(b->pool, grid_scatter_task, b);
    status = 0;
out:
    rt_free(sv);
    rt_free(start);
    return status;
}

/* ------------------------------------------------------------ stage 2 */

static int by_id(const void *pa, const void *pb)
{
    uint32_t a = build_ref_id(pa);
    uint32_t b = build_ref_id(pb);
    return a < b ? -1 : a > b;
}

/*
 * An SAH subtree.  The binned builder runs on the subtree's refs in place
 * and writes its nodes into the subtree's block of 2m - 1 nodes
 * (build_subtree), as a median subtree does
 * (build_binned_sah_refs): no copy of the boxes, no arrays of its own.
 * The refs are renumbered 0 .. m - 1 in range order first (their ids kept
 * aside), so that the tree is the one accel_build makes from the
 * subtree's boxes in range order (the builder reads the ids only for the
 * median fallback's ties).  The sweep builder (BVH_BUILDER_SWEEP_SAH) has
 * no such entry point and runs accel_build on a copy of the boxes in its
 * own arrays, which stage 3 copies from.  Either way the copy goes to the
 * same range of the other ref buffer, which nothing uses meanwhile (each
 * range is live in one buffer; allocated storage, so it may change type,
 * C99 6.5p6), and fits: 4 bytes per id, 24 per box, 32 per ref.  Two
 * things neither builder can be told are handled here: it counts depth
 * from the subtree's root, so a subtree that would end deeper than
 * BVH_MAX_DEPTH in the whole tree is rebuilt by the median builder, which
 * applies the depth guard from depth0 (a safety net: no input we know of
 * drives an SAH build below depth ~40, builders.c, and stage 1 rarely goes
 * 10 deep), from the refs in range order again (sorted back by their
 * local ids); and it does not read leaf_growth.
 */
static int build_sah_subtree(struct pbuild *b, struct subtree *s, struct bvh_node *range)
{
    uint32_t m = s->end - s->begin;
    struct build_ref *refs = &s->refs[s->begin];
    struct build_ref *other = s->refs == b->refs[0] ? b->refs[1] : b->refs[0];
    if (b->p.builder == BVH_BUILDER_BINNED_SAH) {
        uint32_t *ids = (uint32_t *)(void *)&other[s->begin];
        for (uint32_t i = 0; i < m; i++) {
            ids[i] = build_ref_id(&refs[i]);
            build_ref_set_id(&refs[i], i);
        }
        uint32_t depth;
        if (build_binned_sah_refs(range, refs, m, &b->p, 1, &s->node_count, &depth))
            return -1;
        if (s->depth + depth <= BVH_MAX_DEPTH) {
            s->nodes = range;
            s->max_depth = s->depth + depth;
            for (uint32_t i = 0; i < m; i++)
                b->prim_index[s->begin + i] = ids[build_ref_id(&refs[i])];
            return 0;
        }
        /* The range order and the ids back, for the median builder. */
        qsort(refs, m, sizeof(*refs), by_id);
        for (uint32_t i = 0; i < m; i++)
            build_ref_set_id(&refs[i], ids[i]);
    } else {
        struct aabb *boxes = (struct aabb *)(void *)&other[s->begin];
        for (uint32_t i = 0; i < m; i++) {
            for (int k = 0; k < 3; k++) {
                boxes[i].min[k] = refs[i].lo[k];
                boxes[i].max[k] = refs[i].hi[k];
            }
        }
        if (accel_build(&s->sah, boxes, m, &b->p))
            return -1;
        if (s->depth + s->sah.depth <= BVH_MAX_DEPTH) {
            s->nodes = s->sah.nodes;
            s->node_count = s->sah.node_count;
            s->max_depth = s->depth + s->sah.depth;
            for (uint32_t i = 0; i < m; i++)
                b->prim_index[s->begin + i] = build_ref_id(&refs[s->sah.prim_index[i]]);
            return 0;
        }
        bvh_release(&s->sah);
    }
    build_median_refs(range, refs, m, s->depth, &b->p, &s->node_count, &s->max_depth);
    s->nodes = range;
    for (uint32_t i = 0; i < m; i++)
        b->prim_index[s->begin + i] = build_ref_id(&refs[i]);
    return 0;
}

/* A median subtree, in place, into its block of 2m - 1 nodes (Wald, Ize
 * and Parker (2008) sec. 5: "a subtree of N triangles can use at most
 * 2N - 1 nodes"; the paper assigns each subtree such a region of one node
 * array, build_subtree a block of its own). */
static void build_median_subtree(struct pbuild *b, struct subtree *s, struct bvh_node *range)
{
    uint32_t m = s->end - s->begin;
    struct build_ref *refs = &s->refs[s->begin];
    build_median_refs(range, refs, m, s->depth, &b->p, &s->node_count, &s->max_depth);
    s->nodes = range;
    for (uint32_t i = 0; i < m; i++)
        b->prim_index[s->begin + i] = build_ref_id(&refs[i]);
}

/*
 * refs[1]'s spare: from BUILD_SPARE_MIN bytes of refs, refs[1] is a
 * mapping of three times its size (build_spare_refs; rt_malloc_large:
 * 2 MB aligned, advised for huge pages) that the
 * caller's collapse takes over (accel_build_parallel_triangles' spare),
 * of which the partitions touch the first third.  A build that large
 * (rtbench's bumpy, a million triangles: 32 MB) finds refs[1] fresh
 * anyway (build_subtree's comment: it frees more than glibc's trim
 * threshold; 7,800 faults of 4 KB in stage 1, measured), and the wide
 * layout is a fresh mapping in every one-shot build (rt_malloc_large),
 * so one mapping for both lets the layout's first 32 MB be pages the
 * build already touched.  Three times: an 8-wide layout takes about 70
 * bytes a triangle (bumpy's 66 MB) against refs[1]'s 32, and
 * rt_malloc_large_reuse takes a spare of up to twice the layout; one that
 * does not fit is freed by the caller and the layout maps its own, as
 * before.  The arenas stay heap blocks: freed, they serve the gather's
 * triangles warm (with them in the mapping too, the gather's 36 MB came
 * fresh: 8,790 faults of 4 KB).  Smaller builds (the kitchen, the soup:
 * 3.5 MB of refs) keep a heap block, which comes back warm from the last
 * build.
 */

/* Nodes per arena (struct node_arena): twice a thread's even share of
 * the refs, plus two of the largest subtrees for the unevenness of the
 * hand-out; a subtree that does not fit takes a block of its own. */
static size_t arena_cap(const struct pbuild *b)
{
    return 2 * (((size_t)b->n + b->threads - 1) / b->threads) + 2 * (size_t)b->subtree_max;
}

/*
 * Builds subtree s in 2m - 1 nodes at the end of the thread's arena (the
 * arena then keeps the nodes used, rounded up to 64 bytes), or, when they
 * do not fit, in a block of its own that release_build frees, shrunk to
 * the nodes used; stage 3 copies from either.  One scratch array of
 * 2n - 1 nodes with a range per subtree (the paper's way, and this
 * file's until 2026-12) made the kernel zero every huge page a subtree
 * touched although the subtrees use about half their ranges (rtbench's
 * bumpy: 64 MB mapped for 35 MB of nodes).  A block per subtree (1 MB
 * for bumpy) came back from the C library's heap when the heap kept the
 * last build's memory, but a build of a million triangles frees more
 * than its trim threshold (at most 64 MiB) at the top of the heap, so
 * the next build's blocks were fresh 4 KB pages, 8,657 faults a bumpy
 * build (one thread: 10-17 ms of stage 2's CPU time, measured with the
 * trimming turned off).  An arena per thread is one block: on bumpy a
 * mapping above the mmap threshold, advised for huge pages (alloc.c),
 * of which a thread touches the nodes it keeps; on the kitchen a heap
 * block that comes back warm as before.
 */
static int build_subtree(struct pbuild *b, struct subtree *s, struct node_arena *arena)
{
    const uint32_t m = s->end - s->begin;
    const size_t need = 2 * (size_t)m - 1;
    if (arena && !arena->tried) {
        arena->tried = 1;
        arena->cap = arena_cap(b);
        arena->nodes = rt_alloc_array64(arena->cap, sizeof(*arena->nodes), &arena->block);
    }
    struct bvh_node *range = NULL;
    if (arena && arena->nodes && arena->cap - arena->used >= need) {
        range = arena->nodes + arena->used;
    } else {
        range = rt_alloc_array64(need, sizeof(*range), &s->block);
        if (!range)
            return -1;
        arena = NULL;
    }
    int rc = 0;
    if (b->pp.subtree == BVH_SUBTREE_MEDIAN)
        build_median_subtree(b, s, range);
    else
        rc = build_sah_subtree(b, s, range);
    if (rc)
        return rc;
    if (arena) {
        /* A sweep subtree's nodes are its own arrays: nothing kept. */
        if (s->nodes == range)
            arena->used += ((size_t)s->node_count + 1) & ~(size_t)1;
        return 0;
    }
    if (s->nodes == range && s->node_count < need) {
        /* The nodes keep their offset in the block if realloc moves it. */
        const size_t offset = (size_t)((char *)range - (char *)s->block);
        char *shrunk =
            rt_realloc_array(s->block, offset + (size_t)s->node_count * sizeof(*range), 1);
        if (shrunk) {
            s->block = shrunk;
            s->nodes = (const struct bvh_node *)(const void *)(shrunk + offset);
        }
    }
    return 0;
}

/* A deferred node (struct deferred), on one thread: stage 1's steps on a
 * single chunk, depth first (left child first), its subtrees built as
 * they are cut off.  The splits are the ones the level-by-level stage 1
 * makes (pick_split and the stable partition give the same result for
 * any chunking), so the tree does not depend on which nodes are
 * deferred. */
static int build_deferred(struct pbuild *b, struct deferred *d, struct node_arena *arena)
{
    const int bins = b->bins;
    const uint32_t axis_base[4] = {0, (uint32_t)bins * 32u, 2u * (uint32_t)bins * 32u, 0};
    void *hist_box_block, *hist_count_block;
    float(*hist_box)[8] = rt_alloc_array64(3 * (size_t)bins, sizeof(*hist_box), &hist_box_block);
    uint32_t(*hist_count)[8] =
        rt_alloc_array64(3 * (size_t)bins, sizeof(*hist_count), &hist_count_block);
    /* Depth first with the right child pushed: one entry per level below
     * the node plus one, as the serial builders' stacks. */
    struct {
        struct open_node o;
        int src;
    } stack[BUILD_STACK_SIZE];
    int status = -1;
    d->top = reserve(NULL, &d->top_cap, 1, sizeof(*d->top));
    if (!hist_box || !hist_count || !d->top)
        goto out;
    memset(&d->top[0], 0, sizeof(d->top[0]));
    d->top[0].count = 1;
    d->top_count = 1;
    uint32_t sp = 0;
    stack[sp].o = d->node;
    stack[sp].o.slot = 0;
    stack[sp].src = d->src;
    sp++;
    while (sp > 0) {
        sp--;
        struct open_node o = stack[sp].o;
        const int src = stack[sp].src;
        init_binning(&o, bins);
        o.first_chunk = 0;
        o.chunk_count = 1;
        const struct build_bin_map map = bin_map_of(&o, bins - 1);
        b->fill((char *)hist_box, (char *)hist_count, axis_base, bins, &map, b->refs[src],
                o.begin, o.end);
        pick_split(b, &o, (const float(*)[8])hist_box, (const uint32_t(*)[8])hist_count);
        if (o.axis < 0) {
            struct subtree *st = subtree_in(&d->subtrees, &d->subtree_count, &d->subtree_cap,
                                            o.begin, o.end, o.slot, o.depth, b->refs[src]);
            if (!st || build_subtree(b, st, arena))
                goto out;
            continue;
        }
        struct chunk ch;
        memset(&ch, 0, sizeof(ch));
        ch.begin = o.begin;
        ch.end = o.end;
        ch.left_dst = o.begin;
        ch.right_dst = o.begin + o.left_count;
        partition_chunk(b, b->refs[src], b->refs[!src], &o, &ch);
        uint32_t pair = pair_in(&d->top, &d->top_count, &d->top_cap);
        if (pair == UINT32_MAX)
            goto out;
        build_set_inner(&d->top[o.slot], pair);
        struct open_node kid[2];
        make_kids(&o, &ch, pair, kid);
        /* The right child onto the stack first, so the left one goes
         * first. */
        for (int k = 1; k >= 0; k--) {
            uint32_t m = kid[k].end - kid[k].begin;
            if (m > b->subtree_max && !build_must_split_median(kid[k].depth, m)) {
                stack[sp].o = kid[k];
                stack[sp].src = !src;
                sp++;
                continue;
            }
            struct subtree *st =
                subtree_in(&d->subtrees, &d->subtree_count, &d->subtree_cap, kid[k].begin,
                           kid[k].end, kid[k].slot, kid[k].depth, b->refs[!src]);
            if (!st || build_subtree(b, st, arena))
                goto out;
        }
    }
    status = 0;
out:
    rt_free(hist_box_block);
    rt_free(hist_count_block);
    return status;
}

/* Wald, Ize and Parker (2008) sec. 5, stage 2: "the render threads dynamically request
 * subtrees to work on using an atomic read-and-increment on a shared
 * counter, until all subtrees are finished"; here the deferred nodes
 * too, all in one order of descending size. */
static void subtree_task(void *arg, int worker)
{
    struct pbuild *b = arg;
    struct node_arena *arena =
        b->arenas && (uint32_t)worker < b->threads ? &b->arenas[worker] : NULL;
    const uint32_t items = b->subtree_count + b->deferred_count;
    uint32_t i;
    while ((i = chunk_of(b)) < items) {
        if (rt_atomic_load_relaxed(&b->failed))
            continue;
        uint32_t j = b->order[i];
        int rc = j < b->subtree_count
                     ? build_subtree(b, &b->subtrees[j], arena)
                     : build_deferred(b, &b->deferred[j - b->subtree_count], arena);
        if (rc)
            rt_atomic_store_relaxed(&b->failed, 1);
    }
}

/* Moves the deferred nodes' top nodes and subtrees into the pbuild's
 * arrays: local top index 0 becomes the node's own slot, local index
 * i > 0 becomes base + i - 1 (base: the top count before the move). */
static int merge_deferred(struct pbuild *b)
{
    for (uint32_t i = 0; i < b->deferred_count; i++) {
        struct deferred *d = &b->deferred[i];
        const uint32_t base = b->top_count;
        const uint32_t slot = d->node.slot;
        if (d->top_count > 1) {
            struct bvh_node *top =
                reserve(b->top, &b->top_cap, b->top_count + d->top_count - 1, sizeof(*top));
            if (!top)
                return -1;
            b->top = top;
        }
        for (uint32_t t = 0; t < d->top_count; t++) {
            struct bvh_node node = d->top[t];
            if (!node.count)
                node.first = base + node.first - 1; /* a pair never starts at 0 */
            b->top[t == 0 ? slot : base + t - 1] = node;
        }
        b->top_count += d->top_count - 1;
        for (uint32_t k = 0; k < d->subtree_count; k++) {
            struct subtree *ds = &d->subtrees[k];
            struct subtree *st = subtree_in(&b->subtrees, &b->subtree_count, &b->subtree_cap,
                                            ds->begin, ds->end, 0, 0, NULL);
            if (!st)
                return -1;
            *st = *ds;
            st->slot = ds->slot == 0 ? slot : base + ds->slot - 1;
            /* The pbuild's copy owns a sweep subtree's arrays and its
             * node block now. */
            memset(&ds->sah, 0, sizeof(ds->sah));
            ds->block = NULL;
        }
        d->subtree_count = 0;
    }
    return 0;
}

/*
 * Renumbers the top nodes breadth first, each parent's pair in the order
 * of the parents, which is the order in which the level-by-level stage 1
 * appends them (a level's open nodes are the previous level's children in
 * order): the deferred nodes' top nodes then sit where they would had
 * stage 1 split them level by level, so the final array does not depend
 * on which nodes were deferred.
 */
static int renumber_top(struct pbuild *b)
{
    const uint32_t n = b->top_count;
    uint32_t *queue = rt_realloc_array(NULL, n, sizeof(*queue));
    uint32_t *index = rt_realloc_array(NULL, n, sizeof(*index));
    struct bvh_node *top = rt_realloc_array(NULL, n, sizeof(*top));
    int status = -1;
    if (!queue || !index || !top)
        goto out;
    uint32_t tail = 0;
    queue[tail++] = 0;
    index[0] = 0;
    for (uint32_t head = 0; head < tail; head++) {
        const struct bvh_node *node = &b->top[queue[head]];
        if (node->count)
            continue;
        for (uint32_t c = 0; c < 2; c++) {
            index[node->first + c] = tail;
            queue[tail++] = node->first + c;
        }
    }
    for (uint32_t i = 0; i < n; i++) {
        struct bvh_node node = b->top[queue[i]];
        if (!node.count)
            node.first = index[node.first];
        top[i] = node;
    }
    for (uint32_t i = 0; i < b->subtree_count; i++)
        b->subtrees[i].slot = index[b->subtrees[i].slot];
    rt_free(b->top);
    b->top = top;
    b->top_cap = n;
    top = NULL;
    status = 0;
out:
    rt_free(queue);
    rt_free(index);
    rt_free(top);
    return status;
}

static int by_begin(const void *pa, const void *pb)
{
    const struct subtree *a = pa;
    const struct subtree *b = pb;
    return a->begin < b->begin ? -1 : a->begin > b->begin;
}

/* Hand-out order: descending size, then ascending begin; the pair is
 * unique, so qsort's order is deterministic. */
struct size_key {
    uint64_t key; /* (~size << 32) | begin: ascending = the order above */
    uint32_t index;
};

static int by_key(const void *pa, const void *pb)
{
    const struct size_key *a = pa;
    const struct size_key *b = pb;
    return a->key < b->key ? -1 : a->key > b->key;
}

/* ------------------------------------------------------------ stage 3 */

/* Copies subtree nodes into the final array: the root into the slot its
 * parent reserved, the rest after the top nodes, indices rebased. */
static void compact_task(void *arg, int worker)
{
    (void)worker;
    struct pbuild *b = arg;
    uint32_t i;
    while ((i = chunk_of(b)) < b->subtree_count) {
        const struct subtree *s = &b->subtrees[i];
        for (uint32_t j = 0; j < s->node_count; j++) {
            struct bvh_node node = s->nodes[j];
            if (node.count)
                node.first += s->begin;
            else
                node.first += s->final_base - 1;
            b->final_nodes[j == 0 ? s->slot : s->final_base + j - 1] = node;
        }
    }
}

/* ------------------------------------------------------------ driver */

void bvh_parallel_params_default(struct bvh_parallel_params *params)
{
    params->partition = BVH_PARTITION_BINNING;
    params->subtree = BVH_SUBTREE_SAH;
}

static void release_build(struct pbuild *b)
{
    for (uint32_t i = 0; i < b->subtree_count; i++) {
        bvh_release(&b->subtrees[i].sah);
        rt_free(b->subtrees[i].block);
    }
    for (uint32_t i = 0; i < b->deferred_count; i++) {
        for (uint32_t k = 0; k < b->deferred[i].subtree_count; k++) {
            bvh_release(&b->deferred[i].subtrees[k].sah);
            rt_free(b->deferred[i].subtrees[k].block);
        }
        rt_free(b->deferred[i].top);
        rt_free(b->deferred[i].subtrees);
    }
    rt_free(b->deferred);
    for (uint32_t i = 0; b->arenas && i < b->threads; i++)
        rt_free(b->arenas[i].block);
    rt_free(b->arenas);
    rt_free(b->refs_block[0]);
    rt_free(b->refs_block[1]);
    rt_free(b->top);
    rt_free(b->subtrees);
    rt_free(b->chunks);
    rt_free(b->chunk_box);
    rt_free(b->open);
    rt_free(b->hist_box_block);
    rt_free(b->hist_count_block);
    rt_free(b->cell_of);
    rt_free(b->counts);
    rt_free(b->order);
}

/*
 * Stage 3's final array of `total` nodes.  Nothing reads the ref buffers
 * after stage 2 (prim_index is written there, and a sweep subtree's nodes
 * are its own arrays), so the final array takes over the block of
 * refs[0], which the set-up wrote whole and which was allocated for the
 * 2n - 1 nodes a tree can have, shrunk by realloc to the nodes: the
 * first n refs' worth of its pages are in memory already, where a fresh
 * array of a million-triangle build is a fresh mapping whose pages the
 * kernel zeroes as stage 3 first writes them (rtbench's bumpy, one
 * thread: the zeroing under compact_task was 4.7 % of a build
 * pipeline's perf samples).  An n-ref block grown by realloc copied
 * itself (the final array has more nodes than there are refs).  The old
 * contents do not matter: stage 3 writes every node.  If realloc fails,
 * the block stays the pbuild's and a fresh array is tried.
 */
static struct bvh_node *final_array(struct pbuild *b, uint64_t total)
{
    if (b->refs_block[0]) {
        struct bvh_node *nodes = rt_realloc_array(b->refs_block[0], total, sizeof(*nodes));
        if (nodes) {
            b->refs_block[0] = NULL;
            b->refs[0] = NULL;
            return nodes;
        }
    }
    return rt_realloc_array(NULL, total, sizeof(struct bvh_node));
}

/* Stages 2 and 3 once stage 1 has left its subtrees; fills *out. */
static int build_subtrees(struct pbuild *b, struct bvh *out)
{
    const uint32_t items = b->subtree_count + b->deferred_count;
    struct size_key *keys = rt_realloc_array(NULL, items, sizeof(*keys));
    b->order = rt_realloc_array(NULL, items, sizeof(*b->order));
    if (!keys || !b->order) {
        rt_free(keys);
        return -1;
    }
    for (uint32_t i = 0; i < items; i++) {
        const struct open_node *d =
            i < b->subtree_count ? NULL : &b->deferred[i - b->subtree_count].node;
        uint32_t begin = d ? d->begin : b->subtrees[i].begin;
        uint32_t end = d ? d->end : b->subtrees[i].end;
        keys[i].key = ((uint64_t)~(end - begin) << 32) | begin;
        keys[i].index = i;
    }
    /* Wald, Ize and Parker (2008) sec. 5: "to obtain good load balancing we first sort the
     * subtrees by descending size". */
    qsort(keys, items, sizeof(*keys), by_key);
    for (uint32_t i = 0; i < items; i++)
        b->order[i] = keys[i].index;
    rt_free(keys);

    /* Zeroed: a thread allocates its arena at its first subtree. */
    b->arenas = rt_realloc_array(NULL, b->threads, sizeof(*b->arenas));
    if (!b->arenas)
        return -1;
    memset(b->arenas, 0, (size_t)b->threads * sizeof(*b->arenas));
    b->failed = 0;
    run(b, subtree_task);
    if (b->failed)
        return -1;
    if (b->deferred_count && (merge_deferred(b) || renumber_top(b)))
        return -1;
    uint32_t k = b->subtree_count;
    qsort(b->subtrees, k, sizeof(*b->subtrees), by_begin);

    /* Stage 3: the final layout (file comment). */
    uint64_t total = b->top_count;
    uint32_t depth = 0;
    for (uint32_t i = 0; i < k; i++) {
        struct subtree *s = &b->subtrees[i];
        s->final_base = (uint32_t)total;
        total += s->node_count - 1;
        if (s->max_depth > depth)
            depth = s->max_depth;
    }
    b->final_nodes = final_array(b, total);
    if (!b->final_nodes)
        return -1;
    for (uint32_t i = 0; i < b->top_count; i++)
        b->final_nodes[i] = b->top[i];
    run(b, compact_task);
    /* The top nodes' boxes, children before parents (children pairs are
     * appended after their parent). */
    for (uint32_t i = b->top_count; i-- > 0;) {
        if (b->top[i].count)
            continue;
        struct bvh_node *node = &b->final_nodes[i];
        const struct bvh_node *l = &b->final_nodes[node->first];
        const struct bvh_node *r = &b->final_nodes[node->first + 1];
        for (int a = 0; a < 3; a++) {
            node->aabb_min[a] = build_min(l->aabb_min[a], r->aabb_min[a]);
            node->aabb_max[a] = build_max(l->aabb_max[a], r->aabb_max[a]);
        }
    }
    out->nodes = b->final_nodes;
    b->final_nodes = NULL;
    out->node_count = (uint32_t)total;
    out->depth = depth;
    return 0;
}

/* accel_build_parallel_ex on prim_boxes, or (prim_boxes NULL) on the
 * triangles of positions and indices (accel_build_parallel_triangles). */
static int build_parallel(struct bvh *out, const struct aabb *prim_boxes, const float *positions,
                          const uint32_t *indices, uint32_t prim_count,
                          const struct bvh_build_params *params,
                          const struct bvh_parallel_params *parallel, struct rt_pool *pool,
                          struct rt_large_block *spare)
{
    if (spare)
        memset(spare, 0, sizeof(*spare));
    struct pbuild b;
    memset(&b, 0, sizeof(b));
    accel_build_params_normalize(&b.p, params);
    bvh_parallel_params_default(&b.pp);
    if (parallel) {
        if (parallel->partition == BVH_PARTITION_GRID)
            b.pp.partition = BVH_PARTITION_GRID;
        if (parallel->subtree == BVH_SUBTREE_MEDIAN)
            b.pp.subtree = BVH_SUBTREE_MEDIAN;
    }
    b.subtree_max = prim_count / PARALLEL_SUBTREES + (prim_count % PARALLEL_SUBTREES != 0);
    if (b.subtree_max < PARALLEL_MIN_SUBTREE)
        b.subtree_max = PARALLEL_MIN_SUBTREE;
    /* One subtree: stage 2 alone, which is exactly the serial builder. */
    if (prim_count <= b.subtree_max) {
        /* From the triangles the binned builder needs no box array. */
        if (!prim_boxes && b.pp.subtree != BVH_SUBTREE_MEDIAN)
            return accel_build_triangles(out, positions, indices, prim_count, &b.p, NULL);
        struct aabb *boxes = NULL;
        if (!prim_boxes) {
            boxes = accel_triangle_boxes_pool(positions, indices, prim_count, pool);
            if (!boxes) {
                memset(out, 0, sizeof(*out));
                return -1;
            }
            prim_boxes = boxes;
        }
        const int rc = b.pp.subtree == BVH_SUBTREE_MEDIAN
                           ? accel_build_median(out, prim_boxes, prim_count, &b.p)
                           : accel_build(out, prim_boxes, prim_count, &b.p);
        rt_free(boxes);
        return rc;
    }
    memset(out, 0, sizeof(*out));
    /* 2n - 1 nodes must fit the 32-bit indices (as accel_build_alloc). */
    if (prim_count > (UINT32_MAX - 1) / 2 + 1)
        return -1;
    b.boxes = prim_boxes;
    b.positions = positions;
    b.indices = indices;
    b.n = prim_count;
    b.pool = pool;
    b.threads = (uint32_t)rt_pool_threads(pool);
    b.defer_max = prim_count / (PARALLEL_DEFER_PER_THREAD * b.threads);

    int status = -1;
    out->prim_index = rt_realloc_array(NULL, prim_count, sizeof(*out->prim_index));
    b.prim_index = out->prim_index;
    /* refs[0]'s block becomes the final array (final_array): room for
     * 2n - 1 nodes, of which the pages past the refs are touched only by
     * stage 3. */
    const uint64_t ref_bytes = (uint64_t)prim_count * sizeof(struct build_ref);
    const uint64_t node_bytes = (2 * (uint64_t)prim_count - 1) * sizeof(struct bvh_node);
    const uint64_t refs0_bytes = ref_bytes > node_bytes ? ref_bytes : node_bytes;
    if (refs0_bytes <= SIZE_MAX - 64)
        b.refs[0] = rt_alloc_array64((size_t)refs0_bytes, 1, &b.refs_block[0]);
    /* refs[1] in a mapping for the caller's collapse (build_spare_refs);
     * if the mapping fails, the usual block. */
    if (spare)
        b.refs[1] = build_spare_refs((ref_bytes + 63) & ~(uint64_t)63, &b.scratch);
    if (!b.refs[1])
        b.refs[1] = rt_alloc_array64(prim_count, sizeof(struct build_ref), &b.refs_block[1]);
    plan_flat_chunks(&b, prim_count);
    b.chunk_box = rt_realloc_array(NULL, 2 * (size_t)b.chunk_count, sizeof(*b.chunk_box));
    b.top = reserve(NULL, &b.top_cap, 1, sizeof(*b.top));
    if (!out->prim_index || !b.refs[0] || !b.refs[1] || !b.chunk_box || !b.top)
        goto out;
    memset(&b.top[0], 0, sizeof(b.top[0]));
    b.top[0].count = 1;
    b.top_count = 1;

    run(&b, setup_task);
    struct open_node root;
    memset(&root, 0, sizeof(root));
    root.end = prim_count;
    struct aabb cb = aabb_empty();
    root.box = aabb_empty();
    for (uint32_t c = 0; c < b.chunk_count; c++) {
        for (int k = 0; k < 3; k++) {
            root.box.min[k] = build_min(root.box.min[k], b.chunk_box[2 * c].min[k]);
            root.box.max[k] = build_max(root.box.max[k], b.chunk_box[2 * c].max[k]);
            cb.min[k] = build_min(cb.min[k], b.chunk_box[2 * c + 1].min[k]);
            cb.max[k] = build_max(cb.max[k], b.chunk_box[2 * c + 1].max[k]);
        }
    }
    for (int k = 0; k < 3; k++) {
        root.clo[k] = cb.min[k];
        root.chi[k] = cb.max[k];
    }

    if (b.pp.partition == BVH_PARTITION_GRID) {
        if (stage1_grid(&b, root.clo, root.chi))
            goto out;
    } else if (stage1_binning(&b, &root)) {
        goto out;
    }
    if (build_subtrees(&b, out))
        goto out;
    out->prim_count = prim_count;
    status = 0;
out:
    release_build(&b);
    if (status) {
        bvh_release(out);
        rt_free(b.final_nodes);
    }
    if (!status && spare)
        *spare = b.scratch; /* nothing reads refs[1] now */
    else
        rt_free_large(&b.scratch);
    return status;
}

int accel_build_parallel_ex(struct bvh *out, const struct aabb *prim_boxes, uint32_t prim_count,
                            const struct bvh_build_params *params,
                            const struct bvh_parallel_params *parallel, struct rt_pool *pool)
{
    return build_parallel(out, prim_boxes, NULL, NULL, prim_count, params, parallel, pool, NULL);
}

int accel_build_parallel_triangles(struct bvh *out, const float *positions,
                                   const uint32_t *indices, uint32_t prim_count,
                                   const struct bvh_build_params *params, struct rt_pool *pool,
                                   struct rt_large_block *spare)
{
    return build_parallel(out, NULL, positions, indices, prim_count, params, NULL, pool, spare);
}

int accel_build_parallel(struct bvh *out, const struct aabb *prim_boxes, uint32_t prim_count,
                         const struct bvh_build_params *params, struct rt_pool *pool)
{
    return accel_build_parallel_ex(out, prim_boxes, prim_count, params, NULL, pool);
}
