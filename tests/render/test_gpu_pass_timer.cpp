// GPU pass timing on OSMesa: every pass reported, in first-seen order, with finite times.
#include "render/gl/gpu_pass_timer.h"

#include <glad/gl.h>
#include <gtest/gtest.h>

#include <cmath>

#include "core/support/error.h"
#include "render/gl/render_target.h"
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
