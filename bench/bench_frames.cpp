// Frames against the cost of drawing the same triangles (issue 12), as Google Benchmarks: per sample
// and tessellation setting, a live frame (every patch evaluated), a cached frame (the surface
// cache's stored triangles), a frame after a one-vertex edit (the cache refreshes that vertex's
// patches) and the floor (the cached triangles, welded, from a static vertex buffer, same shading).
// `gpsurf bench --render` prints the same four in one table from a few repetitions each; this one
// lets Google Benchmark choose the iterations, as sub-millisecond frames on a GPU need.
// Names: Frame/<kind>/<mesh>/<setting>, e.g. Frame/floor/valence5/level16, Frame/cached/sphere:100000/adaptive6px.
#include <benchmark/benchmark.h>

#include <glad/gl.h>

#include <chrono>
#include <map>
#include <memory>

#include "core/samples.h"
#include "render/gl_context.h"
#include "render/render_target.h"
#include "render/surface_renderer.h"
#include "view/camera.h"

namespace {

enum class FrameKind { live, cached, edit, floor };
constexpr const char* kKindNames[] = {"live", "cached", "edit", "floor"};

struct MeshCase {
  std::string name;
  int faces;
};

gps::GlContext& context() {
  static const std::unique_ptr<gps::GlContext> c = gps::create_offscreen_context(gps::ContextKind::automatic);
  return *c;
}

// One renderer per mesh, kept for all its benchmarks (set_mesh of the 100k sphere is the slow part).
struct Scene {
  gps::CovarianceMesh mesh;
  gps::SurfaceRenderer renderer;
  gps::Camera camera;
  gps::RenderTarget target{512, 512};
  bool grow = true;  // the edit scales a covariance by 1.1, the next one back
  explicit Scene(const MeshCase& m) : mesh(gps::make_sample(m.name, m.faces)) {
    renderer.set_mesh(mesh, gps::PlanOptions{});
    camera = gps::frame_mesh(mesh);
  }
};

Scene& scene(const MeshCase& m) {
  static std::map<std::string, std::unique_ptr<Scene>> scenes;
  auto& s = scenes[m.name + "/" + std::to_string(m.faces)];
  if (!s) s = std::make_unique<Scene>(m);
  return *s;
}

void BM_Frame(benchmark::State& state, MeshCase m, FrameKind kind, int level) {
  context().make_current();
  Scene& s = scene(m);
  gps::DrawOptions o;
  o.level = float(level > 0 ? level : 8);
  o.pixels = level > 0 ? 0.0f : 6.0f;
  o.surface_cache = kind != FrameKind::live;
  s.renderer.draw(s.target, s.camera, o);  // fills the cache (or compiles the live programs)
  if (kind == FrameKind::floor) {
    if (!s.renderer.surface_cache().holds_triangles()) {
      state.SkipWithError("past the surface cache's memory limit: no stored triangles for a floor");
      return;
    }
    s.renderer.set_triangles(s.renderer.surface_cache().stored_triangles());
    o.static_triangles = true;
  }
  const int edited = int(s.mesh.n_vertices() / 2);
  s.renderer.draw(s.target, s.camera, o);
  glFinish();
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    if (kind == FrameKind::edit) {
      s.mesh.set_covariance(size_t(edited), s.mesh.covariance(size_t(edited)) * (s.grow ? 1.1 : 1.0 / 1.1));
      s.grow = !s.grow;
      s.renderer.update_vertices(s.mesh, {edited});
    }
    s.renderer.draw(s.target, s.camera, o);
    glFinish();
    state.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  state.counters["patches"] = double(s.renderer.tables().plans.n_patches());
}

}  // namespace

int main(int argc, char** argv) {
  // `gpsurf bench --render`'s samples, and the 100k-face sphere of the editor's figures.
  const std::vector<MeshCase> meshes = {{"cube", 0},     {"wirecube", 0}, {"cylinder", 0}, {"valence5", 0},  {"cone-pointy", 0},
                                        {"icosphere", 0}, {"pawn", 0},     {"pawn-quads", 0}, {"sphere", 100000}};
  for (const MeshCase& m : meshes)
    for (const int level : {1, 4, 16, 64, 0})
      for (const FrameKind kind : {FrameKind::live, FrameKind::cached, FrameKind::edit, FrameKind::floor}) {
        const std::string id = m.name + (m.faces ? ":" + std::to_string(m.faces) : "") + "/" +
                               (level ? "level" + std::to_string(level) : std::string("adaptive6px"));
        benchmark::RegisterBenchmark(("Frame/" + std::string(kKindNames[int(kind)]) + "/" + id).c_str(), BM_Frame, m, kind, level)
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond);
      }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
