#pragma once
// The F1 help: every mouse and key binding of the editor.
namespace gps {

/// Draws the help window while *open.
void draw_help_overlay(bool* open);

}  // namespace gps
