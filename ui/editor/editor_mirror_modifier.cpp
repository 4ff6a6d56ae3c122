// The mirror modifier (ui/editing/mirror_modifier.h) in the editor: Mesh → Mirror modifier
// (Ctrl+Alt+M) turns it on and off, its submenu sets the axis and clipping and applies it (also
// Ctrl+Alt+Shift+M); every mesh the renderer gets goes through show_mesh and every Gaussian edit
// through show_edit (ui/display/shown_surface.h), so that the mirror side follows the half at once.
// Its settings are kept per file in the editor's settings (the covariance PLY has no place for them).
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>

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
  const auto on = [this] { return shown_->mirror().settings.enabled; };
  t.add({"Mesh",
         "Mirror modifier",
         {Shortcut{GLFW_KEY_M, true, false, true}},
         [this] {
           MirrorSettings s = shown_->mirror().settings;
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
  MirrorSettings s = shown_->mirror().settings;
  if (ImGui::MenuItem("On", nullptr, s.enabled)) s.enabled = !s.enabled;
  for (int axis = 0; axis < 3; ++axis)
    if (ImGui::MenuItem((std::string("Plane ") + kAxisNames[axis] + " = 0").c_str(), nullptr, s.axis == axis))
      s.axis = axis;
  if (ImGui::MenuItem("Clipping (vertices on the plane stay on it)", nullptr, s.clipping)) s.clipping = !s.clipping;
  if (!(s == shown_->mirror().settings)) set_mirror(s);
  ImGui::Separator();
  if (ImGui::MenuItem("Apply", nullptr, false, shown_->mirror().settings.enabled)) apply_mirror();
}

void EditorApp::show_mesh(const CovarianceMesh& mesh, const PlanOptions& plans, std::optional<ReplannedTables> surface,
                          const std::vector<int>& origin) {
  const std::string refusal = shown_->show(mesh, plans, std::move(surface), origin);
  document_.set_clip(shown_->mirror().clip(document_.mesh()));
  if (!refusal.empty()) set_status("mirror modifier: " + refusal + "; the half is shown", true);
}

void EditorApp::show_edit(const std::vector<int>& changed) {
  try {
    const std::string refusal = shown_->show_edit(document_.mesh(), changed, view_.plans());
    if (!refusal.empty()) set_status("mirror modifier: " + refusal + "; the half is shown", true);
  } catch (const Error& e) {
    set_status(e.what(), true);
  }
}

void EditorApp::set_mirror(const MirrorSettings& settings) {
  if (modal_active()) return;  // not in the middle of a drag or a tool
  const MirrorSettings before = shown_->mirror().settings;
  shown_->set_mirror_settings(settings);
  try {
    show_mesh(document_.mesh(), view_.plans());
  } catch (const Error& e) {  // too big for the GPU's buffers: the modifier stays as it was
    shown_->set_mirror_settings(before);
    set_status(e.what(), true);
    return;
  }
  remember_mirror();
  if (settings.enabled && !shown_->mirror().mirroring()) return;  // refused: show_mesh said why
  set_status(mirror_words(settings), false);
}

void EditorApp::remember_mirror() {
  if (document_.source_path().empty()) return;
  const MirrorSettings& settings = shown_->mirror().settings;
  if (settings == MirrorSettings{})
    view_.mirror_modifiers.erase(document_.source_path());
  else
    view_.mirror_modifiers[document_.source_path()] = settings;
}

void EditorApp::apply_mirror() {
  const MirrorSettings before = shown_->mirror().settings;
  if (!before.enabled) return;
  MirrorSettings off = before;
  off.enabled = false;  // the result is shown as it is
  shown_->set_mirror_settings(off);
  // The selection stays, with its images (as Blender mirrors its selection into the new half), not the
  // copies mirror() selects.
  const std::vector<int> selected = selection_.vertices();
  const auto apply = [axis = before.axis, selected](const CovarianceMesh& m) {
    Modelled r = mirror(m, axis, Vec3::Zero(), true);
    const std::vector<int> images = mirror_images(m, axis, Vec3::Zero(), true);
    r.selection = selected;
    for (const int v : selected)
      if (v >= 0 && size_t(v) < images.size()) r.selection.push_back(images[size_t(v)]);
    std::sort(r.selection.begin(), r.selection.end());
    r.selection.erase(std::unique(r.selection.begin(), r.selection.end()), r.selection.end());
    return r;
  };
  if (!run_operation("apply mirror modifier", apply)) {
    shown_->set_mirror_settings(before);
    return;
  }
  remember_mirror();
}

}  // namespace gps
