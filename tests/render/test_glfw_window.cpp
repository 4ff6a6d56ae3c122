// The GLFW window context (the editor's) on a private Xvfb display: the whole pipeline draws and
// the frame reaches the window's default framebuffer.
#include "render/glfw_window.h"

#include <glad/gl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <thread>
#include <vector>

#include "core/error.h"
#include "core/samples.h"
#include "render/surface_renderer.h"

extern char** environ;

namespace gps {
namespace {

// Xvfb on a display number of its own for the test's lifetime; unusable() says why when it failed.
class PrivateXvfb {
public:
  PrivateXvfb() {
    const int number = 90 + int(getpid() % 500);
    display_ = ":" + std::to_string(number);
    const std::string socket = "/tmp/.X11-unix/X" + std::to_string(number);
    std::vector<std::string> args = {"Xvfb", display_, "-screen", "0", "320x240x24", "-nolisten", "tcp"};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    if (posix_spawnp(&pid_, "Xvfb", nullptr, nullptr, argv.data(), environ) != 0) {
      why_ = "Xvfb is not installed";
      pid_ = 0;
      return;
    }
    for (int i = 0; i < 100 && !std::filesystem::exists(socket); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    if (!std::filesystem::exists(socket)) why_ = "Xvfb did not start";
    setenv("DISPLAY", display_.c_str(), 1);
    unsetenv("WAYLAND_DISPLAY");
  }
  ~PrivateXvfb() {
    if (pid_ > 0) {
      kill(pid_, SIGTERM);
      waitpid(pid_, nullptr, 0);
    }
  }
  const std::string& unusable() const { return why_; }

private:
  pid_t pid_ = 0;
  std::string display_, why_;
};

TEST(GlfwWindow, DrawsThePipelineIntoTheWindow) {
  const PrivateXvfb xvfb;
  if (!xvfb.unusable().empty()) GTEST_SKIP() << xvfb.unusable();
  GlfwWindow window(128, 96, "gpsurf test", false);
  EXPECT_NE(window.description().find("OpenGL 4.5"), std::string::npos) << window.description();
  int width = 0, height = 0;
  window.framebuffer_size(width, height);
  ASSERT_EQ(width, 128);
  ASSERT_EQ(height, 96);

  const CovarianceMesh mesh = make_sample("cube");
  SurfaceRenderer renderer;
  renderer.set_mesh(mesh, 2);
  RenderTarget target(width, height);
  DrawOptions o;
  o.level = 4;
  o.background = {1.0f, 1.0f, 1.0f};
  renderer.draw(target, frame_box(Vec3(-1, -1, -1), Vec3(1, 1, 1)), o);
  glBlitNamedFramebuffer(target.framebuffer(), 0, 0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glFinish();
  std::vector<unsigned char> pixels(size_t(4 * width * height));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  check_gl_errors("reading the window");
  size_t covered = 0;
  for (size_t i = 0; i < pixels.size(); i += 4) covered += pixels[i] < 250 || pixels[i + 1] < 250 || pixels[i + 2] < 250;
  // The framed cube covers a good share of the window, and the corners stay background.
  EXPECT_GT(covered, size_t(width * height) / 10);
  EXPECT_LT(covered, size_t(width * height) * 9 / 10);
  EXPECT_EQ(pixels[0], 255);
  window.swap_buffers();
}

TEST(GlfwWindow, NoDisplayIsAOneLineError) {
  const char* saved = std::getenv("DISPLAY");
  const std::string display = saved ? saved : "";
  setenv("DISPLAY", ":4999", 1);
  unsetenv("WAYLAND_DISPLAY");
  try {
    GlfwWindow window(64, 64, "none", false);
    FAIL() << "a window opened without a display";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("GLFW"), std::string::npos);
  }
  if (saved) setenv("DISPLAY", display.c_str(), 1);
}

}  // namespace
}  // namespace gps
