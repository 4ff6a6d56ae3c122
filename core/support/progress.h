#pragma once
// How a long computation (simplifying, fitting) tells its caller how far it has come, and how the
// caller stops it: the editor runs these in the background with a progress bar and a Cancel button.
#include <functional>

#include "core/support/error.h"

namespace gps {

/// Called now and then with the fraction done (0 to 1); returning false asks the computation to
/// stop, which it then does by throwing Cancelled. An empty function is never called.
using ProgressReport = std::function<bool(double fraction)>;

/// Thrown by a computation its ProgressReport stopped; what it was given is left unchanged.
class Cancelled : public Error {
public:
  Cancelled() : Error("cancelled") {}
};

}  // namespace gps
