# SPDX-License-Identifier: Apache-2.0
"""Tracelist from Python: an OpenGL-like immediate-mode ray tracer over numpy.

    import numpy as np
    import tracelist

    with tracelist.Context("threads=4") as ctx:
        mesh = ctx.mesh(vertices, triangles)          # (V, 3) floats, (T, 3) ints
        ctx.instance(mesh)                            # identity placement
        ctx.instance(mesh, tracelist.translate(2, 0, 0))
        hits = ctx.trace_rays(origins, directions)    # structured array, one per ray
        hits["t"], hits["instance"], hits["object"], hits["primitive"], hits["u"], hits["v"]
        blocked = ctx.occluded_rays(origins, directions, tmax=1.0)
        image = ctx.render(640, 480, eye=(0, 1, 5), center=(0, 0, 0))   # (480, 640, 4) uint8

Rays and hits cross the C boundary as whole numpy arrays: one ctypes call
per batch, no Python work per ray.  The GIL is released while the library
traces (ctypes does so for every call), and the library uses its own
threads.  docs/python.md in the repository has the full description.
"""
import ctypes

import numpy as np

from . import _lib

__version__ = "0.1.0"
__all__ = [
    "Context", "TracelistError", "library", "library_path", "version", "RAY_DTYPE",
    "HIT_DTYPE", "INVALID_ID", "pack_rays", "translate", "scale", "rotate", "perspective",
    "look_at",
]

# ---------------------------------------------------------------- constants
INVALID_ID = 0xFFFFFFFF
_RT_NO_ERROR = 0
_ERROR_NAMES = {
    0x0500: "RT_INVALID_ENUM", 0x0501: "RT_INVALID_VALUE", 0x0502: "RT_INVALID_OPERATION",
    0x0503: "RT_STACK_OVERFLOW", 0x0504: "RT_STACK_UNDERFLOW", 0x0505: "RT_OUT_OF_MEMORY",
}
_RT_UNSIGNED_BYTE = 0x1401
_RT_UNSIGNED_INT = 0x1405
_RT_FLOAT = 0x1406
_RT_TRIANGLES = 0x0004
_RT_MODELVIEW = 0x1700
_RT_PROJECTION = 0x1701
_RT_VERSION = 0x1F02
_RT_RENDERER = 0x1F01
_RT_CONFIGURATION = 0x8F00
_RT_VERTEX_ARRAY = 0x8074
_RT_NORMAL_ARRAY = 0x8075
_RT_FRONT_AND_BACK = 0x0408
_RT_AMBIENT_AND_DIFFUSE = 0x1602
_RT_DIFFUSE = 0x1201
_RT_POSITION = 0x1203
_RT_LIGHT0 = 0x4000
_RT_RGBA = 0x1908
_RT_EYE_LIGHT = 0x8F21
_RT_WHITTED = 0x8F22
_RT_INSTANCE_COUNT = 0x8F33
_RT_OBJECT_TRIANGLES = 0x8F50
_RT_OBJECT_CLASS = 0x8F56
_RT_UNSTRUCTURED = 0x8F63

# RTray and RThit, as numpy dtypes with the C layout (checked at import).
RAY_DTYPE = np.dtype([("org", "<f4", (3,)), ("tmin", "<f4"), ("dir", "<f4", (3,)),
                      ("tmax", "<f4")])
HIT_DTYPE = np.dtype([("t", "<f4"), ("u", "<f4"), ("v", "<f4"), ("instance", "<u4"),
                      ("object", "<u4"), ("primitive", "<u4")])
assert RAY_DTYPE.itemsize == ctypes.sizeof(_lib.RTray)
assert HIT_DTYPE.itemsize == ctypes.sizeof(_lib.RThit)

library, library_path = _lib.load()
_lib.bind(library)
_L = library
# The largest batch handed to one call (RTsizei is a C int).
_MAX_BATCH = 1 << 30


