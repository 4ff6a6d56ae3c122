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

/// Reads any image OpenImageIO knows; throws gps::Error naming the file.
Image read_image(const std::string& path);

/// Writes an image (8-bit for PNG/JPEG, float for EXR), atomically; throws gps::Error naming the file.
void write_image(const std::string& path, const Image& image);

}  // namespace gps
