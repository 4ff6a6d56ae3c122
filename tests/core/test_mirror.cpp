// Mirroring (core/modelling/mirror.h): a half cube open at x = 0 mirrored into a closed box, the
// copies' Gaussians mirrored exactly and the seam's made symmetric, an edit of the half shown by index, a mirror
// without merging, about another plane, refusals of non-manifold seams, and the op list's "mirror".
#include "core/modelling/mirror.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/modelling/operation_list.h"
#include "core/modelling/samples.h"
#include "tests/support/error_of.h"
#include "tests/support/mesh_checks.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

using test::error_of;
using test::shape_of;
using test::signed_volume;

// The cube's x ≥ 0 half (x from 0 to 1), open at x = 0: its vertices 0, 3, 4 and 7 lie there.
CovarianceMesh half_cube(unsigned seed = 0) {
  const std::vector<Vec3> p = {{0, -1, -1}, {1, -1, -1}, {1, 1, -1}, {0, 1, -1},
                               {0, -1, 1},  {1, -1, 1},  {1, 1, 1},  {0, 1, 1}};
  const std::vector<std::vector<int>> faces = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}};
  const CovarianceMesh m = make_covariance_mesh(p, std::vector<Mat3>(p.size(), 0.09 * Mat3::Identity()), faces, "half");
  return seed == 0 ? m : test::with_random_covariances(m, seed);
}

TEST(Mirror, AHalfCubeOpenOnThePlaneBecomesAClosedBox) {
  const CovarianceMesh half = half_cube();
  const CovarianceMesh copy = half;
  EXPECT_NEAR(signed_volume(half), 4.0, 1e-12);
  const Modelled r = mirror(half, 0, Vec3::Zero(), true);
  const test::Shape s = shape_of(r.mesh);
  EXPECT_EQ(s.vertices, 12);
  EXPECT_EQ(s.faces, 10);
  EXPECT_EQ(s.boundary_edges, 0);
  EXPECT_TRUE(s.oriented);
  EXPECT_EQ(s.euler(), 2);
  EXPECT_NEAR(signed_volume(r.mesh), 8.0, 1e-12);
  EXPECT_EQ(r.selection, (std::vector<int>{8, 9, 10, 11}));
  EXPECT_EQ(r.summary, "mirrored 8 vertices and 5 faces in x, 4 vertices merged on the plane");
  // Isotropic Gaussians on the plane are their own images: the seam is as it was.
  const MeshArrays a = arrays_of(r.mesh), before = arrays_of(half);
  for (int v : {0, 3, 4, 7}) {
    EXPECT_LE((a.means[size_t(v)] - before.means[size_t(v)]).norm(), 1e-15);
    EXPECT_LE((a.covariances[size_t(v)] - before.covariances[size_t(v)]).norm(), 1e-15);
  }
  EXPECT_TRUE(test::same_mesh(half, copy));
}

TEST(Mirror, GaussiansAreMirroredExactlyAndTheSeamMadeSymmetric) {
  const CovarianceMesh half = half_cube(5);
  const Modelled r = mirror(half, 0, Vec3::Zero(), true);
  const MeshArrays a = arrays_of(r.mesh), before = arrays_of(half);
  const Mat3 flip = Vec3(-1, 1, 1).asDiagonal();
  // The copies of 1, 2, 5 and 6 are 8 to 11: MΣM, Mμ.
  const std::vector<int> off_plane = {1, 2, 5, 6};
  for (size_t i = 0; i < off_plane.size(); ++i) {
    const size_t v = size_t(off_plane[i]), c = 8 + i;
    EXPECT_EQ(a.means[c], flip * before.means[v]);
    EXPECT_LE((a.covariances[c] - flip * before.covariances[v] * flip).norm(), 1e-15);
    EXPECT_EQ(a.means[v], before.means[v]);
    EXPECT_EQ(a.covariances[v], before.covariances[v]);
  }
  // A seam vertex takes the 9D average of its Gaussian and its image: on the plane, no x–y or x–z
  // coupling.
  for (int v : {0, 3, 4, 7}) {
    const Gaussian g = a.gaussian(v);
    EXPECT_LE(std::abs(g.mean.x()), 1e-12);
    EXPECT_LE(std::abs(g.covariance(0, 1)) + std::abs(g.covariance(0, 2)), 1e-12);
    const std::optional<Gaussian> expected =
        from_dual(0.5 * (to_dual(before.gaussian(v)) + to_dual(before.means[size_t(v)].cwiseProduct(Vec3(-1, 1, 1)),
                                                               flip * before.covariances[size_t(v)] * flip)));
    ASSERT_TRUE(expected);
    EXPECT_LE((g.mean - expected->mean).norm(), 1e-14);
    EXPECT_LE((g.covariance - expected->covariance).norm(), 1e-14);
  }
  EXPECT_TRUE(shape_of(r.mesh).oriented);
  EXPECT_GT(signed_volume(r.mesh), 0.0);
}

