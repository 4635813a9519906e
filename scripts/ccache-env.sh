# Sourced by the build scripts: when ccache is installed, ZDG_LAUNCHER holds the CMake flag that
# puts it in front of the compiler, with the settings that let it serve this tree from any clone
# (CCACHE_BASEDIR: paths under the clone become relative) and with precompiled headers
# (sloppiness: the PCH's defines and timestamps). Without ccache, ZDG_LAUNCHER is empty.
# ZDG_CCACHE=0 turns it off.
ZDG_LAUNCHER=()
if [ "${ZDG_CCACHE:-1}" != 0 ] && command -v ccache >/dev/null 2>&1; then
  ZDG_LAUNCHER=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  CCACHE_BASEDIR=${CCACHE_BASEDIR:-$(pwd -P)}
  CCACHE_SLOPPINESS=${CCACHE_SLOPPINESS:-pch_defines,time_macros,include_file_mtime,include_file_ctime}
  export CCACHE_BASEDIR CCACHE_SLOPPINESS
fi
