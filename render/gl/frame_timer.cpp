#include "render/gl/frame_timer.h"

#include "core/support/median.h"

#include <glad/gl.h>

#include <algorithm>
#include <chrono>
#include <vector>

namespace gps {

FrameTiming time_gl_work(const std::function<void()>& work, int repeats) {
  work();
  glFinish();
  std::vector<double> gpu, wall;
  unsigned query = 0;
  glCreateQueries(GL_TIME_ELAPSED, 1, &query);
  for (int i = 0; i < std::max(1, repeats); ++i) {
    const auto start = std::chrono::steady_clock::now();
    glBeginQuery(GL_TIME_ELAPSED, query);
    work();
    glEndQuery(GL_TIME_ELAPSED);
    glFinish();
    wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    GLuint64 ns = 0;
    glGetQueryObjectui64v(query, GL_QUERY_RESULT, &ns);
    gpu.push_back(double(ns) * 1e-6);
  }
  glDeleteQueries(1, &query);
  return {median(gpu), median(wall)};
}

}  // namespace gps
