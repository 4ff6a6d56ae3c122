#pragma once
// What the fitting tests fit to (a cube's faces as grids of triangles, mapped to a block with sharp
// edges or a bumpy, optionally noisy, sphere), the mean length of each vertex's edges (what the fit's
// bounds on the standard deviations are relative to) and the check that two fits gave the same Gaussians.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <random>
#include <vector>

#include "core/mesh/covariance_mesh.h"

namespace gps::test {

/// A cube [−1, 1]³'s faces as n × n grids of triangles, welded; `shape` maps each point.
template <class Shape>
inline CovarianceMesh cube_surface(int n, Shape shape) {
  std::map<std::array<int, 3>, int> index;
  std::vector<Vec3> points;
  std::vector<std::vector<int>> faces;
  const auto vertex = [&](const std::array<int, 3>& key) {
    const auto [it, added] = index.try_emplace(key, int(points.size()));
    if (added) points.push_back(shape(Vec3(key[0], key[1], key[2]) / n - Vec3::Ones()));
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (const int side : {0, 2 * n})
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          int q[4];
          const int corners[4][2] = {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}};
          for (int c = 0; c < 4; ++c) {
            std::array<int, 3> key;
            key[size_t(axis)] = 2 * corners[c][0];
            key[size_t((axis + 1) % 3)] = 2 * corners[c][1];
            key[size_t((axis + 2) % 3)] = side;
            q[c] = vertex(key);
          }
          if (side == 0) std::swap(q[1], q[3]);
          faces.push_back({q[0], q[1], q[2]});
          faces.push_back({q[0], q[2], q[3]});
        }
  return make_covariance_mesh(points, std::vector<Mat3>(points.size(), Mat3::Identity()), faces);
}

/// A block of 2 x 1.2 x 0.8 with sharp edges.
inline CovarianceMesh block(int n) {
  return cube_surface(n, [](const Vec3& p) { return Vec3(p.cwiseProduct(Vec3(1.0, 0.6, 0.4))); });
}

/// The unit sphere with smooth bumps, plus Gaussian noise of standard deviation `noise` at each point.
inline CovarianceMesh bumpy_sphere(int n, double noise = 0) {
  std::mt19937 random(7);
  std::normal_distribution<double> normal(0, noise > 0 ? noise : 1);
  return cube_surface(n, [&](const Vec3& p) {
    const Vec3 d = p.normalized();
    const double r = 1 + 0.08 * std::sin(5 * d[0]) * std::sin(4 * d[1] + 1) + 0.05 * std::cos(6 * d[2]);
    Vec3 x = r * d;
    if (noise > 0) x += Vec3(normal(random), normal(random), normal(random)) * noise;
    return x;
  });
}

/// The mean length of each vertex's edges.
inline std::vector<double> mean_edge_lengths(const CovarianceMesh& m) {
  std::vector<double> out;
  const MeshConnectivity& c = m.connectivity();
  for (int v = 0; v < int(m.n_vertices()); ++v) {
    double sum = 0;
    for (int i = c.vertex_edge_offsets[size_t(v)]; i < c.vertex_edge_offsets[size_t(v) + 1]; ++i)
      sum += (m.mean(size_t(v)) - m.mean(size_t(c.other_vertex(c.vertex_edges[size_t(i)], v)))).norm();
    out.push_back(sum / double(m.valence(size_t(v))));
  }
  return out;
}

/// Bit for bit the same means and covariances.
inline void expect_same_gaussians(const CovarianceMesh& a, const CovarianceMesh& b) {
  ASSERT_EQ(a.n_vertices(), b.n_vertices());
  for (size_t i = 0; i < a.n_vertices(); ++i) {
    EXPECT_EQ(a.mean(i), b.mean(i)) << "vertex " << i;
    EXPECT_EQ(a.covariance(i), b.covariance(i)) << "vertex " << i;
  }
}

}  // namespace gps::test
