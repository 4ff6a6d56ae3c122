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

void check_vertex(const CovarianceMesh& m, int v) {
  if (v < 0 || v >= int(m.n_vertices()))
    throw Error("vertex " + std::to_string(v) + " is not in the mesh (" + std::to_string(m.n_vertices()) +
                " vertices)");
}

// One flag per vertex, set for the given vertices (each checked).
std::vector<char> vertex_mask(const CovarianceMesh& m, const std::vector<int>& vertices) {
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

// Calls visit(w) for each vertex w joined to v by an edge (in edge order).
template <class Visit>
void for_each_neighbour(const MeshConnectivity& c, int v, const Visit& visit) {
  for (int i = c.vertex_edge_offsets[size_t(v)]; i < c.vertex_edge_offsets[size_t(v) + 1]; ++i)
    visit(c.other_vertex(c.vertex_edges[size_t(i)], v));
}

// Calls visit(f) for each face at v (in face order).
template <class Visit>
void for_each_face_at(const MeshConnectivity& c, int v, const Visit& visit) {
  for (int i = c.vertex_face_offsets[size_t(v)]; i < c.vertex_face_offsets[size_t(v) + 1]; ++i)
    visit(c.vertex_faces[size_t(i)]);
}

// The corner running the half-edge a → b (a's corner in the face that has b after a), or −1 where
// no face runs the edge that way.
int corner_from_to(const CovarianceMesh& m, const CornerLinks& links, int a, int b) {
  const PolygonTopology& t = m.topology();
  const MeshConnectivity& c = m.connectivity();
  for (int i = c.vertex_face_offsets[size_t(a)]; i < c.vertex_face_offsets[size_t(a) + 1]; ++i) {
    const int k = t.offsets[size_t(c.vertex_faces[size_t(i)])] + c.vertex_face_corners[size_t(i)];
    if (t.verts[size_t(links.next(t, k))] == b) return k;
  }
  return -1;
}

bool continues(const CovarianceMesh& m, int v) { return !m.is_boundary_vertex(size_t(v)) && m.valence(size_t(v)) == 4; }

// At an interior vertex of valence 4 reached by the half-edge of corner h, the corner running out
// along the opposite edge (two faces on around the vertex).
int straight_on(const CovarianceMesh& m, const CornerLinks& links, int h) {
  const PolygonTopology& t = m.topology();
  return links.next(t, links.twins[size_t(links.next(t, h))]);
}

// Walks the edge loop on from the half-edge of corner h, appending the vertices reached, until a
// vertex where it cannot continue, or `start`; returns whether it came back to `start`.
bool walk_loop(const CovarianceMesh& m, const CornerLinks& links, int h, int start, std::vector<int>& loop) {
  const PolygonTopology& t = m.topology();
  while (true) {
    const int v = t.verts[size_t(links.next(t, h))];
    if (v == start) return true;
    loop.push_back(v);
    if (!continues(m, v)) return false;
    h = straight_on(m, links, h);
  }
}

}  // namespace

