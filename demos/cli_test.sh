#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The command line of a demo behaves as a GNU tool's (docs/demos.md):
# --help and --version exit 0, --info prints the renderer and configuration,
# a bad option or argument exits 2 with "Try 'NAME --help'", an output
# extension the build cannot write is refused before any work (no file
# appears), and --opt=value and --opt value both work.
# Usage: cli_test.sh PROGRAM SCRATCH_DIR [RENDER_ARGS...]
#   RENDER_ARGS: a quick headless run (without --out), when the demo can
#   run without external data.
set -uo pipefail
program="$1" scratch="$2"
shift 2
name="$(basename "$program")"
rm -rf "$scratch"
mkdir -p "$scratch"
cd "$scratch" || exit 1
failures=0
fail() { echo "cli_test: FAILED: $*" >&2; failures=$((failures + 1)); }

expect() { # expect RC PATTERN STREAM ARGS...: run, check exit status and output
  local rc="$1" pattern="$2" stream="$3"
  shift 3
  "$program" "$@" >out.txt 2>err.txt
  local got=$?
  [ "$got" -eq "$rc" ] || fail "$name $* exited $got, expected $rc"
  grep -q -- "$pattern" "$stream.txt" || fail "$name $*: no '$pattern' on std$stream"
}

expect 0 "q, Esc" out --help
expect 0 "Usage: $name" out -h
expect 0 "Tracelist 0\." out --version
expect 0 "renderer:" out --info
expect 0 "configuration: threads=2" out --info --threads=2
expect 0 "configuration: threads=3" out --info --threads 3
expect 2 "Try '$name --help'" err --no-such-option
expect 2 "unrecognized option '--no-such-option'" err --no-such-option
expect 2 "requires an argument" err --size
expect 2 "Try '$name --help'" err --size=12
expect 2 "Try '$name --help'" err --threads zero
expect 2 "cannot write '.foo' files" err --headless --out=picture.foo
expect 2 "Try '$name --help'" err --headless --out picture.foo
ls picture.* >/dev/null 2>&1 && fail "$name wrote a file for --out picture.foo"

if [ $# -gt 0 ]; then
  expect 0 "wrote $scratch/a.ppm" out "$@" --out=a.ppm
  [ -s a.ppm ] || fail "$name $* --out=a.ppm wrote nothing"
  expect 0 "wrote $scratch/b_0000.ppm ... $scratch/b_0001.ppm" out "$@" --frames 2 --out b.ppm
  [ -s b_0000.ppm ] && [ -s b_0001.ppm ] || fail "$name --frames 2 did not number from 0000"
fi
if [ "$failures" -ne 0 ]; then
  exit 1
fi
echo "cli_test: $name ok"
