// Building a covariance mesh from arrays: what it refuses, named by vertex or face.
#include "core/mesh/covariance_mesh.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <random>

#include "core/support/error.h"

namespace gps {
namespace {

std::string error_building(const std::vector<Vec3>& positions) {
  try {
    make_covariance_mesh(positions, std::vector<Mat3>(positions.size(), Mat3::Identity()), {{0, 1, 2}, {0, 2, 3}},
                         "test");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// Copies of a mesh share its faces and connectivity; a mesh moved from is a mesh of nothing, which
// every query still answers.
TEST(CovarianceMesh, CopiesShareTheShapeAndAMovedFromMeshIsEmpty) {
  CovarianceMesh mesh = make_covariance_mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}},
                                             std::vector<Mat3>(4, Mat3::Identity()), {{0, 1, 2, 3}});
  const CovarianceMesh copy = mesh;
  EXPECT_EQ(copy.shape().get(), mesh.shape().get());
  EXPECT_EQ(copy.n_edges(), 4u);
  CovarianceMesh taken = std::move(mesh);
  EXPECT_EQ(taken.shape().get(), copy.shape().get());
  EXPECT_EQ(taken.n_faces(), 1u);
  EXPECT_EQ(mesh.n_vertices(), 0u);
  EXPECT_EQ(mesh.n_faces(), 0u);
  EXPECT_EQ(mesh.n_edges(), 0u);
  EXPECT_EQ(mesh.shape().get(), empty_mesh_shape().get());
  mesh = taken;
  EXPECT_EQ(mesh.n_faces(), 1u);
}

// A position that is NaN or infinite is named as such, by its vertex, not as a degenerate face.
TEST(CovarianceMesh, PositionsThatAreNotFiniteAreNamed) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const std::vector<Vec3> square = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  EXPECT_EQ(error_building(square), "");
  for (const double bad : {nan, inf, -inf}) {
    std::vector<Vec3> positions = square;
    positions[2] = Vec3(1, bad, 0);
    EXPECT_EQ(error_building(positions), "test: vertex 2 has a position that is not finite") << bad;
  }
}

// covariance_problem accepts exactly the symmetric positive definite matrices whose eigenvalues lie in
// [1e-100, 1e100] (a Cholesky factorisation and an eigen-solve, computed here independently), also
// where it decides without an eigen-solve: diagonally dominant matrices at every scale, near the
// ends of the range, rotated needles and matrices that are nearly singular or indefinite.
TEST(CovarianceMesh, CovarianceProblemAcceptsExactlyTheRange) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int accepted = 0, refused = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double scale = std::pow(10.0, 250.0 * unit(random));  // 1e-250 .. 1e250
    Mat3 c;
    if (trial % 3 == 0) {  // diagonally dominant, or nearly so
      Mat3 off = Mat3::Zero();
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < i; ++j) off(i, j) = off(j, i) = 0.6 * unit(random);
      c = scale * (Mat3::Identity() * (1.0 + unit(random) * 0.2) + off);
    } else {  // a rotated ellipsoid, axes up to 1e12 apart, sometimes with an axis of sign flipped
      const Mat3 q =
          Eigen::Quaterniond(Eigen::Vector4d(unit(random), unit(random), unit(random), unit(random)).normalized())
              .toRotationMatrix();
      Vec3 axes(1.0, std::pow(10.0, -6.0 * (unit(random) + 1.0)), std::pow(10.0, 6.0 * unit(random)));
      if (trial % 7 == 1) axes(1) = -axes(1);
      c = scale * q * axes.asDiagonal() * q.transpose();
      c = 0.5 * (c + c.transpose()).eval();
    }
    const Vec3 eigenvalues = Eigen::SelfAdjointEigenSolver<Mat3>(c, Eigen::EigenvaluesOnly).eigenvalues();
    const bool expected = is_spd(c) && eigenvalues(0) > 0 && eigenvalues(0) >= kMinCovarianceEigenvalue &&
                          eigenvalues(2) <= kMaxCovarianceEigenvalue;
    EXPECT_EQ(covariance_problem(c).empty(), expected) << "trial " << trial << "\n" << c;
    (expected ? accepted : refused) += 1;
  }
  EXPECT_GT(accepted, 5000);
  EXPECT_GT(refused, 2000);
}

}  // namespace
}  // namespace gps
