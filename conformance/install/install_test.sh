#!/usr/bin/env bash
# Installs the build tree into a scratch prefix, then configures, builds and
# runs an outside consumer with find_package(Tracelist), and compiles it
# once more with the flags pkg-config gives.
# Usage: install_test.sh BUILD_DIR SOURCE_DIR SCRATCH_DIR
set -euo pipefail
build="$1" src="$2" scratch="$3"
rm -rf "$scratch"
mkdir -p "$scratch"
prefix="$scratch/prefix"
cmake --install "$build" --prefix "$prefix" >"$scratch/install.log"
cmake -S "$src" -B "$scratch/consumer" -DCMAKE_PREFIX_PATH="$prefix" >"$scratch/configure.log"
cmake --build "$scratch/consumer" >"$scratch/build.log"
libdir="$(dirname "$(find "$prefix" -name 'libtracelist.so*' | head -n 1)")"
LD_LIBRARY_PATH="$libdir" "$scratch/consumer/consumer"
if command -v pkg-config >/dev/null; then
  export PKG_CONFIG_PATH="$libdir/pkgconfig"
  # shellcheck disable=SC2046
  cc -std=c99 "$src/consumer.c" -o "$scratch/consumer-pc" $(pkg-config --cflags --libs tracelist)
  LD_LIBRARY_PATH="$libdir" "$scratch/consumer-pc"
fi
