#!/usr/bin/env bash
# Installs the Debian 12 packages gpsurf builds, tests and runs with (as root; skips what is there).
set -euo pipefail
packages=(
  cmake g++ ninja-build pkg-config python3-glad
  libopenmesh-dev libeigen3-dev libglm-dev libopenimageio-dev openimageio-tools libpng-dev
  libglfw3-dev libosmesa6-dev libegl-dev libgl-dev libimgui-dev
  libgl1-mesa-dri libglx-mesa0 libegl-mesa0
  libcli11-dev nlohmann-json3-dev libtinygltf-dev libgtest-dev libgmock-dev libbenchmark-dev
  libcgal-dev  # header-only: the AABB tree of surface distances (core/fitting/)
  libosd-dev  # OpenSubdiv: the peer benchmark (bench/) and the crease reference test, never linked into core, render or app
  xvfb xauth fonts-dejavu-core
  clang libclang-rt-14-dev libomp-dev  # the fuzzers (clang, with OpenMP in core)
  pybind11-dev python3-dev python3-numpy python3-pytest  # the Python module and its tests
  python3-setuptools python3-wheel python3-pip python3-venv python3-mypy  # its wheel and stubs, tested
  ccache clang-format lld  # lld: the tests' links (CMakeLists.txt)
  time  # GNU time: the hostile-input soak measures gpsurf's peak memory with it (tests/render/)
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
