#!/usr/bin/env bash
# Builds everything with AddressSanitizer + UndefinedBehaviorSanitizer (MRPT_FOG_SANITIZE=ON,
# build-asan/) and runs the default test suite (ctest -LE long) under them.
#   scripts/run-sanitizers.sh [extra ctest arguments, e.g. -R faults]
# Environment: BUILD_DIR (default <repo>/build-asan), JOBS (default 2).
# MRPT's shared libraries are not instrumented (their bugs are out of reach; calls into them are
# checked at our side only). Options and suppressions used, and why: see docs/hardening.md.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$here/build-asan}
jobs=${JOBS:-2}

cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMRPT_FOG_SANITIZE=ON \
	-DMRPT_FOG_BUILD_BENCH=OFF >/dev/null
cmake --build "$build" -j"$jobs"

# halt on the first UBSan report (as -fno-sanitize-recover=undefined does at compile time);
# leaks are checked (LeakSanitizer) with the suppressions of scripts/lsan.supp.
export ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$here/scripts/lsan.supp:print_suppressions=0}
ctest --test-dir "$build" -LE long -j"$jobs" --output-on-failure --timeout 900 "$@"
