#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs the Debian packages Tracelist builds, tests and demos with, in
# two groups:
#   library   what building the libraries needs: a C99 compiler, CMake,
#             pthreads (libc).  Nothing else is required.
#   extras    optional: image formats, windows, benchmark comparison, man
#             pages, and what the demos, tests and benchmarks use.  CMake
#             switches each off with a message when it is absent.
# Safe to run repeatedly.  Without root or sudo it installs nothing, says
# exactly which packages are missing and what each group is for, and exits
# non-zero only when a package the library needs is missing.
set -euo pipefail

library=(
  build-essential cmake                       # C99 compiler, make, CMake
)
extras=(
  pkg-config git                              # finding OpenImageIO; rtbench's commit id
  libopenimageio-dev                          # rtu: PNG/EXR/JPEG image I/O
  libglfw3-dev                                # demos: windows
  libembree-dev                               # rtbench: comparison only
  pandoc man-db                               # man(3) pages from docs/*.md; `man rtNewObject`
  xvfb xauth                                  # window tests without a display
  gnuplot-nox                                 # rtbench: PNG plots
  clang libclang-rt-dev                       # test.sh fuzz suite: libFuzzer runtime
  python3 python3-venv python3-pip            # the Python package (python/) and its tests
  python3-numpy python3-pytest
  libosmesa6-dev libglu1-mesa-dev             # tests: the OpenGL oracle (Mesa's GL and GLU)
)

missing_of() { # prints the packages of the list that are not installed
  local p
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || echo "$p"
  done
}

if ! command -v dpkg-query >/dev/null; then
  echo "install-deps: not a Debian system; install by hand: a C99 compiler and CMake >= 3.16" \
       "(library), and optionally ${extras[*]}" >&2
  exit 0
fi
mapfile -t missing_library < <(missing_of "${library[@]}")
mapfile -t missing_extras < <(missing_of "${extras[@]}")
missing=("${missing_library[@]}" "${missing_extras[@]}")
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all packages present"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  if ! command -v sudo >/dev/null || ! sudo -n true 2>/dev/null; then
    echo "install-deps: not root and no password-less sudo: installed nothing." >&2
    if [ ${#missing_library[@]} -gt 0 ]; then
      echo "install-deps: MISSING for building the library: ${missing_library[*]}" >&2
    fi
    if [ ${#missing_extras[@]} -gt 0 ]; then
      echo "install-deps: missing optional packages (demos, tests, benchmarks, man pages;" \
           "switched off or skipped): ${missing_extras[*]}" >&2
    fi
    echo "install-deps: as root: apt-get install ${missing[*]}" >&2
    [ ${#missing_library[@]} -eq 0 ]
    exit
  fi
  sudo="sudo"
fi
echo "install-deps: installing ${missing[*]}"
$sudo apt-get update -qq
# One package that is not in this release's archive must not stop the
# others: try them all together, then one by one.
if ! DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends \
     "${missing[@]}"; then
  for p in "${missing[@]}"; do
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "$p" ||
      echo "install-deps: could not install $p" >&2
  done
fi
still_missing=$(missing_of "${library[@]}")
if [ -n "$still_missing" ]; then
  echo "install-deps: MISSING for building the library: $still_missing" >&2
  exit 1
fi
