#include "ui/panels/file_browser.h"

#include <cstdio>
#include <cstdlib>
#include <utility>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "core/support/error.h"
#include "ui/input/input_events.h"

namespace gps {
namespace fs = std::filesystem;
namespace {

constexpr const char* replace_popup = "Replace?";

/// "512 B", "3.4 KB", "12.0 MB" …
std::string size_text(std::uintmax_t bytes) {
  const char* units[] = {"B", "KB", "MB", "GB", "TB"};
  double value = double(bytes);
  int unit = 0;
  for (; value >= 1024 && unit < 4; ++unit) value /= 1024;
  char text[32];
  std::snprintf(text, sizeof text, unit == 0 ? "%.0f %s" : "%.1f %s", value, units[unit]);
  return text;
}


}  // namespace

void FileBrowser::open(Mode mode, const std::string& title, const std::string& directory,
                       std::vector<std::string> extensions, const std::string& file_name) {
  mode_ = mode;
  title_ = title;
  extensions_ = std::move(extensions);
  file_name_ = file_name;
  entries_.clear();
  replace_.reset();
  result_.reset();
  std::error_code ec;
  directory_ = fs::current_path(ec);
  path_text_ = directory_.string();
  if (!navigate(directory)) {
    const std::string why = error_;
    navigate(".");
    error_ = why;
  }
  open_requested_ = focus_name_ = select_name_ = true;
}

/// `text` ("~" for $HOME) against the current folder, absolute and normal, without a trailing '/'.
fs::path FileBrowser::resolve(const std::string& text) const {
  fs::path path = text;
  const char* home = std::getenv("HOME");
  if (home && (text == "~" || text.starts_with("~/"))) path = fs::path(home) / text.substr(text.size() > 1 ? 2 : 1);
  if (path.is_relative()) path = directory_ / path;
  path = path.lexically_normal();
  if (!path.has_filename() && path != path.root_path()) path = path.parent_path();
  return path;
}

/// Lists `folder` and makes it current; false (the error shown, folder and path bar unchanged) when it cannot.
bool FileBrowser::navigate(const std::string& folder) {
  const fs::path target = resolve(folder);
  try {
    entries_ = list_directory(target.string(), extensions_, show_hidden_);
  } catch (const Error& e) {
    error_ = e.what();
    return false;
  }
  directory_ = target;
  path_text_ = directory_.string();
  error_.clear();
  return true;
}

/// Acts on the file-name field: enters a folder, reports a bad name, asks before replacing, or confirms.
void FileBrowser::confirm_name() {
  focus_name_ = true;
  const size_t first = file_name_.find_first_not_of(" \t"), last = file_name_.find_last_not_of(" \t");
  if (first == std::string::npos) return;
  fs::path target = resolve(file_name_.substr(first, last - first + 1));
  std::error_code ec;
  if (fs::is_directory(target, ec)) {
    if (navigate(target.string())) file_name_.clear();
    return;
  }
  if (mode_ == Mode::save && !extensions_.empty() && !has_extension(target.filename().string(), extensions_))
    target += extensions_.front();
  const fs::file_status status = fs::status(target, ec);
  if (mode_ == Mode::open && !fs::is_regular_file(status)) {
    error_ = target.string() + ": no such file";
  } else if (mode_ == Mode::save && fs::is_directory(status)) {
    error_ = target.string() + ": is a folder";
  } else if (mode_ == Mode::save && !fs::is_directory(target.parent_path(), ec)) {
    error_ = target.parent_path().string() + ": no such folder";
  } else if (mode_ == Mode::save && fs::exists(status)) {
    replace_ = target.string();
    ImGui::OpenPopup(replace_popup);
  } else {
    result_ = target.string();
  }
}

std::optional<std::string> FileBrowser::draw() {
  if (open_requested_) {
    ImGui::OpenPopup(title_.c_str());
    open_requested_ = false;
    open_ = true;
  }
  if (!open_) return std::nullopt;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowSize(ImVec2(display.x * 0.7f, display.y * 0.7f), ImGuiCond_Appearing);
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (!ImGui::BeginPopupModal(title_.c_str())) {  // closed by someone else
    open_ = false;
    return std::nullopt;
  }
  bool cancel = !replace_ && imgui_key_pressed(ImGuiKey_Escape);  // with "Replace?" up, Escape answers that

  const ImGuiStyle& style = ImGui::GetStyle();
  if (ImGui::Button("Up")) navigate("..");
  ImGui::SameLine();
  const float hidden_width = ImGui::GetFrameHeight() + style.ItemInnerSpacing.x + ImGui::CalcTextSize("Hidden").x;
  ImGui::SetNextItemWidth(-(hidden_width + style.ItemSpacing.x));
  if (ImGui::InputText("##folder", &path_text_, ImGuiInputTextFlags_EnterReturnsTrue)) {
    if (navigate(path_text_))
      focus_name_ = true;
    else
      ImGui::SetKeyboardFocusHere(-1);  // keep the typed path to correct it
  }
  ImGui::SameLine();
  if (ImGui::Checkbox("Hidden", &show_hidden_)) navigate(".");
  if (!error_.empty()) ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.35f, 1.0f), "%s", error_.c_str());

  bool confirm = draw_listing(ImGui::GetFrameHeightWithSpacing());
  const float button_width = ImGui::CalcTextSize("Cancel").x + style.FramePadding.x * 2 + ImGui::GetFontSize();
  if (focus_name_ && !replace_) {
    ImGui::SetKeyboardFocusHere();
    focus_name_ = false;
  }
  ImGui::SetNextItemWidth(-2 * (button_width + style.ItemSpacing.x));
  const ImGuiInputTextFlags select = select_name_ ? ImGuiInputTextFlags_AutoSelectAll : 0;
  confirm |=
      ImGui::InputTextWithHint("##name", "file name", &file_name_, ImGuiInputTextFlags_EnterReturnsTrue | select);
  if (ImGui::IsItemActive()) select_name_ = false;  // selected once on opening; later the text is kept to fix
  ImGui::SameLine();
  confirm |= ImGui::Button(mode_ == Mode::open ? "Open" : "Save", ImVec2(button_width, 0));
  ImGui::SameLine();
  cancel |= ImGui::Button("Cancel", ImVec2(button_width, 0));
  if (confirm && !cancel) confirm_name();
  draw_replace_question();

  std::optional<std::string> result = std::exchange(result_, std::nullopt);
  if (result || cancel) {
    open_ = false;
    replace_.reset();
    ImGui::CloseCurrentPopup();  // also closes "Replace?"
  }
  ImGui::EndPopup();
  return result;
}

