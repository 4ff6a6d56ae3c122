// The Merge menu's By distance: its field is a fraction of the bounding-box diagonal, range-checked.
#include "ui/editing/merge_distance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/mesh/covariance_mesh.h"
#include "tests/support/error_of.h"

namespace gps {
namespace {

// The unit square as a pentagon whose vertex 4 lies 0.01 from vertex 0 along the bottom edge: the
// diagonal is √2, so a fraction f welds them where f·√2 > 0.01.
CovarianceMesh square_with_close_pair() {
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.01, 0, 0}};
  return make_covariance_mesh(p, std::vector<Mat3>(p.size(), Mat3::Identity()), {{0, 4, 1, 2, 3}});
}

TEST(MergeDistance, TheFractionIsOfTheBoundingBoxDiagonal) {
  const CovarianceMesh square = square_with_close_pair();
  const Modelled welded = merge_by_distance(square, {}, 0.01 / std::sqrt(2.0) * 1.01);
  EXPECT_EQ(welded.mesh.n_vertices(), 4u);
  EXPECT_EQ(welded.mesh.n_faces(), 1u);
  EXPECT_EQ(welded.mesh.face_size(0), 4);
  const Modelled apart = merge_by_distance(square, {}, 0.01 / std::sqrt(2.0) * 0.99);
  EXPECT_EQ(apart.mesh.n_vertices(), 5u);
  EXPECT_EQ(merge_by_distance(square, {}, kDefaultMergeDistance).mesh.n_vertices(), 5u);
}

TEST(MergeDistance, AFractionOutsideZeroToOneIsRefusedByValue) {
  const CovarianceMesh square = square_with_close_pair();
  for (const double fraction :
       {0.0, -0.5, 1.5, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    const std::string message = test::error_of([&] { merge_by_distance(square, {}, fraction); });
    EXPECT_EQ(message.rfind("the merge distance must be more than 0 and at most 1", 0), 0u) << message;
  }
  EXPECT_NE(test::error_of([&] { merge_by_distance(square, {}, 1.5); }).find("got 1.5"), std::string::npos);
  // 1 passes the range check: the whole square within it, the weld itself refuses a faceless result.
  EXPECT_EQ(test::error_of([&] { merge_by_distance(square, {}, 1.0); }), "the result would have no faces");
}

}  // namespace
}  // namespace gps
