#!/usr/bin/env bash
# Files are sacred: the programs never destroy a file the user had.
#   files_sacred.sh BIN_DIR SOURCE_DIR WORK
# - an output equal to an input (any spelling, hard link) or to another output is refused,
#   exit 1, the file byte-identical;
# - --json into a missing directory fails before the main output is written;
# - an output that is a FIFO is written into, not replaced; a symlink output is written through;
# - an existing output keeps its mode;
# - SIGTERM during a long write leaves no temporary file and the previous output intact.
set -u
bin=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 2
fail=0
bad() { echo "FAIL: $*"; fail=1; }
expect_refused() {  # expect_refused WHAT PATTERN FILE... -- CMD...
	local what=$1 pattern=$2; shift 2
	local files=()
	while [ "$1" != "--" ]; do files+=("$1"); shift; done
	shift
	local sums_before sums_after
	sums_before=$(md5sum "${files[@]}" 2>/dev/null)
	"$@" >out.txt 2>err.txt
	local rc=$?
	sums_after=$(md5sum "${files[@]}" 2>/dev/null)
	[ $rc -eq 1 ] || bad "$what: exit $rc, expected 1"
	grep -q -- "$pattern" err.txt || bad "$what: error lacks '$pattern': $(cat err.txt)"
	[ "$(wc -l <err.txt)" -eq 1 ] || bad "$what: error is not one line"
	[ "$sums_before" = "$sums_after" ] || bad "$what: a file changed"
	echo "ok: $what: $(cat err.txt)"
}
cp "$src/tests/data/io/sample.csv" run.csv
cp "$src/datasets/chamber_A.rawlog" A.rawlog
"$bin/fog-calibrate" -i A.rawlog --model M1@2 -o cal.yaml >/dev/null || bad "calibration failed"
ln run.csv hard.csv

expect_refused "convert -o = -i" "same file as the input" run.csv -- "$bin/fog-convert" -i run.csv -o run.csv
expect_refused "convert -o = ./-i" "same file as the input" run.csv -- "$bin/fog-convert" -i run.csv -o ./run.csv
expect_refused "convert -o = hard link of -i" "same file as the input" run.csv -- "$bin/fog-convert" -i run.csv -o hard.csv
expect_refused "convert --json = -i" "same file as the input" run.csv -- "$bin/fog-convert" -i run.csv -o x.rawlog --json run.csv
expect_refused "calibrate -o = -i" "same file as the input" A.rawlog -- "$bin/fog-calibrate" -i A.rawlog -o A.rawlog
expect_refused "calibrate --json = -o" "same file as -o" cal.yaml -- "$bin/fog-calibrate" -i A.rawlog -o cal.yaml --json cal.yaml
expect_refused "compensate --json = --cal" "same file as the input --cal" cal.yaml -- "$bin/fog-compensate" -i A.rawlog --cal cal.yaml -o c.csv --json cal.yaml
expect_refused "evaluate --json = --cal" "same file as the input --cal" cal.yaml -- "$bin/fog-evaluate" -i A.rawlog --cal cal.yaml --json cal.yaml
[ -e x.rawlog ] && bad "convert wrote x.rawlog although --json was refused"
[ -e c.csv ] && bad "compensate wrote c.csv although --json was refused"

# --json into a missing directory: refused before the main output is written.
"$bin/fog-calibrate" -i A.rawlog --model M1@2 -o new.yaml --json nodir/fit.json >/dev/null 2>err.txt
rc=$?
[ $rc -eq 1 ] || bad "calibrate --json nodir: exit $rc"
[ -e new.yaml ] && bad "calibrate wrote new.yaml before failing on --json nodir/"
grep -q "does not exist" err.txt || bad "calibrate --json nodir: $(cat err.txt)"

# A FIFO output is written into (a reader gets the JSON), not replaced by a file.
mkfifo pipe.json
cat pipe.json >from_pipe.txt &
reader=$!
"$bin/fog-convert" -i run.csv -o y.rawlog --json pipe.json >/dev/null || bad "convert --json FIFO failed"
wait $reader
[ -p pipe.json ] || bad "the FIFO was replaced"
grep -q '"samples"' from_pipe.txt || bad "nothing came through the FIFO"

# A symlink output is written through to its target; the link stays.
mkdir -p real && cp cal.yaml real/cal.yaml && ln -s real/cal.yaml link.yaml
"$bin/fog-calibrate" -i A.rawlog --model M2@2/1 -o link.yaml >/dev/null || bad "calibrate -o symlink failed"
[ -L link.yaml ] || bad "the symlink output was replaced by a file"
grep -q 'preset: "M2@2/1"' real/cal.yaml || bad "the symlink's target was not written"

# An existing output keeps its mode.
chmod 600 cal.yaml
"$bin/fog-calibrate" -i A.rawlog --model M1@2 -o cal.yaml >/dev/null || bad "recalibration failed"
[ "$(stat -c %a cal.yaml)" = 600 ] || bad "mode of cal.yaml changed to $(stat -c %a cal.yaml)"

# SIGTERM while a conversion writes its output: no temporary left, previous output intact.
# (Retried when the program finished before the temporary was seen.)
caught=0
for attempt in 1 2 3 4 5 6 7 8; do
	echo previous >big.csv
	"$bin/fog-convert" -i A.rawlog -o big.csv >/dev/null 2>&1 &
	pid=$!
	while kill -0 $pid 2>/dev/null; do
		if ls big.csv.tmp-* >/dev/null 2>&1; then kill -TERM $pid; break; fi
		sleep 0.002
	done
	wait $pid
	rc=$?
	ls big.csv.tmp-* >/dev/null 2>&1 && bad "SIGTERM: temporary file left: $(ls big.csv.tmp-*)"
	if [ $rc -eq 143 ]; then
		caught=1
		[ "$(cat big.csv)" = previous ] || bad "SIGTERM: previous output not intact"
		echo "ok: SIGTERM during the write (attempt $attempt): no temporary left, previous output intact"
		break
	fi
done
[ $caught -eq 1 ] || bad "SIGTERM: never caught the program while writing (8 attempts)"

[ $fail -eq 0 ] && echo "all file-safety checks passed"
exit $fail
