// The target points' colour ramp (render/overlays/distance_ramp.h): a distance mapped to [0, 1] by
// the ramp's end, and the ramp from blue (on the surface) through yellow to red (at the end and
// beyond), never through the surface's grey.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "render/overlays/distance_ramp.h"

namespace gps {
namespace {

float saturation(const glm::vec3& c) {
  const float hi = std::max({c.r, c.g, c.b}), lo = std::min({c.r, c.g, c.b});
  return hi > 0.0f ? (hi - lo) / hi : 0.0f;
}

TEST(DistanceRamp, DistanceOverTheEndClamped) {
  EXPECT_FLOAT_EQ(ramp_position(0.0, 2.0), 0.0f);
  EXPECT_FLOAT_EQ(ramp_position(0.5, 2.0), 0.25f);
  EXPECT_FLOAT_EQ(ramp_position(2.0, 2.0), 1.0f);
  EXPECT_FLOAT_EQ(ramp_position(7.0, 2.0), 1.0f);  // beyond the end: red, as at it
  EXPECT_FLOAT_EQ(ramp_position(-1.0, 2.0), 0.0f);
}

TEST(DistanceRamp, NoEndOrNoDistanceIsTheStart) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  EXPECT_FLOAT_EQ(ramp_position(nan, 1.0), 0.0f);
  EXPECT_FLOAT_EQ(ramp_position(1.0, 0.0), 0.0f);
  EXPECT_FLOAT_EQ(ramp_position(1.0, -3.0), 0.0f);
  EXPECT_FLOAT_EQ(ramp_position(1.0, nan), 0.0f);
  EXPECT_FLOAT_EQ(ramp_position(1.0, inf), 0.0f);
}

TEST(DistanceRamp, BlueYellowRed) {
  const glm::vec3 start = ramp_colour(0.0f), middle = ramp_colour(0.55f), end = ramp_colour(1.0f);
  EXPECT_GT(start.b, 0.9f);  // blue
  EXPECT_LT(start.r, 0.3f);
  EXPECT_GT(middle.r, 0.9f);  // yellow
  EXPECT_GT(middle.g, 0.8f);
  EXPECT_LT(middle.b, 0.3f);
  EXPECT_GT(end.r, 0.8f);  // red
  EXPECT_LT(end.g, 0.2f);
  EXPECT_LT(end.b, 0.2f);
  EXPECT_EQ(ramp_colour(-1.0f), start);  // clamped
  EXPECT_EQ(ramp_colour(2.0f), end);
  EXPECT_EQ(distance_colour(3.0, 2.0), end);
  EXPECT_EQ(distance_colour(0.0, 2.0), start);
}

TEST(DistanceRamp, ContinuousAndNeverGrey) {
  glm::vec3 previous = ramp_colour(0.0f);
  for (int i = 1; i <= 1000; ++i) {
    const glm::vec3 c = ramp_colour(float(i) / 1000.0f);
    EXPECT_LT(glm::length(c - previous), 0.02f) << "a jump at " << i;
    EXPECT_GT(saturation(c), 0.35f) << "a greyish colour at " << i;
    previous = c;
  }
}

TEST(DistanceRamp, RedderWithDistanceFromYellowOn) {
  // Past the middle the green falls: a farther point is never less red than a nearer one.
  for (int i = 56; i < 100; ++i) EXPECT_GE(ramp_colour(i / 100.0f).g, ramp_colour((i + 1) / 100.0f).g) << i;
  // Before it the blue falls.
  for (int i = 0; i < 55; ++i) EXPECT_GE(ramp_colour(i / 100.0f).b, ramp_colour((i + 1) / 100.0f).b) << i;
}

}  // namespace
}  // namespace gps
