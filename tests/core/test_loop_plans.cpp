// Loop plans against the exact reference: box-spline patches and exact extraordinary nodes equal Loop
// GPS subdivision with limit projection at every tested parameter.
#include "core/plans/loop_plan_builder.h"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <map>

#include "core/support/error.h"
#include "core/reference/limit_masks.h"
#include "core/extraordinary/loop_extraordinary_tables.h"
#include "core/patches/patch_basis.h"
#include "core/evaluation/patch_eval.h"
#include "core/plans/planned_surface.h"
#include "core/reference/reference_subdivision.h"
#include "core/modelling/samples.h"
#include "core/evaluation/tessellator.h"
#include "tests/support/plan_fixture.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

using test::PlannedMesh;

PlannedMesh loop_planned(CovarianceMesh m, LoopBeta beta = LoopBeta::loop) {
  return PlannedMesh(std::move(m), PlanOptions{Scheme::loop, 3, beta});
}

// The box spline of core/patches/patch_basis.h is the limit of Loop subdivision of its 12-point net: a
// regular lattice, one net point a unit vector, three Loop steps and limit projection.
TEST(LoopPatchBasis, IsTheLimitOfLoopSubdivisionOfTheNet) {
  const int R = 5;
  std::map<std::pair<int, int>, int> id;
  std::vector<Eigen::Vector2d> uv;
  for (int i = -R; i <= R; ++i)
    for (int j = -R; j <= R; ++j)
      if (std::abs(i + j) <= R) id[{i, j}] = int(uv.size()), uv.emplace_back(i, j);
  PolygonTopology t;
  t.n_vertices = int(uv.size());
  const auto has = [&](int i, int j) { return id.count({i, j}) > 0; };
  for (const auto& [ij, v] : id) {
    const auto [i, j] = ij;
    for (const auto& tri : {std::array<std::pair<int, int>, 3>{{{i, j}, {i + 1, j}, {i, j + 1}}},
                            std::array<std::pair<int, int>, 3>{{{i + 1, j}, {i + 1, j + 1}, {i, j + 1}}}}) {
      if (!has(tri[0].first, tri[0].second) || !has(tri[1].first, tri[1].second) || !has(tri[2].first, tri[2].second))
        continue;
      for (const auto& x : tri) t.verts.push_back(id[x]);
      t.offsets.push_back(int(t.verts.size()));
    }
  }
  const int net[12][2] = {{0, 0},  {1, 0},  {0, 1}, {-1, 0}, {0, -1}, {1, -1},
                          {-1, 1}, {2, -1}, {2, 0}, {1, 1},  {0, 2},  {-1, 2}};
  std::vector<Eigen::VectorXd> values(uv.size(), Eigen::VectorXd::Zero(12));
  for (int k = 0; k < 12; ++k) values[size_t(id[{net[k][0], net[k][1]}])](k) = 1.0;
  for (int level = 0; level < 3; ++level) {
    const MeshConnectivity c = connectivity_of(t);
    values = loop_values(t, c, values, LoopBeta::loop);
    for (int e = 0; e < c.n_edges(); ++e)
      uv.push_back(0.5 * (uv[size_t(c.edge_verts[2 * size_t(e)])] + uv[size_t(c.edge_verts[2 * size_t(e) + 1])]));
    t = loop_topology(t, c);
  }
  const std::vector<Eigen::VectorXd> limit = loop_limit(t, connectivity_of(t), values, LoopBeta::loop);
  int checked = 0;
  for (size_t v = 0; v < uv.size(); ++v) {
    const double u = uv[v].x(), w = uv[v].y();
    if (u < -1e-12 || w < -1e-12 || u + w > 1 + 1e-12) continue;
    double b[12], bu[12], bv[12];
    loop_box_spline_basis(u, w, b, bu, bv);
    for (int k = 0; k < 12; ++k) EXPECT_NEAR(b[k], limit[v](k), 1e-14) << "net point " << k << " at " << u << ", " << w;
    ++checked;
  }
  EXPECT_EQ(checked, 45);  // the level-3 points of the triangle
}

// Largest distance, relative to the bounding-box diagonal, between the plans at a reference
// vertex's parameter and that vertex (Loop GPS subdivision with limit projection).
double error_against_reference(const PlannedMesh& p, int levels, LoopBeta beta = LoopBeta::loop) {
  return test::error_against_reference(p, {Scheme::loop, levels, true, beta});
}

TEST(LoopPlans, RegularTrianglesAreOneBoxSplineNode) {
  const PlannedMesh p = loop_planned(test::triangle_grid_mesh(6, 5));
  int regular_roots = 0;
  for (const int root : p.tables.plans.patch_roots) regular_roots += p.tables.plans.nodes[size_t(root)] == kNodeRegular;
  // Every triangle but those at the grid corners of one face (1 each) and of two faces (2 each).
  EXPECT_EQ(regular_roots, p.tables.plans.n_patches() - 6);
  EXPECT_EQ(p.tables.plans.shape, PatchShape::triangle);
  EXPECT_LT(error_against_reference(p, 5), 1e-9);
}

