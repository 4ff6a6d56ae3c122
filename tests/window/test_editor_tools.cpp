// The modal tools of ui/tools/ and the modelling keys in a real window under Xvfb as a designer uses
// them: bevel (Ctrl+B on one edge of the cube, Ctrl+Shift+B on a corner; typed width or the mouse,
// the wheel for segments), G G slide, spin, duplicate, the sharpen brush, bisect, knife, split, grid
// fill, the normal orientation, and F9 on the last operation; Esc and a right click change nothing,
// Ctrl+Z restores the file byte for byte. Each saved result is checked against core's operation on
// the file as opened. Designer replays: test_editor_designer_replays.cpp; snapping and the mirror
// modifier: test_editor_snapping.cpp, test_editor_mirror.cpp. Screenshots kept in build/test-artefacts/EditorTools/.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/io/mesh_io.h"
#include "core/io/text_file.h"
#include "core/modelling/bevel.h"
#include "core/modelling/bisect.h"
#include "core/modelling/delete_elements.h"
#include "core/modelling/duplicate.h"
#include "core/modelling/extrude.h"
#include "core/modelling/grid_fill.h"
#include "core/modelling/inset.h"
#include "core/modelling/knife.h"
#include "core/modelling/loop_cut.h"
#include "core/modelling/mesh_queries.h"
#include "core/modelling/mirror.h"
#include "core/modelling/samples.h"
#include "core/modelling/slide.h"
#include "core/modelling/spin.h"
#include "core/modelling/split_faces.h"
#include "render/image/image_io.h"
#include "ui/editing/axis_handles.h"
#include "ui/editing/covariance_presets.h"
#include "ui/panels/view_options.h"
#include "tests/support/editor_tools_fixture.h"
#include "ui/tools/loop_cut_tool.h"

