#include "render/image/matcap.h"

#include <algorithm>
#include <cmath>

#include "core/support/error.h"

namespace gps {

namespace {

struct Material {
  const char* name;
  float base[3];
  float rim[3];
  float specular, shininess;
};

constexpr Material kMaterials[] = {
    {"clay", {0.80f, 0.62f, 0.52f}, {0.35f, 0.30f, 0.32f}, 0.25f, 12.0f},
    {"porcelain", {0.92f, 0.92f, 0.90f}, {0.55f, 0.60f, 0.70f}, 0.8f, 60.0f},
    {"jade", {0.30f, 0.62f, 0.45f}, {0.10f, 0.25f, 0.20f}, 0.5f, 30.0f},
    {"red-wax", {0.75f, 0.12f, 0.10f}, {0.30f, 0.05f, 0.10f}, 0.6f, 40.0f},
};

}  // namespace

std::vector<std::string> builtin_matcap_names() {
  std::vector<std::string> names;
  for (const auto& m : kMaterials) names.emplace_back(m.name);
  return names;
}

Image make_builtin_matcap(const std::string& name, int size) {
  const auto it =
      std::find_if(std::begin(kMaterials), std::end(kMaterials), [&](const Material& m) { return name == m.name; });
  if (it == std::end(kMaterials)) throw usage_error("unknown MatCap '" + name + "'");
  Image image{size, size, 3, std::vector<float>(size_t(size) * size_t(size) * 3)};
  const float light[3] = {-0.4f, 0.6f, 0.69f}, fill[3] = {0.6f, -0.3f, 0.74f};
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      // Texel (x, y) shows the sphere normal n with n.xy = 2·uv − 1 (uv with y up, as the shader reads it).
      const float nx = 2.0f * (x + 0.5f) / size - 1.0f, ny = 1.0f - 2.0f * (y + 0.5f) / size;
      const float r2 = std::min(1.0f, nx * nx + ny * ny), nz = std::sqrt(1.0f - r2);
      const float diffuse = std::max(0.0f, nx * light[0] + ny * light[1] + nz * light[2]);
      const float back = std::max(0.0f, nx * fill[0] + ny * fill[1] + nz * fill[2]);
      const float h[3] = {light[0], light[1], light[2] + 1.0f};
      const float hn = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
      const float spec =
          std::pow(std::max(0.0f, (nx * h[0] + ny * h[1] + nz * h[2]) / hn), it->shininess) * it->specular;
      const float rim = std::pow(1.0f - nz, 3.0f);
      for (int c = 0; c < 3; ++c) {
        const float v = it->base[c] * (0.18f + 0.72f * diffuse + 0.15f * back) + spec + it->rim[c] * rim;
        image.pixels[(size_t(y) * size_t(size) + size_t(x)) * 3 + size_t(c)] = std::clamp(v, 0.0f, 1.0f);
      }
    }
  return image;
}

}  // namespace gps