TEST(LoopPlans, EqualTheReferenceAtEveryDyadicParameter) {
  struct Case {
    const char* name;
    CovarianceMesh mesh;
  };
  std::vector<Case> cases;
  cases.push_back({"icosahedron", test::with_random_covariances(test::icosahedron_mesh(), 1)});
  for (int n = 3; n <= 16; ++n)
    cases.push_back({"bipyramid", test::with_random_covariances(test::bipyramid_mesh(n), unsigned(n))});
  cases.push_back({"open grid", test::with_random_covariances(test::triangle_grid_mesh(5, 4), 7)});
  for (const auto& name : {"cone", "cone-pointy", "cone-concave", "cone-plateau", "cone-cylinder"})
    cases.push_back({name, make_sample(name)});
  for (const auto& c : cases) {
    const PlannedMesh p = loop_planned(c.mesh);
    const double error = error_against_reference(p, 6);
    std::printf("%-14s %3zu vertices: max error at the reference's parameters %.1e of the diagonal\n", c.name,
                c.mesh.n_vertices(), error);
    EXPECT_LT(error, 1e-9) << c.name << " with " << c.mesh.n_vertices() << " vertices";
  }
}

TEST(LoopPlans, WarrensBetaToo) {
  const PlannedMesh p = loop_planned(test::with_random_covariances(test::bipyramid_mesh(3), 5), LoopBeta::warren);
  EXPECT_LT(error_against_reference(p, 5, LoopBeta::warren), 1e-9);
}

// The derivatives are those of the evaluated surface: central differences of q along u and v.
TEST(LoopPlans, DerivativesMatchFiniteDifferences) {
  const PlannedMesh p = loop_planned(test::with_random_covariances(test::bipyramid_mesh(7), 3));
  const double h = 1e-6;
  double worst = 0;
  for (int patch = 0; patch < p.tables.plans.n_patches(); ++patch)
    for (const auto& [u, v] : {std::pair{0.31, 0.22}, {0.05, 0.07}, {0.6, 0.3}, {0.2, 0.45}, {0.013, 0.002}}) {
      Dual q, qu, qv, a, b, x;
      evaluate_dual(p.tables.plans, p.points, patch, u, v, q, qu, qv);
      evaluate_dual(p.tables.plans, p.points, patch, u + h, v, a, x, x);
      evaluate_dual(p.tables.plans, p.points, patch, u - h, v, b, x, x);
      worst = std::max(worst, ((a - b) / (2 * h) - qu).norm() / (1 + qu.norm()));
      evaluate_dual(p.tables.plans, p.points, patch, u, v + h, a, x, x);
      evaluate_dual(p.tables.plans, p.points, patch, u, v - h, b, x, x);
      worst = std::max(worst, ((a - b) / (2 * h) - qv).norm() / (1 + qv.norm()));
    }
  EXPECT_LT(worst, 1e-5);
}

// At the extraordinary vertex itself the normal comes from the limit tangents and agrees with the
// normals just beside it.
TEST(LoopPlans, NormalsAreDefinedAtExtraordinaryVertices) {
  const PlannedMesh p = loop_planned(test::with_random_covariances(test::icosahedron_mesh(), 9));
  for (int patch = 0; patch < p.tables.plans.n_patches(); ++patch) {
    const auto at = evaluate_patch(p.tables.plans, p.points, patch, 0.0, 0.0);
    const auto near = evaluate_patch(p.tables.plans, p.points, patch, 1e-7, 1e-7);
    ASSERT_TRUE(at && near);
    EXPECT_TRUE(at->normal.allFinite());
    EXPECT_GT(at->normal.dot(near->normal), std::cos(0.5 * M_PI / 180)) << "patch " << patch;
  }
}

TEST(LoopPlans, ScalingEveryCovarianceChangesNothingAndIsotropicIsPlainLoop) {
  const CovarianceMesh m = test::icosahedron_mesh(0.2);
  CovarianceMesh scaled = m;
  for (auto& c : scaled.covariances) c *= 7.0;
  const PlannedMesh a = loop_planned(m), b = loop_planned(scaled);
  SubdivisionOptions o;
  o.scheme = Scheme::loop;
  o.levels = 3;
  o.limit = true;
  const std::vector<Vec3> plain = subdivide_points(m, o);
  const auto ref = subdivide(m, o);
  for (size_t k = 0; k < ref.mesh.n_vertices(); ++k) {
    const PatchParam& pp = ref.vertex_params[k];
    const auto sa = evaluate_patch(a.tables.plans, a.points, pp.patch, pp.u, pp.v);
    const auto sb = evaluate_patch(b.tables.plans, b.points, pp.patch, pp.u, pp.v);
    ASSERT_TRUE(sa && sb);
    EXPECT_LT((sa->position - sb->position).norm(), 1e-12);
    EXPECT_LT((sa->position - plain[k]).norm(), 1e-12);
  }
}

