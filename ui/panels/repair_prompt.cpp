#include "ui/panels/repair_prompt.h"

#include <imgui.h>

#include <filesystem>

#include "core/io/mesh_io.h"
#include "core/io/mesh_repair.h"
#include "core/support/error.h"

namespace gps {

namespace {
constexpr const char* kTitle = "Repair mesh?";
}

RepairFindings repair_findings(const std::string& path, const ImportOptions& options) {
  RepairFindings findings;
  try {
    bool has_covariances = false;
    PolygonSoup soup = read_polygon_soup(path, has_covariances);
    const RepairReport report = diagnose_polygon_soup(soup, repair_options_for(options));
    if (!report.changed()) return findings;
    // Offered only where the repaired mesh opens: no flipping orients a Möbius-like part, and a
    // Gaussian the file gives may be refused whatever the faces.
    ImportOptions repairing = options;
    repairing.repair = true;
    read_mesh_of_soup(std::move(soup), has_covariances, path, repairing);
    const ElementNumbering numbering = element_numbering_for(path, report);
    findings.refused = report.problems(numbering, true);
    findings.others = report.problems(numbering, false);
  } catch (const Error&) {  // not readable, or not even once repaired: the reader's own message says why
  }
  return findings;
}

void RepairPrompt::open(const std::string& path, RepairFindings findings, const std::string& refusal, bool opened) {
  path_ = path;
  findings_ = std::move(findings);
  refusal_ = refusal;
  opened_ = opened;
  open_ = popup_requested_ = true;
}

RepairPrompt::Answer RepairPrompt::draw() {
  if (!open_) return Answer::none;
  if (popup_requested_) {
    ImGui::OpenPopup(kTitle);
    popup_requested_ = false;
  }
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(vp->WorkPos.x + 0.5f * vp->WorkSize.x, vp->WorkPos.y + 0.5f * vp->WorkSize.y),
                          ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (!ImGui::BeginPopupModal(kTitle, nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings))
    return Answer::none;
  const std::string name = std::filesystem::path(path_).filename().string();
  if (opened_) {
    ImGui::Text("%s opened as it is, but the repair would mend:", name.c_str());
  } else {
    ImGui::Text("%s cannot be opened as it is:", name.c_str());
    for (const std::string& line : findings_.refused) ImGui::BulletText("%s", line.c_str());
    if (findings_.refused.empty()) ImGui::BulletText("%s", refusal_.c_str());
  }
  if (!findings_.others.empty()) {
    if (!opened_) ImGui::Text(findings_.refused.empty() ? "Repair mends:" : "Repair also mends:");
    for (const std::string& line : findings_.others) ImGui::BulletText("%s", line.c_str());
  }
  ImGui::Separator();
  ImGui::Text(opened_ ? "Repair opens the repaired mesh, unsaved; Cancel keeps the mesh as read."
                      : "Repair opens the repaired mesh, unsaved; Cancel keeps the current mesh.");
  Answer answer = Answer::none;
  if (ImGui::Button("Repair") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter))) answer = Answer::repair;
  ImGui::SameLine();
  if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) answer = Answer::cancel;
  if (answer != Answer::none) {
    ImGui::CloseCurrentPopup();
    open_ = false;
  }
  ImGui::EndPopup();
  return answer;
}

}  // namespace gps
