#include "ui/panels/help_overlay.h"

#include <imgui.h>

namespace gps {

namespace {
constexpr const char* kMouseBindings[][2] = {
    {"Left click", "select a vertex or its ellipsoid / an edge / a face, by the mode (nothing: clear)"},
    {"Shift + left click", "add or remove a vertex, edge or face"},
    {"Alt + left click", "select the edge loop through the nearest edge (face mode: the face loop)"},
    {"Left drag on empty space", "box select what the camera sees (Shift: add, Ctrl: remove; X-ray: hidden too)"},
    {"Left drag an axis end", "along the axis: scale that sigma; across: turn the frame (decided by the first pixels)"},
    {"  ... with Shift / Ctrl", "scale all three sigmas / snap ratios (0.1) and angles (5 deg)"},
    {"Left drag the centre dot", "move the mean(s) in the view plane"},
    {"  ... then X, Y, Z / Shift+X, Y, Z / N", "along that axis / in the plane normal to it / along the normal"},
    {"  ... then digits, Enter", "type the distance; Escape cancels the drag"},
    {"Wheel while dragging", "proportional radius (when proportional editing is on)"},
    {"G / S / R, then X, Y, Z / Shift+X, Y, Z", "grab, scale, rotate; along that axis / in the plane normal to it"},
    {"  ... then digits, Enter / click", "type the amount (distance, factor, degrees); Escape / right click cancels"},
    {"Ctrl+R, wheel, click, move, click", "loop cut: cuts under the cursor, then slide"},
    {"G G, move or digits, Enter / click", "slide the selected edges along their faces, or one vertex along an edge"},
    {"Ctrl+B / Ctrl+Shift+B, move or digits", "bevel the selected edges / vertices; wheel: segments, P: profile"},
    {"Right / middle drag, Alt + left drag", "orbit"},
    {"Shift + right / middle drag", "pan"},
    {"Wheel", "zoom toward the cursor"},
};
}  // namespace

void draw_help_overlay(bool* open, const std::vector<std::pair<std::string, std::string>>& key_bindings) {
  if (!*open) return;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(
      ImVec2(viewport->WorkPos.x + viewport->WorkSize.x * 0.5f, viewport->WorkPos.y + viewport->WorkSize.y * 0.5f),
      ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (ImGui::Begin("Help (F1)", open, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse)) {
    if (ImGui::BeginTable("bindings", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
      const auto row = [](const char* keys, const char* what) {
        ImGui::TableNextRow();
        ImGui::TableSetColumnIndex(0);
        ImGui::TextUnformatted(keys);
        ImGui::TableSetColumnIndex(1);
        ImGui::TextUnformatted(what);
      };
      for (const auto& r : kMouseBindings) row(r[0], r[1]);
      for (const auto& [keys, what] : key_bindings) row(keys.c_str(), what.c_str());
      ImGui::EndTable();
    }
    ImGui::TextDisabled("Files: drop a mesh on the window to open it.");
  }
  ImGui::End();
}

}  // namespace gps
