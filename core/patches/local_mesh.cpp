#include "core/patches/local_mesh.h"

#include <algorithm>
#include <stdexcept>

#include "core/reference/catmull_clark.h"
#include "core/reference/crease_rules.h"
#include "core/reference/loop.h"

namespace gps {

int LocalMesh::find_edge(int a, int b) const {
  const auto& c = connectivity();
  for (int i = c.vertex_edge_offsets[size_t(a)]; i < c.vertex_edge_offsets[size_t(a) + 1]; ++i)
    if (c.other_vertex(c.vertex_edges[size_t(i)], a) == b) return c.vertex_edges[size_t(i)];
  return -1;
}

int LocalMesh::find_face(const std::vector<int>& corners) const {
  const auto& c = connectivity();
  const PolygonTopology& t = topology();
  const int v = corners[0];
  for (int i = c.vertex_face_offsets[size_t(v)]; i < c.vertex_face_offsets[size_t(v) + 1]; ++i) {
    const int f = c.vertex_faces[size_t(i)];
    if (t.face_size(f) != int(corners.size())) continue;
    const auto begin = t.verts.begin() + t.offsets[size_t(f)];
    const auto end = t.verts.begin() + t.offsets[size_t(f) + 1];
    if (std::all_of(corners.begin(), corners.end(), [&](int x) { return std::find(begin, end, x) != end; })) return f;
  }
  return -1;
}

LocalMesh::VertexSharpness LocalMesh::sharpness_at(int v) const {
  VertexSharpness out;
  const double corner = vertex_sharpness(v);
  out.sharp_corner = is_infinitely_sharp(corner);
  out.semi_sharp = corner > 0.0 && !out.sharp_corner;
  const MeshConnectivity& c = connectivity();
  for (int i = c.vertex_edge_offsets[size_t(v)]; i < c.vertex_edge_offsets[size_t(v) + 1]; ++i) {
    const int e = c.vertex_edges[size_t(i)];
    const double s = edge_sharpness(e);
    out.semi_sharp = out.semi_sharp || (s > 0.0 && !is_infinitely_sharp(s));
    out.cut_edges += is_cut_edge(e) ? 1 : 0;
  }
  return out;
}

Stencil LocalMesh::point(int v) const { return combination({{v, 1.0}}); }

Stencil LocalMesh::combination(const std::vector<std::pair<int, double>>& terms) const {
  if (is_base) {
    Stencil s;
    for (const auto& [v, w] : terms) s += Stencil::vertex(v) * w;
    return s;
  }
  thread_local Eigen::VectorXd sum;  // scratch: one allocation per thread, not per point
  sum.setZero(Eigen::Index(base_ids.size()));
  for (const auto& [v, w] : terms) {
    if (points[size_t(v)].size() == 0)
      throw std::logic_error("plan builder read a point outside the known neighbourhood");
    sum += w * points[size_t(v)];
  }
  std::vector<std::pair<int, double>> sparse;
  sparse.reserve(size_t((sum.array() != 0.0).count()));
  for (Eigen::Index i = 0; i < sum.size(); ++i)
    if (sum[i] != 0.0) sparse.emplace_back(base_ids[size_t(i)], sum[i]);
  return Stencil::from_terms(std::move(sparse));
}

void LocalMesh::set_faces(PolygonTopology&& faces) {
  auto made = std::make_shared<MeshShape>();
  made->connectivity = connectivity_of(faces);
  made->topology = std::move(faces);
  shape = std::move(made);
}

LocalMesh base_local_mesh(const PolygonTopology& topology, const Sharpness& sharpness) {
  return base_local_mesh(std::make_shared<const MeshShape>(MeshShape{topology, connectivity_of(topology), {}}),
                         sharpness);
}

LocalMesh base_local_mesh(const PolygonTopology& topology, const MeshConnectivity& connectivity,
                          const Sharpness& sharpness) {
  return base_local_mesh(std::make_shared<const MeshShape>(MeshShape{topology, connectivity, {}}), sharpness);
}

LocalMesh base_local_mesh(std::shared_ptr<const MeshShape> shape, const Sharpness& sharpness) {
  LocalMesh m;
  m.shape = std::move(shape);
  const int n_vertices = m.topology().n_vertices;
  m.complete.assign(size_t(n_vertices), 1);
  if (!sharpness.empty()) {
    CreaseLevel level = crease_level(sharpness, m.connectivity(), n_vertices);
    if (!level.empty()) m.creases = std::move(level);  // all zero: the smooth plans, bit for bit
  }
  m.is_base = true;
  return m;
}

LocalMesh extract_neighbourhood(const LocalMesh& m, const std::vector<int>& corners, std::vector<int>& new_index) {
  const auto& c = m.connectivity();
  std::vector<int> faces;
  for (const int v : corners)
    for (int i = c.vertex_face_offsets[size_t(v)]; i < c.vertex_face_offsets[size_t(v) + 1]; ++i)
      faces.push_back(c.vertex_faces[size_t(i)]);
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());

