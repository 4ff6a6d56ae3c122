#include "core/modelling/shapes.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <utility>

#include "core/modelling/primitives.h"
#include "core/modelling/samples.h"

namespace gps {
namespace {

// Directed edges of the faces: each may appear once; returns how many have no reverse (boundary).
int boundary_edges_of_oriented(const Shape& s) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& f : s.faces)
    for (size_t k = 0; k < f.size(); ++k) ++uses[{f[k], f[(k + 1) % f.size()]}];
  int boundary = 0;
  for (const auto& [edge, n] : uses) {
    EXPECT_EQ(n, 1) << "edge " << edge.first << "-" << edge.second << " used twice in one direction";
    boundary += uses.count({edge.second, edge.first}) == 0;
  }
  return boundary;
}

// Σ of the faces' fan triangles' signed volumes about the origin: positive when they face outward.
double signed_volume(const Shape& s) {
  double volume = 0;
  for (const auto& f : s.faces)
    for (size_t k = 1; k + 1 < f.size(); ++k)
      volume += s.points[size_t(f[0])].dot(s.points[size_t(f[k])].cross(s.points[size_t(f[k + 1])])) / 6;
  return volume;
}

TEST(Shapes, CubeIsTheClosedOutwardCubeOfSideTwo) {
  const Shape s = cube_shape();
  ASSERT_EQ(s.points.size(), 8u);
  ASSERT_EQ(s.faces.size(), 6u);
  for (const Vec3& p : s.points) EXPECT_EQ(p.cwiseAbs(), Vec3(1, 1, 1));
  EXPECT_EQ(boundary_edges_of_oriented(s), 0);
  EXPECT_DOUBLE_EQ(signed_volume(s), 8.0);
}

TEST(Shapes, CylinderHasItsRingsAndTwoCaps) {
  const Shape s = cylinder_shape(8, 3, 2.0, -1.0, 0.5);
  ASSERT_EQ(s.points.size(), 24u);
  ASSERT_EQ(s.faces.size(), 16u + 2u);
  for (size_t v = 0; v < s.points.size(); ++v) {
    EXPECT_NEAR(std::hypot(s.points[v].x(), s.points[v].z()), 2.0, 1e-15);
    EXPECT_EQ(s.points[v].y(), -1.0 + 0.5 * double(v / 8));
  }
  EXPECT_EQ(s.faces[16].size(), 8u);
  EXPECT_EQ(s.faces[17].size(), 8u);
  EXPECT_EQ(boundary_edges_of_oriented(s), 0);
  EXPECT_GT(signed_volume(s), 0);
}

TEST(Shapes, ConeIsOpenOrClosedAtItsBase) {
  const Shape open = cone_shape(8, 2.0, 1.5, -1.5, false), closed = cone_shape(8, 2.0, 1.5, -1.5, true);
  EXPECT_EQ(open.points.size(), 9u);
  EXPECT_EQ(open.faces.size(), 8u);
  EXPECT_EQ(closed.faces.size(), 9u);
  EXPECT_EQ(open.points[0], Vec3(0, 1.5, 0));
  EXPECT_EQ(boundary_edges_of_oriented(open), 8);
  EXPECT_EQ(boundary_edges_of_oriented(closed), 0);
  EXPECT_GT(signed_volume(closed), 0);
}

TEST(Shapes, CubeSphereHasUnitPointsAndSixGridsOfQuads) {
  for (const int m : {1, 2, 5}) {
    const Shape s = cube_sphere_shape(m);
    EXPECT_EQ(s.faces.size(), size_t(6 * m * m));
    EXPECT_EQ(s.points.size(), size_t(6 * m * m + 2));  // Euler: V − E + F = 2 with E = 2F
    for (const Vec3& p : s.points) EXPECT_NEAR(p.norm(), 1.0, 1e-15);
    EXPECT_EQ(boundary_edges_of_oriented(s), 0);
    EXPECT_GT(signed_volume(s), 0);
  }
}

TEST(Shapes, TorusIsClosedWithItsRadii) {
  const Shape s = torus_shape(10, 6, 2.0, 0.5);
  EXPECT_EQ(s.points.size(), 60u);
  EXPECT_EQ(s.faces.size(), 60u);
  for (const Vec3& p : s.points) {
    const double from_ring = std::hypot(std::hypot(p.x(), p.z()) - 2.0, p.y());
    EXPECT_NEAR(from_ring, 0.5, 1e-14);
  }
  EXPECT_EQ(boundary_edges_of_oriented(s), 0);
  EXPECT_GT(signed_volume(s), 0);
}

// The samples and the primitives are made of these shapes: the same points, bit for bit.
TEST(Shapes, SamplesAndPrimitivesAreMadeOfThem) {
  const CovarianceMesh cube = make_sample("cube");
  const Shape c = cube_shape();
  ASSERT_EQ(cube.n_vertices(), c.points.size());
  for (size_t v = 0; v < c.points.size(); ++v) EXPECT_EQ(cube.mean(v), c.points[v]);
  const CovarianceMesh torus = make_sample("torus");
  const Shape t = torus_shape(24, 12, 2.0, 0.7);
  ASSERT_EQ(torus.n_vertices(), t.points.size());
  for (size_t v = 0; v < t.points.size(); ++v) EXPECT_EQ(torus.mean(v), t.points[v]);
  // A primitive of size 2 at the origin is its shape at extent 1 doubled, exactly.
  const Modelled sphere = add_primitive(CovarianceMesh{}, Primitive::sphere, Vec3::Zero(), 2.0);
  const Shape s = cube_sphere_shape(2);
  ASSERT_EQ(sphere.mesh.n_vertices(), s.points.size());
  for (size_t v = 0; v < s.points.size(); ++v) EXPECT_EQ(sphere.mesh.mean(v), s.points[v]);
}

}  // namespace
}  // namespace gps
