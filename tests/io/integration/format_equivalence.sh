#!/bin/sh
# A logger CSV read through its format file gives the same calibration and held-out figures as the
# native CSV of the same samples. The vendor files are written by scripts/vendor_layout.py (Python,
# independent of the C++ readers) from the bundled chamber runs A (fit) and B (held out), every
# N-th row: other column names, time in ms, rates in deg/s, temperatures in K, semicolons, quoted
# header cells, an extra status column (some cells quoted with the delimiter inside), CRLF, two
# preamble lines.
# usage: format_equivalence.sh FOG_CALIBRATE FOG_EVALUATE SOURCE_DIR WORK [EVERY [MAX_ROWS]]
# (MAX_ROWS 0: the whole runs)
set -eu
CAL=$1 EVAL=$2 SRC=$3 W=$4 EVERY=${5:-10} MAX_ROWS=${6:-0}
rm -rf "$W"; mkdir -p "$W"; cd "$W"
for r in A B; do
  python3 "$SRC/scripts/vendor_layout.py" "$SRC/datasets/chamber_$r.csv.gz" --every "$EVERY" --max-rows "$MAX_ROWS" --temp-unit K \
    --native "n_$r.csv" --vendor "v_$r.csv" --format "v_$r.yaml"
done
cmp v_A.yaml v_B.yaml  # one format file serves both runs
"$CAL" -q -i n_A.csv --validate n_B.csv -o cal_n.yaml --json cal_n.json > cal_n.txt
"$CAL" -q --format v_A.yaml -i v_A.csv --validate v_B.csv -o cal_v.yaml --json cal_v.json > cal_v.txt 2> cal_v.err
grep -q 'note: v_A.csv: 1 column not in the format v_A.yaml, ignored: "Status"' cal_v.err
if grep -q "warning" cal_v.err; then cat cal_v.err; exit 1; fi
"$EVAL" -q -i n_B.csv --cal cal_n.yaml --json ev_n.json > /dev/null
"$EVAL" -q --format v_A.yaml -i v_B.csv --cal cal_v.yaml --json ev_v.json > /dev/null 2>&1
grep -A3 "held out\|validation" cal_v.txt | head -8 || true
for f in cal.yaml cal.json ev.json; do
  b=${f%.*} e=${f##*.}
  python3 "$SRC/tests/io/integration/compare_numbers.py" "${b}_n.$e" "${b}_v.$e" 1e-6
done
echo "format_equivalence: same calibration and figures"
