#pragma once
// The editor's status bar: mesh size, selection and its mode, unsaved changes, and the last message
// (errors in red).
#include <string>

#include "ui/document/editor_document.h"

namespace gps {

/// Draws the bar along the bottom of the window; `selection` says what is selected ("3 selected,
/// edge mode: 2 edges").
void draw_status_bar(const EditorDocument& document, const std::string& selection, const std::string& message,
                     bool error);

}  // namespace gps
