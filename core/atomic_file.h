#pragma once
// Writing a file so that the target is either the old file or the complete new one (DESIGN.md §4).
#include <functional>
#include <ostream>
#include <string>

namespace gps {

/// Writes through `write` into a temporary file beside `path`, then renames it over `path`.
/// On any failure the temporary file is removed, `path` is untouched, and gps::Error names it.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                           bool binary = false);

}  // namespace gps
