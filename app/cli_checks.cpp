#include "app/cli_checks.h"

#include <charconv>
#include <cmath>
#include <functional>
#include <optional>
#include <regex>

#include "core/io/number_text.h"
#include "core/support/quoted_text.h"
#include "core/support/error.h"

namespace gps {

PixelSize parse_pixel_size(const std::string& text, const std::string& option, int largest) {
  std::smatch m;
  if (!std::regex_match(text, m, std::regex(R"((\d{1,9})x(\d{1,9}))")))
    throw usage_error(option + ": expected WxH, got " + quoted_token(text));
  const PixelSize size{std::stoi(m[1]), std::stoi(m[2])};
  if (size.width < 1 || size.height < 1 || size.width > largest || size.height > largest)
    throw usage_error(option + ": width and height are 1.." + std::to_string(largest) + " pixels each, got " +
                      quoted_token(text));
  return size;
}

namespace {

// Shows a number as the range check compares it: as few digits as read back the same double.
std::string shown_bound(double value) {
  char text[32];
  const auto [end, ec] = std::to_chars(text, text + sizeof text, value);
  return std::string(text, end);
}

// A check of one option's text: "" when `accept` takes it, else "expected WANTED, got 'TEXT'".
CLI::Validator text_check(const std::string& wanted, const std::string& name,
                          std::function<bool(std::string&)> accept) {
  return CLI::Validator(
      [wanted, accept](std::string& text) -> std::string {
        const std::string given = text;
        return accept(text) ? std::string() : "expected " + wanted + ", got " + quoted_token(given);
      },
      name);
}

// The decimal number `text` as a finite double, or nothing.
std::optional<double> finite_number(const std::string& text) {
  double value = 0;
  if (!parse_number(text, value).empty() || !std::isfinite(value)) return std::nullopt;
  return value;
}

}  // namespace

CLI::Validator number_in(double lo, double hi) {
  return text_check("a number from " + shown_bound(lo) + " to " + shown_bound(hi),
                    "NUMBER:[" + shown_bound(lo) + ", " + shown_bound(hi) + "]", [lo, hi](std::string& text) {
                      const std::optional<double> value = finite_number(text);
                      return value && *value >= lo && *value <= hi;
                    });
}

CLI::Validator positive_number(double hi) {
  const bool bounded = std::isfinite(hi);
  return text_check(bounded ? "a number > 0 and at most " + shown_bound(hi) : "a number > 0",
                    bounded ? "NUMBER:(0, " + shown_bound(hi) + "]" : "POSITIVE", [hi](std::string& text) {
                      const std::optional<double> value = finite_number(text);
                      return value && *value > 0 && *value <= hi;
                    });
}

CLI::Validator non_negative_number() {
  return text_check("a number >= 0", "NONNEGATIVE", [](std::string& text) {
    const std::optional<double> value = finite_number(text);
    return value && *value >= 0;
  });
}

CLI::Validator integer_in(long long lo, long long hi) {
  return text_check("an integer from " + std::to_string(lo) + " to " + std::to_string(hi),
                    "INTEGER:[" + std::to_string(lo) + ", " + std::to_string(hi) + "]", [lo, hi](std::string& text) {
                      const char* begin = text.data() + (text.size() > 1 && text[0] == '+');
                      long long value = 0;
                      const auto [end, ec] = std::from_chars(begin, text.data() + text.size(), value);
                      if (ec != std::errc() || end != text.data() + text.size() || value < lo || value > hi)
                        return false;
                      text = std::to_string(value);  // CLI11 reads 010 as octal
                      return true;
                    });
}

}  // namespace gps
