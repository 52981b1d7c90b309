/* SPDX-License-Identifier: Apache-2.0 */
/*
 * check.c - the test harness every test uses (see check.h).
 *
 * Single-threaded by design: the pass/fail counters are plain globals.
 * Tests that start threads make their checks on the main thread.
 */
#include "check.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>

static int passes;
static int failures;
static const char *section = "";

void tu_report_failure(const char *file, int line)
{
    failures++;
    fprintf(stderr, "%s:%d: [%s] ", file, line, section);
}

int tu_check(int ok, const char *file, int line, const char *expr)
{
    if (ok) {
        passes++;
        return 1;
    }
    tu_report_failure(file, line);
    fprintf(stderr, "CHECK(%s) failed\n", expr);
    return 0;
}

int tu_check_int(long long actual, long long expected, const char *file, int line,
                 const char *actual_expr, const char *expected_expr)
{
    if (actual == expected) {
        passes++;
        return 1;
    }
    tu_report_failure(file, line);
    fprintf(stderr, "%s == %lld (0x%llx), expected %s == %lld (0x%llx)\n", actual_expr, actual,
            (unsigned long long)actual, expected_expr, expected, (unsigned long long)expected);
    return 0;
}

int tu_check_near(double actual, double expected, double tol, const char *file, int line,
                  const char *actual_expr, const char *expected_expr)
{
    /* Written so that NaN fails; exact equality covers matching infinities. */
    if (actual == expected || fabs(actual - expected) <= tol) {
        passes++;
        return 1;
    }
    tu_report_failure(file, line);
    fprintf(stderr, "%s == %.9g, expected %s == %.9g (tolerance %g)\n", actual_expr, actual,
            expected_expr, expected, tol);
    return 0;
}

int tu_check_msg(int ok, const char *file, int line, const char *expr, const char *fmt, ...)
{
    if (ok) {
        passes++;
        return 1;
    }
    tu_report_failure(file, line);
    fprintf(stderr, "CHECK(%s) failed: ", expr);
    va_list args;
    va_start(args, fmt);
    vfprintf(stderr, fmt, args);
    va_end(args);
    fputc('\n', stderr);
    return 0;
}

void tu_report_pass(void)
{
    passes++;
}

void tu_section(const char *name)
{
    section = name;
    printf("-- %s\n", name);
    fflush(stdout);
}

int test_summary(const char *name)
{
    printf("%s: %d passed, %d failed\n", name, passes, failures);
    fflush(stdout);
    return failures != 0;
}
