#include "ui/panels/job_dialog.h"

#include <imgui.h>

#include "core/support/error.h"
#include "ui/input/input_events.h"

namespace gps {

void JobDialog::open(Spec spec) {
  close();
  spec_ = std::move(spec);
  open_ = popup_requested_ = true;
}

void JobDialog::close() {
  if (job_.active()) {
    job_.cancel();
    std::string ignored;
    while (job_.active() && !job_.finished()) std::this_thread::yield();
    job_.take(ignored);
  }
  made_.reset();
  note_.clear();
  note_is_error_ = false;
  open_ = false;
}

void JobDialog::start() {
  made_.reset();
  note_.clear();
  note_is_error_ = false;
  try {
    job_.start(spec_.work());
  } catch (const Error& e) {
    note_ = e.what();
    note_is_error_ = true;
  }
}

std::optional<Modelled> JobDialog::draw() {
  if (!open_) return std::nullopt;
  if (popup_requested_) {
    ImGui::OpenPopup(spec_.title.c_str());
    popup_requested_ = false;
  }
  if (job_.active() && job_.finished()) {
    std::string refusal;
    made_ = job_.take(refusal);
    note_ = made_ ? made_->summary : refusal;
    note_is_error_ = !made_;
  }
  std::optional<Modelled> applied;
  const ImVec2 centre = ImGui::GetMainViewport()->GetCenter();
  ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (!ImGui::BeginPopupModal(spec_.title.c_str(), nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    close();  // closed by ImGui (a new popup on top)
    return std::nullopt;
  }
  const bool appearing = ImGui::IsWindowAppearing();  // the Enter that opened it must not also start
  const bool enter = !appearing && (imgui_key_pressed(ImGuiKey_Enter) || imgui_key_pressed(ImGuiKey_KeyPadEnter));
  const bool escape = imgui_key_pressed(ImGuiKey_Escape);
  if (running()) {
    ImGui::ProgressBar(float(job_.progress()), ImVec2(320.0f, 0.0f));
    if (ImGui::Button("Cancel") || escape) job_.cancel();
  } else {
    ImGui::BeginDisabled(made_.has_value());
    spec_.settings();
    ImGui::EndDisabled();
    if (!note_.empty()) {
      ImGui::Separator();
      if (note_is_error_) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
      ImGui::PushTextWrapPos(ImGui::GetFontSize() * 28.0f);
      ImGui::TextUnformatted(note_.c_str());
      ImGui::PopTextWrapPos();
      if (note_is_error_) ImGui::PopStyleColor();
    }
    ImGui::Separator();
    if (made_) {
      if (ImGui::Button("Apply") || enter) applied = std::move(made_);
      ImGui::SameLine();
      if (ImGui::Button("Discard") || (escape && !applied)) {
        made_.reset();
        note_.clear();
      }
    } else {
      if (ImGui::Button("Start") || enter) start();
      ImGui::SameLine();
      if (ImGui::Button("Close") || escape) {
        close();
        ImGui::CloseCurrentPopup();
      }
    }
    if (applied) {
      close();
      ImGui::CloseCurrentPopup();
    }
  }
  ImGui::EndPopup();
  return applied;
}

}  // namespace gps
