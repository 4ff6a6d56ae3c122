#include "core/evaluation/tessellator.h"

#include <algorithm>
#include <array>
#include <map>
#include <numeric>

#include "core/support/error.h"
#include "core/evaluation/patch_eval.h"
#include "core/evaluation/tessellation_size.h"

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
int append_sample(TriangleMesh& out, const PatchPlans& plans, const std::vector<Dual>& points, int patch, double u,
                  double v) {
  const auto s = evaluate_patch(plans, points, patch, u, v);
  if (!s) throw Error("patch " + std::to_string(patch) + " left the cone of positive definite matrices");
  out.positions.push_back(s->position);
  out.normals.push_back(s->normal);
  return int(out.positions.size()) - 1;
}

// (u, v) of the point at parameter t along patch edge k (edge k runs from corner k to corner k+1).
std::array<double, 2> edge_uv(int k, double t) {
  switch (k) {
    case 0:
      return {t, 0.0};
    case 1:
      return {1.0, t};
    case 2:
      return {1.0 - t, 1.0};
    default:
      return {0.0, 1.0 - t};
  }
}

// Samples on patch boundaries are shared between patches by a key: a mesh vertex (the corner
// point: {point, −1, 0, 0}) or a reduced fraction num/den along the mesh edge between two points
// (lower point first), so a quad's edge sample and the corner of a half-size patch beside it meet.
using BoundaryKey = std::array<int, 4>;

BoundaryKey boundary_key(const PatchEdge& e, int step, int steps) {
  int num = step, den = steps;
  if (e.part == PatchEdgePart::first_half) den *= 2;
  if (e.part == PatchEdgePart::second_half) num += steps, den *= 2;
  int a = e.from, b = e.to;
  if (a > b) std::swap(a, b), num = den - num;
  if (num == 0) return {a, -1, 0, 0};
  if (num == den) return {b, -1, 0, 0};
  const int g = std::gcd(num, den);
  return {a, b, num / g, den / g};
}

// Tells `progress` that `patch` patches of `patches` are done, on every hundredth of them.
void report_patches(const ProgressReport& progress, int patch, int patches) {
  if (progress && patch % std::max(1, patches / 100) == 0 && !progress(double(patch) / patches)) throw Cancelled();
}

