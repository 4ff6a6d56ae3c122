// Plans against the exact reference.
#include "core/plans/plan_builder.h"

#include <gtest/gtest.h>

#include <omp.h>

#include <map>
#include <random>
#include <tuple>

#include "core/support/error.h"
#include "core/evaluation/patch_eval.h"
#include "core/plans/patch_layout.h"
#include "core/reference/reference_subdivision.h"
#include "tests/support/plan_fixture.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

using test::PlannedMesh;
using test::with_random_covariances;

// Max distance (relative to the bounding-box diagonal) between plan and reference limit vertices,
// over the vertices whose leaf node is of the given kinds.
struct Comparison {
  double regular = 0, all = 0;
  double regular_q = 0;  // 9D values on regular nodes, relative to |q| + 1
  int n_regular = 0;
};

// The same against a reference already subdivided from p.mesh (Catmull-Clark, limit projected).
Comparison compare_with_reference(const PlannedMesh& p, const SubdivisionResult& ref) {
  const double diag = bounding_box_diagonal(p.mesh);
  Comparison c;
  for (size_t k = 0; k < ref.mesh.n_vertices(); ++k) {
    const PatchParam& pp = ref.vertex_params[k];
    const auto s = evaluate_patch(p.tables.plans, p.points, pp.patch, pp.u, pp.v);
    EXPECT_TRUE(s.has_value());
    if (!s) continue;
    const double e = (s->position - ref.mesh.mean(k)).norm() / diag;
    c.all = std::max(c.all, e);
    if (s->kind != NodeKind::regular) continue;
    c.regular = std::max(c.regular, e);
    ++c.n_regular;
    const Dual q = to_dual(ref.mesh.mean(k), ref.mesh.covariance(k));
    c.regular_q = std::max(c.regular_q, (s->q - q).norm() / (1 + q.norm()));
  }
  return c;
}

Comparison compare_with_reference(const PlannedMesh& p, int levels) {
  return compare_with_reference(p, subdivide(p.mesh, {Scheme::catmull_clark, levels, true}));
}

TEST(PlanBuilder, RegularPatchesAreExact) {
  for (const char* name : {"grid", "sphere", "torus", "valence5", "wirecube", "cylinder", "cone"}) {
    const PlannedMesh p(with_random_covariances(make_sample(name, 150), 3), 3);
    const Comparison c = compare_with_reference(p, 4);
    EXPECT_LT(c.regular, 1e-9) << name;
    // q matches on a 17×17 grid per patch, so the bicubic q, its derivatives and thereby the analytic
    // normals (Eq. 3.12; checked against differences below) are the exact ones on regular nodes.
    EXPECT_LT(c.regular_q, 1e-9) << name;
    EXPECT_GT(c.n_regular, 100) << name;
  }
}

TEST(PlanBuilder, PatchCornersAreExactLimitPositions) {
  for (const char* name : {"cube", "valence3", "valence7", "wirecube", "cone-pointy", "cylinder"}) {
    const PlannedMesh p(with_random_covariances(make_sample(name), 5), 2);
    const auto ref = subdivide(p.mesh, {Scheme::catmull_clark, 1, true});
    const double diag = bounding_box_diagonal(p.mesh);
    int corners = 0;
    for (size_t k = 0; k < ref.mesh.n_vertices(); ++k) {
      const PatchParam& pp = ref.vertex_params[k];
      if ((pp.u != 0 && pp.u != 1) || (pp.v != 0 && pp.v != 1)) continue;
      const auto s = evaluate_patch(p.tables.plans, p.points, pp.patch, pp.u, pp.v);
      ASSERT_TRUE(s);
      EXPECT_LT((s->position - ref.mesh.mean(k)).norm(), 1e-12 * diag) << name << " vertex " << k;
      ++corners;
    }
    EXPECT_GT(corners, 7) << name;
  }
}

// Near extraordinary vertices the terminal Bézier patches approximate; the error (max over limit
// vertices of reference level 5, relative to the bounding-box diagonal) falls with depth, roughly
// halving with each level, and stays below 7e-3 at depth 3.
TEST(PlanBuilder, ErrorNearExtraordinaryVerticesFallsWithDepth) {
  std::vector<std::string> names = {"cube", "wirecube"};
  for (int n = 3; n <= 10; ++n) names.push_back("valence" + std::to_string(n));
  for (const auto& name : names) {
    const CovarianceMesh mesh = make_sample(name);
    const SubdivisionResult reference = subdivide(mesh, {Scheme::catmull_clark, 5, true});  // one for every depth
    double previous = 1;
    for (int depth = 1; depth <= 3; ++depth) {
      const double error = compare_with_reference(PlannedMesh(mesh, depth), reference).all;
      if (name == "valence4")
        EXPECT_LT(error, 1e-12);  // no extraordinary vertex: exact at every depth
      else
        EXPECT_LT(error, previous) << name << " depth " << depth;
      previous = error;
    }
    EXPECT_LT(previous, 7e-3) << name;
  }
}

