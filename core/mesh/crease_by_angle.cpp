#include "core/mesh/crease_by_angle.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace gps {

namespace {

// Newell's normal of a face (twice its vector area), from the means.
Vec3 face_normal(const CovarianceMesh& m, size_t f) {
  Vec3 n = Vec3::Zero();
  const std::span<const int> corners = m.face(f);
  for (size_t k = 0, previous = corners.size() - 1; k < corners.size(); previous = k++)
    n += m.mean(size_t(corners[previous])).cross(m.mean(size_t(corners[k])));
  return n;
}

}  // namespace

std::vector<double> dihedral_angles(const CovarianceMesh& m) {
  std::vector<Vec3> normals(m.n_faces());
  for (size_t f = 0; f < m.n_faces(); ++f) normals[f] = face_normal(m, f);
  std::vector<double> angles(m.n_edges(), -1.0);
  const std::vector<int>& edge_faces = m.connectivity().edge_faces;
  for (size_t e = 0; e < m.n_edges(); ++e) {
    if (m.is_boundary_edge(e)) continue;
    const Vec3& n0 = normals[size_t(edge_faces[2 * e])];
    const Vec3& n1 = normals[size_t(edge_faces[2 * e + 1])];
    const double length = n0.norm() * n1.norm();
    if (!(length > 0)) continue;
    // atan2 of |n0 × n1| and n0 · n1: accurate at small and large angles alike.
    angles[e] = std::atan2(n0.cross(n1).norm(), n0.dot(n1)) * 180.0 / M_PI;
  }
  return angles;
}

namespace {
constexpr double kAngleRounding = 1e-11;  // degrees
}  // namespace

std::vector<std::array<int, 2>> edges_sharper_than(const CovarianceMesh& m, double degrees) {
  const std::vector<double> angles = dihedral_angles(m);
  std::vector<std::array<int, 2>> sharp;
  for (size_t e = 0; e < m.n_edges(); ++e) {
    const double angle = angles[e];
    // An angle the threshold's within the rounding of the faces' normals is the threshold: edges alike
    // by symmetry get the same answer.
    if (angle < 0 || !(angle > degrees + kAngleRounding)) continue;
    sharp.push_back(m.edge(e));
  }
  std::sort(sharp.begin(), sharp.end());
  return sharp;
}

int crease_by_angle(CovarianceMesh& m, double degrees) {
  const std::vector<std::array<int, 2>> sharp = edges_sharper_than(m, degrees);
  std::vector<EdgeCrease>& creases = m.sharpness.creases;
  for (const auto& [a, b] : sharp) creases.push_back({a, b, kInfiniteSharpness});
  // Sorted with the sharper of two on one edge first, the duplicates after it dropped.
  std::sort(creases.begin(), creases.end(), [](const EdgeCrease& x, const EdgeCrease& y) {
    return x.a != y.a ? x.a < y.a : x.b != y.b ? x.b < y.b : x.sharpness > y.sharpness;
  });
  creases.erase(std::unique(creases.begin(), creases.end(),
                            [](const EdgeCrease& x, const EdgeCrease& y) { return x.a == y.a && x.b == y.b; }),
                creases.end());
  return int(sharp.size());
}

}  // namespace gps
