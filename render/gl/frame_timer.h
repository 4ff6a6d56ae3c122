#pragma once
// GPU time of a piece of GL work (GL_TIME_ELAPSED queries), and the wall time until it finished.
#include <functional>

namespace gps {

struct FrameTiming {
  double gpu_ms = 0;   // median GPU time
  double wall_ms = 0;  // median wall time including glFinish
};

/// Runs `work` `repeats` times (after one warm-up) and reports the medians.
FrameTiming time_gl_work(const std::function<void()>& work, int repeats);

}  // namespace gps
