#pragma once
// A number typed into a modal tool, as Blender takes one: digits, a point, a minus and an exponent arrive as text,
// Backspace takes the last one back; the text is shown in the status bar and its value replaces the mouse's.
#include <string>

#include "ui/input/input_events.h"

namespace gps {

class TypedNumber {
public:
  /// Takes a digit, '.', '-' or an exponent's 'e' after a digit (text events) or Backspace (with something
  /// typed); false for any other event.
  bool handle(const InputEvent& event);
  const std::string& text() const { return text_; }
  bool empty() const { return text_.empty(); }
  /// The value typed, NaN while the text is not a finite number ("", "-", ".").
  double value() const;
  /// "  [TEXT]" while something is typed, else "": for a status line.
  std::string shown() const;

private:
  std::string text_;
};

}  // namespace gps
