#pragma once
// Reading one decimal number from text with a message that says what is wrong with it, and writing
// one back as messages show it.
#include <string>
#include <string_view>

namespace gps {

/// Parses `token` (an optional leading '+' allowed) into `out`. Returns "" on success, else why not,
/// the token shown as core/support/quoted_text.h quotes it: "'x' is not a number", "'1e-400' underflows (too close to zero
/// for a double)", "'1e400' overflows ...".
std::string parse_number(std::string_view token, double& out);

/// A value as a file holds it, in the fewest digits that read back as it: an index 2147483648 in
/// full (not 2.14748e+09), a sharpness 0.1.
std::string number_as_read(double v);

}  // namespace gps
