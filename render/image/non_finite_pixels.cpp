#include "render/image/non_finite_pixels.h"

#include <cmath>

#include "core/support/error.h"

namespace gps {

long long count_non_finite_pixels(const Image& position, const Image& normal) {
  if (position.width != normal.width || position.height != normal.height)
    throw Error("non-finite check: the position and normal images differ in size");
  long long count = 0;
  for (int y = 0; y < position.height; ++y) {
    for (int x = 0; x < position.width; ++x) {
      bool finite = true;
      for (int c = 0; c < position.channels; ++c) finite = finite && std::isfinite(position.at(x, y, c));
      for (int c = 0; c < normal.channels; ++c) finite = finite && std::isfinite(normal.at(x, y, c));
      count += !finite;
    }
  }
  return count;
}

long long count_covered_pixels(const Image& normal) {
  long long count = 0;
  for (int y = 0; y < normal.height; ++y)
    for (int x = 0; x < normal.width; ++x) {
      bool covered = false;
      for (int c = 0; c < normal.channels; ++c) covered = covered || normal.at(x, y, c) != 0.0f;
      count += covered;
    }
  return count;
}

}  // namespace gps
