#include "core/extraordinary/neighbourhood_signature.h"

#include <algorithm>
#include <stdexcept>

namespace gps {

namespace {

// Markers after the faces of a signature: an infinitely sharp edge (its two canonical vertices) and an
// infinitely sharp vertex (its canonical number). Face entries start with a face size, never negative.
constexpr int kSharpEdgeMark = -1, kSharpVertexMark = -2;

// Appends the infinitely sharp edges and vertices of the walked faces to the signature; false where
// one is semi-sharp (its sharpness decays, so the neighbourhood is not self-similar).
bool append_sharpness(const LocalMesh& m, const std::vector<std::pair<int, int>>& walk,
                      NeighbourhoodSignature& out) {
  const auto canonical = [&](int v) { return int(std::find(out.points.begin(), out.points.end(), v) - out.points.begin()); };
  std::vector<int> seen_edges;
  for (const auto& [f, start] : walk) {
    const int n = m.topology().face_size(f), offset = m.topology().offsets[size_t(f)];
    for (int k = 0; k < n; ++k) {
      const int e = m.connectivity().face_edges[size_t(offset + (start + k) % n)];
      const double s = m.edge_sharpness(e);
      if (s <= 0.0 || std::find(seen_edges.begin(), seen_edges.end(), e) != seen_edges.end()) continue;
      if (!is_infinitely_sharp(s)) return false;
      seen_edges.push_back(e);
      const int a = canonical(m.connectivity().edge_verts[2 * size_t(e)]),
                b = canonical(m.connectivity().edge_verts[2 * size_t(e) + 1]);
      out.signature.insert(out.signature.end(), {kSharpEdgeMark, std::min(a, b), std::max(a, b)});
    }
  }
  for (size_t i = 0; i < out.points.size(); ++i) {
    const double s = m.vertex_sharpness(out.points[i]);
    if (s <= 0.0) continue;
    if (!is_infinitely_sharp(s)) return false;
    out.signature.insert(out.signature.end(), {kSharpVertexMark, int(i)});
  }
  return true;
}

}  // namespace

std::optional<NeighbourhoodSignature> neighbourhood_signature(const LocalMesh& m, const std::vector<int>& c) {
  const auto& conn = m.connectivity();
  std::vector<int> region;  // the faces at the corners
  for (const int v : c)
    for (int i = conn.vertex_face_offsets[size_t(v)]; i < conn.vertex_face_offsets[size_t(v) + 1]; ++i)
      if (std::find(region.begin(), region.end(), conn.vertex_faces[size_t(i)]) == region.end())
        region.push_back(conn.vertex_faces[size_t(i)]);
  const int q = m.find_face(c);
  if (q < 0 || face_vertex(m, q, corner_index(m, q, c[0]) + 1) != c[1]) return std::nullopt;
  NeighbourhoodSignature out;
  const auto number = [&](int v) {
    const auto at = std::find(out.points.begin(), out.points.end(), v);
    if (at != out.points.end()) return int(at - out.points.begin());
    out.points.push_back(v);
    return int(out.points.size()) - 1;
  };
  // Breadth first across edges from the node's face, each face read from the vertex where the
  // walk entered it.
  std::vector<std::pair<int, int>> walk = {{q, corner_index(m, q, c[0])}};
  std::vector<char> seen(region.size(), 0);
  seen[size_t(std::find(region.begin(), region.end(), q) - region.begin())] = 1;
  for (size_t w = 0; w < walk.size(); ++w) {
    const auto [f, start] = walk[w];
    const int n = m.topology().face_size(f), offset = m.topology().offsets[size_t(f)];
    out.signature.push_back(n);
    for (int k = 0; k < n; ++k) out.signature.push_back(number(face_vertex(m, f, start + k)));
    for (int k = 0; k < n; ++k) {
      const int e = conn.face_edges[size_t(offset + (start + k) % n)], g = other_face(m, e, f);
      const auto at = std::find(region.begin(), region.end(), g);
      if (g < 0 || at == region.end() || seen[size_t(at - region.begin())]) continue;
      seen[size_t(at - region.begin())] = 1;
      walk.emplace_back(g, corner_index(m, g, face_vertex(m, f, start + k + 1)));
    }
  }
  if (walk.size() != region.size()) return std::nullopt;
  if (m.has_creases() && !append_sharpness(m, walk, out)) return std::nullopt;
  return out;
}

// The neighbourhood of a signature as a LocalMesh of its own: point i is the unit vector e_i, the
// corners (0..3) complete.
LocalMesh neighbourhood_mesh(const std::vector<int>& signature, int n_corners) {
  LocalMesh m;
  PolygonTopology faces;
  size_t at = 0;
  for (; at < signature.size() && signature[at] > 0; at += size_t(signature[at]) + 1) {
    faces.verts.insert(faces.verts.end(), signature.begin() + long(at) + 1,
                       signature.begin() + long(at) + 1 + signature[at]);
    faces.offsets.push_back(int(faces.verts.size()));
  }
  faces.n_vertices = *std::max_element(faces.verts.begin(), faces.verts.end()) + 1;
  const int k = faces.n_vertices;
  m.set_faces(std::move(faces));
  for (int i = 0; i < k; ++i) {
    m.base_ids.push_back(i);
    m.points.push_back(Eigen::VectorXd::Unit(k, i));
    m.complete.push_back(i < n_corners);
  }
  if (at < signature.size()) {  // its infinitely sharp edges and vertices
    m.creases.edges.assign(size_t(m.connectivity().n_edges()), 0.0);
    m.creases.vertices.assign(size_t(k), 0.0);
    while (at < signature.size()) {
      if (signature[at] == kSharpEdgeMark) {
        m.creases.edges[size_t(m.find_edge(signature[at + 1], signature[at + 2]))] = kInfiniteSharpness;
        at += 3;
      } else {
        m.creases.vertices[size_t(signature[at + 1])] = kInfiniteSharpness;
        at += 2;
      }
    }
  }
  return m;
}

// Rows of LocalMesh combinations as a matrix over the K coarse points.
Eigen::MatrixXd rows_over_neighbourhood(const LocalMesh& fine, const std::vector<LocalCombination>& rows, int k) {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(long(rows.size()), k);
  for (size_t r = 0; r < rows.size(); ++r)
    for (const auto& [v, w] : rows[r]) {
      if (fine.points[size_t(v)].size() == 0)
        throw std::logic_error("extraordinary table: a point outside the neighbourhood");
      out.row(long(r)) += w * fine.points[size_t(v)].transpose();
    }
  return out;
}

}  // namespace gps
