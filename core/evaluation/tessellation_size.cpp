#include "core/evaluation/tessellation_size.h"

namespace gps {

namespace {

// Per vertex: its position and normal (48 bytes) with room for the array's growth, and the map
// entry of a shared boundary sample; per triangle: three indices, with room for growth.
constexpr double kBytesPerVertex = 96, kBytesPerTriangle = 16;

}  // namespace

OutputSize tessellation_size(const PatchPlans& plans, int level) {
  double vertices = 0, triangles = 0;
  const double L = level;
  if (plans.shape == PatchShape::triangle) {
    vertices = plans.n_patches() * (L + 1) * (L + 2) / 2;
    triangles = plans.n_patches() * L * L;
  } else {
    const double half = double(level + level % 2) / 2;
    for (int patch = 0; patch < plans.n_patches(); ++patch) {
      const double n = half_size_patch(plans, patch) ? half : L;
      vertices += (n + 1) * (n + 1);
      triangles += 2 * n * n;
      if (level % 2 == 0) continue;
      // At an odd level an edge beside two half-size patches has one sample more, and each of its
      // cells becomes a fan around a new centre: at most 3 triangles more.
      for (int k = 0; k < 4; ++k)
        if (patch_edge(plans, patch, k).part == PatchEdgePart::whole_beside_halves) {
          vertices += 1 + n;
          triangles += 3 * n;
        }
    }
  }
  return {vertices, triangles, kBytesPerVertex * vertices + kBytesPerTriangle * triangles};
}

}  // namespace gps
