// Topology steps in time linear in the mesh whatever the valence or face size: a fan of triangles
// around one vertex (faces in shuffled order) and one face of very many sides, each at n and 4n in
// the same iteration, so that the counter `ratio` shows a quadratic step as 16 (linear: 4).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <random>

#include "core/mesh/inference.h"
#include "core/mesh/mesh_connectivity.h"
#include "core/modelling/shapes.h"
#include "core/reference/reference_subdivision.h"

namespace {

gps::Shape fan(int n) {  // n triangles around vertex 0, the apex, in shuffled order
  gps::Shape s = gps::cone_shape(n, 1.0, 0.1, 0.0, false);
  std::shuffle(s.faces.begin(), s.faces.end(), std::mt19937(1));
  return s;
}

gps::Shape polygon(int n) { return gps::polygon_shape(n, 1.0); }

// What `gpsurf info` and `gpsurf subdivide` do with a mesh: build it (manifold checks), infer its
// covariances, its connectivity, one Catmull-Clark step (which splits every n-gon). Seconds.
double process(const gps::Shape& s) {
  const auto start = std::chrono::steady_clock::now();
  gps::CovarianceMesh m =
      gps::make_covariance_mesh(s.points, std::vector<gps::Mat3>(s.points.size(), gps::Mat3::Identity()), s.faces);
  gps::infer_covariances(m);
  benchmark::DoNotOptimize(m.connectivity().n_edges());
  gps::SubdivisionOptions o;
  o.levels = 1;
  benchmark::DoNotOptimize(gps::subdivide(m, o).mesh.n_faces());
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void run(benchmark::State& state, gps::Shape (*make)(int), int n) {
  const gps::Shape small = make(n), large = make(4 * n);
  double small_s = 0, large_s = 0;
  for (auto _ : state) {
    const double a = process(small), b = process(large);
    small_s += a;
    large_s += b;
    state.SetIterationTime(a + b);
  }
  state.counters["small_s"] = benchmark::Counter(small_s, benchmark::Counter::kAvgIterations);
  state.counters["large_s"] = benchmark::Counter(large_s, benchmark::Counter::kAvgIterations);
  state.counters["ratio"] = large_s / small_s;
}

void BM_HighValenceFan(benchmark::State& state) { run(state, fan, 25000); }
void BM_LongFace(benchmark::State& state) { run(state, polygon, 75000); }

}  // namespace

BENCHMARK(BM_HighValenceFan)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LongFace)->UseManualTime()->Unit(benchmark::kMillisecond);
