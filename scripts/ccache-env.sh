# Sourced by run-tests.sh, run-sanitizers.sh and run-fuzz.sh: compile through ccache when it is
# installed, so that a build of unchanged sources (a clean clone in CI, a second build directory)
# takes its objects from the cache. Sets FOG_LAUNCHER (cmake arguments, empty without ccache).
#   FOG_CCACHE=0          no compiler cache
# Paths under the repository are hashed relative to it (CCACHE_BASEDIR), and the build folder is
# not hashed (CCACHE_NOHASHDIR), so clones at different paths share the cache. The cache's
# location and size are ccache's own settings (ccache -s shows them; docs/validation/ci-time.md).
FOG_LAUNCHER=()
if [ "${FOG_CCACHE:-1}" != 0 ] && command -v ccache >/dev/null; then
	FOG_LAUNCHER=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
	export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}"
	export CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"
fi
