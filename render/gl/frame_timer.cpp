#include "render/gl/frame_timer.h"

#include "core/support/median.h"
#include "render/gl/gl_object.h"

#include <glad/gl.h>

#include <algorithm>
#include <chrono>
#include <vector>

namespace gps {

std::vector<FrameTiming> time_gl_work_interleaved(const std::vector<std::function<void()>>& works, int min_rounds,
                                                  double budget_seconds) {
  using Clock = std::chrono::steady_clock;
  for (const auto& work : works)
    for (int warm_up = 0; warm_up < 2; ++warm_up) {
      work();
      glFinish();
    }
  std::vector<std::vector<double>> gpu(works.size()), wall(works.size());
  const GlQuery query(GL_TIME_ELAPSED);
  const auto begin = Clock::now();
  for (int round = 0; round < std::max(1, min_rounds) ||
                      (round < 200 && std::chrono::duration<double>(Clock::now() - begin).count() < budget_seconds);
       ++round)
    for (size_t i = 0; i < works.size(); ++i) {
      const auto start = Clock::now();
      glBeginQuery(GL_TIME_ELAPSED, query);
      works[i]();
      glEndQuery(GL_TIME_ELAPSED);
      glFinish();
      wall[i].push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
      GLuint64 ns = 0;
      glGetQueryObjectui64v(query, GL_QUERY_RESULT, &ns);
      gpu[i].push_back(double(ns) * 1e-6);
    }
  std::vector<FrameTiming> timings;
  for (size_t i = 0; i < works.size(); ++i) timings.push_back({median(gpu[i]), median(wall[i])});
  return timings;
}

FrameTiming time_gl_work(const std::function<void()>& work, int repeats) {
  return time_gl_work_interleaved({work}, repeats, 0.0)[0];
}

}  // namespace gps
