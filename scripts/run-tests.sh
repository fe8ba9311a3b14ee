#!/usr/bin/env bash
# Installs what is needed, builds everything and runs the default test suite (label "long"
# excluded; run those with: ctest --test-dir build -L long).
# Usage: scripts/run-tests.sh [build-dir]     (default: build)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$here/build}"
"$here/scripts/setup.sh"
jobs="$(nproc)"
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j"$jobs"
ctest --test-dir "$build" -LE long --output-on-failure -j"$jobs" --timeout 900
