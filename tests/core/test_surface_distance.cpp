// Distances from points to a surface: exact distances to triangles, a flat mesh's planar limit
// surface, and their summary.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/fitting/surface_distance.h"
#include "core/support/error.h"
#include "core/mesh/inference.h"

namespace gps {
namespace {

TEST(SurfaceDistance, ExactToOneTriangleInEveryRegion) {
  TriangleMesh t;
  t.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  t.triangles = {{0, 1, 2}};
  const SurfaceDistance d(t);
  EXPECT_NEAR(d.distance(Vec3(0.2, 0.2, 3)), 3, 1e-12);               // above the face
  EXPECT_NEAR(d.distance(Vec3(-1, -1, 0)), std::sqrt(2.0), 1e-12);    // nearest a corner
  EXPECT_NEAR(d.distance(Vec3(0.5, -2, 1)), std::sqrt(5.0), 1e-12);   // nearest an edge
  EXPECT_NEAR(d.distance(Vec3(1, 1, 0)), 1 / std::sqrt(2.0), 1e-12);  // nearest the hypotenuse
  EXPECT_NEAR(d.distance(Vec3(0.25, 0.25, 0)), 0, 1e-12);             // on it
}

TEST(SurfaceDistance, NearestOfManyTrianglesMatchesBruteForce) {
  // Triangles of a bumpy height field; the distance to each triangle alone, from a one-triangle
  // tree, gives the brute-force minimum.
  TriangleMesh t;
  const int n = 12;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) t.positions.emplace_back(i, j, std::sin(i * 0.7) * std::cos(j * 0.5));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const int a = i * (n + 1) + j;
      t.triangles.push_back({a, a + n + 1, a + n + 2});
      t.triangles.push_back({a, a + n + 2, a + 1});
    }
  const SurfaceDistance tree(t);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-2, n + 2);
  std::vector<Vec3> points;
  for (int k = 0; k < 200; ++k)
    points.emplace_back(coordinate(random), coordinate(random), coordinate(random) - n / 2.0);
  const std::vector<double> all = tree.distances(points);
  for (size_t k = 0; k < points.size(); ++k) {
    double nearest = INFINITY;
    for (const auto& triangle : t.triangles) {
      TriangleMesh one;
      one.positions = {t.positions[size_t(triangle[0])], t.positions[size_t(triangle[1])],
                       t.positions[size_t(triangle[2])]};
      one.triangles = {{0, 1, 2}};
      nearest = std::min(nearest, SurfaceDistance(one).distance(points[k]));
    }
    EXPECT_NEAR(all[k], nearest, 1e-12) << "point " << k;
  }
}

/// A flat n × n grid of unit squares in the plane z = 0, split into triangles, with inferred covariances
/// (flat discs in the plane): its limit surface lies in the plane.
CovarianceMesh inferred_triangle_grid(int n) {
  std::vector<Vec3> points;
  std::vector<std::vector<int>> faces;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) points.emplace_back(i, j, 0);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const int a = i * (n + 1) + j;
      faces.push_back({a, a + n + 1, a + n + 2});
      faces.push_back({a, a + n + 2, a + 1});
    }
  CovarianceMesh m = make_covariance_mesh(points, std::vector<Mat3>(points.size(), Mat3::Identity()), faces);
  infer_covariances(m);
  return m;
}

TEST(SurfaceDistance, PointsOffsetFromAPlanarLimitSurfaceAreTheirOffsetAway) {
  const CovarianceMesh grid = inferred_triangle_grid(8);
  const TriangleMesh limit = limit_surface_triangles(grid, 4).triangles;
  for (const Vec3& p : limit.positions) EXPECT_NEAR(p[2], 0, 1e-12);
  // Points above and below the grid's middle, well inside the limit surface's boundary.
  std::vector<Vec3> points;
  std::vector<double> offsets;
  for (int k = 0; k < 50; ++k) {
    const double offset = (k % 2 ? 1 : -1) * 0.01 * (k + 1);
    points.emplace_back(2 + 4.0 * k / 49, 6 - 4.0 * k / 49, offset);
    offsets.push_back(std::abs(offset));
  }
  const std::vector<double> d = SurfaceDistance(limit).distances(points);
  for (size_t k = 0; k < points.size(); ++k) EXPECT_NEAR(d[k], offsets[k], 1e-12) << "point " << k;
  const DistanceSummary s = distances_to_surface(points, limit);
  EXPECT_NEAR(s.max, 0.5, 1e-12);
  EXPECT_NEAR(s.length, bounding_box_diagonal(points), 1e-15);
  EXPECT_NEAR(s.relative_max(), 0.5 / s.length, 1e-12);
}

TEST(SurfaceDistance, LimitTrianglesKeepToTheirCount) {
  const CovarianceMesh grid = inferred_triangle_grid(8);  // 128 triangle patches: L² triangles each at level L
  const LimitTriangles full = limit_surface_triangles(grid, 8);
  EXPECT_EQ(full.level, 8);
  EXPECT_EQ(full.triangles.triangles.size(), 128u * 64);
  const LimitTriangles kept = limit_surface_triangles(grid, 8, {}, 128 * 30);
  EXPECT_EQ(kept.level, 5);
  EXPECT_EQ(kept.triangles.triangles.size(), 128u * 25);
  EXPECT_EQ(limit_surface_triangles(grid, 8, {}, 1).level, 1);
}

TEST(SurfaceDistance, SummaryIsRmsNearestRankPercentileAndMax) {
  std::vector<double> d;
  for (int k = 100; k >= 1; --k) d.push_back(k);  // 1..100, in reverse
  const DistanceSummary s = summarise_distances(d, 10);
  EXPECT_EQ(s.count, 100u);
  EXPECT_NEAR(s.rms, std::sqrt(338350.0 / 100), 1e-12);  // Σk² = 100·101·201/6
  EXPECT_EQ(s.percentile_99, 99);
  EXPECT_EQ(s.max, 100);
  EXPECT_NEAR(s.relative_rms(), s.rms / 10, 1e-15);
  EXPECT_EQ(summarise_distances({3.0}, 1).percentile_99, 3);
  EXPECT_EQ(summarise_distances({}, 1).count, 0u);
}

TEST(SurfaceDistance, DescribesEachFigureOnItsOwnLine) {
  const std::string text = describe(summarise_distances({1, 2, 2}, 4));
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 3);
  EXPECT_EQ(text.rfind("rms ", 0), 0u) << text;
  EXPECT_NE(text.find("99th percentile 2 (5.000e-01 of the diagonal)"), std::string::npos) << text;
  EXPECT_NE(text.find("max 2 (5.000e-01 of the diagonal)"), std::string::npos) << text;
}

TEST(SurfaceDistance, RefusesASurfaceWithoutTriangles) { EXPECT_THROW(SurfaceDistance(TriangleMesh{}), Error); }

}  // namespace
}  // namespace gps
