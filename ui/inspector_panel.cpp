#include "ui/inspector_panel.h"

#include <imgui.h>

#include <Eigen/Geometry>
#include <cmath>

#include "ui/covariance_edit.h"
#include "ui/covariance_presets.h"

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
  return (Eigen::AngleAxisd(r.z(), Vec3::UnitZ()) * Eigen::AngleAxisd(r.y(), Vec3::UnitY()) * Eigen::AngleAxisd(r.x(), Vec3::UnitX()))
      .toRotationMatrix();
}

namespace {

// Begins an undo step when a numeric field is activated and commits it when the user leaves it.
void track_entry(std::optional<VertexEdit>& entry, EditorDocument& document, const Selection& selection) {
  if (ImGui::IsItemActivated()) entry = EditHistory::begin(document.mesh, selection.vertices());
  if (ImGui::IsItemDeactivated() && entry) {
    if (ImGui::IsItemDeactivatedAfterEdit()) document.history.commit(std::move(*entry), document.mesh);
    entry.reset();
  }
}

}  // namespace

std::vector<int> InspectorPanel::apply_preset(EditorDocument& document, const Selection& selection, int preset) {
  const std::vector<int>& vertices = selection.vertices();
  const std::vector<Mat3> covariances =
      preset_covariances(document.mesh, vertices, CovariancePreset(preset), isotropic_sigma_);
  VertexEdit edit = EditHistory::begin(document.mesh, vertices);
  for (size_t i = 0; i < vertices.size(); ++i)
    document.mesh.covariances[size_t(vertices[i])] = clamp_spd(covariances[i], document.mesh.covariance(size_t(vertices[i])));
  document.history.commit(std::move(edit), document.mesh);
  return vertices;
}

std::vector<int> InspectorPanel::draw(EditorDocument& document, const Selection& selection, bool* open) {
  std::vector<int> changed;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x + viewport->WorkSize.x - 10, viewport->WorkPos.y + 10), ImGuiCond_FirstUseEver,
                          ImVec2(1, 0));
  ImGui::SetNextWindowSize(ImVec2(360, 300), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Inspector", open)) {
    ImGui::End();
    return changed;
  }
  const int active = selection.active();
  if (active < 0) {
    ImGui::TextWrapped("Click a vertex or its ellipsoid to select it; shift-click adds or removes, drag a box to select many.");
    ImGui::End();
    return changed;
  }
  CovarianceMesh& mesh = document.mesh;
  const std::vector<int>& vertices = selection.vertices();
  if (vertices.size() == 1) ImGui::Text("Vertex %d", active);
  else ImGui::Text("Vertex %d and %zu more: changes apply to all", active, vertices.size() - 1);
  ImGui::Separator();

  // Mean: the same displacement for every selected vertex.
  Vec3 mean = mesh.mean(size_t(active));
  const Vec3 old_mean = mean;
  if (ImGui::InputScalarN("mean", ImGuiDataType_Double, mean.data(), 3, nullptr, nullptr, "%.6g") && mean.allFinite()) {
    const Vec3 delta = mean - old_mean;
    for (const int v : vertices) mesh.set_mean(size_t(v), mesh.mean(size_t(v)) + delta);
    changed = vertices;
  }
  track_entry(entry_, document, selection);

  // Standard deviations: each axis rank scaled by the same factor.
  const EllipsoidAxes axes = ellipsoid_axes(mesh.covariance(size_t(active)));
  Vec3 sigmas = axes.sigmas;
  if (ImGui::InputScalarN("sigma", ImGuiDataType_Double, sigmas.data(), 3, nullptr, nullptr, "%.6g") && sigmas.allFinite()) {
    const Vec3 factors = sigmas.cwiseMax(1e-5).cwiseQuotient(axes.sigmas.cwiseMax(1e-300));
    for (const int v : vertices) {
      Mat3 c = mesh.covariance(size_t(v));
      const Mat3 before = c;
      for (int a = 0; a < 3; ++a) c = scale_axis(c, a, factors[a]);
      mesh.covariances[size_t(v)] = clamp_spd(c, before);
    }
    changed = vertices;
  }
  track_entry(entry_, document, selection);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("standard deviations along the principal axes, smallest first");

  // Orientation: the principal frame as Euler angles; the same rotation for every selected vertex.
  Vec3 angles = euler_degrees(axes.axes);
  if (ImGui::InputScalarN("rotation", ImGuiDataType_Double, angles.data(), 3, nullptr, nullptr, "%.2f") && angles.allFinite()) {
    const Mat3 turn = rotation_from_euler_degrees(angles) * axes.axes.transpose();
    for (const int v : vertices) mesh.covariances[size_t(v)] = rotate_covariance(mesh.covariance(size_t(v)), turn);
    changed = vertices;
  }
  track_entry(entry_, document, selection);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("principal frame as Euler angles in degrees (about x, then y, then z)");

  const Mat3& c = mesh.covariance(size_t(active));
  ImGui::TextDisabled("Σ = [%.4g %.4g %.4g; %.4g %.4g; %.4g]", c(0, 0), c(0, 1), c(0, 2), c(1, 1), c(1, 2), c(2, 2));
  ImGui::Separator();
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
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("the covariance inferred from the mesh around the vertex (GPS Eq. 16-17)");
  if (preset >= 0) changed = apply_preset(document, selection, preset);
  ImGui::End();
  return changed;
}

}  // namespace gps
