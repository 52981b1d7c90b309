# SPDX-License-Identifier: Apache-2.0
"""pytest: the Python binding against the shared library (docs/python.md)."""
import numpy as np
import pytest

import tracelist as tl


def grid_mesh(n=8, z=0.0):
    """An n x n grid of quads (2 n^2 triangles) over [-1, 1]^2 at height z."""
    xs = np.linspace(-1.0, 1.0, n + 1)
    gx, gy = np.meshgrid(xs, xs)
    vertices = np.stack([gx.ravel(), gy.ravel(), np.full(gx.size, z)], axis=1)
    a = (np.arange(n)[None, :] + (n + 1) * np.arange(n)[:, None]).ravel()
    b, c, d = a + 1, a + n + 1, a + n + 2
    triangles = np.concatenate([np.stack([a, b, d], 1), np.stack([a, d, c], 1)])
    return vertices, triangles


def brute_force(vertices, triangles, origins, directions):
    """Closest t per ray, Moller-Trumbore over every triangle, in numpy."""
    v0, v1, v2 = (vertices[triangles[:, k]][None] for k in range(3))
    o, d = origins[:, None], directions[:, None]
    e1, e2 = v1 - v0, v2 - v0
    p = np.cross(d, e2)
    det = np.sum(e1 * p, -1)
    with np.errstate(divide="ignore", invalid="ignore"):
        inv = 1.0 / det
        s = o - v0
        u = np.sum(s * p, -1) * inv
        q = np.cross(s, e1)
        v = np.sum(d * q, -1) * inv
        t = np.sum(e2 * q, -1) * inv
        ok = (np.abs(det) > 1e-12) & (u >= 0) & (v >= 0) & (u + v <= 1) & (t >= 0)
    return np.where(ok, t, np.inf).min(axis=1)


@pytest.fixture
def ctx():
    with tl.Context("threads=2") as context:
        yield context


def test_library_and_version():
    assert tl.library_path
    assert tl.version().startswith(tl.__version__)


def test_context_strings(ctx):
    assert "Tracelist" in ctx.renderer
    assert "threads=2" in ctx.configuration


def test_trace_single_triangle(ctx):
    tri = ctx.mesh([[-1, -1, 0], [1, -1, 0], [0, 1, 0]], [[0, 1, 2]])
    ctx.instance(tri, tl.translate(0, 0, -5))
    hits = ctx.trace_rays(np.zeros((3, 3)), [[0, 0, -1], [0, 0, -2], [0, 0, 1]])
    assert hits.dtype == tl.HIT_DTYPE
    np.testing.assert_allclose(hits["t"][:2], [5.0, 2.5], rtol=1e-6)
    assert np.isinf(hits["t"][2])
    assert list(hits["object"]) == [tri, tri, tl.INVALID_ID]
    assert list(hits["primitive"][:2]) == [0, 0]
    # p = (1-u-v) v0 + u v1 + v v2 at the origin's projection (0, 0).
    np.testing.assert_allclose([hits["u"][0], hits["v"][0]], [0.25, 0.5], atol=1e-6)


def test_occluded_respects_tmax(ctx):
    tri = ctx.mesh([[-1, -1, -5], [1, -1, -5], [0, 1, -5]], [[0, 1, 2]])
    ctx.instance(tri)
    blocked = ctx.occluded_rays([0, 0, 0], [[0, 0, -1], [0, 0, -1], [0, 0, 1]],
                                tmax=np.array([10.0, 4.0, 10.0], dtype=np.float32))
    assert blocked.dtype == bool
    assert list(blocked) == [True, False, False]


def test_matches_brute_force(ctx):
    rng = np.random.default_rng(7)
    vertices = rng.uniform(-1, 1, (60, 3)).astype(np.float32)
    triangles = rng.integers(0, 60, (40, 3))
    obj = ctx.mesh(vertices, triangles)
    ctx.instance(obj)
    origins = rng.uniform(-2, 2, (2000, 3)).astype(np.float32)
    targets = rng.uniform(-0.5, 0.5, (2000, 3)).astype(np.float32)
    directions = targets - origins
    hits = ctx.trace_rays(origins, directions)
    expected = brute_force(vertices.astype(np.float64), triangles, origins.astype(np.float64),
                           directions.astype(np.float64))
    both = np.isfinite(expected) & np.isfinite(hits["t"])
    # Watertight vs Moller-Trumbore may disagree only on razor-edge rays.
    assert np.mean(np.isfinite(expected) == np.isfinite(hits["t"])) > 0.995
    np.testing.assert_allclose(hits["t"][both], expected[both], rtol=1e-4, atol=1e-5)


