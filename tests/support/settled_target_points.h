#pragma once
// A target points' layer brought to rest, as the editor's frames bring it: updated a frame at a time
// until its distances are of the surface shown.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "ui/display/target_points_layer.h"

namespace gps::test {

/// Updates `layer` a frame at a time (the clock `now` moving past the settle time) until its
/// distances are of the surface as it is, or 20 s went by (a failure).
inline void settle(TargetPointsLayer& layer, const ShownSurface& shown, const CovarianceMesh& document,
                   TargetPointsView& view, TargetPointsLayer::Clock::time_point& now) {
  for (int frame = 0; frame < 2000; ++frame) {
    layer.update(shown, document, PlanOptions{}, view, now);
    if (view.count > 0 && !view.measuring) return;
    now += std::chrono::milliseconds(200);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  FAIL() << "the target points were not measured";
}

}  // namespace gps::test
