#include "ui/panels/status_bar.h"

#include <imgui.h>

namespace gps {

void draw_status_bar(const EditorDocument& document, const std::string& selection, const std::string& message,
                     bool error) {
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  const float height = ImGui::GetFrameHeight() + 4.0f;
  ImGui::SetNextWindowPos(ImVec2(vp->WorkPos.x, vp->WorkPos.y + vp->WorkSize.y - height));
  ImGui::SetNextWindowSize(ImVec2(vp->WorkSize.x, height));
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings |
                                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoBringToFrontOnFocus;
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(8, 2));
  if (ImGui::Begin("##status", nullptr, flags)) {
    ImGui::Text("%zu vertices, %zu faces, %s%s", document.mesh().n_vertices(), document.mesh().n_faces(),
                selection.c_str(), document.dirty() ? "  (unsaved changes)" : "");
    if (!message.empty()) {
      ImGui::SameLine(0, 24);
      if (error)
        ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.3f, 1.0f), "%s", message.c_str());
      else
        ImGui::TextUnformatted(message.c_str());
    }
  }
  ImGui::End();
  ImGui::PopStyleVar();
}

}  // namespace gps
