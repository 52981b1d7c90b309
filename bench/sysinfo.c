/* SPDX-License-Identifier: Apache-2.0 */
/*
 * sysinfo.c - what the report header says about the machine and the build
 * (bench.h).  Linux first (/proc), with "unknown" wherever a source is
 * missing; nothing here fails.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "bench.h"

#ifndef RT_BENCH_BUILD_TYPE
#define RT_BENCH_BUILD_TYPE ""
#endif

static void trim(char *s)
{
    size_t n = strlen(s);
    while (n > 0 && (s[n - 1] == '\n' || s[n - 1] == '\r' || s[n - 1] == ' ' || s[n - 1] == '\t'))
        s[--n] = '\0';
}

void sysinfo_cpu(char *buf, size_t size)
{
    char line[512];
    snprintf(buf, size, "unknown CPU");
    FILE *f = fopen("/proc/cpuinfo", "r");
    if (!f)
        return;
    while (fgets(line, sizeof(line), f)) {
        if (strncmp(line, "model name", 10) != 0)
            continue;
        const char *colon = strchr(line, ':');
        if (!colon)
            continue;
        colon++;
        while (*colon == ' ' || *colon == '\t')
            colon++;
        snprintf(buf, size, "%s", colon);
        trim(buf);
        break;
    }
    fclose(f);
}

int sysinfo_cores(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n < 1 ? 1 : (int)n;
}

const char *sysinfo_loadavg(void)
{
    static char buf[64];
    double a, b, c;
    snprintf(buf, sizeof(buf), "unknown");
    FILE *f = fopen("/proc/loadavg", "r");
    if (!f)
        return buf;
    if (fscanf(f, "%lf %lf %lf", &a, &b, &c) == 3)
        snprintf(buf, sizeof(buf), "%.2f %.2f %.2f (1, 5, 15 min)", a, b, c);
    fclose(f);
    return buf;
}

void sysinfo_date(char *buf, size_t size)
{
    time_t now = time(NULL);
    struct tm tm;
    if (!gmtime_r(&now, &tm) || !strftime(buf, size, "%Y-%m-%d %H:%M UTC", &tm))
        snprintf(buf, size, "unknown");
}

void sysinfo_compiler(char *buf, size_t size)
{
#if defined(__clang__)
    snprintf(buf, size, "clang %s", __clang_version__);
#elif defined(__GNUC__)
    snprintf(buf, size, "gcc %s", __VERSION__);
#else
    snprintf(buf, size, "unknown compiler");
#endif
    trim(buf);
#ifdef RT_BENCH_C_FLAGS
    size_t n = strlen(buf);
    if (RT_BENCH_C_FLAGS[0])
        snprintf(buf + n, size - n, ", flags `%s`", RT_BENCH_C_FLAGS);
#endif
}

/* First line of a shell command's output; 0 on success. */
static int command_line_output(const char *cmd, char *buf, size_t size)
{
    FILE *p = popen(cmd, "r");
    if (!p)
        return -1;
    buf[0] = '\0';
    int got = fgets(buf, (int)size, p) != NULL;
    int status = pclose(p);
    trim(buf);
    return got && status == 0 && buf[0] ? 0 : -1;
}

void sysinfo_commit(char *buf, size_t size)
{
    char cmd[4096 + 128], out[128];
    /* Ask git about the source tree rtbench was built from; the directory
     * goes only into the command, never into the report. */
    snprintf(cmd, sizeof(cmd), "git -C '%s' rev-parse --short HEAD 2>/dev/null",
             RT_BENCH_SOURCE_DIR);
    if (strchr(RT_BENCH_SOURCE_DIR, '\'') || command_line_output(cmd, out, sizeof(out))) {
        snprintf(buf, size, "unknown");
        return;
    }
    snprintf(cmd, sizeof(cmd), "git -C '%s' status --porcelain 2>/dev/null | head -n 1",
             RT_BENCH_SOURCE_DIR);
    char dirty[256];
    int is_dirty = command_line_output(cmd, dirty, sizeof(dirty)) == 0;
    snprintf(buf, size, "%s%s", out, is_dirty ? " (with uncommitted changes)" : "");
}

void sysinfo_command(char *buf, size_t size, int argc, char **argv)
{
    size_t n = 0;
    buf[0] = '\0';
    for (int i = 0; i < argc && n + 1 < size; i++) {
        const char *arg = argv[i];
        const char *elided = "";
        const char *slash = strrchr(arg, '/');
        /* The program's directory goes; other absolute paths keep only
         * their last component, marked as shortened. */
        if (i == 0 && slash) {
            arg = slash + 1;
        } else if (arg[0] == '/' && slash && slash[1]) {
            arg = slash + 1;
            elided = ".../";
        }
        int w = snprintf(buf + n, size - n, "%s%s%s", i ? " " : "", elided, arg);
        if (w < 0)
            break;
        n += (size_t)w;
    }
}

int sysinfo_have_program(const char *name)
{
    const char *path = getenv("PATH");
    char candidate[4096];
    while (path && *path) {
        const char *end = strchr(path, ':');
        size_t len = end ? (size_t)(end - path) : strlen(path);
        if (len > 0 && len + strlen(name) + 2 < sizeof(candidate)) {
            memcpy(candidate, path, len);
            candidate[len] = '/';
            strcpy(candidate + len + 1, name);
            if (access(candidate, X_OK) == 0)
                return 1;
        }
        if (!end)
            break;
        path = end + 1;
    }
    return 0;
}
