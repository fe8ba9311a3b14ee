#!/bin/sh
# A format file that is bad or does not fit the log stops every program with one line naming the
# format file and the key (and, for a column the log lacks, the header's columns), a non-zero
# exit, and no output file: a missing column key, a column mapped twice, an unknown unit, a
# column absent from the file, a column the file holds twice.
# usage: format_errors.sh APPS_BIN_DIR SOURCE_DIR WORK
set -u
BIN=$1 SRC=$2 W=$3
rm -rf "$W"; mkdir -p "$W"; cd "$W"
LOG=$SRC/examples/your_gyro/chamber_run1.csv
good=$SRC/examples/your_gyro/my_gyro.yaml
sed 's/z: {column: "Gyro Z \[deg\/s\]", unit: deg\/s}/z: {unit: deg\/s}/' "$good" > missing.yaml
sed 's/Ti2: {column: "Ti2 \[degC\]"/Ti2: {column: "Ti1 [degC]"/' "$good" > duplicate.yaml
sed 's/unit: deg\/s}/unit: dps}/' "$good" > unit.yaml
sed 's/Gyro Z \[deg\/s\]/GyroZ/' "$good" > absent.yaml
sed 's/"Ti2 \[degC\]";/"Ti1 [degC]";/' "$LOG" > twice.csv
fail=0
check() {  # name, expected message part, command...
  name=$1 want=$2; shift 2
  rm -f out.* cal.yaml
  out=$("$@" 2>&1); rc=$?
  if [ $rc -eq 0 ] || ! echo "$out" | grep -qF "$want" || ls out.* cal.yaml > /dev/null 2>&1; then
    echo "FAIL $name (rc $rc): $out"; fail=1
  else
    echo "ok   $name: $(echo "$out" | tail -1)"
  fi
}
# each problem through another program (every program opens its logs through the same reader)
"$BIN/fog-calibrate" -q --format "$good" -i "$LOG" -o good_cal.yaml > /dev/null 2>&1
check "fog-convert, missing column" "missing.yaml: rates.z.column: missing" \
  "$BIN/fog-convert" --format missing.yaml -i "$LOG" -o out.rawlog --json out.json
check "fog-calibrate, duplicate column" "duplicate.yaml: thermistors.Ti2.column: column 'Ti1 [degC]' is already mapped by thermistors.Ti1" \
  "$BIN/fog-calibrate" -q --format duplicate.yaml -i "$LOG" -o cal.yaml --json out.json
check "fog-compensate, unknown unit" "unit.yaml: rates.z.unit: unknown rate unit 'dps'" \
  "$BIN/fog-compensate" -q --format unit.yaml -i "$LOG" --cal good_cal.yaml -o out.csv --json out.json
check "fog-calibrate, absent column" "absent.yaml: rates.z.column: no column 'GyroZ' in $LOG:2 (delimiter ';'; its columns: \"Status\", \"Time [ms]\", \"Gyro Z [deg/s]\"" \
  "$BIN/fog-calibrate" -q --format absent.yaml -i "$LOG" -o cal.yaml --json out.json
check "fog-evaluate, column twice" "column 'Ti1 [degC]' appears twice (columns 4 and 6)" \
  "$BIN/fog-evaluate" -q --format "$good" -i twice.csv --json out.json
[ $fail -eq 0 ] && echo "format_errors: every bad format stopped with its key named and no output"
