#pragma once
// Input events as a test types them: a character and a key press.
#include "ui/input/input_events.h"

namespace gps::test {

inline InputEvent text_event(char c) {
  InputEvent e;
  e.type = InputEvent::Type::text;
  e.codepoint = unsigned(c);
  return e;
}

inline InputEvent key_event(int k) {
  InputEvent e;
  e.type = InputEvent::Type::key_press;
  e.key = k;
  return e;
}

}  // namespace gps::test
