// GaussianChange: a scale along a principal axis keeps the frame, a rotation keeps every σ,
// weights interpolate, and the mirrored change of the mirrored Gaussian is the mirror image.
#include "core/edit/gaussian_change.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "core/edit/covariance_edit.h"

namespace gps {
namespace {

Mat3 test_covariance() {
  const Mat3 r = Eigen::AngleAxisd(0.7, Vec3(1, -1, 2).normalized()).toRotationMatrix();
  return r * Vec3(0.01, 0.04, 0.2).asDiagonal() * r.transpose();
}

TEST(GaussianChange, ScalingAPrincipalAxisKeepsTheFrameAndTheOtherSigmas) {
  const Mat3 c = test_covariance();
  const EllipsoidAxes before = ellipsoid_axes(c);
  for (int axis = 0; axis < 3; ++axis) {
    GaussianChange change;
    change.scale_axis = before.axes.col(axis);
    change.scale = 3.0;
    const Mat3 after = change.apply_to_covariance(c);
    for (int k = 0; k < 3; ++k) {
      const Vec3 u = before.axes.col(k), image = after * u;
      EXPECT_LT((image - image.dot(u) * u).norm(), 1e-12 * image.norm());
      EXPECT_NEAR(std::sqrt(u.dot(image)), before.sigmas[k] * (k == axis ? 3.0 : 1.0), 1e-12);
    }
  }
}

TEST(GaussianChange, RotationsKeepSigmasAndWeightsInterpolate) {
  const Mat3 c = test_covariance();
  GaussianChange change;
  change.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(1.2, Vec3(0, 1, 1).normalized()));
  change.translation = Vec3(1, 2, 3);
  const Vec3 s0 = Eigen::SelfAdjointEigenSolver<Mat3>(c).eigenvalues();
  const Vec3 s1 = Eigen::SelfAdjointEigenSolver<Mat3>(change.apply_to_covariance(c)).eigenvalues();
  EXPECT_LT((s0 - s1).cwiseAbs().maxCoeff(), 1e-15);
  const GaussianChange half = change.weighted(0.5);
  EXPECT_NEAR(Eigen::AngleAxisd(half.rotation).angle(), 0.6, 1e-12);
  EXPECT_EQ(half.translation, Vec3(0.5, 1, 1.5));
  GaussianChange scale;
  scale.scale = 4.0;
  EXPECT_NEAR(scale.weighted(0.5).scale, 2.0, 1e-15);
  EXPECT_TRUE(GaussianChange{}.weighted(0.3).keeps_covariance());
}

TEST(GaussianChange, TheMirroredChangeOfTheMirrorImageIsTheMirrorImageOfTheChange) {
  GaussianChange change;
  change.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Vec3(1, 2, 3).normalized()));
  change.scale_axis = Vec3(0.6, 0.8, 0);
  change.scale = 1.7;
  change.translation = Vec3(0.3, -0.2, 0.1);
  const Mat3 c = test_covariance();
  const Vec3 mean(0.5, 1, -2);
  for (int axis = 0; axis < 3; ++axis) {
    Mat3 m = Mat3::Identity();
    m(axis, axis) = -1;
    const GaussianChange mirrored = change.mirrored(axis);
    EXPECT_LT((mirrored.apply_to_covariance(m * c * m) - m * change.apply_to_covariance(c) * m).norm(), 1e-12);
    EXPECT_LT((mirrored.apply_to_mean(m * mean) - m * change.apply_to_mean(mean)).norm(), 1e-15);
  }
}

}  // namespace
}  // namespace gps
