#include "ui/panels/inspector_panel.h"

#include <array>
#include <cstring>

#include <imgui.h>
#include <imgui_internal.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/mesh/sharpness.h"
#include "ui/editing/covariance_presets.h"
#include "ui/editing/crease_tool.h"

namespace gps {

Vec3 euler_degrees(const Mat3& r) {
  // R = Rz(c)·Ry(b)·Rx(a): b = −asin(r20); a = atan2(r21, r22); c = atan2(r10, r00) (away from gimbal lock).
  const double b = std::asin(std::clamp(-r(2, 0), -1.0, 1.0));
  double a, c;
  if (std::abs(r(2, 0)) < 1.0 - 1e-12) {
    a = std::atan2(r(2, 1), r(2, 2));
    c = std::atan2(r(1, 0), r(0, 0));
  } else {  // gimbal lock: only a − c (or a + c) is defined; put it all in a
    a = std::atan2(-r(1, 2), r(1, 1));
    c = 0.0;
  }
  return Vec3(a, b, c) * (180.0 / M_PI);
}

Mat3 rotation_from_euler_degrees(const Vec3& angles) {
  const Vec3 r = angles * (M_PI / 180.0);
  return (Eigen::AngleAxisd(r.z(), Vec3::UnitZ()) * Eigen::AngleAxisd(r.y(), Vec3::UnitY()) *
          Eigen::AngleAxisd(r.x(), Vec3::UnitX()))
      .toRotationMatrix();
}

double display_value(double value, int decimals) {
  const double scale = std::pow(10.0, decimals);
  const double rounded = std::round(value * scale) / scale;
  return rounded == 0.0 ? 0.0 : rounded;  // −0.00 shows as 0.00
}

namespace {

const ImVec4 kAxisColours[3] = {ImVec4(0.92f, 0.31f, 0.31f, 1), ImVec4(0.35f, 0.82f, 0.35f, 1),
                                ImVec4(0.35f, 0.59f, 1.0f, 1)};

// Whether coordinate k of the `vertices`' means is not the same for all of them.
bool mixed_coordinate(const CovarianceMesh& mesh, const std::vector<int>& vertices, int k) {
  for (const int v : vertices)
    if (mesh.mean(size_t(v))[k] != mesh.mean(size_t(vertices.front()))[k]) return true;
  return false;
}

// Per principal axis k, whether σ_k of some of the `vertices` is not `shown[k]` (the active vertex's,
// as the field shows it). A covariance bitwise the active one's has its σ without an eigen-solve, and
// the scan stops once every axis is known to differ: a selection of every vertex of a large mesh is
// read each frame.
std::array<bool, 3> mixed_sigmas(const CovarianceMesh& mesh, const std::vector<int>& vertices, int active,
                                 const Vec3& shown) {
  const Mat3& active_covariance = mesh.covariance(size_t(active));
  const Vec3 fresh = ellipsoid_axes(active_covariance).sigmas;
  std::array<bool, 3> mixed{};
  for (const int v : vertices) {
    if (mixed[0] && mixed[1] && mixed[2]) break;
    const Mat3& c = mesh.covariance(size_t(v));
    const Vec3 sigmas = v == active                                              ? shown
                        : std::memcmp(&c, &active_covariance, sizeof(Mat3)) == 0 ? fresh
                                                                                 : ellipsoid_axes(c).sigmas;
    for (int k = 0; k < 3; ++k) mixed[size_t(k)] = mixed[size_t(k)] || sigmas[k] != shown[k];
  }
  return mixed;
}

}  // namespace

// One number field: it shows `value` rounded to `decimals` (or "mixed"); once being edited it holds
// the full-precision value (%.17g), so that a field entered and left unchanged changes nothing and
// a typed value is applied exactly as parsed. Returns the typed value when the text was changed.
std::optional<double> InspectorPanel::number_field(const char* label, double value, bool mixed, int decimals,
                                                   float width) {
  struct Start {
    InspectorPanel* panel;
    ImGuiID id;
    const char* text;
  };
  const ImGuiID id = ImGui::GetID(label);
  char shown[64] = "", full[40] = "";
  if (!mixed) {
    std::snprintf(shown, sizeof shown, "%.*f", decimals, display_value(value, decimals));
    std::snprintf(full, sizeof full, "%.17g", value);
  }
  Start start{this, id, full};
  // The edit buffer begins with the rounded text; the first callback of an entry swaps in the full one.
  const auto swap_in_full = [](ImGuiInputTextCallbackData* data) {
    Start& s = *static_cast<Start*>(data->UserData);
    if (s.panel->precise_id_ == s.id) return 0;
    s.panel->precise_id_ = s.id;
    s.panel->precise_text_ = s.text;
    data->DeleteChars(0, data->BufTextLen);
    data->InsertChars(0, s.text);
    data->SelectionStart = data->BufTextLen;  // all selected, the cursor at the start: the leading digits in view
    data->SelectionEnd = data->CursorPos = 0;
    return 0;
  };
  ImGui::SetNextItemWidth(width);
  const ImGuiInputTextFlags flags =
      ImGuiInputTextFlags_CharsScientific | ImGuiInputTextFlags_AutoSelectAll | ImGuiInputTextFlags_CallbackAlways;
  const bool edited =
      ImGui::InputTextWithHint(label, mixed ? "mixed" : "", shown, sizeof shown, flags, swap_in_full, &start);
  const bool ours = precise_id_ == id;
  if (ImGui::IsItemDeactivated() && ours) precise_id_ = 0;
  if (!edited || !ours || precise_text_ == shown) return std::nullopt;
  char* end = nullptr;
  const double typed = std::strtod(shown, &end);
  while (end && *end == ' ') ++end;
  if (end == shown || !end || *end != '\0' || !std::isfinite(typed)) return std::nullopt;
  return typed;
}

// The mirror partners of the selected vertices (matched at their start positions) take each one's
// change mirrored across the plane: μ_p = μ_p⁰ + M(μ_s − μ_s⁰), and Σ_p = M Σ_s M once Σ_s changed.
void InspectorPanel::mirror_change(EditorDocument& document, const std::vector<int>& vertices) const {
  if (!reach_.mirror) return;
  ReachOptions mirror_only = reach_;
  mirror_only.proportional = false;
  std::vector<Vec3> means(document.mesh().n_vertices());
  for (size_t v = 0; v < means.size(); ++v) means[v] = document.start_mean(int(v));
  Mat3 m = Mat3::Identity();
  m(reach_.mirror_axis, reach_.mirror_axis) = -1.0;
  for (const ReachedVertex& r : edit_reach(means, vertices, mirror_only)) {
    if (!r.mirrored) continue;
    const int s = vertices[r.source];
    document.set_mean(r.vertex,
                      document.start_mean(r.vertex) + m * (document.mesh().mean(size_t(s)) - document.start_mean(s)));
    const Mat3& covariance = document.mesh().covariance(size_t(s));
    document.set_covariance(r.vertex, covariance == document.start_covariance(s) ? document.start_covariance(r.vertex)
                                                                                 : Mat3(m * covariance * m));
  }
}

// Begins the document's edit when a field is activated and commits it when the user leaves it
// (Escape: cancels it, the values as before the entry).
void InspectorPanel::track_entry(EditorDocument& document) {
  if (ImGui::IsItemActivated() && !document.editing()) {
    document.begin_edit();
    entry_open_ = true;
  }
  if (ImGui::IsItemDeactivated() && entry_open_) {
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)))
      document.cancel_edit();
    else
      document.commit_edit();
    entry_open_ = false;
    entry_axes_.reset();
  }
}

