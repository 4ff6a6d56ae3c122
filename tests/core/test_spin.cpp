// Spinning a profile (core/modelling/spin.h): a full turn of a profile with its ends on the axis is
// a closed surface of revolution oriented outward, its Gaussians rotated exactly; a partial spin
// from a boundary edge continues the surface; refusals; the op list's "spin".
#include "core/modelling/spin.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
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

// A triangle far off (faces 0) and a profile of four vertices joined by no edge, 3 and 6 on the z
// axis: (0, 0, −1), (1, 0, −0.5), (1, 0, 0.5), (0, 0, 1); anisotropic covariances.
CovarianceMesh profile_mesh() {
  const std::vector<Vec3> p = {{10, 0, 0}, {11, 0, 0}, {10, 1, 0}, {0, 0, -1}, {1, 0, -0.5}, {1, 0, 0.5}, {0, 0, 1}};
  const CovarianceMesh m =
      make_covariance_mesh(p, std::vector<Mat3>(p.size(), 0.04 * Mat3::Identity()), {{0, 1, 2}}, "profile");
  return test::with_random_covariances(m, 11);
}

// A quad in the xz-plane: 0 (1, 0, 0), 1 (2, 0, 0), 2 (2, 0, 1), 3 (1, 0, 1); its edge 3 → 0 faces the z axis.
CovarianceMesh quad_mesh() {
  const std::vector<Vec3> p = {{1, 0, 0}, {2, 0, 0}, {2, 0, 1}, {1, 0, 1}};
  return make_covariance_mesh(p, std::vector<Mat3>(p.size(), 0.04 * Mat3::Identity()), {{0, 1, 2, 3}}, "quad");
}

TEST(Spin, AFullTurnIsAClosedSurfaceOfRevolution) {
  const CovarianceMesh mesh = profile_mesh();
  const CovarianceMesh copy = mesh;
  for (const std::vector<int>& profile : {std::vector<int>{3, 4, 5, 6}, {6, 5, 4, 3}}) {
    const Modelled r = spin(mesh, profile, Vec3(0, 0, 2), Vec3::Zero(), 360, 8);
    const MeshArrays a = arrays_of(r.mesh);
    const test::Shape s = shape_of(a);
    EXPECT_EQ(s.vertices, 7 + 2 * 7);  // the ends on the axis are not copied; the 8th step is the profile
    EXPECT_EQ(s.faces, 1 + 8 * 3);
    EXPECT_EQ(s.boundary_edges, 3);  // the far triangle's
    EXPECT_TRUE(s.oriented);
    EXPECT_EQ(s.euler(), 2 + 1);
    int triangles = 0;
    for (size_t f = 1; f < a.faces.size(); ++f) triangles += a.faces[f].size() == 3;
    EXPECT_EQ(triangles, 16);
    EXPECT_GT(signed_volume(a, 1), 0.0);
    EXPECT_EQ(r.selection, (std::vector<int>{3, 4, 5, 6}));
  }
  // Step k's copy of vertex 4 or 5 is Rₖμ, RₖΣRₖᵀ for the rotation by k · 45° about z.
  const Modelled r = spin(mesh, {3, 4, 5, 6}, Vec3(0, 0, 1), Vec3::Zero(), 360, 8);
  const MeshArrays before = arrays_of(mesh), after = arrays_of(r.mesh);
  for (int k = 1; k < 8; ++k) {
    const Mat3 rotation = Eigen::AngleAxisd(k * M_PI / 4, Vec3::UnitZ()).toRotationMatrix();
    for (int i = 0; i < 2; ++i) {
      const size_t original = size_t(4 + i), copied = size_t(7 + 2 * (k - 1) + i);
      EXPECT_LE((after.means[copied] - rotation * before.means[original]).norm(), 1e-15);
      const Mat3 expected = rotation * before.covariances[original] * rotation.transpose();
      EXPECT_LE((after.covariances[copied] - expected).norm(), 1e-15 * expected.norm());
    }
  }
  EXPECT_EQ(r.summary, "spun 4 vertices by 360° in 8 steps: 14 vertices, 24 faces added");
  EXPECT_TRUE(test::same_mesh(mesh, copy));
}

