#!/usr/bin/env bash
# README command 2, and what CI runs (.ci/run): installs what is missing,
# builds, and runs every test. Each source is compiled once per tree, and
# each tree has one job:
#   check  one clang tree with AddressSanitizer + UBSan, libFuzzer coverage
#          and the thread-safety analysis as errors (build-check): every
#          test, GoogleTest suites and the tests of the programs as shipped
#          (the local cluster, the Python client, a consumer of the
#          installed engine) under ASAN+UBSAN, then every fuzzer for
#          LOCATOR_FUZZ_SECONDS, then deploy/soak.sh for
#          LOCATOR_SOAK_SECONDS on its locatord and locator-load (ASAN's
#          quarantine off, so that resident memory measures the server's own)
#   tsan   (clang) the concurrency tests (the engine under many threads, the
#          serving layer's parts in process) and locatord under real traffic
#          (locatord_e2e_test) under ThreadSanitizer (build-tsan; only their
#          executables)
# The Release tree README command 1 builds is not built here: its sources
# are all compiled, and its programs all run, in the check tree.
# Any test failure, thread-safety error, sanitizer report (from a test or
# from a server it started), fuzzer crash or soak failure fails the run.
# Stage timings are printed at the end, pass or fail.
#
# Environment knobs (defaults are what CI runs):
#   LOCATOR_CI_SANITIZERS=1  LOCATOR_CI_FUZZ=1  LOCATOR_CI_SOAK=1
#   LOCATOR_FUZZ_SECONDS=20  LOCATOR_SOAK_SECONDS=60
# With LOCATOR_CI_SANITIZERS=0 only a plain Release tree (BUILD_DIR, build)
# is built and tested, for a quick local run.
# ccache is used when it is installed (it is not installed by this script).
set -euo pipefail
cd "$(dirname "$0")/.."

BUILD_DIR="${BUILD_DIR:-build}"
SANITIZERS="${LOCATOR_CI_SANITIZERS:-1}"
FUZZ="${LOCATOR_CI_FUZZ:-1}"
SOAK="${LOCATOR_CI_SOAK:-1}"
# Five fuzzers, two at a time: three rounds of this many seconds.
FUZZ_SECONDS="${LOCATOR_FUZZ_SECONDS:-20}"
SOAK_SECONDS="${LOCATOR_SOAK_SECONDS:-60}"
JOBS="$(nproc)"
# Sanitizer trees: -O1 (the sanitizers' own advice; half the compile time
# of -O2) and no debug info beyond clang's line tables.
SANITIZER_FLAGS=(-DCMAKE_BUILD_TYPE=RelWithDebInfo)
# ccache caches objects built with a precompiled header (cmake/LocatorPch.cmake)
# only under these sloppiness settings.
LAUNCHER=()
if command -v ccache > /dev/null; then
  LAUNCHER=("-DCMAKE_CXX_COMPILER_LAUNCHER=env;CCACHE_SLOPPINESS=pch_defines,time_macros;ccache")
fi
# lld (Debian's lld) links the clang trees' executables in a fraction of GNU
# ld's time; they are many and large (ASAN, gRPC).
CLANG_LINKER=()
if command -v ld.lld > /dev/null; then
  CLANG_LINKER=(-DCMAKE_EXE_LINKER_FLAGS=-fuse-ld=lld
    -DCMAKE_SHARED_LINKER_FLAGS=-fuse-ld=lld)
fi

# Each stage's wall time, and the CPU time (user + sys) of everything it ran:
# on a shared machine the CPU time tells what a dedicated one would need.
timings=()
total_start=$SECONDS
times_file=$(mktemp)
print_timings() {
  echo "== stage timings (seconds)"
  printf '%s\n' "${timings[@]}"
  printf '%-12s wall %5d\n' total $((SECONDS - total_start))
  rm -f "$times_file"
}
trap print_timings EXIT

# CPU seconds of the children waited for so far, from `times` (which must
# run in this shell, not a subshell, hence the file).
children_cpu() {
  awk 'NR == 2 { split($0, t, /[ms]+/); printf "%d", t[1] * 60 + t[2] + t[3] * 60 + t[4] }' \
    "$times_file"
}

# stage NAME COMMAND...: runs COMMAND as stage NAME and records its times.
stage() {
  local name=$1 start=$SECONDS cpu_start result=""
  shift
  echo "== [$name] $*"
  times > "$times_file"
  cpu_start=$(children_cpu)
  "$@" || result="  FAILED"
  times > "$times_file"
  timings+=("$(printf '%-12s wall %5d  cpu %5d%s' "$name" \
    $((SECONDS - start)) $(($(children_cpu) - cpu_start)) "$result")")
  [ -z "$result" ] || exit 1
}

