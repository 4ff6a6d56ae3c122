#include "core/tessellator.h"

#include <map>

#include "core/error.h"
#include "core/patch_eval.h"

namespace gps {

namespace {

// A sample shared between patches: a corner by its point, an edge sample by (edge, step from its lower end).
class SharedSamples {
public:
  template <class Sample>
  int corner(int point, Sample sample) {
    const auto [it, added] = corners_.try_emplace(point, -1);
    if (added) it->second = sample();
    return it->second;
  }
  // Step `step` of `level` along the edge from point a to point b.
  template <class Sample>
  int edge(int a, int b, int step, int level, Sample sample) {
    const auto key = a < b ? std::tuple{a, b, step} : std::tuple{b, a, level - step};
    const auto [it, added] = edges_.try_emplace(key, -1);
    if (added) it->second = sample();
    return it->second;
  }

private:
  std::map<int, int> corners_;
  std::map<std::tuple<int, int, int>, int> edges_;
};

// The limit point at (u, v) of a patch, appended to `out`; its index.
int append_sample(TriangleMesh& out, const PlanTable& plans, const std::vector<Dual>& points, int patch, double u, double v) {
  const auto s = evaluate_patch(plans, points, patch, u, v);
  if (!s) throw Error("patch " + std::to_string(patch) + " left the cone of positive definite matrices");
  out.positions.push_back(s->position);
  out.normals.push_back(s->normal);
  return int(out.positions.size()) - 1;
}

// Triangle patches: the points (i, j)/L, i + j ≤ L, of each patch's (u, v) triangle.
TriangleMesh tessellate_triangles(const PlanTable& plans, const std::vector<Dual>& points, int L) {
  TriangleMesh out;
  SharedSamples shared;
  std::vector<int> grid(size_t(L + 1) * size_t(L + 1), -1);
  for (int patch = 0; patch < plans.n_patches(); ++patch) {
    const int* corner = &plans.patch_corner_points[size_t(3 * patch)];
    for (int j = 0; j <= L; ++j)
      for (int i = 0; i + j <= L; ++i) {
        const auto sample = [&] { return append_sample(out, plans, points, patch, double(i) / L, double(j) / L); };
        int& slot = grid[size_t(i + (L + 1) * j)];
        if (i == 0 && j == 0) slot = shared.corner(corner[0], sample);
        else if (i == L) slot = shared.corner(corner[1], sample);
        else if (j == L) slot = shared.corner(corner[2], sample);
        else if (j == 0) slot = shared.edge(corner[0], corner[1], i, L, sample);
        else if (i + j == L) slot = shared.edge(corner[1], corner[2], j, L, sample);
        else if (i == 0) slot = shared.edge(corner[2], corner[0], L - j, L, sample);
        else slot = sample();
      }
    const auto at = [&](int i, int j) { return grid[size_t(i + (L + 1) * j)]; };
    for (int j = 0; j < L; ++j)
      for (int i = 0; i + j < L; ++i) {
        out.triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
        if (i + j + 1 < L) out.triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
  }
  return out;
}

}  // namespace

TriangleMesh tessellate(const PlanTable& plans, const std::vector<Dual>& points, int level) {
  if (level < 1 || level > 64) throw usage_error("tessellation level must be 1..64, got " + std::to_string(level));
  if (plans.shape == PatchShape::triangle) return tessellate_triangles(plans, points, level);
  TriangleMesh out;
  const int L = level;
  SharedSamples shared;
  std::vector<int> grid(size_t(L + 1) * size_t(L + 1));
  for (int patch = 0; patch < plans.n_patches(); ++patch) {
    const int* corner = &plans.patch_corner_points[size_t(4 * patch)];
    for (int j = 0; j <= L; ++j)
      for (int i = 0; i <= L; ++i) {
        const auto sample = [&] { return append_sample(out, plans, points, patch, double(i) / L, double(j) / L); };
        int& slot = grid[size_t(i + (L + 1) * j)];
        const bool u_end = i == 0 || i == L, v_end = j == 0 || j == L;
        if (u_end && v_end) {
          slot = shared.corner(corner[i == 0 ? (j == 0 ? 0 : 3) : (j == 0 ? 1 : 2)], sample);
        } else if (u_end || v_end) {
          // Edge k runs from corner k to corner k+1; step s counts from corner k.
          int k, step;
          if (j == 0) k = 0, step = i;
          else if (i == L) k = 1, step = j;
          else if (j == L) k = 2, step = L - i;
          else k = 3, step = L - j;
          slot = shared.edge(corner[k], corner[(k + 1) % 4], step, L, sample);
        } else {
          slot = sample();
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
