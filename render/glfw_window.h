#pragma once
// A GL 4.5 core context with a window (GLFW), for the editor; needs a display (X11/Wayland or Xvfb).
#include <memory>
#include <string>

#include "render/gl_context.h"

struct GLFWwindow;

namespace gps {

class GlfwWindow : public GlContext {
public:
  /// Opens a window with a current GL 4.5 core context and the glad loader initialised; throws gps::Error without a display.
  GlfwWindow(int width, int height, const std::string& title, bool visible = true);
  ~GlfwWindow() override;
  GlfwWindow(const GlfwWindow&) = delete;
  GlfwWindow& operator=(const GlfwWindow&) = delete;

  void make_current() override;
  std::string description() const override { return "GLFW window: " + GlContext::description(); }
  GLFWwindow* handle() const { return window_; }
  bool should_close() const;
  void swap_buffers();
  /// Framebuffer size in pixels (differs from the window size on high-DPI screens).
  void framebuffer_size(int& width, int& height) const;

private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace gps
