// The statistics overlay keeps clear of the gizmo: it takes the first free corner.
#include "ui/panels/statistics_overlay.h"

#include <gtest/gtest.h>

namespace gps {
namespace {

const ScreenBox kFree{{0.0f, 20.0f}, {700.0f, 670.0f}};
const glm::vec2 kSize(280.0f, 170.0f);

TEST(StatisticsOverlay, TopLeftWhenNothingIsInTheWay) {
  EXPECT_EQ(statistics_position(kFree, kSize, {}), glm::vec2(10.0f, 30.0f));
  EXPECT_EQ(statistics_position(kFree, kSize, {{{400.0f, 300.0f}, {460.0f, 360.0f}}}), glm::vec2(10.0f, 30.0f));
}

TEST(StatisticsOverlay, MovesToTheNextFreeCornerOfTheFreeRegion) {
  const ScreenBox top_left_gizmo{{60.0f, 80.0f}, {140.0f, 150.0f}};
  const glm::vec2 at = statistics_position(kFree, kSize, {top_left_gizmo});
  EXPECT_EQ(at, glm::vec2(10.0f, 670.0f - 10.0f - 170.0f)) << "bottom left";
  EXPECT_FALSE((ScreenBox{at, at + kSize}.overlaps(top_left_gizmo)));
  // A tall gizmo down the left side: the top right of the free region (left of the panels).
  const ScreenBox left_column{{20.0f, 40.0f}, {120.0f, 640.0f}};
  EXPECT_EQ(statistics_position(kFree, kSize, {left_column}), glm::vec2(700.0f - 10.0f - 280.0f, 30.0f));
}

TEST(StatisticsOverlay, TopLeftWhenEveryCornerIsCovered) {
  EXPECT_EQ(statistics_position(kFree, kSize, {{{0.0f, 0.0f}, {700.0f, 700.0f}}}), glm::vec2(10.0f, 30.0f));
}

TEST(StatisticsOverlay, BoxesThatOnlyTouchDoNotOverlap) {
  const ScreenBox a{{0, 0}, {10, 10}}, b{{10, 0}, {20, 10}}, c{{5, 5}, {15, 15}};
  EXPECT_FALSE(a.overlaps(b));
  EXPECT_TRUE(a.overlaps(c));
  EXPECT_TRUE(c.overlaps(b));
}

}  // namespace
}  // namespace gps
