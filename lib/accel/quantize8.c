/* SPDX-License-Identifier: Apache-2.0 */
/*
 * quantize8.c - the quantized mirror of an 8-wide layout's nodes
 * (struct bvh8q_node, bvh4_layout.h): each child box as 8-bit multiples
 * of a power-of-two step per axis from a float origin (Ylitie, Karras and
 * Laine 2017, "Efficient incoherent ray traversal on GPUs through
 * compressed wide BVHs", sec. 3.1), half the bytes of a float node, so
 * that a ray beyond the caches fetches two lines a node instead of four.
 *
 * The walks decode a bound as fma(q, step, origin) in floats, one
 * rounding (q * step is exact), and run their float slab test on it
 * unchanged.  Their answers stay those of the float nodes only if every
 * decoded box contains the float box: the slab tests are monotonic in
 * the bounds, so the quantized walk then visits every node and leaf the
 * float walk visits (and some more).  So the quantization here evaluates
 * each decoded bound exactly as the walks do (fmaf, correctly rounded as
 * the vector fma) and steps q outwards until it holds, instead of
 * trusting the floor and ceiling of a rounded quotient.
 */
#include <math.h>
#include <string.h>

#include "trace/bvh4_layout.h"

/* The decode of the walks (traverse_wide.h, wide8q_row): fmaf rounds once,
 * as the vector fma does. */
static float decode(uint32_t q, float step, float origin)
{
    return fmaf((float)q, step, origin);
}

/* The smallest exponent e in [-126, 127] with 255 * 2^e >= extent (a
 * finite, non-negative double): then the node's largest bound decodes
 * from some q <= 255.  The extent is the float difference's exact value
 * or close to it; the outward steps below make up for the rest. */
static int step_exponent(double extent)
{
    int e = -126;
    if (extent > 0.0) {
        int x = 0;
        (void)frexp(extent / 255.0, &x); /* extent / 255 < 2^x */
        e = x - 1 > -126 ? x - 1 : -126;
        while (e < 127 && ldexp(255.0, e) < extent)
            e++;
    }
    return e;
}

int accel_quantize8_node(struct bvh8q_node *q, const struct bvh8_node *n)
{
    memset(q, 0, offsetof(struct bvh8q_node, links));
    memcpy(&q->links, n->child, sizeof(q->links));
    unsigned valid = 0;
    for (uint32_t l = 0; l < 8; l++) {
        /* An unused lane holds the empty box min = +inf, max = -inf
         * (bvh4_layout.h); every used lane has min <= max. */
        if (n->bounds[0][l] <= n->bounds[3][l])
            valid |= 1u << l;
        else if (!(n->bounds[0][l] == INFINITY && n->bounds[3][l] == -INFINITY))
            return -1; /* never (bvh_build.h: no NaN bounds), but not masked off */
    }
    q->valid = (uint8_t)valid;
    for (uint32_t a = 0; a < 3; a++) {
        float lo_min = INFINITY, hi_max = -INFINITY;
        for (uint32_t l = 0; l < 8; l++) {
            if (!(valid >> l & 1u))
                continue;
            const float lo = n->bounds[a][l], hi = n->bounds[3 + a][l];
            if (!isfinite(lo) || !isfinite(hi))
                return -1;
            lo_min = lo < lo_min ? lo : lo_min;
            hi_max = hi > hi_max ? hi : hi_max;
        }
        if (!valid) {
            lo_min = 0.0f;
            hi_max = 0.0f;
        }
        const int e = step_exponent((double)hi_max - (double)lo_min);
        const float step = ldexpf(1.0f, e);
        const float origin = lo_min;
        q->origin[a] = origin;
        q->exp[a] = (uint8_t)(e + 127);
        /* The largest code must decode finite, so that every decoded
         * bound is (the fused node test's bound, node_fused.h). */
        if (!isfinite(decode(255, step, origin)))
            return -1;
        for (uint32_t l = 0; l < 8; l++) {
            if (!(valid >> l & 1u)) {
                q->q[a][l] = 0;
                q->q[3 + a][l] = 0;
                continue;
            }
            const float lo = n->bounds[a][l], hi = n->bounds[3 + a][l];
            /* The first guesses from the float quotient (rounded twice:
             * they may be a step inside), then outwards until the decode
             * contains [lo, hi]: origin <= lo decodes q = 0, and
             * origin + 255 step >= hi_max exactly, which rounds to a
             * float >= hi_max, so both steps end inside [0, 255]. */
            float fl = floorf((lo - origin) / step);
            float fh = ceilf((hi - origin) / step);
            uint32_t qlo = fl <= 0.0f ? 0u : fl >= 255.0f ? 255u : (uint32_t)fl;
            uint32_t qhi = fh <= 0.0f ? 0u : fh >= 255.0f ? 255u : (uint32_t)fh;
            while (qlo > 0 && decode(qlo, step, origin) > lo)
                qlo--;
            while (qhi < 255 && decode(qhi, step, origin) < hi)
                qhi++;
            if (decode(qlo, step, origin) > lo || decode(qhi, step, origin) < hi)
                return -1;
            q->q[a][l] = (uint8_t)qlo;
            q->q[3 + a][l] = (uint8_t)qhi;
        }
    }
    return 0;
}

void accel_quantize8_release(struct bvh4 *wide)
{
    rt_free_large(&wide->q_raw);
    wide->nodes8q = NULL;
}

int accel_quantize8(struct bvh4 *wide)
{
    if (wide->width != 8 || !wide->node_count || !wide->nodes8) {
        accel_quantize8_release(wide);
        return -1;
    }
    if (!wide->nodes8q) {
        struct rt_large_block block = {0};
        void *p = rt_malloc_large((size_t)wide->node_count * sizeof(struct bvh8q_node), &block);
        if (!p)
            return -1;
        wide->q_raw = block;
        wide->nodes8q = (struct bvh8q_node *)p;
    }
    for (uint32_t i = 0; i < wide->node_count; i++) {
        if (accel_quantize8_node(&wide->nodes8q[i], &wide->nodes8[i])) {
            accel_quantize8_release(wide);
            return -1;
        }
    }
    return 0;
}