def test_instances_and_ids(ctx):
    vertices, triangles = grid_mesh(4)
    plane = ctx.mesh(vertices, triangles)
    assert ctx.triangles(plane) == 2 * 4 * 4
    ids = [ctx.instance(plane, tl.translate(3.0 * k, 0, -2.0 - k)) for k in range(4)]
    assert ids == [0, 1, 2, 3]
    origins = np.array([[3.0 * k + 0.1, 0.1, 0.0] for k in range(4)], dtype=np.float32)
    hits = ctx.trace_rays(origins, [0, 0, -1])
    assert list(hits["instance"]) == ids
    np.testing.assert_allclose(hits["t"], [2.0, 3.0, 4.0, 5.0], rtol=1e-6)
    # A rotated, scaled instance: t is in units of the world direction.
    ctx.begin_frame()
    ctx.instance(plane, tl.translate(0, 0, -4) @ tl.rotate(90, (0, 1, 0)) @ tl.scale(2.0))
    hit = ctx.trace_rays([[-5.0, 0.2, -4.1]], [[1.0, 0, 0]])
    assert hit["instance"][0] == 0
    np.testing.assert_allclose(hit["t"], [5.0], rtol=1e-5)


def test_packed_rays_and_large_batch(ctx):
    vertices, triangles = grid_mesh(16)
    ctx.instance(ctx.mesh(vertices, triangles), tl.translate(0, 0, -1))
    n = 200_000
    rng = np.random.default_rng(1)
    rays = tl.pack_rays(np.c_[rng.uniform(-1.5, 1.5, (n, 2)), np.zeros(n)], [0, 0, -1])
    hits = ctx.trace_rays(rays)
    inside = (np.abs(rays["org"][:, 0]) < 1) & (np.abs(rays["org"][:, 1]) < 1)
    assert np.array_equal(np.isfinite(hits["t"]), inside)
    # (N, 8) float32 works the same.
    raw = rays.view(np.float32).reshape(n, 8)
    assert np.array_equal(ctx.trace_rays(raw)["t"], hits["t"])


def test_update_vertices(ctx):
    vertices, triangles = grid_mesh(4)
    plane = ctx.mesh(vertices, triangles, dynamic=True)
    ctx.instance(plane)
    assert ctx.trace_rays([[0.1, 0.1, 5]], [[0, 0, -1]])["t"][0] == pytest.approx(5.0)
    moved = vertices.copy()
    moved[:, 2] = -1.0
    ctx.update_vertices(plane, moved)
    ctx.begin_frame()
    ctx.instance(plane)
    assert ctx.trace_rays([[0.1, 0.1, 5]], [[0, 0, -1]])["t"][0] == pytest.approx(6.0)


def test_render_to_numpy(ctx):
    vertices, triangles = grid_mesh(8)
    ctx.instance(ctx.mesh(vertices, triangles, color=(1.0, 0.2, 0.2)))
    ctx.light(0, (0, 0, 1, 0))
    image = ctx.render(64, 48, eye=(0, 0, 3), center=(0, 0, 0), shading="whitted",
                       background=(0, 0, 1, 1))
    assert image.shape == (48, 64, 4) and image.dtype == np.uint8
    centre, corner = image[24, 32], image[0, 0]
    assert centre[0] > 150 and centre[0] > centre[2]      # the red plane
    assert corner[2] == 255 and corner[0] == 0            # the blue background
    # Row 0 is the top: a plane moved up shows in the upper rows.
    ctx.instance(ctx.mesh(vertices * [0.5, 0.2, 1], triangles), tl.translate(0, 0.8, 0))
    up = ctx.render(64, 48, eye=(0, 0, 3), center=(0, 0, 0), background=(0, 0, 0, 1))
    rows = np.nonzero(up[:, 32, 0] > 0)[0]
    assert rows.max() < 24


def test_errors_raise(ctx):
    with pytest.raises(ValueError):
        ctx.mesh(np.zeros((3, 2)), [[0, 1, 2]])
    with pytest.raises(ValueError):
        ctx.mesh(np.zeros((3, 3)), [[0, 1, 3]])
    with pytest.raises(tl.TracelistError) as error:
        ctx.update_vertices(12345, np.zeros((3, 3)))
    assert error.value.name.startswith("RT_INVALID")
    with pytest.raises(ValueError):
        ctx.instance(1, np.eye(3))


def test_closed_context_refuses():
    ctx = tl.Context()
    ctx.close()
    with pytest.raises(ValueError):
        ctx.trace_rays([[0, 0, 0]], [[0, 0, 1]])
