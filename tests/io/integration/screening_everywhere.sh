#!/usr/bin/env bash
# The same thermistor screening in every program that reads thermistors: a log with
# one absurd temperature reading (1e308) gives exactly the figures of the same log with that
# reading missing (a dropout), through fog-calibrate and fog-evaluate, and fog-discrepancy
# reports it (fog-drift screens through the same screenThermistors; before: one reading
# discarded 847 of 2 429 calibration samples and made the held-out figure 3.2x worse).
#   screening_everywhere.sh BIN_DIR SOURCE_DIR WORK
set -u
bin=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 2
fail=0
bad() { echo "FAIL: $*"; fail=1; }
gzip -dc "$src/datasets/chamber_A.csv.gz" | head -n 30000 >clean.csv
# Line 20000: third field (the first thermistor) -> 1e308, or empty.
awk -F, -v OFS=, 'NR == 20000 { $3 = "1e308" } { print }' clean.csv >spike.csv
awk -F, -v OFS=, 'NR == 20000 { $3 = "" } { print }' clean.csv >gap.csv
for v in spike gap; do
	"$bin/fog-calibrate" -i $v.csv --model M2:Ti1@2/1 -o cal_$v.yaml --json cal_$v.json >cal_$v.txt 2>&1 || bad "calibrate $v: $(tail -1 cal_$v.txt)"
done
for v in spike gap; do
	"$bin/fog-evaluate" -i $v.csv --cal cal_gap.yaml --json ev_$v.json >ev_$v.txt 2>&1 || bad "evaluate $v: $(tail -1 ev_$v.txt)"
done
grep -q "out of range 1" cal_spike.txt || bad "fog-calibrate did not report the rejected reading: $(cat cal_spike.txt)"
grep -q "out of range 1" ev_spike.txt || bad "fog-evaluate did not report the rejected reading"
# Same model and figures (the run names differ).
diff <(grep -v "calibration_runs\|label:" cal_spike.yaml) <(grep -v "calibration_runs\|label:" cal_gap.yaml) >/dev/null ||
	bad "fog-calibrate: the 1e308 reading changed the calibration"
s1=$(grep -o '"stability_dph": [^,]*' ev_spike.json | tail -1)
s2=$(grep -o '"stability_dph": [^,]*' ev_gap.json | tail -1)
[ -n "$s1" ] && [ "$s1" = "$s2" ] || bad "fog-evaluate: compensated stability $s1 (1e308 reading) vs $s2 (dropout)"
# --no-screening still lets the reading through (and says so).
"$bin/fog-evaluate" -i spike.csv --cal cal_gap.yaml --no-screening >ev_off.txt 2>&1 || true
grep -q "screening: off" ev_off.txt || bad "fog-evaluate --no-screening: $(tail -2 ev_off.txt)"
# Without the screening the reading changes the calibration (what this test guards against).
"$bin/fog-calibrate" -i spike.csv --model M2:Ti1@2/1 -o cal_off.yaml --no-screening >cal_off.txt 2>&1 || bad "calibrate --no-screening: $(tail -1 cal_off.txt)"
diff <(grep -v "calibration_runs\|label:" cal_off.yaml) <(grep -v "calibration_runs\|label:" cal_gap.yaml) >/dev/null &&
	bad "fog-calibrate --no-screening: the 1e308 reading did not change the calibration (the test shows nothing)"
# fog-discrepancy screens too (fog-drift's screening: tests/nav).
"$bin/fog-discrepancy" --measured spike.csv --model M2:Ti1@2/1 >disc.txt 2>&1 || bad "fog-discrepancy: $(tail -1 disc.txt)"
grep -q "out of range 1" disc.txt || bad "fog-discrepancy did not report the rejected reading: $(head -3 disc.txt)"
[ $fail -eq 0 ] && echo "screening is the same in fog-calibrate and fog-evaluate ($s1)"
exit $fail