// Independent Loop GPS implementation's apex heights (Loop's β, limit projection, apex at y = 1.5).
TEST(LoopPlans, ConeApexesReachTheIndependentLimitHeights) {
  const std::map<std::string, double> apex = {{"cone", 0.11744},
                                              {"cone-pointy", 1.49744},
                                              {"cone-concave", 1.26376},
                                              {"cone-plateau", 1.49744},
                                              {"cone-cylinder", 1.49744}};
  for (const auto& [name, height] : apex) {
    const PlannedMesh p = loop_planned(make_sample(name));
    // The apex is vertex 0, corner 0 of face 0.
    const auto s = evaluate_patch(p.tables.plans, p.points, 0, 0.0, 0.0);
    ASSERT_TRUE(s);
    EXPECT_NEAR(s->position.y(), height, 5e-6) << name;
    EXPECT_TRUE(s->covariance.llt().info() == Eigen::Success) << name;
  }
}

TEST(LoopPlans, TessellationIsWatertight) {
  const PlannedMesh p = loop_planned(test::with_random_covariances(test::triangle_grid_mesh(4, 3), 2));
  const TriangleMesh t = tessellate(p.tables.plans, p.points, 5);
  // Every interior edge of the output is shared by exactly two triangles; boundary edges by one.
  std::map<std::pair<int, int>, int> edges;
  for (const auto& tri : t.triangles)
    for (int k = 0; k < 3; ++k) edges[std::minmax(tri[size_t(k)], tri[size_t((k + 1) % 3)])] += 1;
  int boundary = 0;
  for (const auto& [e, n] : edges) {
    EXPECT_LE(n, 2);
    boundary += n == 1;
  }
  EXPECT_EQ(boundary, 5 * (2 * 4 + 2 * 3));  // the grid's 14 boundary edges, 5 segments each
  EXPECT_EQ(t.triangles.size(), size_t(p.tables.plans.n_patches() * 25));
}

// Every sample of every cone variant keeps q̂ positive definite (tessellate() throws otherwise), and
// the phantom points of boundary box splines leave non-negative net weights on the real vertices.
TEST(LoopPlans, StayInsideThePositiveDefiniteCone) {
  for (const auto& name : {"cone", "cone-pointy", "cone-concave", "cone-plateau", "cone-cylinder"}) {
    const PlannedMesh p = loop_planned(make_sample(name));
    EXPECT_NO_THROW(tessellate(p.tables.plans, p.points, 16)) << name;
  }
  const PlannedMesh grid = loop_planned(test::triangle_grid_mesh(5, 4));
  const auto& plans = grid.tables.plans;
  const auto& stencils = grid.tables.stencils;
  int boundary_nets = 0;
  for (const int root : plans.patch_roots) {
    if (plans.nodes[size_t(root)] != kNodeRegular) continue;
    bool phantom = false;
    for (int j = 0; j < 12; ++j) phantom = phantom || plans.nodes[size_t(root + 1 + j)] >= stencils.n_base;
    if (!phantom) continue;
    ++boundary_nets;
    for (const auto& [u, v] :
         {std::pair{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {0.3, 0.3}, {0.5, 0.0}, {0.1, 0.8}, {0.33, 0.6}}) {
      double w[12], wu[12], wv[12];
      loop_box_spline_basis(u, v, w, wu, wv);
      std::map<int, double> net;  // weight per base vertex
      for (int j = 0; j < 12; ++j) {
        const int point = plans.nodes[size_t(root + 1 + j)];
        if (point < stencils.n_base) {
          net[point] += w[j];
          continue;
        }
        const int r = point - stencils.first_row();
        for (int k = stencils.offsets[size_t(r)]; k < stencils.offsets[size_t(r) + 1]; ++k)
          net[stencils.indices[size_t(k)]] += w[j] * stencils.weights[size_t(k)];
      }
      for (const auto& [vertex, weight] : net)
        EXPECT_GE(weight, -1e-12) << "vertex " << vertex << " at " << u << ", " << v;
    }
  }
  EXPECT_GT(boundary_nets, 10);
}

TEST(LoopPlans, RefuseNonTrianglesAndHugeValences) {
  EXPECT_THROW(build_loop_plans(test::cube_mesh().topology(), LoopBeta::loop), Error);
  const PolygonTopology fan = test::bipyramid_mesh(kMaxLoopValence + 1).topology();
  EXPECT_THROW(build_loop_plans(fan, LoopBeta::loop), Error);
  // The automatic choice takes Catmull-Clark there, Loop for the same shape of lower valence.
  EXPECT_EQ(scheme_for(fan, PlanOptions{}), Scheme::catmull_clark);
  EXPECT_EQ(scheme_for(test::bipyramid_mesh(kMaxLoopValence).topology(), PlanOptions{}), Scheme::loop);
}

}  // namespace
}  // namespace gps