void InspectorPanel::draw_means(EditorDocument& document, const std::vector<int>& vertices) {
  static const char* kLabels[] = {"##mean x", "##mean y", "##mean z"};
  for (int k = 0; k < 3; ++k) {
    if (k > 0) ImGui::SameLine();
    if (const auto typed = number_field(kLabels[k], document.mesh().mean(size_t(vertices.front()))[k],
                                        mixed_coordinate(document.mesh(), vertices, k), 4, 80)) {
      for (const int v : vertices) {
        Vec3 m = document.start_mean(v);
        m[k] = *typed;
        document.set_mean(v, m);
      }
      mirror_change(document, vertices);
    }
    track_entry(document);
  }
  ImGui::SameLine();
  ImGui::TextUnformatted("mean");
}

void InspectorPanel::draw_sigmas(EditorDocument& document, const std::vector<int>& vertices, int active) {
  // While a σ is typed, the axes keep the order they had when the entry began (no re-sorting).
  const EllipsoidAxes axes = entry_axes_ ? *entry_axes_ : ellipsoid_axes(document.mesh().covariance(size_t(active)));
  static const char* kLabels[] = {"##sigma 1", "##sigma 2", "##sigma 3"};
  const std::array<bool, 3> mixed = mixed_sigmas(document.mesh(), vertices, active, axes.sigmas);
  for (int k = 0; k < 3; ++k) {
    if (k > 0) ImGui::SameLine();
    ImGui::PushStyleColor(ImGuiCol_Text, kAxisColours[k]);
    ImGui::PushStyleColor(ImGuiCol_TextDisabled, kAxisColours[k]);  // "mixed" in the axis colour too
    const auto typed = number_field(kLabels[k], axes.sigmas[k], mixed[size_t(k)], 5, 80);
    ImGui::PopStyleColor(2);
    if (typed && *typed > 0) {
      for (const int v :
           vertices) {  // σ_k of every selected vertex (its own axis of rank k at the start) set to the value
        EllipsoidAxes e = ellipsoid_axes(document.start_covariance(v));
        e.sigmas[k] = std::clamp(*typed, 1e-5, 1e5);
        document.set_covariance(v, covariance_from_axes(e.axes, e.sigmas));
      }
      mirror_change(document, vertices);
    }
    if (ImGui::IsItemActivated()) entry_axes_ = axes;
    track_entry(document);
  }
  ImGui::SameLine();
  ImGui::TextUnformatted("σ");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("standard deviations along the principal axes (colours as on the gizmo)");
}

