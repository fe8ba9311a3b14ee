#!/usr/bin/env bash
# Refreshes the recorded test durations that order ctest's first run on a new build folder
# (tests/ctest_costs/; scripts/build-env.sh, fog_seed_test_costs). Run after a full default suite:
#   scripts/update-test-costs.sh [release build dir, default build] [sanitizer build dir, default build-asan]
# Copies each folder's Testing/Temporary/CTestCostData.txt (written by ctest: per test, the run
# count and the average duration in s), keeping only the tests that still exist. The costs only
# order the tests (longest first); a stale entry changes nothing else.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
copy() {
	local src="$1/Testing/Temporary/CTestCostData.txt" dest="$here/tests/ctest_costs/$2"
	if [ ! -f "$src" ]; then
		echo "update-test-costs: $src missing (run the suite in $1 first); $2 kept" >&2
		return 0
	fi
	mkdir -p "$(dirname "$dest")"
	# drop the list of failed tests after the "---" line: a recorded failure is not a cost
	sed '/^---$/q' "$src" >"$dest"
	echo "update-test-costs: $dest: $(grep -c . "$dest") tests"
}
copy "${1:-$here/build}" release.txt
copy "${2:-$here/build-asan}" sanitizers.txt
