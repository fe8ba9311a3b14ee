#!/usr/bin/env bash
# I/O throughput and memory of the programs on logs of 1, 4 and 16 M samples.
#   bench/io/io_throughput.sh BIN_DIR WORK [sizes in M samples, default "1 4 16"]
# For each size: a synthetic 100 Hz chamber log (bench/io/make_log.py, through a FIFO into
# fog-convert: CSV -> rawlog), then per program wall time, CPU time, peak RSS (/usr/bin/time) and
# samples/s, beside `gzip -dc` of the same rawlog in the same run (the reference: reading a
# rawlog cannot be faster than decompressing it), as ratios of wall time and of CPU time (CPU
# time is the steadier one on a shared machine). Everything runs under `nice`. Large files go
# to WORK (never the repository). Prints a markdown table; also WORK/io_throughput.md.
# Not part of the test suite (minutes at 16 M samples). fog-drift needs a drive log and
# fog-discrepancy does not finish on millions of samples (docs/reference/logs.md): neither is measured.
# Last run and its table: docs/reference/logs.md, "Size and speed".
set -euo pipefail
bin=$(cd "$1" && pwd)
work=$2
sizes=${3:-"1 4 16"}
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$work"
cd "$work"
table=io_throughput.md
echo "| samples | program | wall [s] | CPU [s] | peak RSS [MB] | samples/s (wall) | wall / gzip -dc | CPU / gzip -dc |" >$table
echo "|---|---|---|---|---|---|---|---|" >>$table
measure() {  # measure LABEL N REF_WALL REF_CPU CMD...
	local label=$1 n=$2 ref=$3 refc=$4
	shift 4
	/usr/bin/time -f "%e %U %S %M" -o t.txt nice "$@" >/dev/null 2>err.txt || { echo "FAILED: $label: $(tail -1 err.txt)"; return 1; }
	read -r wall user sys rss <t.txt
	awk -v l="$label" -v n="$n" -v w="$wall" -v u="$user" -v s="$sys" -v r="$rss" -v ref="$ref" -v refc="$refc" 'BEGIN {
		printf "| %.2f M | %s | %.2f | %.2f | %.0f | %.0f k | %s | %s |\n", n / 1e6, l, w, u + s, r / 1024, n / w / 1e3,
			(ref > 0 ? sprintf("%.2f", w / ref) : "1"), (refc > 0 ? sprintf("%.2f", (u + s) / refc) : "1") }' | tee -a $table
	LAST_WALL=$wall
	LAST_CPU=$(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.3f", u + s }')
}
for m in $sizes; do
	n=$(awk -v m="$m" 'BEGIN { printf "%d", m * 1e6 }')
	rm -f gen.csv && mkfifo gen.csv
	python3 "$here/make_log.py" "$n" >gen.csv &
	nice "$bin/fog-convert" -i gen.csv -o log_$m.rawlog -q >/dev/null
	wait
	rm -f gen.csv
	measure "gzip -dc (reference)" "$n" 0 0 sh -c "gzip -dc log_$m.rawlog >/dev/null"
	ref=$LAST_WALL refc=$LAST_CPU
	measure "fog-convert rawlog -> csv.gz" "$n" "$ref" "$refc" "$bin/fog-convert" -i log_$m.rawlog -o log_$m.csv.gz -q
	measure "fog-convert csv.gz -> rawlog" "$n" "$ref" "$refc" "$bin/fog-convert" -i log_$m.csv.gz -o back_$m.rawlog -q
	[ "$m" = "$(echo $sizes | cut -d' ' -f1)" ] && nice "$bin/fog-calibrate" -i log_$m.rawlog --model M2:Ti1@2/1 -o cal.yaml >/dev/null
	measure "fog-compensate rawlog -> rawlog" "$n" "$ref" "$refc" "$bin/fog-compensate" -i log_$m.rawlog --cal cal.yaml -o comp_$m.rawlog -q
	measure "fog-calibrate" "$n" "$ref" "$refc" "$bin/fog-calibrate" -i log_$m.rawlog --model M2:Ti1@2/1 -o cal_$m.yaml
	measure "fog-evaluate --cal" "$n" "$ref" "$refc" "$bin/fog-evaluate" -i log_$m.rawlog --cal cal.yaml
	rm -f log_$m.csv.gz back_$m.rawlog comp_$m.rawlog
done
