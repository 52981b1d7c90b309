#!/usr/bin/env bash
# One command from a fresh Debian machine to a tested build: installs the
# packages, then builds and runs four suites under ctest:
#   1. Release build: every test (conformance, internal, demos, bench smoke);
#   2. AddressSanitizer + UndefinedBehaviorSanitizer build: every test;
#   3. ThreadSanitizer build: the tests labelled "threads";
#   4. clang build with libFuzzer + ASan + UBSan: the test labelled "fuzz",
#      which fuzzes the AFF loader for RT_FUZZ_SECONDS (60 s; builds only
#      that target).  Suites 1 and 2 replay its corpus (fuzz/aff_replay).
# Exits non-zero if any build or test fails.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
jobs="$(nproc)"
"$root/scripts/install-deps.sh"

run_suite() {
  local name="$1" ; shift
  local dir="$root/build/$name"
  local ctest_args=()
  while [ "$1" != "--" ]; do ctest_args+=("$1"); shift; done
  shift
  echo "=== $name: configure and build"
  cmake -S "$root" -B "$dir" "$@" >"$dir.configure.log" 2>&1 || { cat "$dir.configure.log"; return 1; }
  grep "Tracelist:" "$dir.configure.log" || true
  # $build_targets (optional): build only these targets.
  cmake --build "$dir" -j"$jobs" ${build_targets:+--target $build_targets}
  echo "=== $name: test"
  ctest --test-dir "$dir" --output-on-failure -j"$jobs" "${ctest_args[@]}"
}

mkdir -p "$root/build"
run_suite release -- -DCMAKE_BUILD_TYPE=Release
# Leaks are real failures for our code; OpenImageIO's own one-time
# allocations are suppressed by name.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
export LSAN_OPTIONS="suppressions=$root/scripts/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
run_suite asan-ubsan -- -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRT_SANITIZE=address,undefined \
  -DRT_BUILD_BENCH=ON
export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1"
run_suite tsan -L threads -- -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRT_SANITIZE=thread \
  -DRT_WITH_OIIO=OFF -DRT_WITH_GLFW=OFF -DRT_WITH_EMBREE=OFF
CC=clang CXX=clang++ build_targets=aff_fuzz run_suite fuzz -L fuzz --no-tests=error -- \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRT_SANITIZE=address,undefined -DRT_FUZZ=ON \
  -DRT_WITH_OIIO=OFF -DRT_WITH_GLFW=OFF -DRT_WITH_EMBREE=OFF -DRT_BUILD_DEMOS=OFF \
  -DRT_BUILD_BENCH=OFF
echo "=== all suites passed"
