// gpsurf-editor end to end, in a real window (ctest runs this under Xvfb, on Mesa): replayed
// input selects a vertex and drags one of its axis ends; the saved file shows exactly that change;
// undo restores the original file byte for byte; the screenshot shows the surface and the UI; a
// malformed file dropped on the window is reported and the mesh stays.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <filesystem>
#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "../support/editor_driver.h"
#include "core/io/mesh_io.h"
#include "core/io/text_file.h"
#include "core/modelling/samples.h"
#include "render/image/image_io.h"
#include "view/picking.h"
#include "ui/editing/axis_handles.h"
#include "ui/panels/view_options.h"

namespace gps {
namespace {

constexpr int kWidth = test::kWindowWidth, kHeight = test::kWindowHeight;
constexpr int kVertex = 6;  // the cube's (1, 1, 1) corner, in front for the default camera

using test::editor_view;
using test::pixel_of;
using test::point;
std::string editor(const std::string& args) { return test::editor_command(args); }

// The cube with an anisotropic, turned Gaussian at the edited corner.
CovarianceMesh test_mesh() {
  CovarianceMesh mesh = make_sample("cube");
  const Mat3 r = Eigen::AngleAxisd(0.5, Vec3(1, -2, 0.5).normalized()).toRotationMatrix();
  mesh.covariances[kVertex] = r * Vec3(0.004, 0.02, 0.06).asDiagonal() * r.transpose();
  return mesh;
}

struct DragPlan {
  int axis = 0;
  double factor = 2.0;
  std::string events;  // the JSON array items: click the vertex, drag the axis end
};

// Clicks the vertex, then drags the end of its longest on-screen axis outward to `factor` times
// its distance from the centre (so σ of that axis should grow by `factor`).
DragPlan plan_drag(const CovarianceMesh& mesh, double factor) {
  const Viewport view = editor_view(mesh);
  const HandleFrame f = handle_frame(mesh, kVertex, ViewOptions{}.draw.sigma_scale, view);
  DragPlan plan;
  plan.factor = factor;
  float longest = 0.0f;
  for (int a = 0; a < 3; ++a) {
    const float length = glm::length(pixel_of(view, f.end(a, 1)) - pixel_of(view, f.centre));
    if (length > longest) longest = length, plan.axis = a;
  }
  EXPECT_GT(longest, 20.0f);
  const Vec3 end = f.end(plan.axis, 1), goal = f.centre + factor * (end - f.centre);
  plan.events = R"({"type": "click", "x": )" + std::to_string(pixel_of(view, f.centre).x) + R"(, "y": )" +
                std::to_string(pixel_of(view, f.centre).y) + "},\n" + R"({"type": "wait", "frames": 2},)" + "\n" +
                R"({"type": "drag", "from": )" + point(pixel_of(view, end)) + R"(, "to": )" +
                point(pixel_of(view, goal)) + R"(, "steps": 6},)" + "\n" + R"({"type": "wait", "frames": 2})";
  return plan;
}

Vec3 sigmas_along(const Mat3& c, const Mat3& axes) {
  Vec3 s;
  for (int a = 0; a < 3; ++a) s[a] = std::sqrt(axes.col(a).dot(c * axes.col(a)));
  return s;
}

class EditorTest : public ::testing::Test {
protected:
  void SetUp() override {
    original_ = test_mesh();
    write_mesh(dir_.file("original.ply"), original_);
  }
  test::CommandResult play(const std::string& events_items, const std::string& extra) {
    const std::string events = dir_.write("events.json", "{\"events\": [\n" + events_items + "\n]}\n");
    // The recent-files list goes to the test's folder, not the user's.
    return test::run_command("XDG_CONFIG_HOME=" + dir_.path().string() + " " +
                             editor(dir_.file("original.ply") + " --size " + std::to_string(kWidth) + "x" +
                                    std::to_string(kHeight) + " --play " + events + " " + extra));
  }
  test::TempDir dir_;
  CovarianceMesh original_;
};

TEST_F(EditorTest, DraggingAnAxisEndScalesThatSigmaAndNothingElse) {
  const DragPlan plan = plan_drag(original_, 2.0);
  const auto r = play(plan.events, "--save " + dir_.file("edited.ply") + " --screenshot " + dir_.file("shot.png"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const CovarianceMesh edited = read_mesh(dir_.file("edited.ply"));
  ASSERT_EQ(edited.n_vertices(), original_.n_vertices());
  // The dragged σ doubled (within 1%), the other two did not change, the axes kept their directions.
  const EllipsoidAxes before = ellipsoid_axes(original_.covariance(kVertex));
  const Vec3 after = sigmas_along(edited.covariance(kVertex), before.axes);
  for (int a = 0; a < 3; ++a) {
    const double expected = before.sigmas[a] * (a == plan.axis ? plan.factor : 1.0);
    EXPECT_NEAR(after[a], expected, 0.01 * expected) << "axis " << a << " (dragged " << plan.axis << ")";
  }
  const Vec3 eig = Eigen::SelfAdjointEigenSolver<Mat3>(edited.covariance(kVertex)).eigenvalues().cwiseSqrt();
  Vec3 expected = before.sigmas;
  expected[plan.axis] *= plan.factor;
  std::sort(expected.data(), expected.data() + 3);
  EXPECT_LT((eig - expected).cwiseAbs().maxCoeff(), 0.01 * expected.maxCoeff());
  // Nothing else changed: every other Gaussian, and this vertex's mean, exactly as saved before.
  EXPECT_EQ(edited.mean(kVertex), original_.mean(kVertex));
  for (size_t v = 0; v < edited.n_vertices(); ++v) {
    if (int(v) == kVertex) continue;
    EXPECT_EQ(edited.mean(v), original_.mean(v)) << v;
    EXPECT_EQ(edited.covariance(v), original_.covariance(v)) << v;
  }

  // The screenshot shows the UI (the menu bar across the top, the status bar at the bottom) and
  // the shaded surface over the editor's background in the middle.
  const Image shot = read_image(dir_.file("shot.png"));
  ASSERT_EQ(shot.width, kWidth);
  ASSERT_EQ(shot.height, kHeight);
  const auto rgb = [&shot](int x, int y) { return glm::vec3(shot.at(x, y, 0), shot.at(x, y, 1), shot.at(x, y, 2)); };
  const glm::vec3 menu = rgb(kWidth / 2, 6), background(0.23f, 0.24f, 0.26f);
  int menu_row = 0, status_row = 0;
  for (int x = 0; x < kWidth; ++x) {
    menu_row += glm::length(rgb(x, 6) - menu) < 0.02f;
    status_row += glm::length(rgb(x, kHeight - 4) - background) > 0.05f;
  }
  EXPECT_GT(menu_row, kWidth * 8 / 10) << "no menu bar";
  EXPECT_GT(glm::length(menu - background), 0.05f);
  EXPECT_GT(status_row, kWidth * 8 / 10) << "no status bar";
  // The clay MatCap is warm (red over blue) where neither the grey background nor the UI is.
  int warm = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) warm += rgb(x, y).r - rgb(x, y).b > 0.06f && rgb(x, y).r > rgb(x, y).g;
  EXPECT_GT(warm, kWidth * kHeight / 50) << "the surface is not drawn";
}

TEST_F(EditorTest, UndoAfterTheDragRestoresTheOriginalFileExactly) {
  const DragPlan plan = plan_drag(original_, 1.7);
  const auto r = play(plan.events + ",\n" + R"({"type": "key", "key": "ctrl+z"}, {"type": "wait", "frames": 2})",
                      "--save " + dir_.file("undone.ply"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(read_text_file(dir_.file("undone.ply")), read_text_file(dir_.file("original.ply")));
  // And redo brings the drag back.
  const auto redo =
      play(plan.events + ",\n" + R"({"type": "key", "key": "ctrl+z"}, {"type": "key", "key": "ctrl+shift+z"})",
           "--save " + dir_.file("redone.ply"));
  ASSERT_EQ(redo.exit_code, 0) << redo.output;
  EXPECT_NE(read_text_file(dir_.file("redone.ply")), read_text_file(dir_.file("original.ply")));
  EXPECT_NE(read_mesh(dir_.file("redone.ply")).covariance(kVertex), original_.covariance(kVertex));
}

TEST_F(EditorTest, AMalformedFileIsReportedAndTheMeshStays) {
  const std::string bad =
      dir_.write("broken.ply", "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nend_header\n1\n");
  const auto r = play(R"({"type": "drop", "paths": [")" + bad + R"("]}, {"type": "wait", "frames": 2})",
                      "--save " + dir_.file("kept.ply") + " --screenshot " + dir_.file("error.png"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("broken.ply"), std::string::npos) << r.output;
  EXPECT_EQ(read_text_file(dir_.file("kept.ply")), read_text_file(dir_.file("original.ply")));
  // The error is on screen: red text in the status bar.
  const Image shot = read_image(dir_.file("error.png"));
  int red = 0;
  for (int y = shot.height - 24; y < shot.height; ++y)
    for (int x = 0; x < shot.width; ++x)
      red += shot.at(x, y, 0) > 0.8f && shot.at(x, y, 1) < 0.5f && shot.at(x, y, 2) < 0.5f;
  EXPECT_GT(red, 50) << "no error shown in the status bar";
}

// A closed pillow of two faces (which Loop's refinement cannot keep manifold) dropped on the window:
// refused at load, named, and the editor keeps its mesh and runs on.
TEST_F(EditorTest, AMeshNoSchemeCanRefineIsRefusedAndTheMeshStays) {
  const std::string pillow = dir_.write("pillow.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 3 2\n");
  const auto r = play(R"({"type": "drop", "paths": [")" + pillow + R"("]}, {"type": "wait", "frames": 2})",
                      "--save " + dir_.file("kept.ply"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("pillow.obj: 1 duplicate face"), std::string::npos) << r.output;
  EXPECT_EQ(read_text_file(dir_.file("kept.ply")), read_text_file(dir_.file("original.ply")));
}

TEST_F(EditorTest, OpeningAnotherMeshWithUnsavedChangesAsksFirst) {
  write_mesh(dir_.file("other.ply"), make_sample("torus"));
  const DragPlan plan = plan_drag(original_, 1.5);
  // Drop another mesh after the drag: the editor asks and holds the open back; Escape cancels.
  const auto r =
      play(plan.events + ",\n" + R"({"type": "drop", "paths": [")" + dir_.file("other.ply") +
               R"("]}, {"type": "wait", "frames": 3}, {"type": "key", "key": "escape"}, {"type": "wait", "frames": 2})",
           "--save " + dir_.file("still.ply"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const CovarianceMesh still = read_mesh(dir_.file("still.ply"));
  EXPECT_EQ(still.n_vertices(), original_.n_vertices());
  EXPECT_NE(still.covariance(kVertex), original_.covariance(kVertex));  // the edit is still there
  // Without changes the same drop opens the other mesh at once.
  const auto clean =
      play(R"({"type": "drop", "paths": [")" + dir_.file("other.ply") + R"("]}, {"type": "wait", "frames": 2})",
           "--save " + dir_.file("opened.ply"));
  ASSERT_EQ(clean.exit_code, 0) << clean.output;
  EXPECT_EQ(read_mesh(dir_.file("opened.ply")).n_vertices(), make_sample("torus").n_vertices());
}

// The statistics name the mesh the editor opened, and the file a scripted save wrote beside it (the
// save makes that file the document's, but it is not what was measured).
TEST_F(EditorTest, StatisticsNameTheOpenedMeshAndTheSavedFile) {
  const auto r = play(R"({"type": "wait", "frames": 2})",
                      "--save " + dir_.file("saved.ply") + " --stats " + dir_.file("stats.json"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json stats = nlohmann::json::parse(read_text_file(dir_.file("stats.json")));
  EXPECT_EQ(stats.at("mesh").get<std::string>(), "original.ply");
  EXPECT_EQ(stats.value("saved", ""), dir_.file("saved.ply"));
  EXPECT_EQ(stats.at("faces").get<int>(), int(original_.n_faces()));
}

// An idle window keeps the surface it drew and draws only its UI; a change of view after idling is
// drawn at once: the window after it equals, pixel for pixel, one that changed the view first.
TEST_F(EditorTest, AnIdleWindowKeepsItsSurfaceAndDrawsTheNextChange) {
  std::filesystem::create_directories(dir_.path() / "gpsurf");
  dir_.write("gpsurf/settings.json", R"({"show_statistics": false})");  // its figures differ run to run
  const std::string idle = R"({"type": "wait", "frames": 30})";
  const std::string front = R"({"type": "key", "key": "kp1"}, {"type": "wait", "frames": 1})";
  const auto idled =
      play(idle + ", " + front, "--screenshot " + dir_.file("idled.png") + " --stats " + dir_.file("s.json"));
  ASSERT_EQ(idled.exit_code, 0) << idled.output;
  const nlohmann::json stats = nlohmann::json::parse(read_text_file(dir_.file("s.json")));
  EXPECT_GE(stats.at("kept_frames").get<int>(), 25) << "idle frames drew the surface again";
  const auto direct = play(front, "--screenshot " + dir_.file("direct.png"));
  ASSERT_EQ(direct.exit_code, 0) << direct.output;
  const auto unturned = play(idle, "--screenshot " + dir_.file("unturned.png"));
  ASSERT_EQ(unturned.exit_code, 0) << unturned.output;
  const Image shot = read_image(dir_.file("idled.png"));
  EXPECT_EQ(shot.pixels, read_image(dir_.file("direct.png")).pixels);
  EXPECT_NE(shot.pixels, read_image(dir_.file("unturned.png")).pixels) << "the front view changed nothing";
}

TEST(EditorCommandLine, BadInputIsOneLineAndNonZero) {
  const test::TempDir dir;
  const std::string bad = dir.write("bad.ply", "ply\nformat ascii 1.0\nelement vertex 1\nend_header\n");
  const auto r = test::run_command(editor(bad + " --screenshot " + dir.file("x.png")));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("bad.ply"), std::string::npos);
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  // A mesh that reads but that the plans refuse (a face of more sides than they handle): the message
  // names the file too, and the face as the file numbers it.
  std::string wide = "";
  for (int k = 0; k < 300; ++k)
    wide += "v " + std::to_string(std::cos(k * 2 * M_PI / 300)) + " " + std::to_string(std::sin(k * 2 * M_PI / 300)) +
            " 0\n";
  wide += "f";
  for (int k = 1; k <= 300; ++k) wide += " " + std::to_string(k);
  const auto sides =
      test::run_command(editor(dir.write("wide.obj", wide + "\n") + " --screenshot " + dir.file("x.png")));
  EXPECT_EQ(sides.exit_code, 1) << sides.output;
  EXPECT_NE(sides.output.find("wide.obj: face 1 (line 301) has 300 sides"), std::string::npos) << sides.output;
  const std::string events = dir.write("e.json", R"({"events": [{"type": "hop"}]})");
  const auto e = test::run_command(editor("--play " + events));
  EXPECT_EQ(e.exit_code, 2) << e.output;
  EXPECT_NE(e.output.find("e.json: event 0: unknown type 'hop'"), std::string::npos) << e.output;
  EXPECT_EQ(test::run_command(editor("--size 12")).exit_code, 2);
  // A file that is not there, and a choice not among the choices, in our words (CLI11's were shown).
  const auto gone = test::run_command(editor(dir.file("gone.ply")));
  EXPECT_EQ(gone.exit_code, 1) << gone.output;
  EXPECT_EQ(gone.output, "gpsurf-editor: " + dir.file("gone.ply") + ": no such file\n");
  const auto scheme = test::run_command(editor("--scheme foo"));
  EXPECT_EQ(scheme.exit_code, 2) << scheme.output;
  EXPECT_EQ(scheme.output, "gpsurf-editor: --scheme: expected one of auto, loop, catmull-clark, got 'foo'\n");
}

}  // namespace
}  // namespace gps
