#include "core/reference/reference_subdivision.h"

#include <gtest/gtest.h>

#include <omp.h>

#include <random>

#include "core/mesh/dual_map.h"
#include "core/support/error.h"
#include "core/modelling/samples.h"
#include "core/plans/patch_layout.h"
#include "tests/support/random_spd.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

void randomize_covariances(CovarianceMesh& m, unsigned seed, double scale = 0.1) {
  std::mt19937 rng(seed);
  for (auto& c : m.covariances) c = scale * test::random_spd(rng, 0.2);
}

double max_mean_distance(const CovarianceMesh& a, const std::vector<Vec3>& b) {
  double d = 0;
  for (size_t i = 0; i < b.size(); ++i) d = std::max(d, (a.mean(i) - b[i]).norm());
  return d;
}

TEST(ReferenceSubdivision, EqualIsotropicCovariancesGiveTheLinearScheme) {
  for (const bool limit : {false, true}) {
    for (const auto& mesh : {test::cube_mesh(), test::prism_mesh(), test::grid_mesh(4, 3)}) {
      const SubdivisionOptions o{Scheme::catmull_clark, 3, limit};
      const auto r = subdivide(mesh, o);
      EXPECT_LT(max_mean_distance(r.mesh, subdivide_points(mesh, o)), 1e-12);
    }
    const auto cone = test::cone_mesh();
    for (const LoopBeta beta : {LoopBeta::loop, LoopBeta::warren}) {
      const SubdivisionOptions o{Scheme::loop, 3, limit, beta};
      EXPECT_LT(max_mean_distance(subdivide(cone, o).mesh, subdivide_points(cone, o)), 1e-12);
    }
  }
}

// No level and no limit: the mesh itself, its Gaussians bit for bit (their round trip through the
// 9D points moved a triangle's corners by a few units in the last place).
TEST(ReferenceSubdivision, NoLevelGivesTheMeshsOwnGaussians) {
  CovarianceMesh pawn = make_sample("pawn");
  randomize_covariances(pawn, 3);
  for (const auto& [mesh, scheme] :
       {std::pair{test::icosahedron_mesh(), Scheme::loop}, std::pair{test::icosahedron_mesh(), Scheme::catmull_clark},
        std::pair{pawn, Scheme::catmull_clark}}) {
    const CovarianceMesh out = subdivide(mesh, {scheme, 0, false}).mesh;
    EXPECT_EQ(out.means(), mesh.means());
    EXPECT_EQ(out.covariances, mesh.covariances);
    EXPECT_EQ(out.topology().verts, mesh.topology().verts);
  }
}

TEST(ReferenceSubdivision, ScalingEveryCovarianceChangesNothing) {
  for (const Scheme scheme : {Scheme::catmull_clark, Scheme::loop}) {
    CovarianceMesh mesh = scheme == Scheme::loop ? test::cone_mesh() : test::prism_mesh();
    randomize_covariances(mesh, 3);
    CovarianceMesh scaled = mesh;
    for (auto& c : scaled.covariances) c *= 7.3;
    const SubdivisionOptions o{scheme, 3, true};
    const auto a = subdivide(mesh, o), b = subdivide(scaled, o);
    std::vector<Vec3> means(a.mesh.n_vertices());
    for (size_t i = 0; i < means.size(); ++i) means[i] = a.mesh.mean(i);
    EXPECT_LT(max_mean_distance(b.mesh, means), 1e-12);
    for (size_t i = 0; i < means.size(); ++i)
      EXPECT_LT((b.mesh.covariance(i) - 7.3 * a.mesh.covariance(i)).norm(), 1e-9 * b.mesh.covariance(i).norm());
  }
}