# build_tree DIR "TARGETS" CMAKE_ARGS...: configures DIR and builds TARGETS.
build_tree() {
  local dir=$1 targets=$2
  shift 2
  # shellcheck disable=SC2086  # TARGETS is a list
  cmake -S . -B "$dir" -G Ninja "${LAUNCHER[@]}" "$@" &&
    cmake --build "$dir" -j"$JOBS" --target $targets
}

# sanitized DIR COMMAND...: runs COMMAND with every sanitizer halting on its
# first report and writing it to DIR/sanitizer-reports, where reports of the
# servers tests and the soak spawn land too (their exit status is not every
# caller's business). Fails if COMMAND fails or on any report. ASAN_EXTRA, if
# set, adds to ASAN's options.
# TSAN ignores what its interceptors (malloc, memcpy, ...) see when called
# from code it did not instrument (gRPC, abseil, protobuf; see the top-level
# CMakeLists.txt for why the gRPC layer is not instrumented): such accesses
# have no visible synchronization, so each one would be a false report.
# tests/sanitizers/tsan.supp holds the (third-party) suppressions.
sanitized() {
  local reports="$PWD/$1/sanitizer-reports" status=0
  shift
  rm -rf "$reports" && mkdir -p "$reports" || return 1
  ASAN_OPTIONS="detect_leaks=1:halt_on_error=1:log_exe_name=1:log_path=$reports/asan${ASAN_EXTRA:+:$ASAN_EXTRA}" \
    UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:log_exe_name=1:log_path=$reports/ubsan" \
    TSAN_OPTIONS="halt_on_error=1:log_exe_name=1:second_deadlock_stack=1:ignore_noninstrumented_modules=1:log_path=$reports/tsan:suppressions=$PWD/tests/sanitizers/tsan.supp" \
    "$@" || status=1
  if compgen -G "$reports/*" > /dev/null; then
    echo "sanitizer reports in $reports (named by program and pid):"
    for report in "$reports"/*; do
      echo "== ${report##*/}"
      cat "$report"
    done
    status=1
  fi
  return $status
}

# sanitized_ctest DIR CTEST_ARGS...: ctest in DIR, sanitized.
sanitized_ctest() {
  local dir=$1
  shift
  sanitized "$dir" ctest --test-dir "$dir" --output-on-failure -j"$JOBS" \
    --timeout 900 "$@"
}

# tsan_test: the concurrency tests, then locatord's engine, re-tune timer and
# serving threads under real gRPC traffic (locatord_e2e_test's suite).
tsan_test() {
  sanitized_ctest build-tsan -L concurrency &&
    sanitized_ctest build-tsan -R '^locatord_e2e_test$'
}

# asan_soak: deploy/soak.sh on build-check's programs, sanitized. Quarantine
# off: ASAN would otherwise hold up to 256 MiB of freed blocks, which the
# soak would count as the server's growth.
asan_soak() {
  ASAN_EXTRA=quarantine_size_mb=0 sanitized build-check \
    env BUILD_DIR=build-check SOAK_WARMUP=$((SOAK_SECONDS / 3)) \
    bash deploy/soak.sh --duration "$SOAK_SECONDS"
}

# fuzz_run: every fuzzer for its bounded time, then how many inputs each ran.
fuzz_run() {
  ctest --test-dir build-check -L fuzz --output-on-failure -j"$JOBS" &&
    grep -E '^[0-9]+/[0-9]+ Test: |^Done [0-9]+ runs' \
      build-check/Testing/Temporary/LastTest.log
}

stage deps bash deploy/install-deps.sh

if [ "$SANITIZERS" = 0 ]; then
  stage build build_tree "$BUILD_DIR" all -DCMAKE_BUILD_TYPE=Release
  stage test ctest --test-dir "$BUILD_DIR" --output-on-failure -j"$JOBS" \
    --timeout 600
  exit 0
fi

stage check-build build_tree build-check "all fuzzers" "${SANITIZER_FLAGS[@]}" \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only -DNDEBUG" \
  -DCMAKE_CXX_COMPILER=clang++ "${CLANG_LINKER[@]}" -DLOCATOR_FUZZ=ON \
  -DLOCATOR_THREAD_SAFETY=ON \
  -DLOCATOR_FUZZ_SECONDS="$FUZZ_SECONDS"
stage asan-test sanitized_ctest build-check -LE fuzz
if [ "$FUZZ" != 0 ]; then
  stage fuzz-run fuzz_run
fi
if [ "$SOAK" != 0 ]; then
  stage soak asan_soak
fi
stage tsan-build build_tree build-tsan \
  "tests-concurrency locatord_e2e_test" \
  "${SANITIZER_FLAGS[@]}" \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g0 -DNDEBUG" \
  -DCMAKE_CXX_COMPILER=clang++ "${CLANG_LINKER[@]}" -DLOCATOR_SANITIZER=thread
stage tsan-test tsan_test