// Both sides of every shared patch edge give the same positions at the same edge parameters, where
// a quad meets two half-size patches of a split face too (T-junctions, core/plans/patch_plans.h); exact
// plans and the thesis' plans of depth 3.
TEST(PlanBuilder, NeighbouringPatchesAreWatertight) {
  for (const bool exact : {true, false})
    for (const char* name :
         {"wirecube", "valence9", "cylinder", "cone-pointy", "grid", "pawn", "prism", "open-cylinder"}) {
      const std::string n = name;
      const CovarianceMesh mesh = n == "prism"           ? test::prism_mesh()
                                  : n == "open-cylinder" ? test::open_cylinder_mesh()
                                                         : make_sample(name, 64);
      const PlannedMesh p(with_random_covariances(mesh, 7),
                          PlanOptions{Scheme::catmull_clark, 3, LoopBeta::loop, exact});
      const auto& plans = p.tables.plans;
      const double diag = bounding_box_diagonal(p.mesh);
      // The first evaluation at parameter s/32 of each mesh edge (lower point first).
      std::map<std::tuple<int, int, int>, Vec3> first_side;
      int shared = 0, t_junctions = 0;
      for (int patch = 0; patch < plans.n_patches(); ++patch)
        for (int k = 0; k < 4; ++k) {
          const PatchEdge e = patch_edge(plans, patch, k);
          t_junctions += e.part == PatchEdgePart::whole_beside_halves;
          const bool half = e.part == PatchEdgePart::first_half || e.part == PatchEdgePart::second_half;
          for (int i = 0; i <= 16; ++i) {
            const double t = i / 16.0;
            const auto [u, v] = std::array<std::pair<double, double>, 4>{
                std::pair{t, 0.0}, std::pair{1.0, t}, std::pair{1.0 - t, 1.0}, std::pair{0.0, 1.0 - t}}[size_t(k)];
            int s = half ? i + (e.part == PatchEdgePart::second_half ? 16 : 0) : 2 * i;  // of 32, from `from`
            if (e.from > e.to) s = 32 - s;
            const auto sample = evaluate_patch(plans, p.points, patch, u, v);
            ASSERT_TRUE(sample);
            const auto [it, added] =
                first_side.try_emplace({std::min(e.from, e.to), std::max(e.from, e.to), s}, sample->position);
            if (added) continue;
            ++shared;
            EXPECT_LT((sample->position - it->second).norm(), 1e-12 * diag)
                << name << " patch " << patch << " edge " << k;
          }
        }
      EXPECT_GT(shared, 10) << name;
      if (std::string(name) == "pawn") {
        EXPECT_EQ(t_junctions, 2 * 32) << name;
      }
    }
}

// A quad stays one patch beside other faces; a face of n sides is n patches.
TEST(PlanBuilder, MixedMeshesSplitOnlyWhatIsNotAQuad) {
  for (const char* name : {"pawn", "cylinder", "cone"}) {
    const CovarianceMesh mesh = make_sample(name);
    int expected = 0;
    for (size_t f = 0; f < mesh.n_faces(); ++f) expected += mesh.face_size(f) == 4 ? 1 : mesh.face_size(f);
    EXPECT_EQ(PlannedMesh(mesh, 3).tables.plans.n_patches(), expected) << name;
    EXPECT_EQ(make_patch_layout(mesh.topology()).n_patches(), expected) << name;
  }
  EXPECT_EQ(PlannedMesh(make_sample("pawn"), 2).tables.plans.n_patches(), 736 + 3 * 64);
}

// Plans are built on all cores in ranges of faces; the result is the one-core result, bit for bit:
// a quad mesh of 20 ranges and a triangle mesh of 2 (its edge midpoints shared across ranges).
TEST(PlanBuilder, AllCoresGiveTheOneCoreTablesBitForBit) {
  const CovarianceMesh triangles = subdivide(make_sample("cone"), {Scheme::loop, 4, false}).mesh;
  for (const CovarianceMesh& mesh : {make_sample("sphere", 20000), triangles}) {
    const PolygonTopology& topology = mesh.topology();
    omp_set_num_threads(1);
    const SurfaceTables one = build_plans(topology, 3);
    omp_set_num_threads(2);
    const SurfaceTables two = build_plans(topology, 3);
    omp_set_num_threads(omp_get_num_procs());
    EXPECT_GT(mesh.n_faces(), 2000u);
    EXPECT_EQ(one.plans.nodes, two.plans.nodes);
    EXPECT_EQ(one.plans.patch_roots, two.plans.patch_roots);
    EXPECT_EQ(one.plans.patch_corner_points, two.plans.patch_corner_points);
    EXPECT_EQ(one.plans.patch_edges, two.plans.patch_edges);
    EXPECT_EQ(one.stencils.offsets, two.stencils.offsets);
    EXPECT_EQ(one.stencils.indices, two.stencils.indices);
    EXPECT_EQ(one.stencils.weights, two.stencils.weights);
  }
  // ... and the merged ranges are right: the sphere's patch corners, in every range, are the exact
  // limit positions of their base vertices.
  const test::PlannedMesh p(make_sample("sphere", 20000), 3);
  const auto limit = subdivide(p.mesh, {Scheme::catmull_clark, 0, true});
  const double diag = bounding_box_diagonal(p.mesh);
  for (int patch = 0; patch < p.tables.plans.n_patches(); patch += 97) {
    const auto corners = p.mesh.face(size_t(patch));
    for (const auto& [k, u, v] : {std::tuple{0, 0.0, 0.0}, std::tuple{2, 1.0, 1.0}}) {
      const auto s = evaluate_patch(p.tables.plans, p.points, patch, u, v);
      ASSERT_TRUE(s);
      EXPECT_LT((s->position - limit.mesh.mean(size_t(corners[size_t(k)]))).norm(), 1e-12 * diag) << "patch " << patch;
    }
  }
}

