// Edges as elements in a real window under Xvfb, on the quad cube: in edge mode (2) a click and a
// Shift+click select two opposite edges of the top face, and Shift+E creases those two only, not the
// face's other two sides that join their ends (the trap of a vertex selection); back in vertex mode
// (1) the same four vertices crease all four sides, as before. Select sharp edges (Ctrl+Shift+E,
// 30°) takes the cube's 12 edges, which Shift+E then creases. Alt+click selects a loop's edges: two
// neighbouring rows of a grid crease without the rungs between them; Ctrl+Alt+click an edge ring,
// Ctrl+click a shortest path, Shift+G similar faces and C a circle dragged along a row select what
// Blender's do. Screenshots kept in build/test-artefacts/EditorEdges/.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "../support/editor_driver.h"
#include "core/io/mesh_io.h"
#include "core/mesh/sharpness.h"
#include "core/modelling/bevel.h"
#include "core/modelling/mesh_queries.h"
#include "core/modelling/samples.h"
#include "tests/support/mesh_checks.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

using test::artefact;
using test::editor_view;
using test::Events;
using test::pixel_of;

constexpr int kWidth = test::kWindowWidth, kHeight = test::kWindowHeight;
constexpr double kInf = kInfiniteSharpness;

class EditorEdges : public ::testing::Test {
protected:
  void SetUp() override {
    write_mesh(dir_.file("original.ply"), make_sample("cube"));
    original_ = read_mesh(dir_.file("original.ply"));
    view_ = editor_view(original_);
  }
  // The pixel a fraction t of the way from vertex a to vertex b.
  glm::vec2 along(int a, int b, double t) const {
    return pixel_of(view_, (1.0 - t) * original_.mean(size_t(a)) + t * original_.mean(size_t(b)));
  }
  // Edge mode; a click on the top face's front edge 6–7 near 7 (7 active: the gizmo there), then a
  // Shift+click on its back edge 2–3 near 2, the end away from 7 on screen (clear of the gizmo).
  Events two_top_edges_selected() const {
    Events e;
    e.key("2").wait().click(along(7, 6, 0.3)).wait().click(along(2, 3, 0.3), "shift").wait();
    return e;
  }
  CovarianceMesh play(const Events& events, const std::string& screenshot) const {
    const auto r = test::play_editor(dir_, dir_.file("original.ply"), events, kWidth, kHeight,
                                     "--save " + dir_.file("saved.ply") + " --screenshot " + artefact(screenshot));
    EXPECT_EQ(r.exit_code, 0) << r.output;
    output_ = r.output;
    return read_mesh(dir_.file("saved.ply"));
  }

  mutable std::string output_;
  test::TempDir dir_;
  CovarianceMesh original_;
  Viewport view_;
};

TEST_F(EditorEdges, ShiftECreasesTheSelectedEdgesNotTheEdgesBetweenTheirEnds) {
  Events shown = two_top_edges_selected();
  play(shown.wait(3), "two_edges_selected.png");

  Events crease = two_top_edges_selected();
  crease.key("shift+e").wait().text("10").wait().key("enter").wait(3);
  const CovarianceMesh creased = play(crease, "two_edges_creased.png");
  EXPECT_EQ(creased.sharpness.creases, (std::vector<EdgeCrease>{{2, 3, kInf}, {6, 7, kInf}}));
  EXPECT_TRUE(creased.sharpness.corners.empty());
  for (size_t v = 0; v < original_.n_vertices(); ++v) EXPECT_EQ(creased.mean(v), original_.mean(v));

  // In vertex mode the edges' ends select every edge between them: the whole rim of the top face.
  Events as_vertices = two_top_edges_selected();
  as_vertices.key("1").wait().key("shift+e").wait().text("10").wait().key("enter").wait(3);
  EXPECT_EQ(play(as_vertices, "as_vertices_creased.png").sharpness.creases,
            (std::vector<EdgeCrease>{{2, 3, kInf}, {2, 6, kInf}, {3, 7, kInf}, {6, 7, kInf}}));
}

// Two edges bevelled (Ctrl+B), then undone (Ctrl+Z): the selection comes back as those two edges, not
// the top face's four sides between their ends, so a second Ctrl+B bevels the same two edges.
TEST_F(EditorEdges, UndoOfABevelGivesBackItsEdgesForTheNext) {
  Events again = two_top_edges_selected();
  again.key("ctrl+b").wait().text("0.25").wait().key("enter").wait();
  again.key("ctrl+z").wait();
  again.key("ctrl+b").wait().text("0.25").wait().key("enter").wait(3);
  const CovarianceMesh saved = play(again, "bevel_undone_and_again.png");
  BevelOptions o;
  o.width = 0.25;
  EXPECT_TRUE(test::same_mesh(saved, bevel_edges(original_, {{2, 3}, {6, 7}}, o).mesh));
  EXPECT_EQ(saved.n_vertices(), 12u);
}

