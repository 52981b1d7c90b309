#!/usr/bin/env bash
# One command from a fresh Debian machine to a rendered image: installs the
# packages, builds Tracelist, and runs the gears demo on its built-in scene.
# Writes gears.png (gears.ppm without OpenImageIO) in the current
# directory; with a display it also opens a window (Esc quits).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/install-deps.sh"
cmake -S "$root" -B "$root/build/release" -DCMAKE_BUILD_TYPE=Release
cmake --build "$root/build/release" -j"$(nproc)"
gears="$root/build/release/demos/gears/gears"
"$gears" --headless --frames 1 --out gears.png
if [ -n "${DISPLAY:-}" ]; then
  "$gears"
fi
