#include "ui/settings/editor_settings.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <type_traits>

#include "core/io/atomic_file.h"
#include "core/support/error.h"

namespace gps {

// A file's mirror modifier in settings.json: {"enabled": …, "axis": 0–2, "clipping": …}.
void to_json(nlohmann::json& j, const MirrorSettings& m) {
  j = {{"enabled", m.enabled}, {"axis", m.axis}, {"clipping", m.clipping}};
}
void from_json(const nlohmann::json& j, MirrorSettings& m) {
  j.at("enabled").get_to(m.enabled);
  j.at("axis").get_to(m.axis);
  j.at("clipping").get_to(m.clipping);
}

namespace {

// Every kept setting, once: its name in the file and where it lives.
template <typename Visit>
void visit_settings(ViewOptions& view, ReachOptions& reach, Visit visit) {
  visit("adaptive", view.adaptive);
  visit("adaptive_pixels", view.adaptive_pixels);
  visit("level", view.draw.level);
  visit("exact_plans", view.exact);
  visit("plan_depth", view.depth);
  visit("scheme", view.scheme);
  visit("loop_warren", view.warren);
  visit("matcap", view.matcap);
  visit("wireframe", view.draw.wireframe);
  visit("surface_cache", view.draw.surface_cache);
  visit("ellipsoids", view.draw.ellipsoids);
  visit("k_sigma", view.draw.sigma_scale);
  visit("vsync", view.vsync);
  visit("common_frame", view.common_frame);
  visit("pivot", view.pivot);
  visit("transform_gaussians", view.transform_gaussians);
  visit("transform_orientation", view.transform_orientation);
  visit("snap", view.snap.enabled);
  visit("snap_increment", view.snap.distance_step);
  visit("ellipsoid_scope", view.ellipsoid_scope);
  visit("show_inspector", view.show_inspector);
  visit("show_view", view.show_view);
  visit("show_statistics", view.show_statistics);
  visit("up_axes", view.up_axes);
  visit("mirror_modifiers", view.mirror_modifiers);
  visit("target_points", view.target_files);
  visit("target_point_size", view.target.point_size);
  visit("proportional", reach.proportional);
  visit("mirror", reach.mirror);
  visit("mirror_axis", reach.mirror_axis);
}

}  // namespace

std::string config_folder() {
  // The XDG base directory specification ignores relative paths in its variables.
  const char* config = std::getenv("XDG_CONFIG_HOME");
  if (config && config[0] == '/') return std::string(config) + "/gpsurf";
  const char* home = std::getenv("HOME");
  if (home && home[0] != '\0') return std::string(home) + "/.config/gpsurf";
  return "";
}

std::string load_settings(const std::string& folder, ViewOptions& view, ReachOptions& reach) {
  if (folder.empty()) return "";
  const std::string path = folder + "/settings.json";
  std::ifstream in(path);
  if (!in) return "";
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const std::exception&) {
    return path + ": not valid JSON; using the default settings";
  }
  std::string error;
  visit_settings(view, reach, [&](const char* name, auto& value) {
    if (!j.is_object() || !j.contains(name)) return;
    try {
      value = j.at(name).get<std::decay_t<decltype(value)>>();
    } catch (const std::exception&) {
      error = path + ": setting '" + name + "' has the wrong type; kept its default";
    }
  });
  int mode = int(view.draw.mode), falloff = int(reach.falloff), snap_target = int(view.snap.target);
  if (j.is_object() && j.contains("shading") && j["shading"].is_number_integer())
    mode = std::clamp(j["shading"].get<int>(), 0, 2);
  if (j.is_object() && j.contains("falloff") && j["falloff"].is_number_integer())
    falloff = std::clamp(j["falloff"].get<int>(), 0, 3);
  if (j.is_object() && j.contains("snap_target") && j["snap_target"].is_number_integer())
    snap_target = std::clamp(j["snap_target"].get<int>(), 0, 3);
  view.snap.target = SnapTarget(snap_target);
  if (!(view.snap.distance_step > 0) || !std::isfinite(view.snap.distance_step)) view.snap.distance_step = 0.1;
  view.draw.mode = ShadingMode(mode);
  reach.falloff = Falloff(falloff);
  view.draw.pixels = view.adaptive ? view.adaptive_pixels : 0.0f;
  reach.mirror_axis = std::clamp(reach.mirror_axis, 0, 2);
  view.pivot = std::clamp(view.pivot, 0, 1);
  view.transform_orientation = std::clamp(view.transform_orientation, 0, 1);
  view.ellipsoid_scope = std::clamp(view.ellipsoid_scope, 0, 2);
  for (auto& [file, axis] : view.up_axes) axis = std::clamp(axis, 0, 2);
  for (auto& [file, mirror] : view.mirror_modifiers) mirror.axis = std::clamp(mirror.axis, 0, 2);
  view.target.point_size = std::clamp(view.target.point_size, 1.0f, 16.0f);
  return error;
}

std::string save_settings(const std::string& folder, const ViewOptions& view, const ReachOptions& reach) {
  if (folder.empty()) return "";
  nlohmann::json j = nlohmann::json::object();
  ViewOptions v = view;
  ReachOptions r = reach;
  visit_settings(v, r, [&](const char* name, const auto& value) { j[name] = value; });
  j["shading"] = int(view.draw.mode);
  j["falloff"] = int(reach.falloff);
  j["snap_target"] = int(view.snap.target);
  try {
    std::filesystem::create_directories(folder);
    write_file_atomically(folder + "/settings.json", [&j](std::ostream& out) { out << j.dump(2) << "\n"; });
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace gps
