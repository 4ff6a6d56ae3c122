#include "core/fitting/face_triangles.h"

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

}  // namespace gps
