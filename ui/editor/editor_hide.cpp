// Hide and reveal (Blender's H, Shift+H, Alt+H): the hidden faces' patches and lines are left out of
// the frame, hidden elements out of picking and the selection. A view state: not saved, not undone;
// an operation that changes the topology shows everything again.
#include <GLFW/glfw3.h>

#include "core/modelling/operation_words.h"
#include "ui/editor/editor_app.h"

namespace gps {

void EditorApp::build_hide_commands() {
  const auto key = [](int k, bool ctrl = false, bool shift = false, bool alt = false) {
    return Shortcut{k, ctrl, shift, alt};
  };
  CommandTable& t = commands_;
  t.add({"Select",
         "Hide selected",
         {key(GLFW_KEY_H)},
         [this] { hide(false); },
         [this] { return !selection_.empty(); },
         nullptr,
         nullptr,
         true});
  t.add({"Select", "Hide unselected", {key(GLFW_KEY_H, false, true)}, [this] { hide(true); }});
  t.add({"Select",
         "Reveal hidden",
         {key(GLFW_KEY_H, false, false, true)},
         [this] { reveal(); },
         [this] { return !hidden_.elements().empty(); }});
}

void EditorApp::hide(bool unselected) {
  if (shown_->preview()) return;  // a modal tool's preview is another mesh
  const size_t faces = hidden_.elements().hide(document_.mesh(), selection_, select_mode_, unselected);
  refresh_hidden();
  set_status(std::string(unselected ? "hide unselected: " : "hide: ") + count_of(faces, "face", "faces") + " hidden (" +
                 count_of(hidden_.elements().faces().size(), "face", "faces") + " in all; Alt+H shows them)",
             false);
}

void EditorApp::reveal() {
  const size_t faces = hidden_.elements().reveal(document_.mesh(), selection_, select_mode_);
  refresh_hidden();
  set_status("reveal: " + count_of(faces, "face", "faces") + " shown and selected", false);
}

void EditorApp::deselect_hidden() { hidden_.elements().deselect_hidden(document_.mesh(), selection_, select_mode_); }

void EditorApp::refresh_hidden() {
  if (const std::string refusal = hidden_.refresh(document_.mesh(), *shown_); !refusal.empty())
    set_status("hide: " + refusal, true);
}

}  // namespace gps