// A quarter turn of the quad's edge 0–3 about the z axis through the origin: three quads that
// continue the surface (oriented as the quad), ending at the last copy of the edge.
TEST(Spin, APartialTurnFromABoundaryEdgeContinuesTheSurface) {
  for (const std::vector<int>& profile : {std::vector<int>{0, 3}, {3, 0}}) {
    const Modelled r = spin(quad_mesh(), profile, Vec3(0, 0, 1), Vec3::Zero(), 90, 3);
    const MeshArrays a = arrays_of(r.mesh);
    const test::Shape s = shape_of(a);
    EXPECT_EQ(s.vertices, 4 + 6);
    EXPECT_EQ(s.faces, 4);
    EXPECT_TRUE(s.oriented);
    EXPECT_EQ(s.boundary_edges, 10);
    EXPECT_EQ(r.selection, (std::vector<int>{8, 9}));
    // The last copy of vertex 0 is (0, 1, 0).
    const int last = profile[0] == 0 ? 8 : 9;
    EXPECT_LE((a.means[size_t(last)] - Vec3(0, 1, 0)).norm(), 1e-15);
  }
}

TEST(Spin, CreasesAndCornersGoToTheCopies) {
  CovarianceMesh mesh = quad_mesh();
  mesh.sharpness.set_crease(0, 3, 2.0);
  mesh.sharpness.set_corner(3, 4.0, 4);
  const Modelled r = spin(mesh, {0, 3}, Vec3(0, 0, 1), Vec3::Zero(), 90, 2);  // copies 4, 5 and 6, 7
  EXPECT_EQ(r.mesh.sharpness.crease(4, 5), 2.0);
  EXPECT_EQ(r.mesh.sharpness.crease(6, 7), 2.0);
  EXPECT_EQ(r.mesh.sharpness.corner(5), 4.0);
  EXPECT_EQ(r.mesh.sharpness.corner(7), 4.0);
  EXPECT_EQ(r.mesh.sharpness.corner(4), 0.0);
}

