#include "render/glfw_window.h"

#include <glad/gl.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "core/error.h"

namespace gps {

namespace {

std::string last_glfw_error() {
  const char* description = nullptr;
  glfwGetError(&description);
  return description ? description : "unknown error";
}

}  // namespace

GlfwWindow::GlfwWindow(int width, int height, const std::string& title, bool visible) {
  if (!glfwInit()) throw Error("GLFW could not start (no display?): " + last_glfw_error());
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
  glfwWindowHint(GLFW_DEPTH_BITS, 24);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) {
    const std::string why = last_glfw_error();
    glfwTerminate();
    throw Error("GLFW could not open a window with an OpenGL 4.5 core context: " + why);
  }
  make_current();
  if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress))) {
    glfwDestroyWindow(window_);
    glfwTerminate();
    throw Error("could not load the OpenGL 4.5 functions through GLFW");
  }
  enable_gl_debug_output();
}

GlfwWindow::~GlfwWindow() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

void GlfwWindow::make_current() { glfwMakeContextCurrent(window_); }
bool GlfwWindow::should_close() const { return glfwWindowShouldClose(window_); }
void GlfwWindow::swap_buffers() { glfwSwapBuffers(window_); }
void GlfwWindow::framebuffer_size(int& width, int& height) const { glfwGetFramebufferSize(window_, &width, &height); }

}  // namespace gps
