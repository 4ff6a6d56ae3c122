// The peer benchmark: ours beside OpenSubdiv's Far (Debian's libosd-dev) at equal output.
// OpenSubdiv is linked into this benchmark only; the reference stays our own code.
//  - Reference: N levels of uniform Catmull-Clark on 9D primvars (q = F(μ, Σ)) and the limit
//    positions of the last level, from Gaussians to Gaussians with the refined faces: ours is
//    subdivide() (core/reference/reference_subdivision.h), theirs TopologyRefiner + PrimvarRefiner in double.
//  - Preprocessing: our build_plans() (plans + stencil table, depth 3) beside Far's adaptive
//    refinement to level 3, StencilTable and PatchTable with its local-point stencils appended.
// Ratios: divide the "Ours" time by the "Osd" time of the same arguments.
#include <benchmark/benchmark.h>

#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/stencilTableFactory.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include <memory>

#include "core/mesh/dual_map.h"
#include "core/mesh/mesh_connectivity.h"
#include "core/plans/plan_builder.h"
#include "core/reference/reference_subdivision.h"
#include "core/modelling/samples.h"

namespace {

using namespace OpenSubdiv;
using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;

// A 9D primvar in the form Far's refiners interpolate.
struct Primvar9 {
  double q[9];
  void Clear(void* = nullptr) {
    for (double& x : q) x = 0.0;
  }
  void AddWithWeight(const Primvar9& s, double w) {
    for (int i = 0; i < 9; ++i) q[i] += w * s.q[i];
  }
};

// Far's topology from ours, with our boundary rules (cubic B-spline boundary curves, sharp corners).
std::unique_ptr<Far::TopologyRefiner> make_refiner(const gps::PolygonTopology& t, std::vector<int>& sizes) {
  sizes.resize(size_t(t.n_faces()));
  for (int f = 0; f < t.n_faces(); ++f) sizes[size_t(f)] = t.face_size(f);
  Far::TopologyDescriptor d;
  d.numVertices = t.n_vertices;
  d.numFaces = t.n_faces();
  d.numVertsPerFace = sizes.data();
  d.vertIndicesPerFace = t.verts.data();
  Sdc::Options options;
  options.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  return std::unique_ptr<Far::TopologyRefiner>(Factory::Create(d, Factory::Options(Sdc::SCHEME_CATMARK, options)));
}

void counters(benchmark::State& state, const gps::CovarianceMesh& mesh) {
  state.counters["faces"] = double(mesh.n_faces());
  state.counters["ns_per_base_face"] = benchmark::Counter(
      double(mesh.n_faces()), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_ReferenceOurs(benchmark::State& state) {
  const gps::CovarianceMesh mesh = gps::make_sample("sphere", int(state.range(0)));
  const gps::SubdivisionOptions options{gps::Scheme::catmull_clark, int(state.range(1)), true};
  for (auto _ : state) benchmark::DoNotOptimize(gps::subdivide(mesh, options));
  counters(state, mesh);
}

void BM_ReferenceOsd(benchmark::State& state) {
  const gps::CovarianceMesh mesh = gps::make_sample("sphere", int(state.range(0)));
  const int levels = int(state.range(1));
  const gps::PolygonTopology& topology = mesh.topology();
  size_t n_out = 0;
  for (auto _ : state) {
    std::vector<int> sizes;
    const auto refiner = make_refiner(topology, sizes);
    Far::TopologyRefiner::UniformOptions uniform(levels);
    uniform.fullTopologyInLastLevel = true;  // the limit needs the last level's vertex rings
    refiner->RefineUniform(uniform);
    std::vector<Primvar9> values(size_t(refiner->GetNumVerticesTotal()));
    const std::vector<gps::Dual> base = gps::base_points(mesh);  // timed like our reference's own
    for (size_t i = 0; i < base.size(); ++i)
      for (int k = 0; k < 9; ++k) values[i].q[k] = base[i][k];
    Far::PrimvarRefinerReal<double> primvars(*refiner);
    Primvar9* src = values.data();
    for (int level = 1; level <= levels; ++level) {
      Primvar9* dst = src + refiner->GetLevel(level - 1).GetNumVertices();
      primvars.Interpolate(level, src, dst);
      src = dst;
    }
    const Far::TopologyLevel& last = refiner->GetLevel(levels);
    std::vector<Primvar9> limit(size_t(last.GetNumVertices()));
    Primvar9* limit_points = limit.data();
    primvars.Limit(src, limit_points);
    // Equal output: Gaussians back from 9D and the refined faces' vertex lists.
    std::vector<gps::Vec3> means(limit.size());
    std::vector<gps::Mat3> covariances(limit.size());
    for (size_t i = 0; i < limit.size(); ++i) {
      const auto g = gps::from_dual(Eigen::Map<const gps::Dual>(limit[i].q));
      means[i] = g->mean;
      covariances[i] = g->covariance;
    }
    std::vector<int> faces;
    faces.reserve(4 * size_t(last.GetNumFaces()));
    for (int f = 0; f < last.GetNumFaces(); ++f)
      for (const int v : last.GetFaceVertices(f)) faces.push_back(v);
    benchmark::DoNotOptimize(faces.data());
    benchmark::DoNotOptimize(means.data());
    n_out = limit.size();
  }
  counters(state, mesh);
  state.counters["points"] = double(n_out);
}

void BM_PreprocessOurs(benchmark::State& state) {
  const gps::CovarianceMesh mesh = gps::make_sample("sphere", int(state.range(0)));
  const gps::PolygonTopology& topology = mesh.topology();
  for (auto _ : state) benchmark::DoNotOptimize(gps::build_plans(topology, 3));
  counters(state, mesh);
}

void BM_PreprocessOsd(benchmark::State& state) {
  const gps::CovarianceMesh mesh = gps::make_sample("sphere", int(state.range(0)));
  const gps::PolygonTopology& topology = mesh.topology();
  for (auto _ : state) {
    std::vector<int> sizes;
    const auto refiner = make_refiner(topology, sizes);
    Far::PatchTableFactory::Options patch_options(3);
    patch_options.SetEndCapType(Far::PatchTableFactory::Options::ENDCAP_GREGORY_BASIS);
    patch_options.useInfSharpPatch = true;
    Far::TopologyRefiner::AdaptiveOptions adaptive(3);
    adaptive.useInfSharpPatch = true;
    refiner->RefineAdaptive(adaptive);
    Far::StencilTableFactoryReal<double>::Options stencil_options;
    stencil_options.generateOffsets = true;
    stencil_options.generateIntermediateLevels = true;
    std::unique_ptr<const Far::StencilTableReal<double>> stencils(
        Far::StencilTableFactoryReal<double>::Create(*refiner, stencil_options));
    patch_options.SetPatchPrecision<double>();
    std::unique_ptr<const Far::PatchTable> patches(Far::PatchTableFactory::Create(*refiner, patch_options));
    std::unique_ptr<const Far::StencilTableReal<double>> all(
        Far::StencilTableFactoryReal<double>::AppendLocalPointStencilTable(
            *refiner, stencils.get(), patches->GetLocalPointStencilTable<double>()));
    benchmark::DoNotOptimize(all.get());
  }
  counters(state, mesh);
}

BENCHMARK(BM_ReferenceOurs)->ArgsProduct({{1000, 10000}, {3}})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ReferenceOsd)->ArgsProduct({{1000, 10000}, {3}})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_PreprocessOurs)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_PreprocessOsd)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
