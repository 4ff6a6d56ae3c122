// Bisecting by a plane (core/modelling/bisect.h): the cube's counts as Blender has them, vertices on
// the plane used as they are, the 9D blend at the crossing, concave faces, triangle meshes kept
// triangles, creases split, refusals, and the op list's "bisect".
#include "core/modelling/bisect.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/modelling/samples.h"
#include "core/modelling/extrude.h"
#include "core/modelling/operation_list.h"
#include "tests/support/error_of.h"
#include "tests/support/mesh_checks.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

using test::error_of;
using test::shape_of;
using test::signed_volume;

TEST(Bisect, TheCubeAtZeroHasTwelveVerticesAndTenFaces) {
  const CovarianceMesh cube = make_sample("cube");
  const CovarianceMesh copy = cube;
  const Modelled r = bisect(cube, Vec3::Zero(), Vec3(0, 0, 2));
  const test::Shape s = shape_of(r.mesh);
  EXPECT_EQ(s.vertices, 12);
  EXPECT_EQ(s.faces, 10);
  EXPECT_EQ(s.boundary_edges, 0);
  EXPECT_TRUE(s.oriented);
  EXPECT_EQ(s.euler(), 2);
  EXPECT_NEAR(signed_volume(r.mesh), 8.0, 1e-12);
  EXPECT_EQ(r.selection, (std::vector<int>{8, 9, 10, 11}));
  EXPECT_EQ(r.summary, "bisected 4 faces: 4 vertices, 4 faces added");
  // Each new vertex halves a vertical edge: equal covariances, so its mean is the edge's midpoint.
  const MeshArrays a = arrays_of(r.mesh), before = arrays_of(cube);
  for (int v = 8; v < 12; ++v) {
    EXPECT_EQ(a.means[size_t(v)].z(), 0.0);
    EXPECT_TRUE(a.covariances[size_t(v)].isApprox(before.covariances[0], 1e-14));
  }
  // Every face lies on one side of the plane.
  for (const auto& face : a.faces) {
    double lo = 0, hi = 0;
    for (int v : face) lo = std::min(lo, a.means[size_t(v)].z()), hi = std::max(hi, a.means[size_t(v)].z());
    EXPECT_TRUE(lo == 0 || hi == 0);
  }
  EXPECT_TRUE(test::same_mesh(cube, copy));
}

TEST(Bisect, NewVerticesTakeTheNineDimensionalBlendAtTheCrossing) {
  const CovarianceMesh cube = test::with_random_covariances(make_sample("cube"), 7);
  const Vec3 point(0, 0, 0.3), normal(0.2, -0.1, 1);
  const Modelled r = bisect(cube, point, normal);
  const MeshArrays before = arrays_of(cube), after = arrays_of(r.mesh);
  ASSERT_EQ(after.n_vertices(), 12);
  const Vec3 n = normal.normalized();
  for (const auto& [u, v] : std::vector<std::pair<int, int>>{{0, 4}, {1, 5}, {2, 6}, {3, 7}}) {
    const double du = n.dot(before.means[size_t(u)] - point), dv = n.dot(before.means[size_t(v)] - point);
    const double t = du / (du - dv);
    const Gaussian expected = blend_gaussians(before, {{u, 1 - t}, {v, t}});
    int found = 0;
    for (int m = 8; m < 12; ++m)
      found += after.means[size_t(m)] == expected.mean && after.covariances[size_t(m)] == expected.covariance;
    EXPECT_EQ(found, 1) << "edge " << u << "–" << v;
  }
  for (int v = 0; v < 8; ++v) {
    EXPECT_EQ(after.means[size_t(v)], before.means[size_t(v)]);
    EXPECT_EQ(after.covariances[size_t(v)], before.covariances[size_t(v)]);
  }
  EXPECT_TRUE(shape_of(r.mesh).oriented);
  EXPECT_EQ(shape_of(r.mesh).boundary_edges, 0);
}

