#!/usr/bin/env bash
# No silent empty model. A run whose gyro output does not follow the thermistors
# (chamber run A's temperatures at 1 Hz with the rate replaced by an alternating +-0.05 deg/h
# pattern): M4 keeps no thermal term -> fog-calibrate says so and why, exits 1 and writes
# nothing, unless --allow-empty-model (then a warning and exit 0). multipoint keeps its linear
# base terms, which compensate nothing -> a warning naming the held-out gain.
# Before: "model: 1 terms (0 thermistors)", exit 0, no word.
#   empty_model.sh BIN_DIR SOURCE_DIR WORK
set -u
bin=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 2
fail=0
bad() { echo "FAIL: $*"; fail=1; }
gzip -dc "$src/datasets/chamber_A.csv.gz" |
	awk -F, -v OFS=, '/^#/ || /^time/ { print; next } NR % 10 == 0 { $2 = (NR % 20 == 0 ? "0.55" : "0.45"); print }' >flat.csv
"$bin/fog-calibrate" -i flat.csv --model M4 -o cal.yaml >out.txt 2>err.txt
rc=$?
[ $rc -eq 1 ] || bad "exit $rc, expected 1"
grep -q "no thermal term" err.txt || bad "error lacks 'no thermal term': $(cat err.txt)"
grep -q "no thermal term lowered the held-out error" err.txt || bad "error lacks the reason: $(cat err.txt)"
[ "$(wc -l <err.txt)" -eq 1 ] || bad "error is not one line"
[ -e cal.yaml ] && bad "cal.yaml written although refused"
"$bin/fog-calibrate" -i flat.csv --model M4 -o cal.yaml --allow-empty-model >out.txt 2>err.txt || bad "--allow-empty-model: exit $?"
[ -e cal.yaml ] || bad "--allow-empty-model: nothing written"
grep -q "warning: the fitted model has no thermal term" err.txt || bad "--allow-empty-model: no warning: $(cat err.txt)"
grep -q "1 terms (0 thermistors)" out.txt || bad "--allow-empty-model: not the constant model: $(head -3 out.txt)"
"$bin/fog-calibrate" -i flat.csv --model multipoint -o cal_mp.yaml >out.txt 2>err.txt || bad "multipoint: exit $?"
grep -q "warning: the thermal terms lower the held-out stability by less than 1 %" err.txt ||
	bad "multipoint: no warning that the model compensates nothing: $(cat err.txt)"
[ $fail -eq 0 ] && echo "empty model refused with its reason"
exit $fail