double bspline(int i, double t) {
  const double s = 1 - t;
  switch (i) {
    case 0:
      return s * s * s / 6;
    case 1:
      return (3 * t * t * t - 6 * t * t + 4) / 6;
    case 2:
      return (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6;
    default:
      return t * t * t / 6;
  }
}

// In 9D the Catmull-Clark limit of a regular region is the bicubic B-spline of the q's.
TEST(ReferenceSubdivision, RegularGridLimitIsTheBicubicBSpline) {
  const int n = 7;
  CovarianceMesh mesh = test::grid_mesh(n, n);
  randomize_covariances(mesh, 5, 0.05);
  const auto r = subdivide(mesh, {Scheme::catmull_clark, 3, true});
  const auto grid_pos = [&](int v) { return Eigen::Vector2i(v % (n + 1), v / (n + 1)); };
  int checked = 0;
  for (size_t k = 0; k < r.mesh.n_vertices(); ++k) {
    const PatchParam pp = r.vertex_params[k];
    const auto corners = mesh.face(size_t(pp.patch));
    const Eigen::Vector2i c0 = grid_pos(corners[0]);
    const Eigen::Vector2i du = grid_pos(corners[1]) - c0, dv = grid_pos(corners[3]) - c0;
    bool inside = true;
    Dual q = Dual::Zero();
    for (int b = 0; b < 4 && inside; ++b)
      for (int a = 0; a < 4; ++a) {
        const Eigen::Vector2i g = c0 + (a - 1) * du + (b - 1) * dv;
        if (g.minCoeff() < 0 || g.maxCoeff() > n) {
          inside = false;
          break;
        }
        const int v = g.y() * (n + 1) + g.x();
        q += bspline(a, pp.u) * bspline(b, pp.v) * to_dual(mesh.mean(size_t(v)), mesh.covariance(size_t(v)));
      }
    if (!inside) continue;
    const auto g = from_dual(q);
    ASSERT_TRUE(g);
    EXPECT_LT((g->mean - r.mesh.mean(k)).norm(), 1e-12) << "vertex " << k;
    EXPECT_LT((g->covariance - r.mesh.covariance(k)).norm(), 1e-12 * g->covariance.norm());
    ++checked;
  }
  EXPECT_GT(checked, 500);
}

TEST(ReferenceSubdivision, LimitPositionsAreFixedUnderFurtherSubdivision) {
  for (const Scheme scheme : {Scheme::catmull_clark, Scheme::loop}) {
    CovarianceMesh mesh = scheme == Scheme::loop ? test::cone_mesh() : test::prism_mesh();
    randomize_covariances(mesh, 9);
    const auto coarse = subdivide(mesh, {scheme, 1, true});
    const auto fine = subdivide(mesh, {scheme, 3, true});
    for (size_t i = 0; i < coarse.mesh.n_vertices(); ++i)
      EXPECT_LT((coarse.mesh.mean(i) - fine.mesh.mean(i)).norm(), 1e-12) << "vertex " << i;
    // Level 0 of a mesh with n-gons projects through one hidden step.
    const auto base = subdivide(mesh, {scheme, 0, true});
    for (size_t i = 0; i < base.mesh.n_vertices(); ++i)
      EXPECT_LT((base.mesh.mean(i) - fine.mesh.mean(i)).norm(), 1e-12) << "vertex " << i;
  }
}

TEST(ReferenceSubdivision, BoundariesFollowTheCubicBSplineCurveAndCornersStay) {
  CovarianceMesh mesh = test::grid_mesh(3, 3);
  randomize_covariances(mesh, 13);
  const auto r = subdivide(mesh, {Scheme::catmull_clark, 2, true});
  for (const int corner : {0, 3, 12, 15})
    EXPECT_LT((r.mesh.mean(size_t(corner)) - mesh.mean(size_t(corner))).norm(), 1e-13);
  // Boundary vertex 1 (between 0 and 2 on the bottom row): limit (a + 4v + b)/6 in 9D.
  const Dual q = (to_dual(mesh.mean(0), mesh.covariance(0)) + 4.0 * to_dual(mesh.mean(1), mesh.covariance(1)) +
                  to_dual(mesh.mean(2), mesh.covariance(2))) /
                 6.0;
  EXPECT_LT((from_dual(q)->mean - r.mesh.mean(1)).norm(), 1e-12);
}

TEST(ReferenceSubdivision, LoopWeightsDiffer) {
  const auto cone = test::cone_mesh();
  EXPECT_NEAR(loop_beta(6, LoopBeta::loop), 1.0 / 16.0, 1e-15);  // regular vertices agree
  EXPECT_NEAR(loop_beta(6, LoopBeta::warren), 1.0 / 16.0, 1e-15);
  const auto a = subdivide(cone, {Scheme::loop, 2, true, LoopBeta::loop});
  const auto b = subdivide(cone, {Scheme::loop, 2, true, LoopBeta::warren});
  EXPECT_GT((a.mesh.mean(0) - b.mesh.mean(0)).norm(), 1e-3);  // the valence-8 apex differs
}

TEST(ReferenceSubdivision, SmallApexCovariancePullsTheSurfaceToTheApex) {
  const double iso = subdivide(test::cone_mesh(), {Scheme::loop, 4, true}).mesh.mean(0).y();
  const double pointy = subdivide(test::cone_mesh(1e-5 * Mat3::Identity()), {Scheme::loop, 4, true}).mesh.mean(0).y();
  EXPECT_LT(iso, 1.5 - 0.1);
  EXPECT_GT(pointy, iso);
  EXPECT_GT(pointy, 1.5 - 0.01);
}

TEST(ReferenceSubdivision, VertexParamsNameAPatchOfTheInput) {
  const auto mesh = test::prism_mesh();
  const auto r = subdivide(mesh, {Scheme::catmull_clark, 2, false});
  ASSERT_EQ(r.vertex_params.size(), r.mesh.n_vertices());
  const int n_patches = make_patch_layout(mesh.topology()).n_patches();
  EXPECT_EQ(n_patches, 2 * 5 + 5);  // the pentagons are split, the quads are not
  for (const auto& p : r.vertex_params) {
    EXPECT_GE(p.patch, 0);
    EXPECT_LT(p.patch, n_patches);
    EXPECT_GE(p.u, 0);
    EXPECT_LE(p.u, 1);
    EXPECT_GE(p.v, 0);
    EXPECT_LE(p.v, 1);
  }
}

// The per-face, per-edge and per-vertex rules run on all cores for large meshes: same result, bit for bit.
TEST(ReferenceSubdivision, AllCoresGiveTheOneCoreResultBitForBit) {
  const CovarianceMesh mesh = make_sample("sphere", 20000);
  omp_set_num_threads(1);
  const auto one = subdivide(mesh, {Scheme::catmull_clark, 2, true});
  omp_set_num_threads(2);
  const auto two = subdivide(mesh, {Scheme::catmull_clark, 2, true});
  omp_set_num_threads(omp_get_num_procs());
  ASSERT_EQ(one.mesh.n_vertices(), two.mesh.n_vertices());
  for (size_t i = 0; i < one.mesh.n_vertices(); ++i) {
    ASSERT_EQ(one.mesh.mean(i), two.mesh.mean(i)) << i;
    ASSERT_EQ(one.mesh.covariance(i), two.mesh.covariance(i)) << i;
  }
}

TEST(ReferenceSubdivision, RefusesBadInput) {
  EXPECT_THROW(subdivide(test::cube_mesh(), {Scheme::loop, 1, false}), Error);
  EXPECT_THROW(subdivide(test::cube_mesh(), {Scheme::catmull_clark, 9, false}), Error);
  // Three faces on one edge: non-manifold.
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  EXPECT_THROW(make_covariance_mesh(p, std::vector<Mat3>(5, Mat3::Identity()), {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}),
               Error);
}

}  // namespace
}  // namespace gps
