// The editor as a modeller, end to end in a real window under Xvfb, driven as a designer would: a
// chisel from the cube and a screwdriver from the cylinder, each in a few operations (loop cut, box
// select, inset, extrude, modal scale with an axis and a typed value, the individual-origins pivot
// to sharpen), saved, reloaded and measured on the limit surface; every operation undone exactly
// (the file byte for byte, after a save too); values typed into the Inspector mirrored as drags are.
// Screenshots of the chisel and the screwdriver are kept in build/test-artefacts/EditorModelling/.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <functional>
#include <limits>

#include "../support/editor_driver.h"
#include "core/io/mesh_io.h"
#include "core/io/text_file.h"
#include "render/image/image_io.h"
#include "core/modelling/samples.h"
#include "core/modelling/affine_transform.h"
#include "core/modelling/extrude.h"
#include "core/modelling/inset.h"
#include "core/modelling/loop_cut.h"
#include "core/reference/reference_subdivision.h"
#include "view/camera.h"

namespace gps {
namespace {

using test::artefact;
using test::editor_view;
using test::Events;
using test::pixel_of;

constexpr int kWidth = test::kWindowWidth, kHeight = test::kWindowHeight;
// The Inspector's mean x field at its first-use place (as in test_editor_views.cpp).
const glm::vec2 kMeanX(700.0f, 72.0f);

// A modal transform with a typed value: S, then an axis ("" none), the value, Enter.
void transform(Events& events, const std::string& kind, const std::string& axis, const std::string& value) {
  events.key(kind);
  if (!axis.empty()) events.key(axis);
  events.text(value).key("enter").wait();
}

// A box (two corners) around the pixels of some points, `margin` pixels wider on every side.
std::pair<glm::vec2, glm::vec2> box_around(const Viewport& view, const std::vector<Vec3>& points, float margin) {
  glm::vec2 lo(1e9f), hi(-1e9f);
  for (const Vec3& p : points) {
    lo = glm::min(lo, pixel_of(view, p));
    hi = glm::max(hi, pixel_of(view, p));
  }
  return {lo - margin, hi + margin};
}

std::vector<Vec3> means_where(const CovarianceMesh& mesh, const std::function<bool(const Vec3&)>& keep) {
  std::vector<Vec3> out;
  for (size_t v = 0; v < mesh.n_vertices(); ++v)
    if (keep(mesh.mean(v))) out.push_back(mesh.mean(v));
  return out;
}

// Points of the limit surface (three Catmull-Clark levels projected to the limit).
std::vector<Vec3> limit_points(const CovarianceMesh& mesh) {
  SubdivisionOptions options;
  options.levels = 3;
  options.limit = true;
  const SubdivisionResult r = subdivide(mesh, options);
  std::vector<Vec3> points;
  for (size_t v = 0; v < r.mesh.n_vertices(); ++v) points.push_back(r.mesh.mean(v));
  return points;
}

// The extent along `axis` of the points whose height (y) lies in [lo, hi].
double extent(const std::vector<Vec3>& points, int axis, double lo, double hi) {
  double a = std::numeric_limits<double>::max(), b = -a;
  for (const Vec3& p : points)
    if (p.y() >= lo && p.y() <= hi) a = std::min(a, p[axis]), b = std::max(b, p[axis]);
  return b > a ? b - a : 0.0;
}

double max_height(const std::vector<Vec3>& points) {
  double top = -std::numeric_limits<double>::max();
  for (const Vec3& p : points) top = std::max(top, p.y());
  return top;
}

class EditorModelling : public ::testing::Test {
protected:
  void use_sample(const std::string& name) {
    write_mesh(dir_.file("original.ply"), make_sample(name));
    original_ = read_mesh(dir_.file("original.ply"));
  }
  test::CommandResult play(const Events& events, const std::string& extra, const std::string& file = "original.ply") {
    return test::play_editor(dir_, dir_.file(file), events, kWidth, kHeight, extra);
  }
  // Plays `events` and saves to `name`; returns the reloaded mesh.
  CovarianceMesh play_and_save(const Events& events, const std::string& name, const std::string& extra = "") {
    const auto r = play(events, "--save " + dir_.file(name) + " " + extra);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return read_mesh(dir_.file(name));
  }
  test::TempDir dir_;
  CovarianceMesh original_;
};

// The chisel's operations on the cube, as a designer does them.
Events chisel_events(const CovarianceMesh& cube) {
  const Viewport view = editor_view(cube);
  Events e;
  // 1. Ctrl+R on the front vertical edge, the wheel up once (two cuts), click, click (no slide):
  //    two loops around the cube.
  const glm::vec2 edge = pixel_of(view, 0.5 * (cube.mean(5) + cube.mean(6)));
  e.key("ctrl+r").move(edge).wait().scroll(edge, 1.0f).wait().click(edge).wait().click(edge).wait();
  // 2. A box around the top face's corners.
  const auto [lo, hi] = box_around(view, means_where(cube, [](const Vec3& p) { return p.y() > 0.99; }), 12.0f);
  e.key("escape").drag(lo, hi, 8).wait();
  // 3. S Z 0.1 Enter: the top thin across z (a wedge, its Gaussians flattened with it).
  transform(e, "s", "z", "0.1");
  // 4. Ctrl+. (individual origins), 5. S Shift+Z 0.1 Enter: each top Gaussian, flat across z since
  //    step 3, scaled across x and y about its own mean: round again and ten times sharper.
  e.key("ctrl+period").wait();
  transform(e, "s", "shift+z", "0.1");
  return e;  // 6. save (--save)
}

TEST_F(EditorModelling, AChiselFromTheCubeInSixOperations) {
  use_sample("cube");
  const CovarianceMesh chisel =
      play_and_save(chisel_events(original_), "chisel.ply", "--screenshot " + artefact("chisel.png"));
  EXPECT_EQ(chisel.n_vertices(), 16u) << "two loops of four added";
  EXPECT_EQ(chisel.n_faces(), 14u);
  // The top corners: thin across z, their Gaussians ten times sharper (σ 0.1 from 1).
  int top = 0;
  for (size_t v = 0; v < chisel.n_vertices(); ++v) {
    if (chisel.mean(v).y() < 0.99) continue;
    ++top;
    EXPECT_NEAR(std::abs(chisel.mean(v).z()), 0.1, 1e-6) << v;
    EXPECT_NEAR(std::abs(chisel.mean(v).x()), 1.0, 1e-6) << v;
    EXPECT_NEAR(chisel.covariance(v)(0, 0), 0.01, 1e-6) << v;
    EXPECT_NEAR(chisel.covariance(v)(1, 1), 0.01, 1e-6) << v;
    EXPECT_NEAR(chisel.covariance(v)(2, 2), 0.01, 1e-6) << v;
  }
  EXPECT_EQ(top, 4);
  // On the limit surface: near the top edge the chisel is far thinner across z than its body, and
  // about as wide across x.
  const std::vector<Vec3> limit = limit_points(chisel);
  const double height = max_height(limit);
  const double edge_z = extent(limit, 2, height - 0.1, height), body_z = extent(limit, 2, -0.5, 0.0);
  const double edge_x = extent(limit, 0, height - 0.1, height), body_x = extent(limit, 0, -0.5, 0.0);
  EXPECT_LT(edge_z, 0.2 * body_z) << "top " << edge_z << ", body " << body_z;
  EXPECT_GT(edge_x, 0.6 * body_x) << "top " << edge_x << ", body " << body_x;
}

// The screwdriver before its loop cut, as core's operations make it (the editor's steps 2-5), and
// its shaft edge nearest the camera (base on the inner cap's ring, tip on the blade).
struct ShaftEdge {
  CovarianceMesh mesh;
  int base = -1, tip = -1;
};
ShaftEdge front_shaft_edge(const CovarianceMesh& cylinder, const Viewport& view) {
  Modelled m = inset_faces(cylinder, {16}, 0.6);
  m = extrude_vertices(m.mesh, m.selection, Vec3::Zero());
  const std::vector<int> cap = m.selection;
  AffineMap up;
  up.translation = Vec3(0, 2.5, 0);
  m = transform_vertices(m.mesh, cap, up);
  m = transform_vertices(m.mesh, cap, AffineMap::about(Vec3::Zero(), Vec3(0.2, 1, 1).asDiagonal()));
  for (const int v : cap)
    m = transform_vertices(m.mesh, {v}, AffineMap::about(m.mesh.mean(size_t(v)), 0.3 * Mat3::Identity()));
  ShaftEdge out{m.mesh};
  const Vec3 eye = to_vec(view.camera.eye());
  double nearest = std::numeric_limits<double>::max();
  for (size_t e = 0; e < out.mesh.n_edges(); ++e) {
    auto [a, b] = out.mesh.edge(e);
    if (out.mesh.mean(size_t(a)).y() > out.mesh.mean(size_t(b)).y()) std::swap(a, b);
    const Vec3 p = out.mesh.mean(size_t(a)), q = out.mesh.mean(size_t(b));
    if (std::abs(p.y() - 1.0) > 1e-6 || std::abs(q.y() - 3.5) > 1e-6) continue;  // a shaft edge: base to tip
    if ((0.5 * (p + q) - eye).norm() < nearest) nearest = (0.5 * (p + q) - eye).norm(), out.base = a, out.tip = b;
  }
  return out;
}

// The screwdriver's operations on the cylinder (y up, the top cap face 16).
Events screwdriver_events(const CovarianceMesh& cylinder, int steps = 6) {
  const Viewport view = editor_view(cylinder);
  Events e;
  // 1. A box around the top cap's corners.
  const auto [lo, hi] = box_around(view, means_where(cylinder, [](const Vec3& p) { return p.y() > 0.99; }), 10.0f);
  e.drag(lo, hi, 8).wait();
  if (steps < 2) return e;
  // 2. I 0.6 Enter: an inner cap for the shaft.
  e.key("i").text("0.6").key("enter").wait();
  if (steps < 3) return e;
  // 3. E 2.5 Enter: the shaft, along the cap's normal.
  e.key("e").text("2.5").key("enter").wait();
  if (steps < 4) return e;
  // 4. S X 0.2 Enter: the blade flat across x.
  transform(e, "s", "x", "0.2");
  if (steps < 5) return e;
  // 5. Ctrl+. and S 0.3 Enter: the tip's Gaussians sharpened about their own means.
  e.key("ctrl+period").wait();
  transform(e, "s", "", "0.3");
  if (steps < 6) return e;
  // 6. Ctrl+R on the shaft's front edge, then a slide toward the handle: a loop that keeps the shaft
  //    round below it.
  const ShaftEdge edge = front_shaft_edge(cylinder, view);
  const std::array<Vec3, 2> front = {edge.mesh.mean(size_t(edge.base)), edge.mesh.mean(size_t(edge.tip))};
  const glm::vec2 middle = pixel_of(view, 0.5 * (front[0] + front[1]));
  const glm::vec2 slid = middle + 0.3f * (pixel_of(view, front[0]) - pixel_of(view, front[1]));
  e.key("ctrl+r").move(middle).wait().click(middle).wait().move(slid).wait().click(slid).wait();
  return e;  // 7. save (--save)
}

// An extrusion and its move are one operation, printed once.
TEST_F(EditorModelling, AnExtrudePrintsItsStatusOnce) {
  use_sample("cylinder");
  const auto r = play(screwdriver_events(original_, 3), "");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  size_t printed = 0;
  for (size_t at = r.output.find("extrude:"); at != std::string::npos; at = r.output.find("extrude:", at + 1))
    ++printed;
  EXPECT_EQ(printed, 1u) << r.output;
}

TEST_F(EditorModelling, AScrewdriverFromTheCylinder) {
  use_sample("cylinder");
  Events events = screwdriver_events(original_);
  events.key("home").wait(3);  // the shaft rises out of the first view: frame it all
  const CovarianceMesh driver = play_and_save(events, "screwdriver.ply", "--screenshot " + artefact("screwdriver.png"));
  // Inset (8 vertices, 8 faces), extrude (8, 8), loop cut around the shaft (8, 8).
  EXPECT_EQ(driver.n_vertices(), 24u + 24u);
  EXPECT_EQ(driver.n_faces(), 18u + 24u);
  const std::vector<Vec3> tip = means_where(driver, [](const Vec3& p) { return p.y() > 3.49; });
  ASSERT_EQ(tip.size(), 8u);
  for (const Vec3& p : tip) EXPECT_LT(std::abs(p.x()), 0.1) << "the blade is flat across x";
  const std::vector<Vec3> loop = means_where(driver, [](const Vec3& p) { return p.y() > 1.01 && p.y() < 3.49; });
  ASSERT_EQ(loop.size(), 8u);
  // The new vertices are 9D blends, drawn toward the blade's sharp Gaussians; the slide brings them
  // toward the handle from where an unslid cut puts them.
  const ShaftEdge edge = front_shaft_edge(original_, editor_view(original_));
  const double unslid = loop_cut(edge.mesh, edge.base, edge.tip).mesh.mean(edge.mesh.n_vertices()).y();
  for (const Vec3& p : loop) EXPECT_LT(p.y(), unslid - 0.05) << "the loop slid toward the handle";
  // On the limit surface: a tall handle, a thin shaft, a blade flat across x but wide across z.
  const std::vector<Vec3> limit = limit_points(driver);
  const double height = max_height(limit);
  EXPECT_GT(height, 3.0);
  const double handle = extent(limit, 2, -0.5, 0.0), shaft = extent(limit, 2, 1.4, 1.6);
  const double blade_x = extent(limit, 0, height - 0.15, height), blade_z = extent(limit, 2, height - 0.15, height);
  EXPECT_LT(shaft, 0.6 * handle) << "shaft " << shaft << ", handle " << handle;
  EXPECT_LT(blade_x, 0.5 * blade_z) << "blade " << blade_x << " by " << blade_z;
}

// Operations, their undo and their redo re-plan only what they change (core/plans/surface_replanner.h):
// the surface then shown is the one the saved result shows when opened afresh, the same pixels in the
// view once Home frames both alike (the selection cleared). A sphere of some thousand faces, so that
// most of its plans are kept through each operation. Uniform tessellation and no statistics in both
// runs (the View panel's settings are kept): adaptive levels keep a hysteresis of earlier views.
TEST_F(EditorModelling, AfterOperationsUndoAndRedoTheViewIsThatOfTheSavedMesh) {
  write_mesh(dir_.file("original.ply"), make_sample("sphere", 2000));
  original_ = read_mesh(dir_.file("original.ply"));
  const Viewport view = editor_view(original_);
  Vec3 low, high;
  bounding_box(original_, low, high);
  const glm::vec2 middle = pixel_of(view, 0.5 * (low + high));
  const glm::vec2 adaptive_box(692.0f, 291.0f), statistics_box(767.0f, 641.0f);
  Events e;
  e.click(adaptive_box).wait().click(statistics_box).wait();
  e.drag(middle - 40.0f, middle + 40.0f, 8).wait();         // the vertices in front
  e.key("e").text("0.2").key("enter").wait();               // extruded
  e.key("e").text("0.1").key("enter").wait();               // and its cap again
  e.key("ctrl+z").wait().key("ctrl+z").wait();              // both undone
  e.key("ctrl+shift+z").wait().key("ctrl+shift+z").wait();  // and redone
  e.key("escape").key("home").wait(3);
  const CovarianceMesh result = play_and_save(e, "result.ply", "--screenshot " + artefact("operations_redone.png"));
  ASSERT_GT(result.n_faces(), original_.n_faces() + 16) << "both extrusions are in the result";
  ASSERT_EQ(play(Events().key("home").wait(3), "--screenshot " + artefact("result_opened.png"), "result.ply").exit_code,
            0);
  const Image edited = read_image(artefact("operations_redone.png")),
              opened = read_image(artefact("result_opened.png"));
  ASSERT_EQ(edited.width, opened.width);
  ASSERT_EQ(edited.height, opened.height);
  const auto [lo, hi] = test::editor_free_region(kWidth, kHeight);
  long long differing = 0, surface = 0;
  for (int y = int(lo.y); y < int(hi.y); ++y)
    for (int x = int(lo.x); x < int(hi.x); ++x) {
      float most = 0.0f;
      for (int c = 0; c < 3; ++c) most = std::max(most, std::abs(edited.at(x, y, c) - opened.at(x, y, c)));
      differing += most > 2.0f / 255.0f;
      surface += opened.at(x, y, 0) != opened.at(0, int(lo.y), 0);
    }
  std::printf("%lld pixels differ of %lld that differ from the background's corner\n", differing, surface);
  EXPECT_GT(surface, 10000) << "the surface fills part of the view";
  EXPECT_LE(differing, 20);
}

// Each operation undone (Ctrl+Z) gives exactly the mesh before it: the file saved after k operations
// equals the file saved after all of them and the undo of the last ones, byte for byte.
TEST_F(EditorModelling, EveryOperationUndoesExactly) {
  use_sample("cylinder");
  const int kSteps = 6, kUndoSteps[] = {0, 0, 1, 2, 3, 4, 5};  // undo steps after k operations (box select: none)
  const Events all = screwdriver_events(original_, kSteps);
  for (int k = 1; k < kSteps; ++k) {
    play_and_save(screwdriver_events(original_, k), "prefix.ply");
    Events undone = all;
    for (int i = kUndoSteps[k]; i < kUndoSteps[kSteps]; ++i) undone.key("ctrl+z").wait();
    play_and_save(undone, "undone.ply");
    EXPECT_EQ(read_text_file(dir_.file("undone.ply")), read_text_file(dir_.file("prefix.ply")))
        << "after " << k << " operations";
  }
}

// Undo after a save, then save again: the original file, byte for byte; the saved file is the chisel.
TEST_F(EditorModelling, UndoAfterSaveGivesTheOriginalFile) {
  use_sample("cube");
  const Events chisel = chisel_events(original_);
  play_and_save(chisel, "chisel.ply");
  std::filesystem::copy_file(dir_.file("original.ply"), dir_.file("work.ply"));
  Events saved_then_undone = chisel;
  saved_then_undone.key("ctrl+s").wait();
  for (int i = 0; i < 3; ++i) saved_then_undone.key("ctrl+z").wait();  // S, S, loop cut
  const auto r = play(saved_then_undone, "--save " + dir_.file("undone.ply"), "work.ply");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(read_text_file(dir_.file("work.ply")), read_text_file(dir_.file("chisel.ply")));
  EXPECT_EQ(read_text_file(dir_.file("undone.ply")), read_text_file(dir_.file("original.ply")));
}

// A refused operation changes nothing and adds no undo step, and says why.
TEST_F(EditorModelling, ARefusedOperationChangesNothing) {
  use_sample("cube");
  const Viewport view = editor_view(original_);
  Events e;
  e.click(pixel_of(view, original_.mean(6))).wait().key("i").key("enter").wait();  // inset: no face selected
  e.key("ctrl+z").wait();                                                          // nothing to undo
  const auto r = play(e, "--save " + dir_.file("same.ply"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("inset refused"), std::string::npos) << r.output;
  EXPECT_EQ(read_text_file(dir_.file("same.ply")), read_text_file(dir_.file("original.ply")));
}

// G Z 1 Enter and R Z 90 Enter: exact moves and turns of the selection's Gaussians (μ′ = Aμ + t,
// Σ′ = AΣAᵀ), one undo step each.
TEST_F(EditorModelling, GrabAndRotateByTypedValues) {
  CovarianceMesh cube = make_sample("cube");
  cube.covariances[6] = Vec3(0.01, 0.04, 0.09).asDiagonal();
  write_mesh(dir_.file("original.ply"), cube);
  original_ = read_mesh(dir_.file("original.ply"));
  const Viewport view = editor_view(original_);
  Events e;
  e.click(pixel_of(view, original_.mean(6))).wait();
  transform(e, "g", "z", "1");
  transform(e, "r", "z", "90");
  const CovarianceMesh moved = play_and_save(e, "moved.ply");
  EXPECT_NEAR((moved.mean(6) - Vec3(1, 1, 2)).norm(), 0.0, 1e-6);
  EXPECT_NEAR(moved.covariance(6)(0, 0), 0.04, 1e-6) << "x and y swapped by the quarter turn";
  EXPECT_NEAR(moved.covariance(6)(1, 1), 0.01, 1e-6);
  EXPECT_NEAR(moved.covariance(6)(2, 2), 0.09, 1e-6);
  for (size_t v = 0; v < moved.n_vertices(); ++v) {
    if (v != 6) {
      EXPECT_EQ(moved.mean(v), original_.mean(v)) << v;
    }
  }
  Events undone = e;
  undone.key("ctrl+z").wait().key("ctrl+z").wait();
  play_and_save(undone, "undone.ply");
  EXPECT_EQ(read_text_file(dir_.file("undone.ply")), read_text_file(dir_.file("original.ply")));
}

// With "G/S/R carry the Gaussians" off (View panel, kept in the settings), S Z 0.5 on the whole cube
// halves its height and keeps every Gaussian as it was; on, the Gaussians are flattened with it.
TEST_F(EditorModelling, ScaleMovesThePositionsOnlyWhenTheGaussiansAreNotCarried) {
  use_sample("cube");
  for (const bool carried : {false, true}) {
    std::filesystem::create_directories(dir_.path() / "gpsurf");
    dir_.write("gpsurf/settings.json",
               carried ? R"({"transform_gaussians": true})" : R"({"transform_gaussians": false})");
    Events e;
    e.key("a").wait();
    transform(e, "s", "z", "0.5");
    const auto r = play(e, "--save " + dir_.file("scaled.ply"));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(r.output.find("positions only") != std::string::npos, !carried) << r.output;
    const CovarianceMesh scaled = read_mesh(dir_.file("scaled.ply"));
    for (size_t v = 0; v < scaled.n_vertices(); ++v) {
      EXPECT_NEAR(scaled.mean(v).z(), 0.5 * original_.mean(v).z(), 1e-9) << v;
      if (carried) {
        EXPECT_NEAR(scaled.covariance(v)(2, 2), 0.25 * original_.covariance(v)(2, 2), 1e-9) << v;
      } else {
        EXPECT_EQ(scaled.covariance(v), original_.covariance(v)) << v;
      }
    }
  }
}

// A value typed into the Inspector with mirror editing on moves the mirror vertex by the mirrored
// amount, as a drag does.
TEST_F(EditorModelling, TypedInspectorValuesMirrorLikeDrags) {
  use_sample("cube");
  const Viewport view = editor_view(original_);
  Events e;
  e.key("shift+m")
      .click(pixel_of(view, original_.mean(6)))
      .wait(3)
      .click(kMeanX)
      .wait(2)
      .text("1.25")
      .key("enter")
      .wait(2);
  const CovarianceMesh edited = play_and_save(e, "typed.ply");
  EXPECT_NEAR(edited.mean(6).x(), 1.25, 1e-6);
  EXPECT_NEAR(edited.mean(7).x(), -1.25, 1e-6) << "vertex 7 is vertex 6's mirror image across x = 0";
  EXPECT_EQ(edited.mean(7).y(), original_.mean(7).y());
  for (size_t v = 0; v < edited.n_vertices(); ++v) {
    if (v != 6 && v != 7) {
      EXPECT_EQ(edited.mean(v), original_.mean(v)) << v;
    }
  }
}

}  // namespace
}  // namespace gps

namespace gps {
namespace {

// Ctrl+E with two faces held in face mode deletes them and bridges the loops they leave, as Blender
// does: the cube's top and bottom faces alone give an open tube of four faces (the faces were kept,
// their vertices' loops bridged into a closed box).
TEST_F(EditorModelling, BridgeOfTwoFacesReplacesThemWithATube) {
  use_sample("cube");
  const MeshArrays cube = arrays_of(original_);
  const CovarianceMesh caps = make_covariance_mesh(cube.means, cube.covariances, {cube.faces[0], cube.faces[1]});
  write_mesh(dir_.file("caps.ply"), caps);
  const Viewport view = editor_view(caps);
  const auto centre = [&](int f) {
    Vec3 c = Vec3::Zero();
    for (const int v : cube.faces[size_t(f)]) c += cube.means[size_t(v)] / 4.0;
    return pixel_of(view, c);
  };
  Events e;
  e.key("3").wait().click(centre(1)).wait().click(centre(0), "shift").wait().key("ctrl+e").wait(2);
  const auto r = play(e, "--save " + dir_.file("tube.ply"), "caps.ply");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const CovarianceMesh tube = read_mesh(dir_.file("tube.ply"));
  EXPECT_EQ(tube.n_vertices(), 8u);
  EXPECT_EQ(tube.n_faces(), 4u) << r.output;
  const SurfaceCounts counts = surface_counts(tube.topology(), tube.connectivity());
  EXPECT_EQ(counts.boundary_loops, 2);
  EXPECT_EQ(counts.genus, 0);
}

// Ctrl+R takes typed numbers as Blender's loop cut does: the cuts before the click, the slide after it.
TEST_F(EditorModelling, LoopCutTakesTypedCutsAndSlide) {
  use_sample("cube");
  const Viewport view = editor_view(original_);
  const glm::vec2 edge = pixel_of(view, 0.5 * (original_.mean(5) + original_.mean(6)));
  Events e;
  e.key("ctrl+r").move(edge).wait().text("3").wait().click(edge).wait().text("0.5").wait().key("enter").wait(3);
  const CovarianceMesh cut = play_and_save(e, "cut.ply");
  ASSERT_EQ(cut.n_vertices(), 8u + 3 * 4);
  // The loops as a cut of 3 slid by half, one way or the other along the ring's first edge.
  bool matched = false;
  for (const double slide : {0.5, -0.5}) {
    const CovarianceMesh expected = loop_cut(original_, 5, 6, 3, slide).mesh;
    bool same = expected.n_vertices() == cut.n_vertices();
    for (size_t v = 0; v < cut.n_vertices() && same; ++v) same = (expected.mean(v) - cut.mean(v)).norm() < 1e-9;
    matched = matched || same;
  }
  EXPECT_TRUE(matched);
}

}  // namespace
}  // namespace gps
