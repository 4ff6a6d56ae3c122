#include "render/image/scalar_colouring.h"

#include <algorithm>
#include <cmath>

#include "core/support/error.h"

namespace gps {
namespace {

struct Colormap {
  const char* name;
  std::array<std::array<float, 3>, 5> stops;  // sRGB at 0, ¼, ½, ¾, 1
};

std::array<float, 3> rgb(int hex) {
  return {float((hex >> 16) & 255) / 255.0f, float((hex >> 8) & 255) / 255.0f, float(hex & 255) / 255.0f};
}

const std::array<Colormap, 3>& colormaps() {
  static const std::array<Colormap, 3> maps = {{
      {"viridis", {rgb(0x440154), rgb(0x3b528b), rgb(0x21918c), rgb(0x5ec962), rgb(0xfde725)}},
      {"coolwarm", {rgb(0x3b4cc0), rgb(0x7b9ff9), rgb(0xdddcdc), rgb(0xf49a7b), rgb(0xb40426)}},
      {"gray", {rgb(0x000000), rgb(0x404040), rgb(0x808080), rgb(0xbfbfbf), rgb(0xffffff)}},
  }};
  return maps;
}

}  // namespace

bool is_colormap(const std::string& colormap) {
  return std::any_of(colormaps().begin(), colormaps().end(), [&](const Colormap& m) { return colormap == m.name; });
}

std::array<float, 3> colormap_colour(const std::string& colormap, double t) {
  for (const Colormap& m : colormaps()) {
    if (colormap != m.name) continue;
    const double x = std::isnan(t) ? 0.0 : std::clamp(t, 0.0, 1.0) * 4;
    const int i = std::min(int(x), 3);
    const float f = float(x - i);
    std::array<float, 3> c;
    for (int k = 0; k < 3; ++k)
      c[size_t(k)] = (1 - f) * m.stops[size_t(i)][size_t(k)] + f * m.stops[size_t(i + 1)][size_t(k)];
    return c;
  }
  throw Error("unknown colormap '" + colormap + "' (viridis, coolwarm or gray)");
}

void colour_by_scalars(Image& colour, const Image& positions, const std::string& colormap, double low, double high,
                       const std::function<std::vector<double>(const std::vector<Vec3>&)>& scalars_at) {
  std::vector<size_t> covered;
  std::vector<Vec3> points;
  const size_t n = size_t(colour.width) * size_t(colour.height);
  float brightest = 0;
  const auto brightness = [&](size_t p) {
    const float* c = &colour.pixels[p * size_t(colour.channels)];
    return (c[0] + c[1] + c[2]) / 3;
  };
  for (size_t p = 0; p < n; ++p) {
    const float* x = &positions.pixels[p * size_t(positions.channels)];
    if (!(x[3] >= 1)) continue;
    covered.push_back(p);
    points.emplace_back(x[0], x[1], x[2]);
    brightest = std::max(brightest, brightness(p));
  }
  const std::vector<double> scalars = scalars_at(points);
  const double span = high > low ? high - low : 1.0;
  for (size_t i = 0; i < covered.size(); ++i) {
    const float shade = brightest > 0 ? brightness(covered[i]) / brightest : 1.0f;
    const std::array<float, 3> c = colormap_colour(colormap, (scalars[i] - low) / span);
    float* out = &colour.pixels[covered[i] * size_t(colour.channels)];
    for (int k = 0; k < 3; ++k) out[k] = c[size_t(k)] * shade;
  }
}

}  // namespace gps