std::vector<std::array<int, 2>> edge_loop_edges(const CovarianceMesh& mesh, int a, int b) {
  check_vertex(mesh, a);
  check_vertex(mesh, b);
  const int e = a == b ? -1 : mesh.find_edge(a, b);
  if (e < 0) throw Error("edge " + std::to_string(a) + "–" + std::to_string(b) + " is not in the mesh");
  const PolygonTopology& t = mesh.topology();
  const MeshConnectivity& c = mesh.connectivity();
  std::vector<std::array<int, 2>> edges;
  const auto add = [&edges](int u, int w) { edges.push_back({std::min(u, w), std::max(u, w)}); };
  const auto add_path = [&add](const std::vector<int>& path) {
    for (size_t k = 1; k < path.size(); ++k) add(path[k - 1], path[k]);
  };
  if (mesh.is_boundary_edge(size_t(e))) {
    // On along the boundary: each boundary vertex has two boundary edges, so from b take the one not
    // leading back, until a again.
    int previous = a, at = b;
    add(a, b);
    while (at != a) {
      int next = -1;
      for (int i = c.vertex_edge_offsets[size_t(at)]; i < c.vertex_edge_offsets[size_t(at) + 1] && next < 0; ++i) {
        const int edge = c.vertex_edges[size_t(i)];
        if (c.is_boundary_edge(edge) && c.other_vertex(edge, at) != previous) next = c.other_vertex(edge, at);
      }
      add(at, next);
      previous = at;
      at = next;
    }
  } else {
    const CornerLinks links = corner_links(t, c);
    const int h = corner_from_to(mesh, links, a, b);
    std::vector<int> forward = {a};
    const bool closed = walk_loop(mesh, links, h, a, forward);
    add_path(forward);
    if (closed) {
      add(forward.back(), a);
    } else if (continues(mesh, a)) {
      std::vector<int> backward = {a};
      walk_loop(mesh, links, straight_on(mesh, links, links.twins[size_t(h)]), a, backward);
      add_path(backward);
    }
    if (edges.size() == 1) {  // a loop of one edge: the rim of its larger face (a cap's), as Blender does
      const int face = links.faces[size_t(h)], other = links.faces[size_t(links.twins[size_t(h)])];
      const int rim = mesh.face_size(size_t(other)) > mesh.face_size(size_t(face)) ? other : face;
      for (int k = t.offsets[size_t(rim)]; k < t.offsets[size_t(rim) + 1]; ++k)
        add(t.verts[size_t(k)], t.verts[size_t(links.next(t, k))]);
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
  std::vector<char> seen = vertex_mask(mesh, seeds);
  std::vector<int> stack = masked(seen);
  while (!stack.empty()) {
    const int v = stack.back();
    stack.pop_back();
    for_each_neighbour(mesh.connectivity(), v, [&](int w) {
      if (!seen[size_t(w)]) {
        seen[size_t(w)] = 1;
        stack.push_back(w);
      }
    });
  }
  return masked(seen);
}

std::vector<int> grow_selection(const CovarianceMesh& mesh, const std::vector<int>& vertices) {
  std::vector<char> grown = vertex_mask(mesh, vertices);
  for (int v : vertices)
    for_each_face_at(mesh.connectivity(), v, [&](int f) {
      for (const int w : mesh.face(size_t(f))) grown[size_t(w)] = 1;
    });
  return masked(grown);
}

std::vector<int> shrink_selection(const CovarianceMesh& mesh, const std::vector<int>& vertices) {
  const std::vector<char> selected = vertex_mask(mesh, vertices);
  std::vector<char> kept = selected;
  for (int v : vertices)
    for_each_face_at(mesh.connectivity(), v, [&](int f) {
      for (const int w : mesh.face(size_t(f)))
        if (!selected[size_t(w)]) kept[size_t(v)] = 0;
    });
  return masked(kept);
}

Vec3 centre_of_vertices(const CovarianceMesh& mesh, const std::vector<int>& vertices) {
  Vec3 sum = Vec3::Zero();
  for (const int v : vertices) sum += mesh.mean(size_t(v));
  return vertices.empty() ? sum : Vec3(sum / double(vertices.size()));
}

std::vector<int> faces_within(const CovarianceMesh& mesh, const std::vector<int>& vertices) {
  const std::vector<char> selected = vertex_mask(mesh, vertices);
  std::vector<int> faces;
  for (size_t f = 0; f < mesh.n_faces(); ++f) {
    bool all = true;
    for (const int v : mesh.face(f)) all = all && selected[size_t(v)];
    if (all) faces.push_back(int(f));
  }
  return faces;
}

std::vector<std::array<int, 2>> edges_within(const CovarianceMesh& mesh, const std::vector<int>& vertices) {
  const std::vector<char> selected = vertex_mask(mesh, vertices);
  // Sorted as made: the vertices ascending, each one's edges in edge order, which is their ends' order
  // (core/mesh/mesh_connectivity.h): its higher neighbours ascending.
  std::vector<std::array<int, 2>> edges;
  for (int v : masked(selected))
    for_each_neighbour(mesh.connectivity(), v, [&](int w) {
      if (w > v && selected[size_t(w)]) edges.push_back({v, w});
    });
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
  const int n = int(mesh.n_vertices());
  for (const int v : {from, to})
    if (v < 0 || v >= n) throw Error("vertex " + std::to_string(v) + " is not in the mesh");
  std::vector<int> path = dijkstra_path(n, from, to, [&](int v, const auto& step) {
    for_each_neighbour(mesh.connectivity(), v,
                       [&](int w) { step(w, (mesh.mean(size_t(w)) - mesh.mean(size_t(v))).norm()); });
  });
  if (path.empty()) throw Error("no edges join vertex " + std::to_string(from) + " to vertex " + std::to_string(to));
  return path;
}

std::vector<int> shortest_face_path(const CovarianceMesh& mesh, int from, int to, const std::vector<char>* hidden) {
  const int n = int(mesh.n_faces());
  for (const int f : {from, to})
    if (f < 0 || f >= n) throw Error("face " + std::to_string(f) + " is not in the mesh");
  const PolygonTopology& t = mesh.topology();
  const MeshConnectivity& c = mesh.connectivity();
  const auto centre = [&](int f) {
    Vec3 sum = Vec3::Zero();
    for (const int v : mesh.face(size_t(f))) sum += mesh.mean(size_t(v));
    return Vec3(sum / double(mesh.face_size(size_t(f))));
  };
  std::vector<int> path = dijkstra_path(n, from, to, [&](int f, const auto& step) {
    const Vec3 here = centre(f);
    for (int k = t.offsets[size_t(f)]; k < t.offsets[size_t(f) + 1]; ++k) {
      const size_t e = size_t(c.face_edges[size_t(k)]);
      const int g = c.edge_faces[2 * e] == f ? c.edge_faces[2 * e + 1] : c.edge_faces[2 * e];
      if (g < 0) continue;
      if (!hidden || size_t(g) >= hidden->size() || !(*hidden)[size_t(g)]) step(g, (centre(g) - here).norm());
    }
  });
  if (path.empty()) throw Error("no edges join face " + std::to_string(from) + " to face " + std::to_string(to));
  return path;
}

std::vector<int> face_loop(const CovarianceMesh& mesh, int a, int b) {
  check_vertex(mesh, a);
  check_vertex(mesh, b);
  if (a == b || mesh.find_edge(a, b) < 0)
    throw Error("edge " + std::to_string(a) + "–" + std::to_string(b) + " is not in the mesh");
  const PolygonTopology& t = mesh.topology();
  const CornerLinks links = corner_links(t, mesh.connectivity());
  std::set<int> faces;
  // From each face of the edge (the corners running it either way; none on the boundary side) across
  // each quad to the face beyond the opposite edge.
  for (int h : {corner_from_to(mesh, links, a, b), corner_from_to(mesh, links, b, a)})
    while (h >= 0) {
      const int f = links.faces[size_t(h)];
      if (mesh.face_size(size_t(f)) != 4 || !faces.insert(f).second) break;
      h = links.twins[size_t(links.next(t, links.next(t, h)))];
    }
  return {faces.begin(), faces.end()};
}

std::vector<std::vector<int>> boundary_loops(const CovarianceMesh& mesh) {
  const PolygonTopology& t = mesh.topology();
  const MeshConnectivity& c = mesh.connectivity();
  const CornerLinks links = corner_links(t, c);
  // The corner at v whose half-edge lies on the boundary: on a manifold mesh a boundary vertex has one.
  const auto boundary_corner = [&](int v) {
    for (int i = c.vertex_face_offsets[size_t(v)]; i < c.vertex_face_offsets[size_t(v) + 1]; ++i) {
      const int k = t.offsets[size_t(c.vertex_faces[size_t(i)])] + c.vertex_face_corners[size_t(i)];
      if (links.twins[size_t(k)] < 0) return k;
    }
    return -1;
  };
  std::vector<char> visited(mesh.n_vertices(), 0);
  std::vector<std::vector<int>> loops;
  for (int v = 0; v < int(mesh.n_vertices()); ++v) {
    if (visited[size_t(v)] || !mesh.is_boundary_vertex(size_t(v))) continue;
    // Along the faces' boundary half-edges, each from its vertex to the next corner's.
    std::vector<int> loop;
    int at = v;
    do {
      visited[size_t(at)] = 1;
      loop.push_back(at);
      at = t.verts[size_t(links.next(t, boundary_corner(at)))];
    } while (at != v);
    loops.push_back(std::move(loop));
  }
  return loops;
}

}  // namespace gps
