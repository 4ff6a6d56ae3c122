// Hide and reveal (Blender's H, Shift+H, Alt+H): the hidden faces' patches and lines are left out of
// the frame, hidden elements out of picking and the selection. A view state: not saved, not undone;
// an operation that changes the topology shows everything again.
#include <GLFW/glfw3.h>

#include "core/modelling/operation_words.h"
#include "core/plans/patch_faces.h"
#include "core/support/error.h"
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
         [this] { return !hidden_.empty(); }});
}

void EditorApp::hide(bool unselected) {
  if (shown_->preview()) return;  // a modal tool's preview is another mesh
  const size_t faces = hidden_.hide(document_.mesh(), selection_, select_mode_, unselected);
  refresh_hidden();
  set_status(std::string(unselected ? "hide unselected: " : "hide: ") + count_of(faces, "face", "faces") + " hidden (" +
                 count_of(hidden_.faces().size(), "face", "faces") + " in all; Alt+H shows them)",
             false);
}

void EditorApp::reveal() {
  const size_t faces = hidden_.reveal(document_.mesh(), selection_, select_mode_);
  refresh_hidden();
  set_status("reveal: " + count_of(faces, "face", "faces") + " shown and selected", false);
}

void EditorApp::deselect_hidden() { hidden_.deselect_hidden(document_.mesh(), selection_, select_mode_); }

void EditorApp::refresh_hidden() {
  hidden_seen_ = shown_->topology_revision();
  hidden_patches_.clear();
  hidden_cage_edges_.clear();
  hidden_vertex_mask_.clear();
  hidden_edge_mask_.clear();
  hidden_face_mask_.clear();
  if (hidden_.empty()) return;
  const CovarianceMesh& mesh = document_.mesh();
  hidden_vertex_mask_ = hidden_.vertex_mask(mesh.n_vertices());
  hidden_edge_mask_ = hidden_.edge_mask(mesh);
  hidden_face_mask_ = hidden_.face_mask(mesh.n_faces());
  if (shown_->preview()) return;  // a modal tool's preview, another mesh, is drawn whole
  // With the mirror modifier, the half's faces and vertices keep their indices in the mesh shown
  // (core/modelling/mirror.h): its mirror image stays drawn.
  const CovarianceMesh& shown = shown_->drawn(mesh);
  try {
    hidden_patches_ = patches_of_faces(shown.topology(), shown_->renderer().tables().plans, hidden_.faces());
  } catch (const Error& e) {  // not the renderer's mesh: nothing is left out rather than the wrong patches
    set_status(std::string("hide: ") + e.what(), true);
  }
  hidden_cage_edges_ = hidden_.edge_mask(shown);
}

}  // namespace gps
