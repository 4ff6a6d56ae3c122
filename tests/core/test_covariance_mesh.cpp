// Building a covariance mesh from arrays: what it refuses, named by vertex or face.
#include "core/mesh/covariance_mesh.h"

#include <gtest/gtest.h>

#include <limits>

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

}  // namespace
}  // namespace gps
