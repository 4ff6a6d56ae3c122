# Sourced by the build scripts: sets `launcher` to cmake's ccache options where ccache is installed
# (scripts/install_deps.sh installs it), with paths taken relative to the checkout and the working
# folder left out of the hash, so that one clone's objects serve another's identical compiles. The
# tests compile with a precompiled header, which ccache caches only with these sloppiness settings
# (ccache's manual, "Precompiled headers"): without them every test is compiled again.
launcher=()
if command -v ccache >/dev/null; then
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}" CCACHE_NOHASHDIR=1
  export CCACHE_SLOPPINESS="${CCACHE_SLOPPINESS:-pch_defines,time_macros,include_file_mtime,include_file_ctime}"
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
