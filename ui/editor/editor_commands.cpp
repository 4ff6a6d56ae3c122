// The editor's command table: every menu item and key binding, in one place.
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <ctime>

#include "core/modelling/samples.h"
#include "ui/input/camera_control.h"
#include "ui/editor/editor_app.h"

namespace gps {

void EditorApp::build_commands() {
  const auto key = [](int k, bool ctrl = false, bool shift = false, bool alt = false) {
    return Shortcut{k, ctrl, shift, alt};
  };
  const auto always = std::function<bool()>();
  CommandTable& t = commands_;
  // File
  t.add({"File", "Open...", {key(GLFW_KEY_O, true)}, [this] { request({Action::Kind::open_file, ""}); }});
  t.add({"File", "Open sample", {}, {}, always, nullptr, [this] {
           for (const std::string& name : sample_names())
             if (ImGui::MenuItem(name.c_str())) request({Action::Kind::open_sample, name});
         }});
  t.add({"File",
         "Open recent",
         {},
         {},
         [this] { return !recent_.paths().empty(); },
         nullptr,
         [this] {
           for (const std::string& path : recent_.paths())
             if (ImGui::MenuItem(path.c_str())) request({Action::Kind::open_file, path});
         }});
  t.add({"File", "Save", {key(GLFW_KEY_S, true)}, [this] { save(); }, always, nullptr, nullptr, true});
  t.add({"File", "Save As...", {key(GLFW_KEY_S, true, true)}, [this] { save_to(""); }});
  t.add({"File", "Simplify...", {key(GLFW_KEY_D, true, true)}, [this] {
           if (!modal_active()) mesh_jobs_.open_simplify(std::make_shared<const CovarianceMesh>(document_.mesh()));
         }});
  t.add({"File", "Fit to...", {key(GLFW_KEY_F, true, true)}, [this] {
           if (!modal_active())
             mesh_jobs_.open_fit(std::make_shared<const CovarianceMesh>(document_.mesh()), document_.source_path());
         }});
  t.add({"File", "Screenshot (PNG in the current folder)", {key(GLFW_KEY_F12)}, [this] {
           char name[64];
           const std::time_t now = std::time(nullptr);
           std::strftime(name, sizeof name, "gpsurf-%Y%m%d-%H%M%S.png", std::localtime(&now));
           screenshot_request_ = name;
         }});
  t.add({"File",
         "Quit",
         {key(GLFW_KEY_Q, true)},
         [this] {
           request({Action::Kind::quit, ""});
         },
         always,
         nullptr,
         nullptr,
         true});
  // Edit
  t.add(
      {"Edit", "Undo", {key(GLFW_KEY_Z, true)}, [this] { undo_redo(true); }, [this] { return document_.can_undo(); }});
  t.add({"Edit",
         "Redo",
         {key(GLFW_KEY_Z, true, true), key(GLFW_KEY_Y, true)},
         [this] { undo_redo(false); },
         [this] { return document_.can_redo(); }});
  t.add({"Edit",
         "Adjust last operation (F9)",
         {key(GLFW_KEY_F9)},
         [this] { show_adjust_last_ = !show_adjust_last_; },
         always,
         [this] { return show_adjust_last_; }});
  t.add({"Edit",
         "Proportional editing",
         {key(GLFW_KEY_O)},
         [this] { reach_options_.proportional = !reach_options_.proportional; },
         always,
         [this] { return reach_options_.proportional; },
         nullptr,
         true});
  t.add({"Edit",
         "Mirror editing",
         {key(GLFW_KEY_M, false, true)},
         [this] { reach_options_.mirror = !reach_options_.mirror; },
         always,
         [this] { return reach_options_.mirror; }});
  build_selection_commands();
  build_hide_commands();
  // View
  t.add({"View", "Frame all", {key(GLFW_KEY_HOME)}, [this] { frame_vertices({}); }});
  t.add({"View", "Frame selection (all when none)", {key(GLFW_KEY_KP_DECIMAL)}, [this] {
           frame_vertices(selection_.vertices());
         }});
  t.add(
      {"View", "Front view", {key(GLFW_KEY_KP_1)}, [this] { axis_view(0.0f, 0.0f); }, always, nullptr, nullptr, true});
  t.add({"View", "Back view", {key(GLFW_KEY_KP_1, true)}, [this] { axis_view(180.0f, 0.0f); }});
  t.add({"View", "Right view", {key(GLFW_KEY_KP_3)}, [this] { axis_view(90.0f, 0.0f); }});
  t.add({"View", "Left view", {key(GLFW_KEY_KP_3, true)}, [this] { axis_view(-90.0f, 0.0f); }});
  t.add({"View", "Top view", {key(GLFW_KEY_KP_7)}, [this] { axis_view(0.0f, 89.9f); }});
  t.add({"View", "Bottom view", {key(GLFW_KEY_KP_7, true)}, [this] { axis_view(0.0f, -89.9f); }});
  t.add({"View",
         "Orthographic",
         {key(GLFW_KEY_KP_5)},
         [this] { camera_.orthographic = !camera_.orthographic; },
         always,
         [this] { return camera_.orthographic; }});
  t.add({"View",
         "Ellipsoids",
         {key(GLFW_KEY_E, false, true)},
         [this] { view_.draw.ellipsoids = !view_.draw.ellipsoids; },
         always,
         [this] { return view_.draw.ellipsoids; },
         nullptr,
         true});
  t.add({"View",
         "Inspector",
         {},
         [this] { view_.show_inspector = !view_.show_inspector; },
         always,
         [this] { return view_.show_inspector; },
         nullptr,
         true});
  t.add({"View",
         "View options",
         {},
         [this] { view_.show_view = !view_.show_view; },
         always,
         [this] { return view_.show_view; }});
  t.add({"View",
         "Statistics",
         {},
         [this] { view_.show_statistics = !view_.show_statistics; },
         always,
         [this] { return view_.show_statistics; }});
  build_target_point_commands();
  build_modelling_commands();
  // A key whose command waits for a selection says so, where Blender is silent (the tool's own
  // refusal is never reached: the key does not start it).
  t.on_disabled_key([this](const std::string& label) {
    if (selection_.empty() && document_.mesh().n_faces() > 0)
      set_status(label.substr(0, label.find(" (")) + ": nothing is selected for it to work on", true);
  });
  build_mirror_commands();
  build_snapping_commands();
  // Help
  t.add({"Help",
         "Mouse and keys",
         {key(GLFW_KEY_F1)},
         [this] { view_.show_help = !view_.show_help; },
         always,
         [this] { return view_.show_help; }});
}

glm::vec2 EditorApp::viewport_size() const {
  const Viewport v = viewport();
  return {float(v.width), float(v.height)};
}

void EditorApp::frame_vertices(const std::vector<int>& vertices) {
  if (vertices.empty()) {  // the whole mesh, as shown (with the mirror modifier's mirror)
    const CovarianceMesh& shown = shown_->drawn(document_.mesh());
    std::vector<int> all(shown.n_vertices());
    for (size_t i = 0; i < all.size(); ++i) all[i] = int(i);
    camera_ = frame_points_in_region(camera_, shown, all, 0.0, viewport_size(), free_min_, free_max_);
    return;
  }
  const double radius = 0.05 * bounding_box_diagonal(document_.mesh());
  camera_ = frame_points_in_region(camera_, document_.mesh(), vertices, radius, viewport_size(), free_min_, free_max_);
}

void EditorApp::frame_first_view() {
  camera_ = Camera{};
  camera_.up_axis = view_.up_axis;
  frame_vertices({});
}

void EditorApp::axis_view(float yaw, float pitch) {
  camera_.yaw_degrees = yaw;
  camera_.pitch_degrees = pitch;
}

}  // namespace gps
