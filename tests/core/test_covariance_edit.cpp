#include "core/edit/covariance_edit.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <random>

#include "tests/support/random_spd.h"

namespace gps {
namespace {

Mat3 random_spd(std::mt19937& rng) { return test::random_spd(rng, 0.05); }

TEST(CovarianceEdit, AxesRoundTrip) {
  std::mt19937 rng(1);
  for (int k = 0; k < 50; ++k) {
    const Mat3 c = random_spd(rng);
    const EllipsoidAxes e = ellipsoid_axes(c);
    EXPECT_NEAR(e.axes.determinant(), 1.0, 1e-12);
    EXPECT_LT((covariance_from_axes(e.axes, e.sigmas) - c).norm(), 1e-12 * c.norm());
  }
}

// Dragging an axis end by d scales that standard deviation by (r + d)/r; the others stay.
TEST(CovarianceEdit, DraggingAnAxisEndScalesThatSigma) {
  std::mt19937 rng(2);
  for (int k = 0; k < 30; ++k) {
    const Mat3 c = random_spd(rng);
    const int axis = k % 3;
    const EllipsoidAxes before = ellipsoid_axes(c);
    const double r = 2.0 * before.sigmas[axis], d = 0.3 * r;
    const double factor = axis_drag_factor(r, d);
    EXPECT_NEAR(factor, 1.3, 1e-15);
    const Mat3 edited = scale_axis(c, axis, factor);
    // The scaled axis keeps its direction: Σ' v = (fσ)² v.
    const Vec3 v = before.axes.col(axis);
    EXPECT_LT((edited * v - std::pow(factor * before.sigmas[axis], 2) * v).norm(), 1e-10);
    for (int other = 0; other < 3; ++other) {
      if (other == axis) continue;
      const Vec3 w = before.axes.col(other);
      EXPECT_LT((edited * w - std::pow(before.sigmas[other], 2) * w).norm(), 1e-10);
    }
  }
  EXPECT_GT(axis_drag_factor(1.0, -5.0), 0.0);  // dragging through the centre never inverts
}

TEST(CovarianceEdit, RotationKeepsTheEigenvalues) {
  std::mt19937 rng(3);
  for (int k = 0; k < 30; ++k) {
    const Mat3 c = random_spd(rng);
    const Mat3 r = Eigen::AngleAxisd(0.1 * k, Vec3(1, 2, 3).normalized()).toRotationMatrix();
    const Vec3 a = Eigen::SelfAdjointEigenSolver<Mat3>(c).eigenvalues();
    const Vec3 b = Eigen::SelfAdjointEigenSolver<Mat3>(rotate_covariance(c, r)).eigenvalues();
    EXPECT_LT((a - b).norm(), 1e-12 * a.norm());
  }
}

TEST(CovarianceEdit, ClampingKeepsCovariancesPositiveDefinite) {
  Mat3 bad;
  bad << 1, 2, 0, 2, 1, 0, 0, 0, -3;  // eigenvalues 3, −1, −3
  const Mat3 fixed = clamp_spd(bad, Mat3::Identity());
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Mat3>(fixed).eigenvalues().minCoeff(), 0.0);
  EXPECT_TRUE(fixed.isApprox(fixed.transpose()));
  Mat3 nan = Mat3::Identity();
  nan(1, 1) = std::nan("");
  EXPECT_EQ(clamp_spd(nan, 2.0 * Mat3::Identity()), 2.0 * Mat3::Identity());
  const Mat3 huge = 1e20 * Mat3::Identity();
  EXPECT_LE(clamp_spd(huge, Mat3::Identity()).maxCoeff(), 1e10 * (1 + 1e-12));
}

}  // namespace
}  // namespace gps
