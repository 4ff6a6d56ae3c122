#include "core/modelling/face_pieces.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

namespace gps {
namespace {

double twice_area(const std::vector<int>& t, const std::vector<Vec3>& p) {
  return (p[size_t(t[1])] - p[size_t(t[0])]).cross(p[size_t(t[2])] - p[size_t(t[0])]).z();
}

TEST(FacePieces, CornersOnAStraightSideAreFannedInSoThatEveryTriangleHasArea) {
  // A triangle (0, 1, 2) with corners 3, 4, 5 on its side from 2 back to 0, as a bevel's straight
  // profile leaves them: ear clipping alone can cut (3, 4, 5) off, in line.
  const std::vector<Vec3> p = {{0, 3, 0}, {-1, 0, 0}, {1, 0, 0}, {0.75, 0.75, 0}, {0.5, 1.5, 0}, {0.25, 2.25, 0}};
  for (int turn = 0; turn < 6; ++turn) {
    std::vector<int> piece = {0, 1, 2, 3, 4, 5};
    std::rotate(piece.begin(), piece.begin() + turn, piece.end());
    std::vector<std::vector<int>> pieces{piece};
    triangulate_pieces(pieces, p, Vec3::UnitZ());
    ASSERT_EQ(pieces.size(), 4u) << turn;
    double total = 0;
    for (const auto& t : pieces) {
      EXPECT_GT(twice_area(t, p), 1e-3) << turn << ": " << t[0] << " " << t[1] << " " << t[2];
      total += twice_area(t, p);
    }
    EXPECT_NEAR(total, 6, 1e-12) << turn;  // twice the area of (0, 1, 2)
  }
  // A quad with no straight corner keeps its shorter diagonal.
  const std::vector<Vec3> q = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}};
  std::vector<std::vector<int>> pieces{{0, 1, 2, 3}};
  triangulate_pieces(pieces, q, Vec3::UnitZ());
  ASSERT_EQ(pieces.size(), 2u);
  for (const auto& t : pieces) EXPECT_GT(twice_area(t, q), 0);
}

}  // namespace
}  // namespace gps
