#!/usr/bin/env bash
# Calibration of a simulated three-axis FOG (fog-sim --triad, docs/reference/simulator.md "Three-axis FOG"), as
# a lab would run it: a chamber run (the seed profile, z up: x east, y north), one rate-table
# run per axis (the ratetable profile with that axis up) and one in transients (below), and a
# cold-start warm-up run in the bias fit (the single-axis recommendation, docs/validation/navigation.md), then
# fog-calibrate on all of them (one model per axis; each rate-table run serves its own axis)
# with chamber run B as the validation run. Writes OUT_DIR/cal3.yaml and the runs.
#
#   scripts/triad_calibration.sh OUT_DIR [BUILD_DIR]
#
# Seeds as the bundled single-axis datasets: 20240501 (chamber, warm-up, run B), 20240502
# (rate tables), 20240503 (rate tables in transients, datasets/ratetable_transient.yaml, one
# per axis up; TRANSIENT=0 leaves them out).
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
OUT=${1:?usage: triad_calibration.sh OUT_DIR [BUILD_DIR]}
BUILD=${2:-$ROOT/build}
SIM="$BUILD/apps/fog-sim"
mkdir -p "$OUT"
"$SIM" --triad --profile seed --seed 20240501 -o "$OUT/chamber3_A.rawlog" >/dev/null
"$SIM" --triad --profile B --seed 20240501 -o "$OUT/chamber3_B.rawlog" >/dev/null
"$SIM" --triad --profile warmup --seed 20240501 -o "$OUT/warmup3.rawlog" >/dev/null
TRANSIENT=${TRANSIENT:-1}  # TRANSIENT=0: rate tables at soaks only (the scale factor in one thermistor)
tables=()
for a in x y z; do
	"$SIM" --triad --profile ratetable --up-axis "$a" --seed 20240502 -o "$OUT/ratetable3_$a.rawlog" >/dev/null
	tables+=(-i "$OUT/ratetable3_$a.rawlog")
	if [ "$TRANSIENT" = 1 ]; then  # table segments in transients: the scale factor in a weighted sum of thermistors
		"$SIM" --triad --profile "$ROOT/datasets/ratetable_transient.yaml" --up-axis "$a" --seed 20240503 \
			-o "$OUT/ratetable3_transient_$a.rawlog" >/dev/null
		tables+=(-i "$OUT/ratetable3_transient_$a.rawlog")
	fi
done
"$BUILD/apps/fog-calibrate" -i "$OUT/chamber3_A.rawlog" "${tables[@]}" \
	-i "$OUT/warmup3.rawlog" --validate "$OUT/chamber3_B.rawlog" \
	-o "$OUT/cal3.yaml" --json "$OUT/cal3.json"
