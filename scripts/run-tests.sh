#!/usr/bin/env bash
# Installs what is needed, builds everything and runs the default test suite (label "long"
# excluded; run those with: ctest --test-dir build -L long).
# Usage: scripts/run-tests.sh [build-dir]     (default: build)
# Compiles through ccache when it is installed (scripts/ccache-env.sh; FOG_CCACHE=0 turns it off).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$here/build}"
"$here/scripts/setup.sh"
jobs="$(nproc)"
source "$here/scripts/ccache-env.sh"  # compiler cache when installed (FOG_CCACHE=0: none)
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release "${FOG_LAUNCHER[@]}"
cmake --build "$build" -j"$jobs"
ctest --test-dir "$build" -LE long --output-on-failure -j"$jobs" --timeout 900
