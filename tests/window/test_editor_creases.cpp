// The crease tool in a real window under Xvfb, as a designer uses it on a quad cube: the top face
// selected (face mode, one click: its four edges), Shift+E, a typed 10 (∞) or a drag, Enter; the
// saved file holds exactly those creases, Ctrl+Z gives the original file byte for byte (Ctrl+Shift+Z
// the creases again), the Inspector's crease field sets them too, and Esc
// changes nothing. Corners the same way with Ctrl+Shift+V. Screenshots kept in
// build/test-artefacts/EditorCreases/.
#include <gtest/gtest.h>

#include <filesystem>

#include "../support/editor_driver.h"
#include "core/io/mesh_io.h"
#include "core/io/text_file.h"
#include "core/modelling/samples.h"
#include "core/mesh/sharpness.h"
#include "ui/editing/crease_tool.h"

namespace gps {
namespace {

using test::artefact;
using test::editor_view;
using test::Events;
using test::pixel_of;

constexpr int kWidth = test::kWindowWidth, kHeight = test::kWindowHeight;

class EditorCreases : public ::testing::Test {
protected:
  void SetUp() override {
    write_mesh(dir_.file("original.ply"), make_sample("cube"));
    original_ = read_mesh(dir_.file("original.ply"));
    view_ = editor_view(original_);
  }
  // The top face (y = 1: vertices 2, 3, 6, 7) selected by a click on its centre in face mode.
  Events top_face_selected() const {
    Vec3 centre = Vec3::Zero();
    for (const int v : kTop) centre += original_.mean(size_t(v)) / 4.0;
    Events e;
    e.key("3").wait().click(pixel_of(view_, centre)).wait();
    return e;
  }
  CovarianceMesh play(const Events& events, const std::string& extra, const std::string& mesh = "original.ply") const {
    const auto r = test::play_editor(dir_, dir_.file(mesh), events, kWidth, kHeight, extra);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return read_mesh(dir_.file("saved.ply"));
  }
  // The saved mesh's creases must be exactly the top face's four edges at `sharpness`, no corners.
  static void expect_top_creases(const CovarianceMesh& saved, double sharpness) {
    const std::vector<EdgeCrease> expected = {
        {2, 3, sharpness}, {2, 6, sharpness}, {3, 7, sharpness}, {6, 7, sharpness}};
    EXPECT_EQ(saved.sharpness.creases, expected);
    EXPECT_TRUE(saved.sharpness.corners.empty());
  }

  static constexpr int kTop[4] = {2, 3, 6, 7};
  test::TempDir dir_;
  CovarianceMesh original_;
  Viewport view_;
};

TEST_F(EditorCreases, TypedInfiniteSharpnessCreasesTheTopRimAndUndoesExactly) {
  Events crease = top_face_selected();
  crease.key("shift+e").wait().text("10").wait().key("enter").wait(3);
  Events shown = crease;  // the selection cleared, so that the screenshot shows the creases' colour
  shown.key("alt+a").wait(3);
  const CovarianceMesh creased =
      play(shown, "--save " + dir_.file("saved.ply") + " --screenshot " + artefact("cube_top_rim_creased.png"));
  expect_top_creases(creased, kInfiniteSharpness);
  EXPECT_EQ(creased.n_vertices(), original_.n_vertices());
  for (size_t v = 0; v < original_.n_vertices(); ++v) {
    EXPECT_EQ(creased.mean(v), original_.mean(v));
    EXPECT_EQ(creased.covariance(v), original_.covariance(v));
  }

  // Saved in place (Ctrl+S), then undone and saved again: the original file, byte for byte.
  std::filesystem::copy_file(dir_.file("original.ply"), dir_.file("work.ply"));
  Events undone = crease;
  undone.key("ctrl+s").wait().key("ctrl+z").wait(3);
  play(undone, "--save " + dir_.file("saved.ply") + " --screenshot " + artefact("cube_undone.png"), "work.ply");
  expect_top_creases(read_mesh(dir_.file("work.ply")), kInfiniteSharpness);
  EXPECT_EQ(read_text_file(dir_.file("saved.ply")), read_text_file(dir_.file("original.ply")));

  // Redone (Ctrl+Shift+Z): the creases again.
  Events redone = crease;
  redone.key("ctrl+z").wait().key("ctrl+shift+z").wait(3);
  expect_top_creases(play(redone, "--save " + dir_.file("saved.ply")), kInfiniteSharpness);
}

// A horizontal drag of half the tool's span from smooth gives half the range: sharpness 5.
TEST_F(EditorCreases, ADragSetsTheSharpness) {
  const glm::vec2 start(300.0f, 600.0f), end = start + glm::vec2(0.5f * crease_drag_span(float(kWidth)), 0.0f);
  Events drag = top_face_selected();
  drag.move(start).wait().key("shift+e").wait();
  for (int k = 1; k <= 4; ++k) drag.move(start + float(k) / 4.0f * (end - start)).wait();
  drag.key("enter").wait().key("alt+a").wait(3);
  expect_top_creases(play(drag, "--save " + dir_.file("saved.ply") + " --screenshot " + artefact("cube_top_rim_5.png")),
                     5.0);
}

TEST_F(EditorCreases, EscapeAndRightClickChangeNothing) {
  Events cancelled = top_face_selected();
  cancelled.key("shift+e").wait().text("7").wait().key("escape").wait();
  cancelled.key("shift+e").wait().move(glm::vec2(700.0f, 600.0f)).wait();
  cancelled.add(R"({"type": "click", "button": "right", "x": 700, "y": 600})").wait(3);
  play(cancelled, "--save " + dir_.file("saved.ply"));
  EXPECT_EQ(read_text_file(dir_.file("saved.ply")), read_text_file(dir_.file("original.ply")));
}

// The Inspector's crease field (below the rotation row, its default place in a 1024 × 700 window):
// a typed 2.5 and Enter sets the selected edges' sharpness.
TEST_F(EditorCreases, TheInspectorsCreaseFieldSetsTheSharpness) {
  const glm::vec2 crease_field(700.0f, 166.0f);
  Events typed = top_face_selected();
  typed.click(crease_field).wait().text("2.5").wait().key("enter").wait(3);
  expect_top_creases(
      play(typed, "--save " + dir_.file("saved.ply") + " --screenshot " + artefact("inspector_crease_2.5.png")), 2.5);
}

// Corner sharpness: the vertex nearest the camera, clicked in vertex mode, Ctrl+Shift+V, 3, Enter.
TEST_F(EditorCreases, CtrlShiftVSetsTheVertexCornerSharpness) {
  int nearest = 0;
  const Vec3 eye = to_vec(view_.camera.eye());
  for (size_t v = 1; v < original_.n_vertices(); ++v)
    if ((original_.mean(v) - eye).norm() < (original_.mean(size_t(nearest)) - eye).norm()) nearest = int(v);
  Events corner;
  corner.key("1").wait().click(pixel_of(view_, original_.mean(size_t(nearest)))).wait();
  corner.key("ctrl+shift+v").wait().text("3").wait().key("enter").wait(3);
  const CovarianceMesh saved =
      play(corner, "--save " + dir_.file("saved.ply") + " --screenshot " + artefact("cube_corner_3.png"));
  EXPECT_TRUE(saved.sharpness.creases.empty());
  for (size_t v = 0; v < saved.n_vertices(); ++v)
    EXPECT_EQ(saved.sharpness.corner(int(v)), v == size_t(nearest) ? 3.0 : 0.0) << v;
}

}  // namespace
}  // namespace gps
