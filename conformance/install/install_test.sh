#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs the build tree into a scratch prefix, then builds and runs
# outside consumers the three ways users build them, all WITHOUT
# LD_LIBRARY_PATH (the loader must find the libraries by runpath):
#   1. CMake find_package(Tracelist) against the prefix;
#   2. pkg-config (tracelist, tracelist-rtu) with the documented rpath;
#   3. CMake add_subdirectory of the source tree (a subproject build that
#      must not build tests, demos or benchmarks).
# Each builds a consumer of rt + rtu and one that calls only rtu.  When
# pandoc made the man pages, `man rtNewObject` must work from the prefix.
# Usage: install_test.sh BUILD_DIR CONSUMER_SOURCE_DIR SCRATCH_DIR TRACELIST_SOURCE_DIR
set -euo pipefail
build="$1" src="$2" scratch="$3" tracelist_src="$4"
unset LD_LIBRARY_PATH
rm -rf "$scratch"
mkdir -p "$scratch"
prefix="$scratch/prefix"
cmake --install "$build" --prefix "$prefix" >"$scratch/install.log"
libdir="$(dirname "$(find "$prefix" -name 'libtracelist.so' | head -n 1)")"

run() { # run NAME PROGRAM: a failure names the way it was built
  echo "install_test: $1"
  "$2" || { echo "install_test: FAILED: $1" >&2; exit 1; }
}

# The soname tracks the 0.x minor version; rtu carries $ORIGIN.
if command -v readelf >/dev/null; then
  readelf -d "$libdir/libtracelist.so" | grep -q 'SONAME.*libtracelist\.so\.0\.[0-9]*\]' ||
    { echo "install_test: soname is not libtracelist.so.0.MINOR" >&2; exit 1; }
  readelf -d "$libdir/libtracelist_rtu.so" | grep -q 'R\(UN\)\?PATH.*\$ORIGIN' ||
    { echo "install_test: libtracelist_rtu has no \$ORIGIN runpath" >&2; exit 1; }
fi
grep -q '#define RT_VERSION_MAJOR' "$prefix/include/rt/rt_version.h"

# 1. find_package
cmake -S "$src" -B "$scratch/package" -DCMAKE_PREFIX_PATH="$prefix" >"$scratch/package.log"
cmake --build "$scratch/package" >>"$scratch/package.log"
run "find_package consumer" "$scratch/package/consumer"
run "find_package consumer_rtu_only" "$scratch/package/consumer_rtu_only"

# 2. pkg-config, with the rpath docs/install.md documents
if command -v pkg-config >/dev/null; then
  export PKG_CONFIG_PATH="$libdir/pkgconfig"
  rpath="-Wl,-rpath,$(pkg-config --variable=libdir tracelist)"
  # shellcheck disable=SC2046
  cc -std=c99 "$src/consumer.c" -o "$scratch/consumer-pc" \
    $(pkg-config --cflags --libs tracelist-rtu) "$rpath"
  run "pkg-config consumer" "$scratch/consumer-pc"
  # shellcheck disable=SC2046
  cc -std=c99 "$src/consumer_rtu_only.c" -o "$scratch/consumer-rtu-pc" \
    $(pkg-config --cflags --libs tracelist-rtu) "$rpath"
  run "pkg-config consumer_rtu_only" "$scratch/consumer-rtu-pc"
fi

# 3. add_subdirectory.  Debug: this checks how the subproject is wired,
# not its speed, and -O0 compiles the library in about a third of
# Release's CPU time (14 s against 39 s), the longest part of this test.
cmake -S "$src" -B "$scratch/subdirectory" -DRT_CONSUME=subdirectory \
  -DRT_SOURCE_DIR="$tracelist_src" -DCMAKE_BUILD_TYPE=Debug >"$scratch/subdirectory.log"
cmake --build "$scratch/subdirectory" -j2 >>"$scratch/subdirectory.log"
run "add_subdirectory consumer" "$scratch/subdirectory/consumer"
run "add_subdirectory consumer_rtu_only" "$scratch/subdirectory/consumer_rtu_only"

# The man pages, when this build generated them.
if [ -d "$build/man/man3" ]; then
  test -f "$prefix/share/man/man3/rtNewObject.3"
  if command -v man >/dev/null; then
    MANPATH="$prefix/share/man" man -P cat rtNewObject 2>/dev/null | grep -q "rtNewObject" ||
      { echo "install_test: 'man rtNewObject' does not work from the prefix" >&2; exit 1; }
    echo "install_test: man rtNewObject"
  else
    echo "install_test: man not installed; checked the page files only"
  fi
fi
echo "install_test: all consumers ok"
