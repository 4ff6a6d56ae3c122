#pragma once
// An in-app Open / Save dialog drawn with Dear ImGui as a modal popup (no native dialogs, no GL).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "ui/panels/directory_listing.h"

namespace gps {

class FileBrowser {
public:
  enum class Mode { open, save };

  /// Opens the dialog at the next draw(): title, starting folder (one that cannot be listed falls back
  /// to the working folder, with the error shown), the extensions it lists (e.g. {".ply", ".obj"}; in
  /// save mode the first is appended to a name without any of them), and for save a proposed file name.
  void open(Mode mode, const std::string& title, const std::string& directory, std::vector<std::string> extensions,
            const std::string& file_name = "");

  /// Draws the dialog while it is open (every frame between ImGui::NewFrame and ImGui::Render, outside
  /// any window); returns the chosen absolute path once, on the frame the user confirms.
  std::optional<std::string> draw();

  /// Whether the dialog is (or is about to be) shown.
  bool is_open() const { return open_requested_ || open_; }

private:
  std::filesystem::path resolve(const std::string& text) const;
  bool navigate(const std::string& folder);
  void confirm_name();
  bool draw_listing(float footer_height);
  void draw_replace_question();

  Mode mode_ = Mode::open;
  std::string title_;
  std::filesystem::path directory_;
  std::vector<std::string> extensions_;
  std::vector<DirectoryEntry> entries_;
  std::string path_text_, file_name_, error_;
  bool show_hidden_ = false, open_requested_ = false, open_ = false, focus_name_ = false, select_name_ = false;
  std::optional<std::string> replace_, result_;  // a path awaiting "Replace?"; the confirmed path
};

}  // namespace gps
