// Handle hit-testing and drag math on a real camera, without a window.
#include "ui/editing/axis_handles.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "core/modelling/samples.h"
#include "tests/support/view_pixels.h"
#include "view/picking.h"

namespace gps {
namespace {

using test::pixel_of;

// A cube whose vertex 0 carries an anisotropic, rotated Gaussian large enough to see.
CovarianceMesh test_mesh() {
  CovarianceMesh mesh = make_sample("cube");
  const Mat3 r = Eigen::AngleAxisd(0.4, Vec3(1, 2, 0.5).normalized()).toRotationMatrix();
  mesh.covariances[0] = r * Vec3(0.01, 0.04, 0.09).asDiagonal() * r.transpose();
  mesh.covariances[3] = Vec3(0.02, 0.03, 0.05).asDiagonal();
  return mesh;
}

Viewport test_view(int width = 900, int height = 700) {
  Viewport v;
  v.camera = frame_box(Vec3(-1, -1, -1), Vec3(1, 1, 1), 35.0f, 25.0f);
  v.width = width;
  v.height = height;
  return v;
}

Vec3 sorted_sigmas(const Mat3& c) { return Eigen::SelfAdjointEigenSolver<Mat3>(c).eigenvalues().cwiseSqrt(); }

// A drag applied as the editor applies it: each vertex's change to its Gaussian at the drag's start.
struct AppliedDrag {
  AppliedDrag(const CovarianceMesh& mesh, const std::vector<int>& vertices, const Handle& grabbed, double k_sigma,
              const Viewport& view, glm::vec2 start_pixel)
      : drag(mesh, vertices, grabbed, k_sigma, view, start_pixel), start(mesh) {}
  bool update(CovarianceMesh& mesh, const Viewport& view, glm::vec2 pixel, const DragModifiers& modifiers = {}) {
    const auto changes = drag.update(view, pixel, modifiers);
    if (!changes) return false;
    for (size_t i = 0; i < drag.vertices().size(); ++i) {
      const size_t v = size_t(drag.vertices()[i]);
      mesh.set_mean(v, (*changes)[i].apply_to_mean(start.mean(v)));
      mesh.set_covariance(v, (*changes)[i].keeps_covariance() ? start.covariance(v)
                                                              : (*changes)[i].apply_to_covariance(start.covariance(v)));
    }
    return true;
  }
  HandleDrag drag;
  CovarianceMesh start;
};

TEST(AxisHandles, EveryHandleIsHitAtItsPixel) {
  const CovarianceMesh mesh = test_mesh();
  for (const auto& [w, h] : {std::pair{900, 700}, std::pair{320, 900}, std::pair{1920, 400}}) {
    const Viewport view = test_view(w, h);
    const HandleFrame f = handle_frame(mesh, 0, 2.0, view);
    for (int axis = 0; axis < 3; ++axis)
      for (const int side : {1, -1}) {
        const auto hit = hit_handle(view, pixel_of(view, f.end(axis, side)), mesh, {0}, 2.0);
        ASSERT_TRUE(hit.has_value());
        EXPECT_EQ(hit->vertex, 0);
        EXPECT_EQ(hit->axis, axis) << w << "x" << h;
        EXPECT_EQ(hit->side, side);
      }
    const auto centre = hit_handle(view, pixel_of(view, f.centre), mesh, {0}, 2.0);
    ASSERT_TRUE(centre.has_value());
    EXPECT_TRUE(centre->is_centre());
    EXPECT_FALSE(hit_handle(view, glm::vec2(2.0f, 2.0f), mesh, {0}, 2.0).has_value());
  }
}

TEST(AxisHandles, TinyGaussiansKeepGrabbableHandles) {
  CovarianceMesh mesh = make_sample("cube");
  mesh.covariances[0] = 1e-10 * Mat3::Identity();
  const Viewport view = test_view();
  const HandleFrame f = handle_frame(mesh, 0, 1.0, view, 24.0);
  for (int axis = 0; axis < 3; ++axis) {
    const float on_screen = glm::length(pixel_of(view, f.end(axis, 1)) - pixel_of(view, f.centre));
    EXPECT_GT(on_screen, 5.0f);  // 24 px along the view plane, foreshortened at most this much here
    EXPECT_LE(on_screen, 24.5f);
  }
}

// Dragging an axis end along its axis by d scales that σ by (r + d)/r; the others stay.
TEST(AxisHandles, DraggingAnEndAlongTheAxisScalesItsSigma) {
  const Viewport view = test_view();
  for (int axis = 0; axis < 3; ++axis)
    for (const double target : {1.6, 0.7}) {
      CovarianceMesh mesh = test_mesh();
      const Vec3 before = sorted_sigmas(mesh.covariance(0));
      const HandleFrame f = handle_frame(mesh, 0, 2.0, view);
      const Vec3 end = f.end(axis, 1), goal = f.centre + target * (end - f.centre);
      AppliedDrag drag(mesh, {0}, Handle{0, axis, 1}, 2.0, view, pixel_of(view, end));
      ASSERT_TRUE(drag.update(mesh, view, pixel_of(view, goal)));
      const Vec3 after = sorted_sigmas(mesh.covariance(0));
      // The scaled σ may change rank; compare as multisets.
      Vec3 expected = before;
      expected[axis] *= target;
      std::sort(expected.data(), expected.data() + 3);
      EXPECT_LT((after - expected).cwiseAbs().maxCoeff(), 0.01 * expected.maxCoeff())
          << "axis " << axis << " × " << target;
      EXPECT_EQ(mesh.mean(0), test_mesh().mean(0));
      for (size_t v = 1; v < mesh.n_vertices(); ++v) EXPECT_EQ(mesh.covariance(v), test_mesh().covariance(v));
    }
}

TEST(AxisHandles, DraggingAcrossTheAxisRotatesAndKeepsTheEigenvalues) {
  const Viewport view = test_view();
  CovarianceMesh mesh = test_mesh();
  const Mat3 original = mesh.covariance(0);
  const HandleFrame f = handle_frame(mesh, 0, 2.0, view);
  const glm::vec2 start = pixel_of(view, f.end(2, 1));
  const glm::vec2 along = glm::normalize(start - pixel_of(view, f.centre));
  AppliedDrag drag(mesh, {0}, Handle{0, 2, 1}, 2.0, view, start);
  ASSERT_TRUE(drag.update(mesh, view, start + 30.0f * glm::vec2(-along.y, along.x)));
  EXPECT_GT((mesh.covariance(0) - original).norm(), 1e-3 * original.norm());  // it turned
  // Motion across the projected axis has no component along the axis in the drag plane up to the
  // pixel grid, so the eigenvalues stay to within a small fraction.
  const Vec3 a = sorted_sigmas(original), b = sorted_sigmas(mesh.covariance(0));
  EXPECT_LT((a - b).cwiseAbs().maxCoeff(), 0.02 * a.maxCoeff());
  // The axis now points toward the cursor: its end projects onto the cursor's direction.
  const HandleFrame g = handle_frame(mesh, 0, 2.0, view);
  int best = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(g.axes.sigmas[k] - a[2]) < std::abs(g.axes.sigmas[best] - a[2])) best = k;
  const glm::vec2 d0 = glm::normalize(pixel_of(view, g.end(best, 1)) - pixel_of(view, g.centre));
  const glm::vec2 d1 = glm::normalize(start + 30.0f * glm::vec2(-along.y, along.x) - pixel_of(view, f.centre));
  EXPECT_GT(std::abs(glm::dot(d0, d1)), 0.99f);
}

TEST(AxisHandles, EveryDragKeepsCovariancesPositiveDefinite) {
  const Viewport view = test_view();
  CovarianceMesh mesh = test_mesh();
  const HandleFrame f = handle_frame(mesh, 0, 2.0, view);
  const glm::vec2 start = pixel_of(view, f.end(0, 1));
  AppliedDrag drag(mesh, {0}, Handle{0, 0, 1}, 2.0, view, start);
  for (const glm::vec2 to :
       {pixel_of(view, f.end(0, -1)), pixel_of(view, f.centre), start + glm::vec2(4000, -3000), glm::vec2(0, 0)}) {
    if (!drag.update(mesh, view, to)) continue;
    EXPECT_TRUE(is_spd(mesh.covariance(0)));
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<Mat3>(mesh.covariance(0)).eigenvalues().minCoeff(), 0.0);
  }
}

