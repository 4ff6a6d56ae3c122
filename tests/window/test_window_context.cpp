// A real GLFW window (run under Xvfb by ctest): the pipeline draws and the frame reaches the window.
#include "render/gl/window_context.h"

#include <glad/gl.h>
#include <gtest/gtest.h>

#include <cstdlib>

#include "core/support/error.h"
#include "core/modelling/samples.h"
#include "render/pipeline/surface_renderer.h"

namespace gps {
namespace {

TEST(WindowContext, DrawsTheSurfaceIntoAWindow) {
  WindowContext window(320, 240, "gpsurf test", true);
  EXPECT_NE(window.description().find("4.5"), std::string::npos) << window.description();
  const CovarianceMesh mesh = make_sample("cube");
  SurfaceRenderer renderer;
  renderer.set_mesh(mesh);
  int width = 0, height = 0;
  window.framebuffer_size(width, height);
  RenderTarget target(width, height);
  DrawOptions o;
  o.background = {0.0f, 0.0f, 0.0f};
  renderer.draw(target, frame_box(Vec3(-1, -1, -1), Vec3(1, 1, 1)), o);
  window.blit(target);
  std::vector<unsigned char> pixels(size_t(width) * size_t(height) * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  int lit = 0;
  for (size_t i = 0; i < pixels.size(); i += 4) lit += pixels[i] > 40;
  EXPECT_GT(lit, width * height / 20);
  EXPECT_LT(lit, width * height);  // the background shows around the surface
  window.swap_buffers();
  EXPECT_FALSE(window.should_close());
}

// read_pixels gives the back buffer top row first: a colour cleared into the top half only (GL's
// rows count from the bottom) shows in the image's first rows.
TEST(WindowContext, ReadPixelsGivesTheBackBufferTopDown) {
  WindowContext window(96, 64, "gpsurf read test", true);
  int width = 0, height = 0;
  window.framebuffer_size(width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, width, height);
  glClearColor(0.2f, 0.4f, 0.6f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, height / 2, width, height - height / 2);
  glClearColor(1.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  const Image image = window.read_pixels();
  ASSERT_EQ(image.width, width);
  ASSERT_EQ(image.height, height);
  ASSERT_EQ(image.channels, 4);
  const auto expect_colour = [&image](int x, int y, float r, float g, float b) {
    EXPECT_NEAR(image.at(x, y, 0), r, 1.0f / 255) << x << "," << y;
    EXPECT_NEAR(image.at(x, y, 1), g, 1.0f / 255) << x << "," << y;
    EXPECT_NEAR(image.at(x, y, 2), b, 1.0f / 255) << x << "," << y;
  };
  for (const int x : {0, width / 2, width - 1}) {
    expect_colour(x, 0, 1.0f, 0.0f, 0.0f);
    expect_colour(x, height / 2 - 1, 1.0f, 0.0f, 0.0f);
    expect_colour(x, height - height / 2, 0.2f, 0.4f, 0.6f);
    expect_colour(x, height - 1, 0.2f, 0.4f, 0.6f);
  }
  window.swap_buffers();
}

TEST(WindowContext, NoDisplayIsAOneLineError) {
  const char* saved = std::getenv("DISPLAY");
  const std::string display = saved ? saved : "";
  setenv("DISPLAY", ":4999", 1);  // no server there
  unsetenv("WAYLAND_DISPLAY");
  try {
    WindowContext window(64, 64, "none", false);
    ADD_FAILURE() << "a window opened without a display";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
  }
  if (saved) setenv("DISPLAY", display.c_str(), 1);
}

}  // namespace
}  // namespace gps
