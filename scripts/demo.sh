#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# One command from a fresh Debian machine to a rendered image: installs the
# packages it can, builds the gears demo (only it and the libraries), and
# renders one frame of its built-in scene.  Writes gears.png (gears.ppm in
# a build without OpenImageIO) in the current directory and ends by
# printing its absolute path; with a display it then opens a window
# (q or Esc quits).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/install-deps.sh" || echo "demo.sh: install-deps.sh failed; continuing with what is installed"
cmake -S "$root" -B "$root/build/release" -DCMAKE_BUILD_TYPE=Release
cmake --build "$root/build/release" -j"$(nproc)" --target gears
gears="$root/build/release/demos/gears/gears"
out="gears.png"
if ! "$gears" --info | grep -q "image formats:.*png"; then
  out="gears.ppm"
fi
"$gears" --headless --frames 1 --out "$out" >/dev/null
if [ -n "${DISPLAY:-}" ]; then
  "$gears"
fi
echo "demo.sh: the image is $(pwd)/$out"
