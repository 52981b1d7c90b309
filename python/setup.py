# SPDX-License-Identifier: Apache-2.0
"""Bundles libtracelist.so into the package when one is at hand.

The metadata is in pyproject.toml; this only extends build_py: when the
environment variable TRACELIST_LIBRARY names the library, or the checkout
has a CMake build (build/*/libtracelist.so, newest first), that file is
copied into the package, where tracelist finds it first after
TRACELIST_LIBRARY.  So `pip install ./python` after a CMake build gives a
package that works on its own; without a build, the package looks for the
library at import time (docs/python.md).
"""
import glob
import os
import shutil

from setuptools import setup
from setuptools.command.build_py import build_py


def _library():
    env = os.environ.get("TRACELIST_LIBRARY")
    if env and os.path.exists(env):
        return env
    checkout = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    builds = glob.glob(os.path.join(checkout, "build", "*", "libtracelist.so"))
    builds.sort(key=os.path.getmtime, reverse=True)
    return builds[0] if builds else None


class BuildPyWithLibrary(build_py):
    def run(self):
        super().run()
        library = _library()
        if library is None:
            print("tracelist: no libtracelist.so to bundle; it will be looked for at import")
            return
        target = os.path.join(self.build_lib, "tracelist", "libtracelist.so")
        shutil.copyfile(os.path.realpath(library), target)
        print("tracelist: bundled %s" % library)


setup(cmdclass={"build_py": BuildPyWithLibrary})
