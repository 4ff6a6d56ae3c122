// The editor's 3D view (ui/display/viewport_frame.h) on an OSMesa context: an unchanged frame keeps
// its target, holding what drawing it again gives; a change of camera, of the surface or of the
// window's size is drawn; target points over the surface are drawn every frame, and the frame after
// they are hidden too.
#include <gtest/gtest.h>

#include "core/io/mesh_io.h"
#include "core/modelling/samples.h"
#include "tests/support/gl_fixture.h"
#include "tests/support/settled_target_points.h"
#include "tests/support/temp_dir.h"
#include "ui/display/viewport_frame.h"

namespace gps {
namespace {

using ViewportFrameTest = test::GlTest;

constexpr int kWidth = 80, kHeight = 60;

struct View {
  ShownSurface shown;
  TargetPointsLayer points;
  TargetPointsView target_view;
  Camera camera;
  DrawOptions options;
  ViewportFrame frame;

  explicit View(const CovarianceMesh& mesh) : camera(frame_mesh(mesh)) {
    shown.show(mesh, PlanOptions{});
    options.pixels = 6.0f;
  }
  // Draws `n` frames of the view as it is; returns how many of them kept the target.
  long long frames(int n, int width = kWidth, int height = kHeight) {
    const long long before = frame.kept_frames();
    for (int i = 0; i < n; ++i) frame.draw(shown, points, camera, options, target_view, width, height, true);
    return frame.kept_frames() - before;
  }
};

TEST_F(ViewportFrameTest, AnUnchangedFrameKeepsItsTargetAndAChangeIsDrawn) {
  CovarianceMesh cube = make_sample("cube");
  View view(cube);
  EXPECT_EQ(view.frame.target(), nullptr);
  EXPECT_GE(view.frames(6), 4) << "the frames after the capture and the first from the cache";
  const RenderTarget* target = view.frame.target();
  ASSERT_NE(target, nullptr);
  const Image kept = target->read(0);
  view.shown.renderer().draw(*target, view.camera, view.options);
  EXPECT_EQ(target->read(0).pixels, kept.pixels) << "the kept frame is what a draw gives";

  view.camera.yaw_degrees += 5.0f;
  EXPECT_EQ(view.frames(1), 0) << "a turn";
  EXPECT_NE(target->read(0).pixels, kept.pixels);
  EXPECT_GE(view.frames(3), 2);
  cube.set_mean(6, 1.2 * cube.mean(6));
  view.shown.show_edit(cube, {6}, PlanOptions{});
  EXPECT_EQ(view.frames(1), 0) << "an edit";
  EXPECT_GE(view.frames(3), 2);
  EXPECT_EQ(view.frames(1, kWidth + 1, kHeight), 0) << "another size";
  EXPECT_EQ(view.frame.target()->width(), kWidth + 1);
}

TEST_F(ViewportFrameTest, TargetPointsAreDrawnEveryFrameAndOnceMoreWhenHidden) {
  const test::TempDir dir;
  const CovarianceMesh cube = make_sample("cube");
  write_mesh(dir.file("target.ply"), cube);
  View view(cube);
  view.points.points().load(dir.file("target.ply"));
  auto now = TargetPointsLayer::Clock::now();
  test::settle(view.points, view.shown, cube, view.target_view, now);
  ASSERT_TRUE(view.points.draws(view.target_view));
  EXPECT_EQ(view.frames(5), 0);
  const Image with_points = view.frame.target()->read(0);
  view.target_view.shown = false;
  EXPECT_EQ(view.frames(1), 0) << "the points drawn last frame are drawn over";
  EXPECT_NE(view.frame.target()->read(0).pixels, with_points.pixels);
  EXPECT_EQ(view.frames(3), 3);
}

}  // namespace
}  // namespace gps
