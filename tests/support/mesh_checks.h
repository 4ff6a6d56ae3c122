#pragma once
// What the modelling tests check of a result: its counts, whether it is closed and consistently
// oriented, and the volume it encloses.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <vector>

#include "core/modelling/mesh_arrays.h"

namespace gps::test {

/// Counts of a mesh and whether its orientation is consistent (every directed edge once).
struct Shape {
  int vertices = 0, edges = 0, faces = 0, boundary_edges = 0;
  bool oriented = true;
  int euler() const { return vertices - edges + faces; }
};

inline Shape shape_of(const MeshArrays& a) {
  std::map<std::pair<int, int>, int> directed;
  for (const auto& face : a.faces)
    for (size_t k = 0; k < face.size(); ++k) ++directed[{face[k], face[(k + 1) % face.size()]}];
  Shape s;
  s.vertices = a.n_vertices();
  s.faces = a.n_faces();
  std::set<std::pair<int, int>> undirected;
  for (const auto& [e, n] : directed) {
    s.oriented = s.oriented && n == 1;
    undirected.insert({std::min(e.first, e.second), std::max(e.first, e.second)});
    if (!directed.count({e.second, e.first})) ++s.boundary_edges;
  }
  s.edges = int(undirected.size());
  return s;
}
inline Shape shape_of(const CovarianceMesh& mesh) { return shape_of(arrays_of(mesh)); }

/// The boundary edges of a mesh that must be consistently oriented (every directed edge once).
inline int boundary_edges_of_oriented(const CovarianceMesh& mesh) {
  const Shape s = shape_of(mesh);
  EXPECT_TRUE(s.oriented) << "a directed edge is used twice";
  return s.boundary_edges;
}

/// The volume the faces from `first_face` on enclose (fanned from each face's first corner), positive
/// where they are oriented outward.
inline double signed_volume(const MeshArrays& a, size_t first_face = 0) {
  double six_volume = 0;
  for (size_t f = first_face; f < a.faces.size(); ++f) {
    const std::vector<int>& face = a.faces[f];
    for (size_t k = 1; k + 1 < face.size(); ++k)
      six_volume += a.means[size_t(face[0])].dot(a.means[size_t(face[k])].cross(a.means[size_t(face[k + 1])]));
  }
  return six_volume / 6;
}
inline double signed_volume(const CovarianceMesh& mesh) { return signed_volume(arrays_of(mesh)); }

/// Expects a closed solid of these counts, consistently oriented and facing outward.
inline void expect_closed_outward(const CovarianceMesh& mesh, int vertices, int faces) {
  const Shape shape = shape_of(mesh);
  EXPECT_EQ(shape.vertices, vertices);
  EXPECT_EQ(shape.faces, faces);
  EXPECT_EQ(shape.boundary_edges, 0);
  EXPECT_TRUE(shape.oriented);
  EXPECT_GT(signed_volume(mesh), 0.0);
}

/// Whether two meshes have the same Gaussians, faces and sharpness, bit for bit.
inline bool same_mesh(const CovarianceMesh& x, const CovarianceMesh& y) {
  const MeshArrays a = arrays_of(x), b = arrays_of(y);
  return a.means == b.means && a.covariances == b.covariances && a.faces == b.faces && a.sharpness == b.sharpness;
}

/// Whether two meshes have the same faces and sharpness, and Gaussians within `tolerance` of each
/// other (each mean and covariance entry): the same operations reached by another rounding.
inline bool nearly_same_mesh(const CovarianceMesh& x, const CovarianceMesh& y, double tolerance) {
  const MeshArrays a = arrays_of(x), b = arrays_of(y);
  if (a.faces != b.faces || !(a.sharpness == b.sharpness) || a.means.size() != b.means.size()) return false;
  for (size_t v = 0; v < a.means.size(); ++v)
    if ((a.means[v] - b.means[v]).cwiseAbs().maxCoeff() > tolerance ||
        (a.covariances[v] - b.covariances[v]).cwiseAbs().maxCoeff() > tolerance)
      return false;
  return true;
}

/// Expects two meshes' arrays to be the same, bit for bit: the faces, then each vertex's mean and
/// covariance.
inline void expect_same_arrays(const MeshArrays& a, const MeshArrays& b) {
  EXPECT_EQ(a.faces, b.faces);
  ASSERT_EQ(a.means.size(), b.means.size());
  ASSERT_EQ(a.covariances.size(), b.covariances.size());
  for (size_t v = 0; v < a.means.size(); ++v) {
    EXPECT_EQ(a.means[v], b.means[v]) << "vertex " << v;
    EXPECT_EQ(a.covariances[v], b.covariances[v]) << "vertex " << v;
  }
}

}  // namespace gps::test
