#pragma once
// Reading one decimal number from text with a message that says what is wrong with it.
#include <string>
#include <string_view>

namespace gps {

/// Parses `token` (an optional leading '+' allowed) into `out`. Returns "" on success, else why not,
/// the token shown as core/io/quoted_text.h quotes it: "'x' is not a number", "'1e-400' underflows (too close to zero
/// for a double)", "'1e400' overflows ...".
std::string parse_number(std::string_view token, double& out);

}  // namespace gps
