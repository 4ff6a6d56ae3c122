// What the editor's undo history costs an extrusion of one face on spheres of 10,000, 100,000 and
// 1,000,000 quads, beside what `gpsurf bench --model` times: the operation's deltas each way (the undo
// step), those deltas told again after the move that follows it (the step folded with the move, as the
// extrude tool confirms), and the undo itself (the mesh before made from the mesh after and its delta).
#include <benchmark/benchmark.h>

#include <map>

#include "core/mesh/mesh_delta.h"
#include "core/modelling/extrude.h"
#include "core/modelling/mesh_arrays.h"
#include "core/modelling/samples.h"

namespace {

// The sphere, its extrusion of the middle face, and that result with the new vertices moved on.
struct Extrusion {
  gps::CovarianceMesh before;
  gps::Modelled made;
  gps::CovarianceMesh moved;
  std::vector<int> vertices;
  std::vector<gps::Vec3> was_means;
  std::vector<gps::Mat3> was_covariances;
};

const Extrusion& extrusion(int faces) {
  static std::map<int, Extrusion> made;
  auto it = made.find(faces);
  if (it != made.end()) return it->second;
  Extrusion e;
  e.before = gps::make_sample("sphere", faces);
  e.made = gps::extrude_faces(e.before, {int(e.before.n_faces() / 2)}, 0.01);
  e.moved = e.made.mesh;
  for (size_t v = 0; v < e.moved.n_vertices(); ++v)
    if (e.made.vertex_origin[v] < 0) {
      e.vertices.push_back(int(v));
      e.was_means.push_back(e.moved.mean(v));
      e.was_covariances.push_back(e.moved.covariance(v));
      e.moved.set_mean(v, 1.1 * e.moved.mean(v));
    }
  return made.emplace(faces, std::move(e)).first->second;
}

gps::MeshDelta forward_of(const Extrusion& e) { return gps::mesh_delta(e.before, e.made.mesh, e.made.vertex_origin); }

gps::MeshDelta back_of(const Extrusion& e) {
  return gps::mesh_delta(e.made.mesh, e.before, gps::inverse_origin(e.made.vertex_origin, e.before.n_vertices()));
}

void BM_UndoStep(benchmark::State& state) {
  const Extrusion& e = extrusion(int(state.range(0)));
  for (auto _ : state) {
    benchmark::DoNotOptimize(forward_of(e));
    benchmark::DoNotOptimize(back_of(e));
  }
}

void BM_FoldTheMove(benchmark::State& state) {
  const Extrusion& e = extrusion(int(state.range(0)));
  const gps::MeshDelta forward = forward_of(e), back = back_of(e);
  for (auto _ : state) {
    state.PauseTiming();
    gps::MeshDelta f = forward, b = back;
    state.ResumeTiming();
    gps::retell_gaussians(f, b, e.moved, e.vertices, e.was_means, e.was_covariances);
    benchmark::DoNotOptimize(f);
  }
}

void BM_Undo(benchmark::State& state) {
  const Extrusion& e = extrusion(int(state.range(0)));
  const gps::MeshDelta back = back_of(e);
  for (auto _ : state) benchmark::DoNotOptimize(gps::apply_delta(e.made.mesh, back));
}

BENCHMARK(BM_UndoStep)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FoldTheMove)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Undo)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

}  // namespace
