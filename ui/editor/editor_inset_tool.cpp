// The editor's inset tool (I): the selected faces inset by a thickness followed from the mouse (its
// distance to the faces' centre) or typed, the document changed in place while it runs and one undo
// step when confirmed. Its events are the modal tools' (ui/editor/editor_modal_tools.cpp).
#include <cstdio>
#include <memory>
#include <string>

#include "core/support/error.h"
#include "core/modelling/inset.h"
#include "core/modelling/mesh_queries.h"
#include "ui/editor/editor_app.h"

namespace gps {

void EditorApp::start_inset() {
  if (modal_active() || mode_ != Mode::none) return;
  std::vector<int> faces = faces_within(document_.mesh(), selection_.vertices());
  if (faces.empty()) {
    operation_note("inset refused: select the corners of one face or more", true);
    return;
  }
  InsetTool tool;
  tool.base = std::make_shared<const CovarianceMesh>(document_.mesh());
  tool.faces = std::move(faces);
  tool.selection_before = selection_.vertices();
  tool.centre = centre_of_vertices(document_.mesh(), selection_.vertices());
  tool.start_cursor = input_.cursor;
  inset_ = std::move(tool);
  status_ = "inset: move toward the faces' centre (or type the thickness), click or Enter confirms, Esc cancels";
  status_error_ = false;
}

void EditorApp::update_inset(double thickness) {
  InsetTool& tool = *inset_;
  if (!(thickness > 0)) return;
  try {
    const Modelled inset = inset_faces(*tool.base, tool.faces, thickness);
    if (!tool.applied) {
      install(inset);
      tool.applied = true;
      document_.begin_edit();
    } else {
      const CovarianceMesh& mesh = document_.mesh();
      if (inset.mesh.n_vertices() != mesh.n_vertices()) return;
      for (size_t i = 0; i < mesh.n_vertices(); ++i) {
        if (mesh.mean(i) != inset.mesh.mean(i)) document_.set_mean(int(i), inset.mesh.mean(i));
        if (mesh.covariance(i) != inset.mesh.covariance(i)) document_.set_covariance(int(i), inset.mesh.covariance(i));
      }
      last_summary_ = inset.summary;
    }
    char text[128];
    std::snprintf(text, sizeof text, "inset: thickness %.4f%s (click or Enter confirms, Esc cancels)", thickness,
                  tool.typed.empty() ? "" : ("  [" + tool.typed + "]").c_str());
    status_ = text;
    status_error_ = false;
  } catch (const Error& e) {
    status_ = std::string("inset: ") + e.what();
    status_error_ = true;
  }
}

void EditorApp::follow_inset(glm::vec2 cursor) {
  const Viewport v = viewport();
  const auto c = project_to_pixel(v.camera, v.width, v.height, inset_->centre);
  if (!c) return;
  const glm::vec2 centre(*c);
  const double pixels = double(glm::length(inset_->start_cursor - centre) - glm::length(cursor - centre));
  update_inset(pixels * world_per_pixel(v.camera, v.height, inset_->centre));
}

void EditorApp::end_inset(bool keep) {
  if (inset_->applied) {
    if (keep) {
      document_.commit_edit_into_last_operation(selection_.vertices());
      operation_note("inset: " + last_summary_, false);
    } else {
      document_.cancel_edit();
      document_.discard_last_operation();
      rebuild_after_undo(inset_->selection_before);
      set_status("inset cancelled", false);
    }
  } else {
    set_status(keep ? "inset: nothing done (move toward the centre or type a thickness)" : "inset cancelled", false);
  }
  inset_.reset();
}

}  // namespace gps
