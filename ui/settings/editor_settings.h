#pragma once
// What the editor keeps between sessions in the user's configuration folder (XDG base directory
// specification): the View settings and the edit reach (settings.json), the panel layout
// (imgui.ini, written by Dear ImGui) and the recent files (recent.txt).
#include <string>

#include "ui/editing/edit_reach.h"
#include "ui/panels/view_options.h"

namespace gps {

/// $XDG_CONFIG_HOME/gpsurf, else $HOME/.config/gpsurf; "" when neither is set (nothing is kept).
std::string config_folder();

/// Reads settings.json from `folder` into the options; a missing file keeps them, a malformed one
/// (or a value of the wrong type) is reported in the returned one-line message and the rest kept.
std::string load_settings(const std::string& folder, ViewOptions& view, ReachOptions& reach);

/// Writes settings.json into `folder` (created when missing); returns "" or a one-line error.
std::string save_settings(const std::string& folder, const ViewOptions& view, const ReachOptions& reach);

}  // namespace gps
