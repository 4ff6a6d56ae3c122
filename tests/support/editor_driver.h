#pragma once
// Driving gpsurf-editor in a real window by an events file (ui/input/event_script.h), from a test folder
// that is also its configuration folder (XDG_CONFIG_HOME): recent files and settings stay there.
#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "run_command.h"
#include "temp_dir.h"
#include "ui/input/camera_control.h"
#include "ui/editing/selection.h"
#include "view/camera.h"
#include "view/projection.h"
#include "view_pixels.h"

namespace gps::test {

#ifdef GPS_TEST_ARTEFACTS_DIR
/// A file kept after the test, for people to look at: build/test-artefacts/<test>/NAME.
inline std::string artefact(const std::string& name) {
  std::filesystem::create_directories(GPS_TEST_ARTEFACTS_DIR);
  return std::string(GPS_TEST_ARTEFACTS_DIR) + "/" + name;
}
#endif

inline std::string editor_command(const std::string& args) { return std::string(GPSURF_EDITOR_BINARY) + " " + args; }

/// The window pixel whose centre a world point projects to (pixel_ray's convention).

/// The window the editor tests open (--size 1024x700).
constexpr int kWindowWidth = 1024, kWindowHeight = 700;

/// The part of a width × height window that the editor's panels leave free at their first-use places
/// (ui/editor/editor.cpp's note_free_region): below the menu bar and above the status bar (21 pixels each,
/// the 15-pixel font with its padding, the status bar 4 more), left of the Inspector (360 wide, 10
/// from the right edge) by 8 pixels.
inline std::pair<glm::vec2, glm::vec2> editor_free_region(int width = kWindowWidth, int height = kWindowHeight) {
  return {glm::vec2(0.0f, 21.0f), glm::vec2(float(width) - 378.0f, float(height) - 25.0f)};
}

/// What the editor shows on opening: its default angles with `up_axis` drawn upward, the mesh's
/// vertices framed in the free region of a width × height window (ui/input/camera_control.h).
inline Viewport editor_view(const CovarianceMesh& mesh, int width = kWindowWidth, int height = kWindowHeight,
                            int up_axis = 1) {
  Viewport v;
  Camera start;
  start.up_axis = up_axis;
  std::vector<int> all(mesh.n_vertices());
  for (size_t i = 0; i < all.size(); ++i) all[i] = int(i);
  const auto [free_min, free_max] = editor_free_region(width, height);
  v.camera = frame_points_in_region(start, mesh, all, 0.0, glm::vec2(float(width), float(height)), free_min, free_max);
  v.width = width;
  v.height = height;
  return v;
}

/// The side of the square box from window pixel `corner`, grown a pixel at a time from 4 (up to
/// 400), at which it first holds `count` of the mesh's vertices (a box selection of that many).
inline float box_side_holding(const Viewport& view, glm::vec2 corner, const CovarianceMesh& mesh, size_t count) {
  float side = 4.0f;
  while (side < 400.0f &&
         vertices_in_box(view.camera, view.width, view.height, corner, corner + side, mesh).size() < count)
    side += 1.0f;
  return side;
}

/// A box corner near `near` (tried outward on a 4-pixel grid, up to 40 pixels away) and the side at
/// which its square box first holds exactly `count` vertices: where several vertices enter a box at
/// once, a neighbouring corner is taken.
inline std::pair<glm::vec2, float> box_holding(const Viewport& view, glm::vec2 near, const CovarianceMesh& mesh,
                                               size_t count) {
  for (int ring = 0; ring <= 10; ++ring)
    for (int dy = -ring; dy <= ring; ++dy)
      for (int dx = -ring; dx <= ring; ++dx) {
        if (std::max(std::abs(dx), std::abs(dy)) != ring) continue;
        const glm::vec2 corner = near + 4.0f * glm::vec2(float(dx), float(dy));
        const float side = box_side_holding(view, corner, mesh, count);
        if (vertices_in_box(view.camera, view.width, view.height, corner, corner + side, mesh).size() == count)
          return {corner, side};
      }
  return {near, box_side_holding(view, near, mesh, count)};
}

inline std::string point(glm::vec2 p) { return "[" + std::to_string(p.x) + ", " + std::to_string(p.y) + "]"; }

/// An events file, built one event at a time.
class Events {
public:
  Events& add(const std::string& item) {
    items_ += (items_.empty() ? "" : ",\n") + item;
    return *this;
  }
  Events& click(glm::vec2 p, const std::string& mods = "") {
    return add(R"({"type": "click", "x": )" + std::to_string(p.x) + R"(, "y": )" + std::to_string(p.y) +
               (mods.empty() ? "" : R"(, "mods": ")" + mods + "\"") + "}");
  }
  Events& drag(glm::vec2 from, glm::vec2 to, int steps = 6, const std::string& mods = "") {
    return add(R"({"type": "drag", "from": )" + point(from) + R"(, "to": )" + point(to) + R"(, "steps": )" +
               std::to_string(steps) + (mods.empty() ? "" : R"(, "mods": ")" + mods + "\"") + "}");
  }
  Events& press(glm::vec2 p) {
    return add(R"({"type": "press", "button": "left", "x": )" + std::to_string(p.x) + R"(, "y": )" +
               std::to_string(p.y) + "}");
  }
  Events& release(glm::vec2 p) {
    return add(R"({"type": "release", "button": "left", "x": )" + std::to_string(p.x) + R"(, "y": )" +
               std::to_string(p.y) + "}");
  }
  Events& move(glm::vec2 p) {
    return add(R"({"type": "move", "x": )" + std::to_string(p.x) + R"(, "y": )" + std::to_string(p.y) + "}");
  }
  Events& key(const std::string& name) { return add(R"({"type": "key", "key": ")" + name + "\"}"); }
  Events& text(const std::string& typed) { return add(R"({"type": "text", "text": ")" + typed + "\"}"); }
  Events& scroll(glm::vec2 p, float steps) {
    return add(R"({"type": "scroll", "steps": )" + std::to_string(steps) + R"(, "x": )" + std::to_string(p.x) +
               R"(, "y": )" + std::to_string(p.y) + "}");
  }
  Events& wait(int frames = 2) { return add(R"({"type": "wait", "frames": )" + std::to_string(frames) + "}"); }
  std::string json() const { return "{\"events\": [\n" + items_ + "\n]}\n"; }

private:
  std::string items_;
};

/// Runs the editor on `mesh_file` in a width × height window with the events, then `extra` (e.g.
/// --save F --screenshot G --stats H); the test folder is its configuration folder.
inline CommandResult play_editor(const TempDir& dir, const std::string& mesh_file, const Events& events, int width,
                                 int height, const std::string& extra) {
  const std::string file = dir.write("events.json", events.json());
  return run_command("XDG_CONFIG_HOME=" + dir.path().string() + " " +
                     editor_command(mesh_file + " --size " + std::to_string(width) + "x" + std::to_string(height) +
                                    " --play " + file + " " + extra));
}

}  // namespace gps::test
