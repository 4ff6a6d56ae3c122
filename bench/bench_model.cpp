// Modelling operation to the frame after it on spheres of 10,000, 100,000 and 1,000,000 faces, the
// figures `gpsurf bench --model` prints (bench/modelling_figures.h), as Google Benchmarks: each
// operation's medians, with its operation + re-plan + upload + frame as the time.
#include <benchmark/benchmark.h>

#include <map>
#include <memory>

#include "bench/modelling_figures.h"
#include "bench/run_benchmarks.h"
#include "render/gl/gl_context.h"

namespace {

constexpr int kOperations = 7;  // those modelling_figures times, in its order

const nlohmann::json& figures(int faces) {
  static const std::unique_ptr<gps::GlContext> context = gps::create_offscreen_context(gps::ContextKind::automatic);
  static std::map<int, nlohmann::json> measured;
  auto it = measured.find(faces);
  if (it == measured.end())
    it = measured.emplace(faces, gps::modelling_figures("sphere", faces, gps::PlanOptions{})).first;
  return it->second;
}

void BM_Model(benchmark::State& state) {
  const nlohmann::json& operation = figures(int(state.range(0)))["operations"].at(size_t(state.range(1)));
  for (auto _ : state) state.SetIterationTime(operation["total_ms"].get<double>() * 1e-3);
  state.SetLabel(operation["operation"].get<std::string>());
  for (const char* key : {"operation_ms", "replan_ms", "upload_ms", "frame_ms", "next_frame_ms", "pause_frame_ms",
                          "still_frame_ms", "undo_ms", "undo_frame_ms", "frame_gpu_ms", "still_gpu_ms", "frame_captures",
                          "frame_refreshed_patches",
                          "still_cached", "still_welded"})
    state.counters[key] = operation[key].get<double>();
}

BENCHMARK(BM_Model)
    ->ArgsProduct({{10000, 100000, 1000000}, benchmark::CreateDenseRange(0, kOperations - 1, 1)})
    ->ArgNames({"faces", "operation"})
    ->Iterations(1)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
