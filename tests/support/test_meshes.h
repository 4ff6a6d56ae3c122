#pragma once
// Small covariance meshes built inside the tests (no files).
#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "core/modelling/samples.h"
#include "tests/support/random_spd.h"

namespace gps::test {

/// An (n × m)-quad grid of unit quads in z = 0, vertex j (n + 1) + i at (i, j), faces facing +z, the
/// covariance `variance`·I everywhere; messages name it `source`.
inline CovarianceMesh flat_grid(int n, int m, double variance, const std::string& source = "mesh") {
  std::vector<Vec3> p;
  std::vector<std::vector<int>> faces;
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= n; ++i) p.emplace_back(i, j, 0);
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i;
      faces.push_back({a, a + 1, a + n + 2, a + n + 1});
    }
  return make_covariance_mesh(p, std::vector<Mat3>(p.size(), variance * Mat3::Identity()), faces, source);
}

/// An (n × m)-quad grid of unit quads, vertex j (n + 1) + i at (i, j), with a gentle bump in z unless
/// `flat`; faces facing +z; covariance sigma²·I everywhere.
inline CovarianceMesh grid_mesh(int n, int m, double sigma = 0.3, bool flat = false) {
  CovarianceMesh mesh = flat_grid(n, m, sigma * sigma, "grid");
  if (!flat)
    for (int j = 0; j <= m; ++j)
      for (int i = 0; i <= n; ++i)
        mesh.set_mean(size_t(j * (n + 1) + i), Vec3(i, j, 0.3 * std::sin(0.7 * i) * std::cos(0.5 * j) + 0.05 * i * j));
  return mesh;
}

