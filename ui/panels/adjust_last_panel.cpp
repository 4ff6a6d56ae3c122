#include "ui/panels/adjust_last_panel.h"

#include <imgui.h>

#include <algorithm>

namespace gps {

namespace {
// Where the panel sits: below the statistics, clear of the Inspector and View panels on the right.
constexpr float kAdjustPanelX = 10.0f, kAdjustPanelY = 230.0f;
}  // namespace

std::optional<std::vector<double>> draw_adjust_last_panel(bool& shown, const AdjustableOperation* operation) {
  if (!shown) return std::nullopt;
  ImGui::SetNextWindowPos(ImVec2(kAdjustPanelX, kAdjustPanelY), ImGuiCond_Always);
  if (!ImGui::Begin("Adjust last operation", &shown,
                    ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings)) {
    ImGui::End();
    return std::nullopt;
  }
  if (!operation) {
    ImGui::TextDisabled("no operation to adjust: extrude, duplicate, inset, loop cut, bevel, spin or grid fill first");
    ImGui::End();
    return std::nullopt;
  }
  std::vector<double> values;
  for (const AdjustableParameter& p : operation->parameters) values.push_back(p.value);
  bool entered = false;
  const ImGuiInputTextFlags flags = ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll;
  for (size_t k = 0; k < values.size(); ++k) {
    const AdjustableParameter& p = operation->parameters[k];
    ImGui::SetNextItemWidth(120.0f);
    if (p.integer) {
      int n = int(values[k]);
      if (ImGui::InputInt(p.label.c_str(), &n, 1, 10, flags)) values[k] = double(n), entered = true;
    } else {
      if (ImGui::InputDouble(p.label.c_str(), &values[k], 0.0, 0.0, "%.4g", flags)) entered = true;
    }
    values[k] = std::clamp(values[k], p.min, p.max);
  }
  ImGui::TextDisabled("%s: Enter applies", operation->name.c_str());
  ImGui::End();
  if (!entered) return std::nullopt;
  return values;
}

}  // namespace gps