/// The folder's entries in a scrolling child region; true when a file was double-clicked.
bool FileBrowser::draw_listing(float footer_height) {
  bool chosen = false;
  std::optional<std::string> entered;
  ImGui::BeginChild("##listing", ImVec2(0, -footer_height), true);
  if (ImGui::BeginTable("##entries", 2, ImGuiTableFlags_RowBg)) {
    ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableSetupColumn("size", ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize("1023.9 MB").x);
    for (size_t i = 0; i < entries_.size(); ++i) {
      const DirectoryEntry& entry = entries_[i];
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::PushID(int(i));
      const bool selected = !entry.is_directory && entry.name == file_name_;
      if (ImGui::Selectable("##row", selected,
                            ImGuiSelectableFlags_SpanAllColumns | ImGuiSelectableFlags_AllowDoubleClick)) {
        const bool twice = ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left);
        if (entry.is_directory && twice) entered = entry.name;
        if (!entry.is_directory) {
          file_name_ = entry.name;
          chosen = twice;
        }
      }
      ImGui::PopID();
      ImGui::SameLine();  // the name as plain text: "##" or "%" in it stays visible
      ImGui::TextUnformatted(entry.is_directory ? (entry.name + "/").c_str() : entry.name.c_str());
      ImGui::TableNextColumn();
      if (!entry.is_directory) ImGui::TextUnformatted(size_text(entry.size).c_str());
    }
    ImGui::EndTable();
  }
  ImGui::EndChild();
  if (entered) navigate(*entered);
  return chosen;
}

/// The nested "Replace X?" question; Replace (or Enter) confirms the pending path, Cancel (or Escape) returns.
void FileBrowser::draw_replace_question() {
  if (!ImGui::BeginPopupModal(replace_popup, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  const bool appearing = ImGui::IsWindowAppearing();  // the Enter that asked must not also answer
  const fs::path path = replace_.value_or("");
  ImGui::Text("Replace %s?", path.filename().c_str());
  ImGui::TextDisabled("It already exists in %s.", path.parent_path().c_str());
  const bool enter = imgui_key_pressed(ImGuiKey_Enter) || imgui_key_pressed(ImGuiKey_KeyPadEnter);
  if (ImGui::Button("Replace") || (enter && !appearing)) result_ = replace_;
  ImGui::SameLine();
  if (ImGui::Button("Cancel") || imgui_key_pressed(ImGuiKey_Escape)) {
    replace_.reset();
    focus_name_ = true;
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

}  // namespace gps
