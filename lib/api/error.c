/* SPDX-License-Identifier: Apache-2.0 */
/*
 * error.c - rt_error, rtGetError, rtErrorCallback and the shared checks.
 *
 * GL semantics (Mesa's _mesa_error): the first error is kept until
 * rtGetError reads it; every error reaches the callback; printing on
 * stderr is opt-in (TRACELIST_DEBUG) and collapses identical repeats.
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "api/context.h"

static const char *error_name(RTenum code)
{
    switch (code) {
    case RT_INVALID_ENUM:
        return "RT_INVALID_ENUM";
    case RT_INVALID_VALUE:
        return "RT_INVALID_VALUE";
    case RT_INVALID_OPERATION:
        return "RT_INVALID_OPERATION";
    case RT_STACK_OVERFLOW:
        return "RT_STACK_OVERFLOW";
    case RT_STACK_UNDERFLOW:
        return "RT_STACK_UNDERFLOW";
    case RT_OUT_OF_MEMORY:
        return "RT_OUT_OF_MEMORY";
    default:
        return "RT_UNKNOWN_ERROR";
    }
}

static void debug_print(struct rt_context *ctx, RTenum code, const char *message)
{
    char line[sizeof(ctx->last_message)];
    snprintf(line, sizeof(line), "%s: %s", error_name(code), message);
    if (strcmp(line, ctx->last_message) == 0) {
        ctx->repeat_count++;
        return;
    }
    if (ctx->repeat_count)
        fprintf(stderr, "tracelist: %u similar errors\n", ctx->repeat_count);
    ctx->repeat_count = 0;
    fprintf(stderr, "tracelist: %s\n", line);
    memcpy(ctx->last_message, line, sizeof(line));
}

void rt_error(struct rt_context *ctx, RTenum code, const char *fmt, ...)
{
    if (ctx->error == RT_NO_ERROR)
        ctx->error = code;
    if (!ctx->error_callback && !ctx->debug_print)
        return;
    char message[256];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(message, sizeof(message), fmt, ap);
    va_end(ap);
    if (ctx->debug_print)
        debug_print(ctx, code, message);
    if (ctx->error_callback)
        ctx->error_callback(code, message, ctx->error_user);
}

RTenum rtGetError(void)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx)
        return RT_NO_ERROR;
    RTenum e = ctx->error;
    ctx->error = RT_NO_ERROR;
    return e;
}

void rtErrorCallback(RTerrorcallback callback, void *user)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx)
        return;
    ctx->error_callback = callback;
    ctx->error_user = callback ? user : NULL;
}

/*
 * For layered libraries (rtu, as GLU relies on GL's error state): the
 * error is recorded as if `function` had failed, with the same rules as
 * any entry point: the first error sticks, the callback and
 * TRACELIST_DEBUG see "function: message".  Between rtBegin and rtEnd the
 * core's first check wins and RT_INVALID_OPERATION is recorded instead,
 * so a layered call checks in the same order as a core one.
 */
void rtRecordError(RTenum error, const char *function, const char *message)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx)
        return;
    switch (error) {
    case RT_INVALID_ENUM:
    case RT_INVALID_VALUE:
    case RT_INVALID_OPERATION:
    case RT_STACK_OVERFLOW:
    case RT_STACK_UNDERFLOW:
    case RT_OUT_OF_MEMORY:
        break;
    default:
        rt_error(ctx, RT_INVALID_ENUM, "rtRecordError(error=0x%x)", error);
        return;
    }
    if (function == NULL || function[0] == '\0') {
        rt_error(ctx, RT_INVALID_VALUE, "rtRecordError: function is NULL or empty");
        return;
    }
    if (rt_check_outside_begin(ctx, function))
        return;
    rt_error(ctx, error, "%s: %s", function, message != NULL ? message : error_name(error));
}

int rt_check_outside_begin(struct rt_context *ctx, const char *caller)
{
    if (!ctx->block.active)
        return 0;
    rt_error(ctx, RT_INVALID_OPERATION, "%s: not allowed between rtBegin and rtEnd", caller);
    return 1;
}

int rt_check_outside_object(struct rt_context *ctx, const char *caller)
{
    if (rt_check_outside_begin(ctx, caller))
        return 1;
    if (!ctx->recording.active)
        return 0;
    rt_error(ctx, RT_INVALID_OPERATION,
             "%s: not allowed between rtNewObject(%u) and rtEndObject", caller,
             ctx->recording.name);
    return 1;
}

int rt_check_finite(struct rt_context *ctx, const char *caller, const float *v, int n)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(v[i])) {
            rt_error(ctx, RT_INVALID_VALUE, "%s: argument %d is not finite (%g)", caller, i,
                     (double)v[i]);
            return 0;
        }
    return 1;
}

int rt_check_finite_d(struct rt_context *ctx, const char *caller, const double *v, int n)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(v[i])) {
            rt_error(ctx, RT_INVALID_VALUE, "%s: argument %d is not finite (%g)", caller, i,
                     v[i]);
            return 0;
        }
    return 1;
}