class TracelistError(RuntimeError):
    """An error the library recorded (rtGetError), with its code and name."""

    def __init__(self, code, during):
        self.code = code
        self.name = _ERROR_NAMES.get(code, "0x%04X" % code)
        super().__init__("%s during %s" % (self.name, during))


def _ptr(array):
    return array.ctypes.data_as(ctypes.c_void_p)


# ---------------------------------------------------------------- matrices
def translate(x, y, z):
    """4x4 translation matrix (row-major numpy, acting on column vectors)."""
    m = np.eye(4)
    m[:3, 3] = (x, y, z)
    return m


def scale(x, y=None, z=None):
    """4x4 scale matrix; one argument scales uniformly."""
    y = x if y is None else y
    z = x if z is None else z
    return np.diag([x, y, z, 1.0])


def rotate(degrees, axis):
    """4x4 rotation by `degrees` about `axis` (as rtRotated / glRotated)."""
    axis = np.asarray(axis, dtype=np.float64)
    x, y, z = axis / np.linalg.norm(axis)
    c, s = np.cos(np.radians(degrees)), np.sin(np.radians(degrees))
    m = np.eye(4)
    m[:3, :3] = [[x * x * (1 - c) + c, x * y * (1 - c) - z * s, x * z * (1 - c) + y * s],
                 [y * x * (1 - c) + z * s, y * y * (1 - c) + c, y * z * (1 - c) - x * s],
                 [x * z * (1 - c) - y * s, y * z * (1 - c) + x * s, z * z * (1 - c) + c]]
    return m


def perspective(fovy, aspect, near, far):
    """The gluPerspective matrix (fovy in degrees)."""
    if not (0 < fovy < 180 and aspect > 0 and 0 < near < far):
        raise ValueError("perspective needs 0 < fovy < 180, aspect > 0, 0 < near < far")
    f = 1.0 / np.tan(np.radians(fovy) / 2.0)
    m = np.zeros((4, 4))
    m[0, 0] = f / aspect
    m[1, 1] = f
    m[2, 2] = (far + near) / (near - far)
    m[2, 3] = 2.0 * far * near / (near - far)
    m[3, 2] = -1.0
    return m


def look_at(eye, center, up=(0.0, 1.0, 0.0)):
    """The gluLookAt matrix."""
    eye, center, up = (np.asarray(v, dtype=np.float64) for v in (eye, center, up))
    forward = center - eye
    if not np.linalg.norm(forward) > 0:
        raise ValueError("look_at needs eye != center")
    forward /= np.linalg.norm(forward)
    side = np.cross(forward, up)
    if not np.linalg.norm(side) > 1e-12:
        raise ValueError("look_at: up is parallel to the view direction")
    side /= np.linalg.norm(side)
    true_up = np.cross(side, forward)
    m = np.eye(4)
    m[0, :3], m[1, :3], m[2, :3] = side, true_up, -forward
    return m @ translate(*(-eye))


def _column_major(matrix):
    m = np.asarray(matrix, dtype=np.float64)
    if m.shape != (4, 4):
        raise ValueError("a matrix must be 4x4, got shape %s" % (m.shape,))
    if not np.all(np.isfinite(m)):
        raise ValueError("the matrix has non-finite elements")
    return np.ascontiguousarray(m.T)  # element (r, c) at c*4 + r, as rt.h wants


# ---------------------------------------------------------------- rays
def pack_rays(origins, directions, tmin=0.0, tmax=np.inf):
    """Packs rays into a RAY_DTYPE array (the C layout of RTray).

    origins and directions are (N, 3) arrays, or one of them a single
    (3,) point or vector broadcast over the other; tmin and tmax are
    scalars or (N,) arrays.  Directions need not be normalised: t is
    measured in units of the direction.
    """
    o = np.atleast_2d(np.asarray(origins, dtype=np.float32))
    d = np.atleast_2d(np.asarray(directions, dtype=np.float32))
    if o.ndim != 2 or d.ndim != 2 or o.shape[1] != 3 or d.shape[1] != 3:
        raise ValueError("origins and directions must be (N, 3) or (3,)")
    o, d = np.broadcast_arrays(o, d)
    rays = np.empty(o.shape[0], dtype=RAY_DTYPE)
    rays["org"] = o
    rays["dir"] = d
    rays["tmin"] = tmin
    rays["tmax"] = tmax
    return rays


