#!/usr/bin/env bash
# fog-discrepancy --write-cal (refit on 1 s block means) against a per-sample fog-calibrate fit
# with the same terms and rate window, on lumped-coil runs at 10 Hz (docs/guide/model-gap.md,
# "--write-cal refits on the block means"). Per seed s: runs 2s and 2s + 1 with EFFECT=3,
# --model M2:Ca@3/1; then both calibrations through fog-evaluate on the confirmation run.
#   write_cal_per_sample.sh BUILD_DIR OUT_DIR EFFECT SEED...
#   e.g. write_cal_per_sample.sh build wc radial_gradient 9601 9602 9603 9604 9605
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
B=$(cd "$1" && pwd); OUT=$2; E=$3; shift 3
mkdir -p "$OUT" && cd "$OUT"
for s in "$@"; do
	p=${E}_$s
	"$B/tests/lumped-coil-gen" -o r1_$p.csv.gz --seed $((2 * s)) --dt 0.1 --effect "$E=3"
	"$B/tests/lumped-coil-gen" -o r2_$p.csv.gz --seed $((2 * s + 1)) --dt 0.1 --effect "$E=3"
	"$B/apps/fog-discrepancy" -q --measured r1_$p.csv.gz --measured r2_$p.csv.gz --model M2:Ca@3/1 \
		--write-cal aug_$p.yaml --json d_$p.json >d_$p.txt
	T=$(grep -m1 'preset:' aug_$p.yaml | sed 's/.*preset: "//; s/"$//')
	W=$(grep -m1 'window_s:' aug_$p.yaml | sed 's/.*window_s: //')
	"$B/apps/fog-calibrate" -q -i r1_$p.csv.gz --model "$T" --selection none --window "$W" -o ps_$p.yaml >/dev/null
	"$B/apps/fog-calibrate" -q -i r1_$p.csv.gz --model M2:Ca@3/1 -o base_$p.yaml >/dev/null
	for c in base ps aug; do "$B/apps/fog-evaluate" -i r2_$p.csv.gz --cal ${c}_$p.yaml --json ev_${c}_$p.json >/dev/null; done
done
python3 "$here/write_cal_per_sample.py" "$PWD" "$E" "$@"