/// The unit cube, 8 vertices and 6 outward quads.
inline CovarianceMesh cube_mesh(double sigma = 0.3) {
  std::vector<Vec3> p = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                         {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  std::vector<std::vector<int>> faces = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                         {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
  return make_covariance_mesh(p, std::vector<Mat3>(8, sigma * sigma * Mat3::Identity()), faces, "cube");
}

/// Preiner's cone: apex (0, 1.5, 0), 8 vertices on a circle of radius 2 at y = −1.5, open bottom.
inline CovarianceMesh cone_mesh(const Mat3& apex_covariance = 0.01 * Mat3::Identity()) {
  std::vector<Vec3> p = {{0, 1.5, 0}};
  for (int k = 0; k < 8; ++k) p.emplace_back(2 * std::cos(k * M_PI / 4), -1.5, -2 * std::sin(k * M_PI / 4));
  std::vector<std::vector<int>> faces;
  for (int k = 0; k < 8; ++k) faces.push_back({0, 1 + k, 1 + (k + 1) % 8});
  std::vector<Mat3> cov(p.size(), 0.01 * Mat3::Identity());
  cov[0] = apex_covariance;
  return make_covariance_mesh(p, cov, faces, "cone");
}

/// A closed mesh of mixed faces: a pentagonal prism (two pentagons, five quads), irregular sizes.
inline CovarianceMesh prism_mesh(double sigma = 0.4) {
  std::vector<Vec3> p;
  for (int k = 0; k < 5; ++k) p.emplace_back(std::cos(k * 2 * M_PI / 5), std::sin(k * 2 * M_PI / 5), -0.7);
  for (int k = 0; k < 5; ++k) p.emplace_back(1.2 * std::cos(k * 2 * M_PI / 5), 1.2 * std::sin(k * 2 * M_PI / 5), 0.9);
  std::vector<std::vector<int>> faces = {{4, 3, 2, 1, 0}, {5, 6, 7, 8, 9}};
  for (int k = 0; k < 5; ++k) faces.push_back({k, (k + 1) % 5, 5 + (k + 1) % 5, 5 + k});
  return make_covariance_mesh(p, std::vector<Mat3>(p.size(), sigma * sigma * Mat3::Identity()), faces, "prism");
}

/// The icosahedron of circumradius 1: 12 vertices of valence 5, 20 outward triangles.
inline CovarianceMesh icosahedron_mesh(double sigma = 0.3) {
  const double g = (1 + std::sqrt(5.0)) / 2, s = 1 / std::sqrt(1 + g * g);
  std::vector<Vec3> p = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                         {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
  for (auto& x : p) x *= s;
  std::vector<std::vector<int>> faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                         {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                         {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                         {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  return make_covariance_mesh(p, std::vector<Mat3>(p.size(), sigma * sigma * Mat3::Identity()), faces, "icosahedron");
}

/// A closed bipyramid: two apexes of valence n over a ring of n vertices of valence 4.
inline CovarianceMesh bipyramid_mesh(int n, double sigma = 0.3) {
  std::vector<Vec3> p = {{0, 0, 1.2}, {0, 0, -0.9}};
  for (int k = 0; k < n; ++k)
    p.emplace_back(std::cos(2 * M_PI * k / n), std::sin(2 * M_PI * k / n), 0.1 * std::sin(3.0 * k));
  std::vector<std::vector<int>> faces;
  for (int k = 0; k < n; ++k) {
    faces.push_back({0, 2 + k, 2 + (k + 1) % n});
    faces.push_back({1, 2 + (k + 1) % n, 2 + k});
  }
  return make_covariance_mesh(p, std::vector<Mat3>(p.size(), sigma * sigma * Mat3::Identity()), faces, "bipyramid");
}

/// An open triangle grid of n × m cells (two triangles each) with a bump: regular inside, boundary
/// vertices of 3 faces, corners of 1 and 2 faces.
inline CovarianceMesh triangle_grid_mesh(int n, int m, double sigma = 0.3) {
  std::vector<Vec3> p;
  std::vector<std::vector<int>> faces;
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= n; ++i) p.emplace_back(i + 0.5 * j, 0.87 * j, 0.4 * std::sin(0.9 * i) * std::cos(0.6 * j));
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i;
      faces.push_back({a, a + 1, a + n + 1});
      faces.push_back({a + 1, a + n + 2, a + n + 1});
    }
  return make_covariance_mesh(p, std::vector<Mat3>(p.size(), sigma * sigma * Mat3::Identity()), faces, "triangle grid");
}

/// Every covariance replaced by a random anisotropic one of about the same size.
inline CovarianceMesh with_random_covariances(CovarianceMesh m, unsigned seed) {
  std::mt19937 rng(seed);
  for (auto& c : m.covariances) c = (c.trace() / 3.0) * 0.3 * random_spd(rng, 0.2 / 0.3);
  return m;
}

/// A mixed open cylinder: two rings of 8 quads, a fan of 8 triangles closing the top, the bottom
/// open (seen from above, the inside stays hidden); T-junctions where the quads meet the fan.
inline CovarianceMesh open_cylinder_mesh(double sigma = 0.4) {
  std::vector<Vec3> p;
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 8; ++k) p.emplace_back(std::cos(k * M_PI / 4), -1.0 + r, -std::sin(k * M_PI / 4));
  p.emplace_back(0, 1.3, 0);
  std::vector<std::vector<int>> faces;
  for (int r = 0; r < 2; ++r)
    for (int k = 0; k < 8; ++k)
      faces.push_back({r * 8 + k, r * 8 + (k + 1) % 8, (r + 1) * 8 + (k + 1) % 8, (r + 1) * 8 + k});
  for (int k = 0; k < 8; ++k) faces.push_back({24, 16 + k, 16 + (k + 1) % 8});
  return make_covariance_mesh(p, std::vector<Mat3>(p.size(), sigma * sigma * Mat3::Identity()), faces, "open-cylinder");
}

/// The torus turned about a generic axis, each vertex's Gaussian of mean σ s (its isotropic σ) made a
/// disc (σ along the vertex normal divided by `ratio`) or a needle (σ across the normal divided by it):
/// condition number ratio².
inline CovarianceMesh thin_torus(double ratio, bool needle) {
  CovarianceMesh mesh = make_sample("torus");
  const Mat3 turn = Eigen::AngleAxisd(0.7, Vec3(0.3, 1.0, 0.5).normalized()).toRotationMatrix();
  for (size_t i = 0; i < mesh.n_vertices(); ++i) mesh.set_mean(i, turn * mesh.mean(i));
  const Vec3 axis = turn * Vec3::UnitY();  // the torus' axis of revolution
  for (size_t i = 0; i < mesh.n_vertices(); ++i) {
    // The normal of a torus point: from the nearest point of its core circle.
    const Vec3 p = mesh.mean(i), flat = p - p.dot(axis) * axis;
    const Vec3 n = (p - 2.0 * flat.normalized()).normalized();
    const double s = std::cbrt(std::sqrt(mesh.covariance(i).determinant()));
    const Mat3 along = n * n.transpose(), across = Mat3::Identity() - along;
    const double thin = s / ratio;
    mesh.set_covariance(
        i, needle ? Mat3(thin * thin * across + s * s * along) : Mat3(s * s * across + thin * thin * along));
  }
  return mesh;
}

/// The torus sample with every Gaussian of condition number `condition` and one orientation, turned
/// off the coordinate axes: a needle (long along one axis, σ along it the vertex's isotropic σ) or a
/// disc (thin along it, σ across it the isotropic σ). Σ = σ² M with one M, so the products weigh the
/// means as σ² I does and the limit surface is the torus sample's own (bounds ±2.64 across its axis);
/// their sums keep the condition number, where Gaussians of varying orientation average it away.
inline CovarianceMesh one_orientation_torus(double condition, bool needle) {
  CovarianceMesh mesh = make_sample("torus");
  const Vec3 axis = Eigen::AngleAxisd(0.7, Vec3(0.3, 1.0, 0.5).normalized()) * Vec3::UnitX();
  const Mat3 along = axis * axis.transpose(), across = Mat3::Identity() - along;
  for (size_t i = 0; i < mesh.n_vertices(); ++i) {
    const double s2 = std::cbrt(mesh.covariance(i).determinant());
    mesh.set_covariance(
        i, needle ? Mat3(s2 * along + (s2 / condition) * across) : Mat3((s2 / condition) * along + s2 * across));
  }
  return mesh;
}

}  // namespace gps::test
