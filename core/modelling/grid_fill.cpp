#include "core/modelling/grid_fill.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <Eigen/Geometry>

#include "core/modelling/mesh_queries.h"
#include "core/modelling/operation_words.h"
#include "core/support/error.h"

namespace gps {

namespace {

// Two corner scores closer than this (radians) count as equal: Blender's tolerance.
constexpr double kEqualTurn = 1e-3;

// How much the loop turns at ring[i]: |π − the angle between its edges to its two neighbours|.
double turn_at(const MeshArrays& a, const std::vector<int>& ring, size_t i) {
  const size_t n = ring.size();
  const Vec3 p = a.means[size_t(ring[i])];
  const Vec3 d0 = a.means[size_t(ring[(i + n - 1) % n])] - p, d1 = a.means[size_t(ring[(i + 1) % n])] - p;
  return std::abs(M_PI - std::atan2(d0.cross(d1).norm(), d0.dot(d1)));
}

// Blender's calculated span for a ring starting at its first corner: the ring index of the vertex
// that turns most, the first corner and the vertex opposite it left out, where it turns more than the
// least of the rest; else n/4.
int calculated_span(const MeshArrays& a, const std::vector<int>& ring) {
  const size_t n = ring.size(), half = n / 2;
  std::vector<double> score(n, 0.0);
  for (size_t i = 1; i < n; ++i)
    if (i != half) score[i] = turn_at(a, ring, i);
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](size_t x, size_t y) { return score[x] > score[y]; });
  return score[order[0]] - score[order[n - 3]] > kEqualTurn ? int(order[0]) : int(n / 4);
}

}  // namespace

