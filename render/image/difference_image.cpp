#include "render/image/difference_image.h"

#include <algorithm>
#include <cmath>

#include "core/support/error.h"
#include "core/mesh/linalg.h"

namespace gps {

Image difference_image(const Image& a, const Image& b, AovKind kind, double factor, double threshold,
                       DifferenceStats& s) {
  if (a.width != b.width || a.height != b.height)
    throw usage_error("the images differ in size: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                      " and " + std::to_string(b.width) + "x" + std::to_string(b.height));
  if (a.channels < 3 || b.channels < 3) throw usage_error("AOV images need at least three channels (x y z)");
  const auto covered = [](const Image& im, int x, int y) { return im.channels < 4 || im.at(x, y, 3) > 0.5f; };
  const auto value = [](const Image& im, int x, int y) { return Vec3(im.at(x, y, 0), im.at(x, y, 1), im.at(x, y, 2)); };
  double scale = 1.0;
  if (kind == AovKind::position) {
    Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
    for (int y = 0; y < a.height; ++y)
      for (int x = 0; x < a.width; ++x)
        if (covered(a, x, y)) lo = lo.cwiseMin(value(a, x, y)), hi = hi.cwiseMax(value(a, x, y));
    scale = hi.x() >= lo.x() ? std::max(1e-30, (hi - lo).norm()) : 1.0;
  }
  Image out{a.width, a.height, 3, std::vector<float>(size_t(a.width) * size_t(a.height) * 3, 0.0f)};
  s = {};
  double sum = 0;
  int above = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      float* px = &out.pixels[(size_t(y) * size_t(a.width) + size_t(x)) * 3];
      const bool ca = covered(a, x, y), cb = covered(b, x, y);
      if (ca != cb) {
        px[0] = 1.0f;
        ++s.coverage_mismatch;
        continue;
      }
      if (!ca) continue;
      const Vec3 d = value(a, x, y) - value(b, x, y);
      double e;
      if (kind == AovKind::position) {
        e = d.norm() / scale;
        px[0] = px[1] = px[2] = float(std::min(1.0, e * factor));
      } else {
        e = d.cwiseAbs().maxCoeff();
        for (int c = 0; c < 3; ++c) px[c] = float(std::min(1.0, std::abs(d[c]) * factor));
      }
      s.max = std::max(s.max, e);
      sum += e;
      above += e > threshold;
      ++s.covered;
    }
  s.mean = s.covered ? sum / s.covered : 0.0;
  s.share_above = s.covered ? double(above) / s.covered : 0.0;
  return out;
}

}  // namespace gps
