#!/usr/bin/env bash
# Installs the Debian packages Tracelist builds, tests and demos with.
# Only the compiler, CMake and pthreads are required; everything else is
# optional and switched off by CMake when absent.  Safe to run repeatedly.
set -euo pipefail

packages=(
  build-essential cmake pkg-config git        # required
  libopenimageio-dev                          # rtu: PNG/EXR/JPEG image I/O
  libglfw3-dev                                # demos: windows
  libembree-dev                               # rtbench: comparison only
  xvfb xauth                                  # window tests without a display
  gnuplot-nox                                 # rtbench: PNG plots
  clang libclang-rt-dev                       # test.sh fuzz suite: libFuzzer runtime
  libosmesa6-dev libglu1-mesa-dev             # tests: the OpenGL oracle (Mesa's GL and GLU)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all packages present"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
echo "install-deps: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
