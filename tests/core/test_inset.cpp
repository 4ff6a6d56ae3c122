#include "core/modelling/inset.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <set>

#include "core/modelling/samples.h"
#include "tests/support/error_of.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

using test::error_of;

/// Whether every directed edge appears once, and how many have no reverse.
std::pair<bool, int> orientation_and_boundary(const CovarianceMesh& mesh) {
  const MeshArrays a = arrays_of(mesh);
  std::map<std::pair<int, int>, int> directed;
  for (const auto& face : a.faces)
    for (size_t k = 0; k < face.size(); ++k) ++directed[{face[k], face[(k + 1) % face.size()]}];
  bool once = true;
  int boundary = 0;
  for (const auto& [e, n] : directed) {
    once = once && n == 1;
    boundary += directed.count({e.second, e.first}) ? 0 : 1;
  }
  return {once, boundary};
}

/// Distance from point p to the line through a and b.
double distance_to_line(const Vec3& p, const Vec3& a, const Vec3& b) {
  return (p - a).cross(b - a).norm() / (b - a).norm();
}

// The cube's face 1 is its +z face: corners 4, 5, 6, 7 at (±1, ±1, 1).
TEST(InsetFaces, OneCubeFaceAddsFourVerticesAndFourQuadsAtTheThickness) {
  const CovarianceMesh cube = make_sample("cube");
  const MeshArrays before = arrays_of(cube);
  const double thickness = 0.3;
  const Modelled m = inset_faces(cube, {1}, thickness);
  EXPECT_EQ(int(m.mesh.n_vertices()), 12);
  EXPECT_EQ(int(m.mesh.n_faces()), 10);
  EXPECT_EQ(orientation_and_boundary(m.mesh), std::make_pair(true, 0));
  EXPECT_EQ(m.selection, (std::vector<int>{8, 9, 10, 11}));
  EXPECT_EQ(m.summary, "inset 1 face: 4 vertices, 4 faces added");

  const MeshArrays a = arrays_of(m.mesh);
  EXPECT_EQ(a.faces[1], (std::vector<int>{8, 9, 10, 11}));
  for (int k = 0; k < 4; ++k) {
    const Vec3& outer = before.means[size_t(4 + k)];
    const Vec3& inner = a.means[size_t(8 + k)];
    EXPECT_LT((inner - Vec3(0.7 * outer.x(), 0.7 * outer.y(), 1)).norm(), 1e-14);
    // Each inner edge lies `thickness` from its outer edge.
    const Vec3& outer_next = before.means[size_t(4 + (k + 1) % 4)];
    const Vec3& inner_next = a.means[size_t(8 + (k + 1) % 4)];
    EXPECT_NEAR(distance_to_line(inner, outer, outer_next), thickness, 1e-14);
    EXPECT_NEAR(distance_to_line(inner_next, outer, outer_next), thickness, 1e-14);
  }
}

TEST(InsetFaces, InnerCovarianceIsTheBlendTowardsTheFacePointAtTheFractionMoved) {
  // The cube with a different covariance at each corner of its +z face.
  MeshArrays arrays = arrays_of(make_sample("cube"));
  for (int v = 4; v < 8; ++v) arrays.covariances[size_t(v)] = Vec3(0.01 * (v - 2), 0.02, 0.05 / (v - 3)).asDiagonal();
  const CovarianceMesh cube = build_mesh(arrays);
  const MeshArrays before = arrays_of(cube);
  const Modelled m = inset_faces(cube, {1}, 0.4);
  const MeshArrays a = arrays_of(m.mesh);
  Dual face_point = Dual::Zero();
  for (int v = 4; v < 8; ++v) face_point += 0.25 * to_dual(before.gaussian(v));
  const Vec3 centre = from_dual(face_point)->mean;
  for (int k = 0; k < 4; ++k) {
    const int v = 4 + k;
    const Vec3& p = before.means[size_t(v)];
    const double t = (a.means[size_t(8 + k)] - p).norm() / (centre - p).norm();
    EXPECT_GT(t, 0.2);
    EXPECT_LT(t, 0.6);
    const Gaussian expected = *from_dual((1 - t) * to_dual(before.gaussian(v)) + t * face_point);
    EXPECT_LT((a.covariances[size_t(8 + k)] - expected.covariance).norm(), 1e-12 * expected.covariance.norm());
    EXPECT_GT((a.covariances[size_t(8 + k)] - before.covariances[size_t(v)]).norm(),
              1e-3 * before.covariances[size_t(v)].norm());
  }
}

