#include "core/mesh/mesh_connectivity.h"

#include <algorithm>

#include "core/support/error.h"

namespace gps {

PolygonTopology polygon_topology(const std::vector<std::vector<int>>& faces) {
  PolygonTopology t;
  const int n_faces = int(faces.size());
  t.offsets.resize(faces.size() + 1);
  for (int f = 0; f < n_faces; ++f) t.offsets[size_t(f) + 1] = t.offsets[size_t(f)] + int(faces[size_t(f)].size());
  t.verts.resize(size_t(t.offsets.back()));
#pragma omp parallel for schedule(static) if (n_faces >= kParallelFaces)
  for (int f = 0; f < n_faces; ++f)
    std::copy(faces[size_t(f)].begin(), faces[size_t(f)].end(), t.verts.begin() + t.offsets[size_t(f)]);
  return t;
}

MeshConnectivity edge_connectivity(const PolygonTopology& t) {
  MeshConnectivity c;
  const size_t n_corners = t.verts.size();
  // The corners keyed by their edge's (min, max) vertex pair, sorted to pair them into edges: a radix
  // sort of corner indices in two counting passes (by the larger vertex, then stably by the smaller),
  // linear whatever the valence, the keys read off the faces (12 bytes a corner held).
  std::vector<int> corner_face(n_corners);
  for (int f = 0; f < t.n_faces(); ++f)
    std::fill(corner_face.begin() + t.offsets[size_t(f)], corner_face.begin() + t.offsets[size_t(f) + 1], f);
  const auto ends = [&](int k) {
    const int f = corner_face[size_t(k)];
    const int a = t.verts[size_t(k)],
              b = t.verts[size_t(k + 1 == t.offsets[size_t(f) + 1] ? t.offsets[size_t(f)] : k + 1)];
    return std::pair<int, int>(std::min(a, b), std::max(a, b));
  };
  std::vector<int> by_high(n_corners), order(n_corners);
  const auto counting_sort = [&](const auto& in, std::vector<int>& out, auto digit) {
    std::vector<size_t> next(size_t(t.n_vertices) + 1, 0);
    for (size_t i = 0; i < n_corners; ++i) ++next[size_t(digit(in(i))) + 1];
    for (int v = 0; v < t.n_vertices; ++v) next[size_t(v) + 1] += next[size_t(v)];
    for (size_t i = 0; i < n_corners; ++i) out[next[size_t(digit(in(i)))]++] = in(i);
  };
  counting_sort([](size_t i) { return int(i); }, by_high, [&](int k) { return ends(k).second; });
  counting_sort([&](size_t i) { return by_high[i]; }, order, [&](int k) { return ends(k).first; });
  by_high = {};
  c.face_edges.assign(n_corners, -1);
  const auto same_edge = [&](size_t i, size_t j) { return ends(order[i]) == ends(order[j]); };
  size_t n_edges = 0;  // counted first: the edge arrays at their exact sizes
  for (size_t i = 0; i < n_corners; ++n_edges) i += i + 1 < n_corners && same_edge(i + 1, i) ? 2 : 1;
  c.edge_verts.reserve(2 * n_edges);
  c.edge_faces.reserve(2 * n_edges);
  for (size_t i = 0; i < n_corners;) {
    const int e = c.n_edges(), k = order[i];
    const auto [low, high] = ends(k);
    c.edge_verts.push_back(low);
    c.edge_verts.push_back(high);
    c.edge_faces.push_back(corner_face[size_t(k)]);
    c.face_edges[size_t(k)] = e;
    if (i + 1 < n_corners && same_edge(i + 1, i)) {
      c.edge_faces.push_back(corner_face[size_t(order[i + 1])]);
      c.face_edges[size_t(order[i + 1])] = e;
      i += 2;
    } else {
      c.edge_faces.push_back(-1);
      i += 1;
    }
  }
  return c;
}

void add_vertex_rows(const PolygonTopology& t, MeshConnectivity& c) {
  const size_t n_corners = t.verts.size();
  // Compressed rows per vertex, each in the order its entries come (edges in edge order, faces in
  // face order): a count, a prefix sum, a fill.
  const auto prefix = [&](std::vector<int>& offsets) {
    for (int v = 0; v < t.n_vertices; ++v) offsets[size_t(v) + 1] += offsets[size_t(v)];
    return std::vector<int>(offsets.begin(), offsets.end() - 1);
  };
  c.vertex_edge_offsets.assign(size_t(t.n_vertices) + 1, 0);
  for (const int v : c.edge_verts) ++c.vertex_edge_offsets[size_t(v) + 1];
  std::vector<int> next = prefix(c.vertex_edge_offsets);
  c.vertex_edges.resize(c.edge_verts.size());
  for (size_t i = 0; i < c.edge_verts.size(); ++i) c.vertex_edges[size_t(next[size_t(c.edge_verts[i])]++)] = int(i / 2);
  c.vertex_face_offsets.assign(size_t(t.n_vertices) + 1, 0);
  for (const int v : t.verts) ++c.vertex_face_offsets[size_t(v) + 1];
  next = prefix(c.vertex_face_offsets);
  c.vertex_faces.resize(n_corners);
  c.vertex_face_corners.resize(n_corners);
  for (int f = 0; f < t.n_faces(); ++f)
    for (int i = t.offsets[size_t(f)], k = 0; i < t.offsets[size_t(f) + 1]; ++i, ++k) {
      const int at = next[size_t(t.verts[size_t(i)])]++;
      c.vertex_faces[size_t(at)] = f;
      c.vertex_face_corners[size_t(at)] = k;
    }
}

MeshConnectivity connectivity_of(const PolygonTopology& t) {
  MeshConnectivity c = edge_connectivity(t);
  add_vertex_rows(t, c);
  return c;
}

namespace {

// The surface counts of a manifold mesh given by its edges: `edge(e, a, b)` sets edge e's ends and
// says whether it is a boundary edge.
template <class Edge>
SurfaceCounts surface_counts_of_edges(int n_vertices, int n_edges, int n_faces, const Edge& edge) {
  // Two forests over the vertices: one joined along every edge (the parts), one along the boundary
  // edges only (on a manifold each boundary vertex has two, so its trees are the loops).
  std::vector<int> part(static_cast<size_t>(n_vertices)), loop(static_cast<size_t>(n_vertices));
  for (int v = 0; v < n_vertices; ++v) part[size_t(v)] = loop[size_t(v)] = v;
  const auto root = [](std::vector<int>& up, int x) {
    while (up[size_t(x)] != x) x = up[size_t(x)] = up[size_t(up[size_t(x)])];
    return x;
  };
  const auto unite = [&](std::vector<int>& up, int a, int b) { up[size_t(root(up, a))] = root(up, b); };
  std::vector<char> used(static_cast<size_t>(n_vertices), 0), on_boundary(static_cast<size_t>(n_vertices), 0);
  for (int e = 0; e < n_edges; ++e) {
    int a = 0, b = 0;
    const bool boundary = edge(e, a, b);
    unite(part, a, b);
    used[size_t(a)] = used[size_t(b)] = 1;
    if (!boundary) continue;
    unite(loop, a, b);
    on_boundary[size_t(a)] = on_boundary[size_t(b)] = 1;
  }
  SurfaceCounts out;
  long long n_used = 0;
  for (int v = 0; v < n_vertices; ++v) {
    if (!used[size_t(v)]) continue;
    ++n_used;
    out.parts += root(part, v) == v;
    out.boundary_loops += on_boundary[size_t(v)] && root(loop, v) == v;
  }
  const long long euler = n_used - n_edges + n_faces;
  out.genus = int((2 * out.parts - euler - out.boundary_loops) / 2);
  return out;
}

}  // namespace

SurfaceCounts surface_counts(const PolygonTopology& t, const MeshConnectivity& c) {
  return surface_counts_of_edges(t.n_vertices, c.n_edges(), t.n_faces(), [&](int e, int& a, int& b) {
    a = c.edge_verts[2 * size_t(e)];
    b = c.edge_verts[2 * size_t(e) + 1];
    return c.is_boundary_edge(e);
  });
}

CornerLinks corner_links(const PolygonTopology& t, const MeshConnectivity& c) {
  CornerLinks links;
  links.faces.resize(t.verts.size());
  for (int f = 0; f < t.n_faces(); ++f)
    std::fill(links.faces.begin() + t.offsets[size_t(f)], links.faces.begin() + t.offsets[size_t(f) + 1], f);
  links.twins.assign(t.verts.size(), -1);
  std::vector<int> first(size_t(c.n_edges()), -1);  // per edge, the first corner met along it
  for (int k = 0; k < int(t.verts.size()); ++k) {
    int& other = first[size_t(c.face_edges[size_t(k)])];
    if (other < 0) {
      other = k;
    } else {
      links.twins[size_t(k)] = other;
      links.twins[size_t(other)] = k;
    }
  }
  return links;
}

int MeshConnectivity::find_edge(int a, int b) const {
  for (int i = vertex_edge_offsets[size_t(a)]; i < vertex_edge_offsets[size_t(a) + 1]; ++i)
    if (other_vertex(vertex_edges[size_t(i)], a) == b) return vertex_edges[size_t(i)];
  return -1;
}

VertexRole vertex_role(const MeshConnectivity& c, int v, int* a, int* b) {
  const int n_faces = c.n_vertex_faces(v);
  if (n_faces == 0) return VertexRole::isolated;
  // Each face at v brings two of v's edges and each edge has one or two faces, so 2F = 2E − B with B
  // the boundary edges at v: as many edges as faces means none (without reading every edge's faces).
  if (c.valence(v) == n_faces) return VertexRole::interior;
  int found = 0;
  for (int i = c.vertex_edge_offsets[size_t(v)]; i < c.vertex_edge_offsets[size_t(v) + 1]; ++i) {
    const int e = c.vertex_edges[size_t(i)];
    if (!c.is_boundary_edge(e)) continue;
    const int w = c.other_vertex(e, v);
    if (found == 0 && a) *a = w;
    if (found == 1 && b) *b = w;
    ++found;
  }
  if (found == 0) return VertexRole::interior;
  return n_faces == 1 ? VertexRole::corner : VertexRole::boundary;
}

void check_manifold(const PolygonTopology& t, const MeshConnectivity& c, const std::string& source,
                    const ElementNames& names) {
  for (int e = 0; e + 1 < c.n_edges(); ++e)  // equal edges are neighbours in connectivity_of's order
    if (c.edge_verts[2 * size_t(e)] == c.edge_verts[2 * size_t(e) + 2] &&
        c.edge_verts[2 * size_t(e) + 1] == c.edge_verts[2 * size_t(e) + 3])
      throw Error(source + ": " + names.face(c.edge_faces[2 * size_t(e) + 2]) +
                  " makes the mesh non-manifold (an edge with more than two faces or a flipped face)");
  // The two faces of an edge must run along it in opposite directions; the later one is named.
  const CornerLinks links = corner_links(t, c);
  const auto runs_up = [&](int k) { return t.verts[size_t(k)] < t.verts[size_t(links.next(t, k))]; };
  int flipped = -1;
  for (int k = 0; k < int(t.verts.size()); ++k) {
    const int twin = links.twins[size_t(k)];
    if (twin > k && runs_up(k) == runs_up(twin) && (flipped < 0 || links.faces[size_t(twin)] < flipped))
      flipped = links.faces[size_t(twin)];
  }
  if (flipped >= 0)
    throw Error(source + ": " + names.face(flipped) +
                " makes the mesh non-manifold (an edge with more than two faces or a flipped face)");
  const auto non_manifold = [&](int v) {
    return Error(source + ": " + names.vertex(v) + " is non-manifold (its faces do not form one fan)");
  };
  // One fan per vertex: at most one boundary edge comes into it along its face (the first such vertex in
  // edge order is named), and circling its corners from there across their own edges meets every face at it.
  std::vector<int> boundary_corner(size_t(c.n_edges()), -1);  // a boundary edge's one corner
  for (int k = 0; k < int(t.verts.size()); ++k)
    if (links.twins[size_t(k)] < 0) boundary_corner[size_t(c.face_edges[size_t(k)])] = k;
  std::vector<int> fan_start(size_t(t.n_vertices), -1);  // the corner whose incoming edge is a boundary
  for (int e = 0; e < c.n_edges(); ++e) {
    const int k = boundary_corner[size_t(e)];
    if (k < 0) continue;
    const int to = t.verts[size_t(links.next(t, k))];
    if (fan_start[size_t(to)] >= 0) throw non_manifold(to);
    fan_start[size_t(to)] = links.next(t, k);
  }
  // Each vertex's faces (its corners) and one of its corners, without the vertices' rows.
  std::vector<int> n_faces_at(size_t(t.n_vertices), 0), a_corner(size_t(t.n_vertices), -1);
  for (int k = 0; k < int(t.verts.size()); ++k) {
    const int v = t.verts[size_t(k)];
    if (n_faces_at[size_t(v)]++ == 0) a_corner[size_t(v)] = k;
  }
  for (int v = 0; v < t.n_vertices; ++v) {
    const int n_faces = n_faces_at[size_t(v)];
    if (n_faces == 0) continue;
    const int first = fan_start[size_t(v)] >= 0 ? fan_start[size_t(v)] : a_corner[size_t(v)];
    int count = 1;
    for (int k = first; count <= n_faces; ++count) {  // across each corner's own edge to the next face at v
      k = links.twins[size_t(k)];
      if (k < 0 || (k = links.next(t, k)) == first) break;
    }
    if (count != n_faces) throw non_manifold(v);
  }
  // Two faces that share all their edges close up on their own (a pillow): manifold, but the first
  // refinement of Loop (and the plans) makes it non-manifold, so it is refused here, named.
  for (int f = 0; f < t.n_faces(); ++f) {
    const int begin = t.offsets[size_t(f)], end = t.offsets[size_t(f) + 1];
    const auto other_face = [&](int e) {
      const int a = c.edge_faces[2 * size_t(e)], b = c.edge_faces[2 * size_t(e) + 1];
      return a == f ? b : a;
    };
    const int g = other_face(c.face_edges[size_t(begin)]);
    if (g <= f || t.face_size(g) != end - begin) continue;
    bool shares_all = true;
    for (int k = begin + 1; k < end && shares_all; ++k) shares_all = other_face(c.face_edges[size_t(k)]) == g;
    if (shares_all)
      throw Error(source + ": " + names.face(f) + " and " + names.face(g) +
                  " share all their edges (a closed pillow of two faces, which no subdivision can refine)");
  }
}

}  // namespace gps
