/* SPDX-License-Identifier: Apache-2.0 */
/*
 * select_median.c - the object-median selection shared by the builders'
 * median splits (binned SAH fallback, median/BIH builder, parallel build).
 */
#include <stddef.h>
#include <stdint.h>

#include "accel/build_internal.h"
#include "accel/build_median.h"

/* Total order for the object median: centroid on `axis`, then index
 * (build_float_order is total even for NaN, so the selection's scans
 * stay inside their range whatever the input). */
static inline int ref_less(const struct build_ref *a, const struct build_ref *b, int axis)
{
    uint32_t ka = build_float_order(a->lo[axis] + a->hi[axis]);
    uint32_t kb = build_float_order(b->lo[axis] + b->hi[axis]);
    if (ka != kb)
        return ka < kb;
    return build_ref_id(a) < build_ref_id(b);
}

static inline void swap_refs(struct build_ref *refs, size_t i, size_t j)
{
    struct build_ref tmp = refs[i];
    refs[i] = refs[j];
    refs[j] = tmp;
}

static void sift_down(struct build_ref *refs, size_t root, size_t n, int axis)
{
    for (;;) {
        size_t child = 2 * root + 1;
        if (child >= n)
            return;
        if (child + 1 < n && ref_less(&refs[child], &refs[child + 1], axis))
            child++;
        if (!ref_less(&refs[root], &refs[child], axis))
            return;
        swap_refs(refs, root, child);
        root = child;
    }
}

static void heap_sort(struct build_ref *refs, size_t n, int axis)
{
    for (size_t i = n / 2; i-- > 0;)
        sift_down(refs, i, n, axis);
    for (size_t end = n; end-- > 1;) {
        swap_refs(refs, 0, end);
        sift_down(refs, 0, end, axis);
    }
}

static struct build_ref median3(const struct build_ref *a, const struct build_ref *b,
                                const struct build_ref *c, int axis)
{
    if (ref_less(a, b, axis)) {
        if (ref_less(b, c, axis))
            return *b;
        return ref_less(a, c, axis) ? *c : *a;
    }
    if (ref_less(a, c, axis))
        return *a;
    return ref_less(b, c, axis) ? *c : *b;
}

/* Ranges this short are finished by insertion sort (the usual cut-off of
 * introsort-style selections). */
#define MEDIAN_SELECT_INSERTION_MAX 16

/*
 * Introselect (Musser 1997): puts the element of rank nth at refs[nth],
 * none greater before it, none smaller after it.  Hoare partitions around
 * a median of three; heapsort once the partitions stop shrinking, so the
 * worst case is O(n log n).
 */
void build_select_nth(struct build_ref *refs, size_t n, size_t nth, int axis)
{
    size_t lo = 0;
    size_t hi = n; /* exclusive */
    int budget = 2 * (int)build_ceil_log2((uint32_t)n) + 2;
    while (hi - lo > MEDIAN_SELECT_INSERTION_MAX) {
        if (budget-- == 0) {
            heap_sort(refs + lo, hi - lo, axis);
            return;
        }
        size_t mid = lo + (hi - lo) / 2;
        struct build_ref pivot = median3(&refs[lo], &refs[mid], &refs[hi - 1], axis);
        /* The pivot value is inside the range, so both scans stop in it;
         * afterwards [lo, j] <= pivot <= [j + 1, hi). */
        size_t i = lo;
        size_t j = hi - 1;
        for (;;) {
            while (ref_less(&refs[i], &pivot, axis))
                i++;
            while (ref_less(&pivot, &refs[j], axis))
                j--;
            if (i >= j)
                break;
            swap_refs(refs, i, j);
            i++;
            j--;
        }
        if (nth <= j)
            hi = j + 1;
        else
            lo = j + 1;
    }
    for (size_t a = lo + 1; a < hi; a++) {
        struct build_ref x = refs[a];
        size_t b = a;
        while (b > lo && ref_less(&x, &refs[b - 1], axis)) {
            refs[b] = refs[b - 1];
            b--;
        }
        refs[b] = x;
    }
}