void InspectorPanel::draw_rotation(EditorDocument& document, const std::vector<int>& vertices, int active) {
  // The principal frame as Euler angles; a change turns every selected vertex by the same rotation.
  const EllipsoidAxes axes = ellipsoid_axes(document.start_covariance(active));
  const Vec3 angles = euler_degrees(ellipsoid_axes(document.mesh().covariance(size_t(active))).axes);
  static const char* kLabels[] = {"##angle x", "##angle y", "##angle z"};
  for (int k = 0; k < 3; ++k) {
    if (k > 0) ImGui::SameLine();
    if (const auto typed = number_field(kLabels[k], angles[k], false, 2, 80)) {
      Vec3 wanted = euler_degrees(axes.axes);
      wanted[k] = *typed;
      const Mat3 turn = rotation_from_euler_degrees(wanted) * axes.axes.transpose();
      for (const int v : vertices) document.set_covariance(v, rotate_covariance(document.start_covariance(v), turn));
      mirror_change(document, vertices);
    }
    track_entry(document);
  }
  ImGui::SameLine();
  ImGui::TextUnformatted("rotation");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("principal frame as Euler angles in degrees (about x, then y, then z)");
}

void InspectorPanel::draw_presets(EditorDocument& document, const std::vector<int>& vertices) {
  ImGui::TextUnformatted("Presets");
  int preset = -1;
  ImGui::SetNextItemWidth(120);
  ImGui::InputDouble("##sigma", &isotropic_sigma_, 0, 0, "%.4g");
  isotropic_sigma_ = std::clamp(std::isfinite(isotropic_sigma_) ? isotropic_sigma_ : 0.05, 1e-5, 1e5);
  ImGui::SameLine();
  if (ImGui::Button("Isotropic σ")) preset = int(CovariancePreset::isotropic);
  if (ImGui::Button("Flat disc (normal)")) preset = int(CovariancePreset::disc);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("thin along the surface normal: a flat spot");
  ImGui::SameLine();
  if (ImGui::Button("Needle (normal)")) preset = int(CovariancePreset::needle);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("long along the surface normal: a tip");
  if (ImGui::Button("Sharpen ×0.1")) preset = int(CovariancePreset::sharpen);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Σ × 0.1: pulls the surface toward the vertex");
  ImGui::SameLine();
  if (ImGui::Button("Soften ×10")) preset = int(CovariancePreset::soften);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Σ × 10");
  ImGui::SameLine();
  if (ImGui::Button("Reset to inferred")) preset = int(CovariancePreset::inferred);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("the covariance inferred from the mesh around the vertex (GPS Eq. 16-17)");
  if (preset < 0) return;
  const std::vector<Mat3> covariances =
      preset_covariances(document.mesh(), vertices, CovariancePreset(preset), isotropic_sigma_);
  document.begin_edit();
  for (size_t i = 0; i < vertices.size(); ++i)
    document.set_covariance(vertices[i], clamp_spd(covariances[i], document.mesh().covariance(size_t(vertices[i]))));
  mirror_change(document, vertices);
  document.commit_edit();
}

