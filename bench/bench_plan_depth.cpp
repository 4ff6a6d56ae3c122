// Exact plans against the thesis' Bézier plans: per mesh and plan kind, the live frame
// (every patch evaluated, surface cache off) at equal tessellation, the preprocessing (plans and
// stencils) and the tables' memory. Plan kinds: the thesis' depth 3 ("approx3"), exact plans of
// depth 0..3 ("exact0".."exact3"). Run with --benchmark_enable_random_interleaving=true and
// --benchmark_repetitions=N so that a changing machine load hits every kind alike.
#include <benchmark/benchmark.h>
#include <glad/gl.h>

#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/support/error.h"
#include "core/plans/planned_surface.h"
#include "core/modelling/samples.h"
#include "bench/gl_bench_cases.h"
#include "bench/run_benchmarks.h"
#include "render/gl/render_target.h"
#include "render/pipeline/surface_renderer.h"
#include "view/camera.h"

namespace {

struct PlanKind {
  const char* name;
  gps::PlanOptions options;
};

gps::PlanOptions plan_options(bool exact, int depth) {
  gps::PlanOptions o;
  o.scheme = gps::Scheme::catmull_clark;
  o.exact = exact;
  o.depth = depth;
  return o;
}

const std::vector<PlanKind>& plan_kinds() {
  static const std::vector<PlanKind> kinds = {{"approx3", plan_options(false, 3)},
                                              {"exact0", plan_options(true, 0)},
                                              {"exact1", plan_options(true, 1)},
                                              {"exact2", plan_options(true, 2)},
                                              {"exact3", plan_options(true, 3)}};
  return kinds;
}

using gps::bench::MeshCase;

const gps::CovarianceMesh& sample(const MeshCase& m) {
  static std::map<std::string, gps::CovarianceMesh> meshes;
  const std::string key = m.id();
  auto it = meshes.find(key);
  if (it == meshes.end()) it = meshes.emplace(key, gps::make_sample(m.name, m.faces)).first;
  return it->second;
}

// One live frame at a uniform level (level > 0) or adaptive 6-pixel edges (level 0), 512x512.
void BM_Frame(benchmark::State& state, MeshCase m, int kind, int level) {
  const gps::CovarianceMesh& mesh = sample(m);
  gps::bench::time_live_frames(state, mesh, plan_kinds()[size_t(kind)].options, level);
}

// Plans and stencils of the mesh (CPU), with the tables' bytes per face.
void BM_Preprocess(benchmark::State& state, MeshCase m, int kind) {
  const gps::CovarianceMesh& mesh = sample(m);
  const gps::PolygonTopology& topology = mesh.topology();
  size_t bytes = 0, rows = 0;
  for (auto _ : state) {
    const gps::SurfaceTables t = gps::build_surface_plans(topology, plan_kinds()[size_t(kind)].options);
    bytes = t.bytes();
    rows = size_t(t.stencils.n_rows());
  }
  state.counters["table_bytes_per_face"] = double(bytes) / double(mesh.n_faces());
  state.counters["table_bytes"] = double(bytes);
  state.counters["stencil_rows"] = double(rows);
}

}  // namespace

int main(int argc, char** argv) {
  // The valence samples, the wirecube, and icospheres under Catmull-Clark (every triangle three
  // quads, extraordinary vertices everywhere): 15k patches, and 246k, past what the thesis' depth-3
  // plans fit in llvmpipe's 128 MiB storage blocks (reported as an error there).
  const std::vector<MeshCase> meshes = {{"valence3", 0}, {"valence5", 0},     {"valence8", 0},     {"valence10", 0},
                                        {"wirecube", 0}, {"icosphere", 5120}, {"icosphere", 81920}};
  for (const MeshCase& m : meshes)
    for (size_t k = 0; k < plan_kinds().size(); ++k) {
      const std::string id = m.id() + "/" + plan_kinds()[k].name;
      benchmark::RegisterBenchmark(("Preprocess/" + id).c_str(), BM_Preprocess, m, int(k))
          ->Unit(benchmark::kMillisecond);
      const std::vector<int> levels = m.faces ? std::vector<int>{1, 0} : std::vector<int>{4, 16, 0};
      for (const int level : levels)
        benchmark::RegisterBenchmark(("Frame/" + id + "/" + gps::bench::setting_name(level)).c_str(), BM_Frame, m,
                                     int(k), level)
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond);
    }
  return gps::bench::run_benchmarks(argc, argv);
}