// The vertices keep their indices and the copies follow in vertex order (mirror_images), so that an
// edit of the half, set by update_mirrored on the vertices it changed, gives exactly mirror() of the
// edited half: a vertex off the plane and one on it moved, with new covariances.
TEST(Mirror, AnEditOfTheHalfIsShownByIndex) {
  const CovarianceMesh half = half_cube(3);
  const std::vector<int> images = mirror_images(half, 0, Vec3::Zero(), true);
  EXPECT_EQ(images, (std::vector<int>{0, 8, 9, 3, 4, 10, 11, 7}));
  EXPECT_EQ(mirror_images(half, 0, Vec3::Zero(), false), (std::vector<int>{8, 9, 10, 11, 12, 13, 14, 15}));
  CovarianceMesh mirrored = mirror(half, 0, Vec3::Zero(), true).mesh;
  const MeshArrays before = arrays_of(half), shown = arrays_of(mirrored);
  for (int v = 0; v < 8; ++v) {
    if (images[size_t(v)] != v) {
      EXPECT_EQ(shown.means[size_t(v)], before.means[size_t(v)]) << v;
    }
  }
  EXPECT_EQ(std::vector<std::vector<int>>(shown.faces.begin(), shown.faces.begin() + 5), before.faces);

  CovarianceMesh edited = half;
  edited.set_mean(2, Vec3(1.5, 1.25, -0.75));
  edited.set_covariance(2, Mat3{{0.2, 0.05, 0.01}, {0.05, 0.1, 0.0}, {0.01, 0.0, 0.3}});
  edited.set_mean(3, Vec3(0, 1.5, -1));
  edited.set_covariance(3, Mat3{{0.1, 0.03, 0.0}, {0.03, 0.2, 0.0}, {0.0, 0.0, 0.1}});
  EXPECT_EQ(update_mirrored(edited, {3, 2}, 0, Vec3::Zero(), images, mirrored), (std::vector<int>{2, 3, 9}));
  EXPECT_TRUE(test::same_mesh(mirrored, mirror(edited, 0, Vec3::Zero(), true).mesh));
}

TEST(Mirror, WithoutMergingTheCopyIsASecondPart) {
  const Modelled r = mirror(half_cube(), 0, Vec3::Zero(), false);
  const test::Shape s = shape_of(r.mesh);
  EXPECT_EQ(s.vertices, 16);
  EXPECT_EQ(s.faces, 10);
  EXPECT_EQ(s.boundary_edges, 8);
  EXPECT_TRUE(s.oriented);
  EXPECT_EQ(r.selection.size(), 8u);
  EXPECT_EQ(r.summary, "mirrored 8 vertices and 5 faces in x");
}

