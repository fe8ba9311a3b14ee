#!/usr/bin/env bash
# fog-discrepancy on the 100 Hz seed-profile chamber run (peak RSS <= 300 MB at 2.43 M
# samples): `fog-sim -p seed --rate-hz 100`, its calibration by fog-calibrate, then
# fog-discrepancy with that calibration and with the multipoint preset, and with the bundled
# 10 Hz chamber runs A (analysed) and B (confirmation). Per command: wall and CPU time (user +
# sys), peak RSS (/usr/bin/time), and the CPU and wall ratios to `gzip -dc` of the same first
# file in the same run. Everything under `nice`.
#   bench/io/discrepancy_memory.sh BIN_DIR WORK [EXTRA fog-discrepancy ARGS, e.g. --block-s 0]
# WORK needs about 60 MB. Prints a markdown table, also WORK/discrepancy_memory.md.
set -euo pipefail
bin=$(cd "$1" && pwd)
src=$(cd "$(dirname "$0")/../.." && pwd)
work=$2
shift 2
extra=("$@")
mkdir -p "$work"
cd "$work"
[ -f seed100.rawlog ] || nice "$bin/fog-sim" -p seed --rate-hz 100 -o seed100.rawlog >/dev/null
[ -f cal.yaml ] || nice "$bin/fog-calibrate" -i seed100.rawlog -o cal.yaml -q >/dev/null
table=discrepancy_memory.md
echo "| command | wall [s] | CPU [s] | peak RSS [MB] | wall / gzip -dc | CPU / gzip -dc |" >$table
echo "|---|---|---|---|---|---|" >>$table
measure() {  # measure LABEL CMD...
	local label=$1
	shift
	/usr/bin/time -f "%e %U %S %M" -o t.txt nice "$@" >out.txt 2>err.txt || { echo "FAILED: $label: $(tail -1 err.txt)"; return 1; }
	read -r wall user sys rss <t.txt
	awk -v l="$label" -v w="$wall" -v u="$user" -v s="$sys" -v m="$rss" -v ref="${REF_WALL:-0}" -v refc="${REF_CPU:-0}" 'BEGIN {
		printf "| %s | %.1f | %.1f | %.0f | %s | %s |\n", l, w, u + s, m / 1024,
			(ref > 0 ? sprintf("%.2f", w / ref) : "1"), (refc > 0 ? sprintf("%.2f", (u + s) / refc) : "1") }' | tee -a $table
	LAST_WALL=$wall
	LAST_CPU=$(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.3f", u + s }')
}
for pair in "seed100.rawlog cal.yaml" "seed100.rawlog multipoint" "$src/datasets/chamber_A.rawlog multipoint $src/datasets/chamber_B.rawlog"; do
	set -- $pair
	log=$1 model=$2 confirm=${3:-}
	REF_WALL=0 REF_CPU=0
	measure "gzip -dc $(basename "$log") (reference)" sh -c "gzip -dc $log >/dev/null"
	REF_WALL=$LAST_WALL REF_CPU=$LAST_CPU
	args=(--measured "$log" --model "$model")
	[ -n "$confirm" ] && args+=(--measured "$confirm")
	measure "fog-discrepancy --measured $(basename "$log")${confirm:+ --measured $(basename "$confirm")} --model $model ${extra[*]:-}" \
		"$bin/fog-discrepancy" "${args[@]}" "${extra[@]}"
done