// Faces 3 and 4 of a flat 3 × 3 grid: the 2 × 1 rectangle [0, 2] × [1, 2].
TEST(InsetFaces, TwoAdjacentFacesAreInsetAsOneRegion) {
  const CovarianceMesh grid = test::flat_grid(3, 3, 0.01);
  const Modelled m = inset_faces(grid, {3, 4}, 0.2);
  EXPECT_EQ(int(m.mesh.n_vertices()), 16 + 6);
  EXPECT_EQ(int(m.mesh.n_faces()), 9 + 6);
  EXPECT_EQ(orientation_and_boundary(m.mesh), std::make_pair(true, 12));
  const MeshArrays a = arrays_of(m.mesh);
  // Region boundary vertices 4, 5, 6, 8, 9, 10 in order, their copies 16..21.
  const std::vector<Vec3> expected = {{0.2, 1.2, 0}, {1, 1.2, 0}, {1.8, 1.2, 0},
                                      {0.2, 1.8, 0}, {1, 1.8, 0}, {1.8, 1.8, 0}};
  for (size_t k = 0; k < expected.size(); ++k) EXPECT_LT((a.means[16 + k] - expected[k]).norm(), 1e-14);
  EXPECT_EQ(a.faces[3], (std::vector<int>{16, 17, 20, 19}));
  EXPECT_EQ(a.faces[4], (std::vector<int>{17, 18, 21, 20}));
}

// An inset face's creased rim keeps its sharpness on the outer edges and gives it to the inner
// ones, which now bound the face; a corner goes to the inner copy as well.
TEST(InsetFaces, CreasesAndCornersOfTheFaceReachItsInnerCopy) {
  CovarianceMesh grid = test::flat_grid(3, 3, 0.01);  // face 4 is the middle quad 5, 6, 10, 9
  grid.sharpness.set_crease(5, 6, 10.0);
  grid.sharpness.set_corner(10, 3.0, int(grid.n_vertices()));
  const Modelled m = inset_faces(grid, {4}, 0.2);
  const MeshArrays a = arrays_of(m.mesh);
  const std::vector<int>& face = a.faces[4];
  ASSERT_EQ(face.size(), 4u);
  EXPECT_EQ(a.sharpness.crease(face[0], face[1]), 10.0);
  EXPECT_EQ(a.sharpness.crease(5, 6), 10.0);
  EXPECT_EQ(a.sharpness.crease(face[1], face[2]), 0.0);
  EXPECT_EQ(a.sharpness.corner(face[2]), 3.0);
  EXPECT_EQ(a.sharpness.corner(10), 3.0);
}

TEST(InsetFaces, AFaceOnTheMeshBorderKeepsTheBoundary) {
  const CovarianceMesh grid = make_sample("grid", 16);
  const Modelled m = inset_faces(grid, {0}, 0.1);
  EXPECT_EQ(int(m.mesh.n_vertices()), 29);
  EXPECT_EQ(int(m.mesh.n_faces()), 20);
  EXPECT_EQ(orientation_and_boundary(m.mesh), std::make_pair(true, 16));
}

TEST(InsetFaces, RefusalsNameTheProblemAndChangeNothing) {
  const CovarianceMesh cube = make_sample("cube");
  const MeshArrays before = arrays_of(cube);
  EXPECT_EQ(error_of([&] { inset_faces(cube, {1}, 0); }), "thickness 0 is not a positive number");
  EXPECT_EQ(error_of([&] { inset_faces(cube, {1}, -0.5); }), "thickness -0.5 is not a positive number");
  EXPECT_EQ(error_of([&] { inset_faces(cube, {1}, NAN); }), "thickness nan is not a positive number");
  EXPECT_EQ(error_of([&] { inset_faces(cube, {7}, 0.1); }), "face 7 is not in the mesh (6 faces)");
  EXPECT_EQ(error_of([&] { inset_faces(cube, {1}, 1.5); }),
            "a thickness of 1.5 would carry vertex 4 past the centre of face 1");
  EXPECT_EQ(error_of([&] {
              inset_faces(cube, {0, 1, 2, 3, 4, 5}, 0.1);
            }),
            "insetting every face of a closed part would leave no border to inset from");
  const MeshArrays after = arrays_of(cube);
  EXPECT_EQ(after.means, before.means);
  EXPECT_EQ(after.covariances, before.covariances);
  EXPECT_EQ(after.faces, before.faces);

  // A 2 × 1 rectangle inset by 0.6: its inner corners pass each other across the short sides
  // before they reach the centre.
  const CovarianceMesh rectangle = make_covariance_mesh({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}},
                                                        std::vector<Mat3>(4, 0.01 * Mat3::Identity()), {{0, 1, 2, 3}});
  EXPECT_EQ(error_of([&] { inset_faces(rectangle, {0}, 0.6); }), "a thickness of 0.6 would turn face 0 inside out");
  EXPECT_EQ(inset_faces(rectangle, {0}, 0.4).mesh.n_faces(), 5u);
}

}  // namespace
}  // namespace gps