// The plane x = y holds the cube's vertices 0, 2, 4 and 6: the top and bottom are cut along their
// diagonals, and no vertex is added.
TEST(Bisect, VerticesOnThePlaneAreNotDuplicated) {
  const CovarianceMesh cube = make_sample("cube");
  const Modelled r = bisect(cube, Vec3::Zero(), Vec3(1, -1, 0));
  const test::Shape s = shape_of(r.mesh);
  EXPECT_EQ(s.vertices, 8);
  EXPECT_EQ(s.faces, 8);
  EXPECT_EQ(s.boundary_edges, 0);
  EXPECT_TRUE(s.oriented);
  EXPECT_NEAR(signed_volume(r.mesh), 8.0, 1e-12);
  EXPECT_EQ(r.selection, (std::vector<int>{0, 2, 4, 6}));
}

// A U-shaped face crossed through both arms: four crossings, paired along the plane's trace (not
// as they follow each other round the face, which pairs them wrongly from some starting corners),
// cut it into three pieces.
TEST(Bisect, AConcaveFaceCrossedFourTimesIsCutIntoThree) {
  const std::vector<Vec3> p = {{0, 0, 0}, {3, 0, 0}, {3, 2, 0}, {2, 2, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
  for (const std::vector<int>& face : {std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}, {3, 4, 5, 6, 7, 0, 1, 2}}) {
    const CovarianceMesh u = make_covariance_mesh(p, std::vector<Mat3>(p.size(), 0.1 * Mat3::Identity()), {face}, "U");
    const Modelled r = bisect(u, Vec3(0, 1.5, 0), Vec3(0, 1, 0));
    const MeshArrays a = arrays_of(r.mesh);
    const test::Shape s = shape_of(a);
    EXPECT_EQ(s.vertices, 12);
    EXPECT_EQ(s.faces, 3);
    EXPECT_TRUE(s.oriented);
    EXPECT_EQ(s.euler(), 1);
    double area = 0;  // the pieces tile the U: its area, 5
    for (int f = 0; f < a.n_faces(); ++f) {
      double lo = 9, hi = -9;
      for (int v : a.faces[size_t(f)])
        lo = std::min(lo, a.means[size_t(v)].y()), hi = std::max(hi, a.means[size_t(v)].y());
      EXPECT_TRUE(lo >= 1.5 - 1e-12 || hi <= 1.5 + 1e-12) << "a piece crosses the plane";
      area += 0.5 * newell_normal(a, f).z();
    }
    EXPECT_NEAR(area, 5.0, 1e-12);
  }
}

TEST(Bisect, ATriangleMeshStaysTriangles) {
  const CovarianceMesh ico = test::icosahedron_mesh();
  const Modelled r = bisect(ico, Vec3(0, 0, 0.1), Vec3(0.3, 0.2, 1));
  const MeshArrays a = arrays_of(r.mesh);
  for (const auto& face : a.faces) EXPECT_EQ(face.size(), 3u);
  const test::Shape s = shape_of(a);
  EXPECT_EQ(s.boundary_edges, 0);
  EXPECT_TRUE(s.oriented);
  EXPECT_EQ(s.euler(), 2);
  EXPECT_GT(s.vertices, 12);
  EXPECT_NEAR(signed_volume(a), signed_volume(arrays_of(ico)), 1e-12);
}

TEST(Bisect, ACreasedEdgeCrossedCreasesBothHalves) {
  CovarianceMesh cube = make_sample("cube");
  cube.sharpness.set_crease(0, 4, 2.5);
  const Modelled r = bisect(cube, Vec3::Zero(), Vec3(0, 0, 1));
  const MeshArrays a = arrays_of(r.mesh);
  int m = -1;
  for (int v = 8; v < 12; ++v)
    if ((a.means[size_t(v)] - Vec3(-1, -1, 0)).norm() < 1e-12) m = v;
  ASSERT_GE(m, 0);
  EXPECT_EQ(r.mesh.sharpness.crease(0, m), 2.5);
  EXPECT_EQ(r.mesh.sharpness.crease(m, 4), 2.5);
  EXPECT_EQ(r.mesh.sharpness.crease(0, 4), 0.0);
  EXPECT_EQ(r.mesh.sharpness.creases.size(), 2u);
}

TEST(Bisect, RefusalsSayWhy) {
  const CovarianceMesh cube = make_sample("cube");
  EXPECT_EQ(error_of([&] { bisect(cube, Vec3(0, 0, 5), Vec3(0, 0, 1)); }), "the plane crosses no face of the mesh");
  EXPECT_EQ(error_of([&] { bisect(cube, Vec3::Zero(), Vec3::Zero()); }), "the plane's normal is zero");
  EXPECT_EQ(error_of([&] { bisect(cube, Vec3(NAN, 0, 0), Vec3(0, 0, 1)); }),
            "the plane has a number that is not finite");
  // A face of the cube lies in the plane z = 1: nothing is crossed.
  EXPECT_EQ(error_of([&] { bisect(cube, Vec3(0, 0, 1), Vec3(0, 0, 1)); }), "the plane crosses no face of the mesh");
  // A plane through a loop of edges (a cylinder's middle ring) has the mesh on both sides: it was said
  // to cross no face.
  EXPECT_EQ(error_of([&] { bisect(make_sample("cylinder"), Vec3::Zero(), Vec3(0, 1, 0)); }),
            "the plane runs along edges of the mesh, which cut it there already: nothing to cut");
}

TEST(Bisect, TheOperationList) {
  const CovarianceMesh cube = make_sample("cube");
  const Modelled scripted =
      OperationList::parse(R"([{"op":"bisect","plane":{"point":[0,0,0.25],"normal":[0,0,1]}}])", "ops.json")
          .apply(cube);
  EXPECT_TRUE(test::same_mesh(scripted.mesh, bisect(cube, Vec3(0, 0, 0.25), Vec3(0, 0, 1)).mesh));
  EXPECT_EQ(scripted.selection, (std::vector<int>{8, 9, 10, 11}));
  const auto parse_error = [](const std::string& text) {
    return error_of([&] { OperationList::parse(text, "ops.json"); });
  };
  EXPECT_EQ(parse_error(R"([{"op":"bisect"}])"), "ops.json: ops[0] (bisect): \"plane\" is missing");
  EXPECT_EQ(parse_error(R"([{"op":"bisect","plane":[0,0,1]}])"),
            "ops.json: ops[0] (bisect): \"plane\" must be {\"point\": [x, y, z], \"normal\": [x, y, z]}");
  EXPECT_EQ(parse_error(R"([{"op":"bisect","plane":{"point":[0,0,0]}}])"),
            "ops.json: ops[0] (bisect): \"plane\": \"normal\" is missing");
  EXPECT_EQ(parse_error(R"([{"op":"bisect","plane":{"point":[0,0,0],"normal":[0,0,0]}}])"),
            "ops.json: ops[0] (bisect): \"plane\": \"normal\" must not be zero");
  EXPECT_EQ(parse_error(R"([{"op":"bisect","plane":{"point":[0,0,0],"normal":[0,0,1],"offset":1}}])"),
            "ops.json: ops[0] (bisect): \"plane\": unknown key 'offset'");
  EXPECT_EQ(parse_error(R"([{"op":"bisect","plane":{"point":[0,0,1e999],"normal":[0,0,1]}}])").rfind("ops.json: ", 0),
            0u);
  EXPECT_EQ(
      error_of([&] {
        OperationList::parse(R"([{"op":"bisect","plane":{"point":[0,0,3],"normal":[0,0,1]}}])", "ops.json").apply(cube);
      }),
      "ops.json: ops[0] (bisect): the plane crosses no face of the mesh");
}

}  // namespace
}  // namespace gps
