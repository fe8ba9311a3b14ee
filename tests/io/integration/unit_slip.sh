#!/bin/sh
# A unit slip does not pass silently: the example logger export read with its rate declared in
# deg/h although the numbers are deg/s (the slip of a renamed column) gives a warning naming the
# likely unit on stderr and under input_notices.unit_warnings in --json; the correct format file
# gives none.
# usage: unit_slip.sh APPS_BIN_DIR SOURCE_DIR WORK
set -eu
BIN=$1 SRC=$2 W=$3
rm -rf "$W"; mkdir -p "$W"; cd "$W"
LOG=$SRC/examples/your_gyro/chamber_run1.csv
sed 's/unit: deg\/s}/unit: deg\/h}/' "$SRC/examples/your_gyro/my_gyro.yaml" > slip.yaml
"$BIN/fog-calibrate" -q --format slip.yaml -i "$LOG" -o cal.yaml --json cal.json > out.txt 2> err.txt || true
cat err.txt
grep -q "warning: units: .*chamber_run1.csv: Gyro Z \[deg/s\]: declared deg/h, but its sample-to-sample noise .*: likely deg/s" err.txt
python3 -c "import json,sys; w=json.load(open('cal.json'))['input_notices']['unit_warnings']; sys.exit(0 if len(w)==1 and 'likely deg/s' in w[0]['message'] else 1)"
"$BIN/fog-evaluate" -q --format "$SRC/examples/your_gyro/my_gyro.yaml" -i "$LOG" --json ok.json > /dev/null 2> ok.err
if grep -q warning ok.err; then cat ok.err; exit 1; fi
echo "unit_slip: named"
