// Preprocessing on 1 and 2 cores: the default plans + stencil table (build_surface_plans) and the
// reference subdivision (2 levels + limit) of a 1M-face sphere, with the tables' memory per face.
// The results are the same bit for bit on any number of cores (tests/core/test_plan_builder.cpp).
#include <benchmark/benchmark.h>
#include <omp.h>
#include <sys/resource.h>

#include "core/plans/planned_surface.h"
#include "core/reference/reference_subdivision.h"
#include "core/modelling/samples.h"

namespace {

const gps::CovarianceMesh& sphere() {
  static const gps::CovarianceMesh mesh = gps::make_sample("sphere", 1'000'000);
  return mesh;
}

double peak_rss_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) * 1024.0;
}

void BM_BuildPlansOnCores(benchmark::State& state) {
  const gps::CovarianceMesh& mesh = sphere();
  const gps::PolygonTopology& topology = mesh.topology();
  omp_set_num_threads(int(state.range(0)));
  size_t table_bytes = 0;
  for (auto _ : state) {
    const gps::SurfaceTables t = gps::build_surface_plans(topology, gps::PlanOptions{});
    table_bytes = t.bytes();
  }
  omp_set_num_threads(omp_get_num_procs());
  const double faces = double(mesh.n_faces());
  state.counters["cores"] = double(state.range(0));
  state.counters["faces"] = faces;
  state.counters["table_bytes_per_face"] = double(table_bytes) / faces;
  state.counters["peak_rss_bytes_per_face"] = peak_rss_bytes() / faces;
}

void BM_ReferenceSubdivisionOnCores(benchmark::State& state) {
  const gps::CovarianceMesh& mesh = sphere();
  omp_set_num_threads(int(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(gps::subdivide(mesh, {gps::Scheme::catmull_clark, 2, true}));
  omp_set_num_threads(omp_get_num_procs());
  state.counters["cores"] = double(state.range(0));
  state.counters["faces"] = double(mesh.n_faces());
}

BENCHMARK(BM_BuildPlansOnCores)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);
BENCHMARK(BM_ReferenceSubdivisionOnCores)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

}  // namespace
