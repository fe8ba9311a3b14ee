#!/usr/bin/env bash
# CI hardening step, one line in .ci/run after the normal build and tests:
#     ./scripts/ci-hardening.sh
# 1. the ASan + UBSan build and the whole default test suite under it (scripts/run-sanitizers.sh,
#    build-asan/, proof trials at FOG_TRIAL_SEEDS seeds per cell, default 1);
# 2. each libFuzzer target for FUZZ_SECONDS (default 20 s) from the seed corpus in
#    tests/fuzz_corpus/ (scripts/run-fuzz.sh, clang++, build-fuzz/).
# Exits non-zero if either part fails (a failing or sanitizer-reported test, a fuzzer finding);
# both parts always run. Prints the time of each part. Measured cost: docs/validation/hardening.md.
# Environment: FUZZ_SECONDS (default 20), JOBS (default nproc), and those of the two scripts.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
fuzz_s=${FUZZ_SECONDS:-20}
if ! command -v clang++ >/dev/null; then
	echo "ci-hardening: clang++ not found (needed for the libFuzzer targets): apt-get install clang" >&2
	exit 1
fi
status=0
t0=$(date +%s)
"$here/run-sanitizers.sh" || { status=1; echo "ci-hardening: sanitizer run FAILED"; }
t1=$(date +%s)
"$here/run-fuzz.sh" "$fuzz_s" || { status=1; echo "ci-hardening: fuzzing FAILED"; }
t2=$(date +%s)
echo "ci-hardening: sanitizer build + tests $((t1 - t0)) s, fuzzing (build + 5 targets x ${fuzz_s} s, ${JOBS:-2} at a time) $((t2 - t1)) s," \
	"total $((t2 - t0)) s, load $(cut -d' ' -f1-3 /proc/loadavg), status $status"
exit $status
