#pragma once
// An image in memory: float channels per pixel, top row first (what OpenGL reads and image_io.h writes).
#include <cstddef>
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

/// Reverses the order of the rows (GL reads rows bottom-up; images run top-down).
void flip_rows(Image& image);

}  // namespace gps
