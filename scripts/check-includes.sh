#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Checks that every #include "dir/file" under lib/ points down the layers
# docs/architecture.md draws, and fails (exit 1, listing each offending
# line) when one points up or sideways:
#
#   api -> scene -> accel -> trace -> base      (a layer may skip layers)
#   render -> scene, trace, base
#   dist -> render, scene, trace, base          (the MPI backend, later)
#   rtu -> rtu only (and <rt/...>, the public headers)
#
# Includes in angle brackets (<rt/rt.h>, system headers) and includes of
# a file in the same directory ("aff_anim.h") are not layer crossings.
# Usage: scripts/check-includes.sh [ROOT]   (ROOT defaults to the checkout)
set -euo pipefail
root="${1:-$(cd "$(dirname "$0")/.." && pwd)}"

allowed() {
  case "$1" in
    api) echo "api scene accel trace base render" ;;
    scene) echo "scene accel trace base" ;;
    accel) echo "accel trace base" ;;
    trace) echo "trace base" ;;
    base) echo "base" ;;
    render) echo "render scene trace base" ;;
    dist) echo "dist render scene trace base" ;;
    rtu) echo "rtu" ;;
    *) echo "" ;;
  esac
}

bad=0
checked=0
while IFS= read -r -d '' file; do
  rel="${file#"$root"/lib/}"
  layer="${rel%%/*}"
  ok=" $(allowed "$layer") "
  if [ "$ok" = "  " ]; then
    echo "$file: lib/$layer is not a known layer (add it to scripts/check-includes.sh)"
    bad=1
    continue
  fi
  checked=$((checked + 1))
  while IFS= read -r hit; do
    line="${hit%%:*}"
    target="$(sed -E 's/^[0-9]+:[[:space:]]*#[[:space:]]*include[[:space:]]*"([^"]*)".*/\1/' <<<"$hit")"
    case "$target" in
      */*) ;;
      *) continue ;; # same directory
    esac
    to="${target%%/*}"
    case "$ok" in
      *" $to "*) ;;
      *)
        echo "$file:$line: lib/$layer includes \"$target\": $layer may include only:$ok"
        bad=1
        ;;
    esac
  done < <(grep -nE '^[[:space:]]*#[[:space:]]*include[[:space:]]*"' "$file" || true)
done < <(find "$root/lib" -type f \( -name '*.c' -o -name '*.h' -o -name '*.cpp' \) -print0)

if [ "$checked" -eq 0 ]; then
  echo "no sources found under $root/lib"
  exit 1
fi
if [ "$bad" -ne 0 ]; then
  echo "include directions: FAILED (see docs/architecture.md, Layers)"
  exit 1
fi
echo "include directions: $checked files, all point down the layers"
