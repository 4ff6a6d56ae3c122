// Snapping while transforming: the points under the pointer (view/snap_point.h) on the cube, and a
// grab, scale and rotation rounded to increments or taken onto a point (ui/editing/transform_mode.h).
#include "view/snap_point.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "core/modelling/samples.h"
#include "ui/editing/transform_mode.h"
#include "tests/support/view_pixels.h"
#include "view/picking.h"

namespace gps {
namespace {

using test::pixel_of;

class Snapping : public ::testing::Test {
protected:
  CovarianceMesh mesh_ = make_sample("cube");
  Viewport view_ = test::framed_view(mesh_);
};

TEST_F(Snapping, AVertexNearThePointerIsFoundUnlessItMoves) {
  for (size_t v = 0; v < mesh_.n_vertices(); ++v) {
    const glm::vec2 near = pixel_of(view_, mesh_.mean(v)) + glm::vec2(3.0f, -2.0f);
    const auto snapped = find_snap_point(mesh_, view_, near, SnapTarget::vertex, {}, 16.0f);
    ASSERT_TRUE(snapped) << v;
    // The cube's hidden corner projects inside the silhouette, away from the others.
    EXPECT_EQ(snapped->point, mesh_.mean(v)) << v;
    EXPECT_EQ(snapped->element, "vertex " + std::to_string(v));
    const auto without = find_snap_point(mesh_, view_, near, SnapTarget::vertex, {int(v)}, 16.0f);
    EXPECT_TRUE(!without || without->point != mesh_.mean(v)) << v;
  }
  EXPECT_FALSE(find_snap_point(mesh_, view_, glm::vec2(3.0f, 3.0f), SnapTarget::vertex, {}, 16.0f));
  EXPECT_FALSE(find_snap_point(mesh_, view_, pixel_of(view_, mesh_.mean(0)), SnapTarget::increment, {}, 16.0f));
}

TEST_F(Snapping, AnEdgePointLiesOnTheEdgeUnderThePointer) {
  int found = 0;
  for (size_t e = 0; e < mesh_.n_edges(); ++e) {
    const Vec3 a = mesh_.mean(size_t(mesh_.edge(e)[0])), b = mesh_.mean(size_t(mesh_.edge(e)[1]));
    const Vec3 on = a + 0.3 * (b - a);
    const auto snapped = find_snap_point(mesh_, view_, pixel_of(view_, on), SnapTarget::edge, {}, 4.0f);
    ASSERT_TRUE(snapped);
    // Where edges cross on the screen either may be taken; every point found lies on an edge under the pointer.
    EXPECT_LT(glm::length(pixel_of(view_, snapped->point) - pixel_of(view_, on)), 0.5f);
    if ((snapped->point - on).norm() < 1e-5) ++found;
  }
  EXPECT_GE(found, 9);  // all but the hidden corner's edges, at least
  // An edge that touches a moving vertex is never taken.
  const auto [v0, v1] = mesh_.edge(0);
  const Vec3 a = mesh_.mean(size_t(v0)), b = mesh_.mean(size_t(v1));
  const auto without = find_snap_point(mesh_, view_, pixel_of(view_, 0.5 * (a + b)), SnapTarget::edge, {v0}, 4.0f);
  EXPECT_TRUE(!without ||
              without->element != "edge " + std::to_string(std::min(v0, v1)) + "–" + std::to_string(std::max(v0, v1)));
}

TEST_F(Snapping, AFacePointIsWhereThePointersRayMeetsTheFrontFace) {
  const Vec3 eye = to_vec(view_.camera.eye_double());
  for (size_t f = 0; f < mesh_.n_faces(); ++f) {
    Vec3 centre = Vec3::Zero();
    for (const int v : mesh_.face(f)) centre += 0.25 * mesh_.mean(size_t(v));
    if (centre.dot(eye - centre) <= 0) continue;  // a back face
    const Vec3 off_centre = centre + 0.2 * (mesh_.mean(size_t(mesh_.face(f)[0])) - centre);
    const auto snapped = find_snap_point(mesh_, view_, pixel_of(view_, off_centre), SnapTarget::face, {}, 16.0f);
    ASSERT_TRUE(snapped);
    EXPECT_EQ(snapped->element, "face " + std::to_string(f));
    EXPECT_LT((snapped->point - off_centre).norm(), 1e-4) << snapped->point.transpose();
  }
}

TransformMode start(TransformKind kind, const CovarianceMesh& mesh, const Viewport& view) {
  return TransformMode(kind, mesh, {6}, 6, TransformPivot::median, view, glm::vec2(320.0f, 240.0f));
}

TEST_F(Snapping, IncrementsRoundTheMouseAmount) {
  TransformMode grab = start(TransformKind::grab, mesh_, view_);
  grab.move_cursor(glm::vec2(371.0f, 203.0f), view_);
  grab.snap_increment(0.25, 0.1, 5.0);
  const Vec3 t = grab.map(0).translation;
  EXPECT_GT(t.norm(), 0.1);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(t[i], std::round(t[i] / 0.25) * 0.25) << i;

  grab.constrain_axis(2, false);  // along z: only z moves, by whole steps
  grab.move_cursor(glm::vec2(371.0f, 283.0f), view_);
  grab.snap_increment(0.25, 0.1, 5.0);
  const Vec3 z = grab.map(0).translation;
  EXPECT_EQ(z.x(), 0.0);
  EXPECT_EQ(z.y(), 0.0);
  EXPECT_EQ(z.z(), std::round(z.z() / 0.25) * 0.25);

  TransformMode rotate = start(TransformKind::rotate, mesh_, view_);
  rotate.move_cursor(glm::vec2(300.0f, 170.0f), view_);
  rotate.snap_increment(0.25, 0.1, 5.0);
  const double degrees = Eigen::AngleAxisd(Mat3(rotate.map(0).linear)).angle() * 180.0 / M_PI;
  EXPECT_NEAR(degrees / 5.0, std::round(degrees / 5.0), 1e-9) << degrees;
}

TEST_F(Snapping, APointTakesThePivotAlongTheConstraint) {
  const Vec3 target(0.3, -0.7, 2.0);
  TransformMode grab = start(TransformKind::grab, mesh_, view_);
  grab.snap_to(target);
  EXPECT_LT((grab.map(0).apply(mesh_.mean(6)) - target).norm(), 1e-15);
  grab.constrain_axis(0, false);  // along x: only the x of the point
  grab.snap_to(target);
  const Vec3 moved = grab.map(0).apply(mesh_.mean(6));
  EXPECT_DOUBLE_EQ(moved.x(), target.x());
  EXPECT_EQ(moved.y(), mesh_.mean(6).y());
  EXPECT_EQ(moved.z(), mesh_.mean(6).z());
  grab.constrain_axis(1, true);  // in the plane normal to y: x and z of the point
  grab.snap_to(target);
  const Vec3 in_plane = grab.map(0).apply(mesh_.mean(6));
  EXPECT_DOUBLE_EQ(in_plane.x(), target.x());
  EXPECT_EQ(in_plane.y(), mesh_.mean(6).y());
  EXPECT_DOUBLE_EQ(in_plane.z(), target.z());
}

TEST_F(Snapping, TheCursorPivotScalesAboutTheCursor) {
  const Vec3 cursor(0.5, 0.25, -1.0);
  TransformMode scale(TransformKind::scale, mesh_, {6}, 6, TransformPivot::cursor, view_, glm::vec2(320.0f, 240.0f),
                      cursor);
  scale.set_typed("2", 2.0);
  EXPECT_LT((scale.map(0).apply(mesh_.mean(6)) - (2.0 * mesh_.mean(6) - cursor)).norm(), 1e-15);
  EXPECT_EQ(std::string(pivot_name(TransformPivot::cursor)), "3D cursor");
}

}  // namespace
}  // namespace gps