def _as_rays(rays_or_origins, directions, tmin, tmax):
    if directions is None:
        rays = np.asarray(rays_or_origins)
        if rays.dtype == RAY_DTYPE:
            return np.ascontiguousarray(rays)
        if rays.ndim == 2 and rays.shape[1] == 8:
            return np.ascontiguousarray(rays, dtype=np.float32).view(RAY_DTYPE).reshape(-1)
        raise ValueError("rays must be a RAY_DTYPE array, an (N, 8) float array, or "
                         "origins and directions")
    return pack_rays(rays_or_origins, directions, tmin, tmax)


# ---------------------------------------------------------------- context
class Context:
    """A Tracelist context (rtCreateContext), current on the calling thread.

    Every method makes the context current first, so several contexts can
    be used from one thread; a context must not be used from two threads
    at once.  After each call the library's error flag is read and a
    recorded error raises TracelistError.
    """

    def __init__(self, configuration=""):
        self._handle = _L.rtCreateContext(configuration.encode())
        if not self._handle:
            raise TracelistError(0x0501, "rtCreateContext(%r)" % configuration)
        self._current()
        self._next_name = 1

    # -- lifetime
    def close(self):
        """Destroys the context (rtDestroyContext); further use raises."""
        if self._handle:
            _L.rtDestroyContext(self._handle)
            self._handle = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        try:
            self.close()
        except Exception:  # interpreter shutdown: the library may be gone
            pass

    def _current(self):
        if not self._handle:
            raise ValueError("the context was closed")
        if _L.rtGetCurrentContext() != self._handle:
            _L.rtMakeCurrent(self._handle)

    def _check(self, during):
        code = _L.rtGetError()
        if code != _RT_NO_ERROR:
            raise TracelistError(code, during)

    # -- state
    def get_string(self, name):
        self._current()
        value = _L.rtGetString(name)
        return value.decode() if value is not None else None

    @property
    def version(self):
        return self.get_string(_RT_VERSION)

    @property
    def renderer(self):
        return self.get_string(_RT_RENDERER)

    @property
    def configuration(self):
        return self.get_string(_RT_CONFIGURATION)

    def get_integer(self, pname):
        self._current()
        value = ctypes.c_int(0)
        _L.rtGetIntegerv(pname, ctypes.byref(value))
        self._check("rtGetIntegerv")
        return value.value

    @property
    def instance_count(self):
        return self.get_integer(_RT_INSTANCE_COUNT)

    # -- objects
    def mesh(self, vertices, triangles, normals=None, color=None, name=None, dynamic=False):
        """Records a triangle mesh as a new object and returns its name.

        vertices: (V, 3) floats; triangles: (T, 3) vertex indices; normals:
        optional (V, 3) per-vertex normals; color: optional RGB(A) material
        colour.  dynamic=True hints that the vertices will change every
        frame (update_vertices), so the object's tree is refitted rather
        than rebuilt.  The arrays are copied by the library.
        """
        self._current()
        v = np.ascontiguousarray(vertices, dtype=np.float32)
        t = np.ascontiguousarray(triangles, dtype=np.uint32)
        if v.ndim != 2 or v.shape[1] != 3:
            raise ValueError("vertices must be (V, 3), got %s" % (v.shape,))
        if t.ndim != 2 or t.shape[1] != 3:
            raise ValueError("triangles must be (T, 3), got %s" % (t.shape,))
        if t.size and int(t.max()) >= v.shape[0]:
            raise ValueError("a triangle index is >= the number of vertices (%d)" % v.shape[0])
        if name is None:
            name = self._next_free_name()
        _L.rtNewObject(name)
        if color is not None:
            rgba = np.ones(4, dtype=np.float32)
            rgba[:len(color)] = color
            _L.rtMaterialfv(_RT_FRONT_AND_BACK, _RT_AMBIENT_AND_DIFFUSE,
                            rgba.ctypes.data_as(ctypes.POINTER(ctypes.c_float)))
        _L.rtEnableClientState(_RT_VERTEX_ARRAY)
        _L.rtVertexPointer(3, _RT_FLOAT, 0, _ptr(v))
        n = None
        if normals is not None:
            n = np.ascontiguousarray(normals, dtype=np.float32)
            if n.shape != v.shape:
                raise ValueError("normals must have the shape of vertices")
            _L.rtEnableClientState(_RT_NORMAL_ARRAY)
            _L.rtNormalPointer(_RT_FLOAT, 0, _ptr(n))
        _L.rtDrawElements(_RT_TRIANGLES, t.size, _RT_UNSIGNED_INT, _ptr(t))
        _L.rtDisableClientState(_RT_VERTEX_ARRAY)
        _L.rtDisableClientState(_RT_NORMAL_ARRAY)
        _L.rtEndObject()
        self._check("recording mesh %d" % name)
        if dynamic:
            _L.rtObjectParameteri(name, _RT_OBJECT_CLASS, _RT_UNSTRUCTURED)
            self._check("rtObjectParameteri")
        return name

    def _next_free_name(self):
        names = (ctypes.c_uint * 1)()
        _L.rtGenObjects(1, names)
        self._check("rtGenObjects")
        return names[0]

    def update_vertices(self, name, vertices, first=0):
        """Replaces vertex positions of a mesh in place (rtUpdateVertices)."""
        self._current()
        v = np.ascontiguousarray(vertices, dtype=np.float32).reshape(-1, 3)
        _L.rtUpdateVertices(name, _RT_VERTEX_ARRAY, first, v.shape[0], _RT_FLOAT, 0, _ptr(v))
        self._check("rtUpdateVertices(%d)" % name)

    def triangles(self, name):
        """Triangle count of an object."""
        self._current()
        value = ctypes.c_int(0)
        _L.rtGetObjectiv(name, _RT_OBJECT_TRIANGLES, ctypes.byref(value))
        self._check("rtGetObjectiv")
        return value.value

    def delete(self, name):
        self._current()
        names = (ctypes.c_uint * 1)(name)
        _L.rtDeleteObjects(1, names)
        self._check("rtDeleteObjects")

    # -- the scene
    def begin_frame(self):
        """Starts a new, empty instance list (rtBeginFrame)."""
        self._current()
        _L.rtBeginFrame()
        self._check("rtBeginFrame")

    def instance(self, name, matrix=None):
        """Places object `name` under a 4x4 matrix (default identity).

        Returns the instance's id (its position in the frame's list), which
        hits report in their "instance" field.
        """
        self._current()
        _L.rtMatrixMode(_RT_MODELVIEW)
        if matrix is None:
            _L.rtLoadIdentity()
        else:
            m = _column_major(matrix)
            _L.rtLoadMatrixd(m.ctypes.data_as(ctypes.POINTER(ctypes.c_double)))
        _L.rtInstantiateObject(name)
        self._check("rtInstantiateObject(%d)" % name)
        return self.instance_count - 1

    # -- ray queries
    def trace_rays(self, rays_or_origins, directions=None, tmin=0.0, tmax=np.inf):
        """Closest hits (rtTraceRays) of a batch of rays.

        Either a RAY_DTYPE / (N, 8) array of rays, or origins and
        directions (see pack_rays).  Returns a HIT_DTYPE array: t (inf on
        a miss), u, v (barycentrics of the 2nd and 3rd vertex), instance,
        object, primitive (INVALID_ID on a miss).
        """
        self._current()
        rays = _as_rays(rays_or_origins, directions, tmin, tmax)
        hits = np.empty(rays.shape[0], dtype=HIT_DTYPE)
        for start in range(0, rays.shape[0], _MAX_BATCH):
            chunk = slice(start, min(start + _MAX_BATCH, rays.shape[0]))
            _L.rtTraceRays(chunk.stop - chunk.start, _ptr(rays[chunk]), _ptr(hits[chunk]))
        self._check("rtTraceRays")
        return hits

    def occluded_rays(self, rays_or_origins, directions=None, tmin=0.0, tmax=np.inf):
        """Whether anything blocks each ray in [tmin, tmax] (rtOccludedRays): a bool array."""
        self._current()
        rays = _as_rays(rays_or_origins, directions, tmin, tmax)
        out = np.empty(rays.shape[0], dtype=np.uint8)
        for start in range(0, rays.shape[0], _MAX_BATCH):
            chunk = slice(start, min(start + _MAX_BATCH, rays.shape[0]))
            _L.rtOccludedRays(chunk.stop - chunk.start, _ptr(rays[chunk]), _ptr(out[chunk]))
        self._check("rtOccludedRays")
        return out.astype(bool)

    # -- rendering
    def light(self, index, position, color=(1.0, 1.0, 1.0)):
        """Sets and enables light `index` (RT_LIGHT0 + index), in world space.

        position: (x, y, z, w), w = 0 for a directional light.
        """
        self._current()
        _L.rtMatrixMode(_RT_MODELVIEW)
        _L.rtLoadIdentity()
        p = np.asarray(position, dtype=np.float32).reshape(4)
        c = np.ones(4, dtype=np.float32)
        c[:len(color)] = color
        fp = ctypes.POINTER(ctypes.c_float)
        _L.rtLightfv(_RT_LIGHT0 + index, _RT_POSITION, p.ctypes.data_as(fp))
        _L.rtLightfv(_RT_LIGHT0 + index, _RT_DIFFUSE, c.ctypes.data_as(fp))
        _L.rtEnable(_RT_LIGHT0 + index)
        self._check("rtLightfv")

    def render(self, width, height, eye=(0.0, 0.0, 5.0), center=(0.0, 0.0, 0.0),
               up=(0.0, 1.0, 0.0), fovy=45.0, near=0.01, far=1000.0, shading="eye",
               background=(0.0, 0.0, 0.0, 1.0)):
        """Renders the scene (rtRenderFrame) and returns a (height, width, 4)
        uint8 RGBA image, row 0 at the top (as image files store it).

        The camera looks from `eye` at `center`; shading is "eye" (a
        headlight, no shadows) or "whitted" (the lights set with light(),
        shadows, reflections).  Rendering ends the frame: the next
        instance() starts a new list, and until then queries and renders
        see this scene.
        """
        self._current()
        if shading not in ("eye", "whitted"):
            raise ValueError("shading must be 'eye' or 'whitted'")
        projection = perspective(fovy, width / float(height), near, far) @ look_at(eye, center, up)
        m = _column_major(projection)
        _L.rtViewport(0, 0, width, height)
        _L.rtMatrixMode(_RT_PROJECTION)
        _L.rtLoadMatrixd(m.ctypes.data_as(ctypes.POINTER(ctypes.c_double)))
        _L.rtMatrixMode(_RT_MODELVIEW)
        _L.rtShadingMode(_RT_EYE_LIGHT if shading == "eye" else _RT_WHITTED)
        _L.rtClearColor(*[float(c) for c in background])
        _L.rtRenderFrame()
        image = np.empty((height, width, 4), dtype=np.uint8)
        _L.rtReadPixels(0, 0, width, height, _RT_RGBA, _RT_UNSIGNED_BYTE, _ptr(image))
        self._check("rtRenderFrame")
        return image[::-1].copy()  # rtReadPixels rows run bottom to top


def version():
    """The library's version string (rtGetString(RT_VERSION)) of a scratch context."""
    with Context("threads=1") as ctx:
        return ctx.version
