#include "core/mesh/sharpness.h"

#include <algorithm>
#include <cmath>

#include "core/support/error.h"
#include "core/mesh/mesh_connectivity.h"

namespace gps {

namespace {
bool before(const EdgeCrease& x, int a, int b) { return x.a < a || (x.a == a && x.b < b); }
}  // namespace

double Sharpness::crease(int a, int b) const {
  if (a > b) std::swap(a, b);
  const auto it = std::lower_bound(creases.begin(), creases.end(), EdgeCrease{a, b, 0.0},
                                   [](const EdgeCrease& x, const EdgeCrease& y) { return before(x, y.a, y.b); });
  return it != creases.end() && it->a == a && it->b == b ? it->sharpness : 0.0;
}

void Sharpness::set_crease(int a, int b, double sharpness) {
  if (a > b) std::swap(a, b);
  const auto it = std::lower_bound(creases.begin(), creases.end(), EdgeCrease{a, b, 0.0},
                                   [](const EdgeCrease& x, const EdgeCrease& y) { return before(x, y.a, y.b); });
  const bool found = it != creases.end() && it->a == a && it->b == b;
  if (sharpness <= 0.0) {
    if (found) creases.erase(it);
  } else if (found) {
    it->sharpness = sharpness;
  } else {
    creases.insert(it, EdgeCrease{a, b, sharpness});
  }
}

void Sharpness::set_corner(int v, double sharpness, int n_vertices) {
  if (sharpness > 0.0 && corners.empty()) corners.assign(size_t(n_vertices), 0.0);
  if (size_t(v) < corners.size()) corners[size_t(v)] = std::max(0.0, sharpness);
  if (sharpness <= 0.0 && std::all_of(corners.begin(), corners.end(), [](double s) { return s <= 0.0; }))
    corners.clear();
}

void Sharpness::normalise() {
  for (auto& c : creases)
    if (c.a > c.b) std::swap(c.a, c.b);
  creases.erase(std::remove_if(creases.begin(), creases.end(), [](const EdgeCrease& c) { return c.sharpness <= 0.0; }),
                creases.end());
  std::sort(creases.begin(), creases.end(), [](const EdgeCrease& x, const EdgeCrease& y) { return before(x, y.a, y.b); });
  if (std::all_of(corners.begin(), corners.end(), [](double s) { return s <= 0.0; })) corners.clear();
}

std::string sharpness_problem(double s) {
  if (!std::isfinite(s)) return "is not finite";
  if (s < 0.0) return "is negative";
  return "";
}

bool CreaseLevel::empty() const {
  return std::all_of(edges.begin(), edges.end(), [](double s) { return s <= 0.0; }) &&
         std::all_of(vertices.begin(), vertices.end(), [](double s) { return s <= 0.0; });
}

CreaseLevel crease_level(const Sharpness& s, const MeshConnectivity& c, int n_vertices) {
  CreaseLevel level;
  level.edges.assign(size_t(c.n_edges()), 0.0);
  level.vertices.assign(size_t(n_vertices), 0.0);
  for (size_t i = 0; i < s.corners.size() && i < size_t(n_vertices); ++i) level.vertices[i] = s.corners[i];
  for (const EdgeCrease& crease : s.creases) {
    if (crease.a < 0 || crease.b >= n_vertices || crease.a >= n_vertices)
      throw Error("crease " + std::to_string(crease.a) + "-" + std::to_string(crease.b) + " names a vertex outside 0.." +
                  std::to_string(n_vertices - 1));
    int edge = -1;
    for (int i = c.vertex_edge_offsets[size_t(crease.a)]; i < c.vertex_edge_offsets[size_t(crease.a) + 1]; ++i)
      if (c.other_vertex(c.vertex_edges[size_t(i)], crease.a) == crease.b) edge = c.vertex_edges[size_t(i)];
    if (edge < 0)
      throw Error("crease " + std::to_string(crease.a) + "-" + std::to_string(crease.b) + " is not an edge of the mesh");
    level.edges[size_t(edge)] = crease.sharpness;
  }
  return level;
}

}  // namespace gps