  LocalMesh out;
  const PolygonTopology& t = m.topology();
  new_index.assign(size_t(t.n_vertices), -1);
  std::vector<int> old_index;
  PolygonTopology piece;
  for (const int f : faces) {
    for (int i = t.offsets[size_t(f)]; i < t.offsets[size_t(f) + 1]; ++i) {
      const int v = t.verts[size_t(i)];
      if (new_index[size_t(v)] < 0) {
        new_index[size_t(v)] = int(old_index.size());
        old_index.push_back(v);
      }
      piece.verts.push_back(new_index[size_t(v)]);
    }
    piece.offsets.push_back(int(piece.verts.size()));
  }
  piece.n_vertices = int(old_index.size());
  out.set_faces(std::move(piece));
  out.complete.resize(old_index.size());
  if (m.is_base) {  // the neighbourhood's own vertices become the base of its dense stencils
    out.base_ids = old_index;
    std::sort(out.base_ids.begin(), out.base_ids.end());  // sorted, so combinations come out sorted
    for (const int v : old_index) {
      const auto at = std::lower_bound(out.base_ids.begin(), out.base_ids.end(), v) - out.base_ids.begin();
      out.points.push_back(Eigen::VectorXd::Unit(Eigen::Index(old_index.size()), Eigen::Index(at)));
    }
  } else {
    out.base_ids = m.base_ids;
    for (const int v : old_index) out.points.push_back(m.points[size_t(v)]);
  }
  for (size_t i = 0; i < old_index.size(); ++i) {
    const int v = old_index[i];
    out.complete[i] = m.complete[size_t(v)] && out.connectivity().n_vertex_faces(int(i)) == c.n_vertex_faces(v);
  }
  if (m.has_creases()) {
    const auto& oc = out.connectivity();
    out.creases.edges.resize(size_t(oc.n_edges()));
    for (int e = 0; e < oc.n_edges(); ++e)
      out.creases.edges[size_t(e)] = m.creases.edges[size_t(m.find_edge(
          old_index[size_t(oc.edge_verts[2 * size_t(e)])], old_index[size_t(oc.edge_verts[2 * size_t(e) + 1])]))];
    for (const int v : old_index) out.creases.vertices.push_back(m.creases.vertices[size_t(v)]);
  }
  return out;
}

namespace {

// One step of either scheme: values by `refine_values`, topology by `refine_topology`; both number
// vertex points as the input's vertices, then one edge point per edge.
template <class Values, class Topology>
LocalMesh refine_piece(const LocalMesh& m, Values refine_values, Topology refine_topology) {
  LocalMesh out;
  out.base_ids = m.base_ids;
  // Unknown points (size 0) stand in as zeros; what they spoil is marked incomplete below.
  const Eigen::Index n_base = Eigen::Index(m.base_ids.size());
  std::vector<Eigen::VectorXd> points = m.points;
  for (auto& p : points)
    if (p.size() == 0) p = Eigen::VectorXd::Zero(n_base);
  out.points = refine_values(points, m.has_creases() ? &m.creases : nullptr);
  out.set_faces(refine_topology());
  if (m.has_creases())
    out.creases = refined_crease_level(m.topology(), m.connectivity(), m.creases, out.connectivity());
  const auto& c = m.connectivity();
  const int nv = m.topology().n_vertices, ne = c.n_edges();
  out.complete.assign(out.points.size(), 1);
  for (int v = 0; v < nv; ++v) out.complete[size_t(v)] = m.complete[size_t(v)];
  for (int e = 0; e < ne; ++e) {
    const bool both_faces = !c.is_boundary_edge(e);
    const bool known =
        m.complete[size_t(c.edge_verts[2 * size_t(e)])] || m.complete[size_t(c.edge_verts[2 * size_t(e) + 1])];
    out.complete[size_t(nv + e)] = both_faces || known;
  }
  for (size_t i = 0; i < out.points.size(); ++i)
    if (!out.complete[i]) out.points[i].resize(0);  // never read: see refine_local_mesh()
  return out;
}

}  // namespace

LocalMesh refine_local_mesh(const LocalMesh& m) {
  return refine_piece(
      m,
      [&](const std::vector<Eigen::VectorXd>& points, const CreaseLevel* creases) {
        return catmull_clark_values(m.topology(), m.connectivity(), points, creases);
      },
      [&] { return catmull_clark_topology(m.topology(), m.connectivity()); });
}

LocalMesh refine_local_mesh_loop(const LocalMesh& m, LoopBeta beta) {
  return refine_piece(
      m,
      [&](const std::vector<Eigen::VectorXd>& points, const CreaseLevel* creases) {
        return loop_values(m.topology(), m.connectivity(), points, beta, creases);
      },
      [&] { return loop_topology(m.topology(), m.connectivity()); });
}

}  // namespace gps
