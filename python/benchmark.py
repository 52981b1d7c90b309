#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Rays per second from Python against the C API, on the same rays.

Builds a bumpy sphere mesh and a batch of camera-like rays in numpy,
traces them with tracelist.Context.trace_rays (two ways: from origins and
directions, which packs them first, and from prepacked RAY_DTYPE rays),
then hands the very same mesh and rays to bench/trace_rays_file, which
calls rtTraceRays from C, and checks that both got the same hits.

    python3 python/benchmark.py [--rays N] [--runs R] [--threads T] [--c-bench PATH]

Reports best-of-R rays/s; the first call (which builds the BVH) is not
timed on either side.  docs/python.md lists measured numbers.
"""
import argparse
import glob
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
import tracelist as tl  # noqa: E402


def bumpy_sphere(n_theta=256, n_phi=512):
    theta = np.linspace(0.0, np.pi, n_theta + 1)
    phi = np.linspace(0.0, 2.0 * np.pi, n_phi + 1)
    t, p = np.meshgrid(theta, phi, indexing="ij")
    r = 1.0 + 0.05 * np.sin(8 * t) * np.cos(12 * p)
    vertices = np.stack([r * np.sin(t) * np.cos(p), r * np.cos(t), r * np.sin(t) * np.sin(p)],
                        axis=-1).reshape(-1, 3).astype(np.float32)
    a = (np.arange(n_phi)[None, :] + (n_phi + 1) * np.arange(n_theta)[:, None]).ravel()
    b, c, d = a + 1, a + n_phi + 1, a + n_phi + 2
    triangles = np.concatenate([np.stack([a, b, d], 1), np.stack([a, d, c], 1)])
    return vertices, triangles.astype(np.uint32)


def camera_rays(n, seed=3):
    """n rays from a camera at z = 3 through random pixels of a 40 degree view."""
    rng = np.random.default_rng(seed)
    xy = rng.uniform(-0.36, 0.36, (n, 2))
    directions = np.c_[xy, -np.ones(n)]
    return tl.pack_rays([0.0, 0.0, 3.0], directions)


def best_of(runs, f):
    best = float("inf")
    result = None
    for _ in range(runs):
        t0 = time.perf_counter()
        result = f()
        best = min(best, time.perf_counter() - t0)
    return best, result


def find_c_bench(path):
    if path:
        return path
    root = os.path.dirname(here)
    found = sorted(glob.glob(os.path.join(root, "build", "*", "bench", "trace_rays_file")),
                   key=os.path.getmtime, reverse=True)
    if not found:
        sys.exit("benchmark: bench/trace_rays_file not built; build the CMake target "
                 "trace_rays_file or pass --c-bench")
    return found[0]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--rays", type=int, default=1_000_000)
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--threads", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--c-bench", default=None)
    args = parser.parse_args()

    vertices, triangles = bumpy_sphere()
    rays = camera_rays(args.rays)
    origins, directions = rays["org"].copy(), rays["dir"].copy()
    print("library: %s" % tl.library_path)
    print("mesh: %d triangles; rays: %d; threads: %d; best of %d runs"
          % (len(triangles), len(rays), args.threads, args.runs))

    with tl.Context("threads=%d" % args.threads) as ctx:
        ctx.instance(ctx.mesh(vertices, triangles))
        ctx.trace_rays(rays)  # builds the BVH: not timed
        packed_s, hits = best_of(args.runs, lambda: ctx.trace_rays(rays))
        unpacked_s, hits2 = best_of(args.runs, lambda: ctx.trace_rays(origins, directions))
    assert np.array_equal(hits, hits2)

    with tempfile.TemporaryDirectory() as scratch:
        data = os.path.join(scratch, "input.bin")
        out = os.path.join(scratch, "hits.bin")
        with open(data, "wb") as f:
            np.array([len(vertices), len(triangles), len(rays)], dtype=np.int32).tofile(f)
            vertices.tofile(f)
            triangles.tofile(f)
            rays.tofile(f)
        result = subprocess.run([find_c_bench(args.c_bench), data, out, str(args.runs),
                                 str(args.threads)], check=True, capture_output=True, text=True)
        c_rate = float(result.stdout.split()[-1])
        c_hits = np.fromfile(out, dtype=tl.HIT_DTYPE)
    same = np.array_equal(c_hits, hits)
    # What the binding adds per call, without tracing: packing the rays
    # (only for origins + directions) and allocating the hit array.
    pack_s, _ = best_of(args.runs, lambda: (tl.pack_rays(origins, directions),
                                             np.empty(len(rays), dtype=tl.HIT_DTYPE)))
    hit_rate = np.mean(np.isfinite(hits["t"]))

    print("hits: %.1f%% of rays; Python and C hits identical: %s" % (100 * hit_rate, same))
    print("%-44s %14s %8s" % ("", "rays/s", "vs C"))
    print("%-44s %14.0f %8s" % ("C: rtTraceRays", c_rate, "1.00"))
    for label, seconds in (("Python: trace_rays(packed RAY_DTYPE rays)", packed_s),
                           ("Python: trace_rays(origins, directions)", unpacked_s)):
        rate = len(rays) / seconds
        print("%-44s %14.0f %8.2f" % (label, rate, rate / c_rate))
    print("binding work without tracing (pack_rays + hit array): %.1f ms per %d rays "
          "= %.0f ns per ray" % (1e3 * pack_s, len(rays), 1e9 * pack_s / len(rays)))
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
