#!/usr/bin/env bash
# The default calibration, measured: fog-calibrate with every bundled calibration run and no
# other option (docs/validation/calibration-default.md).
#   1. cal.yaml = fog-calibrate -i chamber_A -i chamber_C -i ratetable_A -i ratetable_transient
#      -i warmup -i warmup_B (nothing else), then fog-drift over the drives SEEDS (default 11..17,
#      evaluation seeds held out of every choice; cabins cycled winter / mild / hot as in
#      scripts/drift_over_drives.sh, without the bundled drive): OUT/drives.json, median heading
#      RMS compensated/ideal and compensated/raw printed;
#   2. run B held out from chamber A + C (the default, nothing else): raw / compensated stability
#      on datasets/chamber_B.rawlog.
#   scripts/calibration_default.sh OUT_DIR [BUILD_DIR]
# EXTRA="--option ..." adds options to the calibration of 1 (for comparisons; the figures of the
# default are measured without).
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
OUT=${1:?usage: calibration_default.sh OUT_DIR [BUILD_DIR]}
BUILD=${2:-$ROOT/build}
D="$ROOT/datasets"
SEEDS=${SEEDS:-"11 12 13 14 15 16 17"}
mkdir -p "$OUT"
# shellcheck disable=SC2086
"$BUILD/apps/fog-calibrate" -q -i "$D/chamber_A.rawlog" -i "$D/chamber_C.rawlog" -i "$D/ratetable_A.rawlog" \
	-i "$D/ratetable_transient.rawlog" -i "$D/warmup.rawlog" -i "$D/warmup_B.rawlog" ${EXTRA:-} \
	-o "$OUT/cal.yaml" --json "$OUT/cal.json" > "$OUT/cal.txt"
SEEDS="$SEEDS" NO_BUNDLED=1 "$ROOT/scripts/drift_over_drives.sh" "$OUT/cal.yaml" "$OUT/drives" "$BUILD" > "$OUT/drives.txt"
grep -E 'ratio.heading_rms_compensated_over_(ideal|raw)' "$OUT/drives.txt" | tail -2
"$BUILD/apps/fog-calibrate" -q -i "$D/chamber_A.rawlog" -i "$D/chamber_C.rawlog" --validate "$D/chamber_B.rawlog" \
	-o "$OUT/cal_AC.yaml" --json "$OUT/cal_AC.json" > "$OUT/cal_AC.txt"
python3 - "$OUT/cal_AC.json" <<'PY'
import json, sys
v = json.load(open(sys.argv[1]))["validation"]
print("run B held out from chamber A + C: raw %.6g / compensated %.6g deg/h = %.1fx"
      % (v["raw"]["stability_dph"], v["compensated"]["stability_dph"],
         v["raw"]["stability_dph"] / v["compensated"]["stability_dph"]))
PY