TEST(Spin, RefusalsSayWhy) {
  const CovarianceMesh cube = make_sample("cube"), profile = profile_mesh(), quad = quad_mesh();
  const Vec3 z(0, 0, 1), o = Vec3::Zero();
  EXPECT_EQ(error_of([&] {
              spin(cube, {0, 1}, z, o, 90, 4);
            }),
            "edge 0–1 has faces on both sides (a spin from it would join three)");
  EXPECT_EQ(error_of([&] {
              spin(quad, {0, 3}, z, o, 360, 8);
            }),
            "edge 0–3 is an edge of the mesh (a full turn would close on it beside its face)");
  EXPECT_EQ(error_of([&] { spin(profile, {3, 4, 3, 5}, z, o, 90, 4); }), "vertex 3 is twice in the profile");
  EXPECT_EQ(error_of([&] { spin(profile, {3, 4, 3}, z, o, 90, 4); }), "a loop needs 3 vertices");
  EXPECT_EQ(error_of([&] { spin(profile, {4}, z, o, 90, 4); }), "the profile has 1 vertex (2 needed)");
  EXPECT_EQ(error_of([&] { spin(profile, {4, 9}, z, o, 90, 4); }), "vertex 9 is not in the mesh (7 vertices)");
  EXPECT_EQ(error_of([&] { spin(profile, {3, 6}, z, o, 90, 4); }), "the profile lies on the axis (nothing to spin)");
  EXPECT_EQ(error_of([&] { spin(profile, {4, 5}, o, o, 90, 4); }), "the spin's axis is zero");
  EXPECT_EQ(error_of([&] {
              spin(profile, {4, 5}, z, o, 0, 4);
            }),
            "the angle must be from -360 to 360 degrees and not 0, got 0");
  EXPECT_EQ(error_of([&] {
              spin(profile, {4, 5}, z, o, -360, 2);
            }),
            "the steps must be from 3 (a full turn) to 1000, got 2");
  EXPECT_EQ(error_of([&] {
              spin(profile, {4, 5}, z, Vec3(NAN, 0, 0), 90, 2);
            }),
            "the spin has a number that is not finite");
  // Vertex 3, on the axis, gets a triangle per step: past what a surface's patch plans take at a vertex.
  EXPECT_EQ(error_of([&] {
              spin(profile, {3, 4}, z, o, 90, 300);
            }),
            "vertex 3 lies on the axis, so 300 steps would give it 300 faces; a surface's patch plans take up to "
            "256 (at most 256 steps here)");
  EXPECT_EQ(spin(profile, {3, 4}, z, o, 90, 256).mesh.n_faces(), 1u + 256u);
  // Two quads of opposite orientation: the profile 1 → 0 → 5 → 4 runs against one and along the other.
  const std::vector<Vec3> p = {{1, 0, 0}, {2, 0, 0}, {2, 0, 1}, {1, 0, 1}, {1, 0, 3}, {2, 0, 3}, {2, 0, 4}, {1, 0, 4}};
  const CovarianceMesh two = make_covariance_mesh(p, std::vector<Mat3>(p.size(), 0.04 * Mat3::Identity()),
                                                  {{0, 1, 2, 3}, {4, 7, 6, 5}}, "two");
  EXPECT_EQ(error_of([&] {
              spin(two, {1, 0, 5, 4}, z, o, 90, 2);
            }),
            "the profile runs along boundary edges of opposite directions (edge 5–4)");
}

TEST(Spin, TheOperationList) {
  const CovarianceMesh mesh = profile_mesh();
  const Modelled scripted =
      OperationList::parse(
          R"([{"op":"spin","vertices":[3,4,5,6],"axis":[0,0,1],"center":[0,0,0],"angle":360,"steps":6}])", "o")
          .apply(mesh);
  EXPECT_TRUE(test::same_mesh(scripted.mesh, spin(mesh, {3, 4, 5, 6}, Vec3(0, 0, 1), Vec3::Zero(), 360, 6).mesh));
  const auto parse_error = [](const std::string& text) { return error_of([&] { OperationList::parse(text, "o"); }); };
  EXPECT_EQ(parse_error(R"([{"op":"spin","vertices":[3,4],"axis":[0,0,1],"angle":400,"steps":4}])"),
            "o: ops[0] (spin): \"angle\" must be from -360 to 360 degrees and not 0");
  EXPECT_EQ(parse_error(R"([{"op":"spin","vertices":[3,4],"axis":[0,0,1],"angle":360,"steps":2}])"),
            "o: ops[0] (spin): \"steps\" must be an integer from 3 to 1000, got 2");
  EXPECT_EQ(parse_error(R"([{"op":"spin","vertices":[3,4],"axis":[0,0,1],"angle":90,"steps":1.5}])"),
            "o: ops[0] (spin): \"steps\" must be an integer from 1 to 1000, got 1.5");
  EXPECT_EQ(parse_error(R"([{"op":"spin","vertices":[3,4],"axis":[0,0,0],"angle":90,"steps":1}])"),
            "o: ops[0] (spin): \"axis\" must not be zero");
  EXPECT_EQ(parse_error(R"([{"op":"spin","vertices":[3],"axis":[0,0,1],"angle":90,"steps":1}])"),
            "o: ops[0] (spin): \"vertices\" must be a chain of at least 2 vertices");
  EXPECT_EQ(parse_error(R"([{"op":"spin","vertices":[3,4],"axis":[0,0,1],"angle":90}])"),
            "o: ops[0] (spin): \"steps\" is missing");
}

}  // namespace
}  // namespace gps
