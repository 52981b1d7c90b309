/* SPDX-License-Identifier: Apache-2.0 */
/*
 * walk_fiber.h - coroutines for walking several rays of a stream on one
 * thread, each ray's walk on a small stack of its own (stream_fiber.h).
 *
 * Why: a ray's walk over a layout beyond the L2 is a chain of dependent
 * loads (node -> child -> leaf packet), each a miss to the L3, and one
 * ray's walk (about 2000 instructions on the soup's random rays) is far
 * longer than the core's reorder buffer reaches, so consecutive rays do
 * not overlap their misses.  A walk that prefetches the lines it is about
 * to wait for and then switches to another ray's walk overlaps the two
 * chains ("asynchronous memory access chaining": Kocberber, Falsafi and
 * Grot 2015, VLDB 9(4); group and software-pipelined prefetching for
 * hash joins: Chen, Ailamaki, Gibbons and Mowry 2004).  Each walk stays
 * the walk it was, so its answers are the same by construction.
 *
 * The switch (trace_fiber_switch, walk_fiber.c) is a small x86-64
 * function: it pushes the six callee-saved registers of the System V
 * ABI, stores the stack pointer, loads the other coroutine's and pops
 * its registers.  Every vector register and every other general register
 * is the caller's to save across a call, so the walk spills around the
 * switch exactly what it spills around a leaf call; MXCSR and the x87
 * control word are the same in every coroutine of a thread.
 *
 * Only on x86-64 ELF with GCC or Clang (TRACE_FIBER 1), and not in
 * sanitizer builds: ASan and TSan would need fiber annotations
 * (__sanitizer_start_switch_fiber, __tsan_switch_to_fiber) to follow a
 * stack switch; there the stream entry is absent (kernels.h,
 * stream_fiber) and callers trace ray by ray.
 */
#ifndef RT_TRACE_WALK_FIBER_H
#define RT_TRACE_WALK_FIBER_H

#include <stdint.h>
#include <string.h>

#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) ||                       \
    __has_feature(memory_sanitizer)
#define TRACE_FIBER_SANITIZED 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define TRACE_FIBER_SANITIZED 1
#endif

#if defined(__GNUC__) && defined(__x86_64__) && defined(__ELF__) &&                              \
    !defined(TRACE_FIBER_SANITIZED)
#define TRACE_FIBER 1
#else
#define TRACE_FIBER 0
#endif

struct bvh4;

/* The layout size from which a stream of incoherent rays pays for its
 * yields (kernels.h, stream_fiber): a layout beyond the last-level
 * cache, whose walks wait for memory at most nodes and leaves.  On a
 * Zen 3 core (EPYC, 32 MB L3), four rays in flight against walk1 ray by
 * ray, ours/Embree (rtcIntersect1) on the random rays: bumpy (a 60 MB
 * layout) 0.92 -> 1.64; the kitchen (7 MB, about two nodes a ray) 0.84
 * -> 0.76, gears (0.1 MB) 0.9 -> 0.79, the soup (6.5 MB) level to +0.15
 * from quad to quad: where the lines come from the L3 or nearer, the
 * overlap gave about what the yields cost, or less
 * (docs/performance-log.md, round 60).  Coherent rays (a camera's, their
 * shadow rays) lost on every layout (bumpy's camera rays 0.91 -> 0.77):
 * consecutive rays share their lines already.  A heuristic only: the
 * answers do not depend on it. */
#define TRACE_STREAM_FIBER_BYTES ((uint64_t)32 << 20)

/* 1 when wide's nodes and packets take TRACE_STREAM_FIBER_BYTES or more. */
int trace_stream_fiber_pays(const struct bvh4 *wide);

#if TRACE_FIBER
/* A coroutine: its saved stack pointer while it is not running, and its
 * neighbours in the ring of live coroutines (a yield goes to next; a
 * coroutine that ends leaves the ring). */
struct trace_fiber {
    void *sp;
    struct trace_fiber *next;
    struct trace_fiber *prev;
    void *job; /* the caller's, for the coroutine's body */
};

/* Saves the callee-saved registers on the current stack and the stack
 * pointer in *save, then resumes the coroutine whose saved stack pointer
 * is to (walk_fiber.c). */
void trace_fiber_switch(void **save, void *to);
/* Where a new coroutine starts: calls r13 (its body) with r12 (its
 * struct trace_fiber) as the argument (walk_fiber.c). */
void trace_fiber_entry(void);

typedef void (*trace_fiber_body)(struct trace_fiber *f);

/* f ready to start body on the stack [stack, stack + size): the frame
 * trace_fiber_switch pops (r15, r14, r13 = body, r12 = f, rbx, rbp, the
 * return address trace_fiber_entry), placed so that trace_fiber_entry
 * starts with a 16-byte aligned stack pointer and body is called as the
 * ABI requires. */
static inline void trace_fiber_prepare(struct trace_fiber *f, void *stack, size_t size,
                                       trace_fiber_body body, void *job)
{
    const uintptr_t top = ((uintptr_t)stack + size) & ~(uintptr_t)15;
    void **sp = (void **)(top - 72);
    void (*entry)(void) = trace_fiber_entry;
    memset(sp, 0, 7 * sizeof(void *));
    memcpy(&sp[2], &body, sizeof(body));
    sp[3] = f;
    memcpy(&sp[6], &entry, sizeof(entry));
    f->sp = sp;
    f->job = job;
}

/* The next live coroutine, or nothing when f is the last one (a switch
 * to itself would read its stack pointer before storing it). */
static inline void trace_fiber_yield(struct trace_fiber *f)
{
    struct trace_fiber *const n = f->next;
    if (n != f)
        trace_fiber_switch(&f->sp, n->sp);
}

/* f's body is done: f leaves the ring and the next live coroutine runs,
 * or the caller that started the ring (*caller_sp) when f was the last.
 * Never returns. */
#if defined(__GNUC__)
__attribute__((noreturn))
#endif
static inline void trace_fiber_exit(struct trace_fiber *f, void *caller_sp)
{
    void *dead;
    if (f->next == f) {
        trace_fiber_switch(&dead, caller_sp);
    } else {
        f->prev->next = f->next;
        f->next->prev = f->prev;
        trace_fiber_switch(&dead, f->next->sp);
    }
    __builtin_unreachable();
}
#endif

#endif
