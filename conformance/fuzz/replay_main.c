/* SPDX-License-Identifier: Apache-2.0 */
/*
 * replay_main.c - runs a libFuzzer target over files, without libFuzzer.
 *
 *   aff_fuzz_replay [--bart DIR] PATH...
 *
 * Calls LLVMFuzzerTestOneInput once on the contents of every PATH that is
 * a file and of every file below every PATH that is a directory (in name
 * order, recursively).  A PATH that does not exist is an error: a
 * misspelt corpus must not pass as an empty one.  --bart DIR adds the
 * BART folder (third-party data, read where it lies): $TRACELIST_BART_DIR
 * when set, else DIR, and only its files named *.aff; unlike a PATH it may
 * be absent, and is then skipped with a note.
 *
 * This is what the fuzz/aff_replay test runs in every build, with any
 * compiler and with or without the sanitizers: the corpus and the saved
 * regressions (conformance/fuzz/corpus, conformance/fuzz/regressions)
 * become ordinary tests.  Exit status 0 when every input ran, each within
 * REPLAY_TIMEOUT_SECONDS (libFuzzer's -timeout in run_fuzz.sh); an input
 * that makes the target crash or abort ends the process, and the file name
 * printed before it names the input.
 */
#include <dirent.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* Seconds one input may take: run_fuzz.sh's -timeout. */
#define REPLAY_TIMEOUT_SECONDS 10

struct replay {
    int aff_only; /* only files named *.aff (the BART folder holds textures) */
    long inputs;
};

static int ends_with(const char *s, const char *suffix)
{
    size_t n = strlen(s), m = strlen(suffix);
    return n >= m && strcmp(s + n - m, suffix) == 0;
}

static int run_file(struct replay *rp, const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        perror(path);
        return -1;
    }
    unsigned char *data = NULL;
    size_t size = 0, capacity = 0;
    for (;;) {
        if (size == capacity) {
            size_t grown = capacity ? 2 * capacity : 65536;
            unsigned char *p = realloc(data, grown);
            if (!p) {
                fprintf(stderr, "%s: out of memory\n", path);
                free(data);
                fclose(f);
                return -1;
            }
            data = p;
            capacity = grown;
        }
        size_t got = fread(data + size, 1, capacity - size, f);
        size += got;
        if (got == 0)
            break;
    }
    int failed = ferror(f);
    fclose(f);
    if (failed) {
        fprintf(stderr, "%s: read error\n", path);
        free(data);
        return -1;
    }
    printf("replay: %s (%zu bytes)\n", path, size);
    fflush(stdout);
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    LLVMFuzzerTestOneInput(data, size);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    free(data);
    rp->inputs++;
    /* The time bound libFuzzer enforces with -timeout (run_fuzz.sh): work
     * linear in the input, so every input we keep runs well within it. */
    double seconds = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    if (seconds > REPLAY_TIMEOUT_SECONDS) {
        fprintf(stderr, "%s: %.1f s, more than the %d s an input may take\n", path, seconds,
                REPLAY_TIMEOUT_SECONDS);
        return -1;
    }
    return 0;
}

static int compare_names(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

static int run_path(struct replay *rp, const char *path);

static int run_directory(struct replay *rp, const char *path)
{
    DIR *dir = opendir(path);
    if (!dir) {
        perror(path);
        return -1;
    }
    char **names = NULL;
    size_t count = 0, capacity = 0;
    int rc = 0;
    struct dirent *e;
    while (rc == 0 && (e = readdir(dir)) != NULL) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
            continue;
        if (count == capacity) {
            size_t grown = capacity ? 2 * capacity : 64;
            char **p = realloc(names, grown * sizeof *names);
            if (!p) {
                rc = -1;
                break;
            }
            names = p;
            capacity = grown;
        }
        size_t n = strlen(path) + strlen(e->d_name) + 2;
        if (!(names[count] = malloc(n))) {
            rc = -1;
            break;
        }
        snprintf(names[count], n, "%s/%s", path, e->d_name);
        count++;
    }
    closedir(dir);
    if (rc)
        fprintf(stderr, "%s: out of memory\n", path);
    else if (count)
        qsort(names, count, sizeof *names, compare_names);
    for (size_t i = 0; i < count; i++) {
        if (rc == 0)
            rc = run_path(rp, names[i]);
        free(names[i]);
    }
    free(names);
    return rc;
}

static int run_path(struct replay *rp, const char *path)
{
    struct stat st;
    if (stat(path, &st) != 0) {
        perror(path);
        return -1;
    }
    if (S_ISDIR(st.st_mode))
        return run_directory(rp, path);
    if (!S_ISREG(st.st_mode) || (rp->aff_only && !ends_with(path, ".aff")))
        return 0;
    return run_file(rp, path);
}

int main(int argc, char **argv)
{
    struct replay rp = {0, 0};
    int rc = 0;
    if (argc < 2) {
        fprintf(stderr, "usage: %s [--bart DIR] PATH...\n", argv[0]);
        return 2;
    }
    for (int i = 1; i < argc && rc == 0; i++) {
        if (strcmp(argv[i], "--bart") == 0) {
            if (i + 1 >= argc) {
                fprintf(stderr, "%s: --bart needs a directory\n", argv[0]);
                return 2;
            }
            const char *env = getenv("TRACELIST_BART_DIR");
            const char *given = argv[++i];
            const char *bart = env && env[0] ? env : given;
            struct stat st;
            if (stat(bart, &st) != 0 || !S_ISDIR(st.st_mode)) {
                printf("replay: no BART folder at '%s', skipped\n", bart);
                continue;
            }
            rp.aff_only = 1;
            rc = run_path(&rp, bart);
            rp.aff_only = 0;
        } else {
            rc = run_path(&rp, argv[i]);
        }
    }
    printf("replay: %ld inputs%s\n", rp.inputs, rc ? ", stopped by an error" : "");
    return rc ? 1 : 0;
}
