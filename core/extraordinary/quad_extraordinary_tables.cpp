#include "core/extraordinary/quad_extraordinary_tables.h"

#include <algorithm>
#include <stdexcept>

#include "core/extraordinary/extraordinary_corner_masks.h"
#include "core/plans/quad_nets.h"

namespace gps {

namespace {

// Markers after the faces of a signature: an infinitely sharp edge (its two canonical vertices) and an
// infinitely sharp vertex (its canonical number). Face entries start with a face size, never negative.
constexpr int kSharpEdgeMark = -1, kSharpVertexMark = -2;

// Appends the infinitely sharp edges and vertices of the walked faces to the signature; false where
// one is semi-sharp (its sharpness decays, so the neighbourhood is not self-similar).
bool append_sharpness(const LocalMesh& m, const std::vector<std::pair<int, int>>& walk,
                      QuadExtraordinaryNeighbourhood& out) {
  const auto canonical = [&](int v) { return int(std::find(out.points.begin(), out.points.end(), v) - out.points.begin()); };
  std::vector<int> seen_edges;
  for (const auto& [f, start] : walk) {
    const int n = m.topology.face_size(f), offset = m.topology.offsets[size_t(f)];
    for (int k = 0; k < n; ++k) {
      const int e = m.connectivity.face_edges[size_t(offset + (start + k) % n)];
      const double s = m.edge_sharpness(e);
      if (s <= 0.0 || std::find(seen_edges.begin(), seen_edges.end(), e) != seen_edges.end()) continue;
      if (!is_infinitely_sharp(s)) return false;
      seen_edges.push_back(e);
      const int a = canonical(m.connectivity.edge_verts[2 * size_t(e)]),
                b = canonical(m.connectivity.edge_verts[2 * size_t(e) + 1]);
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

std::optional<QuadExtraordinaryNeighbourhood> quad_extraordinary_neighbourhood(const LocalMesh& m,
                                                                               const std::array<int, 4>& c) {
  const auto& conn = m.connectivity;
  std::vector<int> region;  // the faces at the corners
  for (const int v : c)
    for (int i = conn.vertex_face_offsets[size_t(v)]; i < conn.vertex_face_offsets[size_t(v) + 1]; ++i)
      if (std::find(region.begin(), region.end(), conn.vertex_faces[size_t(i)]) == region.end())
        region.push_back(conn.vertex_faces[size_t(i)]);
  const int q = m.find_face({c[0], c[1], c[2], c[3]});
  if (q < 0 || face_vertex(m, q, corner_index(m, q, c[0]) + 1) != c[1]) return std::nullopt;
  QuadExtraordinaryNeighbourhood out;
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
    const int n = m.topology.face_size(f), offset = m.topology.offsets[size_t(f)];
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

namespace {

// The neighbourhood of a signature as a LocalMesh of its own: point i is the unit vector e_i, the
// corners (0..3) complete.
LocalMesh neighbourhood_mesh(const std::vector<int>& signature) {
  LocalMesh m;
  size_t at = 0;
  for (; at < signature.size() && signature[at] > 0; at += size_t(signature[at]) + 1) {
    m.topology.verts.insert(m.topology.verts.end(), signature.begin() + long(at) + 1,
                            signature.begin() + long(at) + 1 + signature[at]);
    m.topology.offsets.push_back(int(m.topology.verts.size()));
  }
  m.topology.n_vertices = *std::max_element(m.topology.verts.begin(), m.topology.verts.end()) + 1;
  m.connectivity = connectivity_of(m.topology);
  const int k = m.topology.n_vertices;
  for (int i = 0; i < k; ++i) {
    m.base_ids.push_back(i);
    m.points.push_back(Eigen::VectorXd::Unit(k, i));
    m.complete.push_back(i < 4);
  }
  if (at < signature.size()) {  // its infinitely sharp edges and vertices
    m.creases.edges.assign(size_t(m.connectivity.n_edges()), 0.0);
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
Eigen::MatrixXd rows_of(const LocalMesh& fine, const std::vector<LocalCombination>& rows, int k) {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(long(rows.size()), k);
  for (size_t r = 0; r < rows.size(); ++r)
    for (const auto& [v, w] : rows[r]) {
      if (fine.points[size_t(v)].size() == 0)
        throw std::logic_error("Catmull-Clark extraordinary table: a point outside the neighbourhood");
      out.row(long(r)) += w * fine.points[size_t(v)].transpose();
    }
  return out;
}

std::shared_ptr<const std::vector<double>> compute_table(const std::vector<int>& signature) {
  const LocalMesh coarse = neighbourhood_mesh(signature);
  const LocalMesh fine = refine_local_mesh(coarse);
  const int k = coarse.topology.n_vertices, ne = coarse.connectivity.n_edges();
  const auto edge_point = [&](int a, int b) { return k + coarse.find_edge(a, b); };
  const int face_point = k + ne + 0, e01 = edge_point(0, 1), e12 = edge_point(1, 2), e23 = edge_point(2, 3),
            e30 = edge_point(3, 0);
  // A: the corner child (0', e01, f, e30) must have the same neighbourhood, one level down.
  const auto child = quad_extraordinary_neighbourhood(fine, {0, e01, face_point, e30});
  if (!child || child->signature != signature) return nullptr;
  std::vector<LocalCombination> step_rows;
  for (const int p : child->points) step_rows.push_back({{p, 1.0}});
  const Eigen::MatrixXd step = rows_of(fine, step_rows, k);
  // Ā_c: the nets of children 1..3 (quadrants s ≥ ½ > t, both ≥ ½, t ≥ ½ > s), each from its (0, 0).
  const std::array<int, 4> children[3] = {
      {e01, 1, e12, face_point}, {face_point, e12, 2, e23}, {e30, face_point, e23, 3}};
  Eigen::MatrixXd nets[3];
  for (int c = 0; c < 3; ++c) {
    const int face = fine.find_face({children[c][0], children[c][1], children[c][2], children[c][3]});
    for (const int v : children[c])
      if (!regular_corner(fine, v, face)) return nullptr;
    std::array<LocalCombination, 16> net;
    bspline_net(fine, face, children[c], net);
    nets[c] = rows_of(fine, {net.begin(), net.end()}, k);
  }
  auto table = std::make_shared<std::vector<double>>(quad_extraordinary_table_size(k), 0.0);
  Eigen::MatrixXd power = Eigen::MatrixXd::Identity(k, k);
  for (int level = 0; level < kExtraordinaryLevels; ++level) {
    for (int c = 0; c < 3; ++c) {
      const Eigen::MatrixXd block = nets[c] * power;
      for (int j = 0; j < 16; ++j)
        for (int i = 0; i < k; ++i) (*table)[size_t((3 * level + c) * 16 + j) * size_t(k) + size_t(i)] = block(j, i);
    }
    power = step * power;
  }
  // Tangents start from child 1's patch at its corner (½, 0), next to the vertex.
  double w[4], dw[4];
  bspline_basis(0.0, w, dw);
  Eigen::RowVectorXd d_s = Eigen::RowVectorXd::Zero(k), d_t = Eigen::RowVectorXd::Zero(k);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      d_s += dw[i] * w[j] * nets[0].row(i + 4 * j);
      d_t += w[i] * dw[j] * nets[0].row(i + 4 * j);
    }
  const CornerMasks masks = extraordinary_corner_masks(step, d_s, d_t);
  double* rows = table->data() + size_t(48 * kExtraordinaryLevels) * size_t(k);
  for (int i = 0; i < k; ++i) {
    rows[i] = masks.position(i);
    rows[k + i] = masks.d_s(i);
    rows[2 * k + i] = masks.d_t(i);
  }
  for (int r = 0; r < k; ++r)
    for (int i = 0; i < k; ++i) rows[size_t(3 + r) * size_t(k) + size_t(i)] = step(r, i);
  return table;
}

}  // namespace

std::shared_ptr<const std::vector<double>> QuadExtraordinaryTableCache::table(const std::vector<int>& signature) {
  {
    const std::lock_guard lock(mutex_);
    if (const auto it = tables_.find(signature); it != tables_.end()) return it->second;
  }
  auto computed = compute_table(signature);  // outside the lock: threads meeting other signatures go on
  const std::lock_guard lock(mutex_);
  return tables_.try_emplace(signature, std::move(computed)).first->second;
}

}  // namespace gps
