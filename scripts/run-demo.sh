#!/usr/bin/env bash
# The main job, end to end, on the bundled datasets (simulating them if absent): installs what
# is needed, builds the programs and runs fog-demo. Report folder: ./fog-demo-report (or $1).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${1:-$PWD/fog-demo-report}"
"$here/scripts/setup.sh"
build="$here/build"
source "$here/scripts/build-env.sh"  # the same build settings as scripts/run-tests.sh
fog_generator "$build"
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release "${FOG_GENERATOR[@]}" "${FOG_BUILD_ARGS[@]}" > /dev/null
cmake --build "$build" -j"$(nproc)" --target fog-demo fog-sim fog-calibrate fog-compensate fog-evaluate fog-drift fog-convert fog-paper
"$build/apps/fog-demo" --datasets "$here/datasets" --out "$out"
