#pragma once
// The statistics overlay: frame rate, GPU time per pass, what the tessellator made, and the time
// from an edit to the frame that showed it.
#include <chrono>
#include <deque>
#include <string>
#include <utility>
#include <vector>

#include "core/median.h"
#include "render/surface_renderer.h"

namespace gps {

/// Wall-clock figures over the last frames (medians of a sliding window).
class FrameClock {
public:
  using Clock = std::chrono::steady_clock;
  /// Call once per frame, after the frame was handed to the window.
  void frame_done();
  /// Call when the frame that shows an edit made at `edit_time` has finished on the GPU.
  void edit_shown(Clock::time_point edit_time);
  double median_frame_ms() const { return median({frames_.begin(), frames_.end()}); }
  double median_edit_ms() const { return median({edits_.begin(), edits_.end()}); }
  double last_edit_ms() const { return edits_.empty() ? 0.0 : edits_.back(); }
  size_t edit_count() const { return edit_total_; }

private:
  Clock::time_point last_frame_{};
  std::deque<double> frames_, edits_;
  size_t edit_total_ = 0;
};

/// Draws the overlay in the viewport's top-left corner.
void draw_statistics_overlay(const FrameClock& clock, const std::vector<std::pair<std::string, double>>& gpu_passes,
                             const DrawStatistics& draw, bool* open);

}  // namespace gps
