# Sourced by run-tests.sh, run-sanitizers.sh and run-fuzz.sh: the build settings they share.
# Sets FOG_BUILD_ARGS (cmake arguments); fog_generator and fog_seed_test_costs are below.
#   FOG_UNITY=OFF   one object per source file (default ON: a CMake unity build, batches of 8
#                   sources of a target compiled as one unit; the headers of MRPT, Eigen and
#                   GoogleTest are parsed once per batch instead of once per file, which is most of
#                   the compile time; docs/validation/ci-time.md). A unity build needs the file-local
#                   names of a target's sources to be distinct (docs/architecture.md).
#   FOG_CCACHE=0    no compiler cache (default: ccache when installed)
# With ccache, paths under the repository are hashed relative to it (CCACHE_BASEDIR) and the
# build folder is not hashed (CCACHE_NOHASHDIR), so clones at different paths share the cache.
FOG_BUILD_ARGS=("-DCMAKE_UNITY_BUILD=${FOG_UNITY:-ON}" -DCMAKE_UNITY_BUILD_BATCH_SIZE=8)
if [ "${FOG_CCACHE:-1}" != 0 ] && command -v ccache >/dev/null; then
	FOG_BUILD_ARGS+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
	export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}"
	export CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"
fi

# fog_generator <build dir>: sets FOG_GENERATOR to "-G Ninja" for a new build folder when ninja
# is installed (scripts/setup.sh installs it): unlike make, ninja compiles a target's sources
# while the libraries it links are still being built, so both cores stay busy. A folder that
# already has a CMakeCache.txt keeps the generator it was made with.
fog_generator() {
	FOG_GENERATOR=()
	if [ ! -f "$1/CMakeCache.txt" ] && command -v ninja >/dev/null; then
		FOG_GENERATOR=(-G Ninja)
	fi
}

# fog_seed_test_costs <build dir> <cost file>: on a build folder that has never run its tests,
# ctest has no record of how long each test takes and starts them in declaration order, so a
# long test started last runs alone at the end. The recorded costs (tests/ctest_costs/, refreshed
# by scripts/update-test-costs.sh) let it start the longest first. Tests are not changed or
# skipped by this: it orders them only.
fog_seed_test_costs() {
	local dest="$1/Testing/Temporary/CTestCostData.txt"
	if [ ! -f "$dest" ] && [ -f "$2" ]; then
		mkdir -p "$(dirname "$dest")"
		cp "$2" "$dest"
	fi
}
