#pragma once
// The statistics overlay: frame rate, GPU time per pass, what the tessellator made, and the time
// from an edit to the frame that showed it; it moves to another corner rather than cover the gizmo.
#include <chrono>
#include <deque>
#include <glm/glm.hpp>
#include <string>
#include <utility>
#include <vector>

#include "core/support/median.h"
#include "render/pipeline/surface_renderer.h"

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

/// A rectangle in window pixels.
struct ScreenBox {
  glm::vec2 min{0.0f}, max{0.0f};
  bool overlaps(const ScreenBox& o) const {
    return min.x < o.max.x && o.min.x < max.x && min.y < o.max.y && o.min.y < max.y;
  }
};

/// Where the overlay's top-left corner goes: the first corner of the `free` part of the window (top
/// left, bottom left, top right, bottom right; 10 pixels in) where a box of `size` covers none of
/// `keep_clear` (the gizmo); the top left when every corner would.
glm::vec2 statistics_position(const ScreenBox& free, glm::vec2 size, const std::vector<ScreenBox>& keep_clear);

/// Draws the overlay at statistics_position() (its size as last drawn). It takes no input: a click
/// on it reaches the view below.
void draw_statistics_overlay(const FrameClock& clock, const std::vector<std::pair<std::string, double>>& gpu_passes,
                             const DrawStatistics& draw, const ScreenBox& free,
                             const std::vector<ScreenBox>& keep_clear, bool* open);

}  // namespace gps
