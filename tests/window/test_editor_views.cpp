// The editor's views and numbers, in a real window under Xvfb: the statistics overlay keeps clear of
// the gizmo; a dot on each selected vertex, selected faces shaded where they face the eye; the gizmo of a
// multi-selection at its centroid; ellipsoids of the selection and its neighbours only on a large mesh; Inspector
// fields that hold the full-precision value while edited and apply a typed value exactly. Screenshots kept in
// build/test-artefacts/EditorViews/.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "../support/editor_driver.h"
#include "core/io/mesh_io.h"
#include "core/modelling/samples.h"
#include "core/io/text_file.h"
#include "render/image/image_io.h"
#include "ui/editing/axis_handles.h"
#include "ui/input/camera_control.h"
#include "ui/overlays/ellipsoid_scope.h"
#include "ui/editing/selection.h"
#include "ui/panels/view_options.h"
#include "view/picking.h"

namespace gps {
namespace {

using test::artefact;
using test::editor_view;
using test::Events;
using test::pixel_of;

constexpr int kWidth = test::kWindowWidth, kHeight = test::kWindowHeight;
// The Inspector's first row of fields (mean x, y, z; then σ1..3 a row below) at its first-use place
// in a 1024-pixel-wide window: 360 wide, 10 pixels from the right edge, below the menu bar.
const glm::vec2 kMeanX(700.0f, 72.0f), kMeanY(790.0f, 72.0f), kSigma1(700.0f, 97.0f);

glm::vec3 colour_at(const Image& im, glm::vec2 p) {
  const int x = int(std::lround(p.x)), y = int(std::lround(p.y));
  return {im.at(x, y, 0), im.at(x, y, 1), im.at(x, y, 2)};
}

class EditorViews : public ::testing::Test {
protected:
  void use_mesh(const CovarianceMesh& mesh) {
    write_mesh(dir_.file("original.ply"), mesh);
    original_ = read_mesh(dir_.file("original.ply"));
  }
  void write_settings(const std::string& json) const {
    std::filesystem::create_directories(dir_.path() / "gpsurf");
    dir_.write("gpsurf/settings.json", json);
  }
  test::CommandResult play(const Events& events, const std::string& extra) const {
    return test::play_editor(dir_, dir_.file("original.ply"), events, kWidth, kHeight, extra);
  }
  // Screenshots after `first` and after `second` (artefacts `stem`_before.png, `stem`_after.png).
  std::pair<Image, Image> two_shots(const Events& first, const Events& second, const std::string& stem) const {
    for (const auto& [events, name] :
         {std::pair{&first, stem + "_before.png"}, std::pair{&second, stem + "_after.png"}}) {
      const auto r = play(*events, "--screenshot " + artefact(name));
      EXPECT_EQ(r.exit_code, 0) << r.output;
    }
    return {read_image(artefact(stem + "_before.png")), read_image(artefact(stem + "_after.png"))};
  }
  test::TempDir dir_;
  CovarianceMesh original_;
};

// Whether window pixel p lies clear of the panels and the statistics overlay at their first-use
// places, and of the gizmo at `gizmo`.
bool clear_of_ui(glm::vec2 p, glm::vec2 gizmo) {
  const auto [free_min, free_max] = test::editor_free_region();
  return p.x > free_min.x + 4.0f && p.y > free_min.y + 4.0f && p.x < free_max.x - 4.0f && p.y < free_max.y - 4.0f &&
         glm::length(p - gizmo) > 60.0f && !(p.x < 300.0f && p.y < 240.0f);
}

// Every selected vertex shows an orange dot (drawn on the GPU in one call, not by the UI's draw list):
// after Select All on the pawn, at each vertex's pixel clear of the panels and the gizmo; before it,
// none of those pixels is orange.
TEST_F(EditorViews, EachSelectedVertexShowsADot) {
  use_mesh(make_sample("pawn"));
  const Viewport view = editor_view(original_);
  Events none;
  none.wait(3).move(glm::vec2(300.0f, 600.0f)).wait(2);
  Events all = none;
  all.key("a").wait(3);
  const auto [before, after] = two_shots(none, all, "vertices_selected");
  const glm::vec3 orange(1.0f, 170.0f / 255.0f, 40.0f / 255.0f);
  const glm::vec2 gizmo = pixel_of(view, original_.mean(0));  // at the active vertex, the first selected
  int checked = 0;
  for (size_t v = 0; v < original_.n_vertices(); ++v) {
    const glm::vec2 p = pixel_of(view, original_.mean(v));
    if (!clear_of_ui(p, gizmo)) continue;
    EXPECT_LT(glm::length(colour_at(after, p) - orange), 0.08f) << "vertex " << v << " at " << p.x << ", " << p.y;
    EXPECT_GT(glm::length(colour_at(before, p) - orange), 0.2f) << "vertex " << v << " unselected";
    ++checked;
  }
  EXPECT_GT(checked, 300);
}

// In face mode, Select All shades every face that looks at the eye: its centre, clear of the panels
// and the dots, blended towards the highlight.
TEST_F(EditorViews, SelectedFacesAreShadedOnTheSideFacingTheEye) {
  use_mesh(make_sample("pawn"));
  const Viewport view = editor_view(original_);
  Events plain;
  plain.wait(3).key("3").wait(1).move(glm::vec2(300.0f, 600.0f)).wait(2);
  Events all = plain;
  all.key("a").wait(3);
  const auto [before, after] = two_shots(plain, all, "faces_selected");
  const glm::vec3 fill(1.0f, 150.0f / 255.0f, 40.0f / 255.0f);
  const glm::vec2 gizmo = pixel_of(view, original_.mean(0));
  const glm::dvec3 eye = view.camera.eye_double();
  int front = 0, once = 0;
  for (size_t f = 0; f < original_.n_faces(); ++f) {
    const std::span<const int> corners = original_.face(f);
    Vec3 centre = Vec3::Zero(), normal = Vec3::Zero();
    for (size_t k = 0; k < corners.size(); ++k) {
      centre += original_.mean(size_t(corners[k]));
      normal += original_.mean(size_t(corners[k])).cross(original_.mean(size_t(corners[(k + 1) % corners.size()])));
    }
    centre /= double(corners.size());
    const glm::vec2 p = pixel_of(view, centre);
    // Clear of the panels, the gizmo and the statistics, and of the face's corners' dots and outline.
    bool clear = clear_of_ui(p, gizmo);
    for (const int v : corners) clear = clear && glm::length(pixel_of(view, original_.mean(size_t(v))) - p) > 8.0f;
    if (!clear) continue;
    if (normal.dot(Vec3(eye.x, eye.y, eye.z) - centre) <= 0.0) continue;
    // Shaded towards the fill; once, where no other face facing the eye (or its outline) lies over it.
    const glm::vec3 was = colour_at(before, p), now = colour_at(after, p);
    ++front;
    EXPECT_LT(glm::length(now - fill), glm::length(was - fill) - 0.05f) << "face " << f << " facing the eye";
    once += glm::length(now - glm::mix(was, fill, 70.0f / 255.0f)) < 0.03f;
  }
  EXPECT_GT(front, 100);
  EXPECT_GT(once, front / 2);
}

// The cube panned (Shift + right drag) until its front corner lies under the statistics overlay's
// usual place, the top-left corner: once the corner is selected the overlay moves away, the gizmo
// shows unshaded and its axis end can be dragged.
TEST_F(EditorViews, TheStatisticsOverlayKeepsClearOfTheGizmo) {
  CovarianceMesh cube = make_sample("cube");
  constexpr int kVertex = 6;  // (1, 1, 1), in front for the default camera; a small Gaussian, a small gizmo
  cube.covariances[kVertex] = Vec3(0.004, 0.01, 0.02).asDiagonal();
  use_mesh(cube);
  Viewport view = editor_view(original_);
  const glm::vec2 wanted(150.0f, 110.0f);  // well inside the overlay's top-left place (10..290 × 30..200)
  // The pan that brings the corner there (a pan moves the target's depth by the mouse's pixels; the
  // corner, nearer, a little more): a few corrections.
  const Camera start = view.camera;
  glm::vec2 delta = wanted - pixel_of(view, original_.mean(kVertex));
  for (int i = 0; i < 20; ++i) {
    view.camera = start;
    pan(view.camera, delta, kHeight);
    delta += 0.7f * (wanted - pixel_of(view, original_.mean(kVertex)));
  }
  view.camera = start;
  pan(view.camera, delta, kHeight);
  const glm::vec2 from(480.0f, 420.0f), to = from + delta;
  const glm::vec2 at = pixel_of(view, original_.mean(kVertex));
  ASSERT_LT(glm::length(at - wanted), 1.0f);

  Events select;
  select.add(R"({"type": "drag", "button": "right", "mods": "shift", "from": )" + test::point(from) + R"(, "to": )" +
             test::point(to) + R"(, "steps": 6})");
  select.wait().click(at).wait(3);
  Events shown = select;
  shown.move(glm::vec2(480.0f, 600.0f)).wait(2);  // the cursor off the gizmo: its centre dot white, not lit
  const auto r = play(shown, "--screenshot " + artefact("statistics_clear_of_gizmo.png"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Image shot = read_image(artefact("statistics_clear_of_gizmo.png"));
  const glm::vec3 centre = colour_at(shot, at);
  EXPECT_GT(std::min({centre.r, centre.g, centre.b}), 0.9f) << "the gizmo's white centre dot is shaded by the overlay";

  // Its longest axis end on screen, dragged outward along the axis: that σ grows.
  const HandleFrame f = handle_frame(original_, kVertex, ViewOptions{}.draw.sigma_scale, view);
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (glm::length(pixel_of(view, f.end(a, 1)) - at) > glm::length(pixel_of(view, f.end(axis, 1)) - at)) axis = a;
  Events drag = select;
  drag.drag(pixel_of(view, f.end(axis, 1)), pixel_of(view, f.centre + 1.5 * (f.end(axis, 1) - f.centre))).wait();
  const auto d = play(drag, "--save " + dir_.file("edited.ply"));
  ASSERT_EQ(d.exit_code, 0) << d.output;
  const CovarianceMesh edited = read_mesh(dir_.file("edited.ply"));
  const Vec3 u = f.axes.axes.col(axis);
  EXPECT_NEAR(std::sqrt(u.dot(edited.covariance(kVertex) * u)), 1.5 * f.axes.sigmas[axis], 0.05 * f.axes.sigmas[axis]);
}

// With "gizmo at: centroid", one gizmo sits at the mean of the 12 selected vertices: dragging its
// centre moves all twelve by the same vector. With the gizmo at the active vertex (the default) the
// same drag moves no vertex.
TEST_F(EditorViews, TheGizmoOfAMultiSelectionAtItsCentroid) {
  use_mesh(make_sample("torus"));
  const Viewport view = editor_view(original_);
  const auto [corner, side] = test::box_holding(view, glm::vec2(205.0f, 318.0f), original_, 12);
  const std::vector<int> selected =
      vertices_in_box(view.camera, view.width, view.height, corner, corner + side, original_);
  ASSERT_EQ(selected.size(), 12u);
  Vec3 centroid = Vec3::Zero();
  for (const int v : selected) centroid += original_.mean(size_t(v)) / 12.0;
  const glm::vec2 pivot = pixel_of(view, centroid);

  // Select through (X-ray): the box takes the hidden vertices behind the torus's front too.
  Events events;
  events.key("alt+z").drag(corner, corner + side, 8).wait().drag(pivot, pivot + glm::vec2(0.0f, -40.0f), 8).wait();
  write_settings(R"({"pivot": 1})");
  const auto r =
      play(events, "--save " + dir_.file("centroid.ply") + " --screenshot " + artefact("pivot_centroid.png"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const CovarianceMesh moved = read_mesh(dir_.file("centroid.ply"));
  const Vec3 shift = moved.mean(size_t(selected[0])) - original_.mean(size_t(selected[0]));
  EXPECT_GT(shift.norm(), 0.05);
  for (size_t v = 0; v < original_.n_vertices(); ++v) {
    const bool in = std::find(selected.begin(), selected.end(), int(v)) != selected.end();
    EXPECT_LT((moved.mean(v) - original_.mean(v) - (in ? shift : Vec3::Zero())).norm(), 1e-12) << v;
    EXPECT_EQ(moved.covariance(v), original_.covariance(v)) << v;
  }

  write_settings(R"({"pivot": 0})");
  const auto a = play(events, "--save " + dir_.file("active.ply"));
  ASSERT_EQ(a.exit_code, 0) << a.output;
  const CovarianceMesh kept = read_mesh(dir_.file("active.ply"));
  for (size_t v = 0; v < original_.n_vertices(); ++v) EXPECT_EQ(kept.mean(v), original_.mean(v)) << v;
}

// The sphere's 1,538 vertices are above kAllEllipsoidsUpTo: by default only the selected vertex's
// ellipsoid and its neighbours' are drawn, all of them when the View panel says so.
TEST_F(EditorViews, OnALargeMeshOnlyTheSelectionsNeighbourhoodHasEllipsoids) {
  use_mesh(make_sample("sphere", 1536));
  ASSERT_GT(original_.n_vertices(), kAllEllipsoidsUpTo);
  const Viewport view = editor_view(original_);
  int vertex = 0;
  const Vec3 eye = to_vec(view.camera.eye());
  for (size_t v = 1; v < original_.n_vertices(); ++v)
    if ((original_.mean(v) - eye).norm() < (original_.mean(size_t(vertex)) - eye).norm()) vertex = int(v);
  const glm::vec2 at = pixel_of(view, original_.mean(size_t(vertex)));
  Events events;
  events.key("shift+e").wait().click(at).wait(3);
  // Ellipsoid lines are drawn in one blue: the pixels of that blue, and the farthest from the vertex.
  const auto blue = [&](const std::string& name) {
    const Image shot = read_image(artefact(name));
    int count = 0;
    float farthest = 0.0f;
    for (int y = 30; y < kHeight - 30; ++y)
      for (int x = 0; x < int(test::editor_free_region().second.x); ++x) {  // the view left of the panels
        const glm::vec3 c = colour_at(shot, glm::vec2(x, y));
        if (glm::length(c - glm::vec3(0.15f, 0.35f, 0.85f)) > 0.06f) continue;
        ++count;
        farthest = std::max(farthest, glm::length(glm::vec2(x, y) - at));
      }
    return std::pair(count, farthest);
  };
  const auto few = play(events, "--screenshot " + artefact("ellipsoids_neighbourhood.png"));
  ASSERT_EQ(few.exit_code, 0) << few.output;
  write_settings(R"({"ellipsoid_scope": 2})");
  const auto all = play(events, "--screenshot " + artefact("ellipsoids_all.png"));
  ASSERT_EQ(all.exit_code, 0) << all.output;
  const auto [few_count, few_reach] = blue("ellipsoids_neighbourhood.png");
  const auto [all_count, all_reach] = blue("ellipsoids_all.png");
  EXPECT_GT(few_count, 30);
  // Within about a third of the sphere's radius on screen (its poles' distance halved).
  const float radius = 0.5f * glm::length(pixel_of(view, Vec3(0, 1, 0)) - pixel_of(view, Vec3(0, -1, 0)));
  EXPECT_LT(few_reach, 0.35f * radius) << "an ellipsoid far from the selected vertex";
  EXPECT_GT(all_count, 10 * few_count);
  EXPECT_GT(all_reach, 120.0f);
}

// The Inspector rounds what it shows, but a field being edited holds the full value: left unchanged
// it changes nothing, and a typed value is applied exactly as typed (even past the shown decimals).
TEST_F(EditorViews, InspectorFieldsHoldFullPrecisionWhileEdited) {
  CovarianceMesh cube = make_sample("cube");
  cube.set_mean(6, Vec3(1.0 + 1e-9, 1.0, 1.0));
  cube.covariances[6] = Vec3(0.004, 0.004, 0.004).asDiagonal();
  use_mesh(cube);
  const Viewport view = editor_view(original_);
  const glm::vec2 at = pixel_of(view, original_.mean(6));
  Events select;
  select.click(at).wait(3);

  // Entered and left unchanged (Enter), the mean x of 1.000000001 (shown as 1.0000) stays as it was.
  Events unchanged = select;
  unchanged.click(kMeanX).wait(2).key("enter").wait(2).click(kSigma1).wait(2).key("enter").wait(2);
  ASSERT_EQ(play(unchanged, "--save " + dir_.file("unchanged.ply")).exit_code, 0);
  EXPECT_EQ(read_text_file(dir_.file("unchanged.ply")), read_text_file(dir_.file("original.ply")));

  // A typed value past the shown decimals, confirmed with Enter, is the value: one undo step.
  const std::string typed = "1.00001234567890123";
  Events edit = select;
  edit.click(kMeanX).wait(2).text(typed).key("enter").wait(2);
  ASSERT_EQ(play(edit, "--save " + dir_.file("typed.ply")).exit_code, 0);
  const CovarianceMesh edited = read_mesh(dir_.file("typed.ply"));
  EXPECT_EQ(edited.mean(6).x(), std::strtod(typed.c_str(), nullptr));
  EXPECT_EQ(edited.mean(6).y(), original_.mean(6).y());
  for (size_t v = 0; v < original_.n_vertices(); ++v) {
    if (v != 6) {
      EXPECT_EQ(edited.mean(v), original_.mean(v));
    }
  }
  Events undo = edit;
  undo.key("ctrl+z").wait();
  ASSERT_EQ(play(undo, "--save " + dir_.file("undone.ply")).exit_code, 0);
  EXPECT_EQ(read_text_file(dir_.file("undone.ply")), read_text_file(dir_.file("original.ply")));

  // Escape leaves the entry without a change.
  Events escape = select;
  escape.click(kMeanX).wait(2).text("7").wait(2).key("escape").wait(2);
  ASSERT_EQ(play(escape, "--save " + dir_.file("escaped.ply")).exit_code, 0);
  EXPECT_EQ(read_text_file(dir_.file("escaped.ply")), read_text_file(dir_.file("original.ply")));

  // Two vertices whose y differ: the field reads "mixed", and a typed value applies to both exactly.
  int below = -1;
  for (size_t v = 0; v < original_.n_vertices(); ++v)
    if ((original_.mean(v) - Vec3(1, -1, 1)).norm() < 1e-12) below = int(v);
  ASSERT_GE(below, 0);
  Events mixed = select;
  mixed.click(pixel_of(view, original_.mean(size_t(below))), "shift")
      .wait(3)
      .click(kMeanY)
      .wait(2)
      .text("0.1")
      .key("enter")
      .wait(2);
  ASSERT_EQ(play(mixed, "--save " + dir_.file("mixed.ply")).exit_code, 0);
  const CovarianceMesh both = read_mesh(dir_.file("mixed.ply"));
  EXPECT_EQ(both.mean(6).y(), 0.1);
  EXPECT_EQ(both.mean(size_t(below)).y(), 0.1);
  EXPECT_EQ(both.mean(6).x(), original_.mean(6).x()) << "the other coordinates as they were";
  EXPECT_EQ(both.mean(size_t(below)).z(), original_.mean(size_t(below)).z());

  // A screenshot while σ1 is being edited: the field holds 0.063245553203367583, the others round.
  Events editing = select;
  editing.click(kSigma1).wait(3);
  ASSERT_EQ(play(editing, "--screenshot " + artefact("inspector_full_precision.png")).exit_code, 0);
}

}  // namespace
}  // namespace gps
