// The editor's modelling operations applied: a result installed as one undo step (the surface
// re-planned around the change, the document given the mesh, the selection and hidden faces carried
// over), and the same after an undo or redo.
#include <optional>
#include <utility>

#include "core/support/error.h"
#include "ui/editor/editor_app.h"

namespace gps {

bool EditorApp::run_operation(const std::string& name, const std::function<Modelled(const CovarianceMesh&)>& run,
                              SurfaceReplanner* replanner) {
  return !modal_active() && operate(name, run, replanner);  // not during a drag or a tool
}

bool EditorApp::operate(const std::string& name, const std::function<Modelled(const CovarianceMesh&)>& run,
                        SurfaceReplanner* replanner) {
  try {
    install(run(document_.mesh()), replanner);
  } catch (const Error& e) {  // refused: nothing changed, no undo step
    operation_note(name + " refused: " + e.what(), true);
    return false;
  }
  operation_note(name + ": " + last_summary_, false);
  return true;
}

void EditorApp::install(Modelled made, SurfaceReplanner* replanner) {
  std::optional<Modelled> open = shown_->mirror().seam_kept_open(document_.mesh(), made);
  Modelled result = open ? std::move(*open) : std::move(made);
  std::optional<ReplannedTables> surface;
  if (replanner) {  // first: it throws before anything changes
    replanner->set_sharpness(result.mesh.sharpness);
    if (!shown_->mirror().settings.enabled) surface = replanner->replanned();
  }
  show_mesh(result.mesh, view_.plans(), std::move(surface), result.vertex_origin);
  shown_->clear_preview();
  last_summary_ = result.summary;
  const std::vector<int> selected = result.selection, selected_faces = result.selected_faces;
  document_.apply(std::move(result), selection_.record());  // the mesh taken over
  topology_changed(selected, selected_faces);
}

void EditorApp::topology_changed(const std::vector<int>& selection, const std::vector<int>& faces) {
  view_.triangle_mesh = scheme_for(document_.mesh().topology(), PlanOptions{}) == Scheme::loop;
  selection_.select(selection, false);
  if (select_mode_ == SelectMode::face && !faces.empty())
    selection_.select_faces(document_.mesh(), faces, false);  // the faces the operation names
  else if (select_mode_ == SelectMode::face)
    selection_.hold_faces(document_.mesh());  // the result's faces
  if (!hidden_.elements().fits(document_.mesh()))
    hidden_.elements().clear();  // the indices are another mesh's: all shown
  refresh_hidden();
}

void EditorApp::rebuild_after_undo(const SelectionRecord& selection) {
  try {
    show_mesh(document_.mesh(), view_.plans(), std::nullopt, document_.replaced_origin());
  } catch (const Error& e) {
    set_status(e.what(), true);
  }
  topology_changed(selection.vertices);
  selection_.restore(selection);
}

void EditorApp::operation_note(const std::string& message, bool error) {
  set_status(message, error);
  inspector_.set_note(message, error);
}

}  // namespace gps
