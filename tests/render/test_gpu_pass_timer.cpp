// GPU pass timing on OSMesa: every pass reported, in first-seen order, with finite times; a pass of
// compute dispatches timed for the dispatches it ran.
#include "render/gl/gpu_pass_timer.h"

#include <glad/gl.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "core/support/error.h"
#include "render/gl/render_target.h"
#include "render/gl/shader_program.h"
#include "tests/support/gl_fixture.h"

namespace gps {
namespace {

using GpuPassTimerTest = test::GlTest;

void clear(const RenderTarget& target, float grey) {
  target.bind();
  const float colour[4] = {grey, grey, grey, 1.0f};
  glClearBufferfv(GL_COLOR, 0, colour);
}

TEST_F(GpuPassTimerTest, ReportsEveryPassInFirstSeenOrder) {
  RenderTarget target(256, 256);
  GpuPassTimer timer;
  for (int frame = 0; frame < 3; ++frame) {
    timer.begin("zeta");
    clear(target, 0.25f);
    timer.end();
    timer.begin("alpha");
    clear(target, 0.5f);
    timer.end();
    if (frame > 0) {  // a pass seen late comes last
      timer.begin("middle");
      clear(target, 0.75f);
      timer.end();
    }
  }
  glFinish();
  const auto times = timer.latest();
  ASSERT_EQ(times.size(), 3u);
  EXPECT_EQ(times[0].first, "zeta");
  EXPECT_EQ(times[1].first, "alpha");
  EXPECT_EQ(times[2].first, "middle");
  for (const auto& [name, ms] : times) {
    EXPECT_TRUE(std::isfinite(ms)) << name;
    EXPECT_GE(ms, 0.0) << name;
  }
  check_gl_errors("timing passes");
}

// More frames than a pass's ring of queries, none read in between: passes whose queries are all
// in flight go untimed instead of waiting, and results keep coming once the GPU catches up.
TEST_F(GpuPassTimerTest, KeepsReportingAfterMoreFramesThanItsRing) {
  RenderTarget target(64, 64);
  GpuPassTimer timer;
  for (int frame = 0; frame < 50; ++frame) {
    const GpuPassScope pass(&timer, "clear");
    clear(target, float(frame % 2));
  }
  glFinish();
  auto times = timer.latest();
  ASSERT_EQ(times.size(), 1u);
  EXPECT_EQ(times[0].first, "clear");
  EXPECT_TRUE(std::isfinite(times[0].second));
  {
    const GpuPassScope pass(&timer, "later");
    clear(target, 0.5f);
  }
  glFinish();
  times = timer.latest();
  ASSERT_EQ(times.size(), 2u);
  EXPECT_EQ(times[1].first, "later");
  check_gl_errors("timing many frames");
}

// A pass of dispatches that keep the GPU busy for a while after a frame was drawn: the time it reports
// is most of the time the dispatches took to finish (on llvmpipe, where a query times the walk of
// the drawn frame's tiles instead, it would be a small part of it), in order with the drawn passes.
TEST_F(GpuPassTimerTest, APassOfDispatchesReportsTheirTime) {
  const ShaderProgram busy("busy", {{GL_COMPUTE_SHADER, {R"(
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Sums { float sums[]; };
uniform int rounds;
void main() {
  float x = float(gl_GlobalInvocationID.x);
  for (int i = 0; i < rounds; ++i) x = fract(x * 1.0001 + 0.37);
  sums[gl_GlobalInvocationID.x] = x;
}
)"}}});
  constexpr int kGroups = 256;
  const GlBuffer sums;
  glNamedBufferData(sums, kGroups * 64 * sizeof(float), nullptr, GL_DYNAMIC_DRAW);
  RenderTarget target(512, 512);
  GpuPassTimer timer;
  using Clock = std::chrono::steady_clock;
  double wall_ms = 0.0;
  for (int frame = 0; frame < 2; ++frame) {
    {
      const GpuPassScope pass(&timer, "frame");
      clear(target, 0.5f);
    }
    glFinish();
    const Clock::time_point start = Clock::now();
    {
      const GpuPassScope pass(&timer, "dispatches", GpuPassTimer::Work::dispatches);
      busy.use();
      busy.set("rounds", 20000);
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, sums);
      glDispatchCompute(kGroups, 1, 1);
    }
    glFinish();
    wall_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  }
  const auto times = timer.latest();
  ASSERT_EQ(times.size(), 2u);
  EXPECT_EQ(times[0].first, "frame");
  EXPECT_EQ(times[1].first, "dispatches");
  EXPECT_GT(times[1].second, 0.5 * wall_ms) << "of " << wall_ms << " ms";
  EXPECT_LE(times[1].second, wall_ms * 1.01 + 0.1);
  check_gl_errors("timing dispatches");
}

TEST_F(GpuPassTimerTest, NestingIsAnErrorAndANullScopeDoesNothing) {
  GpuPassTimer timer;
  timer.begin("outer");
  EXPECT_THROW(timer.begin("inner"), Error);
  timer.end();
  EXPECT_THROW(timer.end(), Error);
  { const GpuPassScope pass(nullptr, "nothing"); }
  glFinish();
  const auto times = timer.latest();
  ASSERT_EQ(times.size(), 1u);
  EXPECT_EQ(times[0].first, "outer");
}

}  // namespace
}  // namespace gps
