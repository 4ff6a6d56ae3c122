// View → Show target points… and the target points' toggle: a dense target (the file a fit went to,
// or any mesh or point file) drawn as points over the surface, coloured by their distance from it
// (ui/display/target_points_layer.h). Which target a mesh file showed is kept with the View settings.
#include <GLFW/glfw3.h>

#include <algorithm>
#include <filesystem>

#include "ui/editor/editor_app.h"

namespace gps {

namespace {
const std::vector<std::string> kTargetExtensions = {".ply", ".obj", ".off", ".stl"};
}  // namespace

void EditorApp::build_target_point_commands() {
  const auto always = std::function<bool()>();
  commands_.add({"View",
                 "Show target points...",
                 {Shortcut{GLFW_KEY_T, true, true}},
                 [this] {
                   browser_purpose_ = BrowserPurpose::load_target;
                   const std::filesystem::path near = !target_layer_->points().path().empty()
                                                          ? target_layer_->points().path()
                                                          : document_.source_path();
                   browser_.open(FileBrowser::Mode::open, "Show target points",
                                 near.empty() ? std::filesystem::current_path().string()
                                              : near.parent_path().string(),
                                 kTargetExtensions);
                 },
                 always,
                 nullptr,
                 nullptr,
                 true});
  commands_.add({"View",
                 "Target points",
                 {Shortcut{GLFW_KEY_T, false, true}},
                 [this] {
                   view_.target.shown = !view_.target.shown;
                   remember_target_points();
                 },
                 [this] { return target_layer_->points().loaded() || target_layer_->points().busy(); },
                 [this] { return view_.target.shown; }});
}

void EditorApp::show_target_points(const std::string& path) {
  target_layer_->points().load(path);
  view_.target.shown = true;
  set_status("measuring the points of " + path + " against the surface", false);
}

void EditorApp::remember_target_points() {
  const std::string& mesh = document_.source_path();
  if (mesh.empty()) return;  // a sample: nothing to keep it under
  const std::string& target = target_layer_->points().path();
  // A file shown over its own surface (after a fit of its simplification) is not worth reopening with.
  if (view_.target.shown && !target.empty() && target != mesh)
    view_.target_files[mesh] = target;
  else
    view_.target_files.erase(mesh);
}

void EditorApp::reopen_target_points() {
  const auto kept = view_.target_files.find(document_.source_path());
  std::error_code ignored;
  if (kept != view_.target_files.end() && std::filesystem::is_regular_file(kept->second, ignored))
    show_target_points(kept->second);
  else
    target_layer_->points().clear();
}

void EditorApp::update_target_points() {
  const TargetPointsLayer::Report report =
      target_layer_->update(*shown_, document_.mesh(), view_.plans(), view_.target, Clock::now());
  if (!report.error.empty()) set_status(report.error, true);
  if (report.shown) {
    const TargetPoints& t = target_layer_->points();
    remember_target_points();
    set_status("showing the " + std::to_string(t.points().size()) + " points of " + t.path() +
                   ", coloured by their distance from the surface",
               false);
  }
}

}  // namespace gps
