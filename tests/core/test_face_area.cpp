// Whether a face is thinner than a tolerance (core/mesh/face_area.h), as the repair drops faces and the
// modelling operations refuse them: a triangle and a strip by their height, whatever their position.
#include "core/mesh/face_area.h"

#include <gtest/gtest.h>

#include <vector>

namespace gps {
namespace {

bool thin(const std::vector<Vec3>& corners, double tolerance) {
  std::vector<int> order(corners.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = int(k);
  return without_area(
      std::span<const int>(order), [&](int k) { return corners[size_t(k)]; }, tolerance);
}

TEST(FaceArea, ATriangleOrAStripIsThinWhereItsHeightIsUnderTheTolerance) {
  for (const double height : {0.9, 1.1}) {
    EXPECT_EQ(thin({{0, 0, 0}, {10, 0, 0}, {3, height, 0}}, 1.0), height < 1) << height;
    EXPECT_EQ(thin({{0, 0, 0}, {10, 0, 0}, {10, height, 0}, {0, height, 0}}, 1.0), height < 1) << height;
  }
  EXPECT_TRUE(thin({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}}, 1e-12));  // corners in a line
  EXPECT_TRUE(thin({{1, 2, 3}, {1, 2, 3}, {1, 2, 3}}, 1e-12));             // corners together
  // Folded onto itself: a bow tie whose halves cancel, its corners well off any line.
  EXPECT_TRUE(thin({{0, 0, 0}, {2, 2, 0}, {2, 0, 0}, {0, 2, 0}}, 1e-3));
}

// Far from the origin the corners' products cancel in Newell's sum: measured from a corner instead.
TEST(FaceArea, DoesNotChangeWhereTheFaceLies) {
  for (const double offset : {0.0, 1e7, -3e9, 1e12}) {
    const Vec3 o(offset, offset, offset);
    EXPECT_FALSE(thin({o + Vec3(0, 0, 0), o + Vec3(2, 0, 0), o + Vec3(2, 0.001, 0), o + Vec3(0, 0.001, 0)}, 7e-6))
        << offset;
    EXPECT_TRUE(thin({o + Vec3(0, 0, 0), o + Vec3(2, 0, 0), o + Vec3(2, 1e-6, 0), o + Vec3(0, 1e-6, 0)}, 7e-6))
        << offset;
  }
}

}  // namespace
}  // namespace gps
