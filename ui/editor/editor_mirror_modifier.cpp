// The mirror modifier (ui/editing/mirror_modifier.h) in the editor: Mesh → Mirror modifier
// (Ctrl+Alt+M) turns it on and off, its submenu sets the axis and clipping and applies it (also
// Ctrl+Alt+Shift+M); every mesh the renderer gets goes through show_mesh and every Gaussian edit
// through show_edit, so that the mirror side follows the half at once. Its settings are kept per file
// in the editor's settings (the covariance PLY has no place for them).
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "core/modelling/mirror.h"
#include "core/support/error.h"
#include "ui/editor/editor_app.h"

namespace gps {

namespace {

const char* const kAxisNames[] = {"x", "y", "z"};

std::string mirror_words(const MirrorSettings& s) {
  if (!s.enabled) return "mirror modifier off";
  return std::string("mirror modifier on: the plane ") + kAxisNames[s.axis] + " = 0, clipping " +
         (s.clipping ? "on" : "off");
}

}  // namespace

void EditorApp::build_mirror_commands() {
  CommandTable& t = commands_;
  const auto on = [this] { return mirror_.settings.enabled; };
  t.add({"Mesh",
         "Mirror modifier",
         {Shortcut{GLFW_KEY_M, true, false, true}},
         [this] {
           MirrorSettings s = mirror_.settings;
           s.enabled = !s.enabled;
           set_mirror(s);
         },
         nullptr,
         on,
         nullptr,
         true});
  t.add({"Mesh", "Mirror modifier settings", {}, nullptr, nullptr, nullptr, [this] { draw_mirror_items(); }});
  t.add({"Mesh", "Apply mirror modifier", {Shortcut{GLFW_KEY_M, true, true, true}}, [this] { apply_mirror(); }, on});
}

void EditorApp::draw_mirror_items() {
  MirrorSettings s = mirror_.settings;
  if (ImGui::MenuItem("On", nullptr, s.enabled)) s.enabled = !s.enabled;
  for (int axis = 0; axis < 3; ++axis)
    if (ImGui::MenuItem((std::string("Plane ") + kAxisNames[axis] + " = 0").c_str(), nullptr, s.axis == axis))
      s.axis = axis;
  if (ImGui::MenuItem("Clipping (vertices on the plane stay on it)", nullptr, s.clipping)) s.clipping = !s.clipping;
  if (!(s == mirror_.settings)) set_mirror(s);
  ImGui::Separator();
  if (ImGui::MenuItem("Apply", nullptr, false, mirror_.settings.enabled)) apply_mirror();
}

void EditorApp::show_mesh(const CovarianceMesh& mesh, const PlanOptions& plans, std::optional<ReplannedTables> surface,
                          const std::vector<int>& origin) {
  MirrorModifier next;
  next.settings = mirror_.settings;
  std::string refusal;
  const CovarianceMesh& shown = next.shown(mesh, refusal);
  if (next.mirroring()) {
    renderer_->set_mesh(shown, plans);
  } else if (surface) {  // a sharpness change: the vertices keep their indices
    renderer_->set_mesh(mesh, std::move(surface->tables), renderer_->frame().following(mesh), surface->change, {});
  } else {  // re-planned where the mesh changed (a wrong origin costs time, never a wrong table)
    if (shown_plans_ && shown_plans_->options() == plans)
      shown_plans_->set_topology(mesh, origin);
    else
      shown_plans_.emplace(mesh, plans);
    renderer_->set_mesh(mesh, shown_plans_->tables(), renderer_->frame().following(mesh), shown_plans_->last_change(),
                        origin);
  }
  mirror_ = std::move(next);
  hidden_stale_ = true;  // the patches and lines it leaves out, of the mesh now shown
  document_.set_clip(mirror_.clip(document_.mesh()));
  if (!refusal.empty()) set_status("mirror modifier: " + refusal + "; the half is shown", true);
  surface_changed();
  check_finite_ = true;
}

void EditorApp::show_edit(const std::vector<int>& changed) {
  std::string refusal;
  if (!mirror_.mirroring()) {
    renderer_->update_vertices(document_.mesh(), changed);
  } else if (const auto shown = mirror_.update(document_.mesh(), changed, refusal)) {
    renderer_->update_vertices(mirror_.mirrored(), *shown);
  } else {
    set_status("mirror modifier: " + refusal + "; the half is shown", true);
    try {
      renderer_->set_mesh(document_.mesh(), view_.plans());
      hidden_stale_ = true;
    } catch (const Error& e) {
      set_status(e.what(), true);
    }
  }
  surface_changed();
}

void EditorApp::set_mirror(const MirrorSettings& settings) {
  if (modal_active() || mode_ == Mode::handle) return;  // not in the middle of a drag or a tool
  const MirrorSettings before = mirror_.settings;
  mirror_.settings = settings;
  try {
    show_mesh(document_.mesh(), view_.plans());
  } catch (const Error& e) {  // too big for the GPU's buffers: the modifier stays as it was
    mirror_.settings = before;
    set_status(e.what(), true);
    return;
  }
  remember_mirror();
  if (settings.enabled && !mirror_.mirroring()) return;  // refused: show_mesh said why
  set_status(mirror_words(settings), false);
}

void EditorApp::remember_mirror() {
  if (document_.source_path().empty()) return;
  if (mirror_.settings == MirrorSettings{})
    view_.mirror_modifiers.erase(document_.source_path());
  else
    view_.mirror_modifiers[document_.source_path()] = mirror_.settings;
}

void EditorApp::apply_mirror() {
  if (!mirror_.settings.enabled) return;
  const MirrorSettings before = mirror_.settings;
  mirror_.settings.enabled = false;  // the result is shown as it is
  if (!run_operation("apply mirror modifier",
                     [axis = before.axis](const CovarianceMesh& m) { return mirror(m, axis, Vec3::Zero(), true); })) {
    mirror_.settings = before;
    return;
  }
  remember_mirror();
}

}  // namespace gps
