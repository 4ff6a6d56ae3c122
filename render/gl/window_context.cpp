#include "render/gl/window_context.h"

#include <glad/gl.h>

#include <GLFW/glfw3.h>

#include "core/support/error.h"
#include "render/gl/driver_heap.h"

namespace gps {

namespace {
std::string last_glfw_error;
void on_glfw_error(int, const char* message) { last_glfw_error = message; }
}  // namespace

WindowContext::WindowContext(int width, int height, const std::string& title, bool visible) {
  retain_freed_heap();  // without a GPU, GLX is llvmpipe
  glfwSetErrorCallback(on_glfw_error);
  if (!glfwInit())
    throw Error("cannot open a window: " + (last_glfw_error.empty() ? std::string("no display") : last_glfw_error));
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) {
    glfwTerminate();
    throw Error("cannot open an OpenGL 4.5 core window: " + last_glfw_error);
  }
  make_current();
  if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress)))
    throw Error("could not load the OpenGL 4.5 functions through GLFW");
  enable_gl_debug_output();
}

WindowContext::~WindowContext() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

void WindowContext::make_current() { glfwMakeContextCurrent(window_); }

void WindowContext::framebuffer_size(int& width, int& height) const {
  glfwGetFramebufferSize(window_, &width, &height);
}

void WindowContext::blit(const RenderTarget& target) const {
  int width = 0, height = 0;
  framebuffer_size(width, height);
  glNamedFramebufferReadBuffer(target.framebuffer(), GL_COLOR_ATTACHMENT0);
  glBlitNamedFramebuffer(target.framebuffer(), 0, 0, 0, target.width(), target.height(), 0, 0, width, height,
                         GL_COLOR_BUFFER_BIT, GL_LINEAR);
  check_gl_errors("showing the frame");
}

Image WindowContext::read_pixels() const {
  int width = 0, height = 0;
  framebuffer_size(width, height);
  Image image{width, height, 4, std::vector<float>(size_t(width) * size_t(height) * 4)};
  glNamedFramebufferReadBuffer(0, GL_BACK);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, image.pixels.data());
  check_gl_errors("reading the window");
  flip_rows(image);
  return image;
}

void WindowContext::bind_default_framebuffer() const {
  int width = 0, height = 0;
  framebuffer_size(width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, width, height);
}

void WindowContext::wait_for_gpu() const {
  const GLsync fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  glClientWaitSync(fence, GL_SYNC_FLUSH_COMMANDS_BIT, GLuint64(2'000'000'000));
  glDeleteSync(fence);
}

void WindowContext::swap_buffers() { glfwSwapBuffers(window_); }

bool WindowContext::should_close() const { return glfwWindowShouldClose(window_); }

}  // namespace gps
