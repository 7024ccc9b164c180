# Sourced by build.sh and fuzz.sh: compile through ccache when it is installed (install-deps.sh
# installs it) and NPSNET_NO_CCACHE is not 1. The cache (~/.cache/ccache, or CCACHE_DIR) keeps
# each object under a hash of its preprocessed source, compiler and flags, so a clean clone
# rebuilds only what changed since a build of any other clone on this machine:
#   CCACHE_BASEDIR: paths under the clone are hashed relative to it (a clone in another folder hits);
#   CCACHE_NOHASHDIR: the build folder is not hashed either (it names only debug info's comp_dir);
#   CCACHE_SLOPPINESS: the tests' precompiled headers are cached, and a header written moments
#     before the compile (a fresh clone, a .gch) does not make the object uncacheable.
# Sets ccache_on (1 or 0) and ccache_args: the CMake arguments that use it, or without ccache
# those that clear a launcher an earlier configure of the same build folder set. `ccache -s`
# shows hits.
ccache_on=0
ccache_args=(-DCMAKE_C_COMPILER_LAUNCHER= -DCMAKE_CXX_COMPILER_LAUNCHER=)
if [ "${NPSNET_NO_CCACHE:-0}" != "1" ] && command -v ccache >/dev/null 2>&1; then
  ccache_on=1
  export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
  export CCACHE_SLOPPINESS="pch_defines,time_macros,include_file_mtime,include_file_ctime"
  export CCACHE_MAXSIZE="${CCACHE_MAXSIZE:-20G}"  # three trees (build, ASan, fuzz) with debug info
  ccache_args=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
