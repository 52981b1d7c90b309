/* SPDX-License-Identifier: Apache-2.0 */
/*
 * atomic.h - the two GNU extensions the library relies on, in one place.
 *
 * Tracelist is C99, which has neither atomics nor thread-local storage.
 * We use the GCC/Clang builtins (__atomic_*, the memory model of C11's
 * <stdatomic.h> with the same orderings) and __thread, both available in
 * every compiler we build with (gcc, clang); a compiler without them
 * stops here with a message instead of failing somewhere in the middle.
 * Porting to C11 means redefining these macros with <stdatomic.h> and
 * _Thread_local, nothing else.
 *
 * Every macro takes a pointer to a plain (non-_Atomic) object of integer
 * or pointer type.
 */
#ifndef RT_BASE_ATOMIC_H
#define RT_BASE_ATOMIC_H

#if !defined(__GNUC__) && !defined(__clang__)
#error "Tracelist needs the GCC/Clang __atomic builtins and __thread (see base/atomic.h)"
#endif

#define RT_THREAD_LOCAL __thread

#define rt_atomic_load_relaxed(p) __atomic_load_n((p), __ATOMIC_RELAXED)
#define rt_atomic_load_acquire(p) __atomic_load_n((p), __ATOMIC_ACQUIRE)
#define rt_atomic_store_relaxed(p, v) __atomic_store_n((p), (v), __ATOMIC_RELAXED)
#define rt_atomic_store_release(p, v) __atomic_store_n((p), (v), __ATOMIC_RELEASE)
#define rt_atomic_exchange_acq_rel(p, v) __atomic_exchange_n((p), (v), __ATOMIC_ACQ_REL)
/* Return the value before the addition (fetch_add) or after it (add_fetch). */
#define rt_atomic_fetch_add_relaxed(p, v) __atomic_fetch_add((p), (v), __ATOMIC_RELAXED)
#define rt_atomic_add_fetch_relaxed(p, v) __atomic_add_fetch((p), (v), __ATOMIC_RELAXED)
#define rt_atomic_add_fetch_acq_rel(p, v) __atomic_add_fetch((p), (v), __ATOMIC_ACQ_REL)
#define rt_atomic_sub_fetch_relaxed(p, v) __atomic_sub_fetch((p), (v), __ATOMIC_RELAXED)

#endif
