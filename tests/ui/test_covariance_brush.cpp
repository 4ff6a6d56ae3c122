// The sharpen/soften brush's math (ui/editing/covariance_brush.h): its falloff, what one dab does to a
// covariance, that dabs never make a Gaussian degenerate, and which vertices a dab reaches.
#include "ui/editing/covariance_brush.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "core/modelling/affine_transform.h"
#include "core/modelling/samples.h"
#include "ui/editing/covariance_presets.h"

namespace gps {
namespace {

TEST(CovarianceBrush, TheWeightFallsSmoothlyToZeroAtTheRadius) {
  EXPECT_DOUBLE_EQ(brush_weight(0.0, 2.0, 0.5), 0.5);
  EXPECT_DOUBLE_EQ(brush_weight(1.0, 2.0, 1.0), 0.5625);  // (1 − 1/4)²
  EXPECT_EQ(brush_weight(2.0, 2.0, 1.0), 0.0);
  EXPECT_EQ(brush_weight(3.0, 2.0, 1.0), 0.0);
  EXPECT_EQ(brush_weight(0.0, 0.0, 1.0), 0.0);
  double before = 2.0;
  for (double d = 0.0; d < 2.0; d += 0.05) {
    const double w = brush_weight(d, 2.0, 1.0);
    EXPECT_LE(w, before);
    before = w;
  }
}

TEST(CovarianceBrush, SharpenHalvesTheExtentAlongTheNormalAndKeepsTheRest) {
  const Mat3 sigma = Vec3(4.0, 1.0, 2.0).asDiagonal();
  const Mat3 dabbed = brushed_covariance(sigma, Vec3::UnitZ(), 1.0, BrushKind::sharpen);
  const Mat3 expected = Vec3(4.0, 1.0, 2.0 * kSharpenKeeps * kSharpenKeeps).asDiagonal();
  EXPECT_LT((dabbed - expected).norm(), 1e-15);
  EXPECT_EQ(brushed_covariance(sigma, Vec3::UnitZ(), 0.0, BrushKind::sharpen), sigma);
  // Along a tilted normal: its variance falls by the same factor, the directions across it keep theirs.
  const Vec3 n = Vec3(1.0, 2.0, 2.0) / 3.0;
  const Mat3 round = Mat3::Identity();
  const Mat3 tilted = brushed_covariance(round, n, 1.0, BrushKind::sharpen);
  EXPECT_NEAR(n.dot(tilted * n), kSharpenKeeps * kSharpenKeeps, 1e-15);
  const Vec3 across = n.cross(Vec3::UnitX()).normalized();
  EXPECT_NEAR(across.dot(tilted * across), 1.0, 1e-15);
}

TEST(CovarianceBrush, DabsNeverFlattenPastTheFloor) {
  Mat3 sigma = Mat3::Identity();
  for (int k = 0; k < 200; ++k) sigma = brushed_covariance(sigma, Vec3::UnitY(), 1.0, BrushKind::sharpen);
  const Eigen::SelfAdjointEigenSolver<Mat3> eigen(sigma);
  EXPECT_GE(eigen.eigenvalues().minCoeff(),
            kFlattestStretch * kFlattestStretch * eigen.eigenvalues().maxCoeff() * 0.999);
  EXPECT_GT(eigen.eigenvalues().minCoeff(), 0.0);
  EXPECT_NEAR(sigma(0, 0), 1.0, 1e-12);
}

TEST(CovarianceBrush, SoftenMakesItRoundKeepingTheVolume) {
  const Mat3 sigma = Vec3(4.0, 1.0, 0.25).asDiagonal();  // σs 2, 1, 0.5: geometric mean 1
  EXPECT_LT((brushed_covariance(sigma, Vec3::UnitZ(), 1.0, BrushKind::soften) - Mat3::Identity()).norm(), 1e-12);
  const Mat3 half = brushed_covariance(sigma, Vec3::UnitZ(), 0.5, BrushKind::soften);
  EXPECT_LT((half - 0.5 * (sigma + Mat3::Identity())).norm(), 1e-12);
}

TEST(CovarianceBrush, ADabReachesTheVerticesWithinItsRadius) {
  const CovarianceMesh cube = make_sample("cube");
  const std::vector<BrushedVertex> one = brush_reach(cube, cube.mean(6), 1.0, 0.5);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].vertex, 6);
  EXPECT_DOUBLE_EQ(one[0].weight, 0.5);
  // Above the top face's centre: its four corners, equally.
  Vec3 top = Vec3::Zero();
  for (size_t v = 0; v < cube.n_vertices(); ++v) top.y() = std::max(top.y(), cube.mean(v).y());
  const std::vector<BrushedVertex> face = brush_reach(cube, top, 2.0, 1.0);
  ASSERT_EQ(face.size(), 4u);
  for (const BrushedVertex& r : face) {
    EXPECT_EQ(cube.mean(size_t(r.vertex)).y(), top.y());
    EXPECT_DOUBLE_EQ(r.weight, face[0].weight);
  }
}

}  // namespace
}  // namespace gps
