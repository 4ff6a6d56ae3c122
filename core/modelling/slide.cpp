#include "core/modelling/slide.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <unordered_set>

#include "core/support/error.h"
#include "core/modelling/operation_words.h"

namespace gps {

namespace {

void check_edge(const MeshArrays& arrays, const DirectedEdges& edges, int a, int b) {
  check_vertex(arrays, a);
  check_vertex(arrays, b);
  if (a == b || !has_edge(edges, a, b)) throw Error(edge_name(a, b) + " is not in the mesh");
}

// The Gaussian a fraction t along the edge from v to u (see slide.h): the ends as they are.
Gaussian slid_gaussian(const MeshArrays& arrays, int v, int u, double t) {
  if (t == 0) return arrays.gaussian(v);
  if (t == 1) return arrays.gaussian(u);
  return blend_gaussians(arrays, {{v, 1 - t}, {u, t}});
}

// A loop or chain of selected edges: path[i] → path[i + 1] (and back to path[0] when closed).
struct SelectedPath {
  std::vector<int> path;
  bool closed = false;
};

// The selected edges as loops and chains, each run in the direction of its first listed edge.
std::vector<SelectedPath> selected_paths(const std::vector<std::array<int, 2>>& edges,
                                         const std::unordered_map<int, std::vector<int>>& neighbours) {
  std::unordered_set<int> visited;
  std::vector<SelectedPath> paths;
  const auto other = [&](int v, int from) {
    for (int w : neighbours.at(v))
      if (w != from) return w;
    return -1;
  };
  for (const auto& [a, b] : edges) {
    if (visited.count(a)) continue;
    SelectedPath p{{a, b}, false};
    for (int prev = a, v = b, next = other(b, a); next >= 0; prev = v, v = next, next = other(v, prev)) {
      if (next == a) {
        p.closed = true;
        break;
      }
      p.path.push_back(next);
    }
    if (!p.closed) {
      std::vector<int> back;
      for (int prev = b, v = a, next = other(a, b); next >= 0; prev = v, v = next, next = other(v, prev))
        back.push_back(next);
      p.path.insert(p.path.begin(), back.rbegin(), back.rend());
    }
    visited.insert(p.path.begin(), p.path.end());
    paths.push_back(std::move(p));
  }
  return paths;
}

// Where each vertex of a path slides: the one edge that leaves the selection, on the side of the
// faces holding path[i] → path[i + 1] (`left`) or path[i + 1] → path[i].
std::vector<int> slide_targets(const MeshArrays& arrays, const DirectedEdges& edges,
                               const std::unordered_set<uint64_t>& selected, const SelectedPath& p, bool left) {
  const size_t n = p.path.size(), links = p.closed ? n : n - 1;
  std::vector<std::vector<int>> found(n);
  const auto offer = [&](size_t i, int u) {
    const int v = p.path[i];
    if (!selected.count(edge_key(v, u)) && std::find(found[i].begin(), found[i].end(), u) == found[i].end())
      found[i].push_back(u);
  };
  for (size_t i = 0; i < links; ++i) {
    const size_t j = (i + 1) % n;
    const int v = p.path[i], w = p.path[j];
    const auto [f, corner] = edges.place(left ? directed_key(v, w) : directed_key(w, v));
    if (f < 0) continue;
    const std::vector<int>& face = arrays.faces[size_t(f)];
    const size_t m = face.size(), k = size_t(corner);  // face[k] is v (left) or w
    const auto at = [&](size_t c) { return face[c % m]; };
    if (left) {
      offer(i, at(k + m - 1));  // v's other edge in the face, before it
      offer(j, at(k + 2));      // w's, after it
    } else {
      offer(i, at(k + 2));
      offer(j, at(k + m - 1));
    }
  }
  std::vector<int> target(n);
  for (size_t i = 0; i < n; ++i) {
    const std::string vertex = "vertex " + std::to_string(p.path[i]);
    if (found[i].empty())
      throw Error(vertex + " has no edge leaving the selection on the side the factor picks (a boundary there)");
    if (found[i].size() > 1)
      throw Error(vertex + " has " + std::to_string(found[i].size()) +
                  " edges leaving the selection on the side the factor picks (edges to " + std::to_string(found[i][0]) +
                  " and " + std::to_string(found[i][1]) + "): slide needs one");
    target[i] = found[i][0];
  }
  return target;
}

}  // namespace

Modelled edge_slide(const CovarianceMesh& mesh, const std::vector<std::array<int, 2>>& edges, double factor,
                    bool even) {
  MeshArrays arrays = arrays_of(mesh);
  const MeshArrays& original = arrays;  // read for every path before any vertex moves
  const DirectedEdges directed(mesh);
  if (edges.empty()) throw Error("no edges to slide");
  if (!(std::abs(factor) <= 1)) throw usage_error("the slide factor must be in [-1, 1], got " + short_number(factor));
  std::unordered_set<uint64_t> selected;
  std::unordered_map<int, std::vector<int>> neighbours;
  for (const auto& [a, b] : edges) {
    check_edge(original, directed, a, b);
    if (!selected.insert(edge_key(a, b)).second) continue;
    for (const auto& [v, w] : {std::pair<int, int>(a, b), std::pair<int, int>(b, a)}) {
      std::vector<int>& n = neighbours[v];
      n.push_back(w);
      if (n.size() > 2)
        throw Error("vertex " + std::to_string(v) + " is on " + std::to_string(n.size()) +
                    " selected edges: slide needs loops or chains");
    }
  }
  const std::vector<SelectedPath> paths = selected_paths(edges, neighbours);
  std::vector<int> moved;
  std::vector<Gaussian> slid;
  for (const SelectedPath& p : paths) {
    moved.insert(moved.end(), p.path.begin(), p.path.end());
    if (factor == 0) continue;
    const std::vector<int> target = slide_targets(original, directed, selected, p, factor > 0);
    std::vector<double> length(p.path.size());
    for (size_t i = 0; i < p.path.size(); ++i)
      length[i] = (original.means[size_t(target[i])] - original.means[size_t(p.path[i])]).norm();
    const double shortest = *std::min_element(length.begin(), length.end());
    for (size_t i = 0; i < p.path.size(); ++i) {
      const double t = !even          ? std::abs(factor)
                       : shortest > 0 ? std::min(1.0, std::abs(factor) * shortest / length[i])
                                      : 0.0;
      slid.push_back(slid_gaussian(original, p.path[i], target[i], t));
    }
  }
  for (size_t i = 0; i < slid.size(); ++i) {
    arrays.means[size_t(moved[i])] = slid[i].mean;
    arrays.covariances[size_t(moved[i])] = slid[i].covariance;
  }
  std::sort(moved.begin(), moved.end());
  Modelled out = modelled(mesh, std::move(arrays), moved);
  out.summary = "slid " + count_of(moved.size(), "vertex", "vertices") + " of " +
                count_of(selected.size(), "edge", "edges") + " by " + short_number(factor) + (even ? " (even)" : "");
  return out;
}

Modelled vertex_slide(const CovarianceMesh& mesh, int vertex, int toward, double factor) {
  MeshArrays a = arrays_of(mesh);
  check_edge(a, DirectedEdges(mesh), vertex, toward);
  if (!(factor >= 0 && factor <= 1))
    throw usage_error("the slide factor must be in [0, 1], got " + short_number(factor));
  const Gaussian g = slid_gaussian(a, vertex, toward, factor);
  a.means[size_t(vertex)] = g.mean;
  a.covariances[size_t(vertex)] = g.covariance;
  Modelled out = modelled(mesh, std::move(a), {vertex});
  out.summary = "slid vertex " + std::to_string(vertex) + " " + short_number(factor) + " of the way along " +
                edge_name(vertex, toward);
  return out;
}

}  // namespace gps
