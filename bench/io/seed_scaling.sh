#!/usr/bin/env bash
# Flat memory and linear time at 1 kHz (target 2): the seed paper's chamber profile
# held 75 min longer at 60 C (8 h: 25 -> -40 -> 60 C at 1 C/min, 2 h and 3 h 15 min soaks),
# simulated by fog-sim at 100 Hz (2.88 M samples) and 1 kHz (28.8 M samples). Per rate and program:
# wall and CPU time (user + sys), peak RSS (/usr/bin/time), and the ratio of the time to
# `gzip -dc` of the same rawlog in the same run. Programs: fog-convert rawlog -> .csv.gz,
# fog-compensate rawlog -> rawlog, fog-calibrate (default model), fog-evaluate (the 100 Hz
# calibration), fog-discrepancy (the same calibration; 1 s block means), fog-drift is not here (a
# drive: docs/reference/logs.md). Everything under `nice`.
#   bench/io/seed_scaling.sh BIN_DIR WORK ["100 1000"]
# WORK needs about 1 GB at 1 kHz (rawlog 280 MB, .csv.gz, compensated rawlog; $TMPDIR holds
# fog-calibrate's spill, 2.7 GB at 28.8 M); the large files are deleted after each rate.
# Prints a markdown table, also WORK/seed_scaling.md. Last run: docs/reference/logs.md, "Size and speed".
set -euo pipefail
profile_dir=$(cd "$(dirname "$0")" && pwd)
bin=$(cd "$1" && pwd)
work=$2
rates=${3:-"100 1000"}
mkdir -p "$work"
cd "$work"
cp "$profile_dir/seed8h.yaml" seed8h.yaml
table=seed_scaling.md
echo "| rate | samples | program | wall [s] | CPU [s] | peak RSS [MB] | wall / gzip -dc | CPU / gzip -dc |" >$table
echo "|---|---|---|---|---|---|---|---|" >>$table
measure() {  # measure RATE N LABEL CMD...
	local rate=$1 n=$2 label=$3
	shift 3
	/usr/bin/time -f "%e %U %S %M" -o t.txt nice "$@" >/dev/null 2>err.txt || { echo "FAILED: $label: $(tail -1 err.txt)"; return 1; }
	read -r wall user sys rss <t.txt
	awk -v r="$rate" -v n="$n" -v l="$label" -v w="$wall" -v u="$user" -v s="$sys" -v m="$rss" -v ref="${REF_WALL:-0}" -v refc="${REF_CPU:-0}" 'BEGIN {
		printf "| %s Hz | %.2f M | %s | %.1f | %.1f | %.0f | %s | %s |\n", r, n / 1e6, l, w, u + s, m / 1024,
			(ref > 0 ? sprintf("%.2f", w / ref) : "1"), (refc > 0 ? sprintf("%.2f", (u + s) / refc) : "1") }' | tee -a $table
	LAST_WALL=$wall
	LAST_CPU=$(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.3f", u + s }')
}
for rate in $rates; do
	log=seed8h_$rate.rawlog
	nice "$bin/fog-sim" -p seed8h.yaml --rate-hz "$rate" -o "$log" --json sim_$rate.json >/dev/null
	n=$(sed -n 's/.*"samples": *\([0-9]*\).*/\1/p' sim_$rate.json)
	REF_WALL=0 REF_CPU=0
	measure "$rate" "$n" "gzip -dc (reference)" sh -c "gzip -dc $log >/dev/null"
	REF_WALL=$LAST_WALL REF_CPU=$LAST_CPU
	measure "$rate" "$n" "fog-convert rawlog -> .csv.gz" "$bin/fog-convert" -i "$log" -o conv_$rate.csv.gz -q
	rm -f conv_$rate.csv.gz
	measure "$rate" "$n" "fog-calibrate" "$bin/fog-calibrate" -i "$log" -o cal_$rate.yaml -q
	[ -f cal.yaml ] || cp cal_$rate.yaml cal.yaml  # the first rate's calibration for the others
	measure "$rate" "$n" "fog-compensate rawlog -> rawlog" "$bin/fog-compensate" -i "$log" --cal cal.yaml -o comp_$rate.rawlog -q
	rm -f comp_$rate.rawlog
	measure "$rate" "$n" "fog-evaluate --cal" "$bin/fog-evaluate" -i "$log" --cal cal.yaml -q
	measure "$rate" "$n" "fog-discrepancy --model cal.yaml" "$bin/fog-discrepancy" --measured "$log" --model cal.yaml -q
	rm -f "$log"
done