TEST(AxisHandles, CentreDragMovesEverySelectedMeanByTheSameVector) {
  const Viewport view = test_view();
  CovarianceMesh mesh = test_mesh();
  const CovarianceMesh original = mesh;
  const glm::vec2 start = pixel_of(view, mesh.mean(0));
  AppliedDrag drag(mesh, {0, 3}, Handle{0, -1, 1}, 2.0, view, start);
  ASSERT_TRUE(drag.update(mesh, view, start + glm::vec2(40, -25)));
  const Vec3 d0 = mesh.mean(0) - original.mean(0), d3 = mesh.mean(3) - original.mean(3);
  EXPECT_GT(d0.norm(), 0.01);
  EXPECT_LT((d0 - d3).norm(), 1e-12);
  // The grabbed vertex follows the cursor.
  EXPECT_LT(glm::length(pixel_of(view, mesh.mean(0)) - (start + glm::vec2(40, -25))), 0.05f);
  EXPECT_EQ(mesh.covariance(0), original.covariance(0));
}

TEST(AxisHandles, SeveralSelectedVerticesGetTheSameRelativeChange) {
  const Viewport view = test_view();
  CovarianceMesh mesh = test_mesh();
  const CovarianceMesh original = mesh;
  const HandleFrame f = handle_frame(mesh, 0, 2.0, view);
  const Vec3 end = f.end(1, 1);
  AppliedDrag drag(mesh, {0, 3}, Handle{0, 1, 1}, 2.0, view, pixel_of(view, end));
  ASSERT_TRUE(drag.update(mesh, view, pixel_of(view, f.centre + 1.5 * (end - f.centre))));
  // Vertex 3's middle σ grew by the same factor; its others stayed.
  Vec3 expected = sorted_sigmas(original.covariance(3));
  expected[1] *= 1.5;
  std::sort(expected.data(), expected.data() + 3);
  EXPECT_LT((sorted_sigmas(mesh.covariance(3)) - expected).cwiseAbs().maxCoeff(), 0.01 * expected.maxCoeff());
  for (const size_t v : {1, 2, 4, 5, 6, 7}) EXPECT_EQ(mesh.covariance(v), original.covariance(v));
}

