// Dihedral angles and creases by angle (core/mesh/crease_by_angle.h), against angles known in closed
// form: a cube's 90°, a regular tetrahedron's 180° − arccos(1/3), a flat grid's 0.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/mesh/crease_by_angle.h"
#include "core/modelling/bevel.h"
#include "core/modelling/samples.h"

namespace gps {
namespace {

CovarianceMesh tetrahedron() {
  const std::vector<Vec3> p = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  return make_covariance_mesh(p, std::vector<Mat3>(4, Mat3::Identity()), {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}});
}

TEST(CreaseByAngle, DihedralAnglesOfKnownSolids) {
  for (const double angle : dihedral_angles(make_sample("cube"))) EXPECT_NEAR(angle, 90.0, 1e-12);
  const double tetra = 180.0 - std::acos(1.0 / 3.0) * 180.0 / M_PI;
  for (const double angle : dihedral_angles(tetrahedron())) EXPECT_NEAR(angle, tetra, 1e-12);
  // A flat grid: interior edges at 0, boundary edges −1.
  std::vector<Vec3> points;
  std::vector<std::vector<int>> quads;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) points.emplace_back(i, j, 0);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) quads.push_back({4 * j + i, 4 * j + i + 1, 4 * j + i + 5, 4 * j + i + 4});
  const CovarianceMesh grid = make_covariance_mesh(points, std::vector<Mat3>(16, Mat3::Identity()), quads);
  int boundary = 0;
  for (size_t e = 0; e < grid.n_edges(); ++e) {
    const double angle = dihedral_angles(grid)[e];
    if (grid.is_boundary_edge(e)) {
      EXPECT_EQ(angle, -1.0);
      ++boundary;
    } else {
      EXPECT_NEAR(angle, 0.0, 1e-12);
    }
  }
  EXPECT_GT(boundary, 0);
}

TEST(CreaseByAngle, MarksEdgesAboveTheThresholdAndKeepsSharperOnes) {
  CovarianceMesh cube = make_sample("cube");
  EXPECT_EQ(crease_by_angle(cube, 95.0), 0);
  EXPECT_TRUE(cube.sharpness.empty());
  cube.sharpness.set_crease(4, 5, 12.0);  // sharper than kInfiniteSharpness: kept
  cube.sharpness.set_crease(0, 1, 2.5);   // raised to infinite
  EXPECT_EQ(crease_by_angle(cube, 30.0), 12);
  ASSERT_EQ(cube.sharpness.creases.size(), 12u);
  for (const EdgeCrease& c : cube.sharpness.creases)
    EXPECT_EQ(c.sharpness, c.a == 4 && c.b == 5 ? 12.0 : kInfiniteSharpness) << c.a << "-" << c.b;
  EXPECT_TRUE(
      std::is_sorted(cube.sharpness.creases.begin(), cube.sharpness.creases.end(),
                     [](const EdgeCrease& x, const EdgeCrease& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; }));
  CovarianceMesh tetra = tetrahedron();
  EXPECT_EQ(crease_by_angle(tetra, 109.0), 6);
  tetra.sharpness = {};
  EXPECT_EQ(crease_by_angle(tetra, 110.0), 0);
}

// The edges over an angle: all 12 of the cube's over 30°, none over 90°; the tetrahedron's 6 just
// below its dihedral angle, none just above.
TEST(CreaseByAngle, EdgesSharperThanAnAngle) {
  const CovarianceMesh cube = make_sample("cube");
  const auto sharp = edges_sharper_than(cube, 30.0);
  ASSERT_EQ(sharp.size(), 12u);  // every cube edge, each once, ascending
  EXPECT_TRUE(std::is_sorted(sharp.begin(), sharp.end()));
  for (const auto& [a, b] : sharp) {
    EXPECT_LT(a, b);
    EXPECT_GE(cube.find_edge(a, b), 0);
  }
  EXPECT_TRUE(edges_sharper_than(cube, 90.0 + 1e-9).empty());
  const double tetra = 180.0 - std::acos(1.0 / 3.0) * 180.0 / M_PI;
  EXPECT_EQ(edges_sharper_than(tetrahedron(), tetra - 1e-9).size(), 6u);
  EXPECT_TRUE(edges_sharper_than(tetrahedron(), tetra + 1e-9).empty());
  // A cube's edge bevelled in 3 segments: its band's faces turn by 30° at each of their two edges
  // between, alike by symmetry, which rounding put on either side of 30° (one edge was sharp, the
  // other not). Both are at the threshold now, not sharper.
  const CovarianceMesh bevelled = bevel_edges(cube, {{0, 1}}, BevelOptions{.width = 0.2, .segments = 3}).mesh;
  const std::vector<double> angles = dihedral_angles(bevelled);
  int at_threshold = 0;
  for (const double a : angles) at_threshold += std::abs(a - 30.0) < 1e-9;
  EXPECT_EQ(at_threshold, 2);
  EXPECT_EQ(edges_sharper_than(bevelled, 30.0).size(), 17u);  // the 11 unbevelled edges and the band's 6 rims
  EXPECT_EQ(edges_sharper_than(bevelled, 30.0 - 1e-9).size(), 19u);
}

}  // namespace
}  // namespace gps
