#pragma once
// The editor's status bar: mesh size, selection, unsaved changes, and the last message (errors in red).
#include <string>

#include "ui/editor_document.h"

namespace gps {

/// Draws the bar along the bottom of the window.
void draw_status_bar(const EditorDocument& document, size_t selected, const std::string& message, bool error);

}  // namespace gps
