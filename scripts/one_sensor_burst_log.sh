#!/usr/bin/env bash
# The one-sensor burst log (tests/data/real/tvc_cold_test.csv.gz: a public MEMS thermal-vacuum
# cold test, 25 bursts of 5 s every 305 s, one on-chip sensor) fitted on the odd bursts (1st,
# 3rd, ...) and judged on the even ones, per axis: fog-calibrate's default, a cubic in T
# (least squares, the PX4-style model) and T alone; 100 s stability of the held-out bursts
# (fog-calibrate --validate). docs/validation/calibration-default.md.
#   scripts/one_sensor_burst_log.sh OUT_DIR [BUILD_DIR]
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
OUT=${1:?usage: one_sensor_burst_log.sh OUT_DIR [BUILD_DIR]}
BUILD=${2:-$ROOT/build}
CAL="$BUILD/apps/fog-calibrate"
mkdir -p "$OUT"
# bursts: a gap of more than 1 s starts the next one
zcat "$ROOT/tests/data/real/tvc_cold_test.csv.gz" | awk -F, -v odd="$OUT/odd.csv" -v even="$OUT/even.csv" '
	/^#/ || /^time_s/ { print > odd; print > even; next }
	{ if (NR > 1 && have && $1 - prev > 1) burst++; prev = $1; have = 1; print > ((burst % 2 == 0) ? odd : even) }'
for axis in x y z; do
	for m in default cubic linear; do
		case $m in
			default) args=() ;;
			cubic) args=(--selection none --model "terms:T(chip)^1;T(chip)^2;T(chip)^3") ;;
			linear) args=(--selection none --model "terms:T(chip)^1") ;;
		esac
		"$CAL" -q -i "$OUT/odd.csv" --axis "$axis" "${args[@]}" --validate "$OUT/even.csv" \
			-o "$OUT/cal_${axis}_$m.yaml" --json "$OUT/cal_${axis}_$m.json" > "$OUT/cal_${axis}_$m.txt"
		python3 - "$OUT/cal_${axis}_$m.json" "$axis" "$m" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
v = j["validation"]
print("axis %s %-8s raw %8.2f  compensated %8.3f deg/h (even bursts, 100 s)  terms: %s"
      % (sys.argv[2], sys.argv[3], v["raw"]["stability_dph"], v["compensated"]["stability_dph"],
         " ".join(j["term_names"][1:])))
PY
	done
done
