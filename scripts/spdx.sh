#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
#
# Checks (--check) or adds (--fix) the SPDX licence line in every source
# file of the tree: .c .h .cpp .py .sh .cmake .in and CMakeLists.txt.
# Build directories, .git and data (conformance/data, the fuzz corpus and
# regressions, which are inputs, not sources) are left out.
#
#   scripts/spdx.sh --check [ROOT]   exit 1 listing the files that lack the
#                                    line among their first 5 lines
#   scripts/spdx.sh --fix [ROOT]     add it: "/* SPDX... */" as the first
#                                    line of C/C++ files (and *.h.in, *.c.in),
#                                    "# SPDX..." after the shebang of scripts,
#                                    first line of the others
set -euo pipefail

mode="${1:-}"
root="${2:-$(cd "$(dirname "$0")/.." && pwd)}"
id="SPDX-License-Identifier: Apache-2.0"
case "$mode" in
  --check | --fix) ;;
  *)
    echo "usage: spdx.sh --check|--fix [ROOT]" >&2
    exit 2
    ;;
esac

sources() {
  find "$root" \
    \( -path "$root/build" -o -path "$root/build-*" -o -name .git -o -name __pycache__ \
       -o -name '*.egg-info' -o -name .venv -o -path "$root/python/build" -o -path '*/conformance/data' \
       -o -path '*/fuzz/corpus' -o -path '*/fuzz/regressions' \) -prune -o \
    -type f \( -name '*.c' -o -name '*.h' -o -name '*.cpp' -o -name '*.py' -o -name '*.sh' \
       -o -name '*.cmake' -o -name '*.in' -o -name CMakeLists.txt \) -print | LC_ALL=C sort
}

# The comment syntax of a file: "c" for /* */, "hash" for #.
style() {
  case "$1" in
    *.c | *.h | *.cpp | *.c.in | *.h.in) echo c ;;
    *) echo hash ;;
  esac
}

missing=()
while IFS= read -r f; do
  head -n 5 "$f" | grep -q "$id" || missing+=("$f")
done < <(sources)

if [ "$mode" = "--check" ]; then
  if [ ${#missing[@]} -eq 0 ]; then
    echo "spdx: every source file carries '$id'"
    exit 0
  fi
  echo "spdx: ${#missing[@]} source file(s) lack '$id' in their first 5 lines:" >&2
  for f in "${missing[@]}"; do echo "  ${f#"$root"/}" >&2; done
  echo "spdx: run scripts/spdx.sh --fix to add it" >&2
  exit 1
fi

for f in "${missing[@]}"; do
  tmp="$(mktemp)"
  if [ "$(style "$f")" = c ]; then
    { echo "/* $id */"; cat "$f"; } >"$tmp"
  elif head -n 1 "$f" | grep -q '^#!'; then
    { head -n 1 "$f"; echo "# $id"; tail -n +2 "$f"; } >"$tmp"
  else
    { echo "# $id"; cat "$f"; } >"$tmp"
  fi
  # Keep the file's mode (scripts stay executable).
  cat "$tmp" >"$f"
  rm -f "$tmp"
  echo "spdx: added to ${f#"$root"/}"
done
