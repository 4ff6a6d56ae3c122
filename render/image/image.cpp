#include "render/image/image.h"

#include <algorithm>

namespace gps {

void flip_rows(Image& image) {
  const size_t row = size_t(image.width) * size_t(image.channels);
  for (int y = 0; y < image.height / 2; ++y)
    std::swap_ranges(image.pixels.begin() + long(size_t(y) * row), image.pixels.begin() + long(size_t(y + 1) * row),
                     image.pixels.begin() + long(size_t(image.height - 1 - y) * row));
}

}  // namespace gps
