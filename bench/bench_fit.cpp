// From a scan to a fitted GPS surface on all cores: simplify of a 1M-triangle icosphere, made bumpy,
// to 10,000 vertices, and the fit (10 iterations) of a 100k-triangle one's points with 1,500
// control vertices, plain and GPS; peak memory per input triangle.
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <cmath>

#include "core/fitting/limit_fit.h"
#include "core/fitting/mesh_simplification.h"
#include "core/modelling/samples.h"

namespace {

// The icosphere of about `faces` triangles, its radius varied by smooth bumps.
gps::CovarianceMesh bumpy_icosphere(int faces) {
  gps::CovarianceMesh m = gps::make_sample("icosphere", faces);
  for (size_t i = 0; i < m.n_vertices(); ++i) {
    const gps::Vec3 d = m.mean(i).normalized();
    const double r = 1 + 0.08 * std::sin(5 * d[0]) * std::sin(4 * d[1] + 1) + 0.05 * std::cos(6 * d[2]);
    m.set_mean(i, r * d);
  }
  return m;
}

double peak_rss_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) * 1024.0;
}

void BM_Simplify1MTo10k(benchmark::State& state) {
  const gps::CovarianceMesh input = bumpy_icosphere(1'300'000);
  gps::SimplifyOptions options;
  options.target_vertices = 10'000;
  for (auto _ : state) benchmark::DoNotOptimize(gps::simplify_mesh(input, options));
  state.counters["input_triangles"] = double(input.n_faces());
  state.counters["peak_rss_bytes_per_triangle"] = peak_rss_bytes() / double(input.n_faces());
}
BENCHMARK(BM_Simplify1MTo10k)->Unit(benchmark::kSecond)->Iterations(1);

void BM_Fit100kWith1500(benchmark::State& state) {
  const gps::CovarianceMesh input = bumpy_icosphere(82'000);
  gps::SimplifyOptions simplify;
  simplify.target_vertices = 1'500;
  const gps::CovarianceMesh coarse = gps::simplify_mesh(input, simplify).mesh;
  const std::vector<gps::Vec3> targets = gps::vertex_means(input);
  gps::FitOptions options;
  options.plain = state.range(0) == 0;
  double rms = 0;
  for (auto _ : state) rms = gps::fit_limit_surface(coarse, targets, options).iterations.back().error.relative_rms();
  state.counters["gps"] = double(state.range(0));
  state.counters["input_triangles"] = double(input.n_faces());
  state.counters["relative_rms"] = rms;
  state.counters["peak_rss_bytes_per_triangle"] = peak_rss_bytes() / double(input.n_faces());
}
BENCHMARK(BM_Fit100kWith1500)->Arg(0)->Arg(1)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
