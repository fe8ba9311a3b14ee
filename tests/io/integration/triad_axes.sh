#!/bin/sh
# Every axis through every program: a three-axis calibration is evaluated per axis by
# fog-evaluate (a table each, --axis picks one), and fog-compensate's CSV and rawlog are read
# back as logs:
# its compensated rates evaluated without --cal give, axis by axis, the compensated stability
# fog-evaluate --cal reports (the same numbers; the CSV has no table-rate column, which on this
# run holds only the constant Earth rate: the means differ, the spreads do not).
# usage: triad_axes.sh FOG_EVALUATE FOG_COMPENSATE FOG_CONVERT CHAMBER3.rawlog CAL3.yaml WORK
set -eu
EVAL=$1 COMP=$2 CONV=$3 RUN=$4 CAL=$5 W=$6
rm -rf "$W"; mkdir -p "$W"; cd "$W"
"$EVAL" -q -i "$RUN" --cal "$CAL" --json ev.json > ev.txt
[ "$(grep -c '^fog-evaluate: .* axis [xyz], tau' ev.txt)" -eq 3 ]
grep -q '"axes"' ev.json
"$EVAL" -q -i "$RUN" --cal "$CAL" --axis y > ev_y.txt
[ "$(grep -c '^fog-evaluate: .* axis y, tau' ev_y.txt)" -eq 1 ] && ! grep -q 'axis [xz], tau' ev_y.txt
"$COMP" -q -i "$RUN" --cal "$CAL" -o comp.csv > /dev/null
"$EVAL" -q -i comp.csv --json back.json > back.txt 2> back.err
grep -q "fog-compensate's output: its compensated rates are read as the rates" back.err
python3 - <<'PY'
import json
ev, back = json.load(open("ev.json")), json.load(open("back.json"))
for a in "xyz":
    c = ev["axes"][a]["compensated"]["stability_dph"]
    b = back["axes"][a]["raw"]["stability_dph"]
    print("axis %s: compensated stability %.9g deg/h (--cal), %.9g deg/h (fog-compensate's CSV read back)" % (a, c, b))
    assert abs(c - b) <= 1e-9 * max(abs(c), 1e-12), a
PY
# fog-compensate's rawlog (stock CObservationIMU + CObservationRawDAQ) read back the same way
"$COMP" -q -i "$RUN" --cal "$CAL" -o comp.rawlog > /dev/null
"$EVAL" -q -i comp.rawlog --json back_rawlog.json > back_rawlog.txt 2> back_rawlog.err
grep -q "read from stock MRPT observations" back_rawlog.err
python3 - <<'PY'
import json
ev, back = json.load(open("ev.json")), json.load(open("back_rawlog.json"))
for a in "xyz":
    c = ev["axes"][a]["compensated"]["stability_dph"]
    b = back["axes"][a]["raw"]["stability_dph"]
    print("axis %s: compensated stability %.9g deg/h (--cal), %.9g deg/h (fog-compensate's rawlog read back)" % (a, c, b))
    assert abs(c - b) <= 1e-9 * max(abs(c), 1e-12), a
PY
# and by the other programs
"$CONV" -q -i comp.csv -o back.rawlog > /dev/null
"$CONV" -q -i comp.rawlog -o back_stock.csv > /dev/null
"$EVAL" -q -i back.rawlog --axis z > /dev/null
echo "triad_axes: every axis evaluated and read back"
