#pragma once
// Whole wheel notches from scroll events, for the tools whose wheel counts something (segments, cuts,
// steps): a notch per step, however many steps one event carries (a fast wheel sends several), and the
// fractions a smooth-scrolling device sends added up until they make one.
#include <cmath>

namespace gps {

class WheelNotches {
public:
  /// The whole notches `steps` completes (negative towards the user).
  int take(float steps) {
    held_ += steps;
    const float whole = std::trunc(held_);
    held_ -= whole;
    return int(whole);
  }

private:
  float held_ = 0.0f;
};

}  // namespace gps
