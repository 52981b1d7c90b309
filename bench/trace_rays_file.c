/* SPDX-License-Identifier: Apache-2.0 */
/*
 * trace_rays_file - the C side of the Python binding's benchmark
 * (python/benchmark.py, docs/python.md): the same mesh and the same rays,
 * traced with rtTraceRays from C, so the two rays/s figures differ only by
 * what the binding adds.
 *
 * Usage: trace_rays_file INPUT HITS_OUT RUNS THREADS
 *   INPUT: int32 V, T, N; V*3 float32 vertices; T*3 uint32 indices; N RTray
 *   (8 float32 each), as python/benchmark.py writes it.  The mesh is one
 *   object, instanced once under the identity; the first call (which builds
 *   the BVH) is not timed.  Prints "c_rays_per_second <best of RUNS>" and
 *   writes the hits (N RThit) to HITS_OUT for the script to compare.
 * Uses the public API only (it links the shared library).
 */
#include <rt/rt.h>

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static int read_all(FILE *f, void *data, size_t size, size_t count)
{
    return fread(data, size, count, f) == count;
}

int main(int argc, char **argv)
{
    if (argc != 5) {
        fprintf(stderr, "usage: trace_rays_file INPUT HITS_OUT RUNS THREADS\n");
        return 2;
    }
    int runs = atoi(argv[3]), threads = atoi(argv[4]);
    FILE *in = fopen(argv[1], "rb");
    int32_t header[3];
    if (in == NULL || !read_all(in, header, sizeof header[0], 3) || header[0] <= 0 ||
        header[1] <= 0 || header[2] <= 0 || runs < 1 || threads < 1) {
        fprintf(stderr, "trace_rays_file: cannot read %s (or bad RUNS/THREADS)\n", argv[1]);
        return 1;
    }
    size_t nv = (size_t)header[0], nt = (size_t)header[1], nr = (size_t)header[2];
    float *vertices = malloc(nv * 3 * sizeof *vertices);
    uint32_t *indices = malloc(nt * 3 * sizeof *indices);
    RTray *rays = malloc(nr * sizeof *rays);
    RThit *hits = malloc(nr * sizeof *hits);
    if (!vertices || !indices || !rays || !hits || !read_all(in, vertices, sizeof(float), nv * 3) ||
        !read_all(in, indices, sizeof(uint32_t), nt * 3) || !read_all(in, rays, sizeof *rays, nr)) {
        fprintf(stderr, "trace_rays_file: %s is truncated or memory ran out\n", argv[1]);
        return 1;
    }
    fclose(in);

    char config[64];
    snprintf(config, sizeof config, "threads=%d", threads);
    RTcontext ctx = rtCreateContext(config);
    if (ctx == NULL || !rtMakeCurrent(ctx))
        return 1;
    rtNewObject(1);
    rtEnableClientState(RT_VERTEX_ARRAY);
    rtVertexPointer(3, RT_FLOAT, 0, vertices);
    rtDrawElements(RT_TRIANGLES, (RTsizei)(nt * 3), RT_UNSIGNED_INT, indices);
    rtDisableClientState(RT_VERTEX_ARRAY);
    rtEndObject();
    rtInstantiateObject(1);
    rtTraceRays((RTsizei)nr, rays, hits); /* builds the BVHs: not timed */
    double best = 1e30;
    for (int r = 0; r < runs; r++) {
        double t0 = now();
        rtTraceRays((RTsizei)nr, rays, hits);
        double dt = now() - t0;
        if (dt < best)
            best = dt;
    }
    if (rtGetError() != RT_NO_ERROR) {
        fprintf(stderr, "trace_rays_file: Tracelist error\n");
        return 1;
    }
    FILE *out = fopen(argv[2], "wb");
    if (out == NULL || fwrite(hits, sizeof *hits, nr, out) != nr) {
        fprintf(stderr, "trace_rays_file: cannot write %s\n", argv[2]);
        return 1;
    }
    fclose(out);
    printf("c_rays_per_second %.0f\n", (double)nr / best);
    rtDestroyContext(ctx);
    free(vertices);
    free(indices);
    free(rays);
    free(hits);
    return 0;
}
