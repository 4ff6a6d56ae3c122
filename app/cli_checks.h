#pragma once
// Command-line values shared by gpsurf and gpsurf-editor: window and image sizes (WxH), and number
// checks whose error names the allowed range in words and shows the text as given (CLI11's own print
// 300-digit bounds, read an empty text as 0 and 0x10 as 16).
#include <CLI/CLI.hpp>

#include <limits>
#include <string>

namespace gps {

struct PixelSize {
  int width = 0, height = 0;
};

/// "WxH" with W and H from 1 to `largest`; throws a usage error naming `option` otherwise.
PixelSize parse_pixel_size(const std::string& text, const std::string& option = "--size",
                           int largest = std::numeric_limits<int>::max());

/// A decimal number from `lo` to `hi` (an optional leading '+'; no empty text, hexadecimal, NaN,
/// infinity or trailing characters).
CLI::Validator number_in(double lo, double hi);
/// A decimal number > 0 and at most `hi`.
CLI::Validator positive_number(double hi = std::numeric_limits<double>::infinity());
/// A decimal number ≥ 0.
CLI::Validator non_negative_number();
/// A decimal integer from `lo` to `hi` (digits with an optional sign, nothing else), rewritten as
/// plain decimal digits for CLI11 to read: add it with ->transform(), not ->check().
CLI::Validator integer_in(long long lo, long long hi);

}  // namespace gps
