/* SPDX-License-Identifier: Apache-2.0 */
/*
 * check.h - the one test harness: the API tests (through testutil.h) and
 * the module tests of conformance/internal use the same checks.
 *
 * A failing check prints "file:line: [section] ..." to stderr and the
 * program carries on, so one run shows every failure; each check returns
 * 1 when it passed and 0 when it failed, so a test can also count its own
 * (failures += !CHECKF(...)).  test_summary prints "name: N passed, M
 * failed" and returns non-zero when any check failed.  No dependency on
 * the library, so tests of its internals link it with the static objects.
 */
#ifndef RT_CONFORMANCE_CHECK_H
#define RT_CONFORMANCE_CHECK_H

int tu_check(int ok, const char *file, int line, const char *expr);
int tu_check_int(long long actual, long long expected, const char *file, int line,
                 const char *actual_expr, const char *expected_expr);
int tu_check_near(double actual, double expected, double tol, const char *file, int line,
                  const char *actual_expr, const char *expected_expr);

/* CHECK(expr): expr must be true. */
#define CHECK(expr) tu_check((expr) != 0, __FILE__, __LINE__, #expr)
/* CHECK_INT(actual, expected): integer equality, both values printed. */
#define CHECK_INT(actual, expected)                                                           \
    tu_check_int((long long)(actual), (long long)(expected), __FILE__, __LINE__, #actual,     \
                 #expected)
/* CHECK_NEAR(actual, expected, tol): |actual - expected| <= tol (NaN fails). */
#define CHECK_NEAR(actual, expected, tol)                                                     \
    tu_check_near((double)(actual), (double)(expected), (double)(tol), __FILE__, __LINE__,    \
                  #actual, #expected)
/* CHECKF(cond, fmt, ...): cond must be true; on failure also prints the
 * printf-style message (the values a bare expression would not show). */
int tu_check_msg(int ok, const char *file, int line, const char *expr, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 5, 6)))
#endif
    ;
#define CHECKF(cond, ...) tu_check_msg((cond) != 0, __FILE__, __LINE__, #cond, __VA_ARGS__)

/* For checks written elsewhere (testutil.c): count a pass, or report a
 * failure's "file:line: [section] " prefix (the caller prints the rest). */
void tu_report_pass(void);
void tu_report_failure(const char *file, int line);

/* Names the group of checks that follows in failure messages and on stdout. */
void tu_section(const char *name);

/* Prints "name: N passed, M failed" and returns 0 when nothing failed, 1 otherwise. */
int test_summary(const char *name);

#endif
