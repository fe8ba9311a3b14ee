#!/bin/sh
# Runs the quickstart of docs/guide/calibrate-your-gyro.md (its first ```sh block, as written)
# on examples/your_gyro/, with the built programs first on PATH: every command must succeed,
# every output be written, and no unit warning be printed; the drafted format file must read the
# example the same way as the checked one (the same samples; it differs in thermistor sides).
# usage: guide_quickstart.sh SOURCE_DIR APPS_BIN_DIR WORK
set -eu
SRC=$1 BIN=$2 W=$3
rm -rf "$W"; mkdir -p "$W"; cd "$W"
ln -s "$SRC/examples" examples
awk '/^```sh/{f=1;next} /^```/{if(f)exit} f' "$SRC/docs/guide/calibrate-your-gyro.md" > quickstart.sh
[ "$(grep -vc '^#' quickstart.sh)" -ge 5 ]
PATH="$BIN:$PATH" sh -e quickstart.sh > out.txt 2> err.txt || { cat out.txt err.txt; exit 1; }
for f in my_gyro.yaml cal.yaml run2_comp.csv run2.rawlog; do [ -s "$f" ] || { echo "missing $f"; exit 1; }; done
if grep -q "warning" err.txt; then cat err.txt; exit 1; fi
grep -q 'note: .*1 column not in the format .*ignored: "Status"' err.txt
grep "compensated" out.txt | head -3
# the draft reads the same samples as the checked format file
"$BIN/fog-convert" -q --format my_gyro.yaml -i examples/your_gyro/chamber_run1.csv -o draft.csv > /dev/null 2>&1
"$BIN/fog-convert" -q --format examples/your_gyro/my_gyro.yaml -i examples/your_gyro/chamber_run1.csv -o checked.csv > /dev/null 2>&1
grep -v '^#' draft.csv > draft_rows.csv
grep -v '^#' checked.csv > checked_rows.csv
cmp draft_rows.csv checked_rows.csv
echo "guide_quickstart: the quickstart runs"
