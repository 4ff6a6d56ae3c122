// Frames against the cost of drawing the same triangles, as Google Benchmarks: per sample
// and tessellation setting, a live frame (every patch evaluated), a cached frame (the surface
// cache's stored triangles), a frame after a one-vertex edit (the cache refreshes that vertex's
// patches) and the floor (the cached triangles, welded, from a static vertex buffer, same shading).
// `unwelded` is the floor without shared vertices; `welded` and `captured` are cached frames with
// the stored vertices welded at each capture or never, whatever this device's default
// (render/cache/surface_cache.h). At adaptive levels, `capture` is a frame that captures everything
// again (as a camera move past the hysteresis does), from the patches' counts in one draw, and
// `queried_capture` the same with a query per block.
// `gpsurf bench --render` prints the same four in one table from a few repetitions each; this one
// lets Google Benchmark choose the iterations, as sub-millisecond frames on a GPU need.
// Names: Frame/<kind>/<mesh>/<setting>, e.g. Frame/floor/valence5/level16, Frame/cached/sphere:100000/adaptive6px.
#include <benchmark/benchmark.h>

#include <glad/gl.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <memory>

#include "bench/edit_scene.h"
#include "bench/gl_bench_cases.h"
#include "bench/run_benchmarks.h"
#include "render/gl/gl_object.h"
#include "render/gl/render_target.h"
#include "render/pipeline/surface_renderer.h"

