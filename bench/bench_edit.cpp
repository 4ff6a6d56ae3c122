// Edit-to-frame on a 100k-face sphere, the scene `gpsurf bench --edit` times
// (bench/edit_scene.h): a frame alone, and an edit of 1 or 16 vertices followed by a frame.
#include <benchmark/benchmark.h>

#include <memory>

#include "bench/edit_scene.h"
#include "render/gl/gl_context.h"

namespace {

gps::EditScene& scene() {
  static const std::unique_ptr<gps::GlContext> context = gps::create_offscreen_context(gps::ContextKind::automatic);
  static gps::EditScene s("sphere", 100000, gps::PlanOptions{});
  return s;
}

void BM_Frame(benchmark::State& state) {
  gps::EditScene& s = scene();
  s.frame();
  for (auto _ : state) s.frame();
}

void BM_EditToFrame(benchmark::State& state) {
  gps::EditScene& s = scene();
  const std::vector<int> vertices = s.middle_vertices(int(state.range(0)));
  s.frame();
  for (auto _ : state) {
    s.edit(vertices);
    s.frame();
  }
}

BENCHMARK(BM_Frame)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EditToFrame)->Arg(1)->Arg(16)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace
