// A number typed into a modal tool.
#include "ui/tools/typed_number.h"

#include <GLFW/glfw3.h>

#include <cmath>
#include <cstdlib>
#include <limits>

namespace gps {

bool TypedNumber::handle(const InputEvent& e) {
  if (e.type == InputEvent::Type::text) {
    const unsigned c = e.codepoint;
    // An exponent after a digit ("1e9", "2.5e-3"), once: dropped, the text would read another number.
    const bool exponent = (c == 'e' || c == 'E') && text_.find_first_of("0123456789") != std::string::npos &&
                          text_.find_first_of("eE") == std::string::npos;
    if (!((c >= '0' && c <= '9') || c == '.' || c == '-' || exponent)) return false;
    text_ += char(c);
    return true;
  }
  if (e.type == InputEvent::Type::key_press && e.key == GLFW_KEY_BACKSPACE && !text_.empty()) {
    text_.pop_back();
    return true;
  }
  return false;
}

double TypedNumber::value() const {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (text_.empty()) return nan;
  char* end = nullptr;
  const double v = std::strtod(text_.c_str(), &end);
  return end && *end == '\0' && std::isfinite(v) ? v : nan;
}

std::string TypedNumber::shown() const { return text_.empty() ? "" : "  [" + text_ + "]"; }

}  // namespace gps