// One sharpness field: typed (applied when the field is left, Escape cancels) or dragged on the
// slider beside it (applied on release); "mixed" where the selection's values differ.
void InspectorPanel::sharpness_field(const char* label, double value, bool corners) {
  const bool mixed = !std::isfinite(value);
  ImGui::PushID(label);
  if (const auto typed = number_field("##typed", mixed ? 0.0 : value, mixed, 2, 80)) sharpness_typed_ = *typed;
  if (ImGui::IsItemDeactivated()) {
    if (sharpness_typed_ && !ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)))
      sharpness_request_ = SharpnessRequest{corners, *sharpness_typed_};
    sharpness_typed_.reset();
  }
  ImGui::SameLine();
  float dragged = mixed ? 0.0f : float(std::min(value, kInfiniteSharpness));
  ImGui::SetNextItemWidth(110);
  ImGui::SliderFloat("##slider", &dragged, 0.0f, float(kInfiniteSharpness),
                     !mixed && is_infinitely_sharp(value) ? "∞" : "%.1f");
  if (ImGui::IsItemDeactivatedAfterEdit()) sharpness_request_ = SharpnessRequest{corners, double(dragged)};
  ImGui::SameLine();
  ImGui::TextUnformatted(label);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(corners ? "corner sharpness of the selected vertices: 0 smooth, 10 = ∞ (Ctrl+Shift+V)"
                              : "crease sharpness of the selected edges: 0 smooth, 10 = ∞ (Shift+E)");
  ImGui::PopID();
}

void InspectorPanel::draw_sharpness(const EditorDocument& document, const Selection& selection) {
  const CovarianceMesh& mesh = document.mesh();
  const auto edges = selection.edges(mesh);
  if (!edges.empty()) sharpness_field("crease", common_crease(mesh, edges), false);
  sharpness_field("corner", common_corner(mesh, selection.vertices()), true);
}

void InspectorPanel::draw(EditorDocument& document, const Selection& selection, ReachOptions& reach, bool* open) {
  if (precise_id_ != 0 && ImGui::GetActiveID() != precise_id_) precise_id_ = 0;  // its field went away while edited
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x + viewport->WorkSize.x - 10, viewport->WorkPos.y + 10),
                          ImGuiCond_FirstUseEver, ImVec2(1, 0));
  ImGui::SetNextWindowSize(ImVec2(360, 300), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Inspector", open)) {
    ImGui::End();
    return;
  }
  reach_ = reach;
  if (!note_.empty()) {
    if (note_error_) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.35f, 0.3f, 1.0f));
    ImGui::TextWrapped("%s", note_.c_str());
    if (note_error_) ImGui::PopStyleColor();
    ImGui::Separator();
  }
  const int active = selection.active();
  if (active < 0) {
    ImGui::TextWrapped(
        "Click a vertex or its ellipsoid to select it; shift-click adds or removes, drag a box to select many.");
  } else {
    const std::vector<int>& vertices = selection.vertices();
    if (vertices.size() == 1)
      ImGui::Text("Vertex %d", active);
    else
      ImGui::Text("Vertex %d and %zu more: a typed value applies to all", active, vertices.size() - 1);
    ImGui::Separator();
    draw_means(document, vertices);
    draw_sigmas(document, vertices, active);
    draw_rotation(document, vertices, active);
    const Mat3& c = document.mesh().covariance(size_t(active));
    ImGui::TextDisabled("Σ = [%.4g %.4g %.4g; %.4g %.4g; %.4g]", c(0, 0), c(0, 1), c(0, 2), c(1, 1), c(1, 2), c(2, 2));
    draw_sharpness(document, selection);
    ImGui::Separator();
    draw_presets(document, vertices);
  }
  ImGui::Separator();
  ImGui::Checkbox("proportional (O)", &reach.proportional);
  if (reach.proportional) {
    ImGui::SetNextItemWidth(90);
    ImGui::InputDouble("radius", &reach.radius, 0, 0, "%.4f");
    reach.radius = std::isfinite(reach.radius) ? std::clamp(reach.radius, 1e-9, 1e9) : 1.0;
    ImGui::SameLine();
    ImGui::SetNextItemWidth(100);
    int falloff = int(reach.falloff);
    if (ImGui::Combo("falloff", &falloff, kFalloffNames)) reach.falloff = Falloff(falloff);
  }
  ImGui::Checkbox("mirror (Shift+M)", &reach.mirror);
  if (reach.mirror) {
    ImGui::SameLine();
    ImGui::SetNextItemWidth(60);
    ImGui::Combo("across", &reach.mirror_axis, "x\0y\0z\0");
  }
  ImGui::End();
}

}  // namespace gps