namespace {

// unwelded: the floor's triangles with three vertices each, as the cache stores them (what sharing
// vertices saves on the device); update: the edit's compute passes alone, no frame.
enum class FrameKind { live, cached, edit, floor, unwelded, update, welded, captured, capture, queried_capture };
constexpr const char* kKindNames[] = {"live",   "cached", "edit",     "floor",   "unwelded",
                                      "update", "welded", "captured", "capture", "queried_capture"};

gps::TriangleMesh unwelded(const gps::TriangleMesh& welded) {
  gps::TriangleMesh soup;
  for (const auto& t : welded.triangles) {
    const int first = int(soup.positions.size());
    for (const int v : t) {
      soup.positions.push_back(welded.positions[size_t(v)]);
      soup.normals.push_back(welded.normals[size_t(v)]);
    }
    soup.triangles.push_back({first, first + 1, first + 2});
  }
  return soup;
}

using gps::bench::MeshCase;

// One renderer per mesh, kept for all its benchmarks (set_mesh of the 100k sphere is the slow
// part), with the edits of the edit-to-frame benchmarks (bench/edit_scene.h), drawn at 512².
struct Scene {
  gps::EditScene edits;
  gps::RenderTarget target{512, 512};
  gps::SurfaceCache::Weld weld_default;  // the surface cache's choice on this device
  explicit Scene(const MeshCase& m)
      : edits(m.name, m.faces, gps::PlanOptions{}), weld_default(edits.renderer().surface_cache().weld_mode()) {}
};

Scene& scene(const MeshCase& m) {
  static std::map<std::string, std::unique_ptr<Scene>> scenes;
  auto& s = scenes[m.id()];
  if (!s) s = std::make_unique<Scene>(m);
  return *s;
}

void BM_Frame(benchmark::State& state, MeshCase m, FrameKind kind, int level) {
  gps::bench::context().make_current();
  Scene& s = scene(m);
  gps::SurfaceRenderer& renderer = s.edits.renderer();
  gps::DrawOptions o;
  o.level = float(level > 0 ? level : 8);
  o.pixels = level > 0 ? 0.0f : 6.0f;
  o.surface_cache = kind != FrameKind::live;
  using Weld = gps::SurfaceCache::Weld;
  renderer.surface_cache().set_weld(kind == FrameKind::welded     ? Weld::at_capture
                                    : kind == FrameKind::captured ? Weld::off
                                                                  : s.weld_default);
  const bool captures_everything = kind == FrameKind::capture || kind == FrameKind::queried_capture;
  renderer.surface_cache().set_counted_captures(kind != FrameKind::queried_capture);
  // Fills the cache (or compiles the live programs); the second, still frame welds it where that
  // waits for one, as an editor's drag starts from a still frame.
  renderer.draw(s.target, s.edits.camera(), o);
  renderer.draw(s.target, s.edits.camera(), o);
  if (kind == FrameKind::floor || kind == FrameKind::unwelded) {
    if (!renderer.surface_cache().has_stored_triangles()) {
      state.SkipWithError("past the surface cache's memory limit: no stored triangles for a floor");
      return;
    }
    const gps::TriangleMesh stored = renderer.surface_cache().stored_triangles();
    renderer.set_triangles(kind == FrameKind::floor ? stored : unwelded(stored));
    o.static_triangles = true;
    state.counters["vertices"] =
        double(kind == FrameKind::floor ? stored.positions.size() : 3 * stored.triangles.size());
  }
  const std::vector<int> edited = s.edits.middle_vertices(1);
  const auto frame = [&] {
    if (kind == FrameKind::edit || kind == FrameKind::update) s.edits.edit(edited);
    if (captures_everything) o.pixels = o.pixels == 6.0f ? 6.001f : 6.0f;  // another key: everything captured again
    if (kind != FrameKind::update) renderer.draw(s.target, s.edits.camera(), o);
  };
  // Warm-up: the first frame of a kind may compile or allocate (reported apart as first_ms).
  auto start = std::chrono::steady_clock::now();
  frame();
  glFinish();
  const double first_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  frame();
  glFinish();
  // The GPU's own time of each frame (GL_TIME_ELAPSED): wall time beyond it is waiting and the CPU.
  const gps::GlQuery query(GL_TIME_ELAPSED);
  double gpu_ns = 0;
  const int captures = renderer.surface_cache().captures(), refreshes = renderer.surface_cache().refreshes();
  for (auto _ : state) {
    start = std::chrono::steady_clock::now();
    glBeginQuery(GL_TIME_ELAPSED, query);
    frame();
    glEndQuery(GL_TIME_ELAPSED);
    glFinish();
    state.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    GLuint64 ns = 0;
    glGetQueryObjectui64v(query, GL_QUERY_RESULT, &ns);
    gpu_ns += double(ns);
  }
  const gps::SurfaceCache& cache = renderer.surface_cache();
  state.counters["captures"] =
      double(cache.captures() - captures) / double(std::max<benchmark::IterationCount>(1, state.iterations()));
  state.counters["refreshes"] =
      double(cache.refreshes() - refreshes) / double(std::max<benchmark::IterationCount>(1, state.iterations()));
  state.counters["patches"] = double(renderer.tables().plans.n_patches());
  state.counters["gpu_ms"] = gpu_ns * 1e-6 / double(std::max<benchmark::IterationCount>(1, state.iterations()));
  state.counters["first_ms"] = first_ms;
  if (captures_everything) state.counters["counted"] = cache.last_capture_counted() ? 1.0 : 0.0;
  // The vertices a frame from the cache fetches (read back, after the timing).
  if (kind != FrameKind::live && kind != FrameKind::floor && kind != FrameKind::unwelded &&
      cache.has_stored_triangles())
    state.counters["vertices"] = double(cache.distinct_vertices());
}

}  // namespace

int main(int argc, char** argv) {
  // `gpsurf bench --render`'s samples, and the 100k-face sphere of the editor's figures.
  const std::vector<MeshCase> meshes = {{"cube", 0},     {"wirecube", 0},    {"cylinder", 0},
                                        {"valence5", 0}, {"cone-pointy", 0}, {"icosphere", 0},
                                        {"pawn", 0},     {"pawn-quads", 0},  {"sphere", 100000}};
  for (const MeshCase& m : meshes)
    for (const int level : {1, 4, 16, 64, 0})
      for (const FrameKind kind : {FrameKind::live, FrameKind::cached, FrameKind::edit, FrameKind::floor,
                                   FrameKind::unwelded, FrameKind::update, FrameKind::welded, FrameKind::captured,
                                   FrameKind::capture, FrameKind::queried_capture}) {
        if ((kind == FrameKind::capture || kind == FrameKind::queried_capture) && level > 0) continue;
        const std::string id = m.id() + "/" + gps::bench::setting_name(level);
        benchmark::RegisterBenchmark(("Frame/" + std::string(kKindNames[int(kind)]) + "/" + id).c_str(), BM_Frame, m,
                                     kind, level)
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond);
      }
  return gps::bench::run_benchmarks(argc, argv);
}
