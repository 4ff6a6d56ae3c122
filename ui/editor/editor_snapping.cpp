// Snapping while transforming (Shift+Tab, the target, Ctrl held inverts it) and the 3D cursor
// (Shift+right click on the surface, to the selection, to the origin): the commands that set them.
#include <GLFW/glfw3.h>

#include "render/pipeline/surface_point.h"
#include "ui/editor/editor_app.h"

namespace gps {

void EditorApp::build_snapping_commands() {
  CommandTable& t = commands_;
  const auto always = [] { return true; };
  t.add({"Mesh",
         "Snap while transforming (Shift+Tab; Ctrl held inverts it)",
         {Shortcut{GLFW_KEY_TAB, false, true}},
         [this] {
           view_.snap.enabled = !view_.snap.enabled;
           set_status(std::string("snapping ") + (view_.snap.enabled ? "on, to " : "off (") +
                          snap_target_name(view_.snap.target) + (view_.snap.enabled ? "" : ")"),
                      false);
         },
         always,
         [this] { return view_.snap.enabled; },
         nullptr,
         true});
  for (const SnapTarget target : {SnapTarget::increment, SnapTarget::vertex, SnapTarget::edge, SnapTarget::face}) {
    t.add({"Mesh",
           std::string("Snap to: ") + snap_target_name(target),
           {},
           [this, target] {
             view_.snap.target = target;
             set_status(std::string("snap to: ") + snap_target_name(target), false);
           },
           always,
           [this, target] { return view_.snap.target == target; }});
  }
  t.add({"", "Snap to: the next target", {Shortcut{GLFW_KEY_TAB, true, true}}, [this] {
           view_.snap.target = SnapTarget((int(view_.snap.target) + 1) % 4);
           set_status(std::string("snap to: ") + snap_target_name(view_.snap.target), false);
         }});
  t.add({"View",
         "3D cursor to selected (Shift+S)",
         {Shortcut{GLFW_KEY_S, false, true}},
         [this] {
           const std::vector<int>& selected = selection_.vertices();
           Vec3 sum = Vec3::Zero();
           for (const int v : selected) sum += document_.mesh().mean(size_t(v));
           set_cursor(sum / double(selected.size()), "at the selection's centre");
         },
         [this] { return !selection_.empty(); },
         nullptr,
         nullptr,
         true});
  t.add({"View", "3D cursor to world origin (Shift+C)", {Shortcut{GLFW_KEY_C, false, true}}, [this] {
           set_cursor(Vec3::Zero(), "at the world origin");
         }});
}

void EditorApp::set_cursor(const Vec3& point, const std::string& how) { set_status(cursor_.place(point, how), false); }

std::optional<Vec3> EditorApp::surface_at(glm::vec2 pixel) const {
  const RenderTarget* target = viewport_->target();
  if (!target) return std::nullopt;
  const Viewport v = viewport();
  const auto hit = surface_point(
      *target, pixel * glm::vec2(float(target->width()) / float(v.width), float(target->height()) / float(v.height)));
  if (!hit) return std::nullopt;
  return to_vec(*hit);
}

// Where the pixel shows the surface, on it (read back from the last frame's position AOV); elsewhere
// at the cursor's depth, as Blender keeps it.
void EditorApp::place_cursor(glm::vec2 pixel) {
  if (const auto hit = surface_at(pixel)) return set_cursor(*hit, "on the surface at");
  if (const auto at = cursor_.at_its_depth(viewport(), pixel)) set_cursor(*at, "at");
}

}  // namespace gps
