#include "core/local_mesh.h"

#include <algorithm>

#include "core/catmull_clark.h"

namespace gps {

int LocalMesh::find_edge(int a, int b) const {
  const auto& c = connectivity;
  for (int i = c.vertex_edge_offsets[size_t(a)]; i < c.vertex_edge_offsets[size_t(a) + 1]; ++i)
    if (c.other_vertex(c.vertex_edges[size_t(i)], a) == b) return c.vertex_edges[size_t(i)];
  return -1;
}

int LocalMesh::find_face(const std::vector<int>& corners) const {
  const auto& c = connectivity;
  const int v = corners[0];
  for (int i = c.vertex_face_offsets[size_t(v)]; i < c.vertex_face_offsets[size_t(v) + 1]; ++i) {
    const int f = c.vertex_faces[size_t(i)];
    if (topology.face_size(f) != int(corners.size())) continue;
    const auto begin = topology.verts.begin() + topology.offsets[size_t(f)];
    const auto end = topology.verts.begin() + topology.offsets[size_t(f) + 1];
    if (std::all_of(corners.begin(), corners.end(), [&](int x) { return std::find(begin, end, x) != end; })) return f;
  }
  return -1;
}

LocalMesh base_local_mesh(const PolygonTopology& topology) {
  LocalMesh m;
  m.topology = topology;
  m.connectivity = connectivity_of(topology);
  m.complete.assign(size_t(topology.n_vertices), 1);
  m.is_base = true;
  return m;
}

LocalMesh extract_neighbourhood(const LocalMesh& m, const std::vector<int>& corners, std::vector<int>& new_index) {
  const auto& c = m.connectivity;
  std::vector<int> faces;
  for (const int v : corners)
    for (int i = c.vertex_face_offsets[size_t(v)]; i < c.vertex_face_offsets[size_t(v) + 1]; ++i)
      faces.push_back(c.vertex_faces[size_t(i)]);
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());

  LocalMesh out;
  new_index.assign(size_t(m.topology.n_vertices), -1);
  std::vector<int> old_index;
  for (const int f : faces) {
    for (int i = m.topology.offsets[size_t(f)]; i < m.topology.offsets[size_t(f) + 1]; ++i) {
      const int v = m.topology.verts[size_t(i)];
      if (new_index[size_t(v)] < 0) {
        new_index[size_t(v)] = int(old_index.size());
        old_index.push_back(v);
      }
      out.topology.verts.push_back(new_index[size_t(v)]);
    }
    out.topology.offsets.push_back(int(out.topology.verts.size()));
  }
  out.topology.n_vertices = int(old_index.size());
  out.connectivity = connectivity_of(out.topology);
  out.points.reserve(old_index.size());
  out.complete.resize(old_index.size());
  for (size_t i = 0; i < old_index.size(); ++i) {
    const int v = old_index[i];
    out.points.push_back(m.point(v));
    out.complete[i] = m.complete[size_t(v)] && out.connectivity.n_vertex_faces(int(i)) == c.n_vertex_faces(v);
  }
  return out;
}

LocalMesh refine_local_mesh(const LocalMesh& m) {
  LocalMesh out;
  std::vector<Stencil> points = m.points;
  if (m.is_base) {
    points.resize(size_t(m.topology.n_vertices));
    for (int v = 0; v < m.topology.n_vertices; ++v) points[size_t(v)] = Stencil::vertex(v);
  }
  out.points = catmull_clark_values(m.topology, m.connectivity, points);
  out.topology = catmull_clark_topology(m.topology, m.connectivity);
  out.connectivity = connectivity_of(out.topology);
  const auto& c = m.connectivity;
  const int nv = m.topology.n_vertices, ne = c.n_edges();
  out.complete.assign(out.points.size(), 1);
  for (int v = 0; v < nv; ++v) out.complete[size_t(v)] = m.complete[size_t(v)];
  for (int e = 0; e < ne; ++e) {
    const bool both_faces = !c.is_boundary_edge(e);
    const bool known = m.complete[size_t(c.edge_verts[2 * size_t(e)])] || m.complete[size_t(c.edge_verts[2 * size_t(e) + 1])];
    out.complete[size_t(nv + e)] = both_faces || known;
  }
  for (size_t i = 0; i < out.points.size(); ++i)
    if (!out.complete[i]) out.points[i] = Stencil();  // never read: see refine_local_mesh()
  return out;
}

}  // namespace gps
