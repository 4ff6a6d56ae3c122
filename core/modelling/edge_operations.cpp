#include "core/modelling/edge_operations.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "core/support/error.h"
#include "core/modelling/operation_words.h"

namespace gps {

namespace {

void check_edge(const MeshArrays& arrays, const DirectedEdges& edges, int a, int b) {
  check_vertex(arrays, a);
  check_vertex(arrays, b);
  if (!has_edge(edges, a, b)) throw Error(edge_name(a, b) + " is not in the mesh");
}

}  // namespace

Modelled split_edge(const CovarianceMesh& mesh, int a, int b, double t) {
  MeshArrays arrays = arrays_of(mesh);
  const DirectedEdges edges(mesh);
  check_edge(arrays, edges, a, b);
  if (!(t > 0 && t < 1)) {
    std::ostringstream value;
    value << t;
    throw Error("the split fraction must be in (0, 1), got " + value.str());
  }
  const int m = add_edge_vertex(arrays, a, b, t);
  std::vector<std::pair<int, int>> beside = {face_of_edge(edges, a, b), face_of_edge(edges, b, a)};
  std::sort(beside.begin(), beside.end());
  int added = 0;
  for (const auto& [f, k] : beside) {
    if (f < 0) continue;
    std::vector<int>& c = arrays.faces[size_t(f)];
    const int u = c[size_t(k)], v = c[size_t(k + 1) % c.size()];
    if (c.size() == 3) {
      const int w = c[size_t(k + 2) % 3];
      const std::vector<int> at_u = {u, m, w}, at_v = {m, v, w};
      c = u == a ? at_u : at_v;
      arrays.faces.push_back(u == a ? at_v : at_u);
      ++added;
    } else {
      c.insert(c.begin() + k + 1, m);
    }
  }
  Modelled out = modelled(mesh, std::move(arrays), {m});
  out.summary = "split " + edge_name(a, b) + ": 1 vertex, " + std::to_string(added) +
                (added == 1 ? " face added" : " faces added");
  return out;
}

int add_edge_vertex(MeshArrays& arrays, int a, int b, double t) {
  const int m = arrays.add_vertex(blend_gaussians(arrays, {{a, 1 - t}, {b, t}}));
  split_crease(arrays, a, b, m);
  return m;
}

Modelled flip_edge(const CovarianceMesh& mesh, int a, int b) {
  MeshArrays arrays = arrays_of(mesh);
  const DirectedEdges edges(mesh);
  check_edge(arrays, edges, a, b);
  if (is_boundary_edge(edges, a, b)) throw Error(edge_name(a, b) + " is on the boundary");
  const auto [f, k] = face_of_edge(edges, a, b);  // [a, b, c]
  const auto [g, l] = face_of_edge(edges, b, a);  // [b, a, d]
  for (const int face : {std::min(f, g), std::max(f, g)})
    if (arrays.faces[size_t(face)].size() != 3)
      throw Error("face " + std::to_string(face) + " beside " + edge_name(a, b) + " is not a triangle");
  const int c = arrays.faces[size_t(f)][size_t(k + 2) % 3], d = arrays.faces[size_t(g)][size_t(l + 2) % 3];
  if (c == d) throw Error("flipping " + edge_name(a, b) + " would make a degenerate face");
  if (has_edge(edges, c, d))
    throw Error("flipping " + edge_name(a, b) + " would duplicate " + edge_name(std::min(c, d), std::max(c, d)));
  arrays.faces[size_t(f)] = {c, a, d};
  arrays.faces[size_t(g)] = {d, b, c};
  Modelled out = modelled(mesh, std::move(arrays), {std::min(c, d), std::max(c, d)});
  out.summary = "flipped " + edge_name(a, b) + " to " + edge_name(std::min(c, d), std::max(c, d));
  return out;
}

}  // namespace gps
