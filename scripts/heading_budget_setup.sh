# Sourced by scripts/heading_budget_per_effect.sh and scripts/heading_error_budget.sh (their
# arguments: OUT_DIR [BUILD_DIR]): the repository root, the output and build folders, the
# programs they run, the bundled datasets, the cabins they cycle, and the output folder holding
# the warm-start cabin profile both drive (scripts/profiles/).
# shellcheck shell=bash disable=SC2034
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
OUT=${1:?usage: $(basename "$0") OUT_DIR [BUILD_DIR]}
BUILD=${2:-$ROOT/build}
SIM="$BUILD/apps/fog-sim"
# The budget's calibrations were measured with the whole of each -i run in the bias fit (the
# warm-up run's turn-on included, as its variants say): fog-calibrate's default now keeps the hour
# after a turn-on out, so the scripts ask for 0 to measure what their figures describe.
CAL_BIN="$BUILD/apps/fog-calibrate"
CAL() { "$CAL_BIN" --turn-on-exclusion 0 "$@"; }
CAL=CAL
DRIFT="$BUILD/apps/fog-drift"
TRUTH="$BUILD/tests/drive-truth"
D="$ROOT/datasets"
CABINS=(drive_cabin drive_cabin_mild drive_cabin_hot)
mkdir -p "$OUT"
cp "$ROOT/scripts/profiles/warm_start.yaml" "$OUT/warm_start.yaml"