TEST_F(EditorEdges, SelectSharpEdgesTakesTheCubesTwelveEdges) {
  Events sharp;
  sharp.key("ctrl+shift+e").wait(3);
  Events shown = sharp;
  play(shown, "sharp_edges_selected.png");
  sharp.key("shift+e").wait().text("10").wait().key("enter").wait(3);
  const CovarianceMesh creased = play(sharp, "sharp_edges_creased.png");
  ASSERT_EQ(creased.sharpness.creases.size(), 12u);
  for (const EdgeCrease& c : creased.sharpness.creases) {
    EXPECT_EQ(c.sharpness, kInf) << c.a << "-" << c.b;
    EXPECT_GE(original_.find_edge(c.a, c.b), 0) << c.a << "-" << c.b;
  }
}

// With vertex 5 hidden (H), Ctrl+Shift+E selects the 9 sharp edges that are shown and says so; it
// said 12. Ctrl+B and Ctrl+Shift+B with nothing selected say why nothing happens (they were silent).
TEST_F(EditorEdges, SelectSharpEdgesCountsWhatItSelectedAndKeysWithoutASelectionSayWhy) {
  Events hidden;
  hidden.click(pixel_of(view_, original_.mean(5))).wait().key("h").wait().key("ctrl+shift+e").wait(3);
  play(hidden, "sharp_edges_with_a_vertex_hidden.png");
  EXPECT_NE(output_.find("select sharp edges: 9 edges folded by more than 30° (3 more hidden)"), std::string::npos)
      << output_;
  Events none;
  none.key("ctrl+b").wait().key("ctrl+shift+b").wait(3);
  play(none, "bevel_without_a_selection.png");
  EXPECT_TRUE(test::same_mesh(read_mesh(dir_.file("saved.ply")), original_));
  EXPECT_NE(output_.find("Bevel edges: nothing is selected for it to work on"), std::string::npos) << output_;
  EXPECT_NE(output_.find("Bevel vertices: nothing is selected for it to work on"), std::string::npos) << output_;
}

// Alt+click in edge mode selects an edge loop's edges: two neighbouring rows of a 4 × 4 grid (vertex
// j·5 + i), Shift+Alt+click adding the second, crease as their 8 edges, not the 5 rungs between them
// (the trap of an inset's rim creased with its diagonals).
TEST_F(EditorEdges, AltClickSelectsTheLoopsEdgesWhichShiftECreases) {
  write_mesh(dir_.file("original.ply"), test::grid_mesh(4, 4));
  original_ = read_mesh(dir_.file("original.ply"));
  view_ = editor_view(original_);
  Events loops;  // row 1 through its edge 6–7, then row 2 through 13–14, away from the gizmo on 6 or 7
  loops.key("2").wait().click(along(6, 7, 0.5), "alt").wait().click(along(13, 14, 0.5), "shift+alt").wait();
  Events shown = loops;
  play(shown.wait(3), "grid_rows_selected.png");
  loops.key("shift+e").wait().text("10").wait().key("enter").wait(3);
  std::vector<EdgeCrease> rows;
  for (const int j : {1, 2})
    for (int i = 0; i < 4; ++i) rows.push_back({5 * j + i, 5 * j + i + 1, kInf});
  std::sort(rows.begin(), rows.end(), [](const EdgeCrease& x, const EdgeCrease& y) { return x.a < y.a; });
  EXPECT_EQ(play(loops, "grid_rows_creased.png").sharpness.creases, rows);
}

// Ctrl+Alt+click in edge mode selects an edge ring: through the row edge 6–7 of a 4 × 4 grid, the
// column of rungs a loop cut there would cross (x from 1 to 2 in every row of quads: 5 edges), which
// Shift+E creases alone, not the rails beside them.
TEST_F(EditorEdges, CtrlAltClickSelectsTheRingWhichShiftECreases) {
  write_mesh(dir_.file("original.ply"), test::grid_mesh(4, 4));
  original_ = read_mesh(dir_.file("original.ply"));
  view_ = editor_view(original_);
  Events ring;
  ring.key("2").wait().click(along(6, 7, 0.5), "ctrl+alt").wait();
  ring.key("shift+e").wait().text("10").wait().key("enter").wait(3);
  std::vector<EdgeCrease> rungs;
  for (int j = 0; j <= 4; ++j) rungs.push_back({5 * j + 1, 5 * j + 2, kInf});
  EXPECT_EQ(play(ring, "grid_ring_creased.png").sharpness.creases, rungs);
}

