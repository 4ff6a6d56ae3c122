#pragma once
// Reading a whole file with one-line errors (missing, a directory, unreadable).
#include <string>

namespace gps {

/// The bytes of the file at `path`; throws gps::Error naming it when it cannot be read.
std::string read_text_file(const std::string& path);

}  // namespace gps
