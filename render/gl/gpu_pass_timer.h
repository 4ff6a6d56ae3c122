#pragma once
// GPU time of named, sequential (never nested) passes, from GL_TIME_ELAPSED queries read back
// without stalling: a small ring of queries per pass, results taken once available, so a caller
// timing every frame sees figures a frame or two old. Compute passes on a software renderer are
// timed by the CPU's clock instead: there each dispatch runs to its end before it returns, while a
// query is binned into every tile of the frame last drawn, whose walk it would time (and add).
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "render/gl/query_ring.h"

namespace gps {

class GpuPassTimer {
public:
  /// Needs a current GL context (the one the passes run in).
  GpuPassTimer();
  ~GpuPassTimer();
  GpuPassTimer(const GpuPassTimer&) = delete;
  GpuPassTimer& operator=(const GpuPassTimer&) = delete;

  /// What a pass runs: draws, or compute dispatches (and the buffer writes between them).
  enum class Work { draws, dispatches };
  /// Starts timing `pass`; throws gps::Error while another pass is open. A pass whose queries all
  /// still await their results is not timed this time.
  void begin(const std::string& pass, Work work = Work::draws);
  /// Ends the open pass.
  void end();
  /// Latest completed GPU time of each pass in milliseconds, in the order passes were first seen;
  /// a pass with no completed measurement yet is left out.
  std::vector<std::pair<std::string, double>> latest();

private:
  struct Pass {
    std::string name;
    std::unique_ptr<QueryRing> queries;  // null for a pass timed by the clock
    std::optional<double> clock_ms;      // the latest such time
  };
  std::vector<Pass> passes_;
  int open_ = -1;  // index into passes_ of the open pass
  bool software_ = false;
  std::chrono::steady_clock::time_point clock_start_;
};

/// Times its own lifetime as one pass of `timer`; does nothing when `timer` is null.
class GpuPassScope {
public:
  GpuPassScope(GpuPassTimer* timer, const std::string& pass, GpuPassTimer::Work work = GpuPassTimer::Work::draws);
  ~GpuPassScope();
  GpuPassScope(const GpuPassScope&) = delete;
  GpuPassScope& operator=(const GpuPassScope&) = delete;

private:
  GpuPassTimer* timer_;
};

}  // namespace gps
