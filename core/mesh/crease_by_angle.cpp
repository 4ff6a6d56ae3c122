#include "core/mesh/crease_by_angle.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace gps {

namespace {

// Newell's normal of a face (twice its vector area), from the means.
Vec3 face_normal(const CovarianceMesh& m, PolyMesh::FaceHandle f) {
  Vec3 n = Vec3::Zero();
  const auto h0 = m.mesh.halfedge_handle(f);
  auto h = h0;
  do {
    const Vec3 a = to_vec3(m.mesh.point(m.mesh.from_vertex_handle(h))),
               b = to_vec3(m.mesh.point(m.mesh.to_vertex_handle(h)));
    n += a.cross(b);
    h = m.mesh.next_halfedge_handle(h);
  } while (h != h0);
  return n;
}

}  // namespace

std::vector<double> dihedral_angles(const CovarianceMesh& m) {
  std::vector<Vec3> normals(m.n_faces());
  for (const auto f : m.mesh.faces()) normals[size_t(f.idx())] = face_normal(m, f);
  std::vector<double> angles(m.mesh.n_edges(), -1.0);
  for (const auto e : m.mesh.edges()) {
    if (m.mesh.is_boundary(e)) continue;
    const Vec3& n0 = normals[size_t(m.mesh.face_handle(m.mesh.halfedge_handle(e, 0)).idx())];
    const Vec3& n1 = normals[size_t(m.mesh.face_handle(m.mesh.halfedge_handle(e, 1)).idx())];
    const double length = n0.norm() * n1.norm();
    if (!(length > 0)) continue;
    // atan2 of |n0 × n1| and n0 · n1: accurate at small and large angles alike.
    angles[size_t(e.idx())] = std::atan2(n0.cross(n1).norm(), n0.dot(n1)) * 180.0 / M_PI;
  }
  return angles;
}

std::vector<std::array<int, 2>> edges_sharper_than(const CovarianceMesh& m, double degrees) {
  const std::vector<double> angles = dihedral_angles(m);
  std::vector<std::array<int, 2>> sharp;
  for (const auto e : m.mesh.edges()) {
    const double angle = angles[size_t(e.idx())];
    if (angle < 0 || !(angle > degrees)) continue;
    const int a = m.mesh.from_vertex_handle(m.mesh.halfedge_handle(e, 0)).idx();
    const int b = m.mesh.to_vertex_handle(m.mesh.halfedge_handle(e, 0)).idx();
    sharp.push_back({std::min(a, b), std::max(a, b)});
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
