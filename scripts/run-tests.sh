#!/usr/bin/env bash
# Installs what is needed, builds everything and runs the default test suite (label "long"
# excluded; run those with: ctest --test-dir build -L long).
# Usage: scripts/run-tests.sh [build-dir]     (default: build)
# Build settings (unity build, ccache when installed, test ordering): scripts/build-env.sh.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$here/build}"
"$here/scripts/setup.sh"
jobs="$(nproc)"
source "$here/scripts/build-env.sh"
fog_generator "$build"
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release "${FOG_GENERATOR[@]}" "${FOG_BUILD_ARGS[@]}"
cmake --build "$build" -j"$jobs"
fog_seed_test_costs "$build" "$here/tests/ctest_costs/release.txt"
ctest --test-dir "$build" -LE long --output-on-failure -j"$jobs" --timeout 900
