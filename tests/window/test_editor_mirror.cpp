// The mirror modifier (Ctrl+Alt+M, applied with Ctrl+Alt+Shift+M) in a real window under Xvfb, on
// the cube's x >= 0 half: the view shows both sides, the file keeps the half, apply writes core's
// mirror; a designer's U-bracket made on the half and applied (DesignerReplayMirrorBracket). Screenshots
// kept in build/test-artefacts/EditorMirror/.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/modelling/bisect.h"
#include "core/modelling/affine_transform.h"
#include "core/modelling/delete_elements.h"
#include "core/modelling/extrude.h"
#include "core/modelling/mirror.h"
#include "core/modelling/samples.h"
#include "render/image/image_io.h"
#include "tests/support/editor_tools_fixture.h"

namespace gps {
namespace {

using test::artefact;
using test::editor_view;
using test::EditorTools;
using test::Events;
using test::pixel_of;

// The mirror modifier (Ctrl+Alt+M) on the cube's x ≥ 0 half, cut at x = 0 by bisect: the editor
// shows the half mirrored about x = 0 and merged at the seam while the file keeps the half.
class EditorToolsMirror : public EditorTools {
protected:
  void SetUp() override {
    const CovarianceMesh cut = bisect(make_sample("cube"), Vec3::Zero(), Vec3(1, 0, 0)).mesh;
    std::vector<int> left;
    for (size_t v = 0; v < cut.n_vertices(); ++v)
      if (cut.mean(v).x() < 0) left.push_back(int(v));
    use_mesh(delete_vertices(cut, left).mesh);
    for (size_t v = 0; v < original_.n_vertices(); ++v) {
      const Vec3 p = original_.mean(v);
      if (p.x() == 0 && p.y() > 0 && p.z() > 0) seam_ = int(v);   // on the plane, top front
      if (p.x() > 0 && p.y() > 0 && p.z() > 0) corner_ = int(v);  // the far corner, top front
    }
    ASSERT_EQ(original_.n_vertices(), 8u);
    ASSERT_GE(seam_, 0);
    ASSERT_GE(corner_, 0);
  }
  // A click on `vertex` (Shift: added to the selection), in the first view of the half, or with
  // `mirrored` in that of its mirror (the file opened with the modifier on frames the whole).
  Events& select(Events& e, int vertex, bool add = false, bool mirrored = false) const {
    const Viewport view = mirrored ? editor_view(mirror(original_, 0, Vec3::Zero(), true).mesh) : view_;
    return e.click(pixel_of(view, original_.mean(size_t(vertex))), add ? "shift" : "").wait();
  }
  int seam_ = -1, corner_ = -1;
};

// The far top corner raised by G Y 0.5 with the modifier on: the file keeps the half with that move
// only, and the orthographic front view of the whole (numpad 1, 5, Home; nothing selected; the
// statistics hidden by the settings) has the outline of each row mirrored about the middle, as wide
// as high: the half alone is half as wide, and a mirror side that missed the edit would lack the
// raised corner, whose rows then stand out by tens of pixels.
TEST_F(EditorToolsMirror, MirrorShowsTheEditOnBothSides) {
  std::filesystem::create_directories(dir_.file("gpsurf"));
  dir_.write("gpsurf/settings.json", R"({"show_statistics": false})");
  Events e;
  select(e, corner_).key("ctrl+alt+m").wait().key("g").wait().key("y").wait().text("0.5").wait().key("enter").wait();
  e.key("alt+a").wait().key("kp1").wait().key("kp5").wait().key("home").wait(3);
  const CovarianceMesh saved = play(e, "mirror_half_cube_front.png");
  ASSERT_EQ(saved.n_vertices(), original_.n_vertices());
  for (size_t v = 0; v < saved.n_vertices(); ++v)
    EXPECT_EQ(saved.mean(v), original_.mean(v) + (int(v) == corner_ ? Vec3(0, 0.5, 0) : Vec3::Zero())) << v;
  EXPECT_NE(output_.find("mirror modifier on: the plane x = 0, clipping on"), std::string::npos) << output_;

  const Image shot = read_image(artefact("mirror_half_cube_front.png"));
  const auto [free_min, free_max] = test::editor_free_region();
  // The surface: the clay MatCap's reddish pixels (the background, the mesh lines and the panels are grey).
  const auto surface = [&](int x, int y) { return shot.at(x, y, 0) - shot.at(x, y, 2) > 0.02f; };
  struct Row {
    int y, first, last;
  };
  std::vector<Row> rows;
  for (int y = int(free_min.y) + 2; y < int(free_max.y) - 2; ++y) {
    Row row{y, -1, -1};
    for (int x = int(free_min.x); x < int(free_max.x); ++x)
      if (surface(x, y)) row.first = row.first < 0 ? x : row.first, row.last = x;
    if (row.first >= 0) rows.push_back(row);
  }
  ASSERT_GT(rows.size(), 50u) << "no surface in the screenshot";
  int left = rows.front().first, right = rows.front().last;
  for (const Row& r : rows) left = std::min(left, r.first), right = std::max(right, r.last);
  EXPECT_GT(double(right - left) / double(rows.back().y - rows.front().y), 0.75) << "the mirror side is missing";
  for (const Row& r : rows) EXPECT_LE(std::abs((r.first - left) - (right - r.last)), 2) << "row " << r.y;
}

// Apply (Ctrl+Alt+Shift+M) after a seam vertex moved up: the file is core's mirror of the half as edited,
// closed (12 vertices, 10 faces), as one undo step (Ctrl+Z gives the half back).
TEST_F(EditorToolsMirror, MirrorApplyWritesCoresMirror) {
  Events e;
  select(e, seam_).key("ctrl+alt+m").wait().key("g").wait().key("z").wait().text("0.25").wait().key("enter").wait();
  e.key("ctrl+alt+shift+m").wait(3);
  const CovarianceMesh saved = play(e, "mirror_applied.png");
  CovarianceMesh half = original_;
  half.set_mean(size_t(seam_), original_.mean(size_t(seam_)) + Vec3(0, 0, 0.25));
  EXPECT_TRUE(test::same_mesh(saved, mirror(half, 0, Vec3::Zero(), true).mesh));
  const test::Shape shape = test::shape_of(saved);
  EXPECT_EQ(shape.vertices, 12);
  EXPECT_EQ(shape.faces, 10);
  EXPECT_EQ(shape.boundary_edges, 0);
  EXPECT_TRUE(shape.oriented);
  EXPECT_NE(output_.find("apply mirror modifier: mirrored 8 vertices and 5 faces in x, 4 vertices merged"),
            std::string::npos)
      << output_;

  e.key("ctrl+z").wait(3);
  const CovarianceMesh undone = play(e);
  EXPECT_TRUE(test::same_mesh(undone, half));
}

// After the apply the selection is what it was with its images, as Blender mirrors its selection: G Y
// 0.5 then moves the far corner and its image (it moved the four copies mirror() selects).
TEST_F(EditorToolsMirror, MirrorApplyKeepsTheSelectionWithItsImages) {
  Events e;
  select(e, corner_).key("ctrl+alt+m").wait().key("ctrl+alt+shift+m").wait(3);
  e.key("g").wait().key("y").wait().text("0.5").wait().key("enter").wait(3);
  const CovarianceMesh saved = play(e, "mirror_applied_selection.png");
  const CovarianceMesh whole = mirror(original_, 0, Vec3::Zero(), true).mesh;
  const int image = mirror_images(original_, 0, Vec3::Zero(), true)[size_t(corner_)];
  ASSERT_EQ(saved.n_vertices(), whole.n_vertices());
  for (size_t v = 0; v < saved.n_vertices(); ++v) {
    const bool moved = int(v) == corner_ || int(v) == image;
    EXPECT_EQ(saved.mean(v), whole.mean(v) + (moved ? Vec3(0, 0.5, 0) : Vec3::Zero())) << v;
  }
}

// Any operation shows on both sides: with the modifier on, the far face (x = 1) extruded by E 0.5 in
// face mode and the modifier applied gives a closed, outward part symmetric about x = 0 reaching
// x = ±1.5: the half's 12 vertices and 9 faces, mirrored with its 4 seam vertices merged.
TEST_F(EditorToolsMirror, MirrorExtrudeShowsOnBothSides) {
  std::vector<int> far;
  for (size_t v = 0; v < original_.n_vertices(); ++v)
    if (original_.mean(v).x() == 1) far.push_back(int(v));
  ASSERT_EQ(far.size(), 4u);
  Events e;
  e.key("3").wait().click(pixel_at(far)).wait().key("ctrl+alt+m").wait();
  e.key("e").wait().text("0.5").wait().key("enter").wait().key("home").wait(3);
  play(e, "mirror_extruded.png");
  std::filesystem::remove(dir_.file("gpsurf/settings.json"));  // the modifier kept for the file: off again
  e.key("ctrl+alt+shift+m").wait(3);
  const CovarianceMesh saved = play(e);
  test::expect_closed_outward(saved, 20, 18);
  for (size_t v = 0; v < saved.n_vertices(); ++v) {
    const Vec3 image = saved.mean(v).cwiseProduct(Vec3(-1, 1, 1));
    size_t found = 0;
    for (size_t w = 0; w < saved.n_vertices(); ++w) found += (saved.mean(w) - image).norm() < 1e-12;
    EXPECT_EQ(found, 1u) << v;
    EXPECT_LE(std::abs(saved.mean(v).x()), 1.5 + 1e-12);
  }
}

// A face on the seam extruded with clipping on: its side along the plane is not made (as Blender's
// extrude leaves it out), so the seam stays open and the mirror goes on showing: applied, a closed part.
TEST_F(EditorToolsMirror, MirrorExtrudeOfAFaceOnTheSeamKeepsTheSeamOpen) {
  std::vector<int> top;
  for (size_t v = 0; v < original_.n_vertices(); ++v)
    if (original_.mean(v).y() == 1) top.push_back(int(v));
  ASSERT_EQ(top.size(), 4u);
  Events e;
  e.key("3").wait().click(pixel_at(top)).wait().key("ctrl+alt+m").wait();
  e.key("e").wait().text("0.5").wait().key("enter").wait().key("home").wait(3);
  const CovarianceMesh half = play(e, "mirror_extruded_on_the_seam.png");
  EXPECT_EQ(half.n_vertices(), 12u);
  EXPECT_EQ(half.n_faces(), 8u);  // the half's 5, the cap and 2 sides of the 3 it would have had
  EXPECT_NE(output_.find("1 face on the mirror plane left out (the seam stays open)"), std::string::npos) << output_;
  EXPECT_EQ(output_.find("lies on the mirror plane"), std::string::npos) << output_;
  std::filesystem::remove(dir_.file("gpsurf/settings.json"));
  e.key("ctrl+alt+shift+m").wait(3);
  test::expect_closed_outward(play(e), 18, 16);
}

// Clipping: G X 0.3 on a seam vertex and the far corner moves the corner by 0.3 and keeps the seam
// vertex on the plane (x = 0 exactly; its y and z as they were). The modifier is kept for the file:
// opened again it is on (the same move clipped) until Ctrl+Alt+M turns it off, and the seam vertex
// then leaves the plane.
TEST_F(EditorToolsMirror, MirrorClippingKeepsTheSeamOnThePlane) {
  const auto moved = [&](const std::string& keys, bool mirrored, const std::string& screenshot = "") {
    Events e;
    select(e, seam_, false, mirrored);
    select(e, corner_, true, mirrored);
    if (!keys.empty()) e.key(keys).wait();
    e.key("g").wait().key("x").wait().text("0.3").wait().key("enter").wait(3);
    return play(e, screenshot);
  };
  const auto expect_clipped = [&](const CovarianceMesh& saved) {
    EXPECT_EQ(saved.mean(size_t(seam_)), original_.mean(size_t(seam_)));
    EXPECT_NEAR(saved.mean(size_t(corner_)).x(), original_.mean(size_t(corner_)).x() + 0.3, 1e-12);
  };
  expect_clipped(moved("ctrl+alt+m", false, "mirror_clipped.png"));
  expect_clipped(moved("", true));
  const CovarianceMesh unclipped = moved("ctrl+alt+m", true);
  EXPECT_NEAR(unclipped.mean(size_t(seam_)).x(), 0.3, 1e-12);
  EXPECT_NEAR(unclipped.mean(size_t(corner_)).x(), original_.mean(size_t(corner_)).x() + 0.3, 1e-12);
  EXPECT_NE(output_.find("mirror modifier off"), std::string::npos) << output_;
}

// A designer's U-bracket from the half in 24 actions, with the modifier on and clipping at the seam:
// Ctrl+Alt+M; A, S Y 0.25 Enter (a plate), S X 2 Enter (stretched about the half's middle: clipping
// keeps the seam's vertices on the plane, where they would cross it); Home; face mode, the far face
// clicked, E 1 Enter (the plate lengthened); Home; the new part's top face clicked, E 1.5 Enter (an
// upright); Ctrl+Alt+Shift+M (applied); Home; the save. The file is core's mirror of the half so made:
// exactly symmetric about x = 0 (each vertex's image a vertex to 1e-12, with the mirrored Gaussian),
// the seam's four vertices on the plane once each, closed and outward.
TEST_F(EditorToolsMirror, DesignerReplayMirrorBracket) {
  std::vector<int> all(original_.n_vertices()), far;
  for (size_t v = 0; v < original_.n_vertices(); ++v) {
    all[v] = int(v);
    if (original_.mean(v).x() == 1) far.push_back(int(v));
  }
  ASSERT_EQ(far.size(), 4u);
  const Vec3 middle(0.5, 0, 0);
  const CovarianceMesh plate =
      transform_vertices(original_, all, AffineMap::about(middle, Vec3(1, 0.25, 1).asDiagonal())).mesh;
  CovarianceMesh stretched = transform_vertices(plate, all, AffineMap::about(middle, Vec3(2, 1, 1).asDiagonal())).mesh;
  for (size_t v = 0; v < plate.n_vertices(); ++v)
    if (plate.mean(v).x() == 0) stretched.set_mean(v, plate.mean(v));  // clipped: kept on the plane
  const CovarianceMesh longer = extrude_vertices(stretched, far, Vec3(1, 0, 0)).mesh;
  std::vector<int> outer_top;  // the top face of the part the extrusion added
  for (size_t v = 0; v < longer.n_vertices(); ++v)
    if (longer.mean(v).x() >= 1.5 && std::abs(longer.mean(v).y() - 0.25) < 1e-12) outer_top.push_back(int(v));
  ASSERT_EQ(outer_top.size(), 4u);
  const CovarianceMesh half = extrude_vertices(longer, outer_top, Vec3(0, 1.5, 0)).mesh;
  const Viewport stretched_view = editor_view(mirror(stretched, 0, Vec3::Zero(), true).mesh),
                 longer_view = editor_view(mirror(longer, 0, Vec3::Zero(), true).mesh);

  Events bracket;
  bracket.key("ctrl+alt+m").wait().key("a").wait();
  bracket.key("s").wait().key("y").wait().text("0.25").wait().key("enter").wait();
  bracket.key("s").wait().key("x").wait().text("2").wait().key("enter").wait().key("home").wait();
  bracket.key("3").wait().click(pixel_of(stretched_view, Vec3(1.5, 0, 0))).wait();
  bracket.key("e").wait().text("1").wait().key("enter").wait().key("home").wait();
  bracket.click(pixel_of(longer_view, Vec3(2, 0.25, 0))).wait();
  bracket.key("e").wait().text("1.5").wait().key("enter").wait();
  bracket.key("ctrl+alt+shift+m").wait().key("home").wait(3);
  const CovarianceMesh saved = play(bracket, "designer_mirror_bracket.png");
  EXPECT_NE(output_.find("mirror modifier on: the plane x = 0, clipping on"), std::string::npos) << output_;
  EXPECT_TRUE(test::nearly_same_mesh(saved, mirror(half, 0, Vec3::Zero(), true).mesh, 1e-12)) << output_;

  const test::Shape shape = test::shape_of(saved);
  EXPECT_EQ(shape.vertices, 2 * 16 - 4);  // the half's 16, mirrored, its 4 seam vertices shared
  EXPECT_EQ(shape.faces, 2 * 13);
  EXPECT_EQ(shape.boundary_edges, 0);
  EXPECT_TRUE(shape.oriented);
  EXPECT_EQ(shape.euler(), 2);
  EXPECT_GT(test::signed_volume(saved), 0.0);
  const Mat3 flip = Vec3(-1, 1, 1).asDiagonal();
  int on_seam = 0;
  for (size_t v = 0; v < saved.n_vertices(); ++v) {
    const Vec3 image = flip * saved.mean(v);
    int images = 0, near = 0;
    for (size_t w = 0; w < saved.n_vertices(); ++w) {
      near += w != v && (saved.mean(w) - saved.mean(v)).norm() < 1e-6;
      if ((saved.mean(w) - image).norm() > 1e-12) continue;
      ++images;
      EXPECT_LT((saved.covariance(w) - flip * saved.covariance(v) * flip).norm(), 1e-12) << v << " and " << w;
    }
    EXPECT_EQ(images, 1) << v;
    EXPECT_EQ(near, 0) << v << " has a duplicate";
    on_seam += saved.mean(v).x() == 0;
    EXPECT_LE(std::abs(saved.mean(v).x()), 2.5 + 1e-12);
    EXPECT_LE(saved.mean(v).y(), 1.75 + 1e-12);
  }
  EXPECT_EQ(on_seam, 4);
}

}  // namespace
}  // namespace gps
