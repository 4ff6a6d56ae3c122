# Sourced by the build scripts: sets `launcher` to cmake's ccache options where ccache is installed
# (scripts/install_deps.sh installs it), with paths taken relative to the checkout and the working
# folder left out of the hash, so that one clone's objects serve another's identical compiles.
launcher=()
if command -v ccache >/dev/null; then
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}" CCACHE_NOHASHDIR=1
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
