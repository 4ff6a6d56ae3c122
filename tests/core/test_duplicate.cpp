// Duplicating faces (core/modelling/duplicate.h): the cube's counts, the copies' Gaussians moved
// exactly, faces that meet at a vertex copied as a manifold part, creases and corners copied,
// refusals, and the op list's "duplicate".
#include "core/modelling/duplicate.h"

#include <gtest/gtest.h>

#include "core/modelling/samples.h"
#include "core/modelling/operation_list.h"
#include "tests/support/error_of.h"
#include "tests/support/mesh_checks.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

using test::error_of;
using test::shape_of;
using test::signed_volume;

TEST(Duplicate, TheWholeCubeIsASecondClosedPart) {
  const CovarianceMesh cube = test::with_random_covariances(make_sample("cube"), 3);
  const CovarianceMesh copy = cube;
  std::vector<int> all(6);
  for (int f = 0; f < 6; ++f) all[size_t(f)] = f;
  const Vec3 offset(3, -1, 0.5);
  const Modelled r = duplicate_faces(cube, all, offset);
  const test::Shape s = shape_of(r.mesh);
  EXPECT_EQ(s.vertices, 16);
  EXPECT_EQ(s.faces, 12);
  EXPECT_EQ(s.boundary_edges, 0);
  EXPECT_TRUE(s.oriented);
  EXPECT_EQ(s.euler(), 4);  // two spheres
  EXPECT_NEAR(signed_volume(r.mesh), 16.0, 1e-12);
  EXPECT_EQ(r.selection, (std::vector<int>{8, 9, 10, 11, 12, 13, 14, 15}));
  EXPECT_EQ(r.summary, "duplicated 6 faces: 8 vertices added");
  const MeshArrays before = arrays_of(cube), after = arrays_of(r.mesh);
  for (int v = 0; v < 8; ++v) {
    EXPECT_EQ(after.means[size_t(v)], before.means[size_t(v)]);
    EXPECT_EQ(after.means[size_t(8 + v)], before.means[size_t(v)] + offset);
    EXPECT_EQ(after.covariances[size_t(8 + v)], before.covariances[size_t(v)]);
  }
  for (int f = 0; f < 6; ++f) {
    std::vector<int> moved = before.faces[size_t(f)];
    for (int& v : moved) v += 8;
    EXPECT_EQ(after.faces[size_t(6 + f)], moved);
  }
  EXPECT_TRUE(test::same_mesh(cube, copy));
}

// Two faces of a 2 × 2 grid that share only the centre vertex: the copy gives each its own copy of
// it, so that the new part is two separate quads rather than a pinched vertex.
TEST(Duplicate, FacesMeetingAtAVertexGetACopyEach) {
  const CovarianceMesh grid = test::grid_mesh(2, 2);
  const Modelled r = duplicate_faces(grid, {0, 3}, Vec3(0, 0, 1));
  const test::Shape s = shape_of(r.mesh);
  EXPECT_EQ(s.vertices, 9 + 8);
  EXPECT_EQ(s.faces, 4 + 2);
  EXPECT_TRUE(s.oriented);
  EXPECT_EQ(r.selection.size(), 8u);
  const MeshArrays a = arrays_of(r.mesh);
  int centre_copies = 0;
  for (int v = 9; v < 17; ++v) centre_copies += a.means[size_t(v)] == a.means[4] + Vec3(0, 0, 1);
  EXPECT_EQ(centre_copies, 2);
}

TEST(Duplicate, CreasesAndCornersAreCopied) {
  CovarianceMesh cube = make_sample("cube");
  cube.sharpness.set_crease(4, 5, 3.0);
  cube.sharpness.set_crease(0, 3, 1.5);  // not on face 1
  cube.sharpness.set_corner(6, 2.0, 8);
  const Modelled r = duplicate_faces(cube, {1}, Vec3(0, 0, 2));  // the +z face 4 5 6 7
  EXPECT_EQ(r.selection, (std::vector<int>{8, 9, 10, 11}));
  EXPECT_EQ(r.mesh.sharpness.crease(8, 9), 3.0);
  EXPECT_EQ(r.mesh.sharpness.crease(4, 5), 3.0);
  EXPECT_EQ(r.mesh.sharpness.creases.size(), 3u);
  EXPECT_EQ(r.mesh.sharpness.corner(10), 2.0);
  EXPECT_EQ(r.mesh.sharpness.corner(6), 2.0);
}

TEST(Duplicate, RefusalsNameTheFace) {
  const CovarianceMesh cube = make_sample("cube");
  EXPECT_EQ(error_of([&] { duplicate_faces(cube, {2, 6}, Vec3::Zero()); }), "face 6 is not in the mesh (6 faces)");
  EXPECT_EQ(error_of([&] { duplicate_faces(cube, {}, Vec3::Zero()); }), "no faces are selected");
  EXPECT_EQ(error_of([&] { duplicate_faces(cube, {0}, Vec3(INFINITY, 0, 0)); }),
            "the offset has a number that is not finite");
}

TEST(Duplicate, TheOperationList) {
  const CovarianceMesh cube = make_sample("cube");
  const Modelled all = OperationList::parse(R"([{"op":"duplicate","faces":"all","offset":[4,0,0]}])", "o").apply(cube);
  EXPECT_EQ(all.mesh.n_vertices(), 16u);
  EXPECT_EQ(all.mesh.n_faces(), 12u);
  EXPECT_TRUE(test::same_mesh(all.mesh, duplicate_faces(cube, {0, 1, 2, 3, 4, 5}, Vec3(4, 0, 0)).mesh));
  const Modelled some = OperationList::parse(R"([{"op":"duplicate","faces":[1,2]}])", "o").apply(cube);
  EXPECT_TRUE(test::same_mesh(some.mesh, duplicate_faces(cube, {1, 2}, Vec3::Zero()).mesh));
  const auto parse_error = [](const std::string& text) { return error_of([&] { OperationList::parse(text, "o"); }); };
  EXPECT_EQ(parse_error(R"([{"op":"duplicate","faces":"some"}])"),
            "o: ops[0] (duplicate): \"faces\" must be \"all\" or a non-empty list of indices");
  EXPECT_EQ(parse_error(R"([{"op":"duplicate","faces":[]}])"),
            "o: ops[0] (duplicate): \"faces\" must be \"all\" or a non-empty list of indices");
  EXPECT_EQ(parse_error(R"([{"op":"duplicate","faces":[0],"offset":[1,2]}])"),
            "o: ops[0] (duplicate): \"offset\" must be 3 numbers");
  EXPECT_EQ(parse_error(R"([{"op":"duplicate","faces":[-1]}])").rfind("o: ops[0] (duplicate): \"faces\"[0] must be", 0),
            0u);
  EXPECT_EQ(error_of([&] { OperationList::parse(R"([{"op":"duplicate","faces":[9]}])", "o").apply(cube); }),
            "o: ops[0] (duplicate): face 9 is not in the mesh (6 faces)");
}

}  // namespace
}  // namespace gps
