#pragma once
// Errors of the work a command does on a mesh it has read, named after that mesh's file.
#include <string>
#include <utility>

#include "core/support/quoted_text.h"
#include "core/support/error.h"

namespace gps {

/// Runs `work` and returns what it returns; a gps::Error it throws (an output too large to hold, a
/// refinement that fails) is thrown again with `input` before its message, keeping its kind.
template <class Work>
auto naming_input(const std::string& input, Work&& work) -> decltype(work()) {
  try {
    return std::forward<Work>(work)();
  } catch (const Error& e) {
    throw Error(escaped(input) + ": " + e.what(), e.kind());
  }
}

}  // namespace gps
