// Subdivision plans: preprocessing (build_plans), full stencil application and the incremental
// update of one vertex, per sample mesh at depth 3.
#include <benchmark/benchmark.h>

#include <algorithm>

#include "core/mesh/dual_map.h"
#include "core/plans/plan_builder.h"
#include "core/modelling/samples.h"
#include "core/plans/stencil_table.h"

namespace {

struct Case {
  const char* name;
  int size;
};
// valence3..10 are cheap; the sphere at ~250 faces stands in for the thesis' anvil.
constexpr Case kCases[] = {{"cube", 0},      {"wirecube", 0},   {"valence3", 0},  {"valence6", 0},
                           {"valence10", 0}, {"sphere", 250},   {"grid", 1000},   {"sphere", 1000},
                           {"grid", 10000},  {"sphere", 10000}, {"grid", 100000}, {"sphere", 100000}};

struct Prepared {
  gps::CovarianceMesh mesh;
  gps::SurfaceTables tables;
  std::vector<gps::Dual> q;
};

Prepared prepare(const Case& c) {
  Prepared p{gps::make_sample(c.name, c.size), {}, {}};
  p.tables = gps::build_plans(p.mesh.topology(), 3);
  p.q = gps::base_points(p.mesh);
  return p;
}

void label(benchmark::State& state, const Case& c, const Prepared& p) {
  state.SetLabel(std::string(c.name) + (c.size ? "/" + std::to_string(c.size) : ""));
  state.counters["faces"] = double(p.mesh.n_faces());
  state.counters["rows"] = double(p.tables.stencils.n_rows());
  state.counters["nnz"] = double(p.tables.stencils.indices.size());
  state.counters["node_ints"] = double(p.tables.plans.nodes.size());
}

void BM_BuildPlans(benchmark::State& state) {
  const Case& c = kCases[state.range(0)];
  const Prepared p = prepare(c);
  const gps::PolygonTopology& topology = p.mesh.topology();
  for (auto _ : state) benchmark::DoNotOptimize(gps::build_plans(topology, 3));
  label(state, c, p);
  state.counters["us_per_face"] = benchmark::Counter(
      double(p.mesh.n_faces()) * 1e-6, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_ApplyStencils(benchmark::State& state) {
  const Case& c = kCases[state.range(0)];
  const Prepared p = prepare(c);
  for (auto _ : state) benchmark::DoNotOptimize(gps::apply_stencils(p.tables.stencils, p.q));
  label(state, c, p);
}

// The k base vertices with the most dependent rows (the worst case: extraordinary vertices first),
// re-applied incrementally; compare with BM_ApplyStencils of the same mesh.
void BM_UpdateVertices(benchmark::State& state) {
  const Case& c = kCases[state.range(0)];
  const Prepared p = prepare(c);
  const gps::StencilDependents deps = gps::stencil_dependents(p.tables.stencils);
  std::vector<gps::Dual> points = gps::apply_stencils(p.tables.stencils, p.q);
  std::vector<int> changed(p.mesh.n_vertices());
  for (size_t v = 0; v < changed.size(); ++v) changed[v] = int(v);
  const auto dependents = [&](int v) { return deps.offsets[size_t(v) + 1] - deps.offsets[size_t(v)]; };
  std::stable_sort(changed.begin(), changed.end(), [&](int a, int b) { return dependents(a) > dependents(b); });
  changed.resize(std::min(changed.size(), size_t(state.range(1))));
  for (auto _ : state) {
    gps::update_stencils(p.tables.stencils, deps, changed, points);
    benchmark::DoNotOptimize(points.data());
  }
  label(state, c, p);
  state.counters["k"] = double(changed.size());
}

constexpr int kNumCases = int(sizeof(kCases) / sizeof(kCases[0]));
BENCHMARK(BM_BuildPlans)->DenseRange(0, kNumCases - 1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ApplyStencils)->DenseRange(0, kNumCases - 1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_UpdateVertices)->ArgsProduct({{0, 1, 5, 9, 11}, {1, 4, 16, 64}})->Unit(benchmark::kMicrosecond);

}  // namespace