Modelled grid_fill(const CovarianceMesh& mesh, const std::vector<int>& loop, int span, int offset) {
  MeshArrays a = arrays_of(mesh);
  const int n = int(loop.size()), half = n / 2;
  if (n < 4) throw Error("a grid fill needs a loop of at least 4 vertices (" + std::to_string(n) + " given)");
  if (n % 2 != 0)
    throw Error("a grid fill needs an even number of vertices around the loop (" + std::to_string(n) + " given)");
  const std::vector<int> sorted = sorted_vertices(a, loop);
  if (int(sorted.size()) != n) {
    std::vector<int> seen = loop;
    std::sort(seen.begin(), seen.end());
    throw Error("vertex " + std::to_string(*std::adjacent_find(seen.begin(), seen.end())) + " is listed twice");
  }
  if (span != 0 && (span < 1 || span > half - 1))
    throw Error("span " + std::to_string(span) + " leaves no room in a loop of " + std::to_string(n) +
                " vertices (from 1 to " + std::to_string(half - 1) + ")");

  // The ring runs along the loop's faces' boundary half-edges (each edge has a face one way only).
  const DirectedEdges edges(mesh);
  int along = 0;
  for (int k = 0; k < n; ++k) {
    const int u = loop[size_t(k)], w = loop[size_t((k + 1) % n)];
    const bool forward = edges.count(directed_key(u, w)) != 0, backward = edges.count(directed_key(w, u)) != 0;
    if (forward == backward)
      throw Error(edge_name(u, w) + (forward ? " has a face on both sides" : " is not an edge of the mesh") +
                  ": a grid fill needs a boundary loop");
    along += forward;
  }
  if (along != 0 && along != n)
    throw Error("the loop's edges are on faces that run both ways: it is not one hole's boundary");
  std::vector<int> ring = loop;
  if (along == 0) std::reverse(ring.begin(), ring.end());

  size_t first = 0;  // the first of the vertices that turn most (within the tolerance)
  for (size_t i = 1; i < ring.size(); ++i)
    if (turn_at(a, ring, i) > turn_at(a, ring, first) + kEqualTurn) first = i;
  std::rotate(ring.begin(), ring.begin() + long((first + size_t(((offset % n) + n) % n)) % size_t(n)), ring.end());
  int start = 0;  // the ring index of the grid's corner (0, span)
  if (span == 0) {
    span = calculated_span(a, ring);
    if (span > half) span = n - span, start = half - span;  // the second corner counted back from the first
  }

  // The grid's vertices by (x, y): the ring around its border, from (0, 0) along y = 0 and up x = last.
  const int columns = half - span + 1, rows = span + 1;
  std::vector<int> grid(size_t(columns * rows), -1);
  const auto at = [&](int x, int y) -> int& { return grid[size_t(y * columns + x)]; };
  const auto ring_at = [&](int i) { return ring[size_t(((i % n) + n) % n)]; };
  for (int x = 0; x < columns; ++x) at(x, 0) = ring_at(start + span + x);
  for (int y = 0; y < rows; ++y) at(columns - 1, y) = ring_at(start + half + y);
  for (int x = 0; x < columns; ++x) at(x, rows - 1) = ring_at(start + half + span + (columns - 1 - x));
  for (int y = 0; y < rows; ++y) at(0, y) = ring_at(start + span - y);

  // Inner vertices on the discrete Coons patch (Coons 1967; Farin, Curves and Surfaces for CAGD §22.4).
  for (int y = 1; y + 1 < rows; ++y)
    for (int x = 1; x + 1 < columns; ++x) {
      const double u = double(x) / (columns - 1), v = double(y) / (rows - 1);
      const int bottom = at(x, 0), top = at(x, rows - 1), left = at(0, y), right = at(columns - 1, y);
      const auto p = [&](int vertex) { return a.means[size_t(vertex)]; };
      const Vec3 mean = (1 - v) * p(bottom) + v * p(top) + (1 - u) * p(left) + u * p(right) -
                        ((1 - u) * (1 - v) * p(at(0, 0)) + u * (1 - v) * p(at(columns - 1, 0)) +
                         (1 - u) * v * p(at(0, rows - 1)) + u * v * p(at(columns - 1, rows - 1)));
      const Gaussian ruled =
          blend_gaussians(a, {{bottom, (1 - v) / 2}, {top, v / 2}, {left, (1 - u) / 2}, {right, u / 2}});
      at(x, y) = a.add_vertex({mean, ruled.covariance});
    }

  // Clockwise in (x, y), against the ring, which runs anticlockwise: each quad's edge on the ring runs
  // opposite to the loop's face there.
  const bool triangles = all_triangles(a);
  const int first_face = a.n_faces();
  for (int y = 0; y + 1 < rows; ++y)
    for (int x = 0; x + 1 < columns; ++x) a.faces.push_back({at(x, y), at(x, y + 1), at(x + 1, y + 1), at(x + 1, y)});
  if (triangles) split_new_quads(a, first_face);

  std::vector<int> selection = grid;
  std::sort(selection.begin(), selection.end());
  const int added = (columns - 2) * (rows - 2);
  Modelled out = modelled(mesh, std::move(a), selection);
  out.summary = "grid-filled a loop of " + std::to_string(n) + " vertices with " + std::to_string(columns - 1) + " × " +
                std::to_string(rows - 1) + " quads: " + count_of(size_t(added), "vertex", "vertices") + " added" +
                (triangles ? " (split into triangles)" : "");
  return out;
}

Modelled grid_fill_selected(const CovarianceMesh& mesh, const std::vector<int>& vertices, int span, int offset) {
  const std::vector<int> selected = sorted_vertices(size_t(mesh.n_vertices()), vertices);
  for (const std::vector<int>& loop : boundary_loops(mesh)) {
    std::vector<int> members = loop;
    std::sort(members.begin(), members.end());
    if (members == selected) return grid_fill(mesh, loop, span, offset);
  }
  throw Error("select one whole boundary loop (the " +
              count_of(selected.size(), "selected vertex is", "selected vertices are") + " not one)");
}

}  // namespace gps
