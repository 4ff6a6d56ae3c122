#include "core/modelling/fill.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "core/support/error.h"
#include "core/modelling/mesh_queries.h"
#include "core/plans/plan_builder.h"
#include "tests/support/error_of.h"
#include "tests/support/test_meshes.h"
#include "tests/support/mesh_checks.h"

namespace gps {
namespace {

using test::signed_volume;

using test::error_of;
using V = std::vector<int>;

using test::boundary_edges_of_oriented;

// The cube of side 2 without its top face {4, 5, 6, 7}.
CovarianceMesh holed_cube() {
  const std::vector<Vec3> p = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                               {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  const std::vector<std::vector<int>> faces = {{0, 3, 2, 1}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
  return make_covariance_mesh(p, std::vector<Mat3>(8, 0.2 * Mat3::Identity()), faces);
}

TEST(Fill, RestoresTheClosedCubeWhicheverOrderTheVerticesComeIn) {
  const CovarianceMesh holed = holed_cube();
  EXPECT_EQ(boundary_edges_of_oriented(holed), 4);
  for (const V& order : {V{4, 5, 6, 7}, V{7, 6, 5, 4}, V{6, 7, 4, 5}, V{5, 4, 7, 6}}) {
    const Modelled r = fill(holed, order);
    EXPECT_EQ(r.mesh.n_faces(), 6u);
    EXPECT_EQ(r.mesh.n_vertices(), 8u);
    EXPECT_EQ(boundary_edges_of_oriented(r.mesh), 0);
    EXPECT_NEAR(signed_volume(r.mesh), 8.0, 1e-12);
    EXPECT_EQ(r.selection, (V{4, 5, 6, 7}));
    const V face = arrays_of(r.mesh).faces[5];
    const auto at = std::find(face.begin(), face.end(), 4) - face.begin();
    EXPECT_EQ(face[size_t(at + 1) % 4], 5) << "the new face runs 4 → 5 → 6 → 7";
  }
  EXPECT_EQ(fill(holed, {7, 6, 5, 4}).summary, "filled a face of 4 vertices (reversed to fit its neighbours)");
  EXPECT_EQ(fill(holed, {4, 5, 6, 7}).summary, "filled a face of 4 vertices");
}

TEST(Fill, FillSelectedTakesAWholeLoopOrThreeOrFourOfIt) {
  const CovarianceMesh holed = holed_cube();
  const Modelled whole = fill_selected(holed, {7, 4, 6, 5});
  EXPECT_EQ(boundary_edges_of_oriented(whole.mesh), 0);
  EXPECT_NEAR(signed_volume(whole.mesh), 8.0, 1e-12);
  // Three of the hole's four: a triangle, leaving a triangular hole 4–6–7.
  const Modelled part = fill_selected(holed, {6, 4, 5});
  EXPECT_EQ(boundary_edges_of_oriented(part.mesh), 3);
  const auto loops = boundary_loops(part.mesh);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0].size(), 3u);
  EXPECT_EQ(fill_selected(part.mesh, {4, 6, 7}).mesh.n_faces(), 7u);
  // Isolated vertices: ordered by angle around their centroid, whatever the order given.
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}, {6, 5, 5}, {5, 6, 5}};
  const CovarianceMesh loose = make_covariance_mesh(p, std::vector<Mat3>(7, Mat3::Identity()), {{4, 5, 6}});
  const Modelled quad = fill_selected(loose, {0, 1, 2, 3});
  const V face = arrays_of(quad.mesh).faces[1];
  for (size_t k = 0; k < 4; ++k)
    EXPECT_NEAR((quad.mesh.mean(size_t(face[k])) - quad.mesh.mean(size_t(face[(k + 1) % 4]))).norm(), 1.0, 1e-12)
        << "an edge of the quad is a diagonal";
}

TEST(Fill, RefusalsNameTheElement) {
  const CovarianceMesh holed = holed_cube();
  EXPECT_EQ(error_of([&] { fill(holed, {4, 5}); }), "a face needs at least 3 vertices");
  EXPECT_EQ(error_of([&] { fill(holed, {4, 5, 4}); }), "vertex 4 is listed twice");
  EXPECT_EQ(error_of([&] { fill(holed, {4, 5, 9}); }), "vertex 9 is not in the mesh (8 vertices)");
  const CovarianceMesh cube = test::cube_mesh();
  EXPECT_EQ(error_of([&] { fill(cube, {4, 5, 6, 7}); }), "vertex 4 is not on a boundary");
  EXPECT_EQ(error_of([&] { fill_selected(cube, {4, 5, 6}); }), "vertex 4 is not on a boundary");
  // A quad split into two triangles: its diagonal 0–2 is interior though both ends are on the boundary.
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const CovarianceMesh split = make_covariance_mesh(p, std::vector<Mat3>(4, Mat3::Identity()), {{0, 1, 2}, {0, 2, 3}});
  EXPECT_EQ(error_of([&] { fill(split, {0, 1, 2}); }), "edge 2–0 is an interior edge (it has two faces)");
  EXPECT_EQ(error_of([&] { fill_selected(holed, {4, 5}); }), "select at least 3 boundary vertices (2 selected)");
  const CovarianceMesh grid = test::grid_mesh(3, 3);  // 12 boundary vertices
  // Three vertices along one side: a face of no area.
  EXPECT_EQ(error_of([&] {
              fill(test::grid_mesh(3, 3, 0.1, true), {0, 1, 2});
            }),
            "the vertices lie in a line: the face would have no area");
  EXPECT_EQ(
      error_of([&] {
        fill_selected(grid, {0, 1, 2, 3, 7});
      }),
      "the 5 selected vertices are not one whole boundary loop (select a whole loop, or 3 or 4 boundary vertices)");
  EXPECT_EQ(holed.n_faces(), 5u);
}

// A hole of more sides than a surface's patch plans take is not filled with one face; one of as
// many as they take is.
TEST(Fill, AFaceOfMoreSidesThanTheSurfaceTakesIsRefused) {
  for (const int n : {kMaxPlanValence, kMaxPlanValence + 1}) {
    std::vector<Vec3> p;
    std::vector<std::vector<int>> faces;
    for (int i = 0; i < n; ++i) {
      const double a = 2 * M_PI * i / n;
      p.emplace_back(std::cos(a), std::sin(a), 0.0);
      p.emplace_back(2 * std::cos(a), 2 * std::sin(a), 0.0);
      faces.push_back({2 * i, 2 * i + 1, 2 * ((i + 1) % n) + 1, 2 * ((i + 1) % n)});
    }
    const CovarianceMesh ring = make_covariance_mesh(p, std::vector<Mat3>(p.size(), 0.01 * Mat3::Identity()), faces);
    std::vector<int> hole;
    for (int i = n - 1; i >= 0; --i) hole.push_back(2 * i);
    if (n == kMaxPlanValence) {
      EXPECT_EQ(fill(ring, hole).mesh.n_faces(), size_t(n + 1));
    } else {
      EXPECT_EQ(error_of([&] { fill(ring, hole); }),
                "the result would have a face of 257 sides; a surface's patch plans take up to 256 (their stencils "
                "grow with the square of it)");
    }
  }
}

}  // namespace
}  // namespace gps
