#pragma once
// What the Google Benchmarks of GL frames share (bench_frames.cpp, bench_plan_depth.cpp): the
// context, a sample by name and size and the names of tessellation settings.

#include <benchmark/benchmark.h>
#include <glad/gl.h>

#include <chrono>
#include <memory>
#include <string>

#include "core/support/error.h"
#include "render/gl/gl_context.h"
#include "render/gl/render_target.h"
#include "render/pipeline/surface_renderer.h"
#include "view/camera.h"

namespace gps::bench {

/// A sample mesh: NAME, or NAME:FACES where `faces` is not 0.
struct MeshCase {
  std::string name;
  int faces;
  std::string id() const { return name + (faces ? ":" + std::to_string(faces) : ""); }
};

/// One context for the whole run: the GPU's EGL device where there is one, else OSMesa.
inline GlContext& context() {
  static const std::unique_ptr<GlContext> c = create_offscreen_context(ContextKind::automatic);
  return *c;
}

/// "levelN" for a uniform level N, "adaptive6px" for 0 (adaptive levels of 6-pixel edges).
inline std::string setting_name(int level) { return level ? "level" + std::to_string(level) : "adaptive6px"; }

/// Times live frames (every patch evaluated, surface cache off) of `mesh` under `options`, 512x512,
/// at a uniform level (level > 0) or adaptive 6-pixel edges (level 0), as manual time; skipped with
/// the renderer's message where the mesh is refused (e.g. plan buffers past the storage-block limit).
inline void time_live_frames(benchmark::State& state, const CovarianceMesh& mesh, const PlanOptions& options,
                             int level) {
  context().make_current();
  SurfaceRenderer renderer;
  try {
    renderer.set_mesh(mesh, options);
  } catch (const Error& e) {
    state.SkipWithError(e.what());
    return;
  }
  const Camera camera = frame_mesh(mesh);
  RenderTarget target(512, 512);
  DrawOptions o;
  o.surface_cache = false;
  o.level = float(level > 0 ? level : 8);
  o.pixels = level > 0 ? 0.0f : 6.0f;
  renderer.draw(target, camera, o);
  glFinish();
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    renderer.draw(target, camera, o);
    glFinish();
    state.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  state.counters["patches"] = double(renderer.tables().plans.n_patches());
  state.counters["gpu_buffer_bytes"] = double(renderer.buffer_bytes());
}

}  // namespace gps::bench
