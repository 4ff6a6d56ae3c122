#pragma once
// Command-line values shared by gpsurf and gpsurf-editor: window and image sizes (WxH), and number
// checks whose error names the allowed range in words (CLI11's own print 300-digit bounds).
#include <CLI/CLI.hpp>

#include <string>

namespace gps {

struct PixelSize {
  int width = 0, height = 0;
};

/// "WxH" with W and H from 1 to 99999; throws a usage error naming `option` otherwise.
PixelSize parse_pixel_size(const std::string& text, const std::string& option = "--size");

/// A finite number > 0.
CLI::Validator positive_number();
/// A finite number ≥ 0.
CLI::Validator non_negative_number();

}  // namespace gps
