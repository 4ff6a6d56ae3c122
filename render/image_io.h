#pragma once
// Images in and out through OpenImageIO: PNG for colour, EXR for float buffers.
#include <string>
#include <vector>

namespace gps {

struct Image {
  int width = 0, height = 0, channels = 0;
  std::vector<float> pixels;  // row-major, top row first, `channels` floats per pixel
  float at(int x, int y, int c) const { return pixels[(size_t(y) * size_t(width) + size_t(x)) * size_t(channels) + size_t(c)]; }
};

/// Reverses the order of the rows (GL reads rows bottom-up; images run top-down).
void flip_rows(Image& image);

/// Reads any image OpenImageIO knows; throws gps::Error naming the file.
Image read_image(const std::string& path);

/// Writes an image (8-bit for PNG/JPEG, float for EXR), atomically; throws gps::Error naming the file.
/// `channel_names` (one per channel, or empty for R, G, B, A) label what a float buffer holds.
void write_image(const std::string& path, const Image& image, const std::vector<std::string>& channel_names = {});

/// The channel names stored in an image file (EXR keeps ours; PNG gives R, G, B, A).
std::vector<std::string> read_channel_names(const std::string& path);

/// Channel names of the world-space AOVs (render --aov), by which `diff` tells them apart.
extern const std::vector<std::string> kPositionChannels, kNormalChannels;

}  // namespace gps
