// The editor's crease tool (Shift+E, Ctrl+Shift+V): the sharpness of the selected edges or the corner
// sharpness of the selected vertices followed from the mouse or typed, the surface re-planned for
// each value (around the changed edges or corners only), one undo step when confirmed
// (docs/editor.md "Crease"). Its events are the modal tools' (ui/editor/editor_modal_tools.cpp).
#include <algorithm>
#include <cmath>
#include <memory>

#include "core/support/error.h"
#include "core/mesh/sharpness.h"
#include "core/modelling/crease_edges.h"
#include "core/modelling/mesh_queries.h"
#include "ui/editing/crease_tool.h"
#include "ui/editor/editor_app.h"

namespace gps {

Modelled EditorApp::creased(const CovarianceMesh& mesh, bool corners, double sharpness) const {
  const std::vector<int>& selected = selection_.vertices();
  if (corners) return set_corner(mesh, with_mirrored_vertices(mesh, selected, reach_options_), sharpness);
  return set_crease(mesh, with_mirrored_edges(mesh, edges_within(mesh, selected), reach_options_), sharpness);
}

void EditorApp::apply_sharpness(bool corners, double sharpness, SharpnessReplanner* replanner) {
  const std::vector<int> before = selection_.vertices();
  const bool done = run_operation(
      corners ? "corner" : "crease", [&](const CovarianceMesh& m) { return creased(m, corners, sharpness); }, replanner);
  if (done) selection_.select(before, false);  // the selection as it was (set_crease selects the edges' ends)
}

void EditorApp::start_crease(bool corners) {
  if (modal_active() || mode_ != Mode::none || selection_.empty()) return;
  const CovarianceMesh& mesh = document_.mesh();
  const auto edges = edges_within(mesh, selection_.vertices());
  if (!corners && edges.empty()) {
    operation_note("crease refused: select an edge or more (both ends of each)", true);
    return;
  }
  CreaseTool tool;
  tool.corners = corners;
  const double common = corners ? common_corner(mesh, selection_.vertices()) : common_crease(mesh, edges);
  tool.start = std::isfinite(common) ? std::min(common, kInfiniteSharpness) : 0.0;
  tool.value = tool.start;
  tool.start_cursor = input_.cursor;
  tool.shown = std::make_shared<const CovarianceMesh>(mesh);
  crease_ = std::move(tool);
  preview_crease(crease_->start);
}

PlannedSurface EditorApp::crease_surface(CreaseTool& tool, const CovarianceMesh& mesh) {
  if (tool.replanner)
    tool.replanner->set_sharpness(mesh.sharpness);
  else
    tool.replanner = std::make_shared<SharpnessReplanner>(topology_of(mesh.mesh), view_.plans(), mesh.sharpness);
  return PlannedSurface(mesh, tool.replanner->scheme(), tool.replanner->tables());
}

// Re-plans the surface for the sharpness (a change of sharpness changes the plans, as a change of
// topology does; only those of the faces around the changed edges or corners after the first change);
// the document keeps its mesh until the tool is confirmed.
void EditorApp::preview_crease(double sharpness) {
  CreaseTool& tool = *crease_;
  const char* what = tool.corners ? "corner" : "crease";
  const std::string typed = tool.typed.empty() ? "" : "  [" + tool.typed + "]";
  try {
    if (sharpness != tool.value) {
      auto shown = std::make_shared<const CovarianceMesh>(creased(document_.mesh(), tool.corners, sharpness).mesh);
      renderer_->set_mesh(*shown, crease_surface(tool, *shown));
      surface_changed();
      tool.shown = std::move(shown);
      tool.value = sharpness;
    }
    status_ = std::string(what) + ": " + sharpness_text(sharpness) + typed +
              "  (drag left/right or type 0-10, 10 = ∞; click or Enter confirms, Esc cancels)";
    status_error_ = false;
  } catch (const Error& e) {
    status_ = std::string(what) + typed + ": " + e.what();
    status_error_ = true;
  }
}

void EditorApp::end_crease(bool keep) {
  CreaseTool tool = *crease_;
  crease_.reset();
  const char* what = tool.corners ? "corner" : "crease";
  if (keep && tool.shown->sharpness != document_.mesh().sharpness) {
    apply_sharpness(tool.corners, tool.value, tool.replanner.get());  // one undo step
    return;
  }
  try {  // the surface planned for the document's sharpness again
    if (tool.replanner)
      renderer_->set_mesh(document_.mesh(), crease_surface(tool, document_.mesh()));
    else
      renderer_->set_mesh(document_.mesh(), view_.plans());
    surface_changed();
  } catch (const Error& e) {
    set_status(e.what(), true);
    return;
  }
  set_status(keep ? std::string(what) + ": nothing changed" : std::string(what) + " cancelled", false);
}

}  // namespace gps
