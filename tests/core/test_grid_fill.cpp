// Grid fill (core/modelling/grid_fill.h): the cube's and the cylinder's holes closed, a rectangular
// hole's grid rebuilt exactly, Blender's sides and spans, the new vertices' Gaussians, a mesh of
// triangles, the editor's selection and refusals.
#include "core/modelling/grid_fill.h"

#include <gtest/gtest.h>

#include "core/modelling/delete_elements.h"
#include "core/modelling/mesh_queries.h"
#include "core/modelling/samples.h"
#include "tests/support/error_of.h"
#include "tests/support/mesh_checks.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

using test::error_of;
using test::shape_of;

// The mesh with these faces deleted (and the vertices only they used), and the boundary loop they leave.
struct Holed {
  CovarianceMesh mesh;
  std::vector<int> loop;
};
Holed with_hole(const CovarianceMesh& mesh, const std::vector<int>& faces) {
  Holed h{delete_faces(mesh, faces).mesh, {}};
  const auto before = boundary_loops(mesh);
  for (const std::vector<int>& loop : boundary_loops(h.mesh))
    if (std::find(before.begin(), before.end(), loop) == before.end()) h.loop = loop;
  return h;
}

TEST(GridFill, TheCubesTopIsOneQuadAgain) {
  const CovarianceMesh cube = make_sample("cube");
  const Holed open = with_hole(cube, {1});  // the +z face 4 5 6 7
  EXPECT_EQ(open.mesh.n_faces(), 5u);
  for (const bool reversed : {false, true}) {
    std::vector<int> loop = open.loop;
    if (reversed) std::reverse(loop.begin(), loop.end());
    const Modelled r = grid_fill(open.mesh, loop);
    const test::Shape s = shape_of(r.mesh);
    EXPECT_EQ(s.vertices, 8);
    EXPECT_EQ(s.faces, 6);
    EXPECT_EQ(s.boundary_edges, 0);
    EXPECT_TRUE(s.oriented);
    EXPECT_EQ(s.euler(), 2);
    EXPECT_NEAR(test::signed_volume(r.mesh), test::signed_volume(cube), 1e-12);  // outward like the rest
    EXPECT_EQ(r.selection, (std::vector<int>{4, 5, 6, 7}));
    EXPECT_EQ(r.summary, "grid-filled a loop of 4 vertices with 1 × 1 quads: 0 vertices added");
  }
}

// The cylinder's octagonal cap hole: a 2 × 2 grid whose one inner vertex is the Coons point of a
// regular octagon, its centre, with the 9D blend of the four side midpoints' Gaussians.
TEST(GridFill, TheCylindersCapHoleIsATwoByTwoGrid) {
  const CovarianceMesh cylinder = test::with_random_covariances(make_sample("cylinder"), 7);
  ASSERT_EQ(cylinder.n_faces(), 18u);  // 16 quads, then the top and bottom octagons
  const Holed open = with_hole(cylinder, {16});
  ASSERT_EQ(open.loop.size(), 8u);
  const Modelled r = grid_fill(open.mesh, open.loop);
  const test::Shape s = shape_of(r.mesh);
  EXPECT_EQ(s.vertices, 24 + 1);
  EXPECT_EQ(s.faces, 18 - 1 + 4);
  EXPECT_EQ(s.boundary_edges, 0);
  EXPECT_TRUE(s.oriented);
  EXPECT_EQ(s.euler(), 2);
  EXPECT_GT(test::signed_volume(r.mesh), 0.0);
  EXPECT_EQ(r.summary, "grid-filled a loop of 8 vertices with 2 × 2 quads: 1 vertex added");
  const MeshArrays before = arrays_of(open.mesh), after = arrays_of(r.mesh);
  Vec3 centre = Vec3::Zero();
  for (int v : open.loop) centre += before.means[size_t(v)] / 8.0;
  EXPECT_LT((after.means[24] - centre).norm(), 1e-12);
  // Every corner turns alike: the sides start at the loop's first vertex and have 2 edges each.
  const Gaussian expected =
      blend_gaussians(before, {{open.loop[1], 0.25}, {open.loop[3], 0.25}, {open.loop[5], 0.25}, {open.loop[7], 0.25}});
  EXPECT_TRUE(after.covariances[24].isApprox(expected.covariance, 1e-12));
  EXPECT_EQ(r.selection.size(), 9u);
}

// A rectangular hole of 4 × 2 unit squares: the corners of the rectangle are found, and the Coons
// patch of its straight sides puts the inner vertices where the deleted grid had them.
TEST(GridFill, ARectangularHoleGetsItsGridBack) {
  const CovarianceMesh grid = test::flat_grid(6, 4, 0.09, "flat grid");  // 7 × 5 vertices
  std::vector<int> inner;
  for (int j = 1; j <= 2; ++j)
    for (int i = 1; i <= 4; ++i) inner.push_back(j * 6 + i);
  const Holed open = with_hole(grid, inner);
  ASSERT_EQ(open.loop.size(), 12u);
  const Modelled r = grid_fill(open.mesh, open.loop);
  const test::Shape s = shape_of(r.mesh);
  EXPECT_EQ(s.vertices, 35);
  EXPECT_EQ(s.faces, 24);
  EXPECT_TRUE(s.oriented);
  EXPECT_EQ(s.boundary_edges, 20);  // the grid's own rim only
  const MeshArrays before = arrays_of(grid), after = arrays_of(r.mesh);
  // The 3 vertices the deletion took (at y = 2, x = 2 3 4) come back after the 32 left, in some order.
  for (int v = 32; v < 35; ++v) {
    const Vec3 p = after.means[size_t(v)];
    EXPECT_NEAR(p.y(), 2.0, 1e-12);
    EXPECT_NEAR(p.x(), std::round(p.x()), 1e-12);
    EXPECT_TRUE(p.x() > 1.5 && p.x() < 4.5) << p.transpose();
    EXPECT_EQ(after.covariances[size_t(v)], before.covariances[0]);
  }
  EXPECT_NE(after.means[32], after.means[33]);
  EXPECT_NE(after.means[33], after.means[34]);
  EXPECT_NE(after.means[32], after.means[34]);
}

