#pragma once
// Images in and out: PNG for colour (libpng, png_file.h), EXR for float buffers and every other format
// OpenImageIO knows (its module, image_file_module.h, opened on first use).
#include <string>
#include <vector>

#include "render/image/image.h"

namespace gps {

/// Reads a PNG, or any image OpenImageIO knows; throws gps::Error naming the file.
Image read_image(const std::string& path);

/// Writes an image (8-bit for PNG/JPEG, float for EXR), atomically; throws gps::Error naming the file.
/// `channel_names` (one per channel, or empty for R, G, B, A) label what a float buffer holds.
void write_image(const std::string& path, const Image& image, const std::vector<std::string>& channel_names = {});

/// The channel names stored in an image file (EXR keeps ours; PNG gives R, G, B, A).
std::vector<std::string> read_channel_names(const std::string& path);

/// Channel names of the world-space AOVs (render --aov), by which `diff` tells them apart.
extern const std::vector<std::string> kPositionChannels, kNormalChannels;

}  // namespace gps
