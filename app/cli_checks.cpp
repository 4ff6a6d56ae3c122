#include "app/cli_checks.h"

#include <cmath>
#include <regex>

#include "core/mesh/error.h"

namespace gps {

PixelSize parse_pixel_size(const std::string& text, const std::string& option) {
  std::smatch m;
  if (!std::regex_match(text, m, std::regex(R"((\d{1,5})x(\d{1,5}))")))
    throw usage_error(option + ": expected WxH, got '" + text + "'");
  const PixelSize size{std::stoi(m[1]), std::stoi(m[2])};
  if (size.width < 1 || size.height < 1)
    throw usage_error(option + ": width and height must be at least 1, got '" + text + "'");
  return size;
}

namespace {

CLI::Validator number_check(bool allow_zero) {
  const std::string wanted = allow_zero ? "a number >= 0" : "a number > 0";
  return CLI::Validator(
      [allow_zero, wanted](std::string& text) -> std::string {
        double value = 0.0;
        size_t used = 0;
        try {
          value = std::stod(text, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        const bool ok = used == text.size() && std::isfinite(value) && (allow_zero ? value >= 0.0 : value > 0.0);
        return ok ? std::string() : "expected " + wanted + ", got '" + text + "'";
      },
      allow_zero ? "NONNEGATIVE" : "POSITIVE");
}

}  // namespace

CLI::Validator positive_number() { return number_check(false); }
CLI::Validator non_negative_number() { return number_check(true); }

}  // namespace gps
