#include "core/modelling/mesh_queries.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <set>
#include <string>

#include "core/support/error.h"

namespace gps {

namespace {

using VH = PolyMesh::VertexHandle;
using HH = PolyMesh::HalfedgeHandle;
using FH = PolyMesh::FaceHandle;

void check_vertex(const PolyMesh& m, int v) {
  if (v < 0 || v >= int(m.n_vertices()))
    throw Error("vertex " + std::to_string(v) + " is not in the mesh (" + std::to_string(m.n_vertices()) +
                " vertices)");
}

// One flag per vertex, set for the given vertices (each checked).
std::vector<char> vertex_mask(const PolyMesh& m, const std::vector<int>& vertices) {
  std::vector<char> mask(m.n_vertices(), 0);
  for (int v : vertices) {
    check_vertex(m, v);
    mask[size_t(v)] = 1;
  }
  return mask;
}

std::vector<int> masked(const std::vector<char>& mask) {
  std::vector<int> out;
  for (size_t v = 0; v < mask.size(); ++v)
    if (mask[v]) out.push_back(int(v));
  return out;
}

bool continues(const PolyMesh& m, VH v) { return !m.is_boundary(v) && m.valence(v) == 4; }

// At an interior vertex of valence 4 reached by half-edge h, the half-edge out along the opposite edge.
HH straight_on(const PolyMesh& m, HH h) {
  HH out = m.opposite_halfedge_handle(h);
  for (int k = 0; k < 2; ++k) out = m.next_halfedge_handle(m.opposite_halfedge_handle(out));
  return out;
}

// Walks the edge loop on from half-edge h, appending the vertices reached, until a vertex where it
// cannot continue, or `start`; returns whether it came back to `start`.
bool walk_loop(const PolyMesh& m, HH h, VH start, std::vector<int>& loop) {
  while (true) {
    const VH v = m.to_vertex_handle(h);
    if (v == start) return true;
    loop.push_back(v.idx());
    if (!continues(m, v)) return false;
    h = straight_on(m, h);
  }
}

}  // namespace

std::vector<std::array<int, 2>> edge_loop_edges(const CovarianceMesh& mesh, int a, int b) {
  const PolyMesh& m = mesh.mesh;
  check_vertex(m, a);
  check_vertex(m, b);
  const HH h = m.find_halfedge(VH(a), VH(b));
  if (!h.is_valid()) throw Error("edge " + std::to_string(a) + "–" + std::to_string(b) + " is not in the mesh");
  std::vector<std::array<int, 2>> edges;
  const auto add = [&edges](int u, int w) { edges.push_back({std::min(u, w), std::max(u, w)}); };
  const auto add_path = [&add](const std::vector<int>& path) {
    for (size_t k = 1; k < path.size(); ++k) add(path[k - 1], path[k]);
  };
  if (m.is_boundary(m.edge_handle(h))) {
    const HH first = m.is_boundary(h) ? h : m.opposite_halfedge_handle(h);
    HH g = first;
    do {
      add(m.from_vertex_handle(g).idx(), m.to_vertex_handle(g).idx());
      g = m.next_halfedge_handle(g);
    } while (g != first);
  } else {
    std::vector<int> forward = {a};
    const bool closed = walk_loop(m, h, VH(a), forward);
    add_path(forward);
    if (closed) {
      add(forward.back(), a);
    } else if (continues(m, VH(a))) {
      std::vector<int> backward = {a};
      walk_loop(m, straight_on(m, m.opposite_halfedge_handle(h)), VH(a), backward);
      add_path(backward);
    }
    if (edges.size() == 1) {  // a loop of one edge: the rim of its larger face (a cap's), as Blender does
      const PolyMesh::FaceHandle face = m.face_handle(h), other = m.opposite_face_handle(h);
      for (const HH g : m.fh_range(m.valence(other) > m.valence(face) ? other : face))
        add(m.from_vertex_handle(g).idx(), m.to_vertex_handle(g).idx());
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

std::vector<int> edge_loop(const CovarianceMesh& mesh, int a, int b) {
  std::vector<int> loop;
  for (const auto& [u, w] : edge_loop_edges(mesh, a, b)) loop.insert(loop.end(), {u, w});
  std::sort(loop.begin(), loop.end());
  loop.erase(std::unique(loop.begin(), loop.end()), loop.end());
  return loop;
}

std::vector<int> linked_vertices(const CovarianceMesh& mesh, const std::vector<int>& seeds) {
  const PolyMesh& m = mesh.mesh;
  std::vector<char> seen = vertex_mask(m, seeds);
  std::vector<int> stack = masked(seen);
  while (!stack.empty()) {
    const VH v(stack.back());
    stack.pop_back();
    for (const VH w : m.vv_range(v))
      if (!seen[size_t(w.idx())]) {
        seen[size_t(w.idx())] = 1;
        stack.push_back(w.idx());
      }
  }
  return masked(seen);
}

std::vector<int> grow_selection(const CovarianceMesh& mesh, const std::vector<int>& vertices) {
  const PolyMesh& m = mesh.mesh;
  std::vector<char> grown = vertex_mask(m, vertices);
  for (int v : vertices)
    for (const auto f : m.vf_range(VH(v)))
      for (const VH w : m.fv_range(f)) grown[size_t(w.idx())] = 1;
  return masked(grown);
}

std::vector<int> shrink_selection(const CovarianceMesh& mesh, const std::vector<int>& vertices) {
  const PolyMesh& m = mesh.mesh;
  const std::vector<char> selected = vertex_mask(m, vertices);
  std::vector<char> kept = selected;
  for (int v : vertices)
    for (const auto f : m.vf_range(VH(v)))
      for (const VH w : m.fv_range(f))
        if (!selected[size_t(w.idx())]) kept[size_t(v)] = 0;
  return masked(kept);
}

Vec3 centre_of_vertices(const CovarianceMesh& mesh, const std::vector<int>& vertices) {
  Vec3 sum = Vec3::Zero();
  for (const int v : vertices) sum += mesh.mean(size_t(v));
  return vertices.empty() ? sum : Vec3(sum / double(vertices.size()));
}

std::vector<int> faces_within(const CovarianceMesh& mesh, const std::vector<int>& vertices) {
  const PolyMesh& m = mesh.mesh;
  const std::vector<char> selected = vertex_mask(m, vertices);
  std::vector<int> faces;
  for (const auto f : m.faces()) {
    bool all = true;
    for (const VH v : m.fv_range(f)) all = all && selected[size_t(v.idx())];
    if (all) faces.push_back(f.idx());
  }
  return faces;
}

std::vector<std::array<int, 2>> edges_within(const CovarianceMesh& mesh, const std::vector<int>& vertices) {
  const PolyMesh& m = mesh.mesh;
  const std::vector<char> selected = vertex_mask(m, vertices);
  std::vector<std::array<int, 2>> edges;
  for (int v : masked(selected))
    for (const VH w : m.vv_range(VH(v)))
      if (w.idx() > v && selected[size_t(w.idx())]) edges.push_back({v, w.idx()});
  std::sort(edges.begin(), edges.end());
  return edges;
}

std::vector<int> chain_of_edges(const std::vector<std::array<int, 2>>& edges) {
  if (edges.empty()) throw Error("no edges: select a chain of edges (both ends of each)");
  std::map<int, std::vector<int>> next;  // each vertex's neighbours along the edges
  for (const auto& [a, b] : edges) {
    if (a == b) throw Error("vertex " + std::to_string(a) + " is joined to itself");
    next[a].push_back(b);
    next[b].push_back(a);
  }
  int start = next.begin()->first, end = -1;  // a closed chain starts at its smallest vertex
  for (const auto& [v, neighbours] : next) {
    if (neighbours.size() > 2) throw Error("the edges branch at vertex " + std::to_string(v) + ": select one chain");
    if (neighbours.size() == 1 && end < 0) end = v;  // the lower-numbered end of an open chain
  }
  if (end >= 0) start = end;
  std::vector<int> chain{start};
  int previous = -1, at = start;
  for (size_t k = 0; k < edges.size(); ++k) {
    const std::vector<int>& n = next[at];
    const int step = n[0] != previous ? n[0] : n.size() > 1 ? n[1] : -1;
    if (step < 0) break;
    previous = at;
    at = step;
    chain.push_back(at);
  }
  if (chain.size() != edges.size() + 1) throw Error("the selected edges are not one connected chain");
  return chain;
}

namespace {

// Dijkstra's shortest path over `n` nodes from `from` to `to`: `steps(node, step)` calls step(next,
// length) for each node one step away. Of paths equally short, the one through lower-numbered nodes.
// Empty where none joins them.
template <class Steps>
std::vector<int> dijkstra_path(int n, int from, int to, const Steps& steps) {
  std::vector<double> distance(size_t(n), std::numeric_limits<double>::infinity());
  std::vector<int> previous(size_t(n), -1);
  using Entry = std::pair<double, int>;  // (distance, node): the smallest first, then the lower node
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  distance[size_t(from)] = 0.0;
  queue.push({0.0, from});
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > distance[size_t(v)]) continue;
    if (v == to) break;
    steps(v, [&, d = d, v = v](int w, double length) {
      if (d + length < distance[size_t(w)]) {
        distance[size_t(w)] = d + length;
        previous[size_t(w)] = v;
        queue.push({d + length, w});
      }
    });
  }
  if (from != to && previous[size_t(to)] < 0) return {};
  std::vector<int> path{to};
  while (path.back() != from) path.push_back(previous[size_t(path.back())]);
  std::reverse(path.begin(), path.end());
  return path;
}

}  // namespace

std::vector<int> shortest_path(const CovarianceMesh& mesh, int from, int to) {
  const PolyMesh& m = mesh.mesh;
  const int n = int(m.n_vertices());
  for (const int v : {from, to})
    if (v < 0 || v >= n) throw Error("vertex " + std::to_string(v) + " is not in the mesh");
  std::vector<int> path = dijkstra_path(n, from, to, [&](int v, const auto& step) {
    for (const VH w : m.vv_range(VH(v))) step(w.idx(), (mesh.mean(size_t(w.idx())) - mesh.mean(size_t(v))).norm());
  });
  if (path.empty()) throw Error("no edges join vertex " + std::to_string(from) + " to vertex " + std::to_string(to));
  return path;
}

std::vector<int> shortest_face_path(const CovarianceMesh& mesh, int from, int to, const std::vector<char>* hidden) {
  const PolyMesh& m = mesh.mesh;
  const int n = int(m.n_faces());
  for (const int f : {from, to})
    if (f < 0 || f >= n) throw Error("face " + std::to_string(f) + " is not in the mesh");
  const auto centre = [&](int f) {
    Vec3 sum = Vec3::Zero();
    int corners = 0;
    for (const VH v : m.fv_range(FH(f))) sum += mesh.mean(size_t(v.idx())), ++corners;
    return Vec3(sum / double(corners));
  };
  std::vector<int> path = dijkstra_path(n, from, to, [&](int f, const auto& step) {
    const Vec3 here = centre(f);
    for (const FH g : m.ff_range(FH(f)))
      if (!hidden || size_t(g.idx()) >= hidden->size() || !(*hidden)[size_t(g.idx())])
        step(g.idx(), (centre(g.idx()) - here).norm());
  });
  if (path.empty()) throw Error("no edges join face " + std::to_string(from) + " to face " + std::to_string(to));
  return path;
}

std::vector<int> face_loop(const CovarianceMesh& mesh, int a, int b) {
  const PolyMesh& m = mesh.mesh;
  check_vertex(m, a);
  check_vertex(m, b);
  const HH start = m.find_halfedge(VH(a), VH(b));
  if (!start.is_valid()) throw Error("edge " + std::to_string(a) + "–" + std::to_string(b) + " is not in the mesh");
  std::set<int> faces;
  for (const HH first : {start, m.opposite_halfedge_handle(start)}) {
    HH h = first;
    while (true) {
      const FH f = m.face_handle(h);
      if (!f.is_valid() || m.valence(f) != 4 || !faces.insert(f.idx()).second) break;
      h = m.opposite_halfedge_handle(m.next_halfedge_handle(m.next_halfedge_handle(h)));
    }
  }
  return {faces.begin(), faces.end()};
}

std::vector<std::vector<int>> boundary_loops(const CovarianceMesh& mesh) {
  const PolyMesh& m = mesh.mesh;
  std::vector<char> visited(m.n_halfedges(), 0);
  std::vector<std::vector<int>> loops;
  for (const VH v : m.vertices()) {
    const HH first = m.halfedge_handle(v);
    if (!first.is_valid() || !m.is_boundary(first) || visited[size_t(first.idx())]) continue;
    // The boundary half-edges (no face) run against the faces' edges: follow them, then reverse.
    std::vector<int> loop;
    HH h = first;
    do {
      visited[size_t(h.idx())] = 1;
      loop.push_back(m.from_vertex_handle(h).idx());
      h = m.next_halfedge_handle(h);
    } while (h != first);
    std::reverse(loop.begin() + 1, loop.end());
    loops.push_back(std::move(loop));
  }
  return loops;
}

}  // namespace gps
