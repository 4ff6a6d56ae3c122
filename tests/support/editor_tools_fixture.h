#pragma once
// The window tests of the modal tools (tests/window/test_editor_tools.cpp, test_editor_snapping.cpp,
// test_editor_mirror.cpp): the cube (or a mesh of the test's) saved as original.ply, the editor
// played on it under Xvfb with events, the result saved and read back to compare with core's
// operation on the file as opened.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/io/mesh_io.h"
#include "core/io/text_file.h"
#include "core/modelling/bevel.h"
#include "core/modelling/mesh_queries.h"
#include "core/modelling/samples.h"
#include "tests/support/editor_driver.h"
#include "tests/support/mesh_checks.h"
#include "tests/support/test_meshes.h"
#include "tests/support/bevel_width.h"

namespace gps::test {

constexpr int kWidth = kWindowWidth, kHeight = kWindowHeight;

class EditorTools : public ::testing::Test {
protected:
  void use_mesh(const CovarianceMesh& mesh) {
    write_mesh(dir_.file("original.ply"), mesh);
    original_ = read_mesh(dir_.file("original.ply"));
    view_ = editor_view(original_);
  }
  void SetUp() override { use_mesh(make_sample("cube")); }
  glm::vec2 pixel_at(const std::vector<int>& vertices) const {
    return pixel_of(view_, centre_of_vertices(original_, vertices));
  }
  // The cube's edge 6–7 (top, front: +y, +z) selected in edge mode by a click beside its middle.
  Events edge_selected() const {
    Events e;
    e.key("2").wait().click(pixel_at({6, 7}) + glm::vec2(1.0f, 3.0f)).wait();
    return e;
  }
  // Plays the events on `mesh` (a file of the test folder), saves to saved.ply (and a screenshot when
  // named); returns the saved mesh.
  CovarianceMesh play(const Events& events, const std::string& screenshot = "",
                      const std::string& mesh = "original.ply") const {
    const std::string extra =
        "--save " + dir_.file("saved.ply") + (screenshot.empty() ? "" : " --screenshot " + artefact(screenshot));
    const auto r = test::play_editor(dir_, dir_.file(mesh), events, kWidth, kHeight, extra);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    output_ = r.output;
    return read_mesh(dir_.file("saved.ply"));
  }
  bool saved_is_original() const {
    return read_text_file(dir_.file("saved.ply")) == read_text_file(dir_.file("original.ply"));
  }
  static BevelOptions width(double w, int segments = 1) { return test::width(w, segments); }

  test::TempDir dir_;
  CovarianceMesh original_;
  Viewport view_;
  mutable std::string output_;
};

}  // namespace gps::test