// Ctrl+click selects the shortest path from the active vertex: corner 0 of a 4 × 4 grid clicked, then
// vertex 12 (the middle) with Ctrl: Shift+E creases the path's four edges, a chain from 0 to 12.
TEST_F(EditorEdges, CtrlClickSelectsTheShortestPath) {
  write_mesh(dir_.file("original.ply"), test::grid_mesh(4, 4));
  original_ = read_mesh(dir_.file("original.ply"));
  view_ = editor_view(original_);
  Events path;
  path.click(along(0, 0, 0.0)).wait().click(along(12, 12, 0.0), "ctrl").wait();
  path.key("shift+e").wait().text("10").wait().key("enter").wait(3);
  const std::vector<EdgeCrease> creases = play(path, "grid_path_creased.png").sharpness.creases;
  ASSERT_EQ(creases.size(), 4u);
  std::map<int, int> ends;  // how many creased edges meet at each vertex
  for (const EdgeCrease& c : creases) ++ends[c.a], ++ends[c.b];
  EXPECT_EQ(ends[0], 1);
  EXPECT_EQ(ends[12], 1);
  for (const auto& [v, n] : ends) {
    if (v != 0 && v != 12) {
      EXPECT_EQ(n, 2) << v;
    }
  }
}

// Shift+G in face mode after a click on one of the cube's faces: Select similar → Sides (the menu's
// second item, where the popup opens at the pointer) adds every quad, so S 0.5 then scales all eight
// vertices about their centre.
TEST_F(EditorEdges, ShiftGSelectsSimilarFaces) {
  const glm::vec2 face =
      pixel_of(view_, 0.25 * (original_.mean(4) + original_.mean(5) + original_.mean(6) + original_.mean(7)));
  const glm::vec2 menu = face + glm::vec2(40.0f, 40.0f);
  Events similar;
  similar.key("3").wait().click(face).wait().move(menu).wait().key("shift+g").wait(2);
  similar.click(menu + glm::vec2(28.0f, 31.5f)).wait(2);
  similar.move(menu + glm::vec2(60.0f, 0.0f)).wait().key("s").wait().text("0.5").wait().key("enter").wait(3);
  const CovarianceMesh saved = play(similar, "cube_similar_faces_scaled.png");
  Vec3 centre = Vec3::Zero();
  for (size_t v = 0; v < original_.n_vertices(); ++v) centre += original_.mean(v) / 8.0;
  for (size_t v = 0; v < original_.n_vertices(); ++v)
    EXPECT_LT((saved.mean(v) - (centre + 0.5 * (original_.mean(v) - centre))).norm(), 1e-12) << v;
}

// C, then a stroke through the grid's middle row (pressed on vertex 10, moved over 11, 12 and 13,
// let go on 14): the circle (25 pixels) takes the vertices it passes over, so Shift+E after Enter
// creases the row's four edges, and no edge with an end the circle never came near.
TEST_F(EditorEdges, CircleSelectTakesWhatTheDragPassesOver) {
  write_mesh(dir_.file("original.ply"), test::grid_mesh(4, 4));
  original_ = read_mesh(dir_.file("original.ply"));
  view_ = editor_view(original_);
  std::vector<glm::vec2> stroke;
  for (const int v : {10, 11, 12, 13, 14}) stroke.push_back(along(v, v, 0.0));
  Events circle;
  circle.move(stroke.front()).wait().key("c").wait().press(stroke.front()).wait();
  for (size_t k = 1; k < stroke.size(); ++k) circle.move(stroke[k]).wait();
  circle.release(stroke.back()).wait().key("enter").wait();
  circle.key("shift+e").wait().text("10").wait().key("enter").wait(3);
  const std::vector<EdgeCrease> creases = play(circle, "grid_circle_selected.png").sharpness.creases;
  for (int i = 10; i < 14; ++i)
    EXPECT_NE(std::find_if(creases.begin(), creases.end(),
                           [i](const EdgeCrease& c) { return c.a == i && c.b == i + 1 && c.sharpness == kInf; }),
              creases.end())
        << i;
  const auto near_stroke = [&](int v) {
    float nearest = 1e9f;
    for (const glm::vec2 p : stroke) nearest = std::min(nearest, glm::length(along(v, v, 0.0) - p));
    return nearest;
  };
  for (const EdgeCrease& c : creases) {
    EXPECT_LE(near_stroke(c.a), 26.0f) << c.a;
    EXPECT_LE(near_stroke(c.b), 26.0f) << c.b;
  }
}
}  // namespace
}  // namespace gps
