// Splitting faces off (core/modelling/split_faces.h): the cube's counts and Gaussians, faces meeting
// at a vertex on either side, creases and corners on both sides of the cut, and refusals.
#include "core/modelling/split_faces.h"

#include <gtest/gtest.h>

#include "core/modelling/mesh_queries.h"
#include "core/modelling/samples.h"
#include "tests/support/error_of.h"
#include "tests/support/mesh_checks.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

using test::error_of;
using test::shape_of;

// The number of connected parts of the mesh.
int parts_of(const CovarianceMesh& mesh) {
  std::vector<char> seen(mesh.n_vertices(), 0);
  int parts = 0;
  for (int v = 0; v < int(mesh.n_vertices()); ++v) {
    if (seen[size_t(v)]) continue;
    ++parts;
    for (const int w : linked_vertices(mesh, {v})) seen[size_t(w)] = 1;
  }
  return parts;
}

TEST(SplitFaces, OneFaceOfTheCubeBecomesAPartOfItsOwn) {
  const CovarianceMesh cube = test::with_random_covariances(make_sample("cube"), 5);
  const CovarianceMesh copy = cube;
  const Modelled r = split_faces(cube, {1});  // the +z face 4 5 6 7
  const test::Shape s = shape_of(r.mesh);
  EXPECT_EQ(s.vertices, 12);
  EXPECT_EQ(s.faces, 6);
  EXPECT_EQ(s.boundary_edges, 8);
  EXPECT_TRUE(s.oriented);
  EXPECT_EQ(parts_of(r.mesh), 2);
  EXPECT_NEAR(test::signed_volume(r.mesh), test::signed_volume(cube), 1e-12);  // no face turned or moved
  EXPECT_EQ(r.selection, (std::vector<int>{8, 9, 10, 11}));
  EXPECT_EQ(r.summary, "split off 1 face: 4 vertices duplicated along the cut");
  const MeshArrays before = arrays_of(cube), after = arrays_of(r.mesh);
  EXPECT_EQ(after.faces[1], (std::vector<int>{8, 9, 10, 11}));
  for (int f : {0, 2, 3, 4, 5}) EXPECT_EQ(after.faces[size_t(f)], before.faces[size_t(f)]);
  for (int v = 0; v < 8; ++v) {
    EXPECT_EQ(after.means[size_t(v)], before.means[size_t(v)]);
    EXPECT_EQ(after.covariances[size_t(v)], before.covariances[size_t(v)]);
  }
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(after.means[size_t(8 + k)], before.means[size_t(4 + k)]);
    EXPECT_EQ(after.covariances[size_t(8 + k)], before.covariances[size_t(4 + k)]);
  }
  EXPECT_TRUE(test::same_mesh(cube, copy));
}

// Two diagonal faces of a 2 × 2 grid: each split face takes its own copy of the centre, and the two
// faces left, which then touch only at the centre, get a copy each as well, so every side is manifold.
TEST(SplitFaces, FacesMeetingAtAVertexGetACopyEachOnBothSides) {
  const CovarianceMesh grid = test::grid_mesh(2, 2);
  const Modelled r = split_faces(grid, {0, 3});
  const test::Shape s = shape_of(r.mesh);
  EXPECT_EQ(s.vertices, 9 + 7);
  EXPECT_EQ(s.faces, 4);
  EXPECT_EQ(s.boundary_edges, 16);
  EXPECT_TRUE(s.oriented);
  EXPECT_EQ(parts_of(r.mesh), 4);
  EXPECT_EQ(r.summary,
            "split off 2 faces: 6 vertices duplicated along the cut, 1 more where the other faces met only there");
  const MeshArrays a = arrays_of(r.mesh);
  int centres = 0;
  for (const Vec3& p : a.means) centres += p == arrays_of(grid).means[4];
  EXPECT_EQ(centres, 4);
}

TEST(SplitFaces, CreasesStayOnBothSidesOfTheCutAndCornersAreCopied) {
  CovarianceMesh cube = make_sample("cube");
  cube.sharpness.set_crease(4, 5, 3.0);  // on the cut around the +z face 4 5 6 7
  cube.sharpness.set_crease(0, 1, 2.0);  // away from it
  cube.sharpness.set_corner(6, 1.5, 8);
  const Modelled r = split_faces(cube, {1});
  EXPECT_EQ(r.mesh.sharpness.crease(4, 5), 3.0);
  EXPECT_EQ(r.mesh.sharpness.crease(8, 9), 3.0);
  EXPECT_EQ(r.mesh.sharpness.crease(0, 1), 2.0);
  EXPECT_EQ(r.mesh.sharpness.creases.size(), 3u);
  EXPECT_EQ(r.mesh.sharpness.corner(6), 1.5);
  EXPECT_EQ(r.mesh.sharpness.corner(10), 1.5);
}

// A crease on a split face's edge with an end on the cut moves onto that end's copy.
TEST(SplitFaces, ACreaseOfTheSplitFacesGoesWithThem) {
  CovarianceMesh grid = test::grid_mesh(3, 1);  // faces 0 1 2 in a row: 0 1 5 4, 1 2 6 5, 2 3 7 6
  grid.sharpness.set_crease(1, 2, 4.0);         // on face 1's outer edge, from the cut's vertex 1
  grid.sharpness.set_crease(2, 6, 2.0);         // between the two split faces
  const Modelled r = split_faces(grid, {1, 2});
  EXPECT_EQ(parts_of(r.mesh), 2);
  EXPECT_EQ(r.mesh.n_vertices(), 8u + 2u);  // 1 → 8 and 5 → 9
  EXPECT_EQ(arrays_of(r.mesh).faces[1], (std::vector<int>{8, 2, 6, 9}));
  EXPECT_EQ(r.mesh.sharpness.crease(8, 2), 4.0);
  EXPECT_EQ(r.mesh.sharpness.crease(2, 6), 2.0);
  EXPECT_EQ(r.mesh.sharpness.crease(1, 2), 0.0);
  EXPECT_EQ(r.mesh.sharpness.creases.size(), 2u);
}

TEST(SplitFaces, RefusalsChangeNothing) {
  const CovarianceMesh cube = make_sample("cube");
  EXPECT_EQ(error_of([&] { split_faces(cube, {}); }), "no faces are selected");
  EXPECT_EQ(error_of([&] { split_faces(cube, {1, 6}); }), "face 6 is not in the mesh (6 faces)");
  EXPECT_EQ(error_of([&] {
              split_faces(cube, {0, 1, 2, 3, 4, 5});
            }),
            "every face is selected: there is nothing to split them from");
  const CovarianceMesh parted = split_faces(cube, {1}).mesh;
  const CovarianceMesh copy = parted;
  EXPECT_EQ(error_of([&] { split_faces(parted, {1}); }),
            "the faces share no vertex with the other faces: they are a part of their own already");
  EXPECT_TRUE(test::same_mesh(parted, copy));
}

}  // namespace
}  // namespace gps
