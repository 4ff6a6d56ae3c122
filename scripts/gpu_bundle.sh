#!/usr/bin/env bash
# Packs what checks gpsurf on another machine's GPU into DIR (default out/gpu-bundle, about 90 MB) and
# DIR.tar.xz (about 8 MB: the binaries share their static libraries, which xz's large window finds):
# the GL tests that need no OpenImageIO (no image format besides PNG) and the frame benchmarks, stripped, with the shared
# libraries they need beyond glibc, libstdc++ and the GL loader (libEGL). On the GPU machine:
#   DIR/run.sh OUT [tests|bench|all]
# runs the GL tests on the GPU's EGL device (GPSURF_TEST_CONTEXT=egl) and the benchmarks, writing
# logs and JSON to OUT. The tests read their data from this checkout's path, as compiled in: run.sh
# needs the checkout (tests/data) at the same path there, or a link to it.
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-out/gpu-bundle}
tests=()
for source in tests/render/test_*.cpp; do
  # Only tests whose libraries a GPU machine has: not those of EXR or other formats than PNG (OpenImageIO's module).
  if grep -q "gl_fixture\|GlTest" "$source" && ! grep -q '\.exr\|openimageio_files' "$source"; then
    tests+=("$(basename "$source" .cpp)")
  fi
done
benches=(gpsurf_bench_frames gpsurf_bench_plan_depth gpsurf_bench_edit gpsurf_bench_creases gpsurf_bench_model)
# Builds only what the bundle packs: on a fresh machine the whole suite takes far longer.
scripts/build.sh $(printf -- '--target %s ' "${tests[@]}" "${benches[@]}")
rm -rf "$dir" && mkdir -p "$dir/bin" "$dir/lib"
for t in "${tests[@]}"; do
  strip -o "$dir/bin/$t" "build/tests/$t"
done
for b in "${benches[@]}"; do
  strip -o "$dir/bin/$b" "build/bench/$b"
done
for l in $(ldd "$dir/bin/gpsurf_bench_frames" "$dir/bin/${tests[0]}" | awk '/=>/ {print $3}' | sort -u); do
  case "$(basename "$l")" in
    libc.so*|libm.so*|libstdc++*|libgcc_s*|libEGL*|libGLdispatch*|ld-linux*) ;;
    *) cp -L "$l" "$dir/lib/" ;;
  esac
done
cat > "$dir/run.sh" <<RUN
#!/usr/bin/env bash
# GL tests on the GPU (EGL) and frame benchmarks; logs and JSON into \$1. Built from $(git rev-parse --short HEAD).
# Checkout: $(pwd)
set -u
here=\$(cd "\$(dirname "\$0")" && pwd)
out=\${1:?usage: run.sh OUT [tests|bench|all]}; mode=\${2:-all}
mkdir -p "\$out"
export LD_LIBRARY_PATH="\$here/lib\${LD_LIBRARY_PATH:+:\$LD_LIBRARY_PATH}"
if [ "\$mode" != bench ]; then
  for t in ${tests[*]}; do
    GPSURF_TEST_CONTEXT=egl timeout 120 "\$here/bin/\$t" > "\$out/\$t.log" 2>&1
    echo "\$t exit \$?" | tee -a "\$out/tests.txt"
  done
fi
if [ "\$mode" != tests ]; then
  # Live, edited and floor frames of three meshes at two settings, and full captures from counts and
  # by a query per block at adaptive levels: all the cases take longer than a device session holds.
  "\$here/bin/gpsurf_bench_frames" --benchmark_min_time=0.1 \\
    --benchmark_filter='^Frame/(live|edit|floor|capture|queried_capture)/(wirecube|pawn|sphere:100000)/(level16|adaptive6px)' \\
    --benchmark_out="\$out/frames.json" --benchmark_out_format=json | tee "\$out/frames.txt"
  # Creased frames against smooth ones (sub-millisecond on a GPU: half a second each).
  "\$here/bin/gpsurf_bench_creases" --benchmark_min_time=0.5 \\
    --benchmark_filter='^Frame/(wirecube|sphere:6144)/(smooth|sharp|semi2.5)/adaptive6px' | tee "\$out/creases.txt"
  "\$here/bin/gpsurf_bench_edit" --benchmark_min_time=0.2 | tee "\$out/edit.txt"
  # Modelling operations to the frame after them, at 10k and 100k faces, then 1M.
  "\$here/bin/gpsurf_bench_model" --benchmark_out="\$out/model.json" --benchmark_out_format=json | tee "\$out/model.txt"
  # Exact plans (depth 2) against the thesis' depth 3, on the wirecube's many extraordinary nodes.
  "\$here/bin/gpsurf_bench_plan_depth" --benchmark_min_time=0.2 --benchmark_filter='wirecube/(approx3|exact2)' | tee "\$out/plan_depth.txt"
fi
RUN
chmod +x "$dir/run.sh"
# The archive is what travels to a lent machine (scripts/gpu_session.sh unpacks it there): the
# directory is past what its remote command tool carries.
tar -C "$(dirname "$dir")" -cf - "$(basename "$dir")" | xz -T0 -6 --lzma2=dict=96MiB > "$dir.tar.xz"
echo "$dir: ${#tests[@]} GL tests and 5 benchmarks, $(du -sh "$dir" | cut -f1) ($dir.tar.xz: $(du -sh "$dir.tar.xz" | cut -f1));" \
  "run $dir/run.sh OUT on the GPU machine"
