#!/usr/bin/env bash
# One device-tool run on a lent NVIDIA machine: the GL tests on its EGL device and the benchmarks
# of out/gpu-bundle (scripts/gpu_bundle.sh, built here first), their logs packed into one file
# under $OUT (the tool returns at most 8), and a summary printed. Here, once:
#   echo /.gl/ >> .git/info/exclude; mkdir -p .gl /tmp/amd64/partial
#   o='-oAPT::Architecture=amd64 -oAPT::Architectures=amd64 -oDir::State::Lists=/tmp/amd64'
#   apt-get $o update; (cd .gl && apt-get $o download libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2)
#   scripts/gpu_bundle.sh
# then the device tool's run with carry [".gl", "out/gpu-bundle.tar.xz"] (the bundle itself is past
# the 64 MiB the tool carries): scripts/gpu_session.sh [tests|bench|all]
set -u
cd "$(dirname "$0")/.."
if [ -f out/gpu-bundle.tar.xz ]; then tar -C out -xJf out/gpu-bundle.tar.xz; fi
for f in .gl/*.deb; do [ -e "$f" ] && dpkg -x "$f" /; done
ldconfig
export __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
# The tests read tests/data from the path compiled in (the checkout where the bundle was built).
built_in=$(sed -n 's/^# GL tests .* Built from \([0-9a-f]*\)\.$/\1/p' out/gpu-bundle/run.sh | head -1)
checkout=$(sed -n 's/^# Checkout: //p' out/gpu-bundle/run.sh | head -1)
if [ -n "$checkout" ] && [ ! -e "$checkout" ]; then mkdir -p "$(dirname "$checkout")" && ln -s "$PWD" "$checkout"; fi
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader || true
results=$(mktemp -d)
# Bounded, so that what ran is packed even where the device session is short (GPSURF_GPU_SECONDS).
timeout "${GPSURF_GPU_SECONDS:-420}" out/gpu-bundle/run.sh "$results" "${1:-all}" > "$results/run.txt" 2>&1
echo "bundle built from ${built_in:-?}"
cat "$results/tests.txt" 2>/dev/null
grep -h "FAILED  \]\|Failure" "$results"/test_*.log 2>/dev/null | sort -u | head -40
grep -h "x5000\|x200 " "$results/test_comparison_images.log" 2>/dev/null
grep -h "^Frame\|^Preprocess" "$results/plan_depth.txt" "$results/creases.txt" 2>/dev/null
grep -h "^BM_Model" "$results/model.txt" 2>/dev/null
tar -czf "${OUT:-out}/gpu-results.tgz" -C "$results" .
echo "logs: ${OUT:-out}/gpu-results.tgz"
