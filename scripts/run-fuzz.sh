#!/usr/bin/env bash
# Builds the libFuzzer targets (clang++, ASan + UBSan, build-fuzz/) and runs each for a fixed time.
#   scripts/run-fuzz.sh [seconds per target, default 30] [target ...]
# Targets: fuzz_csv fuzz_rawlog fuzz_calibration_yaml fuzz_options fuzz_log_format (default: all). Seeds come from
# tests/fuzz_corpus/<target>/; new interesting inputs go to build-fuzz/corpus/<target>/ (not in git).
# A crash leaves build-fuzz/artifacts/<target>/crash-* and makes the script exit non-zero;
# reproduce with: build-fuzz/fuzz/<target> <crash file>.
# Environment: BUILD_DIR (default <repo>/build-fuzz), JOBS (default 2).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
secs=${1:-30}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_csv fuzz_rawlog fuzz_calibration_yaml fuzz_options fuzz_log_format)
build=${BUILD_DIR:-$here/build-fuzz}
jobs=${JOBS:-2}

source "$here/scripts/build-env.sh"  # unity build, ccache when installed
fog_generator "$build"
CXX=clang++ cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMRPT_FOG_BUILD_FUZZ=ON "${FOG_GENERATOR[@]}" "${FOG_BUILD_ARGS[@]}" \
	-DMRPT_FOG_BUILD_TESTS=OFF -DMRPT_FOG_BUILD_APPS=OFF -DMRPT_FOG_BUILD_BENCH=OFF >/dev/null
cmake --build "$build" -j"$jobs" --target "${targets[@]}"

# MRPT's own libraries are not instrumented; their one-time allocations at exit are not ours.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=0:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
# One target per core at a time (JOBS): each still runs its full time, its own corpus and log.
run_one() {
	local t=$1 corpus="$build/corpus/$1" art="$build/artifacts/$1"
	mkdir -p "$corpus" "$art"
	"$build/fuzz/$t" -max_total_time="$secs" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
		-artifact_prefix="$art/" "$corpus" "$here/tests/fuzz_corpus/$t" 2>"$build/$t.log"
}
status=0
declare -A pid_of
for t in "${targets[@]}"; do
	while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n || true; done
	echo "== $t: ${secs} s"
	run_one "$t" &
	pid_of[$t]=$!
done
for t in "${targets[@]}"; do
	if ! wait "${pid_of[$t]}"; then
		echo "!! $t FAILED: see $build/$t.log and $build/artifacts/$t/"
		tail -30 "$build/$t.log"
		status=1
	fi
	echo "== $t done"
	grep -E "stat::number_of_executed_units|stat::peak_rss_mb|#[0-9]+.*DONE" "$build/$t.log" | sed 's/^/   /' || true
done
exit $status
