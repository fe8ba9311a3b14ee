#!/bin/sh
# Figures of docs/validation/turn-on-refinement.md: the in-field refinement of the turn-on bias
# offset (fog-drift's standstill updates) and the calibration that learns it (fog-refine).
#   scripts/turn_on_refinement.sh OUT_DIR        (from the source tree; BUILD=build by default)
# Writes OUT_DIR/*.json, *.txt and OUT_DIR/summary.txt (scripts/turn_on_refinement_summary.py).
# Seeds 61-69 (turn-on drives) and 71-76 (aging) were never used to choose anything; the
# refinement runs at fog-drift's defaults. PARTS="bundled sweep sweepsf nostill aging" selects parts.
set -eu
B=${BUILD:-build}
OUT=${1:-turn_on_refinement}
PARTS=${PARTS:-"bundled sweep sweepsf nostill aging"}
mkdir -p "$OUT"
has() { case " $PARTS " in *" $1 "*) return 0 ;; esac; return 1; }

# the recommended calibration (README)
CAL="$OUT/cal_wu.yaml"
[ -f "$CAL" ] || "$B/apps/fog-calibrate" -i datasets/chamber_A.rawlog -i datasets/ratetable_A.rawlog \
  -i datasets/ratetable_transient.rawlog --warmup-run datasets/warmup.rawlog --warmup-run datasets/warmup_B.rawlog \
  --selection none --model "terms:T(Ti1)^1;dT/dt(Ti1)^1;T(To1)^1;dT/dt(To1)^1;T(Ti2)^1;dT/dt(Ti2)^1;T(To2)^1;dT/dt(To2)^1;T(To1)^2" \
  -o "$CAL" > "$OUT/cal_wu.log"

drift() {  # name, then fog-drift arguments: with (refined) and without (thermal) the standstill updates
  name=$1; shift
  "$B/apps/fog-drift" -q "$@" --cal "$CAL" --json "$OUT/${name}_refined.json" > "$OUT/${name}_refined.txt"
  "$B/apps/fog-drift" -q "$@" --cal "$CAL" --no-field-refinement --json "$OUT/${name}_thermal.json" > "$OUT/${name}_thermal.txt"
}

if has bundled; then
  # the bundled drive, and a copy with +0.3 deg/h on its FOG (independent generator: gyro-shift)
  [ -f "$OUT/drive_plus03.rawlog" ] || "$B/tests/gyro-shift" datasets/drive.rawlog "$OUT/drive_plus03.rawlog" 0.3 > /dev/null
  drift bundled -i datasets/drive.rawlog
  drift plus03 -i "$OUT/drive_plus03.rawlog"
fi

sweep() {  # name, device turn_on section: 9 drives (seeds 61-69, the three cabins in turn)
  name=$1
  printf 'turn_on: %s\n' "$2" > "$OUT/${name}_device.yaml"
  set --
  i=0
  for seed in 61 62 63 64 65 66 67 68 69; do
    case $((i % 3)) in 0) cabin=drive_cabin ;; 1) cabin=drive_cabin_mild ;; 2) cabin=drive_cabin_hot ;; esac
    f="$OUT/${name}_seed${seed}.rawlog"
    [ -f "$f" ] || "$B/apps/fog-sim" --profile drive --cabin "$cabin" --seed "$seed" --device "$OUT/${name}_device.yaml" -o "$f" > /dev/null
    set -- "$@" -i "$f"
    i=$((i + 1))
  done
  drift "$name" "$@"
}
# the gyro draws its turn-on offset at 0.3 deg/h (1-sigma) ...
if has sweep; then sweep sweep "{bias_repeatability_dph: 0.3}"; fi
# ... and also its scale factor at 50 ppm (what standstills cannot see)
if has sweepsf; then sweep sweepsf "{bias_repeatability_dph: 0.3, sf_repeatability_ppm: 50}"; fi

if has nostill; then
  # a piece of the bundled drive without a standstill (gyro-shift's window, shift 0.3 deg/h)
  [ -f "$OUT/nostill.rawlog" ] || "$B/tests/gyro-shift" datasets/drive.rawlog "$OUT/nostill.rawlog" 0.3 FOG "${NOSTILL_FROM:-130}" "${NOSTILL_TO:-400}" > /dev/null
  "$B/apps/fog-drift" -q -i "$OUT/nostill.rawlog" --cal "$CAL" --json "$OUT/nostill_refined.json" --csv "$OUT/nostill_refined.csv" > "$OUT/nostill_refined.txt"
  "$B/apps/fog-drift" -q -i "$OUT/nostill.rawlog" --cal "$CAL" --no-field-refinement --json "$OUT/nostill_thermal.json" --csv "$OUT/nostill_thermal.csv" > "$OUT/nostill_thermal.txt"
  # the per-sample heading and position errors of every gyro, byte for byte
  cmp "$OUT/nostill_refined.csv" "$OUT/nostill_thermal.csv" > "$OUT/nostill_cmp.txt" 2>&1 || true
fi

if has aging; then
  # an aging gyro (1 deg/h per year: an estimate, no source; turn-on repeatability 0.02 deg/h):
  # field logs at 30, 60, 90 days teach fog-refine; drives at 120, 150, 180 days judge the
  # original and the refined calibration with the standstill updates off (the calibration alone)
  for day in 30 60 90 120 150 180; do
    seed=$((70 + day / 30))
    printf 'turn_on: {bias_repeatability_dph: 0.02, aging_dph_per_year: 1.0, age_days: %s}\n' "$day" > "$OUT/aging_day${day}.yaml"
    [ -f "$OUT/aging_day${day}.rawlog" ] || "$B/apps/fog-sim" --profile drive --seed "$seed" --device "$OUT/aging_day${day}.yaml" -o "$OUT/aging_day${day}.rawlog" > /dev/null
  done
  rm -f "$OUT/cal_refined.yaml"
  "$B/apps/fog-refine" --cal "$CAL" -i "$OUT/aging_day30.rawlog" -i "$OUT/aging_day60.rawlog" -i "$OUT/aging_day90.rawlog" \
    --turn-on-repeatability-dph 0.02 -o "$OUT/cal_refined.yaml" --json "$OUT/refine.json" > "$OUT/refine.txt"
  for c in cal_wu cal_refined; do
    "$B/apps/fog-drift" -q -i "$OUT/aging_day120.rawlog" -i "$OUT/aging_day150.rawlog" -i "$OUT/aging_day180.rawlog" \
      --cal "$OUT/$c.yaml" --no-field-refinement --json "$OUT/aging_${c}.json" > "$OUT/aging_${c}.txt"
  done
fi
python3 scripts/turn_on_refinement_summary.py "$OUT" | tee "$OUT/summary.txt"
