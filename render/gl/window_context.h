#pragma once
// A GLFW window with an OpenGL 4.5 core context (the editor's; tests run it under Xvfb).
#include <memory>
#include <string>

#include "render/gl/gl_context.h"
#include "render/gl/render_target.h"

struct GLFWwindow;

namespace gps {

class WindowContext : public GlContext {
public:
  /// Opens a window; throws gps::Error (one line) when there is no display or no GL 4.5 core.
  WindowContext(int width, int height, const std::string& title, bool visible = true);
  ~WindowContext() override;
  WindowContext(const WindowContext&) = delete;
  WindowContext& operator=(const WindowContext&) = delete;

  void make_current() override;
  GLFWwindow* window() const { return window_; }
  /// The framebuffer size in pixels (differs from the window size on high-DPI screens).
  void framebuffer_size(int& width, int& height) const;
  /// Copies a render target's colour into the window's back buffer (scaled to fit).
  void blit(const RenderTarget& target) const;
  /// The back buffer (call after drawing, before swap_buffers) as RGBA in [0,1], rows top-down, for screenshots.
  Image read_pixels() const;
  /// Makes the window's own framebuffer the draw target, over the whole framebuffer (for the UI).
  void bind_default_framebuffer() const;
  /// Blocks until the GPU has finished every command issued so far (at most 2 s).
  void wait_for_gpu() const;
  void swap_buffers();
  bool should_close() const;

private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace gps
