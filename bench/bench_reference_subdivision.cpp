// Reference GPS subdivision (in 9D + limit projection): Catmull-Clark on the parametric sphere, Loop
// on the icosphere.
#include <benchmark/benchmark.h>

#include "core/reference/reference_subdivision.h"
#include "core/modelling/samples.h"

namespace {

void BM_ReferenceSubdivision(benchmark::State& state, gps::Scheme scheme) {
  const gps::CovarianceMesh mesh =
      gps::make_sample(scheme == gps::Scheme::loop ? "icosphere" : "sphere", int(state.range(0)));
  const gps::SubdivisionOptions options{scheme, int(state.range(1)), true};
  for (auto _ : state) benchmark::DoNotOptimize(gps::subdivide(mesh, options));
  state.counters["faces"] = double(mesh.n_faces());
  state.counters["ns_per_base_face"] = benchmark::Counter(
      double(mesh.n_faces()), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK_CAPTURE(BM_ReferenceSubdivision, catmull_clark, gps::Scheme::catmull_clark)
    ->ArgsProduct({{1000, 10000, 100000}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_ReferenceSubdivision, loop, gps::Scheme::loop)
    ->ArgsProduct({{5000, 20000}, {1, 3}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
