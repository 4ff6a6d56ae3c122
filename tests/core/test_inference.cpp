// Gaussian inference for plain meshes (GPS paper Eq. 16–17, docs/design.md §1) and the isotropic default.
#include "core/mesh/inference.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "core/support/error.h"
#include "core/modelling/samples.h"

namespace gps {
namespace {

CovarianceMesh plain(const std::vector<Vec3>& p, const std::vector<std::vector<int>>& f) {
  return make_covariance_mesh(p, std::vector<Mat3>(p.size(), Mat3::Identity()), f, "test");
}

double relative_error(const Mat3& a, const Mat3& b) { return (a - b).norm() / b.norm(); }

// One triangle: every vertex gets the face's second central moment plus bias·λmax·I (Eq. 16), by hand.
TEST(Inference, SingleTriangleMatchesEquation16ByHand) {
  CovarianceMesh m = plain({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
  // Offsets from the centroid (1/3, 1/3): moment xx = yy = 2/9, xy = −1/9; eigenvalues 1/3 and 1/9.
  Mat3 moment;
  moment << 2.0 / 9, -1.0 / 9, 0, -1.0 / 9, 2.0 / 9, 0, 0, 0, 0;
  for (const double bias : {0.05, 0.3}) {
    infer_covariances(m, bias);
    const Mat3 expected = moment + bias / 3.0 * Mat3::Identity();
    for (size_t i = 0; i < 3; ++i) EXPECT_LT(relative_error(m.covariance(i), expected), 1e-12) << m.covariance(i);
  }
}

// Eq. 17: a vertex shared by faces gets the inverse of the summed face precisions.
TEST(Inference, SharedVertexSumsFacePrecisions) {
  CovarianceMesh m = plain({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 1, 2}, {0, 3, 1}});
  const double bias = 0.05;
  infer_covariances(m, bias);
  CovarianceMesh a = plain({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
  CovarianceMesh b = plain({{0, 0, 0}, {0, 0, 1}, {1, 0, 0}}, {{0, 1, 2}});
  infer_covariances(a, bias);
  infer_covariances(b, bias);
  const Mat3 expected = (a.covariance(0).inverse() + b.covariance(0).inverse()).inverse();
  EXPECT_LT(relative_error(m.covariance(0), expected), 1e-12);
  EXPECT_LT(relative_error(m.covariance(2), a.covariance(2)), 1e-12);  // only in face 0
  EXPECT_LT(relative_error(m.covariance(3), b.covariance(1)), 1e-12);  // only in face 1
}

// Moving, rotating and scaling the mesh moves, rotates and scales the Gaussians with it.
TEST(Inference, EquivariantUnderRigidMotionAndScaling) {
  CovarianceMesh m = make_sample("torus");
  infer_covariances(m);
  const Mat3 r = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const double s = 3.5;
  CovarianceMesh t = m;
  for (size_t i = 0; i < t.n_vertices(); ++i) t.set_mean(i, s * (r * m.mean(i)) + Vec3(4, -2, 1));
  infer_covariances(t);
  for (size_t i = 0; i < m.n_vertices(); ++i)
    EXPECT_LT(relative_error(t.covariance(i), s * s * r * m.covariance(i) * r.transpose()), 1e-9) << "vertex " << i;
}

// The bias is a floor on the flatness: the larger the bias, the rounder every Gaussian.
TEST(Inference, LargerBiasGivesRounderGaussians) {
  CovarianceMesh m = make_sample("grid", 100);
  double previous = 0;
  for (const double bias : {0.001, 0.01, 0.1, 1.0}) {
    infer_covariances(m, bias);
    double smallest_ratio = 1;
    for (const Mat3& c : m.covariances) {
      EXPECT_TRUE(is_spd(c));
      const Vec3 eigenvalues = Eigen::SelfAdjointEigenSolver<Mat3>(c, Eigen::EigenvaluesOnly).eigenvalues();
      smallest_ratio = std::min(smallest_ratio, eigenvalues(0) / eigenvalues(2));
    }
    EXPECT_GT(smallest_ratio, previous) << "bias " << bias;
    previous = smallest_ratio;
  }
}

// A vertex in no face: isotropic, σ = half the mean edge length (here edges 1, 1 and √2).
TEST(Inference, IsolatedVertexGetsAnIsotropicGuessAtTheMeshScale) {
  CovarianceMesh m = plain({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {9, 9, 9}}, {{0, 1, 2}});
  infer_covariances(m);
  const double sigma = 0.5 * (2 + std::sqrt(2.0)) / 3;
  EXPECT_LT(relative_error(m.covariance(3), sigma * sigma * Mat3::Identity()), 1e-12);
}

TEST(Inference, DegenerateFaceAndBadBiasAreErrors) {
  CovarianceMesh m = plain({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
  EXPECT_THROW(infer_covariances(m, -1.0), Error);
  EXPECT_THROW(infer_covariances(m, std::nan("")), Error);
  try {
    infer_covariances(m, 0.0);
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(e.exit_code(), 2);
  }
  CovarianceMesh d = plain({{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, {{0, 1, 2}});
  try {
    infer_covariances(d);
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("face 0 is degenerate"), std::string::npos) << e.what();
  }
}

// Inferred covariances scale as the square of the edges: a mesh whose edges are far under or over the
// covariances' range is refused as too small or too large, with its covariances left as they were.
TEST(Inference, AMeshTooSmallOrTooLargeForItsCovariancesIsNamedSo) {
  for (const double scale : {1e-60, 1e-160, 1e60}) {
    std::vector<Vec3> corners = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    for (Vec3& p : corners) p *= scale;
    for (const bool isotropic : {false, true}) {
      CovarianceMesh m = plain(corners, {{0, 1, 2, 3}});
      const std::vector<Mat3> before = m.covariances;
      try {
        isotropic ? isotropic_covariances(m) : infer_covariances(m);
        ADD_FAILURE() << scale;
      } catch (const Error& e) {
        const std::string expected = scale < 1 ? "the mesh is too small" : "the mesh is too large";
        EXPECT_EQ(std::string(e.what()).rfind(expected + " for covariances inferred from its edges", 0), 0u)
            << e.what();
      }
      EXPECT_EQ(m.covariances, before) << scale;
    }
  }
  // Within the range, at either end: accepted.
  for (const double scale : {1e-40, 1e40}) {
    CovarianceMesh m = plain({{0, 0, 0}, {scale, 0, 0}, {scale, scale, 0}, {0, scale, 0}}, {{0, 1, 2, 3}});
    EXPECT_NO_THROW(infer_covariances(m)) << scale;
    EXPECT_EQ(gaussians_problem(m), "") << scale;
  }
}

// Isotropic: σ_i = s × the mean length of the edges at vertex i.
TEST(Inference, IsotropicVarianceFollowsLocalEdgeLength) {
  // A strip of two quads, the second twice as long: edge lengths 1 and 2.
  CovarianceMesh m =
      plain({{0, 0, 0}, {1, 0, 0}, {3, 0, 0}, {0, 1, 0}, {1, 1, 0}, {3, 1, 0}}, {{0, 1, 4, 3}, {1, 2, 5, 4}});
  isotropic_covariances(m, 0.5);
  EXPECT_LT(relative_error(m.covariance(0), 0.25 * Mat3::Identity()), 1e-12);                          // edges 1, 1
  EXPECT_LT(relative_error(m.covariance(2), std::pow(0.5 * 1.5, 2) * Mat3::Identity()), 1e-12);        // edges 2, 1
  EXPECT_LT(relative_error(m.covariance(1), std::pow(0.5 * 4.0 / 3.0, 2) * Mat3::Identity()), 1e-12);  // 1, 2, 1
  EXPECT_THROW(isotropic_covariances(m, 0.0), Error);
}

}  // namespace
}  // namespace gps
