#pragma once
// Errors of the work a command does on a mesh it has read, named after that mesh's file.
#include <string>
#include <utility>

#include "core/io/mesh_io.h"
#include "core/mesh/element_names.h"
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

/// The same for work on the mesh read from the file `input`: an error about one of its elements
/// names it as the file numbers it, or where the mesh was `repaired` (renumbered) by index from 0.
template <class Work>
auto naming_mesh_input(const std::string& input, bool repaired, Work&& work) -> decltype(work()) {
  try {
    return std::forward<Work>(work)();
  } catch (const ElementError& e) {
    throw Error(escaped(input) + ": " + e.named(repaired ? ElementNames{} : file_element_names(input)), e.kind());
  } catch (const Error& e) {
    throw Error(escaped(input) + ": " + e.what(), e.kind());
  }
}

}  // namespace gps
