/* SPDX-License-Identifier: Apache-2.0 */
/*
 * aff_file.c - the files an AFF scene names, opened under the loader's
 * file policy (aff_internal.h, docs/aff.md "Files and resource limits").
 *
 * A scene file is data from elsewhere: its includes and texture names must
 * not be a way to read, or to block on, arbitrary files of the machine
 * (`i 0 ../../../../dev/zero` was read whole until memory ran out).  So a
 * name is resolved with realpath (symbolic links and ".." followed) and,
 * unless the caller allows any directory, must lie inside the top file's
 * directory tree; it is opened with O_NONBLOCK, so a FIFO cannot block the
 * open, and must then be a regular file (no FIFO, device or directory) of
 * at most the size limit, checked with fstat on the open descriptor before
 * a byte is read.
 */
/* realpath is XSI: the build's _POSIX_C_SOURCE alone does not declare it. */
#define _XOPEN_SOURCE 700

#include "rtu/aff_internal.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#ifndef O_CLOEXEC
#define O_CLOEXEC 0
#endif
#ifndef O_NOCTTY
#define O_NOCTTY 0
#endif

void aff_limits_default(struct aff_limits *l)
{
    memset(l, 0, sizeof *l);
    l->max_file_bytes = AFF_DEFAULT_MAX_FILE_BYTES;
}

static int why_fail(char *why, size_t size, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

static int why_fail(char *why, size_t size, const char *fmt, ...)
{
    va_list args;
    va_start(args, fmt);
    if (size)
        vsnprintf(why, size, fmt, args);
    va_end(args);
    return -1;
}

char *aff_file_root(const char *directory)
{
    return realpath(directory && directory[0] ? directory : ".", NULL);
}

/* 1 when `resolved` is `root` itself or lies below it. */
static int inside(const char *resolved, const char *root)
{
    size_t n = strlen(root);
    if (n == 1 && root[0] == '/')
        return resolved[0] == '/';
    return strncmp(resolved, root, n) == 0 && (resolved[n] == '/' || resolved[n] == '\0');
}

int aff_file_open(const char *path, const char *root, uint64_t max_bytes, struct aff_file *f,
                  char *why, size_t why_size)
{
    memset(f, 0, sizeof *f);
    f->fd = -1;
    const char *open_path = path;
    char *resolved = NULL;
    if (root) {
        resolved = realpath(path, NULL);
        if (!resolved)
            return why_fail(why, why_size, "%s", strerror(errno));
        if (!inside(resolved, root)) {
            free(resolved);
            return why_fail(why, why_size,
                            "outside the scene's directory tree (RTU_AFF_ANY_DIRECTORY "
                            "allows it)");
        }
        open_path = resolved;
    }
    int fd = open(open_path, O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    int open_errno = errno;
    free(resolved);
    if (fd < 0)
        return why_fail(why, why_size, "%s", strerror(open_errno));
    struct stat st;
    if (fstat(fd, &st) != 0) {
        int e = errno;
        close(fd);
        return why_fail(why, why_size, "%s", strerror(e));
    }
    if (!S_ISREG(st.st_mode)) {
        close(fd);
        return why_fail(why, why_size, "not a regular file");
    }
    if ((uint64_t)st.st_size > max_bytes || (uint64_t)st.st_size > (uint64_t)SIZE_MAX / 2) {
        close(fd);
        return why_fail(why, why_size, "%llu bytes, more than the limit of %llu per file",
                        (unsigned long long)st.st_size, (unsigned long long)max_bytes);
    }
    f->fd = fd;
    f->size = (uint64_t)st.st_size;
    f->device = (uint64_t)st.st_dev;
    f->inode = (uint64_t)st.st_ino;
    return 0;
}

char *aff_file_read(struct aff_file *f, size_t *length, int *oom)
{
    *oom = 0;
    /* The size fstat gave: a file that grows meanwhile is read up to it,
     * one that shrinks up to its end. */
    size_t want = (size_t)f->size, got = 0;
    char *text = malloc(want ? want : 1);
    if (!text) {
        *oom = 1;
        return NULL;
    }
    while (got < want) {
        ssize_t n = read(f->fd, text + got, want - got);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0) {
            free(text);
            return NULL;
        }
        if (n == 0)
            break;
        got += (size_t)n;
    }
    *length = got;
    return text;
}

void aff_file_close(struct aff_file *f)
{
    if (f->fd >= 0)
        close(f->fd);
    f->fd = -1;
}

int aff_file_check(const char *path, const char *root, uint64_t max_bytes, char *why,
                   size_t why_size)
{
    struct aff_file f;
    if (aff_file_open(path, root, max_bytes, &f, why, why_size))
        return -1;
    aff_file_close(&f);
    return 0;
}
