#pragma once
// An image in memory: float channels per pixel, top row first (what OpenGL reads and image_io.h writes).
#include <cstddef>
#include <string>
#include <vector>

namespace gps {

struct Image {
  int width = 0, height = 0, channels = 0;
  std::vector<float> pixels;  // row-major, top row first, `channels` floats per pixel
  float at(int x, int y, int c) const {
    return pixels[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * std::size_t(channels) + std::size_t(c)];
  }
};

/// The most values (pixels × channels) an image read may hold, 4 GiB as floats: a file's header cannot
/// make a read take more.
inline constexpr std::size_t kMaxImageValues = std::size_t(1) << 30;

/// Why an image of this size is not read ("W x H pixels of C channels: more than ..."), or "" if it is.
/// Inline: the OpenImageIO module links nothing of the render library.
inline std::string image_size_problem(int width, int height, int channels) {
  const auto at_least_0 = [](int n) { return std::size_t(n < 0 ? 0 : n); };
  if (at_least_0(width) * at_least_0(height) * at_least_0(channels) <= kMaxImageValues) return "";
  return std::to_string(width) + " x " + std::to_string(height) + " pixels of " + std::to_string(channels) +
         " channels: more than the 2^30 values gpsurf reads";
}

/// Reverses the order of the rows (GL reads rows bottom-up; images run top-down).
void flip_rows(Image& image);

}  // namespace gps
