// The Normal transform orientation (ui/editing/transform_orientation.h) and G / S / R's axis keys
// cycling through the orientations (ui/editing/transform_mode.h), as Blender's.
#include <gtest/gtest.h>

#include <cmath>

#include "core/modelling/primitives.h"
#include "tests/support/test_meshes.h"
#include "ui/editing/transform_mode.h"
#include "ui/editing/transform_orientation.h"

namespace gps {
namespace {

constexpr double kTolerance = 1e-12;

// A right-handed orthonormal frame.
void expect_rotation(const Mat3& frame) {
  EXPECT_LT((frame.transpose() * frame - Mat3::Identity()).norm(), kTolerance);
  EXPECT_NEAR(frame.determinant(), 1.0, kTolerance);
}

TEST(TransformOrientation, ACubeFacesFrameIsItsFaceNormalAndAnEdge) {
  const CovarianceMesh cube = test::cube_mesh();
  const Mat3 frame = normal_frame(cube, {1, 2, 5, 6});  // the face at x = +1
  expect_rotation(frame);
  EXPECT_LT((frame.col(2) - Vec3::UnitX()).norm(), kTolerance);
  EXPECT_NEAR(std::abs(frame.col(1).y()) + std::abs(frame.col(1).z()), 1.0, kTolerance);  // along an edge
  const Mat3 top = normal_frame(cube, {4, 5, 6, 7});
  EXPECT_LT((top.col(2) - Vec3::UnitZ()).norm(), kTolerance);
}

TEST(TransformOrientation, FacesAverageTheirNormalsByArea) {
  // Two faces of the cube meeting at the edge 5–6: the normal halfway, the tangent along that edge.
  const Mat3 frame = normal_frame(test::cube_mesh(), {1, 2, 4, 5, 6, 7});
  expect_rotation(frame);
  EXPECT_LT((frame.col(2) - Vec3(1, 0, 1).normalized()).norm(), kTolerance);
}

// In face mode the held faces give the normal, not every face among their corners: three sides of the
// cube (+x, +y, −x) hold all eight vertices, whose six faces cancel out, but the three face +y.
TEST(TransformOrientation, HeldFacesGiveTheNormalNotTheFacesAmongTheirCorners) {
  const CovarianceMesh cube = test::cube_mesh();
  const std::vector<int> all{0, 1, 2, 3, 4, 5, 6, 7};
  EXPECT_EQ(normal_frame(cube, all), Mat3(Mat3::Identity()));
  const Mat3 frame = normal_frame(cube, all, {3, 4, 5}, {{2, 3}, {6, 7}});
  expect_rotation(frame);
  EXPECT_LT((frame.col(2) - Vec3::UnitY()).norm(), kTolerance);
  EXPECT_LT((frame.col(1).cwiseAbs() - Vec3::UnitX()).norm(), kTolerance);  // along the edges given
}

TEST(TransformOrientation, OneSphereVertexTakesTheRadialDirection) {
  const CovarianceMesh sphere = add_primitive(CovarianceMesh{}, Primitive::sphere, Vec3::Zero(), 2.0).mesh;
  ASSERT_GT(sphere.n_vertices(), 8u);
  for (size_t v = 0; v < sphere.n_vertices(); ++v) {
    const Mat3 frame = normal_frame(sphere, {int(v)});
    expect_rotation(frame);
    EXPECT_LT((frame.col(2) - sphere.mean(v).normalized()).norm(), 1e-9) << v;
  }
}

TEST(TransformOrientation, AnEdgeAveragesItsVertexNormalsAndFollowsTheEdge) {
  const Mat3 frame = normal_frame(test::cube_mesh(), {4, 5});  // the edge (−1,−1,1)–(1,−1,1)
  expect_rotation(frame);
  EXPECT_LT((frame.col(2) - Vec3(0, -1, 1).normalized()).norm(), kTolerance);
  EXPECT_NEAR(std::abs(frame.col(1).x()), 1.0, kTolerance);
}

TEST(TransformOrientation, AnEmptySelectionFallsBackToGlobal) {
  EXPECT_EQ(normal_frame(test::cube_mesh(), {}), Mat3::Identity());
}

TransformMode grab_of(const CovarianceMesh& mesh, const std::vector<int>& vertices) {
  return TransformMode(TransformKind::grab, mesh, vertices, vertices[0], TransformPivot::median, Viewport{},
                       glm::vec2(0.0f));
}

TEST(TransformOrientation, AnAxisKeyTakesGlobalThenNormalThenNone) {
  // A tilted face: the top of the cube turned about x, so that its normal is no world axis.
  MeshArrays a = arrays_of(test::cube_mesh());
  const Mat3 turn = Eigen::AngleAxisd(0.3, Vec3::UnitX()).toRotationMatrix();
  for (Vec3& p : a.means) p = turn * p;
  const CovarianceMesh tilted = build_mesh(a);
  const std::vector<int> top = {4, 5, 6, 7};
  TransformMode grab = grab_of(tilted, top);
  grab.set_orientations(TransformOrientation::global, normal_frame(tilted, top));
  grab.set_typed("0.5", 0.5);

  grab.constrain_axis(2, false);
  EXPECT_LT((grab.map(0).translation - Vec3(0, 0, 0.5)).norm(), kTolerance);
  EXPECT_NE(grab.describe().find(" along z"), std::string::npos) << grab.describe();
  grab.constrain_axis(2, false);
  EXPECT_LT((grab.map(0).translation - 0.5 * (turn * Vec3::UnitZ())).norm(), kTolerance);
  EXPECT_NE(grab.describe().find(" along normal z"), std::string::npos) << grab.describe();
  grab.constrain_axis(2, false);
  EXPECT_LT((grab.map(0).translation - Vec3(0.5, 0, 0)).norm(), kTolerance);  // unconstrained: typed along x
  EXPECT_EQ(grab.describe().find(" along"), std::string::npos) << grab.describe();
}

TEST(TransformOrientation, NormalFirstWhenItIsTheDefault) {
  MeshArrays a = arrays_of(test::cube_mesh());
  const Mat3 turn = Eigen::AngleAxisd(0.3, Vec3::UnitY()).toRotationMatrix();
  for (Vec3& p : a.means) p = turn * p;
  const CovarianceMesh tilted = build_mesh(a);
  const std::vector<int> top = {4, 5, 6, 7};
  const Mat3 frame = normal_frame(tilted, top);
  TransformMode scale(TransformKind::scale, tilted, top, top[0], TransformPivot::median, Viewport{}, glm::vec2(0.0f));
  scale.set_orientations(TransformOrientation::normal, frame);
  scale.set_typed("0", 0.0);
  scale.constrain_axis(2, true);  // Shift+Z: scaled to nothing across the normal, kept along it
  const Mat3 expected = frame.col(2) * frame.col(2).transpose();
  EXPECT_LT((scale.map(0).linear - expected).norm(), kTolerance);
  EXPECT_NE(scale.describe().find("in the plane normal to normal z"), std::string::npos) << scale.describe();
  scale.constrain_axis(2, true);  // again: the world's z
  EXPECT_LT((scale.map(0).linear - Vec3::UnitZ() * Vec3::UnitZ().transpose()).norm(), kTolerance);
}

}  // namespace
}  // namespace gps
