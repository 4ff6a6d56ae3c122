#include "core/fitting/face_triangles.h"

#include <cmath>
#include <numbers>
#include <span>

namespace gps {

TriangleMesh face_triangles(const CovarianceMesh& mesh) {
  TriangleMesh result;
  result.positions = mesh.means();
  result.normals.assign(result.positions.size(), Vec3::Zero());
  for (size_t f = 0; f < mesh.n_faces(); ++f) {
    const std::span<const int> corners = mesh.face(f);
    for (size_t k = 1; k + 1 < corners.size(); ++k)
      result.triangles.push_back({corners[0], corners[k], corners[k + 1]});
  }
  fill_missing_normals(result);
  return result;
}

TriangleMesh face_triangles(const PolygonSoup& soup) {
  TriangleMesh result;
  result.positions = soup.positions;
  result.normals.assign(result.positions.size(), Vec3::Zero());
  const PolygonTopology& t = soup.faces;
  for (int f = 0; f < t.n_faces(); ++f) {
    const int first = t.offsets[size_t(f)], end = t.offsets[size_t(f) + 1];
    for (int k = first + 1; k + 1 < end; ++k)
      result.triangles.push_back({t.verts[size_t(first)], t.verts[size_t(k)], t.verts[size_t(k + 1)]});
  }
  fill_missing_normals(result);
  return result;
}

std::vector<Vec3> smooth_vertex_normals(const TriangleMesh& fans, double max_angle) {
  std::vector<Vec3> normals = fans.normals;
  const double least_cosine = std::cos(max_angle * std::numbers::pi / 180);
  for (const auto& t : fans.triangles) {
    const Vec3 n = (fans.positions[size_t(t[1])] - fans.positions[size_t(t[0])])
                       .cross(fans.positions[size_t(t[2])] - fans.positions[size_t(t[0])]);
    const double length = n.norm();
    if (!(length > 0)) continue;
    for (const int v : t)
      if (normals[size_t(v)].dot(n) < least_cosine * length * normals[size_t(v)].norm())
        normals[size_t(v)] = Vec3::Zero();
  }
  for (Vec3& n : normals)
    if (n.norm() > 0) n.normalize();
  return normals;
}

}  // namespace gps
