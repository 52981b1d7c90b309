#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# One command from a fresh Debian machine to a tested build: installs the
# packages it can, then builds and runs six suites:
#   1. Release build: every test under ctest (conformance, internal, demos,
#      tutorials, install, bench smoke);
#   2. AddressSanitizer + UndefinedBehaviorSanitizer build: every test but
#      the isa=scalar re-runs (label "isa"), which Release runs;
#   3. ThreadSanitizer build: the tests labelled "threads" (building only
#      their targets);
#   4. Plain C build (RT_NO_SIMD): the tests labelled "plainc" (building
#      only their targets);
#   5. clang build with libFuzzer + ASan + UBSan: the test labelled "fuzz",
#      which fuzzes the AFF loader for RT_FUZZ_SECONDS (60 s; builds only
#      that target).  Suites 1 and 2 replay its corpus (fuzz/aff_replay);
#   6. Python: `pip install ./python` into a virtual environment in the
#      build folder, then pytest over python/tests against the Release build.
#
# The BART scenes (third-party data, not in the repository) are looked for
# in $TRACELIST_BART_DIR, else ../shared/bart beside the checkout.  Without
# them the tests labelled "bart" are skipped with one line saying so and
# everything else runs; under CI (CI=true) missing data is a failure.
#
# The sanitizer suites set RT_TEST_WORKLOAD=small: the longest tests
# (api/query_brute_force, api/dynamic_threads) then run fewer rays or frames
# with the same checks; Release runs them at full size.  With ccache on PATH
# every build goes through it (optional).
#
# Every suite runs even when an earlier one failed; a summary follows with
# each suite's time, and the exit status is non-zero when any build or test
# failed.
set -uo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
jobs="$(nproc)"
"$root/scripts/install-deps.sh" || echo "test.sh: install-deps.sh failed; continuing with what is installed"

# ------------------------------------------------------------ BART data
bart_dir="${TRACELIST_BART_DIR:-$root/../shared/bart}"
bart_ctest=()
bart_note=""
if [ -f "$bart_dir/kitchen/kitchen.aff" ] && [ -f "$bart_dir/robots/Robot.aff" ] &&
   [ -f "$bart_dir/museum/museum5.aff" ]; then
  bart_dir="$(cd "$bart_dir" && pwd)"
  export TRACELIST_BART_DIR="$bart_dir"
  echo "test.sh: BART scenes found in $bart_dir"
else
  bart_note="BART scenes not found in $bart_dir (looked for kitchen/, robots/, museum/): \
get the public BART scenes (Lext, Assarsson, Möller 2000; see docs/bart.md) and set \
TRACELIST_BART_DIR to their folder"
  if [ "${CI:-}" = "true" ]; then
    echo "test.sh: FAILURE: $bart_note; under CI the BART tests are required"
  else
    echo "test.sh: skipping the tests labelled 'bart': $bart_note"
    bart_ctest=(-LE bart)
  fi
fi

# ------------------------------------------------------------ suites
declare -a summary=()
failed=0

suite_start=$SECONDS
record() { # record NAME STATUS: the time since the last record is the suite's
  local took=$((SECONDS - suite_start))
  suite_start=$SECONDS
  echo "=== $1: $took s"
  if [ "$2" -eq 0 ]; then
    summary+=("passed  $1 ($took s)")
  else
    summary+=("FAILED  $1 ($took s)")
    failed=1
  fi
}

launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi

run_suite() {
  local name="$1" ; shift
  local dir="$root/build/$name"
  local ctest_args=()
  while [ "$1" != "--" ]; do ctest_args+=("$1"); shift; done
  shift
  echo "=== $name: configure and build"
  cmake -S "$root" -B "$dir" ${launcher[@]+"${launcher[@]}"} "$@" >"$dir.configure.log" 2>&1 ||
    { cat "$dir.configure.log"; return 1; }
  grep "Tracelist:" "$dir.configure.log" || true
  # $build_targets (optional): build only these targets.  $build_label
  # (optional): build only the programs the tests with that label run
  # (their executables in the build tree, named after their targets; ctest
  # -N names them "Test command: PATH" once built, "Could not find
  # executable PATH" before).  An empty list builds everything.
  local targets="${build_targets:-}"
  if [ -n "${build_label:-}" ]; then
    targets="$(ctest --test-dir "$dir" -N -V -L "$build_label" |
      sed -n -e 's|^Could not find executable \([^ ]*\).*|\1|p' \
        -e 's|.*Test command: \([^ "][^ ]*\).*|\1|p' | grep "^$dir/" |
      xargs -r -n1 basename | sort -u | tr '\n' ' ')"
    echo "=== $name: building the targets of label $build_label: ${targets:-(all)}"
  fi
  cmake --build "$dir" -j"$jobs" ${targets:+--target $targets} || return 1
  echo "=== $name: test"
  ctest --test-dir "$dir" --output-on-failure -j"$jobs" ${bart_ctest[@]+"${bart_ctest[@]}"} \
    "${ctest_args[@]}"
}

