/* SPDX-License-Identifier: Apache-2.0 */
/*
 * walk_fiber.c - the coroutine switch of walk_fiber.h, x86-64 System V:
 * rbx, rbp and r12-r15 are the callee-saved general registers; the
 * vector registers are all the caller's.  Hidden symbols, as every
 * internal name of the library.
 */
#include "trace/walk_fiber.h"

#include "trace/bvh4_layout.h"

int trace_stream_fiber_pays(const struct bvh4 *wide)
{
    return bvh4_node_bytes(wide) + bvh4_leaf_bytes(wide) >= TRACE_STREAM_FIBER_BYTES;
}

#if TRACE_FIBER
__asm__(".text\n"
        ".p2align 4\n"
        ".globl trace_fiber_switch\n"
        ".hidden trace_fiber_switch\n"
        ".type trace_fiber_switch, @function\n"
        "trace_fiber_switch:\n"
        "    pushq %rbp\n"
        "    pushq %rbx\n"
        "    pushq %r12\n"
        "    pushq %r13\n"
        "    pushq %r14\n"
        "    pushq %r15\n"
        "    movq %rsp, (%rdi)\n"
        "    movq %rsi, %rsp\n"
        "    popq %r15\n"
        "    popq %r14\n"
        "    popq %r13\n"
        "    popq %r12\n"
        "    popq %rbx\n"
        "    popq %rbp\n"
        "    ret\n"
        ".size trace_fiber_switch, .-trace_fiber_switch\n"
        "\n"
        ".p2align 4\n"
        ".globl trace_fiber_entry\n"
        ".hidden trace_fiber_entry\n"
        ".type trace_fiber_entry, @function\n"
        "trace_fiber_entry:\n"
        "    movq %r12, %rdi\n"
        "    callq *%r13\n"
        "    ud2\n"
        ".size trace_fiber_entry, .-trace_fiber_entry\n");
#endif
