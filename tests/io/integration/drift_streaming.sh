#!/usr/bin/env bash
# fog-drift streams a single-axis drive (apps/fog-drift/StreamingDrive.h: two reads, memory that
# does not grow with the drive) and must give the figures of the in-memory evaluation
# (--in-memory, the path --plots takes): the same JSON (10 significant digits),
# the same text, and with --csv / --odometry-out the same files.
# Drives from fog-sim (turns, straights, FOG_IDEAL, odometry, truth at the FOG rate), the
# calibration fitted by fog-calibrate on datasets/chamber_A.rawlog; two drives at once, and the
# options that change the arithmetic (no calibration, no screening, instantaneous sampling,
# the calibration's Earth rate) each once.
#   drift_streaming.sh FOG_SIM FOG_CALIBRATE FOG_DRIFT SOURCE_DIR WORK_DIR
set -euo pipefail
sim=$1 calibrate=$2 drift=$3 src=$4 work=$5
mkdir -p "$work"
cd "$work"
"$calibrate" -q -i "$src/datasets/chamber_A.rawlog" -o cal.yaml >/dev/null
"$sim" -p drive --rate-hz 2 -o d1.rawlog >/dev/null
"$sim" -p drive --rate-hz 5 --seed 3 --cabin drive_cabin_mild --duration-s 1800 -o d2.rawlog >/dev/null
run() {  # run NAME OPTIONS...: streaming vs --in-memory
	local name=$1
	shift
	"$drift" -q "$@" --json "s_$name.json" >"s_$name.txt"
	"$drift" -q --in-memory "$@" --json "m_$name.json" >"m_$name.txt"
	cmp "s_$name.json" "m_$name.json" || { echo "JSON differs: $name"; diff "s_$name.json" "m_$name.json" | head; exit 1; }
	cmp "s_$name.txt" "m_$name.txt" || { echo "text differs: $name"; diff "s_$name.txt" "m_$name.txt" | head; exit 1; }
	echo "same: $name"
}
run two_drives -i d1.rawlog -i d2.rawlog --cal cal.yaml
run no_cal -i d1.rawlog
run no_screening -i d2.rawlog --cal cal.yaml --no-screening
run instantaneous -i d2.rawlog --cal cal.yaml --rate-sampling instantaneous
run cal_earth -i d2.rawlog --cal cal.yaml --cal-latitude-deg 10 --latitude-deg 50
# --csv streams too (the per-sample series spilled to temporary files): the same CSV, JSON and
# text as the in-memory path's
"$drift" -q -i d2.rawlog --cal cal.yaml --csv s_csv.csv --json s_csv.json >s_csv.txt
"$drift" -q --in-memory -i d2.rawlog --cal cal.yaml --csv m_csv.csv --json m_csv.json >m_csv.txt
for f in csv.csv csv.json csv.txt; do
	cmp "s_$f" "m_$f" || { echo "--csv: $f differs: streamed vs --in-memory"; diff "s_$f" "m_$f" | head; exit 1; }
done
[ "$(wc -l <s_csv.csv)" -gt 1000 ] || { echo "--csv: too few rows"; exit 1; }
echo "same: --csv"
# --odometry-out streams too: the same rawlog, with and without a calibration (compensated / raw)
for c in cal none; do
	opt=(); [ $c = cal ] && opt=(--cal cal.yaml)
	"$drift" -q -i d2.rawlog "${opt[@]}" --odometry-out "s_odo_$c.rawlog" --csv "s_odo_$c.csv" >/dev/null
	"$drift" -q --in-memory -i d2.rawlog "${opt[@]}" --odometry-out "m_odo_$c.rawlog" --csv "m_odo_$c.csv" >/dev/null
	cmp "s_odo_$c.rawlog" "m_odo_$c.rawlog" || { echo "--odometry-out ($c) differs: streamed vs --in-memory"; exit 1; }
	cmp "s_odo_$c.csv" "m_odo_$c.csv" || { echo "--csv with --odometry-out ($c) differs"; exit 1; }
done
echo "same: --odometry-out"
# the figures are numbers, not all zero or null (the comparison compares something); the JSON
# holds 10 significant digits
grep -Eq '"compensated": [0-9]\.[0-9]*[1-9]' s_two_drives.json
grep -Eq '^  compensated +0\.[0-9]*[1-9]' s_two_drives.txt
echo "streaming == in memory"
