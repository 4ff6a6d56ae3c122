#pragma once
// The F1 help: the mouse bindings and every key binding of the command table.
#include <string>
#include <utility>
#include <vector>

namespace gps {

/// Draws the help window while *open; `key_bindings` are (keys, what they do) rows.
void draw_help_overlay(bool* open, const std::vector<std::pair<std::string, std::string>>& key_bindings);

}  // namespace gps
