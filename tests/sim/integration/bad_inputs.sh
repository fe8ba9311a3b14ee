#!/usr/bin/env bash
# Bad input: one-line error naming the file and field, non-zero exit, no output file left.
# Usage: bad_inputs.sh FOG_SIM WORK_DIR
set -uo pipefail
SIM=$1 WORK=$2
rm -rf "$WORK" && mkdir -p "$WORK" && cd "$WORK"
fail=0
expect_error() {  # expect_error PATTERN ARGS...
	local pattern=$1; shift
	local err rc
	err=$("$SIM" "$@" 2>&1 >/dev/null); rc=$?
	if [ $rc -eq 0 ]; then echo "expected failure: $*"; fail=1; return; fi
	if ! echo "$err" | grep -q -- "$pattern"; then echo "error for [$*] lacks '$pattern': $err"; fail=1; fi
	if [ "$(echo "$err" | wc -l)" -ne 1 ]; then echo "error for [$*] is not one line: $err"; fail=1; fi
	if [ -e out.rawlog ] || ls out.rawlog.tmp-* >/dev/null 2>&1; then echo "output left by [$*]"; fail=1; fi
}
printf 'segments:\n  - {type: ramp, to_C: 5, rate_C_per_min: -1}\n' >bad_rate.yaml
printf 'segments:\n  - {type: hold, duration_min: 10}\n  - {type: warp, to_C: 3}\n' >bad_type.yaml
printf 'segments: [\n' >broken.yaml
printf 'errors: {radial_gradient_dph_per_C: 0.1, typo_key: 1}\n' >bad_device.yaml
expect_error "bad_rate.yaml: segments\[0\].rate_C_per_min" --profile bad_rate.yaml -o out.rawlog
expect_error "bad_type.yaml: segments\[1\].type" --profile bad_type.yaml -o out.rawlog
expect_error "broken.yaml" --profile broken.yaml -o out.rawlog
expect_error "no_such.yaml" --profile no_such.yaml -o out.rawlog
expect_error "unknown profile preset 'nope'" --profile nope -o out.rawlog
expect_error "bad_device.yaml: errors.typo_key" --profile seed --device bad_device.yaml -o out.rawlog
expect_error "unknown effect 'shupe'" --profile seed --effect shupe -o out.rawlog
expect_error "--rate-hz .0.: out of range" --profile seed --rate-hz 0 -o out.rawlog
expect_error "must end in" --profile seed -o out.txt
exit $fail
