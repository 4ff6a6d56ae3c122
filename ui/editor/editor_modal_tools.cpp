// The editor's modal tools (ui/tools/): the one running takes the events first, sees the editor
// through a ToolContext, and shows what it previews in place of the document's mesh.
#include <utility>

#include "core/support/error.h"
#include "ui/editor/editor_app.h"

namespace gps {

ToolContext EditorApp::tool_context() {
  ToolContext c(document_, selection_, reach_options_);
  c.hidden_vertices = &hidden_.vertex_mask();
  c.viewport = viewport();
  c.cursor = input_.cursor;
  c.shift = input_.shift();
  c.ctrl = input_.ctrl();
  c.snap = view_.snap;
  c.orientation = view_.transform_orientation == 1 ? TransformOrientation::normal : TransformOrientation::global;
  c.cursor_point = cursor_.point;
  c.surface_at = [this](glm::vec2 pixel) { return surface_at(pixel); };
  c.adjustable = [this](AdjustableOperation operation) {
    operation.step = document_.last_step();
    adjustable_ = std::move(operation);
  };
  c.transform_gaussians = view_.transform_gaussians;
  c.plans = view_.plans();
  c.install = [this](const Modelled& result, SurfaceReplanner* replanner) { install(result, replanner); };
  c.operate = [this](const std::string& name, const std::function<Modelled(const CovarianceMesh&)>& run,
                     SurfaceReplanner* replanner) { return operate(name, run, replanner); };
  c.last_summary = [this] { return last_summary_; };
  c.show_preview = [this](std::shared_ptr<const CovarianceMesh> mesh, const std::vector<int>& selected,
                          std::optional<ReplannedTables> surface) {
    show_preview(std::move(mesh), selected, std::move(surface));
  };
  c.show_document = [this](std::optional<ReplannedTables> surface) { show_document(std::move(surface)); };
  c.rebuild = [this](const SelectionRecord& selection) { rebuild_after_undo(selection); };
  c.report = [this](const std::string& message, bool error) { set_status(message, error); };
  c.note = [this](const std::string& message, bool error) { operation_note(message, error); };
  c.show_status = [this](const std::string& message, bool error) { status_ = message, status_error_ = error; };
  return c;
}

void EditorApp::start_tool(const std::function<std::unique_ptr<ModalTool>(ToolContext&)>& make) {
  if (tool_ || mode_ != Mode::none) return;
  ToolContext ctx = tool_context();
  tool_ = make(ctx);
  if (!tool_) return;  // refused, and reported
  if (const size_t reached = tool_->reached(); reached > 0) last_edit_vertices_ = reached;
  status_ = tool_->status();
  status_error_ = tool_->error();
}

bool EditorApp::modal_event(const InputEvent& e) {
  if (!tool_) return false;
  ToolContext ctx = tool_context();
  const ToolResult result = tool_->handle(e, ctx);
  if (const size_t reached = tool_->reached(); reached > 0) last_edit_vertices_ = reached;
  switch (result) {
    case ToolResult::passed_on:
      return false;
    case ToolResult::consumed:
      status_ = tool_->status();
      status_error_ = tool_->error();
      return true;
    case ToolResult::replaced:
      tool_ = std::move(ctx.next);
      if (tool_) status_ = tool_->status(), status_error_ = tool_->error();
      return true;
    case ToolResult::confirmed:
    case ToolResult::cancelled:
      tool_.reset();
      return true;
  }
  return true;
}

void EditorApp::show_preview(std::shared_ptr<const CovarianceMesh> mesh, const std::vector<int>& selected,
                             std::optional<ReplannedTables> surface) {
  show_mesh(*mesh, view_.plans(), std::move(surface));
  shown_->set_preview(std::move(mesh), selected);
}

void EditorApp::show_document(std::optional<ReplannedTables> surface) {
  shown_->clear_preview();
  try {
    show_mesh(document_.mesh(), view_.plans(), std::move(surface));
  } catch (const Error& e) {
    set_status(e.what(), true);
  }
}

}  // namespace gps