namespace gps {
namespace {

using test::artefact;
using test::editor_view;
using test::Events;
using test::pixel_of;

using test::EditorTools;

// One cube edge, 1 segment, a typed width: Blender's 10 vertices and 7 faces, closed and outward,
// exactly core's bevel of that edge.
TEST_F(EditorTools, BevelOfACubeEdgeMakesTheBand) {
  Events bevel = edge_selected();
  bevel.key("ctrl+b").wait().text("0.25").wait().key("enter").wait(3);
  const CovarianceMesh saved = play(bevel, "cube_edge_bevelled.png");
  const test::Shape shape = test::shape_of(saved);
  EXPECT_EQ(shape.vertices, 10);
  EXPECT_EQ(shape.faces, 7);
  EXPECT_EQ(shape.boundary_edges, 0);
  EXPECT_TRUE(shape.oriented);
  EXPECT_EQ(shape.euler(), 2);
  EXPECT_GT(test::signed_volume(saved), 0.0);
  EXPECT_TRUE(test::same_mesh(saved, bevel_edges(original_, {{6, 7}}, width(0.25)).mesh));
  EXPECT_NE(output_.find("bevel: "), std::string::npos) << output_;
}

// Every edge of the cube bevelled past where the new vertices meet, as a designer drags too far: the
// width is clamped and the vertices that meet merged, leaving the octahedron of the faces' centres
// with no vertices at one point (core's clamped bevel, exactly).
TEST_F(EditorTools, BevelPastWhereVerticesMeetIsClampedToAClosedSolid) {
  Events bevel;
  bevel.key("2").wait().key("a").wait().key("ctrl+b").wait().text("1.5").wait().key("enter").wait(3);
  const CovarianceMesh saved = play(bevel, "cube_bevel_clamped.png");
  test::expect_closed_outward(saved, 6, 8);
  std::vector<std::array<int, 2>> every_edge;
  for (size_t e = 0; e < original_.n_edges(); ++e) every_edge.push_back({original_.edge(e)[0], original_.edge(e)[1]});
  EXPECT_TRUE(test::same_mesh(saved, bevel_edges(original_, every_edge, width(1.5)).mesh));
  EXPECT_NE(output_.find("that met merged"), std::string::npos) << output_;
}

// The mouse moved away from the edge's middle sets a width: the band is made (a bevel of some width
// > 0, the counts of one segment), and the summary printed.
TEST_F(EditorTools, BevelWidthFollowsTheMouse) {
  const glm::vec2 middle = pixel_at({6, 7}), start = middle + glm::vec2(20.0f, 20.0f);
  Events bevel = edge_selected();
  bevel.move(start).wait().key("ctrl+b").wait();
  for (int k = 1; k <= 4; ++k) bevel.move(start + float(k) * glm::vec2(8.0f, 8.0f)).wait();
  bevel.key("enter").wait(3);
  const CovarianceMesh saved = play(bevel, "cube_edge_mouse_bevel.png");
  EXPECT_EQ(saved.n_vertices(), 10u);
  EXPECT_EQ(saved.n_faces(), 7u);
  // The cube's corners 6 and 7 are gone (the bevel replaced them by the band's ends).
  for (size_t v = 0; v < saved.n_vertices(); ++v) {
    EXPECT_GT((saved.mean(v) - original_.mean(6)).norm(), 1e-3) << v;
    EXPECT_GT((saved.mean(v) - original_.mean(7)).norm(), 1e-3) << v;
  }
}

// While the tool runs the bevel is only shown: the document saved then is the file as opened (the
// screenshot shows the preview, the new vertices selected, two segments).
TEST_F(EditorTools, BevelPreviewLeavesTheDocumentUntilConfirmed) {
  Events previewed = edge_selected();
  previewed.key("ctrl+b").wait().scroll(pixel_at({6, 7}), 1.0f).wait().text("0.3").wait(3);
  play(previewed, "cube_edge_bevel_preview.png");
  EXPECT_TRUE(saved_is_original());
}

// The wheel adds segments, a notch each, each a row of quads across the band: two events of one step
// give 3, as does one event of two steps (a fast wheel) or four of half a step (a smooth one).
TEST_F(EditorTools, BevelWheelSegmentsChangeTheCount) {
  const CovarianceMesh expected = bevel_edges(original_, {{6, 7}}, width(0.25, 3)).mesh;
  for (const std::vector<float>& steps :
       {std::vector<float>{1.0f, 1.0f}, std::vector<float>{2.0f}, std::vector<float>{0.5f, 0.5f, 0.5f, 0.5f}}) {
    Events bevel = edge_selected();
    bevel.key("ctrl+b").wait();
    for (const float step : steps) bevel.scroll(pixel_at({6, 7}), step).wait();
    bevel.text("0.25").wait().key("enter").wait(3);
    const CovarianceMesh saved = play(bevel, "cube_edge_3_segments.png");
    EXPECT_GT(saved.n_vertices(), 10u);
    EXPECT_EQ(saved.n_vertices(), expected.n_vertices()) << steps.size();
    EXPECT_EQ(saved.n_faces(), expected.n_faces()) << steps.size();
    EXPECT_TRUE(test::same_mesh(saved, expected)) << steps.size();
  }
}

// Ctrl+Shift+B on the corner nearest the camera: the corner cut off (10 vertices, 7 faces).
TEST_F(EditorTools, BevelOfACubeVertexCutsTheCorner) {
  int corner = 0;  // the camera looks from +x, +y, +z
  for (size_t v = 0; v < original_.n_vertices(); ++v)
    if (original_.mean(v).sum() > original_.mean(size_t(corner)).sum()) corner = int(v);
  Events bevel;
  bevel.key("1").wait().click(pixel_at({corner})).wait();
  bevel.key("ctrl+shift+b").wait().text("0.5").wait().key("enter").wait(3);
  const CovarianceMesh saved = play(bevel, "cube_corner_bevelled.png");
  EXPECT_EQ(saved.n_vertices(), 10u);
  EXPECT_EQ(saved.n_faces(), 7u);
  EXPECT_TRUE(test::same_mesh(saved, bevel_vertices(original_, {corner}, width(0.5)).mesh));
}

// Esc after a typed width, and a right click after a mouse width: the file as it was, byte for byte.
TEST_F(EditorTools, BevelCancelledLeavesTheFileByteIdentical) {
  Events cancelled = edge_selected();
  cancelled.key("ctrl+b").wait().text("0.25").wait().key("escape").wait();
  const glm::vec2 start = pixel_at({6, 7}) + glm::vec2(20.0f, 20.0f);
  cancelled.move(start).wait().key("ctrl+b").wait().move(start + glm::vec2(40.0f, 40.0f)).wait();
  cancelled.add(R"({"type": "click", "button": "right", "x": )" + std::to_string(start.x + 40.0f) + R"(, "y": )" +
                std::to_string(start.y + 40.0f) + "}");
  cancelled.wait(3);
  play(cancelled, "cube_bevel_cancelled.png");
  EXPECT_TRUE(saved_is_original());
}

// Events that end inside a tool (a scale typed, never confirmed, which moves the vertices as it goes):
// --save writes what was confirmed, the original file.
TEST_F(EditorTools, AToolLeftOpenAtTheEndIsNotSaved) {
  Events open = edge_selected();
  open.key("s").wait().text("2").wait(2);
  play(open, "");
  EXPECT_TRUE(saved_is_original());
}

// A bevel confirmed, saved in place, then undone (Ctrl+Z) and saved again: the original file.
TEST_F(EditorTools, BevelUndoneRestoresTheFile) {
  std::filesystem::copy_file(dir_.file("original.ply"), dir_.file("work.ply"));
  Events undone = edge_selected();
  undone.key("ctrl+b").wait().text("0.25").wait().key("enter").wait();
  undone.key("ctrl+s").wait().key("ctrl+z").wait(3);
  play(undone, "", "work.ply");
  EXPECT_EQ(read_mesh(dir_.file("work.ply")).n_vertices(), 10u);  // the bevel, saved in place
  EXPECT_TRUE(saved_is_original());
}

// Bevel with no edge selected (one vertex): refused in the status line, nothing changed.
TEST_F(EditorTools, BevelOfNoEdgeIsRefused) {
  Events refused;
  refused.key("1").wait().click(pixel_at({6})).wait().key("ctrl+b").wait().key("enter").wait(3);
  play(refused);
  EXPECT_TRUE(saved_is_original());
  EXPECT_NE(output_.find("bevel refused"), std::string::npos) << output_;
}

class EditorToolsSlide : public EditorTools {
protected:
  // A cube with one loop cut across its vertical edges: the middle loop, its vertices and edges.
  void SetUp() override {
    const CovarianceMesh cube = make_sample("cube");
    std::array<int, 2> vertical{-1, -1};
    for (size_t e = 0; e < cube.n_edges(); ++e) {
      const auto [a, b] = cube.edge(e);
      if (cube.mean(size_t(a)).y() != cube.mean(size_t(b)).y()) vertical = {a, b};
    }
    use_mesh(loop_cut(cube, vertical[0], vertical[1], 1).mesh);
    for (size_t v = 0; v < original_.n_vertices(); ++v)
      if (original_.mean(v).y() == 0.0) loop_.push_back(int(v));
    ASSERT_EQ(loop_.size(), 4u);
    loop_edges_ = edges_within(original_, loop_);
    ASSERT_EQ(loop_edges_.size(), 4u);
  }
  // Alt+click on the loop's front edge (the one whose middle is nearest the camera) selects the loop.
  Events loop_selected() const {
    std::array<int, 2> front = loop_edges_.front();
    const Vec3 eye = to_vec(view_.camera.eye());
    const auto distance = [&](const std::array<int, 2>& e) {
      return (0.5 * (original_.mean(size_t(e[0])) + original_.mean(size_t(e[1]))) - eye).norm();
    };
    for (const auto& e : loop_edges_)
      if (distance(e) < distance(front)) front = e;
    Events events;
    events.click(pixel_at({front[0], front[1]}), "alt").wait();
    return events;
  }
  std::vector<int> loop_;
  std::vector<std::array<int, 2>> loop_edges_;
};

// G G and a typed 0.5: the loop halfway toward the side the first edge's faces lie on, exactly core's
// edge slide; the counts kept.
TEST_F(EditorToolsSlide, SlideGGSlidesAnEdgeLoop) {
  Events slide = loop_selected();
  slide.key("g").wait().key("g").wait().text("0.5").wait().key("enter").wait(3);
  const CovarianceMesh saved = play(slide, "cube_loop_slid.png");
  EXPECT_EQ(saved.n_vertices(), original_.n_vertices());
  EXPECT_EQ(saved.n_faces(), original_.n_faces());
  const CovarianceMesh expected = edge_slide(original_, loop_edges_, 0.5).mesh;
  EXPECT_TRUE(test::same_mesh(saved, expected));
  for (const int v : loop_) EXPECT_NEAR(std::abs(saved.mean(size_t(v)).y()), 0.5, 1e-6) << v;
}

// G G and the mouse moved up the screen: the loop slides up (toward the top face), all four
// vertices the same height, the counts and the faces kept; Esc the second time leaves the file.
TEST_F(EditorToolsSlide, SlideFollowsTheMouseAndEscRestores) {
  const glm::vec2 start = pixel_at(loop_);
  Events slide = loop_selected();
  slide.move(start).wait().key("g").wait().key("g").wait();
  for (int k = 1; k <= 4; ++k) slide.move(start - float(k) * glm::vec2(0.0f, 10.0f)).wait();
  slide.key("enter").wait(3);
  const CovarianceMesh saved = play(slide, "cube_loop_slid_up.png");
  EXPECT_EQ(arrays_of(saved).faces, arrays_of(original_).faces);
  const double height = saved.mean(size_t(loop_.front())).y();
  EXPECT_GT(height, 0.05);
  EXPECT_LT(height, 1.0);
  for (const int v : loop_) EXPECT_NEAR(saved.mean(size_t(v)).y(), height, 1e-6) << v;

  Events cancelled = loop_selected();
  cancelled.move(start).wait().key("g").wait().key("g").wait().move(start - glm::vec2(0.0f, 30.0f)).wait();
  cancelled.key("escape").wait(3);
  play(cancelled);
  EXPECT_TRUE(saved_is_original());
}

// Spin (Alt+R) of a grid's far boundary edge around the 3D cursor at the origin (Shift+C), about x,
// typed 90°: exactly core's spin of that edge in Blender's 9 steps; the wheel adds a step; Esc leaves
// the file.
TEST_F(EditorTools, SpinTurnsAnEdgeAroundThe3DCursor) {
  use_mesh(test::grid_mesh(2, 2));
  const Events select = Events().click(pixel_at({6})).wait().click(pixel_at({7}), "shift").wait().key("shift+c").wait();
  Events spun = select;
  spun.key("alt+r").wait().key("x").wait().text("90").wait().key("enter").wait(3);
  const CovarianceMesh saved = play(spun, "grid_edge_spun.png");
  const Modelled expected = spin(original_, {6, 7}, Vec3::UnitX(), Vec3::Zero(), 90.0, 9);
  EXPECT_TRUE(test::same_mesh(saved, expected.mesh));
  EXPECT_EQ(saved.n_faces(), original_.n_faces() + 9);
  EXPECT_NE(output_.find("spin: "), std::string::npos) << output_;

  Events more = select;
  more.key("alt+r").wait().key("x").wait().text("90").wait().scroll(pixel_at({4}), 1.0f).wait().key("enter").wait(3);
  EXPECT_EQ(play(more).n_faces(), original_.n_faces() + 10);

  Events cancelled = select;
  cancelled.key("alt+r").wait().text("90").wait().key("escape").wait(3);
  play(cancelled);
  EXPECT_TRUE(saved_is_original());
}

// Shift+D with everything selected (A) duplicates the cube and moves the copy, here Z 3: Blender's
// 16 vertices and 12 faces, exactly core's duplicate with that offset, one undo step (Ctrl+Z: the
// file again); Esc during the move keeps the copy in place.
TEST_F(EditorTools, DuplicateCopiesTheSelectionAndMovesIt) {
  Events duplicated;
  duplicated.key("a").wait().key("shift+d").wait().key("z").wait().text("3").wait().key("enter").wait(3);
  const CovarianceMesh saved = play(duplicated, "cube_duplicated.png");
  const Modelled expected = duplicate_faces(original_, {0, 1, 2, 3, 4, 5}, Vec3(0.0, 0.0, 3.0));
  EXPECT_EQ(saved.n_vertices(), 16u);
  EXPECT_EQ(saved.n_faces(), 12u);
  EXPECT_TRUE(test::same_mesh(saved, expected.mesh));

  Events undone = duplicated;
  undone.key("ctrl+z").wait(3);
  play(undone);
  EXPECT_TRUE(saved_is_original());

  Events in_place;
  in_place.key("a").wait().key("shift+d").wait().key("escape").wait(3);
  EXPECT_TRUE(test::same_mesh(play(in_place), duplicate_faces(original_, {0, 1, 2, 3, 4, 5}, Vec3::Zero()).mesh));
}

// The sharpen brush (Shift+P): a short stroke over the middle of a 4 × 4 grid flattens the middle
// vertex's Gaussian along its normal (the radius is at first the mean edge length) and leaves the
// vertices farther than 1.5 edges and every mean as they were; Enter keeps it, Esc takes it back.
TEST_F(EditorTools, BrushSharpensTheGaussiansUnderTheStroke) {
  use_mesh(test::grid_mesh(4, 4));
  const int middle = 12;
  const glm::vec2 at = pixel_at({middle});
  Events stroke;
  stroke.move(at).wait().key("shift+p").wait().drag(at, at + glm::vec2(6.0f, 0.0f), 4).wait();
  Events kept = stroke;
  kept.key("enter").wait(3);
  const CovarianceMesh saved = play(kept, "grid_brushed.png");
  for (size_t v = 0; v < saved.n_vertices(); ++v) EXPECT_EQ(saved.mean(v), original_.mean(v)) << v;
  const Vec3 n = vertex_normal(original_, middle);
  EXPECT_LT(n.dot(saved.covariance(middle) * n), 0.8 * n.dot(original_.covariance(middle) * n)) << output_;
  int far = 0;
  for (size_t v = 0; v < saved.n_vertices(); ++v)
    if ((original_.mean(v) - original_.mean(middle)).norm() > 1.5) {
      EXPECT_EQ(saved.covariance(v), original_.covariance(v)) << v;
      ++far;
    }
  EXPECT_EQ(far, 16);
  EXPECT_NE(output_.find("sharpen brush: 5 dabs changed"), std::string::npos) << output_;

  Events taken_back = stroke;
  taken_back.key("escape").wait(3);
  play(taken_back);
  EXPECT_TRUE(saved_is_original());
}

// F9 after a bevel: the panel's width typed 0.5 and Enter makes the bevel again from the cube as it
// was, in place of the first (exactly core's bevel at 0.5); its segments typed 3 likewise; Ctrl+Z then
// restores the file, the adjusted bevel being the one undo step.
TEST_F(EditorTools, BevelAdjustedByF9ReplacesTheLastOperation) {
  // The panel's fields (the panel sits at (10, 230); one row per number).
  const glm::vec2 width_field(70.0f, 267.0f), segments_field(50.0f, 290.0f);
  Events bevel = edge_selected();
  bevel.key("ctrl+b").wait().text("0.25").wait().key("enter").wait().key("f9").wait(2);
  bevel.click(width_field).wait().text("0.5").wait().key("enter").wait(2);
  Events shown = bevel;
  const CovarianceMesh wider = play(shown.wait(2), "cube_bevel_adjusted.png");
  EXPECT_TRUE(test::same_mesh(wider, bevel_edges(original_, {{6, 7}}, width(0.5)).mesh)) << output_;

  Events segments = bevel;
  segments.click(segments_field).wait().text("3").wait().key("enter").wait(3);
  const CovarianceMesh three = play(segments, "cube_bevel_adjusted_segments.png");
  EXPECT_TRUE(test::same_mesh(three, bevel_edges(original_, {{6, 7}}, width(0.5, 3)).mesh)) << output_;

  Events undone = segments;
  undone.key("ctrl+z").wait(3);
  play(undone);
  EXPECT_TRUE(saved_is_original());
}

// Alt+K and a line dragged across the cube's middle on screen: bisected by the plane seen along the
// line, crossing its four sides — Blender's 12 vertices and 10 faces, closed and outward.
TEST_F(EditorTools, BisectByALineAcrossTheView) {
  const glm::vec2 centre = pixel_of(view_, Vec3::Zero());
  Events cut;
  cut.key("alt+k").wait().drag(centre - glm::vec2(250.0f, 0.0f), centre + glm::vec2(250.0f, 0.0f), 6).wait(3);
  const CovarianceMesh saved = play(cut, "cube_bisected.png");
  test::expect_closed_outward(saved, 12, 10);
  EXPECT_NE(output_.find("bisect: "), std::string::npos) << output_;
}

// The knife (K) on the cube's top face (4–5–6–7, z = 1, towards the camera), clicked 3 pixels inside
// the face beside the middles of its edges 4–5 and 6–7, which the clicks snap to.
class EditorToolsKnife : public EditorTools {
protected:
  glm::vec2 beside_middle(int a, int b) const {
    const glm::vec2 middle = pixel_at({a, b}), centre = pixel_at({4, 5, 6, 7});
    return middle + 3.0f * glm::normalize(centre - middle);
  }
  Vec3 middle(int a, int b) const { return (original_.mean(size_t(a)) + original_.mean(size_t(b))) / 2; }
  Events two_points() const {
    Events e;
    e.move(pixel_at({4, 5, 6, 7})).wait().key("k").wait();
    e.click(beside_middle(4, 5)).wait().click(beside_middle(6, 7)).wait();
    return e;
  }
};

// K, two clicks, Enter: exactly core's knife through the two middles (10 vertices, 7 faces, closed).
TEST_F(EditorToolsKnife, KnifeAcrossTheCubeTopIsCoresKnife) {
  Events cut = two_points();
  cut.key("enter").wait(3);
  const CovarianceMesh saved = play(cut, "cube_knife_cut.png");
  const test::Shape shape = test::shape_of(saved);
  EXPECT_EQ(shape.vertices, 10);
  EXPECT_EQ(shape.faces, 7);
  EXPECT_EQ(shape.boundary_edges, 0);
  EXPECT_TRUE(shape.oriented);
  EXPECT_TRUE(test::same_mesh(saved, knife(original_, {middle(4, 5), middle(6, 7)}).mesh));
  EXPECT_NE(output_.find("knife: cut 1 face along 2 points"), std::string::npos) << output_;
}

// K, clicks beside the middles of the top face's four edges and the first again, Enter: the loop
// core's knife cuts for a path back to its start (a diamond in the face, its corners cut off).
TEST_F(EditorToolsKnife, KnifeBackToTheFirstPointCutsALoop) {
  Events loop;
  loop.move(pixel_at({4, 5, 6, 7})).wait().key("k").wait();
  for (const auto& [a, b] : std::vector<std::pair<int, int>>{{4, 5}, {5, 6}, {6, 7}, {7, 4}, {4, 5}})
    loop.click(beside_middle(a, b)).wait();
  loop.key("enter").wait(3);
  const CovarianceMesh saved = play(loop, "cube_knife_loop.png");
  EXPECT_TRUE(test::same_mesh(
      saved, knife(original_, {middle(4, 5), middle(5, 6), middle(6, 7), middle(7, 4), middle(4, 5)}).mesh))
      << output_;
  EXPECT_EQ(saved.n_vertices(), 12u);
  EXPECT_EQ(saved.n_faces(), 10u);
  EXPECT_NE(output_.find("knife: cut 1 face along 5 points"), std::string::npos) << output_;
}

// Esc after two points cancels; two points taken back by Backspace leave nothing to cut on Enter; two
// more points are only drawn (the screenshot shows the path on to the pointer): the document saved is
// the file as opened.
TEST_F(EditorToolsKnife, KnifeEscBackspaceAndThePathChangeNothing) {
  Events events = two_points();
  events.key("escape").wait();
  events.key("k").wait().click(beside_middle(4, 5)).wait().click(beside_middle(6, 7)).wait();
  events.key("backspace").wait().key("backspace").wait().key("enter").wait();
  events.click(beside_middle(4, 5)).wait().click(beside_middle(6, 7)).wait();
  events.move(pixel_at({4, 5, 6, 7}) + glm::vec2(30.0f, 10.0f)).wait(3);
  play(events, "cube_knife_path.png");
  EXPECT_TRUE(saved_is_original());
  EXPECT_NE(output_.find("knife cancelled"), std::string::npos) << output_;
}

// Face mode, a click on the cube's +z face, P (Separate selection) splits it off and Ctrl+Z takes it
// back; Y (Split) on it again and G X 1.5 moves the split face alone beside the open box: core's
// split of that face (12 vertices, 6 faces, 8 boundary edges) with its copies moved.
TEST_F(EditorTools, SplitDetachesTheSelectedFace) {
  Events split;
  split.key("3").wait().click(pixel_at({4, 5, 6, 7})).wait().key("p").wait().key("ctrl+z").wait();
  split.click(pixel_at({4, 5, 6, 7})).wait().key("y").wait();
  split.key("g").wait().key("x").wait().text("1.5").wait().key("enter").wait(3);
  const CovarianceMesh saved = play(split, "cube_face_split.png");
  MeshArrays expected = arrays_of(split_faces(original_, {1}).mesh);
  for (int v = 8; v < 12; ++v) expected.means[size_t(v)] += Vec3(1.5, 0.0, 0.0);
  const MeshArrays got = arrays_of(saved);
  EXPECT_EQ(got.faces, expected.faces);
  ASSERT_EQ(got.means.size(), 12u);
  for (size_t v = 0; v < 12; ++v) EXPECT_LT((got.means[v] - expected.means[v]).norm(), 1e-6) << v;
  EXPECT_EQ(test::shape_of(saved).boundary_edges, 8);
  EXPECT_NE(output_.find("separate: split off 1 face"), std::string::npos) << output_;
  EXPECT_NE(output_.find("split: split off 1 face"), std::string::npos) << output_;
}

// The cylinder without its top: Alt+click beside the rim's front edge selects the hole's boundary
// loop, Ctrl+F fills it with core's 2 × 2 grid (its summary: 1 vertex added); F9 and a span of 1
// typed in the panel make it again as a 3 × 1 grid: core's, closed and outward, one undo step.
// The cylinder without its top as the mesh edited; its rim's edge lowest on screen, nearest the camera
// looking down on the hole, (min, max).
class EditorToolsOpenCylinder : public EditorTools {
protected:
  void SetUp() override {
    EditorTools::SetUp();
    use_mesh(delete_faces(make_sample("cylinder"), {16}).mesh);
    rim_ = boundary_loops(original_).at(0);
    ASSERT_EQ(rim_.size(), 8u);
    size_t front = 0;
    for (size_t k = 0; k < rim_.size(); ++k)
      if (pixel_at({rim_[k], rim_[(k + 1) % 8]}).y > pixel_at({rim_[front], rim_[(front + 1) % 8]}).y) front = k;
    front_ = {std::min(rim_[front], rim_[(front + 1) % 8]), std::max(rim_[front], rim_[(front + 1) % 8])};
  }
  std::vector<int> rim_;
  std::array<int, 2> front_{};
};

TEST_F(EditorToolsOpenCylinder, GridFillClosesTheSelectedHole) {
  const std::vector<int>& rim = rim_;
  const glm::vec2 middle = pixel_at({front_[0], front_[1]}), centre = pixel_at(rim);
  const glm::vec2 span_field(70.0f, 267.0f);  // the F9 panel's first row (as the bevel's test)
  Events fill;
  fill.click(middle + 3.0f * glm::normalize(centre - middle), "alt").wait().key("ctrl+f").wait();
  fill.key("f9").wait().click(span_field).wait().text("1").wait().key("enter").wait(3);
  const CovarianceMesh saved = play(fill, "cylinder_grid_filled.png");
  EXPECT_NE(output_.find("grid fill: grid-filled a loop of 8 vertices with 2 × 2 quads: 1 vertex added"),
            std::string::npos)
      << output_;
  const test::Shape shape = test::shape_of(saved);
  EXPECT_EQ(shape.vertices, 24);
  EXPECT_EQ(shape.faces, 17 + 3);
  EXPECT_EQ(shape.boundary_edges, 0);
  EXPECT_TRUE(shape.oriented);
  EXPECT_TRUE(test::same_mesh(saved, grid_fill(original_, rim, 1).mesh)) << output_;
}

// The cylinder without its top: Ctrl+B on the rim's front edge (a boundary edge) makes core's band in
// the face below it, the rim kept: one boundary loop of 8 edges still, oriented, 2 vertices and 1 face
// more.
TEST_F(EditorToolsOpenCylinder, BevelOfAnOpenRimKeepsItOpen) {
  const int a = front_[0], b = front_[1];
  const glm::vec2 middle = pixel_at({a, b}), centre = pixel_at(rim_);
  Events bevel;
  bevel.key("2").wait().click(middle + 2.0f * glm::normalize(centre - middle)).wait();
  bevel.key("ctrl+b").wait().text("0.2").wait().key("enter").wait(3);
  const CovarianceMesh saved = play(bevel, "open_rim_bevelled.png");
  const test::Shape shape = test::shape_of(saved);
  EXPECT_EQ(shape.vertices, int(original_.n_vertices()) + 2);
  EXPECT_EQ(shape.faces, int(original_.n_faces()) + 1);
  EXPECT_EQ(shape.boundary_edges, 8);
  EXPECT_TRUE(shape.oriented);
  EXPECT_EQ(boundary_loops(saved).size(), 1u);
  EXPECT_TRUE(test::same_mesh(saved, bevel_edges(original_, {{a, b}}, width(0.2)).mesh)) << output_;
}

// A modelling key pressed while an axis end of the gizmo is dragged (W: subdivide, with nothing but
// one vertex selected the whole mesh) does nothing: the drag goes on and ends as a drag alone.
TEST_F(EditorTools, ModellingKeysWaitForTheGizmoDragToEnd) {
  const HandleFrame f = handle_frame(original_, 6, ViewOptions{}.draw.sigma_scale, view_);
  int axis = 0;  // the axis with the longest projection on screen
  for (int a = 1; a < 3; ++a)
    if (glm::length(pixel_of(view_, f.end(a, 1)) - pixel_of(view_, f.centre)) >
        glm::length(pixel_of(view_, f.end(axis, 1)) - pixel_of(view_, f.centre)))
      axis = a;
  const glm::vec2 centre = pixel_of(view_, f.centre), end = pixel_of(view_, f.end(axis, 1));
  Events events;
  events.click(centre).wait().press(end).move(end + 0.2f * (centre - end)).wait().key("w").wait();
  events.move(end + 0.4f * (centre - end)).wait().release(end + 0.4f * (centre - end)).wait(3);
  const CovarianceMesh saved = play(events);
  EXPECT_EQ(saved.n_vertices(), 8u);
  EXPECT_EQ(saved.n_faces(), 6u);
  EXPECT_NE(saved.covariance(6), original_.covariance(6));  // the drag scaled it
}

// The cube's top face (2, 3, 7, 6: y = +1) selected in face mode, G Z Z and 0.5 typed: the second Z
// takes the Normal orientation's z, the face's normal +y, so the face rises by 0.5 (not along the
// world's z), and the status names it.
TEST_F(EditorTools, OrientationNormalAxisMovesAFaceAlongItsNormal) {
  const std::vector<int> top = {2, 3, 6, 7};
  Events grab;
  grab.key("3").wait().click(pixel_at(top)).wait();
  grab.key("g").wait().key("z").wait().key("z").wait().text("0.5").wait().key("enter").wait(3);
  const CovarianceMesh saved = play(grab, "cube_face_along_normal.png");
  ASSERT_EQ(saved.n_vertices(), original_.n_vertices());
  for (size_t v = 0; v < saved.n_vertices(); ++v) {
    const bool moved = std::find(top.begin(), top.end(), int(v)) != top.end();
    const Vec3 expected = original_.mean(v) + (moved ? Vec3(0.0, 0.5, 0.0) : Vec3::Zero());
    EXPECT_LT((saved.mean(v) - expected).norm(), 1e-9) << v << "\n" << output_;
  }
  EXPECT_NE(output_.find("along normal z"), std::string::npos) << output_;
}

// The F9 panel's rows (the panel sits at (10, 230)): an integer field, a real field, a second row.
const glm::vec2 kAdjustIntegerField(50.0f, 267.0f), kAdjustFirstField(70.0f, 267.0f),
    kAdjustSecondField(70.0f, 290.0f);

// E on the cube's top face, 0.5 along its normal; F9 and an offset of 1 typed make the extrusion
// again from the cube as it was (exactly core's extrusion moved by 1 along +y); Ctrl+Z restores the
// file byte for byte, Ctrl+Shift+Z the adjusted extrusion byte for byte.
TEST_F(EditorTools, AdjustLastExtrudeOffset) {
  const std::vector<int> top = {2, 3, 6, 7};
  Events extrude;
  extrude.key("3").wait().click(pixel_at(top)).wait().key("e").wait().text("0.5").wait().key("enter").wait();
  extrude.key("f9").wait(2).click(kAdjustFirstField).wait().text("1").wait().key("enter").wait(3);
  const CovarianceMesh saved = play(extrude, "cube_extrude_adjusted.png");
  EXPECT_TRUE(test::same_mesh(saved, extrude_vertices(original_, top, Vec3(0.0, 1.0, 0.0)).mesh)) << output_;
  const std::string adjusted = read_text_file(dir_.file("saved.ply"));

  Events undone = extrude;
  undone.key("ctrl+z").wait(3);
  play(undone);
  EXPECT_TRUE(saved_is_original());
  Events redone = undone;
  redone.key("ctrl+shift+z").wait(3);
  play(redone);
  EXPECT_EQ(read_text_file(dir_.file("saved.ply")), adjusted);
}

// I on the top face, 0.2 typed; F9 and a thickness of 0.3, then a depth of 0.25: core's inset at 0.3
// with its inner face raised 0.25 along +y; Ctrl+Z restores the file byte for byte.
TEST_F(EditorTools, AdjustLastInsetThicknessAndDepth) {
  Events inset;
  inset.key("3").wait().click(pixel_at({2, 3, 6, 7})).wait().key("i").wait().text("0.2").wait().key("enter").wait();
  inset.key("f9").wait(2).click(kAdjustFirstField).wait().text("0.3").wait().key("enter").wait();
  inset.click(kAdjustSecondField).wait().text("0.25").wait().key("enter").wait(3);
  const CovarianceMesh saved = play(inset, "cube_inset_adjusted.png");
  const Modelled thinner = inset_faces(original_, {3}, 0.3);
  MeshArrays expected = arrays_of(thinner.mesh);
  for (const int v : thinner.selection) expected.means[size_t(v)] += Vec3(0.0, 0.25, 0.0);
  const MeshArrays got = arrays_of(saved);
  EXPECT_EQ(got.faces, expected.faces) << output_;
  ASSERT_EQ(got.means.size(), expected.means.size());
  for (size_t v = 0; v < got.means.size(); ++v) EXPECT_LT((got.means[v] - expected.means[v]).norm(), 1e-9) << v;
  EXPECT_EQ(got.covariances, expected.covariances);

  Events undone = inset;
  undone.key("ctrl+z").wait(3);
  play(undone);
  EXPECT_TRUE(saved_is_original());
}

// Ctrl+R on the front vertical edge, click, click: one loop; F9 and 3 cuts, then a slide of 0.5:
// core's loop cut of that ring with 3 cuts slid by 0.5; Ctrl+Z restores the file byte for byte.
TEST_F(EditorTools, AdjustLastLoopCutCutsAndSlide) {
  const glm::vec2 edge = pixel_at({5, 6});
  const auto under = edge_under(original_, view_, edge);
  ASSERT_TRUE(under);
  const auto [a, b] = edge_ring(original_, (*under)[0], (*under)[1]).edges.front();
  Events cut;
  cut.key("ctrl+r").move(edge).wait().click(edge).wait().click(edge).wait();
  cut.key("f9").wait(2).click(kAdjustIntegerField).wait().text("3").wait().key("enter").wait();
  cut.click(kAdjustSecondField).wait().text("0.5").wait().key("enter").wait(3);
  const CovarianceMesh saved = play(cut, "cube_loop_cut_adjusted.png");
  EXPECT_TRUE(test::same_mesh(saved, loop_cut(original_, a, b, 3, 0.5).mesh)) << output_;

  Events undone = cut;
  undone.key("ctrl+z").wait(3);
  play(undone);
  EXPECT_TRUE(saved_is_original());
}

}  // namespace
}  // namespace gps