// A scale drag changes exactly one σ and keeps the frame; a turn keeps every σ; Shift scales all
// three; the axis keeps its index (its colour) for the whole drag.
TEST(AxisHandles, AScaleDragChangesOneSigmaAndKeepsTheFrameExactly) {
  const Viewport view = test_view();
  for (int axis = 0; axis < 3; ++axis) {
    CovarianceMesh mesh = test_mesh();
    const EllipsoidAxes before = ellipsoid_axes(mesh.covariance(0));
    const HandleFrame f = handle_frame(mesh, 0, 2.0, view);
    const Vec3 end = f.end(axis, 1);
    AppliedDrag drag(mesh, {0}, Handle{0, axis, 1}, 2.0, view, pixel_of(view, end));
    // Past the other σ: the dragged axis keeps its index (and colour) however its rank changes.
    ASSERT_TRUE(drag.update(mesh, view, pixel_of(view, f.centre + 4.0 * (end - f.centre))));
    EXPECT_EQ(drag.drag.kind(), HandleDrag::Kind::scale);
    for (int k = 0; k < 3; ++k) {
      const Vec3 u = before.axes.col(k);
      // Each start axis is still an eigenvector: Σ'u ∥ u, and its σ changed only for the dragged one.
      const Vec3 image = mesh.covariance(0) * u;
      EXPECT_LT((image - image.dot(u) * u).norm(), 1e-9 * image.norm()) << "axis " << k;
      const double sigma = std::sqrt(u.dot(mesh.covariance(0) * u));
      if (k == axis)
        EXPECT_GT(sigma, 2.0 * before.sigmas[k]);
      else
        EXPECT_NEAR(sigma, before.sigmas[k], 1e-9 * before.sigmas[k]) << "axis " << k;
    }
    const HandleFrame during = drag.drag.frame(view);
    EXPECT_LT((during.axes.axes.col(axis) - before.axes.col(axis)).norm(), 1e-9);
  }
}

