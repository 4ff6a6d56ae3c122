#include "ui/editing/covariance_presets.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>

#include "core/mesh/inference.h"

namespace gps {

Vec3 vertex_normal(const CovarianceMesh& mesh, int vertex) {
  const MeshConnectivity& c = mesh.connectivity();
  Vec3 sum = Vec3::Zero();
  for (int k = c.vertex_face_offsets[size_t(vertex)]; k < c.vertex_face_offsets[size_t(vertex) + 1]; ++k) {
    Vec3 area = Vec3::Zero();  // Newell's method: twice the vector area of the polygon
    const std::span<const int> corners = mesh.face(size_t(c.vertex_faces[size_t(k)]));
    for (size_t i = 0; i < corners.size(); ++i)
      area += mesh.mean(size_t(corners[i])).cross(mesh.mean(size_t(corners[(i + 1) % corners.size()])));
    sum += area;
  }
  return sum.norm() > 1e-300 ? Vec3(sum.normalized()) : Vec3::UnitZ();
}

double mean_sigma(const Mat3& covariance) { return std::pow(std::max(covariance.determinant(), 1e-300), 1.0 / 6.0); }

std::vector<Mat3> preset_covariances(const CovarianceMesh& mesh, const std::vector<int>& vertices,
                                     CovariancePreset preset, double sigma) {
  std::vector<Mat3> out;
  if (preset == CovariancePreset::inferred) {
    CovarianceMesh copy = mesh;
    infer_covariances(copy);
    for (const int v : vertices) out.push_back(copy.covariance(size_t(v)));
    return out;
  }
  for (const int v : vertices) {
    const Mat3& c = mesh.covariance(size_t(v));
    const Vec3 n = vertex_normal(mesh, v);
    const Mat3 along = n * n.transpose(), across = Mat3::Identity() - along;
    const double s = mean_sigma(c), thin = kFlatRatio * s;
    switch (preset) {
      case CovariancePreset::isotropic:
        out.push_back(sigma * sigma * Mat3::Identity());
        break;
      case CovariancePreset::disc:
        out.push_back(s * s * across + thin * thin * along);
        break;
      case CovariancePreset::needle:
        out.push_back(thin * thin * across + s * s * along);
        break;
      case CovariancePreset::sharpen:
        out.push_back(0.1 * c);
        break;
      case CovariancePreset::soften:
        out.push_back(10.0 * c);
        break;
      case CovariancePreset::inferred:
        break;
    }
  }
  return out;
}

}  // namespace gps