mkdir -p "$root/build"
run_suite release -- -DCMAKE_BUILD_TYPE=Release
record "release (all tests)" $?

# Leaks are real failures for our code; OpenImageIO's own one-time
# allocations are suppressed by name.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
export LSAN_OPTIONS="suppressions=$root/scripts/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export RT_TEST_WORKLOAD=small
# The isa=scalar re-runs (label "isa") compare kernels, not memory use:
# the Release suite runs them; here they would only double the longest tests.
# -O1 -g1, as the AddressSanitizer documentation advises: the build takes
# 163 s of CPU against 377 s at RelWithDebInfo's -O2 -g, the tests about
# 8 % more, and line tables are all a sanitizer report needs.
asan_flags="-O1 -g1 -DNDEBUG"
run_suite asan-ubsan -LE isa -- -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRT_SANITIZE=address,undefined \
  -DRT_BUILD_BENCH=ON -DCMAKE_C_FLAGS_RELWITHDEBINFO="$asan_flags" \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$asan_flags"
record "asan-ubsan (all tests but the isa=scalar re-runs)" $?

export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1"
build_label=threads run_suite tsan -L threads -- -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DRT_SANITIZE=thread -DRT_WITH_OIIO=OFF -DRT_WITH_GLFW=OFF -DRT_WITH_EMBREE=OFF
record "tsan (label threads)" $?
unset RT_TEST_WORKLOAD

# The plain C library (RT_NO_SIMD: no per-ISA table, no SSE in the
# builders): builds, and its answers pass the tests labelled "plainc".
build_label=plainc run_suite plain-c -L plainc -- -DCMAKE_BUILD_TYPE=Release -DRT_NO_SIMD=ON \
  -DRT_WITH_OIIO=OFF -DRT_WITH_GLFW=OFF -DRT_WITH_EMBREE=OFF
record "plain-c (RT_NO_SIMD, label plainc)" $?

if command -v clang >/dev/null; then
  CC=clang CXX=clang++ build_targets=aff_fuzz run_suite fuzz -L fuzz --no-tests=error -- \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRT_SANITIZE=address,undefined -DRT_FUZZ=ON \
    -DRT_WITH_OIIO=OFF -DRT_WITH_GLFW=OFF -DRT_WITH_EMBREE=OFF -DRT_BUILD_DEMOS=OFF \
    -DRT_BUILD_TUTORIALS=OFF -DRT_BUILD_BENCH=OFF
  record "fuzz (label fuzz)" $?
else
  echo "=== fuzz: clang is not installed (scripts/install-deps.sh lists it)"
  record "fuzz (clang missing)" 1
fi

# The Python package, installed with pip as a user would, into a virtual
# environment that sees the system's numpy and pytest (Debian 12 refuses
# system-wide pip installs).  The first Python that has numpy is used.
run_python() {
  local venv="$root/build/python-venv" python=""
  for candidate in "${PYTHON:-}" python3 /usr/bin/python3; do
    [ -n "$candidate" ] || continue
    if "$candidate" -c "import numpy, pytest, venv" >/dev/null 2>&1; then
      python="$candidate"
      break
    fi
  done
  if [ -z "$python" ]; then
    echo "=== python: no python3 with numpy, pytest and venv (install-deps.sh lists" \
         "python3-numpy python3-pytest python3-venv)"
    return 1
  fi
  echo "=== python: $python -m venv --system-site-packages, pip install ./python, pytest"
  rm -rf "$venv"
  "$python" -m venv --system-site-packages "$venv" || return 1
  # TRACELIST_LIBRARY at install time: python/setup.py bundles that library
  # into the package, so the tests below run on the installed copy alone.
  TRACELIST_LIBRARY="$root/build/release/libtracelist.so" \
    "$venv/bin/python" -m pip install --quiet --no-deps --no-build-isolation "$root/python" ||
    return 1
  # The installed package, not the checkout: run from outside python/.
  (cd "$root/build" && unset TRACELIST_LIBRARY &&
   "$venv/bin/python" -m pytest -q -p no:cacheprovider "$root/python/tests")
}
run_python
record "python (pip install, pytest)" $?

# ------------------------------------------------------------ summary
if [ -n "$bart_note" ]; then
  if [ "${CI:-}" = "true" ]; then
    summary+=("FAILED  BART data missing under CI: $bart_note")
    failed=1
  else
    summary+=("skipped tests labelled 'bart': $bart_note")
  fi
fi
echo "=== summary"
printf '  %s\n' "${summary[@]}"
if [ "$failed" -ne 0 ]; then
  echo "=== some suites FAILED"
  exit 1
fi
echo "=== all suites passed"
