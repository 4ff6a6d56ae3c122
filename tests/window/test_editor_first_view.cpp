// The editor's first view and its repair prompt, in a real window under Xvfb: the mesh framed in the
// part of the window the panels leave free; the View panel's every row on screen for a triangle mesh;
// --up kept for the file; a mesh with a pinch vertex, opened or dropped, shown with what is wrong and
// opened repaired (unsaved) or not at all, the editor running on; --repair and --weld on the command
// line; a file that does not open leaving the default sample and its error. Screenshots kept in
// build/test-artefacts/EditorFirstView/.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "../support/editor_driver.h"
#include "../support/pinched_mesh.h"
#include "core/io/mesh_io.h"
#include "core/io/text_file.h"
#include "core/modelling/samples.h"
#include "render/image/image_io.h"

namespace gps {
namespace {

using test::artefact;
constexpr int kWidth = test::kWindowWidth, kHeight = test::kWindowHeight;
const glm::vec3 kBackground(0.23f, 0.24f, 0.26f);  // ViewOptions' viewport colour

using test::kPinchedObj;  // a pinch vertex, refused as read

class EditorFirstView : public ::testing::Test {
protected:
  test::CommandResult run(const std::string& mesh_file, const test::Events& events, const std::string& extra) const {
    return test::play_editor(dir_, mesh_file, events, kWidth, kHeight, extra + " --stats " + dir_.file("stats.json"));
  }
  nlohmann::json stats() const { return nlohmann::json::parse(read_text_file(dir_.file("stats.json"))); }
  void write_settings(const std::string& json) const {
    std::filesystem::create_directories(dir_.path() / "gpsurf");
    dir_.write("gpsurf/settings.json", json);
  }
  test::TempDir dir_;
};

// The window pixels that are not the viewport's background, inside [lo, hi): their bounding box.
std::pair<glm::vec2, glm::vec2> drawn_box(const Image& shot, glm::vec2 lo, glm::vec2 hi) {
  glm::vec2 a(1e9f), b(-1e9f);
  for (int y = int(lo.y); y < int(hi.y); ++y)
    for (int x = int(lo.x); x < int(hi.x); ++x)
      if (glm::length(glm::vec3(shot.at(x, y, 0), shot.at(x, y, 1), shot.at(x, y, 2)) - kBackground) > 0.05f) {
        a = glm::min(a, glm::vec2(x, y));
        b = glm::max(b, glm::vec2(x + 1, y + 1));
      }
  return {a, b};
}

TEST_F(EditorFirstView, TheMeshIsFramedWhereThePanelsLeaveRoom) {
  write_mesh(dir_.file("cone.ply"), make_sample("cone-pointy"));
  write_settings(R"({"show_statistics": false})");
  const auto r = run(dir_.file("cone.ply"), test::Events().wait(1), "--screenshot " + artefact("first_view.png"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto [free_min, free_max] = test::editor_free_region();
  const auto region = stats()["free_region"];
  EXPECT_EQ(glm::vec2(region[0], region[1]), free_min) << "the panels' first-use places moved: update editor_driver.h";
  EXPECT_EQ(glm::vec2(region[2], region[3]), free_max);
  // The surface and its base mesh drawn inside the free region, filling most of it along one axis
  // and about centred in it.
  const Image shot = read_image(artefact("first_view.png"));
  const auto [lo, hi] = drawn_box(shot, free_min, free_max);
  ASSERT_LT(lo.x, hi.x) << "nothing drawn";
  EXPECT_GT(lo.x, free_min.x + 2.0f);
  EXPECT_GT(lo.y, free_min.y + 2.0f);
  EXPECT_LT(hi.x, free_max.x - 2.0f);
  EXPECT_LT(hi.y, free_max.y - 2.0f);
  const glm::vec2 size = hi - lo, room = free_max - free_min;
  EXPECT_GT(std::max(size.x / room.x, size.y / room.y), 0.85f);
  EXPECT_LT(glm::length(0.5f * (lo + hi) - 0.5f * (free_min + free_max)), 0.1f * room.y);
}

// A triangle mesh adds the scheme's rows to the View panel: it grows, and stays above the status bar.
TEST_F(EditorFirstView, TheViewPanelShowsEveryRowForATriangleMesh) {
  write_mesh(dir_.file("quads.ply"), make_sample("cube"));
  write_mesh(dir_.file("triangles.ply"), make_sample("icosphere"));
  ASSERT_EQ(run(dir_.file("quads.ply"), test::Events().wait(1), "").exit_code, 0);
  const float quads_height = stats()["panels"]["View"][3];
  // Opened after the quads, the panel keeps the place it had (imgui.ini) and grows.
  const auto r = run(dir_.file("triangles.ply"), test::Events().wait(1), "--screenshot " + artefact("view_panel.png"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto panel = stats()["panels"]["View"];
  EXPECT_GT(float(panel[3]), quads_height + 20.0f);
  EXPECT_LE(float(panel[1]) + float(panel[3]), float(test::editor_free_region().second.y) + 4.0f)
      << "the View panel runs under the status bar";
}

// --up z turns the view and is kept for the file: the next run without it shows the same picture;
// another folder's settings (none kept) show the y-up view.
TEST_F(EditorFirstView, TheUpAxisIsKeptForTheFile) {
  write_mesh(dir_.file("cylinder.ply"), make_sample("cylinder"));
  write_settings(R"({"show_statistics": false})");
  ASSERT_EQ(
      run(dir_.file("cylinder.ply"), test::Events().wait(1), "--up z --screenshot " + artefact("up_z.png")).exit_code,
      0);
  EXPECT_NE(read_text_file(dir_.file("gpsurf/settings.json")).find("cylinder.ply\": 2"), std::string::npos);
  ASSERT_EQ(run(dir_.file("cylinder.ply"), test::Events().wait(1), "--screenshot " + artefact("up_kept.png")).exit_code,
            0);
  write_settings(R"({"show_statistics": false})");
  ASSERT_EQ(run(dir_.file("cylinder.ply"), test::Events().wait(1), "--screenshot " + artefact("up_y.png")).exit_code,
            0);
  const Image z = read_image(artefact("up_z.png")), kept = read_image(artefact("up_kept.png")),
              y = read_image(artefact("up_y.png"));
  EXPECT_EQ(z.pixels, kept.pixels);
  EXPECT_NE(z.pixels, y.pixels);
}

// Opened from the command line, the pinched mesh is not refused: the default sample shows under a
// dialog naming the pinch vertex; Enter (Repair) opens it repaired and unsaved.
TEST_F(EditorFirstView, APinchedMeshOpenedIsOfferedRepaired) {
  const std::string pinched = dir_.write("pinched.obj", kPinchedObj);
  const auto asked = run(pinched, test::Events().wait(2), "--screenshot " + artefact("repair_dialog.png"));
  ASSERT_EQ(asked.exit_code, 0) << asked.output;
  EXPECT_NE(stats()["mesh"].get<std::string>(), "pinched.obj");
  // A save of it while the sample stands in its place is refused, nothing written.
  const auto unsaved = run(pinched, test::Events().wait(2), "--save " + dir_.file("never.ply"));
  EXPECT_EQ(unsaved.exit_code, 1) << unsaved.output;
  EXPECT_NE(unsaved.output.find("pinch"), std::string::npos) << unsaved.output;
  EXPECT_FALSE(std::filesystem::exists(dir_.file("never.ply")));
  const auto repaired =
      run(pinched, test::Events().wait(2).key("enter").wait(3), "--screenshot " + artefact("repaired.png"));
  ASSERT_EQ(repaired.exit_code, 0) << repaired.output;
  const nlohmann::json s = stats();
  EXPECT_EQ(s["mesh"], "pinched.obj");
  EXPECT_EQ(s["faces"], 10);
  EXPECT_EQ(s["unsaved"], true);
  EXPECT_NE(repaired.output.find("repaired (unsaved)"), std::string::npos) << repaired.output;
  const auto saved = run(pinched, test::Events().wait(2).key("enter").wait(3), "--save " + dir_.file("mended.ply"));
  ASSERT_EQ(saved.exit_code, 0) << saved.output;
  EXPECT_EQ(read_mesh(dir_.file("mended.ply")).n_vertices(), read_mesh(pinched,
                                                                       [] {
                                                                         ImportOptions o;
                                                                         o.repair = true;
                                                                         return o;
                                                                       }())
                                                                 .n_vertices());
}

// Dropped on the window, the same: Cancel keeps the mesh there was, Repair opens the repaired one.
TEST_F(EditorFirstView, APinchedMeshDroppedIsRepairedOrLeft) {
  write_mesh(dir_.file("cube.ply"), make_sample("cube"));
  const std::string pinched = dir_.write("pinched.obj", kPinchedObj);
  const std::string drop = R"({"type": "drop", "paths": [")" + pinched + R"("]})";
  const auto cancelled = run(dir_.file("cube.ply"), test::Events().add(drop).wait(2).key("escape").wait(2), "");
  ASSERT_EQ(cancelled.exit_code, 0) << cancelled.output;
  EXPECT_EQ(stats()["mesh"], "cube.ply");
  EXPECT_EQ(stats()["unsaved"], false);
  const auto repaired = run(dir_.file("cube.ply"), test::Events().add(drop).wait(2).key("enter").wait(3),
                            "--screenshot " + artefact("dropped_repaired.png"));
  ASSERT_EQ(repaired.exit_code, 0) << repaired.output;
  EXPECT_EQ(stats()["mesh"], "pinched.obj");
  EXPECT_EQ(stats()["faces"], 10);
  EXPECT_EQ(stats()["unsaved"], true);
}

// A scan's faults (18 duplicate vertices in 9 zero-area faces, a pinch vertex): --repair on the command
// line opens it repaired and unsaved, the status line saying what the repair did; --weld F the same.
TEST_F(EditorFirstView, AMeshTheRepairMendsOpensWithRepair) {
  const std::string scan = dir_.write("scan.obj", test::pinched_scan_obj());
  for (const std::string& option : {std::string("--repair"), std::string("--weld 1e-6")}) {
    SCOPED_TRACE(option);
    const auto r =
        run(scan, test::Events().wait(2), option + " --screenshot " + artefact("scan_repaired_on_start.png"));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const nlohmann::json s = stats();
    EXPECT_EQ(s["mesh"], "scan.obj");
    EXPECT_EQ(s["faces"], 10);
    EXPECT_EQ(s["unsaved"], true);
    EXPECT_NE(r.output.find("repaired (unsaved): welded 26 coincident vertices into 8; dropped 9 zero-area faces; "
                            "split 1 pinch vertex"),
              std::string::npos)
        << r.output;
  }
}

// Without --repair the same scan is not refused: the default sample shows under the repair dialog,
// which lists every class the repair mends (the pinch, the coincident vertices, the zero-area faces),
// and Enter opens the repaired mesh.
TEST_F(EditorFirstView, AMeshTheRepairMendsReachesTheRepairDialog) {
  const std::string scan = dir_.write("scan.obj", test::pinched_scan_obj());
  const auto asked = run(scan, test::Events().wait(2), "--screenshot " + artefact("scan_repair_dialog.png"));
  ASSERT_EQ(asked.exit_code, 0) << asked.output;
  EXPECT_EQ(stats()["mesh"], "sample cone-pointy");
  EXPECT_NE(asked.output.find("scan.obj: 1 non-manifold (pinch) vertex, vertex 1 (line 1) with 2 fans"),
            std::string::npos)
      << asked.output;
  const auto repaired = run(scan, test::Events().wait(2).key("enter").wait(3), "");
  ASSERT_EQ(repaired.exit_code, 0) << repaired.output;
  EXPECT_EQ(stats()["mesh"], "scan.obj");
  EXPECT_EQ(stats()["faces"], 10);
  EXPECT_EQ(stats()["unsaved"], true);
}

// A cube torn open at a seam (vertex 9 repeats vertex 1; the top uses it) opens as read, and the same
// dialog asks: Esc keeps it as read (9 vertices), Enter opens it repaired (8), as `info` promises.
TEST_F(EditorFirstView, AMeshThatOpensTornIsOfferedRepaired) {
  const std::string torn = dir_.write("torn.obj",
                                      "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\n"
                                      "v -1 1 1\nv -1 -1 -1\nf 1 4 3 2\nf 5 6 7 8\nf 9 2 6 5\nf 2 3 7 6\nf 3 4 8 7\n"
                                      "f 4 1 5 8\n");
  const auto kept = run(torn, test::Events().wait(2).key("escape").wait(2),
                        "--screenshot " + artefact("torn_kept.png") + " --save " + dir_.file("kept.ply"));
  ASSERT_EQ(kept.exit_code, 0) << kept.output;
  EXPECT_EQ(stats()["mesh"], "torn.obj");
  EXPECT_EQ(read_mesh(dir_.file("kept.ply")).n_vertices(), 9u);
  const auto asked = run(torn, test::Events().wait(2), "--screenshot " + artefact("torn_dialog.png"));
  ASSERT_EQ(asked.exit_code, 0) << asked.output;
  const auto repaired = run(torn, test::Events().wait(2).key("enter").wait(3), "--save " + dir_.file("mended.ply"));
  ASSERT_EQ(repaired.exit_code, 0) << repaired.output;
  EXPECT_NE(repaired.output.find("repaired (unsaved)"), std::string::npos) << repaired.output;
  EXPECT_EQ(read_mesh(dir_.file("mended.ply")).n_vertices(), 8u);
}

// A file that does not open and that no repair mends does not end an interactive session: the default
// sample shows with the error in the status line. A run that must write a screenshot of it still
// fails (exit 1, one line).
TEST_F(EditorFirstView, AMeshThatCannotOpenLeavesTheSampleAndItsError) {
  const std::string bad = dir_.write("bad.ply", "ply\nformat ascii 1.0\nelement vertex 1\nend_header\n");
  const auto shown = run(bad, test::Events().wait(2), "");
  ASSERT_EQ(shown.exit_code, 0) << shown.output;
  EXPECT_EQ(stats()["mesh"], "sample cone-pointy");
  EXPECT_NE(shown.output.find("bad.ply: "), std::string::npos) << shown.output;
  const auto repaired = run(bad, test::Events().wait(2), "--repair");
  ASSERT_EQ(repaired.exit_code, 0) << repaired.output;
  EXPECT_EQ(stats()["mesh"], "sample cone-pointy");
  const auto scripted = run(bad, test::Events().wait(2), "--screenshot " + artefact("unused.png"));
  EXPECT_EQ(scripted.exit_code, 1) << scripted.output;
}

}  // namespace
}  // namespace gps
