#pragma once
// GLFW's callbacks turned into InputEvents (window pixels), the editor's one input path.
#include <functional>

#include "ui/input/input_events.h"

struct GLFWwindow;

namespace gps {

/// While alive, hands every cursor move, button, wheel step, key (repeats excepted: ImGui repeats
/// held keys itself), character and file drop on `window` to `push`, and a request to close the
/// window to `on_close` (the window stays open: the editor asks about unsaved changes first).
/// Uses the window's user pointer.
class GlfwInputForwarder {
public:
  GlfwInputForwarder(GLFWwindow* window, std::function<void(InputEvent)> push, std::function<void()> on_close);
  ~GlfwInputForwarder();
  GlfwInputForwarder(const GlfwInputForwarder&) = delete;
  GlfwInputForwarder& operator=(const GlfwInputForwarder&) = delete;

  /// What the callbacks reach through the window's user pointer.
  struct Handlers {
    std::function<void(InputEvent)> push;
    std::function<void()> on_close;
  };

private:
  GLFWwindow* window_;
  Handlers handlers_;
};

}  // namespace gps
