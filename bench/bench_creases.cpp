// Creases against the same mesh without them: per mesh and crease kind, the live frame (every
// patch evaluated, surface cache off) at equal tessellation, the preprocessing (plans and stencils)
// and the tables' memory; and a sharpness change on a large creased mesh, re-planned in full against
// incrementally (core/plans/surface_replanner.h), both timed in the same run. Crease kinds: none ("smooth"), the same edges infinitely sharp ("sharp"),
// semi-sharp at 2.5 ("semi2.5"). The edges: those of the wirecube's square beams (sharp by angle,
// every beam edge) and three great circles of the sphere and the torus (edges in a coordinate
// plane). Run with --benchmark_enable_random_interleaving=true and --benchmark_repetitions=N so that
// a changing machine load hits every kind alike.
#include <benchmark/benchmark.h>
#include <glad/gl.h>

#include <chrono>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "bench/gl_bench_cases.h"
#include "bench/run_benchmarks.h"
#include "core/mesh/crease_by_angle.h"
#include "core/support/error.h"
#include "core/modelling/samples.h"
#include "core/plans/planned_surface.h"
#include "core/plans/surface_replanner.h"
#include "render/gl/render_target.h"
#include "render/pipeline/surface_renderer.h"
#include "view/camera.h"

namespace {

using gps::bench::MeshCase;

const std::vector<std::pair<const char*, double>>& crease_kinds() {
  static const std::vector<std::pair<const char*, double>> kinds = {
      {"smooth", 0.0}, {"sharp", gps::kInfiniteSharpness}, {"semi2.5", 2.5}};
  return kinds;
}

// The mesh with its chosen edges at `sharpness` (none at 0).
gps::CovarianceMesh creased_sample(const MeshCase& m, double sharpness) {
  gps::CovarianceMesh mesh = gps::make_sample(m.name, m.faces);
  if (sharpness == 0.0) return mesh;
  if (m.name == "wirecube") {
    gps::crease_by_angle(mesh, 30.0);
    for (auto& c : mesh.sharpness.creases) c.sharpness = sharpness;
    return mesh;
  }
  const double diag = gps::bounding_box_diagonal(mesh);
  for (size_t e = 0; e < mesh.n_edges(); ++e) {
    const auto [v0, v1] = mesh.edge(e);
    const gps::Vec3 &a = mesh.mean(size_t(v0)), &b = mesh.mean(size_t(v1));
    for (int axis = 0; axis < 3; ++axis)
      if (std::abs(a[axis]) < 1e-9 * diag && std::abs(b[axis]) < 1e-9 * diag)
        mesh.sharpness.set_crease(v0, v1, sharpness);
  }
  return mesh;
}

const gps::CovarianceMesh& sample(const MeshCase& m, int kind) {
  static std::map<std::string, gps::CovarianceMesh> meshes;
  const std::string key = m.id() + "/" + crease_kinds()[size_t(kind)].first;
  auto it = meshes.find(key);
  if (it == meshes.end()) it = meshes.emplace(key, creased_sample(m, crease_kinds()[size_t(kind)].second)).first;
  return it->second;
}

// One live frame at a uniform level (level > 0) or adaptive 6-pixel edges (level 0), 512x512.
void BM_Frame(benchmark::State& state, MeshCase m, int kind, int level) {
  const gps::CovarianceMesh& mesh = sample(m, kind);
  gps::bench::time_live_frames(state, mesh, gps::PlanOptions{}, level);
  state.counters["creased_edges"] = double(mesh.sharpness.creases.size());
}

// Plans and stencils of the mesh (CPU), with the tables' bytes.
void BM_Preprocess(benchmark::State& state, MeshCase m, int kind) {
  const gps::CovarianceMesh& mesh = sample(m, kind);
  const gps::PolygonTopology& topology = mesh.topology();
  size_t bytes = 0, rows = 0, nodes = 0;
  for (auto _ : state) {
    const gps::SurfaceTables t = gps::build_surface_plans(topology, gps::PlanOptions{}, mesh.sharpness);
    bytes = t.bytes();
    rows = size_t(t.stencils.n_rows());
    nodes = t.plans.nodes.size();
  }
  state.counters["creased_edges"] = double(mesh.sharpness.creases.size());
  state.counters["table_bytes"] = double(bytes);
  state.counters["stencil_rows"] = double(rows);
  state.counters["node_ints"] = double(nodes);
}

// One edge's sharpness changed (set to 2.5 or back to 0, a different edge each time) on the creased
// mesh: the full re-plan (build_surface_plans, then the PlannedSurface the renderer takes) against the
// replanner's (set_sharpness, then the PlannedSurface of its tables), timed alternately in one run.
void BM_SharpnessChange(benchmark::State& state, MeshCase m) {
  using Clock = std::chrono::steady_clock;
  gps::CovarianceMesh mesh = sample(m, 2);
  const gps::PolygonTopology& topology = mesh.topology();
  const gps::PlanOptions options;
  gps::SurfaceReplanner replanner(topology, options, mesh.sharpness);
  std::vector<std::pair<int, int>> edges;
  for (size_t e = 0; e < mesh.n_edges(); ++e) edges.emplace_back(mesh.edge(e)[0], mesh.edge(e)[1]);
  double full_plans = 0, incremental_plans = 0, full_surface = 0, incremental_surface = 0;
  size_t changes = 0, faces = 0;
  for (auto _ : state) {
    const auto [a, b] = edges[(changes * 7919) % edges.size()];
    mesh.sharpness.set_crease(a, b, mesh.sharpness.crease(a, b) > 0.0 ? 0.0 : 2.5);
    const auto t0 = Clock::now();
    const gps::SurfaceTables full = gps::build_surface_plans(topology, options, mesh.sharpness);
    const auto t1 = Clock::now();
    faces += replanner.set_sharpness(mesh.sharpness).size();
    const auto t2 = Clock::now();
    const gps::PlannedSurface full_surface_built(mesh, options);
    const auto t3 = Clock::now();
    const gps::PlannedSurface incremental_surface_built(mesh, replanner.scheme(), replanner.tables());
    const auto t4 = Clock::now();
    benchmark::DoNotOptimize(full.plans.nodes.data());
    benchmark::DoNotOptimize(incremental_surface_built.points().data());
    benchmark::DoNotOptimize(full_surface_built.points().data());
    const auto ms = [](auto d) { return std::chrono::duration<double, std::milli>(d).count(); };
    full_plans += ms(t1 - t0);
    incremental_plans += ms(t2 - t1);
    full_surface += ms(t3 - t2);
    incremental_surface += ms(t2 - t1) + ms(t4 - t3);
    state.SetIterationTime(std::chrono::duration<double>(t2 - t1).count());
    ++changes;
  }
  const double n = double(changes);
  state.counters["faces"] = double(topology.n_faces());
  state.counters["replanned_faces"] = double(faces) / n;
  state.counters["full_plans_ms"] = full_plans / n;
  state.counters["incremental_plans_ms"] = incremental_plans / n;
  state.counters["plans_speedup"] = full_plans / incremental_plans;
  state.counters["full_surface_ms"] = full_surface / n;
  state.counters["incremental_surface_ms"] = incremental_surface / n;
  state.counters["surface_speedup"] = full_surface / incremental_surface;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<MeshCase> meshes = {{"wirecube", 0}, {"torus", 0}, {"sphere", 6144}};
  for (const MeshCase& m : meshes)
    for (size_t k = 0; k < crease_kinds().size(); ++k) {
      const std::string id = m.id() + "/" + crease_kinds()[k].first;
      benchmark::RegisterBenchmark(("Preprocess/" + id).c_str(), BM_Preprocess, m, int(k))
          ->Unit(benchmark::kMillisecond);
      for (const int level : {4, 16, 0})
        benchmark::RegisterBenchmark(("Frame/" + id + "/" + gps::bench::setting_name(level)).c_str(), BM_Frame, m,
                                     int(k), level)
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond);
    }
  for (const MeshCase& m : {MeshCase{"sphere", 98304}, MeshCase{"icosphere", 81920}})
    benchmark::RegisterBenchmark(("SharpnessChange/" + m.id()).c_str(), BM_SharpnessChange, m)
        ->UseManualTime()
        ->Iterations(5)
        ->Unit(benchmark::kMillisecond);
  return gps::bench::run_benchmarks(argc, argv);
}
