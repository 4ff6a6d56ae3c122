// Snapping while transforming (Shift+Tab, Ctrl held) and the 3D cursor (Shift+right click) in a real
// window under Xvfb, on the cube: each saved result against the exact positions it must reach.
// Screenshots kept in build/test-artefacts/EditorSnapping/.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "tests/support/editor_tools_fixture.h"

namespace gps {
namespace {

using test::artefact;
using test::editor_view;
using test::EditorTools;
using test::Events;
using test::kHeight;
using test::kWidth;
using test::pixel_of;

// Snapping while transforming and the 3D cursor, on the cube.
class EditorToolsSnap : public EditorTools {
protected:
  static void hold_ctrl(Events& e, bool down) {
    e.add(std::string(R"({"type": ")") + (down ? "key_press" : "key_release") + R"(", "key": "ctrl"})");
  }
  // Vertex 6 selected and grabbed (then `keys`: a constraint), the pointer moved in steps to `to`;
  // `ctrl`: held from the grab to after the Enter that confirms it.
  Events grab_vertex_6(glm::vec2 to, const std::string& keys = "", bool ctrl = false, Events e = Events()) const {
    const glm::vec2 from = pixel_at({6}) + glm::vec2(0.0f, 2.0f);
    e.click(from).wait().move(from).wait().key("g").wait();
    if (!keys.empty()) e.key(keys).wait();
    if (ctrl) hold_ctrl(e, true);
    for (int k = 1; k <= 4; ++k) e.move(from + (to - from) * (float(k) / 4.0f)).wait();
    e.key("enter").wait(3);
    if (ctrl) hold_ctrl(e, false);
    return e;
  }
};

// Ctrl held during G: the move is whole steps of 0.1 along each axis (the default increment), and not
// none; let go, the same pointer moves freely again.
TEST_F(EditorToolsSnap, SnapIncrementRoundsTheGrabWhileCtrlIsHeld) {
  const glm::vec2 to = pixel_at({6}) + glm::vec2(47.0f, -31.0f);
  const CovarianceMesh saved = play(grab_vertex_6(to, "", true), "cube_grab_snapped_to_increments.png");
  const Vec3 moved = saved.mean(6) - original_.mean(6);
  EXPECT_GT(moved.norm(), 0.05);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(moved[i] / 0.1, std::round(moved[i] / 0.1), 1e-9) << i << ": " << moved[i];
  for (size_t v = 0; v < saved.n_vertices(); ++v) {
    if (v != 6) {
      EXPECT_EQ(saved.mean(v), original_.mean(v)) << v;
    }
  }

  const Vec3 unsnapped = play(grab_vertex_6(to)).mean(6) - original_.mean(6);
  bool off_the_grid = false;
  for (int i = 0; i < 3; ++i) off_the_grid |= std::abs(unsnapped[i] / 0.1 - std::round(unsnapped[i] / 0.1)) > 1e-6;
  EXPECT_TRUE(off_the_grid) << unsnapped.transpose();
}

// Snapping on (Shift+Tab) to vertices (Ctrl+Shift+Tab once) with G X: vertex 6 takes the x of the
// vertex under the pointer and keeps its y and z.
TEST_F(EditorToolsSnap, SnapToAVertexAlongTheConstraint) {
  int target = -1;
  for (size_t v = 0; v < original_.n_vertices(); ++v)
    if (original_.mean(v).x() != original_.mean(6).x() && original_.mean(v).y() == original_.mean(6).y() &&
        original_.mean(v).z() != original_.mean(6).z())
      target = int(v);
  ASSERT_GE(target, 0);
  Events snapping;
  snapping.key("shift+tab").wait().key("ctrl+shift+tab").wait();
  const glm::vec2 to = pixel_at({target}) + glm::vec2(3.0f, 2.0f);
  const CovarianceMesh saved = play(grab_vertex_6(to, "x", false, snapping), "cube_grab_snapped_to_vertex.png");
  EXPECT_NEAR(saved.mean(6).x(), original_.mean(size_t(target)).x(), 1e-12);
  EXPECT_EQ(saved.mean(6).y(), original_.mean(6).y());
  EXPECT_EQ(saved.mean(6).z(), original_.mean(6).z());
  EXPECT_NE(output_.find("snapped to vertex " + std::to_string(target)), std::string::npos) << output_;
}

// Snapping to edges: vertex 6 lands on the edge under the pointer (one that does not touch it), on
// the segment between its ends.
TEST_F(EditorToolsSnap, SnapToAnEdgeLandsOnIt) {
  // The top face's far edge: the edge of the top face (the y of vertex 6) that does not touch 6 or 7.
  std::array<int, 2> edge{-1, -1};
  for (size_t e = 0; e < original_.n_edges(); ++e) {
    const auto [a, b] = original_.edge(e);
    if (a == 6 || b == 6 || a == 7 || b == 7) continue;
    if (original_.mean(size_t(a)).y() == original_.mean(6).y() &&
        original_.mean(size_t(b)).y() == original_.mean(6).y())
      edge = {a, b};
  }
  ASSERT_GE(edge[0], 0);
  Events snapping;
  snapping.key("shift+tab").wait().key("ctrl+shift+tab").wait().key("ctrl+shift+tab").wait();
  const glm::vec2 to = pixel_at({edge[0], edge[1]}) + glm::vec2(0.0f, 4.0f);
  const CovarianceMesh saved = play(grab_vertex_6(to, "", false, snapping), "cube_grab_snapped_to_edge.png");
  const Vec3 a = original_.mean(size_t(edge[0])), b = original_.mean(size_t(edge[1])), p = saved.mean(6);
  const double s = (p - a).dot(b - a) / (b - a).squaredNorm();
  EXPECT_GT(s, 0.2);
  EXPECT_LT(s, 0.8);
  EXPECT_LT((a + s * (b - a) - p).norm(), 1e-9) << p.transpose();
}

// Shift+S puts the 3D cursor at vertex 0 (the corner the cube hides, picked with X-ray, Alt+Z); with
// the pivot at the 3D cursor ("." three times from the median point), S 2 scales vertex 6 about it:
// exactly 2 v6 − v0.
TEST_F(EditorToolsSnap, ScaleAboutThe3DCursor) {
  Events events;
  events.key("alt+z").wait().click(pixel_at({0})).wait().key("alt+z").wait().key("shift+s").wait();
  events.key("period").wait().key("period").wait().key("period").wait();
  const glm::vec2 at6 = pixel_at({6}) + glm::vec2(0.0f, 2.0f);
  events.click(at6).wait().move(at6).wait().key("s").wait().text("2").wait().key("enter").wait(3);
  const CovarianceMesh saved = play(events, "cube_scaled_about_the_cursor.png");
  const Vec3 expected = 2.0 * original_.mean(6) - original_.mean(0);
  EXPECT_LT((saved.mean(6) - expected).norm(), 1e-12) << saved.mean(6).transpose();
  EXPECT_NE(output_.find("pivot: 3D cursor"), std::string::npos) << output_;
}

// Shift+right click on the surface places the 3D cursor there (read back from the frame): the point
// printed projects back onto the clicked pixel.
TEST_F(EditorToolsSnap, ShiftRightClickPlacesThe3DCursorOnTheSurface) {
  const glm::vec2 at = pixel_at({4, 5, 6, 7}) + glm::vec2(5.0f, 0.0f);
  Events events;
  events.add(R"({"type": "click", "button": "right", "mods": "shift", "x": )" + std::to_string(at.x) + R"(, "y": )" +
             std::to_string(at.y) + "}");
  events.wait(3);
  play(events, "cube_cursor_placed.png");
  const size_t found = output_.find("3D cursor on the surface at (");
  ASSERT_NE(found, std::string::npos) << output_;
  Vec3 point;
  ASSERT_EQ(std::sscanf(output_.c_str() + found + 29, "%lf, %lf, %lf", &point.x(), &point.y(), &point.z()), 3);
  const auto pixel = project_to_pixel(view_.camera, kWidth, kHeight, point);
  ASSERT_TRUE(pixel);
  EXPECT_LT(glm::length(glm::vec2(*pixel) - at), 1.5f) << pixel->x << ", " << pixel->y;
}

}  // namespace
}  // namespace gps
