#pragma once
// GPU time of a piece of GL work (GL_TIME_ELAPSED queries), and the wall time until it finished.
#include <functional>
#include <vector>

namespace gps {

struct FrameTiming {
  double gpu_ms = 0;   // median GPU time
  double wall_ms = 0;  // median wall time including glFinish
};

/// Runs `work` `repeats` times (after two warm-up runs) and reports the medians.
FrameTiming time_gl_work(const std::function<void()>& work, int repeats);

/// The steady-state medians of several pieces of work measured side by side, as the Google Benchmarks
/// measure frames: each warmed up twice, then run in turn, round after round, at least `min_rounds`
/// times and until `budget_seconds` have passed (at most 200 rounds), so that drift of the machine
/// (clocks, caches, other load) falls on all of them alike.
std::vector<FrameTiming> time_gl_work_interleaved(const std::vector<std::function<void()>>& works, int min_rounds,
                                                  double budget_seconds);

}  // namespace gps
