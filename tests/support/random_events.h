#pragma once
// Random editor sessions for the soak (tests/window/test_editor_soak.cpp, scripts/soak.sh): an events
// file (ui/input/event_script.h) drawn from a seed: clicks and shift-clicks on vertices and anywhere,
// drags of handle ends and centres, box selections, orbits and pans, keys during drags, undo and
// redo, shortcuts, typed text, wheel steps, and drops of valid and broken files. The same seed gives
// the same file.
#include <random>
#include <string>
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "editor_driver.h"
#include "ui/editing/axis_handles.h"

namespace gps::test {

struct SoakSettings {
  int width = 640, height = 480;
  int events = 300;
  double k_sigma = 1.0;                 // the editor's default sigma scale for handle positions
  std::vector<std::string> drop_paths;  // files to drop: valid meshes and broken ones
};

inline std::string random_events(const CovarianceMesh& mesh, const SoakSettings& s, unsigned seed) {
  std::mt19937 rng(seed);
  const auto uniform = [&rng](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
  const auto pick = [&rng](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
  const Viewport view = editor_view(mesh, s.width, s.height);  // the editor's first view, beside its panels
  // Anywhere in the window below the menu bar (a click on File > Quit would end the session early).
  const auto anywhere = [&] { return glm::vec2(float(uniform(0, s.width - 1)), float(uniform(24, s.height - 1))); };
  const auto jitter = [&](glm::vec2 p, float r) { return p + glm::vec2(float(uniform(-r, r)), float(uniform(-r, r))); };
  const auto vertex_pixel = [&](int v) { return pixel_of(view, mesh.mean(size_t(v))); };
  const int n_vertices = int(mesh.n_vertices());
  static const std::vector<std::string> keys = {"escape",
                                                "enter",
                                                "backspace",
                                                "delete",
                                                "tab",
                                                "home",
                                                "f",
                                                "o",
                                                "m",
                                                "e",
                                                "x",
                                                "y",
                                                "z",
                                                "n",
                                                "kp1",
                                                "kp3",
                                                "kp5",
                                                "kp7",
                                                "ctrl+kp1",
                                                "ctrl+a",
                                                "alt+a",
                                                "ctrl+z",
                                                "ctrl+shift+z",
                                                "ctrl+y",
                                                "ctrl+s",
                                                "f1",
                                                "f12",
                                                "space",
                                                "left",
                                                "right",
                                                "up",
                                                "down",
                                                "shift+x",
                                                "shift+z",
                                                "period",
                                                "minus",
                                                "1",
                                                "5",
                                                "0",
                                                "a",
                                                "s",
                                                "g",
                                                "r",
                                                "h"};
  static const std::vector<std::string> texts = {"0.25", "-1", "1e-300", "nan", "1e308",    "0",
                                                 "3",    ".",  "-",      "e",   "999999999"};
  static const std::vector<std::string> buttons = {"left", "right", "middle"};
  Events events;
  for (int i = 0; i < s.events; ++i) {
    const int kind = pick(100);
    if (kind < 18) {  // click on a vertex, sometimes with shift
      events.click(jitter(vertex_pixel(pick(n_vertices)), 3.0f), pick(3) == 0 ? "shift" : "");
    } else if (kind < 34) {  // drag a handle of a vertex (select it first, as a user does)
      const int v = pick(n_vertices);
      const HandleFrame f = handle_frame(mesh, v, s.k_sigma, view);
      events.click(vertex_pixel(v)).wait(1);
      const glm::vec2 from = pick(4) == 0 ? pixel_of(view, f.centre) : pixel_of(view, f.end(pick(3), pick(2) ? 1 : -1));
      events.drag(from, jitter(from, 120.0f), 1 + pick(8), pick(5) == 0 ? "shift" : pick(5) == 0 ? "ctrl" : "");
    } else if (kind < 42) {  // box selection on empty space, sometimes adding with shift
      const glm::vec2 a = anywhere();
      events.drag(a, jitter(a, 200.0f), 2 + pick(4), pick(2) ? "shift" : "");
    } else if (kind < 48) {  // orbit, pan (right or middle button, or left with alt)
      const glm::vec2 a = anywhere(), b = jitter(a, 150.0f);
      events.add(R"({"type": "drag", "button": ")" + buttons[size_t(1 + pick(2))] + R"(", "from": )" + point(a) +
                 R"(, "to": )" + point(b) + R"(, "steps": )" + std::to_string(1 + pick(5)) +
                 (pick(3) == 0 ? R"(, "mods": "shift")" : "") + "}");
    } else if (kind < 54) {  // a handle drag interrupted by keys: axis constraints, cancel, confirm
      const int v = pick(n_vertices);
      const HandleFrame f = handle_frame(mesh, v, s.k_sigma, view);
      events.click(vertex_pixel(v)).wait(1);
      const glm::vec2 from = pick(2) ? pixel_of(view, f.centre) : pixel_of(view, f.end(pick(3), 1));
      events.press(from).move(jitter(from, 40.0f)).key(keys[size_t(pick(int(keys.size())))]).move(jitter(from, 80.0f));
      if (pick(3) == 0) events.key(pick(2) ? "escape" : "enter");
      events.release(jitter(from, 80.0f));
    } else if (kind < 64) {  // undo and redo
      static const char* const history[] = {"ctrl+z", "ctrl+z", "ctrl+shift+z", "ctrl+y"};
      events.key(history[pick(4)]);
    } else if (kind < 74) {  // shortcuts and plain keys
      events.key(keys[size_t(pick(int(keys.size())))]);
    } else if (kind < 80) {  // the wheel
      events.scroll(anywhere(), float(uniform(-5, 5)));
    } else if (kind < 84) {  // typed text (into whatever has the keyboard)
      events.text(texts[size_t(pick(int(texts.size())))]);
    } else if (kind < 87 && !s.drop_paths.empty()) {  // drop a file, valid or broken
      events.add(R"({"type": "drop", "paths": [")" + s.drop_paths[size_t(pick(int(s.drop_paths.size())))] + R"("]})");
    } else if (kind < 95) {  // a click anywhere: panels, sliders, empty space
      const std::string button = buttons[size_t(pick(10) < 8 ? 0 : 1 + pick(2))];
      const glm::vec2 p = anywhere();
      events.add(R"({"type": "click", "button": ")" + button + R"(", "x": )" + std::to_string(p.x) + R"(, "y": )" +
                 std::to_string(p.y) + (pick(4) == 0 ? R"(, "mods": "shift")" : "") + "}");
    } else {
      events.wait(1 + pick(3));
    }
  }
  events.wait(2);
  return events.json();
}

}  // namespace gps::test
