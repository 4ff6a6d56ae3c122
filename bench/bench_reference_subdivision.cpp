// Reference GPS subdivision (Catmull-Clark in 9D + limit projection) on the parametric sphere.
#include <benchmark/benchmark.h>

#include "core/reference_subdivision.h"
#include "core/samples.h"

namespace {

void BM_ReferenceSubdivision(benchmark::State& state) {
  const gps::CovarianceMesh mesh = gps::make_sample("sphere", int(state.range(0)));
  const gps::SubdivisionOptions options{gps::Scheme::catmull_clark, int(state.range(1)), true};
  for (auto _ : state) benchmark::DoNotOptimize(gps::subdivide(mesh, options));
  state.counters["faces"] = double(mesh.n_faces());
  state.counters["ns_per_base_face"] =
      benchmark::Counter(double(mesh.n_faces()), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_ReferenceSubdivision)
    ->ArgsProduct({{1000, 10000, 100000}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
