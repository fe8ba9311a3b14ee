#!/usr/bin/env bash
# Calibration of a simulated three-axis FOG (fog-sim --triad, docs/sim.md "Three-axis FOG"), as
# a lab would run it: a chamber run (the seed profile, z up: x east, y north), one rate-table
# run per axis (the ratetable profile with that axis up) and a cold-start warm-up run, then
# fog-calibrate on all of them (one model per axis; each rate-table run serves its own axis)
# with chamber run B as the validation run. Writes OUT_DIR/cal3.yaml and the runs.
#
#   scripts/triad_calibration.sh OUT_DIR [BUILD_DIR]
#
# Seeds as the bundled single-axis datasets: 20240501 (chamber, warm-up, run B), 20240502
# (rate tables).
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
OUT=${1:?usage: triad_calibration.sh OUT_DIR [BUILD_DIR]}
BUILD=${2:-$ROOT/build}
SIM="$BUILD/apps/fog-sim"
mkdir -p "$OUT"
"$SIM" --triad --profile seed --seed 20240501 -o "$OUT/chamber3_A.rawlog" >/dev/null
"$SIM" --triad --profile B --seed 20240501 -o "$OUT/chamber3_B.rawlog" >/dev/null
"$SIM" --triad --profile warmup --seed 20240501 -o "$OUT/warmup3.rawlog" >/dev/null
for a in x y z; do
	"$SIM" --triad --profile ratetable --up-axis "$a" --seed 20240502 -o "$OUT/ratetable3_$a.rawlog" >/dev/null
done
"$BUILD/apps/fog-calibrate" -i "$OUT/chamber3_A.rawlog" -i "$OUT/ratetable3_x.rawlog" -i "$OUT/ratetable3_y.rawlog" \
	-i "$OUT/ratetable3_z.rawlog" --warmup-run "$OUT/warmup3.rawlog" --validate "$OUT/chamber3_B.rawlog" \
	-o "$OUT/cal3.yaml" --json "$OUT/cal3.json"