// The cube mirrored about the plane y = 3: a second closed cube, outward, its creases copied.
TEST(Mirror, AboutAPlaneThroughAGivenPoint) {
  CovarianceMesh cube = make_sample("cube");
  cube.sharpness.set_crease(2, 3, 5.0);
  cube.sharpness.set_corner(6, 1.0, 8);
  const Modelled r = mirror(cube, 1, Vec3(7, 3, -2), true);
  const test::Shape s = shape_of(r.mesh);
  EXPECT_EQ(s.vertices, 16);
  EXPECT_EQ(s.faces, 12);
  EXPECT_EQ(s.boundary_edges, 0);
  EXPECT_TRUE(s.oriented);
  EXPECT_NEAR(signed_volume(r.mesh), 16.0, 1e-12);
  const MeshArrays a = arrays_of(r.mesh);
  EXPECT_EQ(a.means[10], Vec3(1, 5, -1));  // vertex 2 (1, 1, −1)
  EXPECT_EQ(r.mesh.sharpness.crease(10, 11), 5.0);
  EXPECT_EQ(r.mesh.sharpness.corner(14), 1.0);
}

TEST(Mirror, NonManifoldSeamsAreRefused) {
  // The cube's +x face lies on the plane x = 1.
  EXPECT_EQ(error_of([] { mirror(make_sample("cube"), 0, Vec3(1, 0, 0), true); }),
            "face 4 lies on the mirror plane (it would meet its own image)");
  // The grid's column x = 1 is inside it.
  EXPECT_EQ(error_of([] { mirror(test::grid_mesh(2, 1), 0, Vec3(1, 0, 0), true); }),
            "edge 1–4 lies on the mirror plane with faces on both sides (the seam would join four)");
  // The cone's apex touches the plane y = 1.5 alone.
  EXPECT_EQ(error_of([] { mirror(test::cone_mesh(), 1, Vec3(0, 1.5, 0), true); }),
            "vertex 0 lies on the mirror plane beside no boundary edge along it (the halves would meet at a point)");
  EXPECT_EQ(error_of([] { mirror(half_cube(), 0, Vec3(NAN, 0, 0), true); }),
            "the mirror's center has a number that is not finite");
  // Without merging, the same meshes are mirrored as separate parts.
  EXPECT_EQ(mirror(test::cone_mesh(), 1, Vec3(0, 1.5, 0), false).mesh.n_vertices(), 18u);
}

TEST(Mirror, TheOperationList) {
  const CovarianceMesh half = half_cube(2);
  const Modelled scripted = OperationList::parse(R"([{"op":"mirror","axis":"x"}])", "o").apply(half);
  EXPECT_TRUE(test::same_mesh(scripted.mesh, mirror(half, 0, Vec3::Zero(), true).mesh));
  const Modelled apart =
      OperationList::parse(R"([{"op":"mirror","axis":"z","center":[0,0,4],"merge":false}])", "o").apply(half);
  EXPECT_TRUE(test::same_mesh(apart.mesh, mirror(half, 2, Vec3(0, 0, 4), false).mesh));
  const auto parse_error = [](const std::string& text) { return error_of([&] { OperationList::parse(text, "o"); }); };
  EXPECT_EQ(parse_error(R"([{"op":"mirror","axis":"w"}])"),
            "o: ops[0] (mirror): \"axis\" must be \"x\", \"y\" or \"z\"");
  EXPECT_EQ(parse_error(R"([{"op":"mirror"}])"), "o: ops[0] (mirror): \"axis\" is missing");
  EXPECT_EQ(parse_error(R"([{"op":"mirror","axis":"x","merge":1}])"),
            "o: ops[0] (mirror): \"merge\" must be true or false");
  EXPECT_EQ(parse_error(R"([{"op":"mirror","axis":"x","center":[0,0]}])"),
            "o: ops[0] (mirror): \"center\" must be 3 numbers");
  EXPECT_EQ(error_of([] {
              OperationList::parse(R"([{"op":"mirror","axis":"x","center":[1,0,0]}])", "o").apply(make_sample("cube"));
            }),
            "o: ops[0] (mirror): face 4 lies on the mirror plane (it would meet its own image)");
}

}  // namespace
}  // namespace gps