TEST(AxisHandles, ATurnKeepsEverySigmaExactly) {
  const Viewport view = test_view();
  CovarianceMesh mesh = test_mesh();
  const Vec3 before = sorted_sigmas(mesh.covariance(0));
  const HandleFrame f = handle_frame(mesh, 0, 2.0, view);
  const glm::vec2 start = pixel_of(view, f.end(1, 1));
  const glm::vec2 along = glm::normalize(start - pixel_of(view, f.centre));
  AppliedDrag drag(mesh, {0}, Handle{0, 1, 1}, 2.0, view, start);
  // Across first (decides a turn), then with some motion along the axis too: still only a turn.
  ASSERT_TRUE(drag.update(mesh, view, start + 20.0f * glm::vec2(-along.y, along.x)));
  ASSERT_TRUE(drag.update(mesh, view, start + 30.0f * glm::vec2(-along.y, along.x) + 25.0f * along));
  EXPECT_EQ(drag.drag.kind(), HandleDrag::Kind::rotate);
  EXPECT_GT((mesh.covariance(0) - test_mesh().covariance(0)).norm(), 1e-3 * mesh.covariance(0).norm());
  EXPECT_LT((sorted_sigmas(mesh.covariance(0)) - before).cwiseAbs().maxCoeff(), 1e-9 * before.maxCoeff());
  // Ctrl snaps the angle to 5°.
  const auto snapped = drag.drag.update(view, start + 30.0f * glm::vec2(-along.y, along.x), DragModifiers{false, true});
  ASSERT_TRUE(snapped.has_value());
  const double degrees = Eigen::AngleAxisd((*snapped)[0].rotation).angle() * 180.0 / M_PI;
  EXPECT_NEAR(degrees, 5.0 * std::round(degrees / 5.0), 1e-9);
}

TEST(AxisHandles, ShiftScalesAllThreeSigmas) {
  const Viewport view = test_view();
  CovarianceMesh mesh = test_mesh();
  const Vec3 before = sorted_sigmas(mesh.covariance(0));
  const HandleFrame f = handle_frame(mesh, 0, 2.0, view);
  const Vec3 end = f.end(2, 1);
  AppliedDrag drag(mesh, {0}, Handle{0, 2, 1}, 2.0, view, pixel_of(view, end));
  ASSERT_TRUE(drag.update(mesh, view, pixel_of(view, f.centre + 1.5 * (end - f.centre)), DragModifiers{true, false}));
  const Vec3 ratio = sorted_sigmas(mesh.covariance(0)).cwiseQuotient(before);
  EXPECT_NEAR(ratio[0], 1.5, 0.01);
  EXPECT_NEAR(ratio[1], ratio[0], 1e-9);
  EXPECT_NEAR(ratio[2], ratio[0], 1e-9);
}

TEST(AxisHandles, AConstrainedMoveChangesOneCoordinate) {
  const Viewport view = test_view();
  for (int axis = 0; axis < 3; ++axis) {
    CovarianceMesh mesh = test_mesh();
    const Vec3 before = mesh.mean(0);
    const glm::vec2 start = pixel_of(view, before);
    AppliedDrag drag(mesh, {0}, Handle{0, -1, 1}, 2.0, view, start);
    drag.drag.constrain(MoveConstraint::axis, axis);
    ASSERT_TRUE(drag.update(mesh, view, start + glm::vec2(35, -20)));
    const Vec3 moved = mesh.mean(0) - before;
    EXPECT_GT(std::abs(moved[axis]), 0.01) << axis;
    for (int k = 0; k < 3; ++k) {
      if (k == axis) continue;
      EXPECT_EQ(mesh.mean(0)[k], before[k]) << axis;
    }
    // A typed distance replaces the mouse's.
    drag.drag.set_typed("0.25");
    ASSERT_TRUE(drag.update(mesh, view, start + glm::vec2(35, -20)));
    EXPECT_NEAR(mesh.mean(0)[axis] - before[axis], 0.25, 1e-12);
  }
  // Along the normal: the motion is parallel to the vertex normal.
  CovarianceMesh mesh = test_mesh();
  const glm::vec2 start = pixel_of(view, mesh.mean(0));
  AppliedDrag drag(mesh, {0}, Handle{0, -1, 1}, 2.0, view, start);
  drag.drag.constrain(MoveConstraint::normal);
  drag.drag.set_typed("-0.1");
  ASSERT_TRUE(drag.update(mesh, view, start));
  const Vec3 normal = (test_mesh().mean(0) - Vec3::Zero()).normalized();  // the cube's corner normal points outward
  EXPECT_LT(((mesh.mean(0) - test_mesh().mean(0)) - (-0.1) * normal).norm(), 1e-9);
}

}  // namespace
}  // namespace gps
