# SPDX-License-Identifier: Apache-2.0
"""Finding and loading libtracelist.so, and the ctypes prototypes.

The library is looked for, in this order:

1. the file named by the environment variable TRACELIST_LIBRARY;
2. beside this package (a wheel or an install that bundles it);
3. the CMake build tree of the checkout this package was imported from
   (build/*/libtracelist.so, newest first);
4. the system: the dynamic loader's search path, by soname, then
   ctypes.util.find_library("tracelist").

The first that loads wins; when none does, ImportError lists where it looked.
"""
import ctypes
import ctypes.util
import glob
import os

# The soname tracks the 0.x minor version (0.1 and 0.2 are incompatible).
SONAME = "libtracelist.so.0.1"


def _candidates():
    env = os.environ.get("TRACELIST_LIBRARY")
    if env:
        yield env, "TRACELIST_LIBRARY"
    here = os.path.dirname(os.path.abspath(__file__))
    for name in ("libtracelist.so", SONAME):
        yield os.path.join(here, name), "beside the package"
    checkout = os.path.dirname(os.path.dirname(here))
    builds = glob.glob(os.path.join(checkout, "build", "*", "libtracelist.so"))
    for path in sorted(builds, key=os.path.getmtime, reverse=True):
        yield path, "the build tree"
    yield SONAME, "the system loader path"
    found = ctypes.util.find_library("tracelist")
    if found:
        yield found, "ctypes.util.find_library"


def load():
    """Returns (CDLL, path) of the first library that loads."""
    tried = []
    for path, where in _candidates():
        if os.sep in path and not os.path.exists(path):
            tried.append("%s (%s): no such file" % (path, where))
            continue
        try:
            return ctypes.CDLL(path), path
        except OSError as error:
            tried.append("%s (%s): %s" % (path, where, error))
    raise ImportError(
        "tracelist: cannot load libtracelist.so; build it with CMake and set "
        "TRACELIST_LIBRARY to its path. Tried:\n  " + "\n  ".join(tried))


class RTray(ctypes.Structure):
    _fields_ = [("org", ctypes.c_float * 3), ("tmin", ctypes.c_float),
                ("dir", ctypes.c_float * 3), ("tmax", ctypes.c_float)]


class RThit(ctypes.Structure):
    _fields_ = [("t", ctypes.c_float), ("u", ctypes.c_float), ("v", ctypes.c_float),
                ("instance", ctypes.c_uint), ("object", ctypes.c_uint),
                ("primitive", ctypes.c_uint)]


_c = ctypes
_P = ctypes.c_void_p
_E = ctypes.c_uint  # RTenum
_PROTOTYPES = {
    # name: (restype, argtypes)
    "rtCreateContext": (_P, [_c.c_char_p]),
    "rtDestroyContext": (None, [_P]),
    "rtMakeCurrent": (_c.c_ubyte, [_P]),
    "rtGetCurrentContext": (_P, []),
    "rtGetError": (_E, []),
    "rtGetString": (_c.c_char_p, [_E]),
    "rtGetIntegerv": (None, [_E, _c.POINTER(_c.c_int)]),
    "rtGetFloatv": (None, [_E, _c.POINTER(_c.c_float)]),
    "rtEnable": (None, [_E]),
    "rtDisable": (None, [_E]),
    "rtGenObjects": (None, [_c.c_int, _c.POINTER(_c.c_uint)]),
    "rtNewObject": (None, [_c.c_uint]),
    "rtEndObject": (None, []),
    "rtDeleteObjects": (None, [_c.c_int, _c.POINTER(_c.c_uint)]),
    "rtIsObject": (_c.c_ubyte, [_c.c_uint]),
    "rtGetObjectiv": (None, [_c.c_uint, _E, _c.POINTER(_c.c_int)]),
    "rtObjectParameteri": (None, [_c.c_uint, _E, _c.c_int]),
    "rtUpdateVertices": (None, [_c.c_uint, _E, _c.c_int, _c.c_int, _E, _c.c_int, _P]),
    "rtEnableClientState": (None, [_E]),
    "rtDisableClientState": (None, [_E]),
    "rtVertexPointer": (None, [_c.c_int, _E, _c.c_int, _P]),
    "rtNormalPointer": (None, [_E, _c.c_int, _P]),
    "rtDrawElements": (None, [_E, _c.c_int, _E, _P]),
    "rtMaterialfv": (None, [_E, _E, _c.POINTER(_c.c_float)]),
    "rtLightfv": (None, [_E, _E, _c.POINTER(_c.c_float)]),
    "rtShadingMode": (None, [_E]),
    "rtMatrixMode": (None, [_E]),
    "rtLoadIdentity": (None, []),
    "rtLoadMatrixd": (None, [_c.POINTER(_c.c_double)]),
    "rtInstantiateObject": (None, [_c.c_uint]),
    "rtBeginFrame": (None, []),
    "rtFinish": (None, []),
    "rtViewport": (None, [_c.c_int, _c.c_int, _c.c_int, _c.c_int]),
    "rtClearColor": (None, [_c.c_float] * 4),
    "rtRenderFrame": (None, []),
    "rtReadPixels": (None, [_c.c_int, _c.c_int, _c.c_int, _c.c_int, _E, _E, _P]),
    "rtTraceRays": (None, [_c.c_int, _P, _P]),
    "rtOccludedRays": (None, [_c.c_int, _P, _P]),
}


def bind(lib):
    """Sets restype/argtypes of every entry point the package uses."""
    for name, (restype, argtypes) in _PROTOTYPES.items():
        function = getattr(lib, name)
        function.restype = restype
        function.argtypes = argtypes
    return lib
