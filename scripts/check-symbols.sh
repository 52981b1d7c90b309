#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Checks that the libraries export the public names only: every global
# symbol defined in each given static archive or shared library must be an
# rt* or rtu* entry point (rtFoo, rtuFoo), so that linking Tracelist can
# never clash with an application's own names.
# Usage: scripts/check-symbols.sh NM LIBRARY...   (exit 1 listing offenders)
set -euo pipefail
nm_tool="$1"
shift
bad=0
for lib in "$@"; do
  case "$lib" in
    *.so | *.so.*) symbols="$("$nm_tool" -D --defined-only "$lib")" ;;
    *) symbols="$("$nm_tool" -g --defined-only "$lib")" ;;
  esac
  # Lines "address type name"; archive member headers and blank lines have
  # fewer fields.
  names="$(awk 'NF == 3 { print $3 }' <<<"$symbols")"
  count="$(grep -c . <<<"$names" || true)"
  offenders="$(grep -vE '^rtu?[A-Z]' <<<"$names" || true)"
  if [ -n "$offenders" ]; then
    echo "$lib exports names outside rt*/rtu*:"
    sed 's/^/  /' <<<"$offenders" | head -50
    bad=1
  else
    echo "$lib: $count global symbols, all rt*/rtu*"
  fi
done
exit "$bad"
