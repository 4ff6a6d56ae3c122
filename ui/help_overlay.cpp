#include "ui/help_overlay.h"

#include <imgui.h>

namespace gps {

namespace {
constexpr const char* kBindings[][2] = {
    {"Left click", "select a vertex or its ellipsoid (nothing: clear)"},
    {"Shift + left click", "add or remove a vertex"},
    {"Left drag on empty space", "box select (Shift: add)"},
    {"Left drag an axis end", "along the axis: scale that sigma; across: rotate the frame"},
    {"Left drag the centre dot", "move the mean(s)"},
    {"Right / middle drag, Alt + left drag", "orbit"},
    {"Shift + right / middle drag", "pan"},
    {"Wheel", "zoom toward the cursor"},
    {"F", "frame the selection (all when none)"},
    {"Home", "frame all"},
    {"Ctrl+A / Escape", "select all / none"},
    {"Ctrl+Z", "undo"},
    {"Ctrl+Shift+Z, Ctrl+Y", "redo"},
    {"Ctrl+O", "open"},
    {"Ctrl+S / Ctrl+Shift+S", "save / save as"},
    {"F12", "screenshot (PNG in the current folder)"},
    {"F1", "this help"},
    {"Ctrl+Q", "quit"},
};
}  // namespace

void draw_help_overlay(bool* open) {
  if (!*open) return;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x + viewport->WorkSize.x * 0.5f, viewport->WorkPos.y + viewport->WorkSize.y * 0.5f),
                          ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (ImGui::Begin("Help (F1)", open, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse)) {
    if (ImGui::BeginTable("bindings", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
      for (const auto& row : kBindings) {
        ImGui::TableNextRow();
        ImGui::TableSetColumnIndex(0);
        ImGui::TextUnformatted(row[0]);
        ImGui::TableSetColumnIndex(1);
        ImGui::TextUnformatted(row[1]);
      }
      ImGui::EndTable();
    }
    ImGui::TextDisabled("Files: drop a mesh on the window to open it.");
  }
  ImGui::End();
}

}  // namespace gps
