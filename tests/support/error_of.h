#pragma once
// The one-line message of the gps::Error that `f` throws, or "(accepted)" when it throws none.
#include <functional>
#include <string>

#include "core/support/error.h"

namespace gps::test {

inline std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "(accepted)";
}

}  // namespace gps::test
