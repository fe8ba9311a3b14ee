#!/usr/bin/env bash
# fog-evaluate time against length at one rate (time linear in length): the 8 h seed
# profile of seed_scaling.sh simulated at 1 kHz, cut to 2.88 M samples (--duration-s 2880) and
# whole (28.8 M samples). Per length: `gzip -dc` of the rawlog (the reference) and
# `fog-evaluate -i LOG --cal cal.yaml -q` of each BIN_DIR given (e.g. before and after a change),
# REPEATS times, alternating; CPU (user + sys), wall, peak RSS, and CPU / gzip -dc CPU.
#   bench/io/evaluate_scaling.sh WORK REPEATS BIN_DIR [BIN_DIR2 ...]
# WORK needs about 320 MB (the 1 kHz rawlogs; deleted at the end). cal.yaml: fog-calibrate on
# the 2.88 M log. Prints a markdown table, also WORK/evaluate_scaling.md.
set -euo pipefail
profile_dir=$(cd "$(dirname "$0")" && pwd)
work=$1
repeats=$2
shift 2
bins=()
for b in "$@"; do bins+=("$(cd "$b" && pwd)"); done
mkdir -p "$work"
cd "$work"
cp "$profile_dir/seed8h.yaml" seed8h.yaml
sim=${bins[0]}/fog-sim
[ -f short.rawlog ] || nice "$sim" -p seed8h.yaml --rate-hz 1000 --duration-s 2880 -o short.rawlog >/dev/null
[ -f long.rawlog ] || nice "$sim" -p seed8h.yaml --rate-hz 1000 -o long.rawlog >/dev/null
[ -f cal.yaml ] || nice "${bins[0]}/fog-calibrate" -i short.rawlog -o cal.yaml -q >/dev/null
table=evaluate_scaling.md
echo "| log | program | CPU [s] | wall [s] | peak RSS [MB] | CPU / gzip -dc |" >$table
echo "|---|---|---|---|---|---|" >>$table
run() {  # run LOG LABEL CMD...
	local log=$1 label=$2
	shift 2
	/usr/bin/time -f "%e %U %S %M" -o t.txt nice "$@" >/dev/null 2>err.txt || { echo "FAILED: $label: $(tail -1 err.txt)"; return 1; }
	read -r wall user sys rss <t.txt
	cpu=$(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.2f", u + s }')
	awk -v g="$log" -v l="$label" -v c="$cpu" -v w="$wall" -v m="$rss" -v ref="${REF_CPU:-0}" 'BEGIN {
		printf "| %s | %s | %.2f | %.1f | %.1f | %s |\n", g, l, c, w, m / 1024, (ref > 0 ? sprintf("%.2f", c / ref) : "1") }' | tee -a $table
}
for r in $(seq "$repeats"); do
	for log in short.rawlog long.rawlog; do
		REF_CPU=0
		run $log "gzip -dc" sh -c "gzip -dc $log >/dev/null"
		REF_CPU=$cpu
		for b in "${bins[@]}"; do run $log "$b/fog-evaluate" "$b/fog-evaluate" -i $log --cal cal.yaml -q; done
	done
done
