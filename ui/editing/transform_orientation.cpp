#include "ui/editing/transform_orientation.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "core/modelling/extrude.h"
#include "core/modelling/mesh_queries.h"

namespace gps {

namespace {

// The unit part of `v` normal to `z` (unit), or zero where little is left.
Vec3 across(const Vec3& v, const Vec3& z) {
  const Vec3 p = v - z * v.dot(z);
  return p.norm() > 1e-9 * std::max(1.0, v.norm()) ? Vec3(p.normalized()) : Vec3(Vec3::Zero());
}

}  // namespace

const char* orientation_name(TransformOrientation orientation) {
  return orientation == TransformOrientation::normal ? "normal" : "global";
}

Mat3 normal_frame(const CovarianceMesh& mesh, const std::vector<int>& vertices) {
  return normal_frame(mesh, vertices, faces_within(mesh, vertices), edges_within(mesh, vertices));
}

Mat3 normal_frame(const CovarianceMesh& mesh, const std::vector<int>& vertices, const std::vector<int>& faces,
                  const std::vector<std::array<int, 2>>& selected_edges) {
  if (vertices.empty()) return Mat3::Identity();
  const MeshArrays arrays = arrays_of(mesh);
  Vec3 z = Vec3::Zero();
  for (const int f : faces) z += newell_normal(arrays, f);
  const MeshConnectivity& c = mesh.connectivity();
  if (faces.empty())
    for (const int v : vertices)
      for (int k = c.vertex_face_offsets[size_t(v)]; k < c.vertex_face_offsets[size_t(v) + 1]; ++k)
        z += newell_normal(arrays, c.vertex_faces[size_t(k)]);
  if (!(z.norm() > 0)) return Mat3::Identity();
  z.normalize();

  // The tangent: the longest selected edge (for one vertex, its longest edge) across the normal.
  std::vector<std::array<int, 2>> edges = selected_edges;
  if (vertices.size() == 1)
    for (int k = c.vertex_edge_offsets[size_t(vertices[0])]; k < c.vertex_edge_offsets[size_t(vertices[0]) + 1]; ++k)
      edges.push_back({vertices[0], c.other_vertex(c.vertex_edges[size_t(k)], vertices[0])});
  Vec3 y = Vec3::Zero();
  double longest = -1.0;
  for (const auto& [a, b] : edges) {
    const Vec3 d = arrays.means[size_t(b)] - arrays.means[size_t(a)];
    const Vec3 t = across(d, z);
    if (t != Vec3::Zero() && d.norm() > longest) longest = d.norm(), y = t;
  }
  if (y == Vec3::Zero()) {  // no edge to follow: the world axis least along the normal
    int least = 0;
    for (int i = 1; i < 3; ++i)
      if (std::abs(z[i]) < std::abs(z[least])) least = i;
    y = across(Vec3::Unit(least), z);
  }
  Mat3 frame;
  frame.col(0) = y.cross(z);
  frame.col(1) = y;
  frame.col(2) = z;
  return frame;
}

}  // namespace gps
