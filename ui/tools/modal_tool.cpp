// What confirms and what cancels every modal tool.
#include "ui/tools/modal_tool.h"

#include <GLFW/glfw3.h>

namespace gps {

bool confirms(const InputEvent& e) {
  return (e.type == InputEvent::Type::press && e.button == 0) ||
         (e.type == InputEvent::Type::key_press && (e.key == GLFW_KEY_ENTER || e.key == GLFW_KEY_KP_ENTER));
}

bool cancels(const InputEvent& e) {
  return (e.type == InputEvent::Type::press && e.button == 1) ||
         (e.type == InputEvent::Type::key_press && e.key == GLFW_KEY_ESCAPE);
}

}  // namespace gps
