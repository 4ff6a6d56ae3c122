// View → Show target points… and the target points' toggle: a dense target (the file a fit went to,
// or any mesh or point file) drawn as points over the surface, coloured by their distance from it
// (render/overlays/point_overlay.h), measured in the background after each change of the surface
// (ui/overlays/target_points.h). Which target a mesh file showed is kept with the View settings.
#include <GLFW/glfw3.h>

#include <algorithm>
#include <filesystem>

#include "ui/editor/editor_app.h"

namespace gps {

namespace {
const std::vector<std::string> kTargetExtensions = {".ply", ".obj", ".off", ".stl"};

/// The ramp's end where no maximum was chosen: the 99th percentile, else the largest distance, else
/// a millionth of the points' size (all on the surface).
double automatic_max_distance(const DistanceSummary& d) {
  if (d.percentile_99 > 0.0) return d.percentile_99;
  if (d.max > 0.0) return d.max;
  return 1e-6 * d.length;
}
}  // namespace

void EditorApp::build_target_point_commands() {
  const auto always = std::function<bool()>();
  commands_.add({"View",
                 "Show target points...",
                 {Shortcut{GLFW_KEY_T, true, true}},
                 [this] {
                   browser_purpose_ = BrowserPurpose::load_target;
                   const std::filesystem::path near =
                       !target_points_.path().empty() ? target_points_.path() : document_.source_path();
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
                 [this] { return target_points_.loaded() || target_points_.busy(); },
                 [this] { return view_.target.shown; }});
}

void EditorApp::show_target_points(const std::string& path) {
  target_points_.load(path);
  view_.target.shown = true;
  set_status("measuring the points of " + path + " against the surface", false);
}

void EditorApp::remember_target_points() {
  const std::string& mesh = document_.source_path();
  if (mesh.empty()) return;  // a sample: nothing to keep it under
  const std::string& target = target_points_.path();
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
    target_points_.clear();
}

void EditorApp::update_target_points() {
  TargetPointsView& t = view_.target;
  if (shown_->changed_since(target_seen_)) target_points_.surface_changed(Clock::now());
  // Hidden, nothing is measured; shown again, the changes missed meanwhile are.
  const TargetPoints::Taken taken =
      !t.shown ? TargetPoints::Taken{}
               : target_points_.poll(
                     Clock::now(),
                     [this]() -> std::shared_ptr<const CovarianceMesh> {
                       if (shown_->preview())
                         return shown_->preview();  // a modal tool's preview (a crease's sharpness, a bevel)
                       return std::make_shared<const CovarianceMesh>(document_.mesh());
                     },
                     view_.plans());
  if (!taken.error.empty()) set_status(taken.error, true);
  if (taken.points) {
    point_overlay_->set_points(target_points_.points(), shown_->renderer().frame());
    remember_target_points();
    set_status("showing the " + std::to_string(target_points_.points().size()) + " points of " +
                   target_points_.path() + ", coloured by their distance from the surface",
               false);
  } else if (!target_points_.loaded()) {
    if (point_overlay_->count() > 0) point_overlay_->set_points({}, shown_->renderer().frame());  // forgotten
  } else if (point_overlay_->frame().centre != shown_->renderer().frame().centre ||
             point_overlay_->frame().unit != shown_->renderer().frame().unit) {
    point_overlay_->set_frame(target_points_.points(), shown_->renderer().frame());  // the overlays' frame moved
  }
  if (taken.distances) point_overlay_->set_distances(target_points_.distances());
  t.name = target_points_.loaded() ? std::filesystem::path(target_points_.path()).filename().string() : "";
  t.count = target_points_.loaded() ? target_points_.points().size() : 0;
  t.measuring = target_points_.busy();
  const DistanceSummary& d = target_points_.summary();
  t.rms = d.rms, t.percentile_99 = d.percentile_99, t.largest = d.max, t.length = d.length;
  if (t.automatic || !(t.max_distance > 0.0f)) t.max_distance = float(automatic_max_distance(d));
}

void EditorApp::draw_target_points() {
  if (!view_.target.shown || point_overlay_->count() == 0) return;
  PointOverlay::Style style;
  style.max_distance = view_.target.max_distance;
  style.point_size = view_.target.point_size;
  point_overlay_->draw(*target_, camera_, style);
}

}  // namespace gps
