// Modelling operation to the frame after it on spheres of 10,000, 100,000 and 1,000,000 quads (Catmull-Clark)
// and icospheres of about as many triangles (Loop), the figures `gpsurf bench --model` prints
// (bench/modelling_figures.h), as Google Benchmarks: each operation's medians, with its operation + re-plan +
// upload + frame as the time.
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <utility>

#include "bench/modelling_figures.h"
#include "bench/run_benchmarks.h"
#include "render/gl/gl_context.h"

namespace {

constexpr int kOperations = 14;          // those modelling_figures times, in its order
constexpr int kInset = 1, kLoopCut = 2;  // which a mesh of triangles leaves out
const char* const kMeshes[] = {"sphere", "icosphere"};

const nlohmann::json& figures(int mesh, int faces) {
  static const std::unique_ptr<gps::GlContext> context = gps::create_offscreen_context(gps::ContextKind::automatic);
  static std::map<std::pair<int, int>, nlohmann::json> measured;
  auto it = measured.find({mesh, faces});
  if (it == measured.end())
    it = measured.emplace(std::pair{mesh, faces}, gps::modelling_figures(kMeshes[mesh], faces, gps::PlanOptions{}))
             .first;
  return it->second;
}

void BM_Model(benchmark::State& state) {
  const nlohmann::json& operation =
      figures(int(state.range(0)), int(state.range(1)))["operations"].at(size_t(state.range(2)));
  if (operation.contains("skipped")) {  // refused by this mesh, or it would change its scheme
    state.SkipWithError(("skipped: " + operation["skipped"].get<std::string>()).c_str());
    for (auto _ : state) {
    }
    return;
  }
  for (auto _ : state) state.SetIterationTime(operation["total_ms"].get<double>() * 1e-3);
  state.SetLabel(operation["operation"].get<std::string>());
  for (const char* key : {"operation_ms", "replan_ms", "upload_ms", "frame_ms", "next_frame_ms", "pause_frame_ms",
                          "still_frame_ms", "first_edit_ms", "undo_ms", "undo_frame_ms", "frame_gpu_ms", "still_gpu_ms",
                          "frame_captures", "frame_refreshed_patches", "still_cached", "still_welded"})
    state.counters[key] = operation[key].get<double>();
}

// The icosphere's sizes are 20·4^k faces: those nearest the sphere's.
void model_cases(benchmark::internal::Benchmark* b) {
  for (const int faces : {10000, 100000, 1000000})
    for (int operation = 0; operation < kOperations; ++operation) b->Args({0, faces, operation});
  for (const int faces : {5120, 81920, 1310720})
    for (int operation = 0; operation < kOperations; ++operation)
      if (operation != kInset && operation != kLoopCut) b->Args({1, faces, operation});
}

BENCHMARK(BM_Model)
    ->Apply(model_cases)
    ->ArgNames({"mesh", "faces", "operation"})
    ->Iterations(1)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
