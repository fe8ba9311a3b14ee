#!/usr/bin/env bash
# CI hardening step: the sanitizer build + the default test suite under ASan/UBSan
# (scripts/run-sanitizers.sh), then each libFuzzer target for FUZZ_SECONDS (default 20 s,
# scripts/run-fuzz.sh). Exits non-zero on the first failure. Prints the time of each part.
#   scripts/ci-hardening.sh
# Environment: FUZZ_SECONDS (default 20), JOBS (default 2), and those of the two scripts.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
fuzz_s=${FUZZ_SECONDS:-20}
t0=$(date +%s)
"$here/run-sanitizers.sh"
t1=$(date +%s)
"$here/run-fuzz.sh" "$fuzz_s"
t2=$(date +%s)
echo "ci-hardening: sanitizers + tests $((t1 - t0)) s, fuzzing $((t2 - t1)) s, total $((t2 - t0)) s"
