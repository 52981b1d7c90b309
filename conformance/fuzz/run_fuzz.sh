#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Runs the libFuzzer target for a bounded time (the fuzz/aff_loader test).
# Usage: run_fuzz.sh FUZZER SCRATCH_DIR SECONDS SOURCE_DIR TEXTURE_DIR BART_DIR
#   SOURCE_DIR  conformance/fuzz: corpus/ (the seeds), regressions/ and aff.dict
#   TEXTURE_DIR the working directory: texture names resolve against it, so
#               it holds the one texture the corpus names and nothing else
#   BART_DIR    the BART folder; $TRACELIST_BART_DIR wins when set.  Read in
#               place as a second, read-only seed corpus when it exists.
# libFuzzer writes what it learns to its FIRST corpus directory, so that is
# a scratch directory in the build tree, seeded with the repository's corpus
# on every run; crashes, leaks and timeouts are saved under
# SCRATCH_DIR/artifacts/ (copy one to regressions/ to keep it as a test).
set -euo pipefail
[ $# -eq 6 ] || { echo "usage: $0 FUZZER SCRATCH_DIR SECONDS SOURCE_DIR TEXTURE_DIR BART_DIR" >&2; exit 2; }
mkdir -p "$2/corpus" "$2/artifacts"
# Absolute paths: the fuzzer runs in TEXTURE_DIR.
fuzzer="$(realpath "$1")" scratch="$(realpath "$2")" seconds="$3" src="$(realpath "$4")"
textures="$5" bart="${TRACELIST_BART_DIR:-$6}"
cp "$src"/corpus/* "$scratch/corpus/"
dirs=("$scratch/corpus" "$src/regressions")
if [ -d "$bart" ]; then
  dirs+=("$(realpath "$bart")")
else
  echo "run_fuzz: no BART folder at '$bart': seeds from the repository only"
fi
cd "$textures"
# -max_len matches the target's own limit (AFF_FUZZ_MAX_INPUT in aff_fuzz.c);
# larger seeds are cut to it.  libFuzzer reads the BART folder recursively,
# textures too: they fail at their first byte, at no cost.
# The resource bound (docs/aff.md, "Files and resource limits"): an input of
# n <= 64 KiB bytes may make at most n / 4 + 65,536 triangles, 7.5 MiB, in
# arrays that double (16 MiB), and the target records at most 4096 of them
# (AFF_FUZZ_MAX_TRIANGLES), so any single allocation above 64 MiB
# (-malloc_limit_mb), a process above 2 GiB under ASan (-rss_limit_mb) or
# an input running longer than 10 s (-timeout) is a finding, saved as an
# artifact like a crash.  The target checks the parsed scene's size against
# its input itself (aff_fuzz.c, AFF_FUZZ_BYTES_PER_INPUT).
exec "$fuzzer" -max_total_time="$seconds" -rss_limit_mb=2048 -malloc_limit_mb=64 -timeout=10 \
  -max_len=65536 \
  -detect_leaks=1 -print_final_stats=1 -dict="$src/aff.dict" \
  -artifact_prefix="$scratch/artifacts/" "${dirs[@]}"