// Every evaluated q̂ is positive definite, extreme covariances included; net weights of the
// boundary phantoms stay non-negative.
TEST(PlanBuilder, EvaluatedGaussiansStayValid) {
  for (const char* name : {"cone-pointy", "cone-cylinder", "cone-concave", "grid", "valence3"}) {
    const PlannedMesh p(make_sample(name, 36), 3);
    for (int patch = 0; patch < p.tables.plans.n_patches(); ++patch)
      for (int i = 0; i <= 8; ++i)
        for (int j = 0; j <= 8; ++j)
          EXPECT_TRUE(evaluate_patch(p.tables.plans, p.points, patch, i / 8.0, j / 8.0)) << name;
  }
  // Net weights: evaluate with q = unit vectors per base vertex (one coordinate of a 9-vector).
  const PlannedMesh grid(make_sample("grid", 16), 3);
  const auto& t = grid.tables;
  for (size_t v = 0; v < grid.base.size(); ++v) {
    std::vector<Dual> unit(grid.base.size(), Dual::Zero());
    unit[v][0] = 1.0;
    const auto pts = apply_stencils(t.stencils, unit);
    for (int patch = 0; patch < t.plans.n_patches(); ++patch)
      for (int i = 0; i <= 6; ++i)
        for (int j = 0; j <= 6; ++j) {
          Dual q, qu, qv;
          evaluate_dual(t.plans, pts, patch, i / 6.0, j / 6.0, q, qu, qv);
          EXPECT_GE(q[0], -1e-12) << "vertex " << v << " patch " << patch;
        }
  }
}

TEST(PlanBuilder, IsotropicCovariancesGivePlainCatmullClarkAndScalingChangesNothing) {
  const CovarianceMesh mesh = make_sample("wirecube");  // equal edges: equal isotropic covariances
  const PlannedMesh p(mesh, 3);
  CovarianceMesh scaled = with_random_covariances(mesh, 9);
  const PlannedMesh a(scaled, 3);
  for (auto& c : scaled.covariances) c *= 123.0;
  const PlannedMesh b(scaled, 3);
  // Plain Catmull-Clark: the same plans over 3D points.
  std::vector<Dual> plain(mesh.n_vertices());
  for (size_t i = 0; i < plain.size(); ++i) plain[i] << 1, 0, 0, 1, 0, 1, mesh.mean(i);
  const auto plain_points = apply_stencils(p.tables.stencils, plain);
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(0, 1);
  for (int k = 0; k < 500; ++k) {
    const int patch = int(u(rng) * p.tables.plans.n_patches());
    const double s = u(rng), t = u(rng);
    Dual q, qu, qv;
    evaluate_dual(p.tables.plans, plain_points, patch, s, t, q, qu, qv);
    EXPECT_LT((evaluate_patch(p.tables.plans, p.points, patch, s, t)->position - q.tail<3>()).norm(), 1e-12);
    EXPECT_LT((evaluate_patch(a.tables.plans, a.points, patch, s, t)->position -
               evaluate_patch(b.tables.plans, b.points, patch, s, t)->position)
                  .norm(),
              1e-12);
  }
}

TEST(PlanBuilder, AnalyticNormalsMatchFiniteDifferences) {
  const PlannedMesh p(with_random_covariances(make_sample("valence5"), 4), 3);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.01, 0.99);
  for (int k = 0; k < 200; ++k) {
    const int patch = int(u(rng) * p.tables.plans.n_patches());
    const double s = u(rng), t = u(rng), h = 1e-6;
    const auto c = evaluate_patch(p.tables.plans, p.points, patch, s, t);
    const auto su = [&](double ds, double dt) {
      return evaluate_patch(p.tables.plans, p.points, patch, s + ds, t + dt)->position;
    };
    const Vec3 du = (su(h, 0) - su(-h, 0)) / (2 * h), dv = (su(0, h) - su(0, -h)) / (2 * h);
    EXPECT_LT((c->du - du).norm(), 1e-5 * (1 + du.norm()));
    EXPECT_LT((c->dv - dv).norm(), 1e-5 * (1 + dv.norm()));
  }
  EXPECT_THROW(build_plans(p.mesh.topology(), 0, ExtraordinaryNodes::bezier), Error);
  EXPECT_THROW(build_plans(p.mesh.topology(), 9), Error);
}

}  // namespace
}  // namespace gps
