#include "ui/input/glfw_input.h"

#include <GLFW/glfw3.h>

namespace gps {

namespace {

GlfwInputForwarder::Handlers& of(GLFWwindow* w) {
  return *static_cast<GlfwInputForwarder::Handlers*>(glfwGetWindowUserPointer(w));
}

glm::vec2 cursor_of(GLFWwindow* w) {
  double x = 0, y = 0;
  glfwGetCursorPos(w, &x, &y);
  return {float(x), float(y)};
}

}  // namespace

GlfwInputForwarder::GlfwInputForwarder(GLFWwindow* window, std::function<void(InputEvent)> push,
                                       std::function<void()> on_close)
    : window_(window), handlers_{std::move(push), std::move(on_close)} {
  glfwSetWindowUserPointer(window, &handlers_);
  glfwSetCursorPosCallback(window, [](GLFWwindow* w, double x, double y) {
    InputEvent e;
    e.position = {float(x), float(y)};
    of(w).push(e);
  });
  glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int) {
    if (button > 2) return;
    InputEvent e;
    e.type = action == GLFW_PRESS ? InputEvent::Type::press : InputEvent::Type::release;
    e.button = button;
    e.position = cursor_of(w);
    of(w).push(e);
  });
  glfwSetScrollCallback(window, [](GLFWwindow* w, double, double dy) {
    InputEvent e;
    e.type = InputEvent::Type::scroll;
    e.steps = float(dy);
    e.position = cursor_of(w);
    of(w).push(e);
  });
  glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int) {
    if (action == GLFW_REPEAT || key < 0) return;
    InputEvent e;
    e.type = action == GLFW_PRESS ? InputEvent::Type::key_press : InputEvent::Type::key_release;
    e.key = key;
    of(w).push(e);
  });
  glfwSetCharCallback(window, [](GLFWwindow* w, unsigned codepoint) {
    InputEvent e;
    e.type = InputEvent::Type::text;
    e.codepoint = codepoint;
    of(w).push(e);
  });
  glfwSetDropCallback(window, [](GLFWwindow* w, int count, const char** paths) {
    InputEvent e;
    e.type = InputEvent::Type::drop;
    e.paths.assign(paths, paths + count);
    of(w).push(e);
  });
  glfwSetWindowCloseCallback(window, [](GLFWwindow* w) {
    glfwSetWindowShouldClose(w, GLFW_FALSE);
    of(w).on_close();
  });
}

GlfwInputForwarder::~GlfwInputForwarder() {
  glfwSetCursorPosCallback(window_, nullptr);
  glfwSetMouseButtonCallback(window_, nullptr);
  glfwSetScrollCallback(window_, nullptr);
  glfwSetKeyCallback(window_, nullptr);
  glfwSetCharCallback(window_, nullptr);
  glfwSetDropCallback(window_, nullptr);
  glfwSetWindowCloseCallback(window_, nullptr);
  glfwSetWindowUserPointer(window_, nullptr);
}

}  // namespace gps
