#include "core/io/number_text.h"

#include <cmath>

#include <charconv>

#include "core/support/quoted_text.h"

namespace gps {

std::string parse_number(std::string_view s, double& out) {
  const std::string shown = quoted_token(s);
  if (!s.empty() && s[0] == '+') s.remove_prefix(1);
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  if (p != s.data() + s.size()) return shown + " is not a number";
  if (ec == std::errc::result_out_of_range) {
    // from_chars says out of range without the direction: a negative exponent means underflow.
    const size_t e = s.find_first_of("eE");
    const bool tiny = e != std::string_view::npos && e + 1 < s.size() && s[e + 1] == '-';
    return shown + (tiny ? " underflows (too close to zero for a double)" : " overflows (too large for a double)");
  }
  if (ec != std::errc()) return shown + " is not a number";
  return "";
}

std::string number_as_read(double v) {
  // A whole number as its digits ("4000000000", not "4e+09"), up to where a double holds every one.
  if (v == std::floor(v) && std::abs(v) < 9007199254740992.0) return std::to_string((long long)v);
  char text[32];
  return std::string(text, std::to_chars(text, text + sizeof text, v).ptr);
}

}  // namespace gps
