#!/usr/bin/env bash
# The bias part of the compensated heading error, one simulator effect at a time (the error
# budget): for each thermal bias effect, the lab runs (chamber A, rate table A, warm-up; the
# bundled recipe's seeds) and the drives are simulated with that effect alone (+ heat_source,
# earth_rate, thermistor_lag, which every run has), calibrated with the bundled recipe
# (fog-calibrate -i chamber -i ratetable -i warmup), and the drives split with the simulator's
# truth (drive-truth, scripts/heading_budget_truth.py): the bias part's heading RMS over the
# ideal gyro's, median [quartiles], on cold starts (cabins cycled) and warm starts.
#
#   scripts/heading_budget_per_effect.sh OUT_DIR [BUILD_DIR]
#
# Drives: SEEDS (default 1..6: the TUNING drives of the budget; the held-out ones are 11..19 +
# the bundled drive and 41..49, scripts/heading_error_budget.sh).
# RECIPE=wu: the recommended calibration instead (cal_wu: chamber + rate table for the
# bias with one curvature term T(To1)^2, the warm-up fitted apart on two warm-up runs, seeds
# 20240501 and 20240504); where the effect leaves no turn-on transient to fit, the warm-up fit
# refuses and the calibration is made without it (printed "no warm-up term").
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/heading_budget_setup.sh"  # ROOT, OUT ($1), BUILD ($2), programs, cabins
SEEDS=${SEEDS:-"1 2 3 4 5 6"}
EFFECTS=${EFFECTS:-"warmup shupe_rate temp_poly_order radial_gradient hysteresis gradient_rate"}
for X in $EFFECTS; do
	EF=(--effect heat_source --effect earth_rate --effect thermistor_lag --effect "$X")
	"$SIM" --profile seed --seed 20240501 "${EF[@]}" -o "$OUT/$X.chamber.rawlog" >/dev/null
	"$SIM" --profile ratetable --seed 20240502 "${EF[@]}" -o "$OUT/$X.ratetable.rawlog" >/dev/null
	"$SIM" --profile warmup --seed 20240501 "${EF[@]}" -o "$OUT/$X.warmup.rawlog" >/dev/null
	note=""
	if [ "${RECIPE:-}" = wu ]; then
		"$SIM" --profile warmup --seed 20240504 "${EF[@]}" -o "$OUT/$X.warmup_B.rawlog" >/dev/null
		WU=(--model "terms:T(Ti1)^1;dT/dt(Ti1)^1;T(To1)^1;dT/dt(To1)^1;T(Ti2)^1;dT/dt(Ti2)^1;T(To2)^1;dT/dt(To2)^1;T(To1)^2"
			--selection none -i "$OUT/$X.chamber.rawlog" -i "$OUT/$X.ratetable.rawlog" --allow-empty-model)
		if ! "$CAL" "${WU[@]}" --warmup-run "$OUT/$X.warmup.rawlog" --warmup-run "$OUT/$X.warmup_B.rawlog" \
			-o "$OUT/$X.cal.yaml" >"$OUT/$X.cal.txt" 2>&1; then
			note=" (no warm-up term: $(grep -o 'warm-up: [^(]*' "$OUT/$X.cal.txt" | head -1))"
			"$CAL" "${WU[@]}" -o "$OUT/$X.cal.yaml" >>"$OUT/$X.cal.txt" 2>&1
		fi
	else
		"$CAL" -i "$OUT/$X.chamber.rawlog" -i "$OUT/$X.ratetable.rawlog" -i "$OUT/$X.warmup.rawlog" --allow-empty-model \
			-o "$OUT/$X.cal.yaml" >"$OUT/$X.cal.txt" 2>&1
	fi
	cold=() warm=() i=0
	for s in $SEEDS; do
		c=${CABINS[$((i % 3))]}
		"$TRUTH" --seed "$s" --cabin "$c" "${EF[@]}" --cal "$OUT/$X.cal.yaml" -o "$OUT/$X.cold_$s.csv"
		"$TRUTH" --seed "$s" --cabin "$OUT/warm_start.yaml" "${EF[@]}" --cal "$OUT/$X.cal.yaml" -o "$OUT/$X.warm_$s.csv"
		cold+=("$OUT/$X.cold_$s.csv") warm+=("$OUT/$X.warm_$s.csv")
		i=$((i + 1))
	done
	c=$(/usr/bin/python3 "$ROOT/scripts/heading_budget_truth.py" "${cold[@]}" | grep 'median bias_part')
	w=$(/usr/bin/python3 "$ROOT/scripts/heading_budget_truth.py" "${warm[@]}" | grep 'median bias_part')
	printf '%-16s cold: %s | warm start: %s%s\n' "$X" "${c##*over_ideal}" "${w##*over_ideal}" "$note"
done