// Blender's span walks the split: 2 → 8 quads, 3 → 9, 4 → 8 on a ring of 12; an offset moves the
// first corner along the loop.
TEST(GridFill, TheSpanAndOffsetChooseTheSides) {
  const CovarianceMesh grid = test::flat_grid(6, 4, 0.09, "flat grid");
  std::vector<int> inner;
  for (int j = 1; j <= 2; ++j)
    for (int i = 1; i <= 4; ++i) inner.push_back(j * 6 + i);
  const Holed open = with_hole(grid, inner);
  const size_t before = open.mesh.n_faces();
  EXPECT_EQ(grid_fill(open.mesh, open.loop, 2).mesh.n_faces(), before + 8);
  EXPECT_EQ(grid_fill(open.mesh, open.loop, 3).mesh.n_faces(), before + 9);
  EXPECT_EQ(grid_fill(open.mesh, open.loop, 4).mesh.n_faces(), before + 8);
  EXPECT_EQ(grid_fill(open.mesh, open.loop, 5).mesh.n_faces(), before + 5);
  EXPECT_EQ(grid_fill(open.mesh, open.loop, 3, 1).mesh.n_faces(), before + 9);
  EXPECT_FALSE(test::same_mesh(grid_fill(open.mesh, open.loop, 3, 1).mesh, grid_fill(open.mesh, open.loop, 3).mesh));
  for (int span : {2, 3, 4, 5}) EXPECT_TRUE(shape_of(grid_fill(open.mesh, open.loop, span).mesh).oriented);
}

TEST(GridFill, OnAMeshOfTrianglesTheQuadsAreSplit) {
  const CovarianceMesh tri = test::triangle_grid_mesh(3, 3);
  const Holed open = with_hole(tri, faces_within(tri, {5, 6, 9, 10}));  // the middle rhombus
  ASSERT_EQ(open.loop.size(), 4u);
  const Modelled r = grid_fill(open.mesh, open.loop);
  EXPECT_EQ(r.mesh.n_faces(), tri.n_faces());
  EXPECT_TRUE(all_triangles(arrays_of(r.mesh)));
  const test::Shape s = shape_of(r.mesh);
  EXPECT_TRUE(s.oriented);
  EXPECT_EQ(s.boundary_edges, 12);
  EXPECT_EQ(r.summary, "grid-filled a loop of 4 vertices with 1 × 1 quads: 0 vertices added (split into triangles)");
}

TEST(GridFill, TheEditorFillsTheSelectedLoop) {
  const Holed open = with_hole(make_sample("cylinder"), {16});
  std::vector<int> shuffled = open.loop;
  std::reverse(shuffled.begin(), shuffled.end());
  std::swap(shuffled[0], shuffled[3]);
  EXPECT_TRUE(test::same_mesh(grid_fill_selected(open.mesh, shuffled).mesh, grid_fill(open.mesh, open.loop).mesh));
  EXPECT_TRUE(
      test::same_mesh(grid_fill_selected(open.mesh, shuffled, 1, 2).mesh, grid_fill(open.mesh, open.loop, 1, 2).mesh));
  EXPECT_EQ(error_of([&] {
              grid_fill_selected(open.mesh, {open.loop[0], open.loop[1], open.loop[2]});
            }),
            "select one whole boundary loop (the 3 selected vertices are not one)");
}

TEST(GridFill, RefusalsChangeNothing) {
  const Holed open = with_hole(make_sample("cylinder"), {16});
  const CovarianceMesh copy = open.mesh;
  const std::vector<int>& l = open.loop;
  EXPECT_EQ(error_of([&] {
              grid_fill(open.mesh, {l[0], l[1], l[2]});
            }),
            "a grid fill needs a loop of at least 4 vertices (3 given)");
  EXPECT_EQ(error_of([&] {
              grid_fill(open.mesh, {l[0], l[1], l[2], l[3], l[4], l[5], l[6]});
            }),
            "a grid fill needs an even number of vertices around the loop (7 given)");
  EXPECT_EQ(error_of([&] {
              grid_fill(open.mesh, {l[0], l[1], l[2], l[1]});
            }),
            "vertex " + std::to_string(l[1]) + " is listed twice");
  EXPECT_EQ(error_of([&] {
              grid_fill(open.mesh, {l[0], l[1], l[2], 99});
            }),
            "vertex 99 is not in the mesh (24 vertices)");
  EXPECT_EQ(error_of([&] {
              grid_fill(open.mesh, {l[0], l[1], l[2], l[3]});
            }),
            "edge " + std::to_string(l[3]) + "–" + std::to_string(l[0]) +
                " is not an edge of the mesh: a grid fill needs a boundary loop");
  EXPECT_EQ(error_of([&] { grid_fill(open.mesh, l, 4); }),
            "span 4 leaves no room in a loop of 8 vertices (from 1 to 3)");
  const CovarianceMesh cube = make_sample("cube");
  EXPECT_EQ(error_of([&] {
              grid_fill(cube, {4, 5, 6, 7});
            }),
            "edge 4–5 has a face on both sides: a grid fill needs a boundary loop");
  EXPECT_TRUE(test::same_mesh(open.mesh, copy));
}

}  // namespace
}  // namespace gps
