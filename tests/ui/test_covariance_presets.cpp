#include "ui/editing/covariance_presets.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "core/mesh/inference.h"
#include "core/modelling/samples.h"
#include "core/edit/covariance_edit.h"
#include "ui/panels/inspector_panel.h"

namespace gps {
namespace {

TEST(CovariancePresets, DiscAndNeedleAlignWithTheNormal) {
  const CovarianceMesh mesh = make_sample("cube");
  for (const int v : {0, 5}) {
    const Vec3 n = vertex_normal(mesh, v);
    EXPECT_GT(n.dot(mesh.mean(size_t(v)).normalized()), 0.99);  // a cube corner's normal points outward
    const double s = mean_sigma(mesh.covariance(size_t(v)));
    const Mat3 disc = preset_covariances(mesh, {v}, CovariancePreset::disc, 0)[0];
    const Mat3 needle = preset_covariances(mesh, {v}, CovariancePreset::needle, 0)[0];
    EXPECT_NEAR(n.dot(disc * n), std::pow(kFlatRatio * s, 2), 1e-12);
    EXPECT_NEAR(n.dot(needle * n), s * s, 1e-12);
    const Vec3 t = n.unitOrthogonal();
    EXPECT_NEAR(t.dot(disc * t), s * s, 1e-12);
    EXPECT_NEAR(t.dot(needle * t), std::pow(kFlatRatio * s, 2), 1e-12);
    EXPECT_TRUE(is_spd(disc));
    EXPECT_TRUE(is_spd(needle));
  }
}

TEST(CovariancePresets, IsotropicSharpenSoftenInferred) {
  CovarianceMesh mesh = make_sample("valence5");
  mesh.set_mean(3, mesh.mean(3) + Vec3(0.1, 0.2, 0.05));
  const std::vector<int> vs = {1, 3};
  EXPECT_TRUE(
      preset_covariances(mesh, vs, CovariancePreset::isotropic, 0.2)[1].isApprox(0.04 * Mat3::Identity(), 1e-15));
  EXPECT_EQ(preset_covariances(mesh, vs, CovariancePreset::sharpen, 0)[0], 0.1 * mesh.covariance(1));
  EXPECT_EQ(preset_covariances(mesh, vs, CovariancePreset::soften, 0)[1], 10.0 * mesh.covariance(3));
  CovarianceMesh inferred = mesh;
  infer_covariances(inferred);
  const auto got = preset_covariances(mesh, vs, CovariancePreset::inferred, 0);
  EXPECT_EQ(got[0], inferred.covariance(1));
  EXPECT_EQ(got[1], inferred.covariance(3));
  EXPECT_NEAR(mean_sigma(Vec3(0.01, 0.04, 0.09).asDiagonal()), std::cbrt(0.1 * 0.2 * 0.3), 1e-12);
}

TEST(Inspector, EulerAnglesRoundTrip) {
  for (const Vec3& angles : {Vec3(10, 20, 30), Vec3(-170, 45, 100), Vec3(0, 0, 0), Vec3(5, -80, -60)}) {
    const Mat3 r = rotation_from_euler_degrees(angles);
    EXPECT_NEAR((r * r.transpose() - Mat3::Identity()).norm(), 0.0, 1e-12);
    EXPECT_LT((euler_degrees(r) - angles).norm(), 1e-9) << angles.transpose();
  }
  // Any principal frame survives the trip (the inspector shows the frame this way).
  const EllipsoidAxes e = ellipsoid_axes(Vec3(1, 2, 3).asDiagonal());
  EXPECT_LT((rotation_from_euler_degrees(euler_degrees(e.axes)) - e.axes).norm(), 1e-12);
}

}  // namespace
}  // namespace gps
