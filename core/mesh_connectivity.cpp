#include "core/mesh_connectivity.h"

#include <algorithm>

#include "core/patch_layout.h"

namespace gps {

PolygonTopology topology_of(const PolyMesh& mesh) {
  PolygonTopology t;
  t.n_vertices = int(mesh.n_vertices());
  t.offsets.reserve(mesh.n_faces() + 1);
  t.verts.reserve(mesh.n_faces() * 4);
  for (const auto f : mesh.faces()) {
    for (const auto v : mesh.fv_range(f)) t.verts.push_back(v.idx());
    t.offsets.push_back(int(t.verts.size()));
  }
  return t;
}

namespace {
// Compressed rows from (key, value) pairs sorted by key.
void fill_rows(int n_keys, const std::vector<std::pair<int, int>>& pairs, std::vector<int>& offsets,
               std::vector<int>& values) {
  offsets.assign(size_t(n_keys) + 1, 0);
  for (const auto& [k, _] : pairs) ++offsets[size_t(k) + 1];
  for (int i = 0; i < n_keys; ++i) offsets[size_t(i) + 1] += offsets[size_t(i)];
  values.resize(pairs.size());
  std::vector<int> next(offsets.begin(), offsets.end() - 1);
  for (const auto& [k, v] : pairs) values[size_t(next[size_t(k)]++)] = v;
}
}  // namespace

MeshConnectivity connectivity_of(const PolygonTopology& t) {
  MeshConnectivity c;
  const size_t n_corners = t.verts.size();
  // Half-edges keyed by (min, max) vertex pair, sorted to pair them into edges: a counting sort by
  // the smaller vertex, then an insertion sort of each (small) bucket by the larger one — linear time.
  struct HalfEdge {
    long long key;
    int face, corner;
  };
  std::vector<int> bucket(size_t(t.n_vertices) + 1, 0);
  for (int f = 0; f < t.n_faces(); ++f) {
    const int begin = t.offsets[size_t(f)], n = t.face_size(f);
    for (int k = 0; k < n; ++k)
      ++bucket[size_t(std::min(t.verts[size_t(begin + k)], t.verts[size_t(begin + (k + 1) % n)])) + 1];
  }
  for (int v = 0; v < t.n_vertices; ++v) bucket[size_t(v) + 1] += bucket[size_t(v)];
  std::vector<HalfEdge> halves(n_corners);
  {
    std::vector<int> next(bucket.begin(), bucket.end() - 1);
    for (int f = 0; f < t.n_faces(); ++f) {
      const int begin = t.offsets[size_t(f)], n = t.face_size(f);
      for (int k = 0; k < n; ++k) {
        const int a = t.verts[size_t(begin + k)], b = t.verts[size_t(begin + (k + 1) % n)];
        const long long key = (long long)std::min(a, b) * t.n_vertices + std::max(a, b);
        halves[size_t(next[size_t(std::min(a, b))]++)] = {key, f, begin + k};
      }
    }
  }
  for (int v = 0; v < t.n_vertices; ++v)
    for (int i = bucket[size_t(v)] + 1; i < bucket[size_t(v) + 1]; ++i)
      for (int j = i; j > bucket[size_t(v)] && halves[size_t(j - 1)].key > halves[size_t(j)].key; --j)
        std::swap(halves[size_t(j - 1)], halves[size_t(j)]);
  c.face_edges.assign(n_corners, -1);
  for (size_t i = 0; i < halves.size();) {
    const int e = c.n_edges();
    const int a = int(halves[i].key / t.n_vertices), b = int(halves[i].key % t.n_vertices);
    c.edge_verts.push_back(a);
    c.edge_verts.push_back(b);
    c.edge_faces.push_back(halves[i].face);
    c.face_edges[size_t(halves[i].corner)] = e;
    if (i + 1 < halves.size() && halves[i + 1].key == halves[i].key) {
      c.edge_faces.push_back(halves[i + 1].face);
      c.face_edges[size_t(halves[i + 1].corner)] = e;
      i += 2;
    } else {
      c.edge_faces.push_back(-1);
      i += 1;
    }
  }
  std::vector<std::pair<int, int>> pairs;
  pairs.reserve(c.edge_verts.size());
  for (int e = 0; e < c.n_edges(); ++e) {
    pairs.emplace_back(c.edge_verts[2 * size_t(e)], e);
    pairs.emplace_back(c.edge_verts[2 * size_t(e) + 1], e);
  }
  fill_rows(t.n_vertices, pairs, c.vertex_edge_offsets, c.vertex_edges);
  pairs.clear();
  std::vector<std::pair<int, int>> corner_pairs;
  for (int f = 0; f < t.n_faces(); ++f)
    for (int k = 0; k < t.face_size(f); ++k) {
      pairs.emplace_back(t.verts[size_t(t.offsets[size_t(f)] + k)], f);
      corner_pairs.emplace_back(t.verts[size_t(t.offsets[size_t(f)] + k)], k);
    }
  fill_rows(t.n_vertices, pairs, c.vertex_face_offsets, c.vertex_faces);
  std::vector<int> unused;
  fill_rows(t.n_vertices, corner_pairs, unused, c.vertex_face_corners);
  return c;
}

VertexRole vertex_role(const MeshConnectivity& c, int v, int* a, int* b) {
  const int n_faces = c.n_vertex_faces(v);
  if (n_faces == 0) return VertexRole::isolated;
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

}  // namespace gps
