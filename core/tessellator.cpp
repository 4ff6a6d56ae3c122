#include "core/tessellator.h"

#include <map>

#include "core/error.h"
#include "core/patch_eval.h"

namespace gps {

TriangleMesh tessellate(const PlanTable& plans, const std::vector<Dual>& points, int level) {
  if (level < 1 || level > 64) throw usage_error("tessellation level must be 1..64, got " + std::to_string(level));
  TriangleMesh out;
  const int L = level;
  // Shared samples: corners by their corner point, edge samples by (edge, step from its lower end).
  std::map<int, int> corner_vertex;
  std::map<std::tuple<int, int, int>, int> edge_vertex;
  std::vector<int> grid(size_t(L + 1) * size_t(L + 1));
  for (int patch = 0; patch < plans.n_patches(); ++patch) {
    const int* corner = &plans.patch_corner_points[size_t(4 * patch)];
    const auto sample = [&](int i, int j) {
      const auto s = evaluate_patch(plans, points, patch, double(i) / L, double(j) / L);
      if (!s) throw Error("patch " + std::to_string(patch) + " left the cone of positive definite matrices");
      out.positions.push_back(s->position);
      out.normals.push_back(s->normal);
      return int(out.positions.size()) - 1;
    };
    for (int j = 0; j <= L; ++j)
      for (int i = 0; i <= L; ++i) {
        int& slot = grid[size_t(i + (L + 1) * j)];
        const bool u_end = i == 0 || i == L, v_end = j == 0 || j == L;
        if (u_end && v_end) {
          const int k = i == 0 ? (j == 0 ? 0 : 3) : (j == 0 ? 1 : 2);
          const auto [it, added] = corner_vertex.try_emplace(corner[k], -1);
          if (added) it->second = sample(i, j);
          slot = it->second;
        } else if (u_end || v_end) {
          // Edge k runs from corner k to corner k+1; step s counts from corner k.
          int k, step;
          if (j == 0) k = 0, step = i;
          else if (i == L) k = 1, step = j;
          else if (j == L) k = 2, step = L - i;
          else k = 3, step = L - j;
          const int a = corner[k], b = corner[(k + 1) % 4];
          const auto key = a < b ? std::tuple{a, b, step} : std::tuple{b, a, L - step};
          const auto [it, added] = edge_vertex.try_emplace(key, -1);
          if (added) it->second = sample(i, j);
          slot = it->second;
        } else {
          slot = sample(i, j);
        }
      }
    for (int j = 0; j < L; ++j)
      for (int i = 0; i < L; ++i) {
        const int a = grid[size_t(i + (L + 1) * j)], b = grid[size_t(i + 1 + (L + 1) * j)];
        const int c = grid[size_t(i + 1 + (L + 1) * (j + 1))], d = grid[size_t(i + (L + 1) * (j + 1))];
        out.triangles.push_back({a, b, c});
        out.triangles.push_back({a, c, d});
      }
  }
  return out;
}

}  // namespace gps