// Triangle patches: the points (i, j)/L, i + j ≤ L, of each patch's (u, v) triangle.
TriangleMesh tessellate_triangles(const PatchPlans& plans, const std::vector<Dual>& points, int L,
                                  const ProgressReport& progress) {
  TriangleMesh out;
  SharedSamples shared;
  std::vector<int> grid(size_t(L + 1) * size_t(L + 1), -1);
  for (int patch = 0; patch < plans.n_patches(); ++patch) {
    report_patches(progress, patch, plans.n_patches());
    const int* corner = &plans.patch_corner_points[size_t(3 * patch)];
    for (int j = 0; j <= L; ++j)
      for (int i = 0; i + j <= L; ++i) {
        const auto sample = [&] { return append_sample(out, plans, points, patch, double(i) / L, double(j) / L); };
        int& slot = grid[size_t(i + (L + 1) * j)];
        if (i == 0 && j == 0)
          slot = shared.corner(corner[0], sample);
        else if (i == L)
          slot = shared.corner(corner[1], sample);
        else if (j == L)
          slot = shared.corner(corner[2], sample);
        else if (j == 0)
          slot = shared.edge(corner[0], corner[1], i, L, sample);
        else if (i + j == L)
          slot = shared.edge(corner[1], corner[2], j, L, sample);
        else if (i == 0)
          slot = shared.edge(corner[2], corner[0], L - j, L, sample);
        else
          slot = sample();
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

namespace {

TriangleMesh tessellate_patches(const PatchPlans& plans, const std::vector<Dual>& points, int level,
                                const ProgressReport& progress) {
  if (level < 1 || level > 64) throw usage_error("tessellation level must be 1..64, got " + std::to_string(level));
  check_output_size(tessellation_size(plans, level),
                    "tessellating " + std::to_string(plans.n_patches()) + " patches at level " + std::to_string(level),
                    "triangles", "use a lower level");
  if (plans.shape == PatchShape::triangle) return tessellate_triangles(plans, points, level, progress);
  TriangleMesh out;
  // Level L is L segments along an edge of the mesh, as on the GPU (shaders/patch_tesc.glsl): a
  // split face's half-size patches take L/2 and a quad's edge beside two of them L; for an odd L,
  // one more: the half-size patches take (L + 1)/2 and the quad's edge beside them L + 1, joined to
  // its L×L grid.
  const int beside_halves = level + level % 2;
  std::map<BoundaryKey, int> shared;
  std::vector<int> grid;
  for (int patch = 0; patch < plans.n_patches(); ++patch) {
    report_patches(progress, patch, plans.n_patches());
    const auto sample = [&](double u, double v) { return append_sample(out, plans, points, patch, u, v); };
    PatchEdge edges[4];
    for (int k = 0; k < 4; ++k) edges[k] = patch_edge(plans, patch, k);
    const int L = half_size_patch(plans, patch) ? beside_halves / 2 : level;  // the patch's grid
    int steps[4];  // samples along each edge: L, or L + 1 where two half-size patches of an odd level lie beside it
    for (int k = 0; k < 4; ++k) steps[k] = edges[k].part == PatchEdgePart::whole_beside_halves ? beside_halves : L;
    // The edge sample that stands for grid step `step` along edge k: the first at or past it.
    const auto snapped = [&](int k, int step) { return (step * steps[k] + L - 1) / L; };
    grid.assign(size_t(L + 1) * size_t(L + 1), -1);
    const auto boundary_sample = [&](int k, int step) {
      const auto [it, added] = shared.try_emplace(boundary_key(edges[k], step, steps[k]), -1);
      if (added) {
        const auto [u, v] = edge_uv(k, double(step) / steps[k]);
        it->second = sample(u, v);
      }
      return it->second;
    };
    // Grid point (i, j) on the boundary: on edge k at step `step` of L (a corner belongs to the
    // edge it starts, unless it is the midpoint where the previous, half-size edge ends).
    const auto grid_sample = [&](int i, int j) {
      const bool u_end = i == 0 || i == L, v_end = j == 0 || j == L;
      if (!u_end && !v_end) return sample(double(i) / L, double(j) / L);
      int k, step;
      if (j == 0 && i < L)
        k = 0, step = i;
      else if (i == L && j < L)
        k = 1, step = j;
      else if (j == L && i > 0)
        k = 2, step = L - i;
      else
        k = 3, step = L - j;
      const int previous = (k + 3) % 4;
      if (step == 0 && edges[previous].part == PatchEdgePart::first_half)
        return boundary_sample(previous, steps[previous]);
      return boundary_sample(k, snapped(k, step));
    };
    for (int j = 0; j <= L; ++j)
      for (int i = 0; i <= L; ++i) grid[size_t(i + (L + 1) * j)] = grid_sample(i, j);
    for (int j = 0; j < L; ++j)
      for (int i = 0; i < L; ++i) {
        const int a = grid[size_t(i + (L + 1) * j)], b = grid[size_t(i + 1 + (L + 1) * j)];
        const int c = grid[size_t(i + 1 + (L + 1) * (j + 1))], d = grid[size_t(i + (L + 1) * (j + 1))];
        // The cell's outline, counter-clockwise, with the samples of a finer edge between its corners.
        std::vector<int> outline = {a};
        const auto side = [&](int k, int step, bool on_edge, int next) {
          if (on_edge)
            for (int s = snapped(k, step) + 1; s < snapped(k, step + 1); ++s) outline.push_back(boundary_sample(k, s));
          outline.push_back(next);
        };
        side(0, i, j == 0, b);
        side(1, j, i + 1 == L, c);
        side(2, L - i - 1, j + 1 == L, d);
        side(3, L - j - 1, i == 0, a);
        outline.pop_back();
        if (outline.size() == 4) {
          out.triangles.push_back({a, b, c});
          out.triangles.push_back({a, c, d});
          continue;
        }
        // A fan around the cell's centre joins the finer edge to the grid.
        const int centre = sample((i + 0.5) / L, (j + 0.5) / L);
        for (size_t m = 0; m < outline.size(); ++m)
          out.triangles.push_back({centre, outline[m], outline[(m + 1) % outline.size()]});
      }
  }
  return out;
}

}  // namespace

TriangleMesh tessellate(const PatchPlans& plans, const std::vector<Dual>& points, int level,
                        const ProgressReport& progress) {
  TriangleMesh out = tessellate_patches(plans, points, level, progress);
  fill_missing_normals(out);  // where the surface has no tangent plane (a degenerate point)
  return out;
}

}  // namespace gps
