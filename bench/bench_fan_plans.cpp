// Plans of one vertex of high valence: an open fan (the vertex on the boundary, one exact table per face
// of the fan) and a closed one (the vertex inside, one table for all), of triangles (Loop) and of quads
// (Catmull-Clark). Each face's table finds its limit masks by subspace iteration
// (core/extraordinary/extraordinary_corner_masks.h), slowest where the step's next eigenvalues crowd.
#include <benchmark/benchmark.h>

#include "core/plans/planned_surface.h"

namespace {

// Triangles (c, s_i, s_i+1), or quads (c, s_i, m_i, s_i+1) with a vertex m_i between two spokes; the
// fan closes round c when `closed`.
gps::PolygonTopology fan(int faces, bool quads, bool closed) {
  const int spokes = closed ? faces : faces + 1;
  std::vector<std::vector<int>> polygons;
  for (int i = 0; i < faces; ++i) {
    const int s = 1 + i, next = 1 + (i + 1) % spokes;
    if (quads)
      polygons.push_back({0, s, 1 + spokes + i, next});
    else
      polygons.push_back({0, s, next});
  }
  gps::PolygonTopology t = gps::polygon_topology(polygons);
  t.n_vertices = 1 + spokes + (quads ? faces : 0);
  return t;
}

// Arguments: faces, quads (0: triangles), closed (0: open).
void BM_FanPlans(benchmark::State& state) {
  const int faces = int(state.range(0));
  const bool quads = state.range(1) != 0, closed = state.range(2) != 0;
  const gps::PolygonTopology topology = fan(faces, quads, closed);
  gps::PlanOptions options;
  options.scheme = quads ? gps::Scheme::catmull_clark : gps::Scheme::loop;
  for (auto _ : state) benchmark::DoNotOptimize(gps::build_surface_plans(topology, options));
  state.SetLabel(std::string(closed ? "closed " : "open ") + (quads ? "quad" : "triangle") + " fan");
  state.counters["faces"] = faces;
}

}  // namespace

// Loop patches take valences up to 64 (core/plans/loop_plan_builder.h).
BENCHMARK(BM_FanPlans)->ArgsProduct({{16, 32, 64}, {0}, {0, 1}})->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_FanPlans)->ArgsProduct({{32, 64, 128}, {1}, {0, 1}})->Unit(benchmark::kMillisecond)->Iterations(1);
